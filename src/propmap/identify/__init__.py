"""Parameter identification (Gill & D'Andrea 2017, Section III) on top of the core model."""

from .data import (DataError, LevelFlightData, LoadData, loads_from_catalogue, loads_from_uiuc_files,
                   read_level_flight, read_loads, rotor_kinematics, sanity_check)
from .fit import FitOptions, FitResult, Identifiability, X0_PAPER, fit_loads
from .joint import fit_loads_joint
from .level_flight_fit import fit_level_flight, level_flight_forces
from .synthetic import simulate_level_flight
from ..vehicle import Rotor, Vehicle, VehicleFileError, read_vehicle

__all__ = [
    "DataError", "LevelFlightData", "LoadData", "loads_from_catalogue", "loads_from_uiuc_files",
    "read_level_flight", "read_loads", "rotor_kinematics", "sanity_check", "FitOptions", "FitResult", "Identifiability",
    "X0_PAPER", "fit_level_flight", "fit_loads", "fit_loads_joint", "level_flight_forces",
    "simulate_level_flight", "Rotor", "Vehicle", "VehicleFileError", "read_vehicle",
]
