"""Readers for UIUC measurement files: static ``RPM CT CP`` and wind-tunnel ``J CT CP eta``
(UIUC Propeller Data Site, Brandt & Selig, AIAA 2011-1255).

Every reader raises :class:`MeasurementFileError` (a ValueError) with a one-line message
naming the file, the line where known and, for a value out of range, the valid range: RPM
in (0, 954929] (the solver's 1e5 rad/s), CT and CP in [-10, 10], J in [0, 20], eta finite.
No other exception escapes for any file content, and none modifies its input.

The geometry readers (io/geometry_files.py) and the safe reading of input files
(io/inputs.py) were in this module until 2026-11-23; their names are still importable from
here.
"""

from __future__ import annotations

import codecs
import io
import math
import os
import re
import stat
from dataclasses import dataclass

import numpy as np

from ..core.units import RPM_MAX  # the largest rotation rate in a measurement file [rpm]: the solver's 1e5 rad/s
from .geometry_files import MM_FAMILIES, GeometryFileError, read_apc_pe0, read_geometry, read_uiuc_geometry
from .inputs import (MAX_FILE_BYTES, MAX_SMALL_FILE_BYTES, TABLE_ALIASES, _check_column, _clip, _read_table, _read_text,
                     as_path, decode_input_text, parse_number, read_input_bytes, show_path)


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


class MeasurementFileError(ValueError):
    """A measurement file is malformed; the message names the file and the problem.

    Attributes
    ----------
    found_header : str or None
        Where the file has no header of the reader's columns (the message's "expected
        columns ..., found header ..."): its first non-blank line, clipped as the message
        gives it; None for every other problem. Callers decide on it, not on the message
        (identify/data.py tells a static file from a sweep by it).
    """

    found_header: str | None = None


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
    TypeError
        ``path`` not a str or os.PathLike.
    """
    path = as_path(path)
    t = _read_table(path, _read_text(path, MeasurementFileError), ["RPM", "CT", "CP"], MeasurementFileError)
    _check_column(t, 0, "RPM", 0.0, RPM_MAX, path, MeasurementFileError, lo_open=True)
    _check_column(t, 1, "CT", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    _check_column(t, 2, "CP", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    d = t.data
    run = re.split("_static_", path.stem, flags=re.IGNORECASE)[-1]  # (an upper-case name's id was the whole stem)
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
    TypeError
        ``path`` not a str or os.PathLike.

    Warns
    -----
    UserWarning
        The eta column departs from J CT / CP by more than 10% in the median (ETA_MISMATCH):
        CT and CP swapped, or the columns out of order.
    """
    path = as_path(path)
    where = show_path(path)
    text = _read_text(path, MeasurementFileError)
    t = _read_table(path, text, ["J", "CT", "CP", "eta"], MeasurementFileError)
    _check_column(t, 0, "J", 0.0, J_MAX, path, MeasurementFileError)
    _check_column(t, 1, "CT", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    _check_column(t, 2, "CP", -COEFFICIENT_MAX, COEFFICIENT_MAX, path, MeasurementFileError)
    d = t.data
    back = np.flatnonzero(np.diff(d[:, 0]) < 0)
    if back.size:  # (every UIUC sweep's J rises; shuffled rows changed a fit's residual correlation, which runs
        # along the rows, 0.77 -> 0.31, and so its uncertainty, unsaid: a file audit, 2026-12-01)
        import warnings

        k = int(back[0])
        warnings.warn(f"{where}, line {int(t.lines[k + 1])}: J falls from {d[k, 0]:g} to {d[k + 1, 0]:g} ({back.size} "
                      "such row(s)): a sweep's rows are taken in the order measured, J rising (a fit's residual "
                      "correlation runs along them); sort them by J", stacklevel=2)
    parts = path.stem.split("_")
    item = next(((k, v) for k, v in t.meta.items() if _is_rpm_key(k)), None)
    if item is None:
        _check_rpm_lines(text, where)
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
    if item is None and rpm < NAME_RPM_MIN:  # (apce_10x7_pg0813_5018_2.txt, a copy's suffix, was read at 2 rpm)
        raise MeasurementFileError(f"{what} is {rpm:g}, below {NAME_RPM_MIN:g} rpm: not a sweep's rate (a copy's "
                                   "suffix?); name the file <fam>_<D>x<P>_<run>_<RPM>.txt or give the rate in an "
                                   "'RPM average = N' line")
    run = parts[-2] if len(parts) >= 2 else path.stem
    _check_efficiency(d, where)
    return Sweep(run, rpm, d[:, 0], d[:, 1], d[:, 2], d[:, 3], f"UIUC Propeller Data Site, {path.name}")


#: the lowest rpm taken from a sweep file's name (UIUC's nominal rates: 1,500 rpm and up)
NAME_RPM_MIN = 100.0
#: a line that gives a sweep's measured rate, whatever its value's form
_RPM_LINE = re.compile(r"\s*(rpm[\s_]*average|average[\s_]*rpm|rpm)\s*[=:]\s*(.*?)\s*$", re.I)


def _is_rpm_key(key: str) -> bool:
    """A metadata key that gives a sweep's measured rate (``RPM average``, ``RPM_average``, ``rpm``)."""
    return re.sub(r"[\s_]", "", key.lower()) in ("rpmaverage", "averagerpm", "rpm")


def _check_rpm_lines(text: str, where: str) -> None:
    """Refuse an 'RPM average = N' line whose value is not a plain number (``4,998``, ``4998
    rpm``), in a file whose metadata gave no rate: it was not read as the rate and the file name's
    nominal rpm was taken instead, 0.4% off, without a word (an input fuzzing audit, 2026-11-27)."""
    for k, ln in enumerate(io.StringIO(text, newline=None), start=1):
        m = _RPM_LINE.fullmatch(ln.rstrip("\n"))
        if m:
            raise MeasurementFileError(f"{where}, line {k}: {_clip(ln.strip(), 60)}: the rate must be a plain number "
                                       "(4998: no thousands separator, no unit)")


#: a sweep whose eta departs from J CT / CP by more than this in the median is warned (1,051 UIUC sweep
#: files of both volumes, those with two points or more to judge: at most 0.33%, 2026-11-28)
ETA_MISMATCH = 0.1


def _check_efficiency(d, where: str) -> None:
    """Warn when a sweep's eta column is not J CT / CP (the columns swapped or out of order: a
    UIUC file's eta is computed from its own J, CT and CP); eta is not read otherwise."""
    J, CT, CP, eta = d.T
    ok = (CP > 1e-3) & (np.abs(eta) > 0.05) & (J * CT != 0)
    if ok.sum() >= 2:
        ratio = float(np.median(eta[ok] * CP[ok] / (J[ok] * CT[ok])))
        if not abs(ratio - 1) <= ETA_MISMATCH:
            import warnings

            warnings.warn(f"{where}: the eta column is {ratio:.3g} times J CT / CP in the median: are the CT and CP "
                          "columns swapped or out of order? (read as J CT CP eta)", UserWarning, stacklevel=3)


def looks_like_uiuc(path) -> bool:
    """Whether ``path`` is a UIUC-format static (``RPM CT CP``) or wind-tunnel (``J CT CP eta``) file:
    a header of exactly those columns (in any order; ``eta``, or ``eff`` or ``efficiency`` for it, may be
    missing) within its first 50 lines.

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
        # (also UIUC's columns in another order, or a sweep without eta: read as UIUC, so that its reader says
        # which columns it expects, rather than the CSV reader that it found no rotation speed: a user-level audit)
        # exactly UIUC's columns: a CSV with more is a CSV (``RPM CT CP thrust (N)`` was read as a UIUC static
        # file and its thrust column dropped without a word until 2026-11-29; a mutation audit)
        if (len(words) in (3, 4) and sorted(words[:3]) in (["cp", "ct", "rpm"], ["cp", "ct", "j"])
                and (not words[3:] or words[3] in ("eta", *TABLE_ALIASES["eta"]))):
            return True
    return False
