"""Simulator coefficients: the simple rotor models of common simulators fitted to propmap.

Each target is a closed-form rotor model that a simulator evaluates; its coefficients are
fitted by linear least squares to the full model (propmap's BET/BEMT) over an envelope of
operating points, and its error against the full model over that envelope is reported, so
that a user sees what the simple model costs. Notation: Omega [rad/s], V [m/s], incidence
beta, V_ip = V sin(beta) (in-plane), V_z = V cos(beta) (axial, positive in climb), R the tip
radius. Sources of the model forms:

* ``rotorpy`` -- RotorPy (Folk et al., "RotorPy: a Python-based multirotor simulator with
  aerodynamics", 2023; its multirotor model): T = k_eta Omega^2 + k_h V_ip^2 - k_z Omega
  V_z, rotor drag D = k_d Omega V_ip, yaw moment Q = k_m Omega^2, flapping moment
  -k_flap Omega (v x z). The flapping moment acts about z x e_ip (a pitch-back moment of
  flapping blades); propmap's rigid-blade, azimuth-uniform-inflow model has none about
  that axis (docs/conventions.md), so k_flap = 0, and propmap's rolling moment M_R (about
  e_ip) has no RotorPy term: its error is reported.
* ``gazebo`` -- the PX4 SITL Gazebo motor model (gazebo_motor_model plugin):
  T = motorConstant Omega^2 max(0, 1 - |V_z| / 25 m/s) (the plugin's fixed axial scaling),
  Q = momentConstant motorConstant Omega^2 (the plugin multiplies momentConstant by the
  thrust before the axial fade), D = rotorDragCoefficient Omega V_ip, rolling moment
  M_R = rollingMomentCoefficient Omega V_ip. PX4-SITL_gazebo-classic's
  src/gazebo_motor_model.cpp applies the rolling moment as -|Omega| turning_direction
  rollingMomentCoefficient V_perp (turning_direction +1 for ccw) since its pull request #809
  (2021, "Modified the rolling moment formula of rotor"): propmap's -spin M_R e_ip for both
  turning directions. gz-sim's MulticopterMotorModel (src/systems/multicopter_motor_model)
  applies -|Omega| rollingMomentCoefficient V_perp without the turning direction, as the
  PX4 plugin did before #809: right for a ccw rotor, the opposite sign for a cw one.
* ``gill2019`` -- a multinomial in the rotorcraft advance ratio mu = V_ip / (Omega R) and
  inflow ratio lambda_c = V_z / (Omega R), the form of Gill & D'Andrea, "Computationally
  efficient force and moment models for propellers in UAV forward flight applications",
  Drones 3(4) 77, 2019 (a Taylor expansion of a BEMT model). Coefficients in the
  rotorcraft normalisation X = rho pi R^2 (Omega R)^2 C_X (R C_X for moments). The term set
  is propmap's choice from the symmetry of the azimuth-averaged model (not the paper's
  list, which this repository does not carry): C_T and C_Q even in mu,
  {1, lambda, lambda^2, mu^2, lambda^3, lambda mu^2}; C_H and C_R odd in mu,
  mu {1, lambda, lambda^2, mu^2}.
"""

from __future__ import annotations

import json
import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import __version__
from .core.airfoil import Air
from .core.geometry import _real
from .core.solver import check_model_args, rotor_loads

__all__ = ["Envelope", "SimExport", "TARGETS", "default_envelope", "error_lines", "export_sim", "predict",
           "write_export"]

TARGETS = ("rotorpy", "gazebo", "gill2019")
GAZEBO_AXIAL_SPEED = 25.0  # [m/s] the PX4 Gazebo motor model's fixed thrust fade with axial speed
#: a term is fitted only if its dimensionless size (1; the advance ratio mu = V_ip/(Omega R),
#: the inflow ratio lambda_c = V_z/(Omega R), their powers and products; Gazebo's thrust
#: fade) reaches this somewhere in the envelope: a term below it changes its load by less
#: than about 0.1% there, and its coefficient would be fitted to round-off (a coefficient of
#: 1e294 from an envelope of airspeed 0 to 1e-300 m/s). Such a coefficient is fixed at 0 and
#: said (SimExport.fixed, a warning); one without which the model has no thrust or torque
#: refuses the envelope.
DETERMINED = 1e-3
#: the largest condition number of the fit's (column-normalised) design matrix: beyond it
#: the envelope cannot separate the terms (e.g. a single rpm and a single speed). The default
#: envelopes of the three targets give 1-4 on catalogue propellers; an envelope that is
#: nearly a point (rpm 5000-5000.001, airspeed 10-10.000001 m/s) gives 1.5e7, where 1e8 let
#: a coefficient be fitted to round-off and written without a word
MAX_CONDITION = 1e4
#: fewest converged points a fit takes
MIN_POINTS = 10


@dataclass(frozen=True)
class Envelope:
    """Operating points to fit over: uniform in rpm, airspeed and incidence.

    Attributes
    ----------
    rpm : (float, float)
        [rpm]
    airspeed : (float, float)
        [m/s]
    incidence_deg : (float, float)
        [deg], within [0, 180].
    """

    rpm: tuple
    airspeed: tuple = (0.0, 25.0)
    incidence_deg: tuple = (0.0, 180.0)

    def __post_init__(self) -> None:
        for name, (a, b) in (("rpm", (1.0, 954929.0)), ("airspeed", (0.0, 500.0)), ("incidence_deg", (0.0, 180.0))):
            value = getattr(self, name)
            pair = tuple(value) if isinstance(value, (tuple, list, np.ndarray)) else None
            if pair is None or len(pair) != 2 or any(_real(v) is None for v in pair):
                raise ValueError(f"envelope {name} must be two numbers (low, high), got {value!r:.60}")
            lo, hi = (_real(v) for v in pair)
            if not (math.isfinite(lo) and math.isfinite(hi) and a <= lo < hi <= b):
                raise ValueError(f"envelope {name} must satisfy {a:g} <= low < high <= {b:g}, got {lo!r}, {hi!r}")
            object.__setattr__(self, name, (lo, hi))


@dataclass
class SimExport:
    """Fitted coefficients of one target and their error against the full model.

    Attributes
    ----------
    target : str
    coefficients : dict
        Name -> value in SI units (as the target's file writes them).
    errors : dict
        Per load (thrust, drag, torque, rolling_moment): rms and max of |simple - full|,
        normalised per point by the static thrust or torque at its Omega (T, Q) or the
        largest |D| or |M_R| of the envelope's points (D, M_R); over the points outside
        vortex ring and multiple roots, and apart over those inside.
    envelope : Envelope
    n_points : int
    meta : dict
        Propeller, parameters, model, propmap version.
    fixed : dict
        Coefficient name (``k_z``; ``CT[lambda^2]`` for gill2019) -> why the envelope
        cannot determine it; those are fixed at 0 (:data:`DETERMINED`).
    """

    target: str
    coefficients: dict
    errors: dict
    envelope: Envelope
    n_points: int
    meta: dict = field(default_factory=dict)
    fixed: dict = field(default_factory=dict)


def default_envelope(propeller) -> Envelope:
    """A multirotor's envelope for ``propeller``: rpm from a third of the rpm of a 150 m/s
    tip speed to it (tip speeds 50-150 m/s), V 0-15 m/s, incidence 0-180 deg (advance
    ratios J up to about 1)."""
    from .maps import default_axes

    rpm, _, _ = default_axes(propeller)
    return Envelope(rpm=(float(rpm[-1]) / 3, float(rpm[-1])), airspeed=(0.0, 15.0))


def _samples(propeller, params, air, envelope: Envelope, n: int, seed: int):
    rng = np.random.default_rng(seed)
    om = rng.uniform(*envelope.rpm, n) * math.pi / 30
    V = rng.uniform(*envelope.airspeed, n)
    b = np.radians(rng.uniform(*envelope.incidence_deg, n))
    full = rotor_loads(propeller, params, om, V, b, air=air, on_failure="flag")
    static = rotor_loads(propeller, params, om, 0.0, 0.0, air=air)
    ok = full.converged
    if ok.sum() < MIN_POINTS:
        raise ValueError(f"only {int(ok.sum())} of the envelope's {n} points converged; at least {MIN_POINTS} are needed "
                         "to fit (a larger envelope, or more points)")
    for k, v in (("thrust", static.thrust), ("torque", static.torque)):
        if not np.all(np.isfinite(v) & (v > 0)):
            raise ValueError(f"the model's static {k} is not positive at every rpm of the envelope "
                             f"({float(np.min(v)):.3g}): the fit, relative to it, cannot be normalised")
    flagged = full.vortex_ring | full.multiple_roots
    return {"omega": om[ok], "V": V[ok], "beta": b[ok], "flagged": flagged[ok],
            "thrust": full.thrust[ok], "drag": full.drag[ok], "torque": full.torque[ok],
            "rolling_moment": full.rolling_moment[ok], "T0": static.thrust[ok], "Q0": static.torque[ok]}


#: what each dimensionless term size is, for messages
_SIZE_TEXT = {"mu": "the advance ratio mu = V sin(beta) / (Omega R)",
              "lambda": "the inflow ratio lambda_c = V cos(beta) / (Omega R)",
              "fade": f"the plugin's thrust fade 1 - |V_z| / {GAZEBO_AXIAL_SPEED:g} m/s"}


def _lstsq(terms, y, fixed: dict, required=()):
    """Least squares of ``y`` on the terms that the envelope determines.

    Parameters
    ----------
    terms : list of (name, column, size, what)
        The coefficient's name, its column (weighted like ``y``), the term's
        dimensionless size at each point and what that size is (a key of _SIZE_TEXT,
        with a power: "mu^2").
    y : ndarray
    fixed : dict
        Receives name -> reason for each term left out (its coefficient 0).
    required : collection of str
        Terms without which the model has no thrust or torque: refused instead.

    Returns
    -------
    list of float
        One coefficient per term, 0 for those left out.

    Raises
    ------
    ValueError
        A required term below DETERMINED, or terms the envelope cannot separate.
    """
    keep = []
    for k, (name, col, size, what) in enumerate(terms):
        peak = float(np.max(np.abs(size)))
        if peak >= DETERMINED:
            keep.append(k)
            continue
        legend = "; ".join(text for key, text in _SIZE_TEXT.items() if key in what)
        why = (f"its term's size {what} ({legend}) stays below {DETERMINED:g} over the envelope "
               f"(at most {peak:.2g})")
        if name in required:
            raise ValueError(f"the envelope cannot determine {name}: {why}; widen the envelope")
        fixed[name] = why
    x = np.zeros(len(terms))
    if keep:
        A = np.column_stack([terms[k][1] for k in keep])
        scale = np.max(np.abs(A), axis=0)
        scale[scale == 0] = 1.0
        A = A / scale
        _, sv, vt = np.linalg.svd(A / np.maximum(np.linalg.norm(A, axis=0), 1e-300), full_matrices=False)
        if sv[-1] < sv[0] / MAX_CONDITION:
            mixed = [terms[k][0] for k, v in zip(keep, vt[-1]) if abs(v) > 0.1]
            raise ValueError(f"the envelope cannot separate {', '.join(mixed)} (condition number "
                             f"{sv[0] / max(sv[-1], 1e-300):.2g}): widen its rpm, airspeed or incidence range")
        sol, *_ = np.linalg.lstsq(A, y, rcond=None)
        x[keep] = sol / scale
    return [float(v) for v in x]


def _mu_lambda(s, R):
    tip = s["omega"] * R
    return s["V"] * np.sin(s["beta"]) / tip, s["V"] * np.cos(s["beta"]) / tip


#: gill2019's terms (names as in the JSON file's terms_even / terms_odd)
EVEN_TERMS = ("1", "lambda", "lambda^2", "mu^2", "lambda^3", "lambda mu^2")
ODD_TERMS = ("mu", "mu lambda", "mu lambda^2", "mu^3")


def _fit(target: str, s, R: float, rho: float, fixed: dict) -> dict:
    om, V, b = s["omega"], s["V"], s["beta"]
    Vip, Vz = V * np.sin(b), V * np.cos(b)
    mu, lam = _mu_lambda(s, R)
    one = np.ones_like(mu)
    # each load is fitted relative to its scale at the point (static value at that Omega), so
    # that low and high rpm count alike: divide both sides by the scale
    wT, wQ = 1 / s["T0"], 1 / s["Q0"]
    wD = 1 / max(float(np.max(np.abs(s["drag"]))), 1e-300)
    wR = 1 / max(float(np.max(np.abs(s["rolling_moment"]))), 1e-300)
    if target == "rotorpy":
        k_eta, k_h, k_z = _lstsq([("k_eta", om**2 * wT, one, "1"), ("k_h", Vip**2 * wT, mu**2, "mu^2"),
                                  ("k_z", -om * Vz * wT, lam, "lambda")], s["thrust"] * wT, fixed, {"k_eta"})
        (k_d,) = _lstsq([("k_d", om * Vip * wD, mu, "mu")], s["drag"] * wD, fixed)
        (k_m,) = _lstsq([("k_m", om**2 * wQ, one, "1")], s["torque"] * wQ, fixed, {"k_m"})
        return {"k_eta": k_eta, "k_m": k_m, "k_d": k_d, "k_z": k_z, "k_h": k_h, "k_flap": 0.0, "rotor_radius": R}
    if target == "gazebo":
        fade = np.maximum(0.0, 1.0 - np.abs(Vz) / GAZEBO_AXIAL_SPEED)
        (kT,) = _lstsq([("motorConstant", om**2 * fade * wT, fade, "fade")], s["thrust"] * wT, fixed,
                       {"motorConstant"})
        (kQ,) = _lstsq([("momentConstant", kT * om**2 * wQ, one, "1")], s["torque"] * wQ, fixed, {"momentConstant"})
        (kD,) = _lstsq([("rotorDragCoefficient", om * Vip * wD, mu, "mu")], s["drag"] * wD, fixed)
        (kR,) = _lstsq([("rollingMomentCoefficient", om * Vip * wR, mu, "mu")], s["rolling_moment"] * wR, fixed)
        return {"motorConstant": kT, "momentConstant": kQ, "rotorDragCoefficient": kD,
                "rollingMomentCoefficient": kR}
    if target == "gill2019":
        q = rho * math.pi * R**2 * (om * R) ** 2  # force scale; moments add R
        even = [one, lam, lam**2, mu**2, lam**3, lam * mu**2]
        odd = [mu, mu * lam, mu * lam**2, mu**3]
        out = {"R": R, "rho": rho}
        for key, terms, names, y, w, moment in (
                ("CT", even, EVEN_TERMS, s["thrust"], wT, False), ("CH", odd, ODD_TERMS, s["drag"], wD, False),
                ("CQ", even, EVEN_TERMS, s["torque"], wQ, True), ("CR", odd, ODD_TERMS, s["rolling_moment"], wR, True)):
            scale = q * (R if moment else 1.0)
            out[key] = _lstsq([(f"{key}[{n}]", t * scale * w, t, n) for t, n in zip(terms, names)], y * w, fixed,
                              {f"{key}[1]"})
        return out
    raise ValueError(f"target must be one of {', '.join(TARGETS)}, got {target!r}")


def predict(target: str, coefficients: dict, omega, airspeed, incidence):
    """The simple model's (T, D, Q, M_R) [N, N, N m, N m] at Omega [rad/s], V [m/s], beta [rad].

    The formulas are those of the module docstring (what the target simulator evaluates).

    Raises
    ------
    ValueError
        Unknown target.
    """
    om, V, b = (np.asarray(x, float) for x in (omega, airspeed, incidence))
    Vip, Vz = V * np.sin(b), V * np.cos(b)
    c = coefficients
    if target == "rotorpy":
        T = c["k_eta"] * om**2 + c["k_h"] * Vip**2 - c["k_z"] * om * Vz
        return T, c["k_d"] * om * Vip, c["k_m"] * om**2, 0.0 * om
    if target == "gazebo":
        T = c["motorConstant"] * om**2 * np.maximum(0.0, 1.0 - np.abs(Vz) / GAZEBO_AXIAL_SPEED)
        return (T, c["rotorDragCoefficient"] * om * Vip, c["momentConstant"] * c["motorConstant"] * om**2,
                c["rollingMomentCoefficient"] * om * Vip)
    if target == "gill2019":
        R, rho = c["R"], c["rho"]
        mu, lam = Vip / (om * R), Vz / (om * R)
        q = rho * math.pi * R**2 * (om * R) ** 2
        even = [np.ones_like(mu), lam, lam**2, mu**2, lam**3, lam * mu**2]
        odd = [mu, mu * lam, mu * lam**2, mu**3]

        def poly(coef, terms):
            return sum(k * t for k, t in zip(coef, terms))

        return (q * poly(c["CT"], even), q * poly(c["CH"], odd), q * R * poly(c["CQ"], even),
                q * R * poly(c["CR"], odd))
    raise ValueError(f"target must be one of {', '.join(TARGETS)}, got {target!r}")


def _errors(target: str, coefficients: dict, s) -> dict:
    T, D, Q, MR = predict(target, coefficients, s["omega"], s["V"], s["beta"])
    norm = {"thrust": np.abs(s["T0"]), "torque": np.abs(s["Q0"]),
            "drag": np.full_like(T, max(float(np.max(np.abs(s["drag"]))), 1e-300)),
            "rolling_moment": np.full_like(T, max(float(np.max(np.abs(s["rolling_moment"]))), 1e-300))}
    out = {}
    for k, pred in (("thrust", T), ("drag", D), ("torque", Q), ("rolling_moment", MR)):
        e = np.abs(pred - s[k]) / norm[k]
        ok, bad = e[~s["flagged"]], e[s["flagged"]]
        out[k] = {"rms": float(np.sqrt(np.mean(ok**2))) if ok.size else math.nan,
                  "max": float(np.max(ok)) if ok.size else math.nan,
                  "max_flagged": float(np.max(bad)) if bad.size else math.nan}
    out["normalisation"] = ("T by the static thrust and Q by the static torque at each point's Omega; D and M_R by "
                            "the largest |D|, |M_R| over the envelope; 'flagged': points in vortex ring or with "
                            "multiple roots")
    out["points_flagged"] = int(np.sum(s["flagged"]))
    return out


def report_path(path) -> Path:
    """The report written beside an export: ``<stem>.report.json`` (``c.json`` gets
    ``c.report.json``, not ``c.json.json``; the fit commands' convention)."""
    path = Path(path)
    return path.with_name(path.stem + ".report.json")


def export_sim(target: str, propeller, params, *, air: Air | None = None, envelope: Envelope | None = None,
               n_points: int = 4000, seed: int = 0, params_label: str = "") -> SimExport:
    """Fit ``target``'s coefficients to the full model over ``envelope`` and measure its error.

    Parameters
    ----------
    target : {"rotorpy", "gazebo", "gill2019"}
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: the parameter set's own (``.air``).
    envelope : Envelope, optional
        Default: :func:`default_envelope`.
    n_points : int
        Random operating points in the envelope (seeded), >= 20.
    seed : int
    params_label : str
        Recorded in the result.

    Returns
    -------
    SimExport

    Raises
    ------
    ValueError
        Unknown target; ``n_points`` not an integer in [20, 1,000,000]; ``seed`` not an
        integer >= 0; ``envelope`` not an Envelope; fewer than 10 converged points; a
        coefficient without which the model has no thrust or torque that the envelope
        cannot determine (:data:`DETERMINED`: e.g. Gazebo's motorConstant where the
        plugin's thrust fade is 0 at every point, |V_z| >= 25 m/s), or terms it cannot
        separate (:data:`MAX_CONDITION`).

    Warns
    -----
    UserWarning
        Each coefficient fixed at 0 because the envelope cannot determine it (also in
        ``SimExport.fixed``); an envelope whose every point is flagged (its errors
        outside flagged regions are NaN: nothing to measure them on).
    """
    air = getattr(params, "air", None) if air is None else air  # checked below
    check_model_args(propeller, params, air)
    if target not in TARGETS:
        raise ValueError(f"target must be one of {', '.join(TARGETS)}, got {target!r:.60}")
    for name, value, lo, hi in (("n_points", n_points, 20, 1_000_000), ("seed", seed, 0, 2**63 - 1)):
        x = _real(value)
        if x is None or not (math.isfinite(x) and x.is_integer() and lo <= x <= hi):
            raise ValueError(f"{name} must be an integer in [{lo}, {hi}], got {value!r:.60}")
    if envelope is None:
        envelope = default_envelope(propeller)
    elif not isinstance(envelope, Envelope):
        raise ValueError(f"envelope must be an Envelope or None, got {type(envelope).__name__}")
    s = _samples(propeller, params, air, envelope, int(n_points), int(seed))
    fixed: dict = {}
    coefficients = {k: (float(v) if not isinstance(v, list) else v)
                    for k, v in _fit(target, s, propeller.radius, air.rho, fixed).items()}
    for name, why in fixed.items():
        warnings.warn(f"{name} fixed at 0: {why}", UserWarning, stacklevel=2)
    errors = _errors(target, coefficients, s)
    if errors["points_flagged"] == s["omega"].size:
        warnings.warn(f"every one of the {s['omega'].size} points of the envelope is flagged (vortex ring or multiple "
                      "roots): no error outside flagged regions to report (n/a)", UserWarning, stacklevel=2)
    meta = {"propeller": propeller.name, "params": params_label or params.section_model,
            "section_model": params.section_model, "propmap_version": __version__,
            "model": "Gill & D'Andrea 2017 BET/BEMT (propmap)", "seed": int(seed)}
    return SimExport(target, coefficients, errors, envelope, int(s["omega"].size), meta, fixed)


def error_lines(res: SimExport, comment: str = "") -> list[str]:
    """The error table as text lines, each starting with ``comment`` (and a space)."""
    e = res.errors
    lines = [f"{comment} error against the full model over the envelope (rpm {res.envelope.rpm[0]:g}-"
             f"{res.envelope.rpm[1]:g}, V {res.envelope.airspeed[0]:g}-{res.envelope.airspeed[1]:g} m/s, "
             f"incidence {res.envelope.incidence_deg[0]:g}-{res.envelope.incidence_deg[1]:g} deg; "
             f"{res.n_points} points, {e['points_flagged']} flagged):"]
    for k in ("thrust", "drag", "torque", "rolling_moment"):
        lines.append(f"{comment}   {k:<15} rms {_pct(e[k]['rms']):>7}  max {_pct(e[k]['max']):>7}  "
                     f"(max in flagged regions {_pct(e[k]['max_flagged'])})")
    lines.append(f"{comment} normalised: {e['normalisation']}")
    for name, why in res.fixed.items():
        lines.append(f"{comment} {name} fixed at 0: {why}")
    return lines


def _pct(value: float) -> str:
    """A fraction as a percentage; n/a for NaN (no point to measure it on)."""
    return "n/a" if math.isnan(value) else f"{value:.2%}"


def write_export(res: SimExport, path) -> list[Path]:
    """Write the coefficients in the target's own format (atomically), and a JSON report
    ``<path>.json`` with the coefficients, the envelope and the errors.

    rotorpy: a Python file defining ``rotor_params`` (keys of RotorPy's ``quad_params``);
    gazebo: an SDF fragment of the gazebo_motor_model plugin's coefficient elements;
    gill2019: JSON.

    The two are written as a pair (io.atomic.atomic_paths); the report records the
    file's SHA-256 (``describes``) and the coefficients fixed at 0 (``fixed_at_zero``).

    Raises
    ------
    OSError
        The files cannot be written.
    """
    path = Path(path)
    head = (f"propmap {__version__}: {res.target} coefficients of {res.meta.get('propeller')} "
            f"({res.meta.get('params')}), fitted to the full model")
    if res.target == "rotorpy":
        c = res.coefficients
        lines = [f"# {head}", *error_lines(res, "#"),
                 "# Merge into RotorPy's quad_params. k_flap = 0: the rigid-blade model has no moment about",
                 "# z x e_ip; its rolling moment about e_ip has no RotorPy term (its error above).",
                 "rotor_params = {",
                 f"    'k_eta': {c['k_eta']!r},  # thrust coefficient N/(rad/s)**2",
                 f"    'k_m': {c['k_m']!r},  # yaw moment coefficient Nm/(rad/s)**2",
                 f"    'k_d': {c['k_d']!r},  # rotor drag coefficient N/(rad*m/s**2) = kg/rad",
                 f"    'k_z': {c['k_z']!r},  # induced inflow coefficient N/(rad*m/s**2) = kg/rad",
                 f"    'k_h': {c['k_h']!r},  # translational lift coefficient N/(m/s)**2",
                 f"    'k_flap': {c['k_flap']!r},  # flapping moment coefficient Nm/(rad*m/s**2)",
                 f"    'rotor_radius': {c['rotor_radius']!r},  # m",
                 "}"]
        text = "\n".join(lines) + "\n"
    elif res.target == "gazebo":
        c = res.coefficients
        lines = ["<!--", f"  {head}", *(" " + ln for ln in error_lines(res, "")),
                 "  Thrust fades with axial speed as 1 - |V_z| / 25 m/s in the plugin (not a parameter);",
                 "  the torque, momentConstant times the unfaded thrust, does not fade.",
                 "  PX4-SITL_gazebo-classic (since its PR #809, 2021) signs the rolling moment by the turning",
                 "  direction: right for both. gz-sim's MulticopterMotorModel does not: right for ccw only.",
                 "  Paste these elements into each rotor's gazebo_motor_model plugin.", "-->",
                 f"<motorConstant>{c['motorConstant']!r}</motorConstant>",
                 f"<momentConstant>{c['momentConstant']!r}</momentConstant>",
                 f"<rotorDragCoefficient>{c['rotorDragCoefficient']!r}</rotorDragCoefficient>",
                 f"<rollingMomentCoefficient>{c['rollingMomentCoefficient']!r}</rollingMomentCoefficient>"]
        text = "\n".join(lines) + "\n"
    else:
        text = json.dumps({"model": "multinomial in mu = V sin(beta)/(Omega R), lambda_c = V cos(beta)/(Omega R)",
                           "terms_even": list(EVEN_TERMS), "terms_odd": list(ODD_TERMS),
                           "normalisation": "T, H = rho pi R^2 (Omega R)^2 C; Q, M_R = rho pi R^3 (Omega R)^2 C",
                           **res.coefficients, "fixed_at_zero": res.fixed}, indent=2) + "\n"
    from .io.atomic import atomic_paths, file_sha256
    from .io.mapfile import _json_safe

    report = report_path(path)
    # the file and its report as a pair; the report names the file's SHA-256
    with atomic_paths([path, report]) as (tmp, tmp_report):
        tmp.write_text(text)
        tmp_report.write_text(json.dumps(_json_safe({
            "target": res.target, "coefficients": res.coefficients, "fixed_at_zero": res.fixed, "errors": res.errors,
            "envelope": {"rpm": list(res.envelope.rpm), "airspeed": list(res.envelope.airspeed),
                         "incidence_deg": list(res.envelope.incidence_deg)},
            "n_points": res.n_points, **res.meta, "describes": {"file": path.name, "sha256": file_sha256(tmp)}}),
            indent=2, allow_nan=False))
    return [path, report]
