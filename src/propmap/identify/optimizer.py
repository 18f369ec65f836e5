"""The fitting engine's bounded least squares (identify/engine.py): each parameter's bounds, the
central-difference Jacobian where a residual brings no implicit one, the residual with its model
calls counted (:class:`CountedResidual`, every fit's), and SciPy's trust-region
reflective least squares from the start and ``FitOptions.multistart`` scrambled Sobol' starts,
screened and the two best polished (docs/identification.md).
"""

from __future__ import annotations

import math
import time

import numpy as np

from .options import ALL_BOUNDS, FitOptions
from .result import _scale_of

__all__ = ["SCREEN_NFEV", "SAME_COST_RTOL", "DIFFERENT_X_RTOL", "CountedResidual"]


SCREEN_NFEV = 12  # residual evaluations per start in the multistart screening stage
SAME_COST_RTOL = 0.01  # multistart optima within 1% in cost ...
DIFFERENT_X_RTOL = 0.05  # ... but 5% apart in a parameter: the data do not determine it


def _bounds(names, options: FitOptions):
    table = {**ALL_BOUNDS, **(options.bounds or {})}
    unknown = [n for n in names if n not in table]
    if unknown:
        raise ValueError(f"cannot fit {', '.join(unknown)}: valid names are {', '.join(table)}")
    lb = np.array([table[n][0] for n in names], float)
    ub = np.array([table[n][1] for n in names], float)
    return lb, ub


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


class CountedResidual:
    """A fit's residual with its model calls counted, and its Jacobian: the model's own where it
    has one, else central differences within the bounds (:func:`_jacobian`).

    The counting rule of every fit's reported evaluations (``FitResult.nfev``): a residual is
    one model call, the model's own Jacobian (``residual.jacobian``: the implicit derivatives,
    one solve with derivatives) one, the residual with that Jacobian (``residual.with_jacobian``)
    one, and a differenced Jacobian two per parameter (its residuals, counted as they are made).

    Parameters
    ----------
    residual : callable
        x -> residual vector, with ``jacobian`` and ``with_jacobian`` where the model brings its
        implicit derivatives (engine._attach_jacobian).
    lb, ub : ndarray, shape (n,)
        The parameters' bounds, which the differences' steps stay within.
    on_call : callable, optional
        Called with the number of each count's model calls (a progress bar's ``update``).

    Attributes
    ----------
    n : int
        The model calls counted so far.
    paired : bool
        Whether the residual and its own Jacobian come from one model call (``with_jacobian``).
    """

    def __init__(self, residual, lb, ub, on_call=None):
        self.residual, self.lb, self.ub, self.n = residual, lb, ub, 0
        self._own = getattr(residual, "jacobian", None)
        self._pair = getattr(residual, "with_jacobian", None)
        self.paired = self._pair is not None
        self._on_call = on_call

    def _count(self, calls: int) -> None:
        self.n += calls
        if self._on_call is not None:
            self._on_call(calls)

    def __call__(self, x):
        """The residual at x: one model call."""
        self._count(1)
        return self.residual(x)

    def jacobian(self, x):
        """The Jacobian at x: the model's own (one model call), else central differences of
        the residual (two model calls per parameter)."""
        x = np.array(x, float)
        if self._own is not None:
            self._count(1)
            return self._own(x)
        return _jacobian(self, x, self.lb, self.ub)

    def with_jacobian(self, x):
        """(residual, Jacobian) at x: one model call where the model brings both
        (``paired``), else the residual's and :meth:`jacobian`'s."""
        x = np.array(x, float)
        if self._pair is not None:
            self._count(1)
            return self._pair(x)
        return self(x), self.jacobian(x)


def _solve(residual, names, options: FitOptions, label: str, x0):
    """Bounded least squares from x0 and ``options.multistart`` Sobol starts; best cost wins.

    Returns (best, log, nfev, elapsed, warnings): ``warnings`` names multistart optima
    that reach the same cost with different parameters.
    """
    from tqdm import tqdm

    lb, ub = _bounds(names, options)
    starts = _starts(x0, lb, ub, options)
    # disable=None: off unless a terminal
    bar = tqdm(desc=label, unit="eval", disable=None if options.progress else True, leave=False)
    model = CountedResidual(residual, lb, ub, on_call=bar.update)
    last = {}  # the Jacobian of the last residual evaluated, and where

    def fun(x):
        if not model.paired:
            return model(x)
        # the implicit derivatives come with the residual from one model call: least_squares asks
        # for the Jacobian where it last evaluated the residual (after an accepted step), so most
        # calls need it, and the derivatives cost less than a second call (benchmarks/README.md)
        x = np.array(x, float)
        r, last["J"] = model.with_jacobian(x)
        last["x"] = x
        return r

    def jac(x):
        x = np.array(x, float)
        if "x" in last and np.array_equal(last["x"], x):  # (that Jacobian, free: counted with its residual)
            return last["J"]
        return model.jacobian(x)

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
            warns += _equal_optima(best, polished[1], names)
        # best.jac is _jacobian at best.x: least_squares evaluates jac after every
        # accepted step and returns it unchanged for the default linear loss
    finally:
        bar.close()
    return best, log, model.n, time.perf_counter() - t0, warns


def _starts(x0, lb: np.ndarray, ub: np.ndarray, options: FitOptions) -> list:
    """The fit's starts: x0 clipped to the bounds, then ``options.multistart`` points of a scrambled
    Sobol' sequence (``options.seed``) in the bounds' box."""
    starts = [np.clip(np.asarray(x0, float), lb, ub)]
    if options.multistart > 0:
        m = max(0, math.ceil(math.log2(options.multistart)))  # Sobol' points come in powers of 2
        from scipy.stats import qmc

        sob = qmc.Sobol(len(lb), scramble=True, seed=options.seed).random_base2(m)[: options.multistart]
        starts += list(lb + sob * (ub - lb))
    return starts


def _equal_optima(best, other, names) -> list[str]:
    """A warning where the two polished multistart optima reach the same cost (within SAME_COST_RTOL,
    or both at round-off level: a perfect fit) with a parameter more than DIFFERENT_X_RTOL of its
    scale apart; else none."""
    if other.cost <= best.cost * (1 + SAME_COST_RTOL) + 1e-12 * best.fun.size:
        span = np.maximum(np.abs(best.x), [max(_scale_of(n), 1e-12) for n in names])
        differ = [n for n, a, b, sc in zip(names, best.x, other.x, span) if abs(a - b) > DIFFERENT_X_RTOL * sc]
        if differ:
            return [f"two multistart optima reach the same residual (costs {best.cost:.4g} and "
                    f"{other.cost:.4g}) with different {', '.join(differ)}: the data do not "
                    "determine them"]
    return []
