"""A mutation audit of the helpers split out of long functions (2026-11-30): identify/sanity.py, cli/fit.py,
cli/validate.py, cli/loads.py, identify/loads_csv.py, identify/flight_samples._log_part. Each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed. The load
data are the generic set's loads of bundled catalogue propellers; the flight logs are hand-built logs of the
bundled NeuroBEM quadrotor."""

import dataclasses
import math
import re

import numpy as np
import pytest

import propmap as pm
from propmap.identify.data import DataError
from propmap.identify.flight_samples import _hover_speed, flight_samples
from propmap.identify.load_data import LoadData
from propmap.identify.loads_csv import read_loads
from propmap.identify.sanity import sanity_check
from propmap.io.flightlog import FlightLog
from propmap.io.params_file import write_params

from cli_helpers import one_line_error, run
from stand_exports import write_steps_export

G = 9.80665


# --- identify/sanity.py --------------------------------------------------------------------------------------------

def _descent_data(n_static: int):
    """apce_10x7's generic-set loads: 29 descent points (0-14 m/s at 5000 rpm, incidence 180 deg) and ``n_static``
    static points at 3000-7000 rpm; (data, the number of points in the vortex-ring or turbulent-wake state)."""
    prop = pm.load_propeller("apce_10x7")
    V = np.concatenate([np.linspace(0.0, 14.0, 29), np.zeros(n_static)])
    om = np.concatenate([np.full(29, 5000.0), np.linspace(3000, 7000, n_static)]) * math.pi / 30
    inc = np.where(V > 0, math.pi, 0.0)
    r = pm.rotor_loads(prop, pm.generic_params(), om, V, inc)
    n = int(np.sum(np.isin(r.state_name, ("vortex ring", "turbulent wake")) & r.converged))
    group = np.where(V > 0, "descent", "static")
    return prop, LoadData(om, V, inc, {"thrust": r.thrust, "torque": r.torque}, group, "x"), n


def test_a_vortex_ring_share_just_above_a_tenth_is_warned_of_and_just_below_not():
    """Mutant S3 (the vortex-ring warning from 20% of the points, not 10%): descent points padded with static ones
    to 11-15% of the points in the vortex-ring state are warned of; below 10% they are not."""
    prop, data, n = _descent_data(40)
    assert n >= 4
    total = int(n / 0.12)  # (n / total in (0.11, 0.15))
    prop, data, n2 = _descent_data(total - 29)
    assert n2 == n and 0.11 <= n / data.n < 0.15
    said = [w for w in sanity_check(data, prop) if "vortex-ring or turbulent-wake" in w]
    assert len(said) == 1 and said[0].startswith(f"{n} of {data.n} points lie in the vortex-ring")
    prop, data, n3 = _descent_data(int(n / 0.09) - 29)
    assert n3 == n and n / data.n < 0.1
    assert not [w for w in sanity_check(data, prop) if "vortex-ring" in w]


def _geometry(tmp_path, prop, diameter_in):
    """``prop``'s blade (r/R, c/R, pitch angle) read from a file with the diameter ``diameter_in`` [in], 2 blades."""
    path = tmp_path / "g.txt"
    path.write_text("r/R c/R beta\n" + "".join(
        f"{x:.4f} {c:.4f} {math.degrees(t):.3f}\n" for x, c, t in zip(prop.r / prop.radius, prop.chord / prop.radius,
                                                                       prop.theta)))
    return pm.read_geometry(path, diameter_in=diameter_in, n_blades=2)


def test_a_diameter_eight_times_off_is_named_as_one_in_mm(tmp_path):
    """Mutant S10 (a diameter named only beyond 1e6 times the model's loads, not 1e4): 8 in data against the
    geometry at 64 in, thrust 8^4 = 4096 and torque 8^5 = 32768 times the data's (beyond 1e4), is named a diameter
    far off, in mm given as inches; a geometry at 32 in (torque 1024 times) is not."""
    prop = pm.load_propeller("apce_8x6")
    om = np.linspace(3000, 9000, 7) * math.pi / 30
    r = pm.rotor_loads(prop, pm.generic_params(), om, 0.0, 0.0)
    data = LoadData(om, np.zeros(7), np.zeros(7), {"thrust": r.thrust, "torque": r.torque}, np.full(7, "s"), "d")
    big = _geometry(tmp_path, prop, 64.0)
    with pytest.raises(DataError, match=r"likely a diameter far off \(1\.626 m: one in mm given as inches\?\)"):
        sanity_check(data, big)
    half = _geometry(tmp_path, prop, 32.0)
    with pytest.raises(DataError) as exc:
        sanity_check(data, half)
    assert "diameter far off" not in str(exc.value) and "check the units, the rpm and the geometry" in str(exc.value)


def _static_data(thrust_factor=1.0, rpm_factor=1.0, collective=None):
    """apce_8x6's generic-set static loads at 3000-9000 rpm (the blade at ``collective`` [rad]), the thrust times
    ``thrust_factor`` and the rates logged ``rpm_factor`` times fast: (propeller, LoadData)."""
    prop = pm.load_propeller("apce_8x6")
    om = np.linspace(3000, 9000, 7) * math.pi / 30
    r = pm.rotor_loads(prop, pm.generic_params(), om, 0.0, 0.0, collective=0.0 if collective is None else collective)
    return prop, LoadData(om * rpm_factor, np.zeros(7), np.zeros(7),
                          {"thrust": thrust_factor * r.thrust, "torque": r.torque}, np.full(7, "s"), "d",
                          collective=None if collective is None else np.full(7, collective))


def test_a_mismatch_against_given_parameters_is_said_against_the_model():
    """Mutant S15 (the warning always names the generic set): thrust 1.8 times the generic set's is warned of as
    'what the model predicts' where the parameters are given, asking whether they are this propeller's; without
    them, as the generic set's, with the catalogue's 5%."""
    prop, data = _static_data(thrust_factor=1.8)
    (w,) = sanity_check(data, prop, params=pm.generic_params())
    assert w.startswith("the measured thrust is 1.8 times (outside 0.714-1.4x) what the model predicts for "
                        "apce_8x6 in the median: check the blade count"), w
    assert w.endswith(", or whether the parameters are this propeller's")
    (w,) = sanity_check(data, prop)
    assert "what the generic set predicts for apce_8x6 in the median (the generic set is outside these for 5%" in w


def test_the_data_are_compared_at_their_own_collective():
    """Mutant S20 (the model solved without the data's collective): loads of the generic set with the blade at
    -6 deg are its own loads, nothing said; compared at 0 deg their torque (0.56 times) is warned of."""
    prop, data = _static_data(collective=math.radians(-6.0))
    assert sanity_check(data, prop) == []
    plain = dataclasses.replace(data, collective=None)
    assert any(w.startswith("the measured torque is 0.56") for w in sanity_check(plain, prop))


def test_an_electrical_rpm_of_a_twelve_pole_pair_motor_is_named():
    """Mutant S19 (pole-pair counts searched only up to 9): rates logged 12 times fast (the electrical rpm of a
    12-pole-pair motor) are refused naming a motor's pole pairs, 12 among the counts."""
    prop, data = _static_data(rpm_factor=12.0)
    with pytest.raises(DataError, match=r"the electrical rpm of a motor with ([\d, -]+) pole pairs") as exc:
        sanity_check(data, prop)
    counts = re.search(r"motor with ([\d, -]+) pole pairs", str(exc.value)).group(1)
    lo, hi = (int(x) for x in (counts.split("-") if "-" in counts else (counts, counts)))
    assert lo <= 12 <= hi, counts


def test_a_thrust_unit_slip_is_said_before_a_drag_of_the_other_sign():
    """Mutant S16 (the drag's sign refused before the thrust and torque checks): oblique-flow data with the thrust
    in kgf read as N and the drag of the other sign are refused for the thrust's unit first."""
    prop = pm.load_propeller("apce_8x6")
    om = np.full(6, 7000.0) * math.pi / 30
    V, inc = np.linspace(4.0, 12.0, 6), np.full(6, math.radians(60.0))
    r = pm.rotor_loads(prop, pm.generic_params(), om, V, inc)
    data = LoadData(om, V, inc, {"thrust": r.thrust / G, "torque": r.torque, "drag": -r.drag}, np.full(6, "o"), "o")
    with pytest.raises(DataError, match=r"likely thrust in kgf read as N"):
        sanity_check(data, prop)
    good = dataclasses.replace(data, measured={**data.measured, "thrust": r.thrust})
    with pytest.raises(DataError, match=r"the measured drag has the other sign than the model's in-plane force"):
        sanity_check(good, prop)


def test_the_vortex_ring_warning_names_four_groups_and_marks_the_rest():
    """Mutant S22 (the list of groups cut to four without ' ...'): descent points in five groups are warned of with
    the first four groups named and ' ...' for the fifth."""
    prop, data, n = _descent_data(40)
    group = np.where(data.airspeed > 0, np.array([f"d{i % 5}" for i in range(data.n)]), "static")
    data = dataclasses.replace(data, group=group)
    (w,) = [w for w in sanity_check(data, prop) if "vortex-ring" in w]
    named = re.search(r"\(groups ([^)]*)\)", w).group(1)
    assert named.endswith(" ...") and len(named[:-4].split(", ")) == 4, named


def test_slow_runs_are_named_three_at_most_then_marked():
    """Mutant S18 (two slow runs named, not three): four runs at 80-150 'rpm' (chord Reynolds numbers below 2000)
    are warned of naming the first three and ' ...'."""
    prop = pm.load_propeller("apce_8x6")
    om = np.tile([80.0, 150.0], 4) * math.pi / 30
    r = pm.rotor_loads(prop, pm.generic_params(), om, 0.0, 0.0)
    data = LoadData(om, np.zeros(8), np.zeros(8), {"thrust": r.thrust, "torque": r.torque},
                    np.repeat(["g0", "g1", "g2", "g3"], 2), "slow")
    (w,) = [w for w in sanity_check(data, prop) if "chord Reynolds number" in w]
    assert "(80-150 rpm) in g0, g1, g2 ..., below 2000" in w, w


# --- identify/loads_csv.py ----------------------------------------------------------------------------------------

def test_an_rpm_row_beyond_the_solvers_limit_in_a_steps_test_is_refused_by_its_line(tmp_path):
    """Mutant C13 (a steps test's rows not range-checked before averaging): a stand export's optical speed of
    2e6 rpm on file line 31 is refused naming that line and the limit, not averaged into (or dropped from) its
    step."""
    path = tmp_path / "steps.csv"
    write_steps_export(path)
    lines = path.read_text(encoding="utf-8-sig").splitlines()
    i = lines[0].split(",").index("Motor Optical Speed (RPM)")
    row = lines[30].split(",")
    row[i] = "2e6"
    lines[30] = ",".join(row)
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(DataError, match=r"steps\.csv, line 31: rpm must be > 0 and <= 954929 \(the solver's limit "
                                        r"of 1e5 rad/s\), got rpm = 2e\+06"):
        read_loads(path)


# --- cli/fit.py ---------------------------------------------------------------------------------------------------

def test_fit_loads_names_the_catalogue_runs_and_refuses_holding_out_the_static_one(capsys, tmp_path):
    """Mutants F3 (a catalogue propeller's static run held out without a word) and F9 (an unknown run's message
    listing the held-out names, not the data's runs): --holdout nope lists apce_8x6's runs, sorted, a static one
    among them; holding that one out is refused before any fit, and no file is written."""
    out = tmp_path / "p.toml"
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--holdout", "nope", "--out", out)
    assert one_line_error(code, err, "--holdout: unknown run(s) nope; available: "), err
    runs = re.search(r"available: (.*)$", err.strip().splitlines()[-1]).group(1).split(", ")
    assert runs == sorted(runs) and len(runs) >= 2 and "nope" not in runs
    static = [r for r in runs if r.startswith("static")]
    assert static
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--holdout", static[0], "--out", out)
    assert one_line_error(code, err, "--holdout: the static run calibrates the hover model and cannot be held out")
    assert not out.exists()


def test_fit_loads_says_the_readers_notes_and_warnings_before_refusing(capsys, tmp_path):
    """Mutants F8 (the reader's notes not said), F10 (the reader's warnings dropped) and C9 (a column
    'mechanical_power_w' not taken for a power column): a CSV of the generic set's thrust with a shaft power column
    and no torque, one row pasted twice, is noted and warned of on stderr before --holdout's refusal."""
    prop = pm.load_propeller("apce_8x6")
    rpm = np.linspace(3000, 8000, 6)
    r = pm.rotor_loads(prop, pm.generic_params(), rpm * math.pi / 30, 0.0, 0.0)
    rows = [f"{n:.1f},{T:.6f},{P:.4f}" for n, T, P in zip(rpm, r.thrust, r.torque * rpm * math.pi / 30)]
    path = tmp_path / "s.csv"
    path.write_text("\n".join(["rpm,thrust,mechanical_power_w", *rows, rows[-1]]) + "\n")
    code, _, err = run(capsys, "fit", "loads", path, "--prop", "apce_8x6", "--holdout", "nope",
                       "--out", tmp_path / "p.toml")
    assert one_line_error(code, err, "--holdout: unknown run(s) nope"), err
    assert "propmap: note: 'mechanical_power_w' is not read: propmap fits a torque column, Q = P / Omega" in err
    assert re.search(r"propmap: warning: .*s\.csv: 1 row\(s\) repeat another row to every digit", err), err


# --- cli/validate.py ----------------------------------------------------------------------------------------------

def test_validate_writes_an_svg_figure(capsys, tmp_path):
    """Mutant V4 (.svg not among the figure formats): --figure v.svg is written as SVG, exit 0."""
    fig = tmp_path / "v.svg"
    code, out, err = run(capsys, "validate", "apce_8x6", "--figure", fig)
    assert code == 0, err
    assert f"figure: {fig}" in out and b"<svg" in fig.read_bytes()[:400]


# --- cli/loads.py -------------------------------------------------------------------------------------------------

def test_loads_says_the_parameter_sets_own_collective_without_the_option(capsys, tmp_path):
    """Mutant L6 (the collective said only where --collective-deg is given): a parameter file's 3 deg collective
    is said in the first line without the option, with no 'of the parameter set' split (nothing added)."""
    f = tmp_path / "c.toml"
    write_params(f, dataclasses.replace(pm.default_params("apce_8x6"), collective=math.radians(3.0)))
    code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "6000", "--params", f)
    assert code == 0, err
    first = out.splitlines()[0]
    assert first.startswith("apce_8x6 at 6000 rpm, V = 0 m/s, incidence 0 deg, collective 3 deg (params "), first
    assert "of the parameter set" not in first


def test_loads_edgewise_and_in_a_slow_climb_write_lambda2_as_zero_without_a_sign(capsys):
    """Mutant L8 (lambda2 printed without its rounding to +0): edgewise (incidence 90 deg, where cos gives 6e-17)
    and in a 1 mm/s climb the descent ratio is 'lambda2 = V_descent/v_h = 0.000', never '-0.000'."""
    for airspeed, incidence in (("5", "90"), ("0.001", "0")):
        code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", "--airspeed", airspeed,
                             "--incidence-deg", incidence)
        assert code == 0, err
        (line,) = [x for x in out.splitlines() if "lambda2" in x]
        assert line.endswith("lambda2 = V_descent/v_h = 0.000)"), line


# --- identify/flight_samples._log_part ----------------------------------------------------------------------------

@pytest.fixture(scope="module")
def quad():
    """The bundled NeuroBEM quadrotor and its generic-set hover speed H [rad/s]."""
    veh = pm.read_vehicle("neurobem_quadrotor")
    return veh, _hover_speed(veh)


def _flight(om, rate=100.0, name="synthetic"):
    """A NeuroBEM-format log at ``rate`` Hz flying level at 3 m/s with the accelerometer reading g, its motors at
    ``om`` (shape (N, k)) [rad/s]."""
    om = np.asarray(om, float)
    n = len(om)
    return FlightLog(name=name, path="", format="neurobem", t=np.arange(n) / rate,
                     angular_velocity=np.zeros((n, 3)), angular_acceleration=np.zeros((n, 3)),
                     specific_force=np.tile([0.0, 0.0, G], (n, 1)), velocity=np.tile([3.0, 0.0, 0.0], (n, 1)),
                     attitude=np.tile([0.0, 0.0, 0.0, 1.0], (n, 1)), rotor_omega=om, rotor_acceleration=None)


def test_a_log_of_five_motors_for_four_rotors_is_refused(quad):
    """Mutant FS1 (only fewer motors than rotors refused): a log of 5 motor speeds for the quadrotor is refused,
    naming both counts."""
    veh, H = quad
    with pytest.raises(ValueError, match=r"^synthetic: 5 motor speeds but the vehicle has 4 rotors \(the vehicle "
                                         r"file lists its rotors in the log's motor order\)$"):
        flight_samples([_flight(np.full((200, 5), H))], veh, motor_time_constant=0.0)


def test_a_neurobem_log_for_a_five_rotor_vehicle_points_to_a_ulog(quad):
    """Mutant FS2 (the NeuroBEM hint only from 6 rotors): a 4-motor NeuroBEM log for a vehicle of 5 rotors is told
    that the layout carries 4 motors and more rotors need a PX4 ULog."""
    veh, H = quad
    five = dataclasses.replace(veh, rotors=tuple(veh.rotors) + (veh.rotors[0],))
    with pytest.raises(ValueError, match=r"^synthetic: 4 motor speeds but the vehicle has 5 rotors .*motor order; "
                                         r"the NeuroBEM layout carries 4 motors, a vehicle of more rotors needs a "
                                         r"PX4 ULog\)$"):
        flight_samples([_flight(np.full((200, 4), H))], five, motor_time_constant=0.0)


def test_decimation_rounds_the_step_to_the_nearest_whole_number(quad):
    """Mutant FS5 (the step truncated, not rounded): 100 Hz at 35 Hz asked is every round(2.86) = 3rd sample, 34 of
    100 samples at 33.33 Hz (truncated: every 2nd, 50 at 50 Hz)."""
    veh, H = quad
    s = flight_samples([_flight(np.full((100, 4), H))], veh, rate_hz=35.0, motor_time_constant=0.0)
    assert s.n == 34 and s.rate_hz == pytest.approx(100.0 / 3.0, rel=1e-12)
