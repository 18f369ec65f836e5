"""``propmap validate``: the model against a catalogue propeller's bundled measurements."""

from __future__ import annotations

from pathlib import Path

import click

from ..core.solver import SolverError
from ..io.catalogue import get_entry, load_propeller
from ..validation import validate as run_validation
from ._common import InputError, echo_json, load_params


def print_table(v) -> None:
    """Print the per-run CT/CP RMSE table of a Validation, model beside hover model."""
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
@click.argument("prop")
@click.option("--params", "params_spec", default="gill2017-apc", show_default=True,
              help="Preset or parameter TOML file.")
@click.option("--json", "as_json", is_flag=True, help="Print the errors as JSON.")
@click.option("--figure", type=click.Path(path_type=Path), default=None,
              help="PNG to write (default ./<PROP>_validation.png).")
def validate(prop, params_spec, as_json, figure):
    """Model and hover model against PROP's bundled UIUC static and J-sweep data."""
    try:
        entry = get_entry(prop)
    except KeyError as exc:
        raise InputError(f"PROP: {exc.args[0]} (validate needs a catalogue propeller with measurements)") from None
    params, air = load_params(params_spec)
    try:
        v = run_validation(entry, load_propeller(prop), params, air=air)
    except ValueError as exc:
        raise InputError(f"PROP: {exc}") from None
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    from ..plots import plot_validation

    fig = plot_validation(v, figure or Path(f"{prop}_validation.png"),
                          title=f"{prop}, params {params_spec}: model vs measured")
    if as_json:
        echo_json({**v.to_dict(), "figure": str(fig)})
    else:
        print_table(v)
        click.echo(f"figure: {fig}")
