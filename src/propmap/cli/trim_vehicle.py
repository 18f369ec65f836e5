"""``propmap trim-vehicle``: a multirotor's attitude, rotor speeds and power in steady straight
flight at one or more airspeeds (:func:`propmap.trim_vehicle`)."""

from __future__ import annotations

import math

import click

from ..core.units import RPM
from ._air import air_label, air_record, with_air_options
from ._common import Command, InputError, PathArg, echo_json

#: the most airspeeds one call trims (each about 0.1 s)
MAX_SPEEDS = 200


def _speeds(text: str) -> list:
    """--airspeed's comma-separated speeds [m/s]; an empty item (a stray comma) is refused, as
    every comma list's is (docs/cli.md; it was dropped until 2026-12-01, a user-level audit)."""
    items = [v.strip() for v in str(text).split(",")]
    if "" in items:
        raise InputError(f"--airspeed: an empty speed in {str(text)[:60]!r}" + (" (a stray comma?)" if "," in str(text)
                                                                                else ": give 1 or more speeds"))
    try:
        out = [float(v) for v in items]
    except ValueError:
        out = []
    if not out or len(out) > MAX_SPEEDS or not all(math.isfinite(v) and 0.0 <= v <= 100.0 for v in out):
        raise InputError(f"--airspeed must be 1 to {MAX_SPEEDS} comma-separated speeds in [0, 100] m/s (e.g. "
                         f"0,5,10), got {str(text)[:60]!r}")
    return out


@click.command("trim-vehicle", cls=Command)
@click.option("--vehicle", type=PathArg(text=True), required=True,
              help="Vehicle TOML, or a bundled example's name (quadrotor, neurobem_quadrotor).")
@click.option("--airspeed", "airspeed", default="0", show_default=True,
              help="Speed(s) along the flight path [m/s], comma-separated, each in [0, 100].")
@click.option("--climb-rate", "climb_rate", type=float, default=0.0, show_default=True,
              help="Vertical part of the speed [m/s], up positive, |climb rate| <= each airspeed.")
@click.option("--params", "params_spec", default=None,
              help="Parameter set (a file, e.g. from fit flight, or a named set); default: the vehicle's rotor sets, "
                   "else the vehicle file's own params, else each rotor's catalogue propeller's calibrated set, else "
                   "'generic'.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@with_air_options
def trim_vehicle_command(vehicle, airspeed, climb_rate, params_spec, as_json, air_choice):
    """Roll, pitch, rotor speeds and shaft power of the --vehicle in steady straight flight,
    nose first, in still air (docs/flight.md, Hover and trim in steady flight).

    Roll is right side down positive, pitch nose up positive; the rotors in the file's order.
    """
    from ..core.solver import SolverError
    from ..vehicle import trim_vehicle
    from ._vehicle import _rotor_coverage, _vehicle_sets

    speeds = _speeds(airspeed)
    if not math.isfinite(climb_rate) or abs(climb_rate) > min(speeds):
        slow = min(speeds)
        raise InputError(f"--climb-rate must be a speed within [{-slow if slow else 0.0:g}, {slow:g}] m/s (at most "
                         f"the slowest --airspeed), got {climb_rate!r}")
    # (a flight fit's [body] table: its airframe, as wrench takes it; air: the command's Air)
    veh, params, air, label, sets = _vehicle_sets(vehicle, params_spec, air_choice)
    rows, trims = [], []
    for V in speeds:
        try:
            t = trim_vehicle(veh, params, V, climb_rate, air=air)
        except ValueError as exc:
            raise InputError(f"--airspeed {V:g}: {exc}") from None
        except SolverError as exc:
            raise click.ClickException(str(exc)) from None
        _refuse_supersonic(veh, t, V, air)
        trims.append(t)
        rows.append({"airspeed": V, "climb_rate": climb_rate, "roll_deg": math.degrees(t.roll),
                     "pitch_deg": math.degrees(t.pitch), "rotor_rpm": [float(w) / RPM for w in t.rotor_omega],
                     "power_W": t.power})
    # the rotors' operating points beyond the data behind their sets, and a fast tip (the CLI keeps the API's
    # tip-Mach warning to itself: _coverage.coverage_messages says it, from Mach 0.7)
    _rotor_coverage(veh, sets, [[t.wrench.loads[i] for t in trims] for i in range(len(veh.rotors))],
                    air)
    if as_json:
        echo_json({"vehicle": str(vehicle), "params": label, "rotor_params": list(sets), "mass_kg": veh.mass,
                   "rho_kg_m3": air.rho, "air": air_record(air), "trims": rows,
                   "units": {"airspeed": "m/s", "climb_rate": "m/s", "roll_deg": "deg", "pitch_deg": "deg",
                             "rotor_rpm": "rpm", "power_W": "W"}})
        return
    n = len(veh.rotors)
    click.echo(f"{veh.name or vehicle}: {veh.mass:g} kg, {n} rotors (params {label}); steady flight, climb rate "
               f"{climb_rate:g} m/s; air: {air_label(air)}")
    click.echo(f"{'V [m/s]':>8}{'roll [deg]':>12}{'pitch [deg]':>13}" + "".join(f"{f'rotor {k + 1} [rpm]':>16}"
                                                                            for k in range(n)) + f"{'power [W]':>11}")
    for r in rows:
        click.echo(f"{r['airspeed']:>8g}{round(r['roll_deg'], 3) + 0.0:>12.3f}{round(r['pitch_deg'], 3) + 0.0:>13.3f}"
                   + "".join(f"{w:>16.1f}" for w in r["rotor_rpm"]) + f"{r['power_W']:>11.2f}")


def _refuse_supersonic(veh, trim, V: float, air) -> None:
    """Refuse a trim whose advancing blade tips (Omega R + V) turn faster than sound (beyond the
    model's physics): the vehicle's mass in grams, or rotors not the ones it flies (the bundled
    NeuroBEM quadrotor with its mass written as 772 trimmed at 242,803 rpm and 2.48 MW, exit 0:
    a flight-log audit, 2026-11-30; `wrench` and `export-sim` refuse such a vehicle)."""
    # (the advancing tip, Omega R + V, as the library's warning takes it: a review)
    mach = max(float(w) * r.propeller.radius + V for w, r in zip(trim.rotor_omega, veh.rotors)) / air.speed_of_sound
    if mach > 1.0:
        rpm = max(float(w) for w in trim.rotor_omega) / RPM
        raise InputError(f"--airspeed {V:g}: the rotors turn at up to {rpm:.0f} rpm, a blade tip Mach number of "
                         f"{mach:.3g} (supersonic, beyond the model's physics): is the vehicle's mass ({veh.mass:g} "
                         "kg) in kg, and are its rotors the ones it flies?")
