"""propmap: thrust, rotor drag and torque of small propellers anywhere in the flight envelope.

The rotor model of Gill & D'Andrea, "Propeller Thrust and Drag in Forward Flight", IEEE CCTA
2017 (doi:10.1109/CCTA.2017.8062440), with the paper's section model or a cambered one
calibrated on UIUC measurements (docs/models.md). Units are SI throughout (rad, rad/s, m/s,
N, N m).

The public names are imported on first use (PEP 562), so that ``import propmap`` and the
command line start without loading numba and SciPy until they are needed.
"""

from __future__ import annotations

from ._lazy import lazy_exports

__version__ = "0.1.0"

_EXPORTS = {
    "Air": "core.air", "AirfoilParams": "core.airfoil", "CamberedParams": "core.airfoil",
    "PRESETS": "core.airfoil", "preset": "core.airfoil", "lift_coefficient": "core.polar",
    "drag_coefficient": "core.polar", "Propeller": "core.geometry", "HoverModel": "core.hover",
    "Discretization": "core.solver", "DEFAULT_DISCRETIZATION": "core.solver", "RotorLoads": "core.solver",
    "SolverError": "core.solver", "FlappingWarning": "core.flapping", "TipMachWarning": "core.air",
    "rotor_loads": "core.solver", "RotorWrench": "core.vector", "rotor_wrench": "core.vector",
    "catalogue": "io.catalogue", "load_propeller": "io.catalogue",
    "read_geometry": "io.geometry_files", "read_params": "io.params_file", "resolve_params": "io.param_sets",
    "write_params": "io.params_file", "default_params": "io.calibration", "generic_params": "io.calibration",
    "RotorMap": "maps", "build_map": "maps", "BodyDrag": "core.body", "Vehicle": "vehicle", "Rotor": "vehicle",
    "read_vehicle": "vehicle", "vehicle_wrench": "vehicle", "hover_omega": "vehicle", "VehicleWrench": "vehicle",
    "VehicleMap": "vehicle", "trim_vehicle": "vehicle", "VehicleTrim": "vehicle", "vehicle_params_file": "vehicle",
    "read_vehicle_with_params": "vehicle", "resolve_vehicle": "vehicle", "ResolvedVehicle": "vehicle",
    "trim_collective": "core.trim", "TrimResult": "core.trim", "TrimError": "core.trim", "trim_omega": "core.trim",
    "OmegaTrimResult": "core.trim",
    "torque_change_at_constant_thrust": "core.torque_change", "section_preset": "io.param_sets",
    "rotor_like": "core.geometry", "example_file": "io.catalogue", "example_files": "io.catalogue",
    "nominal_propeller": "io.nominal_geometry",
}

__all__ = [*_EXPORTS, "__version__"]
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS, globals())
