"""Issue 15: would a population aeroelastic washout, a nose-down blade-angle change that grows
with the dynamic pressure, help blind prediction on propellers of new families?

dtheta = -K Z at every operating point, with Z one of (tip = Omega R / 100 m/s, AR = R / c75 / 6):
tip^2 (a blade twisted by its aerodynamic moment against a torsional stiffness, W. Johnson,
Helicopter Theory, 1980, Ch. 9), tip^2 AR, tip^2 AR^2 (the twist of a thin plate of fixed
thickness ratio grows with the square of its aspect ratio), tip^2 R / 0.1 m and tip^2 AR^2 R / 0.1 m;
K fitted to the blind sweep errors of all propellers outside the held-out one's family (least
squares, linearised: the CT change of a -0.5 deg collective step per point), then applied to the
family: leave-one-family-out, as `propmap validate --all`'s blind protocol (the generic set without
the propeller's family, UIUC Propeller Data Site vol. 1 and 2; error in % of static CT over the
sweep points).

    .venv/bin/python tools/blind_washout.py        # ~10 s with the kernel cache warm

Findings (2026-11-25): docs/validation.md, "What the blind error follows".
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from blind_bias import blind_cases  # tools/blind_bias.py: the propellers and their blind sets

from propmap.core.solver import rotor_loads

STEP = math.radians(0.5)
LAWS = ("none", "tip2", "tip2_ar", "tip2_ar2", "tip2_R", "tip2_ar2_R")


def _law(p: dict, kind: str) -> np.ndarray:
    tip = p["omega"] * p["R"] / 100.0
    ar = p["R"] / p["c75"] / 6.0
    return {"none": 0.0 * tip, "tip2": tip**2, "tip2_ar": tip**2 * ar, "tip2_ar2": tip**2 * ar**2,
            "tip2_R": tip**2 * p["R"] / 0.1, "tip2_ar2_R": tip**2 * ar**2 * p["R"] / 0.1}[kind]


def compute() -> dict:
    out = {}
    for name, e, prop, data, generic, label, CT, _, static, air in blind_cases():
        CT0 = float(np.mean(CT[static]))
        r0 = rotor_loads(prop, generic, data.omega, data.airspeed, data.incidence, air=air)
        r1 = rotor_loads(prop, generic.replace(collective=generic.collective - STEP), data.omega, data.airspeed,
                         data.incidence, air=air)
        sweep = ~static
        out[name] = {"volume": e.volume, "fold": label, "error": ((r0.CT - CT) / CT0)[sweep],
                     "slope": ((r1.CT - r0.CT) / CT0 / STEP)[sweep], "omega": data.omega[sweep],
                     "R": prop.radius, "c75": float(np.interp(0.75 * prop.radius, prop.r, prop.chord))}
    return out


def main() -> None:
    d = compute()
    folds = sorted({p["fold"] for p in d.values()})
    print("law          K median [deg]  blind CT rms, % of static CT: vol. 1 median / p90 / worst   vol. 2")
    for kind in LAWS:
        rms, ks = {1: [], 2: []}, []
        for fold in folds:
            num = den = 0.0
            for p in d.values():
                if p["fold"] != fold:
                    sz = p["slope"] * _law(p, kind)
                    num += float(np.sum(p["error"] * sz))
                    den += float(np.sum(sz * sz))
            k = -num / den if den > 0 else 0.0
            ks.append(k)
            for p in d.values():
                if p["fold"] == fold:
                    e = p["error"] + p["slope"] * k * _law(p, kind)
                    rms[p["volume"]].append(float(np.sqrt(np.mean(e * e))))
        q = [" / ".join(f"{100 * x:.1f}" for x in np.percentile(rms[v], [50, 90, 100])) for v in (1, 2)]
        print(f"{kind:12s} {math.degrees(float(np.median(ks))):+6.2f}          {q[0]:>24}   {q[1]}")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
