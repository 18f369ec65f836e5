"""``propmap validate``: the model against bundled measurements, one propeller or the whole catalogue."""

from __future__ import annotations

import click

from ._common import (PARAMS_HELP, InputError, PathArg, check_out_dir, check_outputs, echo_json, load_params,
                      parse_names, resolve_air, with_air_options)
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


@click.command("validate")
@click.argument("prop", required=False)
@click.option("--all", "all_props", is_flag=True,
              help="Cross-validate every catalogue propeller with measurements (about 1 minute on 2 cores).")
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP + " Single propeller only.")
@click.option("--protocols", default=None,
              help=f"With --all: comma-separated subset of {', '.join(PROTOCOLS)} (default: all).")
@click.option("--props", "only", default=None, help="With --all: comma-separated catalogue names to restrict to.")
@click.option("--out-dir", type=PathArg(), default=None,
              help="With --all: folder for the tables (CSV, JSON) and figures (default: none written).")
@click.option("--json", "as_json", is_flag=True, help="Print the errors as JSON.")
@click.option("--figure", type=PathArg(), default=None,
              help="Single propeller: figure (.png, .pdf or .svg) of the model against the measurements "
                   "(default: none written).")
@with_air_options
def validate(prop, all_props, params_spec, protocols, only, out_dir, as_json, figure, air_choice):
    """The model against bundled measurements.

    PROP: the model and the hover model against that catalogue propeller's UIUC static
    and J-sweep data. --all: held-out errors of every calibration protocol over the
    catalogue, and the published cases (APC 10x7E, DJI 9443, Beaver propeller at
    incidence, four catalogue propellers in oblique flow).
    """
    if all_props:
        if prop:
            raise InputError("give PROP or --all, not both")
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
            check_out_dir("--out-dir", out_dir, OUTPUT_FILES)
        run_all(list(protocols), list(only), out_dir, as_json)
        return
    if not prop:
        raise InputError("give PROP (a catalogue propeller) or --all")
    for option, value in (("--protocols", protocols is not None),
                          ("--props", only is not None), ("--out-dir", out_dir is not None)):
        if value:
            raise InputError(f"{option} applies to --all")
    if figure is not None:
        if figure.suffix.lower() not in (".png", ".pdf", ".svg"):
            raise InputError(f"--figure: {figure}: give a .png, .pdf or .svg file name (the format follows it)")
        check_outputs([("--figure", figure)], [params_spec])
    from ..core.solver import SolverError
    from ..io.catalogue import get_entry, load_propeller
    from ..validation import validate as run_validation

    try:
        entry = get_entry(prop)
    except KeyError as exc:
        raise InputError(f"PROP: {exc.args[0]} (validate needs a catalogue propeller with measurements)") from None
    params, air, label = load_params(params_spec, prop)
    air = resolve_air(air, air_choice)
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
    if as_json:
        echo_json({**v.to_dict(), "params_label": label, "figure": None if fig is None else str(fig)})
    else:
        click.echo(f"{prop}, params {label}")
        print_table(v)
        if fig is not None:
            click.echo(f"figure: {fig}")
