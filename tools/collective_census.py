"""How the calibrated sets respond to the collective, and how they carry to a sibling propeller.

Data: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255) and the bundled part of
vol. 2 (Deters, Ananda & Selig, AIAA 2014-2151), through the shipped calibration.

    .venv/bin/python tools/collective_census.py      # about 1 minute on 2 cores

Prints the census numbers of docs/models.md, "The calibrated sets do not pin the response to
the collective" (the paragraph's other figures, the generic set's slope, UIUC's static CT and
the stall_delay recalibration, were measured separately): the count of calibrated sets whose
static thrust falls as the collective rises (dT/d(collective) < 0 at a tip speed of 60 m/s,
implicit derivatives), the median slope, the
static-CT error of each set used on a sibling of the same family and diameter but another
pitch (and of the generic set without the family on the same propellers), and the
oblique-flow case's ratios (docs/validation.md).
"""

import argparse
import math
import re
import warnings

import numpy as np

import propmap as pm
from propmap.cases import run_case
from propmap.io.calibration import generic_without

warnings.simplefilter("ignore")  # the catalogue's coverage notes
TIP_SPEED = 60.0  # [m/s]


def collective_slopes(names) -> dict:
    """dT/d(collective) / T at rest [1/deg] of each propeller's calibrated set."""
    out = {}
    for n in names:
        prop, p = pm.load_propeller(n), pm.default_params(n)
        r = pm.rotor_loads(prop, p, TIP_SPEED / prop.radius, 0.0, 0.0, derivatives=("collective",))
        out[n] = float(r.derivative("thrust", "collective") / r.thrust) * math.pi / 180
    return out


def _static_error(prop, p, run) -> float:
    """rms (CT_model - CT) / mean CT over a static run."""
    n_rev = np.asarray(run.rpm) / 60
    zero = np.zeros_like(n_rev)
    r = pm.rotor_loads(prop, p, 2 * math.pi * n_rev, zero, zero)
    ct = r.thrust / (p.air.rho * n_rev**2 * prop.diameter**4)
    return float(np.sqrt(np.mean(((ct - run.CT) / np.mean(run.CT)) ** 2)))


def sibling_errors(cat, names) -> tuple[list, list]:
    """Static-CT errors (rms / mean static CT) of each set used on every sibling of its family
    and diameter with another pitch, and of the generic set without the family on the same
    propellers (blind)."""
    groups = {}
    for n in names:
        m = re.match(r"([a-z0-9]+)_([0-9.]+)x([0-9.]+)$", n)
        if m:
            groups.setdefault((m.group(1), m.group(2)), []).append(n)
    errs, blind = [], []
    for members in groups.values():
        if len(members) < 2:
            continue
        for b in members:
            prop, run = pm.load_propeller(b), cat[b].static_runs()[0]
            blind.append(_static_error(prop, generic_without(b)[0], run))
            errs.extend(_static_error(prop, pm.default_params(a), run) for a in members if a != b)
    return errs, blind


def main() -> None:
    cat = pm.catalogue()
    names = [n for n in sorted(cat) if pm.default_params(n).label.startswith("calibrated")]
    slopes = collective_slopes(names)
    falling = sum(s < 0 for s in slopes.values())
    print(f"calibrated sets: {len(names)}; static thrust falling with the collective (tip {TIP_SPEED:g} m/s): "
          f"{falling}; median slope {100 * np.median(list(slopes.values())):+.2f} %/deg")
    errs, blind = sibling_errors(cat, names)
    print(f"a set on a sibling of another pitch, static CT: {len(errs)} pairs, rms error median "
          f"{100 * np.median(errs):.1f}%, 90th percentile {100 * np.percentile(errs, 90):.1f}%; the generic set "
          f"without the family on the same {len(blind)} propellers: {100 * np.median(blind):.1f}%, "
          f"{100 * np.percentile(blind, 90):.1f}%")
    m = run_case("gill2019", {"own": pm.default_params}).metrics["own"]
    print("gill2019, the calibrated sets: " + " ".join(f"{k.replace('_ratio', '')} {v:.2f}" for k, v in m.items()
                                                        if not k.endswith(("min", "max"))))


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
