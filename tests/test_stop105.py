"""Stop 105: defects found by this stop's audits, each test failing on the code before its fix, except the guards
said so (what a fix must keep: files that read before). Data: synthetic flight logs (NeuroBEM's layout), stand
exports and wind-tunnel tables; the catalogue's APC 8x6E and 10x7E (APC PE0 and UIUC geometry)."""

import dataclasses
import math
import re
import warnings

import numpy as np
import pytest

from propmap.identify import DataError, read_loads
from test_audit_mutation_stop101 import _check, _log


def test_a_motor_acceleration_is_judged_over_the_windows_kept_only():
    """_derivative_ratio judges the speeds' change by its rms over the windows it keeps: a log whose first 3 of 5 s
    carry no motor acceleration (all motors exactly 0: left out) and whose speeds then change by 13 rad/s^2 rms
    (judged: 10) has motor 1's column in rpm/s refused. Counting the left-out windows as zeros took the rms to 8.4
    rad/s^2 and the column was read without a word."""
    from propmap.io.flightlog_checks import FlightLogError

    log = _log(duration=5.0)
    phase = 2 * math.pi * log.t[:, None] + 0.7 * np.arange(4)[None, :]
    acc = 6.0 * math.pi * np.cos(phase)  # (the exact derivative of 1100 + 3 sin(phase): 13.3 rad/s^2 rms)
    acc[:, 0] *= 30.0 / math.pi
    acc[log.t < 3.0, :] = 0.0
    with pytest.raises(FlightLogError, match=r"motor 1's logged acceleration is 9.5\d times .* in rpm/s"):
        _check(dataclasses.replace(log, rotor_omega=1100.0 + 3.0 * np.sin(phase), rotor_acceleration=acc))


# ---- thrust-stand exports (identify/steps.py, loads_csv.py, headers.py; an export audit of this stop) ---------------
def _stand_rows(up=0, down=0, rate=25.0, jitter=0.0, hold=12):
    """(ESC signal [us], rpm) rows of a steps test: 7 steps of ``hold`` rows, 1150-1750 us and 3000-9000 rpm, with
    ``up`` ramp rows from idle before the first step and ``down`` after the last (``rate`` us a row, +-``jitter``
    us of readback noise), between motor-stopped rows."""
    noise = np.random.default_rng(1).integers(-jitter, jitter + 1, up + down) if jitter else np.zeros(up + down)
    rows = [(1000.0, 0.0)] * 4
    rows += [(1150.0 - rate * (up - k) + noise[k], 3000.0 - 250.0 * (up - k)) for k in range(up)]
    for k in range(7):
        rows += [(1150.0 + 100 * k, 3000.0 + 1000 * k)] * hold
    rows += [(1750.0 - rate * (k + 1) + noise[up + k], 9000.0 - 6000.0 * (k + 1) / down) for k in range(down)]
    return rows + [(1000.0, 0.0)] * 4


def _stand_log(path, header, *, up=0, down=0, rate=25.0, rows=None, hz=40.0, groups=None):
    """A steps test sampled at ``hz`` (default :func:`_stand_rows`), thrust 6.8e-8 rpm^2 N and torque 1.36e-9
    rpm^2 N m (an APC 8x6E's order), the load following the speed; ``groups`` a label per row."""
    rows = rows or _stand_rows(up, down, rate)
    lines = [",".join(header + (["group"] if groups else []))]
    for i, (esc, rpm) in enumerate(rows):
        lines.append(f"{i / hz:.3f},{esc:.0f},{-1.36e-9 * rpm**2:.6g},{6.8e-8 * rpm**2:.6g},{rpm:.0f}"
                     + (f",{groups[i]}" if groups else ""))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


HEADER = ["Time (s)", "ESC signal (µs)", "Torque (N·m)", "Thrust (N)", "Motor Optical Speed (RPM)"]


@pytest.mark.parametrize("up, down", [(0, 0), (6, 0), (0, 28), (6, 28)])
def test_the_ramps_up_from_idle_and_back_to_it_are_no_points(tmp_path, up, down):
    """A steps test's ramps at the rows' ends (the stopped rows skipped) are transients: 7 points for 7 steps with
    or without them (the ramp back to idle made 35 points of 7 steps, the ramp up 11, each ramp row a point)."""
    from propmap.identify import read_loads

    data = read_loads(_stand_log(tmp_path / "s.csv", HEADER, up=up, down=down))
    assert data.n == 7
    np.testing.assert_allclose(data.omega * 60 / (2 * math.pi), np.arange(3000, 9001, 1000), rtol=1e-9)
    assert any(f"{84 + up + down} rows averaged into 7 ESC steps" in n for n in data.notes), data.notes


def test_the_ramps_of_two_tests_in_one_log_are_no_points(tmp_path):
    """A test's ends are also where the label changes and where the time jumps (the stopped rows between two tests
    skipped): two tests with their ramps, labelled or concatenated, are 14 points (a review: 48, the ramps inside the
    log kept)."""
    from propmap.identify import read_loads

    rows = _stand_rows(6, 28)
    labels = ["A"] * len(rows) + ["B"] * len(rows)
    with pytest.warns(UserWarning, match="7 row"):  # (the two tests' points alike: said as repeated rows)
        assert read_loads(_stand_log(tmp_path / "g.csv", HEADER, rows=rows + rows, groups=labels)).n == 14
    with pytest.warns(UserWarning, match="7 row"):
        assert read_loads(_stand_log(tmp_path / "c.csv", HEADER, rows=rows + rows)).n == 14


def test_a_jittering_ramp_is_no_points_and_short_steps_of_a_slow_log_are(tmp_path):
    """A 5 us/row ramp back to idle with +-2 us of readback jitter (some rows merged into two-row steps, a few moving
    back) is dropped; the two-row steps of a 2 Hz log beside a 6-row step stay points (a review: a first version read
    ten such steps as a ramp and refused the log as one point)."""
    from propmap.identify import read_loads

    assert read_loads(_stand_log(tmp_path / "j.csv", HEADER, rows=_stand_rows(0, 100, rate=5.0, jitter=2))).n == 7
    slow = [(1000.0, 0.0)] * 2 + [(1150.0 + 60 * k, 3000.0 + 600 * k) for k in range(10) for _ in range(2)]
    slow += [(1750.0, 9200.0)] * 6 + [(1000.0, 0.0)] * 2
    assert read_loads(_stand_log(tmp_path / "s.csv", HEADER, rows=slow, hz=2.0)).n == 11


def test_a_ramp_at_the_end_that_rises_stays_points(tmp_path):
    """Short steps after the last long step that rise (a warm-up hold, then a table of short steps) are no ramp to
    idle: the end rule takes only a fall (here 7 + 10 points: the 7 steps, then 10 single rows rising 25 us each)."""
    from propmap.identify import read_loads

    path = _stand_log(tmp_path / "s.csv", HEADER)
    lines = path.read_text(encoding="utf-8").splitlines()[:-4]  # (the stopped rows at the end dropped)
    lines += [f"{3 + k / 40:.3f},{1775 + 25 * k},{-1.36e-9 * (9250 + 250 * k)**2:.6g},"
              f"{6.8e-8 * (9250 + 250 * k)**2:.6g},{9250 + 250 * k}" for k in range(10)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert read_loads(path).n == 17


def test_tytos_pwm_throttle_signal_is_the_esc_signal(tmp_path):
    """'PWM throttle signal (µs)' (Tyto Robotics' database exports) is read as the ESC signal: its rows are
    averaged into steps, not each fitted as a point (84 points, settling rows included)."""
    from propmap.identify import read_loads

    header = ["Time (s)", "PWM throttle signal (µs)", "Torque (N⋅m)", "Thrust (N)", "Rotation speed (rpm)"]
    data = read_loads(_stand_log(tmp_path / "t.csv", header, down=5))
    assert data.n == 7


def test_a_makers_power_column_is_named_as_electrical_not_as_the_torque(tmp_path):
    """A bare 'Power (W)' beside voltage and current (a motor maker's table) is likely the electrical V I: the note
    says that Q = P / Omega needs the shaft power (it advised Q = P / Omega for it)."""
    from propmap.identify import read_loads

    path = tmp_path / "m.csv"
    rows = [f"{30 + 10 * k},{6.8e-8 * (3000 + 1000 * k)**2 / 9.80665e-3:.1f},{3000 + 1000 * k},16.6,{1 + k},"
            f"{16.6 * (1 + k):.2f}" for k in range(7)]
    path.write_text("Throttle (%),Thrust (g),RPM,Voltage (V),Current (A),Power (W)\n" + "\n".join(rows) + "\n")
    notes = read_loads(path).notes
    assert any("'Power (W)' is not read: propmap fits a torque column, Q = P / Omega with P the shaft (mechanical) "
               "power, not the electrical V I" in n and "likely the electrical one" in n for n in notes), notes


def test_a_stand_export_without_any_rotation_speed_names_both_columns(tmp_path):
    """Both of the stand's speed columns 0 in every row (no probe, no telemetry): the refusal names both."""
    from propmap.identify import DataError, read_loads

    header = ["Time (s)", "ESC signal (µs)", "Torque (N·m)", "Thrust (N)", "Motor Electrical Speed (RPM)",
              "Motor Optical Speed (RPM)"]
    lines = [",".join(header)] + [f"{k / 40:.3f},{1150 + 100 * (k // 12)},-0.02,1.0,0,0" for k in range(84)]
    (tmp_path / "z.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    with pytest.raises(DataError, match=r"'Motor Electrical Speed \(RPM\)' is empty or 0 in every row, and so is "
                                        r"'Motor Optical Speed \(RPM\)': no rotation speed was recorded"):
        read_loads(tmp_path / "z.csv")


def test_a_continuous_sweep_is_read_row_by_row_with_a_note(tmp_path):
    """A signal that changes at every row (a sweep, 0.5 us a row, no held steps) is read as one point a row, and a
    note says so (1,400 rows were fitted as points without a word)."""
    from propmap.identify import read_loads

    lines = [",".join(HEADER)] + [f"{k / 40:.3f},{1100 + 0.5 * k:.1f},{-1.36e-9 * (3000 + 5 * k)**2:.6g},"
                                  f"{6.8e-8 * (3000 + 5 * k)**2:.6g},{3000 + 5 * k}" for k in range(60)]
    (tmp_path / "w.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    data = read_loads(tmp_path / "w.csv")
    assert data.n == 60
    assert any("each of the 60 rows is a point: no two rows of 'ESC signal (µs)' hold one value (a continuous sweep"
               in n for n in data.notes), data.notes


# ---- the held-out fits without the profile likelihood (identify/options.py, validation/loads.py) --------------------
def test_profile_likelihood_off_keeps_the_linearised_interval_and_the_optimum():
    """FitOptions(profile_likelihood=False): the fit of a saturating flap compliance (test_user_data_edges' case:
    loads made with 20 rad/(N m), 0.5% noise; with the profile its interval reaches the bound 50 with a warning)
    keeps the linearised interval and says nothing of the saturation, at the same optimum (15-40)."""
    from test_user_data_edges import _incidence_data

    import propmap as pm
    from propmap.identify import FitOptions, fit_loads

    prop, data = _incidence_data(20.0, 0.005, seed=2)
    res = fit_loads(data, prop, base=pm.default_params("apce_10x7"), options=FitOptions(profile_likelihood=False))
    j = res.names.index("flap_compliance")
    assert 15.0 < res.x[j] < 40.0
    assert not any("flap_compliance: the data hardly tell" in w or "saturates" in w for w in res.warnings), res.warnings
    with pytest.raises(ValueError, match="profile_likelihood must be True or False, got 'no'"):
        FitOptions(profile_likelihood="no")


def test_holdout_loads_fits_without_the_profile_likelihood(monkeypatch):
    """holdout_loads uses each fold's parameters only, so its fits skip the profile likelihood (2.7 times faster on
    the four gill2019 propellers, the same errors)."""
    from test_user_data_edges import _incidence_data

    import propmap as pm
    import propmap.identify
    from propmap.validation import holdout_loads

    seen = []

    def spy(*args, options=None, **kwargs):
        seen.append(options)
        raise RuntimeError("spied")

    monkeypatch.setattr(propmap.identify, "fit_loads", spy)
    prop, data = _incidence_data(1.0, 0.002)
    with pytest.raises(RuntimeError, match="spied"):
        holdout_loads(data, prop, pm.default_params("apce_10x7"), [np.arange(data.n) % 2 == 0])
    assert len(seen) == 1 and seen[0].profile_likelihood is False


def test_a_maps_flags_say_what_their_values_mean(small_map, tmp_path):
    """The map file's flag variables carry the CF conventions' flag_values and flag_meanings (a reader without xarray
    saw int8 0/1 with a long_name only)."""
    import xarray as xr

    from propmap.io.mapfile import write_map

    write_map(small_map[2], tmp_path / "m.nc")
    with xr.open_dataset(tmp_path / "m.nc") as ds:
        for f in ("converged", "vortex_ring", "multiple_roots", "reverse_flow"):
            attrs = ds[f].attrs
            assert list(attrs["flag_values"]) == [0, 1] and attrs["flag_meanings"] == f"not_{f} {f}", attrs


# ---- wind-tunnel files at incidence (identify/unread.py; a wind-tunnel data audit of this stop) ---------------------
def _tunnel(tmp_path, header, rows=None):
    rows = rows or [(5000, 0.0, 0.0, 3.9, 0.074), (5000, 10.0, 90.0, 4.3, 0.081), (6000, 5.0, 45.0, 5.4, 0.10)]
    (tmp_path / "w.csv").write_text(",".join(header) + "\n" + "\n".join(",".join(map(str, r)) for r in rows) + "\n")
    return tmp_path / "w.csv"


@pytest.mark.parametrize("angle", ["alpha_angle", "tilt_angle", "shaft_angle", "theta", "wind_angle", "alpha_prop",
                                   "prop angle", "propeller_angle (deg)"])
def test_an_unread_angle_beside_an_airspeed_is_refused(tmp_path, angle):
    """Beside an airspeed, a column with a flow angle's word that propmap does not read is refused (TU Delft's
    'alpha_angle' with the loads renamed: every point read as axial, 28% thrust error, exit 0)."""
    from propmap.identify import DataError, read_loads

    path = _tunnel(tmp_path, ["rpm", "airspeed", angle, "thrust", "torque"])
    with pytest.raises(DataError, match=rf"column '{re.escape(angle)}' looks like a flow angle, which propmap reads "
                                        r"only as 'incidence_deg'"):
        read_loads(path)


@pytest.mark.parametrize("name", ["phase_angle", "theta_75", "alpha_filter", "Tilt servo", "Coning angle"])
def test_an_angles_word_among_others_beside_an_airspeed_gets_a_note(tmp_path, name):
    """A name with a flow angle's word among other words (a motor's phase angle, a blade angle at 0.75 R, a filter's
    alpha) is not refused but named in a note (a review: a first version refused them, files that read before)."""
    from propmap.identify import read_loads

    data = read_loads(_tunnel(tmp_path, ["rpm", "airspeed", name, "thrust", "torque"]), min_points=1)
    assert any(f"column '{name}' is not read; if it is a flow angle, name it 'incidence_deg'" in n
               for n in data.notes), data.notes


def test_a_blade_pitch_beside_an_airspeed_is_still_refused_as_a_pitch(tmp_path):
    from propmap.identify import DataError, read_loads

    with pytest.raises(DataError, match=r"column 'pitch_angle' looks like a blade pitch setting"):
        read_loads(_tunnel(tmp_path, ["rpm", "airspeed", "pitch_angle", "thrust", "torque"]))


def test_a_balances_moment_is_named_and_its_axis_components_explained(tmp_path):
    """'Mz (ft-lb)' beside a thrust without a torque is named in a note; a file of Fx, Fz and Mz alone is refused
    saying that the loads are read in the rotor's axes (it was told 'no load column' only)."""
    from propmap.identify import DataError, read_loads

    data = read_loads(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "Thrust (N)", "Mz (ft-lb)"]), min_points=1)
    assert any("column(s) 'Mz (ft-lb)' (a moment) not read: if one is the moment about the rotor axis, name it "
               "'torque'" in n for n in data.notes), data.notes
    with pytest.raises(DataError, match=r"no load column: .*'Fx \(N\)', 'Fz \(N\)', 'Mz \(N m\)' look like a balance's "
                                        r"axis components: propmap reads the loads in the rotor's axes"):
        read_loads(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "Fx (N)", "Fz (N)", "Mz (N m)"]),
                   min_points=1)


# ---- the survivors of this stop's mutation audit (a helper session: 82 hand-made mutants of the change, 35 killed, 13
# equivalent; these tests kill 20 of the real gaps; S: steps.py, L: loads_csv.py, H: headers.py, U: unread.py,
# C: cli/flight.py). Synthetic stand logs and tunnel tables as above.
def _n(path, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return read_loads(path, **kw)


def test_S2_label_cut_without_time_gap(tmp_path):
    """A label change ends a test even without stopped rows or a time gap between two tests (14 points, not 48)."""
    rows = _stand_rows(6, 28)[4:-4]
    assert (
        _n(_stand_log(tmp_path / "g.csv", HEADER, rows=rows + rows, groups=["A"] * len(rows) + ["B"] * len(rows))).n
        == 14
    )


def test_S5_backmove_3us_still_ramp(tmp_path):
    """A ramp to idle with a 3 us move back (merged into a step of two rows) is still a ramp: 7 points."""
    lv = [1740, 1730, 1720, 1723, 1710, 1700, 1690, 1680, 1670, 1660]
    rows = _stand_rows()[:-4] + [(float(e), 9000.0 - 30 * (1750 - e)) for e in lv] + [(1000.0, 0.0)] * 4
    assert _n(_stand_log(tmp_path / "s.csv", HEADER, rows=rows)).n == 7


def test_S6_backmove_6us_stays_points(tmp_path):
    """A fall with a 6 us move back (two steps) is no monotone ramp: its 10 rows stay points, 17."""
    lv = [1740, 1730, 1720, 1726, 1710, 1700, 1690, 1680, 1670, 1660]
    rows = _stand_rows()[:-4] + [(float(e), 9000.0 - 30 * (1750 - e)) for e in lv] + [(1000.0, 0.0)] * 4
    assert _n(_stand_log(tmp_path / "s.csv", HEADER, rows=rows)).n == 17


def test_S11_a_short_burst_before_a_test_stays_points(tmp_path):
    """A 3-row rising burst, stopped rows, then a test: the burst ends at the gap, so it stays points (10)."""
    rows = [(1000.0, 0.0)] * 4 + [(1050.0, 1500.0), (1075.0, 1800.0), (1100.0, 2100.0)] + _stand_rows()
    assert _n(_stand_log(tmp_path / "s.csv", HEADER, rows=rows)).n == 10


def _csv(path, header, rows):
    path.write_text(
        ",".join(header) + "\n" + "\n".join(",".join(f"{x:.6g}" for x in r) for r in rows) + "\n", encoding="utf-8"
    )
    return path


H6 = ["Time (s)", "ESC signal (µs)", "Torque (N·m)", "Thrust (N)", "Motor Optical Speed (RPM)", "airspeed"]


def _r(t, esc, rpm, v):
    return (t, esc, -1.36e-9 * rpm**2, 6.8e-8 * rpm**2, rpm, v)


def test_S14_end_fall_at_other_airspeeds_stays_points(tmp_path):
    """Short steps falling at the end at other airspeeds are tunnel points, not a ramp (11)."""
    rows = [_r(0, 1150 + 100 * k, 3000 + 1000 * k, 0.0) for k in range(7) for _ in range(12)]
    rows += [_r(0, e, 8000 - 500 * i, 2.0 * (i + 1)) for i, e in enumerate((1700, 1650, 1600, 1550))]
    rows = [(i / 40, *r[1:]) for i, r in enumerate(rows)]
    assert _n(_csv(tmp_path / "t.csv", H6, rows)).n == 11


def test_S19_middle_run_at_other_airspeeds_stays_points(tmp_path):
    """Short steps between two long ones at other airspeeds are points (the middle rule's condition: 6)."""
    rows = [_r(0, 1500, 6000, 0.0)] * 12
    rows += [_r(0, 1500 + 20 * i, 6000 + 200 * i, 2.0 * i) for i in range(1, 5) for _ in range(2)]
    rows += [_r(0, 1600, 7000, 10.0)] * 12
    rows = [(i / 40, *r[1:]) for i, r in enumerate(rows)]
    assert _n(_csv(tmp_path / "t.csv", H6, rows), min_points=1).n == 6


def test_S18_throttle_percent_ramp_to_idle(tmp_path):
    """A ramp to idle of 1 %/row in a throttle log is dropped with the throttle's tolerance (7 points, not 37)."""
    hdr = ["Time (s)", "Throttle (%)", "Torque (N·m)", "Thrust (N)", "Motor Optical Speed (RPM)"]
    rows = [(20.0 + 10 * k, 3000.0 + 1000 * k) for k in range(7) for _ in range(12)]
    rows += [(79.0 - k, 9000.0 - 150 * (k + 1)) for k in range(30)]
    rows = [(i / 40, e, -1.36e-9 * n**2, 6.8e-8 * n**2, n) for i, (e, n) in enumerate(rows)]
    assert _n(_csv(tmp_path / "p.csv", hdr, rows)).n == 7


def test_L8_optical_chosen_zero_electrical_not(tmp_path):
    """rpm_source='optical' with the optical column 0: the refusal does not name the electrical one, which reads."""
    header = [
        "Time (s)",
        "ESC signal (µs)",
        "Torque (N·m)",
        "Thrust (N)",
        "Motor Electrical Speed (RPM)",
        "Motor Optical Speed (RPM)",
    ]
    lines = [",".join(header)] + [
        f"{k / 40:.3f},{1150 + 100 * (k // 12)},-0.02,1.0,{3000 + 1000 * (k // 12)},0" for k in range(84)
    ]
    (tmp_path / "z.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    with pytest.raises(DataError) as e:
        _n(tmp_path / "z.csv", rpm_source="optical")
    assert "and so is" not in str(e.value), str(e.value)


def test_L4_no_time_no_sweep_note(tmp_path):
    """50 distinct signal rows without a time column are a table, not a sweep: no sweep note."""
    hdr = ["ESC signal (µs)", "Torque (N·m)", "Thrust (N)", "rpm"]
    rows = [
        (1100 + 10 * k, -1.36e-9 * (3000 + 50 * k) ** 2, 6.8e-8 * (3000 + 50 * k) ** 2, 3000 + 50 * k)
        for k in range(50)
    ]
    d = _n(_csv(tmp_path / "w.csv", hdr, rows))
    assert d.n == 50 and not any("continuous sweep" in n for n in d.notes), d.notes


def test_L12_power_notes(tmp_path):
    """'likely the electrical' only for a bare 'Power' beside voltage and current (not a shaft power, not alone)."""
    for col, extra, likely in (
        ("Shaft power (W)", True, False),
        ("Power (W)", False, False),
        ("Power (W)", True, True),
    ):
        path = tmp_path / "m.csv"
        head = "Throttle (%),Thrust (g),RPM," + ("Voltage (V),Current (A)," if extra else "") + col
        rows = [
            f"{30 + 10 * k},{6.8e-8 * (3000 + 1000 * k) ** 2 / 9.80665e-3:.1f},{3000 + 1000 * k},"
            + ("16.6," + f"{1 + k}," if extra else "")
            + f"{16.6 * (1 + k):.2f}"
            for k in range(7)
        ]
        path.write_text(head + "\n" + "\n".join(rows) + "\n")
        notes = _n(path).notes
        assert (
            any("Q = P / Omega" in n for n in notes) and any("likely the electrical" in n for n in notes) == likely
        ), (col, notes)


def test_H2_pwm_throttle(tmp_path):
    """'PWM throttle (µs)' is the ESC signal too."""
    header = ["Time (s)", "PWM throttle (µs)", "Torque (N⋅m)", "Thrust (N)", "Rotation speed (rpm)"]
    assert _n(_stand_log(tmp_path / "t.csv", header, down=5)).n == 7


def test_U9_other_column_no_angle_note(tmp_path):
    """A column without an angle's word ('temperature') gets no flow-angle note."""
    d = _n(_tunnel(tmp_path, ["rpm", "airspeed", "temperature", "thrust", "torque"]), min_points=1)
    assert not any("'temperature' is not read; if it is a flow angle" in n for n in d.notes), d.notes


def test_U19_U20_D2_moment_note_only_for_axis_moments(tmp_path):
    """No moment note for a force, a pitching moment, or beside a torque read."""
    for hdr in (
        ["rpm", "airspeed", "incidence_deg", "Thrust (N)", "Fx (N)"],
        ["rpm", "airspeed", "incidence_deg", "Thrust (N)", "Pitching moment (N m)"],
        ["rpm", "airspeed", "incidence_deg", "Thrust (N)", "Torque (N m)", "Mz (N m)"],
    ):
        d = _n(_tunnel(tmp_path, hdr), min_points=1)
        assert not any("(a moment) not read" in n for n in d.notes), (hdr, d.notes)


def test_U2_U21_underscored_components(tmp_path):
    """'M_z' is an axis moment as 'Mz' is; F_x, F_z, M_z get the axis-components hint."""
    d = _n(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "Thrust (N)", "M_z (N m)"]), min_points=1)
    assert any("column(s) 'M_z (N m)' (a moment) not read" in n for n in d.notes), d.notes
    with pytest.raises(DataError, match=r"'F_x \(N\)', 'F_z \(N\)', 'M_z \(N m\)' look like a balance's"):
        _n(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "F_x (N)", "F_z (N)", "M_z (N m)"]), min_points=1)


def test_S16_coarse_time(tmp_path):
    """A log whose time is rounded to 0.1 s (zero steps between rows) still finds its tests' ends: 7 points."""
    rows = _stand_rows(6, 28)
    lines = [",".join(HEADER)] + [
        f"{int(i / 40 * 10) / 10:.1f},{e:.0f},{-1.36e-9 * n**2:.6g},{6.8e-8 * n**2:.6g},{n:.0f}"
        for i, (e, n) in enumerate(rows)
    ]
    (tmp_path / "c.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert _n(tmp_path / "c.csv").n == 7


def test_C8_held_out_log_is_no_fold(tmp_path, capsys, shared_data):
    """--holdout's log is no cross-validation fold: warned of as held out, not as a fold."""
    from test_flight_log_units import SEGMENTS, VEHICLE, main

    logs = [str(shared_data / "neurobem_flights" / s) for s in SEGMENTS]
    code = main(
        [
            "fit",
            "flight",
            *logs,
            "--vehicle",
            str(VEHICLE),
            "--out",
            str(tmp_path / "p.toml"),
            "--rate-hz",
            "1",
            "--holdout",
            SEGMENTS[1],
            "--cross-validate",
            "--fit-params",
            "collective",
        ]
    )
    err = capsys.readouterr().err
    assert code == 0 and f"the fold of {SEGMENTS[1]}" not in err and f"held-out log {SEGMENTS[1]} reaches" in err, err


def test_profile_likelihood_takes_numpys_bool():
    """FitOptions(profile_likelihood=np.True_) is a bool (a mask's element): accepted."""
    from propmap.identify import FitOptions

    assert FitOptions(profile_likelihood=np.True_).profile_likelihood


def test_the_cv_report_gives_angles_in_degrees_under_their_report_names():
    """_cv_report: a fold's collective 0.1 rad is collective_deg 5.73 deg, its at_bound names likewise, the
    jackknife std error 0.01 rad 0.573 deg; other parameters as fitted."""
    from propmap.cli.flight import _cv_report

    cv = _cv_report({"folds": [{"log": "a", "x": {"collective": 0.1, "cl_alpha": 4.0}, "at_bound": ["collective"]}],
                     "jackknife_std_error": {"collective": 0.01, "cl_alpha": 0.5}, "pooled": {}})
    fold = cv["folds"][0]
    assert fold["x"] == {"collective_deg": pytest.approx(math.degrees(0.1)), "cl_alpha": 4.0}
    assert fold["at_bound"] == ["collective_deg"] and fold["log"] == "a"
    assert cv["jackknife_std_error"] == {"collective_deg": pytest.approx(math.degrees(0.01)), "cl_alpha": 0.5}


def test_the_name_patterns_of_flow_angles_and_axis_components(tmp_path):
    """The patterns of unread.py at their edges (the mutation audit's untested forms): an angle's words joined by a
    hyphen or a point are refused; in a unit that is no angle's they are neither refused nor noted; a blade pitch's
    name gets no flow-angle note; 'Moment Z' and both of 'Mx', 'Mz' are axis moments; 'Mz_tare' is no component."""
    for name in ("alpha-angle", "tilt.angle"):
        with pytest.raises(DataError, match=rf"column '{re.escape(name)}' looks like a flow angle"):
            read_loads(_tunnel(tmp_path, ["rpm", "airspeed", name, "thrust", "torque"]), min_points=1)
    for name in ("phase_angle (A)", "theta (Hz)"):
        d = _n(_tunnel(tmp_path, ["rpm", "airspeed", name, "thrust", "torque"]), min_points=1)
        assert not any("flow angle" in n for n in d.notes), d.notes
    rows = [(5000, 0.0, 0.0, 3.9, 0.074, 0.0), (5000, 10.0, 2.0, 4.3, 0.081, 2.0), (6000, 5.0, 0.0, 5.4, 0.10, 0.0)]
    d = _n(_tunnel(tmp_path, ["rpm", "airspeed", "collective_deg", "thrust", "torque", "pitch_angle"], rows),
           min_points=1)
    assert d.n == 3 and not any("flow angle" in n for n in d.notes), d.notes
    d = _n(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "thrust", "Moment Z (N m)"]), min_points=1)
    assert any("column(s) 'Moment Z (N m)' (a moment) not read" in n for n in d.notes), d.notes
    d = _n(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "thrust", "Mx (N m)", "Mz (N m)"],
                   [r + (0.01,) for r in [(5000, 0.0, 0.0, 3.9, 0.074), (5000, 10.0, 90.0, 4.3, 0.081)]]),
           min_points=1)
    assert any("column(s) 'Mx (N m)', 'Mz (N m)' (a moment)" in n for n in d.notes), d.notes
    with pytest.raises(DataError) as err:
        read_loads(_tunnel(tmp_path, ["rpm", "airspeed", "incidence_deg", "Fx (N)", "Mz_tare (N m)"]), min_points=1)
    assert "'Fx (N)' look like a balance's axis components" in str(err.value), str(err.value)
