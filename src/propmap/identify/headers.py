"""The vocabulary of load files' column names: the quantities propmap reads, by the names and
units instruments write them (:mod:`propmap.identify.stand` gives the table), and the parsing of
one header into a quantity and a unit (:func:`split_header`). :mod:`propmap.identify.unread`
checks the columns it does not read; :func:`propmap.identify.stand.map_columns` maps a header."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..core.air import G0
from ..core.units import RPM

__all__ = ["ColumnMap", "split_header", "UNITS", "ROTATION_COLUMNS", "OPERATING", "LOOKED_FOR", "G0", "LBF",
           "INCH"]

#: how an advance ratio converts to the airspeed propmap reads (nomenclature.md's J and mu; the mu of a message was
#: mu n D, 3.1 times too small edgewise: a conventions audit, 2026-12-01)
RATIO_TO_AIRSPEED = "V = J n D; for mu = V sin(incidence) / (Omega R), V = pi mu n D / sin(incidence)"


LBF = 4.4482216152605
INCH = 0.0254
#: an ESC signal's units: a pulse width or a throttle in percent (identify/steps.esc_form)
_ESC_UNITS = {"us": "us", "microseconds": "us", "microsecond": "us", "%": "pct", "pct": "pct", "percent": "pct"}
#: other names of the ESC signal, read where no 'ESC signal' or 'throttle' column is ('PWM (µs)' was left unread and
#: every raw sample of a steps test fitted as a point: a thrust-stand export audit, 2026-11-27)
_ESC_ALIASES = ("pwm", "esc pwm", "pwm signal", "motor pwm", "pulse width", "esc pulse width", "throttle signal",
                # (Tyto's database exports: 'PWM throttle signal (µs)' was left unread, an export audit, 2026-12-02)
                "pwm throttle signal", "pwm throttle",
                # (Tyto's Flight Stand exports, after the powertrain's prefix: stand.map_columns)
                "esc throttle")
#: other names of the thrust, read where no 'thrust' column is (beside one, with a note that they are not read)
_THRUST_ALIASES = ("static thrust", "average thrust", "avg thrust", "avg. thrust", "mean thrust", "thrust avg",
                   "thrust average", "thrust mean")
#: the torque's likewise (Mean torque (N*mm), Torque avg were dropped without a word beside a thrust: a review,
#: 2026-11-30)
_TORQUE_ALIASES = ("average torque", "avg torque", "avg. torque", "mean torque", "torque avg", "torque average",
                   "torque mean")
#: the rank of a name that gives way to another of its quantity (0: the quantity's own; PWM gives way to a throttle,
#: both to an ESC signal; Thrust avg to Thrust); two of one rank are refused ('ESC (µs)' beside 'Throttle (%)' was:
#: a thrust-stand export audit, 2026-11-30)
#: other names of a file's run labels, read where no 'group' column is
_GROUP_ALIASES = ("run", "run id", "run_id", "run name", "test id", "test_id", "series")
_RANK = {**dict.fromkeys(_ESC_ALIASES, 2), **dict.fromkeys(_THRUST_ALIASES, 1), **dict.fromkeys(_TORQUE_ALIASES, 1),
         "throttle": 1,
         **dict.fromkeys(_GROUP_ALIASES, 1)}
#: quantity -> {unit token (lower case, separators removed) -> factor to SI}
UNITS = {
    "force": {"n": 1.0, "mn": 1e-3, "kn": 1e3, "kgf": G0, "kg": G0, "gf": G0 * 1e-3, "g": G0 * 1e-3, "lbf": LBF,
              "lb": LBF, "lbs": LBF, "ozf": LBF / 16, "oz": LBF / 16,
              # the units' names written out (Thrust (grams), thrust_newtons: a user-level audit, 2026-11-28)
              "newton": 1.0, "newtons": 1.0,
              **{name: f for unit, f in (("gram", G0 * 1e-3), ("kilogram", G0), ("pound", LBF), ("ounce", LBF / 16))
                 for name in (unit, unit + "s", unit + "force", unit + "sforce")}},
    "torque": {"nm": 1.0, "nmm": 1e-3, "ncm": 1e-2, "mnm": 1e-3, "kgfcm": G0 * 1e-2, "gfcm": G0 * 1e-5,
               "kgcm": G0 * 1e-2, "gcm": G0 * 1e-5, "lbfin": LBF * INCH, "lbin": LBF * INCH,
               "ozfin": LBF / 16 * INCH, "ozin": LBF / 16 * INCH, "lbfft": LBF * 0.3048, "lbft": LBF * 0.3048,
               "inlbf": LBF * INCH, "inlb": LBF * INCH, "inozf": LBF / 16 * INCH, "inoz": LBF / 16 * INCH,
               "ftlbf": LBF * 0.3048, "ftlb": LBF * 0.3048,
               # (kgf·m and gf·m: a motor maker's tables; refused as unknown, an export audit, 2026-11-30)
               "kgfm": G0, "kgm": G0, "gfm": G0 * 1e-3, "gm": G0 * 1e-3,
               **dict.fromkeys(("newtonmeter", "newtonmeters", "newtonmetre", "newtonmetres"), 1.0)},
    # (1/min, min^-1 and U/min: the European spellings of rpm; krpm, thousands)
    # (tr/min, giri/min, obr/min: the French, Italian and Slavic spellings; a thrust-stand export audit, 2026-11-30)
    "rotation": {"rpm": 1.0, "revmin": 1.0, "rmin": 1.0, "1min": 1.0, "min1": 1.0, "min⁻¹": 1.0, "umin": 1.0,
                 "trmin": 1.0, "girimin": 1.0, "obrmin": 1.0,
                 "krpm": 1e3, "rads": 1 / RPM, "hz": 60.0, "revs": 60.0, "rps": 60.0},
    # (m s-1, m.s-1, km h^-1: SI's negative powers, left unread with every point static: a review, 2026-11-30)
    "speed": {"ms": 1.0, "mps": 1.0, "ms1": 1.0, "kmh": 1 / 3.6, "kmh1": 1 / 3.6, "kph": 1 / 3.6, "mph": 0.44704,
              "kn": 1852 / 3600,
              "kt": 1852 / 3600, "kts": 1852 / 3600, "knots": 1852 / 3600, "fts": 0.3048, "fps": 0.3048,
              # (a vertical speed's unit: Sink rate (ft/min) was refused as an unknown unit, a review, 2026-12-01)
              "ftmin": 0.00508, "fpm": 0.00508,
              # (a hobby tunnel logger's 'Wind Speed (in/s)' was refused as an unknown unit: export audit, 2026-12-02)
              "ins": INCH, "ips": INCH},
    "angle": {"deg": 1.0, "degrees": 1.0, "°": 1.0, "rad": 180.0 / math.pi},
    "density": {"kgm3": 1.0, "kgm³": 1.0, "gl": 1.0, "gcm3": 1e3, "gcm³": 1e3, "lbft3": 16.018463373960138,
                "lbft³": 16.018463373960138},
}
#: an axial descent rate's names (positive descending) and a climb rate's (positive climbing)
DESCENT_RATE_NAMES = ("descent rate", "descent speed", "rate of descent", "sink rate", "descent velocity",
                      "descending velocity", "v descent")
CLIMB_RATE_NAMES = ("climb rate", "climb speed", "rate of climb", "climb velocity", "climbing velocity", "v climb")
#: the quantities of those (loads_csv._axial_rate reads either as the airspeed and the incidence)
AXIAL_RATES = ("descent_rate", "climb_rate")
#: the names each quantity is recognised by (lower case, without unit); value: (quantity, kind)
_NAMES = {
    "thrust": ("thrust", "force"), "drag": ("drag", "force"), "torque": ("torque", "torque"),
    # Tyto's Flight Stand exports, after the powertrain's prefix ('Powertrain 1 - force Fz (thrust) (N)': stand.py)
    "force fz (thrust)": ("thrust", "force"), "torque mz (torque)": ("torque", "torque"),
    # German stands' exports (Schub, Drehmoment, Drehzahl [U/min]: a user-level audit, 2026-11-28)
    "schub": ("thrust", "force"), "schubkraft": ("thrust", "force"), "drehmoment": ("torque", "torque"),
    "drehzahl": ("rpm", "rotation"),
    # a spreadsheet's Static thrust, Avg. thrust (read as nothing, a gram thrust left unsaid: an export audit,
    # 2026-11-30); they give way to a 'thrust' column (_RANK)
    **dict.fromkeys(_THRUST_ALIASES, ("thrust", "force")), **dict.fromkeys(_TORQUE_ALIASES, ("torque", "torque")),
    # the in-plane force along the in-plane airspeed, by the names wind-tunnel tests give it
    "h force": ("drag", "force"), "h_force": ("drag", "force"), "h-force": ("drag", "force"),
    "in-plane force": ("drag", "force"), "inplane force": ("drag", "force"), "in_plane_force": ("drag", "force"),
    "normal force": ("drag", "force"), "normal_force": ("drag", "force"), "rotor drag": ("drag", "force"),
    # (Hforce (N), in plane force, drag force (N) were left unread beside a thrust, the in-plane force never fitted: a
    # wind-tunnel data audit, 2026-11-30)
    "hforce": ("drag", "force"), "in plane force": ("drag", "force"), "drag force": ("drag", "force"),
    "rotor_drag": ("drag", "force"),
    # the hub's rolling moment about the in-plane airspeed, in propmap's sign (positive where the advancing side
    # carries more thrust, docs/conventions.md; noted as not read until 2026-12-01)
    **dict.fromkeys(("rolling moment", "rolling_moment", "roll moment", "roll_moment", "hub rolling moment",
                     "hub_rolling_moment"), ("rolling_moment", "torque")),
    "rpm": ("rpm", "rotation"), "speed": ("rpm", "rotation"), "rotation speed": ("rpm", "rotation"),
    "omega": ("rpm", "rotation"), "rps": ("rpm", "rotation"), "rev/s": ("rpm", "rotation"),
    **{f"{who}{sep}speed": ("rpm", "rotation") for who in ("motor", "rotor", "propeller", "prop", "rotational")
       for sep in " _"},
    # (Motor RPM, Prop RPM: the hand-made stands' spreadsheets; 'prop speed' too. A user-level check, 2026-11-29)
    **{f"{who}{sep}rpm": ("rpm", "rotation") for who in ("motor", "rotor", "propeller", "prop") for sep in " _"},
    "motor optical speed": ("rpm_optical", "rotation"), "motor electrical speed": ("rpm_electrical", "rotation"),
    "airspeed": ("airspeed", "speed"), "air speed": ("airspeed", "speed"), "wind speed": ("airspeed", "speed"),
    # an axial descent's or climb's rate, read as the airspeed with incidence 180 or 0 deg by its sign (refused until
    # 2026-12-01, to be written as those two columns: rotors in descent are measured so); not Vz, V_c or a vertical
    # speed, whose sign convention a name does not say
    **dict.fromkeys((*DESCENT_RATE_NAMES, *(n.replace(" ", "_") for n in DESCENT_RATE_NAMES)),
                    ("descent_rate", "speed")),
    **dict.fromkeys((*CLIMB_RATE_NAMES, *(n.replace(" ", "_") for n in CLIMB_RATE_NAMES)), ("climb_rate", "speed")),
    "incidence": ("incidence_deg", "angle"), "incidence_deg": ("incidence_deg", "angle"),
    # (refused as a flow angle to be renamed, though they name the incidence: a wind-tunnel data audit, 2026-11-30)
    "incidence angle": ("incidence_deg", "angle"), "angle of incidence": ("incidence_deg", "angle"),
    "collective": ("collective_deg", "angle"), "collective_deg": ("collective_deg", "angle"),
    # a pulse width [us] or a throttle [%, or a fraction]: its unit is read by esc_form
    "esc signal": ("esc", None), "esc": ("esc", None), "esc_us": ("esc", None), "throttle": ("esc", None),
    **{name: ("esc", None) for name in _ESC_ALIASES},
    "time": ("time", None), "time_s": ("time", None), "group": ("group", None),
    # (a logger's 'Time_ms' was not read and its 800 raw samples fitted as points without a word: a thrust-stand
    # export audit, 2026-12-02; the time's unit is not needed, only its gaps)
    # (not a bare 'Timestamp', which loggers write as a clock time, 10:12:00.250: such a file would be refused)
    **dict.fromkeys(("time_ms", "time_us", "time_sec", "timestamp_ms", "timestamp_s"), ("time", None)),
    # a tunnel's run labels under another name (a 'Run' column was read as nothing, and --holdout found one group
    # 'all': a wind-tunnel data audit, 2026-11-30)
    **dict.fromkeys(_GROUP_ALIASES, ("group", None)),
    # the air density a stand or tunnel logs (its median is the fit's air where no air option is given)
    "air density": ("air_density", "density"), "air_density": ("air_density", "density"),
    "density": ("air_density", "density"), "rho": ("air_density", "density"),
}
#: names read only where a unit of their quantity follows them ('n (rev/s)', 'Empuje (g)', 'Velocidad (rpm)'); a bare
#: one, or one in another quantity's unit, is not read, as a name propmap does not know: n is as often a count, par a
#: pair, vitesse and velocidad an airspeed, and an underscore after one ('vitesse_vent', 'couple_moteur') no unit (a
#: review of the export audit's names, 2026-11-30)
_UNIT_ONLY_NAMES = {
    # the symbol of a rotational frequency (ISO 80000-3:2019: n, revolutions per time)
    "n": ("rpm", "rotation"),
    # Spanish, French and Italian stands' and spreadsheets' names (an export audit, 2026-11-30)
    **dict.fromkeys(("empuje", "poussée", "poussee", "spinta"), ("thrust", "force")),
    **dict.fromkeys(("couple", "coppia", "par", "par motor"), ("torque", "torque")),
    **dict.fromkeys(("régime", "regime", "giri", "velocidad", "vitesse", "vitesse de rotation", "velocidad de rotación",
                     "velocidad de rotacion", "velocidad de giro", "velocità di rotazione"), ("rpm", "rotation")),
}
#: every name whose unit split_header reads
_PARSED = {**_NAMES, **_UNIT_ONLY_NAMES}
#: the names of the quantities a load file's reader takes (a units row's conflict with one is refused)
READ_NAMES = frozenset(_PARSED)
#: per name, rotation units beyond UNITS["rotation"]: 1/s of a rotational frequency n is a revolution per second (ISO
#: 80000-3:2019; German stands write Drehzahl in 1/s too), of an angular speed it would be rad/s
_PER_SECOND = {tok: 60.0 for tok in ("1s", "s1", "s⁻¹")}
_NAME_UNITS = {"n": _PER_SECOND, "drehzahl": _PER_SECOND}
#: the names of an ESC signal (a pulse width or a throttle), which take an ESC unit after an underscore (esc_us, pwm_us)
_ESC_NAMES = frozenset(k for k, (q, _) in _NAMES.items() if q == "esc")
#: suffixes of a column that gives a statistic of a quantity, not the quantity (thrust_std): not read
_STATISTICS = frozenset(("std", "sd", "stdev", "stddev", "sigma", "err", "error", "unc", "uncertainty", "var",
                         "variance", "min", "max", "count", "ci", "se", "sem"))

#: the rotation-speed columns, in the order of preference when several are present
ROTATION_COLUMNS = ("rpm", "rpm_optical", "rpm_electrical")
#: what each quantity is looked for as, for messages
LOOKED_FOR = {
    "rpm": "rpm (or speed_rad_s, Motor Speed (RPM), Motor Optical Speed (RPM), Motor Electrical Speed (RPM))",
    "loads": "thrust, torque or drag (or H force, in-plane force, normal force, rotor drag), with or without a unit "
             "(thrust_kgf, Thrust (gf), torque_Nmm, Torque (N·m))",
}


def _factor(name: str, base: str, unit: str | None, error) -> float:
    """The factor to SI (rpm for a rotation speed, deg for an angle) of column ``name``, whose
    recognised quantity name is ``base`` (in _PARSED) and unit ``unit`` (None: the quantity's SI,
    except ``omega``, the field's symbol of a rotation rate in rad/s, and ``rps`` or ``rev/s``,
    revolutions per second)."""
    quantity, kind = _PARSED[base]
    if kind is None:
        return 1.0
    if unit is None and kind == "angle" and base != quantity:  # 'incidence': degrees or radians? (1.0 is either)
        raise error(f"column {name!r} gives no unit: name it {quantity!r} (degrees) or give its unit, e.g. "
                    f"'{base} (deg)' or '{base} (rad)'")
    if unit is None:  # (a bare 'RPS' or 'rev/s' names its unit: it was not found as a speed, an audit, 2026-11-27)
        return UNITS["rotation"]["rads"] if base == "omega" else (60.0 if base in ("rps", "rev/s") else 1.0)
    tok = _token(unit)
    if tok in _NAME_UNITS.get(base, {}):
        return _NAME_UNITS[base][tok]
    if kind == "rotation" and tok in UNITS["speed"]:
        raise error(f"column {name!r} is in {unit}, a linear speed, not a rotation speed (rpm, rad/s or Hz): name an "
                    "airspeed 'airspeed' (with its unit, e.g. 'airspeed (m/s)')")
    if tok not in UNITS[kind]:
        raise error(f"column {name!r}: unknown unit {unit!r} for {quantity} (known: {', '.join(UNITS[kind])})")
    return UNITS[kind][tok]


def _unit_missing(base: str, unit: str | None) -> bool:
    """Whether ``base`` is a name read only with a unit of its quantity (:data:`_UNIT_ONLY_NAMES`:
    ``n`` with a rotation unit, ``par`` with a torque's) and ``unit`` is none (a bare ``n``, a
    count), for ``n`` any other unit (``N (N)``, a normal force), for the others a speed's, an
    angle's or a density's (``Vitesse (m/s)``, an airspeed): such a column is not read. Another
    unit (``Empuje (gr)``) is the name's, refused as unknown by :func:`_factor` (it was dropped
    without a word: a review, 2026-11-30)."""
    if base not in _UNIT_ONLY_NAMES:
        return False
    if unit is None:
        return True
    tok = _token(unit)
    if tok in UNITS[_UNIT_ONLY_NAMES[base][1]] or tok in _NAME_UNITS.get(base, {}):
        return False
    return base == "n" or any(tok in UNITS[kind] for kind in ("speed", "angle", "density"))


def _entry(base: str, unit: str | None):
    """(quantity, kind) of a column that split_header gave ``base`` and ``unit``; None: not read."""
    if base in _NAMES:
        return _NAMES[base]
    return None if base not in _UNIT_ONLY_NAMES or _unit_missing(base, unit) else _UNIT_ONLY_NAMES[base]


def _token(unit: str) -> str:
    """A unit written any usual way, as a lookup token: 'N·m' -> 'nm', 'rad/s' -> 'rads', 'µs' -> 'us';
    also UTF-8 read as Windows-1252 and saved so ('NÂ·m', 'Â°', 'Âµs': an 'Â' before each of those
    characters)."""
    return re.sub(r"[\s·⋅*./_\-^]", "", unit.lower().replace("â", "").replace("µ", "u").replace("μ", "u"))


#: other channels' units spelt out or with a degree sign, as their tokens in _OTHER_UNITS ('sec' under 'Time (s)' and
#: '°C' under 'Temp (C)' were refused as other units: a review, 2026-12-01)
_SPELT = {"sec": "s", "secs": "s", "second": "s", "seconds": "s", "°c": "c", "degc": "c", "amp": "a", "amps": "a",
          "ampere": "a", "amperes": "a", "volt": "v", "volts": "v", "watt": "w", "watts": "w"}
#: units of a stand's other channels, which a row of units under the header gives beside UNITS' ones (tokens; those
#: _SPELT spells out too)
_OTHER_UNITS = frozenset(("s", "ms", "us", "min", "h", "v", "mv", "a", "ma", "w", "kw", "%", "pct", "c", "k", "pa",
                          "hpa", "kpa", "bar", "mbar", "hz", "khz", "j", "wh", "mah", "ohm", "gw", "", "1", *_SPELT))


def _same_unit(a: str, b: str) -> bool:
    """Whether two units as written are one (``rpm`` and ``rev/min``, ``g`` and ``gf``: the same
    factor in one of UNITS' quantities; ``s`` and ``sec``, ``C`` and ``°C``), or are spelt alike."""
    ta, tb = (_SPELT.get(t, t) for t in (_token(a), _token(b)))
    return ta == tb or any(ta in kind and tb in kind and math.isclose(kind[ta], kind[tb], rel_tol=1e-12)
                           for kind in UNITS.values())


def units_row(header: list[str], cells: list[str]) -> tuple[list[str], list[tuple[int, str, str]]] | None:
    """A row of units under a header merged into it ('rpm' over 'rev/min' -> 'rpm (rev/min)'), or None.

    The row is one of units where no cell is a number, at least two cells are given, each under a
    named column and none longer than 16 characters, and more than half of them are units propmap
    knows (UNITS', or a stand's other channels': s, V, A, W, %, °C, Pa, ...). A cell in
    brackets, ``[N]``, is read without them; ``-`` and ``1`` (no unit) count as units and add
    none. A column whose name carries a unit keeps it where the row's is the same unit, spelt
    either way (``rpm`` over ``rev/min``; a data logger's export, which writes both:
    a thrust-stand data audit, 2026-11-30, found such a row
    refused as "not a number").

    Parameters
    ----------
    header : list of str
        The header's cells, as written.
    cells : list of str
        The row under it.

    Returns
    -------
    (list of str, list of (int, str, str)) or None
        The header with the row's units in brackets, and the columns (index, name, the row's
        unit) whose name gives another unit than the row (the caller refuses those); None where
        the row is no units row.
    """
    given = [(j, c.strip()) for j, c in enumerate(cells) if c.strip()]
    if len(given) < 2 or any(len(c) > 16 or j >= len(header) or not header[j].strip() for j, c in given):
        return None
    for _, c in given:
        try:
            if c != "1":  # (a 1 is a dimensionless column's unit here: the others decide)
                float(c.replace(",", "."))
                return None
        except ValueError:
            pass
    bare = [(j, re.sub(r"^[(\[](.*)[)\]]$", r"\1", c).strip()) for j, c in given]
    known = {t for kind in UNITS.values() for t in kind} | _OTHER_UNITS
    if 2 * sum(_token(u) in known for _, u in bare) <= len(bare) or all(_token(u) in ("", "1") for _, u in bare):
        return None  # (a row of '-' alone is missing data, not units)
    out, conflicts = list(header), []
    for j, unit in bare:
        if _token(unit) in ("", "1"):
            continue
        own = split_header(out[j])[1]
        if own is None:
            out[j] = f"{out[j].strip()} ({unit})"
        elif not _same_unit(own, unit):
            conflicts.append((j, out[j], unit))
    return out, conflicts


def split_header(name: str) -> tuple[str, str | None]:
    """The quantity and the unit of a column name: ``Thrust (kgf)``, ``thrust [N]``,
    ``Thrust, N``, ``thrust_kgf``; a trailing ``_<unit>`` counts only when the unit is a known one.

    Parameters
    ----------
    name : str
        A CSV header's column name, as written.

    Returns
    -------
    (str, str or None)
        The quantity's text in lower case (blanks trimmed) and the unit as written, or None
        where the name carries none.
    """
    name = name.strip()
    m = re.fullmatch(r"(.*?)\s*[(\[]([^()\[\]]*)[)\]]\s*", name)
    if m:
        return m.group(1).strip().lower(), m.group(2).strip()
    low = name.lower()
    if low in _PARSED:
        return low, None
    if "," in low and low.rsplit(",", 1)[0].strip() in _PARSED:  # 'Thrust, N', 'Torque, N*m' (a unit after a comma)
        return low.rsplit(",", 1)[0].strip(), name.rsplit(",", 1)[1].strip()
    if " - " in low:  # 'Thrust - gf', 'Torque - N*m' (a stand's log: refused as 'lines above the header?', an export
        # audit, 2026-12-02); only a unit after it, of the name's quantity where propmap reads the name ('Thrust -
        # filtered', 'Airspeed - pitot' are other columns, read as nothing: a review), of any quantity where it does
        # not ('Wind - m/s' is checked as an unread airspeed, as 'Wind (m/s)' is: a mutation audit)
        base, unit = low.rsplit(" - ", 1)[0].strip(), name.rsplit(" - ", 1)[1].strip()
        tok = _token(unit)
        if base not in _PARSED:
            if any(tok in u for u in UNITS.values()):
                return base, unit
        elif _PARSED[base][1] is not None and tok in UNITS[_PARSED[base][1]] or (
                _PARSED[base][0] == "esc" and tok in _ESC_UNITS):
            return base, unit
    if " " in low:  # 'Thrust g', 'Thrust in g' (a known unit after a blank: read as a column of nothing, a user audit)
        base, unit = low.rsplit(" ", 1)
        base = re.sub(r"\s+in$", "", base.strip())
        if base in _PARSED and _PARSED[base][1] is not None and _token(unit) in UNITS[_PARSED[base][1]]:
            return base, name.strip().rsplit(" ", 1)[1]
    if low.replace("_", " ") in _NAMES:  # wind_speed, air_speed
        return low.replace("_", " "), None
    if "_" in low and low.rsplit("_", 1)[0].replace("_", " ") in _ESC_NAMES and _token(
            low.rsplit("_", 1)[1]) in _ESC_UNITS:
        return low.rsplit("_", 1)[0].replace("_", " "), low.rsplit("_", 1)[1]  # throttle_pct, esc_us, esc_signal_us
    if "_" in low:
        base, unit = low.rsplit("_", 1)
        if base not in _PARSED and base.replace("_", " ") in _PARSED:  # wind_speed_mps
            base = base.replace("_", " ")
        if base in _PARSED:
            kind = _PARSED[base][1]
            if kind is not None and _token(unit) in UNITS[kind]:
                return base, unit
        # e.g. speed_rad_s, wind_speed_m_s: the unit itself holds an underscore (a known name's blanks as underscores)
        for k in sorted(_PARSED, key=len, reverse=True):
            stem = k.replace(" ", "_") + "_"
            if low.startswith(stem) and _PARSED[k][1] is not None and _token(low[len(stem):]) in UNITS[_PARSED[k][1]]:
                return k, low[len(stem):]
        # a statistic of a quantity beside it (thrust_std, torque_err): not read (it was refused as an unknown unit)
        if base in _NAMES and unit in _STATISTICS:
            return low, None
        # a known quantity with a unit suffix propmap does not know (torque_Ncm): returned
        # as such, so that the unit is refused rather than the column silently ignored
        if base in _NAMES and _NAMES[base][1] is not None:
            return base, name.strip().rsplit("_", 1)[1]
    return low, None


def _name_stems(name: str) -> frozenset:
    """The quantity texts of a column propmap does not read, for comparing it with the names of
    airspeeds and flow angles: :func:`split_header`'s, and that less a trailing speed or angle unit
    after an underscore (``freestream_mps``, ``tunnel_speed_m_s``, ``V_inf_ms``, ``alpha_deg``),
    underscores as blanks (``disk_angle_deg`` -> ``disk angle``). Only a stem that is such a name
    counts (``timestamp_ms`` is no airspeed: ms there is a millisecond)."""
    base, unit = split_header(name)
    if unit is not None or base in _NAMES:
        return frozenset((base,))
    parts = base.split("_")
    out = {base.replace("_", " ")}
    for k in (1, 2):  # m_s, km_h
        if len(parts) > k and any(_token("_".join(parts[-k:])) in UNITS[kind] for kind in ("speed", "angle")):
            out.add(" ".join(parts[:-k]))
    return frozenset(out)


def _loose(names) -> frozenset:
    """Names compared with underscores as spaces."""
    return frozenset(n.replace("_", " ") for n in names)


@dataclass
class ColumnMap:
    """Which file column gives each quantity, and its factor to SI (rpm for rotation).

    Attributes
    ----------
    columns : dict
        quantity -> (column name as written, factor, unit as written or None).
    notes : list of str
        What the mapping decided (units converted, the rotation-speed column chosen).
    """

    columns: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)

    def column(self, quantity: str):
        return self.columns[quantity][0] if quantity in self.columns else None


#: the operating-point quantities of a points file (``propmap loads --points``)
OPERATING = ("rpm", "airspeed", "incidence_deg", "collective_deg")
