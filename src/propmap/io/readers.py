"""Readers for propeller geometry and measurement files.

* UIUC Propeller Data Site (Brandt & Selig, AIAA 2011-1255) geometry ``r/R c/R beta``,
  static ``RPM CT CP`` and wind-tunnel ``J CT CP eta`` files.
* APC Propellers PE0 geometry files (APC "Technical Information", v2022-0915).

Every reader raises :class:`GeometryFileError` / :class:`MeasurementFileError` (both
ValueError) with a one-line message naming the file, the line where known and, for a value
out of range, the valid range; no other exception escapes for any file content, and none
modifies its input.

Input files, here and in the other readers of the package (parameter and vehicle TOML,
identification CSVs), are read through :func:`read_input_bytes` and
:func:`decode_input_text`: only regular files (a directory, a device such as
``/dev/zero``, a pipe or a socket is refused before anything is read), at most
:data:`MAX_FILE_BYTES` (data CSVs) or :data:`MAX_SMALL_FILE_BYTES` (geometry, UIUC
measurement and TOML files), UTF-8 with or without a byte-order mark (UIUC and APC files
also Latin-1), never UTF-16 or binary (NUL bytes).

Valid ranges of the values read (a value outside is refused, naming the line):

========================  ====================================================
UIUC geometry             r/R in (0, 1], c/R in [0, 1], beta in [-90, 90] deg
UIUC static / sweep       RPM in (0, 954929] (the solver's 1e5 rad/s), CT and CP in
                          [-10, 10], J in [0, 20], eta finite
APC PE0                   RADIUS in [0.25, 50] in, BLADES an integer in [1, 100],
                          TWIST in [-90, 90] deg, every table value finite
diameter from the name    in [0.5, 100] in
========================  ====================================================

Diameters in file names: UIUC names are ``<family>_<D>x<P>``, D and P in inches, except
the families whose sizes are in millimetres (:data:`MM_FAMILIES`: ``ef``, ``kpf``, ``pl``,
``vp``, e.g. ``ef_130x70`` is 130 mm = 5.118 in). :func:`read_uiuc_geometry` reads those
as millimetres, says so in ``Propeller.source`` and warns (``UserWarning``).
"""

from __future__ import annotations

import codecs
import io
import math
import numbers
import os
import re
import stat
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.geometry import INCH, Propeller

__all__ = [
    "GeometryFileError",
    "MeasurementFileError",
    "read_uiuc_geometry",
    "read_apc_pe0",
    "read_geometry",
    "read_uiuc_static",
    "read_uiuc_sweep",
    "StaticRun",
    "Sweep",
    "looks_like_uiuc",
    "read_input_bytes",
    "decode_input_text",
    "show_path",
    "parse_number",
    "MAX_FILE_BYTES",
    "MAX_SMALL_FILE_BYTES",
    "RPM_MAX",
    "MM_FAMILIES",
]


class GeometryFileError(ValueError):
    """A geometry file is malformed; the message names the file and the problem."""


class MeasurementFileError(ValueError):
    """A measurement file is malformed; the message names the file and the problem."""


#: the largest data file (loads and level-flight CSVs) a reader accepts [bytes]
MAX_FILE_BYTES = 200 * 1024 * 1024
#: the largest geometry, UIUC measurement or TOML file a reader accepts [bytes]; such
#: files are a few kB
MAX_SMALL_FILE_BYTES = 16 * 1024 * 1024
#: the largest rotation rate in a measurement file [rpm]: the solver's 1e5 rad/s
RPM_MAX = 954929.0
#: UIUC families whose file names give the diameter and pitch in millimetres
_SIZE_HINT = ("give diameter_in (--diameter-in; a vehicle file's rotor takes the size from a file name "
              "<family>_<D>x<P>_geom.txt: D in inches, in mm for the ef, kpf, pl and vp families)")
MM_FAMILIES = frozenset({"ef", "kpf", "pl", "vp"})
#: plausible diameters derived from a file name [in]
NAME_DIAMETER_RANGE_IN = (0.5, 100.0)


# --- reading input files safely --------------------------------------------------------

def show_path(path) -> str:
    """``path`` as text for a one-line message (quoted if it holds control characters)."""
    s = os.fsdecode(path) if isinstance(path, (bytes, os.PathLike)) else str(path)
    return s if s.isprintable() else repr(s)


def _clip(text: str, n: int = 60) -> str:
    """``repr(text)`` cut to about ``n`` characters (for echoing user input in messages)."""
    r = repr(text)
    return r if len(r) <= n else r[: n - 5] + "...'" + f" ({len(text)} characters)"


def _mb(n: int) -> str:
    return f"{n / 2**20:.0f} MiB" if n >= 2**20 else f"{n} bytes"


def read_input_bytes(path, error: type[ValueError], *, limit: int = MAX_FILE_BYTES) -> bytes:
    """The content of the regular file ``path``, refusing anything else.

    Parameters
    ----------
    path : str or PathLike
    error : ValueError subclass
        Raised with a one-line message naming the file.
    limit : int
        Largest size accepted [bytes].

    Returns
    -------
    bytes

    Raises
    ------
    error
        No such file, a directory, not a regular file (a device such as ``/dev/zero``, a
        pipe, a socket: refused before reading, so never a hang), larger than ``limit``, a
        name the OS cannot represent, or unreadable (permissions, I/O error).
    """
    name = show_path(path)
    try:
        fspath = os.fspath(path)
    except TypeError:
        raise error(f"{name}: not a file path") from None
    try:
        st = os.stat(fspath)
    except FileNotFoundError:
        raise error(f"{name}: no such file") from None
    except OSError as exc:
        raise error(f"{name}: cannot read ({exc.strerror or type(exc).__name__})") from None
    except ValueError:
        raise error(f"{name}: not a valid file name (it contains a NUL character)") from None
    _check_stat(st, name, error, limit)
    # O_NONBLOCK: if the name was swapped for a pipe after the stat, opening it does not block
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(fspath, flags)
    except OSError as exc:
        raise error(f"{name}: cannot read ({exc.strerror or type(exc).__name__})") from None
    try:
        _check_stat(os.fstat(fd), name, error, limit)
        with os.fdopen(fd, "rb", closefd=True) as fh:
            fd = None
            data = fh.read(limit + 1)
    except OSError as exc:
        raise error(f"{name}: cannot read ({exc.strerror or type(exc).__name__})") from None
    finally:
        if fd is not None:
            os.close(fd)
    if len(data) > limit:
        raise error(f"{name}: larger than {_mb(limit)}, the limit for this kind of file")
    return data


def _check_stat(st, name: str, error, limit: int) -> None:
    if stat.S_ISDIR(st.st_mode):
        raise error(f"{name}: is a directory, not a file")
    if not stat.S_ISREG(st.st_mode):
        raise error(f"{name}: not a regular file (a device, pipe or socket); give a file")
    if st.st_size > limit:
        raise error(f"{name}: {_mb(st.st_size)} is larger than {_mb(limit)}, the limit for this kind of file")


def decode_input_text(raw: bytes, path, error: type[ValueError], *, latin1: bool = False) -> str:
    """Decode an input file: UTF-8 (a leading byte-order mark is dropped).

    Parameters
    ----------
    raw : bytes
    path : str or PathLike
        Named in messages.
    error : ValueError subclass
    latin1 : bool
        Fall back to Latin-1 for text that is not UTF-8 (legacy UIUC and APC files).

    Returns
    -------
    str

    Raises
    ------
    error
        UTF-16 or UTF-32 text, bytes that are not UTF-8 (without ``latin1``; the message
        gives the line and the byte), or NUL bytes (a binary file).
    """
    name = show_path(path)
    if raw.startswith((codecs.BOM_UTF32_LE, codecs.BOM_UTF32_BE)):
        raise error(f"{name}: UTF-32 text; save it as UTF-8")
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        raise error(f"{name}: UTF-16 text; save it as UTF-8")
    if b"\x00" in raw:
        line = _line_of(raw, raw.index(b"\x00"))
        raise error(f"{name}, line {line}: NUL byte: a binary file, not text")
    skip = len(codecs.BOM_UTF8) if raw.startswith(codecs.BOM_UTF8) else 0
    body = memoryview(raw)[skip:]  # no copy of a large file
    try:
        return str(body, "utf-8")
    except UnicodeDecodeError as exc:
        if latin1:
            return str(body, "latin-1")
        at = exc.start + skip
        line = _line_of(raw, at)
        col = at - max(raw.rfind(b"\n", 0, at), raw.rfind(b"\r", 0, at))
        raise error(f"{name}, line {line}: byte 0x{raw[at]:02x} (byte {col} of the line) is not UTF-8; "
                    "save the file as UTF-8") from None


def _line_of(text, pos: int) -> int:
    """The line number (from 1) of position ``pos`` in ``text`` (str or bytes), for LF, CRLF or CR line ends."""
    lf, cr, crlf = ("\n", "\r", "\r\n") if isinstance(text, str) else (b"\n", b"\r", b"\r\n")
    return text.count(lf, 0, pos) + text.count(cr, 0, pos) - text.count(crlf, 0, pos) + 1


def parse_number(text: str) -> float:
    """``float(text)`` for plain ASCII decimal numbers only.

    Python's ``float`` also takes ``1_000`` and non-ASCII digits; a data file should not.
    ``nan`` and ``inf`` parse (the caller refuses non-finite values with its own message).

    Raises
    ------
    ValueError
        Not a number.
    """
    s = text.strip()
    if not s.isascii() or "_" in s:
        raise ValueError(text)
    return float(s)


def _read_text(path, error, *, latin1: bool = True) -> str:
    return decode_input_text(read_input_bytes(path, error, limit=MAX_SMALL_FILE_BYTES), path, error, latin1=latin1)


# --- whitespace tables (UIUC) -------------------------------------------------------------

_KEY_RE = re.compile(r"[A-Za-z][A-Za-z0-9 _./()-]*")
_VALUE_RE = re.compile(r"[-+0-9.eE]+")
_SEP_RE = re.compile(r"[=:]")


def _meta(line: str) -> tuple[str, str] | None:
    """``(key, value)`` of a ``key = value`` / ``key: value`` line with a numeric-looking value."""
    m = _SEP_RE.search(line)
    if not m:
        return None
    key, value = line[: m.start()].strip(), line[m.end():].strip()
    if _KEY_RE.fullmatch(key) and _VALUE_RE.fullmatch(value):
        return key, value
    return None


@dataclass
class _Table:
    data: np.ndarray  # (k, n)
    lines: np.ndarray  # (k,) line number of each row
    meta: dict  # key -> (raw value, line)


def _read_table(path: Path, text: str, expected: list[str], error) -> _Table:
    """Numeric rows of a whitespace table whose header starts with ``expected``.

    Lines before the header and ``key = value`` lines anywhere (e.g. UIUC's
    ``RPM average = 4042``) are metadata; any other line that is not numeric is an error
    naming the file and the line. Every value must be a finite number.
    """
    name = show_path(path)
    meta: dict[str, tuple[str, int]] = {}
    want = [e.lower() for e in expected]
    start = None
    first = ""
    lines = io.StringIO(text, newline=None)
    k = 0
    for k, ln in enumerate(lines, start=1):
        ln = ln.rstrip("\n")
        if not ln or ln.isspace():
            continue
        if not first:
            first = ln.strip()
        m = _meta(ln)
        if m:
            meta[m[0]] = (m[1], k)
            continue
        if [h.lower() for h in ln.split()[: len(expected)]] == want:
            start = k
            break
    if start is None:
        if not first:
            raise error(f"{name}: empty file")
        raise error(f"{name}: expected columns {' '.join(expected)}, found header {_clip(first)}")
    rows, where = [], []
    n = len(expected)
    for k, ln in enumerate(lines, start=start + 1):
        ln = ln.rstrip("\n")
        if not ln or ln.isspace():
            continue
        m = _meta(ln)
        if m:
            meta[m[0]] = (m[1], k)
            continue
        parts = ln.split()
        if len(parts) < n:
            raise error(f"{name}, line {k}: expected {n} columns, found {len(parts)}")
        vals = []
        for j, x in enumerate(parts[:n]):
            try:
                v = parse_number(x)
            except ValueError:
                raise error(f"{name}, line {k}: non-numeric value {_clip(x, 40)} in column "
                            f"{expected[j]}") from None
            if not math.isfinite(v):
                raise error(f"{name}, line {k}: non-finite value {_clip(x, 40)} in column {expected[j]}")
            vals.append(v)
        rows.append(vals)
        where.append(k)
    if not rows:
        raise error(f"{name}: no data rows")
    return _Table(np.array(rows, dtype=float), np.array(where), meta)


def _check_column(table: _Table, j: int, label: str, lo: float, hi: float, path, error, *,
                  lo_open: bool = False, unit: str = "") -> None:
    """Refuse the first value of column ``j`` outside [lo, hi] (or (lo, hi]), naming its line."""
    x = table.data[:, j]
    bad = (x > hi) | ((x <= lo) if lo_open else (x < lo))
    if bad.any():
        i = int(np.argmax(bad))
        rng = f"{'(' if lo_open else '['}{lo:g}, {hi:g}]{' ' + unit if unit else ''}"
        raise error(f"{show_path(path)}, line {int(table.lines[i])}: {label} = {x[i]:g} is outside {rng}")


# --- geometry -------------------------------------------------------------------------------

_NAME_RE = re.compile(r"(?P<D>\d+(?:\.\d+)?)x(?P<P>\d+(?:\.\d+)?)", re.ASCII)


def _size_from_name(name: str) -> tuple[float | None, float | None, str, str]:
    """(diameter, pitch, unit, family) from ``<family>_<D>x<P>``; unit ``"in"``, or ``"mm"`` for MM_FAMILIES."""
    m = _NAME_RE.search(name)
    if not m:
        return None, None, "in", ""
    family = name[: m.start()].rstrip("_").split("_")[-1]
    return float(m["D"]), float(m["P"]), ("mm" if family.lower() in MM_FAMILIES else "in"), family


def _check_number(value, label: str, error, where: str, *, integer: bool = False) -> None:
    ok = (isinstance(value, numbers.Integral) if integer else isinstance(value, numbers.Real))
    if isinstance(value, (bool, np.bool_)) or not ok:
        kind = "an integer" if integer else "a number"
        raise error(f"{where}: {label} must be {kind}, got {value!r}"[:300])


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
        deg, radii not strictly increasing, fewer than 2 stations, a bad ``diameter_in``
        or ``n_blades``, or no diameter given or plausibly derivable from the name (the
        message suggests ``--diameter-in``); each message names the file and the line.

    Warns
    -----
    UserWarning
        The diameter was read in millimetres from the name; or the blade angles look like
        radians (every one below 1.6, and read as radians they make a near-constant pitch
        r tan(beta) over 0.3-1 R, as propellers have); they are read as degrees. A rotor's
        small, nearly untwisted angles in degrees (a collective given separately) do not
        warn.
    """
    text = _read_text(path, GeometryFileError)
    return _uiuc_geometry(Path(path), text, diameter_in=diameter_in, n_blades=n_blades, name=name, source=source)


def _uiuc_geometry(path: Path, text: str, *, diameter_in, n_blades, name, source) -> Propeller:
    where = show_path(path)
    table = _read_table(path, text, ["r/R", "c/R", "beta"], GeometryFileError)
    _check_column(table, 0, "r/R (station radius / tip radius)", 0.0, 1.0, path, GeometryFileError, lo_open=True)
    _check_column(table, 1, "c/R", 0.0, 1.0, path, GeometryFileError)
    _check_column(table, 2, "beta", -90.0, 90.0, path, GeometryFileError, unit="deg")
    data = table.data
    stem = path.name.replace("_geom.txt", "")
    D_name, P_name, unit, family = _size_from_name(stem)
    note = ""
    if diameter_in is None:
        if D_name is None:
            raise GeometryFileError(f"{where}: diameter unknown; {_SIZE_HINT}")
        lo, hi = NAME_DIAMETER_RANGE_IN
        diameter_in = D_name / 25.4 if unit == "mm" else D_name
        if not (lo <= diameter_in <= hi):
            raise GeometryFileError(
                f"{where}: diameter {D_name:g} {unit} from the file name is not plausible (a diameter from a name "
                f"must be in [{lo:g}, {hi:g}] in); {_SIZE_HINT}")
        if unit == "mm":
            note = (f"diameter {D_name:g} mm = {diameter_in:.4g} in from the file name (UIUC family "
                    f"{family!r} gives sizes in millimetres)")
            warnings.warn(f"{where}: {note}; if that is wrong, {_SIZE_HINT}", UserWarning,
                          stacklevel=3)
    else:
        _check_number(diameter_in, "diameter_in", GeometryFileError, where)
        try:
            ok = math.isfinite(float(diameter_in)) and diameter_in > 0
        except OverflowError:  # an int too large for a float
            ok = False
        if not ok:
            raise GeometryFileError(f"{where}: diameter_in must be finite and > 0 in, got {_clip(str(diameter_in))}")
    pitch_in = None
    if P_name is not None:
        pitch_in = P_name / 25.4 if unit == "mm" else P_name
        if not (math.isfinite(pitch_in) and 0 < pitch_in <= 10 * NAME_DIAMETER_RANGE_IN[1]):
            pitch_in = None  # catalogue information only: an implausible one is dropped
    if _looks_like_radians(data[:, 0], data[:, 2]):
        warnings.warn(f"{where}: every blade angle beta is below 1.6 in magnitude: the column looks like radians, "
                      "but UIUC geometry files give degrees (read as degrees)", UserWarning, stacklevel=3)
    R = 0.5 * float(diameter_in) * INCH
    src = source or f"UIUC Propeller Data Site geometry file {path.name}"
    if note:
        src = f"{src}; {note}"
    try:
        return Propeller(name=name or stem, radius=R, n_blades=n_blades, r=data[:, 0] * R,
                         chord=data[:, 1] * R, theta=np.radians(data[:, 2]),
                         pitch=None if pitch_in is None else pitch_in * INCH, source=src)
    except ValueError as exc:
        raise GeometryFileError(f"{where}: {exc}") from None


#: the coefficient of variation of r tan(beta) over 0.3-1 R below which radian-valued blade
#: angles make a propeller's near-constant pitch (the 108 catalogue propellers: <= 0.185;
#: an untwisted rotor: 0.32)
RADIANS_PITCH_CV = 0.25


def _looks_like_radians(r_over_R, beta) -> bool:
    """True when the blade-angle column is plausibly radians (see _uiuc_geometry's warning)."""
    if not np.all(np.abs(beta) < 1.6):
        return False
    outer = r_over_R >= 0.3
    if outer.sum() < 2 or np.any(beta[outer] <= 0):
        return False
    q = r_over_R[outer] * np.tan(beta[outer])
    return bool(np.std(q) < RADIANS_PITCH_CV * np.mean(q))


_PE0_RADIUS_IN = (0.25, 50.0)
_PE0_MAX_BLADES = 100


def read_apc_pe0(path, *, name: str | None = None, source: str = "") -> Propeller:
    """Read an APC PE0 geometry file (STATION [in], CHORD [in], ..., TWIST [deg]).

    The blade angle is APC's TWIST column (LE-TE datum); RADIUS and BLADES come from
    the file's summary lines.

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
        beyond RADIUS, negative chord).
    """
    text = _read_text(path, GeometryFileError)
    return _apc_pe0(Path(path), text, name=name, source=source)


def _pe0_summary(text: str, key: str, where: str) -> tuple[str, int]:
    m = re.search(rf"{key}:[ \t]*(\S*)", text)
    if not m:
        raise GeometryFileError(f"{where}: {key} line missing (RADIUS and BLADES are needed)")
    return m.group(1), _line_of(text, m.start())


def _apc_pe0(path: Path, text: str, *, name, source) -> Propeller:
    where = show_path(path)
    rows, row_lines, header = [], [], []
    in_table = False
    for k, ln in enumerate(io.StringIO(text, newline=None), start=1):
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
            if len(parts) >= 13 and vals:  # a station row (it starts with a number) with a bad value
                raise GeometryFileError(f"{where}, line {k}: non-numeric value {_clip(bad, 40)} in the station table")
            if rows:
                break
            continue  # the units line under the header
        if len(vals) >= 13:
            for j, v in enumerate(vals):
                if not math.isfinite(v):
                    col = header[j][:20] if j < len(header) else "?"
                    raise GeometryFileError(f"{where}, line {k}: column {j + 1} ({col}) is {_clip(parts[j], 40)}, "
                                            "not a finite number")
            rows.append(vals[:13])
            row_lines.append(k)
        elif rows:
            break
    if not rows:
        raise GeometryFileError(f"{where}: no STATION/CHORD/.../TWIST table found")
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
    data = np.array(rows)
    twist = data[:, 7]
    if np.any(np.abs(twist) > 90):
        i = int(np.argmax(np.abs(twist) > 90))
        raise GeometryFileError(f"{where}, line {row_lines[i]}: TWIST = {twist[i]:g} deg is outside [-90, 90] deg")
    station, chord = data[:, 0], data[:, 1]
    for label, values, (lo, hi) in (("STATION", station, (0.0, radius_in * (1 + 1e-9))),
                                    ("CHORD", chord, (0.0, radius_in))):
        bad = ~((values >= lo) & (values <= hi)) | ((values == 0) & (label == "STATION"))
        if bad.any():
            i = int(np.argmax(bad))
            raise GeometryFileError(f"{where}, line {row_lines[i]}: {label} = {values[i]:g} in is outside "
                                    f"{'(0' if label == 'STATION' else '[0'}, {radius_in:g}] in (RADIUS)")
    if np.any(np.diff(station) <= 0):
        i = int(np.argmax(np.diff(station) <= 0)) + 1
        raise GeometryFileError(f"{where}, line {row_lines[i]}: STATION = {station[i]:g} in does not increase "
                                f"(previous {station[i - 1]:g} in)")
    R = radius_in * INCH
    pitch = float(np.median(data[:, 2])) * INCH  # QUOTED pitch column [in]
    try:
        return Propeller(name=name or path.name.replace("-PERF.PE0", ""), radius=R, n_blades=int(b_raw),
                         r=data[:, 0] * INCH, chord=data[:, 1] * INCH, theta=np.radians(twist),
                         pitch=pitch, source=source or f"APC Propellers PE0 geometry file {path.name}")
    except ValueError as exc:
        raise GeometryFileError(f"{where}: {exc}") from None


def _is_uiuc_geometry(text: str) -> bool:
    for ln in io.StringIO(text[:65536], newline=None):
        words = ln.split()
        if not words or _meta(ln.rstrip("\n")):
            continue
        return words[0].lower() == "r/r"
    return False


def read_geometry(path, *, diameter_in: float | None = None, n_blades: int | None = None) -> Propeller:
    """Read a geometry file, choosing the reader by content (PE0 or UIUC ``r/R c/R beta``).

    Parameters
    ----------
    path : str or Path
    diameter_in : float, optional
        For a UIUC file (see :func:`read_uiuc_geometry`); a PE0 file gives its RADIUS, and
        a different ``diameter_in`` is refused.
    n_blades : int, optional
        Blade count: required for a UIUC file (which does not state it); a PE0 file's
        BLADES by default.

    Returns
    -------
    Propeller

    Raises
    ------
    GeometryFileError
        As the chosen reader; also if the file is not a readable regular file or the format
        is not recognised, or a UIUC file without ``n_blades``.

    Warns
    -----
    UserWarning
        As :func:`read_uiuc_geometry`.
    """
    path = Path(path)
    text = _read_text(path, GeometryFileError)
    head = text[:4000]
    if "STATION" in head and "TWIST" in head:
        prop = _apc_pe0(path, text, name=None, source="")
        if diameter_in is not None and not math.isclose(diameter_in, prop.diameter / 0.0254, rel_tol=1e-9):
            raise GeometryFileError(f"{show_path(path)}: diameter_in = {diameter_in:g} in, but a PE0 file gives its "
                                    f"own radius (diameter {prop.diameter / 0.0254:g} in); diameter_in applies to "
                                    "UIUC files")
        if n_blades is not None and n_blades != prop.n_blades:
            try:
                prop = Propeller(prop.name, prop.radius, n_blades, prop.r, prop.chord, prop.theta, prop.pitch,
                                 prop.source)
            except ValueError as exc:
                raise GeometryFileError(f"{show_path(path)}: {exc}") from None
        return prop
    if _is_uiuc_geometry(text):
        prop = _uiuc_geometry(path, text, diameter_in=diameter_in, n_blades=2 if n_blades is None else n_blades,
                              name=None, source="")  # the file's own errors first
        if n_blades is None:
            raise GeometryFileError(f"{show_path(path)}: a UIUC geometry file (r/R c/R beta) does not state the blade "
                                    "count: give it (--blades, n_blades); a wrong count scales the thrust (3 blades "
                                    "read as 2: -26% in hover)")
        return prop
    raise GeometryFileError(f"{show_path(path)}: unrecognised geometry format (expected UIUC 'r/R c/R beta' or an "
                            "APC PE0 file)")


# --- measurements ---------------------------------------------------------------------------

@dataclass(frozen=True)
class StaticRun:
    """A UIUC static test: CT, CP against rpm at V = 0.

    Attributes
    ----------
    run_id : str
    rpm, CT, CP : ndarray, shape (k,)
        Measured rotation rate [rpm] and propeller-convention coefficients.
    source : str
    """

    run_id: str
    rpm: np.ndarray
    CT: np.ndarray
    CP: np.ndarray
    source: str


@dataclass(frozen=True)
class Sweep:
    """A UIUC wind-tunnel advance-ratio sweep at a nominal rpm (axial flow).

    Attributes
    ----------
    run_id : str
    rpm : float
        Nominal rotation rate [rpm] (from the file name).
    J, CT, CP, eta : ndarray, shape (k,)
    source : str
    """

    run_id: str
    rpm: float
    J: np.ndarray
    CT: np.ndarray
    CP: np.ndarray
    eta: np.ndarray
    source: str


COEFFICIENT_MAX = 10.0
J_MAX = 20.0


def read_uiuc_static(path) -> StaticRun:
    """Read a UIUC static file (``RPM CT CP``).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    StaticRun

    Raises
    ------
    MeasurementFileError
        Not a readable regular file (or over 16 MiB), missing columns, non-numeric or
        non-finite values, RPM outside (0, 954929], CT or CP outside [-10, 10]; the
        message names the file and the line.
    """
    path = Path(path)
    t = _read_table(path, _read_text(path, MeasurementFileError), ["RPM", "CT", "CP"], MeasurementFileError)
    _check_column(t, 0, "RPM", 0.0, RPM_MAX, path, MeasurementFileError, lo_open=True)
    _check_column(t, 1, "CT", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    _check_column(t, 2, "CP", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    d = t.data
    run = path.stem.split("_static_")[-1]
    return StaticRun(run, d[:, 0], d[:, 1], d[:, 2], f"UIUC Propeller Data Site, {path.name}")


def read_uiuc_sweep(path) -> Sweep:
    """Read a UIUC wind-tunnel file ``<fam>_<D>x<P>_<run>_<RPM>.txt`` (``J CT CP eta``).

    The rotation rate is a ``RPM average = N`` line of the file when it has one (the
    measured mean), else the nominal rpm at the end of the file name. Other header and
    ``key = value`` lines are ignored.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    Sweep

    Raises
    ------
    MeasurementFileError
        Not a readable regular file (or over 16 MiB), bad columns, non-numeric or
        non-finite values, J outside [0, 20], CT or CP outside [-10, 10], or no rpm in
        (0, 954929] in the file or at the end of its name.
    """
    path = Path(path)
    where = show_path(path)
    t = _read_table(path, _read_text(path, MeasurementFileError), ["J", "CT", "CP", "eta"], MeasurementFileError)
    _check_column(t, 0, "J", 0.0, J_MAX, path, MeasurementFileError)
    _check_column(t, 1, "CT", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    _check_column(t, 2, "CP", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    d = t.data
    parts = path.stem.split("_")
    rpm_keys = ("rpmaverage", "averagerpm", "rpm")
    item = next(((k, v) for k, v in t.meta.items() if k.lower().replace(" ", "") in rpm_keys), None)
    if item is not None:
        key, (raw, line) = item
        what = f"{where}, line {line}: {key} = {_clip(raw, 40)}"
    else:
        raw = parts[-1]
        what = f"{where}: the rpm {_clip(raw, 40)} at the end of the file name"
    try:
        rpm = parse_number(raw)
    except ValueError:
        if item is not None:
            raise MeasurementFileError(f"{what} is not a number") from None
        raise MeasurementFileError(f"{where}: no rpm: neither an 'RPM average = N' line nor a nominal rpm at "
                                   "the end of the file name (<fam>_<D>x<P>_<run>_<RPM>.txt)") from None
    if not (math.isfinite(rpm) and 0 < rpm <= RPM_MAX):
        raise MeasurementFileError(f"{what} is outside (0, {RPM_MAX:.0f}] rpm")
    run = parts[-2] if len(parts) >= 2 else path.stem
    return Sweep(run, rpm, d[:, 0], d[:, 1], d[:, 2], d[:, 3], f"UIUC Propeller Data Site, {path.name}")


def looks_like_uiuc(path) -> bool:
    """Whether ``path`` is a UIUC-format static (``RPM CT CP``) or wind-tunnel (``J CT CP eta``) file.

    Reads at most the first 64 KiB of a regular file (never a device or a pipe).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    bool
        False for anything that is not a readable regular file; never raises.
    """
    try:
        fspath = os.fspath(path)
        if not stat.S_ISREG(os.stat(fspath).st_mode):
            return False
        fd = os.open(fspath, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
        with os.fdopen(fd, "rb") as fh:
            if not stat.S_ISREG(os.fstat(fh.fileno()).st_mode):
                return False
            raw = fh.read(65536)
    except (OSError, TypeError, ValueError):
        return False
    if raw.startswith(codecs.BOM_UTF8):
        raw = raw[3:]
    head = raw.decode("latin-1")
    for ln in head.splitlines()[:50]:
        words = [w.lower() for w in ln.split()]
        if words[:3] == ["rpm", "ct", "cp"] or words[:4] == ["j", "ct", "cp", "eta"]:
            return True
    return False
