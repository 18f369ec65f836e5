"""Mutation audit of cli/_common.py (option checks and messages), cli/trim_vehicle.py, cli/_vehicle.py
and io/toml_file.py: each test names the mutant of the source it kills (the existing tests let it pass)."""

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from cli_helpers import one_line_error, run

import propmap as pm
from propmap.cli import trim_vehicle as trim_cli
from propmap.core.body import BodyDrag
from propmap.identify.flight import shift_centre_of_mass
from propmap.io.params_file import BodyTable, ParamsFileError, read_params, write_params

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
GEOMETRY = EXAMPLES / "neurobem_5.1x4.8_geom.txt"
#: a blade positive at 0.75 R (5 deg) whose angles are negative on average (-16.6 deg): twisted like a rotor
ODD_BLADE = ("r/R c/R beta\n0.15 0.15 -60\n0.30 0.17 -50\n0.50 0.17 -30\n0.70 0.15 3\n0.75 0.14 5\n0.90 0.11 8\n"
             "1.00 0.08 8\n")


@pytest.mark.parametrize("extra, match", [
    (["--diameter-in", "100.5"], "--diameter-in must be finite and in [0.5, 100] in, got 100.5"),
    (["--diameter-in", "0.49"], "--diameter-in must be finite and in [0.5, 100] in, got 0.49"),
    (["--blades", "21"], "--blades must be an integer in [1, 20], got 21"),
    (["--blades", "0"], "--blades must be an integer in [1, 20], got 0"),
])
def test_geometry_options_are_refused_just_beyond_their_bounds(capsys, extra, match):
    """Mutant A5: the diameter's bound 100 in made 1000; Mutant A6: the blade count's bound 20
    made 21 (the tests gave -9 in and 1000 blades, far beyond either)."""
    code, out, err = run(capsys, "loads", GEOMETRY, "--rpm", "8000", *extra)
    assert one_line_error(code, err, match), err
    assert out == ""


def test_trim_vehicle_climb_rate_is_bounded_by_the_slowest_airspeed(capsys):
    """Mutant T3: the climb rate checked against the fastest --airspeed instead of the slowest
    (a climb of 3 m/s at 2 m/s along the path is no flight)."""
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "2,10",
                         "--climb-rate", "3")
    assert one_line_error(code, err, "--climb-rate must be a speed within [-2, 2] m/s (at most the slowest "
                                     "--airspeed), got 3.0"), err
    assert out == ""


def test_trim_vehicle_climbs_with_the_sign_given(capsys):
    """Mutant T7: the climb rate's sign flipped on its way to trim_vehicle. Climbing at 2 m/s at
    6 m/s takes more power than descending (89.9 W against 73.6 W, generic set); the command's
    row is the function's trim."""
    vehicle, params = pm.read_vehicle("neurobem_quadrotor"), pm.generic_params()
    code, out, _ = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "6",
                       "--climb-rate", "2", "--json", "--params", "generic")
    assert code == 0
    row = json.loads(out)["trims"][0]
    up, down = pm.trim_vehicle(vehicle, params, 6.0, 2.0), pm.trim_vehicle(vehicle, params, 6.0, -2.0)
    assert up.power > down.power + 10.0
    assert row["climb_rate"] == 2.0 and row["power_W"] == pytest.approx(up.power, rel=1e-9)
    assert row["pitch_deg"] == pytest.approx(math.degrees(up.pitch), abs=1e-9)


def test_trim_vehicle_takes_up_to_max_speeds(capsys, monkeypatch):
    """Mutant T2: MAX_SPEEDS speeds refused (>= for >). With the bound at 2, two speeds trim and
    three are refused naming the bound."""
    monkeypatch.setattr(trim_cli, "MAX_SPEEDS", 2)
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "0,5", "--json")
    assert code == 0, err
    assert [r["airspeed"] for r in json.loads(out)["trims"]] == [0.0, 5.0]
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "0,5,10")
    assert one_line_error(code, err, "--airspeed must be 1 to 2 comma-separated speeds in [0, 100] m/s"), err


def test_trim_vehicle_takes_a_flight_fits_body_table(tmp_path, capsys):
    """Mutants T9 (the fit's [body] table not read), V3 (its drag dropped), V4 (its centre of mass
    dropped) and V5 (its rotor interference dropped): with --params FIT.toml the trim is the
    function's of the vehicle with the table's drag areas, centre of mass and interference."""
    fit = tmp_path / "fit.toml"
    drag, com = BodyDrag((0.05, 0.02, 0.03), 1.0), np.array([0.01, 0.005, 0.0])
    write_params(fit, pm.generic_params(), body=BodyTable(drag, com, 0.8))
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "10",
                         "--params", fit, "--json")
    assert code == 0, err
    row = json.loads(out)["trims"][0]
    veh = pm.read_vehicle("neurobem_quadrotor")
    veh = replace(shift_centre_of_mass(replace(veh, body_drag=drag), com), rotor_interference=0.8)
    want = pm.trim_vehicle(veh, pm.generic_params(), 10.0)
    assert row["pitch_deg"] == pytest.approx(math.degrees(want.pitch), abs=1e-7)
    assert row["roll_deg"] == pytest.approx(math.degrees(want.roll), abs=1e-7)
    np.testing.assert_allclose(row["rotor_rpm"], want.rotor_omega * 30 / math.pi, rtol=1e-9)
    assert row["power_W"] == pytest.approx(want.power, rel=1e-9)


def test_a_parameter_files_own_collective_keeps_its_digits(tmp_path, capsys):
    """Mutant A11: the set's collective rounded to 6 significant digits instead of 12 (a fitted
    collective of 1.23456789 deg was reported and added as 1.23457 deg)."""
    path = tmp_path / "c.toml"
    write_params(path, replace(pm.generic_params(), collective=math.radians(1.23456789)))
    code, out, err = run(capsys, "loads", "apce_8x6", "--params", path, "--rpm", "8000", "--json")
    assert code == 0, err
    got = json.loads(out)
    assert got["params_collective_deg"] == pytest.approx(1.23456789, abs=1e-10)
    assert got["collective_deg"] == pytest.approx(1.23456789, abs=1e-10)


def test_a_toml_error_names_the_file_and_tomllibs_place(tmp_path):
    """Mutant M4: the file's name dropped from a TOML syntax error (the tests matched only 'not
    valid TOML')."""
    path = tmp_path / "p.toml"
    path.write_text("cl1 = 5.3\ncl1 = 5.3\n")
    with pytest.raises(ParamsFileError) as exc:
        read_params(path)
    # (with the line's text since stop 102: a key given twice was named by nothing else)
    assert str(exc.value) == (f"{path}: not valid TOML (Cannot overwrite a value (at line 2, column 10)); "
                              "line 2: cl1 = 5.3")


def test_a_vehicle_file_error_is_the_vehicle_options(tmp_path, capsys):
    """Mutant V1: the vehicle file's error printed without '--vehicle:', the option it came from;
    Mutant M4 too (the file named)."""
    path = tmp_path / "v.toml"
    path.write_text("mass = 1.0\nmass = 2.0\n")
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", path)
    assert one_line_error(code, err, f"propmap: error: --vehicle: {path}: not valid TOML (Cannot overwrite a value "
                                     "(at line 2, column 11))"), err
    assert out == ""


def _fitted_file(tmp_path, **coverage):
    """The generic set written as a file fitted to load data of the propeller ``coverage`` names."""
    path = tmp_path / "f.toml"
    write_params(path, pm.generic_params(), coverage=coverage)
    return path


def test_a_pitch_sibling_six_percent_apart_is_warned_of(tmp_path, capsys):
    """Mutant A13: the pitch siblings' ratio tolerance 2% made 20% (apce_11x8 with a file fitted
    to apce_11x8.5, 6% more pitch, ran without a word; the tests' siblings were 10x5 and 10x7)."""
    prop = pm.load_propeller("apce_11x8")
    fit = _fitted_file(tmp_path, propeller="apce_11x8.5", diameter_m=prop.diameter, n_blades=2)
    code, _, err = run(capsys, "loads", "apce_11x8", "--params", fit, "--rpm", "5000")
    assert code == 0
    assert ("apce_11x8 runs with f.toml, fitted to data of apce_11x8.5 (the same diameter and blade count): if that "
            "is another propeller (a pitch sibling)") in err


def test_a_long_unknown_name_is_cut_to_80_characters(capsys, tmp_path):
    """Mutant A22: _short kept n characters and added '...' (83 in all) instead of cutting to n - 3
    plus '...'."""
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--out", tmp_path / "p.toml", "--quantities",
                       "thrust," + "q" * 100)
    assert code == 2
    assert err == f"propmap: error: --quantities: unknown {'q' * 77}...; valid: thrust, drag, torque, rolling_moment\n"
    assert list(tmp_path.iterdir()) == []


def test_a_file_fitted_to_another_diameter_is_warned_of_without_its_blade_count(tmp_path, capsys):
    """Mutant A16: the check left where either the diameter or the blade count is unrecorded
    (and for or): a file fitted to apce_10x7 (0.254 m, no blade count) ran apce_8x6 without a word."""
    fit = _fitted_file(tmp_path, propeller="apce_10x7", diameter_m=0.254)
    code, _, err = run(capsys, "loads", "apce_8x6", "--params", fit, "--rpm", "5000")
    assert code == 0
    assert ("propmap: warning: apce_8x6 (0.2032 m, 2 blades) runs with f.toml, fitted to data of apce_10x7 "
            "(0.254 m): its section parameters absorb that propeller's geometry and data") in err


def test_a_blade_positive_at_three_quarters_is_no_mirrored_geometry(tmp_path, capsys):
    """Mutant A19: the mirrored-geometry warning given where the angle at 0.75 R or (for and) the
    mean is negative; Mutant A20: the rotor-like blade's warning given for sets other than generic
    (for ==). This blade, 5 deg at 0.75 R and -16.6 deg on average, is a rotor's blade under the
    generic set, not a pusher's."""
    geom = tmp_path / "odd_geom.txt"
    geom.write_text(ODD_BLADE)
    code, _, err = run(capsys, "loads", geom, "--blades", "2", "--diameter-in", "10", "--rpm", "5000")
    assert code == 0
    assert "blade angles are negative" not in err
    assert ("propmap: warning: odd: blade angle 5.0 deg at 0.75 R and twist -58.0 deg from 0.30 R to the tip: a "
            "rotor's blade, not a propeller's. The generic parameters assume a hobby propeller's cambered sections; "
            "for a symmetric-section rotor give --params section:NAME (naca0012, naca0015, naca0018)") in err


def test_the_least_rotation_rate_is_accepted_and_below_it_refused(capsys):
    """Mutant A23: RPM_MIN itself refused (< for <=): 1 rpm is in [1, RPM_MAX] as the message says,
    and its coefficients are the slow rotor's (CT about 0.10, calibrated:apce_8x6); 0.5 rpm is refused."""
    code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "1", "--json")
    assert code == 0, err
    got = json.loads(out)
    assert got["rpm"] == 1.0 and 0.09 < got["CT"] < 0.11
    code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "0.5")
    assert one_line_error(code, err, "--rpm must be finite and in [1, 954929], got 0.5 (a parked propeller"), err


def test_incidence_180_deg_the_axial_descent_is_accepted(capsys):
    """Mutant A25: incidence 180 deg refused (< for <=): the axial descent, at 3 m/s and 5000 rpm
    apce_8x6's vortex ring (regression: T = 1.692 N, calibrated:apce_8x6, 2026-11-29)."""
    code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", "--airspeed", "3", "--incidence-deg", "180",
                         "--json")
    assert code == 0, err
    got = json.loads(out)
    assert got["incidence_deg"] == 180.0 and got["state"] == "vortex ring"
    assert got["thrust"] == pytest.approx(1.6923, abs=2e-4)


def test_a_negative_incidence_is_told_the_convention(capsys):
    """Mutant A27: the convention's hint given only down to -90 deg (for -180): a disk tilted to
    -120 deg is told to give the magnitude."""
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", "--incidence-deg", "-120")
    assert one_line_error(code, err, "--incidence-deg must be finite and in [0, 180] deg, got -120.0 (the model is "
                                     "symmetric: give the magnitude of a negative incidence"), err


def test_a_vehicle_option_ending_in_a_separator_is_read_as_the_folder_it_names(tmp_path, capsys):
    """Mutant A28: every PathArg refusing a value ending in a separator (the check meant for output
    files, file=True): --vehicle craft/ is an input, and the reader says the folder is no file."""
    (tmp_path / "craft").mkdir()
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", f"{tmp_path / 'craft'}/")
    assert one_line_error(code, err, f"propmap: error: --vehicle: {tmp_path / 'craft'}: is a directory, not a "
                                     "file"), err
    assert out == ""


def test_trim_vehicle_takes_a_named_set_as_params(capsys):
    """Mutant V2: --params read for a [body] table whatever it names (a named set, 'generic', is no
    file): the named set's trim is the function's with that set and the vehicle without an airframe
    (the vehicle file's own set, the default since 2026-11-30, replaced with its [body] table)."""
    argv = ("trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "3", "--json")
    code, out, err = run(capsys, *argv, "--params", "generic")
    assert code == 0, err
    named = json.loads(out)
    want = pm.trim_vehicle(pm.read_vehicle("neurobem_quadrotor"), pm.generic_params(), 3.0)
    assert named["params"] == "generic"
    assert named["trims"][0]["pitch_deg"] == pytest.approx(math.degrees(want.pitch), abs=1e-9)
    assert named["trims"][0]["pitch_deg"] == pytest.approx(-1.503, abs=1e-3)


def test_trim_vehicle_warns_once_of_a_set_calibrated_on_another_propeller(capsys):
    """Mutant V9: the rotors' propellers and sets not checked (_check_rotor_sets dropped): the
    NeuroBEM rotors with calibrated:apce_10x7 are warned of, once for the four rotors of one blade,
    and the rpm warning gives the rotors' span low to high (11909-12014 rpm)."""
    code, _, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--params", "calibrated:apce_10x7",
                       "--airspeed", "3")
    assert code == 0
    assert err.count("the set calibrated on another propeller") == 1
    assert ("propmap: warning: neurobem_5.1x4.8 runs with calibrated:apce_10x7, the set calibrated on another "
            "propeller: such a set predicts even a pitch sibling's data") in err
    assert "propmap: warning: 11909-12014 rpm: the data behind calibrated:apce_10x7 span 1975-6542 rpm" in err
