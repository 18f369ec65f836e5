"""Stop 106: defects found by this stop's audits and rereads, each test failing on the code before its fix, except the
guards said so (what a fix must keep: files that read before). Data: synthetic load files (a collective sweep of the
catalogue's APC 10x7E, UIUC geometry)."""

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import propmap as pm

from propmap.cli.main import main
from propmap.identify import DataError, read_loads


# ---- a blade pitch column with the station it is taken at (identify/unread.py) ------------------------------------
def _sweep(path, name, airspeed=False):
    """A collective and rpm sweep whose blade angle is in column ``name`` (and a 5 m/s airspeed column)."""
    head = "rpm," + ("airspeed (m/s)," if airspeed else "") + f"{name},thrust (N),torque (N m)\n"
    v = "5," if airspeed else ""
    rows = "".join(f"{4000 + 500 * c},{v}{20 + c},{1 + 0.1 * c},{0.02 + 0.001 * c}\n" for c in range(6))
    path.write_text(head + rows)
    return path


@pytest.mark.parametrize("name", ["Blade angle 75% (deg)", "blade_pitch_75_deg", "Pitch at 0.75R (deg)",
                                  "pitch 3/4 (°)", "blade setting angle (deg)", "collective pitch"])
@pytest.mark.parametrize("airspeed", [False, True])
def test_a_blade_pitch_with_its_station_is_refused_as_a_blade_pitch(tmp_path, name, airspeed):
    """A variable-pitch propeller's sweep with its blade angle as 'Blade angle 75% (deg)' or 'blade_pitch_75_deg' was
    read at collective 0 without a word in a static file (the measured thrust then 1.65x the model's; only the
    thrust's size was warned of), and refused as a flow angle beside an airspeed (2026-12-02)."""
    with pytest.raises(DataError, match=f"column '{re.escape(name)}' looks like a blade pitch setting, which propmap "
                                        r"reads only as 'collective_deg'.*less the geometry's at the same station"):
        read_loads(_sweep(tmp_path / "s.csv", name, airspeed))


def test_a_points_file_with_a_blade_pitch_at_a_station_is_refused(tmp_path, capsys):
    """loads --points solved a 'blade_pitch_75_deg' column's rows at collective 0."""
    pts = tmp_path / "p.csv"
    pts.write_text("rpm,airspeed,incidence_deg,blade_pitch_75_deg\n5000,0,0,24\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 2
    assert "column 'blade_pitch_75_deg' looks like a blade pitch setting" in capsys.readouterr().err


@pytest.mark.parametrize("name", ["pitch trim (deg)", "pitch_1"])
def test_a_blade_pitch_word_among_others_is_noted(tmp_path, name):
    """'pitch trim (deg)' or a channel's 'pitch_1' may be a blade pitch setting: a note names collective_deg, the file
    reads ('pitch_1' was refused by a first version, its 1 taken for a station, a review)."""
    data = read_loads(_sweep(tmp_path / "s.csv", name))
    assert data.collective is None and data.n == 6
    assert any(f"column {name!r} is not read; if it is a blade pitch setting, name it 'collective_deg'" in n
               for n in data.notes), data.notes


@pytest.mark.parametrize("name", ["angle_pitch", "pitch rate (deg/s)", "Pitching moment (N m)", "prop_pitch_in",
                                  "pitch (in)", "vehicle pitch (deg)", "Geometric pitch", "geometric_pitch"])
def test_other_pitches_read_as_before(tmp_path, name):
    """Guard (passed before the fix): an attitude's pitch, a rate, a moment, a pitch in inches and a propeller's
    nominal (geometric) pitch are no blade pitch setting: the file reads, with no note on a blade pitch (the geometric
    pitch was refused by a first version, a review)."""
    data = read_loads(_sweep(tmp_path / "s.csv", name))
    assert data.collective is None and data.n == 6
    assert not any("blade pitch" in n for n in data.notes), data.notes


@pytest.mark.parametrize("name", ["Pitch (deg)", "sting pitch (deg)"])
def test_a_bare_pitch_beside_an_airspeed_is_still_refused_as_a_flow_angle(tmp_path, name):
    """Guard (passed before the fix): beside an airspeed a bare 'Pitch (deg)' may be a tunnel sting's, the flow's
    angle: refused as a flow angle, whose message names collective_deg too."""
    with pytest.raises(DataError, match=f"column '{re.escape(name)}' looks like a flow angle.*'collective_deg'"):
        read_loads(_sweep(tmp_path / "s.csv", name, airspeed=True))


# ---- unknown keys of a parameter file's tables and a vehicle file: the nearest valid one (io/toml_file.py) -----------
@pytest.mark.parametrize("table, typo, meant", [("body", "wash_factr", "wash_factor"), ("coverage", "J_maxx", "J_max"),
                                                ("vehicle", "gravty", "gravity"), ("rotor", "Spin", "spin")])
def test_an_unknown_key_in_a_table_names_the_nearest_valid_one(tmp_path, capsys, table, typo, meant):
    """A parameter file's top level said 'did you mean cl_alpha?' for 'cl_alhpa', its [body] and [coverage] tables and
    the vehicle file only listed every valid key (2026-12-02)."""

    examples = Path(pm.__file__).parent / "data" / "examples"
    if table in ("body", "coverage"):
        text = (examples / "neurobem_quadrotor.params.toml").read_text()
        key = {"body": "wash_factor =", "coverage": "J_max ="}[table]
        path = tmp_path / "p.toml"
        path.write_text(text.replace(key, f"{typo} =", 1))
        args = ["loads", "apce_8x6", "--rpm", "5000", "--params", str(path)]
    else:
        text = (examples / "quadrotor.toml").read_text()
        key = {"vehicle": "gravity =", "rotor": "spin ="}[table]
        path = tmp_path / "v.toml"
        path.write_text(text.replace(key, f"{typo} =", 1))
        args = ["trim-vehicle", "--vehicle", str(path), "--airspeed", "0"]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert re.search(rf"unknown key\(s\) '?{typo}'?: did you mean {meant}\? \((allowed|valid): ", err), err


# ---- Tyto's Flight Stand exports (identify/stand.py; a thrust-stand export audit, 2026-12-02) ------------------------
def test_a_flight_stand_export_is_read_through_its_powertrain_prefix(tmp_path):
    """A Flight Stand export ('Powertrain 1 - force Fz (thrust) (kgf)', 'Powertrain 1 - rotation speed (rpm)', ...) was
    refused (no rotation-speed column); its thrust, negative on the stand's Fz axis, was said to come from 'a pusher
    mount'. The loads are propmap's own (tests/stand_exports.py), so the steps read are checked against them."""

    from stand_exports import write_steps_export

    path = tmp_path / "fs.csv"
    truth = write_steps_export(path, series="flightstand", thrust_unit="kgf", steps=(1000, *range(1200, 1900, 100)))
    data = read_loads(path)
    assert data.n == len(truth) == 7
    np.testing.assert_allclose(data.measured["thrust"], truth[:, 1], rtol=0.01)
    np.testing.assert_allclose(data.measured["torque"], truth[:, 2], rtol=0.01)
    assert data.notes[0] == ("the prefix 'Powertrain 1 - ' is dropped from 11 column names (a powertrain's, as a "
                             "Flight Stand export writes them)")
    assert "'Powertrain 1 - force Fz (thrust) (kgf)' converted to N (x 9.80665)" in data.notes, data.notes
    assert any(n.startswith("thrust negated: 'Powertrain 1 - force Fz (thrust) (kgf)'") and "force axis Fz points "
               "along the slipstream" in n and "pusher" not in n for n in data.notes), data.notes


def test_a_flight_stand_export_of_two_powertrains_is_refused(tmp_path):
    """Two powertrains' columns: one isolated rotor is fitted, so the file is refused naming both (after stripping one
    prefix, the other's columns were dropped without a word)."""
    head = ["Time (s)", *(f"Powertrain {k} - {c}" for k in (1, 2) for c in (
        "ESC throttle (μs)", "force Fz (thrust) (N)", "torque MZ (torque) (N⋅m)", "rotation speed (rpm)"))]
    rows = "".join(f"{0.1 * i:.1f},{1100 + 100 * (i // 8)},-1.0,-0.02,{3000 + 500 * (i // 8)},"
                   f"{1100 + 100 * (i // 8)},-1.0,-0.02,{3000 + 500 * (i // 8)}\n" for i in range(48))
    (tmp_path / "two.csv").write_text(",".join(head) + "\n" + rows, encoding="utf-8")
    with pytest.raises(DataError, match=r"columns of 2 powertrains \('Powertrain 1', 'Powertrain 2'\).*one isolated "
                                        "rotor"):
        read_loads(tmp_path / "two.csv")


def test_a_name_unit_table_is_not_taken_for_a_powertrain_prefix(tmp_path):
    """Guard (read before): a prefix borne by fewer than 3 columns ('Test - 1'), or by 3 whose columns give no speed or
    load ('Ambient - temperature (C)', '... pressure', '... humidity'), is kept; so is one whose names without it
    would repeat a column's ('thrust (N)' beside 'Run 1 - thrust (N)': it was refused as two thrust columns, a
    review). 'Thrust - filtered' (no unit after ' - ') is another column, read as nothing (it was refused as an
    unknown unit, a review)."""
    rows = "".join(f"{3000 + 500 * k},{0.5 + 0.3 * k},x,20,1013,40,{0.4 + 0.3 * k}\n" for k in range(6))
    path = tmp_path / "t.csv"
    path.write_text("rpm,thrust (N),Test - 1,Ambient - temperature (C),Ambient - pressure (hPa),Ambient - humidity (%),"
                    "Thrust - filtered\n" + rows)
    data = read_loads(path)
    assert data.n == 6 and not any("prefix" in n for n in data.notes)
    rows = "".join(f"{3000 + 500 * k},{0.5 + 0.3 * k},{0.5 + 0.3 * k},0.01,{3000 + 500 * k}\n" for k in range(6))
    path.write_text("rpm,thrust (N),Run 1 - thrust (N),Run 1 - torque (N m),Run 1 - rpm\n" + rows)
    data = read_loads(path)
    assert data.n == 6 and "torque" not in data.measured and not any("prefix" in n for n in data.notes)


def test_a_flight_stand_refusal_says_the_prefix_was_dropped(tmp_path):
    """A Flight Stand export without a rotation speed was refused naming its columns without the prefix, which the
    file does not have: the refusal says the prefix was dropped."""
    head = ["Time (s)", *(f"Powertrain 1 - {c}" for c in ("ESC throttle (μs)", "force Fz (thrust) (N)",
                                                          "torque MZ (torque) (N⋅m)", "voltage (V)"))]
    path = tmp_path / "fs.csv"
    path.write_text(",".join(head) + "\n" + "".join(f"{0.1 * k},1200,-1.0,-0.02,16\n" for k in range(10)),
                    encoding="utf-8")
    with pytest.raises(DataError, match=r"no rotation-speed column: .*\(the prefix 'Powertrain 1 - ' was dropped from "
                                        r"4 column names"):
        read_loads(path)


def test_a_logger_time_in_milliseconds_is_read_as_the_time(tmp_path):
    """A logger's 'Time_ms' was not read, and its raw samples were fitted as points without a word: it is the time
    column now, so the rows-as-points note names it."""
    rows = "".join(f"{20 * i},{3000 + 10 * i},{0.5 + 0.001 * i}\n" for i in range(60))
    path = tmp_path / "log.csv"
    path.write_text("Time_ms,RPM,Thrust_g\n" + rows)
    data = read_loads(path)
    assert data.n == 60
    assert any("the file has a time column ('Time_ms') but no ESC signal column" in n for n in data.notes), data.notes


def test_a_name_dash_unit_header_is_read(tmp_path):
    """A stand log's 'Thrust - gf', 'Torque - N*m' (the unit after ' - ') was refused as 'lines above the header?';
    a clock-time 'Timestamp' beside them stays unread (not taken for the time column and refused as not a number)."""
    rows = "".join(f"10:12:{k:02d}.250,{30 + 10 * k},{3000 + 800 * k},{(1 + k) ** 2 * 40:.1f},"
                   f"{(1 + k) ** 2 * 0.001:.4f}\n" for k in range(7))
    path = tmp_path / "ly.csv"
    path.write_text("Timestamp,Throttle - %,RPM,Thrust - gf,Torque - N*m\n" + rows)
    data = read_loads(path)
    assert data.n == 7
    assert data.measured["thrust"][0] == pytest.approx(0.040 * 9.80665) and data.measured["torque"][0] == 0.001
    path.write_text("Timestamp,RPM1 - RPM,Thrust - gf\n" + "".join(f"10:12:0{k},{3000 + 500 * k},{50 + k}\n"
                                                                    for k in range(7)))
    with pytest.raises(DataError, match=r"column 'RPM1 - RPM' is in a rotation speed's unit but its name is not "
                                        r"read: name it 'rpm' \(or 'Motor speed \(RPM\)'\)"):
        read_loads(path)


def test_an_airspeed_in_inches_per_second_is_read(tmp_path):
    """'Wind Speed (in/s)' (a hobby tunnel logger's) was refused as an unknown unit."""
    rows = "".join(f"6000,{0.5 - 0.05 * k:.3f},{100 * k}\n" for k in range(7))
    path = tmp_path / "w.csv"
    path.write_text("RPM,Thrust (N),Wind Speed (in/s)\n" + rows)
    data = read_loads(path)
    assert data.airspeed[-1] == pytest.approx(600 * 0.0254)


# ---- samples descending into their rotors' wakes (cli/_vehicle.py; an audit of faster flights, 2026-12-02) ---------
def test_the_descent_state_warning_counts_samples_with_a_rotor_in_its_wake():
    """Three samples of the example quadrotor at its hover speed: at rest, descending at 4 m/s (the vortex-ring band:
    k ~ 0.6 of its v_h ~ 6.6 m/s) and flying forward at 10 m/s. Only the descent is counted; ``keep`` counts the
    samples it keeps."""

    from propmap.cli._vehicle import _descent_state_warning


    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    params = pm.generic_params()
    omega = pm.hover_omega(veh, params)
    w = pm.vehicle_wrench(veh, params, np.array([[0.0, 0, 0], [0, 0, -4.0], [10.0, 0, 0]]), np.zeros((3, 3)),
                          np.full((3, 4), omega))
    assert [str(s) for s in np.ravel(w.loads[0].state_name)] == ["normal working", "vortex ring", "normal working"]
    (line,) = _descent_state_warning(w.loads, "log.csv")
    assert line.startswith("1 of 3 samples of log.csv (33.3%) have a rotor in the vortex-ring or turbulent-wake "
                           "state")
    assert _descent_state_warning(w.loads, "log.csv", keep=[True, False, True]) == []


def test_wrench_warns_of_the_race_tracks_descents(shared_data, tmp_path, capsys):
    """wrench on the race track (the shipped NeuroBEM set) said nothing of its 6% of samples with a rotor descending
    into its wake, where its vertical force is 1.1 N low on average (docs/flight.md). Regression value: 773 samples
    (the shipped set of 2026-12-01). With --json it is among the JSON's warnings, said after the error table was
    computed (since 2026-12-02)."""
    log = shared_data / "neurobem_flights" / "bemnn20210218171908seg2.mat"
    assert main(["wrench", str(log), "--vehicle", "neurobem_quadrotor", "--out", str(tmp_path / "w.csv"),
                 "--json"]) == 0
    out, err = capsys.readouterr()
    said = ("773 of 12724 samples of bemnn20210218171908seg2.mat (6.1%) have a rotor in the vortex-ring or "
            "turbulent-wake state")
    assert f"propmap: warning: {said}" in err
    lines = [ln[len("propmap: warning: "):] for ln in err.splitlines() if ln.startswith("propmap: warning: ")]
    got = json.loads(out)["warnings"]
    assert got == lines and any(w.startswith(said) for w in got)


def test_an_incidence_within_a_tenth_of_a_degree_of_the_datas_is_not_warned_of(tmp_path):
    """A vertical descent (180 deg) on a flight set whose logs reached 179.971 deg was warned of, the only line said;
    0.1 deg beyond is within the data now, 0.5 deg still warned of."""
    from propmap.io.coverage import coverage_warnings

    p = tmp_path / "p.toml"
    pm.write_params(p, pm.default_params("apce_8x6"), coverage={"J_max": 1.0, "incidence_deg_max": 179.971})
    prop, air = pm.load_propeller("apce_8x6"), pm.Air()
    assert coverage_warnings(prop, str(p), air, 100.0, 0.0, 180.0) == []
    assert coverage_warnings(prop, str(p), air, 100.0, 0.0, 179.5) == []
    p.unlink()
    pm.write_params(p, pm.default_params("apce_8x6"), coverage={"J_max": 1.0, "incidence_deg_max": 120.0})
    assert coverage_warnings(prop, str(p), air, 100.0, 0.0, 120.09) == []
    assert coverage_warnings(prop, str(p), air, 100.0, 0.0, 120.5) == [
        f"incidence up to 120.5 deg: {p} was fitted to data up to 120 deg"]


def test_a_flight_fits_residuals_are_named_by_axis_log_and_time():
    """fit flight's report listed its largest residuals as bare indices ('#11333 -12.1'): each is named by its axis,
    log and time now, in the residual vector's order (the force errors sample by sample, then the moments')."""
    from types import SimpleNamespace


    from propmap.identify.flight import _residual_labels

    s = SimpleNamespace(log_names=("a.mat", "b.mat"), log_index=np.array([0, 0, 1]), t=np.array([0.0, 0.04, 1.5]))
    labels = _residual_labels(s, moments=False)
    assert labels[:4] == ["Fx, a.mat, t 0.00 s", "Fy, a.mat, t 0.00 s", "Fz, a.mat, t 0.00 s", "Fx, a.mat, t 0.04 s"]
    assert labels[-1] == "Fz, b.mat, t 1.50 s" and len(labels) == 9
    both = _residual_labels(s, moments=True)
    assert both[:9] == labels and both[9] == "Mx / arm, a.mat, t 0.00 s" and len(both) == 18


# ---- PX4 ULog: an ESC's telemetry marked offline (io/ulog.py; a PX4 audit, 2026-12-02) -------------------------------
def _px4_hover(n=400, hz=100.0):
    """(timestamps [us], the four topics besides the motors) of a PX4 log flying level at 1 m/s (test_flightlog's)."""
    from tests.test_flightlog import _px4_topics

    return _px4_topics(n, hz)


def test_an_escs_offline_readings_are_left_out_not_read_as_a_stopped_motor(tmp_path):
    """PX4's DShot driver zeroes an ESC's entry when its telemetry times out and clears its bit of esc_online_flags
    (PX4's own ESC check reads bit k as esc[k] online): the zeros were read as a stopped motor and interpolated into
    the samples around them (0-4050 rpm in a hover). Now they are left out with a warning, the speed interpolated
    between the online readings; flags never set (0 throughout: not kept) leave every reading in."""

    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover()
    off = range(200, 205)  # (esc[1]'s telemetry lost for 5 messages: its rpm zeroed, its bit cleared)

    def esc_rows(flags_kept):
        return [(ti, 4, (0b1101 if i in off else 0b1111) if flags_kept else 0,
                 *sum(([ti, 0 if (i in off and k == 1) else 5000] for k in range(4)), [])) for i, ti in enumerate(t)]

    fields = [("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("uint8_t", "esc_online_flags"),
              ("esc_report[4]", "esc")]
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm")]}
    topics["esc_status"] = (fields, esc_rows(True))
    write_ulog(tmp_path / "f.ulg", topics, nested)
    with pytest.warns(UserWarning, match=r"topic 'esc_status': 5 reading\(s\) of an ESC marked offline "
                                         r"\(esc_online_flags; the most, 5, of esc\[1\]\) left out"):
        log = read_flight_log(tmp_path / "f.ulg")
    np.testing.assert_allclose(log.rotor_omega * 30 / math.pi, 5000.0, rtol=1e-9)
    topics["esc_status"] = (fields, esc_rows(False))
    write_ulog(tmp_path / "g.ulg", topics, nested)
    rpm = read_flight_log(tmp_path / "g.ulg").rotor_omega[:, 1] * 30 / math.pi
    assert rpm.min() == 0.0  # (no flags kept: the zeros are the log's, read as written)


def test_an_esc_never_online_or_offline_before_arming_is_read_as_logged(tmp_path):
    """An ESC never marked online (its telemetry wire missing) made its column all NaN, refused as 'a gap in the log';
    ESCs offline for the first 100 messages (zeros before arming) had their first online reading carried back over
    them, ground samples read spinning (a review). Before an ESC's first online reading the readings stay as logged."""

    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover()
    fields = [("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("uint8_t", "esc_online_flags"),
              ("esc_report[4]", "esc")]
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm")]}
    topics["esc_status"] = (fields, [(ti, 4, 0b0111, *sum(([ti, 5000] for _ in range(4)), [])) for ti in t])
    write_ulog(tmp_path / "never.ulg", topics, nested)
    with pytest.warns(UserWarning, match=r"esc\[3\] never marked online \(esc_online_flags\): its readings are read "
                                         "as logged"):
        log = read_flight_log(tmp_path / "never.ulg")
    assert (log.rotor_omega * 30 / math.pi == 5000).all()
    topics["esc_status"] = (fields, [(ti, 4, 0 if i < 100 else 0b1111,
                                      *sum(([ti, 0 if i < 100 else 5000] for _ in range(4)), []))
                                     for i, ti in enumerate(t)])
    write_ulog(tmp_path / "arm.ulg", topics, nested)
    rpm = read_flight_log(tmp_path / "arm.ulg").rotor_omega * 30 / math.pi
    assert (rpm[:100] == 0).all() and (rpm[101:] == 5000).all()


def test_uavcan_escs_are_ordered_by_their_output_functions(tmp_path):
    """PX4's UAVCAN ESC driver fills esc[] by the ESC's index (UAVCAN output i+1) and names no actuator_function
    (PX4-Autopilot src/drivers/uavcan/actuators/esc.cpp): with UAVCAN_EC_FUNC1..4 = Motor3, Motor1, Motor4, Motor2
    the speeds were read in entry order, [5300, 5100, 5400, 5200] rpm for motors 1-4's [5100, ..., 5400]."""

    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover()
    fn = [103, 101, 104, 102]
    topics["esc_status"] = ([("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("esc_report[4]", "esc")],
                            [(ti, 4, *sum(([ti, 5000 + 100 * (fn[k] - 100)] for k in range(4)), [])) for ti in t])
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm")]}
    write_ulog(tmp_path / "can.ulg", topics, nested, params={f"UAVCAN_EC_FUNC{k + 1}": fn[k] for k in range(4)})
    log = read_flight_log(tmp_path / "can.ulg", n_motors=4)
    np.testing.assert_allclose(log.rotor_omega[0] * 30 / math.pi, [5100, 5200, 5300, 5400], rtol=1e-12)
    assert "by UAVCAN_EC_FUNCn (entries 1, 3, 0, 2" in log.motor_order
    # (without the parameters: entry order, as before)
    write_ulog(tmp_path / "plain.ulg", topics, nested)
    assert "in entry order" in read_flight_log(tmp_path / "plain.ulg", n_motors=4).motor_order


def _px4_x500():
    """(timestamps, topics, nested formats, parameters) of a PX4 log of PX4's x500 quad X at 5400 rpm, its ESC entries
    naming motors 1-4 and its control allocation's rotor geometry (motor 1 front-right ccw, 2 back-left ccw, 3
    front-left cw, 4 back-right cw)."""
    t, topics = _px4_hover()
    topics["esc_status"] = ([("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("esc_report[4]", "esc")],
                            [(ti, 4, *sum(([ti, 5400, 101 + k] for k in range(4)), [])) for ti in t])
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm"), ("uint8_t", "actuator_function")]}
    layout = [(0.13, 0.22, 0.05), (-0.13, -0.2, 0.05), (0.13, -0.22, -0.05), (-0.13, 0.2, -0.05)]
    params = {f"CA_ROTOR{i}_{k}": v for i, row in enumerate(layout) for k, v in zip(("PX", "PY", "KM"), row)}
    return t, topics, nested, params


def test_a_vehicle_file_out_of_the_px4_logs_motor_order_is_warned_of(tmp_path, capsys):
    """A PX4 log carries its vehicle's geometry (CA_ROTORn_PX, _PY, _KM; PX4's x500: motor 1 front-right ccw, 2
    back-left ccw, 3 front-left cw, 4 back-right cw): the example quadrotor's file (front-left ccw first) was read
    without a word on such a log, its moments those of other rotors. A file in the log's order reads silently."""

    from ulog_writer import write_ulog

    t, topics, nested, params = _px4_x500()
    # (guards: the parameters' defaults, every hub at the centre, and motor columns in entry order say nothing)
    defaults = {f"CA_ROTOR{i}_{k}": v for i in range(4) for k, v in (("PX", 0.0), ("PY", 0.0), ("KM", 0.05))}
    write_ulog(tmp_path / "d.ulg", topics, nested, params=defaults)
    rows = [r[:2] + tuple(x for j, x in enumerate(r[2:]) if j % 3 < 2) for r in topics["esc_status"][1]]
    plain = dict(topics, esc_status=(topics["esc_status"][0], rows))
    write_ulog(tmp_path / "e.ulg", plain, {"esc_report": nested["esc_report"][:2]}, params=params)
    for f in ("d.ulg", "e.ulg"):
        assert main(["wrench", str(tmp_path / f), "--vehicle", "quadrotor", "--out", str(tmp_path / "w.csv")]) == 0
        assert "the log's own geometry" not in capsys.readouterr().err
    write_ulog(tmp_path / "x.ulg", topics, nested, params=params)
    assert main(["wrench", str(tmp_path / "x.ulg"), "--vehicle", "quadrotor", "--out", str(tmp_path / "w.csv")]) == 0
    err = capsys.readouterr().err
    assert ("propmap: warning: x.ulg: the log's own geometry (PX4's CA_ROTORn_PX, _PY, _KM) has motors 1..4 "
            "front-right ccw, back-left ccw, front-left cw, back-right cw; the vehicle file's rotor 1 is front-left "
            "ccw (4 rotors differ): list the vehicle's rotors in the log's motor order") in err, err
    example = (Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml").read_text()
    head, *rotors = example.split("[[rotors]]")
    spins = {"front-left": "cw", "front-right": "ccw", "back-right": "cw", "back-left": "ccw"}
    by = {next(w for w in spins if w in r.splitlines()[0]): r for r in rotors}
    ordered = head + "".join("[[rotors]]" + by[w].replace('"ccw"', f'"{spins[w]}"').replace('"cw"', f'"{spins[w]}"')
                             for w in ("front-right", "back-left", "front-left", "back-right"))
    (tmp_path / "px4.toml").write_text(ordered)
    assert main(["wrench", str(tmp_path / "x.ulg"), "--vehicle", str(tmp_path / "px4.toml"), "--out",
                 str(tmp_path / "w2.csv")]) == 0
    assert "the log's own geometry" not in capsys.readouterr().err


def test_a_px4_logs_slow_vehicle_acceleration_beside_a_fast_sensor_combined_is_said(tmp_path):
    """PX4's default logging profile records vehicle_acceleration, whose messages are the samples, at 20 Hz beside a
    250 Hz sensor_combined: 157 samples of 1951 were taken without a word. Guard: both at one rate, nothing said."""
    import warnings

    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover(n=800, hz=250.0)
    topics["sensor_combined"] = ([("uint64_t", "timestamp"), ("float[3]", "accelerometer_m_s2")],
                                 [(ti, 0.0, 0.0, -9.80665) for ti in t])
    fields, rows = topics["vehicle_acceleration"]
    topics["esc_status"] = ([("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("esc_report[4]", "esc")],
                            [(ti, 4, *sum(([ti, 5400] for _ in range(4)), [])) for ti in t])
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm")]}
    write_ulog(tmp_path / "same.ulg", topics, nested)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_flight_log(tmp_path / "same.ulg").n == 800
    topics["vehicle_acceleration"] = (fields, rows[::12])  # (20.8 Hz)
    write_ulog(tmp_path / "slow.ulg", topics, nested)
    with pytest.warns(UserWarning, match=r"the samples are vehicle_acceleration's messages, logged at 20.8 Hz \(PX4's "
                                         r"default logging profile; sensor_combined, at 250 Hz, is not corrected"):
        assert read_flight_log(tmp_path / "slow.ulg").n == 67


# ---- APC PE0 files of later vintages (io/pe0.py; a geometry audit, 2026-12-02) -------------------------------------
def _pe0_lines():
    from propmap.io.catalogue import _data_path

    src = next(_data_path("apc_pe0").glob("8x6E*.PE0"))
    return src.name, src.read_text(errors="replace").splitlines()


def test_a_pe0_table_with_a_fourteenth_column_is_read_by_its_header(tmp_path):
    """APC's later PE0 files add a rake column before TWIST (14 values a row, TWIST the 9th, as a public converter of
    APC's 2026-02 archive reads them): such a file was refused as 'a value split by a blank'. A column of zeros named
    RAKE(Z) added to the catalogue's 8x6E file gives the same propeller."""

    name, lines = _pe0_lines()
    head = next(i for i, ln in enumerate(lines) if "STATION" in ln.split() and "TWIST" in ln.split())
    out = []
    for i, ln in enumerate(lines):
        parts = ln.split()
        if i == head:
            parts.insert(parts.index("THICKNESS"), "RAKE(Z)")
            ln = "  ".join(parts)
        elif i > head and len(parts) == 13 and parts[0][0].isdigit():
            ln = "  ".join([*parts[:6], "0.0000", *parts[6:]])
        out.append(ln)
    path = tmp_path / name
    path.write_text("\n".join(out) + "\n")
    mine, theirs = pm.read_geometry(path), pm.load_propeller("apce_8x6")
    np.testing.assert_allclose(mine.theta, theirs.theta, rtol=1e-12)
    np.testing.assert_allclose(mine.chord, theirs.chord, rtol=1e-12)


def test_pe0_stations_inside_the_hub_transition_are_left_out(tmp_path):
    """APC's later files tabulate the hub fairing inside HUBTRA (TWIST from 0 deg), which its v2022 files start at:
    read as blade it moved a 5x3.75 propeller's static thrust by +0.9% and its CT at J = 0.6 by -3.6%. Two stations
    put inside the catalogue's 8x6E file's HUBTRA are left out with a warning; the propeller is the catalogue's."""

    name, lines = _pe0_lines()
    first = next(i for i, ln in enumerate(lines) if len(ln.split()) == 13 and ln.split()[0][0].isdigit())
    hub = []
    for station, twist in ((0.30, 0.0), (0.60, 30.0)):
        parts = lines[first].split()
        parts[0], parts[7] = f"{station:.4f}", f"{twist:.4f}"
        hub.append("  ".join(parts))
    path = tmp_path / name
    path.write_text("\n".join([*lines[:first], *hub, *lines[first:]]) + "\n")
    with pytest.warns(UserWarning, match=r"2 station\(s\) inside HUBTRA, the hub's transition at [\d.]+ in, left out"):
        mine = pm.read_geometry(path)
    np.testing.assert_allclose(mine.r, pm.load_propeller("apce_8x6").r, rtol=1e-12)


# ---- a blade count in a third size figure (io/geometry_files.py, cli/_sources.py; a geometry audit, 2026-12-02) ------
def _hqprop_files(tmp_path):
    """HQProp's naming of a 3-blade 5.1 x 3.7 in propeller: a UIUC-format geometry (the catalogue's DA4022 5 in blade's
    table) and a static run beside it."""
    from propmap.io.catalogue import _data_path

    geom = next(_data_path("uiuc_v2").glob("da4022_5x3.75_geom.txt")).read_text()
    (tmp_path / "hqprop_5.1x3.7x3_geom.txt").write_text(geom)
    (tmp_path / "hqprop_5.1x3.7x3_static_0001.txt").write_text(
        "RPM         CT          CP\n" + "".join(f"{n}   {0.15 + 1e-6 * n:.4f}   0.0900\n"
                                                 for n in (6000, 8000, 10000)))
    return tmp_path / "hqprop_5.1x3.7x3_geom.txt", tmp_path / "hqprop_5.1x3.7x3_static_0001.txt"


def test_a_third_size_figure_gives_the_blade_count(tmp_path, capsys):
    """'hqprop_5.1x3.7x3': loads refused the geometry for want of a blade count its name gives, and validate took 2
    blades from the data file's name while warning that the name says 3 (a thrust error of 22% for 10%)."""
    geom, static = _hqprop_files(tmp_path)
    assert main(["loads", str(geom), "--rpm", "6000", "--json"]) == 0
    out = capsys.readouterr()
    assert '"n_blades": 3' in out.out and "3 blades, from the file name" in out.err
    assert main(["validate", str(static), "--prop", str(geom)]) == 0
    err = capsys.readouterr().err
    assert "3 blades, from the UIUC data files' name (hqprop_5.1x3.7x3_static_0001.txt: its third size figure)" in err
    assert "not the 3 of the file name" not in err


def test_loads_prints_the_geometrys_blade_angle_and_solidity(capsys):
    """loads printed only the blade count and the diameter, where a misread twist or chord does not show: the APC
    8x6E's blade angle at 0.75 R is the helix of its 6 in pitch, atan(6 / (0.75 pi 8)) = 17.66 deg."""
    import json

    assert main(["loads", "apce_8x6", "--rpm", "6000"]) == 0
    assert "2 blades, D = 0.2032 m, blade angle at 0.75 R 17.66 deg, solidity 0.0861; air:" in capsys.readouterr().out
    assert main(["loads", "apce_8x6", "--rpm", "6000", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["theta75_deg"] == pytest.approx(math.degrees(math.atan(6 / (0.75 * math.pi * 8))), abs=0.01)
    assert d["solidity"] == pytest.approx(0.0861, abs=5e-5)


def test_a_load_in_a_force_or_torque_unit_under_another_name_is_named_in_the_refusal(tmp_path):
    """A stand log's 'F(KG)' and 'T(N.M)' (a Chinese stand's export, as a public parser reads it) were refused as 'no
    load column' without naming them; an accelerometer's 'ax(G)' is no force."""
    path = tmp_path / "det.csv"
    path.write_text("TIME(ms),PWM(us),ax(G),N(RPM),F(KG),T(N.M)\n"
                    + "".join(f"{100 * k},{1100 + 100 * k},0.02,{3000 + 500 * k},0.2,0.01\n" for k in range(8)))
    with pytest.raises(DataError, match=r"no load column: .*; column\(s\) 'F\(KG\)' in a force's unit and 'T\(N\.M\)' "
                                        r"in a torque's unit: name the thrust 'thrust' and the torque 'torque'"):
        read_loads(path)


def test_a_pe0_header_of_other_words_than_columns_reads_its_13_columns(tmp_path):
    """Guard (read before): a header that writes 'CROSS SECTION' as two words (14 words over 13 values a row) lost its
    whole table once the header set the width ('no STATION/CHORD/.../TWIST table found', a review); a first row of a
    width neither the header's nor 13 is refused naming its line."""

    name, lines = _pe0_lines()
    head = next(i for i, ln in enumerate(lines) if "STATION" in ln.split() and "TWIST" in ln.split())
    lines[head] = lines[head].replace("CROSS-SECTION", "CROSS SECTION")
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    np.testing.assert_allclose(pm.read_geometry(path).theta, pm.load_propeller("apce_8x6").theta, rtol=1e-12)
    first = next(i for i, ln in enumerate(lines) if i > head and len(ln.split()) == 13 and ln.split()[0][0].isdigit())
    lines[first] = lines[first] + "  0.0  0.0"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(Exception, match=rf"line {first + 1}: 15 values in the station table's first row, where its "
                                        "header names 14 columns"):
        pm.read_geometry(path)


def test_the_airspeed_line_is_not_said_beside_the_j_line_of_static_data(tmp_path):
    """The airspeed line beside the advance-ratio line (said since 2026-12-02 for a flight set's faster logs) repeated
    it for a static-stand set (J_max 0, airspeed_max 0, a review); a set fitted at airspeed still gets both."""
    from propmap.io.coverage import coverage_warnings

    prop, air = pm.load_propeller("apce_8x6"), pm.Air()
    p = tmp_path / "static.toml"
    pm.write_params(p, pm.default_params("apce_8x6"), coverage={"J_max": 0.0, "airspeed_max": 0.0})
    (line,) = coverage_warnings(prop, str(p), air, 100.0, 0.5, 0.0, airspeed=10.0)
    assert line.startswith("advance ratio up to 0.50")
    q = tmp_path / "moving.toml"
    pm.write_params(q, pm.default_params("apce_8x6"), coverage={"J_max": 0.24, "airspeed_max": 11.5})
    assert [w.split(":")[0] for w in coverage_warnings(prop, str(q), air, 100.0, 0.5, 0.0, airspeed=15.0)] == [
        "advance ratio up to 0.50", "airspeed up to 15 m/s"]



# ---- tests from the mutation audit of this stop's change (each kills a mutant the suite let pass) ------------------
EXAMPLES = Path(pm.__file__).parent / "data" / "examples"


def test_a_powertrain_prefix_is_a_prefix_of_3_columns_one_a_load_or_speed():
    """The rule of _powertrain_columns, each side of it: a Flight Stand export of 3 channels is read through its prefix;
    a prefix on 2 columns ('Raw - thrust (N)' beside the read thrust), or on columns of no load or speed (the time,
    the ESC signal, a group; an ambient sensor's), is another column's name and kept; a hyphen without blanks
    ('Motor-Speed (rpm)') is no prefix."""
    from propmap.identify.stand import map_columns

    cm = map_columns(["Time (s)", "Powertrain 1 - force Fz (thrust) (N)", "Powertrain 1 - torque MZ (torque) (N⋅m)",
                      "Powertrain 1 - rotation speed (rpm)"])
    assert cm.columns["rpm"][0] == "Powertrain 1 - rotation speed (rpm)"
    assert cm.notes[0].startswith("the prefix 'Powertrain 1 - ' is dropped from 3 column names")
    for names in (["rpm", "thrust (N)", "torque (N m)", "Raw - thrust (N)", "Raw - torque (N m)"],
                  ["rpm", "thrust (N)", "Logger - time (s)", "Logger - ESC signal (us)", "Logger - group"],
                  ["rpm", "thrust (N)", "Ambient - temperature (C)", "Ambient - pressure (hPa)",
                   "Ambient - humidity (%)"]):
        cm = map_columns(names)
        assert cm.columns["thrust"][0] == "thrust (N)" and "time" not in cm.columns, (names, cm.columns)
        assert not any("prefix" in n for n in cm.notes), (names, cm.notes)
    cm = map_columns(["Time (s)", "Thrust (N)", "RPM", "Motor-Temp (C)", "Motor-Current (A)", "Motor-Speed (rpm)"])
    assert cm.columns["rpm"][0] == "RPM" and not any("prefix" in n for n in cm.notes)


def test_a_flight_stand_export_without_a_load_channel_is_refused_for_its_load():
    """A powertrain's rotation speed makes its prefix a powertrain's: the export is refused for want of a load, not of
    the speed it has."""
    from propmap.identify.stand import map_columns

    with pytest.raises(ValueError, match="no load column"):
        map_columns(["Time (s)", "Powertrain 1 - ESC throttle (μs)", "Powertrain 1 - rotation speed (rpm)",
                     "Powertrain 1 - voltage (V)"])


@pytest.mark.parametrize("name", ["time_us", "Time_sec", "timestamp_ms", "timestamp_s"])
def test_a_loggers_time_under_its_other_names_is_read_as_the_time(name):
    from propmap.identify.stand import map_columns

    assert map_columns(["RPM", "Thrust (N)", name]).columns["time"][0] == name


def test_an_unread_speed_in_the_dash_unit_form_is_refused_as_its_bracket_form_is():
    """'Wind (m/s)' is refused as an unread airspeed; 'Wind - m/s' (the ' - ' unit form, read since this stop) was left
    unread without a word, every point taken as static (the mutation audit)."""
    from propmap.identify.stand import map_columns

    with pytest.raises(ValueError, match="column 'Wind \\(m/s\\)' looks like an airspeed"):
        map_columns(["rpm", "Thrust (gf)", "Wind (m/s)"])
    with pytest.raises(ValueError, match="column 'Wind - m/s' looks like an airspeed"):
        map_columns(["rpm", "Thrust - gf", "Wind - m/s"])


def test_a_collective_angle_is_refused_as_a_blade_pitch(tmp_path):
    with pytest.raises(DataError, match="column 'Collective angle \\(deg\\)' looks like a blade pitch setting"):
        read_loads(_sweep(tmp_path / "s.csv", "Collective angle (deg)"))


def test_an_angle_that_is_no_pitch_gets_no_pitch_note(tmp_path):
    """'phase angle (deg)': an angle's word alone makes no blade pitch."""
    data = read_loads(_sweep(tmp_path / "s.csv", "phase angle (deg)"))
    assert data.n == 6 and not any("blade pitch" in n for n in data.notes), data.notes


def test_a_pitch_angle_beside_an_airspeed_is_refused_as_a_flow_angle(tmp_path):
    """'Pitch angle (deg)' beside an airspeed may be a sting's pitch: a flow angle, as 'Pitch (deg)'."""
    with pytest.raises(DataError, match="column 'Pitch angle \\(deg\\)' looks like a flow angle"):
        read_loads(_sweep(tmp_path / "s.csv", "Pitch angle (deg)", airspeed=True))


def test_two_columns_in_a_forces_unit_are_both_named(tmp_path):
    path = tmp_path / "f.csv"
    path.write_text("RPM,F1(KG),F2(KG)\n" + "".join(f"{3000 + 500 * k},0.2,0.3\n" for k in range(6)))
    with pytest.raises(DataError, match=r"column\(s\) 'F1\(KG\)', 'F2\(KG\)' in a force's unit: name the thrust"):
        read_loads(path)


def test_did_you_mean_ignores_case_and_takes_the_first_unknown_key(tmp_path, capsys):
    """A rotor's 'SPIN' is 'spin' (case ignored); of two unknown keys the first (sorted) is matched; a [coverage]
    text key and a top-level text key are among the valid ones."""
    text = (EXAMPLES / "quadrotor.toml").read_text()
    (tmp_path / "v.toml").write_text(text.replace("spin =", "SPIN =", 1))
    assert main(["trim-vehicle", "--vehicle", str(tmp_path / "v.toml"), "--airspeed", "0"]) == 2
    assert "unknown key(s) SPIN: did you mean spin?" in capsys.readouterr().err
    params = (EXAMPLES / "neurobem_quadrotor.params.toml").read_text()
    for old, new, meant in (("wash_factor =", "wash_factr = 0.5\nzz_extra =", "wash_factor"),
                            ("J_max =", 'propeler = "apce_8x6"\nJ_max =', "propeller")):
        (tmp_path / "p.toml").write_text(params.replace(old, new, 1))
        assert main(["loads", "apce_8x6", "--rpm", "5000", "--params", str(tmp_path / "p.toml")]) == 2
        assert f": did you mean {meant}? (" in capsys.readouterr().err
    (tmp_path / "p.toml").write_text('commentt = "x"\n' + params)
    assert main(["loads", "apce_8x6", "--rpm", "5000", "--params", str(tmp_path / "p.toml")]) == 2
    assert ": did you mean comment? (" in capsys.readouterr().err


def test_fit_flight_names_its_residuals_and_counts_the_training_logs_descents(shared_data, tmp_path, capsys):
    """fit flight (the race track fitted at 2 Hz, the figure-8 held out): the report's residuals are named by axis,
    log and time, and the training samples with a rotor descending into its wake are counted (the figure-8 has
    none)."""
    logs = shared_data / "neurobem_flights"
    assert main(["fit", "flight", str(logs / "bemnn20210218171908seg2.mat"), str(logs / "bemnn20210218170320seg2.mat"),
                 "--vehicle", "neurobem_quadrotor", "--holdout", "bemnn20210218170320seg2.mat", "--rate-hz", "2",
                 "--out", str(tmp_path / "p.toml")]) == 0
    out, err = capsys.readouterr()
    assert re.search(r"#\d+ [-+][\d.]+ \(Fz, bemnn20210218171908seg2\.mat, t [\d.]+ s\)", out), out
    assert re.search(r"warning: [1-9]\d* of 64 samples of the training logs \([\d.]+%\) have a rotor in the "
                     "vortex-ring", err), err
    assert "samples of held-out log" not in err


def test_fit_flight_warns_of_a_vehicle_file_out_of_the_px4_logs_motor_order(tmp_path, capsys):
    from ulog_writer import write_ulog

    t, topics, nested, params = _px4_x500()
    write_ulog(tmp_path / "a.ulg", topics, nested, params=params)
    main(["fit", "flight", str(tmp_path / "a.ulg"), "--vehicle", "quadrotor", "--out", str(tmp_path / "p.toml"),
          "--rate-hz", "5"])
    assert "a.ulg: the log's own geometry (PX4's CA_ROTORn_PX, _PY, _KM) has motors 1..4" in capsys.readouterr().err


def _quad_and_layout():
    from types import SimpleNamespace

    veh = pm.read_vehicle(EXAMPLES / "quadrotor.toml")
    return veh, lambda layout: SimpleNamespace(name="x.ulg", rotor_layout=np.asarray(layout, float))


def _turned(lay, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.column_stack([c * lay[:, 0] - s * lay[:, 1], s * lay[:, 0] + c * lay[:, 1], lay[:, 2]])


def test_the_layout_check_turns_on_30_degrees_and_on_a_spin():
    """The vehicle file's own layout turned by 20 deg is within the check, by 45 deg not (every rotor); one spin
    flipped names that rotor without a count; a rotor mounted upside down (axis -z, spin flipped) and an offset
    centre of mass (the log's positions are about it) are the same layout."""
    from dataclasses import replace

    from propmap.cli._vehicle import _layout_warnings

    veh, log = _quad_and_layout()
    lay = np.array([[r.position[0], r.position[1], r.spin] for r in veh.rotors])
    assert _layout_warnings([log(lay)], veh) == [] and _layout_warnings([log(_turned(lay, 20))], veh) == []
    (line,) = _layout_warnings([log(_turned(lay, 45))], veh)
    assert "(4 rotors differ)" in line
    flipped = lay.copy()
    flipped[2, 2] *= -1
    (line,) = _layout_warnings([log(flipped)], veh)
    assert "the vehicle file's rotor 3 is back-right ccw: list" in line
    rotors = list(veh.rotors)
    rotors[0] = replace(rotors[0], axis=np.array([0.0, 0, -1]), spin=-rotors[0].spin)
    assert _layout_warnings([log(lay)], replace(veh, rotors=tuple(rotors))) == []
    c = np.array([0.3, 0.0, 0.0])
    moved = replace(veh, centre_of_mass=c, rotors=tuple(replace(r, position=r.position + c) for r in veh.rotors))
    assert _layout_warnings([log(lay)], moved) == []


def test_a_rotor_in_the_turbulent_wake_state_is_counted():
    from propmap.cli._vehicle import _descent_state_warning

    veh = pm.read_vehicle(EXAMPLES / "quadrotor.toml")
    params = pm.generic_params()
    omega = pm.hover_omega(veh, params)
    w = pm.vehicle_wrench(veh, params, np.array([[0.0, 0, -9.0]]), np.zeros((1, 3)), np.full((1, 4), omega))
    assert str(np.ravel(w.loads[0].state_name)[0]) == "turbulent wake"
    (line,) = _descent_state_warning(w.loads, "log.csv")
    assert line.startswith("1 of 1 samples of log.csv (100.0%)")


_ESC = [("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("uint8_t", "esc_online_flags"), ("esc_report[4]", "esc")]


def test_a_zero_moment_coefficient_gives_no_rotor_layout():
    from propmap.io.ulog_motors import _px4_rotor_layout

    params = {f"CA_ROTOR{i}_{k}": v for i in range(4) for k, v in (("PX", 0.1), ("PY", 0.1), ("KM", 0.05))}
    assert _px4_rotor_layout(params, 4).shape == (4, 3)
    assert _px4_rotor_layout({**params, "CA_ROTOR2_KM": 0.0}, 4) is None
    assert _px4_rotor_layout({**params, "SYS_CTRL_ALLOC": 0}, 4) is None
    assert _px4_rotor_layout({**params, "CA_ROTOR_COUNT": 3}, 4) is None


@pytest.mark.parametrize("hz, acc_every, sc_every, said", [(250.0, 4, 1, False), (120.0, 3, 2, False),
                                                         (100.0, 8, 1, True)])
def test_slow_vehicle_acceleration_is_said_below_50_hz_and_half_the_sensors_rate(tmp_path, hz, acc_every, sc_every,
                                                                                said):
    """vehicle_acceleration at 62.5 Hz beside a 250 Hz sensor_combined (not below 50 Hz), at 40 Hz beside a 60 Hz one
    (not below half its rate): nothing said; at 12.5 Hz beside 100 Hz, said."""
    import warnings

    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover(n=480, hz=hz)
    topics["sensor_combined"] = ([("uint64_t", "timestamp"), ("float[3]", "accelerometer_m_s2")],
                                 [(ti, 0.0, 0.0, -9.80665) for ti in t[::sc_every]])
    fields, rows = topics["vehicle_acceleration"]
    topics["vehicle_acceleration"] = (fields, rows[::acc_every])
    topics["esc_status"] = (_ESC[:2] + _ESC[3:], [(ti, 4, *sum(([ti, 5400] for _ in range(4)), [])) for ti in t])
    write_ulog(tmp_path / "a.ulg", topics, {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm")]})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        read_flight_log(tmp_path / "a.ulg")
    assert any("vehicle_acceleration's messages, logged at" in str(w.message) for w in caught) == said


def test_an_offline_escs_bit_is_its_entrys_not_its_motors(tmp_path):
    """esc_online_flags' bit k is esc[k]'s: with actuator_function naming esc[0] Motor4, esc[0]'s dropout is left out
    of motor 4's speed (the 4th column), said of esc[0]."""
    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover()
    fn, off = [104, 101, 102, 103], range(200, 205)
    rows = [(ti, 4, 0b1110 if i in off else 0b1111,
             *sum(([ti, 0 if (i in off and k == 0) else 5000 + 100 * (fn[k] - 100), fn[k]] for k in range(4)), []))
            for i, ti in enumerate(t)]
    topics["esc_status"] = (_ESC, rows)
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm"), ("uint8_t", "actuator_function")]}
    write_ulog(tmp_path / "f.ulg", topics, nested)
    with pytest.warns(UserWarning, match=r"5 reading\(s\) of an ESC marked offline \(esc_online_flags; the most, 5, of "
                                         r"esc\[0\]\)"):
        log = read_flight_log(tmp_path / "f.ulg")
    np.testing.assert_allclose(log.rotor_omega[100] * 30 / math.pi, [5100, 5200, 5300, 5400], rtol=1e-9)
    np.testing.assert_allclose(log.rotor_omega[:, 3] * 30 / math.pi, 5400, rtol=1e-9)


def test_uavcan_order_where_actuator_function_is_logged_as_0_and_other_outputs_have_functions(tmp_path):
    """PX4 v1.14+ logs esc[k].actuator_function, which the UAVCAN driver leaves 0: UAVCAN_EC_FUNCn order the entries
    still; a PWM_MAIN_FUNCn of the same motors (another output group) does not; UAVCAN_ENABLE below 3 (no UAVCAN
    ESCs) leaves the entry order."""
    from propmap.io.flightlog import read_flight_log
    from ulog_writer import write_ulog

    t, topics = _px4_hover()
    fn = [103, 101, 104, 102]
    topics["esc_status"] = (_ESC[:2] + _ESC[3:],
                            [(ti, 4, *sum(([ti, 5000 + 100 * (fn[k] - 100), 0] for k in range(4)), [])) for ti in t])
    nested = {"esc_report": [("uint64_t", "timestamp"), ("int32_t", "esc_rpm"), ("uint8_t", "actuator_function")]}
    params = {**{f"PWM_MAIN_FUNC{k + 1}": 101 + k for k in range(4)},
              **{f"UAVCAN_EC_FUNC{k + 1}": fn[k] for k in range(4)}}
    write_ulog(tmp_path / "can.ulg", topics, nested, params=params)
    log = read_flight_log(tmp_path / "can.ulg", n_motors=4)
    np.testing.assert_allclose(log.rotor_omega[0] * 30 / math.pi, [5100, 5200, 5300, 5400], rtol=1e-12)
    write_ulog(tmp_path / "off.ulg", topics, nested, params={**params, "UAVCAN_ENABLE": 2})
    assert "in entry order" in read_flight_log(tmp_path / "off.ulg", n_motors=4).motor_order


def _pe0_with(tmp_path, edit):
    name, lines = _pe0_lines()
    lines = edit(list(lines))
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


def _station_rows(lines):
    return [i for i, ln in enumerate(lines) if len(ln.split()) >= 13 and ln.split()[0][0].isdigit()]


def test_a_station_at_hubtra_is_kept_and_hubtra_leaving_one_station_keeps_all(tmp_path):
    """A first station at HUBTRA is the blade's; a HUBTRA beyond all but the last station is no hub transition of this
    table (every row kept, nothing said)."""
    import warnings

    def at_hubtra(lines):
        hubtra = next(re.search(r"HUBTRA:\s*(\S+)", ln).group(1) for ln in lines if "HUBTRA:" in ln)
        i = _station_rows(lines)[0]
        lines[i] = "  ".join([hubtra, *lines[i].split()[1:]])
        return lines

    def late_hubtra(lines):
        last = float(lines[_station_rows(lines)[-1]].split()[0])
        return [re.sub(r"HUBTRA:\s*\S+", f"HUBTRA:  {last - 0.01:.4f}", ln) for ln in lines]

    for edit in (at_hubtra, late_hubtra):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            prop = pm.read_geometry(_pe0_with(tmp_path, edit))
        assert prop.r.size == pm.load_propeller("apce_8x6").r.size


def test_a_bad_twist_after_hub_stations_names_its_own_line(tmp_path):
    """The rows left out inside HUBTRA leave the line numbers of the others as they are."""
    def edit(lines):
        rows = _station_rows(lines)
        hub = []
        for station in (0.30, 0.60):
            parts = lines[rows[0]].split()
            parts[0], parts[7] = f"{station:.4f}", "0.0000"
            hub.append("  ".join(parts))
        parts = lines[rows[5]].split()
        parts[7] = "95.0000"
        lines[rows[5]] = "  ".join(parts)
        return [*lines[:rows[0]], *hub, *lines[rows[0]:]]

    _, lines = _pe0_lines()
    bad_line = _station_rows(lines)[5] + 1 + 2  # (1-based, after the 2 hub rows put before it)
    with (pytest.warns(UserWarning, match="inside HUBTRA"),
          pytest.raises(Exception, match=rf", line {bad_line}: TWIST = 95 deg")):
        pm.read_geometry(_pe0_with(tmp_path, edit))


def test_a_pe0_table_of_15_columns_is_read_by_its_header(tmp_path):
    def edit(lines):
        head = next(i for i, ln in enumerate(lines) if "STATION" in ln.split() and "TWIST" in ln.split())
        for i in range(len(lines)):
            parts = lines[i].split()
            if i == head:
                lines[i] = "  ".join([*parts[:6], "RAKE(Z)", "SKEW", *parts[6:]])
            elif i > head and len(parts) == 13 and parts[0][0].isdigit():
                lines[i] = "  ".join([*parts[:6], "0.0000", "0.0000", *parts[6:]])
        return lines

    mine = pm.read_geometry(_pe0_with(tmp_path, edit))
    np.testing.assert_allclose(mine.theta, pm.load_propeller("apce_8x6").theta, rtol=1e-12)


def test_trim_prints_the_geometrys_blade_angle_and_solidity(capsys):
    import json

    assert main(["trim", "apce_8x6", "--thrust", "2", "--rpm", "6000"]) == 0
    assert "2 blades, D = 0.2032 m, blade angle at 0.75 R 17.66 deg, solidity 0.0861; air:" in capsys.readouterr().out
    assert main(["trim", "apce_8x6", "--thrust", "2", "--rpm", "6000", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["theta75_deg"] == pytest.approx(17.66, abs=0.01) and d["solidity"] == pytest.approx(0.0861, abs=5e-5)


def test_a_px4_simulation_logs_esc_rpm_in_rad_s_is_named_in_the_refusal():
    """PX4's Gazebo bridge writes esc_rpm in rad/s (GZMixingInterfaceESC.cpp): such a log's speeds, read as rpm, are
    9.55 times too slow, and it was refused as an implausible speed without that cause; a ulog 3 times too slow is
    not said to be in rad/s."""
    from types import SimpleNamespace

    from propmap.identify.flight_samples import _check_hover

    veh = pm.read_vehicle(EXAMPLES / "quadrotor.toml")
    log = SimpleNamespace(name="sitl.ulg", format="ulog")
    with pytest.raises(ValueError, match=r"and rpm, not rad/s \(PX4's Gazebo simulation logs esc_rpm in rad/s\)"):
        _check_hover(log, np.full((50, 4), 1000.0 * math.pi / 30), veh, 1000.0)
    with pytest.raises(ValueError) as refused:
        _check_hover(log, np.full((50, 4), 1000.0 / 3), veh, 1000.0)
    assert "rad/s (PX4's Gazebo" not in str(refused.value)
