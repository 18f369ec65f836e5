"""Fitting load data at incidence: the rigid rotor's section fit against the default, which frees
the flapping too (identify.options.INPLANE_FIT), on held-out incidences or speeds.

Data: the oblique-flow fits of Gill & D'Andrea (Drones 3(4):77, 2019, Appendix A; data/published)
for the four catalogue propellers they measured, turned into loads by propmap.cases.gill2019_loads
(static point and total advance ratios 0.04-0.24 at incidences 0-90 deg, 5000 and 7000 rpm, or
5000 rpm alone). Each fit starts from and is held by the generic set without the propeller's
family and its prior (src/propmap/data/calibration.json), as `propmap validate --all` does
(which prints the first table).

    .venv/bin/python tools/incidence_fit.py [--one-rate] [--speed] [--rolling-moment]    # 5-70 s on 2 cores

Prints, per propeller and fit, the rms held-out error of thrust and in-plane force (of the
static thrust) and of torque (of the static torque), pooled over the six folds (incidence 15,
30, ..., 90 deg held out in turn; with ``--speed`` one fold instead: the points at total advance
ratios 0.16-0.24 predicted from those up to 0.12), and the fitted flap compliance of each fold:
the tables of docs/identification.md, "Load data at incidence". With ``--rolling-moment`` the loads
carry the published rolling moment as well: the two fits above fit the thrust, in-plane force and
torque and are scored on the rolling moment too (of the static thrust times R), and a third fits
all four (about 70 s).
"""

import argparse
import warnings

from propmap.cases import gill2019_incidence_fits


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--one-rate", action="store_true", help="5000 rpm only (default: 5000 and 7000)")
    ap.add_argument("--speed", action="store_true", help="advance ratios 0.16-0.24 predicted from those up to 0.12")
    ap.add_argument("--rolling-moment", action="store_true", help="score, and in a third fit fit, the rolling moment")
    args = ap.parse_args()
    rpm = (5000.0,) if args.one_rate else (5000.0, 7000.0)
    warnings.simplefilter("ignore")  # the fits' bound warnings (the compliance at 50 rad/(N m))
    fits = gill2019_incidence_fits("speed" if args.speed else "incidence", rpm, rolling_moment=args.rolling_moment)
    print(f"{'advance ratio 0.16-0.24 from 0-0.12' if args.speed else 'leave one incidence out'}, "
          f"{', '.join(f'{r:.0f}' for r in rpm)} rpm; rms held-out error, T and D of static T, Q of static Q"
          + (", M_R of static T times R" if args.rolling_moment else ""))
    for name, by_fit in fits.items():
        for label, e in by_fit.items():
            c = e["flap_compliance"]
            mr = f"M_R {100 * e['rms_rolling_moment']:5.2f}%  " if "rms_rolling_moment" in e else ""
            print(f"{name:13s} {label:32s} T {100 * e['rms_thrust']:5.2f}%  D {100 * e['rms_drag']:5.2f}%  "
                  f"Q {100 * e['rms_torque']:5.2f}%  {mr}flap compliance {min(c):.3g}-{max(c):.3g} rad/(N m)")


if __name__ == "__main__":
    main()
