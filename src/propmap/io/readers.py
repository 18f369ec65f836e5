"""Readers for propeller geometry and measurement files.

* UIUC Propeller Data Site (Brandt & Selig, AIAA 2011-1255) geometry ``r/R c/R beta``,
  static ``RPM CT CP`` and wind-tunnel ``J CT CP eta`` files.
* APC Propellers PE0 geometry files (APC "Technical Information", v2022-0915).

Every reader raises :class:`GeometryFileError` / :class:`MeasurementFileError` (both
ValueError) naming the file and the problem; none modifies its input.
"""

from __future__ import annotations

import math
import re
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
]


class GeometryFileError(ValueError):
    """A geometry file is malformed; the message names the file and the problem."""


class MeasurementFileError(ValueError):
    """A measurement file is malformed; the message names the file and the problem."""


_META_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9 _./()-]*?)\s*[=:]\s*([-+0-9.eE]+)\s*$")


def _read_table(path: Path, expected: list[str], error, *, with_meta: bool = False):
    """Numeric rows of a whitespace table whose header starts with ``expected``.

    Lines before the header and ``key = value`` lines anywhere (e.g. UIUC's
    ``RPM average = 4042``) are metadata, returned with ``with_meta``; any other line
    that is not numeric is an error naming the file and the line.
    """
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise error(f"{path}: cannot read ({exc.strerror})") from None
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = raw.decode("latin-1")
    lines = text.splitlines()
    meta: dict[str, float] = {}
    want = [e.lower() for e in expected]
    start = None
    for k, ln in enumerate(lines):
        m = _META_RE.match(ln)
        if m:
            meta[m.group(1).strip()] = float(m.group(2))
            continue
        if [h.lower() for h in ln.split()[: len(expected)]] == want:
            start = k
            break
    if start is None:
        first = next((ln.strip() for ln in lines if ln.strip()), "")
        if not first:
            raise error(f"{path}: empty file")
        raise error(f"{path}: expected columns {' '.join(expected)}, found header {first!r}")
    rows = []
    for k, ln in enumerate(lines[start + 1:], start=start + 2):
        if not ln.strip():
            continue
        m = _META_RE.match(ln)
        if m:
            meta[m.group(1).strip()] = float(m.group(2))
            continue
        parts = ln.split()
        if len(parts) < len(expected):
            raise error(f"{path}, line {k}: expected {len(expected)} columns, found {len(parts)}")
        try:
            rows.append([float(x) for x in parts[: len(expected)]])
        except ValueError:
            raise error(f"{path}, line {k}: non-numeric value in {ln.strip()[:80]!r}") from None
    if not rows:
        raise error(f"{path}: no data rows")
    data = np.array(rows)
    if not np.all(np.isfinite(data)):
        raise error(f"{path}: non-finite value")
    return (data, meta) if with_meta else data


_NAME_RE = re.compile(r"(?P<D>\d+(?:\.\d+)?)x(?P<P>\d+(?:\.\d+)?)")


def _diameter_pitch_from_name(name: str) -> tuple[float | None, float | None]:
    m = _NAME_RE.search(name)
    if not m:
        return None, None
    return float(m["D"]), float(m["P"])


def read_uiuc_geometry(path, *, diameter_in: float | None = None, n_blades: int = 2,
                       name: str | None = None, source: str = "") -> Propeller:
    """Read a UIUC geometry file (columns ``r/R c/R beta``, beta in degrees).

    Parameters
    ----------
    path : str or Path
    diameter_in : float, optional
        Diameter [in]; taken from a UIUC-style name ``<fam>_<D>x<P>_geom.txt`` if omitted.
    n_blades : int
        Blade count (UIUC vol. 1 propellers are 2-bladed).
    name, source : str, optional

    Returns
    -------
    Propeller

    Raises
    ------
    GeometryFileError
        Missing columns, non-numeric rows, radii not strictly increasing, r/R outside
        (0, 1], or no diameter given or derivable from the name.
    """
    path = Path(path)
    data = _read_table(path, ["r/R", "c/R", "beta"], GeometryFileError)
    stem = path.name.replace("_geom.txt", "")
    if diameter_in is None:
        diameter_in, _ = _diameter_pitch_from_name(stem)
        if diameter_in is None:
            raise GeometryFileError(f"{path}: diameter unknown; give diameter_in (--diameter-in)")
    _, pitch_in = _diameter_pitch_from_name(stem)
    R = 0.5 * diameter_in * INCH
    try:
        return Propeller(name=name or stem, radius=R, n_blades=n_blades, r=data[:, 0] * R,
                         chord=data[:, 1] * R, theta=np.radians(data[:, 2]),
                         pitch=None if pitch_in is None else pitch_in * INCH,
                         source=source or f"UIUC Propeller Data Site geometry file {path.name}")
    except ValueError as exc:
        raise GeometryFileError(f"{path}: {exc}") from None


def read_apc_pe0(path, *, name: str | None = None, source: str = "") -> Propeller:
    """Read an APC PE0 geometry file (STATION [in], CHORD [in], ..., TWIST [deg]).

    The blade angle is APC's TWIST column (LE-TE datum); RADIUS and BLADES come from
    the file's summary lines.

    Raises
    ------
    GeometryFileError
        No station table, no RADIUS or BLADES line, or invalid geometry.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="latin-1")
    except OSError as exc:
        raise GeometryFileError(f"{path}: cannot read ({exc.strerror})") from None
    rows = []
    in_table = False
    for ln in text.splitlines():
        parts = ln.split()
        if "STATION" in parts and "TWIST" in parts:
            in_table = True
            continue
        if in_table:
            try:
                vals = [float(x) for x in parts]
            except ValueError:
                if rows:
                    break
                continue
            if len(vals) >= 13:
                rows.append(vals)
            elif rows:
                break
    m_r = re.search(r"RADIUS:\s*([0-9.]+)", text)
    m_b = re.search(r"BLADES:\s*([0-9]+)", text)
    if not rows:
        raise GeometryFileError(f"{path}: no STATION/CHORD/.../TWIST table found")
    if not (m_r and m_b):
        raise GeometryFileError(f"{path}: RADIUS or BLADES line missing")
    data = np.array(rows)
    R = float(m_r.group(1)) * INCH
    pitch = float(np.median(data[:, 2])) * INCH  # QUOTED pitch column [in]
    try:
        return Propeller(name=name or path.name.replace("-PERF.PE0", ""), radius=R, n_blades=int(m_b.group(1)),
                         r=data[:, 0] * INCH, chord=data[:, 1] * INCH, theta=np.radians(data[:, 7]),
                         pitch=pitch, source=source or f"APC Propellers PE0 geometry file {path.name}")
    except ValueError as exc:
        raise GeometryFileError(f"{path}: {exc}") from None


def read_geometry(path, *, diameter_in: float | None = None, n_blades: int | None = None) -> Propeller:
    """Read a geometry file, choosing the reader by content (PE0 or UIUC ``r/R c/R beta``).

    Raises
    ------
    GeometryFileError
        As the chosen reader; also if the format is not recognised.
    """
    path = Path(path)
    if not path.is_file():
        raise GeometryFileError(f"{path}: no such file")
    head = path.read_text(encoding="latin-1", errors="replace")[:4000]
    if "STATION" in head and "TWIST" in head:
        prop = read_apc_pe0(path)
        if n_blades is not None and n_blades != prop.n_blades:
            prop = Propeller(prop.name, prop.radius, n_blades, prop.r, prop.chord, prop.theta, prop.pitch, prop.source)
        return prop
    if head.split() and head.split()[0].lower() == "r/r":
        return read_uiuc_geometry(path, diameter_in=diameter_in, n_blades=2 if n_blades is None else n_blades)
    raise GeometryFileError(f"{path}: unrecognised geometry format (expected UIUC 'r/R c/R beta' or an APC PE0 file)")


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


def read_uiuc_static(path) -> StaticRun:
    """Read a UIUC static file (``RPM CT CP``).

    Raises
    ------
    MeasurementFileError
    """
    path = Path(path)
    d = _read_table(path, ["RPM", "CT", "CP"], MeasurementFileError)
    run = path.stem.split("_static_")[-1]
    return StaticRun(run, d[:, 0], d[:, 1], d[:, 2], f"UIUC Propeller Data Site, {path.name}")


def read_uiuc_sweep(path) -> Sweep:
    """Read a UIUC wind-tunnel file ``<fam>_<D>x<P>_<run>_<RPM>.txt`` (``J CT CP eta``).

    The rotation rate is a ``RPM average = N`` line of the file when it has one (the
    measured mean), else the nominal rpm at the end of the file name. Other header and
    ``key = value`` lines are ignored.

    Raises
    ------
    MeasurementFileError
        Bad columns, or no rpm in the file or at the end of its name.
    """
    path = Path(path)
    d, meta = _read_table(path, ["J", "CT", "CP", "eta"], MeasurementFileError, with_meta=True)
    parts = path.stem.split("_")
    rpm = next((v for k, v in meta.items() if k.lower().replace(" ", "") in ("rpmaverage", "averagerpm", "rpm")), None)
    if rpm is None:
        try:
            rpm = float(parts[-1])
        except (ValueError, IndexError):
            raise MeasurementFileError(f"{path}: no rpm: neither an 'RPM average = N' line nor a nominal rpm at "
                                       "the end of the file name (<fam>_<D>x<P>_<run>_<RPM>.txt)") from None
    if not (math.isfinite(rpm) and rpm > 0):
        raise MeasurementFileError(f"{path}: rpm must be > 0, got {rpm!r}")
    run = parts[-2] if len(parts) >= 2 else path.stem
    return Sweep(run, rpm, d[:, 0], d[:, 1], d[:, 2], d[:, 3], f"UIUC Propeller Data Site, {path.name}")


def looks_like_uiuc(path) -> bool:
    """Whether ``path`` is a UIUC-format static (``RPM CT CP``) or wind-tunnel (``J CT CP eta``) file.

    Reads at most the first 64 KiB; False for anything unreadable.
    """
    try:
        with open(path, "rb") as fh:
            head = fh.read(65536).decode("latin-1")
    except OSError:
        return False
    for ln in head.splitlines()[:50]:
        words = [w.lower() for w in ln.split()]
        if words[:3] == ["rpm", "ct", "cp"] or words[:4] == ["j", "ct", "cp", "eta"]:
            return True
    return False
