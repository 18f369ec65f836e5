"""Flight-log benchmark: the vehicle model on a whole log, and a flight fit.

Run:  .venv/bin/python benchmarks/bench_flight.py [--fit]

Needs ../shared/data/neurobem_flights beside the checkout (the NeuroBEM logs, Bauersfeld
et al., RSS 2021). Writes benchmarks/results/flight.json atomically and prints it.

* ``propmap wrench`` on the 29.4 s, 400 Hz segment bemnn20210223104803seg2 (11,749 samples
  x 4 rotors) as a whole process (median, min, max of 5 runs after a warm-up), beside
  ``propmap props`` (the CLI's start-up, the same run) so that the ratio carries over; both
  with the bytecode cache a normal install has (PYTHONDONTWRITEBYTECODE removed for them).
* ``vehicle_wrench`` in-process on the same samples: seconds, rotor evaluations per
  second, residual evaluations per annulus, for the default (48 x 16) and the flight-fit
  (24 x 8) discretizations, uniform inflow and Pitt-Peters.
* With ``--fit``: ``fit_flight`` on all four segments at 25 Hz with the default
  parameters (FLIGHT_FIT), with the implicit Jacobian (the default) and with differences of
  the solver: seconds, residual evaluations, rotor points, the optimum.
* With ``--cg``: the same fit with the centre of mass freed (``cg_x``, ``cg_y``) and the
  moments in the residual, with the default Jacobian only (run it with another tree's
  ``src`` first on PYTHONPATH for an A/B of the Jacobian's code).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.identify import FitOptions
from propmap.identify.flight import FLIGHT_DISCRETIZATION, FLIGHT_FIT, fit_flight, flight_samples
from propmap.io.atomic import atomic_write
from propmap.io.flightlog import read_flight_log

ROOT = Path(__file__).resolve().parents[1]
LOGS = ROOT.parent / "shared" / "data" / "neurobem_flights"
VEHICLE = ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml"
SEGMENT = "bemnn20210223104803seg2.mat"
BIN = Path(sys.executable).parent


def in_process(params, disc, runs=3):
    veh = pm.read_vehicle(VEHICLE)
    s = flight_samples([read_flight_log(LOGS / SEGMENT)], veh, rate_hz=1e4)
    pm.vehicle_wrench(veh, params, s.velocity[:64], s.angular_velocity[:64], s.rotor_omega[:64],
                      discretization=disc)  # compile / load the cache
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        w = pm.vehicle_wrench(veh, params, s.velocity, s.angular_velocity, s.rotor_omega,
                              rotor_acceleration=s.rotor_acceleration, discretization=disc)
        times.append(time.perf_counter() - t)
    nev = sum(float(np.sum(lo.n_evaluations)) for lo in w.loads)
    points = s.n * len(veh.rotors)
    med = float(np.median(times))
    return {"samples": s.n, "rotor_points": points, "median_s": med, "min_s": min(times),
            "us_per_rotor_point": 1e6 * med / points,
            "residual_evaluations_per_annulus": nev / (points * disc.n_radial)}


def main() -> None:
    if not LOGS.is_dir():
        sys.exit(f"needs {LOGS}")
    sys.path.insert(0, str(Path(__file__).parent))
    from bench_everyday import wall
    from bench_solver import cpu_name

    out = {"cpu": cpu_name(), "cores": os.cpu_count(), "load_average": os.getloadavg()}
    with tempfile.TemporaryDirectory() as tmp:
        out["wrench_cli"] = wall([str(BIN / "propmap"), "wrench", str(LOGS / SEGMENT), "--vehicle", str(VEHICLE),
                                  "--out", str(Path(tmp) / "p.csv")], runs=5)
        out["props_cli"] = wall([str(BIN / "propmap"), "props"], runs=5)
    out["wrench_cli"]["ratio_to_props"] = out["wrench_cli"]["median_s"] / out["props_cli"]["median_s"]
    g = pm.generic_params()
    out["vehicle_wrench"] = {
        "48x16 uniform": in_process(g, pm.DEFAULT_DISCRETIZATION),
        "24x8 uniform": in_process(g, FLIGHT_DISCRETIZATION),
        "24x8 pitt-peters": in_process(g.replace(inflow="pitt-peters"), FLIGHT_DISCRETIZATION),
    }
    if "--fit" in sys.argv:
        veh = pm.read_vehicle(VEHICLE)
        logs = [read_flight_log(p) for p in sorted(LOGS.glob("*.mat"))]
        s = flight_samples(logs, veh, rate_hz=25)
        out["fit_flight"] = {}
        for jac in ("implicit", "differences"):  # the default Jacobian, and differences of the solver, in one run
            t = time.perf_counter()
            res = fit_flight(s, veh, air=pm.Air(rho=1.204), options=FitOptions(jacobian=jac))
            out["fit_flight"][jac] = {"samples": s.n, "seconds": time.perf_counter() - t,
                                      "residual_evaluations": res.nfev, "rotor_points": res.n_model_points,
                                      "names": list(res.names), "x": [float(x) for x in res.x],
                                      "rms_residual_N": float(np.sqrt(np.mean(res.residuals ** 2)))}
    if "--cg" in sys.argv:
        veh = pm.read_vehicle(VEHICLE)
        s = flight_samples([read_flight_log(p) for p in sorted(LOGS.glob("*.mat"))], veh, rate_hz=25)
        names = (*FLIGHT_FIT, "cg_x", "cg_y")
        t = time.perf_counter()
        res = fit_flight(s, veh, air=pm.Air(rho=1.204), options=FitOptions(names=names), moments=True)
        out["fit_flight_cg"] = {"samples": s.n, "seconds": time.perf_counter() - t, "propmap": pm.__file__,
                                "residual_evaluations": res.nfev, "rotor_points": res.n_model_points,
                                "names": list(res.names), "x": [float(x) for x in res.x],
                                "rms_residual_N": float(np.sqrt(np.mean(res.residuals ** 2)))}
    path = ROOT / "benchmarks" / "results" / "flight.json"
    path.parent.mkdir(exist_ok=True)
    with atomic_write(path) as fh:
        json.dump(out, fh, indent=2)
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fit", action="store_true")
    parser.add_argument("--cg", action="store_true")
    parser.parse_args()  # (main reads its flags from sys.argv)
    main()
