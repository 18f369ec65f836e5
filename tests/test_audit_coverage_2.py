"""A coverage-guided test-gap audit, second round: user-reachable branches that the first round
(tests/test_audit_coverage.py) left unexecuted, in identify/, the CLI's fit, map and validate commands, the
readers and the map builder. Each test names the module and the function holding the lines it covers and the
hand-made mutant of them it kills (each mutant run by hand: the test failed, and passes on the clean source)."""

from __future__ import annotations

import json
import math
import re
from dataclasses import replace
from importlib import resources

import numpy as np
import pytest
import scipy.io
import xarray as xr

import propmap as pm
from cli_helpers import one_line_error, run
from ulog_writer import hover_ulog
from propmap.identify import DataError, FitOptions, LoadData, fit_loads, read_loads
from propmap.identify.flight_samples import flight_samples
from propmap.identify.sanity import sanity_check
from propmap.maps import RotorMap
from propmap.io.flightlog import NEUROBEM_COLUMNS, read_flight_log
from propmap.io.flightlog_checks import FlightLogError
from propmap.export_c import c_header_text
from propmap.io.mapfile import read_dataset, read_sidecar, write_map
from propmap.io.params_file import params_from_dict, set_coverage

EXAMPLES = resources.files("propmap").joinpath("data/examples")
QUAD = EXAMPLES.joinpath("quadrotor.toml").read_text()
RPM = np.linspace(3000.0, 8000.0, 6)


def _loads_csv(tmp_path, header, rows, name="loads.csv"):
    path = tmp_path / name
    path.write_text(header + "\n" + "".join(",".join(str(x) for x in r) + "\n" for r in rows))
    return path


def _mixed_quad(tmp_path):
    """The example quad with apce_8x4 on its rotors 3 and 4 (apce_8x6 on 1 and 2)."""
    head, *rest = QUAD.split('propeller = "apce_8x6"')
    assert len(rest) == 4
    text = head + "".join(f'propeller = "{p}"' + part for p, part in zip(
        ("apce_8x6", "apce_8x6", "apce_8x4", "apce_8x4"), rest))
    path = tmp_path / "mixed.toml"
    path.write_text(text)
    return path


# ---------------------------------------------------------------- identify/loads_air.py


def test_load_csv_air_columns_of_text_or_empty_are_noted_and_not_read(tmp_path):
    """identify/loads_air.py (_conditions_density: a temperature column of text, a pressure column empty in every
    row). Mutants: 'except DataError' made 'except KeyError' (read_loads then refuses the file over its air
    columns); the empty-column check made 'if False:' (the median of nothing, NaN, then said as 'they give ...')."""
    d = read_loads(_loads_csv(tmp_path, "rpm,thrust,temperature (C),pressure (Pa)",
                              [(r, 1e-7 * r * r, "warm", 101325) for r in RPM]))
    skip = "; 'temperature (C)' and 'pressure (Pa)' are not read (give the air with --temperature-c/--pressure-pa"
    assert d.notes == ("'temperature (C)' is not numeric" + skip  # (naming the column since 2026-11-30)
                       + ", --rho or a density column)",)
    assert d.air_density is None
    np.testing.assert_allclose(d.measured["thrust"], 1e-7 * RPM ** 2)
    d = read_loads(_loads_csv(tmp_path, "rpm,thrust,temperature (C),pressure (Pa)",
                              [(r, 1e-7 * r * r, 15, "") for r in RPM]))
    assert d.notes == ("'pressure (Pa)' is empty in every row" + skip + ", --rho or a density column)",)
    assert d.air_density is None


# ---------------------------------------------------------------- identify/csvfile.py, loads_csv.py


def test_a_preamble_line_like_a_header_that_cannot_be_read_is_passed_over(tmp_path):
    """identify/csvfile.py (_Csv.after_preamble: a candidate header whose rows do not read, DataError, or that no row
    follows, StopIteration). Line 2 names rpm and thrust but opens a quote never closed: the header is line 3. A
    candidate on the file's last line: the file refused as having no rotation-speed column. Mutants: DataError
    dropped from the except tuple (the unterminated quote refused, though a header follows); StopIteration dropped
    (a StopIteration leaves read_loads)."""
    rows = "".join(f"{r:g},{1e-7 * r * r:g}\n" for r in RPM)
    f = tmp_path / "pre.csv"
    f.write_text('Stand export v2\nrpm,thrust,"comment\nrpm,thrust\n' + rows)
    d = read_loads(f)
    assert d.notes == (f"{f}: lines 1-2 above the header (line 3) not read: a preamble",)
    np.testing.assert_allclose(d.measured["thrust"], 1e-7 * RPM ** 2, rtol=1e-5)
    f.write_text("Stand export v2\nrpm,thrust\n")
    with pytest.raises(DataError, match="no rotation-speed column: looked for rpm .* found 'Stand export v2'; lines "
                                        "above the header"):
        read_loads(f)


def test_optical_dropouts_are_filled_from_the_electrical_speed_only_where_three_rows_show_both(tmp_path):
    """identify/loads_csv.py (_optical_gaps: fewer than 3 rows where both speeds read: the ratio is not judged). 9
    rows, the electrical speed in each, the optical one in the first 2, then 3: with 2 the dropouts stay (the file
    keeps 2 points, refused for a fit), with 3 the other 6 take the electrical speed, with a note. Mutant: the
    'both.sum() < 3' guard deleted (2 rows then fill 7 without a word of doubt: 9 points read)."""
    rates = (3000, 3500, 4000, 4500, 5000, 5500, 6000, 7000, 8000)
    f = tmp_path / "oe.csv"
    for n_both in (2, 3):
        f.write_text("Motor Optical Speed (RPM),Motor Electrical Speed (RPM),Thrust (N)\n" + "".join(
            f"{r if k < n_both else ''},{r},{1e-7 * r * r:g}\n" for k, r in enumerate(rates)))
        if n_both == 2:
            with pytest.raises(DataError, match="oe.csv has 2 points; a fit needs at least 6 distinct operating"):
                read_loads(f)
        else:
            d = read_loads(f)
            np.testing.assert_allclose(d.omega * 30 / math.pi, rates, rtol=1e-6)
            assert ("'Motor Optical Speed (RPM)' reads 0 or nothing in 6 rows where the electrical speed runs (a probe "
                    "dropout): those rows take the electrical speed, within 0.0% of the optical one") in d.notes[1]


def test_a_thrust_ratio_is_judged_over_two_loaded_points_or_more(apc8x6):
    """identify/sanity.py (_moderate_mismatch: fewer than 2 points where the model's thrust is at least 30% of its
    static thrust: no median ratio). One rate, 6000 rpm, airspeeds towards the zero-thrust advance ratio, the loads
    1.5 times the generic set's: with a point at 14 m/s (31% of the static thrust) two points are loaded and the
    1.5x is warned of; at 14.5 m/s (27%) only the static point is, and nothing is said. Mutant: '< 2' made '< 3' (the
    two loaded points then not judged: the 1.5x unsaid). (Deleting the guard is an equivalent mutant: the model's
    ratios of one point give no ratio either, their own 'ok.sum() >= 2'.)"""
    g = pm.generic_params()
    om = np.full(6, 6000 * math.pi / 30)
    said = []
    for second in (14.0, 14.5):
        V = np.array([0.0, second, 15.0, 16.0, 17.0, 18.0])
        r = pm.rotor_loads(apc8x6, g, om, V, 0 * V)
        assert (r.thrust[1] >= 0.3 * r.thrust[0]) == (second == 14.0)
        data = LoadData(om, V, 0 * V, {"thrust": 1.5 * r.thrust, "torque": 1.5 * r.torque},
                        np.array(["a"] * 6, object), "x")
        said.append(list(sanity_check(data, apc8x6)))
    assert len(said[0]) == 1 and said[0][0].startswith("the measured thrust is 1.5 times (outside 0.714-1.4x) what "
                                                       "the generic set predicts for apce_8x6 in the median")
    assert said[1] == []


# ---------------------------------------------------------------- identify/flight_samples.py, options.py


def test_flight_samples_refuse_no_logs_and_a_log_that_is_a_path():
    """identify/flight_samples.py (flight_samples: no logs; _log_part: a log that is not a FlightLog). Mutants: the
    empty check made 'if False:' (np.concatenate of nothing: 'need at least one array', no word of logs); the
    isinstance check made 'if False:' (a str's missing n_motors: AttributeError)."""
    veh = pm.read_vehicle(EXAMPLES.joinpath("quadrotor.toml"))
    with pytest.raises(ValueError, match="^no flight logs given$"):
        flight_samples([], veh)
    with pytest.raises(ValueError, match=r"^logs must be FlightLog records \(io.flightlog.read_flight_log\), got str"):
        flight_samples(["log.csv"], veh)


def test_fit_options_x0_of_text_or_none_is_refused_naming_it():
    """identify/options.py (FitOptions.__post_init__: x0 whose items are not numbers). Mutant: 'except (TypeError,
    ValueError)' made 'except KeyError' (float('a')'s ValueError, or iterating None's TypeError, then escapes
    without naming x0)."""
    for x0, shown in (("abcd", "'abcd'"), (None, "None")):
        with pytest.raises(ValueError, match=re.escape(f"x0 must be 4 finite numbers (cl1, cl2, cd, alpha0 [rad]), "
                                                       f"got {shown}")):
            FitOptions(x0=x0)


# ---------------------------------------------------------------- io/catalogue.py, maps.py


def test_example_file_of_a_number_and_a_propeller_that_is_a_device_are_refused(capsys):
    """io/catalogue.py (example_file: a name not a str; resolve_propeller: a path that exists and is not a regular
    file). Mutants: the isinstance check made 'if False:' (3 then refused as a ValueError, 'name: 3 is not a bundled
    example', not a TypeError of its type); the path.exists() refusal deleted (/dev/null then refused as 'no file ...,
    and no catalogue propeller')."""
    with pytest.raises(TypeError, match=r"name must be a bundled example's file name \(str\), got int"):
        pm.example_file(3)
    code, out, err = run(capsys, "loads", "/dev/null", "--rpm", "6000")
    assert one_line_error(code, err, "PROP: '/dev/null' is not a regular file"), err
    assert out == ""


def test_build_map_with_a_ragged_rpm_axis_is_refused_naming_it(apc8x6):
    """maps.py (_check_axis: NumPy's ValueError of a ragged list). Mutant: ValueError dropped from the except tuple
    (NumPy's 'inhomogeneous shape' message escapes, naming no axis)."""
    with pytest.raises(ValueError, match=r"^omega must be a 1-D array of numbers \[rad/s\], got \[\[600.0\], \[700"):
        pm.build_map(apc8x6, pm.default_params("apce_8x6"), [[600.0], [700.0, 800.0]], [0.0, 5.0], [0.0, 1.0])


# ---------------------------------------------------------------- cli/map.py


def test_map_scheduler_that_is_not_an_address_is_refused_naming_the_option(capsys, tmp_path):
    """cli/map.py (_scheduler: scheduler_client's ValueError). Mutant: 'except ValueError' made 'except KeyError'
    (the ValueError then reaches the command's generic handler: its message without '--scheduler: ')."""
    code, _, err = run(capsys, "map", "apce_8x6", "--out", tmp_path / "m.nc", "--scheduler", "nonsense",
                       "--rpm", "4000:8000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:180:5",
                       "--check-points", "0")
    assert one_line_error(code, err, "--scheduler: scheduler must be an address PROTOCOL://HOST:PORT"), err
    assert "got 'nonsense'" in err
    assert not (tmp_path / "m.nc").exists() and not (tmp_path / "m.nc.json").exists()


# ---------------------------------------------------------------- cli/fit.py


def test_fit_level_flight_warns_of_a_mistyped_rpm_and_records_no_propeller_of_a_mixed_vehicle(capsys, tmp_path):
    """cli/fit.py (level_flight: level_flight_warnings said as 'DATA:' warnings; _vehicle_propeller: {} where
    the rotors carry two geometries). Mutants: the warning loop deleted (the rpm typed a tenth of its value fitted
    unsaid); _vehicle_propeller's 'return {}' deleted (the coverage then names apce_8x6 alone for rotors of two
    propellers)."""
    lines = EXAMPLES.joinpath("level_flight_synthetic.csv").read_text().splitlines()[:9]  # (8 rows: a short fit)
    row = lines[3].split(",")
    typed = float(row[3]) / 10  # rpm_2 of data row 3, a digit lost
    row[3] = f"{typed:g}"
    lines[3] = ",".join(row)
    data = tmp_path / "lf.csv"
    data.write_text("\n".join(lines) + "\n")
    code, out, err = run(capsys, "fit", "level-flight", data, "--vehicle", _mixed_quad(tmp_path),
                         "--out", tmp_path / "p.toml", "--fit-params", "cd", "--json")
    assert code == 0, err
    assert (f"propmap: warning: DATA: data row 3: rpm_2 = {typed:g} is 0.1 times the row's median rotor speed "
            "(1 such value(s)): a truncated or mistyped value?") in err
    cov = json.loads(out)["coverage"]
    assert not {"propeller", "diameter_m", "n_blades", "re75_min"} & set(cov), cov
    top = max(float(ln.split(",")[0]) for ln in lines[1:])
    assert cov["rpm_min"] == pytest.approx(typed) and cov["airspeed_max"] == pytest.approx(top)


def test_fit_loads_warns_when_the_held_out_group_is_predicted_worse_than_by_its_base(capsys, tmp_path):
    """cli/fit.py (loads, the fit loads command: its held-out check: held_out_worse's groups said as a warning). Mutant:
    the 'if worse:' branch made 'if False:' (a fit to group a, its thrust 1.3 times the model's, predicts group b, the
    model's own loads, 3x worse than the unfitted generic set, unsaid)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    r = pm.rotor_loads(prop, params, RPM * math.pi / 30, 0 * RPM, 0 * RPM)
    rows = [(f"{w:.1f}", f"{k * t:.6f}", f"{q:.7f}", g) for g, k in (("a", 1.3), ("b", 1.0))
            for w, t, q in zip(RPM, r.thrust, r.torque)]
    src = _loads_csv(tmp_path, "rpm,thrust,torque,group", rows)
    code, _, err = run(capsys, "fit", "loads", src, "--prop", "apce_8x6", "--out", tmp_path / "q.toml",
                       "--holdout", "b")
    assert code == 0, err
    said = re.search(r"propmap: warning: the fitted set predicts the held-out b 25% or more worse than generic does "
                     r"\(thrust rmse (\S+) against (\S+)\): what it learned from the fitted groups does not carry", err)
    assert said, err
    fitted, blind = float(said.group(1)), float(said.group(2))
    assert fitted >= 1.25 * blind
    # the fit matches group a, 1.3 times b's thrust at every rate: its thrust error on b is about 0.3 of b's thrust
    rms_b = float(np.sqrt(np.mean(r.thrust ** 2)))
    assert 0.25 * rms_b < fitted < 0.35 * rms_b


# ---------------------------------------------------------------- cli/validate.py, cli/_vehicle.py


def test_validate_files_says_the_readers_notes(capsys, tmp_path):
    """cli/validate.py (_validate_files: the data's notes said as 'propmap: note:'). Mutant: the note loop deleted
    (the air columns not read, unsaid: the comparison then runs at the set's air without a word). The file holds
    the calibrated set's own loads: the comparison reads 0.00% (a check the note did not change the numbers)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    r = pm.rotor_loads(prop, params, RPM * math.pi / 30, 0 * RPM, 0 * RPM)
    src = _loads_csv(tmp_path, "rpm,thrust,torque,temperature (C),pressure (Pa)",
                     [(w, f"{t:.6f}", f"{q:.7f}", "warm", 101325) for w, t, q in zip(RPM, r.thrust, r.torque)])
    code, out, err = run(capsys, "validate", src, "--prop", "apce_8x6")
    assert code == 0, err
    assert ("propmap: note: 'temperature (C)' is not numeric; 'temperature (C)' and 'pressure (Pa)' "
            "are not read") in err
    assert re.search(r"all points\s+0\.00%\s+[+-]0\.00%\s+0\.00%\s+6\s+0\.00%", out), out


def test_validate_files_with_a_torque_of_zeros_warns_then_refuses_naming_the_source(capsys, tmp_path):
    """cli/validate.py (_validate_files: load_errors' ValueError said as 'SOURCE: ...'). A torque column of 0 in every
    row (not measured): the sanity check's warning, then no static CQ to scale the errors by. Mutant: 'except
    ValueError' made 'except KeyError' (the message then reaches the generic handler without 'SOURCE: ')."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    r = pm.rotor_loads(prop, params, RPM * math.pi / 30, 0 * RPM, 0 * RPM)
    src = _loads_csv(tmp_path, "rpm,thrust,torque", [(w, f"{t:.6f}", 0) for w, t in zip(RPM, r.thrust)])
    code, out, err = run(capsys, "validate", src, "--prop", "apce_8x6")
    assert "the measured torque is 0 at every point: not measured?" in err
    assert one_line_error(code, err, "SOURCE: the mean static CQ is 0: no reference for the torque errors"), err
    assert out == ""


def test_trim_vehicle_params_file_that_is_not_toml_is_refused_naming_params(capsys, tmp_path):
    """cli/_vehicle.py (_vehicle_sets since 2026-12-01, _fitted_vehicle before: the parameter file's
    ParamsFileError named as --params's). Mutant: the exceptions caught there narrowed to KeyError (the parser's error
    then reaches the generic handler: its message without '--params: ')."""
    bad = tmp_path / "bad.toml"
    bad.write_text("this is = = not toml\n")
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", EXAMPLES.joinpath("quadrotor.toml"),
                         "--params", bad, "--airspeed", "5")
    assert one_line_error(code, err, f"--params: {bad}: not valid TOML"), err
    assert out == ""


# ---------------------------------------------------------------- vehicle/_jacobians.py, io/ulog.py, io/mapfile.py


def test_vehicle_wrench_derivatives_given_as_one_name_are_refused():
    """vehicle/_jacobians.py (requested_derivatives: a str for derivatives). Mutant: the check made 'if False:' ('omega'
    then split into the letters 'o', 'm', ..., refused as unknown names, not as a str)."""
    veh = pm.read_vehicle(EXAMPLES.joinpath("quadrotor.toml"))
    with pytest.raises(ValueError, match="^derivatives must be True, False or a sequence of names, got 'omega'$"):
        pm.vehicle_wrench(veh, pm.default_params("apce_8x6"), [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [600.0] * 4,
                          derivatives="omega")


def test_ulog_motor_map_without_actuator_outputs_is_refused(tmp_path):
    """io/ulog.py (the motor map's read of actuator_outputs, in a log of ESC rpm only). Mutant: the 'if not d:'
    refusal deleted (then d[0]: an IndexError, not a FlightLogError naming the topic)."""
    path = tmp_path / "h.ulg"
    hover_ulog(path)
    assert read_flight_log(path).n_motors == 4  # (the log reads without the map)
    with pytest.raises(FlightLogError, match=r"h\.ulg: topic 'actuator_outputs' not in the log \(needed with a motor "
                                             r"map\)"):
        read_flight_log(path, motor_map=(0.0, 10.0))


@pytest.fixture(scope="module")
def tiny_map(apc8x6):
    """apce_8x6's calibrated set, a 2 x 2 x 2 map without check points."""
    return pm.build_map(apc8x6, pm.default_params("apce_8x6"), np.array([400.0, 600.0]), np.array([0.0, 5.0]),
                        np.array([0.0, math.pi]), n_check=0)


def test_read_sidecar_that_is_not_json_is_refused_naming_it(tiny_map, tmp_path):
    """io/mapfile.py (read_sidecar: json's ValueError). Mutant: ValueError dropped from the except tuple (json's
    JSONDecodeError escapes, naming neither the sidecar nor the map)."""
    path = tmp_path / "m.nc"
    written = write_map(tiny_map, path)
    side = tmp_path / "m.nc.json"
    assert side in written and read_sidecar(path)["describes"]["sha256"]
    side.write_text("{not json")
    with pytest.raises(ValueError, match=r"m\.nc\.json: cannot read the sidecar of .*m\.nc \(Expecting property"):
        read_sidecar(path)


# ---------------------------------------------------------------- identify/flight_samples.py (_motor_spread)


def test_a_slow_motor_is_compared_only_with_three_or_more_of_its_propeller(tmp_path):
    """identify/flight_samples.py (_motor_spread: a propeller turned by fewer than 3 rotors is not compared). A PX4
    ULog (actuator outputs, --motor-map 0,10) with motor 3 at 0.3 times the others' speed: noted on the example quad
    (4 rotors of apce_8x6), not on the quad with apce_8x4 on rotors 3 and 4 (two propellers of 2 rotors: a quadplane's
    pusher is not a lift motor). Mutant: 'continue' made 'pass' (motor 3 then said at 0.46 times the median of its
    pair, a note of two rotors that differ by design)."""
    path = tmp_path / "o.ulg"
    hover_ulog(path, with_esc=False, rpm=10000.0, outputs=[1000.0, 1000.0, 300.0, 1000.0] + [0.0] * 12)
    log = read_flight_log(path, motor_map=(0.0, 10.0))
    np.testing.assert_allclose(np.median(log.rotor_omega, axis=0) * 30 / math.pi, [10000, 10000, 3000, 10000],
                               rtol=1e-6)
    same = flight_samples([log], pm.read_vehicle(EXAMPLES.joinpath("quadrotor.toml")))
    assert same.notes == ("o.ulg: motor 3's median speed is 0.3 times the median of the motors that turn its propeller "
                          "(a speed sensor or pole-pair count of its own, another rotor's number?): it is read as "
                          "logged",)
    mixed = flight_samples([log], pm.read_vehicle(_mixed_quad(tmp_path)))
    assert mixed.notes == () and mixed.n == same.n > 0


# ---------------------------------------------------------------- identify/fit.py, io/params_file.py


def test_fit_loads_of_a_quantity_not_measured_is_refused_naming_what_is(apc8x6):
    """identify/fit.py (_load_keys: a quantity the data do not hold). Mutant: the refusal made 'if False:'
    (data.measured['drag']: a KeyError 'drag', naming neither the argument nor the measured ones)."""
    params = pm.default_params("apce_8x6")
    om = RPM * math.pi / 30
    r = pm.rotor_loads(apc8x6, params, om, 0 * om, 0 * om)
    data = LoadData(om, 0 * om, 0 * om, {"thrust": r.thrust, "torque": r.torque}, np.array(["a"] * 6, object), "x")
    with pytest.raises(ValueError, match=r"^quantity 'drag' is not measured; measured: thrust, torque$"):
        fit_loads(data, apc8x6, base=params, quantities=("drag",))


def test_params_from_a_list_and_the_coverage_of_a_file_that_does_not_read(tmp_path):
    """io/params_file.py (params_from_dict: data not a table; _file_coverage: a file that does not read gives None,
    the readers then say why). Mutants: the isinstance check made 'if False:' ('list' has no 'get': AttributeError);
    'except ValueError' made 'except KeyError' (the ParamsFileError leaves set_coverage, which a command's warnings
    call before the file's own reader names the fault)."""
    with pytest.raises(ValueError, match=r"^p\.toml: expected a table of keys, got \[1, 2\]"):
        params_from_dict([1, 2], where="p.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("cl1 = = 1\n")
    assert set_coverage(str(bad)) is None
    good = tmp_path / "good.toml"
    pm.write_params(good, pm.default_params("apce_8x6"), coverage={})
    assert set_coverage(str(good)) is None  # (a file without [coverage]: None as well, by the other branch)


# ---------------------------------------------------------------- io/flightlog.py (NeuroBEM CSV)


@pytest.fixture(scope="module")
def neurobem_rows(shared_data):
    """The first 300 rows of a shared NeuroBEM segment (400 Hz) and the segment's file."""
    seg = shared_data / "neurobem_flights" / "bemnn20210223114138seg3.mat"
    a = scipy.io.loadmat(seg)
    return np.asarray(next(v for k, v in a.items() if not k.startswith("__")), float)[:300], seg


def _neurobem_csv(path, rows, order=None, head=""):
    order = list(range(len(NEUROBEM_COLUMNS))) if order is None else order
    path.write_text(head + ",".join(NEUROBEM_COLUMNS[j] for j in order) + "\n"
                    + "".join(",".join(repr(float(r[j])) for j in order) + "\n" for r in rows))
    return path


def test_a_blank_line_above_a_commented_header_still_finds_the_header(tmp_path, neurobem_rows):
    """io/flightlog.py (_csv_lines: a blank line skipped in the search for a header written as a comment). Motors 1
    and 4 swapped and named so, under '# ' after a blank line. Mutant: 'continue' made 'break' (the commented
    header then skipped: the columns read by position, motors 1 and 4 exchanged without a word)."""
    rows, seg = neurobem_rows
    order = list(range(len(NEUROBEM_COLUMNS)))
    order[20], order[23] = order[23], order[20]
    log = read_flight_log(_neurobem_csv(tmp_path / "h.csv", rows, order, head="\n# "))
    np.testing.assert_array_equal(log.rotor_omega, read_flight_log(seg).rotor_omega[:300])


def test_neurobem_reference_mass_is_none_without_a_residual_or_a_specific_force(tmp_path, neurobem_rows):
    """io/flightlog.py (_reference_mass: residual columns all 0; specific force all 0). The segment's own: 0.752 kg
    (PROVENANCE.md's vehicle). Mutants: the residual check's 'return None' made 'pass' (a residual never logged, and a
    model force 0.6 times the specific force, then read as a 0.6 kg reference); the 'if not ff > 0' check deleted (a
    ZeroDivisionError)."""
    rows, seg = neurobem_rows
    assert read_flight_log(_neurobem_csv(tmp_path / "a.csv", rows)).reference_mass == pytest.approx(0.752, abs=1e-6)
    no_residual = rows.copy()
    no_residual[:, 35:38] = 0.0  # (not logged), the model force alone 0.6 kg times the specific force
    no_residual[:, 29:32] = 0.6 * rows[:, 11:14]
    log = read_flight_log(_neurobem_csv(tmp_path / "b.csv", no_residual))
    assert log.reference_mass is None and log.reference_force is not None
    no_force = rows.copy()
    no_force[:, 11:14] = 0.0
    assert read_flight_log(_neurobem_csv(tmp_path / "c.csv", no_force)).reference_mass is None


def test_a_map_of_two_propellers_whose_per_prop_json_is_not_json_is_refused(tiny_map, tmp_path):
    """io/mapfile.py (_select: per_prop_json that json cannot read). Mutant: 'except ValueError' made 'except
    KeyError' (json's error then reaches read_dataset's handler of damaged files: 'not a readable netCDF rotor map
    (Expecting property name ...)', of a file that is one, the attribute unnamed)."""
    two = xr.concat([tiny_map, tiny_map], dim=xr.DataArray(["a", "b"], dims="prop", name="prop"),
                    combine_attrs="override")
    two.attrs["per_prop_json"] = "{bad"
    two.to_netcdf(tmp_path / "two.nc")
    with pytest.raises(ValueError, match=r"two\.nc: a map of several propellers needs the attribute per_prop_json, "
                                         r"a JSON object with an object for 'a'$"):
        read_dataset(tmp_path / "two.nc", prop="a")


# ---------------------------------------------------------------- export_c.py


def test_c_header_of_a_map_without_its_geometry_record_checks_the_vehicle_by_size(tiny_map, tmp_path):
    """export_c.py (_vehicle_block: a map whose attributes do not give map_model's geometry, as a map written before
    the geometry record: the rotors then compared by diameter and blade count). Mutants: 'except ValueError' made
    'except KeyError' (map_model's 'missing attribute' escapes for the right vehicle too); the size refusal made
    'if False:' (a 9x6 quad given the 8x6 map's table)."""
    old = tiny_map.copy()
    del old.attrs["geometry_r_m"]
    quad = pm.read_vehicle(EXAMPLES.joinpath("quadrotor.toml"))
    text = c_header_text(RotorMap(old), tmp_path / "m.h", vehicle=quad)
    assert "pm_m_vehicle_wrench(" in text
    nine = pm.load_propeller("apce_9x6")
    other = replace(quad, rotors=[replace(r, propeller=nine) for r in quad.rotors])
    with pytest.raises(ValueError, match=re.escape("rotor 1 carries apce_9x6 (0.2286 m, 2 blades), not the map's "
                                                   "apce_8x6 (0.2032 m, 2 blades): a C header holds one map")):
        c_header_text(RotorMap(old), tmp_path / "m.h", vehicle=other)
