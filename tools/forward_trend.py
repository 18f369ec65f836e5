"""Which way does thrust go in edgewise flight at a fixed rotation rate? The measurements
propmap holds, and the shipped parameter sets' predictions.

1. NeuroBEM quadrotor flight logs (Bauersfeld et al., RSS 2021; the four segments, not bundled:
   ../shared/data/neurobem_flights, vehicle data/examples/neurobem_quadrotor.toml): the body
   force fitted by linear least squares to k Omega^2 - k_z Omega v_z + c Omega v_ip (RotorPy's
   terms) plus k_h |v_ip|^2 along each rotor axis (RotorPy's translational lift), leaving each
   log out in turn; k_h > 0 means thrust rising with in-plane speed. Compared with the
   generic set's prediction for the same (lumped) propeller at the logs' hover speed.
2. The catalogue: every calibrated propeller at a 100 m/s tip speed, T(10 m/s edgewise) /
   T(hover) - 1 with its own set and with the generic set (UIUC vol. 1 and 2 geometry).

    .venv/bin/python tools/forward_trend.py

Prints the numbers docs/simulators.md quotes ("Which trend is right").
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.identify.flight import flight_samples
from propmap.identify.flight_scores import _baseline_columns, _hub_velocities
from propmap.io.calibration import calibration
from propmap.io.flightlog import read_flight_log
from propmap.vehicle import read_vehicle
from propmap.vehicle import rotor_geometry
from _neurobem import log_paths  # (tools/, the script's folder)

ROOT = Path(__file__).resolve().parents[1]
TERMS = ("thrust", "drag", "kz")


def _design(samples, vehicle) -> np.ndarray:
    """RotorPy's terms and the translational lift k_h |v_ip|^2 along each axis, shape (N * 3, 4)."""
    arms, axes, _, _ = rotor_geometry(vehicle)  # about the centre of mass; unit axes
    V = _hub_velocities(samples, arms)
    v_ip = V - np.einsum("nkj,kj->nk", V, axes)[..., None] * axes[None]
    kh = np.einsum("nk,kj->nj", (v_ip**2).sum(-1), axes)
    return np.concatenate([_baseline_columns(samples, vehicle, TERMS), kh[..., None]], axis=-1).reshape(-1, 4)


def flight_logs() -> None:
    veh = read_vehicle(ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml")
    logs = [read_flight_log(p) for p in log_paths()]
    s = flight_samples(logs, veh)
    folds = []
    for k in range(len(logs)):
        train = s.select(s.log_index != k)
        folds.append(np.linalg.lstsq(_design(train, veh), train.force.reshape(-1), rcond=None)[0])
    c = np.linalg.lstsq(_design(s, veh), s.force.reshape(-1), rcond=None)[0]
    om_h = math.sqrt(veh.weight / len(veh.rotors) / c[0])
    print(f"NeuroBEM logs: {s.n} samples, speeds up to {s.speed.max():.1f} m/s")
    print("  k_h leaving each log out [N/(m/s)^2]: " + ", ".join(f"{f[3]:.5f}" for f in folds))
    print(f"  all logs: k = {c[0]:.4g}, k_h = {c[3]:.4g}; hover {om_h:.0f} rad/s; thrust rise at 10 m/s edgewise "
          f"k_h 10^2 / (k Omega_h^2) = {c[3] * 100 / (c[0] * om_h**2):+.1%}")
    r = pm.rotor_loads(veh.rotors[0].propeller, pm.generic_params(), om_h, np.array([0.0, 10.0]), math.pi / 2)
    print(f"  the generic set for this propeller, same point: {r.thrust[1] / r.thrust[0] - 1:+.1%}")


def catalogue() -> None:
    gen = pm.generic_params()
    rows = []
    for name, c in sorted(calibration()["propellers"].items()):
        prop = pm.load_propeller(name)
        om = 100.0 / prop.radius
        rise = []
        for p in (c.params, gen):
            r = pm.rotor_loads(prop, p, om, np.array([0.0, 10.0]), math.pi / 2, air=c.air, on_failure="flag")
            rise.append(r.thrust[1] / r.thrust[0] - 1)
        rows.append((name, *rise))
    a = np.array([r[1:] for r in rows])
    for k, label in enumerate(("calibrated sets", "generic set")):
        q = np.percentile(a[:, k], [10, 50, 90])
        print(f"catalogue, {label}: thrust falls edgewise for {int(np.sum(a[:, k] < 0))} of {len(rows)}; "
              f"10/50/90th percentile {q[0]:+.1%} / {q[1]:+.1%} / {q[2]:+.1%}")
    name, cal, gen_ = next(r for r in rows if r[0] == "apce_8x6")
    print(f"apce_8x6: calibrated {cal:+.1%}, generic {gen_:+.1%}")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    flight_logs()
    catalogue()
