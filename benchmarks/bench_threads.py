"""Thread scaling of the batch solver: one thread against all, alternated in one process.

Run:  .venv/bin/python benchmarks/bench_threads.py [--quick]

Propeller apce_8x6 (APC PE0 geometry) with its calibrated set (UIUC vol. 1). Batches of
10^4 and 10^5 random forward-flight points (rpm 3000-12000, V 0-25 m/s, incidence 0-90 deg)
and 10^4 axial ones (incidence 0; issue 20's per-core targets: <= 60 and <= 15 us per point),
each timed with numba's thread count set to 1 and to all cores in turn, 5 rounds (3 with
--quick; the 10^5 batch is left out with --quick). The speed-up is the median over rounds
of t(1 thread) / t(all) of each round's pair, so it holds when the machine's speed drifts;
the 1-minute load average before and after each batch says whether another job shared the
cores (a load near the core count halves what a second thread can give). Writes
benchmarks/results/threads.json atomically and prints it.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numba
import numpy as np

import propmap as pm
from propmap.io.atomic import atomic_write

RPM = np.pi / 30


def main() -> None:
    sys.path.insert(0, str(Path(__file__).parent))
    from bench_solver import cpu_name, points

    quick = "--quick" in sys.argv
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    cores = numba.get_num_threads()
    pm.rotor_loads(prop, params, *points(100, 0, 90, 0), on_failure="flag")  # compile / load the kernel
    out = {"cpu": cpu_name(), "cores": os.cpu_count(), "numba_threads": cores, "propeller": "apce_8x6",
           "params": params.label, "batches": []}
    cases = [("forward", 10_000, 90)] + ([] if quick else [("forward", 100_000, 90)]) + [("axial", 10_000, 0)]
    for kind, n, inc_max in cases:
        om, V, b = points(n, 0, inc_max, 1)
        pairs, loads = [], []
        for _ in range(3 if quick else 5):
            t = {}
            for threads in (1, cores):
                numba.set_num_threads(threads)
                before = os.getloadavg()[0]
                t0 = time.perf_counter()
                pm.rotor_loads(prop, params, om, V, b, on_failure="flag")
                t[threads] = time.perf_counter() - t0
                loads.append((threads, before, os.getloadavg()[0]))
            pairs.append(t)
        numba.set_num_threads(cores)
        one = [p[1] for p in pairs]
        full = [p[cores] for p in pairs]
        out["batches"].append({
            "kind": kind, "points": n, "rounds": len(pairs),
            "one_thread_us_per_point_median": 1e6 * float(np.median(one)) / n,
            "all_threads_us_per_point_median": 1e6 * float(np.median(full)) / n,
            "speedup_median_of_pairs": float(np.median([p[1] / p[cores] for p in pairs])),
            "speedup_min": float(min(p[1] / p[cores] for p in pairs)),
            "load_average_1min": {"min": min(x for _, a, b in loads for x in (a, b)),
                                  "max": max(x for _, a, b in loads for x in (a, b))}})
    path = Path(__file__).parent / "results" / "threads.json"
    with atomic_write(path) as fh:
        json.dump(out, fh, indent=2)
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true")
    parser.parse_args()  # (main reads its flags from sys.argv)
    main()
