"""Audit of the kernels' root solve (core/_annulus.py), the elements' partials (core/_tangents.py) and the
linear inflow's and section parameters' sensitivities (core/_linear_sensitivity.py,
core/_parameter_sensitivity.py): tests that pin what a hand-made mutant of each changed and the
existing tests did not see (a mutation audit, helper)."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core import _annulus
from propmap.core._momentum import momentum_thrust
from propmap.core._physics import NODE_TH, element
from propmap.core.nodes import _nodes
from propmap.core.polar import _model_constants

DISC = pm.Discretization(24, 8)
LOADS = ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "v_i_mean")


def _solve_python(nd, p, om, V, b):
    """The lockstep root solve as plain Python (solve_annuli.py_func: reads _annulus' constants at call time)."""
    nr = nd.y.size
    v, status, mult = np.empty(nr), np.empty((2, nr), np.int64), np.empty(nr, bool)
    sect = np.stack([nd.sc, np.zeros(nr), np.zeros(nr), np.zeros(nr)])
    blade = nd.rows[NODE_TH:NODE_TH + 3]
    _annulus.solve_annuli.py_func(om, V * math.sin(b), V * math.cos(b), nd.rows, blade, np.zeros(nr), sect,
                                  nd.azimuth, np.zeros((2, nr)), nd.sinpsi.size // 2, *_model_constants(p), False, v,
                                  status, mult)
    return v, status[0], status[1]


def test_the_doubling_gives_up_after_exactly_max_doubling_steps(apc8x6, apc_params, monkeypatch):
    """Mutant A4 (``cnt >= MAX_DOUBLING`` -> ``>``: one doubling more than the cap). With a march of one step
    (the root lies about three march steps out) and one doubling allowed, every annulus evaluates F(0), F(h)
    and F(2 h), finds no sign change and gives up (NO_BRACKET, NaN); with three doublings (to F(8 h)) a bracket
    holds the root, which is the march's."""
    nd = _nodes(apc8x6, 6, 8, pm.Air(), apc_params)
    om, V, b = 800.0, 10.0, 1.0
    v_ref, code_ref, _ = _solve_python(nd, apc_params, om, V, b)
    assert np.all(code_ref == _annulus.OK)
    monkeypatch.setattr(_annulus, "MAX_MARCH", 1)
    monkeypatch.setattr(_annulus, "MAX_DOUBLING", 1)
    v, code, nev = _solve_python(nd, apc_params, om, V, b)
    assert np.all(code == _annulus.NO_BRACKET) and np.all(np.isnan(v))
    np.testing.assert_array_equal(nev, 3)
    monkeypatch.setattr(_annulus, "MAX_DOUBLING", 3)
    v, code, nev = _solve_python(nd, apc_params, om, V, b)
    assert np.all(code == _annulus.OK)
    np.testing.assert_allclose(v, v_ref, rtol=0, atol=2e-7 * np.max(np.abs(v_ref)))
    assert np.all(nev >= 4)


def _incidence_difference(prop, params, om, V, b, h):
    a = pm.rotor_loads(prop, params, om, V, b + h, discretization=DISC)
    c = pm.rotor_loads(prop, params, om, V, b - h, discretization=DISC)
    return {q: (float(getattr(a, q)) - float(getattr(c, q))) / (2 * h) for q in LOADS}


@pytest.mark.parametrize("inflow", ["pitt-peters", "drees"])
def test_linear_inflow_incidence_slope_exactly_edgewise_is_the_two_sides_mean(apc8x6, inflow):
    """Mutant L1 (the skew ratio's slope in V cos beta at V cos beta = 0 taken as the climb side's 1 / (Omega R)
    instead of the two sides' mean 0.5 / (Omega R)). Exactly edgewise (beta = pi/2, where lambda = (V cos beta
    + v_u) / (Omega R) in climb and v_u / (Omega R) in descent) the incidence derivative of every load with a
    linear inflow is the central difference of the solver, which averages the two sides' slopes."""
    params = pm.generic_params().replace(inflow=inflow, descent="glauert", inplane_induction=False)
    om, V, b = 800.0, 6.0, math.pi / 2
    r = pm.rotor_loads(apc8x6, params, om, V, b, discretization=DISC, derivatives=True)
    fd = _incidence_difference(apc8x6, params, om, V, b, 1e-4)
    for q in LOADS:
        scale = abs(float(r.v_i_mean)) if q == "v_i_mean" else abs(float(r.thrust if q in ("thrust", "drag",
                                                                                          "side_force") else r.torque))
        err = abs(float(r.derivative(q, "incidence")) - fd[q]) / scale
        assert err < 2e-5, (q, float(r.derivative(q, "incidence")), fd[q])


def _paper_residual(nd, p, om, V, b, j, v):
    """F(v) of annulus j with the paper's section over the half circle (as tests/test_solver_roots.py)."""
    Vs, Vc = V * math.sin(b), V * math.cos(b)
    if abs(Vs) < 1e-12 * max(V, 1e-300):
        Vs = 0.0
    UT = om * nd.y[j] + Vs * nd.sinpsi[None, : nd.sinpsi.size // 2]
    with np.errstate(all="ignore"):
        qT, _ = element(UT, (Vc + v)[:, None], nd.theta[j], nd.sin_th[j], nd.cos_th[j], nd.sc[j], 0.0, 0.0, 0.0,
                        *_model_constants(p))
    return nd.cfac[j] * qT.mean(axis=1) - momentum_thrust(v, nd.mfac[j], Vs, Vc)


def test_a_grazing_fold_in_slow_descent_is_flagged(apc8x6, apc_params):
    """Mutant A12 (GRAZE 0.01 -> 0.001: the march's grazing check only within 0.001 |F(0)| of zero). The paper's
    set in axial descent at 900 rad/s and 4 m/s: annulus 14 (of 48) has three roots, 9.13, 9.82 and 11.94 m/s
    (a dense scan of F); the march (step v_m / 3) steps over the first pair and selects the third, the
    documented gap of the rule (docs/solver.md), and the parabola through the march points, whose minimum lies
    between 0.001 and 0.01 |F(0)| of zero, raises multiple_roots (the extra scan beyond the bracket does not)."""
    om, V, b, j = 900.0, 4.0, math.pi, 14
    r = pm.rotor_loads(apc8x6, apc_params, om, V, b, radial=True)
    nd = _nodes(apc8x6, 48, 16, pm.Air(), apc_params)
    s = np.sign(_paper_residual(nd, apc_params, om, V, b, j, np.array([0.0]))[0])
    grid = np.linspace(0.0, 20.0, 40001) * s
    f = _paper_residual(nd, apc_params, om, V, b, j, grid)
    roots = grid[np.nonzero(np.diff(np.sign(f)))[0]]
    np.testing.assert_allclose(roots, [9.134, 9.824, 11.936], atol=2e-3)
    assert r.v_i[j] == pytest.approx(11.93627, abs=1e-4)  # the third root: the pair stepped over
    assert r.converged and r.multiple_roots


@pytest.mark.parametrize("inflow", ["pitt-peters", "drees"])
def test_linear_inflow_incidence_slope_just_off_axial_flow(apc8x6, inflow):
    """Mutant L4 (the gradients' partial in mu by central differences wherever mu > 0, instead of one-sided
    for mu <= 2e-6, where mu - 1e-6 < 0 and the gradients are 0: half the slope or so). At beta = 1e-7 rad
    (mu ~ 6e-9) the incidence derivative of every load with a linear inflow, the pitching moment (linear in
    k_x) the largest, equals the solver's one-sided second-order differences."""
    params = pm.generic_params().replace(inflow=inflow, descent="glauert", inplane_induction=False)
    om, V, b, h = 800.0, 5.0, 1e-7, 1e-4
    r = pm.rotor_loads(apc8x6, params, om, V, b, discretization=DISC, derivatives=True)
    f0, f1, f2 = (pm.rotor_loads(apc8x6, params, om, V, b + k * h, discretization=DISC) for k in (0, 1, 2))
    assert abs(float(r.derivative("pitching_moment", "incidence"))) > 1e-2 * abs(float(r.torque))
    for q in LOADS:
        fd = (4 * float(getattr(f1, q)) - float(getattr(f2, q)) - 3 * float(getattr(f0, q))) / (2 * h)
        scale = abs(float(r.v_i_mean)) if q == "v_i_mean" else abs(float(r.thrust if q in ("thrust", "drag",
                                                                                          "side_force") else r.torque))
        got = float(r.derivative(q, "incidence"))
        assert abs(got - fd) / scale < 2e-5, (q, got, fd)
