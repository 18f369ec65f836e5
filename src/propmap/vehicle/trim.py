"""A multirotor trimmed in steady straight flight: the attitude and rotor speeds at which the
vehicle model's force balances the weight and its moment about the centre of mass vanishes.

Body frame x forward, y left, z up (vehicle/model.py); the flight path along the world's x
axis (the vehicle flies nose first), climbing at ``climb_rate``, in still air. The attitude is
roll phi (right side down positive) and pitch theta (nose up positive), yaw 0: the body axes
are R = R_y(-theta) R_x(phi) of the world's (R_y(-theta) pitches the nose up about the left
axis y). The equations, six, are the steady-flight case of a rigid body's equations of motion
(B. Etkin and L. D. Reid, Dynamics of Flight: Stability and Control, 3rd ed., 1996), with the
rotors' forces and moments of :func:`~propmap.vehicle.vehicle_wrench` in place of an
aircraft's:

    F(v_b, Omega) + m R^T g = 0,    M(v_b, Omega) = 0,    v_b = R^T (V, 0, V_c),

in the unknowns phi, theta and the n rotor speeds Omega_i, solved by SciPy's trust-region
least squares from every rotor at the hover speed Omega_h of :func:`~propmap.vehicle.hover_omega`.
A quadrotor has as many unknowns as equations. A vehicle with more rotors has more, and many
trims: the one returned is the nearest to the hover speed, the least sum of (Omega_i / Omega_h -
1)^2 under the six equations (SciPy's SLSQP from the least-squares solution), as a flight
controller's pseudo-inverse allocation shares a load among redundant rotors to first order.
Until 2026-11-28 it was wherever the least-squares search ended: for a hexacopter with its
centre of mass 5 cm forward, 2 cm left, a sum of 0.226 at 15 m/s against 0.124, one rotor at
0.66 Omega_h where the nearest trim has 0.86 (a review had found it).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ..core._numbers import checked
from ..core.airfoil import Air, SectionParams
from ..core.air import SUPERSONIC_TIP, TipMachWarning
from ..core.flapping import flapping_warning_held
from ..core.solver import (DEFAULT_DISCRETIZATION, OMEGA_MAX, OMEGA_MIN, TIP_MACH_WARN, Discretization,
                           model_air, supersonic_tips_allowed)
from .layout import Vehicle, body_to_world, check_vehicle
from .model import VehicleWrench, _warn_rotor_air, hover_omega, vehicle_wrench

__all__ = ["VehicleTrim", "trim_vehicle"]

#: the balance a trim must reach: force within this fraction of the weight, moment within it times the weight
#: times the largest arm
TRIM_TOL = 1e-7
#: the attitude's search range [rad] (a multirotor beyond 80 deg of tilt is not in steady flight)
TILT_MAX = math.radians(80.0)


@dataclass(frozen=True)
class VehicleTrim:
    """A trimmed steady flight (:func:`trim_vehicle`).

    Attributes
    ----------
    airspeed, climb_rate : float
        The flight [m/s]: speed along the path and its vertical part (the path along the
        world's x axis).
    roll, pitch : float
        Attitude [rad]: roll right side down positive, pitch nose up positive (a vehicle
        flying forward pitches nose down: negative).
    rotor_omega : ndarray, shape (n_rotors,)
        Rotor speeds [rad/s], in the vehicle's rotor order (with more than four rotors, the trim
        nearest the hover speed: module docstring).
    velocity : ndarray, shape (3,)
        The flight's velocity in body axes [m/s] (vehicle_wrench's ``velocity``).
    power : float
        Shaft power of the rotors, sum of Q_i Omega_i [W].
    wrench : VehicleWrench
        The vehicle model at the trim (one sample): its force balances the weight, its
        moment vanishes, within TRIM_TOL.
    """

    airspeed: float
    climb_rate: float
    roll: float
    pitch: float
    rotor_omega: np.ndarray
    velocity: np.ndarray
    power: float
    wrench: VehicleWrench


#: a trimmed rotor below this fraction of the hover rate is warned of as (nearly) stopped
STOPPED_FRACTION = 0.05

def trim_vehicle(vehicle: Vehicle, params: SectionParams, airspeed: float, climb_rate: float = 0.0, *,
                 air: Air | None = None, discretization: Discretization = DEFAULT_DISCRETIZATION) -> VehicleTrim:
    """Attitude and rotor speeds of steady straight flight (module docstring).

    Parameters
    ----------
    vehicle : Vehicle
        Its airframe drag (``vehicle.body_drag``) and rotor interference are those of the file.
    params : AirfoilParams or CamberedParams
        The rotors' parameter set (a rotor with its own ``params`` uses those).
    airspeed : float
        Speed along the flight path [m/s], in [0, 100] (still air: airspeed and ground speed
        alike).
    climb_rate : float
        Its vertical part [m/s], |climb_rate| <= airspeed (0: level flight; negative:
        descent). The horizontal part is sqrt(airspeed^2 - climb_rate^2).
    air : Air, optional
        Default: the parameter set's.
    discretization : Discretization

    Returns
    -------
    VehicleTrim
        The attitude, rotor speeds, body-axis velocity, shaft power and the model's wrench at
        the trim.

    Raises
    ------
    TypeError
        ``vehicle`` not a Vehicle (read a file or a bundled name with :func:`read_vehicle`).
    ValueError
        ``airspeed`` or ``climb_rate`` not a finite number in range (the message names it);
        the vehicle cannot hover (:func:`~propmap.vehicle.hover_omega`); no attitude within 80
        deg and rotor speeds within the solver's range balance it as far as the search from the
        hover goes (the message gives the balance reached).
    SolverError
        A rotor solve fails (:func:`propmap.rotor_loads`).

    Warns
    -----
    UserWarning
        A trim whose advancing blade tips meet the air beyond Mach 0.8, with a rotor in the
        vortex-ring state (descent: momentum theory is not predictive there, docs/models.md), or
        with a rotor below STOPPED_FRACTION of the hover rate (spins that do not balance in yaw);
        :func:`hover_omega`'s warnings.
    FlappingWarning
        Once, where the trim's blades flap beyond the small-angle range (not at the search's
        trial points).

    Notes
    -----
    Costs 15-50 vehicle_wrench calls of one sample (n_rotors + 3 each iteration of the
    differenced Jacobian), besides hover_omega's: the NeuroBEM quadrotor 15 at rest and 43-50 at
    5-15 m/s, 0.04-0.12 s (2-core AMD EPYC, 2026-11-28). With more than four rotors the search
    for the nearest trim adds about 10 calls per SLSQP iteration: a hexacopter with an offset
    centre of mass 74-93 calls in 7-9 iterations, 0.16-0.22 s. The balance leaves out what the
    vehicle model leaves out: the airframe's aerodynamic moment (its drag acts at the centre of
    mass) and, unless the vehicle file sets ``rotor_interference``, the rotors' wakes on each
    other.
    """
    from scipy.optimize import least_squares

    check_vehicle(vehicle)
    V = checked("airspeed", airspeed, 0.0, 100.0, unit="m/s")  # (the text "5" was 5 m/s, a user-level audit)
    Vc = checked("climb_rate", climb_rate, -V if V else 0.0, V, unit="m/s (|climb_rate| <= airspeed)")
    Vh = math.sqrt(max(V * V - Vc * Vc, 0.0))
    n = len(vehicle.rotors)
    if air is None:  # (resolved once: hover_omega and vehicle_wrench each said the rotors' other air, twice)
        air = model_air(params, None)
        _warn_rotor_air(vehicle, air)
    om_h = hover_omega(vehicle, params, air=air, discretization=discretization)
    weight = vehicle.weight
    arm = max(float(np.linalg.norm(r.position - vehicle.centre_of_mass)) for r in vehicle.rotors) or 1.0
    still = np.zeros(3)

    def state(x):
        R = body_to_world(x[1], x[0])
        v_b = R.T @ np.array([Vh, 0.0, Vc])
        g_b = R.T @ np.array([0.0, 0.0, -weight])
        return v_b, g_b

    def balance(x):
        v_b, g_b = state(x)
        w = vehicle_wrench(vehicle, params, v_b, still, x[2:] * om_h, air=air, discretization=discretization)
        return np.concatenate([(w.force[0] + g_b) / weight, w.moment[0] / (weight * arm)]), v_b, w

    x0 = np.concatenate([[0.0, 0.0], np.ones(n)])
    lo = np.concatenate([[-TILT_MAX, -TILT_MAX], np.full(n, OMEGA_MIN / om_h)])
    hi = np.concatenate([[TILT_MAX, TILT_MAX], np.full(n, OMEGA_MAX / om_h)])
    # (the search may try fast or flapping rotors on its way; the trim is checked below, and its wrench says the rest)
    with supersonic_tips_allowed(), flapping_warning_held():
        x = least_squares(lambda x: balance(x)[0], x0, bounds=(lo, hi), method="trf",
                          x_scale=np.concatenate([[0.1, 0.1], np.ones(n)]), xtol=1e-14, ftol=1e-14, gtol=1e-14,
                          max_nfev=200).x
        r = balance(x)[0]
        if n > 4 and np.max(np.abs(r)) <= TRIM_TOL:  # more unknowns than equations: the nearest trim, if it balances
            y = _nearest_trim(lambda x: balance(x)[0], x, lo, hi)
            if y is not None:
                ry = balance(y)[0]
                if np.all(np.isfinite(ry)) and np.max(np.abs(ry)) <= TRIM_TOL:
                    x = y
    with supersonic_tips_allowed():
        r, v_b, w = balance(x)  # (the trim's wrench, kept: its flapping warned of once)
    if not np.all(np.isfinite(r)) or np.max(np.abs(r)) > TRIM_TOL:
        raise ValueError(f"airspeed {V:g} m/s, climb_rate {Vc:g} m/s: no trim found from the hover (the force "
                         "balance reached "
                         f"{np.max(np.abs(r[:3])):.3g} of the weight, the moment {np.max(np.abs(r[3:])):.3g} of the "
                         f"weight times the largest arm, at roll {math.degrees(x[0]):.3g} deg, pitch "
                         f"{math.degrees(x[1]):.3g} deg), where the search ended: beyond what the rotors balance, "
                         "or a trim the search does not reach")
    omega = x[2:] * om_h
    power = float(sum(float(ld.power[0]) for ld in w.loads))
    tip = max(om * rot.propeller.radius + V for om, rot in zip(omega, vehicle.rotors))  # (the advancing tip's)
    mach = tip / air.speed_of_sound
    ring = [k + 1 for k, ld in enumerate(w.loads) if bool(np.asarray(ld.vortex_ring).reshape(-1)[0])]
    if ring:
        warnings.warn(f"rotor(s) {', '.join(map(str, ring))} trim in the vortex-ring state (climb_rate {Vc:g} m/s): "
                      "momentum theory is not predictive there (docs/models.md), so this trim is rough",
                      UserWarning, stacklevel=2)
    parked = [k + 1 for k, om in enumerate(omega) if om < STOPPED_FRACTION * om_h]
    if parked:  # (two of a ccw, ccw, ccw, cw quad's rotors stopped, balancing yaw, printed as 1 rpm unsaid: an audit)
        warnings.warn(f"rotor(s) {', '.join(map(str, parked))} (nearly) stopped in this trim, below "
                      f"{STOPPED_FRACTION:.0%} of the hover rate: the others alone balance it; do the spins balance "
                      "in yaw?", UserWarning, stacklevel=2)
    if mach > TIP_MACH_WARN:
        warnings.warn(f"{SUPERSONIC_TIP} {mach:.3g} in this trim (airspeed {V:g} m/s, rotors up to {max(omega):.4g} "
                      "rad/s): these loads mean little", TipMachWarning, stacklevel=2)
    return VehicleTrim(V, Vc, float(x[0]), float(x[1]), omega, v_b, power, w)


def _nearest_trim(balance, x, lo, hi):
    """Of the trims of a vehicle with more rotors than four (unknowns x = roll, pitch, Omega_i /
    Omega_h), the one of least sum (Omega_i / Omega_h - 1)^2, by SciPy's SLSQP from the trim
    ``x`` under the balance's six equations (``balance(x) = 0``) and the bounds; None where SLSQP
    fails (the caller keeps ``x`` where the result does not balance within TRIM_TOL)."""
    from scipy.optimize import minimize

    res = minimize(lambda x: float(np.sum((x[2:] - 1.0) ** 2)), x, method="SLSQP",
                   jac=lambda x: np.concatenate([[0.0, 0.0], 2.0 * (x[2:] - 1.0)]),
                   constraints={"type": "eq", "fun": balance}, bounds=list(zip(lo, hi)),
                   options={"ftol": 1e-14, "maxiter": 50})
    return res.x if res.success and np.all(np.isfinite(res.x)) else None
