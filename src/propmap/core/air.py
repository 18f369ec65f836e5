"""Air properties: :class:`Air` (density, viscosity, speed of sound; footnote 2 of Gill &
D'Andrea 2017 by default, or from temperature and pressure, or the standard atmosphere).

Constants of dry air: U.S. Standard Atmosphere, 1976; ISO 2533:1975. Viscosity:
Sutherland's law.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ._numbers import checked

__all__ = ["Air", "air_words", "check_air"]


@dataclass(frozen=True)
class Air:
    """Air properties (footnote 2 of Gill & D'Andrea 2017).

    Parameters
    ----------
    rho : float
        Density [kg/m^3], > 0. Default 1.225.
    mu : float
        Dynamic viscosity [Pa s], > 0. Default 1.983e-5.
    speed_of_sound : float
        [m/s], > 0; used by the cambered section's compressibility correction. Default
        340.3 (ISA sea level).

    Raises
    ------
    ValueError
        If a value is non-finite or not positive.
    """

    rho: float = 1.225
    mu: float = 1.983e-5
    speed_of_sound: float = 340.3

    def __post_init__(self) -> None:
        for name, unit in (("rho", "kg/m^3"), ("mu", "Pa s"), ("speed_of_sound", "m/s")):
            object.__setattr__(self, name, checked(name, getattr(self, name), 0.0, low_open=True, unit=unit))

    @classmethod
    def from_conditions(cls, temperature: float, pressure: float) -> "Air":
        """Dry air at a measured temperature and static pressure.

        rho = p / (R T) with R = 287.05287 J/(kg K); mu by Sutherland's law,
        mu = 1.458e-6 T^1.5 / (T + 110.4); speed of sound sqrt(1.4 R T) (the constants of
        the U.S. Standard Atmosphere, 1976, and ISO 2533:1975). Humidity is left out: at
        25 degC and 60% relative humidity it lowers rho by 0.8%.

        Parameters
        ----------
        temperature : float
            Static temperature T [K], in [180, 350].
        pressure : float
            Static pressure p [Pa], in [1e3, 1.2e5].

        Returns
        -------
        Air
            rho [kg/m^3], mu [Pa s], speed_of_sound [m/s] of that air.

        Raises
        ------
        ValueError
            Naming the value out of its range.
        """
        T = checked("temperature", temperature, *TEMPERATURE_RANGE_K, unit="K")
        p = checked("pressure", pressure, *PRESSURE_RANGE_PA, unit="Pa")
        return cls(rho=p / (R_AIR * T), mu=SUTHERLAND_C1 * T**1.5 / (T + SUTHERLAND_S),
                   speed_of_sound=math.sqrt(GAMMA_AIR * R_AIR * T))

    @classmethod
    def isa(cls, altitude: float) -> "Air":
        """The International Standard Atmosphere at a geopotential altitude.

        Troposphere (h <= 11 km): T = 288.15 K - 0.0065 K/m h, p = 101325 Pa (T / 288.15
        K)^5.255877; the isothermal layer above it to 20 km: T = 216.65 K,
        p = p11 exp(-g0 (h - 11000 m) / (R T)) (ISO 2533:1975; U.S. Standard
        Atmosphere, 1976), with p11 the troposphere's law at 11 km (22632.04 Pa; the standard
        tabulates 22632.06 Pa, which would put a step of 9e-7 in rho at 11 km); then
        :meth:`from_conditions`. Sea level: rho 1.2250 kg/m^3, mu 1.789e-5 Pa s, speed of
        sound 340.29 m/s.

        Parameters
        ----------
        altitude : float
            h [m], in [-500, 20000].

        Returns
        -------
        Air
            The standard atmosphere's air at ``altitude``.

        Raises
        ------
        ValueError
            ``altitude`` out of its range or not a number.
        """
        h = checked("altitude", altitude, *ALTITUDE_RANGE_M, unit="m")
        T = 288.15 - 0.0065 * min(h, 11000.0)  # (216.65 K at and above 11 km)
        p = 101325.0 * (T / 288.15) ** (G0 / (0.0065 * R_AIR))
        if h > 11000.0:
            p *= math.exp(-G0 * (h - 11000.0) / (R_AIR * T))
        return cls.from_conditions(T, p)


#: constants of dry air (U.S. Standard Atmosphere, 1976; ISO 2533:1975)
R_AIR = 287.05287  # [J/(kg K)]
GAMMA_AIR = 1.4
SUTHERLAND_C1 = 1.458e-6  # [kg/(m s K^0.5)]
SUTHERLAND_S = 110.4  # [K]
G0 = 9.80665  # [m/s^2]
#: valid ranges of Air.from_conditions and Air.isa
TEMPERATURE_RANGE_K = (180.0, 350.0)
PRESSURE_RANGE_PA = (1e3, 1.2e5)
ALTITUDE_RANGE_M = (-500.0, 20000.0)
#: the start of the warnings of a blade tip near or past the speed of sound (:class:`TipMachWarning`)
SUPERSONIC_TIP = "a blade tip meets the air at Mach"


class TipMachWarning(UserWarning):
    """A blade tip that meets the air beyond Mach 0.8 (``core._inputs.TIP_MACH_WARN``), where the
    model's compressibility ends (its Prandtl-Glauert factor is held at Mach 0.9): said by
    :func:`propmap.rotor_loads`, the load fit, the vehicle's hover and trim.

    A category of its own, for a user's warning filters (a simulation loop that has checked
    its rates; the command line, which warns from tip Mach 0.7 in its own terms, filters it
    so); :func:`propmap.core.solver.supersonic_tips_allowed` holds it in a search. Its text
    starts with :data:`SUPERSONIC_TIP`. (A UserWarning told by its text until 2026-12-01.)
    """


def check_air(air) -> None:
    """Refuse an ``air`` that is not an :class:`Air` (the one check of every entry point that
    takes one: the solver, the hover model, the load readers, the parameter files).

    Parameters
    ----------
    air : object
        The air an entry point was given (density [kg/m^3], viscosity [Pa s] and speed of
        sound [m/s] travel in an :class:`Air`).

    Raises
    ------
    TypeError
        ``air`` not an :class:`Air` (the message names its type).
    """
    if not isinstance(air, Air):
        raise TypeError(f"air must be a propmap.Air, got {type(air).__name__}")


def air_words(rho: float, mu: float | None = None, speed_of_sound: float | None = None, rho_digits: int = 6) -> str:
    """The air in words, for the outputs that name it: ``rho 1.225 kg/m^3, mu 1.983e-05 Pa s,
    speed of sound 340.3 m/s`` (mu and the speed of sound where given).

    Parameters
    ----------
    rho : float
        Density [kg/m^3].
    mu : float, optional
        Dynamic viscosity [Pa s]; None leaves it out (a file written before it was recorded).
    speed_of_sound : float, optional
        [m/s]; None leaves it out.
    rho_digits : int, optional
        Significant digits of rho (4 in the commands' lines, 6 in the exports' heads).

    Returns
    -------
    str

    Raises
    ------
    ValueError, TypeError
        A value that is not a number (``float`` of it).
    """
    return (f"rho {float(rho):.{rho_digits}g} kg/m^3" + (f", mu {float(mu):.4g} Pa s" if mu is not None else "")
            + (f", speed of sound {float(speed_of_sound):.4g} m/s" if speed_of_sound is not None else ""))
