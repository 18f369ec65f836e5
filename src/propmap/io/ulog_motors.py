"""PX4 ULog motor speeds: ``esc_status``' rpm in motor order (its entries' actuator_function, the
log's UAVCAN_EC_FUNCn, telemetry dropouts left out) or ``actuator_outputs`` through a stated
linear mapping in the order the output functions give, and the log's own rotor geometry
(control allocation) that a vehicle file is checked against (:func:`propmap.io.ulog.read_ulog`)."""

from __future__ import annotations

import re

import numpy as np

from .ulog_topics import _has, _missing, _topic


#: PX4's output function of motor 1 (Motor1 = 101 ... Motor12 = 112; PX4-Autopilot,
#: src/lib/mixer_module/output_functions.yaml), which esc_status' esc[k].actuator_function holds
MOTOR1_FUNCTION = 101
MOTOR_FUNCTIONS = 12
#: a PX4 output driver's parameter assigning output i (from 1) a function (control allocation, PX4 v1.13 with
#: SYS_CTRL_ALLOC = 1 and every release since: PWM_MAIN_FUNC1, PWM_AUX_FUNC1, UAVCAN_EC_FUNC1, ...;
#: PX4-Autopilot, Tools/module_config/generate_params.py and the drivers' module.yaml)
_FUNC_PARAMETER = re.compile(r"([A-Z][A-Z0-9_]*)_FUNC(\d+)")


def _uavcan_motor_order(params: dict, cols: list, n_motors: int | None):
    """(esc_rpm columns in motor order, description) by the log's ``UAVCAN_EC_FUNC<i>``, or None
    where they do not assign motors 1..n to the entries: PX4's UAVCAN ESC driver fills esc[] by
    the ESC's index, output i+1 of UAVCAN_EC_FUNC<i+1>, and names no actuator_function (its speeds
    were read in entry order: [5300, 5100, 5400, 5200] rpm for [5100, ..., 5400], a PX4 audit,
    2026-12-02; PX4-Autopilot src/drivers/uavcan/actuators/esc.cpp)."""
    if params.get("UAVCAN_ENABLE", 3) < 3:  # (PX4's UAVCAN ESCs need 3, 'Sensors and Actuators': a review)
        return None
    outputs = sorted((int(m.group(2)), int(v)) for k, v in params.items()
                     if (m := _FUNC_PARAMETER.fullmatch(k)) and m.group(1) == "UAVCAN_EC")
    motors = {}  # motor -> its lowest output's entry
    for i, v in outputs:
        if MOTOR1_FUNCTION <= v < MOTOR1_FUNCTION + MOTOR_FUNCTIONS:
            motors.setdefault(v - MOTOR1_FUNCTION + 1, i - 1)
    entry = {_entry_index(f): f for f in cols}
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
    channels = [_entry_index(f) for f in cols]
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
    entry's bit of ``esc_online_flags`` is clear between its first and last online reading (PX4's
    own ESC check reads bit k as esc[k] online): a telemetry dropout, whose zeroed rpm (PX4's DShot
    driver zeroes an offline entry) was read as a stopped motor and interpolated into the samples
    around it (0 to 4050 rpm in a hover: a PX4 audit, 2026-12-02). Before an ESC's first online
    reading and after its last (not yet reporting, or lost for good) the readings are kept as
    logged, and an ESC never marked online is kept whole, with a note (its column was all NaN:
    a review). Flags that are 0 in every message are taken as not kept."""
    if "esc_online_flags" not in d.data:
        return rpm
    flags = np.asarray(d.data["esc_online_flags"]).astype(np.int64)
    if not flags.any():
        return rpm
    entries = [_entry_index(f) for f in cols]
    online = np.column_stack([(flags >> k) & 1 == 1 for k in entries])
    missing = np.zeros_like(online)
    for j in range(online.shape[1]):
        on = np.flatnonzero(online[:, j])
        if on.size:
            missing[on[0]:on[-1] + 1, j] = ~online[on[0]:on[-1] + 1, j]
    never = [entries[j] for j in range(online.shape[1]) if not online[:, j].any()]
    if never:
        said.append(f"{name}: topic 'esc_status': esc[{never[0]}]{' and others' if len(never) > 1 else ''} never "
                    "marked online (esc_online_flags): its readings are read as logged")
    if missing.any():
        worst = int(np.argmax(missing.sum(axis=0)))
        said.append(f"{name}: topic 'esc_status': {int(missing.sum())} reading(s) of an ESC marked offline "
                    f"(esc_online_flags; the most, {int(missing[:, worst].sum())}, of esc[{entries[worst]}]) left "
                    "out: that motor's speed is interpolated between its online readings")
    return np.where(missing, np.nan, rpm)


def _entry_index(field: str) -> int:
    """k of an esc_status field ``esc[k].<name>``."""
    return int(field[4:field.index("]")])


def _ulog_motors(ulog, name: str, motor_map, n_motors: int | None, error: type[ValueError], said: list):
    """(t, rpm columns, description, topic) of the motor speeds (actuator_outputs: the first ``n_motors``)."""
    if _has(ulog, "esc_status") and motor_map is None:
        d = min((s for s in ulog.data_list if s.name == "esc_status"), key=lambda s: s.multi_id)
        cols = sorted((f for f in d.data if f.startswith("esc[") and f.endswith("].esc_rpm")),
                      key=_entry_index)
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


def _px4_rotor_layout(params: dict, n: int) -> np.ndarray | None:
    """(n, 3): motor i+1's hub position x forward, y left [m] and spin (+1 counter-clockwise seen
    from above, -1 clockwise) from the log's control allocation ``CA_ROTOR<i>_PX``, ``_PY``,
    ``_KM`` (PX4's FRD body axes, y to the right; a moment coefficient KM > 0 for a
    counter-clockwise rotor: PX4's x500 airframe, motor 1 front-right at KM = +0.05; PX4's
    control_allocator module.yaml), or None where the log does not give them in use: a motor's
    missing (PX4 before control allocation), SYS_CTRL_ALLOC = 0 (v1.13's mixer files), fewer
    rotors in CA_ROTOR_COUNT than motors, a KM of 0, or a hub at the centre (the parameters'
    defaults, PX = PY = 0: every motor 'front', a review)."""
    keys = [(f"CA_ROTOR{i}_PX", f"CA_ROTOR{i}_PY", f"CA_ROTOR{i}_KM") for i in range(n)]
    if (not n or any(k not in params for row in keys for k in row) or params.get("SYS_CTRL_ALLOC", 1) == 0
            or params.get("CA_ROTOR_COUNT", n) < n):
        return None
    lay = np.array([[float(params[px]), -float(params[py]), float(params[km])] for px, py, km in keys])
    if np.any(lay[:, 2] == 0) or np.any(np.hypot(lay[:, 0], lay[:, 1]) == 0):
        return None
    lay[:, 2] = np.sign(lay[:, 2])
    return lay
