"""The operating points of :func:`propmap.rotor_loads`: the inputs' ranges, their checks (a
Python or NumPy scalar by a fast path of plain floats, anything else as arrays, broadcast), the
velocity components in the disk's frame, and the warning of a blade tip near or above Mach 1
(with the context that silences it for callers that go there on purpose).
"""

from __future__ import annotations

import contextlib
import contextvars
import math
import operator
import warnings
from typing import NamedTuple

import numba
import numpy as np

from ._interp import INCIDENCE_SNAP, snap_incidence, snap_incidence_scalar
from ._plain import compiled_layout
from .air import SUPERSONIC_TIP, TipMachWarning
from .geometry import has_bool, refuse_masked

#: the rotation rates [rad/s]: [0, OMEGA_MAX]; below OMEGA_MIN the blades are parked: the loads are the
#: solution at OMEGA_MIN (in still air scaled by (Omega / OMEGA_MIN)^2 to 0 at Omega = 0); the solver
#: itself, whose coefficients are referred to n^2, runs from OMEGA_MIN
OMEGA_MIN = 0.1
OMEGA_MAX = 1e5
AIRSPEED_MAX = 500.0
#: rotor_loads warns where a blade tip meets the air beyond this Mach number (an 11 in propeller at 1500-2400 "rad/s",
#: rpm given as rad/s, reaches Mach 0.6-0.98 and 106-137 times the thrust; until 2026-11-26 only Mach 1 was warned)
TIP_MACH_WARN = 0.8
#: the per-point collective's range [rad] (the blade-angle offset of ``rotor_loads(collective=)``)
COLLECTIVE_RANGE = math.radians(45.0)
_RANGES = {"omega": (0.0, OMEGA_MAX, "rad/s"), "airspeed": (0.0, AIRSPEED_MAX, "m/s"),
           "incidence": (0.0, math.pi, "rad"), "collective": (-COLLECTIVE_RANGE, COLLECTIVE_RANGE, "rad")}

#: one point's inputs as 1-element views of one array (omega, V, beta, collective, V_s, V_c)
_ONE_POINT = operator.itemgetter(*(slice(i, i + 1) for i in range(6)))


def _range_error(name: str, value) -> ValueError:
    lo, hi, unit = _RANGES[name]
    why = ""
    if name == "omega" and isinstance(value, float) and value < 0:
        why = " (a signed rotation rate is refused: give its magnitude, and the sense as the rotor's spin)"
    if name == "incidence" and isinstance(value, float) and -math.pi <= value < 0:
        why = " (the model is symmetric in the incidence: give its magnitude)"
    # (180.0 and -5.0 were told the range alone: a wind-tunnel data audit, 2026-11-30)
    if name == "incidence" and isinstance(value, float) and math.pi < value <= 180.0:
        why = f" (in degrees? {value:g} deg is {math.radians(value):.6g} rad: the incidence is in radians)"
    # (pi + 1e-6, an arccos's rounding, was asked whether it was in degrees: an API audit, 2026-12-01)
    if name == "incidence" and isinstance(value, float) and math.pi < value < math.pi + 1e-5:
        why = (f" ({value - math.pi:.3g} rad beyond pi, as rounding leaves it: clip it to pi; within "
               f"{INCIDENCE_SNAP:g} rad it is taken as pi)")
    if name == "airspeed" and isinstance(value, float) and value < 0:
        why = (" (a descent given as a negative airspeed? give its magnitude with incidence pi: the incidence is "
               "the angle between the airspeed and the rotor axis, pi for axial descent)")
    return ValueError(f"{name} must be finite and in [{lo:g}, {hi:g}] {unit}; got {value!r}{why}")


@numba.njit(cache=True)
def _outside(a, lo, hi, snap):
    """(index of the first value of the 1-D float array ``a`` outside [lo - snap, hi + snap] or NaN,
    -1 if none; the number of values within ``snap`` outside [lo, hi]): one pass, compiled (the
    NumPy comparisons, their error state and reductions took 6-12 us of a small batch's call)."""
    first = -1
    near = 0
    for i in range(a.shape[0]):
        x = a[i]
        if not (lo - snap <= x <= hi + snap):  # (NaN too)
            if first < 0:
                first = i
        elif x < lo or x > hi:
            near += 1
    return first, near


@numba.njit(cache=True)
def _disk_components(om, V, b, radius, omega_min):
    """(V_s, V_c, any Omega below omega_min, the largest tip speed) of flat operating points:
    V_s = V sin(beta), exactly 0 in axial flow (below 1e-12 V), V_c = V cos(beta), the tip speed
    hypot(Omega R + |V_s|, V_c), 0 for no point; in one compiled pass (the scalar path's arithmetic)."""
    n = om.shape[0]
    Vs = np.empty(n)
    Vc = np.empty(n)
    slow = False
    tip = 0.0
    for i in range(n):
        s = V[i] * np.sin(b[i])
        c = V[i] * np.cos(b[i])
        if abs(s) < 1e-12 * max(V[i], 1e-300):  # exact axial flow at beta = 0, pi
            s = 0.0
        Vs[i] = s
        Vc[i] = c
        tip = max(tip, np.hypot(om[i] * radius + abs(s), c))
        slow = slow or om[i] < omega_min
    return Vs, Vc, slow, tip


def _as_array(name: str, value) -> np.ndarray:
    """``value`` as a float array, checked against ``_RANGES[name]``; strings and bools refused."""
    lo, hi, _ = _RANGES[name]
    try:
        a = np.asarray(value)
    except (ValueError, OverflowError) as exc:  # ragged nesting, ints beyond int64
        raise ValueError(f"{name} must be a number or a rectangular array of numbers ({exc})") from None
    refuse_masked(name, value)
    if a.dtype.kind == "O":
        try:
            # (float(None) fails, but an array's None casts to NaN; and a text, "800", cast to 800: a mutation
            # audit, 2026-11-29, where the list [800.0, "800"] was refused)
            if any(v is None or isinstance(v, (str, bytes)) for v in a.reshape(-1)):
                raise TypeError
            a = a.astype(float)
        except OverflowError:  # (an int beyond the float range is a number: it was told it was none)
            lo, hi, unit = _RANGES[name]
            raise ValueError(f"{name} must be finite and in [{lo:g}, {hi:g}] {unit}; got a number beyond any "
                             "float") from None
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be a number or an array of numbers, got {value!r:.60}") from None
    if a.dtype.kind not in "fiu" or has_bool(value):
        raise ValueError(f"{name} must be a number or an array of numbers, got {value!r:.60}")
    a = a.astype(float, copy=False)
    # (contiguous and writeable: a strided or read-only array is another type to _outside, compiled once more;
    # not by np.require, which cost 2 us of a small batch's call for each input)
    flat = compiled_layout(a.reshape(-1))
    first, near = _outside(flat, lo, hi, INCIDENCE_SNAP if name == "incidence" else 0.0)
    if first >= 0:  # (beyond the incidence's snap, so as given)
        raise _range_error(name, float(flat[first]))
    if near:  # an incidence within INCIDENCE_SNAP of 0 or pi: on it (a new array: the caller's is never written)
        a = snap_incidence(a)
    return a


def _scalar(name: str, value) -> float:
    """Fast path for a Python or NumPy real scalar (no array machinery)."""
    lo, hi, unit = _RANGES[name]
    try:
        x = float(value)
    except OverflowError:  # an int beyond the float range (said as such: 10**400 was told "got inf", an API audit)
        digits = int(abs(int(value)).bit_length() * math.log10(2)) + 1  # (not str(): Python refuses 4300 digits)
        raise ValueError(f"{name} must be finite and in [{lo:g}, {hi:g}] {unit}; got an integer of about "
                         f"{digits} digits, beyond any float") from None
    if name == "incidence":  # (as the array path: within INCIDENCE_SNAP of 0 or pi, on it)
        x = snap_incidence_scalar(x, lo, hi)
    if not lo <= x <= hi:
        raise _range_error(name, x)
    return x


#: the exact types that take the one-point path (a set of types, not of their abstract bases: ``type(x) in`` with
#: np.floating and np.integer matched no NumPy scalar, so a float64 taken from an array ran the array path, 1.45x the
#: call's cost, until 2026-11-28: a review of the peer benchmark; a bool, a subclass, an array take the array path)
_REAL_SCALARS = frozenset((float, int, np.float64, np.float32, np.float16, np.int64, np.int32, np.int16, np.int8,
                           np.uint64, np.uint32, np.uint16, np.uint8))

#: set by supersonic_tips_allowed (per thread and task: a context variable, not the global warning filters)
_SUPERSONIC_ALLOWED = contextvars.ContextVar("propmap_supersonic_tips_allowed", default=False)


@contextlib.contextmanager
def supersonic_tips_allowed():
    """Within the block, :func:`rotor_loads` does not warn of a supersonic blade tip.

    For callers that evaluate such rates on purpose: a hover search doubling its bracket
    (:func:`propmap.vehicle.hover_omega`), a unit check of measured data that says its own
    (:func:`propmap.identify.data.sanity_check`), a user sweeping past Mach 1 knowingly. The
    flag is a context variable, so other threads keep their warning.

    Yields
    ------
    None
    """
    token = _SUPERSONIC_ALLOWED.set(True)
    try:
        yield
    finally:
        _SUPERSONIC_ALLOWED.reset(token)


class OperatingPoints(NamedTuple):
    """The checked operating points of one :func:`propmap.rotor_loads` call, flattened.

    Attributes
    ----------
    shape : tuple
        The broadcast shape of the inputs (() for one point of scalars).
    omega, airspeed, incidence, collective : ndarray, shape (n,)
        Omega [rad/s], V [m/s], beta [rad] (snapped onto 0 or pi within INCIDENCE_SNAP) and the
        collective offset [rad] (0 where none was given); new arrays, never the caller's.
    V_s, V_c : ndarray, shape (n,)
        V sin(beta) and V cos(beta) [m/s], contiguous; V_s exactly 0 in axial flow.
    any_slow : bool
        A rate below :data:`OMEGA_MIN` (parked blades).
    tip_speed : float
        The largest blade-tip airspeed, hypot(Omega R + |V_s|, V_c) [m/s].
    """

    shape: tuple
    omega: np.ndarray
    airspeed: np.ndarray
    incidence: np.ndarray
    collective: np.ndarray
    V_s: np.ndarray
    V_c: np.ndarray
    any_slow: bool
    tip_speed: float


def operating_points(omega, airspeed, incidence, collective, radius: float) -> OperatingPoints:
    """Check and flatten the operating points of :func:`propmap.rotor_loads`.

    Parameters
    ----------
    omega, airspeed, incidence : float or array_like
        Omega [rad/s] in [0, OMEGA_MAX], V [m/s] in [0, AIRSPEED_MAX], beta [rad] in [0, pi];
        broadcast together.
    collective : float, array_like or None
        Blade-angle offset [rad] in [-COLLECTIVE_RANGE, COLLECTIVE_RANGE], broadcast with them.
    radius : float
        R [m], for the tip speed.

    Returns
    -------
    OperatingPoints
        Where every input is one Python or NumPy real scalar (not a bool), built from plain
        floats (no ufunc calls on one-element arrays): ``shape`` (), and the arrays 1-element
        views of one array.

    Raises
    ------
    ValueError
        An input that is not a number (a string, a bool, a masked entry), outside its range, or
        shapes that do not broadcast; the message names the input and its range.
    """
    if (type(omega) in _REAL_SCALARS and type(airspeed) in _REAL_SCALARS  # noqa: E721 (bool excluded)
            and type(incidence) in _REAL_SCALARS and (collective is None or type(collective) in _REAL_SCALARS)):
        w0 = _scalar("omega", omega)
        v0, b0 = _scalar("airspeed", airspeed), _scalar("incidence", incidence)
        vs0, vc0 = v0 * math.sin(b0), v0 * math.cos(b0)  # Python floats: no ufunc calls on 1-element arrays
        if abs(vs0) < 1e-12 * max(v0, 1e-300):  # exact axial flow at beta = 0, pi
            vs0 = 0.0
        x = np.array([w0, v0, b0, 0.0 if collective is None else _scalar("collective", collective), vs0, vc0])
        om1, V1, b1, c1, Vs, Vc = _ONE_POINT(x)  # one-point views
        return OperatingPoints((), om1, V1, b1, c1, Vs, Vc, w0 < OMEGA_MIN, math.hypot(w0 * radius + abs(vs0), vc0))
    arrays = [_as_array("omega", omega), _as_array("airspeed", airspeed), _as_array("incidence", incidence)]
    if collective is not None:
        arrays.append(_as_array("collective", collective))
    shapes = {a.shape for a in arrays}
    try:  # (np.broadcast_shapes costs 3 us: not called for the common inputs of one shape)
        shape = shapes.pop() if len(shapes) == 1 else np.broadcast_shapes(*(a.shape for a in arrays))
    except ValueError as exc:
        if "broadcast" in str(exc):
            what = "omega, airspeed, incidence and collective" if collective is not None else \
                "omega, airspeed and incidence"
            raise ValueError(f"{what} must broadcast together: {exc}") from None
        raise
    n = math.prod(shape)
    # flat copies: the result keeps omega, airspeed and incidence, and must not share the caller's memory (a
    # later om *= 2 on the input changed r.power and r.CT; user-level audit, 2026-11-26); one number filled in
    flat = [a.reshape(-1).copy() if a.shape == shape else np.full(n, a.reshape(-1)[0]) if a.size == 1
            else np.broadcast_to(a, shape).reshape(-1).copy() for a in arrays]
    om1, V1, b1 = flat[:3]
    c1 = flat[3] if collective is not None else np.zeros(n)
    Vs, Vc, slow, tip = _disk_components(om1, V1, b1, float(radius), OMEGA_MIN)
    return OperatingPoints(shape, om1, V1, b1, c1, Vs, Vc, slow, tip)


def warn_tip_mach(tip_speed: float, speed_of_sound: float) -> None:
    """Warn (:class:`propmap.core.air.TipMachWarning`, attributed to rotor_loads' caller) where a
    blade tip meets the air beyond :data:`TIP_MACH_WARN`, unless :func:`supersonic_tips_allowed`
    is in force.

    Parameters
    ----------
    tip_speed : float
        The largest blade-tip airspeed [m/s] (:attr:`OperatingPoints.tip_speed`).
    speed_of_sound : float
        [m/s].
    """
    if tip_speed <= TIP_MACH_WARN * speed_of_sound or _SUPERSONIC_ALLOWED.get():
        return
    mach = tip_speed / speed_of_sound  # a rate in rpm, most likely
    said = ("the model has no transonic or supersonic physics (its Prandtl-Glauert factor stops at Mach 0.9), "
            "so these loads mean nothing" if mach > 1 else
            "past the end of the model's compressibility (its Prandtl-Glauert factor is held at its Mach 0.9 "
            "value; small UAV propellers run below 0.7)" if mach > 0.9 else
            "near the end of the model's compressibility (its Prandtl-Glauert factor stops at Mach 0.9; small "
            "UAV propellers run below 0.7)")  # (past 0.9 it said "near": an API audit, 2026-12-01)
    # (the rpm hint from Mach 0.9: a racing propeller's punch-out reaches 0.8-0.9, an 11 in propeller at 2400
    # 'rad/s' (rpm) 0.98; the Mach number to two digits, so that a simulation loop's slowly varying rate does
    # not warn at every step)
    hint = "; is omega given in rpm? it is in rad/s (rpm * pi / 30)" if mach > 0.9 else ""
    warnings.warn(f"{SUPERSONIC_TIP} {mach:.2g} (> {TIP_MACH_WARN:g}): {said}{hint}", TipMachWarning, stacklevel=3)
