"""``propmap demo``: the APC 8x6E with the paper's APC parameters, on bundled real data."""

from __future__ import annotations

import math
from pathlib import Path

import click
import numpy as np

from ..core.airfoil import preset
from ..core.hover import HoverModel
from ..core.solver import rotor_loads
from ..io.atomic import atomic_write
from ..io.catalogue import get_entry, load_propeller
from ..validation import validate
from .validate import print_table

PROP = "apce_8x6"
PARAMS = "gill2017-apc"
HOLDOUT = ("2801rd", "2802rd")


def envelope_table(prop, params, rpm: float):
    """Loads over airspeed x incidence at one rpm beside the hover model (pandas DataFrame)."""
    import pandas as pd

    V = np.linspace(0.0, 20.0, 21)
    inc = np.array([0.0, 30.0, 60.0, 90.0])
    VV, BB = np.meshgrid(V, inc)
    om = rpm * 2 * math.pi / 60
    r = rotor_loads(prop, params, om, VV, np.radians(BB))
    hover = HoverModel.from_model(prop, params, om)
    return pd.DataFrame({
        "rpm": rpm, "airspeed": VV.ravel(), "incidence_deg": BB.ravel(),
        "thrust": r.thrust.ravel(), "drag": r.drag.ravel(), "torque": r.torque.ravel(),
        "thrust_hover": np.full(VV.size, float(hover.thrust(om))),
        "torque_hover": np.full(VV.size, float(hover.torque(om))),
        "flags": [";".join(r.flags(np.unravel_index(i, VV.shape))) for i in range(VV.size)],
    })


def fit_demo(prop, params, out_dir: Path):
    """Fit to UIUC apce_8x6 with HOLDOUT held out; returns (figure path, text table)."""
    from ..identify import FitOptions, fit_loads, loads_from_catalogue
    from ..io.params_file import write_params
    from ..plots import plot_load_fit
    from ..validation import holdout_comparison

    entry = get_entry(PROP)
    data = loads_from_catalogue(entry, prop.diameter)
    res = fit_loads(data.subset(~np.isin(data.group, HOLDOUT)), prop, base=params, options=FitOptions())
    write_params(out_dir / "fitted_params.toml", res.params, res.air, comment=f"propmap demo: fit to UIUC {PROP}")
    cmp = holdout_comparison(entry, prop, res.params, params, HOLDOUT)
    p = res.params
    rows = [f"   {'':<22}{'cl1':>7}{'cl2':>7}{'cd':>7}{'alpha0 [deg]':>14}",
            f"   {'fitted (UIUC data)':<22}{p.cl1:>7.2f}{p.cl2:>7.2f}{p.cd:>7.2f}{math.degrees(p.alpha0):>14.1f}",
            f"   {'Table I (APC)':<22}{params.cl1:>7.2f}{params.cl2:>7.2f}{params.cd:>7.2f}"
            f"{math.degrees(params.alpha0):>14.1f}",
            f"   held-out {cmp['fitted']['n_points']} points:  CT rmse / CP rmse",
            f"   {'fitted model':<22}{cmp['fitted']['ct_rmse']:.4f} / {cmp['fitted']['cp_rmse']:.4f}",
            f"   {'Table I model':<22}{cmp['baseline']['ct_rmse']:.4f} / {cmp['baseline']['cp_rmse']:.4f}",
            f"   {'hover model':<22}{cmp['hover_model']['ct_rmse']:.4f} / {cmp['hover_model']['cp_rmse']:.4f}",
            f"   ({res.nfev} model evaluations, {res.elapsed_s:.1f} s; poorly determined: "
            f"{', '.join(res.identifiability.poorly_determined) or 'none'})"]
    fig = plot_load_fit(cmp["validation_fitted"].runs, cmp["validation_baseline"].runs, set(HOLDOUT),
                        out_dir / "fit.png", baseline_label="Table I",
                        title=f"{PROP}: fitted to UIUC data (open: held out)\nData: {entry.citation}")
    return fig, "\n".join(rows)


@click.command("demo")
@click.option("--out-dir", type=click.Path(path_type=Path), default=Path("propmap-demo"), show_default=True,
              help="Folder for the figures and tables.")
@click.option("--rpm", type=float, default=8000.0, show_default=True, help="Rotation rate of the envelope [rpm].")
def demo(out_dir: Path, rpm: float):
    """APC 8x6E (APC PE0 geometry) with Gill & D'Andrea's Table I APC parameters.

    1. Loads over the envelope vs the hover model T = k_T Omega^2, D = 0.
    2. The model against UIUC's measured apce_8x6 static and J-sweep data.
    3. The parameters fitted to that data with the 6000 rpm sweeps held out, beside Table I.
    """
    from ..plots import plot_envelope, plot_validation

    prop = load_propeller(PROP)
    params = preset(PARAMS)
    click.echo(f"propmap demo: {PROP} (APC 8x6 Thin Electric, geometry {prop.source})")
    click.echo(f"parameters {PARAMS} (Gill & D'Andrea 2017, Table I): cl1={params.cl1}, cl2={params.cl2}, "
               f"cd={params.cd}, alpha0={math.degrees(params.alpha0):.1f} deg\n")

    table = envelope_table(prop, params, rpm)
    out_dir.mkdir(parents=True, exist_ok=True)
    with atomic_write(out_dir / "envelope.csv", "w", newline="") as fh:
        table.to_csv(fh, index=False, float_format="%.6g")
    click.echo(f"1. Envelope at {rpm:g} rpm: model vs hover model (T_hover = {table.thrust_hover.iloc[0]:.3f} N, D = 0)")
    click.echo("   hover-model thrust error = T_hover - T, in N and in % of the static thrust")
    click.echo(f"   {'V [m/s]':>8}{'incid.':>8}{'T [N]':>9}{'D [N]':>8}{'Q [N m]':>10}{'T_hover - T':>13}")
    for _, row in table[table.airspeed.isin([0.0, 10.0, 20.0])].iterrows():
        err = row["thrust_hover"] - row["thrust"]
        click.echo(f"   {row['airspeed']:>8.0f}{row['incidence_deg']:>8.0f}{row['thrust']:>9.3f}{row['drag']:>8.3f}"
                   f"{row['torque']:>10.4f}{err:>+9.3f} N {100 * err / row['thrust_hover']:>+4.0f}%  {row['flags']}")
    fig1 = plot_envelope(table, out_dir / "envelope.png",
                         title=f"{PROP} at {rpm:g} rpm, params {PARAMS}: BET+BEMT vs hover model")

    click.echo("\n2. Against UIUC measurements of apce_8x6 (no fitting; Table I parameters):")
    v = validate(get_entry(PROP), prop, params)
    print_table(v)
    fig2 = plot_validation(v, out_dir / "validation.png",
                           title=f"{PROP}, params {PARAMS}: model vs UIUC measured")
    click.echo("   Known bias with Table I parameters (see docs/validation.md): eq 3 has C_L(0) = 0 (no camber),")
    click.echo("   so thrust falls too fast with J; the hover model is exact only at J = 0.")

    click.echo(f"\n3. Fit {PROP} to UIUC's measurements, holding out the 6000 rpm sweeps {', '.join(HOLDOUT)}:")
    fig3, table3 = fit_demo(prop, params, out_dir)
    click.echo(table3)
    click.echo(f"\nwrote {out_dir / 'envelope.csv'}, {fig1}, {fig2}, {fig3}, {out_dir / 'fitted_params.toml'}")
