"""A mutation audit of identify/engine.py, export_c.py and io/calibration.py (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed (103 mutants,
38 / 35 / 30; 58 survived those files, 50 of them are killed here, the other 8 are equivalent: two refusals no
public call reaches, an optimum exactly on a bound, a diameter a RotorMap always has, three branches the shipped
calibration file never takes, a fold loop's break once each name has one fold). Analytic residuals, maps of 2-3
nodes an axis and the shipped calibration: every expected value is exact or documented."""

import math

import numpy as np
import pytest

from propmap.identify import FitOptions
from propmap.identify.engine import _x0
from propmap.identify.optimizer import _bounds, _jacobian, _solve
from propmap.identify.options import FLAP_START
from propmap.io.calibration import generic_params


# ---------------------------------------------------------------- identify/engine.py


def test_the_jacobians_step_at_zero_is_the_floors_1e_5():
    # docs/identification.md: central differences with step 1e-4 max(|x_k|, 0.1): at x = 0 the
    # points are +-1e-5 (a floor of 1e-9 gives +-1e-13, a derivative of exp(x) off by 1e-3)
    seen = []

    def residual(x):
        seen.append(np.array(x, float))
        return np.array([math.exp(x[0])])

    J = _jacobian(residual, np.array([0.0]), np.array([-1.0]), np.array([1.0]))
    assert sorted(float(p[0]) for p in seen) == pytest.approx([-1e-5, 1e-5], rel=1e-12)
    assert J[0, 0] == pytest.approx(1.0, abs=1e-9)


def test_screening_gives_each_start_12_evaluations_and_polishes_the_two_best():
    # docs/identification.md, Global stage: N Sobol starts, 12 evaluations each, the two best polished.
    # A narrow valley (Rosenbrock's, in cl_alpha [2, 9] and cd_min [0, 0.05]) needs more than 12 from most starts
    names = ("cl_alpha", "cd_min")
    options = FitOptions(names=names, multistart=4, seed=0, prior=False)
    lb, ub = _bounds(names, options)

    def residual(x):
        u, v = (x[0] - 2.0) / 7.0, x[1] / 0.05
        return np.array([30.0 * (v - u * u), 1.0 - u - 0.5])

    best, log, nfev, _, _ = _solve(residual, names, options, "test", 0.5 * (lb + ub))
    screen = [e for e in log if e["stage"] == "screen"]
    polish = [e for e in log if e["stage"] == "polish"]
    assert len(screen) == 5 and len(polish) == 2
    assert max(e["nfev"] for e in screen) == 12 and all(e["nfev"] <= 12 for e in screen)
    assert best.x[0] == pytest.approx(2.0 + 3.5, abs=1e-6)
    # FitOptions.multistart: that many extra starts, whether a power of 2 or not (Sobol' points come in
    # powers of 2: 5 starts are the first 5 of 8)
    log = _solve(residual, names, FitOptions(names=names, multistart=5, seed=0, prior=False), "test",
                 0.5 * (lb + ub))[1]
    assert len([e for e in log if e["stage"] == "screen"]) == 6


def test_the_start_of_the_flap_compliance_and_a_fits_own_terms():
    # _x0: the flap compliance at the base's value, or FLAP_START where that is 0 (its
    # derivatives vanish at 0); a fit's own terms (overrides) before everything else
    base = generic_params()
    options = FitOptions(prior=False)
    names = ("cl_alpha", "flap_compliance")
    assert base.flap_compliance == 0.0
    assert _x0(names, options, base).tolist() == [base.cl_alpha, FLAP_START]
    flapping = base.replace(flap_compliance=2.5)
    assert _x0(names, options, flapping).tolist() == [base.cl_alpha, 2.5]
    assert _x0(names, options, base, {"cl_alpha": 6.25}).tolist() == [6.25, FLAP_START]
    assert _x0(("drag_area_x",), options, base, {"drag_area_x": 0.004}).tolist() == [0.004]


def test_optima_apart_by_less_than_5_percent_of_a_natural_scale_are_one():
    # docs/identification.md: "parameters more than 5% apart", of max(|estimate|, its natural scale)
    # (re_exp_lift's 0.1): -0.002 and 0.002 are 4% of it apart, not 200% of the estimate
    names = ("re_exp_lift",)
    options = FitOptions(names=names, multistart=1, seed=1, prior=False)
    lb, ub = _bounds(names, options)
    best, log, _, _, warns = _solve(lambda x: np.array([(x[0] + 0.002) * (x[0] - 0.002)]), names, options, "test",
                                    0.5 * (lb + ub))
    ends = sorted(float(e["x"][0]) for e in log if e["stage"] == "polish")
    assert ends == pytest.approx([-0.002, 0.002], abs=2e-5)  # the branch is reached: two optima of cost ~0
    assert warns == []


def _finished(x, jac, residuals, names=("cd_min", "cl_alpha"), status=2):
    """engine._finish of a fit that ended at ``x`` with this Jacobian and these residuals."""
    from scipy.optimize import OptimizeResult

    from propmap.core.airfoil import Air
    from propmap.identify.engine import _finish

    best = OptimizeResult(x=np.asarray(x, float), fun=np.asarray(residuals, float), jac=np.asarray(jac, float),
                          status=status, success=status > 0, message="test")
    options = FitOptions(names=names, prior=False)
    return _finish(names, generic_params(), options, best, [], 10, 0.0, [], len(residuals), Air(), {})


def test_a_parameter_1e_4_of_its_range_from_a_bound_is_not_at_it_and_intervals_are_cut_at_the_bounds():
    # _finish: "at a bound" within 1e-6 of the bounds' span; every 95% interval is cut at its parameter's
    # bounds, and the cut ends marked (docs/identification.md: ci95_cut_at_bound)
    lo, hi = 0.002, 0.2
    jac = np.array([[1.0, 0.0], [0.0, 1.0], [1.0, 1.0], [0.5, -1.0]])
    res = np.array([0.01, -0.01, 0.02, -0.02])
    near = lo + 1e-4 * (hi - lo)
    r = _finished([near, 5.0], jac, res)
    assert r.at_bound == () and r.warnings == ()
    ci = np.asarray(r.identifiability.ci95)
    assert ci[0, 0] == lo and ci[0, 1] > near  # the linearised interval, about +-0.03, cut at cd_min's 0.002
    assert np.asarray(r.identifiability.ci95_cut).tolist() == [[True, False], [False, False]]
    r = _finished([lo + 1e-7 * (hi - lo), 5.0], jac, res)
    assert r.at_bound == ("cd_min",) and "cd_min ended at its lower bound 0.002" in r.warnings[0]


def test_the_bound_and_evaluation_limit_warnings_of_a_fit():
    # docs/identification.md: an angle at a bound is named with the bound in degrees; a fit that stopped at
    # its evaluation limit says so in the first warning (status 0 of least squares), one that converged not
    jac = np.array([[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    res = np.array([0.01, -0.01, 0.02])
    top = math.radians(5.0)  # alpha_L0's upper bound
    r = _finished([top, 5.0], jac, res, names=("alpha_L0", "cl_alpha"), status=0)
    assert r.hit_max_nfev and r.at_bound == ("alpha_L0",)
    limit = FitOptions().max_nfev
    assert r.warnings[0] == (f"the fit stopped at its evaluation limit ({limit}) before converging: its parameters "
                             "are where it stopped, not an optimum")
    assert r.warnings[1].startswith("alpha_L0 ended at its upper bound 5 deg: the data pull it beyond")
    r = _finished([top, 5.0], jac, res, names=("alpha_L0", "cl_alpha"), status=1)
    assert not r.hit_max_nfev and len(r.warnings) == 1


def test_under_the_prior_the_report_is_the_datas_and_the_objective_is_both_costs():
    # _finish: with the population prior, residuals and cost are the data's alone, the prior's pseudo-residuals
    # and cost go to extra["prior"]; _objective: the objective the fit minimised, 0.5 |all residuals|^2
    from scipy.optimize import OptimizeResult

    from propmap.core.airfoil import Air
    from propmap.identify.engine import _finish, _objective

    names = ("cl_alpha", "cd2")
    data_jac = np.array([[1.0, 0.5], [0.2, 1.0], [1.0, -1.0], [0.3, 0.3]])
    fun = np.array([0.01, -0.02, 0.015, 0.005, 0.3, -0.4])  # 4 data rows, 2 prior rows
    jac = np.vstack([data_jac, 0.02 * np.eye(2)])
    best = OptimizeResult(x=np.array([5.0, 0.1]), fun=fun, jac=jac, status=2, success=True, message="test")
    extra = {"prior": {"names": list(names), "sigma_data": 0.02, "scale": 1.0}}
    r = _finish(names, generic_params(), FitOptions(names=names), best, [], 10, 0.0, [], 4, Air(), extra)
    assert r.residuals.tolist() == fun[:4].tolist() and r.cost == pytest.approx(0.5 * fun[:4] @ fun[:4], rel=1e-15)
    assert r.extra["prior"]["pseudo_residuals"] == [0.3, -0.4]
    assert r.extra["prior"]["cost"] == pytest.approx(0.125, rel=1e-15)
    assert _objective(r) == pytest.approx(0.5 * fun @ fun, rel=1e-15)


def test_directions_the_data_know_1e_12_as_well_as_the_first_are_not_fitted():
    # _fit_along_directions: not beyond the directions the data know at all, eigenvalues above 1e-9 of the
    # largest (the data against the prior); a second direction at 1e-12 of the first is held, and said so
    from propmap.identify.engine import _fit_along_directions, _prior_stats

    base = generic_params()
    names = ("cl_alpha", "cd2")
    options = FitOptions(names=names)
    _, mu, chol, pop = _prior_stats(names, base, options)
    w = float(pop["sigma_data"])
    jac = np.vstack([np.diag([1e3 * w, 1e-3 * w]) @ np.linalg.inv(chol), np.zeros((1, 2))])  # lambda 1e6, 1e-6
    x_true = mu + chol @ np.array([0.5, 0.0])

    def make_data(opts):
        return lambda x, opts=opts: jac @ (np.asarray(x, float) - x_true)

    best, _, _, _, warns, extra = _fit_along_directions(make_data, names, base, options, 2)
    assert extra["directions"]["eigenvalues"] == pytest.approx([1e6, 1e-6], rel=1e-6)
    assert extra["directions"]["count"] == 1
    assert warns == ["1 parameter direction(s) fitted, not 2: the data have no information on the others "
                     "(eigenvalues 1e-06 of the data against the prior)"]


def test_a_direction_the_data_know_less_well_than_the_prior_is_named():
    # _directions_report: a direction whose data-only std error is 1 prior standard deviation or more is
    # named in the warnings ("fewer directions would do"); one at 0.1 is not. Data J L = diag(0.1, 0.00667)
    # and two rows of pure noise 0.01: data-only std errors 0.01 / s_i, 0.1 and 1.5
    from propmap.core.airfoil import Air
    from propmap.identify.engine import _directions_report, _finish, _fit_along_directions, _prior_stats, _with_prior

    base = generic_params()
    names = ("cl_alpha", "cd2")
    options = FitOptions(names=names)
    _, mu, chol, _ = _prior_stats(names, base, options)
    jac = np.vstack([np.diag([0.1, 0.01 / 1.5]) @ np.linalg.inv(chol), np.zeros((2, 2))])
    noise = np.array([0.0, 0.0, 0.01, -0.01])

    def make_data(opts):
        return lambda x, opts=opts: jac @ (np.asarray(x, float) - mu) + noise

    prior = _with_prior(make_data, names, base, options)[1]
    best, log, nfev, elapsed, warns, extra = _fit_along_directions(make_data, names, base, options, 2)
    assert extra.pop("outside") == []
    result = _finish(names, base, options, best, log, nfev, elapsed, warns, 4, Air(), {**extra, "prior": prior})
    report = _directions_report(result, options)
    assert report.extra["directions"]["std_error_data_only"] == pytest.approx([0.1, 1.5], rel=1e-6)
    assert [w.split(" is determined")[0] for w in report.identifiability.warnings] == ["direction_2"]


def _saturating_fit(scale, k_true=3.0):
    """A fit of cl_alpha and a flap compliance k whose effect saturates, scale k / (1 + k), 12 points with noise
    0.002: (result, residual, options, profile rise of k, the 95% edge of the rise)."""
    from scipy import stats

    from propmap.core.airfoil import Air
    from propmap.identify.engine import _finish

    t = np.linspace(0.0, 1.0, 12)
    u, b = 1.0 + t, scale * np.cos(3.0 * t)
    y = 5.0 * u + b * k_true / (1.0 + k_true) + 0.002 * np.sin(7.3 * np.arange(12))

    def residual(x):
        return x[0] * u + b * x[1] / (1.0 + x[1]) - y

    names = ("cl_alpha", "flap_compliance")
    options = FitOptions(names=names, prior=False)
    best, log, nfev, elapsed, warns = _solve(residual, names, options, "test", np.array([5.0, 1.0]))
    result = _finish(names, generic_params(), options, best, log, nfev, elapsed, warns, 12, Air(), {})

    def rise(k):  # the profile: cl_alpha refitted in closed form (linear least squares) with k held
        r0 = b * k / (1.0 + k) - y
        r = r0 - u * (u @ r0) / (u @ u)
        return 0.5 * r @ r - result.cost

    s2 = float(result.residuals @ result.residuals) / (12 - 2)
    return result, residual, options, rise, 0.5 * stats.t.ppf(0.975, 12 - 2) ** 2 * s2


def test_a_saturating_flap_compliance_gets_its_upper_limit_from_the_profile_likelihood():
    # _flap_saturation (docs/identification.md): where the profile's rise at the linearised upper limit is below
    # the 95% edge, (t_0.975)^2 / 2 residual variances, five geometric bisections between it and the bound
    # place the limit: within (bound / linear)^(1/32) of where the rise crosses the edge; where the rise at the
    # bound itself is below the edge, the limit is the bound, marked as a cut end
    from propmap.identify.engine import _flap_saturation

    result, residual, options, rise, edge = _saturating_fit(0.01)
    linear = float(result.identifiability.ci95[1][1])
    out = _flap_saturation(result, residual, options)
    limit = float(out.identifiability.ci95[1][1])
    assert rise(linear) < edge <= rise(limit) and limit < 50.0
    assert rise(limit / (50.0 / linear) ** (1 / 32)) < edge
    assert not out.identifiability.ci95_cut[1][1] and "by the profile likelihood" in out.warnings[-1]
    result, residual, options, rise, edge = _saturating_fit(0.004)
    assert rise(50.0) < edge
    out = _flap_saturation(result, residual, options)
    assert float(out.identifiability.ci95[1][1]) == 50.0 and out.identifiability.ci95_cut[1][1]
    assert "the data hardly tell" in out.warnings[-1]
    # a compliance held at 0 (the data show none of the effect) has no interval, and the profile is not run
    result, residual, options, rise, edge = _saturating_fit(0.0015, k_true=-0.95)  # (pulled below 0)
    assert result.at_bound == ("flap_compliance",) and rise(50.0) < edge
    out = _flap_saturation(result, residual, options)
    assert not np.isfinite(out.identifiability.ci95[1]).any() and out.warnings == result.warnings


# ---------------------------------------------------------------- export_c.py

RPM = 2 * math.pi / 60


def _tiny_map(omega_rpm, airspeed, incidence_deg):
    import propmap as pm
    from propmap.maps import RotorMap, build_map

    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.asarray(omega_rpm, float) * RPM, np.asarray(airspeed, float),
                   np.radians(incidence_deg), air=params.air, params_label=params.label, n_check=0)
    return RotorMap(ds)


@pytest.fixture(scope="module")
def jittered():
    """A 3 x 3 x 3 map whose rpm axis is geometric but for 1e-4 of its log step, and whose airspeed
    axis is uniform but for 2e-6 of its step; its incidence axis is uniform."""
    return _tiny_map([3000.0, 5000.0, 5000.0 * (5 / 3) ** 1.0001], [0.0, 5.0, 10.00001], [0.0, 90.0, 180.0])


def test_an_axis_found_by_arithmetic_only_where_its_steps_are_equal_to_1e_9(jittered):
    # _inverse_step: 1 / the step of a uniform axis, -1 / log of the ratio of a geometric one, each
    # "equal to 1e-9 relative"; another axis's cells are found by bisection (0.0): an axis that is
    # nearly uniform or nearly geometric is neither (its cell by arithmetic could be off by more
    # than the one correction where it is long)
    from propmap.export_c import c_header_text

    text = c_header_text(jittered, "m.h")
    macros = dict(line.split()[1:3] for line in text.splitlines() if line.startswith("#define PM_M_U"))
    assert macros["PM_M_U0"] == "0.0" and macros["PM_M_U1"] == "0.0"
    assert float(macros["PM_M_U2"]) == pytest.approx(1 / math.radians(90.0), rel=1e-15)
    exact = _tiny_map([3000.0, 5000.0, 5000.0 * 5 / 3], [0.0, 5.0, 10.0], [0.0, 90.0, 180.0])
    macros = dict(line.split()[1:3] for line in c_header_text(exact, "m.h").splitlines()
                  if line.startswith("#define PM_M_U"))
    assert float(macros["PM_M_U0"]) == pytest.approx(-1 / math.log(5 / 3), rel=1e-12)
    assert float(macros["PM_M_U1"]) == pytest.approx(0.2, rel=1e-15)


def test_a_map_with_a_side_force_is_warned_of_and_says_so_in_its_header():
    # c_header_text, Warns: a map that holds the side force and the pitching moment (RotorMap.side_loads):
    # the header's functions give T, D, Q and M_R and leave them out (said in the header too)
    import propmap as pm
    from propmap.export_c import c_header_text
    from propmap.maps import RotorMap, build_map

    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6").replace(flap_compliance=1.0)
    rm = RotorMap(build_map(prop, params, np.array([4000.0, 6000.0]) * RPM, np.array([0.0, 5.0]),
                            np.radians([0.0, 90.0, 180.0]), air=params.air, params_label="flapping", n_check=0))
    assert rm.side_loads
    with pytest.warns(UserWarning, match="the C header's loads and wrench leave them out"):
        text = c_header_text(rm, "m.h")
    assert "makes a side force Y and a pitching moment M_P" in " ".join(text.split())


def test_the_c_prefix_from_a_file_name_is_lower_case_and_a_given_one_is_checked():
    # c_prefix: pm_<file stem> in lower case, its non-word characters as underscores; a given name is kept as
    # given, refused empty or where it is not a C identifier
    from propmap.export_c import c_prefix

    assert c_prefix("out/My-Map 2.h") == "pm_my_map_2"
    assert c_prefix("x.h", "Rotor_A") == "Rotor_A"
    with pytest.raises(ValueError, match="the C name prefix is empty"):
        c_prefix("m.h", "")
    with pytest.raises(ValueError, match=r"must be a C identifier \(ASCII letters, digits, underscores\), got '9x'"):
        c_prefix("m.h", "9x")
    with pytest.raises(ValueError, match=r"would define ERR_CLIP, ERR_NAN, ERR_ERROR, \.\.\.: names reserved by "
                                         r"<errno\.h>"):
        c_prefix("m.h", "err")  # (E followed by an uppercase letter)


def test_text_from_a_maps_attributes_is_one_line_inside_the_headers_comment():
    # _comment: one line, and no "*/" that would end the comment
    from propmap.export_c import _comment

    assert _comment("apce_8x6\n#define X 1 */ int y;\r\n  end") == "apce_8x6 #define X 1 * / int y; end"


# ---------------------------------------------------------------- io/calibration.py


def test_the_population_without_a_propeller_is_the_fold_of_its_generic_set():
    # population(without=name): the statistics of the fold that excludes name's family, the fold whose set
    # generic_without(name) gives; a propeller outside the calibration (in no fold) gets the full statistics,
    # as generic_without gives it the full generic set (it got the first fold's, without the apc29ff family)
    from propmap.io.calibration import _raw, generic_without, population

    folds = _raw()["generic_folds"]
    params, label = generic_without("apce_10x7")
    fold = next(f for f in folds if f["label"] == label)
    assert label == "generic without apce" and "apce_10x7" not in fold["propellers"]
    np.testing.assert_array_equal(population(without="apce_10x7")["covariance"], fold["population"]["covariance"])
    assert population(without="apce_10x7")["sigma_data"] == fold["population"]["sigma_data"]
    assert generic_without("my_own_prop")[1] == "generic"
    full, outside = population(), population(without="my_own_prop")
    np.testing.assert_array_equal(outside["covariance"], full["covariance"])
    assert (outside["sigma_data"], outside["source"]) == (full["sigma_data"], full["source"])


def test_the_headers_comment_gives_the_grid_in_rpm_and_degrees_and_the_checked_errors_in_percent():
    # TEMPLATE's comment: the grid's ends in rpm, m/s and deg, the off-grid check's errors as percentages
    # (n/a and 0 points where there was no check)
    from propmap.export_c import c_header_text

    rm = _tiny_map([3000.0, 4000.0, 6000.0], [0.0, 5.0, 10.0], [30.0, 105.0, 180.0])
    text = " ".join(c_header_text(rm, "m.h").replace("\n *", " ").split())  # (the comment's lines as one)
    assert ("Grid: 3 rpm (3000-6000 rpm) x 3 airspeed (0-10 m/s) x 3 incidence (30-180 deg); table in float; "
            "cubic interpolation.") in text
    assert ("T n/a of static thrust, Q n/a of static torque, D n/a of the largest drag (max over 0 random "
            "points)") in text
    import propmap as pm
    from propmap.maps import RotorMap, build_map

    params = pm.default_params("apce_8x6")
    checked = RotorMap(build_map(pm.load_propeller("apce_8x6"), params, np.array([3000.0, 6000.0]) * RPM,
                                 np.array([0.0, 10.0]), np.radians([0.0, 90.0, 180.0]), air=params.air,
                                 params_label=params.label, n_check=4), "linear")
    a = checked.attrs
    text = " ".join(c_header_text(checked, "m.h").replace("\n *", " ").split())
    assert (f"T {a['check_linear_thrust_max']:.3%} of static thrust, Q {a['check_linear_torque_max']:.3%} of static "
            f"torque, D {a['check_linear_drag_max']:.3%} of the largest drag (max over 4 random points)") in text


def test_coverage_of_the_shipped_sets():
    # coverage: a generic set's (the full one, a fold's) is the generic's record; a calibrated set's adds its
    # propeller's UIUC rates, its static runs' and its sweeps' nominal ones; None for another label
    from propmap.io.calibration import _raw, coverage
    from propmap.io.catalogue import catalogue

    raw = _raw()
    generic = raw["generic"]["coverage"]
    assert coverage("generic") == generic and coverage("generic without apce") == generic
    assert coverage("generic fold 3") == generic
    entry = catalogue()["apce_8x6"]
    static = [float(r) for run in entry.static_runs() for r in run.rpm]
    sweeps = [float(sw.rpm) for sw in entry.sweeps()]
    assert static and sweeps and max(sweeps) > max(static)  # (both ends are decided by the sweeps)
    rates = static + sweeps
    assert coverage("calibrated:apce_8x6") == {**raw["propellers"]["apce_8x6"]["coverage"], "rpm_min": min(rates),
                                               "rpm_max": max(rates)}
    assert coverage("table_i") is None and coverage("calibrated:no_such_prop") is None


def test_parameter_sets_in_si_round_trip_and_a_bad_one_is_named():
    # params_to_si / params_from_si: exact inverses; section_model default gill2017; air and label ignored;
    # an unknown model refused; the shipped sets carry their names and their fits' figures
    from propmap.core.airfoil import AirfoilParams
    from propmap.io.calibration import _entry, _raw, calibrated, params_from_si, params_to_si

    cambered = calibrated("apce_8x6").params
    assert params_from_si(params_to_si(cambered)) == cambered.replace(label="")
    paper = AirfoilParams(cl1=5.0, cl2=2.0, cd=0.5, alpha0=0.3)
    d = params_to_si(paper)
    assert d["section_model"] == "gill2017"
    d.pop("section_model")
    assert params_from_si({**d, "label": "x", "air": None}) == paper
    with pytest.raises(ValueError, match="unknown section_model 'nope'"):
        params_from_si({"section_model": "nope"})
    with pytest.raises(ValueError, match=r"calibration.json \[broken\]: "):
        _entry("broken", {"params": {"section_model": "cambered", "no_such_field": 1.0}, "rms_ct": 0.1, "rms_cp": 0.1,
                          "n_points": 3}, "test")
    raw = _raw()["propellers"]["apce_8x6"]
    c = calibrated("apce_8x6")
    assert (c.name, c.params.label) == ("calibrated:apce_8x6", "calibrated:apce_8x6")
    assert (c.rms_ct, c.rms_cp, c.n_points) == (raw["rms_ct"], raw["rms_cp"], raw["n_points"])
    assert raw["rms_ct"] != raw["rms_cp"]


def test_default_params_of_names():
    # default_params: the calibrated set of a catalogue propeller with data, else the generic set; a
    # catalogue name without data quietly, a near name with a warning naming it; not a str or blank refused
    import warnings

    from propmap.io.calibration import default_params

    assert default_params("apce_8x6").label == "calibrated:apce_8x6"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert default_params("cfnq_45p1").label == "generic"  # (in the catalogue, no measurements)
        assert default_params("my_own_prop").label == "generic"
    with pytest.warns(UserWarning, match=r"'apce_8x66' is not a catalogue propeller, so this is the generic set; "
                                         r"did you mean .*apce_8x6"):
        assert default_params("apce_8x66").label == "generic"
    with pytest.raises(TypeError, match=r"name must be a propeller's name \(str\), got int"):
        default_params(5)
    with pytest.raises(ValueError, match="name must be a propeller's name, got an empty one"):
        default_params("  ")


def test_a_vehicle_rotor_with_its_own_parameter_set_is_refused_by_the_header():
    # c_header_text, Raises: a vehicle rotor with its own parameter set (a header holds one map)
    from dataclasses import replace
    from pathlib import Path

    import propmap as pm
    from propmap.export_c import c_header_text
    from propmap.maps import build_map

    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml")
    g = generic_params()
    rm = pm.RotorMap(build_map(veh.rotors[0].propeller, g, np.array([900.0, 1500.0]), np.array([0.0, 10.0]),
                               np.radians([0.0, 90.0, 180.0]), n_check=0))
    # (a set other than the map's: the map's own set on a rotor is taken since 2026-12-01, stop 96)
    own = replace(veh, rotors=(veh.rotors[0], replace(veh.rotors[1], params=g.replace(cl_alpha=0.5 * g.cl_alpha)),
                               *veh.rotors[2:]))
    with pytest.raises(ValueError, match="rotor 2 has its own parameter set: a C header holds one map"):
        c_header_text(rm, "x.h", vehicle=own)
    # and the rotors' interference, which a map cannot hold, is said to be left out
    with pytest.warns(UserWarning, match=r"the rotors' interference \(factor 0.5\) is left out of the C vehicle"):
        assert "_vehicle_wrench" in c_header_text(rm, "x.h", vehicle=replace(veh, rotor_interference=0.5))


def test_the_include_guard_hashes_the_table_and_the_vehicle_block():
    # c_header_text: the include guard adds a hash of the table (two different maps with one prefix collide at
    # compile time instead of one being skipped silently), and of the vehicle function where there is one
    from pathlib import Path

    import propmap as pm
    from propmap.export_c import c_header_text
    from propmap.maps import build_map

    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml")
    g = generic_params()

    def guard(params, vehicle=None):
        rm = pm.RotorMap(build_map(veh.rotors[0].propeller, params, np.array([900.0, 1500.0]),
                                   np.array([0.0, 10.0]), np.radians([0.0, 90.0, 180.0]), n_check=0))
        return next(line for line in c_header_text(rm, "x.h", vehicle=vehicle).splitlines()
                    if line.startswith("#ifndef"))

    plain = guard(g)
    assert plain.startswith("#ifndef PM_X_H_") and guard(g) == plain
    assert guard(g.replace(cl_alpha=g.cl_alpha * 1.01)) != plain
    assert guard(g, veh) != plain
