"""Reading input files safely, and the whitespace tables of UIUC files.

Every input file of the package (geometry and measurement files, parameter and vehicle
TOML, identification CSVs, flight logs) is read through :func:`read_input_bytes` and
:func:`decode_input_text`: only regular files (a directory, a device such as ``/dev/zero``,
a pipe or a socket is refused before anything is read), at most :data:`MAX_FILE_BYTES`
(data CSVs) or :data:`MAX_SMALL_FILE_BYTES` (geometry, UIUC measurement and TOML files),
UTF-8 with or without a byte-order mark (UIUC and APC files also Latin-1), never UTF-16 or
binary (NUL bytes). Errors are the caller's ValueError subclass, one line naming the file.
"""

from __future__ import annotations

import codecs
import io
import math
import numbers
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core._numbers import real

__all__ = ["MAX_FILE_BYTES", "MAX_SMALL_FILE_BYTES", "show_path", "short_path", "read_input_bytes", "decode_input_text",
           "parse_number", "header_separator", "SEPARATORS"]

#: the largest data file (loads and level-flight CSVs) a reader accepts [bytes]
MAX_FILE_BYTES = 200 * 1024 * 1024
#: the largest geometry, UIUC measurement or TOML file a reader accepts [bytes]; such
#: files are a few kB
MAX_SMALL_FILE_BYTES = 16 * 1024 * 1024


def show_path(path) -> str:
    """``path`` as text for a one-line message (quoted if it holds control characters).

    Parameters
    ----------
    path : str, bytes or PathLike
        Bytes and path objects are decoded with the file-system encoding
        (``os.fsdecode``); anything else is ``str(path)``.

    Returns
    -------
    str
        The path as written, or its ``repr`` where it is not printable (a newline, a
        terminal escape).
    """
    s = _path_text(path)
    return s if s.isprintable() else repr(s)


def _path_text(path) -> str:
    """``path`` as text: bytes and path objects decoded with the file-system encoding."""
    return os.fsdecode(path) if isinstance(path, (bytes, os.PathLike)) else str(path)


def short_path(path, n: int = 80, *, quote: bool = False) -> str:
    """``path`` as :func:`show_path` gives it, cut to at most ``n`` characters in its middle.

    The end of a path, the file's name, is what a message must show: a path longer than ``n``
    keeps its first quarter and its end with "..." between (``/home/alice/...
    /campaign_3/maps/apce_10x7.nc``), where cutting its end lost the name (``.../maps/apce_10``
    in messages before 2026-11-28).

    Parameters
    ----------
    path : str, bytes or PathLike
    n : int
        The longest text returned, at least 8.
    quote : bool
        The path's ``repr`` (quoted, control characters escaped) in every case, cut likewise.

    Returns
    -------
    str
        The path as written where it fits, else its first ``(n - 3) // 4`` characters, "..."
        and its last ones, ``n`` characters in all.

    Raises
    ------
    ValueError
        ``n`` below 8.
    """
    if n < 8:
        raise ValueError(f"n must be at least 8 (characters), got {n!r}")
    s = repr(_path_text(path)) if quote else show_path(path)
    if len(s) <= n:
        return s
    head = (n - 3) // 4
    return s[:head] + "..." + s[len(s) - (n - 3 - head):]


def as_path(path, name: str = "path") -> Path:
    """``path`` (str or PathLike) as a Path (pathlib's own error said "expected str, bytes or
    os.PathLike object, not NoneType", naming nothing).

    Parameters
    ----------
    path : str or os.PathLike
    name : str
        The argument's name, for the message.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"{name} must be a file path (str or os.PathLike), got {type(path).__name__}")
    return Path(path)


def _clip(text: str, n: int = 60) -> str:
    """``repr(text)`` cut to about ``n`` characters (for echoing user input in messages)."""
    r = repr(text)
    return r if len(r) <= n else r[: n - 5] + "...'" + f" ({len(text)} characters)"


def _mb(n: int) -> str:
    return f"{n / 2**20:.0f} MiB" if n >= 2**20 else f"{n} bytes"


def read_input_bytes(path, error: type[ValueError], *, limit: int = MAX_FILE_BYTES, too_large: str = "") -> bytes:
    """The content of the regular file ``path``, refusing anything else.

    Parameters
    ----------
    path : str or PathLike
    error : ValueError subclass
        Raised with a one-line message naming the file.
    limit : int
        Largest size accepted [bytes].
    too_large : str
        Appended to the message of a file over ``limit`` (what to do instead).

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
    _check_stat(st, name, error, limit, too_large)
    # O_NONBLOCK: if the name was swapped for a pipe after the stat, opening it does not block
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(fspath, flags)
    except OSError as exc:
        raise error(f"{name}: cannot read ({exc.strerror or type(exc).__name__})") from None
    try:
        _check_stat(os.fstat(fd), name, error, limit, too_large)
        with os.fdopen(fd, "rb", closefd=True) as fh:
            fd = None
            data = fh.read(limit + 1)
    except OSError as exc:
        raise error(f"{name}: cannot read ({exc.strerror or type(exc).__name__})") from None
    finally:
        if fd is not None:
            os.close(fd)
    if len(data) > limit:
        raise error(f"{name}: larger than {_mb(limit)}, the limit for this kind of file{too_large}")
    return data


def _check_stat(st, name: str, error, limit: int, too_large: str = "") -> None:
    if stat.S_ISDIR(st.st_mode):
        raise error(f"{name}: is a directory, not a file")
    if not stat.S_ISREG(st.st_mode):
        raise error(f"{name}: not a regular file (a device, pipe or socket); give a file")
    if st.st_size > limit:
        raise error(f"{name}: {_mb(st.st_size)} is larger than {_mb(limit)}, the limit for this kind of file"
                    f"{too_large}")


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
        gives the line and the byte, and the error's attribute ``not_utf8`` is True, for a
        caller that falls back to another encoding), or NUL bytes (a binary file).
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
        refused = error(f"{name}, line {line}: byte 0x{raw[at]:02x} (byte {col} of the line) is not UTF-8; "
                        "save the file as UTF-8")
        refused.not_utf8 = True  # (structured: a caller's fallback to another encoding decides on it, not the text)
        raise refused from None


def _line_of(text, pos: int) -> int:
    """The line number (from 1) of position ``pos`` in ``text`` (str or bytes), for LF, CRLF or CR line ends."""
    lf, cr, crlf = ("\n", "\r", "\r\n") if isinstance(text, str) else (b"\n", b"\r", b"\r\n")
    return text.count(lf, 0, pos) + text.count(cr, 0, pos) - text.count(crlf, 0, pos) + 1


#: the separators a header line may use, in the order that breaks a tie (a comma first)
SEPARATORS = (",", ";", "\t")


def header_separator(line: str, row: str | None = None) -> str:
    """The separator of a CSV from its header line (and its first data row).

    Parameters
    ----------
    line : str
        The header line (column names).
    row : str, optional
        The first data row: where given, only a separator that occurs in the header as often
        as in it is a candidate (names with a unit after a comma, ``Speed, rev/min;Thrust, N``
        in a ';'-separated file, or ``Thrust, N`` in a tab-separated one, were split at their
        commas: an audit of thrust-stand exports, 2026-11-27), unless none is.

    Returns
    -------
    str
        The most frequent candidate of ``','``, ``';'`` (spreadsheets in locales with a decimal
        comma) and a tab; a tie of ``';'`` and ``','`` gives ``';'`` (names such as ``Thrust, N``
        hold a comma, few a semicolon), any other tie (a one-column header included) the comma.
        Where both ``';'`` and ``','`` occur in the row as often as in the header, ``';'`` is
        taken, however many commas there are (``Zeit, s;Drehzahl, U/min`` over ``1,5;3000,5``:
        each name's unit and each value's decimal comma; it was split at the commas, 2026-11-29).
    """
    counts = {c: line.count(c) for c in SEPARATORS}
    both = [c for c in SEPARATORS if counts[c] and row is not None and row.count(c) == counts[c]]
    if ";" in both and "," in both:  # (every name 'Drehzahl, U/min' and every value '3000,5': a ';' file)
        both.remove(",")
    return max(both or SEPARATORS, key=lambda c: (counts[c], c == ";" and counts[c] > 0, c == ","))


def parse_number(text: str) -> float:
    """``float(text)`` for plain ASCII decimal numbers only.

    Python's ``float`` also takes ``1_000`` and non-ASCII digits; a data file should not.
    ``nan`` and ``inf`` parse (the caller refuses non-finite values with its own message).

    Parameters
    ----------
    text : str
        One field; surrounding whitespace is ignored.

    Returns
    -------
    float

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


#: other spellings of a table column's name in a header (UIUC-like files written by other tools: 'eff' for eta,
#: 'beta(deg)' for beta; refused as another header until 2026-11-30, a UIUC file audit)
TABLE_ALIASES = {"eta": ("eff", "efficiency"),
                 "beta": ("beta(deg)", "beta[deg]", "beta_deg", "beta(°)", "beta[°]", "beta°")}


def _read_table(path: Path, text: str, expected: list[str], error) -> _Table:
    """Numeric rows of a whitespace table whose header starts with ``expected`` (a name or one
    of its :data:`TABLE_ALIASES`, in any case).

    Lines before the header and ``key = value`` lines anywhere (e.g. UIUC's
    ``RPM average = 4042``) are metadata, lines starting with ``#`` comments; any other line
    that is not numeric, or has more fields than the header, is an error naming the file and
    the line. Every value must be a finite number. Where no line is that header, the error
    raised carries the file's first non-blank line as its ``found_header`` attribute.
    """
    name = show_path(path)
    meta: dict[str, tuple[str, int]] = {}
    want = [{e.lower(), *TABLE_ALIASES.get(e.lower(), ())} for e in expected]
    start = None
    first = ""
    lines = io.StringIO(text, newline=None)
    k = 0
    numeric_above = 0  # (the first line of numbers above the header, 0: none)
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
        head = [h.lower() for h in ln.split()[: len(expected)]]
        if len(head) == len(want) and all(h in w for h, w in zip(head, want)):
            start, width = k, len(ln.split())
            break
        if not numeric_above and _all_numbers(ln.split(), len(expected)):
            numeric_above = k
    if start is not None and numeric_above:
        # (rows above the header were skipped as a title: a geometry's nine hub stations lost, 35% less thrust, and a
        # sweep's five points, without a word; a UIUC file audit, 2026-12-01)
        raise error(f"{name}, line {numeric_above}: a row of numbers above the header line {start} "
                    f"({' '.join(expected)}): the header comes first, then every row")
    if start is None:
        if not first:
            raise error(f"{name}: empty file")
        exc = error(f"{name}: expected columns {' '.join(expected)}, found header {_clip(first)}")
        exc.found_header = _clip(first)  # (structured: a caller decides on it, not on the message's text)
        raise exc
    rows, where = [], []
    n = len(expected)
    for k, ln in enumerate(lines, start=start + 1):
        ln = ln.rstrip("\n")
        if not ln or ln.isspace() or ln.lstrip().startswith("#"):
            continue
        m = _meta(ln)
        if m:
            meta[m[0]] = (m[1], k)
            continue
        parts = ln.split()
        if len(parts) < n:
            raise error(f"{name}, line {k}: expected {n} columns, found {len(parts)}")
        if len(parts) > width:  # (a value split by a blank, 0 .0540, would shift the columns silently)
            raise error(f"{name}, line {k}: {len(parts)} fields where the header has {width} (a value split by a "
                        "blank?)")
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


def _all_numbers(parts: list, n: int) -> bool:
    """Whether ``parts`` holds at least ``n`` fields, each a number (:func:`parse_number`)."""
    if len(parts) < n:
        return False
    try:
        for x in parts:
            parse_number(x)
    except ValueError:
        return False
    return True


def _check_column(table: _Table, j: int, label: str, lo: float, hi: float, path, error, *,
                  lo_open: bool = False, unit: str = "") -> None:
    """Refuse the first value of column ``j`` outside [lo, hi] (or (lo, hi]), naming its line."""
    x = table.data[:, j]
    bad = (x > hi) | ((x <= lo) if lo_open else (x < lo))
    if bad.any():
        i = int(np.argmax(bad))
        rng = f"{'(' if lo_open else '['}{lo:g}, {hi:g}]{' ' + unit if unit else ''}"
        raise error(f"{show_path(path)}, line {int(table.lines[i])}: {label} = {x[i]:g} is outside {rng}")


def _check_number(value, label: str, error, where: str, *, integer: bool = False) -> None:
    ok = isinstance(value, numbers.Integral) if integer else real(value) is not None  # (a 0-d array too)
    if isinstance(value, (bool, np.bool_)) or not ok:
        kind = "an integer" if integer else "a number"
        raise error(f"{where}: {label} must be {kind}, got {value!r}"[:300])


def first_copy(paths):
    """The first of ``paths`` that is a file given before it under another name: the same file (a
    symbolic or a hard link, the same name again) or a byte-identical copy (SHA-256; only files
    that share a size are read).

    Parameters
    ----------
    paths : sequence of str or Path

    Returns
    -------
    tuple of (Path, str, Path) or None
        (the path, "the same file as" or "a copy of", the earlier path); None where every file
        is given once.

    Raises
    ------
    OSError
        A path that cannot be stat'ed or read (missing, unreadable).
    """
    import hashlib

    stats = [(Path(p), os.stat(p)) for p in paths]
    sizes = [st.st_size for _, st in stats]
    seen: dict = {}
    for p, st in stats:
        keys = [((st.st_dev, st.st_ino), "the same file as")]
        if sizes.count(st.st_size) > 1:  # (only files of one size can be copies: the others are not read twice)
            with open(p, "rb") as fh:
                keys.append((hashlib.file_digest(fh, "sha256").hexdigest(), "a copy of"))
        for key, what in keys:
            if key in seen:
                return p, what, seen[key]
            seen[key] = p
    return None
