"""The multirotor vehicle model (its rotors' wrenches about the centre of mass) and its file.

Shared by identification (level flight, flight logs), maps and exports; imports the core
and io only.
"""

from ._kinematics import hub_velocities
from .file import VehicleFileError, read_vehicle
from .layout import Rotor, Vehicle, rotor_geometry
from .mapped import VehicleMap, VehicleMapWrench
from .model import VehicleWrench, hover_omega, vehicle_wrench
from .own_set import ResolvedVehicle, read_vehicle_with_params, resolve_vehicle, vehicle_params_file
from .trim import VehicleTrim, trim_vehicle

__all__ = ["ResolvedVehicle", "Rotor", "Vehicle", "VehicleMap", "VehicleMapWrench", "VehicleTrim", "VehicleWrench",
           "VehicleFileError", "hover_omega", "hub_velocities", "read_vehicle", "read_vehicle_with_params",
           "resolve_vehicle", "rotor_geometry", "trim_vehicle", "vehicle_params_file", "vehicle_wrench"]
