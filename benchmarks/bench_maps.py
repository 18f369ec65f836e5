"""Rotor-map benchmark: build cost against the solver, lookup speed (Python and C), file
size, and the interpolation error against grid density.

Run:  .venv/bin/python benchmarks/bench_maps.py [--quick]

Propeller apce_8x6 with its calibrated parameters (UIUC Propeller Data Site vol. 1, APC
PE0 geometry). Writes benchmarks/results/maps.json atomically and prints it.

* Build: the default map (21 x 26 x 73) and the 21 x 26 x 37 grid of the issue, each
  timed beside one rotor_loads batch of the same number of points in the same run (ratio);
  the build includes its error check (2,000 random points, about 10% of the work).
* Lookups: a batch of 10,000 random points (median of 20), the model on the same points
  (ratio); one scalar Python call (median of 20,000); a quadrotor step from the map (VehicleMap, batch and one
  step) against the full vehicle model; the C function, compiled with the
  system compiler at -O2 (ns per call over 10^6 calls of varying points).
* Size: the default map's netCDF file (zlib level 4).
* Lookups and the C function with the multilinear interpolation, then with the cubic
  (the Python evaluator's default; `map --format c` defaults to the multilinear).
* Density: max and rms interpolation error (T, Q over static values, D over the largest
  drag) outside flagged cells, on 2,000 fresh points, for grids from coarse to fine, for
  the multilinear and the cubic interpolation.
"""

from __future__ import annotations

import argparse
import json
import math
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.export_c import write_c_header
from propmap.io.atomic import atomic_write
from propmap.maps import RotorMap, build_map, check_map, default_axes, write_map

RPM = math.pi / 30


def timed(f):
    t = time.perf_counter()
    out = f()
    return time.perf_counter() - t, out


def build_vs_solver(prop, params, air, rpm, V, inc):
    om, b = rpm * RPM, np.radians(inc)
    n = om.size * V.size * b.size
    O, VV, B = (a.reshape(-1) for a in np.meshgrid(om, V, b, indexing="ij"))
    pm.rotor_loads(prop, params, O[:100], VV[:100], B[:100], air=air)
    t_solver, _ = timed(lambda: pm.rotor_loads(prop, params, O, VV, B, air=air, on_failure="flag"))
    t_build, ds = timed(lambda: build_map(prop, params, om, V, b, air=air, n_check=2000))
    t_nocheck, _ = timed(lambda: build_map(prop, params, om, V, b, air=air, n_check=0))
    return {"grid": [int(om.size), int(V.size), int(b.size)], "points": n, "solver_batch_s": t_solver,
            "build_s": t_build, "build_without_check_s": t_nocheck, "ratio_build_to_solver": t_build / t_solver,
            "ratio_build_without_check_to_solver": t_nocheck / t_solver,
            "build_us_per_point": 1e6 * t_build / n}, ds


def lookups(rm: RotorMap, prop, params, air, n=10_000):
    rng = np.random.default_rng(1)
    om = rng.uniform(rm.omega[0], rm.omega[-1], n)
    V = rng.uniform(rm.airspeed[0], rm.airspeed[-1], n)
    b = rng.uniform(rm.incidence[0], rm.incidence[-1], n)
    rm.loads(om, V, b)
    batch = [timed(lambda: rm.loads(om, V, b))[0] for _ in range(20)]
    t_model, _ = timed(lambda: pm.rotor_loads(prop, params, om, V, b, air=air, on_failure="flag"))
    rm.loads(800.0, 10.0, 1.0)
    single = []
    for i in range(20_000):
        o, v, x = float(om[i % n]), float(V[i % n]), float(b[i % n])
        t = time.perf_counter()
        rm.loads(o, v, x)
        single.append(time.perf_counter() - t)
    # one rotor's wrench (RotorMap.wrench's scalar path), alternated with loads in the same loop
    wrench, single2 = [], []
    axis = np.array([0.0, 0.0, 1.0])
    for i in range(20_000):
        o, v, x = float(om[i % n]), float(V[i % n]), float(b[i % n])
        vel = np.array([v * math.sin(x), 0.0, v * math.cos(x)])
        t = time.perf_counter()
        rm.wrench(vel, axis, o, "ccw")
        t1 = time.perf_counter()
        rm.loads(o, v, x)
        t2 = time.perf_counter()
        wrench.append(t1 - t)
        single2.append(t2 - t1)
    return {"interpolation": rm.interpolation, "batch_points": n,
            "batch_us_per_point_median": 1e6 * float(np.median(batch)) / n,
            "model_us_per_point": 1e6 * t_model / n, "ratio_model_to_map_batch": t_model / float(np.median(batch)),
            "single_python_call_us_median": 1e6 * float(np.median(single)),
            "single_wrench_call_us_median": 1e6 * float(np.median(wrench)),
            "ratio_wrench_to_loads_single": float(np.median(wrench)) / float(np.median(single2))}


C_BENCH = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>
#include "map.h"
int main(void)
{
    double out[4], acc = 0.0;
    const int n = 1000000;
    struct timespec t0, t1;
    int i;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (i = 0; i < n; i++) {
        double f = (double)(i % 9973) / 9973.0, g = (double)(i % 7919) / 7919.0, h = (double)(i % 6007) / 6007.0;
        pm_map_loads(OMIN + f * (OMAX - OMIN), VMAX * g, 3.14159 * h, PM_MAP_CLIP, out);
        acc += out[0];
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("%.3f %g\n", ((t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec)) / n, acc);
    return 0;
}
"""


def _c_runs(rm: RotorMap, source: str, vehicle=None):
    """(compiler, ns per call of each of 5 runs) of the C program ``source`` against rm's header
    (map.h, with ``vehicle``'s function), compiled at -O2; (None, []) without a compiler."""
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        return None, []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        write_c_header(rm, tmp / "map.h", vehicle=vehicle)
        (tmp / "b.c").write_text(source)
        subprocess.run([cc, "-std=c99", "-O2", "-o", str(tmp / "b"), str(tmp / "b.c"), "-lm"], check=True)
        runs = [subprocess.run([str(tmp / "b")], capture_output=True, text=True, check=True) for _ in range(5)]
        return cc, [float(r.stdout.split()[0]) for r in runs]


def c_speed(rm: RotorMap):
    cc, runs = _c_runs(rm, C_BENCH.replace("OMIN", repr(float(rm.omega[0]))).replace(
        "OMAX", repr(float(rm.omega[-1]))).replace("VMAX", repr(float(rm.airspeed[-1]))))
    if cc is None:
        return {"c_ns_per_call": None, "note": "no C compiler"}
    return {"c_ns_per_call_median": float(np.median(runs)), "c_ns_per_call_min": min(runs), "compiler": cc}


C_VEHICLE_BENCH = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>
#include "map.h"
int main(void)
{
    double v[3], w[3], o[4], f[3], m[3], acc = 0.0;
    const int n = 200000;
    struct timespec t0, t1;
    int i, k;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (i = 0; i < n; i++) {
        double g = (double)(i % 7919) / 7919.0, h = (double)(i % 6007) / 6007.0;
        v[0] = 12.0 * g - 6.0; v[1] = 4.0 * h - 2.0; v[2] = 3.0 * g * h;
        w[0] = 0.5 * h; w[1] = -0.4 * g; w[2] = 0.2;
        for (k = 0; k < 4; k++) o[k] = 500.0 + 600.0 * (double)((i + 997 * k) % 4999) / 4999.0;
        pm_map_vehicle_wrench(v, w, o, PM_MAP_CLIP, f, m);
        acc += f[2] + m[0];
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("%.3f %g\n", ((t1.tv_sec - t0.tv_sec) * 1e9 + (t1.tv_nsec - t0.tv_nsec)) / n, acc);
    return 0;
}
"""


def c_vehicle_speed(rm: RotorMap):
    """The quadrotor example's C vehicle step (pm_map_vehicle_wrench, four rotors), ns per step, -O2."""
    from propmap.vehicle import read_vehicle

    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    cc, runs = _c_runs(rm, C_VEHICLE_BENCH, veh)
    if cc is None:
        return {"c_ns_per_step": None, "note": "no C compiler"}
    return {"interpolation": rm.interpolation, "c_ns_per_vehicle_step_median": float(np.median(runs)),
            "c_ns_per_vehicle_step_min": min(runs), "compiler": cc}


def density(prop, params, air, quick):
    top = default_axes(prop)[0][-1]
    grids = [(11, 13, 19), (21, 26, 37), (21, 26, 73), (31, 51, 73)] if not quick else [(11, 13, 19), (21, 26, 37)]
    out = []
    for n0, n1, n2 in grids:
        ds = build_map(prop, params, np.geomspace(top / 6, top, n0) * RPM, np.linspace(0, 25, n1),
                       np.radians(np.linspace(0, 180, n2)), air=air, n_check=0)
        c = check_map(ds, 2000, seed=5)
        for method in ("linear", "cubic"):
            p = f"check_{method}_"
            out.append({"grid": [n0, n1, n2], "points": n0 * n1 * n2, "interpolation": method,
                        **{f"{k}_{s}": c[f"{p}{k}_{s}"] for k in ("thrust", "torque", "drag") for s in ("max", "rms")},
                        "flagged_fraction": c["check_points_flagged"] / c["check_points"]})
    return out


def vehicle_step(rm: RotorMap, params, n=10_000):
    """A quadrotor step (four apce_8x6, data/examples/quadrotor.toml) from the map (VehicleMap.wrench, a batch of n
    steps) against the full vehicle model (vehicle_wrench, 500 steps), in one run: us per vehicle step and ratio."""
    from propmap.vehicle import VehicleMap, read_vehicle, vehicle_wrench

    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    rng = np.random.default_rng(3)
    v = rng.normal(0, 3, (n, 3))
    v[:, 2] = np.abs(v[:, 2])
    w = rng.normal(0, 1, (n, 3))
    om = rng.uniform(500, 1100, (n, 4))
    vm = VehicleMap(veh, rm)
    vm.wrench(v[:10], w[:10], om[:10], out_of_grid="clip")
    batch = [timed(lambda: vm.wrench(v, w, om, out_of_grid="clip"))[0] for _ in range(10)]
    single = []
    for i in range(2000):
        t = time.perf_counter()
        vm.wrench(v[i], w[i], om[i], out_of_grid="clip")
        single.append(time.perf_counter() - t)
    m = 500
    vehicle_wrench(veh, params, v[:5], w[:5], om[:5], on_failure="flag")
    t_model, _ = timed(lambda: vehicle_wrench(veh, params, v[:m], w[:m], om[:m], on_failure="flag"))
    per_step = float(np.median(batch)) / n
    return {"rotors": 4, "batch_steps": n, "map_batch_us_per_step_median": 1e6 * per_step,
            "map_single_step_us_median": 1e6 * float(np.median(single)),
            "model_us_per_step": 1e6 * t_model / m, "ratio_model_to_map_batch": (t_model / m) / per_step}


def main() -> None:
    from bench_solver import cpu_name

    quick = "--quick" in sys.argv
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    air, label = params.air, params.label
    rpm, V, inc = default_axes(prop)
    # warm-up: imports (xarray, dask) and the compiled kernels loaded before anything is timed
    build_map(prop, params, rpm[:2] * RPM, V[:2], np.radians(inc[:2]), air=air, n_check=20)
    default_build, ds = build_vs_solver(prop, params, air, rpm, V, inc)
    issue_build, _ = build_vs_solver(prop, params, air, rpm, V, np.linspace(0, 180, 37))
    rm = RotorMap(ds, "linear")
    with tempfile.TemporaryDirectory() as tmp:
        size = write_map(ds, Path(tmp) / "m.nc")[0].stat().st_size
    res = {"cpu": cpu_name(), "propeller": "apce_8x6", "params": label,
           "build_default_grid": default_build, "build_21x26x37": issue_build,
           "lookups": lookups(rm, prop, params, air), "lookups_cubic": lookups(RotorMap(ds), prop, params, air),
           "c_linear": c_speed(rm), "c_cubic": c_speed(RotorMap(ds)),
           "vehicle_step_cubic": vehicle_step(RotorMap(ds), params),
           "c_vehicle_linear": c_vehicle_speed(rm), "c_vehicle_cubic": c_vehicle_speed(RotorMap(ds)),
           "default_map_netcdf_bytes": size,
           "default_map_check": {k: v for k, v in ds.attrs.items()
                                 if k.startswith("check_") and k != "check_normalisation"},
           "density": density(prop, params, air, quick)}
    out = Path(__file__).parent / "results" / "maps.json"
    with atomic_write(out) as fh:
        json.dump(res, fh, indent=2, default=float)
    print(json.dumps(res, indent=2, default=float))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true")
    parser.parse_args()  # (main reads its flags from sys.argv)
    sys.path.insert(0, str(Path(__file__).parent))
    main()
