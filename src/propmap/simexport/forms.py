"""Simulators' simple rotor models: what each target evaluates, and propmap's evaluation of it.

The coefficients are fitted to propmap's full model in :mod:`propmap.simexport.fit`.

Notation: Omega [rad/s], V [m/s], incidence beta,
V_ip = V sin(beta) (in-plane), V_z = V cos(beta) (axial, positive in climb), R the tip
radius. Sources of the model forms (each checked against the simulator's source):

* ``rotorpy`` -- RotorPy (Folk et al., "RotorPy: a Python-based multirotor simulator with
  aerodynamics", 2023; ``rotorpy/vehicles/multirotor.py``, ``Multirotor.compute_body_wrench``
  of release 3.0.0): T = k_eta Omega^2 + k_h V_ip^2 - k_z Omega V_z, rotor drag
  D = k_d Omega V_ip, yaw moment rotor_dir k_m Omega^2 about +z, flapping moment
  -k_flap Omega (v x z). The flapping moment acts about the pitching axis z x e_ip (flapping
  blades' tilted disk); propmap's model with rigid blades and uniform inflow (the defaults) has
  none about that axis (docs/conventions.md), so k_flap = 0 (a set with flapping, a linear
  inflow model or the dynamic stall is warned about: its pitching moment and side force are
  left out),
  and propmap's rolling moment M_R (about e_ip) has no RotorPy term: its error is reported.
  RotorPy's ``rotor_directions`` entry is the sign of the reaction torque on the body about
  +z: -spin in propmap's convention
  (a "ccw" rotor, spin +1 about its thrust axis, is -1 there).
* ``gazebo-classic`` -- PX4-SITL_gazebo-classic's motor model
  (``src/gazebo_motor_model.cpp``, ``GazeboMotorModel::UpdateForcesAndMoments``):
  T = motorConstant Omega^2 clamp(1 - |V_z| / 25 m/s, 0, 1) (the plugin's fixed axial
  fade), drag torque -turning_direction momentConstant motorConstant Omega^2 (the unfaded
  thrust), D = rotorDragCoefficient |Omega| V_ip, rolling moment
  -|Omega| turning_direction rollingMomentCoefficient V_perp (turning_direction +1 for
  ccw; the turning direction since the plugin's pull request #809, 2021): propmap's
  -spin M_R e_ip for both turning directions.
* ``gz-sim`` -- gz-sim's MulticopterMotorModel system
  (``src/systems/multicopter_motor_model/MulticopterMotorModel.cc``): the same formulas
  without the axial fade (T = motorConstant Omega^2) and with the rolling moment
  -|Omega| rollingMomentCoefficient V_perp, not multiplied by the turning direction:
  right for a ccw rotor; a cw rotor needs the coefficient's negative (the written file
  gives both).
* ``multinomial`` -- a multinomial in the rotorcraft advance ratio mu = V_ip / (Omega R)
  and inflow ratio lambda_c = V_z / (Omega R), of the form of Gill & D'Andrea,
  "Computationally efficient force and moment models for propellers in UAV forward flight
  applications", Drones 3(4) 77, 2019 (a Taylor expansion of a BEMT model). Coefficients
  in the rotorcraft normalisation X = rho pi R^2 (Omega R)^2 C_X (R C_X for moments). The
  term set is propmap's choice from the symmetry of the azimuth-averaged model, not the
  paper's list (which this repository does not carry): C_T and C_Q even in mu,
  {1, lambda, lambda^2, mu^2, lambda^3, lambda mu^2}; C_H and C_R odd in mu,
  mu {1, lambda, lambda^2, mu^2}. (``gill2019``, its former name, is still accepted.)
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..core._inputs import _as_array
from ..core._numbers import checked

__all__ = ["ALIASES", "EVEN_TERMS", "GAZEBO_AXIAL_SPEED", "ODD_TERMS", "TARGETS", "canonical_target", "predict"]

TARGETS = ("rotorpy", "gazebo-classic", "gz-sim", "multinomial")
#: former names, still accepted: "gazebo" (the PX4 classic plugin) and "gill2019" (propmap's
#: multinomial, whose term set is not that paper's)
ALIASES = {"gazebo": "gazebo-classic", "gill2019": "multinomial"}
GAZEBO_AXIAL_SPEED = 25.0  # [m/s] PX4-SITL_gazebo-classic's fixed thrust fade with axial speed


def canonical_target(target: str) -> str:
    """``target``'s current name (a former name, :data:`ALIASES`, is mapped to it).

    Parameters
    ----------
    target : str
        One of :data:`TARGETS` or :data:`ALIASES`.

    Returns
    -------
    str
        One of :data:`TARGETS`.

    Warns
    -----
    FutureWarning
        For "gill2019".

    Raises
    ------
    ValueError
        Not a target.
    """
    if isinstance(target, str) and target in ALIASES:
        if target == "gill2019":
            warnings.warn("target 'gill2019' is now called 'multinomial': its term set is propmap's, not the list of "
                          "Gill & D'Andrea 2019", FutureWarning, stacklevel=3)
        return ALIASES[target]
    if target not in TARGETS:
        raise ValueError(f"target must be one of {', '.join(TARGETS)}, got {target!r:.60}")
    return target


#: the multinomial's terms (names as in the JSON file's terms_even / terms_odd)
EVEN_TERMS = ("1", "lambda", "lambda^2", "mu^2", "lambda^3", "lambda mu^2")
ODD_TERMS = ("mu", "mu lambda", "mu lambda^2", "mu^3")
#: each target's terms: a number, or a list of the multinomial's coefficients (one per term)
_TERMS = {"rotorpy": ("k_eta", "k_h", "k_z", "k_d", "k_m"),
          "gazebo-classic": ("motorConstant", "rotorDragCoefficient", "momentConstant", "rollingMomentCoefficient"),
          "multinomial": ("R", "rho", "CT", "CH", "CQ", "CR")}
_TERMS["gz-sim"] = _TERMS["gazebo-classic"]


def _checked_coefficients(target: str, coefficients) -> dict:
    """``coefficients`` with each of the target's terms a finite number (R and rho > 0) or, for the
    multinomial's CT, CQ (EVEN_TERMS) and CH, CR (ODD_TERMS), a list of one per term; a missing
    term: KeyError (a list of 2 was read by zip as 2 terms, R = 0 gave NaN loads, None met
    "'NoneType' object is not subscriptable": a bad-input audit, stop 104)."""
    if not hasattr(coefficients, "keys") or not hasattr(coefficients, "__getitem__"):
        raise TypeError(f"coefficients must be a dict of the {target} model's terms, got {type(coefficients).__name__}")
    out = {}
    for k in _TERMS[target]:
        if k not in coefficients:
            raise KeyError(f"coefficients has no {k!r}, a term of the {target} model (its terms: "
                           f"{', '.join(_TERMS[target])})")
        v, name = coefficients[k], f"coefficients[{k!r}]"
        if k in ("CT", "CQ", "CH", "CR"):
            n = len(EVEN_TERMS if k in ("CT", "CQ") else ODD_TERMS)
            if isinstance(v, (str, bytes)) or not hasattr(v, "__len__") or len(v) != n:
                raise ValueError(f"{name} must be a list of {n} numbers, one per term, got {v!r:.60}")
            out[k] = [checked(f"{name}[{i}]", x) for i, x in enumerate(v)]
        else:
            out[k] = checked(name, v, 0.0, low_open=True) if k in ("R", "rho") else checked(name, v)
    return out


def predict(target: str, coefficients: dict, omega, airspeed, incidence):
    """The simple model's (T, D, Q, M_R) [N, N, N m, N m] at Omega [rad/s], V [m/s], beta [rad].

    The formulas are those of the module docstring (what the target simulator evaluates),
    in propmap's scalar convention: D against the in-plane motion, Q opposing the rotation,
    M_R positive for more thrust on the advancing side; Omega > 0.

    Parameters
    ----------
    target : str
        One of :data:`TARGETS` (or a former name).
    coefficients : dict
        As :attr:`SimExport.coefficients` (or as read back from the written file).
    omega, airspeed, incidence : float or array_like
        Omega [rad/s], V [m/s], beta [rad]; broadcast together to a shape S.

    Returns
    -------
    tuple of 4 ndarray
        T, D, Q, M_R, shape S (M_R is zeros for rotorpy, which has no such term).

    Raises
    ------
    ValueError
        Unknown target; an input outside the range :func:`propmap.rotor_loads` takes, NaN, text or
        a bool (Omega in [0, OMEGA_MAX] rad/s, a magnitude; V in [0, AIRSPEED_MAX] m/s, a
        magnitude; beta in [0, pi] rad), or an Omega of 0 for the multinomial, whose terms divide
        by Omega R (NaN loads and, below 0, loads of the wrong sign before); inputs whose shapes
        do not broadcast; a term that is not a finite number (R, rho not > 0), or a multinomial
        list of another length than its terms'.
    KeyError
        ``coefficients`` without a term of the target's model.
    TypeError
        ``coefficients`` not a dict.
    """
    target = canonical_target(target)
    c = _checked_coefficients(target, coefficients)
    # (broadcast first: Q and M_R of rotorpy, T and Q of the Gazebo forms took omega's shape alone)
    # (each checked as rotor_loads checks it: a negative airspeed gave a negative drag, NaN NaN loads and "800" was
    # read as 800, an export audit)
    arrays = [_as_array(k, x) for k, x in (("omega", omega), ("airspeed", airspeed), ("incidence", incidence))]
    try:
        om, V, b = np.broadcast_arrays(*arrays)
    except ValueError as exc:  # (NumPy's words alone, naming no input, until stop 104: as rotor_loads words it)
        raise ValueError(f"omega, airspeed and incidence must broadcast together: {exc}") from None
    # (below 0 and NaN refused above, as rotor_loads refuses them; the multinomial is singular at 0 as well)
    if target == "multinomial" and np.any(om == 0):
        raise ValueError(f"omega must be > 0 rad/s for the {target} model (the rotation rate's magnitude), got 0.0")
    Vip, Vz = V * np.sin(b), V * np.cos(b)
    if target == "rotorpy":
        T = c["k_eta"] * om**2 + c["k_h"] * Vip**2 - c["k_z"] * om * Vz
        return T, c["k_d"] * om * Vip, c["k_m"] * om**2, 0.0 * om
    if target in ("gazebo-classic", "gz-sim"):
        fade = np.clip(1.0 - np.abs(Vz) / GAZEBO_AXIAL_SPEED, 0.0, 1.0) if target == "gazebo-classic" else 1.0
        T0 = c["motorConstant"] * om**2
        return (T0 * fade, c["rotorDragCoefficient"] * om * Vip, c["momentConstant"] * T0,
                c["rollingMomentCoefficient"] * om * Vip)
    R, rho = c["R"], c["rho"]
    mu, lam = Vip / (om * R), Vz / (om * R)
    q = rho * math.pi * R**2 * (om * R) ** 2
    even = [np.ones_like(mu), lam, lam**2, mu**2, lam**3, lam * mu**2]
    odd = [mu, mu * lam, mu * lam**2, mu**3]

    def poly(coef, terms):
        return sum(k * t for k, t in zip(coef, terms))

    return (q * poly(c["CT"], even), q * poly(c["CH"], odd), q * R * poly(c["CQ"], even),
            q * R * poly(c["CR"], odd))
