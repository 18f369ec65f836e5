"""The kernel's polynomial atan2 and saturated exp (core/_fastmath.py) against NumPy, and
the compiled blade element built on them against the NumPy element."""

import importlib.util
import math
from pathlib import Path

import numba
import numpy as np
import pytest

from propmap.core import _fastmath, _kernel
from propmap.core._physics import element

ROOT = Path(__file__).resolve().parents[1]


@numba.njit
def _atan2_all(y, x, out):
    for i in range(y.size):
        out[i] = _kernel._atan2(y[i], x[i])


@numba.njit
def _exp_all(z, out):
    for i in range(z.size):
        out[i] = _kernel._exp_sat(z[i])


@numba.njit
def _element_all(UT, UP, th, kre, cl1, cl2, cd, a0, M, cd0, sincos, qT, qH):
    for i in range(UT.size):
        qT[i], qH[i] = _kernel._element(UT[i], UP[i], th[i], math.sin(th[i]), math.cos(th[i]), kre[i],
                                        cl1, cl2, cd, a0, M, cd0, sincos)


def atan2_poly(y, x):
    out = np.empty_like(y)
    _atan2_all(y, x, out)
    return out


def test_coefficients_are_the_documented_chebyshev_interpolants():
    spec = importlib.util.spec_from_file_location("fmc", ROOT / "tools" / "fastmath_coefficients.py")
    fmc = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(fmc)
    atan, exp = fmc.coefficients()
    np.testing.assert_allclose(_fastmath.ATAN, atan, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(_fastmath.EXP, exp, rtol=1e-9, atol=1e-15)


def test_atan2_poly_matches_numpy_on_random_inputs_of_every_scale_and_quadrant():
    rng = np.random.default_rng(7)
    n = 1_000_000
    y = rng.standard_normal(n) * 10.0 ** rng.uniform(-8, 4, n)
    x = rng.standard_normal(n) * 10.0 ** rng.uniform(-8, 4, n)
    err = np.abs(atan2_poly(y, x) - np.arctan2(y, x))
    assert err.max() <= 4e-15


def test_atan2_poly_on_the_axes_and_diagonals():
    y = np.array([0.0, 1.0, 0.0, -1.0, 0.0, 1.0, -1.0, 1e-300, 1e300, 3.0])
    x = np.array([0.0, 0.0, -1.0, 0.0, 1.0, 1.0, -1.0, -1.0, 1.0, -3.0])
    np.testing.assert_allclose(atan2_poly(y, x), np.arctan2(y, x), rtol=0, atol=4e-15)
    assert atan2_poly(y[:5], x[:5]).tolist() == np.arctan2(y[:5], x[:5]).tolist()  # axes exact


def test_exp_sat_is_exp_of_the_clipped_argument():
    z = np.concatenate([np.linspace(-60, 60, 200_001), [-40.0, 40.0, 0.0, -1e300, 1e300]])
    out = np.empty_like(z)
    _exp_all(z, out)
    ref = np.exp(np.clip(z, -40, 40))
    assert np.max(np.abs(out / ref - 1)) <= 5e-13
    assert out[-5] == out[0] and out[-4] == out[-1]  # saturated beyond +-40
    assert out[-3] == pytest.approx(1.0, rel=1e-13)


@pytest.mark.parametrize("sincos", [False, True])
def test_compiled_element_matches_numpy_element_in_every_flow_quadrant(sincos):
    """Forward, reverse (U_T < 0) and up-through (U_P < 0) flow, stall and pre-stall."""
    rng = np.random.default_rng(3)
    n = 200_000
    UT = rng.uniform(-40, 120, n)
    UP = rng.uniform(-40, 40, n)
    th = rng.uniform(0.05, 0.8, n)
    kre = rng.uniform(0.0, 0.02, n)
    pars = (2 * np.pi, 1.7, 1.8, math.radians(20.6), 50.0, 0.01, sincos)
    qT, qH = np.empty(n), np.empty(n)
    _element_all(UT, UP, th, kre, *pars, qT, qH)
    rT, rH = element(UT, UP, th, np.sin(th), np.cos(th), kre, *pars)
    scale = UT**2 + UP**2
    assert np.max(np.abs(qT - rT) / scale) < 1e-12
    assert np.max(np.abs(qH - rH) / scale) < 1e-12
