"""The vehicle model evaluated from rotor maps: a simulator's vehicle step in one batch call.

The same sums as :func:`propmap.vehicle.vehicle_wrench` (module ``model``): rotor i at hub
position r_i (from the centre of mass) with axis a_i sees the air at V_i = v + w x r_i -
v_wind, its force F_i and hub moment M_i come from its map (``RotorMap.wrench``: T z - D e_ip
+ Y e_adv and -s_i (Q z + M_R e_ip) + M_P (e_ip x z), Y and M_P where the map holds them)
instead of the full model, and

    F = sum_i F_i + F_body,    M = sum_i (r_i x F_i + M_i - w x h_i),

with h_i = s_i J_i Omega_i a_i where the rotor inertia J_i is known (the spin-up reaction of
``vehicle_wrench``'s ``rotor_acceleration`` is not included). F_body is the airframe
drag at the centre of mass (core/body.py) in the freestream: a map holds no induced
velocity, so the slipstream term of a vehicle's ``wash_factor`` and the rotors' interference
(``rotor_interference``, core/interference.py) are left out (said once, at construction).
The maps are duck-typed (anything with RotorMap's ``wrench``), so this module imports the
core only. One step (a simulator's call) of a vehicle whose rotors share one RotorMap is one
compiled call (core._interp.vehicle_point, through the map's ``_packed`` arguments); otherwise
each rotor takes its map's one-rotor path.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, replace

import numpy as np

from ..core._interp import OutOfGridError, vehicle_point
from ..core._plain import plain_vector
from ..core._numbers import checked
from ..core.body import body_drag_force
from ..core.vector import VELOCITY_MAX, cross3
from ._kinematics import _samples, hub_velocities
from .layout import Vehicle, check_vehicle, rotor_geometry

__all__ = ["VehicleMap", "VehicleMapWrench"]


def _check_rotor_map(i: int, m, rotor) -> None:
    """Refuse rotor ``i``'s map ``m`` where it was built for another blade geometry or, for a rotor
    with its own set, another set than the rotor's (the models the map records: the C header's
    checks, export_c; until 2026-12-01 only the diameter and blade count were checked, and an
    apce_8x4 rotor took an apce_8x6 map, 21% more hover thrust, a rotor's own set the map's,
    4% of the thrust: a vehicle-model audit); a map without that record by its size."""
    from ..io.mapcheck import map_model

    try:
        recorded = map_model(m.attrs)
    except ValueError:  # (a map written before its model was recorded, or a duck-typed one)
        recorded = None
    d, b = float(m.attrs.get("diameter_m", np.nan)), m.attrs.get("n_blades")
    p = rotor.propeller
    same = (p.same_geometry(recorded[0]) if recorded is not None else bool(np.isfinite(d)) and p.same_size(d, b))
    if not same:
        other = (", another chord or blade angle" if recorded is not None
                 and recorded[0].same_size(p.diameter, p.n_blades, rtol=5e-5) else "")
        raise ValueError(f"maps: rotor {i + 1}'s map is of {m.attrs.get('propeller', '?')} ({d:.4g} m, {b} blades), "
                         f"its propeller {p.name} is {p.diameter:.4g} m with {p.n_blades} blades{other}: build the "
                         "map for the vehicle's propeller (propmap map PROP, PROP the rotor's propeller, one map per "
                         "propeller)")
    if recorded is not None and rotor.params is not None and not recorded[1].same_section(rotor.params):
        raise ValueError(f"maps: rotor {i + 1} has its own parameter set ({rotor.params.label or 'unlabelled'}), its "
                         f"map another ({m.attrs.get('params_label') or 'unlabelled'}): build that rotor's map with "
                         "its set (one map per rotor)")


def _warn_map_air(maps, vehicle: Vehicle) -> None:
    """Warn where the maps were built in different densities, or a rotor's own set carries another
    air than its map was built in (accepted silently until 2026-12-01: a quadrotor's maps at rho
    1.225 and 1.0 made a yaw moment of -0.018 N m in hover, an air-consistency audit; each map is
    evaluated in its own air, as vehicle_wrench solves every rotor in one)."""
    rho = [float(m.attrs.get("rho_kg_m3", np.nan)) for m in maps]
    known = list(dict.fromkeys(r for r in rho if np.isfinite(r)))
    if len(known) > 1:
        warnings.warn(f"maps: built in different air (rho {', '.join(f'{r:.4g}' for r in known)} kg/m^3): each rotor "
                      "is evaluated in its map's, the airframe's drag in the first map's (or rho=)", UserWarning,
                      stacklevel=3)
    other = [(k + 1, r.params.air.rho, rho[k]) for k, r in enumerate(vehicle.rotors)
             if r.params is not None and np.isfinite(rho[k]) and not np.isclose(r.params.air.rho, rho[k], rtol=1e-9)]
    if other:
        k, own, made = other[0]
        warnings.warn(f"rotor {k} has its own parameter set in other air (rho {own:.4g} kg/m^3) than its map (rho "
                      f"{made:.4g} kg/m^3){f', and {len(other) - 1} more rotor(s)' if len(other) > 1 else ''}: the "
                      "map's air is used", UserWarning, stacklevel=3)


@dataclass(frozen=True)
class VehicleMapWrench:
    """Force and moment on a vehicle from its rotors' maps, body axes, at N samples.

    Attributes
    ----------
    force : ndarray, shape (N, 3)
        Rotor forces and airframe drag [N] (no gravity).
    moment : ndarray, shape (N, 3)
        About the centre of mass [N m].
    flagged : ndarray of bool, shape (N,)
        A rotor's query lies outside its map's grid or in a flagged cell: the maps' error
        bounds do not hold for that sample.
    """

    force: np.ndarray
    moment: np.ndarray
    flagged: np.ndarray


class VehicleMap:
    """A vehicle whose rotors are evaluated from maps (module docstring).

    Parameters
    ----------
    vehicle : Vehicle
        Taken as it is now: the VehicleMap keeps a copy of its rotors' arrays (``.vehicle``), so
        a rotor position or axis written in place afterwards changes nothing here (build another
        VehicleMap; :func:`propmap.vehicle_wrench` reads the vehicle at every call). Until
        2026-11-30 it kept the caller's vehicle but the geometry of its construction, so that
        ``.vehicle`` showed a tilted rotor the forces did not have (a concurrency audit).
    maps : RotorMap or sequence of RotorMap
        One map for every rotor, or one per rotor in the vehicle's order, each built for that
        rotor's propeller and, for a rotor with its own parameter set (``Rotor.params``), with
        that set: checked against the model the map records (its blade geometry and set:
        :func:`propmap.io.mapcheck.map_model`), or, for a map without that record, its diameter
        and blade count.
    rho : float, optional
        Air density for the airframe drag [kg/m^3]; default the first map's
        (``attrs["rho_kg_m3"]``).

    Raises
    ------
    TypeError
        ``vehicle`` not a :class:`propmap.Vehicle`.
    ValueError
        ``maps`` neither a RotorMap nor a sequence of them, a
        number of maps other than 1 or the number of rotors, a map of another blade geometry
        than its rotor's propeller (without the record: another diameter, by more than 1%, or
        blade count), a map of another parameter set than its rotor's own, or ``rho`` not a
        positive finite number, or not given where the first map records no density.

    Warns
    -----
    UserWarning
        The vehicle's airframe drag has a slipstream factor (``wash_factor`` > 0): left out;
        maps built in different air (the airframe's drag takes the first map's density), or a
        rotor's own set in other air than its map's (the map's is used).
    """

    def __init__(self, vehicle: Vehicle, maps, *, rho: float | None = None) -> None:
        check_vehicle(vehicle)  # (a TypeError, as at every entry point that takes a vehicle; it was a ValueError)
        n = len(vehicle.rotors)
        try:
            maps = [maps] * n if hasattr(maps, "wrench") else list(maps)
        except TypeError:  # (None met "'NoneType' object is not iterable", a user-level audit, 2026-11-30)
            raise ValueError(f"maps must be one RotorMap or one per rotor ({n}), got {type(maps).__name__}") from None
        if len(maps) != n or not all(hasattr(m, "wrench") for m in maps):
            raise ValueError(f"maps must be one RotorMap or one per rotor ({n}), got {len(maps)}")
        for i, (m, r) in enumerate(zip(maps, vehicle.rotors)):
            _check_rotor_map(i, m, r)
        _warn_map_air(maps, vehicle)
        # a snapshot: each Rotor and the centre of mass re-made, their arrays copied (layout._vector3)
        vehicle = replace(vehicle, rotors=tuple(replace(r) for r in vehicle.rotors))
        self.vehicle = vehicle
        self.maps = maps
        self._pos, self._axes, self._spins, self._h = rotor_geometry(vehicle)
        # the same as Python floats and lists, for the one-step path
        self._pos_list = self._pos.tolist()
        self._reach = float(np.max(np.linalg.norm(self._pos, axis=1))) if len(self._pos) else 0.0  # the longest arm
        self._h_list = self._h.tolist()
        self._spin_list = [float(x) for x in self._spins]
        groups: dict[int, list[int]] = {}
        for i, m in enumerate(maps):
            groups.setdefault(id(m), []).append(i)
        self._groups = [(maps[idx[0]], np.array(idx)) for idx in groups.values()]
        # one map for every rotor: one step in one compiled call, the rotors as core._interp.vehicle_point's rows
        # (ROTOR_COLUMNS: arm, axis, spin, h)
        self._one_map = maps[0] if len(self._groups) == 1 and hasattr(maps[0], "_packed") else None
        self._rotors = np.ascontiguousarray(np.column_stack([self._pos, self._axes, self._spins, self._h]), dtype=float)
        body = vehicle.body_drag
        self._body = body if body is not None and body.active else None
        if self._body is not None and self._body.wash_factor > 0:
            warnings.warn(f"the airframe's slipstream factor ({self._body.wash_factor:g}) is left out: a map holds no "
                          "induced velocity; its drag is taken in the freestream", UserWarning, stacklevel=2)
        if vehicle.rotor_interference > 0:
            warnings.warn(f"the rotors' interference (factor {vehicle.rotor_interference:g}) is left out: a map "
                          "holds no induced velocity; each rotor is evaluated in the freestream", UserWarning,
                          stacklevel=2)
        # (any rho was taken: -1 reversed the airframe drag, NaN made every force NaN, a user-level audit, 2026-11-30)
        if rho is None and "rho_kg_m3" not in maps[0].attrs:  # (a bare KeyError: an audit, stop 100)
            raise ValueError("rho: the first map records no density (attribute rho_kg_m3, a map of another program): "
                             "give rho= [kg/m^3] for the airframe drag")
        self._rho = float(maps[0].attrs["rho_kg_m3"]) if rho is None else checked("rho", rho, 0.0, low_open=True,
                                                                                     unit="kg/m^3")

    @staticmethod
    def _check_hub(hub: float) -> None:
        """Refuse inputs whose bound ``hub`` [m/s] on a rotor hub's velocity component reaches
        VELOCITY_MAX (the rotors' wrench vectors would overflow; the C header refuses it too)."""
        if not hub < VELOCITY_MAX:
            raise ValueError(f"velocity, wind and angular_velocity make a rotor hub's velocity of up to {hub:.3g} m/s "
                             f"(velocity - wind + angular_velocity x arm); it must stay below {VELOCITY_MAX:g} m/s")

    def _step1(self, velocity, angular_velocity, rotor_omega, wind, out_of_grid):
        """:meth:`wrench` at one step of plain numbers (a simulator's call) in one compiled call
        (core._interp.vehicle_point) where every rotor shares one map; None where the general
        path must answer (other inputs, a non-finite one, a query outside the grid under
        "raise", an unknown policy), which then raises what it raises."""
        v, w = plain_vector(velocity, 3, int64=True), plain_vector(angular_velocity, 3, int64=True)
        om = plain_vector(rotor_omega, self._rotors.shape[0], int64=True)
        if v is None or w is None or om is None:
            return None
        if wind is not None:
            v_wind = plain_vector(wind, 3, int64=True)
            if v_wind is None:
                return None
            v = v - v_wind
        packed = self._one_map._packed(out_of_grid)
        if packed is None:
            return None
        grid, tables, cellflag, res = packed
        out = np.empty((2, 1, 3))  # (the force and moment returned: a new array each call)
        if vehicle_point(grid, tables, cellflag, self._rotors, self._reach, v, w, om, res, out):
            return None
        force = out[0]
        if self._body is not None:
            force = force + body_drag_force(self._body, v[None, :], np.zeros((1, 3)), self._rho)
        return VehicleMapWrench(force=force, moment=out[1], flagged=np.array([res[3, 1] != 0.0]))

    @staticmethod
    def _rotor_error(k: int, exc: ValueError) -> ValueError:
        """A rotor map's error in the caller's terms: ``omega`` is rotor ``k``'s entry of
        ``rotor_omega``, and the hub's airspeed and incidence come from ``velocity``,
        ``angular_velocity`` and ``wind`` (said as the map's own quantities, no rotor named,
        until stop 100: an audit)."""
        if isinstance(exc, OutOfGridError) and exc.quantity != "omega":
            given = f"velocity, angular_velocity and wind give rotor {k}'s hub "
            return OutOfGridError(exc.quantity, exc.detail, given)
        if str(exc).startswith("omega"):  # (outside the grid, or below 0)
            return ValueError(f"rotor_omega: rotor {k}'s {exc}")
        return exc

    def _step(self, air_v: list, w: list, om: list, out_of_grid: str):
        """One step's (force, moment, flagged), shapes (1, 3), (1, 3), (1,): the sums of
        :meth:`wrench` in Python floats, each rotor by RotorMap.wrench's one-rotor path."""
        vx, vy, vz = air_v
        wx, wy, wz = w
        F = [0.0, 0.0, 0.0]
        M = [0.0, 0.0, 0.0]
        flagged = False
        h = [0.0, 0.0, 0.0]
        for i, m in enumerate(self.maps):
            px, py, pz = self._pos_list[i]
            v_hub = np.array((vx + wy * pz - wz * py, vy + wz * px - wx * pz, vz + wx * py - wy * px))
            try:
                res = m.wrench(v_hub, self._axes[i], float(om[i]), self._spin_list[i], out_of_grid=out_of_grid)
            except ValueError as exc:
                raise self._rotor_error(i + 1, exc) from None
            fx, fy, fz = res.force.tolist()
            mx, my, mz = res.torque.tolist()
            F[0] += fx
            F[1] += fy
            F[2] += fz
            M[0] += py * fz - pz * fy + mx
            M[1] += pz * fx - px * fz + my
            M[2] += px * fy - py * fx + mz
            flagged = flagged or bool(res.loads.flagged)
            hx, hy, hz = self._h_list[i]
            h[0] += hx * om[i]
            h[1] += hy * om[i]
            h[2] += hz * om[i]
        M[0] -= wy * h[2] - wz * h[1]  # gyroscopic: -w x h
        M[1] -= wz * h[0] - wx * h[2]
        M[2] -= wx * h[1] - wy * h[0]
        return np.array([F]), np.array([M]), np.array([flagged])

    def wrench(self, velocity, angular_velocity, rotor_omega, *, wind=None,
               out_of_grid: str = "raise") -> VehicleMapWrench:
        """Body force and moment at N samples (broadcast like :func:`propmap.vehicle_wrench`).

        Parameters
        ----------
        velocity : array_like, shape (N, 3) or (3,)
            Velocity of the centre of mass over the ground, body axes [m/s].
        angular_velocity : array_like, shape (N, 3) or (3,)
            Body rates w [rad/s].
        rotor_omega : array_like, shape (N, n_rotors) or (n_rotors,)
            Rotor speeds Omega_i >= 0 [rad/s], in the vehicle's rotor order.
        wind : array_like, shape (N, 3) or (3,), optional
            Wind velocity in body axes [m/s].
        out_of_grid : {"raise", "clip", "nan"}
            As :meth:`propmap.RotorMap.loads` (under "clip" a rotor below its grid's lowest
            rpm, a stopped one included, has its loads scaled to zero).

        Returns
        -------
        VehicleMapWrench

        Raises
        ------
        ValueError
            Inputs not numbers, of the wrong shape, non-finite, with sample counts that do
            not match; what the maps raise (a query outside a grid under "raise", naming it;
            Omega < 0).

        Notes
        -----
        One step of plain numbers (``velocity`` and ``angular_velocity`` of shape (3,),
        ``rotor_omega`` of shape (n_rotors,), arrays, lists or tuples) on a vehicle whose rotors
        share one map is one compiled call (core._interp.vehicle_point; 14-17 us against 117-121
        us for each rotor through its map, Intel Xeon, docs/simulators.md); the same sums to
        1e-13. Threads may share a VehicleMap: a RotorMap's scalar path keeps its output buffers
        per thread.
        """
        if self._one_map is not None:
            fast = self._step1(velocity, angular_velocity, rotor_omega, wind, out_of_grid)
            if fast is not None:
                return fast
        n_rot = len(self.vehicle.rotors)
        v = _samples("velocity", velocity, 3)
        w = _samples("angular_velocity", angular_velocity, 3)
        om = _samples("rotor_omega", rotor_omega, n_rot)
        wind_a = np.zeros((1, 3)) if wind is None else _samples("wind", wind, 3)
        counts = {a.shape[0] for a in (v, w, om, wind_a)} - {1}
        if len(counts) > 1:
            raise ValueError("velocity, angular_velocity, rotor_omega and wind must have the same number of samples "
                             f"(or one), got {[a.shape[0] for a in (v, w, om, wind_a)]}")
        N = counts.pop() if counts else 1
        air_v = np.broadcast_to(v - wind_a, (N, 3))
        w = np.broadcast_to(w, (N, 3))
        om = np.broadcast_to(om, (N, n_rot))
        if N == 1:  # one step (a simulator's call): each rotor through its map's one-rotor path, in floats
            v1, w1 = air_v[0].tolist(), w[0].tolist()
            self._check_hub(max(map(abs, v1)) + max(map(abs, w1)) * self._reach)
            force, moment, flagged = self._step(v1, w1, om[0].tolist(), out_of_grid)
        else:
            self._check_hub(float(np.max(np.abs(air_v), initial=0.0)) + float(np.max(np.abs(w), initial=0.0))
                            * self._reach)  # (initial: no samples, shape (0, 3), as vehicle_wrench gives)
            v_hub = hub_velocities(air_v, w, self._pos)  # (N, n_rot, 3)
            force = np.zeros((N, 3))
            moment = np.zeros((N, 3))
            flagged = np.zeros(N, dtype=bool)
            for m, idx in self._groups:
                try:
                    res = m.wrench(v_hub[:, idx, :], self._axes[idx], om[:, idx], self._spins[idx],
                                   out_of_grid=out_of_grid)
                except ValueError as exc:  # (the rotor named: its map asked alone)
                    for j in idx:
                        try:
                            m.wrench(v_hub[:, j, :], self._axes[j], om[:, j], self._spins[j], out_of_grid=out_of_grid)
                        except ValueError as one:
                            raise self._rotor_error(int(j) + 1, one) from None
                    raise exc
                force += res.force.sum(axis=1)
                moment += (cross3(self._pos[idx][None, :, :], res.force) + res.torque).sum(axis=1)
                flagged |= np.asarray(res.loads.flagged).any(axis=1)
            if np.any(self._h):
                moment -= cross3(w, om @ self._h)  # gyroscopic: -w x sum_i s_i J_i Omega_i a_i
        if self._body is not None:
            force += body_drag_force(self._body, air_v, np.zeros((N, 3)), self._rho)
        return VehicleMapWrench(force=force, moment=moment, flagged=flagged)
