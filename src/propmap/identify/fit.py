"""Parameter identification, Gill & D'Andrea (2017) Section III, with the robustness the
paper lacked (docs/identification.md): bounds, continuation in the stall-blend sharpness M,
a multistart stage and an identifiability report that says what the data do not determine.

Either section model can be identified: the paper's (c_l1, c_l2, c_d, alpha_0), started
from the paper's x0, or a subset of the cambered polar's parameters, started from the
base set (normally the catalogue-fitted ``generic`` set).

* Level flight (eqs 16-18): residual_j = vertical component of the summed rotor forces
  (+ optional body lift, Sec. III-A) - m g, per steady condition j.
* Loads: residuals (model - measured) / RMS(measured) for each measured quantity; several
  propellers can be fitted jointly (:func:`fit_loads_joint`), each weighted alike.

This module holds these two data kinds' residuals; they, and the flight logs'
(identify/flight.py), share one engine: identify/options.py (what is fitted, bounds,
:class:`FitOptions`), identify/engine.py (prior, solve, directions, report),
identify/continuation.py (the continuation in M) and identify/result.py
(:class:`FitResult`, identifiability).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..core.airfoil import Air, CamberedParams, SectionParams, sigmoid_blend
from ..core.hover import HoverModel
from ..core.solver import DEFAULT_DISCRETIZATION, OMEGA_MIN, Discretization, differentiable, rotor_loads
from ..core.vector import rotor_wrench
from .data import LevelFlightData, LoadData, body_to_world, rotor_kinematics
from .load_data import STATIC_AIRSPEED
from ..vehicle import Vehicle, rotor_geometry
from .continuation import _fit_with_continuation
from .engine import (_attach_jacobian, _bounds, _directions_report, _finish, _fit_along_directions, _solve,
                     _m_effect, _params_from, _prior_stats, _with_prior, _x0)
from .options import (BODY_X0, CAMBERED_FIT, CAMBERED_FIT_RE, CAMBERED_FIT_STATIC, FLAP_START, INPLANE_FIT,
                      MIN_RATES_FOR_RE, RATE_STEP, STATIC_RPM_SPAN, X0_PAPER, FitOptions, _default_names, _is_angle,
                      param_names)
from .result import FitResult, Identifiability

__all__ = ["FitOptions", "FitResult", "Identifiability", "X0_PAPER", "fit_level_flight", "fit_loads",
           "fit_loads_joint", "level_flight_forces", "param_names", "CAMBERED_FIT", "CAMBERED_FIT_STATIC",
           "CAMBERED_FIT_RE"]


def level_flight_forces(params: SectionParams, data: LevelFlightData, vehicle: Vehicle, *, air: Air | None = None,
                        discretization: Discretization = DEFAULT_DISCRETIZATION, derivatives=()) -> dict:
    """Rotor loads of every rotor at every condition and the net vertical force (eq 16).

    Uses the vector form (:func:`rotor_wrench`) on V_i = V_vehicle + omega x r_i; for rotor
    axes along body z, no rates and no roll this is exactly eq 16,
    sum_i T_i sin(beta_i) + D_i cos(beta_i).

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
        The section set of every rotor.
    data : LevelFlightData
    vehicle : Vehicle
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization
    derivatives : sequence of str
        Section parameters' names (and ``"collective"``) to differentiate the vertical
        force with respect to, as :func:`propmap.rotor_loads` takes them; () (default): none.

    Returns
    -------
    dict with ``thrust``, ``drag``, ``torque`` (shape (N, n_rotors)) [N, N, N m],
    ``vertical`` (shape (N,)) [N] and ``beta`` (shape (N, n_rotors)) [rad]; with
    ``derivatives`` (section parameters' names) also ``vertical_jacobian``, shape (N, len(names)):
    d vertical / d p by the implicit function theorem (rotor_wrench's derivatives).

    Raises
    ------
    ValueError
        ``derivatives`` that :func:`propmap.rotor_loads` refuses (an unknown or node-changing
        name, Omega below 0.1 rad/s).
    SolverError
        From the rotor model.
    """
    air = params.air if air is None else air
    R, vel = rotor_kinematics(data, vehicle)
    n_rot = len(vehicle.rotors)
    T = np.empty((data.n, n_rot))
    D = np.empty_like(T)
    Q = np.empty_like(T)
    vertical = np.zeros(data.n)
    names = tuple(derivatives or ())
    dvert = np.zeros((data.n, len(names)))
    groups: dict[int, list[int]] = {}
    for i, rotor in enumerate(vehicle.rotors):
        groups.setdefault(id(rotor.propeller), []).append(i)
    for idx in groups.values():
        prop = vehicle.rotors[idx[0]].propeller
        axes = np.stack([vehicle.rotors[i].axis for i in idx])
        spins = np.array([vehicle.rotors[i].spin for i in idx])
        w = rotor_wrench(prop, params, vel[:, idx, :], np.broadcast_to(axes, (data.n, len(idx), 3)),
                         data.omega[:, idx], np.broadcast_to(spins, (data.n, len(idx))), air=air,
                         discretization=discretization, derivatives=names)
        T[:, idx], D[:, idx], Q[:, idx] = w.loads.thrust, w.loads.drag, w.loads.torque
        vertical += np.einsum("nj,nkj->n", R[:, 2, :], w.force)
        for c, n in enumerate(names):
            dvert[:, c] += np.einsum("nj,nkj->n", R[:, 2, :], w.jacobian[("force", n)])
    beta = np.arccos(np.clip(np.einsum("nkj,kj->nk", vel, rotor_geometry(vehicle)[1])  # unit axes
                             / np.maximum(np.linalg.norm(vel, axis=-1), 1e-300), -1, 1))
    out = {"thrust": T, "drag": D, "torque": Q, "vertical": vertical, "beta": beta}
    if names:
        out["vertical_jacobian"] = dvert
    return out


def body_lift(xb, data: LevelFlightData, vehicle: Vehicle, M: float, air: Air) -> np.ndarray:
    """Body lift of Sec. III-A [N], shape (N,): 0.5 rho V^2 C_L^body(beta_body - pi/2) S_body.

    C_L^body has eq 3's form with ``xb`` = (cl1_body, cl2_body, alpha0_body [rad]) and
    sharpness M [1/rad]; the angle of attack is that of the body's z axis against the
    flight direction.
    """
    cl1b, cl2b, a0b = xb
    z_world = body_to_world(data.pitch, data.roll)[:, :, 2]  # body z in world
    beta_body = np.arccos(np.clip(z_world[:, 0], -1, 1))  # angle between velocity (world x) and body z
    a = beta_body - math.pi / 2
    s = sigmoid_blend(a, a0b, M)
    CL = (1 - s) * cl1b * a + s * cl2b * np.sin(a) * np.cos(a)
    return 0.5 * air.rho * data.airspeed**2 * CL * vehicle.body_area


def fit_level_flight(data: LevelFlightData, vehicle: Vehicle, *, base: SectionParams | None = None,
                     air: Air | None = None, options: FitOptions = FitOptions(), start=None) -> FitResult:
    """Identify section parameters from steady level flight, eqs (16)-(18).

    Parameters
    ----------
    data : LevelFlightData
    vehicle : Vehicle
    base : AirfoilParams or CamberedParams, optional
        The model and the constants not fitted; gill2017-apc (the paper's model and
        footnote 2 values) by default. Paper's model: the fit starts from the paper's x0
        and, when the base M exceeds 30, continues in M (FitOptions). Cambered: the fit
        starts from ``base``.
    air : Air, optional
        Default: the parameter set's own (``.air``).
    options : FitOptions
    start : array_like, optional
        The start of the fitted parameters, in the fit's order (default: above). With body
        lift, the fit without it starts there.

    Returns
    -------
    FitResult
        ``residuals`` is eq 17 per condition [N]; ``extra`` holds, with
        ``options.body_lift``, the body-lift verdict. With body lift ``params`` are those
        of the model the F-test selects: the fit with body lift when it matters
        (p < 0.05), else the fit without it.

    Raises
    ------
    ValueError
        Fewer conditions than parameters + 1, a rotor count in ``data.omega`` other than the
        vehicle's, an unknown parameter name, or body lift requested without body_area.
    SolverError
        From the rotor model.
    """
    from ..core.airfoil import preset

    base = base or preset("gill2017-apc")
    air = base.air if air is None else air
    names = _default_names(base, options)
    if options.body_lift:
        if vehicle.body_area <= 0:
            raise ValueError("body_lift needs the vehicle's body_area > 0 m^2")
        names = names + ("cl1_body", "cl2_body", "alpha0_body")
    if data.n <= len(names):
        raise ValueError(f"{data.n} conditions cannot identify {len(names)} parameters; need at least {len(names) + 1}")
    n_rot = len(vehicle.rotors)
    if data.omega.shape[1] != n_rot:
        raise ValueError(f"data.omega has {data.omega.shape[1]} rotor columns; the vehicle has {n_rot} rotors")

    def make_residual(opts):
        def errors(f, x, p):  # the vertical force balance (eq 16) of the model's forces f
            r = f["vertical"] - vehicle.weight
            if opts.body_lift:
                r = r + body_lift(x[-3:], data, vehicle, p.M, air)
            return r

        def residual(x, opts=opts):
            p = _params_from(x, names, base, opts)
            return errors(level_flight_forces(p, data, vehicle, air=air, discretization=opts.discretization), x, p)

        def with_jacobian(x):
            """The residual and its Jacobian from one model call: the rotors' columns from the
            implicit derivatives; the body-lift terms (a closed form, no solve) by central
            differences."""
            x = np.asarray(x, float)
            p = _params_from(x, names, base, opts)
            section = names[:-3] if opts.body_lift else names
            f = level_flight_forces(p, data, vehicle, air=air, discretization=opts.discretization,
                                    derivatives=section)
            r = errors(f, x, p)
            cols = [f["vertical_jacobian"]]
            if opts.body_lift:
                for k in range(3):
                    h = 1e-6 * max(abs(x[-3 + k]), 0.1)
                    hi, lo = x[-3:].copy(), x[-3:].copy()
                    hi[k] += h
                    lo[k] -= h
                    cols.append(((body_lift(hi, data, vehicle, p.M, air) - body_lift(lo, data, vehicle, p.M, air))
                                 / (2 * h))[:, None])
                if "M" in section and opts.M is None:  # the body lift's blend shares the section's M
                    k, h = names.index("M"), 1e-6 * p.M
                    cols[0][:, k] += (body_lift(x[-3:], data, vehicle, p.M + h, air)
                                      - body_lift(x[-3:], data, vehicle, p.M - h, air)) / (2 * h)
            return r, np.hstack(cols)

        section_names = names[:-3] if opts.body_lift else names
        if opts.jacobian == "implicit" and differentiable(base, section_names):
            _attach_jacobian(residual, with_jacobian)
        return residual

    make_data = make_residual
    make_residual, prior = _with_prior(make_residual, names, base, options, scale=vehicle.weight)
    x0 = _x0(names, options, base) if start is None else np.asarray(start, float)
    without = None
    no_body = replace(options, body_lift=False, progress=False, names=names[:-3])
    if options.body_lift:
        # the model without body lift first; the full fit starts from its optimum with
        # zero body lift (BODY_X0), so that it can only improve on it (nested models)
        without = fit_level_flight(data, vehicle, base=base, air=air, options=no_body,
                                   start=None if start is None else x0[:-3])
        x0 = np.concatenate([without.x, BODY_X0])
    best, log, nfev, elapsed, warns, extra = _fit_with_continuation(make_residual, names, base, options,
                                                                    "fit level-flight", x0)
    extra = {"kind": "level_flight", "n_conditions": data.n, "weight_N": vehicle.weight, **extra,
             **_m_effect(make_data, best, base, options)}
    if prior:
        extra["prior"] = prior
    result = _finish(names, base, options, best, log, nfev, elapsed, warns,
                     nfev * data.n * n_rot, air, extra)
    if options.body_lift:
        M_used = result.params.M
        L = body_lift(best.x[-3:], data, vehicle, M_used, air)
        # nested-model F-test: do the 3 body-lift parameters reduce the residual more than
        # fitting noise would? (the paper's Sec. III-A check, made quantitative)
        rss1, rss0 = float(result.residuals @ result.residuals), float(without.residuals @ without.residuals)
        if rss1 < (1 - 1e-6) * rss0:
            # the full fit reached a better optimum of the section parameters than the fit without body lift
            # (a local minimum of that one): the fit without it again from there, so that the test compares
            # the body terms, not two optima of the section
            again = fit_level_flight(data, vehicle, base=base, air=air, options=no_body, start=best.x[:-3])
            spent = {"nfev": again.nfev + without.nfev, "elapsed_s": again.elapsed_s + without.elapsed_s}
            # (the fit's own objective decides: with the population prior it is more than the data's residual)
            better = _objective(again) < _objective(without)
            without = replace(again if better else without, **spent)
            rss0 = float(without.residuals @ without.residuals)
        dof1 = data.n - len(names)
        # (F >= 0: after that second fit the model without body lift can end a little below the full fit, which was
        # not run again from it; no evidence for body lift then)
        F = max((rss0 - rss1) / 3, 0.0) / (rss1 / dof1) if rss1 > 0 and dof1 > 0 else math.inf
        from scipy import stats

        p_value = float(stats.f.sf(F, 3, dof1)) if dof1 > 0 else float("nan")
        matters = bool(p_value < 0.05)
        verdict = {
            "max_abs_N": float(np.max(np.abs(L))), "max_abs_over_weight": float(np.max(np.abs(L)) / vehicle.weight),
            "rms_residual_with": float(np.sqrt(rss1 / data.n)), "rms_residual_without": float(np.sqrt(rss0 / data.n)),
            "F": float(F), "p_value": p_value, "matters": matters,
            "body_terms": {"cl1_body": float(best.x[-3]), "cl2_body": float(best.x[-2]),
                           "alpha0_body_deg": math.degrees(best.x[-1])},
        }
        if not matters:
            # the F-test selects the model without body lift: report and write that one
            return replace(without, extra={**without.extra, "body_lift": {**verdict, "selected": "without"}},
                           nfev=without.nfev + nfev, elapsed_s=without.elapsed_s + elapsed)
        result.extra["body_lift"] = {**verdict, "selected": "with"}
    return result


def _objective(result: FitResult) -> float:
    """The objective a fit minimised: 0.5 |residuals|^2 plus the population prior's term, if any."""
    return result.cost + result.extra.get("prior", {}).get("cost", 0.0)


def hover_vertical_force(params: SectionParams, data: LevelFlightData, vehicle: Vehicle, *, air: Air | None = None):
    """Vertical force of the hover model (T = k_T Omega^2 along each rotor axis, D = 0) [N], shape (N,).

    k_T of each propeller from the model at V = 0 at the mean rotor speed of the
    slowest condition (the hover point of the data set).

    Raises
    ------
    SolverError
        From the rotor model.
    """
    air = params.air if air is None else air
    R = body_to_world(data.pitch, data.roll)
    j0 = int(np.argmin(data.airspeed))
    out = np.zeros(data.n)
    for i, rotor in enumerate(vehicle.rotors):
        h = HoverModel.from_model(rotor.propeller, params, float(np.mean(data.omega[j0])), air=air)
        out += h.thrust(data.omega[:, i]) * np.einsum("nj,j->n", R[:, 2, :], rotor.axis)
    return out


def _load_norms(data: LoadData, propeller, keys, air: Air):
    n = data.omega / (2 * math.pi)
    norm = {k: air.rho * n**2 * propeller.diameter ** (5 if k == "torque" else 4) for k in keys}
    scales = {k: float(np.sqrt(np.mean((data.measured[k] / norm[k]) ** 2))) for k in keys}
    for k, s in scales.items():
        if not (np.isfinite(s) and s > 0):
            others = [q for q in keys if q != k]
            raise ValueError(f"measured {k} is zero everywhere or not finite, so it cannot be fitted: fit "
                             f"{', '.join(others) or 'another quantity'} alone (quantities=, the CLI's --quantities)")
    return norm, scales


def _load_keys(data: LoadData, quantities) -> list:
    keys = list(quantities or data.measured)
    for k in keys:
        if k not in data.measured:
            raise ValueError(f"quantity {k!r} is not measured; measured: {', '.join(data.measured)}")
    return keys


def _data_kind(data: LoadData) -> str:
    """"static" (all airspeeds static: at most STATIC_AIRSPEED, a stand's pitot noise included),
    "collective" (static, several collectives), "few_rates" (moving points at < MIN_RATES_FOR_RE
    rotation rates, :func:`_sweep_rates`, and no static run spanning STATIC_RPM_SPAN, within a
    relative 1e-6 so that a unit's rounding does not decide) or "rates"."""
    moving = data.airspeed > STATIC_AIRSPEED
    if not moving.any():
        swept = data.collective is not None and np.ptp(data.collective) > 0
        return "collective" if swept else "static"
    rates = _sweep_rates(data)
    static = data.omega[~moving]
    spans = static.size > 1 and float(static.max() / static.min()) >= STATIC_RPM_SPAN * (1.0 - 1e-6)
    return "rates" if rates >= MIN_RATES_FOR_RE or spans else "few_rates"


def _measures_inplane_force(data: LoadData, keys) -> bool:
    """Whether the fitted quantities include the in-plane force D measured where the rotor
    has an in-plane speed (V sin beta > 0): what identifies the flapping (INPLANE_FIT)."""
    if "drag" not in keys:
        return False
    in_plane = data.airspeed * np.abs(np.sin(data.incidence))  # (axial below 1e-12 V, as the solver: sin(pi) ~ 1e-16)
    edgewise = (in_plane > 1e-12 * data.airspeed) & np.isfinite(data.measured["drag"])
    return bool(edgewise.any())


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
    moving = data.airspeed > STATIC_AIRSPEED
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
    if kind == "collective" or options.names is not None or stats is None or len(stats[0]) != len(names):
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

    def make(opts):
        def loads(x, derivatives=False):
            p = _params_from(x, names, base, opts)
            return rotor_loads(propeller, p, data.omega, data.airspeed, data.incidence, air=air,
                               discretization=opts.discretization, collective=data.collective,
                               derivatives=names if derivatives else False)

        def errors(r):
            model = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque}
            return weight * np.concatenate([(model[k] - data.measured[k]) / norm[k] / scales[k] for k in keys])

        def residual(x, opts=opts):
            return errors(loads(x))

        def with_jacobian(x):
            r = loads(x, derivatives=True)
            return errors(r), weight * np.vstack([np.column_stack([r.derivative(k, n) for n in names])
                                                  / norm[k][:, None] / scales[k] for k in keys])

        if (opts.jacobian == "implicit" and differentiable(base, names)
                and np.all(data.omega >= OMEGA_MIN)):
            _attach_jacobian(residual, with_jacobian)  # (a parked point, below OMEGA_MIN, has no derivatives)
        return residual

    return make, scales


def fit_loads(data: LoadData, propeller, *, base: SectionParams | None = None, air: Air | None = None,
              quantities: tuple[str, ...] | None = None, options: FitOptions = FitOptions()) -> FitResult:
    """Identify section parameters from direct load measurements of one propeller.

    Residuals are compared in coefficient form so that every rpm weighs alike: for each
    fitted quantity k, (model_k - measured_k) / (rho n^2 D^m_k) / RMS(measured coefficient),
    m = 4 for thrust and drag (CT), 5 for torque (CQ); the residuals of all k are stacked.

    Parameters
    ----------
    data : LoadData
        Static thrust-stand data (all airspeeds 0), wind-tunnel sweeps, or both.
    propeller : Propeller
    base : AirfoilParams or CamberedParams, optional
        The model, the start and the constants not fitted; the catalogue-fitted
        ``generic`` cambered set by default (``gill2017-apc`` for the paper's model).
    air : Air, optional
        Default: the parameter set's own (``.air``).
    quantities : tuple of str, optional
        Which measured quantities to fit (default: all in ``data.measured``).
    options : FitOptions
        ``names`` default: the paper's four parameters; for the cambered model as
        :class:`FitOptions` says (CAMBERED_FIT_RE or CAMBERED_FIT under the prior,
        CAMBERED_FIT_STATIC for a static run without it), and under the prior, by default,
        only the data's leading directions for a static run or sweeps at one rotation rate
        (``FitOptions.directions``; identify/directions.py). Where the fitted quantities
        include the in-plane force ``drag`` measured at points with an in-plane speed, the
        cambered model's default also frees the flapping (INPLANE_FIT, outside the prior, so
        every name is fitted; docs/identification.md, Load data at incidence).

    Returns
    -------
    FitResult
        With a fit along directions ``extra["directions"]``: their count, coefficients and
        std errors (posterior and data only) in prior standard deviations, loadings, the
        eigenvalues and the base (angles in degrees, ``units``); the parameters' std errors
        are the posterior's with the held directions at the population's spread.

    Raises
    ------
    ValueError
        Unknown or unmeasured quantity, an unknown parameter name, fewer residuals than
        parameters + 1, or a measured quantity that is zero everywhere.
    SolverError
        From the rotor model.

    Notes
    -----
    Residual method of Gill & D'Andrea (2017), Section III, applied to load measurements;
    the population prior and the directions: docs/identification.md.
    """
    from ..io.calibration import generic_params

    base = base or generic_params()
    air = base.air if air is None else air
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
    if data.n * len(keys) <= free:
        raise ValueError(f"{data.n} points cannot identify {free} parameters" if k_dirs == 0 else
                         f"{data.n} points of {', '.join(keys)} cannot identify {free} parameter directions")
    make_data, scales = _load_residual(data, propeller, keys, air, names, base)
    make_residual, prior = _with_prior(make_data, names, base, options)
    notes, outside, spent = [], [], (0, 0.0)
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
        notes.append(f"{', '.join(INPLANE_FIT)} fitted too: the data measure the in-plane force at incidence "
                     "(docs/identification.md)")
    warns = [*notes, *warns]
    extra = {"kind": "loads", "n_points": data.n, "quantities": keys, "coefficient_scales": scales, **extra,
             **_m_effect(make_data, best, base, options)}
    if prior:
        extra["prior"] = prior
    result = _finish(names, base, options, best, log, nfev, elapsed, warns, nfev * data.n, air, extra)
    if inplane:
        result = _flap_saturation(result, make_residual(options), options)
    return result if k_dirs == 0 else _directions_report(result, options)


def _flap_saturation(result: FitResult, residual, options: FitOptions) -> FitResult:
    """The flap compliance's upper 95% limit from the profile likelihood where the linearised
    one is too narrow.

    The flapping saturates: beyond a few rad/(N m) a propeller's blades flap nearly as an
    articulated blade's (the centrifugal stiffening), so the loads change little and the
    linearised interval, from the local slope, is far too narrow (a user-level audit,
    2026-11-26: fits of loads made with a compliance of 15 and 1% noise gave 7-50, each with
    an interval of about +-10%). The profile likelihood decides (D. J. Venzon and S. H.
    Moolgavkar, "A method for computing profile-likelihood-based confidence intervals",
    Applied Statistics 37(1), 1988): the other parameters refitted (``residual``, with the
    prior's rows where the fit had them) with the compliance held, the upper limit is where
    the cost has risen by the 95% criterion, (t_{0.975, N-p})^2 / 2 times the data's residual
    variance. Held at the upper bound first: a smaller rise puts the limit at the bound;
    else held at the linearised limit: a smaller rise there means that limit is too narrow,
    and five bisections (geometric) between it and the bound place the profile's. The limit
    and a warning replace the linearised ones; the lower limit stays linearised. 1-7 refits of
    the other parameters from the optimum, by the fit engine (engine._solve, one start).
    """
    names = result.names
    if "flap_compliance" not in names or "flap_compliance" in result.at_bound:
        return result
    from scipy import stats

    from ..core.solver import SolverError

    j = names.index("flap_compliance")
    lb, ub = _bounds(names, options)
    top = float(ub[j])
    x_opt = np.asarray(result.x, float)
    if not (math.isfinite(top) and x_opt[j] < top):
        return result
    keep = np.array([i != j for i in range(len(names))])
    others = tuple(n for n in names if n != "flap_compliance")
    refit = replace(options, multistart=0)  # (from the optimum: one local refit)
    both = getattr(residual, "with_jacobian", None)
    dof = max(result.residuals.size - len(names), 1)
    s2 = float(result.residuals @ result.residuals) / dof
    optimum = result.cost + float(result.extra.get("prior", {}).get("cost", 0.0))
    edge = 0.5 * float(stats.t.ppf(0.975, dof)) ** 2 * s2

    def rise(k: float) -> float:
        """The profile's cost at compliance k, less the optimum's: the fit engine's refit of the others."""
        def held(z):
            return residual(np.insert(np.asarray(z, float), j, k))

        if both is not None:
            def held_with_jacobian(z):
                r, J = both(np.insert(np.asarray(z, float), j, k))
                return r, J[:, keep]

            _attach_jacobian(held, held_with_jacobian)
        best = _solve(held, others, refit, "profile", x_opt[keep])[0]
        return float(best.cost) - optimum

    idf = result.identifiability
    ci = np.array(idf.ci95, dtype=float)
    linear = float(ci[j, 1])
    try:
        at_top = rise(top)
        if at_top < edge:
            limit, why = top, (f"the data hardly tell {x_opt[j]:.3g} from the bound {top:g} rad/(N m) (refitted with "
                               f"it there, the cost rises by {at_top / s2:.2g} residual variances, the 95% edge "
                               f"{edge / s2:.2g}): the blades' flapping saturates, so the 95% interval reaches the "
                               "bound (the data say the blades flap at least about this much, not how much more)")
        elif math.isfinite(linear) and x_opt[j] < linear < top and rise(linear) < edge:
            lo_k, hi_k = linear, top
            for _ in range(5):
                mid = math.sqrt(lo_k * hi_k)
                lo_k, hi_k = (mid, hi_k) if rise(mid) < edge else (lo_k, mid)
            limit, why = hi_k, (f"its 95% interval's upper end is {hi_k:.3g} rad/(N m) by the profile likelihood "
                                f"(the linearised one, {linear:.3g}, is too narrow: the flapping saturates)")
        else:
            return result
    except (SolverError, ValueError, FloatingPointError):  # a refit that fails leaves the linearised interval
        return result
    ci[j, 1] = limit
    warns = (*result.warnings, f"flap_compliance: {why}")
    return replace(result, identifiability=replace(idf, ci95=ci), warnings=warns)


def fit_loads_joint(datasets, *, base: SectionParams | None = None, air: Air | None = None,
                    options: FitOptions = FitOptions(), weights=None) -> FitResult:
    """One parameter set fitted to the load measurements of several propellers at once.

    Each propeller's residuals (as :func:`fit_loads`, all measured quantities) are
    weighted by sqrt(w / its number of points), so that every propeller counts in
    proportion to its weight w whatever its number of measurements (alike by default).
    This is how the catalogue's ``generic`` set is made (tools/calibrate_catalogue.py).

    Parameters
    ----------
    datasets : sequence of (LoadData, Propeller)
    base, air, options
        As :func:`fit_loads`.
    weights : sequence of float, optional
        One positive, finite weight per dataset, its share of the sum of squares (default:
        1 each).

    Returns
    -------
    FitResult
        ``residuals`` stacked over the propellers in order; ``extra["per_propeller"]``
        gives each propeller's name, point count and rms (unweighted) residual.

    Raises
    ------
    ValueError
        No datasets, ``weights`` not one positive finite number per dataset, or as
        :func:`fit_loads`.
    SolverError
        From the rotor model.
    """
    from ..io.calibration import generic_params

    datasets = list(datasets)
    if not datasets:
        raise ValueError("fit_loads_joint needs at least one (data, propeller) pair")
    try:
        w = np.ones(len(datasets)) if weights is None else np.asarray(weights, dtype=float)
    except (TypeError, ValueError):
        w = np.array([np.nan])
    if w.shape != (len(datasets),) or not np.all(np.isfinite(w) & (w > 0)):
        raise ValueError(f"weights must be {len(datasets)} positive finite numbers (one per dataset), got "
                         f"{weights!r:.80}")
    base = base or generic_params()
    air = base.air if air is None else air
    names = _default_names(base, options)
    makers = []
    for (data, prop), wk in zip(datasets, w):
        makers.append(_load_residual(data, prop, _load_keys(data, None), air, names, base,
                                     weight=math.sqrt(wk) / math.sqrt(data.n))[0])

    def make_residual(opts):
        parts = [m(opts) for m in makers]

        def residual(x, opts=opts):
            return np.concatenate([f(x) for f in parts])

        if all(hasattr(f, "with_jacobian") for f in parts):  # each propeller's implicit Jacobian, stacked
            def with_jacobian(x):
                pairs = [f.with_jacobian(x) for f in parts]
                return np.concatenate([r for r, _ in pairs]), np.vstack([J for _, J in pairs])

            _attach_jacobian(residual, with_jacobian)
        return residual

    best, log, nfev, elapsed, warns, extra = _fit_with_continuation(make_residual, names, base, options,
                                                                    "fit loads (joint)", _x0(names, options, base))
    result = _finish(names, base, options, best, log, nfev, elapsed, warns,
                     nfev * sum(d.n for d, _ in datasets), air, {"kind": "loads_joint", **extra})
    per, k = [], 0
    for (data, prop), wk in zip(datasets, w):
        m = data.n * len(data.measured)
        r = best.fun[k:k + m] * (math.sqrt(data.n) / math.sqrt(wk))
        per.append({"propeller": prop.name, "n_points": data.n, "rms_residual": float(np.sqrt(np.mean(r ** 2)))})
        k += m
    result.extra["per_propeller"] = per
    return result
