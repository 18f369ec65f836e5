"""Issues 14 and 15: the Reynolds and Mach numbers of each blade element instead of each annulus.
A measurement, not a model of propmap.

propmap's cambered section takes its Reynolds and Mach corrections (the lift slope's and the
drag's Reynolds exponents, the zero-lift shift, Prandtl-Glauert) once per annulus, at the
azimuth mean of the section's speed, U^2 = (Omega y)^2 + (V sin beta)^2 / 2 + (V cos beta)^2
(docs/models.md). In edgewise flow the advancing blade meets the air faster than that and the
retreating blade slower: with the section's speed of each element, U^2 = (Omega y + V sin(beta)
sin(psi))^2 + (V cos beta)^2, whose azimuth mean is the annulus' value (the induced velocities,
normal and in-plane, left out of both), the advancing side gets the higher lift slope and the
lower drag coefficient that its Reynolds number gives. In axial flow
U_T is the same at every azimuth, so nothing axial changes. Expected from the drag's share in
the H-force (its in-plane part is largest where U_T is, on the advancing side): a smaller
H-force; measured here.

It patches the NumPy reference solver (core/_reference.py, 48 x 16 nodes; the kernel is
untouched): the element and its profile drag recompute the annulus' four section constants at
each node (``_physics.cambered_annulus`` with the node's U^2). It prints, with each catalogue
propeller's own calibrated set, the gill2019 case's quantities (docs/validation.md: Gill &
D'Andrea, Drones 3(4):77, 2019, Appendix A's multinomial fits): the H-force slope fitted as k4 mu
alone over the case's grid, in units of the static thrust, and the thrust and torque rise at mu
= 0.2 edgewise, 6000 rpm; then the NeuroBEM quadrotor's rotor (the example vehicle's lumped
blade, generic set) edgewise at 1500 rad/s; then one axial point of each, which must not move.

    .venv/bin/python tools/element_reynolds_probe.py     # seconds
"""

from __future__ import annotations

import argparse
import math

import numpy as np

import propmap as pm
from propmap.cases import GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, gill2019_coefficients
from propmap.core import _reference as reference
from propmap.core._physics import CAMBERED, cambered_annulus
from propmap.core.nodes import _cambered_args, _nodes

_element, _profile_cd = reference.element, reference.profile_cd
_state: dict = {}


def _constants():
    """The four section constants at each node: U^2 = (Omega y + V_s sin psi)^2 + V_c^2, whose azimuth mean
    is the annulus' U^2 (the induced velocities left out of both)."""
    st = _state
    U2 = (st["wy"] + st["Vs"] * st["sinpsi"]) ** 2 + st["Vc"] ** 2
    cam = st["cam"]
    return cambered_annulus(U2, st["sc"], st["cy2"], cam[4], cam[0], cam[1], cam[2], cam[3] != 0.0, cam[5],
                            cam[6], cam[7])


def element(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, model, pk):
    if _state.get("on") and model == CAMBERED:
        s0, s1, s2, s3 = _constants()
    return _element(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, model, pk)


def profile_cd(UT, UP, theta, s0, s1, s2, s3, model, pk):
    if _state.get("on") and model == CAMBERED:
        s0, s1, s2, s3 = _constants()
    return _profile_cd(UT, UP, theta, s0, s1, s2, s3, model, pk)


reference.element, reference.profile_cd = element, profile_cd


def loads(prop, p, omega, V, incidence, per_element):
    """(T, D, Q) [N, N, N m] of the reference solver, the section constants per annulus or per element."""
    air = p.air
    nd = _nodes(prop, 48, 16, air, p)
    V, incidence = np.asarray(V, float), np.asarray(incidence, float)
    omega = np.full(V.shape, float(omega))
    Vc = V * np.cos(incidence)
    _state.update(on=per_element, Vc=Vc[:, None, None], sc=nd.sc[None, :, None], cy2=nd.cy2[None, :, None],
                  cam=_cambered_args(p, air), wy=omega[:, None, None] * nd.y[None, :, None],
                  Vs=(V * np.sin(incidence))[:, None, None], sinpsi=nd.sinpsi[None, None, : nd.sinpsi.size // 2])
    T, D, Q, _, converged = reference.solve_reference(omega, V * np.sin(incidence), Vc, nd, p, air)
    if not converged.all():
        raise RuntimeError("the reference solver did not converge")
    return T, D, Q


def main() -> None:
    print("Section constants per annulus -> per element (the reference solver, 48 x 16 nodes)")
    print("gill2019 (6000 rpm, own calibrated set): H slope k4/CT_static (mu only); thrust and torque rise at mu = 0.2")
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv = np.concatenate([[0.0], adv.ravel(), [0.2, 0.1]])
    inc = np.concatenate([[0.0], inc.ravel(), [math.pi / 2, 0.0]])
    mu = adv * np.sin(inc)
    for name, c in gill2019_coefficients().items():
        prop, p = pm.load_propeller(name), pm.default_params(name)
        omega = 6000 * math.pi / 30
        row, axial = [], []
        for per_element in (False, True):
            T, D, Q = loads(prop, p, omega, adv * omega * prop.radius, inc, per_element)
            k4 = np.linalg.lstsq(mu[1:-2, None], D[1:-2], rcond=None)[0][0]  # D = k4 mu (the normalisation cancels)
            row.append((k4 / T[0], T[-2] / T[0] - 1, Q[-2] / Q[0] - 1))
            axial.append((T[-1], Q[-1]))
        meas = (c["k4"] / c["CT_static"], c["k2"] * 0.04 / c["CT_static"], c["k7"] * 0.04 / c["CQ_static"])
        cells = [f"{lab} {r0 / m:.2f} -> {r1 / m:.2f} ({m:.3f} measured)"
                 for lab, m, r0, r1 in zip(("H", "dT", "dQ"), meas, row[0], row[1])]
        moved = max(abs(axial[1][k] / axial[0][k] - 1) for k in range(2))
        print(f"  {name:13s} ratio to measured, per annulus -> per element: " + "; ".join(cells)
              + f"; axial (J-like 0.1) moved {moved:.1e}")
    veh = pm.read_vehicle(pm.__path__[0] + "/data/examples/neurobem_quadrotor.toml")
    prop, p = veh.rotors[0].propeller, pm.generic_params()
    Vs = np.array([3.0, 6.0, 9.0, 12.0])
    T0, D0, _ = loads(prop, p, 1500.0, Vs, np.full(4, math.pi / 2), False)
    T1, D1, _ = loads(prop, p, 1500.0, Vs, np.full(4, math.pi / 2), True)
    print("NeuroBEM rotor, 1500 rad/s, generic set, edgewise at 3 / 6 / 9 / 12 m/s: thrust "
          + " ".join(f"{t:+.2%}" for t in T1 / T0 - 1) + "; H-force " + " ".join(f"{d:+.2%}" for d in D1 / D0 - 1))


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
