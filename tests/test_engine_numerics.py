"""The fitting engine's own numerics: its finite-difference Jacobian and its multistart rule.

Every fit whose residual has no implicit derivatives (identify/optimizer._solve without
``residual.jacobian``) steps with ``_jacobian``: central differences of step
1e-4 max(|x|, 0.1), one-sided at a bound. And a multistart fit whose two best optima reach
the same cost with parameters 5% apart warns that the data do not determine them. No test
held either (a mutation audit, 2026-11-27, left the Jacobian's step and the multistart
thresholds without a test; each of seven mutants of them fails the tests here). Analytic
residuals, so every expected value is exact.
"""

import math

import numpy as np
import pytest

from propmap.identify import FitOptions
from propmap.identify.optimizer import _bounds, _jacobian, _solve


def _recording(f):
    seen = []

    def residual(x):
        seen.append(np.array(x, float))
        return f(np.asarray(x, float))

    return residual, seen


def _smooth(x):
    return np.array([math.exp(x[0]), x[0] * x[1], math.sin(x[1]), 1e-3 * x[0] + x[0] ** 3])


def _exact(x):
    return np.array([[math.exp(x[0]), 0.0], [x[1], x[0]], [0.0, math.cos(x[1])], [1e-3 + 3 * x[0] ** 2, 0.0]])


def test_central_differences_inside_the_bounds():
    x = np.array([0.3, -2.0])
    J = _jacobian(_smooth, x, np.array([-1.0, -5.0]), np.array([1.0, 5.0]))
    # central differences: error h^2 f''' / 6 with h = 1e-4 max(|x|, 0.1), below 1e-8 here
    np.testing.assert_allclose(J, _exact(x), rtol=0, atol=1e-8)


def test_a_parameter_at_zero_still_gets_a_step():
    # the step's floor 0.1 max(|x|, 0.1): a purely relative step would be 0 at x = 0 (the paper's
    # start c_d = 0) and give a derivative of round-off or a division by zero
    x = np.array([0.0, 1.0])
    J = _jacobian(_smooth, x, np.array([-1.0, -5.0]), np.array([1.0, 5.0]))
    assert J[3, 0] == pytest.approx(1e-3, rel=1e-6)  # d(1e-3 x + x^3)/dx at 0, the x^3 part h^2 = 1e-10
    assert np.all(np.isfinite(J))


@pytest.mark.parametrize("side", ["upper", "lower"])
def test_one_sided_at_a_bound_and_never_outside(side):
    x = np.array([0.5, -2.0])
    lb, ub = np.array([-1.0, -5.0]), np.array([1.0, 5.0])
    if side == "upper":
        ub[0] = x[0]
    else:
        lb[0] = x[0]
    residual, seen = _recording(_smooth)
    J = _jacobian(residual, x, lb, ub)
    pts = np.array(seen)
    assert np.all(pts >= lb) and np.all(pts <= ub)  # a model outside its bounds may not even run
    # one-sided in x0: error h f'' / 2 with h = 5e-5, about 1e-4 relative (the x^3 row's 0.999e-4); x1 central
    np.testing.assert_allclose(J[:, 0], _exact(x)[:, 0], rtol=2e-4, atol=1e-12)
    np.testing.assert_allclose(J[:, 1], _exact(x)[:, 1], rtol=0, atol=1e-8)


def _fit(f, names, multistart=1, seed=1):
    # multistart 1, seed 1: the starts are the bounds' mid-point 5.5 and one Sobol point, 3.09
    options = FitOptions(names=names, multistart=multistart, seed=seed, prior=False)
    lb, ub = _bounds(names, options)
    best, log, nfev, _, warns = _solve(f, names, options, "test", 0.5 * (lb + ub))
    return best, log, warns


def test_two_optima_of_equal_cost_are_warned_of():
    # cl_alpha in [2, 9]: r = (x - 3)(x - 7) is 0 at 3 and at 7, both reachable from the starts
    best, log, warns = _fit(lambda x: np.array([(x[0] - 3.0) * (x[0] - 7.0)]), ("cl_alpha",))
    ends = sorted({round(float(e["x"][0]), 6) for e in log if e["stage"] == "polish"})
    assert ends == [3.0, 7.0]  # the two polished optima are the two roots
    assert len(warns) == 1 and "two multistart optima reach the same residual" in warns[0]
    assert "different cl_alpha" in warns[0]


@pytest.mark.parametrize("roots, warned", [((4.0, 5.0), True), ((4.0, 4.1), False)])
def test_equal_cost_optima_are_warned_of_from_5_percent_apart(roots, warned):
    # DIFFERENT_X_RTOL: optima 25% apart differ, 2.5% apart are one (the starts 5.5 and 3.09 reach one root each)
    a, b = roots
    best, log, warns = _fit(lambda x: np.array([(x[0] - a) * (x[0] - b)]), ("cl_alpha",))
    ends = sorted(round(float(e["x"][0]), 6) for e in log if e["stage"] == "polish")
    assert ends == [a, b]
    assert bool(warns) == warned


def test_one_optimum_is_not_warned_of():
    best, log, warns = _fit(lambda x: np.array([x[0] - 4.0, 0.1 * (x[0] - 4.0) ** 2]), ("cl_alpha",), 8, 0)
    assert best.x[0] == pytest.approx(4.0, abs=1e-8) and warns == []


def test_optima_of_different_cost_are_not_warned_of():
    # two minima, at 3 (cost 0.5, the constant residual's) and near 7 (cost 0.531, 6% more,
    # beyond the rule's 1%): the better one wins, no warning
    best, log, warns = _fit(lambda x: np.array([(x[0] - 3.0) * (x[0] - 7.0), 0.25 * (x[0] - 3.0) / 4.0, 1.0]),
                            ("cl_alpha",))
    polished = sorted((float(e["x"][0]), e["cost"]) for e in log if e["stage"] == "polish")
    assert polished[0][0] == pytest.approx(3.0, abs=1e-6) and polished[1][0] == pytest.approx(7.0, abs=0.1)
    assert 1.02 < polished[1][1] / polished[0][1] < 1.1  # the branch is exercised: two optima, 6% apart
    assert best.x[0] == pytest.approx(3.0, abs=1e-6) and warns == []


def _model(own: bool):
    """_smooth as a model that records its calls; with its exact Jacobian (``jacobian`` and
    ``with_jacobian``, as engine._attach_jacobian gives) where ``own``."""
    residual, seen = _recording(_smooth)
    if own:
        def with_jacobian(x):
            seen.append(np.array(x, float))
            return _smooth(x), _exact(x)

        residual.jacobian = lambda x: with_jacobian(x)[1]
        residual.with_jacobian = with_jacobian
    return residual, seen


@pytest.mark.parametrize("own", [True, False])
def test_counted_residual_counts_each_model_call(own):
    # the rule of every fit's nfev: a residual 1 call, the model's own Jacobian or residual with it 1,
    # a differenced Jacobian 2 per parameter; ``n`` equals the calls the model saw
    from propmap.identify.optimizer import CountedResidual

    lb, ub = np.array([-1.0, -5.0]), np.array([1.0, 5.0])
    x = np.array([0.3, -2.0])
    residual, seen = _model(own)
    ticks = []
    model = CountedResidual(residual, lb, ub, on_call=ticks.append)
    assert model.paired == own
    np.testing.assert_array_equal(model(x), _smooth(x))
    assert model.n == 1
    J = model.jacobian(x)
    assert model.n == (2 if own else 1 + 2 * x.size)
    np.testing.assert_allclose(J, _exact(x), rtol=0, atol=0 if own else 1e-8)
    before = model.n
    r, J = model.with_jacobian(x)
    assert model.n - before == (1 if own else 1 + 2 * x.size)
    np.testing.assert_array_equal(r, _smooth(x))
    assert model.n == len(seen) == sum(ticks)
    if not own:  # the differences' steps stay within the bounds
        assert np.all(np.array(seen) >= lb) and np.all(np.array(seen) <= ub)
