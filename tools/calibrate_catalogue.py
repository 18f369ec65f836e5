"""Rebuild src/propmap/data/calibration.json from the bundled UIUC measurements.

Run from the repository root (about 10 minutes on a 2-core machine):

    .venv/bin/python tools/calibrate_catalogue.py

The procedure (docs/validation.md explains and measures each choice) is hierarchical:

1. Every catalogue propeller alone: the 8 cambered parameters CAMBERED_FIT_RE fitted to
   all its static-run and J-sweep data, free (no prior), from START.
2. ``generic``: each Reynolds term (re_exp_lift, re_exp, alpha_L0_re) at the median of
   the single-propeller fits (the within-propeller Reynolds dependence: across
   propellers, size and Reynolds number are confounded, so a joint fit would let the
   Reynolds terms absorb propeller-to-propeller offsets; measured, static + lowest-rpm
   sweep calibration 4.7% -> 3.3% median, docs/identification.md), and the 5 level
   parameters CAMBERED_FIT fitted jointly to all propellers (fit_loads_joint, each
   weighted alike).
3. The fits' population prior: the covariance of the single-propeller fits around the
   generic set, and their median rms residual.
4. ``generic_folds``: steps 2-3 on each half of the catalogue (propellers alternately by
   name), so that validation predicts a propeller with a generic set and a prior that
   never saw it.
5. ``propellers``: each propeller's own set: fit_loads on all its data with the default
   parameters and the population prior, from ``generic``.

Data: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255), as bundled.
"""

from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.identify import FitOptions, fit_loads, fit_loads_joint, loads_from_catalogue
from propmap.identify.fit import CAMBERED_FIT, CAMBERED_FIT_RE
from propmap.io.atomic import atomic_write
from propmap.io.catalogue import UIUC_CITATION, catalogue
from propmap.io.calibration import params_to_si
from propmap.validation import coefficient_errors

OUT = Path("src/propmap/data/calibration.json")
RE_TERMS = ("re_exp_lift", "re_exp", "alpha_L0_re")
#: start of the per-propeller fits (a rounded earlier joint fit; each fit converges from it)
START = pm.CamberedParams(cl_alpha=5.5, alpha_L0=math.radians(-5.0), cl_max=1.9, cd_min=0.022, cd2=0.065,
                          re_exp=-0.6, re_exp_lift=0.06, alpha_L0_re=math.radians(-2.0))
#: the joint fits' evaluation limit (they converge in 20-80; a stop at the limit is printed)
JOINT_MAX_NFEV = 150
POPULATION_SOURCE = ("covariance and median rms residual of the 8-parameter fits to each catalogue propeller "
                     "(tools/calibrate_catalogue.py)")


def _entry(params, rms_ct, rms_cp, n_points, **more):
    return {"params": params_to_si(params), "rms_ct": float(rms_ct), "rms_cp": float(rms_cp),
            "n_points": int(n_points), **more}


def _coverage(datasets) -> dict:
    """What the fitted data covered (io.calibration.coverage): largest J, incidences."""
    J = [float(np.max(d.airspeed / (d.omega / (2 * math.pi) * p.diameter))) for d, p in datasets]
    return {"J_max": max(J), "incidence_deg_max": max(float(np.degrees(np.max(d.incidence))) for d, _ in datasets)}


def _generic(data: dict, single: dict, names: list):
    """The generic set of ``names`` and its population statistics (the fits' prior).

    Reynolds terms: medians of the single-propeller fits; level parameters: joint fit; the
    prior's covariance: the spread of the single-propeller fits around this generic set
    (its mean), sigma_d: their median rms residual.
    """
    X = np.array([[getattr(single[n]["params"], k) for k in CAMBERED_FIT_RE] for n in names])
    re_medians = {k: float(np.median(X[:, CAMBERED_FIT_RE.index(k)])) for k in RE_TERMS}
    res = fit_loads_joint([data[n] for n in names], base=START.replace(**re_medians),
                          options=FitOptions(names=CAMBERED_FIT, prior=False, max_nfev=JOINT_MAX_NFEV))
    if res.hit_max_nfev:
        print(f"WARNING: the joint fit of {len(names)} propellers stopped at its evaluation limit", flush=True)
    g = np.array([getattr(res.params, k) for k in CAMBERED_FIT_RE])
    dev = X - g
    pop = {"names": list(CAMBERED_FIT_RE), "covariance": (dev.T @ dev / (len(names) - 1)).tolist(),
           "sigma_data": float(np.median([single[n]["rms_residual"] for n in names])),
           "re_medians": re_medians, "n_propellers": len(names), "source": POPULATION_SOURCE}
    errs = [coefficient_errors(*data[n], res.params) for n in names]
    return res, pop, float(np.median([e["rms_ct"] for e in errs])), float(np.median([e["rms_cp"] for e in errs]))


def main() -> None:
    t0 = time.perf_counter()
    names = sorted(n for n, e in catalogue().items() if e.static_files or e.sweep_files)
    data = {}
    for n in names:
        prop = pm.load_propeller(n)
        data[n] = (loads_from_catalogue(catalogue()[n], prop.diameter), prop)

    single = {}
    for i, n in enumerate(names):
        res = fit_loads(*data[n], base=START, options=FitOptions(names=CAMBERED_FIT_RE, prior=False))
        single[n] = {"params": res.params, "rms_residual": float(np.sqrt(np.mean(res.residuals ** 2)))}
        print(f"[1: {i + 1}/{len(names)}] {n}: rms residual {single[n]['rms_residual']:.4f}", flush=True)
    generic, pop, gct, gcp = _generic(data, single, names)
    print(f"population: sigma_data {pop['sigma_data']:.4f}, Reynolds medians {pop['re_medians']}", flush=True)
    print(f"generic: {generic.nfev} evaluations; median rms dCT/CT0 {gct:.4f}, dCP/CP0 {gcp:.4f}", flush=True)
    out = {
        "citation": UIUC_CITATION,
        "created_by": "tools/calibrate_catalogue.py (propmap " + pm.__version__ + ")",
        "generic": _entry(generic.params, gct, gcp, sum(data[n][0].n for n in names),
                          coverage=_coverage([data[n] for n in names]),
                          source=f"Reynolds terms: medians of single-propeller fits; {', '.join(CAMBERED_FIT)} "
                                 f"fitted jointly to the bundled UIUC static runs and J-sweeps of all {len(names)} "
                                 "catalogue propellers; rms_ct, rms_cp: medians over the propellers (in-sample)"),
        "population": pop,
        "generic_folds": [],
        "propeller_source": "fit of all of the propeller's bundled UIUC data (default parameters, population "
                            "prior), started from the generic set; rms_ct, rms_cp in-sample",
        "propellers": {},
    }
    for k in range(2):
        fold = names[k::2]
        res, fpop, c, p = _generic(data, single, fold)
        out["generic_folds"].append(_entry(res.params, c, p, sum(data[n][0].n for n in fold), propellers=fold,
                                           population=fpop))
        print(f"generic fold {k}: median rms dCT/CT0 {c:.4f}, dCP/CP0 {p:.4f}", flush=True)
    prior = {**pop, "covariance": np.asarray(pop["covariance"])}
    for i, n in enumerate(names):
        d, prop = data[n]
        res = fit_loads(d, prop, base=generic.params, options=FitOptions(population=prior))
        e = coefficient_errors(d, prop, res.params)
        out["propellers"][n] = _entry(res.params, e["rms_ct"], e["rms_cp"], d.n, fitted=list(res.names),
                                      coverage=_coverage([data[n]]))
        if res.at_bound:
            out["propellers"][n]["at_bound"] = list(res.at_bound)
        print(f"[5: {i + 1}/{len(names)}] {n}: rms dCT/CT0 {e['rms_ct']:.4f}, dCP/CP0 {e['rms_cp']:.4f}"
              f"{'; at bound: ' + ', '.join(res.at_bound) if res.at_bound else ''}", flush=True)
    with atomic_write(OUT, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    print(f"wrote {OUT} in {time.perf_counter() - t0:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
