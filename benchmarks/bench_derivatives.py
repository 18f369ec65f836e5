"""Derivatives benchmark: the implicit derivatives' cost against the loads alone and against
differencing the solver, on one batch, in one run.

Run:  .venv/bin/python benchmarks/bench_derivatives.py

Writes benchmarks/results/derivatives.json atomically and prints it.

On 2,000 operating points of apce_8x6 (generic cambered set, 48 x 16 nodes; seed 0: 2,000
to 12,000 rpm, 0 to 20 m/s, incidence 0 to 180 deg, a fifth of them axial), each timed as
the median of 5 alternated runs:

* ``rotor_loads`` alone (the baseline);
* with ``derivatives=True`` (omega, airspeed, incidence), with the collective too, and with
  the 8 section parameters of the cambered fit (issue 20's target: <= 3x);
* the central differences of the whole solver for the same three inputs (6 more solves);
* a vehicle's linearisation: ``vehicle_wrench`` of the example quadrotor (4 x APC 8x6E,
  generic set) on 200 samples, alone and with the velocity and angular-velocity Jacobians,
  at rest (hover: the rotors' slopes at V = 0 along three rays) and at 3 m/s forward;
* the same batch with Pitt-Peters inflow (``linear_inflow``): its loads, with the three
  inputs' and the 8 parameters' derivatives (core/_linear_sensitivity.py) and the three
  inputs' central differences, each ratio to its own loads; and the same with swirl too
  (``linear_inflow_swirl``, since 2026-11-26, when it gained implicit derivatives);
* the same batch with Gormont's dynamic stall (``dynamic_stall``, gamma 1.5; its implicit
  derivatives since 2026-11-26, core/_delayed_sensitivity.py): its loads and the three inputs'
  and 8 parameters' derivatives, each ratio to its own loads.

Reported: seconds and the ratios to the baseline (issue 20's target: <= 1.5x for the three
inputs), the residual evaluations per annulus of the solve, and the CPU.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.io.atomic import atomic_write

ROOT = Path(__file__).resolve().parents[1]
N = 2000
RUNS = 5
#: the cambered fit's parameters with Reynolds terms (identify.fit.CAMBERED_FIT_RE)
PARAMS = ("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2", "re_exp_lift", "re_exp", "alpha_L0_re")


def _timed(cases: dict) -> dict:
    """{case: [seconds of each of RUNS alternated runs]}, each case called once before."""
    for f in cases.values():  # compile / load the caches
        f()
    times = {k: [] for k in cases}
    for _ in range(RUNS):
        for k, f in cases.items():
            t = time.perf_counter()
            f()
            times[k].append(time.perf_counter() - t)
    return times


def _summary(times: dict, base: str) -> dict:
    b = float(np.median(times[base]))
    return {k: {"median_s": float(np.median(v)), "min_s": float(np.min(v)), "ratio_to_loads": float(np.median(v)) / b}
            for k, v in times.items()}


def main() -> dict:
    sys.path.insert(0, str(Path(__file__).parent))
    from bench_solver import cpu_name

    prop = pm.load_propeller("apce_8x6")
    params = pm.generic_params()
    rng = np.random.default_rng(0)
    om = rng.uniform(2000, 12000, N) * 2 * np.pi / 60
    V = rng.uniform(0, 20, N)
    b = np.radians(rng.uniform(0, 180, N))
    b[: N // 5] = 0.0  # axial
    steps = ((om, V, b), (om * (1 + 1e-4), V, b), (om * (1 - 1e-4), V, b), (om, V + 1e-3, b),
             (om, np.maximum(V - 1e-3, 0), b), (om, V, np.minimum(b + 1e-4, np.pi)), (om, V, np.maximum(b - 1e-4, 0)))
    cases = {
        "loads": lambda: pm.rotor_loads(prop, params, om, V, b),
        "loads + derivatives (3 inputs)": lambda: pm.rotor_loads(prop, params, om, V, b, derivatives=True),
        "loads + derivatives (4 inputs)": lambda: pm.rotor_loads(
            prop, params, om, V, b, derivatives=("omega", "airspeed", "incidence", "collective")),
        "loads + derivatives (8 section parameters)": lambda: pm.rotor_loads(prop, params, om, V, b,
                                                                            derivatives=PARAMS),
        "central differences of the solver (3 inputs)": lambda: [pm.rotor_loads(prop, params, *a) for a in steps],
    }
    times = _timed(cases)
    r = pm.rotor_loads(prop, params, om, V, b)
    out = {
        "cpu": cpu_name(), "cores": os.cpu_count(), "load_average": os.getloadavg(), "points": N,
        "discretization": [48, 16], "date": time.strftime("%Y-%m-%d"),
        "residual_evaluations_per_annulus": float(r.n_evaluations.sum() / (N * r.r.size)),
        "cases": _summary(times, "loads"),
    }
    for key, swirl in (("linear_inflow", False), ("linear_inflow_swirl", True)):
        linear = params.replace(inflow="pitt-peters", swirl=swirl)
        out[key] = _summary(_timed({
            "loads (Pitt-Peters)": lambda: pm.rotor_loads(prop, linear, om, V, b),
            "loads + derivatives (3 inputs)": lambda: pm.rotor_loads(prop, linear, om, V, b, derivatives=True),
            "loads + derivatives (8 section parameters)": lambda: pm.rotor_loads(prop, linear, om, V, b,
                                                                                derivatives=PARAMS),
            "central differences of the solver (3 inputs)": lambda: [pm.rotor_loads(prop, linear, *a)
                                                                     for a in steps],
        }), "loads (Pitt-Peters)")
    stall = params.replace(dynamic_stall=1.5)  # Gormont's dynamic stall (an option; since 2026-11-26 differentiable)
    out["dynamic_stall"] = _summary(_timed({
        "loads (dynamic stall)": lambda: pm.rotor_loads(prop, stall, om, V, b),
        "loads + derivatives (3 inputs)": lambda: pm.rotor_loads(prop, stall, om, V, b, derivatives=True),
        "loads + derivatives (8 section parameters)": lambda: pm.rotor_loads(prop, stall, om, V, b,
                                                                            derivatives=PARAMS),
    }), "loads (dynamic stall)")
    out["vehicle_linearisation"] = vehicle_linearisation()
    path = ROOT / "benchmarks" / "results" / "derivatives.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_write(path) as fh:
        fh.write(json.dumps(out, indent=2))
    return out


def vehicle_linearisation(n: int = 200) -> dict:
    """vehicle_wrench's cost with the velocity and angular-velocity Jacobians over its cost alone,
    at rest and at 3 m/s forward (median of RUNS alternated runs each)."""
    from importlib import resources

    from propmap.vehicle import read_vehicle, vehicle_wrench

    veh = read_vehicle(str(resources.files("propmap") / "data/examples/quadrotor.toml"))
    params = pm.generic_params()
    om = np.full((n, len(veh.rotors)), 800.0)
    w = np.zeros((n, 3))
    res = {}
    for label, speed in (("at rest", 0.0), ("3 m/s forward", 3.0)):
        vel = np.tile([speed, 0.0, 0.0], (n, 1))
        runs = {"wrench": lambda: vehicle_wrench(veh, params, vel, w, om),
                "with Jacobians": lambda: vehicle_wrench(veh, params, vel, w, om,
                                                         derivatives=("velocity", "angular_velocity"))}
        t = {k: [] for k in runs}
        for f in runs.values():
            f()
        for _ in range(RUNS):
            for k, f in runs.items():
                t0 = time.perf_counter()
                f()
                t[k].append(time.perf_counter() - t0)
        a, b = float(np.median(t["wrench"])), float(np.median(t["with Jacobians"]))
        res[label] = {"samples": n, "wrench_s": a, "with_jacobians_s": b, "ratio": b / a}
    return res


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    print(json.dumps(main(), indent=2))
