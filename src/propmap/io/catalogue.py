"""The bundled propeller catalogue (UIUC vol. 1 and APC PE0 geometries, UIUC measurements).

Sources: src/propmap/data/CITATION.md. Files are read with importlib.resources.
"""

from __future__ import annotations

import functools
import json
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from ..core.geometry import Propeller
from .readers import StaticRun, Sweep, read_apc_pe0, read_geometry, read_uiuc_geometry, read_uiuc_static, read_uiuc_sweep

__all__ = ["CatalogueEntry", "catalogue", "get_entry", "load_propeller", "resolve_propeller"]

UIUC_CITATION = ("UIUC Propeller Data Site vol. 1, Brandt & Selig, AIAA 2011-1255")
APC_CITATION = "APC Propellers PE0 geometry (v2022-0915)"


def _data_path(rel: str) -> Path:
    return Path(str(resources.files("propmap") / "data" / rel))


@dataclass(frozen=True)
class CatalogueEntry:
    """One catalogue propeller.

    Attributes
    ----------
    name : str
        UIUC-style name ``<family>_<D>x<P>``, e.g. ``"apce_8x6"``.
    family : str
        UIUC family code (apce = APC Thin Electric, apcsf = Slow Flyer, apcsp = Sport, ...).
    diameter_in, pitch_in : float
        Nominal diameter and pitch [in] (from the name).
    n_blades : int
    geometry_format : {"uiuc", "apc_pe0"}
    geometry_file : str
        Path relative to the package data folder.
    static_files, sweep_files : tuple of str
        Bundled UIUC measurement files (relative paths).
    """

    name: str
    family: str
    diameter_in: float
    pitch_in: float
    n_blades: int
    geometry_format: str
    geometry_file: str
    static_files: tuple[str, ...]
    sweep_files: tuple[str, ...]

    @property
    def citation(self) -> str:
        """Sources of the geometry and the measurements, for figures and reports."""
        geo = UIUC_CITATION if self.geometry_format == "uiuc" else APC_CITATION
        return f"geometry: {geo}; measurements: {UIUC_CITATION}"

    def static_runs(self) -> list[StaticRun]:
        """The bundled UIUC static runs (may be empty)."""
        return [read_uiuc_static(_data_path(f)) for f in self.static_files]

    def sweeps(self) -> list[Sweep]:
        """The bundled UIUC wind-tunnel J-sweeps (may be empty)."""
        return [read_uiuc_sweep(_data_path(f)) for f in self.sweep_files]


@functools.lru_cache(maxsize=1)
def catalogue() -> dict[str, CatalogueEntry]:
    """All bundled propellers, by name (108 entries: 79 UIUC geometries, 29 APC PE0)."""
    raw = json.loads(_data_path("catalogue.json").read_text())
    return {
        e["name"]: CatalogueEntry(e["name"], e["family"], e["diameter_in"], e["pitch_in"], e["n_blades"],
                                  e["geometry"]["format"], e["geometry"]["file"],
                                  tuple(e["static"]), tuple(e["sweeps"]))
        for e in raw
    }


def get_entry(name: str) -> CatalogueEntry:
    """Catalogue entry by name.

    Raises
    ------
    KeyError
        Unknown name; the message suggests close names.
    """
    cat = catalogue()
    if name not in cat:
        import difflib

        near = difflib.get_close_matches(name, cat, n=3)
        hint = f"; did you mean {', '.join(near)}?" if near else "; run 'propmap props' for the list"
        raise KeyError(f"unknown propeller {name!r}{hint}")
    return cat[name]


@functools.lru_cache(maxsize=256)
def load_propeller(name: str) -> Propeller:
    """The geometry of a catalogue propeller as a :class:`Propeller`.

    Raises
    ------
    KeyError
        Unknown name.
    """
    e = get_entry(name)
    path = _data_path(e.geometry_file)
    if e.geometry_format == "uiuc":
        return read_uiuc_geometry(path, diameter_in=e.diameter_in, n_blades=e.n_blades, name=e.name,
                                  source=e.citation)
    return read_apc_pe0(path, name=e.name, source=e.citation)


def resolve_propeller(spec: str, *, diameter_in: float | None = None, n_blades: int | None = None) -> Propeller:
    """A catalogue name or a path to a geometry file (UIUC ``r/R c/R beta`` or APC PE0).

    Raises
    ------
    KeyError
        ``spec`` is neither a catalogue name nor an existing file.
    GeometryFileError
        The file is malformed.
    """
    if spec in catalogue():
        return load_propeller(spec)
    if Path(spec).is_file():
        return read_geometry(spec, diameter_in=diameter_in, n_blades=n_blades)
    get_entry(spec)  # raises KeyError with suggestions
    raise AssertionError("unreachable")
