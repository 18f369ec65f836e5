"""Rebuild src/propmap/data/calibration.json from the bundled UIUC measurements.

Run from the repository root (141 s on the 2-core machine, two worker processes, 2026-11-23;
about 40 minutes before the fits had implicit Jacobians):

    .venv/bin/python tools/calibrate_catalogue.py [--jobs 2] [--balance families] [--swirl] [--work DIR]

``--balance families`` weights every UIUC family alike instead of every propeller (in the
generic set's joint fit, its Reynolds medians and the prior's covariance; measured and not
adopted, docs/validation.md). ``--swirl`` calibrates the model with the swirl option
(RotorOptions.swirl) on every fit: 984 s on the same machine (2026-11-23; the fits
difference the solver, which costs 5x per point with swirl). Either overwrites the shipped
calibration like any run: do it in a scratch copy of the repository, or restore the file
afterwards (docs/models.md, Swirl). ``--work DIR`` keeps each step's results for a rerun.

The procedure (docs/validation.md explains and measures each choice) is hierarchical, over
every catalogue propeller with a static run and J-sweeps, both UIUC volumes:

1. Every propeller alone: the 8 cambered parameters CAMBERED_FIT_RE fitted to all its
   static-run and J-sweep data, free (no prior), from START.
2. ``generic``: each Reynolds term (re_exp_lift, re_exp, alpha_L0_re) at the median of
   the single-propeller fits (the within-propeller Reynolds dependence: across
   propellers, size and Reynolds number are confounded, so a joint fit would let the
   Reynolds terms absorb propeller-to-propeller offsets), and the 5 level parameters
   CAMBERED_FIT fitted jointly to all propellers (fit_loads_joint, each weighted alike).
3. The fits' population prior: the covariance of the single-propeller fits around the
   generic set, and their median rms residual.
4. ``generic_folds``: steps 2-3 without each family (UIUC family code) in turn, so that
   validation predicts every propeller of a family with a generic set and a prior that
   never saw that family: leave-one-family-out, the honest estimate of what a user with a
   propeller of a new family gets.
5. ``propellers``: each propeller's own set: fit_loads on all its data with the default
   parameters and the population prior, from ``generic``.

Data: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255) and the part of
vol. 2 in the repository (Deters, Ananda & Selig, AIAA 2014-2151), as bundled.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from multiprocessing import get_context
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.identify import FitOptions, fit_loads, fit_loads_joint, loads_from_catalogue
from propmap.identify.fit import CAMBERED_FIT, CAMBERED_FIT_RE
from propmap.io.atomic import atomic_write
from propmap.io.catalogue import VOLUME_CITATION, catalogue
from propmap.io.calibration import params_from_si, params_to_si
from propmap.validation import coefficient_errors

OUT = Path("src/propmap/data/calibration.json")
RE_TERMS = ("re_exp_lift", "re_exp", "alpha_L0_re")
#: start of the per-propeller fits (a rounded earlier joint fit; each fit converges from it); the
#: stall blend's sharpness M is not fitted: 12 was chosen among 8, 12, 16, 20 and 40 by
#: leave-one-family-out validation and checks the fits never see (docs/models.md, The blend's sharpness)
START = pm.CamberedParams(cl_alpha=5.5, alpha_L0=math.radians(-5.0), cl_max=1.9, cd_min=0.022, cd2=0.065, M=12.0,
                          re_exp=-0.6, re_exp_lift=0.06, alpha_L0_re=math.radians(-2.0))
#: the joint fits' evaluation limit (they converge in 20-80; a stop at the limit is printed)
JOINT_MAX_NFEV = 150
POPULATION_SOURCE = ("covariance and median rms residual of the 8-parameter fits to each catalogue propeller "
                     "(tools/calibrate_catalogue.py)")


def calibration_names() -> list:
    """Catalogue propellers with a static run and J-sweeps (those the calibration uses)."""
    return sorted(n for n, e in catalogue().items() if e.static_files and e.sweep_files)


def _data(name: str):
    prop = pm.load_propeller(name)
    return loads_from_catalogue(catalogue()[name], prop.diameter), prop


def _worker_init() -> None:
    import numba

    numba.set_num_threads(1)


def _single(name: str, start=START):
    """Step 1: the free 8-parameter fit of one propeller, from ``start``."""
    d, prop = _data(name)
    res = fit_loads(d, prop, base=start, options=FitOptions(names=CAMBERED_FIT_RE, prior=False))
    return name, {"params": params_to_si(res.params), "rms_residual": float(np.sqrt(np.mean(res.residuals ** 2)))}


def _entry(params, rms_ct, rms_cp, n_points, **more):
    return {"params": params_to_si(params), "rms_ct": float(rms_ct), "rms_cp": float(rms_cp),
            "n_points": int(n_points), **more}


def _coverage(datasets) -> dict:
    """What the fitted data covered (io.calibration.coverage): largest J, incidences."""
    J = [float(np.max(d.airspeed / (d.omega / (2 * math.pi) * p.diameter))) for d, p in datasets]
    return {"J_max": max(J), "incidence_deg_max": max(float(np.degrees(np.max(d.incidence))) for d, _ in datasets)}


def _weights(names, balance: str) -> np.ndarray:
    """Each propeller's share of the population statistics, summing to 1: alike
    (``propellers``), or each family's alike, split among its members (``families``)."""
    if balance == "propellers":
        return np.full(len(names), 1.0 / len(names))
    fam = [catalogue()[n].family for n in names]
    size = {f: fam.count(f) for f in fam}
    w = np.array([1.0 / size[f] for f in fam])
    return w / w.sum()


def _weighted_median(x: np.ndarray, w: np.ndarray) -> float:
    """The value below which half of the weight lies (the plain median for equal weights)."""
    order = np.argsort(x)
    cw = np.cumsum(w[order]) - 0.5 * w[order]
    return float(np.interp(0.5 * w.sum(), cw, x[order]))


def _generic(names, single, data, start=START, balance="propellers"):
    """Steps 2-3 on ``names``: the generic set, its population statistics and its in-sample errors.

    Reynolds terms: (weighted) medians of the single-propeller fits; level parameters: joint
    fit from ``start``; the prior's covariance: the (weighted) spread of the single-propeller
    fits around this generic set, sigma_d: their median rms residual. ``balance``: the
    weights (:func:`_weights`).
    """
    w = _weights(names, balance)
    X = np.array([[single[n]["params"][k] for k in CAMBERED_FIT_RE] for n in names])
    re_medians = {k: _weighted_median(X[:, CAMBERED_FIT_RE.index(k)], w) for k in RE_TERMS}
    data = [data[n] for n in names]
    res = fit_loads_joint(data, base=start.replace(**re_medians),
                          weights=None if balance == "propellers" else w * len(names),
                          options=FitOptions(names=CAMBERED_FIT, prior=False, max_nfev=JOINT_MAX_NFEV))
    g = np.array([getattr(res.params, k) for k in CAMBERED_FIT_RE])
    dev = X - g
    # the weighted spread about the generic set; (n - 1) in the denominator for equal weights
    cov = (dev * w[:, None]).T @ dev / (1.0 - np.sum(w ** 2))
    source = POPULATION_SOURCE + ("" if balance == "propellers" else "; every UIUC family weighted alike")
    pop = {"names": list(CAMBERED_FIT_RE), "covariance": cov.tolist(),
           "sigma_data": _weighted_median(np.array([single[n]["rms_residual"] for n in names]), w),
           "re_medians": re_medians, "n_propellers": len(names), "source": source}
    errs = [coefficient_errors(*d, res.params) for d in data]
    return (params_to_si(res.params), pop, float(np.median([e["rms_ct"] for e in errs])),
            float(np.median([e["rms_cp"] for e in errs])), sum(d.n for d, _ in data), bool(res.hit_max_nfev),
            _coverage(data))


def _own(args):
    """Step 5: a propeller's own set, fitted from the generic set with the prior."""
    name, generic, pop = args
    d, prop = _data(name)
    prior = {**pop, "covariance": np.asarray(pop["covariance"])}
    res = fit_loads(d, prop, base=params_from_si(generic), options=FitOptions(population=prior))
    e = coefficient_errors(d, prop, res.params)
    out = _entry(res.params, e["rms_ct"], e["rms_cp"], d.n, fitted=list(res.names), coverage=_coverage([(d, prop)]))
    if res.at_bound:
        out["at_bound"] = list(res.at_bound)
    return name, out


def _load(work, name: str, names):
    """A step's saved result in ``work`` if it is there and was made for ``names``, else None."""
    if work is None or not (work / name).is_file():
        return None
    saved = json.loads((work / name).read_text())
    if saved.get("names") != list(names):
        return None
    print(f"reusing {work / name}", flush=True)
    return saved["result"]


def _save(work, name: str, result) -> None:
    if work is not None:
        with atomic_write(work / name, "w") as fh:
            json.dump({"names": calibration_names(), "result": result}, fh)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2, help="worker processes")
    ap.add_argument("--swirl", action="store_true", help="calibrate with the swirl option on (an experiment)")
    ap.add_argument("--balance", choices=("propellers", "families"), default="propellers",
                    help="weights of the generic set's joint fit, Reynolds medians and prior: every propeller "
                         "alike (default), or every family alike")
    ap.add_argument("--work", type=Path, default=None,
                    help="folder for the steps' results: a rerun reuses those already there (default: none kept)")
    args = ap.parse_args()
    jobs, work = args.jobs, args.work
    start = START.replace(swirl=True) if args.swirl else START
    if work is not None:
        work.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    cat = catalogue()
    names = calibration_names()
    families = sorted({cat[n].family for n in names})
    # workers are spawned: numba's OpenMP layer in this process makes fork() unsafe
    pool = partial(ProcessPoolExecutor, jobs, mp_context=get_context("spawn"), initializer=_worker_init)
    single = _load(work, "single.json", names)
    if single is None:
        with pool() as ex:
            single = {}
            for i, (n, r) in enumerate(ex.map(partial(_single, start=start), names)):
                single[n] = r
                print(f"[1: {i + 1}/{len(names)}] {n}: rms residual {r['rms_residual']:.4f}", flush=True)
        _save(work, "single.json", single)
    # the joint fits run here, one at a time on numba's threads (one full joint fit: about a
    # minute; run in the worker processes, a pair had not finished in 17); the folds start
    # from the full generic set
    data = {n: _data(n) for n in names}
    joint_file = "joint.json" if args.balance == "propellers" else f"joint_{args.balance}.json"
    joint = _load(work, joint_file, names)
    if joint is None:
        gparams, pop, gct, gcp, gn, ghit, gcov = _generic(names, single, data, start=start, balance=args.balance)
        print(f"generic: median rms dCT/CT0 {gct:.4f}, dCP/CP0 {gcp:.4f}; Reynolds medians {pop['re_medians']}",
              flush=True)
        folds = []
        for f in families:
            members = [n for n in names if cat[n].family != f]
            p, fpop, c, cp, n_pts, hit, _ = _generic(members, single, data, start=params_from_si(gparams),
                                                     balance=args.balance)
            folds.append({**_entry(params_from_si(p), c, cp, n_pts), "label": f"generic without {f}",
                          "family": f, "propellers": members, "population": fpop})
            print(f"generic without {f}: median rms dCT/CT0 {c:.4f}{' (evaluation limit)' if hit else ''}",
                  flush=True)
        joint = {"generic": [gparams, pop, gct, gcp, gn, ghit, gcov], "folds": folds}
        _save(work, joint_file, joint)
    gparams, pop, gct, gcp, gn, ghit, gcov = joint["generic"]
    folds = joint["folds"]
    with pool() as ex:
        own = {}
        for i, (n, e) in enumerate(ex.map(_own, [(n, gparams, pop) for n in names])):
            own[n] = e
            print(f"[5: {i + 1}/{len(names)}] {n}: rms dCT/CT0 {e['rms_ct']:.4f}, dCP/CP0 {e['rms_cp']:.4f}"
                  f"{'; at bound: ' + ', '.join(e['at_bound']) if 'at_bound' in e else ''}", flush=True)
    vols = sorted({cat[n].volume for n in names})
    out = {
        "citation": "; ".join(VOLUME_CITATION[v] for v in vols),
        "created_by": "tools/calibrate_catalogue.py (propmap " + pm.__version__ + ")",
        "generic": {**_entry(params_from_si(gparams), gct, gcp, gn), "coverage": gcov,
                    "source": f"Reynolds terms: medians of single-propeller fits; {', '.join(CAMBERED_FIT)} fitted "
                              f"jointly to the bundled UIUC static runs and J-sweeps of all {len(names)} catalogue "
                              "propellers with both (UIUC vol. 1 and 2)"
                              + ("" if args.balance == "propellers" else ", every UIUC family alike")
                              + "; rms_ct, rms_cp: medians over the propellers (in-sample)"},
        "population": pop,
        "single_fits": single,
        "generic_folds": folds,
        "propeller_source": "fit of all of the propeller's bundled UIUC data (default parameters, population "
                            "prior), started from the generic set; rms_ct, rms_cp in-sample",
        "propellers": own,
    }
    with atomic_write(OUT, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    print(f"wrote {OUT} in {time.perf_counter() - t0:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
