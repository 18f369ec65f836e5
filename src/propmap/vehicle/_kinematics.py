"""A multirotor's rigid-body kinematics and moment sums, compiled (numba): the hub velocities
V_i = v - wind + w x r_i before the rotors are solved and the hub moments r_i x F_i + M_i -
w x (Omega_i h_i) - (dOmega_i/dt) h_i after (:func:`propmap.vehicle.vehicle_wrench`; the
vehicle's model in docs/flight.md). They were NumPy expressions on (N, n_rotors, 3) arrays,
some 20 calls that cost a one-sample simulator step about as much as solving one of its rotors.
:func:`hub_velocities` serves every other place that needs the hubs' velocities (the flight and
level-flight fits, the flight scores, ``propmap flight``'s coverage, VehicleMap's batches).

Compiled without fastmath, in NumPy's order of operations: the same numbers to the bit as the
expressions they replace (tests/test_vehicle_kinematics.py).
"""

from __future__ import annotations

import numba
import numpy as np

from ..core import _jitcache  # noqa: F401 (a writable cache folder for numba before the functions below are cached)
from ..core.geometry import has_bool, refuse_masked

#: IEEE arithmetic as NumPy's elementwise operations (no contraction into fused multiply-adds)
_FLAGS = dict(cache=True, error_model="numpy")


def hub_velocities(velocity, angular_velocity, arms, wind=None) -> np.ndarray:
    """Each rotor hub's velocity relative to the air, V_i = v - wind + w x r_i (rigid-body kinematics).

    Parameters
    ----------
    velocity, angular_velocity : array_like, shape (N, 3) or (3,)
        The centre of mass' velocity [m/s] and the body's angular velocity w [rad/s], body
        axes; one row (or a vector) stands for every sample.
    arms : array_like, shape (n_rotors, 3)
        The hubs from the centre of mass, r_i [m] (:func:`propmap.vehicle.rotor_geometry`).
    wind : array_like, shape (N, 3) or (3,), optional
        The wind [m/s], body axes; default none.

    Returns
    -------
    ndarray, shape (N, n_rotors, 3)
        V_i [m/s], computed as NumPy's ``(v - wind)[:, None] + np.cross(w[:, None], r)`` to the bit.

    Raises
    ------
    ValueError
        An input that is not finite numbers (a bool, a string, a masked entry, NaN) or not of
        those shapes, or sample counts other than N and 1, naming the inputs.

    Notes
    -----
    The velocity of a point of a rigid body, r_i from its centre of mass: the vehicle model of
    docs/flight.md (each rotor solved at its hub's V_i, as :func:`propmap.vehicle.vehicle_wrench`),
    whose steady, level case is the hub velocity of Gill & D'Andrea's level-flight fit (2017,
    Section III).
    """
    v, w, r = _samples("velocity", velocity, 3), _samples("angular_velocity", angular_velocity, 3), \
        _samples("arms", arms, 3)
    wind_a = np.zeros((1, 3)) if wind is None else _samples("wind", wind, 3)
    counts = {v.shape[0], w.shape[0], wind_a.shape[0]} - {1}
    if len(counts) > 1:
        raise ValueError(f"velocity, angular_velocity and wind must have the same number of samples (or one), got "
                         f"{v.shape[0]}, {w.shape[0]} and {wind_a.shape[0]}")
    out = np.empty((counts.pop() if counts else 1, r.shape[0], 3))
    hub_velocity_loop(v, wind_a, w, r, out)
    return out


def _samples(name: str, value, n_cols: int) -> np.ndarray:
    """``value`` as a new C-contiguous float array of shape (N, n_cols), a single row promoted to
    N = 1 (the compiled loops' one type): vehicle_wrench's, VehicleMap's and :func:`hub_velocities`'
    inputs. Numbers only (not bools, not masked), finite; ValueError naming ``name`` otherwise."""
    refuse_masked(name, value)
    try:
        a = np.asarray(value)
    except (ValueError, OverflowError):  # ragged nesting, ints beyond int64 (NumPy's message named no argument)
        raise ValueError(f"{name} must be a rectangular array of numbers of shape (N, {n_cols}) or ({n_cols},), "
                         f"got {value!r:.60}") from None
    if a.dtype.kind not in "iuf" or has_bool(value):
        raise ValueError(f"{name} must be numbers of shape (N, {n_cols}) or ({n_cols},), got {value!r:.60}")
    a = a.astype(float, order="C")  # (a copy, C-ordered)
    if a.ndim == 1:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != n_cols:
        raise ValueError(f"{name} must have shape (N, {n_cols}) or ({n_cols},), got {np.shape(value)}")
    if not np.isfinite(a).all():  # (the method: np.all's dispatch cost more than the test on one sample)
        raise ValueError(f"{name} must be finite")
    return a


@numba.njit(**_FLAGS)
def hub_velocity_loop(v, wind, w, arms, out):
    """Each hub's velocity relative to the air, V[n, i] = (v[n] - wind[n]) + w[n] x r_i.

    Parameters
    ----------
    v, wind, w : ndarray, shape (1, 3) or (N, 3)
        The centre of mass' velocity [m/s], the wind [m/s] and the body's angular velocity
        [rad/s], body axes; one row is every sample's.
    arms : ndarray, shape (n_rotors, 3)
        r_i, the hubs from the centre of mass [m].
    out : ndarray, shape (N, n_rotors, 3)
        Receives V.
    """
    for n in range(out.shape[0]):
        j = 0 if v.shape[0] == 1 else n
        k = 0 if wind.shape[0] == 1 else n
        m = 0 if w.shape[0] == 1 else n
        ux = v[j, 0] - wind[k, 0]
        uy = v[j, 1] - wind[k, 1]
        uz = v[j, 2] - wind[k, 2]
        wx, wy, wz = w[m, 0], w[m, 1], w[m, 2]
        for i in range(arms.shape[0]):
            px, py, pz = arms[i, 0], arms[i, 1], arms[i, 2]
            out[n, i, 0] = ux + (wy * pz - wz * py)
            out[n, i, 1] = uy + (wz * px - wx * pz)
            out[n, i, 2] = uz + (wx * py - wy * px)


@numba.njit(**_FLAGS)
def hub_moments(arms, force, moment, w, omega, h, acc):
    """The rotors' moments about the centre of mass, in place: moment[n, i] += r_i x F[n, i] and,
    where a rotor's inertia is known (any h_i non-zero), -= w[n] x (Omega[n, i] h_i) and -=
    (dOmega/dt)[n, i] h_i.

    Parameters
    ----------
    arms : ndarray, shape (n_rotors, 3)
        r_i [m].
    force, moment : ndarray, shape (N, n_rotors, 3)
        Each rotor's force [N] and its moment about its hub [N m]; ``moment`` is updated.
    w : ndarray, shape (1, 3) or (N, 3)
        Angular velocity [rad/s].
    omega : ndarray, shape (1, n_rotors) or (N, n_rotors)
        Omega_i [rad/s]; one row is every sample's.
    h : ndarray, shape (n_rotors, 3)
        s_i J_i a_i [kg m^2] (0 for a rotor of unknown inertia). Where every h_i is 0 the
        gyroscopic and spin-up terms are not added, as the expressions this replaced skipped them
        (a subtraction of a signed zero can change a zero moment's sign).
    acc : ndarray, shape (1, n_rotors), (N, n_rotors) or (0, n_rotors)
        dOmega_i/dt [rad/s^2]; one row is every sample's; no rows: none given, and the spin-up
        term not added (for the same reason).
    """
    gyro = False
    for i in range(h.shape[0]):
        gyro = gyro or h[i, 0] != 0.0 or h[i, 1] != 0.0 or h[i, 2] != 0.0
    for n in range(force.shape[0]):
        k = 0 if acc.shape[0] == 1 else n
        j = 0 if omega.shape[0] == 1 else n
        m = 0 if w.shape[0] == 1 else n
        wx, wy, wz = w[m, 0], w[m, 1], w[m, 2]
        for i in range(arms.shape[0]):
            px, py, pz = arms[i, 0], arms[i, 1], arms[i, 2]
            fx, fy, fz = force[n, i, 0], force[n, i, 1], force[n, i, 2]
            mx = moment[n, i, 0] + (py * fz - pz * fy)
            my = moment[n, i, 1] + (pz * fx - px * fz)
            mz = moment[n, i, 2] + (px * fy - py * fx)
            if gyro:
                om = omega[j, i]
                hx = om * h[i, 0]
                hy = om * h[i, 1]
                hz = om * h[i, 2]
                mx -= wy * hz - wz * hy
                my -= wz * hx - wx * hz
                mz -= wx * hy - wy * hx
                if acc.shape[0] > 0:
                    a = acc[k, i]
                    mx -= a * h[i, 0]
                    my -= a * h[i, 1]
                    mz -= a * h[i, 2]
            moment[n, i, 0] = mx
            moment[n, i, 1] = my
            moment[n, i, 2] = mz
