"""Everyday-path benchmark: CLI start-up, one rotor_loads call, memory per point.

Run:  .venv/bin/python benchmarks/bench_everyday.py [--million]

Writes benchmarks/results/everyday.json atomically and prints it.

* CLI wall time, whole process, median (and min, max) of 10 runs after one warm-up run:
  ``propmap --help``, ``propmap props``, a single-point ``propmap loads`` (warm kernel
  cache). Baselines timed in the same run: ``python -c pass`` and ``python -c "import
  numba; import numba.np.arraymath"`` (what any numba program pays before its first call),
  so the ratios carry over to other machines.
* One ``rotor_loads`` call (one operating point, paper's and generic sets), median of
  2,000 calls, split into the compiled kernel alone (``_kernel.solve_batch_serial`` on
  prepared arrays) and the Python wrapper around it (input checks, nodes, the result); their
  ratio (issue 20's target: the call within 1.3x of the kernel alone); one ``rotor_wrench`` call
  at the same point (velocity and axis vectors), and its ratio to the ``rotor_loads`` call; one
  step of the example quadrotor with the full model (``vehicle_wrench``: four apce_8x6 rotors at
  about that rate, 10 m/s forward, sinking at 1 m/s, turning; since 2026-11-29), and its ratio to the
  ``rotor_loads`` call (four rotors: about 4 if the step cost only its rotors' solves).
  Each set is timed in :data:`PROCESSES` fresh processes (``--single-call SET``, run by
  :func:`single_call_processes`): the median over processes of each figure, with the
  processes' range of the wrapper and the ratio (each figure is its own median, so the
  medians of the call and the kernel differ from the wrapper's median by a little). One
  process' wrapper came out 10.9-27.3 us in runs minutes apart on a 2-core Intel Xeon VM,
  fresh processes 5.6-14.8 us (2026-11-27), more than any change to the wrapper.
* Memory: bytes per operating point held by a ``RotorLoads`` with and without the
  per-annulus fields (``radial``), tracemalloc peak over 100,000 points (machine-
  independent); the peak resident memory of ``propmap loads --points`` on 100,000 points
  (10^6 with ``--million``; ~1 min on 2 cores).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.core import _kernel
from propmap.core.nodes import _prepared
from propmap.io.atomic import atomic_write

BIN = Path(sys.executable).parent
RUNS = 10
#: fresh processes per parameter set for the single call (:func:`single_call_processes`)
PROCESSES = 5


#: the commands run as on a user's machine, where Python caches the modules' bytecode: an
#: environment with PYTHONDONTWRITEBYTECODE set (this project's build machines) recompiles
#: propmap's 68 modules in every process, 0.16 s of a 2 s `propmap wrench` (2026-11-26)
USER_ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def wall(argv, runs=RUNS):
    """(min, median, max) wall seconds of ``argv`` as a whole process, after one warm-up (which
    writes the bytecode and numba caches), with the environment :data:`USER_ENV`."""
    subprocess.run(argv, capture_output=True, check=True, env=USER_ENV)
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        subprocess.run(argv, capture_output=True, check=True, env=USER_ENV)
        times.append(time.perf_counter() - t)
    return {"min_s": min(times), "median_s": float(np.median(times)), "max_s": max(times)}


def cli_times():
    py = [sys.executable]
    res = {
        "python_-c_pass": wall(py + ["-c", "pass"]),
        "import_numba_and_arraymath": wall(py + ["-c", "import numba; import numba.np.arraymath"]),
        "propmap_--help": wall([str(BIN / "propmap"), "--help"]),
        "propmap_props": wall([str(BIN / "propmap"), "props"]),
        "propmap_loads_single_point": wall([str(BIN / "propmap"), "loads", "apce_8x6", "--rpm", "8000",
                                            "--airspeed", "10", "--incidence-deg", "45"]),
    }
    base = res["import_numba_and_arraymath"]["median_s"]
    res["ratio_single_point_to_numba_import"] = res["propmap_loads_single_point"]["median_s"] / base
    return res


def single_call(params, n=2000):
    """Median seconds of one rotor_loads call and of the kernel alone on the same point."""
    prop = pm.load_propeller("apce_8x6")
    om, V, b = 8000 * math.pi / 30, 10.0, math.radians(45)
    pm.rotor_loads(prop, params, om, V, b)
    nd, model, pk, cam, inflow, empirical, cls = _prepared(prop, params, params.air, pm.DEFAULT_DISCRETIZATION)
    nr = nd.y.size
    args = (np.array([om]), np.array([V * math.sin(b)]), np.array([V * math.cos(b)]), np.zeros(1), nd.rows, nd.azimuth,
            model, pk, cam, inflow, empirical, params.swirl, prop.radius, False, cls, np.empty((_kernel.N_OUT, 1)),
            np.empty((_kernel.N_RAD, 1, nr)), np.empty((_kernel.N_COUNTS, 1), np.int64),
            np.empty((_kernel.N_FLAGS, 1), np.bool_))
    vel, axis = np.array([V * math.sin(b), 0.0, V * math.cos(b)]), np.array([0.0, 0.0, 1.0])  # the same point
    # one step of the example quadrotor (four apce_8x6; body z up), full model: 10 m/s, sinking, turning
    veh = pm.read_vehicle("quadrotor")
    step = (np.array([[V, 0.0, -1.0]]), np.array([[0.1, -0.2, 0.3]]), np.array([[om, 1.02 * om, 0.98 * om, om]]))
    pm.vehicle_wrench(veh, params, *step)
    total, kernel, wrench = [], [], []
    for _ in range(n):  # interleaved, so that drift of the machine's speed hits all alike
        t = time.perf_counter()
        pm.rotor_loads(prop, params, om, V, b)
        total.append(time.perf_counter() - t)
        t = time.perf_counter()
        _kernel.solve_batch_serial(*args)
        kernel.append(time.perf_counter() - t)
        t = time.perf_counter()
        pm.rotor_wrench(prop, params, vel, axis, om)
        wrench.append(time.perf_counter() - t)
    tot, ker, wr = float(np.median(total)), float(np.median(kernel)), float(np.median(wrench))
    # the vehicle step in a loop of its own, with its own rotor_loads calls for the ratio: timed between the calls
    # above, its code and data evicted theirs and raised the wrapper's figure (20-35 -> 32-60 us, 2026-11-29)
    loads, vehicle = [], []
    for _ in range(max(1, n // 4)):
        t = time.perf_counter()
        pm.vehicle_wrench(veh, params, *step)
        vehicle.append(time.perf_counter() - t)
        t = time.perf_counter()
        pm.rotor_loads(prop, params, om, V, b)
        loads.append(time.perf_counter() - t)
    veh_step = float(np.median(vehicle))
    return {"rotor_loads_us_median": 1e6 * tot, "kernel_us_median": 1e6 * ker, "wrapper_us": 1e6 * (tot - ker),
            "ratio_call_to_kernel": tot / ker, "rotor_wrench_us_median": 1e6 * wr, "ratio_wrench_to_loads": wr / tot,
            "vehicle_step_us_median": 1e6 * veh_step, "ratio_vehicle_step_to_loads": veh_step / float(np.median(loads))}


def _single_params(name: str):
    from propmap.io.calibration import generic_params

    return {"paper": pm.preset("gill2017-apc"), "generic": generic_params()}[name]


def single_call_processes(name: str, k: int = PROCESSES) -> dict:
    """:func:`single_call` of the set ``name`` ("paper" or "generic") in ``k`` fresh processes:
    each figure's median over the processes, and the range of the wrapper and the ratio."""
    runs = []
    for _ in range(k):
        res = subprocess.run([sys.executable, __file__, "--single-call", name], capture_output=True, text=True,
                             env=USER_ENV)
        if res.returncode != 0:
            raise SystemExit(f"the single call's process failed:\n{res.stderr}")
        runs.append(json.loads(res.stdout))
    out = {key: float(np.median([r[key] for r in runs])) for key in runs[0]}
    out["processes"] = k
    for key in ("wrapper_us", "ratio_call_to_kernel"):
        out[key + "_range"] = [min(r[key] for r in runs), max(r[key] for r in runs)]
    return out


def bytes_per_point(n=100_000):
    prop, params = pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")
    rng = np.random.default_rng(3)
    om, V, b = rng.uniform(3000, 12000, n) * math.pi / 30, rng.uniform(0, 25, n), np.radians(rng.uniform(0, 90, n))
    pm.rotor_loads(prop, params, om[:50], V[:50], b[:50])
    out = {}
    for radial in (False, True):
        tracemalloc.start()
        r = pm.rotor_loads(prop, params, om, V, b, radial=radial)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        del r
        out[f"radial_{radial}"] = peak / n
    return out


def points_file_peak_rss(n):
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "points.csv"
        rng = np.random.default_rng(5)
        rpm, V, inc = rng.uniform(3000, 12000, n), rng.uniform(0, 25, n), rng.uniform(0, 90, n)
        with src.open("w") as fh:
            fh.write("rpm,airspeed,incidence_deg\n")
            np.savetxt(fh, np.column_stack([rpm, V, inc]), fmt="%.6g", delimiter=",")
        t = time.perf_counter()
        subprocess.run([str(BIN / "propmap"), "loads", "apce_8x6", "--points", str(src), "--out",
                        str(Path(tmp) / "out.csv")], capture_output=True, check=True)
        elapsed = time.perf_counter() - t
    peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # the largest child so far: run first
    return {"points": n, "peak_rss_MiB": peak_kib / 1024, "wall_s": elapsed}


def main() -> None:
    from bench_solver import cpu_name

    # first: ru_maxrss of the children is the largest child so far
    points = points_file_peak_rss(1_000_000 if "--million" in sys.argv else 100_000)
    res = {
        "cpu": cpu_name(),
        "cli": cli_times(),
        "single_call_paper": single_call_processes("paper"),
        "single_call_generic": single_call_processes("generic"),
        "bytes_per_point": bytes_per_point(),
        "loads_points_file": points,
    }
    out = Path(__file__).parent / "results" / "everyday.json"
    with atomic_write(out) as fh:
        json.dump(res, fh, indent=2)
    print(json.dumps(res, indent=2))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--million", action="store_true")
    parser.add_argument("--single-call", metavar="SET", help="one process of the single-call loop (internal)")
    args = parser.parse_args()  # (main reads --million from sys.argv)
    sys.path.insert(0, str(Path(__file__).parent))
    if args.single_call:  # one process of single_call_processes
        print(json.dumps(single_call(_single_params(args.single_call))))
    else:
        main()
