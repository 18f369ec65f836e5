"""Load measurements as instruments write them: column names with units, thrust-stand exports.

:func:`propmap.identify.read_loads` reads any CSV whose columns name a quantity and, where
it is not the SI one, a unit: ``thrust``, ``thrust_kgf``, ``Thrust (gf)``, ``torque_Nmm``,
``Torque (N·m)``, ``airspeed_kmh``; and the exports of the RCbenchmark / Tyto Robotics
thrust stands (Series 1520, 1580, 1585, 1780: ``Time (s)``, ``ESC signal (µs)``,
``Thrust (kgf)`` or ``(gf)``, ``(N)``, ``(lbf)``, ``Torque (N·m)`` (not on the 1520),
``Motor Electrical Speed (RPM)``, ``Motor Optical Speed (RPM)``, ...; UTF-8 with a byte-order
mark), as the stand's software writes them; the rotation speed also as ``Motor Speed (RPM)``,
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
airspeed        m/s (mps), km/h (kmh, kph), mph, kn (kt, kts, knots), ft/s (fps)
angle           deg (degrees, °), rad
air density     kg/m³ (kg/m^3, g/L), g/cm³, lb/ft³
==============  ===================================================================

1 kgf = 9.80665 N (the standard gravity, by definition); 1 lbf = 4.4482216152605 N;
1 ozf = lbf / 16; 1 in = 0.0254 m. A unit follows the name in brackets, after a comma
(``Thrust, N``), after a blank (``Thrust g``, ``Thrust in g``) or after an underscore
(``thrust_kgf``); German names are read too (``Schub``, ``Drehmoment``, ``Drehzahl``), and Spanish,
French and Italian ones where a unit of their quantity follows them (``Empuje (g)``, ``Par (N m)``,
``Velocidad (rpm)``; ``Poussée``, ``Couple``, ``Régime``, ``Vitesse``; ``Spinta``, ``Coppia``, ``Giri``:
a bare ``Vitesse`` may be an airspeed), as is ``n``; ``Static thrust``, ``Thrust avg`` where no
``thrust`` is; a statistic's column beside its quantity (``thrust_std``, ``torque_err``, ``rpm_max``)
is not read.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..core._numbers import integer
from ..core.units import RPM

__all__ = ["ColumnMap", "map_columns", "map_operating_columns", "split_header", "UNITS", "ROTATION_COLUMNS",
           "OPERATING"]

G0 = 9.80665
LBF = 4.4482216152605
INCH = 0.0254
#: an ESC signal's units: a pulse width or a throttle in percent (identify/steps.esc_form)
_ESC_UNITS = {"us": "us", "microseconds": "us", "microsecond": "us", "%": "pct", "pct": "pct", "percent": "pct"}
#: other names of the ESC signal, read where no 'ESC signal' or 'throttle' column is ('PWM (µs)' was left unread and
#: every raw sample of a steps test fitted as a point: a thrust-stand export audit, 2026-11-27)
_ESC_ALIASES = ("pwm", "esc pwm", "pwm signal", "motor pwm", "pulse width", "esc pulse width", "throttle signal")
#: other names of the thrust, read where no 'thrust' column is (beside one, with a note that they are not read)
_THRUST_ALIASES = ("static thrust", "average thrust", "avg thrust", "avg. thrust", "mean thrust", "thrust avg",
                   "thrust average", "thrust mean")
#: the rank of a name that gives way to another of its quantity (0: the quantity's own; PWM gives way to a throttle,
#: both to an ESC signal; Thrust avg to Thrust); two of one rank are refused ('ESC (µs)' beside 'Throttle (%)' was:
#: a thrust-stand export audit, 2026-11-30)
#: other names of a file's run labels, read where no 'group' column is
_GROUP_ALIASES = ("run", "run id", "run_id", "run name", "test id", "test_id", "series")
_RANK = {**dict.fromkeys(_ESC_ALIASES, 2), **dict.fromkeys(_THRUST_ALIASES, 1), "throttle": 1,
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
    "speed": {"ms": 1.0, "mps": 1.0, "kmh": 1 / 3.6, "kph": 1 / 3.6, "mph": 0.44704, "kn": 1852 / 3600,
              "kt": 1852 / 3600, "kts": 1852 / 3600, "knots": 1852 / 3600, "fts": 0.3048, "fps": 0.3048},
    "angle": {"deg": 1.0, "degrees": 1.0, "°": 1.0, "rad": 180.0 / math.pi},
    "density": {"kgm3": 1.0, "kgm³": 1.0, "gl": 1.0, "gcm3": 1e3, "gcm³": 1e3, "lbft3": 16.018463373960138,
                "lbft³": 16.018463373960138},
}
#: the names each quantity is recognised by (lower case, without unit); value: (quantity, kind)
_NAMES = {
    "thrust": ("thrust", "force"), "drag": ("drag", "force"), "torque": ("torque", "torque"),
    # German stands' exports (Schub, Drehmoment, Drehzahl [U/min]: a user-level audit, 2026-11-28)
    "schub": ("thrust", "force"), "schubkraft": ("thrust", "force"), "drehmoment": ("torque", "torque"),
    "drehzahl": ("rpm", "rotation"),
    # a spreadsheet's Static thrust, Avg. thrust (read as nothing, a gram thrust left unsaid: an export audit,
    # 2026-11-30); they give way to a 'thrust' column (_RANK)
    **dict.fromkeys(_THRUST_ALIASES, ("thrust", "force")),
    # the in-plane force along the in-plane airspeed, by the names wind-tunnel tests give it
    "h force": ("drag", "force"), "h_force": ("drag", "force"), "h-force": ("drag", "force"),
    "in-plane force": ("drag", "force"), "inplane force": ("drag", "force"), "in_plane_force": ("drag", "force"),
    "normal force": ("drag", "force"), "normal_force": ("drag", "force"), "rotor drag": ("drag", "force"),
    "rotor_drag": ("drag", "force"),
    "rpm": ("rpm", "rotation"), "speed": ("rpm", "rotation"), "rotation speed": ("rpm", "rotation"),
    "omega": ("rpm", "rotation"), "rps": ("rpm", "rotation"), "rev/s": ("rpm", "rotation"),
    **{f"{who}{sep}speed": ("rpm", "rotation") for who in ("motor", "rotor", "propeller", "prop", "rotational")
       for sep in " _"},
    # (Motor RPM, Prop RPM: the hand-made stands' spreadsheets; 'prop speed' too. A user-level check, 2026-11-29)
    **{f"{who}{sep}rpm": ("rpm", "rotation") for who in ("motor", "rotor", "propeller", "prop") for sep in " _"},
    "motor optical speed": ("rpm_optical", "rotation"), "motor electrical speed": ("rpm_electrical", "rotation"),
    "airspeed": ("airspeed", "speed"), "air speed": ("airspeed", "speed"), "wind speed": ("airspeed", "speed"),
    "incidence": ("incidence_deg", "angle"), "incidence_deg": ("incidence_deg", "angle"),
    # (refused as a flow angle to be renamed, though they name the incidence: a wind-tunnel data audit, 2026-11-30)
    "incidence angle": ("incidence_deg", "angle"), "angle of incidence": ("incidence_deg", "angle"),
    "collective": ("collective_deg", "angle"), "collective_deg": ("collective_deg", "angle"),
    # a pulse width [us] or a throttle [%, or a fraction]: its unit is read by esc_form
    "esc signal": ("esc", None), "esc": ("esc", None), "esc_us": ("esc", None), "throttle": ("esc", None),
    **{name: ("esc", None) for name in _ESC_ALIASES},
    "time": ("time", None), "time_s": ("time", None), "group": ("group", None),
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
#: per name, rotation units beyond UNITS["rotation"]: 1/s of a rotational frequency n is a revolution per second (ISO
#: 80000-3:2019; German stands write Drehzahl in 1/s too), of an angular speed it would be rad/s
_PER_SECOND = {tok: 60.0 for tok in ("1s", "s1", "s⁻¹")}
_NAME_UNITS = {"n": _PER_SECOND, "drehzahl": _PER_SECOND}
#: the names of an ESC signal (a pulse width or a throttle), which take an ESC unit after an underscore (esc_us, pwm_us)
_ESC_NAMES = frozenset(k for k, (q, _) in _NAMES.items() if q == "esc")
#: suffixes of a column that gives a statistic of a quantity, not the quantity (thrust_std): not read
_STATISTICS = frozenset(("std", "sd", "stdev", "stddev", "sigma", "err", "error", "unc", "uncertainty", "var",
                         "variance", "min", "max", "count", "ci", "se", "sem"))
#: names that are not read but mean an airspeed, an advance ratio, a flow angle or load coefficients (a file
#: with them and without 'airspeed' / 'incidence_deg' / loads is refused, naming them: map_columns)
_AIRSPEED_LIKE = ("velocity", "v_inf", "vinf", "u_inf", "uinf", "freestream", "free stream", "freestream velocity",
                  "free stream velocity", "freestream speed", "tunnel speed", "wind velocity", "flow speed",
                  "flow velocity", "true airspeed")
_ADVANCE_LIKE = ("advance ratio", "advance_ratio")
_ANGLE_LIKE = ("alpha", "aoa", "angle of attack", "angle_of_attack", "disk angle", "disc angle", "flow angle",
               "alpha p", "alpha s", "alpha d", "alpha disk", "alpha shaft", "alpha tpp")
#: a climb or descent rate, which propmap reads as the airspeed with incidence 0 or 180 deg: refused unless both the
#: airspeed and the incidence are read (left unread, an axial sweep was fitted as static, or a descent as a climb: a
#: wind-tunnel data audit, 2026-11-27); not a bare 'w' (a power in watts)
_AXIAL_RATE_LIKE = ("vz", "v z", "vc", "v c", "climb rate", "climb speed", "descent rate", "descent speed",
                    "rate of climb", "rate of descent", "sink rate", "vertical speed", "vertical velocity",
                    "axial velocity", "axial speed", "axial flow speed")
#: a blade pitch setting under another name than collective_deg (its points were fitted at collective 0: an input
#: fuzzing audit, 2026-11-27)
_PITCH_LIKE = ("pitch", "pitch angle", "blade pitch", "blade angle", "collective pitch", "pitch setting",
               "blade pitch angle", "blade setting", "blade setting angle", "pitch_angle", "blade_angle", "blade_pitch")
#: names that may mean either (V a voltage or a velocity, J a joule or an advance ratio, mu a viscosity, a stand's
#: tilt): a note; an angle's is refused beside an airspeed (the points move: an unread angle leaves them axial, a
#: wind-tunnel data audit, 2026-11-27), and a J's or mu's where its values are not all 0 and no airspeed is read
#: (loads_csv.read_loads: an axial sweep's J was read as static, the thrust 11-23% off)
_AMBIGUOUS = {"v": "airspeed", "j": "airspeed", "mu": "airspeed", "tas": "airspeed", "angle": "incidence_deg",
              "tilt": "incidence_deg", "tilt angle": "incidence_deg", "disk tilt": "incidence_deg",
              "disc tilt": "incidence_deg", "rotor tilt": "incidence_deg", "shaft tilt": "incidence_deg",
              "inclination": "incidence_deg",
              "yaw": "incidence_deg", "yaw angle": "incidence_deg"}
_COEFFICIENT_NAMES = ("ct", "cp", "cq", "c_t", "c_p", "c_q", "kt", "kq", "k_t", "k_q")
#: speeds in a load file that are not the airspeed (a blade's, the slipstream's: derived or measured behind the
#: propeller); a unit 'kN' is a force (kilonewton), not knots
_NOT_AIRSPEED = re.compile(r"\b(tip|blade|slipstream|induced|exit|wake|jet|outlet|downwash|propwash|rotor)\b")
#: an acceleration's or a vibration's column, whose unit g is no gram (AccX (g), Vibration (g), a_z [g])
_ACCELERATION_LIKE = re.compile(r"^(acc|a[ _]?[xyz]\b)|accel|vibration|\bvib\b|\bimu\b|g[ -]?force|\bgyro")
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
        ``collective_deg``, ``esc``, ``time``, ``group``, ``air_density``; the columns it does not recognise
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
        gets a note instead, except an angle's beside an airspeed), a climb or descent rate
        (``Vz``, ``V_c``, ``descent_rate``) unless both the airspeed and the incidence are read,
        any column it does not read whose unit is a speed's (``Flight
        speed (m/s)``) where no airspeed is, or an angle's (``Shaft angle (deg)``) where an
        airspeed is read and no incidence, a wind tunnel's ``lift`` column (the loads are read in
        the rotor's axes; the message gives the conversion), a rotation speed in a speed's unit (``Speed (m/s)``),
        an unknown ``rpm_source``, or a ``pole_pairs`` outside [1, 50].
    """
    cm = ColumnMap()
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
            cm.notes[:] = [note for note in cm.notes if not note.startswith(f"{alias!r} converted")]
        cm.columns[quantity] = (name, factor, unit)
        if unit is not None and factor != 1.0:
            # (rates are read in rpm, angles in deg; the note named the unit's token, 'from nmm': a docs audit)
            target = {"rotation": "rpm", "angle": "deg", "force": "N", "torque": "N m", "speed": "m/s",
                      "density": "kg/m^3"}.get(kind, "SI")
            cm.notes.append(f"{name!r} converted to {target} (x {factor:.6g})")
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
        _refuse_no_load(bases, found, error)
    _refuse_wind_axes_and_rates(cm, split, bases, stems, error)
    _refuse_unread_flow(cm, split, bases, stems, error)
    if "collective_deg" not in cm.columns:
        _refuse_pitch_like(names, error)
    if "thrust" not in cm.columns:
        _note_unread_force(cm, split)
    if rpm_source is not None and f"rpm_{rpm_source}" not in cm.columns:
        raise error(f"rpm_source {rpm_source!r}: the file has no Motor {rpm_source.title()} Speed column; "
                    f"found {found}")
    return cm


def _refuse_no_speed(names, cm: ColumnMap, found: str, error) -> None:
    """map_columns without a rotation-speed column: refused, saying where it looks like a
    two-rotor export (columns for rotors A and B), where a column is in a rotation unit under a
    name not read (``Velocita (rpm)``), where a bare ``n`` stands, or like lines above the header."""
    pair = [n for n in names if re.search(r"\b(speed|thrust|torque)\b.*\s[AB](\s*\(.*\))?\s*$", n, re.I)]
    # a bare name read as the rotation speed only with a rotation unit ('n': a count is written so too)
    bare_n = [n for n in names if (b := split_header(n))[1] is None and _UNIT_ONLY_NAMES.get(b[0], ("",))[0] == "rpm"]
    # a column in a rotation unit under a name propmap does not read ('Velocidad (rpm)' was told of lines above the
    # header: a thrust-stand export audit, 2026-11-30)
    in_rpm = [n for n in names
              if n.strip() and (u := split_header(n)[1]) is not None and _token(u) in UNITS["rotation"]]
    hint = ""
    if pair:
        hint = ("; this looks like a two-rotor export (a coaxial or dual stand, columns for rotors A and B): propmap "
                "fits one isolated rotor, so write one rotor's columns to a file of their own without the A/B "
                "suffix (in a coaxial pair each rotor also works in the other's flow, which propmap leaves out)")
    elif in_rpm:
        hint = (f"; column {in_rpm[0]!r} is in a rotation speed's unit but its name is not read: name it 'rpm' (or "
                f"'Motor speed ({split_header(in_rpm[0])[1]})')")
    elif bare_n:
        x = bare_n[0].strip()
        hint = (f"; column {bare_n[0]!r} is read as the rotation speed only with a rotation unit: '{x} (rev/s)', "
                f"'{x} (1/min)' or '{x}_rpm'")
    elif not cm.columns:  # no name read at all: 'RCbenchmark Steps Test' above the header
        hint = ("; lines above the header (a title, the test's settings)? remove them, so that the column names "
                "are the file's first line (a load file's header is looked for in its first 41 lines)")
    raise error(f"no rotation-speed column: looked for {LOOKED_FOR['rpm']}; found {found}{hint}")


def _refuse_no_load(bases: dict, found: str, error) -> None:
    """map_columns without a thrust, torque or drag column: refused, naming coefficient columns
    (CT, CP) where they stand instead."""
    coeff = [n for n, b in bases.items() if b in _loose(_COEFFICIENT_NAMES)]
    if coeff:
        raise error(f"no load column, but coefficient column(s) {', '.join(map(repr, coeff))}: a CSV gives the "
                    "loads in SI (thrust = CT rho n^2 D^4, torque = CP rho n^2 D^5 / (2 pi), airspeed = J n D); "
                    "UIUC-format files (RPM CT CP static runs, J CT CP eta sweeps) are read as they are")
    raise error(f"no load column: looked for {LOOKED_FOR['loads']}; found {found}")


def _refuse_wind_axes_and_rates(cm: ColumnMap, split: dict, bases: dict, stems: dict, error) -> None:
    """map_columns' wind-axis lift (refused where the points move, or as a static stand's thrust
    under another name) and a climb or descent rate column (refused unless the airspeed and
    the incidence are read; then a note)."""
    # a tunnel's wind-axis lift and drag are not the rotor's thrust and in-plane force (lift = T sin i + H cos i,
    # drag = H sin i - T cos i at incidence i, the lift positive towards the rotor axis' side)
    lift = [n for n, (b, _) in split.items()
            if re.fullmatch(r"(wind[ _])?lift([ _]force)?([ _](n|mn|kn|kgf|kg|gf|g|lbf|lbs|lb|ozf|oz))?", b)]
    moving = "airspeed" in cm.columns or "incidence_deg" in cm.columns or any(
        stems[n] & _loose(_AIRSPEED_LIKE + _ADVANCE_LIKE + _ANGLE_LIKE) for n in stems)
    if lift and moving:
        raise error(f"column {lift[0]!r}: propmap reads the loads in the rotor's axes (thrust along the axis, 'drag' "
                    "the in-plane force); a wind tunnel's lift L and drag D convert with the incidence i as thrust = "
                    "L sin(i) - D cos(i), in-plane force = L cos(i) + D sin(i) (the lift positive towards the rotor "
                    "axis' side): write those columns instead")
    if lift and "thrust" not in cm.columns:
        raise error(f"column {lift[0]!r}: a static stand's lift is the propeller's thrust: name the column 'thrust' "
                    "(with its unit) to fit it")
    rate = [n for n in bases if stems[n] & _loose(_AXIAL_RATE_LIKE)]
    if rate and "airspeed" in cm.columns and "incidence_deg" in cm.columns:
        cm.notes.append(f"column {rate[0]!r} (a climb or descent rate) is not read: the airspeed and the incidence "
                        "give the flow")
    elif rate:
        raise error(f"column {rate[0]!r} looks like a climb or descent rate, which propmap reads only as 'airspeed' "
                    "(its magnitude, in its unit: 'airspeed (mph)' is read as such) with 'incidence_deg' 0 (climb) "
                    "or 180 (descent): write those columns, or remove it; left unread, its points would be taken as "
                    "static or in the airspeed's direction")


def _refuse_unread_flow(cm: ColumnMap, split: dict, bases: dict, stems: dict, error) -> None:
    """map_columns' airspeed, advance ratio or flow angle under a name propmap does not read
    (refused: every point would be taken as static or axial), or under an ambiguous name (a
    note)."""
    # a wind-tunnel file's airspeed or angle under a name propmap does not read would leave every point static
    for quantity, similar, what, read_as, default in (
            ("airspeed", _AIRSPEED_LIKE + _ADVANCE_LIKE, "an airspeed or advance ratio",
             "'airspeed' [m/s] (an advance ratio as airspeed = J n D)", "static (airspeed 0)"),
            ("incidence_deg", _ANGLE_LIKE, "a flow angle",
             "'incidence_deg', the angle between the airspeed and the rotor axis (0 axial climb, 90 edgewise, 180 "
             "axial descent; a blade pitch setting as 'collective_deg')", "in axial flow (incidence 0)")):
        if quantity in cm.columns:
            continue
        similar = _loose(similar)
        like = [n for n in bases if stems[n] & similar]
        # any column propmap does not read whose unit is a speed's (Flight speed (m/s)), or an angle's where the
        # points move (Shaft angle (deg) beside an airspeed): its name may be anything
        kind = "speed" if quantity == "airspeed" else "angle"
        if quantity == "airspeed" or "airspeed" in cm.columns:
            like += [n for n, (b, u) in split.items() if b not in _NAMES and u is not None and _token(u) in UNITS[kind]
                     and not (kind == "speed" and ("N" in u or _NOT_AIRSPEED.search(b)))]
        if kind == "angle" and "airspeed" in cm.columns:  # an angle's unit after an underscore (tilt_deg, beta_rad)
            like += [n for n, (b, u) in split.items() if u is None and b not in _NAMES and "_" in b
                     and _token(b.rsplit("_", 1)[1]) in UNITS["angle"] and n not in like
                     and not re.search(r"temp", b)]  # (temp_deg, motor_temp_degrees: a temperature)
        if like:
            joule = " (an energy in joules: give its unit, 'energy (J)')" if like[0].strip().lower() == "j" else ""
            raise error(f"column {like[0]!r} looks like {what}, which propmap reads only as {read_as}: rename it, "
                        f"converted, or remove it; left unread, every point would be taken as {default}{joule}")
        maybe = [n for n, b in bases.items() if _AMBIGUOUS.get(b) == quantity]  # (no underscores in its keys)
        if maybe and quantity == "incidence_deg" and "airspeed" in cm.columns:
            raise error(f"column {maybe[0]!r} looks like {what} beside the airspeed, which propmap reads only as "
                        f"{read_as}: rename it, converted, or remove it; left unread, every point would be taken "
                        f"as {default}")
        if maybe:
            ratio = bases[maybe[0]] in ("j", "mu")  # (an advance ratio is no airspeed: it converts, V = J n D)
            cm.notes.append(f"column {maybe[0]!r} is not read; if it is "
                            + ("an advance ratio, give the airspeed instead (V = J n D; mu n D for mu)" if ratio else
                               f"{what}, name it {read_as}") + f" (every point is taken as {default})")


def _note_unread_force(cm: ColumnMap, split: dict) -> None:
    """map_columns without a thrust column: a force column under another name ('Force (N)') is
    named in a note (it was left out unsaid and a torque-only fit ran: a user-level audit)."""
    # any force unit (a gram thrust under 'Weight (g)', 'Thrust avg (g)' was left unsaid: a thrust-stand export
    # audit, 2026-11-30), but not an accelerometer's or a vibration's g (AccX (g), Vibration (g))
    # (a unit after an underscore too, weight_g, load_kgf; not _n there: sample_n is a count)
    forces = [n for n, (b, u) in split.items() if b not in _NAMES and not _ACCELERATION_LIKE.search(b)
              and (_token(u) if u is not None else b.rsplit("_", 1)[-1] if "_" in b else "") in UNITS["force"]
              and (u is not None or not b.endswith("_n"))]
    if forces:
        cm.notes.append(f"column {forces[0]!r} (a force) is not read: name it 'thrust' (or 'drag', the in-plane "
                        "force) with its unit to fit it; without a thrust column "
                        + ("only the " + " and ".join(q for q in ("drag", "torque") if q in cm.columns)
                           + " is fitted" if {"drag", "torque"} & set(cm.columns) else "nothing is fitted"))


#: the operating-point quantities of a points file (``propmap loads --points``)
OPERATING = ("rpm", "airspeed", "incidence_deg", "collective_deg")


def _refuse_pitch_like(names, error) -> None:
    """Refuse a blade pitch setting under another name than collective_deg, in degrees, radians or
    no unit (``Pitch (deg)``, ``pitch``, ``blade_angle_deg``): left unread, every point was taken at
    collective 0 (an input fuzzing audit, 2026-11-27); a pitch in inches is not one."""
    for name in names:
        if not name.strip():
            continue
        b, u = split_header(name)
        if b in _NAMES or not (u is None or _token(u) in UNITS["angle"]):
            continue
        if (_name_stems(name) | {b}) & _loose(_PITCH_LIKE):
            raise error(f"column {name!r} looks like a blade pitch setting, which propmap reads only as "
                        "'collective_deg' (the angle added to the geometry's blade angles at every station, "
                        "[deg]; a tunnel sting's pitch, the flow's angle to the rotor axis, is 'incidence_deg'): "
                        "rename it, converted, or remove it; left unread, every point would be taken at the "
                        "geometry's blade angles (collective 0)")


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
