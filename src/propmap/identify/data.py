"""Identification data: load measurements (thrust-stand exports, UIUC runs) and their
readers; the level-flight conditions (eqs 16-18, identify/level_flight.py) are importable from
here too.

Readers raise :class:`DataError` (a ValueError) with a one-line message naming the file,
the line and the column, and for a value out of range the valid range; no other exception
escapes for any file content, and no reader modifies its input. The CSV rules (size,
encoding, quoting, column names, number syntax) and the valid ranges of every column are in
identify/csvfile.py.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from ..core.airfoil import Air
from ..io.catalogue import CatalogueEntry
from ..io.inputs import show_path
from .csvfile import DataError, RANGES, RPM, _Csv
from .level_flight import LevelFlightData, body_to_world, read_level_flight, rotor_kinematics

__all__ = ["DataError", "LevelFlightData", "LoadData", "read_level_flight", "read_loads", "loads_from_catalogue",
           "loads_from_uiuc_files", "body_to_world", "rotor_kinematics"]


@dataclass(frozen=True)
class LoadData:
    """Direct load measurements of one propeller.

    Attributes
    ----------
    omega, airspeed, incidence : ndarray, shape (N,)
        Operating points [rad/s, m/s, rad].
    measured : dict[str, ndarray]
        Any non-empty subset of ``thrust`` [N], ``drag`` [N], ``torque`` [N m], each shape (N,).
    group : ndarray of str, shape (N,)
        Run label of each point (for hold-out).
    source : str
    collective : ndarray, shape (N,), or None
        Blade-angle offset of each point [rad] (a collective sweep of a variable-pitch
        rotor); None: none.
    notes : tuple of str
        What the reader decided (units converted, rows skipped, steps averaged, a sign
        turned), for the user.

    Raises
    ------
    ValueError
        Built by hand with an array that is not numbers of shape (N,) (the length of
        ``omega``), a non-finite value (in ``measured`` NaN marks a load not measured at a
        point; an infinity is refused), ``omega`` <= 0 rad/s, ``airspeed`` < 0 m/s,
        ``incidence`` outside [0, pi] rad, an empty ``measured`` or a key of it other than
        thrust, drag, torque; the message names the field. (The readers check the signs and
        the ranges of the loads themselves.)
    """

    omega: np.ndarray
    airspeed: np.ndarray
    incidence: np.ndarray
    measured: dict
    group: np.ndarray
    source: str = ""
    collective: np.ndarray | None = None
    notes: tuple = ()

    def __post_init__(self):
        def floats(name, value, nan=False):
            try:
                a = np.asarray(value, dtype=float)
            except (TypeError, ValueError):
                raise ValueError(f"LoadData.{name} must be numbers, got {value!r:.60}") from None
            if a.ndim != 1:
                raise ValueError(f"LoadData.{name} must have shape (N,), got {a.shape}")
            if not np.all(np.isfinite(a) | (nan & np.isnan(a))):
                raise ValueError(f"LoadData.{name} must be finite (point {int(np.argmax(~np.isfinite(a)))} is not)")
            return a

        omega = floats("omega", self.omega)
        n = omega.size
        fields_ = {"omega": omega}
        for name in ("airspeed", "incidence") + (("collective",) if self.collective is not None else ()):
            a = floats(name, getattr(self, name))
            if a.size != n:
                raise ValueError(f"LoadData.{name} must have the N = {n} points of omega, got {a.size}")
            fields_[name] = a
        if np.any(omega <= 0):
            raise ValueError(f"LoadData.omega must be > 0 rad/s, got {omega[omega <= 0][0]:g}")
        if np.any(fields_["airspeed"] < 0):
            raise ValueError("LoadData.airspeed must be >= 0 m/s (a descent is an incidence above 90 deg)")
        if np.any((fields_["incidence"] < 0) | (fields_["incidence"] > np.pi)):
            raise ValueError("LoadData.incidence must be in [0, pi] rad (radians, not degrees)")
        if not isinstance(self.measured, dict) or not self.measured:
            raise ValueError("LoadData.measured must be a non-empty dict of thrust, drag or torque arrays")
        bad = [k for k in self.measured if k not in LOAD_KEYS]
        if bad:
            raise ValueError(f"LoadData.measured: unknown quantity {bad[0]!r} (valid: {', '.join(LOAD_KEYS)})")
        measured = {}
        for k, v in self.measured.items():
            a = floats(f"measured[{k!r}]", v, nan=True)  # (NaN: not measured there; the fits refuse it)
            if a.size != n:
                raise ValueError(f"LoadData.measured[{k!r}] must have the N = {n} points of omega, got {a.size}")
            measured[k] = a
        group = np.asarray(self.group, dtype=object)
        if group.shape != (n,):
            raise ValueError(f"LoadData.group must have shape ({n},), got {group.shape}")
        for name, a in {**fields_, "measured": measured, "group": group}.items():
            object.__setattr__(self, name, a)

    @property
    def n(self) -> int:
        """Number of points N."""
        return self.omega.size

    def subset(self, mask) -> "LoadData":
        """The points where ``mask`` is True."""
        mask = np.asarray(mask, bool)
        return LoadData(self.omega[mask], self.airspeed[mask], self.incidence[mask],
                        {k: v[mask] for k, v in self.measured.items()}, self.group[mask], self.source,
                        None if self.collective is None else self.collective[mask], self.notes)


LOAD_KEYS = ("thrust", "drag", "torque")
#: a point at an airspeed up to this [m/s] is static for the thrust's sign rule (:func:`read_loads`)
STATIC_AIRSPEED = 0.3


def read_loads(path, *, min_points: int = 6, rpm_source: str | None = None, pole_pairs: int | None = None) -> LoadData:
    """Read load measurements: a wind-tunnel or thrust-stand CSV, as written.

    Columns: a rotation speed and at least one of thrust, torque, drag, each named with or
    without a unit (``rpm``, ``thrust``, ``torque`` in rpm, N, N m; or ``thrust_kgf``,
    ``Thrust (gf)``, ``torque_Nmm``, ``Torque (N·m)``, ``speed_rad_s``; the units of
    :mod:`propmap.identify.stand`); ``airspeed`` [m/s] and ``incidence_deg`` (both default 0:
    a static thrust stand); optional ``collective_deg`` (blade-angle offset of a
    variable-pitch rotor, in [-45, 45] deg: a hover collective sweep is a valid data set)
    and ``group`` (run label). The exports of RCbenchmark / Tyto thrust stands (Series
    1520, 1580, 1585, 1780) are read as written: the optical or electrical motor speed (the
    choice stated), a "steps" test averaged to one point per ESC step (its settling rows
    dropped; each step a group for holding out), rows of a stopped motor (rpm 0, or an empty
    rotation speed, whose load cells may then be empty too) skipped, a rotation speed that is
    negative in every running row taken as its magnitude, and a stand's reaction torque
    (negative) turned to the propeller's; an ESC signal as a pulse width [us] or a throttle
    in percent or as a fraction, by its unit or its values (:func:`propmap.identify.stand.esc_form`);
    every decision is in ``LoadData.notes``. Format and valid ranges in the module docstring.

    Signs, decided after the ESC steps are averaged, on the points whose value is larger
    than 2% of the column's largest magnitude (those below are noise about zero), each
    decision a note: a torque negative at every static point is negated (the stand's
    reaction torque; without a static point: negative at every point nearest to static, the
    smallest axial advance |V cos(incidence)| / rpm, where the thrust, if measured, is
    positive); a torque of both signs there is refused; a torque of the other sign elsewhere
    is read as written (windmilling, noted), unless the thrust is positive there in climb or
    edgewise flow (a propeller that pulls takes power: refused). A thrust negative at every
    static point
    (airspeed at most :data:`STATIC_AIRSPEED`, no negative ``collective_deg``) is negated,
    whatever its sign at the other points: at a standstill a propeller pulls, so it is the
    sign of a pusher mount or of a stand mounted the other way round (propmap's thrust is
    positive in the direction the propeller pulls, opposite to its slipstream); a pusher's
    sweep past its zero-thrust advance ratio, written positive there, is negated as a whole.
    Any other thrust is read as written: beyond its zero-thrust advance ratio a propeller
    makes negative thrust, at some points of a sweep or at all of them (UIUC's apcsf_11x3.8
    run kt0545); a run without a static point keeps its sign (:func:`sanity_check` names a
    pusher's).

    Parameters
    ----------
    path : str or Path
    min_points : int
    rpm_source : {"optical", "electrical"}, optional
        Which speed column of a stand export to use (default: optical where present).
    pole_pairs : int, optional
        Divide an electrical speed by the motor's pole pairs (an export of raw electrical rpm).

    Returns
    -------
    LoadData

    Raises
    ------
    DataError
        Not a readable regular file (a directory, a device, over 200 MiB or 10,000,000
        lines), not UTF-8, a malformed CSV (unterminated quote, more fields than the
        header), no rotation-speed or no load column (the message lists the columns found
        and what was looked for), a unit it does not know, two columns for one quantity, an
        empty (except a rotation speed: an empty one is a stopped motor, skipped),
        non-numeric or non-finite value, a rotation speed negative in some rows and positive
        in others, a value out of range (rpm outside
        (0, 954929] once stopped rows are skipped, airspeed outside [0, 500] m/s,
        incidence_deg outside [0, 180], collective_deg outside [-45, 45], |thrust| or
        |drag| > 1e5 N, |torque| > 1e4 N m, all in SI after conversion), a torque of both signs
        at the static points (or those nearest to static), a negative torque where the
        thrust is positive in climb or edgewise flow, fewer than ``min_points`` points, or all operating points
        identical; the message names the file, the line and the column.
    """
    from .stand import ESC_TOL, esc_form, map_columns, stand_points

    what = "load data"
    f = _Csv(path, what)
    p = f.name
    try:
        cm = map_columns(f.header, rpm_source=rpm_source, pole_pairs=pole_pairs, error=DataError)
    except DataError as exc:
        raise DataError(f"{what}: {p}: {exc}") from None
    notes = list(cm.notes)
    power = [c for c in f.header if c.strip().lower().split("(")[0].split("[")[0].strip().replace("_", " ")
             in ("power", "shaft power", "mechanical power", "power w", "shaft power w", "mechanical power w")]
    if power and "torque" not in cm.columns:
        notes.append(f"{power[0]!r} is not read: propmap fits a torque column, Q = P / Omega (give it so, and the "
                     "fit uses the torque too)")
    speeds = [q for q in ("rpm", "rpm_optical", "rpm_electrical") if q in cm.columns]
    if "airspeed" not in cm.columns and "incidence_deg" in cm.columns:
        raise DataError(f"{what}: {p} has incidence_deg but lacks column airspeed")
    keys = [k for k in LOAD_KEYS if k in cm.columns]
    quantities = [*speeds, *(q for q in ("airspeed", "incidence_deg", "collective_deg", "esc", "time")
                             if q in cm.columns), *keys]
    low = {q: cm.column(q).lower() for q in quantities}
    optional = {low[q] for q in speeds} | ({low["time"]} if "time" in low else set())
    raw, texts, lines = f.read([low[q] for q in quantities], (low.get("group", "group"),), optional=optional,
                               stop={low[q] for q in speeds})
    v = {q: raw[low[q]] * cm.columns[q][1] for q in quantities}
    group_col = cm.column("group")
    # the rotation speed: a plain rpm column, else the stand's optical, else its electrical
    use = speeds[0]
    if use != "rpm":
        if rpm_source is not None:
            use = f"rpm_{rpm_source}"
        elif "rpm_optical" in v and v["rpm_optical"].size and np.nanmax(np.abs(np.nan_to_num(v["rpm_optical"]))) > 0:
            use = "rpm_optical"
        elif "rpm_electrical" in v:
            use = "rpm_electrical"
        notes.append(f"rotation speed from {cm.column(use)!r}" + (
            " (the optical probe)" if use == "rpm_optical" else
            (f", divided by {pole_pairs} pole pairs" if pole_pairs else
             ", as the stand computed it from its motor-pole setting; if the export is raw electrical rpm, give "
             "the pole pairs (--pole-pairs)")))
    if pole_pairs and use != "rpm_electrical":
        raise DataError(f"{what}: {p}: pole_pairs (--pole-pairs) divides an electrical speed, but the rotation "
                        f"speed is from {cm.column(use)!r} (give rpm_source='electrical', --rpm-source electrical, "
                        "to use the electrical one)")
    rpm = v[use] / (pole_pairs if (use == "rpm_electrical" and pole_pairs) else 1)
    for q in speeds:
        v.pop(q)
    v["rpm"] = rpm
    # a rotation speed of one sign: propmap's is its magnitude (a probe or ESC that reports the other sense negative);
    # a negative reading within 1% of the column's largest magnitude is a stopped motor's noise (0)
    big = np.nanmax(np.abs(rpm)) if rpm.size and not np.all(np.isnan(rpm)) else 0.0
    rpm = v["rpm"] = np.where((rpm < 0) & (np.abs(rpm) < 0.01 * big), 0.0, rpm)
    neg = np.nan_to_num(rpm) < 0
    if neg.any():
        if np.any(np.nan_to_num(rpm) > 0):
            k = int(np.argmax(neg))
            raise DataError(f"{what}: {p}, line {lines[k]}: {cm.column(use)!r} is {rpm[k]:g} rpm where other rows "
                            "are positive; a rotation speed must be positive, in (0, 954929] rpm (0 or empty: a "
                            "stopped motor, skipped)")
        rpm = v["rpm"] = -rpm
        notes.append(f"rotation speed negated: {cm.column(use)!r} is negative in every running row "
                     f"({int(neg.sum())}), a probe or ESC that reports this sense of rotation negative; propmap's "
                     "rotation speed is its magnitude")
    # stopped motor: rows skipped
    stopped = ~(np.nan_to_num(rpm) > 0)
    if stopped.any():
        notes.append(f"{int(stopped.sum())} rows with rpm 0 (or empty) skipped: a stopped motor")
        keep = ~stopped
        v = {k: a[keep] for k, a in v.items()}
        lines = lines[keep]
        texts = {k: [t for t, m in zip(col, keep) if m] for k, col in texts.items()}
    n = lines.size
    for c in ("airspeed", "incidence_deg"):
        v.setdefault(c, np.zeros(n))  # a static thrust stand
    # a "steps" test: one averaged point per ESC step
    group = (np.array(texts[group_col.lower()], dtype=object) if group_col and group_col.lower() in texts
             else None)
    form = None
    if "esc" in v:
        form, note = esc_form(cm.column("esc"), cm.columns["esc"][2], v["esc"])
        if note:
            notes.append(note)
    if form and n and np.unique(np.round(v["esc"] / (0.05 * ESC_TOL[form]))).size < n:
        esc, time = v.pop("esc"), v.pop("time", None)
        f.check_ranges({"rpm": v["rpm"]}, lines, RANGES)
        if n and np.all(np.isnan(v["rpm"])):
            raise DataError(f"{what}: {p}: no rotation speed in any row")
        v, group, dropped, unsteady = stand_points(v, esc, time, labels=group, form=form)
        if not group.size:
            raise DataError(f"{what}: {p}: no ESC step reaches a steady rotation speed (within 2% over the second "
                            "half of the step)")
        notes.append(f"{n} rows averaged into {group.size} ESC steps ({dropped} settling or unsteady rows dropped"
                     + (f"; {len(unsteady)} step(s) never steady, left out: {', '.join(unsteady)}" if unsteady else "")
                     + f"); each step is a group (e.g. --holdout {group[min(2, group.size - 1)]})")
        lines = np.zeros(group.size, dtype=np.int64)
        n = group.size
    else:
        v.pop("esc", None)
        v.pop("time", None)
    # the sign rules (docstring, docs/identification.md): the stand's sign turned to the propeller's
    if "thrust" in v and n:
        t = v["thrust"]
        big = _significant(t)
        static = big & (v["airspeed"] <= STATIC_AIRSPEED) & (v.get("collective_deg", np.zeros(n)) >= 0)
        if static.any() and np.all(t[static] < 0):
            v["thrust"] = -t
            notes.append(f"thrust negated: {cm.column('thrust')!r} is negative at every static point "
                         f"({int(static.sum())}; {int(np.sum(t[big] < 0))} of {int(big.sum())} points negative): a "
                         "pusher mount or a stand mounted the other way round; propmap's thrust is positive in the "
                         "direction the propeller pulls, opposite to its slipstream")
    if "torque" in v and n:
        v["torque"] = _torque_sign(v, what, p, cm.column("torque"), notes)
    named = {("rpm" if k == "rpm" else k): a for k, a in v.items()}
    f.check_ranges(named, lines if lines.any() else np.zeros(n, dtype=np.int64), RANGES)
    if n < min_points:
        raise DataError(f"{what}: {p} has {n} points; at least {min_points} are needed")
    collective = np.radians(v["collective_deg"]) if "collective_deg" in v else None
    ops = np.column_stack([v["rpm"], v["airspeed"], v["incidence_deg"], v.get("collective_deg", np.zeros(n))])
    if np.all(np.ptp(ops, axis=0) == 0):
        raise DataError(f"{what}: {p}: all operating points are identical")
    if group is None:
        group = np.full(n, "all", dtype=object)
    return LoadData(v["rpm"] * RPM, v["airspeed"], np.radians(v["incidence_deg"]), {k: v[k] for k in keys},
                    group, f"{path}", collective, tuple(notes))


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


def _check_diameter(diameter) -> None:
    """Raise DataError unless ``diameter`` is a number in (0, 10] m."""
    if isinstance(diameter, bool) or not isinstance(diameter, numbers.Real) or not 0 < diameter <= 10:
        raise DataError(f"diameter must be a finite number in (0, 10] m, got {diameter!r:.60}")


def loads_from_catalogue(entry: CatalogueEntry, diameter: float, *, air: Air = Air()) -> LoadData:
    """UIUC static runs and axial J-sweeps of a catalogue propeller as thrust and torque.

    T = CT rho n^2 D^4, Q = CP rho n^2 D^5 / (2 pi), V = J n D, incidence 0; groups are
    the UIUC run ids (e.g. ``"2801rd"``; static runs ``"static_<id>"``).

    Parameters
    ----------
    entry : CatalogueEntry
        Its bundled UIUC static runs and J-sweeps (:func:`propmap.io.catalogue.get_entry`).
    diameter : float
        Propeller diameter [m] (the coefficients' reference length), in (0, 10].
    air : Air
        Its density ``rho`` [kg/m^3] converts the coefficients.

    Returns
    -------
    LoadData
        Static points first, then the sweeps' points: ``omega`` [rad/s], ``airspeed``
        [m/s], ``incidence`` 0 [rad], ``measured`` with ``thrust`` [N] and ``torque``
        [N m], each shape (N,); ``source`` the entry's name and citation.

    Raises
    ------
    DataError
        The entry has no bundled measurements; a ``diameter`` outside (0, 10] m; or
        converted loads out of the ranges of :func:`read_loads` (|thrust| > 1e5 N, |torque|
        > 1e4 N m, airspeed outside [0, 500] m/s), the message naming the run's file.
    """
    _check_diameter(diameter)
    return _loads_from_runs(entry.static_runs(), entry.sweeps(), diameter, air, entry.name,
                            f"{entry.name}: {entry.citation}")


def loads_from_uiuc_files(paths, diameter: float, *, air: Air = Air()) -> LoadData:
    """UIUC-format static (``RPM CT CP``) and wind-tunnel (``J CT CP eta``) files as thrust and torque.

    Each file's kind is recognised from its header; extra header and ``key = value``
    lines (``RPM average = 4042``) are accepted (io.readers). Conversion as
    :func:`loads_from_catalogue`.

    Parameters
    ----------
    paths : sequence of str or Path
    diameter : float
        Propeller diameter [m] (the coefficients' reference length), in (0, 10].
    air : Air

    Returns
    -------
    LoadData

    Raises
    ------
    DataError
        A file that is neither kind, or malformed (as :func:`propmap.io.readers.read_uiuc_static`
        and :func:`~propmap.io.readers.read_uiuc_sweep`: not a readable regular file,
        non-numeric or non-finite values, RPM outside (0, 954929], CT or CP outside
        [-10, 10], J outside [0, 20]); a ``diameter`` outside (0, 10] m; or converted
        loads out of the ranges of :func:`read_loads` (|thrust| > 1e5 N, |torque| > 1e4
        N m, airspeed > 500 m/s). The message names the file.
    """
    from pathlib import Path

    from ..io.readers import MeasurementFileError, read_uiuc_static, read_uiuc_sweep

    _check_diameter(diameter)
    statics, sweeps, static_files, sweep_files = [], [], [], []
    for p in paths:
        p = Path(p)
        try:
            try:
                statics.append(read_uiuc_static(p))
                static_files.append(show_path(p))
            except MeasurementFileError as static_exc:
                try:
                    sweeps.append(read_uiuc_sweep(p))
                    sweep_files.append(show_path(p))
                except MeasurementFileError as sweep_exc:
                    if "expected columns" in str(sweep_exc) and "expected columns" not in str(static_exc):
                        raise static_exc from None
                    if "expected columns" in str(sweep_exc):
                        raise DataError(f"{show_path(p)}: not a UIUC static (RPM CT CP) or wind-tunnel (J CT CP eta) "
                                        "file") from None
                    raise
        except MeasurementFileError as exc:
            raise DataError(str(exc)) from None
    source = "UIUC-format files " + ", ".join(Path(p).name for p in paths)
    return _loads_from_runs(statics, sweeps, float(diameter), air, "UIUC files", source, [*static_files, *sweep_files])


def _loads_from_runs(statics, sweeps, diameter, air, name, source, files=None) -> LoadData:
    """Thrust and torque from the runs' coefficients; ``files``: each run's file (statics, then sweeps)."""
    om, V, T, Q, grp = [], [], [], [], []
    for s in statics:
        n = s.rpm / 60
        om.append(2 * math.pi * n), V.append(0 * n), grp.append(np.full(n.size, f"static_{s.run_id}"))
        T.append(s.CT * air.rho * n**2 * diameter**4), Q.append(s.CP * air.rho * n**2 * diameter**5 / (2 * math.pi))
    for w in sweeps:
        n = np.full(w.J.size, w.rpm / 60)
        om.append(2 * math.pi * n), V.append(w.J * n * diameter), grp.append(np.full(n.size, w.run_id))
        T.append(w.CT * air.rho * n**2 * diameter**4), Q.append(w.CP * air.rho * n**2 * diameter**5 / (2 * math.pi))
    if not om:
        raise DataError(f"{name} has no measurements")
    runs = [*statics, *sweeps]
    files = files or [run.source for run in runs]
    for label, arrays in (("thrust", T), ("torque", Q), ("airspeed", V)):
        lo, hi, _, _, unit = RANGES[label]
        for file, x in zip(files, arrays):
            if np.any((x < lo) | (x > hi)):  # coefficients, rpm and J are bounded: never NaN
                bad = float(x[np.argmax((x < lo) | (x > hi))])
                raise DataError(f"{file}: {label} {bad:.4g} {unit} (from the coefficients, the rpm and the diameter "
                                f"{diameter:g} m) is outside [{lo:g}, {hi:g}] {unit}")
    omega = np.concatenate(om)
    return LoadData(omega, np.concatenate(V), np.zeros(omega.size),
                    {"thrust": np.concatenate(T), "torque": np.concatenate(Q)}, np.concatenate(grp), source)


#: measured over predicted (generic set, the data's geometry) beyond which load data are refused
SANITY_FACTOR = 3.0
#: unit slips of load data: (factor on the measured thrust, on the measured torque, cause)
_UNIT_SLIPS = [
    (9.80665, 1.0, "thrust in kgf read as N (name the column thrust_kgf or 'Thrust (kgf)')"),
    (9.80665e-3, 1.0, "thrust in gf read as N (name the column thrust_gf or 'Thrust (gf)')"),
    (4.4482216152605, 1.0, "thrust in lbf read as N (name the column thrust_lbf)"),
    (1 / 9.80665, 1.0, "thrust in N declared as kgf"),
    (1.0, 1e-3, "torque in N mm read as N m (name the column torque_Nmm)"),
    (1.0, 0.0980665, "torque in kgf cm read as N m (name the column torque_kgfcm)"),
    (1.0, -1.0, ("a torque of the opposite sign, in a run the reader could not orient (no static point, and "
                 "no positive thrust where the propeller is nearest to static): negate the torque column")),
    (-1.0, 1.0, ("thrust of the opposite sign (a pusher mount, or a stand mounted the other way round; the reader "
                 "negates it only where it is negative at every static point): negate the "
                 "thrust column")),
]


def sanity_check(data: LoadData, propeller, *, params=None, air: Air | None = None) -> list[str]:
    """Refuse load data that cannot be this propeller's in these units; warn of risks.

    The measured thrust and torque are compared with the model's at the measured operating
    points (the generic set by default: hobby-propeller sections, accurate to about 10% blind,
    docs/validation.md): a median ratio beyond 1/3 to 3, or a thrust or torque of the other
    sign, is refused with the likely cause (thrust in kgf, gf or lbf read as N, torque in
    N mm, the electrical rpm of a motor with pole pairs, a reaction torque, a pusher's
    thrust in data the reader left as written).

    Parameters
    ----------
    data : LoadData
    propeller : Propeller
    params : SectionParams, optional
        The model compared with (default: the generic set).
    air : Air, optional
        Default: the set's.

    Returns
    -------
    list of str
        Warnings: a tip Mach number above 0.7 in the data; a measured in-plane force (drag)
        of the other sign than the model's at most points at incidence (propmap's D points
        along the in-plane airspeed, against the disk's in-plane motion: docs/conventions.md).

    Raises
    ------
    DataError
        The data are off by more than :data:`SANITY_FACTOR` (the message gives the factor and
        the likely cause).
    """
    from ..core.solver import rotor_loads
    from ..io.calibration import generic_params

    params = params or generic_params()
    air = params.air if air is None else air
    warnings_ = []
    tip = float(np.max(np.hypot(data.omega * propeller.radius + data.airspeed * np.sin(data.incidence),
                                data.airspeed * np.cos(data.incidence))) / air.speed_of_sound)
    if tip > 0.7:
        warnings_.append(f"tip Mach number up to {tip:.2f} in the data (> 0.7): compressibility beyond "
                         "Prandtl-Glauert is not modelled" + (" - or is the rpm electrical?" if tip > 1 else ""))

    def loads_at(omega):
        return rotor_loads(propeller, params, omega, data.airspeed, data.incidence, air=air, on_failure="flag",
                           collective=data.collective)

    at_rpm = loads_at(data.omega)  # (the drag's sign and the ratios at the measured rpm)

    def ratios(omega, fT=1.0, fQ=1.0, r=None):
        r = loads_at(omega) if r is None else r
        out = {}
        for key, model, f in (("thrust", r.thrust, fT), ("torque", r.torque, fQ)):
            if key not in data.measured:
                continue
            ok = np.isfinite(model) & (np.abs(model) > 0.05 * np.nanmax(np.abs(model)))
            if ok.sum() >= 2:
                out[key] = float(np.median(f * data.measured[key][ok] / model[ok]))
        return out

    def plausible(rat, lo=1 / SANITY_FACTOR, hi=SANITY_FACTOR):
        return all(lo <= v <= hi for v in rat.values())

    if "drag" in data.measured:  # the sign convention of the in-plane force (a fit of the other sign is nonsense)
        D = at_rpm.drag
        sure = np.isfinite(D) & np.isfinite(data.measured["drag"]) & (np.abs(D) > 0.1 * np.nanmax(np.abs(D), initial=0))
        opposite = int(np.sum(np.sign(data.measured["drag"][sure]) == -np.sign(D[sure])))
        if sure.sum() >= 3 and opposite >= 0.8 * sure.sum():
            warnings_.append(f"the measured drag has the other sign than the model's in-plane force at {opposite} of "
                             f"{int(sure.sum())} points at incidence: propmap's drag points along the in-plane "
                             "airspeed (against the disk's in-plane motion); negate the column if the file uses the "
                             "other convention")
    ratio = ratios(data.omega, r=at_rpm)
    if plausible(ratio):
        return warnings_
    bad = {k: v for k, v in ratio.items() if not (1 / SANITY_FACTOR <= v <= SANITY_FACTOR)}
    causes = [why for fT, fQ, why in _UNIT_SLIPS
              if plausible({k: v * (fT if k == "thrust" else fQ) for k, v in ratio.items()}, 0.6, 1.6)]
    # the electrical speed of a motor with pp pole pairs: the pp that brings the loads closest
    miss = {pp: max(abs(math.log(max(abs(v), 1e-300))) for v in ratios(data.omega / pp).values())
            for pp in range(2, 15)}
    pp = min(miss, key=miss.get)
    if miss[pp] < math.log(1.6):
        causes.append(f"the electrical rpm of a motor with {pp} pole pairs read as the propeller's (give "
                      f"--pole-pairs {pp}, or the optical speed)")
    said = "; ".join(f"{k} {v:.3g} times" for k, v in bad.items())
    raise DataError(f"load data: {data.source}: the measured {said} what the model predicts for {propeller.name} "
                    f"at the measured rpm (expected within {1 / SANITY_FACTOR:.2g}-{SANITY_FACTOR:g}x): "
                    + (f"likely {' or '.join(causes[:2])}" if causes else
                       "check the units, the rpm and the geometry (a 3-blade propeller given as 2?)"))
