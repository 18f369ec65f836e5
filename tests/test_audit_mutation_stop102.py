"""A mutation audit of stop 102's change (794d6f0..a959333, its src diff against 6c493ff).

Hand-made mutants of the new or changed lines of plots.py, io/params_file.py, io/params_tables.py,
io/calibration.py, io/toml_file.py, io/mapcheck.py, maps.py, identify/loads_csv.py,
core/torque_change.py and cli/{map,fit,flight,demo,validate}.py (73 in all; a helper session,
2026-12-02) were each run against the test files covering their module (tests/test_stop102.py first):
36 killed by the suite, 5 equivalent, 32 real gaps. Each test here passes on the code and fails on the
surviving mutant its docstring names (file, line, the change). Data: the catalogue's APC 8x6E (APC PE0 geometry), its
calibrated set and the shipped generic set and folds; small hand-made maps and tables.
"""

from __future__ import annotations

import builtins
import math
import os
import subprocess
import sys
import warnings
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM

from .cli_helpers import one_line_error, run
from .test_stop102 import _map_ds  # the hand-made one-rpm map of stop 102's own tests
import propmap.plots_flight as plots_flight


@pytest.fixture
def drawn(monkeypatch):
    """The figures the plot functions would save (plots._save replaced: nothing written)."""
    from propmap import plots

    figs = []
    monkeypatch.setattr(plots, "_save", lambda fig, path: figs.append(fig) or Path(path))
    return plots, figs


@pytest.fixture
def no_matplotlib(monkeypatch):
    """plots.require_matplotlib as where matplotlib does not import (MPLBACKEND=bogus): the error the
    commands must give before any work."""
    from propmap import plots

    def refuse():
        raise ValueError("the environment variable MPLBACKEND='bogus' is not a matplotlib backend")

    monkeypatch.setattr(plots, "require_matplotlib", refuse)


# ---- plots.py --------------------------------------------------------------------------------------------------------

def test_a_plot_function_names_an_unknown_mplbackend():
    """Kills plots.py:58 (``_figure`` without its ``require_matplotlib()``): a plot function called with
    MPLBACKEND=bogus raised matplotlib's own "Key backend: 'bogus'" instead of naming the variable."""
    code = ("import numpy as np\nimport propmap.plots_flight as p\ntry:\n"
            "    p.plot_flight_speed([1.0, 1.2, 1.4], {k: np.ones(3) for k in ('thrust', 'drag', 'torque')},\n"
            "                        {k: np.ones(3) for k in ('thrust', 'drag', 'torque')}, {'m': np.zeros(3)},\n"
            "                        'never.png')\nexcept ValueError as e:\n    print(e)\n")
    r = subprocess.run([sys.executable, "-c", code], env=dict(os.environ, MPLBACKEND="bogus"), capture_output=True,
                       text=True, timeout=120, check=False)
    assert "MPLBACKEND='bogus' is not a matplotlib backend" in r.stdout, r.stdout + r.stderr


def test_require_matplotlib_passes_on_an_import_error_not_due_to_mplbackend(monkeypatch):
    """Kills plots.py:44-45 (the ``if backend is None: raise`` dropped): where MPLBACKEND is unset, a
    ValueError of ``import matplotlib`` (a broken matplotlibrc) was said as "MPLBACKEND=None is not a
    matplotlib backend"."""
    from propmap.plots import require_matplotlib

    real = builtins.__import__

    def failing(name, *args, **kw):
        if name == "matplotlib":
            raise ValueError("Key lines.linewidth: could not convert 'wide' to float")
        return real(name, *args, **kw)

    monkeypatch.delenv("MPLBACKEND", raising=False)
    monkeypatch.setattr(builtins, "__import__", failing)
    with pytest.raises(ValueError, match="^Key lines.linewidth: could not convert"):
        require_matplotlib()


def test_figures_use_constrained_layout_and_the_contour_width_follows_its_panels(drawn, tmp_path):
    """Kills plots.py:57 (``layout="constrained"`` dropped: colour bars and labels overlapped) and
    plots.py:490 (the contour figure 18 in wide whatever its panels: the three-panel figure of an axis
    without the static node kept the four-panel width, 4.5 in a panel)."""
    from matplotlib.layout_engine import ConstrainedLayoutEngine

    plots, figs = drawn
    plots.plot_map_contours(_map_ds([5.0, 10.0]), 6000.0, tmp_path / "a.png", title="m")
    assert len(figs[0].axes) == 6  # three panels, each with its colour bar
    assert figs[0].get_size_inches()[0] == pytest.approx(13.5)
    assert isinstance(figs[0].get_layout_engine(), ConstrainedLayoutEngine)


def test_cv_summary_leaves_out_a_row_without_the_protocol(drawn, tmp_path):
    """Kills plots.py:357 (``r.get(key) and`` dropped): a row without the protocol's key, or with None for it,
    is left out of its curve (the docstring), not a KeyError / TypeError."""
    plots, figs = drawn
    rows = [{"blind": {"rms_ct": 0.02, "rms_cp": 0.04}}, {}, {"blind": None},
            {"blind": {"rms_ct": 0.05, "rms_cp": 0.06}}]
    plots.plot_cv_summary({"summary": {"blind": {}}, "propellers": rows}, tmp_path / "c.png")
    x = np.asarray(figs[0].axes[0].get_lines()[0].get_xdata(), float)
    assert sorted(set(x)) == pytest.approx([2.0, 5.0])


def test_the_speed_figure_refuses_no_samples(drawn, tmp_path):
    """Kills plots.py:590 (``speed.size == 0 or`` dropped): no samples met numpy's "zero-size array to reduction
    operation maximum" instead of the function's own error."""
    plots, _ = drawn
    loads = {k: np.ones(0) for k in ("thrust", "drag", "torque")}
    with pytest.raises(ValueError, match="got 0 samples, 0 of them not finite"):
        plots_flight.plot_flight_speed([], loads, loads, {"m": np.zeros(0)}, tmp_path / "s.png")


# ---- io/calibration.py: shipped_coverage, propeller_coverage ---------------------------------------------------------

def test_a_calibrated_sets_coverage_carries_its_propellers_reynolds_span_and_blade_angle(apc8x6):
    """Kills io/calibration.py:130 (``re75_max`` the Reynolds number of the lowest rate; ``theta75_deg`` in
    radians): the keys are the blade angle at 0.75 R in degrees and the Reynolds numbers at 0.75 R of the
    set's data's rpm_min and rpm_max, in the set's air."""
    from propmap.io.calibration import shipped_coverage

    cov = shipped_coverage(pm.default_params("apce_8x6"))
    re = apc8x6.reynolds_75(np.array([cov["rpm_min"], cov["rpm_max"]]) * RPM, pm.Air())
    assert cov["re75_min"] == pytest.approx(re[0], rel=1e-12) and cov["re75_max"] == pytest.approx(re[1], rel=1e-12)
    assert cov["re75_max"] > 1.5 * cov["re75_min"]
    assert cov["theta75_deg"] == pytest.approx(math.degrees(apc8x6.theta_75()), rel=1e-12)
    assert 5.0 < cov["theta75_deg"] < 30.0
    assert cov["diameter_m"] == pytest.approx(apc8x6.diameter) and cov["propeller"] == "apce_8x6"


def test_a_generic_fold_written_keeps_the_generic_coverage_and_a_changed_generic_set_none(tmp_path):
    """Kills io/calibration.py:173 (the folds left out of the shipped sets: ``generic without apce`` written
    lost its coverage) and io/calibration.py:175 (the by-value check of the generic sets dropped: the generic
    set with another lift slope, its label kept, was written with the generic data's coverage)."""
    import dataclasses

    from propmap.io.calibration import coverage, generic_without
    from propmap.io.params_file import read_coverage, write_params

    fold, label = generic_without("apce_8x6")
    assert label.startswith("generic without") and fold.label == label
    write_params(tmp_path / "f.toml", fold)
    assert read_coverage(tmp_path / "f.toml") == pytest.approx(coverage(label))
    g = pm.generic_params()
    write_params(tmp_path / "g.toml", dataclasses.replace(g, cl_alpha=1.5 * g.cl_alpha))
    assert read_coverage(tmp_path / "g.toml") is None


def test_a_calibrated_set_whose_propeller_does_not_load_keeps_its_data_coverage(monkeypatch):
    """Kills io/calibration.py:171 (``return cov`` -> ``return None``): where the catalogue cannot load the
    calibrated set's propeller, the set still carries its data's J, incidence and rpm span."""
    import importlib

    from propmap.io.calibration import coverage, shipped_coverage

    catalogue = importlib.import_module("propmap.io.catalogue")  # (the package's attribute is a function)

    def unreadable(name, *args, **kw):
        raise OSError(f"{name}: the geometry file cannot be read")

    monkeypatch.setattr(catalogue, "load_propeller", unreadable)
    assert shipped_coverage(pm.default_params("apce_8x6")) == coverage("calibrated:apce_8x6")


# ---- io/params_file.py: write_params, _read_set_coverage, unknown keys ----------------------------------------------

def _radian_like_set():
    """Table I's APC set with alpha0 = 1.5 deg: a value read_params warns of ("radians?")."""
    return pm.preset("gill2017-apc").replace(alpha0=math.radians(1.5))


def test_write_params_checks_the_file_without_warning_and_the_reader_warns(tmp_path):
    """Kills io/params_file.py:531 (the ``simplefilter("ignore")`` of write_params' check dropped): writing a
    set whose alpha0 looks like radians warned "radians?" at the writing; that warning belongs to reading."""
    from propmap.io.params_file import read_params, write_params

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        write_params(tmp_path / "r.toml", _radian_like_set(), coverage={})
    with pytest.warns(UserWarning, match="alpha0_deg = 1.5 deg is small"):
        read_params(tmp_path / "r.toml")


def test_a_set_read_from_a_file_is_written_again_without_the_files_warnings(tmp_path):
    """Kills io/params_file.py:546 (the ``simplefilter("ignore")`` of _read_set_coverage dropped): writing
    a set read from a file re-read that file and repeated its warnings at the writing."""
    from propmap.io.params_file import read_coverage, read_params, write_params

    write_params(tmp_path / "r.toml", _radian_like_set(), coverage={"J_max": 0.8, "incidence_deg_max": 0.0})
    with pytest.warns(UserWarning, match="radians"):
        p = read_params(tmp_path / "r.toml")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        write_params(tmp_path / "copy.toml", p)
    assert read_coverage(tmp_path / "copy.toml") == {"J_max": 0.8, "incidence_deg_max": 0.0}


def test_a_set_labelled_with_the_path_of_a_file_that_is_no_parameter_file_is_written_without_coverage(tmp_path):
    """Kills io/params_file.py:549 (``except (ValueError, OSError)`` -> ``except OSError``): a set whose label is
    the path of a file read_params refuses (here a CSV) is written, with no [coverage], not refused."""
    from propmap.io.params_file import read_coverage, read_params, write_params

    (tmp_path / "data.csv").write_text("rpm,thrust\n5000,1.0\n")
    p = pm.generic_params().replace(cl_alpha=5.0, label=str(tmp_path / "data.csv"))
    write_params(tmp_path / "w.toml", p)
    assert read_coverage(tmp_path / "w.toml") is None
    assert read_params(tmp_path / "w.toml").cl_alpha == pytest.approx(5.0)


def test_an_unknown_key_is_matched_also_against_the_tables_and_the_first_gets_the_hint(tmp_path):
    """Kills io/params_file.py:227 (the [body] and [coverage] tables left out of the keys named: a misspelt
    ``[coverag]`` got no hint) and io/params_file.py:228 (the hint for the last unknown key, not the first
    shown: ``cd_0`` and ``zzz`` gave none)."""
    from propmap.io.params_file import ParamsFileError, read_params

    f = tmp_path / "t.toml"
    f.write_text('section_model = "cambered"\n[coverag]\nJ_max = 1.0\n')
    with pytest.raises(ParamsFileError,
                       match=r"unknown key\(s\) coverag .*did you mean coverage\? \(its keys: .*\bbody\b"):
        read_params(f)
    g = tmp_path / "u.toml"
    g.write_text('section_model = "gill2017"\ncl1 = 5.0\ncl2 = 1.0\ncd = 1.0\nalpha0_deg = 20\ncd_0 = 0.01\n'
                 'zzz = 1\n')
    with pytest.raises(ParamsFileError, match=r"unknown key\(s\) cd_0, zzz for section_model 'gill2017': did you mean "
                                              r"cd0\?"):
        read_params(g)


# ---- io/toml_file.py: the line of a TOML error shown ----------------------------------------------------------------

def test_a_toml_error_line_is_shown_with_its_spaces_collapsed_and_cut_at_100_characters(tmp_path):
    """Kills io/toml_file.py:63 (the line shown as it is, its tabs and runs of spaces kept) and
    io/toml_file.py:66 (a long line shown whole, or cut without " ..."): the line is shown on one line
    with single spaces, at most 100 characters and " ..." where cut."""
    from propmap.io.params_file import ParamsFileError, read_params

    f = tmp_path / "dup.toml"
    f.write_text('section_model = "cambered"\ncl_alpha = 5.0\ncl_alpha\t=   6.0\n')
    with pytest.raises(ParamsFileError) as exc:
        read_params(f)
    assert str(exc.value).endswith("; line 3: cl_alpha = 6.0")
    g = tmp_path / "long.toml"
    g.write_text('section_model = "cambered"\ncl_alpha = 5.0\ncl_alpha = 6.0 # ' + "x" * 200 + "\n")
    with pytest.raises(ParamsFileError) as exc:
        read_params(g)
    shown = str(exc.value).split("; line 3: ", 1)[1]
    assert shown == ("cl_alpha = 6.0 # " + "x" * 200)[:100] + " ..."


# ---- identify/loads_csv.py: a group label's length -------------------------------------------------------------------

def _loads_csv(path, label):
    path.write_text("rpm,thrust,group\n" + "".join(f"{w},{t},{label if k == 4 else 'a'}\n" for k, (w, t) in
                                                   enumerate(zip(range(3000, 9000, 1000), np.linspace(1, 4, 6)))))
    return path


def test_a_group_label_of_exactly_1000_characters_is_read(tmp_path):
    """Kills identify/loads_csv.py:188 (``>`` -> ``>=``): a label of COVERAGE_TEXT_MAX (1000) characters is what a
    [coverage] table takes, and is read; 1001 is refused."""
    from propmap.identify.csvfile import DataError
    from propmap.identify.loads_csv import read_loads

    data = read_loads(_loads_csv(tmp_path / "ok.csv", "g" * 1000))
    assert "g" * 1000 in set(map(str, data.group))
    with pytest.raises(DataError, match="holds a label of 1001 characters at line 6"):
        read_loads(_loads_csv(tmp_path / "long.csv", "g" * 1001))


# ---- io/mapcheck.py: coordinates in single precision ----------------------------------------------------------------

@pytest.fixture(scope="module")
def tiny_map():
    """apce_8x6 with the generic set on a 2 x 2 x 2 grid, no check points."""
    from propmap.maps import build_map

    return build_map(pm.load_propeller("apce_8x6"), pm.generic_params(), np.array([4000.0, 6000.0]) * RPM,
                     [0.0, 5.0], np.radians([0.0, 90.0]), n_check=0)


def test_a_float32_omega_beside_a_float64_rpm_opens(tiny_map):
    """Kills io/mapcheck.py:285 (``any`` -> ``all``): a map whose omega alone is stored as float32 (its rpm
    float64) is judged to float32's precision, not refused at 1e-9."""
    from propmap.io.mapcheck import check_dataset

    ds = tiny_map.copy()
    ds["omega"] = ds["omega"].astype(np.float32)
    assert ds["rpm"].dtype == np.float64
    check_dataset(ds)


def test_single_and_double_precision_coordinates_are_held_to_their_own_tolerances(tiny_map):
    """Kills io/mapcheck.py:286 (float32's tolerance 1e3 roundings, 1.2e-4, not 8, 9.5e-7; float64's 1e-7, not
    1e-9): an omega 1e-5 off in a float32 map, and 1e-8 off in a float64 one, is refused."""
    from propmap.io.mapcheck import check_dataset

    d32 = tiny_map.copy()
    for k in list(d32.data_vars) + list(d32.coords):
        if d32[k].dtype == np.float64:
            d32[k] = d32[k].astype(np.float32)
    check_dataset(d32)
    d32["omega"] = (d32["omega"] * np.float32(1 + 1e-5)).astype(np.float32)
    with pytest.raises(ValueError, match=r"coordinate omega must equal rpm in rad/s along rpm \(to a relative 9.5e-07"):
        check_dataset(d32)
    d64 = tiny_map.copy()
    d64["omega"] = d64["omega"] * (1 + 1e-8)
    with pytest.raises(ValueError, match=r"coordinate omega must equal rpm .*\(to a relative 1e-09\)"):
        check_dataset(d64)


# ---- maps.py: build_map refuses air a map cannot record -------------------------------------------------------------

@pytest.mark.parametrize("air, key", [({"rho": 5000.0}, "rho_kg_m3"), ({"mu": 20.0}, "mu_Pa_s")])
def test_build_map_refuses_a_density_or_viscosity_a_map_cannot_record_before_the_solve(air, key, monkeypatch):
    """Kills maps.py:267 (``rho_kg_m3`` or ``mu_Pa_s`` left out of the air checked before the solve): an air of
    5000 kg/m^3 or 20 Pa s was solved over the whole grid before being refused."""
    from propmap import maps

    def solved(*args, **kw):
        raise AssertionError("the grid was solved")

    monkeypatch.setattr(maps, "rotor_loads", solved)
    with pytest.raises(ValueError, match=rf"^air: a map records it within the ranges of a parameter file: .*{key}"):
        maps.build_map(pm.load_propeller("apce_8x6"), pm.generic_params(), np.array([4e3, 6e3]) * RPM, [0.0, 5.0],
                       [0.0, 1.0], air=pm.Air(**air), n_check=0)


# ---- cli: matplotlib checked before any work; map's static-node warning; demo's table; fit flight's speed figure ----

def test_map_plot_warns_of_its_airspeed_axis_not_its_incidence_axis(capsys, tmp_path, monkeypatch):
    """Kills cli/map.py:217 (the grid given to _plot_files as (rpm, incidence, airspeed)): an airspeed axis
    5:10 with an incidence axis from 0 deg drew no hover panel and said nothing; an airspeed axis from 0 with
    an incidence axis from 30 deg was warned of as "starts at 30 m/s"."""
    from propmap import plots

    monkeypatch.setattr(plots, "plot_map_contours", lambda ds, rpm, path, **kw: Path(path))
    common = ["--rpm", "4000:6000:2", "--check-points", "0"]
    code, _, err = run(capsys, "map", "apce_8x6", "--out", tmp_path / "a.nc", "--airspeed", "5:10:2",
                       "--incidence-deg", "0:90:2", "--plot", tmp_path / "pa", *common)
    assert code == 0 and "the airspeed axis starts at 5 m/s, without the static node" in err, err
    code, _, err = run(capsys, "map", "apce_8x6", "--out", tmp_path / "b.nc", "--airspeed", "0:10:2",
                       "--incidence-deg", "30:90:2", "--plot", tmp_path / "pb", *common)
    assert code == 0 and "static node" not in err, err


def test_demo_checks_matplotlib_before_any_work(capsys, tmp_path, no_matplotlib):
    """Kills cli/demo.py:115 (``require_matplotlib()`` dropped): the demo computed and wrote its envelope table,
    then failed at its first figure."""
    code, out, err = run(capsys, "demo", "--out-dir", tmp_path / "d")
    assert one_line_error(code, err, "MPLBACKEND='bogus'"), err
    assert out == "" and not (tmp_path / "d").exists()


def test_demo_table_keeps_a_space_before_a_thrust_of_nine_characters(capsys, tmp_path, monkeypatch):
    """Kills cli/demo.py:148 (the thrust column back to ``{incidence:>8.0f}{thrust:>9.3f}``): at the top of the
    rpm range a thrust of 12345.678 N ran into the incidence ("012345.678")."""
    import pandas as pd

    from propmap import plots
    from propmap.cli import demo
    from propmap.cli._common import InputError

    table = pd.DataFrame({"airspeed": [0.0], "incidence_deg": [0.0], "thrust": [12345.678], "drag": [1234.567],
                          "torque": [12345.6789], "thrust_hover": [12345.678], "flags": [""]})
    monkeypatch.setattr(demo, "envelope_table", lambda prop, params, rpm: table)

    def stop(*args, **kw):
        raise InputError("the table was printed")

    monkeypatch.setattr(plots, "plot_envelope", stop)
    code, out, err = run(capsys, "demo", "--out-dir", tmp_path / "d")
    assert code == 2 and "the table was printed" in err, err
    row = next(line for line in out.splitlines() if line.split()[:1] == ["0"])
    assert row.split()[:7] == ["0", "0", "12345.678", "1234.567", "12345.6789", "+0.000", "N"]


def test_validate_checks_matplotlib_before_validating(capsys, tmp_path, no_matplotlib, monkeypatch):
    """Kills cli/validate.py:125 and cli/validate.py:137 (``require_matplotlib()`` dropped): ``validate --all
    --out-dir`` ran the whole catalogue, and ``validate PROP --figure`` the whole validation, before the
    figures failed."""
    from propmap import validation
    from propmap.cli import validate_all

    def ran(*args, **kw):
        raise AssertionError("the validation was run")

    monkeypatch.setattr(validate_all, "run_all", ran)
    monkeypatch.setattr(validation, "validate", ran)
    code, out, err = run(capsys, "validate", "--all", "--out-dir", tmp_path / "all")
    assert one_line_error(code, err, "MPLBACKEND='bogus'"), err
    assert out == "" and not (tmp_path / "all").exists()
    code, out, err = run(capsys, "validate", "apce_8x6", "--figure", tmp_path / "v.png")
    assert one_line_error(code, err, "MPLBACKEND='bogus'"), err
    assert out == "" and not (tmp_path / "v.png").exists()


def test_a_fits_output_files_are_checked_with_matplotlib(tmp_path, no_matplotlib):
    """Kills cli/fit.py:124 (``require_matplotlib()`` dropped from _out_files): fit loads and fit flight ran the
    whole fit and wrote its file before their figure failed."""
    from propmap.cli.fit import _out_files

    with pytest.raises(ValueError, match="MPLBACKEND='bogus'"):
        _out_files(tmp_path / "f.toml")


def test_fit_flights_speed_figure_takes_the_hover_models_vertical_force_for_the_vertical_error(apc8x6, apc_params,
                                                                                                 tmp_path, monkeypatch):
    """Kills cli/flight.py:296 (the vertical-force error of the hover model from its thrust along each rotor's axis,
    ``hover["thrust"]``, not its body-z component ``hover["vertical"]``): with a rotor tilted 20 deg the error
    drawn was off by T (1 - cos 20 deg)."""
    import propmap.identify.flight as identify_flight
    from propmap.cli.flight import _figures, _hover_loads

    tilt = np.radians(20.0)
    rotors = [SimpleNamespace(propeller=apc8x6, params=None, axis=np.array([0.0, 0.0, 1.0])),
              SimpleNamespace(propeller=apc8x6, params=None, axis=np.array([np.sin(tilt), 0.0, np.cos(tilt)]))]
    veh = SimpleNamespace(name="tilted", rotors=rotors)
    n = 6
    force = np.column_stack([np.zeros(n), np.zeros(n), np.linspace(-5.0, -4.0, n)])
    samples = SimpleNamespace(t=np.arange(n) * 0.01, log_index=np.zeros(n, int), force=force, reference_force=None,
                              of_log=lambda k: None, speed=np.linspace(0.0, 3.0, n),
                              rotor_omega=np.full((n, 2), 6000 * RPM), n=n)
    one = SimpleNamespace(thrust=np.full(n, 2.0), drag=np.zeros(n), torque=np.full(n, 0.05))
    pred = SimpleNamespace(force=force + 0.1, loads=[one, one])
    seen = {}
    monkeypatch.setattr(identify_flight, "baseline_force", lambda *args: np.zeros((n, 3)))
    monkeypatch.setattr(plots_flight, "plot_flight_timeseries", lambda *args, **kw: None)
    monkeypatch.setattr(plots_flight, "plot_flight_speed", lambda speed, loads, hover, vertical, path, **kw:
                        seen.update(hover=hover, vertical=vertical))
    key = identify_flight.BASELINES[-1][0]
    _figures(samples, ["log"], set(), pred, {key: {}}, veh, apc_params, pm.Air(), "v.toml")(tmp_path / "f.png")
    hover = _hover_loads(apc_params, veh, samples, pm.Air())
    assert seen["vertical"]["hover model"] == pytest.approx(hover["vertical"] - force[:, 2], rel=1e-12)
    assert not np.allclose(hover["vertical"], hover["thrust"], rtol=1e-3)


# ---- core/torque_change.py: the windmill brake named only of a negative thrust ---------------------------------------

def test_a_small_positive_thrust_below_the_hovers_least_is_not_called_negative(apc8x6):
    """Kills core/torque_change.py:102 (``T >= 0`` -> ``T >= 0.5``): a climb at 24 m/s and 800 rad/s makes 0.31 N,
    below the 3.40 N hover makes at 10 deg collective; the error names no negative thrust or windmill brake."""
    from propmap.core.trim import TrimError

    p = pm.default_params("apce_8x6")
    with pytest.raises(TrimError,
                       match=r"makes thrust=0\.30\d* N .* below the least hover makes there, about 3\.3975 N$"):
        pm.torque_change_at_constant_thrust(apc8x6, p, 800.0, 24.0, 0.0,
                                            bounds=(math.radians(10.0), math.radians(30.0)))
