"""Compiled (numba) interpolation in a rotor map (maps.RotorMap): multilinear or cubic.

The table holds, on a rectilinear grid (Omega, V, beta), the loads divided by the square of
a reference speed, (Omega R)^2 + V^2: T, D, Q, M_R scale as Omega^2 in hover and as V^2 at
high advance ratio, so the quotient varies slowly and linear interpolation is far more
accurate than on the loads themselves (measured: docs/simulators.md); the result is
multiplied back by the query's (Omega R)^2 + V^2. Each query is located by bisection on
each axis (the axes need not be uniform) and interpolated from the 8 corners of its cell
(``order`` 1, multilinear) or from the 4 x 4 x 4 nodes around it (``order`` 3, cubic).

The cubic interpolation is the tensor product of 1-D cubic Hermite interpolation whose
node slopes are those of the parabola through the node and its two neighbours (the
three-point derivative on a non-uniform axis; one-sided at the ends). Each 1-D step is a
fixed linear combination of 4 nodes, so the 3-D result is a weighted sum of 64 nodes; it
is continuous with a continuous first derivative along each axis, equals the table at the
nodes and reproduces any polynomial of degree 2 in each axis exactly. This is the
"Catmull-Rom" spline of computer graphics (Catmull & Rom 1974) written for non-uniform
spacing (Bessel's slopes, de Boor, A Practical Guide to Splines, 2001, ch. IV). An axis
of 2 nodes is interpolated linearly.

Out-of-grid policy (``policy``): CLIP (0) moves the query onto the grid's boundary, except
that a rotation rate below the grid's lowest, 0 <= Omega < Omega_min (spin-up, a stopped
rotor), takes the lowest row's loads scaled by (Omega / Omega_min)^2: the loads of a
constant-coefficient rotor, zero at Omega = 0 (a parked rotor's blade drag is not
modelled); NAN (1) returns NaN; both set ``inside[i] = False``. The raising policy, and the
refusal of Omega < 0, are applied by the caller before this kernel runs.
"""

from __future__ import annotations

import numba
import numpy as np

from . import _jitcache  # noqa: F401 (a writable cache folder for numba before the kernels below are cached)
from ._frame import FLAGS as _FLAGS
from ._frame import point_frame, point_vectors

CLIP = 0
NAN = 1

# the helpers below are compiled once each and inlined by LLVM (forceinline), not copied into each caller's numba IR
# (inline="always"): the three kernels' first compile 29 -> 8 s, a scalar lookup 3.91 against 3.97 us at best of six
# processes (2026-11-28, 2-core AMD EPYC; benchmarks/README.md, "Compile time")


@numba.njit(forceinline=True, **_FLAGS)
def _locate(ax, x):
    """(cell index, fraction in [0, 1]) of x in the increasing axis ax (x within its range)."""
    n = ax.shape[0]
    lo = 0
    hi = n - 1
    while hi - lo > 1:
        mid = (lo + hi) >> 1
        if ax[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo, (x - ax[lo]) / (ax[lo + 1] - ax[lo])


@numba.njit(forceinline=True, **_FLAGS)
def _cubic_weights(ax, x):
    """(cell index i, weights of the nodes i-1, i, i+1, i+2) of the cubic at x in axis ax.

    A weight whose node lies outside the axis (i-1 < 0 or i+2 > n-1) is exactly 0; the
    caller clamps that node's index into the axis.
    """
    n = ax.shape[0]
    i, t = _locate(ax, x)
    if n == 2:
        return i, 0.0, 1.0 - t, t, 0.0
    h = ax[i + 1] - ax[i]
    t2 = t * t
    t3 = t2 * t
    h00 = 2.0 * t3 - 3.0 * t2 + 1.0
    h01 = 3.0 * t2 - 2.0 * t3
    h10 = h * (t3 - 2.0 * t2 + t)
    h11 = h * (t3 - t2)
    # slope at node i as weights (a0..a3) on the nodes i-1..i+2
    if i == 0:
        g0 = ax[1] - ax[0]
        g1 = ax[2] - ax[1]
        c = g0 / (g0 + g1)
        a0, a1, a2, a3 = 0.0, -(1.0 + c) / g0, (1.0 + c) / g0 + c / g1, -c / g1
    else:
        gm = ax[i] - ax[i - 1]
        s = gm + h
        a0, a1, a2, a3 = -h / (gm * s), (h / gm - gm / h) / s, gm / (h * s), 0.0
    # slope at node i + 1
    if i + 1 == n - 1:
        gm = ax[i] - ax[i - 1]
        c = h / (gm + h)
        b0, b1, b2, b3 = c / gm, -(1.0 + c) / h - c / gm, (1.0 + c) / h, 0.0
    else:
        gp = ax[i + 2] - ax[i + 1]
        s = h + gp
        b0, b1, b2, b3 = 0.0, -gp / (h * s), (gp / h - h / gp) / s, h / (gp * s)
    return (i, h10 * a0 + h11 * b0, h00 + h10 * a1 + h11 * b1, h01 + h10 * a2 + h11 * b2,
            h10 * a3 + h11 * b3)


class OutOfGridError(ValueError):
    """A map query outside the grid under ``out_of_grid="raise"`` (RotorMap.loads and wrench,
    VehicleMap.wrench): its ``quantity`` ("omega", "airspeed" or "incidence") and ``detail`` (the
    value and the grid's range), so that a caller that derived the quantity from its own
    arguments can say it in their terms (RotorMap.wrench: the velocity and axis; VehicleMap:
    the rotor and its velocity, angular_velocity and wind) without reading the message."""

    def __init__(self, quantity: str, detail: str, given: str = "") -> None:
        super().__init__(f"{given}{detail}")
        self.quantity, self.detail = quantity, detail


#: an airspeed up to this [m/s] is still air for a map whose airspeed axis starts at 0: any incidence is on its
#: incidence axis (the loads at 1e-6 m/s differ from hover's by far less than the interpolation's error)
HOVER_SPEED = 1e-6


@numba.njit(forceinline=True, **_FLAGS)
def hover_incidence(ax1, ax2, q1, q2):
    """The incidence at an airspeed q1 up to HOVER_SPEED on a grid whose airspeed axis starts at
    0: any incidence names the same still air, so it is taken into the incidence axis [ax2[0],
    ax2[-1]] (a map of descent only, 90-180 deg, refused the hover of every simulator: a
    user-level audit). A NaN stays NaN (refused or flagged by the caller)."""
    if q1 <= HOVER_SPEED and ax1[0] == 0.0 and q2 == q2:
        return min(max(q2, ax2[0]), ax2[-1])
    return q2


@numba.njit(forceinline=True, **_FLAGS)
def _one(ax0, ax1, ax2, table, cellflag, radius, q0, q1, q2, policy, order, out, i, inside, flagged):
    nvar = table.shape[3]
    q2 = hover_incidence(ax1, ax2, q1, q2)
    ok = ax0[0] <= q0 <= ax0[-1] and ax1[0] <= q1 <= ax1[-1] and ax2[0] <= q2 <= ax2[-1]
    inside[i] = ok
    fade = 1.0
    if not ok:
        if policy == NAN:
            for k in range(nvar):
                out[i, k] = np.nan
            flagged[i] = True
            return
        if q0 < ax0[0]:  # spin-up below the grid (0 <= q0, the caller's check): the lowest row's loads x (q0/min)^2
            fade = (q0 / ax0[0]) * (q0 / ax0[0])
        q0 = min(max(q0, ax0[0]), ax0[-1])
        q1 = min(max(q1, ax1[0]), ax1[-1])
        q2 = min(max(q2, ax2[0]), ax2[-1])
    s = (q0 * q0 * radius * radius + q1 * q1) * fade
    if order == 3:
        i0, u0, u1, u2, u3 = _cubic_weights(ax0, q0)
        i1, v0, v1, v2, v3 = _cubic_weights(ax1, q1)
        i2, w0, w1, w2, w3 = _cubic_weights(ax2, q2)
        flagged[i] = (not ok) or cellflag[i0, i1, i2] != 0
        # nodes outside the axis have weight 0: clamp their index (no branch in the sum)
        n0 = ax0.shape[0] - 1
        n1 = ax1.shape[0] - 1
        n2 = ax2.shape[0] - 1
        ja = (max(i0 - 1, 0), i0, i0 + 1, min(i0 + 2, n0))
        jb = (max(i1 - 1, 0), i1, i1 + 1, min(i1 + 2, n1))
        jc = (max(i2 - 1, 0), i2, i2 + 1, min(i2 + 2, n2))
        wa = (u0, u1, u2, u3)
        wb = (v0, v1, v2, v3)
        wc = (w0, w1, w2, w3)
        # the table holds 4 variables (T, D, Q, M_R), summed together
        r0 = 0.0
        r1 = 0.0
        r2 = 0.0
        r3 = 0.0
        for a in range(4):
            for b in range(4):
                wab = wa[a] * wb[b]
                t = table[ja[a], jb[b]]
                for c in range(4):
                    w = wab * wc[c]
                    row = t[jc[c]]
                    r0 += w * row[0]
                    r1 += w * row[1]
                    r2 += w * row[2]
                    r3 += w * row[3]
        out[i, 0] = r0 * s
        out[i, 1] = r1 * s
        out[i, 2] = r2 * s
        out[i, 3] = r3 * s
        return
    i0, f0 = _locate(ax0, q0)
    i1, f1 = _locate(ax1, q1)
    i2, f2 = _locate(ax2, q2)
    flagged[i] = (not ok) or cellflag[i0, i1, i2] != 0
    g0 = 1.0 - f0
    g1 = 1.0 - f1
    g2 = 1.0 - f2
    w000 = g0 * g1 * g2
    w001 = g0 * g1 * f2
    w010 = g0 * f1 * g2
    w011 = g0 * f1 * f2
    w100 = f0 * g1 * g2
    w101 = f0 * g1 * f2
    w110 = f0 * f1 * g2
    w111 = f0 * f1 * f2
    for k in range(nvar):
        v = (w000 * table[i0, i1, i2, k] + w001 * table[i0, i1, i2 + 1, k]
             + w010 * table[i0, i1 + 1, i2, k] + w011 * table[i0, i1 + 1, i2 + 1, k]
             + w100 * table[i0 + 1, i1, i2, k] + w101 * table[i0 + 1, i1, i2 + 1, k]
             + w110 * table[i0 + 1, i1 + 1, i2, k] + w111 * table[i0 + 1, i1 + 1, i2 + 1, k])
        out[i, k] = v * s


@numba.njit(**_FLAGS)
def interp_batch(ax0, ax1, ax2, table, cellflag, radius, q0, q1, q2, policy, order, out, inside, flagged):
    """Interpolate every query (q0[i], q1[i], q2[i]); shapes (n,) in, (n, nvar) out.

    ``order`` 1: multilinear, 3: cubic; ``cellflag`` must be the one for that order.
    """
    for i in range(q0.shape[0]):
        _one(ax0, ax1, ax2, table, cellflag, radius, q0[i], q1[i], q2[i], policy, order, out, i, inside, flagged)


#: a map's scalar paths pass its settings and its three axes as one float array ``grid`` =
#: (R [m], order, policy, strict, n_Omega, n_V, then the Omega, V and beta axes): one argument
#: instead of eight, which numba's dispatcher types and unboxes one by one (19 arguments took
#: 1.9-2.6 us of a 6 us ``RotorMap.wrench`` call; 2026-11-28, Intel Xeon, docs/simulators.md)
GRID_HEAD = 6


@numba.njit(forceinline=True, **_FLAGS)
def _unpack(grid):
    """(ax0, ax1, ax2, R, order, policy, strict) from a packed ``grid`` (views, no copy)."""
    n0 = int(grid[4])
    n1 = int(grid[5])
    a = GRID_HEAD + n0
    b = a + n1
    return grid[GRID_HEAD:a], grid[a:b], grid[b:], grid[0], int(grid[1]), int(grid[2]), grid[3] != 0.0


@numba.njit(**_FLAGS)
def interp_point(grid, tables, cellflag, q0, q1, q2, res):
    """One query (scalars q0, q1, q2) as the fields of maps.MapLoads, in its order.

    ``grid``: as :data:`GRID_HEAD` says; ``tables``, shape (1 or 2, n0, n1, n2, 4): the
    loads' table and the side table (Y, M_P, 0, 0) where the map holds one; ``res``, shape
    (4, >= 4), scratch (:func:`_lookup`'s layout).

    Returns
    -------
    tuple
        :func:`_fields`: (T, D, Q, M_R, Omega, inside, flagged, Y, M_P), floats and two bools
        (returned, not read back from ``res`` by the caller: 1-2 us of a 3-5 us call, 2026-11-29).
    """
    ax0, ax1, ax2, radius, order, policy, _ = _unpack(grid)
    _lookup(ax0, ax1, ax2, tables, cellflag, radius, q0, q1, q2, policy, order, res)
    return _fields(tables, res, q0, ax0[-1], policy)


@numba.njit(forceinline=True, **_FLAGS)
def _fields(tables, res, omega, omega_max, policy):
    """maps.MapLoads' fields from :func:`_lookup`'s ``res``: (T, D, Q, M_R, Omega, inside, flagged,
    Y, M_P), Y = M_P = 0 without a side table. Omega is the query's, held at the grid's top
    ``omega_max`` under "clip" (where the loads hold at the top row: below the grid they are
    scaled to the query's rate); under the other policies a query above the grid is NaN or
    refused, so the rate is the query's."""
    Y = 0.0
    P = 0.0
    if tables.shape[0] > 1:
        Y = res[1, 0]
        P = res[1, 1]
    om = min(omega, omega_max) if policy == CLIP else omega
    return res[0, 0], res[0, 1], res[0, 2], res[0, 3], om, res[2, 0] != 0.0, res[3, 0] != 0.0, Y, P


@numba.njit(forceinline=True, **_FLAGS)
def _lookup(ax0, ax1, ax2, tables, cellflag, radius, q0, q1, q2, policy, order, res):
    """One query into ``res`` from both tables (:func:`interp_point`'s layout)."""
    _one(ax0, ax1, ax2, tables[0], cellflag, radius, q0, q1, q2, policy, order, res, 0, res[2], res[3])
    if tables.shape[0] > 1:  # the same query in the side table (the same inside and flagged)
        _one(ax0, ax1, ax2, tables[1], cellflag, radius, q0, q1, q2, policy, order, res, 1, res[2], res[3])


#: an incidence within this of an end of the grid's axis (or of [0, pi]) [rad] is taken on it:
#: single precision's nearest value to pi lies 8.7e-8 rad above pi (np.float32(np.pi),
#: np.deg2rad(np.float32(180)); refused or flagged outside until 2026-11-27: a physics audit and
#: a review), and an incidence from vectors lands a few ulp either side of pi/2 (0, pi)
#: depending on the arithmetic; neither may decide between "inside" and "outside"
#: (rotor_loads, RotorMap's paths, build_map's axis, LoadData, the C header). One float32
#: spacing at pi.
INCIDENCE_SNAP = 2.5e-7


#: an airspeed within this fraction of an end of the grid's airspeed axis is on it: a hub's speed |V|
#: from its velocity rounds by an ulp or two (and, until core/_frame.py served both, differently on the
#: one-point paths, the root of the squares, and the array path, the largest component times the scaled
#: vector's norm), and that may not decide between "inside" and "outside" (a mutation audit, 2026-11-28:
#: of 2,000 velocities of |V| = 12 m/s, 511 were outside a 0-12 m/s map on the one-point path and 449
#: on the array path, NaN loads under "nan" on one and finite on the other); the C header's loads take
#: the same rule
AIRSPEED_SNAP = 1e-12


def snap_ends(a, lo: float, hi: float, below: float, above: float):
    """The float array ``a`` with values in [lo - below, lo) moved onto ``lo`` and in (hi, hi +
    above] onto ``hi`` (a new array where any moves: the caller's is never written; NaN kept).

    Parameters
    ----------
    a : ndarray of float
        Any shape.
    lo, hi : float
        An axis' ends.
    below, above : float
        How far beyond each end a value is on it (>= 0).

    Returns
    -------
    ndarray
        Shape of ``a``; ``a`` itself where nothing moves.
    """
    with np.errstate(invalid="ignore"):  # (NaN compares False)
        high = (a > hi) & (a <= hi + above)
        low = (a < lo) & (a >= lo - below)
    if not (high.any() or low.any()):
        return a
    return np.where(high, hi, np.where(low, lo, a))


def snap_ends_scalar(x: float, lo: float, hi: float, below: float, above: float) -> float:
    """:func:`snap_ends` for one float (the one-point paths: no arrays built; compiled for the
    kernels as :func:`snap_edge` and :func:`snap_speed`)."""
    if hi < x <= hi + above:
        return hi
    if lo - below <= x < lo:
        return lo
    return x


def snap_incidence(a, lo=0.0, hi=np.pi):
    """Incidences [rad] within INCIDENCE_SNAP beyond [lo, hi] (0 and pi, or a map's axis) on the
    end: :func:`snap_ends` (a new array where any moves; ``a`` itself where none does)."""
    return snap_ends(a, lo, hi, INCIDENCE_SNAP, INCIDENCE_SNAP)


def snap_incidence_scalar(x: float, lo: float = 0.0, hi: float = np.pi) -> float:
    """:func:`snap_incidence` for one float [rad]."""
    return snap_ends_scalar(x, lo, hi, INCIDENCE_SNAP, INCIDENCE_SNAP)


def snap_airspeed(a, lo: float, hi: float):
    """Airspeeds [m/s] within AIRSPEED_SNAP (relative) beyond a map's airspeed axis [lo, hi] on
    the end: :func:`snap_ends` (a new array where any moves; ``a`` itself where none does)."""
    return snap_ends(a, lo, hi, lo * AIRSPEED_SNAP, hi * AIRSPEED_SNAP)


def snap_airspeed_scalar(x: float, lo: float, hi: float) -> float:
    """:func:`snap_airspeed` for one float [m/s]."""
    return snap_ends_scalar(x, lo, hi, lo * AIRSPEED_SNAP, hi * AIRSPEED_SNAP)


_snap_ends_compiled = numba.njit(forceinline=True, **_FLAGS)(snap_ends_scalar)


@numba.njit(forceinline=True, **_FLAGS)
def snap_edge(x, lo, hi):
    """:func:`snap_incidence_scalar`, compiled for the kernels (one rule, one body)."""
    return _snap_ends_compiled(x, lo, hi, INCIDENCE_SNAP, INCIDENCE_SNAP)


@numba.njit(forceinline=True, **_FLAGS)
def snap_speed(x, lo, hi):
    """:func:`snap_airspeed_scalar`, compiled for the kernels."""
    return _snap_ends_compiled(x, lo, hi, lo * AIRSPEED_SNAP, hi * AIRSPEED_SNAP)


@numba.njit(forceinline=True, **_FLAGS)
def _rotor(ax0, ax1, ax2, tables, cellflag, radius, order, policy, strict, vx, vy, vz, a0, a1, a2, omega, spin, res):
    """One rotor's (status, Fx, Fy, Fz, Mx, My, Mz) at hub velocity (vx, vy, vz), axis (a0, a1, a2),
    rate ``omega`` and ``spin``: :func:`wrench_point`'s arithmetic (status and ``res`` as there)."""
    if not (np.isfinite(vx) and np.isfinite(vy) and np.isfinite(vz) and np.isfinite(a0) and np.isfinite(a1)
            and np.isfinite(a2)):  # (one by one: numba's max drops a NaN that is not its first argument; a review)
        return 1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    amax = max(abs(a0), abs(a1), abs(a2))
    vmax = max(abs(vx), abs(vy), abs(vz))
    if not (amax > 0.0 and vmax < 1e150 and omega >= 0.0):  # (a NaN rate fails the comparison)
        return 1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    zx, zy, zz, speed, axial, beta = point_frame(vx, vy, vz, a0, a1, a2)
    q1 = snap_speed(speed, ax1[0], ax1[-1])  # (the lookup's airspeed; the vectors take |V| as computed)
    beta = hover_incidence(ax1, ax2, q1, snap_edge(beta, ax2[0], ax2[-1]))
    if strict and not (ax0[0] <= omega <= ax0[-1] and ax1[0] <= q1 <= ax1[-1] and ax2[0] <= beta <= ax2[-1]):
        return 2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    _lookup(ax0, ax1, ax2, tables, cellflag, radius, omega, q1, beta, policy, order, res)
    Y = 0.0
    P = 0.0
    if tables.shape[0] > 1:
        Y = res[1, 0]
        P = res[1, 1]
    fx, fy, fz, mx, my, mz = point_vectors(vx, vy, vz, zx, zy, zz, speed, axial, res[0, 0], res[0, 1], res[0, 2],
                                           res[0, 3], Y, P, spin)
    return 0, fx, fy, fz, mx, my, mz


@numba.njit(**_FLAGS)
def wrench_point(grid, tables, cellflag, velocity, axis, omega, spin, res, vectors):
    """One rotor's force and moment vectors from the map (maps.RotorMap.wrench's scalar path).

    The disk frame and the vectors as core.vector.disk_frame and wrench_vectors
    (:func:`point_frame`, :func:`point_vectors`, which core.vector's one-point path calls too).
    ``grid``, ``tables``, ``cellflag`` and ``res`` as :func:`interp_point`'s (``grid``'s
    ``strict`` for the raising policy); ``vectors``, shape (2, 3), receives the force and the
    moment.

    Returns
    -------
    status : int
        0: done; 1: a zero or non-finite axis, a velocity that is not finite or beyond
        1e150 m/s, or Omega < 0; 2: outside the grid with ``strict`` (the raising policy). On 1 and 2
        ``vectors`` is not written: the caller's general path answers and raises what it raises.
    fields : tuple
        The loads as :func:`interp_point` returns them (zeros unless ``status`` is 0).
    """
    ax0, ax1, ax2, radius, order, policy, strict = _unpack(grid)
    status, fx, fy, fz, mx, my, mz = _rotor(ax0, ax1, ax2, tables, cellflag, radius, order, policy, strict,
                                            velocity[0], velocity[1], velocity[2], axis[0], axis[1], axis[2], omega,
                                            spin, res)
    if status:
        return status, (0.0, 0.0, 0.0, 0.0, 0.0, False, False, 0.0, 0.0)
    vectors[0, 0] = fx
    vectors[0, 1] = fy
    vectors[0, 2] = fz
    vectors[1, 0] = mx
    vectors[1, 1] = my
    vectors[1, 2] = mz
    return 0, _fields(tables, res, omega, ax0[-1], policy)


#: a vehicle's rotors for :func:`vehicle_point`, one row each: the arm r_i [m] (3), the unit axis a_i (3), the
#: spin s_i, and h_i = s_i J_i a_i [kg m^2] (3)
ROTOR_COLUMNS = 10


@numba.njit(**_FLAGS)
def vehicle_point(grid, tables, cellflag, rotors, reach, air_velocity, angular_velocity, omega, res, out):
    """One step of a vehicle whose rotors share one map (vehicle.mapped.VehicleMap.wrench's one-step path).

    Rotor i sees V_i = v_air + w x r_i (:func:`_rotor`); F = sum_i F_i and M = sum_i (r_i x F_i +
    M_i) - w x sum_i h_i Omega_i, summed in the rotors' order as VehicleMap's Python sums.
    ``grid``, ``tables``, ``cellflag``, ``res`` as :func:`wrench_point`'s; ``rotors``, shape
    (n, :data:`ROTOR_COLUMNS`); ``reach`` the longest arm [m]; ``air_velocity`` (3,) the centre
    of mass' velocity relative to the air, ``angular_velocity`` (3,) [rad/s], ``omega`` (n,)
    [rad/s]; ``out``, shape (2, 1, 3), receives F and M; res[3, 1] 1.0 where a rotor's query
    is flagged (else 0.0).

    Returns
    -------
    int
        0: done; 1: a non-finite input, a hub velocity bound max|v_air| + max|w| reach of
        1e150 m/s or more, or an Omega_i < 0; 2: a rotor outside the grid with ``strict``. On 1
        and 2 ``out`` is not written: the caller's general path answers and raises what it raises.
    """
    ax0, ax1, ax2, radius, order, policy, strict = _unpack(grid)
    vx = air_velocity[0]
    vy = air_velocity[1]
    vz = air_velocity[2]
    wx = angular_velocity[0]
    wy = angular_velocity[1]
    wz = angular_velocity[2]
    if not (np.isfinite(vx) and np.isfinite(vy) and np.isfinite(vz) and np.isfinite(wx) and np.isfinite(wy)
            and np.isfinite(wz)):  # (one by one: numba's max drops a NaN that is not its first argument)
        return 1
    if not max(abs(vx), abs(vy), abs(vz)) + max(abs(wx), abs(wy), abs(wz)) * reach < 1e150:
        return 1
    F0 = 0.0
    F1 = 0.0
    F2 = 0.0
    M0 = 0.0
    M1 = 0.0
    M2 = 0.0
    h0 = 0.0
    h1 = 0.0
    h2 = 0.0
    flagged = False
    for i in range(rotors.shape[0]):
        px = rotors[i, 0]
        py = rotors[i, 1]
        pz = rotors[i, 2]
        om = omega[i]
        status, fx, fy, fz, mx, my, mz = _rotor(ax0, ax1, ax2, tables, cellflag, radius, order, policy, strict,
                                                vx + wy * pz - wz * py, vy + wz * px - wx * pz, vz + wx * py - wy * px,
                                                rotors[i, 3], rotors[i, 4], rotors[i, 5], om, rotors[i, 6], res)
        if status:
            return status
        F0 += fx
        F1 += fy
        F2 += fz
        M0 += py * fz - pz * fy + mx
        M1 += pz * fx - px * fz + my
        M2 += px * fy - py * fx + mz
        flagged = flagged or res[3, 0] != 0.0
        h0 += rotors[i, 7] * om
        h1 += rotors[i, 8] * om
        h2 += rotors[i, 9] * om
    out[0, 0, 0] = F0
    out[0, 0, 1] = F1
    out[0, 0, 2] = F2
    out[1, 0, 0] = M0 - (wy * h2 - wz * h1)  # gyroscopic: -w x h
    out[1, 0, 1] = M1 - (wz * h0 - wx * h2)
    out[1, 0, 2] = M2 - (wx * h1 - wy * h0)
    res[3, 1] = 1.0 if flagged else 0.0
    return 0
