"""The bundled propeller catalogue: UIUC Propeller Data Site vol. 1 and part of vol. 2 (geometry
and measurements), APC PE0 geometries for the APC propellers UIUC measured without one.

Sources: src/propmap/data/CITATION.md. Files are read with importlib.resources.
"""

from __future__ import annotations

import functools
import json
import os
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path

import numpy as np

from ..core.geometry import INCH, Propeller
from .inputs import short_path
from .geometry_files import read_apc_pe0, read_geometry, read_uiuc_geometry
from .nominal_geometry import propeller_from_size
from .readers import StaticRun, Sweep, read_uiuc_static, read_uiuc_sweep

__all__ = ["CatalogueEntry", "catalogue", "catalogue_source", "example_file", "example_files", "get_entry",
           "load_propeller", "near", "near_names", "resolve_propeller", "catalogue_sizes"]

UIUC_CITATION = ("UIUC Propeller Data Site vol. 1, Brandt & Selig, AIAA 2011-1255")
UIUC_V2_CITATION = ("UIUC Propeller Data Site vol. 2, Deters, Ananda & Selig, AIAA 2014-2151")
#: citation of each volume's measurements
VOLUME_CITATION = {1: UIUC_CITATION, 2: UIUC_V2_CITATION}
APC_CITATION = "APC Propellers PE0 geometry (v2022-0915)"


def _data_path(rel: str) -> Path:
    return Path(str(resources.files("propmap") / "data" / rel))


def example_files() -> tuple[str, ...]:
    """The names of the example files bundled with propmap (``data/examples``): the example
    vehicles (``quadrotor.toml``; ``neurobem_quadrotor.toml``, the NeuroBEM quadrotor of Bauersfeld
    et al., RSS 2021, with its lumped blade ``neurobem_5.1x4.8_geom.txt`` and its own parameter set
    ``neurobem_quadrotor.params.toml``, fitted to its flight logs) and synthetic level-flight data
    (``level_flight_synthetic.csv``); their sources in data/CITATION.md.

    Returns
    -------
    tuple of str
        Sorted file names.
    """
    return tuple(sorted(p.name for p in _data_path("examples").iterdir() if p.is_file()))


def example_file(name: str) -> Path:
    """The path of a bundled example file, wherever propmap is installed (a wheel's files live
    in site-packages, not in a source tree).

    Parameters
    ----------
    name : str
        A name of :func:`example_files`, or one without its extension (``"neurobem_quadrotor"``).

    Returns
    -------
    pathlib.Path
        The installed file (read it, never write to it).

    Raises
    ------
    TypeError
        ``name`` not a string.
    ValueError
        Not the name of a bundled example (the message lists them).

    Examples
    --------
    >>> import propmap as pm
    >>> veh = pm.read_vehicle(pm.example_file("neurobem_quadrotor.toml"))
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a bundled example's file name (str), got {type(name).__name__}")
    names = example_files()
    found = [n for n in names if name in (n, n.rsplit(".", 1)[0])]
    if len(found) != 1:
        raise ValueError(f"name: {name!r:.80} is not a bundled example; they are {', '.join(names)}")
    return _data_path("examples") / found[0]


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
    volume : {1, 2}
        UIUC Propeller Data Site volume of the measurements.
    beta_offset_deg : float
        Added to the geometry file's blade angles [deg] (a blade run at another setting than
        the one its file gives: NR640 at 20 deg).
    helical_pitch_in : float or None
        If set, the blade angles are the helix of this pitch, atan(P / (2 pi r)), on the
        file's chord (a DA-series design without a measured geometry of its own).
    note : str
        How the entry was derived where the files do not say it (tools/build_catalogue.py).

    ``pitch_in`` is None where the name gives no pitch (``union_u80``, ``cfnq_45p1``,
    ``pl_triturbo``).
    """

    name: str
    family: str
    diameter_in: float
    pitch_in: float | None
    n_blades: int
    geometry_format: str
    geometry_file: str
    static_files: tuple[str, ...]
    sweep_files: tuple[str, ...]
    volume: int = 1
    beta_offset_deg: float = 0.0
    helical_pitch_in: float | None = None
    note: str = ""

    @property
    def citation(self) -> str:
        """Sources of the geometry and the measurements, for figures and reports."""
        data = VOLUME_CITATION[self.volume]
        geo = data if self.geometry_format == "uiuc" else APC_CITATION
        extra = f" ({self.note})" if self.note else ""
        return f"geometry: {geo}{extra}; measurements: {data}"

    def static_runs(self) -> list[StaticRun]:
        """The bundled UIUC static runs.

        Returns
        -------
        list of StaticRun
            Read from the package's files (empty for a propeller without static data).
        """
        return [read_uiuc_static(_data_path(f)) for f in self.static_files]

    def sweeps(self) -> list[Sweep]:
        """The bundled UIUC wind-tunnel J-sweeps.

        Returns
        -------
        list of Sweep
            Read from the package's files (empty for a propeller without sweeps).
        """
        return [read_uiuc_sweep(_data_path(f)) for f in self.sweep_files]

    def data_paths(self) -> list[Path]:
        """The installed paths of the bundled UIUC files.

        Returns
        -------
        list of pathlib.Path
            The static runs' files, then the sweeps' (empty for a propeller without data).
        """
        return [_data_path(f) for f in (*self.static_files, *self.sweep_files)]


def catalogue() -> dict[str, CatalogueEntry]:
    """All bundled propellers, by name (147 entries: vol. 1, 79 UIUC geometries and 29 APC PE0;
    vol. 2, 39).

    Returns
    -------
    dict of str to CatalogueEntry
        A new dict each call (the entries are frozen): the file is read once per process; the
        data: UIUC Propeller Data Site vol. 1 and 2 and APC's PE0 geometry (each entry's
        ``citation``).
    """
    # (the cached dict itself was returned: catalogue().pop("apce_10x7") made load_propeller("apce_10x7") an
    # unknown propeller for the rest of the process, a user-level audit, 2026-11-30)
    return dict(_catalogue())  # (the module's own lookups read _catalogue(), without the copy)


@functools.lru_cache(maxsize=1)
def _catalogue() -> dict[str, CatalogueEntry]:
    raw = json.loads(_data_path("catalogue.json").read_text())
    return {
        e["name"]: CatalogueEntry(e["name"], e["family"], e["diameter_in"], e["pitch_in"], e["n_blades"],
                                  e["geometry"]["format"], e["geometry"]["file"],
                                  tuple(e["static"]), tuple(e["sweeps"]), volume=e.get("volume", 1),
                                  beta_offset_deg=e["geometry"].get("beta_offset_deg", 0.0),
                                  helical_pitch_in=e["geometry"].get("helical_pitch_in"), note=e.get("note", ""))
        for e in raw
    }


def get_entry(name: str) -> CatalogueEntry:
    """Catalogue entry by name.

    Parameters
    ----------
    name : str
        A catalogue propeller's name (``propmap props``), e.g. ``"apce_8x6"``.

    Returns
    -------
    CatalogueEntry

    Raises
    ------
    KeyError
        Unknown name; the message suggests close names.
    TypeError
        ``name`` not a str.
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a catalogue propeller's name (str), got {type(name).__name__}")
    cat = _catalogue()
    if name not in cat:
        raise KeyError(f"unknown propeller {name!r}{near_names(name, cat)}")
    return cat[name]


def near(name: str, names, cutoff: float = 0.6) -> list[str]:
    """The ``names`` near ``name``: the same but for case and blanks, else difflib's close
    matches (at most 3, ratio ``cutoff`` or more).

    Parameters
    ----------
    name : str
        What the user typed (a propeller, a parameter set, a column name).
    names : iterable of str
        The valid names.
    cutoff : float, optional
        :func:`difflib.get_close_matches`' similarity ratio, 0-1.

    Returns
    -------
    list of str
        The matches, best first; empty if none.
    """
    import difflib

    names = list(names)
    return [n for n in names if n.lower() == name.strip().lower()] or difflib.get_close_matches(
        name.strip(), names, n=3, cutoff=cutoff)


def near_names(name: str, names, otherwise: str = "; run 'propmap props' for the list") -> str:
    """'; did you mean A, B?' for the ``names`` :func:`near` ``name``, else ``otherwise`` (by
    default a pointer to ``propmap props``): the tail of an unknown-propeller message.

    Parameters
    ----------
    name : str
        The unknown name.
    names : iterable of str
        The valid names.
    otherwise : str, optional
        The tail where no name is near (default: a pointer to ``propmap props``).

    Returns
    -------
    str
        The tail, starting with ``"; "``, or ``otherwise``. A bare size (``8x6``) names the catalogue's
        propellers of that size in every family (``apce_8x6``, ``apcsf_8x6``, ...; at most 6).
    """
    names = list(names)
    key = name.strip().lower()
    # (a bare size matched no family's name by difflib's ratio: no suggestion, a user-level audit, 2026-11-28)
    sized = [n for n in names if key and n.lower().endswith("_" + key)]
    found = sized[:6] if sized else near(name, names)
    more = f" ({len(sized)} in all: 'propmap props')" if len(sized) > 6 else ""
    return f"; did you mean {', '.join(found)}?{more}" if found else otherwise


def catalogue_source(propeller: Propeller) -> str:
    """The citation of a catalogue propeller as :func:`load_propeller` gives it: the entry's
    citation where ``propeller`` carries a catalogue name, that citation as its ``source`` and
    the catalogue's blade geometry (``Propeller.same_geometry``), else "" (a user's geometry
    file, even under a catalogue name, whose ``source`` says which reader read it, and a
    catalogue propeller changed, are cited by nothing).

    Parameters
    ----------
    propeller : Propeller

    Returns
    -------
    str
    """
    entry = catalogue().get(propeller.name) if isinstance(propeller.name, str) else None
    if entry is None or propeller.source != entry.citation:
        return ""
    return entry.citation if propeller.same_geometry(load_propeller(entry.name)) else ""


def load_propeller(name: str) -> Propeller:
    """The geometry of a catalogue propeller as a :class:`Propeller`.

    Parameters
    ----------
    name : str
        A catalogue name (:func:`catalogue`, ``propmap props``).

    Returns
    -------
    Propeller
        Its blade stations (SI: r, chord [m], theta [rad]) with ``source`` the entry's citation.

    Raises
    ------
    KeyError
        Unknown name.
    TypeError
        ``name`` not a str.
    """
    if not isinstance(name, str):  # (before the cache: a list met "unhashable type", an API audit)
        raise TypeError(f"name must be a catalogue propeller's name (str), got {type(name).__name__}")
    return _load_propeller(name)


@functools.lru_cache(maxsize=256)
def _load_propeller(name: str) -> Propeller:
    """:func:`load_propeller`'s cached reading (one Propeller object per name)."""
    e = get_entry(name)
    path = _data_path(e.geometry_file)
    if e.geometry_format != "uiuc":
        return read_apc_pe0(path, name=e.name, source=e.citation)
    prop = read_uiuc_geometry(path, diameter_in=e.diameter_in, n_blades=e.n_blades, name=e.name, source=e.citation)
    if e.helical_pitch_in is not None:
        P = e.helical_pitch_in * INCH
        prop = replace(prop, theta=np.arctan(P / (2.0 * np.pi * prop.r)), pitch=P)
    if e.beta_offset_deg:
        prop = replace(prop, theta=prop.theta + np.radians(e.beta_offset_deg))
    return prop


def catalogue_sizes() -> dict:
    """Each catalogue propeller's size as its entry gives it (:class:`CatalogueEntry`).

    Returns
    -------
    dict
        name -> ``(diameter_in, pitch_in, n_blades)``: the nominal sizes of the names, in
        inches for the millimetre-named families too; ``pitch_in`` None where the name gives
        no pitch, the helix of the blade angle at 0.75 R for vol. 2's NR640 blades.
    """
    return {n: (e.diameter_in, e.pitch_in, e.n_blades) for n, e in _catalogue().items()}


def resolve_propeller(spec: str, *, diameter_in: float | None = None, n_blades: int | None = None) -> Propeller:
    """A catalogue name, a path to a geometry file (UIUC ``r/R c/R beta``, APC PE0, QPROP) or a
    size designation (``"9x4.5"``, ``"5x4.5x3"``: a nominal blade).

    Parameters
    ----------
    spec : str or os.PathLike
        A catalogue name (``propmap props``), the path of a geometry file, or, where no file
        of that name exists, a size designation ``DxP`` or ``DxPxB`` in inches
        (:func:`propmap.io.nominal_geometry.propeller_from_size`: the helix of the pitch on
        the catalogue's median chord, said in a warning).
    diameter_in, n_blades
        For a geometry file, as :func:`propmap.io.geometry_files.read_geometry`; for a size
        designation, they must agree with it (``n_blades`` the blade count where it has no
        third figure, default 2); a catalogue propeller's own are used.

    Returns
    -------
    Propeller

    Raises
    ------
    KeyError
        ``spec`` is neither a catalogue name nor an existing file: the message says what it
        looks like (empty, a folder, something other than a file, a missing file, or an
        unknown name), with close catalogue names suggested.
    GeometryFileError
        The file is malformed.
    ValueError
        A size designation whose figures are out of range or unlike ``diameter_in`` /
        ``n_blades``.
    TypeError
        ``spec`` neither a str nor an os.PathLike.

    Warns
    -----
    UserWarning
        As the geometry readers (e.g. stations stopping short of the tip); a catalogue name
        that is also a file in the working folder (the catalogue's propeller is used); a
        nominal blade built from a size designation.
    """
    if isinstance(spec, os.PathLike):  # (a pathlib.Path met "'PosixPath' object has no attribute 'strip'")
        return read_geometry(spec, diameter_in=diameter_in, n_blades=n_blades)
    if not isinstance(spec, str):
        raise TypeError(f"the propeller must be a catalogue name or a geometry file's path, got {type(spec).__name__}")
    if spec in _catalogue():
        if Path(spec).is_file():
            import warnings

            warnings.warn(f"{spec!r} is a catalogue propeller and a file here: the catalogue's is used (give "
                          f"./{spec} for the file)", UserWarning, stacklevel=2)
        return load_propeller(spec)
    shown = short_path(spec, 120, quote=True)
    if not spec.strip():
        raise KeyError("the propeller is empty: give a catalogue name, a geometry file or a size (9x4.5)")
    path = Path(spec)
    try:  # (a name past the system's limit met "OSError: File name too long", an API audit)
        kind = "file" if path.is_file() else "folder" if path.is_dir() else "other" if path.exists() else None
    except OSError as exc:
        raise KeyError(f"{shown}: {exc.strerror or exc}: not a catalogue name, nor a geometry file") from None
    if kind == "file":
        return read_geometry(spec, diameter_in=diameter_in, n_blades=n_blades)
    if kind == "folder":
        raise KeyError(f"{shown} is a folder, not a catalogue name or a geometry file")
    if kind == "other":
        raise KeyError(f"{shown} is not a regular file")
    nominal = propeller_from_size(spec, diameter_in=diameter_in, n_blades=n_blades,  # ("9x4.5": no geometry file)
                                  catalogue_sizes=catalogue_sizes())
    if nominal is not None:
        return nominal
    if len(path.parts) > 1 or path.suffix.lower() in (".txt", ".pe0", ".dat", ".csv"):  # a path: no file there
        import difflib

        near = difflib.get_close_matches(path.name.split(".")[0].replace("-PERF", ""), _catalogue(), n=3)
        hint = f"; did you mean the catalogue's {', '.join(near)}?" if near else ""
        raise KeyError(f"no file {shown}, and no catalogue propeller of that name{hint}")
    code = (" (a maker's code as 1045 or 5045 is written 10x4.5 or 5x4.5 here: its figures are read one way by one "
            "maker and another by the next, so propmap does not guess)" if spec.strip().isdigit() else "")
    raise KeyError(f"unknown propeller {spec!r}" + (near_names(spec, _catalogue(), otherwise="") or
                   ": not in the catalogue ('propmap props' lists it), nor a file; a propeller without a geometry "
                   f"file is given by its size, 9x4.5 (D x P in inches: a nominal blade){code}"))
