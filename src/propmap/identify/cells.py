"""What one cell or column of an identification CSV file says on its own, apart from the file
it is in (identify/csvfile.py's reader, and ``propmap loads --points``, cli/_points.py, ask):
a missing-value mark, a stopped motor's zero, a summary row's label, a point grouping thousands
beside a decimal comma, a value under a column with no name, and a cell shown short in a message.

The missing-value marks are a spreadsheet's ('#N/A', a formula's error such as '#VALUE!' or
LibreOffice's 'Err:502') as well as the usual words and a C runtime's not-a-number ('-nan(ind)'):
a stand log's dropout written '#N/A' was refused where 'n/a' was read (a thrust-stand data audit,
2026-11-30). A summary row's labels ('Average' under 'Point' in a spreadsheet's last row was read
as a measured point and fitted: the same audit). A value under an unnamed column beside a named
one is likely the decimals of a number split by its decimal comma in a comma-separated file (a
user-level audit: ``RPM,Thrust (gf),`` with ``1975,55,27`` read 55 gf).
"""

from __future__ import annotations

import re

from ..io.inputs import parse_number

__all__: list[str] = []


def unnamed_columns(names) -> list[int]:
    """The 0-based indexes of a header's unnamed columns after its first named one (those before
    it are a row index, read as nothing); a value under one is refused (unnamed_value_message)."""
    lead = next((j for j, c in enumerate(names) if c), len(names))
    return [j for j, c in enumerate(names) if not c and j > lead]


def unnamed_value_message(j: int, cell: str, sep: str, after_named: bool = True) -> str:
    """What a value in column ``j`` (0-based, after the first named one) with no name in the
    header is likely to be: beside a named column, the decimals of a number split by its decimal
    comma, in a file whose separator is the comma (a user-level audit: ``RPM,Thrust (gf),`` with
    ``1975,55,27`` read 55 gf)."""
    why = (" (a number with a decimal comma in a comma-separated file? save it with decimal points, or "
           "with ';' as the separator)" if sep == "," and after_named and re.fullmatch(r"[0-9]+", cell) else
           # (text: 'Warning: current 30 A, check ESC' in an unquoted message cell was called a decimal comma)
           f" (text with a '{sep}' in a field without quotes? quote the field, or remove the column)"
           if re.search(r"[A-Za-z]", cell) else "")
    return f"column {j + 1} has no name in the header but holds {_short(cell)}{why}: name the column or remove it"


def _short(text: str, n: int = 40) -> str:
    r = repr(text)
    return r if len(r) <= n else r[: n - 5] + "...'" + f" ({len(text)} characters)"


#: cells that mark a missing value (no units-row hint for them); '#N/A' and a formula's error ('#VALUE!', '#DIV/0!')
#: are a spreadsheet's (a stand log's dropout so written was refused where 'n/a' was read: a thrust-stand data audit,
#: 2026-11-30)
MISSING_MARKS = ("n/a", "na", "nan", "none", "null", "-", "--", "#n/a", "#na", "#value!", "#div/0!", "#num!",
                 "#ref!", "#null!", "#name?", "#spill!", "#calc!")
_MISSING = frozenset(("", *MISSING_MARKS))
#: the not-a-number forms C runtimes print (glibc '-nan', MSVC '-nan(ind)', '1.#QNAN', '1.#IND')
_C_NAN = re.compile(r"nan(\([a-z0-9_]*\))?|1\.#(qnan|snan|ind)0*", re.ASCII)


def missing_mark(cell: str) -> bool:
    """Whether a CSV cell marks a missing value.

    Parameters
    ----------
    cell : str
        One field as read; surrounding whitespace is ignored.

    Returns
    -------
    bool
        True for an empty cell, one of MISSING_MARKS, LibreOffice's ``Err:502`` or a C runtime's
        not-a-number (glibc ``-nan``, MSVC ``-nan(ind)``, ``1.#QNAN``, ``1.#IND``), in any case and
        sign.
    """
    low = cell.strip().lower().lstrip("+-")
    # (LibreOffice's formula errors, Err:502: a review; called on every cell of a sampled log's loads, so the
    # common cell, a number, leaves at the first test)
    return (low in _MISSING or _C_NAN.fullmatch(low) is not None
            or (low.startswith("err:") and low[4:].isdigit()))


def _zero_or_empty(cell: str) -> bool:
    """A cell that is empty or reads as the number 0 (a stopped motor's speed)."""
    cell = cell.strip()
    if not cell:
        return True
    try:
        return parse_number(cell.replace(",", ".")) == 0.0
    except ValueError:
        return False


#: a summary row's label in a column not read ('Average' under 'Point' in a spreadsheet's last row was read as a
#: measured point and fitted: a thrust-stand data audit, 2026-11-30)
SUMMARY_LABELS = frozenset(("average", "avg", "avg.", "mean", "total", "sum", "median", "std", "stdev", "std dev",
                            "standard deviation", "averages", "totals"))


def _ungrouped(cell: str) -> str:
    """A cell whose points group thousands beside a decimal comma as a decimal number: 1.234,5 -> 1234.5."""
    return cell.replace(".", "").replace(",", ".")
