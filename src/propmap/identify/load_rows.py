"""The rows and signs of a load file as :func:`propmap.identify.read_loads` reads it
(identify/loads_csv.py): a stopped motor's rows and a load cell's dropouts skipped, a stand's
zero offset noted, an optical speed probe's gaps filled from the electrical speed, and the
sign rules that turn the thrust and the torque columns into the propeller's.

The row and sign rules take the columns read so far (``v``, name -> float array, SI units,
rpm for the rotation speed) and append what they did to ``notes`` (one line each, the load
data's notes, which ``propmap fit loads`` prints); a file they cannot read raises
:class:`DataError` naming the file and the column.
"""

from __future__ import annotations

import re

import numpy as np

from .csvfile import DataError
from .load_data import STATIC_AIRSPEED

__all__: list[str] = []


def _skip_stopped(v: dict, lines, texts: dict, notes: list):
    """(v, lines, texts) without the rows of a stopped motor (rpm 0, empty or NaN), with a note
    of how many, of those whose thrust says the motor ran, and of the stand's load at rest."""
    rpm = v["rpm"]
    stopped = ~(np.nan_to_num(rpm) > 0)
    if stopped.any():
        running = 0
        if "thrust" in v:  # a speed of 0 with a thrust: the reading is missing, not the motor stopped
            t = np.abs(np.nan_to_num(v["thrust"]))
            running = int(np.sum(stopped & (t > 0.05 * max(float(t.max(initial=0.0)), 1e-300))))
        # a stand's zero: its load at rest, which propmap does not subtract (the torque's too since 2026-11-27: a
        # thrust-stand export audit, +0.003 N m on every row moved the fitted torque by +22%)
        tare = "" if running else "".join(_tare(v[q], stopped, q, unit) for q, unit in (("thrust", "N"),
                                                                                       ("torque", "N m")) if q in v)
        notes.append(f"{int(stopped.sum())} rows with rpm 0 (or empty or NaN) skipped: a stopped motor"
                     + (f"; {running} of them with a thrust above 5% of the largest: a speed reading missing while "
                        "the motor ran (those points are lost)" if running else "") + tare)
        keep = ~stopped
        v = {k: a[keep] for k, a in v.items()}
        lines = lines[keep]
        texts = {k: [t for t, m in zip(col, keep) if m] for k, col in texts.items()}
    return v, lines, texts


#: an optical probe's gaps are filled from the electrical speed where the two agree within this (median ratio)
OPTICAL_ELECTRICAL_TOL = 0.03


def _tare(load: np.ndarray, stopped: np.ndarray, name: str, unit: str) -> str:
    """A note where a load reads a zero offset at rest: its median over the stopped motor's rows
    above 1% of the lowest running steps' (the 10th percentile of its magnitude there) and twice
    the rest rows' scatter (a tared stand's rest rows scatter about 0); else ''."""
    load = np.asarray(load, float)
    rest, moving = load[stopped], np.abs(load[~stopped])
    rest, moving = rest[np.isfinite(rest)], moving[np.isfinite(moving)]
    zero = float(np.median(rest)) if rest.size else 0.0
    low = float(np.percentile(moving, 10)) if moving.size else 0.0  # (the lowest steps: a tare hurts them most)
    scatter = float(np.std(rest)) if rest.size > 1 else 0.0
    if low > 0 and abs(zero) > 0.01 * low and abs(zero) > 2 * scatter:
        return (f"; their {name} reads {zero:.4g} {unit} in the median ({abs(zero) / low:.1%} of the lowest running "
                f"steps'), a stand's zero offset? propmap fits the {name} as written: tare it first")
    return ""


def _skip_dropouts(v: dict, lines: np.ndarray, texts: dict, keys: list, cm, what: str, p: str, notes: list):
    """A sampled log's running rows with a load cell empty or NaN skipped, with a note (the
    first line named); a load column with no value in any running row is not read (a sensor
    the stand lacks), unless it is the only one. Returns (v, lines, texts, keys)."""
    empty = [k for k in keys if lines.size and np.isnan(v[k]).all()]
    if empty and len(empty) == len(keys):
        raise DataError(f"{what}: {p}: {', '.join(repr(cm.column(k)) for k in empty)} empty (or NaN) in every running "
                        "row: no loads to read")
    if empty:
        notes.append(f"{', '.join(repr(cm.column(k)) for k in empty)} empty (or NaN) in every running row: not read "
                     "(a sensor the stand lacks?)")
        v = {k: a for k, a in v.items() if k not in empty}
        keys = [k for k in keys if k not in empty]
    gap = np.zeros(lines.size, dtype=bool)
    for k in keys:
        gap |= np.isnan(v[k])
    if not gap.any():
        return v, lines, texts, keys
    names = ", ".join(repr(cm.column(k)) for k in keys if np.isnan(v[k]).any())
    if gap.all():  # (sensors written on alternate rows: 'has 0 points', the reason lost with the notes)
        raise DataError(f"{what}: {p}: every running row lacks one of {names} (empty or NaN): no row holds all the "
                        "loads; give them in one row per sample, or one load's columns alone")
    notes.append(f"{int(gap.sum())} of {gap.size} running rows skipped: {names} empty or NaN there (a sensor's "
                 f"dropout; the first at line {lines[int(np.argmax(gap))]})")
    keep = ~gap
    return ({k: a[keep] for k, a in v.items()}, lines[keep],
            {k: [t for t, m in zip(col, keep) if m] for k, col in texts.items()}, keys)


def _optical_gaps(optical: np.ndarray, electrical: np.ndarray, column: str, notes: list) -> np.ndarray:
    """The optical speed with its dropouts (0 or empty where the electrical speed runs: above
    5% of its median where both read) taken from the electrical one, where the two agree
    elsewhere (median ratio within OPTICAL_ELECTRICAL_TOL: the stand's motor-pole setting is
    right) or the ratio is that close to a whole number of pole pairs (a raw electrical rpm,
    divided by it), with a note. Only where the optical speed was chosen by default (no
    rpm_source)."""
    o, e = np.nan_to_num(optical), np.nan_to_num(electrical)
    both = (o > 0) & (e > 0)
    if both.sum() < 3:
        return optical
    # running: above 5% of the typical electrical speed (a stopped motor's ESC may report a few rpm of noise)
    gap = (o <= 0) & (e > 0.05 * float(np.median(e[both])))
    if not gap.any():
        return optical
    ratio = float(np.median(e[both] / o[both]))
    pp = max(round(ratio), 1)
    if pp >= 2 and abs(ratio / pp - 1.0) <= OPTICAL_ELECTRICAL_TOL:  # raw electrical rpm: pp pole pairs times (a
        # user-level audit: the dropouts were left out although the ratio said how to fill them)
        notes.append(f"{column!r} reads 0 or nothing in {int(gap.sum())} rows where the electrical speed runs (a probe "
                     f"dropout): those rows take the electrical speed divided by {pp}, the motor's pole pairs by the "
                     f"two speeds' median ratio elsewhere ({ratio:.4g}: a raw electrical rpm)")
        return np.where(gap, electrical / pp, optical)
    if abs(ratio - 1.0) > OPTICAL_ELECTRICAL_TOL:
        notes.append(f"{column!r} reads 0 or nothing in {int(gap.sum())} rows where the electrical speed runs; not "
                     f"filled from it, which reads {ratio:.3g} times the optical speed elsewhere (the stand's "
                     "motor-pole setting?)")
        return optical
    notes.append(f"{column!r} reads 0 or nothing in {int(gap.sum())} rows where the electrical speed runs (a probe "
                 f"dropout): those rows take the electrical speed, within {abs(ratio - 1.0):.1%} of the optical one "
                 "elsewhere (median)")
    return np.where(gap, electrical, optical)


def _thrust_sign(v: dict, column: str, notes: list) -> np.ndarray:
    """The thrust as the propeller's: negated where it is negative at every static point (the
    sign of a pusher mount or of a stand mounted the other way round), else as written
    (read_loads' sign rules)."""
    t = v["thrust"]
    big = _significant(t)
    static = big & (v["airspeed"] <= STATIC_AIRSPEED) & (v.get("collective_deg", np.zeros(t.size)) >= 0)
    if static.any() and np.all(t[static] < 0):
        # (a Flight Stand's 'force Fz (thrust)' is negative as its axis is: 'a pusher mount' misled, an export audit)
        why = ("the stand's force axis Fz points along the slipstream (as a Flight Stand's does)"
               if re.search(r"\bf ?z\b", column.lower()) else "a pusher mount or a stand mounted the other way round")
        notes.append(f"thrust negated: {column!r} is negative at every static point "
                     f"({int(static.sum())}; {int(np.sum(t[big] < 0))} of {int(big.sum())} points negative): {why}; "
                     "propmap's thrust is positive in the direction the propeller pulls, opposite to its slipstream")
        return -t
    return t


def _torque_sign(v: dict, what: str, p: str, column: str, notes: list) -> np.ndarray:
    """The torque column turned to the propeller's sign (read_loads' docstring, the sign rules).

    The reference points are the significant static ones (airspeed at most
    :data:`STATIC_AIRSPEED`), else those nearest to static, at the smallest axial advance
    |V cos(incidence)| / rpm. At a standstill a propeller takes power whatever its collective,
    so a torque negative at every static point is the stand's reaction torque and is negated.
    Without a static point the same holds where the thrust is significantly positive at the
    reference points (in axial climb the shaft power is at least T V: a propeller that pulls
    takes power), and, with no thrust column, a torque negative at all of them is taken for a
    reaction torque too; where the thrust is negative there (a run beyond its zero-thrust
    advance ratio) the torque keeps its sign and :func:`sanity_check` judges it. A negative
    torque elsewhere is windmilling (beyond the zero-torque advance ratio) and kept with a
    note, but in climb or edgewise flow (V cos(incidence) >= 0) not where the thrust is
    significantly positive: the torque changes sign after the thrust. That is exact in axial
    climb; at incidence the in-plane force's work enters the balance (Q Omega >= T V
    cos(incidence) - H V sin(incidence)) and it is what the model gives (apce_8x6, 0-90 deg,
    collective -10 to +10 deg, 2-40 m/s: no point with T > 0 and Q < 0). In descent (the
    windmill-brake state) a rotor may both pull and give power.
    """
    q = v["torque"]
    big = _significant(q)
    if not big.any():
        return q
    static = big & (v["airspeed"] <= STATIC_AIRSPEED)
    t = v.get("thrust")
    pulling = None if t is None else _significant(t) & (t > 0)
    if static.any():
        ref, where = static, "the static points"
        reaction = np.all(q[ref] < 0)
    else:
        x = np.abs(v["airspeed"] * np.cos(np.radians(v["incidence_deg"]))) / v["rpm"]
        xmin = np.min(x[big])
        ref, where = big & (x <= xmin + 1e-9 * xmin), "the points nearest to static (smallest axial advance)"
        reaction = np.all(q[ref] < 0) and (pulling is None or np.all(pulling[ref]))
    if np.any(q[ref] < 0) and np.any(q[ref] > 0):
        raise DataError(f"{what}: {p}: column {column!r} has both signs at {where} ({int(np.sum(q[ref] < 0))} "
                        f"negative, {int(np.sum(q[ref] > 0))} positive): there a propeller takes power, so one "
                        "propeller turning one way has one torque sign")
    if reaction:
        q = -q
        notes.append(f"torque negated: it is the stand's reaction torque (negative at {where}"
                     + ("" if static.any() else ", where the propeller pulls" if t is not None else "")
                     + "); the propeller's torque opposes its rotation")
    neg = big & (q < 0)
    if neg.any():
        if pulling is not None:
            climb = np.cos(np.radians(v["incidence_deg"])) >= 0
            pulls = neg & climb & pulling
            if pulls.any():
                raise DataError(f"{what}: {p}: column {column!r} is negative at {int(neg.sum())} points, "
                                f"{int(pulls.sum())} of them with positive thrust in climb or edgewise flow: a "
                                "propeller that pulls takes power, so the torque changes sign only beyond the "
                                "zero-thrust advance ratio (windmilling); is part of the file a reaction torque, "
                                "or the thrust of the other sign (a pusher mount)?")
        speeds = v["airspeed"][neg]
        notes.append(f"torque negative at {int(neg.sum())} of {int(big.sum())} points (airspeed {np.min(speeds):.3g}-"
                     f"{np.max(speeds):.3g} m/s), read as written: the propeller windmills there, beyond its "
                     "zero-torque advance ratio" + ("" if static.any() or reaction else
                                                    " (no static point: the sanity check compares the sign with "
                                                    "the model's)"))
    return q


def _significant(x: np.ndarray) -> np.ndarray:
    """Mask of the values larger than 2% of the largest |x| (all False for a column of zeros):
    the points whose sign counts in the reader's sign rules (values near zero are noise)."""
    return np.abs(x) > 0.02 * np.max(np.abs(x)) if np.any(x) else np.zeros(x.size, bool)
