"""The vehicle file's plausibility warnings: a layout in other units than the file's, rotors at
one position, pointing down beside others up, all spinning one way, or whose disks overlap
(moved from vehicle/file.py, which had reached 613 lines; :func:`propmap.vehicle.read_vehicle`
calls :func:`_warn_implausible`)."""

from __future__ import annotations

import math

import numpy as np


#: a rotor farther from the centre of mass than this many of its radii is warned about (a multirotor's arms are
#: 1-3 radii long, the NeuroBEM quadrotor's 2.0, a helicopter's tail rotor about 11; positions in mm read as m are
#: 1000 times that)
ARM_RADII_MAX = 20.0
#: the inertia's largest principal moment is warned about outside these multiples of mass x (largest arm)^2 (a
#: quadrotor's 0.2-0.6: the NeuroBEM vehicle's 0.33; an inertia in g cm^2 is 1e7 times kg m^2)
INERTIA_ARM_RANGE = (1e-3, 10.0)


def _warn_implausible(name: str, rotors, mass: float, inertia, cg, interference: float = 0.0) -> None:
    """Warn about a layout in other units than the file's (ARM_RADII_MAX, INERTIA_ARM_RANGE, a
    rotor inertia above m R^2), rotors at one position, rotors pointing down beside others up, and
    rotors whose disks overlap (_warn_overlap): read as given, they make every moment, or the
    hover's power, wrong without an error."""
    import warnings

    arms = [float(np.linalg.norm(r.position - cg)) for r in rotors]
    far = False
    for k, (r, arm) in enumerate(zip(rotors, arms), start=1):
        if arm > ARM_RADII_MAX * r.propeller.radius:
            far = True
            warnings.warn(f"{name}: rotor {k}'s hub lies {arm:.4g} m from the centre of mass, "
                          f"{arm / r.propeller.radius:.3g} of its radii: are the positions in metres?", UserWarning,
                          stacklevel=4)
            break
    for k in range(len(rotors)):
        for j in range(k + 1, len(rotors)):
            if np.array_equal(rotors[k].position, rotors[j].position):
                warnings.warn(f"{name}: rotors {k + 1} and {j + 1} have the same position "
                              f"{rotors[k].position.tolist()} m (a coaxial pair lies apart along its axis)",
                              UserWarning, stacklevel=4)
    _warn_overlap(name, rotors, interference)
    axes = np.array([r.axis for r in rotors])
    parallel = bool(np.all(axes @ axes[0] > math.cos(math.radians(10.0))))
    if len(rotors) >= 4 and parallel and len({r.spin for r in rotors}) == 1:  # (a multirotor all one way: an audit;
        # not a helicopter's tail rotor or a tricopter's tilting one, which balance yaw by thrust)
        warnings.warn(f"{name}: every rotor spins {'ccw' if rotors[0].spin > 0 else 'cw'}: their torques cannot "
                      "balance in yaw (a multirotor's alternate, cw and ccw); is a spin mistyped?", UserWarning,
                      stacklevel=4)
    units = np.array([a / np.linalg.norm(a) for a in axes])
    down = [k + 1 for k, a in enumerate(units) if a[2] < -math.cos(math.radians(45.0))]
    up = [k + 1 for k, a in enumerate(units) if a[2] > math.cos(math.radians(45.0))]
    if down and up:  # (one such rotor was accepted unsaid, and fitted: an audit; a pusher's downthrust is not it)
        warnings.warn(f"{name}: rotor(s) {', '.join(map(str, down))} point down (within 45 deg of -z) while rotor(s) "
                      f"{', '.join(map(str, up))} point up: a sign slipped (the axis is the thrust's direction, body z "
                      "up)?", UserWarning, stacklevel=4)
    heavy = [k + 1 for k, r in enumerate(rotors) if r.inertia and r.inertia > mass * r.propeller.radius**2]
    if heavy:  # (94 for the 9.4e-6 kg m^2 of a rotor in g cm^2: 26,500 N m of gyroscopic pitch, unsaid: an audit)
        warnings.warn(f"{name}: rotor(s) {', '.join(map(str, heavy))} have an inertia above the vehicle's mass at the "
                      "blade tip (m R^2), which no rotor has: is it in kg m^2?", UserWarning, stacklevel=4)
    reach = max(arms)
    if inertia is not None and reach > 0 and not far:  # (beside arms in other units, the inertia's ratio says nothing)
        ratio = float(np.max(np.linalg.eigvalsh(inertia))) / (mass * reach**2)
        lo, hi = INERTIA_ARM_RANGE
        if not lo <= ratio <= hi:
            warnings.warn(f"{name}: the inertia's largest principal moment is {ratio:.3g} times the mass times the "
                          f"largest arm squared ({mass:g} kg x ({reach:.4g} m)^2), where a multirotor's is "
                          "0.2-0.6: is the mass in kg and the inertia in kg m^2?", UserWarning, stacklevel=4)


#: rotors whose axes lie within this angle of parallel (or antiparallel) are checked for overlapping disks (the
#: interference model's own limit for rotors that interact, docs/models.md)
OVERLAP_AXES_DEG = 8.0


def _warn_overlap(name: str, rotors, interference: float) -> None:
    """Warn once about the pairs of rotors with (anti)parallel axes, within OVERLAP_AXES_DEG, whose
    disks overlap seen along them (hubs closer across the axis than the sum of their radii;
    rotors at one position are warned of apart): in one plane their blades would strike (a
    diameter or a position in another unit); apart along the axis, a coaxial or overlapping
    pair, which the vehicle model solves as isolated rotors (a vehicle-designer audit,
    2026-11-28: an X8's lower rotors made the thrust of isolated ones, without a word). Pairs
    of other axes (a lift rotor and a pusher) are not judged: seen along one axis or the other
    they overlap or not (a review)."""
    import warnings

    strike, stacked = [], []
    for k in range(len(rotors)):
        for j in range(k + 1, len(rotors)):
            a, b = rotors[k], rotors[j]
            if abs(float(a.axis @ b.axis)) < math.cos(math.radians(OVERLAP_AXES_DEG)):
                continue
            d = b.position - a.position
            along = float(d @ a.axis)
            across = float(np.linalg.norm(d - along * a.axis))
            reach = a.propeller.radius + b.propeller.radius
            if np.array_equal(a.position, b.position) or across >= reach:
                continue
            pair = f"{k + 1} and {j + 1} ({across:.3g} m apart across the axis, {abs(along):.3g} m along it)"
            (strike if abs(along) < 0.05 * reach else stacked).append(pair)
    if strike:
        warnings.warn(f"{name}: the disks of rotors {'; '.join(strike)} overlap in one plane, closer than the sum of "
                      "their radii, so their blades would strike: is a diameter or a position in another unit?",
                      UserWarning, stacklevel=5)
    if stacked:
        how = ("rotor_interference models such pairs outside its accuracy (their disks cut each other's wake wall: "
               "docs/models.md)" if interference else
               "each rotor is solved as if alone (rotor_interference, off here, models them only roughly)")
        warnings.warn(f"{name}: rotors {'; '.join(stacked)} overlap seen along the axis (a coaxial or overlapping "
                      f"pair): {how}, so the downstream rotor's loss in the other's wake is missing or rough, and "
                      "the hover power comes out low (momentum theory puts a coaxial pair's induced power 26-41% "
                      "above that of two isolated rotors: J. G. Leishman, Principles of Helicopter Aerodynamics, "
                      "2nd ed., 2006, Ch. 2)", UserWarning, stacklevel=5)
