"""Thrust-stand exports as RCbenchmark / Tyto Robotics software writes them, for tests.

Written from the documented column sets of the stands' CSV exports (Series 1520: no torque
cell; 1580, 1585: torque; 1780: torque, more channels), UTF-8 with a byte-order mark. The
loads are propmap's own for a propeller (plus noise and the motor's settling at each ESC
step), so that a fit of the export can be checked against the truth.
"""

from __future__ import annotations

import math

import numpy as np

import propmap as pm

G0 = 9.80665
LBF = 4.4482216152605
THRUST_UNITS = {"kgf": 1 / G0, "gf": 1000 / G0, "N": 1.0, "lbf": 1 / LBF}
#: the export's columns per series (those propmap reads plus the stand's others)
COLUMNS = {
    "1520": ["Time (s)", "ESC signal (µs)", "Servo 1 (µs)", "Servo 2 (µs)", "Servo 3 (µs)", "Thrust ({u})",
             "Voltage (V)", "Current (A)", "Motor Electrical Speed (RPM)", "Motor Optical Speed (RPM)",
             "Electrical Power (W)", "Overall Efficiency (kgf/W)", "App message"],
    "1580": ["Time (s)", "ESC signal (µs)", "Servo 1 (µs)", "Servo 2 (µs)", "Servo 3 (µs)", "AccX (g)", "AccY (g)",
             "AccZ (g)", "Torque (N·m)", "Thrust ({u})", "Voltage (V)", "Current (A)",
             "Motor Electrical Speed (RPM)", "Motor Optical Speed (RPM)", "Electrical Power (W)",
             "Mechanical Power (W)", "Motor Efficiency (%)", "Propeller Mech. Efficiency (kgf/W)",
             "Overall Efficiency (kgf/W)", "Vibration (g)", "App message"],
    "1780": ["Time (s)", "ESC signal (µs)", "Torque (N·m)", "Thrust ({u})", "Voltage (V)", "Current (A)",
             "Motor Electrical Speed (RPM)", "Motor Optical Speed (RPM)", "Electrical Power (W)",
             "Mechanical Power (W)", "Motor Efficiency (%)", "Propeller Mech. Efficiency (kgf/W)",
             "Overall Efficiency (kgf/W)", "Temperature 1 (°C)", "Pressure (Pa)", "App message"],
}
COLUMNS["1585"] = COLUMNS["1580"]
#: Tyto's Flight Stand software: every channel but the time after its powertrain's name (as public analysis scripts
#: of its exports name them); its Fz is negative for a tractor's thrust
COLUMNS["flightstand"] = ["Time (s)", *(f"Powertrain 1 - {c}" for c in (
    "ESC throttle (μs)", "force Fz (thrust) ({u})", "torque MZ (torque) (N⋅m)", "voltage (V)", "current (A)",
    "rotation speed (rpm)", "electrical power (W)", "mechanical power (W)", "motor & ESC efficiency (%)",
    "propeller efficiency ({u}/W)", "powertrain efficiency ({u}/W)"))]


def write_steps_export(path, *, series="1585", thrust_unit="gf", prop="apce_8x6", params=None, pole_pairs=7,
                       electrical_raw=False, optical=True, noise=0.004, steps=(1000, 1150, 1250, 1350, 1450, 1550,
                                                                                 1650, 1750, 1850, 1950),
                       hold_s=3.0, rate_hz=10.0, seed=0, reaction_torque=True, pusher=False):
    """Write a "steps" test: each ESC step held ``hold_s`` seconds, sampled at ``rate_hz``.

    The rotor speed goes from 0 at 1000 us linearly to 9000 rpm at 2000 us, each step
    approached with a 0.25 s time constant; thrust and torque are propmap's at the
    instantaneous speed, with relative noise. ``pusher``: the thrust written negated (a
    pusher mount), the same digits otherwise. Returns the true (rpm, thrust [N], torque
    [N m]) of each step's steady state.
    """
    rng = np.random.default_rng(seed)
    p = pm.load_propeller(prop)
    params = params or pm.generic_params()
    rows, truth = [], []
    rpm_now, t = 0.0, 0.0
    for esc in steps:
        target = max(0.0, (esc - 1000) / 1000 * 9000.0)
        for k in range(int(hold_s * rate_hz)):
            rpm_now = target + (rpm_now - target) * math.exp(-1 / rate_hz / 0.25)
            if rpm_now > 1.0:
                r = pm.rotor_loads(p, params, rpm_now * math.pi / 30, 0.0, 0.0)
                T, Q = float(r.thrust), float(r.torque)
            else:
                T = Q = 0.0
            rows.append((t, esc, rpm_now, T * (1 + noise * rng.standard_normal()),
                         Q * (1 + noise * rng.standard_normal())))
            t += 1 / rate_hz
        if target > 0:
            r = pm.rotor_loads(p, params, target * math.pi / 30, 0.0, 0.0)
            truth.append((target, float(r.thrust), float(r.torque)))
    cols = [c.replace("{u}", thrust_unit) for c in COLUMNS[series]]
    lines = [",".join(cols)]
    flight_stand = series == "flightstand"
    for (t, esc, rpm, T, Q) in rows:
        vals = []
        for c in cols:
            c = c.split(" - ", 1)[1] if flight_stand and " - " in c else c
            c = {"ESC throttle (μs)": "ESC signal (µs)", "rotation speed (rpm)": "Motor Optical Speed (RPM)"}.get(c, c)
            if c.startswith("force Fz"):
                T, c = -T, c.replace("force Fz (thrust)", "Thrust")
            c = c.replace("torque MZ (torque)", "Torque")
            if c == "Time (s)":
                vals.append(f"{t:.3f}")
            elif c == "ESC signal (µs)":
                vals.append(f"{esc}")
            elif c.startswith("Thrust"):
                vals.append(f"{(-T if pusher else T) * THRUST_UNITS[thrust_unit]:.6g}")
            elif c.startswith("Torque"):
                vals.append(f"{-Q if reaction_torque else Q:.6g}")
            elif c == "Motor Electrical Speed (RPM)":
                vals.append(f"{rpm * (pole_pairs if electrical_raw else 1):.1f}")
            elif c == "Motor Optical Speed (RPM)":
                vals.append(f"{rpm:.1f}" if optical else "")
            elif c == "App message":
                vals.append("")
            else:
                vals.append(f"{rng.uniform(0, 1):.4f}")
        lines.append(",".join(vals))
    with open(path, "w", encoding="utf-8-sig", newline="") as fh:
        fh.write("\r\n".join(lines) + "\r\n")
    return np.array(truth)
