"""PX4 ULog flight logs (read with pyulog, https://github.com/PX4/pyulog): the topics
``vehicle_acceleration`` (or ``sensor_combined``), ``vehicle_angular_velocity`` (with
``xyz_derivative`` when logged), ``vehicle_attitude``, ``vehicle_local_position`` and the motor
speeds from ``esc_status`` (``esc_rpm``), or, with a stated linear mapping rpm = a + b u, from
``actuator_outputs``. PX4's body frame is forward-right-down and its world frame
north-east-down: vectors are turned into propmap's frame (x forward, y left, z up; y and z
negated) and the velocity rotated into the body frame with the attitude
(:func:`read_ulog`; io/flightlog.py makes the :class:`~propmap.io.flightlog.FlightLog`).
"""

from __future__ import annotations

import builtins
import io
import math
import re
import threading

import numpy as np

from ..core.units import RPM

_FRD_TO_FLU = np.array([1.0, -1.0, -1.0])


def _missing(ulog, name: str) -> str:
    """How topic ``name`` is missing from a log: declared (its format is in the log) without a
    message, or not at all (a zero-message topic was said to be 'not in the log')."""
    formats = getattr(ulog, "message_formats", None) or {}
    return "has no message in the log (its format is declared)" if name in formats else "not in the log"


def _topic(ulog, name: str, fields: list[str], where: str, error: type[ValueError], instance: int | None = None):
    """(t [s], columns) of topic ``name``'s instance ``instance`` (multi_id; default the
    lowest); the error names what is missing."""
    sets = [d for d in ulog.data_list if d.name == name and (instance is None or d.multi_id == instance)]
    if not sets:
        found = sorted({d.name for d in ulog.data_list})
        raise error(f"{where}: topic {name!r} {_missing(ulog, name)} (topics found: {', '.join(found)[:300]})")
    d = min(sets, key=lambda s: s.multi_id)
    missing = [f for f in fields if f not in d.data]
    if missing:
        raise error(f"{where}: topic {name!r} lacks field(s) {', '.join(missing)} (fields: "
                    f"{', '.join(sorted(d.data))[:300]})")
    return d.data["timestamp"] * 1e-6, np.column_stack([np.asarray(d.data[f], float) for f in fields])


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


def _has(ulog, name: str) -> bool:
    return any(d.name == name for d in ulog.data_list)


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
        :func:`_output_motor_order`, else the first outputs).
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
    return {**fields, "rotor_layout": _px4_rotor_layout(dict(ulog.initial_parameters), rpm.shape[1])}, said


def _px4_rotor_layout(params: dict, n: int) -> np.ndarray | None:
    """(n, 3): motor i+1's hub position x forward, y left [m] and spin (+1 counter-clockwise seen
    from above, -1 clockwise) from the log's control allocation ``CA_ROTOR<i>_PX``, ``_PY``,
    ``_KM`` (PX4's FRD body axes, y to the right; a moment coefficient KM > 0 for a
    counter-clockwise rotor: PX4's x500 airframe, motor 1 front-right at KM = +0.05), or None
    where a motor's are missing (PX4 before control allocation) or a KM is 0."""
    keys = [(f"CA_ROTOR{i}_PX", f"CA_ROTOR{i}_PY", f"CA_ROTOR{i}_KM") for i in range(n)]
    if not n or any(k not in params for row in keys for k in row) or any(params[k[2]] == 0 for k in keys):
        return None
    return np.array([[float(params[px]), -float(params[py]), math.copysign(1.0, float(params[km]))]
                     for px, py, km in keys])


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

    def motors_at(tt, a):  # (an ESC's offline readings, NaN, left out of its motor's interpolation)
        return np.column_stack([np.interp(t, tt[ok], a[ok, k]) if (ok := ~np.isnan(a[:, k])).any() else
                                np.interp(t, tt, a[:, k]) for k in range(a.shape[1])])

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


#: PX4's output function of motor 1 (Motor1 = 101 ... Motor12 = 112; PX4-Autopilot,
#: src/lib/mixer_module/output_functions.yaml), which esc_status' esc[k].actuator_function holds
MOTOR1_FUNCTION = 101
MOTOR_FUNCTIONS = 12


def _uavcan_motor_order(params: dict, cols: list, n_motors: int | None):
    """(esc_rpm columns in motor order, description) by the log's ``UAVCAN_EC_FUNC<i>``, or None
    where they do not assign motors 1..n to the entries: PX4's UAVCAN ESC driver fills esc[] by
    the ESC's index, output i+1 of UAVCAN_EC_FUNC<i+1>, and names no actuator_function (its speeds
    were read in entry order: [5300, 5100, 5400, 5200] rpm for [5100, ..., 5400], a PX4 audit,
    2026-12-02; PX4-Autopilot src/drivers/uavcan/actuators/esc.cpp)."""
    motors = {}
    for k, v in params.items():
        m = _FUNC_PARAMETER.fullmatch(k)
        if m and m.group(1) == "UAVCAN_EC" and MOTOR1_FUNCTION <= int(v) < MOTOR1_FUNCTION + MOTOR_FUNCTIONS:
            motors.setdefault(int(v) - MOTOR1_FUNCTION + 1, int(m.group(2)) - 1)
    entry = {int(f[4:f.index("]")]): f for f in cols}
    n = n_motors if n_motors is not None else (max(motors) if motors else 0)
    if not n or any(motors.get(m) not in entry for m in range(1, n + 1)):
        return None
    return ([entry[motors[m]] for m in range(1, n + 1)],
            f"PX4 esc_status esc_rpm of Motor1..Motor{n} by UAVCAN_EC_FUNCn (entries "
            f"{', '.join(str(motors[m]) for m in range(1, n + 1))}; the UAVCAN driver names no actuator_function)")


def _esc_motor_order(d, cols: list, name: str, n_motors: int | None, error: type[ValueError],
                     params: dict | None = None):
    """(esc_rpm columns in motor order, description). PX4 numbers esc[] in its own output order
    and, since v1.14, names each entry's motor in esc[k].actuator_function (101 = Motor1): where it
    does, motor m is the entry whose function is 100 + m (read in entry order, a quadrotor whose
    outputs MAIN1-4 drive motors 4, 1, 2, 3 had its speeds read as [5400, 5100, 5200, 5300] rpm for
    [5100, ..., 5400]: a PX4 audit, 2026-11-27). Entry order where the field is absent or all 0;
    a motor on two entries, or missing, or beyond ``n_motors``, is refused. Where no entry names a
    motor, the log's ``UAVCAN_EC_FUNC<i>`` (``params``) order them, where they assign every motor
    (:func:`_uavcan_motor_order`)."""
    channels = [int(f[4:f.index("]")]) for f in cols]
    fields = [f"esc[{k}].actuator_function" for k in channels]
    plain = f"PX4 esc_status esc[0..{len(cols) - 1}].esc_rpm in entry order (no actuator_function)"
    uavcan = _uavcan_motor_order(params or {}, cols, n_motors) if cols else None
    if not cols or not all(f in d.data for f in fields):
        return uavcan or (cols, plain)
    codes = []
    for f in fields:  # each entry's function: its most frequent nonzero value (0 before the mixer assigns it)
        v = np.asarray(d.data[f]).astype(int)
        v = v[v != 0]
        codes.append(int(np.bincount(v).argmax()) if v.size else 0)
    numbers = [c - MOTOR1_FUNCTION + 1 for c in codes if MOTOR1_FUNCTION <= c < MOTOR1_FUNCTION + MOTOR_FUNCTIONS]
    if not numbers:
        return uavcan or (cols, plain)
    if len(set(numbers)) < len(numbers):
        twice = next(m for m in numbers if numbers.count(m) > 1)
        raise error(f"{name}: esc_status' actuator_function assigns motor {twice} to two entries")
    motors = {c - MOTOR1_FUNCTION + 1: k for k, c in enumerate(codes)
              if MOTOR1_FUNCTION <= c < MOTOR1_FUNCTION + MOTOR_FUNCTIONS}
    n = n_motors if n_motors is not None else max(motors)
    if max(motors) > n:
        raise error(f"{name}: esc_status' actuator_function assigns motors up to {max(motors)}; the vehicle has "
                    f"{n} rotors")
    missing = [m for m in range(1, n + 1) if m not in motors]
    if missing:
        raise error(f"{name}: esc_status' actuator_function assigns motor(s) {', '.join(map(str, sorted(motors)))} to "
                    f"its entries, not motor {missing[0]} of the {n}")
    return ([cols[motors[m]] for m in range(1, n + 1)],
            f"PX4 esc_status esc_rpm of Motor1..Motor{n} by actuator_function (entries "
            f"{', '.join(str(channels[motors[m]]) for m in range(1, n + 1))})")


def _offline_as_missing(d, cols: list, rpm: np.ndarray, name: str, said: list) -> np.ndarray:
    """The esc_rpm columns ``cols`` of esc_status ``d`` (its messages' rows) with NaN where the
    entry's bit of ``esc_online_flags`` is clear (PX4's own ESC check reads bit k as esc[k]
    online): a telemetry dropout, whose zeroed rpm (PX4's DShot driver zeroes an offline entry)
    was read as a stopped motor and interpolated into the samples around it (0 to 4050 rpm in a
    hover: a PX4 audit, 2026-12-02). Flags that are 0 in every message are taken as not kept."""
    if "esc_online_flags" not in d.data:
        return rpm
    flags = np.asarray(d.data["esc_online_flags"]).astype(np.int64)
    if not flags.any():
        return rpm
    entries = [int(f[4:f.index("]")]) for f in cols]
    offline = np.column_stack([(flags >> k) & 1 == 0 for k in entries])
    if not offline.any():
        return rpm
    worst = int(np.argmax(offline.sum(axis=0)))
    said.append(f"{name}: topic 'esc_status': {int(offline.sum())} reading(s) of an ESC marked offline "
                f"(esc_online_flags; the most, {int(offline[:, worst].sum())}, of esc[{entries[worst]}]) left out: "
                "that motor's speed is interpolated between its online readings")
    return np.where(offline, np.nan, rpm)


def _ulog_motors(ulog, name: str, motor_map, n_motors: int | None, error: type[ValueError], said: list):
    """(t, rpm columns, description, topic) of the motor speeds (actuator_outputs: the first ``n_motors``)."""
    if _has(ulog, "esc_status") and motor_map is None:
        d = min((s for s in ulog.data_list if s.name == "esc_status"), key=lambda s: s.multi_id)
        cols = sorted((f for f in d.data if f.startswith("esc[") and f.endswith("].esc_rpm")),
                      key=lambda f: int(f[4:f.index("]")]))
        count = int(np.max(d.data["esc_count"])) if "esc_count" in d.data else len(cols)
        cols = cols[:count]
        cols, order = _esc_motor_order(d, cols, name, n_motors, error, dict(ulog.initial_parameters))
        if cols:
            t, rpm = _topic(ulog, "esc_status", cols, name, error)
            rpm = _offline_as_missing(d, cols, np.abs(rpm), name, said)
            if np.any(rpm > 0):
                return t, rpm, order, "esc_status"
        raise error(f"{name}: topic 'esc_status' carries no motor rpm (esc_rpm all zero or absent); give "
                    "the mapping rpm = a + b * output of actuator_outputs (--motor-map a,b)")
    if motor_map is None:
        raise error(f"{name}: no motor speeds: topic 'esc_status' {_missing(ulog, 'esc_status')}; give the mapping "
                    "rpm = a + b * output of actuator_outputs (--motor-map a,b)")
    a, b = motor_map
    d = [s for s in ulog.data_list if s.name == "actuator_outputs"]
    if not d:
        raise error(f"{name}: topic 'actuator_outputs' {_missing(ulog, 'actuator_outputs')} (needed with a motor "
                    "map)")
    outputs, how = _output_motor_order(ulog, n_motors, name, error)

    def motor_columns(s):  # (instance s's columns of motors 1..n; the error a reading of it would raise)
        n_out = (int(np.max(s.data["noutputs"])) if "noutputs" in s.data
                 else sum(f"output[{k}]" in s.data for k in range(len(s.data))))  # (without the field: those logged)
        if outputs is not None:
            if max(outputs) >= n_out:
                return None, (f"{name}: {how} puts a motor on output {max(outputs) + 1}; topic 'actuator_outputs' "
                              f"(instance {s.multi_id}) has {n_out} outputs")
            k = outputs
        elif n_motors is not None and n_out < n_motors:
            return None, f"{name}: topic 'actuator_outputs' has {n_out} outputs; the vehicle has {n_motors} rotors"
        else:  # no output functions in the log: the first outputs are the motors (a flight controller logs 8 or 16)
            k = list(range(n_out if n_motors is None else n_motors))
        cols = [f"output[{j}]" for j in k]
        if not cols or any(c not in s.data for c in cols):
            return None, (f"{name}: topic 'actuator_outputs' has no outputs" if not cols else
                          f"{name}: topic 'actuator_outputs' lacks field {next(c for c in cols if c not in s.data)}")
        return k, cols

    d = sorted(d, key=lambda s: s.multi_id)
    chosen = d[0]
    if len(d) > 1:  # one instance per output driver (px4io's MAIN, the FMU's AUX, UAVCAN), numbered by boot order,
        # which the log does not name: the lowest whose motor outputs vary (a review: the motors on AUX, instance 1,
        # were read from MAIN's servos at 1500 us, instance 0)
        varying = [s for s, (k, cols) in ((s, motor_columns(s)) for s in d)
                   if k is not None and all(np.ptp(np.asarray(s.data[c], float)) > 0 for c in cols)]
        chosen = varying[0] if varying else d[0]
        said.append(f"{name}: topic 'actuator_outputs' has instances {', '.join(str(s.multi_id) for s in d)} (one "
                    f"per output driver; the log does not say which is which): the motor speeds are read from instance "
                    f"{chosen.multi_id}, " + ("the lowest whose motor outputs vary" if varying else
                                               "the lowest (no instance's motor outputs vary)")
                    + "; check that they drive the motors")
    outputs, cols = motor_columns(chosen)
    if outputs is None:
        raise error(cols)
    t, u = _topic(ulog, "actuator_outputs", cols, name, error, instance=chosen.multi_id)
    where = (f"output[0..{len(cols) - 1}]" if outputs == list(range(len(outputs))) and how is None else
             f"output[{', '.join(map(str, outputs))}] for Motor1..Motor{len(outputs)} ({how})")
    return (t, np.maximum(a + b * u, 0.0), f"PX4 actuator_outputs {where} mapped rpm = {a:g} + {b:g} u",
            "actuator_outputs")


#: a PX4 output driver's parameter assigning output i (from 1) a function (control allocation, PX4 v1.13 with
#: SYS_CTRL_ALLOC = 1 and every release since: PWM_MAIN_FUNC1, PWM_AUX_FUNC1, UAVCAN_EC_FUNC1, ...;
#: PX4-Autopilot, Tools/module_config/generate_params.py and the drivers' module.yaml)
_FUNC_PARAMETER = re.compile(r"([A-Z][A-Z0-9_]*)_FUNC(\d+)")


def _output_motor_order(ulog, n_motors: int | None, name: str, error: type[ValueError]):
    """(output index of motor 1..n, description) from the log's parameters, or (None, None)
    where they say nothing (no output function logged: mixer files, where the first outputs are
    the motors; PX4 logs every parameter in use, defaults included).

    Control allocation: motor m is on output i where ``<PREFIX>_FUNC<i>`` = 100 + m (PX4's
    Motor1 = 101, :data:`MOTOR1_FUNCTION`); one driver (prefix) must carry motors 1..n, as
    actuator_outputs is read from one instance (several that do: the first prefix in name
    order, the others named in the description; a motor on several outputs of it is read from the
    lowest, which carries the same command). Mixer files (no FUNC parameter, or
    SYS_CTRL_ALLOC = 0 in v1.13; not SYS_CTRL_ALLOC = 1, whose dynamic mixing ignores it) with
    ``MOT_ORDERING`` = 1 (Betaflight's order; PX4's MixingOutput::reorderOutputs writes motor 4
    on output 1 and motors 1-3 on outputs 2-4 before it publishes actuator_outputs): motors
    1-4 on outputs 2, 3, 4, 1. A parameter of these that changes value during the log, motors
    split over drivers, missing or beyond ``n_motors`` are refused."""
    p = dict(ulog.initial_parameters)
    changed = sorted({k for _, k, v in ulog.changed_parameters if k in p and p[k] != v})
    funcs = sorted((m.group(1), int(m.group(2)), int(v), k) for k, v in p.items()
                   if (m := _FUNC_PARAMETER.fullmatch(k)))  # (prefix, output from 1, function, name)
    if funcs and p.get("SYS_CTRL_ALLOC", 1) != 0:
        motors, twice = {}, []  # prefix -> {motor: lowest output index}; motors assigned to more outputs than one
        for prefix, i, v, k in funcs:
            if MOTOR1_FUNCTION <= v < MOTOR1_FUNCTION + MOTOR_FUNCTIONS:
                m = v - MOTOR1_FUNCTION + 1
                if m in motors.get(prefix, {}):  # (the same command on both: the lowest output is read)
                    twice.append(f"{k} = {v} as {prefix}_FUNC{motors[prefix][m] + 1}")
                motors.setdefault(prefix, {}).setdefault(m, i - 1)
        if not motors:
            raise error(f"{name}: the log's output functions ({', '.join(sorted(f[3] for f in funcs)[:3])}"
                        f"{' ...' if len(funcs) > 3 else ''}) assign no output a motor (Motor1..Motor12 = "
                        f"{MOTOR1_FUNCTION}..{MOTOR1_FUNCTION + MOTOR_FUNCTIONS - 1})")
        n = n_motors if n_motors is not None else max(max(m) for m in motors.values())
        whole = [q for q, m in motors.items() if all(k in m for k in range(1, n + 1))]
        if not whole:
            said = "; ".join(f"{q}_FUNCn: motor(s) {', '.join(map(str, sorted(m)))}" for q, m in motors.items())
            # (a motor assigned twice was not named, the missing one's cause: a flight-log audit, 2026-12-01)
            dup = f"; {', '.join(twice)}: a motor assigned twice" if twice else ""
            raise error(f"{name}: no output driver carries motors 1..{n} ({said}{dup}); the motor speeds are read "
                        "from one actuator_outputs instance")
        prefix = whole[0]
        if max(motors[prefix]) > n:
            raise error(f"{name}: {prefix}_FUNCn assign(s) motors up to {max(motors[prefix])}; the vehicle has {n} "
                        "rotors")
        used = [k for k in changed if k.startswith(prefix + "_FUNC")]  # (SYS_CTRL_ALLOC acts after a reboot)
        if used:
            raise error(f"{name}: parameter {used[0]} changes during the log (the motors' outputs with it)")
        also = "".join(f"; {q}_FUNCn assign(s) them too" for q in whole[1:])
        return [motors[prefix][m] for m in range(1, n + 1)], f"by {prefix}_FUNCn{also}"
    if p.get("MOT_ORDERING", 0) == 1 and p.get("SYS_CTRL_ALLOC", 0) == 0:  # (dynamic mixing ignores it)
        if "MOT_ORDERING" in changed:
            raise error(f"{name}: parameter MOT_ORDERING changes during the log (the motors' outputs with it)")
        n = n_motors if n_motors is not None else 4
        if n < 4:
            raise error(f"{name}: MOT_ORDERING = 1 (Betaflight's order of a quadrotor's 4 motors); the vehicle has "
                        f"{n} rotors")
        return [1, 2, 3, 0] + list(range(4, n)), "MOT_ORDERING = 1, Betaflight's order"
    return None, None
