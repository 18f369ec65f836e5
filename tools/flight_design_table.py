"""Leave-one-log-out scores of the flight fit's design table (docs/flight.md, "What the default
fits, and why"), with the shipped calibration.

Data: the four NeuroBEM segments (Bauersfeld et al., "NeuroBEM: Hybrid Aerodynamic Quadrotor
Model", RSS 2021; ../shared/data/neurobem_flights) and the bundled vehicle
data/examples/neurobem_quadrotor.toml, at the logs' air density 1.204 kg/m^3. Each row fits
its names to three logs and predicts the fourth (``cross_validate_flight``: 25 samples a
second, the vehicle file's 33 ms motor lag), from the generic set; rows with
``flap_compliance`` start it at FLAP_START (1 rad/(N m)), and T and U switch the generic
lift's Reynolds terms off (re_exp_lift = alpha_L0_re = 0).

    .venv/bin/python tools/flight_design_table.py [--differences] [ROW ...]    # all rows: about 5-7 min on 2 cores

Prints per row the pooled held-out F [N], the four logs' F and the fitted compliance per fold.
Rows C and WP (Pitt-Peters inflow) run only when named: a linear inflow's loads cost 2.4x the
uniform inflow's (docs/solver.md); rows C and WP take about 1 and 2 minutes. So does row WN
(W without the skewed wake's in-plane induced velocity, ``inplane_induction``, the cambered
default since 2026-11-25: the default before), about 1 minute, and row WD (W with Gormont's
dynamic stall, ``dynamic_stall = 1.5``; with its implicit derivatives since 2026-11-26, about as
long as W).
``--differences``: the fits' Jacobians by central differences of the solver instead of the
implicit derivatives (an A/B of the two; the same optimum).
"""

import argparse
import time
import warnings
from pathlib import Path

import propmap as pm
from propmap.core.airfoil import Air
from propmap.identify import FitOptions
from propmap.identify.flight import cross_validate_flight, flight_samples
from propmap.identify.options import FLAP_START
from propmap.io.flightlog import read_flight_log
from propmap.vehicle import read_vehicle
from _neurobem import log_paths  # (tools/, the script's folder)

ROOT = Path(__file__).resolve().parents[1]
VEHICLE = ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml"
INPLANE = ("drag_area_x", "drag_area_y", "wash_factor")


def rows(g) -> dict:
    """Row label -> (fitted names, base set), as the table describes them."""
    flap = g.replace(flap_compliance=FLAP_START)
    return {
        "W": (("collective", "cl_alpha", "alpha_L0_re") + INPLANE, g),
        "A": (("collective", "flap_compliance"), flap),
        "B": (("collective", "cl_alpha", "flap_compliance"), flap),
        "D": (("collective", "flap_compliance", "drag_area_x", "drag_area_y", "drag_area_z", "wash_factor"), flap),
        "P": (("collective", "cl_alpha", "flap_compliance", "alpha_L0_re"), flap),
        "T": (("collective", "cl_alpha", "flap_compliance") + INPLANE, flap.replace(re_exp_lift=0.0, alpha_L0_re=0.0)),
        "U": (("collective", "cl_alpha") + INPLANE, g.replace(re_exp_lift=0.0, alpha_L0_re=0.0)),
        "J": (("collective", "flap_compliance", "cl_max"), flap),
        "K": (("collective", "flap_compliance", "cl_max", "stall_delay"), flap),
        "C": (("collective", "flap_compliance"), flap.replace(inflow="pitt-peters")),
        "WP": (("collective", "cl_alpha", "alpha_L0_re") + INPLANE, g.replace(inflow="pitt-peters")),
        "WN": (("collective", "cl_alpha", "alpha_L0_re") + INPLANE, g.replace(inplane_induction=False)),
        "WD": (("collective", "cl_alpha", "alpha_L0_re") + INPLANE, g.replace(dynamic_stall=1.5)),
    }


def main(keys, differences: bool) -> None:
    warnings.simplefilter("ignore")  # the catalogue's coverage notes
    vehicle = read_vehicle(VEHICLE)
    samples = flight_samples([read_flight_log(p) for p in log_paths()], vehicle)
    air = Air(rho=1.204)
    table = rows(pm.generic_params().replace(air=air))
    if any(k not in table for k in keys):
        raise SystemExit(f"flight_design_table.py: unknown row(s) {[k for k in keys if k not in table]}; the rows: "
                         f"{', '.join(table)}")
    jacobian = "differences" if differences else "implicit"
    for key in keys or [k for k in table if k not in ("C", "WP", "WN", "WD")]:
        names, base = table[key]
        t = time.perf_counter()
        cv = cross_validate_flight(samples, vehicle, base=base, air=air,
                                   options=FitOptions(names=names, progress=False, jacobian=jacobian))
        comp = [f["x"].get("flap_compliance") for f in cv["folds"]]
        print(f"{key}: pooled held-out F {cv['pooled']['model']:.3f} N; per log "
              + " / ".join(f"{f['model']['F']:.3f}" for f in cv["folds"])
              + ("; compliance " + " / ".join(f"{c:.3g}" for c in comp) if comp[0] is not None else "")
              + f" ({time.perf_counter() - t:.0f} s)", flush=True)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rows", nargs="*", help="the table's rows to run (default: all but C, WP, WN, WD)")
    parser.add_argument("--differences", action="store_true", help="the Jacobian by differences")
    a = parser.parse_args()
    main(a.rows, a.differences)
