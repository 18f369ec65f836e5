"""The validation functions' argument checks: an object of the wrong kind is a TypeError naming
the argument, not an AttributeError deep inside (``'NoneType' object has no attribute
'diameter'``: a bad-input audit, stop 104)."""

from __future__ import annotations

from ..core.geometry import Propeller
from ..core.solver import _check_params
from ..identify.load_data import LoadData
from ..io.catalogue import CatalogueEntry

_NOT_GIVEN = object()


def check_inputs(propeller, params: dict, *, data=_NOT_GIVEN, entry=_NOT_GIVEN) -> None:
    """Refuse arguments of the wrong type, each named.

    Parameters
    ----------
    propeller : Propeller
    params : dict
        Argument name -> parameter set (``{"generic": generic}``): each an AirfoilParams or
        CamberedParams.
    data : LoadData, optional
        Checked where given.
    entry : CatalogueEntry, optional
        Checked where given.

    Raises
    ------
    TypeError
        Naming the first argument of the wrong type.
    """
    if data is not _NOT_GIVEN and not isinstance(data, LoadData):
        raise TypeError(f"data must be a propmap LoadData (propmap.identify.loads_from_catalogue, read_loads, ...), "
                        f"got {type(data).__name__}")
    if entry is not _NOT_GIVEN and not isinstance(entry, CatalogueEntry):
        raise TypeError(f"entry must be a CatalogueEntry (propmap.catalogue()[name]), got {type(entry).__name__}")
    if not isinstance(propeller, Propeller):
        raise TypeError(f"propeller must be a Propeller (propmap.load_propeller, read_geometry), got "
                        f"{type(propeller).__name__}")
    for name, p in params.items():
        _check_params(p, name)


def check_names(name: str, values) -> list[str]:
    """``values`` as a list of str (one str is refused: "blind" was read as b, l, i, n, d), not
    empty; ValueError naming ``name`` otherwise (whether each names something is the caller's).

    Parameters
    ----------
    name : str
        The argument's name.
    values : iterable of str

    Returns
    -------
    list of str

    Raises
    ------
    ValueError
        One str, not an iterable, an empty one, or an item that is not a str.
    """
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise ValueError(f"{name} must be a list of names, got {values!r:.60}" +
                         (f" (give [{values!r}])" if isinstance(values, str) else ""))
    out = list(values)
    bad = [v for v in out if not isinstance(v, str)]
    if not out or bad:
        raise ValueError(f"{name}: " + (f"unknown {', '.join(map(repr, bad[:5]))}" if bad else "none given"))
    return out
