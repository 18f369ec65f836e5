"""A mutation audit of cli/_coverage.py (the warnings of a run beyond the data behind its parameters),
cli/_air.py (the air options and their refusals) and core/_frame.py (the disk frame and the load vectors):
each test names the mutant it kills."""

from __future__ import annotations

import math

import numpy as np
import pytest

import propmap as pm
from cli_helpers import one_line_error, run
from propmap.cli._air import AirChoice, air_label, resolve_air
from propmap.cli._common import InputError
from propmap.cli._coverage import coverage_messages, envelope_extremes
from propmap.core.units import RPM
from propmap.io.params_file import write_params

AIR = pm.Air(rho=1.225, mu=1.983e-05, speed_of_sound=340.3)


def _fitted(tmp_path, **coverage):
    """apce_8x6's set in a parameter file whose [coverage] table is ``coverage``: its path, as a label."""
    f = tmp_path / "fitted.toml"
    write_params(f, pm.default_params("apce_8x6"), coverage=coverage)
    return str(f)


def _warnings(capsys, prop, label, *, J=0.0, incidence_deg=0.0, rpm=None, airspeed=None, air=AIR, tip_speed=100.0):
    """The warning lines coverage_messages prints for one run's extremes."""
    capsys.readouterr()
    coverage_messages(prop, label, air, tip_speed, J, incidence_deg, rpm=rpm, airspeed=airspeed)
    return [line for line in capsys.readouterr().err.splitlines() if line.startswith("propmap: warning:")]


# ---------------------------------------------------------------- cli/_coverage.py


def test_the_tip_mach_number_is_warned_of_from_0_7(capsys):
    """Mutant C1: the tip Mach threshold 0.7 raised to 0.8 (24000 rpm on the 8x6, tip Mach 0.750, unsaid)."""
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "24000")
    assert code == 0, err
    assert "tip Mach number up to 0.75 (> 0.7): compressibility beyond Prandtl-Glauert is not modelled" in err


def test_the_tip_mach_number_is_in_the_runs_own_speed_of_sound(capsys):
    """Mutant C2: the tip Mach number over a fixed 343 m/s, not the run's air (at -50 degC, 299.5 m/s, the tip
    at 20000 rpm, 212.8 m/s, is Mach 0.71: warned; over 343 m/s it is 0.62)."""
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "20000", "--temperature-c", "-50", "--pressure-pa", "1e5")
    assert code == 0, err
    assert "tip Mach number up to 0.71 (> 0.7)" in err


def test_the_extremes_take_the_advancing_tip_the_axial_advance_ratio_and_moving_incidences(apc8x6):
    """Mutants C18 (the advancing tip without V sin(beta)), C19 (the still-air threshold 1% of the tip speed made
    10%) and C20 (the advance ratio of V, not of V cos(beta)): 6000 rpm (tip 63.84 m/s) at 20 m/s edgewise has
    its tip at 83.84 m/s and J = 0; at 1 m/s (above 1% of the tip speed, 0.64 m/s) its 90 deg counts."""
    omega_r = 2 * math.pi * 100.0 * apc8x6.radius
    tip, J, beta = envelope_extremes(apc8x6, 6000.0, 20.0, 90.0)
    assert tip == pytest.approx(omega_r + 20.0, rel=1e-12) and tip == pytest.approx(83.837, abs=1e-3)
    assert abs(J) < 1e-12 and beta == 90.0
    tip, J, beta = envelope_extremes(apc8x6, 6000.0, [0.0, 1.0], 90.0)
    assert beta == 90.0
    tip, J, beta = envelope_extremes(apc8x6, 6000.0, [0.0, 0.5], 90.0)  # (below 1% of 63.8 m/s: drift)
    assert beta == 0.0
    _, J, _ = envelope_extremes(apc8x6, 6000.0, 10.0, 60.0)
    assert J == pytest.approx(10.0 * 0.5 / (100.0 * 0.2032), rel=1e-12)


def test_an_incidence_just_beyond_the_datas_is_warned_of(tmp_path, capsys, apc8x6):
    """Mutant C4: the incidence's rounding margin 1e-6 deg made 1 deg (30.5 deg beside data up to 30 deg unsaid)."""
    label = _fitted(tmp_path, J_max=2.0, incidence_deg_max=30.0)
    assert _warnings(capsys, apc8x6, label, incidence_deg=30.5) == [
        f"propmap: warning: incidence up to 30.5 deg: {label} was fitted to data up to 30 deg"]
    assert _warnings(capsys, apc8x6, label, incidence_deg=30.0) == []


def test_axial_data_beyond_90_deg_name_the_descent(tmp_path, capsys, apc8x6):
    """Mutants C5 (axial data said as 'data up to 0 deg') and C6 (the descent named from 180 deg, not 90):
    120 deg on a set fitted to axial data."""
    label = _fitted(tmp_path, J_max=2.0, incidence_deg_max=0.0)
    (line,) = _warnings(capsys, apc8x6, label, incidence_deg=120.0)
    assert line.startswith(f"propmap: warning: incidence up to 120 deg: {label} was fitted to axial data only; ")
    assert line.endswith("; beyond 90 deg the rotor descends, beyond the climb data: the momentum of rotors in "
                         "descent, docs/models.md")
    (line,) = _warnings(capsys, apc8x6, label, incidence_deg=80.0)
    assert "axial data only" in line and "descends" not in line


def test_an_airspeed_beyond_the_datas_by_more_than_1_percent_is_warned_of(tmp_path, capsys, apc8x6):
    """Mutant C7 (the airspeed margin 1% made 10%: 10.6 m/s beside 10 m/s unsaid); the airspeed line is said beside
    an incidence line too since 2026-12-02 (it was left out there: a log at 15-18 m/s on a flight set fitted to 11.5
    m/s was told only of its advance ratio, 0.25 against 0.24, an audit of faster flights)."""
    label = _fitted(tmp_path, J_max=2.0, incidence_deg_max=30.0, airspeed_max=10.0)
    assert _warnings(capsys, apc8x6, label, airspeed=10.6) == [
        f"propmap: warning: airspeed up to 10.6 m/s: the data behind {label} reach 10 m/s"]
    assert _warnings(capsys, apc8x6, label, airspeed=10.2) == []  # (within 1% and 0.1 m/s)
    lines = _warnings(capsys, apc8x6, label, airspeed=20.0, incidence_deg=45.0)
    assert lines == [f"propmap: warning: incidence up to 45 deg: {label} was fitted to data up to 30 deg",
                     f"propmap: warning: airspeed up to 20 m/s: the data behind {label} reach 10 m/s"]


@pytest.mark.parametrize("rpm, shown", [(2990.0, "2990"), (6030.0, "6030"), ((4000.0, 7000.0), "4000-7000")])
def test_rates_just_outside_the_datas_span_are_warned_of(tmp_path, capsys, apc8x6, rpm, shown):
    """Mutants C9 and C10 (the rates' rounding margin 1e-6 made 1%: 2990 and 6030 rpm beside 3000-6000 rpm
    unsaid) and C11 (a range's high end taken as its low: 4000-7000 rpm unsaid)."""
    label = _fitted(tmp_path, rpm_min=3000.0, rpm_max=6000.0)
    assert _warnings(capsys, apc8x6, label, rpm=rpm) == [
        f"propmap: warning: {shown} rpm: the data behind {label} span 3000-6000 rpm (Reynolds numbers beyond them "
        "are extrapolated)"]


def test_a_table_with_only_the_highest_rate_says_up_to(tmp_path, capsys, apc8x6):
    """Mutants C12 (a span without its low end printed '0-6000 rpm') and C13 (the missing low end taken as
    1000 rpm, not 0: 500 rpm warned of)."""
    label = _fitted(tmp_path, rpm_max=6000.0)
    assert _warnings(capsys, apc8x6, label, rpm=7000.0) == [
        f"propmap: warning: 7000 rpm: the data behind {label} span up to 6000 rpm (Reynolds numbers beyond them "
        "are extrapolated)"]
    assert _warnings(capsys, apc8x6, label, rpm=500.0) == []


def test_the_reynolds_numbers_are_checked_with_the_rates_within_the_span(tmp_path, capsys, apc8x6):
    """Mutants C14 (no Reynolds check), C15 and C16 (its 5% margin made 50%) and C21 (the rates taken as rad/s):
    a run at 3000-6000 rpm whose Reynolds numbers at 0.75 R are 10% beyond the file's re75 span."""
    re_lo, re_hi = (float(apc8x6.reynolds_75(r * RPM, AIR)) for r in (3000.0, 6000.0))
    assert re_lo == pytest.approx(2.9e4, rel=0.3)  # (a chord Reynolds number of a few 1e4, not 1e3 of rad/s)
    for span, warned in [((re_lo * 1.1, re_hi), True), ((re_lo, re_hi / 1.1), True),
                         ((re_lo * 1.04, re_hi / 1.04), False)]:
        label = _fitted(tmp_path, rpm_min=3000.0, rpm_max=6000.0, re75_min=span[0], re75_max=span[1])
        lines = _warnings(capsys, apc8x6, label, rpm=(3000.0, 6000.0))
        expected = (f"propmap: warning: Reynolds number at 0.75 R {re_lo:.3g}-{re_hi:.3g} in this air and on apce_8x6:"
                    f" the data behind {label} span {span[0]:.3g}-{span[1]:.3g} (the section's Reynolds terms are "
                    "extrapolated; another air or another propeller size than the data's)")
        assert lines == ([expected] if warned else []), span


def test_a_calibrated_sets_reynolds_span_is_in_its_own_air(capsys, apc8x6):
    """Mutant C17: the calibrated set's Reynolds span computed in the run's air, not the set's (at 10000 m the same
    rates run below the data's Reynolds numbers: unsaid when both are in the thin air)."""
    thin = pm.Air.isa(10000.0)
    lines = _warnings(capsys, apc8x6, "calibrated:apce_8x6", rpm=4000.0, air=thin)
    own = pm.default_params("apce_8x6").air
    span = [float(apc8x6.reynolds_75(r * RPM, own)) for r in (2534.0, 6713.0)]
    re = float(apc8x6.reynolds_75(4000.0 * RPM, thin))
    assert lines == [f"propmap: warning: Reynolds number at 0.75 R {re:.3g} in this air and on apce_8x6: the data "
                     f"behind calibrated:apce_8x6 span {span[0]:.3g}-{span[1]:.3g} (the section's Reynolds terms are "
                     "extrapolated; another air or another propeller size than the data's)"]
    assert re < span[0] / 1.05


def test_a_hand_written_reynolds_span_without_rates_is_checked(capsys, tmp_path, apc8x6):
    """A [coverage] table with re75_min and re75_max but no rpm keys: its Reynolds span is checked (it was
    not: the check ran only beside the rates', an audit, 2026-11-29); 6000 rpm on the 8x6 at sea level is a
    Reynolds number of 4.77e4 at 0.75 R, beyond a span of 1e5-2e5."""
    re = float(apc8x6.reynolds_75(6000 * RPM, AIR))
    assert 3e4 < re < 6e4
    label = _fitted(tmp_path, re75_min=1e5, re75_max=2e5)
    lines = _warnings(capsys, apc8x6, label, rpm=6000.0)
    assert len(lines) == 1 and "Reynolds number at 0.75 R" in lines[0] and "span 1e+05-2e+05" in lines[0], lines
    assert _warnings(capsys, apc8x6, _fitted(tmp_path, re75_min=0.9 * re, re75_max=1.1 * re), rpm=6000.0) == []


# ---------------------------------------------------------------- cli/_air.py

SET_AIR = pm.Air(rho=1.2, mu=1.7e-5, speed_of_sound=330.0)


@pytest.mark.parametrize("argv, message", [
    (["--rho", "1.1", "--altitude-m", "100"], "give the air one way: --rho or --altitude-m, not both"),
    (["--pressure-pa", "1e5", "--rho", "1.1"],
     "give the air one way: --rho or --temperature-c/--pressure-pa, not both"),
    (["--rho", "2500"], "--rho must be in [0.001, 2000] kg/m^3, got 2500.0"),
    (["--rho", "1.1", "--altitude-m", "100", "--temperature-c", "10"],  # (three ways were "not both")
     "give the air one way: --rho or --temperature-c/--pressure-pa or --altitude-m, not all three"),
])
def test_the_air_options_refusals_say_what_was_given(capsys, argv, message):
    """Mutants A2 (the ways joined by 'and'), A14 (--pressure-pa alone not counted as a way: beside --rho, taken
    silently) and A3 (--rho's upper bound 2000 kg/m^3 raised to 20000)."""
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", *argv)
    assert one_line_error(code, err, message), err


def test_the_ends_of_the_air_ranges_are_taken():
    """Mutants A4 (--rho's lower end 0.001 kg/m^3 refused) and A11 (the ends of --pressure-pa's and --altitude-m's
    ranges refused: 1000 Pa, -500 m)."""
    assert resolve_air(SET_AIR, AirChoice(rho=1e-3)).rho == 1e-3
    assert resolve_air(SET_AIR, AirChoice(rho=2000.0)).rho == 2000.0
    low = resolve_air(SET_AIR, AirChoice(temperature_c=15.0, pressure_pa=1000.0))
    assert low.rho == pytest.approx(1000.0 / (287.05287 * 288.15), rel=1e-12)
    assert resolve_air(SET_AIR, AirChoice(altitude_m=-500.0)).rho == pytest.approx(pm.Air.isa(-500.0).rho, rel=1e-15)
    assert pm.Air.isa(-500.0).rho == pytest.approx(1.2849, rel=1e-4)
    with pytest.raises(InputError, match=r"--pressure-pa must be finite and in \[1000, 120000\] Pa, got 999.0"):
        resolve_air(SET_AIR, AirChoice(temperature_c=15.0, pressure_pa=999.0))


def test_rho_replaces_the_density_only_and_no_option_keeps_the_sets_air():
    """Mutants A5 and A6 (--rho's air given a fixed viscosity or speed of sound, not the set's) and A15 (no air
    option giving the sea-level ISA, not the set's air)."""
    got = resolve_air(SET_AIR, AirChoice(rho=0.9))
    assert (got.rho, got.mu, got.speed_of_sound) == (0.9, 1.7e-5, 330.0)
    assert resolve_air(SET_AIR, AirChoice()) == SET_AIR


def test_the_air_line_prints_each_quantity():
    """Mutant A13: the viscosity's place in the air line given the density."""
    assert air_label(SET_AIR) == "rho 1.2 kg/m^3, mu 1.7e-05 Pa s, speed of sound 330 m/s"


def test_validate_all_names_the_air_option_as_typed(capsys):
    """Mutant A16: the options given named by their field (--temperature_c), not as typed (--temperature-c)."""
    assert AirChoice(temperature_c=20.0, pressure_pa=1e5).options_given() == ["--temperature-c", "--pressure-pa"]
    code, _, err = run(capsys, "validate", "--all", "--temperature-c", "20", "--pressure-pa", "1e5")
    assert one_line_error(code, err, "--temperature-c applies to a single PROP; --all compares coefficients"), err


# ---------------------------------------------------------------- core/_frame.py


def _by_hand(velocity, axis, loads, spin):
    """Force and moment from the rotor-frame loads, rotated by hand (docs/conventions.md): force T z - D e_ip -
    spin Y (z x e_ip), moment -spin (Q z + M_R e_ip) - M_P (z x e_ip)."""
    v, a = np.asarray(velocity, float), np.asarray(axis, float)
    z = a / np.linalg.norm(a)
    ip = v - (v @ z) * z
    e = ip / np.linalg.norm(ip)
    lat = np.cross(z, e)
    T, D, Q, MR, Y, MP = (float(getattr(loads, k)) for k in ("thrust", "drag", "torque", "rolling_moment",
                                                             "side_force", "pitching_moment"))
    return T * z - D * e - spin * Y * lat, -spin * (Q * z + MR * e) - MP * lat


@pytest.mark.parametrize("spin, sign", [("ccw", 1.0), ("cw", -1.0)])
def test_the_wrench_is_the_rotor_frame_loads_rotated(apc8x6, spin, sign):
    """Mutants F1 (the drag's sign in the force), F2 (the side force's), F3 (the pitching moment's) and F4 (the
    rolling moment's): a flapping rotor (every load non-zero) at 12 m/s, 50 deg off a tilted axis, one point and
    a batch of two, against its loads rotated by hand; the loads are rotor_loads' at that speed and incidence."""
    params = pm.default_params("apce_8x6").replace(flap_compliance=0.05)
    axis = np.array([0.3, -0.2, 1.0])
    z = axis / np.linalg.norm(axis)
    lat = np.cross(z, [1.0, 0.0, 0.0])
    lat /= np.linalg.norm(lat)
    velocity = 12.0 * (math.cos(math.radians(50.0)) * z + math.sin(math.radians(50.0)) * lat)
    ref = pm.rotor_loads(apc8x6, params, 700.0, 12.0, math.radians(50.0))
    for k in ("drag", "rolling_moment", "side_force", "pitching_moment"):
        assert abs(float(getattr(ref, k))) > 1e-3, k  # (each term seen)
    w = pm.rotor_wrench(apc8x6, params, velocity, axis, 700.0, spin)
    assert float(w.loads.thrust) == pytest.approx(float(ref.thrust), rel=1e-9)
    assert float(w.loads.side_force) == pytest.approx(float(ref.side_force), rel=1e-9)  # (the sense: below)
    force, moment = _by_hand(velocity, axis, w.loads, sign)
    np.testing.assert_allclose(w.force, force, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(w.torque, moment, rtol=1e-12, atol=1e-12)
    batch = pm.rotor_wrench(apc8x6, params, [velocity, 0.5 * velocity], [axis, axis], 700.0, spin)
    np.testing.assert_allclose(batch.force[0], force, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(batch.torque[0], moment, rtol=1e-12, atol=1e-12)
    f1, m1 = _by_hand(0.5 * velocity, axis, pm.rotor_loads(apc8x6, params, 700.0, 6.0, math.radians(50.0)), sign)
    np.testing.assert_allclose(batch.force[1], f1, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(batch.torque[1], m1, rtol=1e-9, atol=1e-12)


def test_the_in_plane_direction_is_kept_a_hundredth_of_a_degree_off_the_axis(apc8x6):
    """Mutant F5: the in-plane unit vector dropped below 1e-3 of the speed (not 1e-12): at 0.01 deg off the axis
    (1.7e-4 of the speed in the plane) the drag, rolling moment, side force and pitching moment left out."""
    params = pm.default_params("apce_8x6").replace(flap_compliance=0.05)
    axis = np.array([0.3, -0.2, 1.0])
    z = axis / np.linalg.norm(axis)
    lat = np.cross(z, [1.0, 0.0, 0.0])
    lat /= np.linalg.norm(lat)
    b = math.radians(0.01)
    velocity = 12.0 * (math.cos(b) * z + math.sin(b) * lat)
    w = pm.rotor_wrench(apc8x6, params, velocity, axis, 700.0)
    assert abs(float(w.loads.drag)) > 1e-6 and abs(float(w.loads.rolling_moment)) > 1e-7
    force, moment = _by_hand(velocity, axis, w.loads, 1.0)
    np.testing.assert_allclose(w.force, force, rtol=1e-9, atol=1e-13)
    np.testing.assert_allclose(w.torque, moment, rtol=1e-9, atol=1e-13)
