"""A vehicle file's own parameter set (its top-level ``params``, vehicle/file.py): where it is, and
the vehicle with it applied as the vehicle commands apply it (``wrench``, ``trim-vehicle``,
``export-sim --vehicle``, ``map --format c --vehicle``): its section set for the rotors and, where
it is a flight fit's file, its ``[body]`` table (airframe drag, centre of mass, rotor
interference) in place of the vehicle file's."""

from __future__ import annotations

from dataclasses import replace

from ..io.toml_file import load_toml
from .file import VehicleFileError, _local_file, _resolved_spec, _rotor_params, read_vehicle, vehicle_path
from .layout import Vehicle, shift_centre_of_mass

__all__ = ["read_vehicle_with_params", "vehicle_params_file", "with_body_table"]


def vehicle_params_file(path) -> str | None:
    """The vehicle file's own parameter set (its top-level ``params``), as the vehicle commands
    take it where ``--params`` is not given.

    Parameters
    ----------
    path : str or Path
        A vehicle file, or a bundled example vehicle's name (:func:`propmap.vehicle.file.vehicle_path`);
        read it with :func:`propmap.read_vehicle` for the full check.

    Returns
    -------
    str or None
        The parameter file's path (relative to the vehicle's folder, where it exists there) or
        the named set; None where the vehicle names none.

    Raises
    ------
    VehicleFileError
        The file cannot be read as TOML.
    """
    path = vehicle_path(path)
    return _resolved_spec(load_toml(path, VehicleFileError).get("params"), path.parent)


def with_body_table(vehicle: Vehicle, table) -> Vehicle:
    """The vehicle with a parameter file's ``[body]`` table in place of its own airframe.

    Parameters
    ----------
    vehicle : Vehicle
    table : propmap.io.params_tables.BodyTable or None
        What :func:`propmap.io.params_file.read_body` gives: the airframe drag, and the centre of
        mass and rotor interference where the table gives them (a flight fit writes them only
        where it fitted them); None: the vehicle as it is.

    Returns
    -------
    Vehicle
        A copy with the table's drag, centre of mass and interference (each the vehicle's where
        the table gives none).
    """
    if table is None:
        return vehicle
    vehicle = replace(vehicle, body_drag=table.drag)
    if table.centre_of_mass is not None:
        vehicle = shift_centre_of_mass(vehicle, table.centre_of_mass)
    if table.rotor_interference is not None:
        vehicle = replace(vehicle, rotor_interference=table.rotor_interference)
    return vehicle


def read_vehicle_with_params(path):
    """A vehicle file and its own parameter set, applied as the vehicle commands apply it.

    Parameters
    ----------
    path : str or Path
        A vehicle file, or a bundled example vehicle's name (``"neurobem_quadrotor"``, whose set
        is the flight fit to its four NeuroBEM segments, docs/flight.md).

    Returns
    -------
    vehicle : Vehicle
        :func:`propmap.read_vehicle`'s, with the set's ``[body]`` table in place of the file's
        airframe where the set is a file that has one (:func:`with_body_table`).
    params : SectionParams or None
        The set (None where the file names none): pass it to :func:`propmap.vehicle_wrench`,
        :func:`propmap.trim_vehicle` or :func:`propmap.hover_omega` for the rotors without a set
        of their own, with its air (``params.air``), as the commands do.

    Raises
    ------
    VehicleFileError
        As :func:`propmap.read_vehicle`.

    Examples
    --------
    >>> import propmap as pm
    >>> veh, own = pm.read_vehicle_with_params("neurobem_quadrotor")
    >>> trim = pm.trim_vehicle(veh, own, 10.0)   # what `propmap trim-vehicle --vehicle neurobem_quadrotor` gives
    """
    from ..io.params_file import read_body

    vehicle = read_vehicle(path)
    spec = vehicle_params_file(path)
    if spec is None:
        return vehicle, None
    folder = vehicle_path(path).parent
    params = _rotor_params(spec, folder, str(path))
    local = _local_file(spec, folder)
    return (with_body_table(vehicle, read_body(local)) if local is not None else vehicle), params
