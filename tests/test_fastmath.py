"""The kernel's polynomial atan2 and saturated exp (core/_fastmath.py) against NumPy, and
the compiled blade element built on them against the NumPy element."""

import importlib.util
import math
from pathlib import Path

import numba
import numpy as np
import pytest

from propmap.core import _annulus, _fastmath
import propmap as pm
from propmap.core._physics import element, loss_factor_numpy
from propmap.core.polar import _model_constants

ROOT = Path(__file__).resolve().parents[1]


@numba.njit
def _atan2_all(y, x, out):
    for i in range(y.size):
        out[i] = _annulus._atan2(y[i], x[i])


@numba.njit
def _exp_all(z, out):
    for i in range(z.size):
        out[i] = _annulus._exp_sat(z[i])


@numba.njit
def _exp_wide_all(z, out):
    for i in range(z.size):
        out[i] = _annulus._exp_wide(z[i])


@numba.njit
def _blend_all(z, h, out):
    for i in range(z.size):
        out[i] = _annulus._stall_blend(z[i], h[i])


@numba.njit
def _element_all(UT, UP, th, s0, s1, s2, s3, model, pk, qT, qH):
    for i in range(UT.size):
        qT[i], qH[i] = _annulus._element(UT[i], UP[i], th[i], math.sin(th[i]), math.cos(th[i]), s0[i], s1[i], s2[i],
                                         s3[i], model, pk)


@numba.njit
def _loss_all(UP, wy, ct, ch, out):
    for i in range(UP.size):
        out[i] = _annulus._loss_factor(UP[i], wy[i], ct[i], ch[i])


def atan2_poly(y, x):
    out = np.empty_like(y)
    _atan2_all(y, x, out)
    return out


def test_coefficients_are_the_documented_chebyshev_interpolants():
    spec = importlib.util.spec_from_file_location("fmc", ROOT / "tools" / "fastmath_coefficients.py")
    fmc = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(fmc)
    atan, exp = fmc.coefficients()
    # compared as functions, not coefficient by coefficient: the degree-12 exp interpolant's
    # top coefficients are set by round-off (NumPy 2.4 moves them by 2e-4 relative) while the
    # polynomials agree to ~4e-16 of exp(y) over the whole interval
    t = np.linspace(0.0, 1.0, 20001)
    y = np.linspace(-fmc.EXP_HALF_WIDTH, fmc.EXP_HALF_WIDTH, 20001)
    poly = np.polynomial.polynomial.polyval
    assert len(_fastmath.ATAN) == len(atan) and len(_fastmath.EXP) == len(exp)
    assert np.max(np.abs(poly(t, _fastmath.ATAN) - poly(t, atan))) < 1e-14
    assert np.max(np.abs(poly(y, _fastmath.EXP) - poly(y, exp)) / np.exp(y)) < 1e-14


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


@pytest.mark.parametrize("fill, clip, rel", [(_exp_all, 40.0, 5e-13), (_exp_wide_all, 320.0, 2e-12)],
                         ids=["exp_sat", "exp_wide"])
def test_saturated_exp_is_exp_of_the_clipped_argument(fill, clip, rel):
    """_fastmath.exp_sat (|z| <= 40) and make_exp_wide's (|z| <= 320, exp_sat(z / 8)^8) against np.exp."""
    z = np.concatenate([np.linspace(-1.5 * clip, 1.5 * clip, 240_001), [-clip, clip, 0.0, -1e300, 1e300]])
    out = np.empty_like(z)
    fill(z, out)
    ref = np.exp(np.clip(z, -clip, clip))
    assert np.max(np.abs(out / ref - 1)) <= rel
    assert out[-5] == out[0] and out[-4] == out[-1]  # saturated beyond +-clip
    assert out[-3] == pytest.approx(1.0, rel=1e-13)
    assert np.all(np.isfinite(out)) and np.all(out > 0)


@pytest.mark.parametrize("sharpness, half_width", [((5.0, 12.0, 50.0, 200.0), 0.6), ((500.0, 1000.0), np.pi / 2)],
                         ids=["usual", "M to its bound"])
def test_stall_blend_with_one_exponential_is_eq_3s_sigmoid(sharpness, half_width):
    """_physics.make_stall_blend (compiled and NumPy) against eq (3)'s two exponentials, 1 - 1/((1 + p)(1 + q)),
    p = exp(z - h), q = exp(-z - h) (airfoil.sigmoid_blend, overflow-safe), from attached flow to deep stall, for
    the paper's sharp M = 50 and up to M's bound 1000 (h = M times the half-width to 1571: a first version clipped
    exp(|z|) and exp(-h) at 320 each and gave 1/2 beyond h = 320, a review, 2026-11-27); even in z, 0 at z = 0
    for a wide band, 1 beyond it, no overflow for any h."""
    from propmap.core._physics import stall_blend_numpy
    from propmap.core.airfoil import sigmoid_blend

    rng = np.random.default_rng(13)
    n = 200_000
    M = rng.choice(sharpness, n)
    alpha = rng.uniform(-np.pi, np.pi, n)
    a0 = rng.uniform(0.0, half_width, n)  # half the stall band [rad]
    z, h = M * alpha, M * a0
    ref = sigmoid_blend(alpha, a0, M)
    out = np.empty(n)
    _blend_all(z, h, out)
    assert np.max(np.abs(out - ref)) < 1e-12
    with np.errstate(all="raise"):
        assert np.max(np.abs(stall_blend_numpy(z, h) - ref)) < 1e-13
        np.testing.assert_array_equal(stall_blend_numpy(-z, h), stall_blend_numpy(z, h))
        assert stall_blend_numpy(0.0, 40.0) < 1e-17 and stall_blend_numpy(300.0, 5.0) == 1.0
        assert stall_blend_numpy(-300.0, 5.0) == 1.0 and stall_blend_numpy(1e300, 5.0) == 1.0
        assert stall_blend_numpy(0.0, 2000.0) == 0.0 and stall_blend_numpy(2500.0, 2000.0) == 1.0
        assert stall_blend_numpy(0.0, -400.0) == 1.0  # a band of negative width: stalled everywhere
    assert np.all((out >= 0.0) & (out <= 1.0))


@pytest.mark.parametrize("params", [pm.preset("gill2017-apc").replace(M=1000.0),
                                    pm.CamberedParams(M=1000.0, cl_max=2.0, cl_min=-2.0)], ids=["gill2017", "cambered"])
def test_a_sharp_blend_past_stall_and_its_derivatives(params):
    """M at its bound with a wide stall band (h = M alpha_0 = 360, or M g (a+ - a-) / 2 = 350): at 90 deg the
    section is stalled (lift of the flat plate's cd90 sin a cos a = 0, as eq (3)'s blend -> 1), and the rotor's
    implicit dT/dOmega (whose element partials, core/_tangents.py, take the blend's two exponentials) equals central
    differences of the loads (the one-exponential blend's first version put C_L(90 deg) at 4.2-4.7 and these 16-37%
    apart; a review, 2026-11-27)."""
    assert abs(float(pm.lift_coefficient(np.pi / 2, params))) < 1e-12
    prop = pm.load_propeller("apce_8x6")
    om, V, b = 400.0, 15.0, np.pi / 2
    r = pm.rotor_loads(prop, params, om, V, b, derivatives=True)
    step = 1e-3 * om
    fd = (pm.rotor_loads(prop, params, om + step, V, b).thrust - pm.rotor_loads(prop, params, om - step, V, b).thrust)
    assert r.derivative("thrust", "omega") == pytest.approx(fd / (2 * step), rel=1e-4)


@pytest.mark.parametrize("params", [pm.preset("gill2017-apc").replace(M=50.0),
                                    pm.preset("gill2017-apc").replace(lift_model="sincos"),
                                    pm.CamberedParams()], ids=["gill2017", "sincos", "cambered"])
def test_compiled_element_matches_numpy_element_in_every_flow_quadrant(params):
    """Forward, reverse (U_T < 0) and up-through (U_P < 0) flow, stall and pre-stall."""
    rng = np.random.default_rng(3)
    n = 200_000
    UT = rng.uniform(-40, 120, n)
    UP = rng.uniform(-40, 40, n)
    th = rng.uniform(0.05, 0.8, n)
    s0 = rng.uniform(0.0, 0.02, n) if params.section_model == "gill2017" else rng.uniform(3.0, 7.0, n)
    s1 = rng.uniform(0.5, 2.0, n)
    s2 = rng.uniform(0.5, 2.0, n)
    s3 = rng.uniform(-0.05, 0.05, n)
    model, pk = _model_constants(params)
    qT, qH = np.empty(n), np.empty(n)
    _element_all(UT, UP, th, s0, s1, s2, s3, model, pk, qT, qH)
    rT, rH = element(UT, UP, th, np.sin(th), np.cos(th), s0, s1, s2, s3, model, pk)
    scale = UT**2 + UP**2
    assert np.max(np.abs(qT - rT) / scale) < 1e-12
    assert np.max(np.abs(qH - rH) / scale) < 1e-12


def test_compiled_loss_factor_matches_numpy_and_its_limits():
    """Prandtl's F: compiled vs NumPy; F -> 1 far from the tip, -> 0 at the tip."""
    rng = np.random.default_rng(5)
    n = 100_000
    UP = rng.uniform(-30, 30, n)
    wy = rng.uniform(1, 200, n)
    ct = rng.uniform(-1, 20, n)
    ch = rng.uniform(-1, 5, n)
    out = np.empty(n)
    _loss_all(UP, wy, ct, ch, out)
    # acos(x) has slope -1/sqrt(1 - x^2): near the tip (x -> 1) it amplifies exp_sat's
    # 5e-13 relative error, so agreement is ~5e-12 there and ~1e-16 elsewhere
    np.testing.assert_allclose(out, loss_factor_numpy(UP, wy, ct, ch), rtol=0, atol=2e-11)
    assert np.all((out >= 0) & (out <= 1))
    # limits: c = (N_b/2)(R - y)/y -> 0 at the tip gives F -> 0; far inboard F = 1 to double precision
    up, w = np.full(4, 5.0), np.full(4, 100.0)
    F = loss_factor_numpy(up, w, np.array([0.0, 1e-6, 0.2, 50.0]), -1.0)  # f = 0, 2e-5, 4, 1000
    assert F[0] == 0.0 and F[1] < 0.01 and 0.0 < F[2] < 1.0 and F[3] == 1.0
    # closed form (2/pi) acos(exp(-f)), f = c |U_P|^-1 sqrt(U_P^2 + (Omega y)^2)
    f = 0.3 * np.hypot(5.0, 100.0) / 5.0
    assert loss_factor_numpy(5.0, 100.0, 0.3, -1.0) == pytest.approx(2 / np.pi * np.arccos(np.exp(-f)), rel=1e-13)
    # no axial flow through the disk (U_P = 0): no loss
    assert loss_factor_numpy(0.0, 100.0, 0.3, 0.3) == 1.0
