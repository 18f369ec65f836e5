"""The vehicle file and its parameter sets as the vehicle commands take them (``fit flight``,
``wrench``, ``trim-vehicle``, ``export-sim --vehicle``, ``map --vehicle``): the
file read with its errors as the option's, a flight fit's ``[body]`` table, the rotors' sets
and their coverage."""

from __future__ import annotations

import math
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


def _export_reading(path, params_spec):
    """(reading, vehicle, body_from) of --vehicle in a one-propeller export (``export-sim
    --vehicle``, ``map --format c --vehicle``), from one parse of the file (six until 2026-12-01,
    where trim-vehicle parsed it once: an audit, stop 96): the reading
    (:func:`propmap.vehicle.own_set._reading`), the vehicle with the ``[body]`` table a flight fit
    writes (the airframe drag, the centre of mass, the rotors' wake interference) of ``params_spec``
    (--params, where it is a file with one) or without it of the vehicle file's own set, as
    :func:`propmap.resolve_vehicle` takes it, whatever propeller is exported (the airframe is the
    vehicle's, not a rotor set's), and the file whose table it is (None: none); the rotors keep
    the sets the file gives them, but with --params, which gives every rotor's set (the rotors'
    own dropped, said in a warning, as :func:`_vehicle_sets` drops them)."""
    from ..io.params_file import ParamsFileError
    from ..vehicle.file import VehicleFileError
    from ..vehicle.own_set import _reading, with_set_body

    try:
        reading = _reading(path)
    except VehicleFileError as exc:
        raise InputError(f"--vehicle: {exc}") from None
    if params_spec is None:
        return reading, *reading.with_own_body()
    try:
        veh, body_from = with_set_body(reading.vehicle, params_spec)
    except ParamsFileError as exc:
        raise InputError(f"--params: {exc}") from None
    # (--params gives every rotor's set, the rotors' own dropped and said, as trim-vehicle and wrench take it: until
    # stop 96 the exports refused them, export-sim unless --hover-rpm, where trim-vehicle hovered with --params)
    return reading, _one_set(veh, "--params gives every rotor's set"), body_from


def _vehicle_sets(vehicle, params_spec, air_choice):
    """(vehicle, params, air, label, sets) of a command given a vehicle file and --params, as
    :func:`propmap.vehicle.own_set.resolve_vehicle` resolves them (the API's rule): with --params
    one set for every rotor (the rotors' own sets dropped, said) and its ``[body]`` table, else the
    rotors' own sets, the vehicle file's own set (its top-level ``params``, with its ``[body]``
    table), a catalogue propeller's calibrated set, the generic set (``sets``: each rotor's
    label); each rotor's propeller and set checked as `loads` checks them, the air the command's
    options give."""
    from ..vehicle.file import VehicleFileError
    from ..vehicle.own_set import resolve_vehicle

    try:
        r = resolve_vehicle(vehicle, params_spec)  # (the vehicle file read first: its errors before --params's)
    except VehicleFileError as exc:
        raise InputError(f"--vehicle: {exc}") from None
    except (KeyError, ValueError, TypeError, OSError) as exc:  # --params's set or its [body] table
        if params_spec is None:  # (the vehicle's own set: _read_vehicle checked it, so not met today; a review)
            raise InputError(f"--vehicle (its params): {exc}") from None
        load_params(params_spec)  # (its message, as every command's)
        raise InputError(f"--params: {exc}") from None
    _check_rotor_sets(r.vehicle, r.sets)
    air = resolve_air(r.air, air_choice)
    if r.dropped:
        click.echo(f"propmap: warning: the vehicle file's parameter sets of rotor(s) "
                   f"{', '.join(map(str, r.dropped))} are not used: --params gives every rotor's set", err=True)
    _warn_rotor_air(r.vehicle, air, air_choice)
    return r.vehicle, r.params, air, r.label, list(r.sets)


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


def _descent_state_warning(loads, what: str, keep=None) -> list[str]:
    """A warning where samples have a rotor in the vortex-ring or turbulent-wake state
    (``loads``: a vehicle wrench's RotorLoads per rotor, over the samples; ``keep``: a mask of the
    samples counted, default all; ``what`` names them): momentum theory is not predictive there,
    and such samples carry the flight logs' largest force errors (docs/flight.md: on the race
    track 6% of the samples, a mean Fz error of -1.1 N). Said by ``trim-vehicle`` and ``fit loads``
    alike; ``wrench`` and ``fit flight`` said nothing (an audit of faster flights, 2026-12-02)."""
    import numpy as np

    from ..core.states import STATES

    codes = [STATES.index("vortex ring"), STATES.index("turbulent wake")]
    hit = np.any([np.isin(np.ravel(ld.state), codes) for ld in loads], axis=0)
    if keep is not None:
        hit = hit[np.asarray(keep, bool)]
    if not hit.any():
        return []
    return [f"{int(hit.sum())} of {hit.size} samples of {what} ({100 * hit.mean():.1f}%) have a rotor in the "
            "vortex-ring or turbulent-wake state (descending into its own wake), where momentum theory is not "
            "predictive and the model's thrust is least certain (docs/flight.md: Where it is still wrong)"]


def _direction(x: float, y: float) -> str:
    """'front-right', 'left', ... of a hub at (x forward, y left) from the centre."""
    names = ("front", "front-left", "left", "back-left", "back", "back-right", "right", "front-right")
    return names[int(round(math.degrees(math.atan2(y, x)) / 45.0)) % 8]


def _layout_warnings(logs, veh) -> list[str]:
    """A warning per log whose own vehicle geometry (:attr:`FlightLog.rotor_layout`, a PX4 log's
    control allocation) puts a motor elsewhere (more than 30 deg round the centre) or spinning
    the other way than the vehicle file's rotor of that number: the moments would be of other
    rotors (a PX4 audit, 2026-12-02: the example quadrotor's order, front-left first, on a PX4
    quad X, whose motor 1 is front-right, gave 9 times the moment error, the forces unchanged)."""
    import numpy as np

    out = []
    cg = np.asarray(veh.centre_of_mass, float)[:2]
    for log in logs:
        lay = getattr(log, "rotor_layout", None)
        if lay is None or len(lay) != len(veh.rotors):
            continue
        bad = []
        for k, (r, (px, py, spin)) in enumerate(zip(veh.rotors, lay)):
            x, y = np.asarray(r.position, float)[:2] - cg
            turn = abs((math.degrees(math.atan2(y, x) - math.atan2(py, px)) + 180.0) % 360.0 - 180.0)
            own = r.spin * np.sign(r.axis[2]) if abs(r.axis[2]) > 0.9 else spin  # (a tilted rotor: spin unchecked)
            if turn > 30.0 or own != spin:
                bad.append(k)
        if bad:
            def said(x, y, s):
                return f"{_direction(x, y)} {'ccw' if s > 0 else 'cw'}"

            k = bad[0]
            mine = np.asarray(veh.rotors[k].position, float)[:2] - cg
            out.append(f"{log.name}: the log's own geometry (PX4's CA_ROTORn_PX, _PY, _KM) has motors 1..{len(lay)} "
                       f"{', '.join(said(*row) for row in lay)}; the vehicle file's rotor {k + 1} is "
                       f"{said(mine[0], mine[1], veh.rotors[k].spin * np.sign(veh.rotors[k].axis[2]))}"
                       + (f" ({len(bad)} rotors differ)" if len(bad) > 1 else "") + ": list the vehicle's rotors in "
                       "the log's motor order, or its moments are of other rotors")
    return out
