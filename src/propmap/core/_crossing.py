"""The bracketing search of the trims (core/trim.py's module docstring, "Which solution"): the
thrust asked for, checked, and its first crossing along a grid of collectives or rotation rates,
refined; and the helpers that both trims' messages and NaN results share."""

from __future__ import annotations

import math

import numpy as np

from ._numbers import real

__all__ = []  # (core/trim.py's: its trims and their constants)


def _two_reals(bounds, what: str) -> tuple[float, float]:
    """``bounds`` as two floats, each a real number (:func:`real`: a text or a bool is none; float() read
    ("-0.3", "0.5") as numbers, an API audit, 2026-12-01); else ValueError(``what``, got ...)."""
    try:
        lo, hi = (real(b) for b in bounds)
    except (TypeError, ValueError):
        lo = hi = None
    if lo is None or hi is None:
        raise ValueError(f"{what}, got {bounds!r:.80}")
    return lo, hi


def _where(i: int, shape) -> str:
    """The index of point ``i`` for a message ('' for a single point)."""
    return f"{tuple(int(k) for k in np.unravel_index(i, shape))} " if shape else ""


def _check_on_missing(on_missing) -> None:
    """Refuse an ``on_missing`` other than 'raise' or 'nan' (both searches' argument)."""
    if on_missing not in ("raise", "nan"):
        raise ValueError(f"on_missing must be 'raise' or 'nan', got {on_missing!r}")


#: the loads both searches set to NaN where nothing in the bounds makes the thrust
_MISSING_FIELDS = ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "v_i_mean")


def _nan_where_missing(loads, ok: np.ndarray, shape, fields=_MISSING_FIELDS) -> None:
    """Set ``fields`` of ``loads`` to NaN, in place, at the points where ``ok`` (flat) is False."""
    if not ok.all():
        bad = ~ok.reshape(shape)
        for f in fields:
            np.asarray(getattr(loads, f))[bad] = np.nan


def _checked_thrust(thrust, thrust_tol) -> tuple[np.ndarray, float | None]:
    """The thrust wanted as a float array and its tolerance as a float (None: the default),
    checked (ValueError naming each)."""
    tol = None if thrust_tol is None else real(thrust_tol)  # (True was a tolerance of 1 N)
    if thrust_tol is not None and (tol is None or not (tol > 0 and math.isfinite(tol))):
        raise ValueError(f"thrust_tol must be a positive number [N], got {thrust_tol!r}")
    try:
        T_star = np.asarray(thrust)
    except (ValueError, OverflowError) as exc:  # (ragged nesting: NumPy's words alone did not name the thrust)
        raise ValueError(f"thrust must be a number or a rectangular array of numbers [N] ({exc})") from None
    if T_star.dtype.kind not in "iuf":  # (a string '4' read as 4 N, True as 1 N)
        raise ValueError(f"thrust must be a number or an array of numbers [N], got {thrust!r:.60}")
    T_star = T_star.astype(float)
    if not np.all(np.isfinite(T_star)):
        raise ValueError("thrust must be finite [N]")
    return T_star, tol


class _RefineFailed(Exception):
    """The root refinement of :func:`_first_crossing` failed at point ``index`` (SciPy ``status``)."""

    def __init__(self, index: int, status: int):
        super().__init__(index, status)
        self.index, self.status = index, status


#: the default thrust tolerance: THRUST_TOL [N], or THRUST_RTOL of the thrust asked where that is smaller, point by
#: point (the absolute 1e-6 N alone was 2% of the 5e-5 N of a 45 mm propeller at 465 rpm, a user-level audit,
#: 2026-11-30); a thrust_tol given is used as it is
THRUST_TOL = 1e-6
THRUST_RTOL = 1e-6
#: the smallest tolerance: a thrust of 5e-324 N would make 1e-6 of it 0 (then the variable's tolerance stops)
THRUST_TOL_FLOOR = 1e-300


def _tolerances(T1: np.ndarray, thrust_tol: float | None) -> np.ndarray:
    """Each point's thrust tolerance [N]: ``thrust_tol`` where given (a float, _checked_thrust's), else
    THRUST_TOL or THRUST_RTOL |T*|, the smaller (THRUST_TOL where T* = 0)."""
    if thrust_tol is not None:
        return np.full(T1.shape, thrust_tol)
    tol = np.where(T1 != 0.0, np.minimum(THRUST_TOL, THRUST_RTOL * np.abs(T1)), THRUST_TOL)
    return np.maximum(tol, THRUST_TOL_FLOOR)


def _first_crossing(thrust_at, grid, T1, columns, thrust_tol, *, xatol: float = 0.0, xrtol: float = 0.0,
                    falling: bool = False):
    """The first upward crossing of T* = ``T1`` along ``grid`` for every point (the rule of the
    module docstring, for the collective or the rotation rate alike); with ``falling``, where
    there is none, the first downward one.

    ``thrust_at(x, *cols)`` is the thrust [N] at the variable's values ``x`` (shape (k,) or
    (k, m)) for the points whose ``columns`` (each shape (n,), the other inputs) are ``cols``.
    Returns ``(x, n_solutions, missing, reach, fell)``: the solution (NaN where missing), the
    crossings seen, where none is, (lowest thrust, highest thrust, the variable where it is
    highest, whether that peak lies inside the grid) per point for messages, and where the
    solution is a downward crossing (``falling``). Raises
    _RefineFailed (its point's index and SciPy's status) where the refinement fails. The
    refinements solve the thrust difference in units of each point's tolerance (:func:`_tolerances`),
    so that one SciPy tolerance holds each point to its own.
    """
    from scipy.optimize import elementwise

    n, m = T1.size, grid.size
    tol = _tolerances(T1, thrust_tol)
    Tg = thrust_at(grid[None, :], *(c[:, None] for c in columns)) - T1[:, None]  # (n, m)
    up = (Tg[:, :-1] <= 0) & (Tg[:, 1:] > 0)  # upward crossings
    down = (Tg[:, :-1] > 0) & (Tg[:, 1:] <= 0)
    exact = Tg == 0
    # (a node that makes the thrust exactly is a solution: a parked rotor's 0 N at every collective counted 0)
    n_solutions = np.maximum(up.sum(axis=1) + down.sum(axis=1), exact.any(axis=1))
    fell = falling & ~up.any(axis=1) & ~exact.any(axis=1) & down.any(axis=1)
    missing = ~up.any(axis=1) & ~exact.any(axis=1) & ~fell
    j = np.where(up.any(axis=1), np.argmax(up, axis=1), np.where(fell, np.argmax(down, axis=1), 0))
    xl, xr = grid[j], grid[j + 1]
    on_node = exact.any(axis=1) & ~up.any(axis=1)
    # a thrust the grid misses only near the peak of T(x) (a stalling set): the peak between the grid's neighbours of
    # its highest node refined first, and where it reaches the thrust, the crossing below it
    k_top = np.argmax(Tg, axis=1)
    top, at_top = (Tg + T1[:, None]).max(axis=1), grid[k_top]
    # (every node below the thrust: one above them all, or below them all, has no peak to refine, a review found)
    inner = missing & (k_top > 0) & (k_top < m - 1) & (Tg.max(axis=1) < 0)
    if inner.any():
        idx, kk = np.flatnonzero(inner), k_top[inner]

        def minus(x, T_, tol_, *cols):
            return (T_ - thrust_at(x, *cols)) / tol_

        peak = elementwise.find_minimum(minus, (grid[kk - 1], grid[kk], grid[kk + 1]),
                                        args=(T1[idx], tol[idx], *(c[idx] for c in columns)),
                                        tolerances=dict(xatol=xatol, xrtol=xrtol, fatol=0.1, frtol=0.0))
        top[idx], at_top[idx] = T1[idx] - peak.f_x * tol[idx], peak.x
        reached = peak.f_x <= 0
        hit = idx[reached]
        missing[hit] = False
        n_solutions[hit] += 2  # (an upward and a downward crossing about the peak)
        xl[hit], xr[hit] = grid[kk[reached] - 1], peak.x[reached]
    reach = ((Tg + T1[:, None]).min(axis=1), top, at_top, inner)
    x = np.full(n, np.nan)
    x[on_node] = grid[np.argmax(exact[on_node], axis=1)]
    todo = ~on_node & ~missing
    if todo.any():
        def f(x_, T_, tol_, *cols):
            return (thrust_at(x_, *cols) - T_) / tol_

        res = elementwise.find_root(f, (xl[todo], xr[todo]), args=(T1[todo], tol[todo], *(c[todo] for c in columns)),
                                    tolerances=dict(xatol=xatol, xrtol=xrtol, fatol=1.0, frtol=0.0))
        if not np.all(res.success):
            k = int(np.argmax(~res.success))
            raise _RefineFailed(int(np.flatnonzero(todo)[k]), int(res.status[k]))
        x[todo] = res.x
    return x, n_solutions, missing, reach, fell
