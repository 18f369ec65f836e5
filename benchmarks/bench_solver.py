"""Solver benchmark: accuracy of the default discretization and speed, both section models.

Run:  make bench        (or .venv/bin/python benchmarks/bench_solver.py [--quick])

Propeller apce_8x6 (APC PE0 geometry); parameters gill2017-apc (Gill & D'Andrea 2017
Table I) and the shipped generic cambered set (docs/models.md). Prints a report and writes
benchmarks/results/solver.json atomically.

* Accuracy: default Discretization vs a converged reference (1024 radial x 32 azimuth
  nodes) on random points over rpm 3000-12000, V 0-25 m/s, incidence 0-90 deg; descent
  (90-180 deg) reported separately. T and Q: relative error, and error relative to the
  hover value at the same rpm (the pure relative error is meaningless where T or Q
  cross zero in windmilling). D: relative to the largest D in the set.
* Speed: batch of 10,000 points (numba, all cores) and one point after warm-up, beside
  the straightforward vectorised NumPy implementation (src/propmap/core/_reference.py)
  timed in the same run; the paper's ~3 s per call for scale.
* Section models: the cambered section (with and without tip loss, with hub loss)
  against the paper's, timed in turn in one process (batch of 2,000 points, one thread
  and all threads, 7 rounds), reported as the median of the paired ratios, with residual
  evaluations per annulus (machine-independent) and the discretization accuracy of the
  cambered model with tip loss.
* JIT cache: wall time of a first call in two fresh processes (the second reads the
  compiled kernel from the on-disk cache).
"""

from __future__ import annotations

import argparse
import json
import math
import re
import subprocess
import sys
import time
from pathlib import Path

import numba
import numpy as np

import propmap as pm
from propmap.core import _annulus, _physics
from propmap.core._reference import solve_reference
from propmap.core.nodes import _nodes
from propmap.io.atomic import atomic_write

RPM = 2 * math.pi / 60
PAPER_S_PER_CALL = 3.0  # Gill & D'Andrea 2017, Section IV


def points(n, inc_lo, inc_hi, seed):
    rng = np.random.default_rng(seed)
    return rng.uniform(3000, 12000, n) * RPM, rng.uniform(0, 25, n), np.radians(rng.uniform(inc_lo, inc_hi, n))


def accuracy(prop, params, n, inc_lo, inc_hi, seed):
    om, V, b = points(n, inc_lo, inc_hi, seed)
    ref_disc = pm.Discretization(1024, 32)
    ref = pm.rotor_loads(prop, params, om, V, b, discretization=ref_disc, on_failure="flag")
    r = pm.rotor_loads(prop, params, om, V, b, on_failure="flag")
    hover = pm.rotor_loads(prop, params, om, 0.0, 0.0, discretization=ref_disc)
    ok = ref.converged & r.converged
    eT, eQ = np.abs(r.thrust - ref.thrust)[ok], np.abs(r.torque - ref.torque)[ok]
    big_T = np.abs(ref.thrust[ok]) >= 0.1 * hover.thrust[ok]
    big_Q = np.abs(ref.torque[ok]) >= 0.1 * hover.torque[ok]
    return {
        "n_points": int(n), "incidence_deg": [inc_lo, inc_hi], "not_converged": int((~ok).sum()),
        "T_max_rel_err_all": float(np.max(eT / np.abs(ref.thrust[ok]))),
        "T_max_rel_err_where_abs_T_ge_10pct_hover": float(np.max(eT[big_T] / np.abs(ref.thrust[ok][big_T]))),
        "T_max_err_over_hover_T": float(np.max(eT / hover.thrust[ok])),
        "Q_max_rel_err_all": float(np.max(eQ / np.abs(ref.torque[ok]))),
        "Q_max_rel_err_where_abs_Q_ge_10pct_hover": float(np.max(eQ[big_Q] / np.abs(ref.torque[ok][big_Q]))),
        "Q_max_err_over_hover_Q": float(np.max(eQ / hover.torque[ok])),
        "D_max_err_over_max_D": float(np.max(np.abs(r.drag - ref.drag)[ok]) / np.max(np.abs(ref.drag[ok]))),
    }


def best_of(f, repeat):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def speed(prop, params, n_batch):
    om, V, b = points(n_batch, 0, 90, 7)
    pm.rotor_loads(prop, params, om[:10], V[:10], b[:10])  # warm-up (JIT or cache load)
    t_batch = best_of(lambda: pm.rotor_loads(prop, params, om, V, b), 3)
    n_eval = pm.rotor_loads(prop, params, om, V, b).n_evaluations
    single = [best_of(lambda i=i: pm.rotor_loads(prop, params, om[i], V[i], b[i]), 5) for i in range(200)]
    d = pm.DEFAULT_DISCRETIZATION
    nd = _nodes(prop, d.n_radial, d.n_azimuth, pm.Air(), params)
    Vs, Vc = V * np.sin(b), V * np.cos(b)
    n_np = min(n_batch, 2000)
    t_np = best_of(lambda: solve_reference(om[:n_np], Vs[:n_np], Vc[:n_np], nd, params), 1)
    return {
        "threads": numba.get_num_threads(),
        "residual_evaluations_per_annulus": float(n_eval.mean() / pm.DEFAULT_DISCRETIZATION.n_radial),
        "simd_widths_in_residual_loop": simd_widths(),
        "batch_points": n_batch,
        "numba_batch_us_per_point": 1e6 * t_batch / n_batch,
        "numba_single_point_us_median": 1e6 * float(np.median(single)),
        "numba_single_point_us_p90": 1e6 * float(np.percentile(single, 90)),
        "numpy_reference_points": n_np,
        "numpy_reference_us_per_point": 1e6 * t_np / n_np,
        "speedup_numba_batch_vs_numpy": (t_np / n_np) / (t_batch / n_batch),
        "speedup_vs_paper_3s_per_call": PAPER_S_PER_CALL / (t_batch / n_batch),
    }


def simd_widths():
    """Vector widths (doubles) LLVM used in the compiled residual (eq 11) loops of both models."""
    fresh = numba.njit(error_model="numpy", fastmath=_annulus._FM)(_annulus._residual.py_func)
    # the dispatcher loaded from the disk cache holds no IR: compile a copy for one call
    psi = np.linspace(-1.0, 1.0, 16)
    pk = np.zeros(_physics.N_PK)  # (the section constants, then the options' switches off)
    pk[:8] = 0.5
    fresh(1.0, 0.1, 0.1, 0.1, (0.1, 0.1, 0.1), (0.1, 0.1, 0.1, 0.1), 0.1, 0.1, 0.1, np.stack([psi, psi]), 0.0, 0.0, 16,
          0, pk, False, 0.0)
    ir = "".join(fresh.inspect_llvm().values())
    return sorted({int(w) for w in re.findall(r"<(\d+) x double>", ir)})


def section_models(prop, paper, n=2000, rounds=7):
    """Per-point time of each section model against the paper's, paired in one process."""
    from propmap.io.calibration import generic_params

    g = generic_params()
    models = {"gill2017-apc (paper)": paper, "cambered, tip loss (default)": g,
              "cambered, no loss": g.replace(tip_loss=False), "cambered, tip + hub loss": g.replace(hub_loss=True),
              "cambered, tip loss, swirl (option)": g.replace(swirl=True),
              "cambered, tip loss, without the in-plane induction (the default until 2026-11-25)":
                  g.replace(inplane_induction=False)}
    om, V, b = points(n, 0, 90, 5)
    out = {}
    threads_all = numba.get_num_threads()
    for threads in (1, threads_all):
        numba.set_num_threads(threads)
        times = {k: [] for k in models}
        for p in models.values():
            pm.rotor_loads(prop, p, om[:50], V[:50], b[:50])
        for _ in range(rounds):
            for k, p in models.items():
                t = time.perf_counter()
                pm.rotor_loads(prop, p, om, V, b)
                times[k].append(time.perf_counter() - t)
        base = np.array(times["gill2017-apc (paper)"])
        out[f"{threads}_threads"] = {k: {"us_per_point_median": 1e6 * float(np.median(v)) / n,
                                         "ratio_to_paper_median_of_pairs": float(np.median(np.array(v) / base))}
                                     for k, v in times.items()}
    numba.set_num_threads(threads_all)
    out["residual_evaluations_per_annulus"] = {
        k: float(pm.rotor_loads(prop, p, om, V, b).n_evaluations.mean() / pm.DEFAULT_DISCRETIZATION.n_radial)
        for k, p in models.items()}
    return out


def jit_cache():
    code = ("import time; t=time.perf_counter(); import propmap as pm; "
            "pm.rotor_loads(pm.load_propeller('apce_8x6'), pm.preset('gill2017-apc'), 800.0, 5.0, 1.0); "
            "print(time.perf_counter()-t)")
    return [float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout)
            for _ in range(2)]


def main() -> None:
    quick = "--quick" in sys.argv
    from propmap.io.calibration import generic_params

    prop, params = pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")
    d = pm.DEFAULT_DISCRETIZATION
    res = {
        "cpu": cpu_name(),
        "propeller": "apce_8x6 (APC PE0 geometry)", "params": "gill2017-apc (Gill & D'Andrea 2017 Table I)",
        "default_discretization": {"n_radial": d.n_radial, "n_azimuth": d.n_azimuth},
        "reference_discretization": {"n_radial": 1024, "n_azimuth": 32},
        "accuracy_climb_to_edgewise": accuracy(prop, params, 100 if quick else 500, 0, 90, 11),
        "accuracy_descent": accuracy(prop, params, 100 if quick else 300, 90, 180, 12),
        "speed": speed(prop, params, 2000 if quick else 10000),
        "section_models": section_models(prop, params, n=500 if quick else 2000, rounds=3 if quick else 7),
        "accuracy_cambered_tip_loss_climb_to_edgewise": accuracy(prop, generic_params(), 100 if quick else 500,
                                                                 0, 90, 13),
        "first_call_s_in_fresh_process": jit_cache(),
    }
    out = Path(__file__).parent / "results" / "solver.json"
    with atomic_write(out) as fh:
        json.dump(res, fh, indent=2)
    print(json.dumps(res, indent=2))
    s = res["speed"]
    print(f"\nbatch {s['numba_batch_us_per_point']:.1f} us/pt ({s['threads']} threads) vs NumPy "
          f"{s['numpy_reference_us_per_point']:.0f} us/pt: x{s['speedup_numba_batch_vs_numpy']:.1f}; "
          f"single point {s['numba_single_point_us_median']:.0f} us; SIMD widths {s['simd_widths_in_residual_loop']}; "
          f"paper 3 s/call: "
          f"x{s['speedup_vs_paper_3s_per_call']:.0f}")
    for k, v in res["section_models"]["1_threads"].items():
        print(f"  one thread, {k}: {v['us_per_point_median']:.1f} us/pt, x{v['ratio_to_paper_median_of_pairs']:.2f} "
              "the paper's model")


def cpu_name() -> str:
    """The CPU model (Linux /proc/cpuinfo), for reading absolute times."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    import platform

    return platform.processor() or platform.machine()


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true")
    parser.parse_args()  # (main reads its flags from sys.argv)
    main()
