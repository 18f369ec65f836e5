"""Rotor-map files: the netCDF reader for hostile files and the writers of a map with its
JSON sidecar (the checks every map passes: io/mapcheck.py).

A map file is input like any other (docs/cli.md): it may be truncated, mutated, edited by
hand or crafted. :func:`read_dataset` reads only regular files, refuses declared sizes
beyond :data:`MAX_NODES` before reading any data, reads only the variables a map has, and
turns whatever the netCDF/HDF5 libraries raise into a ValueError naming the file.
:func:`check_dataset` then holds every axis, variable and attribute to the ranges of the
maps ``propmap map`` and :func:`propmap.maps.build_map` make, so that a map answers only
inside the model that made it.

The checks and their ranges are in io/mapcheck.py; the names of this module's ``__all__``
(``check_dataset``, ``check_propeller``, ``map_model``, ``MAX_NODES``) are importable from here too.

A damaged file can make the netCDF/HDF5 libraries loop forever inside a C call, where no
signal reaches Python (a file with one byte changed was seen to). :func:`read_dataset`
therefore reads the file first in a child process (``fork``) and refuses it when that read
does not finish within :func:`open_timeout`: the caller never hangs, and SIGTERM and
Ctrl-C keep working meanwhile. A daemonic process (a multiprocessing pool's or a Dask
worker) may start no child: there the file is read in-process, without that guard.

Threads: the netCDF-C and HDF5 libraries are not thread-safe; every read and write of a map
by propmap holds :data:`NETCDF_LOCK`, so that propmap's own reads and writes in one process run
one at a time (a caller's own netCDF or HDF5 calls from other threads, xarray's included, are
not serialised with them unless the caller holds the lock too). A fork while a thread holds
the libraries leaves the child's copy of them in that state: a fork-based pool started while
a thread reads a map may hang its workers (use ``spawn`` or ``forkserver``).
"""

from __future__ import annotations

import json
import math
import os
import stat
import threading
from pathlib import Path

import numpy as np

from ..core.geometry import short_repr
from .inputs import as_path, short_path
from .netcdf_write import to_netcdf_here
from .mapcheck import (DERIVED, DIMS, FLAGS, LOADS, MAX_NODES, SIDE_LOADS, check_dataset, check_propeller,
                       map_model)

__all__ = ["MAX_NODES", "check_dataset", "check_propeller", "map_model", "map_props", "read_dataset", "read_sidecar",
           "sidecar_path", "write_map", "write_sidecar", "write_with_sidecar"]

#: the largest map file read (a map of MAX_NODES nodes is about 1.3 GB)
MAX_FILE_BYTES = 4 * 2**30
#: the child read of a map file may take this long [s], plus OPEN_SECONDS_PER_GB per GiB
OPEN_TIMEOUT = 20.0
OPEN_SECONDS_PER_GB = 60.0
#: the longest propeller name of a map over several, written as fixed-length characters
MAX_NAME_CHARS = 256
#: held around every read and write of a map file: the netCDF-C and HDF5 libraries are not thread-safe (two
#: threads opening map files crashed the interpreter, SIGSEGV, in 3 of 3 runs, and writing them in 1 of 2: a
#: parallel-use audit, 2026-11-27); one process's map files are read and written one at a time
NETCDF_LOCK = threading.RLock()


# ---------------------------------------------------------------- reading a file

def _stat_regular(path):
    """(the path as shown in messages, its os.stat) of a map file that must be a regular file
    of at most MAX_FILE_BYTES.

    Raises
    ------
    ValueError
        The path cannot be stat-ed, is a folder, device or pipe, or is larger than
        MAX_FILE_BYTES.
    """
    where = short_path(path)
    try:
        st = os.stat(path)
    except (OSError, ValueError) as exc:
        raise ValueError(f"{where}: {getattr(exc, 'strerror', None) or exc}") from None
    if not stat.S_ISREG(st.st_mode):
        raise ValueError(f"{where}: not a regular file (a folder, device or pipe); a map is a netCDF file")
    if st.st_size > MAX_FILE_BYTES:
        raise ValueError(f"{where}: {st.st_size:,} bytes; a map file is at most {MAX_FILE_BYTES:,}")
    return where, st


def _layout(path, where: str) -> list[str]:
    """Read the file's dimensions and variables (no data); refuse a layout that is not a
    map's or declares more than MAX_NODES nodes. Returns the variables not to read."""
    import netCDF4

    wanted = {*LOADS, *SIDE_LOADS, *DERIVED, *FLAGS, *DIMS, "omega", "incidence", "prop"}
    with netCDF4.Dataset(path, "r") as nc:
        sizes = {name: len(dim) for name, dim in nc.dimensions.items()}
        variables = {name: tuple(v.dimensions) for name, v in nc.variables.items()}
    for name, dims in variables.items():
        if name not in wanted:
            continue
        if (name == "prop" and len(dims) == 2 and dims[0] == "prop" and dims[1] not in DIMS
                and sizes.get(dims[1], 0) <= MAX_NAME_CHARS):
            continue  # names as fixed-length characters (prop, their length), as `propmap map --all` writes them
        n = math.prod(sizes.get(d, 0) for d in dims)
        if n > MAX_NODES or not set(dims) <= {*DIMS, "prop"}:
            raise ValueError(f"{where}: variable {name} of dimensions {', '.join(dims)} "
                             f"({' x '.join(str(sizes.get(d, 0)) for d in dims)}) is not a map's "
                             f"(the dimensions {', '.join(DIMS)} and prop, at most {MAX_NODES:,} nodes)")
    return [name for name in variables if name not in wanted]


def open_timeout(size: int) -> float:
    """Seconds the child read of a map file of ``size`` bytes may take (module docstring)."""
    return OPEN_TIMEOUT + OPEN_SECONDS_PER_GB * size / 2**30


def _probe_child(path, conn) -> None:
    """In the child: open the file and read every map variable, then report (never raises)."""
    try:
        import netCDF4

        wanted = {*LOADS, *SIDE_LOADS, *DERIVED, *FLAGS, *DIMS, "omega", "incidence", "prop"}
        with netCDF4.Dataset(path, "r") as nc:
            for name, var in nc.variables.items():
                if name in wanted and math.prod(var.shape) <= MAX_NODES:
                    var[...]
        conn.send(None)
    except BaseException as exc:  # noqa: BLE001 -- reported to the parent, which decides
        try:
            conn.send(f"{type(exc).__name__}: {' '.join(str(exc).split())[:200]}")
        except BaseException:  # noqa: BLE001
            pass
    finally:
        conn.close()


def _probe(path, where: str, size: int) -> None:
    """Read the file in a child process first (module docstring); refuse it when the read
    does not end within :func:`open_timeout`. Errors found there are left to the reader,
    which names them as usual."""
    import multiprocessing as mp

    if mp.current_process().daemon:  # (a pool's or Dask's worker may start no child: AssertionError, "daemonic
        return  # processes are not allowed to have children"; a parallel-use audit, 2026-11-27) read in-process
    methods = mp.get_all_start_methods()
    ctx = mp.get_context("fork" if "fork" in methods else methods[0])
    recv, send = ctx.Pipe(duplex=False)
    child = ctx.Process(target=_probe_child, args=(os.fspath(path), send), daemon=True)
    with NETCDF_LOCK:  # (a fork while another thread is inside HDF5 hung the child: a good file refused, a review)
        child.start()
    send.close()
    limit = open_timeout(size)
    try:
        done = recv.poll(limit)
    finally:
        if child.is_alive() and not recv.poll(0):
            child.kill()
        child.join(5.0)
        recv.close()
    if not done:
        raise ValueError(f"{where}: not a readable netCDF rotor map (the netCDF/HDF5 libraries did not finish "
                         f"reading it within {limit:.0f} s: a damaged file)")


def map_props(path) -> tuple[str, ...] | None:
    """The propellers of a map file over several (``propmap map --all``), or None for a map
    of one.

    Parameters
    ----------
    path : str or os.PathLike
        The map file (netCDF).

    Returns
    -------
    tuple of str or None
        The names of the ``prop`` coordinate, in the file's order; None where the file has
        no ``prop`` variable.

    Raises
    ------
    TypeError, ValueError
        As :func:`read_dataset` (the file is read in a child first, its layout checked),
        and a ``prop`` coordinate that is empty or holds a name twice.
    """
    import netCDF4

    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a str or os.PathLike (a map file), got {type(path).__name__}")
    where, st = _stat_regular(path)
    _probe(path, where, st.st_size)
    try:
        with NETCDF_LOCK:
            _layout(path, where)
            with netCDF4.Dataset(path, "r") as nc:
                if "prop" not in nc.variables:
                    return None
                names = [str(n) for n in np.asarray(nc.variables["prop"][:]).ravel()]
    except (ValueError, MemoryError):  # (MemoryError: too large for the memory, not a damaged file; the CLI says so)
        raise
    except Exception as exc:  # noqa: BLE001 -- the netCDF/HDF5 libraries raise anything on a damaged file
        raise ValueError(f"{where}: not a readable netCDF rotor map ({type(exc).__name__}: "
                         f"{' '.join(str(exc).split())[:200]})") from None
    if not names or len(set(names)) != len(names):
        raise ValueError(f"{where}: the prop coordinate must hold distinct propeller names")
    return tuple(names)


def read_dataset(path, prop: str | None = None):
    """Read one propeller's map from a netCDF file, as hostile input.

    Parameters
    ----------
    path : str or os.PathLike
    prop : str, optional
        The propeller of a map over several (a ``prop`` dimension).

    Returns
    -------
    xarray.Dataset
        Loaded into memory (the file is closed), not yet checked (:func:`check_dataset`).

    Raises
    ------
    TypeError
        ``path`` not a str or path, ``prop`` not a str.
    ValueError
        Not a regular file (a folder, device, pipe: refused before opening), larger than
        4 GiB, not readable netCDF (whatever the netCDF/HDF5 libraries raise), a variable
        of a map with dimensions not a map's or declaring more than MAX_NODES nodes
        (refused before reading data), a read that does not end within
        :func:`open_timeout` (a damaged file; module docstring), or ``prop`` missing or unknown for a map over
        several propellers, or their metadata (``per_prop_json``) malformed. The message
        names the file.
    """
    import xarray as xr

    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a str or os.PathLike (a map file), got {type(path).__name__}")
    if prop is not None and not isinstance(prop, str):
        raise TypeError(f"prop must be a propeller name (str) or None, got {type(prop).__name__}")
    where, st = _stat_regular(path)
    _probe(path, where, st.st_size)
    try:
        with NETCDF_LOCK:
            unused = _layout(path, where)
            with xr.open_dataset(path, engine="netcdf4", drop_variables=unused) as ds:
                if "prop" in ds.dims:
                    ds = _select(ds, prop, where)
                elif prop is not None and prop != ds.attrs.get("propeller"):
                    raise ValueError(f"{where}: a map of {short_repr(ds.attrs.get('propeller'))}, not of {prop!r}")
                return ds.load()
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith(where) else f"{where}: not a readable netCDF rotor map ({msg})") \
            from None
    except MemoryError:  # (too large for the memory, not a damaged file: the CLI says so)
        raise
    except Exception as exc:  # noqa: BLE001 -- the netCDF/HDF5 libraries raise anything on a damaged file
        raise ValueError(f"{where}: not a readable netCDF rotor map ({type(exc).__name__}: "
                         f"{' '.join(str(exc).split())[:200]})") from None


def _select(ds, prop, where: str):
    """One propeller of a map over several, with its own metadata as attributes."""
    values = ds["prop"].values
    if ds["prop"].dims != ("prop",) or values.dtype.kind not in "USO" or len(set(map(str, values))) != values.size:
        raise ValueError(f"{where}: the prop coordinate must hold distinct propeller names")
    names = [str(n) for n in values]
    if prop not in names:
        raise ValueError(f"{where}: a map of {len(names)} propellers; give prop= one of them "
                         f"(e.g. {', '.join(names[:3])}), got {prop!r}")
    text = ds.attrs.get("per_prop_json")
    try:
        per_prop = json.loads(text) if isinstance(text, str) else None
    except ValueError:
        per_prop = None
    if not isinstance(per_prop, dict) or not isinstance(per_prop.get(prop), dict):
        raise ValueError(f"{where}: a map of several propellers needs the attribute per_prop_json, a JSON object "
                         f"with an object for {prop!r}")
    attrs = {k: (np.asarray(v) if isinstance(v, list) else v) for k, v in per_prop[prop].items()}
    kept = {k: v for k, v in ds.attrs.items() if k != "per_prop_json"}
    out = ds.sel(prop=prop, drop=True)
    out.attrs = {**kept, **attrs}  # (assign_attrs updates: the JSON of every propeller stayed on each one's map)
    return out


# ---------------------------------------------------------------- writing

def sidecar_path(path) -> Path:
    """The JSON sidecar of a map file: ``<path>.json``.

    Parameters
    ----------
    path : str or Path
        The map file, e.g. ``m.nc``.

    Returns
    -------
    Path
        The same folder, the file name with ``.json`` appended (``m.nc.json``).
    """
    path = as_path(path)
    return path.with_name(path.name + ".json")


def written_path(path) -> Path:
    """Where :func:`write_with_sidecar` writes the map file ``path``: the file a symbolic link to
    an existing file points to (written through, io.atomic), else ``path``; its sidecar is
    :func:`sidecar_path` of this, beside the file, not beside the link, where opening the file
    found none (a review). A command checks that sidecar, not one beside the link (a
    link's sidecar overwrote an input file of that name beside its target: an audit, stop 100).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    Path
    """
    path = as_path(path)
    try:
        if path.is_symlink() and path.exists():
            return Path(os.path.realpath(path))
    except OSError:  # (a name too long for the system: the caller's checks name it, `--out: File name too long`)
        pass
    return path


def _json_safe(value):
    """``value`` with every non-finite float replaced by None (JSON null): strict JSON."""
    if isinstance(value, dict):
        return {k: _json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_json_safe(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def map_metadata(ds) -> dict:
    """A map's metadata as its sidecar holds it (strict JSON values): its attributes (propeller,
    parameter set, air, model, measured error), ``dims`` (axis sizes), ``axes`` (each axis'
    first and last value in its own unit: ``rpm`` [rpm], ``airspeed`` [m/s], ``incidence_deg``
    [deg]) and ``variables`` (each variable's unit).

    Parameters
    ----------
    ds : xarray.Dataset
        A map as :func:`propmap.maps.build_map` writes it, with the axes ``rpm``, ``airspeed``
        and ``incidence_deg``.

    Returns
    -------
    dict
        JSON-safe: NumPy values as Python ones, non-finite floats as None.

    Raises
    ------
    KeyError
        An axis of the map is missing.
    """
    meta = {k: (v.tolist() if isinstance(v, np.ndarray) else v.item() if isinstance(v, np.generic) else v)
            for k, v in ds.attrs.items()}
    meta["dims"] = {d: int(n) for d, n in ds.sizes.items()}
    meta["axes"] = {d: [float(ds[d].values[0]), float(ds[d].values[-1])] for d in DIMS}
    meta["variables"] = {k: ds[k].attrs.get("units", "") for k in ds.data_vars}
    return _json_safe(meta)


def _sidecar_text(ds, describes: dict | None) -> str:
    meta = map_metadata(ds)
    if describes is not None:
        meta["describes"] = describes
    return json.dumps(meta, indent=2, allow_nan=False)


def write_with_sidecar(ds, path, write) -> list[Path]:
    """Write a map file with ``write(tmp_path)`` and its sidecar, as a pair
    (io.atomic.atomic_paths): the sidecar, derived from the map's attributes, names the
    map file and its SHA-256 (``describes``), which :func:`read_sidecar` checks.

    Parameters
    ----------
    ds : xarray.Dataset
        The map: the sidecar holds its attributes, sizes, axis ranges (``rpm``,
        ``airspeed``, ``incidence_deg``) and variable units.
    path : str or Path
        The map file; the sidecar is :func:`sidecar_path` of it (of the file a symbolic link
        points to, which is written through).
    write : callable
        ``write(tmp)`` writes the map file's content to the temporary path ``tmp``
        (a :class:`~pathlib.Path` beside ``path``, existing and empty).

    Returns
    -------
    list of Path
        The map file and the sidecar.

    Raises
    ------
    OSError
        The files cannot be written.
    """
    from .atomic import atomic_paths, file_sha256

    path = written_path(path)
    side = sidecar_path(path)
    with atomic_paths([path, side]) as (tmp, tmp_side):
        write(tmp)
        tmp_side.write_text(_sidecar_text(ds, {"file": path.name, "sha256": file_sha256(tmp)}), encoding="utf-8")
    return [path, side]


def write_map(ds, path, fmt: str = "netcdf", *, sidecar: bool = True) -> list[Path]:
    """Write a map atomically: netCDF (``fmt="netcdf"``) or a long-form CSV (``"csv"``),
    plus a JSON sidecar ``<path>.json`` of its metadata and measured error, written as a pair
    (:func:`write_with_sidecar`).

    Parameters
    ----------
    ds : xarray.Dataset
        The map (:func:`propmap.maps.build_map`).
    path : str or Path
        The map file; its folder is created if missing.
    fmt : {"netcdf", "csv"}
        netCDF4 with every variable compressed (zlib, level 4; the names of a ``prop``
        coordinate as fixed-length characters), or CSV: one row per node,
        the axes ``rpm``, ``airspeed``, ``incidence_deg`` and every variable as columns
        (the coordinates ``omega`` and ``incidence`` left out), numbers to 10 significant
        digits, flags ``true``/``false``.
    sidecar : bool
        Write the sidecar ``<path>.json`` too (:func:`sidecar_path`).

    Returns
    -------
    list of Path
        The files written: ``[path, <path>.json]``, or ``[path]`` without ``sidecar``.

    Raises
    ------
    ValueError
        Unknown format, an empty path, or (netCDF) a name of a ``prop`` coordinate longer
        than MAX_NAME_CHARS bytes (UTF-8).
    TypeError
        ``ds`` not an xarray Dataset.
    OSError
        The folder cannot be written.
    """
    import xarray as xr

    if not isinstance(ds, xr.Dataset):
        raise TypeError(f"ds must be an xarray.Dataset (a map from build_map), got {type(ds).__name__}")
    if not os.fspath(path):
        raise ValueError("path is empty: give the map file to write")
    if fmt not in ("netcdf", "csv"):
        raise ValueError(f"unknown map format {fmt!r} (netcdf or csv)")
    names_as_text = "prop" in ds.variables and ds["prop"].dtype.kind in "UO"  # a map over several propellers
    if fmt == "netcdf" and names_as_text:
        longest = max((len(str(n).encode("utf-8")) for n in ds["prop"].values.ravel()), default=0)
        if longest > MAX_NAME_CHARS:  # (the reader refuses longer ones)
            raise ValueError(f"a propeller name of the prop coordinate is {longest} bytes long (UTF-8); a map file "
                             f"holds names of at most {MAX_NAME_CHARS}")

    def write(tmp):
        if fmt == "netcdf":
            encoding = {k: {"zlib": True, "complevel": 4} for k in ds.data_vars}
            if names_as_text:
                # fixed-length characters, not netCDF-4 variable-length strings: a file with those,
                # held open lazily by xarray and opened again in the same process, crashes Python
                # (segmentation fault; netCDF4 1.7.5 with netCDF-C 4.10.1, 2026-11-26)
                encoding["prop"] = {"dtype": "S1"}
            from .atomic import signals_held

            with NETCDF_LOCK, signals_held():  # (a signal inside HDF5's write deadlocked it: atomic.signals_held)
                to_netcdf_here(ds, tmp, encoding=encoding)
        else:
            table = ds.drop_vars(["omega", "incidence"]).to_dataframe().reset_index()
            for f in FLAGS:
                table[f] = np.where(table[f].to_numpy(bool), "true", "false")
            with open(tmp, "w", newline="", encoding="utf-8") as fh:
                table.to_csv(fh, index=False, float_format="%.10g", lineterminator="\n")

    if sidecar:
        return write_with_sidecar(ds, path, write)
    from .atomic import atomic_path

    with atomic_path(path) as tmp:
        write(tmp)
    return [Path(path)]


def write_sidecar(ds, path) -> Path:
    """Write a map's metadata and measured error as JSON (atomically): its attributes, sizes,
    axis ranges and variable units; a value that is not finite (an error with no point
    to measure it) is written as null. Without the map file it describes: prefer
    :func:`write_map` or :func:`write_with_sidecar`, which write both as a pair.

    Parameters
    ----------
    ds : xarray.Dataset
        The map.
    path : str or Path
        The sidecar file itself (e.g. :func:`sidecar_path` of the map file); written
        without a ``describes`` entry.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    TypeError
        ``path`` not a str or os.PathLike.
    OSError
        The file cannot be written.
    """
    from .atomic import atomic_write

    path = as_path(path)
    with atomic_write(path) as fh:
        fh.write(_sidecar_text(ds, None))
    return path


def read_sidecar(path) -> dict:
    """The sidecar of the map file ``path``, checked against the map it describes.

    Parameters
    ----------
    path : str or Path
        The map file (``m.nc``; its sidecar is ``m.nc.json``).

    Returns
    -------
    dict

    Raises
    ------
    ValueError
        The sidecar is missing, not JSON, or describes another version of the map (its
        SHA-256 differs: the map was rewritten since, or the pair is being replaced).
    """
    from .atomic import file_sha256

    side = sidecar_path(path)
    try:
        with open(side, encoding="utf-8") as fh:
            meta = json.load(fh)
        digest = file_sha256(path)
    except (OSError, ValueError) as exc:
        raise ValueError(f"{short_path(side)}: cannot read the sidecar of {short_path(path)} "
                         f"({getattr(exc, 'strerror', None) or exc})") from None
    described = meta.get("describes") if isinstance(meta, dict) else None
    if not isinstance(described, dict) or described.get("sha256") != digest:
        raise ValueError(f"{short_path(side)} does not describe {short_path(path)} as it is now (SHA-256 differs): "
                         "the map was rewritten without it, or the pair is being replaced; read both again")
    return meta
