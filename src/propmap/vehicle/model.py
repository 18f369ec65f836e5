"""The multirotor vehicle model: its rotors' wrenches summed about the centre of mass.

Body frame: x forward, y left, z up; every vector of this module is in body axes. Each rotor
i at hub position r_i (from the centre of mass) with axis a_i sees the air at the hub
velocity V_i = v + w x r_i - v_wind (v the velocity of the centre of mass and w the angular
velocity, both of the body, v_wind the wind), and gives, by :func:`propmap.rotor_wrench`
(Gill & D'Andrea 2017 eqs 13-15 and the rotor options), a force F_i and an aerodynamic
moment M_i about its hub. About the centre of mass:

    F = sum_i F_i + F_body,
    M = sum_i (r_i x F_i + M_i - w x h_i - s_i J_i dOmega_i/dt a_i),

(r_i taken from the centre of mass: ``Vehicle.centre_of_mass`` is subtracted from the
file's positions)

with h_i = s_i J_i Omega_i a_i the rotor's angular momentum (s_i = +1 ccw about a_i): the
gyroscopic moment -w x h_i and the reaction to the rotor's spin-up, both only when the
rotor inertia J_i is known (a rigid body carrying spinning rotors, as in R. Mahony,
V. Kumar and P. Corke, "Multirotor aerial vehicles", IEEE Robotics & Automation Magazine
19(3), 2012). F_body is
the airframe drag (core/body.py), acting at the centre of mass.

With ``Vehicle.rotor_interference`` k_I > 0, each rotor also sees the inflow the other
rotors' skewed wakes induce at its disk (core/interference.py): the rotors are solved once
without it, which gives their induced velocities, and again with it in their hub
velocities (twice the rotor evaluations).

The vehicle's description (Rotor, Vehicle, the rotors' arms) is in vehicle/layout.py, the
derivatives of the wrench (``vehicle_wrench(derivatives=...)``) in vehicle/_jacobians.py.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.units import RPM
from ..core.airfoil import Air, SectionParams
from ..core.body import BodyDrag, body_drag_force
from ..core.loads import _new_loads
from ..core.air import SUPERSONIC_TIP, TipMachWarning
from ..core.solver import (AIRSPEED_MAX, DEFAULT_DISCRETIZATION, OMEGA_MAX, OMEGA_MIN, TIP_MACH_WARN, Discretization,
                           RotorLoads, check_model_args, model_air, rotor_loads,
                           supersonic_tips_allowed)
from ..core.vector import VELOCITY_INPUTS, checked_frame, wrench_vectors
from ..io.flightlog_checks import ROTOR_ACCELERATION_MAX
from ._jacobians import (BODY_DRAG_NAMES, MOTION_NAMES, hub_velocity_jacobians, load_derivatives, motion_derivatives,
                        requested_derivatives)
from ._kinematics import _samples, hub_moments, hub_velocity_loop
from .layout import Rotor, Vehicle, cached_rotor_geometry, check_vehicle, rotor_geometry

__all__ = ["Rotor", "Vehicle", "VehicleWrench", "hover_omega", "rotor_geometry", "vehicle_wrench"]


@dataclass(frozen=True)
class VehicleWrench:
    """Force and moment on a vehicle, body axes, at N samples.

    Attributes
    ----------
    force : ndarray, shape (N, 3)
        Aerodynamic force: the rotors' and the airframe drag [N] (no gravity).
    moment : ndarray, shape (N, 3)
        Moment about the centre of mass [N m].
    rotor_force : ndarray, shape (N, n_rotors, 3)
        Each rotor's force [N].
    rotor_moment : ndarray, shape (N, n_rotors, 3)
        Each rotor's moment about the centre of mass [N m]: r_i x F_i, its aerodynamic hub
        moment and, with a rotor inertia, the gyroscopic and spin-up moments.
    body_force : ndarray, shape (N, 3)
        Airframe drag [N] (zeros without one).
    loads : tuple of RotorLoads
        Each rotor's scalar loads and flags, shape (N,).
    force_domega, moment_domega : ndarray, shape (N, 3, n_rotors), or None
        With ``vehicle_wrench(..., derivatives=True)`` (or "omega" among the names):
        dF/dOmega_i and dM/dOmega_i [N s/rad, N m s/rad] (column i: rotor i's speed), the
        control-effectiveness matrix of a linearisation; else None.
    jacobian : dict or None
        With parameter names among ``derivatives``: {("force", name): dF/dp, ("moment",
        name): dM/dp}, each shape (N, 3); with "velocity" or "angular_velocity" among them
        dF/dv, dM/dv [N s/m, N s] and dF/dw, dM/dw [N s/rad, N m s/rad], each shape (N, 3, 3),
        entry [n, i, j] the derivative of component i with respect to component j of the
        body velocity v or the angular velocity w (the state matrix of a linearisation;
        with respect to the wind, -dF/dv and -dM/dv); with "centre_of_mass", dF/dc and
        dM/dc [N/m, N], shape (N, 3, 3), entry [n, i, j] with respect to component j of the
        centre of mass; else None.
    """

    force: np.ndarray
    moment: np.ndarray
    rotor_force: np.ndarray
    rotor_moment: np.ndarray
    body_force: np.ndarray
    loads: tuple[RotorLoads, ...]
    force_domega: np.ndarray | None = None
    moment_domega: np.ndarray | None = None
    jacobian: dict | None = None


def vehicle_wrench(vehicle: Vehicle, params: SectionParams, velocity, angular_velocity, rotor_omega, *,
                   wind=None, rotor_acceleration=None, body_drag: BodyDrag | None = None, air: Air | None = None,
                   discretization: Discretization = DEFAULT_DISCRETIZATION, on_failure: str = "raise",
                   derivatives=False) -> VehicleWrench:
    """Body force and moment of a multirotor from its motion and rotor speeds (module docstring).

    Parameters
    ----------
    vehicle : Vehicle
    params : AirfoilParams or CamberedParams
        The rotors' parameter set (a rotor with its own ``params`` uses those).
    velocity : array_like, shape (N, 3) or (3,)
        Velocity of the centre of mass, body axes [m/s] (relative to the ground; the wind
        is given separately).
    angular_velocity : array_like, shape (N, 3) or (3,)
        Body angular velocity w, body axes [rad/s].
    rotor_omega : array_like, shape (N, n_rotors) or (n_rotors,)
        Rotation rates Omega_i [rad/s], in the vehicle's rotor order, each in [0, 1e5] (below
        0.1 rad/s parked blades, as :func:`propmap.rotor_loads`).
    wind : array_like, shape (N, 3) or (3,), optional
        Wind velocity in body axes [m/s]; default none.
    rotor_acceleration : array_like, shape (N, n_rotors) or (n_rotors,), optional
        dOmega_i/dt [rad/s^2] for the spin-up reaction (rotors with a known inertia), within
        +-ROTOR_ACCELERATION_MAX (1e6 rad/s^2).
    body_drag : BodyDrag, optional
        Airframe drag; default the vehicle's (none if it has none).
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization
    on_failure : {"raise", "flag"}
        As :func:`propmap.rotor_loads`.
    derivatives : bool or sequence of str
        True (or "omega" among the names): dF/dOmega_i and dM/dOmega_i
        (``VehicleWrench.force_domega``, ``moment_domega``). Other names: derivatives of F
        and M with respect to a section parameter of ``params`` (as :func:`propmap.rotor_loads`
        takes them, "collective" included), the air density "rho" [kg/m^3] (the rotors'
        loads and the airframe drag) or an airframe term (``drag_area_x``,
        ``drag_area_y``, ``drag_area_z``, ``wash_factor``), in ``VehicleWrench.jacobian``;
        "velocity" and "angular_velocity" give the Jacobians with respect to v and w
        (each rotor's through :func:`propmap.core.vector.velocity_jacobian`, its hub moving
        at v + w x r_i - wind; at a hub speed of 0 its axial column is the mean of the climb
        and descent slopes, :func:`propmap.core.vector.still_air_slopes`);
        "centre_of_mass" the Jacobians with respect to ``vehicle.centre_of_mass`` c [m] at
        fixed v and w: every arm r_i = p_i - c moves by -dc, so each hub velocity by
        -w x dc and the moment of the rotors' total force F_r by -dc x F_r (the chain rule
        through the same hub Jacobians; the airframe drag acts at the centre of mass).
        Each rotor's load derivatives come from the implicit function theorem (docs/solver.md)
        and are carried through the vector sums, the arms, the gyroscopic moment and the
        airframe's slipstream (its wash moves with the rotors' induced velocity). Not with
        ``rotor_interference`` (the wakes couple the rotors), nor for a section parameter
        when a rotor has its own set; Omega_i >= 0.1 rad/s. The side force and pitching
        moment of flapping rotors or of a linear inflow, and ``flap_compliance``, by the
        chain rule (core/flapping.py, core/_linear_sensitivity.py).

    Returns
    -------
    VehicleWrench
        N the broadcast number of samples.

    Raises
    ------
    ValueError
        An input that is not numbers, of the wrong shape, non-finite, samples counts that
        do not match, a ``rotor_acceleration`` beyond its range, a
        ``vehicle.rotor_interference`` outside [0, 3], or the ranges of
        :func:`propmap.rotor_loads` (naming the input); ``derivatives`` with rotor
        interference, or where :func:`propmap.rotor_loads` refuses them.
    TypeError
        ``vehicle`` not a Vehicle, ``body_drag`` not a BodyDrag, or a model argument of the
        wrong type (:func:`propmap.core.solver.check_model_args`).
    SolverError
        As :func:`propmap.rotor_loads`.

    Warns
    -----
    UserWarning
        Without ``air``: a rotor whose own parameter set carries other air than ``params``
        (every rotor is solved in one air, ``params``'s).
    """
    check_vehicle(vehicle)
    check_model_args(vehicle.rotors[0].propeller, params, **({} if air is None else {"air": air}),
                     discretization=discretization)
    if body_drag is not None and not isinstance(body_drag, BodyDrag):
        raise TypeError(f"body_drag must be a propmap.BodyDrag or None, got {type(body_drag).__name__}")
    if air is None:  # (an air given is the caller's choice for every rotor: not warned of)
        air = params.air
        _warn_rotor_air(vehicle, air)
    n_rot = len(vehicle.rotors)
    kappa = vehicle.rotor_interference  # (in [0, 3]: Vehicle checks it)
    v, w, om, wind_a, acc, N = _checked_samples(velocity, angular_velocity, rotor_omega, wind, rotor_acceleration,
                                                n_rot)
    pos, axes, _, h_spin = cached_rotor_geometry(vehicle)  # arms about the centre of mass, unit axes, s_i J_i a_i
    V_hub = np.empty((N, n_rot, 3))  # v - wind + w x r_i (compiled: _kinematics.py)
    hub_velocity_loop(v, wind_a, w, pos, V_hub)
    frame = _hub_frames(V_hub, axes)
    speed = frame[1]  # (the speed the rotors are solved at: the compiled frame's, as rotor_wrench's)
    _check_hub_speed(speed)
    wrt = requested_derivatives(derivatives, vehicle, params)
    if wrt:
        _check_derivative_points(kappa, om)
    motion = any(n in MOTION_NAMES for n in wrt)
    rotor_wrt = tuple(n for n in wrt if n not in BODY_DRAG_NAMES + MOTION_NAMES) + (VELOCITY_INPUTS if motion else ())
    solve = dict(air=air, discretization=discretization, on_failure=on_failure, derivatives=rotor_wrt)
    w_rows, om_rows = w, om  # (1 or N rows, as given: the compiled sums below take them so)
    v, w, wind_a = (a if a.shape[0] == N else np.broadcast_to(a, (N, 3)) for a in (v, w, wind_a))
    om = om if om.shape[0] == N else np.broadcast_to(om, (N, n_rot))
    rotor_force, rotor_moment, loads, batches = _rotor_wrenches(vehicle, params, V_hub, frame, om, **solve)
    hub_jac = hub_velocity_jacobians(vehicle, batches, om) if motion else None
    if kappa > 0 and n_rot > 1:  # (solved again in the other rotors' wakes)
        V_wake = V_hub - _wake_inflow(vehicle, loads, pos, axes, V_hub, kappa)
        rotor_force, rotor_moment, loads, batches = _rotor_wrenches(vehicle, params, V_wake, _hub_frames(V_wake, axes),
                                                                    om, **solve)
    # the arms' moments r_i x F_i and the gyroscopic and spin-up moments -w x (Omega_i h_i) - (dOmega_i/dt) h_i of the
    # rotors with a known inertia (h_i 0 for the others)
    hub_moments(pos, rotor_force, rotor_moment, w_rows, om_rows, h_spin, np.empty((0, n_rot)) if acc is None else acc)
    body = vehicle.body_drag if body_drag is None else body_drag
    body_force = np.zeros((N, 3))
    wash = None
    if body is not None and body.active:
        wash = np.mean([loads[i].v_i_mean[:, None] * axes[i] for i in range(n_rot)], axis=0)
        body_force = body_drag_force(body, v - wind_a, wash, air.rho)
    dF = dM = jac = None
    if wrt:
        dF, dM, jac = load_derivatives(wrt, vehicle, loads, batches, axes, pos, w, body, v - wind_a, wash, air.rho)
        if motion:
            jac = {} if jac is None else jac
            jac.update(motion_derivatives(wrt, hub_jac, axes, pos, h_spin, om, w, rotor_force.sum(axis=1), body,
                                           v - wind_a, wash, air.rho))
    return VehicleWrench(force=rotor_force.sum(axis=1) + body_force, moment=rotor_moment.sum(axis=1),
                         rotor_force=rotor_force, rotor_moment=rotor_moment, body_force=body_force,
                         loads=tuple(loads), force_domega=dF, moment_domega=dM, jacobian=jac)


def _checked_samples(velocity, angular_velocity, rotor_omega, wind, rotor_acceleration, n_rot: int):
    """vehicle_wrench's sample arrays, checked: (v, w, rotor_omega, wind, rotor_acceleration or None,
    N), each with 1 or N rows as given; ValueError for a rate out of [0, OMEGA_MAX], a rotor
    acceleration beyond ROTOR_ACCELERATION_MAX or row counts that differ."""
    v = _samples("velocity", velocity, 3)
    w = _samples("angular_velocity", angular_velocity, 3)
    om = _samples("rotor_omega", rotor_omega, n_rot)
    if (om < 0).any():
        n, i = np.argwhere(om < 0)[0]
        raise ValueError(f"rotor_omega must be >= 0 rad/s (the rate's magnitude; the sense is the rotor's spin), got "
                         f"{om[n, i]:g} for rotor {i + 1} (sample {n + 1})")
    if (om > OMEGA_MAX).any():
        n, i = np.argwhere(om > OMEGA_MAX)[0]
        raise ValueError(f"rotor_omega must be <= {OMEGA_MAX:g} rad/s, got {om[n, i]:g} for rotor {i + 1} (sample "
                         f"{n + 1}; rpm given for rad/s?)")
    wind_a = np.zeros((1, 3)) if wind is None else _samples("wind", wind, 3)
    acc = None if rotor_acceleration is None else _samples("rotor_acceleration", rotor_acceleration, n_rot)
    if acc is not None and (np.abs(acc) > ROTOR_ACCELERATION_MAX).any():  # (1e30 gave a yaw moment of 9.4e24 N m)
        n, i = np.argwhere(np.abs(acc) > ROTOR_ACCELERATION_MAX)[0]
        raise ValueError(f"rotor_acceleration must be within +-{ROTOR_ACCELERATION_MAX:g} rad/s^2, got {acc[n, i]:g} "
                         f"for rotor {i + 1} (sample {n + 1}; rpm/s or another unit given for rad/s^2?)")
    arrays = [v, w, om, wind_a] + ([] if acc is None else [acc])
    counts = {a.shape[0] for a in arrays} - {1}
    if len(counts) > 1:
        raise ValueError(f"velocity, angular_velocity, rotor_omega, wind and rotor_acceleration must have the same "
                         f"number of samples (or one), got {[a.shape[0] for a in arrays]}")
    N = counts.pop() if counts else 1
    return v, w, om, wind_a, acc, N


def _check_hub_speed(speed: np.ndarray) -> None:
    """Refuse hub airspeeds (N, n_rot) beyond AIRSPEED_MAX or not finite (w x r or v - wind
    overflowing to inf - inf), naming the rotor and the sample."""
    if speed.size and not speed.max() <= AIRSPEED_MAX:  # (NaN too)
        n, i = np.argwhere(~(speed <= AIRSPEED_MAX))[0]
        raise ValueError(f"rotor {i + 1}'s hub airspeed |v + w x r - wind| is {speed[n, i]:.4g} m/s at sample {n + 1}, "
                         f"beyond the model's {AIRSPEED_MAX:g} m/s (velocity, angular_velocity and wind in m/s and "
                         "rad/s?)" if speed[n, i] > AIRSPEED_MAX else
                         f"rotor {i + 1}'s hub velocity v + w x r - wind is not finite at sample {n + 1} (it "
                         "overflows; velocity, angular_velocity and wind in m/s and rad/s?)")


def _check_derivative_points(kappa: float, om: np.ndarray) -> None:
    """Refuse derivatives with rotor interference (the wakes couple the rotors' speeds) or at a
    parked rotor (below OMEGA_MIN its loads are not differentiated)."""
    if kappa > 0 and om.shape[1] > 1:
        raise ValueError("derivatives are not implemented with rotor_interference > 0 (the rotors' wakes couple "
                         "their speeds); set the vehicle's rotor_interference to 0")
    if np.any(om < OMEGA_MIN):
        n, i = np.argwhere(om < OMEGA_MIN)[0]
        raise ValueError(f"derivatives need every rotor_omega >= {OMEGA_MIN:g} rad/s (below it a rotor's blades are "
                         f"parked and its loads are not differentiated), got {om[n, i]:g} for rotor {i + 1} (sample "
                         f"{n + 1})")


def _wake_inflow(vehicle: Vehicle, loads, pos: np.ndarray, axes: np.ndarray, V_hub: np.ndarray,
                 kappa: float) -> np.ndarray:
    """The velocity (N, n_rot, 3) the other rotors' wakes induce at each hub, from the rotors'
    mean inflow in ``loads`` (core/interference.py); a failed point (on_failure="flag") induces
    nothing."""
    from ..core.interference import interference_inflow

    radii = np.array([r.propeller.radius for r in vehicle.rotors])
    v_i = np.stack([ld.v_i_mean for ld in loads], axis=1)
    v_i = np.where(np.isfinite(v_i), v_i, 0.0)
    return interference_inflow(pos, axes, radii, V_hub, v_i, kappa)


def _hub_frames(V_hub: np.ndarray, axes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The disk frames (unit axes z, shape (N, n_rot, 3), speeds and incidences, shape (N, n_rot))
    of the hubs moving at ``V_hub`` (N, n_rot, 3) with the rotors' ``axes`` (n_rot, 3):
    :func:`propmap.core.vector.disk_frame`'s arithmetic, without its checks of a user's input (a
    non-finite hub velocity gives a NaN or infinite speed, which vehicle_wrench refuses)."""
    a = np.empty(V_hub.shape)  # (filled: np.broadcast_to's view cost 3 us, and the compiled loop takes a copy)
    a[...] = axes
    return checked_frame(V_hub, a)


def _rotor_wrenches(vehicle: Vehicle, params: SectionParams, V_hub, frame, om, *, air, discretization, on_failure,
                    derivatives=()):
    """Each rotor's force and hub moment (body axes) and loads at hub velocities ``V_hub``
    (N, n_rot, 3) with the disk frames ``frame`` (:func:`_hub_frames`): one solver call per distinct
    (propeller, parameter set), all its rotors' samples together; and those calls as (rotor
    indices, their loads of shape (N, k), the disk frames' velocity and axis, shape (N, k, 3)),
    for the Jacobians' batched algebra."""
    N, n_rot = om.shape
    spins = np.array([r.spin for r in vehicle.rotors])
    groups: dict[tuple[int, int], list[int]] = {}  # rotors of one propeller and set, solved in one batch
    for i, r in enumerate(vehicle.rotors):
        p = r.params if r.params is not None else params
        key = (id(r.propeller), id(p))  # (the same objects: no comparison, the common case of a file's rotors)
        if key not in groups:
            key = next((k for k, idx in groups.items() if _same_rotor_model(vehicle.rotors[idx[0]], r, params)), key)
        groups.setdefault(key, []).append(i)
    rotor_force = np.empty((N, n_rot, 3))
    rotor_moment = np.empty((N, n_rot, 3))
    loads: list[RotorLoads | None] = [None] * n_rot
    batches = []
    for idx in groups.values():
        rot = vehicle.rotors[idx[0]]
        p = rot.params if rot.params is not None else params
        sel = slice(None) if len(idx) == n_rot else idx  # (every rotor, in order: views, not copies)
        Vd, z, speed, beta = V_hub[:, sel], frame[0][:, sel], frame[1][:, sel], frame[2][:, sel]  # (N, k, 3), (N, k)
        r = rotor_loads(rot.propeller, p, om[:, sel], speed, beta, air=air, discretization=discretization,
                        on_failure=on_failure, derivatives=derivatives or False)
        F, M = wrench_vectors(r.thrust, r.drag, r.torque, r.rolling_moment, Vd, z, spins[sel],
                              side_force=r.side_force, pitching_moment=r.pitching_moment)
        rotor_force[:, sel, :] = F
        rotor_moment[:, sel, :] = M
        for i, column in zip(idx, _columns(r)):
            loads[i] = column
        batches.append((idx, r, Vd, z))
    return rotor_force, rotor_moment, loads, batches


def rotors_in_other_air(vehicle: Vehicle, air: Air) -> list[tuple[int, float]]:
    """The rotors whose own parameter set carries another air than the one every rotor is solved
    in (said by :func:`vehicle_wrench`, :func:`hover_omega`, ``trim_vehicle`` and the vehicle
    commands).

    Parameters
    ----------
    vehicle : Vehicle
    air : Air
        The air every rotor is solved in.

    Returns
    -------
    list of (int, float)
        Per such rotor, its number from 1 and its set's density [kg/m^3], in rotor order.

    Raises
    ------
    AttributeError
        ``vehicle`` without rotors (not a :class:`Vehicle`; the callers check it).
    """
    return [(k + 1, r.params.air.rho) for k, r in enumerate(vehicle.rotors)
            if r.params is not None and getattr(r.params, "air", air) != air]


def _warn_rotor_air(vehicle: Vehicle, air: Air) -> None:
    """Warn where a rotor's own parameter set carries another air than the one every rotor is
    solved in, the parameter set's where no air is given (it was dropped silently: a rotor's set
    at rho 1.0 made 25% more thrust than in its own air, a user-level audit)."""
    other = rotors_in_other_air(vehicle, air)
    if other:
        import warnings

        k, rho = other[0]
        warnings.warn(f"rotor {k} has its own parameter set in other air (rho {rho:.4g} kg/m^3"
                      f"{f', and {len(other) - 1} more rotor(s)' if len(other) > 1 else ''}): every rotor is solved in "
                      f"one air, the parameter set's (rho {air.rho:.4g} kg/m^3); give air= to choose it",
                      UserWarning, stacklevel=3)


def _same_rotor_model(a: Rotor, b: Rotor, params: SectionParams) -> bool:
    """Whether rotors ``a`` and ``b`` have the same parameter set by value and the same blade
    geometry (:meth:`Propeller.same_geometry`; a vehicle file reads each rotor's propeller on its
    own, so that grouping by identity solved the NeuroBEM quadrotor's four rotors in four
    batches: 1.6 ms a sample)."""
    pa = a.params if a.params is not None else params
    pb = b.params if b.params is not None else params
    if not (pa is pb or pa == pb):  # (the sets' air is one of their fields)
        return False
    return a.propeller is b.propeller or a.propeller.same_geometry(b.propeller)


def _columns(r: RotorLoads) -> list[RotorLoads]:
    """The columns of loads of shape (N, k_rotors): each rotor's RotorLoads of shape (N,) (the
    fields to split found once, not per rotor)."""
    base = vars(r)
    names = [n for n, a in base.items() if n != "r" and type(a) is np.ndarray and a.ndim >= 2]
    # each field's columns a[:, k] in one call (iterating over a.swapaxes(0, 1)), not one indexing per field and rotor
    columns = zip(*(base[n].swapaxes(0, 1) for n in names))
    jac = r.jacobian
    jac_columns = zip(*(a.swapaxes(0, 1) for a in jac.values())) if jac is not None else None
    out = []
    for values in columns:
        fields_k = base.copy()  # (replace() would run the dataclass's __init__ again: 7 us a rotor)
        fields_k.update(zip(names, values))
        if jac is not None:
            fields_k["jacobian"] = dict(zip(jac, next(jac_columns, ())))  # (an empty Jacobian: empty dicts)
        out.append(_new_loads(fields_k))
    return out


def hover_omega(vehicle: Vehicle, params: SectionParams, *, air: Air | None = None,
                discretization: Discretization = DEFAULT_DISCRETIZATION) -> float:
    """The rotor speed at which the vehicle hovers in still air, every rotor at the same speed.

    Solves F_z(Omega) = m g for Omega, F_z the body-up force of :func:`vehicle_wrench` at rest
    in still air with every rotor at Omega: sum_i T_i (a_i . e_z), T_i the static thrust of
    rotor i's propeller (a rotor's own ``params`` where it has them), a_i its axis, e_z body
    up, plus the airframe's drag in the rotors' slipstream (``BodyDrag.wash_factor`` > 0: a
    downward force in hover, which the rotors must also carry) and the rotors' interference
    (``Vehicle.rotor_interference``), as the vehicle model has them.

    Parameters
    ----------
    vehicle : Vehicle
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization
        Nodes of the static solves (default: the solver's).

    Returns
    -------
    float
        Omega [rad/s].

    Raises
    ------
    ValueError
        The rotors give no upward thrust (axes with a_i . e_z <= 0), or the weight needs
        more than the solver's 1e5 rad/s or less than 0.1 rad/s.
    SolverError
        A static solve fails (as :func:`propmap.rotor_loads`).
    TypeError
        ``vehicle`` not a :class:`Vehicle`, ``params`` not a parameter set, ``air`` not an
        :class:`Air`.

    Warns
    -----
    TipMachWarning
        A hover whose blade tips meet the air beyond Mach 0.8 (the solver's TIP_MACH_WARN: a
        mass in grams, 1200 for 1.2 kg, hovered at tip Mach 3.7 without a word).
    UserWarning
        Without ``air``: a rotor whose own parameter set carries other air than ``params``
        (every rotor is solved in one air, ``params``'s), as :func:`vehicle_wrench`.
    """
    from scipy.optimize import brentq

    check_vehicle(vehicle)
    given = air is not None
    air = model_air(params, air)
    if not given:  # (as vehicle_wrench: a rotor's set in other air was dropped without a word, an air audit)
        _warn_rotor_air(vehicle, air)
    up = np.array([float(r.axis[2]) / float(np.linalg.norm(r.axis)) for r in vehicle.rotors])  # a_i . e_z, a_i unit
    if not np.any(up > 0):
        raise ValueError("no rotor's axis has an upward component: the vehicle cannot hover")

    rest = np.zeros(3)

    solved = {}  # (the bracket's ends, each solved once: the search's and brentq's)

    def lift(om: float) -> float:
        if om in solved:
            return solved[om]
        with supersonic_tips_allowed():  # the bracket doubles past the hover rate on purpose
            w = vehicle_wrench(vehicle, params, rest, rest, np.full(len(vehicle.rotors), om), air=air,
                               discretization=discretization)
        solved[om] = float(w.force[0, 2]) - vehicle.weight
        return solved[om]

    hi = 100.0
    while lift(hi) < 0:  # (doubled up to the solver's limit itself: it stopped at 51,200 rad/s, an API audit)
        if hi >= OMEGA_MAX:
            raise ValueError(f"the vehicle's weight {vehicle.weight:.4g} N needs more than {OMEGA_MAX:.4g} rad/s of "
                             "its rotors (the solver's limit): check its mass and propellers")
        hi = min(2 * hi, OMEGA_MAX)
    lo = 0.1 if hi == 100.0 else hi / 2
    if lift(lo) >= 0:  # (brentq's own message named no input: a user-level audit, 2026-11-28)
        raise ValueError(f"the vehicle's weight {vehicle.weight:.4g} N is carried below {lo:g} rad/s of its rotors, "
                         "where a rotor is a parked blade (the solver's rates start at 0.1 rad/s): check its mass "
                         f"({vehicle.mass:g} kg) and propellers")
    omega = float(brentq(lift, lo, hi, xtol=1e-9, rtol=1e-12))
    mach = omega * max(r.propeller.radius for r in vehicle.rotors) / air.speed_of_sound
    if mach > TIP_MACH_WARN:  # (the search turned the solver's tip check off: the answer is checked here)
        import warnings

        warnings.warn(f"{SUPERSONIC_TIP} {mach:.3g} in this hover (Omega {omega:.4g} rad/s, {omega / RPM:.0f} "
                      f"rpm): is the vehicle's mass {vehicle.mass:g} kg in kg, and its rotors the ones it flies?",
                      TipMachWarning, stacklevel=2)
    return omega
