"""The checks of identification data built by hand (LoadData, LevelFlightData, FlightSamples):
one rule for numbers, shapes and finiteness, each error naming the field."""

from __future__ import annotations

import numbers

import numpy as np

from ..core.geometry import has_bool


def float_array(owner: str, name: str, value, shape: tuple, *, row: str, nan: bool = False) -> np.ndarray:
    """``value`` as a float array of ``shape``, finite (NaN allowed with ``nan``).

    Parameters
    ----------
    owner, name : str
        The class and the field, for the message (``LoadData.omega``).
    value : array_like
    shape : tuple of int or str
        The shape wanted; a str entry (e.g. ``"n_rotors"``) matches nothing and names the
        dimension in the message (an array that cannot have a valid shape). The first entry is N.
    row : str
        What one row is, for the message ("point", "condition", "sample").
    nan : bool
        NaN allowed (a value not measured there); infinities never are.

    Returns
    -------
    ndarray of float

    Raises
    ------
    ValueError
        Not numbers (strings, bools, an int beyond the float range), another shape, or a
        non-finite value; the message names ``owner.name``, the shape wanted with N, and the
        first bad row (its index, from 0).
    """
    try:
        raw = np.asarray(value)
        numeric = raw.dtype.kind in "iuf" or (raw.dtype.kind == "O" and all(  # (None: NaN, as NumPy reads it)
            x is None or (isinstance(x, numbers.Real) and not isinstance(x, (bool, np.bool_))) for x in raw.flat))
        numeric = numeric and not has_bool(value)  # (no strings, no bools read as 0 or 1)
        a = raw.astype(float) if numeric else None
    except (TypeError, ValueError, OverflowError):  # ragged, or an int beyond the floats
        a = None
    if a is None:
        raise ValueError(f"{owner}.{name} must be numbers, got {value!r:.60}") from None
    if a.shape != shape:
        want = ", ".join(map(str, shape)) + ("," if len(shape) == 1 else "")
        raise ValueError(f"{owner}.{name} must have shape ({want}) (N = {shape[0]} {row}s), got {a.shape}")
    bad = ~(np.isfinite(a) | (nan & np.isnan(a)))
    if bad.any():
        raise ValueError(f"{owner}.{name} must be finite ({row} {int(np.argwhere(bad)[0][0])} is not; from 0)")
    return a


def first_length(owner: str, name: str, value) -> int:
    """N, the length of the field that defines it (shape (N,)); ValueError naming it otherwise."""
    shape = np.shape(value)
    if len(shape) != 1:
        raise ValueError(f"{owner}.{name} must have shape (N,), got {shape}")
    return shape[0]


def boolean_mask(owner: str, mask, n: int, name: str = "mask") -> np.ndarray:
    """``mask`` as a boolean array of shape (n,), for ``owner``'s selection of rows.

    Parameters
    ----------
    owner : str
        The method, for the message (``LoadData.subset``).
    mask : array_like of bool, shape (n,)
    n : int
        The number of rows.
    name : str
        The argument's name, for the message (default ``mask``).

    Returns
    -------
    ndarray of bool, shape (n,)

    Raises
    ------
    ValueError
        ``mask`` not booleans (integer indices were read as truth values: the row of index 0
        dropped, the order ignored, without a word, an identification-API audit, stop 100), or
        not of shape (n,).
    """
    a = np.asarray(mask)
    if a.dtype != bool:
        raise ValueError(f"{owner}: {name} must be an array of booleans of shape ({n},), one per row, got dtype "
                         f"{a.dtype} (for indices, give a boolean array such as np.isin(np.arange({n}), indices); "
                         "rows keep their order)")
    if a.shape != (n,):
        raise ValueError(f"{owner}: {name} must have shape ({n},), one boolean per row, got {a.shape}")
    return a
