"""Each compiled kernel family's first-call compile time, in one process with an empty cache.

Times the first call of ``rotor_loads`` that needs each kernel, in this order: the loads of a
small batch (the serial kernel, fewer than solver.PARALLEL_MIN_POINTS points, with the annuli's
root solve and the point's body), of a large batch (the parallel kernel, the same body), the
implicit derivatives of a small and a large batch (core/_sensitivity.py), and those of the
linear inflow model (Pitt-Peters, core/_linear_sensitivity.py). apce_8x6 (the APC 8x6E of the
UIUC Propeller Data Site), the generic set. Wall and process CPU seconds per step; the
numbers are those of the machine it runs on (the compile is numba's own passes, then LLVM's,
on one core: they scale with the CPU's speed, not its vector width).

    NUMBA_CACHE_DIR=$(mktemp -d) .venv/bin/python tools/compile_times.py   # about 3 minutes on a 2-core AMD EPYC

An empty ``NUMBA_CACHE_DIR`` is what makes the compile happen: with the in-tree cache warm,
each step takes a second or less. Results: benchmarks/README.md, Compile time.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

import propmap as pm


def main() -> int:
    if not os.environ.get("NUMBA_CACHE_DIR"):
        print("give an empty NUMBA_CACHE_DIR (else the in-tree cache serves the kernels)", file=sys.stderr)
        return 2
    prop = pm.load_propeller("apce_8x6")
    generic = pm.generic_params()
    linear = generic.replace(inflow="pitt-peters")
    rng = np.random.default_rng(0)
    n = 64  # >= solver.PARALLEL_MIN_POINTS: the parallel kernels
    om, V, b = rng.uniform(300.0, 1200.0, n), rng.uniform(0.0, 20.0, n), rng.uniform(0.0, np.pi, n)
    steps = [
        ("loads, serial kernel (and the root solve)", lambda: pm.rotor_loads(prop, generic, om[:4], V[:4], b[:4])),
        ("loads, parallel kernel", lambda: pm.rotor_loads(prop, generic, om, V, b)),
        ("derivatives, serial", lambda: pm.rotor_loads(prop, generic, om[:4], V[:4], b[:4], derivatives=True)),
        ("derivatives, parallel", lambda: pm.rotor_loads(prop, generic, om, V, b, derivatives=True)),
        ("linear inflow derivatives, serial",
         lambda: pm.rotor_loads(prop, linear, om[:4], V[:4], b[:4], derivatives=True)),
        ("linear inflow derivatives, parallel", lambda: pm.rotor_loads(prop, linear, om, V, b, derivatives=True)),
    ]
    total = 0.0
    for name, call in steps:
        t, c = time.perf_counter(), time.process_time()
        call()
        wall = time.perf_counter() - t
        total += wall
        print(f"{name:40s} wall {wall:6.1f} s  CPU {time.process_time() - c:6.1f} s", flush=True)
    print(f"{'all':40s} wall {total:6.1f} s")
    return 0


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    sys.exit(main())
