"""Would Theodorsen's unsteady lift deficiency bring propmap's hub moments and in-plane force
closer to a wind tunnel's? A measurement at propmap's converged inflow, not a model of propmap.

Question. In edgewise flow a rigid blade section's angle of attack varies once per revolution
(more on the advancing side). propmap's element is quasi-steady: the lift follows the angle at
once. The circulatory lift of a thin aerofoil whose angle varies harmonically at frequency omega
is attenuated and lagged by Theodorsen's function C(k) = H1(k) / (H1(k) + i H0(k)), H the Hankel
functions of the second kind and k = omega b / U the reduced frequency (b = c / 2). For the n-th
harmonic of a rotating section omega = n Omega, U = Omega r, so k_n = n c / (2 r): for the
1/rev 0.09-0.13 at 0.75 R on these propellers (0.29-0.35 at 0.3 R; printed), |C| 0.92 / 0.85 / 0.80
at k = 0.05 / 0.1 / 0.15 with 8 / 12 / 14 deg of lag (printed). That should
lower the rolling moment (which propmap makes 1.17-1.77 times the published one on the gill2019
case's propellers, docs/validation.md) and turn part of it into a pitching moment (propmap's is 0,
the published 11-58% of the rolling moment). This probe measures how much, and what it does to
the in-plane H-force and the thrust and torque rise.

Method (post-processing only; the kernel and propmap's model are untouched):
1. rotor_loads(..., radial=True) at each operating point gives the converged per-annulus inflow
   v_i(r) on the default discretization's 48 Gauss-Legendre annuli.
2. At each annulus the elements are recomputed on a full circle of N_PSI azimuth nodes (psi = 0
   downstream, 90 deg advancing): U_P = V cos(beta) + v_i, U_T = Omega r + V_b sin(psi), V_b the
   in-plane airspeed plus, with ``inplane_induction``, the skewed wake's in-plane induced velocity
   at v_i (_momentum.inplane_induction_numpy, as the solver); the section's per-annulus Reynolds,
   Mach and rotation factors exactly as the solver takes them (_physics.cambered_annulus at the
   azimuth-mean U^2 = (Omega r)^2 + (V sin beta)^2 / 2 + (V cos beta)^2, not per element), and the
   solver's own element (_physics.element: C_L, C_D of the polar, per unit span without 0.5 rho c);
   the radial flow's drag (``radial_drag``) with _physics.profile_cd as the loads do. Integrated
   with the annuli's quadrature weights and N_b / (2 pi) over psi: T, H (along the in-plane
   airspeed, propmap's drag D), Q, M_R = (N_b / 2 pi) int int r dT sin psi and M_P = -(N_b / 2 pi)
   int int r dT cos psi (positive when the upstream half carries more thrust: nose-up;
   docs/conventions.md). With C = 1 this reproduces rotor_loads (printed: the worst relative
   differences over the grid).
3. Unsteady: at each annulus the angle of attack from the blade-angle datum, alpha(psi) = theta -
   phi(psi), phi = atan2(U_P, U_T) (unwrapped along psi), is split into harmonics; the n-th (n =
   1, 2, 3) is multiplied by C(n k), k = c(r) / (2 r), the mean and the harmonics above 3 kept.
   The element is then evaluated with the blade angle shifted by alpha_unsteady - alpha at the
   same U_T and U_P: C_L and C_D (the whole polar, stall blend and profile drag included: an
   effective angle of attack read on the static polar) at the modified angle, the dynamic pressure
   and the force directions (phi) quasi-steady. The radial drag's profile C_D too.
4. Printed per propeller with its calibrated set (pm.default_params), and the generic set on the
   APC 8x6E: the H-force, rolling- and pitching-moment slopes fitted as k mu over the gill2019 grid
   (as multinomial_fit's k4_mu_only, k9_mu_only, k11_mu_only: least squares of C = k mu over the
   static point and advance ratios GILL2019_ADVANCE at incidences GILL2019_INCIDENCE_DEG, 6000 rpm),
   each divided by the static thrust coefficient (the thrust's fitted CT_static, as in multinomial_fit
   and the case), with the ratios to the published ones, and the thrust and torque rise at mu = 0.2
   edgewise, against the published k4, k9, k11 over CT_static and k2 mu^2 / CT_static,
   k7 mu^2 / CQ_static (gill2019_coefficients).
5. Checks printed: the unsteady change in axial flow (alpha is then the same at every psi, so its
   harmonics are zero and the change must be 0 to round-off), and the unsteady result with every
   k scaled by 1e-9 (C -> 1) against the quasi-steady one. Also printed: the side force, and the
   loads with alpha's harmonics 1-3 removed altogether (C = 0), a bound on what any attenuation of
   the angle's 1/rev-3/rev can do (the rest of the asymmetry is the dynamic pressure's).

Limitations. The inflow v_i(r) is the quasi-steady solve's, not re-balanced with the unsteady
thrust (the unsteady change of the thrust rise at mu = 0.2 is under 1 point of the static thrust
on these sets, so the mean inflow would move little; not measured). k uses U = Omega r; the
section speed varies by +-V_b over the revolution, which Theodorsen's theory (a constant free
stream) does not cover (Greenberg's extension would), and inside the reverse-flow circle (r < V_b
/ Omega, inboard on the retreating side at mu = 0.2) the theory does not apply at all; it is
applied there as elsewhere (small dynamic pressure). Only C(k) on the circulatory lift: the non-
circulatory (apparent-mass) terms, of relative order k / 2 in quadrature, and the pitching moment
about the quarter chord are left out, as is the shed wake's effect on the drag beyond reading the
polar at the effective angle. Rigid blades, propmap's uniform inflow (per annulus, no azimuthal
variation); the tip- and hub-loss factors act on the momentum side only, as in propmap.

Sources: T. Theodorsen, "General Theory of Aerodynamic Instability and the Mechanism of Flutter",
NACA Report 496, 1935 (C(k)); W. Johnson, Helicopter Theory, 1980, Ch. 10, and J. G. Leishman,
Principles of Helicopter Aerodynamics, 2nd ed., 2006, Ch. 8 (its use on rotor sections);
R. Gill and R. D'Andrea, "Computationally Efficient Force and Moment Models for Propellers in UAV
Forward Flight Applications", Drones 3(4):77, 2019, Appendix A (the published fits, data/published).
Modelled on tools/dynamic_stall_probe.py.

Measured on the first run (ratios to the published, APC 8x6E / 8x8E / 10x7E / 10x4.7SF, calibrated sets,
quasi-steady -> unsteady): H slope 0.61 / 0.69 / 0.55 / 0.70 -> 0.55 / 0.64 / 0.49 / 0.60; M_R
slope 1.34 / 1.17 / 1.27 / 1.77 -> 1.31 / 1.16 / 1.23 / 1.61; M_P slope 0 -> +0.24 / +0.10 / +0.19 /
+0.20 (nose-up); thrust rise 0.38 / 0.26 / 0.45 / 1.82 -> 0.38 / 0.27 / 0.47 / 1.77; torque rise
0.36 / 0.53 / -0.08 / 1.05 -> 0.28 / 0.46 / -0.21 / 0.81. Not adopted.

    PYTHONPATH=src .venv/bin/python tools/unsteady_lift_probe.py     # about 2 s (30 s compiling the kernel)
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np
from scipy.special import hankel2

import propmap as pm
from propmap.cases_gill2019 import (GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, GILL2019_MU_RISE, GILL2019_RPM,
                                    gill2019_coefficients)
from propmap.core._momentum import inplane_induction_numpy
from propmap.core._physics import CAMBERED, PK_INPLANE, PK_RADIAL_DRAG, cambered_annulus, element, profile_cd
from propmap.core.nodes import _cambered_args, _nodes
from propmap.core.polar import _model_constants
from propmap.core.solver import DEFAULT_DISCRETIZATION

N_PSI = 64  # full-circle azimuth nodes
HARMONICS = (1, 2, 3)  # the harmonics of alpha(psi) given Theodorsen's C(n k)
GENERIC_ON = "apce_8x6"


def theodorsen(k):
    """C(k) = H1(k) / (H1(k) + i H0(k)), Hankel functions of the second kind (k > 0)."""
    h1, h0 = hankel2(1, k), hankel2(0, k)
    return h1 / (h1 + 1j * h0)


def grid():
    """(total advance ratio, incidence [rad]) of the gill2019 fit (static point first) plus mu = 0.2 edgewise."""
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    return (np.concatenate([[0.0], adv.ravel(), [GILL2019_MU_RISE]]),
            np.concatenate([[0.0], inc.ravel(), [math.pi / 2]]))


def probe_loads(prop, p, omega, V, inc, v, transfer, modify=None):
    """(T, H, Q, M_R, M_P, Y) [N, N, N m, N m, N m, N] of the elements at the annuli's inflow v (n, nr), on
    N_PSI azimuth nodes; ``transfer`` None: quasi-steady, else a function of the reduced frequency n k (per
    annulus) whose complex value multiplies alpha's harmonics n in HARMONICS (theodorsen: C(n k)).
    ``modify(U_T, U_P, u_R, theta, g) -> (theta, g)``, optional: another change of each element's blade angle
    or stall-angle factor g (u_R = V_b cos psi, the radial velocity along the blade; tools/yawed_stall_probe.py)."""
    air = p.air
    nd = _nodes(prop, DEFAULT_DISCRETIZATION.n_radial, DEFAULT_DISCRETIZATION.n_azimuth, air, p)
    model, pk = _model_constants(p)
    psi = (np.arange(N_PSI) + 0.5) * 2 * np.pi / N_PSI
    sinpsi, cospsi = np.sin(psi)[None, None, :], np.cos(psi)[None, None, :]
    Vs, Vc = (V * np.sin(inc))[:, None], (V * np.cos(inc))[:, None]
    axial = Vs == 0
    y = nd.y[None, :]
    if model == CAMBERED:
        cam = _cambered_args(p, air)
        U2 = (omega * y) ** 2 + 0.5 * Vs**2 + Vc**2
        sec = cambered_annulus(U2, nd.sc[None, :], nd.cy2[None, :], cam[4], cam[0], cam[1], cam[2], cam[3] != 0.0,
                               cam[5], cam[6], cam[7])
    else:
        sec = (nd.sc[None, :] + 0 * Vs, 0 * y * Vs, 0 * y * Vs, 0 * y * Vs)
    a, cdf, g, dal0 = (np.broadcast_to(s, v.shape)[..., None] for s in sec)
    Vb = Vs + pk[PK_INPLANE] * np.where(axial, 0.0, inplane_induction_numpy(v, Vs, Vc))
    UT = omega * y[..., None] + Vb[..., None] * sinpsi
    UP = np.broadcast_to((Vc + v)[..., None], UT.shape)
    theta = np.broadcast_to(nd.theta[None, :, None], UT.shape)
    if transfer is not None:  # Theodorsen on alpha's harmonics 1-3 (alpha = theta - phi; theta constant in psi)
        alpha = np.unwrap(theta - np.arctan2(UP, UT), axis=-1)
        A = np.fft.rfft(alpha, axis=-1)
        k = np.sqrt(nd.cy2) / 2.0  # c / (2 r) per annulus
        for n in HARMONICS:
            A[..., n] *= transfer(n * k)[None, :]
        theta = theta + np.fft.irfft(A, n=N_PSI, axis=-1) - alpha
    if modify is not None:
        theta, g = modify(UT, UP, Vb[..., None] * cospsi, theta, g)
    qT, qH = element(UT, UP, theta, np.sin(theta), np.cos(theta), a, cdf, g, dal0, model, pk)
    cdpU = profile_cd(UT, UP, theta, a, cdf, g, dal0, model, pk) * np.sqrt(UT**2 + UP**2)
    kr = pk[PK_RADIAL_DRAG] * Vb[..., None]  # the radial flow's drag, u_R = V_b cos psi (_annulus_loads)
    cfac, w = nd.cfac[None, :], nd.w
    dT = cfac * qT.mean(-1)
    dH = np.where(axial, 0.0, cfac * (qH * sinpsi + kr * cdpU * cospsi**2).mean(-1))
    dY = cfac * (-qH * cospsi + kr * cdpU * sinpsi * cospsi).mean(-1)
    dQ = y * cfac * qH.mean(-1)
    dMR = y * cfac * (qT * sinpsi).mean(-1)
    dMP = -y * cfac * (qT * cospsi).mean(-1)
    return tuple(d @ w for d in (dT, dH, dQ, dMR, dMP, dY))


def summary(T, H, Q, MR, MP, mu, lam, R):
    """H, M_R, M_P slopes (k mu least squares over the fit's points, all but the last) over the static thrust
    (the moments' over T_static R) and the thrust and torque rise at the last point (mu = 0.2 edgewise).

    The static thrust is the fitted CT_static of the thrust's multinomial form (CT_static + k1 lambda_c + k2 mu^2
    + k3 lambda_c^2), as multinomial_fit's and the gill2019 case's (and the published k4 / CT_static); the rises
    are T / T(0) - 1 of the loads themselves, as the case's."""
    fit = slice(0, -1)
    one = np.ones_like(mu[fit])
    T0 = np.linalg.lstsq(np.column_stack([one, lam[fit], mu[fit] ** 2, lam[fit] ** 2]), T[fit], rcond=None)[0][0]
    slope = [float(np.sum(mu[fit] * x[fit]) / np.sum(mu[fit] ** 2)) / T0 for x in (H, MR / R, MP / R)]
    return (*slope, T[-1] / T[0] - 1, Q[-1] / Q[0] - 1)


def published(c):
    mu2 = GILL2019_MU_RISE**2
    return (c["k4"] / c["CT_static"], c["k9"] / c["CT_static"], c["k11"] / c["CT_static"],
            c["k2"] * mu2 / c["CT_static"], c["k7"] * mu2 / c["CQ_static"])


def run(name, p, coeffs, checks):
    prop = pm.load_propeller(name)
    omega = GILL2019_RPM * math.pi / 30
    adv, inc = grid()
    V = adv * omega * prop.radius
    r = pm.rotor_loads(prop, p, omega, V, inc, radial=True)
    if not np.all(r.converged):
        raise RuntimeError(f"{name}: rotor_loads did not converge")
    qs = probe_loads(prop, p, omega, V, inc, r.v_i, None)
    un = probe_loads(prop, p, omega, V, inc, r.v_i, theodorsen)
    zero = probe_loads(prop, p, omega, V, inc, r.v_i, lambda k: 0.0 * k)  # alpha's harmonics 1-3 removed
    nax = inc > 0  # D and M_R are 0 in axial flow: relative to their own size elsewhere, T and Q everywhere
    for lab, a, b, m in (("T", qs[0], r.thrust, inc >= 0), ("D", qs[1], r.drag, nax), ("Q", qs[2], r.torque, inc >= 0),
                         ("M_R", qs[3], r.rolling_moment, nax)):
        checks[lab] = max(checks.get(lab, 0.0), float(np.max(np.abs(a[m] - b[m]) / np.abs(b[m]))))
    axial = inc == 0
    checks["axial"] = max(checks.get("axial", 0.0),
                          *(float(np.max(np.abs(u[axial] - q[axial]) / np.abs(qs[0][axial]))) for u, q in zip(un, qs)))
    small = probe_loads(prop, p, omega, V, inc, r.v_i, lambda k: theodorsen(1e-9 * k))
    checks["k->0"] = max(checks.get("k->0", 0.0), *(float(np.max(np.abs(s - q) / np.abs(qs[0]))) for s, q in
                                                      zip(small, qs)))
    mu, lam = adv * np.sin(inc), adv * np.cos(inc)
    s_qs, s_un, s_0 = (summary(*x[:5], mu, lam, prop.radius) for x in (qs, un, zero))
    meas = published(coeffs[name])
    cells = []
    for i, fmt in enumerate(("{:.2f}", "{:.2f}", "{:+.2f}", "{:+.1%}", "{:+.1%}")):
        f = fmt.format
        ratio = (f"{s_qs[i] / meas[i]:+.2f} -> {s_un[i] / meas[i]:+.2f}x")
        cells.append(f"{f(s_qs[i])} -> {f(s_un[i])} ({ratio})")
    side = un[5][-1] / un[0][-1]
    bound = (f"    alpha's harmonics 1-3 removed (C = 0, a bound): H {s_0[0]:.2f}, M_R {s_0[1]:.2f}, "
             f"M_P {s_0[2]:+.2f}, thrust rise {s_0[3]:+.1%}, torque rise {s_0[4]:+.1%}")
    return cells, meas, side, bound


def main():
    t0 = time.perf_counter()
    coeffs = gill2019_coefficients()
    k = np.array([0.05, 0.1, 0.15])
    C = theodorsen(k)
    print("Theodorsen C(k) at k = " + ", ".join(f"{a:g}: |C| {abs(c):.3f}, phase {math.degrees(np.angle(c)):+.1f} deg"
                                               for a, c in zip(k, C)))
    print(f"gill2019 grid, {GILL2019_RPM:g} rpm, {N_PSI} azimuth nodes, harmonics {HARMONICS} of alpha(psi) times "
          "C(n c / 2r); quasi-steady -> unsteady (ratio to published)")
    cols = ("H slope", "M_R slope", "M_P slope", "thrust rise mu=0.2", "torque rise mu=0.2")
    checks: dict = {}
    runs = [(n, pm.default_params(n), "calibrated") for n in coeffs] + [(GENERIC_ON, pm.generic_params(), "generic")]
    for name, p, label in runs:
        cells, meas, side, bound = run(name, p, coeffs, checks)
        prop = pm.load_propeller(name)
        r = np.linspace(0.3, 1.0, 71) * prop.radius  # (the blade from 0.3 R: inboard the chord over r grows)
        k1 = prop.chord_at(r) / (2.0 * r)
        print(f"{name} ({label}); the 1/rev's k = c / 2r over 0.3-1 R: {k1.min():.3f}-{k1.max():.3f}, "
              f"{float(prop.chord_at(0.75 * prop.radius)) / (1.5 * prop.radius):.3f} at 0.75 R")
        for col, cell, m in zip(cols, cells, meas):
            print(f"    {col:19s} {cell:40s} published {m:+.3f}")
        print(f"    side force / thrust at mu = 0.2 (unsteady): {side:+.4f}")
        print(bound)
    print("quasi-steady probe vs rotor_loads, worst relative difference over all points and sets: "
          + ", ".join(f"{lab} {checks[lab]:.1e}" for lab in ("T", "D", "Q", "M_R")) + " (D, M_R off the axial points)")
    print(f"unsteady - quasi-steady in axial flow, worst (of T): {checks['axial']:.1e}; "
          f"k scaled by 1e-9 vs quasi-steady, worst (of T): {checks['k->0']:.1e}")
    print(f"run time {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
