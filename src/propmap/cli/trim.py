"""``propmap trim``: the collective (or the rotation rate) that makes a given thrust at one
operating point."""

from __future__ import annotations

import math

import click

from ..core.units import RPM
from ._air import air_label, air_record, resolve_air, with_air_options
from ._common import (PARAMS_HELP, RPM_MAX, RPM_MIN, Command, InputError, check_point, check_section_match, echo_json,
                      fixed, geometry_label, geometry_record, load_params, set_collective_deg, warn,
                      warn_incidence_radians, with_prop_options)
from ._coverage import coverage_messages, envelope_extremes
from .loads import COLLECTIVE_DEG_MAX, FLAG_MEANINGS, UNITS, _descent_outputs, numeric_keys

#: the collectives searched by default [deg] (trim_collective's default bounds)
RANGE_DEG = (-20.0, 30.0)


@click.command("trim", cls=Command)
@click.argument("prop")
@click.option("--thrust", type=float, required=True, help="Thrust to make [N].")
@click.option("--rpm", type=float, default=None,
              help=f"Rotation rate [rpm], in [{RPM_MIN:g}, {RPM_MAX:.0f}]: the collective is trimmed. Without it the "
                   "rpm is trimmed, at the parameter set's collective.")
@click.option("--airspeed", type=float, default=0.0, show_default=True, help="Airspeed V [m/s], in [0, 500].")
@click.option("--incidence-deg", type=float, default=0.0, show_default=True,
              help="Angle between the rotor's velocity through the air and its axis [deg]: 0 climb, 90 edgewise, "
                   "180 descent.")
@click.option("--range-deg", nargs=2, type=float, default=None,
              help=f"Collectives searched [deg], within [-{COLLECTIVE_DEG_MAX:g}, {COLLECTIVE_DEG_MAX:g}] (with --rpm; "
                   f"default {RANGE_DEG[0]:g} {RANGE_DEG[1]:g}).")
@click.option("--rpm-range", nargs=2, type=float, default=None,
              help=f"Rotation rates searched [rpm], within (0, {RPM_MAX:.0f}] (without --rpm; default the rates of a "
                   "tip speed of 1 m/s to Mach 0.9).")
@click.option("--hover-reference", is_flag=True,
              help="Also trim hover to the same thrust and rpm and report dCQ = CQ - CQ_hover.")
@click.option("--params", "params_spec", default=None, help=PARAMS_HELP)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@with_prop_options
@with_air_options
def trim_command(prop, thrust, rpm, airspeed, incidence_deg, range_deg, rpm_range, hover_reference, params_spec,
                 as_json, prop_choice, air_choice):
    """Collective (blade-angle offset) at which PROP makes --thrust at --rpm; without --rpm,
    the rpm at which it makes --thrust.

    The lowest collective in --range-deg (or the lowest rpm in --rpm-range) that makes the
    thrust is returned (below stall, and in still air or climb, the only one); the output
    states the branch and how many solutions the search saw.
    """
    from ..core.trim import default_omega_bounds

    solve_rpm = rpm is None
    lo, hi = _check_options(thrust, rpm, airspeed, incidence_deg, range_deg, rpm_range)
    warn_incidence_radians(incidence_deg, airspeed)
    propeller = prop_choice.load(prop)
    params, air, label = load_params(params_spec, prop)
    air = resolve_air(air, air_choice)
    check_section_match(propeller, label)
    beta = math.radians(incidence_deg)
    bounds = (math.radians(lo), math.radians(hi))
    res, omega, added, dcq = _trim(propeller, params, air, thrust, rpm, airspeed, beta, rpm_range, bounds,
                                   hover_reference)
    rpm = omega / RPM if solve_rpm else rpm
    coverage_messages(propeller, label, air, *envelope_extremes(propeller, rpm, airspeed, incidence_deg), rpm=rpm,
                      airspeed=airspeed)
    r = res.loads
    d = _descent_outputs(r)
    set_deg = set_collective_deg(params)
    out = {"solved_for": "rpm" if solve_rpm else "collective", "rpm": rpm,
           "collective_deg": set_deg + added, "params_collective_deg": set_deg, "added_collective_deg": added,
           "branch": _branch(res),
           "solutions_seen": int(res.n_solutions), **{k: float(getattr(r, k)) for k in numeric_keys(params)},
           "dCQ_constant_thrust": dcq, "v_i_over_v_h": _finite(d["v_i_over_v_h"]), "lambda2": _finite(d["lambda2"]),
           "state": str(d["state"]), "flags": r.flags()}
    searched = ({"rpm_range": list(rpm_range) if rpm_range is not None else
                 [w / RPM for w in default_omega_bounds(propeller, air)]} if solve_rpm else {"range_deg": [lo, hi]})
    if as_json:
        echo_json({**out, "propeller": propeller.name, "n_blades": propeller.n_blades, **geometry_record(propeller),
                   "diameter_m": propeller.diameter, "params": label, "airspeed": airspeed,
                   "incidence_deg": incidence_deg, "thrust_target": thrust, **searched,
                   "air": air_record(air),
                   "flag_meanings": {f: FLAG_MEANINGS[f] for f in r.flags()},
                   "units": {**{k: u for k, u in UNITS.items() if k in out}, "collective_deg": "deg",
                             "rpm": "rpm"}})
        return
    _echo_text(propeller, label, air, out, searched, airspeed, incidence_deg, omega)


def _check_options(thrust, rpm, airspeed, incidence_deg, range_deg, rpm_range) -> tuple[float, float]:
    """The refusals of the trim's options, before any input is read; returns --range-deg's
    (LOW, HIGH) [deg], the default where it is not given."""
    solve_rpm = rpm is None
    check_point(RPM_MIN if solve_rpm else rpm, airspeed, incidence_deg)  # (no --rpm: the rate is solved below)
    if not math.isfinite(thrust) or abs(thrust) > 1e5:
        raise InputError(f"--thrust must be finite and in [-1e5, 1e5] N, got {thrust!r}")
    if solve_rpm and range_deg is not None:
        raise InputError("--range-deg: the collective is trimmed only at a given --rpm; without --rpm the rpm is "
                         "trimmed (search range: --rpm-range)")
    if not solve_rpm and rpm_range is not None:
        raise InputError("--rpm-range: with --rpm the collective is trimmed (search range: --range-deg); leave "
                         "--rpm out to trim the rpm")
    lo, hi = range_deg if range_deg is not None else RANGE_DEG
    if not (-COLLECTIVE_DEG_MAX <= lo < hi <= COLLECTIVE_DEG_MAX):
        raise InputError(f"--range-deg must be two angles LOW < HIGH within [-{COLLECTIVE_DEG_MAX:g}, "
                         f"{COLLECTIVE_DEG_MAX:g}] deg, got {lo!r} {hi!r}")
    if rpm_range is not None and not (0 < rpm_range[0] < rpm_range[1] <= RPM_MAX):
        raise InputError(f"--rpm-range must be two rates LOW < HIGH within (0, {RPM_MAX:.0f}] rpm, got "
                         f"{rpm_range[0]!r} {rpm_range[1]!r}")
    return lo, hi


def _trim(propeller, params, air, thrust, rpm, airspeed, beta, rpm_range, bounds, hover_reference):
    """The trim: the rpm (no --rpm) or the collective that makes the thrust, and with
    --hover-reference the torque change at constant thrust. Returns (result, omega [rad/s],
    the collective added [deg], dCQ or None); an unreachable thrust is an InputError."""
    from ..core.solver import SolverError
    from ..core.torque_change import torque_change_at_constant_thrust
    from ..core.trim import TrimError, trim_collective, trim_omega

    solve_rpm = rpm is None
    try:
        if solve_rpm:
            res = trim_omega(propeller, params, thrust, airspeed, beta, air=air,
                             bounds=None if rpm_range is None else (rpm_range[0] * RPM, rpm_range[1] * RPM))
            omega, added = float(res.omega), 0.0
        else:
            omega = rpm * RPM
            res = trim_collective(propeller, params, thrust, omega, airspeed, beta, air=air, bounds=bounds)
            added = math.degrees(float(res.collective))  # (on top of the set's own collective, within --range-deg)
    except TrimError as exc:
        raise InputError(f"--thrust: {exc}") from None
    except SolverError as exc:
        raise click.ClickException(str(exc)) from None
    if _falls(res):
        warn(f"the range holds no collective at which the thrust rises through {thrust:g} N: the one returned makes it "
             "where the thrust falls as the collective rises (the set is stalled there; docs/models.md, Collective "
             "pitch as an input, and trim)")
    dcq = None
    if hover_reference:
        # (its own failure said as the hover reference's: it was said as --thrust's, of a point at 0 m/s the user did
        # not ask for, and the trim found was lost; a user-level audit, 2026-12-01)
        try:
            d, _, hover = torque_change_at_constant_thrust(propeller, params, omega, airspeed, beta,
                                                           collective=math.radians(added), air=air, bounds=bounds)
        except TrimError as exc:
            raise InputError(f"--hover-reference: the hover at the same rpm and thrust, the reference of dCQ, cannot "
                             f"be trimmed: {exc}") from None
        except SolverError as exc:
            raise click.ClickException(f"--hover-reference: {exc}") from None
        dcq = float(d)
        if _falls(hover):  # (said, as the trim's own: a review, 2026-12-01)
            warn(f"--hover-reference: hover at {omega / RPM:.6g} rpm makes {thrust:g} N, nearest the operating "
                 "collective, where the thrust falls as the collective rises (the set stalled there): dCQ is taken "
                 "against that stalled hover")
    return res, omega, added, dcq


def _falls(res) -> bool:
    """Whether ``res``, a trim's result at one point, is a collective trim's falling branch."""
    return getattr(res, "falling", None) is not None and bool(res.falling)


def _branch(res) -> str:
    """The branch of ``res`` (a trim's result at one point) in words."""
    from ..core.trim import FALLING_BRANCH

    return FALLING_BRANCH if _falls(res) else res.branch


def _echo_text(propeller, label, air, out: dict, searched: dict, airspeed, incidence_deg, omega) -> None:
    """The trim's text output, from its JSON fields ``out`` and the searched range."""
    rpm, set_deg, added = out["rpm"], out["params_collective_deg"], out["added_collective_deg"]
    click.echo(f"{propeller.name} at {rpm:g} rpm, V = {airspeed:g} m/s, incidence {incidence_deg:g} deg "
               f"(params {label})")
    click.echo(f"  {propeller.n_blades} blades, D = {propeller.diameter:.4g} m, {geometry_label(propeller)}; air: "
               f"{air_label(air)}")
    if out["solved_for"] == "rpm":
        a, b = searched["rpm_range"]
        click.echo(f"  {rpm:.1f} rpm ({omega:.4g} rad/s) makes T = {fixed(out['thrust'], 4)} N at collective "
                   f"{set_deg:g} deg ({out['branch']}; {out['solutions_seen']} solution(s) seen in [{a:.6g}, {b:.6g}] "
                   "rpm)")
    else:
        click.echo(f"  collective {out['collective_deg']:.4f} deg makes T = {fixed(out['thrust'], 4)} N "
                   + (f"(the set's {set_deg:g} deg + {added:.4f} deg) " if set_deg else "")
                   + f"({out['branch']}; {out['solutions_seen']} solution(s) seen in "
                   f"[{searched['range_deg'][0]:g}, {searched['range_deg'][1]:g}] deg added)")
    click.echo(f"  torque Q = {fixed(out['torque'], 5)} N m  power P = {fixed(out['power'], 2)} W  "
               f"CQ = {fixed(out['CQ'], 5)}")
    click.echo(f"  drag D = {fixed(out['drag'], 4)} N  rolling moment M_R = {fixed(out['rolling_moment'], 5)} N m"
               + (f"  side force Y = {fixed(out['side_force'], 4)} N  pitching moment M_P = "
                  f"{fixed(out['pitching_moment'], 5)} N m"
                  if "side_force" in out else ""))
    if out["dCQ_constant_thrust"] is not None:
        click.echo("  dCQ at constant thrust (minus hover at the same T and rpm) = "
                   f"{fixed(out['dCQ_constant_thrust'], 5)}")
    ratios = (f" (v_i/v_h = {out['v_i_over_v_h']:.3f}, lambda2 = V_descent/v_h = "
              f"{round(out['lambda2'], 3) + 0.0:.3f})" if out["v_i_over_v_h"] is not None and out["lambda2"] is not None
              else "")  # (as loads says them; no "-0.000")
    click.echo(f"  state: {out['state']}{ratios}  flags: {', '.join(out['flags']) or 'none'}")
    for f in out["flags"]:
        click.echo(f"    {f}: {FLAG_MEANINGS[f]}")


def _finite(x):
    x = float(x)
    return x if math.isfinite(x) else None
