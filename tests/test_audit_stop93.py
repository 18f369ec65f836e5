"""Load files read the wrong way, found at stop 93 (2026-12-01) among what stop 92 left alone. Each
test fails on the code before its fix; the guards say so. Data: loads made by propmap's model for
the catalogue's APC 8x6E (UIUC geometry) with its calibrated set, so that the right reading matches
the model to the noise."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.identify import read_loads
from propmap.identify.steps import CONDITION_TOL, condition_tolerances

PROP = "apce_8x6"


def _tunnel_log(path, sigma, seed=0):
    """A stand log through a tunnel's speeds, its pitot read with ``sigma`` m/s rms of noise (clipped
    at 0 at rest, as a pitot's reading is): 4 ESC steps x 3 airspeeds (0, 4, 8 m/s), 30 rows each."""
    rng = np.random.default_rng(seed)
    p, prop = pm.resolve_params(f"calibrated:{PROP}"), pm.load_propeller(PROP)
    rows, t = [], 0.0
    for esc, rpm in zip(range(1200, 2000, 200), (4000, 5500, 7000, 8500)):
        for V in (0.0, 4.0, 8.0):
            r = pm.rotor_loads(prop, p, rpm * math.pi / 30, V, 0.0)
            for _ in range(30):
                a = max(V + sigma * rng.standard_normal(), 0.0)
                rows.append(f"{t:.1f},{esc},{float(r.thrust):.5g},{float(r.torque):.5g},{rpm},{a:.3f}")
                t += 0.1
    head = "Time (s),ESC signal (µs),Thrust (N),Torque (N·m),Motor Optical Speed (RPM),Airspeed (m/s)\n"
    path.write_text(head + "\n".join(rows) + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("sigma", [0.1, 0.2, 0.4])
def test_a_noisy_pitot_does_not_split_a_tunnel_steps(tmp_path, sigma):
    """A pitot's noise of 0.2 m/s rms (its dynamic pressure is a few pascals at 4 m/s) split the 12
    steps of a tunnel log into 62 points (14 at 0.1 m/s, 160 at 0.4), each fragment a point; the
    tolerance now grows with the column's noise (5 times it), and a note says so."""
    data = read_loads(_tunnel_log(tmp_path / "log.csv", sigma))
    assert data.n == 12, data.notes
    assert np.allclose(np.sort(data.airspeed), np.repeat([0.0, 4.0, 8.0], 4), atol=0.25)
    assert any(n.startswith("airspeed is noisy (") for n in data.notes), data.notes


def test_a_noisy_pitot_at_one_speed_keeps_the_ramps_between_steps_out(tmp_path):
    """One airspeed (5 m/s, 0.3 m/s rms) through 14 ESC steps with a 4-row ramp between each: 176
    points before (every noisy row a step, the ramps' rows too); 14 now, the ramps dropped."""
    rng = np.random.default_rng(3)
    p, prop = pm.resolve_params(f"calibrated:{PROP}"), pm.load_propeller(PROP)
    rows, t = [], 0.0
    for k, (esc, rpm) in enumerate(zip(range(1200, 1900, 50), range(3000, 10000, 500))):
        ramp = [(esc - 50 + 10 * j, rpm - 500 + 100 * j, 0.0, 0.0) for j in range(1, 5)] if k else []
        r = pm.rotor_loads(prop, p, rpm * math.pi / 30, 5.0, 0.0)
        for e, n, T, Q in ramp + [(esc, rpm, float(r.thrust), float(r.torque))] * 20:
            rows.append(f"{t:.1f},{e},{n},{T:.5g},{Q:.5g},{5 + 0.3 * rng.standard_normal():.3f}")
            t += 0.1
    path = tmp_path / "ramps.csv"
    path.write_text("Time (s),ESC signal (µs),rpm,Thrust (N),Torque (N·m),Airspeed (m/s)\n" + "\n".join(rows) + "\n",
                    encoding="utf-8")
    data = read_loads(path)
    assert data.n == 14 and np.allclose(data.omega * 30 / math.pi, range(3000, 10000, 500))
    assert np.allclose(data.airspeed, 5.0, atol=0.25)


def test_a_quiet_pitot_and_a_tables_levels_keep_the_fixed_tolerance():
    """Guards (pass before the fix too): noise of 0.03 m/s rms is below the fixed 0.3 m/s over 5,
    and the levels of a table (one row each, or a tunnel's short steps at one signal) are not noise."""
    rng = np.random.default_rng(1)
    quiet = np.repeat([0.0, 4.0, 8.0], 30) + 0.03 * rng.standard_normal(90)
    assert condition_tolerances({"airspeed": quiet}, np.full(90, 1500.0))[1] == {}
    for levels in (np.tile([0.0, 5.0, 10.0], 10), np.repeat(np.arange(0.0, 22.0, 2.0), 2),
                   np.arange(0.0, 20.0, 0.5)):
        tol, noisy = condition_tolerances({"airspeed": levels}, np.full(levels.size, 1500.0))
        assert noisy == {} and tol == {"airspeed": CONDITION_TOL["airspeed"]}, levels


def _stand_table(units_row, header="rpm,thrust,torque", scale=(1.0, 1.0)):
    """The APC 8x6E's static loads at 3000-8000 rpm under ``header`` and a row of units."""
    rpm = np.arange(3000.0, 9000.0, 1000.0)
    T, _, Q = _loads(rpm)
    rows = "".join(f"{r:.0f},{t * scale[0]:.6g},{q * scale[1]:.6g}\n" for r, t, q in zip(rpm, T, Q))
    return f"{header}\n{units_row}\n{rows}", T, Q


def _loads(rpm):
    p = pm.resolve_params(f"calibrated:{PROP}")
    r = pm.rotor_loads(pm.load_propeller(PROP), p, np.asarray(rpm) * math.pi / 30, 0.0, 0.0)
    return r.thrust, r.drag, r.torque


@pytest.mark.parametrize("units, scale", [("RPM,N,N·m", (1.0, 1.0)), ("[rev/min],[g],[N·mm]", (1000 / 9.80665, 1000.0)),
                                          ("(1/min), (kgf) , (kgf·cm)", (1 / 9.80665, 100 / 9.80665))])
def test_a_row_of_units_under_the_header_gives_the_columns_units(tmp_path, units, scale):
    """A data logger's row of units under the header (a thrust-stand data audit, 2026-11-30) was
    refused as 'not a number'; it is read as the columns' units, converted, with a note."""
    text, T, Q = _stand_table(units, scale=scale)
    path = tmp_path / "u.csv"
    path.write_text(text, encoding="utf-8")
    data = read_loads(path)
    assert np.allclose(data.measured["thrust"], T, rtol=1e-5) and np.allclose(data.measured["torque"], Q, rtol=1e-5)
    assert any("line 2 read as the columns' units (" in n for n in data.notes), data.notes


def test_a_units_row_repeating_the_names_units_is_skipped_and_a_contradicting_one_refused(tmp_path):
    text, T, _ = _stand_table("rpm,N,N m", header="Speed (rpm),Thrust (N),Torque (N·m)")
    path = tmp_path / "u.csv"
    path.write_text(text, encoding="utf-8")
    data = read_loads(path)
    assert np.allclose(data.measured["thrust"], T, rtol=1e-5)
    assert any("line 2 repeats the units the columns' names give" in n for n in data.notes), data.notes
    path.write_text(text.replace("rpm,N,N m", "rpm,kgf,N m"), encoding="utf-8")
    with pytest.raises(ValueError, match=r"line 2: the row of units under the header gives 'kgf' for column "
                                         r"'Thrust \(N\)', whose name gives another unit"):
        read_loads(path)


def test_a_first_row_of_text_and_numbers_is_no_units_row(tmp_path):
    """Guard (passes before too): a label column's text beside numbers is a data row."""
    text, T, _ = _stand_table("", header="prop,rpm,thrust (N),torque (N m)")
    lines = text.split("\n")
    body = "\n".join(["prop,rpm,thrust (N),torque (N m)"] + [f"APC 8x6E,{ln}" for ln in lines[2:] if ln]) + "\n"
    path = tmp_path / "t.csv"
    path.write_text(body, encoding="utf-8")
    data = read_loads(path)
    assert data.n == 6 and not any("units" in n for n in data.notes)


def _table(rows, sep=",", head="rpm,thrust (g),torque (N m)"):
    return head.replace(",", sep) + "\n" + "".join(sep.join(r) + "\n" for r in rows)


def _static_rows():
    rpm = np.arange(3000.0, 9000.0, 1000.0)
    T, _, Q = _loads(rpm)
    return rpm, T * 1000 / 9.80665, Q


def test_quoted_thousands_in_a_comma_separated_file_are_read(tmp_path):
    """A spreadsheet's comma-separated save of numbers formatted with thousands separators quotes
    them, "3,000"; refused as 'not a number' until 2026-12-01, now read, with a note. A quoted
    decimal comma, "0,5", is still refused, and told so."""
    rpm, T_g, Q = _static_rows()
    rows = [(f'"{r:,.0f}"', f'"{t:,.1f}"', f"{q:.5f}") for r, t, q in zip(rpm, T_g, Q)]
    path = tmp_path / "q.csv"
    path.write_text(_table(rows), encoding="utf-8")
    data = read_loads(path)
    assert np.allclose(data.omega * 30 / math.pi, rpm)
    assert np.allclose(data.measured["thrust"], np.round(T_g, 1) * 9.80665e-3, rtol=1e-9)
    assert any("commas read as thousands separators (line 2: 3,000 read as 3000)" in n for n in data.notes)
    rows[2] = (rows[2][0], '"0,5"', rows[2][2])
    path.write_text(_table(rows), encoding="utf-8")
    with pytest.raises(ValueError, match=r"'0,5' is not a number \(a decimal comma\? a comma-separated file"):
        read_loads(path)


def test_points_grouping_thousands_beside_decimal_commas_are_read(tmp_path):
    """A German spreadsheet's ';' file with its rpm as 3.000 and its loads with decimal commas was
    refused ("decimal commas and points in one file"); beside decimal commas such a point is a
    thousands separator, and is read as one, with a note (1.234,5 too). A point that groups no
    thousands beside decimal commas is still refused."""
    rpm, T_g, Q = _static_rows()
    rows = [(f"{r:,.0f}".replace(",", "."), f"{t:.1f}".replace(".", ","), f"{q:.5f}".replace(".", ","))
            for r, t, q in zip(rpm, T_g, Q)]
    rows[-1] = ("8.000,0", *rows[-1][1:])
    path = tmp_path / "de.csv"
    path.write_text(_table(rows, ";"), encoding="utf-8")
    data = read_loads(path)
    assert np.allclose(data.omega * 30 / math.pi, rpm)
    assert any("points read as thousands separators beside the file's decimal commas (column 'rpm', line 2: 3.000 "
               "read as 3000)" in n for n in data.notes), data.notes
    rows[0] = ("3000.5", *rows[0][1:])
    path.write_text(_table(rows, ";"), encoding="utf-8")
    with pytest.raises(ValueError, match="decimal commas .* and points .* in one file"):
        read_loads(path)


def test_a_flight_fits_trial_points_do_not_warn_of_flapping_its_optimum_does_once():
    """The flight fit, too, silences the model's FlappingWarning at its trial parameter sets and
    says it once at its optimum (a synthetic log of the example quadrotor, four APC 8x6E, at 100-160
    rad/s and up to 15 m/s in the disk planes, so that its blades flap beyond 0.25 rad)."""
    import warnings
    from pathlib import Path

    from propmap.core.solver import Discretization
    from propmap.identify import FitOptions
    from propmap.identify.flight import FlightSamples, fit_flight, predict_flight

    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    rng, n, coarse = np.random.default_rng(3), 30, Discretization(12, 8)
    s = FlightSamples(log_names=("synthetic",), log_index=np.zeros(n, int), t=np.arange(n) * 0.1,
                      velocity=rng.uniform(-15, 15, (n, 3)) * [1, 1, 0.1], angular_velocity=np.zeros((n, 3)),
                      rotor_omega=rng.uniform(100, 160, (n, 4)), rotor_acceleration=np.zeros((n, 4)),
                      force=np.zeros((n, 3)), moment=None, reference_force=None, reference_moment=None, rate_hz=10.0)
    truth = pm.generic_params().replace(flap_compliance=40.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pm.FlappingWarning)
        s = s.__class__(**{**s.__dict__, "force": predict_flight(s, veh, truth, discretization=coarse).force})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = fit_flight(s, veh, base=pm.generic_params().replace(flap_compliance=5.0),
                         options=FitOptions(names=("flap_compliance",), prior=False), discretization=coarse)
    said = [str(w.message) for w in caught if issubclass(w.category, pm.FlappingWarning)]
    assert res.params.flap_compliance == pytest.approx(40.0, rel=1e-4)
    assert len(said) == 1 and "flap_compliance 40 rad/(N m)" in said[0], said


@pytest.mark.parametrize("fT, fQ, said", [
    (9.80665, 0.0980665, "thrust in kgf and torque in kgf cm read as N and N m"),
    (9.80665e-3, 9.80665e-5, "thrust in gf and torque in gf cm read as N and N m"),
    (9.80665e-3, 1e-3, "thrust in gf and torque in N mm read as N and N m"),
    (0.27801385095378125, 0.00706155181, "thrust in ozf and torque in ozf in read as N and N m")])
def test_a_makers_pair_of_units_unlabelled_is_named_as_the_pair(tmp_path, fT, fQ, said):
    """Thrust and torque in a maker's pair of units, both columns unlabelled (read as N and N m): kgf
    with kgf cm was refused as "the thrust and torque columns swapped", gf with gf cm as "a diameter
    far off" (a thrust-stand data audit, 2026-11-30); each pair is now named."""
    from propmap.identify.sanity import sanity_check

    rpm = np.arange(3000.0, 9000.0, 1000.0)
    T, _, Q = _loads(rpm)
    path = tmp_path / "pair.csv"
    path.write_text("rpm,thrust,torque\n" + "".join(f"{r:.0f},{t / fT:.6g},{q / fQ:.6g}\n"
                                                    for r, t, q in zip(rpm, T, Q)), encoding="utf-8")
    with pytest.raises(ValueError, match=f"likely {said}"):
        sanity_check(read_loads(path), pm.load_propeller(PROP))


@pytest.mark.parametrize("made_with", ["calibrated", "generic"])
def test_slow_descent_data_without_an_incidence_column_are_warned_of(tmp_path, made_with):
    """Axial descent at 1-6 m/s (4000-7000 rpm), written without an incidence column, is read as
    climb: its thrust rises with the airspeed where a climb's falls, yet it misfits the climb by
    only 0.07 of the largest thrust (below the 0.1 from which the airspeed's unit was judged), so
    it was validated at 8.7% and fitted without a word (stop 92 left the data made with the
    calibrated set told 'km/h' where refused); now warned of as descent."""
    import warnings

    from propmap.identify.sanity import sanity_check

    p = pm.resolve_params(f"calibrated:{PROP}") if made_with == "calibrated" else pm.generic_params()
    prop, rows = pm.load_propeller(PROP), []
    for rpm in (4000, 5000, 6000, 7000):
        for V in range(7):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                r = pm.rotor_loads(prop, p, rpm * math.pi / 30, float(V), math.pi)
            rows.append(f"{rpm},{V},{float(r.thrust):.5g},{float(r.torque):.5g}\n")
    path = tmp_path / "descent.csv"
    path.write_text("rpm,airspeed (m/s),thrust (N),torque (N m)\n" + "".join(rows), encoding="utf-8")
    said = sanity_check(read_loads(path), prop)
    assert any("matches the model far better in axial descent" in w for w in said), said


@pytest.mark.parametrize("column, sign", [("Descent rate (m/s)", 1.0), ("descent_velocity_m_s", 1.0),
                                          ("V_descent_mps", 1.0), ("sink rate (km/h)", 1.0),
                                          ("Rate of climb (m/s)", -1.0)])
def test_an_axial_descent_or_climb_rate_column_is_read_as_the_flow(tmp_path, column, sign):
    """Rotors in descent are measured against a descent rate; such a column was refused, to be
    rewritten as an airspeed and an incidence. A descent rate (positive descending) or a climb rate
    (positive climbing) is now read: its magnitude the airspeed, incidence 180 deg descending and 0
    climbing, with a note. The loads made by the model at those points validate to 0."""
    import warnings

    p, prop = pm.resolve_params(f"calibrated:{PROP}"), pm.load_propeller(PROP)
    kmh = 3.6 if "km/h" in column else 1.0
    rows, truth = [], []
    for rpm in (4000, 6000):
        for down in (-2.0, 0.0, 1.0, 3.0, 5.0):  # descending positive
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                r = pm.rotor_loads(prop, p, rpm * math.pi / 30, abs(down), math.pi if down > 0 else 0.0)
            rows.append(f"{rpm},{sign * down * kmh:g},{float(r.thrust):.6g},{float(r.torque):.6g}\n")
            truth.append((abs(down), 180.0 if down > 0 else 0.0, float(r.thrust)))
    path = tmp_path / "descent.csv"
    path.write_text(f"rpm,{column},thrust (N),torque (N m)\n" + "".join(rows), encoding="utf-8")
    data = read_loads(path)
    V, inc, T = np.array(truth).T
    assert np.allclose(data.airspeed, V, atol=1e-9) and np.allclose(np.degrees(data.incidence), inc)
    assert np.allclose(data.measured["thrust"], T, rtol=1e-5)
    assert any(f"{column!r} read as the airspeed in axial flow: 6 row(s) descending" in n for n in data.notes)


def test_a_rate_beside_the_airspeed_and_the_incidence_is_not_read_and_vz_is_still_refused(tmp_path):
    """Guards: with the airspeed and the incidence the flow is theirs (a note); Vz, V_c and a vertical
    speed, whose sign convention a name does not say, are still refused."""
    T, _, Q = _loads(np.array([4000.0, 5000.0, 6000.0, 7000.0, 8000.0, 9000.0]))
    body = "".join(f"{r},0,0,0,{t:.5g},{q:.5g}\n" for r, t, q in zip(range(4000, 10000, 1000), T, Q))
    path = tmp_path / "both.csv"
    path.write_text("rpm,airspeed,incidence_deg,descent rate,thrust,torque\n" + body, encoding="utf-8")
    assert any("(a descent rate) is not read: the airspeed and the incidence give the flow" in n
               for n in read_loads(path).notes)
    for name in ("Vz", "V_c", "vertical speed"):
        path.write_text(f"rpm,{name},thrust,torque\n" + "".join(
            f"{r},0,{t:.5g},{q:.5g}\n" for r, t, q in zip(range(4000, 10000, 1000), T, Q)), encoding="utf-8")
        with pytest.raises(ValueError, match="looks like a climb or descent rate"):
            read_loads(path)


def test_quoted_decimal_commas_with_three_decimals_read_as_thousands_are_named_when_refused(tmp_path):
    """A quoted decimal comma with three decimals, "1,734", reads as thousands (in a comma-separated
    file no other reading tells it from 1734); the thrust then is a thousand times the model's, and
    the refusal said only "check the units": it names the decimal commas now."""
    from propmap.identify.sanity import sanity_check

    rpm = np.arange(5000.0, 11000.0, 1000.0)
    T, _, Q = _loads(rpm)
    assert np.all((T >= 1.0) & (T < 10.0))  # (each "d,ddd": the form read as thousands)
    path = tmp_path / "dec.csv"
    path.write_text("rpm,thrust (N),torque (N m)\n" + "".join(
        f'{r:.0f},"{t:.3f}",{q:.5f}\n'.replace(f'"{t:.3f}"', '"' + f"{t:.3f}".replace(".", ",") + '"')
        for r, t, q in zip(rpm, T, Q)), encoding="utf-8")
    data = read_loads(path)
    assert np.allclose(data.measured["thrust"], np.round(T, 3) * 1000)
    with pytest.raises(ValueError, match="likely decimal commas read as thousands separators"):
        sanity_check(data, pm.load_propeller(PROP))
