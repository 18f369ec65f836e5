"""A mutation audit of identify/flight_samples.py, io/flightlog.py and core/trim.py (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed. The trim tests
use the bundled APC 8x6E with its calibrated set; the flight tests hand-built logs of the bundled NeuroBEM
quadrotor (Bauersfeld et al. 2021) or small NeuroBEM CSV files."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.trim import TrimError, trim_collective, trim_omega
from propmap.identify.flight_samples import flight_samples


@pytest.fixture(scope="module")
def apc():
    return pm.load_propeller("apce_8x6"), pm.resolve_params("calibrated:apce_8x6")


# --- core/trim.py -----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bounds", [(-1.0, 0.3), (-0.3, 1.0)])
def test_collective_bounds_beyond_a_quarter_turn_are_refused(apc, bounds):
    """bounds 'within [-pi/4, pi/4]': a low end of -1 rad or a high end of +1 rad is refused, naming bounds."""
    prop, p = apc
    with pytest.raises(ValueError, match=r"^bounds must satisfy -0\.785398 <= low < high <= 0\.785398 rad"):
        trim_collective(prop, p, 3.0, 900.0, bounds=bounds)


@pytest.mark.parametrize("tol", [0.0, math.inf])
def test_a_thrust_tolerance_of_zero_or_infinity_is_refused(apc, tol):
    """thrust_tol is 'a positive number [N]': 0 and inf are refused, naming it."""
    prop, p = apc
    with pytest.raises(ValueError, match=r"^thrust_tol must be a positive number \[N\]"):
        trim_collective(prop, p, 3.0, 900.0, thrust_tol=tol)


def test_a_grid_step_of_true_is_refused_where_one_radian_would_fit_the_bounds(apc):
    """grid_step is a spacing [rad]: True (1 as a bool) is refused even where 1 rad lies in [width / 10,000, width]
    (bounds of -40 to +40 deg: 1.396 rad wide)."""
    prop, p = apc
    with pytest.raises(ValueError, match=r"^grid_step must be in \[0\.00013962\d*, 1\.39626\] rad .*got True"):
        trim_collective(prop, p, 3.0, 900.0, bounds=(-math.radians(40.0), math.radians(40.0)), grid_step=True)


def test_an_unreachable_collective_trim_with_nan_leaves_the_torque_nan_too(apc):
    """on_missing='nan': 'NaN collective and loads there', every load field (the torque was left at the collective
    0's value by a mutant) while a reachable point beside it keeps its finite loads."""
    prop, p = apc
    r = trim_collective(prop, p, [3.0, 300.0], 900.0, on_missing="nan")
    assert list(r.n_solutions) == [1, 0] and math.isfinite(r.collective[0]) and math.isnan(r.collective[1])
    for f in ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "v_i_mean"):
        v = np.asarray(getattr(r.loads, f))
        assert np.isfinite(v[0]) and np.isnan(v[1]), f


def test_default_rate_bounds_stop_at_the_solvers_largest_rate():
    """default_omega_bounds: 'the high one at most the solver's OMEGA_MAX (1e5 rad/s)'. A 2 mm rotor reaches Mach 0.9
    at 0.9 x 340.3 / 0.002 = 153,135 rad/s: the bound is 1e5; the low one 1 m/s / 0.002 m = 500 rad/s."""
    from propmap.core.trim import default_omega_bounds

    R = 0.002
    r = np.linspace(0.2, 1.0, 8) * R
    tiny = pm.Propeller(name="tiny", radius=R, n_blades=2, r=r, chord=np.full(8, 0.0005), theta=np.full(8, 0.2),
                        source="test: a 4 mm rotor")
    assert default_omega_bounds(tiny, pm.Air()) == (500.0, 1e5)


def test_rate_bounds_beyond_the_solvers_largest_rate_are_refused(apc):
    prop, p = apc
    with pytest.raises(ValueError, match=r"^bounds must satisfy 0 < low < high <= 100000 rad/s, got \(100\.0, 200000"):
        trim_omega(prop, p, 3.0, bounds=(100.0, 2e5))


def test_a_thrust_beyond_the_rotors_reach_names_the_tip_mach_of_the_top_rate(apc):
    """300 N from an 8 in propeller: 'the rotor makes T <= ... N up to tip Mach 0.9' (the default top rate, 0.9 of the
    speed of sound at the tip), not the rate over the speed of sound (a mutant's 14)."""
    prop, p = apc
    with pytest.raises(TrimError, match=r"\(the rotor makes T <= [\d.]+ N up to tip Mach 0\.9: is the thrust in grams"):
        trim_omega(prop, p, 300.0)


def test_the_hover_trim_of_dcq_searches_the_bounds_given(apc):
    """torque_change_at_constant_thrust's bounds are 'collectives searched for the hover trim': climbing at 5 m/s the
    APC makes less thrust than in hover at the same rate, so the hover collective is negative and bounds of 0 to 0.01
    rad hold none (TrimError), where the default -20 to +30 deg find it."""
    from propmap.core.torque_change import torque_change_at_constant_thrust

    prop, p = apc
    _, _, hover = torque_change_at_constant_thrust(prop, p, 900.0, 5.0, 0.0)
    assert float(hover.collective) < 0
    with pytest.raises(TrimError, match=r"^no collective in \[0, 0\.573\] deg makes thrust="):
        torque_change_at_constant_thrust(prop, p, 900.0, 5.0, 0.0, bounds=(0.0, 0.01))


def test_a_collective_trim_error_gives_the_rate_in_rpm_too(apc):
    """The TrimError names the point: 'omega=900 rad/s = 8594.37 rpm' (900 x 60 / 2 pi), and the bounds in degrees."""
    prop, p = apc
    with pytest.raises(TrimError, match=r"^no collective in \[-20, 30\] deg makes thrust=300 N at operating point "
                                        r"\(omega=900 rad/s = 8594\.37 rpm, airspeed=0 m/s, incidence=0 deg\)"):
        trim_collective(prop, p, 300.0, 900.0)


# --- identify/flight_samples.py ---------------------------------------------------------------------------------

G = 9.80665


@pytest.fixture(scope="module")
def quad():
    """The bundled NeuroBEM quadrotor and its generic-set hover speed H [rad/s]."""
    from propmap.identify.flight_samples import _hover_speed

    veh = pm.read_vehicle("neurobem_quadrotor")
    return veh, _hover_speed(veh)


def _flight(om, rate=100.0, name="synthetic", **change):
    """A log at ``rate`` Hz flying level at 3 m/s with the accelerometer reading g, its motors at ``om`` (shape (N,)
    or (N, 4)) [rad/s]; ``change`` replaces fields."""
    from propmap.io.flightlog import FlightLog

    om = np.asarray(om, float)
    om = np.tile(om[:, None], (1, 4)) if om.ndim == 1 else om
    n = len(om)
    fields = dict(t=np.arange(n) / rate, angular_velocity=np.zeros((n, 3)), angular_acceleration=np.zeros((n, 3)),
                  specific_force=np.tile([0.0, 0.0, G], (n, 1)), velocity=np.tile([3.0, 0.0, 0.0], (n, 1)),
                  attitude=np.tile([0.0, 0.0, 0.0, 1.0], (n, 1)), rotor_omega=om, rotor_acceleration=None)
    return FlightLog(name=name, path="", format="neurobem", **{**fields, **change})


def _samples(**change):
    """Two hand-built samples of one log, valid; ``change`` replaces fields."""
    from propmap.identify.flight_samples import FlightSamples

    z3 = np.zeros((2, 3))
    fields = dict(log_names=("a",), log_index=np.array([0, 0]), t=np.array([0.0, 0.1]), velocity=z3,
                  angular_velocity=z3, rotor_omega=np.full((2, 4), 1000.0), rotor_acceleration=np.zeros((2, 4)),
                  force=z3, moment=z3, reference_force=None, reference_moment=None, rate_hz=10.0)
    return FlightSamples(**{**fields, **change})


@pytest.mark.parametrize("change, match", [
    (dict(log_index=np.array([0, -1])), r"log_index must be N = 2 indices into log_names \(1 logs\)"),
    (dict(rate_hz=math.inf), r"rate_hz must be a rate > 0 Hz, got inf"),
    (dict(rate_hz=True), r"rate_hz must be a rate > 0 Hz, got True"),
])
def test_hand_built_samples_refuse_a_negative_log_index_and_a_bad_rate(change, match):
    """FlightSamples' Raises: a log_index that is not an index of log_names (-1), a rate_hz not > 0 (inf; True, a
    bool, is not a rate); the message names the field."""
    _samples()  # (valid as it is)
    with pytest.raises(ValueError, match=r"^FlightSamples\." + match):
        _samples(**change)


@pytest.mark.parametrize("kw, match", [(dict(rate_hz=2e4), r"^rate_hz must be a finite number in \(0, 10000\] Hz, "
                                                                r"got 20000"),
                                       (dict(motor_time_constant=2.0), r"^motor_time_constant must be a finite "
                                                                       r"number in "
                                                                       r"\[0, 1\] s, got 2\.0")])
def test_flight_samples_refuses_a_rate_above_10_khz_and_a_motor_lag_over_a_second(quad, kw, match):
    veh, H = quad
    with pytest.raises(ValueError, match=match):
        flight_samples([_flight(np.full(200, H))], veh, **kw)


def test_decimation_rounds_the_step_and_the_rate_is_the_median_of_the_logs(quad):
    """rate_hz: 'every k-th sample of a log, k = round(log rate / rate_hz)': 100 Hz at 30 Hz asked is k = 3 (not 4, the
    ceiling; 3 truncated too: tests/test_audit_split_helpers_2.py tells rounding from truncation at 35 Hz), 34
    of 100 samples at 33.33 Hz; the samples' rate is 'the median over the logs': with a 20 Hz log (k = 1) beside it,
    (33.33 + 20) / 2. Without a prediction in the logs, reference_mass is NaN per log."""
    veh, H = quad
    s = flight_samples([_flight(np.full(100, H))], veh, rate_hz=30.0, motor_time_constant=0.0)
    assert s.n == 34 and s.rate_hz == pytest.approx(100.0 / 3.0, rel=1e-12)
    s = flight_samples([_flight(np.full(100, H)), _flight(np.full(40, H), rate=20.0, name="slow")], veh, rate_hz=30.0,
                       motor_time_constant=0.0)
    assert s.n == 34 + 40 and s.rate_hz == pytest.approx((100.0 / 3.0 + 20.0) / 2.0, rel=1e-12)
    assert len(s.reference_mass) == 2 and all(math.isnan(m) for m in s.reference_mass)


def test_the_measured_moment_differentiates_the_rates_and_keeps_the_gyroscopic_sign(quad):
    """Without a logged dw/dt, M = I dw/dt + w x I w with dw/dt from w: w = (0.5 t, 0.2, 0) rad/s gives
    M = (Ixx 0.5, 0, wx wy (Iyy - Ixx)) [N m], Ixx = 0.0025, Iyy = 0.0021 kg m^2."""
    veh, H = quad
    n = 200
    t = np.arange(n) / 100.0
    w = np.column_stack([0.5 * t, np.full(n, 0.2), np.zeros(n)])
    s = flight_samples([_flight(np.full(n, H), angular_velocity=w, angular_acceleration=None)], veh, rate_hz=100.0,
                       motor_time_constant=0.0)
    expected = np.column_stack([np.full(n, 0.0025 * 0.5), np.zeros(n), w[:, 0] * 0.2 * (0.0021 - 0.0025)])
    np.testing.assert_allclose(s.moment, expected, rtol=1e-9, atol=1e-15)


def test_the_motor_lag_of_a_ramp_is_exact_and_the_vehicles_by_default(quad):
    """tau dOmega/dt = Omega_logged - Omega from the first sample, the logged speed linear between samples: for a ramp
    x = x0 + c t the lagged speed is x - tau c (1 - exp(-t / tau)) and dOmega/dt = c (1 - exp(-t / tau)), exactly at
    any sampling rate; tau is the vehicle's 33 ms where none is given."""
    veh, H = quad
    rate, c = 400.0, 0.2 * H  # [Hz], [rad/s^2]
    t = np.arange(400) / rate
    s = flight_samples([_flight(H + c * t, rate=rate)], veh, rate_hz=rate)
    tau = veh.motor_time_constant
    assert tau == 0.033
    lag = 1.0 - np.exp(-t / tau)
    np.testing.assert_allclose(s.rotor_omega, np.tile((H + c * t - tau * c * lag)[:, None], (1, 4)), rtol=1e-12)
    np.testing.assert_allclose(s.rotor_acceleration, np.tile((c * lag)[:, None], (1, 4)), rtol=1e-9, atol=1e-9)


def test_a_motor_beyond_mach_1_in_its_99th_percentile_is_refused_and_a_spike_is_not(quad):
    """MAX_TIP_MACH: motor 2 at 7881 rad/s, Mach 1.5 on the 6.477 cm rotor, in 3% of the samples is refused naming the
    motor, its speed and Mach; in 0.5% of them (below the 99th percentile) it is read."""
    veh, H = quad
    fast = 1.5 * 340.3 / 0.06477
    om = np.full((1000, 4), H)
    om[500:530, 1] = fast
    with pytest.raises(ValueError, match=rf"^synthetic: motor 2 runs at {fast:.0f} rad/s \(99th percentile\), a tip "
                                         r"speed of Mach 1\.50 on its 0\.06477 m rotor: are the log's motor speeds"):
        flight_samples([_flight(om)], veh, motor_time_constant=0.0)
    om[505:530, 1] = H
    assert flight_samples([_flight(om)], veh, rate_hz=100.0, motor_time_constant=0.0).n == 1000


def test_the_ground_rule_needs_the_accelerometer_at_g_and_the_vehicle_not_turning(quad):
    """On the ground: standing still (speed < 0.5 m/s, rates < 0.5 rad/s), the accelerometer reading g within 20%, the
    rotors below 0.7 of the hover speed. Of 50 idling samples at rest reading g, 25 reading 0.5 g and 25 turning at
    1 rad/s (each at 0.3 H), only the first 50 are on the ground; 100 fly at H."""
    veh, H = quad
    om = np.r_[np.full(100, H), np.full(100, 0.3 * H)]
    f = np.tile([0.0, 0.0, G], (200, 1))
    f[150:175, 2] = 0.5 * G
    v = np.zeros((200, 3))
    v[:100, 0] = 3.0
    w = np.zeros((200, 3))
    w[175:, 2] = 1.0
    s = flight_samples([_flight(om, specific_force=f, velocity=v, angular_velocity=w)], veh, rate_hz=100.0,
                       motor_time_constant=0.0)
    assert s.n == 150 and any("50 sample(s) on the ground left out" in x for x in s.notes), s.notes


def test_a_log_is_judged_slow_by_the_95th_percentile_of_its_rms_speed(quad):
    """HOVER_RANGE[0] applies to the kept samples' rms speed 'in its 95th percentile': 10% of the samples at H and 90%
    at 0.4 H (below 0.5 H) are read; all at 0.4 H are refused."""
    veh, H = quad
    om = np.r_[np.full(20, H), np.full(180, 0.4 * H)]
    assert flight_samples([_flight(om)], veh, rate_hz=100.0, motor_time_constant=0.0).n == 200
    with pytest.raises(ValueError, match=r"^synthetic: the rotors' rms speed is [\d.]+ rad/s in the median and "
                                         r"[\d.]+ in its 95th percentile, 0\.4 and 0\.4 times the vehicle's hover"):
        flight_samples([_flight(np.full(200, 0.4 * H))], veh, rate_hz=100.0, motor_time_constant=0.0)


def test_the_hover_speed_carries_the_weight_and_counts_only_the_rotors_upward_thrust(quad):
    """_hover_speed: 4 T(H) = m g, T the generic set's static thrust (24 x 8 nodes), within 0.3% (interpolated between
    grid rates 16% apart); with every rotor tilted 60 deg only half its thrust is upward: near sqrt(2) H (T ~ Omega^2
    within a few percent)."""
    import dataclasses

    from propmap.core.solver import Discretization
    from propmap.identify.flight_samples import _hover_speed
    from propmap.io.calibration import generic_params

    veh, H = quad
    prop = veh.rotors[0].propeller
    T = float(pm.rotor_loads(prop, generic_params(), H, 0.0, 0.0, discretization=Discretization(24, 8)).thrust)
    assert 4 * T == pytest.approx(veh.weight, rel=3e-3)
    a = math.radians(60.0)
    axis = np.array([0.0, math.sin(a), math.cos(a)])
    tilted = dataclasses.replace(veh, rotors=tuple(dataclasses.replace(r, axis=axis) for r in veh.rotors))
    assert _hover_speed(tilted) / H == pytest.approx(math.sqrt(2.0), rel=0.05)


def test_a_rotor_stopped_through_the_motor_lag_alone_is_left_out(quad):
    """A stopped rotor is one below 1 rad/s 'by its logged speed or through the motor lag': motor 1 logged at 0 for
    100 samples at 1000 Hz, then at H, with tau = 1 s. The lag's first step after the start reaches b H, b = 1 - tau a
    / h (a = 1 - exp(-h / tau)), below 1 rad/s, its second above: 101 samples are left out, not the 100 logged at 0."""
    veh, H = quad
    h, tau = 1.0 / 1000.0, 1.0
    a = -math.expm1(-h / tau)
    b = 1.0 - tau * a / h
    assert b * H < 1.0 < b * H + a * (H - b * H)
    om = np.full((600, 4), H)
    om[:100, 0] = 0.0
    s = flight_samples([_flight(om, rate=1000.0)], veh, rate_hz=1000.0, motor_time_constant=tau)
    assert s.n == 499 and any("101 sample(s) with a stopped rotor" in x for x in s.notes), s.notes



def test_a_log_of_three_motors_for_four_rotors_is_refused(quad):
    """'a log whose motor count differs from the vehicle's rotor count' is refused, naming both counts."""
    veh, H = quad
    with pytest.raises(ValueError, match=r"^synthetic: 3 motor speeds but the vehicle has 4 rotors \(the vehicle file "
                                         r"lists its rotors in the log's motor order\)"):
        flight_samples([_flight(np.full((200, 3), H))], veh, motor_time_constant=0.0)


# --- io/flightlog.py --------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def seg_rows(shared_data):
    """The first 300 rows (0.75 s at 400 Hz) of a shared NeuroBEM segment, all 41 columns."""
    import scipy.io

    a = scipy.io.loadmat(shared_data / "neurobem_flights" / "bemnn20210223114138seg3.mat")
    return next(v for k, v in a.items() if not k.startswith("__")).astype(float)[:300].copy()


def _csv(path, rows, header=True, end=""):
    from propmap.io.flightlog import NEUROBEM_COLUMNS

    top = [",".join(NEUROBEM_COLUMNS) + end] if header is True else ([header] if header else [])
    path.write_text("\n".join(top + [",".join(repr(float(x)) for x in row) + end for row in rows]) + "\n")
    return path


def test_an_upper_case_suffix_names_the_format(tmp_path, seg_rows):
    """The format by the suffix, '.mat and .csv NeuroBEM': LOG.CSV is read as the NeuroBEM CSV it is."""
    from propmap.io.flightlog import read_flight_log

    log = read_flight_log(_csv(tmp_path / "LOG.CSV", seg_rows))
    assert log.format == "neurobem" and log.n == 300
    np.testing.assert_array_equal(log.rotor_omega, seg_rows[:, 20:24])


def test_the_rate_is_one_over_the_median_step():
    """FlightLog.rate_hz: '1 / the median time step': steps of 0.01 s with one gap of 1 s are 100 Hz, not the mean's."""
    from propmap.io.flightlog import FlightLog

    t = np.array([0.0, 0.01, 0.02, 0.03, 0.04, 1.04])
    z = np.zeros((6, 3))
    log = FlightLog(name="x", path="x", format="neurobem", t=t, angular_velocity=z, angular_acceleration=None,
                    specific_force=z, velocity=z, attitude=np.zeros((6, 4)), rotor_omega=np.ones((6, 4)),
                    rotor_acceleration=None)
    assert log.rate_hz == pytest.approx(100.0, rel=1e-9) and log.duration == pytest.approx(1.04)


def test_a_header_of_column_numbers_1_to_41_reads_as_the_plain_csv(tmp_path, seg_rows):
    """A header of column numbers (pandas' 0-40, or 1-41) is not data."""
    from propmap.io.flightlog import read_flight_log

    log = read_flight_log(_csv(tmp_path / "n.csv", seg_rows, header=",".join(map(str, range(1, 42)))))
    assert log.n == 300
    np.testing.assert_array_equal(log.specific_force, seg_rows[:, 11:14])


def test_a_trailing_comma_with_a_comment_among_the_rows(tmp_path, seg_rows):
    """'#' lines are skipped among the data too: a spreadsheet's trailing comma on every data line is still dropped
    where a '# note' line (without one) sits among them."""
    from propmap.io.flightlog import NEUROBEM_COLUMNS, read_flight_log

    rows = [",".join(repr(float(x)) for x in row) + "," for row in seg_rows]
    rows.insert(150, "# the pilot took over here")
    (tmp_path / "c.csv").write_text(",".join(NEUROBEM_COLUMNS) + "\n" + "\n".join(rows) + "\n")
    np.testing.assert_array_equal(read_flight_log(tmp_path / "c.csv").rotor_omega, seg_rows[:, 20:24])


def test_an_unknown_format_and_two_mat_arrays_are_refused(tmp_path, seg_rows):
    """format one of FORMATS ('px4' is not), and a .mat of 'one array of any name' (two are named, not unpacked)."""
    import scipy.io

    from propmap.io.flightlog import FlightLogError, read_flight_log

    with pytest.raises(FlightLogError, match=r"^format must be one of neurobem, ulog, got 'px4'"):
        read_flight_log(_csv(tmp_path / "x.csv", seg_rows), format="px4")
    scipy.io.savemat(tmp_path / "two.mat", {"a": seg_rows, "b": seg_rows})
    with pytest.raises(FlightLogError, match=r"two\.mat: expected one N x 41 array, found 2 variable\(s\) \(a, b\)"):
        read_flight_log(tmp_path / "two.mat")


@pytest.mark.parametrize("noise, mass", [(2e-3, 0.752), (2e-2, None)])
def test_the_reference_mass_holds_within_1e_3_of_the_forces_rms(seg_rows, tmp_path, noise, mass):
    """prediction + residual = m a_s within 1e-3 of its rms (4.26 N over the three components here, so 4.3e-3 N):
    noise of 2e-3 N rms on the residual keeps the mass 0.752 kg, 2e-2 N rms loses it; a sum that is -m a_s (a
    negative mass) is none."""
    import scipy.io

    from propmap.io.flightlog import read_flight_log

    a = seg_rows.copy()
    a[:, 35:38] += noise * np.random.default_rng(1).standard_normal((len(a), 3))
    scipy.io.savemat(tmp_path / "m.mat", {"log": a})
    got = read_flight_log(tmp_path / "m.mat").reference_mass
    assert got == (None if mass is None else pytest.approx(mass, abs=2e-4))
    a = seg_rows.copy()
    a[:, 29:32] = -a[:, 29:32] - 2 * a[:, 35:38]  # (prediction + residual = -(the logged sum))
    scipy.io.savemat(tmp_path / "neg.mat", {"log": a})
    log = read_flight_log(tmp_path / "neg.mat")
    assert log.reference_force is not None and log.reference_mass is None


def _layout_log(quad, slow):
    """20 s at 25 Hz, the motors 5% about H at random; the measured roll moment -0.02 z_x (z = sum_i G_i Omega_i^2, the
    layout's) plus a residual orthogonal to z_x with 3 times its rms: a sine of 20 s (slow) or white noise."""
    from propmap.identify.flight_samples import _layout_moments

    veh, H = quad
    n = 500
    t = np.arange(n) / 25.0
    rng = np.random.default_rng(0)
    om = H * (1 + 0.05 * rng.standard_normal((n, 4)))
    zx = (om**2 @ _layout_moments(veh, H))[:, 0]
    zx = zx - zx.mean()
    r = np.sin(2 * math.pi * 0.05 * t) if slow else rng.standard_normal(n)
    r = r - r.mean()
    r = r - (r @ zx) / (zx @ zx) * zx
    mx = -0.02 * zx + 3 * 0.02 * np.std(zx) * r / np.std(r)
    wdot = np.zeros((n, 3))
    wdot[:, 0] = mx / veh.inertia[0, 0]
    return _flight(om, rate=25.0, name="layout", angular_acceleration=wdot)


def test_the_layout_note_counts_the_effective_samples_of_a_correlated_residual(quad):
    """LAYOUT_T with 'the effective sample count of the residuals' lag-1 autocorrelation rho, n (1 - rho) / (1 + rho)':
    a slow residual (rho at its 0.99 cap, 3 effective samples of 500) leaves the slope's t near -0.8 (about -10.5 with
    n alone): no note; white noise of the same rms, t = -7.4: the note about body x."""
    veh, _ = quad
    s = flight_samples([_layout_log(quad, slow=True)], veh, rate_hz=25.0, motor_time_constant=0.0)
    assert not any("rotor layout" in x for x in s.notes), s.notes
    s = flight_samples([_layout_log(quad, slow=False)], veh, rate_hz=25.0, motor_time_constant=0.0)
    assert any("the measured moment about body x (t = -" in x for x in s.notes), s.notes


def test_a_header_naming_a_column_twice_is_refused(tmp_path, seg_rows):
    """A header with 'mot 1' a second time (a 42nd column) is refused naming it, not read from its first copy."""
    from propmap.io.flightlog import NEUROBEM_COLUMNS, FlightLogError, read_flight_log

    path = tmp_path / "d.csv"
    path.write_text(",".join(NEUROBEM_COLUMNS + ("mot 1",)) + "\n"
                    + "\n".join(",".join(repr(float(x)) for x in [*row, 0.0]) for row in seg_rows) + "\n")
    with pytest.raises(FlightLogError, match=r"d\.csv: column\(s\) mot 1 appear twice in the header"):
        read_flight_log(path)


def test_no_reference_mass_without_the_residual_columns(seg_rows, tmp_path):
    """reference_mass needs the residual (columns 36-38) as well: a prediction that is exactly 0.752 kg times the
    specific force with residual columns of zeros (a log without them) has no mass, though its prediction is read."""
    import scipy.io

    from propmap.io.flightlog import read_flight_log

    a = seg_rows.copy()
    a[:, 29:32] = 0.752 * a[:, 11:14]
    a[:, 35:38] = 0.0
    scipy.io.savemat(tmp_path / "r.mat", {"log": a})
    log = read_flight_log(tmp_path / "r.mat")
    assert log.reference_force is not None and log.reference_mass is None


# --- a defect the audit found: a bool taken as a number ---------------------------------------------------------

@pytest.mark.parametrize("kw, match", [(dict(rate_hz=True), r"^rate_hz must be a finite number in \(0, 10000\] Hz, "
                                                                 r"got True"),
                                       (dict(motor_time_constant=True),
                                        r"^motor_time_constant must be a finite number in \[0, 1\] s, got True")])
def test_flight_samples_refuses_a_bool_for_its_rate_or_motor_lag(quad, kw, match):
    """rate_hz=True was read as 1 Hz (2 samples of a 2 s log kept) and motor_time_constant=True as a lag of 1 s,
    without a word, where FlightSamples refuses a bool rate and trim_collective a bool grid_step."""
    veh, H = quad
    with pytest.raises(ValueError, match=match):
        flight_samples([_flight(np.full(200, H))], veh, **kw)


@pytest.mark.parametrize("trim", ["collective", "omega"])
def test_a_bool_thrust_tolerance_is_refused(apc, trim):
    """thrust_tol=True was a tolerance of 1 N (trim_omega returned 3.12 N for 3 N asked)."""
    prop, p = apc
    with pytest.raises(ValueError, match=r"^thrust_tol must be a positive number \[N\], got True"):
        if trim == "collective":
            trim_collective(prop, p, 3.0, 900.0, thrust_tol=True)
        else:
            trim_omega(prop, p, 3.0, thrust_tol=True)
