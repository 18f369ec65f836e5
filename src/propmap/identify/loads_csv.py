"""The reader of load measurements as written: a wind-tunnel or thrust-stand CSV
(:func:`read_loads`); its rules for rows and signs (a stopped motor, a sensor's dropouts, the
thrust and torque signs) are in identify/load_rows.py.

It raises :class:`DataError` (a ValueError) with a one-line message naming the file, the line
and the column, and for a value out of range the valid range; no other exception escapes for
any file content, and the file is not modified. The CSV rules (size, encoding, quoting,
column names, number syntax) and the valid ranges of every column are in identify/csvfile.py,
the thrust stands' exports in identify/stand.py, the air a file's columns give in
identify/loads_air.py.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..core._numbers import integer
from ..core.units import RPM
from ..io.params_tables import COVERAGE_TEXT_MAX
from .csvfile import RANGES, DataError, _Csv
from .headers import AXIAL_RATES, RATIO_TO_AIRSPEED
from .loads_air import _air_density, _conditions_density
from .load_data import LOAD_KEYS, STATIC_AIRSPEED, LoadData, radians_hint
from .load_rows import _optical_gaps, _skip_dropouts, _skip_stopped, _thrust_sign, _torque_sign


def read_loads(path, *, min_points: int = 6, rpm_source: str | None = None, pole_pairs: int | None = None) -> LoadData:
    """Read load measurements: a wind-tunnel or thrust-stand CSV, as written.

    Columns: a rotation speed and at least one of thrust, torque, drag, each named with or
    without a unit (``rpm``, ``thrust``, ``torque`` in rpm, N, N m; or ``thrust_kgf``,
    ``Thrust (gf)``, ``torque_Nmm``, ``Torque (N·m)``, ``speed_rad_s``; the units of
    :mod:`propmap.identify.stand`); ``airspeed`` [m/s] and ``incidence_deg`` (both default 0:
    a static thrust stand); optional ``collective_deg`` (blade-angle offset of a
    variable-pitch rotor, in [-45, 45] deg: a hover collective sweep is a valid data set)
    and ``group`` (run label); beside a torque, an optional hub rolling moment [N m]
    (``rolling moment``, ``roll moment``, ``hub rolling moment``, with a torque's unit; propmap's
    sign, docs/conventions.md; beside no torque it is not read, with a note: a balance's rolling
    moment about its shaft is the torque); optional ``air density`` [kg/m^3] (``Air Density (kg/m³)``, ``rho``;
    its median is ``LoadData.air_density``). The exports of RCbenchmark / Tyto thrust stands (Series
    1520, 1580, 1585, 1780) are read as written: the optical or electrical motor speed (the
    choice stated), a "steps" test averaged to one point per ESC step (its settling rows
    dropped; each step a group for holding out), rows of a stopped motor (rpm 0, or an empty
    rotation speed, whose load cells may then be empty too) skipped, a rotation speed that is
    negative in every running row taken as its magnitude, and a stand's reaction torque
    (negative) turned to the propeller's; an ESC signal as a pulse width [us] or a throttle
    in percent or as a fraction, by its unit or its values (:func:`propmap.identify.steps.esc_form`;
    cells ending in ``%``, ``50%``, a throttle in percent); every decision is in ``LoadData.notes``.
    Format and valid ranges in the module docstring.

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
        The fewest distinct operating points accepted (6 for a fit); with 1 (a comparison,
        ``propmap validate``) every operating point may also be the same one (a repeatability
        run).
    rpm_source : {"optical", "electrical"}, optional
        Which speed column of a stand export to use (default: optical where present, its
        dropouts, 0 or empty while the electrical speed runs, taken from the electrical speed
        where the two agree within 3% elsewhere, with a note).
    pole_pairs : int, optional
        Divide an electrical speed by the motor's pole pairs (an export of raw electrical rpm).

    Returns
    -------
    LoadData
        The points in SI, with ``notes`` (every decision), ``air_density`` (the file's, or
        None) and ``converted`` (the factor each load column's unit was converted by).

    Raises
    ------
    DataError
        Not a readable regular file (a directory, a device, over 200 MiB or 10,000,000
        lines), not UTF-8, a malformed CSV (unterminated quote, more fields than the
        header), no rotation-speed or no load column (the message lists the columns found
        and what was looked for), a unit it does not know, two columns for one quantity, an
        empty (except a rotation speed: an empty one is a stopped motor, skipped; and a load
        cell of a sampled log, a file with an ESC or time column, empty or NaN: that row is
        skipped with a note, a load column empty in every running row not read),
        non-numeric or non-finite value, a rotation speed negative in some rows and positive
        in others, a value out of range (rpm outside
        (0, 954929] once stopped rows are skipped, airspeed outside [0, 500] m/s,
        incidence_deg outside [0, 180], collective_deg outside [-45, 45], an air density
        outside [0.05, 5] kg/m^3 (AIR_DENSITY_RANGE), |thrust| or
        |drag| > 1e5 N, |torque| > 1e4 N m, all in SI after conversion), a torque of both signs
        at the static points (or those nearest to static), a negative torque where the
        thrust is positive in climb or edgewise flow, fewer than ``min_points`` points or distinct
        operating points, or all operating points identical (where ``min_points`` > 1), a
        column of PROPELLER_COLUMNS that names several propellers, a bare ``J`` or ``mu`` of
        values other than 0 where no airspeed is read (an advance ratio), a steps log whose ESC
        signal stays within one tolerance while the speed varies; the message names the file,
        the line and the column.
    ValueError
        ``min_points`` not an integer >= 1 (before the file is read).

    Warns
    -----
    UserWarning
        Rows that repeat another row to every digit, operating point and loads (a table
        pasted twice); an airspeed column reading 0.3-1.5 m/s at every point (a static
        stand's pitot); an incidence column without a unit that looks like radians.
    """
    from .stand import split_header

    min_points = integer("min_points", min_points, 1)
    what = "load data"
    f = _Csv(path, what, windows_1252=True, spreadsheet=True)
    p = f.name

    f, cm = _header_columns(f, rpm_source, pole_pairs, what, p)
    _rolling_moment_without_torque(cm)
    notes = [*f.notes, *cm.notes]
    _power_note(f.header, cm, notes)
    _side_loads_note(f.header, cm, notes)
    speeds = [q for q in ("rpm", "rpm_optical", "rpm_electrical") if q in cm.columns]
    # a bare J or mu where no airspeed is read: an advance ratio unless 0 everywhere (or a viscosity's ~1e-5 Pa s)
    ratio = [c for c in f.header if c.strip().lower() in ("j", "mu")] if "airspeed" not in cm.columns else []
    if "airspeed" not in cm.columns and "incidence_deg" in cm.columns:  # (with J or mu: say how, an audit)
        raise DataError(f"{what}: {p} has incidence_deg but lacks column airspeed" + (
            f" (is {ratio[0]!r} an advance ratio? give the airspeed, {RATIO_TO_AIRSPEED})" if ratio else ""))
    keys = [k for k in LOAD_KEYS if k in cm.columns]
    quantities = [*speeds, *(q for q in ("airspeed", "incidence_deg", "collective_deg", "esc", "time", "air_density",
                                         *AXIAL_RATES) if q in cm.columns), *keys]
    low = {q: cm.column(q).lower() for q in quantities}
    optional = {low[q] for q in speeds} | {low[q] for q in ("time", "air_density") if q in low}
    # a sampled log (a stand export, a time column): a load cell empty or NaN in a row is a sensor's dropout, that
    # row skipped below; in a table of points each row is a point and such a cell is refused
    sampled = "esc" in cm.columns or "time" in cm.columns
    # a column naming the propeller of each row: several in one file were fitted as one (a wind-tunnel data audit,
    # 2026-11-27: the thrust 44-64% off, exit 0)
    named = [c for c in f.header if _propeller_column(*split_header(c))]
    raw, texts, lines = f.read([low[q] for q in quantities] + [c.lower() for c in ratio],
                               ((cm.column("group") or "group").lower(), *(c.lower() for c in named)),
                               optional={*optional, *(c.lower() for c in ratio)}, stop={low[q] for q in speeds},
                               gaps={low[q] for q in keys} if sampled else (),
                               percent={low["esc"]} if "esc" in low else (), mean_row=True)
    notes += f.read_notes
    if "esc" in low and low["esc"] in f.percent_cells:
        cm.columns["esc"] = _esc_in_percent(cm.columns["esc"], raw[low["esc"]], notes)
    _check_unread_columns(raw, texts, ratio, named, what, p, notes)
    v = {q: raw[low[q]] * cm.columns[q][1] for q in quantities}
    group_col = cm.column("group")
    v, speed_column = _rotation_speed(v, speeds, cm, rpm_source, pole_pairs, lines, what, p, notes)
    v, lines, texts = _skip_stopped(v, lines, texts, notes)
    if sampled:
        v, lines, texts, keys = _skip_dropouts(v, lines, texts, keys, cm, what, p, notes)
    n = lines.size
    if "airspeed" in v:
        v["airspeed"] = _pitot_noise(v["airspeed"], cm.column("airspeed"), notes, sampled)
    _axial_rate(v, cm, notes)
    for c in ("airspeed", "incidence_deg"):
        v.setdefault(c, np.zeros(n))  # a static thrust stand
    air_density = _air_density(v.pop("air_density", None), cm.column("air_density"), what, p, notes)
    if air_density is None:  # (a tunnel's temperature and pressure columns were once ignored: sea-level air)
        air_density = _conditions_density(f, what, p, notes)
    # a "steps" test: one averaged point per ESC step
    group = (np.array(texts[group_col.lower()], dtype=object) if group_col and group_col.lower() in texts
             else None)
    if group is not None and n:  # (an empty cell was a group named '', which --holdout could not name: an audit)
        empty = np.flatnonzero(np.array([not str(g).strip() for g in group]))
        if empty.size:
            raise DataError(f"{what}: {p}: column {group_col!r} is empty at line {int(lines[empty[0]])} ({empty.size} "
                            "row(s)): give every row its group label, or drop the column")
        # (a fit's [coverage] lists the groups, each of at most COVERAGE_TEXT_MAX characters: a longer label was
        # refused once the whole fit had run, naming [coverage], not the column: an audit, stop 102)
        long = np.flatnonzero(np.array([len(str(g)) > COVERAGE_TEXT_MAX for g in group]))
        if long.size:
            raise DataError(f"{what}: {p}: column {group_col!r} holds a label of {len(str(group[long[0]]))} "
                            f"characters at line {int(lines[long[0]])}: at most {COVERAGE_TEXT_MAX}")
    v, group, lines, n, averaged = _steps_or_points(f, cm, v, group, lines, what, p, notes)
    # the sign rules (docstring, docs/identification.md): the stand's sign turned to the propeller's
    if "thrust" in v and n:
        v["thrust"] = _thrust_sign(v, cm.column("thrust"), notes)
    if "torque" in v and n:
        v["torque"] = _torque_sign(v, what, p, cm.column("torque"), notes)
    named = {("rpm" if k == "rpm" else k): a for k, a in v.items()}
    f.check_ranges(named, lines if lines.any() else np.zeros(n, dtype=np.int64), RANGES,
                   written={q: cm.columns[q][:2] for q in cm.columns})
    collective = np.radians(v["collective_deg"]) if "collective_deg" in v else None
    _check_points(v, keys, cm, min_points, averaged, what, p)
    if group is None:
        group = np.full(n, "all", dtype=object)
    return LoadData(v["rpm"] * RPM, v["airspeed"], np.radians(v["incidence_deg"]), {k: v[k] for k in keys},
                    group, f"{path}", collective, tuple(notes), air_density,
                    {k: cm.columns[k][1] for k in keys if cm.columns[k][1] != 1.0},
                    tuple(k for k in keys if low[k] in f.comma_thousands), speed_column.removeprefix("rpm_"))


def _header_columns(f, rpm_source, pole_pairs, what: str, p: str):
    """(the file, its column map): the header's columns mapped to propmap's quantities, or, where
    a preamble stands above the header (a test's name, a date), those of the first line below
    that names the columns; DataError naming the file where no line does."""
    from .stand import map_columns

    def columns(header):
        return map_columns(header, rpm_source=rpm_source, pole_pairs=pole_pairs, error=DataError)

    try:
        cm = columns(f.header)
    except DataError as exc:
        below = f.after_preamble(lambda header: _succeeds(columns, header))
        if below is None:
            raise DataError(f"{what}: {p}: {exc}") from None
        f, cm = below, columns(below.header)
    return f, cm


def _esc_in_percent(column: tuple, values: np.ndarray, notes: list) -> tuple:
    """The ESC column's (name, factor, unit) where its cells end in '%' (a motor maker's table:
    ``Throttle`` over ``50%``, refused as not a number until 2026-11-30): the unit '%' where the
    header gives none, so that the signal is read as a throttle in percent, with a note (not
    where the values stay within 1, which esc_form reads as a fraction and says so: both notes,
    percent then fraction, were given for 0.3%-0.8%)."""
    name, factor, unit = column
    if unit is None:
        if np.nanmax(np.abs(values), initial=0.0) > 1.0:
            notes.append(f"{name!r}: its values end in %: read as a throttle in percent")
        return name, factor, "%"
    return column


#: in a sampled log, negative airspeeds down to this [m/s] are a pitot's noise where few (PITOT_SPIKES of the samples)
PITOT_NOISE_SAMPLED = 1.0
PITOT_SPIKES = 0.02


def _pitot_noise(airspeed: np.ndarray, name: str, notes: list, sampled: bool = False) -> np.ndarray:
    """The airspeed with negative values down to -STATIC_AIRSPEED, a static stand's pitot noise
    about zero, read as 0, with a note (a Series 1780 export reading -0.2 to +0.4 m/s at rest was
    refused as a descent given as a negative airspeed: a thrust-stand export audit, 2026-11-30);
    in a ``sampled`` log also those down to -PITOT_NOISE_SAMPLED where they are at most
    PITOT_SPIKES of the samples (one sample of -0.31 m/s in 648, a tunnel log's noise of 0.15 m/s rms
    at rest, refused the log: a thrust-stand data audit, 2026-11-30; a descent given as negative
    airspeeds has many). Others stay, for the range check to refuse, naming them."""
    band = STATIC_AIRSPEED
    if sampled:
        beyond = (airspeed < -STATIC_AIRSPEED) & (airspeed >= -PITOT_NOISE_SAMPLED)
        if beyond.sum() <= PITOT_SPIKES * airspeed.size and not (airspeed < -PITOT_NOISE_SAMPLED).any():
            band = PITOT_NOISE_SAMPLED
    noise = (airspeed < 0.0) & (airspeed >= -band)
    if not noise.any():
        return airspeed
    notes.append(f"{name!r}: {int(noise.sum())} value(s) from {airspeed[noise].min():.3g} to 0 m/s (a static "
                 f"stand's pitot noise about zero, within {band:g} m/s) read as 0")
    return np.where(noise, 0.0, airspeed)


def _power_note(header, cm, notes: list) -> None:
    """A note that a power column is not read where no torque column is (Q = P / Omega)."""
    power = [c for c in header if c.strip().lower().split("(")[0].split("[")[0].strip().replace("_", " ")
             in ("power", "shaft power", "mechanical power", "power w", "shaft power w", "mechanical power w")]
    if power and "torque" not in cm.columns:
        bare = power[0].strip().lower().replace("_", " ").startswith("power")
        # (a motor maker's 'Power (W)' is the electrical V I: a torque from it, as the note advised, was 1.43 times the
        # shaft's and validated without a warning, an export audit, 2026-12-02)
        electrical = bare and any(c.strip().lower().startswith(("voltage", "current")) for c in header)
        notes.append(f"{power[0]!r} is not read: propmap fits a torque column, Q = P / Omega with P the shaft "
                     "(mechanical) power, not the electrical V I, which holds the motor's and ESC's losses" + (
                         f" ({power[0]!r} beside a voltage and a current is likely the electrical one)"
                         if electrical else "") + "; give the torque so, and the fit uses it too")


#: the loads a wind-tunnel balance gives besides the thrust, in-plane force, torque and rolling moment, which propmap
#: predicts (with flapping or a linear inflow, docs/models.md) but does not fit or validate (the rolling moment is read
#: since 2026-12-01)
_SIDE_LOADS = ("side force", "sideforce", "lateral force", "y force", "pitching moment", "pitch moment",
               "yawing moment", "yaw moment", "hub moment", "hub pitching moment")


def _side_load_name(column: str) -> str | None:
    """The side force's or hub moment's name (of :data:`_SIDE_LOADS`) that ``column`` is, with or
    without a unit in brackets, after a comma, a blank or an underscore ('Side force, N',
    'side_force_lbf', 'rolling_moment_N_m'); None for any other column."""
    from .headers import UNITS, _token

    text = column.strip().lower().split("(")[0].split("[")[0].split(",")[0].replace("_", " ").strip()
    units = {**UNITS["force"], **UNITS["torque"]}
    for name in _SIDE_LOADS:
        if text == name or (text.startswith(name + " ") and _token(text[len(name):]) in units):
            return name
    return None


def _rolling_moment_without_torque(cm) -> None:
    """A rolling-moment column is not read where no torque column is, with a note: a balance's
    rolling moment about its own x axis, along the shaft, is the propeller's torque (a wind-tunnel
    data audit's file, 2026-11-30, had 'rolling moment (N m)' and no torque); beside a torque
    column it is the hub's rolling moment about the in-plane airspeed (since 2026-12-01)."""
    if "rolling_moment" not in cm.columns or "torque" in cm.columns:
        return
    name = cm.columns.pop("rolling_moment")[0]
    cm.notes[:] = [n for n in cm.notes if not n.startswith(f"{name!r} converted")]
    cm.notes.append(f"{name!r} is not read: beside no torque column a balance's rolling moment may be its moment "
                    "about the rotor axis, the torque: name that column 'torque' (with a torque column too, propmap "
                    "reads it as the hub's rolling moment about the in-plane airspeed, docs/identification.md)")


def _side_loads_note(header, cm, notes: list) -> None:
    """A note naming a side force or hub moment column, which is not read (a wind-tunnel file's
    'side force (N)' and 'pitching moment (N m)' were left out without a word: a wind-tunnel
    data audit, 2026-11-30); beside no torque column, that a balance's moment about the rotor
    axis is the torque."""
    side = [c for c in header if _side_load_name(c)]
    if side:
        moment = "torque" not in cm.columns and any("moment" in _side_load_name(c) for c in side)
        notes.append(f"{', '.join(repr(c) for c in side)} {'is' if len(side) == 1 else 'are'} not read: propmap "
                     "fits and validates the thrust, the in-plane force (drag, along the in-plane airspeed), the "
                     "torque and the rolling moment; the side force and the pitching moment it predicts "
                     "(rotor_loads' side_force, pitching_moment) are not compared with measurements"
                     + ("; a balance's moment about the rotor axis is the torque: name that column 'torque'"
                        if moment else ""))


def _check_unread_columns(raw: dict, texts: dict, ratio: list, named: list, what: str, p: str, notes: list) -> None:
    """Refuse an advance-ratio column (J or mu) that is not 0 everywhere (left unread, every point
    would be static) and a propeller column that names more than one propeller; note the one it
    names."""
    for c in ratio:
        if np.nanmax(np.abs(raw[c.lower()]), initial=0.0) > 1e-3:  # (an axial sweep's J read as static: the thrust
            # 11-23% off, a wind-tunnel data audit, 2026-11-27)
            raise DataError(f"{what}: {p}: column {c!r} looks like an advance ratio, which propmap reads only as "
                            f"'airspeed' [m/s] ({RATIO_TO_AIRSPEED}): convert it, or remove it; left unread, "
                            "every point would be taken as static (airspeed 0)")
    for c in named:
        props = sorted({t.casefold(): t for t in texts[c.lower()] if t}.values())  # (APC 10x7 and apc 10x7 are one)
        if len(props) > 1:
            raise DataError(f"{what}: {p}: column {c!r} names {len(props)} propellers ({', '.join(props[:4])}"
                            f"{' ...' if len(props) > 4 else ''}): propmap fits one propeller's loads; write each "
                            "propeller's rows to a file of its own")
        if props:
            notes.append(f"column {c!r} names {props[0]} on every row (the geometry is the one given to the fit)")


def _steps_or_points(f, cm, v: dict, group, lines: np.ndarray, what: str, p: str, notes: list):
    """(v, group, lines, n, averaged): a stand's "steps" test (an ESC signal column whose rows
    repeat a step, or at most 40 rows each a step of its own) averaged to one point per step
    (:func:`_average_steps`), else each row a point (the ESC and time columns dropped, with a
    note where a long log has a time column but no ESC signal column)."""
    from .steps import ESC_TOL, esc_form

    n = lines.size
    form = None
    if "esc" in v:
        form, note = esc_form(cm.column("esc"), cm.columns["esc"][2], v["esc"])
        if note:
            notes.append(note)
    averaged = bool(form and n and (np.unique(np.round(v["esc"] / (0.05 * ESC_TOL[form]))).size < n
                                    # (an export of one row per step, already averaged: each row its step, so that
                                    # the steps are groups; a ramp's rows, a few us apart, are not steps; a file's
                                    # own group column keeps its groups)
                                    or (group is None and n <= 40
                                        and np.all(np.abs(np.diff(v["esc"])) >= 5 * ESC_TOL[form]))))
    if averaged:
        f.check_ranges({"rpm": v["rpm"]}, lines, RANGES)
        v, group = _average_steps(v, group, form, cm.column("esc"), f"{what}: {p}", notes)
        lines = np.zeros(group.size, dtype=np.int64)
        n = group.size
    else:
        if v.pop("esc", None) is not None and "time" in v and n > 40:
            # (a sweep's 1400 rows were fitted as points without a word: an export audit, 2026-12-02)
            notes.append(f"each of the {n} rows is a point: no two rows of {cm.column('esc')!r} hold one value (a "
                         "continuous sweep, no held steps to average), so each is taken as the motor followed the "
                         "sweep (near steady in a slow sweep, not in a fast one)")
        if v.pop("time", None) is not None and "esc" not in cm.columns and n > 40:
            # (a stand log whose signal column went unread, 'PWM (µs)', had its 380 raw samples fitted as points with
            # no word: a thrust-stand export audit, 2026-11-27)
            notes.append(f"each of the {n} rows is a point: the file has a time column ({cm.column('time')!r}) but no "
                         "ESC signal column, by which a stand's steps test is averaged (name it 'ESC signal (µs)' or "
                         "'Throttle (%)' for that)")
    return v, group, lines, n, averaged


def _axial_rate(v: dict, cm, notes: list) -> None:
    """A descent or climb rate column (headers.DESCENT_RATE_NAMES, CLIMB_RATE_NAMES) read as the
    flow: its magnitude the airspeed, in axial descent (incidence 180 deg) where the rotor descends
    and in axial climb (0 deg) where it climbs, at rest within STATIC_AIRSPEED, with a note (since
    2026-12-01: such a column was refused, to be written as an airspeed and an incidence)."""
    for q, sign in zip(AXIAL_RATES, (1.0, -1.0)):
        if q in v:
            down = sign * v.pop(q)  # positive descending
            # (a rate within a static stand's pitot noise is rest: its sign flipped the incidence from row to row, and
            # a sampled log's 8 steps were read as 83, a review, 2026-12-01)
            down = np.where(np.abs(down) <= STATIC_AIRSPEED, 0.0, down)
            v["airspeed"], v["incidence_deg"] = np.abs(down), np.where(down > 0, 180.0, 0.0)
            n_down, n_up = int(np.count_nonzero(down > 0)), int(np.count_nonzero(down < 0))
            notes.append(f"{cm.column(q)!r} read as the airspeed in axial flow: {n_down} row(s) descending "
                         f"(incidence 180 deg), {n_up} climbing (0 deg), {down.size - n_down - n_up} at rest (within "
                         f"{STATIC_AIRSPEED:g} m/s)")


def _average_steps(v: dict, group, form: str, column: str, where: str, notes: list):
    """(v, group) of a stand's "steps" test: one point per ESC step, its settling rows dropped
    (:func:`propmap.identify.steps.stand_points`), each step a group, with a note; DataError
    where no row has a speed, the signal never steps or no step settles."""
    from .steps import CONDITION_TOL, ESC_TOL, NOISE_K, NOISY_ROWS, condition_tolerances, stand_points

    n = v["rpm"].size
    esc, time = v.pop("esc"), v.pop("time", None)
    if n and np.all(np.isnan(v["rpm"])):
        raise DataError(f"{where}: no rotation speed in any row")
    _one_signal(esc, v, group, form, column, where)
    cond_tol, noisy = condition_tolerances({q: v[q] for q in CONDITION_TOL if q in v}, esc, group, ESC_TOL[form])
    for q, sigma in noisy.items():
        unit = RANGES[q][4]  # (its unit as read: m/s, deg)
        shift = max(CONDITION_TOL[q], cond_tol[q] / NOISY_ROWS ** 0.5)
        notes.append(f"{q} is noisy ({sigma:.2g} {unit} rms from row to row, a pitot's or a sensor's): a new step "
                     f"starts where the mean of {NOISY_ROWS} rows moves by more than {shift:.2g} {unit} ({NOISE_K:g} "
                     f"times its noise over sqrt({NOISY_ROWS})) instead of where one row moves by "
                     f"{CONDITION_TOL[q]:g}, so levels closer than that are one step")
    v, group, dropped, unsteady = stand_points(v, esc, time, labels=group, form=form, cond_tol=cond_tol)
    if not group.size:
        raise DataError(f"{where}: no ESC step reaches a steady rotation speed (within 2% over the second "
                        "half of the step)")
    notes.append((f"each of the {n} rows is an ESC step (an export already averaged" if group.size == n else
                  f"{n} rows averaged into {group.size} ESC steps ({dropped} settling, ramp or unsteady rows "
                  "dropped")
                 + (f"; {len(unsteady)} step(s) never steady, left out: {', '.join(unsteady)}" if unsteady else "")
                 + f"); each step is a group (e.g. --holdout {group[min(2, group.size - 1)]})")
    return v, group


def _check_points(v: dict, keys: list, cm, min_points: int, averaged: bool, what: str, p: str) -> None:
    """Enough distinct operating points (read_loads' min_points), and the warnings of a table
    pasted twice, a static stand's pitot and an incidence that looks like radians."""
    n = v["rpm"].size
    if n < min_points:
        steps = " (one per ESC step: its rows averaged)" if averaged else ""
        raise DataError(f"{what}: {p} has {n} points{steps}; " + (
            "no data rows under the header" if n == 0 else
            f"a fit needs at least {min_points} distinct operating points (propmap validate compares any number)"))
    if "airspeed" in cm.columns and n and np.all(v["airspeed"] > STATIC_AIRSPEED) and np.max(v["airspeed"]) < 1.5:
        warnings.warn(f"{p}: {cm.column('airspeed')!r} reads {np.min(v['airspeed']):.2g}-"
                      f"{np.max(v['airspeed']):.2g} m/s at every point: a static stand's pitot offset or noise? Every "
                      f"point is read as moving (static up to {STATIC_AIRSPEED:g} m/s), which changes what a fit "
                      "frees; zero or drop the column for a static test", stacklevel=3)
    if "incidence_deg" in cm.columns and cm.columns["incidence_deg"][2] is None:  # a unit given is believed
        hint = radians_hint(v["incidence_deg"], v["airspeed"], cm.column("incidence_deg"))
        if hint:
            warnings.warn(f"{p}: {hint}", stacklevel=3)
    ops = np.column_stack([v["rpm"], v["airspeed"], v["incidence_deg"], v.get("collective_deg", np.zeros(n))])
    # (rows were counted, not operating points: 3 points written twice were fitted, and a table pasted twice fitted
    # without a word with every standard error shrunk by sqrt(2): a user-level audit, 2026-11-28)
    distinct = int(np.unique(ops, axis=0).shape[0])
    if min_points > 1 and distinct == 1:
        raise DataError(f"{what}: {p}: all operating points are identical")
    if min_points > 1 and distinct < min_points:
        raise DataError(f"{what}: {p} has {n} points at {distinct} distinct operating points; a fit needs at least "
                        f"{min_points} distinct operating points (propmap validate compares any number)")
    whole = np.nan_to_num(np.column_stack([ops] + [v[k] for k in keys]), nan=np.inf)  # (a missing value alike)
    repeated = n - int(np.unique(whole, axis=0).shape[0])
    if repeated:
        warnings.warn(f"{p}: {repeated} row(s) repeat another row to every digit (operating point and loads): a table "
                      "pasted twice? Each row counts as a measurement, and a repeated one shrinks the fit's standard "
                      "errors as if it were another", stacklevel=3)


def _rotation_speed(v: dict, speeds: list, cm, rpm_source, pole_pairs, lines, what: str, p: str,
                    notes: list) -> tuple[dict, str]:
    """(v with the rotation speed under "rpm", the speed columns removed; the column used): a plain
    rpm column, else the stand's optical, else its electrical (divided by ``pole_pairs``), the
    optical probe's dropouts filled from the electrical speed, one sign (its magnitude), with
    notes; DataError for a choice that cannot hold (read_loads' docstring)."""
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
                        f"speed is from {cm.column(use)!r} " + (
                            "(give rpm_source='electrical', --rpm-source electrical, to use the electrical one)"
                            if "rpm_electrical" in v else
                            "and the file has no electrical speed column ('Motor Electrical Speed (RPM)'): leave "
                            "pole_pairs out, or name the column of a raw electrical speed so"))
    rpm = v[use] / (pole_pairs if (use == "rpm_electrical" and pole_pairs) else 1)
    if use == "rpm_optical" and rpm_source is None and "rpm_electrical" in v:
        rpm = _optical_gaps(rpm, v["rpm_electrical"], cm.column("rpm_optical"), notes)
    if rpm.size and not np.any(np.nan_to_num(rpm) != 0):
        # (the stand's other speed column named too: an export without a probe, both 0, an export audit, 2026-12-02)
        others = [cm.column(q) for q in speeds if q != use and not np.any(np.nan_to_num(v[q]) != 0)]
        raise DataError(f"{what}: {p}: the rotation speed column {cm.column(use)!r} is empty or 0 in every row"
                        + (f" (chosen by rpm_source={rpm_source!r}, --rpm-source)" if rpm_source else "")
                        + (f", and so is {', '.join(map(repr, others))}: no rotation speed was recorded (no optical "
                           "probe, no ESC telemetry?); propmap needs it" if others else ""))
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
    return v, use


#: column names that name the propeller of each row (lower case, blanks for underscores)
PROPELLER_COLUMNS = ("propeller", "prop", "propeller name", "propeller model", "prop name", "propeller id")

#: what may stand in brackets after such a name: 'Propeller (name)' names the propeller, 'Prop (in)' or 'Propeller
#: (rpm)' is a size or a speed, not a name (a review)
PROPELLER_COLUMN_UNITS = (None, "name", "id", "model", "type", "-")


def _succeeds(call, *args) -> bool:
    """Whether ``call(*args)`` returns without a DataError."""
    try:
        call(*args)
    except DataError:
        return False
    return True


def _propeller_column(base: str, unit: str | None) -> bool:
    """Whether a column split into (name, unit) names the propeller of each row."""
    written = None if unit is None else unit.strip().lower()
    return base.replace("_", " ") in PROPELLER_COLUMNS and written in PROPELLER_COLUMN_UNITS


def _one_signal(esc: np.ndarray, v: dict, group, form: str, name: str, where: str) -> None:
    """Refuse a steps log whose ESC signal stays within one step's tolerance while the rotation
    speed runs over a range, at one operating condition (a constant column, or a throttle
    fraction under a pulse width's unit: the log was one "step" that never settled, and the
    error said so, not why: a thrust-stand export audit, 2026-11-27)."""
    from .steps import CONDITION_TOL, ESC_TOL

    span = float(np.nanmax(esc) - np.nanmin(esc)) if esc.size else 0.0
    rpm = v["rpm"][np.isfinite(v["rpm"])]
    moving = any(np.ptp(v[q]) > tol for q, tol in CONDITION_TOL.items() if q in v and v[q].size)
    if group is None and not moving and rpm.size and span <= 2 * ESC_TOL[form] and rpm.max() > 1.1 * rpm.min():
        unit = {"us": " us", "pct": "%", "fraction": ""}[form]
        raise DataError(f"{where}: the ESC signal {name!r} stays within {span:g}{unit} over the whole log (one "
                        f"step's tolerance) while the rotation speed runs {rpm.min():.0f}-{rpm.max():.0f} rpm: it is "
                        "not the signal that set the steps (a constant column, or a unit its name does not say); "
                        "name its unit, or remove the column to fit each row as a point")
