"""One real number from what a user may pass for it: a Python int or float, a NumPy scalar of
any integer or float type, or a 0-d array of one (``np.float32(800.0)``, ``np.array(0.1)``,
``np.int64(2)``). Bools, strings and other objects are not numbers here (``True`` was once a
tolerance of 1 N; ``"5"`` a thrust of 5 N). The scalar checks of the model's inputs and
records take their values through :func:`real` (``np.float32`` and 0-d arrays were refused by
some of them with a message that quoted a value in range: a user-level audit, 2026-11-30).
"""

from __future__ import annotations

import numbers

import numpy as np


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
