"""Level flight, Gill & D'Andrea (2017) Section III, eqs (16)-(18): the rotors' net vertical
force of a vehicle at steady level-flight conditions, the body lift of Sec. III-A, the fit of
section parameters to the vertical force balance and the hover model's vertical force beside it.

The fit is one of the data kinds of the shared engine (identify/engine.py: prior, solve,
report; identify/continuation.py: the continuation in M); the load data's fits are in
identify/fit.py, the flight logs' in identify/flight.py.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..core.airfoil import Air, SectionParams, sigmoid_blend
from ..core.flapping import flapping_warning_held
from ..core.hover import HoverModel
from ..core.solver import DEFAULT_DISCRETIZATION, Discretization, differentiable, model_air
from ..vehicle import Vehicle, rotor_geometry, vehicle_wrench
from .continuation import _fit_with_continuation
from .data import LevelFlightData, body_to_world, rotor_kinematics
from .level_flight import check_level_flight
from .engine import (_attach_jacobian, _finish, _m_effect, _objective, _params_from, _warn_at_optimum, _with_prior,
                     _x0)
from .options import BODY_X0, FitOptions, _default_names, refuse_unused_options
from .dependence import lag1_autocorrelation
from .result import FitResult

__all__ = ["body_lift", "fit_level_flight", "hover_vertical_force", "level_flight_forces"]


def level_flight_forces(params: SectionParams, data: LevelFlightData, vehicle: Vehicle, *, air: Air | None = None,
                        discretization: Discretization = DEFAULT_DISCRETIZATION, derivatives=()) -> dict:
    """Rotor loads of every rotor at every condition and the net vertical force (eq 16).

    Uses the vehicle model (:func:`propmap.vehicle_wrench`: each hub at V_i = V_vehicle +
    omega x r_i, the vector form of :func:`propmap.core.vector.rotor_wrench`, a rotor's own
    parameter set where it has one, the vehicle's ``rotor_interference`` and airframe drag,
    ``body_drag``, in the rotors' slipstream too); the body lift of Sec. III-A is the fit's
    own term. For rotor axes along body z, no rates, no roll and no airframe drag this is
    exactly eq 16, sum_i T_i sin(beta_i) + D_i cos(beta_i). (Until 2026-12-01 each rotor's
    loads were solved with ``params`` alone, without the interference or the airframe: a
    structural review found a vehicle with ``rotor_interference = 1`` 0.5% off and a rotor's
    own set ignored, a vehicle-model audit a [body] table with ``wash_factor`` 1 whose
    downwash on the airframe, 13-19% of the weight at 0-10 m/s, the fit and ``simulate_level_flight``
    left out, without a word.)

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
    ``vertical`` (shape (N,), the rotors' and the airframe's) [N] and ``beta`` (shape
    (N, n_rotors)) [rad]; with
    ``derivatives`` (section parameters' names) also ``vertical_jacobian``, shape (N, len(names)):
    d vertical / d p by the implicit function theorem (vehicle_wrench's derivatives).

    Raises
    ------
    ValueError
        ``derivatives`` that :func:`propmap.vehicle_wrench` refuses (an unknown or
        node-changing name, Omega below 0.1 rad/s, a vehicle with rotor interference, a
        section parameter where a rotor has its own set).
    SolverError
        From the rotor model.
    TypeError
        ``params``, ``data``, ``vehicle`` or ``air`` of the wrong type.
    """
    air = model_air(params, air)
    R, vel = rotor_kinematics(data, vehicle)
    names = tuple(derivatives or ())
    # the body velocity R^T V_world, V_world along world x: V times R's first row
    w = vehicle_wrench(vehicle, params, data.airspeed[:, None] * R[:, 0, :], data.rates, data.omega, air=air,
                       discretization=discretization, derivatives=names or False)
    up = R[:, 2, :]  # the world vertical in body axes
    beta = np.arccos(np.clip(np.einsum("nkj,kj->nk", vel, rotor_geometry(vehicle)[1])  # unit axes
                             / np.maximum(np.linalg.norm(vel, axis=-1), 1e-300), -1, 1))
    out = {**{k: np.stack([getattr(ld, k) for ld in w.loads], axis=1) for k in ("thrust", "drag", "torque")},
           "vertical": np.einsum("nj,nj->n", up, w.force), "beta": beta}
    if names:
        out["vertical_jacobian"] = np.stack([np.einsum("nj,nj->n", up, w.jacobian[("force", n)]) for n in names],
                                            axis=1)
    return out


def body_lift(xb, data: LevelFlightData, vehicle: Vehicle, M: float, air: Air) -> np.ndarray:
    """Body lift of Sec. III-A [N], shape (N,): 0.5 rho V^2 C_L^body(beta_body - pi/2) S_body.

    C_L^body has eq 3's form with ``xb`` = (cl1_body, cl2_body, alpha0_body [rad]) and
    sharpness M [1/rad]; the angle of attack is that of the body's z axis against the
    flight direction.

    Parameters
    ----------
    xb : sequence of 3 floats
        cl1_body [1/rad], cl2_body [-], alpha0_body [rad].
    data : LevelFlightData
        N level-flight conditions (airspeed, pitch, roll).
    vehicle : Vehicle
        Its ``body_area`` S_body [m^2].
    M : float
        Stall-blend sharpness [1/rad], > 0.
    air : Air
        The density rho [kg/m^3].

    Returns
    -------
    ndarray, shape (N,)
        The body lift [N] along the world vertical.
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
        vehicle's, a rotor with its own parameter set (one set is fitted for every rotor), an
        unknown parameter name, body lift requested without body_area, or a ``start`` of
        another length than the fitted names, not finite or outside their bounds.
    SolverError
        From the rotor model.
    TypeError
        ``data``, ``vehicle``, ``base``, ``air`` or ``options`` of the wrong type.
    """
    from ..core.airfoil import preset

    check_level_flight(data, vehicle)
    if not isinstance(options, FitOptions):  # (None met "'NoneType' object has no attribute 'names'")
        raise TypeError(f"options must be a propmap.identify.FitOptions, got {type(options).__name__}")
    refuse_unused_options(options, "fit_level_flight", body_lift=True)
    base = base or preset("gill2017-apc")
    air = model_air(base, air, name="base")
    names = _level_flight_names(data, vehicle, base, options)
    make_data = _level_flight_residual(data, vehicle, names, base, air)
    make_residual, prior = _with_prior(make_data, names, base, options, scale=vehicle.weight)
    x0 = _x0(names, options, base) if start is None else _checked_start(start, names, options)
    without = None
    no_body = replace(options, body_lift=False, progress=False, names=names[:-3])
    if options.body_lift:
        # the model without body lift first; the full fit starts from its optimum with
        # zero body lift (BODY_X0), so that it can only improve on it (nested models)
        with flapping_warning_held():  # (the nested model's optimum is a trial point of this fit)
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
                     nfev * data.n * len(vehicle.rotors), air, extra)
    # the residuals' dependence from condition to condition, in the data's order (the std errors assume none; load and
    # flight fits report it since 2026-11-27, this fit did not: a structural review)
    result.extra["residual_autocorrelation"] = lag1_autocorrelation(result.residuals[:data.n], np.zeros(data.n))
    if options.body_lift:
        result = _select_body_lift(result, best, without, data, vehicle, base, air, no_body, (nfev, elapsed))
    _warn_at_optimum(result, make_data, options)
    return result


def _checked_start(start, names, options: FitOptions) -> np.ndarray:
    """``start`` as one finite number per fitted name, within its bounds (a wrong length met a
    broadcasting error, NaN "Initial guess is outside of provided bounds", a start beyond a bound
    was clipped without a word: an API audit, stop 100)."""
    from .optimizer import _bounds

    try:
        x = np.asarray(start, float)
    except (TypeError, ValueError):
        raise ValueError(f"start must be numbers, one per fitted parameter ({', '.join(names)}), got "
                         f"{start!r:.60}") from None
    if x.shape != (len(names),):
        raise ValueError(f"start must have {len(names)} values, one per fitted parameter ({', '.join(names)}), got "
                         f"shape {x.shape}")
    lb, ub = _bounds(names, options)
    for n, v, lo, hi in zip(names, x, lb, ub):
        if not (math.isfinite(v) and lo <= v <= hi):
            raise ValueError(f"start: {n} = {float(v)!r} is outside its bounds [{lo:g}, {hi:g}] (or not finite)")
    return x


def _level_flight_names(data: LevelFlightData, vehicle: Vehicle, base: SectionParams,
                        options: FitOptions) -> tuple[str, ...]:
    """The fitted names (the body-lift terms last), refused where the data cannot identify them."""
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
    own = [k + 1 for k, r in enumerate(vehicle.rotors) if r.params is not None]
    if own:  # (fit_flight's refusal; until 2026-12-01 the rotors' own sets were silently replaced by the fitted one)
        raise ValueError(f"rotor(s) {', '.join(map(str, own))} of the vehicle carry their own parameter sets, which "
                         "the fitted section parameters would not reach: fit_level_flight fits one set for every "
                         "rotor (build the vehicle without the rotors' params)")
    return names


def _level_flight_residual(data: LevelFlightData, vehicle: Vehicle, names, base: SectionParams, air: Air):
    """The engine's ``make_residual`` of eq 17: the vertical force balance per condition [N], with
    the implicit Jacobian where the section's derivatives reach every name."""

    def make_residual(opts):
        def errors(f, x, p):  # the vertical force balance (eq 16) of the model's forces f
            r = f["vertical"] - vehicle.weight
            if opts.body_lift:
                r = r + body_lift(x[-3:], data, vehicle, p.M, air)
            return r

        def residual(x, opts=opts):
            p = _params_from(x, names, base, opts)
            with flapping_warning_held():  # (a trial point's: said once at the fit's optimum)
                return errors(level_flight_forces(p, data, vehicle, air=air, discretization=opts.discretization), x,
                              p)

        def with_jacobian(x):
            """The residual and its Jacobian from one model call: the rotors' columns from the
            implicit derivatives; the body-lift terms (a closed form, no solve) by central
            differences."""
            x = np.asarray(x, float)
            p = _params_from(x, names, base, opts)
            section = names[:-3] if opts.body_lift else names
            with flapping_warning_held():
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
        if opts.jacobian == "implicit" and differentiable(base, section_names) and vehicle.rotor_interference == 0:
            _attach_jacobian(residual, with_jacobian)
        # the model's warnings at the optimum (engine._warn_at_optimum); x may be the selected fit's without body lift,
        # names[:-3]'s values (the body-lift terms, last, are no section field)
        residual.at_optimum = lambda x: level_flight_forces(_params_from(x, names, base, opts), data, vehicle, air=air,
                                                            discretization=opts.discretization)
        return residual

    return make_residual


def _select_body_lift(result: FitResult, best, without: FitResult, data: LevelFlightData, vehicle: Vehicle,
                      base: SectionParams, air: Air, no_body: FitOptions, spent: tuple[int, float]) -> FitResult:
    """The paper's Sec. III-A check, made quantitative: a nested-model F-test of the three body-lift
    terms; the fit with them (``result``) when they matter (p < 0.05), else the fit without them,
    each with the verdict in ``extra["body_lift"]``. ``spent``: the full fit's (nfev, elapsed_s)."""
    nfev, elapsed = spent
    L = body_lift(best.x[-3:], data, vehicle, result.params.M, air)
    # do the 3 body-lift parameters reduce the residual more than fitting noise would?
    rss1, rss0 = float(result.residuals @ result.residuals), float(without.residuals @ without.residuals)
    if rss1 < (1 - 1e-6) * rss0:
        # the full fit reached a better optimum of the section parameters than the fit without body lift
        # (a local minimum of that one): the fit without it again from there, so that the test compares
        # the body terms, not two optima of the section
        again = fit_level_flight(data, vehicle, base=base, air=air, options=no_body, start=best.x[:-3])
        totals = {"nfev": again.nfev + without.nfev, "elapsed_s": again.elapsed_s + without.elapsed_s}
        # (the fit's own objective decides: with the population prior it is more than the data's residual)
        better = _objective(again) < _objective(without)
        without = replace(again if better else without, **totals)
        rss0 = float(without.residuals @ without.residuals)
    dof1 = data.n - len(result.names)
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


def hover_vertical_force(params: SectionParams, data: LevelFlightData, vehicle: Vehicle, *, air: Air | None = None):
    """Vertical force of the hover model (T = k_T Omega^2 along each rotor axis, D = 0) [N], shape (N,).

    k_T of each propeller from the model at V = 0 at the mean rotor speed of the
    slowest condition (the hover point of the data set).

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
        The section set the hover thrust coefficient comes from.
    data : LevelFlightData
        N level-flight conditions (rotor speeds, attitude).
    vehicle : Vehicle
        Rotor positions, axes and propellers.
    air : Air, optional
        Default: ``params.air``.

    Returns
    -------
    ndarray, shape (N,)
        The vertical force [N] (world frame, up positive) of the hover model.

    Raises
    ------
    SolverError
        From the rotor model.
    """
    air = model_air(params, air)
    R = body_to_world(data.pitch, data.roll)
    j0 = int(np.argmin(data.airspeed))
    out = np.zeros(data.n)
    for i, rotor in enumerate(vehicle.rotors):
        h = HoverModel.from_model(rotor.propeller, params, float(np.mean(data.omega[j0])), air=air)
        out += h.thrust(data.omega[:, i]) * np.einsum("nj,j->n", R[:, 2, :], rotor.axis)
    return out
