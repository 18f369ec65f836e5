"""Trim: the collective that makes a given thrust, and the torque change at constant thrust.

A variable-pitch rotor is flown by its collective: at a given rotation rate and velocity the
blade-angle offset is set so that the rotor makes the thrust wanted. :func:`trim_collective`
finds it with the full model (:func:`propmap.rotor_loads` with its ``collective`` input).

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
that a second (stalled) branch is reported, not hidden.

:func:`torque_change_at_constant_thrust` gives the descent literature's dCQ: the torque
coefficient at an operating point minus the one in hover at the same thrust and rotation
rate (both trimmed with the collective), the quantity the measured descent data tabulate
(e.g. Castles & Gray, NACA TN 2474, 1951, who derive the induced velocity from it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .units import RPM
from .airfoil import Air, SectionParams
from .geometry import Propeller
from .solver import (COLLECTIVE_RANGE, DEFAULT_DISCRETIZATION, Discretization, RotorLoads, model_air,
                     rotor_loads)

__all__ = ["TrimError", "TrimResult", "trim_collective", "torque_change_at_constant_thrust"]

#: the bracketing grid's default spacing [rad] (narrowed to the bounds' width where they are narrower)
GRID_STEP = math.radians(2.5)
#: the most steps of the bracketing grid across the bounds (a grid_step of 1e-300 rad failed inside NumPy)
GRID_NODES_MAX = 10_000
#: the branch :func:`trim_collective` returns, in words (reported with every result)
BRANCH = "lowest collective that makes the thrust (the first upward crossing on the grid)"


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
        Which solution is returned, in words (:data:`BRANCH`).
    """

    collective: np.ndarray
    loads: RotorLoads
    n_solutions: np.ndarray
    branch: str = BRANCH


def _check_bounds(bounds) -> tuple[float, float]:
    try:
        lo, hi = (float(b) for b in bounds)
    except (TypeError, ValueError):
        raise ValueError(f"bounds must be two numbers [rad], got {bounds!r}") from None
    if not (-COLLECTIVE_RANGE <= lo < hi <= COLLECTIVE_RANGE):
        raise ValueError(f"bounds must satisfy -{COLLECTIVE_RANGE:.6g} <= low < high <= {COLLECTIVE_RANGE:.6g} rad, "
                         f"got ({lo!r}, {hi!r})")
    return lo, hi


def _where(i: int, shape) -> str:
    """The index of point ``i`` for a message ('' for a single point)."""
    return f"{tuple(int(k) for k in np.unravel_index(i, shape))} " if shape else ""


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
    thrust_tol: float = 1e-6,
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
    thrust_tol : float
        Absolute tolerance on T [N] (default 1e-6 N); the collective is also converged to
        1e-10 rad.
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
    """
    air = model_air(params, air)
    from scipy.optimize import elementwise

    if on_missing not in ("raise", "nan"):
        raise ValueError(f"on_missing must be 'raise' or 'nan', got {on_missing!r}")
    lo, hi = _check_bounds(bounds)
    if grid_step is None:  # (a narrow --range-deg once met 'grid_step must be in (0, 0.0349] rad')
        grid_step = min(GRID_STEP, hi - lo)
    if not (isinstance(grid_step, (int, float)) and not isinstance(grid_step, bool)
            and (hi - lo) / GRID_NODES_MAX <= grid_step <= hi - lo):
        raise ValueError(f"grid_step must be in [{(hi - lo) / GRID_NODES_MAX:.6g}, {hi - lo:.6g}] rad (the bounds' "
                         f"width over 1 to {GRID_NODES_MAX:,} steps), got {grid_step!r}")
    if not (isinstance(thrust_tol, (int, float)) and thrust_tol > 0 and math.isfinite(thrust_tol)):
        raise ValueError(f"thrust_tol must be a positive number [N], got {thrust_tol!r}")
    T_star = np.asarray(thrust)
    if T_star.dtype.kind not in "iuf":  # (a string '4' read as 4 N, True as 1 N)
        raise ValueError(f"thrust must be a number or an array of numbers [N], got {thrust!r:.60}")
    T_star = T_star.astype(float)
    if not np.all(np.isfinite(T_star)):
        raise ValueError("thrust must be finite [N]")
    # the operating points are checked by rotor_loads; broadcast them with the thrust here
    try:
        T_star, om, V, b = np.broadcast_arrays(T_star, *(np.asarray(a, float) for a in (omega, airspeed, incidence)))
    except ValueError as exc:
        raise ValueError(f"thrust, omega, airspeed and incidence must broadcast together: {exc}") from None
    shape = T_star.shape
    T1, om1, V1, b1 = (np.ascontiguousarray(a.reshape(-1)) for a in (T_star, om, V, b))
    n = T1.size

    m = max(2, int(math.ceil((hi - lo) / grid_step)) + 1)
    grid = np.linspace(lo, hi, m)
    kw = dict(air=air, discretization=discretization)
    Tg = rotor_loads(propeller, params, om1[:, None], V1[:, None], b1[:, None], collective=grid[None, :],
                     **kw).thrust - T1[:, None]  # (n, m)
    up = (Tg[:, :-1] <= 0) & (Tg[:, 1:] > 0)  # upward crossings
    down = (Tg[:, :-1] > 0) & (Tg[:, 1:] <= 0)
    exact = Tg == 0
    # (a node that makes the thrust exactly is a solution: a parked rotor's 0 N at every collective counted 0)
    n_solutions = np.maximum(up.sum(axis=1) + down.sum(axis=1), exact.any(axis=1))
    missing = ~up.any(axis=1) & ~exact.any(axis=1)
    j = np.where(up.any(axis=1), np.argmax(up, axis=1), 0)
    xl, xr = grid[j], grid[j + 1]
    on_node = exact.any(axis=1) & ~up.any(axis=1)
    # a thrust the grid misses only near the peak of T(collective) (a stalling set): the peak between the grid's
    # neighbours of its highest node refined first, and where it reaches the thrust, the crossing below it
    k_top = np.argmax(Tg, axis=1)
    top, at_top = (Tg + T1[:, None]).max(axis=1), grid[k_top]
    # (every node below the thrust: one above them all, or below them all, has no peak to refine, a review found)
    inner = missing & (k_top > 0) & (k_top < m - 1) & (Tg.max(axis=1) < 0)
    if inner.any():
        idx, kk = np.flatnonzero(inner), k_top[inner]

        def minus(c, om_, V_, b_, T_):
            return T_ - rotor_loads(propeller, params, om_, V_, b_, collective=c, **kw).thrust

        peak = elementwise.find_minimum(minus, (grid[kk - 1], grid[kk], grid[kk + 1]),
                                        args=(om1[idx], V1[idx], b1[idx], T1[idx]),
                                        tolerances=dict(xatol=1e-10, xrtol=0.0, fatol=0.1 * thrust_tol, frtol=0.0))
        top[idx], at_top[idx] = T1[idx] - peak.f_x, peak.x
        reached = peak.f_x <= 0
        hit = idx[reached]
        missing[hit] = False
        n_solutions[hit] += 2  # (an upward and a downward crossing about the peak)
        xl[hit], xr[hit] = grid[kk[reached] - 1], peak.x[reached]
    if missing.any() and on_missing == "raise":
        i = int(np.argmax(missing))
        stalls = bool(inner[i])  # short of the target at a peak inside
        peak_at = (f", highest near a collective of {round(math.degrees(at_top[i]), 4) + 0.0:.4g} deg, where the set "
                   "stalls (docs/models.md, Collective pitch as an input, and trim)") if stalls else ""
        if top[i] > 0 and T1[i] > 10 * top[i]:  # (a thrust in gf: 300 for 2.9 N got the stall's diagnosis)
            peak_at = f": {T1[i] / top[i]:.3g} times the most it reaches; is the thrust in grams? It is in N"
        raise TrimError(
            f"no collective in [{math.degrees(lo):.4g}, {math.degrees(hi):.4g}] deg makes thrust={T1[i]:.6g} N at "
            f"operating point {_where(i, shape)}(omega={om1[i]:.6g} rad/s = {om1[i] / RPM:.6g} rpm, "
            f"airspeed={V1[i]:.6g} m/s, incidence={math.degrees(b1[i]):.6g} deg): the thrust there spans "
            f"[{(Tg[i] + T1[i]).min():.6g}, {top[i]:.6g}] N{peak_at}")
    x = np.full(n, np.nan)
    x[on_node] = grid[np.argmax(exact[on_node], axis=1)]
    todo = ~on_node & ~missing
    if todo.any():
        def f(c, om_, V_, b_, T_):
            return rotor_loads(propeller, params, om_, V_, b_, collective=c, **kw).thrust - T_

        res = elementwise.find_root(f, (xl[todo], xr[todo]), args=(om1[todo], V1[todo], b1[todo], T1[todo]),
                                    tolerances=dict(xatol=1e-10, xrtol=0.0, fatol=thrust_tol, frtol=0.0))
        if not np.all(res.success):
            k = int(np.argmax(~res.success))
            i = int(np.flatnonzero(todo)[k])
            raise TrimError(f"the collective refinement did not converge at operating point {_where(i, shape)}"
                            f"(omega={om1[i]:.6g} rad/s = {om1[i] / RPM:.6g} rpm, thrust={T1[i]:.6g} N; "
                            f"scipy status {int(res.status[k])})")
        x[todo] = res.x
    ok = ~missing
    loads = rotor_loads(propeller, params, om1.reshape(shape), V1.reshape(shape), b1.reshape(shape),
                        collective=np.where(ok, x, 0.0).reshape(shape), **kw)
    if not ok.all():  # NaN loads where no collective makes the thrust
        bad = ~ok.reshape(shape)
        for f in ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "v_i_mean"):
            np.asarray(getattr(loads, f))[bad] = np.nan
    return TrimResult(collective=x.reshape(shape), loads=loads, n_solutions=n_solutions.reshape(shape))


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

    Returns
    -------
    (dCQ, loads, hover) : (ndarray, RotorLoads, TrimResult)
        dCQ of the broadcast shape, the loads at the operating point and the hover trim.

    Raises
    ------
    ValueError, TrimError, propmap.SolverError
        As :func:`trim_collective` (a thrust that no hover collective in ``bounds`` makes,
        e.g. a negative thrust in the windmill brake, raises TrimError); ValueError also for
        an ``omega`` of 0 (CQ undefined).
    """
    air = model_air(params, air)
    loads = rotor_loads(propeller, params, omega, airspeed, incidence, collective=collective, air=air,
                        discretization=discretization)
    if np.any(loads.omega <= 0):  # (CQ = Q / (rho n^2 D^5) has no value at rest: a silent NaN once)
        raise ValueError("omega must be > 0 rad/s: the torque coefficient of a stopped rotor is undefined")
    hover = trim_collective(propeller, params, loads.thrust, loads.omega, 0.0, 0.0, air=air,
                            discretization=discretization, bounds=bounds)
    return loads.CQ - hover.loads.CQ, loads, hover
