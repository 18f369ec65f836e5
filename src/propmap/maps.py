"""Rotor maps: the model tabulated over (rpm, airspeed, incidence) for real-time use (this
module builds them; rotormap.py evaluates and checks them, and its names are re-exported here).

The paper closes its Sec. V with "since the computation time is in the order of seconds, a
look-up-table can be used for real-time purposes" (Gill & D'Andrea 2017). A map is
an xarray Dataset (written as netCDF) with the loads on a rectilinear grid, the flags of
every node, what made it (propeller geometry, parameters, model, propmap version, data
citation) and its measured interpolation error: :func:`build_map` evaluates the full model
at random off-grid points and stores the rms and largest error of each variable.

:class:`RotorMap` evaluates a map: cubic (default) or multilinear interpolation of T, D, Q
and M_R divided by (Omega R)^2 + V^2 (compiled, core/_interp.py), multiplied back, with an
explicit out-of-grid policy. docs/simulators.md shows the netCDF, C and coefficient routes.
"""

from __future__ import annotations

import json
import math
import re
import sys

import numpy as np

from . import __version__
from .core._interp import snap_incidence
from .core._numbers import SEED_MAX, integer
from .core.airfoil import Air, SectionParams
from .core.geometry import Propeller
from .core.solver import (AIRSPEED_MAX, DEFAULT_DISCRETIZATION, OMEGA_MAX, OMEGA_MIN, Discretization,
                          check_model_args, rotor_loads)
from .io.mapcheck import (CHECK_POINTS_MAX, FLAGS, LOADS, MAX_NODES, SIDE_LOADS, UNITS, check_attributes,
                          check_dataset, check_propeller)
from .io.mapfile import read_sidecar, write_map, write_sidecar
from .io.provenance import source_digest
from .io.uncertainty import model_uncertainty
from .core.units import RPM
from .rotormap import MapLoads, MapWrench, RotorMap, check_map

__all__ = ["MAX_NODES", "MapLoads", "MapWrench", "RotorMap", "build_map", "check_map", "default_axes", "read_sidecar",
           "scheduler_client", "write_map", "write_sidecar"]

LONG_NAMES = {"thrust": "thrust T along the rotor axis",
              "drag": "rotor drag D (H-force), against the in-plane velocity",
              "torque": "shaft torque Q opposing the rotation",
              "rolling_moment": "rolling moment M_R (advancing/retreating thrust asymmetry)",
              "side_force": "side force Y toward the advancing side (flapping blades, a linear inflow or the dynamic "
                            "stall)",
              "pitching_moment": "pitching moment M_P about e_ip x z, positive nose-up for a disk moving along e_ip "
                                 "(flapping blades, a linear inflow or the dynamic stall)",
              "power": "shaft power P = Q Omega", "CT": "thrust coefficient T / (rho n^2 D^4)",
              "CP": "power coefficient P / (rho n^3 D^5)"}
#: static tip speed [m/s] of the default map's highest rpm (tip Mach 0.44 at sea level)
DEFAULT_TIP_SPEED = 150.0


def default_axes(propeller: Propeller):
    """Default grid (rpm [rpm], airspeed [m/s], incidence [deg]) for ``propeller``.

    rpm from 1/6 of the top value to the rpm of a 150 m/s tip speed, 21 values spaced
    geometrically (equal relative steps of 9.4%; the UIUC measurements behind the
    calibration reach tip speeds of 60-130 m/s); airspeed 0-25 m/s in 1 m/s steps (26);
    incidence 0-180 deg in 2.5 deg steps (73). 39,858 points; with the defaults the
    interpolation error stays within 1% of static thrust and torque and 2% of the largest
    drag outside flagged regions (docs/simulators.md gives the measured figures and how
    they fall with grid density).

    Parameters
    ----------
    propeller : Propeller
        Its ``diameter`` [m] sets the top rpm (the 150 m/s tip speed's, rounded to
        100 rpm).

    Returns
    -------
    (ndarray, ndarray, ndarray)
        rpm, airspeed, incidence_deg, each strictly increasing.
    """
    top = DEFAULT_TIP_SPEED / propeller.radius / RPM
    top = float(np.round(top, -2))
    return np.geomspace(top / 6, top, 21), np.linspace(0.0, 25.0, 26), np.linspace(0.0, 180.0, 73)


def _check_axis(name: str, a, lo: float, hi: float, unit: str, snap: bool = False) -> np.ndarray:
    try:
        a = np.asarray(a)
        numeric = a.dtype.kind in "iuf"
    except (TypeError, ValueError):
        numeric = False
    if not numeric:
        raise ValueError(f"{name} must be a 1-D array of numbers [{unit}], got {a!r:.60}")
    a = a.astype(float)
    if snap:  # an end within INCIDENCE_SNAP of [lo, hi] is on it (float32's pi)
        a = snap_incidence(a, lo, hi)
    if a.ndim != 1 or a.size < 2:
        raise ValueError(f"{name} must be a 1-D axis of at least 2 values, got shape {a.shape}")
    if not np.all(np.isfinite(a)) or a[0] < lo or a[-1] > hi:
        raise ValueError(f"{name} must be finite and within [{lo:g}, {hi:g}] {unit}, got [{a[0]:g}, {a[-1]:g}]")
    if np.any(np.diff(a) <= 0):
        raise ValueError(f"{name} must be strictly increasing")
    return a


#: seconds to wait for a dask.distributed scheduler
SCHEDULER_TIMEOUT = 10.0
#: a scheduler address: PROTOCOL://HOST:PORT (HOST a name, an IPv4 or a bracketed IPv6 address)
_ADDRESS = re.compile(r"(tcp|tls|ucx|ws|wss)://(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9._-]+):([0-9]{1,5})")


def scheduler_client(address: str):
    """A ``dask.distributed`` Client connected to the scheduler at ``address``.

    Parameters
    ----------
    address : str
        ``tcp://HOST:PORT`` (or tls, ucx, ws, wss).

    Returns
    -------
    distributed.Client
        The caller closes it.

    Raises
    ------
    ValueError
        Not such an address (a port outside [1, 65535] included), or no scheduler
        answering there within SCHEDULER_TIMEOUT (10 s; a server that accepts the
        connection but does not answer dask's handshake within twice that); the message
        names the scheduler.
    """
    from distributed import Client

    m = _ADDRESS.fullmatch(address) if isinstance(address, str) else None
    if m is None or not 1 <= int(m.group(3)) <= 65535:
        raise ValueError(f"scheduler must be an address PROTOCOL://HOST:PORT (e.g. tcp://10.0.0.5:8786; protocol "
                         f"tcp, tls, ucx, ws or wss; port in [1, 65535]), got {address!r:.80}")
    import threading

    # Client's timeout bounds the connection, not the handshake: a server that accepts the
    # connection but does not speak dask's protocol would keep it waiting forever, so the
    # client is made in a thread that is given up after twice the timeout
    box: dict = {}

    def connect() -> None:
        try:
            box["client"] = Client(address, timeout=SCHEDULER_TIMEOUT)
        except Exception as exc:  # noqa: BLE001 -- distributed raises OSError, TimeoutError, ValueError, ...
            box["error"] = exc

    worker = threading.Thread(target=connect, name="propmap-scheduler-connect", daemon=True)
    worker.start()
    worker.join(2 * SCHEDULER_TIMEOUT)
    if "client" in box:
        return box["client"]
    exc = box.get("error")
    why = (f"{type(exc).__name__}: {' '.join(str(exc).split())[:120]}" if exc is not None
           else "connected, but no dask scheduler answered the handshake")
    raise ValueError(f"scheduler: no scheduler answered at {address} within {SCHEDULER_TIMEOUT:g} s ({why})")


def _solve_block(propeller, params, air, discretization, loads, om, V, b):
    r = rotor_loads(propeller, params, om, V, b, air=air, discretization=discretization, on_failure="flag",
                    radial=False)
    return np.stack([*(getattr(r, k) for k in loads), *(np.asarray(getattr(r, f), float) for f in FLAGS)])


def _rounded(x: np.ndarray) -> np.ndarray:
    """An axis converted to rpm or degrees without the conversion's round-off: a value within 4
    units in the last place of one of 12 significant digits is that one (6000 rpm through rad/s
    came back 6000.000000000001, 15 deg 14.999999999999998, which ``Dataset.sel(rpm=6000)`` did
    not find); others, and an axis the rounding would not keep strictly increasing, as they are.
    RotorMap evaluates at the stored SI coordinates, the nodes as solved."""
    r = np.array([float(f"{v:.12g}") for v in x])
    r = np.where(np.abs(r - x) <= 4 * np.spacing(np.abs(x)), r, x)
    return r if np.all(np.diff(r) > 0) else x


def build_map(propeller: Propeller, params: SectionParams, omega, airspeed, incidence, *, air: Air | None = None,
              discretization: Discretization = DEFAULT_DISCRETIZATION, params_label: str = "",
              citation: str = "", chunk_points: int = 20_000, scheduler=None, progress: bool = False,
              n_check: int = 2000, seed: int = 0):
    """Tabulate the model on the grid omega x airspeed x incidence, with its measured
    interpolation error (a sample maximum).

    Parameters
    ----------
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    omega, airspeed, incidence : array_like, shape (n0,), (n1,), (n2,)
        Strictly increasing axes: Omega [rad/s] in [0.1, 1e5], V [m/s] in [0, 500],
        incidence beta [rad] in [0, pi].
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization
    params_label : str
        How the parameters were named (``calibrated:apce_8x6``, a file), kept in the map;
        default the set's own ``label``.
    citation : str
        The data behind the parameters and geometry, kept in the map.
    chunk_points : int
        Grid points per Dask chunk (each chunk is one batched model call).
    scheduler : None, str or distributed.Client
        None: local, one chunk at a time (the model call itself uses every core); a
        ``dask.distributed`` scheduler address or Client: the chunks run on its workers.
    progress : bool
        A progress bar over the chunks, on standard error where it is a terminal (tqdm; on a
        dask cluster, dask's text bar).
    n_check : int
        Random off-grid points at which the full model checks the interpolation
        (:func:`check_map`); 0 skips the check.
    seed : int
        Seed of the check points, in [0, 2**63 - 1].

    Returns
    -------
    xarray.Dataset
        Dimensions ``rpm`` [rpm], ``airspeed`` [m/s], ``incidence_deg`` [deg] (with the SI
        coordinates ``omega`` [rad/s] and ``incidence`` [rad]); variables thrust, drag,
        torque, rolling_moment (and side_force, pitching_moment where the set makes them:
        blade flapping, a linear inflow, the dynamic stall; RotorOptions.side_load_sources),
        power, CT, CP and the node flags converged, vortex_ring,
        multiple_roots, reverse_flow; attributes as described in docs/simulators.md.

    Raises
    ------
    ValueError
        An axis that is not a 1-D array of numbers, has fewer than 2 values, is not
        increasing, or leaves the model's range; more than MAX_NODES (20,000,000) nodes
        (refused before any work); a propeller a map cannot record (diameter outside
        0.5-100 in, more than 100 blades; io.mapcheck) or air it cannot (a parameter file's
        ranges: rho in [0.001, 2000] kg/m^3, mu in (0, 10] Pa s, a speed of sound in [100, 1e4]
        m/s); ``chunk_points`` not an integer
        in [1, MAX_NODES]; ``n_check`` not an integer in [0, 1,000,000]; ``seed`` not an
        integer >= 0; a scheduler address that cannot be reached within 10 s; once solved, a
        map a file cannot hold (loads beyond the file's limits, |T| up to 1e5 N: the top of
        an rpm axis for a large propeller; io.mapcheck.check_dataset).
    TypeError
        A model argument of the wrong type (:func:`propmap.core.solver.check_model_args`).

    Warns
    -----
    CoverageWarning
        The grid beyond the data behind the parameter set (``params_label``, else
        ``params.label``): its rpm axis past the rates a calibrated set or a fitted file was
        fitted at, its advance ratio, incidence or airspeed past theirs, its Reynolds numbers
        (another air or propeller) past theirs by 5% (:func:`propmap.io.coverage.coverage_warnings`,
        as the `map` command says them).
    """
    air = getattr(params, "air", None) if air is None else air  # checked below
    import dask.array as da

    check_model_args(propeller, params, air, discretization)
    # the side force and the pitching moment where the set makes them (RotorOptions.side_load_sources)
    loads = LOADS + (SIDE_LOADS if params.side_load_sources() else ())
    om = _check_axis("omega", omega, OMEGA_MIN, OMEGA_MAX, "rad/s")
    V = _check_axis("airspeed", airspeed, 0.0, AIRSPEED_MAX, "m/s")
    b = _check_axis("incidence", incidence, 0.0, math.pi, "rad", snap=True)
    chunk_points = integer("chunk_points", chunk_points, 1, MAX_NODES)
    n_check = integer("n_check", n_check, 0, CHECK_POINTS_MAX)
    seed = integer("seed", seed, 0, SEED_MAX)
    nodes = om.size * V.size * b.size
    if nodes > MAX_NODES:
        raise ValueError(f"the grid omega x airspeed x incidence has {om.size} x {V.size} x {b.size} = {nodes:,} "
                         f"nodes; at most {MAX_NODES:,}")
    check_propeller(propeller)
    try:  # (the air a map records, within the ranges of parameter files: refused after the solve until stop 102)
        check_attributes({"diameter_m": propeller.diameter, "rho_kg_m3": air.rho, "mu_Pa_s": air.mu,
                          "speed_of_sound_m_s": air.speed_of_sound})
    except ValueError as exc:
        raise ValueError(f"air: a map records it within the ranges of a parameter file: {exc}") from None
    _warn_coverage(propeller, params, air, params_label, om, V, b)
    shape = (om.size, V.size, b.size)
    O3, V3, B3 = (a.reshape(-1) for a in np.meshgrid(om, V, b, indexing="ij"))
    chunks = int(chunk_points)
    O3, V3, B3 = (da.from_array(a, chunks=chunks) for a in (O3, V3, B3))
    parts = da.map_blocks(_solve_block, propeller, params, air, discretization, loads, O3, V3, B3, new_axis=0,
                          chunks=((len(loads) + len(FLAGS),), O3.chunks[0]), dtype=float)
    result = np.asarray(_compute(parts, scheduler, progress)).reshape((len(loads) + len(FLAGS),) + shape)
    ds = _dataset(result, loads, om, V, b, propeller, params, air, discretization, params_label, citation)
    # what a map file may hold, checked whether or not the map is checked against the model (with n_check = 0 a
    # map past the loads' limits was written, and `map --check` then refused the file `map` had just written)
    try:
        check_dataset(ds)
    except ValueError as exc:
        raise ValueError(f"the solved map cannot be recorded: {exc} (narrow its rpm or airspeed axis: --rpm, "
                         "--airspeed)") from None
    if n_check:
        ds.attrs.update(check_map(ds, n_check, seed=seed, propeller=propeller, params=params, air=air,
                                  discretization=discretization))
    return ds


def _warn_coverage(propeller, params, air, params_label: str, om, V, b) -> None:
    """build_map's warnings of a grid beyond the data behind its parameter set (the rpm axis past
    the rates a calibrated set was fitted at, an advance ratio, incidence or airspeed past a
    fitted file's), as the `map` command says them: a map built in Python over 3000-15000 rpm
    with apce_8x6's calibrated set (its data 2534-6713 rpm) was built without a word (an audit
    of stop 90). The tip Mach number is the solver's to warn of."""
    import warnings

    from .io.coverage import CoverageWarning, coverage_warnings, envelope_extremes

    rpm = om / RPM
    extremes = envelope_extremes(propeller, rpm[:, None, None], V[None, :, None], np.degrees(b)[None, None, :])
    for line in coverage_warnings(propeller, params_label or getattr(params, "label", ""), air, *extremes,
                                  rpm=(float(rpm[0]), float(rpm[-1])), airspeed=float(V[-1]), tip_mach=False):
        warnings.warn(line, CoverageWarning, stacklevel=3)


def _stderr_is_terminal() -> bool:
    """Whether standard error is a terminal (False where it is None or closed)."""
    try:
        return bool(sys.stderr.isatty())
    except (AttributeError, ValueError, OSError):
        return False


def _compute(parts, scheduler, progress: bool):
    """build_map's solve of the grid's chunks: one at a time in this process (the model call is
    parallel over the cores already, and two concurrent numba parallel regions would compete for
    them), or on a dask.distributed cluster (a Client, or an address whose client is closed
    after), with a progress bar where asked."""
    if scheduler is None:
        if progress:
            from dask.callbacks import Callback
            from tqdm import tqdm

            class _Bar(Callback):
                def _start_state(self, dsk, state):
                    # disable=None: no bar where stderr is not a terminal (a log file, a pipe)
                    self.bar = tqdm(total=sum(len(v) for v in state.values() if isinstance(v, (set, list))),
                                    unit="task", leave=False, disable=None)

                def _posttask(self, key, result, dsk, state, worker_id):
                    self.bar.update(1)

                def _finish(self, dsk, state, errored):
                    self.bar.close()

            with _Bar():
                result = parts.compute(scheduler="threads", num_workers=1)
        else:
            result = parts.compute(scheduler="threads", num_workers=1)
    else:
        from distributed import Client

        own = not isinstance(scheduler, Client)
        if own and not isinstance(scheduler, str):
            raise ValueError(f"scheduler must be None, a dask.distributed Client or an address such as "
                             f"tcp://HOST:PORT, got {scheduler!r:.60}")
        client = scheduler_client(scheduler) if own else scheduler
        try:
            future = client.compute(parts)
            if progress and _stderr_is_terminal():  # (as the local bar: on a terminal's stderr only; distributed's
                import contextlib  # text bar writes to stdout, which broke map --json's output: an audit, stop 100)

                from distributed import progress as dist_progress

                with contextlib.redirect_stdout(sys.stderr):
                    dist_progress(future)
            result = future.result()
        finally:
            if own:
                client.close()
    return result


def _dataset(result, loads, om, V, b, propeller, params, air, discretization, params_label, citation):
    """build_map's dataset from the solved grid ``result`` (loads and flags x rpm x airspeed x
    incidence): the loads, power, CT and CP, the flags, the coordinates in the file's units and
    the attributes that record the model, its inputs and its measured uncertainty."""
    import xarray as xr

    from .io.calibration import params_to_si

    dims = ("rpm", "airspeed", "incidence_deg")
    n = om[:, None, None] / (2 * math.pi)
    data = {k: (dims, result[i], {"units": UNITS[k], "long_name": LONG_NAMES[k]}) for i, k in enumerate(loads)}
    data["power"] = (dims, result[2] * om[:, None, None], {"units": "W", "long_name": LONG_NAMES["power"]})
    data["CT"] = (dims, result[0] / (air.rho * n**2 * propeller.diameter**4), {"units": "1",
                                                                               "long_name": LONG_NAMES["CT"]})
    data["CP"] = (dims, data["power"][1] / (air.rho * n**3 * propeller.diameter**5),
                  {"units": "1", "long_name": LONG_NAMES["CP"]})
    for i, f in enumerate(FLAGS):
        # (the CF conventions' flag attributes, so that the file says what its 0 and 1 mean: a docs audit, 2026-12-02)
        data[f] = (dims, result[len(loads) + i] != 0, {"long_name": f"model flag {f} (docs/solver.md)",
                                                       "flag_values": np.array([0, 1], np.int8),
                                                       "flag_meanings": f"not_{f} {f}"})
    coords = {"rpm": ("rpm", _rounded(om / RPM), {"units": "rpm", "long_name": "rotation rate"}),
              "airspeed": ("airspeed", V, {"units": "m/s", "long_name": "speed of the disk relative to the air"}),
              "incidence_deg": ("incidence_deg", _rounded(np.degrees(b)),
                                {"units": "degree", "long_name": "incidence beta (0 climb, 90 edgewise, 180 descent)"}),
              "omega": ("rpm", om, {"units": "rad/s", "long_name": "rotation rate Omega"}),
              "incidence": ("incidence_deg", b, {"units": "rad", "long_name": "incidence beta"})}
    attrs = {
        "title": f"propmap rotor map of {propeller.name}",
        "propeller": propeller.name, "propeller_source": propeller.source or "",
        "diameter_m": propeller.diameter, "n_blades": propeller.n_blades,
        "geometry_r_m": propeller.r, "geometry_chord_m": propeller.chord, "geometry_theta_rad": propeller.theta,
        "section_model": params.section_model, "params_label": params_label or getattr(params, "label", ""),
        "params_json": json.dumps(params_to_si(params)),
        "rho_kg_m3": air.rho, "mu_Pa_s": air.mu, "speed_of_sound_m_s": air.speed_of_sound,
        "n_radial": discretization.n_radial, "n_azimuth": discretization.n_azimuth,
        "model": "Gill & D'Andrea, Propeller Thrust and Drag in Forward Flight, IEEE CCTA 2017 "
                 f"(BET/BEMT), section model {params.section_model} (propmap docs/models.md)",
        "citation": citation, "propmap_version": __version__, "propmap_source_sha256": source_digest(),
        "interpolation": "of T, D, Q, M_R (and Y, M_P where the map holds them) divided by (Omega R)^2 + V^2 in "
                         "(rpm, airspeed, incidence), "
                         "multiplied back by (Omega R)^2 + V^2 of the query: cubic Hermite with three-point "
                         "slopes (RotorMap's default) or multilinear (RotorMap(..., 'linear'), the C export's default)",
        "Conventions": "CF-1.8",
    }
    # the model's own error against measurements with this set, beside the map's against the model
    unc = model_uncertainty(params_label or getattr(params, "label", ""), propeller)
    attrs["model_uncertainty_axial"] = unc["axial"]
    attrs["model_uncertainty_off_axis"] = unc["off_axis"]
    return xr.Dataset(data, coords=coords, attrs=attrs)
