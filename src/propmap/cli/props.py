"""``propmap props``: list the bundled catalogue."""

from __future__ import annotations

import click

from ..io.catalogue import catalogue
from ._common import echo_json


@click.command("props")
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of a table.")
def props(as_json: bool) -> None:
    """List the bundled propellers and which measurements come with them."""
    rows = [
        {"name": e.name, "diameter_in": e.diameter_in, "pitch_in": e.pitch_in, "blades": e.n_blades,
         "geometry": "UIUC" if e.geometry_format == "uiuc" else "APC PE0",
         "static_runs": len(e.static_files), "sweeps": len(e.sweep_files)}
        for e in catalogue().values()
    ]
    if as_json:
        echo_json(rows)
        return
    click.echo(f"{'name':<18}{'D [in]':>7}{'P [in]':>7}{'blades':>7}  {'geometry':<9}{'static':>7}{'sweeps':>7}")
    for r in rows:
        click.echo(f"{r['name']:<18}{r['diameter_in']:>7g}{r['pitch_in']:>7g}{r['blades']:>7}  {r['geometry']:<9}"
                   f"{r['static_runs']:>7}{r['sweeps']:>7}")
    click.echo(f"{len(rows)} propellers. Measurements: UIUC Propeller Data Site vol. 1 (Brandt & Selig, "
               "AIAA 2011-1255); APC geometry: APC PE0 files.")
