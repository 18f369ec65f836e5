"""The air a command runs in: the options --rho [kg/m^3], --temperature-c [degC] with
--pressure-pa [Pa] and --altitude-m [m], and their resolution against a parameter set's air
(docs/cli.md, Air)."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import click

from ._common import InputError, option_group

__all__ = ["RHO_RANGE", "AirChoice", "air_label", "air_options", "air_record", "resolve_air", "with_air_options"]


#: the densities accepted on the command line [kg/m^3] (as parameter files)
RHO_RANGE = (1e-3, 2000.0)

air_options = [
    click.option("--rho", type=float, default=None,
                 help="Air density [kg/m^3] (default: that of the parameter set); viscosity and speed of sound stay "
                      "the set's."),
    click.option("--temperature-c", type=float, default=None,
                 help="Air temperature [degC], with --pressure-pa: density, viscosity and speed of sound of dry air."),
    click.option("--pressure-pa", type=float, default=None, help="Static air pressure [Pa], with --temperature-c."),
    click.option("--altitude-m", type=float, default=None,
                 help="The International Standard Atmosphere at this altitude [m] (ISO 2533)."),
]


@dataclass(frozen=True)
class AirChoice:
    """The air options of a command: --rho [kg/m^3], --temperature-c [degC] with
    --pressure-pa [Pa], or --altitude-m [m] (:func:`resolve_air`)."""

    rho: float | None = None
    temperature_c: float | None = None
    pressure_pa: float | None = None
    altitude_m: float | None = None

    def options_given(self) -> list[str]:
        """The options given (not None), as typed: ``["--rho"]``."""
        return ["--" + f.name.replace("_", "-") for f in fields(self) if getattr(self, f.name) is not None]


#: adds --rho, --temperature-c, --pressure-pa and --altitude-m, passed as ``air_choice`` (an AirChoice)
with_air_options = option_group("air_choice", AirChoice, air_options)


def resolve_air(air, choice: AirChoice):
    """The air of a command: the parameter set's ``air``, or what the air options give.

    ``--rho`` replaces the density only; ``--temperature-c`` with ``--pressure-pa`` gives
    dry air at those conditions and ``--altitude-m`` the ISA (core.air.Air). One of the
    three ways at a time.

    Parameters
    ----------
    air : Air
        The parameter set's air.
    choice : AirChoice
        The command's air options.

    Raises
    ------
    InputError
        Options of two ways, a temperature without a pressure (or the reverse), a value out
        of its range (named with the option).
    """
    from ..core.air import ALTITUDE_RANGE_M, PRESSURE_RANGE_PA, TEMPERATURE_RANGE_K, Air

    rho, temperature_c = choice.rho, choice.temperature_c
    pressure_pa, altitude_m = choice.pressure_pa, choice.altitude_m
    ways = [w for w, given_ in (("--rho", rho is not None),
                                ("--temperature-c/--pressure-pa", temperature_c is not None or pressure_pa is not None),
                                ("--altitude-m", altitude_m is not None)) if given_]
    if len(ways) > 1:
        raise InputError(f"give the air one way: {' or '.join(ways)}, not {'both' if len(ways) == 2 else 'all three'}")
    if rho is not None:
        if not (math.isfinite(rho) and RHO_RANGE[0] <= rho <= RHO_RANGE[1]):
            raise InputError(f"--rho must be in [{RHO_RANGE[0]:g}, {RHO_RANGE[1]:g}] kg/m^3, got {rho!r}")
        return Air(rho=rho, mu=air.mu, speed_of_sound=air.speed_of_sound)
    if temperature_c is not None or pressure_pa is not None:
        if temperature_c is None or pressure_pa is None:
            raise InputError("--temperature-c and --pressure-pa go together (or give --rho or --altitude-m)")
        lo, hi = TEMPERATURE_RANGE_K
        T = round(temperature_c + 273.15, 9) if math.isfinite(temperature_c) else math.nan  # (-93.15 degC is 180 K)
        if not lo <= T <= hi:
            raise InputError(f"--temperature-c must be finite and in [{lo - 273.15:g}, {hi - 273.15:g}] degC, got "
                             f"{temperature_c!r}")
        return Air.from_conditions(T, _check_option("--pressure-pa", pressure_pa, *PRESSURE_RANGE_PA, "Pa"))
    if altitude_m is not None:
        return Air.isa(_check_option("--altitude-m", altitude_m, *ALTITUDE_RANGE_M, "m"))
    return air


def _check_option(option: str, value: float, lo: float, hi: float, unit: str) -> float:
    """``value`` if finite and in [lo, hi]; else an InputError naming ``option`` and its range."""
    if not (math.isfinite(value) and lo <= value <= hi):
        raise InputError(f"{option} must be finite and in [{lo:g}, {hi:g}] {unit}, got {value!r}")
    return value


def air_label(air) -> str:
    """One line of the air used, for outputs."""
    from ..core.air import air_words

    return air_words(air.rho, air.mu, air.speed_of_sound, rho_digits=4)


def air_record(air) -> dict:
    """The air used, SI, for the --json outputs: rho [kg/m^3], mu [Pa s], speed_of_sound [m/s]."""
    return {"rho": air.rho, "mu": air.mu, "speed_of_sound": air.speed_of_sound}
