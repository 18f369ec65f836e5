"""Parameter identification, Gill & D'Andrea (2017) Section III, with the robustness the
paper lacked (docs/identification.md): bounds, continuation in the stall-blend sharpness M,
a multistart stage and an identifiability report that says what the data do not determine.

Either section model can be identified: the paper's (c_l1, c_l2, c_d, alpha_0), started
from the paper's x0, or a subset of the cambered polar's parameters, started from the
base set (normally the catalogue-fitted ``generic`` set).

* Loads: residuals (model - measured) / RMS(measured) for each measured quantity; several
  propellers can be fitted jointly (:func:`fit_loads_joint`, identify/joint.py), each weighted alike.

This module holds the load data's residuals; they, level flight's (eqs 16-18,
identify/level_flight_fit.py; propmap.identify exports both) and the flight logs' (identify/flight.py)
share one engine: identify/options.py (what is fitted, bounds,
:class:`FitOptions`), identify/engine.py (prior, solve, directions, report),
identify/continuation.py (the continuation in M), identify/result.py
(:class:`FitResult`, identifiability) and identify/dependence.py (the residuals'
autocorrelation, the jackknife).
"""

from __future__ import annotations

import contextlib
import math
import warnings
from dataclasses import replace

import numpy as np

from ..core.units import RPM
from ..core.airfoil import Air, AirfoilParams, CamberedParams, SectionParams
from ..core.air import SUPERSONIC_TIP, TipMachWarning
from ..core.flapping import flapping_warning_held
from ..core.solver import (OMEGA_MIN, TIP_MACH_WARN, check_model_args, differentiable, rotor_loads,
                           supersonic_tips_allowed)
from .data import LoadData
from .load_data import INPLANE_KEYS, INPLANE_WORDS, STATIC_AIRSPEED, data_air
from .continuation import _fit_with_continuation
from .engine import (_attach_jacobian, _directions_report, _finish, _fit_along_directions, _flap_articulated,
                     _flap_saturation, _m_effect, _params_from, _prior_stats, _warn_at_optimum, _with_prior, _x0)
from .options import (CAMBERED_FIT, CAMBERED_FIT_RE, CAMBERED_FIT_STATIC, FLAP_START, INPLANE_FIT,
                      MIN_RATES_FOR_RE, RATE_STEP, STATIC_RPM_SPAN, X0_PAPER, FitOptions, _default_names, _is_angle,
                      param_names, refuse_unused_options)
from .dependence import lag1_autocorrelation
from .result import FitResult, Identifiability

__all__ = ["FitOptions", "FitResult", "Identifiability", "X0_PAPER", "fit_loads", "param_names",
           "CAMBERED_FIT", "CAMBERED_FIT_STATIC", "CAMBERED_FIT_RE"]


def _fitted_rows(data: LoadData, keys) -> dict:
    """Each quantity's points in the fit: every point, but the in-plane force ``drag`` and the
    rolling moment (INPLANE_KEYS) only where the rotor has an in-plane airspeed above
    STATIC_AIRSPEED (elsewhere model and measurement should both be zero: a tunnel's normal
    force at axial points is its noise, which as a residual scaled by its own rms came out near
    1 at every such point and swamped the fit's uncertainty report, a user-level audit,
    2026-11-26; as ``validate`` scores them; data without such points do not fit them,
    :func:`_load_keys`)."""
    return {k: data.inplane if k in INPLANE_KEYS else np.ones(data.n, bool) for k in keys}


def _load_norms(data: LoadData, propeller, keys, air: Air):
    n = data.omega / (2 * math.pi)
    norm = {k: air.rho * n**2 * propeller.diameter ** (5 if k in MOMENT_KEYS else 4) for k in keys}
    rows = _fitted_rows(data, keys)
    scales = {k: float(np.sqrt(np.mean((data.measured[k][rows[k]] / norm[k][rows[k]]) ** 2))) for k in keys}
    for k, s in scales.items():
        gaps = np.flatnonzero(rows[k] & ~np.isfinite(data.measured[k]))
        if gaps.size:  # (NaN: not measured there; it was called 'zero everywhere or not finite')
            i = int(gaps[0])
            raise ValueError(f"measured {k} is NaN (not measured) at {gaps.size} point(s), the first #{i} "
                             f"({data.group[i]}, {data.omega[i] / RPM:.5g} rpm, {data.airspeed[i]:.4g} m/s): "
                             "give the data without those points (LoadData.subset), or fit the other quantities "
                             "(quantities=)")
        if not (np.isfinite(s) and s > 0):
            others = [q for q in keys if q != k]
            raise ValueError(f"measured {k} is zero everywhere or not finite, so it cannot be fitted: fit "
                             f"{', '.join(others) or 'another quantity'} alone (quantities=, the CLI's --quantities)")
    return norm, scales


#: the static CT and CQ (propeller convention) outside which fit_loads warns of a unit or sign mistake: the 147
#: catalogue propellers' static medians are CT 0.054-0.246 and CQ 0.0037-0.027 (thrust in gf reads 102 times, in
#: kgf 0.102 times; torque in N cm 100 times)
STATIC_CT_RANGE = (0.02, 0.6)
STATIC_CQ_RANGE = (0.001, 0.1)


def _unit_notes(data: LoadData, propeller, keys, air: Air) -> list[str]:
    """Warnings where the static points' median measured CT or CQ lies outside STATIC_CT_RANGE or
    STATIC_CQ_RANGE, or is negative: a quantity in other units than N and N m (the fit divides each
    quantity by its own RMS, so such a quantity fits without an error and is, in effect, left out)
    or of the other sign."""
    static = data.static & (data.omega >= OMEGA_MIN)
    notes = []
    if not static.any():
        return notes
    norm = _load_norms(data, propeller, keys, air)[0]  # (rho n^2 D^4 for thrust, rho n^2 D^5 for torque)
    for key, (lo, hi), sym, unit in (("thrust", STATIC_CT_RANGE, "CT", "N"), ("torque", STATIC_CQ_RANGE, "CQ", "N m")):
        if key not in keys:
            continue
        c = float(np.median(data.measured[key][static] / norm[key][static]))
        if c < 0:
            notes.append(f"the measured static {key} is negative ({sym} {c:.3g} in the median): give its magnitude "
                         f"(propmap's {key} is positive in hover)")
        elif not lo <= c <= hi:
            notes.append(f"the measured static {sym} is {c:.3g} in the median, outside the {lo:g}-{hi:g} of propellers "
                         f"(the catalogue's: CT 0.054-0.246, CQ 0.0037-0.027): is the {key} in {unit}? (the fit "
                         f"divides each quantity by its own size, so a {key} in other units fits without an error)")
    return notes


def _check_fit_args(data, propeller, base, air, options, where: str = "") -> None:
    """TypeErrors naming an argument of the wrong type (each was an AttributeError from inside:
    options as a dict, base as a set's name, a propeller's name for the Propeller)."""
    if not isinstance(data, LoadData):
        raise TypeError(f"{where}data must be a LoadData (propmap.identify.read_loads), got {type(data).__name__}")
    if not isinstance(base, (AirfoilParams, CamberedParams)):
        hint = " (a set's name: resolve it with propmap.resolve_params)" if isinstance(base, str) else ""
        raise TypeError(f"base must be AirfoilParams or CamberedParams{hint}, got {type(base).__name__}")
    check_model_args(propeller, base, **({} if air is None else {"air": air}))
    if not isinstance(options, FitOptions):
        raise TypeError(f"options must be a FitOptions, got {type(options).__name__}")


def _load_keys(data: LoadData, quantities) -> list:
    if isinstance(quantities, str):  # (iterated, 'thrust' was the quantities 't', 'h', ...)
        raise ValueError(f"quantities must be a tuple of names, e.g. ({quantities!r},), got the string {quantities!r}")
    quantities = None if quantities is None else tuple(quantities)  # (a generator as well)
    if quantities is not None and (not len(quantities) or len(set(quantities)) != len(quantities)):
        # (() meant all of them, and ('thrust', 'thrust') dropped the torque and weighed the thrust twice)
        raise ValueError(f"quantities must name each fitted quantity once (or be None: all measured), got "
                         f"{tuple(quantities)!r:.80}")
    keys = list(data.measured if quantities is None else quantities)
    for k in keys:
        if k not in data.measured:
            raise ValueError(f"quantity {k!r} is not measured; measured: {', '.join(data.measured)}")
    if any(k in INPLANE_KEYS for k in keys) and not data.inplane.any():
        for k in [k for k in keys if k in INPLANE_KEYS]:
            if quantities is not None or len(keys) == 1:
                raise ValueError(f"{INPLANE_WORDS[k]} ({k}) cannot be fitted: no point has an in-plane airspeed above "
                                 f"{STATIC_AIRSPEED:g} m/s (below it model and measurement are near 0; is the "
                                 "incidence missing?)")
            keys.remove(k)  # (its measurement there is noise: sanity_check says so where it is large)
    return keys


#: the loads in units of a moment (normalised by rho n^2 D^5, as CQ)
MOMENT_KEYS = ("torque", "rolling_moment")


def _data_kind(data: LoadData) -> str:
    """"static" (all airspeeds static: at most STATIC_AIRSPEED, a stand's pitot noise included),
    "collective" (static, several collectives; "collective_rates" where those points span
    STATIC_RPM_SPAN in rpm), "few_rates" (moving points at < MIN_RATES_FOR_RE
    rotation rates, :func:`_sweep_rates`, and no static run spanning STATIC_RPM_SPAN, within a
    relative 1e-6 so that a unit's rounding does not decide) or "rates"."""
    moving = ~data.static
    static = data.omega[~moving]
    spans = static.size > 1 and float(static.max() / static.min()) >= STATIC_RPM_SPAN * (1.0 - 1e-6)
    if not moving.any():
        swept = data.collective is not None and np.ptp(data.collective) > 0
        return ("collective_rates" if spans else "collective") if swept else "static"
    rates = _sweep_rates(data)
    return "rates" if rates >= MIN_RATES_FOR_RE or spans else "few_rates"


def _measures_inplane_force(data: LoadData, keys) -> bool:
    """Whether the fitted quantities include the in-plane force D or the hub's rolling moment
    (INPLANE_KEYS) measured where the rotor has an in-plane speed (V sin beta > 0): what
    identifies the flapping (INPLANE_FIT)."""
    in_plane = data.airspeed * np.abs(np.sin(data.incidence))  # (axial below 1e-12 V, as the solver: sin(pi) ~ 1e-16)
    edgewise = in_plane > 1e-12 * data.airspeed
    return any(bool(np.any(edgewise & np.isfinite(data.measured[k]))) for k in keys if k in INPLANE_KEYS)


def _sweep_rates(data: LoadData) -> int:
    """Distinct rotation rates of the moving points (0 for static data): each run (``group``)
    split where its sorted rates jump by more than 3% (RATE_STEP), each part's median rate a
    level, and the levels counted in order where one lies more than 3% above the last one
    counted. A run's continuous spread is one rate (a UIUC sweep's rpm scatter; a sweep at one
    throttle whose rpm drifts as the tunnel speeds up, its Reynolds effects confounded with J),
    a run at several rates apart (a CSV without groups) counts each, and runs at rates in steps
    finer than 3% count by the span they cover (all 147 catalogue propellers count as with the
    neighbouring points compared, the rule before 2026-11-26). Points at most STATIC_AIRSPEED
    are static."""
    moving = ~data.static
    if not moving.any():
        return 0
    w, g = data.omega[moving], data.group[moving]
    levels = []
    for k in set(g):
        rates = np.sort(w[g == k])
        for part in np.split(rates, np.nonzero(rates[1:] > RATE_STEP * rates[:-1])[0] + 1):
            levels.append(float(np.median(part)))
    n, last = 0, -math.inf
    for rate in sorted(levels):
        if rate > RATE_STEP * last:
            n, last = n + 1, rate
    return n


def _direction_count(options: FitOptions, base: SectionParams, data: LoadData, kind: str, names) -> int | None:
    """How many directions :func:`fit_loads` frees: 0 every name (under the prior), None as
    many as the data determine DATA_OVER_PRIOR times better than the prior (at least one).

    Only for the cambered model under the prior with the default names: ``options.directions``
    where given; else STATIC_DIRECTIONS for a static run, the rule (None) for sweeps at one
    rotation rate (with or without a static run), 0 for sweeps at two or more
    (identify/directions.py; docs/identification.md has the measurements)."""
    from .directions import STATIC_DIRECTIONS

    stats = _prior_stats(names, base, options)
    if kind.startswith("collective") or options.names is not None or stats is None or len(stats[0]) != len(names):
        return 0
    if options.directions is not None:
        return min(int(options.directions), len(names))
    if kind == "static":
        return min(STATIC_DIRECTIONS, len(names))
    return None if _sweep_rates(data) < 2 else 0


def _load_residual(data: LoadData, propeller, keys, air: Air, names, base, weight: float = 1.0):
    """x -> stacked (model - measured) coefficient errors / RMS(measured coefficient), times ``weight``.

    The residual carries its Jacobian as ``residual.jacobian(x)`` where the model can
    differentiate every name (``rotor_loads(derivatives=names)``, the implicit function
    theorem: core/_sensitivity.py); the fit then uses it instead of differencing the solver.
    """
    norm, scales = _load_norms(data, propeller, keys, air)
    rows = _fitted_rows(data, keys)
    # blade tips past TIP_MACH_WARN in the data: said once here, not by every evaluation of the fit (7-100 of them)
    tip = data.tip_mach(propeller, air)
    quiet = tip > TIP_MACH_WARN
    if quiet:
        warnings.warn(f"{SUPERSONIC_TIP} {tip:.2g} (> {TIP_MACH_WARN:g}) in {data.source or 'the data'}: near or "
                      "past the end of the model's compressibility (its Prandtl-Glauert factor stops at Mach 0.9); "
                      "said once for the fit" + ("; is the rotation speed given in rpm where rad/s is meant?"
                                                 if tip > 1 else ""), TipMachWarning, stacklevel=3)
    # each quantity's fitted rows, measured value and divisor, once (not at every residual evaluation)
    fitted = {k: (rows[k], data.measured[k][rows[k]], norm[k][rows[k]] * scales[k]) for k in keys}

    def make(opts):
        def loads(x, derivatives=False, trial=True):
            p = _params_from(x, names, base, opts)
            with (supersonic_tips_allowed() if quiet else contextlib.nullcontext(),
                  flapping_warning_held() if trial else contextlib.nullcontext()):
                return rotor_loads(propeller, p, data.omega, data.airspeed, data.incidence, air=air,
                                   discretization=opts.discretization, collective=data.collective,
                                   derivatives=names if derivatives else False)

        def errors(r):
            model = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque, "rolling_moment": r.rolling_moment}
            return weight * np.concatenate([(model[k][m] - meas) / div for k, (m, meas, div) in fitted.items()])

        def residual(x, opts=opts):
            return errors(loads(x))

        def with_jacobian(x):
            r = loads(x, derivatives=True)
            return errors(r), weight * np.vstack([np.column_stack([r.derivative(k, n)[m] for n in names]) / div[:, None]
                                                  for k, (m, _, div) in fitted.items()])

        if (opts.jacobian == "implicit" and differentiable(base, names)
                and np.all(data.omega >= OMEGA_MIN)):
            _attach_jacobian(residual, with_jacobian)  # (a parked point, below OMEGA_MIN, has no derivatives)
        residual.at_optimum = lambda x: loads(x, trial=False)  # (engine._warn_at_optimum: the model's warnings)
        return residual

    return make, scales


def fit_loads(data: LoadData, propeller, *, base: SectionParams | None = None, air: Air | None = None,
              quantities: tuple[str, ...] | None = None, options: FitOptions = FitOptions()) -> FitResult:
    """Identify section parameters from direct load measurements of one propeller.

    Residuals are compared in coefficient form so that every rpm weighs alike: for each
    fitted quantity k, (model_k - measured_k) / (rho n^2 D^m_k) / RMS(measured coefficient),
    m = 4 for thrust and drag (CT), 5 for torque (CQ) and the rolling moment; the residuals of
    all k are stacked, the in-plane force's and the rolling moment's at the points with an
    in-plane airspeed (``LoadData.inplane``).

    Parameters
    ----------
    data : LoadData
        Static thrust-stand data (all airspeeds 0), wind-tunnel sweeps, or both.
    propeller : Propeller
    base : AirfoilParams or CamberedParams, optional
        The model, the start and the constants not fitted; the catalogue-fitted
        ``generic`` cambered set by default (``gill2017-apc`` for the paper's model).
    air : Air, optional
        Default: the parameter set's own (``.air``), at the density the data logged
        (``LoadData.air_density``) where they logged one (said in the result's warnings).
    quantities : tuple of str, optional
        Which measured quantities to fit (default: all in ``data.measured``).
    options : FitOptions
        ``names`` default: the paper's four parameters; for the cambered model as
        :class:`FitOptions` says (CAMBERED_FIT_RE or CAMBERED_FIT under the prior,
        CAMBERED_FIT_STATIC for a static run without it), and under the prior, by default,
        only the data's leading directions for a static run or sweeps at one rotation rate
        (``FitOptions.directions``; identify/directions.py). Where the fitted quantities
        include the in-plane force ``drag`` or the rolling moment measured at points with an
        in-plane speed, the cambered model's default also frees the flapping (INPLANE_FIT,
        outside the prior, so every name is fitted; docs/identification.md, Load data at
        incidence).

    Returns
    -------
    FitResult
        With a fit along directions ``extra["directions"]``: their count, coefficients and
        std errors (data and prior, and data only) in prior standard deviations, loadings, the
        eigenvalues and the base (angles in degrees, ``units``); the parameters' std errors
        are the free directions' (Identifiability) with the held directions at the population's
        spread.

    Raises
    ------
    ValueError
        Unknown or unmeasured quantity (or one named twice), an unknown parameter name, fewer
        residuals than parameters + 1, a measured quantity that is zero everywhere or NaN
        (not measured) at a fitted point.
    TypeError
        ``data``, ``propeller``, ``base``, ``air`` or ``options`` of the wrong type.
    SolverError
        From the rotor model.

    Warns
    -----
    UserWarning
        Once, where the data's blade tips pass Mach 0.8 (the solver's TIP_MACH_WARN; its own
        warning is held during the fit's evaluations).
    FlappingWarning
        Once, where the fitted set's blades flap beyond the small-angle range at the data's
        points (the model's own warning, silenced at the fit's trial parameter sets).

    Notes
    -----
    Residual method of Gill & D'Andrea (2017), Section III, applied to load measurements;
    the population prior and the directions: docs/identification.md.
    """
    from ..io.calibration import generic_params

    base = base or generic_params()
    _check_fit_args(data, propeller, base, air, options)
    refuse_unused_options(options, "fit_loads", directions=True)
    air, air_note = data_air(data, air, base.air)
    kind = _data_kind(data)
    names = _default_names(base, options, kind)
    keys = _load_keys(data, quantities)
    inplane = options.names is None and isinstance(base, CamberedParams) and _measures_inplane_force(data, keys)
    if inplane:  # the flapping carries the in-plane force (outside the prior: the directions do not apply)
        names = (*names, *(n for n in INPLANE_FIT if n not in names))
        if base.flap_compliance == 0.0:  # rigid blades: the loads are quadratic in the compliance, flat there
            base = base.replace(flap_compliance=FLAP_START)
    k_dirs = _direction_count(options, base, data, kind, names)
    free = len(names) if k_dirs == 0 else (k_dirs or 1)  # (a fit along directions frees k_dirs, at least 1)
    if sum(int(m.sum()) for m in _fitted_rows(data, keys).values()) <= free:
        raise ValueError(f"{data.n} points cannot identify {free} parameters" if k_dirs == 0 else
                         f"{data.n} points of {', '.join(keys)} cannot identify {free} parameter directions")
    make_data, scales = _load_residual(data, propeller, keys, air, names, base)
    make_residual, prior = _with_prior(make_data, names, base, options)
    notes, outside, spent = [air_note] if air_note else [], [], (0, 0.0)
    if options.directions is not None and k_dirs == 0 and options.directions != 0:
        notes.append("directions ignored: they apply to the cambered model under the population prior with the "
                     "default parameters (not with the flapping freed for the in-plane force), on load data other "
                     "than a collective sweep")
    if k_dirs != 0:
        best, log, nfev, elapsed, warns, extra = _fit_along_directions(make_data, names, base, options, k_dirs)
        outside, spent = extra.pop("outside"), (nfev, elapsed)
        if outside:  # the directions' optimum is not a point of the range: every name under the prior instead
            k_dirs = 0
        elif options.multistart:
            notes.append("multistart not used: the fit along directions starts from the base set")
    if k_dirs == 0:
        best, log, nfev, elapsed, warns, extra = _fit_with_continuation(make_residual, names, base, options,
                                                                        "fit loads", _x0(names, options, base))
        nfev, elapsed = nfev + spent[0], elapsed + spent[1]
        if outside:
            shown = ", ".join(f"{n} {math.degrees(v):.4g} deg" if _is_angle(n) else f"{n} {v:.4g}" for n, v in outside)
            warns = [f"the optimum along the data's leading directions left the allowed range ({shown}): all "
                     f"{len(names)} parameters fitted under the prior instead", *warns]
    if inplane:
        what = " and ".join(w for k, w in INPLANE_WORDS.items() if k in keys)
        notes.append(f"{', '.join(INPLANE_FIT)} fitted too: the data measure {what} at incidence "
                     "(docs/identification.md)" + (
                         "; without the hub's rolling moment it is an equivalent compliance that may carry an in-plane "
                         "force of another cause (on four APC propellers in a wind tunnel it came out 0.8-50 rad/(N m) "
                         "so, 0.4-1.5 with their rolling moments fitted too): a rolling-moment column pins it"
                         if "rolling_moment" not in keys else ""))
    for k in INPLANE_KEYS:
        if k in data.measured and k not in keys and quantities is None:
            notes.append(f"the measured {'drag' if k == 'drag' else 'rolling moment'} is not fitted: no point has an "
                         f"in-plane airspeed above {STATIC_AIRSPEED:g} m/s (below it model and measurement are near 0, "
                         "the measurement a balance's noise)")
    warns = [*_unit_notes(data, propeller, keys, air), *notes, *warns]
    extra = {"kind": "loads", "n_points": data.n, "quantities": keys, "coefficient_scales": scales, **extra,
             **_m_effect(make_data, best, base, options)}
    if prior:
        extra["prior"] = prior
    result = _finish(names, base, options, best, log, nfev, elapsed, warns, nfev * data.n, air, extra)
    result = _traced_residuals(result, data, keys)
    if inplane:
        result = _flap_articulated(_flap_saturation(result, make_residual(options), options)
                                   if options.profile_likelihood else result)
    _warn_at_optimum(result, make_data, options)
    return result if k_dirs == 0 else _directions_report(result, options)


#: a data residual beyond this many times the rms residual is named in a warning: an outlier in the data, or where
#: the model is weakest (at 4x, 31 of the 147 catalogue fits warned, mostly of low-rpm static points: the review of
#: 2026-11-26)
OUTLIER_FACTOR = 5.0
#: an rms data residual of a load fit above this is warned of first (residuals in units of the rms measured coefficient:
#: two propellers' steps in one stand export left 0.77, the UIUC data of apce_8x6 and apce_10x7 together 0.38);
#: CATALOGUE_RMS the catalogue's own fits with the defaults, all their data: 0.012 the smallest, magf_10x8, 0.029 and
#: 0.035 for apce_10x7 and apce_8x6, 0.104 the largest, gwsdd_2.5x0.8_spec3 (measured 2026-11-26, all 147)
POOR_FIT = 0.25
CATALOGUE_RMS = "0.012-0.104"


def _poor_fit(rms: float) -> str:
    """The words of a load fit's rms data residual beyond POOR_FIT (fit_loads' and each propeller's
    of fit_loads_joint)."""
    return (f"the fit leaves an rms residual of {rms:.3g} ({rms:.0%} of the measured coefficients' rms; the "
            f"catalogue's fits leave {CATALOGUE_RMS})")


def _traced_residuals(result: FitResult, data: LoadData, keys) -> FitResult:
    """The fit with each data residual's point named (``extra["residual_labels"]``: the quantity,
    the group, the rpm, the airspeed and, in data at incidence, the incidence; the residual vector stacks
    the quantities ``keys`` over their fitted points, :func:`_fitted_rows`), which the text report
    shows beside the largest, and a warning naming the
    residuals beyond OUTLIER_FACTOR times the rms (likely outliers: 3 of them at 7x the rms once
    passed without a word)."""
    rows = _fitted_rows(data, keys)
    r = np.asarray(result.residuals, float)[:sum(int(m.sum()) for m in rows.values())]
    moving = ~data.static & bool(np.any(data.incidence > 0))  # (axial data: no angle said)
    labels = [f"{k}, {data.group[j]}, {data.omega[j] / RPM:.0f} rpm, {data.airspeed[j]:.3g} m/s"
              + (f" at {math.degrees(data.incidence[j]):.3g} deg" if moving[j] else "")
              for k in keys for j in np.flatnonzero(rows[k])]
    rms = float(np.sqrt(np.mean(r**2))) if r.size else 0.0
    out = [i for i in np.argsort(-np.abs(r)) if rms > 0 and abs(r[i]) > OUTLIER_FACTOR * rms]
    warns = list(result.warnings)
    if rms > POOR_FIT:  # (first, after an evaluation limit: the rest is of a model that does not describe the data)
        warns.insert(int(result.hit_max_nfev),
                     f"{_poor_fit(rms)}: the model does not describe these data as one "
                     "propeller's (" + ("the fit did not converge, " if result.hit_max_nfev else "")
                     + "two propellers or set-ups in one file, another geometry, a unit slip?)")
    if out and r.size >= 10:
        shown = "; ".join(f"{labels[i]} ({r[i] / rms:+.1f}x)" for i in out[:3])
        warns.append(f"{len(out)} residual(s) beyond {OUTLIER_FACTOR:g} times the rms residual, the largest misfits: "
                     f"{shown}{' ...' if len(out) > 3 else ''} (outliers in the data, or where the model is weakest: "
                     "check those points)")
    # the residuals' dependence along each quantity's run, in the data's order (a UIUC sweep's J, a stand's steps in
    # time; sorted by rpm, a sweep's measured rpm scattering by 5 rpm shuffled it along J: lag-1 -0.05 for 0.79, a
    # review): the std errors assume none
    key = np.array([f"{k}\x00{data.group[j]}" for k in keys for j in np.flatnonzero(rows[k])])
    order = np.argsort(key, kind="stable")
    auto = lag1_autocorrelation(r[order], key[order]) if r.size else None
    return replace(result, warnings=tuple(warns) if isinstance(result.warnings, tuple) else warns,
                   extra={**result.extra, "residual_labels": labels, "residual_autocorrelation": auto})
