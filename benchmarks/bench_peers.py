"""Speed of propmap against a peer, dynbem, on the same propeller and points, in one process.

dynbem (PyPI ``dynbem``, MIT; https://github.com/mcroomp/dynbem) is a blade element momentum
library compiled from Rust, called from Python; issue 20 measured propmap against it and CCBlade
(CCBlade has no package this benchmark can install). It is an optional dependency of the
benchmarks only (``pip install ".[bench]"``).

Measures the cost per operating point of propmap's ``rotor_loads`` and of dynbem's
quasi-static blade element momentum model (``dynbem.QuasiStaticBEM``, a compiled Rust
extension, PyPI ``dynbem``) on the APC 8x6E (``apce_8x6``), each called the way a user
calls it:

* propmap: one ``pm.rotor_loads(prop, params, omega, airspeed, incidence)`` call per batch,
  whole NumPy arrays in, numba kernels (``--threads`` threads, 1 by default: a per-core
  comparison, dynbem being single-threaded);
* dynbem: one ``model.compute_forces(RotorInputs(...), state)`` call per point in a Python
  loop (its API has no batch entry point), the ``RotorInputs`` built per point (its fields
  cannot be reassigned); the quasi-static model's state is empty (``to_array()`` is []), so
  its initial state serves every call.

Cases: the forward-flight envelope of ``benchmarks/bench_solver.py`` (random rpm 3000-12000,
V 0-25 m/s, incidence 0-90 deg; incidence is the angle between the free stream and the rotor
axis, 0 = axial climb, 90 = edgewise), an axial set (incidence 0, V 0-25 m/s, every fifth
point hover) and single-point calls with Python floats (the first ``--single`` envelope
points, one call each, median; each variant's calls in a row, then the variants' calls
interleaved point by point, where each call finds the caches holding the others' data and
code). Each batch is timed ``--rounds`` times; the order of the libraries alternates from
round to round (and from point to point in the interleaved calls). Per-point cost: median
over rounds of the batch time divided by its size, as process CPU time
(``time.process_time``) and wall time (``time.perf_counter``). Ratios are dynbem / propmap:
the median over rounds of the paired per-round ratios (batches; so not the quotient of the
two medians) and the ratio of the medians (single points). The garbage collector is off while
a call is timed.

Variants timed:

* propmap with ``pm.preset("gill2017-apc")`` (Gill & D'Andrea 2017's section, the one the
  dynbem polar below is built from) and with ``pm.default_params("apce_8x6")`` (the
  calibrated cambered set a user gets by default); both at propmap's default
  discretization (48 radial x 16 azimuth nodes);
* dynbem at its defaults (``BladeGeometry``'s ``n_elements`` and ``QuasiStaticBEM``'s
  ``n_psi_elements`` keyword defaults, read from the signatures at run time) and at
  propmap's 48 radial x 16 azimuth elements.

dynbem's rotor: ``BladeGeometry(n_blades, radius_m, root_cutout_m = propmap's r_hub,
chord_m = mean chord (scalar; the station arrays below drive the loads),
r_stations_m / chord_stations_m / twist_stations_deg = propmap's stations, chord and blade
angle theta in degrees)``, tip loss at its default; a ``LinearPolar`` from the paper's
section: CL0 = 0, CL_alpha = cl1, CD0 = cd0, stall at alpha0 (``LinearPolarParameters``,
built by dynbem's own factory); zero collective and cyclic, ``R_hub`` = identity.
Frame: dynbem's thrust acts along -z of the hub frame (``F_world = -T R_hub[:, 2]``);
a hub moving at ``v_hub_world = V (sin b, 0, -cos b)`` in still air is propmap's point
(V, incidence b); thrust T = -F_z, in-plane H-force (propmap's drag, positive against
the in-plane motion) = -F_x, torque Q = ``Q_spin`` (shaft reaction, positive opposing
rotation, as propmap's torque).

Run (on one core: ``taskset -c 1`` where there are two; propmap's first calls compile its
kernels, 30-60 s, in the untimed warm-up; about a minute more for the default sizes)::

    NUMBA_NUM_THREADS=1 taskset -c 1 .venv/bin/python benchmarks/bench_peers.py [--points 2000] [--rounds 6]

Prints one JSON object. Without dynbem installed it prints how to install it and exits 0.
"""

from __future__ import annotations

import argparse
import gc
import inspect
import json
import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from bench_solver import RPM, cpu_name, points  # noqa: E402 (the solver benchmark's envelope and CPU name)


def envelope(n: int, seed: int):
    """Forward-flight points of benchmarks/bench_solver.py: omega [rad/s], V [m/s], incidence [rad]."""
    return points(n, 0.0, 90.0, seed)


def axial(n: int, seed: int):
    """Axial points: incidence 0, V 0-25 m/s, every fifth point hover (V = 0)."""
    om, V, b = points(n, 0.0, 0.0, seed)
    V[::5] = 0.0
    return om, V, b


def build_dynbem(dynbem, prop, paper, n_elements=None, n_psi=None):
    """dynbem QuasiStaticBEM for ``prop`` with a LinearPolar from the paper's section ``paper``.

    ``n_elements`` / ``n_psi`` None: dynbem's own defaults (the keywords are left out).
    """
    geo = {} if n_elements is None else {"n_elements": int(n_elements)}
    blade = dynbem.BladeGeometry(
        n_blades=int(prop.n_blades), radius_m=float(prop.radius), root_cutout_m=float(prop.r_hub),
        chord_m=float(np.mean(prop.chord)), r_stations_m=[float(x) for x in prop.r],
        chord_stations_m=[float(x) for x in prop.chord],
        twist_stations_deg=[float(x) for x in np.degrees(prop.theta)], **geo)
    airfoil = dynbem.LinearPolarParameters(CL0=0.0, CL_alpha_per_rad=float(paper.cl1), CD0=float(paper.cd0),
                                           alpha_stall_deg=math.degrees(paper.alpha0))
    defn = dynbem.RotorDefinition(blade=blade, airfoil=airfoil, name=prop.name)
    model = dynbem.QuasiStaticBEM(defn) if n_psi is None else dynbem.QuasiStaticBEM(defn, n_psi_elements=int(n_psi))
    return model, blade


class DynbemRotor:
    """One dynbem model and the per-point call a user would write."""

    def __init__(self, dynbem, model, rho):
        self.dynbem, self.model, self.rho = dynbem, model, float(rho)
        self.state = model.initial_rotor_state()
        self.eye = np.eye(3)
        self.still = np.zeros(3)

    def point(self, omega, V, b):
        """Thrust, H-force, torque of one point (propmap's sign conventions)."""
        s, c = math.sin(b), math.cos(b)
        inputs = self.dynbem.RotorInputs(collective_rad=0.0, tilt_lon=0.0, tilt_lat=0.0, R_hub=self.eye,
                                         v_hub_world=np.array([V * s, 0.0, -V * c]), wind_world=self.still,
                                         omega_rad_s=float(omega), rho_kg_m3=self.rho)
        res, _ = self.model.compute_forces(inputs, self.state)
        F = res.F_world
        return -F[2], -F[0], res.Q_spin

    def batch(self, om, V, b):
        out = np.empty((len(om), 3))
        for i in range(len(om)):
            out[i] = self.point(om[i], V[i], b[i])
        return out


def timed(f):
    """(process CPU time, wall time) of one call of f, seconds, with Python's garbage collector off."""
    gc.disable()
    try:
        c0, w0 = time.process_time(), time.perf_counter()
        f()
        return time.process_time() - c0, time.perf_counter() - w0
    finally:
        gc.enable()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--points", type=int, default=2000, help="points per batch (default 2000)")
    ap.add_argument("--rounds", type=int, default=6, help="timed rounds per batch, each order alike (default 6)")
    ap.add_argument("--single", type=int, default=200, help="single-point calls timed (default 200)")
    ap.add_argument("--threads", type=int, default=1, help="propmap's numba threads (default 1)")
    ap.add_argument("--seed", type=int, default=7)
    args = ap.parse_args()

    try:
        import dynbem
    except ImportError:
        print('dynbem is not installed; install it with `pip install "dynbem>=0.8,<0.9"` (or `pip install ".[bench]"` '
              'in a checkout) to run this comparison.')
        sys.exit(0)
    try:
        from importlib.metadata import version
        dynbem_version = version("dynbem")
    except Exception:  # noqa: BLE001 (metadata missing on a source checkout)
        dynbem_version = getattr(dynbem, "__version__", "unknown")

    import numba

    import propmap as pm


    numba.set_num_threads(min(args.threads, numba.config.NUMBA_NUM_THREADS))
    prop = pm.load_propeller("apce_8x6")
    paper, calibrated = pm.preset("gill2017-apc"), pm.default_params("apce_8x6")
    rho = paper.air.rho
    d = pm.DEFAULT_DISCRETIZATION

    psi_default = inspect.signature(dynbem.QuasiStaticBEM).parameters["n_psi_elements"].default
    m_def, blade_def = build_dynbem(dynbem, prop, paper)
    m_grid, _ = build_dynbem(dynbem, prop, paper, n_elements=d.n_radial, n_psi=d.n_azimuth)

    pm_variants = {"propmap gill2017-apc": paper, f"propmap {calibrated.label}": calibrated}
    db_variants = {f"dynbem defaults ({blade_def.n_elements} radial x {psi_default} azimuth)":
                   DynbemRotor(dynbem, m_def, rho),
                   f"dynbem {d.n_radial} radial x {d.n_azimuth} azimuth": DynbemRotor(dynbem, m_grid, rho)}

    def run_pm(p, om, V, b):
        return lambda: pm.rotor_loads(prop, p, om, V, b)

    def run_db(m, om, V, b):
        return lambda: m.batch(om, V, b)

    runners = {k: (lambda om, V, b, p=p: run_pm(p, om, V, b)) for k, p in pm_variants.items()}
    runners.update({k: (lambda om, V, b, m=m: run_db(m, om, V, b)) for k, m in db_variants.items()})
    pm_keys, db_keys = list(pm_variants), list(db_variants)

    # warm-up: compile (or load) propmap's kernels for both sets: the batches' (parallel, from
    # solver.PARALLEL_MIN_POINTS points) and the one-point call's (serial)
    t_warm = time.perf_counter()
    n_warm = max(args.points, 64)
    for p in pm_variants.values():
        pm.rotor_loads(prop, p, *envelope(n_warm, 0))
        pm.rotor_loads(prop, p, *axial(n_warm, 0))
        pm.rotor_loads(prop, p, 800.0, 5.0, 1.0)
    for m in db_variants.values():
        m.batch(*envelope(10, 0))
    warm_s = time.perf_counter() - t_warm

    load_before = os.getloadavg()
    cases = {"forward_flight_envelope": envelope(args.points, args.seed), "axial": axial(args.points, args.seed + 1)}
    batches = {}
    for case, (om, V, b) in cases.items():
        rec = {k: [] for k in runners}
        for r in range(args.rounds):
            order = pm_keys + db_keys if r % 2 == 0 else db_keys + pm_keys
            for k in order:
                rec[k].append(timed(runners[k](om, V, b)))
        n = len(om)
        per = {k: {"cpu_us_per_point": 1e6 * float(np.median([c for c, _ in v])) / n,
                   "wall_us_per_point": 1e6 * float(np.median([w for _, w in v])) / n} for k, v in rec.items()}
        ratios = {f"{kd} / {kp}": {
            "cpu": float(np.median([rec[kd][i][0] / rec[kp][i][0] for i in range(args.rounds)])),
            "wall": float(np.median([rec[kd][i][1] / rec[kp][i][1] for i in range(args.rounds)]))}
            for kd in db_keys for kp in pm_keys}
        batches[case] = {"points": n, "rounds": args.rounds, "per_point": per,
                         "ratio_dynbem_over_propmap_median_of_paired_rounds": ratios}

    # single points, Python floats as a simulator passes them: one call per point, (1) each variant's calls in a
    # row ("back to back"), (2) the variants' calls interleaved point by point, the order alternating (each call
    # then finds the caches holding the other library's data and code)
    om, V, b = (x.tolist() for x in envelope(args.single, args.seed))
    calls = {k: [(lambda p=p, i=i: pm.rotor_loads(prop, p, om[i], V[i], b[i])) for i in range(args.single)]
             for k, p in pm_variants.items()}
    calls.update({k: [(lambda m=m, i=i: m.point(om[i], V[i], b[i])) for i in range(args.single)]
                  for k, m in db_variants.items()})
    in_a_row = {k: [timed(c) for c in cs] for k, cs in calls.items()}
    single = {k: [] for k in runners}
    for i in range(args.single):
        order = pm_keys + db_keys if i % 2 == 0 else db_keys + pm_keys
        for k in order:
            single[k].append(timed(calls[k][i]))
    def medians(times):
        return {k: {"cpu_us": 1e6 * float(np.median([c for c, _ in v])),
                    "wall_us": 1e6 * float(np.median([w for _, w in v]))} for k, v in times.items()}

    def ratios(med):
        return {f"{kd} / {kp}": {"cpu": med[kd]["cpu_us"] / med[kp]["cpu_us"],
                                 "wall": med[kd]["wall_us"] / med[kp]["wall_us"]} for kd in db_keys for kp in pm_keys}

    row_med, single_med = medians(in_a_row), medians(single)
    load_after = os.getloadavg()

    # check points: same problem, same sign conventions
    chk = [(8000, 0.0, 0.0), (8000, 10.0, 0.0), (8000, 10.0, 45.0), (8000, 10.0, 90.0), (12000, 25.0, 90.0),
           (5000, 5.0, 60.0)]
    c_om = np.array([c[0] for c in chk]) * RPM
    c_V = np.array([c[1] for c in chk])
    c_b = np.radians([c[2] for c in chk])
    check = []
    pm_chk = {k: pm.rotor_loads(prop, p, c_om, c_V, c_b) for k, p in pm_variants.items()}
    db_chk = {k: m.batch(c_om, c_V, c_b) for k, m in db_variants.items()}
    for j, (rpm, v, inc) in enumerate(chk):
        row = {"rpm": rpm, "V_m_s": v, "incidence_deg": inc}
        for k, r in pm_chk.items():
            row[k] = {"T_N": round(float(r.thrust[j]), 4), "H_N": round(float(r.drag[j]), 4),
                      "Q_Nm": round(float(r.torque[j]), 5)}
        for k, r in db_chk.items():
            row[k] = {"T_N": round(float(r[j, 0]), 4), "H_N": round(float(r[j, 1]), 4),
                      "Q_Nm": round(float(r[j, 2]), 5)}
        row["T_ratio_dynbem_defaults_over_propmap_gill2017-apc"] = round(
            float(db_chk[db_keys[0]][j, 0] / pm_chk[pm_keys[0]].thrust[j]), 3)
        check.append(row)

    out = {
        "cpu": cpu_name(),
        "cpu_affinity": sorted(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None,
        "load_average_1min_before_after": [load_before[0], load_after[0]],
        "python": platform.python_version(),
        "propmap_version": getattr(pm, "__version__", "unknown"),
        "propmap_numba_threads": numba.get_num_threads(),
        "dynbem_version": dynbem_version,
        "propeller": f"{prop.name} (radius {prop.radius} m, {prop.n_blades} blades, {len(prop.r)} stations, "
                     f"r_hub {prop.r_hub:.5f} m)",
        "how_called": {
            "propmap": "pm.rotor_loads(prop, params, omega, V, incidence): one call per batch with arrays; "
                       "single point: one call with scalars",
            "dynbem": "QuasiStaticBEM.compute_forces(RotorInputs(...), state): one call per point in a Python loop, "
                      "RotorInputs built per point (no batch API)",
        },
        "discretization": {
            "propmap": {"n_radial": d.n_radial, "n_azimuth": d.n_azimuth},
            "dynbem_defaults": {"n_elements": blade_def.n_elements, "n_psi_elements": psi_default,
                                "source": "keyword defaults of dynbem.BladeGeometry (n_elements) and "
                                          "dynbem.QuasiStaticBEM (n_psi_elements)",
                                "tip_loss": blade_def.tip_loss},
            "dynbem_matched": {"n_elements": d.n_radial, "n_psi_elements": d.n_azimuth},
        },
        "dynbem_polar": {"type": "LinearPolar (via LinearPolarParameters)", "CL0": 0.0, "CL_alpha_per_rad": paper.cl1,
                         "CD0": paper.cd0, "alpha_stall_rad": paper.alpha0,
                         "from": "gill2017-apc: cl1, cd0, alpha0"},
        "frame": "dynbem R_hub = I, v_hub_world = V (sin b, 0, -cos b), still air; T = -F_world[2], "
                 "H = -F_world[0], Q = Q_spin",
        "warmup_s_untimed": round(warm_s, 1),
        "batches": batches,
        "single_point": {"calls": args.single, "inputs": "Python floats",
                         "back_to_back": {"median": row_med, "ratio_dynbem_over_propmap_of_medians": ratios(row_med)},
                         "interleaved": {"median": single_med,
                                         "ratio_dynbem_over_propmap_of_medians": ratios(single_med)}},
        "check_points": check,
    }
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
