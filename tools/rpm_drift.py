"""How the held-out error of the static + lowest-rpm protocol grows with the rotation rate.

Data: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255) and the bundled part of
vol. 2 (Deters, Ananda & Selig, AIAA 2014-2151). Each propeller is fitted as `propmap validate
--all`'s static + lowest protocol fits it (the CLI defaults, from the generic set and prior
without its family), and each held-out rpm group's mean signed CT error (of static CT) is
regressed on ln(rpm / rpm of the lowest sweeps); the same for the generic set without the
family (blind).

    .venv/bin/python tools/rpm_drift.py      # 15-30 s on 2 cores (30 s under another job's load, 2026-12-02)

Prints the median slope over the catalogue and per family: positive where the model's thrust
runs ahead of the measured one as the rpm rises (docs/validation.md, Where the model is still
wrong).
"""

import argparse
import warnings
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pandas as pd

import propmap as pm
from propmap.identify import FitOptions, fit_loads, loads_from_catalogue
from propmap.io.calibration import generic_without, population
from propmap.io.catalogue import catalogue
from propmap.validation.catalogue import _coefficients, rpm_groups


def static_lowest_case(name: str) -> dict:
    """One catalogue propeller as the static + lowest protocol sees it: entry, prop, data, the
    generic set and prior without its family, the static mask, the rpm groups, the training mask
    (static run and lowest sweeps), the measured CT and the mean static CT0."""
    warnings.simplefilter("ignore")  # the catalogue's coverage notes
    entry, prop = catalogue()[name], pm.load_propeller(name)
    data = loads_from_catalogue(entry, prop.diameter)
    generic, pop = generic_without(name)[0], population(without=name)
    static, groups = data.airspeed == 0, rpm_groups(data)
    CT = _coefficients(data, prop, generic.air)[0]
    return dict(entry=entry, prop=prop, data=data, generic=generic, pop=pop, static=static, groups=groups,
                train=static | np.isin(data.group, groups[0]), CT=CT, CT0=CT[static].mean())


def biases(name: str) -> list:
    """(name, family, "fit" or "blind", ln rpm ratio, mean signed dCT / CT0) per held-out rpm group."""
    c = static_lowest_case(name)
    entry, prop, data, generic, groups, CT, CT0 = (c[k] for k in ("entry", "prop", "data", "generic", "groups", "CT",
                                                                   "CT0"))
    fitted = fit_loads(data.subset(c["train"]), prop, base=generic, options=FitOptions(population=c["pop"])).params
    rpm0 = np.mean(data.omega[np.isin(data.group, groups[0])])
    rows = []
    for grp in groups[1:]:
        m = np.isin(data.group, grp)
        for params, kind in ((fitted, "fit"), (generic, "blind")):
            r = pm.rotor_loads(prop, params, data.omega[m], data.airspeed[m], data.incidence[m])
            bias = np.mean((r.CT - CT[m]) / CT0)
            rows.append((name, entry.family, kind, np.log(np.mean(data.omega[m]) / rpm0), bias))
    return rows


def main() -> None:
    names = sorted(n for n, e in catalogue().items() if e.static_files and e.sweep_files)
    with ProcessPoolExecutor(2) as ex:
        df = pd.DataFrame([r for rows in ex.map(biases, names) for r in rows],
                          columns=["name", "family", "kind", "ln_rpm_ratio", "bias"])
    for kind in ("fit", "blind"):
        d = df[df.kind == kind]
        slope = pd.Series({n: np.polyfit(g.ln_rpm_ratio, g.bias, 1)[0] if len(g) > 1 else np.nan
                           for n, g in d.groupby("name")})
        family = d.groupby("name").family.first()
        print(f"{kind}: median slope of the held-out bias against ln(rpm / lowest rpm) {np.nanmedian(slope):+.3f} "
              f"({slope.notna().sum()} propellers); per family (median, count):")
        per = slope.groupby(family).agg(["median", "count"]).sort_values("median")
        print("  " + "; ".join(f"{f} {m:+.3f} ({int(c)})" for f, (m, c) in per.iterrows()))


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
