"""Issue 15: can a fit of the static run and the lowest-rpm sweeps learn a propeller's own washout?

Each propeller is fitted as `propmap validate --all`'s static + lowest protocol fits it (the CLI
defaults, from the generic set and prior without its family; UIUC Propeller Data Site vol. 1,
Brandt & Selig AIAA 2011-1255, and the bundled part of vol. 2, Deters, Ananda & Selig AIAA
2014-2151), with a blade-angle change -K Z held at each K of a grid (the per-point collective of
`rotor_loads`), Z one of

* ``omega``: (Omega R / 100 m/s)^2, the washout of a blade twisted by its aerodynamic moment
  against a torsional stiffness (W. Johnson, Helicopter Theory, 1980, Ch. 9);
* ``airspeed``: (V / 10 m/s)^2, a loss that grows with the tunnel speed and leaves the static
  run alone.

For every K it records the training objective (data + prior) and the held-out rms CT error (% of
static CT over the other sweeps). "chosen" takes each propeller's K of least training objective
(what a fit freeing K would find, to the grid's resolution), "oracle" the K of least held-out
error (not available to a user: the ceiling), "fixed" one K for every propeller.

    .venv/bin/python tools/washout_fit.py omega      # about 150 s on 2 cores
    .venv/bin/python tools/washout_fit.py airspeed
    .venv/bin/python tools/washout_fit.py omega --hold-reynolds

``--hold-reynolds`` fits with the Reynolds terms (re_exp_lift, re_exp, alpha_L0_re) held at the
generic set's values, as the fit's own rule does for a static run spanning less than 1.5x in rpm
(``identify.fit.STATIC_RPM_SPAN``, set to infinity in the workers), so that the static run's rise
of thrust with rpm is carried by K alone; its grid adds K = -1 and -0.5 deg (a blade that
untwists). "K = 0" is then the fit without the Reynolds terms, not the shipped one.

Findings (2026-11-26, --hold-reynolds 2026-11-28): docs/validation.md, "Flexible and
thin-section propellers".
"""

from __future__ import annotations

import argparse
import dataclasses
import math
from concurrent.futures import ProcessPoolExecutor
from functools import partial

import numpy as np

import propmap as pm
from rpm_drift import static_lowest_case  # tools/rpm_drift.py: the protocol's case of one propeller

import propmap.identify.fit as fit_module
from propmap.identify import FitOptions, fit_loads
from propmap.identify.engine import _objective
from propmap.io.catalogue import catalogue

K_DEG = (0.0, 0.5, 1.0, 2.0, 3.0, 5.0)  # blade-angle change at Z = 1 [deg]
K_DEG_HELD = (-1.0, -0.5) + K_DEG  # with the Reynolds terms held


def _z(data, prop, law: str) -> np.ndarray:
    if law == "omega":
        return (data.omega * prop.radius / 100.0) ** 2
    return (data.airspeed / 10.0) ** 2


def grid(name: str, law: str, hold_reynolds: bool = False) -> tuple:
    """(volume, [(K, training objective, held-out rms dCT / CT0)] for K in the grid)."""
    if hold_reynolds:  # (a worker process of its own: the rule's span, never restored, is this run's)
        fit_module.STATIC_RPM_SPAN = math.inf
    c = static_lowest_case(name)
    entry, prop, data, generic, train, CT, CT0 = (c[k] for k in ("entry", "prop", "data", "generic", "train", "CT",
                                                                  "CT0"))
    pop, z = c["pop"], _z(data, prop, law)
    out = []
    for K in K_DEG_HELD if hold_reynolds else K_DEG:
        coll = -math.radians(K) * z
        res = fit_loads(dataclasses.replace(data, collective=coll).subset(train), prop, base=generic,
                        options=FitOptions(population=pop))
        r = pm.rotor_loads(prop, res.params, data.omega[~train], data.airspeed[~train], data.incidence[~train],
                           collective=coll[~train])
        out.append((K, _objective(res), float(np.sqrt(np.mean(((r.CT - CT[~train]) / CT0) ** 2)))))
    return entry.volume, out


def _stats(v) -> str:
    v = 100 * np.asarray(v)
    return f"{np.median(v):.1f} / {np.percentile(v, 90):.1f} / {v.max():.1f}%"


def main(law: str, hold_reynolds: bool = False) -> None:
    names = sorted(n for n, e in catalogue().items() if e.static_files and e.sweep_files)
    with ProcessPoolExecutor(2) as ex:
        rows = list(ex.map(partial(grid, law=law, hold_reynolds=hold_reynolds), names))
    grid_deg = K_DEG_HELD if hold_reynolds else K_DEG
    print(f"washout law {law}{', Reynolds terms held' if hold_reynolds else ''}: held-out CT rms median / 90th "
          "percentile / worst (static + lowest)")
    for volume in (1, 2):
        errs = np.array([[e for _, _, e in out] for v, out in rows if v == volume])
        cost = np.array([[c for _, c, _ in out] for v, out in rows if v == volume])
        best = np.array(grid_deg)[cost.argmin(axis=1)]
        chosen = errs[np.arange(len(errs)), cost.argmin(axis=1)]
        print(f"vol. {volume} ({len(errs)}): K = 0 {_stats(errs[:, grid_deg.index(0.0)])}; chosen {_stats(chosen)} "
              f"(K > 0 for {np.mean(best > 0):.0%}, < 0 for {np.mean(best < 0):.0%}); oracle "
              f"{_stats(errs.min(axis=1))}")
        if hold_reynolds:
            nonneg = np.array(grid_deg) >= 0
            pick = cost[:, nonneg].argmin(axis=1)
            print(f"  chosen among K >= 0: {_stats(errs[:, nonneg][np.arange(len(errs)), pick])}")
        print("  fixed: " + "; ".join(f"K {K:g} deg {_stats(errs[:, j])}" for j, K in enumerate(grid_deg)))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("law", nargs="?", choices=("omega", "airspeed"), default="omega")
    parser.add_argument("--hold-reynolds", action="store_true", help="the Reynolds terms held at the generic set's")
    a = parser.parse_args()
    main(a.law, a.hold_reynolds)
