"""A fit's result and its identifiability report: standard errors, correlations, what the
data do not determine (docs/identification.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..core.airfoil import Air, SectionParams
from .options import AIRFRAME_BOUNDS, CAMBERED_SCALE, FLAP_START, ROTOR_BOUNDS, _is_angle, report_name, report_value

__all__ = ["FitResult", "Identifiability", "POOR_REL_STD"]


POOR_REL_STD = 0.10  # relative std error above which a parameter is reported poorly determined
#: lag-1 autocorrelation of the residuals above which the report says the std errors understate the uncertainty
#: (an AR(1) series at 0.2 carries 2/3 of its samples' information)
AUTOCORRELATION_SAID = 0.2


@dataclass(frozen=True)
class Identifiability:
    """Local identifiability at the optimum, from the residual Jacobian J.

    J is the residual Jacobian at the optimum (the model's implicit derivatives where it
    gives them, else central differences of the solver: FitOptions.jacobian). Covariance
    s^2 (J^T J)^-1 (from the
    SVD of J, no cut-off) with s^2 = |r|^2 / (N - p); 95% intervals use Student's t with
    N - p degrees of freedom, cut at the parameter's bounds (a fit's report; the flap
    compliance's reaches its upper bound where the profile likelihood says so:
    engine._flap_saturation). A parameter is "poorly determined" when its std error
    exceeds POOR_REL_STD (10%) of max(|estimate|, its natural scale) (the scale matters
    for cambered parameters whose value may be near zero: CAMBERED_SCALE), i.e. its 95%
    interval is wider than about +-20%; "not determined" when the std error is not finite
    (also where the parameter has a share of at least 1e-3 in a direction that J diag(max(|x|,
    0.1)) leaves numerically free: a singular value within p max(N, p) machine epsilons of the
    largest). A parameter that ended at a bound (FitResult.at_bound) is held there: the
    constraint is active, so the linearised covariance does not describe it; its std error and
    interval are NaN (null in JSON, "-" in the text report), the others' are those with it
    fixed, and ``singular_values`` are those of the others' columns.
    ``singular_values`` are those of J diag(max(|x|, 0.1)), i.e. of the Jacobian with
    respect to relative parameter changes.

    With the population prior, ``std_error``, ``ci95`` and ``correlation`` are those of the
    estimate's error over the data's noise and the population's propellers, covariance
    (J^T J)^-1 (s^2 J_d^T J_d + w^2 J_p^T J_p) (J^T J)^-1, J = [J_d; J_p] (J_p the prior's rows,
    weighted by w, the population's residual level sigma_d, times the vehicle's weight for
    level-flight and flight-log fits; the shrinkage's bias included: engine._shrinkage_meat, an
    average over the population, docs/identification.md); where s = w that is the posterior
    (J_d^T J_d / s^2 + Sigma^-1)^-1, Sigma the population covariance, and a direction the data
    leave free keeps the population's spread (in the limit; where s > w a little more).
    ``std_error_data`` holds the data's alone beside them (None without a
    prior, and in a fit along directions, FitResult.extra["directions"]); ``poorly_determined``
    and the strong-correlation warnings (pairs of parameters the data determine) are still judged
    on the data alone, except in a fit along directions (the default for a
    static run or sweeps at one rotation rate), where it is empty: there the data determine
    directions, not parameters, and a direction the data know less well than the prior is
    named in the warnings (each parameter's ``std_error`` then says how well it is
    known). ``effective_parameters``
    is how many parameter directions the data determine against the prior, the trace of the
    posterior hat matrix, tr[J_d^T J_d (J_d^T J_d + J_p^T J_p)^-1] (J_d the data's rows, J_p
    the prior's): p without a prior, fewer as the prior holds directions the data leave free
    (the effective degrees of freedom of a ridge fit: Hastie, Tibshirani & Friedman, The
    Elements of Statistical Learning, 2nd ed. 2009, eq 3.50).

    Attributes
    ----------
    names : tuple of str, length p
        The fitted parameters, in the order of every array below.
    std_error : ndarray, shape (p,)
        Standard errors, in the parameters' SI units (angles in rad); NaN where held at a
        bound or not determined.
    ci95 : ndarray, shape (p, 2)
        95% intervals (low, high), same units.
    correlation : ndarray, shape (p, p)
        Correlation matrix of the estimates.
    singular_values : ndarray
        Of J diag(max(|x|, 0.1)) (the parameters not at a bound), descending.
    poorly_determined : tuple of str
        Parameters whose std error exceeds POOR_REL_STD of their scale, or not finite.
    warnings : tuple of str
        What the report says of the identifiability.
    std_error_data : ndarray, shape (p,), or None
        The data's std errors alone, beside those of data and prior together.
    effective_parameters : float or None
        The trace of the posterior hat matrix (p without a prior).
    ci95_cut : ndarray of bool, shape (p, 2), or None
        Where an interval's end is a parameter's bound, not the linearised end (a fit's
        report marks it ``*``).
    warning_kinds : tuple of (str, tuple of str)
        What each of ``warnings`` is about, in the same order: its kind and the parameters (or
        directions) it names. Kinds: ``"exact"`` (a residual of 0), ``"not_determined"``,
        ``"poorly_determined"``, ``"correlated"`` (a pair), ``"singular"`` (the Jacobian),
        ``"prior_holds"`` (parameters the prior weighs on), ``"weak_direction"`` (a fit along
        directions). Empty where the warnings were given without it.
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
    ci95_cut: np.ndarray | None = None
    warning_kinds: tuple[tuple[str, tuple[str, ...]], ...] = ()

    def to_dict(self) -> dict:
        """JSON-ready form (a non-finite std error is null), keyed and in units as the fit
        report's: an angle's under its name with ``_deg``, in degrees
        (:func:`~propmap.identify.options.report_name`), the others as fitted (SI)."""
        def per_name(values):
            return {report_name(n): report_value(n, v) for n, v in zip(self.names, values)}

        return {
            "std_error": per_name(self.std_error),
            "std_error_data_only": None if self.std_error_data is None else per_name(self.std_error_data),
            "ci95": {report_name(n): [report_value(n, lo), report_value(n, hi)]
                     for n, (lo, hi) in zip(self.names, self.ci95)},
            "ci95_cut_at_bound": (None if self.ci95_cut is None else
                                  {report_name(n): [bool(a), bool(b)] for n, (a, b) in zip(self.names, self.ci95_cut)
                                   if a or b}),
            "effective_parameters": (None if self.effective_parameters is None
                                     else float(self.effective_parameters)),
            "correlation": [[float(c) for c in row] for row in self.correlation],
            "singular_values": [float(s) for s in self.singular_values],
            "poorly_determined": [report_name(n) for n in self.poorly_determined],
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
        """The JSON report: an angle under its name with ``_deg`` (``alpha_L0_deg``, as in a
        parameter file), in degrees, and listed in ``units`` (estimates, std errors, 95% intervals
        and the jackknife's alike); the other parameters as fitted (SI); the residuals in their
        own units. ``starts`` holds each start's vectors as fitted (SI, in the order of
        ``names``)."""
        from ..io.params_file import params_to_dict

        return {
            "params": params_to_dict(self.params, self.air),
            "fitted": {report_name(n): report_value(n, v) for n, v in zip(self.names, self.x)},
            "names": list(self.names),
            "units": {report_name(n): "deg" for n in self.names if _is_angle(n)},
            "cost": self.cost, "rms_residual": float(np.sqrt(np.mean(self.residuals**2))),
            "residuals": [float(r) for r in self.residuals],
            "nfev": self.nfev, "n_model_points": self.n_model_points, "elapsed_s": self.elapsed_s,
            "success": self.success, "message": self.message,
            "at_bound": [report_name(n) for n in self.at_bound], "hit_max_nfev": self.hit_max_nfev,
            "warnings": list(self.warnings),
            "starts": [{k: ([float(a) for a in v] if isinstance(v, np.ndarray) else v) for k, v in s.items()}
                       for s in self.starts],
            "identifiability": self.identifiability.to_dict(),
            **self.extra,
        }

    def report_text(self, *, max_residuals: int = 20) -> str:
        """Plain-text report: estimates, 95% intervals, correlations, warnings.

        Parameters
        ----------
        max_residuals : int, optional
            At most this many residuals are listed (the largest in magnitude), with their
            count, in [0, inf); the JSON report (:meth:`to_dict`) has them all.

        Returns
        -------
        str
            Lines; angles in degrees, marked ``[deg]``, the other parameters as fitted (SI).

        Raises
        ------
        ValueError
            ``max_residuals`` not an integer >= 0 (-1 printed "the -1 largest" and listed all
            but one, True "the True largest": an API audit, stop 100).
        """
        from ..core._numbers import integer

        max_residuals = integer("max_residuals", max_residuals, 0)
        return "\n".join(_parameter_lines(self) + _dependence_lines(self) + _directions_lines(self)
                         + _fit_lines(self, max_residuals))


def _parameter_lines(res: FitResult) -> list[str]:
    """report_text's table of the estimates (std error, 95% interval, the data's own and the
    jackknife's std error where there are) and what the std errors include."""
    idf = res.identifiability
    data_only = idf.std_error_data is not None
    jk = res.extra.get("jackknife")
    dirs = res.extra.get("directions")
    lines = [f"{'parameter':<19}{'estimate':>10}{'std err':>10}{'95% interval':>24}"
             + (f"{'data only':>12}" if data_only else "") + (f"{'jackknife':>12}" if jk else "")]
    for k, n in enumerate(res.names):
        deg = _is_angle(n)
        f = math.degrees if deg else float
        lo, hi = idf.ci95[k]
        flag = " (at bound)" if n in res.at_bound else ""
        held = np.isnan(idf.std_error[k])  # held at its bound: no linearised uncertainty
        extra = (f"{'-' if np.isnan(idf.std_error_data[k]) else format(f(idf.std_error_data[k]), '.3g'):>12}"
                 if data_only else "")
        sd = "-" if held else format(f(idf.std_error[k]), ".3g")
        cut = idf.ci95_cut[k] if idf.ci95_cut is not None else (False, False)
        interval = "-" if held else f"[{f(lo):.4g}{'*' if cut[0] else ''}, {f(hi):.4g}{'*' if cut[1] else ''}]"
        if jk:
            extra += f"{format(jk['std_error'][report_name(n)], '.3g'):>12}"
        lines.append(f"{n + (' [deg]' if deg else ''):<19}{f(res.x[k]):>10.4g}{sd:>10}{interval:>24}{extra}{flag}")
    if idf.ci95_cut is not None and idf.ci95_cut[~np.isnan(idf.std_error)].any():
        lines.append("*: the interval ends at the parameter's bound, which it reaches (the interval the data "
                     "give goes past it)")
    if dirs:
        lines.append(f"std err and interval: data and population prior together along the {dirs['count']} free "
                     "directions (the prior's pull included, as an average over the catalogue's propellers) and "
                     "the population's spread along the held ones (the "
                     "data determine the directions, not a parameter alone: their own figures are the "
                     "directions', below)")
    elif data_only:
        lines.append("std err and interval: data and population prior together (the prior's pull on the estimate "
                     "included, as an average over the catalogue's propellers: one far from the base set is "
                     "pulled more; compare --no-prior); 'data only': the data's alone")
    return lines


def _dependence_lines(res: FitResult) -> list[str]:
    """report_text's lines on what the std errors miss: the residuals' lag-1
    autocorrelation where it is large, and the jackknife's spread between groups."""
    jk = res.extra.get("jackknife")
    lines = []
    auto = res.extra.get("residual_autocorrelation")
    if auto and auto["lag1"] is not None and auto["lag1"] > AUTOCORRELATION_SAID:
        flight = res.extra.get("kind") == "flight"
        several = not flight or len(res.extra.get("logs", ())) > 1
        hint = ({"flight": "; the leave-one-log-out jackknife (fit flight --cross-validate) measures the spread "
                           "between logs",
                 "loads": "; the jackknife of the runs (fit loads --jackknife) measures the spread between runs"}
                .get(res.extra.get("kind"), "") if several else "")
        said = (f"the jackknife below measures the spread between {jk['by']}s" if jk else
                f"the uncertainty is likely larger{hint}")
        # (n counts residuals in a load fit, each point's thrust and torque, and samples of 3 force errors in a flight
        # fit: "samples" said both until 2026-12-01, a fit-statistics audit)
        unit = {"flight": "samples (3 force errors each)", "level_flight": "conditions"}.get(res.extra.get("kind"),
                                                                                           "residuals")
        lines.append(f"std err and interval assume independent residuals; consecutive residuals within each "
                     f"{'log' if flight else 'run'} correlate at {auto['lag1']:.2f} (lag 1: the information "
                     f"of about {auto['n_effective']:.0f} independent {unit} of {auto['n']}): {said}")
    if jk:
        g = len(jk["groups"])
        ratios = [v for v in jk["ratio"].values() if v is not None]
        band_lo, band_hi = jk["band"]
        lines.append(f"jackknife: the std error from the {g} fits leaving one {jk['by']} out (the spread between "
                     f"{jk['by']}s; {g} {jk['by']}s make it itself uncertain, 95%: about "
                     f"{band_lo:.2g}-{band_hi:.2g} times it)"
                     + (f"; {min(ratios):.2g}-{max(ratios):.2g} times the linearised std err" if ratios else "")
                     + "".join(f"; without {g}: {', '.join(b)} at a bound (its spread understated)"
                               for g, b in jk.get("at_bound", {}).items()))
    return lines


def _directions_lines(res: FitResult) -> list[str]:
    """report_text's free parameter directions (fit loads --directions) with their loadings,
    or the effective number of parameters the data determine."""
    idf = res.identifiability
    dirs = res.extra.get("directions")
    lines = []
    if dirs:
        lines.append(f"free: {dirs['count']} directions of the {len(res.names)} parameters, those the data "
                     "determine best against the population prior\n  (the others held at the base set); "
                     "coefficient +- std error (data only) in prior standard deviations,\n  and the parameter "
                     "changes per unit (the four largest against each parameter's population spread):")
        for i, (cf, sd, sdd, load) in enumerate(zip(dirs["coefficients"], dirs["std_error"],
                                                    dirs["std_error_data_only"], dirs["loadings"])):
            big = sorted(range(len(load)), key=lambda j: -abs(load[j]) / dirs["prior_std"][j])[:4]
            unit = dirs["units"]
            terms = ", ".join(f"{res.names[j]} {load[j]:+.3g}{' deg' if dirs['names'][j] in unit else ''}"
                              for j in big)
            sd, sdd = ("inf" if v is None else f"{v:.3f}" for v in (sd, sdd))  # (None: not determined)
            lines.append(f"  direction_{i + 1} {cf:+.3f} +- {sd} ({sdd}): {terms}")
        lines.append(f"the data determine {idf.effective_parameters:.1f} of the {dirs['count']} free directions "
                     f"(effective number; the other {len(res.names) - dirs['count']} held at the base set)")
    elif idf.effective_parameters is not None:
        lines.append(f"the data determine {idf.effective_parameters:.1f} of the {len(res.names)} parameters' "
                     "directions (effective number; the prior holds the others near the base set)")
    return lines


def _fit_lines(res: FitResult, max_residuals: int) -> list[str]:
    """report_text's correlations, singular values, largest residuals, cost, the stall blend's
    continuation and the warnings."""
    idf = res.identifiability
    data_only = idf.std_error_data is not None
    dirs = res.extra.get("directions")
    lines = []
    # (held at a bound, NaN, or not determined, inf: no correlation; the latter's were printed as +0.00, an API audit,
    # stop 100)
    free = [k for k in range(len(res.names)) if np.isfinite(idf.std_error[k])]
    undetermined = [res.names[k] for k in range(len(res.names)) if np.isinf(idf.std_error[k])]
    if len(free) > 1:
        said = " (data and prior together)" if data_only or dirs else ""
        lines.append(f"correlation{said}: " + "; ".join(
            f"{res.names[i]}-{res.names[j]} {idf.correlation[i, j]:+.2f}"
            for a, i in enumerate(free) for j in free[a + 1:])
            + (f" ({', '.join(undetermined)} not determined: none)" if undetermined else ""))
    elif undetermined:
        lines.append(f"correlation: none ({', '.join(undetermined)} not determined)")
    label = ("the free directions' Jacobian" if dirs else "scaled Jacobian (data and prior rows, as fitted)"
             if data_only else "scaled Jacobian")
    lines.append(f"{label} singular values: " + ", ".join(f"{s:.3g}" for s in idf.singular_values))
    level = res.extra.get("kind") in ("level_flight", "flight")
    joint = res.extra.get("kind") == "loads_joint"
    unit = (" [N]" if level else " [-] (coefficient error / RMS of the measured coefficient, each propeller's "
            "weighted by sqrt(w N / (W n)); each one's own rms: per_propeller)" if joint
            else " [-] (coefficient error / RMS of the measured coefficient)")
    r = res.residuals
    order = np.argsort(-np.abs(r))[:max_residuals]
    shown = "" if r.size <= max_residuals else f" (the {max_residuals} largest of {r.size}; all in the JSON report)"
    labels = res.extra.get("residual_labels")  # (load fits: each residual's quantity, group and point)
    lines.append(f"residuals{unit}{shown}: " + ", ".join(
        f"#{i} {r[i]:+.3g}" + (f" ({labels[i]})" if labels is not None and i < len(labels) else "")
        for i in order))
    u = " N" if level else " [-]"
    lines.append(f"rms residual {np.sqrt(np.mean(r ** 2)):.4g}{u}; {res.nfev} evaluations "
                 f"({res.n_model_points} rotor points) in {res.elapsed_s:.2f} s; {len(res.starts)} start(s)")
    eff = res.extra.get("M_effect")
    if eff:
        lines.append(f"stall-blend smoothing: fitted with M = {eff['M_fit']:g}; the same parameters give rms "
                     f"residual {eff['rms_residual_at_M_fit']:.4g} at M = {eff['M_fit']:g} and "
                     f"{eff['rms_residual_at_M_base']:.4g} at M = {eff['M_base']:g} (the base value)")
    cont = res.extra.get("M_continuation")
    if cont:
        lines.append(f"continuation in M: fitted at M = {cont['M_first']:g} (rms residual "
                     f"{cont['rms_residual_first']:.4g}{u}), then at M = {cont['M_final']:g} from there")
    lines.extend(f"WARNING: {w}" for w in res.warnings)
    lines.extend(f"WARNING: {w}" for w in idf.warnings)
    return lines


def _scale_of(name: str) -> float:
    """A parameter's natural scale, against which a std error is judged where the estimate is
    near zero: CAMBERED_SCALE's, FLAP_START for the flap compliance, else a tenth of its bounds'
    span (the collective, the airframe terms), else 0."""
    if name in CAMBERED_SCALE:
        return CAMBERED_SCALE[name]
    if name == "flap_compliance":
        return FLAP_START  # (the typical compliance of small propellers, 0.3-4 rad/(N m))
    for bounds in (ROTOR_BOUNDS, AIRFRAME_BOUNDS):
        if name in bounds:
            lo, hi = bounds[name]
            return 0.1 * (hi - lo)
    return 0.0


def _identifiability(names, x, jac, residuals, dof_rows: int | None = None, held=(),
                     meat=None) -> Identifiability:
    """Identifiability from ``jac`` (rows: residuals, a prior's rows included where it has one);
    the residual variance from ``residuals`` with ``dof_rows`` (default: jac's rows) - p
    degrees of freedom; the parameters named in ``held`` (at a bound) fixed (class docstring).

    ``meat``: rows K of a sandwich covariance (J^T J)^+ K^T K (J^T J)^+, J = ``jac`` (in the
    covariance's own units, no residual variance applied): the error of a penalised estimate
    whose penalty rows are in ``jac`` (engine._shrinkage_meat); None, the usual s^2 (J^T J)^+.
    A parameter held at a bound is left out of J and K alike: the others' error as if it were
    known there (its distance from its true value is not propagated), as without ``meat``."""
    names = tuple(names)
    if any(n in held for n in names):
        keep = np.array([n not in held for n in names])
        sub = _identifiability([n for n, k in zip(names, keep) if k], np.asarray(x)[keep], jac[:, keep], residuals,
                               dof_rows, meat=None if meat is None else meat[:, keep])
        p = len(names)
        std = np.full(p, np.nan)
        ci = np.full((p, 2), np.nan)
        corr = np.eye(p)
        std[keep] = sub.std_error
        ci[keep] = sub.ci95
        corr[np.ix_(keep, keep)] = sub.correlation
        return Identifiability(names, std, ci, corr, sub.singular_values, sub.poorly_determined, sub.warnings,
                               warning_kinds=sub.warning_kinds)
    std, ci, corr, sig, s2 = _covariance(x, jac, residuals, dof_rows, meat)
    partners = _free_partners(names, x, jac) if not np.all(np.isfinite(std)) else None
    poor, notes = _identifiability_notes(names, x, std, corr, sig, s2 == 0.0 and meat is None, partners)
    return Identifiability(tuple(names), std, ci, corr, sig, tuple(poor), tuple(t for _, _, t in notes),
                           warning_kinds=tuple((k, s) for k, s, _ in notes))


def _covariance(x, jac, residuals, dof_rows, meat):
    """Std errors, 95% intervals (Student's t) and correlations of the parameters ``x`` from ``jac``
    (:func:`_identifiability`'s arguments), with the singular values of J diag(max(|x|, 0.1)) and
    the residual variance s^2 (1 with ``meat``); a parameter in a numerically free direction has an
    infinite std error and no correlation."""
    N, p = jac.shape
    dof = max((N if dof_rows is None else dof_rows) - p, 1)
    s2 = float(residuals @ residuals) / dof
    # covariance from the SVD of J D, D = diag(max(|x|, 0.1)) (relative changes, so that what is
    # rounding level does not depend on the parameters' units), with no cut-off: a weak direction
    # gets a large variance (a pseudo-inverse with a cut-off would report it as perfectly known);
    # a direction numerically free (its singular value within p max(N, p) epsilons of the largest)
    # is infinite for every parameter with a share of at least 1e-3 in it
    d, sig, Vt, null = _null_directions(x, jac)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv_sig2 = np.where(null, 0.0, 1.0 / sig**2)
        shape = np.outer(d, d) * ((Vt.T * inv_sig2) @ Vt)  # the covariance per unit residual variance
        if meat is not None:  # the sandwich: (J^T J)^+ K^T K (J^T J)^+
            shape = shape @ (meat.T @ meat) @ shape
            s2 = 1.0
        cov = s2 * shape
        std = np.sqrt(np.clip(np.diag(cov), 0, None))
        std[np.any(np.abs(Vt[null]) >= 1e-3, axis=0)] = np.inf
        if sig.size < p:  # fewer residuals than parameters: the missing directions are free
            std = np.full(p, np.inf)
        std = np.where(np.isnan(std), np.inf, std)
        from scipy import stats

        t = stats.t.ppf(0.975, dof)
        ci = np.column_stack([x - t * std, x + t * std])
        unit = np.sqrt(np.clip(np.diag(shape), 0, None))
        # (from the shape alone, not s2: an exact fit, s2 = 0, gave 0/0 and reported every correlation as 0)
        corr = shape / np.outer(unit, unit)
    corr = np.where(np.isfinite(corr), corr, 0.0)
    free = ~np.isfinite(std)  # (a parameter in a null direction: the pseudo-inverse's shape says nothing of it)
    corr[free, :] = 0.0
    corr[:, free] = 0.0
    np.fill_diagonal(corr, 1.0)
    return std, ci, corr, sig, s2


def _null_directions(x, jac):
    """(D, singular values, V^T, which are numerically free) of J D, D = diag(max(|x|, 0.1)): a
    direction is free where its singular value is within p max(N, p) epsilons of the largest
    (:func:`_covariance`)."""
    N, p = jac.shape
    d = np.maximum(np.abs(np.asarray(x, float)), 0.1)
    _, sig, Vt = np.linalg.svd(jac * d, full_matrices=False)
    return d, sig, Vt, sig <= (sig[0] if sig.size else 0.0) * p * max(N, p) * np.finfo(float).eps


def _free_partners(names, x, jac) -> dict:
    """Each parameter's partners in the free directions of the Jacobian (those with a share of at
    least 1e-3 in a direction it has one in): what the data leave free with it."""
    _, _, Vt, null = _null_directions(x, jac)
    share = np.abs(Vt[null]) >= 1e-3
    return {n: [m for j, m in enumerate(names) if j != k and np.any(share[:, k] & share[:, j])]
            for k, n in enumerate(names)}


def _identifiability_notes(names, x, std, corr, sv, exact: bool, partners=None):
    """The poorly determined parameters and the notes (kind, parameters, text) of
    :class:`Identifiability`: an exact fit (``exact``: residual 0 without a sandwich), a parameter
    not determined or poorly determined (std error over POOR_REL_STD of its estimate or natural
    scale), a pair correlated beyond 0.95, a nearly singular Jacobian."""
    p = len(names)
    poor, notes = [], []  # notes: (kind, parameters, text), Identifiability.warning_kinds
    if exact:
        notes.append(("exact", (), "the fit reproduces the data exactly (residual 0: noise-free data?): the std "
                      "errors and intervals are 0 and say nothing of how well the data determine the parameters; "
                      "the correlations below do"))
    for k, n in enumerate(names):
        if not np.isfinite(std[k]):
            poor.append(n)
            with_ = (partners or {}).get(n)
            # (where it shares a free direction with others, the data leave their combination free, not it alone: said
            # "no residual changes with it" of three parameters each of which moves the residuals, an API audit, stop
            # 100)
            why = (f"the data leave a combination of it with {', '.join(with_)} free: no residual changes along it at "
                   "the optimum" if with_ else "no residual changes with it at the optimum")
            notes.append(("not_determined", (n,), f"{n} is not determined by the data: its std error is not "
                          f"finite ({why})"))
            continue
        rel = std[k] / max(abs(x[k]), _scale_of(n), 1e-12)
        if rel > POOR_REL_STD:
            poor.append(n)
            shown = f"{math.degrees(std[k]):.3g} deg" if _is_angle(n) else f"{std[k]:.3g}"
            share = f"{100 * rel:.0f}% of" if rel < 10 else f"{rel:.3g} times"
            notes.append(("poorly_determined", (n,), f"{n} is poorly determined: std error {shown} is {share} its "
                          f"{'estimate' if abs(x[k]) >= _scale_of(n) else 'natural scale'}"))
    for i in range(p):
        for j in range(i + 1, p):
            if abs(corr[i, j]) > 0.95:
                notes.append(("correlated", (names[i], names[j]),
                              f"{names[i]} and {names[j]} are strongly correlated ({corr[i, j]:+.2f}): "
                              "the data constrain mainly a combination of them"))
    if sv.size and sv[-1] < 1e-6 * sv[0]:
        notes.append(("singular", (), "the Jacobian is nearly singular: some direction in parameter space is not "
                      "identifiable"))
    return poor, notes


def _effective_parameters(jac_data, jac_all) -> float:
    """tr[J_d^T J_d (J^T J)^+] with J = jac_all (data and prior rows): the directions the data
    determine against the prior (Identifiability)."""
    A = jac_data.T @ jac_data
    return float(np.trace(A @ np.linalg.pinv(jac_all.T @ jac_all)))
