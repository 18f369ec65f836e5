"""Thrust-stand exports, motor makers' tables and lab spreadsheets as a user-level audit wrote
them (2026-11-30): each test reproduces what the audit found and fails on the code before it."""

from __future__ import annotations

import numpy as np
import pytest

import propmap as pm
from propmap.identify import DataError, read_loads
from propmap.identify.sanity import sanity_check
from propmap.identify.stand import map_columns

G0 = 9.80665


def _rotor(rpm):
    """apce_10x7's static thrust [N] and torque [N m] with the generic set at ``rpm``."""
    r = pm.rotor_loads(pm.load_propeller("apce_10x7"), pm.generic_params(), np.asarray(rpm) * np.pi / 30, 0.0, 0.0)
    return r.thrust, r.torque


@pytest.mark.parametrize("name", ["Static thrust (g)", "Weight (g)", "load_g", "Force (kg)", "Pull (oz)",
                                  "weight_kgf"])
def test_a_force_in_grams_under_another_name_is_named_not_dropped(name):
    """A gram (or kg, oz) force under a name not read was left out without a word and a torque-only
    fit ran (only N, kgf, gf, lbf, ozf were named); 'Static thrust' is now read as the thrust."""
    cm = map_columns(["RPM", name, "Torque (N·m)"])
    if name.startswith("Static thrust"):
        assert cm.column("thrust") == name and cm.columns["thrust"][1] == pytest.approx(G0 * 1e-3)
    else:
        assert cm.column("thrust") is None
        assert any(n.startswith(f"column {name!r} (a force) is not read") and "only the torque is fitted" in n
                   for n in cm.notes), cm.notes


@pytest.mark.parametrize("name", ["AccX (g)", "Vibration (g)", "a_z (g)", "Accel Y [g]", "acc_x_g", "sample_n"])
def test_an_accelerometers_g_is_no_gram(name):
    """An accelerometer's or a vibration sensor's g is an acceleration, not a gram, and a count's _n
    no newton: not noted as a force."""
    assert not [n for n in map_columns(["rpm", "torque", name]).notes if "(a force)" in n]


@pytest.mark.parametrize("header, thrust, torque", [
    (["Velocidad (rpm)", "Empuje (g)", "Par (N·m)"], G0 * 1e-3, 1.0),
    (["Régime (tr/min)", "Poussée (g)", "Couple (N.m)"], G0 * 1e-3, 1.0),
    (["Giri (giri/min)", "Spinta (kg)", "Coppia (Nm)"], G0, 1.0)])
def test_spanish_french_and_italian_headers_are_read(tmp_path, header, thrust, torque):
    """Spanish, French and Italian spreadsheets' names and units (Empuje, Poussée, Spinta; Par,
    Couple, Coppia; Velocidad, Régime, Giri; tr/min, giri/min) read as the thrust, torque and rpm:
    they were told of 'lines above the header'."""
    rpm = np.arange(4000.0, 9001.0, 1000.0)
    T, Q = _rotor(rpm)
    path = tmp_path / "es.csv"
    path.write_text(",".join(header) + "\n" + "".join(f"{a:.0f},{t / thrust:.6g},{q / torque:.6g}\n"
                                                      for a, t, q in zip(rpm, T, Q)), encoding="utf-8")
    d = read_loads(path)
    np.testing.assert_allclose(d.omega, rpm * np.pi / 30)
    np.testing.assert_allclose(d.measured["thrust"], T, rtol=1e-5)
    np.testing.assert_allclose(d.measured["torque"], Q, rtol=1e-5)


def test_a_bare_par_is_not_a_torque():
    """'Par' is read as a torque only with a torque's unit (a bare one may be a pair or a parameter)."""
    assert map_columns(["rpm", "thrust", "par"]).column("torque") is None
    assert map_columns(["rpm", "thrust", "Par (N m)"]).column("torque") == "Par (N m)"


def test_an_averaged_thrust_gives_way_to_the_thrust():
    """'Thrust avg (g)' is read where it is the only thrust; beside 'Thrust (g)' it gives way, with a
    note and without a stale conversion note, in either order."""
    assert map_columns(["RPM", "Thrust avg (g)"]).column("thrust") == "Thrust avg (g)"
    for names in (["RPM", "Thrust (g)", "Thrust avg (g)"], ["RPM", "Thrust avg (g)", "Thrust (g)"]):
        cm = map_columns(names)
        assert cm.column("thrust") == "Thrust (g)"
        assert "column 'Thrust avg (g)' is not read: the thrust is read from 'Thrust (g)'" in cm.notes
        assert not [n for n in cm.notes if n.startswith("'Thrust avg (g)' converted")], cm.notes
    with pytest.raises(ValueError, match="both give thrust"):
        map_columns(["RPM", "Thrust avg (g)", "Static thrust (g)"])


def test_a_column_in_rpm_under_another_name_is_named_in_the_error():
    """With no rotation-speed column read, a column whose unit is a rotation speed's is named (it
    was 'lines above the header?', wrong for a header on line 1)."""
    with pytest.raises(ValueError, match=r"column 'Obroty \(obr/min\)' is in a rotation speed's unit but its name "
                                         r"is not read: name it 'rpm'"):
        map_columns(["Obroty (obr/min)", "thrust"])


def test_a_static_stands_pitot_noise_below_zero_reads_as_zero(tmp_path):
    """A static export's airspeed reading -0.2 to +0.3 m/s (a pitot's noise about zero) was refused
    as 'a descent given as a negative airspeed'; it reads as 0 with a note, and -0.5 m/s is still
    refused."""
    rpm = np.arange(4000.0, 9001.0, 1000.0)
    T, _ = _rotor(rpm)
    V = [-0.05, 0.1, -0.2, 0.3, 0.02, 0.0]
    path = tmp_path / "pitot.csv"
    path.write_text("rpm,Airspeed (m/s),thrust\n" + "".join(f"{a:.0f},{v:g},{t:.6g}\n" for a, v, t in zip(rpm, V, T)))
    d = read_loads(path)
    np.testing.assert_array_equal(d.airspeed, [0.0, 0.1, 0.0, 0.3, 0.02, 0.0])
    assert "'Airspeed (m/s)': 2 value(s) from -0.2 to 0 m/s (a static stand's pitot noise about zero, within " \
           "0.3 m/s) read as 0" in d.notes
    path.write_text(path.read_text().replace(",-0.2,", ",-0.5,"))
    with pytest.raises(DataError, match=r"line 4: airspeed must be in \[0, 500\] m/s, got -0.5"):
        read_loads(path)


def test_a_point_as_a_thousands_separator_is_refused(tmp_path):
    """In a ';' file a column of 951 and 1.059 (grams) holds a thousands separator; read as decimal
    points it gave points a thousand times small that were fitted. Decimal commas and a column of
    decimals alone still read."""
    bad = tmp_path / "de.csv"
    bad.write_text("Drehzahl [U/min];Schub [g];Drehmoment [Nmm]\n5000;451;79\n6000;651;110\n7502;951;169\n"
                   "8009;1.059;188\n9000;1.340;240\n9499;1.514;267\n")
    with pytest.raises(DataError, match=r"line 7: column 'Schub \[g\]': 1.514 \(line 7\) beside 951 \(line 4\): a "
                                        r"point as a thousands separator \(1514\)\?"):
        read_loads(bad)
    # decimals beside whole numbers of their size are decimals (a tab file's throttle, a gram thrust)
    for header, cells in (("Throttle\tRPM\tThrust (N)", ("16.667", "33.333", "50", "66.667", "83.333", "100")),
                          ("RPM\tThrust (g)", ("98.125", "215", "300.5", "420", "560", "720"))):
        tsv = tmp_path / "ok.tsv"
        tsv.write_text(header + "\n" + "".join(f"{c}\t{3000 + 1000 * k}\t{1 + k}\n" if header.startswith("Thr") else
                                               f"{3000 + 1000 * k}\t{c}\n" for k, c in enumerate(cells)))
        assert read_loads(tsv).n == 6
    ok = tmp_path / "ok.csv"
    ok.write_text("Drehzahl [U/min];Schub [N];Drehmoment [Nm]\n5000;4,51;0,079\n6000;6,51;0,110\n7502;9,51;0,169\n"
                  "8009;10,59;0,188\n9000;13,40;0,240\n9499;15,14;0,267\n")
    assert read_loads(ok).measured["thrust"][3] == pytest.approx(10.59)
    points = tmp_path / "points.csv"
    text = bad.read_text()
    for grams in ("451", "651", "951"):
        text = text.replace(f";{grams};", f";0.{grams};")
    points.write_text(text)
    assert read_loads(points).measured["thrust"][3] == pytest.approx(1.059 * G0 * 1e-3)


@pytest.mark.parametrize("torque", [False, True])
def test_an_rpm_counted_per_blade_is_named_as_the_likely_cause(torque):
    """A tachometer counting both blades doubles the rpm; a thrust-only file was told 'thrust in lbf
    read as N ... or thrust in lbf and torque in lbf in' (a torque it lacks, a unit its header
    gave): now the per-blade count is named first, and no torque slip for a file without torque."""
    rpm = np.arange(2500.0, 7600.0, 500.0)
    T, Q = _rotor(rpm)
    measured = {"thrust": T, **({"torque": Q} if torque else {})}
    data = pm.identify.LoadData(2 * rpm * np.pi / 30, np.zeros(rpm.size), np.zeros(rpm.size), measured,
                                np.full(rpm.size, "all", dtype=object), "tacho.csv", converted={"thrust": G0 * 1e-3})
    with pytest.raises(DataError) as exc:
        sanity_check(data, pm.load_propeller("apce_10x7"))
    msg = str(exc.value)
    assert "likely an optical tachometer counting every blade read as the rpm (2 pulses per revolution" in msg, msg
    assert "lbf" not in msg and ("torque" in msg) == torque, msg
    # an unlabelled thrust: its lbf slip is a cause, but not one with a torque the file lacks
    with pytest.raises(DataError) as exc:
        sanity_check(pm.identify.LoadData(data.omega, data.airspeed, data.incidence, {"thrust": T}, data.group),
                     pm.load_propeller("apce_10x7"))
    assert "thrust in lbf read as N" in str(exc.value) and "torque" not in str(exc.value), str(exc.value)


def test_a_converted_drag_does_not_hide_an_unlabelled_thrusts_slip(tmp_path):
    """The sanity check took any force conversion for the thrust's: an unlabelled thrust in kgf
    beside 'drag (g)' lost its cause ('check the units'); now the thrust's own conversion counts."""
    rpm = np.arange(3000.0, 8001.0, 1000.0)
    T, _ = _rotor(rpm)
    path = tmp_path / "kd.csv"
    path.write_text("rpm,thrust,drag (g)\n" + "".join(f"{a:.0f},{t / G0:.6g},0\n" for a, t in zip(rpm, T)))
    d = read_loads(path)
    assert d.converted == {"drag": pytest.approx(G0 * 1e-3)}
    with pytest.raises(DataError, match=r"likely thrust in kgf read as N"):
        sanity_check(d, pm.load_propeller("apce_10x7"), quantities=("thrust",))


@pytest.mark.parametrize("temperatures, read", [((35.0, 45.0, 55.0, 65.0, 75.0, 85.0), False),  # a motor heating
                                                ((60.0,) * 6, False),  # above 50 degC
                                                ((5.0, 15.0, 25.0, 35.0, 45.0, 55.0), False),  # spanning 50 K
                                                ((21.0, 22.0, 22.5, 23.0, 23.5, 24.0), True),  # a lab's air
                                                ((20.0, 25.0, 30.0, 35.0, 40.0, 45.0), True)])  # a warming tunnel
def test_a_motors_temperature_is_not_taken_for_the_airs(tmp_path, temperatures, read):
    """A 'Temperature (°C)' column beside 'Pressure (hPa)' that rises 35 -> 85 degC with the motor
    was taken as the air's (1.06 kg/m^3: every point 14% off, with only a note); a median above
    50 degC or a 5th-95th percentile span over 30 K is not the air's: the columns are not read,
    with a note, unless an air temperature column follows, which is then read."""
    rpm = np.arange(4000.0, 9001.0, 1000.0)
    T, Q = _rotor(rpm)
    path = tmp_path / "stand.csv"
    path.write_text("RPM,Thrust (N),Torque (N m),Temperature (°C),Pressure (hPa)\n" + "".join(
        f"{a:.0f},{t:.6g},{q:.6g},{c:g},1013\n" for a, t, q, c in zip(rpm, T, Q, temperatures)), encoding="utf-8")
    d = read_loads(path)
    if read:
        assert d.air_density == pytest.approx(101300 / (287.05 * (np.median(temperatures) + 273.15)), rel=1e-3)
        return
    assert d.air_density is None
    assert any("not the air's (above 50 degC or spanning over 30 K; a motor's or an ESC's temperature?)" in n
               for n in d.notes), d.notes
    path.write_text("RPM,Thrust (N),Temperature (°C),Pressure (hPa),Air temperature (°C)\n" + "".join(
        f"{a:.0f},{t:.6g},{c:g},1013,21\n" for a, t, c in zip(rpm, T, temperatures)), encoding="utf-8")
    assert read_loads(path).air_density == pytest.approx(101300 / (287.05 * 294.15), rel=1e-3)


@pytest.mark.parametrize("names", [["ESC (µs)", "Throttle (%)", "rpm", "thrust"],
                                   ["Throttle (%)", "ESC signal (µs)", "rpm", "thrust"]])
def test_a_throttle_beside_an_esc_signal_gives_way(names):
    """An export with both a pulse width and a throttle column was refused ('both give esc: keep
    one'); the pulse width is read, the throttle named as not read (PWM still gives way to both)."""
    cm = map_columns(names)
    assert cm.column("esc").startswith("ESC")
    assert f"column 'Throttle (%)' is not read: the ESC signal is read from {cm.column('esc')!r}" in cm.notes
    assert map_columns(["Throttle (%)", "PWM (us)", "rpm", "thrust"]).column("esc") == "Throttle (%)"
    with pytest.raises(ValueError, match="both give esc"):
        map_columns(["ESC (us)", "ESC signal (us)", "rpm", "thrust"])


def test_a_wrapped_quoted_heading_does_not_hide_the_separator(tmp_path):
    """A spreadsheet's heading wrapped over two lines in its quotes ("Drehzahl<newline>[U/min]") in a
    ';' file: the separator was looked for in the first line alone, the file read with ',' and
    refused ('a closing quote must be followed by a comma'); it reads as the one-line heading does."""
    rows = "5000;4,51;0,079\n6000;6,51;0,110\n7502;9,51;0,169\n8009;10,59;0,188\n9000;13,40;0,240\n"
    wrapped, plain = tmp_path / "wrapped.csv", tmp_path / "plain.csv"
    wrapped.write_text('"Drehzahl\n[U/min]";"Schub\n[N]";"Drehmoment\n[Nm]"\n' + rows)
    plain.write_text("Drehzahl [U/min];Schub [N];Drehmoment [Nm]\n" + rows)
    a, b = read_loads(wrapped, min_points=1), read_loads(plain, min_points=1)
    np.testing.assert_array_equal(a.omega, b.omega)
    np.testing.assert_array_equal(a.measured["thrust"], b.measured["thrust"])


def test_an_extra_field_says_what_likely_made_it(tmp_path):
    """A row with more fields than the header said only so; it now names an unquoted comma in a
    cell's text (a stand's 'App message') or decimal commas as the likely causes."""
    path = tmp_path / "app.csv"
    path.write_text("Time (s),ESC signal (µs),Thrust (N),Motor Optical Speed (RPM),App message\n1,1200,1.0,3000,\n"
                    "2,1300,1.5,4000,Warning: high temp, check motor\n", encoding="utf-8")
    with pytest.raises(DataError, match=r"line 3: 6 fields, but the header \(line 1\) has 5: a comma inside a cell's "
                                        r"text \(the last column's, 'App message'\?\) that is not quoted, or decimal "
                                        r"commas in a comma-separated file"):
        read_loads(path)


@pytest.mark.parametrize("unit, factor", [("kgf·m", G0), ("kg·m", G0), ("gf·m", G0 * 1e-3), ("g·m", G0 * 1e-3)])
def test_a_torque_in_kgf_m_or_g_m_is_read(unit, factor):
    """Torque in kgf·m or gf·m (motor makers' tables) was refused as an unknown unit."""
    assert map_columns(["rpm", f"Torque ({unit})"]).columns["torque"][1] == pytest.approx(factor)


def test_other_languages_names_need_their_quantitys_unit():
    """The review's cases: a French 'Vitesse (m/s)' beside an airspeed, 'vitesse_vent' or
    'couple_moteur' (no unit) were refused once these names were read unconditionally, and a
    bare 'Velocidad' (often the airspeed) was taken for the rpm; they read as before: not read."""
    cm = map_columns(["rpm", "thrust", "Vitesse (m/s)", "airspeed (m/s)", "vitesse_vent", "couple_moteur",
                      "regime_moteur"])
    assert set(cm.columns) == {"rpm", "thrust", "airspeed"}
    with pytest.raises(ValueError, match=r"column 'Velocidad' is read as the rotation speed only with a rotation "
                                         r"unit"):
        map_columns(["Velocidad", "thrust"])
    assert any(n.startswith("column 'N (N)' (a force) is not read") for n in map_columns(["rpm", "torque",
                                                                                          "N (N)"]).notes)


def test_an_inch_mark_in_a_data_row_does_not_join_rows(tmp_path):
    """Only the header line takes a wrapped quoted heading: an inch mark in the first data row
    (APC 10x7") joined two rows and the separator was guessed wrong (a review, 2026-11-30)."""
    path = tmp_path / "inch.csv"
    path.write_text('Propeller, Typ;Drehzahl, U/min;Schub, N\n' + "".join(
        f'APC 10x7";{3000 + 1000 * k};{1 + k},0\n' for k in range(6)))
    d = read_loads(path)
    np.testing.assert_allclose(d.omega * 30 / np.pi, [3000.0 + 1000 * k for k in range(6)])


def test_the_review_cases_of_the_second_round(tmp_path):
    """A second review's cases (2026-11-30): an unknown unit under another language's name is
    refused as before (it was dropped without a word); the thousands rule takes the column's
    largest whole number (120 ... 760 beside 1.050, 1.400 was read 1000 times small) and keeps
    a column with other decimals (0.5 beside 1.250 and 350 grams); a text temperature column after
    a good one does not hide it; subset keeps the conversions; a run id equal in any case to two
    runs is not guessed; the extra-field message names no last column that is read as a number."""
    with pytest.raises(ValueError, match=r"column 'Empuje \(gr\)': unknown unit 'gr' for thrust"):
        map_columns(["rpm", "Empuje (gr)", "Par (N·m)"])
    sweep = tmp_path / "sweep.csv"
    sweep.write_text("Drehzahl;Schub [g]\n3000;120\n4000;250\n5000;480\n6000;760\n7000;1.050\n8000;1.400\n")
    with pytest.raises(DataError, match=r"1.400 \(line 7\) beside 760 \(line 5\): a point as a thousands separator"):
        read_loads(sweep)
    grams = tmp_path / "grams.csv"
    grams.write_text("Drehzahl;Schub [g]\n1000;0.5\n2000;1.250\n6000;350\n8000;720\n")
    assert read_loads(grams, min_points=1).measured["thrust"][1] == pytest.approx(1.25 * G0 * 1e-3)
    rpm = np.arange(4000.0, 9001.0, 1000.0)
    T, _ = _rotor(rpm)
    air = tmp_path / "air.csv"
    air.write_text("RPM,Thrust (N),Temperature (°C),Pressure (hPa),Ambient temperature\n" + "".join(
        f"{a:.0f},{t:.6g},21,1013,warm\n" for a, t in zip(rpm, T)), encoding="utf-8")
    d = read_loads(air)
    assert d.air_density == pytest.approx(101300 / (287.05 * 294.15), rel=1e-3)
    assert d.subset(np.arange(d.n) < 3).converted == d.converted
    g = read_loads(grams, min_points=1)
    assert g.subset(np.arange(g.n) < 2).converted == g.converted == {"thrust": pytest.approx(G0 * 1e-3)}
    from propmap.cli.fit import _run_of
    assert _run_of("0702Rd", {"0702rd", "0702RD"}) == "0702Rd" and _run_of("0702rd", {"0702RD"}) == "0702RD"
    extra = tmp_path / "extra.csv"
    extra.write_text("rpm,Thrust (N),Torque (N.m)\n3000,1,33,0,027\n")
    with pytest.raises(DataError, match=r"5 fields, but the header \(line 1\) has 3: a comma inside a cell's text "
                                        r"that is not quoted, or decimal commas"):
        read_loads(extra, min_points=1)


def test_one_spike_does_not_make_a_temperature_a_motors(tmp_path):
    """The span is the 5th to 95th percentile's: one spike among 21 rows (a sensor's glitch) leaves
    the air's temperature read; max - min would have passed it over."""
    rpm = np.linspace(4000.0, 9000.0, 21)
    T, _ = _rotor(rpm)
    temperatures = [22.0] * 20 + [90.0]
    path = tmp_path / "spike.csv"
    path.write_text("RPM,Thrust (N),Temperature (°C),Pressure (hPa)\n" + "".join(
        f"{a:.0f},{t:.6g},{c:g},1013\n" for a, t, c in zip(rpm, T, temperatures)), encoding="utf-8")
    assert read_loads(path).air_density == pytest.approx(101300 / (287.05 * 295.15), rel=1e-3)


def test_a_run_column_is_read_as_the_groups(tmp_path):
    """A tunnel file's run labels under 'Run' were read as nothing (every point one group 'all',
    --holdout of a run refused): read as the groups where no 'group' column is, and beside one
    not read, with a note (a wind-tunnel data audit, 2026-11-30)."""
    rows = [(5000.0 + 1000 * (k // 3), 2.0 * k, 60.0, 1.0 + 0.1 * k, f"r{k // 3}") for k in range(9)]
    path = tmp_path / "runs.csv"
    path.write_text("rpm,airspeed,incidence_deg,thrust,Run\n" + "".join(",".join(map(str, r)) + "\n" for r in rows))
    assert list(read_loads(path).group) == [f"r{k // 3}" for k in range(9)]
    cm = map_columns(["rpm", "thrust", "Run", "group"])
    assert cm.column("group") == "group"
    assert "column 'Run' is not read: the run labels are read from 'group'" in cm.notes


def test_a_drag_of_the_other_sign_at_half_the_points_is_warned_of():
    """A sweep through negative angles given as magnitudes puts about half its in-plane forces on
    the other side: fitted without a word (warned of from 80%); warned of from 25% (a wind-tunnel
    data audit, 2026-11-30), and not where the signs agree."""
    prop = pm.load_propeller("apce_10x7")
    omega = np.full(12, 6000 * np.pi / 30)
    V, inc = np.full(12, 10.0), np.radians(np.linspace(30, 90, 12))
    r = pm.rotor_loads(prop, pm.generic_params(), omega, V, inc)
    flipped = np.where(np.arange(12) % 2 == 0, -1.0, 1.0) * r.drag
    for drag, warned in ((flipped, True), (r.drag, False)):
        data = pm.identify.LoadData(omega, V, inc, {"thrust": r.thrust, "drag": drag}, np.full(12, "a", dtype=object))
        said = [w for w in sanity_check(data, prop) if "the measured drag has the other sign" in w]
        assert bool(said) == warned, said
        if warned:
            assert "at 6 of 12 points at incidence" in said[0] and "given as magnitudes" in said[0]


@pytest.mark.parametrize("axes", ["rotor", "wind thrust and lift", "wind drag"])
def test_loads_in_wind_axes_are_named_as_such(axes):
    """A tunnel's force along the flow under 'thrust' with its lift under 'normal force', or its
    drag along the flow under 'drag', were fitted with exit 0 (parameters at their bounds), said
    only as a thrust ratio or a drag sign (a wind-tunnel data audit, 2026-11-30): a warning names
    wind axes and the conversion; loads in the rotor's axes get none."""
    prop = pm.load_propeller("apce_10x7")
    omega = np.full(16, 6000 * np.pi / 30)
    V, inc = np.tile([6.0, 12.0], 8), np.radians(np.repeat(np.linspace(20, 160, 8), 2))
    r = pm.rotor_loads(prop, pm.generic_params(), omega, V, inc)
    along, lift = r.thrust * np.cos(inc) - r.drag * np.sin(inc), r.thrust * np.sin(inc) + r.drag * np.cos(inc)
    T, D = {"rotor": (r.thrust, r.drag), "wind thrust and lift": (along, lift), "wind drag": (r.thrust, -along)}[axes]
    data = pm.identify.LoadData(omega, V, inc, {"thrust": T, "drag": D}, np.full(16, "a", dtype=object))
    if axes == "wind thrust and lift":  # (beyond 90 deg the force along the flow turns negative: refused, said first)
        with pytest.raises(DataError, match=r"likely loads in wind axes, not the rotor's \(thrust = L sin i - D_w"):
            sanity_check(data, prop)
        data = data.subset(inc < np.radians(95))  # (a tunnel's 20-90 deg: warned of)
    said = [w for w in sanity_check(data, prop) if "are the loads in wind axes?" in w]
    assert bool(said) == (axes != "rotor"), said
    if said:
        assert "thrust = L sin i - D_w cos i, in-plane force = L cos i + D_w sin i" in said[0]
        assert ("the tunnel's drag along the flow" in said[0]) == (axes == "wind drag")


@pytest.mark.parametrize("name, factor", [("Incidence angle (deg)", 1.0), ("Angle of incidence (rad)", 180 / np.pi),
                                          ("incidence_angle_deg", 1.0)])
def test_the_incidence_by_its_longer_names_is_read(name, factor):
    """'Incidence angle' and 'Angle of incidence' name propmap's incidence (the angle between the
    axis and the flow), with their unit: they were refused as a flow angle to be renamed (a
    wind-tunnel data audit, 2026-11-30); without a unit, degrees or radians, they are refused."""
    cm = map_columns(["rpm", "airspeed (m/s)", name, "thrust (N)"])
    assert cm.columns["incidence_deg"][:2] == (name, pytest.approx(factor))
    with pytest.raises(ValueError, match="gives no unit"):
        map_columns(["rpm", "airspeed (m/s)", name.split(" (")[0].replace("_deg", ""), "thrust (N)"])
