"""``propmap props``: list the bundled catalogue."""

from __future__ import annotations

import click

from ..io.calibration import calibrated
from ..io.catalogue import catalogue
from ._common import Command, echo_json


@click.command("props", cls=Command)
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def props(as_json: bool) -> None:
    """List the bundled propellers, their measurements and calibration.

    A calibrated propeller has its own section parameters, fitted to all its bundled
    measurements; 'propmap loads' uses them by default. The fit's rms errors are in-sample,
    as fractions of the measured static CT and CP ('propmap validate --all' gives held-out
    errors).
    """
    rows = []
    for e in catalogue().values():
        c = calibrated(e.name)
        rows.append({"name": e.name, "volume": e.volume, "family": e.family, "diameter_in": e.diameter_in,
                     "pitch_in": e.pitch_in, "blades": e.n_blades,
                     "geometry": "UIUC" if e.geometry_format == "uiuc" else "APC PE0",
                     "static_runs": len(e.static_files), "sweeps": len(e.sweep_files),
                     "calibrated": c is not None,
                     "fit_rms_ct": None if c is None else c.rms_ct, "fit_rms_cp": None if c is None else c.rms_cp,
                     "citation": e.citation})
    if as_json:
        echo_json(rows)
        return
    click.echo(f"{'name':<22}{'vol':>4}{'D [in]':>7}{'P [in]':>7}{'blades':>7}  {'geometry':<9}{'static':>7}"
               f"{'sweeps':>7}  {'calibrated (fit rms dCT/CT0, dCP/CP0)'}")
    for r in rows:
        cal = (f"yes ({100 * r['fit_rms_ct']:.1f}%, {100 * r['fit_rms_cp']:.1f}%)" if r["calibrated"]
               else "no (generic)")
        pitch = "-" if r["pitch_in"] is None else f"{r['pitch_in']:.3g}"
        click.echo(f"{r['name']:<22}{r['volume']:>4}{r['diameter_in']:>7.3g}{pitch:>7}{r['blades']:>7}  "
                   f"{r['geometry']:<9}{r['static_runs']:>7}{r['sweeps']:>7}  {cal}")
    n_cal = sum(r["calibrated"] for r in rows)
    click.echo(f"{len(rows)} propellers, {n_cal} calibrated. Measurements: UIUC Propeller Data Site vol. 1 "
               "(Brandt & Selig, AIAA 2011-1255) and part of vol. 2 (Deters, Ananda & Selig, AIAA 2014-2151); APC "
               "geometry: APC PE0 files. P of vol. 2's nr640 blades: the helix of their blade angle at 0.75 R.")
