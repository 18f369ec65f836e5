"""The vehicle file and its parameter sets as the vehicle commands take them (``fit flight``,
``wrench``, ``trim-vehicle``, ``export-sim --vehicle``, ``map --vehicle``): the
file read with its errors as the option's, a flight fit's ``[body]`` table, the rotors' sets
and their coverage."""

from __future__ import annotations

from pathlib import Path

import click

from ..core.units import RPM
from ._air import resolve_air
from ._common import InputError, load_params, warn
from ._coverage import coverage_messages, envelope_extremes


def _vehicle(path: Path):
    from ..vehicle import VehicleFileError, read_vehicle

    try:
        return read_vehicle(path)
    except VehicleFileError as exc:
        raise InputError(f"--vehicle: {exc}") from None


def _check_rotor_sets(veh, labels) -> None:
    """check_section_match for each rotor's propeller and set label, once per pair (a set
    calibrated on another propeller, the generic set on a rotor-like blade: said as `loads` says
    it for one propeller)."""
    from ._common import check_section_match

    for prop, label in dict.fromkeys((r.propeller.name, lab) for r, lab in zip(veh.rotors, labels)):
        check_section_match(next(r.propeller for r in veh.rotors if r.propeller.name == prop), label)


def _default_spec(path, params_spec):
    """``params_spec``, or where it is None the vehicle file's own parameter set (its top-level
    ``params``: vehicle.file), the default of --params in the commands that model the vehicle."""
    from ..vehicle.file import VehicleFileError
    from ..vehicle.own_set import vehicle_params_file

    if params_spec is not None:
        return params_spec
    try:
        return vehicle_params_file(path)
    except VehicleFileError as exc:  # (read_vehicle says the same of the file first, where a command reads it)
        raise InputError(f"--vehicle: {exc}") from None


def _own_spec_for(path, propeller):
    """The vehicle file's own parameter set, or else its rotors' one set (each rotor's ``params``,
    all the same), where ``propeller`` (export-sim's PROP) is every rotor's geometry, else None:
    export-sim's default of --params with --vehicle (the vehicle's set is its rotors', not another
    propeller's; a review found apce_8x6 exported with the NeuroBEM rotors' fit)."""
    from ..vehicle.file import rotor_file_specs

    spec = _default_spec(path, None)
    if not all(r.propeller.same_geometry(propeller) for r in _vehicle(path).rotors):
        return None
    specs = set(rotor_file_specs(path))
    if spec is None and len(specs) == 1 and None not in specs:
        # (the rotors' one set, as trim-vehicle takes it: the export took PROP's default and hovered 9.9% slower
        # than trim-vehicle where the rotors' set was fitted at rho 1.0, an air-consistency audit, 2026-12-01)
        spec = specs.pop()
    return spec


def _fitted_vehicle(path: Path, params_spec, own: bool = True):
    """(vehicle, fitted): the vehicle file's vehicle and, where ``params_spec`` (None, with ``own``:
    the vehicle file's own ``params``) is a parameter file with the ``[body]`` table a flight fit
    writes (the airframe drag, the centre of mass, the rotors' wake interference), the vehicle with
    those in place of the file's, and whether it had one (what `wrench`, `export-sim --vehicle` and
    the C vehicle export all model)."""
    from ..io.params_file import ParamsFileError, read_body
    from ..vehicle.own_set import with_body_table

    veh = _vehicle(path)
    if own:
        params_spec = _default_spec(path, params_spec)
    if params_spec is None or not Path(params_spec).is_file():
        return veh, False
    try:
        table = read_body(params_spec)
    except ParamsFileError as exc:
        raise InputError(f"--params: {exc}") from None
    if table is None:
        return veh, False
    return with_body_table(veh, table), True


def _vehicle_sets(veh, vehicle, params_spec, air_choice):
    """(vehicle, params, air, label, sets) of a command given a vehicle file and --params: with
    --params one set for every rotor (the rotors' own sets dropped, said), else the vehicle's
    rotor sets (one label for all where they are one, each its own otherwise) and, for a rotor
    without one, the vehicle file's own set (its top-level ``params``), else its propeller's
    default as `loads` takes it: a catalogue propeller's calibrated set, else 'generic'
    (``sets``: each rotor's label); each rotor's propeller and set checked as `loads` checks
    them."""
    from dataclasses import replace

    from ..io.calibration import default_params
    from ..io.catalogue import catalogue
    from ..io.inputs import show_path
    from ..vehicle.file import rotor_file_specs

    own, mine, mine_loaded = (), None, None
    if params_spec is None:
        # (a rotor without a set of its own took the generic set where `loads`, `map` and `export-sim`
        # take its catalogue propeller's calibrated one: the example quadrotor's apce_8x6 rotors hovered
        # at 5187 rpm in trim-vehicle and at 5387 rpm in export-sim --vehicle, an audit of stop 90)
        names = rotor_file_specs(vehicle, "propeller")
        mine = _default_spec(vehicle, None)  # (the vehicle's own set before a catalogue propeller's)
        own = tuple(o if o is not None else mine if mine is not None else
                    default_params(n).label if n in catalogue() else None
                    for o, n in zip(rotor_file_specs(vehicle), names))
        own = tuple(None if o == "generic" else o for o in own)
        mine_loaded = load_params(mine, option="--vehicle (its params)") if mine is not None else None
    mine_set = mine_loaded[0] if mine_loaded else None
    spec = params_spec if params_spec is not None else (
        own[0] if own and own[0] is not None and len(set(own)) == 1 else None)
    if spec is None and any(own):  # (mixed: each catalogue rotor carries its own calibrated set, or the vehicle's)
        veh = replace(veh, rotors=[r if r.params is not None or o is None else
                                   replace(r, params=mine_set if mine_set is not None else default_params(n))
                                   for r, o, n in zip(veh.rotors, own, names)])
    # (the vehicle's own set, where it is every rotor's, loaded once)
    params, air, label = (mine_loaded if mine_loaded and spec == mine else
                          load_params("generic" if spec is None else spec, option="--params"))
    if spec is None and mine_set is not None:  # (mixed: the vehicle's own set, fitted at its air, gives the air)
        air = mine_set.air
    sets = [o or "generic" for o in own] if spec is None and any(own) else [label] * len(veh.rotors)
    if len(set(sets)) > 1:
        label = "the vehicle's rotor sets: " + ", ".join(dict.fromkeys(show_path(s) for s in sets))
    _check_rotor_sets(veh, sets)
    air = resolve_air(air, air_choice)
    if params_spec is not None:
        veh = _one_set(veh, "--params gives every rotor's set")
    _warn_rotor_air(veh, air, air_choice)
    return veh, params, air, label, sets


def _warn_rotor_air(veh, air, air_choice) -> None:
    """Without an air option: a warning where a rotor's own parameter set carries other air than
    the one every rotor is solved in (the command's; dropped without a word until 2026-12-01: a
    vehicle's two rotors on a set at rho 1.0 made 25% more thrust than in their own air, an
    air-consistency audit), as vehicle_wrench warns in the API."""
    from ..vehicle.model import rotors_in_other_air

    other = [] if air_choice.options_given() else rotors_in_other_air(veh, air)
    if other:
        warn(f"--vehicle: rotor(s) {', '.join(str(k) for k, _ in other)} carry parameter sets in other air (rho "
             f"{', '.join(f'{r:.4g}' for r in sorted({rho for _, rho in other}))} kg/m^3): every rotor is solved in "
             f"one air, rho {air.rho:.4g} kg/m^3; give --rho (or --altitude-m, --temperature-c with --pressure-pa) "
             "to choose it")


def _one_set(veh, why: str):
    """The vehicle with its rotors' own parameter sets removed (said in a warning), so that one
    set reaches every rotor."""
    from dataclasses import replace

    own = [str(k + 1) for k, r in enumerate(veh.rotors) if r.params is not None]
    if not own:
        return veh
    click.echo(f"propmap: warning: the vehicle file's parameter sets of rotor(s) {', '.join(own)} are not used: {why}",
               err=True)
    return replace(veh, rotors=[replace(r, params=None) for r in veh.rotors])


def _rotor_coverage(veh, sets, loads, air) -> None:
    """coverage_messages for the rotors' operating points (``loads``: per rotor, a list of its
    RotorLoads), once per propeller and set (each rotor's own set where the vehicle file names
    one, with its coverage)."""
    import numpy as np

    for (name, set_label), prop in {(r.propeller.name, k): r.propeller for r, k in zip(veh.rotors, sets)}.items():
        ld = [x for i, r in enumerate(veh.rotors) if r.propeller.name == name and sets[i] == set_label
              for x in loads[i]]
        rpm = np.concatenate([np.ravel(x.omega) for x in ld]) / RPM
        coverage_messages(prop, set_label, air, *envelope_extremes(
            prop, rpm, np.concatenate([np.ravel(x.airspeed) for x in ld]),
            np.degrees(np.concatenate([np.ravel(x.incidence) for x in ld]))),
            rpm=(float(rpm.min()), float(rpm.max())), airspeed=float(max(np.max(x.airspeed) for x in ld)))
