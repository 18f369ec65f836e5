"""Validation over the catalogue: the numbers of docs/validation.md, with their run time.

Run:  .venv/bin/python benchmarks/validate_catalogue.py [--out-dir DIR]   (about 2 minutes on 2 cores:
      128 s of `propmap validate --all` on the 2-core AMD EPYC, 2026-11-30)

Same as ``propmap validate --all --out-dir benchmarks/results/validation``: held-out errors
of every calibration protocol for the 143 catalogue propellers with sweeps (UIUC Propeller
Data Site vol. 1, Brandt & Selig, AIAA 2011-1255; vol. 2, Deters, Ananda & Selig, AIAA
2014-2151) and the digitized published cases; adds the wall time and the CPU to
benchmarks/results/validation/timing.json (``--out-dir``: another folder, e.g. to reproduce the numbers
without touching a checkout's results; since 2026-12-02).
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

from propmap.cli.validate_all import PROTOCOLS, run_all
from propmap.io.atomic import atomic_write


def main(out: Path) -> None:
    t0 = time.perf_counter()
    run_all(list(PROTOCOLS), [], out, as_json=False)
    wall = time.perf_counter() - t0
    from bench_solver import cpu_name

    with atomic_write(out / "timing.json") as fh:
        json.dump({"wall_s": wall, "cpu": cpu_name(), "cores": os.cpu_count()}, fh, indent=1)
    print(f"validation over the catalogue: {wall:.0f} s on {os.cpu_count()} cores ({cpu_name()})")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out-dir", type=Path, default=Path(__file__).parent / "results" / "validation",
                        help="folder for the tables, figures and timing.json (default: benchmarks/results/validation)")
    main(parser.parse_args().out_dir)
