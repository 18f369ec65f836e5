"""The ``propmap`` command line: a thin layer over the public API."""

from __future__ import annotations

import sys

import click

from .. import __version__
from .demo import demo
from .fit import fit
from .loads import loads
from .props import props
from .validate import validate


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="propmap")
def cli() -> None:
    """Thrust, rotor drag and torque of small propellers (Gill & D'Andrea 2017)."""


for _cmd in (props, loads, validate, fit, demo):
    cli.add_command(_cmd)


def main(argv: list[str] | None = None) -> int:
    """Run the CLI with ``argv``; return the exit code (0 ok, 1 solver failure, 2 bad input).

    Errors are printed as one line ``propmap: error: ...`` on stderr, never a traceback.
    """
    try:
        cli.main(args=argv, prog_name="propmap", standalone_mode=False)
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except click.exceptions.Abort:
        click.echo("propmap: aborted", err=True)
        return 1
    except click.UsageError as exc:  # unknown option, bad type, missing argument: exit 2
        click.echo(f"propmap: error: {exc.format_message()}", err=True)
        return 2
    except click.ClickException as exc:
        click.echo(f"propmap: error: {exc.format_message()}", err=True)
        return exc.exit_code
    return 0


def run() -> None:
    """Console-script entry point."""
    sys.exit(main())
