"""Vector form: force and torque vectors of a rotor at any orientation.

From the disk velocity vector V (velocity of the rotor hub relative to the air), the
rotor axis z (the thrust direction) and the spin, Gill & D'Andrea (2017) Section II
gives beta = arccos(<V, z>/|V|) (docs/numerics.md item 1), thrust along z and rotor drag
in the disk plane along the projection of V, against the motion (Fig. 1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .airfoil import Air, AirfoilParams
from .geometry import Propeller
from .solver import DEFAULT_DISCRETIZATION, Discretization, RotorLoads, check_model_args, rotor_loads

__all__ = ["RotorWrench", "rotor_wrench"]


@dataclass(frozen=True)
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
        With ``rotor_wrench(..., derivatives=names)``: {("force", name): dF/dp, ("torque",
        name): dtau/dp}, shape S + (3,), for each name (the rotation rate "omega", the
        "collective" or a section parameter); else None.
    """

    force: np.ndarray
    torque: np.ndarray
    loads: RotorLoads
    jacobian: dict | None = None


def _spin_sign(spin) -> np.ndarray:
    table = {"ccw": 1.0, "cw": -1.0}
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
    try:
        a = np.asarray(value)
    except ValueError:  # a ragged list
        raise ValueError(f"{name} must be a rectangular array of numbers, got {value!r:.60}") from None
    if a.dtype.kind not in "iuf":
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
    params : AirfoilParams
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
    derivatives : sequence of str
        Names to differentiate the force and torque vectors with respect to: "omega", the
        "collective" or section parameters (as :func:`rotor_loads` takes them; the loads'
        derivatives by the implicit function theorem, carried through the vector form, which
        is linear in them). Not the velocity vector: at V = 0 the model is not
        differentiable in it (docs/solver.md, Derivatives).

    Returns
    -------
    RotorWrench

    Raises
    ------
    ValueError
        Non-numeric inputs, shapes not ending in 3, a zero or non-finite axis, a non-finite
        velocity, a bad spin (a bool included, or an array that does not broadcast to the
        loads' shape S), or the ranges of :func:`rotor_loads`
        (the speed |velocity| at most 500 m/s); ``derivatives`` not a sequence of names,
        naming "airspeed" or "incidence", or refused by :func:`rotor_loads`.
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
    V, z, speed, beta = disk_frame(velocity, axis)
    s = _spin_sign(spin)
    try:
        shape = np.broadcast_shapes(speed.shape, np.shape(omega))
    except ValueError:
        shape = None  # rotor_loads names the argument
    if shape is not None:
        _check_spin(s, shape)
    if derivatives is True or isinstance(derivatives, str) or not hasattr(derivatives or (), "__iter__"):
        raise ValueError(f"derivatives must be a sequence of names, got {derivatives!r:.60}")
    names = tuple(derivatives or ())
    if any(n in ("airspeed", "incidence") for n in names):
        raise ValueError("derivatives must be a sequence of names other than 'airspeed' and 'incidence' (the "
                         f"velocity vector's derivatives are not given), got {derivatives!r:.60}")
    loads = rotor_loads(propeller, params, omega, speed, beta, air=air, discretization=discretization,
                        on_failure=on_failure, derivatives=names or False)
    force, torque = wrench_vectors(loads.thrust, loads.drag, loads.torque, loads.rolling_moment, V, z, s,
                                   side_force=loads.side_force, pitching_moment=loads.pitching_moment)
    jac = None
    if names:
        jac = {}
        for n in names:
            dF, dtau = wrench_vectors(*(loads.derivative(q, n) for q in ("thrust", "drag", "torque", "rolling_moment")),
                                      V, z, s)
            jac[("force", n)], jac[("torque", n)] = dF, dtau
    return RotorWrench(force=force, torque=torque, loads=loads, jacobian=jac)


def disk_frame(velocity, axis):
    """(V, z, speed, beta): the checked velocity and unit axis (broadcast together, shape
    S + (3,)), the speed |V| [m/s] and the incidence beta [rad] (0 where V = 0).

    Raises
    ------
    ValueError
        As :func:`rotor_wrench` (non-numeric, not ending in 3, non-finite, zero axis).
    """
    V = _vectors("velocity", velocity)
    z = _vectors("axis", axis)
    # normalise without overflow: scale by the largest component first (|z| of [0, 1e200,
    # 1e200] would overflow to inf and make the thrust direction 0)
    zmax = np.max(np.abs(z), axis=-1, keepdims=True)
    if np.any(zmax == 0):
        raise ValueError("axis must be non-zero")
    z = z / zmax
    z = z / np.linalg.norm(z, axis=-1, keepdims=True)
    V, z = np.broadcast_arrays(V, z)
    # |V| without overflow (a speed beyond float range is refused by rotor_loads as such)
    vmax = np.max(np.abs(V), axis=-1)
    with np.errstate(over="ignore"):
        speed = vmax * np.linalg.norm(V / np.where(vmax > 0, vmax, 1.0)[..., None], axis=-1)
    axial = np.einsum("...i,...i->...", V, z)
    safe = np.where(speed > 0, speed, 1.0)
    beta = np.where(speed > 0, np.arccos(np.clip(axial / safe, -1.0, 1.0)), 0.0)
    return V, z, speed, beta


def wrench_vectors(thrust, drag, torque, rolling_moment, V, z, spin, *, side_force=0.0, pitching_moment=0.0):
    """(force, moment) vectors, shape S + (3,), from the scalar loads (shape S), the
    velocity V and unit axis z (shape S + (3,) or broadcastable) and the spin sign.

    force T z - D e_ip + Y e_adv, moment -spin (Q z + M_R e_ip) + M_P (e_ip x z), with e_ip
    the in-plane unit velocity (0 where the velocity is axial or zero) and e_adv =
    -spin (z x e_ip) the direction of the advancing side (docs/conventions.md).
    """
    shape = np.shape(thrust)
    z = np.broadcast_to(z, shape + (3,))
    V = np.broadcast_to(V, shape + (3,))
    v_ip = V - np.einsum("...i,...i->...", V, z)[..., None] * z
    n_ip = np.linalg.norm(v_ip, axis=-1, keepdims=True)
    e_ip = np.where(n_ip > 1e-12 * np.maximum(np.linalg.norm(V, axis=-1, keepdims=True), 1e-300),
                    v_ip / np.where(n_ip > 0, n_ip, 1.0), 0.0)
    s = np.broadcast_to(spin, shape)[..., None]
    lateral = np.cross(z, e_ip)  # z x e_ip
    force = np.asarray(thrust)[..., None] * z - np.asarray(drag)[..., None] * e_ip
    moment = -s * (np.asarray(torque)[..., None] * z + np.asarray(rolling_moment)[..., None] * e_ip)
    if np.any(side_force):
        force = force - s * np.asarray(side_force)[..., None] * lateral
    if np.any(pitching_moment):
        moment = moment - np.asarray(pitching_moment)[..., None] * lateral
    return force, moment
