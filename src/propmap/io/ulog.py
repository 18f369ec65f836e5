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

import io
import math

import numpy as np

_FRD_TO_FLU = np.array([1.0, -1.0, -1.0])


def _topic(ulog, name: str, fields: list[str], where: str, error: type[ValueError]):
    """(t [s], columns) of the first instance of topic ``name``; the error names what is missing."""
    sets = [d for d in ulog.data_list if d.name == name]
    if not sets:
        found = sorted({d.name for d in ulog.data_list})
        raise error(f"{where}: topic {name!r} not in the log (topics found: {', '.join(found)[:300]})")
    d = min(sets, key=lambda s: s.multi_id)
    missing = [f for f in fields if f not in d.data]
    if missing:
        raise error(f"{where}: topic {name!r} lacks field(s) {', '.join(missing)} (fields: "
                             f"{', '.join(sorted(d.data))[:300]})")
    return d.data["timestamp"] * 1e-6, np.column_stack([np.asarray(d.data[f], float) for f in fields])


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


def read_ulog(raw: bytes, name: str, motor_map, n_motors: int | None = None, *, error: type[ValueError],
              min_samples: int) -> dict:
    """The fields of a :class:`propmap.io.flightlog.FlightLog` (``t``, ``angular_velocity``,
    ``angular_acceleration``, ``specific_force``, ``velocity``, ``attitude``, ``rotor_omega``,
    ``rotor_acceleration``, ``motor_order``) read from the ULog file's bytes ``raw``: every topic
    interpolated to the acceleration topic's timestamps over the time they all cover, turned into
    propmap's body frame (module docstring).

    Parameters
    ----------
    raw : bytes
    name : str
        The file as shown in messages.
    motor_map : (float, float) or None
        rpm = a + b * actuator_outputs; None: ``esc_status``'s rpm.
    n_motors : int, optional
        The vehicle's rotor count (the first outputs of ``actuator_outputs``).
    error : type of ValueError
        Raised, with one line naming the file, for what cannot be read.
    min_samples : int
        The fewest samples of the acceleration topic the topics' overlap must hold.
    """
    try:
        from pyulog import ULog
    except ImportError:  # pragma: no cover (a declared dependency)
        raise error("reading ULog files needs the package pyulog (pip install pyulog)") from None
    try:
        ulog = ULog(io.BytesIO(raw))
    except Exception as exc:  # pyulog raises many types for a corrupt file
        raise error(f"{name}: not a readable ULog file ({type(exc).__name__}: {str(exc)[:120]})") from None
    acc_topic = "vehicle_acceleration" if _has(ulog, "vehicle_acceleration") else "sensor_combined"
    if not _has(ulog, acc_topic):
        found = ", ".join(sorted({d.name for d in ulog.data_list}))[:200]
        raise error(f"{name}: no accelerations: neither topic 'vehicle_acceleration' nor 'sensor_combined' "
                             f"is in the log (topics found: {found or 'none'})")
    acc_fields = ["xyz[0]", "xyz[1]", "xyz[2]"] if acc_topic == "vehicle_acceleration" else [
        "accelerometer_m_s2[0]", "accelerometer_m_s2[1]", "accelerometer_m_s2[2]"]
    t, acc = _topic(ulog, acc_topic, acc_fields, name, error)
    tw, rates = _topic(ulog, "vehicle_angular_velocity", ["xyz[0]", "xyz[1]", "xyz[2]"], name, error)
    deriv = None
    d = [s for s in ulog.data_list if s.name == "vehicle_angular_velocity"]
    if d and all(f"xyz_derivative[{k}]" in d[0].data for k in range(3)):
        deriv = _topic(ulog, "vehicle_angular_velocity", [f"xyz_derivative[{k}]" for k in range(3)], name, error)[1]
    tq, q = _topic(ulog, "vehicle_attitude", ["q[0]", "q[1]", "q[2]", "q[3]"], name, error)
    # q and -q are one attitude: make the sequence continuous before interpolating it component by component (a
    # sign flip between two samples would otherwise interpolate through 0)
    if q.shape[0] > 1:
        flips = np.sum(q[1:] * q[:-1], axis=1) < 0
        q = q * np.concatenate([[1.0], np.where(np.cumsum(flips) % 2 == 1, -1.0, 1.0)])[:, None]
    tv, vel = _topic(ulog, "vehicle_local_position", ["vx", "vy", "vz"], name, error)
    tm, rpm, order = _ulog_motors(ulog, name, motor_map, n_motors, error)
    lo = max(t[0], tw[0], tq[0], tv[0], tm[0])
    hi = min(t[-1], tw[-1], tq[-1], tv[-1], tm[-1])
    keep = (t >= lo) & (t <= hi)
    if keep.sum() < min_samples:
        raise error(f"{name}: the topics overlap on {keep.sum()} sample(s) of {acc_topic}; need at least "
                             f"{min_samples}")
    t, acc = t[keep], acc[keep]

    def at(tt, a):
        return np.column_stack([np.interp(t, tt, a[:, k]) for k in range(a.shape[1])])

    q_i = at(tq, q)
    q_i /= np.linalg.norm(q_i, axis=1, keepdims=True)
    v_body = _rotate_ned_to_body(q_i, at(tv, vel)) * _FRD_TO_FLU
    w = at(tw, rates) * _FRD_TO_FLU
    # attitude as (x, y, z, w) of FLU body -> ENU-like z-up world: FRD->NED conjugated by the flips
    quat = np.column_stack([q_i[:, 1], -q_i[:, 2], -q_i[:, 3], q_i[:, 0]])
    omega = at(tm, rpm) * (2 * math.pi / 60)
    return dict(t=t - t[0], angular_velocity=w,
                angular_acceleration=None if deriv is None else at(tw, deriv) * _FRD_TO_FLU,
                specific_force=acc * _FRD_TO_FLU, velocity=v_body, attitude=quat, rotor_omega=omega,
                rotor_acceleration=None, motor_order=order)


def _ulog_motors(ulog, name: str, motor_map, n_motors: int | None, error: type[ValueError]):
    """(t, rpm columns, description) of the motor speeds (actuator_outputs: the first ``n_motors``)."""
    if _has(ulog, "esc_status") and motor_map is None:
        d = min((s for s in ulog.data_list if s.name == "esc_status"), key=lambda s: s.multi_id)
        cols = sorted((f for f in d.data if f.startswith("esc[") and f.endswith("].esc_rpm")),
                      key=lambda f: int(f[4:f.index("]")]))
        count = int(np.max(d.data["esc_count"])) if "esc_count" in d.data else len(cols)
        cols = cols[:count]
        if cols:
            t, rpm = _topic(ulog, "esc_status", cols, name, error)
            if np.any(np.abs(rpm) > 0):
                return t, np.abs(rpm), f"PX4 esc_status esc[0..{len(cols) - 1}].esc_rpm (motor numbering)"
        raise error(f"{name}: topic 'esc_status' carries no motor rpm (esc_rpm all zero or absent); give "
                             "the mapping rpm = a + b * output of actuator_outputs (--motor-map a,b)")
    if motor_map is None:
        raise error(f"{name}: no motor speeds: topic 'esc_status' not in the log; give the mapping "
                             "rpm = a + b * output of actuator_outputs (--motor-map a,b)")
    a, b = motor_map
    d = [s for s in ulog.data_list if s.name == "actuator_outputs"]
    if not d:
        raise error(f"{name}: topic 'actuator_outputs' not in the log (needed with a motor map)")
    d = min(d, key=lambda s: s.multi_id)
    n = (int(np.max(d.data["noutputs"])) if "noutputs" in d.data
         else sum(f"output[{k}]" in d.data for k in range(len(d.data))))  # (without the field: those logged)
    if n_motors is not None:
        if n < n_motors:
            raise error(f"{name}: topic 'actuator_outputs' has {n} outputs; the vehicle has {n_motors} rotors")
        n = n_motors  # (a flight controller logs 8 or 16 outputs; the motors are the first)
    cols = [f"output[{k}]" for k in range(n) if f"output[{k}]" in d.data]
    if not cols:
        raise error(f"{name}: topic 'actuator_outputs' has no outputs")
    t, u = _topic(ulog, "actuator_outputs", cols, name, error)
    return (t, np.maximum(a + b * u, 0.0),
            f"PX4 actuator_outputs output[0..{len(cols) - 1}] mapped rpm = {a:g} + {b:g} u")
