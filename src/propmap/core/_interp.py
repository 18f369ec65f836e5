"""Compiled (numba) multilinear interpolation in a rotor map (maps.RotorMap).

The table holds, on a rectilinear grid (Omega, V, beta), the loads divided by the square of
a reference speed, (Omega R)^2 + V^2: T, D, Q, M_R scale as Omega^2 in hover and as V^2 at
high advance ratio, so the quotient varies slowly and linear interpolation is far more
accurate than on the loads themselves (measured: docs/simulators.md); the result is
multiplied back by the query's (Omega R)^2 + V^2. Each query is located by bisection on
each axis (the axes need not be uniform) and interpolated from the 8 corners of its cell.

Out-of-grid policy (``policy``): CLIP (0) moves the query onto the grid's boundary,
NAN (1) returns NaN; both set ``inside[i] = False``. The raising policy is applied by the
caller before this kernel runs.
"""

from __future__ import annotations

import numba
import numpy as np

CLIP = 0
NAN = 1

_FLAGS = dict(cache=True, error_model="numpy", fastmath={"nsz", "arcp", "contract", "afn", "reassoc"})


@numba.njit(inline="always", **_FLAGS)
def _locate(ax, x):
    """(cell index, fraction in [0, 1]) of x in the increasing axis ax (x within its range)."""
    n = ax.shape[0]
    lo = 0
    hi = n - 1
    while hi - lo > 1:
        mid = (lo + hi) >> 1
        if ax[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo, (x - ax[lo]) / (ax[lo + 1] - ax[lo])


@numba.njit(inline="always", **_FLAGS)
def _one(ax0, ax1, ax2, table, cellflag, radius, q0, q1, q2, policy, out, i, inside, flagged):
    nvar = table.shape[3]
    ok = ax0[0] <= q0 <= ax0[-1] and ax1[0] <= q1 <= ax1[-1] and ax2[0] <= q2 <= ax2[-1]
    inside[i] = ok
    if not ok:
        if policy == NAN:
            for k in range(nvar):
                out[i, k] = np.nan
            flagged[i] = True
            return
        q0 = min(max(q0, ax0[0]), ax0[-1])
        q1 = min(max(q1, ax1[0]), ax1[-1])
        q2 = min(max(q2, ax2[0]), ax2[-1])
    i0, f0 = _locate(ax0, q0)
    i1, f1 = _locate(ax1, q1)
    i2, f2 = _locate(ax2, q2)
    flagged[i] = (not ok) or cellflag[i0, i1, i2] != 0
    g0 = 1.0 - f0
    g1 = 1.0 - f1
    g2 = 1.0 - f2
    w000 = g0 * g1 * g2
    w001 = g0 * g1 * f2
    w010 = g0 * f1 * g2
    w011 = g0 * f1 * f2
    w100 = f0 * g1 * g2
    w101 = f0 * g1 * f2
    w110 = f0 * f1 * g2
    w111 = f0 * f1 * f2
    s = q0 * q0 * radius * radius + q1 * q1
    for k in range(nvar):
        v = (w000 * table[i0, i1, i2, k] + w001 * table[i0, i1, i2 + 1, k]
             + w010 * table[i0, i1 + 1, i2, k] + w011 * table[i0, i1 + 1, i2 + 1, k]
             + w100 * table[i0 + 1, i1, i2, k] + w101 * table[i0 + 1, i1, i2 + 1, k]
             + w110 * table[i0 + 1, i1 + 1, i2, k] + w111 * table[i0 + 1, i1 + 1, i2 + 1, k])
        out[i, k] = v * s


@numba.njit(**_FLAGS)
def interp_batch(ax0, ax1, ax2, table, cellflag, radius, q0, q1, q2, policy, out, inside, flagged):
    """Interpolate every query (q0[i], q1[i], q2[i]); shapes (n,) in, (n, nvar) out."""
    for i in range(q0.shape[0]):
        _one(ax0, ax1, ax2, table, cellflag, radius, q0[i], q1[i], q2[i], policy, out, i, inside, flagged)


@numba.njit(**_FLAGS)
def interp_point(ax0, ax1, ax2, table, cellflag, radius, q0, q1, q2, policy, out, inside, flagged):
    """One query (scalars q0, q1, q2) into out[0, :], inside[0], flagged[0]."""
    _one(ax0, ax1, ax2, table, cellflag, radius, q0, q1, q2, policy, out, 0, inside, flagged)
