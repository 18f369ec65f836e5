"""Stop 104: a figure's file extension gives its format, and any other extension is refused before drawing
(a ``.jpg`` path got PNG bytes under its name, and an extension-less path a PNG, until stop 104)."""

from __future__ import annotations

import inspect

import numpy as np
import pytest
from cli_helpers import run

import propmap as pm
import propmap.plots as plots
import propmap.plots_flight as plots_flight
from propmap.simexport import predict

#: every public figure function, by the module that holds it
FIGURES = [getattr(m, n) for m in (plots, plots_flight) for n in m.__all__ if n.startswith("plot_")]


def test_every_figure_function_is_listed():
    """The list above misses none: every ``plot_*`` function of both modules is in its ``__all__``."""
    found = {n for m in (plots, plots_flight) for n, f in vars(m).items()
             if n.startswith("plot_") and inspect.isfunction(f) and f.__module__ == m.__name__}
    assert found == {f.__name__ for f in FIGURES}
    assert len(FIGURES) == 10


@pytest.mark.parametrize("name", ["fig.jpg", "fig", "fig.png.txt", "fig.eps"])
@pytest.mark.parametrize("figure", FIGURES, ids=lambda f: f.__name__)
def test_an_extension_that_is_not_png_pdf_or_svg_is_refused_before_drawing(figure, name, tmp_path, monkeypatch):
    def no_drawing(*args, **kw):
        raise AssertionError("drew a figure it then could not write")

    monkeypatch.setattr(plots, "_figure", no_drawing)
    n_args = sum(p.default is p.empty and p.kind == p.POSITIONAL_OR_KEYWORD
                 for p in inspect.signature(figure).parameters.values())
    args = [None] * (n_args - 1) + [tmp_path / name]  # (the path is each one's last positional argument)
    suffix = name.rpartition(".")[2] if "." in name else "none"
    with pytest.raises(ValueError, match=rf"a figure's extension gives its format, one of \.png, \.pdf, \.svg; "
                                         rf"got \.?{suffix}"):
        figure(*args)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name, magic", [("f.PNG", b"\x89PNG"), ("f.pdf", b"%PDF"), ("f.Svg", b"<?xml")])
def test_the_extension_in_any_case_gives_the_format_written(name, magic, tmp_path):
    loads = {k: np.linspace(1.0, 2.0, 6) for k in ("thrust", "drag", "torque")}
    out = plots_flight.plot_flight_speed(np.linspace(0.0, 2.0, 6), loads, loads, {"m": np.zeros(6)}, tmp_path / name)
    assert out == tmp_path / name
    assert out.read_bytes().startswith(magic)


# ---- a catalogue set of the same blade on another hub (UIUC vol. 2's _3b and _4b) -----------------------------------

def test_a_set_calibrated_on_the_same_blade_on_another_hub_is_warned_of_as_such(capsys):
    """``calibrated:da4022_5x3.75`` on ``da4022_5x3.75_3b`` was warned of as "no better than the generic set", where it
    predicts the 3-blade hub's runs to 2.5% of static CT and the generic set to 12.7% (docs/cli.md); the
    warning now says what such sets did on UIUC's other hubs. Its errors are not labelled in-sample either: the data
    are the 3-blade hub's own."""
    code, out, err = run(capsys, "validate", "da4022_5x3.75_3b", "--params", "calibrated:da4022_5x3.75")
    assert code == 0
    assert "calibrated on the same blade on another hub: such a set predicted UIUC's 3- and 4-blade hubs" in err
    assert "no better than the generic set" not in err
    assert "in-sample" not in out  # (the set was not fitted to these runs)
    code, out, err = run(capsys, "validate", "da4022_5x3.75", "--params", "calibrated:da4022_5x3.75")
    assert code == 0 and "in-sample" in out and "another hub" not in err  # (its own runs: its fit's residual)
    code, _, err = run(capsys, "validate", "da4022_5x3.75_3b", "--params", "calibrated:apce_8x6")
    assert code == 0 and "no better than the generic set" in err and "another hub" not in err


def test_the_hub_rule_compares_the_blade_not_only_the_size():
    """Blades equal but for their count: the other hub; another blade of the same size and count: not."""
    from propmap.cli._common import _catalogue_geometry

    three = pm.load_propeller("da4022_5x3.75_3b")
    assert _catalogue_geometry("da4022_5x3.75", three) == "other hub"
    assert _catalogue_geometry("da4022_5x3.75_3b", three) is True
    assert _catalogue_geometry("nr640_5_15deg", pm.load_propeller("nr640_5_15deg_4b")) == "other hub"
    assert _catalogue_geometry("apce_8x6", three) is False
    assert _catalogue_geometry("no_such_propeller", three) is False


# ---- a figure's inputs: what it cannot draw is refused, not written as an empty figure (a helper's audit) -----------

@pytest.mark.parametrize("path, error, said", [
    (None, TypeError, r"path must be a file path \(str or os.PathLike\), got NoneType"),
    (3, TypeError, r"path must be a file path \(str or os.PathLike\), got int"),
    ("t.png/", ValueError, r"path is empty or names no file \('t.png/'\)"),
    ("", ValueError, "path is empty or names no file"),
])
def test_a_figure_path_that_is_no_file_path_is_refused_naming_it(path, error, said):
    with pytest.raises(error, match=said):
        plots.plot_cases({"beaver": None}, path)


def test_a_folder_named_like_a_figure_is_refused_before_drawing(tmp_path, monkeypatch):
    (tmp_path / "f.png").mkdir()
    monkeypatch.setattr(plots, "_figure", lambda *a, **k: pytest.fail("drew a figure it then could not write"))
    with pytest.raises(ValueError, match=r"f.png' is a folder: give the figure's file"):
        plots.plot_cases({"beaver": None}, tmp_path / "f.png")


def _loads(n):
    return {k: np.ones(n) for k in ("thrust", "drag", "torque")}


@pytest.mark.parametrize("speed, said", [
    ([2e7, 1.0, 1.0], r"speed: give speeds \[m/s\] in \[0, 1000\], got 1 to 2e\+07"),  # (2e7 bins took minutes)
    ([-1.0, 1.0, 1.0], r"in \[0, 1000\], got -1 to 1"),
    ([0.5, 1.5, 2.5], "no 1 m/s bin holds the 3 samples a median needs"),  # (an empty figure)
    ([2.0, 2.0, 1.5], "no 1 m/s bin holds the 3 samples"),  # (counted in a closed last bin, drawn in none)
])
def test_the_speed_figure_refuses_speeds_it_cannot_bin(speed, said, tmp_path):
    with pytest.raises(ValueError, match=said):
        plots_flight.plot_flight_speed(speed, _loads(3), _loads(3), {"m": np.zeros(3)}, tmp_path / "s.png")
    assert list(tmp_path.iterdir()) == []


def test_the_cases_figure_refuses_no_case_it_draws(tmp_path):
    with pytest.raises(ValueError, match=r"cases: none of apc10x7e, dji9443, beaver, gill2019 among \['x'\]"):
        plots.plot_cases({"x": 1}, tmp_path / "c.png")
    with pytest.raises(TypeError, match="cases must be a dict of case name -> CaseResult, got list"):
        plots.plot_cases([], tmp_path / "c.png")


@pytest.mark.parametrize("value", [0.0, float("nan"), -0.01])
def test_the_cv_figure_refuses_an_error_a_log_axis_cannot_show(value, tmp_path):
    rows = [{"blind": {"rms_ct": 0.05, "rms_cp": 0.04}}, {"blind": {"rms_ct": value, "rms_cp": 0.03}}]
    with pytest.raises(ValueError, match="1 rms errors not finite and positive"):
        plots.plot_cv_summary({"summary": {"blind": {}}, "propellers": rows}, tmp_path / "c.png")
    with pytest.raises(ValueError, match="0 rms errors not finite and positive .*, among 0"):
        plots.plot_cv_summary({"summary": {"blind": {}}, "propellers": []}, tmp_path / "c.png")


def test_the_parity_figure_checks_its_mask_and_models(tmp_path):
    from types import SimpleNamespace

    data = SimpleNamespace(measured={"thrust": np.array([1.0, 2.0, 3.0])})
    model = {"fitted": {"thrust": np.array([1.1, 2.0, 2.9])}}
    with pytest.raises(ValueError, match=r"plot_load_parity: held_mask must be an array of booleans of shape \(3,"):
        plots.plot_load_parity(data, model, [0, 1, 0], tmp_path / "p.png")
    with pytest.raises(ValueError, match=r"plot_load_parity: held_mask must have shape \(3,\), one boolean per row"):
        plots.plot_load_parity(data, model, np.zeros(2, bool), tmp_path / "p.png")
    with pytest.raises(ValueError, match="model: give label -> loads with each measured one .*got 0 sets"):
        plots.plot_load_parity(data, {}, np.zeros(3, bool), tmp_path / "p.png")
    with pytest.raises(ValueError, match="got 1 sets, missing thrust"):
        plots.plot_load_parity(data, {"fitted": {"drag": np.ones(3)}}, np.zeros(3, bool), tmp_path / "p.png")
    assert list(tmp_path.iterdir()) == []
    plots.plot_load_parity(data, model, [False, True, False], tmp_path / "p.png")  # (a list of bools is taken)
    assert (tmp_path / "p.png").read_bytes().startswith(b"\x89PNG")


def test_the_envelope_figure_refuses_a_hover_thrust_of_zero(tmp_path):
    import pandas as pd

    table = pd.DataFrame({"airspeed": [0.0, 5.0], "incidence_deg": [90.0, 90.0], "thrust": [2.0, 2.1],
                          "drag": [0.0, 0.1], "thrust_hover": [0.0, 0.0]})
    with pytest.raises(ValueError, match=r"the largest \|thrust_hover\| must be finite and > 0, got 0.0"):
        plots.plot_envelope(table, tmp_path / "e.png")


def test_the_contour_figure_checks_its_map_and_rpm(tmp_path):
    from test_stop102 import _map_ds

    ds = _map_ds([0.0, 5.0, 10.0])
    for rpm in (None, -5.0, float("inf")):  # (None: xarray's KeyError; the others drew the nearest row)
        with pytest.raises(ValueError, match=r"rpm must be a finite number in \(0, inf\) rpm"):
            plots.plot_map_contours(ds, rpm, tmp_path / "m.png")
    with pytest.raises(ValueError, match=r"rpm must lie within the map's rpm axis \[6000, 6000\], got 7000"):
        plots.plot_map_contours(ds, 7000.0, tmp_path / "m.png")
    with pytest.raises(TypeError, match="ds must be a map .* got dict"):
        plots.plot_map_contours({}, 6000.0, tmp_path / "m.png")
    blank = ds.assign(thrust=ds["thrust"] * np.nan)
    with pytest.raises(ValueError, match="the map has no finite thrust at 6000 rpm: nothing to draw"):
        plots.plot_map_contours(blank, 6000.0, tmp_path / "m.png")
    assert list(tmp_path.iterdir()) == []


def test_the_contour_figure_takes_a_rotor_map(small_map, tmp_path):
    from propmap.rotormap import RotorMap

    out = plots.plot_map_contours(RotorMap(small_map[2]), 6500.0, tmp_path / "m.svg")  # ('sel' until stop 104)
    assert out.read_bytes().lstrip().startswith(b"<?xml")
    top = float(small_map[2]["rpm"].max())
    plots.plot_map_contours(small_map[2], top * (1 + 1e-12), tmp_path / "t.png")  # (an end node to round-off)


def test_validate_takes_a_figure_extension_in_any_case(capsys, tmp_path):
    """The CLI's check of --figure and the plots' agree (an upper-case .PNG passes both)."""
    code, _, err = run(capsys, "validate", "apce_8x6", "--figure", tmp_path / "v.PNG")
    assert code == 0, err
    assert (tmp_path / "v.PNG").read_bytes().startswith(b"\x89PNG")


# ---- simexport.predict's coefficients (a helper's bad-input audit) ---------------------------------------------------

_MULTINOMIAL = {"R": 0.1, "rho": 1.225, "CT": [0.01, -0.05, 0.0, 0.02, 0.0, 0.0], "CH": [0.01, 0.0, 0.0, 0.0],
                "CQ": [0.001, 0.0, 0.0, 0.0, 0.0, 0.0], "CR": [0.0, 0.0, 0.0, 0.0]}


@pytest.mark.parametrize("change, error, said", [
    ({"CT": [1.0, 1.0]}, ValueError, r"coefficients\['CT'\] must be a list of 6 numbers, one per term, got \[1.0, 1"),
    ({"CH": [0.0] * 6}, ValueError, r"coefficients\['CH'\] must be a list of 4 numbers"),
    ({"CQ": "000000"}, ValueError, r"coefficients\['CQ'\] must be a list of 6 numbers"),
    ({"R": 0.0}, ValueError, r"coefficients\['R'\] must be a finite number in \(0, inf\), got 0.0"),  # (NaN loads)
    ({"rho": -1.0}, ValueError, r"coefficients\['rho'\] must be a finite number in \(0, inf\)"),
    ({"CT": [0.01, float("nan"), 0, 0, 0, 0]}, ValueError, r"coefficients\['CT'\]\[1\] must be a finite number"),
    ({"CR": None}, KeyError, r"coefficients has no 'CR', a term of the multinomial model"),
])
def test_predict_refuses_a_multinomial_it_cannot_evaluate(change, error, said):
    c = {k: v for k, v in {**_MULTINOMIAL, **change}.items() if v is not None}
    with pytest.raises(error, match=said):
        predict("multinomial", c, 800.0, 1.0, 0.5)


def test_predict_refuses_coefficients_that_are_not_numbers():
    c = {"k_eta": 1e-5, "k_h": 1e-3, "k_z": 1e-4, "k_d": 1e-4, "k_m": 1e-7}
    assert np.isfinite(predict("rotorpy", c, 800.0, 1.0, 0.5)).all()
    for k, bad in (("k_eta", float("nan")), ("k_d", "1e-4"), ("k_m", None)):
        with pytest.raises(ValueError, match=rf"coefficients\['{k}'\] must be a finite number"):
            predict("rotorpy", {**c, k: bad}, 800.0, 1.0, 0.5)
    with pytest.raises(TypeError, match="coefficients must be a dict of the rotorpy model's terms, got NoneType"):
        predict("rotorpy", None, 800.0, 1.0, 0.5)
    T, D, Q, MR = predict("multinomial", _MULTINOMIAL, 800.0, 1.0, 0.5)  # (the valid one evaluates)
    assert T > 0 and D > 0 and Q > 0 and MR == 0


@pytest.mark.parametrize("mask, said", [
    ("abc", r"mask must be an array of booleans of shape \(\d+,\), one per row, got dtype <U3"),
    (True, r"mask must have shape \(\d+,\), one boolean per row, got \(\)"),  # (these two ran every point as 1)
    ([0, 5, 7], r"mask must be an array of booleans .* got dtype int64"),  # (NumPy's IndexError)
    (np.ones(3, bool), r"mask must have shape \(\d+,\), one boolean per row, got \(3,\)"),
])
def test_coefficient_errors_takes_a_boolean_mask_of_one_per_point_only(mask, said, apce):
    from propmap.validation import coefficient_errors

    prop, data = apce
    with pytest.raises(ValueError, match="coefficient_errors: " + said):
        coefficient_errors(data, prop, pm.generic_params(), mask=mask)


def test_multinomial_fit_names_omega_where_its_grid_would_pass_the_model_airspeed():
    """Above 500 m/s / (0.24 R) its error named an airspeed (518 m/s) the caller never gave."""
    from propmap.cases import multinomial_fit

    prop = pm.load_propeller("apce_10x7")
    with pytest.raises(ValueError, match=r"omega must be a finite number in \[1, 16404.19\d*\] rad/s, got 17000.0"):
        multinomial_fit(prop, pm.generic_params(), 17000.0)
    for name in ("apce_11x10", "apce_11x5.5"):  # (the bound itself: 0.24 omega R came out 500 + 1 ulp for these)
        p = pm.load_propeller(name)
        assert multinomial_fit(p, pm.generic_params(), 500.0 / (0.24 * p.radius))["CT_static"] > 0


@pytest.mark.parametrize("kw, error, said", [
    ({"rpm": "6000"}, ValueError, r"rpm must be rotation rates in \[100, 50000\] rpm, at least one, got '6000'"),
    ({"rpm": ["a"]}, ValueError, r"rpm must be rotation rates .* at least one, got \['a'\]"),
    ({"rpm": []}, ValueError, r"rpm must be rotation rates .* at least one, got \[\]"),
    ({"rpm": [True]}, ValueError, r"rpm must be rotation rates"),
    ({"rpm": [50.0]}, ValueError, r"rpm must be rotation rates in \[100, 50000\] rpm, got array\(\[50"),
    ({"air": None}, TypeError, "air must be a propmap Air, got NoneType"),
    ({"rolling_moment": "no"}, TypeError, "rolling_moment must be a bool, got str"),
    ({"name": ["apce_8x6"]}, TypeError, r"name must be a catalogue name \(str\), got list"),
])
def test_gill2019_loads_names_a_bad_argument(kw, error, said):
    from propmap.cases_gill2019 import gill2019_loads

    with pytest.raises(error, match=said):
        gill2019_loads(**{"name": "apce_8x6", **kw})
    assert gill2019_loads("apce_8x6", np.array([6000])).n == 43  # (NumPy integers are numbers)


def test_run_case_names_a_bad_argument():
    from propmap.cases import run_case

    with pytest.raises(TypeError, match="param_sets must be a dict of label -> parameters, got list"):
        run_case("dji9443", [pm.generic_params()])
    for case in ("apc10x7e", "dji9443", "beaver", "gill2019"):  # (two met AttributeError, two took None)
        with pytest.raises(TypeError, match="air must be a propmap Air, got NoneType"):
            run_case(case, {"generic": pm.generic_params()}, air=None)


# ---- simexport's files (a helper's bad-input audit) ------------------------------------------------------------------

def test_write_export_never_overwrites_the_vehicle_file_it_names(tmp_path):
    import shutil

    from propmap.simexport import export_sim, write_export

    veh_file = tmp_path / "quad.toml"
    shutil.copy(pm.__path__[0] + "/data/examples/quadrotor.toml", veh_file)
    before = veh_file.read_bytes()
    prop = pm.load_propeller("apce_8x6")
    res = export_sim("rotorpy", prop, pm.generic_params(), n_points=50, seed=0)
    veh = pm.read_vehicle(veh_file)
    with pytest.raises(ValueError, match=r"quad.toml, the file the vehicle or airframe came from: an input is never"):
        write_export(res, veh_file, vehicle=veh, vehicle_label=str(veh_file))
    assert veh_file.read_bytes() == before
    with pytest.raises(TypeError, match="vehicle_label and airframe_label must be text or a path, got dict"):
        write_export(res, tmp_path / "r.py", vehicle_label={})
    with pytest.raises(ValueError, match="the file the vehicle or airframe came from"):  # (a Path as the label too)
        write_export(res, veh_file, vehicle=veh, vehicle_label=veh_file)
    assert write_export(res, tmp_path / "q.py", vehicle_label="x" * 300)[0].exists()  # (free text: no OSError)
    written = write_export(res, tmp_path / "r.py", vehicle=veh, vehicle_label=str(veh_file))
    assert [p.name for p in written] == ["r.py", "r.report.json"] and veh_file.read_bytes() == before


@pytest.mark.parametrize("path", ["", ".", "dir/"])
def test_report_path_refuses_a_path_that_names_no_file(path):
    from propmap.simexport import report_path

    with pytest.raises(ValueError, match="path is empty or names no file"):  # ("dir/" gave dir.report.json)
        report_path(path)
    assert report_path("dir/c.json").name == "c.report.json"


# ---- the validation functions' arguments (a helper's bad-input audit) -----------------------------------------------

def test_the_validation_functions_name_an_argument_of_the_wrong_kind(apce):
    from propmap import validation as v

    prop, data = apce
    g = pm.generic_params()
    entry = pm.catalogue()["apce_8x6"]
    calls = [  # (each met an AttributeError deep inside: 'diameter', 'radius', 'air', 'static_runs', 'static')
        (lambda: v.coefficient_errors(None, prop, g), "data must be a propmap LoadData"),
        (lambda: v.coefficient_errors(data, None, g), "propeller must be a Propeller"),
        (lambda: v.cross_validate(data, prop, None), "generic must be AirfoilParams or CamberedParams"),
        (lambda: v.holdout_loads(data, None, g, [data.static]), "propeller must be a Propeller"),
        (lambda: v.load_errors(data, prop, None), "params must be AirfoilParams or CamberedParams"),
        (lambda: v.validate(None, prop, g), "entry must be a CatalogueEntry"),
        (lambda: v.holdout_comparison(entry, prop, g, "generic", ["x"]), "baseline must be AirfoilParams"),
        (lambda: v.rpm_groups(None), "data must be a propmap LoadData, got NoneType"),
    ]
    for call, said in calls:
        with pytest.raises(TypeError, match=said):
            call()


def test_the_validation_functions_take_lists_of_names_only(apce):
    from propmap import validation as v

    prop, data = apce
    g = pm.generic_params()
    with pytest.raises(ValueError, match=r"protocols must be a list of names, got 'blind' \(give \['blind'\]\)"):
        v.cross_validate(data, prop, g, protocols="blind")  # (read as b, l, i, n, d)
    with pytest.raises(ValueError, match="protocols: none given"):
        v.cross_validate(data, prop, g, protocols=[])  # (returned {})
    with pytest.raises(ValueError, match="protocols: unknown None"):
        v.cross_validate(data, prop, g, protocols=[None])
    with pytest.raises(ValueError, match="folds must be a list of one boolean training mask per fold"):
        v.holdout_loads(data, prop, g, [])
    val = v.validate(pm.catalogue()["apce_8x6"], prop, g, discretization=pm.Discretization(12, 8))
    with pytest.raises(ValueError, match="run_ids must be a list of names, got 5"):
        val.summary("model", 5)
    one = val.runs[1].run_id
    assert val.summary("model", one) == val.summary("model", [one])


def test_the_flight_figures_refuse_forces_of_another_shape(tmp_path):
    from types import SimpleNamespace

    t = {"log": np.linspace(0.0, 1.0, 5)}
    good = {"log": np.zeros((5, 3))}
    for args, said in [
        (({}, {}, {}), "t_by_log must be a dict of at least one log name"),  # (matplotlib's "Number of columns")
        ((t, {"log": np.zeros((5, 2))}, good), r"measured: log 'log' needs a body force of shape \(5, 3\).*\(5, 2\)"),
        ((t, good, {}), r"predicted: log 'log' needs a body force of shape \(5, 3\).* got none"),
        ((t, good, {"log": np.zeros((4, 3))}), r"predicted: .* got \(4, 3\)"),
    ]:
        with pytest.raises(ValueError, match=said):
            plots_flight.plot_flight_timeseries(*args, tmp_path / "f.png")
    with pytest.raises(ValueError, match=r"other\['k'\]: log 'log' needs"):
        plots_flight.plot_flight_timeseries(t, good, good, tmp_path / "f.png", other={"k": {"log": np.zeros(5)}})
    data = SimpleNamespace(airspeed=np.array([1.0, 2.0]), pitch=np.zeros(2))
    forces = {"thrust": np.ones((2, 4)), "drag": np.ones((2, 4)), "torque": np.ones((2, 4)), "vertical": np.ones(2)}
    with pytest.raises(ValueError, match=r"forces\['thrust'\] must have shape \(2, n_rotors\).* got \(2,\)"):
        plots_flight.plot_level_flight_fit(data, {**forces, "thrust": np.ones(2)}, np.ones(2), 10.0, tmp_path / "l.png")
    with pytest.raises(ValueError, match=r"hover_vertical must have shape \(2,\) and weight be finite"):
        plots_flight.plot_level_flight_fit(data, forces, np.ones(2), float("nan"), tmp_path / "l.png")
    assert list(tmp_path.iterdir()) == []


def test_the_load_fit_figure_takes_the_same_runs_twice_and_a_set_of_ids(tmp_path):
    from types import SimpleNamespace

    a, b = SimpleNamespace(run_id="a"), SimpleNamespace(run_id="b")
    with pytest.raises(ValueError, match="must be the same runs in one order, at least one; got 0 and 0 runs"):
        plots.plot_load_fit([], [], set(), tmp_path / "l.png")  # (an IndexError)
    with pytest.raises(ValueError, match="got 2 and 1 runs"):
        plots.plot_load_fit([a, b], [a], set(), tmp_path / "l.png")  # (the baseline's length cut the figure)
    with pytest.raises(ValueError, match="holdout must be a set of run ids"):
        plots.plot_load_fit([a], [a], "ab", tmp_path / "l.png")  # ("a" in "ab": a substring)


def test_rotorpy_directions_takes_a_sequence_of_spins():
    from propmap.simexport import rotorpy_directions

    assert rotorpy_directions(["ccw", "cw", 1, -1]) == [-1, 1, -1, 1]
    for bad in ("ccw", 1):  # ("ccw" read as the spins 'c', 'c', 'w')
        with pytest.raises(ValueError, match="spins must be a sequence of spins, one per rotor"):
            rotorpy_directions(bad)


def test_the_speed_figure_bins_the_largest_speed(monkeypatch, tmp_path):
    """A largest speed of a whole number fell in no bin (the bins [k, k + 1) ended at it): three samples at
    2.0 m/s drew an empty figure."""
    drawn = []
    monkeypatch.setattr(plots, "_save", lambda fig, path: drawn.append(fig) or path)
    plots_flight.plot_flight_speed([2.0, 2.0, 2.0], _loads(3), _loads(3), {"m": np.zeros(3)}, tmp_path / "s.png")
    (line, *_), *_ = (ax.get_lines() for ax in drawn[0].axes)
    assert np.nanmax(line.get_ydata()) == 1.0 and line.get_xdata()[np.nanargmax(line.get_ydata())] == 2.5


def test_fit_flight_warns_where_its_speed_figure_has_nothing_to_draw(apc8x6, apc_params, tmp_path, monkeypatch,
                                                                     capsys):
    """The figures come after the parameter file: a speed figure refused (no 1 m/s bin of 3 samples) is a warning,
    and the command's last line names the figures written."""
    from types import SimpleNamespace

    import propmap.identify.flight as identify_flight
    from propmap.cli.flight import _figures

    n = 6
    rotors = [SimpleNamespace(propeller=apc8x6, params=None, axis=np.array([0.0, 0.0, 1.0]))] * 2
    veh = SimpleNamespace(name="quad", rotors=rotors)
    force = np.column_stack([np.zeros(n), np.zeros(n), np.linspace(-5.0, -4.0, n)])
    samples = SimpleNamespace(t=np.arange(n) * 0.01, log_index=np.zeros(n, int), force=force, reference_force=None,
                              of_log=lambda k: None, speed=np.linspace(0.0, 3.0, n),  # (2, 2, 1, 1 per bin)
                              rotor_omega=np.full((n, 2), 6000 * np.pi / 30), n=n)
    one = SimpleNamespace(thrust=np.full(n, 2.0), drag=np.zeros(n), torque=np.full(n, 0.05))
    pred = SimpleNamespace(force=force + 0.1, loads=[one, one])
    monkeypatch.setattr(identify_flight, "baseline_force", lambda *args: np.zeros((n, 3)))
    monkeypatch.setattr(plots_flight, "plot_flight_timeseries", lambda *args, **kw: None)
    key = identify_flight.BASELINES[-1][0]
    figures = _figures(samples, ["log"], set(), pred, {key: {}}, veh, apc_params, pm.Air(), "v.toml")
    assert figures(tmp_path / "f.png") == (".png",)
    assert "the speed figure is not drawn: speed: no 1 m/s bin holds the 3 samples" in capsys.readouterr().err
    assert not (tmp_path / "f.speed.png").exists()
    samples.speed = np.full(n, 2.5)
    assert figures(tmp_path / "g.png") == (".png", ".speed.png") and (tmp_path / "g.speed.png").exists()


# ---- a mutation audit of this stop's figure checks: the cases its survivors showed untested --------------------------

def test_the_figure_checks_edges(tmp_path, small_map):
    from types import SimpleNamespace

    import pandas as pd
    import xarray as xr

    table = pd.DataFrame({"airspeed": [0.0, 5.0], "incidence_deg": [90.0, 90.0], "thrust": [2.0, 2.1],
                          "drag": [0.0, 0.1], "thrust_hover": [np.inf, 1.0]})
    with pytest.raises(ValueError, match=r"largest \|thrust_hover\| must be finite and > 0, got inf"):
        plots.plot_envelope(table, tmp_path / "e.png")
    a, b = SimpleNamespace(run_id="a"), SimpleNamespace(run_id="b")
    with pytest.raises(ValueError, match=r"got 2 and 2 runs \(a, b; b, a\)"):  # (the same runs in another order)
        plots.plot_load_fit([a, b], [b, a], set(), tmp_path / "l.png")
    with pytest.raises(ValueError, match="holdout must be a set of run ids"):
        plots.plot_load_fit([a], [a], {1}, tmp_path / "l.png")
    with pytest.raises(ValueError, match="none measured"):
        plots.plot_load_parity(SimpleNamespace(measured={}), {"fitted": {}}, np.zeros(0, bool), tmp_path / "p.png")
    rows = [{"blind": {"rms_ct": np.inf, "rms_cp": 0.03}}]
    with pytest.raises(ValueError, match="1 rms errors not finite and positive"):
        plots.plot_cv_summary({"summary": {"blind": {}}, "propellers": rows}, tmp_path / "c.png")
    ds = small_map[2]
    lo, hi = float(ds["rpm"].min()), float(ds["rpm"].max())
    plots.plot_map_contours(ds, lo * (1 - 1e-12), tmp_path / "lo.png")  # (an end node to round-off, both ends)
    with pytest.raises(ValueError, match="rpm must lie within the map's rpm axis"):
        plots.plot_map_contours(ds, hi * 1.001, tmp_path / "m.png")  # (beyond round-off: refused)
    with pytest.raises(TypeError, match="ds must be a map"):
        plots.plot_map_contours(xr.Dataset({"thrust": ("x", [1.0])}), 6000.0, tmp_path / "m.png")  # (no rpm axis)
    with pytest.raises(ValueError, match=r"speed: give speeds \[m/s\] in \[0, 1000\], got 1 to 1001"):
        plots_flight.plot_flight_speed([1.0, 1.0, 1001.0], _loads(3), _loads(3), {"m": np.zeros(3)},
                                       tmp_path / "s.png")
    data = SimpleNamespace(airspeed=np.array([1.0, 2.0]), pitch=np.zeros(2))
    forces = {"thrust": np.ones((2, 4)), "drag": np.ones((2, 4)), "torque": np.ones((2, 4)), "vertical": np.ones(2)}
    for change, hover, weight, said in [
        ({"thrust": np.ones((3, 4))}, np.ones(2), 10.0, r"forces\['thrust'\] must have shape \(2, n_rotors\)"),
        ({}, np.ones(3), 10.0, r"hover_vertical must have shape \(2,\)"),
        ({}, np.ones(2), np.ones(3), r"weight be finite, of shape \(\) or \(2,\)"),
    ]:
        with pytest.raises(ValueError, match=said):
            plots_flight.plot_level_flight_fit(data, {**forces, **change}, hover, weight, tmp_path / "l.png")
    good = {"log": np.zeros((5, 3))}
    with pytest.raises(ValueError, match="t_by_log must be a dict of at least one log name"):
        plots_flight.plot_flight_timeseries([np.zeros(5)], good, good, tmp_path / "f.png")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lo.png"]


def test_the_remaining_checks_a_mutation_audit_found_untested(tmp_path, capsys, apce, shared_data):
    """Survivors of the mutation audit of this stop's change, each killed by one line here."""
    import dataclasses
    import shutil

    from propmap import validation as v
    from propmap.cases_gill2019 import gill2019_loads
    from propmap.cli._common import _catalogue_geometry
    from propmap.simexport import export_sim, write_export

    good = {"log": np.zeros((5, 3))}
    with pytest.raises(ValueError, match="needs a body force of shape"):  # (a time that is no 1-D array)
        plots_flight.plot_flight_timeseries({"log": 0.5}, good, good, tmp_path / "f.png")
    # the same diameter with another blade and count is another propeller, not another hub
    other = dataclasses.replace(pm.load_propeller("apce_8x8"), n_blades=3)
    assert _catalogue_geometry("apce_8x6", other) is False
    # the 2-blade hub's own UIUC runs given as files with the 3-blade geometry: not the owner's residual
    runs = sorted(str(p) for pattern in ("da4022_5x3.75_0*.txt", "da4022_5x3.75_static_*.txt")
                  for p in (shared_data / "uiuc_propdb/v2").glob(pattern))
    assert len(runs) == 5  # (its static run and four sweeps)
    code, out, _ = run(capsys, "validate", *runs, "--prop", "da4022_5x3.75_3b", "--params", "generic")
    assert code == 0 and "in-sample" not in out and "(fitted)" not in out
    # write_export: an output named by neither label, and free text as a label, are written again
    prop = pm.load_propeller("apce_8x6")
    res = export_sim("rotorpy", prop, pm.generic_params(), n_points=50, seed=0)
    veh_file = tmp_path / "quad.toml"
    shutil.copy(pm.__path__[0] + "/data/examples/quadrotor.toml", veh_file)
    for _ in range(2):
        write_export(res, tmp_path / "r.py", vehicle_label=str(veh_file), airframe_label="the [body] table of x")
        write_export(res, tmp_path / "s.py", vehicle_label="my quad")
    report_named = tmp_path / "c.report.json"
    shutil.copy(veh_file, report_named)
    with pytest.raises(ValueError, match="the file the vehicle or airframe came from"):  # (its report would be it)
        write_export(res, tmp_path / "c.py", vehicle_label=str(report_named))
    with pytest.raises(ValueError, match="the file the vehicle or airframe came from"):
        write_export(res, veh_file, airframe_label=str(veh_file))
    assert report_named.read_bytes() == veh_file.read_bytes()
    assert gill2019_loads("apce_8x6", [100.0]).n == 43  # (the range's ends are in it)
    g = pm.generic_params()
    with pytest.raises(TypeError, match="data must be a propmap LoadData"):
        v.cross_validate(None, prop, g)
    with pytest.raises(ValueError, match="folds must be a list of one boolean training mask per fold"):
        v.holdout_loads(apce[1], prop, g, 5)
    entry = pm.catalogue()["apce_8x6"]
    one = entry.sweeps()[0].run_id
    coarse = pm.Discretization(12, 8)
    assert v.holdout_comparison(entry, prop, g, g, one, discretization=coarse)["holdout"] == [one]  # (not split)
    with pytest.raises(ValueError, match="holdout: none given"):
        v.holdout_comparison(entry, prop, g, g, [], discretization=coarse)


def test_the_fit_commands_last_line_names_the_figures_a_figure_function_wrote(tmp_path, capsys):
    """_write_outputs takes the suffixes a figure function returns (fit flight's, without its speed figure where
    that has nothing to draw), and keeps its own where the function returns something else (a Path)."""
    from dataclasses import dataclass, field

    from propmap.cli.fit import _write_outputs

    @dataclass
    class Result:  # (what _write_outputs reads of a fit's result)
        params: object = field(default_factory=pm.generic_params)
        air: object = field(default_factory=pm.Air)
        warnings: tuple = ()

        def to_dict(self):
            return {"kind": "test"}

        def report_text(self):
            return "a report"

    for returned, said in (((".png",), "f.report.txt, f.png\n"), (None, "f.report.txt, f.png, f.speed.png\n"),
                           (tmp_path / "f.png", "f.report.txt, f.png, f.speed.png\n")):
        _write_outputs(Result(), tmp_path / "f.toml", "generic", False, figure=lambda png: returned,
                       figure_suffixes=(".png", ".speed.png"))
        assert capsys.readouterr().err.endswith(said)
