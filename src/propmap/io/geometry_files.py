"""Readers for propeller geometry files (io/readers.py has the measurement files).

* UIUC Propeller Data Site (Brandt & Selig, AIAA 2011-1255) geometry ``r/R c/R beta``.
* APC Propellers PE0 geometry files (APC "Technical Information", v2022-0915): io/pe0.py's
  reader, re-exported here.
* QPROP propeller files (M. Drela, QPROP 1.22, GPL source qprop.f): io/qprop_file.py's reader.

:func:`read_geometry` chooses among the three by the file's text. The checks of the stations
that they share are io/blade_stations.py's.

Every reader raises :class:`GeometryFileError` (a ValueError) with a one-line message naming
the file, the line where known and, for a value out of range, the valid range: UIUC r/R in
(0, 1], c/R in [0, 1], beta in [-90, 90] deg; APC RADIUS in [0.25, 50] in, BLADES an integer
in [1, 100], TWIST in [-90, 90] deg, every table value finite; a diameter from the name in
[0.5, 100] in. No other exception escapes for any file content, and none modifies its input.

Diameters in file names: UIUC names are ``<family>_<D>x<P>``, D and P in inches, except
the families whose sizes are in millimetres (:data:`MM_FAMILIES`: ``ef``, ``kpf``, ``pl``,
``vp``, e.g. ``ef_130x70`` is 130 mm = 5.118 in). :func:`read_uiuc_geometry` reads those
as millimetres, says so in ``Propeller.source`` and warns (``UserWarning``). A blade count
in the name (a UIUC hub's ``_3b``, or a third figure, ``hq_6x4.5x3``) other than ``n_blades``
is warned of too.
"""

from __future__ import annotations

import io
import math
import re
import warnings
from pathlib import Path

import numpy as np

from ..core.geometry import INCH, Propeller, rotor_like
from .blade_stations import (CHORD_MAX_PLAUSIBLE, FIRST_STATION_MAX, LAST_STATION_MIN, LAST_STATION_REFUSED,
                             GeometryFileError, _refuse_short_blade, _warn_partial_blade)
from .inputs import _check_column, _check_number, _clip, _read_table, _read_text, as_path, show_path
from .pe0 import _apc_pe0, _is_pe0, read_apc_pe0
from .qprop_file import _geometry as _qprop_geometry
from .qprop_file import _is_qprop

__all__ = ["GeometryFileError", "read_uiuc_geometry", "read_apc_pe0", "read_geometry", "geometry_format", "MM_FAMILIES",
           "NAME_DIAMETER_RANGE_IN", "blade_angle_from_name", "name_blade_count", "name_without_blade_angle",
           "size_in_inches_from_name", "FIRST_STATION_MAX", "LAST_STATION_MIN", "LAST_STATION_REFUSED"]


#: what a diameter-less geometry file needs (a vehicle file says it in its own key: vehicle/file.py)
SIZE_HINT = ("give the diameter (--diameter-in; read_geometry's diameter_in) or name the file "
             "<family>_<D>x<P>_geom.txt (D in inches, in mm for the ef, kpf, pl and vp families)")
#: UIUC families whose file names give the diameter and pitch in millimetres
MM_FAMILIES = frozenset({"ef", "kpf", "pl", "vp"})
#: plausible diameters derived from a file name [in]
NAME_DIAMETER_RANGE_IN = (0.5, 100.0)
#: a name's size ``<D>x<P>``; D not after a digit, point or comma: ``kp_4,9x3,1`` (a decimal comma) gives no size,
#: not 9 in (taken silently from a data file's name and the geometry file's; a mutation audit, 2026-11-29)
_NAME_RE = re.compile(r"(?<![\d.,])(?P<D>\d+(?:\.\d+)?)x(?P<P>\d+(?:\.\d+)?)", re.ASCII | re.IGNORECASE)
#: UIUC vol. 2's NR640 names: the diameter [in] and the blade angle at 0.75 R, ``nr640_9_15deg`` (a file named
#: without ``_geom``, ``nr640_5_15deg.txt``, too: its reader names it by the whole file name)
_ANGLE_NAME_RE = re.compile(r"_(?P<D>\d+(?:\.\d+)?)_(?P<A>\d+(?:\.\d+)?)deg(?=[_.]|$)", re.ASCII | re.IGNORECASE)


def size_from_name(name: str) -> tuple[float | None, float | None, str, str]:
    """(diameter, pitch, unit, family) from a UIUC-style name ``<family>_<D>x<P>``.

    Parameters
    ----------
    name : str
        A propeller's or a file's name (``apce_10x7``, ``ef_130x70_geom``, ``8x6E``), or UIUC
        vol. 2's ``<family>_<D>_<angle>deg`` (``nr640_9_15deg``: 9 in, the blade at 15 deg at
        0.75 R, :func:`blade_angle_from_name`), whose pitch is not written (None).

    Returns
    -------
    tuple
        D and P as written (None, None without a size), the unit ``"in"``, or ``"mm"`` for
        :data:`MM_FAMILIES`, and the family.
    """
    m = _NAME_RE.search(name)
    if not m:
        a = _ANGLE_NAME_RE.search(name)
        if a is None:
            return None, None, "in", ""
        return float(a["D"]), None, "in", name[: a.start()].split("_")[-1]
    family = name[: m.start()].rstrip("_").split("_")[-1]
    return float(m["D"]), float(m["P"]), ("mm" if family.lower() in MM_FAMILIES else "in"), family


def size_in_inches_from_name(name: str) -> tuple[float | None, float | None]:
    """The diameter and pitch a UIUC-style name gives, in inches, as the geometry reader takes them.

    Parameters
    ----------
    name : str
        A propeller's or a file's name (:func:`size_from_name`: millimetres for
        :data:`MM_FAMILIES`, ``ef_130x70``: 5.118 in).

    Returns
    -------
    tuple of (float or None, float or None)
        Diameter and pitch [in]; the diameter None where the name gives none or one outside
        :data:`NAME_DIAMETER_RANGE_IN` (a size in millimetres of a family not known to give them,
        which the reader refuses to take from a name), the pitch None where it is not written
        (``nr640_9_15deg``) or the diameter is None.
    """
    D, P, unit, _ = size_from_name(name)
    scale = 1 / 25.4 if unit == "mm" else 1.0
    lo, hi = NAME_DIAMETER_RANGE_IN
    d_in = None if D is None or not lo <= D * scale <= hi else D * scale
    return d_in, None if P is None or d_in is None else P * scale


def blade_angle_from_name(name: str) -> float | None:
    """The blade angle at 0.75 R that a UIUC vol. 2 name ``<family>_<D>_<angle>deg`` gives.

    Parameters
    ----------
    name : str
        A propeller's or a file's name (``nr640_5_20deg``: the NR640 blades set to 20 deg at
        0.75 R; Deters, Ananda & Selig, AIAA 2014-2151).

    Returns
    -------
    float or None
        The angle [deg]; None for a name of another form (``apce_10x7``, ``nr640_geom``).
    """
    a = _angle_match(name)
    return None if a is None else float(a["A"])


def name_without_blade_angle(name: str) -> str:
    """A UIUC vol. 2 name without the blade angle :func:`blade_angle_from_name` reads from it.

    Parameters
    ----------
    name : str
        A propeller's or a file's name: ``nr640_5_20deg`` (the NR640 blades set to 20 deg at
        0.75 R on an adjustable hub; Deters, Ananda & Selig, AIAA 2014-2151) gives ``nr640_5``,
        the same blades at any setting.

    Returns
    -------
    str
        The name without ``_<angle>deg``; a name of another form as it is.
    """
    a = _angle_match(name)
    return name if a is None else f"{name[: a.start()]}_{a['D']}{name[a.end():]}"


def _angle_match(name: str):
    """The ``_<D>_<angle>deg`` of an NR640-style name, None where the name gives a size ``<D>x<P>``."""
    return None if _NAME_RE.search(name) else _ANGLE_NAME_RE.search(name)


def read_uiuc_geometry(path, *, diameter_in: float | None = None, n_blades: int = 2,
                       name: str | None = None, source: str = "") -> Propeller:
    """Read a UIUC geometry file (columns ``r/R c/R beta``, beta in degrees).

    Parameters
    ----------
    path : str or Path
    diameter_in : float, optional
        Diameter [in], finite and > 0. If omitted it is taken from a UIUC-style name
        ``<fam>_<D>x<P>_geom.txt``: D in inches, except the families of
        :data:`MM_FAMILIES` (``ef``, ``kpf``, ``pl``, ``vp``), whose names give millimetres
        (``ef_130x70`` is 5.118 in): the reader then says so in ``Propeller.source`` and
        warns. A diameter from the name must lie in [0.5, 100] in.
    n_blades : int
        Blade count (UIUC vol. 1 propellers are 2-bladed).
    name, source : str, optional

    Returns
    -------
    Propeller

    Raises
    ------
    GeometryFileError
        Not a readable regular file (or over 16 MiB), missing columns, non-numeric or
        non-finite values, r/R outside (0, 1], c/R outside [0, 1], beta outside [-90, 90]
        deg, radii not strictly increasing, fewer than 2 stations, a last station inside
        r/R = 0.7, a bad ``diameter_in`` or ``n_blades``, or no diameter given or plausibly
        derivable from the name (the message suggests ``--diameter-in``); each message names
        the file and the line.

    Warns
    -----
    UserWarning
        The diameter was read in millimetres from the name; or the blade angles look like
        radians (every one below 1.6, and read as radians they make a near-constant pitch
        r tan(beta) over 0.3-1 R, as propellers have); they are read as degrees. A rotor's
        small, nearly untwisted angles in degrees (a collective given separately) do not
        warn. Or the largest c/R lies outside [0.12, 0.6] (CHORD_MAX_PLAUSIBLE; the
        catalogue's: 0.15-0.39), as a chord in another unit or c/D gives (below it, not for
        a helicopter-style rotor's slender blades: :func:`propmap.core.geometry.rotor_like`).
        Or the stations stop inside r/R = 0.9 (LAST_STATION_MIN): the blade beyond them is
        extrapolated to the tip (refused inside r/R = 0.7, LAST_STATION_REFUSED, or where
        that extrapolation gives no blade: :class:`propmap.core.geometry.Propeller`). Or
        ``key = value`` lines, which a geometry file does not use (not read).
    """
    text = _read_text(path, GeometryFileError)
    return _uiuc_geometry(Path(path), text, diameter_in=diameter_in, n_blades=n_blades, name=name, source=source)


def _uiuc_table(path: Path, text: str, where: str) -> np.ndarray:
    """The r/R c/R beta table of a UIUC geometry file, each column in its range and r/R strictly
    increasing (refused naming the line); other lines of the form ``key: value`` warned of as not
    read."""
    table = _read_table(path, text, ["r/R", "c/R", "beta"], GeometryFileError)
    _check_column(table, 0, "r/R (station radius / tip radius)", 0.0, 1.0, path, GeometryFileError, lo_open=True)
    _check_column(table, 1, "c/R", 0.0, 1.0, path, GeometryFileError)
    _check_column(table, 2, "beta", -90.0, 90.0, path, GeometryFileError, unit="deg")
    data = table.data
    zero = np.flatnonzero(data[:-1, 1] <= 0.0)
    if zero.size:  # (as a QPROP file's rule: a chord of 0 inside the blade cut its thrust 8% unsaid, a file audit)
        i = int(zero[0])
        raise GeometryFileError(f"{where}, line {int(table.lines[i])}: c/R = {data[i, 1]:g} at r/R = {data[i, 0]:g}: "
                                "a chord must be > 0 (>= 0 at the last station, the tip)")
    step = np.diff(data[:, 0])
    if np.any(step <= 0):  # (in the file's terms: Propeller would say it in metres, counting from 0)
        i = int(np.argmax(step <= 0)) + 1
        raise GeometryFileError(f"{where}, line {int(table.lines[i])}: r/R = {data[i, 0]:g} does not exceed the "
                                f"previous station's {data[i - 1, 0]:g} (line {int(table.lines[i - 1])}): the stations "
                                "must be strictly increasing")
    if table.meta:  # (a UIUC geometry file has none: its name gives the size, --blades the count)
        shown = ", ".join(f"{k} = {v} (line {line})" for k, (v, line) in list(table.meta.items())[:4])
        warnings.warn(f"{where}: {shown} not read: a UIUC geometry file is its r/R c/R beta table (the diameter from "
                      "the file name or diameter_in, the blade count from n_blades: --diameter-in, --blades)",
                      UserWarning, stacklevel=4)
    return data


def _uiuc_diameter(stem: str, size, diameter_in, where: str) -> tuple[float, str]:
    """The diameter [in] of a UIUC geometry file named ``stem`` (``size``: its
    :func:`size_from_name`): ``diameter_in`` where given (checked, warned of where it differs from
    the name's by more than 5%), else the name's (refused where the name gives none or an
    implausible one; a millimetre family's warned of); and the note of a diameter read in
    millimetres for the propeller's source ("" otherwise)."""
    D_name, _, unit, family = size
    note = ""
    if diameter_in is None:
        if D_name is None:
            raise GeometryFileError(f"{where}: diameter unknown; {SIZE_HINT}")
        lo, hi = NAME_DIAMETER_RANGE_IN
        diameter_in = size_in_inches_from_name(stem)[0]
        if diameter_in is None:
            # (a name without its decimal point, 125x75 for 12.5 x 7.5 in: a UIUC file audit, 2026-11-30)
            dropped = (f"; a name may drop the decimal point ({D_name:g} for {D_name / 10:g} in: --diameter-in "
                       f"{D_name / 10:g}?)" if unit == "in" and float(D_name).is_integer() and lo <= D_name / 10 <= hi
                       else "")
            raise GeometryFileError(
                f"{where}: diameter {D_name:g} {unit} from the file name is not plausible (a diameter from a name "
                f"must be in [{lo:g}, {hi:g}] in){dropped}; {SIZE_HINT}")
        if unit == "mm":
            note = (f"diameter {D_name:g} mm = {diameter_in:.4g} in from the file name (UIUC family "
                    f"{family!r} gives sizes in millimetres)")
            warnings.warn(f"{where}: {note}; if that is wrong, {SIZE_HINT}", UserWarning,
                          stacklevel=4)
    else:
        _check_number(diameter_in, "diameter_in", GeometryFileError, where)
        try:
            ok = math.isfinite(float(diameter_in)) and diameter_in > 0
        except OverflowError:  # an int too large for a float
            ok = False
        if not ok:
            raise GeometryFileError(f"{where}: diameter_in must be finite and > 0 in, got {_clip(str(diameter_in))}")
        named = None if D_name is None else (D_name / 25.4 if unit == "mm" else D_name)
        if named is not None and named > 0 and abs(float(diameter_in) / named - 1.0) > 0.05:  # (130 mm is sold as 5 in)
            warnings.warn(f"{where}: diameter {float(diameter_in):g} in as given, not the {D_name:g} {unit} of the "
                          "file name", UserWarning, stacklevel=4)
    return diameter_in, note


def name_blade_count(file_name: str) -> int | None:
    """The blade count a propeller's file name gives, or None: a UIUC hub's ``_3b``, or a third
    size figure (``6x4.5x3``, as HQProp names its three-blade propellers).

    Parameters
    ----------
    file_name : str
        A geometry or data file's name, or a propeller's (``_geom`` and an extension dropped).

    Returns
    -------
    int or None
        The count, 1-9.
    """
    # (an extension starts with a letter: a bare name's '5.1x3.7x3' lost '.7x3' as one)
    bare = re.sub(r"(_geom)?(\.[a-z][a-z0-9]*)?$", "", file_name, flags=re.IGNORECASE)
    count = re.search(r"_([1-9])b(?:_|$)", bare, re.IGNORECASE) or re.search(
        r"\d(?:\.\d+)?x\d+(?:\.\d+)?x([1-9])(?:_|$)", bare, re.IGNORECASE)
    return int(count.group(1)) if count else None


def _warn_blade_count(file_name: str, n_blades: int, blades_given: bool, where: str) -> None:
    """Warn where the file name gives a blade count other than ``n_blades`` (given by the user)."""
    # a blade count in the name: a UIUC hub's "_3b", or a third size figure ("6x4.5x3", as HQProp names its
    # tri-blades); a user-level audit ran such files with --blades 2 unwarned
    count = name_blade_count(file_name)
    if count and blades_given and count != n_blades:
        warnings.warn(f"{where}: {n_blades} blades (n_blades, --blades), not the {count} of the file name",
                      UserWarning, stacklevel=4)


def _uiuc_geometry(path: Path, text: str, *, diameter_in, n_blades, name, source, blades_given=True) -> Propeller:
    where = show_path(path)
    data = _uiuc_table(path, text, where)
    stem = re.sub(r"_geom\.txt$", "", path.name, flags=re.IGNORECASE)
    size = size_from_name(stem)
    _, P_name, unit, _ = size
    diameter_in, note = _uiuc_diameter(stem, size, diameter_in, where)
    _warn_blade_count(path.name, n_blades, blades_given, where)
    pitch_in = None
    if P_name is not None:
        pitch_in = P_name / 25.4 if unit == "mm" else P_name
        if not (math.isfinite(pitch_in) and 0 < pitch_in <= 10 * NAME_DIAMETER_RANGE_IN[1]):
            pitch_in = None  # catalogue information only: an implausible one is dropped
    if _looks_like_radians(data[:, 0], data[:, 2]):
        warnings.warn(f"{where}: every blade angle beta is below 1.6 in magnitude: the column looks like radians, "
                      "but UIUC geometry files give degrees (read as degrees)", UserWarning, stacklevel=3)
    if np.all(np.diff(data[:, 0]) > 0):  # (else: Propeller says so)
        _refuse_short_blade(where, data[:, 0])
    R = 0.5 * float(diameter_in) * INCH
    src = source or f"UIUC Propeller Data Site geometry file {path.name}"
    if note:
        src = f"{src}; {note}"
    try:
        prop = Propeller(name=name or stem, radius=R, n_blades=n_blades, r=data[:, 0] * R,
                         chord=data[:, 1] * R, theta=np.radians(data[:, 2]),
                         pitch=None if pitch_in is None else pitch_in * INCH, source=src)
    except ValueError as exc:
        raise GeometryFileError(f"{where}: {exc}") from None
    c_max = float(np.max(data[:, 1]))
    # (a helicopter-style rotor's slender blades, c/R 0.05-0.1, are not warned: rotor_like)
    if c_max > CHORD_MAX_PLAUSIBLE[1] or (c_max < CHORD_MAX_PLAUSIBLE[0] and rotor_like(prop) is None):
        warnings.warn(f"{where}: the largest c/R is {c_max:.3g}, where the 147 catalogue propellers' lie within "
                      "0.15-0.39: is the c/R column the chord in another unit, or c/D? (read as c/R)", UserWarning,
                      stacklevel=3)
    _warn_partial_blade(where, data[:, 0])
    return prop


#: the coefficient of variation of r tan(beta) over 0.3-1 R below which radian-valued blade
#: angles make a propeller's near-constant pitch (the 108 catalogue propellers: <= 0.185;
#: an untwisted rotor: 0.32)
RADIANS_PITCH_CV = 0.25


def _looks_like_radians(r_over_R, beta) -> bool:
    """True when the blade-angle column is plausibly radians (see _uiuc_geometry's warning)."""
    if not np.all(np.abs(beta) < 1.6):
        return False
    outer = r_over_R >= 0.3
    beta = np.abs(beta) if np.all(beta[outer] < 0) else beta  # (a pusher's or mirrored file: negative angles)
    if outer.sum() < 2 or np.any(beta[outer] <= 0):
        return False
    q = r_over_R[outer] * np.tan(beta[outer])
    return bool(np.std(q) < RADIANS_PITCH_CV * np.mean(q))


def _format(text: str) -> str | None:
    """``"qprop"``, ``"pe0"``, ``"uiuc"`` or None: the reader :func:`read_geometry` chooses for the text.

    QPROP first: its signature (a name line, then data lines starting with numbers as QPROP's lines
    2-8 do, not a table's rows of as many numbers each, no ``r/R`` header line; io/qprop_file.py's
    ``_is_qprop``) is narrower than PE0's words, which a QPROP comment line may hold; a PE0 file's
    second line is text, and a UIUC file has its header."""
    if _is_qprop(text):
        return "qprop"
    if _is_pe0(text):
        return "pe0"
    return "uiuc" if _is_uiuc_geometry(text) else None


def geometry_format(path) -> str | None:
    """The format of a geometry file as :func:`read_geometry` tells it, without parsing the table.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    str or None
        ``"pe0"`` (an APC PE0 file: it states its radius and blade count), ``"qprop"`` (a
        QPROP propeller file: both too), ``"uiuc"`` (a UIUC ``r/R c/R beta`` table: neither),
        or None for a file that cannot be read as text or is in none of these formats. Never
        raises.
    """
    try:
        return _format(_read_text(as_path(path), GeometryFileError))
    except (GeometryFileError, TypeError, OSError):
        return None


def _is_uiuc_geometry(text: str) -> bool:
    """Whether the text has a UIUC geometry header (``r/R ...``) in its first 64 kB, after any
    title, comment or ``key = value`` lines (as :func:`read_uiuc_geometry` reads it)."""
    for ln in io.StringIO(text[:65536], newline=None):
        words = ln.split()
        if words and words[0].lower() == "r/r":
            return True
    return False


def _same_diameter(given: float, own: float) -> bool:
    """Whether a diameter given beside a PE0 file is the file's own [in]: equal to 1e-3, or the
    file's rounded to the given's decimals (none for a whole number) within 2% (``--diameter-in 4.2`` beside a PE0 of
    4.183 in was refused: an audit of stop 90)."""
    if math.isclose(given, own, rel_tol=1e-3):
        return True
    text = repr(float(given))
    # (a whole number, 10 for a PE0 of 10.08 in, has none: a review)
    decimals = 0 if float(given).is_integer() else len(text.split(".")[1]) if "e" not in text else 99
    return decimals <= 3 and math.isclose(round(own, decimals), given, rel_tol=1e-9) and abs(given / own - 1) < 0.02


def _own_size(path: Path, prop: Propeller, diameter_in, n_blades, kind: str, states: str) -> Propeller:
    """``prop``, read from a file that states its own size (PE0, QPROP): a ``diameter_in`` or
    ``n_blades`` given beside it is refused unless it is the file's own (the diameter to the
    given's precision, :func:`_same_diameter`); ``states`` says where the file gives its blade count."""
    if diameter_in is not None:
        _check_number(diameter_in, "diameter_in", GeometryFileError, show_path(path))  # (the text "10" met a
        # bare "must be real number"; NaN and inf an IndexError of the decimals' count, an API audit)
        if not (math.isfinite(float(diameter_in)) and float(diameter_in) > 0):
            raise GeometryFileError(f"{show_path(path)}: diameter_in must be finite and > 0 in, got {diameter_in!r}")
        if not _same_diameter(diameter_in, prop.diameter / 0.0254):
            raise GeometryFileError(f"{show_path(path)}: diameter_in = {diameter_in:.8g} in, but a {kind} file gives "
                                    f"its own radius (diameter {prop.diameter / 0.0254:.8g} in): leave the "
                                    "option out (it applies to UIUC files), or give that diameter, to fewer "
                                    "decimals if you like (within 2%)")
    if n_blades is not None:  # (an array met NumPy's "truth value is ambiguous"; the text "2" a self-contradiction)
        _check_number(n_blades, "n_blades", GeometryFileError, show_path(path), integer=True)
    if n_blades is not None and n_blades != prop.n_blades:
        raise GeometryFileError(f"{show_path(path)}: n_blades = {n_blades}, but the {kind} file states {states}"
                                f"{prop.n_blades}; the blade count applies to UIUC files (a wrong count scales "
                                "the thrust nearly in proportion)")
    return prop


def read_geometry(path, *, diameter_in: float | None = None, n_blades: int | None = None) -> Propeller:
    """Read a geometry file, choosing the reader by content (PE0, QPROP or UIUC ``r/R c/R beta``).

    Parameters
    ----------
    path : str or Path
    diameter_in : float, optional
        For a UIUC file (see :func:`read_uiuc_geometry`); a PE0 file gives its RADIUS and a
        QPROP file its R (or its last station's radius), and a different ``diameter_in`` is
        refused, except the file's diameter rounded to the given's 0 to 3 decimals, within
        2% (a nominal 4.2 in for a PE0 radius of 2.09 in, 4.18 in, or 10 for 10.08 in; not 4
        for 4.18 in, 4.4% off), and the file's diameter is used.
    n_blades : int, optional
        Blade count: required for a UIUC file (which does not state it); a PE0 file states
        its BLADES and a QPROP file its Nblades, and a different ``n_blades`` is refused.

    Returns
    -------
    Propeller

    Raises
    ------
    TypeError
        ``path`` not a str or os.PathLike.
    GeometryFileError
        As the chosen reader; also if the file is not a readable regular file or the format
        is not recognised, a UIUC file without ``n_blades``, or a PE0 or QPROP file with a
        ``diameter_in`` or ``n_blades`` other than its own.

    Warns
    -----
    UserWarning
        As :func:`read_uiuc_geometry` or :func:`propmap.io.qprop_file.read_qprop_geometry`.
    """
    path = as_path(path)
    text = _read_text(path, GeometryFileError)
    kind = _format(text)
    if kind == "pe0":  # (the diameter to the file's own precision: RADIUS is printed to 0.01 in)
        return _own_size(path, _apc_pe0(path, text, name=None, source=""), diameter_in, n_blades, "PE0",
                         "BLADES: ")
    if kind == "qprop":
        return _own_size(path, _qprop_geometry(path, text, name=None, source="", detected=True), diameter_in,
                         n_blades, "QPROP", "Nblades (its second data line): ")
    if kind == "uiuc":
        named = name_blade_count(path.name) if n_blades is None else None
        prop = _uiuc_geometry(path, text, diameter_in=diameter_in,
                              n_blades=n_blades if n_blades is not None else named or 2, name=None, source="",
                              blades_given=n_blades is not None)  # the file's own errors first
        if n_blades is None and named:  # ('hqprop_5.1x3.7x3_geom.txt' was refused for want of a count it gives)
            warnings.warn(f"{show_path(path)}: {named} blades, from the file name; give n_blades (--blades) if the "
                          "propeller has another count", UserWarning, stacklevel=2)
        elif n_blades is None:
            raise GeometryFileError(f"{show_path(path)}: a UIUC geometry file (r/R c/R beta) does not state the blade "
                                    "count: give it (--blades, n_blades); a wrong count scales the thrust (3 blades "
                                    "read as 2: -30% of static thrust on the APC 8x6E)")
        return prop
    first = next((ln.strip() for ln in io.StringIO(text[:65536], newline=None) if ln.strip()), "")
    hint = ("; its columns are separated by commas or semicolons: a UIUC file's are separated by blanks or tabs"
            if re.match(r"r/r\s*[,;]", first, re.I) else
            "; a UIUC file's table starts with its header line 'r/R c/R beta' (radius / R, chord / R, blade angle in "
            "degrees), then one station per line; a QPROP file starts with the propeller's name, then a line with "
            "its blade count")
    raise GeometryFileError(f"{show_path(path)}: unrecognised geometry format (expected UIUC 'r/R c/R beta', an "
                            f"APC PE0 file or a QPROP propeller file){hint}")
