"""A mutation audit of core/airfoil.py, identify/result.py and io/mapcheck.py (2026-11-29): each
test kills a hand-made mutant that survived the modules' own test files, by the documented behaviour it changed
(the ranges and defaults of the section records, replace()'s label, the fit report's table, JSON
and warnings, a map's checks)."""

import json
import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.airfoil import sigmoid_blend
from propmap.identify.dependence import jackknife_report, jackknife_std_error, lag1_autocorrelation
from propmap.identify.result import FitResult, _identifiability
from propmap.core._numbers import integer as check_integer
from propmap.io.mapcheck import DIMS, FLAGS, LOADS, check_attributes, check_dataset, check_propeller, map_model

# ---------------------------------------------------------------- core/airfoil.py

def _refused(match, make):
    with pytest.raises(ValueError, match=match):
        make()


def test_the_rotor_options_ranges_end_where_documented():
    """RotorOptions: flap_compliance in [0, 1e3] rad/(N m), collective in [-30, 30] deg (rad),
    dynamic_stall in [0, 5] (the cambered model's)."""
    assert pm.CamberedParams(flap_compliance=1e3).flap_compliance == 1e3
    _refused(r"flap_compliance must be a finite number in \[0, 1000\] rad/\(N m\)",
             lambda: pm.CamberedParams(flap_compliance=1.001e3))
    c = math.radians(30.0)
    assert pm.CamberedParams(collective=c).collective == c and pm.CamberedParams(collective=-c).collective == -c
    _refused(r"collective must be a finite number in \[-0.5235987755982988, 0.5235987755982988\] rad",
             lambda: pm.CamberedParams(collective=math.radians(30.01)))
    _refused("collective must be a finite number in", lambda: pm.CamberedParams(collective=-math.radians(30.01)))
    assert pm.CamberedParams(dynamic_stall=5.0).dynamic_stall == 5.0
    _refused(r"dynamic_stall must be a finite number in \[0, 5\]", lambda: pm.CamberedParams(dynamic_stall=5.01))


def test_the_defaults_of_each_record_are_the_documented_ones():
    """The paper's record stays the paper's (Glauert in descent, no radial drag, no in-plane
    induction, no tip loss); the cambered one has the empirical descent, radial drag, in-plane
    induction, the tip loss and cd90 = 1.98."""
    a = pm.AirfoilParams(cl1=5.0, cl2=2.0, cd=1.5, alpha0=0.3)
    assert (a.descent, a.radial_drag, a.inplane_induction, a.swirl, a.tip_loss, a.hub_loss) == (
        "glauert", False, False, False, False, False)
    assert (a.M, a.cd0, a.cp_blasius, a.lift_model, a.inflow) == (50.0, 0.01, 1.328, "sigmoid", "uniform")
    c = pm.CamberedParams()
    assert (c.descent, c.radial_drag, c.inplane_induction, c.swirl, c.tip_loss, c.hub_loss, c.compressibility) == (
        "empirical", True, True, False, True, False, True)
    assert (c.cd90, c.M, c.cl_alpha, c.cl_max, c.cl_min) == (1.98, 20.0, 5.7, 1.2, -0.5)
    assert c.alpha_L0 == pytest.approx(math.radians(-4.0))


def test_an_air_or_label_of_the_wrong_type_is_refused_by_name():
    _refused("air must be a propmap.Air, got str", lambda: pm.CamberedParams(air="1.225"))
    _refused("label must be text, got int", lambda: pm.CamberedParams(label=3))


def test_the_dynamic_stall_needs_the_cambered_model_and_the_uniform_inflow():
    _refused("dynamic_stall applies to the cambered section model",
             lambda: pm.AirfoilParams(cl1=5.0, cl2=2.0, cd=1.5, alpha0=0.3, dynamic_stall=1.0))
    _refused("dynamic_stall needs the uniform inflow, got inflow='drees'",
             lambda: pm.CamberedParams(dynamic_stall=1.0, inflow="drees"))


def test_side_load_sources_name_each_option_that_makes_them():
    c = pm.CamberedParams()
    assert c.side_load_sources() == ()
    assert c.replace(flap_compliance=1e-3).side_load_sources() == ("blade flapping",)
    assert c.replace(inflow="pitt-peters").side_load_sources() == ("a linear inflow",)
    assert c.replace(dynamic_stall=1.0).side_load_sources() == ("the dynamic stall",)


def test_as_dict_leaves_out_the_air_and_the_label():
    d = pm.CamberedParams(label="x").as_dict()
    assert "air" not in d and "label" not in d and d["cd90"] == 1.98 and d["descent"] == "empirical"


def test_the_papers_record_refuses_each_value_outside_its_range():
    base = dict(cl1=5.0, cl2=2.0, cd=1.5, alpha0=0.3)
    for name in ("cl1", "cl2", "cd", "cd0", "cp_blasius"):
        _refused(rf"{name} must be a finite number in \[0, inf\)", lambda: pm.AirfoilParams(**{**base, name: -1e-9}))
    _refused(r"M must be a finite number in \(0, inf\)", lambda: pm.AirfoilParams(**base, M=0.0))
    _refused(r"alpha0 must be in \(0, pi/2\)", lambda: pm.AirfoilParams(**{**base, "alpha0": math.pi / 2}))
    _refused(r"alpha0 must be in \(0, pi/2\)", lambda: pm.AirfoilParams(**{**base, "alpha0": 0.0}))


def test_replace_labels_a_changed_set_once_and_keeps_a_given_label():
    p = pm.preset("gill2017-apc")
    assert p.label == "gill2017-apc"
    q = p.replace(cd=1.9)
    assert q.label == "modified gill2017-apc"
    assert q.replace(cd=2.0).label == "modified gill2017-apc"  # (not "modified modified")
    assert p.replace(cd=1.9, label="mine").label == "mine"
    assert p.replace(air=pm.Air(rho=1.1)).label == "gill2017-apc"  # (the air is not a model field)
    assert p.replace(cd=p.cd).label == "gill2017-apc"  # (nothing moved)
    with pytest.raises(ValueError, match=r"unknown parameter\(s\) alpha0_deg of AirfoilParams \(angles are in rad"):
        p.replace(alpha0_deg=20.0)
    with pytest.raises(ValueError) as e:
        p.replace(cl_alpah=5.0)
    assert "angles are in rad" not in str(e.value) and "cl1, cl2, cd, alpha0, M, cd0" in str(e.value)


def test_a_numpy_bool_flag_is_stored_as_a_bool():
    """_check_flags: a numpy bool (a flag read from an array) is stored as Python's bool, so
    that the record's dict is JSON (a file, a map's params_json)."""
    p = pm.CamberedParams(tip_loss=np.bool_(False), swirl=np.bool_(True))
    assert type(p.tip_loss) is bool and type(p.swirl) is bool
    assert json.loads(json.dumps(p.as_dict()))["swirl"] is True


def test_the_cambered_ranges_end_where_documented():
    """CamberedParams' documented ranges: each end accepted, just past it refused (the message
    names the field)."""
    ends = {"cl_alpha": (None, 20.0), "alpha_L0": (math.radians(-20.0), math.radians(10.0)),
            "cl_max": (None, 4.0), "cl_min": (-4.0, None), "cd_min": (0.0, 1.0), "cd2": (0.0, 10.0),
            "cl_cdmin": (-2.0, 3.0), "cd90": (None, 4.0), "re_exp": (-2.0, 1.0), "re_exp_lift": (-1.0, 1.0),
            "re_exp_stall": (-1.0, 1.0), "stall_delay": (0.0, 20.0),
            "alpha_L0_re": (math.radians(-5.0), math.radians(5.0)), "re_ref": (None, 1e9), "M": (None, 1000.0)}
    for name, (lo, hi) in ends.items():
        for end, step in ((lo, -1e-6), (hi, 1e-6)):
            if end is None:
                continue
            assert getattr(pm.CamberedParams(**{name: end}), name) == end
            _refused(f"{name} must be a finite number in", lambda: pm.CamberedParams(**{name: end + step}))
    for name in ("cl_alpha", "cl_max", "cd90", "re_ref", "M"):  # open at 0
        _refused(rf"{name} must be a finite number in \(0,", lambda: pm.CamberedParams(**{name: 0.0}))
    _refused(r"cl_min must be in \[-4, 0\)", lambda: pm.CamberedParams(cl_min=0.0))


def test_the_presets_are_table_I_with_their_names():
    """Table I of Gill & D'Andrea (2017); preset() labels the set with its name."""
    table = {"gill2017-soft": (6.9, 2.0, 3.7, 20.4), "gill2017-stiff": (4.2, 2.0, 1.3, 27.5),
             "gill2017-apc": (5.3, 1.7, 1.8, 20.6)}
    for name, (cl1, cl2, cd, a0) in table.items():
        p = pm.preset(name)
        assert (p.cl1, p.cl2, p.cd, p.label) == (cl1, cl2, cd, name)
        assert math.degrees(p.alpha0) == pytest.approx(a0)


def test_the_stall_blend_is_eq_3s_even_function():
    """sigma of eq (3) is even in alpha, 0 well inside (-alpha0, alpha0), 1/2 at the stall angle
    (for a large M), 1 well outside."""
    a = np.linspace(-1.5, 1.5, 31)
    np.testing.assert_allclose(sigmoid_blend(a, 0.35, 50.0), sigmoid_blend(-a, 0.35, 50.0), rtol=0, atol=1e-15)
    assert sigmoid_blend(0.0, 0.35, 50.0) == pytest.approx(0.0, abs=1e-7)
    assert sigmoid_blend(0.35, 0.35, 50.0) == pytest.approx(0.5, abs=1e-6)
    assert sigmoid_blend(-0.35, 0.35, 50.0) == pytest.approx(0.5, abs=1e-6)
    assert sigmoid_blend(1.5, 0.35, 50.0) == 1.0


# ---------------------------------------------------------------- identify/result.py

def _fit(names=("cl_alpha", "alpha_L0", "cd_min"), x=(5.5, -0.06, 0.02), jac=None, residuals=None, **kw):
    """A FitResult of a synthetic fit (a Jacobian of 12 rows), its identifiability _identifiability's."""
    rng = np.random.default_rng(7)
    x = np.array(x, float)
    jac = rng.standard_normal((12, len(names))) if jac is None else np.asarray(jac, float)
    residuals = 1e-3 * rng.standard_normal(jac.shape[0]) if residuals is None else np.asarray(residuals, float)
    held = kw.pop("at_bound", ())
    idf = kw.pop("identifiability", None) or _identifiability(names, x, jac, residuals, held=held)
    return FitResult(params=pm.CamberedParams(), air=pm.Air(), names=tuple(names), x=x, residuals=residuals,
                     cost=0.5 * float(residuals @ residuals), nfev=10, n_model_points=100, elapsed_s=0.5,
                     success=True, message="ok", starts=[], identifiability=idf, at_bound=held, **kw)


def test_poorly_determined_is_a_std_error_above_10_percent_of_the_scale():
    """Identifiability: a std error above POOR_REL_STD (10%) of max(|estimate|, natural scale)
    is poorly determined; one at 15% is (a 0.20 threshold passed the suite)."""
    J = np.eye(2)
    for rel, poor in ((0.15, True), (0.05, False)):
        r = np.zeros(6)
        r[:4] = rel * 2.0  # s^2 = |r|^2 / (6 - 2) = (2 rel)^2: std errors 2 rel, the first estimate 2
        jac = np.vstack([J, np.zeros((4, 2))])
        idf = _identifiability(("cl_alpha", "cd_min"), np.array([2.0, 1.0]), jac, r)
        assert idf.std_error[0] == pytest.approx(2 * rel)
        assert ("cl_alpha" in idf.poorly_determined) is poor


def test_a_natural_scale_judges_an_estimate_near_zero():
    """Against max(|estimate|, natural scale): alpha_L0's 2 deg, the collective's tenth of its
    bounds' span (3 deg); an estimate of 0 with a std error of 1% of the scale is determined."""
    from propmap.identify.result import _scale_of

    assert _scale_of("collective") == pytest.approx(0.1 * math.radians(30))
    assert _scale_of("flap_compliance") == 1.0
    r = np.zeros(5)
    r[:4] = 1e-4 * math.sqrt(3)  # s^2 = |r|^2 / (5 - 1): std error 1.7e-4 rad, 0.3% of the scale
    jac = np.vstack([[1.0], np.zeros((4, 1))])
    idf = _identifiability(("collective",), np.array([0.0]), jac, r)
    assert 0 < idf.std_error[0] < 0.1 * _scale_of("collective")
    assert idf.poorly_determined == ()


def test_the_interval_is_students_t_with_n_minus_p_degrees():
    """95% intervals: estimate +- t_0.975(N - p) std error (the class docstring)."""
    from scipy import stats

    res = _fit()
    idf = res.identifiability
    half = (idf.ci95[:, 1] - idf.ci95[:, 0]) / 2
    np.testing.assert_allclose(half, stats.t.ppf(0.975, 12 - 3) * idf.std_error, rtol=1e-12)
    s2 = float(res.residuals @ res.residuals) / (12 - 3)
    rng = np.random.default_rng(7)
    jac = rng.standard_normal((12, 3))
    cov = s2 * np.linalg.inv(jac.T @ jac)
    np.testing.assert_allclose(idf.std_error, np.sqrt(np.diag(cov)), rtol=1e-9)


def test_the_correlation_and_singularity_warnings_have_their_thresholds():
    """Pairs with |correlation| > 0.95 are named (0.97 is); a smallest singular value under 1e-6 of
    the largest is 'nearly singular' (1e-7 is)."""
    c = 0.97
    jac = np.vstack([np.linalg.cholesky(np.linalg.inv([[1, c], [c, 1]])).T, np.zeros((6, 2))])
    rng = np.random.default_rng(3)
    idf = _identifiability(("cl_alpha", "cd_min"), np.array([1.0, 1.0]), jac, rng.standard_normal(8))
    assert idf.correlation[0, 1] == pytest.approx(c)
    assert ("correlated", ("cl_alpha", "cd_min")) in idf.warning_kinds
    jac = np.vstack([np.diag([1.0, 1e-7]), np.zeros((6, 2))])
    idf = _identifiability(("cl_alpha", "cd_min"), np.array([1.0, 1.0]), jac, rng.standard_normal(8))
    assert ("singular", ()) in idf.warning_kinds and np.all(np.isfinite(idf.std_error))


def test_a_small_share_in_a_free_direction_is_not_determined():
    """A parameter with a share of at least 1e-3 in a direction J diag(max(|x|, 0.1)) leaves free is
    not determined (the class docstring): here 0.007 (a 0.1 threshold passed the suite)."""
    rng = np.random.default_rng(6)
    u, w = rng.standard_normal((2, 10))
    jac = np.column_stack([u, w, u + 0.01 * w])  # null direction (1, 0.01, -1) / |.|
    idf = _identifiability(("cl_alpha", "cd_min", "cd2"), np.ones(3), jac, 1e-3 * rng.standard_normal(10))
    assert not np.isfinite(idf.std_error).any()
    assert idf.poorly_determined == ("cl_alpha", "cd_min", "cd2")
    assert ("not_determined", ("cd_min",)) in idf.warning_kinds

def test_a_parameter_held_at_a_bound_keeps_the_others_correlation():
    c = 0.5
    jac = np.column_stack([np.vstack([np.linalg.cholesky(np.linalg.inv([[1, c], [c, 1]])).T, np.zeros((6, 2))]),
                           np.arange(8.0)])
    rng = np.random.default_rng(4)
    idf = _identifiability(("cl_alpha", "cd_min", "cd2"), np.array([1.0, 1.0, 0.0]), jac, rng.standard_normal(8),
                           held=("cd2",))
    assert idf.correlation[0, 1] == pytest.approx(c) and idf.correlation[1, 0] == pytest.approx(c)
    assert np.isnan(idf.std_error[2]) and idf.correlation[2, 2] == 1.0


def test_a_poorly_determined_angle_is_said_in_degrees():
    r = np.zeros(5)
    r[:4] = 0.1
    jac = np.vstack([[1.0], np.zeros((4, 1))])
    idf = _identifiability(("alpha_L0",), np.array([-0.05]), jac, r)
    assert f"std error {math.degrees(idf.std_error[0]):.3g} deg is" in idf.warnings[0]


def test_the_json_report_gives_angles_in_degrees_and_the_data_only_errors():
    res = _fit()
    idf = res.identifiability
    data_only = idf.std_error * 0.5
    from dataclasses import replace

    cut = np.array([[False, False], [True, False], [False, False]])
    d = replace(res, identifiability=replace(idf, std_error_data=data_only, ci95_cut=cut),
                at_bound=(), extra={"kind": "loads", "holdout": {"x": 1}}).to_dict()
    i = d["identifiability"]
    assert i["std_error_data_only"]["cl_alpha"] == pytest.approx(data_only[0])
    assert i["std_error_data_only"]["alpha_L0_deg"] == pytest.approx(math.degrees(data_only[1]))
    assert i["ci95"]["alpha_L0_deg"] == [pytest.approx(math.degrees(v)) for v in idf.ci95[1]]
    assert i["ci95_cut_at_bound"] == {"alpha_L0_deg": [True, False]}
    assert d["units"] == {"alpha_L0_deg": "deg"}
    assert d["rms_residual"] == pytest.approx(math.sqrt(np.mean(res.residuals ** 2)))
    assert d["holdout"] == {"x": 1} and d["kind"] == "loads"
    held = _fit(at_bound=("alpha_L0",)).to_dict()
    assert held["at_bound"] == ["alpha_L0_deg"] and held["identifiability"]["std_error"]["alpha_L0_deg"] is None


def test_the_text_report_marks_bounds_degrees_and_cut_intervals():
    from dataclasses import replace

    res = _fit(at_bound=("cd_min",), warnings=("the fit stopped at its evaluation limit (10)",))
    idf = res.identifiability
    cut = np.array([[True, True], [False, False], [False, False]])
    text = replace(res, identifiability=replace(idf, ci95_cut=cut)).report_text()
    rows = {line.split()[0]: line for line in text.splitlines()[1:4]}
    assert rows["cd_min"].endswith("(at bound)") and rows["cd_min"].split()[2:4] == ["-", "-"]
    assert rows["alpha_L0"].startswith("alpha_L0 [deg]") and f"{math.degrees(res.x[1]):.4g}" in rows["alpha_L0"]
    assert f"{math.degrees(idf.std_error[1]):.3g}" in rows["alpha_L0"]
    assert f"[{idf.ci95[0, 0]:.4g}*, {idf.ci95[0, 1]:.4g}*]" in rows["cl_alpha"]
    assert "*: the interval ends at the parameter's bound" in text
    assert "WARNING: the fit stopped at its evaluation limit (10)" in text
    assert "correlation: cl_alpha-alpha_L0" in text


def test_the_correlation_line_needs_two_free_parameters():
    one = _fit(names=("cl_alpha", "cd_min"), x=(5.5, 0.02), at_bound=("cd_min",)).report_text()
    assert "correlation" not in one
    two = _fit(names=("cl_alpha", "cd_min"), x=(5.5, 0.02)).report_text()
    assert "correlation: cl_alpha-cd_min" in two


def test_the_text_report_lists_the_largest_residuals_with_their_unit():
    r = np.array([0.1, -0.5, 0.2, 0.05, 0.3])
    jac = np.random.default_rng(1).standard_normal((5, 2))
    res = _fit(names=("cl_alpha", "cd_min"), x=(5.5, 0.02), jac=jac, residuals=r)
    line = [s for s in res.report_text(max_residuals=2).splitlines() if s.startswith("residuals")][0]
    assert line.endswith("(the 2 largest of 5; all in the JSON report): #1 -0.5, #4 +0.3")
    line = [s for s in res.report_text(max_residuals=5).splitlines() if s.startswith("residuals")][0]
    assert "largest" not in line and line.count("#") == 5
    flight = _fit(names=("cl_alpha", "cd_min"), x=(5.5, 0.02), jac=jac, residuals=r, extra={"kind": "flight"})
    text = flight.report_text()
    assert "residuals [N]" in text and "rms residual" in text and " N; 10 evaluations" in text


def test_correlated_residuals_are_said_above_0_2_with_the_right_hint():
    """Above a lag-1 of 0.2 the report says the std errors understate; a flight fit of one log has
    no jackknife to suggest; a load fit's residuals are within each run."""
    auto = {"lag1": 0.3, "n_effective": 50.0, "n": 100}
    loads = _fit(extra={"kind": "loads", "residual_autocorrelation": auto}).report_text()
    assert ("consecutive residuals within each run correlate at 0.30 (lag 1: the information of about 50 "
            "independent residuals of 100): the uncertainty is likely larger; the jackknife of the runs") in loads
    one_log = _fit(extra={"kind": "flight", "logs": ["a"], "residual_autocorrelation": auto}).report_text()
    assert "within each log correlate at 0.30" in one_log and "the uncertainty is likely larger\n" in one_log + "\n"
    assert "50 independent samples (3 force errors each) of 100" in one_log
    two = _fit(extra={"kind": "flight", "logs": ["a", "b"], "residual_autocorrelation": auto}).report_text()
    assert "leave-one-log-out jackknife" in two
    low = _fit(extra={"kind": "loads", "residual_autocorrelation": {**auto, "lag1": 0.19}}).report_text()
    assert "assume independent residuals" not in low


def test_lag1_is_taken_about_each_groups_mean():
    """Two groups at different levels, each a white series, do not correlate: rho about each
    group's own mean."""
    rng = np.random.default_rng(5)
    r = np.concatenate([rng.standard_normal(400), 50 + rng.standard_normal(400)])
    assert abs(lag1_autocorrelation(r, np.repeat([0, 1], 400))["lag1"]) < 0.15
    got = lag1_autocorrelation([1.0, -1.0, 1.0, -1.0], [0, 0, 0, 0])
    assert got["lag1"] < 0 and got["n_effective"] == 4.0


def test_the_jackknife_of_two_groups_and_its_report():
    """g = 2 is enough (the docstring: fewer than 2 refused); the interval is t(g - 1); the ratio is
    the jackknife's over the linearised std error."""
    from scipy import stats

    assert jackknife_std_error([[1.0], [3.0]])[0] == pytest.approx(math.sqrt(0.5 * 2.0))
    with pytest.raises(ValueError, match="g >= 2"):
        jackknife_std_error(np.zeros((1, 2)))
    res = _fit(names=("cl_alpha", "cd_min"), x=(5.5, 0.02))
    folds = [{"cl_alpha": 5.4, "cd_min": 0.02}, {"cl_alpha": 5.5, "cd_min": 0.02}, {"cl_alpha": 5.6, "cd_min": 0.02}]
    rep = jackknife_report(res, folds, "run", ["a", "b", "c"])
    se = math.sqrt(2 / 3 * 0.02)
    assert rep["std_error"]["cl_alpha"] == pytest.approx(se)
    lo, hi = rep["ci95"]["cl_alpha"]
    assert (hi - lo) / 2 == pytest.approx(stats.t.ppf(0.975, 2) * se)
    assert rep["ratio"]["cl_alpha"] == pytest.approx(se / res.identifiability.std_error[0])


# ---------------------------------------------------------------- io/mapcheck.py

def _map(*, rpm=(1000.0, 5000.0, 9000.0), airspeed=(0.0, 10.0), incidence=(0.0, 90.0, 180.0), **attrs):
    """A synthetic map (no model: the checks look at its layout and ranges), every node converged."""
    import xarray as xr

    shape = (len(rpm), len(airspeed), len(incidence))
    data = {k: (DIMS, np.ones(shape)) for k in LOADS}
    data.update({k: (DIMS, np.zeros(shape, bool)) for k in FLAGS})
    data["converged"] = (DIMS, np.ones(shape, bool))
    return xr.Dataset(data, coords={"rpm": np.array(rpm, float), "airspeed": np.array(airspeed, float),
                                    "incidence_deg": np.array(incidence, float)}, attrs={"diameter_m": 0.2, **attrs})


def _bad(match, ds_or_attrs):
    with pytest.raises(ValueError, match=match):
        (check_dataset if hasattr(ds_or_attrs, "data_vars") else check_attributes)(ds_or_attrs)


def test_the_axes_end_where_the_module_table_says():
    """Omega in [0.1, 1e5] rad/s, airspeed in [0, 500] m/s, incidence in [0, 180] deg (1e-12 of the
    range's end as tolerance), at least 2 strictly increasing values per axis."""
    top = 1e5 * 30 / math.pi
    check_dataset(_map(rpm=(1000.0, top), airspeed=(0.0, 500.0)))
    _bad("axis rpm must lie within", _map(rpm=(1000.0, top * 1.0001)))
    _bad("axis airspeed must lie within", _map(airspeed=(0.0, 500.001)))
    _bad("axis airspeed must hold at least 2 finite, strictly increasing", _map(airspeed=(0.0, 5.0, 5.0)))
    _bad("axis airspeed must hold at least 2", _map(airspeed=(0.0,)))
    _bad("axis incidence_deg must be in 'degree'", _map().assign_coords(
        incidence_deg=("incidence_deg", [0.0, 90.0, 180.0], {"units": "rad"})))


def test_the_loads_their_units_and_flags_are_held_to_the_table():
    ds = _map()
    torque = ds.copy(deep=True)
    torque["torque"][0, 0, 0] = 1e4
    check_dataset(torque)
    torque["torque"][0, 0, 0] = 1.0001e4
    _bad(r"variable torque must lie within \+-10000 N m", torque)
    neg = ds.copy(deep=True)
    neg["thrust"][0, 0, 0] = -1.1e5
    _bad(r"variable thrust must lie within \+-100000 N", neg)
    side = ds.assign(side_force=ds["thrust"] * 0)
    _bad("a map holds both of side_force, pitching_moment or neither", side)
    check_dataset(side.assign(pitching_moment=ds["thrust"] * 0))
    _bad("flag vortex_ring must be boolean", ds.assign(vortex_ring=ds["thrust"] * 0.5))
    units = ds.copy()
    units["drag"].attrs["units"] = "kN"
    _bad("variable drag must be in 'N', its units attribute says", units)
    _bad("no node of the map converged", ds.assign(converged=ds["converged"] & False))
    gap = ds.copy(deep=True)
    gap["converged"][0, 0, 0] = False
    gap["thrust"][0, 0, 0] = np.nan
    check_dataset(gap)  # (a node that did not converge may lack values)
    _bad("a map of several propellers", ds.expand_dims(prop=["a", "b"]))


def test_the_si_incidence_coordinate_is_in_radians():
    ds = _map()
    check_dataset(ds.assign_coords(incidence=("incidence_deg", np.radians(ds["incidence_deg"].values))))
    _bad("coordinate incidence must equal incidence_deg in rad",
         ds.assign_coords(incidence=("incidence_deg", ds["incidence_deg"].values)))


def test_the_attributes_are_held_to_their_ranges_and_types():
    ok = {"diameter_m": 0.2, "n_blades": 1, "rho_kg_m3": 1.225, "mu_Pa_s": 1.8e-5, "check_points": 10,
          "check_points_flagged": 10, "check_linear_thrust_rms": float("nan"),
          "geometry_r_m": np.linspace(0.02, 0.1, 5)}
    check_attributes(ok)
    _bad(r"attribute n_blades must be an integer in \[1, 100\]", {**ok, "n_blades": 2.5})
    _bad(r"attribute n_blades must be an integer in \[1, 100\], got True", {**ok, "n_blades": True})
    _bad(r"attribute n_blades must be an integer in \[1, 100\]", {**ok, "n_blades": 101})
    _bad(r"attribute mu_Pa_s must be a number in \(0, 10\] Pa s", {**ok, "mu_Pa_s": 0.0})
    _bad(r"attribute rho_kg_m3 must be a number in \[0.001, 2000\]", {**ok, "rho_kg_m3": 0.0})
    _bad(r"attribute check_points_flagged must be an integer in \[0, 10\]", {**ok, "check_points_flagged": 11})
    _bad("attribute check_linear_thrust_rms must be a number", {**ok, "check_linear_thrust_rms": -1.0})
    _bad("attribute geometry_r_m must be an array of 1 to 10000 numbers", {**ok, "geometry_r_m": np.ones((2, 3))})
    r = np.linspace(0.02, 0.1, 10_000)
    check_attributes({**ok, "geometry_r_m": r})
    _bad("attribute geometry_r_m must be an array of 1 to 10000",
         {**ok, "geometry_r_m": np.linspace(0.02, 0.1, 10_001)})
    _bad("attribute diameter_m .* disagrees with geometry_r_m", {**ok, "geometry_r_m": r * (1 + 1e-4)})
    _bad("attribute note must be text, got 3", {**ok, "note": 3})


def test_check_propeller_and_check_integer_hold_their_ranges():
    from types import SimpleNamespace

    check_propeller(SimpleNamespace(diameter=100 * 0.0254, n_blades=100))
    with pytest.raises(ValueError, match=r"diameter must be in \[0.0127, 2.54\] m"):
        check_propeller(SimpleNamespace(diameter=2.6, n_blades=2))
    with pytest.raises(ValueError, match="must have 1 to 100 blades, got 101"):
        check_propeller(SimpleNamespace(diameter=0.2, n_blades=101))
    assert check_integer("n_check", 5, 0, 5) == 5 and check_integer("n_check", 2000.0, 0, 5000) == 2000
    with pytest.raises(ValueError, match=r"n_check must be an integer in \[0, 5\], got 2.5"):
        check_integer("n_check", 2.5, 0, 5)
    with pytest.raises(ValueError, match=r"n_check must be an integer in \[0, 5\], got 6"):
        check_integer("n_check", 6, 0, 5)


def _model_attrs(si):
    return dict(propeller="t", diameter_m=0.2, n_blades=2, geometry_r_m=np.linspace(0.02, 0.1, 8),
                geometry_chord_m=np.full(8, 0.02), geometry_theta_rad=np.linspace(0.6, 0.2, 8),
                params_json=json.dumps(si),
                rho_kg_m3=1.1, mu_Pa_s=1.8e-5, speed_of_sound_m_s=330.0, n_radial=20, n_azimuth=8,
                propeller_source="a test")


def test_map_model_rebuilds_the_recorded_model():
    from propmap.io.calibration import params_to_si

    si = params_to_si(pm.CamberedParams(collective=0.05))
    prop, params, air, disc = map_model(_model_attrs(si))
    assert params == pm.CamberedParams(collective=0.05)
    assert air == pm.Air(rho=1.1, mu=1.8e-5, speed_of_sound=330.0)
    assert (disc.n_radial, disc.n_azimuth) == (20, 8) and prop.source == "a test" and prop.radius == 0.1
    # a record written before the radial drag and the in-plane induction existed: made without them
    old = {k: v for k, v in si.items() if k not in ("radial_drag", "inplane_induction")}
    params = map_model(_model_attrs(old))[1]
    assert params.radial_drag is False and params.inplane_induction is False
    # an angle is checked in degrees against the parameter file's range, named as there
    with pytest.raises(ValueError, match=r"attribute params_json: alpha_L0_deg must be .* in \[-20, 10\] deg"):
        map_model(_model_attrs({**si, "alpha_L0": math.radians(15.0)}))
