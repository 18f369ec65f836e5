"""The pure core: geometry, airfoil polars, BEMT solver, hover model, vector form.

Imports only NumPy, SciPy and numba.
"""

from .airfoil import PRESETS, Air, AirfoilParams, CamberedParams, drag_coefficient, lift_coefficient, preset
from .geometry import Propeller
from .hover import HoverModel
from .solver import DEFAULT_DISCRETIZATION, Discretization, RotorLoads, SolverError, rotor_loads
from .vector import RotorWrench, rotor_wrench

__all__ = [
    "Air", "AirfoilParams", "CamberedParams", "PRESETS", "preset", "lift_coefficient", "drag_coefficient",
    "Propeller", "HoverModel", "Discretization", "DEFAULT_DISCRETIZATION", "RotorLoads",
    "SolverError", "rotor_loads", "RotorWrench", "rotor_wrench",
]
