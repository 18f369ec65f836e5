"""Which parameters should a static-only fit free? The catalogue's static protocol (fit the
static run, predict every sweep; leave-one-family-out defaults and prior) with the default
(the 3 leading directions of the 8 of CAMBERED_FIT_RE against the population prior,
identify/directions.py), another number of directions, or a candidate subset of names freed
under the prior, the others held at the generic set's values (docs/identification.md).

    .venv/bin/python tools/static_fit_subsets.py                      # the default
    DIRECTIONS=0 .venv/bin/python tools/static_fit_subsets.py         # all 8 under the prior
    DIRECTIONS=2 .venv/bin/python tools/static_fit_subsets.py         # 2 directions
    CAND=alpha_L0,cd_min .venv/bin/python tools/static_fit_subsets.py  # a subset

Prints the CT and CP held-out error (median / 90th percentile / worst, and the share of
propellers within 3 / 5 / 10% of static CT) over the catalogue (UIUC vol. 1 and 2) and per
volume; about 10 s on 2 cores. The choice is patched into the fit in this module so that the
worker processes (spawned, re-importing it) use it too.
"""

from __future__ import annotations

import argparse
import os

import propmap.identify.directions as D
import propmap.identify.fit as F

CAND = os.environ.get("CAND", "base")
if CAND != "base":
    _names = tuple(CAND.split(","))
    _orig = F._default_names

    def _patched(base, options, data_kind="rates"):
        if options.names is None and data_kind == "static" and options.prior:
            return _names
        return _orig(base, options, data_kind)

    F._default_names = _patched
if "DIRECTIONS" in os.environ:
    D.STATIC_DIRECTIONS = int(os.environ["DIRECTIONS"])


def _row(rows) -> str:
    import numpy as np

    from propmap.cli.validate_all import summarize

    out = []
    for q in ("ct", "cp"):
        s = summarize([r["static"][f"rms_{q}"] for r in rows])
        out.append(f"{q.upper()} " + " / ".join(f"{100 * s[k]:.1f}" for k in ("median", "p90", "worst")) + "%")
    ct = np.array([r["static"]["rms_ct"] for r in rows])
    out.append("within 3/5/10% " + " / ".join(f"{100 * np.mean(ct <= t):.0f}" for t in (0.03, 0.05, 0.10)) + "%")
    return "  ".join(out)


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    from propmap.cli.validate_all import run_catalogue

    rows = run_catalogue(["static"], [], progress=False)["propellers"]
    label = (CAND if CAND != "base" else f"{D.STATIC_DIRECTIONS} directions" if D.STATIC_DIRECTIONS
             else "8 under the prior")
    print(f"{label} ({len(rows)}):", _row(rows))
    for v in sorted({r["volume"] for r in rows}):
        sub = [r for r in rows if r["volume"] == v]
        print(f"  vol. {v} ({len(sub)}):", _row(sub))
