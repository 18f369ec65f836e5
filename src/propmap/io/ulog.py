"""PX4 ULog flight logs (read with pyulog, https://github.com/PX4/pyulog): the topics
``vehicle_acceleration`` (or ``sensor_combined``), ``vehicle_angular_velocity`` (with
``xyz_derivative`` when logged), ``vehicle_attitude``, ``vehicle_local_position`` and the motor
speeds from ``esc_status`` (``esc_rpm``), or, with a stated linear mapping rpm = a + b u, from
``actuator_outputs``. PX4's body frame is forward-right-down and its world frame
north-east-down: vectors are turned into propmap's frame (x forward, y left, z up; y and z
negated) and the velocity rotated into the body frame with the attitude
(:func:`read_ulog`; io/flightlog.py makes the :class:`~propmap.io.flightlog.FlightLog`). The
motor speeds and the log's rotor geometry are read by :mod:`propmap.io.ulog_motors`, the topics
through :mod:`propmap.io.ulog_topics`.
"""

from __future__ import annotations

import builtins
import io
import threading

import numpy as np

from ..core.units import RPM
from .ulog_motors import _px4_rotor_layout, _ulog_motors
from .ulog_topics import _has, _topic

_FRD_TO_FLU = np.array([1.0, -1.0, -1.0])


#: a gap in a topic other than the accelerations' longer than this [s] is warned of, whatever its rate
GAP_S = 1.0
#: a topic other than the accelerations' logged more slowly than this [Hz] (by more than 10%: PX4 logs many topics at
#: exactly 10 Hz) is warned of (older PX4 releases' default logging profile records esc_status at 4 Hz): interpolated
#: to the accelerations' timestamps, it misses what changes faster
SLOW_TOPIC_HZ = 10.0
#: a log whose topics' common time leaves out more than this fraction of its accelerations says so (a topic that starts
#: late or ends early: the ESC telemetry lost in flight)
SPAN_NOTE_FRACTION = 0.05


def _out_of_order(t: np.ndarray) -> np.ndarray:
    """Mask of the messages whose timestamps break the topic's time order: a repeat of the one
    before; then, in up to 8 passes, one that lies outside its neighbours' interval where they are
    in order (a stale, zero or forward stamp; at either end, one out of order with the next two in
    order); then any at or before an earlier kept one."""
    bad = np.zeros(t.size, dtype=bool)
    bad[1:] = t[1:] == t[:-1]
    for _ in range(8):
        idx = np.flatnonzero(~bad)
        u = t[idx]
        if u.size < 3 or np.all(np.diff(u) > 0):
            break
        a, b, c = u[:-2], u[1:-1], u[2:]
        lone = np.concatenate([[u[0] >= u[1] and u[1] < u[2]], (a < c) & ~((a < b) & (b < c)),
                               [u[-1] <= u[-2] and u[-3] < u[-2]]])
        if not lone.any():
            break
        bad[idx[lone]] = True
    idx = np.flatnonzero(~bad)
    u = t[idx]
    later = np.zeros(u.size, dtype=bool)
    later[1:] = u[1:] <= np.maximum.accumulate(u)[:-1]
    bad[idx[later]] = True
    return bad


def _in_time_order(topic: str, name: str, said: list, t: np.ndarray, *columns):
    """(t, *columns) without the messages out of the topic's time order (:func:`_out_of_order`),
    said in ``said``: np.interp needs increasing times, and one stamped 0 read an rpm of 11 for 0.5
    (a PX4 audit, 2026-11-27); one stamped forward left out the rest of its topic (a review)."""
    bad = _out_of_order(t)
    if not bad.any():
        return (t, *columns)
    i = int(np.argmax(bad))
    said.append(f"{name}: topic {topic!r}: {int(bad.sum())} message(s) out of time order left out (the first, "
                f"message {i + 1}, stamped {t[i]:.6g} s since boot)")
    keep = ~bad
    return (t[keep], *(None if c is None else c[keep] for c in columns))


def _check_steps(topic: str, t: np.ndarray, lo: float, hi: float, name: str, gap_steps: float, said: list) -> None:
    """Say in ``said`` a topic's gap (a step longer than ``gap_steps`` median steps or GAP_S) or
    its rate below SLOW_TOPIC_HZ (by more than 10%: PX4 logs topics at exactly 10 Hz) within [lo,
    hi], the time every topic covers: it is interpolated across (a 2 s hole in the attitude read
    20 deg off, a 1.5 s dropout of esc_status 3000 rpm off, without a word; only the
    accelerations' gaps were warned of: a PX4 audit, 2026-11-27)."""
    inside = (t >= lo) & (t <= hi)
    i0, i1 = max(int(np.argmax(inside)) - 1, 0), min(t.size - 1 - int(np.argmax(inside[::-1])) + 1, t.size - 1)
    dt = np.diff(t[i0:i1 + 1])  # (with the messages either side of the window: a hole across its edge counts)
    if dt.size == 0:
        return
    step = float(np.median(dt))
    big = int(np.argmax(dt))
    if dt[big] > min(gap_steps * step, GAP_S):
        said.append(f"{name}: topic {topic!r}: a gap of {dt[big]:.3g} s at {t[i0 + big]:.6g} s since boot "
                    f"({dt[big] / step:.0f} median steps): interpolated across")
    elif step > 1.1 / SLOW_TOPIC_HZ:
        said.append(f"{name}: topic {topic!r} logged at {1.0 / step:.3g} Hz: interpolated to the accelerations' "
                    "timestamps, it misses what changes faster (log it faster)")


def _rotate_ned_to_body(q_wxyz: np.ndarray, v: np.ndarray) -> np.ndarray:
    """R(q)^T v: a NED vector into the FRD body frame, q (w, x, y, z) FRD -> NED."""
    w, x, y, z = q_wxyz.T
    R = np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)
    return np.einsum("nji,nj->ni", R, v)


class _FileBytes(io.BytesIO):
    """A ULog file's bytes for pyulog, which steps back over a damaged message by its size field:
    where that message was cut short by the end of the file, the step lands before the message,
    and pyulog read the definitions again from there without end (a damaged header hung
    `propmap wrench` at full CPU: a PX4 audit, 2026-11-27; at the file's start, where io.BytesIO
    clamps the seek, and in a file of more than 64 KiB, where it does not: a review). A relative
    seek back before the earlier of the last two reads' starts (a message's header and payload)
    raises OSError, as a seek before a file's start does; pyulog never steps back further.
    ``cut`` records a read the file's end cut short (fewer bytes than asked, but for a header's
    3 bytes met with none, a whole file's end): a file that ends inside a message, which pyulog
    stops at without a word (power lost, a full card: a flight-log audit, 2026-11-28)."""

    _starts = (0, 0)
    cut = False

    def read(self, size=-1):
        self._starts = (self._starts[1], self.tell())
        data = super().read(size)
        # (pyulog meets a whole file's end reading a 3-byte message header and getting nothing; a payload that gets
        # nothing after its header is a cut as well: a review)
        if size is not None and size > 0 and len(data) < size and (data or size != 3):
            self.cut = True
        return data

    def seek(self, pos, whence=0):
        target = pos if whence == 0 else (self.tell() + pos if whence == 1 else len(self.getbuffer()) + pos)
        if target < 0 or (whence == 1 and pos < 0 and target < min(self._starts)):
            raise OSError(f"a damaged message: a step back to byte {target}, before the message read at byte "
                          f"{min(self._starts)}")
        return super().seek(pos, whence)


#: the notices pyulog prints while this thread parses a file (pyulog prints them on standard output, the CLI's
#: --json; a review found redirecting sys.stdout caught other threads' prints and, from two threads, lost it)
_PARSING = threading.local()


def _pyulog_print(*args, **kwargs):
    """pyulog's print: into the parsing thread's list of notices, elsewhere the built-in print."""
    sink = getattr(_PARSING, "notices", None)
    if sink is None or kwargs.get("file") is not None:
        return builtins.print(*args, **kwargs)
    sink.append(" ".join(str(a) for a in args))


def read_ulog(raw: bytes, name: str, motor_map, n_motors: int | None = None, *, error: type[ValueError],
              min_samples: int, gap_steps: float) -> tuple[dict, list]:
    """The fields of a :class:`propmap.io.flightlog.FlightLog` read from a ULog file's bytes:
    every topic interpolated to the acceleration topic's timestamps over the time they all
    cover, turned into propmap's body frame (module docstring).

    Parameters
    ----------
    raw : bytes
        The file's content.
    name : str
        The file as shown in messages.
    motor_map : (float, float) or None
        rpm = a + b * actuator_outputs; None: ``esc_status``'s rpm.
    n_motors : int, optional
        The vehicle's rotor count (``actuator_outputs``: the outputs of motors 1..n_motors,
        :func:`propmap.io.ulog_motors._output_motor_order`, else the first outputs).
    error : type of ValueError
        Raised, with one line naming the file, for what cannot be read.
    min_samples : int
        The fewest samples of the acceleration topic the topics' overlap must hold.
    gap_steps : float
        A step of another topic longer than this many of its median steps, or than GAP_S, within
        the time the topics cover is said (the acceleration topic's: io/flightlog.py).

    Returns
    -------
    fields : dict
        ``t`` [s] from 0 at the first acceleration sample every topic covers (shape (N,)),
        ``angular_velocity`` [rad/s], ``angular_acceleration`` [rad/s^2] (None where not logged),
        ``specific_force`` [m/s^2], ``velocity`` [m/s] (body frame, (N, 3)), ``attitude``
        (x, y, z, w), ``rotor_omega`` [rad/s] (N, n_motors), ``rotor_acceleration`` (None) and
        ``motor_order`` (str).
    said : list of str
        What the caller warns of once the log is accepted: a damaged file pyulog read on (or its
        other notices); a file that ends inside a message; a topic's messages out of time order
        (left out), a gap in it or a rate below SLOW_TOPIC_HZ; several actuator_outputs instances.

    Raises
    ------
    error
        A file pyulog cannot read, a topic or field missing, motors the ESCs' actuator_function
        or the output functions do not assign (or assign beyond ``n_motors``, or change during the
        log), too short an overlap of the topics.
    """
    ulog, name, said = _parsed(raw, name, error)
    acc_topic = "vehicle_acceleration" if _has(ulog, "vehicle_acceleration") else "sensor_combined"
    if not _has(ulog, acc_topic):
        found = ", ".join(sorted({d.name for d in ulog.data_list}))[:200]
        raise error(f"{name}: no accelerations: neither topic 'vehicle_acceleration' nor 'sensor_combined' "
                    f"is in the log (topics found: {found or 'none'})")
    acc_fields = ["xyz[0]", "xyz[1]", "xyz[2]"] if acc_topic == "vehicle_acceleration" else [
        "accelerometer_m_s2[0]", "accelerometer_m_s2[1]", "accelerometer_m_s2[2]"]
    t, acc = _topic(ulog, acc_topic, acc_fields, name, error)
    t, acc = _in_time_order(acc_topic, name, said, t, acc)  # (as every topic: it was refused, the others filtered)
    _slow_accelerations(ulog, acc_topic, t, name, said)
    tw, rates = _topic(ulog, "vehicle_angular_velocity", ["xyz[0]", "xyz[1]", "xyz[2]"], name, error)
    deriv = None
    d = [s for s in ulog.data_list if s.name == "vehicle_angular_velocity"]
    if d and all(f"xyz_derivative[{k}]" in d[0].data for k in range(3)):
        deriv = _topic(ulog, "vehicle_angular_velocity", [f"xyz_derivative[{k}]" for k in range(3)], name, error)[1]
    tw, rates, deriv = _in_time_order("vehicle_angular_velocity", name, said, tw, rates, deriv)
    tq, q = _topic(ulog, "vehicle_attitude", ["q[0]", "q[1]", "q[2]", "q[3]"], name, error)
    tq, q = _in_time_order("vehicle_attitude", name, said, tq, q)
    # q and -q are one attitude: make the sequence continuous before interpolating it component by component (a
    # sign flip between two samples would otherwise interpolate through 0)
    if q.shape[0] > 1:
        flips = np.sum(q[1:] * q[:-1], axis=1) < 0
        q = q * np.concatenate([[1.0], np.where(np.cumsum(flips) % 2 == 1, -1.0, 1.0)])[:, None]
    tv, vel = _topic(ulog, "vehicle_local_position", ["vx", "vy", "vz"], name, error)
    tv, vel = _valid_velocity(ulog, name, said, tv, vel, error)
    tv, vel = _in_time_order("vehicle_local_position", name, said, tv, vel)
    tm, rpm, order, motor_topic = _ulog_motors(ulog, name, motor_map, n_motors, error, said)
    tm, rpm = _in_time_order(motor_topic, name, said, tm, rpm)
    lo = max(t[0], tw[0], tq[0], tv[0], tm[0])
    hi = min(t[-1], tw[-1], tq[-1], tv[-1], tm[-1])
    for topic, tt in (("vehicle_angular_velocity", tw), ("vehicle_attitude", tq), ("vehicle_local_position", tv),
                      (motor_topic, tm)):
        _check_steps(topic, tt, lo, hi, name, gap_steps, said)
    keep = (t >= lo) & (t <= hi)
    left = int(np.count_nonzero(~keep))
    if left and t[-1] > t[0] and (lo - t[0]) + (t[-1] - hi) > SPAN_NOTE_FRACTION * (t[-1] - t[0]):
        # (an ESC telemetry that stopped after a quarter of the log cut it to that quarter without a word: a file
        # audit, 2026-12-01)
        ends = {acc_topic: (t[0], t[-1]), "vehicle_angular_velocity": (tw[0], tw[-1]),
                "vehicle_attitude": (tq[0], tq[-1]), "vehicle_local_position": (tv[0], tv[-1]),
                motor_topic: (tm[0], tm[-1])}
        late = [k for k, (a, _) in ends.items() if a == lo and lo > t[0]]
        early = [k for k, (_, b) in ends.items() if b == hi and hi < t[-1]]
        why = "; ".join([*(f"{k} starts at {lo - t[0]:.3g} s" for k in late),
                         *(f"{k} ends at {hi - t[0]:.3g} s" for k in early)])
        said.append(f"{name}: {left} of the log's {t.size} {acc_topic} samples (over {t[-1] - t[0]:.3g} s) lie outside "
                    f"the time every topic covers and are left out ({why}; times from the log's first {acc_topic} "
                    "sample)")
    if keep.sum() < min_samples:
        raise error(f"{name}: the topics overlap on {keep.sum()} sample(s) of {acc_topic}; need at least "
                    f"{min_samples}")
    fields = _resampled(t[keep], acc[keep], (tw, rates, deriv), (tq, q), (tv, vel), (tm, rpm), order)
    # (the log's own geometry, where its motor columns are known to be in motor order: a review)
    known = "by actuator_function" in order or "_FUNCn" in order
    layout = _px4_rotor_layout(dict(ulog.initial_parameters), rpm.shape[1]) if known else None
    return {**fields, "rotor_layout": layout}, said


#: the samples are the accelerations' messages: logged more slowly than this [Hz] beside a faster sensor_combined, said
SLOW_ACCELERATION_HZ = 50.0


def _slow_accelerations(ulog, acc_topic: str, t: np.ndarray, name: str, said: list) -> None:
    """Say in ``said`` where vehicle_acceleration, whose messages are the samples, is logged below
    SLOW_ACCELERATION_HZ while sensor_combined is logged faster: PX4's default logging profile
    records it at 20 Hz (src/modules/logger/logged_topics.cpp), and a log of 1951 sensor_combined
    messages gave 157 samples without a word (a PX4 audit, 2026-12-02). sensor_combined's
    accelerometer is not corrected for the estimator's bias, so it is not read instead."""
    if acc_topic != "vehicle_acceleration" or t.size < 2 or not _has(ulog, "sensor_combined"):
        return
    rate = 1.0 / float(np.median(np.diff(t)))
    d = min((s for s in ulog.data_list if s.name == "sensor_combined"), key=lambda s: s.multi_id)
    ts = np.asarray(d.data["timestamp"], float) * 1e-6
    other = 1.0 / float(np.median(np.diff(ts))) if ts.size > 1 and np.median(np.diff(ts)) > 0 else 0.0
    if rate < SLOW_ACCELERATION_HZ and other > 2.0 * rate:
        said.append(f"{name}: the samples are vehicle_acceleration's messages, logged at {rate:.3g} Hz (PX4's default "
                    f"logging profile; sensor_combined, at {other:.3g} Hz, is not corrected for the estimator's "
                    "accelerometer bias and is not read): log vehicle_acceleration faster for more samples "
                    "(PX4's etc/logging/logger_topics.txt on the SD card sets a topic's interval)")


def _parsed(raw: bytes, name: str, error):
    """(the ULog, the file's name as shown, what was said): the file's bytes parsed by pyulog
    (its notices said, not printed to the console), a damaged or cut file said of, one pyulog
    cannot read refused."""
    try:
        import pyulog.core
        from pyulog import ULog
    except ImportError:  # pragma: no cover (a declared dependency)
        raise error("reading ULog files needs the package pyulog (pip install pyulog)") from None
    pyulog.core.print = _pyulog_print  # (its module-level name: pyulog's notices into the list below)
    said = []
    _PARSING.notices = notices = []
    source = _FileBytes(raw)
    try:
        ulog = ULog(source)
    except MemoryError:  # (the input too large for the memory, not a damaged file: the CLI says so)
        raise
    except Exception as exc:  # pyulog raises many types for a corrupt file
        raise error(f"{name}: not a readable ULog file ({type(exc).__name__}: {str(exc)[:120]})") from None
    finally:
        _PARSING.notices = None
    lines = [x.strip() for x in notices if x.strip()]
    first = (f"pyulog: {lines[0][:100]}" + (f" and {len(lines) - 1} more notice(s)" if len(lines) > 1 else "")
             if lines else "")
    if ulog.file_corruption:
        said.append(f"{name}: a damaged ULog file ({first or 'pyulog found corrupt data'}); what pyulog skipped is "
                    "missing from the log")
        name = f"{name} (a damaged file)"  # (a topic lost to the damage is named missing: said so)
    elif lines:
        said.append(f"{name}: {first}")
    if source.cut and not ulog.file_corruption:
        said.append(f"{name}: the file ends inside a message (cut short: power lost, a full card, a partial copy?); "
                    "the log is read up to its last whole message")
    return ulog, name, said


def _resampled(t, acc, rates, attitude, velocity, motors, order) -> dict:
    """The FlightLog fields: every topic ((timestamps, values) pairs; the angular rates with
    their derivative or None) interpolated to the acceleration's timestamps ``t`` [s], the
    attitude normalised and every vector turned from PX4's FRD body and NED world into propmap's
    FLU body frame (module docstring), the motor speeds from rpm to rad/s."""
    tw, w_frd, deriv = rates
    tq, q = attitude
    tv, vel = velocity
    tm, rpm = motors

    def at(tt, a):
        return np.column_stack([np.interp(t, tt, a[:, k]) for k in range(a.shape[1])])

    def motors_at(tt, a):  # (an ESC's offline readings, NaN between online ones, left out of its interpolation)
        ok = ~np.isnan(a)
        return np.column_stack([np.interp(t, tt[ok[:, k]], a[ok[:, k], k]) for k in range(a.shape[1])])

    q_i = at(tq, q)
    q_i /= np.linalg.norm(q_i, axis=1, keepdims=True)
    v_body = _rotate_ned_to_body(q_i, at(tv, vel)) * _FRD_TO_FLU
    w = at(tw, w_frd) * _FRD_TO_FLU
    # attitude as (x, y, z, w) of FLU body -> ENU-like z-up world: FRD->NED conjugated by the flips
    quat = np.column_stack([q_i[:, 1], -q_i[:, 2], -q_i[:, 3], q_i[:, 0]])
    omega = motors_at(tm, rpm) * RPM
    return dict(t=t - t[0], angular_velocity=w,
                angular_acceleration=None if deriv is None else at(tw, deriv) * _FRD_TO_FLU,
                specific_force=acc * _FRD_TO_FLU, velocity=v_body, attitude=quat, rotor_omega=omega,
                rotor_acceleration=None, motor_order=order)


def _valid_velocity(ulog, name: str, said: list, tv, vel, error):
    """The velocity messages the estimator flags valid (``v_xy_valid`` and ``v_z_valid`` of
    vehicle_local_position, where logged), the others left out with a note: an invalid estimate
    (no GPS, indoors) of 0 m/s was read as the velocity (an input fuzzing audit, 2026-11-27).
    Where every message is flagged, all are read, with a note: PX4's EKF2 sets the flags with the
    horizontal position's validity, so a flight without position aiding (no GPS, vision or optical
    flow) has none valid (a review); the kinematic check then judges the velocity."""
    d = min((s for s in ulog.data_list if s.name == "vehicle_local_position"), key=lambda s: s.multi_id)
    if not all(f in d.data for f in ("v_xy_valid", "v_z_valid")):
        return tv, vel
    ok = (np.asarray(d.data["v_xy_valid"]) != 0) & (np.asarray(d.data["v_z_valid"]) != 0)
    if not ok.any():
        said.append(f"{name}: vehicle_local_position: the velocity estimate is flagged invalid (v_xy_valid, "
                    f"v_z_valid) in all {ok.size} messages (a flight without position aiding: no GPS, vision or "
                    "optical flow?): read as logged")
        return tv, vel
    if not ok.all():
        said.append(f"{name}: vehicle_local_position: {int((~ok).sum())} of {ok.size} velocity messages flagged "
                    "invalid (v_xy_valid, v_z_valid) left out; the velocity is interpolated across them")
    return tv[ok], vel[ok]


