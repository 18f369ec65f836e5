"""Count the hostile cases that propmap handles (docs/cli.md): the API cases and seeded
fuzzed netCDF maps (damaged bytes, hostile attribute values), each classified as handled or
not. Run from the repository root against any source tree, e.g. an older one:

    PYTHONPATH=/path/to/old/src python tools/hostile_census.py --fuzz 300

Handled: a map that opens answers inside its grid with finite loads (or flags the
query), or ValueError (TypeError for an argument of the wrong type) naming the file or
argument. Anything else (another exception class, an unnamed message) is not. The CLI
regression cases are counted by running tests/test_cli_hostile_maps.py and
tests/test_maps_hostile.py under pytest against the same tree.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
import tempfile
from collections import Counter
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))


def _tiny():
    import propmap as pm
    from propmap.maps import build_map

    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    air, label = params.air, params.label
    rpm = 2 * math.pi / 60
    return prop, build_map(prop, params, np.linspace(3000, 9000, 4) * rpm, np.linspace(0, 10, 3),
                           np.radians(np.linspace(0, 180, 5)), air=air, params_label=label, n_check=20)


def _valid(rm) -> bool:
    q = rm.loads(float(np.mean(rm.omega)), float(np.mean(rm.airspeed)), float(np.mean(rm.incidence)))
    return bool(q.flagged) or all(math.isfinite(v) for v in (q.thrust, q.drag, q.torque, q.rolling_moment))


def _open_outcome(path) -> str:
    from propmap.maps import RotorMap

    try:
        rm = RotorMap.open(path)
    except ValueError as exc:
        return "handled" if str(exc).startswith(str(path)) else f"unnamed ValueError: {str(exc)[:60]}"
    except Exception as exc:  # noqa: BLE001 -- what is counted
        return f"{type(exc).__name__}"
    try:
        return "handled" if _valid(rm) else "answers NaN"
    except Exception as exc:  # noqa: BLE001
        return f"{type(exc).__name__} on a query"


def fuzz_bytes(data: bytes, n: int, rng, folder: Path) -> Counter:
    out = Counter()
    for k in range(n):
        b = bytearray(data)
        for _ in range(int(rng.integers(1, 7))):
            b[int(rng.integers(0, len(b)))] ^= int(rng.integers(1, 256))
        if rng.random() < 0.3:
            b = b[: int(rng.integers(0, len(b) + 1))]
        path = folder / f"bytes{k}.nc"
        path.write_bytes(bytes(b))
        out[_open_outcome(path)] += 1
    return out


def fuzz_attributes(ds, n: int, rng, folder: Path) -> Counter:
    keys = ["diameter_m", "n_blades", "rho_kg_m3", "mu_Pa_s", "speed_of_sound_m_s", "n_radial", "n_azimuth",
            "check_points", "check_seed", "check_cubic_thrust_max", "geometry_r_m", "params_json", "propeller"]
    values = [math.nan, math.inf, -1.0, 0.0, 1e-300, 1e300, 1e30, 2.5, -7, 0, 1, 10**12, "x", "", "{}",
              np.array([0.2, 0.3]), np.array([], float), np.array([1e300, -1e300]), '{"section_model": "nope"}']
    out = Counter()
    for k in range(n):
        edits = {keys[int(rng.integers(len(keys)))]: values[int(rng.integers(len(values)))]
                 for _ in range(int(rng.integers(1, 3)))}
        path = folder / f"attrs{k}.nc"
        try:
            ds.copy().assign_attrs(edits).to_netcdf(path)
        except (TypeError, ValueError):
            out["not storable in netCDF (skipped)"] += 1
            continue
        outcome = _open_outcome(path)
        if outcome == "handled":  # the model recorded in the map must rebuild or be refused, named
            from propmap.maps import RotorMap

            try:
                rm = RotorMap.open(path)
                rm.check(3)
            except ValueError:
                pass
            except Exception as exc:  # noqa: BLE001
                outcome = f"{type(exc).__name__} in check"
            except BaseException:  # a rebuilt model that does not return
                outcome = "hang"
        out[outcome] += 1
    return out


def api(prop, ds) -> Counter:
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    from tests.test_maps_hostile import _api_cases

    out = Counter()
    for name, (call, kind, match) in _api_cases(prop, ds).items():
        try:
            call()
        except kind as exc:
            out["handled" if re.search(match, str(exc)) else f"{kind.__name__}, message not naming it"] += 1
        except Exception as exc:  # noqa: BLE001
            out[type(exc).__name__] += 1
        else:
            out["no error"] += 1
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fuzz", type=int, default=300, help="fuzzed files of each kind")
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import propmap

    prop, ds = _tiny()
    rng = np.random.default_rng(args.seed)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        ds.to_netcdf(folder / "m.nc")
        data = (folder / "m.nc").read_bytes()
        report = {"propmap": str(Path(propmap.__file__).parent), "api": api(prop, ds),
                  "fuzzed bytes": fuzz_bytes(data, args.fuzz, rng, folder),
                  "fuzzed attributes": fuzz_attributes(ds, args.fuzz, rng, folder)}
    for k, c in report.items():
        if isinstance(c, Counter):
            tried = sum(v for key, v in c.items() if "skipped" not in key)
            print(f"{k}: {c['handled']} of {tried} handled; {dict(c)}")
    print(json.dumps({k: dict(v) if isinstance(v, Counter) else v for k, v in report.items()}))


if __name__ == "__main__":
    main()
