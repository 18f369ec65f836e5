"""One real number from what a user may pass for it: a Python int or float, a NumPy scalar of
any integer or float type, or a 0-d array of one (``np.float32(800.0)``, ``np.array(0.1)``,
``np.int64(2)``). Bools, strings and other objects are not numbers here (``True`` was once a
tolerance of 1 N; ``"5"`` a thrust of 5 N). The scalar checks of the model's inputs and
records take their values through :func:`real` (``np.float32`` and 0-d arrays were refused by
some of them with a message that quoted a value in range: a user-level audit, 2026-11-30),
and :func:`checked` is the range check most of them share (one wording: the name, the range
with its unit, the value given); :func:`integer` is its counterpart for counts, seeds and
limits.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

#: the largest seed accepted (a NumPy int64)
SEED_MAX = 2**63 - 1


def real(value) -> float | None:
    """``float(value)`` for a real number, a NumPy integer or float scalar or a 0-d array of
    one; None for anything else (a bool, a string, a time (``np.timedelta64``), an int too
    large for a float, an array of several values)."""
    if isinstance(value, np.ndarray):
        if value.ndim != 0 or value.dtype.kind not in "iuf":
            return None
        value = value[()]
    if isinstance(value, np.generic) and value.dtype.kind not in "iuf":  # (np.timedelta64 is a NumPy integer)
        return None
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    try:
        return float(value)
    except (OverflowError, TypeError, ValueError):
        return None


def _shown(x: float) -> str:
    """``x`` as ``:g`` shows it where that is exact (1e+04, 0.1), else its full repr (a bound of 30 deg in rad)."""
    text = f"{x:g}"
    return text if float(text) == x else repr(float(x))


def checked(name: str, value, low: float | None = None, high: float | None = None, *, low_open: bool = False,
            high_open: bool = False, unit: str = "", error: type[Exception] = ValueError) -> float:
    """``value`` as a float where it is a finite real number (:func:`real`) within the range;
    else ``error`` naming ``name``, the range with its ``unit`` and the value given.

    The one range check of the model's scalar inputs and records (Air, BodyDrag, the section
    records, trims, load data, flight samples): ``checked("rho", -1, 0, low_open=True,
    unit="kg/m^3")`` raises "rho must be a finite number in (0, inf) kg/m^3, got -1".
    """
    x = real(value)
    if (x is None or not math.isfinite(x) or (low is not None and (x < low or (low_open and x == low)))
            or (high is not None and (x > high or (high_open and x == high)))):
        if low is None and high is None:
            where = "a finite number"
        else:
            lo = "(-inf" if low is None else ("(" if low_open else "[") + _shown(low)
            hi = "inf)" if high is None else _shown(high) + (")" if high_open else "]")
            where = f"a finite number in {lo}, {hi}"
        unit = "" if not unit else f" [{unit}]" if low is None and high is None else f" {unit}"
        raise error(f"{name} must be {where}{unit}, got {value!r:.60}")
    return x


def integer(name: str, value, low: int, high: int | None = None, *, whole_float: bool = True,
            error: type[Exception] = ValueError) -> int:
    """``value`` as an int in [low, high] (``high`` None: no upper bound); else ``error`` naming
    ``name``, the range and the value given.

    The one check of the integer arguments (counts, seeds, evaluation limits, pole pairs,
    blade counts): a Python or NumPy integer, or a 0-d array of one, and, with ``whole_float``,
    an integral float too (2000.0, ``np.float64(48.0)``); never a bool or a string.
    ``integer("seed", -1, 0, 2**63 - 1)`` raises "seed must be an integer in [0,
    9223372036854775807], got -1".
    """
    n = None
    if isinstance(value, (bool, np.bool_)):
        pass
    elif isinstance(value, (numbers.Integral, np.integer)) or (isinstance(value, np.ndarray) and value.ndim == 0
                                                               and value.dtype.kind in "iu"):
        n = int(value)  # (exact: float(2**63 - 1) rounds up past the bound, 10**400 overflows a float)
    elif whole_float:
        x = real(value)
        if x is not None and math.isfinite(x) and x.is_integer():
            n = int(x)
    if n is None or n < low or (high is not None and n > high):
        where = f"in [{low}, {high}]" if high is not None else f">= {low}"
        raise error(f"{name} must be an integer {where}, got {value!r:.60}")
    return n
