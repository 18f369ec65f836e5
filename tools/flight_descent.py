"""Where the vertical force of the flight fit goes wrong: the rotors in descent, measured.

Data: the four NeuroBEM segments (Bauersfeld et al., "NeuroBEM: Hybrid Aerodynamic
Quadrotor Model", RSS 2021; ../shared/data/neurobem_flights), the bundled vehicle
data/examples/neurobem_quadrotor.toml, the generic set's air (rho = 1.225 kg/m^3; the CLI
examples in docs/flight.md use the logs' 1.204), 25 samples a second.

    .venv/bin/python tools/flight_descent.py          # about 20 s on 2 cores
    .venv/bin/python tools/flight_descent.py --cv     # and the leave-one-log-out fits, about 6 min

Prints the numbers of docs/flight.md, "The vertical force in hard manoeuvres":

1. the default fit to all four logs (in-sample): the vertical-force error by the rotors' mean
   axial velocity through the disk (along the rotor axis; negative: the flow comes from
   below, a descent), with the mean in-plane speed, the thrust per rotor, the descent ratio
   and the working states (core/states.py), and the share of the squared Fz error that the
   samples in descent carry;
2. the same parameters with Glauert's momentum in descent instead of the empirical curve;
3. with ``--cv``: leave-one-log-out (each log predicted by a fit to the other three) of the
   default fit, of the default with Glauert's momentum in descent, and of the default with
   ``cl_max`` or ``stall_delay`` freed; pooled F [N], per held-out log, and the freed
   parameter's value per fold.
"""

from __future__ import annotations

import argparse
from dataclasses import replace
from pathlib import Path

import numpy as np

from propmap.identify import FitOptions
from propmap.identify.flight import (FLIGHT_FIT, cross_validate_flight, fit_flight, fitted_body_drag, fitted_vehicle,
                                     flight_samples, predict_flight)
from propmap.identify.flight_scores import _hub_velocities
from propmap.io.calibration import generic_params
from propmap.io.flightlog import read_flight_log
from propmap.vehicle import read_vehicle
from propmap.vehicle import rotor_geometry
from _neurobem import log_paths  # (tools/, the script's folder)

ROOT = Path(__file__).resolve().parents[1]
VEHICLE = ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml"
BINS = ((-20, -4), (-4, -2), (-2, -1), (-1, 0), (0, 1), (1, 2), (2, 4), (4, 20))


def rms(a) -> float:
    """Root mean square over every entry."""
    return float(np.sqrt(np.mean(np.square(a))))


def main(cv: bool) -> None:
    vehicle = read_vehicle(VEHICLE)
    logs = [read_flight_log(p) for p in log_paths()]
    s = flight_samples(logs, vehicle)
    base = generic_params()
    res = fit_flight(s, vehicle, base=base)
    body, veh = fitted_body_drag(res), fitted_vehicle(vehicle, res)
    w = predict_flight(s, veh, res.params, body=body)
    e = w.force - s.force
    arms, axes, _, _ = rotor_geometry(veh)  # about the centre of mass; unit axes
    V = _hub_velocities(s, arms)
    v_ax = np.einsum("nkj,kj->nk", V, axes)
    v_ip = np.linalg.norm(V - v_ax[..., None] * axes[None], axis=-1)
    va = v_ax.mean(axis=1)
    T = np.stack([ld.thrust for ld in w.loads], axis=1)
    state = np.stack([ld.state for ld in w.loads], axis=1)
    k = np.stack([ld.descent_ratio for ld in w.loads], axis=1)
    print(f"1. default fit, in-sample ({s.n} samples): F {rms(e):.4f} N, Fz {rms(e[:, 2]):.4f} N")
    print("   axial velocity [m/s], n, Fz error mean / rms [N], in-plane speed [m/s], thrust per rotor [N], "
          "descent ratio, rotor-samples per state (normal, vortex ring, turbulent wake, windmill brake)")
    for lo, hi in BINS:
        m = (va >= lo) & (va < hi)
        if m.sum() >= 5:
            print(f"   {lo:+3d}..{hi:+3d}  {m.sum():5d}  {e[m, 2].mean():+.3f} / {rms(e[m, 2]):.3f}  "
                  f"{v_ip[m].mean():4.1f}  {T[m].mean():.2f}  {np.mean(k[m]):+.2f}  "
                  f"{np.bincount(state[m].ravel(), minlength=4)}")
    d = va < -2
    print(f"   samples below -2 m/s: {d.sum()} of {s.n} ({d.mean():.1%}), carrying "
          f"{np.sum(e[d, 2] ** 2) / np.sum(e[:, 2] ** 2):.0%} of the squared Fz error")
    wg = predict_flight(s, veh, replace(res.params, descent="glauert"), body=body)
    eg = wg.force - s.force
    print(f"2. the same parameters, Glauert's momentum in descent: F {rms(eg):.4f} N, Fz {rms(eg[:, 2]):.4f} N; "
          f"below -2 m/s Fz error mean {eg[d, 2].mean():+.3f} (empirical {e[d, 2].mean():+.3f})")
    if not cv:
        return
    print("3. leave-one-log-out: pooled F [N], per held-out log, the freed parameter per fold")
    runs = (("default (empirical descent)", base, FLIGHT_FIT), ("Glauert's momentum in descent",
            replace(base, descent="glauert"), FLIGHT_FIT), ("cl_max freed", base, FLIGHT_FIT + ("cl_max",)),
            ("stall_delay freed", base, FLIGHT_FIT + ("stall_delay",)))
    for name, b, names in runs:
        out = cross_validate_flight(s, vehicle, base=b, options=FitOptions(names=names))
        folds = [f["model"]["F"] for f in out["folds"]]
        extra = [{n: round(v, 3) for n, v in f["x"].items() if n not in FLIGHT_FIT} for f in out["folds"]]
        print(f"   {name:<32} {out['pooled']['model']:.4f}  " + " ".join(f"{x:.3f}" for x in folds)
              + (f"  {extra}" if any(extra) else ""), flush=True)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cv", action="store_true", help="and the leave-one-log-out fits (about 6 min)")
    main(parser.parse_args().cv)
