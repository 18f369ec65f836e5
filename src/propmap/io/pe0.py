"""Reader of APC Propellers PE0 geometry files (APC "Technical Information", v2022-0915, and
later files with a rake column and hub stations inside HUBTRA):
:func:`read_apc_pe0`, which :func:`propmap.io.read_geometry` chooses for a file with a
STATION ... TWIST table.

Every refusal is a :class:`GeometryFileError` with a one-line message naming the file, the line
where known and the valid range: RADIUS in [0.25, 50] in, BLADES an integer in [1, 100], TWIST
in [-90, 90] deg, every table value finite.
"""

from __future__ import annotations

import io
import math
import re
import warnings
from pathlib import Path

import numpy as np

from ..core.geometry import INCH, Propeller
from .blade_stations import GeometryFileError, _refuse_short_blade, _warn_partial_blade
from .inputs import _clip, _line_of, _read_text, parse_number, show_path

__all__ = ["PE0_COLUMNS", "read_apc_pe0"]

#: the ranges of a PE0 file's RADIUS [in] and BLADES
_PE0_RADIUS_IN = (0.25, 50.0)
_PE0_MAX_BLADES = 100


def read_apc_pe0(path, *, name: str | None = None, source: str = "") -> Propeller:
    """Read an APC PE0 geometry file (STATION [in], CHORD [in], ..., TWIST [deg]).

    The blade angle is APC's TWIST column (LE-TE datum), found by the table's header (one
    word a column: 13 in v2022 files, 14 with a later file's rake column); RADIUS and BLADES
    come from the file's summary lines. Stations inside HUBTRA (the hub's transition, where
    later files tabulate the hub fairing) are left out, with a UserWarning.

    Parameters
    ----------
    path : str or Path
    name, source : str, optional

    Returns
    -------
    Propeller

    Raises
    ------
    GeometryFileError
        Not a readable regular file (or over 16 MiB), no station table, a malformed or
        non-finite table value (naming the line and column), no RADIUS or BLADES line, a
        RADIUS that is not a number in [0.25, 50] in, BLADES not an integer in [1, 100],
        TWIST outside [-90, 90] deg, or invalid geometry (stations not increasing or
        beyond RADIUS (by more than half its last printed digit: APC prints RADIUS rounded, and
        a last STATION within that is taken as the radius), negative chord).
    """
    text = _read_text(path, GeometryFileError)
    return _apc_pe0(Path(path), text, name=name, source=source)


def _is_pe0(text: str) -> bool:
    """Whether the text reads as an APC PE0 file: the words STATION and TWIST (its table's columns)
    in its first 4000 characters, the signature :func:`propmap.io.read_geometry` dispatches on."""
    head = text[:4000]
    return "STATION" in head and "TWIST" in head


#: the columns of a PE0 station row (STATION, CHORD, ..., TWIST) in APC's v2022 files; a table whose header names
#: more, one word each (APC's later files add a rake column: 14 values a row, TWIST the 9th), is read by its header
PE0_COLUMNS = 13
#: the most columns a station table's header may name
_PE0_MAX_COLUMNS = 20


def _pe0_table_continues(lines, end: int, where: str, ncol: int = PE0_COLUMNS) -> None:
    """Refuse a station table that a damaged row (blank, short, decimal commas) cut short: a
    station row of PE0_COLUMNS numbers after the line ``end`` that ended it, before the file's next
    header-like line (an input fuzzing audit, 2026-11-27: the rows after a blank line near the
    tip were dropped and the tip extrapolated without a word)."""
    for k in range(end + 1, len(lines) + 1):
        parts = lines[k - 1].split()
        if any(re.match(r"[A-Za-z]", x) for x in parts):
            return  # the next section
        try:
            vals = [parse_number(x) for x in parts]
        except ValueError:
            continue
        if len(vals) >= ncol:
            raise GeometryFileError(f"{where}, line {end}: the station table breaks off here (a blank, short or "
                                    f"malformed row) and goes on at line {k}: repair line {end}")


def _pe0_summary(text: str, key: str, where: str) -> tuple[str, int]:
    m = re.search(rf"{key}:[ \t]*(\S*)", text)
    if not m:
        raise GeometryFileError(f"{where}: {key} line missing (RADIUS and BLADES are needed)")
    return m.group(1), _line_of(text, m.start())


def _pe0_table(lines, where: str) -> tuple[list, list, int | None, list]:
    """The station table of a PE0 file's ``lines``: its rows (as many numbers each as its first row
    holds: PE0_COLUMNS in APC's v2022 files, 14 in later ones with a rake column), the line number
    of each, the line that ended the table (None at the end of the file) and the header's words
    where they name the columns one word each (else none: TWIST is then the 8th of 13 columns);
    refuses a first row of another width than its header's words and PE0_COLUMNS, a later row of
    more values than the first (a value split by a blank), a non-numeric or non-finite value in a
    station row, naming its line and column, and a file without the table."""
    rows, row_lines, header = [], [], []
    in_table = False
    end = None  # the line that ended the station table
    ncol = None  # the width of the table's rows: its first row's
    for k, ln in enumerate(lines, start=1):
        parts = ln.split()
        if "STATION" in parts and "TWIST" in parts:
            in_table, header = True, parts
            continue
        if not in_table:
            continue
        vals = []
        bad = None
        for x in parts:
            try:
                vals.append(parse_number(x))
            except ValueError:
                bad = x
                break
        if bad is not None:
            if len(parts) >= (ncol or PE0_COLUMNS) and vals:  # a station row (it starts with a number), a bad value
                raise GeometryFileError(f"{where}, line {k}: non-numeric value {_clip(bad, 40)} in the station table")
            if rows:
                end = k
                break
            continue  # the units line under the header
        if ncol is None and len(vals) >= PE0_COLUMNS:
            # (by the header where its words name the columns: a later file's 14 columns were refused as 'a value
            # split by a blank', a geometry audit, 2026-12-02; a header of other words, 'CROSS SECTION', with 13 values
            # a row: the v2022 columns, a review)
            if len(vals) == len(header) <= _PE0_MAX_COLUMNS:
                ncol = len(vals)
            elif len(vals) == PE0_COLUMNS:
                ncol, header = PE0_COLUMNS, []
            else:
                raise GeometryFileError(f"{where}, line {k}: {len(vals)} values in the station table's first row, "
                                        f"where its header names {len(header)} columns (a value split by a blank?)")
        if ncol is not None and len(vals) > ncol:  # (a value split by a blank shifted TWIST to the thickness ratio
            # without a word: a file audit, 2026-12-01; every PE0 file of the catalogue and ../shared has 13 a row)
            raise GeometryFileError(f"{where}, line {k}: {len(vals)} values where the station table's rows have "
                                    f"{ncol} (a value split by a blank?)")
        if ncol is not None and len(vals) == ncol:
            for j, v in enumerate(vals):
                if not math.isfinite(v):
                    col = header[j][:20] if j < len(header) else "?"
                    raise GeometryFileError(f"{where}, line {k}: column {j + 1} ({col}) is {_clip(parts[j], 40)}, "
                                            "not a finite number")
            rows.append(vals)
            row_lines.append(k)
        elif rows:
            end = k
            break
    if not rows:
        raise GeometryFileError(f"{where}: no STATION/CHORD/.../TWIST table found")
    return rows, row_lines, end, header


def _pe0_radius_blades(text: str, where: str) -> tuple[float, str, int]:
    """RADIUS [in] (with the digits as printed) and BLADES of a PE0 file's summary lines, each
    refused with its line where missing or out of range."""
    r_raw, r_line = _pe0_summary(text, "RADIUS", where)
    b_raw, b_line = _pe0_summary(text, "BLADES", where)
    try:
        radius_in = parse_number(r_raw)
    except ValueError:
        raise GeometryFileError(f"{where}, line {r_line}: RADIUS {_clip(r_raw, 40)} is not a number") from None
    lo, hi = _PE0_RADIUS_IN
    if not (math.isfinite(radius_in) and lo <= radius_in <= hi):
        raise GeometryFileError(f"{where}, line {r_line}: RADIUS {_clip(r_raw, 40)} in is outside [{lo:g}, {hi:g}] in")
    if not (b_raw.isascii() and b_raw.isdigit() and len(b_raw) <= 3 and 1 <= int(b_raw) <= _PE0_MAX_BLADES):
        raise GeometryFileError(f"{where}, line {b_line}: BLADES {_clip(b_raw, 40)} is not an integer in "
                                f"[1, {_PE0_MAX_BLADES}]")
    return radius_in, r_raw, int(b_raw)


def _outside_hub(data: np.ndarray, row_lines: list, text: str, where: str) -> tuple[np.ndarray, list]:
    """The station rows from the file's HUBTRA (the hub's transition [in]) out, the others left out
    with a warning: APC's later files (v2025) tabulate the hub fairing inside it (TWIST from 0 deg
    at 0.05 R), where its v2022 files start at HUBTRA; read as blade, it moved a 5x3.75 propeller's
    static thrust by +0.9% and its CT at J = 0.6 by -3.6% (a geometry audit, 2026-12-02). Without a
    HUBTRA line, or with fewer than 2 stations from it, every row is kept."""
    m = re.search(r"HUBTRA:[ \t]*(\S+)", text)
    try:
        hubtra = parse_number(m.group(1)) if m else math.nan
    except ValueError:
        return data, row_lines
    inside = data[:, 0] < hubtra * (1 - 1e-9)
    if not (math.isfinite(hubtra) and inside.any() and np.count_nonzero(~inside) >= 2):
        return data, row_lines
    warnings.warn(f"{where}: {int(inside.sum())} station(s) inside HUBTRA, the hub's transition at {hubtra:g} in, left "
                  "out (the hub fairing's, not the blade's: the file's first station is "
                  f"{data[0, 0]:g} in)", UserWarning, stacklevel=4)
    return data[~inside], [ln for ln, i in zip(row_lines, inside) if not i]


def _apc_pe0(path: Path, text: str, *, name, source) -> Propeller:
    where = show_path(path)
    lines = io.StringIO(text, newline=None).readlines()
    rows, row_lines, end, header = _pe0_table(lines, where)
    if end is not None:
        _pe0_table_continues(lines, end, where, len(rows[0]))
    radius_in, r_raw, n_blades = _pe0_radius_blades(text, where)
    data = np.array(rows)
    data, row_lines = _outside_hub(data, row_lines, text, where)
    twist = data[:, header.index("TWIST") if header else 7]
    if np.any(np.abs(twist) > 90):
        i = int(np.argmax(np.abs(twist) > 90))
        raise GeometryFileError(f"{where}, line {row_lines[i]}: TWIST = {twist[i]:g} deg is outside [-90, 90] deg")
    station, chord = data[:, 0], data[:, 1]
    # RADIUS is printed rounded (42x2-PERF.PE0: RADIUS 2.09 and a last STATION 2.0915 in): a station
    # beyond it by up to half its last printed digit is the tip, and the radius is taken there
    digits = r_raw.split(".")[1] if "." in r_raw and r_raw.split(".")[1].isdigit() else ""
    rounding = 0.5 * 10.0 ** -len(digits) if digits else 0.0
    # (at exactly half a digit too: 2.09 + 0.005 is 2.0949999999999998 in floating point)
    if radius_in < station[-1] <= radius_in + rounding * (1 + 1e-9):
        radius_in = float(station[-1])
    for label, values, (lo, hi) in (("STATION", station, (0.0, radius_in * (1 + 1e-9))),
                                    ("CHORD", chord, (0.0, radius_in))):
        bad = ~((values >= lo) & (values <= hi)) | ((values == 0) & (label == "STATION"))
        if bad.any():
            i = int(np.argmax(bad))
            raise GeometryFileError(f"{where}, line {row_lines[i]}: {label} = {values[i]:g} in is outside "
                                    f"{'(0' if label == 'STATION' else '[0'}, {radius_in:g}] in (RADIUS)")
    if np.any(chord[:-1] <= 0):  # (as a QPROP file's rule: a 0 chord inside the blade was read unsaid, a file audit)
        i = int(np.argmax(chord[:-1] <= 0))
        raise GeometryFileError(f"{where}, line {row_lines[i]}: CHORD = {chord[i]:g} in at STATION {station[i]:g} in: "
                                "a chord must be > 0 (>= 0 at the last station, the tip)")
    if np.any(np.diff(station) <= 0):
        i = int(np.argmax(np.diff(station) <= 0)) + 1
        raise GeometryFileError(f"{where}, line {row_lines[i]}: STATION = {station[i]:g} in does not increase "
                                f"(previous {station[i - 1]:g} in)")
    R = radius_in * INCH
    pitch = float(np.median(data[:, 2])) * INCH  # QUOTED pitch column [in]
    _refuse_short_blade(where, station / radius_in)
    try:
        prop = Propeller(name=name or path.name.replace("-PERF.PE0", ""), radius=R, n_blades=n_blades,
                         r=data[:, 0] * INCH, chord=data[:, 1] * INCH, theta=np.radians(twist),
                         pitch=pitch, source=source or f"APC Propellers PE0 geometry file {path.name}")
    except ValueError as exc:
        raise GeometryFileError(f"{where}: {exc}") from None
    _warn_partial_blade(where, station / radius_in)
    return prop
