"""Identification data: load measurements from the catalogue and UIUC files; the load data's
type (identify/load_data.py), the thrust-stand CSV reader (identify/loads_csv.py), the sanity
check of any load data against the model (identify/sanity.py) and the level-flight conditions
(eqs 16-18, identify/level_flight.py) are importable from here too.

Readers raise :class:`DataError` (a ValueError) with a one-line message naming the file,
the line and the column, and for a value out of range the valid range; no other exception
escapes for any file content, and no reader modifies its input. The CSV rules (size,
encoding, quoting, column names, number syntax) and the valid ranges of every column are in
identify/csvfile.py.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from ..core.units import RPM
from ..core._numbers import checked
from ..core.air import check_air
from ..core.airfoil import Air
from ..io.catalogue import CatalogueEntry, get_entry
from ..io.inputs import first_copy, show_path
from .csvfile import DataError, RANGES
from .level_flight import LevelFlightData, body_to_world, read_level_flight, rotor_kinematics
from .load_data import LoadData
from .loads_csv import read_loads
from .sanity import DRAG_SIGN_REFUSED, RE75_FLOOR, SANITY_FACTOR, SANITY_WARN, sanity_check

__all__ = ["DataError", "LevelFlightData", "LoadData", "read_level_flight", "read_loads", "loads_from_catalogue",
           "loads_from_uiuc_files", "body_to_world", "rotor_kinematics", "sanity_check", "SANITY_FACTOR", "SANITY_WARN",
           "RE75_FLOOR", "DRAG_SIGN_REFUSED"]


def loads_from_catalogue(entry: CatalogueEntry, diameter: float, *, air: Air = Air()) -> LoadData:
    """UIUC static runs and axial J-sweeps of a catalogue propeller as thrust and torque.

    T = CT rho n^2 D^4, Q = CP rho n^2 D^5 / (2 pi), V = J n D, incidence 0; groups are
    the UIUC run ids (e.g. ``"2801rd"``; static runs ``"static_<id>"``).

    Parameters
    ----------
    entry : CatalogueEntry or str
        Its bundled UIUC static runs and J-sweeps (:func:`propmap.io.catalogue.get_entry`), or
        the propeller's name in the catalogue (``"apce_8x6"``).
    diameter : float
        Propeller diameter [m] (the coefficients' reference length), in (0, 10].
    air : Air
        Its density ``rho`` [kg/m^3] converts the coefficients.

    Returns
    -------
    LoadData
        Static points first, then the sweeps' points: ``omega`` [rad/s], ``airspeed``
        [m/s], ``incidence`` 0 [rad], ``measured`` with ``thrust`` [N] and ``torque``
        [N m], each shape (N,); ``source`` the entry's name and citation.

    Raises
    ------
    DataError
        The entry has no bundled measurements; a ``diameter`` outside (0, 10] m; or
        converted loads out of the ranges of :func:`read_loads` (|thrust| > 1e5 N, |torque|
        > 1e4 N m, airspeed outside [0, 500] m/s), the message naming the run's file.
    KeyError
        A name that is not a catalogue propeller's (the message offers near names).
    TypeError
        ``entry`` neither a CatalogueEntry nor a string, ``air`` not an :class:`Air`.
    """
    if isinstance(entry, str):  # (a name met an AttributeError, a user-level audit, 2026-11-30)
        entry = get_entry(entry)
    if not isinstance(entry, CatalogueEntry):
        raise TypeError(f"entry must be a CatalogueEntry (propmap.io.catalogue.get_entry) or a catalogue propeller's "
                        f"name, got {type(entry).__name__}")
    check_air(air)
    diameter = checked("diameter", diameter, 0.0, 10.0, low_open=True, unit="m", error=DataError)
    return _loads_from_runs(entry.static_runs(), entry.sweeps(), diameter, air, entry.name,
                            f"{entry.name}: {entry.citation}")


def loads_from_uiuc_files(paths, diameter: float, *, air: Air = Air()) -> LoadData:
    """UIUC-format static (``RPM CT CP``) and wind-tunnel (``J CT CP eta``) files as thrust and torque.

    Each file's kind is recognised from its header; extra header and ``key = value``
    lines (``RPM average = 4042``) are accepted (io.readers). Conversion as
    :func:`loads_from_catalogue`.

    Parameters
    ----------
    paths : sequence of str or Path
    diameter : float
        Propeller diameter [m] (the coefficients' reference length), in (0, 10].
    air : Air

    Returns
    -------
    LoadData

    Raises
    ------
    TypeError
        ``paths`` a single path (a str, bytes or path-like) or not iterable: give a list;
        ``air`` not an :class:`Air`.
    DataError
        A file that is neither kind, or malformed (as :func:`propmap.io.readers.read_uiuc_static`
        and :func:`~propmap.io.readers.read_uiuc_sweep`: not a readable regular file,
        non-numeric or non-finite values, RPM outside (0, 954929], CT or CP outside
        [-10, 10], J outside [0, 20]); a file given twice (the same file under two names,
        or a byte-identical copy); a ``diameter`` outside (0, 10] m; or converted
        loads out of the ranges of :func:`read_loads` (|thrust| > 1e5 N, |torque| > 1e4
        N m, airspeed > 500 m/s). The message names the file.
    """
    from ..io.readers import MeasurementFileError, read_uiuc_static, read_uiuc_sweep

    # (a single path was read one character at a time: "/: is a directory, not a file", a Path was a TypeError from
    # inside, and a generator's file names were gone from the source: a mutation audit, 2026-11-29)
    if isinstance(paths, (str, bytes, os.PathLike)) or not hasattr(paths, "__iter__"):
        raise TypeError(f"paths must be a sequence of file paths, got {type(paths).__name__} {str(paths)!r:.80} "
                        "(give a list: [path])")
    paths = list(paths)
    check_air(air)  # (air=1.2 met "'float' object has no attribute 'rho'"; as loads_from_catalogue)
    diameter = checked("diameter", diameter, 0.0, 10.0, low_open=True, unit="m", error=DataError)
    try:  # (a file listed twice counted its points twice, its standard errors 0.75-0.85x: an API audit, stop 100)
        copy = first_copy(paths)
    except OSError:
        copy = None  # (a missing or unreadable file: its reader names it below)
    if copy is not None:
        p, what, earlier = copy
        raise DataError(f"paths: {show_path(p)} is {what} {show_path(earlier)}: its points would count twice")
    statics, sweeps, static_files, sweep_files = [], [], [], []
    for p in paths:
        p = Path(p)
        try:
            try:
                statics.append(read_uiuc_static(p))
                static_files.append(show_path(p))
            except MeasurementFileError as static_exc:
                try:
                    sweeps.append(read_uiuc_sweep(p))
                    sweep_files.append(show_path(p))
                except MeasurementFileError as sweep_exc:
                    # (decided on the errors' found_header, which is set only where a file lacks the reader's
                    # header, not on their messages' text: a file or folder named "expected columns" was misread)
                    if sweep_exc.found_header is not None and static_exc.found_header is None:
                        raise static_exc from None
                    if sweep_exc.found_header is not None:
                        found = sweep_exc.found_header
                        raise DataError(f"{show_path(p)}: not a UIUC static (RPM CT CP) or wind-tunnel (J CT CP eta) "
                                        "file" + (f": its header is {found}; UIUC's columns come in that order, "
                                                  "a wind-tunnel run with its eta column" if found else "")) from None
                    raise
        except MeasurementFileError as exc:
            raise DataError(str(exc)) from None
    source = "UIUC-format files " + ", ".join(Path(p).name for p in paths)
    return _loads_from_runs(statics, sweeps, float(diameter), air, "UIUC files", source, [*static_files, *sweep_files])


def _loads_from_runs(statics, sweeps, diameter, air, name, source, files=None) -> LoadData:
    """Thrust and torque from the runs' coefficients; ``files``: each run's file (statics, then sweeps)."""
    om, V, T, Q, grp = [], [], [], [], []
    labels = [f"static_{s.run_id}" for s in statics] + [w.run_id for w in sweeps]
    if files is not None and len(set(labels)) < len(labels):  # (two files of one run name, e.g. sweep_4000.txt and
        # sweep_6000.txt, both run 'sweep': each file its own group, named by its stem, so that one can be held out)
        labels = [Path(f).stem if labels.count(lab) > 1 else lab for lab, f in zip(labels, files)]
    for s, label in zip(statics, labels):  # (omega as rpm * RPM, every conversion's: nomenclature.md)
        n = s.rpm / 60
        om.append(s.rpm * RPM), V.append(0 * n), grp.append(np.full(n.size, label))
        T.append(s.CT * air.rho * n**2 * diameter**4), Q.append(s.CP * air.rho * n**2 * diameter**5 / (2 * math.pi))
    for w, label in zip(sweeps, labels[len(statics):]):
        n = np.full(w.J.size, w.rpm / 60)
        om.append(np.full(w.J.size, w.rpm * RPM)), V.append(w.J * n * diameter), grp.append(np.full(n.size, label))
        T.append(w.CT * air.rho * n**2 * diameter**4), Q.append(w.CP * air.rho * n**2 * diameter**5 / (2 * math.pi))
    if not om:
        raise DataError(f"{name} has no measurements")
    runs = [*statics, *sweeps]
    files = files or [run.source for run in runs]
    for label, arrays in (("thrust", T), ("torque", Q), ("airspeed", V)):
        lo, hi, _, _, unit = RANGES[label]
        for file, x in zip(files, arrays):
            if np.any((x < lo) | (x > hi)):  # coefficients, rpm and J are bounded: never NaN
                bad = float(x[np.argmax((x < lo) | (x > hi))])
                raise DataError(f"{file}: {label} {bad:.4g} {unit} (from the coefficients, the rpm and the diameter "
                                f"{diameter:g} m) is outside [{lo:g}, {hi:g}] {unit}")
    omega = np.concatenate(om)
    return LoadData(omega, np.concatenate(V), np.zeros(omega.size),
                    {"thrust": np.concatenate(T), "torque": np.concatenate(Q)}, np.concatenate(grp), source)
