"""Simulator coefficients: the simple rotor models of common simulators fitted to propmap.

Each target is a closed-form rotor model that a simulator evaluates. Its coefficients are
fitted to the full model (propmap's BET/BEMT) over an envelope of operating points, with
hover pinned: the static coefficients (thrust and torque at V = 0) are set so that the
simple model's hover thrust and torque equal the full model's at the envelope's hover rpm,
and the speed terms are then fitted by least squares to what remains, each within its
physical sign. The error against the full model is measured on other points of the envelope
than the fitted ones and reported, so that a user sees what the simple model costs.
The targets' model forms and their sources: :mod:`propmap.simexport.forms`.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from ..core.units import RPM, RPM_MAX
from .. import __version__
from ..core._numbers import SEED_MAX, integer
from ..core.airfoil import Air
from ..core.geometry import _real
from ..io.catalogue import catalogue_source
from ..core.solver import AIRSPEED_MAX, check_model_args, rotor_loads
from ..io.provenance import source_digest
from ..io.uncertainty import model_uncertainty
from .forms import EVEN_TERMS, GAZEBO_AXIAL_SPEED, ODD_TERMS, TARGETS, canonical_target, predict

__all__ = ["Envelope", "SimExport", "check_seed", "default_envelope", "export_sim"]

#: a term is fitted only if its dimensionless size (1; the advance ratio mu = V_ip/(Omega R),
#: the inflow ratio lambda_c = V_z/(Omega R), their powers and products; Gazebo's thrust
#: fade) reaches this somewhere in the envelope: a term below it changes its load by less
#: than about 0.1% there, and its coefficient would be fitted to round-off (a coefficient of
#: 1e294 from an envelope of airspeed 0 to 1e-300 m/s). Such a coefficient is fixed at 0 and
#: said (SimExport.fixed, a warning).
DETERMINED = 1e-3
#: the largest condition number of the fit's (column-normalised) design matrix: beyond it
#: the envelope cannot separate the terms (e.g. a single rpm and a single speed). The default
#: envelopes of the targets give 1-4 on catalogue propellers; an envelope that is nearly a
#: point (rpm 5000-5000.001, airspeed 10-10.000001 m/s) gives 1.5e7, where 1e8 let a
#: coefficient be fitted to round-off and written without a word
MAX_CONDITION = 1e4
#: fewest converged points a fit takes
MIN_POINTS = 10
#: what the physical sign of each sign-constrained coefficient means (all >= 0)
PHYSICAL_SIGN = {
    "k_h": "translational lift: k_h V_ip^2 can only raise the thrust with in-plane speed",
    "k_z": "induced inflow: -k_z Omega V_z lowers the thrust in climb and raises it in descent",
    "k_d": "rotor drag acts against the in-plane motion",
    "rotorDragCoefficient": "rotor drag acts against the in-plane motion",
    "rollingMomentCoefficient": "more thrust on the advancing side than on the retreating side",
}


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
    hover_rpm : float, optional
        [rpm], within ``rpm``: where the simple model's static thrust and torque are pinned
        to the full model's. None: the geometric mean of ``rpm`` (give the vehicle's hover
        rpm where it is known; ``propmap export-sim --vehicle`` computes it).

    Raises
    ------
    ValueError
        A range that is not two finite numbers with low < high within rpm [1, 954929],
        airspeed [0, 500] m/s, incidence [0, 180] deg, or a ``hover_rpm`` outside ``rpm``.
    """

    rpm: tuple
    airspeed: tuple = (0.0, 25.0)
    incidence_deg: tuple = (0.0, 180.0)
    hover_rpm: float | None = None

    def __post_init__(self) -> None:
        for name, (a, b) in (("rpm", (1.0, RPM_MAX)), ("airspeed", (0.0, AIRSPEED_MAX)),
                             ("incidence_deg", (0.0, 180.0))):
            value = getattr(self, name)
            pair = tuple(value) if isinstance(value, (tuple, list, np.ndarray)) else None
            if pair is None or len(pair) != 2 or any(_real(v) is None for v in pair):
                raise ValueError(f"envelope {name} must be two numbers (low, high), got {value!r:.60}")
            lo, hi = (_real(v) for v in pair)
            if not (math.isfinite(lo) and math.isfinite(hi) and a <= lo < hi <= b):
                raise ValueError(f"envelope {name} must satisfy {a:g} <= low < high <= {b:g}, got {lo!r}, {hi!r}")
            object.__setattr__(self, name, (lo, hi))
        if self.hover_rpm is not None:
            h, (lo, hi) = _real(self.hover_rpm), self.rpm
            if h is None or not (math.isfinite(h) and lo <= h <= hi):
                raise ValueError(f"envelope hover_rpm must be a number within its rpm range [{lo:g}, {hi:g}], "
                                 f"got {self.hover_rpm!r:.60}")
            object.__setattr__(self, "hover_rpm", h)

    @property
    def hover(self) -> float:
        """The hover rpm in use: ``hover_rpm``, or the geometric mean of ``rpm`` [rpm]."""
        return self.hover_rpm if self.hover_rpm is not None else math.sqrt(self.rpm[0] * self.rpm[1])


@dataclass
class SimExport:
    """Fitted coefficients of one target and their error against the full model.

    Attributes
    ----------
    target : str
        One of :data:`TARGETS`.
    coefficients : dict
        Name -> value in SI units (as the target's file writes them).
    errors : dict
        Measured on check points of the envelope other than the fitted ones (``n_points`` of
        them, seeded by :func:`check_seed`; ``fitted_points``: each load's rms and max on the
        fitted points, for comparison). Per load (thrust, drag, torque, rolling_moment): rms
        and max of |simple - full|,
        normalised per point by the static thrust or torque at its Omega (T, Q) or the
        largest |D| or |M_R| of the envelope's points (D, M_R); over the points outside
        vortex ring and multiple roots, and apart (``rms_flagged``, ``max_flagged``) over
        those inside. ``hover``: the full model's and the simple model's static thrust
        and torque at the hover rpm and their relative differences; ``static``: the
        largest relative difference of static thrust and torque over the envelope's rpm.
    envelope : Envelope
    n_points : int
    meta : dict
        Propeller, parameters, model, propmap version.
    fixed : dict
        Coefficient name (``k_z``; ``CT[lambda^2]`` for the multinomial) -> why the
        envelope cannot determine it; those are fixed at 0 (:data:`DETERMINED`).
    held : dict
        Coefficient name -> why it is held at 0, the bound of its physical sign
        (:data:`PHYSICAL_SIGN`): the full model's trend over the envelope is the opposite
        of what the term can represent.
    """

    target: str
    coefficients: dict
    errors: dict
    envelope: Envelope
    n_points: int
    meta: dict = field(default_factory=dict)
    fixed: dict = field(default_factory=dict)
    held: dict = field(default_factory=dict)


def default_envelope(propeller) -> Envelope:
    """A multirotor's envelope for ``propeller``: rpm from a third of the rpm of a 150 m/s
    tip speed to it (tip speeds 50-150 m/s), V 0-15 m/s, incidence 0-180 deg (advance
    ratios J up to about 1), hover at the geometric mean of the rpm range.

    Parameters
    ----------
    propeller : Propeller

    Returns
    -------
    Envelope

    Raises
    ------
    TypeError
        ``propeller`` not a :class:`propmap.Propeller`.
    """
    from ..core.geometry import Propeller
    from ..maps import default_axes

    if not isinstance(propeller, Propeller):
        raise TypeError(f"propeller must be a Propeller (propmap.load_propeller, read_geometry), "
                        f"got {type(propeller).__name__}")

    rpm, _, _ = default_axes(propeller)
    return Envelope(rpm=(float(rpm[-1]) / 3, float(rpm[-1])), airspeed=(0.0, 15.0))


def _samples(propeller, params, air, envelope: Envelope, n: int, seed: int):
    rng = np.random.default_rng(seed)
    om = rng.uniform(*envelope.rpm, n) * RPM
    V = rng.uniform(*envelope.airspeed, n)
    b = np.radians(rng.uniform(*envelope.incidence_deg, n))
    full = rotor_loads(propeller, params, om, V, b, air=air, on_failure="flag")
    om_h = envelope.hover * RPM
    static = rotor_loads(propeller, params, np.append(om, om_h), 0.0, 0.0, air=air)
    ok = full.converged
    if ok.sum() < MIN_POINTS:
        raise ValueError(f"only {int(ok.sum())} of the envelope's {n} points converged; at least {MIN_POINTS} are "
                         "needed to fit (a larger envelope, or more points)")
    for k, v in (("thrust", static.thrust), ("torque", static.torque)):
        if not np.all(np.isfinite(v) & (v > 0)):
            raise ValueError(f"the model's static {k} is not positive at every rpm of the envelope "
                             f"({float(np.min(v)):.3g}): the fit, relative to it, cannot be normalised")
    flagged = full.vortex_ring | full.multiple_roots
    return {"omega": om[ok], "V": V[ok], "beta": b[ok], "flagged": flagged[ok],
            "thrust": full.thrust[ok], "drag": full.drag[ok], "torque": full.torque[ok],
            "rolling_moment": full.rolling_moment[ok], "T0": static.thrust[:-1][ok], "Q0": static.torque[:-1][ok],
            "omega_h": om_h, "T_h": float(static.thrust[-1]), "Q_h": float(static.torque[-1])}


#: what each dimensionless term size is, for messages
_SIZE_TEXT = {"mu": "the advance ratio mu = V sin(beta) / (Omega R)",
              "lambda": "the inflow ratio lambda_c = V cos(beta) / (Omega R)",
              "fade": f"the plugin's thrust fade 1 - |V_z| / {GAZEBO_AXIAL_SPEED:g} m/s"}


def _lstsq(terms, y, fixed: dict, held: dict):
    """Least squares of ``y`` on the terms that the envelope determines, each within its sign.

    Parameters
    ----------
    terms : list of (name, column, size, what)
        The coefficient's name, its column (weighted like ``y``), the term's
        dimensionless size at each point and what that size is (a key of _SIZE_TEXT,
        with a power: "mu^2"). A name in :data:`PHYSICAL_SIGN` is bounded below by 0.
    y : ndarray
    fixed : dict
        Receives name -> reason for each term left out (its coefficient 0).
    held : dict
        Receives name -> reason for each sign-bounded coefficient that ends at its bound
        while the unbounded fit gives the opposite sign.

    Returns
    -------
    list of float
        One coefficient per term, 0 for those left out.

    Raises
    ------
    ValueError
        Terms the envelope cannot separate.
    """
    from scipy.optimize import lsq_linear

    keep = []
    for k, (name, col, size, what) in enumerate(terms):
        peak = float(np.max(np.abs(size)))
        if peak >= DETERMINED:
            keep.append(k)
            continue
        legend = "; ".join(text for key, text in _SIZE_TEXT.items() if key in what)
        fixed[name] = (f"its term's size {what} ({legend}) stays below {DETERMINED:g} over the envelope "
                       f"(at most {peak:.2g})")
    x = np.zeros(len(terms))
    if not keep:
        return [float(v) for v in x]
    names = [terms[k][0] for k in keep]
    A = np.column_stack([terms[k][1] for k in keep])
    scale = np.max(np.abs(A), axis=0)
    scale[scale == 0] = 1.0
    A = A / scale
    _, sv, vt = np.linalg.svd(A / np.maximum(np.linalg.norm(A, axis=0), 1e-300), full_matrices=False)
    if sv[-1] < sv[0] / MAX_CONDITION:
        mixed = [n for n, v in zip(names, vt[-1]) if abs(v) > 0.1]
        raise ValueError(f"the envelope cannot separate {', '.join(mixed)} (condition number "
                         f"{sv[0] / max(sv[-1], 1e-300):.2g}): widen its rpm, airspeed or incidence range")
    free, *_ = np.linalg.lstsq(A, y, rcond=None)
    lower = np.array([0.0 if n in PHYSICAL_SIGN else -np.inf for n in names])
    sol = free
    if np.any(free < lower):
        sol = lsq_linear(A, y, bounds=(lower, np.inf), method="bvls").x
        for n, f, v, lo, sc in zip(names, free, sol, lower, scale):
            if lo == 0.0 and v <= 0.0 and f < 0.0:
                held[n] = (f"held at 0, the bound of its physical sign ({PHYSICAL_SIGN[n]}): the full model's trend "
                           f"over the envelope is the opposite (the unbounded fit gives {f / sc:.3g})")
    x[keep] = sol / scale
    return [float(v) for v in x]


def _mu_lambda(s, R):
    tip = s["omega"] * R
    return s["V"] * np.sin(s["beta"]) / tip, s["V"] * np.cos(s["beta"]) / tip


def _fit(target: str, s, R: float, rho: float, fixed: dict, held: dict) -> dict:
    om, V, b = s["omega"], s["V"], s["beta"]
    Vip, Vz = V * np.sin(b), V * np.cos(b)
    mu, lam = _mu_lambda(s, R)
    om_h, T_h, Q_h = s["omega_h"], s["T_h"], s["Q_h"]
    # each load is fitted relative to its scale at the point (static value at that Omega), so
    # that low and high rpm count alike: divide both sides by the scale
    wT, wQ = 1 / s["T0"], 1 / s["Q0"]
    wD = 1 / max(float(np.max(np.abs(s["drag"]))), 1e-300)
    wR = 1 / max(float(np.max(np.abs(s["rolling_moment"]))), 1e-300)
    if target == "rotorpy":
        k_eta, k_m = T_h / om_h**2, Q_h / om_h**2  # hover pinned
        k_h, k_z = _lstsq([("k_h", Vip**2 * wT, mu**2, "mu^2"), ("k_z", -om * Vz * wT, lam, "lambda")],
                          (s["thrust"] - k_eta * om**2) * wT, fixed, held)
        (k_d,) = _lstsq([("k_d", om * Vip * wD, mu, "mu")], s["drag"] * wD, fixed, held)
        return {"k_eta": k_eta, "k_m": k_m, "k_d": k_d, "k_z": k_z, "k_h": k_h, "k_flap": 0.0, "rotor_radius": R}
    if target in ("gazebo-classic", "gz-sim"):
        kT, kQ = T_h / om_h**2, Q_h / T_h  # hover pinned (the plugins' torque: momentConstant x unfaded thrust)
        if target == "gazebo-classic":
            fade = np.maximum(0.0, 1.0 - np.abs(Vz) / GAZEBO_AXIAL_SPEED)
            if float(np.max(fade)) < DETERMINED:
                raise ValueError(f"the plugin's thrust fade 1 - |V_z| / {GAZEBO_AXIAL_SPEED:g} m/s is 0 at every point "
                                 f"of the envelope (|V_z| >= {GAZEBO_AXIAL_SPEED:g} m/s): its thrust is 0 there "
                                 "whatever motorConstant; widen the envelope")
        (kD,) = _lstsq([("rotorDragCoefficient", om * Vip * wD, mu, "mu")], s["drag"] * wD, fixed, held)
        (kR,) = _lstsq([("rollingMomentCoefficient", om * Vip * wR, mu, "mu")], s["rolling_moment"] * wR, fixed,
                       held)
        return {"motorConstant": kT, "momentConstant": kQ, "rotorDragCoefficient": kD,
                "rollingMomentCoefficient": kR}
    if target == "multinomial":
        q = rho * math.pi * R**2 * (om * R) ** 2  # force scale; moments add R
        q_h = rho * math.pi * R**2 * (om_h * R) ** 2
        even = [lam, lam**2, mu**2, lam**3, lam * mu**2]
        odd = [mu, mu * lam, mu * lam**2, mu**3]
        out = {"R": R, "rho": rho}
        for key, c0, terms, names, y, w, moment in (
                ("CT", T_h / q_h, even, EVEN_TERMS[1:], s["thrust"], wT, False),
                ("CH", None, odd, ODD_TERMS, s["drag"], wD, False),
                ("CQ", Q_h / (q_h * R), even, EVEN_TERMS[1:], s["torque"], wQ, True),
                ("CR", None, odd, ODD_TERMS, s["rolling_moment"], wR, True)):
            scale = q * (R if moment else 1.0)
            rest = y - (c0 * scale if c0 is not None else 0.0)
            fitted = _lstsq([(f"{key}[{n}]", t * scale * w, t, n) for t, n in zip(terms, names)], rest * w, fixed,
                            held)
            out[key] = [c0, *fitted] if c0 is not None else fitted
        return out
    raise ValueError(f"target must be one of {', '.join(TARGETS)}, got {target!r}")


#: the loads whose error against the full model is reported
LOADS = ("thrust", "drag", "torque", "rolling_moment")


def check_seed(seed: int) -> int:
    """The seed of the check points on which :func:`export_sim` measures its errors: ``seed`` + 1
    (the coefficients are fitted on the points of ``seed``; the check points are others).

    Parameters
    ----------
    seed : int
        The fit points' seed, in [0, 2**63 - 2] (the check points' seed is a NumPy int64 too).

    Returns
    -------
    int
        The check points' seed.

    Raises
    ------
    ValueError
        ``seed`` not an integer in that range (-1 gave 0, another seed's points).
    """
    return integer("seed", seed, 0, SEED_MAX - 1) + 1


def _rel(a: float, b: float) -> float:
    return float(abs(a - b) / abs(b))


def _errors(target: str, coefficients: dict, s) -> dict:
    T, D, Q, MR = predict(target, coefficients, s["omega"], s["V"], s["beta"])
    norm = {"thrust": np.abs(s["T0"]), "torque": np.abs(s["Q0"]),
            "drag": np.full_like(T, max(float(np.max(np.abs(s["drag"]))), 1e-300)),
            "rolling_moment": np.full_like(T, max(float(np.max(np.abs(s["rolling_moment"]))), 1e-300))}
    out = {}
    for k, pred in zip(LOADS, (T, D, Q, MR)):
        e = np.abs(pred - s[k]) / norm[k]
        ok, bad = e[~s["flagged"]], e[s["flagged"]]
        out[k] = {"rms": float(np.sqrt(np.mean(ok**2))) if ok.size else math.nan,
                  "max": float(np.max(ok)) if ok.size else math.nan,
                  "rms_flagged": float(np.sqrt(np.mean(bad**2))) if bad.size else math.nan,
                  "max_flagged": float(np.max(bad)) if bad.size else math.nan}
    out["normalisation"] = ("T by the static thrust and Q by the static torque at each point's Omega; D and M_R by "
                            "the largest |D|, |M_R| over the envelope; 'flagged': points in vortex ring or with "
                            "multiple roots")
    out["points_flagged"] = int(np.sum(s["flagged"]))
    Th, _, Qh, _ = predict(target, coefficients, s["omega_h"], 0.0, 0.0)
    out["hover"] = {"rpm": s["omega_h"] / RPM, "thrust": s["T_h"], "torque": s["Q_h"],
                    "thrust_export": float(Th), "torque_export": float(Qh),
                    "thrust_error": _rel(float(Th), s["T_h"]), "torque_error": _rel(float(Qh), s["Q_h"])}
    T0, _, Q0, _ = predict(target, coefficients, s["omega"], 0.0, 0.0)
    out["static"] = {"thrust_max": float(np.max(np.abs(T0 - s["T0"]) / s["T0"])),
                     "torque_max": float(np.max(np.abs(Q0 - s["Q0"]) / s["Q0"]))}
    return out


def _edgewise_trend(propeller, params, air, envelope: Envelope) -> dict:
    """The thrust change from hover to edgewise flight at the envelope's top airspeed (hover
    rpm, incidence 90 deg) with this set and with the generic set: the model's own spread in
    forward flight, where no measurement of the propeller arbitrates (docs/simulators.md)."""
    from ..io.calibration import generic_params

    om, V = envelope.hover * RPM, float(envelope.airspeed[1])
    out = {"rpm": envelope.hover, "airspeed": V}
    for key, p in (("this_set", params), ("generic", generic_params())):
        r = rotor_loads(propeller, p, np.array([om, om]), np.array([0.0, V]), math.pi / 2, air=air,
                        on_failure="flag")
        out[key] = float(r.thrust[1] / r.thrust[0] - 1) if r.converged.all() else math.nan
    return out


def export_sim(target: str, propeller, params, *, air: Air | None = None, envelope: Envelope | None = None,
               n_points: int = 4000, seed: int = 0, params_label: str = "") -> SimExport:
    """Fit ``target``'s coefficients to the full model over ``envelope`` and measure its error.

    Hover is pinned: the static coefficients make the simple model's thrust and torque at
    V = 0 and ``envelope.hover`` rpm equal the full model's (to round-off); the speed
    terms are fitted by least squares, relative to each point's static load, to what
    remains, each within its physical sign (:data:`PHYSICAL_SIGN`).

    Parameters
    ----------
    target : {"rotorpy", "gazebo-classic", "gz-sim", "multinomial"}
        Also the former names "gazebo" (gazebo-classic) and "gill2019" (multinomial, with
        a FutureWarning).
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: the parameter set's own (``.air``).
    envelope : Envelope, optional
        Default: :func:`default_envelope`.
    n_points : int
        Random operating points in the envelope (seeded), >= 20: as many to fit and, others,
        to measure the errors on.
    seed : int
        The fitted points' seed, in [0, 2**63 - 2]; the check points' is :func:`check_seed`
        (``seed`` + 1).
    params_label : str
        Recorded in the result (``meta["params"]``); default the set's own ``label``, else its
        section model. ``meta["citation"]`` is a catalogue propeller's citation
        (:func:`propmap.io.catalogue.catalogue_source`).

    Returns
    -------
    SimExport

    Raises
    ------
    ValueError
        Unknown target; ``n_points`` not an integer in [20, 1,000,000]; ``seed`` not an
        integer in [0, 2**63 - 2]; ``envelope`` not an Envelope; fewer than 10 converged points; an
        envelope where gazebo-classic's thrust fade is 0 at every point (|V_z| >= 25 m/s),
        or terms it cannot separate (:data:`MAX_CONDITION`).
    TypeError
        A propeller, parameter set or air of the wrong type
        (:func:`propmap.core.solver.check_model_args`); ``params_label`` not a str.

    Warns
    -----
    UserWarning
        Each coefficient fixed at 0 because the envelope cannot determine it (also in
        ``SimExport.fixed``); each held at 0 by its physical sign (``SimExport.held``); an
        envelope whose every point is flagged (its errors outside flagged regions are
        NaN: nothing to measure them on).
    """
    air = getattr(params, "air", None) if air is None else air  # checked below
    check_model_args(propeller, params, air)
    target = canonical_target(target)
    side = ", ".join(params.side_load_sources())
    if side:
        warnings.warn(f"this parameter set gives a side force and a pitching moment ({side}); the "
                      f"{target} model has no term fitted to them (RotorPy's k_flap is written 0), so they are left "
                      "out and their error is not reported", UserWarning, stacklevel=2)
    if not isinstance(params_label, str):
        raise TypeError(f"params_label must be a str, got {type(params_label).__name__}")
    n_points = integer("n_points", n_points, 20, 1_000_000)
    seed = integer("seed", seed, 0, SEED_MAX - 1)
    if envelope is None:
        envelope = default_envelope(propeller)
    elif not isinstance(envelope, Envelope):
        raise ValueError(f"envelope must be an Envelope or None, got {type(envelope).__name__}")
    s = _samples(propeller, params, air, envelope, int(n_points), int(seed))
    fixed: dict = {}
    held: dict = {}
    coefficients = {k: (float(v) if not isinstance(v, list) else v)
                    for k, v in _fit(target, s, propeller.radius, air.rho, fixed, held).items()}
    for name, why in fixed.items():
        warnings.warn(f"{name} fixed at 0: {why}", UserWarning, stacklevel=2)
    for name, why in held.items():
        warnings.warn(f"{name} {why}", UserWarning, stacklevel=2)
    # the error on fresh points of the envelope (as a map's check), the fitted points' beside it
    check = _samples(propeller, params, air, envelope, int(n_points), check_seed(int(seed)))
    errors = _errors(target, coefficients, check)
    fitted = _errors(target, coefficients, s)
    errors["fitted_points"] = {k: {"rms": fitted[k]["rms"], "max": fitted[k]["max"]} for k in LOADS}
    if errors["points_flagged"] == check["omega"].size:
        warnings.warn(f"every one of the {check['omega'].size} check points of the envelope is flagged (vortex ring or "
                      "multiple roots): no error outside flagged regions to report (n/a)", UserWarning, stacklevel=2)
    label = params_label or params.label or params.section_model  # (the set's own label: the file's head said
    # "(cambered)" of calibrated:apce_8x6 where the API was given no params_label, an export audit)
    meta = {"propeller": propeller.name, "params": label,
            **({"citation": cited} if (cited := catalogue_source(propeller)) else {}),
            "model_uncertainty": {**model_uncertainty(params_label or getattr(params, "label", ""), propeller),
                                  "edgewise_trend": _edgewise_trend(propeller, params, air, envelope)},
            "section_model": params.section_model, "propmap_version": __version__,
            "propmap_source_sha256": source_digest(), "model": "Gill & D'Andrea 2017 BET/BEMT (propmap)",
            "seed": int(seed),
            "check_seed": check_seed(int(seed)), "check_points": int(check["omega"].size), "rho": float(air.rho),
            "mu": float(air.mu), "speed_of_sound": float(air.speed_of_sound)}
    return SimExport(target, coefficients, errors, envelope, int(s["omega"].size), meta, fixed, held)
