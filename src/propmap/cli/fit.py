"""``propmap fit``: identify section parameters from level-flight data or load measurements."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, replace
from pathlib import Path

import click

from ..core.units import RPM
from ._air import resolve_air, with_air_options
from ._common import (Command, InputError, PathArg, _short, check_section_match, load_params, one_line,
                       option_group, parse_names, run_warnings, warn, with_prop_options)
from ._coverage import j_max
from ._load_comparison import _catalogue_comparison, _file_comparison
from ._paths import check_outputs, vehicle_inputs
from ._sources import MIN_FIT_POINTS, catalogue_citation, data_digest, file_air, file_digests, read_sources

#: the fit warnings printed (the report has them all)
MAX_WARNINGS = 3

output_options = [
    click.option("--out", type=PathArg(file=True), required=True, help="Parameter TOML to write."),
    click.option("--json", "as_json", is_flag=True, help="Print the JSON report instead of the text report."),
]
fit_options = [
    click.option("--M", "M", type=float, default=None,
                 help="Stall-blend sharpness used while fitting (default: that of --base; the paper's model at "
                      "M = 50 is fitted at M = 30 first and continued to 50); in (0, 1e6] 1/rad for the paper's "
                      "model, (0, 1000] for the cambered one."),
    click.option("--lift-model", type=click.Choice(["sigmoid", "sincos"]), default=None,
                 help="Paper's model only: eq 3 (sigmoid, the default), or footnote 1's C_L = c_l sin a cos a "
                      "(sincos; fits cl2, cd only)."),
    click.option("--fit-params", "fit_params", default=None,
                 help="Comma-separated parameters to fit (default: cl1,cl2,cd,alpha0 for the paper's model; for the "
                      "cambered one chosen by the data, docs/identification.md)."),
    click.option("--multistart", type=int, default=0, show_default=True,
                 help="Extra Sobol starts (global stage), in [0, 256]."),
    click.option("--no-prior", "no_prior", is_flag=True,
                 help="Cambered model: fit without the catalogue population prior (docs/identification.md)."),
]


@dataclass(frozen=True)
class FitChoice:
    """The fitting options every fit command shares: --M [1/rad], --lift-model, --fit-params,
    --multistart, --no-prior (checked by :func:`_options`)."""

    M: float | None = None
    lift_model: str | None = None
    fit_params: str | None = None
    multistart: int = 0
    no_prior: bool = False


def with_fit_options(f):
    """Decorate a fit command with the options shared by every fit: --out and --json (as
    themselves) and the fitting options (as ``fit_choice``, a FitChoice)."""
    f = option_group("fit_choice", FitChoice, fit_options)(f)
    for opt in reversed(output_options):
        f = opt(f)
    return f


#: the largest stall-blend sharpness accepted (as in parameter files) [1/rad]
M_MAX = 1e6
#: the most extra starts (each costs about one local fit)
MULTISTART_MAX = 256


def _options(choice: FitChoice, base=None, base_label="", extra_names=()):
    """FitOptions from the options, checked against the model of ``base`` when given
    (before any work).

    Raises
    ------
    InputError
        --M or --multistart out of range; --fit-params empty or repeated; with ``base``:
        --lift-model with the cambered model, --no-prior with the paper's (options that
        would be ignored), --fit-params naming parameters the model does not have.
    """
    from ..core.airfoil import CamberedParams
    from ..identify import FitOptions
    from ..identify.options import _check_names

    M, lift_model, multistart, no_prior = choice.M, choice.lift_model, choice.multistart, choice.no_prior
    if M is not None and not (math.isfinite(M) and 0 < M <= M_MAX):
        raise InputError(f"--M must be finite and in (0, {M_MAX:g}] 1/rad, got {M!r}")
    if not 0 <= multistart <= MULTISTART_MAX:
        raise InputError(f"--multistart must be in [0, {MULTISTART_MAX}] (each start is a whole fit), "
                         f"got {multistart}")
    cambered = isinstance(base, CamberedParams)
    top = CamberedParams.RANGES["M"][1]
    if base is not None and cambered and M is not None and M > top:  # (the cambered set's own range: a CLI audit)
        raise InputError(f"--M must be in (0, {top:g}] 1/rad for the cambered model (--base "
                         f"{_short(base_label, 40)}), got {M!r}")
    if base is not None and cambered and lift_model is not None:
        raise InputError(f"--lift-model applies to the paper's model; --base {_short(base_label, 40)} is the cambered "
                         "model (give a Table I set, e.g. --base gill2017-apc)")
    if base is not None and no_prior and not cambered:
        raise InputError(f"--no-prior applies to the cambered model (its population prior); --base "
                         f"{_short(base_label, 40)} is the paper's model, fitted without one")
    names = parse_names("--fit-params", choice.fit_params, what="parameter name")
    options = FitOptions(M=M, lift_model=lift_model or "sigmoid", multistart=multistart, progress=True, names=names,
                         prior=not no_prior)
    if names is not None and base is not None:
        try:
            _check_names(names, base, options, extra=extra_names)
        except ValueError as exc:
            raise InputError(f"--fit-params: {exc}") from None
    return options


def _out_files(out: Path) -> list:
    """(option, path) of every file a fit writes: the parameters and, beside them, reports and figure
    (matplotlib checked here, before the fit: ``plots.require_matplotlib``).
    A parameter file's name ends in .toml (``--out f.report.json`` wrote TOML over another fit's
    report: a user-level audit; the commands tell a parameter file by that suffix)."""
    from ..io.inputs import short_path
    from ..plots import require_matplotlib

    require_matplotlib()  # (the figure comes last: an unusable matplotlib is said before any work, stop 102)
    if Path(out).suffix.lower() != ".toml":
        raise InputError("--out: a parameter file is TOML: give a name ending in .toml, got "
                         f"{short_path(out, quote=True)}")
    stem = Path(out).with_suffix("")
    return [("--out", Path(out))] + [("--out (report/figure beside it)", stem.with_name(stem.name + s))
                                     for s in (".report.json", ".report.txt", ".png")]


def _coverage(data, prop, air) -> dict:
    """What load data cover, for the written file's [coverage] table: their advance ratios,
    incidences, rates and airspeeds, the propeller they are of, their chord Reynolds numbers at
    0.75 R in the fit's air (what a run in other air or on another size is checked against), and
    a collective sweep's range of collectives."""
    import numpy as np

    from ..io.calibration import propeller_coverage

    n = data.omega / (2 * math.pi)
    # (the largest climb advance ratio; 0 for data all in descent, whose V cos(incidence) is negative)
    return {"J_max": j_max(data.airspeed * np.cos(data.incidence), n, prop.diameter),
            "incidence_deg_max": float(np.degrees(np.max(data.incidence))),
            "rpm_min": float(np.min(data.omega) / RPM), "rpm_max": float(np.max(data.omega) / RPM),
            "airspeed_max": float(np.max(data.airspeed)),
            **propeller_coverage(prop, float(data.omega.min()), float(data.omega.max()), air),
            **({} if data.collective is None else {"collective_deg_min": float(np.degrees(np.min(data.collective))),
                                                   "collective_deg_max": float(np.degrees(np.max(data.collective)))})}


def fitted_coverage(train, prop, air, sources, label: str, held) -> dict:
    """A load fit's [coverage] table (:func:`_coverage`), with the data fitted (``label``, by
    content: the SHA-256 of ``sources``, each file's) and the runs or groups it saw and held out,
    so that ``validate`` can say which of its rows are in-sample: ``fit loads`` and ``demo`` write
    it (the demo's file lacked the last until 2026-12-01, a user-level audit)."""
    files = file_digests(sources)  # (each file read once for both digests)
    return {**_coverage(train, prop, air), "data": label, "data_sha256": data_digest(sources, files),
            "files_sha256": files, "groups": [str(g) for g in dict.fromkeys(train.group)],
            "held_out": [str(h) for h in held]}


def _vehicle_propeller(veh, omega_min: float, omega_max: float, air) -> dict:
    """:func:`propmap.io.calibration.propeller_coverage` of a vehicle's propeller where every
    rotor carries one geometry; {} where the rotors differ (a flight fit's file ran an 8 in
    propeller unwarned: a user-level audit, 2026-11-26)."""
    from ..io.calibration import propeller_coverage

    prop = veh.rotors[0].propeller
    if not all(r.propeller.same_geometry(prop) for r in veh.rotors):
        return {}
    return propeller_coverage(prop, omega_min, omega_max, air)


def _write_outputs(result, out: Path, base_label: str, as_json: bool, extra_text: str = "", figure=None,
                   body=None, coverage=None, header: str = "", figure_suffixes=(".png",), data_warnings=()) -> dict:
    """Write the parameter file and its reports, and print the report. ``data_warnings``: what
    reading and checking the data warned of (already printed as they arose), kept in both
    reports (``data_warnings`` in the JSON; they were on standard error only: a user-level audit)."""
    from ..io.atomic import atomic_write
    from ..io.params_file import write_params

    from .. import __version__
    from ..io.provenance import source_digest

    report = {**result.to_dict(), "base": base_label, "params_file": str(out), "coverage": coverage,
              "data_warnings": list(data_warnings), "propmap_version": __version__,  # (as maps and exports record it)
              "propmap_source_sha256": source_digest()}
    write_params(out, result.params, result.air, body=body, coverage=coverage,
                 comment=f"fitted by propmap {__version__} fit ({report.get('kind')}); source sha256 "
                         f"{report['propmap_source_sha256']}")
    stem = out.with_suffix("")
    if figure is not None:  # after the parameters: a stopped run leaves no figure without them
        # (a figure function may return the suffixes it wrote, a tuple, where one of them had nothing to draw)
        written = figure(stem.with_name(stem.name + ".png"))
        figure_suffixes = written if isinstance(written, tuple) else figure_suffixes
    # every warning the run says, as every command's --json gives them: the run's so far (the data's and the figures'
    # among them: the figures are drawn first since 2026-12-02), then the fit's own, which are said after the report
    # (they alone were the report's warnings until 2026-12-02)
    so_far = run_warnings()
    report["warnings"] = list(dict.fromkeys(so_far + [one_line(w) for w in result.warnings]))
    with atomic_write(stem.with_name(stem.name + ".report.json")) as fh:
        json.dump(report, fh, indent=2, default=float)
    said = [f"DATA WARNING: {w}" for w in data_warnings]
    head, tail = (header + "\n" if header else ""), ("\n" + extra_text if extra_text else "")
    text = head + result.report_text() + tail + "".join("\n" + line for line in said)
    with atomic_write(stem.with_name(stem.name + ".report.txt")) as fh:
        fh.write(text + "\n")
    # the fit's warnings go to standard error, once (the first MAX_WARNINGS, and how many more): the report on
    # standard output leaves them all out (report.txt keeps them), and the data's, said as they arose. It is the
    # report of the result without its warnings, not report.txt's lines less those whose text matched a warning's
    # (which dropped an identifiability warning or another line that read the same, and kept the second line of a
    # warning written over two; until 2026-12-01)
    shown = head + replace(result, warnings=()).report_text() + tail
    click.echo(json.dumps(report, indent=2, default=float) if as_json else "\n".join(shown.splitlines()))
    for w in result.warnings[:MAX_WARNINGS]:
        click.echo(f"propmap: warning: {w}", err=True)
    if len(result.warnings) > MAX_WARNINGS:
        click.echo(f"propmap: warning: {len(result.warnings) - MAX_WARNINGS} more in {stem.name}.report.txt", err=True)
    figures = "".join(f", {stem.name}{suffix}" for suffix in figure_suffixes)
    click.echo(f"wrote {out} and beside it {stem.name}.report.json, {stem.name}.report.txt{figures}", err=True)
    return report


def _run_fit(fn, *args, **kwargs):
    from ..core.solver import SolverError

    try:
        return fn(*args, **kwargs)
    except ValueError as exc:
        raise InputError(str(exc)) from None
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None


@click.group("fit")
def fit() -> None:
    """Identify section parameters from flight data or load measurements (paper Sec. III)."""


@fit.command("level-flight", cls=Command)
@click.argument("data", type=PathArg())
@click.option("--vehicle", type=PathArg(text=True), required=True, help="Vehicle TOML.")
@click.option("--body-lift", is_flag=True,
              help="Append the body-lift term of Sec. III-A and report whether it matters.")
@click.option("--base", "base_spec", default="gill2017-apc", show_default=True,
              help="The model and the constants not fitted: the paper's Table I sets (fit from the paper's x0), "
                   "'generic' or a parameter file (cambered: fit from it).")
@with_fit_options
@with_air_options
def level_flight(data, vehicle, body_lift, base_spec, out, as_json, fit_choice, air_choice):
    """Fit to steady level-flight conditions (eqs 16-18): DATA.csv with airspeed, pitch_deg, rpm_1..rpm_n."""
    import numpy as np

    from ..identify import DataError, fit_level_flight, level_flight_forces, read_level_flight
    from ..identify.level_flight import level_flight_warnings
    from ..identify.level_flight_fit import hover_vertical_force
    from ..plots_flight import plot_level_flight_fit
    from ._vehicle import _one_set, _vehicle

    check_outputs(_out_files(out), [data, vehicle, base_spec])
    veh = _vehicle(vehicle)
    # the vehicle's propellers may be geometry files (relative to the vehicle file): inputs too
    check_outputs(_out_files(out), vehicle_inputs(vehicle))
    veh = _one_set(veh, "fit level-flight fits one set for every rotor")
    try:
        d = read_level_flight(data, veh)
    except DataError as exc:
        raise InputError(f"DATA: {exc}") from None
    for w in level_flight_warnings(d, veh):
        warn(f"DATA: {w}")
    base, air, base_label = load_params(base_spec, option="--base")
    air = resolve_air(air, air_choice)
    opts = replace(_options(fit_choice, base, base_label), body_lift=body_lift)
    res = _run_fit(fit_level_flight, d, veh, base=base, air=air, options=opts)
    forces = level_flight_forces(res.params, d, veh, air=air)
    hover = hover_vertical_force(res.params, d, veh, air=air)
    rms_model = np.sqrt(np.mean((forces['vertical'] - veh.weight) ** 2))
    n = d.omega / (2 * math.pi)  # (N, n_rotors); what the data cover, as a load fit's and a flight fit's files record
    V_axial = d.airspeed[:, None] * np.cos(forces["beta"])
    D = np.array([r.propeller.diameter for r in veh.rotors])[None, :]
    moving = d.airspeed > 0.3  # (a hover row's incidence names no flow)
    coverage = {"J_max": j_max(V_axial, n, D),
                "incidence_deg_max": float(np.degrees(np.max(forces["beta"][moving]))) if moving.any() else 0.0,
                "rpm_min": float(np.min(d.omega) / RPM), "rpm_max": float(np.max(d.omega) / RPM),
                "airspeed_max": float(np.max(d.airspeed)),
                **_vehicle_propeller(veh, float(np.min(d.omega)), float(np.max(d.omega)), air),
                "data": Path(data).name, "files_sha256": file_digests([data])}
    coverage["data_sha256"] = data_digest([data], coverage["files_sha256"])
    extra = (f"vertical-force error rms (without the body lift): model {rms_model:.4f} N, "
             f"hover model {np.sqrt(np.mean((hover - veh.weight) ** 2)):.4f} N (weight {veh.weight:.3f} N)")
    if body_lift:
        bl = res.extra["body_lift"]
        extra += (f"\nbody lift: max {bl['max_abs_N']:.4f} N ({100 * bl['max_abs_over_weight']:.2f}% of weight); "
                  f"rms residual {bl['rms_residual_with']:.4f} N with, {bl['rms_residual_without']:.4f} N without; "
                  f"F-test p = {bl['p_value']:.3g}: "
                  + ("it matters (p < 0.05): the parameters written are those fitted with body lift"
                     if bl["matters"] else "not significant (p >= 0.05): the parameters written are those fitted "
                                           "without body lift"))
    _write_outputs(res, out, base_label, as_json, extra, coverage=coverage, figure=lambda png: plot_level_flight_fit(
        d, forces, hover, veh.weight, png, title=f"level-flight fit of {data.name}: BET+BEMT (fitted) vs hover model"))


@fit.command("loads", cls=Command)
@click.argument("sources", metavar="SOURCE...", nargs=-1, required=True)
@click.option("--holdout", default=None, help="Comma-separated run ids (catalogue, UIUC files) or group labels (CSV) "
                                              "to hold out (default: none).")
@click.option("--quantities", default=None, help="Comma-separated subset of thrust,drag,torque,rolling_moment to fit "
                                                 "(default: all measured).")
@click.option("--prop", "prop_spec", default=None,
              help="Propeller (catalogue name, geometry file, or a size 9x4.5 in inches: a nominal blade) of file "
                   "SOURCEs.")
@with_prop_options
@click.option("--base", "base_spec", default=None,
              help="The model, start and constants not fitted: default 'generic' (cambered, fitted to the "
                   "catalogue); a parameter file, 'calibrated:NAME', or a Table I set for the paper's model.")
@click.option("--rpm-source", type=click.Choice(["optical", "electrical"]), default=None,
              help="A thrust-stand export's speed column (default: the optical one where present).")
@click.option("--pole-pairs", type=int, default=None,
              help="Divide a stand's electrical speed by the motor's pole pairs (raw electrical rpm), in [1, 50].")
@click.option("--skip-sanity-check", is_flag=True,
              help="Fit data whose loads are more than 3x off the generic model's (refused by default: units?).")
@click.option("--directions", type=click.IntRange(0, 8), default=None,
              help="Cambered model under the prior: how many parameter directions to free, those the data "
                   "determine best against the prior (0: every parameter; default: 3 for a static run, those the "
                   "data know 10x better than the prior for sweeps at one rate, 0 for sweeps at more).")
@click.option("--jackknife", is_flag=True,
              help="Refit leaving each fitted run out (3 runs or more) and report the spread between runs as the "
                   "parameters' jackknife std error beside the linearised one.")
@with_fit_options
@with_air_options
def loads(sources, holdout, quantities, prop_spec, prop_choice, base_spec, rpm_source, pole_pairs,
          skip_sanity_check, directions, jackknife, out, as_json, fit_choice, air_choice):
    """Fit to load measurements of one propeller.

    SOURCE: a catalogue propeller (its bundled UIUC data); or, with --prop, one CSV with
    rpm and any of thrust, drag, torque (and, beside a torque, the hub's rolling moment), with
    or without units in the names (thrust_kgf,
    Thrust (gf), torque_Nmm; airspeed, incidence_deg and collective_deg optional: a static
    thrust stand, or a rotor's hover collective sweep; optional group), an RCbenchmark /
    Tyto thrust-stand export as written, or UIUC-format static and wind-tunnel files. A fit
    needs 6 distinct operating points at least (`propmap validate` compares any number).
    """
    import numpy as np

    from ..identify import fit_loads
    from ..identify.load_data import LOAD_KEYS

    check_outputs(_out_files(out), [*sources, prop_spec, base_spec])
    base, air, base_label = load_params("generic" if base_spec is None else base_spec, option="--base")
    air = resolve_air(air, air_choice)
    data, prop, entry, label, data_warnings = _read_loads_sources(sources, prop_spec, prop_choice, air, rpm_source,
                                                                  pole_pairs)
    air = file_air(data, air, air_choice)
    check_section_match(prop, base_label)
    qty = parse_names("--quantities", quantities, valid=LOAD_KEYS, what="quantity")
    missing = [q for q in (qty or ()) if q not in data.measured]
    if missing:
        raise InputError(f"--quantities: {missing[0]!r} is not measured in SOURCE (measured: "
                         f"{', '.join(data.measured)})")
    if entry is None:
        data_warnings += _sanity_warnings(data, prop, air, qty, pole_pairs, skip_sanity_check)
    held, population, base, base_label = _held_runs(holdout, data, entry, base_spec, base, base_label)
    train = data.subset(~np.isin(data.group, held))
    asked = parse_names("--fit-params", fit_choice.fit_params, what="parameter name") or ()
    if "flap_compliance" in asked and not train.inplane.any():
        # (asked of axial data, the compliance stayed at its start, 1 rad/(N m), written as fitted and flapping the
        # set's blades wherever it ran at incidence: a user-level audit, 2026-12-01; a jackknife's fold without the
        # run at incidence keeps it as the full fit frees it)
        raise InputError("--fit-params: flap_compliance cannot be fitted to these data: no point has an in-plane "
                         "airspeed (V |sin beta| above 0.3 m/s), where the blades flap; in axial flow no load "
                         "depends on it")
    if directions:
        _check_directions(base, base_label, fit_choice)
    options = replace(_options(fit_choice, base, base_label),
                      population=population, directions=directions)
    if jackknife:
        _check_jackknife(train)
    res = _run_fit(fit_loads, train, prop, base=base, air=air, quantities=qty, options=options)
    if jackknife:
        from ..identify.jackknife import jackknife_loads

        _run_fit(jackknife_loads, res, train, prop, base=base, air=air, quantities=qty, options=options)
    if entry is not None:
        extra, figure = _catalogue_comparison(res, entry, prop, base, base_label, held, air, label)
    else:
        extra, figure = _file_comparison(res, data, prop, base, base_label, held, air, label)
    coverage = fitted_coverage(train, prop, air, sources, label, held)
    cited = entry.citation if entry is not None else catalogue_citation(prop_spec, geometry_only=True)
    if cited:  # (the catalogue's data, or the catalogue geometry under a user's data: cited in the reports)
        res.extra["data_citation"] = cited
    _write_outputs(res, out, base_label, as_json, extra, figure=figure, coverage=coverage,
                   header=f"{prop.name}: {prop.n_blades} blades, D = {prop.diameter:.4g} m; air rho "
                          f"{air.rho:.4g} kg/m^3" + (f"\nData: {cited}" if cited else ""),
                   data_warnings=data_warnings)


def _read_loads_sources(sources, prop_spec, prop_choice, air, rpm_source, pole_pairs):
    """fit loads' reading of SOURCE: (data, propeller, catalogue entry or None, label, the data's
    warnings). The reader's notes and warnings are said now, before the fit, and the warnings kept
    for the reports; a library's own warnings go the usual way, under the command's filters."""
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        data, prop, entry, label = read_sources(sources, prop_spec, prop_choice, air, rpm_source, pole_pairs)
    data_warnings = list(dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, UserWarning)))
    for w in caught:
        if not issubclass(w.category, UserWarning):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    for note in data.notes:
        click.echo(f"propmap: note: {note}", err=True)
    for w in data_warnings:
        warn(w)
    return data, prop, entry, label, data_warnings


def _sanity_warnings(data, prop, air, qty, pole_pairs, skip_sanity_check: bool) -> list[str]:
    """The sanity check of a user's load data (identify/sanity.py), each warning said as it comes
    and returned for the reports; a refusal is an InputError, or with --skip-sanity-check a
    warning."""
    from ..identify.data import DataError
    from ..identify.sanity import sanity_check

    said = []
    try:
        for w in sanity_check(data, prop, air=air, quantities=qty, pole_pairs=pole_pairs):
            warn(w)
            said.append(w)
    except DataError as exc:
        if not skip_sanity_check:
            raise InputError(f"SOURCE: {exc} (--skip-sanity-check fits it anyway)") from None
        warn(str(exc))
        said.append(str(exc))
    return said


def _held_runs(holdout, data, entry, base_spec, base, base_label: str):
    """--holdout's runs, checked against the data's: (the held-out runs, the population prior
    and the base set and its label to fit with). Judging held-out runs of a catalogue propeller,
    the generic set and the prior come from the catalogue without the propeller's family, which
    never saw them."""
    held = parse_names("--holdout", holdout, what="run") or ()
    population = None
    if entry is not None and held:
        from ..io.calibration import generic_without
        from ..io.calibration import population as population_without

        population = population_without(without=entry.name)
        if base_spec is None:
            base, base_label = generic_without(entry.name)
    groups = set(data.group)
    held = tuple(_run_of(h, groups) for h in held)
    unknown = [h for h in held if h not in groups]
    if unknown:
        raise InputError(f"--holdout: unknown run(s) {', '.join(unknown)}; available: {', '.join(sorted(groups))}")
    if entry is not None and any(h.startswith("static") for h in held):
        raise InputError("--holdout: the static run calibrates the hover model and cannot be held out")
    if held and groups <= set(held):
        raise InputError(f"--holdout: every run of SOURCE is held out ({', '.join(sorted(groups))}); keep at least one "
                         "to fit")
    if held:  # (the readers' minimum, for the runs left to fit: 3 points were fitted, a user-level audit, 2026-12-01)
        import numpy as np

        kept = ~np.isin(data.group, held)
        columns = (data.omega, data.airspeed, data.incidence) + (() if data.collective is None else (data.collective,))
        points = np.column_stack([a[kept] for a in columns])
        distinct = int(np.unique(points, axis=0).shape[0])
        if distinct < MIN_FIT_POINTS:
            raise InputError(f"--holdout: the runs left to fit ({', '.join(sorted(groups - set(held)))}) hold "
                             f"{distinct} distinct operating point(s); a fit needs at least {MIN_FIT_POINTS}")
    return held, population, base, base_label


def _run_of(name: str, groups: set) -> str:
    """The run of ``groups`` that --holdout's ``name`` means: itself, else the one run equal to it
    in any case or as a static run's id (``0702rd`` for files named ``..._0702RD_...``; ``0350rd``
    for ``static_0350rd``: both refused until 2026-11-30, a UIUC file audit); else ``name``."""
    if name in groups:
        return name
    for want in (name.casefold(), f"static_{name}".casefold()):
        found = [g for g in groups if str(g).casefold() == want]
        if len(found) == 1:
            return found[0]
    return name


def _check_directions(base, base_label: str, fit_choice) -> None:
    """Refuse the options that would make --directions ignored (refused, not warned about)."""
    from ..core.airfoil import CamberedParams

    if not isinstance(base, CamberedParams):
        raise InputError(f"--directions applies to the cambered model; --base {base_label} is the paper's model")
    if fit_choice.no_prior:
        raise InputError("--directions frees the parameter directions the data know better than the population "
                         "prior; with --no-prior there is none: give one of them")
    if fit_choice.fit_params:
        raise InputError("--directions frees directions of the default parameters; --fit-params chooses the "
                         "parameters instead: give one of them")


def _check_jackknife(train) -> None:
    """Refuse --jackknife before the fit where the training data have fewer than 3 runs to leave out."""
    from ..identify.jackknife import jackknife_runs

    runs = jackknife_runs(train)
    if len(runs) < 3:
        raise InputError(f"--jackknife leaves each fitted run out in turn (the sweeps where static runs are "
                         f"fitted too) and needs at least 3; SOURCE has {len(runs)} "
                         f"({', '.join(map(str, runs)) or 'none'})")
