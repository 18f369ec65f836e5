"""Blade count: does the same section predict the same blade on 2-, 3- and 4-blade hubs?

Data: UIUC Propeller Data Site vol. 2 (Deters, Ananda & Selig, AIAA 2014-2151), the NR640
5 in 15 deg and DA4022 5 in blades on 2-, 3- and 4-blade hubs (the catalogue's
``nr640_5_15deg``, ``_3b``, ``_4b`` and ``da4022_5x3.75``, ``_3b``, ``_4b``).

    .venv/bin/python tools/blade_count.py      # 5-10 s with the kernels compiled (2 cores; 10 s under load)

For each blade, the cambered model is fitted (CLI defaults) to all of the 2-blade
propeller's data; that set predicts the 3- and 4-blade hubs' J-sweeps (rms and mean of
dCT / static CT, %). Then one parameter, a collective offset, is fitted to each hub's
static run alone (thrust and torque, under the population prior; the rest of the 2-blade set
kept) and the sweeps predicted again, with the static run's own thrust error left; and to
the sweeps alone, for comparison: a hub that seats its blades at another angle would ask for
the same offset from both. Last, the same with swirl (``RotorOptions.swirl``): the 2-blade
fit from the generic set with swirl on, and its predictions of the other hubs (most of the
time: swirl's solves cost about 5x). Prints the numbers of docs/validation.md, "Blade
count", and docs/models.md, "Swirl".
"""

from __future__ import annotations

import argparse
import math
import warnings

import numpy as np

import propmap as pm
from propmap.core.air import Air
from propmap.identify import FitOptions, fit_loads, loads_from_catalogue
from propmap.identify.data import _loads_from_runs
from propmap.io.calibration import generic_params

BLADES = ("nr640_5_15deg", "da4022_5x3.75")


def static_bias(prop, params, entry) -> float:
    """Mean of (CT_model - CT_measured) / static CT over the static runs [%]."""
    errs, cts = [], []
    for run in entry.static_runs():
        n = np.asarray(run.rpm) / 60.0
        loads = pm.rotor_loads(prop, params, 2 * math.pi * n, 0.0, 0.0)
        errs.extend(loads.thrust / (params.air.rho * n**2 * prop.diameter**4) - run.CT)
        cts.extend(run.CT)
    return 100 * float(np.mean(errs) / np.mean(cts))


def sweep_errors(prop, params, entry) -> tuple[float, float]:
    """rms and mean of (CT_model - CT_measured) / static CT over the sweeps [%]."""
    ct0 = float(np.mean(np.concatenate([r.CT for r in entry.static_runs()])))
    errs = []
    for sw in entry.sweeps():
        n = sw.rpm / 60.0
        loads = pm.rotor_loads(prop, params, 2 * math.pi * n, sw.J * n * prop.diameter, 0.0)
        errs.extend(loads.thrust / (params.air.rho * n**2 * prop.diameter**4) - sw.CT)
    e = np.asarray(errs) / ct0
    return 100 * float(np.sqrt(np.mean(e**2))), 100 * float(np.mean(e))


def main() -> None:
    warnings.simplefilter("ignore")  # the fits' coverage notes
    cat = pm.catalogue()
    for blade in BLADES:
        prop2 = pm.load_propeller(blade)
        two = fit_loads(loads_from_catalogue(cat[blade], prop2.diameter), prop2).params
        for hub in ("_3b", "_4b"):
            entry = cat[blade + hub]
            prop = pm.load_propeller(blade + hub)
            static = _loads_from_runs(entry.static_runs(), [], prop.diameter, Air(), entry.name, entry.name)
            sweeps = _loads_from_runs([], entry.sweeps(), prop.diameter, Air(), entry.name, entry.name)
            opts = FitOptions(names=("collective",))
            off = fit_loads(static, prop, base=two, options=opts).params
            off_sw = fit_loads(sweeps, prop, base=two, options=opts).params
            b, a = sweep_errors(prop, two, entry), sweep_errors(prop, off, entry)
            print(f"{entry.name:<18} {prop.n_blades} blades: the 2-blade set {b[0]:4.1f}% (mean {b[1]:+.1f}%); "
                  f"+ a collective from the static run ({math.degrees(off.collective):+.2f} deg) {a[0]:4.1f}% "
                  f"(mean {a[1]:+.1f}%), static CT then {static_bias(prop, off, entry):+.1f}%; a collective from the "
                  f"sweeps {math.degrees(off_sw.collective):+.2f} deg")
    for swirl in (False, True):
        base = generic_params().replace(swirl=swirl)
        for blade in BLADES:
            prop2 = pm.load_propeller(blade)
            two = fit_loads(loads_from_catalogue(cat[blade], prop2.diameter), prop2, base=base).params
            own = sweep_errors(prop2, two, cat[blade])
            line = f"swirl {'on ' if swirl else 'off'} {blade:<16} 2 blades (fitted) {own[0]:4.1f}%"
            for hub in ("_3b", "_4b"):
                entry = cat[blade + hub]
                prop = pm.load_propeller(blade + hub)
                e = sweep_errors(prop, two, entry)
                line += (f"; {prop.n_blades} blades {e[0]:4.1f}% (mean {e[1]:+.1f}%), "
                         f"static {static_bias(prop, two, entry):+.1f}%")
            print(line)


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
