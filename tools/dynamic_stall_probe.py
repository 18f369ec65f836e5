"""Issue 14: would quasi-steady dynamic stall give the edgewise thrust rise and H-force slope
that wind tunnels measure? A measurement, not a model of propmap.

In edgewise flow a blade section's angle of attack varies once per revolution; at a
propeller's reduced pitch rates the stall is delayed while the angle rises and comes early
while it falls. Gormont's quasi-steady form (R. E. Gormont, "A Mathematical Model of
Unsteady Aerodynamics and Radial Flow for Application to Helicopter Rotors", USAAMRDL TR
72-67, 1973; as summarised in J. G. Leishman, Principles of Helicopter Aerodynamics, 2nd
ed., 2006, Ch. 9) reads the static polar at alpha - gamma K1 sqrt(|c alpha_dot / (2 W)|)
sign(alpha_dot), K1 = 1 while alpha rises and -1/2 while it falls, gamma = 1.4 - 6 (0.06 -
t/c) for the lift (about 1.5 at t/c = 0.08). Here it shifts the cambered section's positive
stall angle by that amount (the attached lift is unchanged), with the section's own rate of
the uniform-inflow element: alpha_dot = Omega U_P V sin(beta) cos(psi) / W^2 (the in-plane
induction left out of the rate), on the full circle: each of the reference solver's
half-circle nodes (cos psi > 0, the angle rising) with its mirror azimuth pi - psi (the same
U_T and U_P, the angle falling). Axial flow is unchanged (alpha_dot = 0).

It patches the NumPy reference solver (core/_reference.py, 48 x 16 nodes; the kernel is
untouched) and prints, for gamma from the command line (default 1.5):

* the gill2019 case's quantities (docs/validation.md: Gill & D'Andrea, Drones 3(4):77, 2019,
  Appendix A's multinomial fits): the H-force slope fitted as k4 mu alone over the case's
  grid, in units of the static thrust, and the thrust and torque rise at mu = 0.2 edgewise,
  6000 rpm, each catalogue propeller with its own calibrated set;
* the NeuroBEM quadrotor's rotor (the example vehicle's lumped blade, generic set) at 1500
  rad/s edgewise: the thrust change, where the flight logs say the model's edgewise thrust
  is already 1-3% high (docs/flight.md);
* the Beaver propeller's wind-axis thrust ratios at 10 and 20 deg (generic set; Sinnige et
  al. 2019, digitized; docs/validation.md).

    .venv/bin/python tools/dynamic_stall_probe.py [GAMMA]     # about 2 s

Measured 2026-11-26 (docs/validation.md, the gill2019 case's bullets); propmap's option `dynamic_stall` since
(docs/models.md), which this probe preceded.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

import propmap as pm
from propmap.cases import (BEAVER_N, GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, beaver_propeller,
                           gill2019_coefficients)
from propmap.core import _reference as reference
from propmap.core._physics import CAMBERED, exp_sat_numpy
from propmap.core.nodes import _nodes

K1_FALLING = 0.5
_static_element = reference.element
_state: dict = {}


def _element(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, model, pk):
    """The cambered element with the positive stall angle shifted by Gormont's delay (_state set),
    as the mean of the node and its mirror azimuth pi - psi: the reference solver evaluates the
    half circle cos(psi) > 0 (uniform inflow: the mirror node has the same U_T and U_P), where the
    angle of attack rises; at the mirror node it falls at the same rate (K1 = -1/2 there)."""
    if not _state.get("gamma") or model != CAMBERED:
        return _static_element(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, model, pk)
    rising = _delayed(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, pk, 1.0)
    falling = _delayed(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, pk, -1.0)
    return 0.5 * (rising[0] + falling[0]), 0.5 * (rising[1] + falling[1])


def _delayed(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, pk, mirror):
    """The delayed element at the half circle's nodes (mirror 1) or at their mirror azimuths (-1)."""
    alpha_L0, cd90, cd_min, cd2, cl_cdmin, M, a_pos, a_neg = pk[:8]
    W2 = UT * UT + UP * UP + 1e-300
    U = np.sqrt(W2)
    alpha_dot = mirror * UP * _state["omega"] * _state["Vs"] * _state["cospsi"] / W2
    rate = _state["chord"] * np.abs(alpha_dot) / (2.0 * U)
    delay = _state["gamma"] * np.where(alpha_dot >= 0.0, 1.0, -K1_FALLING) * np.sqrt(rate)
    ae = theta - (alpha_L0 + s3) - np.arctan2(UP, UT)
    ae = ae - 2 * np.pi * (ae > np.pi) + 2 * np.pi * (ae < -np.pi)
    sin_a, cos_a = (sin_th * UT - cos_th * UP) / U, (cos_th * UT + sin_th * UP) / U
    p, q = exp_sat_numpy(M * (ae - s2 * a_pos - delay)), exp_sat_numpy(-M * (ae - s2 * a_neg))
    s = 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))
    cl_att = s0 * ae
    CL = (1.0 - s) * cl_att + s * cd90 * sin_a * cos_a
    CD = s1 * (cd_min + (1.0 - s) * cd2 * (cl_att - cl_cdmin) ** 2) + s * cd90 * sin_a * sin_a
    return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT)


reference.element = _element


def loads(prop, p, omega, V, incidence, gamma):
    """(T, D, Q) [N, N, N m] of the reference solver, with Gormont's delay of factor gamma (0: none)."""
    nd = _nodes(prop, 48, 16, pm.Air(), p)
    V, incidence = np.asarray(V, float), np.asarray(incidence, float)
    omega = np.full(V.shape, float(omega))
    Vs = V * np.sin(incidence)
    _state.update(gamma=gamma, omega=omega[:, None, None], Vs=Vs[:, None, None],
                  cospsi=nd.cospsi[None, None, : nd.cospsi.size // 2],
                  chord=np.asarray(prop.chord_at(nd.y))[None, :, None])
    T, D, Q, _, converged = reference.solve_reference(omega, Vs, V * np.cos(incidence), nd, p)
    if not converged.all():
        raise RuntimeError("the reference solver did not converge")
    return T, D, Q


def main(gamma: float) -> None:
    print(f"Gormont's quasi-steady stall delay, gamma = {gamma:g} (0: the static polar)")
    print("gill2019 (6000 rpm, own calibrated set): H slope k4/CT_static (mu only); thrust and torque rise at mu = 0.2")
    published = gill2019_coefficients()
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv = np.concatenate([[0.0], adv.ravel(), [0.2]])
    inc = np.concatenate([[0.0], inc.ravel(), [math.pi / 2]])
    mu = adv * np.sin(inc)
    for name, c in published.items():
        prop, p = pm.load_propeller(name), pm.default_params(name)
        omega = 6000 * math.pi / 30
        row = []
        for g in (0.0, gamma):
            T, D, Q = loads(prop, p, omega, adv * omega * prop.radius, inc, g)
            k4 = np.linalg.lstsq(mu[1:-1, None], D[1:-1], rcond=None)[0][0]  # D = k4 mu (the normalisation cancels)
            row.append((k4 / T[0], T[-1] / T[0] - 1, Q[-1] / Q[0] - 1))
        meas = (c["k4"] / c["CT_static"], c["k2"] * 0.04 / c["CT_static"], c["k7"] * 0.04 / c["CQ_static"])
        cells = [f"{lab} {m:.2f} / {r0:.2f} -> {r1:.2f}"
                 for lab, m, r0, r1 in zip(("H", "dT", "dQ"), meas, row[0], row[1])]
        print(f"  {name:13s} measured / static polar -> delayed: " + "; ".join(cells))
    veh = pm.read_vehicle(pm.__path__[0] + "/data/examples/neurobem_quadrotor.toml")
    prop, p = veh.rotors[0].propeller, pm.generic_params()
    print("NeuroBEM rotor, 1500 rad/s, generic set: thrust change edgewise at 3 / 6 / 9 / 12 m/s:", end="")
    for V in (3.0, 6.0, 9.0, 12.0):
        T0, T1 = (loads(prop, p, 1500.0, [V], [math.pi / 2], g)[0][0] for g in (0.0, gamma))
        print(f" {T1 / T0 - 1:+.2%}", end="")
    print()
    bp, a = beaver_propeller(), np.radians([0.0, 10.0, 20.0])
    for g in (0.0, gamma):
        T, D, _ = loads(bp, pm.generic_params(), 2 * math.pi * BEAVER_N, np.full(3, 40.0), a, g)
        ctw = T * np.cos(a) - D * np.sin(a)
        print(f"Beaver, generic set, gamma {g:g}: CT_w(10 deg)/CT_w(0) {ctw[1] / ctw[0]:.3f}, "
              f"CT_w(20 deg)/CT_w(0) {ctw[2] / ctw[0]:.3f} (measured 1.128, 1.351)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("gamma", nargs="?", type=float, default=1.5, help="Gormont's gamma (0: the static polar)")
    main(parser.parse_args().gamma)
