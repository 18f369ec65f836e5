"""A vehicle file with its parameter sets, resolved as the vehicle commands resolve them
(``wrench``, ``trim-vehicle``, ``export-sim --vehicle``, ``map --format c --vehicle``) and the API
(:func:`resolve_vehicle`, :func:`read_vehicle_with_params`): the vehicle's own set (its top-level
``params``), where it is a flight fit's file its ``[body]`` table (airframe drag, centre of mass,
rotor interference) in place of the vehicle file's, and each rotor's set (its own, else the
vehicle's, else its catalogue propeller's calibrated set, else the generic set). One rule for the
commands and the library: until 2026-12-01 it lived in the command line alone, and
``read_vehicle_with_params("quadrotor")`` gave no set where the commands took apce_8x6's
calibrated one (a review of stop 94)."""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from pathlib import Path

from ..io.qprop_file import _spec_file
from ..io.toml_file import load_toml
from .file import VehicleFileError, _entry_specs, _read_vehicle, _resolved_spec, vehicle_path
from .layout import Vehicle, shift_centre_of_mass

__all__ = ["ResolvedVehicle", "read_vehicle_with_params", "resolve_vehicle", "vehicle_files", "vehicle_params_file",
           "with_body_table", "with_set_body"]


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


def vehicle_files(path) -> list[Path]:
    """The files a vehicle file names: its own parameter file (its top-level ``params``) and its
    rotors' geometry and parameter files (``[[rotors]] propeller`` and ``params`` entries that are
    files, as :func:`propmap.read_vehicle` resolves them), from one reading of the file; the
    inputs of a command given the vehicle, which it must not write over.

    Parameters
    ----------
    path : str or Path
        A vehicle file, or a bundled example vehicle's name.

    Returns
    -------
    list of Path
        The entries that exist as files or folders, in the file's order (the vehicle's set, the
        rotors' propellers, the rotors' sets; a ``qprop:FILE`` set's FILE).

    Raises
    ------
    VehicleFileError
        The file cannot be read as TOML.
    """
    path = vehicle_path(path)
    data = load_toml(path, VehicleFileError)
    specs = [_resolved_spec(data.get("params"), path.parent),
             *(s for key in ("propeller", "params") for s in _entry_specs(data, path.parent, key))]
    specs = [_spec_file(s) for s in specs if s is not None]  # (qprop:FILE reads FILE)
    return [Path(s) for s in specs if os.path.lexists(s)]


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


@dataclass(frozen=True, eq=False)  # (compared by identity: a Vehicle's arrays have no one truth value, an audit)
class ResolvedVehicle:
    """A vehicle with its parameter sets, as :func:`resolve_vehicle` resolves them.

    Attributes
    ----------
    vehicle : Vehicle
        The vehicle file's, with the ``[body]`` table of the set's file in place of its airframe
        (:func:`with_body_table`, where the set is a file with one) and, where the rotors' sets
        differ, each rotor without a set of its own given its set (the vehicle's, else its
        catalogue propeller's calibrated one); with a given ``params``, no rotor keeps its own.
    params : SectionParams
        The set for every rotor without one of its own, whose air the rotors are solved in (pass
        it to :func:`propmap.vehicle_wrench`, :func:`propmap.trim_vehicle` or
        :func:`propmap.hover_omega`).
    label : str
        The set's name or file; where the rotors' sets differ, "the vehicle's rotor sets: "
        followed by them.
    sets : tuple of str
        Each rotor's set label, in the file's order.
    air : Air
        The air the set was fitted in, where the rotors are solved by default (``params.air``).
    body_from : str or None
        The parameter file whose ``[body]`` table replaced the vehicle file's airframe; None: none did.
    dropped : tuple of int
        The rotors (1-based) whose own sets a given ``params`` replaced.
    """

    vehicle: Vehicle
    params: object
    label: str
    sets: tuple
    air: object
    body_from: str | None = None
    dropped: tuple = ()


def resolve_vehicle(path, params=None) -> ResolvedVehicle:
    """A vehicle file with its parameter sets, resolved as the vehicle commands resolve them.

    Without ``params``: each rotor takes its own set (its ``params`` entry), else the vehicle's
    own set (the file's top-level ``params``), else its catalogue propeller's calibrated set
    (:func:`propmap.default_params`), else the generic set; the vehicle's own set, where it is a
    flight fit's file, gives its ``[body]`` table (even where every rotor names a set of its
    own). Where every rotor's set is one, that set is ``params`` (so a set every rotor names
    comes before the vehicle's); where they differ, the rotors carry theirs (``vehicle``: each
    rotor with a set of its own, the vehicle's or a calibrated one) and ``params`` is the
    vehicle's own set, whose air the rotors are solved in, or without one the generic set, which
    the rotors without any set take. With ``params`` (as ``--params``): that set for every rotor
    (the rotors' own sets dropped: ``dropped``) and, where it is a file with a ``[body]`` table,
    its airframe.

    Parameters
    ----------
    path : str or Path
        A vehicle file, or a bundled example vehicle's name (``"quadrotor"``,
        ``"neurobem_quadrotor"``: :func:`propmap.vehicle.file.vehicle_path`).
    params : str, Path or SectionParams, optional
        A named set or a parameter file (:func:`propmap.resolve_params`; a relative path is taken
        from the working directory, as ``--params`` is), or a section parameter set (its
        ``label`` the record's; no ``[body]`` table).

    Returns
    -------
    ResolvedVehicle

    Raises
    ------
    VehicleFileError
        As :func:`propmap.read_vehicle`.
    TypeError
        ``params`` of another type.
    KeyError, ValueError, OSError
        ``params`` as :func:`propmap.resolve_params` raises them (an unknown set, a malformed
        file); :class:`propmap.io.params_file.ParamsFileError` for a malformed ``[body]`` table.

    Notes
    -----
    The resolution of ``propmap trim-vehicle`` and ``propmap wrench``, which call it
    (tests/test_stop95.py compares the example quadrotor's trim and each case's sets with the
    command's); the commands add their warnings (a rotor's set calibrated on another
    propeller, rotors' sets in other air than the command's) and their air options.
    """
    from ..io.calibration import default_params
    from ..io.inputs import show_path
    from ..io.param_sets import resolve_params
    from ..core.airfoil import AirfoilParams, CamberedParams

    given_set = isinstance(params, (AirfoilParams, CamberedParams))
    if not (params is None or given_set or isinstance(params, (str, os.PathLike))):
        raise TypeError(f"params must be a named set, a parameter file or a section parameter set, got "
                        f"{type(params).__name__}")
    reading = _reading(path)
    vehicle, mine, mine_set = reading.vehicle, reading.mine, reading.mine_set
    if params is None:
        vehicle, body_from = reading.with_own_body()
    else:
        vehicle, body_from = with_set_body(vehicle, None if given_set else params)
    n = len(vehicle.rotors)
    if params is not None:
        given = params if given_set else resolve_params(params)
        label = (params.label or "the given set") if given_set else str(params)
        dropped = tuple(k + 1 for k, r in enumerate(vehicle.rotors) if r.params is not None)
        if dropped:
            vehicle = replace(vehicle, rotors=tuple(replace(r, params=None) for r in vehicle.rotors))
        return ResolvedVehicle(vehicle, given, label, (label,) * n, given.air, body_from, dropped)
    names, own = reading.propellers, _rotor_sets(reading)
    spec = own[0] if own and own[0] is not None and len(set(own)) == 1 else None
    mixed = spec is None and any(own)
    if mixed:  # (each catalogue rotor carries its own calibrated set, or the vehicle's)
        vehicle = replace(vehicle, rotors=tuple(
            r if r.params is not None or o is None else
            replace(r, params=mine_set if mine_set is not None else default_params(p))
            for r, o, p in zip(vehicle.rotors, own, names)))
    label = "generic" if spec is None else spec  # (a rotor's file: its path from the vehicle's folder)
    # (mixed: every rotor carries its set where the vehicle has one, whose air is the vehicle's; the generic set for
    # the rotors without any otherwise)
    if mine_set is not None and (spec == mine or mixed):
        params = mine_set
    else:  # (a set every rotor names: as the reader read it, its file not read again; a named set otherwise)
        params = next((r.params for r in vehicle.rotors if r.params is not None), None) if spec is not None else None
        params = params if params is not None else resolve_params(label)
    sets = tuple(o or "generic" for o in own) if mixed else (label,) * n
    if len(set(sets)) > 1:
        label = "the vehicle's rotor sets: " + ", ".join(dict.fromkeys(show_path(s) for s in sets))
    return ResolvedVehicle(vehicle, params, label, sets, params.air, body_from)


@dataclass(frozen=True, eq=False)
class _Reading:
    """One reading of a vehicle file (:func:`_reading`): the vehicle as :func:`propmap.read_vehicle`
    reads it, the file, the vehicle's own set's entry (a path from the working directory where it
    is a file beside the vehicle, else a name; None: none), that set and its file's ``[body]``
    table as the reader read and checked them, and each rotor's ``propeller`` and ``params``
    entries (resolved alike)."""

    vehicle: Vehicle
    path: Path
    mine: str | None
    mine_set: object
    mine_table: object
    propellers: tuple
    own: tuple

    def with_own_body(self) -> tuple[Vehicle, str | None]:
        """(the vehicle with its own set's ``[body]`` table in place of its airframe, that set's file
        or None where it has no table): what every resolution without a given set models."""
        table = self.mine_table
        return with_body_table(self.vehicle, table), (None if table is None else self.mine)


def _reading(path) -> _Reading:
    """:class:`_Reading` of the vehicle file ``path`` (one parse of it: resolve_vehicle's, and the
    one-propeller exports', which parsed it six times until 2026-12-01, stop 96)."""
    vehicle, data, path, own_read = _read_vehicle(path)
    folder = path.parent
    mine_set, mine_table = own_read if own_read is not None else (None, None)
    return _Reading(vehicle, path, _resolved_spec(data.get("params"), folder), mine_set, mine_table,
                    _entry_specs(data, folder, "propeller"), _entry_specs(data, folder, "params"))


def _rotor_sets(reading: _Reading) -> tuple:
    """Each rotor's set by the rule (:func:`resolve_vehicle`): its own entry, else the vehicle's own
    set's, else its catalogue propeller's calibrated set's label, else None (the generic set; a
    rotor that names ``generic`` is None too)."""
    from ..io.calibration import default_params
    from ..io.catalogue import catalogue

    own = tuple(o if o is not None else reading.mine if reading.mine is not None else
                default_params(p).label if p in catalogue() else None
                for o, p in zip(reading.own, reading.propellers))
    return tuple(None if o == "generic" else o for o in own)


def _one_propeller_set(reading: _Reading, propeller) -> str | None:
    """The set a one-propeller export of the vehicle takes without a given set (``export-sim
    --vehicle``, ``map --format c --vehicle``), where ``propeller`` is every rotor's geometry: the
    set the rule gives every rotor (:func:`_rotor_sets`; ``"generic"`` where that is the generic
    set), else, where the rotors' sets differ, the vehicle's own set (which the rotors without one
    take); None (the export's own default) where neither is one, or a rotor carries another
    propeller. (The vehicle's set is its rotors', not another propeller's: a review found apce_8x6
    exported with the NeuroBEM rotors' fit. Until 2026-12-01 the vehicle's own set came first,
    and export-sim refused a vehicle whose rotors all name another set, which trim-vehicle hovers
    with; where the rotors' set was fitted at rho 1.0 the export took PROP's default and hovered
    9.9% slower than trim-vehicle, an air-consistency audit. Until 2026-12-01 the exports took a
    set only where the vehicle named one for every rotor: a vehicle of mixed sets was exported
    on calibrated:apce_8x6 at rho 1.225 where its rotors without a set take its own flight fit at
    rho 1.204, and the catalogue apce_8x6's rotors exported from its geometry file on the generic
    set, hovering at 5187.09 rpm where trim-vehicle hovers them at 5386.76 on their calibrated
    set: an audit, stop 96.)"""
    if not all(r.propeller.same_geometry(propeller) for r in reading.vehicle.rotors):
        return None
    sets = {s or "generic" for s in _rotor_sets(reading)}
    return sets.pop() if len(sets) == 1 else reading.mine


def with_set_body(vehicle: Vehicle, spec) -> tuple[Vehicle, str | None]:
    """The vehicle with the ``[body]`` table of the parameter file ``spec`` in place of its airframe.

    Parameters
    ----------
    vehicle : Vehicle
    spec : str, Path or None
        A parameter file (a flight fit's writes the table), a named set or None (no table: the
        vehicle as it is).

    Returns
    -------
    vehicle : Vehicle
        :func:`with_body_table`'s.
    body_from : str or None
        The file whose table replaced the airframe; None where none did.

    Raises
    ------
    propmap.io.params_file.ParamsFileError
        A malformed ``[body]`` table.
    """
    from ..io.params_file import read_body

    if spec is None or not Path(spec).is_file():
        return vehicle, None
    table = read_body(spec)
    return with_body_table(vehicle, table), (None if table is None else str(spec))


def read_vehicle_with_params(path):
    """A vehicle file and its parameter set, resolved as the vehicle commands resolve them.

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
    params : SectionParams
        The set for the rotors without one of their own (the rotors' one set where every rotor's
        is one, else the vehicle's own set, else the generic set; :func:`resolve_vehicle`, whose
        record says more): pass it to :func:`propmap.vehicle_wrench`, :func:`propmap.trim_vehicle`
        or :func:`propmap.hover_omega`, with its air (``params.air``), as the commands do. (Until
        2026-12-01 None where the file names no set of its own, where the commands took the
        rotors' catalogue propeller's calibrated set.)

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
    resolved = resolve_vehicle(path)
    return resolved.vehicle, resolved.params
