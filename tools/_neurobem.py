"""Where the flight tools find the NeuroBEM quadrotor's flight logs (L. Bauersfeld, E. Kaufmann,
P. Foehn, S. Sun, D. Scaramuzza, "NeuroBEM: Hybrid Aerodynamic Quadrotor Model", RSS 2021):
four segments as .mat files, not bundled with propmap, looked for in
``../shared/data/neurobem_flights`` beside the repository checkout (docs/flight.md)."""

from __future__ import annotations

import sys
from pathlib import Path

#: the folder of the four segments
LOGS = Path(__file__).resolve().parents[2] / "shared" / "data" / "neurobem_flights"


def log_paths() -> list[Path]:
    """The segments' paths, sorted; exits with one line naming the folder where there are none
    (the tools ended in 'ValueError: no flight logs given' there: a docs audit, 2026-11-27)."""
    paths = sorted(LOGS.glob("*.mat"))
    if not paths:
        sys.exit(f"{Path(sys.argv[0]).name}: needs the NeuroBEM flight logs (.mat segments) in {LOGS}: they are not "
                 "bundled with propmap (docs/flight.md)")
    return paths
