"""The air a load file gives (identify/loads_csv.py reads the file): the median of its density
column (:func:`_air_density`), or, without one, the density of its air temperature and pressure
columns (:func:`_conditions_density`, rho = p / (R T) as :meth:`propmap.Air.from_conditions`
gives it). A density column outside AIR_DENSITY_RANGE is refused; temperature and pressure
columns that cannot be read are said in a note and left unread, never refused.
"""

from __future__ import annotations

import numpy as np

from ..core.air import R_AIR, Air
from .csvfile import DataError

#: the air densities a load file's density column may give [kg/m^3] (sea level 1.225; 5 km 0.74)
AIR_DENSITY_RANGE = (0.05, 5.0)


def _air_density(rho, column, what: str, p: str, notes: list) -> float | None:
    """The median of a density column's running rows [kg/m^3] (None without one, or where it is
    empty or 0 in every row: a sensor absent), with a note."""
    if rho is None:
        return None
    rho = rho[np.isfinite(rho) & (rho != 0)]  # (empty or 0: a sensor absent from the rows)
    if not rho.size:
        notes.append(f"{column!r} is empty or 0 in every row: not read")
        return None
    lo, hi = AIR_DENSITY_RANGE
    if not (lo <= rho.min() and rho.max() <= hi):
        bad = rho.min() if rho.min() < lo else rho.max()
        raise DataError(f"{what}: {p}: {column!r} gives {bad:g} kg/m^3; an air density must be in [{lo:g}, {hi:g}] "
                        "kg/m^3")
    med = float(np.median(rho))
    spread = f" (the rows range {rho.min():.4g}-{rho.max():.4g})" if rho.max() > 1.01 * rho.min() else ""
    notes.append(f"air density {med:.4g} kg/m^3 from {column!r}, the median of its rows{spread}")
    return med


#: the names of a load file's air temperature and pressure columns (before a unit in brackets or after '_'): names
#: of the air's state only (a bare 'temp' may be a motor's, a bare 'pressure' a tunnel's dynamic pressure)
_T_NAMES = ("temperature", "air temperature", "air temp", "ambient temperature", "ambient temp", "tunnel temperature")
_P_NAMES = ("pressure", "air pressure", "ambient pressure", "barometric pressure", "baro", "barometer",
            "static pressure", "atmospheric pressure", "p atm", "tunnel static pressure")
#: names read only with a unit in the header (a bare 'pressure' of 735 may be a tunnel's dynamic pressure in Pa,
#: which read as hPa would give 0.87 kg/m^3)
_UNIT_NEEDED = ("pressure",)
#: their units: name -> (scale, offset) to K, and -> scale to Pa
_C, _F = (1.0, 273.15), (5 / 9, 255.3722222222222)
_T_UNITS = {"c": _C, "°c": _C, "ºc": _C, "degc": _C, "deg c": _C, "celsius": _C, "k": (1.0, 0.0), "kelvin": (1.0, 0.0),
            "f": _F, "°f": _F, "ºf": _F, "degf": _F, "deg f": _F, "fahrenheit": _F}
_P_UNITS = {"pa": 1.0, "hpa": 100.0, "mbar": 100.0, "mb": 100.0, "kpa": 1000.0, "bar": 1e5, "psi": 6894.757293168,
            "psia": 6894.757293168, "inhg": 3386.389, "in hg": 3386.389, "mmhg": 133.322387415, "torr": 133.322368421,
            "atm": 101325.0}
#: a temperature column is not the air's above this median [K] (50 degC) or where its rows' 5th to 95th percentiles lie
#: more than AIR_T_SPAN [K] apart (a motor's or an ESC's, heating through a test; a tunnel's air warms less)
AIR_T_MAX = 323.15
AIR_T_SPAN = 30.0
#: the air densities a temperature and a pressure column are believed to give without a warning [kg/m^3]
#: (sea level at -20 to 45 degC; 3,000 m; beyond them a column is more likely another quantity)
PLAUSIBLE_DENSITY = (0.85, 1.4)


def _split_unit(column: str) -> tuple[str, str | None]:
    """(name, unit) of a header such as 'Temperature (C)', 'pressure [hPa]' or 'temp_c' (lower case)."""
    c = column.strip().lower()
    for o, e in (("(", ")"), ("[", "]")):
        if o in c and c.endswith(e):
            return c[:c.index(o)].strip().replace("_", " "), c[c.index(o) + 1:-1].strip()
    name, _, unit = c.rpartition("_")
    return (name.replace("_", " "), unit) if name and (unit in _T_UNITS or unit in _P_UNITS) else (c.replace("_", " "),
                                                                                                    None)


def _conditions_density(f, what: str, p: str, notes: list) -> float | None:
    """The air density [kg/m^3] of a file's air temperature and pressure columns (their medians;
    rho = p / (R T) as :meth:`propmap.Air.from_conditions` gives it, within its ranges of T and
    p), with a note; None where it has not both, where a unit cannot be told (not in the header
    and not unambiguous from the values: T 200-350 K or -40 to 31 degC; p 5e4-1.1e5 Pa, 500-1100
    hPa, 50-110 kPa), or where the density would lie outside AIR_DENSITY_RANGE: then a note says
    the columns are not read (never a refusal: the air options still serve). A temperature
    column that cannot be read as the air's (not numeric, empty, its unit not told or not known,
    or above AIR_T_MAX or spanning more than AIR_T_SPAN: a motor's) gives way to the next
    temperature column, a note saying so. A density outside PLAUSIBLE_DENSITY is used and said
    to be checked."""
    found: dict = {"T": [], "p": []}
    for c in f.header:
        name, unit = _split_unit(c)
        kind = "T" if name in _T_NAMES else "p" if name in _P_NAMES else None
        if kind:
            found[kind].append((c, unit, name))
    if not (found["T"] and found["p"]):
        if found["T"] or found["p"]:
            c = (found["T"] or found["p"])[0][0]
            notes.append(f"{c!r} is not read without the other of temperature and pressure (or a density column): "
                         "the fit's air is the parameter set's unless --altitude-m, --temperature-c/--pressure-pa or "
                         "--rho say otherwise")
        return None
    p_col = found["p"][0][0]
    values = _air_columns(f, [c for c, _, _ in found["T"]] + [p_col])
    pressure = _state(found["p"][0], values, "p", notes, _skipped(found["T"][0][0], p_col))
    if pressure is None:
        return None
    for k, candidate in enumerate(found["T"]):
        last = k == len(found["T"]) - 1
        tail = _skipped(candidate[0], p_col) if last else "the next temperature column is tried"
        temperature = _state(candidate, values, "T", notes, tail)
        if temperature is not None:
            break
    else:
        return None
    T_col = candidate[0]
    try:  # (the air of --temperature-c/--pressure-pa: its gas constant and its ranges of T and p)
        rho = Air.from_conditions(temperature, pressure).rho
    except ValueError as exc:
        notes.append(f"they give {exc}; " + _skipped(T_col, p_col))
        return None
    lo, hi = AIR_DENSITY_RANGE
    if not lo <= rho <= hi:
        notes.append(f"they would give an air density of {rho:.4g} kg/m^3 (T {temperature:.5g} K, p {pressure:.6g} "
                     "Pa); " + _skipped(T_col, p_col))
        return None
    check = ("" if PLAUSIBLE_DENSITY[0] <= rho <= PLAUSIBLE_DENSITY[1] else
             f"; outside the {PLAUSIBLE_DENSITY[0]:g}-{PLAUSIBLE_DENSITY[1]:g} kg/m^3 of air near the ground: check "
             "that these columns are the air's temperature and static pressure")
    notes.append(f"air density {rho:.4g} kg/m^3 from {T_col!r} and {p_col!r} (medians, T {temperature:.5g} K, p "
                 f"{pressure:.6g} Pa, rho = p / ({R_AIR:g} T)){check}")
    return rho


def _skipped(T_col: str, p_col: str) -> str:
    """The tail of a note saying that a temperature and a pressure column are not read."""
    return (f"{T_col!r} and {p_col!r} are not read (give the air with --temperature-c/--pressure-pa, --rho or a "
            "density column)")


def _air_columns(f, columns: list) -> dict:
    """The values of the air's candidate ``columns`` of the file ``f`` (lower-case name -> array,
    or None for a column that is not numeric): one parse of the file for all, column by column
    only where one is text (which hid the others when read together: a review, 2026-11-30)."""
    names = [c.lower() for c in columns]
    try:
        return f.read(names, optional=set(names))[0]
    except DataError:
        out = {}
        for c in names:
            try:
                out[c] = f.read([c], optional={c})[0][c]
            except DataError:  # (a column of text: not the air's state)
                out[c] = None
        return out


def _state(column: tuple, values: dict, kind: str, notes: list, tail: str) -> float | None:
    """The median of a temperature [K] (``kind`` "T") or pressure [Pa] ("p") column ``column`` =
    (name as written, unit or None, name), its values from ``values`` (:func:`_air_columns`);
    None, with a note ending in ``tail`` (what follows), where it cannot be told (not numeric,
    empty, no unit and values that do not tell it, an unknown unit) or a temperature is not the
    air's (above AIR_T_MAX in the median, or its rows' 5th to 95th percentiles more than
    AIR_T_SPAN apart: a motor's or an ESC's, heating through a test; a motor's rising 35 -> 85
    degC gave 1.06 kg/m^3 and every point 14% off: a thrust-stand export audit, 2026-11-30)."""
    c, unit, name = column
    skip = "; " + tail
    x = values[c.lower()]
    if x is None:
        notes.append(f"{c!r} is not numeric" + skip)
        return None
    x = x[np.isfinite(x)]
    if not x.size:
        notes.append(f"{c!r} is empty in every row" + skip)
        return None
    med = float(np.median(x))
    table = _T_UNITS if kind == "T" else _P_UNITS
    if unit is None and name in _UNIT_NEEDED:
        notes.append(f"{c!r} has no unit in its name (a dynamic pressure?)" + skip)
        return None
    if unit is None:  # (only where the values leave one reading: 32-60 may be degF as well as degC)
        spans = ((("k", 200, 350), ("c", -40, 31)) if kind == "T" else
                 (("pa", 5e4, 1.1e5), ("hpa", 500, 1100), ("kpa", 50, 110)))
        unit = next((u for u, lo, hi in spans if lo <= med <= hi), None)
        if unit is None:
            notes.append(f"{c!r} has no unit in its name and its values ({med:g} in the median) do not tell it" + skip)
            return None
        notes.append(f"{c!r} read in {dict(k='K', c='degC', pa='Pa', hpa='hPa', kpa='kPa')[unit]} (its values; no "
                     "unit in the header)")
    if unit not in table:
        notes.append(f"{c!r}: a unit propmap does not know" + skip)
        return None
    if kind == "p":
        return med * table[unit]
    scale, offset = table[unit]
    span = scale * float(np.percentile(x, 95) - np.percentile(x, 5))
    if med * scale + offset > AIR_T_MAX or span > AIR_T_SPAN:
        notes.append(f"{c!r} is {med * scale + offset - 273.15:.3g} degC in the median and spans {span:.3g} K over "
                     f"the rows (5th to 95th percentile): not the air's (above {AIR_T_MAX - 273.15:g} degC or spanning "
                     f"over {AIR_T_SPAN:g} K; a motor's or an ESC's temperature?)" + skip)
        return None
    return med * scale + offset
