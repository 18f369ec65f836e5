"""The pure core: geometry, airfoil polars, BEMT solver, hover model, vector form.

Imports only NumPy, SciPy and numba (the public names on first use, PEP 562).
"""

from __future__ import annotations

import importlib

_EXPORTS = {
    "Air": "airfoil", "AirfoilParams": "airfoil", "CamberedParams": "airfoil", "PRESETS": "airfoil",
    "preset": "airfoil", "lift_coefficient": "airfoil", "drag_coefficient": "airfoil", "Propeller": "geometry",
    "HoverModel": "hover", "Discretization": "solver", "DEFAULT_DISCRETIZATION": "solver", "RotorLoads": "solver",
    "SolverError": "solver", "rotor_loads": "solver", "RotorWrench": "vector", "rotor_wrench": "vector",
}

__all__ = list(_EXPORTS)


def __getattr__(name: str):
    if name in _EXPORTS:
        value = getattr(importlib.import_module(f".{_EXPORTS[name]}", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'propmap.core' has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
