"""``propmap export-sim``: coefficients of simulators' simple rotor models, fitted to propmap."""

from __future__ import annotations

from pathlib import Path

import click

from ..core.units import RPM
from ._air import resolve_air, with_air_options
from ._common import (PARAMS_HELP, Command, InputError, PathArg, check_section_match, echo_json, load_params,
                      run_warnings, warn, with_prop_options)
from ._coverage import coverage_messages, envelope_extremes
from ._paths import check_outputs, vehicle_inputs
from ._sources import catalogue_citation

SUFFIX = {"rotorpy": ".py", "gazebo-classic": ".sdf", "gz-sim": ".sdf", "multinomial": ".json"}
#: --target choices: the targets and their former names (gazebo: the PX4 classic plugin; gill2019: the multinomial)
CHOICES = ["rotorpy", "gazebo-classic", "gz-sim", "multinomial", "gazebo", "gill2019"]
KEYS = {"rpm": "rpm", "airspeed": "airspeed", "incidence_deg": "incidence_deg", "incidence-deg": "incidence_deg"}


def parse_envelope(text: str | None, propeller):
    """``rpm=A:B,airspeed=A:B,incidence_deg=A:B`` (any subset; the rest default; None:
    the default envelope).

    Raises
    ------
    InputError
        Not that form (an empty value or item included), unknown names, a name given
        twice, or ranges outside the model's.
    """
    from dataclasses import replace

    from ..simexport import default_envelope

    env = default_envelope(propeller)
    if text is None:
        return env
    changes = {}
    for part in text.split(","):
        name, _, rng = part.partition("=")
        key = KEYS.get(name.strip().lower())
        if key is None or rng.count(":") != 1:
            raise InputError(f"--envelope: {part.strip()[:60]!r} is not NAME=LOW:HIGH with NAME rpm, airspeed or "
                             "incidence_deg (items separated by commas)")
        if key in changes:
            raise InputError(f"--envelope: {key} given more than once; give one range per name")
        try:
            lo, hi = (float(x) for x in rng.split(":"))
        except ValueError:
            raise InputError(f"--envelope: {part.strip()!r}: LOW and HIGH must be numbers") from None
        changes[key] = (lo, hi)
    if "incidence_deg" in changes:
        from .map import radians_note

        radians_note("--envelope incidence_deg", changes["incidence_deg"][1])
    try:
        return replace(env, **changes)
    except ValueError as exc:
        raise InputError(f"--envelope: {exc}") from None


@click.command("export-sim", cls=Command)
@click.argument("prop")
@click.option("--target", type=click.Choice(CHOICES), required=True,
              help="rotorpy (quad_params keys; a whole quad_params with --vehicle), gazebo-classic (PX4-SITL "
                   "gazebo_motor_model SDF elements), gz-sim (MulticopterMotorModel SDF elements) or multinomial "
                   "(in mu and lambda_c, JSON); gazebo and gill2019 are the former names of gazebo-classic and "
                   "multinomial.")
@click.option("--out", type=PathArg(file=True), required=True,
              help="Coefficient file (.py, .sdf or .json by target); a JSON report <stem>.report.json beside it.")
@click.option("--envelope", default=None,
              help="Fit envelope rpm=A:B,airspeed=A:B,incidence_deg=A:B (default: tip speeds 50-150 m/s, "
                   "0-15 m/s, 0-180 deg).")
@click.option("--hover-rpm", "hover_rpm", type=float, default=None,
              help="Where hover thrust and torque are pinned to the model's [rpm] (default: the vehicle's hover with "
                   "--vehicle, else the geometric mean of the envelope's rpm).")
@click.option("--vehicle", type=PathArg(text=True), default=None,
              help="Vehicle TOML: its hover rpm pins the fit; with --target rotorpy a whole quad_params is written.")
@click.option("--points", "n_points", type=int, default=4000, show_default=True,
              help="Random operating points in the envelope.")
@click.option("--params", "params_spec", default=None,
              help=PARAMS_HELP + " With --vehicle, where PROP is its rotors' propeller: the set the vehicle gives "
                                 "every rotor (the rotors' own params, else the vehicle file's, else their catalogue "
                                 "propeller's calibrated set), else the vehicle file's own params.")
@click.option("--json", "as_json", is_flag=True, help="Print the report as JSON.")
@with_prop_options
@with_air_options
def export_sim_command(prop, target, out, envelope, hover_rpm, vehicle, n_points, params_spec, as_json, prop_choice,
                       air_choice):
    """Fit a simulator's simple rotor model to propmap and report what it costs.

    Hover thrust and torque are pinned to the model's; the speed terms are fitted by least
    squares to the full model over the envelope, each within its physical sign, and each
    load's error against the full model is reported (docs/simulators.md).
    """
    from dataclasses import replace

    from ..simexport import export_sim, report_path, write_export

    target = _checked_target(target, out, n_points)
    check_outputs([("--out", out), ("--out (report)", report_path(out))],
                  [params_spec, prop, vehicle, *vehicle_inputs(vehicle)])
    propeller = prop_choice.load(prop)
    given_spec = params_spec  # (--params as given: its [body] table, else the vehicle file's own set's)
    read = None
    if vehicle is not None:  # (one parse of the file; the vehicle's set for every rotor, where PROP is theirs)
        from ..vehicle.own_set import _one_propeller_set
        from ._vehicle import _export_reading

        read = _export_reading(vehicle, params_spec)
        if params_spec is None:
            params_spec = _one_propeller_set(read[0], propeller)
    params, air, label = load_params(params_spec, prop)
    air = resolve_air(air, air_choice)
    check_section_match(propeller, label)
    env = parse_envelope(envelope, propeller)
    veh, hover_from, airframe = None, "--hover-rpm", ""
    rpm_given = hover_rpm is not None  # (else the vehicle's hover pins it)
    if vehicle is not None and hover_rpm is not None and target != "rotorpy":
        # (cli.md: an option with nothing to do is refused; gz-sim's export pinned 7000 rpm and dropped the vehicle,
        # whose hover is 5140 rpm, without a word: a vehicle-designer audit, 2026-11-28)
        raise InputError(f"--vehicle: with --hover-rpm it has nothing to do in a {target} export (a vehicle pins "
                         "the hover rpm, which --hover-rpm gives; only rotorpy's export writes the vehicle itself): "
                         "give one of them")
    if vehicle is not None:
        veh, hover_rpm, hover_from, airframe = _export_vehicle(read[1:], propeller, params, label, air, target,
                                                               hover_rpm)
        if given_spec is None and hover_from != "--hover-rpm":  # (the rotors' own sets pin the hover)
            from ._vehicle import _warn_rotor_air

            _warn_rotor_air(veh, air, air_choice)
        if target == "rotorpy" and veh.body_drag is not None and veh.body_drag.wash_factor > 0:
            _warn_wash_drag(veh, params, hover_rpm, air)
        if target == "rotorpy" and veh.rotor_interference > 0:  # (said by VehicleMap and the C header, not here
            # until 2026-12-01: a vehicle-model audit)
            warn(f"--vehicle: its rotors' interference (factor {veh.rotor_interference:g}) has no RotorPy term: "
                 "quad_params leave it out, each rotor in the freestream (in hover it changes little: the example "
                 "quadrotor's vertical force by 1e-5 of its weight; at 10 m/s by 0.34% and its pitching moment by "
                 "0.0032 N m)")
    if hover_rpm is not None:
        try:
            env = replace(env, hover_rpm=hover_rpm)
        except ValueError as exc:
            raise InputError(f"{hover_from}: {exc}; widen --envelope rpm=LOW:HIGH") from None
    if veh is not None and target == "rotorpy":  # (after the envelope's check: a hover beyond it is refused alone)
        _warn_rotorpy_limits(veh, hover_rpm, env.rpm[1], own=not rpm_given)
    try:
        res = export_sim(target, propeller, params, air=air, envelope=env, n_points=n_points, params_label=label)
    except ValueError as exc:
        raise InputError(f"--envelope: {exc}") from None
    import numpy as np

    # the envelope beyond the data behind the parameters, after every input check (an error is the only
    # line); the advancing tip is fastest edgewise, so 90 deg is checked where the envelope holds it
    inc = np.unique(np.clip([env.incidence_deg[0], 90.0, env.incidence_deg[1]], *env.incidence_deg))
    coverage_messages(propeller, label, air, *envelope_extremes(
        propeller, np.array(env.rpm)[:, None, None], np.array(env.airspeed)[None, :, None], inc[None, None, :]),
        rpm=tuple(env.rpm), airspeed=float(env.airspeed[1]))
    # (PROP a catalogue name: its geometry and data behind the set, cited in the file and the report; a file of a
    # catalogue propeller's name is the user's own geometry, cited by nothing: a review)
    cited = catalogue_citation(prop)
    if cited:
        res.meta["citation"] = cited
    res.meta["warnings"] = run_warnings()  # (the report's, printed with --json, as every --json output has them)
    files = write_export(res, out, vehicle=veh if target == "rotorpy" else None,
                         vehicle_label=str(vehicle) if vehicle is not None else "", airframe_label=airframe)
    _echo_export(res, target, f"{propeller.name} ({label})", cited, files[1] if as_json else None)
    click.echo("wrote " + ", ".join(str(f) for f in files), err=True)


def _checked_target(target: str, out, n_points: int) -> str:
    """The export's target by its current name (``gill2019`` warned of as ``multinomial``), refusing an
    ``--out`` not named for it or named as a report, and a ``--points`` out of [20, 1000000]."""
    import warnings

    from ..simexport import ALIASES

    if target == "gill2019":
        warnings.warn("--target gill2019 is now called multinomial: its term set is propmap's, not the list of "
                      "Gill & D'Andrea 2019", UserWarning, stacklevel=1)
    target = ALIASES.get(target, target)
    if out.suffix.lower() != SUFFIX[target]:
        raise InputError(f"--out: {out}: the {target} file is named *{SUFFIX[target]}")
    if out.name.lower().endswith(".report.json"):  # (it wrote over another export's report; write_export says so too)
        raise InputError(f"--out: {out}: a name ending in .report.json is an export's report (written beside its "
                         "coefficient file); name the coefficient file otherwise")
    if not 20 <= n_points <= 1_000_000:
        raise InputError(f"--points must be in [20, 1000000], got {n_points}")
    return target


def _echo_export(res, target: str, what: str, cited: str | None, report: Path | None) -> None:
    """The export's coefficients and errors against the full model, as text (``what``: the
    propeller and its parameter set), or with ``report`` (--json) the report file's JSON as
    written (since 2026-11-30: its own record left out the report's other keys, and a NaN two
    levels down, every check point flagged, failed it with exit 2 after the files were written);
    the report holds the run's ``warnings``, as every --json output does (since 2026-12-02)."""
    if report is not None:
        import json

        echo_json(json.loads(report.read_text(encoding="utf-8")))
    else:
        click.echo(f"{target} coefficients of {what}:" + (f"\n  (data: {cited})" if cited else ""))
        for k, v in res.coefficients.items():
            click.echo(f"  {k} = {v}")
        from ..simexport import error_lines

        for line in error_lines(res):
            click.echo(line[1:])  # the empty comment's space


def _export_vehicle(read, propeller, params, label: str, air, target: str, hover_rpm):
    """export-sim's --vehicle: (the vehicle, its hover rpm, where that came from, the airframe's
    label); ``read`` (the vehicle, the file of its ``[body]`` table or None) as
    :func:`propmap.cli._vehicle._export_reading` gives them (the airframe of --params, else of the
    vehicle file's own set, not a rotor's set, as trim-vehicle and wrench take it). Its
    hover pins the export's hover rpm unless --hover-rpm gives it; refused where its rotors
    carry another propeller or their own parameter sets (other than PARAMS) without
    --hover-rpm (their hover is not PROP's with PARAMS), where rotorpy cannot write it, or
    where it hovers beyond tip Mach TIP_MACH_WARN; warned of where --hover-rpm stands in for
    such a hover."""
    import warnings

    from ..core.solver import TIP_MACH_WARN, SolverError
    from ..simexport import check_rotorpy_vehicle
    from ..vehicle import hover_omega

    hover_from, airframe = "--hover-rpm", ""
    # a flight fit's [body] table: its airframe drag (c_D), from --params, else from the vehicle file's own set (its
    # top-level params), whatever propeller is exported: the airframe is the vehicle's (with another PROP its drag
    # was written 0: an air-consistency audit, 2026-12-01), not a rotor's set's (a review)
    veh, body_from = read
    if body_from is not None:
        airframe = f"the [body] table of {Path(body_from).name} (a flight fit)"
    if target == "rotorpy":
        try:
            check_rotorpy_vehicle(veh)
        except ValueError as exc:
            raise InputError(f"--vehicle: {exc}") from None

    def shown(p, rotor=True):  # (a name alone does not tell two readings of one geometry file apart)
        same = rotor and propeller.same_size(p.diameter, p.n_blades, rtol=5e-5)
        return f"{p.name} ({p.diameter:.4g} m, {p.n_blades} blades{', another chord or blade angle' * same})"

    names = sorted({shown(r.propeller) for r in veh.rotors if not r.propeller.same_geometry(propeller)})
    # (the other targets take the rpm without the vehicle: a vehicle with nothing to do is refused above)
    instead = "give --hover-rpm" if target == "rotorpy" else "give --hover-rpm instead of --vehicle"
    if names and hover_rpm is None:
        # (the vehicle's hover with PROP's parameter set on its own propellers is neither's hover)
        raise InputError(f"--vehicle: its rotors carry {', '.join(names)}, not {shown(propeller, False)}, so it "
                         f"cannot pin {propeller.name}'s hover rpm: export the vehicle's propeller, or "
                         f"{instead}")
    if names:
        warnings.warn(f"--vehicle: its rotors carry {', '.join(names)}, not {shown(propeller, False)}: the export "
                      f"gives {propeller.name}'s coefficients on the vehicle's layout, at --hover-rpm", UserWarning,
                      stacklevel=1)
    # (a rotor's own set equal to PARAMS but for its air is PARAMS: every rotor is solved in one air)
    own = [k + 1 for k, r in enumerate(veh.rotors)
           if r.params is not None and not params.same_section(r.params)]
    if own and hover_rpm is None:  # (its hover is that of the rotors' own sets, which the export has not)
        raise InputError(f"--vehicle: rotor(s) {', '.join(map(str, own))} carry their own parameter set, not "
                         f"{label}, so the vehicle's hover is not {propeller.name}'s with it: give --params "
                         f"(the set of every rotor), or {instead.removeprefix('give ')}")
    if own:
        warnings.warn(f"--vehicle: rotor(s) {', '.join(map(str, own))} carry their own parameter set: the export "
                      f"gives {label}'s coefficients on every rotor, at --hover-rpm", UserWarning, stacklevel=1)
    if hover_rpm is None:
        hover_from = "--vehicle (its hover rpm)"
        try:
            hover_rpm = hover_omega(veh, params, air=air) / RPM
        except (ValueError, SolverError) as exc:
            raise InputError(f"--vehicle: its hover rpm: {exc}") from None
        mach = hover_rpm * RPM * max(r.propeller.radius for r in veh.rotors) / air.speed_of_sound
        if mach > TIP_MACH_WARN:  # (the envelope's error said "widen --envelope", which wrote coefficients
            # pinned at tip Mach 4.3 for a mass in grams: a vehicle-designer audit, 2026-11-28)
            raise InputError(f"--vehicle: it hovers at {hover_rpm:.0f} rpm, a blade tip Mach number of "
                             f"{mach:.3g} (> {TIP_MACH_WARN:g}, beyond the model's physics): is its mass "
                             f"({veh.mass:g} kg) in kg, and are its rotors the ones it flies?")
    return veh, hover_rpm, hover_from, airframe


#: RotorPy's Multirotor's gravity [m/s^2] (its dynamics take g = 9.81, whatever the vehicle file says)
ROTORPY_G = 9.81
#: the thrust margin above hover at the written rotor_speed_max below which rotorpy's export warns
ROTORPY_MARGIN = 0.3


def _warn_rotorpy_limits(veh, hover_rpm: float, rpm_max: float, own: bool) -> None:
    """rotorpy's export of a vehicle that hovers near the written rotor_speed_max (the envelope's
    top: a thrust margin (rpm_max / hover)^2 - 1 below ROTORPY_MARGIN, where RotorPy saturates
    on any climb), or whose file's gravity is not RotorPy's ROTORPY_G (hover pinned at the
    file's g sinks or climbs there): warned of (a simulator-user audit, 2026-11-30: a 6 kg
    vehicle pinned at 14,086 rpm against a rotor_speed_max of 14,100, and at g = 9.0 a thrust
    8.3% below the weight, both without a word). ``own``: whether the hover rpm is the vehicle's
    (else --hover-rpm's: then the gravity is not said, the rpm being the user's)."""
    import warnings

    pinned = "it hovers" if own else "its hover pinned by --hover-rpm is"
    margin = (rpm_max / hover_rpm) ** 2 - 1.0
    if margin < ROTORPY_MARGIN:
        warnings.warn(f"--vehicle: {pinned} at {hover_rpm:.0f} rpm, where the written rotor_speed_max "
                      f"({rpm_max:.0f} rpm, the envelope's top) leaves {100 * margin:.1f}% of thrust above hover: "
                      "RotorPy saturates there on any climb; widen --envelope rpm=LOW:HIGH to your motors' top and "
                      "set rotor_speed_max to it", UserWarning, stacklevel=1)
    off = veh.gravity / ROTORPY_G - 1.0
    if own and abs(off) > 2e-3:  # (with --hover-rpm the rpm is the user's, not the file's gravity's)
        warnings.warn(f"--vehicle: its gravity is {veh.gravity:g} m/s^2, RotorPy's Multirotor takes {ROTORPY_G:g}: at "
                      f"the hover rpm pinned for {veh.gravity:g} its thrust in RotorPy is {100 * abs(off):.1f}% "
                      f"{'below' if off < 0 else 'above'} its weight", UserWarning, stacklevel=1)


def _warn_wash_drag(veh, params, hover_rpm: float, air) -> None:
    """rotorpy's export of a vehicle whose airframe drag in the rotors' slipstream (wash_factor > 0)
    pushes it down at the hover rpm: warned of, since RotorPy's quad_params leave it out."""
    import warnings

    import numpy as np

    from ..vehicle import vehicle_wrench

    down = -float(vehicle_wrench(veh, params, np.zeros(3), np.zeros(3),
                                 np.full(len(veh.rotors), hover_rpm * RPM), air=air).body_force[0, 2])
    if down > 5e-4 * veh.weight:  # (a zero vertical drag area makes none: "pushes it down by 0 N", an audit)
        warnings.warn(f"--vehicle: its airframe's drag in the rotors' slipstream (wash_factor "
                      f"{veh.body_drag.wash_factor:g}) pushes it down by {down:.3g} N at the hover rpm "
                      f"({100 * down / veh.weight:.1f}% of its weight), which RotorPy's quad_params (drag of "
                      "the freestream only) leave out: there the exported vehicle's thrust at that rpm exceeds "
                      "its weight by as much", UserWarning, stacklevel=1)
