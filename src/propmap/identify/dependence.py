"""What a fit's linearised standard errors miss: the serial dependence of its residuals
(lag-1 autocorrelation) and the spread between groups of data (the delete-a-group
jackknife), for the report of every data kind (docs/identification.md).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from .options import report_name, report_value

if TYPE_CHECKING:
    from .result import FitResult

__all__ = ["jackknife_report", "jackknife_std_error", "lag1_autocorrelation"]


def lag1_autocorrelation(residuals, groups) -> dict:
    """How much consecutive residuals resemble each other: their lag-1 autocorrelation within
    each group (a log, a sweep), pooled, and the effective sample size it implies.

    The linearised std errors (:class:`~propmap.identify.result.Identifiability`) treat every
    residual as independent. Residuals of a smooth model error sampled densely (flight logs at
    25 Hz, sweeps along J) are not: rho = sum (r_t - m)(r_t+1 - m) / sum (r_t - m)^2, with m each group's and
    column's mean, numerator and denominator summed over the groups and columns. An AR(1)
    series of n samples carries the information of n (1 - rho) / (1 + rho) independent ones
    (G. E. P. Box, G. M. Jenkins and G. C. Reinsel, Time Series Analysis, 4th ed. 2008,
    Sec. 2.1.6; the large-sample variance of a mean), reported as ``n_effective`` (n where
    rho <= 0). A measure of dependence, not a correction: the std errors are not rescaled.

    Parameters
    ----------
    residuals : array_like, shape (N,) or (N, k)
        In the data's order (time within a log, J within a sweep); columns (axes) apart.
    groups : array_like, shape (N,)
        Each row's group; a group's rows in order. Groups of one row add nothing.

    Returns
    -------
    dict
        ``lag1`` (pooled rho, None where no group has two rows or the residuals are constant),
        ``lag1_per_column`` (list of k), ``n`` (N) and ``n_effective`` (float or None).

    Raises
    ------
    ValueError
        ``residuals`` not of one or two dimensions, ``groups`` not of length N, or residuals
        not finite.
    """
    r = np.asarray(residuals, float)
    r = r[:, None] if r.ndim == 1 else r
    g = np.asarray(groups)
    if r.ndim != 2:
        raise ValueError(f"residuals must be of shape (N,) or (N, k), got shape {r.shape}")
    if g.shape != (r.shape[0],):
        raise ValueError(f"groups must have one entry per residual row ({r.shape[0]}), got shape {g.shape}")
    if not np.all(np.isfinite(r)):
        raise ValueError("residuals must be finite")
    num = np.zeros(r.shape[1])
    den = np.zeros(r.shape[1])
    for key in np.unique(g):
        part = r[g == key]
        if part.shape[0] < 2:
            continue
        d = part - part.mean(axis=0)
        num += np.sum(d[1:] * d[:-1], axis=0)
        den += np.sum(d * d, axis=0)
    per = [float(a / b) if b > 0 else None for a, b in zip(num, den)]
    rho = float(num.sum() / den.sum()) if den.sum() > 0 else None
    n = int(r.shape[0])
    n_eff = None if rho is None else (n * (1 - rho) / (1 + rho) if rho > 0 else float(n))
    return {"lag1": rho, "lag1_per_column": per, "n": n, "n_effective": n_eff}


def jackknife_std_error(estimates) -> np.ndarray:
    """Delete-a-group jackknife standard error of a fit's parameters.

    From the estimates of g fits, each leaving one group out (a log, a sweep):
    se = sqrt((g - 1) / g * sum_i (theta_i - mean theta)^2) (B. Efron and R. J. Tibshirani, An
    Introduction to the Bootstrap, 1993, eq. 11.5). Leaving whole groups out keeps the
    dependence inside each group (H. R. Kunsch, "The jackknife and the bootstrap for general
    stationary observations", Ann. Statist. 17(3), 1989), so the spread between groups, which
    the linearised std errors of correlated residuals miss, is measured. With few groups it is
    itself uncertain (g = 4: its true value within about 0.57 to 3.7 times it, 95%, from
    the chi-square with g - 1 degrees of freedom).

    Parameters
    ----------
    estimates : array_like, shape (g, p)
        The g leave-one-group-out fits' parameters (in the units the caller reports).

    Returns
    -------
    ndarray, shape (p,)

    Raises
    ------
    ValueError
        Fewer than 2 groups, or estimates not finite.
    """
    e = np.asarray(estimates, float)
    if e.ndim != 2 or e.shape[0] < 2:
        raise ValueError(f"estimates must be (g, p) with g >= 2 leave-one-group-out fits, got shape {e.shape}")
    if not np.all(np.isfinite(e)):
        raise ValueError("estimates must be finite")
    g = e.shape[0]
    return np.sqrt((g - 1) / g * np.sum((e - e.mean(axis=0)) ** 2, axis=0))


def jackknife_report(result: FitResult, fold_x, by: str, groups, at_bound=None, bounds=None) -> dict:
    """The delete-a-group jackknife of a fit (:func:`jackknife_std_error`), for its report.

    Parameters
    ----------
    result : FitResult
        The fit on all groups.
    fold_x : sequence of dict
        Per group left out, its fit's parameters (name -> value as fitted, angles in rad);
        every fold must hold every one of ``result.names``.
    by : str
        What a group is ("log", "sweep").
    groups : sequence of str
        The groups left out, in ``fold_x``'s order.
    at_bound : sequence of sequence of str, optional
        Per fold, its parameters that ended at a bound (their value there is the bound's, so
        the spread understates theirs): said in the report.
    bounds : (ndarray, ndarray), optional
        The fit's lower and upper bounds of ``result.names`` (as fitted, angles in rad): the
        intervals cut at them, as every interval of the report is (``ci95_cut_at_bound``).

    Returns
    -------
    dict
        ``by``, ``groups``, ``std_error`` and ``ci95`` (estimate +- Student's t with g - 1
        degrees of freedom times it, cut at ``bounds``; ``ci95_cut_at_bound``: per parameter whether
        its low and high ends are cut) per parameter, keyed and in units as the report's (an
        angle's as ``alpha_L0_deg``, in deg: :func:`~propmap.identify.options.report_name`), and
        ``ratio`` to the linearised std error (None where that is not finite), ``band`` ([low,
        high]: the 95% band of the std error itself as multiples of it, g - 1 degrees of freedom:
        sqrt((g - 1) / chi2_0.975) to sqrt((g - 1) / chi2_0.025)), ``at_bound`` (group ->
        parameters at a bound in the fit without it, where any). The report
        (``FitResult.report_text``, ``to_dict``) shows it where ``result.extra["jackknife"]``
        holds it.

    Raises
    ------
    ValueError
        Fewer than 2 folds, a fold without one of the fit's parameters, estimates not finite.
    """
    from scipy import stats

    missing = [n for f in fold_x for n in result.names if n not in f]
    if missing:
        raise ValueError(f"a fold lacks the fitted parameter {missing[0]}")
    est = np.array([[f[n] for n in result.names] for f in fold_x], float)
    se = jackknife_std_error(est)
    g = est.shape[0]
    t = float(stats.t.ppf(0.975, g - 1))

    lin = result.identifiability.std_error
    lo, hi = result.x - t * se, result.x + t * se
    cut_lo = cut_hi = np.zeros(len(se), bool)
    if bounds is not None:  # (every interval of the report is cut at the bounds; this one was not until 2026-12-01:
        # cl_alpha's [7.33, 9.68] past its bound of 9, a fit-statistics audit)
        lb, ub = (np.asarray(b, float) for b in bounds)
        cut_lo, cut_hi = lo < lb, hi > ub
        lo, hi = np.maximum(lo, lb), np.minimum(hi, ub)
    return {"by": by, "groups": [str(x) for x in groups],
            "std_error": {report_name(n): report_value(n, s) for n, s in zip(result.names, se)},
            "ci95": {report_name(n): [report_value(n, a), report_value(n, b)]
                     for n, a, b in zip(result.names, lo, hi)},
            "ci95_cut_at_bound": {report_name(n): [bool(a), bool(b)] for n, a, b in zip(result.names, cut_lo, cut_hi)},
            "ratio": {report_name(n): (float(s / v) if np.isfinite(v) and v > 0 else None)
                      for n, s, v in zip(result.names, se, lin)},
            "band": [math.sqrt((g - 1) / stats.chi2.ppf(0.975, g - 1)),
                     math.sqrt((g - 1) / stats.chi2.ppf(0.025, g - 1))],
            "at_bound": {str(g): [report_name(n) for n in b] for g, b in zip(groups, at_bound or ()) if b}}
