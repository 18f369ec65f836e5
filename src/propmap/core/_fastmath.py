"""Branch-free polynomial atan2 and saturated exp for the compiled kernel.

Why: numba compiles ``np.arctan2`` and ``np.exp`` on scalars to scalar libm calls,
which stop LLVM from vectorising the azimuth loop of the residual (eq 11). The
functions below use only arithmetic, ``abs``, ``min``/``max`` and selects, so the
loop over azimuth nodes compiles to SIMD code (measured in benchmarks/README.md).

Accuracy (asserted by tests/test_fastmath.py against NumPy on 10^6 random inputs):

* ``atan2_poly``: absolute error <= 4e-15 rad on all finite inputs.
* ``exp_sat``: ``exp(clip(z, -40, 40))`` to a relative error <= 5e-13. The clip is
  where the stall blend of eq (3) is within exp(-40) = 4e-18 of its limits, i.e.
  equal to them in double precision; it is applied identically in the NumPy
  reference (``_physics.exp_sat_numpy``).
* ``exp_wide`` (``make_exp_wide``): ``exp(clip(z, -320, 320))`` as ``exp_sat(z / 8)^8``, to a
  relative error <= 2e-12: the stall blend's per-annulus constant exp(-2h)
  (``_physics.make_stall_blend``, which takes its two exponentials as one exp_sat and this).
  NumPy twin: ``_physics.exp_wide_numpy``.

They are plain Python functions of scalars (``make_exp_wide`` a factory of one);
``_annulus.py`` compiles them inline.
The coefficients are monomial forms of Chebyshev interpolants (numpy.polynomial):
``atan(x) = x P(x^2)`` with P of degree 18 interpolating atan(sqrt t)/sqrt t on
t in [0, 1], and ``exp(y)`` of degree 12 on y in [-0.625, 0.625];
``tools/fastmath_coefficients.py`` recomputes them.
"""

from __future__ import annotations

import math

HALF_PI = 0.5 * math.pi
PI = math.pi
EXP_CLIP = 40.0
EXP_WIDE = 8.0 * EXP_CLIP  # make_exp_wide's exp_sat(z / 8)^8

ATAN = (1.000000000000002, -0.33333333333421167, 0.2000000000643493, -0.14285714479457498,
        0.11111114175207791, -0.09090936926888635, 0.0769244729865118, -0.06666856734869056,
        0.05879811319113958, -0.052408230657372205, 0.04659406894107203,
        -0.040240758904378476, 0.032354315889901245, -0.02294302305304691,
        0.013521291315555574, -0.0062079962931181265, 0.0020490696555689764,
        -0.0004281495746813321, 4.226283023231908e-05)

EXP = (1.0000000000000009, 0.9999999999999931, 0.4999999999998476, 0.1666666666670624,
       0.04166666667169981, 0.008333333326978372, 0.001388888831582051,
       0.0001984127421810852, 2.480187467012823e-05, 2.7555837289945715e-06,
       2.7491731995739863e-07, 2.5297670833730897e-08, 2.649422190734004e-09)


def atan2_poly(y, x):
    """Four-quadrant arctangent of scalars y, x [rad], in [-pi, pi].

    Octant reduction to r = min(|x|, |y|) / max(|x|, |y|) in [0, 1], then
    atan(r) = r P(r^2), evaluated by Estrin's scheme (written out, no loop).
    ``atan2_poly(0, 0) = 0`` like ``np.arctan2``; the sign of a zero ``y`` is not
    honoured (returns +pi for y = -0.0, x < 0), which no caller distinguishes.
    """
    ax = abs(x)
    ay = abs(y)
    r = min(ax, ay) / (max(ax, ay) + 1e-300)
    t = r * r
    # Estrin's scheme: the same polynomial as Horner, with a dependency chain of ~6
    # operations instead of 18 (the root solve is latency-bound, one F(v) at a time)
    c = ATAN
    t2 = t * t
    t4 = t2 * t2
    t8 = t4 * t4
    r0 = (c[0] + c[1] * t) + (c[2] + c[3] * t) * t2
    r1 = (c[4] + c[5] * t) + (c[6] + c[7] * t) * t2
    r2 = (c[8] + c[9] * t) + (c[10] + c[11] * t) * t2
    r3 = (c[12] + c[13] * t) + (c[14] + c[15] * t) * t2
    r4 = (c[16] + c[17] * t) + c[18] * t2
    p = ((r0 + r1 * t4) + (r2 + r3 * t4) * t8) + r4 * (t8 * t8)
    a = r * p
    a = HALF_PI - a if ay > ax else a
    a = PI - a if x < 0.0 else a
    return -a if y < 0.0 else a


def exp_sat(z):
    """``exp(min(max(z, -40), 40))`` of a scalar, by ``exp(z/64)^64``."""
    u = min(max(z, -EXP_CLIP), EXP_CLIP) * (1.0 / 64.0)
    c = EXP
    u2 = u * u
    u4 = u2 * u2
    r0 = (c[0] + c[1] * u) + (c[2] + c[3] * u) * u2
    r1 = (c[4] + c[5] * u) + (c[6] + c[7] * u) * u2
    r2 = (c[8] + c[9] * u) + (c[10] + c[11] * u) * u2
    p = (r0 + r1 * u4) + (r2 + c[12] * u4) * (u4 * u4)
    p = p * p
    p = p * p
    p = p * p
    p = p * p
    p = p * p
    return p * p


def make_exp_wide(exp_sat):
    """Return ``exp_wide(z)`` = ``exp(min(max(z, -320), 320))`` of a scalar, as ``exp_sat(z / 8)^8``.

    Parameters
    ----------
    exp_sat : callable
        :func:`exp_sat` or its compiled form (so that the kernel's compiled one is inlined).

    Returns
    -------
    callable
        ``exp_wide(z)`` of a float z [-], relative error <= 2e-12 (tests/test_fastmath.py).
    """

    def exp_wide(z):
        p = exp_sat(min(max(z, -EXP_WIDE), EXP_WIDE) * 0.125)
        p = p * p
        p = p * p
        return p * p

    return exp_wide
