"""``propmap map``: tabulate the model for real-time use (netCDF, CSV or C), check a map."""

from __future__ import annotations

import contextlib
import json
import math
import time
from dataclasses import dataclass
from pathlib import Path

import click

from ..core.units import RPM
from ._air import resolve_air, with_air_options
from ._common import (Command, warn, PARAMS_HELP, RPM_MAX, RPM_MIN, InputError, PathArg, check_section_match, echo_json,
                      given, load_params, option_group, parse_names, radians_like, set_collective_deg,
                      with_prop_options)
from ._coverage import coverage_messages, envelope_extremes
from ._paths import check_out_dir, check_outputs, vehicle_inputs
from ._sources import catalogue_citation
from .map_check import TARGETS_PCT, _check, _pct, _target_misses, _where

FORMATS = {"netcdf": ".nc", "csv": ".csv", "c": ".h"}
MAX_AXIS = 2000


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


def radians_note(option: str, stop: float) -> None:
    """Warn where an incidence range in degrees ends at pi / 2 or pi to 2-5 digits (1.57, 3.14,
    3.1416: radians typed into a degrees option, :func:`radians_like`)."""
    if radians_like(stop):
        warn(f"{option}: the incidences end at {stop:g} deg: radians? ({stop:g} rad = {math.degrees(stop):.4g} deg; "
             "the option takes degrees)")


@dataclass(frozen=True)
class MapAxes:
    """The grid's axes as given: --rpm, --airspeed [m/s], --incidence-deg, each
    ``start:stop:count[:log]`` or None for the default (:func:`_axes`)."""

    rpm_axis: str | None = None
    airspeed_axis: str | None = None
    incidence_axis: str | None = None


@dataclass(frozen=True)
class CHeaderChoice:
    """The options of ``--format c``: the table type, the interpolation, the identifier
    prefix and a vehicle whose body wrench the header adds."""

    c_type: str = "float"
    c_interpolation: str = "linear"
    c_name: str | None = None
    vehicle: Path | None = None


@dataclass(frozen=True)
class PlotChoice:
    """--plot (a folder of contour maps) and --plot-rpm (their rpm, comma-separated)."""

    plot_dir: Path | None = None
    plot_rpm: str | None = None


axis_options = [
    click.option("--rpm", "rpm_axis", default=None,
                 help="rpm axis start:stop:count[:log] (default: 21 values, geometric, from 1/6 of the rpm of a "
                      "150 m/s tip speed to it)."),
    click.option("--airspeed", "airspeed_axis", default=None,
                 help="Airspeed axis [m/s] start:stop:count (default 0:25:26)."),
    click.option("--incidence-deg", "incidence_axis", default=None,
                 help="Incidence axis [deg] start:stop:count (default 0:180:73)."),
]
c_options = [
    click.option("--c-type", type=click.Choice(["float", "double"]), default="float", show_default=True,
                 help="Table type of --format c."),
    click.option("--c-interpolation", type=click.Choice(["linear", "cubic"]), default="linear", show_default=True,
                 help="Interpolation of the --format c function (linear: 22-23 ns a call; cubic, the Python "
                      "evaluator's default: 92-97 ns, 2.6-5.4x smaller largest errors; docs/simulators.md)."),
    click.option("--c-name", default=None, help="C identifier prefix of --format c (default: pm_<file name>)."),
    click.option("--vehicle", type=PathArg(text=True), default=None,
                 help="With --format c: add <prefix>_vehicle_wrench, the body force and moment of this vehicle TOML "
                      "(every rotor this map's propeller)."),
]
plot_options = [
    click.option("--plot", "plot_dir", type=PathArg(), default=None,
                 help="Folder for contour maps of T, D, Q and the hover model's error."),
    click.option("--plot-rpm", default=None, help="Comma-separated rpm of the contour maps, within the rpm axis (each "
                                                  "drawn at its nearest node; default: the middle of the axis)."),
]
with_axis_options = option_group("axes", MapAxes, axis_options)
with_c_options = option_group("c_header", CHeaderChoice, c_options)
with_plot_options = option_group("plot", PlotChoice, plot_options)


@click.command("map", cls=Command)
@click.argument("prop", required=False)
@with_axis_options
@click.option("--params", "params_spec", default=None,
              help=PARAMS_HELP + " With --vehicle: the set the vehicle gives every rotor (the rotors' own params, "
                                 "else the vehicle file's, else their catalogue propeller's calibrated set), else the "
                                 "vehicle file's own params.")
@click.option("--collective-deg", type=float, default=None,
              help="Collective of a variable-pitch rotor: a blade-angle offset [deg] added to the parameter set's "
                   "(the sum within [-30, 30]); stored with the map's parameters.")
@click.option("--out", type=PathArg(file=True), default=None,
              help="Map file; a JSON sidecar OUT.json of its metadata is written beside it.")
@click.option("--format", "fmt", type=click.Choice(list(FORMATS)), default="netcdf", show_default=True,
              help="netcdf (xarray Dataset), csv (long form) or c (a C99 header).")
@with_c_options
@click.option("--check-points", type=int, default=2000, show_default=True,
              help="Random off-grid points at which the full model checks the map (0: none).")
@click.option("--check", "check_file", type=PathArg(), default=None,
              help="Recompute the measured error of an existing netCDF map on fresh points (no PROP).")
@click.option("--all", "all_props", is_flag=True,
              help="One netCDF map over every catalogue propeller (a prop dimension), each with its default "
                   "parameters, on one grid (default axes from the median diameter).")
@click.option("--props", "only", default=None,
              help="With --all: comma-separated catalogue names to restrict to; with --check of a map over several "
                   "propellers: those to check (default: all).")
@click.option("--max-error-pct", type=float, default=None,
              help="With --check: the largest error outside flagged regions that passes, in % of static thrust and "
                   "torque (twice it for drag), cubic interpolation (default 1; exit 3 beyond).")
@click.option("--scheduler", default=None,
              help="Address of a dask.distributed scheduler (tcp://HOST:PORT) to build on; default: this machine.")
@with_plot_options
@click.option("--json", "as_json", is_flag=True, help="Print the map's metadata and measured error as JSON.")
@with_prop_options
@with_air_options
def map_command(prop, axes, params_spec, collective_deg, out, fmt, c_header, check_points, check_file, all_props, only,
                max_error_pct, scheduler, plot, as_json, prop_choice, air_choice):
    """Tabulate the model over (rpm, airspeed, incidence) for real-time use.

    The map stores thrust, drag, torque, rolling moment (and the side force and pitching
    moment where the parameter set makes them: flapping blades, a linear inflow, the dynamic
    stall; the C header leaves those out), power, CT, CP and the flags of every node, the
    propeller, parameters, model and version that made it, and its measured interpolation
    error (the full model at random off-grid points). Evaluate it with propmap.RotorMap
    (Python) or the C header (--format c); docs/simulators.md.
    """
    ctx = click.get_current_context()
    if check_file is not None:
        extra = [o for o in given(ctx, *(p.name for p in ctx.command.params)) if o not in ("--check", "--check-points",
                                                                                          "--json", "--props",
                                                                                          "--max-error-pct")]
        if extra:
            verb = "does" if len(extra) == 1 else "do"
            raise InputError(f"--check takes a map file only; {', '.join(extra)} {verb} not apply")
        return _check(check_file, check_points, as_json, parse_names("--props", only, what="propeller name"),
                      max_error_pct)
    only = _check_options(ctx, prop, out, fmt, c_header, check_points, all_props, only, max_error_pct, plot)
    inputs = [params_spec, prop, c_header.vehicle, *vehicle_inputs(c_header.vehicle)]
    from ..io.mapfile import sidecar_path, written_path

    outputs = [("--out", out), ("--out (sidecar)", sidecar_path(written_path(out)))]
    check_outputs(outputs, inputs)
    veh = reading = None
    if c_header.vehicle is not None:
        from ._vehicle import _export_reading

        # (one parse of the file) a flight fit's [body] table (its airframe drag): from --params, else from the
        # vehicle file's own set, not from a rotor's set (as export-sim --vehicle takes it)
        reading, veh, _ = _export_reading(c_header.vehicle, params_spec)

    import numpy as np

    from ..maps import build_map, write_map

    if all_props:
        names, props = _catalogue(only)
        # one grid for all: the default axes of the median diameter
        median = props[int(np.argsort([p.diameter for p in props])[len(props) // 2])]
        rpm, V, inc = _axes(median, axes, len(names))
    else:
        propeller = prop_choice.load(prop)
        if veh is not None and params_spec is None:  # (the vehicle's set for every rotor, as export-sim's)
            from ..vehicle.own_set import _one_propeller_set

            params_spec = _one_propeller_set(reading, propeller)
        params, air, label = load_params(params_spec, prop)
        if veh is not None:  # refused before the build, not after it
            veh = _one_map_vehicle(veh, propeller, params, label)
        air = resolve_air(air, air_choice)
        check_section_match(propeller, label, collective_deg or 0.0)
        data_label = label  # (the set whose data coverage the envelope is checked against)
        if collective_deg is not None:
            params, label = _with_collective(params, label, collective_deg)
        rpm, V, inc = _axes(propeller, axes)
        plots = [] if plot.plot_dir is None else _plot_files(plot.plot_dir, (rpm, V, inc), plot.plot_rpm, inputs,
                                                             outputs)
    t0 = time.perf_counter()
    with _scheduler(scheduler) as client:
        if all_props:
            air_of = (lambda a: resolve_air(a, air_choice))
            air_of(load_params("generic")[1])  # options checked before any work
            with _catalogue_maps(out, names, props, rpm, V, inc, check_points, client, air_of) as ds:
                files = write_map(ds, out, fmt)
        else:
            # the grid beyond the data behind the parameters (a fitted file's [coverage], a catalogue set's),
            # after every input check, the scheduler's included (an error is the only line)
            coverage_messages(propeller, data_label, air, *envelope_extremes(
                propeller, rpm[:, None, None], V[None, :, None], inc[None, None, :]),
                rpm=(float(rpm[0]), float(rpm[-1])), airspeed=float(V[-1]))
            ds = build_map(propeller, params, rpm * RPM, V, np.radians(inc), air=air, params_label=label,
                           citation=catalogue_citation(prop), scheduler=client, progress=True, n_check=check_points)
    elapsed = time.perf_counter() - t0
    if not all_props:  # (the build time is reported, not stored: a map built twice is the same file, a review)
        if fmt == "c":
            files = _write_c_header(ds, out, c_header, veh)
        else:
            files = write_map(ds, out, fmt)
        files += _plots(ds, plots)
    _report(ds, files, elapsed, as_json, c_header.c_interpolation if fmt == "c" else None)


def _check_options(ctx, prop, out, fmt, c_header: CHeaderChoice, check_points, all_props, only, max_error_pct,
                   plot: PlotChoice):
    """The refusals of a map build's options, before any input is read: which options go
    together, --out's name for the format and the C prefix it makes. Returns ``--props`` read
    (a tuple of names, or None)."""
    if max_error_pct is not None:
        raise InputError("--max-error-pct applies to --check")
    if all_props and prop:
        raise InputError("give PROP or --all, not both")
    only = parse_names("--props", only, what="propeller name")
    if only is not None and not all_props:
        raise InputError("--props applies to --all")
    if not all_props and not prop:
        raise InputError("give PROP (catalogue name, geometry file or a size such as 9x4.5), --all, or --check MAP.nc")
    if out is None:
        raise InputError("--out is required (the map file)")
    if all_props:
        ignored = given(ctx, "params_spec", "collective_deg", "fmt", "plot_dir", "plot_rpm", "diameter_in", "blades",
                        "c_type", "c_interpolation", "c_name", "vehicle")
        if ignored:
            raise InputError(f"{', '.join(ignored)} {'does' if len(ignored) == 1 else 'do'} not apply to --all (one "
                             "netCDF map, each propeller with its catalogue geometry and default parameters, no plots)")
    if not 0 <= check_points <= 1_000_000:
        raise InputError(f"--check-points must be in [0, 1000000], got {check_points}")
    if fmt != "c":
        ignored = given(ctx, "c_type", "c_interpolation", "c_name", "vehicle")
        if ignored:
            raise InputError(f"{', '.join(ignored)} appl{'ies' if len(ignored) == 1 else 'y'} to --format c")
    else:
        from ..export_c import c_prefix

        try:
            c_prefix(out, c_header.c_name)
        except ValueError as exc:
            raise InputError(f"{'--c-name' if c_header.c_name is not None else '--out'}: {exc}"
                             f"{'' if c_header.c_name is not None else ' (give --c-name)'}") from None
    if plot.plot_rpm is not None and plot.plot_dir is None:
        raise InputError("--plot-rpm applies to --plot")
    if out.suffix.lower() != FORMATS[fmt]:
        hint = f"--format {fmt}" if given(ctx, "fmt") else "or choose --format"
        raise InputError(f"--out: {out}: a {fmt} map is named *{FORMATS[fmt]} ({hint})")
    return only


def _one_map_vehicle(veh, propeller, params, label: str):
    """--vehicle with --format c: the vehicle whose body wrench the header adds, every rotor on the
    map's propeller (its geometry, not its name: a geometry file read with other blades) and set; a
    rotor's own set that is the map's (but for its air: every rotor is solved in the map's) is
    taken off the rotor, another is refused. (Until 2026-12-01 a rotor's own set was refused even
    where it was the map's: a vehicle whose rotors all name ``generic`` had no header, with or
    without ``--params generic``, stop 96.)"""
    from dataclasses import replace

    for k, r in enumerate(veh.rotors):
        if not r.propeller.same_geometry(propeller):
            other = (", another chord or blade angle" if
                     propeller.same_size(r.propeller.diameter, r.propeller.n_blades, rtol=5e-5) else "")
            raise InputError(f"--vehicle: rotor {k + 1} carries {r.propeller.name} ({r.propeller.diameter:.4g} "
                             f"m, {r.propeller.n_blades} blades{other}), not the map's {propeller.name} "
                             f"({propeller.diameter:.4g} m, {propeller.n_blades} blades): a C header holds one map "
                             "and one set")
        if r.params is not None and not params.same_section(r.params):
            theirs = f" ({r.params.label})" if r.params.label else ""
            raise InputError(f"--vehicle: rotor {k + 1} carries its own parameter set{theirs}, not the map's, "
                             f"{label}: a C header holds one map and one set (give --params, the set of every "
                             "rotor)")
    return replace(veh, rotors=tuple(replace(r, params=None) for r in veh.rotors))


def _with_collective(params, label: str, collective_deg: float):
    """The parameter set with --collective-deg added to its own collective, checked against
    [-30, 30] deg in sum, and its label saying so; a 0 leaves the set and its label as they are
    (its collective was rounded to 12 digits and its label changed, which lost the set's model
    uncertainty: an audit, stop 102)."""
    from ..core.airfoil import COLLECTIVE_MAX

    if collective_deg == 0.0:
        return params, label
    # (12 digits: 30 deg is degrees(COLLECTIVE_MAX) = 29.999999999999996, and must pass)
    set_deg = set_collective_deg(params)
    total = float(f"{set_deg + collective_deg:.12g}")
    limit = float(f"{math.degrees(COLLECTIVE_MAX):.12g}")
    if not (math.isfinite(collective_deg) and abs(total) <= limit):
        raise InputError(f"--collective-deg: the parameter set's collective {set_deg:g} deg plus "
                         f"{collective_deg:g} deg must be within [-{limit:g}, {limit:g}] deg, got {total:.6g}")
    return params.replace(collective=math.radians(total)), f"{label} + collective {collective_deg:g} deg"


def _write_c_header(ds, out: Path, c_header: CHeaderChoice, veh):
    """Write the C99 header of the map (with the vehicle's body wrench when --vehicle is given)
    and its sidecar; returns the files written."""
    from ..export_c import c_header_text, c_prefix
    from ..io.mapfile import write_with_sidecar
    from ..maps import RotorMap

    try:
        text = c_header_text(RotorMap(ds, c_header.c_interpolation), out, dtype=c_header.c_type,
                             name=c_header.c_name, vehicle=veh)
    except ValueError as exc:
        raise InputError(f"{'--vehicle' if veh is not None else '--format c'}: {exc}") from None
    # the sidecar describes the header: its interpolation, table type and identifiers' prefix
    ds.attrs.update(c_interpolation=c_header.c_interpolation, c_type=c_header.c_type,
                    c_prefix=c_prefix(out, c_header.c_name))
    return write_with_sidecar(ds, out, lambda tmp: tmp.write_text(text, encoding="utf-8"))


def _axes(propeller, axes: MapAxes, n_props: int = 1):
    """The grid's axes: the options given, else the defaults for ``propeller``; refused
    (before any work) beyond MAX_NODES nodes over ``n_props`` propellers."""
    from ..maps import MAX_NODES, default_axes

    rpm, V, inc = default_axes(propeller)
    if axes.rpm_axis is not None:
        rpm = parse_axis("--rpm", axes.rpm_axis, RPM_MIN, RPM_MAX, "rpm")
    if axes.airspeed_axis is not None:
        V = parse_axis("--airspeed", axes.airspeed_axis, 0.0, 500.0, "m/s")
    if axes.incidence_axis is not None:
        inc = parse_axis("--incidence-deg", axes.incidence_axis, 0.0, 180.0, "deg")
        radians_note("--incidence-deg", float(inc[-1]))
    n = rpm.size * V.size * inc.size
    if n * n_props > MAX_NODES:
        each = f" for each of {n_props} propellers" if n_props > 1 else ""
        raise InputError(f"the grid has {n:,} points{each} ({n * n_props:,} in all); at most {MAX_NODES:,} "
                         "(about 8 minutes on 2 cores): give coarser axes" + (" or --props" if n_props > 1 else ""))
    return rpm, V, inc


@contextlib.contextmanager
def _scheduler(address):
    """A dask.distributed Client for --scheduler (None without), closed at the end."""
    if address is None:
        yield None
        return
    from ..maps import scheduler_client

    try:
        client = scheduler_client(address)
    except ValueError as exc:
        raise InputError(f"--scheduler: {exc}") from None
    try:
        yield client
    finally:
        client.close()


def _catalogue(only):
    """(names, propellers) of --all: the catalogue, or the --props names in it."""
    from ..io.catalogue import catalogue, load_propeller

    names = sorted(only or catalogue())
    unknown = [n for n in names if n not in catalogue()]
    if unknown:
        raise InputError(f"--props: unknown propeller(s) {', '.join(unknown)}")
    return names, [load_propeller(n) for n in names]


@contextlib.contextmanager
def _catalogue_maps(out: Path, names, props, rpm, V, inc, check_points, client, air_of=lambda air: air):
    """The maps of ``names`` on one grid, as one lazy Dataset along ``prop`` (per-propeller
    metadata in the attribute ``per_prop_json``). Each propeller's map goes to a hidden
    folder beside ``out`` as soon as it is built (removed at the end, also when stopped),
    so that memory holds one propeller's map at a time, also while the result is written."""
    import tempfile

    import numpy as np
    import xarray as xr
    from tqdm import tqdm

    from ..io.atomic import signals_held
    from ..io.calibration import default_params
    from ..io.catalogue import catalogue
    from ..io.mapfile import NETCDF_LOCK
    from ..io.netcdf_write import to_netcdf_here
    from ..maps import build_map

    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix=f".{out.name}.", suffix=".parts", dir=out.parent) as tmp:
        parts, per_prop = [], {}
        for k, (name, p) in enumerate(tqdm(list(zip(names, props)), unit="prop", leave=False, disable=None)):
            params = default_params(name)
            air, label = params.air, params.label
            ds = build_map(p, params, rpm * RPM, V, np.radians(inc), air=air_of(air), params_label=label,
                           citation=catalogue()[name].citation, scheduler=client, n_check=check_points)
            per_prop[name] = {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in ds.attrs.items()}
            parts.append(Path(tmp) / f"{k:04d}.nc")
            ds.attrs = {}
            with NETCDF_LOCK, signals_held():  # (a signal inside HDF5's write deadlocked it: io.atomic.signals_held)
                to_netcdf_here(ds, parts[-1])
            del ds
        with NETCDF_LOCK:
            combined = xr.open_mfdataset(parts, combine="nested", concat_dim="prop", engine="netcdf4",
                                         data_vars="all", coords="minimal", compat="override",
                                         combine_attrs="override")
        try:
            combined = combined.assign_coords(prop=("prop", names))
            for v in combined.variables.values():
                v.encoding = {}
            combined.attrs = {"title": "propmap rotor maps of the catalogue",
                              "propmap_version": per_prop[names[0]]["propmap_version"],
                              "propmap_source_sha256": per_prop[names[0]]["propmap_source_sha256"],
                              "citation": "; ".join(sorted({str(a.get("citation", "")) for a in per_prop.values()}
                                                           - {""})),
                              "per_prop_json": json.dumps(per_prop, default=float),
                              "note": "RotorMap.open(path, prop=NAME) evaluates one propeller's map"}
            yield combined
        finally:
            with NETCDF_LOCK:
                combined.close()


def _plot_files(plot_dir: Path, grid, plot_rpm: str | None, inputs, outputs=()) -> list:
    """(node rpm, figure path) of each contour map, checked as outputs before any work, beside the
    command's ``outputs`` ((option, path): the map and its sidecar); ``grid`` the map's (rpm,
    airspeed [m/s], incidence [deg]) axes. Warns where the airspeed axis has no node at 0 m/s
    (the figures then leave out the hover model's panel).

    Raises
    ------
    InputError
        A --plot-rpm value that is not a number within the rpm axis, two values on one
        node, an airspeed or incidence axis of one node (no contour), or an unusable figure
        path (an input among them).
    ValueError
        Where matplotlib does not import (``plots.require_matplotlib``: an unknown MPLBACKEND).
    """
    import numpy as np

    from ..plots import require_matplotlib

    rpm, V, inc = grid
    require_matplotlib()  # (before the build: it failed after the map was written, an audit, stop 102)
    if V.size < 2 or inc.size < 2:
        raise InputError(f"--plot: a contour needs at least two nodes on --airspeed and --incidence-deg; the grid "
                         f"has {V.size} and {inc.size}")
    if not np.any(V == 0.0):
        warn(f"--plot: the airspeed axis starts at {float(np.min(V)):g} m/s, without the static node, so the figures "
             "leave out the hover model's error panel (it needs the static thrust)")

    if plot_rpm is None:
        nodes = [float(rpm[len(rpm) // 2])]
    else:
        nodes = []
        for part in plot_rpm.split(","):
            try:
                r = float(part)
            except ValueError:
                raise InputError(f"--plot-rpm: {part.strip()!r:.40} is not a number") from None
            if not (math.isfinite(r) and rpm[0] <= r <= rpm[-1]):
                raise InputError(f"--plot-rpm: {part.strip():.40} is outside the map's rpm axis "
                                 f"[{rpm[0]:g}, {rpm[-1]:g}]")
            node = float(rpm[int(np.argmin(np.abs(rpm - r)))])
            if node in nodes:
                raise InputError(f"--plot-rpm: {part.strip():.40} falls on the node {node:.0f} rpm of another "
                                 "value (maps are drawn at nodes)")
            nodes.append(node)
            if abs(node - r) > 1e-9 * node:
                warn(f"--plot-rpm {part.strip():.40}: drawn at the nearest node of the rpm axis, {node:.0f} rpm (maps "
                     "are drawn at nodes; give --rpm with that value as a node to draw it)")
    paths = check_out_dir("--plot", plot_dir, [f"map_contours_{n:.0f}rpm.png" for n in nodes], inputs, outputs)
    return list(zip(nodes, paths))


def _plots(ds, plots) -> list:
    from ..plots import plot_map_contours

    title = (f"{ds.attrs.get('propeller', '')}, {ds.attrs.get('params_label', '')} "
             f"(propmap map; data: {ds.attrs.get('citation', '') or 'see params'})")
    return [plot_map_contours(ds, node, path, title=title) for node, path in plots]


def _report(ds, files, elapsed: float, as_json: bool, c_interpolation: str | None = None) -> None:
    a = ds.attrs
    miss = None
    if "check_points" in a and "per_prop_json" not in a:  # one propeller's map: the targets, warned of where missed
        method = c_interpolation or "cubic"  # what the written file interpolates
        over = _target_misses(a, method)
        if over:
            said = ", ".join(f"{k} {v:.1f}%{_where(a, method, k)}" for k, v in over.items())
            miss = (f"the map misses the targets at its check points ({method}, outside flagged regions: 1% of static "
                    f"thrust and torque, 2% of the largest drag): {said} (the "
                    f"{'check_ values' if as_json else 'table above'}; refine the axes where it matters, and "
                    "`map --check FILE` measures again at fresh points)")
    # (the sidecar's metadata beside the measured error: propeller, set, air, grid; once only the error)
    if as_json:
        if miss:  # (before the JSON, which carries the run's warnings: it left this one out until 2026-12-02, a review)
            warn(miss)
        from ..io.mapfile import map_metadata

        echo_json({"files": [str(f) for f in files], "build_seconds": elapsed,
                   **{k: v for k, v in a.items() if (k.startswith("check_") or k.startswith("model_uncertainty_"))
                      and not (isinstance(v, float) and math.isnan(v))},
                   "metadata": map_metadata(ds) if "propeller" in a else None})
        return
    dims = " x ".join(f"{n} {d}" for d, n in ds.sizes.items())
    click.echo(f"map of {a.get('propeller', 'the catalogue')}: {dims} = {math.prod(ds.sizes.values()):,} nodes "
               f"in {elapsed:.1f} s")
    if "check_points" in a:
        click.echo(f"interpolation error against the full model at {a['check_points']} random points "
                   f"({a['check_points_flagged']} in flagged cells, reported apart):")
        click.echo(f"  {'':<16}{'cubic rms':>10}{'max':>9}{'max flagged':>13}{'linear rms':>12}{'max':>9}"
                   f"{'max flagged':>13}   normalised by")
        norms = {"thrust": "static thrust", "drag": "largest drag", "torque": "static torque",
                 "rolling_moment": "largest M_R", "side_force": "largest Y", "pitching_moment": "largest M_P",
                 "power": "static power"}
        for k, norm in ((k, n) for k, n in norms.items() if f"check_cubic_{k}_rms" in a):
            c, lin = (f"check_{m}_{k}" for m in ("cubic", "linear"))
            click.echo(f"  {k:<16}{_pct(a[c + '_rms'], 10)}{_pct(a[c + '_max'], 9)}{_pct(a[c + '_max_flagged'], 13, 2)}"
                       f"{_pct(a[lin + '_rms'], 12)}{_pct(a[lin + '_max'], 9)}{_pct(a[lin + '_max_flagged'], 13, 2)}"
                       f"   {norm}")
        click.echo("  (propmap.RotorMap interpolates cubic by default; "
                   + (f"this C header interpolates {c_interpolation})" if c_interpolation
                      else "a C header linear unless --c-interpolation cubic)"))
    if "per_prop_json" in a:  # a map over several propellers: which of them miss the targets on the shared grid
        click.echo(_catalogue_summary(a["per_prop_json"]))
    elif miss:  # one propeller's map: the same targets, said as a warning where they are missed
        warn(miss)
    if "model_uncertainty_axial" in a:  # the model's own error against measurements, beside the map's against it
        click.echo(f"the model against measurements ({a.get('params_label', '')}): axial: "
                   f"{a['model_uncertainty_axial']}; off-axis: {a['model_uncertainty_off_axis']}")
    click.echo("wrote " + ", ".join(str(f) for f in files), err=True)


def _catalogue_summary(per_prop_json: str) -> str:
    """One paragraph on a map over several propellers: how many miss the map targets (cubic, outside
    flagged regions: 1% of static thrust and torque, 2% of the largest drag) at their stored check
    points, and the worst three."""
    per_prop = json.loads(per_prop_json)
    checked = [name for name, attrs in per_prop.items()
               if all(math.isfinite(float(attrs.get(f"check_cubic_{k}_max", float("nan")))) for k in TARGETS_PCT)]
    if not checked:
        return f"the {len(per_prop)} propellers' maps were not checked against the model (--check-points 0)"
    worst = {}
    for name in checked:
        over = _target_misses(per_prop[name])
        if over:
            k = max(over, key=lambda q: over[q] / TARGETS_PCT[q])
            worst[name] = (over[k] / TARGETS_PCT[k], k, over[k])
    if not worst:
        return (f"every one of the {len(checked)} checked propellers' maps meets the targets (cubic, outside flagged "
                "regions: 1% of static thrust and torque, 2% of the largest drag) at its check points")
    top = sorted(worst.items(), key=lambda kv: -kv[1][0])[:3]
    shown = ", ".join(f"{n} {q} {v:.1f}%" for n, (_, q, v) in top)
    return (f"{len(worst)} of the {len(checked)} checked propellers' maps miss the targets at their check points "
            f"(cubic, outside flagged regions: 1% of static thrust and torque, 2% of the largest drag), worst "
            f"{shown}: the shared grid is coarse for them; map them one by one (its default grid follows the "
            "propeller) or refine the axes")
