"""Recompute the polynomial coefficients of src/propmap/core/_fastmath.py and print them.

Both are Chebyshev interpolants (numpy.polynomial.chebyshev.chebinterpolate) converted
to monomial form for Horner evaluation:

* atan: P(t) = atan(sqrt t) / sqrt t on t in [0, 1], degree 18, so atan(x) = x P(x^2);
* exp: exp(y) on y in [-0.625, 0.625] (= [-40, 40] / 64), degree 12.

Run:  .venv/bin/python tools/fastmath_coefficients.py

The approximations and their errors: docs/solver.md (the element's branch-free polynomials).
"""

import argparse

import numpy as np
from numpy.polynomial import chebyshev, polynomial

ATAN_DEGREE = 18
EXP_DEGREE = 12
EXP_HALF_WIDTH = 40.0 / 64.0


def monomial_interpolant(func, lo, hi, degree):
    """Monomial coefficients (lowest first) of the Chebyshev interpolant of func on [lo, hi]."""
    cheb = chebyshev.chebinterpolate(lambda u: func(lo + 0.5 * (u + 1.0) * (hi - lo)), degree)
    in_u = chebyshev.cheb2poly(cheb)  # monomial in u = (2 t - lo - hi) / (hi - lo)
    scale, shift = 2.0 / (hi - lo), -(hi + lo) / (hi - lo)
    out = np.zeros(1)
    for c in in_u[::-1]:  # Horner composition p(scale t + shift)
        out = polynomial.polyadd(polynomial.polymul(out, [shift, scale]), [c])
    return out


def atan_over_sqrt(t):
    s = np.sqrt(t)
    out = np.ones_like(t)
    pos = t > 0
    out[pos] = np.arctan(s[pos]) / s[pos]
    return out


def coefficients():
    """Return (ATAN, EXP) coefficient arrays, lowest order first."""
    return (monomial_interpolant(atan_over_sqrt, 0.0, 1.0, ATAN_DEGREE),
            monomial_interpolant(np.exp, -EXP_HALF_WIDTH, EXP_HALF_WIDTH, EXP_DEGREE))


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    atan, exp = coefficients()
    print("ATAN = (" + ", ".join(repr(float(c)) for c in atan) + ")")
    print("EXP = (" + ", ".join(repr(float(c)) for c in exp) + ")")
