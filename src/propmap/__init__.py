"""propmap: thrust, rotor drag and torque of small propellers anywhere in the flight envelope.

The rotor model of Gill & D'Andrea, "Propeller Thrust and Drag in Forward Flight", IEEE CCTA
2017 (doi:10.1109/CCTA.2017.8062440), with the paper's section model or a cambered one
calibrated on UIUC measurements (docs/models.md). Units are SI throughout (rad, rad/s, m/s,
N, N m).
"""

from .core import (DEFAULT_DISCRETIZATION, PRESETS, Air, AirfoilParams, CamberedParams, Discretization, HoverModel, Propeller,
                   RotorLoads, RotorWrench, SolverError, drag_coefficient, lift_coefficient, preset, rotor_loads,
                   rotor_wrench)
from .io import catalogue, load_propeller, read_geometry, read_params, resolve_params, write_params
from .io.calibration import default_params, generic_params

__version__ = "0.1.0"

__all__ = [
    "Air", "AirfoilParams", "CamberedParams", "PRESETS", "preset", "lift_coefficient", "drag_coefficient", "Propeller",
    "HoverModel", "Discretization", "DEFAULT_DISCRETIZATION", "RotorLoads", "SolverError", "rotor_loads",
    "RotorWrench", "rotor_wrench", "catalogue", "load_propeller", "read_geometry", "read_params",
    "resolve_params", "write_params", "default_params", "generic_params", "__version__",
]
