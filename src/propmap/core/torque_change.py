"""The descent literature's dCQ (:func:`torque_change_at_constant_thrust`): the torque
coefficient at an operating point minus the one in hover at the same thrust and rotation rate
(the hover reference trimmed with the collective, core/trim.py's :func:`trim_collective`, on the
branch nearest the operating point's), the quantity the measured descent data tabulate (e.g.
Castles & Gray, NACA TN 2474, 1951, who derive the induced velocity from it).
"""

from __future__ import annotations

import math

import numpy as np

from ._crossing import _check_on_missing, _nan_where_missing, _tolerances, _where
from .airfoil import Air, SectionParams
from .flapping import flapping_warning_held
from .geometry import Propeller
from .solver import DEFAULT_DISCRETIZATION, Discretization, model_air, rotor_loads
from .trim import TrimError, TrimResult, _check_bounds, trim_collective
from .units import RPM

__all__ = ["NEAREST_BRANCH", "torque_change_at_constant_thrust"]


def torque_change_at_constant_thrust(
    propeller: Propeller,
    params: SectionParams,
    omega,
    airspeed,
    incidence,
    *,
    collective=None,
    air: Air | None = None,
    discretization: Discretization = DEFAULT_DISCRETIZATION,
    bounds=(-math.radians(20.0), math.radians(30.0)),
    on_missing: str = "raise",
):
    """dCQ: CQ at an operating point minus CQ in hover at the same thrust and Omega.

    The hover point is trimmed with the collective (:func:`trim_collective`) to the thrust
    the rotor makes at the operating point; CQ = Q / (rho n^2 D^5) in the propeller
    convention. Negative dCQ: the descent gives the rotor power (ideal autorotation where
    CQ itself reaches 0).

    Parameters
    ----------
    propeller, params, omega, airspeed, incidence, air, discretization
        As in :func:`propmap.rotor_loads`.
    collective : float or array_like, optional
        The operating point's blade-angle offset [rad].
    bounds : (float, float)
        Collectives searched for the hover trim [rad].
    on_missing : {"raise", "nan"}
        Where hover makes the operating point's thrust at no collective in ``bounds`` (no hover
        reference): raise TrimError (default), or return NaN dCQ there (``hover.n_solutions`` 0,
        its collective and loads NaN).

    Returns
    -------
    (dCQ, loads, hover) : (ndarray, RotorLoads, TrimResult)
        dCQ of the broadcast shape, the loads at the operating point and the hover trim (its
        ``falling`` set where hover makes the thrust only where it falls as the collective
        rises, the stalled branch: :func:`trim_collective`'s rule). Where hover makes the
        thrust at more than one collective in ``bounds`` (a set that stalls: the thrust peaks
        and falls with the collective), the hover reference is the one nearest the operating
        point's ``collective`` (:data:`NEAREST_BRANCH`, ``hover.branch``): continuous with
        the operating point from hover, where dCQ = 0 (until 2026-12-01 the lowest, on
        another branch: dCQ 10% of CQ in hover); its ``falling`` then says where the hover
        thrust falls as the collective rises at that collective (the stalled side), whether
        or not a rising crossing exists too.

    Raises
    ------
    ValueError, propmap.SolverError
        As :func:`trim_collective`; ValueError also for an ``omega`` of 0 (CQ undefined).
    TrimError
        With ``on_missing="raise"``, where no hover collective in ``bounds`` makes the thrust
        of an operating point (e.g. a negative thrust in the windmill brake, or a slow descent's
        thrust above the most hover makes at that Omega): the message names the operating point.
    """
    air = model_air(params, air)
    _check_on_missing(on_missing)
    loads = rotor_loads(propeller, params, omega, airspeed, incidence, collective=collective, air=air,
                        discretization=discretization)
    if np.any(loads.omega <= 0):  # (CQ = Q / (rho n^2 D^5) has no value at rest: a silent NaN once)
        raise ValueError("omega must be > 0 rad/s: the torque coefficient of a stopped rotor is undefined")
    hover = trim_collective(propeller, params, loads.thrust, loads.omega, 0.0, 0.0, air=air,
                            discretization=discretization, bounds=bounds, on_missing="nan")
    missing = np.asarray(hover.n_solutions).reshape(-1) == 0
    if missing.any() and on_missing == "raise":  # (the hover trim's own error named its airspeed 0 and incidence 0
        # where the caller's descent was 1 m/s at 180 deg: an export audit)
        i, (lo, hi) = int(np.argmax(missing)), _check_bounds(bounds)
        om, V, b, T = (np.broadcast_to(a, np.shape(loads.thrust)).reshape(-1)[i]
                       for a in (loads.omega, loads.airspeed, loads.incidence, loads.thrust))
        # (the hover thrust's span over the bounds at that rate, for the cause: a climb's thrust below the least was
        # said as a descent's above the most, a review)
        with flapping_warning_held():
            span = rotor_loads(propeller, params, om, 0.0, 0.0, collective=np.linspace(lo, hi, SPAN_NODES), air=air,
                               discretization=discretization).thrust
        why = (f"above the most hover makes there, about {np.max(span):.5g} N" if T > np.max(span) else
               f"below the least hover makes there, about {np.min(span):.5g} N"
               + ("" if T >= 0 else " (a negative thrust: the windmill brake)" if V * math.cos(b) > 1e-9 else
                  " (a negative thrust)"))  # (the windmill brake in a climb only: at rest, reverse pitch; stop 102)
        raise TrimError(f"no collective in [{math.degrees(lo):.4g}, {math.degrees(hi):.4g}] deg makes thrust={T:.6g} N "
                        f"in hover at omega={om:.6g} rad/s = {om / RPM:.6g} rpm, the hover reference of operating "
                        f"point {_where(i, np.shape(loads.thrust))}(airspeed={V:.6g} m/s, incidence="
                        f"{math.degrees(b):.6g} deg): {why}")
    hover = _hover_nearest(propeller, params, loads, 0.0 if collective is None else collective, hover, air,
                           discretization, bounds, ~missing)
    return loads.CQ - hover.loads.CQ, loads, hover


#: collectives across the bounds at which the hover thrust's span is said where none makes the thrust (0.25 deg apart
#: across the default bounds: the span to about 1e-4 of itself)
SPAN_NODES = 201
#: the hover reference of :func:`torque_change_at_constant_thrust` where hover makes the thrust at more than one
#: collective
NEAREST_BRANCH = ("the collective nearest the operating point's that makes the thrust in hover (continuous with the "
                  "operating point from hover; the lowest where the search out from it finds none)")
#: the first step out from the operating collective in search of the nearest hover crossing [rad], doubled
#: NEAREST_LEVELS times at most (0.25 deg to 64 deg: beyond any bounds)
NEAREST_STEP = math.radians(0.25)
NEAREST_LEVELS = 9


def _hover_nearest(propeller, params, loads, collective, hover: TrimResult, air, discretization, bounds,
                   ok) -> TrimResult:
    """The hover trim nearest the operating point's ``collective``: the crossing of the hover
    thrust with the operating thrust found by steps out from it (NEAREST_STEP, doubling, within
    ``bounds``) on either side and refined; ``hover`` (the lowest crossing) where none is found.
    Only the points where ``ok`` (flat; hover makes the thrust somewhere in the bounds) are searched,
    the others left NaN, collective and loads.
    At 1338.58 rad/s apce_8x6's calibrated set peaks near -1.1 deg in hover, so from its 0 deg
    (the falling branch) the lowest crossing, -2.17 deg, made dCQ 1.2e-3 (10% of CQ) in hover
    itself, where it is 0, and at 1e-3 m/s of descent (a physics audit, stop 100)."""
    shape = np.shape(hover.collective)
    lo, hi = _check_bounds(bounds)
    om_all = np.broadcast_to(np.asarray(loads.omega, float), shape).reshape(-1)
    T, om = np.asarray(loads.thrust, float).reshape(-1)[ok], om_all[ok]
    c0 = np.clip(np.broadcast_to(np.asarray(collective, float), shape).reshape(-1)[ok], lo, hi)
    tol = _tolerances(T, None)

    def f(c, om_, T_, tol_):  # the hover thrust's excess over the operating point's, in units of its tolerance
        return (rotor_loads(propeller, params, om_, 0.0, 0.0, collective=c, air=air,
                            discretization=discretization).thrust - T_) / tol_

    x, fell = np.array(hover.collective, float).reshape(-1)[ok], np.zeros(T.size, bool)
    if T.size:  # (none: no point with a hover reference, on_missing="nan")
        with flapping_warning_held():
            x, fell = _nearest_crossing(f, c0, om, T, tol, x, lo, hi)
    x_all, fell_all = np.full(ok.size, np.nan), np.zeros(ok.size, bool)
    x_all[ok], fell_all[ok] = x, fell
    hover_loads = rotor_loads(propeller, params, om_all.reshape(shape), 0.0, 0.0,
                              collective=np.where(ok, x_all, 0.0).reshape(shape), air=air,
                              discretization=discretization)
    _nan_where_missing(hover_loads, ok, shape)
    return TrimResult(collective=x_all.reshape(shape), loads=hover_loads, n_solutions=hover.n_solutions,
                      branch=NEAREST_BRANCH, falling=fell_all.reshape(shape))


def _nearest_crossing(f, c0, om, T, tol, x, lo, hi):
    """(collective, falling) of :func:`_hover_nearest`'s points: the crossing of ``f`` (the hover
    thrust's excess, in units of ``tol``) nearest ``c0`` on either side, found by steps doubling out
    from it within [lo, hi] and refined; ``x`` (the lowest crossing) where none is found."""
    from scipy.optimize import elementwise

    n = T.size
    x = x.copy()
    f0 = f(c0, om, T, tol)
    # each side's nearest bracket [inner, outer] of a sign change, found by steps doubling out from c0
    brackets = []
    for sgn in (-1.0, 1.0):
        a, b, found, inner = np.empty(n), np.empty(n), f0 == 0, c0
        for k in range(NEAREST_LEVELS):
            outer = np.clip(c0 + sgn * NEAREST_STEP * 2.0**k, lo, hi)
            new = ~found & (np.sign(f(outer, om, T, tol)) != np.sign(f0))
            a[new], b[new], found = inner[new], outer[new], found | new
            inner = outer
            if found.all():
                break
        brackets.append((np.minimum(a, b), np.maximum(a, b), found & (f0 != 0)))
    best = np.where(f0 == 0, 0.0, np.inf)
    x[f0 == 0] = c0[f0 == 0]
    for left, right, inside in brackets:
        if not inside.any():
            continue
        res = elementwise.find_root(f, (left[inside], right[inside]), args=(om[inside], T[inside], tol[inside]),
                                    tolerances=dict(xatol=1e-10, xrtol=0.0, fatol=1.0, frtol=0.0))
        idx = np.flatnonzero(inside)[res.success]
        root = res.x[res.success]
        nearer = np.abs(root - c0[idx]) < best[idx]
        idx, root = idx[nearer], root[nearer]
        x[idx], best[idx] = root, np.abs(root - c0[idx])
    # the side of the hover curve each reference lies on, from its slope there (the operating collective's own
    # crossing, f0 = 0, kept the lowest crossing's flag: a review, stop 100)
    fell = f(np.minimum(x + 1e-4, hi), om, T, tol) < f(np.maximum(x - 1e-4, lo), om, T, tol)
    return x, fell
