"""The side tables of a section-parameter file (io/params_file.py): ``[body]`` (the airframe
drag, the centre of mass and the rotor interference of a flight fit) and ``[coverage]`` (what the
data behind a fitted set covered), read from the file's dict form; and the number checks that
every key of the file shares.
"""

from __future__ import annotations

import math
import numbers
from typing import NamedTuple

from .toml_file import did_you_mean

__all__ = ["BODY_TABLE", "COVERAGE_KEYS", "COVERAGE_SINGLE_TEXTS", "COVERAGE_TEXT_KEYS", "COVERAGE_TABLE", "BodyTable",
           "body_from_dict", "check_number", "coverage_from_dict", "short_repr"]

BODY_TABLE = "body"
#: [m] the largest magnitude of each component of a position: a vehicle file's rotor hubs and centre
#: of mass, and the ``[body]`` table's fitted centre of mass (which ``fit flight`` writes from the
#: vehicle file's: the table allowed 1 m until stop 102, and refused the file a fit had written)
POSITION_MAX = 100.0
#: the table of what a fitted set's data covered (warnings when the set is used beyond it)
COVERAGE_TABLE = "coverage"
COVERAGE_KEYS = {"J_max": (0.0, 100.0), "incidence_deg_max": (0.0, 180.0), "rpm_min": (0.0, 1e7),
                 "rpm_max": (0.0, 1e7), "airspeed_max": (0.0, 500.0),
                 # the propeller the data are of (a load fit's; since 2026-11-26): its diameter [m] and blade count
                 "diameter_m": (0.0, 100.0), "n_blades": (1.0, 100.0),
                 # the chord Reynolds numbers at 0.75 R of the data's rates, in the fit's air (since 2026-11-26)
                 "re75_min": (0.0, 1e9), "re75_max": (0.0, 1e9),
                 # the fitted blade's angle at 0.75 R [deg], the set's own collective not included (since 2026-11-29:
                 # a blade set from UIUC names, nr640_5_20deg's +5 deg, was lost when the file ran the geometry again)
                 "theta75_deg": (-90.0, 90.0),
                 # the data's collective column's range [deg], added to the blade (a collective sweep's; since
                 # 2026-12-01: its fit warned of a collective inside it as another blade angle, a user-level audit)
                 "collective_deg_min": (-45.0, 45.0), "collective_deg_max": (-45.0, 45.0)}
#: the [coverage] keys whose lower end is open (a hand-edited diameter_m = 0 silenced the size check: an audit)
COVERAGE_OPEN_LOW = ("diameter_m", "re75_min", "re75_max")
#: the [coverage] table's text: the data fitted (a label) and the groups (runs, a CSV's group labels, logs) the fit
#: saw and held out, so that `propmap validate` can say which of its rows are in-sample; each data file's SHA-256
#: (files_sha256, since 2026-11-26; a flight fit's training logs' since 2026-11-30, which `wrench` reads), so that
#: it can say so for a part of them too
COVERAGE_TEXT_KEYS = ("data", "data_sha256", "groups", "held_out", "propeller", "files_sha256")
#: the [coverage] text keys that hold one text (the others a list of texts)
COVERAGE_SINGLE_TEXTS = ("data", "data_sha256", "propeller")
#: the longest text and list of the [coverage] table's text keys
COVERAGE_TEXT_MAX, COVERAGE_LIST_MAX = 1000, 100_000


class BodyTable(NamedTuple):
    """A parameter file's ``[body]`` table.

    Attributes
    ----------
    drag : BodyDrag
        The airframe drag (core/body.BodyDrag).
    centre_of_mass : ndarray of shape (3,) or None
        The centre of mass [m] in the vehicle frame; None when the table has none.
    rotor_interference : float or None
        The rotor interference factor [-]; None when the table has none.
    """

    drag: object
    centre_of_mass: object
    rotor_interference: float | None = None


def coverage_from_dict(data: dict, *, where: str = "parameters") -> dict | None:
    """The ``[coverage]`` table of a file-form dict (what the fitted data covered: J_max,
    incidence_deg_max, rpm_min, rpm_max, airspeed_max; and, as text, the data fitted and the
    groups it saw and held out), or None without one.

    Parameters
    ----------
    data : dict
        File form (io/params_file.py's module docstring); only its ``[coverage]`` table is read.
    where : str
        Starts every error message.

    Returns
    -------
    dict or None
        The table's keys, each as a float (``J_max`` [-], ``incidence_deg_max`` [deg],
        ``rpm_min``, ``rpm_max`` [rpm], ``airspeed_max`` [m/s], ``diameter_m`` [m],
        ``re75_min``, ``re75_max``), ``n_blades`` as int, ``data``, ``data_sha256`` and ``propeller``
        as str and ``groups``, ``held_out`` and ``files_sha256`` as tuples of str; None without
        a table.

    Raises
    ------
    ValueError
        Not a table, an unknown key, a value not a number or out of its range, rpm_min above
        rpm_max, ``data``, ``data_sha256`` or ``propeller`` not a text of at most 1,000
        characters, ``groups``, ``held_out`` or ``files_sha256`` not a list of such texts (at
        most 100,000). (Every key is optional: the warnings check those given.)
    """
    table = data.get(COVERAGE_TABLE)
    if table is None:
        return None
    if not isinstance(table, dict):
        raise ValueError(f"{where}: [{COVERAGE_TABLE}] must be a table, got {short_repr(table)}")
    unknown = sorted(set(table) - set(COVERAGE_KEYS) - set(COVERAGE_TEXT_KEYS))
    if unknown:
        valid = [*COVERAGE_KEYS, *COVERAGE_TEXT_KEYS]
        raise ValueError(f"{where}: [{COVERAGE_TABLE}] unknown key(s) {', '.join(map(str, unknown[:5]))}"
                         f"{did_you_mean(unknown, valid)} (valid: {', '.join(valid)})")
    text = {}
    for k, v in table.items():
        if k not in COVERAGE_TEXT_KEYS:  # (a diameter and a Reynolds number of 0 are no data's: open below)
            check_number(v, f"{COVERAGE_TABLE}.{k}", where, (*COVERAGE_KEYS[k], k in COVERAGE_OPEN_LOW, False, ""))
            if k == "n_blades" and float(v) != round(float(v)):
                raise ValueError(f"{where}: [{COVERAGE_TABLE}] n_blades must be a whole number, got {short_repr(v)}")
            continue
        items = [v] if k in COVERAGE_SINGLE_TEXTS else v
        if not (isinstance(items, list) and len(items) <= COVERAGE_LIST_MAX
                and all(isinstance(x, str) and len(x) <= COVERAGE_TEXT_MAX for x in items)):
            raise ValueError(f"{where}: [{COVERAGE_TABLE}] {k} must be "
                             + ("a text" if k in COVERAGE_SINGLE_TEXTS else "a list of texts")
                             + f" of at most {COVERAGE_TEXT_MAX} characters, got {short_repr(v)}")
        text[k] = v if k in COVERAGE_SINGLE_TEXTS else tuple(v)
    table = {k: v for k, v in table.items() if k not in COVERAGE_TEXT_KEYS}
    for lo, hi in (("rpm_min", "rpm_max"), ("re75_min", "re75_max"), ("collective_deg_min", "collective_deg_max")):
        if lo in table and hi in table and table[lo] > table[hi]:
            raise ValueError(f"{where}: [{COVERAGE_TABLE}] {lo} {table[lo]:g} exceeds {hi} {table[hi]:g}")
    return {**{k: (int(v) if k == "n_blades" else float(v)) for k, v in table.items()}, **text}


def body_from_dict(data: dict, *, where: str = "parameters") -> BodyTable | None:
    """The ``[body]`` table of a file-form dict (io/params_file.py's module docstring), or None
    without one.

    Parameters
    ----------
    data : dict
        File form (io/params_file.py's module docstring); only its ``[body]`` table is read.
    where : str
        Starts every error message.

    Returns
    -------
    BodyTable or None

    Raises
    ------
    ValueError
        A ``[body]`` that is not a table, an unknown key in it, a missing ``drag_area``, or
        values of the wrong type or out of range (core/body.py; centre_of_mass in [-100, 100] m,
        rotor_interference in [0, 3]; comment a str);
        the message starts with ``where``.
    """
    import numpy as np

    from ..core.body import BodyDrag

    if BODY_TABLE not in data:
        return None
    table = data[BODY_TABLE]
    if not isinstance(table, dict):
        raise ValueError(f"{where}: [body] must be a table with drag_area (wash_factor optional), "
                         f"got {short_repr(table)}")
    allowed = ("drag_area", "wash_factor", "centre_of_mass", "rotor_interference", "comment")
    extra = sorted(str(k) for k in table if k not in allowed)
    if extra:
        raise ValueError(f"{where}: [body]: unknown key(s) {', '.join(short_repr(k, 40) for k in extra[:5])}"
                         f"{did_you_mean(extra, allowed)} (allowed: {', '.join(allowed)})")
    if "drag_area" not in table:
        raise ValueError(f"{where}: [body]: missing key 'drag_area'")
    vectors = {}
    for key, rng in (("drag_area", (0.0, 10.0, False, False, "m^2")),
                     ("centre_of_mass", (-POSITION_MAX, POSITION_MAX, False, False, "m"))):
        if key not in table:
            continue
        value = table[key]
        if not (isinstance(value, list) and len(value) == 3):
            raise ValueError(f"{where}: [body]: {key} must be 3 numbers [{rng[4]}], got {short_repr(value)}")
        for k, v in enumerate(value):
            check_number(v, f"[body] {key}[{k}]", where, rng)
        vectors[key] = [float(v) for v in value]
    if "comment" in table and not isinstance(table["comment"], str):  # (a list was taken, stop 102)
        raise ValueError(f"{where}: [body] comment must be text, got {short_repr(table['comment'])}")
    if "wash_factor" in table:
        check_number(table["wash_factor"], "[body] wash_factor", where, (0.0, 3.0, False, False, ""))
    drag = BodyDrag(drag_area=tuple(vectors["drag_area"]), wash_factor=float(table.get("wash_factor", 0.0)))
    cg = np.array(vectors["centre_of_mass"]) if "centre_of_mass" in vectors else None
    kappa = None
    if "rotor_interference" in table:
        check_number(table["rotor_interference"], "[body] rotor_interference", where, (0.0, 3.0, False, False, ""))
        kappa = float(table["rotor_interference"])
    return BodyTable(drag, cg, kappa)


def short_repr(value, n: int = 60) -> str:
    """``repr(value)`` cut to about ``n`` characters, for messages.

    Parameters
    ----------
    value : object
        What to show; an integer of 30 or more digits is described by its length instead.
    n : int, optional
        The longest result, in characters (a cut one ends in ``' ...'``).

    Returns
    -------
    str
    """
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**30:
        return f"an integer of {len(str(abs(value)))} digits"
    r = repr(value)
    return r if len(r) <= n else r[: n - 4] + " ..."


def check_number(value, key: str, where: str, rng) -> None:
    """Refuse a non-number, a non-finite number or one outside ``rng``, naming ``key``.

    Parameters
    ----------
    value : object
        The value read from a file (a bool is not a number here).
    key : str
        Its key, named in the error.
    where : str
        The file or table it came from, the error's prefix.
    rng : tuple or None
        ``(lo, hi, lo_open, hi_open, unit)``: the valid interval, each end open where its flag
        is true, and the unit the message names; None: any finite number.

    Raises
    ------
    ValueError
        ``value`` is not a real number, is not finite, or lies outside ``rng``; a quoted number
        is told to be written without quotes.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        hint = " (a quoted string: write the number without quotes)" if isinstance(value, str) else ""
        raise ValueError(f"{where}: {key} must be a number, got {short_repr(value)}{hint}")
    try:
        x = float(value)
    except OverflowError:
        x = math.inf if value > 0 else -math.inf
    if rng is None:
        if not math.isfinite(x):
            raise ValueError(f"{where}: {key} must be a finite number, got {short_repr(value)}")
        return
    lo, hi, lo_open, hi_open, unit = rng
    if not (math.isfinite(x) and (lo < x if lo_open else lo <= x) and (x < hi if hi_open else x <= hi)):
        interval = f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}{' ' + unit if unit else ''}"
        raise ValueError(f"{where}: {key} must be a finite number in {interval}, got {short_repr(value)}")
