"""Monotone piecewise cubic Hermite interpolation (PCHIP) of the blade geometry.

The same interpolant as ``scipy.interpolate.PchipInterpolator(x, y, extrapolate=True)``
(Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) 238-246, with the derivative rule of
Fritsch & Butland, SIAM J. Sci. Stat. Comput. 5 (1984) 300-304, and SciPy's one-sided
three-point end slopes), written out in NumPy because importing ``scipy.interpolate``
costs ~0.4 s, more than a whole single-point ``propmap loads`` may take (docs/solver.md,
Speed). tests/test_geometry_pchip.py checks it against SciPy's to 1e-13.
"""

from __future__ import annotations

import numpy as np


def _end_slope(h0, h1, m0, m1):
    """SciPy's one-sided three-point end slope, limited to keep the shape."""
    d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
    if np.sign(d) != np.sign(m0):
        return 0.0
    if np.sign(m0) != np.sign(m1) and abs(d) > abs(3 * m0):
        return 3 * m0
    return d


class Pchip:
    """PCHIP interpolant of y(x); called on any array shape, extrapolating with the end cubics.

    Parameters
    ----------
    x : ndarray, shape (n,), n >= 2
        Strictly increasing abscissae (not checked here: the caller validates them).
    y : ndarray, shape (n,)
        Values at ``x``.
    """

    def __init__(self, x, y) -> None:
        x = np.asarray(x, float)
        y = np.asarray(y, float)
        h = np.diff(x)
        m = np.diff(y) / h
        n = x.size
        d = np.empty(n)
        if n == 2:
            d[:] = m[0]
        else:
            h0, h1, m0, m1 = h[:-1], h[1:], m[:-1], m[1:]
            w1 = 2 * h1 + h0
            w2 = h1 + 2 * h0
            same = (np.sign(m0) * np.sign(m1)) > 0
            with np.errstate(divide="ignore", invalid="ignore"):
                harmonic = (w1 + w2) / (w1 / m0 + w2 / m1)
            d[1:-1] = np.where(same, harmonic, 0.0)
            d[0] = _end_slope(h[0], h[1], m[0], m[1])
            d[-1] = _end_slope(h[-1], h[-2], m[-1], m[-2])
        self.x, self.y, self.d, self.h, self.m = x, y, d, h, m

    def __call__(self, xq) -> np.ndarray:
        xq = np.asarray(xq, float)
        i = np.clip(np.searchsorted(self.x, xq, side="right") - 1, 0, self.x.size - 2)
        h = self.h[i]
        t = (xq - self.x[i]) / h
        y0, y1 = self.y[i], self.y[i + 1]
        d0, d1 = self.d[i] * h, self.d[i + 1] * h
        t2 = t * t
        t3 = t2 * t
        return ((2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * y1
                + (t3 - t2) * d1)
