"""Would the yawed-flow (radial-flow) stall delay raise propmap's edgewise thrust towards a wind tunnel's?
A measurement at propmap's converged inflow, not a model of propmap.

Question. In edgewise flow a blade section near psi = 0 and 180 deg is yawed: the in-plane airspeed puts a radial
velocity u_R = V_b cos(psi) along the blade, at a yaw angle Lambda = atan(|u_R| / |U_T|), U_T = Omega r +
V_b sin(psi). A yawed aerofoil stalls later than an unyawed one at the same normal-plane angle of attack (the
radial flow's stall delay). The delay grows as Lambda^2 ~ mu^2 at small mu, the shape of the tunnel's thrust rise,
where Gormont's dynamic-stall option (docs/models.md) grows as sqrt(mu). propmap's edgewise thrust rises by 4-9%
at mu = 0.2 on three APC electric propellers where the tunnel's rises by 15-19% (docs/validation.md, case
gill2019). This probe measures what the delay does to that rise, to the in-plane force and to the hub moments.

Method (post-processing only; the kernel and propmap's model are untouched). The machinery of
tools/unsteady_lift_probe.py (its docstring, steps 1-2): rotor_loads(..., radial=True) gives the converged
per-annulus inflow v_i(r); at each of the 48 annuli the elements are recomputed on a full circle of N_PSI azimuth
nodes, U_P = V cos(beta) + v_i, U_T = Omega r + V_b sin(psi), V_b the in-plane airspeed plus the skewed wake's
in-plane induced velocity at v_i (as the solver), with the solver's per-annulus section constants and its own
element, and integrated to T, H, Q, M_R, M_P. With no delay this reproduces rotor_loads (printed). The yawed
stall: at each element the cambered section's stall-angle factor g (which multiplies both stall angles a_pos and
a_neg from the zero-lift line in the stall blend, g = (Re factor) (1 + stall_delay (c/r)^2),
_physics.cambered_annulus) is multiplied by 1 / cos(Lambda) = sqrt(1 + (u_R / U_T)^2), u_R = V_b cos(psi) (the same
radial velocity as the radial drag's), capped at 1 / cos(LAMBDA_MAX): the static polar's positive and negative
stall onsets move from g a_stall to g a_stall / cos(Lambda), the attached lift (slope, zero-lift angle) and the
post-stall flat plate unchanged. The profile drag's blend (the radial drag's C_D,p) takes the same factor.
Printed per propeller (the four gill2019 ones with their calibrated sets, pm.default_params, and the generic set on
the APC 8x6E), quasi-steady -> yawed: the H-force, rolling- and pitching-moment slopes fitted as k mu over the
gill2019 grid (static point, advance ratios GILL2019_ADVANCE at GILL2019_INCIDENCE_DEG, 6000 rpm), over the
fitted CT_static as in tools/unsteady_lift_probe.py, with the ratios to the published (gill2019_coefficients); the
thrust rise at mu = 0.05, 0.1, 0.2 edgewise as ratios to the published k2 mu^2 / CT_static (the tunnel's rise goes
as mu^2) and the torque rise at mu = 0.2 against k7 mu^2 / CQ_static. Also the NeuroBEM quadrotor's rotor
(the example vehicle's propeller, generic set) edgewise at 1500 rad/s, 3-12 m/s, and the Beaver propeller's
wind-axis thrust ratios CT_w(a) / CT_w(0), CT_w ~ T cos(a) - H sin(a), at 10 and 20 deg (generic set; measured
1.128 and 1.351), as tools/dynamic_stall_probe.py. Checks printed: the change in axial flow (u_R = 0: must be 0)
and the quasi-steady reproduction of rotor_loads.

Limitations. The inflow v_i(r) is the quasi-steady solve's, not re-balanced with the yawed loads (a larger thrust
would draw a larger inflow and give back part of the rise; not measured). The form of the delay: the simplest
common one, the stall angle divided by cos(Lambda) (the independence principle's normal-plane stall angle scaled
by the sweep, a stall delay with the attached lift unchanged), as the brief for this probe states it; the sources
below describe the radial flow's stall delay, Gormont's model applying it to the static section data and St.
Hilaire et al. measuring a delayed and larger lift stall with 30 deg of sweep, but their exact forms and constants
(Gormont's, Leishman's) were not checked against the reports here: the factor 1 / cos(Lambda) is unfitted and not
tuned. The cap LAMBDA_MAX: 1 / cos(Lambda) is unbounded where U_T -> 0 (the edge of the reverse-flow circle on the
retreating side); there the dynamic pressure is small, and the sensitivity to the cap is printed (45 and 75 deg).
The delay is applied in the reverse-flow region as elsewhere. Steady yaw only: no dynamic stall, no unsteady lift;
rigid blades, propmap's uniform inflow per annulus.

Sources: R. E. Gormont, "A Mathematical Model of Unsteady Aerodynamics and Radial Flow for Application to
Helicopter Rotors", USAAMRDL TR 72-67, 1973; F. D. Harris, "Preliminary Study of Radial Flow Effects on Rotor
Blades", J. American Helicopter Society 11(3), 1966; P. F. St. Hilaire, F. O. Carta, M. R. Fink and W. D. Jepson,
"The Influence of Sweep on the Aerodynamic Loading of an Oscillating NACA 0012 Airfoil", NASA CR-3092, 1979;
J. G. Leishman, Principles of Helicopter Aerodynamics, 2nd ed., 2006, Ch. 7 and 9; R. Gill and R. D'Andrea, Drones
3(4):77, 2019, Appendix A (the published fits, data/published). Built on tools/unsteady_lift_probe.py.

Measured on the first run (ratios to the published, APC 8x6E / 8x8E / 10x7E / 10x4.7SF, calibrated sets,
quasi-steady -> yawed; the reproduction of rotor_loads to 2.9e-6, the axial change 0): H slope 0.61 / 0.69 / 0.55 /
0.70 -> unchanged to 0.01; M_R slope 1.34 / 1.17 / 1.27 / 1.77 -> 1.33 / 1.17 / 1.26 / 1.76; M_P stays 0 (the
factor is the same at psi and pi - psi); thrust rise at mu = 0.05 0.77 / 0.38 / 1.07 / 3.32 -> 1.12 / 0.74 / 1.38 /
3.44, at 0.1 0.61 / 0.31 / 0.83 / 2.82 -> 0.90 / 0.61 / 1.09 / 2.95, at 0.2 0.38 / 0.26 / 0.45 / 1.82 -> 0.59 /
0.47 / 0.65 / 1.95; torque rise 0.36 / 0.53 / -0.08 / 1.05 -> 0.48 / 0.62 / -0.03 / 1.18 (the cap at 45 or 75 deg:
the same to 0.01). NeuroBEM rotor +0.06 / +0.22 / +0.48 / +0.83%; Beaver 1.021 / 1.072 -> 1.022 / 1.074.

    PYTHONPATH=src .venv/bin/python tools/yawed_stall_probe.py     # about 1 s (35 s compiling the kernel)
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

import propmap as pm
from propmap.cases import BEAVER_N, beaver_propeller
from propmap.cases_gill2019 import GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, GILL2019_RPM, gill2019_coefficients
from propmap.core._physics import CAMBERED
from propmap.core.polar import _model_constants
from unsteady_lift_probe import N_PSI  # (tools/, the script's folder: its full-circle elements)
from unsteady_lift_probe import probe_loads as full_circle

LAMBDA_MAX = math.radians(60.0)  # cap on the yaw angle: stall angles at most 1 / cos(60 deg) = 2 times
CAPS_SENSITIVITY = (45.0, 75.0)  # [deg]
MU_RISE = (0.05, 0.1, 0.2)  # edgewise points of the thrust rise (the last also the torque's)
GENERIC_ON = "apce_8x6"


def probe_loads(prop, p, omega, V, inc, v, lam_max):
    """(T, H, Q, M_R, M_P) [N, N, N m, N m, N m] of the elements at the annuli's inflow v (n, nr) on N_PSI azimuth
    nodes (tools/unsteady_lift_probe.probe_loads), the stall-angle factor g of each element times
    min(1 / cos(Lambda), 1 / cos(lam_max)) (lam_max [rad]; None: quasi-steady, the solver's element)."""
    if _model_constants(p)[0] != CAMBERED:
        raise ValueError("the yawed stall acts on the cambered section's stall angles only")

    def yawed(UT, UP, uR, theta, g):
        """1 / cos(Lambda) = sqrt(1 + (u_R / U_T)^2), Lambda = atan(|u_R| / |U_T|), capped at lam_max."""
        inv_cos = np.sqrt(1.0 + (uR / np.maximum(np.abs(UT), 1e-300)) ** 2)
        return theta, g * np.minimum(inv_cos, 1.0 / math.cos(lam_max))

    return full_circle(prop, p, omega, V, inc, v, None, None if lam_max is None else yawed)[:5]


def solve(prop, p, omega, V, inc):
    r = pm.rotor_loads(prop, p, omega, V, inc, radial=True)
    if not np.all(r.converged):
        raise RuntimeError("rotor_loads did not converge")
    return r


def grid():
    """(total advance ratio, incidence [rad]) of the gill2019 fit (static point first), then MU_RISE edgewise."""
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    return (np.concatenate([[0.0], adv.ravel(), MU_RISE]),
            np.concatenate([[0.0], inc.ravel(), np.full(len(MU_RISE), math.pi / 2)]))


def summary(T, H, Q, MR, MP, mu, lam, R):
    """H, M_R, M_P slopes (k mu least squares over the fit's points) over the fitted static thrust (the moments'
    over T_static R), as tools/unsteady_lift_probe.summary; the thrust rises T / T(0) - 1 at MU_RISE and the torque
    rise at the last."""
    fit = slice(0, -len(MU_RISE))
    one = np.ones_like(mu[fit])
    T0 = np.linalg.lstsq(np.column_stack([one, lam[fit], mu[fit] ** 2, lam[fit] ** 2]), T[fit], rcond=None)[0][0]
    slope = [float(np.sum(mu[fit] * x[fit]) / np.sum(mu[fit] ** 2)) / T0 for x in (H, MR / R, MP / R)]
    rises = [float(t / T[0] - 1) for t in T[-len(MU_RISE):]]
    return (*slope, *rises, float(Q[-1] / Q[0] - 1))


def published(c):
    return (c["k4"] / c["CT_static"], c["k9"] / c["CT_static"], c["k11"] / c["CT_static"],
            *(c["k2"] * m**2 / c["CT_static"] for m in MU_RISE), c["k7"] * MU_RISE[-1] ** 2 / c["CQ_static"])


COLS = ("H slope", "M_R slope", "M_P slope", *(f"thrust rise mu={m:g}" for m in MU_RISE), "torque rise mu=0.2")


def run(name, p, coeffs, checks):
    prop = pm.load_propeller(name)
    omega = GILL2019_RPM * math.pi / 30
    adv, inc = grid()
    V = adv * omega * prop.radius
    r = solve(prop, p, omega, V, inc)
    qs = probe_loads(prop, p, omega, V, inc, r.v_i, None)
    ys = probe_loads(prop, p, omega, V, inc, r.v_i, LAMBDA_MAX)
    nax = inc > 0
    for lab, x, b, m in (("T", qs[0], r.thrust, inc >= 0), ("D", qs[1], r.drag, nax), ("Q", qs[2], r.torque, inc >= 0),
                         ("M_R", qs[3], r.rolling_moment, nax)):
        checks[lab] = max(checks.get(lab, 0.0), float(np.max(np.abs(x[m] - b[m]) / np.abs(b[m]))))
    axial = inc == 0
    checks["axial"] = max(checks.get("axial", 0.0),
                          *(float(np.max(np.abs(u[axial] - q[axial]) / np.abs(qs[0][axial]))) for u, q in zip(ys, qs)))
    mu, lam = adv * np.sin(inc), adv * np.cos(inc)
    s_qs, s_ys = summary(*qs, mu, lam, prop.radius), summary(*ys, mu, lam, prop.radius)
    caps = [summary(*probe_loads(prop, p, omega, V, inc, r.v_i, math.radians(c)), mu, lam, prop.radius)
            for c in CAPS_SENSITIVITY]
    return s_qs, s_ys, caps, published(coeffs[name])


def edgewise_change(prop, p, omega, V):
    """Yawed / quasi-steady thrust - 1, edgewise at airspeeds V."""
    V = np.asarray(V, float)
    inc = np.full(V.shape, math.pi / 2)
    r = solve(prop, p, omega, V, inc)
    return probe_loads(prop, p, omega, V, inc, r.v_i, LAMBDA_MAX)[0] / probe_loads(prop, p, omega, V, inc, r.v_i,
                                                                                       None)[0] - 1


def beaver_ratios(lam_max):
    a = np.radians([0.0, 10.0, 20.0])
    prop, p = beaver_propeller(), pm.generic_params()
    V, omega = np.full(3, 40.0), 2 * math.pi * BEAVER_N
    r = solve(prop, p, omega, V, a)
    T, H = probe_loads(prop, p, omega, V, a, r.v_i, lam_max)[:2]
    ctw = T * np.cos(a) - H * np.sin(a)
    return ctw[1] / ctw[0], ctw[2] / ctw[0]


def main():
    t0 = time.perf_counter()
    coeffs = gill2019_coefficients()
    print(f"gill2019 grid, {GILL2019_RPM:g} rpm, {N_PSI} azimuth nodes; stall angles times 1 / cos(Lambda), Lambda "
          f"capped at {math.degrees(LAMBDA_MAX):g} deg; quasi-steady -> yawed (ratio to published); inflow not "
          "re-balanced")
    checks: dict = {}
    runs = [(n, pm.default_params(n), "calibrated") for n in coeffs] + [(GENERIC_ON, pm.generic_params(), "generic")]
    for name, p, label in runs:
        s_qs, s_ys, caps, meas = run(name, p, coeffs, checks)
        print(f"{name} ({label})")
        for i, col in enumerate(COLS):
            pct = "rise" in col
            f = "{:+.1%}".format if pct else "{:+.3f}".format
            print(f"    {col:19s} {f(s_qs[i]):>7s} -> {f(s_ys[i]):>7s}  ({s_qs[i] / meas[i]:+.2f} -> "
                  f"{s_ys[i] / meas[i]:+.2f}x)  published {f(meas[i])}")
        print("    cap " + "; ".join(f"{c:g} deg: thrust rise mu=0.2 {s[5] / meas[5]:+.2f}x, H {s[0] / meas[0]:+.2f}x"
                                     for c, s in zip(CAPS_SENSITIVITY, caps)))
    veh = pm.read_vehicle("neurobem_quadrotor")
    dT = edgewise_change(veh.rotors[0].propeller, pm.generic_params(), 1500.0, [3.0, 6.0, 9.0, 12.0])
    print("NeuroBEM rotor, 1500 rad/s, generic set: thrust change edgewise at 3 / 6 / 9 / 12 m/s: "
          + " / ".join(f"{x:+.2%}" for x in dT))
    for lab, lm in (("quasi-steady", None), ("yawed", LAMBDA_MAX)):
        b10, b20 = beaver_ratios(lm)
        print(f"Beaver, generic set, 40 m/s, {lab}: CT_w(10 deg)/CT_w(0) {b10:.3f}, CT_w(20 deg)/CT_w(0) {b20:.3f} "
              "(measured 1.128, 1.351)")
    print("quasi-steady probe vs rotor_loads, worst relative difference over all points and sets: "
          + ", ".join(f"{lab} {checks[lab]:.1e}" for lab in ("T", "D", "Q", "M_R")) + " (D, M_R off the axial points)")
    print(f"yawed - quasi-steady in axial flow, worst (of T): {checks['axial']:.1e}")
    print(f"run time {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
