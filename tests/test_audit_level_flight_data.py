"""A mutation audit of identify/level_flight.py, identify/level_flight_fit.py, identify/load_data.py and
identify/loads_air.py (2026-11-29): each test kills a hand-made mutant that survived the modules' own test files, by
the documented behaviour it changed."""

import dataclasses
import math
import types

import numpy as np
import pytest

import propmap as pm
from propmap.identify import DataError, read_loads, read_vehicle
from propmap.identify.level_flight import LevelFlightData, read_level_flight
from propmap.identify.load_data import LoadData, radians_hint

@pytest.fixture(scope="module")
def quad():
    from importlib import resources

    return read_vehicle(resources.files("propmap") / "data" / "examples" / "quadrotor.toml")


def _lf(n=6, **change):
    ok = dict(airspeed=np.linspace(0.0, 10.0, n), pitch=np.radians(np.linspace(0.0, -15.0, n)), roll=np.zeros(n),
              omega=np.full((n, 4), 1100.0), rates=np.zeros((n, 3)))
    return LevelFlightData(**{**ok, **change})


def _lf_csv(tmp_path, header, rows):
    p = tmp_path / "lf.csv"
    p.write_text(header + "\n" + "\n".join(rows) + "\n")
    return p


HEAD = "airspeed,pitch_deg,rpm_1,rpm_2,rpm_3,rpm_4"
ROWS = [f"{v},{-2.5 * v},{6000 + 100 * v:g},{6000 + 100 * v:g},{6000 + 100 * v:g},{6000 + 100 * v:g}"
        for v in (0, 2, 4, 6, 8, 10)]


def test_L2_a_pitch_or_roll_of_pi_over_2_or_more_is_refused_as_degrees():
    """L2 (|a| >= pi/2 -> |a| >= pi): a hand-built pitch or roll of 1.6 rad (above pi/2: degrees
    given as radians, or a vehicle on its side) is refused naming the field and the range."""
    with pytest.raises(ValueError, match=r"LevelFlightData.pitch must be in \(-pi/2, pi/2\) rad \(radians, not "
                                         r"degrees\), got 1.6"):
        _lf(pitch=np.array([0.0, 0.1, 0.2, 0.3, 0.4, 1.6]))
    with pytest.raises(ValueError, match=r"LevelFlightData.roll must be in \(-pi/2, pi/2\) rad"):
        _lf(roll=np.full(6, -math.pi / 2))
    assert _lf(pitch=np.full(6, 1.5)).pitch[0] == 1.5


def test_F13_F14_the_hover_model_balances_the_weight_at_the_slowest_condition_and_follows_each_rotor_axis(quad):
    """F13 (k_T at the fastest condition), F14 (R[:, :, 2] for R[:, 2, :]): the hover model's k_T
    is the model's at V = 0 at the slowest condition's rotor speed, so at a trimmed hover it gives
    the weight; its thrust acts along each rotor axis, so a vehicle whose axes are tilted by the
    attitude's inverse lifts as the upright one does unpitched."""
    from propmap.identify import simulate_level_flight
    from propmap.identify.level_flight_fit import hover_vertical_force
    from propmap.vehicle.layout import body_to_world

    params = pm.core.airfoil.preset("gill2017-apc")
    data = simulate_level_flight(quad, params, [8.0, 0.0, 12.0], [-10.0, 0.0, -15.0])
    f = hover_vertical_force(params, data, quad)
    assert f[1] == pytest.approx(quad.weight, rel=1e-6)
    # axes tilted so that at a pitch of -12 deg they point up: the upright vehicle's force at pitch 0
    pitch = math.radians(-12.0)
    up = body_to_world(np.array([pitch]), np.array([0.0]))[0][2, :]  # world z in the body frame
    tilted = dataclasses.replace(quad, rotors=tuple(dataclasses.replace(r, axis=up) for r in quad.rotors))
    om = np.full((2, 4), 1100.0)
    pitched = LevelFlightData(np.zeros(2), np.full(2, pitch), np.zeros(2), om, np.zeros((2, 3)))
    level = LevelFlightData(np.zeros(2), np.zeros(2), np.zeros(2), om, np.zeros((2, 3)))
    np.testing.assert_allclose(hover_vertical_force(params, pitched, tilted), hover_vertical_force(params, level, quad),
                               rtol=1e-9)


def test_L4_two_of_the_three_body_rates_are_refused_naming_the_missing_one(tmp_path, quad):
    """L4 (refused only with fewer than 2 of p, q, r): p and q without r is refused, the message
    naming the rate missing; all three are read."""
    rows = [r + ",0.1,0.2" for r in ROWS]
    with pytest.raises(DataError, match=r"has body-rate column\(s\) p, q but not r: give all of p, q, r or none"):
        read_level_flight(_lf_csv(tmp_path, HEAD + ",p,q", rows), quad)
    d = read_level_flight(_lf_csv(tmp_path, HEAD + ",p,q,r", [r + ",0.1,0.2,0.3" for r in ROWS]), quad)
    np.testing.assert_allclose(d.rates, np.tile([0.1, 0.2, 0.3], (6, 1)))


def test_L5_fewer_rows_than_min_conditions_are_refused_at_exactly_one_short(tmp_path, quad):
    """L5 (n < min_conditions - 1): five conditions with the default six needed is refused, naming
    both counts; six are read; min_conditions=5 reads the five."""
    with pytest.raises(DataError, match=r"lf.csv has 5 conditions; at least 6 are needed"):
        read_level_flight(_lf_csv(tmp_path, HEAD, ROWS[:5]), quad)
    assert read_level_flight(_lf_csv(tmp_path, HEAD, ROWS), quad).n == 6
    assert read_level_flight(_lf_csv(tmp_path, HEAD, ROWS[:5]), quad, min_conditions=5).n == 5


def test_L6_only_rows_identical_in_every_column_are_refused(tmp_path, quad):
    """L6 (identical judged by the airspeed alone): conditions at one airspeed but different
    pitches and rotor speeds are read; rows identical in every column are refused."""
    rows = [f"5,{-p},{6000 + 50 * p},{6000 + 50 * p},{6000 + 50 * p},{6000 + 50 * p}" for p in range(1, 7)]
    d = read_level_flight(_lf_csv(tmp_path, HEAD, rows), quad)
    assert d.n == 6 and np.all(d.airspeed == 5.0) and np.ptp(d.pitch) > 0
    with pytest.raises(DataError, match="all conditions are identical; the parameters cannot be identified"):
        read_level_flight(_lf_csv(tmp_path, HEAD, [rows[0]] * 6), quad)



def _ld(n=3, **change):
    ok = dict(omega=np.full(n, 1000.0), airspeed=np.full(n, 10.0), incidence=np.full(n, math.pi / 2),
              measured={"thrust": np.ones(n)}, group=["a"] * n)
    return LoadData(**{**ok, **change})


def test_D10_the_tip_mach_number_adds_the_in_plane_airspeed_to_the_blade_speed():
    """D10 (sin and cos of the incidence swapped): |(Omega R + V sin beta, V cos beta)| / a; at
    beta = 90 deg (edgewise) the airspeed adds to the advancing tip, at beta = 0 (axial) it is
    perpendicular to it."""
    prop, air = types.SimpleNamespace(radius=0.1), types.SimpleNamespace(speed_of_sound=340.0)
    assert _ld().tip_mach(prop, air) == pytest.approx((1000.0 * 0.1 + 10.0) / 340.0, rel=1e-12)
    assert _ld(incidence=np.zeros(3)).tip_mach(prop, air) == pytest.approx(math.hypot(100.0, 10.0) / 340.0, rel=1e-12)


def test_D11_a_subset_keeps_the_logged_air_density():
    """D11 (subset drops air_density): the points cut, source, notes and air density kept."""
    d = _ld(air_density=1.05, notes=("n",), source="s").subset([True, False, True])
    assert d.n == 2 and d.air_density == 1.05 and d.notes == ("n",) and d.source == "s"


def test_D12_D13_D14_the_radians_hint_edges():
    """D12 (one moving point enough), D13 (0.35 deg for 0.035 deg), D14 (up to 6.3 for 3.15): the
    hint needs two moving points, incidences no larger than 3.15, and every one, read as radians,
    within 0.035 deg of a whole degree."""
    deg = np.radians([10.0, 20.0, 45.0]).round(4)  # 0.1745, 0.3491, 0.7854: a tunnel's degrees in radians
    assert "incidences up to 0.7854 deg at airspeed: radians?" in radians_hint(deg, [5.0, 5.0, 5.0])
    assert radians_hint(deg, [0.0, 0.0, 5.0]) is None  # one point at airspeed
    assert radians_hint([1.0, 1.5, 2.5], [5.0] * 3) is None  # 57.30, 85.94, 143.24 deg: not whole degrees
    hi = np.radians([100.0, 200.0]).round(4)  # 1.7453, 3.4907: above 3.15
    assert radians_hint(hi, [5.0, 5.0]) is None


def _loads(tmp_path, extra_header, cells):
    rows = [f"rpm,thrust (N),{extra_header}"]
    rows += [f"{rpm},{(rpm / 3000) ** 2},{c}" for rpm, c in zip((3000, 4000, 5000, 6000, 7000, 8000), cells)]
    p = tmp_path / "loads.csv"
    p.write_text("\n".join(rows) + "\n")
    return read_loads(p)


def test_A1_A2_a_density_column_skips_absent_rows_and_refuses_a_value_below_the_range(tmp_path):
    """A1 (rows of 0 kept), A2 (no lower bound): a density column of 0 in some rows (a sensor
    absent) is the median of the others; a density below 0.05 kg/m^3 is refused naming the column
    and the range."""
    d = _loads(tmp_path, "air density", [0, 1.1, 1.2, 0, 1.2, 1.3])
    assert d.air_density == pytest.approx(1.2, rel=1e-12)
    with pytest.raises(DataError, match=r"'air density' gives 0.01 kg/m\^3; an air density must be in \[0.05, 5\]"):
        _loads(tmp_path, "air density", [0.01, 1.1, 1.2, 1.2, 1.2, 1.3])


def test_A5_A11_temperature_and_pressure_in_kpa_and_after_an_underscore_give_the_isa_density(tmp_path):
    """A5 (kPa read as 100 Pa), A11 (a unit after '_' only for temperatures): 15 degC at 101.325 kPa
    or 1013.25 hPa is the ISA sea level, rho = p / (R T) = 1.225 kg/m^3."""
    for header, cells in (("temperature (C),pressure (kPa)", "15,101.325"), ("temperature_c,baro_hpa", "15,1013.25")):
        d = _loads(tmp_path, header, [cells] * 6)
        assert d.air_density == pytest.approx(1.225, rel=2e-3), (header, d.notes)


def test_A10_a_density_outside_the_plausible_range_is_used_and_said_to_be_checked(tmp_path):
    """A10 (no check said): 15 degC at 600 hPa gives 0.726 kg/m^3, within AIR_DENSITY_RANGE but
    outside PLAUSIBLE_DENSITY (0.85-1.4): it is used, and the note says to check the columns."""
    d = _loads(tmp_path, "temperature (C),pressure (hPa)", ["15,600"] * 6)
    assert d.air_density == pytest.approx(60000 / (287.05 * 288.15), rel=2e-5)
    assert any("outside the 0.85-1.4 kg/m^3 of air near the ground: check" in n for n in d.notes), d.notes
    d = _loads(tmp_path, "temperature (C),pressure (hPa)", ["15,1013.25"] * 6)
    assert not any("check that" in n for n in d.notes), d.notes


def test_D1_a_load_point_at_zero_rotor_speed_is_refused_naming_the_field():
    """D1 (omega < 0 refused, 0 let through): a hand-built point at Omega = 0 is refused, naming
    LoadData.omega and the range."""
    with pytest.raises(ValueError, match=r"LoadData.omega must be > 0 rad/s, got 0"):
        _ld(omega=np.array([1000.0, 0.0, 1000.0]))


def test_D2_an_air_density_of_zero_is_refused():
    """D2 (rho >= 0 accepted): an air density of 0 kg/m^3 is no air; refused naming the field."""
    with pytest.raises(ValueError, match=r"LoadData.air_density must be a finite number > 0 kg/m\^3 or None, got 0.0"):
        _ld(air_density=0.0)
    assert _ld(air_density=1e-3).air_density == 1e-3


def test_D3_a_boolean_air_density_is_refused():
    """D3 (the bool check dropped): True is no density (it would read as 1 kg/m^3)."""
    with pytest.raises(ValueError, match=r"LoadData.air_density must be a finite number > 0 kg/m\^3 or None, got True"):
        _ld(air_density=True)


def test_D4_a_negative_airspeed_is_refused_as_a_descent_by_incidence():
    """D4 (airspeed < 0 let through): a negative airspeed is refused, naming the field and saying a
    descent is an incidence above 90 deg."""
    with pytest.raises(ValueError, match=r"LoadData.airspeed must be >= 0 m/s \(a descent is an incidence above 90"):
        _ld(airspeed=np.array([10.0, -1.0, 10.0]))


def test_F10_F11_F15_the_body_lift_verdict_is_the_nested_f_test_of_its_three_terms(quad):
    """F10 (p < 0.5 selects body lift), F11 (F divides by 2 terms), F15 (max_abs_over_weight per
    kg): synthetic data without body lift (gill2017-apc, M = 30, 20 speeds 0-14 m/s, 0.5% rpm and
    0.3 deg pitch noise, seed 5): F = ((rss0 - rss1) / 3) / (rss1 / (N - 7)), p its F(3, N - 7)
    tail, here 0.11: above 0.05, so body lift does not matter and the fit without it is selected."""
    from scipy import stats

    from propmap.identify import FitOptions, fit_level_flight, simulate_level_flight

    V = np.linspace(0, 14, 20)
    d = simulate_level_flight(quad, pm.preset("gill2017-apc").replace(M=30.0), V, -2.5 * V)
    rng = np.random.default_rng(5)
    d = dataclasses.replace(d, omega=d.omega * (1 + 0.005 * rng.standard_normal(d.omega.shape)),
                            pitch=d.pitch + np.radians(0.3) * rng.standard_normal(d.n))
    r = fit_level_flight(d, quad, options=FitOptions(M=30.0, body_lift=True))
    bl = r.extra["body_lift"]
    rss1, rss0, dof = 20 * bl["rms_residual_with"] ** 2, 20 * bl["rms_residual_without"] ** 2, 20 - 7
    assert bl["F"] == pytest.approx((rss0 - rss1) / 3 / (rss1 / dof), rel=1e-9)
    assert bl["p_value"] == pytest.approx(stats.f.sf(bl["F"], 3, dof), rel=1e-9)
    assert 0.05 < bl["p_value"] < 0.5 and not bl["matters"] and bl["selected"] == "without"
    assert r.names == ("cl1", "cl2", "cd", "alpha0")
    assert bl["max_abs_over_weight"] == pytest.approx(bl["max_abs_N"] / (0.8 * 9.81), rel=1e-12)


def test_D5_an_incidence_beyond_pi_is_refused_as_degrees():
    """D5 (refused only beyond 2 pi): an incidence of 3.5 rad (above pi: degrees?) is refused; pi
    itself (a descent along the axis) and single precision's pi are read as pi."""
    with pytest.raises(ValueError, match=r"LoadData.incidence must be in \[0, pi\] rad \(radians, not degrees\)"):
        _ld(incidence=np.array([0.0, 1.0, 3.5]))
    d = _ld(incidence=np.array([0.0, np.pi, float(np.float32(np.pi))]))
    assert d.incidence[1] == d.incidence[2] == np.pi


def test_L13_a_rate_column_beside_p_q_r_is_left_unread(tmp_path, quad):
    """L13 (a rate column not mapped to the body rates): 'pitch_rate (deg/s)' beside p, q, r (the
    body rates already there) is not read and not refused; without p, q, r it is refused, saying
    to give it as p, q, r [rad/s]."""
    rows = [r + ",0.1,0.2,0.3,5" for r in ROWS]
    d = read_level_flight(_lf_csv(tmp_path, HEAD + ",p,q,r,pitch_rate (deg/s)", rows), quad)
    np.testing.assert_allclose(d.rates[:, 1], 0.2)
    with pytest.raises(DataError, match=r"column 'pitch_rate \(deg/s\)' is not read: .* give this one as p, q, r "
                                        r"\[rad/s\]"):
        read_level_flight(_lf_csv(tmp_path, HEAD + ",pitch_rate (deg/s)", [r + ",5" for r in ROWS]), quad)


def test_L14_rotor_columns_are_ordered_by_number_past_rpm_9(tmp_path, quad):
    """L14 (rotor columns sorted as text: rpm_10 before rpm_2): a twelve-rotor vehicle's
    rpm_1 .. rpm_12 are read in the rotors' order, each column to its rotor."""
    rotors = tuple(dataclasses.replace(r, position=r.position * (1 + k)) for k in range(3) for r in quad.rotors)
    twelve = dataclasses.replace(quad, rotors=rotors)
    head = "airspeed,pitch_deg," + ",".join(f"rpm_{k}" for k in range(1, 13))
    rows = [f"{v},{-2.5 * v}," + ",".join(f"{5000 + 10 * k + v:g}" for k in range(1, 13)) for v in range(6)]
    d = read_level_flight(_lf_csv(tmp_path, head, rows), twelve)
    np.testing.assert_allclose(d.omega[0] * 30 / np.pi, 5000 + 10 * np.arange(1, 13), rtol=1e-12)


def test_D6_a_measured_quantity_other_than_thrust_drag_torque_is_refused():
    """D6 (any key accepted): 'lift' is not a load the fits know; refused naming it and the valid."""
    with pytest.raises(ValueError, match=r"LoadData.measured: unknown quantity 'lift' \(valid: thrust, drag, torque, "
                                         r"rolling_moment\)"):
        _ld(measured={"thrust": np.ones(3), "lift": np.ones(3)})


def test_D8_a_collective_beyond_45_degrees_is_refused_as_degrees():
    """D8 (refused only beyond 90 deg): a collective of 1.0 rad (57 deg) is refused, naming the
    field and the range +-0.785398 rad; 0.7 rad is read."""
    with pytest.raises(ValueError, match=r"LoadData.collective must be in \[-0.785398, 0.785398\] rad \(radians, not"):
        _ld(collective=np.array([0.0, 0.1, 1.0]))
    assert _ld(collective=np.array([0.0, -0.7, 0.7])).collective[2] == 0.7


def test_F7_as_many_conditions_as_parameters_are_refused(quad):
    """F7 (N = number of parameters let through): four conditions cannot identify the four
    section parameters (no residual degree of freedom); refused with both counts."""
    from propmap.identify import fit_level_flight

    with pytest.raises(ValueError, match=r"4 conditions cannot identify 4 parameters; need at least 5"):
        fit_level_flight(_lf(n=4), quad)


def test_F9_body_lift_in_the_data_is_recovered_with_its_sign(quad):
    """F9 (body lift subtracted from the rotors' vertical force): synthetic conditions where the
    body carries part of the weight (the rotors trimmed to W - L at each condition, L the body lift
    of cl1_body = 2, cl2_body = 1, alpha0_body = 15 deg, M = 30): the fit with body lift finds that
    it matters and recovers the body lift L with its sign."""
    from propmap.identify import FitOptions, fit_level_flight, simulate_level_flight
    from propmap.identify.level_flight_fit import body_lift

    true = pm.preset("gill2017-apc").replace(M=30.0)
    V = np.linspace(0, 14, 12)
    pitch = -2.5 * V
    xb = (2.0, 1.0, math.radians(15.0))
    probe = LevelFlightData(V, np.radians(pitch), np.zeros(12), np.full((12, 4), 1000.0), np.zeros((12, 3)))
    L = body_lift(xb, probe, quad, 30.0, true.air)
    parts = [simulate_level_flight(dataclasses.replace(quad, mass=(quad.weight - L[j]) / quad.gravity), true,
                                   V[j:j + 1], pitch[j:j + 1]) for j in range(12)]
    d = dataclasses.replace(probe, omega=np.concatenate([p.omega for p in parts]))
    r = fit_level_flight(d, quad, options=FitOptions(M=30.0, body_lift=True))
    bl = r.extra["body_lift"]
    assert bl["matters"] and bl["selected"] == "with"
    b = bl["body_terms"]
    fitted = body_lift((b["cl1_body"], b["cl2_body"], math.radians(b["alpha0_body_deg"])), d, quad, 30.0, true.air)
    # (the body terms trade off against the section parameters: the fitted body lift is within 30%, its sign the
    # data's: a downforce of up to 1.1 N at the nose-down pitches)
    assert np.all(L[1:] < 0) and np.all(fitted[1:] < 0)
    np.testing.assert_allclose(fitted, L, rtol=0.3, atol=0.01)


def test_F6_body_lift_without_a_body_area_is_refused(quad):
    """F6 (body_area 0 let through): body lift needs S_body > 0; a vehicle without one is refused
    before any fit, naming body_area."""
    from propmap.identify import FitOptions, fit_level_flight

    with pytest.raises(ValueError, match=r"body_lift needs the vehicle's body_area > 0 m\^2"):
        fit_level_flight(_lf(n=12), dataclasses.replace(quad, body_area=0.0), options=FitOptions(body_lift=True))


def test_A9_temperature_and_pressure_giving_a_density_below_the_range_are_not_read(tmp_path):
    """A9 (the density range not applied to temperature and pressure): 25 degC at 2000 Pa gives
    0.023 kg/m^3, below AIR_DENSITY_RANGE (0.05-5): not used, and a note says why (never a
    refusal)."""
    d = _loads(tmp_path, "temperature (C),pressure (Pa)", ["25,2000"] * 6)
    assert d.air_density is None
    assert any("they would give an air density of 0.02337 kg/m^3" in n and "are not read" in n for n in d.notes)


def test_F16_the_body_lift_fits_jacobian_carries_the_blends_m_with_its_sign(quad, monkeypatch):
    """F16 (the body lift's dL/dM added to the M column with the wrong sign): with body lift and M fitted, the
    residual's implicit Jacobian (the rotors' implicit derivatives, the body terms' closed form) equals central
    differences of the residual, the M column included; the standard errors and correlations of M come from it."""
    from propmap.identify import FitOptions, fit_level_flight
    from propmap.identify import level_flight_fit as lff

    caught = []
    real = lff._attach_jacobian

    def catch(residual, with_jacobian):
        caught.append(residual)
        return real(residual, with_jacobian)

    monkeypatch.setattr(lff, "_attach_jacobian", catch)
    V = np.linspace(0.0, 12.0, 10)
    d = _lf(n=10, airspeed=V, pitch=np.radians(-2.5 * V), omega=np.full((10, 4), 1000.0) + 8.0 * V[:, None])
    names = ("cl_alpha", "alpha_L0", "cd_min", "M")  # (M is a cambered-section parameter)
    fit_level_flight(d, quad, base=pm.generic_params(), options=FitOptions(body_lift=True, max_nfev=1, prior=False,
                                                                            names=names))
    g = pm.generic_params()
    x = np.array([g.cl_alpha, g.alpha_L0, g.cd_min, 20.0, 1.5, 0.8, math.radians(10.0)])  # (body terms felt)
    # (the fit with body lift takes seven parameters; the F-test's fit without it, four)
    residual = None
    for f in caught:
        try:
            out = f.with_jacobian(x)
        except (IndexError, ValueError):
            continue
        if out[1].shape == (10, 7):
            residual, (res, jac) = f, out
    assert residual is not None
    np.testing.assert_allclose(res, residual(x), rtol=1e-12, atol=1e-12)
    k = 3  # M
    h = 1e-4 * x[k]
    hi, lo = x.copy(), x.copy()
    hi[k] += h
    lo[k] -= h
    fd = (residual(hi) - residual(lo)) / (2 * h)
    assert np.max(np.abs(fd)) > 1e-6  # (the data feel M)
    # (measured 2026-11-29: 5.5e-5 relative at most; the sign error 1.4e-2)
    np.testing.assert_allclose(jac[:, k], fd, rtol=1e-3, atol=1e-4 * np.max(np.abs(fd)))
