"""``propmap validate``: the model against measurements: a catalogue propeller's bundled ones, the
whole catalogue's, or a user's own load files."""

from __future__ import annotations

import os
from pathlib import Path

import click

from ._air import air_label, air_record, resolve_air, with_air_options

from ._common import (Command, PARAMS_HELP, InputError, PathArg, _catalogue_geometry, check_section_match, echo_json,
                       load_params, parse_names, warn, with_prop_options)
from ._paths import _is_file, check_out_dir, check_outputs
from .validate_all import PROTOCOLS


def print_table(v) -> None:
    """Print the per-run CT/CP RMSE table of a Validation, model beside hover model."""
    click.echo("rms errors of the thrust and power coefficients CT, CP [-] (propeller convention, "
               "T = CT rho n^2 D^4, P = CP rho n^3 D^5)")
    click.echo(f"{'run':<24}{'n':>4}  {'CT rmse':>8}{'CP rmse':>8}  |  hover: {'CT rmse':>8}{'CP rmse':>8}")
    for r in v.runs:
        m, h = r.errors("model"), r.errors("hover_model")
        click.echo(f"{r.label:<24}{r.CT.size:>4}  {m['ct_rmse']:>8.4f}{m['cp_rmse']:>8.4f}  |  "
                   f"       {h['ct_rmse']:>8.4f}{h['cp_rmse']:>8.4f}")
    m, h = v.summary("model"), v.summary("hover_model")
    click.echo(f"{'all points':<24}{m['n_points']:>4}  {m['ct_rmse']:>8.4f}{m['cp_rmse']:>8.4f}  |  "
               f"       {h['ct_rmse']:>8.4f}{h['cp_rmse']:>8.4f}")
    click.echo(f"model bias: CT {m['ct_bias']:+.4f}, CP {m['cp_bias']:+.4f}. Data: {v.citation}")


@click.command("validate", cls=Command)
@click.argument("sources", metavar="[PROP | SOURCE...]", nargs=-1)
@click.option("--all", "all_props", is_flag=True,
              help="Cross-validate every catalogue propeller with measurements (about 2 minutes on 2 cores).")
@click.option("--prop", "prop_spec", default=None,
              help="The propeller (catalogue name, geometry file, or a size 9x4.5 in inches: a nominal blade) of "
                   "SOURCE files.")
@with_prop_options
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP + " Not with --all.")
@click.option("--rpm-source", type=click.Choice(["optical", "electrical"]), default=None,
              help="A thrust-stand export's speed column (default: the optical one where present).")
@click.option("--pole-pairs", type=int, default=None,
              help="Divide a stand's electrical speed by the motor's pole pairs (raw electrical rpm), in [1, 50].")
@click.option("--protocols", default=None,
              help=f"With --all: comma-separated subset of {', '.join(PROTOCOLS)} (default: all).")
@click.option("--props", "only", default=None, help="With --all: comma-separated catalogue names to restrict to.")
@click.option("--out-dir", type=PathArg(), default=None,
              help="With --all: folder for the tables (CSV, JSON) and figures (default: none written).")
@click.option("--json", "as_json", is_flag=True, help="Print the errors as JSON.")
@click.option("--figure", type=PathArg(file=True), default=None,
              help="A catalogue PROP: figure (.png, .pdf or .svg) of the model against the measurements (default: "
                   "none written).")
@with_air_options
def validate(sources, all_props, prop_spec, prop_choice, params_spec, rpm_source, pole_pairs, protocols, only,
             out_dir, as_json, figure, air_choice):
    """The model against measurements.

    PROP: the model and the hover model against that catalogue propeller's UIUC static
    and J-sweep data. SOURCE... with --prop: a parameter set (--params; default the
    propeller's calibrated set if it is a catalogue one, else the generic set) against your
    own load measurements, read as `fit loads` reads them (a loads CSV, a thrust-stand
    export, UIUC-format files): errors overall and per group, in coefficient form. --all:
    held-out errors of every calibration protocol over the catalogue, and the published
    cases (APC 10x7E, DJI 9443, Beaver propeller at incidence, four catalogue propellers in
    oblique flow).
    """
    from ..io.catalogue import catalogue

    prop = sources[0] if len(sources) == 1 and prop_spec is None and sources[0] in catalogue() else None
    files = bool(sources) and prop is None
    if files and len(sources) == 1 and prop_spec is None and not os.path.lexists(sources[0]):
        from ..io.catalogue import get_entry

        try:  # a misspelt catalogue name: its suggestions
            get_entry(sources[0])
        except KeyError as exc:
            raise InputError(f"PROP: {exc.args[0]} (validate needs a catalogue propeller with measurements, or "
                             "SOURCE files with --prop)") from None
    if not files:
        for option, value in (("--prop", prop_spec), ("--rpm-source", rpm_source), ("--pole-pairs", pole_pairs)):
            if value is not None:
                raise InputError(f"{option} applies to SOURCE files (give --prop with them)")
        for option, value in (("--diameter-in", prop_choice.diameter_in), ("--blades", prop_choice.blades)):
            if value is not None:
                raise InputError(f"{option} applies to SOURCE files with a geometry file as --prop")
    if all_props:
        _validate_all(sources, params_spec, air_choice, figure, protocols, only, out_dir, as_json)
        return
    if not sources:
        raise InputError("give PROP (a catalogue propeller), SOURCE files with --prop, or --all")
    for option, value in (("--protocols", protocols is not None),
                          ("--props", only is not None), ("--out-dir", out_dir is not None)):
        if value:
            raise InputError(f"{option} applies to --all")
    if files:
        if figure is not None:
            raise InputError("--figure applies to a catalogue PROP")
        _validate_files(sources, prop_spec, prop_choice, params_spec, rpm_source, pole_pairs, as_json, air_choice)
        return
    _validate_catalogue(prop, params_spec, air_choice, figure, as_json)


def _validate_all(sources, params_spec, air_choice, figure, protocols, only, out_dir, as_json) -> None:
    """validate --all: its option checks, then every calibration protocol over the catalogue and
    the published cases (validate_all.run_all)."""
    if sources:
        raise InputError("give PROP (or SOURCE files) or --all, not both")
    if params_spec is not None:
        raise InputError("--params applies to a single PROP; --all uses the shipped generic sets")
    air_given = air_choice.options_given()
    if air_given:
        raise InputError(f"{air_given[0]} applies to a single PROP; --all compares coefficients in the air the "
                         "sets were fitted in")
    from .validate_all import OUTPUT_FILES, run_all

    if figure is not None:
        raise InputError("--figure applies to a single PROP; --all writes its figures into --out-dir")
    protocols = parse_names("--protocols", protocols, valid=PROTOCOLS, what="protocol") or PROTOCOLS
    only = parse_names("--props", only, what="propeller name") or ()
    if out_dir is not None:
        from ..plots import require_matplotlib

        require_matplotlib()  # (its figures come after the whole run, stop 102)
        check_out_dir("--out-dir", out_dir, OUTPUT_FILES)
    run_all(list(protocols), list(only), out_dir, as_json)


def _validate_catalogue(prop: str, params_spec, air_choice, figure, as_json) -> None:
    """validate PROP: the model and the hover model against a catalogue propeller's UIUC static
    and J-sweep data, printed (or as JSON), with the figure where --figure names one, and what
    of the data the set was fitted to."""
    if figure is not None:
        from ..plots import FIGURE_FORMATS, require_matplotlib

        require_matplotlib()  # (the figure comes after the validation, stop 102)
        if figure.suffix.lower().lstrip(".") not in FIGURE_FORMATS:  # (plots refuses the others too, stop 104)
            raise InputError(f"--figure: {figure}: give a .png, .pdf or .svg file name (the format follows it)")
        check_outputs([("--figure", figure)], [params_spec])
    from ..core.solver import SolverError
    from ..io.catalogue import get_entry, load_propeller
    from ..validation import validate as run_validation

    try:
        entry = get_entry(prop)
    except KeyError as exc:
        raise InputError(f"PROP: {exc.args[0]} (validate needs a catalogue propeller with measurements)") from None
    params, set_air, label = load_params(params_spec, prop)
    air = resolve_air(set_air, air_choice)
    check_section_match(load_propeller(prop), label)
    try:
        v = run_validation(entry, load_propeller(prop), params, air=air)
    except ValueError as exc:
        raise InputError(f"PROP: {exc}") from None
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    fig = None
    if figure is not None:
        from ..plots import plot_validation

        fig = plot_validation(v, figure, title=f"{prop}, params {label}: model vs measured\nData: {entry.citation}")
    in_fit = _catalogue_in_fit(entry, label, params_spec, v.runs)
    if as_json:
        echo_json({**v.to_dict(), "params_label": label, "air": air_record(air), "in_fit": in_fit,
                   "figure": None if fig is None else str(fig)})
    else:
        click.echo(f"{prop}, params {label}; air {air_label(air)}")
        print_table(v)
        if in_fit:  # (the default calibrated set's residual once read as a prediction: a validation audit)
            fitted = [r for r, how in in_fit.items() if how == "fitted"]
            held = [r for r, how in in_fit.items() if how == "held out"]
            which = "these runs" if len(fitted) == len(v.runs) else "runs " + ", ".join(fitted)
            whole = " (with the whole catalogue's)" if label == "generic" else ""
            if air != set_air:  # (--altitude-m 3000 moved apce_8x6's CT rmse 0.0030 -> 0.0042, still called the
                # fit's residual: a validate audit, stop 100)
                click.echo(f"{label} was fitted to {which}{whole} in its own air ({air_label(set_air)}); compared here "
                           "in the air the options give, so these errors are neither the fit's residual nor a "
                           "prediction" + (f"; held out: {', '.join(held)}" if held else ""))
            else:
                click.echo(f"{label} was fitted to {which}{whole}: in-sample (the fit's residual, not a prediction)"
                           + (f"; held out: {', '.join(held)}" if held else "")
                           + ("; `propmap validate --all` gives held-out errors" if not held else ""))
        elif label == "generic":
            click.echo(f"generic was not fitted to {prop}'s runs (its calibration took the propellers with a static "
                       "run and sweeps): a blind prediction")
        if fig is not None:
            click.echo(f"figure: {fig}")


def _catalogue_in_fit(entry, label: str, params_spec, runs) -> dict:
    """{run label: "fitted" or "held out"} of a catalogue propeller's runs (labelled as `fit
    loads` groups them: ``static_2797rd``, ``2798rd``) that the parameter set was fitted to:
    every run for its own calibrated set and for the generic set where it was fitted to them
    (:func:`_fitted_by`), the [coverage] groups of a fit of the catalogue name or of its bundled
    files ({} for any other set)."""
    ids = [f"static_{r.run_id}" if r.kind == "static" else r.run_id for r in runs]
    if _fitted_by(label, entry.name):
        return {g: "fitted" for g in ids}
    from ..io.params_file import set_coverage

    cov = (set_coverage(label) or {}) if params_spec is not None else {}
    if not cov:
        return {}
    if cov.get("data") != entry.name and not set(cov.get("files_sha256", ())) & _bundled_digests(entry.name):
        return {}
    held, fitted = set(cov.get("held_out", ())), set(cov.get("groups", ()))
    return {g: ("held out" if g in held else "fitted") for g in ids if g in held | fitted}


def _fitted_by(label: str, name: str) -> bool:
    """Whether the shipped set ``label`` was fitted to catalogue propeller ``name``'s runs: its own
    calibrated set, or the generic set where ``name`` is among the propellers it was fitted to (the
    calibrated ones, those with a static run and sweeps: the CFNQ propellers' one static run each
    was called in-sample, a validate audit, stop 100)."""
    from ..io.calibration import calibration

    return label == f"calibrated:{name}" or (label == "generic" and name in calibration()["propellers"])


def _bundled_digests(name: str) -> set:
    """The SHA-256 of each bundled UIUC file of catalogue propeller ``name`` (none for another)."""
    from ..io.atomic import file_sha256
    from ..io.catalogue import catalogue

    entry = catalogue().get(name)
    return set() if entry is None else {file_sha256(f) for f in entry.data_paths()}


def _bundled_owner(digests) -> str | None:
    """The catalogue propeller whose bundled UIUC files include every one of ``digests`` (the
    files a user gave with a geometry of another name, an APC PE0 file, say), or None (about 1,000
    files hashed: 0.1 s)."""
    from ..io.atomic import file_sha256
    from ..io.catalogue import catalogue

    digests = set(digests)
    for name, entry in catalogue().items():
        if digests and digests <= {file_sha256(f) for f in entry.data_paths()}:
            return name
    return None


def _run_pairs(files, prop, seen: set, every: list) -> dict:
    """UIUC runs: each file a run, named by its run id, or by its stem where two files share
    one id, in a fit's read and in this one alike: {this table's label: the fit's label} of
    each run that both know."""
    from ..identify import loads_from_uiuc_files

    pairs = {}
    for f in files:
        names = {str(g) for g in loads_from_uiuc_files([f], prop.diameter).group} | {Path(f).stem}
        if names & seen and names & set(every):
            pairs[min(names & set(every))] = min(names & seen)
    return pairs


def _validate_files(sources, prop_spec, prop_choice, params_spec, rpm_source, pole_pairs, as_json, air_choice):
    """``validate SOURCE... --prop P``: a parameter set against the user's own load files."""
    from ..core.solver import SolverError
    from ..validation import load_errors
    from ._sources import file_air, read_sources

    params, set_air, label = load_params(params_spec, prop_spec, option="--params")
    air = resolve_air(set_air, air_choice)
    # (the fitted groups' errors in other air than the set's are no residual: validate PROP said so, SOURCE did not,
    # a review, stop 100)
    other_air = bool(air_choice.options_given()) and air != set_air
    data, prop, _, what = read_sources(sources, prop_spec, prop_choice, air, rpm_source, pole_pairs, min_points=1)
    for note in data.notes:
        click.echo(f"propmap: note: {note}", err=True)
    check_section_match(prop, label)
    air = file_air(data, air, air_choice, what="comparison")
    from ..identify.data import DataError
    from ..identify.sanity import sanity_check

    try:  # a unit slip looks like a bad model: said, and the comparison goes on (a fit refuses it)
        # (against the parameters given, not the generic set: their own errors follow; a user-level audit, 2026-11-29;
        # --params generic is the generic set, said as such: it is no propeller's, a fit would absorb the difference)
        given = params_spec is not None and params_spec != "generic"
        for w in sanity_check(data, prop, params=params if given else None, air=air, pole_pairs=pole_pairs):
            warn(w)
    except DataError as exc:
        warn(f"{exc} (the comparison below takes the file as written)")
    try:
        e = load_errors(data, prop, params, air=air)
    except ValueError as exc:
        raise InputError(f"SOURCE: {exc}") from None
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    in_fit, every, owner = _in_fit(label, params_spec, sources, data, prop, what)
    from ..io.catalogue import catalogue

    # (the catalogue's own UIUC files were shown without their source, which validate PROP cites: an audit, stop 100)
    citation = catalogue()[owner].citation if owner else None
    if as_json:  # (air: the record of loads, trim and validate PROP; the flat rho, mu, speed_of_sound kept as before)
        echo_json({**e, "in_fit": in_fit, "params_label": label, "propeller": prop.name, "diameter_m": prop.diameter,
                   "n_blades": prop.n_blades, "data": [str(s) for s in sources], "citation": citation,
                   "air": air_record(air), "rho": air.rho, "mu": air.mu, "speed_of_sound": air.speed_of_sound})
        return
    _print_errors(e, in_fit, every, what, prop, label, air, other_air)
    if citation:
        click.echo(f"Data: {citation}")


def _in_fit(label: str, params_spec, sources, data, prop, what: str) -> tuple[dict, list[str], str | None]:
    """validate's in-sample labels: (group -> "fitted" or "held out" for the groups the parameter
    file's fit saw, by its [coverage] table and the files' contents, or the catalogue's calibration
    did; the data's groups in order; the catalogue propeller whose bundled UIUC files these are,
    with its geometry, or None)."""
    from ..io.params_file import set_coverage
    from ._sources import data_digest, file_digests

    # which groups the parameter file's fit saw or held out (its [coverage] table), where it was fitted to this data
    cov = (set_coverage(label) or {}) if params_spec is not None else {}
    in_fit = {}
    seen = set(cov.get("held_out", ())) | set(cov.get("groups", ()))
    every = [str(g) for g in dict.fromkeys(data.group)]  # (the data's groups, one or more)
    fit_files = set(cov.get("files_sha256", ()))
    uiuc = what == "UIUC files"
    files = file_digests(sources) if cov or uiuc else []  # (each file read once, for every rule below)
    mine = dict(zip([s for s in sources if _is_file(Path(s))], files))
    bundled = _bundled_digests(prop.name) if uiuc else set()
    own = [s for s, h in mine.items() if h in bundled]  # (the catalogue's own files of this propeller, by content)
    owner = prop.name
    if uiuc and not own and mine:  # (a catalogue propeller's bundled runs with a geometry of another name, its APC
        # PE0 file: the generic set's in-sample errors read as a prediction, a vehicle-designer audit, 2026-11-28)
        owner = _bundled_owner(mine.values()) or prop.name
        # (only where the geometry given is that propeller's: another blade's errors are no residual, a review)
        own = list(mine) if owner != prop.name and _catalogue_geometry(owner, prop) is True else []
        owner = owner if own else prop.name
    if fit_files:  # (by each file's content: a part of the fit's files, or them among others, labelled too)
        matched = [s for s, h in mine.items() if h in fit_files]
        if what != "UIUC files":  # (a CSV: its groups are the fit's, where it is the fit's file)
            pairs = {g: g for g in every if g in seen} if matched else {}  # (a row's label -> the fit's label)
        else:
            pairs = _run_pairs(matched, prop, seen, every)
        in_fit = {g: ("held out" if f in cov.get("held_out", ()) else "fitted") for g, f in pairs.items()}
    elif own and cov.get("data") == owner:  # (a fit of the catalogue name: its runs are the bundled files)
        in_fit = {g: ("held out" if f in cov.get("held_out", ()) else "fitted")
                  for g, f in _run_pairs(own, prop, seen, every).items()}
    elif own and _fitted_by(label, owner):  # (the calibration saw every run of these data)
        in_fit = {g: "fitted" for g in _run_pairs(own, prop, set(every), every)}
    elif cov.get("data") == what and cov.get("data_sha256") in (None, data_digest(sources, files)):
        # (by content: another day's file of the same name once read as this fit's data; a file written before
        # 2026-11-26 has the name and the files' joint digest only)
        in_fit = {g: ("held out" if g in cov.get("held_out", ()) else "fitted") for g in every if g in seen}
    return in_fit, every, (owner if own else None)


def _inplane_words(keys) -> str:
    """The tail of the reference line naming the loads scored only where the rotor has an
    in-plane airspeed ('; the rolling moment likewise' once followed nothing where no in-plane
    force was measured, a review, 2026-12-01)."""
    from ..identify.load_data import INPLANE_WORDS

    which = [w for k, w in INPLANE_WORDS.items() if k in keys]
    return f"; {' and '.join(which)} where the rotor has an in-plane airspeed" if which else ""


def _print_errors(e: dict, in_fit: dict, every: list[str], what: str, prop, label: str, air,
                  other_air: bool = False) -> None:
    """validate's table of the coefficients' errors (all points, by group, by state), with the
    groups' in-sample labels (the fitted ones' errors no residual where ``other_air``: the air
    options gave other air than the set's) and the rms errors in SI."""
    keys = list(e["overall"])
    click.echo(f"{what} ({e['n_points']} points) against {prop.name} ({prop.n_blades} blades, D = "
               f"{prop.diameter:.4g} m), params {label}; air {air_label(air)}")
    click.echo("errors of the coefficients, model - measured (max: the largest magnitude), in % of the reference: "
               + "; ".join(f"{k}: {w} = {v:.4g}" for k, (w, v) in e["reference"].items())
               + _inplane_words(keys))
    one = every[0] if len(every) == 1 and every[0] in in_fit else None  # (one group: the all-points row is it)
    rows = ([("all points" + (f" ({in_fit[one]})" if one else ""), e["overall"])]
            + [(g + (f" ({in_fit[g]})" if g in in_fit else ""), row) for g, row in e["groups"].items()]
            + [(f"state: {s}", row) for s, row in e["states"].items()])
    width = min(max(len(name) for name, _ in rows) + 2, 60)
    wide = {k: max(13, len(k) + 6) for k in keys}  # (a blank ahead of 'rolling_moment rms' too)
    click.echo(f"{'':<{width}}" + "".join(f"{k + ' rms':>{wide[k]}}{'bias':>10}{'max':>10}{'n':>6}" for k in keys))

    def pct(v, w, sign=""):  # (a blank ahead of every number: 121.63% does not run into the next column)
        return f"{'-':>{w}}" if v is None else " " + f"{100 * v:>{sign}{w - 2}.2f}%"

    for name, row in rows:
        click.echo(f"{name[:width - 1]:<{width}}" + "".join(
            pct(row[k]["rms"], wide[k]) + pct(row[k]["bias"], 10, "+") + pct(row[k]["max"], 10) + f"{row[k]['n']:>6}"
            for k in keys))
    part = bool(in_fit) and set(in_fit) != set(every)
    if in_fit and (part or len(set(in_fit.values())) > 1):
        click.echo("the 'all points' row mixes the fit's own groups with others: read the rows by group")
    if in_fit:
        fitted = sorted(g for g, v in in_fit.items() if v == "fitted")
        residual = ("fitted in the set's own air, compared here in other air: neither the fit's residual nor a "
                    "prediction" if other_air else "in-sample (the fit's residual)")
        click.echo(f"{label} was fitted to {'part of ' if part else ''}this data: "
                   + (f"{', '.join(fitted)} {residual}, " if fitted else "")
                   + "held out: " + (", ".join(sorted(g for g, v in in_fit.items() if v == "held out")) or "none"))
    si = ", ".join(f"{k} {e['overall'][k]['rms_si']:.4g} {'N m' if k in ('torque', 'rolling_moment') else 'N'}"
                   for k in keys
                   if e["overall"][k]["rms_si"] is not None)
    click.echo(f"rms errors in SI: {si}" + (f"; the solver did not converge on {e['n_points'] - e['converged']} "
                                            "points, left out" if e["converged"] < e["n_points"] else ""))
