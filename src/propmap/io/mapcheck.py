"""The checks every rotor map passes (io/mapfile.py reads and writes the files).

:func:`check_dataset` holds every axis, variable and attribute to the ranges of the maps
``propmap map`` and :func:`propmap.maps.build_map` make (the table below), so that a map
answers only inside the model that made it; :func:`map_model` rebuilds that model.

==========================  ===========================================================
axis rpm                    Omega = rpm 2 pi / 60 in [0.1, 1e5] rad/s, strictly increasing
axis airspeed               [0, 500] m/s
axis incidence_deg          [0, 180] deg
nodes                       at least 2 per axis, at most 20,000,000 in all (MAX_NODES)
loads                       finite at every converged node; at least one converged node;
                            |thrust|, |drag| <= 1e5 N, |torque|, |rolling_moment| <= 1e4 N m
                            (the load data files' ranges); side_force (<= 1e5 N) and
                            pitching_moment (<= 1e4 N m) both or neither (SIDE_LOADS)
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
"""

from __future__ import annotations

import json
import math
import numbers
import re

import numpy as np

from ..core.units import RPM
from ..core.geometry import short_repr

__all__ = ["DIMS", "LOADS", "SIDE_LOADS", "map_loads", "DERIVED", "FLAGS", "UNITS", "MAX_NODES", "CHECK_POINTS_MAX",
           "check_propeller", "check_attributes", "check_dataset", "check_derived", "map_model"]


DIMS = ("rpm", "airspeed", "incidence_deg")
#: the loads a map interpolates, the derived variables and the node flags
LOADS = ("thrust", "drag", "torque", "rolling_moment")
#: the side force and pitching moment, which a map holds where its parameter set makes them (blade flapping, a
#: linear inflow, the dynamic stall: RotorOptions.side_load_sources); a map without them has none
SIDE_LOADS = ("side_force", "pitching_moment")
DERIVED = ("power", "CT", "CP")
FLAGS = ("converged", "vortex_ring", "multiple_roots", "reverse_flow")
UNITS = {"thrust": "N", "drag": "N", "torque": "N m", "rolling_moment": "N m", "side_force": "N",
         "pitching_moment": "N m", "power": "W", "CT": "1", "CP": "1",
         "rpm": "rpm", "airspeed": "m/s", "incidence_deg": "degree", "omega": "rad/s", "incidence": "rad"}


#: the most nodes a map may hold (all propellers of a ``prop`` dimension together): what
#: ``propmap map`` builds in about 8 minutes on 2 cores, 1.3 GB of tables
MAX_NODES = 20_000_000
#: SI ranges of the axes: Omega [rad/s], V [m/s], beta [rad] (the solver's)
OMEGA_RANGE = (0.1, 1e5)
AIRSPEED_RANGE = (0.0, 500.0)
INCIDENCE_RANGE = (0.0, math.pi)
DIAMETER_RANGE = (0.5 * 0.0254, 100 * 0.0254)  # [m]
N_BLADES_RANGE = (1, 100)
MAX_STATIONS = 10_000
CHECK_POINTS_MAX = 1_000_000
#: largest |value| of each load at a node (the load data files' ranges, identify.csvfile.RANGES)
LOAD_LIMITS = {"thrust": 1e5, "drag": 1e5, "torque": 1e4, "rolling_moment": 1e4, "side_force": 1e5,
               "pitching_moment": 1e4}
_CHECK_KEY = re.compile(r"check_(linear|cubic)_(thrust|drag|torque|rolling_moment|side_force|pitching_moment|power)_"
                        r"(rms|max|max_flagged)")
_TEXT = ("title", "propeller", "propeller_source", "section_model", "params_label", "params_json", "model",
         "citation", "propmap_version", "propmap_source_sha256", "interpolation", "Conventions", "check_normalisation",
         "note",
         "model_uncertainty_axial", "model_uncertainty_off_axis")


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
        raise ValueError(f"attribute {key} must be {kind} in {interval}, got {short_repr(v)}")
    x = float(v)
    if nan_ok and math.isnan(x):
        return x
    ok = math.isfinite(x) and (lo < x if lo_open else lo <= x) and x <= hi
    if not ok or (integer and not x.is_integer()):
        raise ValueError(f"attribute {key} must be {kind} in {interval}, got {short_repr(v)}")
    return int(x) if integer else x


def _array(attrs: dict, key: str) -> np.ndarray | None:
    """attrs[key] as a 1-D float array of at most MAX_STATIONS numbers, or None when absent."""
    if key not in attrs:
        return None
    v = attrs[key]
    a = np.asarray(v) if isinstance(v, (list, tuple, np.ndarray)) or isinstance(v, numbers.Real) else None
    if a is None or a.dtype.kind not in "iuf" or a.ndim > 1 or not 1 <= a.size <= MAX_STATIONS:
        raise ValueError(f"attribute {key} must be an array of 1 to {MAX_STATIONS} numbers, got {short_repr(v)}")
    return a.reshape(-1).astype(float)


def check_propeller(propeller) -> None:
    """Refuse a propeller outside what a map records: diameter in [0.5, 100] in, at most
    100 blades (the ranges :func:`check_dataset` holds a map file to). Nothing is returned:
    a propeller within both ranges passes silently.

    Parameters
    ----------
    propeller : Propeller
        Its ``diameter`` [m] and ``n_blades``.

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
        raise ValueError(f"axis {d} must be in {UNITS[d]!r}, its units attribute says {short_repr(units)}")


def map_loads(ds) -> tuple[str, ...]:
    """The loads a map holds: LOADS, and SIDE_LOADS where it has them.

    Parameters
    ----------
    ds : xarray.Dataset
        A rotor map.

    Returns
    -------
    tuple of str

    Raises
    ------
    ValueError
        One of the side force and the pitching moment without the other.
    """
    present = [k for k in SIDE_LOADS if k in ds.data_vars]
    if present and len(present) != len(SIDE_LOADS):
        raise ValueError(f"a map holds both of {', '.join(SIDE_LOADS)} or neither, this one {present[0]} only")
    return LOADS + tuple(present)


def _check_variables(ds) -> np.ndarray:
    """The checks of the map's variables; returns its converged-node mask."""
    loads = map_loads(ds)
    for k in (*loads, *FLAGS, *(v for v in DERIVED if v in ds)):
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
            raise ValueError(f"variable {k} must be in {UNITS[k]!r}, its units attribute says {short_repr(units)}")
    converged = ds["converged"].transpose(*DIMS).values.astype(bool)
    if not converged.any():
        raise ValueError("no node of the map converged: nothing to interpolate")
    for k in loads:
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


#: how far a stored derived variable (power, CT, CP) may lie from the value of the map's own loads, relative (a map
#: holds float64; float32 would round to 6e-8)
DERIVED_RTOL = 1e-6


def check_derived(ds) -> None:
    """The derived variables a map holds agree with its loads at its converged nodes: power with
    torque x omega, CT and CP with T / (rho n^2 D^4) and P / (rho n^3 D^5) where the map records
    its air density (build_map writes them so).

    A reader of the file uses them as they are, while the interpolation reads the loads alone;
    ``map --check`` (:func:`propmap.rotormap.check_map`) runs this, and a map with its power
    doubled passed it until 2026-12-01 (a user-level audit).

    Parameters
    ----------
    ds : xarray.Dataset
        One propeller's map, valid as :func:`check_dataset` says.

    Raises
    ------
    ValueError
        A derived variable more than DERIVED_RTOL (relative) off at some converged node: the
        message names it, the node and the number of such nodes.
    """
    converged = ds["converged"].transpose(*DIMS).values.astype(bool)
    omega = (ds["rpm"].values.astype(float) * RPM)[:, None, None]
    torque = ds["torque"].transpose(*DIMS).values.astype(float)
    expected = {"power": torque * omega}
    rho, diameter = ds.attrs.get("rho_kg_m3"), float(np.ravel(ds.attrs["diameter_m"])[0])
    if rho is not None:
        n = omega / (2 * math.pi)
        rho = float(np.ravel(rho)[0])
        expected["CT"] = ds["thrust"].transpose(*DIMS).values.astype(float) / (rho * n**2 * diameter**4)
        expected["CP"] = expected["power"] / (rho * n**3 * diameter**5)
    for k, want in expected.items():
        if k not in ds:
            continue
        have = ds[k].transpose(*DIMS).values.astype(float)
        with np.errstate(invalid="ignore"):
            off = converged & ~(np.abs(have - want) <= DERIVED_RTOL * np.abs(want) + 1e-12 * np.nanmax(np.abs(want)))
        if off.any():
            i = np.unravel_index(int(np.argmax(off)), off.shape)
            node = ", ".join(f"{d} {float(ds[d].values[j]):g}" for d, j in zip(DIMS, i))
            raise ValueError(f"variable {k} disagrees with the map's loads at a converged node ({node}: {have[i]:.6g} "
                             f"where {LONG_DERIVED[k]} gives {want[i]:.6g}; {int(off.sum())} such nodes)")


#: each derived variable's definition, in the words of its error
LONG_DERIVED = {"power": "torque x omega", "CT": "T / (rho n^2 D^4)", "CP": "P / (rho n^3 D^5)"}


def _check_coordinates(ds) -> None:
    """The SI coordinates omega and incidence, when present, agree with rpm and incidence_deg (to
    1e-9, or to 8 roundings where either is stored in single precision: a map saved as float32 was
    refused, an audit, stop 102)."""
    for name, axis, factor in (("omega", "rpm", RPM), ("incidence", "incidence_deg", math.pi / 180)):
        if name not in ds.coords and name not in ds:
            continue
        c = ds[name]
        if c.dims != (axis,) or c.dtype.kind not in "iuf":
            raise ValueError(f"coordinate {name} must equal {axis} in {UNITS[name]} along {axis}")
        single = any(a.dtype == np.float32 for a in (c, ds[axis]))
        rtol = 8 * float(np.finfo(np.float32).eps) if single else 1e-9
        if not np.allclose(c.values.astype(float), ds[axis].values.astype(float) * factor, rtol=rtol, atol=0):
            raise ValueError(f"coordinate {name} must equal {axis} in {UNITS[name]} along {axis} (to a relative "
                             f"{rtol:.2g})")


def check_attributes(attrs: dict) -> None:
    """Check a map's attributes against the ranges of the module docstring.

    Nothing is returned: valid attributes pass silently (``attrs`` is not modified).

    Parameters
    ----------
    attrs : dict
        A map's attributes (``Dataset.attrs``): ``diameter_m`` is required, every other
        checked key only where present; keys the table does not name are not checked.
        A number may be a one-element array.

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
    _number(attrs, "speed_of_sound_m_s", 100.0, 1e4, "m/s")  # (as parameter files: it took 1 m/s, stop 102)
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
            raise ValueError(f"attribute {key} must be text, got {short_repr(attrs[key])}")


def check_dataset(ds) -> None:
    """Check a map (from :func:`propmap.maps.build_map` or a file) before it is evaluated.

    Nothing is returned: a valid map passes silently (``ds`` is not modified).

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
    if "params_json" in ds.attrs:  # (RotorMap.open took any record, so a VehicleMap took another propeller's
        _recorded_params(ds.attrs)  # map as one without it: an audit, stop 100)
    _check_variables(ds)


def _recorded_params(attrs: dict):
    """The section set of a map's ``params_json`` (SI, angles in rad), held to the ranges of a
    parameter file (io.params_file, angles in degrees there) with the map's air where it records
    it; a ValueError naming ``params_json`` where the record is not JSON, not an object or out
    of range (:func:`check_dataset` calls it on every map that has the attribute)."""
    from .calibration import params_from_si
    from .params_file import DEG_KEYS, params_from_dict

    try:
        si = json.loads(attrs["params_json"])
    except (TypeError, ValueError) as exc:
        raise ValueError(f"attribute params_json is not JSON ({exc})") from None
    if not isinstance(si, dict):
        raise ValueError(f"attribute params_json must be a JSON object, got {short_repr(si)}")
    # a map written before the radial flow's drag existed (2026-11-24) was made without it,
    # whatever the record's default is now
    si.setdefault("radial_drag", False)
    si.setdefault("inplane_induction", False)  # (2026-11-25) likewise
    # the ranges of a parameter file (angles in degrees there), then the exact SI record
    form = {({v: k for k, v in DEG_KEYS.items()}.get(k, k)): (math.degrees(v) if k in DEG_KEYS.values()
                                                             and isinstance(v, numbers.Real) else v)
            for k, v in si.items()}
    form.update({k: attrs[a] for k, a in (("rho", "rho_kg_m3"), ("mu", "mu_Pa_s"),
                                          ("speed_of_sound", "speed_of_sound_m_s")) if a in attrs})
    form = {k: (v.item() if isinstance(v, np.generic) else v) for k, v in form.items()}
    params_from_dict(form, where="attribute params_json")
    try:
        return params_from_si(si)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"the recorded parameters are invalid ({exc})") from None


def map_model(attrs: dict):
    """(propeller, params, air, discretization) recorded in a map's attributes.

    A record without ``radial_drag`` or ``inplane_induction`` (a map written before that
    option) is read with it False, the model that made it.

    Parameters
    ----------
    attrs : dict
        A map's attributes (``Dataset.attrs``), with at least ``propeller``, ``diameter_m``,
        ``n_blades``, ``geometry_r_m``, ``geometry_chord_m``, ``geometry_theta_rad`` [m, m,
        rad], ``params_json`` (the parameter record's fields, SI, angles in rad),
        ``rho_kg_m3``, ``mu_Pa_s``, ``speed_of_sound_m_s``, ``n_radial`` and ``n_azimuth``.

    Returns
    -------
    propeller : Propeller
        Radius ``diameter_m / 2`` [m] and the recorded stations, chords and blade angles.
    params : AirfoilParams or CamberedParams
        The recorded section set (``section_model`` in ``params_json``, default
        ``"gill2017"``), with an empty label and the record's default air.
    air : Air
        The recorded air: density [kg/m^3], viscosity [Pa s], speed of sound [m/s].
    discretization : Discretization
        ``Discretization(n_radial, n_azimuth)``.

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

    need = ("propeller", "diameter_m", "n_blades", "geometry_r_m", "geometry_chord_m", "geometry_theta_rad",
            "params_json", "rho_kg_m3", "mu_Pa_s", "speed_of_sound_m_s", "n_radial", "n_azimuth")
    missing = [k for k in need if k not in attrs]
    if missing:
        raise ValueError(f"the map does not record the model that made it (lacks {', '.join(missing)})")
    check_attributes(attrs)
    params = _recorded_params(attrs)
    try:
        prop = Propeller(name=attrs["propeller"], radius=float(attrs["diameter_m"]) / 2,
                         n_blades=int(attrs["n_blades"]), r=_array(attrs, "geometry_r_m"),
                         chord=_array(attrs, "geometry_chord_m"), theta=_array(attrs, "geometry_theta_rad"),
                         source=str(attrs.get("propeller_source", "")))
    except (TypeError, ValueError) as exc:
        raise ValueError(f"the recorded propeller or parameters are invalid ({exc})") from None
    air = Air(rho=float(attrs["rho_kg_m3"]), mu=float(attrs["mu_Pa_s"]),
              speed_of_sound=float(attrs["speed_of_sound_m_s"]))
    return prop, params, air, Discretization(int(attrs["n_radial"]), int(attrs["n_azimuth"]))
