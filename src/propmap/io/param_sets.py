"""Named parameter sets: what ``--params NAME`` and :func:`resolve_params` accept.

The paper's Table I sets (``gill2017-soft``, ``gill2017-stiff``, ``gill2017-apc``), the
catalogue's cambered ``generic`` set and each propeller's ``calibrated:<name>`` set
(io/calibration.py, fitted to the bundled UIUC measurements), the symmetric section presets
``section:<name>`` (data/sections/presets.toml; Sheldahl & Klimas, Sandia SAND80-2114, 1981),
the section aero lines of a QPROP propeller file, ``qprop:<file>`` (io/qprop_file.py), or a
parameter file's path (io/params_file.py reads and writes the files).
"""

from __future__ import annotations

import os
from pathlib import Path

from ..core.airfoil import PRESETS, CamberedParams, SectionParams
from .blade_stations import GeometryFileError
from .params_file import SECTION_PREFIX, _section_tables, params_from_dict, read_params
from .qprop_file import QPROP_PREFIX, read_qprop_params

__all__ = ["named_sets", "resolve_params", "section_preset", "section_presets"]


def named_sets() -> tuple[str, ...]:
    """Names :func:`resolve_params` accepts besides files (for messages and help).

    Returns
    -------
    tuple of str
    """
    return (*PRESETS, "generic", "calibrated:<catalogue name>", *(SECTION_PREFIX + k for k in _section_tables()),
            QPROP_PREFIX + "<QPROP propeller file>")


def section_presets() -> dict[str, str]:
    """The named section presets and their sources.

    Returns
    -------
    dict
        name -> source (the published data and how the parameters were derived).
    """
    return {k: v["source"] for k, v in _section_tables().items()}


def section_preset(name: str) -> CamberedParams:
    """A named section's cambered-polar parameters (symmetric NACA sections).

    Fitted by tools/fit_section_presets.py to the tables of Sheldahl & Klimas, "Aerodynamic
    Characteristics of Seven Symmetrical Airfoil Sections Through 180-Degree Angle of
    Attack", Sandia SAND80-2114 (1981), at chord Reynolds numbers 1.6e5-1e6 (NACA 0015,
    0018) or 3.6e5 (NACA 0012, whose Reynolds exponents are the NACA 0015 fit's), reference
    3.6e5; zero-lift angle 0, tip loss on, empirical descent inflow. The fit's errors are in
    the preset's ``comment`` (docs/models.md).

    Parameters
    ----------
    name : str
        ``naca0012``, ``naca0015`` or ``naca0018`` (:func:`section_presets` lists them).

    Returns
    -------
    CamberedParams

    Raises
    ------
    KeyError
        An unknown name; the message lists the valid ones.
    """
    tables = _section_tables()
    if name not in tables:
        raise KeyError(f"unknown section preset {name!r}; valid: {', '.join(tables)}")
    return params_from_dict({k: v for k, v in tables[name].items()}, where=f"section preset {name}",
                            label=SECTION_PREFIX + name)


def resolve_params(spec: str) -> SectionParams:
    """A named parameter set or a parameter file path, as a record carrying its air and label.

    Named sets: the paper's Table I (``gill2017-soft``, ``gill2017-stiff``,
    ``gill2017-apc``), the catalogue-fitted ``generic`` cambered set,
    ``calibrated:<name>``, a catalogue propeller's own calibrated set,
    ``section:<name>``, a symmetric section preset (:func:`section_preset`), and
    ``qprop:<file>``, the section aero lines of a QPROP propeller file
    (:func:`propmap.io.qprop_file.read_qprop_params`, labelled with the whole spec).

    Parameters
    ----------
    spec : str
        One of the names above, or the path of a parameter file (:func:`read_params`).

    Returns
    -------
    AirfoilParams or CamberedParams
        The set, with its air (``.air``) and its name or path as ``.label``.

    Raises
    ------
    KeyError
        Neither a named set nor an existing file.
    TypeError
        ``spec`` neither a string nor a path.
    ParamsFileError
        Malformed file.
    GeometryFileError
        ``qprop:<file>``: a malformed QPROP file, or one whose section values lie outside the
        cambered set's ranges.

    Notes
    -----
    A PathLike is read as a parameter file (:func:`read_params`: ParamsFileError where it is
    not one or does not exist), and so is a name that exists but is no regular file (a folder,
    a device, a pipe: the reader names what it is; they read as "not a named set nor an existing
    file" until 2026-11-26).
    """
    from ..core.airfoil import preset
    from .calibration import GENERIC, calibrated, generic_params

    if isinstance(spec, os.PathLike):  # (a parameter file as a Path)
        return read_params(spec)
    if not isinstance(spec, str):
        raise TypeError(f"spec must be a set's name or a parameter file's path (str or os.PathLike), got "
                        f"{type(spec).__name__}")
    if spec in PRESETS:
        return preset(spec)
    if spec == GENERIC:
        return generic_params()
    if spec.startswith(SECTION_PREFIX):
        return section_preset(spec[len(SECTION_PREFIX):])
    if spec.startswith(QPROP_PREFIX):
        if not spec[len(QPROP_PREFIX):].strip():  # (Path("") is the working directory)
            raise GeometryFileError(f"{spec!r} names no file: give qprop:FILE, a QPROP propeller file")
        return read_qprop_params(spec[len(QPROP_PREFIX):], label=spec)
    if spec.startswith("calibrated:"):
        name = spec.split(":", 1)[1]
        c = calibrated(name)
        if c is None:
            from .calibration import calibration
            from .catalogue import catalogue, near_names

            if name in catalogue():  # (it was offered as its own near name, a user-level audit, 2026-11-30)
                raise KeyError(f"unknown parameters {spec!r}: the catalogue's {name!r} has no calibrated set (its "
                               f"measurements, static runs only, do not calibrate one); its default set is {GENERIC!r}")
            raise KeyError(f"unknown parameters {spec!r}: {name!r} has no calibrated set"
                           f"{near_names(name, calibration()['propellers'])}")
        return c.params
    # a file; /dev/null, a folder, a FIFO too: the file reader names what it is (is_file raises on a name too long,
    # which the command line says as such; lexists would call it no file)
    if Path(spec).is_file() or os.path.lexists(spec):
        return read_params(spec)
    raise KeyError(f"unknown parameters {spec!r}: not a named set ({', '.join(named_sets())}) nor an existing file")
