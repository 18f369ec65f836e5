"""Helpers shared by the subcommands: input errors as one line and exit code 2."""

from __future__ import annotations

import json
import math

import click

from ..core.geometry import Propeller
from ..io.catalogue import resolve_propeller
from ..io.params_file import resolve_params


class InputError(click.ClickException):
    """Bad user input: printed as one line, exit code 2."""

    exit_code = 2


def load_prop(spec: str, diameter_in: float | None, blades: int | None) -> Propeller:
    try:
        return resolve_propeller(spec, diameter_in=diameter_in, n_blades=blades)
    except KeyError as exc:
        raise InputError(f"PROP: {exc.args[0]}") from None
    except ValueError as exc:
        raise InputError(f"PROP: {exc}") from None


PARAMS_HELP = ("Parameter set: a parameter TOML file, 'generic' (cambered, fitted to the whole catalogue), "
               "'calibrated:NAME' (a catalogue propeller's own fit) or the paper's Table I "
               "(gill2017-soft|gill2017-stiff|gill2017-apc). Default: PROP's calibrated set if it has one, "
               "else 'generic'.")


def load_params(spec: str | None, prop_spec: str | None = None, option: str = "--params"):
    """(params, air, label) for ``spec``; None: the default for the propeller ``prop_spec``.

    The default is the catalogue propeller's calibrated set, else the generic set (for
    geometry files and propellers without measurements).
    """
    if spec is None:
        from ..io.calibration import default_params
        from ..io.catalogue import catalogue

        return default_params(prop_spec if prop_spec in catalogue() else "")
    try:
        params, air = resolve_params(spec)
    except KeyError as exc:
        raise InputError(f"{option}: {exc.args[0]}") from None
    except ValueError as exc:
        raise InputError(f"{option}: {exc}") from None
    return params, air, spec


def check_point(rpm: float, airspeed: float, incidence_deg: float, where: str = "") -> None:
    """Raise InputError naming the input and its valid range."""
    pre = f"{where}: " if where else ""
    if not (math.isfinite(rpm) and 0 < rpm <= 1e6):
        raise InputError(f"{pre}rpm must be finite and in (0, 1e6], got {rpm!r}")
    if not (math.isfinite(airspeed) and 0 <= airspeed <= 500):
        raise InputError(f"{pre}airspeed must be finite and in [0, 500] m/s, got {airspeed!r}")
    if not (math.isfinite(incidence_deg) and 0 <= incidence_deg <= 180):
        raise InputError(f"{pre}incidence_deg must be finite and in [0, 180] deg, got {incidence_deg!r}")


def echo_json(obj) -> None:
    click.echo(json.dumps(obj, indent=2, allow_nan=False))


prop_options = [
    click.option("--diameter-in", type=float, default=None, help="Diameter [in] for geometry files that lack it."),
    click.option("--blades", type=int, default=None, help="Blade count for geometry files (default 2)."),
]


def with_prop_options(f):
    for opt in reversed(prop_options):
        f = opt(f)
    return f
