"""A minimal PX4 ULog writer for tests: the documented binary format, written from scratch.

ULog (https://docs.px4.io/main/en/dev_log/ulog_file_format.html): a 16-byte header (magic
'ULog' 0x01 0x12 0x35, version, timestamp [us]), then messages of (uint16 size, uint8 type,
payload): 'F' formats ("name:type field;..."), 'A' subscriptions (multi id, msg id, name)
and 'D' data (msg id, packed fields). Enough for pyulog to read the topics a flight log
needs; nested types are written as their own formats ("esc_report[8] esc").
"""

from __future__ import annotations

import math
import struct

import numpy as np

_TYPES = {"uint64_t": "<Q", "float": "<f", "uint8_t": "<B", "int32_t": "<i", "uint16_t": "<H", "uint32_t": "<I",
          "bool": "<B"}


def _msg(kind: bytes, payload: bytes) -> bytes:
    return struct.pack("<HB", len(payload), kind[0]) + payload


def _param(name: str, value) -> bytes:
    """A 'P' message: uint8 key length, key "int32_t NAME" (or "float NAME"), the value."""
    key = f"{'int32_t' if isinstance(value, int) else 'float'} {name}".encode()
    return _msg(b"P", bytes([len(key)]) + key + struct.pack("<i" if isinstance(value, int) else "<f", value))


def write_ulog(path, topics: dict, nested: dict | None = None, params: dict | None = None,
               changed: list | None = None) -> None:
    """Write ``topics``: name -> (fields, rows).

    ``fields`` is a list of (type, name) with type a C type, an array "float[3]", or a
    nested format name from ``nested`` (name -> list of (type, name)) with a count
    ("esc_report[8]"). ``rows`` is a list of flat tuples of values in field order (arrays
    and nested fields flattened). The first field must be ``uint64_t timestamp``. A name
    ``"topic#k"`` writes instance (multi_id) k of a topic given as ``"topic"`` too.
    ``params`` (name -> int or float) are written in the definitions (pyulog's
    ``initial_parameters``), ``changed`` ((timestamp [us], name, value)) among the data
    (``changed_parameters``).
    """
    nested = nested or {}
    out = bytearray(b"ULog\x01\x12\x35" + bytes([0]) + struct.pack("<Q", 0))
    for pname, value in (params or {}).items():
        out += _param(pname, value)

    def fmt_text(name, fields):
        return f"{name}:" + "".join(f"{t} {n};" for t, n in fields)

    for name, fields in nested.items():
        out += _msg(b"F", fmt_text(name, fields).encode())
    for name, (fields, _) in topics.items():
        if "#" not in name:  # ("name#k": instance k of a topic whose format instance 0 gave)
            out += _msg(b"F", fmt_text(name, fields).encode())

    def flat_types(fields):
        types = []
        for t, _ in fields:
            base, count = (t.split("[")[0], int(t.split("[")[1][:-1])) if "[" in t else (t, 1)
            for _ in range(count):
                types.extend(flat_types(nested[base]) if base in nested else [_TYPES[base]])
        return types

    for msg_id, name in enumerate(topics):
        topic, _, multi_id = name.partition("#")
        out += _msg(b"A", struct.pack("<BH", int(multi_id or 0), msg_id) + topic.encode())
    events = []
    for msg_id, (name, (fields, rows)) in enumerate(topics.items()):
        types = flat_types(fields)
        for row in rows:
            payload = b"".join(struct.pack(t, v) for t, v in zip(types, row))
            events.append((row[0], msg_id, payload))
    for ts, pname, value in changed or []:
        events.append((ts, -1, _param(pname, value)))
    for ts, msg_id, payload in sorted(events, key=lambda e: (e[0], e[1])):
        out += payload if msg_id < 0 else _msg(b"D", struct.pack("<H", msg_id) + payload)
    with open(path, "wb") as fh:
        fh.write(bytes(out))


def hover_ulog(path, *, n: int = 200, rate_hz: float = 100.0, rpm: float = 12000.0, with_esc: bool = True,
               n_motors: int = 4, rpm_scale: float = 1.0, n_outputs: int | None = None, q_flip: bool = False,
               nan_derivative_at: int | None = None, outputs: list | None = None, params: dict | None = None,
               changed: list | None = None, second_outputs: list | None = None, velocity_valid=None,
               esc_empty: bool = False, esc_stop: int | None = None, nan_attitude_at: int | None = None) -> dict:
    """A ULog of a slow forward flight: constant attitude (yawed 30 deg, pitched 5 deg), north
    velocity 2 m/s, a small roll rate, motors at ``rpm`` (esc_status, or actuator_outputs
    with output = rpm / 10 when ``with_esc`` is False, ``n_outputs`` outputs logged, default
    ``n_motors``, the others at 1000). ``q_flip``: the attitude quaternion's sign alternates
    from sample to sample (q and -q: the same attitude), its timestamps offset by half a
    sample. ``nan_derivative_at``: that sample's logged angular acceleration (xyz_derivative)
    NaN. ``outputs``: actuator_outputs' values (16, rpm / 10 for a motor) instead; ``params`` and
    ``changed``: as :func:`write_ulog`'s. ``second_outputs``: a second actuator_outputs
    instance (multi_id 1) with these values, each + 0.01 on every other sample (motors that
    vary; the first instance's do not). ``velocity_valid``: per sample, the estimator's v_xy_valid
    and v_z_valid flags (logged then; an invalid sample's velocity 0). ``esc_empty``: esc_status
    declared (its format and subscription) without a message. ``esc_stop``: esc_status's messages
    after the first ``esc_stop`` lost (telemetry that stops in flight). ``nan_attitude_at``: that
    sample's attitude quaternion NaN. Returns the truth in propmap's frame."""
    t = (np.arange(n) / rate_hz * 1e6).astype(np.uint64) + np.uint64(1_000_000)
    yaw, pitch = np.radians(30.0), np.radians(5.0)
    # FRD -> NED: yaw about z (down), then pitch about y
    cy, sy, cp, sp = np.cos(yaw / 2), np.sin(yaw / 2), np.cos(pitch / 2), np.sin(pitch / 2)
    q = (cy * cp, -sy * sp, cy * sp, sy * cp)  # w, x, y, z of q_yaw * q_pitch
    topics = {
        "vehicle_acceleration": ([("uint64_t", "timestamp"), ("uint64_t", "timestamp_sample"), ("float[3]", "xyz")],
                                 [(int(ti), int(ti), 0.5, 0.2, -9.9) for ti in t]),
        "vehicle_angular_velocity": ([("uint64_t", "timestamp"), ("uint64_t", "timestamp_sample"),
                                      ("float[3]", "xyz"), ("float[3]", "xyz_derivative")],
                                     [(int(ti), int(ti), 0.1, 0.0, 0.0, math.nan if i == nan_derivative_at else 0.0,
                                       0.0, 0.0) for i, ti in enumerate(t)]),
        "vehicle_attitude": ([("uint64_t", "timestamp"), ("float[4]", "q")],
                             [(int(ti) + (int(5e5 / rate_hz) if q_flip else 0),
                               *((math.nan,) * 4 if i == nan_attitude_at else
                                 tuple(-qk for qk in q) if q_flip and i % 2 else q)) for i, ti in enumerate(t)]),
        "vehicle_local_position": ([("uint64_t", "timestamp"), ("float", "vx"), ("float", "vy"), ("float", "vz")],
                                   [(int(ti), 2.0, 0.0, 0.0) for ti in t]),
    }
    if velocity_valid is not None:
        topics["vehicle_local_position"] = (
            topics["vehicle_local_position"][0] + [("bool", "v_xy_valid"), ("bool", "v_z_valid")],
            [(int(ti), 2.0 if ok else 0.0, 0.0, 0.0, int(ok), int(ok)) for ti, ok in zip(t, velocity_valid)])
    nested = {}
    if with_esc:
        nested["esc_report"] = [("uint64_t", "timestamp"), ("int32_t", "esc_rpm"), ("float", "esc_voltage")]
        rows = []
        for ti in t:
            esc = []
            for k in range(8):
                esc += [int(ti), int(rpm * rpm_scale) if k < n_motors else 0, 16.0]
            rows.append((int(ti), n_motors, *esc))
        topics["esc_status"] = ([("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("esc_report[8]", "esc")],
                                [] if esc_empty else rows[:esc_stop])
    else:
        n_out = n_motors if n_outputs is None else n_outputs
        if outputs is None:
            outputs = [rpm / 10.0] * n_motors + [1000.0] * (n_out - n_motors) + [0.0] * (16 - n_out)
        topics["actuator_outputs"] = ([("uint64_t", "timestamp"), ("uint32_t", "noutputs"), ("float[16]", "output")],
                                      [(int(ti), n_out, *outputs) for ti in t])
        if second_outputs is not None:
            topics["actuator_outputs#1"] = (topics["actuator_outputs"][0],
                                            [(int(ti), n_out, *(v + 0.01 * (i % 2) for v in second_outputs))
                                             for i, ti in enumerate(t)])
    write_ulog(path, topics, nested, params, changed)
    return {"yaw": yaw, "pitch": pitch, "v_ned": (2.0, 0.0, 0.0), "rpm": rpm}
