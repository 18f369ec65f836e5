"""Evaluating a rotor map: :class:`RotorMap` (built by :func:`propmap.maps.build_map`).

Cubic (default) or multilinear interpolation of T, D, Q and M_R (and Y, M_P where the map
holds them) divided by (Omega R)^2 + V^2 (compiled, core/_interp.py), multiplied back, with an explicit out-of-grid
policy; scalar fast paths for one point and for one rotor's force and moment vectors.
docs/simulators.md has the conventions and the measured speeds. :func:`check_map` measures
a map's interpolation error against the model that made it (here, so that
:meth:`RotorMap.check` needs no import of the module that builds maps).
"""

from __future__ import annotations

import math
import threading
import numpy as np

from .core.units import RPM
from .core._interp import OutOfGridError, snap_airspeed, snap_airspeed_scalar, snap_incidence, snap_incidence_scalar
from .core._numbers import SEED_MAX, integer
from .core._plain import SPINS, plain_float, plain_vector
from .core.geometry import broadcast_readonly, has_bool, refuse_masked
from .io.inputs import short_path
from .io.mapcheck import CHECK_POINTS_MAX, LOADS, SIDE_LOADS, check_dataset, check_derived, map_loads, map_model
from .io.mapfile import read_dataset
from .mapresults import MapLoads, MapWrench

__all__ = ["BAD_FLAGS", "INTERPOLATIONS", "MapLoads", "MapWrench", "POLICIES", "RPM", "RotorMap", "check_map"]

POLICIES = ("raise", "clip", "nan")
#: :meth:`RotorMap.wrench` refuses a velocity component this large or larger [m/s], as the C header does
#: (core.vector.VELOCITY_MAX, not imported: that module loads the solver, 0.3 s of a map's import)
VELOCITY_MAX = 1e150
#: interpolation methods of RotorMap and of the C export
INTERPOLATIONS = ("linear", "cubic")
#: the model flags that make a cell's interpolation unreliable (reverse flow is not one:
#: the model is smooth there)
BAD_FLAGS = ("vortex_ring", "multiple_roots")


def _cell_flags(bad: np.ndarray) -> np.ndarray:
    """Cells (shape n - 1 per axis) with a bad node among the nodes i-1 .. i+2 of every
    axis: the 4 x 4 x 4 nodes the cubic reads, cut at the grid's edges."""
    cell = bad
    for axis in range(3):
        n = cell.shape[axis]
        padded = np.pad(cell, [(1, 1) if a == axis else (0, 0) for a in range(3)])
        acc = np.zeros_like(np.take(padded, range(n - 1), axis=axis))
        for k in range(4):
            acc |= np.take(padded, range(k, k + n - 1), axis=axis)
        cell = acc
    return cell


def _warn_side_loads_missing(attrs: dict) -> None:
    """Warn where a map's recorded set makes a side force and pitching moment that the map
    does not hold (a map built before 2026-11-26, when maps left them out)."""
    try:
        sources = map_model(attrs)[1].side_load_sources()
    except (ValueError, KeyError, TypeError):  # a map that does not record its model: nothing to say
        return
    if sources:
        import warnings

        warnings.warn(f"the map's parameter set gives a side force and a pitching moment ({', '.join(sources)}), "
                      "which this map does not hold (built before 2026-11-26): its loads and wrench give 0 for "
                      "them; build it again to have them", UserWarning, stacklevel=3)


#: the one-point paths' results from a tuple of their fields: ``_NEW(MapLoads, fields)``, tuple.__new__ as
#: NamedTuple._make calls it, without _make's count check (the compiled kernels return a fixed count; 0.7 against
#: 1.1 us for a wrench's two results, against the constructor's 0.6 us for one, of a 4-9 us call; 2026-11-30)
_NEW = tuple.__new__


class _Buffers(threading.local):
    """The scalar paths' output arrays, one set per thread (a simulator-developer audit,
    2026-11-27: shared by the whole map, two threads' one-point calls returned each other's
    loads, about 1 in 200 calls)."""

    def __init__(self) -> None:
        #: the scratch of core._interp.interp_point, wrench_point and vehicle_point (the lookups' loads, inside
        #: and flagged; the first two return their fields, vehicle_point its flag in res[3, 1])
        self.res = np.empty((4, 4))


class RotorMap:
    """A rotor map ready to evaluate: ``RotorMap.open("map.nc").loads(omega, V, beta)``.

    Parameters
    ----------
    dataset : xarray.Dataset
        A map from :func:`build_map` or read from its netCDF file.
    interpolation : {"cubic", "linear"}
        ``"cubic"`` (default): tensor-product cubic Hermite with three-point slopes
        (core/_interp.py), continuous with a continuous first derivative along each
        axis; on the default grid its largest error is 3-9x smaller than the
        multilinear one, at 1.5x its cost per lookup (0.24 against 0.16 us; docs/simulators.md).
        ``"linear"``: multilinear in each cell, the C export's default. The map
        stores both measured bounds (``check_cubic_*``, ``check_linear_*``). For both,
        a query is flagged when any of the 4 x 4 x 4 nodes around its cell (its cell's
        and its neighbours') is.

    Attributes
    ----------
    omega, airspeed, incidence : ndarray
        The grid's axes in SI units (rad/s, m/s, rad).
    attrs : dict
        The map's metadata (propeller, parameters, model, version, citation, measured error).
    interpolation : str
    side_loads : bool
        The map holds the side force and the pitching moment (its set has blade flapping, a
        linear inflow or the dynamic stall); without them :class:`MapLoads` gives 0 for both.

    Raises
    ------
    TypeError
        ``dataset`` is not an xarray Dataset.
    ValueError
        The dataset is not a valid map (io.mapcheck.check_dataset: a missing variable,
        flag or axis, an axis outside the model's range, non-finite loads at a converged
        node, an attribute of the wrong type or out of range); unknown interpolation.
    """

    def __init__(self, dataset, interpolation: str = "cubic") -> None:
        if interpolation not in INTERPOLATIONS:
            raise ValueError(f"interpolation must be one of {', '.join(INTERPOLATIONS)}, got {interpolation!r}")
        self.interpolation = interpolation
        self._order = 3 if interpolation == "cubic" else 1
        check_dataset(dataset)
        ds = dataset.transpose("rpm", "airspeed", "incidence_deg")
        self.dataset = ds
        self.attrs = dict(ds.attrs)
        # the nodes where the map was solved: its SI coordinates omega and incidence where it has them (equal to the
        # rpm and degree axes to 1e-9, io.mapcheck; those are for people and may be rounded), else the axes converted
        self.omega = np.ascontiguousarray(ds["omega"].values if "omega" in ds.coords or "omega" in ds
                                          else ds["rpm"].values * RPM, dtype=float)
        self.airspeed = np.ascontiguousarray(ds["airspeed"].values, dtype=float)
        self.incidence = np.ascontiguousarray(ds["incidence"].values if "incidence" in ds.coords or "incidence" in ds
                                              else np.radians(ds["incidence_deg"].values), dtype=float)
        self.radius = float(ds.attrs["diameter_m"]) / 2
        ref = (self.omega[:, None] * self.radius) ** 2 + self.airspeed[None, :] ** 2
        table = np.stack([ds[k].values for k in LOADS], axis=-1) / ref[:, :, None, None]
        tables = [table]
        #: the map holds the side force and the pitching moment (io.mapcheck.SIDE_LOADS)
        self.side_loads = len(map_loads(ds)) > len(LOADS)
        if not self.side_loads:
            _warn_side_loads_missing(ds.attrs)
        finite = np.isfinite(table).all(axis=-1)
        if self.side_loads:  # Y, M_P in a second 4-wide table (zeros beside), for the compiled 4-load kernels
            side = np.stack([ds[k].values for k in SIDE_LOADS], axis=-1) / ref[:, :, None, None]
            finite &= np.isfinite(side).all(axis=-1)
            tables.append(np.concatenate([side, np.zeros_like(side)], axis=-1))
        #: the loads' table and the side table in one array, shape (1 or 2, n_Omega, n_V, n_beta, 4), for the
        #: scalar paths' one argument (core._interp.interp_point); _table and _side_table are views of it
        self._tables = np.ascontiguousarray(np.stack(tables), dtype=float)
        self._views()
        # a node whose loads are not finite is as unreliable as a non-converged one
        bad = ~ds["converged"].values.astype(bool) | ~finite
        for f in BAD_FLAGS:
            bad |= ds[f].values.astype(bool)
        # a cell is flagged when a node of it or of its neighbour cells is: the loads bend
        # sharply at the edge of the vortex-ring region, and the cubic reads those nodes
        self._cellflag = np.ascontiguousarray(_cell_flags(bad).astype(np.uint8))
        # the grid's box as Python floats, for the scalar fast path of loads()
        self._box = (float(self.omega[0]), float(self.omega[-1]), float(self.airspeed[0]), float(self.airspeed[-1]),
                     float(self.incidence[0]), float(self.incidence[-1]))
        from .core import _interp

        # the scalar paths' kernels, and their settings and axes packed per policy (core._interp.GRID_HEAD)
        self._interp_point, self._wrench_point = _interp.interp_point, _interp.wrench_point
        self._hover_speed = _interp.HOVER_SPEED  # (below it, on an airspeed axis from 0, any incidence is inside)
        self._grid = {name: np.concatenate([(self.radius, self._order, policy, strict, self.omega.size,
                                             self.airspeed.size), self.omega, self.airspeed, self.incidence])
                      for name, policy, strict in (("raise", _interp.CLIP, 1), ("clip", _interp.CLIP, 0),
                                                   ("nan", _interp.NAN, 0))}
        self._buffers = _Buffers()

    def __getstate__(self) -> dict:
        """Pickle and copy without the per-thread buffers (a copy makes its own)."""
        state = self.__dict__.copy()
        for k in ("_buffers", "_table", "_side_table"):  # (the tables as views of _tables again on loading)
            state.pop(k, None)
        return state

    def __setstate__(self, state: dict) -> None:
        if "_tables" not in state:  # pickled before 2026-11-28 (the tables apart): built again from its dataset
            self.__init__(state["dataset"], state["interpolation"])
            return
        self.__dict__.update(state)
        self._views()
        self._buffers = _Buffers()

    def _views(self) -> None:
        """The loads' table and the side table (None where the map holds none) as views of ``_tables``."""
        self._table = self._tables[0]
        self._side_table = self._tables[1] if self._tables.shape[0] > 1 else None

    @classmethod
    def open(cls, path, prop: str | None = None, interpolation: str = "cubic") -> "RotorMap":
        """Read a map's netCDF file (written by :func:`write_map` or ``propmap map``).

        Parameters
        ----------
        path : str or Path
        prop : str, optional
            For a map over several propellers (``propmap map --all``, a ``prop``
            dimension): the propeller to evaluate.
        interpolation : {"cubic", "linear"}
            As in :class:`RotorMap`.

        Returns
        -------
        RotorMap

        Raises
        ------
        TypeError
            ``path`` not a str or os.PathLike, ``prop`` not a str.
        ValueError
            Not a regular file, not a readable netCDF file (whatever the netCDF/HDF5
            libraries raise on a damaged file), declared sizes beyond MAX_NODES nodes
            (refused before reading), not a valid rotor map (:class:`RotorMap`), or
            ``prop`` missing or unknown for a map over several propellers; the message
            names the file (io.mapfile.read_dataset). Unknown interpolation.
        """
        if interpolation not in INTERPOLATIONS:
            raise ValueError(f"interpolation must be one of {', '.join(INTERPOLATIONS)}, got {interpolation!r}")
        ds = read_dataset(path, prop)
        try:
            return cls(ds, interpolation)
        except ValueError as exc:
            raise ValueError(f"{short_path(path)}: {exc}") from None

    def _queries(self, omega, airspeed, incidence, out_of_grid):
        arrays = []
        for name, v in (("omega", omega), ("airspeed", airspeed), ("incidence", incidence)):
            refuse_masked(name, v)
            try:
                a = np.asarray(v)
            except ValueError:  # a ragged list
                raise ValueError(f"{name} must be a number or a rectangular array of numbers, got {v!r:.60}") from None
            if a.dtype.kind not in "fiu" or has_bool(v):
                raise ValueError(f"{name} must be a number or an array of numbers, got {v!r:.60}")
            arrays.append(a.astype(float, copy=False))
        try:
            q = broadcast_readonly(*arrays)
        except ValueError:
            raise ValueError("omega, airspeed and incidence must broadcast together, got shapes "
                             f"{', '.join(str(a.shape) for a in arrays)}") from None
        for name, a in zip(("omega", "airspeed", "incidence"), q):
            if np.isnan(a).any():
                raise ValueError(f"{name} must not be NaN")
        # an incidence within INCIDENCE_SNAP of an end of the axis is on it (float32's pi)
        # and an airspeed within AIRSPEED_SNAP of an end (|V| from a velocity, rounded either way)
        q = [q[0], snap_airspeed(q[1], self._box[2], self._box[3]), snap_incidence(q[2], self._box[4], self._box[5])]
        if (q[0] < 0).any():
            raise ValueError(f"omega must be >= 0 rad/s, the rotation rate's magnitude (the sense is the spin), got "
                             f"{float(q[0][q[0] < 0].reshape(-1)[0])!r}")
        if (q[1] < 0).any():  # (clipped to still air under "clip" until 2026-11-28: a user-level audit)
            raise ValueError(f"airspeed must be >= 0 m/s, the speed's magnitude (its direction is the incidence), "
                             f"got {float(q[1][q[1] < 0].reshape(-1)[0])!r}")
        if out_of_grid == "raise":
            for name, a, ax, unit in (("omega", q[0], self.omega, "rad/s"), ("airspeed", q[1], self.airspeed, "m/s"),
                                      ("incidence", q[2], self.incidence, "rad")):
                with np.errstate(invalid="ignore"):
                    bad = ~((a >= ax[0]) & (a <= ax[-1]))
                if name == "incidence" and self.airspeed[0] == 0.0:  # (still air: any incidence, core._interp)
                    bad &= q[1] > self._hover_speed
                if bad.any():
                    v = float(a.reshape(-1)[int(np.argmax(bad.reshape(-1)))])
                    lo, hi = f"{ax[0]:g}", f"{ax[-1]:g}"
                    if float(lo) <= v <= float(hi):  # (rounded, the ends would hold the value: shown whole)
                        lo, hi = repr(float(ax[0])), repr(float(ax[-1]))
                    raise OutOfGridError(name, f"{name} = {v!r} is outside the map's grid [{lo}, {hi}] {unit} "
                                               "(out_of_grid='clip' or 'nan' to flag instead)")
        return q

    def loads(self, omega, airspeed, incidence, *, out_of_grid: str = "raise") -> MapLoads:
        """Interpolated loads at Omega [rad/s], V [m/s], incidence beta [rad] (broadcast).

        Parameters
        ----------
        omega, airspeed, incidence : float or array_like
            Broadcast together to a shape S. An incidence within 2.5e-7 rad of an end of the
            grid's incidence axis is on it (single precision's pi, 8.7e-8 rad above pi).
        out_of_grid : {"raise", "clip", "nan"}
            A query outside the grid raises ValueError ("raise", the default), takes the
            value at the nearest boundary point ("clip"), or gets NaN ("nan"); the last two
            set ``inside = False`` and ``flagged = True``. Never silent extrapolation. Under
            "clip", a rotation rate below the grid's lowest, 0 <= Omega < Omega_min (spin-up,
            a stopped or windmill-starting rotor), takes the lowest row's loads at the same
            airspeed and incidence scaled by (Omega / Omega_min)^2, the loads of a rotor with
            constant coefficients: 0 at Omega = 0 (a parked rotor's blade drag is not
            modelled), continuous at Omega_min.

        Returns
        -------
        MapLoads

        Raises
        ------
        ValueError
            Non-numeric or NaN queries, Omega < 0 (a signed rate: give its magnitude, the
            sense is the spin of :meth:`wrench`), an airspeed < 0 (a speed is a magnitude; its
            direction is the incidence), an unknown policy, or (policy "raise") a
            query outside the grid, naming the argument and the grid's range.
        """
        o, v, b = plain_float(omega), plain_float(airspeed), plain_float(incidence)
        if o is not None and v is not None and b is not None:
            fast = self._loads1(o, v, b, out_of_grid)
            if fast is not None:
                return fast
        from .core import _interp

        if out_of_grid not in POLICIES:
            raise ValueError(f"out_of_grid must be one of {', '.join(POLICIES)}, got {out_of_grid!r}")
        policy = _interp.NAN if out_of_grid == "nan" else _interp.CLIP
        q = self._queries(omega, airspeed, incidence, out_of_grid)
        shape = q[0].shape
        # contiguous and writeable (a read-only omega, which _queries passes on unchanged, compiled interp_batch once
        # more for its type)
        flat = [np.require(a.reshape(-1), requirements=("C", "W")) for a in q]
        n = flat[0].size
        out = np.empty((n, len(LOADS)))
        inside = np.empty(n, dtype=np.bool_)
        flagged = np.empty(n, dtype=np.bool_)
        _interp.interp_batch(self.omega, self.airspeed, self.incidence, self._table, self._cellflag, self.radius,
                             *flat, policy, self._order, out, inside, flagged)
        side = np.zeros((n, 2))
        if self.side_loads:  # the same queries in the side table: the same inside and flagged
            side = np.empty((n, len(LOADS)))
            _interp.interp_batch(self.omega, self.airspeed, self.incidence, self._side_table, self._cellflag,
                                 self.radius, *flat, policy, self._order, side, inside, flagged)
        # under "clip" the loads hold at the top row above the grid, at the query's Omega below it (scaled)
        # (a copy: q[0] may be the caller's array, which the result shared and, writeable, let write: a user-level
        # audit, 2026-11-30)
        om = np.minimum(q[0], self.omega[-1]) if out_of_grid == "clip" else q[0].copy()
        return MapLoads(*(out[:, k].reshape(shape) for k in range(len(LOADS))), omega=om,
                        inside=inside.reshape(shape), flagged=flagged.reshape(shape),
                        side_force=side[:, 0].reshape(shape), pitching_moment=side[:, 1].reshape(shape))

    def wrench(self, velocity, axis, omega, spin="ccw", *, out_of_grid: str = "raise") -> MapWrench:
        """Force and moment vectors from the map, as :func:`propmap.rotor_wrench`.

        Parameters
        ----------
        velocity, axis : array_like, shape S + (3,)
            Hub velocity relative to the air [m/s]; rotor axis (thrust direction).
        omega : float or array_like, shape S
            Omega [rad/s].
        spin : {"ccw", "cw"} or +1/-1
        out_of_grid : {"raise", "clip", "nan"}
            As :meth:`loads`.

        Returns
        -------
        MapWrench

        Raises
        ------
        ValueError
            As :func:`propmap.rotor_wrench` and :meth:`loads`; a velocity component of
            :data:`VELOCITY_MAX` (1e150 m/s) or more.
        """
        fast = self._wrench1(velocity, axis, omega, spin, out_of_grid)
        if fast is not None:
            return fast
        from .core.vector import _check_spin, _spin_sign, disk_frame, wrench_vectors

        V, z, speed, beta = disk_frame(velocity, axis)
        if np.any(np.abs(V) >= VELOCITY_MAX):
            big = float(np.max(np.abs(V)))
            raise ValueError(f"velocity: a component of {big:.6g} m/s; a hub velocity must be below {VELOCITY_MAX:g} "
                             "m/s (its force and moment vectors would overflow)")
        s = _spin_sign(spin)
        try:  # (a ragged omega: loads names it)
            omega_shape = np.shape(omega)
        except ValueError:
            omega_shape = None
        try:  # (said of omega, airspeed and incidence, which the caller never gave: a simulator-user audit, 2026-11-30)
            np.broadcast_shapes(speed.shape, omega_shape or ())
        except ValueError:
            raise ValueError(f"omega (shape {omega_shape}) must broadcast with the samples of velocity and axis "
                             f"(shape {speed.shape}: velocity {np.shape(velocity)}, axis {np.shape(axis)})") from None
        try:
            ml = self.loads(omega, speed, beta, out_of_grid=out_of_grid)
        except OutOfGridError as exc:  # (the airspeed and incidence are no arguments here: named by what gives them)
            if exc.quantity == "omega":
                raise
            raise OutOfGridError(exc.quantity, exc.detail, "velocity and axis give the hub's ") from None
        _check_spin(s, np.shape(ml.thrust))
        force, moment = wrench_vectors(ml.thrust, ml.drag, ml.torque, ml.rolling_moment, V, z, s,
                                       side_force=ml.side_force, pitching_moment=ml.pitching_moment)
        return MapWrench(force=force, torque=moment, loads=ml)

    def _loads1(self, omega: float, airspeed: float, incidence: float, out_of_grid):
        """:meth:`loads` at one point of Python floats (a simulator's call): no arrays built, no
        broadcasting. None where the general path must answer (an unknown policy, a NaN, or
        a query outside the grid under "raise"), which then raises what it raises."""
        o0, o1, v0, v1, b0, b1 = self._box
        if not b0 <= incidence <= b1:  # within INCIDENCE_SNAP of an end: on it (float32's pi)
            incidence = snap_incidence_scalar(incidence, b0, b1)
        if not v0 <= airspeed <= v1:  # within AIRSPEED_SNAP of an end: on it
            airspeed = snap_airspeed_scalar(airspeed, v0, v1)
        inside = o0 <= omega <= o1 and v0 <= airspeed <= v1 and (
            b0 <= incidence <= b1 or (airspeed <= self._hover_speed and v0 == 0.0 and incidence == incidence))
        if not inside and (out_of_grid not in ("clip", "nan") or math.isnan(omega) or math.isnan(airspeed)
                           or math.isnan(incidence) or omega < 0 or airspeed < 0):
            return None
        if out_of_grid not in POLICIES:
            return None
        # (the fields in MapLoads' order, Omega held at the grid's top under "clip": core._interp._fields)
        return _NEW(MapLoads, self._interp_point(self._grid[out_of_grid], self._tables, self._cellflag, omega,
                                                airspeed, incidence, self._buffers.res))

    def _packed(self, out_of_grid):
        """(grid, tables, cellflag, res) of the compiled one-point kernels (core._interp) under the
        policy ``out_of_grid``, ``res`` this thread's; None for an unknown policy or where this
        map's ``wrench`` is not RotorMap's own (a subclass's or an instance's: VehicleMap's
        one-step path then calls it rotor by rotor, as it always did; a review)."""
        if type(self).wrench is not RotorMap.wrench or "wrench" in self.__dict__:
            return None
        grid = self._grid.get(out_of_grid) if isinstance(out_of_grid, str) else None
        return None if grid is None else (grid, self._tables, self._cellflag, self._buffers.res)

    def _wrench1(self, velocity, axis, omega, spin, out_of_grid):
        """:meth:`wrench` for one rotor (a simulator's call) in one compiled call
        (core._interp.wrench_point: the arithmetic of core.vector.disk_frame and
        wrench_vectors), without building and broadcasting arrays. None where the inputs
        are not one rotor's plain numbers, or not finite, or outside the grid under
        "raise": the general path then answers (and raises what it raises)."""
        v, a, omega = plain_vector(velocity, 3), plain_vector(axis, 3), plain_float(omega)
        if v is None or a is None or omega is None or omega != omega:
            return None  # (a velocity beyond VELOCITY_MAX: wrench_point returns 1, and the general path refuses it)
        s = SPINS.get(spin.lower()) if isinstance(spin, str) else plain_float(spin)  # (a NumPy +-1 too)
        s = s if s in (1.0, -1.0) else None
        grid = self._grid.get(out_of_grid) if isinstance(out_of_grid, str) else None
        if s is None or grid is None:
            return None
        vectors = np.empty((2, 3))  # (the vectors returned: a new array each call)
        status, fields = self._wrench_point(grid, self._tables, self._cellflag, v, a, omega, s, self._buffers.res,
                                            vectors)
        if status:
            return None
        return _NEW(MapWrench, (vectors[0], vectors[1], _NEW(MapLoads, fields)))

    def check(self, n_check: int = 2000, *, seed: int = 0) -> dict:
        """The map's interpolation error against the model recorded in it (:func:`check_map`).

        Parameters
        ----------
        n_check : int
            Number of random off-grid points, in [1, 1,000,000].
        seed : int
            Seed of the points (NumPy's ``default_rng``), in [0, 2**63 - 1].

        Returns
        -------
        dict
            As :func:`check_map`.

        Raises
        ------
        ValueError, SolverError
            As :func:`check_map`.
        """
        return check_map(self.dataset, n_check, seed=seed)


def check_map(ds, n_check: int = 2000, *, seed: int = 0, propeller=None, params=None, air=None,
              discretization=None) -> dict:
    """Interpolation error of a map against the full model at random off-grid points.

    Points are uniform in the grid's box. Errors are normalised per point: T and P by the
    static thrust and power at the point's Omega, Q by the static torque, D and M_R by the
    largest |D| (|M_R|) of the map at the two rpm rows around the point, or the model's own
    |D| (|M_R|) there where that is larger. Points flagged by
    the evaluator (a node within one node of their cell in vortex_ring, with multiple
    roots, or not converged), or that the model flags so, are counted apart ("flagged
    regions"). A map with the side force and pitching moment has them checked too,
    normalised as D and M_R by their largest values at the two rpm rows.

    Parameters
    ----------
    ds : xarray.Dataset
        A map from :func:`propmap.maps.build_map` (or read back from netCDF).
    n_check : int
        Number of points, in [1, 1,000,000].
    seed : int
        In [0, 2**63 - 1].
    propeller, params, air, discretization
        The model; default: the one recorded in the map.

    Returns
    -------
    dict
        ``check_points``, ``check_points_flagged``, ``check_seed``, ``check_normalisation``
        and, per interpolation m (linear, cubic) and variable (thrust, drag, torque,
        rolling_moment, side_force and pitching_moment where the map holds them, power),
        ``check_<m>_<var>_rms`` and ``check_<m>_<var>_max``
        outside flagged regions, with ``check_<m>_<var>_max_at`` the maximum's point [rpm,
        m/s, deg] (where there is one), and ``check_<m>_<var>_max_flagged`` inside them (NaN if
        there are none); both methods on the same points and flagged regions.

    Raises
    ------
    ValueError
        ``n_check`` or ``seed`` out of range; a map that does not record its model (when
        one is not given), is malformed (io.mapcheck.check_dataset) or stores a power, CT or
        CP its loads do not give (io.mapcheck.check_derived).
    """
    from .core.solver import rotor_loads  # here: evaluating a map needs neither the solver nor SciPy

    n_check = integer("n_check", n_check, 1, CHECK_POINTS_MAX)
    seed = integer("seed", seed, 0, SEED_MAX)
    check_dataset(ds)
    check_derived(ds)  # (the stored power, CT, CP: a reader of the file uses them; the interpolation does not)
    if None in (propeller, params, air, discretization):
        model = map_model(ds.attrs)
        prop = propeller or model[0]
        params = params or model[1]
        air = air or model[2]
        disc = discretization or model[3]
    else:
        prop, disc = propeller, discretization
    evaluators = {m: RotorMap(ds, m) for m in INTERPOLATIONS}
    rm = evaluators["linear"]
    rng = np.random.default_rng(seed)
    om = rng.uniform(rm.omega[0], rm.omega[-1], n_check)
    V = rng.uniform(rm.airspeed[0], rm.airspeed[-1], n_check)
    b = rng.uniform(rm.incidence[0], rm.incidence[-1], n_check)
    full = rotor_loads(prop, params, om, V, b, air=air, discretization=disc, on_failure="flag", radial=False)
    static = rotor_loads(prop, params, om, 0.0, 0.0, air=air, discretization=disc, on_failure="flag", radial=False)
    row = np.clip(np.searchsorted(rm.omega, om, side="right") - 1, 0, rm.omega.size - 2)
    norm = {"thrust": np.abs(static.thrust), "torque": np.abs(static.torque), "power": np.abs(static.power)}
    loads = map_loads(ds)
    for k in ("drag", "rolling_moment", *loads[len(LOADS):]):
        peak = np.max(np.abs(ds[k].transpose("rpm", ...).values), axis=(1, 2))
        # (not below the model's own value at the point: a map whose nodes all hold D = 0, its incidence axis
        # only 0 and 180 deg, divided every error by an infinite norm and reported 0% where it gave D = 0)
        norm[k] = np.maximum(np.maximum(peak[row], peak[row + 1]), np.abs(getattr(full, k)))
    peaks = "D, M_R (Y, M_P)" if len(loads) > len(LOADS) else "D and M_R"
    out = {"check_points": int(n_check), "check_seed": int(seed),
           "check_normalisation": "fractions (0.01 is 1%), per point: T, P by the static thrust and power at its "
                                  "Omega, Q by the static "
                                  f"torque, {peaks} by their largest magnitude in the map at the rpm rows around it "
                                  "(or the model's at the point where larger); "
                                  "flagged: the point, or a node within one node of its cell, in vortex ring, "
                                  "with multiple roots or not converged"}
    for method, evaluator in evaluators.items():
        prefix = f"check_{method}_"
        got = evaluator.loads(om, V, b)
        # both methods flag the same cells (RotorMap), so the same points
        flagged = got.flagged | ~full.converged | full.vortex_ring | full.multiple_roots
        out["check_points_flagged"] = int(flagged.sum())
        for k in (*loads, "power"):
            err = np.abs(getattr(got, k) - getattr(full, k)) / np.where(norm[k] > 0, norm[k], np.inf)
            ok = err[~flagged]
            out[f"{prefix}{k}_rms"] = float(np.sqrt(np.mean(ok**2))) if ok.size else math.nan
            out[f"{prefix}{k}_max"] = float(np.max(ok)) if ok.size else math.nan
            if ok.size:  # (where: the axis to refine)
                at = int(np.flatnonzero(~flagged)[np.argmax(ok)])
                out[f"{prefix}{k}_max_at"] = [float(om[at] / RPM), float(V[at]), math.degrees(b[at])]
            out[f"{prefix}{k}_max_flagged"] = float(np.nanmax(err[flagged])) if flagged.any() else math.nan
    return out
