"""Rotor-map files: the checks every map passes, the netCDF reader for hostile files, and
the writers of a map with its JSON sidecar.

A map file is input like any other (docs/cli.md): it may be truncated, mutated, edited by
hand or crafted. :func:`read_dataset` reads only regular files, refuses declared sizes
beyond :data:`MAX_NODES` before reading any data, reads only the variables a map has, and
turns whatever the netCDF/HDF5 libraries raise into a ValueError naming the file.
:func:`check_dataset` then holds every axis, variable and attribute to the ranges of the
maps ``propmap map`` and :func:`propmap.maps.build_map` make (the table below), so that a
map answers only inside the model that made it.

==========================  ===========================================================
axis rpm                    Omega = rpm 2 pi / 60 in [0.1, 1e5] rad/s, strictly increasing
axis airspeed               [0, 500] m/s
axis incidence_deg          [0, 180] deg
nodes                       at least 2 per axis, at most 20,000,000 in all (MAX_NODES)
loads                       finite at every converged node; at least one converged node;
                            |thrust|, |drag| <= 1e5 N, |torque|, |rolling_moment| <= 1e4 N m
                            (the load data files' ranges)
flags                       boolean (or 0/1)
diameter_m                  [0.0127, 2.54] m (the CLI's --diameter-in range, 0.5-100 in)
n_blades                    an integer in [1, 100] (the PE0 reader's range)
rho_kg_m3, mu_Pa_s, ...     as in parameter files (io.params_file.FILE_RANGES)
n_radial, n_azimuth         as :class:`propmap.Discretization`
geometry_*                  1-D arrays of at most 10,000 numbers (a valid Propeller) whose
                            outermost station is the tip, diameter_m / 2 (within 1e-6)
check_points                an integer in [0, 1,000,000]; check_seed an integer >= 0
check_<m>_<load>_<stat>     a number >= 0, or NaN (no point to measure it)
text attributes             strings
==========================  ===========================================================

Numbers are never bools, strings or arrays where one number is expected.

A damaged file can make the netCDF/HDF5 libraries loop forever inside a C call, where no
signal reaches Python (a file with one byte changed was seen to). :func:`read_dataset`
therefore reads the file first in a child process (``fork``) and refuses it when that read
does not finish within :func:`open_timeout`: the caller never hangs, and SIGTERM and
Ctrl-C keep working meanwhile.
"""

from __future__ import annotations

import json
import math
import numbers
import os
import re
import stat
from pathlib import Path

import numpy as np

__all__ = ["MAX_NODES", "check_dataset", "check_propeller", "map_model", "map_props", "read_dataset", "read_sidecar",
           "sidecar_path", "write_map", "write_sidecar", "write_with_sidecar"]

RPM = 2 * math.pi / 60  # rad/s per rpm
DIMS = ("rpm", "airspeed", "incidence_deg")
#: the loads a map interpolates, the derived variables and the node flags
LOADS = ("thrust", "drag", "torque", "rolling_moment")
DERIVED = ("power", "CT", "CP")
FLAGS = ("converged", "vortex_ring", "multiple_roots", "reverse_flow")
UNITS = {"thrust": "N", "drag": "N", "torque": "N m", "rolling_moment": "N m", "power": "W", "CT": "1", "CP": "1",
         "rpm": "rpm", "airspeed": "m/s", "incidence_deg": "degree", "omega": "rad/s", "incidence": "rad"}
#: the most nodes a map may hold (all propellers of a ``prop`` dimension together): what
#: ``propmap map`` builds in about 8 minutes on 2 cores, 1.3 GB of tables
MAX_NODES = 20_000_000
#: the largest map file read (a map of MAX_NODES nodes is about 1.3 GB)
MAX_FILE_BYTES = 4 * 2**30
#: SI ranges of the axes: Omega [rad/s], V [m/s], beta [rad] (the solver's)
OMEGA_RANGE = (0.1, 1e5)
AIRSPEED_RANGE = (0.0, 500.0)
INCIDENCE_RANGE = (0.0, math.pi)
DIAMETER_RANGE = (0.5 * 0.0254, 100 * 0.0254)  # [m]
N_BLADES_RANGE = (1, 100)
MAX_STATIONS = 10_000
CHECK_POINTS_MAX = 1_000_000
#: largest |value| of each load at a node (the load data files' ranges, identify.data.RANGES)
LOAD_LIMITS = {"thrust": 1e5, "drag": 1e5, "torque": 1e4, "rolling_moment": 1e4}
#: the child read of a map file may take this long [s], plus OPEN_SECONDS_PER_GB per GiB
OPEN_TIMEOUT = 20.0
OPEN_SECONDS_PER_GB = 60.0
_CHECK_KEY = re.compile(r"check_(linear|cubic)_(thrust|drag|torque|rolling_moment|power)_(rms|max|max_flagged)")
_TEXT = ("title", "propeller", "propeller_source", "section_model", "params_label", "params_json", "model",
         "citation", "propmap_version", "interpolation", "Conventions", "check_normalisation", "note",
         "model_uncertainty_axial", "model_uncertainty_off_axis")


def _short(value, n: int = 60) -> str:
    r = repr(value.tolist() if isinstance(value, (np.ndarray, np.generic)) else value)
    return r if len(r) <= n else r[: n - 4] + " ..."


def _number(attrs: dict, key: str, lo: float, hi: float, unit: str = "", *, integer: bool = False,
            lo_open: bool = False, nan_ok: bool = False):
    """attrs[key] as a float (int with ``integer``), or None when absent.

    Raises
    ------
    ValueError
        Not a single real number (a bool, a string, an array), not an integer where one
        is needed, or outside [lo, hi] ((lo, hi] with ``lo_open``); NaN unless ``nan_ok``.
    """
    if key not in attrs:
        return None
    v = attrs[key]
    if isinstance(v, np.ndarray) and v.size == 1 and v.ndim <= 1:
        v = v.reshape(-1)[0]
    kind = "an integer" if integer else "a number"
    interval = f"{'(' if lo_open else '['}{lo:g}, {hi:g}]{' ' + unit if unit else ''}"
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, numbers.Real):
        raise ValueError(f"attribute {key} must be {kind} in {interval}, got {_short(v)}")
    x = float(v)
    if nan_ok and math.isnan(x):
        return x
    ok = math.isfinite(x) and (lo < x if lo_open else lo <= x) and x <= hi
    if not ok or (integer and not x.is_integer()):
        raise ValueError(f"attribute {key} must be {kind} in {interval}, got {_short(v)}")
    return int(x) if integer else x


def _array(attrs: dict, key: str) -> np.ndarray | None:
    """attrs[key] as a 1-D float array of at most MAX_STATIONS numbers, or None when absent."""
    if key not in attrs:
        return None
    v = attrs[key]
    a = np.asarray(v) if isinstance(v, (list, tuple, np.ndarray)) or isinstance(v, numbers.Real) else None
    if a is None or a.dtype.kind not in "iuf" or a.ndim > 1 or not 1 <= a.size <= MAX_STATIONS:
        raise ValueError(f"attribute {key} must be an array of 1 to {MAX_STATIONS} numbers, got {_short(v)}")
    return a.reshape(-1).astype(float)


def check_propeller(propeller) -> None:
    """Refuse a propeller outside what a map records: diameter in [0.5, 100] in, at most
    100 blades (the ranges :func:`check_dataset` holds a map file to).

    Raises
    ------
    ValueError
        Naming the diameter or blade count and the range.
    """
    lo, hi = DIAMETER_RANGE
    if not lo <= propeller.diameter <= hi:
        raise ValueError(f"a map's propeller diameter must be in [{lo:g}, {hi:g}] m (0.5-100 in), "
                         f"got {propeller.diameter:g} m")
    if not N_BLADES_RANGE[0] <= propeller.n_blades <= N_BLADES_RANGE[1]:
        raise ValueError(f"a map's propeller must have 1 to {N_BLADES_RANGE[1]} blades, got {propeller.n_blades}")


def _check_axis(ds, d: str) -> None:
    ax = ds[d]
    values = np.asarray(ax.values)
    if ax.dims != (d,) or values.dtype.kind not in "iuf":
        raise ValueError(f"axis {d} must be a 1-D array of numbers along {d}")
    a = values.astype(float)
    scale, (lo, hi), unit = {"rpm": (RPM, OMEGA_RANGE, "rpm"), "airspeed": (1.0, AIRSPEED_RANGE, "m/s"),
                             "incidence_deg": (math.pi / 180, INCIDENCE_RANGE, "deg")}[d]
    if a.size < 2 or not np.all(np.isfinite(a)) or np.any(np.diff(a) <= 0):
        raise ValueError(f"axis {d} must hold at least 2 finite, strictly increasing values "
                         f"(got {a.size}: {np.array2string(a[:4], precision=4)}...)")
    tol = 1e-12 * hi
    if a[0] * scale < lo - tol or a[-1] * scale > hi + tol:
        raise ValueError(f"axis {d} must lie within [{lo / scale:.6g}, {hi / scale:.6g}] {unit}, "
                         f"got [{a[0]:g}, {a[-1]:g}]")
    units = ax.attrs.get("units")
    if units is not None and units != UNITS[d]:
        raise ValueError(f"axis {d} must be in {UNITS[d]!r}, its units attribute says {_short(units)}")


def _check_variables(ds) -> np.ndarray:
    """The checks of the map's variables; returns its converged-node mask."""
    for k in (*LOADS, *FLAGS, *(v for v in DERIVED if v in ds)):
        if set(ds[k].dims) != set(DIMS) or ds[k].ndim != 3:
            raise ValueError(f"variable {k} must have the dimensions {', '.join(DIMS)}, has {', '.join(ds[k].dims)}")
        kind = ds[k].dtype.kind
        if k in FLAGS:
            if kind not in "biu" or (kind != "b" and not np.isin(ds[k].values, (0, 1)).all()):
                raise ValueError(f"flag {k} must be boolean (true/false or 0/1)")
        elif kind not in "iuf":
            raise ValueError(f"variable {k} must hold numbers, has dtype {ds[k].dtype}")
        units = ds[k].attrs.get("units")
        if k not in FLAGS and units is not None and units != UNITS[k]:
            raise ValueError(f"variable {k} must be in {UNITS[k]!r}, its units attribute says {_short(units)}")
    converged = ds["converged"].transpose(*DIMS).values.astype(bool)
    if not converged.any():
        raise ValueError("no node of the map converged: nothing to interpolate")
    for k in LOADS:
        v = ds[k].transpose(*DIMS).values.astype(float)
        bad = converged & ~np.isfinite(v)
        if bad.any():
            i = np.unravel_index(int(np.argmax(bad)), bad.shape)
            node = ", ".join(f"{d} {float(ds[d].values[j]):g}" for d, j in zip(DIMS, i))
            raise ValueError(f"variable {k} is not finite at a converged node ({node}; {int(bad.sum())} such "
                             "nodes): only nodes that did not converge may lack values")
        with np.errstate(invalid="ignore"):
            big = np.abs(v) > LOAD_LIMITS[k]
        if big.any():
            i = np.unravel_index(int(np.argmax(big)), big.shape)
            node = ", ".join(f"{d} {float(ds[d].values[j]):g}" for d, j in zip(DIMS, i))
            raise ValueError(f"variable {k} must lie within +-{LOAD_LIMITS[k]:g} {UNITS[k]}, got {v[i]:.6g} "
                             f"({node}; {int(big.sum())} such nodes)")
    return converged


def _check_coordinates(ds) -> None:
    """The SI coordinates omega and incidence, when present, agree with rpm and incidence_deg."""
    for name, axis, factor in (("omega", "rpm", RPM), ("incidence", "incidence_deg", math.pi / 180)):
        if name not in ds.coords and name not in ds:
            continue
        c = ds[name]
        if c.dims != (axis,) or c.dtype.kind not in "iuf" or not np.allclose(
                c.values.astype(float), ds[axis].values.astype(float) * factor, rtol=1e-9, atol=0):
            raise ValueError(f"coordinate {name} must equal {axis} in {UNITS[name]} along {axis}")


def check_attributes(attrs: dict) -> None:
    """Check a map's attributes against the ranges of the module docstring.

    Raises
    ------
    ValueError
        The first attribute out of its range or of the wrong type, named.
    """
    d = _number(attrs, "diameter_m", *DIAMETER_RANGE, "m")
    if d is None:
        raise ValueError("not a propmap rotor map: lacks the attribute diameter_m")
    _number(attrs, "n_blades", *N_BLADES_RANGE, integer=True)
    _number(attrs, "rho_kg_m3", 1e-3, 2000.0, "kg/m^3")
    _number(attrs, "mu_Pa_s", 0.0, 10.0, "Pa s", lo_open=True)
    _number(attrs, "speed_of_sound_m_s", 1.0, 1e4, "m/s")
    _number(attrs, "n_radial", 2, 10000, integer=True)
    _number(attrs, "n_azimuth", 2, 1000, integer=True)
    _number(attrs, "build_seconds", 0.0, math.inf, "s")
    n = _number(attrs, "check_points", 0, CHECK_POINTS_MAX, integer=True)
    _number(attrs, "check_points_flagged", 0, CHECK_POINTS_MAX if n is None else n, integer=True)
    _number(attrs, "check_seed", 0, 2**63 - 1, integer=True)
    for key in attrs:
        if _CHECK_KEY.fullmatch(key):
            _number(attrs, key, 0.0, math.inf, nan_ok=True)
    for key in ("geometry_r_m", "geometry_chord_m", "geometry_theta_rad"):
        _array(attrs, key)
    r = _array(attrs, "geometry_r_m")
    if r is not None and r.size and not math.isclose(float(np.max(r)), 0.5 * d, rel_tol=1e-6):
        raise ValueError(f"attribute diameter_m ({d:g} m) disagrees with geometry_r_m, whose tip radius is "
                         f"{float(np.max(r)):g} m")
    for key in _TEXT:
        if key in attrs and not isinstance(attrs[key], str):
            raise ValueError(f"attribute {key} must be text, got {_short(attrs[key])}")


def check_dataset(ds) -> None:
    """Check a map (from :func:`propmap.maps.build_map` or a file) before it is evaluated.

    Parameters
    ----------
    ds : xarray.Dataset
        One propeller's map (no ``prop`` dimension).

    Raises
    ------
    TypeError
        ``ds`` is not an xarray Dataset.
    ValueError
        A missing variable, flag or axis, an axis outside the model's range (module
        docstring), too many nodes, non-finite loads at a converged node, no converged
        node, or an attribute of the wrong type or out of range; the message names it.
    """
    import xarray as xr

    if not isinstance(ds, xr.Dataset):
        raise TypeError(f"dataset must be an xarray.Dataset (a map from build_map or RotorMap.open), "
                        f"got {type(ds).__name__}")
    if "prop" in ds.dims:
        raise ValueError("a map of several propellers: select one (RotorMap.open(path, prop=NAME))")
    missing = [k for k in (*LOADS, *FLAGS) if k not in ds.data_vars]
    missing += [k for k in DIMS if k not in ds.coords or k not in ds.dims]
    if missing:
        raise ValueError(f"not a propmap rotor map: lacks {', '.join(missing)}")
    nodes = math.prod(int(ds.sizes[d]) for d in DIMS)
    if nodes > MAX_NODES:
        raise ValueError(f"the map has {nodes:,} nodes; at most {MAX_NODES:,}")
    for d in DIMS:
        _check_axis(ds, d)
    _check_coordinates(ds)
    check_attributes(ds.attrs)
    _check_variables(ds)


def map_model(attrs: dict):
    """(propeller, params, air, discretization) recorded in a map's attributes.

    Raises
    ------
    ValueError
        An attribute of the model missing (the map does not record the model that made
        it), of the wrong type or out of range (:func:`check_attributes`, the parameter
        file ranges of io.params_file, the checks of Propeller and Discretization).
    """
    from ..core.airfoil import Air
    from ..core.geometry import Propeller
    from ..core.solver import Discretization
    from .calibration import params_from_si
    from .params_file import DEG_KEYS, params_from_dict

    need = ("propeller", "diameter_m", "n_blades", "geometry_r_m", "geometry_chord_m", "geometry_theta_rad",
            "params_json", "rho_kg_m3", "mu_Pa_s", "speed_of_sound_m_s", "n_radial", "n_azimuth")
    missing = [k for k in need if k not in attrs]
    if missing:
        raise ValueError(f"the map does not record the model that made it (lacks {', '.join(missing)})")
    check_attributes(attrs)
    try:
        si = json.loads(attrs["params_json"])
    except ValueError as exc:
        raise ValueError(f"attribute params_json is not JSON ({exc})") from None
    if not isinstance(si, dict):
        raise ValueError(f"attribute params_json must be a JSON object, got {_short(si)}")
    # the ranges of a parameter file (angles in degrees there), then the exact SI record
    form = {({v: k for k, v in DEG_KEYS.items()}.get(k, k)): (math.degrees(v) if k in DEG_KEYS.values()
                                                             and isinstance(v, numbers.Real) else v)
            for k, v in si.items()}
    form.update(rho=attrs["rho_kg_m3"], mu=attrs["mu_Pa_s"], speed_of_sound=attrs["speed_of_sound_m_s"])
    form = {k: (v.item() if isinstance(v, np.generic) else v) for k, v in form.items()}
    params_from_dict(form, where="attribute params_json")
    try:
        params = params_from_si(si)
        prop = Propeller(name=attrs["propeller"], radius=float(attrs["diameter_m"]) / 2,
                         n_blades=int(attrs["n_blades"]), r=_array(attrs, "geometry_r_m"),
                         chord=_array(attrs, "geometry_chord_m"), theta=_array(attrs, "geometry_theta_rad"),
                         source=str(attrs.get("propeller_source", "")))
    except (TypeError, ValueError) as exc:
        raise ValueError(f"the recorded propeller or parameters are invalid ({exc})") from None
    air = Air(rho=float(attrs["rho_kg_m3"]), mu=float(attrs["mu_Pa_s"]),
              speed_of_sound=float(attrs["speed_of_sound_m_s"]))
    return prop, params, air, Discretization(int(attrs["n_radial"]), int(attrs["n_azimuth"]))


# ---------------------------------------------------------------- reading a file

def _where(path) -> str:
    s = os.fspath(path)
    s = s if isinstance(s, str) else os.fsdecode(s)
    return s if len(s) <= 80 else s[:77] + "..."


def _stat_regular(path):
    """(the path as shown in messages, its os.stat) of a map file that must be a regular file.

    Raises
    ------
    ValueError
        The path cannot be stat-ed, or is a folder, device or pipe.
    """
    where = _where(path)
    try:
        st = os.stat(path)
    except (OSError, ValueError) as exc:
        raise ValueError(f"{where}: {getattr(exc, 'strerror', None) or exc}") from None
    if not stat.S_ISREG(st.st_mode):
        raise ValueError(f"{where}: not a regular file (a folder, device or pipe); a map is a netCDF file")
    return where, st


def _layout(path, where: str) -> list[str]:
    """Read the file's dimensions and variables (no data); refuse a layout that is not a
    map's or declares more than MAX_NODES nodes. Returns the variables not to read."""
    import netCDF4

    wanted = {*LOADS, *DERIVED, *FLAGS, *DIMS, "omega", "incidence", "prop"}
    with netCDF4.Dataset(path, "r") as nc:
        sizes = {name: len(dim) for name, dim in nc.dimensions.items()}
        variables = {name: tuple(v.dimensions) for name, v in nc.variables.items()}
    for name, dims in variables.items():
        if name not in wanted:
            continue
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

        wanted = {*LOADS, *DERIVED, *FLAGS, *DIMS, "omega", "incidence", "prop"}
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

    methods = mp.get_all_start_methods()
    ctx = mp.get_context("fork" if "fork" in methods else methods[0])
    recv, send = ctx.Pipe(duplex=False)
    child = ctx.Process(target=_probe_child, args=(os.fspath(path), send), daemon=True)
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

    Raises
    ------
    TypeError, ValueError
        As :func:`read_dataset` (the file is read in a child first, its layout checked).
    """
    import netCDF4

    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a str or os.PathLike (a map file), got {type(path).__name__}")
    where, st = _stat_regular(path)
    _probe(path, where, st.st_size)
    try:
        _layout(path, where)
        with netCDF4.Dataset(path, "r") as nc:
            if "prop" not in nc.variables:
                return None
            names = [str(n) for n in np.asarray(nc.variables["prop"][:]).ravel()]
    except ValueError:
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
    if st.st_size > MAX_FILE_BYTES:
        raise ValueError(f"{where}: {st.st_size:,} bytes; a map file is at most {MAX_FILE_BYTES:,}")
    _probe(path, where, st.st_size)
    try:
        unused = _layout(path, where)
        with xr.open_dataset(path, engine="netcdf4", drop_variables=unused) as ds:
            if "prop" in ds.dims:
                ds = _select(ds, prop, where)
            elif prop is not None and prop != ds.attrs.get("propeller"):
                raise ValueError(f"{where}: a map of {_short(ds.attrs.get('propeller'))}, not of {prop!r}")
            return ds.load()
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith(where) else f"{where}: not a readable netCDF rotor map ({msg})") \
            from None
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
    return ds.sel(prop=prop, drop=True).assign_attrs({**kept, **attrs})


# ---------------------------------------------------------------- writing

def sidecar_path(path) -> Path:
    """The JSON sidecar of a map file: ``<path>.json``."""
    path = Path(path)
    return path.with_name(path.name + ".json")


def _json_safe(value):
    """``value`` with every non-finite float replaced by None (JSON null): strict JSON."""
    if isinstance(value, dict):
        return {k: _json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_json_safe(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _sidecar_text(ds, describes: dict | None) -> str:
    meta = {k: (v.tolist() if isinstance(v, np.ndarray) else v.item() if isinstance(v, np.generic) else v)
            for k, v in ds.attrs.items()}
    meta["dims"] = {d: int(n) for d, n in ds.sizes.items()}
    meta["axes"] = {d: [float(ds[d].values[0]), float(ds[d].values[-1])] for d in DIMS}
    meta["variables"] = {k: ds[k].attrs.get("units", "") for k in ds.data_vars}
    if describes is not None:
        meta["describes"] = describes
    return json.dumps(_json_safe(meta), indent=2, allow_nan=False)


def write_with_sidecar(ds, path, write) -> list[Path]:
    """Write a map file with ``write(tmp_path)`` and its sidecar, as a pair
    (io.atomic.atomic_paths): the sidecar, derived from the map's attributes, names the
    map file and its SHA-256 (``describes``), which :func:`read_sidecar` checks.

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

    path = Path(path)
    side = sidecar_path(path)
    with atomic_paths([path, side]) as (tmp, tmp_side):
        write(tmp)
        tmp_side.write_text(_sidecar_text(ds, {"file": path.name, "sha256": file_sha256(tmp)}))
    return [path, side]


def write_map(ds, path, fmt: str = "netcdf", *, sidecar: bool = True) -> list[Path]:
    """Write a map atomically: netCDF (``fmt="netcdf"``) or a long-form CSV (``"csv"``),
    plus a JSON sidecar ``<path>.json`` of its metadata and measured error, written as a pair
    (:func:`write_with_sidecar`).

    Returns
    -------
    list of Path
        The files written.

    Raises
    ------
    ValueError
        Unknown format, or an empty path.
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

    def write(tmp):
        if fmt == "netcdf":
            encoding = {k: {"zlib": True, "complevel": 4} for k in ds.data_vars}
            ds.to_netcdf(tmp, engine="netcdf4", encoding=encoding)
        else:
            table = ds.drop_vars(["omega", "incidence"]).to_dataframe().reset_index()
            for f in FLAGS:
                table[f] = np.where(table[f].to_numpy(bool), "true", "false")
            with open(tmp, "w", newline="") as fh:
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

    Raises
    ------
    OSError
        The file cannot be written.
    """
    from .atomic import atomic_write

    path = Path(path)
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
        raise ValueError(f"{_where(side)}: cannot read the sidecar of {_where(path)} "
                         f"({getattr(exc, 'strerror', None) or exc})") from None
    described = meta.get("describes") if isinstance(meta, dict) else None
    if not isinstance(described, dict) or described.get("sha256") != digest:
        raise ValueError(f"{_where(side)} does not describe {_where(path)} as it is now (SHA-256 differs): the map "
                         "was rewritten without it, or the pair is being replaced; read both again")
    return meta
