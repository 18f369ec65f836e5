"""A vendor's own prediction as a baseline: APC's published performance files against UIUC's
measurements, beside propmap blind.

APC Propellers publish, for each propeller, predicted thrust and power coefficients against the
advance ratio at rotation rates every 1000 rpm (their ``PER3_<name>.dat`` files, v2022-0915,
"AIRFOIL AERO DATA GENERATED USING: POLAR DIAGRAMS": APC's own blade-element predictions, not
measurements). For every catalogue propeller of the APC electric, slow-flyer and sport families
that has such a file (../shared/data/apc_vendor_data/performance_PER3; UIUC Propeller Data Site
vol. 1, Brandt & Selig AIAA 2011-1255, and vol. 2, Deters, Ananda & Selig AIAA 2014-2151, for the
measurements) this scores, in `propmap validate`'s metric (rms dCT / static CT and dCP / static
CP, the static CT and CP the mean measured static coefficients):

* APC: its Ct and Cp interpolated linearly in J within each rpm block and then in rpm between
  the blocks around the measured point (points beyond a block's J range are left out and
  counted);
* propmap blind: the generic set derived without the propeller's family (the shipped folds),
  which `validate --all` scores as its "blind" protocol,

on the J-sweeps (as the blind protocol) and on the static runs, on the same points.

    .venv/bin/python tools/apc_baseline.py      # a few seconds with the kernel cache warm (../shared beside)

Findings (2026-11-28): docs/validation.md, "A vendor's prediction as a baseline".
"""

from __future__ import annotations

import argparse
import re
import sys
import warnings
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
PER3 = ROOT.parent / "shared" / "data" / "apc_vendor_data" / "performance_PER3"
FAMILIES = {"apce": "E", "apcsf": "SF", "apcsp": ""}
_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def per3_name(name: str) -> str | None:
    """APC's file name of a catalogue propeller (apce_10x4.7 -> PER3_10x47E.dat), or None."""
    family, _, size = name.partition("_")
    if family not in FAMILIES or not size:
        return None
    return f"PER3_{size.replace('.', '')}{FAMILIES[family]}.dat"


def read_per3(path: Path) -> dict[float, np.ndarray]:
    """rpm -> array of (J, Ct, Cp) rows of one PER3 file."""
    blocks: dict[float, list] = {}
    rpm = None
    for line in path.read_text(errors="replace").splitlines():
        if "PROP RPM" in line:
            rpm = float(_NUMBER.findall(line)[0])
            blocks[rpm] = []
            continue
        if rpm is None:
            continue
        fields = _NUMBER.findall(line)
        if len(fields) >= 15 and len(fields) == len(line.split()):
            blocks[rpm].append([float(fields[1]), float(fields[3]), float(fields[4])])
    return {k: np.array(v) for k, v in blocks.items() if len(v) >= 2}


def apc_coefficients(blocks: dict, rpm: np.ndarray, J: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """APC's Ct and Cp at (rpm, J): linear in J within a block, then in rpm; NaN beyond a block's
    J range or the blocks' rpm range."""
    rates = np.array(sorted(blocks))
    out = np.full((2, rpm.size), np.nan)
    for k, (n, j) in enumerate(zip(rpm, J)):
        if not rates[0] <= n <= rates[-1]:
            continue
        i = min(int(np.searchsorted(rates, n)), rates.size - 1)
        lo, hi = (rates[i - 1], rates[i]) if rates[i] > n and i > 0 else (rates[i], rates[i])
        vals = []
        for r in (lo, hi):
            b = blocks[r]
            if not b[0, 0] <= j <= b[-1, 0]:
                break
            vals.append([np.interp(j, b[:, 0], b[:, c]) for c in (1, 2)])
        if len(vals) < 2:
            continue
        w = 0.0 if hi == lo else (n - lo) / (hi - lo)
        out[:, k] = (1 - w) * np.array(vals[0]) + w * np.array(vals[1])
    return out[0], out[1]


def one(name: str) -> dict | None:
    warnings.simplefilter("ignore")
    if str(Path(__file__).parent) not in sys.path:
        sys.path.insert(0, str(Path(__file__).parent))
    from rpm_drift import static_lowest_case  # (tools/rpm_drift.py: the propeller as the protocols see it)

    import propmap as pm
    from propmap.validation.catalogue import _coefficients

    path = PER3 / per3_name(name)
    if not path.is_file():
        return None
    c = static_lowest_case(name)
    data, prop, generic, static = c["data"], c["prop"], c["generic"], c["static"]
    CT, CP = _coefficients(data, prop, generic.air)
    CT0, CP0 = CT[static].mean(), CP[static].mean()
    rpm = data.omega * 30 / np.pi
    J = data.airspeed / (data.omega / (2 * np.pi) * prop.diameter)
    a_ct, a_cp = apc_coefficients(read_per3(path), rpm, J)
    r = pm.rotor_loads(prop, generic, data.omega, data.airspeed, data.incidence)
    row = {"name": name, "family": c["entry"].family, "volume": c["entry"].volume}
    for part, m in (("sweeps", ~static), ("static", static)):
        ok = m & np.isfinite(a_ct) & np.isfinite(CT)
        okp = m & np.isfinite(a_cp) & np.isfinite(CP)
        row[part] = {
            "n": int(m.sum()), "n_apc": int(ok.sum()),
            "apc_ct": float(np.sqrt(np.mean(((a_ct[ok] - CT[ok]) / CT0) ** 2))),
            "apc_cp": float(np.sqrt(np.mean(((a_cp[okp] - CP[okp]) / CP0) ** 2))),
            "apc_bias_ct": float(np.mean((a_ct[ok] - CT[ok]) / CT0)),
            "propmap_ct": float(np.sqrt(np.mean(((r.CT[ok] - CT[ok]) / CT0) ** 2))),
            "propmap_cp": float(np.sqrt(np.mean(((r.CP[okp] - CP[okp]) / CP0) ** 2))),
            "propmap_bias_ct": float(np.mean((r.CT[ok] - CT[ok]) / CT0)),
        }
    return row


def _stats(v) -> str:
    v = 100 * np.asarray(v)
    return f"{np.median(v):.1f} / {np.percentile(v, 90):.1f} / {v.max():.1f}%"


def main() -> None:
    if not PER3.is_dir():
        sys.exit(f"apc_baseline.py: APC's performance files are not at {PER3} (../shared beside the checkout)")
    from propmap.io.catalogue import catalogue

    names = sorted(n for n, e in catalogue().items() if per3_name(n) and e.static_files and e.sweep_files)
    with ProcessPoolExecutor(2) as ex:
        rows = [r for r in ex.map(one, names) if r is not None]
    missing = sorted(set(names) - {r["name"] for r in rows})
    print(f"{len(rows)} of {len(names)} APC catalogue propellers have an APC performance file (not: "
          f"{', '.join(missing) or 'none'}); rms dCT / static CT "
          "(median / 90th percentile / worst) on the same points, APC's prediction | propmap blind:")
    for part in ("sweeps", "static"):
        for fam in ("apce", "apcsf", "apcsp", None):
            sel = [r for r in rows if fam is None or r["family"] == fam]
            if not sel:
                continue
            s = [r[part] for r in sel]
            print(f"  {part:6s} {fam or 'all':6s} ({len(sel):2d}; {sum(x['n_apc'] for x in s)} of "
                  f"{sum(x['n'] for x in s)} points) CT {_stats([x['apc_ct'] for x in s])} | "
                  f"{_stats([x['propmap_ct'] for x in s])}; CP {_stats([x['apc_cp'] for x in s])} | "
                  f"{_stats([x['propmap_cp'] for x in s])}; signed CT median "
                  f"{100 * np.median([x['apc_bias_ct'] for x in s]):+.1f}% | "
                  f"{100 * np.median([x['propmap_bias_ct'] for x in s]):+.1f}%")
    better = sum(r["sweeps"]["propmap_ct"] < r["sweeps"]["apc_ct"] for r in rows)
    print(f"propmap blind closer than APC on the sweeps' CT for {better} of {len(rows)} propellers")
    for r in sorted(rows, key=lambda r: -r["sweeps"]["apc_ct"])[:5]:
        print(f"  {r['name']}: APC {100 * r['sweeps']['apc_ct']:.1f}%, propmap {100 * r['sweeps']['propmap_ct']:.1f}%")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
