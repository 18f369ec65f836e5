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
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, fields, replace

import numpy as np

from ..core.airfoil import Air, AirfoilParams, CamberedParams, SectionParams, sigmoid_blend
from ..core.hover import HoverModel
from ..core.solver import DEFAULT_DISCRETIZATION, OMEGA_MIN, Discretization, differentiable, rotor_loads
from ..core.vector import rotor_wrench
from .data import LevelFlightData, LoadData, body_to_world, rotor_kinematics
from ..vehicle import Vehicle

__all__ = ["FitOptions", "FitResult", "Identifiability", "X0_PAPER", "fit_level_flight", "fit_loads",
           "fit_loads_joint", "level_flight_forces", "param_names", "CAMBERED_FIT", "CAMBERED_FIT_STATIC",
           "CAMBERED_FIT_RE"]

#: the paper's initial guess (c_l1, c_l2, c_d, alpha_0) = (2 pi, 2, 0, 0.47)
X0_PAPER = (2 * math.pi, 2.0, 0.0, 0.47)
#: default bounds for (cl1, cl2, cd, alpha0 [rad]); wide but physical
BOUNDS = {"cl1": (0.5, 15.0), "cl2": (0.0, 6.0), "cd": (0.0, 10.0), "alpha0": (math.radians(3), math.radians(60))}
#: default bounds of the cambered polar's parameters (SI, angles in rad): the range of
#: low-Reynolds-number propeller sections, wide enough that the catalogue fits end inside
CAMBERED_BOUNDS = {
    "cl_alpha": (2.0, 9.0), "alpha_L0": (math.radians(-15), math.radians(5)), "cl_max": (0.4, 2.5),
    "cl_min": (-1.5, -0.05), "cd_min": (0.002, 0.2), "cd2": (0.0, 2.0), "cl_cdmin": (-0.5, 1.5),
    "cd90": (0.5, 3.0), "re_exp": (-1.5, 0.5), "re_exp_lift": (-0.3, 0.8), "re_exp_stall": (-0.5, 1.0),
    "stall_delay": (0.0, 15.0), "alpha_L0_re": (math.radians(-4), math.radians(4)), "M": (5.0, 100.0),
}
#: natural size of each cambered parameter: a standard error above POOR_REL_STD of
#: max(|estimate|, this) is "poorly determined" (parameters whose value may be ~0)
CAMBERED_SCALE = {"alpha_L0": math.radians(2), "cl_cdmin": 0.3, "re_exp": 0.3, "re_exp_lift": 0.1,
                  "re_exp_stall": 0.1, "stall_delay": 1.0, "alpha_L0_re": math.radians(1), "cd2": 0.05}
#: cambered parameters fitted by default from data with advance-ratio sweeps / static only /
#: sweeps at several Reynolds numbers (docs/identification.md has the measured choice)
CAMBERED_FIT = ("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2")
CAMBERED_FIT_RE = CAMBERED_FIT + ("re_exp_lift", "re_exp", "alpha_L0_re")
#: static-only data without the prior: two parameters (a static run has two or three degrees
#: of freedom; fitted freely, more parameters chase them)
CAMBERED_FIT_STATIC = ("alpha_L0", "cd_min")
#: a hover collective sweep (static points at several collectives) spans the angles of
#: attack: the lift slope and the drag polar are identified too
CAMBERED_FIT_COLLECTIVE = ("cl_alpha", "alpha_L0", "cd_min", "cd2")
#: sweeps at this many distinct rotation rates (or more) let the fit estimate the
#: Reynolds terms (CAMBERED_FIT_RE); fewer keep them at the base values
MIN_RATES_FOR_RE = 3
#: ... as does a static run over this ratio of rotation rates (a UIUC static run spans 2-8x):
#: with the static run and the lowest sweep, leave-one-family-out on both UIUC volumes
#: (docs/identification.md) gave a held-out median of 3.9% (vol. 1) and 5.0% (vol. 2) with the
#: Reynolds terms fitted, 3.5% and 7.7% with them held at the generic set's
STATIC_RPM_SPAN = 1.5
BODY_BOUNDS = {"cl1_body": (0.0, 10.0), "cl2_body": (0.0, 5.0), "alpha0_body": (math.radians(3), math.radians(60))}
BODY_X0 = (0.0, 0.0, 0.47)
#: bounds of the rotor options (RotorOptions) and of the airframe drag (core/body.py) when fitted
ROTOR_BOUNDS = {"collective": (math.radians(-15), math.radians(15)), "flap_compliance": (0.0, 50.0)}
AIRFRAME_BOUNDS = {"drag_area_x": (0.0, 0.05), "drag_area_y": (0.0, 0.05), "drag_area_z": (0.0, 0.05),
                   "wash_factor": (0.0, 3.0), "cg_x": (-0.05, 0.05), "cg_y": (-0.05, 0.05),
                   "rotor_interference": (0.0, 3.0)}
#: parameters that are angles [rad], reported in degrees
ANGLES = ("alpha0", "alpha0_body", "alpha_L0", "alpha_L0_re", "collective")
POOR_REL_STD = 0.10  # relative std error above which a parameter is reported poorly determined
SCREEN_NFEV = 12  # residual evaluations per start in the multistart screening stage
NM_STAT_TOL = 0.01  # Nelder-Mead at its limit counts as converged within 1% of the std errors
M_SMOOTH = 30.0  # first stage of the continuation in M (eq 3's blend has no root folds at 30)
SAME_COST_RTOL = 0.01  # multistart optima within 1% in cost ...
DIFFERENT_X_RTOL = 0.05  # ... but 5% apart in a parameter: the data do not determine it


def param_names(lift_model: str) -> tuple[str, ...]:
    """Fitted parameters of the paper's model: all four for eq 3, (cl2, cd) for footnote 1's sin-cos lift."""
    return ("cl1", "cl2", "cd", "alpha0") if lift_model == "sigmoid" else ("cl2", "cd")


def _default_names(base: SectionParams, options: "FitOptions", data_kind: str = "rates") -> tuple[str, ...]:
    """The parameters fitted: ``options.names`` (checked), else the default for
    ``data_kind`` "static", "collective" (a static collective sweep), "few_rates" or "rates"."""
    if options.names is not None:
        return _check_names(options.names, base, options)
    if isinstance(base, CamberedParams):
        if data_kind == "collective":
            return CAMBERED_FIT_COLLECTIVE
        if data_kind == "static" and not options.prior:
            return CAMBERED_FIT_STATIC
        return CAMBERED_FIT if data_kind == "few_rates" else CAMBERED_FIT_RE
    return param_names(options.lift_model)


def _check_names(names, base: SectionParams, options: "FitOptions", extra=()) -> tuple[str, ...]:
    """``names`` as a tuple, refused unless each is a parameter of the base's model (the
    paper's: cl1, cl2, cd, alpha0; the cambered: CAMBERED_BOUNDS and any field given
    bounds in ``options.bounds``), a rotor option (ROTOR_BOUNDS) or one of ``extra`` (the
    kind of fit's own terms, e.g. the airframe's in a flight fit), given once.

    Raises
    ------
    ValueError
        Not a sequence of str, empty, a name given twice, a name the model does not
        have (a paper-model name with a cambered base, ``alpha0``, included), or ``M``
        fitted while ``options.M`` fixes it.
    """
    if isinstance(names, str) or not isinstance(names, (tuple, list)) or not all(isinstance(n, str) for n in names):
        raise ValueError(f"names must be a tuple of parameter names (str), got {names!r:.60}")
    if not names:
        raise ValueError("names is empty: give the parameters to fit, or None for the default")
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise ValueError(f"cannot fit {', '.join(twice)} twice: give each parameter once")
    if isinstance(base, CamberedParams):
        valid = (*CAMBERED_BOUNDS, *(k for k in (options.bounds or {}) if hasattr(base, k) and k not in CAMBERED_BOUNDS))
        model = "the cambered model"
    else:  # all four under either lift model (with sin-cos lift the report says cl1 and alpha0 do not enter)
        valid, model = tuple(BOUNDS), "the paper's model"
    valid = (*valid, *ROTOR_BOUNDS, *extra)
    unknown = [n for n in names if n not in valid]
    if unknown:
        hint = " (body-lift terms: body_lift=True, --body-lift)" if any(n in BODY_BOUNDS for n in unknown) else ""
        raise ValueError(f"cannot fit {', '.join(unknown)[:120]} with {model}: its parameters are "
                         f"{', '.join(valid)}{hint}")
    if options.M is not None and "M" in names:
        raise ValueError(f"M is fixed at {options.M:g} by the fit's options (--M) and cannot also be fitted: "
                         "drop one")
    return tuple(names)


def _is_angle(name: str) -> bool:
    return name in ANGLES


@dataclass(frozen=True)
class FitOptions:
    """Options of a fit.

    Parameters
    ----------
    x0 : tuple
        Paper's model: start (cl1, cl2, cd, alpha0 [rad]); the paper's (2 pi, 2, 0, 0.47)
        by default. For ``lift_model="sincos"`` only cl2 and cd are used. The cambered
        model starts from the base parameters instead.
    bounds : dict, optional
        name -> (low, high); defaults :data:`BOUNDS` / :data:`CAMBERED_BOUNDS`.
    M : float, optional
        Sigmoid sharpness used while fitting (None: that of the base parameters). Paper's
        model, None: when the base M exceeds M_SMOOTH (30), the fit runs at M = 30 first
        (no root-branch jumps, a smooth objective) and then continues at the base M from
        that optimum (continuation in M).
    names : tuple of str, optional
        Parameters to fit. Default: :func:`param_names` for the paper's model; for the
        cambered model :data:`CAMBERED_FIT_RE` when the data are static only or contain
        sweeps at three or more rotation rates, else :data:`CAMBERED_FIT` (Reynolds terms
        kept at the base values), and :data:`CAMBERED_FIT_STATIC` for static data without
        the prior (docs/identification.md gives the measurements behind this rule).
    prior : bool
        Cambered model: add the population prior, pseudo-residuals
        sigma_d L^-1 (x - x_base) with L L^T the covariance of the parameters fitted to
        each catalogue propeller and sigma_d their median rms residual
        (io.calibration.population). The fit then moves a parameter away from the base
        only as far as the data warrant (a maximum a posteriori estimate; along the data's
        leading directions only, ``directions``); on sparse data (a static run) this
        measured better than a free fit (docs/identification.md).
    population : dict, optional
        The prior's statistics (``names``, ``covariance``, ``sigma_data``, ``source``);
        default the shipped ones (io.calibration.population). Validation passes the
        statistics of the catalogue without the family of the propeller it predicts.
    lift_model : {"sigmoid", "sincos"}
    multistart : int
        Extra starts from a scrambled Sobol sequence inside the bounds (0: x0 only). With
        starts, every start gets a short screening run (SCREEN_NFEV evaluations) and the
        two best are polished to convergence.
    body_lift : bool
        Level flight only: append the body-lift term of Sec. III-A (needs the vehicle's
        ``body_area``). The model without body lift is fitted first and the full fit
        starts from its optimum with zero body lift, so the residual can only shrink.
    max_nfev : int
        Residual evaluations allowed per start.
    seed : int
    progress : bool
        Show a tqdm progress bar (on a terminal).
    discretization : Discretization
    directions : int, optional
        :func:`fit_loads` only. Cambered model under the prior, ``names`` not given, data
        other than a collective sweep: fit only this many of the
        parameter directions the data determine best against the prior
        (identify/directions.py), the others held at the base values; 0: every name under
        the prior. None (default): 3 (STATIC_DIRECTIONS) for a static run, those the data
        know DATA_OVER_PRIOR (10) times better than the prior for sweeps at one rotation
        rate, 0 for sweeps at two or more (the measurements: docs/identification.md).
    jacobian : {"implicit", "differences"}
        The residual Jacobian: ``"implicit"`` (default) the model's implicit derivatives
        (``rotor_loads``, ``rotor_wrench`` and ``vehicle_wrench`` with ``derivatives``;
        docs/solver.md) where it can give them for every section name (uniform inflow, rigid
        blades, no node-changing name such as re_ref), the terms outside the rotor model
        (the centre of mass, the body-lift closed form) by central differences; else, and
        always with ``"differences"``, central differences of the solver.
    """

    x0: tuple = X0_PAPER
    bounds: dict | None = None
    M: float | None = None
    names: tuple | None = None
    prior: bool = True
    population: dict | None = None
    lift_model: str = "sigmoid"
    multistart: int = 0
    body_lift: bool = False
    max_nfev: int = 200
    seed: int = 0
    progress: bool = False
    discretization: Discretization = DEFAULT_DISCRETIZATION
    jacobian: str = "implicit"
    directions: int | None = None

    def __post_init__(self) -> None:
        if self.jacobian not in ("implicit", "differences"):
            raise ValueError(f"jacobian must be 'implicit' or 'differences', got {self.jacobian!r:.40}")
        d = self.directions
        if d is not None and (isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 0):
            raise ValueError(f"directions must be None or an integer >= 0, got {d!r:.40}")


@dataclass(frozen=True)
class Identifiability:
    """Local identifiability at the optimum, from the residual Jacobian J.

    J is the residual Jacobian at the optimum (the model's implicit derivatives where it
    gives them, else central differences of the solver: FitOptions.jacobian). Covariance
    s^2 (J^T J)^-1 (from the
    SVD of J, no cut-off) with s^2 = |r|^2 / (N - p); 95% intervals use Student's t with
    N - p degrees of freedom. A parameter is "poorly determined" when its std error
    exceeds POOR_REL_STD (10%) of max(|estimate|, its natural scale) (the scale matters
    for cambered parameters whose value may be near zero: CAMBERED_SCALE), i.e. its 95%
    interval is wider than about +-20%; "not determined" when the std error is not finite.
    ``singular_values`` are those of J diag(max(|x|, 0.1)), i.e. of the Jacobian with
    respect to relative parameter changes.

    With the population prior, ``std_error``, ``ci95`` and ``correlation`` are the
    posterior's, covariance (J_d^T J_d / s^2 + Sigma^-1)^-1 with Sigma the population
    covariance (what data and prior together determine; a direction the data leave free
    keeps the population's spread), and ``std_error_data`` holds the data's alone beside them (None without a
    prior, and in a fit along directions, FitResult.extra["directions"]); ``poorly_determined``
    is still judged on the data alone. ``effective_parameters``
    is how many parameter directions the data determine against the prior, the trace of the
    posterior hat matrix, tr[J_d^T J_d (J_d^T J_d + J_p^T J_p)^-1] (J_d the data's rows, J_p
    the prior's): p without a prior, fewer as the prior holds directions the data leave free
    (the effective degrees of freedom of a ridge fit: Hastie, Tibshirani & Friedman, The
    Elements of Statistical Learning, 2nd ed. 2009, eq 3.50).
    """

    names: tuple[str, ...]
    std_error: np.ndarray
    ci95: np.ndarray
    correlation: np.ndarray
    singular_values: np.ndarray
    poorly_determined: tuple[str, ...]
    warnings: tuple[str, ...]
    std_error_data: np.ndarray | None = None
    effective_parameters: float | None = None

    def to_dict(self) -> dict:
        """JSON-ready form (angles in rad; a non-finite std error is null)."""
        def num(v):
            return float(v) if np.isfinite(v) else None

        return {
            "std_error": {n: num(v) for n, v in zip(self.names, self.std_error)},
            "std_error_data_only": (None if self.std_error_data is None
                                    else {n: num(v) for n, v in zip(self.names, self.std_error_data)}),
            "ci95": {n: [num(a), num(b)] for n, (a, b) in zip(self.names, self.ci95)},
            "effective_parameters": (None if self.effective_parameters is None
                                     else float(self.effective_parameters)),
            "correlation": [[float(c) for c in row] for row in self.correlation],
            "singular_values": [float(s) for s in self.singular_values],
            "poorly_determined": list(self.poorly_determined),
            "warnings": list(self.warnings),
        }


@dataclass(frozen=True)
class FitResult:
    """Result of :func:`fit_level_flight`, :func:`fit_loads` or :func:`fit_loads_joint`.

    Attributes
    ----------
    params : AirfoilParams or CamberedParams
        The fitted parameters (with the M and lift model used in the fit).
    air : Air
    names : tuple of str
        Fitted parameter names (angles in rad); body-lift names appended if used.
    x : ndarray
        Fitted values, in ``names`` order.
    residuals : ndarray
        Residual per condition at the optimum (level flight: N; loads: dimensionless).
    cost : float
        0.5 |residuals|^2.
    nfev : int
        Residual evaluations over all starts (each one batched model call).
    n_model_points : int
        Rotor operating points evaluated over the whole fit.
    elapsed_s : float
    success : bool
    message : str
    starts : list of dict
        Every start: x0, final x, cost, nfev.
    identifiability : Identifiability
    at_bound : tuple of str
        Fitted parameters that ended on (within 1e-6 of the range of) a bound: the data
        pull them outside the bounds, and their value is the bound's, not the data's.
    hit_max_nfev : bool
        The best start stopped at its evaluation limit, not at convergence.
    warnings : tuple of str
        Everything the report must say about the fit itself (bounds, evaluation limit,
        multistart optima that disagree), beside the identifiability warnings.
    extra : dict
        Problem-specific information (body-lift verdict, held-out errors, ...).
    """

    params: SectionParams
    air: Air
    names: tuple[str, ...]
    x: np.ndarray
    residuals: np.ndarray
    cost: float
    nfev: int
    n_model_points: int
    elapsed_s: float
    success: bool
    message: str
    starts: list
    identifiability: Identifiability
    at_bound: tuple = ()
    hit_max_nfev: bool = False
    warnings: tuple = ()
    extra: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        """The JSON report (angles in degrees, as labelled in ``units``)."""
        from ..io.params_file import params_to_dict

        return {
            "params": params_to_dict(self.params, self.air),
            "fitted": {n: (math.degrees(v) if _is_angle(n) else float(v)) for n, v in zip(self.names, self.x)},
            "units": {n: "deg" for n in self.names if _is_angle(n)},
            "cost": self.cost, "rms_residual": float(np.sqrt(np.mean(self.residuals**2))),
            "residuals": [float(r) for r in self.residuals],
            "nfev": self.nfev, "n_model_points": self.n_model_points, "elapsed_s": self.elapsed_s,
            "success": self.success, "message": self.message,
            "at_bound": list(self.at_bound), "hit_max_nfev": self.hit_max_nfev, "warnings": list(self.warnings),
            "starts": [{k: ([float(a) for a in v] if isinstance(v, np.ndarray) else v) for k, v in s.items()}
                       for s in self.starts],
            "identifiability": self.identifiability.to_dict(),
            **self.extra,
        }

    def report_text(self, *, max_residuals: int = 20) -> str:
        """Plain-text report: estimates, 95% intervals, correlations, warnings.

        At most ``max_residuals`` residuals are listed (the largest in magnitude), with
        their count; the JSON report has them all.
        """
        idf = self.identifiability
        data_only = idf.std_error_data is not None
        lines = [f"{'parameter':<19}{'estimate':>10}{'std err':>10}{'95% interval':>24}"
                 + (f"{'data only':>12}" if data_only else "")]
        for k, n in enumerate(self.names):
            deg = _is_angle(n)
            f = math.degrees if deg else float
            lo, hi = idf.ci95[k]
            flag = " (at bound)" if n in self.at_bound else ""
            extra = f"{f(idf.std_error_data[k]):>12.3g}" if data_only else ""
            lines.append(f"{n + (' [deg]' if deg else ''):<19}{f(self.x[k]):>10.4g}{f(idf.std_error[k]):>10.3g}"
                         f"{'[' + format(f(lo), '.4g') + ', ' + format(f(hi), '.4g') + ']':>24}{extra}{flag}")
        dirs = self.extra.get("directions")
        if dirs:
            lines.append(f"std err and interval: the posterior, the data's along the {dirs['count']} free directions "
                         "and the population's spread along the held ones (the data determine the directions, not a "
                         "parameter alone: their own figures are the directions', below)")
        elif data_only:
            lines.append("std err and interval: data and population prior together (the posterior); 'data only': "
                         "the data's alone")
        if dirs:
            lines.append(f"free: {dirs['count']} directions of the {len(self.names)} parameters, those the data "
                         "determine best against the population prior\n  (the others held at the base set); "
                         "coefficient +- std error (data only) in prior standard deviations,\n  and the parameter "
                         "changes per unit (the four largest against each parameter's population spread):")
            for i, (cf, sd, sdd, load) in enumerate(zip(dirs["coefficients"], dirs["std_error"],
                                                        dirs["std_error_data_only"], dirs["loadings"])):
                big = sorted(range(len(load)), key=lambda j: -abs(load[j]) / dirs["prior_std"][j])[:4]
                unit = dirs["units"]
                terms = ", ".join(f"{self.names[j]} {load[j]:+.3g}{' deg' if self.names[j] in unit else ''}"
                                  for j in big)
                lines.append(f"  direction_{i + 1} {cf:+.3f} +- {sd:.3f} ({sdd:.3f}): {terms}")
            lines.append(f"the data determine {idf.effective_parameters:.1f} of the {dirs['count']} free directions "
                         f"(effective number; the other {len(self.names) - dirs['count']} held at the base set)")
        elif idf.effective_parameters is not None:
            lines.append(f"the data determine {idf.effective_parameters:.1f} of the {len(self.names)} parameters' "
                         "directions (effective number; the prior holds the others near the base set)")
        if len(self.names) > 1:
            lines.append("correlation: " + "; ".join(
                f"{self.names[i]}-{self.names[j]} {idf.correlation[i, j]:+.2f}"
                for i in range(len(self.names)) for j in range(i + 1, len(self.names))))
        label = "the free directions' Jacobian" if dirs else "scaled Jacobian"
        lines.append(f"{label} singular values: " + ", ".join(f"{s:.3g}" for s in idf.singular_values))
        level = self.extra.get("kind") in ("level_flight", "flight")
        unit = " [N]" if level else " [-] (coefficient error / RMS of the measured coefficient)"
        r = self.residuals
        order = np.argsort(-np.abs(r))[:max_residuals]
        shown = "" if r.size <= max_residuals else f" (the {max_residuals} largest of {r.size}; all in the JSON report)"
        lines.append(f"residuals{unit}{shown}: " + ", ".join(f"#{i} {r[i]:+.3g}" for i in order))
        u = " N" if level else " [-]"
        lines.append(f"rms residual {np.sqrt(np.mean(r ** 2)):.4g}{u}; {self.nfev} evaluations "
                     f"({self.n_model_points} rotor points) in {self.elapsed_s:.2f} s; {len(self.starts)} start(s)")
        eff = self.extra.get("M_effect")
        if eff:
            lines.append(f"stall-blend smoothing: fitted with M = {eff['M_fit']:g}; the same parameters give rms "
                         f"residual {eff['rms_residual_at_M_fit']:.4g} at M = {eff['M_fit']:g} and "
                         f"{eff['rms_residual_at_M_base']:.4g} at M = {eff['M_base']:g} (the base value)")
        cont = self.extra.get("M_continuation")
        if cont:
            lines.append(f"continuation in M: fitted at M = {cont['M_first']:g} (rms residual "
                         f"{cont['rms_residual_first']:.4g}{u}), then at M = {cont['M_final']:g} from there")
        lines.extend(f"WARNING: {w}" for w in self.warnings)
        lines.extend(f"WARNING: {w}" for w in idf.warnings)
        return "\n".join(lines)


def _scale_of(name: str) -> float:
    return CAMBERED_SCALE.get(name, 0.0)


def _identifiability(names, x, jac, residuals, dof_rows: int | None = None) -> Identifiability:
    """Identifiability from ``jac`` (rows: residuals, prior rows included for the posterior);
    the residual variance from ``residuals`` with ``dof_rows`` (default: jac's rows) - p
    degrees of freedom."""
    N, p = jac.shape
    dof = max((N if dof_rows is None else dof_rows) - p, 1)
    s2 = float(residuals @ residuals) / dof
    # covariance from the SVD of J with no cut-off: a weak direction gets a large
    # variance (a pseudo-inverse with a cut-off would report it as perfectly known)
    _, sig, Vt = np.linalg.svd(jac, full_matrices=False)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv_sig2 = np.where(sig > 0, 1.0 / sig**2, np.inf)
        cov = s2 * (Vt.T * inv_sig2) @ Vt
        std = np.sqrt(np.clip(np.diag(cov), 0, None))
        if sig.size < p:  # fewer residuals than parameters: the missing directions are free
            std = np.full(p, np.inf)
        std = np.where(np.isnan(std), np.inf, std)
        from scipy import stats

        t = stats.t.ppf(0.975, dof)
        ci = np.column_stack([x - t * std, x + t * std])
        corr = cov / np.outer(std, std)
    corr = np.where(np.isfinite(corr), corr, 0.0)
    np.fill_diagonal(corr, 1.0)
    scale = np.maximum(np.abs(x), 0.1)
    sv = np.linalg.svd(jac * scale, compute_uv=False)
    poor, warns = [], []
    for k, n in enumerate(names):
        if not np.isfinite(std[k]):
            poor.append(n)
            warns.append(f"{n} is not determined by the data: its std error is not finite (no residual "
                         "changes with it at the optimum)")
            continue
        rel = std[k] / max(abs(x[k]), _scale_of(n), 1e-12)
        if rel > POOR_REL_STD:
            poor.append(n)
            shown = f"{math.degrees(std[k]):.3g} deg" if _is_angle(n) else f"{std[k]:.3g}"
            warns.append(f"{n} is poorly determined: std error {shown} is {100 * rel:.0f}% of its "
                         f"{'estimate' if abs(x[k]) >= _scale_of(n) else 'natural scale'}")
    for i in range(p):
        for j in range(i + 1, p):
            if abs(corr[i, j]) > 0.95:
                warns.append(f"{names[i]} and {names[j]} are strongly correlated ({corr[i, j]:+.2f}): "
                             "the data constrain mainly a combination of them")
    if sv.size and sv[-1] < 1e-6 * sv[0]:
        warns.append("the Jacobian is nearly singular: some direction in parameter space is not identifiable")
    return Identifiability(tuple(names), std, ci, corr, sv, tuple(poor), tuple(warns))


def _effective_parameters(jac_data, jac_all) -> float:
    """tr[J_d^T J_d (J^T J)^+] with J = jac_all (data and prior rows): the directions the data
    determine against the prior (Identifiability)."""
    A = jac_data.T @ jac_data
    return float(np.trace(A @ np.linalg.pinv(jac_all.T @ jac_all)))


def _bounds(names, options: FitOptions):
    table = {**BOUNDS, **CAMBERED_BOUNDS, **BODY_BOUNDS, **ROTOR_BOUNDS, **AIRFRAME_BOUNDS, **(options.bounds or {})}
    unknown = [n for n in names if n not in table]
    if unknown:
        raise ValueError(f"cannot fit {', '.join(unknown)}: valid names are {', '.join(table)}")
    lb = np.array([table[n][0] for n in names], float)
    ub = np.array([table[n][1] for n in names], float)
    return lb, ub


def _x0(names, options: FitOptions, base: SectionParams):
    """Start vector: the paper's x0 for its model, the base parameters for the cambered one."""
    if isinstance(base, CamberedParams):
        full = {n: getattr(base, n) for n in names if hasattr(base, n)}
    else:
        full = dict(zip(("cl1", "cl2", "cd", "alpha0"), options.x0))
    full.update(zip(("cl1_body", "cl2_body", "alpha0_body"), BODY_X0))
    return np.array([full[n] for n in names], float)


def _m_effect(make_data_residual, best, base: SectionParams, options: FitOptions) -> dict:
    """When the fit used a smoother M than the base parameters, report what that did: the
    rms data residual of the fitted parameters under the fit's M and under the base M."""
    if options.M is None or options.M == base.M:
        return {"M_used": base.M if options.M is None else options.M}
    r_fit = make_data_residual(options)(best.x)
    r_base = make_data_residual(replace(options, M=base.M))(best.x)
    return {"M_used": options.M, "M_effect": {
        "M_fit": options.M, "M_base": base.M,
        "rms_residual_at_M_fit": float(np.sqrt(np.mean(r_fit**2))),
        "rms_residual_at_M_base": float(np.sqrt(np.mean(r_base**2)))}}


def _jacobian(residual, x, lb, ub):
    """Central-difference Jacobian at x (one-sided at a bound), step 1e-4 max(|x_k|, 0.1).

    The floor 0.1 matters: a purely relative step (SciPy's ``diff_step``) is 1e-14 at
    the paper's start c_d = 0, far below the root solve's tolerance, and gives a
    derivative that is pure round-off.
    """
    cols = []
    for k in range(x.size):
        h = 1e-4 * max(abs(x[k]), 0.1)
        hi, lo = x.copy(), x.copy()
        hi[k] = min(x[k] + h, ub[k])
        lo[k] = max(x[k] - h, lb[k])
        cols.append((residual(hi) - residual(lo)) / (hi[k] - lo[k]))
    return np.column_stack(cols)


def _params_from(x, names, base: SectionParams, options: FitOptions) -> SectionParams:
    """The section record with the fitted values of its own fields (other names, such as the
    body-lift or airframe terms, are the caller's)."""
    own = {f.name for f in fields(base)}
    kw = {n: float(v) for n, v in zip(names, x) if n in own}
    if isinstance(base, AirfoilParams):
        kw["lift_model"] = options.lift_model
    if options.M is not None:
        kw["M"] = float(options.M)
    return base.replace(**kw)


def _attach_jacobian(residual, with_jacobian, eager: bool = True):
    """Give a residual function its implicit Jacobian: ``residual.jacobian(x)``, and with
    ``eager`` ``residual.with_jacobian(x)``, (residual, Jacobian) from one model call, which
    the fitting engine then evaluates at every point (least squares asks for the Jacobian
    where it evaluated last). Not eager where the Jacobian costs more than its derivatives
    (columns differenced by extra solves): the engine then asks for it only when needed."""
    residual.jacobian = lambda x: with_jacobian(x)[1]
    if eager:
        residual.with_jacobian = with_jacobian


def _solve(residual, names, options: FitOptions, label: str, x0):
    """Bounded least squares from x0 and ``options.multistart`` Sobol starts; best cost wins.

    Returns (best, log, nfev, elapsed, warnings): ``warnings`` names multistart optima
    that reach the same cost with different parameters.
    """
    from tqdm import tqdm

    lb, ub = _bounds(names, options)
    x0 = np.clip(np.asarray(x0, float), lb, ub)
    starts = [x0]
    if options.multistart > 0:
        m = max(0, math.ceil(math.log2(options.multistart)))  # Sobol' points come in powers of 2
        from scipy.stats import qmc

        sob = qmc.Sobol(len(names), scramble=True, seed=options.seed).random_base2(m)[: options.multistart]
        starts += list(lb + sob * (ub - lb))
    counter = {"n": 0}
    bar = tqdm(desc=label, unit="eval", disable=None if options.progress else True, leave=False)  # None: off unless a terminal

    both = getattr(residual, "with_jacobian", None)
    last = {}  # the Jacobian of the last residual evaluated, and where

    def fun(x):
        counter["n"] += 1
        bar.update(1)
        if both is None:
            return residual(x)
        # the implicit derivatives come with the residual from one model call: least_squares asks
        # for the Jacobian where it last evaluated the residual (after an accepted step), so most
        # calls need it, and the derivatives cost less than a second call (benchmarks/README.md)
        r, J = both(np.array(x, float))
        last["x"], last["J"] = np.array(x, float), J
        return r

    analytic = getattr(residual, "jacobian", None)

    def jac(x):
        x = np.array(x, float)
        if both is not None and "x" in last and np.array_equal(last["x"], x):
            return last["J"]
        if analytic is not None:  # the implicit derivatives (one solve with derivatives)
            counter["n"] += 1
            bar.update(1)
            return analytic(x)
        return _jacobian(fun, x, lb, ub)

    def run(x_start, max_nfev):
        from scipy import optimize

        r = optimize.least_squares(fun, x_start, jac=jac, bounds=(lb, ub), method="trf", x_scale="jac",
                                   max_nfev=max_nfev, xtol=1e-10, ftol=1e-10, gtol=1e-10)
        log.append({"x0": np.array(x_start), "x": r.x.copy(), "cost": float(r.cost), "nfev": int(r.nfev),
                    "status": int(r.status), "stage": "polish" if max_nfev == options.max_nfev else "screen"})
        bar.set_postfix(best_cost=f"{min(e['cost'] for e in log):.3g}")
        return r

    log = []
    warns = []
    t0 = time.perf_counter()
    try:
        if len(starts) == 1:
            best = run(starts[0], options.max_nfev)
        else:
            # global stage: short runs from every start, then polish the two best to convergence
            screened = sorted((run(s, SCREEN_NFEV) for s in starts), key=lambda r: r.cost)
            polished = sorted((run(r.x, options.max_nfev) for r in screened[:2]), key=lambda r: r.cost)
            best = polished[0]
            other = polished[1]
            # same cost: within 1%, or both at round-off level (a perfect fit)
            if other.cost <= best.cost * (1 + SAME_COST_RTOL) + 1e-12 * best.fun.size:
                span = np.maximum(np.abs(best.x), [max(_scale_of(n), 1e-12) for n in names])
                differ = [n for n, a, b, sc in zip(names, best.x, other.x, span) if abs(a - b) > DIFFERENT_X_RTOL * sc]
                if differ:
                    warns.append(f"two multistart optima reach the same residual (costs {best.cost:.4g} and "
                                 f"{other.cost:.4g}) with different {', '.join(differ)}: the data do not "
                                 "determine them")
        # best.jac is _jacobian at best.x: least_squares evaluates jac after every
        # accepted step and returns it unchanged for the default linear loss
    finally:
        bar.close()
    return best, log, counter["n"], time.perf_counter() - t0, warns


def _finish(names, base, options, best, log, nfev, elapsed, warns, n_points, air, extra):
    """Assemble the FitResult: identifiability, parameters at a bound, evaluation limit.

    With the population prior, ``residuals``, ``cost`` and the identifiability report are
    the data's alone (the prior's pseudo-residuals and cost go to ``extra["prior"]``), so
    the report says what the data determine; a parameter they leave free is named, and
    said to be held near the base by the prior.
    """
    lb, ub = _bounds(names, options)
    params = _params_from(best.x, names, base, options)
    residuals, jac = best.fun, best.jac
    if "prior" in extra:
        k = len(extra["prior"]["names"])
        residuals, jac = best.fun[:-k], best.jac[:-k]
        extra["prior"]["pseudo_residuals"] = [float(v) for v in best.fun[-k:]]
        extra["prior"]["cost"] = 0.5 * float(best.fun[-k:] @ best.fun[-k:])
    idf = _identifiability(names, best.x, jac, residuals)
    if "prior" in extra:
        # the posterior: the prior rows were weighted by w = sigma_d * scale (the population's
        # residual level) in the fit; rescaled by sqrt(s2) / w they carry the population
        # covariance Sigma against this fit's residual variance s2, so that
        # cov = s2 (J_d^T J_d + s2 Sigma^-1)^-1 = (J_d^T J_d / s2 + Sigma^-1)^-1 (a direction
        # the data leave free keeps the prior's spread, whatever the data's noise)
        w = extra["prior"]["sigma_data"] * extra["prior"]["scale"]
        s2 = float(residuals @ residuals) / max(residuals.size - len(names), 1)
        prior_rows = best.jac[-k:] * (math.sqrt(s2) / w)
        post = _identifiability(names, best.x, np.vstack([jac, prior_rows]), residuals, dof_rows=residuals.size)
        held = [n for n in idf.poorly_determined if n in extra["prior"]["names"]]
        # one line for what the prior holds; the data's own word on parameters it does not
        # cover; the posterior's correlations (its std errors are in the report)
        determined = ("poorly determined", "not determined")
        own = tuple(w for w in idf.warnings if any(d in w for d in determined)
                    and w.split(" ", 1)[0] not in extra["prior"]["names"])
        idf_warns = own + tuple(w for w in post.warnings if not any(d in w for d in determined)) + (
            (f"the data alone leave {', '.join(held)} (nearly) free: the population prior holds them near the "
             "base set's values (data-only std errors in the report)",) if held else ())
        idf = replace(post, poorly_determined=idf.poorly_determined, warnings=idf_warns, std_error_data=idf.std_error,
                      effective_parameters=_effective_parameters(jac, best.jac))
    tol = 1e-6 * (ub - lb)
    at_bound = tuple(n for n, v, lo, hi, t in zip(names, best.x, lb, ub, tol) if v <= lo + t or v >= hi - t)
    warns = list(warns)
    for n, v, lo, hi in zip(names, best.x, lb, ub):
        if n in at_bound:
            side, b = ("lower", lo) if abs(v - lo) <= abs(v - hi) else ("upper", hi)
            shown = f"{math.degrees(b):.4g} deg" if _is_angle(n) else f"{b:.4g}"
            warns.append(f"{n} ended at its {side} bound {shown}: the data pull it beyond the allowed range, so "
                         "its value is the bound's; suspect the data, the geometry or the model")
    hit = int(best.status) == 0
    if hit:
        limit = getattr(best, "nfev_limit", options.max_nfev)
        warns.append(f"the fit stopped at its evaluation limit ({limit}) before converging")
    cost = 0.5 * float(residuals @ residuals)
    return FitResult(params, air, names, best.x, residuals, cost, nfev, n_points, elapsed,
                     bool(best.success), str(best.message), log, idf, at_bound, hit, tuple(warns), extra)


# ---------------------------------------------------------------- level flight (eqs 16-18)

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
        name, a linear inflow, flapping, Omega below 0.1 rad/s).
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
    beta = np.arccos(np.clip(np.einsum("nkj,kj->nk", vel, np.stack([r.axis for r in vehicle.rotors]))
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


def _polish_at_base_M(make_residual, names, options, base_M, x_smooth, label):
    """Stages 2 and 3 of the continuation in M, at the base M (docs/identification.md).

    2. Trust-region least squares on the EXACT residual at the base M, with the Jacobian
       of the smooth M_SMOOTH model: at M = 50 the stall folds make the residual jump by
       small amounts as parameters move (root-branch switches), so finite differences at
       M = 50 are dominated by the jumps, while the smooth Jacobian still points downhill.
    3. Nelder-Mead on the exact cost from there: it needs no derivatives, so the jumps do
       not stall it where the smooth Jacobian stops being a good model (measured: the
       paper's case generated at M = 50 is then recovered to 2e-13).

    Returns an OptimizeResult-like object (x, fun, jac, cost, status, success, message,
    nfev) whose ``jac`` is the smooth model's Jacobian at the optimum (used for the
    identifiability report) and the number of residual evaluations spent.
    """
    lb, ub = _bounds(names, options)
    exact = make_residual(replace(options, M=base_M))
    smooth = make_residual(replace(options, M=M_SMOOTH))
    count = {"n": 0}

    def f(x):
        count["n"] += 1
        return exact(x)

    analytic = getattr(smooth, "jacobian", None)

    def jac(x):
        if analytic is not None:
            count["n"] += 1
            return analytic(np.array(x, float))
        count["n"] += 2 * len(x)
        return _jacobian(smooth, np.array(x, float), lb, ub)

    from scipy import optimize  # imported where used: `propmap wrench` and `loads` start without it

    r2 = optimize.least_squares(f, x_smooth, jac=jac, bounds=(lb, ub), method="trf", x_scale="jac",
                                max_nfev=options.max_nfev, xtol=1e-12, ftol=1e-12, gtol=1e-12)
    scale = np.maximum(np.abs(r2.x), 0.1)
    z0 = r2.x / scale
    simplex = np.vstack([z0, z0 + 0.02 * np.eye(z0.size)])
    simplex = np.clip(simplex, lb / scale, ub / scale)
    max_fev = 200 * len(names)
    nm = optimize.minimize(lambda z: 0.5 * float(np.sum(f(z * scale) ** 2)), z0, method="Nelder-Mead",
                           bounds=list(zip(lb / scale, ub / scale)),
                           options={"xatol": 1e-12, "fatol": 1e-30, "maxfev": max_fev, "adaptive": True,
                                    "initial_simplex": simplex})
    x = np.clip(nm.x * scale, lb, ub) if nm.fun <= r2.cost else r2.x
    fun = exact(x)
    J = analytic(x) if analytic is not None else _jacobian(smooth, x, lb, ub)
    stopped = nm.nfev >= max_fev and nm.fun < r2.cost
    if stopped:
        # with noisy data Nelder-Mead's 1e-12 tolerance is not reached in max_fev evaluations;
        # it has converged for every purpose when its simplex is within NM_STAT_TOL of the
        # parameters' standard errors (the data's scatter, not the optimiser, sets the error)
        spread = np.ptp(nm.final_simplex[0], axis=0) * scale
        s2 = float(fun @ fun) / max(fun.size - len(names), 1)
        with np.errstate(divide="ignore", invalid="ignore"):
            std = np.sqrt(np.clip(np.diag(s2 * np.linalg.pinv(J.T @ J)), 0, None))
        stopped = not np.all(spread <= NM_STAT_TOL * std)
    result = optimize.OptimizeResult(
        x=x, fun=fun, jac=J, cost=0.5 * float(fun @ fun), nfev_limit=max_fev,
        status=0 if stopped else 2, success=not stopped, nfev=r2.nfev + nm.nfev,
        message=("Nelder-Mead stopped at its evaluation limit" if stopped else
                 f"converged: least squares with the M = {M_SMOOTH:g} Jacobian, then Nelder-Mead at M = {base_M:g}"))
    return result, count["n"] + len(names) * 2 + 1


def _fit_with_continuation(make_residual, names, base, options, label, x0):
    """Solve; for the paper's model with a base M above M_SMOOTH and no M given, continue in M.

    Stage 1 fits at M_SMOOTH (no root folds: a smooth objective), then
    :func:`_polish_at_base_M` fits at the base M from that optimum.

    Returns (best, log, nfev, elapsed, warnings, extra).
    """
    if isinstance(base, AirfoilParams) and options.M is None and base.M > M_SMOOTH and options.lift_model == "sigmoid":
        smooth = replace(options, M=M_SMOOTH)
        b1, log, n1, t1, w1 = _solve(make_residual(smooth), names, smooth, label, x0)
        t0 = time.perf_counter()
        best, n2 = _polish_at_base_M(make_residual, names, options, base.M, b1.x, label)
        elapsed = t1 + time.perf_counter() - t0
        log.append({"x0": b1.x.copy(), "x": best.x.copy(), "cost": best.cost, "nfev": n2, "status": best.status,
                    "stage": f"continuation to M = {base.M:g}"})
        extra = {"M_continuation": {"M_first": M_SMOOTH, "M_final": base.M,
                                    "rms_residual_first": float(np.sqrt(np.mean(b1.fun ** 2))),
                                    "x_first": [float(v) for v in b1.x],
                                    "jacobian": f"identifiability from the M = {M_SMOOTH:g} model's Jacobian"}}
        return best, log, n1 + n2, elapsed, w1, extra
    best, log, nfev, elapsed, warns = _solve(make_residual(options), names, options, label, x0)
    return best, log, nfev, elapsed, warns, {}


def fit_level_flight(data: LevelFlightData, vehicle: Vehicle, *, base: SectionParams | None = None,
                     air: Air | None = None, options: FitOptions = FitOptions()) -> FitResult:
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
        Fewer conditions than parameters + 1, an unknown parameter name, or body lift
        requested without body_area.
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
    x0 = _x0(names, options, base)
    without = None
    if options.body_lift:
        # the model without body lift first; the full fit starts from its optimum with
        # zero body lift (BODY_X0), so that it can only improve on it (nested models)
        without = fit_level_flight(data, vehicle, base=base, air=air,
                                   options=replace(options, body_lift=False, progress=False, names=names[:-3]))
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
        dof1 = data.n - len(names)
        F = ((rss0 - rss1) / 3) / (rss1 / dof1) if rss1 > 0 and dof1 > 0 else math.inf
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


# ---------------------------------------------------------------- loads

def _load_norms(data: LoadData, propeller, keys, air: Air):
    n = data.omega / (2 * math.pi)
    norm = {k: air.rho * n**2 * propeller.diameter ** (5 if k == "torque" else 4) for k in keys}
    scales = {k: float(np.sqrt(np.mean((data.measured[k] / norm[k]) ** 2))) for k in keys}
    for k, s in scales.items():
        if not (np.isfinite(s) and s > 0):
            raise ValueError(f"measured {k} is zero everywhere or not finite; cannot scale its residuals")
    return norm, scales


def _load_keys(data: LoadData, quantities) -> list:
    keys = list(quantities or data.measured)
    for k in keys:
        if k not in data.measured:
            raise ValueError(f"quantity {k!r} is not measured; measured: {', '.join(data.measured)}")
    return keys


def _data_kind(data: LoadData) -> str:
    """"static" (all airspeeds 0), "collective" (all airspeeds 0, several collectives),
    "few_rates" (moving points at < MIN_RATES_FOR_RE rotation rates, within 3%, and no
    static run spanning STATIC_RPM_SPAN) or "rates"."""
    moving = data.airspeed > 0
    if not moving.any():
        swept = data.collective is not None and np.ptp(data.collective) > 0
        return "collective" if swept else "static"
    rates = _sweep_rates(data)
    static = data.omega[~moving]
    spans = static.size > 1 and float(static.max() / static.min()) >= STATIC_RPM_SPAN
    return "rates" if rates >= MIN_RATES_FOR_RE or spans else "few_rates"


def _prior_stats(names, base, options):
    """(sel, mu, L, population) of the population prior on ``names`` (the indices it covers,
    the base values there, the Cholesky factor of its covariance, the statistics), or None
    without a prior (the paper's model, ``options.prior`` off, no name covered)."""
    if not (options.prior and isinstance(base, CamberedParams)):
        return None
    from ..io.calibration import population

    pop = options.population or population()
    sel = [k for k, n in enumerate(names) if n in pop["names"]]
    if not sel:
        return None
    idx = [pop["names"].index(names[k]) for k in sel]
    cov = np.asarray(pop["covariance"], float)[np.ix_(idx, idx)]
    return sel, np.array([getattr(base, names[k]) for k in sel]), np.linalg.cholesky(cov), pop


def _with_prior(make_residual, names, base, options, scale: float = 1.0):
    """Wrap ``make_residual`` with the population prior's pseudo-residuals (cambered model).

    ``scale`` converts the prior's dimensionless weight sigma_d (the median rms residual of
    fit_loads' normalised residuals) into the residuals' unit: 1 for loads, the weight [N]
    for level flight (whose residuals are forces).
    """
    stats = _prior_stats(names, base, options)
    if stats is None:
        return make_residual, None
    sel, mu, chol, pop = stats
    Linv = np.linalg.inv(chol)
    weight = float(pop["sigma_data"]) * scale

    E = np.zeros((len(sel), len(names)))
    E[np.arange(len(sel)), sel] = 1.0
    prior_jac = weight * (Linv @ E)  # the prior rows are linear in x

    def make(opts):
        data = make_residual(opts)

        def residual(x, opts=opts):
            prior_rows = weight * (Linv @ (np.asarray(x)[sel] - mu))
            return np.concatenate([data(x, opts), prior_rows])

        if hasattr(data, "with_jacobian"):
            def with_jacobian(x):
                r, J = data.with_jacobian(x)
                return np.concatenate([r, weight * (Linv @ (np.asarray(x)[sel] - mu))]), np.vstack([J, prior_jac])

            _attach_jacobian(residual, with_jacobian)
        elif hasattr(data, "jacobian"):
            residual.jacobian = lambda x: np.vstack([data.jacobian(x), prior_jac])
        return residual

    info = {"names": [names[k] for k in sel], "mean": [float(m) for m in mu], "sigma_data": float(pop["sigma_data"]),
            "scale": scale, "source": pop["source"]}
    return make, info


def _sweep_rates(data: LoadData) -> int:
    """Distinct rotation rates (3% apart) of the moving points (0 for static data)."""
    rpm = np.sort(data.omega[data.airspeed > 0])
    return 0 if rpm.size == 0 else 1 + int(np.sum(np.diff(rpm) > 0.03 * rpm[1:]))


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


def _fit_along_directions(make_data, names, base, options, k):
    """Fit the ``k`` directions the data determine best against the population prior
    (identify/directions.py; None: those whose eigenvalue is at least DATA_OVER_PRIOR, at
    least one): x = mu + B c, c in prior standard deviations, the residual the data's and the
    prior's (whose rows are w U_k c: the others' deviations stay 0).

    Returns (best, log, nfev, elapsed, warnings, extra) as :func:`_fit_with_continuation`;
    ``best`` in the parameters' space (x, the residual and Jacobian with the prior's rows;
    the directions' optimum clipped to the bounds), ``extra["directions"]`` the directions'
    coefficients and loadings for :func:`_directions_report`, ``extra["outside"]`` the names
    that the optimum put outside their range (the caller then fits every name instead).
    """
    import time

    from scipy import optimize

    from .directions import DATA_OVER_PRIOR, leading_directions

    _, mu, chol, pop = _prior_stats(names, base, options)  # (on every name: _direction_count)
    weight = float(pop["sigma_data"])
    lb, ub = _bounds(names, options)
    data = make_data(options)
    count = {"n": 0}

    def data_jac(x):
        count["n"] += 1
        if hasattr(data, "with_jacobian"):
            return data.with_jacobian(x)
        count["n"] += 2 * len(x)
        return data(x), _jacobian(data, x, lb, ub)

    t0 = time.perf_counter()
    every, lam = leading_directions(data_jac(mu)[1], chol, weight, len(names))
    if k is None:
        k = max(1, int(np.sum(lam >= DATA_OVER_PRIOR)))
    B = every[:, :k]

    def x_of(c):
        return np.clip(mu + B @ c, lb, ub)

    last = {}

    def fun(c):  # the residual with its Jacobian from one model call (least_squares asks for both at each x)
        last["c"], (last["r"], last["J"]) = np.array(c, float), data_jac(x_of(c))
        return np.concatenate([last["r"], weight * c])

    def jac(c):
        J = last["J"] if np.array_equal(last.get("c"), c) else data_jac(x_of(c))[1]
        return np.vstack([J @ B, weight * np.eye(k)])

    sol = optimize.least_squares(fun, np.zeros(k), jac=jac, method="trf", x_scale="jac", max_nfev=options.max_nfev,
                                 xtol=1e-12, ftol=1e-12, gtol=1e-12)
    x = x_of(sol.x)
    r, J = (last["r"], last["J"]) if np.array_equal(last.get("c"), sol.x) else data_jac(x)
    prior_rows = weight * np.linalg.solve(chol, x - mu)  # as _with_prior's, w L^-1 (x - mu)
    best = optimize.OptimizeResult(x=x, fun=np.concatenate([r, prior_rows]),
                                   jac=np.vstack([J, weight * np.linalg.inv(chol)]), status=sol.status,
                                   success=sol.success, message=f"least squares along {k} directions: {sol.message}")
    elapsed = time.perf_counter() - t0
    unclipped = mu + B @ sol.x
    extra = {"outside": [(n, v) for n, v, lo, hi in zip(names, unclipped, lb, ub) if not lo <= v <= hi],
             "directions": {"count": k, "c": sol.x, "loadings": B, "eigenvalues": lam, "base": mu,
                            "jac_c": J @ B, "prior_std": np.sqrt(np.sum(chol**2, axis=1)), "held": every[:, k:]}}
    log = [{"x0": mu, "x": x, "cost": 0.5 * float(r @ r), "nfev": int(sol.nfev)}]
    return best, log, count["n"], elapsed, [], extra


def _directions_report(result: FitResult) -> FitResult:
    """The identifiability of a fit along directions: the k free directions' posterior
    (covariance (J_c^T J_c / s^2 + I)^-1, c in prior standard deviations) and the data's
    alone (s^2 (J_c^T J_c)^-1), in ``extra["directions"]``. The parameters' posterior
    covariance is B cov_c B^T + H H^T, B the free directions' loadings and H the held ones'
    (each a prior standard deviation: the data do not move them, the prior's spread stays);
    they have no data-only figure (the data determine the directions, not a parameter alone:
    ``std_error_data`` None), ``singular_values`` are the free directions' Jacobian's and
    ``poorly_determined`` is empty (a direction the data know less well than the prior is
    named in the warnings). Angles in the JSON loadings and base are in degrees, as
    ``fitted``."""
    d = result.extra["directions"]
    k, B, Jc, c = d["count"], d["loadings"], d["jac_c"], d["c"]
    dnames = tuple(f"direction_{i + 1}" for i in range(k))
    r = result.residuals
    dof = max(r.size - k, 1)
    s2 = float(r @ r) / dof
    own = _identifiability(dnames, c, Jc, r)
    post = _identifiability(dnames, c, np.vstack([Jc, math.sqrt(s2) * np.eye(k)]), r, dof_rows=r.size)

    def to_x(idf, held):
        cov_c = idf.correlation * np.outer(idf.std_error, idf.std_error)
        cov = B @ cov_c @ B.T + held @ held.T
        return cov, np.sqrt(np.clip(np.diag(cov), 0, None))

    cov, std = to_x(post, d["held"])
    from scipy import stats

    t = stats.t.ppf(0.975, dof)
    with np.errstate(divide="ignore", invalid="ignore"):
        corr = np.where(np.outer(std, std) > 0, cov / np.outer(std, std), 0.0)
    np.fill_diagonal(corr, 1.0)
    weight = result.extra["prior"]["sigma_data"] * result.extra["prior"]["scale"]
    eff = float(np.trace(Jc.T @ Jc @ np.linalg.inv(Jc.T @ Jc + weight**2 * np.eye(k))))
    weak = [n for n, sd in zip(dnames, own.std_error) if not sd < 1.0]  # less known from the data than the prior
    warns = tuple(f"{n} is determined less well by the data than by the prior (data-only std error "
                  f"{sd:.3g} prior standard deviations): fewer directions (--directions) would do"
                  for n, sd in zip(dnames, own.std_error) if n in weak)
    idf = Identifiability(result.names, std, np.column_stack([result.x - t * std, result.x + t * std]), corr,
                          own.singular_values, (), warns, std_error_data=None, effective_parameters=eff)
    extra = dict(result.extra)
    deg = np.array([math.degrees(1.0) if _is_angle(n) else 1.0 for n in result.names])  # (as FitResult "fitted")
    extra["directions"] = {
        "count": k, "names": list(result.names), "units": {n: "deg" for n in result.names if _is_angle(n)},
        "coefficients": [float(v) for v in c],
        "std_error": [float(v) for v in post.std_error], "std_error_data_only": [float(v) for v in own.std_error],
        "loadings": [[float(v) for v in B[:, i] * deg] for i in range(k)],
        "eigenvalues": [float(v) for v in d["eigenvalues"]],
        "base": [float(v) for v in d["base"] * deg],
        "prior_std": [float(v) for v in d["prior_std"] * deg],
    }
    return replace(result, identifiability=idf, extra=extra)


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

        if opts.jacobian == "implicit" and differentiable(base, names) and np.all(data.omega >= OMEGA_MIN):
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
        (``FitOptions.directions``; identify/directions.py).

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
                     "default parameters, on load data other than a collective sweep")
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
    warns = [*notes, *warns]
    extra = {"kind": "loads", "n_points": data.n, "quantities": keys, "coefficient_scales": scales, **extra,
             **_m_effect(make_data, best, base, options)}
    if prior:
        extra["prior"] = prior
    result = _finish(names, base, options, best, log, nfev, elapsed, warns, nfev * data.n, air, extra)
    return result if k_dirs == 0 else _directions_report(result)


def fit_loads_joint(datasets, *, base: SectionParams | None = None, air: Air | None = None,
                    options: FitOptions = FitOptions()) -> FitResult:
    """One parameter set fitted to the load measurements of several propellers at once.

    Each propeller's residuals (as :func:`fit_loads`, all measured quantities) are
    weighted by 1/sqrt(its number of points), so that every propeller counts alike
    whatever its number of measurements. This is how the catalogue's ``generic`` set is
    made (tools/calibrate_catalogue.py).

    Parameters
    ----------
    datasets : sequence of (LoadData, Propeller)
    base, air, options
        As :func:`fit_loads`.

    Returns
    -------
    FitResult
        ``residuals`` stacked over the propellers in order; ``extra["per_propeller"]``
        gives each propeller's name, point count and rms (unweighted) residual.

    Raises
    ------
    ValueError
        No datasets, or as :func:`fit_loads`.
    SolverError
        From the rotor model.
    """
    from ..io.calibration import generic_params

    datasets = list(datasets)
    if not datasets:
        raise ValueError("fit_loads_joint needs at least one (data, propeller) pair")
    base = base or generic_params()
    air = base.air if air is None else air
    names = _default_names(base, options)
    makers = []
    for data, prop in datasets:
        makers.append(_load_residual(data, prop, _load_keys(data, None), air, names, base,
                                     weight=1.0 / math.sqrt(data.n))[0])

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
    for data, prop in datasets:
        m = data.n * len(data.measured)
        r = best.fun[k:k + m] * math.sqrt(data.n)
        per.append({"propeller": prop.name, "n_points": data.n, "rms_residual": float(np.sqrt(np.mean(r ** 2)))})
        k += m
    result.extra["per_propeller"] = per
    return result
