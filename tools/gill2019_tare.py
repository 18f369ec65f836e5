"""Issue 14: could the wind tunnel's larger H-force be the drag of the rig around the propeller?

A measurement, not a model of propmap. Gill & D'Andrea (Drones 3(4):77, 2019, Appendix A) publish,
for four catalogue propellers, the in-plane force of their oblique-flow tests as C_FH = k4 mu
(normalised by (rho/2) pi R^2 (Omega R)^2; case ``gill2019``, docs/validation.md). propmap's
in-plane force, each propeller's own calibrated set fitted the same way (``multinomial_fit``'s
``k4_mu_only``, 6000 rpm, the case's grid of total advance ratios 0.04-0.24 at incidences 0-90
deg), rises at 0.55-0.70 of the published slope. If the balance also measured a drag that the
tests did not tare away (the motor's, the mount's: D = (rho/2) C_D A V^2 along the wind), its
in-plane part D sin(incidence) is, in their normalisation, (C_D A / (pi R^2)) a mu with a = V / (Omega R)
the total advance ratio; fitted as k4 mu over the same grid it adds (C_D A / (pi R^2)) <a>, <a> the
mu^2-weighted mean of a over the grid. This prints the drag area C_D A that would make up each
propeller's missing slope. Then a check in axial flow, where the same drag would take
(C_D A / (pi R^2)) lambda_c^2 off the published thrust: the published C_FT at lambda_c = 0.2 as a
fraction of its static value, the same with that drag added back, and propmap's (its loads at
V = 0.2 Omega R in axial climb over its static thrust; each set calibrated on UIUC's axial data,
another rig). Last, the shaft: a rig's drag does not load the motor, a rotor force that tilts the
resultant back does, by its work H V. Edgewise at mu = 0.2, in units of the static power, the
published torque rise (k7 mu^2 / CQ_static) less propmap's, beside the published in-plane force's
work (k4 mu^2 / CQ_static) less propmap's (H V / (Q_static Omega)).

    .venv/bin/python tools/gill2019_tare.py     # seconds

A rig's drag is the same for every propeller tested on it; the paper's description of its rig is
not in this repository, so the result bounds the explanation, it does not decide it.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

import propmap as pm
from propmap.cases import (GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, GILL2019_RPM, gill2019_coefficients,
                           multinomial_fit)


def main() -> None:
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv, inc = adv.ravel(), inc.ravel()
    mu = adv * np.sin(inc)
    mean_adv = float(np.sum(mu**2 * adv) / np.sum(mu**2))
    print(f"the grid's mu^2-weighted mean total advance ratio <V / (Omega R)> = {mean_adv:.4f}")
    omega = GILL2019_RPM * math.pi / 30
    for name, c in gill2019_coefficients().items():
        prop, params = pm.load_propeller(name), pm.default_params(name)
        fit = multinomial_fit(prop, params, omega)
        measured = c["k4"] / c["CT_static"]
        model = fit["k4_mu_only"] / fit["CT_static"]
        missing_k4 = (measured - model) * c["CT_static"]  # in the published normalisation
        area = math.pi * prop.radius**2
        drag_area = missing_k4 * area / mean_adv
        print(f"{name:13s} D {2 * prop.radius * 1000:.0f} mm: H slope / CT_static measured {measured:.3f}, "
              f"propmap {model:.3f} (ratio {model / measured:.2f}); missing k4 {missing_k4:.5f}, "
              f"as a rig drag C_D A = {drag_area * 1e4:.1f} cm^2 ({drag_area / area * 100:.1f}% of the disk)")
        lam = 0.2
        published = (c["CT_static"] + c["k1"] * lam + c["k3"] * lam**2) / c["CT_static"]
        added_back = published + drag_area / area * lam**2 / c["CT_static"]
        r = pm.rotor_loads(prop, params, omega, np.array([0.0, lam * omega * prop.radius]), 0.0)
        print(f"{'':13s} axial thrust at lambda_c = {lam}: published {published:.3f} of static, with that drag "
              f"added back {added_back:.3f}; propmap {float(r.thrust[1] / r.thrust[0]):.3f}")
        mu = 0.2
        e = pm.rotor_loads(prop, params, omega, np.array([0.0, mu * omega * prop.radius]), np.array([0.0, math.pi / 2]))
        torque_gap = c["k7"] * mu**2 / c["CQ_static"] - float(e.torque[1] / e.torque[0] - 1)
        work_gap = c["k4"] * mu**2 / c["CQ_static"] - float(e.drag[1] * mu * prop.radius / e.torque[0])
        print(f"{'':13s} edgewise at mu = {mu}, of the static power: the torque rise propmap misses {torque_gap:.3f}, "
              f"the missing in-plane force's work {work_gap:.3f}")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
