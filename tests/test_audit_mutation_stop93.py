"""Tests for the survivors of a mutation audit of stop 93's change (a helper session, 2026-12-01:
61 mutants of the noisy-condition steps, the units row, the thousands separators, the unit pairs and
the held flapping warning; 35 killed by the committed tests, 4 equivalent, 22 real gaps, each test
here checked to pass on the code and fail on its mutant; the mutant ids in the comments), and for the
four defects it found (each fixed the same day; the tests fail on the code before the fix)."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.identify import read_loads
from propmap.identify.headers import units_row
from propmap.identify.steps import CONDITION_TOL, condition_tolerances, stand_points



# ---- test_gaps_steps.py
def _holds(n_holds, rows, levels=(5.0,), sigma=0.2, seed=0, esc0=1200, esc_step=100):
    """ESC holds of ``rows`` rows each; airspeed at levels[k % len] + sigma noise."""
    rng = np.random.default_rng(seed)
    esc = np.repeat(esc0 + esc_step * np.arange(n_holds), rows).astype(float)
    base = np.repeat([levels[k % len(levels)] for k in range(n_holds)], rows)
    return esc, base + sigma * rng.standard_normal(esc.size)


def test_noisy_tolerance_is_five_times_the_rms_noise():  # S2 (NOISE_K 5 -> 8), S14/S15 too
    esc, a = _holds(4, 30, sigma=0.2)
    tol, noisy = condition_tolerances({"airspeed": a}, esc)
    assert noisy["airspeed"] == pytest.approx(0.2, rel=0.2)
    assert tol["airspeed"] == pytest.approx(5 * noisy["airspeed"], rel=1e-12)


def test_holds_of_six_rows_are_no_sampled_log():  # S3 (sampled-log test dropped)
    esc, a = _holds(40, 6, sigma=0.3)  # 0.3 m/s rms: widened to ~1.4 where the log counted as sampled
    assert condition_tolerances({"airspeed": a}, esc) == ({"airspeed": CONDITION_TOL["airspeed"]}, {})


def test_twelve_rows_per_hold_are_enough_to_estimate_the_noise():  # S13 (min diffs 10 -> 100)
    esc, a = _holds(4, 12, sigma=0.2)  # 44 first differences
    assert set(condition_tolerances({"airspeed": a}, esc)[1]) == {"airspeed"}


def test_noise_is_judged_against_the_range_when_the_median_is_small():  # S8 (scale = median only)
    # 3 holds at 1 m/s and one at 8 m/s, 0.3 m/s rms: 0.3 > 0.1 * median (1) but <= 0.1 * range (~8)
    esc, a = _holds(4, 30, levels=(1.0, 1.0, 1.0, 8.0), sigma=0.3, seed=2)
    tol, noisy = condition_tolerances({"airspeed": a}, esc)
    assert set(noisy) == {"airspeed"} and tol["airspeed"] > 1.0


def test_a_column_that_runs_one_way_with_uneven_steps_is_not_noise():  # S9 (turns-back test dropped)
    rng = np.random.default_rng(5)
    a = np.cumsum(rng.uniform(0.2, 1.0, 60))  # a tunnel spinning up: every row moves, never back
    assert condition_tolerances({"airspeed": a}, np.full(60, 1500.0))[1] == {}


def test_a_column_that_holds_at_most_rows_is_not_noise():  # S11 (moves-at-most-rows test dropped)
    # a 1 m/s-resolution reading at 10 m/s flickering by one count at a quarter of its rows: it moves at
    # about 40% of the rows (turning back at most of those), so it is not noise
    rng = np.random.default_rng(11)
    a = 10.0 + rng.choice([-1.0, 0.0, 1.0], p=[0.125, 0.75, 0.125], size=200)
    moves = np.count_nonzero(np.diff(a)) / 199
    assert 0.3 < moves < 0.5
    assert condition_tolerances({"airspeed": a}, np.full(200, 1500.0))[1] == {}


def test_a_hold_is_one_label_too():  # S26 (holds ignore labels)
    esc, a = _holds(1, 60, sigma=0.2)
    labels = np.repeat([f"run{k}" for k in range(12)], 5)  # 12 runs of 5 rows at one signal: no sampled log
    assert condition_tolerances({"airspeed": a}, esc, labels)[1] == {}


def test_a_noisy_step_splits_at_the_mean_of_its_rows_not_its_first_row():  # S17, S18
    # one ESC signal, airspeed 4 then 5.3 m/s (tolerance 1.0): the first row of the 4 m/s level is 4.4
    lo = [4.4] + [3.8, 4.2] * 9 + [3.8]            # 20 rows, mean 4.03
    hi = [5.2, 5.6] * 10                            # 20 rows
    a = np.array(lo + hi)
    n = a.size
    values = {"rpm": np.full(n, 6000.0), "airspeed": a, "thrust": np.arange(n, dtype=float)}
    out, groups, _, _ = stand_points(values, np.full(n, 1500.0), None, settle=0.0, cond_tol={"airspeed": 1.0})
    # step 1 is rows 0-19 exactly (5.2 is 1.17 from their mean; it is only 0.8 from the first row)
    assert len(groups) == 2
    assert out["thrust"][0] == pytest.approx(np.mean(np.arange(20)))


def test_jittering_pieces_of_a_noisy_step_are_merged_within_its_tolerance():  # S21 (_merge_steps fixed tol)
    rng = np.random.default_rng(4)
    esc = np.repeat([1200.0, 1400.0, 1600.0], 40) + rng.integers(-2, 3, 120)  # +-2 us readback jitter
    a = 5.0 + 0.2 * rng.standard_normal(120)
    values = {"rpm": np.repeat([4000.0, 5500.0, 7000.0], 40), "airspeed": a}
    out, groups, _, _ = stand_points(values, esc, None, cond_tol={"airspeed": 1.0})
    assert len(groups) == 3, groups


def test_stand_points_widens_a_noisy_columns_tolerance_by_default():  # S25 (default cond_tol fixed)
    rng = np.random.default_rng(0)
    esc = np.repeat(1200.0 + 200 * np.arange(4), 90)
    a = np.tile(np.repeat([0.0, 4.0, 8.0], 30), 4)
    a = np.maximum(a + 0.2 * rng.standard_normal(a.size), 0.0)
    values = {"rpm": np.repeat([4000.0, 5500.0, 7000.0, 8500.0], 90), "airspeed": a}
    out, groups, _, _ = stand_points(values, esc, None)
    assert len(groups) == 12, groups
    assert np.allclose(np.sort(out["airspeed"]), np.repeat([0.0, 4.0, 8.0], 4), atol=0.25)



# ---- test_gaps_csv.py
ROWS = "".join(f"{r},{r * r * 1e-7:.5g},{r * r * 2e-9:.5g}\n" for r in range(3000, 9000, 1000))


def test_a_units_row_cell_longer_than_16_characters_is_no_unit():  # C4 (length cap)
    assert units_row(["rpm", "thrust", "torque", "comment"], ["RPM", "N", "N m", "motor warmed up 5 min"]) is None
    assert units_row(["rpm", "thrust", "torque"], ["RPM", "N", "N m"]) is not None


def test_a_row_half_of_whose_cells_are_units_is_no_units_row():  # C6 (more than half, not half)
    assert units_row(["motor", "prop", "rpm", "thrust"], ["A", "APC", "B", "RPM"]) is None  # a, rpm known; apc, b not
    assert units_row(["motor", "prop", "rpm", "thrust"], ["A", "APC", "N", "RPM"]) is not None


def test_a_units_row_cell_under_an_unnamed_column_is_no_units_row():  # C7
    assert units_row(["rpm", "thrust", ""], ["RPM", "N", "s"]) is None
    assert units_row(["rpm", "thrust", "x"], ["RPM", "N", "s"]) is not None


def test_a_dash_or_1_in_a_units_row_adds_no_unit(tmp_path):  # C8
    header, conflicts = units_row(["rpm", "thrust", "torque", "esc"], ["RPM", "N", "-", "-"])
    assert header == ["rpm (RPM)", "thrust (N)", "torque", "esc"] and conflicts == []
    path = tmp_path / "u.csv"
    path.write_text("rpm,thrust,torque (N m),ratio\nRPM,N,-,-\n" + ROWS.replace("\n", ",1\n"))
    data = read_loads(path)
    assert data.n == 6 and data.measured["thrust"][0] == pytest.approx(0.9)


@pytest.mark.parametrize("cell", ['"1,50"', '"0,500"', '"12,5"'])
def test_a_quoted_decimal_comma_is_not_read_as_thousands(tmp_path, cell):  # C13, C14
    path = tmp_path / "q.csv"
    lines = ["rpm,thrust (N),torque (N m)"] + [f"{r},{r * r * 1e-7:.4f},{r * r * 2e-9:.5f}"
                                               for r in range(3000, 9000, 1000)]
    lines[3] = lines[3].split(",")[0] + f",{cell}," + lines[3].split(",")[2]
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=r"is not a number \(a decimal comma\?"):
        read_loads(path)


def _semicolon(path, rows, head="rpm;thrust (g);torque (N m)"):
    path.write_text(head + "\n" + "".join(";".join(r) + "\n" for r in rows), encoding="utf-8")
    return path


def test_several_point_groups_beside_decimal_commas_are_thousands(tmp_path):  # C17 (one group only)
    rows = [(f"{3 + k}.000", f"1.{234 + k}.567,5", f"0,0{k + 1}")
            for k in range(6)]
    data = read_loads(_semicolon(tmp_path / "m.csv", rows, "rpm;thrust (mN);torque (N m)"))
    assert np.allclose(data.measured["thrust"], [1234.5675 + k * 1.0 for k in range(6)])


def test_a_point_and_decimal_comma_cell_alone_marks_the_decimal_commas(tmp_path):  # C18
    # no plain decimal comma in the file: only 1.234,5-like thrust (g) cells say that points group thousands
    rows = [(f"{r // 1000}.000", f"1.{200 + 10 * k},5", f"{100 + k}") for k, r in enumerate(range(3000, 9000, 1000))]
    data = read_loads(_semicolon(tmp_path / "p.csv", rows, "rpm;thrust (g);torque (N mm)"))
    assert np.allclose(data.omega * 30 / np.pi, np.arange(3000, 9000, 1000))


def test_thousands_beside_three_digit_numbers_are_read_beside_decimal_commas(tmp_path):  # C19
    rows = [(r, f"{k + 1},5", f"0,0{k + 1}") for k, r in enumerate(("900", "950", "1.000", "1.050", "1.100", "1.200"))]
    data = read_loads(_semicolon(tmp_path / "t.csv", rows))
    assert np.allclose(data.omega * 30 / np.pi, [900, 950, 1000, 1050, 1100, 1200])



# ---- test_gaps_sanity.py
PROP = "apce_8x6"


@pytest.mark.parametrize("fT, fQ, said", [
    (9.80665, 9.80665, "thrust in kgf and torque in kgf m read as N and N m"),
    (9.80665, 1e-3, "thrust in kgf and torque in N mm read as N and N m"),
    (9.80665e-3, 0.01, "thrust in gf and torque in N cm read as N and N m")])
def test_the_other_makers_pairs_of_units_are_named(tmp_path, fT, fQ, said):  # A1-A4
    from propmap.identify.sanity import sanity_check

    rpm = np.arange(3000.0, 9000.0, 1000.0)
    r = pm.rotor_loads(pm.load_propeller(PROP), pm.resolve_params(f"calibrated:{PROP}"), rpm * math.pi / 30, 0.0, 0.0)
    path = tmp_path / "pair.csv"
    path.write_text("rpm,thrust,torque\n" + "".join(f"{n:.0f},{t / fT:.6g},{q / fQ:.6g}\n"
                                                    for n, t, q in zip(rpm, r.thrust, r.torque)), encoding="utf-8")
    with pytest.raises(ValueError, match=f"likely {said}"):
        sanity_check(read_loads(path), pm.load_propeller(PROP))



# ---- test_bugs.py
def test_esc_jitter_does_not_hide_a_noisy_pitot():
    # 4 ESC steps x 3 airspeeds x 30 rows, +-2 us readback jitter, 0.2 m/s rms pitot
    rng = np.random.default_rng(0)
    esc = np.repeat(1200.0 + 200 * np.arange(4), 90) + rng.integers(-2, 3, 360)
    a = np.maximum(np.tile(np.repeat([0.0, 4.0, 8.0], 30), 4) + 0.2 * rng.standard_normal(360), 0.0)
    assert set(condition_tolerances({"airspeed": a}, esc)[1]) == {"airspeed"}   # HEAD: {} (holds of 1-3 rows)
    values = {"rpm": np.repeat([4000.0, 5500.0, 7000.0, 8500.0], 90), "airspeed": a}
    assert len(stand_points(values, esc, None)[1]) == 12                         # HEAD: ~70


def test_a_1_in_a_units_row_counts_as_no_unit():  # documented in units_row, unreachable: float("1") parses
    assert units_row(["rpm", "thrust", "torque", "ratio"], ["RPM", "N", "N m", "1"]) is not None  # HEAD: None


def test_a_units_row_spelling_the_names_unit_otherwise_is_no_conflict():
    header, conflicts = units_row(["Speed (rpm)", "Thrust (g)", "Torque (N m)"], ["rev/min", "gf", "N m"])
    assert conflicts == []   # HEAD: [(0, 'Speed (rpm)', 'rev/min'), (1, 'Thrust (g)', 'gf')] -> read_loads refuses


def test_trim_prints_the_flapping_warning_once(tmp_path, capsys):

    from propmap.cli.main import main
    pm.write_params(tmp_path / "f.toml", pm.resolve_params("calibrated:apce_8x6").replace(flap_compliance=50.0))
    assert main(["trim", "apce_8x6", "--thrust", "0.05", "--airspeed", "12", "--incidence-deg", "80",
                 "--params", str(tmp_path / "f.toml")]) == 0
    assert capsys.readouterr().err.count("warning: flapping") == 1   # 3a70d1d: 1; HEAD: 4


def test_a_vehicle_trim_says_its_own_flapping_not_its_searchs():
    """trim-vehicle (the example quadrotor, four APC 8x6E at 50 rad/(N m), 30 m/s) printed two
    flapping warnings from its search's trial points, at a trim whose own rotors flap less (the
    engine holds them since 2026-12-01): what it says is what its trim's wrench says."""
    import warnings

    from propmap.vehicle import trim_vehicle, vehicle_wrench

    veh = pm.read_vehicle("quadrotor")
    p = pm.resolve_params("calibrated:apce_8x6").replace(flap_compliance=50.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        t = trim_vehicle(veh, p, 30.0)
        said = [str(w.message) for w in caught if issubclass(w.category, pm.FlappingWarning)]
        vehicle_wrench(veh, p, t.velocity, np.zeros(3), t.rotor_omega)
        again = [str(w.message) for w in caught if issubclass(w.category, pm.FlappingWarning)][len(said):]
    assert said == again


# ---- a review of the change (helper, 2026-12-01): its defects, each test failing on the code before its fix

def _sampled(path, head, rows):
    path.write_text(head + "\n" + "\n".join(rows) + "\n", encoding="utf-8")
    return path


def test_a_descent_rate_at_rest_within_its_noise_is_static(tmp_path):
    """8 ESC steps of 40 rows, the descent rate at 0 or 3 m/s with 0.1 m/s rms of noise: its sign
    at rest flipped the incidence from row to row (0 / 180 deg) and the 8 steps were read as 83."""
    rng = np.random.default_rng(0)
    p, prop = pm.resolve_params("calibrated:apce_8x6"), pm.load_propeller("apce_8x6")
    rows, t = [], 0.0
    for k, rpm in enumerate(range(4000, 8000, 500)):
        down = 3.0 * (k % 2)
        r = pm.rotor_loads(prop, p, rpm * math.pi / 30, down, math.pi if down else 0.0)
        for _ in range(40):
            rows.append(f"{t:.1f},{1200 + 100 * k},{rpm},{float(r.thrust):.5g},{float(r.torque):.5g},"
                        f"{down + 0.1 * rng.standard_normal():.3f}")
            t += 0.1
    data = read_loads(_sampled(tmp_path / "d.csv", "Time (s),ESC signal (µs),rpm,Thrust (N),Torque (N·m),"
                               "Descent rate (m/s)", rows))
    assert data.n == 8
    assert np.allclose(np.degrees(data.incidence), [0, 180] * 4) and np.allclose(data.airspeed, [0, 3] * 4, atol=0.1)


@pytest.mark.parametrize("step", [1.0, 0.5])
def test_a_noisy_tunnel_sweep_at_one_throttle_keeps_its_levels(tmp_path, step):
    """One ESC hold, 8 airspeed levels ``step`` m/s apart, 60 rows each, 0.25 m/s rms of pitot noise:
    each row judged against 5 sigma alone merged them into 5 (1 m/s) or 2 (0.5 m/s) points; a level
    held over 8 rows is now told from noise."""
    rng = np.random.default_rng(0)
    p, prop = pm.resolve_params("calibrated:apce_8x6"), pm.load_propeller("apce_8x6")
    rows, t, levels = [], 0.0, 3.0 + step * np.arange(8)
    for V in levels:
        r = pm.rotor_loads(prop, p, 6000 * math.pi / 30, float(V), 0.0)
        for _ in range(60):
            rows.append(f"{t:.1f},1500,6000,{float(r.thrust):.5g},{float(r.torque):.5g},"
                        f"{V + 0.25 * rng.standard_normal():.3f}")
            t += 0.1
    data = read_loads(_sampled(tmp_path / "s.csv", "Time (s),ESC signal (µs),rpm,Thrust (N),Torque (N·m),"
                               "Airspeed (m/s)", rows), min_points=1)
    assert data.n == 8 and np.allclose(data.airspeed, levels, atol=0.15)


def test_a_units_row_that_spells_a_columns_unit_otherwise_is_read(tmp_path):
    """'sec' under 'Time (s)', '°C' under 'Temp (C)': the same units spelt otherwise were refused as
    contradicting the names; they are read. Another unit under a column propmap does not read ('mV'
    under 'Voltage (V)') is a note, not a refusal (under a read one it still is: test_audit_stop93)."""
    rows = "".join(f"{k * 0.1:.1f},{r},{r * r * 1e-7:.5g},{r * r * 2e-9:.5g},25,11.1\n"
                   for k, r in enumerate(range(3000, 9000, 1000)))
    path = tmp_path / "u.csv"
    path.write_text("Time (s),rpm,thrust,torque,Temp (C),Voltage (V)\nsec,RPM,N,N m,°C,mV\n" + rows, encoding="utf-8")
    data = read_loads(path)
    assert data.n == 6 and any("gives 'mV' for column 'Voltage (V)'" in n for n in data.notes), data.notes
    assert not any("'sec'" in n or "'°C'" in n for n in data.notes), data.notes


def test_a_level_flight_files_units_row_is_not_merged_into_its_exact_names(tmp_path):
    """A level-flight file's names are exact (airspeed, pitch_deg, rpm_1..): a units row merged into
    them read as 'lacks column(s) airspeed, pitch_deg'; it is refused naming the row, as before."""
    from propmap.identify.level_flight import read_level_flight

    path = tmp_path / "lf.csv"
    path.write_text("airspeed,pitch_deg,rpm_1,rpm_2,rpm_3,rpm_4\nm/s,deg,rpm,rpm,rpm,rpm\n"
                    "2,-3,5200,5200,5200,5200\n4,-6,5300,5300,5300,5300\n", encoding="utf-8")
    with pytest.raises(ValueError, match="a row of units under the header"):
        read_level_flight(path, pm.read_vehicle("quadrotor"))


@pytest.mark.parametrize("column, factor", [("V_descent (m/s)", 1.0), ("Sink rate (ft/min)", 0.00508),
                                            ("Rate of descent [fpm]", 0.00508)])
def test_more_names_and_units_of_a_descent_rate_are_read(tmp_path, column, factor):
    """V_descent (m/s) was refused as an airspeed to rename, and ft/min (a vertical speed's unit) as
    unknown."""
    values = np.array([0, 4, 0, 6, 0, 8]) / factor
    rows = "".join(f"{r},{v:g},{r * r * 1e-7:.5g},{r * r * 2e-9:.5g}\n"
                   for r, v in zip(range(3000, 9000, 1000), values))
    path = tmp_path / "r.csv"
    path.write_text(f"rpm,{column},thrust,torque\n" + rows, encoding="utf-8")
    data = read_loads(path)
    assert np.allclose(data.airspeed, values * factor)
    assert np.allclose(np.degrees(data.incidence), [0, 180] * 3)


def test_loads_points_warns_of_flapping_once_for_the_whole_file(tmp_path, capsys, monkeypatch):
    """`propmap loads --points` solves a file in chunks (20,000 rows): each chunk said its own flapping
    warning with its own count once the CLI's special case went; one warning counts the file's."""
    import propmap.cli.loads as cli_loads
    from propmap.cli.main import main

    monkeypatch.setattr(cli_loads, "CHUNK", 100)
    rng = np.random.default_rng(0)
    pts = tmp_path / "pts.csv"
    pts.write_text("rpm,airspeed,incidence_deg\n" + "".join(f"{a:.1f},{b:.2f},90\n" for a, b in zip(
        rng.uniform(800, 2000, 300), rng.uniform(10, 20, 300))), encoding="utf-8")
    params = tmp_path / "flap.toml"
    p = pm.resolve_params("calibrated:apce_8x6").replace(flap_compliance=50.0)
    pm.write_params(params, p)
    assert main(["loads", "apce_8x6", "--params", str(params), "--points", str(pts), "--out",
                 str(tmp_path / "out.csv")]) == 0
    err = capsys.readouterr().err
    import warnings

    from propmap.core.flapping import large_flapping

    rpm, V, _ = np.loadtxt(pts, delimiter=",", skiprows=1).T
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = pm.rotor_loads(pm.load_propeller("apce_8x6"), p, rpm * math.pi / 30, V, math.pi / 2)
    n = large_flapping(r.flap_1c, r.flap_1s)[0]
    assert n > 100 and err.count("warning: flapping: ") == 1 and f"flapping: {n} point(s)" in err, err


def test_an_unread_flow_angle_beside_a_descent_rate_is_told_the_rates_incidence(tmp_path):
    """A flow angle column beside a descent rate is refused (the rate gives axial flow only); the
    message said the points would be 'in axial flow (incidence 0)', where descending ones are at 180."""
    path = tmp_path / "a.csv"
    path.write_text("rpm,Descent rate (m/s),flow angle (deg),thrust,torque\n" + "".join(
        f"{r},{v},{a},{t},{q}\n" for r, v, a, t, q in zip((5000, 5000, 6000, 6000, 7000, 7000), (0, 2, 0, 3, 0, 4),
                                                          (0, 30) * 3, (2.6, 2.7, 3.7, 3.8, 5.0, 5.1),
                                                          (0.03,) * 6)), encoding="utf-8")
    with pytest.raises(ValueError, match=r"column 'flow angle \(deg\)' looks like a flow angle.*incidence 0 or 180 "
                                         r"deg by the rate's sign\)$"):
        read_loads(path)


def test_a_level_flight_files_point_beside_decimal_commas_is_refused_naming_its_column(tmp_path):
    """The final reread: a level-flight file (not read as a spreadsheet's) with 5.200 beside 2,5 was
    refused naming 'column 0' (the row index) for the point; it names the column."""
    from propmap.identify.level_flight import read_level_flight

    path = tmp_path / "lf.csv"
    path.write_text("airspeed;pitch_deg;rpm_1;rpm_2;rpm_3;rpm_4\n2,5;-3;5.200;5200;5200;5200\n"
                    "4;-6;5300;5300;5300;5300\n", encoding="utf-8")
    with pytest.raises(ValueError, match=r"decimal commas \(line 2, column 'airspeed'\) and points \(line 2, column "
                                         r"'rpm_1'\)"):
        read_level_flight(path, pm.read_vehicle("quadrotor"))
