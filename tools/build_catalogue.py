"""Rebuild the bundled propeller catalogue from ../shared/data (run from the repo root).

Copies, verbatim, the UIUC vol. 1 geometry/static/wind-tunnel files of every propeller
that has a UIUC geometry file, and APC PE0 geometries (plus their UIUC measurements) for
the APC propellers that UIUC measured but has no geometry for; writes catalogue.json.
Sources and citations: src/propmap/data/CITATION.md.
"""

import csv
import json
import shutil
import sys
from pathlib import Path

SHARED = Path(sys.argv[1] if len(sys.argv) > 1 else "../shared/data")
OUT = Path("src/propmap/data")
APC_SUFFIX = {"apce": "E", "apcsf": "SF", "apcsp": ""}


def main() -> None:
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
            "name": f"{fam}_{dxp}",
            "family": fam,
            "diameter_in": float(d),
            "pitch_in": float(p),
            "n_blades": 2,
            "geometry": geometry,
            "static": sorted("uiuc_v1/" + f["file"] for f in files if f["kind"] == "static"),
            "sweeps": sorted("uiuc_v1/" + f["file"] for f in files if f["kind"] == "wind_tunnel"),
        })
    (OUT / "catalogue.json").write_text(json.dumps(entries, indent=1) + "\n")
    print(f"{len(entries)} propellers")


if __name__ == "__main__":
    main()
