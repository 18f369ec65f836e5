"""The ``--points`` file of ``propmap loads`` (cli/loads.py), read as a stream: its header (the
separator, the operating columns, each refusal of a file that cannot be read), its chunks of
checked rpm, airspeed, incidence_deg and collective_deg values, and the messages of a file or a
cell that does not parse.

A comma-, semicolon- or tab-separated UTF-8 file of at most MAX_POINTS_FILE_BYTES (2 GiB), its
header line at most MAX_HEADER_BYTES; column names matched in any case, with or without a unit
(:func:`propmap.identify.stand.map_operating_columns`). A ';'- or tab-separated file may have
decimal commas (a file with decimal commas and points is refused: a points file reads no
thousands separators, which the load files read since 2026-12-01, identify/csvfile.py); a cell
that is not a number is told its likely cause (a thousands separator, or a units row under the
header: stop 94's noticed-and-left); a thrust stand's export of measured loads, which lacks the
points' columns, is told the command that compares it with the model (a user-level audit,
2026-11-28).
"""

from __future__ import annotations

import re
from pathlib import Path

from ._common import AIRSPEED_MAX, NEGATIVE_INCIDENCE, RPM_MAX, RPM_MIN, InputError

INPUT_COLUMNS = ("rpm", "airspeed", "incidence_deg")
#: optional input column: the blade-angle offset of a variable-pitch rotor [deg]
COLLECTIVE_COLUMN = "collective_deg"
#: the largest collective [deg]: a points row's (with the parameter set's) and --collective-deg's (cli/loads.py)
COLLECTIVE_DEG_MAX = 45.0
MAX_POINTS_FILE_BYTES = 2 * 1024**3  # a points file larger than this is refused


#: the longest column name accepted in a points file [characters]
MAX_NAME = 255
MAX_HEADER_BYTES = 65536


def _points_reader(path: Path, chunksize: int):
    """(iterator of DataFrame chunks, column names, separator, operating columns) of the points
    CSV, all cells as text.

    Comma-, semicolon- or tab-separated (detected from the header), header names (quoted or
    not) matched case-insensitively after stripping blanks and a UTF-8 BOM, with or without a
    unit (:func:`propmap.identify.stand.map_operating_columns`: the operating columns map to
    (name, factor to rpm, m/s or deg)). Blank lines are kept as empty rows, so that a row's
    position gives its line number.

    Raises
    ------
    InputError
        Unreadable, not a regular file, too large, not text, a header over 64 KiB,
        duplicate, empty or over-long column names, or lacking the columns.
    """
    import warnings

    import pandas as pd

    where = f"--points: {path}"
    first, sep = _points_header(path, where)
    names, mapped = _points_columns(first, sep, where)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", pd.errors.ParserWarning)
            reader = pd.read_csv(path, sep=sep, encoding="utf-8-sig", dtype=str, keep_default_na=False,
                                 skip_blank_lines=False, header=0, index_col=False, chunksize=chunksize,
                                 names=[n or f"(unnamed {j})" for j, n in enumerate(names)])  # (pandas: unique)
    except (pd.errors.ParserError, pd.errors.ParserWarning, pd.errors.EmptyDataError, UnicodeDecodeError,
            ValueError) as exc:
        raise _parse_error(path, exc, sep, len(names)) from None
    return reader, names, sep, mapped


#: a number written with thousands separators ('12,000', '1,234.5'), which a points file does not read
_GROUPED = re.compile(r"[+-]?\d{1,3}(,\d{3})+(\.\d*)?")


def _cell_hint(cell: str, sep: str, first: bool) -> str:
    """The likely cause of a points cell that is not a number: thousands separators in a
    comma-separated file ('12,000', quoted), or, in the first row (``first``), a units row under
    the header ('m/s', 'deg'; the load files read both, the points file neither: stop 94's
    noticed-and-left)."""
    if sep == "," and _GROUPED.fullmatch(cell):
        return f" (a thousands separator? write {cell.replace(',', '')}: a points file is read without grouping)"
    if first and cell and not any(ch.isdigit() for ch in cell):
        return " (a units row? give each unit in its column's name, e.g. 'airspeed (m/s)', 'incidence (deg)')"
    return ""


def _points_header(path: Path, where: str) -> tuple[str, str]:
    """The points file's first line (decoded, without a UTF-8 BOM) and its separator; refuses a file
    that cannot be read, is not a regular file, too large, has NUL bytes (UTF-16), a header over
    MAX_HEADER_BYTES or a first line that is not UTF-8 (``where``: the option and file, for messages)."""
    from ..io.inputs import header_separator

    try:
        st = path.stat()
        regular = path.is_file()
    except (OSError, ValueError) as exc:
        raise InputError(f"{where}: cannot read ({getattr(exc, 'strerror', None) or exc})") from None
    if not regular:
        raise InputError(f"{where}: not a regular file")
    if st.st_size > MAX_POINTS_FILE_BYTES:
        raise InputError(f"{where}: {st.st_size} bytes; at most {MAX_POINTS_FILE_BYTES} are read")
    try:
        with open(path, "rb") as fh:
            head = fh.read(MAX_HEADER_BYTES + 1)
    except OSError as exc:
        raise InputError(f"{where}: cannot read ({exc.strerror})") from None
    if b"\x00" in head[:4096]:  # (UTF-16 without a byte-order mark decodes as UTF-8 with NULs: "lacks column(s)")
        utf16 = head[:2] in (b"\xff\xfe", b"\xfe\xff") or head[1:2] == b"\x00" or head[:1] == b"\x00"
        raise InputError(f"{where}: NUL bytes in the text" + ("; it looks like UTF-16" if utf16 else "")
                         + ": save the file as UTF-8 CSV")
    if b"\n" not in head and len(head) > MAX_HEADER_BYTES:
        raise InputError(f"{where}: the header line is longer than {MAX_HEADER_BYTES} bytes")
    try:
        first = re.split(rb"\r\n|\r|\n", head, maxsplit=1)[0].decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(f"{where}, line 1: byte 0x{exc.object[exc.start]:02x} is not UTF-8; save the file as "
                         "UTF-8 CSV") from None
    sep = header_separator(first, next((r.decode("utf-8-sig", "replace") for r in re.split(rb"\r\n|\r|\n", head)[1:9]
                                        if r.strip()), None))
    return first, sep


def _points_columns(first: str, sep: str, where: str) -> tuple[list[str], dict]:
    """The header's column names and the operating columns they map to
    (:func:`propmap.identify.stand.map_operating_columns`); refuses an empty header, an over-long,
    duplicate or missing column (naming what a stand's export of measured loads needs instead)."""
    import csv

    names = [h.strip() for h in next(csv.reader([first], delimiter=sep), [])]
    if not any(names):
        raise InputError(f"{where}: the first line is empty; it must name the columns")
    long = [n for n in names if len(n) > MAX_NAME]
    if long:
        raise InputError(f"{where}, line 1: a column name of {len(long[0])} characters (at most {MAX_NAME})")
    lower = [n.lower() for n in names]
    dup = sorted({n for n in lower if n and lower.count(n) > 1})  # (unnamed ones: checked for values per row)
    if dup:
        raise InputError(f"{where}: duplicate column(s) {', '.join(repr(d) for d in dup)}")
    from ..identify.stand import map_operating_columns, split_header

    try:
        mapped = map_operating_columns(names, error=InputError)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    missing = [c for c in INPUT_COLUMNS if c not in mapped]
    if missing:
        # (a thrust stand's export, rpm and loads only: `fit loads` takes it as static, --points asks for the points;
        # the measured loads against the model are `validate`'s: a user-level audit, 2026-11-28)
        measured = "rpm" in mapped and any(split_header(n)[0] in ("thrust", "torque", "drag") for n in names)
        raise InputError(f"{where}: lacks column(s) {', '.join(missing)} (needs {', '.join(INPUT_COLUMNS)}, any case, "
                         "with or without a unit: RPM, airspeed (m/s), airspeed_kmh, incidence (deg))"
                         + ("; a static stand's points have airspeed 0 and incidence_deg 0: add those columns, or "
                            "compare measured loads with the model by 'propmap validate FILE --prop P --params "
                            "SET'" if measured else ""))
    return names, mapped


def _long_row(path: Path, sep: str, width: int) -> str:
    """``"line N "`` of the first row with more than ``width`` fields ("a row " if none is
    found): pandas' warning does not say which (read again only on this error's path)."""
    import csv

    with open(path, encoding="utf-8-sig", newline="") as fh:
        fh.readline()  # the header, read by _points_reader
        rows = csv.reader(fh, delimiter=sep)
        for row in rows:
            if len(row) > width:
                return f"line {rows.line_num + 1} "  # + the header line; line_num counts physical lines
    return "a row "


def _parse_error(path: Path, exc: Exception, sep: str, width: int) -> InputError:
    if isinstance(exc, UnicodeDecodeError):
        return InputError(f"--points: {path}: not UTF-8 text (byte 0x{exc.object[exc.start]:02x}); "
                          "save it as UTF-8 CSV")
    if isinstance(exc, Warning):  # pandas' ParserWarning: a row with more fields than the header
        return InputError(f"--points: {path}: {_long_row(path, sep, width)}has more fields than the header")
    m = re.search(r"Expected (\d+) fields in line (\d+), saw (\d+)", str(exc))
    if m:  # (pandas' C parser: a row longer than the first data row, the header's width)
        return InputError(f"--points: {path}: line {m.group(2)} has {m.group(3)} fields, but the header has "
                          f"{m.group(1)}")
    return InputError(f"--points: {path}: cannot parse ({str(exc).splitlines()[0][:200]})")


def _chunks(path: Path, chunksize: int, offset_deg: float = 0.0, skipped: list | None = None):
    """Chunks of the points CSV: the cells as text, and rpm, airspeed, incidence_deg (and
    collective_deg where the file has it) as checked floats.

    Yields (DataFrame of the text as read, first line number, dict of the three float
    arrays); blank lines and rows of empty cells are dropped, and ``skipped`` (a list) receives the
    lines of those that lie before a data row. ``offset_deg``: the parameter set's collective [deg], added
    to each row's, the sum within [-COLLECTIVE_DEG_MAX, COLLECTIVE_DEG_MAX]. Raises InputError
    naming the line of the first bad value (line numbers count blank lines; a quoted field
    spanning lines shifts them) or the parse error.
    """
    import warnings

    import numpy as np
    import pandas as pd

    reader, names, sep, mapped = _points_reader(path, chunksize)
    from ..identify.cells import unnamed_columns, unnamed_value_message

    cols = {c: mapped[c][0] for c in INPUT_COLUMNS + (COLLECTIVE_COLUMN,) if c in mapped}
    unnamed = unnamed_columns(names)
    limits = {"rpm": (RPM_MIN, RPM_MAX), "airspeed": (0.0, AIRSPEED_MAX), "incidence_deg": (0.0, 180.0),
              COLLECTIVE_COLUMN: (-COLLECTIVE_DEG_MAX - offset_deg, COLLECTIVE_DEG_MAX - offset_deg)}
    line = 2
    rows = 0
    pending = []  # empty rows not yet followed by a data row (a file's trailing blank lines never are)
    marks = [None, None]  # a ';' file: where a decimal comma and a point were first seen, (line, column)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", pd.errors.ParserWarning)
            for df in reader:
                lines = line + np.arange(len(df))
                line += len(df)
                blank = (df == "").all(axis=1).to_numpy()
                if blank.any():
                    pending.extend(int(k) for k in lines[blank])
                    df, lines = df[~blank], lines[~blank]
                if len(df) and pending:  # (an empty row before a data row leaves no output row: the caller says so)
                    last = int(lines[-1])
                    if skipped is not None:
                        skipped.extend(k for k in pending if k < last)
                    pending = [k for k in pending if k > last]
                if len(df) == 0:
                    continue
                for j in unnamed:
                    held = (df.iloc[:, j].str.strip() != "").to_numpy()
                    if held.any():
                        i = int(np.argmax(held))
                        raise InputError(f"--points: {path}, line {lines[i]}: "
                                         + unnamed_value_message(j, df.iloc[i, j].strip(), sep, bool(names[j - 1])))
                values = {}
                for c, name in cols.items():
                    text = df[name].str.strip()
                    if sep != ",":
                        text = _decimal_commas(path, c, text, lines, marks)
                        # (echoed as read: the output is comma-separated with decimal points, and its '2,5' was
                        # quoted text beside the loads' numbers, an audit of stop 90)
                        df[name] = text
                    v = pd.to_numeric(text, errors="coerce").to_numpy(float) * mapped[c][1]  # (rpm, m/s, deg)
                    lo, hi = limits[c]
                    bad = ~((v >= lo) & (v <= hi))
                    if bad.any():
                        i = int(np.argmax(bad))
                        why = (NEGATIVE_INCIDENCE if c == "incidence_deg" and -180 <= v[i] < 0 else
                               f" (the parameter set's collective {offset_deg:g} deg is added to it, the sum within "
                               f"[-{COLLECTIVE_DEG_MAX:g}, {COLLECTIVE_DEG_MAX:g}])"
                               if c == COLLECTIVE_COLUMN and offset_deg else
                               _cell_hint(str(text.iloc[i]), sep, first=rows == 0 and i == 0))
                        raise InputError(f"--points: {path}, line {lines[i]}: {c} must be a finite number in "
                                         f"[{lo:g}, {hi:g}], got {str(df[name].iloc[i])[:40]!r}{why}")
                    values[c] = v
                rows += len(df)
                df.columns = names  # (as written: the unnamed ones had placeholders for pandas only)
                yield df, int(lines[0]), values
    except (pd.errors.ParserError, pd.errors.ParserWarning, UnicodeDecodeError, ValueError) as exc:
        raise _parse_error(path, exc, sep, len(names)) from None
    if rows == 0:
        raise InputError(f"--points: {path} has no data rows")


def _decimal_commas(path: Path, column: str, text, lines, marks: list):
    """A ';'-separated points file's cells with decimal commas as points; a file with decimal
    commas and points is refused, a point beside decimal commas being a thousands separator (load
    files read 3.000 and 1.234,5 as thousands there since 2026-12-01, identify/csvfile.py; a points
    file does not). ``marks``: where a decimal comma and a point were first seen so far, (line,
    column)."""
    import numpy as np

    comma = (text.str.count(",") == 1) & ~text.str.contains(".", regex=False)
    point = text.str.contains(".", regex=False) & ~text.str.contains(",", regex=False)
    for k, m in ((0, comma.to_numpy()), (1, point.to_numpy())):
        if m.any() and not marks[k]:
            marks[k] = (int(lines[int(np.argmax(m))]), column)
    if marks[0] and marks[1]:
        (lc, cc), (lp, cp) = marks
        raise InputError(f"--points: {path}: decimal commas (line {lc}, column {cc}) and points (line {lp}, column "
                         f"{cp}) in one file; beside decimal commas a point is a thousands separator: save the "
                         "numbers without one")
    return text.where(~comma, text.str.replace(",", ".", regex=False))
