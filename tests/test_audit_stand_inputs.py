"""A mutation audit of identify/stand.py, identify/steps.py and io/inputs.py (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""

import math

import numpy as np
import pytest

from propmap.identify import read_loads
from propmap.io.readers import MeasurementFileError, read_uiuc_static
from propmap.identify.stand import map_columns, map_operating_columns
from propmap.identify.steps import esc_form, stand_points
from propmap.io.inputs import (MAX_FILE_BYTES, decode_input_text, header_separator, parse_number, read_input_bytes,
                               short_path)

G0 = 9.80665
LBF = 4.4482216152605
INCH = 0.0254


def _factor(names, quantity):
    return map_columns(names).columns[quantity][1]


@pytest.mark.parametrize("unit", ["ozf", "oz", "ounces"])
def test_an_ounce_force_is_a_sixteenth_of_a_pound_force(unit):
    """Thrust in ozf (oz, ounces) converts at 1 ozf = lbf / 16 = 0.278014 N (module docstring)."""
    assert _factor(["rpm", f"Thrust ({unit})"], "thrust") == pytest.approx(0.2780138509537812, rel=1e-12)


@pytest.mark.parametrize("unit, n_m", [("kgf·cm", G0 * 1e-2), ("kg·cm", G0 * 1e-2), ("gf·cm", G0 * 1e-5),
                                       ("lbf·in", LBF * INCH), ("lb·in", LBF * INCH), ("in·lb", LBF * INCH),
                                       ("ozf·in", LBF / 16 * INCH), ("oz·in", LBF / 16 * INCH),
                                       ("oz-in", LBF / 16 * INCH), ("lbf·ft", LBF * 0.3048),
                                       ("ft·lb", LBF * 0.3048)])
def test_the_stand_torque_units_convert_to_newton_metres(unit, n_m):
    """Torque in kgf·cm, gf·cm, lbf·in, ozf·in, lbf·ft converts with 1 kgf = 9.80665 N, 1 in = 0.0254 m."""
    assert _factor(["rpm", "thrust", f"Torque ({unit})"], "torque") == pytest.approx(n_m, rel=1e-12)


@pytest.mark.parametrize("unit, m_s", [("km/h", 1 / 3.6), ("kmh", 1 / 3.6), ("kph", 1 / 3.6), ("kn", 0.5144444444),
                                       ("kt", 0.5144444444), ("knots", 0.5144444444), ("mph", 0.44704),
                                       ("ft/s", 0.3048)])
def test_airspeed_units_convert_to_metres_per_second(unit, m_s):
    """An airspeed in km/h, kn, mph or ft/s converts to m/s (36 km/h = 10 m/s, 1 kn = 1852 m / 3600 s)."""
    assert _factor(["rpm", "thrust", f"airspeed ({unit})"], "airspeed") == pytest.approx(m_s, rel=1e-9)


def test_an_incidence_in_radians_is_read_in_degrees():
    """'incidence (rad)' converts to degrees: pi/2 rad is 90 deg (an edgewise point)."""
    assert _factor(["rpm", "thrust", "airspeed", "incidence (rad)"], "incidence_deg") * math.pi / 2 == \
        pytest.approx(90.0, rel=1e-12)
    assert _factor(["rpm", "thrust", "airspeed", "collective (rad)"], "collective_deg") == \
        pytest.approx(180 / math.pi, rel=1e-12)


@pytest.mark.parametrize("unit, kg_m3", [("g/cm³", 1000.0), ("g/cm3", 1000.0), ("g/L", 1.0), ("kg/m^3", 1.0),
                                         ("lb/ft³", 16.018463373960138)])
def test_an_air_density_in_grams_per_cubic_centimetre_is_converted(unit, kg_m3):
    """Air density in g/cm³ converts to kg/m³ x 1000 (0.001225 g/cm³ is sea-level air, 1.225 kg/m³)."""
    assert _factor(["rpm", "thrust", f"Air Density ({unit})"], "air_density") == pytest.approx(kg_m3, rel=1e-12)


def _steps(levels, rows=10, rpm_of=lambda e: 10 * (e - 1000), extra=None):
    """A steps test: each ESC level held ``rows`` rows at 10 Hz, rpm steady; returns (values, esc, time)."""
    esc = np.repeat(np.asarray(levels, float), rows)
    rpm = np.array([rpm_of(e) for e in esc], float)
    values = {"rpm": rpm, "thrust": rpm / 1000.0}
    values.update(extra or {})
    return values, esc, np.arange(esc.size) * 0.1


def test_signal_levels_six_us_apart_are_two_steps():
    """ESC levels 6 us apart are two steps (a step spans 2 us, merged pieces 4 us): 1500 and 1506 us give 2 points."""
    values, esc, time = _steps([1500, 1506])
    out, groups, _, _ = stand_points(values, esc, time)
    assert list(groups) == ["step1_1500us", "step2_1506us"]
    assert out["rpm"] == pytest.approx([5000.0, 5060.0])


def test_a_readback_jittering_by_3_us_is_one_step():
    """Pieces of a step whose medians are 3 us apart (under twice the 2 us tolerance) are one step, one point."""
    esc = np.array([1500, 1500, 1500, 1503, 1503, 1503, 1500, 1500, 1503, 1503], float)
    values = {"rpm": np.full(10, 5000.0), "thrust": np.full(10, 4.0)}
    out, groups, _, _ = stand_points(values, esc, np.arange(10) * 0.1)
    assert len(groups) == 1 and groups[0].startswith("step1_15")
    assert out["thrust"] == pytest.approx([4.0])


def test_throttle_levels_six_tenths_of_a_percent_apart_are_two_steps():
    """A throttle's tolerance is 0.2% (merged 0.4%): 50% and 50.6% are two steps, labelled in pct."""
    values, esc, time = _steps([50.0, 50.6], rpm_of=lambda e: 100 * e)
    out, groups, _, _ = stand_points(values, esc, time, form="pct")
    assert list(groups) == ["step1_50pct", "step2_50.6pct"]
    assert out["rpm"] == pytest.approx([5000.0, 5060.0])


def test_airspeeds_one_metre_per_second_apart_at_one_signal_are_two_steps():
    """One ESC signal at airspeeds 5 and 6 m/s (tolerance 0.3 m/s) are two steps, one per condition."""
    values, esc, time = _steps([1500, 1500], extra={"airspeed": np.repeat([5.0, 6.0], 10)})
    out, groups, _, _ = stand_points(values, esc, time)
    assert out["airspeed"] == pytest.approx([5.0, 6.0])
    assert list(groups) == ["step1_1500us", "step2_1500us"]


def test_a_step_never_spans_two_group_labels():
    """One ESC signal under two `group` labels is two steps, each labelled <label>_step<k>_<esc>us."""
    values, esc, time = _steps([1500, 1500])
    out, groups, _, _ = stand_points(values, esc, time, labels=np.repeat(["a", "b"], 10).astype(object))
    assert list(groups) == ["a_step1_1500us", "b_step2_1500us"]


def test_the_first_half_of_a_step_is_dropped_as_settling():
    """Of a step, the first half of its duration is dropped (settle=0.5): thrust 1 then 2 N averages to 2 N."""
    esc = np.full(10, 1500.0)
    values = {"rpm": np.full(10, 5000.0), "thrust": np.repeat([1.0, 2.0], 5)}
    out, _, dropped, _ = stand_points(values, esc, np.arange(10) * 0.1)
    assert out["thrust"] == pytest.approx([2.0])
    assert dropped == 5


def test_settling_is_measured_in_time_where_a_time_column_is():
    """With a time column the settling half is half the step's duration, not of its rows (a sampling gap)."""
    esc = np.full(8, 1500.0)
    time = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 9.9, 10.0])
    values = {"rpm": np.full(8, 5000.0), "thrust": np.array([1.0] * 6 + [3.0, 3.0])}
    out, _, dropped, _ = stand_points(values, esc, time)
    assert out["thrust"] == pytest.approx([3.0])  # by rows (the last 4) it would be 2.0
    assert dropped == 6


def test_rows_off_the_steady_speed_by_3_percent_are_not_averaged():
    """After settling only rows within 2% of the step's median speed are averaged: a 3% excursion is left out."""
    esc = np.full(10, 1500.0)
    rpm = np.array([0, 1000, 2000, 3000, 4000, 5000, 5000, 5000, 5000, 5150], float)
    values = {"rpm": rpm, "thrust": rpm / 1000}
    out, _, dropped, _ = stand_points(values, esc, np.arange(10) * 0.1)
    assert out["rpm"] == pytest.approx([5000.0])
    assert dropped == 6


def test_a_step_with_under_half_its_rows_steady_gives_no_point():
    """A step where fewer than half the settled rows are steady (a spin-down) gives no point, named as unsteady."""
    esc = np.full(20, 1500.0)
    rpm = np.concatenate([np.full(10, 5000.0), [5000, 5000, 5000, 5000, 4000, 3500, 3000, 2500, 2000, 1500]])
    values = {"rpm": rpm, "thrust": rpm / 1000}
    out, groups, dropped, unsteady = stand_points(values, esc, np.arange(20) * 0.1)
    assert len(groups) == 0 and unsteady == ("step1_1500us",) and dropped == 20


def test_a_step_of_two_rows_is_taken_whole():
    """A step of one or two rows (an export that averaged its steps) is averaged whole, no settling dropped."""
    esc = np.array([1300, 1300, 1600, 1600], float)
    values = {"rpm": np.array([3000.0, 3100.0, 6000.0, 6200.0]), "thrust": np.array([1.0, 1.2, 4.0, 4.4])}
    out, groups, dropped, _ = stand_points(values, esc, None)
    assert out["thrust"] == pytest.approx([1.1, 4.2])
    assert list(groups) == ["step1_1300us", "step2_1600us"] and dropped == 0


def test_a_pulse_width_label_is_rounded_to_whole_microseconds():
    """A step's group is step<k>_<esc>us with the median pulse width in whole us (step1_1220us)."""
    values, esc, time = _steps([1220.4])
    _, groups, _, _ = stand_points(values, esc, time)
    assert list(groups) == ["step1_1220us"]


def test_a_short_step_between_steps_of_four_rows_is_no_ramp():
    """A ramp is one- or two-row steps between steps of 5 rows or more: between 4-row steps a row stays a point."""
    esc = np.array([1300] * 4 + [1450] + [1600] * 4, float)
    values = {"rpm": 10 * (esc - 1000), "thrust": (esc - 1000) / 100}
    out, groups, _, _ = stand_points(values, esc, np.arange(esc.size) * 0.1)
    assert list(groups) == ["step1_1300us", "step2_1450us", "step3_1600us"]
    esc5 = np.array([1300] * 5 + [1450] + [1600] * 5, float)
    out5, groups5, dropped5, _ = stand_points({"rpm": 10 * (esc5 - 1000)}, esc5, np.arange(esc5.size) * 0.1)
    assert list(groups5) == ["step1_1300us", "step2_1600us"] and out5["rpm"] == pytest.approx([3000.0, 6000.0])


@pytest.mark.parametrize("unit, values, form", [
    (None, [0.0, 0.5, 1.0], "fraction"), (None, [0.0, 50.0, 100.0], "pct"), (None, [0.0, 100.5], "us"),
    ("%", [0.0, 60.0, 150.0], "pct"), ("%", [1000.0, 1500.0, 2000.0], "us"), ("µs", [10.0, 90.0], "pct"),
    ("µs", [0.2, 0.9], "fraction"), ("µs", [1000.0, 1100.0], "us")])
def test_an_esc_signal_form_follows_its_unit_and_values(unit, values, form):
    """esc_form: at most 1 a fraction, at most 100 percent, else us; a '%' reaching 500 is us, a 'us' within 100 not."""
    assert esc_form("ESC", unit, np.array(values))[0] == form


@pytest.mark.parametrize("name, rpm_per_unit", [("omega", 30 / math.pi), ("RPS", 60.0), ("rev/s", 60.0),
                                                ("rpm", 1.0), ("Motor Speed (rad/s)", 30 / math.pi)])
def test_a_bare_omega_is_radians_per_second_and_a_bare_rps_revolutions(name, rpm_per_unit):
    """A bare 'omega' is in rad/s (x 9.5493 to rpm), a bare 'RPS' or 'rev/s' in rev/s (x 60); 'rpm' as it is."""
    assert _factor([name, "thrust"], "rpm") == pytest.approx(rpm_per_unit, rel=1e-12)


@pytest.mark.parametrize("name", ["incidence", "Collective"])
def test_a_bare_incidence_or_collective_is_refused_asking_for_its_unit(name):
    """A bare 'incidence' or 'collective' (degrees or radians?) is refused, the message asking for '(deg)'/'(rad)'."""
    with pytest.raises(ValueError, match=r"gives no unit.*'(incidence|collective) \(deg\)'"):
        map_columns(["rpm", "thrust", "airspeed", name])


@pytest.mark.parametrize("name", ["Speed (m/s)", "Motor Speed (km/h)", "rpm (mph)"])
def test_a_rotation_speed_in_a_linear_speeds_unit_says_to_name_it_airspeed(name):
    """A rotation-speed name in a linear speed's unit is refused saying so and naming 'airspeed (m/s)'."""
    with pytest.raises(ValueError, match=r"a linear speed, not a rotation speed.*'airspeed \(m/s\)'"):
        map_columns([name, "thrust"])


STAND = ["Time (s)", "ESC signal (µs)", "Thrust (kgf)", "Torque (N·m)", "Motor Electrical Speed (RPM)",
         "Motor Optical Speed (RPM)"]


@pytest.mark.parametrize("pole_pairs", [0, 51, 7.0, -7, True])
def test_pole_pairs_outside_one_to_fifty_are_refused_naming_the_option(pole_pairs):
    """pole_pairs (--pole-pairs) must be an integer in [1, 50]: 0, 51, 7.0 and True are refused, naming the option."""
    with pytest.raises(ValueError, match=r"pole_pairs \(--pole-pairs\) must be an integer in \[1, 50\]"):
        map_columns(STAND, rpm_source="electrical", pole_pairs=pole_pairs)


@pytest.mark.parametrize("pole_pairs", [1, 7, 50])
def test_pole_pairs_from_one_to_fifty_are_taken(pole_pairs):
    """pole_pairs 1, 7 and 50 lie in [1, 50] and are taken with the electrical speed."""
    cm = map_columns(STAND, rpm_source="electrical", pole_pairs=pole_pairs)
    assert cm.column("rpm_electrical") == "Motor Electrical Speed (RPM)"
    assert cm.column("thrust") == "Thrust (kgf)" and cm.columns["thrust"][1] == pytest.approx(G0, rel=1e-15)


@pytest.mark.parametrize("source", ["optics", "Optical", "esc"])
def test_an_unknown_rpm_source_is_refused_naming_the_choices(source):
    """rpm_source (--rpm-source) is 'optical' or 'electrical': anything else is refused naming both."""
    with pytest.raises(ValueError, match=r"rpm_source must be 'optical' or 'electrical', got"):
        map_columns(STAND, rpm_source=source)


def test_an_rpm_source_the_file_lacks_is_refused_naming_the_columns():
    """--rpm-source optical on a file with only the electrical speed is refused, listing the columns found."""
    names = [n for n in STAND if "Optical" not in n]
    with pytest.raises(ValueError, match=r"rpm_source 'optical': the file has no Motor Optical Speed column; found "
                                         r"'Time \(s\)'"):
        map_columns(names, rpm_source="optical")
    assert map_columns(names).column("rpm_electrical") == "Motor Electrical Speed (RPM)"


def test_a_static_stands_lift_column_is_refused_asking_for_thrust():
    """A 'Lift (N)' column on a static stand without a thrust column is refused: name it 'thrust' to fit it."""
    with pytest.raises(ValueError, match=r"column 'Lift \(N\)': a static stand's lift is the propeller's thrust"):
        map_columns(["rpm", "torque", "Lift (N)"])


@pytest.mark.parametrize("name", ["Load (kgf)", "Force (N)", "Load cell (gf)", "Force (lbf)"])
def test_a_force_of_another_name_is_named_in_a_note(name):
    """A force column of another name ('Load (kgf)') where no thrust is read is named in a note, not left unsaid."""
    notes = map_columns(["rpm", "torque", name]).notes
    assert any(note.startswith(f"column {name!r} (a force) is not read") and "only the torque is fitted" in note
               for note in notes)


@pytest.mark.parametrize("name", ["Tip speed (m/s)", "Blade speed (m/s)", "Slipstream speed (m/s)"])
def test_a_tip_or_slipstream_speed_is_no_airspeed(name):
    """A blade's or the slipstream's speed in m/s is no airspeed: a static file with it reads, it is not refused."""
    cm = map_columns(["rpm", "thrust", name])
    assert "airspeed" not in cm.columns and cm.column("thrust") == "thrust"
    with pytest.raises(ValueError, match=r"looks like an airspeed"):
        map_columns(["rpm", "thrust", "Flight speed (m/s)"])


def test_only_converted_columns_get_a_unit_note():
    """A column in its SI unit gets no 'converted' note; one in kgf does, with its factor 9.80665."""
    notes = map_columns(["Motor Optical Speed (RPM)", "Thrust (N)", "Torque (kgf·cm)"]).notes
    assert notes == ["'Torque (kgf·cm)' converted to N m (x 0.0980665)"]


def test_a_data_file_over_200_mib_is_refused_before_reading(tmp_path):
    """A measurement CSV over 200 MiB (MAX_FILE_BYTES) is refused naming the limit, without reading it."""
    big = tmp_path / "huge.csv"
    with open(big, "wb") as fh:
        fh.truncate(200 * 2**20 + 1)  # (sparse: nothing is written)
    with pytest.raises(ValueError, match=r"huge.csv: 200 MiB is larger than 200 MiB, the limit"):
        read_input_bytes(big, ValueError)
    assert MAX_FILE_BYTES == 200 * 2**20


def test_a_byte_order_mark_is_dropped_and_utf16_and_nul_bytes_refused():
    """UTF-8 with a byte-order mark decodes without it; UTF-16 text and a NUL byte are refused in one line."""
    assert decode_input_text(b"\xef\xbb\xbfThrust (N),rpm\n", "a.csv", ValueError) == "Thrust (N),rpm\n"
    with pytest.raises(ValueError, match=r"^a.csv: UTF-16 text; save it as UTF-8$"):
        decode_input_text("rpm,thrust\n".encode("utf-16"), "a.csv", ValueError)
    with pytest.raises(ValueError, match=r"^a.csv, line 2: NUL byte: a binary file, not text$"):
        decode_input_text(b"rpm,thrust\r\n1\x00", "a.csv", ValueError)


def test_a_stray_byte_is_named_by_its_line_with_crlf_line_ends():
    """A byte that is not UTF-8 is named by its line, CRLF counted as one line end (line 3, not 5)."""
    with pytest.raises(ValueError, match=r"^a.csv, line 3: byte 0xff \(byte 2 of the line\) is not UTF-8"):
        decode_input_text(b"rpm,thrust\r\n1,2\r\n3\xff,4\r\n", "a.csv", ValueError)


def test_a_tie_of_semicolons_and_commas_in_a_header_is_semicolons():
    """A header 'Speed, rev/min;Thrust' (one of each) is ';'-separated: a tie of ';' and ',' goes to ';'."""
    assert header_separator("Speed, rev/min;Thrust") == ";"
    assert header_separator("rpm,thrust") == ","
    assert header_separator("rpm\tThrust, N\tTorque, N m", "3000\t1.5\t0.02") == "\t"


@pytest.mark.parametrize("text", ["1_000", "１２", "٣", " 1e3x"])
def test_only_plain_ascii_numbers_parse(text):
    """parse_number refuses '1_000' and non-ASCII digits that Python's float takes."""
    with pytest.raises(ValueError):
        parse_number(text)
    assert parse_number(" 1e3 ") == 1000.0


def test_a_long_path_keeps_its_first_quarter_and_its_file_name():
    """short_path cuts a long path in its middle: its first (n - 3) // 4 characters, '...' and its end."""
    path = "/home/alice/" + "x" * 100 + "/campaign_3/maps/apce_10x7.nc"
    s = short_path(path, 40)
    assert len(s) == 40 and s.startswith("/home/ali...campaign_3/") and s.endswith("/maps/apce_10x7.nc")


def test_a_semicolon_file_with_units_after_commas_and_decimal_commas_is_read(tmp_path):
    """'Zeit, s;Schub, N;Drehmoment, N m;Drehzahl, U/min' over '1,5;2,25;0,025;3000,0' is ';'-separated."""
    assert header_separator("Zeit, s;Schub, N;Drehmoment, N m;Drehzahl, U/min", "1,5;2,25;0,025;3000,0") == ";"
    rpm = np.arange(3000.0, 9000.0, 1000.0)
    rows = [f"{k},5;{r * r / 2e7:.4f};{r * r / 1e9:.5f};{r:.1f}".replace(".", ",") for k, r in enumerate(rpm)]
    path = tmp_path / "eu.csv"
    path.write_text("Zeit, s;Schub, N;Drehmoment, N m;Drehzahl, U/min\n" + "\n".join(rows) + "\n", encoding="utf-8")
    d = read_loads(path)
    assert d.omega * 30 / math.pi == pytest.approx(rpm)
    assert d.measured["thrust"] == pytest.approx(np.round(rpm ** 2 / 2e7, 4))
    assert d.measured["torque"] == pytest.approx(np.round(rpm ** 2 / 1e9, 5))


def test_a_points_files_bare_rpm_is_taken_before_another_name_for_it():
    """In a points file the bare 'rpm' is taken first; 'Motor Speed (rad/s)' beside it stays an extra column."""
    out = map_operating_columns(["rpm", "Motor Speed (rad/s)", "airspeed (km/h)"])
    assert out == {"rpm": ("rpm", 1.0), "airspeed": ("airspeed (km/h)", pytest.approx(1 / 3.6))}
    assert map_operating_columns(["omega", "airspeed"])["rpm"] == ("omega", pytest.approx(30 / math.pi))


def test_a_points_files_pitch_column_is_refused_naming_collective_deg():
    """A points file's 'Pitch (deg)' (a blade pitch setting) is refused naming collective_deg, never left unread."""
    with pytest.raises(ValueError, match=r"column 'Pitch \(deg\)' looks like a blade pitch setting.*'collective_deg'"):
        map_operating_columns(["rpm", "airspeed", "Pitch (deg)"])
    assert "collective_deg" in map_operating_columns(["rpm", "collective_deg", "Pitch (deg)"])


def test_a_uiuc_static_run_at_zero_rpm_is_refused_naming_its_line(tmp_path):
    """A UIUC static file's RPM lies in (0, max]: a row at 0 rpm is refused naming its line and the open interval."""
    path = tmp_path / "apce_8x6_static_0001.txt"
    path.write_text("RPM CT CP\n3000 0.11 0.05\n0 0.11 0.05\n4000 0.11 0.05\n", encoding="utf-8")
    with pytest.raises(MeasurementFileError, match=r"line 3: RPM = 0 is outside \(0, "):
        read_uiuc_static(path)
