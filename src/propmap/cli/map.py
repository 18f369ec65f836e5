"""``propmap map``: tabulate the model for real-time use (netCDF, CSV or C), check a map."""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import click

from ._common import (PARAMS_HELP, RPM_MAX, RPM_MIN, InputError, check_out_dir, check_outputs, echo_json, load_params,
                      load_prop, with_prop_options)

FORMATS = {"netcdf": ".nc", "csv": ".csv", "c": ".h"}
MAX_AXIS = 2000
MAX_POINTS = 20_000_000


def parse_axis(option: str, text: str, lo: float, hi: float, unit: str):
    """``start:stop:count`` (or ``start:stop:count:log``, geometric) as a NumPy array.

    Raises
    ------
    InputError
        Not that form, a bound outside [lo, hi], start >= stop, count outside [2, 2000].
    """
    import numpy as np

    parts = text.split(":")
    log = len(parts) == 4 and parts[3].strip().lower() == "log"
    if len(parts) not in (3, 4) or (len(parts) == 4 and not log):
        raise InputError(f"{option}: {text!r} is not start:stop:count (or start:stop:count:log)")
    try:
        a, b = float(parts[0]), float(parts[1])
        n = int(parts[2])
    except ValueError:
        raise InputError(f"{option}: {text!r} is not start:stop:count with numbers and an integer count") from None
    if not (math.isfinite(a) and math.isfinite(b) and lo <= a < b <= hi):
        raise InputError(f"{option}: need {lo:g} <= start < stop <= {hi:g} {unit}, got {a:g}:{b:g}")
    if not 2 <= n <= MAX_AXIS:
        raise InputError(f"{option}: count must be in [2, {MAX_AXIS}], got {n}")
    if log and a <= 0:
        raise InputError(f"{option}: a geometric axis needs start > 0, got {a:g}")
    return np.geomspace(a, b, n) if log else np.linspace(a, b, n)


@click.command("map")
@click.argument("prop", required=False)
@click.option("--rpm", "rpm_axis", default=None,
              help="rpm axis start:stop:count[:log] (default: 21 values, geometric, from 1/6 of the rpm of a "
                   "150 m/s tip speed to it).")
@click.option("--airspeed", "airspeed_axis", default=None, help="Airspeed axis [m/s] start:stop:count (default 0:25:26).")
@click.option("--incidence-deg", "incidence_axis", default=None,
              help="Incidence axis [deg] start:stop:count (default 0:180:73).")
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP)
@click.option("--out", type=click.Path(path_type=Path), default=None,
              help="Map file; a JSON sidecar OUT.json of its metadata is written beside it.")
@click.option("--format", "fmt", type=click.Choice(list(FORMATS)), default="netcdf", show_default=True,
              help="netcdf (xarray Dataset), csv (long form) or c (a C99 header).")
@click.option("--c-type", type=click.Choice(["float", "double"]), default="float", show_default=True,
              help="Table type of --format c.")
@click.option("--c-interpolation", type=click.Choice(["linear", "cubic"]), default="linear", show_default=True,
              help="Interpolation of the --format c function (linear: 54 ns a call; cubic, the Python "
                   "evaluator's default: 167 ns, 3-9x smaller largest errors; docs/simulators.md).")
@click.option("--c-name", default=None, help="C identifier prefix of --format c (default: pm_<file name>).")
@click.option("--check-points", type=int, default=2000, show_default=True,
              help="Random off-grid points at which the full model checks the map (0: none).")
@click.option("--check", "check_file", type=click.Path(path_type=Path), default=None,
              help="Recompute the error bound of an existing netCDF map (no PROP).")
@click.option("--all", "all_props", is_flag=True,
              help="One netCDF map over every catalogue propeller (a prop dimension), each with its default "
                   "parameters, on one grid (default axes from the median diameter).")
@click.option("--props", "only", default="", help="With --all: comma-separated catalogue names to restrict to.")
@click.option("--scheduler", default=None,
              help="Address of a dask.distributed scheduler (tcp://HOST:PORT) to build on; default: this machine.")
@click.option("--plot", "plot_dir", type=click.Path(path_type=Path), default=None,
              help="Folder for contour maps of T, D, Q and the hover model's error.")
@click.option("--plot-rpm", default=None, help="Comma-separated rpm of the contour maps (default: the middle of the "
                                               "rpm axis).")
@click.option("--json", "as_json", is_flag=True, help="Print the map's metadata and error bound as JSON.")
@with_prop_options
def map_command(prop, rpm_axis, airspeed_axis, incidence_axis, params_spec, out, fmt, c_type, c_interpolation,
                c_name, check_points, check_file, all_props, only, scheduler, plot_dir, plot_rpm, as_json, diameter_in,
                blades):
    """Tabulate the model over (rpm, airspeed, incidence) for real-time use.

    The map stores thrust, drag, torque, rolling moment, power, CT, CP and the flags of
    every node, the propeller, parameters, model and version that made it, and its measured
    interpolation error (the full model at random off-grid points). Evaluate it with
    propmap.RotorMap (Python) or the C header (--format c); docs/simulators.md.
    """
    import numpy as np

    if check_file is not None:
        given = [o for o, v in (("PROP", prop), ("--out", out), ("--all", all_props), ("--plot", plot_dir),
                                ("--rpm", rpm_axis), ("--airspeed", airspeed_axis),
                                ("--incidence-deg", incidence_axis), ("--params", params_spec)) if v]
        if given:
            raise InputError(f"--check takes a map file only; {', '.join(given)} do not apply")
        return _check(check_file, check_points, as_json)
    if all_props and prop:
        raise InputError("give PROP or --all, not both")
    if only and not all_props:
        raise InputError("--props applies to --all")
    only_names = [n.strip() for n in only.split(",") if n.strip()]
    if only and not only_names:
        raise InputError(f"--props: no propeller name in {only!r}")
    twice = sorted({n for n in only_names if only_names.count(n) > 1})
    if twice:
        raise InputError(f"--props: {', '.join(twice)} given more than once")
    if not all_props and not prop:
        raise InputError("give PROP (catalogue name or geometry file), --all, or --check MAP.nc")
    if out is None:
        raise InputError("--out is required (the map file)")
    if all_props and fmt != "netcdf":
        raise InputError("--all writes one netCDF map with a prop dimension; --format must be netcdf")
    if all_props and params_spec is not None:
        raise InputError("--params does not apply to --all (each propeller gets its default parameters)")
    if check_points < 0 or check_points > 1_000_000:
        raise InputError(f"--check-points must be in [0, 1000000], got {check_points}")
    if fmt != "c" and c_type != "float":
        raise InputError("--c-type applies to --format c")
    if fmt != "c" and (c_interpolation != "linear" or c_name is not None):
        raise InputError(f"{'--c-name' if c_name is not None else '--c-interpolation'} applies to --format c")
    if fmt == "c":
        from ..export_c import c_prefix

        try:
            c_prefix(out, c_name)
        except ValueError as exc:
            raise InputError(f"{'--c-name' if c_name else '--out'}: {exc} (give --c-name)") from None
    if plot_rpm is not None and plot_dir is None:
        raise InputError("--plot-rpm applies to --plot")
    if out.suffix.lower() != FORMATS[fmt]:
        raise InputError(f"--out: {out}: a {fmt} map is named *{FORMATS[fmt]} (or choose --format)")
    inputs = [params_spec, prop]
    outputs = [("--out", out), ("--out (sidecar)", out.with_name(out.name + ".json"))]
    check_outputs(outputs, inputs)
    if plot_dir is not None:
        check_out_dir("--plot", plot_dir, ["map_contours_probe.png"], inputs)

    from ..maps import build_map, write_map, write_sidecar

    t0 = time.perf_counter()
    if all_props:
        ds = _build_all(rpm_axis, airspeed_axis, incidence_axis, check_points, scheduler, only_names)
    else:
        propeller = load_prop(prop, diameter_in, blades)
        params, air, label = load_params(params_spec, prop)
        rpm, V, inc = _axes(propeller, rpm_axis, airspeed_axis, incidence_axis)
        citation = _citation(prop)
        ds = build_map(propeller, params, rpm * math.pi / 30, V, np.radians(inc), air=air, params_label=label,
                       citation=citation, scheduler=scheduler, progress=True, n_check=check_points)
    elapsed = time.perf_counter() - t0
    ds.attrs["build_seconds"] = elapsed
    if fmt == "c":
        from ..export_c import write_c_header
        from ..maps import RotorMap

        files = [write_c_header(RotorMap(ds, c_interpolation), out, dtype=c_type, name=c_name),
                 write_sidecar(ds, out.with_name(out.name + ".json"))]
    else:
        files = write_map(ds, out, fmt)
    if plot_dir is not None and not all_props:
        files += _plots(ds, plot_dir, plot_rpm)
    _report(ds, files, elapsed, as_json)


def _axes(propeller, rpm_axis, airspeed_axis, incidence_axis):
    from ..maps import default_axes

    rpm, V, inc = default_axes(propeller)
    if rpm_axis:
        rpm = parse_axis("--rpm", rpm_axis, RPM_MIN, RPM_MAX, "rpm")
    if airspeed_axis:
        V = parse_axis("--airspeed", airspeed_axis, 0.0, 500.0, "m/s")
    if incidence_axis:
        inc = parse_axis("--incidence-deg", incidence_axis, 0.0, 180.0, "deg")
    n = rpm.size * V.size * inc.size
    if n > MAX_POINTS:
        raise InputError(f"the grid has {n:,} points; at most {MAX_POINTS:,} (about 8 minutes on 2 cores)")
    return rpm, V, inc


def _citation(prop: str) -> str:
    from ..io.catalogue import catalogue

    entry = catalogue().get(prop)
    return entry.citation if entry is not None else ""


def _build_all(rpm_axis, airspeed_axis, incidence_axis, check_points, scheduler, only):
    """One Dataset over the catalogue: the maps stacked along ``prop``, per-propeller
    metadata in the attribute ``per_prop_json``."""
    import numpy as np
    import xarray as xr
    from tqdm import tqdm

    from ..io.calibration import default_params
    from ..io.catalogue import catalogue, load_propeller
    from ..maps import build_map

    names = sorted(only or catalogue())
    unknown = [n for n in names if n not in catalogue()]
    if unknown:
        raise InputError(f"--props: unknown propeller(s) {', '.join(unknown)}")
    props = [load_propeller(n) for n in names]
    median = props[int(np.argsort([p.diameter for p in props])[len(props) // 2])]
    rpm, V, inc = _axes(median, rpm_axis, airspeed_axis, incidence_axis)
    maps, per_prop = [], {}
    for name, p in tqdm(list(zip(names, props)), unit="prop", leave=False, disable=None):
        params, air, label = default_params(name)
        ds = build_map(p, params, rpm * math.pi / 30, V, np.radians(inc), air=air, params_label=label,
                       citation=catalogue()[name].citation, scheduler=scheduler, n_check=check_points)
        per_prop[name] = {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in ds.attrs.items()}
        ds = ds.copy()
        ds.attrs = {}
        maps.append(ds)
    # "override": the variables keep their units and long names (those of the first map)
    out = xr.concat(maps, dim=xr.DataArray(names, dims="prop", name="prop"), combine_attrs="override")
    out.attrs = {"title": "propmap rotor maps of the catalogue", "propmap_version": maps and per_prop[names[0]]
                 ["propmap_version"], "per_prop_json": json.dumps(per_prop, default=float),
                 "note": "RotorMap.open(path, prop=NAME) evaluates one propeller's map"}
    return out


def _plots(ds, plot_dir: Path, plot_rpm):
    import numpy as np

    from ..plots import plot_map_contours

    rpm_values = ds["rpm"].values
    wanted = [float(rpm_values[len(rpm_values) // 2])] if not plot_rpm else []
    for part in (plot_rpm or "").split(","):
        if part.strip():
            try:
                wanted.append(float(part))
            except ValueError:
                raise InputError(f"--plot-rpm: {part!r} is not a number") from None
    files = []
    for r in wanted:
        node = float(rpm_values[int(np.argmin(np.abs(rpm_values - r)))])
        path = plot_dir / f"map_contours_{node:.0f}rpm.png"
        title = (f"{ds.attrs.get('propeller', '')}, {ds.attrs.get('params_label', '')} "
                 f"(propmap map; data: {ds.attrs.get('citation', '') or 'see params'})")
        files.append(plot_map_contours(ds, node, path, title=title))
    return files


def _report(ds, files, elapsed: float, as_json: bool) -> None:
    a = ds.attrs
    if as_json:
        echo_json({"files": [str(f) for f in files], "build_seconds": elapsed,
                   **{k: v for k, v in a.items() if k.startswith("check_") and not (isinstance(v, float)
                                                                                  and math.isnan(v))}})
        return
    dims = " x ".join(f"{n} {d}" for d, n in ds.sizes.items())
    click.echo(f"map of {a.get('propeller', 'the catalogue')}: {dims} = {math.prod(ds.sizes.values()):,} nodes "
               f"in {elapsed:.1f} s")
    if "check_points" in a:
        click.echo(f"interpolation error against the full model at {a['check_points']} random points "
                   f"({a['check_points_flagged']} in flagged cells, reported apart):")
        click.echo(f"  {'':<16}{'cubic rms':>10}{'max':>8}{'max flagged':>13}{'linear rms':>12}{'max':>8}"
                   f"{'max flagged':>13}   normalised by")
        norms = {"thrust": "static thrust", "drag": "largest drag", "torque": "static torque",
                 "rolling_moment": "largest M_R", "power": "static power"}
        for k, norm in norms.items():
            c, lin = (f"check_{m}_{k}" for m in ("cubic", "linear"))
            click.echo(f"  {k:<16}{a[c + '_rms']:>10.3%}{a[c + '_max']:>8.3%}{a[c + '_max_flagged']:>13.2%}"
                       f"{a[lin + '_rms']:>12.3%}{a[lin + '_max']:>8.3%}{a[lin + '_max_flagged']:>13.2%}   {norm}")
        click.echo("  (propmap.RotorMap interpolates cubic by default, the C header linear)")
    click.echo("wrote " + ", ".join(str(f) for f in files), err=True)


def _check(path: Path, n: int, as_json: bool) -> None:
    from ..maps import RotorMap

    if not 1 <= n <= 1_000_000:
        raise InputError(f"--check-points must be in [1, 1000000] with --check, got {n}")
    try:
        rm = RotorMap.open(path)
    except ValueError as exc:
        raise InputError(f"--check: {exc}") from None
    # fresh points: another seed than the stored check's
    seed = int(rm.attrs.get("check_seed", 0)) + 1
    try:
        res = rm.check(n, seed=seed)
    except (KeyError, ValueError, TypeError) as exc:
        raise InputError(f"--check: {path} does not record the model that made it ({type(exc).__name__}: "
                         f"{exc}); it was not written by propmap map") from None
    stored = {k: (v.item() if hasattr(v, "item") else v) for k, v in rm.attrs.items() if k.startswith("check_")}
    if as_json:
        echo_json({"recomputed": {k: v for k, v in res.items() if not (isinstance(v, float) and math.isnan(v))},
                   "stored": {k: v for k, v in stored.items() if not (isinstance(v, float) and math.isnan(v))}})
        return
    click.echo(f"{path}: {rm.attrs.get('propeller')} ({rm.attrs.get('params_label')}), recomputed at {n} fresh "
               f"points (seed {seed}; stored values in brackets):")
    nan = float("nan")
    click.echo(f" {res['check_points_flagged']} of them flagged")
    for method in ("cubic", "linear"):
        p = f"check_{method}_"
        click.echo(f" {method}:")
        for k in ("thrust", "drag", "torque", "rolling_moment", "power"):
            click.echo(f"  {k:<16} max {res[f'{p}{k}_max']:.3%} ({stored.get(f'{p}{k}_max', nan):.3%}), "
                       f"rms {res[f'{p}{k}_rms']:.3%} ({stored.get(f'{p}{k}_rms', nan):.3%})")
