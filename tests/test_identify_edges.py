"""The identification API under a property-based audit (2026-11-26): each test failed on the
code before the fix it names. The data are propmap's own loads (apce_8x6's calibrated set, UIUC
vol. 1, Brandt & Selig AIAA 2011-1255), so that a fit's answer is known."""

import dataclasses
import math
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.identify import FitOptions, LoadData, fit_loads, fit_loads_joint, loads_from_catalogue
from propmap.identify import continuation
from propmap.validation import load_errors

PROP = pm.load_propeller("apce_8x6")
TRUE = pm.default_params("apce_8x6")


def _sweeps(air=None, n_rpm=3, noise=0.0, seed=0):
    om = np.repeat(np.linspace(4000.0, 8000.0, n_rpm) * math.pi / 30, 6)
    V = np.tile(np.linspace(0.0, 10.0, 6), n_rpm)
    zero = np.zeros(om.size)
    r = pm.rotor_loads(PROP, TRUE, om, V, zero, air=air)
    rng = np.random.default_rng(seed)
    noisy = {k: getattr(r, k) * (1 + noise * rng.standard_normal(om.size)) for k in ("thrust", "torque")}
    return om, V, zero, noisy, np.repeat([f"g{i}" for i in range(n_rpm)], 6).astype(object)


def test_the_python_fits_use_the_density_the_data_logged():
    """LoadData.air_density (a density column) was used by the command line only: fit_loads,
    fit_loads_joint and load_errors solved at the set's 1.225 kg/m^3 (loads made at 1.0 fitted
    to a wrong set with an rms of 0.048, without a word)."""
    om, V, b, m, g = _sweeps(air=pm.Air(rho=1.0))
    d = LoadData(om, V, b, m, g, "rho.csv", air_density=1.0)
    f = fit_loads(d, PROP, base=TRUE, options=FitOptions(prior=False))
    assert f.air.rho == 1.0 and any("the air density is the data's, 1 kg/m^3" in w for w in f.warnings)
    assert load_errors(d, PROP, TRUE)["overall"]["thrust"]["rms"] < 1e-12
    # an air given is the caller's: used as given, without the note
    given = fit_loads(d, PROP, base=TRUE, air=pm.Air(rho=1.0), options=FitOptions(prior=False))
    assert not any("air density" in w for w in given.warnings)
    assert load_errors(d, PROP, TRUE, air=pm.Air(rho=1.225))["overall"]["thrust"]["rms"] > 0.05
    # a joint fit: each data set at its own density
    om2, V2, b2, m2, g2 = _sweeps()
    d2 = LoadData(om2, V2, b2, m2, g2, "sea.csv", air_density=1.225)
    j = fit_loads_joint([(d, PROP), (d2, PROP)], base=TRUE, options=FitOptions(names=("cl_alpha",), prior=False))
    assert j.params.cl_alpha == pytest.approx(TRUE.cl_alpha, rel=1e-6)


@pytest.mark.parametrize("kw, said", [
    (dict(max_nfev=2.5), r"max_nfev must be an integer in \[1, 10000000\], got 2.5"),
    (dict(max_nfev=0), r"max_nfev must be an integer in \[1,"),
    (dict(multistart=-1), r"multistart must be an integer in \[0, 256\], got -1"),
    (dict(multistart=1.5), r"multistart must be an integer"),
    (dict(bounds={"cl_alpha": (9.0, 3.0)}), r"bounds\['cl_alpha'\] must be finite with low < high"),
    (dict(bounds={"cl_alpa": (3.0, 9.0)}), r"bounds: unknown parameter 'cl_alpa'"),
    (dict(bounds={"cl_alpha": (3.0, 9.0, 1.0)}), r"bounds\['cl_alpha'\] must be two numbers"),
    (dict(x0=(1.0, 2.0)), r"x0 must be 4 finite numbers"),
])
def test_fit_options_refuse_what_would_hang_or_be_ignored(kw, said):
    """max_nfev=2.5 ran SciPy's least_squares without end (400 s and on); a negative
    multistart counted as 0; a misspelt bound was ignored, an inverted one failed in SciPy."""
    with pytest.raises(ValueError, match=said):
        FitOptions(**kw)
    assert FitOptions(bounds={"cl_alpha": (3.0, 9.0)}, max_nfev=50, multistart=2).max_nfev == 50


def test_the_joint_fit_applies_the_prior_and_refuses_too_few_values():
    """fit_loads_joint ignored options.prior (the default): its x equalled the free fit's bit
    for bit; 2 points for 8 parameters ran to the evaluation limit."""
    om, V, b, m, g = _sweeps(noise=0.01)
    d = LoadData(om, V, b, m, g)
    free = fit_loads_joint([(d, PROP)], options=FitOptions(prior=False, max_nfev=60))
    prior = fit_loads_joint([(d, PROP)], options=FitOptions(max_nfev=60))
    assert "prior" in prior.extra and "prior" not in free.extra
    assert not np.array_equal(free.x, prior.x)
    few = d.subset(np.arange(d.n) < 2)
    with pytest.raises(ValueError, match=r"4 fitted load values cannot identify 8 parameters"):
        fit_loads_joint([(few, PROP)])


@pytest.mark.parametrize("group, said", [
    (np.full(4, np.nan), r"each label must be a string or a number \(not NaN\), got np.float64\(nan\)"),
    ([(1, 2)] * 4, r"got \(1, 2\)"),
    (["a", "b", None, "c"], r"got None"),
    ("abcd", r"must be 4 labels \(one per point\)"),
])
def test_load_data_refuses_group_labels_it_cannot_compare(group, said):
    """NaN labels (pandas' empty cells) never equal themselves: the rate count fell from 4 to 0
    and the fit took another route; a tuple label failed inside with a broadcast error."""
    om, z = np.full(4, 800.0), np.zeros(4)
    with pytest.raises(ValueError, match=said):
        LoadData(om, z, z, {"thrust": np.ones(4)}, group)
    with pytest.raises(ValueError, match=r"collective must be in \[-0.785398, 0.785398\] rad \(radians, not degrees\)"):
        LoadData(om, z, z, {"thrust": np.ones(4)}, ["a"] * 4, collective=np.full(4, 10.0))
    with pytest.raises(ValueError, match=r"omega must be <= 100000 rad/s"):
        LoadData(np.full(4, 1e6), z, z, {"thrust": np.ones(4)}, ["a"] * 4)
    assert list(LoadData(om, z, z, {"thrust": np.ones(4)}, [1, 2, 3, 4]).group) == [1, 2, 3, 4]


def test_an_exact_fit_reports_its_correlations_and_says_its_std_errors_mean_nothing():
    """With a residual of exactly 0 every std error is 0, and every correlation was reported as
    0 (0/0): cl_alpha and cl_min at -0.98 went unsaid."""
    om = np.linspace(400.0, 900.0, 8)
    z = np.zeros(8)
    r = pm.rotor_loads(PROP, TRUE, om, z, z)
    d = LoadData(om, z, z, {"thrust": r.thrust, "torque": r.torque}, ["a"] * 8)
    f = fit_loads(d, PROP, base=TRUE, options=FitOptions(names=("cl_alpha", "alpha_L0", "cd_min", "cl_min"),
                                                          prior=False))
    idf = f.identifiability
    assert np.all(idf.std_error == 0.0) and abs(idf.correlation[0, 3]) > 0.95
    assert any("reproduces the data exactly" in w for w in idf.warnings)
    assert any("cl_alpha and cl_min are strongly correlated" in w for w in idf.warnings)


def test_a_fit_along_directions_frees_no_direction_the_data_know_nothing_of():
    """A static run at one rpm: the data's eigenvalues 929, 153 and ~1e-13; the default three
    directions freed the third, and the report called the two good ones worse than the prior."""
    om, z = np.full(8, 700.0), np.zeros(8)
    r = pm.rotor_loads(PROP, TRUE, om, z, z)
    rng = np.random.default_rng(0)
    d = LoadData(om, z, z, {k: getattr(r, k) * (1 + 0.003 * rng.standard_normal(8)) for k in ("thrust", "torque")},
                 ["a"] * 8)
    f = fit_loads(d, PROP)
    assert f.extra["directions"]["count"] == 2
    assert any("2 parameter direction(s) fitted, not 3" in w for w in f.warnings)
    assert not any("direction_1" in w and "less well" in w for w in f.warnings)


def test_quantities_name_each_quantity_once_and_a_missing_load_is_named():
    """quantities=('thrust', 'thrust') dropped the torque and weighed the thrust twice, () meant
    all; one NaN thrust was called 'zero everywhere or not finite'; load_errors gave NaN rms."""
    om = np.linspace(400.0, 900.0, 8)
    z = np.zeros(8)
    r = pm.rotor_loads(PROP, TRUE, om, z, z)
    thrust = r.thrust.copy()
    thrust[3] = np.nan
    d = LoadData(om, z, z, {"thrust": thrust, "torque": r.torque}, ["a"] * 8)
    for q in (("thrust", "thrust"), ()):
        with pytest.raises(ValueError, match=r"quantities must name each fitted quantity once"):
            fit_loads(d, PROP, quantities=q)
    with pytest.raises(ValueError, match=r"measured thrust is NaN \(not measured\) at 1 point\(s\), the first #3 "):
        fit_loads(d, PROP)
    e = load_errors(d, PROP, TRUE)["overall"]["thrust"]
    assert e["n"] == 7 and e["rms"] < 1e-12


def test_a_stall_delay_ending_at_zero_is_no_delay_not_suspect():
    """stall_delay 0 is the absence of the delay: ending there was called 'the data pull it
    beyond the allowed range ... suspect the data'."""
    om, V, b, m, g = _sweeps(noise=0.002)
    d = LoadData(om, V, b, m, g)
    f = fit_loads(d, PROP, base=TRUE.replace(stall_delay=0.0),
                  options=FitOptions(names=("cl_alpha", "alpha_L0", "stall_delay"), prior=False))
    said = [w for w in f.warnings if w.startswith("stall_delay")]
    assert f.params.stall_delay == 0.0 and len(said) == 1 and "suspect" not in said[0]
    assert "ended at 0, its lower bound: the data show none of this effect" in said[0]


def test_simulated_level_flight_does_not_warn_of_its_own_bracket():
    """The trim bracket's top (3000 rad/s) warned 'a blade tip meets the air at Mach 0.9 ... is
    omega given in rpm?' of data at about 545 rad/s."""
    from propmap.identify.synthetic import simulate_level_flight

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        simulate_level_flight(pm.read_vehicle("quadrotor"), pm.preset("gill2017-apc"), [5.0], [-5.0])


def test_simulated_level_flight_balances_the_weight_to_round_off():
    """The module says each condition is trimmed so that eq (16) holds exactly: the net vertical force
    at the rotor speed returned is the weight to 1e-9 (a trim tolerance of 0.1 rad/s, a mutant that
    survived the suite, leaves 4.9e-5 of it here; stop 87's audit)."""
    from propmap.identify.level_flight_fit import level_flight_forces
    from propmap.identify.synthetic import simulate_level_flight

    veh, params = pm.read_vehicle("quadrotor"), pm.preset("gill2017-apc")
    d = simulate_level_flight(veh, params, [0.0, 6.0, 12.0], [0.0, -6.0, -14.0])
    assert d.omega.shape == (3, len(veh.rotors)) and np.all(np.diff(d.omega, axis=1) == 0)  # one speed for all
    forces = level_flight_forces(params, d, veh, air=params.air)
    np.testing.assert_allclose(forces["vertical"], veh.weight, rtol=1e-9, atol=0)


def test_rev_per_second_as_rps_and_a_dot_operator_in_n_m(tmp_path):
    """'rps' and 'N⋅m' (U+22C5) were refused as unknown units."""
    from propmap.identify import read_loads

    rows = [(r, 0.5 + r / 10000, 0.01 + r / 1e6) for r in range(3000, 9001, 1000)]
    a = tmp_path / "a.csv"
    a.write_text("rpm,thrust (N),torque (N·m)\n" + "".join(f"{r},{t},{q}\n" for r, t, q in rows), encoding="utf-8")
    b = tmp_path / "b.csv"
    b.write_text("speed (rps),thrust (N),torque (N⋅m)\n" + "".join(f"{r / 60},{t},{q}\n" for r, t, q in rows),
                 encoding="utf-8")
    da, db = read_loads(a), read_loads(b)
    np.testing.assert_allclose(db.omega, da.omega, rtol=1e-12)
    np.testing.assert_array_equal(db.measured["torque"], da.measured["torque"])
    assert dataclasses.replace(da).n == 7


def test_the_fits_name_an_argument_of_the_wrong_type():
    """Each was an AttributeError from inside (options as a dict, base as a set's name, a
    propeller's name, a (Propeller, LoadData) pair the wrong way round)."""
    om = np.linspace(400.0, 900.0, 8)
    z = np.zeros(8)
    d = LoadData(om, z, z, {"thrust": pm.rotor_loads(PROP, TRUE, om, z, z).thrust}, ["a"] * 8)
    for call, said in ((lambda: fit_loads(d, PROP, options={}), "options must be a FitOptions, got dict"),
                       (lambda: fit_loads(d, PROP, base="generic"), "base must be AirfoilParams or CamberedParams "
                                                                    r"\(a set's name"),
                       (lambda: fit_loads(d, PROP, air=1.2), "air must be a propmap.Air, got float"),
                       (lambda: fit_loads(d, "apce_8x6"), "propeller must be a Propeller"),
                       (lambda: fit_loads({}, PROP), r"data must be a LoadData \(propmap.identify.read_loads\)"),
                       (lambda: fit_loads_joint([(PROP, d)]), r"datasets\[0\]: data must be a LoadData"),
                       (lambda: fit_loads_joint([d]), r"datasets\[0\] must be a \(LoadData, Propeller\) pair")):
        with pytest.raises(TypeError, match=said):
            call()


def test_a_parameter_in_a_null_direction_has_no_correlation_reported():
    """Two parameters entering as their sum only: the shape-based correlation (for the exact fit)
    reported them +1.00 correlated, where the trade-off is -1 and neither is determined (a review);
    they are undetermined, with no correlation, and a nearly degenerate pair reads -1."""
    from propmap.identify.result import _identifiability

    t = np.linspace(0.0, 1.0, 20)
    c = np.sin(3 * t)
    r = 0.01 * np.random.default_rng(0).standard_normal(20)
    idf = _identifiability(("a", "b", "c"), np.ones(3), np.column_stack([c, c, t]), r)
    assert np.all(np.isinf(idf.std_error[:2])) and np.isfinite(idf.std_error[2])
    np.testing.assert_array_equal(idf.correlation, np.eye(3))
    assert not any("strongly correlated" in w for w in idf.warnings)
    near = _identifiability(("a", "b", "c"), np.ones(3), np.column_stack([c, c * (1 + 1e-3 * t), t]), r)
    assert near.correlation[0, 1] == pytest.approx(-1.0, abs=1e-3)


def test_options_the_cambered_fit_would_ignore_are_refused():
    """lift_model='sincos' with a cambered base and population={} were ignored without a word."""
    om = np.linspace(400.0, 900.0, 8)
    z = np.zeros(8)
    d = LoadData(om, z, z, {"thrust": pm.rotor_loads(PROP, TRUE, om, z, z).thrust}, ["a"] * 8)
    with pytest.raises(ValueError, match=r"lift_model='sincos' applies to the paper's model"):
        fit_loads(d, PROP, options=FitOptions(lift_model="sincos"))
    with pytest.raises(ValueError, match=r"population must be None or a dict with names, covariance, sigma_data"):
        FitOptions(population={})


def test_a_drag_only_file_is_scored_against_its_rms_in_plane_drag():
    """With a drag column and no thrust, the reference was the mean static drag coefficient
    (about 0), labelled 'mean static CQ', and the errors read 19,077% (a validation audit)."""
    om = np.full(8, 800.0)
    V = np.r_[0.0, 0.0, np.linspace(2.0, 12.0, 6)]
    b = np.full(8, 1.2)
    r = pm.rotor_loads(PROP, TRUE, om, V, b)
    e = load_errors(LoadData(om, V, b, {"drag": r.drag * 1.01}, ["a"] * 8), PROP, TRUE)
    assert e["reference"]["drag"][0] == "rms measured drag coefficient"
    assert e["overall"]["drag"]["n"] == 6 and e["overall"]["drag"]["rms"] == pytest.approx(0.0099, rel=0.01)


def test_a_drag_only_file_without_an_in_plane_airspeed_keeps_its_rms_reference():
    """The in-plane reference left no point at axial data: 'the rms measured drag coefficient is
    nan' (a review); without in-plane points every point is scored, as the docstring says."""
    om = np.linspace(600.0, 900.0, 6)
    V = np.linspace(0.0, 5.0, 6)
    e = load_errors(LoadData(om, V, np.zeros(6), {"drag": np.full(6, 0.01)}, ["a"] * 6), PROP, TRUE)
    assert e["overall"]["drag"]["n"] == 6 and np.isfinite(e["reference"]["drag"][1])


def test_a_flight_fit_refuses_lift_model_sincos_with_a_cambered_base(shared_data):
    """fit_flight ignored lift_model='sincos' with the cambered generic set (the check lived in
    the load fit's names only; a review)."""
    from propmap.identify.flight import fit_flight, flight_samples
    from propmap.io.flightlog import read_flight_log

    log = read_flight_log(shared_data / "neurobem_flights" / "bemnn20210223104803seg2.mat")
    samples = flight_samples([log], pm.read_vehicle("neurobem_quadrotor"), rate_hz=2.0)
    with pytest.raises(ValueError, match=r"lift_model='sincos' applies to the paper's model"):
        fit_flight(samples, pm.read_vehicle("neurobem_quadrotor"), options=FitOptions(lift_model="sincos"))


def test_nelder_mead_at_its_limit_counts_as_converged_only_within_the_standard_errors(monkeypatch):
    """The paper's model fitted to apce_8x6's static run (UIUC vol. 1, Brandt & Selig): the continuation's
    Nelder-Mead at M = 50 stops at its 800 evaluations (200 per parameter) short of its 1e-12 tolerance, and
    the fit is converged for every purpose where the final simplex lies within NM_STAT_TOL of the
    parameters' standard errors (the data's scatter sets the error, not the optimiser: docs/identification.md);
    with that tolerance 0 the same fit says Nelder-Mead stopped at its limit."""
    prop = pm.load_propeller("apce_8x6")
    data = loads_from_catalogue(pm.catalogue()["apce_8x6"], prop.diameter)
    static = data.subset(data.airspeed == 0)
    res = fit_loads(static, prop, base=pm.preset("gill2017-apc"))
    assert res.nfev >= 800 and res.success
    assert res.message.endswith("then Nelder-Mead at M = 50")
    monkeypatch.setattr(continuation, "NM_STAT_TOL", 0.0)
    stopped = fit_loads(static, prop, base=pm.preset("gill2017-apc"))
    np.testing.assert_array_equal(stopped.x, res.x)
    assert not stopped.success and stopped.message == "Nelder-Mead stopped at its evaluation limit"
