"""Reading TOML input files with errors that name the file.

The file is read as :func:`propmap.io.inputs.read_input_bytes` reads every input file:
a regular file only (never a directory, a device or a pipe), at most
:data:`~propmap.io.inputs.MAX_SMALL_FILE_BYTES`, UTF-8 (a byte-order mark is dropped).
"""

from __future__ import annotations

import difflib
import re
import tomllib
from pathlib import Path

from .inputs import MAX_SMALL_FILE_BYTES, decode_input_text, read_input_bytes, show_path

__all__ = ["load_toml", "did_you_mean"]


def load_toml(path: Path, error: type[ValueError]) -> dict:
    """Parse the TOML file ``path``.

    Parameters
    ----------
    path : str or Path
    error : ValueError subclass
        Raised with a one-line message naming the file.

    Returns
    -------
    dict
        The parsed document (values as :mod:`tomllib` gives them: the caller checks
        types and ranges).

    Raises
    ------
    error
        Not a readable regular file, larger than 16 MiB, not UTF-8 (the message gives the
        line), or not valid TOML (the message gives tomllib's line and column; also for
        arrays nested too deeply and integers of more than 4300 digits), with that line's
        text (a key given twice is named so).
    """
    name = show_path(path)
    text = decode_input_text(read_input_bytes(path, error, limit=MAX_SMALL_FILE_BYTES), path, error)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{name}: not valid TOML ({' '.join(str(exc).split())}){_line_shown(text, str(exc))}") from None
    except RecursionError:
        raise error(f"{name}: not valid TOML (arrays or tables nested too deeply)") from None
    except ValueError as exc:  # int() of a number of more than sys.get_int_max_str_digits() digits
        why = "an integer of more than 4300 digits" if "digits" in str(exc) else " ".join(str(exc).split())[:120]
        raise error(f"{name}: not valid TOML ({why})") from None


def _line_shown(text: str, message: str) -> str:
    """``"; line N: <its text>"`` for tomllib's "(at line N, column M)", so that the key the error is
    about is named (tomllib's "Cannot overwrite a value" of a key given twice named none: an audit,
    stop 102); "" where the message gives no line."""
    found = re.search(r"at line (\d+)", message)
    lines = text.splitlines()
    if not found or not 1 <= int(found.group(1)) <= len(lines):
        return ""
    shown = " ".join(lines[int(found.group(1)) - 1].split())
    # (control characters escaped as tomllib's own part escapes them: a terminal would act on them, a review)
    shown = "".join(c if c.isprintable() else repr(c)[1:-1] for c in shown)
    return f"; line {found.group(1)}: {shown[:100]}{' ...' if len(shown) > 100 else ''}"


def did_you_mean(unknown, allowed) -> str:
    """The hint for a table's unknown key: ``": did you mean KEY?"`` for the allowed key nearest
    the first unknown one (:func:`difflib.get_close_matches`, case ignored), else ``""``.

    Parameters
    ----------
    unknown : sequence of str
        The unknown keys, as written.
    allowed : iterable of str
        The table's keys.

    Returns
    -------
    str
        The hint, starting with ``": "``, or the empty string.
    """
    allowed = list(allowed)
    lowered = {k.lower(): k for k in allowed}
    first = str(unknown[0]) if len(unknown) else ""
    close = difflib.get_close_matches(first.lower(), list(lowered), n=1)
    return f": did you mean {lowered[close[0]]}?" if close else ""
