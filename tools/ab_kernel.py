"""Paired A/B timing of two checkouts' solvers in one process (one thread, alternated).

Loads propmap from two source trees (each with its kernel cache already compiled: run any
solve in each checkout first), then times ``rotor_loads`` on the same batch with each in
turn (each tree's modules put back into ``sys.modules`` before its call, :func:`use`),
alternating the order every round, and prints the median of the paired ratios B/A
(forward flight and axial): in one process the machine's drift between runs cancels, which
whole-process timings on a shared machine do not resolve to a few percent. The batch is
benchmarks/bench_solver.py's envelope (rpm 3000-12000, V 0-25 m/s, incidence 0-90 deg;
apce_8x6, the APC 8x6E of the UIUC Propeller Data Site, with its calibrated set).

    taskset -c 1 .venv/bin/python tools/ab_kernel.py OLD/src NEW/src [ROUNDS] [--serial]   # ~2 min for 30 rounds
    taskset -c 1 .venv/bin/python tools/ab_kernel.py OLD/src NEW/src [ROUNDS] --derivatives [forward|axial|hover]
    taskset -c 1 .venv/bin/python tools/ab_kernel.py OLD/src NEW/src [ROUNDS] --single   # ~1 min for 30 rounds
    taskset -c 1 .venv/bin/python tools/ab_kernel.py OLD/src NEW/src [ROUNDS] --map   # ~1 min for 30 rounds
    taskset -c 1 .venv/bin/python tools/ab_kernel.py OLD/src NEW/src [ROUNDS] --small   # ~2 min for 30 rounds

``--serial`` times the serial kernel that small batches run (solver.PARALLEL_MIN_POINTS
raised above the batch) instead of the parallel one on one thread. ``--derivatives`` times
the implicit derivatives instead, on benchmarks/bench_derivatives.py's batch (2,000 points of
apce_8x6, generic set, a fifth axial; or all forward-flight, all axial or all at rest, V = 0): the loads alone,
with the three inputs' derivatives, with the collective too and with the 8 section
parameters, each tree's ratio to its loads and the paired new / old of each (~2 min for 10
rounds). ``--single`` times one scalar call (bench_everyday.py's point: 8000 rpm, 10 m/s, 45 deg,
the paper's Table I set and the generic set), the median of 200 calls per tree and round: the
wrapper's cost, which the kernel's spread between processes hides. ``--map`` times
``RotorMap.loads`` and ``.wrench``'s scalar calls (1,000 random queries of Python floats and a
velocity array per round) on an 8 x 8 x 9 map of apce_8x6, linear and cubic with the paper's
Table I set and cubic with flapping blades (a side table), after checking that both trees
answer the same to the bit, and one step of the example quadrotor from that map
(``VehicleMap.wrench``, 1,000 random steps, checked equal to 1e-13). ``--small`` times the
array path of small batches, where the inputs' checks weigh: ``rotor_loads`` with four rates
and a scalar airspeed and incidence (a quadrotor's rotors), with three 16-point arrays, and one
step of the example quadrotor's ``vehicle_wrench`` (the paper's Table I set; 200 calls per
tree and round), after checking that both trees' loads are equal (the vehicle's force and moment
to 1e-13 of the largest).

e.g. OLD a clone of the previous commit (``git worktree add /tmp/old HEAD~1``, then
``make env`` there); also prints each tree's residual evaluations per annulus.

One process is one draw of memory layout: where a tree's arrays and the thread's stack lie
modulo 4 KiB moved a forward-flight point's cost by up to 18% on an Intel Xeon
(2026-11-27, docs/solver.md, Speed), so one run can show a change of that size that is not
there (0.797, 1.167 and 1.193 were seen between trees whose other runs differ by 0-2%). Run it in
several processes, the trees' order alternated, and report the median with the range.
"""

import importlib
import os
import sys
import time
from pathlib import Path

import numba
import numpy as np


def load(src: str, serial: bool = False):
    """propmap imported from ``src``, its solver modules loaded before the next tree replaces them
    (``serial``: small-batch threshold raised, so that every batch runs the serial kernel)."""
    src = os.path.abspath(src)  # (a relative path was refused: the module's file is absolute; a docs audit)
    for m in [m for m in sys.modules if m == "propmap" or m.startswith("propmap.")]:
        del sys.modules[m]
    sys.path.insert(0, src)
    pm = importlib.import_module("propmap")
    if not pm.__file__.startswith(src):
        raise SystemExit(f"propmap came from {pm.__file__}, not {src}")
    for name in ("rotor_loads", "load_propeller", "default_params"):  # resolve the lazy exports now
        getattr(pm, name)
    for mod in ("core.solver", "core._kernel", "core._annulus", "core.derivatives", "core._sensitivity", "io.catalogue",
                "io.calibration"):
        importlib.import_module(f"propmap.{mod}")
    pm.load_propeller("apce_8x6")
    pm.default_params("apce_8x6")
    if serial:
        sys.modules["propmap.core.solver"].PARALLEL_MIN_POINTS = 10**9
    sys.path.remove(src)
    pm._ab_modules = {m: mod for m, mod in sys.modules.items() if m == "propmap" or m.startswith("propmap.")}
    return pm


def use(pm) -> None:
    """Make ``pm``'s tree the one ``sys.modules`` holds: a function-level import (``from . import
    _sensitivity`` in core/derivatives.py) resolves through it at call time, and would otherwise
    run the last loaded tree's module whichever tree is called."""
    for m in [m for m in sys.modules if m == "propmap" or m.startswith("propmap.")]:
        del sys.modules[m]
    sys.modules.update(pm._ab_modules)


def alternated(trees: dict, rounds: int, run) -> dict:
    """``run(k)`` for tree k in each of ``rounds`` rounds, the trees' order alternated round by round,
    each tree's modules in ``sys.modules`` while it runs: {"A": [results], "B": [results]}."""
    t = {"A": [], "B": []}
    for i in range(rounds):
        for k in ("A", "B") if i % 2 == 0 else ("B", "A"):
            use(trees[k])
            t[k].append(run(k))
    return t


def report(label: str, a, b, unit: str = "us", scale: float = 1e6) -> None:
    """Print tree A's and B's median times (``a``, ``b`` [s] per round, times ``scale`` in ``unit``), the
    median paired difference and the median and quartiles of the paired ratio B / A."""
    a, b = np.asarray(a), np.asarray(b)
    q = np.percentile(b / a, [25, 50, 75])
    print(f"{label}: A {scale * np.median(a):.2f} {unit}, B {scale * np.median(b):.2f} {unit}; B - A "
          f"{scale * np.median(b - a):+.2f} {unit}; B / A paired median {q[1]:.3f} (quartiles {q[0]:.3f}-{q[2]:.3f})")


#: the cambered fit's parameters with Reynolds terms (benchmarks/bench_derivatives.py's)
PARAMS = ("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2", "re_exp_lift", "re_exp", "alpha_L0_re")


def derivatives_ab(trees: dict, rounds: int, batch: str) -> None:
    """The paired timing of the implicit derivatives (``--derivatives``)."""
    rng = np.random.default_rng(0)
    n = 2000
    om = rng.uniform(2000, 12000, n) * 2 * np.pi / 60
    V = rng.uniform(0, 20, n)
    b = np.radians(rng.uniform(0, 180, n))
    b[: n // 5] = 0.0
    if batch == "forward":
        b = np.radians(rng.uniform(1, 179, n))
    elif batch == "axial":
        b = 0.0 * V
    elif batch == "hover":  # at rest: the airspeed's slope one-sided along its ray
        V = 0.0 * V
        b = 0.0 * V
    cases = {"loads": None, "3 inputs": True, "with the collective": ("omega", "airspeed", "incidence", "collective"),
             "8 parameters": PARAMS}
    args = {}
    for k, pm in trees.items():
        use(pm)
        args[k] = (pm.load_propeller("apce_8x6"), pm.generic_params())
        for d in cases.values():  # warm
            pm.rotor_loads(*args[k], om, V, b, derivatives=d)
    t = {(k, c): [] for k in trees for c in cases}
    for i in range(rounds):
        for k in ("A", "B") if i % 2 == 0 else ("B", "A"):
            use(trees[k])
            for c, d in cases.items():
                t0 = time.process_time()
                trees[k].rotor_loads(*args[k], om, V, b, derivatives=d)
                t[(k, c)].append(time.process_time() - t0)
    for c in cases:
        a, bb = np.array(t[("A", c)]), np.array(t[("B", c)])
        ra, rb = a / np.array(t[("A", "loads")]), bb / np.array(t[("B", "loads")])
        print(f"{batch} batch, {c}: A {1e3 * np.median(a):.1f} ms ({np.median(ra):.3f}x its loads), B "
              f"{1e3 * np.median(bb):.1f} ms ({np.median(rb):.3f}x); B / A paired median {np.median(bb / a):.3f}")


def single_ab(trees: dict, rounds: int) -> None:
    """The paired timing of one scalar ``rotor_loads`` call (``--single``)."""
    om, V, b = 8000 * np.pi / 30, 10.0, np.radians(45.0)
    for label in ("paper", "generic"):
        args = {}
        for k, pm in trees.items():
            use(pm)
            args[k] = (pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc") if label == "paper" else
                       pm.generic_params())
            pm.rotor_loads(*args[k], om, V, b)

        def run(k):
            f, a = trees[k].rotor_loads, args[k]
            calls = []
            for _ in range(200):
                t0 = time.perf_counter()
                f(*a, om, V, b)
                calls.append(time.perf_counter() - t0)
            return np.median(calls)

        t = alternated(trees, rounds, run)
        report(f"one call, {label} set", t["A"], t["B"])


def small_ab(trees: dict, rounds: int) -> None:
    """The paired timing of small batches' calls (``--small``)."""
    rng = np.random.default_rng(3)
    om4 = np.array([800.0, 820.0, 790.0, 810.0])
    om16, V16, b16 = rng.uniform(300, 1300, 16), rng.uniform(0, 20, 16), rng.uniform(0, 3.1, 16)
    step = (np.array([3.0, 0.5, -0.2]), np.array([0.1, -0.2, 0.05]), om4)
    calls = {}
    for k, pm in trees.items():
        use(pm)
        from propmap.vehicle import read_vehicle, vehicle_wrench  # (this tree's)

        prop, params = pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")
        veh = read_vehicle(Path(pm.__file__).parent / "data/examples/quadrotor.toml")
        calls[k] = {"rotor_loads, 4 rates": (pm.rotor_loads, (prop, params, om4, 3.0, 1.0)),
                    "rotor_loads, three 16-point arrays": (pm.rotor_loads, (prop, params, om16, V16, b16)),
                    "vehicle_wrench, one step": (vehicle_wrench, (veh, params) + step)}
    for label in calls["A"]:
        got = {}
        for k in trees:
            use(trees[k])
            f, a = calls[k][label]
            got[k] = f(*a)
        fields = ("thrust", "drag", "torque") if label.startswith("rotor_loads") else ("force", "moment")
        # (the loads to the bit; a vehicle's vectors within 1e-13 of the largest: trees whose disk frame rounds
        # differently, NumPy's expressions against the compiled one-point arithmetic, 2026-11-29)
        tol = 0.0 if label.startswith("rotor_loads") else 1e-13
        if not all(np.allclose(getattr(got["A"], q), getattr(got["B"], q), rtol=0.0,
                               atol=tol * np.abs(getattr(got["A"], q)).max()) for q in fields):
            raise SystemExit(f"the trees answer {label} differently")

        def run(k):
            f, a = calls[k][label]
            t0 = time.process_time()
            for _ in range(200):
                f(*a)
            return (time.process_time() - t0) / 200

        t = alternated(trees, rounds, run)
        report(label, t["A"], t["B"])


def map_ab(trees: dict, rounds: int) -> None:
    """The paired timing of RotorMap's scalar calls (``--map``)."""
    import math

    rng = np.random.default_rng(1)
    n = 1000
    queries = np.column_stack([rng.uniform(300, 1300, n), rng.uniform(0, 20, n), rng.uniform(0, 3.1, n)]).tolist()
    axis = np.array([0.0, 0.0, 1.0])
    vels = [np.array([v * math.sin(x), 0.0, v * math.cos(x)]) for _, v, x in queries]
    grid = (np.linspace(300, 1300, 8), np.linspace(0, 20, 8), np.radians(np.linspace(0, 180, 9)))
    for interp, label in (("linear", "paper"), ("cubic", "paper"), ("cubic", "flapping")):
        maps, vehicles = {}, {}
        for k, pm in trees.items():
            use(pm)
            from propmap.maps import RotorMap, build_map  # (this tree's)
            from propmap.vehicle import VehicleMap, read_vehicle

            params = (pm.generic_params().replace(flap_compliance=2.0) if label == "flapping"
                      else pm.preset("gill2017-apc"))
            maps[k] = RotorMap(build_map(pm.load_propeller("apce_8x6"), params, *grid, n_check=0), interp)
            vehicles[k] = VehicleMap(read_vehicle(Path(pm.__file__).parent / "data/examples/quadrotor.toml"), maps[k])
        steps = [(vel, 0.3 * vel[::-1], [o, 0.97 * o, 1.02 * o, o]) for (o, _, _), vel in zip(queries, vels)]
        for s in steps:
            use(trees["A"])
            a = vehicles["A"].wrench(*s, out_of_grid="clip")
            use(trees["B"])
            b = vehicles["B"].wrench(*s, out_of_grid="clip")
            if not (np.allclose(a.force, b.force, rtol=1e-13, atol=1e-13)
                    and np.allclose(a.moment, b.moment, rtol=1e-13, atol=1e-13) and a.flagged[0] == b.flagged[0]):
                raise SystemExit(f"the trees' vehicle steps differ at {s}")
        for (o, v, x), vel in zip(queries, vels):
            use(trees["A"])
            a, la = maps["A"].wrench(vel, axis, o, "ccw"), maps["A"].loads(o, v, x)
            use(trees["B"])
            b, lb = maps["B"].wrench(vel, axis, o, "ccw"), maps["B"].loads(o, v, x)
            if not (np.array_equal(a.force, b.force) and np.array_equal(a.torque, b.torque)
                    and tuple(a.loads) == tuple(b.loads) and tuple(la) == tuple(lb)):
                raise SystemExit(f"the trees answer differently at {o, v, x}")

        def run(rm, vm):
            t0 = time.perf_counter()
            for o, v, x in queries:
                rm.loads(o, v, x)
            t1 = time.perf_counter()
            for (o, v, x), vel in zip(queries, vels):
                rm.wrench(vel, axis, o, "ccw")
            t2 = time.perf_counter()
            for s in steps:
                vm.wrench(*s, out_of_grid="clip")
            return (t1 - t0) / n, (t2 - t1) / n, (time.perf_counter() - t2) / n

        t = alternated(trees, rounds + 1, lambda k: run(maps[k], vehicles[k]))
        a, b = np.array(t["A"][1:]), np.array(t["B"][1:])  # (the first round warms)
        for j, call in enumerate(("loads", "wrench", "vehicle step")):
            report(f"{interp}, {label} set, {call}", a[:, j], b[:, j])


def main() -> None:
    flags = ("--serial", "--derivatives", "forward", "axial", "hover", "--single", "--map", "--small")
    argv = [a for a in sys.argv[1:] if a not in flags]
    if len(argv) < 2:
        raise SystemExit(__doc__)
    numba.set_num_threads(1)
    serial = "--serial" in sys.argv
    trees = {"A": load(argv[0], serial), "B": load(argv[1], serial)}
    rounds = int(argv[2]) if len(argv) > 2 else 30
    if "--derivatives" in sys.argv:
        derivatives_ab(trees, rounds, next((a for a in ("forward", "axial", "hover") if a in sys.argv), "mixed"))
        return
    if "--single" in sys.argv:
        single_ab(trees, rounds)
        return
    if "--map" in sys.argv:
        map_ab(trees, rounds)
        return
    if "--small" in sys.argv:
        small_ab(trees, rounds)
        return
    rng = np.random.default_rng(5)
    n = 4000
    om = rng.uniform(3000, 12000, n) * np.pi / 30
    V = rng.uniform(0, 25, n)
    inc = np.radians(rng.uniform(0, 90, n))
    args = {k: (pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")) for k, pm in trees.items()}
    for k, pm in trees.items():
        use(pm)
        r = pm.rotor_loads(*args[k], om, V, inc)
        print(f"{k}: {pm.__file__}; {r.n_evaluations.mean() / r.r.size:.3f} residual evaluations per annulus")
    for label, beta in (("forward flight", inc), ("axial", 0.0 * inc)):
        def run(k):
            t0 = time.process_time()
            trees[k].rotor_loads(*args[k], om, V, beta)
            return time.process_time() - t0

        t = alternated(trees, rounds, run)
        report(label, t["A"], t["B"], "us per point", 1e6 / n)


if __name__ == "__main__":
    main()
