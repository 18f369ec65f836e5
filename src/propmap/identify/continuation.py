"""The continuation in the stall-blend sharpness M (the paper's model at footnote 2's M = 50):
stage 1 at M_SMOOTH, where eq 3's blend has no root folds, then least squares, Nelder-Mead
and Gauss-Newton tries on the exact M = 50 residual (docs/identification.md, Robustness).
Part of the fitting engine (identify/engine.py), which every data kind calls.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np

from ..core.airfoil import AirfoilParams
from .optimizer import CountedResidual, _bounds, _solve

__all__ = ["NM_STAT_TOL", "M_SMOOTH", "GN_STEP_TOL", "GN_MAX_ITER", "GN_TRY_EVERY"]

NM_STAT_TOL = 0.01  # Nelder-Mead at its limit counts as converged within 1% of the std errors
M_SMOOTH = 30.0  # first stage of the continuation in M (eq 3's blend has no root folds at 30)
GN_STEP_TOL = 1e-10  # Gauss-Newton has converged when its step is below this, relative to max(|x|, 0.1)
GN_MAX_ITER = 20  # Gauss-Newton iterations per try
GN_TRY_EVERY = 20  # model calls of Nelder-Mead between Gauss-Newton tries


def _gauss_newton(evaluate, x, lb, ub):
    """Gauss-Newton on the exact residual with its exact local (implicit) Jacobian.

    Full steps only: at M = 50 the residual jumps where an annulus' selected root changes
    branch; on the piece that holds the optimum, Gauss-Newton's full steps converge in a few
    iterations (measured: 2-8 from points along Nelder-Mead's path on the paper's case,
    every step accepted whole), while a step that does not lower the exact cost means a jump
    or a curved valley that a shorter step would only creep along, and the try ends there (a
    try that stalls at once costs two model calls: its start and the step). A residual or
    Jacobian that is not finite ends the try too.

    Parameters
    ----------
    evaluate : callable
        x -> (residual, Jacobian) from one model call.
    x : ndarray, shape (n,)
        The start, within [lb, ub].
    lb, ub : ndarray, shape (n,)
        Bounds; every iterate is clipped to them.

    Returns
    -------
    x : ndarray, shape (n,)
        The best point met.
    cost : float
        Half the squared residual norm there.
    converged : bool
        A step below GN_STEP_TOL relative to max(|x|, 0.1) was taken, or was all that was
        left and no longer lowered the cost (rounding): the piece's optimum. False where the
        try stalled at a jump or ran out of iterations.
    """
    r, J = evaluate(x)
    cost = 0.5 * float(r @ r)
    for _ in range(GN_MAX_ITER):
        if not (np.all(np.isfinite(r)) and np.all(np.isfinite(J))):
            return x, cost, False
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        small = bool(np.all(np.abs(step) <= GN_STEP_TOL * np.maximum(np.abs(x), 0.1)))
        xt = np.clip(x + step, lb, ub)
        rt, Jt = evaluate(xt)
        ct = 0.5 * float(rt @ rt)
        if not ct < cost:  # also a NaN
            return x, cost, small
        x, r, J, cost = xt, rt, Jt, ct
        if small:
            return x, cost, True
    return x, cost, False


def _polish_at_base_M(make_residual, names, options, base_M, x_smooth, label):
    """Stages 2 and 3 of the continuation in M, at the base M (docs/identification.md).

    2. Trust-region least squares on the EXACT residual at the base M, with the Jacobian
       of the smooth M_SMOOTH model: at M = 50 the stall folds make the residual jump by
       small amounts as parameters move (root-branch switches), so finite differences at
       M = 50 are dominated by the jumps, while the smooth Jacobian still points downhill.
    3. Nelder-Mead on the exact cost from there: it needs no derivatives, so the jumps do
       not stall it where the smooth Jacobian stops being a good model (measured: the
       paper's case generated at M = 50 is then recovered to 2e-13). With the implicit
       derivatives, Gauss-Newton with the exact M = 50 Jacobian (:func:`_gauss_newton`) is
       tried from stage 2's optimum and then from Nelder-Mead's best vertex after GN_TRY_EVERY
       model calls (1.5 times as many after each try that stalls); once a try converges below
       Nelder-Mead's best cost and every earlier try's, that is the optimum (the paper's
       case: Nelder-Mead's 800 model calls become 42, 31 of Nelder-Mead's and 11 of
       Gauss-Newton's). Like Nelder-Mead it is a local search: the optimum is that of the
       smooth piece of the M = 50 residual the try converged on.

    Returns an OptimizeResult-like object (x, fun, jac, cost, status, success, message,
    nfev) whose ``jac`` is the smooth model's Jacobian at the optimum (used for the
    identifiability report) and the number of residual evaluations spent.
    """
    lb, ub = _bounds(names, options)
    # the exact residual at the base M, the smooth model's Jacobian; the model calls of both count
    exact = CountedResidual(make_residual(replace(options, M=base_M)), lb, ub)
    smooth = CountedResidual(make_residual(replace(options, M=M_SMOOTH)), lb, ub)

    def calls():
        return exact.n + smooth.n

    from scipy import optimize  # imported where used: `propmap wrench` and `loads` start without it

    r2 = optimize.least_squares(exact, x_smooth, jac=smooth.jacobian, bounds=(lb, ub), method="trf", x_scale="jac",
                                max_nfev=options.max_nfev, xtol=1e-12, ftol=1e-12, gtol=1e-12)
    # only where the residual and its exact Jacobian come from one model call (the implicit
    # derivatives); a Jacobian with differenced columns would straddle the jumps
    newton = {"x": None, "cost": math.inf, "calls": 0, "every": GN_TRY_EVERY, "spent": 0, "done": None}

    def try_newton(x, best_other):
        """Gauss-Newton from x. Where it converges to a cost no higher than ``best_other``
        and any earlier try's, its point is the optimum (newton["done"]); each try that does
        not makes Nelder-Mead take 1.5 times as many model calls before the next (noisy data:
        the optimum may lie at a jump, where no try converges)."""
        def evaluate(z):  # (a model call in calls() as every other, and in newton["spent"]: the tries' share of nfev)
            newton["spent"] += 1
            return exact.with_jacobian(z)

        xg, cg, ok = _gauss_newton(evaluate, np.clip(np.asarray(x, float), lb, ub), lb, ub)
        if ok and cg <= best_other and cg <= newton["cost"]:
            newton["done"] = (cg, xg)
        if cg < newton["cost"]:
            newton["x"], newton["cost"] = xg, cg
        if not ok:
            newton["every"] = int(1.5 * newton["every"])
        newton["calls"] = calls()
        return newton["done"] is not None

    done = exact.paired and try_newton(r2.x, r2.cost)
    scale = np.maximum(np.abs(r2.x), 0.1)
    z0 = r2.x / scale
    simplex = np.vstack([z0, z0 + 0.02 * np.eye(z0.size)])
    simplex = np.clip(simplex, lb / scale, ub / scale)
    max_fev = 200 * len(names)

    def callback(intermediate_result):
        if not exact.paired or calls() - newton["calls"] < newton["every"]:
            return
        if try_newton(intermediate_result.x * scale, intermediate_result.fun):
            raise StopIteration

    if done:
        nm = optimize.OptimizeResult(x=z0, fun=math.inf, nfev=0, final_simplex=(simplex, None))
    else:
        nm = optimize.minimize(lambda z: 0.5 * float(np.sum(exact(z * scale) ** 2)), z0, method="Nelder-Mead",
                               bounds=list(zip(lb / scale, ub / scale)), callback=callback,
                               options={"xatol": 1e-12, "fatol": 1e-30, "maxfev": max_fev, "adaptive": True,
                                        "initial_simplex": simplex})
        done = newton["done"] is not None
    if done:
        x = newton["done"][1]
    else:  # the best point met: stage 2's, Nelder-Mead's or a stalled Gauss-Newton try's
        candidates = [(r2.cost, r2.x), (nm.fun, np.clip(nm.x * scale, lb, ub))]
        if newton["x"] is not None:
            candidates.append((newton["cost"], newton["x"]))
        x = min(candidates, key=lambda c: c[0])[1]
    spent = calls()
    fun, J = exact(x), smooth.jacobian(x)
    stopped = not done and nm.nfev >= max_fev and nm.fun < r2.cost and _simplex_wider_than_errors(nm, scale, fun, J)
    how = (f"Gauss-Newton with the exact M = {base_M:g} Jacobian" if done else f"Nelder-Mead at M = {base_M:g}")
    result = optimize.OptimizeResult(
        x=x, fun=fun, jac=J, cost=0.5 * float(fun @ fun), nfev_limit=max_fev,
        status=0 if stopped else 2, success=not stopped, nfev=r2.nfev + nm.nfev + newton["spent"],
        message=("Nelder-Mead stopped at its evaluation limit" if stopped else
                 f"converged: least squares with the M = {M_SMOOTH:g} Jacobian, then {how}"))
    # the optimum's residual and Jacobian count 2 n + 1 model calls whichever Jacobian the smooth model has (as
    # before CountedResidual: the counts reported unchanged)
    return result, spent + len(names) * 2 + 1


def _simplex_wider_than_errors(nm, scale: np.ndarray, fun: np.ndarray, J: np.ndarray) -> bool:
    """Whether Nelder-Mead, stopped at its evaluation limit, has not converged for any purpose:
    with noisy data its 1e-12 tolerance is not reached in max_fev evaluations, and it has
    converged for every purpose when its simplex is within NM_STAT_TOL of the parameters'
    standard errors (the data's scatter, not the optimiser, sets the error), from the residual
    ``fun`` and the Jacobian ``J`` at the optimum."""
    spread = np.ptp(nm.final_simplex[0], axis=0) * scale
    s2 = float(fun @ fun) / max(fun.size - J.shape[1], 1)
    with np.errstate(divide="ignore", invalid="ignore"):
        std = np.sqrt(np.clip(np.diag(s2 * np.linalg.pinv(J.T @ J)), 0, None))
    return not np.all(spread <= NM_STAT_TOL * std)


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
