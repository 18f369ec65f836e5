"""The pure core: geometry, airfoil polars, BEMT solver, hover model, vector form.

Imports only NumPy, SciPy and numba (the public names on first use, PEP 562).
"""

from __future__ import annotations

from .._lazy import lazy_exports

_EXPORTS = {
    "Air": "air", "AirfoilParams": "airfoil", "CamberedParams": "airfoil", "RotorOptions": "airfoil",
    "PRESETS": "airfoil", "preset": "airfoil", "lift_coefficient": "polar", "drag_coefficient": "polar",
    "Propeller": "geometry", "HoverModel": "hover", "Discretization": "solver", "DEFAULT_DISCRETIZATION": "solver",
    "RotorLoads": "solver", "SolverError": "solver", "rotor_loads": "solver", "RotorWrench": "vector",
    "rotor_wrench": "vector",
}

__all__ = list(_EXPORTS)
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS, globals())
