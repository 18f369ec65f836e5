"""One-point inputs of the scalar fast paths (:meth:`propmap.RotorMap.loads`, ``.wrench``,
:meth:`propmap.vehicle.VehicleMap.wrench` and :func:`propmap.rotor_wrench`): a query that is one
real number (a Python or NumPy real scalar, not a bool), or one vector of them (an ndarray of
shape (n,), not a subclass, or a list or tuple, a named tuple too: a velocity, an axis, a
vehicle's rotor speeds), takes the compiled one-point path; anything else gives None and takes
the array path, which broadcasts it or says what is wrong with it."""

from __future__ import annotations

import numpy as np

__all__ = ["SPINS", "compiled_layout", "plain_float", "plain_vector"]


_F64 = np.dtype(np.float64)
#: a rotor's spin by name: +1 counter-clockwise about its axis, -1 clockwise (docs/conventions.md)
SPINS = {"ccw": 1.0, "cw": -1.0}


def compiled_layout(a: np.ndarray) -> np.ndarray:
    """``a`` itself where it is C-contiguous and writeable, else a C-contiguous copy: the one array
    layout propmap's compiled functions are compiled for (numba compiles per array type, and a
    read-only, strided or Fortran-ordered array is another: a compile of 0.5-1.6 s in the middle
    of a run, measured 2026-11-28). A flags check of about 50 ns for an ordinary array.

    Parameters
    ----------
    a : ndarray
        Any shape and dtype (the dtype is kept).

    Returns
    -------
    ndarray
        ``a`` or its copy, of ``a``'s shape and dtype.
    """
    flags = a.flags
    return a if flags.c_contiguous and flags.writeable else np.array(a, order="C")


def plain_float(x, *, int64: bool = False) -> float | None:
    """``x`` as a Python float where it is one real number, else None.

    Parameters
    ----------
    x : object
        A float, an int, a NumPy floating or integer scalar pass (an int or a float32 took the
        array path, 10-60x slower, until 2026-11-26); a bool, a NumPy bool, an integer beyond a
        float's range and anything else give None.
    int64 : bool
        Also None for an integer beyond int64, which NumPy reads as no number (:func:`propmap.rotor_wrench`'s
        array path then names it: "velocity must be numbers"); RotorMap's one-point calls take it as a float,
        whose range the query then fails (the array path would call it no number).

    Returns
    -------
    float or None
    """
    if type(x) is float:
        return x
    if isinstance(x, (int, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_)):
        if int64 and isinstance(x, int) and abs(x) >= 2**63:
            return None
        try:
            return float(x)
        except OverflowError:  # an int beyond a float's range: the array path says what is wrong
            return None
    return None


def plain_vector(value, n: int, *, int64: bool = False) -> np.ndarray | None:
    """``value`` as a float64 array of shape (n,) where it is one n-vector of plain numbers, else None.

    Parameters
    ----------
    value : object
        A NumPy array (not a subclass) of shape (n,) and a float or integer dtype, or a tuple or
        list (a named tuple too) of n :func:`plain_float` numbers.
    n : int
        The length.
    int64 : bool
        As :func:`plain_float`'s, for the tuple's or list's numbers.

    Returns
    -------
    ndarray of shape (n,) or None
        C-contiguous, aligned and writeable: ``value`` itself where it is already such a float64 array,
        else a copy (a read-only or strided array is another type to the compiled one-point
        calls, which compiled them once more for it: 0.5-1.6 s, then cached on disk).
    """
    if type(value) is np.ndarray:
        if value.shape != (n,):
            return None
        if value.dtype is _F64 or value.dtype == np.float64:  # (identity first: 30 against 95 ns)
            # compiled_layout's test in one flag, which also asks for alignment (numba's typing does not see
            # it; an unaligned array, rare, is copied); about compiled_layout's cost (0.36-0.45 against 0.40-0.41
            # us a call in one process, 2026-11-30)
            return value if value.flags.carray else np.array(value, order="C")
        return value.astype(np.float64) if value.dtype.kind in "iuf" else None
    if isinstance(value, (tuple, list)) and len(value) == n:
        if type(value) is list or type(value) is tuple:  # (not a subclass, whose __array__ np.array would take)
            xs = tuple(value)  # (one read: the items checked are the items converted)
            for x in xs:  # Python floats only, the common case, straight to an array (1.2-1.4 against 1.7-2.1 us)
                if type(x) is not float:
                    break
            else:
                return np.array(xs, dtype=np.float64)
        xs = [plain_float(x, int64=int64) for x in value]
        return None if any(x is None for x in xs) else np.array(xs)
    return None
