"""A mutation audit of stop 101's change (7a927ae..6c493ff; a helper session, stop 102, 2026-12-02: 79 hand-made
mutants of io/flightlog_checks.py, core/torque_change.py, vehicle/layout.py, io/atomic.py, export_c.py,
io/catalogue.py, simexport/ and core/trim.py; 48 killed by the suite, 7 equivalent, 24 real gaps). Each test here
passes on the code and fails on the mutant its audit named (F: flight-log checks, T: torque change, I: inertia,
A: atomic writes, R: trims). Data: a synthetic 400 Hz log with exact motor derivatives; the catalogue's APC 8x6E
(APC PE0 geometry) with its calibrated set."""

import dataclasses
import math
import os
import warnings
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM


# ---- flight-log checks (io/flightlog_checks.py) ---------------------------------------------------------------------
def _log(rate=400.0, duration=2.0, n_motors=4):
    """A consistent synthetic NeuroBEM-like log: hovering while yawing at 1 + cos(pi t) rad/s, each
    motor's speed 1100 + 150 sin(2 pi t + 0.7 m) rad/s with its exact derivative logged as the motor
    acceleration (942 rad/s^2 peak: judged, as the shared segments' 177-1,231 rad/s^2 rms)."""
    from propmap.io.flightlog import FlightLog
    from propmap.io.flightlog_checks import G

    t = np.arange(0.0, duration + 0.5 / rate, 1.0 / rate)
    z, yaw = 0.0 * t, t + np.sin(math.pi * t) / math.pi
    phase = 2 * math.pi * t[:, None] + 0.7 * np.arange(n_motors)[None, :]
    return FlightLog(name="f.csv", path="f.csv", format="neurobem", t=t,
                     angular_velocity=np.column_stack([z, z, 1.0 + np.cos(math.pi * t)]),
                     angular_acceleration=np.column_stack([z, z, -math.pi * np.sin(math.pi * t)]),
                     specific_force=np.column_stack([z, z, z + G]), velocity=np.column_stack([z, z, z]),
                     attitude=np.column_stack([z, z, np.sin(yaw / 2), np.cos(yaw / 2)]),
                     rotor_omega=1100.0 + 150.0 * np.sin(phase), rotor_acceleration=300.0 * math.pi * np.cos(phase))


def _check(log):
    from propmap.io.flightlog_checks import check_log

    check_log(log, "f.csv")


def _motor_in_rpm_s(log, m):
    acc = log.rotor_acceleration.copy()
    acc[:, m] *= 30.0 / math.pi
    return dataclasses.replace(log, rotor_acceleration=acc)


def test_the_synthetic_log_passes_silently():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for rate in (400.0, 50.0):
            _check(_log(rate))


def test_a_log_sampled_at_20_khz_is_refused_and_one_at_10_khz_is_not():
    """docs/flight.md: a log sampled faster than 10 kHz is refused (MAX_RATE_HZ), one at 10 kHz is read."""
    from propmap.io.flightlog_checks import FlightLogError

    with pytest.raises(FlightLogError, match=r"\(2e\+04 Hz\), faster than the 10000 Hz"):
        _check(_log(rate=20000.0, duration=0.3))
    _check(_log(rate=10000.0, duration=0.3))  # (the limit itself is read)


def test_a_50_hz_logs_motor_acceleration_in_rpm_s_is_refused():
    """docs/flight.md: motor accelerations are judged over windows of 3 samples or more, 'logs at 50 Hz or faster';
    a 50 Hz log of rounded steps (49.99999999999996 Hz here, _window_samples' own example) is judged."""
    from propmap.io.flightlog_checks import FlightLogError

    log = _log(rate=50.0)
    assert log.rate_hz < 50.0  # (the rounded steps of the docstring's case)
    with pytest.raises(FlightLogError, match=r"motor 2's logged acceleration is 9.\d+ times .* in rpm/s"):
        _check(_motor_in_rpm_s(log, 1))


def test_a_40_hz_logs_motor_acceleration_is_not_judged():
    """docs/flight.md: below 50 Hz (a window of 2 samples) the motor acceleration is not judged (a window's few
    samples of a noisy derivative say nothing): the check leaves a 40 Hz log's column alone."""
    _check(_motor_in_rpm_s(_log(rate=40.0), 1))


def test_each_motor_is_judged_the_last_one_too():
    """Each motor on its own (docs/flight.md): the last motor's column in rpm/s is refused and named."""
    from propmap.io.flightlog_checks import FlightLogError

    for m in range(4):
        with pytest.raises(FlightLogError, match=rf"motor {m + 1}'s logged acceleration is 9.5\d times"):
            _check(_motor_in_rpm_s(_log(), m))


def test_a_motor_whose_acceleration_column_is_all_zeros_is_taken_as_not_logged():
    """All zeros are taken as not logged (docs/flight.md), a single motor's column as well (the code's comment)."""
    log = _log()
    acc = log.rotor_acceleration.copy()
    acc[:, 1] = 0.0
    _check(dataclasses.replace(log, rotor_acceleration=acc))


def test_samples_without_any_motor_acceleration_logged_are_left_out():
    """The samples where no motor's acceleration is logged (all motors exactly 0: a prefix written without them) are
    left out of the check (bb9fdebc), their speeds' change with them: a spin-up from 300 to 1100 rad/s logged without
    accelerations, then a steady hover whose logged accelerations carry a bias of -3 rad/s^2 (its speeds' change
    below the 10 rad/s^2 judged), passes."""
    log = _log()
    t = log.t
    om = np.where(t[:, None] < 1.0, 300.0 + 800.0 * t[:, None], 1100.0) * np.ones((1, 4))
    acc = np.where(t[:, None] < 1.0, 0.0, -3.0) * np.ones((1, 4))
    _check(dataclasses.replace(log, rotor_omega=om, rotor_acceleration=acc))


def test_a_motor_logged_stopped_is_left_out_of_the_acceleration_check():
    """A motor logged at 0 among flight speeds (a telemetry dropout, below OMEGA_STOPPED) is no change of speed: its
    windows are left out (the code's comment), so a dropout of half a second, its logged acceleration kept, does not
    make the motor's acceleration look negated."""
    log = _log()
    om = log.rotor_omega.copy()
    om[311:511, 2] = 0.0  # (from where the motor speeds up to where it slows down most)
    _check(dataclasses.replace(log, rotor_omega=om))


def test_a_motor_speeds_spike_is_warned_of_not_refused_as_an_acceleration():
    """A speed's spike is warned of as such and the windows holding it left out of the acceleration check
    (_derivative_ratio's docstring: a spike took a consistent log's ratio to 0.0002)."""
    log = _log()
    om = log.rotor_omega.copy()
    om[300, 2] = 5000.0
    with pytest.warns(UserWarning, match=r"1 sample\(s\) of the motor speed lie far from their neighbours"):
        _check(dataclasses.replace(log, rotor_omega=om))


def test_a_stopped_motor_leaves_out_only_its_own_windows():
    """Each motor is judged on its own (docs/flight.md): a motor logged at 0 throughout (its telemetry dead) leaves
    the other motors judged, and one of them in rpm/s is still refused."""
    from propmap.io.flightlog_checks import FlightLogError

    log = _motor_in_rpm_s(_log(), 0)
    om = log.rotor_omega.copy()
    om[:, 2] = 0.0
    with pytest.raises(FlightLogError, match=r"motor 1's logged acceleration is 9.5\d times"):
        _check(dataclasses.replace(log, rotor_omega=om))


def test_a_glitch_row_left_out_does_not_pass_a_mis_scaled_acceleration():
    """The windows holding a speed's spike are left out of the ratio (_derivative_ratio: both the speeds' change and
    the logged acceleration's means there): a glitch row, the speed and the acceleration both corrupted, does not
    make a column logged 100 times too small (refused: 'zeros or another quantity?') pass."""
    from propmap.io.flightlog_checks import FlightLogError

    log = _log()
    acc, om = 0.01 * log.rotor_acceleration, log.rotor_omega.copy()
    om[400, 0], acc[400, 0] = 5000.0, 1e5  # (the glitch row: a spike in both columns)
    with pytest.raises(FlightLogError, match=r"motor 1's logged acceleration is 0.01\d* times .* zeros or another"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # (the spike's own warning)
            _check(dataclasses.replace(log, rotor_acceleration=acc, rotor_omega=om))


# ---- the torque change at constant thrust (core/torque_change.py) ---------------------------------------------------
@pytest.fixture(scope="module")
def cal():
    return pm.default_params("apce_8x6")


def test_a_climbs_negative_thrust_is_said_as_the_windmill_brake(apc8x6, cal):
    """The docstring's example of a point without a hover reference, 'a negative thrust in the windmill brake': at
    800 rad/s and 26 m/s of climb apce_8x6 makes -0.27 N, which the message says."""
    loads = pm.rotor_loads(apc8x6, cal, 800.0, 26.0, 0.0)
    assert -0.3 < float(loads.thrust) < 0
    with pytest.raises(pm.TrimError, match=r"below the least hover makes there, about [\d.]+ N \(a negative thrust: "
                                           r"the windmill brake\)"):
        pm.torque_change_at_constant_thrust(apc8x6, cal, 800.0, 26.0, 0.0)


def test_the_hover_reference_stays_within_the_bounds_for_a_collective_beyond_them(apc8x6, cal):
    """``bounds`` are the collectives searched for the hover trim: an operating collective beyond them (hover at
    40 deg, bounds to 30 deg) gets a hover reference inside them, not its own collective."""
    d, loads, hover = pm.torque_change_at_constant_thrust(apc8x6, cal, 1200.0, 0.0, 0.0, collective=math.radians(40))
    c = float(hover.collective)
    assert math.radians(-20) <= c <= math.radians(30)
    assert float(hover.loads.thrust) == pytest.approx(float(loads.thrust), rel=1e-6)


# ---- the inertia's checks (vehicle/layout.py: check_inertia) -------------------------------------------------------
@pytest.fixture()
def fresh_triangle(monkeypatch):
    """check_inertia warns once per tensor and process: a clean record for the test."""
    from propmap.vehicle import layout

    monkeypatch.setattr(layout, "_TRIANGLE_WARNED", set())


def _triangle_warnings(inertia):
    veh = pm.read_vehicle("neurobem_quadrotor")  # (0.0025, 0.0021, 0.0043 kg m^2: within the triangle)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        dataclasses.replace(veh, inertia=inertia)
    return [str(w.message) for w in caught if "triangle" in str(w.message)]


def test_an_inertia_breaking_the_triangle_by_21_percent_is_warned_of(fresh_triangle):
    """docs/cli.md: principal moments that break the triangle inequality by more than 1% are warned of, 'RotorS'
    firefly by 21%' the example (its Ixx, Iyy, Izz 0.0347563, 0.0458929, 0.0977 kg m^2)."""
    said = _triangle_warnings([0.0347563, 0.0458929, 0.0977])
    assert len(said) == 1 and "1.21 times the sum" in said[0], said


def test_an_inertia_within_1_percent_of_the_triangle_is_not_warned_of(fresh_triangle):
    """A flat airframe is near equality: a tensor that misses the triangle by less than 1%
    (INERTIA_TRIANGLE_SLACK; 0.00201 against 0.001 + 0.001, 0.5%) is read without a word."""
    assert _triangle_warnings([0.001, 0.001, 0.00201]) == []
    assert len(_triangle_warnings([0.001, 0.001, 0.00203])) == 1  # (1.5%: warned of)


def test_an_inertia_not_quite_symmetric_is_refused():
    """check_inertia refuses a tensor that is not symmetric: an off-diagonal pair 0.5% apart (one mistyped)."""
    veh = pm.read_vehicle("neurobem_quadrotor")
    with pytest.raises(ValueError, match="^Vehicle.inertia must be symmetric"):
        dataclasses.replace(veh, inertia=[[0.0025, 1.0e-4, 0.0], [1.005e-4, 0.0021, 0.0], [0.0, 0.0, 0.0043]])


# ---- atomic writes (io/atomic.py: check_file_name, atomic_paths) --------------------------------------------------
def test_atomic_writes_refuse_a_path_that_names_no_file(tmp_path, monkeypatch):
    """check_file_name's docstring: '', Path(''), '..' and a trailing separator name no file (ValueError), 'x/.' (a
    folder, as 'x/') too; nothing is written."""
    from propmap.io.atomic import atomic_write, check_file_name

    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    for bad in ("", Path(""), "..", "sub/..", "new/", "new/.", str(tmp_path / "new") + "/."):
        with pytest.raises(ValueError, match="names no file"):
            check_file_name(bad)
        with pytest.raises(ValueError, match="names no file"):
            with atomic_write(bad) as fh:
                fh.write("a")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sub"] and not any((tmp_path / "sub").iterdir())
    check_file_name("sub/x.h")  # (a file's name: taken)


def test_a_failed_rename_names_the_target_not_the_temporary_file(tmp_path, monkeypatch):
    """atomic_paths' docstring: an OSError of the rename names the target, not its temporary file."""
    import errno

    from propmap.io.atomic import atomic_write

    def refuse(src, dst):
        raise OSError(errno.EXDEV, "Invalid cross-device link", str(src))

    monkeypatch.setattr(os, "replace", refuse)
    target = tmp_path / "x.h"
    with pytest.raises(OSError) as info:
        with atomic_write(target) as fh:
            fh.write("a")
    assert info.value.errno == errno.EXDEV and info.value.filename == str(target)
    assert list(tmp_path.iterdir()) == []  # (the temporary file removed)


# ---- trims (core/trim.py: the branch's words, the thin air) ---------------------------------------------------------
def test_the_branch_words_count_only_the_points_with_a_solution(apc8x6, cal):
    """TrimResult.branch: FALLING_BRANCH 'where every point's solution is on the falling branch'; a point with no
    solution (on_missing='nan') has none to be on: 1.6 N on the falling side at 5000 rpm (bounds 5-30 deg), 1.7 N
    made nowhere."""
    from propmap.core.trim import FALLING_BRANCH, trim_collective

    r = trim_collective(apc8x6, cal, [1.6, 1.7], 5000 * RPM, bounds=(math.radians(5), math.radians(30)),
                        on_missing="nan")
    assert list(r.n_solutions) == [1, 0] and bool(r.falling[0]) and np.isnan(r.collective[1])
    assert r.branch == FALLING_BRANCH


def test_air_a_twenty_fifth_of_sea_levels_is_suspected_before_grams(apc8x6, cal):
    """THIN_AIR_RHO is a tenth of sea level's density: at 0.05 kg/m^3 a thrust beyond 10 times the most is put down
    to the air, in trim_collective and trim_omega alike."""
    from propmap.core.trim import trim_collective, trim_omega

    thin = pm.Air(rho=0.05)
    for call in (lambda: trim_collective(apc8x6, cal, 2.0, 800.0, air=thin),
                 lambda: trim_omega(apc8x6, cal, 50.0, air=thin)):
        with pytest.raises(pm.TrimError, match=r"the air's density is 0.05 kg/m\^3 \(1.225 at sea level\)") as info:
            call()
        assert "grams" not in str(info.value)
    # at the threshold's edge: just below it the air is suspected, just above it grams (a review)
    for rho, words in ((0.12, "the air's density is 0.12 kg/m^3"), (0.125, "is the thrust in grams?")):
        with pytest.raises(pm.TrimError) as info:
            trim_collective(apc8x6, cal, 6.0, 800.0, air=pm.Air(rho=rho))
        assert words in str(info.value)


def test_a_thrust_50_times_the_most_is_asked_whether_it_is_in_grams(apc8x6, cal):
    """'a thrust beyond 10 times the most a rotor makes' (trim.THIN_AIR_RHO's comment): 203.5 N at 800 rad/s, where
    apce_8x6 makes at most 4.07 N in hover (150 gf would be 1.47 N)."""
    from propmap.core.trim import trim_collective

    with pytest.raises(pm.TrimError, match=r": 50 times the most it reaches; is the thrust in grams\? It is in N"):
        trim_collective(apc8x6, cal, 50 * 4.0701, 800.0)

