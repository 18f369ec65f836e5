"""Does an accelerometer away from the centre of mass explain the flight fit's force errors?

An accelerometer at r from the centre of mass reads a_s + dw/dt x r + w x (w x r), so the
measured force m a_s would carry m (dw/dt x r + w x (w x r)), linear in r. The default flight
fit's force residuals (``fit_flight`` on all four NeuroBEM segments, 25 samples a second, the
logs' air 1.204 kg/m^3; Bauersfeld et al., "NeuroBEM: Hybrid Aerodynamic Quadrotor Model",
RSS 2021; ../shared/data/neurobem_flights) are regressed on those terms: in sample, and each
log predicted with the arm fitted on the other three (the rotor model itself fitted on all
four, so the held-out gains are an upper bound).

    .venv/bin/python tools/flight_imu_arm.py      # about 50 s on 2 cores (2026-12-02; 105 s under another job's load)

Findings (2026-11-25): docs/flight.md, "Where it is still wrong".
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.identify.flight import fit_flight, fitted_body_drag, flight_samples, predict_flight
from propmap.io.flightlog import read_flight_log
from propmap.vehicle._jacobians import cross_matrix
from _neurobem import log_paths  # (tools/, the script's folder)

ROOT = Path(__file__).resolve().parents[1]
VEHICLE = ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml"
RATE_HZ = 25.0


def pooled(e: np.ndarray) -> float:
    """NeuroBEM's Table II F: sqrt of the mean of the three axes' mean square errors [N]."""
    return float(np.sqrt(np.mean(e**2)))


def main() -> None:
    veh = pm.read_vehicle(VEHICLE)
    paths = log_paths()
    logs = [read_flight_log(p) for p in paths]
    s = flight_samples(logs, veh, rate_hz=RATE_HZ)
    wdot = []  # the angular acceleration at the same samples as flight_samples takes them
    for log in logs:
        step = max(1, int(round(log.rate_hz / RATE_HZ)))
        wd = log.angular_acceleration
        wdot.append((wd if wd is not None else np.gradient(log.angular_velocity, log.t, axis=0))[::step])
    wdot = np.concatenate(wdot)
    w = s.angular_velocity
    # the measured force's error from an arm r: m (dw/dt x r + w x (w x r)) = A r, A shape (N, 3, 3)
    A = veh.mass * (cross_matrix(wdot) + cross_matrix(w) @ cross_matrix(w))
    air = pm.Air(rho=1.204)
    res = fit_flight(s, veh, air=air)
    err = predict_flight(s, veh, res.params, body=fitted_body_drag(res), air=air).force - s.force
    print(f"{s.n} samples; rms |w| {np.sqrt(np.mean(np.sum(w**2, 1))):.2f} rad/s, "
          f"rms |dw/dt| {np.sqrt(np.mean(np.sum(wdot**2, 1))):.1f} rad/s^2")
    r, *_ = np.linalg.lstsq(A.reshape(-1, 3), -err.reshape(-1), rcond=None)
    print(f"in sample: F {pooled(err):.3f} N -> {pooled(err + A @ r):.3f} N with the arm "
          f"({', '.join(f'{1000 * x:+.1f}' for x in r)}) mm")
    for k, path in enumerate(paths):
        train, test = s.log_index != k, s.log_index == k
        rk, *_ = np.linalg.lstsq(A[train].reshape(-1, 3), -err[train].reshape(-1), rcond=None)
        print(f"held out {path.stem}: arm ({', '.join(f'{1000 * x:+.1f}' for x in rk)}) mm, "
              f"F {pooled(err[test]):.3f} -> {pooled(err[test] + A[test] @ rk):.3f} N")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
