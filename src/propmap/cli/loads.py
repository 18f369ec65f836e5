"""``propmap loads``: loads at one operating point or at every row of a CSV file."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import click
import numpy as np

from ..core.solver import SolverError, rotor_loads
from ..io.atomic import atomic_write
from ._common import PARAMS_HELP, InputError, check_point, echo_json, load_params, load_prop, with_prop_options

OUTPUT_KEYS = ("thrust", "drag", "torque", "power", "CT", "CP", "converged", "flags")
INPUT_COLUMNS = ("rpm", "airspeed", "incidence_deg")
CHUNK = 2000


def read_points(path: Path) -> np.ndarray:
    """Rows (rpm, airspeed, incidence_deg) of a points CSV; InputError names the bad line."""
    try:
        fh = open(path, newline="", encoding="utf-8")
    except OSError as exc:
        raise InputError(f"--points: cannot read {path} ({exc.strerror})") from None
    with fh:
        reader = csv.reader(fh)
        header = next(reader, None)
        if header is None:
            raise InputError(f"--points: {path} is empty")
        header = [h.strip() for h in header]
        missing = [c for c in INPUT_COLUMNS if c not in header]
        if missing:
            raise InputError(f"--points: {path} lacks column(s) {', '.join(missing)} "
                             f"(needs {', '.join(INPUT_COLUMNS)})")
        idx = [header.index(c) for c in INPUT_COLUMNS]
        rows = []
        for row in reader:
            line = reader.line_num
            if not row or all(not x.strip() for x in row):
                continue
            if len(row) != len(header):
                raise InputError(f"--points: {path}, line {line}: expected {len(header)} fields, got {len(row)}")
            try:
                vals = [float(row[i]) for i in idx]
            except ValueError:
                raise InputError(f"--points: {path}, line {line}: non-numeric value in {','.join(row)!r}") from None
            check_point(*vals, where=f"--points: {path}, line {line}")
            rows.append(vals)
    if not rows:
        raise InputError(f"--points: {path} has no data rows")
    return np.array(rows)


def _solve(prop, params, air, pts: np.ndarray, progress: bool):
    from tqdm import tqdm

    n = len(pts)
    out = {k: np.empty(n) for k in ("thrust", "drag", "torque", "power", "CT", "CP")}
    conv = np.empty(n, bool)
    flags = [""] * n
    # disable=None: shown only on a terminal, and only for batches longer than one chunk
    with tqdm(total=n, unit="pt", disable=True if (not progress or n <= CHUNK) else None, leave=False) as bar:
        for s in range(0, n, CHUNK):
            p = pts[s:s + CHUNK]
            r = rotor_loads(prop, params, p[:, 0] * 2 * math.pi / 60, p[:, 1], np.radians(p[:, 2]), air=air,
                            on_failure="flag")
            for k in out:
                out[k][s:s + len(p)] = getattr(r, k)
            conv[s:s + len(p)] = r.converged
            for i in range(len(p)):
                flags[s + i] = ";".join(r.flags(i))
            bar.update(len(p))
    return out, conv, flags


@click.command("loads")
@click.argument("prop")
@click.option("--rpm", type=float, help="Rotation rate [rpm], > 0.")
@click.option("--airspeed", type=float, default=0.0, show_default=True, help="Airspeed V [m/s], >= 0.")
@click.option("--incidence-deg", type=float, default=0.0, show_default=True,
              help="Angle between freestream and rotor axis [deg]: 0 climb, 90 edgewise, 180 descent.")
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP)
@click.option("--points", type=click.Path(path_type=Path), help="CSV with columns rpm, airspeed, incidence_deg.")
@click.option("--out", type=click.Path(path_type=Path), help="Output CSV (with --points).")
@click.option("--json", "as_json", is_flag=True, help="Print JSON (single point).")
@with_prop_options
def loads(prop, rpm, airspeed, incidence_deg, params_spec, points, out, as_json, diameter_in, blades):
    """Thrust, rotor drag, torque and power of PROP (catalogue name or geometry file).

    Outputs are SI: N, N m, W; CT and CP in the propeller convention.
    """
    propeller = load_prop(prop, diameter_in, blades)
    params, air, params_label = load_params(params_spec, prop)
    if points is not None:
        if out is None:
            raise InputError("--out is required with --points")
        if rpm is not None:
            raise InputError("give either --rpm (one point) or --points (many), not both")
        pts = read_points(points)
        res, conv, flags = _solve(propeller, params, air, pts, progress=True)
        with atomic_write(out, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(list(INPUT_COLUMNS) + list(OUTPUT_KEYS))
            for i in range(len(pts)):
                w.writerow([f"{x:.10g}" for x in pts[i]] + [f"{res[k][i]:.10g}" for k in res]
                           + [str(bool(conv[i])).lower(), flags[i]])
        n_bad = int((~conv).sum())
        click.echo(f"wrote {len(pts)} points to {out} (params {params_label})"
                   + (f"; {n_bad} did not converge (see flags)" if n_bad else ""),
                   err=True)
        return
    if rpm is None:
        raise InputError("give --rpm (one point) or --points IN.csv --out OUT.csv")
    check_point(rpm, airspeed, incidence_deg)
    try:
        r = rotor_loads(propeller, params, rpm * 2 * math.pi / 60, airspeed, math.radians(incidence_deg), air=air)
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    result = {k: float(getattr(r, k)) for k in ("thrust", "drag", "torque", "power", "CT", "CP")}
    result.update(converged=bool(r.converged), flags=r.flags())
    if as_json:
        echo_json({**result, "propeller": propeller.name, "params": params_label, "rpm": rpm, "airspeed": airspeed,
                   "incidence_deg": incidence_deg,
                   "units": {"thrust": "N", "drag": "N", "torque": "N m", "power": "W"}})
        return
    click.echo(f"{propeller.name} at {rpm:g} rpm, V = {airspeed:g} m/s, incidence {incidence_deg:g} deg "
               f"(params {params_label})")
    click.echo(f"  thrust T = {result['thrust']:.4f} N    drag D = {result['drag']:.4f} N")
    click.echo(f"  torque Q = {result['torque']:.5f} N m  power P = {result['power']:.2f} W")
    click.echo(f"  CT = {result['CT']:.4f}  CP = {result['CP']:.4f}  flags: {', '.join(r.flags()) or 'none'}")
