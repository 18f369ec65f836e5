"""Which parameters should a static-only fit free? The catalogue's static protocol (fit the
static run, predict every sweep; leave-one-family-out defaults and prior) with the default
(the 8 of CAMBERED_FIT_RE under the population prior) or a candidate subset freed under the
prior, the others held at the generic set's values (docs/identification.md).

    .venv/bin/python tools/static_fit_subsets.py                      # the default
    CAND=alpha_L0,cd_min .venv/bin/python tools/static_fit_subsets.py  # a subset

Prints the CT and CP held-out error (median / 90th percentile / worst) over the catalogue
(UIUC vol. 1 and 2); about 30 s on 2 cores. The subset is patched into the fit in this module
so that the worker processes (spawned, re-importing it) use it too.
"""

from __future__ import annotations

import os

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

if __name__ == "__main__":
    from propmap.cli.validate_all import run_catalogue

    s = run_catalogue(["static"], [])["summary"]["static"]
    print(CAND, *(f"{q.upper()} " + " / ".join(f"{100 * s[q][k]:.1f}" for k in ("median", "p90", "worst")) + "%"
                  for q in ("ct", "cp")))
