"""Mutation audit of propmap.identify.fit (fit_loads, fit_loads_joint and their helpers) and of
``propmap fit loads`` (cli/fit.py), 2026-11-29: each test pins what one hand-made mutant of the
source changed and the module's own tests did not notice (its docstring names the mutant)."""

import math
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.core.airfoil import Air
from propmap.identify import FitOptions, LoadData, fit_loads
from propmap.identify.fit import _load_norms, _unit_notes

PROP = "apce_8x6"


def _data(rpm, airspeed=0.0, incidence=0.0, scale=None, group="all"):
    """Loads of apce_8x6 under its default set at ``rpm`` (model-made, so a fit starts at its optimum)."""
    prop = pm.load_propeller(PROP)
    om = np.asarray(rpm, float) * math.pi / 30
    V = np.broadcast_to(np.asarray(airspeed, float), om.shape).copy()
    inc = np.broadcast_to(np.asarray(incidence, float), om.shape).copy()
    r = pm.rotor_loads(prop, pm.default_params(PROP), om, V, inc)
    measured = {"thrust": r.thrust * (scale or {}).get("thrust", 1.0),
                "torque": r.torque * (scale or {}).get("torque", 1.0)}
    groups = np.broadcast_to(np.asarray(group, dtype=object), om.shape).copy()
    return prop, LoadData(om, V, inc, measured, groups, "audit")


def test_load_norms_are_rho_n2_d4_for_thrust_and_rho_n2_d5_for_torque():
    """Mutant A3 (torque's norm rho n^2 D^4, as the thrust's): each quantity's scale is the rms of its
    measured coefficient, CT = T / (rho n^2 D^4) and CQ = Q / (rho n^2 D^5)."""
    prop, data = _data(np.linspace(3000, 9000, 7))
    air = Air()
    norm, scales = _load_norms(data, prop, ["thrust", "torque"], air)
    n = data.omega / (2 * math.pi)
    ct = data.measured["thrust"] / (1.225 * n**2 * 0.2032**4)
    cq = data.measured["torque"] / (1.225 * n**2 * 0.2032**5)
    assert scales["thrust"] == pytest.approx(float(np.sqrt(np.mean(ct**2))), rel=1e-12)
    assert scales["torque"] == pytest.approx(float(np.sqrt(np.mean(cq**2))), rel=1e-12)
    assert 0.05 < scales["thrust"] < 0.25 and 0.003 < scales["torque"] < 0.03  # a propeller's static CT and CQ
    np.testing.assert_allclose(norm["torque"] / norm["thrust"], 0.2032, rtol=1e-12)


def test_a_quantity_zero_everywhere_is_refused_before_the_fit():
    """Mutant A6 (the 'zero everywhere' check only asks for a finite rms): a thrust of 0 at every
    point has an rms of 0, and dividing by it is no fit: fit_loads says so and names the other."""
    prop, data = _data(np.linspace(3000, 9000, 7), scale={"thrust": 0.0})
    with pytest.raises(ValueError, match=r"measured thrust is zero everywhere .*: fit torque alone"):
        fit_loads(data, prop, options=FitOptions(max_nfev=2))


def test_unit_notes_count_a_pitots_noise_as_static_and_name_grams_force():
    """Mutant A7 (static points for the unit check only below 0.1 m/s): a stand whose pitot reads
    0.2 m/s of noise (under STATIC_AIRSPEED, 0.3) is static, and its thrust in gf (CT ~100x) is said."""
    prop, data = _data(np.linspace(3000, 9000, 7), airspeed=0.2, scale={"thrust": 1 / 0.00980665})
    notes = _unit_notes(data, prop, ["thrust", "torque"], Air())
    assert len(notes) == 1
    ct = float(notes[0].split("CT is ")[1].split(" ")[0])
    assert 9.0 < ct < 20.0  # (a static CT of 0.09-0.2 in gf)
    assert "is the thrust in N?" in notes[0]


def test_unit_notes_say_a_static_ct_above_0_6():
    """Mutant A9 (STATIC_CT_RANGE's top 6 instead of 0.6): a thrust 8 times too large (CT ~1, a
    thrust in another unit, or the data of a larger rotor) is said; the model's own is not."""
    prop, data = _data(np.linspace(3000, 9000, 7), scale={"thrust": 8.0})
    notes = _unit_notes(data, prop, ["thrust", "torque"], Air())
    assert len(notes) == 1 and "outside the 0.02-0.6 of propellers" in notes[0]
    assert 0.6 < float(notes[0].split("CT is ")[1].split(" ")[0]) < 2.0
    assert _unit_notes(_data(np.linspace(3000, 9000, 7))[1], prop, ["thrust", "torque"], Air()) == []


def test_unit_notes_check_the_torque_when_only_the_torque_is_fitted():
    """Mutant A11 (the loop over thrust and torque stops at an unfitted thrust): a torque-only fit of a
    torque in N mm (CQ ~1000x) is still told its CQ is outside the range of propellers."""
    prop, data = _data(np.linspace(3000, 9000, 7), scale={"torque": 1000.0})
    notes = _unit_notes(data, prop, ["torque"], Air())
    assert len(notes) == 1 and "static CQ is" in notes[0] and "is the torque in N m?" in notes[0]
    assert 3.0 < float(notes[0].split("CQ is ")[1].split(" ")[0]) < 30.0


def test_a_drag_only_file_at_axial_points_is_refused_not_emptied():
    """Mutant A15 (an unfittable drag is dropped even where it is the only quantity measured): a file of
    the in-plane force alone at axial points would leave nothing to fit; fit_loads says why."""
    from propmap.identify.fit import _load_keys

    prop, d = _data(np.linspace(3000, 9000, 7), airspeed=10.0)
    data = LoadData(d.omega, d.airspeed, d.incidence, {"drag": np.full(d.n, 0.01)}, d.group, "audit")
    with pytest.raises(ValueError, match=r"the in-plane force \(drag\) cannot be fitted: no point .* above 0.3 m/s"):
        _load_keys(data, None)
    both = LoadData(d.omega, d.airspeed, d.incidence, {**d.measured, "drag": np.full(d.n, 0.01)}, d.group, "audit")
    assert _load_keys(both, None) == ["thrust", "torque"]  # (beside others it is left out, and said)


def test_a_constant_collective_is_not_a_collective_sweep():
    """Mutant A17 (any collective column makes a 'collective' run): a static run logged at one blade
    angle is static (its STATIC_DIRECTIONS apply); two angles make a collective sweep."""
    from propmap.identify.fit import _data_kind

    prop, d = _data(np.linspace(3000, 4000, 7))
    one = LoadData(d.omega, d.airspeed, d.incidence, d.measured, d.group, "audit", collective=np.full(d.n, 0.05))
    assert _data_kind(one) == "static"
    two = LoadData(d.omega, d.airspeed, d.incidence, d.measured, d.group, "audit",
                   collective=np.r_[np.full(4, 0.05), np.full(3, 0.1)])
    assert _data_kind(two) == "collective"


def test_each_rate_of_a_run_without_groups_is_a_level():
    """Mutant A22 (a run split one point early where its rates jump): one point at each of 4000, 5000
    and 6000 rpm at 10 m/s (a CSV without groups) are three rotation rates, so the Reynolds terms are
    fitted ("rates"); split early, the first part is empty and the last two merge into one level."""
    from propmap.identify.fit import _data_kind, _sweep_rates

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # (the mutant's median of an empty part)
        three = _data([4000.0, 5000.0, 6000.0], airspeed=10.0)[1]
        assert _sweep_rates(three) == 3 and _data_kind(three) == "rates"
        assert _sweep_rates(_data([5000.0, 6000.0], airspeed=10.0)[1]) == 2


def _fast_tip(mach):
    """Static data of apce_8x6 whose blade tips reach ``mach`` (CT 0.1, CQ 0.008: plausible loads)."""
    prop = pm.load_propeller(PROP)
    om = np.linspace(0.5, 1.0, 5) * mach * 340.3 / (prop.diameter / 2)
    n = om / (2 * math.pi)
    measured = {"thrust": 0.1 * 1.225 * n**2 * prop.diameter**4, "torque": 0.008 * 1.225 * n**2 * prop.diameter**5}
    return prop, LoadData(om, np.zeros(5), np.zeros(5), measured, np.full(5, "all", dtype=object), "fast.csv")


@pytest.mark.parametrize("mach, hint", [(0.85, False), (1.3, True)])
def test_a_fast_tip_is_warned_once_and_rpm_for_rad_s_only_past_mach_1(mach, hint):
    """Mutant A25 (the rpm-for-rad/s hint from tip Mach 0.5): tips at Mach 0.85 are near the end of the
    compressibility model (warned), not a unit slip; at Mach 1.3 the hint is given."""
    from propmap.identify.fit import CAMBERED_FIT, _load_residual

    prop, data = _fast_tip(mach)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _load_residual(data, prop, ["thrust", "torque"], Air(), CAMBERED_FIT, pm.default_params(PROP))
    said = [str(w.message) for w in caught if "blade tip meets the air at Mach" in str(w.message)]
    assert len(said) == 1 and f"Mach {mach:.2g} (> 0.8) in fast.csv" in said[0]
    assert ("rpm where rad/s is meant" in said[0]) is hint


def test_a_parked_point_leaves_the_fit_without_the_implicit_jacobian():
    """Mutant A28 (the implicit Jacobian attached where any point turns): a point below OMEGA_MIN
    (0.1 rad/s, parked) has no derivatives, so its data's residual differences the solver instead."""
    from propmap.identify.fit import CAMBERED_FIT, _load_residual

    prop = pm.load_propeller(PROP)
    base = pm.default_params(PROP)
    for om, attached in ((np.array([0.05, 300.0, 500.0, 700.0, 900.0]), False), (np.linspace(300, 900, 5), True)):
        n = om / (2 * math.pi)
        measured = {"thrust": 0.1 * 1.225 * n**2 * prop.diameter**4}
        data = LoadData(om, np.zeros(5), np.zeros(5), measured, np.full(5, "all", dtype=object), "audit")
        make, _ = _load_residual(data, prop, ["thrust"], Air(), CAMBERED_FIT, base)
        assert hasattr(make(FitOptions()), "with_jacobian") is attached


def test_as_many_thrust_values_as_static_directions_are_refused():
    """Mutant A30 (a fit with as many values as free parameters allowed): 3 static thrusts cannot identify
    the 3 parameter directions a static run frees (STATIC_DIRECTIONS): nothing would be left to judge it."""
    prop, data = _data([4000.0, 5000.0, 6000.0])
    with pytest.raises(ValueError, match=r"^3 points of thrust cannot identify 3 parameter directions$"):
        fit_loads(data, prop, quantities=("thrust",), options=FitOptions(max_nfev=2))


def test_the_unfitted_drag_is_said_only_where_the_quantities_were_not_chosen():
    """Mutant A31 (the 'measured drag is not fitted' note also where quantities= left it out): a user who
    chose thrust and torque is not told the drag was not fitted; by default (all measured) they are."""
    from propmap.identify import LoadData as LD

    prop, d = _data(np.linspace(4000, 6000, 5), airspeed=np.linspace(5, 12, 5))
    data = LD(d.omega, d.airspeed, d.incidence, {**d.measured, "drag": np.full(d.n, 0.01)}, d.group, "audit")
    note = "the measured drag is not fitted: no point has an in-plane airspeed above 0.3 m/s"
    chosen = fit_loads(data, prop, quantities=("thrust", "torque"), options=FitOptions(max_nfev=3))
    assert chosen.extra["quantities"] == ["thrust", "torque"]
    assert not any(w.startswith(note) for w in chosen.warnings)
    default = fit_loads(data, prop, options=FitOptions(max_nfev=3))
    assert default.extra["quantities"] == ["thrust", "torque"]
    assert sum(w.startswith(note) for w in default.warnings) == 1


def test_the_joint_fit_refuses_as_many_values_as_parameters():
    """Mutant A40 (a joint fit with exactly as many load values as parameters allowed): one point's
    thrust and torque cannot identify two parameters."""
    from propmap.identify import fit_loads_joint

    prop, data = _data([5000.0])
    opts = FitOptions(names=("cl_alpha", "cd_min"), max_nfev=2)
    with pytest.raises(ValueError, match=r"^datasets: 2 fitted load values cannot identify 2 parameters$"):
        fit_loads_joint([(data, prop)], options=opts)


def test_the_joint_fit_solves_each_data_set_at_the_density_it_logged():
    """Mutant A41 (every propeller's per_propeller rho the first data set's): data logged at 1.1 kg/m^3
    beside data logging none are solved at 1.1 and at the base's 1.225, and the result's air is the base's."""
    from propmap.identify import fit_loads_joint

    prop, a = _data(np.linspace(4000, 6000, 4))
    _, b = _data(np.linspace(4000, 6000, 4))
    b = LoadData(b.omega, b.airspeed, b.incidence, b.measured, b.group, "thin", air_density=1.1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = fit_loads_joint([(a, prop), (b, prop)], options=FitOptions(names=("cl_alpha", "cd_min"), max_nfev=2))
    assert [p["rho"] for p in res.extra["per_propeller"]] == [pytest.approx(1.225), pytest.approx(1.1)]
    assert res.air.rho == pytest.approx(1.225)


def test_the_joint_fit_names_an_empty_list_and_a_pair_that_is_not_one():
    """Mutants A42 (no check for an empty list of data sets) and A43 (a dataset of three items
    unpacked into the checks): each is said as itself, not as a confusing count or a stray argument."""
    from propmap.identify import fit_loads_joint

    with pytest.raises(ValueError, match=r"^fit_loads_joint needs at least one \(data, propeller\) pair$"):
        fit_loads_joint([])
    prop, data = _data([4000.0, 5000.0, 6000.0])
    with pytest.raises(TypeError, match=r"^datasets\[0\] must be a \(LoadData, Propeller\) pair, got tuple$"):
        fit_loads_joint([(data, prop, 1.0)])


@pytest.mark.parametrize("M, base", [(0.0, None), (2e6, "gill2017-apc"), (-1.0, None)])
def test_fit_m_is_refused_outside_0_to_1e6(M, base):
    """Mutants B1 (--M 0 accepted) and B2 (M_MAX 1e7): the stall-blend sharpness is in (0, 1e6] 1/rad
    (0 is no blend at all; as parameter files accept), refused before any work with the range said."""
    from propmap.cli._common import InputError, load_params
    from propmap.cli.fit import FitChoice, _options

    args = () if base is None else load_params(base, option="--base")[::2]
    with pytest.raises(InputError, match=r"^--M must be finite and in \(0, 1e\+06\] 1/rad, got "):
        _options(FitChoice(M=M), *args)
    assert _options(FitChoice(M=1e6)).M == 1e6


@pytest.mark.parametrize("starts", [-1, 257])
def test_fit_multistart_outside_0_to_256_is_an_input_error(starts):
    """Mutant B3 (no lower bound on --multistart): -1 extra starts is refused as the option's
    error (exit 2, the range said), not as FitOptions's ValueError from inside."""
    from propmap.cli._common import InputError
    from propmap.cli.fit import FitChoice, _options

    with pytest.raises(InputError, match=rf"^--multistart must be in \[0, 256\] \(each start is a whole fit\), "
                                         rf"got {starts}$"):
        _options(FitChoice(multistart=starts))
    assert _options(FitChoice(multistart=256)).multistart == 256


def test_held_out_worse_needs_25_percent_and_2_percent_of_the_largest():
    """Mutant B12 (the factor 1.25 as 1.0): a held-out rmse 20% above the base set's (0.24 N against 0.2 N,
    4% of the largest 1 N thrust) is not said; 30% above is."""
    from propmap.cli._load_comparison import held_out_worse

    base, largest = {"thrust_rmse": 0.2, "torque_rmse": 0.01}, {"thrust": 1.0, "torque": 0.1}
    assert held_out_worse({"thrust_rmse": 0.24, "torque_rmse": 0.01}, base, largest, ["thrust", "torque"]) == []
    assert held_out_worse({"thrust_rmse": 0.26, "torque_rmse": 0.01}, base, largest, ["thrust", "torque"]) == ["thrust"]
    assert held_out_worse({"thrust_rmse": 0.26}, base, largest, ["torque"]) == []


def _csv(tmp_path, groups=("a", "a", "a", "b", "b", "b")):
    """A static stand's CSV of apce_8x6 (its default set's loads) with a group column."""
    rpm = np.linspace(3000.0, 8000.0, len(groups))
    _, d = _data(rpm)
    path = tmp_path / "stand.csv"
    rows = zip(rpm, d.measured["thrust"], d.measured["torque"], groups)
    path.write_text("rpm,thrust,torque,group\n" + "".join(f"{r:.1f},{t:.6f},{q:.7f},{g}\n" for r, t, q, g in rows))
    return path


def test_holding_out_every_run_of_a_csv_is_refused(tmp_path):
    """Mutant B17 (refused only where the held-out runs exceed the file's): holding out both runs of a
    two-run CSV leaves nothing to fit, and is said before any fit, with the runs named; no file written."""
    from click.testing import CliRunner

    from propmap.cli.main import cli

    out = tmp_path / "p.toml"
    res = CliRunner().invoke(cli, ["fit", "loads", str(_csv(tmp_path)), "--prop", PROP, "--holdout", "a,b",
                                   "--out", str(out)])
    assert res.exit_code == 2
    assert "--holdout: every run of SOURCE is held out (a, b); keep at least one to fit" in res.output
    assert not out.exists()


def test_a_fits_value_error_is_the_commands_input_error():
    """Mutant B25 (fit loads's ValueErrors not turned into its input error): too few points for the
    directions a static run frees is a one-line error (exit 2), not a traceback."""
    from propmap.cli._common import InputError
    from propmap.cli.fit import _run_fit

    prop, data = _data([4000.0, 5000.0, 6000.0])
    with pytest.raises(InputError, match=r"^3 points of thrust cannot identify 3 parameter directions$"):
        _run_fit(fit_loads, data, prop, quantities=("thrust",), options=FitOptions(max_nfev=2))


def test_loads_far_off_the_generic_models_are_refused_unless_told(tmp_path):
    """Mutant B26 (the sanity check's refusal applied only with --skip-sanity-check): a stand's thrust 6
    times the generic model's (a unit slip?) stops the command before the fit, and says how to go on."""
    from click.testing import CliRunner

    from propmap.cli.main import cli

    path = _csv(tmp_path)
    text = path.read_text().splitlines()
    rows = [line.split(",") for line in text[1:]]
    path.write_text("\n".join([text[0]] + [f"{r},{6 * float(t):.6f},{q},{g}" for r, t, q, g in rows]) + "\n")
    out = tmp_path / "p.toml"
    res = CliRunner().invoke(cli, ["fit", "loads", str(path), "--prop", PROP, "--out", str(out)])
    assert res.exit_code == 2, res.output
    assert "SOURCE: " in res.output and "(--skip-sanity-check fits it anyway)" in res.output
    assert not out.exists()


def test_no_prior_reaches_the_fit_options():
    """Mutant B27 (--no-prior dropped on the way to FitOptions): the cambered fit is then without the
    catalogue's population prior; without the flag, with it."""
    from propmap.cli._common import load_params
    from propmap.cli.fit import FitChoice, _options

    base, _, label = load_params("generic", option="--base")
    assert _options(FitChoice(no_prior=True), base, label).prior is False
    assert _options(FitChoice(), base, label).prior is True


def test_the_coverage_of_load_data_in_units_said():
    """Mutants B9 (J with the radius for the diameter), B10 (a descent's negative J kept), B11 (rpm_max in
    rev/s) and B31 (incidence_deg_max in rad): the [coverage] a fitted file records is J = V cos(incidence)
    / (n D), rpm and degrees; data all in descent have J_max 0."""
    from propmap.cli.fit import _coverage

    rpm = np.array([4000.0, 5000.0, 6000.0])
    prop, data = _data(rpm, airspeed=np.array([6.0, 10.0, 8.0]), incidence=math.radians(30.0))
    cov = _coverage(data, prop, Air())
    assert cov["J_max"] == pytest.approx(10.0 * math.cos(math.radians(30.0)) / (5000.0 / 60 * 0.2032), rel=1e-12)
    assert cov["J_max"] == pytest.approx(0.5114, abs=1e-4)
    assert (cov["rpm_min"], cov["rpm_max"]) == (pytest.approx(4000.0), pytest.approx(6000.0))
    assert cov["incidence_deg_max"] == pytest.approx(30.0) and cov["airspeed_max"] == 10.0
    assert cov["propeller"] == PROP and cov["diameter_m"] == 0.2032 and cov["re75_min"] < cov["re75_max"]
    _, descent = _data(rpm, airspeed=8.0, incidence=math.pi)
    assert _coverage(descent, prop, Air())["J_max"] == 0.0


def test_the_written_reports_keep_every_warning_and_the_terminal_the_first_three(tmp_path, capsys):
    """Mutants B21 (MAX_WARNINGS 30), B22 (the 'N more' line only past 4), B29 (the data warnings left out
    of the JSON report) and B30 (the report on standard output repeats the warnings standard error gives):
    four fit warnings print three and '1 more in p.report.txt'; both reports keep all and the data's."""
    import dataclasses
    import json

    from propmap.cli.fit import _write_outputs

    prop, data = _data([4000.0, 5000.0, 6000.0, 7000.0, 8000.0])
    res = fit_loads(data, prop, options=FitOptions(max_nfev=2))
    said = tuple(f"audit warning {i}" for i in range(4))
    res = dataclasses.replace(res, warnings=said)
    capsys.readouterr()
    _write_outputs(res, tmp_path / "p.toml", "generic", False, data_warnings=["a data warning"])
    out, err = capsys.readouterr()
    assert [line for line in err.splitlines() if line.startswith("propmap: warning:")] == [
        *(f"propmap: warning: {w}" for w in said[:3]), "propmap: warning: 1 more in p.report.txt"]
    assert "audit warning" not in out and "a data warning" not in out
    report = json.loads((tmp_path / "p.report.json").read_text())
    assert report["data_warnings"] == ["a data warning"] and report["warnings"] == list(said)
    text = (tmp_path / "p.report.txt").read_text()
    assert all(w in text for w in said) and "DATA WARNING: a data warning" in text


def test_the_held_out_rmse_of_a_csv_is_over_the_held_out_group(tmp_path):
    """Mutants B23 (the held-out rmse taken over the fitted points) and B33 (the file's coverage without
    its held-out runs): with run b of a stand CSV held out, the base set's thrust and torque rmse in the
    report are its errors at b's three points [N, N m], and the file records a fitted, b held out (a holds six:
    a fit needs six distinct points, held-out runs aside, since 2026-12-01)."""
    import json

    from click.testing import CliRunner

    from propmap.cli.main import cli
    from propmap.io.calibration import generic_params

    out = tmp_path / "p.toml"
    res = CliRunner().invoke(cli, ["fit", "loads", str(_csv(tmp_path, ("a",) * 6 + ("b",) * 3)), "--prop", PROP,
                                   "--holdout", "b", "--out", str(out)])
    assert res.exit_code == 0, res.output
    report = json.loads((tmp_path / "p.report.json").read_text())
    held = report["extra"]["holdout"] if "extra" in report else report["holdout"]
    assert held["holdout"] == ["b"]
    from propmap.io.params_file import read_coverage

    cov = read_coverage(out)
    assert list(cov["groups"]) == ["a"] and list(cov["held_out"]) == ["b"] and cov["rpm_max"] == pytest.approx(6125.0)
    prop, data = _data(np.linspace(3000.0, 8000.0, 9))
    r = pm.rotor_loads(prop, generic_params(), data.omega[6:], data.airspeed[6:], 0.0)
    for k, model in (("thrust", r.thrust), ("torque", r.torque)):
        rmse = float(np.sqrt(np.mean((model - data.measured[k][6:]) ** 2)))
        assert held["generic"][f"{k}_rmse"] == pytest.approx(rmse, rel=1e-3, abs=1e-6)
        assert rmse > 1e-3 * float(np.max(np.abs(data.measured[k])))  # (the two sets differ there)


def test_the_joint_fits_residual_runs_end_at_each_propeller():
    """Mutant A50 (the joint fit's runs keyed without the propeller): two data sets whose runs share a
    label ('all') are still two runs each, so the residuals' lag-1 autocorrelation is that of differently
    labelled runs (no lag pair across the propellers); the fit itself does not see the labels."""
    from propmap.identify import fit_loads_joint

    prop, a = _data(np.linspace(4000, 8000, 5))
    _, b = _data(np.linspace(3000, 9000, 5), scale={"thrust": 1.1, "torque": 0.95})
    other = LoadData(b.omega, b.airspeed, b.incidence, b.measured, np.full(b.n, "other", dtype=object), "b")
    opts = FitOptions(names=("cl_alpha", "cd_min"), max_nfev=2)
    same = fit_loads_joint([(a, prop), (b, prop)], options=opts)
    apart = fit_loads_joint([(a, prop), (other, prop)], options=opts)
    np.testing.assert_array_equal(same.residuals, apart.residuals)
    assert same.extra["residual_autocorrelation"] is not None
    assert same.extra["residual_autocorrelation"] == apart.extra["residual_autocorrelation"]

