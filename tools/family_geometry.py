"""A DA-series family design file (da4002_geom.txt, da4052_geom.txt: one blade, a 0.75 P/D helix) as the
geometry of the family's other pitches: the file as it is, the helix of the named pitch (the catalogue's
construction for DA4052), the file rotated to that helix's angle at 0.75 R, and the catalogue's geometry
(DA4002: measured), each scored blind and static + lowest (CT rms in % of static CT) with the generic set
and prior fitted without the family, as `propmap validate --all` scores.

    .venv/bin/python tools/family_geometry.py da4002     # (and da4052; ~10 s each, kernels compiled; 2026-12-02)

Data: UIUC Propeller Data Site vol. 2 (Deters, Ananda & Selig, AIAA 2014-2151), as bundled; da4002_geom.txt
from ../shared/data/uiuc_propdb/v2 (the package does not ship it). Results: docs/validation.md, Where the model
is still wrong (a family's design file as another pitch's geometry).
"""

import argparse
import math
from dataclasses import replace
from importlib import resources
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.identify import loads_from_catalogue
from propmap.io.calibration import generic_without, population
from propmap.io.catalogue import catalogue
from propmap.validation.catalogue import cross_validate

BUNDLED = Path(str(resources.files("propmap") / "data" / "uiuc_v2"))
SHARED = Path(__file__).resolve().parents[2] / "shared" / "data" / "uiuc_propdb" / "v2"


def main(family: str) -> None:
    geom = BUNDLED / f"{family}_geom.txt"
    geom = geom if geom.is_file() else SHARED / f"{family}_geom.txt"
    print("name, the file's and the helix's angle at 0.75 R [deg]; blind / static + lowest CT rms [%] with the "
          "file, the helix, the rotated file, the catalogue's geometry")
    for name, e in catalogue().items():
        if e.family != family or name.endswith(("_3b", "_4b")):
            continue
        file_prop = pm.read_geometry(geom, diameter_in=e.diameter_in, n_blades=e.n_blades)
        P = e.pitch_in * 0.0254
        helix = replace(file_prop, theta=np.arctan(P / (2 * np.pi * file_prop.r)), pitch=P)
        rotated = replace(file_prop, theta=file_prop.theta + helix.theta_75() - file_prop.theta_75())
        data = loads_from_catalogue(e, file_prop.diameter)
        row = [name, f"{math.degrees(file_prop.theta_75()):.1f}", f"{math.degrees(helix.theta_75()):.1f}"]
        for prop in (file_prop, helix, rotated, pm.load_propeller(name)):
            cv = cross_validate(data, prop, generic_without(name)[0], protocols=("blind", "lowest"),
                                population=population(without=name))
            row += [f"{100 * cv['blind']['rms_ct']:.2f}", f"{100 * cv['lowest']['rms_ct']:.2f}"]
        print(" ".join(row), flush=True)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("family", choices=("da4002", "da4052"))
    main(parser.parse_args().family)
