"""Load measurements as instruments write them: column names with units, thrust-stand exports.

:func:`propmap.identify.read_loads` reads any CSV whose columns name a quantity and, where
it is not the SI one, a unit: ``thrust``, ``thrust_kgf``, ``Thrust (gf)``, ``torque_Nmm``,
``Torque (N·m)``, ``airspeed_kmh``; and the exports of the RCbenchmark / Tyto Robotics
thrust stands (Series 1520, 1580, 1585, 1780: ``Time (s)``, ``ESC signal (µs)``,
``Thrust (kgf)`` or ``(gf)``, ``(N)``, ``(lbf)``, ``Torque (N·m)`` (not on the 1520),
``Motor Electrical Speed (RPM)``, ``Motor Optical Speed (RPM)``, ...; UTF-8 with a byte-order
mark), as the stand's software writes them, and Tyto's Flight Stand exports, every channel after
its powertrain's name (``Powertrain 1 - force Fz (thrust) (N)``, ``Powertrain 1 - torque MZ
(torque) (N⋅m)``, ``Powertrain 1 - rotation speed (rpm)``, ``Powertrain 1 - ESC throttle (μs)``:
the prefix is dropped); the rotation speed also as ``Motor Speed (RPM)``,
``rotor_speed_hz``, ``Rotational speed (rad/s)``, ``propeller speed``, ``Prop Speed``, ``Motor RPM``,
``omega`` (rad/s without a unit), ``n (rev/s)`` or ``n (1/min)`` (the symbol of a rotational frequency, read
only with its unit; its ``1/s`` is a revolution per second). This module maps the columns; :mod:`propmap.identify.steps`
turns a "steps" test into one averaged point per ESC step.

Units (a quantity without a unit is SI, rpm for rotation speed):

==============  ===================================================================
thrust, drag    N (newtons), mN, kN, kgf (kg, kilograms), gf (g, grams), lbf (lb, lbs, pounds), ozf
                (oz, ounces)
torque          N·m (Nm, N.m, N m), N·mm (Nmm), N·cm, mN·m, kgf·m (kg·m), kgf·cm (kg·cm), gf·m (g·m), gf·cm
                (g·cm), lbf·in (lb·in, in·lb), ozf·in (oz·in, oz-in, in·oz), lbf·ft (lb·ft, ft·lb)
rotation speed  rpm (rev/min, r/min, 1/min, min^-1, U/min, tr/min, giri/min, obr/min), krpm, rad/s, Hz (rev/s,
                rps)
airspeed        m/s (mps), km/h (kmh, kph), mph, kn (kt, kts, knots), ft/s (fps), in/s
angle           deg (degrees, °), rad
air density     kg/m³ (kg/m^3, g/L), g/cm³, lb/ft³
==============  ===================================================================

1 kgf = 9.80665 N (the standard gravity, by definition); 1 lbf = 4.4482216152605 N;
1 ozf = lbf / 16; 1 in = 0.0254 m. A unit follows the name in brackets, after a comma
(``Thrust, N``), after ``' - '`` (``Thrust - gf``), after a blank (``Thrust g``, ``Thrust in g``) or after an underscore
(``thrust_kgf``); German names are read too (``Schub``, ``Drehmoment``, ``Drehzahl``), and Spanish,
French and Italian ones where a unit of their quantity follows them (``Empuje (g)``, ``Par (N m)``,
``Velocidad (rpm)``; ``Poussée``, ``Couple``, ``Régime``, ``Vitesse``; ``Spinta``, ``Coppia``, ``Giri``:
a bare ``Vitesse`` may be an airspeed), as is ``n``; ``Static thrust``, ``Thrust avg`` where no
``thrust`` is; a statistic's column beside its quantity (``thrust_std``, ``torque_err``, ``rpm_max``)
is not read.
"""

from __future__ import annotations

import re

from ..core._numbers import integer
# (the vocabulary and the unread columns' checks live in .headers and .unread; the names other modules and users
# import from here are re-exported)
from .headers import (G0, INCH, LBF, LOOKED_FOR, OPERATING, ROTATION_COLUMNS, UNITS, ColumnMap, _entry, _factor,
                      _name_stems, _RANK, _token, split_header)
from .unread import (_note_unread_force, _note_unread_moment, _refuse_no_load, _refuse_no_speed, _refuse_pitch_like,
                     _refuse_unread_flow, _refuse_wind_axes_and_rates)

__all__ = ["ColumnMap", "map_columns", "map_operating_columns", "split_header", "UNITS", "ROTATION_COLUMNS",
           "OPERATING", "LOOKED_FOR", "G0", "LBF", "INCH"]


#: a column name after a powertrain's prefix, as Tyto's Flight Stand software writes its exports ('Powertrain 1 - force
#: Fz (thrust) (N)', 'Powertrain 1 - rotation speed (rpm)'; the powertrain as the user named it)
_PREFIXED = re.compile(r"^\s*(\S.*?)\s+-\s+(\S.*)$")
#: the quantities that make a prefix a powertrain's: a column of it, without the prefix, gives one of them
_POWERTRAIN_READS = frozenset(("thrust", "torque", "drag", *ROTATION_COLUMNS))


def _powertrain_columns(names: list, error) -> tuple[list, dict, str | None]:
    """(names, original, note): a Flight Stand export's column names without their powertrain's
    prefix, each stripped name's name as written, and a note saying so; the names as they are
    where no prefix is a powertrain's (3 columns or more, one a rotation speed or a load).

    Every column was refused before (no rotation-speed column: a thrust-stand export audit,
    2026-12-02). Two powertrains' columns are refused: propmap fits one isolated rotor."""
    groups: dict[str, list] = {}
    for name in names:
        if m := _PREFIXED.match(name):
            groups.setdefault(m.group(1), []).append(name)

    def reads(name: str) -> bool:
        entry = _entry(*split_header(_PREFIXED.match(name).group(2)))
        return entry is not None and entry[0] in _POWERTRAIN_READS

    trains = [p for p, cols in groups.items() if len(cols) >= 3 and any(map(reads, cols))]
    if not trains:
        return names, {}, None
    if len(trains) > 1:
        raise error(f"columns of {len(trains)} powertrains ({', '.join(repr(t) for t in trains[:4])}), as a Flight "
                    "Stand export of several motors writes them: propmap fits one isolated rotor, so write one "
                    "powertrain's columns (and the time's) to a file of their own")
    ours = set(groups[trains[0]])
    stripped = [_PREFIXED.match(n).group(2) if n in ours else n for n in names]
    if len(set(stripped)) < len(stripped):  # (a name without the prefix beside it, 'thrust (N)' and 'Run 1 - thrust
        # (N)': read as written, as before; it was refused as two thrust columns, a review)
        return names, {}, None
    return stripped, dict(zip(stripped, names)), (
        f"the prefix {trains[0] + ' - '!r} is dropped from {len(ours)} column names (a powertrain's, as a Flight Stand "
        "export writes them)")


def map_columns(names, *, rpm_source: str | None = None, pole_pairs: int | None = None,
                error=ValueError) -> ColumnMap:
    """Map a CSV header to the load quantities (module docstring).

    Parameters
    ----------
    names : sequence of str
        The header's column names, as written.
    rpm_source : {"optical", "electrical"}, optional
        Which of a stand's two speed columns to use; default: the optical one where the
        file has both (the electrical speed depends on the pole setting of the stand's
        software).
    pole_pairs : int, optional
        Divide the electrical speed by this (an export of the raw electrical rpm).
    error : type
        The exception raised.

    Returns
    -------
    ColumnMap
        ``columns``: each recognised quantity (``thrust``, ``drag``, ``torque``, ``rpm``,
        ``rpm_optical``, ``rpm_electrical``, ``airspeed``, ``incidence_deg``,
        ``collective_deg``, ``descent_rate``, ``climb_rate``, ``esc``, ``time``, ``group``,
        ``air_density``; the columns it does not recognise
        left out) -> (column name as written, factor to N, N m, rpm, m/s or deg, unit as
        written or None); ``notes``: the units converted. ``pole_pairs`` is only checked
        here: the caller divides the speed (:func:`propmap.identify.read_loads`).

    Raises
    ------
    error
        A recognised quantity in an unknown unit (naming the column and the known units),
        two columns for one quantity of one rank (an alias, ``PWM``, ``Thrust avg``, or a
        ``throttle`` beside an ESC signal, gives way to the quantity's own name, with a note:
        :data:`_RANK`), no rotation-speed column or no load column (listing
        the columns found and what was looked for; naming coefficient columns such as CT, CP
        where they stand instead), a column that looks like an airspeed, advance ratio or flow
        angle (``velocity``, ``V_inf``, ``advance ratio``, ``alpha``, ``AoA``, ...; one in a unit
        that is neither a speed's nor an angle's is not) where no ``airspeed`` or
        ``incidence_deg`` column is recognised (the points would be read as static or axial; a
        name that may mean something else, ``V``, ``J``, ``mu``, ``angle``, ``tilt``, ``yaw``,
        gets a note instead, except an angle's beside an airspeed), a vertical speed whose sign a
        name does not say (``Vz``, ``V_c``) unless both the airspeed and the incidence are read, a
        named descent or climb rate (``descent_rate``, ``rate of climb``: read, as ``descent_rate``
        or ``climb_rate``) beside only one of them,
        any column it does not read whose unit is a speed's (``Flight
        speed (m/s)``) where no airspeed is, or an angle's (``Shaft angle (deg)``) where an
        airspeed is read and no incidence, a wind tunnel's ``lift`` column (the loads are read in
        the rotor's axes; the message gives the conversion), a rotation speed in a speed's unit (``Speed (m/s)``),
        an unknown ``rpm_source``, or a ``pole_pairs`` outside [1, 50], or the columns of two
        powertrains of a Flight Stand export (``Powertrain 1 - ...``, ``Powertrain 2 - ...``; one
        powertrain's prefix is dropped from its names, with a note).
    """
    names, original, note = _powertrain_columns(list(names), error)
    try:
        cm = _map_columns(names, rpm_source, pole_pairs, error)
    except error as exc:  # (the refusal names the columns without the prefix: said so, a review)
        if not original:
            raise
        raise error(f"{exc} ({note.replace('is dropped', 'was dropped')})") from None
    if original:  # (the file's columns are read, and named in the notes, by their names as written)
        cm.columns = {q: (original[c[0]], *c[1:]) for q, c in cm.columns.items()}
        for short, name in original.items():
            cm.notes = [n.replace(repr(short), repr(name)) for n in cm.notes]
        cm.notes.insert(0, note)
    return cm


def _map_columns(names: list, rpm_source, pole_pairs, error) -> ColumnMap:
    """map_columns' mapping of the ``names`` (a powertrain's prefix dropped)."""
    cm = ColumnMap()
    converted: dict[str, str] = {}  # a column's note that its unit is converted, dropped where the column gives way
    for name in names:
        if not name.strip():
            continue
        base, unit = split_header(name)
        entry = _entry(base, unit)
        if entry is None:
            continue
        quantity, kind = entry
        factor = _factor(name, base, unit, error)
        if quantity in cm.columns:
            first = cm.columns[quantity][0]
            rank, rank_first = _RANK.get(base, 0), _RANK.get(split_header(first)[0], 0)
            if rank == rank_first:
                raise error(f"columns {first!r} and {name!r} both give {quantity}: keep one")
            # an alias (PWM, Thrust avg) gives way to the quantity's own name (ESC signal, throttle; Thrust)
            alias, signal = (name, first) if rank > rank_first else (first, name)
            what = {"esc": "the ESC signal is", "group": "the run labels are"}.get(quantity, f"the {quantity} is")
            cm.notes.append(f"column {alias!r} is not read: {what} read from {signal!r}")
            if alias == name:
                continue
            if alias in converted:  # (found by the column, not by the note's text, since 2026-12-01)
                cm.notes.remove(converted.pop(alias))
        cm.columns[quantity] = (name, factor, unit)
        if unit is not None and factor != 1.0:
            # (rates are read in rpm, angles in deg; the note named the unit's token, 'from nmm': a docs audit)
            target = {"rotation": "rpm", "angle": "deg", "force": "N", "torque": "N m", "speed": "m/s",
                      "density": "kg/m^3"}.get(kind, "SI")
            converted[name] = f"{name!r} converted to {target} (x {factor:.6g})"
            cm.notes.append(converted[name])
    if rpm_source not in (None, "optical", "electrical"):
        raise error(f"rpm_source must be 'optical' or 'electrical', got {rpm_source!r}")
    # (True, an int to Python, divided the speed by 1: refused since 2026-11-29, an audit)
    if pole_pairs is not None:
        integer("pole_pairs (--pole-pairs)", pole_pairs, 1, 50, whole_float=False, error=error)
    found = ", ".join(repr(n) for n in names if n.strip())
    if not any(q in cm.columns for q in ROTATION_COLUMNS):
        _refuse_no_speed(names, cm, found, error)
    split = {name: split_header(name) for name in names if name.strip()}
    # a column whose unit is neither a speed's nor an angle's (V (V), a current, a power) is not one of them
    bases = {name: b for name, (b, u) in split.items()
             if u is None or _token(u) in UNITS["speed"] or _token(u) in UNITS["angle"]}
    stems = {name: _name_stems(name) for name in bases}
    if not any(q in cm.columns for q in ("thrust", "torque", "drag")):
        _refuse_no_load(bases, split, found, error)
    _refuse_wind_axes_and_rates(cm, split, bases, stems, error)
    _refuse_unread_flow(cm, split, bases, stems, error)
    if "collective_deg" not in cm.columns:
        _refuse_pitch_like(names, error, cm.notes)
    if "thrust" not in cm.columns or ("drag" not in cm.columns and "airspeed" in cm.columns):
        _note_unread_force(cm, split)
    if "torque" not in cm.columns:
        _note_unread_moment(cm, split)
    if rpm_source is not None and f"rpm_{rpm_source}" not in cm.columns:
        raise error(f"rpm_source {rpm_source!r}: the file has no Motor {rpm_source.title()} Speed column; "
                    f"found {found}")
    return cm


def map_operating_columns(names, *, error=ValueError) -> dict:
    """Map a points file's header to its operating-point quantities, by the names and units
    :func:`map_columns` reads (``RPM``, ``speed_rad_s``, ``omega`` [rad/s], ``airspeed (m/s)``,
    ``airspeed_kmh``, ``incidence (deg)``, ``Incidence (°)``, ``collective_deg``).

    Parameters
    ----------
    names : sequence of str
        The header's column names, as written.
    error : type
        The exception raised.

    Returns
    -------
    dict
        quantity (of :data:`OPERATING`) -> (column name as written, factor to rpm, m/s or deg).
        A quantity's bare name (``rpm``, ``airspeed``, ``incidence_deg``, ``collective_deg``,
        any case) is taken first; another name for a quantity it gives, and every other
        column, stays an extra column of the file.

    Raises
    ------
    error
        An operating quantity, not given by its bare name, in a unit it does not know (a rotation
        speed in a linear speed's unit said as such), two such columns for one quantity, or a
        blade pitch setting under another name than ``collective_deg`` (``Pitch (deg)``).
    """
    out = {name.strip().lower(): (name, 1.0) for name in names if name.strip().lower() in OPERATING}
    bare = set(out)
    for name in names:
        if not name.strip() or name.strip().lower() in OPERATING:
            continue
        base, unit = split_header(name)
        quantity = (_entry(base, unit) or (None, None))[0]
        if quantity not in OPERATING or quantity in bare:
            continue
        factor = _factor(name, base, unit, error)
        if quantity in out:
            raise error(f"columns {out[quantity][0]!r} and {name!r} both give {quantity}: keep one")
        out[quantity] = (name, factor)
    if "collective_deg" not in out:
        _refuse_pitch_like(names, error)
    return out
