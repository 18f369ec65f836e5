"""A coverage-guided test-gap audit: the branches a user reaches that the suite's line and branch coverage
(coverage.py over the whole suite, 2026-11-30) found unexecuted. Each test names the module and line(s) it
covers (by the function that holds them) and the hand-made mutant of them it kills."""

from __future__ import annotations

import json
import math
import re
from dataclasses import replace
from importlib import resources

import numpy as np
import pytest

import propmap as pm
from cli_helpers import one_line_error, run
from propmap.identify import FitOptions, LoadData, fit_loads, read_loads
from propmap.identify.data import DataError
from propmap.io import ParamsFileError, read_params, write_params
from propmap.io.flightlog import read_flight_log
from propmap.io.flightlog_checks import FlightLogError
from propmap.vehicle import trim_vehicle
from propmap.vehicle.file import VehicleFileError

QUAD = resources.files("propmap").joinpath("data/examples/quadrotor.toml").read_text()


def _params_text(tmp_path) -> str:
    """apce_8x6's default set as a parameter file's text."""
    f = tmp_path / "base.toml"
    write_params(f, pm.default_params("apce_8x6"), coverage={})  # (none: a shipped set's own is written by default)
    return f.read_text()


def _stand_csv(tmp_path, thrust_scale=1.0):
    """A static stand's CSV of apce_8x6 (its default set's loads, thrust times ``thrust_scale``), two runs."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    rpm = np.linspace(3000.0, 8000.0, 6)
    r = pm.rotor_loads(prop, params, rpm * math.pi / 30, 0.0 * rpm, 0.0 * rpm)
    path = tmp_path / "stand.csv"
    path.write_text("rpm,thrust,torque,group\n" + "".join(
        f"{w:.1f},{thrust_scale * t:.6f},{q:.7f},{g}\n"
        for w, t, q, g in zip(rpm, r.thrust, r.torque, "aaabbb")))
    return path


# ---------------------------------------------------------------- cli/export_sim.py


def test_export_sim_envelope_bounds_that_are_not_numbers_are_refused(capsys, tmp_path):
    """cli/export_sim.py (parse_envelope). Mutant: 'except ValueError' made 'except KeyError' (float's own 'could not
    convert string to float' then, naming neither --envelope nor the item)."""
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "rotorpy", "--out", tmp_path / "x.py",
                       "--envelope", "rpm=a:9000")
    assert one_line_error(code, err, "--envelope: 'rpm=a:9000': LOW and HIGH must be numbers"), err
    assert not (tmp_path / "x.py").exists()


def test_export_sim_former_target_name_gill2019_warns_and_means_multinomial(capsys, tmp_path):
    """cli/export_sim.py (_checked_target: the warning and the alias to multinomial after it). Mutant: the test made 'if
    False:' (the former name taken silently). The .sdf name is then refused as the multinomial target's (*.json), not
    gill2019's."""
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "gill2019", "--out", tmp_path / "x.sdf")
    assert "propmap: warning: --target gill2019 is now called multinomial" in err
    assert one_line_error(code, err, "the multinomial file is named *.json"), err


def test_export_sim_vehicle_with_another_propeller_is_warned_of_at_hover_rpm(capsys, tmp_path):
    """cli/export_sim.py (_export_vehicle). Mutant: 'if names:' made 'if False:' (8x6 coefficients on a 10x7 quad,
    unsaid). The hover rpm beyond the envelope is then refused, naming --hover-rpm, so the run stays short."""
    veh = tmp_path / "other.toml"
    veh.write_text(QUAD.replace('"apce_8x6"', '"apce_10x7"'))
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "rotorpy", "--out", tmp_path / "o.py",
                       "--vehicle", veh, "--hover-rpm", "50000")
    assert ("propmap: warning: --vehicle: its rotors carry apce_10x7 (0.254 m, 2 blades), not apce_8x6 (0.2032 m, "
            "2 blades): the export gives apce_8x6's coefficients on the vehicle's layout, at --hover-rpm") in err
    assert one_line_error(code, err, "--hover-rpm: envelope hover_rpm must be a number within its rpm range"), err
    assert not (tmp_path / "o.py").exists()


def test_export_sim_vehicle_that_cannot_hover_is_refused_naming_vehicle(capsys, tmp_path):
    """cli/export_sim.py (_export_vehicle: hover_omega's refusal). Mutant: the except clause narrowed to SolverError
    (the ValueError then reported as 'propmap: error: no rotor's axis ...' without '--vehicle: its hover rpm')."""
    veh = tmp_path / "tilt.toml"
    veh.write_text(QUAD.replace("axis = [0.0, 0.0, 1.0]", "axis = [1.0, 0.0, 0.0]"))
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "gz-sim", "--out", tmp_path / "h.sdf",
                       "--vehicle", veh)
    assert one_line_error(code, err, "--vehicle: its hover rpm: no rotor's axis has an upward component: the "
                                     "vehicle cannot hover"), err
    assert not (tmp_path / "h.sdf").exists()


# ---------------------------------------------------------------- cli/map.py


def test_map_axis_with_text_bounds_is_refused_naming_the_option(capsys, tmp_path):
    """cli/map.py (parse_axis). Mutant: 'except ValueError' made 'except KeyError' (float('a') then escapes: 'could not
    convert string to float', without the option)."""
    code, _, err = run(capsys, "map", "apce_8x6", "--out", tmp_path / "m.nc", "--rpm", "a:9000:5")
    assert one_line_error(code, err, "--rpm: 'a:9000:5' is not start:stop:count with numbers and an integer count")
    code, _, err = run(capsys, "map", "apce_8x6", "--out", tmp_path / "m.nc", "--airspeed", "0:15:4.5")
    assert one_line_error(code, err, "--airspeed: '0:15:4.5' is not start:stop:count"), err
    assert not (tmp_path / "m.nc").exists()


# ---------------------------------------------------------------- cli/loads.py (--points)


def test_loads_points_file_over_the_size_limit_is_refused_before_reading(capsys, tmp_path):
    """cli/_points.py (_points_header; a sparse file of 2 GiB + 1 byte: no disk used). Mutant: the size refusal deleted
    (the file is then read: its zeros refused as NUL bytes, another message)."""
    f = tmp_path / "big.csv"
    with open(f, "wb") as fh:
        fh.truncate(2 * 1024 ** 3 + 1)
    code, out, err = run(capsys, "loads", "apce_8x6", "--points", f, "--out", tmp_path / "o.csv")
    assert one_line_error(code, err, "big.csv: 2147483649 bytes; at most 2147483648 are read"), err
    assert out == "" and not (tmp_path / "o.csv").exists()


def test_loads_points_header_line_over_64_kib_is_refused(capsys, tmp_path):
    """cli/_points.py (_points_header). Mutant: the refusal made 'if False:' (the 70000-byte line is then refused as 'a
    column name of 65533 characters', not as a header line too long)."""
    f = tmp_path / "pts.csv"
    f.write_text("rpm," + "x" * 70000)
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", f, "--out", tmp_path / "o.csv")
    assert one_line_error(code, err, "pts.csv: the header line is longer than 65536 bytes"), err


def test_loads_points_without_out_is_refused(capsys, tmp_path):
    """cli/loads.py (_points_command). Mutant: the refusal made 'if False:' (None then reaches the output check: an
    internal error, TypeError, exit 1)."""
    f = tmp_path / "pts.csv"
    f.write_text("rpm,airspeed,incidence_deg\n6000,0,0\n")
    code, out, err = run(capsys, "loads", "apce_8x6", "--points", f)
    assert one_line_error(code, err, "--out is required with --points (a file, or '-' for standard output)"), err
    assert out == ""


# ---------------------------------------------------------------- io/params_tables.py (via read_params and CLI)


def test_params_file_coverage_that_is_not_a_table_is_refused(capsys, tmp_path):
    """io/params_tables.py (coverage_from_dict). Mutant: the isinstance(table, dict) check made 'if False:' (then
    iterating 3 raises TypeError, no file name: an internal error in the CLI, exit 1)."""
    f = tmp_path / "cov.toml"
    f.write_text("coverage = 3\n" + _params_text(tmp_path))
    with pytest.raises(ParamsFileError, match=r"cov\.toml: \[coverage\] must be a table, got 3"):
        read_params(f)
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "6000", "--params", f)
    assert one_line_error(code, err, "[coverage] must be a table, got 3"), err


def test_params_file_body_that_is_not_a_table_is_refused(tmp_path):
    """io/params_tables.py (body_from_dict). Mutant: the isinstance(table, dict) check made 'if False:' (a TypeError,
    'int' object is not iterable, leaves read_params, not a ParamsFileError)."""
    f = tmp_path / "body.toml"
    f.write_text("body = 3\n" + _params_text(tmp_path))
    with pytest.raises(ParamsFileError,
                       match=r"\[body\] must be a table with drag_area \(wash_factor optional\), got 3"):
        read_params(f)


def test_params_file_body_with_an_unknown_key_is_refused_naming_it(tmp_path):
    """io/params_tables.py (body_from_dict). Mutant: 'extra = []' (a typo such as 'colour' read silently)."""
    f = tmp_path / "body2.toml"
    f.write_text(_params_text(tmp_path) + "\n[body]\ndrag_area = 0.01\ncolour = 1\n")
    with pytest.raises(ParamsFileError, match=r"\[body\]: unknown key\(s\) 'colour' \(allowed: drag_area,"):
        read_params(f)


# ---------------------------------------------------------------- vehicle/file.py, vehicle/layout.py, vehicle/trim.py


def test_vehicle_file_body_that_is_not_a_table_is_refused(tmp_path):
    """vehicle/file.py (_body). Mutant: the isinstance(table, dict) check made 'if False:' (a TypeError, no file
    name)."""
    f = tmp_path / "v.toml"
    f.write_text(QUAD.replace("inertia =", "body = 3\ninertia =", 1))
    with pytest.raises(VehicleFileError, match=r"v\.toml: \[body\] must be a table with drag_area"):
        pm.read_vehicle(f)


def test_vehicle_file_rotor_params_that_are_not_text_are_refused(tmp_path):
    """vehicle/file.py (_rotor_params). Mutant: the check made 'if False:' (a TypeError joining the vehicle's folder
    with 3)."""
    f = tmp_path / "v.toml"
    f.write_text(QUAD.replace('propeller = "apce_8x6"', 'propeller = "apce_8x6"\nparams = 3', 1))
    with pytest.raises(VehicleFileError, match=r"rotor 1: params must be a parameter file or a named set \(a string\)"):
        pm.read_vehicle(f)


def test_rotor_params_given_as_a_name_are_refused(apc8x6):
    """vehicle/layout.py (__post_init__). Mutant: the SectionParams check made 'if False:' (a name kept as the rotor's
    set)."""
    with pytest.raises(ValueError, match="Rotor.params must be a parameter set or None, got str"):
        pm.Rotor((0.1, 0.0, 0.0), (0.0, 0.0, 1.0), 1, apc8x6, params="gill2017-apc")


def test_trim_vehicle_airspeed_that_is_not_a_number_is_refused_naming_it():
    """vehicle/trim.py (_number). Mutant: the except branch made 'v = 0.0' (text trimmed as hover, no error)."""
    veh = pm.read_vehicle(resources.files("propmap").joinpath("data/examples/quadrotor.toml"))
    with pytest.raises(ValueError, match=r"airspeed must be a finite number in \[0, 100\] m/s, got 'fast'"):
        trim_vehicle(veh, pm.default_params("apce_8x6"), "fast")


def test_rotor_position_and_vehicle_inertia_that_are_ragged_are_refused_naming_them(apc8x6):
    """vehicle/layout.py (_vector3, __post_init__; NumPy's ValueError of a ragged list). Mutants: ValueError dropped
    from each except tuple (NumPy's inhomogeneous-shape message escapes, naming neither field)."""
    with pytest.raises(ValueError, match=r"^Rotor.position must be 3 finite numbers \(body axes\), got \[\[0.1\]"):
        pm.Rotor([[0.1], [0.0, 0.0]], (0.0, 0.0, 1.0), 1, apc8x6)
    veh = pm.read_vehicle(resources.files("propmap").joinpath("data/examples/quadrotor.toml"))
    with pytest.raises(ValueError, match=r"^Vehicle.inertia must be a 3x3 tensor or its diagonal"):
        replace(veh, inertia=[[1.0], [1.0, 2.0]])


# ---------------------------------------------------------------- identify/options.py


def test_fit_option_bounds_that_are_not_a_dict_or_have_a_non_text_name_are_refused():
    """identify/options.py (_check_bounds). Mutants: the dict check deleted (a list of pairs: AttributeError
    'items'), the name check deleted (1 then refused as an unknown name, not as a non-string)."""
    with pytest.raises(ValueError, match=r"bounds must be a dict of name -> \(low, high\), got list"):
        FitOptions(bounds=[("cd_min", (0.0, 0.1))])
    with pytest.raises(ValueError, match="bounds: a name must be a string, got 1"):
        FitOptions(bounds={1: (0.0, 0.1)})


def test_fit_names_given_as_one_string_are_refused(apc8x6):
    """identify/options.py (_check_names). Mutant: the check made 'if False:' (then 'cd_min' is split into letters,
    refused as unknown names 'c', 'd', ...). (Dropping only its isinstance(names, str) term is an equivalent
    mutant: a str is not a tuple or list either.)"""
    params = pm.default_params("apce_8x6")
    om = np.linspace(3000.0, 8000.0, 6) * math.pi / 30
    r = pm.rotor_loads(apc8x6, params, om, 0 * om, 0 * om)
    data = LoadData(om, 0 * om, 0 * om, {"thrust": r.thrust, "torque": r.torque}, np.array(["a"] * 6, object), "x")
    with pytest.raises(ValueError, match=r"names must be a tuple of parameter names \(str\), got 'cd_min'"):
        fit_loads(data, apc8x6, base=params, options=FitOptions(names="cd_min"))


# ---------------------------------------------------------------- core/trim.py


def test_trim_refuses_bounds_that_are_not_numbers_and_inputs_that_do_not_broadcast(apc8x6):
    """core/trim.py (_check_bounds, trim_collective). Mutants: ValueError dropped from the bounds' except tuple
    (float('a')'s own message); 'except ValueError' of the broadcast made 'except KeyError' (NumPy's message, no
    names)."""
    params = pm.default_params("apce_8x6")
    with pytest.raises(ValueError, match=r"^bounds must be two numbers \[rad\], got 'ab'"):
        pm.trim_collective(apc8x6, params, 1.0, 600.0, 0.0, 0.0, bounds="ab")
    with pytest.raises(ValueError, match="^thrust, omega, airspeed and incidence must broadcast together"):
        pm.trim_collective(apc8x6, params, [1.0, 2.0, 3.0], [600.0, 700.0], 0.0, 0.0)


# ---------------------------------------------------------------- core: hover, polar, airfoil


def test_hover_model_refuses_non_numeric_rates_and_a_bool_coefficient():
    """core/hover.py (_finite_rates, from_coefficients). Mutants: 'except (TypeError, ValueError)' made 'except
    KeyError' (float()'s TypeError escapes, no 'omega' in it); the isinstance(v, bool) term dropped (True read as CT =
    1)."""
    h = pm.HoverModel.from_coefficients(0.1, 0.05, 0.2)
    with pytest.raises(ValueError, match=r"omega must be a number or an array of numbers \[rad/s\], got \{'a': 1\}"):
        h.thrust({"a": 1})
    with pytest.raises(ValueError, match="CT must be a finite number, got True"):
        pm.HoverModel.from_coefficients(True, 0.05, 0.2)
    # the numbers it takes: T = CT rho n^2 D^4 (n in rev/s), against the formula
    n = 100.0
    assert float(h.thrust(2 * math.pi * n)) == pytest.approx(0.1 * pm.Air().rho * n ** 2 * 0.2 ** 4, rel=1e-12)


def test_polar_with_a_ragged_alpha_is_refused_naming_it():
    """core/polar.py (_polar_inputs). Mutant: 'except ValueError' made 'except KeyError' (NumPy's inhomogeneous-shape
    message escapes, not naming alpha)."""
    with pytest.raises(ValueError, match=r"alpha must be a number or an array of numbers, got \[0\.1, \[0\.2"):
        pm.lift_coefficient([0.1, [0.2, 0.3]], pm.preset("gill2017-apc"))


def test_params_with_an_unknown_descent_model_are_refused():
    """core/airfoil.py (_check_rotor_options). Mutant: the descent check made 'if False:' ('vortex' kept without a
    word)."""
    with pytest.raises(ValueError, match="descent must be one of glauert, empirical, got 'vortex'"):
        pm.default_params("apce_8x6").replace(descent="vortex")


# ---------------------------------------------------------------- readers: flight log, load CSV


def test_a_matlab_v73_flight_log_is_refused_with_how_to_save_it(tmp_path):
    """io/flightlog.py (_mat_array; SciPy's NotImplementedError for an HDF5 MAT-file). Mutant: the except clause made
    'except KeyError' (SciPy's 'Please use HDF reader' escapes as NotImplementedError)."""
    head = b"MATLAB 7.3 MAT-file, Platform: GLNXA64, Created on: Mon Jan  1 00:00:00 2024 HDF5 schema 1.00 ."
    f = tmp_path / "log.mat"
    f.write_bytes(head.ljust(116, b" ") + b"\x00" * 8 + b"\x00\x02IM" + b"\x00" * 512)
    with pytest.raises(FlightLogError, match=r"log\.mat: MATLAB v7\.3 \(HDF5\) file; save it as MATLAB v5"):
        read_flight_log(f)


def test_a_load_csv_with_text_after_a_closing_quote_is_refused_with_its_line(tmp_path):
    """identify/csvfile.py (_rows; the csv module's "',' expected after '\"'" said in words). Mutant: the
    'expected after' branch deleted (the csv module's own message then)."""
    f = tmp_path / "q.csv"
    f.write_text('rpm,thrust,torque\n"6000"x,1,0.01\n6000,1,0.01\n')
    with pytest.raises(DataError, match=r"q\.csv, line 2: a closing quote must be followed by a comma or the end"):
        read_loads(f)
    g = tmp_path / "q2.csv"
    g.write_text('rpm;thrust;torque\n"6000"x;1;0.01\n6000;1;0.01\n')
    with pytest.raises(DataError, match="a closing quote must be followed by a semicolon"):
        read_loads(g)


# ---------------------------------------------------------------- cli/fit.py --skip-sanity-check


def test_fit_loads_skip_sanity_check_warns_and_fits(capsys, tmp_path):
    """cli/fit.py (_sanity_warnings: the sanity check's refusal said as a warning with --skip-sanity-check, and kept for
    the report). Mutants: warn(str(exc)) deleted (the 6x thrust slip fitted unsaid); said.append(str(exc)) deleted (the
    report's data_warnings lose it)."""
    src = _stand_csv(tmp_path, thrust_scale=6.0)
    out = tmp_path / "p.toml"
    code, _, err = run(capsys, "fit", "loads", src, "--prop", "apce_8x6", "--out", out, "--skip-sanity-check")
    assert code == 0, err
    slip = r"the measured thrust (\d+\.\d+) times what the model predicts for apce_8x6 at the measured rpm"
    said = re.search(f"propmap: warning: load data: {re.escape(str(src))}: {slip}", err)
    # (the check's model is the generic set, whose thrust lies within 10% of apce_8x6's own set's: about 6x)
    assert said and 5.0 < float(said.group(1)) < 7.0, err
    assert "(--skip-sanity-check fits it anyway)" not in err
    assert out.exists()
    read_params(out)  # (the written set reads back: a malformed file raises)
    report = json.loads((tmp_path / "p.report.json").read_text())
    assert any(re.search(slip, w) for w in report["data_warnings"])
