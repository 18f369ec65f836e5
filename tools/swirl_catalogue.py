"""Swirl on the catalogue: `propmap validate --all`'s protocols with and without the swirl option.

    .venv/bin/python tools/swirl_catalogue.py [--volume 1|2] [--swirl-only]   # about 10 minutes on 2 cores

Every generic set, and so every fit started from it and every blind prediction, is given
``swirl = True`` (RotorOptions.swirl, docs/models.md); the generic sets and the population
prior stay those calibrated without swirl (leave-one-family-out, as `validate --all`).
Prints CT median / 90th percentile / worst (% of static CT) and the CP median per volume
for leave one sweep out, static + lowest-rpm sweeps, static only and blind, without and
with swirl: the table of docs/models.md, "Swirl". Data: UIUC Propeller Data Site vol. 1
(Brandt & Selig, AIAA 2011-1255) and the bundled part of vol. 2 (Deters, Ananda & Selig,
AIAA 2014-2151); the four CFNQ propellers (static runs only) are not scored.

With the defaults recalibrated with swirl (in a scratch copy of the repository, whose
calibration it overwrites: ``tools/calibrate_catalogue.py --swirl``, then this tool with
``--swirl-only`` there), the same protocols measure swirl with defaults fitted for it.
"""

from __future__ import annotations

import argparse

from propmap.cli.validate_all import run_catalogue
from propmap.io.catalogue import catalogue

PROTOCOLS = ("loso", "lowest", "static", "blind")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--volume", type=int, choices=(1, 2), default=None, help="one UIUC volume (default: both)")
    ap.add_argument("--swirl-only", action="store_true", help="only with swirl (defaults recalibrated with it)")
    args = ap.parse_args()
    cat = catalogue()
    names = sorted(n for n, e in cat.items() if e.static_files and len(e.sweep_files) >= 2
                   and (args.volume is None or e.volume == args.volume))
    for swirl in (True,) if args.swirl_only else (False, True):
        res = run_catalogue(PROTOCOLS, names, progress=False, rotor_options={"swirl": swirl})
        for vol, s in res["by_volume"].items():
            cells = "; ".join(f"{p} {100 * s[p]['ct']['median']:.2f} / {100 * s[p]['ct']['p90']:.1f} / "
                              f"{100 * s[p]['ct']['worst']:.1f} (CP {100 * s[p]['cp']['median']:.2f})"
                              for p in PROTOCOLS)
            print(f"swirl {'on ' if swirl else 'off'} {vol}: {cells}", flush=True)


if __name__ == "__main__":
    main()
