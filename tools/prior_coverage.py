"""Do a fit's 95% intervals under the population prior hold 95% of the truth?

Synthetic propellers are drawn from the population prior itself (the generic set's values plus
the population covariance's Cholesky factor times standard normal draws, cut at the fit's
bounds), so the prior is exactly right on average and only the interval's construction is on
trial. Each draw's loads are computed on the APC 8x6E of the catalogue (rotor_loads, the draw's
set) with relative noise of a given level on thrust and torque (and the same level times the
in-plane force's rms, additive, on it) and fitted as ``propmap fit loads`` fits them (the CLI
defaults: fit_loads with the generic set as base and the population prior). Two designs:

* ``tunnel``: 75 points, 5000/7000/9000 rpm, 0-16 m/s at incidences 0-150 deg every 30 deg
  and the static ones (the 8 parameters and the flapping under the prior);
* ``static``: a static run of 12 points at 3000-10000 rpm (the data's leading directions).

For every parameter it counts how often the reported 95% interval holds the draw's value
(Wilson's binomial 95% interval of that fraction beside it; a fraction well below 0.95 means
intervals too narrow) and gives the median ratio of the interval's half-width to the data-only
one.

    .venv/bin/python tools/prior_coverage.py tunnel 0.003 24   # level, draws; about 10 s with the kernel cache warm
    .venv/bin/python tools/prior_coverage.py static 0.003 40

Findings (2026-11-28): docs/identification.md, "Intervals under the prior".
"""

from __future__ import annotations

import argparse
import math
import os
import tempfile
import warnings
from concurrent.futures import ProcessPoolExecutor

import numpy as np


def _design(kind):
    rows = []
    if kind == "tunnel":
        for inc in range(0, 151, 30):
            for V in (0.0, 4.0, 8.0, 12.0, 16.0):
                if V == 0.0 and inc > 0:
                    continue
                rows += [(rpm, V, inc) for rpm in (5000.0, 7000.0, 9000.0)]
    elif kind == "static":
        rows = [(rpm, 0.0, 0.0) for rpm in np.linspace(3000.0, 10000.0, 12)]
    else:
        raise SystemExit(f"design must be tunnel or static, not {kind!r}")
    return np.array(rows, float)


def _one(args):
    kind, level, seed = args
    warnings.simplefilter("ignore")
    import propmap as pm
    from propmap.identify import fit_loads
    from propmap.identify.load_data import LoadData
    from propmap.identify.options import ALL_BOUNDS
    from propmap.io.calibration import population

    pop = population()
    names = pop["names"]
    base = pm.generic_params()
    rng = np.random.default_rng(seed)
    mu = np.array([getattr(base, n) for n in names])
    chol = np.linalg.cholesky(np.asarray(pop["covariance"], float))
    lb, ub = np.array([ALL_BOUNDS[n][0] for n in names]), np.array([ALL_BOUNDS[n][1] for n in names])
    while True:  # the prior cut at the bounds (a third of its cd_min is below 0.002)
        x = mu + chol @ rng.standard_normal(len(names))
        if np.all((x > lb) & (x < ub)):
            break
    truth = base.replace(**dict(zip(names, x)))
    prop = pm.load_propeller("apce_8x6")
    d = _design(kind)
    omega, V, inc = d[:, 0] * math.pi / 30.0, d[:, 1], np.radians(d[:, 2])
    r = pm.rotor_loads(prop, truth, omega, V, inc)
    measured = {"thrust": r.thrust * (1 + level * rng.standard_normal(omega.size)),
                "torque": r.torque * (1 + level * rng.standard_normal(omega.size))}
    if kind == "tunnel":
        measured["drag"] = r.drag + level * np.sqrt(np.mean(r.drag**2)) * rng.standard_normal(omega.size)
    data = LoadData(omega, V, inc, measured, np.array([f"inc{v:.0f}" for v in d[:, 2]]), "synthetic")
    res = fit_loads(data, prop)
    idf = res.identifiability
    out = {}
    for k, n in enumerate(names):
        i = list(res.names).index(n)
        lo, hi = idf.ci95[i]
        sd, sdd = idf.std_error[i], (idf.std_error_data[i] if idf.std_error_data is not None else np.nan)
        held = None if np.isnan(lo) else bool(lo <= x[k] <= hi)  # (None: the fit held it at a bound)
        out[n] = (held, float(sd / sdd) if sdd and np.isfinite(sdd) else np.nan)
    return out, "directions" in res.extra


def _wilson(k, n):
    z = 1.96
    p = k / n
    c = (p + z * z / (2 * n)) / (1 + z * z / n)
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return c - h, c + h


def main(kind: str, level: float, n: int) -> None:
    os.environ.setdefault("NUMBA_CACHE_DIR", os.path.join(tempfile.gettempdir(), "propmap-numba"))
    with ProcessPoolExecutor(2) as ex:
        runs, along = zip(*ex.map(_one, [(kind, level, 1000 + s) for s in range(n)]))
    print(f"design {kind}, noise {level:g}, {n} propellers drawn from the population prior, "
          f"{sum(along)} fitted along the data's directions")
    print("parameter       held    (Wilson 95%)      median interval / data-only   (held at a bound)")
    total = m = 0
    for name in runs[0]:
        seen = [r[name][0] for r in runs if r[name][0] is not None]
        k, c = sum(seen), len(seen)
        total, m = total + k, m + c
        lo, hi = _wilson(k, c)
        ratio = np.nanmedian([r[name][1] for r in runs])
        print(f"{name:14s} {k:3d}/{c:<3d} ({lo:.2f}-{hi:.2f})   {ratio:.3g}   ({n - c})")
    lo, hi = _wilson(total, m)
    print(f"{'all':14s} {total:3d}/{m:<3d} ({lo:.2f}-{hi:.2f})")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("design", choices=("tunnel", "static"))
    parser.add_argument("level", type=float, help="relative noise level, e.g. 0.003")
    parser.add_argument("draws", type=int, help="propellers drawn from the prior")
    a = parser.parse_args()
    main(a.design, a.level, a.draws)
