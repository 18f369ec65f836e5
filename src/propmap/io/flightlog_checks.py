"""The plausibility checks every flight log passes (io/flightlog.py reads the logs).

:func:`check_log` refuses, with one line naming the file and the sample, a log whose time does
not increase or is sampled below MIN_RATE_HZ, values beyond their plausible ranges (a unit or
column mistake) or not finite, negative motor speeds, an attitude quaternion not of unit norm,
an accelerometer whose mean reading is not gravity plus the log's acceleration (g units,
gravity removed, a z-down frame), rates that are the attitude's change times 57 or its negative
(deg/s, another frame), a velocity that the accelerations do not integrate to, and a logged
angular acceleration unlike the rates' change or motor acceleration unlike the motor speeds'
(or sampled faster than MAX_RATE_HZ); it warns of gaps in the time and of isolated
spikes. The limits are this module's constants, each with what it was set on.
"""

from __future__ import annotations

import math
import warnings
from typing import TYPE_CHECKING

import numpy as np

from ..core.air import G0

if TYPE_CHECKING:
    from .flightlog import FlightLog

__all__ = ["FlightLogError", "check_log"]

#: a log sampled more slowly than this is refused [Hz]: time in ms or us read as seconds (NeuroBEM logs 400 Hz,
#: PX4's slowest estimator topics tens of Hz; a 1 kHz log in ms would read as 1 Hz); dw/dt, differentiated from
#: the rates, needs the vehicle's motion resolved
MIN_RATE_HZ = 10.0
#: plausibility limits of logged values (refused beyond: a unit or column mistake)
OMEGA_MAX = 1e5  # [rad/s], the solver's limit
ACC_MAX = 2000.0  # [m/s^2]
#: spikes (:func:`_warn_spikes`): a sample this far from the median of the SPIKE_WINDOW samples around it, an
#: accelerometer's [m/s^2] (5 g; the four shared segments: none), a motor speed's as a fraction of it (and 100 rad/s)
SPIKE_WINDOW = 9
SPIKE_RATE_HZ = 200.0
SPIKE_ACC = 49.0
SPIKE_OMEGA = 0.3
#: a time step this many times the log's median is a gap, warned of (NeuroBEM's 400 Hz logs: at most 1.0)
GAP_STEPS = 20
RATE_MAX = 200.0  # [rad/s]
SPEED_MAX = 500.0  # [m/s]
MIN_SAMPLES = 2
G = G0  # [m/s^2]
#: the attitude quaternion's norm may differ from 1 by this (a logged one is normalised to about 1e-3)
QUAT_TOLERANCE = 0.05
#: the accelerometer's time-mean upward reading must lie within this fraction of g (plus three standard errors of
#: the mean) of g plus the log's mean vertical acceleration (the four NeuroBEM segments: within 0.006 m/s^2);
#: accelerations in g read 0.10 g, without gravity about 0, in a z-down frame -g; judged over logs of
#: GRAVITY_JUDGED s or more (a short window of a flip is all acceleration)
GRAVITY_TOLERANCE = 0.2
GRAVITY_JUDGED = 1.0  # [s]
#: the rates are judged against the attitude's change over RATE_WINDOW where both turn at this rms or more [rad/s]
#: (the NeuroBEM segments: ratios 0.996-1.022 at 0.36-1.11 rad/s; 0.71 in hover, at 0.05 rad/s, not judged)
RATE_JUDGED = 0.2
RATE_WINDOW = 0.02  # [s]
#: logged rates this many times the attitude's are refused as deg/s (180 / pi = 57.3); below RATE_RATIO_AGAINST, as
#: turning against it (another frame)
RATE_RATIO_DEG = (20.0, 150.0)
RATE_RATIO_AGAINST = -0.5
#: the body-frame kinematics dv/dt = a_s + R^T g - w x v, the velocity's change over a window against the integral:
#: refused where the rms difference exceeds KINEMATIC_TOLERANCE m/s^2 and KINEMATIC_RATIO times the rms acceleration
#: over windows of both KINEMATIC_WINDOWS (an input fuzzing audit, 2026-11-27; figures in docs/flight.md)
KINEMATIC_WINDOWS = (0.2, 0.5)  # [s]: refused where both windows miss
KINEMATIC_TOLERANCE = 1.0  # [m/s^2]
KINEMATIC_RATIO = 0.5
#: a logged angular acceleration over the rates' change (least squares, both ways, over ANGULAR_ACCELERATION_WINDOW)
#: must reach into this, judged where the rates change by ANGULAR_ACCELERATION_JUDGED rad/s^2 rms or more
ANGULAR_ACCELERATION_RATIO = (0.3, 3.0)
ANGULAR_ACCELERATION_WINDOW = 0.05  # [s]
ANGULAR_ACCELERATION_JUDGED = 1.0  # [rad/s^2]
#: the same for a logged motor acceleration (NeuroBEM's dmot columns) against the motor speeds' change, judged where
#: they change by this rms or more [rad/s^2] (the four shared segments: 177-1,231 rad/s^2, ratios 0.992-0.997; in
#: rpm/s 9.5 and 1e6 times too large were read without a word, their spin-up moments with them: a flight-log audit,
#: 2026-12-01)
ROTOR_ACCELERATION_JUDGED = 10.0  # [rad/s^2]
#: ... over windows of this many samples or more (logs at 50 Hz or faster)
ROTOR_ACCELERATION_MIN_WINDOW = 3
#: a motor speed below this is a stopped (or unreported) rotor [rad/s]: left out of the motor acceleration's check
#: here, and of a flight fit's samples (identify.flight_samples)
OMEGA_STOPPED = 1.0
#: a motor acceleration beyond this is refused [rad/s^2] (0 to 1000 rad/s in 1 ms; the shared segments reach 2.5e4)
ROTOR_ACCELERATION_MAX = 1e6
#: a log sampled faster than this is refused [Hz] (a time in another unit; flight_samples takes at most 10 kHz, and a
#: 20 kHz log lost every other sample, said as stopped rotors: a flight-log audit, 2026-12-01)
MAX_RATE_HZ = 1e4


class FlightLogError(ValueError):
    """A flight log that cannot be read; the message names the file and the problem."""


def check_log(log: FlightLog, name: str) -> None:
    """Refuse or warn of what the module docstring names: the sample count, the time, the
    values' ranges, the frames and units (attitude, gravity, rates, angular acceleration, then
    the kinematics), then gaps and spikes (warned).

    Parameters
    ----------
    log : FlightLog
        As a reader made it (io/flightlog.py).
    name : str
        The file as messages show it.

    Raises
    ------
    FlightLogError
        Fewer than MIN_SAMPLES samples, time not strictly increasing or sampled below
        MIN_RATE_HZ or above MAX_RATE_HZ, a value not finite or beyond its limit (RATE_MAX,
        ACC_MAX, SPEED_MAX, OMEGA_MAX, ROTOR_ACCELERATION_MAX), a negative motor speed, or
        frames and units that the attitude, gravity, rates (deg/s, another frame), angular- and
        motor-acceleration and kinematics checks refuse (one line naming the file and sample).

    Warns
    -----
    UserWarning
        A gap of GAP_STEPS median steps or more in the time; isolated spikes.
    """
    if log.n < MIN_SAMPLES:
        raise FlightLogError(f"{name}: {log.n} sample(s); a log needs at least {MIN_SAMPLES}")
    dt = np.diff(log.t)
    if not np.all(dt > 0):
        i = int(np.argmax(~(dt > 0)))
        same = int(np.sum(dt == 0))  # (repeated stamps: rows written twice, or a time rounded: a flight-log audit)
        why = ("" if not same else f"; {same} sample(s) repeat the time before them: remove rows written twice, or "
               "give the time to its full precision (a time rounded coarser than the sampling repeats)")
        raise FlightLogError(f"{name}: time does not increase at sample {i + 2} (t = {log.t[i + 1]:.6g} s after "
                             f"{log.t[i]:.6g} s){why}")
    if log.rate_hz < (1 - 1e-3) * MIN_RATE_HZ:  # (a 10 Hz log's rounded steps: refused at 9.99 Hz, an audit)
        units = "is it in milliseconds or microseconds? " if log.rate_hz <= 2.0 else ""
        raise FlightLogError(f"{name}: the time steps by {1 / log.rate_hz:.6g} s in the median ({log.rate_hz:.3g} Hz): "
                             f"{units}a log's time is read in seconds, and a flight "
                             f"log sampled below {MIN_RATE_HZ:g} Hz does not resolve the vehicle's motion (its "
                             "angular acceleration is differentiated from the rates)")
    if log.rate_hz > (1 + 1e-3) * MAX_RATE_HZ:
        raise FlightLogError(f"{name}: the time steps by {1 / log.rate_hz:.6g} s in the median ({log.rate_hz:.4g} Hz), "
                             f"faster than the {MAX_RATE_HZ:g} Hz propmap samples a flight log at, at most: is the "
                             "time in seconds?")
    # (the attitude first: a ULog's velocity is turned into body axes with it, and a NaN quaternion was said as a NaN
    # velocity, a file audit, 2026-12-01)
    checks = [("attitude", log.attitude, math.inf, ""),
              ("angular_velocity", log.angular_velocity, RATE_MAX, "rad/s"),
              ("specific_force", log.specific_force, ACC_MAX, "m/s^2"),
              ("velocity", log.velocity, SPEED_MAX, "m/s"),
              ("rotor_omega", log.rotor_omega, OMEGA_MAX, "rad/s")]
    if log.angular_acceleration is not None:  # (a logged derivative's NaN surfaced later as 'FlightSamples.moment')
        checks.append(("angular_acceleration", log.angular_acceleration, math.inf, "rad/s^2"))
    if log.rotor_acceleration is not None:
        checks.append(("rotor_acceleration", log.rotor_acceleration, ROTOR_ACCELERATION_MAX, "rad/s^2"))
    for what, a, limit, unit in checks:
        bad = ~np.isfinite(a) | (np.abs(a) > limit)
        if bad.any():
            i = int(np.argmax(bad.any(axis=1)))
            if not np.all(np.isfinite(a[i])):
                raise FlightLogError(f"{name}: sample {i + 1}: {what} {a[i].round(6).tolist()} is not finite (a gap "
                                     "in the log: cut it out, or the sample)")
            raise FlightLogError(f"{name}: sample {i + 1}: {what} {a[i].round(6).tolist()} beyond +-{limit:g} {unit} "
                                 "(a unit or column mistake?)")
    if np.any(log.rotor_omega < 0):
        i = int(np.argmax((log.rotor_omega < 0).any(axis=1)))
        raise FlightLogError(f"{name}: sample {i + 1}: negative motor speed {log.rotor_omega[i].tolist()} rad/s "
                             "(give speeds as magnitudes; the spin is the vehicle file's)")
    _check_frames(log, name)
    big = int(np.argmax(dt))  # (warned after the refusals: a refused log printed the warning too, a review)
    if dt[big] > GAP_STEPS * np.median(dt):  # (a 5 s jump inside a 2 s log was read without a word: a flight audit)
        warnings.warn(f"{name}: a gap of {dt[big]:.3g} s in the log's time at t = {log.t[big]:.6g} s "
                      f"({dt[big] * log.rate_hz:.0f} median steps): the samples either side are read as they are"
                      + ("; the angular acceleration is differentiated across it: cut the log there"
                         if log.angular_acceleration is None else ""), UserWarning, stacklevel=3)
    _warn_spikes(log, name)


def _warn_spikes(log: FlightLog, name: str) -> None:
    """Warn of isolated samples far from their neighbours (SPIKE_WINDOW samples' median, in logs
    sampled at SPIKE_RATE_HZ or faster): an accelerometer reading SPIKE_ACC beyond it, a motor
    speed SPIKE_OMEGA of it and 100 rad/s beyond (telemetry glitches: two samples at 300 m/s^2
    took a log's Fz rms from 0.27 to 2.6 N without a word, a flight-log audit, 2026-11-27). They
    are read as logged: the warning says how many and where."""
    if log.n < SPIKE_WINDOW or log.rate_hz < SPIKE_RATE_HZ:  # (slower, a sample's neighbours are too far away in time
        return  # to tell a glitch from the motion: a consistent agile log at 20 Hz had one, a test's)
    for what, bad in (("accelerometer", np.any(_spikes(log.specific_force, "acc"), axis=1)),
                      ("motor speed", np.any(_spikes(log.rotor_omega, "omega"), axis=1))):
        if bad.any():
            i = int(np.argmax(bad))
            warnings.warn(f"{name}: {int(bad.sum())} sample(s) of the {what} lie far from their neighbours (spikes; "
                          f"the first at sample {i + 1}, t = {log.t[i]:.6g} s): they are read as logged and weigh in "
                          "the fit and the rms; cut them out if they are glitches", UserWarning, stacklevel=4)


def _spikes(a: np.ndarray, kind: str) -> np.ndarray:
    """The isolated samples of ``a`` (N, k) far from the median of the SPIKE_WINDOW samples around
    them: SPIKE_ACC beyond it for an accelerometer (``kind`` "acc"), SPIKE_OMEGA of it and 100 rad/s
    beyond for a motor speed ("omega"); boolean, shaped like ``a``."""
    from scipy.ndimage import median_filter

    med = median_filter(a, size=(SPIKE_WINDOW, 1), mode="nearest")
    d = np.abs(a - med)
    return d > SPIKE_ACC if kind == "acc" else (d > SPIKE_OMEGA * np.abs(med)) & (d > 100.0)


def _check_frames(log: FlightLog, name: str) -> None:
    """The attitude, the accelerometer and the rate gyro against each other: a unit quaternion
    (QUAT_TOLERANCE); in a shorter log, the accelerometer's median reading along body z, where the
    rotors push, not below -g/2 (a z-down body frame); over a log of GRAVITY_JUDGED s or more, the
    accelerometer's time-mean upward
    reading, turned into the world frame with the attitude, against g plus the mean vertical
    acceleration that the logged velocity's change asks for (within GRAVITY_TOLERANCE g plus three
    standard errors of the mean: accelerations in g, gravity removed, a z-down frame); the rates
    against the attitude's change over RATE_WINDOW s (RATE_RATIO_DEG: rates in deg/s; below
    RATE_RATIO_AGAINST: another frame), judged where both turn at RATE_JUDGED rad/s rms or more."""
    from scipy.spatial.transform import Rotation

    norm = np.linalg.norm(log.attitude, axis=1)
    bad = np.abs(norm - 1.0) > QUAT_TOLERANCE
    if bad.any():
        i = int(np.argmax(bad))
        raise FlightLogError(f"{name}: sample {i + 1}: attitude quaternion {log.attitude[i].round(6).tolist()} has "
                             f"norm {norm[i]:.4g}, not 1 (within {QUAT_TOLERANCE:g}): a column mistake?")
    q = log.attitude / norm[:, None]
    if log.duration < GRAVITY_JUDGED and float(np.median(log.specific_force[:, 2])) < -0.5 * G:
        # (the gravity test below needs a second of log; a 0.9 s log in a z-down frame was scored with exit 0 and an
        # Fz error of 13 N: a flight-log audit, 2026-11-28. A multirotor's rotors push along body z: its accelerometer
        # reads up along it, in hover g, whatever the log's length)
        raise FlightLogError(f"{name}: the accelerometer reads {float(np.median(log.specific_force[:, 2])):.4g} m/s^2 "
                             "along body z in the median, where the rotors push (g in hover): a z-down (FRD) body "
                             "frame? (docs/flight.md, Flight logs)")
    if log.duration >= GRAVITY_JUDGED:
        turn = Rotation.from_quat(q)  # (x, y, z, w), body -> z-up world
        f_up = turn.apply(log.specific_force)[:, 2]
        v_up = turn.apply(log.velocity)[:, 2]
        up = float(np.sum(0.5 * (f_up[1:] + f_up[:-1]) * np.diff(log.t))) / log.duration  # (the time mean)
        expected = G + (v_up[-1] - v_up[0]) / log.duration
        tolerance = GRAVITY_TOLERANCE * G + 3.0 * float(np.std(f_up)) / math.sqrt(log.n)
        if abs(up - expected) > tolerance:
            raise FlightLogError(f"{name}: the accelerometer reads {up:.4g} m/s^2 upwards on average (its readings "
                                 "turned into the world frame with the logged attitude), where the log's vertical "
                                 f"speed asks for {expected:.4g} (g plus its mean vertical acceleration; within "
                                 f"{tolerance:.3g}): accelerations in g, gravity removed, a z-down (FRD) body frame, "
                                 "or a quaternion not (x, y, z, w) from body to world? (docs/flight.md, Flight logs)")
    _check_rates(log, q, name)
    _check_angular_acceleration(log, name)
    if log.duration >= GRAVITY_JUDGED:  # (after the rates: rates in deg/s would miss here first, naming the velocity)
        _check_kinematics(log, Rotation.from_quat(q), name)


def _check_angular_acceleration(log: FlightLog, name: str) -> None:
    """A logged angular acceleration (NeuroBEM's columns 2-4, the measured moments' I dw/dt) against
    the logged rates' change (:func:`_derivative_ratio`), judged where the rates change by
    ANGULAR_ACCELERATION_JUDGED rad/s^2 rms or more (in deg/s^2 57, zeros 0, negated -1, each read
    without a word, the measured moments 57 times too large: an input fuzzing audit, 2026-11-27; the
    NeuroBEM segments 0.97-0.99, a review's consistent logs at 20-50 Hz 0.98-0.997 and its
    noisy-gyro one 0.90 and 0.97); and a logged motor acceleration (NeuroBEM's dmot columns, the
    spin-up moment's) against the motor speeds' change, each motor on its own, judged from
    ROTOR_ACCELERATION_JUDGED over windows of ROTOR_ACCELERATION_MIN_WINDOW samples or more
    (the speeds' spikes left out), unless all zeros (not logged)."""
    if log.angular_acceleration is not None:
        b1 = _derivative_ratio(log, log.angular_velocity, log.angular_acceleration, ANGULAR_ACCELERATION_JUDGED)
        if b1 is not None:
            # (1/57.3: the rates in deg/s, the acceleration in rad/s^2; on a slow log the rates' own check does not
            # judge, and this said "zeros or another quantity?": a flight-log audit, 2026-11-30)
            why = ("in deg/s^2?" if 20 <= b1 <= 150 else
                   "are the rates in deg/s (the ratio near 1/57.3)?" if 1 / 150 <= b1 <= 1 / 20 else _odd_ratio(b1))
            raise FlightLogError(f"{name}: the logged angular acceleration is {b1:.3g} times the logged rates' change "
                                 f"(within {ANGULAR_ACCELERATION_RATIO[0]:g}-{ANGULAR_ACCELERATION_RATIO[1]:g} "
                                 f"expected): {why} It is read in rad/s^2, body axes (the measured moment is I dw/dt + "
                                 "w x I w)")
    # (all zeros: not logged, as a ULog's, whose spin-up moment is none either; below ROTOR_ACCELERATION_MIN_WINDOW
    # samples a window's dmot is a point sample of a noisy derivative: the shared slow segment decimated to 20 Hz was
    # refused at every phase, a review; each motor on its own: one motor's column in rpm/s passed among three good
    # ones, a review)
    acc = log.rotor_acceleration
    if acc is None or not np.any(acc) or _window_samples(log.rate_hz) < ROTOR_ACCELERATION_MIN_WINDOW:
        return
    calm = ~_spikes(log.rotor_omega, "omega")  # (a speed's spike, warned of, is no change of speed)
    # (a sample whose motors' accelerations are all exactly 0 is one where they were not logged, as a whole column of
    # zeros: a log's prefix on the ground, written without them, made every motor's ratio 0 at its step to flight)
    calm &= ~np.all(acc == 0, axis=1)[:, None]
    # (a motor logged stopped, at 0 among flight speeds: a telemetry dropout, which the flight fit leaves out; its steps
    # are no change of speed)
    calm &= log.rotor_omega >= OMEGA_STOPPED
    for m in range(acc.shape[1]):
        if not np.any(acc[:, m]):  # (a motor's column of zeros: not logged)
            continue
        b1 = _derivative_ratio(log, log.rotor_omega[:, m:m + 1], acc[:, m:m + 1], ROTOR_ACCELERATION_JUDGED,
                               calm[:, m:m + 1])
        if b1 is not None:
            why = ("in rpm/s (the ratio near 9.55)?" if 6 <= b1 <= 14 else
                   "are the motor speeds in rpm (the ratio near 1/9.55)?" if 1 / 14 <= b1 <= 1 / 6 else
                   _odd_ratio(b1, "negated, or another motor's?"))
            raise FlightLogError(f"{name}: motor {m + 1}'s logged acceleration is {b1:.3g} times its logged speed's "
                                 f"change (within {ANGULAR_ACCELERATION_RATIO[0]:g}-{ANGULAR_ACCELERATION_RATIO[1]:g} "
                                 f"expected): {why} It is read in rad/s^2 (the spin-up moment's)")


def _window_samples(rate_hz: float) -> int:
    """The samples of an ANGULAR_ACCELERATION_WINDOW at ``rate_hz``, rounded half up (a 50 Hz log's
    49.99999999999996 Hz of rounded steps made 2.5 samples 2, and its motor accelerations unjudged:
    a review), at least 1."""
    return max(1, int(math.floor(ANGULAR_ACCELERATION_WINDOW * rate_hz + 0.5 + 1e-6)))


def _odd_ratio(b1: float, against: str = "another frame or sign?") -> str:
    """The likely cause of a logged derivative ``b1`` times its variable's change, in words
    (``against`` where they correlate negatively)."""
    lo = ANGULAR_ACCELERATION_RATIO[0]
    return "zeros or another quantity?" if abs(b1) < lo else against if b1 < 0 else "another unit or column?"


#: the fewest windows a logged derivative is judged over (_derivative_ratio)
DERIVATIVE_MIN_WINDOWS = 10


def _derivative_ratio(log: FlightLog, values: np.ndarray, logged: np.ndarray, judged: float,
                      calm: np.ndarray | None = None) -> float | None:
    """None where the logged derivative ``logged`` of ``values`` (rows at the log's times) is
    plausible, else the least-squares ratio of it on the values' change over
    ANGULAR_ACCELERATION_WINDOW s (the logged one's trapezoid mean over the same windows): a
    derivative is implausible where the two least-squares ratios (of either on the other, which
    noise in one or the other pulls apart) both lie outside ANGULAR_ACCELERATION_RATIO, or they
    correlate negatively, where the values change by ``judged`` rms or more. With ``calm`` (shaped
    like ``values``), the windows holding a sample not calm are left out (a motor speed's spike,
    warned of as such, took the ratio of a consistent log to 0.0002)."""
    k = _window_samples(log.rate_hz)
    if log.n <= k:
        return None
    d = (values[k:] - values[:-k]) / (log.t[k:] - log.t[:-k])[:, None]
    means = _window_means(log.t, logged, k)
    if calm is not None:  # (the windows holding a sample not calm left out)
        inside = np.concatenate([np.zeros((1, calm.shape[1]), int), np.cumsum(~calm, axis=0)])
        keep = inside[k + 1:] - inside[:-k - 1] == 0
        # (the rms over the windows kept: the left-out ones, counted as zeros, diluted it, so a log whose first seconds
        # carry no motor acceleration went unjudged, an audit of stop 105, 2026-12-02)
        d, means = d[keep], means[keep]
    # (fewer than DERIVATIVE_MIN_WINDOWS windows judge nothing, their noise would: a review)
    if d.size < DERIVATIVE_MIN_WINDOWS or np.sqrt(np.mean(d**2)) < judged:
        return None
    ld, dd, ll = float(np.sum(means * d)), float(np.sum(d * d)), float(np.sum(means * means))
    lo, hi = ANGULAR_ACCELERATION_RATIO
    b1 = ld / dd
    if ld > 0 and (ll / ld >= lo and b1 <= hi):  # ([b1, b2] meets [lo, hi]: b1 <= b2 where they correlate)
        return None
    return b1


def _check_rates(log: FlightLog, q, name: str) -> None:
    """The logged rates against the unit attitude quaternions ``q``' change (_check_frames)."""
    q = q * np.where(np.concatenate([[False], np.cumsum(np.sum(q[1:] * q[:-1], axis=1) < 0) % 2 == 1]), -1.0,
                     1.0)[:, None]  # (q and -q are one attitude)
    k = max(1, int(round(RATE_WINDOW * log.rate_hz)))  # (a derivative over one sample step is the noise's)
    if log.n <= k:
        return
    dq = (q[k:] - q[:-k]) / (log.t[k:] - log.t[:-k])[:, None]
    x, y, z, w = (0.5 * (q[k:] + q[:-k])).T
    dx, dy, dz, dw = dq.T
    w_att = 2 * np.column_stack([w * dx - x * dw - y * dz + z * dy, w * dy + x * dz - y * dw - z * dx,
                                 w * dz - x * dy + y * dx - z * dw])  # body rates of the attitude: 2 conj(q) dq/dt
    w_log = 0.5 * (log.angular_velocity[k:] + log.angular_velocity[:-k])
    if min(np.sqrt(np.mean(w_att**2)), np.sqrt(np.mean(w_log**2))) < RATE_JUDGED:
        return
    ratio = float(np.sum(w_log * w_att) / np.sum(w_att * w_att))
    if RATE_RATIO_DEG[0] <= ratio <= RATE_RATIO_DEG[1]:
        raise FlightLogError(f"{name}: the logged body rates are {ratio:.3g} times those of the logged attitude's "
                             "change: are they in deg/s? A log's rates are read in rad/s")
    if ratio < RATE_RATIO_AGAINST:
        raise FlightLogError(f"{name}: the logged body rates turn against the logged attitude (ratio {ratio:.3g}): "
                             "rates in another body frame (z down?) or a quaternion from world to body?")


def _window_means(t: np.ndarray, a: np.ndarray, k: int) -> np.ndarray:
    """The trapezoid-rule mean of ``a`` (rows at times ``t``) over each window [t_i, t_i+k]."""
    c = np.concatenate([np.zeros((1, a.shape[1])),
                        np.cumsum(0.5 * (a[1:] + a[:-1]) * np.diff(t)[:, None], axis=0)])
    return (c[k:] - c[:-k]) / (t[k:] - t[:-k])[:, None]


def _check_kinematics(log: FlightLog, turn, name: str) -> None:
    """The logged body-frame velocity against the accelerometer: the velocity's change over a
    window against the trapezoid integral of dv/dt = a_s + R^T g - w x v over the same window (the
    accelerometer's vibration and the velocity's noise averaged out); refused where it misses by
    more than KINEMATIC_TOLERANCE and KINEMATIC_RATIO times the rms acceleration over windows of
    both KINEMATIC_WINDOWS: a velocity in the world frame, the z-down body frame or km/h was read
    without a word, its force errors up to 7.7 N (an input fuzzing audit, 2026-11-27; a review
    measured consistent logs at 20-400 Hz with a 5 cm lever arm, 50 ms of velocity delay, 3 m/s^2
    of accelerometer noise and differentiated motion-capture positions at most 0.84 of the limit)."""
    accel = log.specific_force + turn.inv().apply(np.array([0.0, 0.0, -G]))  # a_s + R^T g = dv/dt + w x v
    rate = accel - np.cross(log.angular_velocity, log.velocity)  # dv/dt
    worst = None
    for window in KINEMATIC_WINDOWS:
        k = max(1, int(round(window * log.rate_hz)))
        if log.n <= k:
            return
        change = (log.velocity[k:] - log.velocity[:-k]) / (log.t[k:] - log.t[:-k])[:, None]
        miss = float(np.sqrt(np.mean((change - _window_means(log.t, rate, k)) ** 2)))
        size = float(np.sqrt(np.mean(_window_means(log.t, accel, k) ** 2)))
        if miss <= max(KINEMATIC_TOLERANCE, KINEMATIC_RATIO * size):
            return
        worst = worst or (miss, size, window, k, change)
    miss, size, window, k, change = worst
    # (rates in deg/s make w x v 57 times large: said as a velocity in the world frame, a flight-log audit, 2026-11-30)
    degrees = accel - np.cross(np.radians(log.angular_velocity), log.velocity)
    if float(np.sqrt(np.mean((change - _window_means(log.t, degrees, k)) ** 2))) <= max(
            KINEMATIC_TOLERANCE, KINEMATIC_RATIO * size):
        raise FlightLogError(f"{name}: the logged velocity's change (in the body frame) misses what the accelerometer "
                             f"and the rates make of it (dv/dt = a_s + R^T g - w x v) by {miss:.3g} m/s^2 rms over "
                             f"{window:g} s, and agrees with the rates read in deg/s: are they in deg/s? A log's rates "
                             "are read in rad/s")
    raise FlightLogError(f"{name}: the logged velocity's change (in the body frame) misses what the accelerometer "
                         f"and the rates make of it (dv/dt = a_s + R^T g - w x v) by {miss:.3g} m/s^2 rms over "
                         f"{window:g} s, where the acceleration is {size:.3g} m/s^2 rms: is the velocity in the body "
                         "frame (x forward, y left, z up), not the world's or a z-down one, and in m/s? "
                         "(docs/flight.md, Flight logs)")
