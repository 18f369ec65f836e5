"""Reader of QPROP propeller files (M. Drela's QPROP, the axial propeller and motor program):
:func:`read_qprop_geometry`, which :func:`propmap.io.read_geometry` chooses for a file in the
format, and :func:`read_qprop_params`, the file's section aero line as a cambered parameter set
(``--params qprop:FILE``).

The format, as QPROP 1.22 reads it (M. Drela, QPROP, version 1.22, source file qprop.f,
and its line reader io.f; M. Drela, "QPROP Formulation", MIT, 2006), in the order of the file's
data lines:

1. the propeller's name (any text);
2. ``Nblades [R]``: the blade count, and optionally the tip radius R in metres, which the
   scaling factors do not touch (0 or absent: the last station's radius; never inside it);
3. ``CL0 CL_a``; 4. ``CLmin CLmax``; 5. ``CD0 CD2u CD2l [CLCD0]``; 6. ``REref REexp``:
   the section's lift line, stall limits, drag polar and its Reynolds scaling;
7. ``Rfac Cfac Bfac``; 8. ``Radd Cadd Badd``: the stations' radius r, chord c and blade
   angle beta are r Rfac + Radd [m], c Cfac + Cadd [m], beta Bfac + Badd [deg];
9. and on: one station per line, ``r c beta`` and optionally, in order, the station's own
   ``CL0 CL_a CLmin CLmax CD0 CD2u CD2l CLCD0 REref REexp``, which replace the lines 3-6
   values there (but for REref: QPROP 1.22's tqcalc.f passes CDFUN the array REREF where
   REREF(I) belongs, so every station's drag takes the first computed station's REref).

A line whose first character is ``#`` or ``!`` is a comment, and so is the rest of any line
after a ``!``; blank lines are skipped. Values are separated by blanks, tabs or commas; a
line's values beyond those QPROP reads are ignored, as QPROP ignores them. Fortran's ``1.5d0``
is a number. QPROP reads a line's first 128 characters only (CHARACTER*128): values past
column 128, which propmap reads, are warned of.

Every refusal is a :class:`GeometryFileError` with a one-line message naming the file, the line
and the valid range: at least 2 stations, radii > 0 m and increasing, chords > 0 m (>= 0 at
the last station, as QPROP takes them), blade angles in [-90, 90] deg (after the scaling),
a whole number of blades in [1, 100], R >= the last station's radius, a diameter in
[0.5, 100] in, every value a finite number. QPROP itself takes a first station at r = 0 and a
blade count that is not whole (refused here), and stops at more than 81 stations (its IRDIM;
read here).
"""

from __future__ import annotations

import io
import math
import re
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.air import Air
from ..core.airfoil import CamberedParams
from ..core.geometry import INCH, Propeller, rotor_like
from .blade_stations import (CHORD_MAX_PLAUSIBLE, LAST_STATION_REFUSED, GeometryFileError,
                             _warn_partial_blade)
from .inputs import _clip, _read_text, show_path
from .pe0 import _is_pe0

__all__ = ["QPROP_CITATION", "QPROP_PREFIX", "read_qprop_geometry", "read_qprop_params"]

#: where the format and the section model come from
QPROP_CITATION = ('M. Drela, QPROP (version 1.22), source file qprop.f; M. Drela, "QPROP Formulation", '
                  'MIT, 2006')
#: the prefix of a parameter set read from a QPROP file's section aero lines (``--params qprop:FILE``)
QPROP_PREFIX = "qprop:"

#: the data lines 2-8 of a QPROP file: the values each gives, and how many of them QPROP requires
_HEADER = ((("Nblades", "R"), 1), (("CL0", "CL_a"), 2), (("CLmin", "CLmax"), 2),
           (("CD0", "CD2u", "CD2l", "CLCD0"), 3), (("REref", "REexp"), 2), (("Rfac", "Cfac", "Bfac"), 3),
           (("Radd", "Cadd", "Badd"), 3))
#: the section aero values, in the order of lines 3-6 and of a station row's columns 4-13
AERO = ("CL0", "CL_a", "CLmin", "CLmax", "CD0", "CD2u", "CD2l", "CLCD0", "REref", "REexp")
_STATION = ("r", "c", "beta", *AERO)
#: the diameters a QPROP file may give [in] (--diameter-in's range): outside it, a scaling factor is wrong
_DIAMETER_RANGE_IN = (0.5, 100.0)
_NUMBER_RE = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][+-]?\d+)?", re.ASCII)
_TOKEN_RE = re.compile(r"[^ \t,]+|,|[ \t]+")


@dataclass(frozen=True)
class _Propfile:
    """A QPROP file's values as read, each with its line number."""

    where: str
    name: str
    header: tuple  # of (line, values) for the data lines 2-8
    rows: tuple  # of (line, values) for the station rows


def _data_lines(text: str) -> list[tuple[int, str]]:
    """(line number, text before any ``!``) of every line that is no comment and not blank."""
    out = []
    for k, ln in enumerate(io.StringIO(text, newline=None), start=1):
        ln = ln.rstrip("\n")
        if ln[:1] in ("#", "!") or not ln.strip():
            continue
        out.append((k, ln.split("!", 1)[0]))
    return out


def _fields(s: str) -> list[str | None]:
    """The fields of a data line; None for an empty one (a comma after a blank, after another comma or
    at the start, which QPROP counts as a value it leaves unset); commas at the end dropped."""
    out: list[str | None] = []
    after_value = False
    for tok in _TOKEN_RE.findall(s):
        if tok == ",":
            if not after_value:
                out.append(None)
            after_value = False
        elif tok[0] in " \t":
            after_value = False
        else:
            out.append(tok)
            after_value = True
    while out and out[-1] is None:
        out.pop()
    return out


def _float(tok: str) -> float:
    """A field that matches :data:`_NUMBER_RE` as a float (Fortran's ``d`` exponent an ``e``)."""
    return float(tok.replace("d", "e").replace("D", "e"))


def _number(where: str, k: int, tok: str, label: str) -> float:
    number = _NUMBER_RE.fullmatch(tok) is not None
    if number and math.isfinite(x := _float(tok)):
        return x
    if number:  # (1e400: a number beyond a float's range; QPROP's REAL too)
        what = "a finite number (beyond the floating-point range)"
    else:
        what = "a finite number" if tok.lower().lstrip("+-") in ("nan", "inf", "infinity") else "a number"
    raise GeometryFileError(f"{where}, line {k}: {label} = {_clip(tok, 40)} is not {what}")


def _numbers(where: str, k: int, s: str, labels, need: int, what: str, hint: str = "") -> tuple[float, ...]:
    """The values of a data line: the first ``len(labels)`` fields (more are ignored, as QPROP ignores
    them), at least ``need`` of them, each a finite number; ``hint`` ends the message of a line with
    fewer than ``need``."""
    if not s.strip():  # (a line blank up to its '!': an indented note)
        raise GeometryFileError(f"{where}, line {k}: no values before the '!', where {what} reads "
                                f"{' '.join(labels[:need])}: QPROP takes a line for a comment only with '#' or '!' "
                                "in its first column")
    if s.lstrip(" \t").startswith("#"):  # (QPROP's GETFLT fails on the '#' too)
        raise GeometryFileError(f"{where}, line {k}: a '#' after blanks, where {what} reads "
                                f"{' '.join(labels[:need])}: QPROP takes a line for a comment only with '#' or '!' "
                                "in its first column, and reads this one as data")
    vals = []
    for j, f in enumerate(_fields(s)[: len(labels)]):
        if f is None:
            raise GeometryFileError(f"{where}, line {k}: an empty field where {labels[j]} belongs (a comma after a "
                                    "blank or another comma, which QPROP reads as a value left unset): separate the "
                                    "values by blanks, or by a comma right after each")
        vals.append(_number(where, k, f, labels[j]))
    if len(vals) < need:
        optional = f" [{' '.join(labels[need:])}]" if need < len(labels) else ""
        raise GeometryFileError(f"{where}, line {k}: {len(vals)} number{'s' * (len(vals) != 1)} where {what} reads "
                                f"{' '.join(labels[:need])}{optional} (at least {need}){hint}")
    return tuple(vals)


def _parse(path: Path, text: str, detected: bool = False) -> _Propfile:
    """A QPROP file's name line, data lines 2-8 and station rows, each value a finite number; a file of
    another geometry format (a UIUC table, an APC PE0 file) is refused as such (not looked for where
    ``detected``: read_geometry took the text for a QPROP file), and data lines whose values run past
    column 128, which QPROP does not read, are warned of."""
    where = show_path(path)
    lines = _data_lines(text)
    if not lines:
        raise GeometryFileError(f"{where}: no data lines: a QPROP propeller file starts with the propeller's name")
    other = None if detected or _is_qprop(text) else _other_format(text, lines)
    if other:
        raise GeometryFileError(f"{where}: {other}, not a QPROP propeller file (the propeller's name, then "
                                "Nblades [R], CL0 CL_a, ...): give it as the geometry (PROP, --prop), not qprop:FILE")
    header = []
    for i, (labels, need) in enumerate(_HEADER):
        if i + 1 >= len(lines):
            raise GeometryFileError(f"{where}: the file ends after line {lines[-1][0]}, where QPROP reads "
                                    f"{' '.join(labels)} next (its data line {i + 2} of 8 before the stations)")
        k, s = lines[i + 1]
        header.append((k, _numbers(where, k, s, labels, need, f"QPROP's data line {i + 2}")))
    rows = tuple((k, _numbers(where, k, s, _STATION, 3, "a station row", _QMIL_HINT if j == 0 else ""))
                 for j, (k, s) in enumerate(lines[len(_HEADER) + 1:]))
    _warn_past_column_128(where, lines[1:])
    return _Propfile(where=where, name=lines[0][1].strip()[:80], header=tuple(header), rows=rows)


#: said where the first station row has too few values (QMIL's input file reads as a propfile up to there)
_QMIL_HINT = ("; a QMIL input file (XIdes and CLdes where QPROP reads Rfac Cfac Bfac and Radd Cadd Badd, then "
              "one value a line: hub radius, tip radius, ...) is no QPROP propeller file: give the propfile QMIL "
              "writes")
#: the characters of a line QPROP 1.22 reads (io.f's RREAD into qprop.f's CHARACTER*128 LINE)
QPROP_LINE_CHARS = 128


def _uiuc_header(lines) -> int | None:
    """The line number of the first data line that is a UIUC geometry table's ``r/R ...`` header; None."""
    return next((k for k, ln in lines if (ln.split() or [""])[0].lower() == "r/r"), None)


def _other_format(text: str, lines) -> str | None:
    """What a text that is no QPROP file reads as: a UIUC geometry table (its ``r/R`` header line, of
    the data ``lines``) or an APC PE0 file (read_geometry's signature, :func:`propmap.io.pe0._is_pe0`);
    None for neither."""
    k = _uiuc_header(lines)
    if k is not None:
        return f"a UIUC geometry file (its 'r/R c/R beta' header, line {k})"
    if _is_pe0(text):
        return "an APC PE0 file (its STATION and TWIST columns)"
    return None


def _warn_past_column_128(where: str, lines) -> None:
    """Warn of the first data line whose values QPROP does not read whole: it reads a line's first 128
    characters (the rest of a longer line is lost to it, a value there dropped or cut), where propmap
    reads the whole line."""
    cut = []
    for i, (k, s) in enumerate(lines):
        labels = _HEADER[i][0] if i < len(_HEADER) else _STATION
        if len(s.rstrip()) <= QPROP_LINE_CHARS:
            continue
        seen, whole = _fields(s[:QPROP_LINE_CHARS]), _fields(s)[:len(labels)]
        lost = next((j for j, f in enumerate(whole) if j >= len(seen) or seen[j] != f), None)
        if lost is not None:
            cut.append((k, labels[lost]))
    if cut:
        k, label = cut[0]
        more = f" (and {len(cut) - 1} more line{'s' * (len(cut) > 2)})" if len(cut) > 1 else ""
        warnings.warn(f"{where}, line {k}: its values run past column {QPROP_LINE_CHARS}{more}; QPROP 1.22 reads the "
                      f"first {QPROP_LINE_CHARS} characters of a line, and so drops or cuts {label} and the values "
                      "after it, which propmap reads: QPROP's own results for this file are not of these values",
                      UserWarning, stacklevel=4)


def _leading_numbers(s: str) -> list[float]:
    """The numbers a data line starts with, up to its first field that is none (or empty)."""
    out = []
    for f in _fields(s):
        if f is None or not _NUMBER_RE.fullmatch(f):
            break
        out.append(_float(f))
    return out


def _spec_file(spec):
    """The file a parameter spec reads: FILE of ``qprop:FILE``; any other spec (a path, a named set,
    None) as it is. An input no output may overwrite (until stop 96 ``loads --params qprop:q.csv
    --out q.csv`` wrote over it)."""
    return spec[len(QPROP_PREFIX):] if isinstance(spec, str) and spec.startswith(QPROP_PREFIX) else spec


def _qprop_from(spec: str, folder: Path) -> str:
    """``spec`` with the file of a ``qprop:FILE`` set taken from ``folder`` where it exists there, as a
    vehicle file's other entries are (until stop 96 from the working folder); any other spec as it is."""
    rest = spec[len(QPROP_PREFIX):] if spec.startswith(QPROP_PREFIX) else ""
    try:
        return QPROP_PREFIX + str(folder / rest) if rest.strip() and (folder / rest).is_file() else spec
    except (OSError, ValueError):  # (a name the system refuses: the reader says so)
        return spec


def _is_qprop(text: str) -> bool:
    """Whether the text reads as a QPROP propeller file's beginning, by QPROP's comment rules: after a
    name line (any text, a number too: QPROP's FREAD takes it whole), data lines that start with numbers
    in a QPROP file's pattern, not a table's. The lines 2-8 either give all that QPROP requires (1 2 2 3
    2 3 3 numbers at least, and two on line 3, 4 or 6: then a blade count out of range, or values
    beyond Nblades and R on line 2, which QPROP ignores, are the reader's to name), or line 2 starts
    with one or two numbers, the first in [1, 100] (Nblades [R]), and line 3 with a number. Refused:
    a line of a UIUC file's ``r/R`` header, and lines 2-8 that each start with as many numbers (a
    table's rows, 2 or more columns: a QPROP file's lines 3, 4 and 6 have two, lines 5, 7 and 8
    three)."""
    lines = _data_lines(text[:65536])
    if len(lines) < 3 or _uiuc_header(lines) is not None:
        return False
    counts = [len(_leading_numbers(s)) for _, s in lines[1:8]]
    if not (counts[0] and counts[1]) or (len(counts) >= 3 and len(set(counts)) == 1):
        return False
    full = (len(counts) == len(_HEADER) and all(n >= need for n, (_, need) in zip(counts, _HEADER))
            and 2 in (counts[1], counts[2], counts[4]))
    return full or (counts[0] <= 2 and 1 <= _leading_numbers(lines[1][1])[0] <= 100)


def _scaled(f: _Propfile) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """The stations' radii [m], chords [m] and blade angles [deg] after the scaling, and the tip radius R
    [m], each refused naming its line where QPROP or propmap would refuse it."""
    where, rows = f.where, f.rows
    (k_n, (blades, *rest)), k_fac, k_add = f.header[0], f.header[5][0], f.header[6][0]
    if blades != round(blades) or not 1 <= blades <= 100:
        raise GeometryFileError(f"{where}, line {k_n}: Nblades = {blades:g} is not a whole number in [1, 100] (read "
                                "as a QPROP propeller file, whose data line 2 gives the blade count; a table of "
                                "stations is read with its header line, r/R c/R beta)")
    radius = rest[0] if rest else 0.0
    if radius < 0:
        raise GeometryFileError(f"{where}, line {k_n}: R = {radius:g} m is negative: give the tip radius in metres, "
                                "or 0 (or nothing) for the last station's radius")
    if len(rows) < 2:
        raise GeometryFileError(f"{where}: {len(rows)} station row{'s' * (len(rows) != 1)} (r c beta, after line "
                                f"{k_add}): at least 2 are needed")
    rfac, cfac, bfac = f.header[5][1]
    radd, cadd, badd = f.header[6][1]
    raw = np.array([v[:3] for _, v in rows])
    with np.errstate(over="ignore", invalid="ignore"):  # (an overflow is refused below, naming its line)
        r, c, beta = raw[:, 0] * rfac + radd, raw[:, 1] * cfac + cadd, raw[:, 2] * bfac + badd
    scaled = f"scaled by line {k_fac}'s factors and line {k_add}'s offsets"
    for i, (k, _) in enumerate(rows):
        if not (math.isfinite(r[i]) and math.isfinite(c[i]) and math.isfinite(beta[i])):
            raise GeometryFileError(f"{where}, line {k}: r c beta = {raw[i, 0]:g} {raw[i, 1]:g} {raw[i, 2]:g}, "
                                    f"{scaled}, are not all finite")
        if not r[i] > 0:
            raise GeometryFileError(f"{where}, line {k}: r = {raw[i, 0]:g} gives {r[i]:.6g} m ({scaled}): a station "
                                    "must lie off the axis, r > 0 m (the blade starts at the first station)")
        if i and r[i] <= r[i - 1]:
            raise GeometryFileError(f"{where}, line {k}: r = {raw[i, 0]:g} ({r[i]:.6g} m) does not exceed the "
                                    f"previous station's {raw[i - 1, 0]:g} ({r[i - 1]:.6g} m, line {rows[i - 1][0]}): "
                                    "the radii must increase")
        last = i == len(rows) - 1
        if c[i] < 0 or (c[i] == 0 and not last):
            raise GeometryFileError(f"{where}, line {k}: c = {raw[i, 1]:g} gives a chord of {c[i]:.6g} m ({scaled}): "
                                    f"it must be > 0 m{' (>= 0 at the last station)' if not last else ' or 0 here'}")
        if abs(beta[i]) > 90:
            raise GeometryFileError(f"{where}, line {k}: beta = {raw[i, 2]:g} gives {beta[i]:.6g} deg ({scaled}), "
                                    "outside [-90, 90] deg")
    k_last = rows[-1][0]
    if radius == 0:
        radius = float(r[-1])
    elif r[-1] > radius * (1 + 1e-9):
        raise GeometryFileError(f"{where}, line {k_n}: R = {radius:g} m is inside the last station (r = "
                                f"{r[-1]:.6g} m, line {k_last}): R must be >= it (R is in metres, not scaled by Rfac "
                                f"and Radd; or are those, lines {k_fac} and {k_add}, wrong?)")
    elif r[-1] < LAST_STATION_REFUSED * radius:
        raise GeometryFileError(f"{where}, line {k_n}: R = {radius:g} m, but the stations stop at {r[-1]:.6g} m = "
                                f"{r[-1] / radius:.3g} R (line {k_last}): the outer blade, which makes most of the "
                                f"thrust, is not given (at least r = {LAST_STATION_REFUSED:g} R is needed); R is in "
                                "metres, not scaled by Rfac and Radd")
    lo, hi = _DIAMETER_RANGE_IN
    if not lo <= 2 * radius / INCH <= hi:
        given = f"line {k_n}'s R" if rest and rest[0] else f"the last station's r (line {k_last})"
        raise GeometryFileError(f"{where}: the diameter 2R = {2 * radius:.6g} m ({2 * radius / INCH:.4g} in, from "
                                f"{given}) is outside [{lo:g}, {hi:g}] in: are Rfac and Radd (lines {k_fac}, {k_add}) "
                                "right? The radii are r Rfac + Radd in metres (Rfac = 0.0254 for inches)")
    return r, c, beta, radius


def _geometry(path: Path, text: str, *, name: str | None, source: str, detected: bool = False) -> Propeller:
    f = _parse(path, text, detected)
    r, c, beta, radius = _scaled(f)
    shown = f" ({_clip(f.name, 80)})" if f.name else ""
    try:
        prop = Propeller(name=name or path.stem or path.name, radius=radius, n_blades=int(f.header[0][1][0]), r=r,
                         chord=c, theta=np.radians(beta),
                         source=source or f"QPROP propeller file {path.name}{shown}")
    except ValueError as exc:
        raise GeometryFileError(f"{f.where}: {exc}") from None
    c_max = float(np.max(c)) / radius
    if c_max > CHORD_MAX_PLAUSIBLE[1] or (c_max < CHORD_MAX_PLAUSIBLE[0] and rotor_like(prop) is None):
        warnings.warn(f"{f.where}: the largest chord is {c_max:.3g} R, where the catalogue propellers' lie within "
                      f"0.15-0.39 R: are Cfac and Cadd (lines {f.header[5][0]}, {f.header[6][0]}) right? The chords "
                      "are c Cfac + Cadd in metres", UserWarning, stacklevel=3)
    _warn_partial_blade(f.where, r / radius)
    return prop


def read_qprop_geometry(path, *, name: str | None = None, source: str = "") -> Propeller:
    """Read a QPROP propeller file's blade geometry (the module's docstring gives the format).

    The stations are scaled as QPROP scales them (r Rfac + Radd, c Cfac + Cadd [m],
    beta Bfac + Badd [deg]); the tip radius R is line 2's, else the last station's. The
    blade starts at the first station, as in QPROP. Where R lies beyond the last station,
    QPROP's blade ends at the station and R enters only its tip-loss factor, while propmap's
    blade reaches R, its chord and angle carried on from the last stations (warned of inside
    0.9 R, refused inside 0.7 R). The section aero lines are checked as numbers but not used
    here (:func:`read_qprop_params` reads them).

    Parameters
    ----------
    path : str or Path
    name : str, optional
        The propeller's name; default the file's name without its suffix.
    source : str, optional
        Default ``"QPROP propeller file <file name> (<the file's name line>)"``.

    Returns
    -------
    Propeller
        With diameter 2R, the file's blade count and its stations (SI).

    Raises
    ------
    GeometryFileError
        Not a readable regular text file (or over 16 MiB), a data line missing or with
        fewer values than QPROP requires, a value that is not a finite number or an empty
        field (``a ,b``), fewer than 2 stations, a blade count not a whole number in
        [1, 100], a negative R, an R inside the last station or one that puts the last
        station inside 0.7 R, scaled radii not > 0 and increasing, a scaled chord <= 0 (< 0 at the last
        station), a scaled blade angle outside [-90, 90] deg, or a diameter outside
        [0.5, 100] in, or a UIUC table or APC PE0 file given for a QPROP file; each
        message names the file and the line.

    Warns
    -----
    UserWarning
        The largest chord lies outside [0.12, 0.6] R (a wrong Cfac; below it, not for a
        helicopter-style rotor's slender blades), the stations stop inside 0.9 R or start
        outside 0.4 R (as for the other geometry files), or a line's values run past column
        128, which QPROP does not read.
    """
    text = _read_text(path, GeometryFileError)
    return _geometry(Path(path), text, name=name, source=source)


def _station_aero(f: _Propfile) -> tuple[dict, dict, list[str]]:
    """The section aero values at every station, name -> array (lines 3-6's, replaced by a station row's
    own), the line of each in lines 3-6, and the names a station row gives. A CLCD0 that neither line 5
    nor the station gives is refused."""
    glob, line = {}, {}
    for (labels, _), (k, vals) in zip(_HEADER[1:5], f.header[1:5]):
        glob.update(zip(labels, vals))
        line.update((a, k) for a in labels)
    own, table = set(), {a: [] for a in AERO}
    for k, vals in f.rows:
        station = {**glob, **dict(zip(AERO, vals[3:]))}
        own.update(AERO[:len(vals) - 3])
        if "CLCD0" not in station:
            raise GeometryFileError(f"{f.where}, line {line['CLCD0']}: CD0 CD2u CD2l without CLCD0, which QPROP "
                                    f"leaves undefined (the station of line {k} does not give its own): add the lift "
                                    "coefficient of minimum drag to the line (written CD0 CD2 CLCD0, an older "
                                    "layout, its third value is CD2l to QPROP 1.22)")
        for a in AERO:
            table[a].append(station[a])
    return {a: np.array(v) for a, v in table.items()}, line, [a for a in AERO if a in own]


def read_qprop_params(path, *, label: str | None = None, air: Air | None = None) -> CamberedParams:
    """The section aero lines of a QPROP propeller file as a cambered parameter set.

    QPROP's section (qprop.f, cdfun.f; "QPROP Formulation") is the cambered model's attached
    flow: ``cl_alpha = CL_a``, ``alpha_L0 = -CL0 / CL_a``, ``cl_max = CLmax``,
    ``cl_min = CLmin``, ``cd_min = CD0``, ``cl_cdmin = CLCD0``, ``re_ref = REref``,
    ``re_exp = REexp``. QPROP's drag polar has two curvatures, CD2u above CLCD0 and CD2l
    below; propmap's has one, ``cd2 = CD2u``, the branch a thrusting propeller's sections
    work on. Where the station rows give their own values, or these vary along the blade,
    their values at 0.75 R (linear in r) are taken. The rest is the cambered model's own
    (:class:`CamberedParams` defaults): its stall blend to a flat plate in place of QPROP's
    post-stall lift CLmax cos(alpha - CL0/CL_a) with its added drag (tqcalc.f, cdfun.f), no drag
    rise above QPROP's critical Mach number 0.7 (10 (M - 0.7)^3 there), Prandtl-Glauert on
    the lift as in QPROP (which holds M^2 at 0.9, propmap M at 0.9), and Prandtl's tip loss
    factor with sin phi where QPROP's modified one (gvcalc.f) has tan phi.

    Parameters
    ----------
    path : str or Path
    label : str, optional
        The set's ``.label``; default ``"qprop:<path>"``.
    air : Air, optional
        The set's air; default :class:`Air` () (a QPROP file gives none).

    Returns
    -------
    CamberedParams

    Raises
    ------
    GeometryFileError
        As :func:`read_qprop_geometry` (the whole file is checked); also line 5 without
        CLCD0 (QPROP leaves it undefined) where a station does not give it, or a value
        outside the range of the :class:`CamberedParams` field it becomes (CL_a in (0, 20],
        CLmax in (0, 4], CLmin in [-4, 0), -CL0/CL_a in [-20, 10] deg, CD0 in [0, 1], CD2u in
        [0, 10], CLCD0 in [-2, 3], REref in (0, 1e9], REexp in [-2, 1]), naming its line.

    Warns
    -----
    UserWarning
        CD2l differs from CD2u (below CLCD0 the drag is then not QPROP's), the station
        rows give values of their own (those at 0.75 R are taken; a REref that varies is
        not QPROP 1.22's own either), or values run past column 128.
    """
    path = Path(path)
    f = _parse(path, _read_text(path, GeometryFileError))
    r, _, _, radius = _scaled(f)
    table, lines, own = _station_aero(f)
    at = {a: float(np.interp(0.75, r / radius, table[a])) for a in AERO}
    rows = f"lines {f.rows[0][0]}-{f.rows[-1][0]}"
    where = {a: f"{f.where}, {rows} (the stations' {a} at 0.75 R)" if a in own else f"{f.where}, line {lines[a]}"
             for a in AERO}
    if own:
        reref = ("; QPROP 1.22 itself applies one REref at every station, its innermost computed station's (tqcalc.f "
                 "passes CDFUN the array REREF, whose first element it reads)" if np.ptp(table["REref"]) > 0 else "")
        warnings.warn(f"{f.where}: the station rows give their own {', '.join(own)} ({rows}): a propmap parameter "
                      f"set is one section, and their values at 0.75 R are taken{reref}", UserWarning, stacklevel=2)
    if at["CD2l"] != at["CD2u"]:
        warnings.warn(f"{f.where}: CD2u = {at['CD2u']:g} and CD2l = {at['CD2l']:g} differ: propmap's drag polar has "
                      "one curvature, cd2 = CD2u (above CLCD0, where a thrusting propeller's sections work); below "
                      "CLCD0 its drag is not QPROP's", UserWarning, stacklevel=2)
    fields = {"cl_alpha": "CL_a", "cl_max": "CLmax", "cl_min": "CLmin", "cd_min": "CD0", "cd2": "CD2u",
              "cl_cdmin": "CLCD0", "re_ref": "REref", "re_exp": "REexp"}
    kw = {}
    for field, a in fields.items():
        lo, hi = CamberedParams.RANGES[field]
        low_open, high_open = field in CamberedParams._OPEN_LOW, field == "cl_min"
        x = at[a]
        if x < lo or x > hi or (low_open and x == lo) or (high_open and x == hi):
            raise GeometryFileError(f"{where[a]}: {a} = {x:g} is outside {'(' if low_open else '['}{lo:g}, {hi:g}"
                                    f"{')' if high_open else ']'}, the range of propmap's {field}")
        kw[field] = x
    alpha_L0 = -at["CL0"] / at["CL_a"]
    lo, hi = CamberedParams.RANGES["alpha_L0"]
    if not lo <= alpha_L0 <= hi:
        raise GeometryFileError(f"{where['CL0']}: CL0 = {at['CL0']:g} with CL_a = {at['CL_a']:g} gives a zero-lift "
                                f"angle -CL0/CL_a of {math.degrees(alpha_L0):.4g} deg, outside "
                                f"[{math.degrees(lo):g}, {math.degrees(hi):g}] deg")
    try:
        return CamberedParams(**kw, alpha_L0=alpha_L0, air=Air() if air is None else air,
                              label=f"{QPROP_PREFIX}{path}" if label is None else label)
    except (TypeError, ValueError) as exc:  # (an air or label of the wrong kind)
        raise GeometryFileError(f"{f.where}: {exc}") from None
