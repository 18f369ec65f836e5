"""Trim: the collective (or the rotation rate) that makes a given thrust.

A variable-pitch rotor is flown by its collective: at a given rotation rate and velocity the
blade-angle offset is set so that the rotor makes the thrust wanted. :func:`trim_collective`
finds it with the full model (:func:`propmap.rotor_loads` with its ``collective`` input). A
fixed-pitch rotor is flown by its rate: :func:`trim_omega` finds the rate, by the same rule on
a grid of rates.

Which solution: the thrust need not be monotonic in the collective (past the sections'
stall it falls again), so T(collective) = T* can have several solutions. The one returned
is the **lowest collective** that makes the thrust: the thrust is tabulated on a grid of
collectives (``grid_step``, 2.5 deg by default) across ``bounds``, the first upward
crossing of T* is bracketed and refined by Chandrupatla's method
(:func:`scipy.optimize.elementwise.find_root`). Where no node of the grid reaches T* and the
thrust peaks inside the bounds (a stalling set), the peak between the highest node's
neighbours is refined first (:func:`scipy.optimize.elementwise.find_minimum`): where it
reaches T*, the crossing below it is returned. For a rotor below stall this is the only
solution; ``n_solutions`` counts the crossings the grid saw (two about a refined peak), so
that a second (stalled) branch is reported, not hidden. Where the bounds hold no upward
crossing but the thrust falls through T* (a set stalled across the bounds: the thrust falls as
the collective rises), the first downward crossing is the lowest collective that makes T*, and
it is returned, marked in ``TrimResult.falling`` (until 2026-12-01 such a thrust was refused as
one no collective makes: a user-level audit). :func:`trim_omega` keeps the rising branch only.

The torque change at constant thrust, which trims its hover reference with the collective, is
core/torque_change.py's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._crossing import (_MISSING_FIELDS, THRUST_RTOL, THRUST_TOL, _check_on_missing,  # noqa: F401 (re-exported)
                        _checked_thrust, _first_crossing, _nan_where_missing, _RefineFailed, _tolerances, _two_reals,
                        _where)
from ._numbers import real
from .units import RPM
from .airfoil import Air, SectionParams
from .flapping import flapping_warning_held
from ._inputs import _as_array
from .geometry import Propeller, broadcast_readonly
from .solver import (COLLECTIVE_RANGE, DEFAULT_DISCRETIZATION, OMEGA_MAX, Discretization, RotorLoads, model_air,
                     rotor_loads, supersonic_tips_allowed)

__all__ = ["TrimError", "TrimResult", "OmegaTrimResult", "trim_collective", "trim_omega", "default_omega_bounds"]

#: the bracketing grid's default spacing [rad] (narrowed to the bounds' width where they are narrower)
GRID_STEP = math.radians(2.5)
#: the most steps of the bracketing grid across the bounds (a grid_step of 1e-300 rad failed inside NumPy)
GRID_NODES_MAX = 10_000
#: the branch :func:`trim_collective` returns, in words (reported with every result)
BRANCH = "lowest collective that makes the thrust (the first upward crossing on the grid)"
#: the branch :func:`trim_collective` returns where the bounds hold no upward crossing, in words
FALLING_BRANCH = ("lowest collective that makes the thrust, where it falls as the collective rises (no rising "
                  "crossing in the range: the set stalled there)")
#: the branch :func:`trim_collective` returns where some points' solutions are on the rising branch and others, with no
#: rising crossing in the range, on the falling one
MIXED_BRANCH = f"{BRANCH}; where `falling` is True: the {FALLING_BRANCH}"
#: the branch :func:`trim_omega` returns, in words
OMEGA_BRANCH = "lowest rotation rate that makes the thrust (the first upward crossing on the grid)"
#: nodes of trim_omega's bracketing grid, spaced geometrically across its bounds
OMEGA_GRID_NODES = 64
#: trim_omega's default bounds as tip speeds: from this [m/s] ...
OMEGA_TIP_SPEED_MIN = 1.0
#: ... to this Mach number of the air's speed of sound (where the model's Prandtl-Glauert factor stops)
OMEGA_TIP_MACH_MAX = 0.9


class TrimError(ValueError):
    """No collective in the bounds makes the thrust asked for at some operating point."""


@dataclass(frozen=True)
class TrimResult:
    """The trimmed collective and the loads there.

    Attributes
    ----------
    collective : ndarray
        Blade-angle offset [rad] (added to ``params.collective`` and the geometry's blade
        angles), broadcast shape of the inputs.
    loads : RotorLoads
        The full model's loads at the trimmed collective (same shape).
    n_solutions : ndarray of int
        Crossings of the thrust asked for that the collective grid saw (1: a unique
        solution in the bounds; more: a stalled branch as well, not the one returned).
    branch : str
        Which solution is returned, in words: :data:`BRANCH`, :data:`FALLING_BRANCH` where
        every point's solution is on the falling branch, :data:`MIXED_BRANCH` where some are.
    falling : ndarray of bool, optional
        True where the bounds hold no upward crossing and the solution returned is the first
        downward one: the thrust falls as the collective rises there (a stalled branch;
        :data:`FALLING_BRANCH`); for the hover reference of
        :func:`torque_change_at_constant_thrust` (``branch`` :data:`NEAREST_BRANCH`), where
        the thrust falls as the collective rises at the collective returned. None: False
        everywhere.
    """

    collective: np.ndarray
    loads: RotorLoads
    n_solutions: np.ndarray
    branch: str = BRANCH
    falling: np.ndarray | None = None


@dataclass(frozen=True)
class OmegaTrimResult:
    """The trimmed rotation rate and the loads there (:func:`trim_omega`).

    Attributes
    ----------
    omega : ndarray
        Rotation rate Omega [rad/s], broadcast shape of the inputs (NaN where no rate in the
        bounds makes the thrust, with ``on_missing="nan"``).
    loads : RotorLoads
        The full model's loads at that rate (same shape).
    n_solutions : ndarray of int
        Crossings of the thrust asked for that the rate grid saw (1: a unique solution in
        the bounds).
    branch : str
        Which solution is returned, in words (:data:`OMEGA_BRANCH`).
    """

    omega: np.ndarray
    loads: RotorLoads
    n_solutions: np.ndarray
    branch: str = OMEGA_BRANCH


def _check_bounds(bounds) -> tuple[float, float]:
    lo, hi = _two_reals(bounds, "bounds must be two numbers [rad]")
    if not (-COLLECTIVE_RANGE <= lo < hi <= COLLECTIVE_RANGE):
        raise ValueError(f"bounds must satisfy -{COLLECTIVE_RANGE:.6g} <= low < high <= {COLLECTIVE_RANGE:.6g} rad, "
                         f"got ({lo!r}, {hi!r})")
    return lo, hi


def trim_collective(
    propeller: Propeller,
    params: SectionParams,
    thrust,
    omega,
    airspeed=0.0,
    incidence=0.0,
    *,
    air: Air | None = None,
    discretization: Discretization = DEFAULT_DISCRETIZATION,
    bounds=(-math.radians(20.0), math.radians(30.0)),
    grid_step: float | None = None,
    thrust_tol: float | None = None,
    on_missing: str = "raise",
) -> TrimResult:
    """The collective (blade-angle offset) at which the rotor makes ``thrust``.

    Parameters
    ----------
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    thrust : float or array_like
        The thrust wanted T* [N], finite (may be negative: a windmilling rotor).
    omega, airspeed, incidence : float or array_like
        Omega [rad/s], V [m/s] and beta [rad] as in :func:`propmap.rotor_loads`; all four
        inputs broadcast together.
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization, optional
    bounds : (float, float)
        The collectives searched [rad], within [-pi/4, pi/4]; default -20 to +30 deg.
    grid_step : float, optional
        Spacing of the bracketing grid [rad], in [bounds width / 10,000, bounds width];
        default 2.5 deg, or the bounds' width where that is narrower.
    thrust_tol : float, optional
        Absolute tolerance on T [N], > 0. Default: 1e-6 N, or 1e-6 of |thrust| where that is
        smaller, point by point (:data:`THRUST_TOL`, :data:`THRUST_RTOL`). The collective is
        also converged to 1e-10 rad.
    on_missing : {"raise", "nan"}
        Where no collective in ``bounds`` makes the thrust: raise TrimError (default), or
        return NaN collective and loads there (``n_solutions`` 0 tells them).

    Returns
    -------
    TrimResult
        ``collective`` [rad] and ``loads`` at it, of the broadcast shape; the branch rule
        is the module docstring's.

    Raises
    ------
    ValueError
        A bad argument (the message names it and its range).
    TrimError
        At some point no collective in ``bounds`` makes the thrust: the message names the
        point and the thrust range the bounds reach there, and where a thrust too high peaks
        inside the bounds, the collective of the peak, refined (the set stalls beyond it).
    propmap.SolverError
        The inflow solve failed at some collective (the message names where).

    Warns
    -----
    FlappingWarning
        The solution's blades flap beyond the small-angle range (as :func:`propmap.rotor_loads`;
        the search itself does not warn).
    """
    air = model_air(params, air)
    _check_on_missing(on_missing)
    lo, hi = _check_bounds(bounds)
    if grid_step is None:  # (a narrow --range-deg once met 'grid_step must be in (0, 0.0349] rad')
        grid_step = min(GRID_STEP, hi - lo)
    step = real(grid_step)  # (np.float32(0.05) was refused as out of [8.7e-05, 0.87] rad)
    if step is None or not (hi - lo) / GRID_NODES_MAX <= step <= hi - lo:
        raise ValueError(f"grid_step must be in [{(hi - lo) / GRID_NODES_MAX:.6g}, {hi - lo:.6g}] rad (the bounds' "
                         f"width over 1 to {GRID_NODES_MAX:,} steps), got {grid_step!r}")
    grid_step = step
    T_star, thrust_tol = _checked_thrust(thrust, thrust_tol)
    # the operating points checked as rotor_loads checks them (np.asarray(a, float) read the text '800' as 800 and
    # True as 1 rad: an API audit, 2026-12-01), and broadcast with the thrust
    points = tuple(_as_array(name, a) for name, a in (("omega", omega), ("airspeed", airspeed),
                                                      ("incidence", incidence)))
    try:
        T_star, om, V, b = broadcast_readonly(T_star, *points)
    except ValueError as exc:
        raise ValueError(f"thrust, omega, airspeed and incidence must broadcast together: {exc}") from None
    shape = T_star.shape
    T1, om1, V1, b1 = (np.ascontiguousarray(a.reshape(-1)) for a in (T_star, om, V, b))

    m = max(2, int(math.ceil((hi - lo) / grid_step)) + 1)
    grid = np.linspace(lo, hi, m)
    kw = dict(air=air, discretization=discretization)

    def thrust_at(c, om_, V_, b_):
        return rotor_loads(propeller, params, om_, V_, b_, collective=c, **kw).thrust

    try:
        with flapping_warning_held():  # (the search's trial collectives: the answer's loads below say it)
            x, n_solutions, missing, reach, fell = _first_crossing(thrust_at, grid, T1, (om1, V1, b1), thrust_tol,
                                                                   xatol=1e-10, falling=True)
    except _RefineFailed as exc:
        i = exc.index
        raise TrimError(f"the collective refinement did not converge at operating point {_where(i, shape)}"
                        f"(omega={om1[i]:.6g} rad/s = {om1[i] / RPM:.6g} rpm, thrust={T1[i]:.6g} N; scipy status "
                        f"{exc.status})") from None
    if missing.any() and on_missing == "raise":
        i = int(np.argmax(missing))
        low, top, at_top, stalls = reach[0][i], reach[1][i], reach[2][i], bool(reach[3][i])
        peak_at = (f", highest near a collective of {round(math.degrees(at_top), 4) + 0.0:.4g} deg, where the set "
                   "stalls (docs/models.md, Collective pitch as an input, and trim)") if stalls else ""
        if top > 0 and T1[i] > 10 * top:  # (a thrust in gf: 300 for 2.9 N got the stall's diagnosis)
            peak_at = f": {T1[i] / top:.3g} times the most it reaches; {_too_much(air)}"
        raise TrimError(
            f"no collective in [{math.degrees(lo):.4g}, {math.degrees(hi):.4g}] deg makes thrust={T1[i]:.6g} N at "
            f"operating point {_where(i, shape)}(omega={om1[i]:.6g} rad/s = {om1[i] / RPM:.6g} rpm, "
            f"airspeed={V1[i]:.6g} m/s, incidence={math.degrees(b1[i]):.6g} deg): the thrust there spans "
            f"[{low:.6g}, {top:.6g}] N{peak_at}")
    ok = ~missing
    loads = rotor_loads(propeller, params, om1.reshape(shape), V1.reshape(shape), b1.reshape(shape),
                        collective=np.where(ok, x, 0.0).reshape(shape), **kw)
    _nan_where_missing(loads, ok, shape)  # NaN loads where no collective makes the thrust
    # (the words of the branch returned: BRANCH's "upward crossing" was said of a falling-branch solution, a review)
    fell_ok = fell[ok]
    branch = BRANCH if not fell_ok.any() else FALLING_BRANCH if fell_ok.all() else MIXED_BRANCH
    return TrimResult(collective=x.reshape(shape), loads=loads, n_solutions=n_solutions.reshape(shape),
                      branch=branch, falling=fell.reshape(shape))


#: the air's density below which a thrust beyond 10 times the most a rotor makes is put down to the thin air rather than
#: to a thrust given in grams [kg/m^3] (a tenth of the sea level's)
THIN_AIR_RHO = 0.1225


def _too_much(air: Air) -> str:
    """The likely cause of a thrust beyond 10 times the most the rotor makes: grams for newtons, or,
    in air thinner than THIN_AIR_RHO, the air (in air of 1e-6 kg/m^3 the grams were suspected)."""
    if air.rho < THIN_AIR_RHO:
        return (f"the air's density is {air.rho:.3g} kg/m^3 (1.225 at sea level), and the thrust is in proportion to "
                "it: is the density meant?")
    return "is the thrust in grams? It is in N"


def default_omega_bounds(propeller: Propeller, air: Air) -> tuple[float, float]:
    """:func:`trim_omega`'s default bounds: the rates of a tip speed of OMEGA_TIP_SPEED_MIN
    (1 m/s) and of OMEGA_TIP_MACH_MAX (0.9) of ``air``'s speed of sound.

    Parameters
    ----------
    propeller : Propeller
        Its radius R [m] turns the tip speeds into rates.
    air : Air
        Its speed of sound [m/s].

    Returns
    -------
    (float, float)
        Omega low and high [rad/s], the high one at most the solver's OMEGA_MAX (1e5 rad/s).
    """
    return (OMEGA_TIP_SPEED_MIN / propeller.radius,
            min(OMEGA_TIP_MACH_MAX * air.speed_of_sound / propeller.radius, OMEGA_MAX))


def trim_omega(
    propeller: Propeller,
    params: SectionParams,
    thrust,
    airspeed=0.0,
    incidence=0.0,
    *,
    collective=None,
    air: Air | None = None,
    discretization: Discretization = DEFAULT_DISCRETIZATION,
    bounds=None,
    thrust_tol: float | None = None,
    on_missing: str = "raise",
) -> OmegaTrimResult:
    """The rotation rate at which the rotor makes ``thrust`` (a fixed-pitch rotor's trim:
    the hover rpm of a given load, or the rpm that makes a thrust in climb, edgewise flight
    or descent).

    The rule is :func:`trim_collective`'s with Omega for the collective: the thrust is
    tabulated on OMEGA_GRID_NODES rates spaced geometrically across ``bounds``, the first
    upward crossing of T* is bracketed and refined by Chandrupatla's method, and a peak
    between the grid's nodes is refined where the grid misses T* (module docstring). In
    still air the thrust rises with Omega and the solution is unique; in climb it rises from
    a windmilling rotor's negative thrust too, but not always monotonically: a small negative
    thrust may be made at three rates (apce_8x6's calibrated set at 15 m/s of axial climb
    makes -0.54 N at 18.0, 257.1 and 349.3 rad/s), and the lowest is returned, counted in
    ``n_solutions`` (said "unique" until 2026-12-01: a physics audit); in descent the flow
    alone makes thrust on a slowly turning rotor, so a thrust below that has no solution on
    the rising branch and the vortex-ring state can add crossings (``n_solutions`` counts
    them).

    Parameters
    ----------
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    thrust : float or array_like
        The thrust wanted T* [N], finite.
    airspeed, incidence : float or array_like
        V [m/s] and beta [rad] as in :func:`propmap.rotor_loads`; broadcast with ``thrust``
        and ``collective``.
    collective : float or array_like, optional
        Blade-angle offset [rad] (added to ``params.collective``), as in
        :func:`propmap.rotor_loads`.
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization, optional
    bounds : (float, float), optional
        The rates searched [rad/s], 0 < low < high <= 1e5; default the rates of a tip speed
        of OMEGA_TIP_SPEED_MIN (1 m/s) to OMEGA_TIP_MACH_MAX (0.9) of the air's speed of
        sound.
    thrust_tol : float, optional
        Absolute tolerance on T [N], > 0. Default: 1e-6 N, or 1e-6 of |thrust| where that is
        smaller, point by point (:data:`THRUST_TOL`, :data:`THRUST_RTOL`). Omega is also
        converged to 1e-12 of itself.
    on_missing : {"raise", "nan"}
        Where no rate in ``bounds`` makes the thrust: raise TrimError (default), or return
        NaN rate and loads there (``n_solutions`` 0 tells them).

    Returns
    -------
    OmegaTrimResult
        ``omega`` [rad/s] and ``loads`` at it, of the broadcast shape.

    Raises
    ------
    ValueError
        A bad argument (the message names it and its range).
    TrimError
        At some point no rate in ``bounds`` makes the thrust: the message names the point and
        the thrust range the bounds reach there.
    propmap.SolverError
        The inflow solve failed at some rate.

    Warns
    -----
    UserWarning
        The solution's blade tips meet the air beyond Mach 0.8 (as :func:`propmap.rotor_loads`;
        the search itself does not warn).
    FlappingWarning
        The solution's blades flap beyond the small-angle range (as :func:`propmap.rotor_loads`;
        the search itself does not warn).
    """
    air = model_air(params, air)
    _check_on_missing(on_missing)
    lo, hi = _omega_bounds(bounds, propeller, air)
    T_star, thrust_tol = _checked_thrust(thrust, thrust_tol)
    points = tuple(_as_array(name, a) for name, a in (("airspeed", airspeed), ("incidence", incidence),
                                                      ("collective", 0.0 if collective is None else collective)))
    try:
        T_star, V, b, c = broadcast_readonly(T_star, *points)
    except ValueError as exc:
        raise ValueError(f"thrust, airspeed, incidence and collective must broadcast together: {exc}") from None
    shape = T_star.shape
    T1, V1, b1, c1 = (np.ascontiguousarray(a.reshape(-1)) for a in (T_star, V, b, c))
    grid = np.geomspace(lo, hi, OMEGA_GRID_NODES)
    kw = dict(air=air, discretization=discretization)

    def thrust_at(om, V_, b_, c_):
        return rotor_loads(propeller, params, om, V_, b_, collective=c_, **kw).thrust

    try:
        # the grid's top reaches Mach 0.9 on purpose, and its trial rates may flap: the answer's loads say both below
        with supersonic_tips_allowed(), flapping_warning_held():
            x, n_solutions, missing, reach, _ = _first_crossing(thrust_at, grid, T1, (V1, b1, c1), thrust_tol,
                                                                xrtol=1e-12)
    except _RefineFailed as exc:
        i = exc.index
        raise TrimError(f"the rotation-rate refinement did not converge at operating point {_where(i, shape)}"
                        f"(thrust={T1[i]:.6g} N, airspeed={V1[i]:.6g} m/s, incidence={math.degrees(b1[i]):.6g} "
                        f"deg; scipy status {exc.status})") from None
    if missing.any() and on_missing == "raise":
        i = int(np.argmax(missing))
        raise _no_rate(i, shape, (lo, hi), (T1[i], V1[i], b1[i], c1[i]), (reach[0][i], reach[1][i]),
                       hi * propeller.radius / air.speed_of_sound, air)
    ok = ~missing
    loads = rotor_loads(propeller, params, np.where(ok, x, lo).reshape(shape), V1.reshape(shape), b1.reshape(shape),
                        collective=None if collective is None else c1.reshape(shape), **kw)
    _nan_where_missing(loads, ok, shape, _MISSING_FIELDS + ("omega",))  # NaN loads where no rate makes the thrust
    return OmegaTrimResult(omega=x.reshape(shape), loads=loads, n_solutions=n_solutions.reshape(shape))


def _omega_bounds(bounds, propeller: Propeller, air: Air) -> tuple[float, float]:
    """:func:`trim_omega`'s ``bounds`` as (low, high) [rad/s], the default where None; refused
    unless 0 < low < high <= OMEGA_MAX."""
    if bounds is None:
        bounds = default_omega_bounds(propeller, air)
    lo, hi = _two_reals(bounds, "bounds must be two rotation rates [rad/s]")
    if not (0 < lo < hi <= OMEGA_MAX):
        raise ValueError(f"bounds must satisfy 0 < low < high <= {OMEGA_MAX:g} rad/s, got ({lo!r}, {hi!r})")
    return lo, hi


def _no_rate(i: int, shape, bounds, point, reach, top_mach: float, air: Air) -> TrimError:
    """The error of :func:`trim_omega` where no rate in ``bounds`` makes the thrust at point ``i``
    (``point``: its thrust, airspeed, incidence and collective; ``reach``: the thrust the bounds
    reach there; ``top_mach``: the upper bound's tip Mach number; ``air`` the air solved in), with the
    likely cause."""
    lo, hi = bounds
    T, V, b, c = point
    low, top = reach
    if T > top:
        why = f" (the rotor makes T <= {top:.6g} N up to tip Mach {top_mach:.2g}: {_too_much(air)})"
    elif T >= low:
        why = ""
    elif V > 0 and math.cos(b) < 0:
        why = " (in descent the flow alone makes that much on a slowly turning rotor)"
    elif T <= 0 and V == 0:
        why = " (in still air a turning rotor's thrust is positive: give a thrust above 0 N)"
    else:
        why = (f" (the slowest rate, {lo:.6g} rad/s, already makes {low:.6g} N here: give a larger thrust, or a "
               "lower bound on the rate)")
    return TrimError(
        f"no rotation rate in [{lo:.6g}, {hi:.6g}] rad/s ({lo / RPM:.6g}-{hi / RPM:.6g} rpm) makes "
        f"thrust={T:.6g} N at operating point {_where(i, shape)}(airspeed={V:.6g} m/s, "
        f"incidence={math.degrees(b):.6g} deg, collective={math.degrees(c):.6g} deg): the thrust there "
        f"spans [{low:.6g}, {top:.6g}] N{why}")
