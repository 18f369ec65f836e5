"""Leave one maker out: the catalogue's defaults refitted without every family of one maker.

The shipped validation (``propmap validate --all``) holds out one UIUC family at a time
(apce, apcsp, gwsdd, ...: src/propmap/data/calibration.json, ``generic_folds``). A maker's
other product lines stay in the generic set and the prior that predict the family: APC's
four lines (electric, sport, slow flyer, 29ff) are 59 of the 143 calibrated propellers. This
tool measures what that is worth: for each maker with two families or more it refits the
generic set and the population prior without all of the maker's families (the calibration's
steps 2-3, tools/calibrate_catalogue.py, from the shipped single-propeller fits), then scores
the maker's propellers blind and with static + lowest sweep fits under both folds. Run from
the repository root (about 2 minutes on the 2-core machine):

    .venv/bin/python tools/maker_folds.py
    .venv/bin/python tools/maker_folds.py --control   # the size-matched control of APC's figure, ~1 minute

``--control`` asks whether APC's blind figure moves because the maker fold is small (84
propellers without APC, 113-142 in a family fold): each APC family is predicted blind by a
generic set fitted to 84 propellers that keep APC's other lines, the rest drawn at random
from the other makers (seed 1).

Errors are issue 15's metric: rms (CT_model - CT_measured) / static CT over the predicted
sweep points (propmap.validation.cross_validate). Data: UIUC Propeller Data Site vol. 1
(Brandt & Selig, AIAA 2011-1255) and the part of vol. 2 in the repository (Deters, Ananda &
Selig, AIAA 2014-2151), as bundled. Results: docs/validation.md, Leave one maker out.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import calibrate_catalogue as cc  # noqa: E402

from propmap.io.calibration import generic_without, params_from_si, population, population_from_dict  # noqa: E402
from propmap.io.catalogue import catalogue  # noqa: E402
from propmap.validation import cross_validate  # noqa: E402

#: UIUC family codes by maker (the makers with two families or more; the DA4002, DA4022 and
#: DA4052 blades are UIUC's own designs, Deters, Ananda & Selig 2014)
MAKERS = {
    "APC": ("apce", "apcsf", "apcsp", "apc29ff"),
    "Graupner": ("grcp", "grcsp", "grsn"),
    "GWS": ("gwsdd", "gwssf"),
    "Master Airscrew": ("ma", "mae", "magf", "mas"),
    "MicroInvent": ("mi", "mit"),
    "UIUC DA designs": ("da4002", "da4022", "da4052"),
}
PROTOCOLS = ("blind", "lowest")


def _stats(x) -> str:
    x = 100 * np.asarray(x)
    return f"{np.median(x):.1f} / {np.percentile(x, 90):.1f} / {x.max():.1f}%"


def _setup():
    """The calibration file (its single-propeller fits are the raw file's), the catalogue, the
    calibrated propellers' names and their data."""
    cal = json.loads(cc.OUT.read_text())
    names = sorted(cal["propellers"])
    return cal, catalogue(), names, {n: cc._data(n) for n in names}


def control(seed: int = 1) -> None:
    """APC's blind error with a generic set of the maker fold's size that keeps APC's other lines."""
    cal, cat, names, data = _setup()
    apc = MAKERS["APC"]
    rng = np.random.default_rng(seed)
    size = sum(cat[n].family not in apc for n in names)  # the maker fold's
    errs = []
    for fam in apc:
        held = [n for n in names if cat[n].family == fam]
        kept = [n for n in names if cat[n].family in apc and cat[n].family != fam]
        others = [n for n in names if cat[n].family not in apc]
        members = kept + list(rng.choice(others, size=size - len(kept), replace=False))
        generic = params_from_si(cc._generic(members, cal["single_fits"], data)[0])
        e = [cross_validate(*data[n], generic, protocols=("blind",))["blind"]["rms_ct"] for n in held]
        errs += e
        print(f"{fam} ({len(held)}): blind {_stats(e)} with {len(members)} propellers, {len(kept)} of them APC",
              flush=True)
    print(f"APC ({len(errs)}), size-matched family folds: blind {_stats(errs)}")


def main() -> None:
    cal, cat, names, data = _setup()
    single = cal["single_fits"]
    print("maker (propellers): protocol, family folds -> maker fold, CT median / 90th percentile / worst")
    for maker, families in MAKERS.items():
        t0 = time.perf_counter()
        held = [n for n in names if cat[n].family in families]
        members = [n for n in names if n not in held]
        p, pop, *_ = cc._generic(members, single, data)
        generic_m = params_from_si(p)
        pop_m = population_from_dict(pop)
        errs = {(k, q): [] for k in ("family", "maker") for q in PROTOCOLS}
        for n in held:
            d, prop = data[n]
            fam = cross_validate(d, prop, generic_without(n)[0], protocols=PROTOCOLS, population=population(n))
            mak = cross_validate(d, prop, generic_m, protocols=PROTOCOLS, population=pop_m)
            for q in PROTOCOLS:
                errs[("family", q)].append(fam[q]["rms_ct"])
                errs[("maker", q)].append(mak[q]["rms_ct"])
        for q in PROTOCOLS:
            print(f"{maker} ({len(held)}): {q}, {_stats(errs[('family', q)])} -> {_stats(errs[('maker', q)])}",
                  flush=True)
        print(f"  ({len(members)} propellers in the maker fold's generic set, {time.perf_counter() - t0:.0f} s)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--control", action="store_true", help="the size-matched control of APC's figure")
    control() if parser.parse_args().control else main()
