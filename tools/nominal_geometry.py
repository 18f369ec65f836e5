"""A propeller known only by its size: the nominal blade (propmap.io.nominal_geometry) against the
propeller's own geometry, on the catalogue.

    .venv/bin/python tools/nominal_geometry.py shape          # the median chord table the package ships
    .venv/bin/python tools/nominal_geometry.py validate [--out CSV]   # 91 s on 2 cores, kernels compiled (2026-12-02)

``validate`` scores every catalogue propeller whose name gives its pitch (and that has a static run and
two sweeps) as ``propmap validate --all`` does, blind (the generic set) and fitted (static only; static +
lowest sweep), CT and CP rms in % of static, with the generic set and the population prior fitted without
the propeller's family (its fold), twice: on its own geometry and on the nominal blade of its name's
diameter, pitch and blade count, the nominal chord itself the median of the geometries outside that fold.

Data: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255) and vol. 2 (Deters, Ananda & Selig,
AIAA 2014-2151), APC PE0 geometry (APC Propellers, v2022-0915), as bundled with the package. Results:
docs/validation.md, A propeller known only by its size.
"""

import argparse
import csv
import statistics
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.core.geometry import INCH
from propmap.identify import loads_from_catalogue
from propmap.io.calibration import calibration, generic_without, population
from propmap.io.catalogue import catalogue
from propmap.io.nominal_geometry import R_OVER_R, nominal_propeller
from propmap.validation.catalogue import cross_validate

PROTOCOLS = ("blind", "static", "lowest")


def chord_shape(names) -> np.ndarray:
    """Median c/R at R_OVER_R over the catalogue geometries ``names`` (each interpolated linearly between its
    stations; a station outside a blade's span is not counted)."""
    rows = []
    for name in names:
        p = pm.load_propeller(name)
        rows.append(np.interp(R_OVER_R, p.r / p.radius, p.chord / p.radius, left=np.nan, right=np.nan))
    return np.nanmedian(np.array(rows), axis=0)


def twist_offset(names) -> np.ndarray:
    """Median over the catalogue geometries ``names`` whose name gives a pitch of the measured blade angle less the
    helix of that pitch, at R_OVER_R [rad] (an experiment: ``validate --twist``)."""
    rows = []
    for name in names:
        e = catalogue()[name]
        if e.pitch_in is None:
            continue
        p = pm.load_propeller(name)
        x = np.asarray(R_OVER_R)
        helix = np.arctan(e.pitch_in * INCH / (2 * np.pi * x * p.radius))
        rows.append(np.interp(x, p.r / p.radius, p.theta, left=np.nan, right=np.nan) - helix)
    return np.nanmedian(np.array(rows), axis=0)


def shape() -> None:
    names = list(catalogue())
    c = chord_shape(names)
    print(f"{len(names)} geometries; r/R and median c/R:")
    print(" ".join(f"{x:.2f}" for x in R_OVER_R))
    print(" ".join(f"{x:.3f}" for x in c))
    hub = [pm.load_propeller(n).r[0] / pm.load_propeller(n).radius for n in names]
    print(f"first station r/R: median {np.median(hub):.3f}")
    by_family = {}
    for name, e in catalogue().items():
        if e.pitch_in is None:
            continue
        p = pm.load_propeller(name)
        helix = np.arctan(e.pitch_in / (np.pi * e.diameter_in * 0.75))
        by_family.setdefault(e.family, []).append(np.degrees(p.theta_75() - helix))
    print("measured blade angle at 0.75 R less the helix of the named pitch [deg], family medians:")
    print(", ".join(f"{f} {statistics.median(v):+.2f} ({len(v)})" for f, v in sorted(by_family.items())))


def _fold_training(name: str) -> set:
    """The propellers the generic fold without ``name``'s family was fitted to (all others where no fold leaves it
    out)."""
    for _, members, _ in calibration()["generic_folds"]:
        if name not in members:
            return set(members)
    return set(catalogue()) - {name}


def validate(out: Path | None, twist: bool = False) -> None:
    rows = []
    for name, e in catalogue().items():
        if e.pitch_in is None or not (e.static_files and len(e.sweep_files) >= 2):
            continue
        own = pm.load_propeller(name)
        shape_without = chord_shape(sorted(_fold_training(name)))
        nominal = nominal_propeller(own.diameter, e.pitch_in * INCH, e.n_blades, chord_over_r=shape_without)
        if twist:
            from dataclasses import replace

            nominal = replace(nominal, theta=nominal.theta + twist_offset(sorted(_fold_training(name))))
        data = loads_from_catalogue(e, own.diameter)
        generic, pop = generic_without(name)[0], population(without=name)
        row = {"name": name, "volume": e.volume, "family": e.family}
        for label, prop in (("own", own), ("nominal", nominal)):
            try:
                cv = cross_validate(data, prop, generic, protocols=PROTOCOLS, population=pop)
            except ValueError as exc:  # (a protocol the data cannot serve)
                print(f"{name} {label}: {exc}")
                continue
            for proto in PROTOCOLS:
                row[f"{label}_{proto}_ct"] = 100 * cv[proto]["rms_ct"]
                row[f"{label}_{proto}_cp"] = 100 * cv[proto]["rms_cp"] if cv[proto]["rms_cp"] is not None else None
        rows.append(row)
        print(name, " ".join(f"{k} {v:.1f}" for k, v in row.items() if isinstance(v, float)), flush=True)
    if out is not None:
        keys = sorted({k for r in rows for k in r}, key=lambda k: (k not in ("name", "volume", "family"), k))
        with open(out, "w", newline="") as fh:
            w = csv.DictWriter(fh, keys)
            w.writeheader()
            w.writerows(rows)
    print("\nCT (CP) rms in % of static: median / 90th percentile / worst")
    for vol in (1, 2):
        sel = [r for r in rows if r["volume"] == vol]
        for label in ("own", "nominal"):
            cells = []
            for proto in PROTOCOLS:
                for q in ("ct", "cp"):
                    v = [r[f"{label}_{proto}_{q}"] for r in sel if r.get(f"{label}_{proto}_{q}") is not None]
                    cells.append(f"{proto} {q} {np.median(v):.1f} / {np.percentile(v, 90):.1f} / {max(v):.1f}")
            print(f"vol. {vol} ({len(sel)}), {label}: " + "; ".join(cells))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("what", choices=("shape", "validate"))
    parser.add_argument("--out", type=Path, default=None, help="validate: a CSV of every propeller's figures")
    parser.add_argument("--twist", action="store_true",
                        help="validate: the nominal blade angle corrected by the training geometries' median "
                             "difference from the helix, station by station (an experiment, not adopted)")
    args = parser.parse_args()
    shape() if args.what == "shape" else validate(args.out, args.twist)
