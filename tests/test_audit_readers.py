"""A mutation audit of io/ulog.py, io/geometry_files.py and identify/csvfile.py (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files (the loads-CSV mutants a shortened set of them), by the
documented behaviour it changed."""

import math
import warnings

import numpy as np
import pytest

from propmap.identify import DataError, read_level_flight, read_loads
from propmap.io.flightlog import FlightLogError, read_flight_log
from propmap.io.geometry_files import GeometryFileError, read_apc_pe0, read_geometry, read_uiuc_geometry

from .test_flightlog import _esc, _px4_topics, _restamp
from .ulog_writer import write_ulog


# --- io/ulog.py -------------------------------------------------------------------------------------------------

def _said(path, **kw):
    """(log, the warnings' texts) of reading ``path``."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        log = read_flight_log(path, **kw)
    return log, [str(w.message) for w in caught]


def _steady(tmp_path, name="f.ulg", rpm=lambda ti, k: 5000, keep=lambda ti: True, edit=None):
    """A level, steady 4 s ULog at 100 Hz (test_flightlog's topics) with esc_status; ``edit(topics)``
    changes the topics before they are written."""
    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc(t, rpm, keep=keep)
    if edit is not None:
        edit(topics)
    write_ulog(tmp_path / name, topics, nested)
    return tmp_path / name


def test_a_repeated_stamp_leaves_out_the_repeat_alone(tmp_path):
    """_out_of_order: 'a repeat of the one before' is the message left out, not the one it repeats
    too (mutant: the repeat check dropped; the lone-message passes then left out both)."""
    path = _steady(tmp_path)
    raw = bytearray(path.read_bytes())
    t, topics = _px4_topics()
    _restamp(raw, list(topics).index("vehicle_local_position"), 101, t[99])  # message 101 stamped as message 100
    path.write_bytes(bytes(raw))
    _, said = _said(path)
    assert any("'vehicle_local_position': 1 message(s) out of time order left out (the first, message 101, "
               "stamped 1.99 s since boot)" in s for s in said), said


def test_a_block_stamped_back_is_left_out_to_the_last_stamp_it_repeats(tmp_path):
    """_out_of_order: 'then any at or before an earlier kept one': a stretch of messages stamped back
    over the ones before (a restart of the topic's clock), up to and including the one that repeats the
    latest kept stamp (mutant: '<' for '<=' kept that one, a repeated time for np.interp)."""
    path = _steady(tmp_path)
    raw = bytearray(path.read_bytes())
    t, topics = _px4_topics()
    topic = list(topics).index("vehicle_local_position")
    for k in range(101, 106):  # messages 101-105 stamped as 96-100: the last repeats message 100's stamp
        _restamp(raw, topic, k, t[k - 6])
    path.write_bytes(bytes(raw))
    _, said = _said(path)
    assert any("'vehicle_local_position': 5 message(s) out of time order left out (the first, message 101, "
               "stamped 1.95 s" in s for s in said), said


def test_a_gap_shorter_than_a_second_but_of_many_steps_is_said(tmp_path):
    """_check_steps: a gap is a step longer than gap_steps (20) median steps *or* GAP_S (1 s): a 0.5 s
    dropout of esc_status at 100 Hz is 50 steps (mutant: max for min: said nothing)."""
    path = _steady(tmp_path, keep=lambda ti: not 2.0e6 < ti < 2.5e6)
    _, said = _said(path)
    assert any("topic 'esc_status': a gap of 0.5 s at 2 s since boot (50 median steps): interpolated across" in s
               for s in said), said


def test_a_gap_across_the_start_of_the_common_time_is_said(tmp_path):
    """_check_steps counts 'the messages either side of the window: a hole across its edge': esc_status
    logged from 0.5 s, then silent until 2 s, the other topics from 1 s (mutant: the window's first
    message only, the 1.5 s hole unsaid)."""
    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc([500_000] + t, lambda ti, k: 5000, keep=lambda ti: not 5e5 < ti < 2e6)
    write_ulog(tmp_path / "f.ulg", topics, nested)
    _, said = _said(tmp_path / "f.ulg")
    assert any("topic 'esc_status': a gap of 1.5 s at 0.5 s since boot" in s for s in said), said


def test_an_attitude_interpolated_between_samples_is_a_unit_quaternion(tmp_path):
    """The attitude is interpolated component by component, then normalised: a yawing vehicle's attitude
    logged at 20 Hz read between its samples (mutant: not normalised: |q| 0.9997, the body velocity 0.06%
    short of the 2 m/s the log gives, the attitude not a rotation)."""
    t, topics = _px4_topics()
    rate = 2.0  # yaw rate [rad/s], about body z (down): FRD rate r

    def q_at(ti):
        yaw = rate * (ti - t[0]) * 1e-6
        return math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)

    topics["vehicle_attitude"] = (topics["vehicle_attitude"][0], [(ti, *q_at(ti)) for ti in t[::5]])
    topics["vehicle_angular_velocity"] = (topics["vehicle_angular_velocity"][0], [(ti, 0.0, 0.0, rate) for ti in t])
    topics["vehicle_local_position"] = (topics["vehicle_local_position"][0], [(ti, 2.0, 0.0, 0.0) for ti in t])
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000)
    write_ulog(tmp_path / "yaw.ulg", topics, nested)
    log = read_flight_log(tmp_path / "yaw.ulg")
    np.testing.assert_allclose(np.linalg.norm(log.attitude, axis=1), 1.0, atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(log.velocity, axis=1), 2.0, rtol=1e-5)
    # north seen from a body yawed by psi (right-handed about down): forward 2 cos psi, left 2 sin psi
    yaw = rate * log.t
    np.testing.assert_allclose(log.velocity[:, :2], np.column_stack([2 * np.cos(yaw), 2 * np.sin(yaw)]), atol=3e-3)


def test_a_logged_angular_acceleration_is_turned_into_propmaps_frame(tmp_path):
    """xyz_derivative is FRD like the rates: y and z negated (module docstring; mutant: read as logged)."""
    def edit(topics):
        fields = [("uint64_t", "timestamp"), ("float[3]", "xyz"), ("float[3]", "xyz_derivative")]
        rows = [(r[0], *r[1:], 0.25, 0.5, 0.75) for r in topics["vehicle_angular_velocity"][1]]
        topics["vehicle_angular_velocity"] = (fields, rows)

    log = read_flight_log(_steady(tmp_path, edit=edit))
    np.testing.assert_allclose(log.angular_acceleration, np.tile([0.25, -0.5, -0.75], (log.n, 1)))


def test_an_escs_negative_rpm_is_read_as_the_motors_speed(tmp_path):
    """esc_status' esc_rpm signed by the direction of spin (a reversed motor's negative) is read as its
    magnitude, as read_flight_log's FlightLog takes speeds (mutant: signed: 'negative motor speed')."""
    log = read_flight_log(_steady(tmp_path, rpm=lambda ti, k: -5000 if k % 2 else 5000))
    np.testing.assert_allclose(log.rotor_omega * 30 / math.pi, 5000.0, rtol=1e-12)


def test_an_esc_status_of_zero_rpm_is_refused_naming_the_motor_map(tmp_path):
    """esc_status whose esc_rpm is 0 throughout (ESCs without telemetry) is refused, pointing to
    --motor-map (mutant: the check dropped: the motors read as stopped)."""
    with pytest.raises(FlightLogError, match=r"f\.ulg: topic 'esc_status' carries no motor rpm \(esc_rpm all zero or "
                                             r"absent\); give the mapping rpm = a \+ b \* output of actuator_outputs "
                                             r"\(--motor-map a,b\)"):
        read_flight_log(_steady(tmp_path, rpm=lambda ti, k: 0))


def test_a_motor_map_below_its_zero_reads_a_stopped_motor(tmp_path):
    """rpm = a + b u of an output below the map's zero (a disarmed motor's output, a < 0) is 0 rpm,
    not a negative speed (mutant: not clipped: refused as 'negative motor speed')."""
    def edit(topics):
        del topics["esc_status"]
        fields = [("uint64_t", "timestamp"), ("uint32_t", "noutputs"), ("float[16]", "output")]
        topics["actuator_outputs"] = (fields, [(r[0], 4, *([50.0 if i < 100 else 160.0] * 4), *[0.0] * 12)
                                               for i, r in enumerate(topics["vehicle_acceleration"][1])])

    log = read_flight_log(_steady(tmp_path, edit=edit), motor_map=(-1000.0, 10.0))
    np.testing.assert_allclose(log.rotor_omega[:100] * 30 / math.pi, 0.0)
    np.testing.assert_allclose(log.rotor_omega[100:] * 30 / math.pi, 600.0, rtol=1e-6)


def test_topics_overlapping_on_min_samples_are_read(tmp_path):
    """min_samples is 'the fewest samples of the acceleration topic the topics' overlap must hold':
    an overlap of exactly MIN_SAMPLES (2) is read (mutant: '<=' refused it, 'need at least 2')."""
    t, _ = _px4_topics()
    log = read_flight_log(_steady(tmp_path, keep=lambda ti: ti <= t[1]))
    assert log.n == 2


def test_the_common_time_starts_where_the_motor_topic_does(tmp_path):
    """Every topic is interpolated over 'the time they all cover': esc_status from 2 s, the others
    from 1 s: the log starts at 2 s (mutant: the motors' start left out: 100 samples of the first
    motor message held constant before it)."""
    log = read_flight_log(_steady(tmp_path, keep=lambda ti: ti >= 2_000_000))
    assert log.n == 300 and log.t[0] == 0.0


def test_a_velocity_message_with_either_flag_invalid_is_left_out(tmp_path):
    """_valid_velocity reads the messages flagged valid by v_xy_valid *and* v_z_valid: 20 with only
    v_z_valid 0 are left out (mutant: 'or': read, their 0 m/s with them)."""
    def edit(topics):
        fields = topics["vehicle_local_position"][0] + [("bool", "v_xy_valid"), ("bool", "v_z_valid")]
        topics["vehicle_local_position"] = (fields, [(r[0], *((0.0, 0.0, 0.0) if 100 <= i < 120 else r[1:]), 1,
                                                      int(not 100 <= i < 120))
                                                     for i, r in enumerate(topics["vehicle_local_position"][1])])

    log, said = _said(_steady(tmp_path, edit=edit))
    assert any("20 of 400 velocity messages flagged invalid (v_xy_valid, v_z_valid) left out" in s for s in said)
    np.testing.assert_allclose(log.velocity, np.tile([1.0, 0.0, 0.0], (log.n, 1)), atol=1e-6)


def _esc_with_functions(tmp_path, name, functions, unassigned_first=0):
    """A steady log whose esc_status entry k is at 5000 + 100 k rpm with actuator_function functions[k]
    (0 in the first ``unassigned_first`` messages, before the mixer assigns it)."""
    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000 + 100 * k, functions)
    rows = topics["esc_status"][1]
    for i in range(unassigned_first):
        row = list(rows[i])
        for k in range(4):
            row[2 + 3 * k + 2] = 0
        rows[i] = tuple(row)
    write_ulog(tmp_path / name, topics, nested)
    return tmp_path / name


def test_esc_functions_beyond_motor12_are_no_motors(tmp_path):
    """PX4's Motor1..Motor12 are functions 101..112 (MOTOR_FUNCTIONS): two entries of function 113
    are no motors, not one motor on two entries; the two others are the vehicle's (mutant: 113 counted
    as motor 13: 'assigns motor 13 to two entries')."""
    log = read_flight_log(_esc_with_functions(tmp_path, "f.ulg", [102, 113, 101, 113]))
    np.testing.assert_allclose(log.rotor_omega[0] * 30 / math.pi, [5200, 5000], rtol=1e-12)


def test_an_esc_function_is_its_most_frequent_nonzero_value(tmp_path):
    """_esc_motor_order: 'each entry's function: its most frequent nonzero value (0 before the mixer
    assigns it)': 0 in the first 250 of 400 messages (mutant: 0 counted: entry order, no error)."""
    log = read_flight_log(_esc_with_functions(tmp_path, "f.ulg", [104, 101, 102, 103], unassigned_first=250))
    np.testing.assert_allclose(log.rotor_omega[0] * 30 / math.pi, [5100, 5200, 5300, 5000], rtol=1e-12)
    assert "by actuator_function (entries 1, 2, 3, 0)" in log.motor_order


def test_vehicle_acceleration_is_read_before_sensor_combined(tmp_path):
    """The accelerations are vehicle_acceleration's, sensor_combined's only where it is not logged
    (module docstring; PX4 logs both: mutant: sensor_combined first, its raw accelerometer read)."""
    def edit(topics):
        fields = [("uint64_t", "timestamp"), ("float[3]", "accelerometer_m_s2")]
        topics["sensor_combined"] = (fields, [(r[0], 0.3, 0.0, -9.80665) for r in topics["vehicle_acceleration"][1]])

    log = read_flight_log(_steady(tmp_path, edit=edit))
    np.testing.assert_allclose(log.specific_force, np.tile([0.0, 0.0, 9.80665], (log.n, 1)), atol=1e-5)


_OUT = [510.0, 520.0, 530.0, 540.0, 550.0] + [0.0] * 11  # rpm / 10 on outputs 1-5


def _outputs_log(tmp_path, params, n_outputs=8):
    from .ulog_writer import hover_ulog

    hover_ulog(tmp_path / "o.ulg", with_esc=False, n_outputs=n_outputs, outputs=_OUT, params=params)
    return tmp_path / "o.ulg"


def test_a_motor_on_two_outputs_is_read_from_the_lower(tmp_path):
    """_output_motor_order keeps each motor's lowest output (PWM_MAIN_FUNC1 and FUNC5 both Motor1:
    output 1; mutant: the last parameter's, output 5)."""
    params = {f"PWM_MAIN_FUNC{i}": 100 + i for i in range(1, 5)} | {"PWM_MAIN_FUNC5": 101}
    log = read_flight_log(_outputs_log(tmp_path, params), motor_map=(0.0, 10.0), n_motors=4)
    np.testing.assert_allclose(log.rotor_omega[0] * 30 / math.pi, [5100, 5200, 5300, 5400], rtol=1e-6)


def test_a_motor_on_the_output_after_the_last_logged_is_refused(tmp_path):
    """A motor on output noutputs + 1 (PWM_MAIN_FUNC9 with 8 outputs logged) is refused naming it
    (mutant: '>' for '>=': its unlogged value, 0, read as the motor's speed)."""
    params = {f"PWM_MAIN_FUNC{i}": 100 + i for i in range(1, 4)} | {"PWM_MAIN_FUNC9": 104}
    with pytest.raises(FlightLogError, match=r"by PWM_MAIN_FUNCn puts a motor on output 9; topic 'actuator_outputs' "
                                             r"\(instance 0\) has 8 outputs"):
        read_flight_log(_outputs_log(tmp_path, params), motor_map=(0.0, 10.0), n_motors=4)


def test_betaflights_order_of_a_quadrotor_is_refused_for_three_rotors(tmp_path):
    """MOT_ORDERING = 1 orders a quadrotor's 4 motors: a vehicle of 3 rotors is refused (mutant: 'n < 3':
    the 4 motors read for 3 rotors)."""
    with pytest.raises(FlightLogError, match=r"MOT_ORDERING = 1 \(Betaflight's order of a quadrotor's 4 motors\); "
                                             "the vehicle has 3 rotors"):
        read_flight_log(_outputs_log(tmp_path, {"MOT_ORDERING": 1}), motor_map=(0.0, 10.0), n_motors=3)


def test_a_damaged_file_cut_short_is_said_damaged_once(tmp_path):
    """A damaged file is said as such; 'the file ends inside a message' is said of an undamaged one
    only (mutant: both said)."""
    path = _steady(tmp_path)
    raw = bytearray(path.read_bytes())
    raw[len(raw) // 2:len(raw) // 2 + 64] = bytes(64)
    (tmp_path / "d.ulg").write_bytes(bytes(raw[:int(len(raw) * 0.8)]))
    _, said = _said(tmp_path / "d.ulg")
    assert any("d.ulg: a damaged ULog file (" in s for s in said), said
    assert not any("ends inside a message" in s for s in said), said


def test_mot_ordering_changing_during_the_log_is_refused(tmp_path):
    """MOT_ORDERING changed during the log (the motors' outputs with it) is refused (mutant: the
    check dropped: the first value read for the whole log)."""
    from .ulog_writer import hover_ulog

    hover_ulog(tmp_path / "o.ulg", with_esc=False, n_outputs=8, outputs=_OUT, params={"MOT_ORDERING": 1},
               changed=[(1_500_000, "MOT_ORDERING", 0)])
    with pytest.raises(FlightLogError, match="parameter MOT_ORDERING changes during the log"):
        read_flight_log(tmp_path / "o.ulg", motor_map=(0.0, 10.0), n_motors=4)


def test_a_gap_across_the_end_of_the_common_time_is_said(tmp_path):
    """The accelerations end at 3 s; esc_status has a message at 3 s, then none until 4.5 s: the hole
    across the window's end is said (mutant: the window's last message left out, the hole with it)."""
    def edit(topics):
        rows = topics["vehicle_acceleration"][1]
        rows[:] = [r for r in rows if r[0] <= 3_000_000]

    _, said = _said(_steady(tmp_path, keep=lambda ti: not 3.0e6 < ti < 4.5e6, edit=edit))
    assert any("topic 'esc_status': a gap of 1.5 s at 3 s since boot" in s for s in said), said


# --- io/geometry_files.py ---------------------------------------------------------------------------------------

#: a plausible UIUC geometry table (r/R c/R beta)
_STATIONS = [(0.15, 0.12, 40.0), (0.3, 0.17, 32.0), (0.5, 0.19, 24.0), (0.7, 0.16, 18.0), (0.9, 0.11, 14.0),
             (1.0, 0.07, 12.0)]


def _uiuc(tmp_path, name="x_10x5_geom.txt", stations=_STATIONS, head="r/R c/R beta\n"):
    path = tmp_path / name
    path.write_text(head + "".join(f"{r:g} {c:g} {b:g}\n" for r, c, b in stations))
    return path


def _quiet(reader, *args, **kw):
    """reader(*args, **kw), failing on any warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return reader(*args, **kw)


def test_a_uiuc_station_at_the_axis_is_refused_naming_the_range(tmp_path):
    """UIUC r/R lies in (0, 1] (module docstring): a station at r/R = 0 is refused naming its line and
    the open range (mutant: [0, 1]: read)."""
    path = _uiuc(tmp_path, stations=[(0.0, 0.12, 40.0)] + _STATIONS[1:])
    with pytest.raises(GeometryFileError, match=r"x_10x5_geom\.txt, line 2: r/R \(station radius / tip radius\) = 0 "
                                                r"is outside \(0, 1\]"):
        read_uiuc_geometry(path)


def test_a_repeated_uiuc_station_is_refused_in_the_files_terms(tmp_path):
    """Radii not strictly increasing are refused naming the file's lines and r/R (the reader's own
    check; mutant: '<' for '<=': a repeated station was left to Propeller, which says it in metres)."""
    path = _uiuc(tmp_path, stations=_STATIONS[:3] + [_STATIONS[2]] + _STATIONS[3:])
    with pytest.raises(GeometryFileError, match=r"line 5: r/R = 0\.5 does not exceed the previous station's 0\.5 "
                                                r"\(line 4\): the stations must be strictly increasing"):
        read_uiuc_geometry(path)


@pytest.mark.parametrize("name, diameter_in", [("x_100x50_geom.txt", 100.0), ("x_0.5x0.3_geom.txt", 0.5),
                                               ("vp_2540x1270_geom.txt", 100.0)])
def test_a_diameter_from_the_name_at_either_end_of_its_range_is_read(tmp_path, name, diameter_in):
    """A diameter from the name must lie in [0.5, 100] in, both ends included (mutant: open)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (vp: read in millimetres, warned)
        prop = read_uiuc_geometry(_uiuc(tmp_path, name), n_blades=2)
    assert prop.diameter == pytest.approx(diameter_in * 0.0254, rel=1e-12)


def test_a_millimetre_family_after_a_prefix_is_read_in_millimetres(tmp_path):
    """The family is the name's part just before the size: 'old_ef_130x70' is of the ef family, in
    millimetres (mutant: the name's first part, 'old': 130 in, refused as implausible)."""
    from propmap.io.geometry_files import size_from_name

    assert size_from_name("old_ef_130x70") == (130.0, 70.0, "mm", "ef")
    with pytest.warns(UserWarning, match="diameter 130 mm = 5.118 in from the file name"):
        prop = read_uiuc_geometry(_uiuc(tmp_path, "old_ef_130x70_geom.txt"))
    assert prop.diameter == pytest.approx(0.130, rel=1e-12)


def test_a_rotors_small_slightly_twisted_angles_in_degrees_are_not_called_radians(tmp_path):
    """A rotor's small, nearly untwisted angles in degrees do not warn: r tan(beta) over 0.3-1 R varies
    by 0.31 of its mean, above RADIANS_PITCH_CV = 0.25 (the catalogue's propellers read as radians:
    <= 0.185; mutant: 0.35, warned)."""
    stations = [(r, 0.13, 1.0 - 0.25 * (r - 0.15) / 0.85) for r, _, _ in _STATIONS]
    prop = _quiet(read_uiuc_geometry, _uiuc(tmp_path, stations=stations))
    np.testing.assert_allclose(np.degrees(prop.theta), [s[2] for s in stations], rtol=1e-5)  # (as written: %g)


def test_blade_angles_in_radians_up_to_1_5_are_warned_of(tmp_path):
    """Every angle below 1.6 in magnitude and a near-constant pitch read as radians: warned (the APC
    8x6E's degrees / 57.3: 0.21-0.64; a coarse pitch's root at 1.5 rad; mutant: below 1.2 only)."""
    r = np.array([s[0] for s in _STATIONS])
    beta = np.arctan(0.4 / np.maximum(r, 0.27))  # (a constant pitch 2 pi 0.4 R; 1.5 rad at the root)
    beta[0] = 1.5
    stations = [(ri, ci, round(float(bi), 4)) for (ri, ci, _), bi in zip(_STATIONS, beta)]
    with pytest.warns(UserWarning, match="every blade angle beta is below 1.6 in magnitude: the column looks like "
                                         "radians"):
        read_uiuc_geometry(_uiuc(tmp_path, stations=stations))


def test_a_helicopter_style_rotors_slender_blades_are_not_warned_of(tmp_path):
    """c/R below 0.12 is not warned of for a rotor's blades (rotor_like: untwisted, a collective;
    mutant: warned as a chord in another unit)."""
    stations = [(r, 0.06, 8.0) for r, _, _ in _STATIONS]
    prop = _quiet(read_uiuc_geometry, _uiuc(tmp_path, stations=stations))
    assert float(np.max(prop.chord)) == pytest.approx(0.06 * 0.127, rel=1e-12)


def test_uiuc_stations_stopping_at_0_7_r_are_extrapolated_with_a_warning(tmp_path):
    """Refused *inside* r/R = 0.7 (LAST_STATION_REFUSED); at 0.7 the blade beyond is extrapolated and
    warned of (mutant: '<=': refused)."""
    with pytest.warns(UserWarning, match=r"the stations stop at r/R = 0\.7: the blade from there to the tip is "
                                         "extrapolated"):
        read_uiuc_geometry(_uiuc(tmp_path, stations=_STATIONS[:4]))


def test_uiuc_stations_starting_at_0_45_r_are_warned_of(tmp_path):
    """Stations that start outside r/R = 0.4 (FIRST_STATION_MAX) are warned of (mutant: from 0.5)."""
    stations = [(0.45, 0.18, 26.0)] + _STATIONS[2:]
    with pytest.warns(UserWarning, match=r"the stations start at r/R = 0\.45: the blade inside it makes no load"):
        read_uiuc_geometry(_uiuc(tmp_path, stations=stations))


def test_a_geom_suffix_in_capitals_is_not_the_propellers_name(tmp_path):
    """The name is the file's without _geom.txt, in any case (mutant: 'X_10X5_GEOM.TXT' kept whole)."""
    assert _quiet(read_uiuc_geometry, _uiuc(tmp_path, "X_10X5_GEOM.TXT")).name == "X_10X5"


def test_a_uiuc_header_in_capitals_is_recognised(tmp_path):
    """read_geometry recognises a UIUC file by its header 'r/R ...' in any case (as read_uiuc_geometry
    reads it; mutant: 'R/R C/R BETA' unrecognised)."""
    prop = _quiet(read_geometry, _uiuc(tmp_path, head="R/R C/R BETA\n"), n_blades=3)
    assert prop.n_blades == 3 and prop.diameter == pytest.approx(0.254, rel=1e-12)


def _pe0(tmp_path, radius="5.00", last=None, *, stations=None, twist0=35.0, pitch_tip=None):
    """A PE0 file (t10x5-PERF.PE0) of 13 columns (STATION, CHORD, PITCH (QUOTED), ..., TWIST the 8th),
    2 blades: STATION ``stations`` [in] (default 9 rows from 0.2 to 1 R; ``last`` the last station
    instead), CHORD 0.15 R, QUOTED pitch 5.0, 5.1, ... in (``pitch_tip`` the last), TWIST ``twist0``
    - 3 k deg."""
    R = float(radius)
    stations = [R * (0.2 + 0.1 * k) for k in range(9)] if stations is None else list(stations)
    if last is not None:
        stations[-1] = last
    pitch = [5.0 + 0.1 * k for k in range(len(stations))]
    if pitch_tip is not None:
        pitch[-1] = pitch_tip
    rows = [[s, 0.15 * R, pitch[k], 5.2, 5.1, 0.3, 0.15, twist0 - 3.0 * k, 0.1, 0.05, 0.2, 0.1, 0.05]
            for k, s in enumerate(stations)]
    text = ("demo\n\n      STATION     CHORD       PITCH       PITCH        PITCH       SWEEP    THICKNESS      TWIST"
            "      MAX-THICK  CROSS-SECTION ZHIGH       CGY          CGZ\n"
            "       (IN)       (IN)       (QUOTED)    (LE-TE)     (PRATHER)      (IN)     RATIO         (DEG)       "
            "(IN)      (IN**2)      (IN)         (IN)         (IN)\n\n"
            + "".join("  ".join(f"{v:10.4f}" for v in row) + "\n" for row in rows)
            + f"\n\n RADIUS:  {radius}    PROPELLER RADIUS (IN)\n\n BLADES:  2       NUMBER OF BLADES\n")
    path = tmp_path / "t10x5-PERF.PE0"
    path.write_text(text)
    return path


def test_a_pe0_files_name_twist_and_quoted_pitch(tmp_path):
    """The name without -PERF.PE0, the blade angle from TWIST, the pitch the QUOTED column's median
    (mutants: the name kept whole; the first row's pitch)."""
    prop = _quiet(read_apc_pe0, _pe0(tmp_path))
    assert prop.name == "t10x5" and prop.n_blades == 2 and prop.radius == pytest.approx(5 * 0.0254, rel=1e-12)
    np.testing.assert_allclose(np.degrees(prop.theta), 35.0 - 3.0 * np.arange(9), rtol=1e-12)
    assert prop.pitch == pytest.approx(5.4 * 0.0254, rel=1e-12)  # (the QUOTED pitch column's median)


def test_a_pe0_twist_beyond_90_deg_is_refused(tmp_path):
    """TWIST in [-90, 90] deg (mutant: up to 91)."""
    path = _pe0(tmp_path)
    path.write_text(path.read_text().replace("   35.0000", "   90.5000", 1))
    with pytest.raises(GeometryFileError, match=r"line 6: TWIST = 90.5 deg is outside \[-90, 90\] deg"):
        read_apc_pe0(path)


def test_a_pe0_last_station_within_half_radius_digit_is_the_tip(tmp_path):
    """RADIUS is printed rounded: a last STATION beyond it by up to half its last printed digit is the
    tip (RADIUS 4.00, STATION 4.005: the radius 4.005 in; mutant: '<': refused); beyond that, refused
    (4.0051; mutant: a whole digit)."""
    prop = _quiet(read_apc_pe0, _pe0(tmp_path, radius="4.00", last=4.005))
    assert prop.radius == pytest.approx(4.005 * 0.0254, rel=1e-12)
    # (RADIUS 2.09 and STATION 2.095: 2.09 + 0.005 is 2.0949999999999998 in floating point, refused until 2026-11-29)
    prop = _quiet(read_apc_pe0, _pe0(tmp_path, radius="2.09", last=2.095))
    assert prop.radius == pytest.approx(2.095 * 0.0254, rel=1e-12)
    with pytest.raises(GeometryFileError, match=r"line 14: STATION = 4.0051 in is outside \(0, 4\] in \(RADIUS\)"):
        read_apc_pe0(_pe0(tmp_path, radius="4.00", last=4.0051))


def test_a_pe0_chord_beyond_the_radius_or_a_station_at_the_axis_is_refused(tmp_path):
    """Stations in (0, RADIUS], chords in [0, RADIUS] (mutants: chords to 2 RADIUS; a station at 0)."""
    path = _pe0(tmp_path)
    path.write_text(path.read_text().replace("    0.7500", "    6.0000", 1))
    with pytest.raises(GeometryFileError, match=r"line 6: CHORD = 6 in is outside \[0, 5\] in \(RADIUS\)"):
        read_apc_pe0(path)
    path = _pe0(tmp_path)
    path.write_text(path.read_text().replace("    1.0000      0.7500", "    0.0000      0.7500", 1))
    with pytest.raises(GeometryFileError, match=r"line 6: STATION = 0 in is outside \(0, 5\] in \(RADIUS\)"):
        read_apc_pe0(path)


# --- identify/csvfile.py ----------------------------------------------------------------------------------------

_RPM = [3000.0, 4000.0, 5000.0, 6000.0, 7000.0, 8000.0]
_ROWS = "".join(f"{r:g},{1e-7 * r * r:g}\n" for r in _RPM)


def _loads(tmp_path, text, name="loads.csv"):
    path = tmp_path / name
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    return path


def _notes_of(path):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return read_loads(path).notes


@pytest.fixture(scope="module")
def quad():
    from importlib import resources

    from propmap.vehicle import read_vehicle

    return read_vehicle(resources.files("propmap") / "data" / "examples" / "quadrotor.toml")


def _flight(tmp_path, old, new):
    from importlib import resources

    text = (resources.files("propmap") / "data" / "examples" / "level_flight_synthetic.csv").read_text()
    assert text.count(old) == 1
    return _loads(tmp_path, text.replace(old, new), "flight.csv")


@pytest.mark.parametrize("rpm, shown", [("2e6", r"2e\+06"), ("0", "0")])
def test_a_per_rotor_rpm_column_is_checked_as_rpm(tmp_path, quad, rpm, shown):
    """rpm_<k> in (0, 954929] as rpm (module docstring; mutants: rpm_1 unchecked, 2e6 rpm read; the
    range closed at 0, a rotor at rest read in level flight)."""
    with pytest.raises(DataError, match=r"line 2: rpm must be > 0 and <= 954929 \(the solver's limit of 1e5 rad/s\), "
                                        rf"got rpm_1 = {shown}$"):
        read_level_flight(_flight(tmp_path, "0.000,0.233,5290.9", f"0.000,0.233,{rpm}"), quad)


def test_trailing_separators_and_a_row_index_are_read_as_nothing(tmp_path):
    """Unnamed columns that hold nothing (trailing separators: two of them are not 'a column twice')
    or come before the first named one (a row index) are ignored, and so are empty cells beyond the
    header (mutant: a row's empty cells beyond the header refused)."""
    empty = "rpm,thrust,,\n" + "".join(f"{r:g},{1e-7 * r * r:g},,\n" for r in _RPM)
    assert read_loads(_loads(tmp_path, empty)).n == 6
    index = ",rpm,thrust\n" + "".join(f"{i},{r:g},{1e-7 * r * r:g}\n" for i, r in enumerate(_RPM))
    assert read_loads(_loads(tmp_path, index)).n == 6
    assert read_loads(_loads(tmp_path, "rpm,thrust\n" + _ROWS.replace("\n", ",,\n"))).n == 6


def test_a_value_under_an_unnamed_column_after_an_unnamed_one_is_not_called_a_decimal_comma(tmp_path):
    """The decimal-comma hint is for a value beside a named column (unnamed_value_message's
    after_named; mutant: given after an empty column too)."""
    with pytest.raises(DataError, match=r"line 2: column 4 has no name in the header but holds '5': name the column "
                                        "or remove it$"):
        read_loads(_loads(tmp_path, "rpm,thrust,,\n" + _ROWS.replace("\n", ",,5\n")))


@pytest.mark.parametrize("mark", ["null", "NULL", "-null"])
def test_missing_value_marks_in_an_optional_column_are_missing(tmp_path, mark):
    """An optional column's cell 'null' marks a missing value (missing_mark: MISSING_MARKS, in any
    case and sign; mutant: 'null' dropped from MISSING_MARKS): the air density is the median of the others."""
    rows = "".join(f"{r:g},{1e-7 * r * r:g},{mark if i < 2 else 1.2}\n" for i, r in enumerate(_RPM))
    assert read_loads(_loads(tmp_path, "rpm,thrust,air density\n" + rows)).air_density == pytest.approx(1.2)


def test_a_stopped_motors_row_of_empty_or_decimal_comma_zero_speed_is_skipped(tmp_path):
    """A row whose speed is empty or 0 (in a ';' file with decimal commas: '0,0') and whose loads are
    empty is a stopped motor's, skipped (read's ``stop``; mutants: '0,0' not read as 0; an empty speed
    not a stop: 'column 'thrust' is empty')."""
    semi = "rpm;thrust;torque\n" + "".join(f"{r:g};{1e-7 * r * r:g};{1e-9 * r * r:g}\n".replace(".", ",") for r in _RPM)
    for tail in ("0,0;;0,01\n", ";;0,01\n"):
        d = read_loads(_loads(tmp_path, semi + tail))
        assert d.n == 6 and any("1 rows with rpm 0 (or empty or NaN) skipped: a stopped motor" in n for n in d.notes)


def test_a_quoted_decimal_comma_in_a_comma_separated_file_is_not_a_number(tmp_path):
    """Decimal commas are read in ';'- or tab-separated files only: '"5300,5"' in a comma-separated
    file is refused (mutant: read as 5300.5)."""
    with pytest.raises(DataError, match=r"line 8: column 'rpm': '5300,5' is not a number"):
        read_loads(_loads(tmp_path, "rpm,thrust\n" + _ROWS + '"5300,5",1\n'))


def test_an_incidence_above_180_deg_gets_no_sign_hint(tmp_path):
    """The hint 'give its magnitude' is for a negative incidence (mutant: for 190 deg too)."""
    rows = "".join(f"{r:g},{1e-7 * r * r:g},5,190\n" for r in _RPM)
    with pytest.raises(DataError, match=r"line 2: incidence_deg must be in \[0, 180\] deg, got 190$"):
        read_loads(_loads(tmp_path, "rpm,thrust,airspeed,incidence_deg\n" + rows))


def test_a_preamble_of_ten_lines_is_read_past_and_named(tmp_path):
    """A preamble above the header (up to PREAMBLE_MAX_LINES = 40 lines) is read past and said, naming
    its lines (mutant: 4 lines: refused as having no rotation-speed column)."""
    d = read_loads(_loads(tmp_path, "".join(f"note {i}\n" for i in range(10)) + "rpm,thrust\n" + _ROWS))
    assert d.n == 6 and any("loads.csv: lines 1-10 above the header (line 11) not read: a preamble" in n
                            for n in d.notes)


def test_a_file_of_more_lines_than_max_lines_is_refused_counting_cr_line_ends(tmp_path, monkeypatch):
    """At most MAX_LINES lines, line ends LF, CRLF or CR (module docstring): a file of CR line ends is
    counted too (mutant: only LF counted: a file of CR line ends never refused)."""
    from propmap.identify import csvfile

    monkeypatch.setattr(csvfile, "MAX_LINES", 7)
    assert read_loads(_loads(tmp_path, "rpm,thrust\r" + _ROWS.replace("\n", "\r"))).n == 6  # (7 lines)
    for end in ("\r", "\n"):
        with pytest.raises(DataError, match="loads.csv: 8 lines; a data file may have at most 7"):
            read_loads(_loads(tmp_path, ("rpm,thrust\n" + _ROWS + "9000,8.1\n").replace("\n", end)))


def test_a_row_is_a_stopped_motors_only_where_every_speed_column_says_so(tmp_path):
    """A row is a stopped motor's where its speed columns are *all* empty or 0 (read's ``stop``): the
    optical probe at 0 beside an electrical speed of 5000 rpm is not, and its empty thrust is refused
    (mutant: any: skipped as stopped)."""
    head = "Motor Optical Speed (RPM),Motor Electrical Speed (RPM),Thrust (N)\n"
    rows = "".join(f"{r:g},{r:g},{1e-7 * r * r:g}\n" for r in _RPM)
    with pytest.raises(DataError, match=r"line 8: column 'Thrust \(N\)' is empty \(missing value\)"):
        read_loads(_loads(tmp_path, head + rows + "0,5000,\n"))
    assert read_loads(_loads(tmp_path, head + rows + "0,0,\n")).n == 6


def test_utf8_text_with_a_stray_byte_is_not_read_as_windows_1252(tmp_path):
    """A file with UTF-8 multi-byte text ('N·m') and a stray byte is UTF-8 with a fault, refused naming
    the byte, not re-read as Windows-1252 ('N·m' turned into 'NÂ·m'; mutant: re-read)."""
    text = "rpm,thrust,torque (N\u00b7m)\n".encode() + _ROWS.replace("\n", ",0.01\n").encode() + b"5000,1\xb5,0.01\n"
    with pytest.raises(DataError, match=r"line 8: byte 0xb5 \(byte 7 of the line\) is not UTF-8; save the file as "
                                        "UTF-8"):
        read_loads(_loads(tmp_path, text))
