"""``propmap loads``: loads at one operating point or at every row of a CSV file."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import click

from ..core.units import RPM
from ._air import air_label, air_record, resolve_air, with_air_options
from ._common import (PARAMS_HELP, RPM_MAX, RPM_MIN, Command, InputError, PathArg, check_point, check_section_match,
                      echo_json, fixed, geometry_label, geometry_record, load_params, set_collective_deg, warn,
                      warn_incidence_radians, with_prop_options)
from ._coverage import coverage_messages, envelope_extremes
from ._paths import check_outputs
# (the --points file's reader, cli/_points.py; its constants re-exported here, where they were)
from ._points import (COLLECTIVE_COLUMN, COLLECTIVE_DEG_MAX, INPUT_COLUMNS, MAX_HEADER_BYTES,  # noqa: F401
                      MAX_NAME, MAX_POINTS_FILE_BYTES, _chunks)

#: the numeric outputs (RotorLoads attributes), then the descent outputs, converged and flags
OUTPUT_KEYS = ("thrust", "drag", "torque", "rolling_moment", "power", "CT", "CQ", "CP", "v_i_over_v_h", "lambda2",
               "state", "converged", "flags")
NUMERIC_KEYS = OUTPUT_KEYS[:8]
#: the side force Y [N] and the pitching moment M_P [N m], after rolling_moment where the parameter
#: set makes them (RotorOptions.side_load_sources: blade flapping, a linear inflow, the dynamic
#: stall), as a map holds them; absent (0 by symmetry) otherwise
SIDE_KEYS = ("side_force", "pitching_moment")
UNITS = {"thrust": "N", "drag": "N", "torque": "N m", "rolling_moment": "N m", "side_force": "N",
         "pitching_moment": "N m", "power": "W"}

#: what the flags mean (printed with a single point, and in docs/cli.md)
FLAG_MEANINGS = {
    "not_converged": "the inflow solve failed at this point: its loads are NaN",
    "vortex_ring": "inside the vortex-ring band of descent rate and in-plane speed (Johnson, NASA/TP-2005-213477: "
                   "descent 0.45-1.5 v_h, closing at 0.95 v_h in-plane; thrust unsteady there, the loads are "
                   "the empirical mean)",
    "multiple_roots": "an annulus had several inflow roots; the selection rule of docs/solver.md picked one",
    "reverse_flow": "part of the blade root sees the air from behind (the blades' in-plane airspeed > Omega r_hub; "
                    "that airspeed includes the skewed wake's in-plane induction, docs/solver.md)",
    "inflow_extrapolated": "the inflow model was used beyond the measurements behind it (a linear inflow model "
                           "with net upflow through the disk, Drees's beyond an advance ratio of 0.5, or the "
                           "empirical descent curve blended with forward speed)",
}
CHUNK = 20000


def _flag_strings(r):
    """Per-point ';'-joined flag names, as a pandas Categorical (32 combinations at most)."""
    import numpy as np
    import pandas as pd

    keys = tuple(FLAG_MEANINGS)
    bits = np.stack([~r.converged, r.vortex_ring, r.multiple_roots, r.reverse_flow,
                     r.inflow_extrapolated]).astype(np.int64)
    code = (bits * (1 << np.arange(len(keys)))[:, None]).sum(axis=0)
    labels = [";".join(k for b, k in enumerate(keys) if m >> b & 1) for m in range(1 << len(keys))]
    return pd.Categorical.from_codes(code, categories=labels)


def _descent_outputs(r) -> dict:
    """v_i_over_v_h (mean induced inflow over the hover induced velocity at the thrust made),
    lambda2 (descent rate over v_h, positive descending) and the working state's name; the
    ratios are NaN (an empty CSV cell) where T <= 0, which has no hover induced velocity.
    lambda2 below 1e-12 is written 0 (cos(90 deg) is 6e-17 in floating point: no -5.2e-17 or -0.0 edgewise)."""
    import numpy as np

    lam = np.asarray(r.descent_ratio, float)
    lam = np.where(np.abs(lam) < 1e-12, 0.0, lam) + 0.0
    return {"v_i_over_v_h": r.v_i_over_v_h, "lambda2": lam, "state": r.state_name}


def numeric_keys(params) -> tuple[str, ...]:
    """The RotorLoads attributes written for ``params``: NUMERIC_KEYS, with SIDE_KEYS after
    rolling_moment where the set makes them."""
    return NUMERIC_KEYS[:4] + SIDE_KEYS + NUMERIC_KEYS[4:] if params.side_load_sources() else NUMERIC_KEYS


def solve_points(prop, params, air, rpm, airspeed, incidence_deg, collective_deg=None, flapping=None):
    """Loads at every point (arrays of rpm, airspeed [m/s], incidence [deg], and optionally
    the collective [deg]).

    Per-annulus outputs are not kept (``radial=False``). Returns a DataFrame of the
    outputs, one row per input row: thrust, drag, torque, rolling_moment (side_force,
    pitching_moment where the set makes them: :func:`numeric_keys`), power, CT, CQ, CP,
    v_i_over_v_h, lambda2, state, converged ("true"/"false"), flags. ``flapping``: a list to
    which (the points flapping beyond FLAP_ANGLE_WARN, the largest angle) is appended, for a
    caller that solves chunks and warns once.
    """
    import numpy as np
    import pandas as pd

    from ..core.solver import rotor_loads

    r = rotor_loads(prop, params, rpm * RPM, airspeed, np.radians(incidence_deg), air=air,
                    on_failure="flag", radial=False,
                    collective=None if collective_deg is None else np.radians(collective_deg))
    res = pd.DataFrame({k: getattr(r, k) for k in numeric_keys(params)})
    for k, v in _descent_outputs(r).items():
        res[k] = v
    res["converged"] = np.where(r.converged, "true", "false")
    res["flags"] = _flag_strings(r)
    if flapping is not None:
        from ..core.flapping import large_flapping

        flapping.append(large_flapping(r.flap_1c, r.flap_1s))
    return res


def _output_names(inputs, outputs) -> list[str]:
    """Output column names that clash with no input column (any case): ``_model`` is
    appended, as often as needed."""
    taken = {c.lower() for c in inputs}
    names = []
    for c in outputs:
        name = c
        while name.lower() in taken:
            name += "_model"
        taken.add(name.lower())
        names.append(name)
    return names


def _run_points(prop, params, air, label: str, path: Path, out, progress: bool) -> tuple[int, dict, str]:
    """Validate the whole points file, then solve and write it chunk by chunk.

    Memory stays bounded by the chunk size whatever the file's length (the output goes to a
    temporary file renamed at the end, or to standard output). Returns (points, the number
    of points carrying each flag of FLAG_MEANINGS, in its order, the name of the output's flags
    column: ``flags``, or ``flags_model`` where an input column took ``flags``).
    """
    import warnings

    from tqdm import tqdm

    from ..core.flapping import FlappingWarning, flapping_message, flapping_warning_held
    from ..io.atomic import atomic_write

    # first pass: every value checked before any work, and the extremes for the warnings
    offset = set_collective_deg(params)  # the set's collective, added to each row's
    n, extremes, rpm_range, v_max, collectives = _scan(prop, path, offset)
    check_section_match(prop, label, collective_range=collectives)  # (the column's rows, not 0 deg)
    coverage_messages(prop, label, air, *extremes, rpm=rpm_range, airspeed=v_max)

    column = ["flags"]  # (the output's name of it, set by the first chunk)

    def write(fh):
        counts = dict.fromkeys(FLAG_MEANINGS, 0)
        flapping = []  # (each chunk's large flapping: one warning for the file, not one per chunk, a review)
        with tqdm(total=n, unit="pt", disable=True if (not progress or n <= CHUNK) else None, leave=False) as bar:
            for k, (df, _, values) in enumerate(_chunks(path, CHUNK, offset)):  # the input cells are written as read
                rows = values.get(COLLECTIVE_COLUMN)
                # with a collective column the solver gets the sum (the set's offset + the row's), the one limit
                with flapping_warning_held():
                    res = solve_points(prop, params if rows is None else params.replace(collective=0.0), air,
                                       values["rpm"], values["airspeed"], values["incidence_deg"],
                                       None if rows is None else rows + offset, flapping)
                flags = list(res.columns).index("flags")  # (by place: it may be renamed below)
                res.columns = _output_names(df.columns, res.columns)
                column[0] = res.columns[flags]
                df = df.reset_index(drop=True)
                for c in res.columns:
                    a = res[c].to_numpy()
                    df[c] = a + 0.0 if a.dtype.kind == "f" else a  # (+ 0.0: no "-0" written for a zero)
                df.to_csv(fh, index=False, header=k == 0, float_format="%.10g", lineterminator="\n")
                for names, count in res.iloc[:, flags].value_counts().items():
                    for name in filter(None, names.split(";")):
                        counts[name] += int(count)
                bar.update(len(df))
        big = sum(c for c, _ in flapping)
        if big:
            warnings.warn(flapping_message(big, max(a for _, a in flapping), params.flap_compliance), FlappingWarning,
                          stacklevel=2)
        return counts

    if str(out) == "-":
        return n, write(sys.stdout), column[0]
    with atomic_write(out, "w", newline="") as fh:
        bad = write(fh)
    return n, bad, column[0]


@click.command("loads", cls=Command)
@click.argument("prop")
@click.option("--rpm", type=float, help=f"Rotation rate [rpm], in [{RPM_MIN:g}, {RPM_MAX:.0f}].")
@click.option("--airspeed", type=float, default=None, help="Airspeed V [m/s], in [0, 500] (default 0).")
@click.option("--incidence-deg", type=float, default=None,
              help="Angle between the rotor's velocity through the air and its axis [deg]: 0 climb, 90 edgewise, "
                   "180 descent (default 0).")
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP)
@click.option("--collective-deg", type=float, default=None,
              help=f"Collective: a blade-angle offset [deg] added to every blade angle, in "
                   f"[-{COLLECTIVE_DEG_MAX:g}, {COLLECTIVE_DEG_MAX:g}] (default 0; a points file takes a "
                   f"{COLLECTIVE_COLUMN} column).")
@click.option("--points", type=PathArg(),
              help="CSV (',', ';' or tab) with columns rpm, airspeed, incidence_deg (any case, with or without a "
                   "unit: RPM, airspeed (m/s), incidence (deg)) and optionally collective_deg; other columns are "
                   "kept in the output.")
@click.option("--out", help="Output CSV of --points ('-': standard output).")
@click.option("--json", "as_json", is_flag=True, help="Print JSON (single point).")
@with_prop_options
@with_air_options
def loads(prop, rpm, airspeed, incidence_deg, collective_deg, params_spec, points, out, as_json, prop_choice,
          air_choice):
    """Thrust, rotor drag, torque and power of PROP (catalogue name, geometry file, or a size
    9x4.5 or 5x4.5x3 in inches: a nominal blade, docs/cli.md).

    Outputs are SI: N, N m, W; CT, CQ and CP in the propeller convention; in descent the
    mean induced inflow over the hover induced velocity at that thrust (v_i_over_v_h),
    the descent ratio lambda2 = -V cos(incidence) / v_h and the rotor's working state.
    """
    if points is not None:
        _points_command(prop, rpm, airspeed, incidence_deg, collective_deg, params_spec, points, out, as_json,
                        prop_choice, air_choice)
        return
    if out is not None:
        raise InputError("--out applies to --points; a single point is printed")
    if rpm is None:
        raise InputError("give --rpm (one point) or --points IN.csv --out OUT.csv")
    airspeed = 0.0 if airspeed is None else airspeed
    incidence_deg = 0.0 if incidence_deg is None else incidence_deg
    check_point(rpm, airspeed, incidence_deg)
    warn_incidence_radians(incidence_deg, airspeed)
    collective_deg = check_collective(collective_deg)
    propeller = prop_choice.load(prop)
    params, air, label = load_params(params_spec, prop)
    air = resolve_air(air, air_choice)
    check_section_match(propeller, label, collective_deg)
    set_deg = set_collective_deg(params)  # the parameter set's own blade-angle offset, added to the option's
    total_deg = set_deg + collective_deg
    if abs(total_deg) > COLLECTIVE_DEG_MAX:
        raise InputError(f"--collective-deg: the parameter set's collective {set_deg:g} deg plus {collective_deg:g} "
                         f"deg must be within [-{COLLECTIVE_DEG_MAX:g}, {COLLECTIVE_DEG_MAX:g}] deg, got {total_deg:g}")
    coverage_messages(propeller, label, air, *envelope_extremes(propeller, rpm, airspeed, incidence_deg), rpm=rpm,
                      airspeed=airspeed)
    from ..core.solver import SolverError, rotor_loads

    try:
        r = rotor_loads(propeller, params, rpm * RPM, airspeed, math.radians(incidence_deg), air=air,
                        radial=False, collective=math.radians(collective_deg) if collective_deg else None)
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    result = {k: float(getattr(r, k)) for k in numeric_keys(params)}
    d = _descent_outputs(r)
    ratio = {k: (float(d[k]) if math.isfinite(float(d[k])) else None) for k in ("v_i_over_v_h", "lambda2")}
    result.update(ratio, state=str(d["state"]), converged=bool(r.converged), flags=r.flags())
    if as_json:
        echo_json({**result, "propeller": propeller.name, "n_blades": propeller.n_blades, **geometry_record(propeller),
                   "diameter_m": propeller.diameter, "params": label, "rpm": rpm, "airspeed": airspeed,
                   "incidence_deg": incidence_deg, "collective_deg": total_deg, "params_collective_deg": set_deg,
                   "air": air_record(air),
                   "flag_meanings": {f: FLAG_MEANINGS[f] for f in r.flags()},
                   "units": {k: u for k, u in UNITS.items() if k in result}})
        return
    _echo_point(propeller, params, air, label, r, result, ratio, rpm, airspeed, incidence_deg, collective_deg, set_deg)


def _points_command(prop, rpm, airspeed, incidence_deg, collective_deg, params_spec, points, out, as_json, prop_choice,
                    air_choice) -> None:
    """loads --points: the operating points of a CSV solved and written as CSV (a file, or '-' for
    standard output), with a line on standard error of how many were written, did not converge
    or were flagged."""
    given = [o for o, v in (("--rpm", rpm), ("--airspeed", airspeed), ("--incidence-deg", incidence_deg),
                            ("--collective-deg", collective_deg)) if v is not None]
    if given:
        raise InputError(f"{', '.join(given)}: give the operating points either as options (one point) or in "
                         "--points (many), not both")
    if as_json:  # (before --out: "--out is required" sent a --json user the wrong way, a user-level audit)
        raise InputError("--json applies to a single point; --points writes a CSV")
    if out is None:
        raise InputError("--out is required with --points (a file, or '-' for standard output)")
    inputs = [points, prop, params_spec]
    if out != "-":
        check_outputs([("--out", out)], inputs)
    propeller = prop_choice.load(prop)
    params, air, label = load_params(params_spec, prop)
    air = resolve_air(air, air_choice)
    n, counts, column = _run_points(propeller, params, air, label, points, out, progress=out != "-")
    where = "standard output" if out == "-" else out
    n_bad = counts.pop("not_converged")
    flagged = ", ".join(f"{c} {name}" for name, c in counts.items() if c)  # (the vortex ring's rows unsaid before)
    click.echo(f"wrote {n} point{'s' if n != 1 else ''} to {where} (params {label}; air {air_label(air)})"
               + (f"; {n_bad} did not converge (see {column})" if n_bad else "")
               + (f"; flagged: {flagged} (column {column}, docs/cli.md)" if flagged else ""), err=True)


def _echo_point(propeller, params, air, label: str, r, result: dict, ratio: dict, rpm, airspeed, incidence_deg,
                collective_deg, set_deg) -> None:
    """loads' printed report of one operating point: the point, the loads, the coefficients, the
    working state in descent and the flags with their meanings."""
    total_deg = set_deg + collective_deg
    click.echo(f"{propeller.name} at {rpm:g} rpm, V = {airspeed:g} m/s, incidence {incidence_deg:g} deg"
               + (f", collective {total_deg:g} deg" if total_deg else "")
               + (f" ({set_deg:g} of the parameter set + {collective_deg:g})" if set_deg and collective_deg else "")
               + f" (params {label})")
    click.echo(f"  {propeller.n_blades} blades, D = {propeller.diameter:.4g} m, {geometry_label(propeller)}; air: "
               f"{air_label(air)}")
    click.echo(f"  thrust T = {fixed(result['thrust'], 4)} N    drag D = {fixed(result['drag'], 4)} N")
    click.echo(f"  torque Q = {fixed(result['torque'], 5)} N m  power P = {fixed(result['power'], 2)} W")
    click.echo(f"  rolling moment M_R = {fixed(result['rolling_moment'], 5)} N m")
    if "side_force" in result:
        click.echo(f"  side force Y = {fixed(result['side_force'], 4)} N  pitching moment M_P = "
                   f"{fixed(result['pitching_moment'], 5)} N m  ({', '.join(params.side_load_sources())})")
    click.echo(f"  CT = {fixed(result['CT'], 4)}  CQ = {fixed(result['CQ'], 5)}  CP = {fixed(result['CP'], 4)}")
    if ratio["v_i_over_v_h"] is not None:
        click.echo(f"  state: {result['state']}  (v_i/v_h = {ratio['v_i_over_v_h']:.3f}, "
                   f"lambda2 = V_descent/v_h = {round(ratio['lambda2'], 3) + 0.0:.3f})")  # no "-0.000"
    else:
        click.echo(f"  state: {result['state']}  (T <= 0: no hover induced velocity to refer to)")
    click.echo(f"  flags: {', '.join(r.flags()) or 'none'}")
    for f in r.flags():
        click.echo(f"    {f}: {FLAG_MEANINGS[f]}")


def check_collective(collective_deg):
    """The --collective-deg value (0 when not given); InputError outside its range."""
    if collective_deg is None:
        return 0.0
    if not (math.isfinite(collective_deg) and abs(collective_deg) <= COLLECTIVE_DEG_MAX):
        raise InputError(f"--collective-deg must be finite and in [-{COLLECTIVE_DEG_MAX:g}, {COLLECTIVE_DEG_MAX:g}] "
                         f"deg, got {collective_deg!r}")
    return float(collective_deg)


#: a points file's rotation rate below which a misread is suspected [rpm]
SLOW_RPM = 100.0


def _scan(prop, path: Path, offset_deg: float = 0.0) -> tuple[int, tuple[float, float, float], tuple[float, float],
                                                              float, tuple[float, float] | None]:
    """(points, extremes, rpm range, largest airspeed, the collective column's range [deg] or None) of a points
    file, every value checked (InputError on the first bad one)."""
    import numpy as np

    from ..identify.load_data import STATIC_AIRSPEED, radians_hint

    n, ext, lo, hi, v_max = 0, (0.0, 0.0, 0.0), math.inf, 0.0, 0.0
    collectives = None
    seen = []  # each chunk's largest incidence at airspeed and one that is not a whole degree: the radians check
    bare = False  # the incidence under its bare name incidence_deg (taken first), no unit stated in the header
    skipped = []  # the lines of empty rows among the data (blank, or cells all empty: a spreadsheet's cleared row)
    for df, _, values in _chunks(path, CHUNK, offset_deg, skipped):
        bare = any(str(c).strip().lower() == "incidence_deg" for c in df.columns)
        e = envelope_extremes(prop, *(values[c] for c in INPUT_COLUMNS))  # the collective does not change them
        ext = tuple(max(a, b) for a, b in zip(ext, e))
        lo, hi = min(lo, float(values["rpm"].min())), max(hi, float(values["rpm"].max()))
        v_max = max(v_max, float(values["airspeed"].max()))
        if COLLECTIVE_COLUMN in values:
            c_lo, c_hi = float(values[COLLECTIVE_COLUMN].min()), float(values[COLLECTIVE_COLUMN].max())
            collectives = (c_lo, c_hi) if collectives is None else (min(collectives[0], c_lo),
                                                                     max(collectives[1], c_hi))
        n += len(df)
        inc = values["incidence_deg"][values["airspeed"] > STATIC_AIRSPEED]
        if inc.size:  # (and the one farthest from a whole degree read as radians)
            far = np.abs(np.degrees(inc) - np.round(np.degrees(inc)))
            seen += [inc.max(), *inc[np.abs(inc - np.round(inc)) > 1e-6][:1], inc[int(np.argmax(far))]]
    # a unit stated in the header is believed (incidence (deg), Incidence (°)); the bare incidence_deg is checked
    hint = radians_hint(seen, np.full(len(seen), np.inf)) if bare else None
    # (said at once, before the work and its closing line: they came after it, a points-file audit, 2026-12-01)
    if hint:
        warn(f"--points: {path}: {hint}")
    if lo < SLOW_RPM:  # (a ';' file's 5.000 for 5000 read as 5 rpm, an input fuzzing audit: Re of about 40)
        warn(f"--points: {path}: rpm as low as {lo:g}, below {SLOW_RPM:g} rpm: a thousands separator read as a "
             "decimal point ('5.000' for 5000), or rev/s? (a propeller there makes almost no thrust)")
    # (rows of empty cells, ',,,', were dropped without a word, the output's rows then not the input's; those after the
    # last data row, a file's trailing blank lines, shift none and are not said: a review)
    if skipped:
        warn(f"--points: {path}: {len(skipped)} empty row(s) skipped among the data (blank, or every cell empty; the "
             f"first at line {skipped[0]}): the output has no row for them")
    return n, ext, (lo, hi), v_max, collectives
