"""Fitting load data at incidence: the rigid rotor's section fit against the default, which frees
the flapping too (identify.options.INPLANE_FIT), by leaving one incidence out.

Data: the oblique-flow fits of Gill & D'Andrea (Drones 3(4):77, 2019, Appendix A; data/published)
for the four catalogue propellers they measured, turned into loads by propmap.cases.gill2019_loads
(static point and total advance ratios 0.04-0.24 at incidences 0-90 deg, 5000 and 7000 rpm, or
5000 rpm alone). Each fit starts from and is held by the generic set without the propeller's
family and its prior (src/propmap/data/calibration.json), as `propmap validate --all` does.

    .venv/bin/python tools/incidence_fit.py [--one-rate] [--speed]    # about 15 s on 2 cores

Prints, per propeller and fit, the rms held-out error of thrust and in-plane force (of the
static thrust) and of torque (of the static torque), pooled over the six folds (incidence 15,
30, ..., 90 deg held out in turn; with ``--speed`` one fold instead: the points at total advance
ratios 0.16-0.24 predicted from those up to 0.12), and the fitted flap compliance of each fold:
the tables of docs/identification.md, "Load data at incidence".
"""

import argparse
import warnings

import numpy as np

import propmap as pm
from propmap.cases import gill2019_coefficients, gill2019_loads
from propmap.identify import FitOptions, fit_loads
from propmap.identify.options import CAMBERED_FIT
from propmap.io.calibration import generic_without, population

warnings.simplefilter("ignore")  # the fits' bound warnings (the compliance at 50 rad/(N m))
AIR = pm.Air(rho=1.225)
FITS = {"rigid: the section alone": CAMBERED_FIT, "default: section + flapping": None}


def held_out(name: str, rpm, names, speed: bool = False) -> tuple[dict, list]:
    """rms held-out errors (T, D of static T; Q of static Q) and each fold's flap compliance."""
    prop, data = pm.load_propeller(name), gill2019_loads(name, rpm, air=AIR)
    base, pop = generic_without(name)[0], population(without=name)
    static = data.airspeed == 0
    T0, Q0 = data.measured["thrust"][static].mean(), data.measured["torque"][static].mean()
    inc = np.round(np.degrees(data.incidence)).astype(int)
    advance = data.airspeed / (data.omega * prop.radius)
    folds = [advance < 0.14] if speed else [inc != held for held in sorted(set(inc[inc > 0]))]
    err, compliance = {"T": [], "D": [], "Q": []}, []
    for train in folds:
        p = fit_loads(data.subset(train), prop, base=base, air=AIR,
                      options=FitOptions(population=pop, names=names)).params
        compliance.append(p.flap_compliance)
        r = pm.rotor_loads(prop, p, data.omega[~train], data.airspeed[~train], data.incidence[~train], air=AIR)
        err["T"].append((r.thrust - data.measured["thrust"][~train]) / T0)
        err["D"].append((r.drag - data.measured["drag"][~train]) / T0)
        err["Q"].append((r.torque - data.measured["torque"][~train]) / Q0)
    return {k: float(np.sqrt(np.mean(np.concatenate(v) ** 2))) for k, v in err.items()}, compliance


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--one-rate", action="store_true", help="5000 rpm only (default: 5000 and 7000)")
    ap.add_argument("--speed", action="store_true", help="advance ratios 0.16-0.24 predicted from those up to 0.12")
    args = ap.parse_args()
    rpm = (5000.0,) if args.one_rate else (5000.0, 7000.0)
    print(f"{'advance ratio 0.16-0.24 from 0-0.12' if args.speed else 'leave one incidence out'}, "
          f"{', '.join(f'{r:.0f}' for r in rpm)} rpm; rms held-out error, T and D of static T, Q of static Q")
    for name in gill2019_coefficients():
        for label, names in FITS.items():
            e, c = held_out(name, rpm, names, args.speed)
            print(f"{name:13s} {label:28s} T {100 * e['T']:5.2f}%  D {100 * e['D']:5.2f}%  Q {100 * e['Q']:5.2f}%  "
                  f"flap compliance {min(c):.3g}-{max(c):.3g} rad/(N m)", flush=True)


if __name__ == "__main__":
    main()
