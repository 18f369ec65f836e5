"""``propmap trim``: the collective that makes a given thrust at one operating point."""

from __future__ import annotations

import math

import click

from ..core.units import RPM
from ._common import (resolve_air, with_air_options, PARAMS_HELP, RPM_MAX, RPM_MIN, InputError, check_point,
                      air_label, check_section_match, coverage_messages, echo_json, envelope_extremes, load_params,
                      set_collective_deg, with_prop_options)
from .loads import COLLECTIVE_DEG_MAX, FLAG_MEANINGS, UNITS, _descent_outputs, numeric_keys


@click.command("trim")
@click.argument("prop")
@click.option("--thrust", type=float, required=True, help="Thrust to make [N].")
@click.option("--rpm", type=float, required=True, help=f"Rotation rate [rpm], in [{RPM_MIN:g}, {RPM_MAX:.0f}].")
@click.option("--airspeed", type=float, default=0.0, show_default=True, help="Airspeed V [m/s], in [0, 500].")
@click.option("--incidence-deg", type=float, default=0.0, show_default=True,
              help="Angle between freestream and rotor axis [deg]: 0 climb, 90 edgewise, 180 descent.")
@click.option("--range-deg", nargs=2, type=float, default=(-20.0, 30.0), show_default=True,
              help=f"Collectives searched [deg], within [-{COLLECTIVE_DEG_MAX:g}, {COLLECTIVE_DEG_MAX:g}].")
@click.option("--hover-reference", is_flag=True,
              help="Also trim hover to the same thrust and rpm and report dCQ = CQ - CQ_hover.")
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@with_prop_options
@with_air_options
def trim_command(prop, thrust, rpm, airspeed, incidence_deg, range_deg, hover_reference, params_spec, as_json,
                 prop_choice, air_choice):
    """Collective (blade-angle offset) at which PROP makes --thrust.

    The lowest collective in --range-deg that makes the thrust is returned (below stall the
    only one); the output states the branch and how many solutions the search saw.
    """
    from ..core.solver import SolverError
    from ..core.trim import TrimError, torque_change_at_constant_thrust, trim_collective

    check_point(rpm, airspeed, incidence_deg)
    if not math.isfinite(thrust) or abs(thrust) > 1e5:
        raise InputError(f"--thrust must be finite and in [-1e5, 1e5] N, got {thrust!r}")
    lo, hi = range_deg
    if not (-COLLECTIVE_DEG_MAX <= lo < hi <= COLLECTIVE_DEG_MAX):
        raise InputError(f"--range-deg must be two angles LOW < HIGH within [-{COLLECTIVE_DEG_MAX:g}, "
                         f"{COLLECTIVE_DEG_MAX:g}] deg, got {lo!r} {hi!r}")
    propeller = prop_choice.load(prop)
    params, air, label = load_params(params_spec, prop)
    air = resolve_air(air, air_choice)
    check_section_match(propeller, label)
    omega, beta = rpm * RPM, math.radians(incidence_deg)
    bounds = (math.radians(lo), math.radians(hi))
    try:
        res = trim_collective(propeller, params, thrust, omega, airspeed, beta, air=air, bounds=bounds)
        dcq = None
        if hover_reference:
            d, _, _ = torque_change_at_constant_thrust(propeller, params, omega, airspeed, beta,
                                                       collective=float(res.collective), air=air, bounds=bounds)
            dcq = float(d)
    except TrimError as exc:
        raise InputError(f"--thrust: {exc}") from None
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    coverage_messages(propeller, label, air, *envelope_extremes(propeller, rpm, airspeed, incidence_deg), rpm=rpm,
                      airspeed=airspeed)
    r = res.loads
    d = _descent_outputs(r)
    added = math.degrees(float(res.collective))  # (on top of the set's own collective, within --range-deg)
    set_deg = set_collective_deg(params)
    out = {"collective_deg": set_deg + added, "params_collective_deg": set_deg, "added_collective_deg": added,
           "branch": res.branch,
           "solutions_seen": int(res.n_solutions), **{k: float(getattr(r, k)) for k in numeric_keys(params)},
           "CQ": float(r.CQ),
           "dCQ_constant_thrust": dcq, "v_i_over_v_h": _finite(d["v_i_over_v_h"]), "lambda2": _finite(d["lambda2"]),
           "state": str(d["state"]), "flags": r.flags()}
    if as_json:
        echo_json({**out, "propeller": propeller.name, "n_blades": propeller.n_blades,
                   "diameter_m": propeller.diameter, "params": label, "rpm": rpm, "airspeed": airspeed,
                   "incidence_deg": incidence_deg, "thrust_target": thrust, "range_deg": [lo, hi],
                   "air": {"rho": air.rho, "mu": air.mu,
                                                           "speed_of_sound": air.speed_of_sound},
                   "flag_meanings": {f: FLAG_MEANINGS[f] for f in r.flags()},
                   "units": {**{k: u for k, u in UNITS.items() if k in out}, "collective_deg": "deg"}})
        return
    click.echo(f"{propeller.name} at {rpm:g} rpm, V = {airspeed:g} m/s, incidence {incidence_deg:g} deg "
               f"(params {label})")
    click.echo(f"  {propeller.n_blades} blades, D = {propeller.diameter:.4g} m; air: {air_label(air)}")
    click.echo(f"  collective {out['collective_deg']:.4f} deg makes T = {out['thrust']:.4f} N "
               + (f"(the set's {set_deg:g} deg + {added:.4f} deg) " if set_deg else "")
               + f"({res.branch}; {out['solutions_seen']} solution(s) seen in [{lo:g}, {hi:g}] deg added)")
    click.echo(f"  torque Q = {out['torque']:.5f} N m  power P = {out['power']:.2f} W  CQ = {out['CQ']:.5f}")
    click.echo(f"  drag D = {out['drag']:.4f} N  rolling moment M_R = {out['rolling_moment']:.5f} N m"
               + (f"  side force Y = {out['side_force']:.4f} N  pitching moment M_P = {out['pitching_moment']:.5f} N m"
                  if "side_force" in out else ""))
    if dcq is not None:
        click.echo(f"  dCQ at constant thrust (minus hover at the same T and rpm) = {dcq:.5f}")
    ratios = (f" (v_i/v_h = {out['v_i_over_v_h']:.3f}, lambda2 = V_descent/v_h = "
              f"{round(out['lambda2'], 3) + 0.0:.3f})" if out["v_i_over_v_h"] is not None and out["lambda2"] is not None
              else "")  # (as loads says them; no "-0.000")
    click.echo(f"  state: {out['state']}{ratios}  flags: {', '.join(out['flags']) or 'none'}")
    for f in out["flags"]:
        click.echo(f"    {f}: {FLAG_MEANINGS[f]}")


def _finite(x):
    x = float(x)
    return x if math.isfinite(x) else None
