"""Rebuild the bundled propeller catalogue from ../shared/data (run from the repo root).

Volume 1 (Brandt & Selig, AIAA 2011-1255): copies, verbatim, the UIUC geometry, static and
wind-tunnel files of every propeller that has a UIUC geometry file, and APC PE0 geometries
(plus their UIUC measurements) for the APC propellers that UIUC measured but has no
geometry for.

Volume 2 (Deters, Ananda & Selig, AIAA 2014-2151), the part in ../shared: every propeller
with measurements, by the rules of :data:`V2_RULES` (sizes in the names, hubs of 3 and 4
blades, blades whose only geometry is their family's design file). The decisions, each
with its evidence, are in src/propmap/data/CITATION.md.

Writes catalogue.json. Sources and citations: src/propmap/data/CITATION.md.

    .venv/bin/python tools/build_catalogue.py [../shared/data]
"""

import argparse
import csv
import json
import math
import re
import shutil
from pathlib import Path

#: the shared data folder (the command line's DATA)
SHARED = Path("../shared/data")
OUT = Path("src/propmap/data")
APC_SUFFIX = {"apce": "E", "apcsf": "SF", "apcsp": ""}
INCH_MM = 25.4
#: helical pitch P = 0.75 pi D tan(beta_0.75): the convention of the DA-series and NR640 design
#: files (da4002_geom.txt, a 5x3.75 design: beta(0.75 R) = 17.657 deg = atan(3.75 / (0.75 pi 5)))
DESIGN_STATION = 0.75


def _pitch_angle(d_in: float, p_in: float) -> float:
    return math.degrees(math.atan(p_in / (DESIGN_STATION * math.pi * d_in)))


def _beta_at(geom: Path, station: float = DESIGN_STATION) -> float:
    rows = [line.split() for line in geom.read_text().splitlines()[1:] if line.strip()]
    r = [float(x[0]) for x in rows]
    b = [float(x[2]) for x in rows]
    for k in range(len(r) - 1):
        if r[k] <= station <= r[k + 1]:
            t = (station - r[k]) / (r[k + 1] - r[k])
            return b[k] + t * (b[k + 1] - b[k])
    raise ValueError(f"{geom}: no station at r/R = {station}")


def _v1_entries() -> list:
    rows = list(csv.DictReader(open(SHARED / "uiuc_propdb/INDEX.csv")))
    by_prop: dict[tuple[str, str], list[dict]] = {}
    for r in rows:
        by_prop.setdefault((r["family_code"], r["DxP_in"]), []).append(r)
    pe0_dir = SHARED / "apc_vendor_data/geometry_PE0"
    (OUT / "uiuc_v1").mkdir(parents=True, exist_ok=True)
    (OUT / "apc_pe0").mkdir(parents=True, exist_ok=True)
    entries = []
    for (fam, dxp), files in sorted(by_prop.items()):
        kinds = {f["kind"] for f in files}
        geom = [f for f in files if f["kind"] == "geometry"]
        if geom:
            geometry = {"format": "uiuc", "file": "uiuc_v1/" + geom[0]["file"]}
        elif fam in APC_SUFFIX and "static" in kinds:
            pe0 = dxp.replace(".", "") + APC_SUFFIX[fam] + "-PERF.PE0"
            if not (pe0_dir / pe0).is_file():
                continue
            shutil.copy2(pe0_dir / pe0, OUT / "apc_pe0" / pe0)
            geometry = {"format": "apc_pe0", "file": "apc_pe0/" + pe0}
        else:
            continue
        for f in files:
            shutil.copy2(SHARED / "uiuc_propdb/v1" / f["file"], OUT / "uiuc_v1" / f["file"])
        d, p = dxp.split("x")
        entries.append({
            "name": f"{fam}_{dxp}", "family": fam, "volume": 1,
            "diameter_in": float(d), "pitch_in": float(p), "n_blades": 2, "geometry": geometry,
            "static": sorted("uiuc_v1/" + f["file"] for f in files if f["kind"] == "static"),
            "sweeps": sorted("uiuc_v1/" + f["file"] for f in files if f["kind"] == "wind_tunnel"),
        })
    return entries


#: measurement file names of vol. 2: <prop>_static_<run>.txt and <prop>_<run>_<rpm>.txt
_STATIC = re.compile(r"^(?P<prop>.+)_static_(?P<run>[0-9]{4}[a-z]{2})\.txt$")
_SWEEP = re.compile(r"^(?P<prop>.+)_(?P<run>[0-9]{4}[a-z]{2})_(?P<rpm>[0-9]+)\.txt$")


def _v2_size(prop: str, folder: Path):
    """(family, diameter_in, pitch_in, n_blades, geometry file, geometry rule, note) of a vol. 2
    propeller. Rules:

    * ``<fam>_<D>x<P>``: D and P in inches (da4002, da4022, da4052, gwsdd, mi, mit);
    * ``pl_<D>x<P>``, ``union_u<D>``, ``cfnq_<D><variant>``: millimetres (the Plantraco, Union and
      CFNQ names; cfnq_45 is a 45 mm propeller);
    * ``pl_triturbo``: 3 blades, 64 mm: inferred, the name gives no size. Every sized vol. 2
      propeller's low-speed wind-tunnel runs stop at 11.2-12.2 m/s; the TriTurbo's two low-speed
      runs (15,027 and 20,064 rpm) stop at J = 0.752 and 0.561, i.e. 12 m/s at D = 64 mm;
    * ``nr640_<D>_<angle>deg``: D in inches, the blade set to that angle at 0.75 R (nr640_geom.txt
      is the design at 15 deg); the pitch is the helical 0.75 pi D tan(angle);
    * ``_3b``, ``_4b``: 3- and 4-blade hubs of the same blade (its geometry file);
    * a DA-series blade with no geometry file of its own (da4052_<D>x<P>): its family design file's
      chord with the helical blade angle of the named pitch, atan(P / (pi D r/R)). The family design
      files are helical (da4002_geom.txt: 38.51 deg at 0.3 R and 13.43 at the tip, a 0.75 P/D helix
      to 0.01 deg; da4052_geom.txt within 0.7 deg), and each named pitch is its own design. The
      measured DA4002 blades came out 1.8-3.4 deg above their helix at 0.75 R and with more twist
      (da4002_5x1.58: 27.7 deg at 0.3 R against 18.5): the uncertainty of these geometries;
    * nr640_5_20deg: the 5 in blade measured at its 15 deg setting (nr640_5_15deg_geom.txt, 16.6
      deg at 0.75 R in its own datum) turned 5 deg: the same blades are run at several angles and in
      2-, 3- and 4-blade hubs, an adjustable-pitch propeller. nr640_9_20deg, whose blade was not
      measured: the NR640 design blade (nr640_geom.txt, 15 deg at 0.75 R) set 5 deg higher.
    """
    base, blades = prop, 2
    m = re.fullmatch(r"(.+)_([34])b", prop)
    if m:
        base, blades = m.group(1), int(m.group(2))
    fam = base.split("_")[0]
    note = ""
    if fam == "pl" and base == "pl_triturbo":
        d_in, p_in, blades = 64.0 / INCH_MM, None, 3
        note = "diameter 64 mm inferred from the wind tunnel's airspeed limit (tools/build_catalogue.py)"
    elif fam == "pl":
        d, p = re.fullmatch(r"pl_([0-9.]+)x([0-9.]+)", base).groups()
        d_in, p_in = float(d) / INCH_MM, float(p) / INCH_MM
    elif fam == "union":
        d_in, p_in = float(re.fullmatch(r"union_u([0-9]+)", base).group(1)) / INCH_MM, None
    elif fam == "cfnq":
        d_in, p_in = float(re.fullmatch(r"cfnq_([0-9]+)[a-z][0-9]", base).group(1)) / INCH_MM, None
    elif fam == "nr640":
        d, ang = re.fullmatch(r"nr640_([0-9.]+)_([0-9.]+)deg", base).groups()
        d_in = float(d)
        p_in = DESIGN_STATION * math.pi * d_in * math.tan(math.radians(float(ang)))
    else:
        d, p = re.fullmatch(r"[a-z0-9]+_([0-9.]+)x([0-9.]+)(?:_spec[0-9])?", base).groups()
        d_in, p_in = float(d), float(p)
    own = folder / f"{base}_geom.txt"
    rule = {}
    if own.is_file():
        geom = own
    elif fam == "nr640":
        d_name, target = re.fullmatch(r"nr640_([0-9.]+)_([0-9.]+)deg", base).groups()
        target = float(target)
        # the same blade measured at another setting of its hub: that blade, turned by the
        # difference between the two names' settings (its own angle datum kept)
        measured = sorted(folder.glob(f"nr640_{d_name}_*deg_geom.txt"))
        if measured:
            geom = measured[0]
            setting = float(re.fullmatch(r"nr640_[0-9.]+_([0-9.]+)deg_geom\.txt", geom.name).group(1))
            rule["beta_offset_deg"] = round(target - setting, 4)
            note = (f"no measured geometry at this setting: the same blade measured at {setting:g} deg "
                    f"({geom.name}) turned {rule['beta_offset_deg']:+.3f} deg, the difference of the "
                    f"names' settings")
        else:
            geom = folder / f"{fam}_geom.txt"
            rule["beta_offset_deg"] = round(target - _beta_at(geom), 4)
            note = (f"no measured geometry: the NR640 design blade (nr640_geom.txt) set "
                    f"{rule['beta_offset_deg']:+.3f} deg to {target:g} deg at 0.75 R")
    else:
        geom = folder / f"{fam}_geom.txt"
        rule["helical_pitch_in"] = p_in
        note = (f"no measured geometry: the {fam} design file's chord with the helical blade angle of a "
                f"{p_in:g} in pitch, atan(P / (pi D r/R)) ({_pitch_angle(d_in, p_in):.2f} deg at 0.75 R)")
    return fam, d_in, p_in, blades, geom, rule, note


def _v2_entries() -> list:
    folder = SHARED / "uiuc_propdb/v2"
    (OUT / "uiuc_v2").mkdir(parents=True, exist_ok=True)
    props: dict[str, dict] = {}
    for f in sorted(folder.iterdir()):
        for kind, rx in (("static", _STATIC), ("sweeps", _SWEEP)):
            m = rx.match(f.name)
            if m:
                props.setdefault(m["prop"], {"static": [], "sweeps": []})[kind].append(f)
                break
    entries = []
    for prop, files in sorted(props.items()):
        fam, d_in, p_in, blades, geom, rule, note = _v2_size(prop, folder)
        for f in [geom, *files["static"], *files["sweeps"]]:
            shutil.copy2(f, OUT / "uiuc_v2" / f.name)
        e = {"name": prop, "family": fam, "volume": 2, "diameter_in": round(d_in, 6),
             "pitch_in": None if p_in is None else round(p_in, 6), "n_blades": blades,
             "geometry": {"format": "uiuc", "file": "uiuc_v2/" + geom.name},
             "static": ["uiuc_v2/" + f.name for f in files["static"]],
             "sweeps": ["uiuc_v2/" + f.name for f in files["sweeps"]]}
        e["geometry"].update(rule)
        if note:
            e["note"] = note
        entries.append(e)
    return entries


def main() -> None:
    entries = _v1_entries() + _v2_entries()
    (OUT / "catalogue.json").write_text(json.dumps(entries, indent=1) + "\n")
    n2 = sum(e["volume"] == 2 for e in entries)
    print(f"{len(entries)} propellers ({len(entries) - n2} from vol. 1, {n2} from vol. 2)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("data", nargs="?", type=Path, default=SHARED, help="the shared data (default ../shared/data)")
    SHARED = parser.parse_args().data
    main()
