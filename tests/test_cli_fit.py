"""``propmap fit`` through main([...]): outputs, round trip, bad data exits 2 with one line."""

import json
from importlib import resources

import pytest
from cli_helpers import run

import propmap as pm
from propmap.cli.main import main

EXAMPLES = resources.files("propmap") / "data" / "examples"
VEHICLE = str(EXAMPLES / "quadrotor.toml")
FLIGHT = str(EXAMPLES / "level_flight_synthetic.csv")


def test_fit_level_flight_writes_params_report_and_figure(capsys, tmp_path):
    out = tmp_path / "p.toml"
    code, stdout, err = run(capsys, "fit", "level-flight", FLIGHT, "--vehicle", VEHICLE, "--out", str(out),
                            "--M", "30", "--json")
    assert code == 0, err
    rep = json.loads(stdout)
    assert set(rep["fitted"]) == {"cl1", "cl2", "cd", "alpha0_deg"}
    idf = rep["identifiability"]
    assert "cd" in idf["poorly_determined"]  # noisy synthetic data: cd poorly determined,
    assert any("cl2" in w for w in idf["warnings"])  # cl2 named (here via its -1.00 correlation with alpha0)
    assert len(rep["residuals"]) == 20
    for name in ("p.toml", "p.report.json", "p.report.txt", "p.png"):
        assert (tmp_path / name).stat().st_size > 100
    params = pm.read_params(out)
    assert params.M == 30.0 and params.cl1 == pytest.approx(rep["fitted"]["cl1"])
    # the fitted file is accepted back by loads and validate
    assert run(capsys, "loads", "apce_8x6", "--rpm", "6000", "--params", str(out))[0] == 0
    assert run(capsys, "validate", "apce_8x6", "--params", str(out), "--figure", str(tmp_path / "v.png"))[0] == 0
    # and records what its data covered (it wrote no [coverage]: a JSON audit, 2026-11-26): the vehicle's
    # propeller, its rates and airspeeds, so that another propeller and other rates are warned of
    assert rep["coverage"]["propeller"] == "apce_8x6" and rep["coverage"]["airspeed_max"] == 14.0
    assert 80 < rep["coverage"]["incidence_deg_max"] < 90  # (level flight: near edgewise; hover rows not counted)
    code, _, err = run(capsys, "loads", "apce_10x7", "--rpm", "9000", "--params", str(out))
    assert code == 0 and "fitted to data of apce_8x6" in err and "the data behind" in err, err


def test_fit_loads_catalogue_with_holdout(capsys, tmp_path):
    out = tmp_path / "f.toml"
    code, stdout, err = run(capsys, "fit", "loads", "apce_8x6", "--holdout", "2801rd,2802rd", "--out", str(out))
    assert code == 0, err
    # regression value (2026-11-21): the cambered model fitted without the 6000 rpm sweeps
    # predicts them to CT rmse 0.0025 (the paper's model fitted the same way: 0.0322)
    assert "held-out (2801rd, 2802rd) CT rmse: fitted 0.002" in stdout
    rep = json.loads((tmp_path / "f.report.json").read_text())
    assert rep["holdout"]["fitted"]["ct_rmse"] < 0.5 * rep["holdout"][rep["base"]]["ct_rmse"]
    assert rep["propmap_version"] == pm.__version__  # (recorded as maps and exports do: a JSON audit)
    # judging held-out runs, the base (and the prior) come from the catalogue half without apce_8x6
    from propmap.io.calibration import generic_without

    assert rep["params"]["section_model"] == "cambered" and rep["base"] == generic_without("apce_8x6")[1]


def _flight(tmp_path, text):
    p = tmp_path / "d.csv"
    p.write_text(text)
    return str(p)


H = "airspeed,pitch_deg,rpm_1,rpm_2,rpm_3,rpm_4\n"
ROWS = "".join(f"{k},{-k},5000,5000,5000,5000\n" for k in range(8))


@pytest.mark.parametrize(
    "text, match",
    [
        ("airspeed,rpm_1,rpm_2,rpm_3,rpm_4\n" + "1,5000,5000,5000,5000\n" * 8, "lacks column(s) pitch_deg"),
        (H + ROWS + "9,nan,5000,5000,5000,5000\n", "line 10"),
        (H + "".join(ROWS.splitlines(keepends=True)[:3]), "at least 6"),
        (H + "1,-1,5000,5000,5000,5000\n" * 8, "identical"),
        ("airspeed,pitch_deg,rpm_1,rpm_2\n" + "1,-1,5000,5000\n" * 8, "4 rotors"),
    ],
)
def test_fit_level_flight_bad_data_exits_2(capsys, tmp_path, text, match):
    code, _, err = run(capsys, "fit", "level-flight", _flight(tmp_path, text), "--vehicle", VEHICLE,
                       "--out", str(tmp_path / "p.toml"))
    assert code == 2 and match in err and err.count("\n") == 1
    assert not (tmp_path / "p.toml").exists()


@pytest.mark.parametrize(
    "argv, match",
    [
        (["fit", "loads", "apce_8x6", "--holdout", "nope"], "unknown run"),
        (["fit", "loads", "apce_8x6", "--holdout", "static_2797rd"], "static run"),
        (["fit", "loads", "nosuch.csv"], "neither a catalogue propeller nor a file"),
        (["fit", "loads", "apce_8x6", "--M", "-3"], "--M"),
        (["fit", "loads", "apce_8x6", "--M", "5000"], "--M must be in (0, 1000] 1/rad for the cambered model"),
        (["fit", "level-flight", FLIGHT, "--vehicle", "missing.toml"], "--vehicle"),
    ],
)
def test_fit_bad_arguments_exit_2(capsys, tmp_path, argv, match):
    code, _, err = run(capsys, *argv, "--out", str(tmp_path / "p.toml"))
    assert code == 2 and match in err and err.count("\n") == 1


def test_fit_loads_csv_needs_prop(capsys, tmp_path):
    p = tmp_path / "l.csv"
    p.write_text("rpm,airspeed,incidence_deg,thrust\n" + "".join(f"{5000 + 100 * k},1,0,2\n" for k in range(8)))
    code, _, err = run(capsys, "fit", "loads", str(p), "--out", str(tmp_path / "p.toml"))
    assert code == 2 and "--prop" in err


def test_fit_loads_csv_with_prop_and_holdout(capsys, tmp_path):
    from .test_identify import TRUE_X, _loads_csv

    src = _loads_csv(tmp_path, pm.load_propeller("apce_8x6"))  # T, D, Q made with gill2017-apc at M = 30
    out = tmp_path / "c.toml"
    code, stdout, err = run(capsys, "fit", "loads", str(src), "--prop", "apce_8x6", "--holdout", "g2", "--M", "30",
                            "--base", "gill2017-apc", "--out", str(out), "--json")
    assert code == 0, err
    rep = json.loads(stdout)
    assert rep["holdout"]["holdout"] == ["g2"]
    assert rep["holdout"]["fitted"]["thrust_rmse"] < 1e-6  # the CSV is consistent with the model
    params = pm.read_params(out)
    assert params.cl1 == pytest.approx(TRUE_X[0], rel=1e-5)
    assert (tmp_path / "c.png").stat().st_size > 10_000


@pytest.mark.parametrize("extra, match", [
    (["--base", "gill2017-apc"], "--directions applies to the cambered model; --base gill2017-apc"),
    (["--no-prior"], "with --no-prior there is none"),
    (["--fit-params", "cl_alpha,cd_min"], "--fit-params chooses the parameters instead"),
])
def test_directions_with_options_that_would_ignore_them_are_refused(capsys, tmp_path, extra, match):
    """They were warned about ("directions ignored") and the fit ran without them."""
    code = main(["fit", "loads", "apce_8x6", "--directions", "2", *extra, "--out", str(tmp_path / "p.toml")])
    err = capsys.readouterr().err
    assert code == 2 and match in err and err.count("\n") == 1, err
    assert not (tmp_path / "p.toml").exists()


def test_quantities_not_measured_is_refused_naming_the_option(capsys, tmp_path):
    src = tmp_path / "q.csv"
    src.write_text("rpm,thrust,torque\n" + "".join(f"{3000 + 1000 * k},{0.5 + k / 2},{0.01 + k / 100}\n"
                                                   for k in range(6)))
    code = main(["fit", "loads", str(src), "--prop", "apce_8x6", "--quantities", "drag", "--out",
                 str(tmp_path / "p.toml")])
    err = capsys.readouterr().err
    assert code == 2 and "--quantities: 'drag' is not measured in SOURCE (measured: thrust, torque)" in err, err


def test_a_fit_to_descent_data_writes_a_file_that_reads_back(tmp_path, capsys):
    """Data all in descent (incidence 150 deg): the [coverage] table's J_max, the largest climb
    advance ratio, is 0 (it was the negative V cos(incidence) / (n D), which read_params refuses)."""
    prop = pm.load_propeller("apce_8x6")
    rows = []
    for rpm in (4000.0, 5000.0, 6000.0):
        for V in (2.0, 4.0, 6.0):
            r = pm.rotor_loads(prop, pm.default_params("apce_8x6"), rpm * 3.141592653589793 / 30, V,
                               2.6179938779914944)
            rows.append(f"{rpm},{V},150,{float(r.thrust):.6g},{float(r.torque):.6g}")
    src = tmp_path / "descent.csv"
    src.write_text("rpm,airspeed,incidence_deg,thrust,torque\n" + "\n".join(rows) + "\n")
    out = tmp_path / "d.toml"
    assert main(["fit", "loads", str(src), "--prop", "apce_8x6", "--out", str(out)]) == 0, capsys.readouterr().err
    capsys.readouterr()
    from propmap.io.params_file import read_coverage

    cov = read_coverage(out)
    assert cov["J_max"] == 0.0 and cov["incidence_deg_max"] == 150.0
    pm.read_params(out)


def test_the_load_figure_says_open_markers_are_held_out_only_where_some_are(monkeypatch, tmp_path):
    """The title said "(open markers: held out)" of a fit that held nothing out (a new-user
    audit, 2026-11-27)."""
    import numpy as np

    import propmap.plots as plots
    from propmap.identify.load_data import LoadData

    titles = []

    def keep(fig, path):
        titles.append(fig._suptitle.get_text())
        return path

    monkeypatch.setattr(plots, "_save", keep)
    data = LoadData(np.full(4, 800.0), np.zeros(4), np.zeros(4), {"thrust": np.array([1.0, 1.1, 1.2, 1.3])},
                    np.zeros(4, int))
    model = {"fitted": {"thrust": np.array([1.0, 1.12, 1.18, 1.31])}}
    plots.plot_load_parity(data, model, np.zeros(4, bool), tmp_path / "a.png", title="load fit")
    plots.plot_load_parity(data, model, np.array([False, False, True, True]), tmp_path / "b.png", title="load fit")
    assert titles == ["load fit", "load fit (open markers: held out)"]
