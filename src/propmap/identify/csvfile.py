"""The identification CSV files (level flight, loads): parsing, checks and errors
(identify/loads_csv.py and identify/level_flight.py read them; what one cell says on its own,
a missing-value mark or a summary row's label, is identify/cells.py's).

Readers raise :class:`DataError` (a ValueError) with a one-line message naming the file,
the line and the column, and for a value out of range the valid range; no other exception
escapes for any file content, and no reader modifies its input.

CSV files (:func:`read_level_flight`, :func:`read_loads`): a regular file of at most
200 MiB and 10,000,000 lines (never a directory, a device or a pipe), UTF-8 with or
without a byte-order mark
(as Excel writes it), comma-separated, or semicolon-separated (the separator is read from
the header line) with decimal points or, as spreadsheets in decimal-comma locales save it,
decimal commas (``0,057``; a file with both is refused: beside decimal commas a point is a
thousands separator), a header line then one row per point; line ends
LF or CRLF; blank lines and rows of empty cells are skipped, a row that ends before a column
that must be read is an error (since 2026-11-29); double quotes as in RFC 4180
(an unterminated quote is an error). Column names are stripped of spaces, at most 255
characters, each at most once (a duplicated column is an error, never "the first wins");
columns not listed are ignored, and so are unnamed ones that hold nothing (a trailing
separator) or come before the first named one (a spreadsheet's or pandas' row index); an
unnamed column after a named one that holds a value is an error (the decimals of ``55,27``
in a comma-separated file land there). Numbers are plain ASCII decimals
(``1e3``; not ``1_000``, not NaN or inf). Valid ranges:

=====================  ======================================================
rpm, rpm_<k>           (0, 954929] (the solver's limit of 1e5 rad/s)
airspeed               [0, 500] m/s
incidence_deg          [0, 180] deg
collective_deg         [-45, 45] deg
thrust, drag           [-1e5, 1e5] N
torque                 [-1e4, 1e4] N m
pitch_deg, roll_deg    (-90, 90) deg
p, q, r                [-100, 100] rad/s
=====================  ======================================================
"""

from __future__ import annotations

import array
import csv
import io
import math
import re

import numpy as np

from ..io.inputs import (MAX_FILE_BYTES, decode_input_text, header_separator, parse_number, read_input_bytes,
                         show_path)
from ..core.solver import AIRSPEED_MAX, COLLECTIVE_RANGE
from ..core.units import RPM_MAX
# (what one cell says, identify/cells.py; its public names re-exported here, where they were)
from .cells import (MISSING_MARKS, SUMMARY_LABELS, _short, _ungrouped, _zero_or_empty, missing_mark,  # noqa: F401
                    unnamed_columns, unnamed_value_message)

__all__ = ["DataError", "RANGES", "MAX_NAME", "MAX_LINES"]


#: valid ranges of the CSV columns: (low, high, low open, high open, unit)
RANGES = {
    "rpm": (0.0, RPM_MAX, True, False, "rpm"),
    "airspeed": (0.0, AIRSPEED_MAX, False, False, "m/s"),
    "incidence_deg": (0.0, 180.0, False, False, "deg"),
    "collective_deg": (-math.degrees(COLLECTIVE_RANGE), math.degrees(COLLECTIVE_RANGE), False, False, "deg"),
    "thrust": (-1e5, 1e5, False, False, "N"),
    "drag": (-1e5, 1e5, False, False, "N"),
    "torque": (-1e4, 1e4, False, False, "N m"),
    "rolling_moment": (-1e4, 1e4, False, False, "N m"),
    "pitch_deg": (-90.0, 90.0, True, True, "deg"),
    "roll_deg": (-90.0, 90.0, True, True, "deg"),
    "p": (-100.0, 100.0, False, False, "rad/s"),
    "q": (-100.0, 100.0, False, False, "rad/s"),
    "r": (-100.0, 100.0, False, False, "rad/s"),
}
#: the longest column name accepted [characters]
MAX_NAME = 255
#: lines below the first that :meth:`_Csv.after_preamble` tries as the header (a preamble's length)
PREAMBLE_MAX_LINES = 40
#: the most lines a CSV may have (bounds the time a 200 MiB file of tiny lines takes)
MAX_LINES = 10_000_000


class DataError(ValueError):
    """Bad identification data; the message names the problem.

    Attributes
    ----------
    not_utf8 : bool
        True where the file's bytes are not UTF-8 (and not UTF-16, UTF-32 or binary:
        :func:`propmap.io.inputs.decode_input_text` sets it); False for every other problem.
        The CSV reader's Windows-1252 fallback decides on it, not on the message.
    """

    not_utf8: bool = False


def _interval(rng) -> str:
    lo, hi, lo_open, hi_open, unit = rng
    return f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'} {unit}"


#: a per-rotor rotation-rate column, rpm_<k>
_ROTOR_RE = re.compile(r"rpm_([1-9][0-9]{0,5})", re.ASCII)


#: the names of the separators other than ',' (for messages)
SEPARATOR_NAMES = {";": "semicolon", "\t": "tab"}


#: the note's words for a comma-separated file's quoted cells read with commas as thousands separators
COMMA_THOUSANDS = "commas read as thousands separators"


class _Csv:
    """A parsed CSV: the header's columns, and numbers or text of the columns asked for.

    Only the columns asked for are converted (to float arrays), so that a large file
    costs 8 bytes a value; every message names the file, the line and the column.
    """

    def __init__(self, path, what: str, *, windows_1252: bool = False, spreadsheet: bool = False):
        # (spreadsheet: a row of units under the header and thousands separators are read, in load data; a
        # level-flight file's names are exact, and a units row merged into them hid its columns: a review, 2026-12-01)
        self.what, self.name, self.spreadsheet = what, show_path(path), spreadsheet
        self.notes: list[str] = []  # (what reading the bytes decided, for the reader's notes)
        try:
            raw = read_input_bytes(path, DataError, limit=MAX_FILE_BYTES)
            try:
                decode_input_text(raw, path, DataError)  # refuses UTF-16, NUL bytes, non-UTF-8 (naming the line)
            except DataError as exc:
                if not windows_1252:
                    raise
                raw = self._windows_1252(raw, exc)
        except DataError as exc:
            raise DataError(f"{what}: {exc}") from None
        n_lines = raw.count(b"\n") + raw.count(b"\r") - raw.count(b"\r\n")
        if n_lines > MAX_LINES:
            raise DataError(f"{what}: {self.name}: {n_lines:,} lines; a data file may have at most {MAX_LINES:,}")
        self._raw = raw
        self._find_header()

    def _find_header(self) -> None:
        """The separator and the header: the first non-blank line of ``self._raw``."""
        raw = self._raw
        # ',', ';' (spreadsheets in locales with a decimal comma) or a tab, from the header line
        # (and its first data row: a separator that occurs as often in both)
        lines = re.split(rb"\r\n|\r|\n", raw.lstrip(b"\xef\xbb\xbf\r\n "), maxsplit=8)[:8]
        # a quoted name over two lines ("Drehzahl<newline>[U/min]", a spreadsheet's wrapped heading) is one line here
        # (its first line alone gave no ';' and the file was read with ',': an export audit, 2026-11-30)
        # (the header line only: an inch mark in a data row, 'APC 10x7"', joined two rows: a review, 2026-11-30)
        joined: list[bytes] = []
        for r in lines:
            if len(joined) == 1 and joined[0].count(b'"') % 2:
                joined[0] += b"\n" + r
            else:
                joined.append(r)
        head, *rows = [r.decode("utf-8", "replace") for r in joined if r.strip()][:2] or [""]
        self.sep = header_separator(head, rows[0] if rows else None)
        self.header_line = self.units_line = 0
        self.columns: list[str] = []
        rows = self._rows()
        for line, cells in rows:
            self.header_line = line
            self.header = [c.strip() for c in cells]  # as written, for messages and unit parsing
            self.columns = [c.lower() for c in self.header]  # names match in any case
            break
        if not self.header_line:
            raise self.error("empty file (no header line)")
        try:
            under = next(rows)
        except (StopIteration, DataError):  # (no row under it, or one that does not parse: the reader says so)
            under = None
        if under is not None and self.spreadsheet:
            self._units_row(*under)
        seen: dict[str, int] = {}
        for j, c in enumerate(self.columns, start=1):
            if len(c) > MAX_NAME:
                raise self.error(f"column {j} has a name of {len(c)} characters (at most {MAX_NAME})",
                                 self.header_line)
            if c and c in seen:
                raise self.error(f"column {_short(self.header[j - 1])} appears twice (columns {seen[c]} and {j}); "
                                 "remove one",
                                 self.header_line)
            seen[c] = j
        self.index = {c: j - 1 for c, j in seen.items() if c}  # named column -> 0-based index

    def _units_row(self, line: int, cells: list[str]) -> None:
        """The row under the header read as the columns' units where it is one
        (:func:`propmap.identify.headers.units_row`): merged into the header's names, with a note,
        and skipped by :meth:`read`; a unit that contradicts a name's own is refused."""
        from .headers import READ_NAMES, split_header, units_row

        merged = units_row(self.header, cells)
        if merged is None:
            return
        header, conflicts = merged
        for j, name, unit in conflicts:
            if split_header(name)[0] in READ_NAMES:
                raise self.error(f"the row of units under the header gives {_short(unit)} for column {_short(name)}, "
                                 "whose name gives another unit: write one", line)
            self.notes.append(f"{self.name}: line {line} gives {_short(unit)} for column {_short(name)}, whose name "
                              "gives another unit (a column propmap does not read: left as named)")
        self.units_line = line
        self.notes.append(f"{self.name}: line {line} read as the columns' units (" + ", ".join(
            _short(h) for h, old in zip(header, self.header) if h != old) + ")" if header != self.header else
            f"{self.name}: line {line} repeats the units the columns' names give: not read as data")
        self.header = header
        self.columns = [c.lower() for c in header]

    def after_preamble(self, accepts, max_lines: int = PREAMBLE_MAX_LINES) -> _Csv | None:
        """This file read with its header further down: the first of the next ``max_lines``
        non-blank lines whose cells ``accepts`` (a callable of the header's cells, True where they
        name the columns the reader needs) and which a row follows, the lines above it blanked
        (so that every message keeps the file's own line numbers) and named in a note; None where
        no line is accepted. For a preamble above the header (a test's name, a date, the stand's
        settings; a user-level check of thrust-stand exports, 2026-11-29: such a file was refused
        as having no rotation-speed column)."""
        breaks = re.finditer(rb"\r\n|\r(?!\n)|\n", self._raw)
        starts = [m.end() for _, m in zip(range(max_lines + 1), breaks)]
        for k, start in enumerate(starts[:max_lines], start=2):  # k: the candidate header's line number
            text = re.split(rb"\r\n|\r|\n", self._raw[start:start + 65536], maxsplit=2)[:2]
            line, *after = [t.decode("utf-8", "replace") for t in text]
            if not line.strip():
                continue  # (a blank line, or the end of the file: not a header)
            # (its cells checked first, so that a file with no such line is copied no time)
            cells = next(csv.reader([line], delimiter=header_separator(line, after[0] if after else None)), [])
            if not accepts([c.strip() for c in cells]):
                continue
            other = object.__new__(_Csv)
            other.what, other.name, other.notes = self.what, self.name, list(self.notes)
            other.spreadsheet = self.spreadsheet
            other._raw = re.sub(rb"[^\r\n]", b"", self._raw[:start]) + self._raw[start:]  # (line breaks kept)
            try:
                other._find_header()
                rows = other._rows()
                next(rows)
                next(rows)  # (a row under it)
            except (DataError, StopIteration):
                continue
            if other.header_line == k and accepts(other.header):
                above = "line 1" if k == 2 else f"lines 1-{k - 1}"
                other.notes.append(f"{self.name}: {above} above the header (line {k}) not read: a preamble")
                return other
        return None

    def _windows_1252(self, raw: bytes, exc: DataError) -> bytes:
        """Text that is not UTF-8 but Windows-1252 (a spreadsheet saved on Windows: 'µs', 'N·m',
        '°C' as single bytes), re-encoded as UTF-8 with a note; else ``exc`` raised (a user-level
        audit: a stand export re-saved by Excel was refused). Not a file with a UTF-8 byte-order
        mark or a UTF-8 multi-byte sequence: UTF-8 with a stray byte stays refused, naming it. Decided
        on ``exc.not_utf8``, not the message (a file named '... is not UTF-8 ...' in UTF-16 was read
        as Windows-1252 until 2026-12-01)."""
        if (not exc.not_utf8 or raw.startswith(b"\xef\xbb\xbf")
                or re.search(rb"[\xc2-\xf4][\x80-\xbf]", raw)):
            raise exc
        try:
            text = raw.decode("cp1252")
        except UnicodeDecodeError:  # (bytes Windows-1252 leaves undefined: another encoding)
            raise exc from None
        self.notes.append(f"{self.name} is not UTF-8: read as Windows-1252 (a spreadsheet's save on Windows)")
        return text.encode("utf-8")

    def error(self, message: str, line: int | None = None) -> DataError:
        at = f", line {line}" if line else ""
        return DataError(f"{self.what}: {self.name}{at}: {message}")

    def _rows(self):
        """(first line number, cells) of every non-blank row, after the header if it is known."""
        text = io.TextIOWrapper(io.BytesIO(self._raw), encoding="utf-8-sig", newline="")
        reader = csv.reader(text, delimiter=getattr(self, "sep", ","), strict=True, skipinitialspace=True)
        last = 0
        try:
            for cells in reader:
                first, last = last + 1, reader.line_num
                if any(c.strip() for c in cells):
                    yield first, cells
        except csv.Error as exc:
            msg = str(exc)
            if "field larger than field limit" in msg:
                msg = f"a field longer than {csv.field_size_limit()} characters"
            elif "unexpected end of data" in msg:
                msg = "unterminated quote: a quoted field is never closed"
            elif "expected after" in msg:
                mark = SEPARATOR_NAMES.get(getattr(self, "sep", ","), "comma")
                msg = f"a closing quote must be followed by a {mark} or the end of the line"
            raise self.error(msg, last + 1) from None

    def read(self, numeric: list[str], text: tuple[str, ...] = (), optional=(), stop=(), gaps=(),
             percent=(), mean_row: bool = False) -> tuple[dict, dict, np.ndarray]:
        """(numbers by column, text by column, line of each row) for the named columns; an
        empty cell of a column in ``optional`` is NaN instead of an error, and so is every
        empty cell of a row whose ``stop`` columns (a subset of ``optional``) are all empty or 0:
        a stopped motor's row, e.g. a stand export's last line after the test ended. A cell of a
        column in ``gaps`` or ``optional`` that is empty or a missing-value mark (``NaN``,
        ``n/a``, ``-``, ``-nan(ind)``, ...; :func:`missing_mark`) is NaN too: a sensor's dropout in
        a sampled log, which the caller drops, or an optional column's missing reading (a stand's
        optical speed ``NaN`` in every row was refused while the same column left empty was read:
        a thrust-stand export audit, 2026-11-27). A cell of a column in ``percent`` may end in ``%``
        (``50%``, ``62.5 %``: a motor maker's table of throttle settings): read without it, and the
        column is added to ``self.percent_cells``. A comma-separated file's quoted cell that groups
        thousands with commas (``"3,000"``, ``"1,234.5"``) and, beside decimal commas, a ';'- or
        tab-separated file's point before groups of three digits (``3.000``, ``1.234,5``) are read
        as thousands separators, with a note in ``self.read_notes``; the columns of the former, a
        quoted "1,100" being 1.1 or 1100, are ``self.comma_thousands``. With ``mean_row``, a last
        row that is the mean of the rows above is refused (:meth:`_refuse_mean_row`: load data, whose loads grow as the
        rotation rate's square; a points file's design point at the centre of its grid is none). A
        last row labelled as a summary in a column not read is refused
        (:meth:`_refuse_summary_label`)."""
        self.percent_cells: set[str] = set()
        self.read_notes: list[str] = []  # (what reading the cells decided: thousands separators)
        self.comma_thousands: set[str] = set()
        n = len(self.columns)
        cols = [(c, self.index[c]) for c in numeric]
        nums = {c: array.array("d") for c in numeric}
        texts = {c: [] for c in text if c in self.index}
        lines = array.array("q")
        # a ';'- or tab-separated file: where a decimal comma and a point were first seen, (line, column)
        marks = [None, None]
        # a ';'- or tab-separated file's cells like 3.000 (a point before groups of three digits), (column, row, line,
        # cell): read as decimals, or as thousands where the file has decimal commas (_decimal_comma)
        pending: list = []
        # a comma-separated file's columns whose (quoted) cells group thousands with commas, "3,000": (line, cell)
        commas: dict = {}
        # per column of a ';'- or tab-separated file: its cells like 1.059 and like 951 (_thousands)
        grouped: dict = {}
        rows = self._rows()
        next(rows)  # the header
        if self.units_line:
            next(rows)  # its units, merged into it
        first_cells = last_cells = last_line = None
        unnamed = unnamed_columns(self.columns)
        read_at = {j for _, j in cols}
        for line, cells in rows:
            if len(cells) > n and any(c.strip() for c in cells[n:]):
                mark = SEPARATOR_NAMES.get(self.sep, "comma")
                # (an unquoted comma in a stand export's last text cell, 'App message': an export audit, 2026-11-30;
                # the last column named only where it is not read as a number, a review)
                last = "" if n - 1 in read_at else f" (the last column's, {_short(self.header[-1])}?)"
                why = (f": a {mark} inside a cell's text{last} that is not quoted"
                       + (", or decimal commas in a comma-separated file" if mark == "comma" else ""))
                raise self.error(f"{len(cells)} fields, but the header (line {self.header_line}) has {n}{why}", line)
            cut = [j for c, j in cols if j >= len(cells) and (c in stop or c not in optional)] if len(cells) < n else ()
            if cut:  # (a row cut short: read as a stopped motor's row and skipped until 2026-11-29, an audit)
                raise self.error(f"{len(cells)} fields, but the header (line {self.header_line}) has {n}: the row "
                                 f"ends before column {_short(self.header[min(cut)])}", line)
            for j in unnamed:
                if j < len(cells) and cells[j].strip():
                    raise self.error(unnamed_value_message(j, cells[j].strip(), self.sep, bool(self.columns[j - 1])),
                                     line)
            first_cells = cells if first_cells is None else first_cells
            last_cells, last_line = cells, line
            stopped = bool(stop) and all(_zero_or_empty(cells[self.index[c]] if self.index[c] < len(cells) else "")
                                         for c in stop)
            for c, j in cols:
                cell = cells[j].strip() if j < len(cells) else ""
                if (not cell and stopped) or ((c in gaps or c in optional) and missing_mark(cell)):
                    nums[c].append(math.nan)
                    continue
                if not cell:
                    raise self.error(f"column {_short(self.header[j])} is empty (missing value)", line)
                number = cell
                if c in percent and cell.endswith("%") and cell[:-1].strip():
                    number = cell[:-1].strip()
                    self.percent_cells.add(c)
                if self.sep != ",":
                    self._thousands(c, number, line, grouped)
                    number = self._decimal_comma(c, number, line, marks, pending, len(nums[c]))
                elif self.spreadsheet and "," in number and re.fullmatch(r"[+-]?[1-9]\d{0,2}(,\d{3})+(\.\d+)?", number):
                    commas.setdefault(c, (line, number))  # ("3,000" quoted: refused as not a number until 2026-12-01)
                    number = number.replace(",", "")
                try:
                    x = parse_number(number)
                except ValueError:
                    if missing_mark(cell):  # ('#N/A' was told only "is not a number": a thrust-stand data audit)
                        raise self.error(f"column {_short(self.header[j])} is {_short(cell)}, a missing value: a "
                                         "point needs every column read; remove the row or give the value",
                                         line) from None
                    unit_like = re.search(r"[a-zA-Z%]", cell) and not missing_mark(cell)
                    hint = (" (a row of units under the header? write each unit in its column's name instead, e.g. "
                            "'thrust (N)', and remove the row)" if not len(lines) and unit_like else
                            " (a decimal comma? a comma-separated file needs decimal points, or ';' between its cells)"
                            if self.sep == "," and re.fullmatch(r"[+-]?\d*,\d+", cell) else "")
                    raise self.error(f"column {_short(self.header[j])}: {_short(cell)} is not a number{hint}",
                                     line) from None
                if not math.isfinite(x):
                    raise self.error(f"column {_short(self.header[j])} is {_short(cell)}, not a finite number", line)
                nums[c].append(x)
            for c in texts:
                j = self.index[c]
                texts[c].append(cells[j].strip() if j < len(cells) else "")
            lines.append(line)
        self._thousands_read(nums, marks, pending, commas)
        self._refuse_thousands({c: seen for c, seen in grouped.items()
                                if not (marks[0] and seen["grouped"] and "." in seen["grouped"][1])})
        self._refuse_summary_label(first_cells, last_cells, last_line, read_at | {self.index[c] for c in texts})
        out = {c: np.frombuffer(v, dtype=float).copy() for c, v in nums.items()}
        if mean_row:
            self._refuse_mean_row(out, lines)
        return out, texts, np.frombuffer(lines, dtype=np.int64).copy()

    def _refuse_summary_label(self, first, last, line, read: set) -> None:
        """Refuse a last row labelled as a summary (``Average``, ``Mean``, ``Total``: SUMMARY_LABELS)
        in a column not read whose first row is not so labelled too (a column of 'mean' on every
        row says what each row is: a review) (read as a measured point and fitted: a thrust-stand
        data audit, 2026-11-30)."""
        if last is None or last is first:
            return
        for j, cell in enumerate(last):
            low = cell.strip().lower().rstrip(":")
            if j not in read and low in SUMMARY_LABELS and (j >= len(first) or first[j].strip().lower().rstrip(":")
                                                              != low):
                raise self.error(f"column {_short(self.header[j])} is {_short(cell.strip())}: a summary row (of the "
                                 "rows above)? remove it: every row is read as a measured point", line)

    def _refuse_mean_row(self, nums: dict, lines) -> None:
        """Refuse a last row that is the mean of the rows above in every column read (to 0.1%, a
        spreadsheet's rounding), where 4 or more rows stand above it and 2 or more columns vary by a
        tenth of their size: a summary row without a label (read as a measured point and fitted: a
        thrust-stand data audit, 2026-11-30). A measured point does not fall on the mean of thrust
        and torque as well as of the rotation rate (they grow as its square)."""
        cols = [v for v in nums.values() if len(v) >= 5 and np.isfinite(v).all()]
        if len(cols) < 2 or len(cols) < len(nums):
            return
        # (varying by a tenth of their size: a repeatability table at one setting, 0.3% in rpm, was refused: a review)
        varying = [v for v in cols if np.ptp(v[:-1]) > 0.1 * np.max(np.abs(v[:-1]))]
        if len(varying) >= 2 and all(abs(v[-1] - v[:-1].mean()) <= 1e-3 * abs(v[:-1].mean()) for v in cols):
            raise self.error(f"the last row is the mean of the {len(lines) - 1} rows above it in every column read: a "
                             "summary row (an average)? remove it: every row is read as a measured point", lines[-1])

    @staticmethod
    def _thousands(column: str, cell: str, line: int, grouped: dict) -> None:
        """Note, for :meth:`_refuse_thousands`, a ';'- or tab-separated file's cell: the largest
        like ``1.059`` or ``1,059`` (a digit 1-9, up to two more, a point or a comma, three
        digits), the largest whole number of three digits (``951``), and whether any other
        decimal (``0.125``, ``16,5``) stands in the column; ``grouped`` holds them per column (a
        web table's ``1,056`` beside ``802`` in grams was read as a decimal comma, 1.056 g, and
        fitted: a thrust-stand data audit, 2026-11-30)."""
        seen = grouped.setdefault(column, {"grouped": None, "whole": None, "decimal": False})
        if re.fullmatch(r"[+-]?[1-9]\d{0,2}[.,]\d{3}", cell):
            if seen["grouped"] is None or float(cell.replace(",", ".")) > float(seen["grouped"][1].replace(",", ".")):
                seen["grouped"] = (line, cell)
        elif re.fullmatch(r"[+-]?[1-9]\d{2}", cell):
            if seen["whole"] is None or float(cell) > float(seen["whole"][1]):
                seen["whole"] = (line, cell)
        elif "." in cell or "," in cell:
            seen["decimal"] = True

    def _refuse_thousands(self, grouped: dict) -> None:
        """Refuse a column whose cells like ``1.059`` (``1,059``) are all more than 100 times smaller than its
        largest whole number of three digits (``951``), where no other decimal stands: there the point is
        a thousands separator (951, 1059), which read as a decimal point made points 1000 times too
        small that were fitted (a thrust-stand export audit, 2026-11-30); a column of decimals
        beside whole numbers of their size (16.667 beside 100, 98.125 beside 215) is read."""
        for column, seen in grouped.items():
            if seen["grouped"] and seen["whole"] and not seen["decimal"] and (
                    100 * abs(float(seen["grouped"][1].replace(",", "."))) < abs(float(seen["whole"][1]))):
                (lg, cg), (lw, cw) = seen["grouped"], seen["whole"]
                mark = "a comma" if "," in cg else "a point"
                whole = cg.replace(".", "").replace(",", "")
                raise self.error(f"column {_short(self.header[self.index[column]])}: {cg} (line {lg}) beside {cw} "
                                 f"(line {lw}): {mark} as a thousands separator ({whole})? save the numbers without "
                                 "one", lg)

    def _decimal_comma(self, column: str, cell: str, line: int, marks: list, pending: list, row: int) -> str:
        """A ';'- or tab-separated file's cell with its decimal comma as a point (``0,057`` -> ``0.057``).

        ``marks`` holds where a decimal comma and a point were first seen, (line, column). A point
        before groups of three digits is a thousands separator where a decimal comma follows
        (``1.234,5``), and is left for the caller where none does (``3.000``: read as 3000 where
        the file has decimal commas and as 3.0 where it has none; refused until 2026-12-01); both
        are appended to ``pending`` as (column, row, line, cell), for the caller's note. Any other point beside
        decimal commas is refused: there a point is a thousands separator (``7.5``?), which no
        reading can make of it."""
        if cell.count(",") == 1 and "." not in cell:
            marks[0] = marks[0] or (line, column)
            cell = cell.replace(",", ".")
        elif re.fullmatch(r"[+-]?[1-9]\d{0,2}(\.\d{3})+(,\d+)?", cell):
            pending.append((column, row, line, cell))
            if "," in cell:
                marks[0] = marks[0] or (line, column)
                cell = _ungrouped(cell)
        elif "." in cell and "," not in cell:
            marks[1] = marks[1] or (line, column)
        if marks[0] and marks[1]:
            raise self._mixed_marks(marks[0], marks[1], line)
        return cell

    def _mixed_marks(self, comma: tuple, point: tuple, line: int) -> DataError:
        """The refusal of a file with decimal commas and points, each (line, column) where first seen."""
        return self.error(f"decimal commas (line {comma[0]}, column {_short(comma[1])}) and points (line {point[0]}, "
                          f"column {_short(point[1])}) in one file; beside decimal commas a point is a thousands "
                          "separator: save the numbers without one", line)

    def _thousands_read(self, nums: dict, marks: list, pending: list, commas: dict) -> None:
        """:meth:`read`'s thousands separators, once every row is read: beside decimal commas the
        ``pending`` cells of a ';'- or tab-separated file (3.000, 1.234,5) re-read as thousands in
        ``nums`` (refused in a file that is not a spreadsheet's, a level-flight file's), and a note
        for them and for each comma-separated column whose quoted cells grouped thousands with
        commas (``commas``: column -> (line, cell))."""
        if marks[0] and pending and not self.spreadsheet:  # (a level-flight file: refused, as before 2026-12-01)
            raise self._mixed_marks(marks[0], (pending[0][2], pending[0][0]), pending[0][2])
        if marks[0] and pending:  # beside decimal commas a point groups thousands: 3.000 is 3000
            for c, row, _, cell in pending:
                nums[c][row] = float(_ungrouped(cell))
            c, _, line, cell = pending[0]
            self.read_notes.append(f"{self.name}: points read as thousands separators beside the file's decimal commas "
                                   f"(column {_short(self.header[self.index[c]])}, line {line}: {cell} read as "
                                   f"{_ungrouped(cell)})")
        self.comma_thousands = set(commas)
        for c, (line, cell) in commas.items():
            self.read_notes.append(f"{self.name}: column {_short(self.header[self.index[c]])}: {COMMA_THOUSANDS} "
                                   f"(line {line}: {cell} read as {cell.replace(',', '')})")

    def check_ranges(self, values: dict, lines: np.ndarray, ranges: dict, written: dict | None = None) -> None:
        """Refuse the first value outside its column's range, naming the line and the range;
        ``written``: quantity -> (column name as written, factor to SI) of converted columns, whose
        value is then named as written too."""
        for c, x in values.items():
            key = "rpm" if (c == "rpm" or _ROTOR_RE.fullmatch(c)) else c
            if key not in ranges:
                continue
            lo, hi, lo_open, hi_open, unit = ranges[key]
            bad = ((x <= lo) if lo_open else (x < lo)) | ((x >= hi) if hi_open else (x > hi))
            if bad.any():
                i = int(np.argmax(bad))
                if key == "rpm":  # rpm_1 .. rpm_n too
                    raise self.error(f"rpm must be > 0 and <= {hi:.0f} (the solver's limit of 1e5 rad/s), got "
                                     f"{c} = {x[i]:g}", int(lines[i]))
                name, factor = (written or {}).get(c, (c, 1.0))
                shown = (f"{name!r} = {x[i] / factor:g}, i.e. {c} = {x[i]:g}" if factor != 1.0 else f"{x[i]:g}")
                hint = ("; the incidence is the angle between the airspeed and the rotor axis, whose sign the "
                        "model does not see: give its magnitude, and where the file's in-plane (normal) force is "
                        "body-fixed, negate it on those rows (propmap's drag points along the in-plane airspeed); a "
                        "disk angle of attack alpha_d (0 edgewise, positive with the disk tilted back against the "
                        "airspeed) is incidence_deg = 90 + alpha_d"
                        if key == "incidence_deg" and x[i] < 0 else
                        # (a descent in a climb-positive convention: a wind-tunnel data audit, 2026-11-27)
                        "; a descent given as a negative airspeed? give its magnitude with incidence_deg 180 (axial "
                        "descent; 0 is climb, 90 edgewise)" if key == "airspeed" and x[i] < 0 else "")
                raise self.error(f"{c} must be in {_interval(ranges[key])}, got {shown}{hint}", int(lines[i]))
