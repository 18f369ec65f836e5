"""Rotor-rotor interference: the inflow one rotor's skewed wake induces at another's disk.

Each rotor i is an actuator disk of radius R_i with uniform loading whose wake is a skewed
cylinder of ring vortices of constant strength per unit length, parallel to the disk and
convected along the skewed axis at the wake skew angle chi_i from the rotor axis, the
model of Castles and De Leeuw (W. Castles and J. H. De Leeuw, "The normal component of the
induced velocity in the vicinity of a lifting rotor and some examples of its application",
NACA Report 1184, 1954; the skew angle as in J. G. Leishman, Principles of Helicopter
Aerodynamics, 2nd ed., 2006, Sec. 3.4):

    tan chi_i = |V_ip| / |V . a_i + v_i|,

V the hub velocity relative to the air, a_i the axis, v_i the rotor's mean induced
velocity (:attr:`propmap.RotorLoads.v_i_mean`). On the disk itself the model gives the
mean normal velocity gamma / 2 at every skew angle (Coleman's result), so that its field,
divided by that mean, is a pure function of the geometry and chi:

    f_ij(chi_i, psi_ij) = <u_n>_disk j / <u_n>_disk i,

psi_ij the angle between the wake's in-plane direction (along -V_ip, where the air goes)
and the in-plane offset of rotor j from rotor i. Rotor j then sees the air moving along
-a_i at sum_i k_I f_ij v_i, k_I the interference factor (1: the model as it is; the
ring field of one vortex ring: e.g. Leishman 2006, Sec. 10.7).

What it gives: nothing in hover or axial flight (a semi-infinite cylinder induces no
normal velocity outside it in its end plane, f = 0 at chi = 0), a growing downwash on the
rotors downstream in forward flight (for the NeuroBEM quadrotor's rear rotors, 2.41 R
behind the front ones: f = 0.05 at chi = 20 deg, 0.18 at 45 deg, 0.75 at 75 deg) and a
weak upwash beside and ahead of a rotor. Left out: the in-plane part of the induced
velocity, the wake's contraction and roll-up (both would move the downwash), and the
wake's deflection by the others' wakes. Only rotors whose axes are parallel (within
:data:`PARALLEL_COS`) interact; the wake of a rotor in descent (V . a_i + v_i < 0), which
rises above the disk, is the mirror image in the disk's plane (its normal velocity at a
height h above the disk is the falling wake's at -h). Tables of f over chi and psi are
computed once per pair geometry (Biot-Savart with elliptic integrals,
:func:`ring_normal_velocity`) and cached.
"""

from __future__ import annotations

import functools
import math

import numpy as np

__all__ = ["PARALLEL_COS", "ring_normal_velocity", "wake_ratio", "InterferenceTable", "interference_table",
           "interference_inflow"]

#: rotors interact only when their axes are this parallel (cos 8 deg)
PARALLEL_COS = math.cos(math.radians(8.0))
#: table nodes: skew angle chi (0 to 90 deg) and the offset's angle psi from the wake direction (0 to 180 deg);
#: a table of 31 x 19 nodes takes about 0.2 s (2-core AMD EPYC), and interpolates f within about 1% of f
#: between nodes (0.1488 against 0.1504 at 45 deg, 17 deg off the wake's direction, 2.41 R)
CHI_NODES = np.radians(np.arange(0.0, 90.01, 3.0))
PSI_NODES = np.radians(np.arange(0.0, 180.01, 10.0))
#: ring stations along the wake axis [R]: cells growing geometrically from the disk to 1 R, 0.25 R wide to
#: 40 R, geometric again to WAKE_LENGTH (the rest of a semi-infinite wake adds < 1e-4 of the disk's mean at
#: 2 R or more); the far wake's 2 v_i on the axis at 20 R is reproduced to 0.5%
WAKE_LENGTH = 300.0
_EDGES = np.concatenate([[0.0], np.geomspace(1e-3, 1.0, 60), np.arange(1.25, 40.0, 0.25),
                         np.geomspace(40.0, WAKE_LENGTH, 20)])
#: disk quadrature: Gauss-Legendre in (r/R)^2 (equal-area weights) x uniform azimuth
N_RADIAL = 4
N_AZIMUTH = 12


def ring_normal_velocity(rho, z, radius=1.0):
    """Velocity along the axis of a vortex ring of unit circulation, radius ``radius``.

    Parameters
    ----------
    rho, z : array_like
        Distance from the ring's axis and along it from the ring's plane (same unit as
        ``radius``), broadcast together; not on the ring itself (rho = radius, z = 0).
    radius : float
        The ring's radius (> 0), in the unit of ``rho`` and ``z``.

    Returns
    -------
    ndarray
        u_z per unit circulation: 1 / (2 pi sqrt(A)) (K(m) + (R^2 - rho^2 - z^2) / B E(m)),
        A = (R + rho)^2 + z^2, B = (R - rho)^2 + z^2, m = 4 R rho / A (K, E the complete
        elliptic integrals of parameter m), which is 1 / (2 R) at the centre (H. Lamb,
        Hydrodynamics, 6th ed., 1932, Sec. 161; Leishman 2006, Sec. 10.7).
    """
    from scipy.special import ellipe, ellipk

    rho = np.asarray(rho, float)
    z = np.asarray(z, float)
    R = float(radius)
    A = (R + rho) ** 2 + z * z
    B = (R - rho) ** 2 + z * z
    m = 4.0 * R * rho / A
    return (ellipk(m) + (R * R - rho * rho - z * z) / B * ellipe(m)) / (2.0 * np.pi * np.sqrt(A))


def _wake_normal_velocity(chi: float, x, y, z) -> np.ndarray:
    """Mean-normalised normal velocity of a unit-radius skewed wake at points (x, y, z) [R].

    Frame of the source rotor: z its axis, x the wake's in-plane direction; rings of unit
    strength per unit length at s (sin chi, 0, -cos chi), s >= 0.
    """
    s = 0.5 * (_EDGES[1:] + _EDGES[:-1])
    ds = np.diff(_EDGES)
    xq = np.asarray(x, float)[:, None] - s * math.sin(chi)
    zq = np.asarray(z, float)[:, None] + s * math.cos(chi)
    rho = np.hypot(xq, np.asarray(y, float)[:, None])
    return ring_normal_velocity(rho, zq) @ ds / 0.5  # the disk's own mean is gamma / 2 (module docstring)


@functools.lru_cache(maxsize=1)
def _disk_points():
    g, w = np.polynomial.legendre.leggauss(N_RADIAL)
    r = np.sqrt(0.5 * (g + 1.0))
    th = (np.arange(N_AZIMUTH) + 0.5) * 2.0 * np.pi / N_AZIMUTH
    rr, tt = np.meshgrid(r, th, indexing="ij")
    weights = np.repeat(w[:, None] / 2.0, N_AZIMUTH, axis=1) / N_AZIMUTH
    return rr.ravel() * np.cos(tt.ravel()), rr.ravel() * np.sin(tt.ravel()), weights.ravel()


def wake_ratio(chi: float, offset, radius_ratio: float = 1.0) -> float:
    """f: the mean normal velocity a rotor's skewed wake induces over another disk, in units
    of its own mean (module docstring).

    Parameters
    ----------
    chi : float
        Wake skew angle from the source rotor's axis [rad], in [0, pi/2].
    offset : sequence of 3 floats
        The other disk's centre from the source hub in units of the source radius R_i, in
        the frame (wake's in-plane direction, its normal in the plane, source axis).
    radius_ratio : float
        R_j / R_i.

    Returns
    -------
    float
        Positive: a downwash (along -a_i) at the other disk.
    """
    x, y, w = _disk_points()
    dx, dy, dz = (float(v) for v in offset)
    return float(w @ _wake_normal_velocity(chi, radius_ratio * x + dx, radius_ratio * y + dy,
                                           np.full_like(x, dz)))


class InterferenceTable:
    """f_ij(chi, psi) of one rotor pair on a (chi, psi) grid, interpolated bilinearly.

    Parameters
    ----------
    distance : float
        In-plane distance of rotor j's hub from rotor i's, in units of R_i (> 0).
    height : float
        Offset of rotor j's hub along a_i, in units of R_i.
    radius_ratio : float
        R_j / R_i.
    """

    def __init__(self, distance: float, height: float, radius_ratio: float) -> None:
        self.distance, self.height, self.radius_ratio = float(distance), float(height), float(radius_ratio)
        x, y, w = _disk_points()
        values = np.empty((CHI_NODES.size, PSI_NODES.size))
        for k, psi in enumerate(PSI_NODES):
            px = radius_ratio * x + distance * math.cos(psi)
            py = radius_ratio * y + distance * math.sin(psi)
            pz = np.full_like(x, height)
            for i, chi in enumerate(CHI_NODES):
                values[i, k] = w @ _wake_normal_velocity(chi, px, py, pz)
        self.values = values

    def __call__(self, chi, psi) -> np.ndarray:
        """f at skew angles ``chi`` [rad] and offset angles ``psi`` [rad] (broadcast; psi taken
        modulo the mirror symmetry about the wake's plane, chi clipped to [0, pi/2])."""
        chi = np.clip(np.asarray(chi, float), 0.0, CHI_NODES[-1])
        psi = np.abs(np.angle(np.exp(1j * np.asarray(psi, float))))  # in [0, pi]
        hc = CHI_NODES[1] - CHI_NODES[0]
        hp = PSI_NODES[1] - PSI_NODES[0]
        fi = np.minimum(chi / hc, CHI_NODES.size - 1 - 1e-9)
        fk = np.minimum(psi / hp, PSI_NODES.size - 1 - 1e-9)
        i = fi.astype(int)
        k = fk.astype(int)
        ti, tk = fi - i, fk - k
        v = self.values
        return ((1 - ti) * ((1 - tk) * v[i, k] + tk * v[i, k + 1])
                + ti * ((1 - tk) * v[i + 1, k] + tk * v[i + 1, k + 1]))


@functools.lru_cache(maxsize=64)
def interference_table(distance: float, height: float, radius_ratio: float) -> InterferenceTable:
    """The :class:`InterferenceTable` of a pair geometry, built once per process (LRU cache of 64).

    Parameters
    ----------
    distance, height, radius_ratio : float
        As :class:`InterferenceTable` (in units of the source rotor's radius); round them
        (e.g. to 4 decimals) so that the same geometry hits the cache.

    Returns
    -------
    InterferenceTable
    """
    return InterferenceTable(distance, height, radius_ratio)


def interference_inflow(positions, axes, radii, velocity, v_i, factor: float) -> np.ndarray:
    """The extra inflow each rotor sees from the other rotors' wakes (module docstring).

    Parameters
    ----------
    positions : ndarray, shape (n, 3)
        Hub positions [m].
    axes : ndarray, shape (n, 3)
        Unit rotor axes.
    radii : ndarray, shape (n,)
        Tip radii R [m].
    velocity : ndarray, shape (N, n, 3)
        Hub velocities relative to the (undisturbed) air [m/s].
    v_i : ndarray, shape (N, n)
        Each rotor's mean induced velocity [m/s] (RotorLoads.v_i_mean).
    factor : float
        k_I, the interference factor (>= 0).

    Returns
    -------
    ndarray, shape (N, n, 3)
        The velocity of the air at each hub from the other rotors' wakes [m/s]
        (sum_i -k_I f_ij v_i a_i): add it to the wind, i.e. subtract it from the hub's
        velocity relative to the air.
    """
    positions = np.asarray(positions, float)
    axes = np.asarray(axes, float)
    n = positions.shape[0]
    out = np.zeros(np.shape(velocity))
    if factor == 0 or n < 2:
        return out
    for i in range(n):
        a = axes[i]
        V = velocity[:, i, :]
        Va = V @ a
        V_ip = V - Va[:, None] * a
        speed_ip = np.linalg.norm(V_ip, axis=1)
        chi = np.arctan2(speed_ip, np.abs(Va + v_i[:, i]))
        # the wake's in-plane direction: where the air goes, -V_ip (any direction at chi = 0, where f = 0)
        e = np.where(speed_ip[:, None] > 0, -V_ip / np.maximum(speed_ip, 1e-300)[:, None], 0.0)
        for j in range(n):
            if j == i or float(axes[j] @ a) < PARALLEL_COS:
                continue
            d = positions[j] - positions[i]
            h = float(d @ a)
            d_ip = d - h * a
            dist = float(np.linalg.norm(d_ip))
            table = interference_table(round(dist / radii[i], 4), round(h / radii[i], 4),
                                       round(float(radii[j] / radii[i]), 4))
            if dist > 0:
                cos_psi = (e @ d_ip) / dist
                psi = np.arccos(np.clip(cos_psi, -1.0, 1.0))
            else:
                psi = np.zeros(V.shape[0])
            f = table(chi, psi)
            up = (Va + v_i[:, i]) < 0  # in descent the wake rises: the mirror image, rotor j at -h
            if h != 0 and up.any():
                mirror = interference_table(round(dist / radii[i], 4), round(-h / radii[i], 4),
                                            round(float(radii[j] / radii[i]), 4))
                f = np.where(up, mirror(chi, psi), f)
            out[:, j, :] -= (factor * f * v_i[:, i])[:, None] * a
    return out
