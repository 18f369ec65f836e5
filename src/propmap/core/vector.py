"""Vector form: force and torque vectors of a rotor at any orientation.

From the disk velocity vector V (velocity of the rotor hub relative to the air), the
rotor axis z (the thrust direction) and the spin, Gill & D'Andrea (2017) Section II
gives beta = arccos(<V, z>/|V|) (docs/numerics.md item 1), thrust along z and rotor drag
in the disk plane along the projection of V (Fig. 1); propmap's drag is positive
against the motion (docs/conventions.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from .airfoil import RECORD_META, Air, AirfoilParams
from .derivatives import _ODD_LOADS as _ODD  # the loads odd in the in-plane speed V sin(beta)
from .derivatives import RHO, STILL_AIR
from ._frame import frames, vectors
from ._plain import SPINS, compiled_layout, plain_float, plain_vector
from .geometry import Propeller, broadcast_readonly, has_bool, refuse_masked
from .solver import AIRSPEED_MAX, DEFAULT_DISCRETIZATION, Discretization, RotorLoads, check_model_args, rotor_loads

__all__ = ["RotorWrench", "rotor_wrench", "still_air_slopes", "velocity_gradient", "velocity_jacobian"]

#: a hub velocity component this large or larger [m/s] is no airspeed: the one-point path leaves it to the array
#: path's checks, and the maps' wrench (RotorMap, VehicleMap) and the C header refuse it (its force and moment
#: vectors would overflow)
VELOCITY_MAX = 1e150


#: what ``rotor_loads`` differentiates for the velocity vector's Jacobian: the airspeed, the incidence and, at
#: the points at rest, the slopes along three rays from the same roots (:func:`still_air_slopes`)
VELOCITY_INPUTS = ("airspeed", "incidence", STILL_AIR)


@dataclass(frozen=True, eq=False)  # (arrays: == of two wrenches raised, as RotorLoads' did before its eq=False)
class RotorWrench:
    """Force and torque vectors of a rotor, in the frame the inputs were given in.

    Attributes
    ----------
    force : ndarray, shape S + (3,)
        T z_hat - D e_ip + Y e_adv [N], e_ip the unit in-plane velocity direction and
        e_adv = -spin (z_hat x e_ip) the advancing side (Y = 0 with the paper's uniform
        inflow and rigid blades).
    torque : ndarray, shape S + (3,)
        Aerodynamic moment about the hub, -spin (Q z_hat + M_R e_ip) + M_P (e_ip x z_hat)
        [N m]: the shaft torque opposing the rotation (at constant speed, the reaction the
        motor passes to the airframe), the rolling moment M_R of the advancing/retreating
        asymmetry (:attr:`RotorLoads.rolling_moment`), which for a ccw rotor points along
        -e_ip: the advancing side, where the extra thrust acts, lies at -z_hat x e_ip; and
        the pitching moment M_P (0 with the uniform inflow and rigid blades).
    loads : RotorLoads
        The scalar loads and flags behind them, shape S.
    jacobian : dict or None
        With ``rotor_wrench(..., derivatives=names)`` (True: "omega" and "velocity"):
        {("force", name): dF/dp, ("torque", name): dtau/dp}, shape S + (3,), for each name
        (the rotation rate "omega", the "collective", "rho" or a section parameter); for
        "velocity" shape S + (3, 3), entry [..., i, j] = dF_i/dV_j [N s/m] (dtau_i/dV_j
        [N s]); else None.
    """

    force: np.ndarray
    torque: np.ndarray
    loads: RotorLoads
    jacobian: dict | None = None


def _spin_sign(spin) -> np.ndarray:
    table = SPINS
    if isinstance(spin, str):
        if spin.lower() not in table:
            raise ValueError(f"spin must be 'ccw', 'cw', +1 or -1, got {spin!r}")
        return np.asarray(table[spin.lower()])
    s = np.asarray(spin)
    if s.dtype.kind in "UO" and all(isinstance(x, str) for x in s.reshape(-1)):  # e.g. ["cw", "ccw"]
        words = [x.lower() for x in s.reshape(-1)]
        if not all(w in table for w in words):
            raise ValueError(f"spin must be 'ccw', 'cw', +1 or -1, got {spin!r:.60}")
        return np.array([table[w] for w in words]).reshape(s.shape)
    if s.dtype.kind not in "iuf" or not np.all(np.isin(s, (-1.0, 1.0))):
        raise ValueError(f"spin must be 'ccw', 'cw', +1 or -1 (not a bool), got {spin!r:.60}")
    return s.astype(float)


def _check_spin(s: np.ndarray, shape: tuple) -> None:
    """Refuse a spin array that does not broadcast to the loads' shape S."""
    try:
        ok = np.broadcast_shapes(shape, s.shape) == tuple(shape)
    except ValueError:
        ok = False
    if not ok:
        raise ValueError(f"spin of shape {s.shape} does not broadcast to the shape {tuple(shape)} of the loads "
                         "(of velocity and omega)")


def _vectors(name: str, value) -> np.ndarray:
    refuse_masked(name, value)
    try:
        a = np.asarray(value)
    except ValueError:  # a ragged list
        raise ValueError(f"{name} must be a rectangular array of numbers, got {value!r:.60}") from None
    if a.dtype.kind not in "iuf" or has_bool(value):
        raise ValueError(f"{name} must be numbers, got {value!r:.60}")
    a = a.astype(float)
    if a.shape[-1:] != (3,):
        raise ValueError(f"{name} must have a last axis of length 3, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be finite")
    return a


def rotor_wrench(propeller: Propeller, params: AirfoilParams, velocity, axis, omega, spin="ccw", *,
                 air: Air | None = None, discretization: Discretization = DEFAULT_DISCRETIZATION,
                 on_failure: str = "raise", derivatives=()) -> RotorWrench:
    """Force and torque vectors of a rotor from its velocity, axis and rotation rate.

    Parameters
    ----------
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    velocity : array_like, shape S + (3,)
        Hub velocity relative to the air [m/s] (the negative of the wind seen by the
        rotor). V = 0 is allowed (beta is then irrelevant; D = 0).
    axis : array_like, shape S + (3,)
        Rotor axis, the thrust direction; normalised here; must be non-zero.
    omega : float or array_like, shape S
        Rotation rate magnitude Omega [rad/s], in [0, 1e5] (below 0.1 rad/s parked blades, as
        :func:`propmap.rotor_loads`).
    spin : {"ccw", "cw"} or +1/-1 (array_like, shape S)
        Rotation sense about ``axis`` by the right-hand rule: "ccw" (+1) spins about
        +axis (counter-clockwise seen from the tip of the axis looking back at the disk).
    air, discretization, on_failure
        As for :func:`rotor_loads`.
    derivatives : bool or sequence of str
        True for the operating point's inputs, ("omega", "velocity") (as ``rotor_loads``'
        True gives its omega, airspeed and incidence); False, None or () for none; or the
        names to differentiate the force and torque vectors with respect to: "omega", the
        "collective", "rho" or section parameters (as :func:`rotor_loads` takes them; the
        loads' derivatives by the implicit function theorem, carried through the vector
        form, which is linear in them), and "velocity": the Jacobians dF/dV and dtau/dV
        with respect to the velocity vector (:func:`velocity_jacobian`; at V = 0 its axial
        column is the mean of the climb and descent slopes, :func:`still_air_slopes`).
        Flapping blades (``flap_compliance > 0``) and ``flap_compliance`` itself included:
        their side force and pitching moment by the chain rule (core/flapping.py).

    Returns
    -------
    RotorWrench

    Raises
    ------
    ValueError
        Non-numeric inputs, shapes not ending in 3, a velocity and an axis whose shapes do not
        broadcast, a zero or non-finite axis, a non-finite velocity, a bad spin (a bool
        included, or an array that does not broadcast to the loads' shape S), or the ranges
        of :func:`rotor_loads` (the speed |velocity| at most 500 m/s); ``derivatives`` neither a bool nor a
        sequence of names, naming "airspeed" or "incidence" (ask for "velocity"), or refused by
        :func:`rotor_loads`.
    TypeError
        A propeller, parameter set, air or discretization of the wrong type
        (:func:`propmap.core.solver.check_model_args`).
    SolverError
        As :func:`rotor_loads`.

    Notes
    -----
    With the paper's inflow, independent of azimuth (Section II), and rigid blades, the
    side force and the pitching moment (about z_hat x e_ip) are zero by symmetry; spin then
    mirrors the shaft torque and the rolling moment and leaves the force unchanged. A
    linear inflow model or flapping blades (RotorOptions) give both.
    """
    air = getattr(params, "air", None) if air is None else air  # checked below
    check_model_args(propeller, params, air, discretization)
    if isinstance(derivatives, np.bool_):
        derivatives = bool(derivatives)
    if isinstance(derivatives, np.ndarray) and derivatives.ndim == 1:  # (names as rotor_loads takes them: its
        derivatives = derivatives.tolist()  # truth value was asked and failed, an API audit, 2026-12-01)
    if derivatives is True:  # the operating point's inputs, as rotor_loads(derivatives=True)
        derivatives = ("omega", "velocity")
    if derivatives is None or derivatives is False or (isinstance(derivatives, (tuple, list)) and not derivatives):
        one = _one_rotor(propeller, params, velocity, axis, omega, spin, air, discretization, on_failure)
        if one is not None:
            return one
    V, z, speed, beta = disk_frame(velocity, axis)
    _check_speed(speed)
    s = _spin_sign(spin)
    try:
        omega_shape = np.shape(omega)
    except ValueError:  # a ragged list: rotor_loads names it
        omega_shape = None
    if omega_shape is not None:
        try:
            shape = np.broadcast_shapes(speed.shape, omega_shape)
        except ValueError:
            raise ValueError(f"omega (shape {omega_shape}) must broadcast with velocity's samples (shape "
                             f"{speed.shape}: velocity of shape {speed.shape + (3,)})") from None
        _check_spin(s, shape)
    if isinstance(derivatives, str) or not hasattr(derivatives or (), "__iter__"):
        raise ValueError(f"derivatives must be True, False or a sequence of names, got {derivatives!r:.60}")
    names = tuple(dict.fromkeys(derivatives or ()))
    if any(n in ("airspeed", "incidence") for n in names):
        raise ValueError("derivatives must be a sequence of names other than 'airspeed' and 'incidence' (ask for "
                         f"'velocity', the velocity vector's Jacobian), got {derivatives!r:.60}")
    own = {f.name for f in fields(params)} - set(RECORD_META)
    bad = [n for n in names if n not in ("velocity", "omega", "collective", RHO) and n not in own]
    if bad:  # (rotor_loads' own message lists its airspeed and incidence, which this function refuses)
        raise ValueError(f"derivatives: unknown input or parameter {bad[0]!r:.60}; valid: velocity, omega, "
                         f"collective, {RHO} or a numeric field of {type(params).__name__}")
    solve = dict(air=air, discretization=discretization, on_failure=on_failure)
    scalar = tuple(n for n in names if n != "velocity")
    wrt = scalar + (VELOCITY_INPUTS if "velocity" in names else ())
    loads = rotor_loads(propeller, params, omega, speed, beta, derivatives=wrt or False, **solve)
    force, torque = wrench_vectors(loads.thrust, loads.drag, loads.torque, loads.rolling_moment, V, z, s,
                                   side_force=loads.side_force, pitching_moment=loads.pitching_moment)
    jac = None
    if names:
        jac = {}
        for n in scalar:
            dF, dtau = wrench_vectors(*(loads.derivative(q, n) for q in ("thrust", "drag", "torque", "rolling_moment")),
                                      V, z, s, side_force=loads.derivative("side_force", n),
                                      pitching_moment=loads.derivative("pitching_moment", n))
            jac[("force", n)], jac[("torque", n)] = dF, dtau
        if "velocity" in names:
            jac[("force", "velocity")], jac[("torque", "velocity")] = velocity_jacobian(loads, V, z, s)
    return RotorWrench(force=force, torque=torque, loads=loads, jacobian=jac)


def _check_speed(speed) -> None:
    """Refuse a rotor speed |velocity| beyond rotor_loads' airspeed range, naming ``velocity``
    (rotor_loads' own message names its ``airspeed``, an argument this function does not have:
    a physics audit, 2026-11-28)."""
    if np.any(np.asarray(speed) > AIRSPEED_MAX):
        worst = float(np.nanmax(speed))
        raise ValueError(f"velocity: the rotor's airspeed |velocity| must be at most {AIRSPEED_MAX:g} m/s (the "
                         f"model's range); got {worst:.6g} m/s")


def _one_rotor(propeller, params, velocity, axis, omega, spin, air, discretization, on_failure):
    """:func:`rotor_wrench` at one operating point (a controller's call: the array path's frame and
    vectors cost twice the loads' own call), or None where the inputs are not one velocity, one
    axis, one rate and one spin (the array path takes them, and its errors). The frame and the
    vectors are the map's one-point ones (core/_interp.py ``point_frame``, ``point_vectors``),
    the arithmetic of :func:`disk_frame` and :func:`wrench_vectors`, tested against them."""
    from ._interp import point_frame, point_vectors

    Vv, zv = plain_vector(velocity, 3, int64=True), plain_vector(axis, 3, int64=True)
    om = plain_float(omega, int64=True)
    if Vv is None or zv is None or om is None or not (isinstance(spin, str) or plain_float(spin) is not None):
        return None
    # (Python floats, and no generators: the checks took 10 us of the call, 2026-11-29)
    vx, vy, vz = Vv.tolist()
    a0, a1, a2 = zv.tolist()
    if not (math.isfinite(a0) and math.isfinite(a1) and math.isfinite(a2)
            and abs(vx) < VELOCITY_MAX and abs(vy) < VELOCITY_MAX and abs(vz) < VELOCITY_MAX):
        return None  # (the array path names a non-finite axis or velocity; a huge one is no airspeed)
    zmax = max(abs(a0), abs(a1), abs(a2))
    if zmax == 0.0:
        raise ValueError("axis must be non-zero")
    if not 1e-100 < zmax < 1e100:  # (scaled first, as disk_frame does: |z| of a 1e-310 axis underflowed to 0)
        a0, a1, a2 = a0 / zmax, a1 / zmax, a2 / zmax
    s = SPINS.get(spin.lower()) if isinstance(spin, str) else None
    s = float(_spin_sign(spin)) if s is None else s
    zx, zy, zz, speed, axial, beta = point_frame(vx, vy, vz, a0, a1, a2)
    if speed > AIRSPEED_MAX:  # (np.any of an array of one float cost 10 us of a call that passes)
        _check_speed(speed)
    loads = rotor_loads(propeller, params, om, speed, beta, air=air, discretization=discretization,
                        on_failure=on_failure)
    F_M = point_vectors(vx, vy, vz, zx, zy, zz, speed, axial, float(loads.thrust), float(loads.drag),
                        float(loads.torque), float(loads.rolling_moment), float(loads.side_force),
                        float(loads.pitching_moment), s)
    return RotorWrench(force=np.array(F_M[:3]), torque=np.array(F_M[3:]), loads=loads, jacobian=None)


#: the loads whose slopes at rest :func:`still_air_slopes` gives (the odd ones edgewise, the even ones axially)
_AT_REST = ("drag", "rolling_moment", "side_force", "pitching_moment", "thrust", "torque", "v_i_mean")


def still_air_slopes(propeller: Propeller, params: AirfoilParams, omega, speed, **solve) -> dict:
    """The loads' slopes in the velocity at the points where ``speed`` is 0 (0 elsewhere).

    At V = 0 the loads' incidence derivative is 0 and their airspeed derivative lies along
    one ray, so :func:`velocity_jacobian` takes the slopes there along three rays, from the
    same roots (at rest the root does not depend on the incidence; ``rotor_loads`` does this
    for the points at rest of a call that asks for :data:`VELOCITY_INPUTS`; this function
    solves the points at rest once): edgewise (beta = pi/2) for the in-plane slopes of
    D, M_R and (flapping blades) Y and M_P, which are odd in V sin(beta) (the azimuth nodes
    are symmetric in sin psi), so that this one-sided slope is the derivative; climbing
    (beta = 0) and descending (beta = pi) for the axial slopes of T, Q and v_i,mean, whose
    mean is returned: the limit of central differences. With Glauert's momentum the two are
    equal; with the empirical descent momentum, which switches on at V cos(beta) = 0, they
    differ (docs/solver.md, Derivatives), and the mean is what a vehicle's rotation sees (its
    rotors on either side climb and descend alike).

    Parameters
    ----------
    propeller, params
        As :func:`propmap.rotor_loads`.
    omega : float or array_like, shape S
        Rotation rates [rad/s].
    speed : ndarray, shape S
        Airspeeds [m/s] (:func:`disk_frame`).
    **solve
        ``air``, ``discretization``, ``on_failure`` as :func:`propmap.rotor_loads`.

    Returns
    -------
    dict
        {"drag": dD/dV_s [N s/m], "rolling_moment": dM_R/dV_s [N s], "side_force": dY/dV_s
        [N s/m], "pitching_moment": dM_P/dV_s [N s] (0 for rigid blades with the uniform inflow), "thrust": dT/dV_c
        [N s/m], "torque": dQ/dV_c [N s], "v_i_mean": dv_i,mean/dV_c [-]}, each shape S.
    """
    shape = np.broadcast_shapes(np.shape(speed), np.shape(omega))
    out = {q: np.zeros(shape) for q in _AT_REST}
    still = np.broadcast_to(np.asarray(speed) == 0.0, shape)
    if np.any(still):
        om = np.broadcast_to(np.asarray(omega, float), shape)[still]
        r = rotor_loads(propeller, params, om, 0.0, 0.0, derivatives=(STILL_AIR,), **solve)
        for q in out:
            out[q][still] = r.derivative(q, STILL_AIR)
    return out


def _slopes_at_rest(loads: RotorLoads):
    """The slopes at rest that ``rotor_loads`` computed with :data:`VELOCITY_INPUTS`, or None."""
    if loads.jacobian is None or ("thrust", STILL_AIR) not in loads.jacobian:
        return None
    return {q: loads.derivative(q, STILL_AIR) for q in _AT_REST}


def velocity_jacobian(loads: RotorLoads, V, z, spin, still=None) -> tuple:
    """dF/dV and dtau/dV: the force's and torque's Jacobians with respect to the velocity vector.

    With V_c = V . z, V_s = |V - V_c z|, e_ip the in-plane unit velocity and l = z x e_ip,
    the force F = T z - D e_ip (:func:`wrench_vectors`) has (the chain rule; de_ip/dV =
    l l^T / V_s)

        dF/dV = z (T_s e_ip + T_c z)^T - e_ip (D_s e_ip + D_c z)^T - (D / V_s) l l^T,

    X_s, X_c the loads' derivatives with respect to V_s and V_c, from their airspeed and
    incidence derivatives (X_s = sin(beta) X_V + cos(beta) X_beta / V, X_c = cos(beta) X_V -
    sin(beta) X_beta / V); the torque -spin (Q z + M_R e_ip) likewise. In axial flow (V_s =
    0) D / V_s and M_R / V_s are their limits D_s and M_R,s (D and M_R are odd in V_s, T and Q
    even, so T_s = Q_s = 0 there) and the in-plane block is -D_s (I - z z^T): isotropic.
    Flapping blades add the side force -spin Y l and the pitching moment -M_P l (odd in V_s
    too); with dl/dV = -e_ip l^T / V_s,

        d(Y l)/dV = l (Y_s e_ip + Y_c z)^T - (Y / V_s) e_ip l^T,

    whose last term with the first's Y_s l e_ip^T is (Y / V_s) [z]x in axial flow ([z]x the
    cross-product matrix of z: isotropic in the disk plane).

    Parameters
    ----------
    loads : RotorLoads, shape S
        With the derivatives "airspeed" and "incidence" (:func:`propmap.rotor_loads`): the
        uniform or a linear inflow, rigid or flapping blades.
    V, z : array_like, shape S + (3,)
        Velocity [m/s] and unit axis (:func:`disk_frame`).
    spin : array_like, shape S
        +1 ccw, -1 cw.
    still : dict, optional
        The slopes where V = 0 (:func:`still_air_slopes`); required when a point has V = 0,
        where the loads' own derivatives lie along one ray, unless the loads were computed
        with :data:`VELOCITY_INPUTS` (which carry them).

    Returns
    -------
    tuple of ndarray
        dF/dV [N s/m] and dtau/dV [N s], shape S + (3, 3), entry [..., i, j] the derivative
        of component i with respect to V_j.

    Raises
    ------
    ValueError
        ``still`` missing while a point has V = 0 and the loads do not carry the slopes
        at rest (loads computed with :data:`VELOCITY_INPUTS`, as :func:`rotor_wrench`'s, do).

    Notes
    -----
    At V = 0 the axial column is the mean of the climb and descent slopes
    (:func:`still_air_slopes`), as exactly edgewise (V_c = 0) the loads' own derivatives
    are: the empirical descent momentum switches on at V_c = 0 and the model has a kink
    there (docs/solver.md, Derivatives). Elsewhere these are derivatives.
    """
    shape = np.shape(loads.thrust)
    z = np.broadcast_to(z, shape + (3,))
    s = np.broadcast_to(spin, shape)
    e, axial, vs, split = _disk_split(loads, V, z, still)
    (Ts, Tc), (Ds, Dc), (Qs, Qc), (Rs, Rc) = (split(q) for q in ("thrust", "drag", "torque", "rolling_moment"))
    # D / V_s and M_R / V_s; their limits D_s, M_R,s in axial flow and where V_s is below 1e-6 of the
    # blade's speed scale (they differ by O((V_s / Omega R)^2) there, while the quotient of the tiny
    # D, a sum over the nodes that cancels to O(V_s), loses digits: 1e-3 at V_s = 1e-12 m/s)
    blade = np.asarray(loads.omega) * (0.5 * loads.diameter) + np.asarray(loads.airspeed)  # speed scale [m/s]
    small = axial | (np.abs(vs) < 1e-6 * blade)
    d_ratio = np.where(small, Ds, loads.drag / np.where(small, 1.0, vs))
    r_ratio = np.where(small, Rs, loads.rolling_moment / np.where(small, 1.0, vs))
    proj = np.eye(3) - z[..., :, None] * z[..., None, :]  # I - z z^T
    ee = e[..., :, None] * e[..., None, :]

    def outer(a, b):
        return a[..., :, None] * b[..., None, :]

    def row(xs, xc):  # X_s e_ip + X_c z
        return xs[..., None] * e + xc[..., None] * z

    # -(D_s e e^T + (D / V_s) l l^T) = -((D_s - D / V_s) e e^T + (D / V_s) (I - z z^T))
    dF = (outer(z, row(Ts, Tc)) - outer(e, Dc[..., None] * z) - (Ds - d_ratio)[..., None, None] * ee
          - d_ratio[..., None, None] * proj)
    dtau = -s[..., None, None] * (outer(z, row(Qs, Qc)) + outer(e, Rc[..., None] * z)
                                  + (Rs - r_ratio)[..., None, None] * ee + r_ratio[..., None, None] * proj)
    # flapping blades or a linear inflow (zeros for rigid blades with the uniform one): -spin Y l and -M_P l,
    # l = z x e_ip, with dl/dV = -e_ip l^T / V_s, so
    # d(-spin Y l)/dV = -spin ((Y_s - Y / V_s) l e^T + Y_c l z^T + (Y / V_s) [z]x), as l e^T - e l^T = [z]x
    # (the cross-product matrix of z, isotropic in the disk plane), and M_P likewise; Y and M_P are odd in V_s
    (Ys, Yc), (Ps, Pc) = split("side_force"), split("pitching_moment")
    y_ratio = np.where(small, Ys, loads.side_force / np.where(small, 1.0, vs))
    p_ratio = np.where(small, Ps, loads.pitching_moment / np.where(small, 1.0, vs))
    lat = cross3(z, e)
    zx = np.zeros(shape + (3, 3))
    zx[..., 0, 1], zx[..., 0, 2], zx[..., 1, 2] = -z[..., 2], z[..., 1], -z[..., 0]
    zx = zx - np.swapaxes(zx, -1, -2)

    def turn(xs, xc, ratio):  # d(X l)/dV
        return ((xs - ratio)[..., None, None] * outer(lat, e) + outer(lat, xc[..., None] * z)
                + ratio[..., None, None] * zx)

    dF = dF - s[..., None, None] * turn(Ys, Yc, y_ratio)
    dtau = dtau - turn(Ps, Pc, p_ratio)
    return dF, dtau


def velocity_gradient(loads: RotorLoads, quantity: str, V, z, still=None) -> np.ndarray:
    """d(quantity)/dV for a load even in the in-plane speed ("thrust", "torque", "v_i_mean").

    X_s e_ip + X_c z (:func:`velocity_jacobian`, its notation): the gradient of the scalar
    with respect to the velocity vector; in axial flow X_s = 0 (the load is even in V_s),
    at V = 0 X_c is the mean of the climb and descent slopes.

    Parameters
    ----------
    loads : RotorLoads, shape S
        With the derivatives "airspeed" and "incidence".
    quantity : {"thrust", "torque", "v_i_mean"}
    V, z : array_like, shape S + (3,)
        Velocity [m/s] and unit axis.
    still : dict, optional
        As :func:`velocity_jacobian`.

    Returns
    -------
    ndarray, shape S + (3,)
        The gradient [unit of the quantity per m/s].

    Raises
    ------
    ValueError
        ``quantity`` odd in the in-plane speed ("drag", "rolling_moment", "side_force",
        "pitching_moment": use :func:`velocity_jacobian`), ``still`` missing while a point has V = 0 and the
        loads do not carry the slopes at rest (as :func:`velocity_jacobian`), or as
        :meth:`RotorLoads.derivative`.
    """
    if quantity not in ("thrust", "torque", "v_i_mean"):
        raise ValueError(f"quantity must be 'thrust', 'torque' or 'v_i_mean' (a load even in the in-plane speed), "
                         f"got {quantity!r:.40}")
    z = np.broadcast_to(z, np.shape(loads.thrust) + (3,))
    e, _, _, split = _disk_split(loads, V, z, still)
    xs, xc = split(quantity)
    return xs[..., None] * e + xc[..., None] * z


def _disk_split(loads: RotorLoads, V, z, still) -> tuple:
    """(e_ip, axial, V_s, split) at the loads' points: the in-plane unit velocity (0 in axial
    flow), the mask of axial flow (V = 0 included), V_s [m/s] as the solver had it, and
    split(q) -> (dq/dV_s, dq/dV_c) from q's airspeed and incidence derivatives (dq/dV_s = 0
    in axial flow for the even loads), at V = 0 from ``still`` (:func:`still_air_slopes`)."""
    shape = np.shape(loads.thrust)
    V = np.broadcast_to(V, shape + (3,))
    # the speed and incidence the loads were solved at, so that D / V_s is theirs
    speed = np.broadcast_to(loads.airspeed, shape)
    sb = np.sin(np.broadcast_to(loads.incidence, shape))
    cb = np.cos(np.broadcast_to(loads.incidence, shape))
    vs = speed * sb
    axial = (np.abs(vs) < 1e-12 * speed) | (vs == 0.0)  # as the solver: no in-plane speed
    at_rest = speed == 0.0
    if np.any(at_rest) and still is None:
        still = _slopes_at_rest(loads)
        if still is None:
            raise ValueError("still (the slopes of still_air_slopes) is required where V = 0, unless the loads "
                             "were computed with derivatives=VELOCITY_INPUTS")
    v_ip = V - np.einsum("...i,...i->...", V, z)[..., None] * z
    n_ip = np.linalg.norm(v_ip, axis=-1)
    e = np.where(axial[..., None], 0.0, v_ip / np.where(n_ip > 0, n_ip, 1.0)[..., None])
    sb = np.where(axial, 0.0, sb)
    safe = np.where(at_rest, 1.0, speed)

    def split(q):
        xv, xb = loads.derivative(q, "airspeed"), loads.derivative(q, "incidence") / safe
        xs, xc = sb * xv + cb * xb, cb * xv - sb * xb
        if q not in _ODD:
            xs = np.where(axial, 0.0, xs)  # even loads: no in-plane slope in axial flow
        if np.any(at_rest):
            xs = np.where(at_rest, still.get(q, 0.0) if q in _ODD else 0.0, xs)
            xc = np.where(at_rest, 0.0 if q in _ODD else still[q], xc)
        return xs, xc

    return e, axial, vs, split


def cross3(a, b):
    """a x b over the last axis (length 3), broadcast: numpy.cross's arithmetic without its
    per-call overhead (15 us a call on small arrays, measured for VehicleMap; 63 us under cProfile
    in one-sample `vehicle_wrench` calls, 2026-11-28).

    Parameters
    ----------
    a, b : ndarray, shape S + (3,)
        Broadcast together.

    Returns
    -------
    ndarray, shape S + (3,)
        (a1 b2 - a2 b1, a2 b0 - a0 b2, a0 b1 - a1 b0), as numpy.cross computes it.
    """
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack((a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0), axis=-1)


def disk_frame(velocity, axis):
    """(V, z, speed, beta): the checked velocity and unit axis (broadcast together, shape
    S + (3,)), the speed |V| [m/s] and the incidence beta [rad] (0 where V = 0), point by point
    as the one-point paths (core/_frame.py: :func:`~propmap.core._frame.frames`).

    Raises
    ------
    ValueError
        As :func:`rotor_wrench` (non-numeric, not ending in 3, non-finite, zero axis, shapes
        that do not broadcast).
    """
    V = _vectors("velocity", velocity)
    a = _vectors("axis", axis)
    if not np.all(np.shape(velocity)) and not np.all(np.any(a != 0.0, axis=-1)):  # (no sample: the loop sees none)
        raise ValueError("axis must be non-zero")
    try:
        V, a = broadcast_readonly(V, a)
    except ValueError:
        raise ValueError(f"velocity (shape {V.shape}) and axis (shape {a.shape}) must broadcast together: N x 3 "
                         "beside N x 3 or 3") from None
    return (V,) + checked_frame(V, a)


def checked_frame(V: np.ndarray, a: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(z, speed, beta) of :func:`disk_frame` for inputs its caller has checked: velocities ``V``
    [m/s] and axes ``a``, float arrays of one shape S + (3,) (vehicle_wrench's hubs, whose motion
    is checked once for all rotors). A non-finite velocity is not refused here: its speed comes
    out NaN or infinite, for the caller to refuse.

    Raises
    ------
    ValueError
        An axis of zero length.
    """
    shape = V.shape[:-1]
    z = np.empty(V.shape)
    out = np.empty((3,) + shape)
    # (one compiled pass: the NumPy expressions of before took 80-90 us of a vehicle step's 4 rotors)
    if frames(_rows(V), _rows(a), z.reshape(-1, 3), out.reshape(3, -1)) >= 0:
        raise ValueError("axis must be non-zero")
    return z, out[0, ...], out[2, ...]  # (0-d arrays for one point, as V's other quantities)


def _rows(a: np.ndarray) -> np.ndarray:
    """``a`` (shape S + (3,)) as a C-contiguous, writeable (M, 3) array (the compiled loops' one type)."""
    return compiled_layout(a.reshape(-1, 3))


def wrench_vectors(thrust, drag, torque, rolling_moment, V, z, spin, *, side_force=0.0, pitching_moment=0.0):
    """(force, moment) vectors, shape S + (3,), from the scalar loads (shape S), the
    velocity V and unit axis z (shape S + (3,) or broadcastable) and the spin sign.

    force T z - D e_ip + Y e_adv, moment -spin (Q z + M_R e_ip) + M_P (e_ip x z), with e_ip
    the in-plane unit velocity (0 where the in-plane speed is below 1e-12 of the speed, axial
    flow or none) and e_adv = -spin (z x e_ip) the direction of the advancing side
    (docs/conventions.md); point by point as the one-point paths (core/_frame.py:
    :func:`~propmap.core._frame.vectors`).
    """
    shape = np.shape(thrust)
    loads = np.empty((6,) + shape)
    for k, q in enumerate((thrust, drag, torque, rolling_moment, side_force, pitching_moment)):
        loads[k] = q
    s = np.empty(shape)
    s[...] = spin
    out = np.empty((2,) + shape + (3,))
    full = shape + (3,)  # (np.broadcast_to only where needed: 3 us a call, a sixth of a vehicle step's vectors)
    V, z = (a if np.shape(a) == full else np.broadcast_to(a, full) for a in (V, z))
    vectors(_rows(V), _rows(z), loads.reshape(6, -1), s.reshape(-1), out.reshape(2, -1, 3))
    return out[0], out[1]
