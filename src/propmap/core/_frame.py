"""The disk frame of a rotor and its load vectors, compiled (numba): one point's arithmetic
(:func:`point_frame`, :func:`point_vectors`), which the maps' one-point kernels (core/_interp.py)
and core/vector.py's one-point path inline, and its loops over a batch (:func:`frames`,
:func:`vectors`), which :func:`propmap.core.vector.disk_frame` and
:func:`~propmap.core.vector.wrench_vectors` run.

The frame of a velocity V and an axis a: the unit axis z = a / |a|, the speed |V|, the axial
speed V . z and the incidence beta = atan2(|V - (V . z) z|, V . z) (docs/conventions.md); the
vectors: force T z - D e_ip - spin Y (z x e_ip), moment -spin (Q z + M_R e_ip) - M_P (z x e_ip),
e_ip the unit in-plane velocity (Gill & D'Andrea 2017, Section II, in the frame of
docs/conventions.md).
"""

from __future__ import annotations

import numba
import numpy as np

from . import _jitcache  # noqa: F401 (a writable cache folder for numba before the kernels below are cached)

#: the compile options of the frame's functions and of the maps' kernels (core/_interp.py), which inline them
FLAGS = dict(cache=True, error_model="numpy", fastmath={"nsz", "arcp", "contract", "afn", "reassoc"})
#: a speed from this up is scaled by 1 / POW2 first (exact), so that its squares do not overflow (core.vector's
#: velocities reach VELOCITY_MAX = 1e150 m/s; a speed beyond AIRSPEED_MAX is refused after the frame, by its value)
HUGE = 1e100

#: below this, a frame's vector is scaled by POW2 first (exact): its squares would lose digits
#: or underflow, and 1 / its largest component overflow under fastmath's reciprocal ("arcp")
TINY = 1e-150
POW2 = 2.0 ** 600


@numba.njit(forceinline=True, **FLAGS)
def point_frame(vx, vy, vz, a0, a1, a2):
    """One point's disk frame (core.vector.disk_frame loops over it: :func:`frames`): the axis (a0,
    a1, a2), not zero and finite, scaled by its largest component and normalised to (zx, zy, zz);
    the speed |V|, the axial
    speed V . z and the incidence beta = arccos(V . z / |V|) (0 where V = 0), computed as
    atan2(|V - (V . z) z|, V . z), which keeps its digits near axial flow (the arccos of a cosine
    rounded to 1 - 1e-16 is 1.5e-8 rad: a simulator-developer audit, 2026-11-27). A vector below
    TINY is scaled by the power of two POW2 first, so that neither a velocity of 1e-200 m/s
    (its squares 0) nor an axis of 1e-320 (1 / 1e-320 overflows) is lost (a physics audit and a
    simulator-developer audit, 2026-11-27: the speed 0, and NaN loads under "clip").
    Returns (zx, zy, zz, speed, axial, beta)."""
    amax = max(abs(a0), abs(a1), abs(a2))
    if amax < TINY:
        a0 *= POW2
        a1 *= POW2
        a2 *= POW2
        amax *= POW2
    a0 /= amax
    a1 /= amax
    a2 /= amax
    n = np.sqrt(a0 * a0 + a1 * a1 + a2 * a2)
    zx = a0 / n
    zy = a1 / n
    zz = a2 / n
    speed = np.sqrt(vx * vx + vy * vy + vz * vz)
    if speed < TINY:
        sx = vx * POW2
        sy = vy * POW2
        sz = vz * POW2
        ns = np.sqrt(sx * sx + sy * sy + sz * sz)
        cs = sx * zx + sy * zy + sz * zz
        speed = ns * (1.0 / POW2)
        axial = cs * (1.0 / POW2)
        return zx, zy, zz, speed, axial, incidence(sx, sy, sz, zx, zy, zz, cs)
    axial = vx * zx + vy * zy + vz * zz
    return zx, zy, zz, speed, axial, incidence(vx, vy, vz, zx, zy, zz, axial)


@numba.njit(forceinline=True, **FLAGS)
def incidence(vx, vy, vz, zx, zy, zz, axial):
    """beta = atan2(|V - axial z|, axial) for the velocity V, the unit axis z and axial = V . z
    (0 where V = 0; core.vector.disk_frame's arithmetic)."""
    ix = vx - axial * zx
    iy = vy - axial * zy
    iz = vz - axial * zz
    n_ip = np.sqrt(ix * ix + iy * iy + iz * iz)
    if n_ip == 0.0 and axial == 0.0:  # V = 0 (atan2(0, -0.0) would be pi)
        return 0.0
    return np.arctan2(n_ip, axial)


@numba.njit(forceinline=True, **FLAGS)
def point_vectors(vx, vy, vz, zx, zy, zz, speed, axial, T, D, Q, M, Y, P, spin):
    """One rotor's force and moment vectors from its loads (core.vector.wrench_vectors loops over
    it: :func:`vectors`): e_ip
    the in-plane unit velocity (0 where the in-plane speed is below 1e-12 of the speed), force
    T z - D e_ip - spin Y (z x e_ip), moment -spin (Q z + M_R e_ip) - M_P (z x e_ip), with
    (zx, zy, zz, speed, axial) from :func:`point_frame`; a velocity below TINY scaled by POW2
    first, as there (else e_ip's squares underflow: the drag dropped below 1e-162 m/s; a review,
    2026-11-27). Returns (Fx, Fy, Fz, Mx, My, Mz)."""
    if speed < TINY:  # (axial from the scaled V: a subnormal axial speed has lost its digits)
        vx *= POW2
        vy *= POW2
        vz *= POW2
        axial = vx * zx + vy * zy + vz * zz
        speed *= POW2
    ix = vx - axial * zx
    iy = vy - axial * zy
    iz = vz - axial * zz
    n_ip = np.sqrt(ix * ix + iy * iy + iz * iz)
    ex = 0.0
    ey = 0.0
    ez = 0.0
    if n_ip > 1e-12 * max(speed, 1e-300):
        ex = ix / n_ip
        ey = iy / n_ip
        ez = iz / n_ip
    lx = zy * ez - zz * ey  # z x e_ip
    ly = zz * ex - zx * ez
    lz = zx * ey - zy * ex
    return (T * zx - D * ex - spin * Y * lx, T * zy - D * ey - spin * Y * ly, T * zz - D * ez - spin * Y * lz,
            -spin * (Q * zx + M * ex) - P * lx, -spin * (Q * zy + M * ey) - P * ly, -spin * (Q * zz + M * ez) - P * lz)


@numba.njit(**FLAGS)
def frames(V, a, z, out):
    """The disk frames of M points (:func:`point_frame` each): ``V``, ``a`` (M, 3) C-contiguous
    velocities [m/s] and axes (finite, checked by the caller); ``z`` (M, 3) receives the unit
    axes, ``out`` (3, M) the speeds, the axial speeds and the incidences. A velocity from HUGE
    up is scaled by 1 / POW2 first and its speeds back (exact powers of two).

    Returns
    -------
    int
        -1 where every axis is non-zero, else the index of the first zero one (nothing written
        from it on).
    """
    for i in range(V.shape[0]):
        a0, a1, a2 = a[i, 0], a[i, 1], a[i, 2]
        if a0 == 0.0 and a1 == 0.0 and a2 == 0.0:
            return i
        vx, vy, vz = V[i, 0], V[i, 1], V[i, 2]
        big = max(abs(vx), abs(vy), abs(vz)) >= HUGE
        if big:
            vx *= 1.0 / POW2
            vy *= 1.0 / POW2
            vz *= 1.0 / POW2
        zx, zy, zz, speed, axial, beta = point_frame(vx, vy, vz, a0, a1, a2)
        if big:
            speed *= POW2
            axial *= POW2
        z[i, 0] = zx
        z[i, 1] = zy
        z[i, 2] = zz
        out[0, i] = speed
        out[1, i] = axial
        out[2, i] = beta
    return -1


@numba.njit(**FLAGS)
def vectors(V, z, loads, spin, out):
    """The force and moment vectors of M points (:func:`point_vectors` each): ``V``, ``z`` (M, 3)
    C-contiguous velocities [m/s] and unit axes; ``loads`` (6, M) the rows T, D,
    Q, M_R, Y, M_P; ``spin`` (M,) +1 or -1; ``out`` (2, M, 3) receives the forces and moments.
    A velocity from HUGE up is scaled by 1 / POW2 first (only its direction enters)."""
    for i in range(V.shape[0]):
        vx, vy, vz = V[i, 0], V[i, 1], V[i, 2]
        zx, zy, zz = z[i, 0], z[i, 1], z[i, 2]
        if max(abs(vx), abs(vy), abs(vz)) >= HUGE:
            vx *= 1.0 / POW2
            vy *= 1.0 / POW2
            vz *= 1.0 / POW2
        # (written out as in point_frame, not shared through a helper: under fastmath's contraction a helper
        # inlined here and there rounded the speed differently by an ulp, and the loops must equal the one-point
        # paths to the bit, tests/test_wrench_one_point.py; measured 2026-11-29)
        speed = np.sqrt(vx * vx + vy * vy + vz * vz)
        if speed < TINY:  # (as point_frame: the squares scaled, else they underflow and speed is 0, which
            # point_vectors' own scaling cannot restore: e_ip from an in-plane part of 1e-28 of the speed; a review)
            sx = vx * POW2
            sy = vy * POW2
            sz = vz * POW2
            speed = np.sqrt(sx * sx + sy * sy + sz * sz) * (1.0 / POW2)
        axial = vx * zx + vy * zy + vz * zz
        fx, fy, fz, mx, my, mz = point_vectors(vx, vy, vz, zx, zy, zz, speed, axial, loads[0, i], loads[1, i],
                                               loads[2, i], loads[3, i], loads[4, i], loads[5, i], spin[i])
        out[0, i, 0] = fx
        out[0, i, 1] = fy
        out[0, i, 2] = fz
        out[1, i, 0] = mx
        out[1, i, 1] = my
        out[1, i, 2] = mz
