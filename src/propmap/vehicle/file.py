"""Vehicle files (TOML): a multirotor's mass, inertia, rotors and airframe drag.

Format (body frame: x forward, y left, z up; SI units)::

    mass = 0.8            # [kg], in (0, 1e4]
    gravity = 9.81        # [m/s^2], optional, in (0, 100]
    body_area = 0.02      # [m^2], optional, in [0, 100]: S_body of the body-lift option (Sec. III-A)
    inertia = [0.0025, 0.0021, 0.0043]   # [kg m^2], optional: the diagonal, or a symmetric
                                         # positive definite 3 x 3 list [[Ixx, Ixy, Ixz], ...]
    centre_of_mass = [0.0, 0.0, 0.0]     # [m], optional: where the centre of mass is in the frame
                                         # of the rotor positions (each in [-100, 100])
    motor_time_constant = 0.033          # [s], optional, in [0, 1]: first-order lag from a log's
                                         # motor speeds to the rotors' (flight logs only)
    rotor_interference = 1.0             # optional, in [0, 3]: factor on the inflow each rotor's
                                         # wake induces at the others (core/interference.py; default 0)
    params = "my_fit.toml"               # optional: the vehicle's own parameter set (a file, relative
                                         # to the vehicle file, e.g. a `fit flight` output, or a named
                                         # set): what the vehicle commands take without --params (below)

    [body]                # optional airframe drag (core/body.py)
    drag_area = [0.004, 0.004, 0.008]   # (C_D A) along body x, y, z [m^2], each in [0, 10]
    wash_factor = 1.0                   # slipstream factor kappa, in [0, 3]

    [[rotors]]
    position = [0.08, -0.08, 0.0]   # [m], hub in the frame of centre_of_mass (its origin), each in [-100, 100]
    axis = [0.0, 0.0, 1.0]          # thrust direction (normalised; length in [1e-6, 1e6])
    spin = "ccw"                    # about +axis (right-hand rule), or "cw"
    propeller = "apce_8x6"          # geometry file or catalogue name
    # blades = 3                    # with a geometry file: its blade count (1 to 100); a UIUC file needs it
    # diameter_m = 0.13             # with a UIUC geometry file, optional: its diameter [m], in (0, 100]
    #                               # (both refused with a catalogue propeller, whose geometry fixes them)
    params = "generic"              # optional: this rotor's parameter set (a file, relative to
                                    # the vehicle file, or a named set); default the set in use
    inertia = 9.4e-6                # optional: rotor + motor inertia about the axis [kg m^2],
                                    # in [0, 100] (gyroscopic and spin-up moments)

Numbers must be TOML integers or floats (a ``true`` or a quoted ``"0.8"`` is refused).
Free-text keys ``name``, ``comment`` and ``source`` are allowed at the top level, in
``[body]`` and in a rotor; any other unknown key is an error (a typo such as ``gravty`` is
never ignored).

``propeller`` (and ``params``, when it is not a named set) is resolved as follows: a
relative path is taken from the folder of the vehicle file (not from the working
directory), an absolute path as it is; if no file (or folder) of that name exists there,
the value must be a catalogue name (a named parameter set). A geometry file is read with
:func:`propmap.io.geometry_files.read_geometry` (a UIUC file takes its diameter from a
``<family>_<D>x<P>`` name unless ``diameter_m`` is given).

The top-level ``params`` is the vehicle's calibration, as a catalogue propeller's calibrated set is
the propeller's: the commands that model the vehicle (``wrench``, ``trim-vehicle``, ``map --format
c --vehicle``, and ``export-sim --vehicle`` where its PROP is the rotors' propeller) take it where
``--params`` is not given, its section set for every rotor without a ``params`` of its own and,
where it is a flight fit's file, its ``[body]`` table (airframe drag, centre of mass, wake
interference) in place of the vehicle file's, as they take a ``--params`` file (a vehicle file
that gives what that table gives too is refused). The fits (``fit flight``, ``fit level-flight``) fit their own set from
``--base`` and do not use it. :func:`read_vehicle` checks it (a readable parameter file or a named
set) but does not apply it; :func:`propmap.vehicle.own_set.resolve_vehicle` applies it as the
commands do (they call it).
"""

from __future__ import annotations

import difflib
import math
import numbers
import os
import re
from pathlib import Path

import numpy as np

from ..core._numbers import integer
from ..core.geometry import INCH, Propeller, short_repr
from ..core.body import BodyDrag
from ..io.inputs import as_path, short_path, show_path
from ..io.params_tables import POSITION_MAX  # [m], each component
from ..io.qprop_file import _qprop_from
from ..io.toml_file import did_you_mean, load_toml
from ._plausibility import _warn_implausible
from .layout import INERTIA_MAX, Rotor, Vehicle, check_inertia

__all__ = ["VehicleFileError", "read_vehicle", "rotor_file_specs"]

#: valid ranges (low, high, low open) of the vehicle's numbers
MASS_RANGE = (0.0, 1e4, True)  # [kg]
GRAVITY_RANGE = (0.0, 100.0, True)  # [m/s^2]
BODY_AREA_RANGE = (0.0, 100.0, False)  # [m^2]
AXIS_LENGTH_RANGE = (1e-6, 1e6)
ROTOR_INERTIA_RANGE = (0.0, 100.0, False)  # [kg m^2]
BLADES_RANGE = (1, 100)
DIAMETER_RANGE = (0.0, 100.0, True)  # [m]
TEXT_KEYS = ("name", "comment", "source")
MOTOR_TAU_RANGE = (0.0, 1.0, False)  # [s]
INTERFERENCE_RANGE = (0.0, 3.0, False)  # [-]
VEHICLE_KEYS = ("mass", "gravity", "body_area", "inertia", "centre_of_mass", "motor_time_constant",
                "rotor_interference", "params", "body", "rotors", *TEXT_KEYS)
BODY_KEYS = ("drag_area", "wash_factor", *TEXT_KEYS)
ROTOR_KEYS = ("position", "axis", "spin", "propeller", "blades", "diameter_m", "params", "inertia", *TEXT_KEYS)


class VehicleFileError(ValueError):
    """A vehicle file is malformed; the message names the file and the entry."""


def _is_number(value) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _float(value) -> float:
    """``float(value)`` of a real number; +-inf for an integer too large for a float."""
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def _number(value, what: str, unit: str, rng) -> float:
    lo, hi, lo_open = rng
    interval = f"{'>' if lo_open else '>='} {lo:g} and <= {hi:g} {unit}"
    if not _is_number(value):
        raise VehicleFileError(f"{what} must be a number {interval}, got {short_repr(value)}")
    x = _float(value)
    if not (math.isfinite(x) and (lo < x if lo_open else lo <= x) and x <= hi):
        raise VehicleFileError(f"{what} must be {interval}, got {short_repr(value)}")
    return x


def _vec3(value, what: str) -> np.ndarray:
    if not (isinstance(value, list) and len(value) == 3 and all(_is_number(v) for v in value)):
        raise VehicleFileError(f"{what} must be 3 numbers [x, y, z], got {short_repr(value)}")
    a = np.array([_float(v) for v in value])
    if not np.all(np.isfinite(a)):
        raise VehicleFileError(f"{what} must be 3 finite numbers, got {short_repr(value)}")
    return a


def _unknown(table: dict, allowed, where: str) -> None:
    extra = sorted(str(k) for k in table if k not in allowed)
    if extra:
        shown = ", ".join(k if k.isidentifier() else short_repr(k, 40) for k in extra[:5])
        raise VehicleFileError(f"{where}: unknown key(s) {shown}{did_you_mean(extra, allowed)} "
                               f"(allowed: {', '.join(allowed)})")


def _inertia(value, what: str) -> np.ndarray:
    """A 3 x 3 inertia tensor from a diagonal [a, b, c] or a nested 3 x 3 list [kg m^2]."""
    shape_msg = f"{what} must be [Ixx, Iyy, Izz] or a 3 x 3 list of numbers [kg m^2], got {short_repr(value)}"
    if isinstance(value, list) and len(value) == 3 and all(_is_number(v) for v in value):
        m = np.diag([_float(v) for v in value])
    elif (isinstance(value, list) and len(value) == 3
          and all(isinstance(row, list) and len(row) == 3 and all(_is_number(v) for v in row) for row in value)):
        m = np.array([[_float(v) for v in row] for row in value])
    else:
        raise VehicleFileError(shape_msg)
    if not np.all(np.isfinite(m)):
        raise VehicleFileError(f"{what} must have finite elements within +-{INERTIA_MAX:g} kg m^2, "
                               f"got {short_repr(value)}")
    try:  # (the Vehicle's own rule: the elements' range, symmetric, positive definite; the triangle warned of)
        check_inertia(m, what)
    except ValueError as exc:
        raise VehicleFileError(str(exc)) from None
    return m


def _body(table, name: str) -> BodyDrag:
    where = f"{name}: [body]"
    if not isinstance(table, dict):
        raise VehicleFileError(f"{where} must be a table with drag_area and optional wash_factor, "
                               f"got {short_repr(table)}")
    _unknown(table, BODY_KEYS, where)
    if "drag_area" not in table:
        raise VehicleFileError(f"{where}: missing key 'drag_area'")
    area = _vec3(table["drag_area"], f"{where} drag_area")
    try:
        return BodyDrag(drag_area=tuple(float(a) for a in area), wash_factor=table.get("wash_factor", 0.0))
    except ValueError as exc:
        raise VehicleFileError(f"{where}: {exc}") from None


def _blades(value, where: str) -> int:
    return integer(f"{where}: blades", value, *BLADES_RANGE, whole_float=False, error=VehicleFileError)


def _local_file(spec: str, folder: Path) -> Path | None:
    """The file a rotor's ``propeller`` or ``params`` entry names, relative to the vehicle file's
    ``folder`` (or absolute), where one exists; None: the entry is a name (catalogue, named set)."""
    local = folder / spec
    try:
        return local if "\x00" not in spec and os.path.lexists(local) else None
    except (OSError, ValueError):
        return None


def _rotor_params(spec, folder: Path, where: str, itself: Path):
    """A rotor's (or the vehicle's) own parameter set: a file relative to ``folder`` (or absolute),
    else a named set; refused where it is the vehicle file ``itself``."""
    from ..io.param_sets import resolve_params
    from ..io.params_file import ParamsFileError, read_params

    if not isinstance(spec, str) or not spec.strip():
        raise VehicleFileError(f"{where}: params must be a parameter file or a named set (a string), "
                               f"got {short_repr(spec)}")
    local = _local_file(spec, folder)
    if local is not None and os.path.realpath(local) == os.path.realpath(itself):  # (it was read as a parameter file,
        # its missing keys named: a flight-log audit, 2026-12-01)
        raise VehicleFileError(f"{where}: params: {short_path(spec, quote=True)} is this vehicle file itself; name a "
                               "parameter file (a fit's output, or [section] in TOML) or a named set")
    try:
        return read_params(local) if local is not None else resolve_params(_qprop_from(spec, folder))
    except (ParamsFileError, KeyError, ValueError) as exc:
        msg = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        if local is None and ":" not in spec:  # (a file not found, not a named set: where it was looked for)
            msg += f" ({short_path(folder / spec, 300)}: a relative path is taken from the vehicle file's folder)"
        raise VehicleFileError(f"{where}: params: {msg}") from None


def _own_params(spec, folder: Path, name: str, data: dict, itself: Path):
    """Check the vehicle's own parameter set (its top-level ``params``): readable, and not a file
    whose ``[body]`` table gives what the vehicle file ``data`` gives too (the airframe's drag, a
    centre of mass, the rotor interference: the set's would replace the file's without a word).
    Returns (the set, its file's ``[body]`` table or None), which resolve_vehicle applies."""
    from ..io.params_file import read_body

    own = _rotor_params(spec, folder, name, itself)
    local = _local_file(spec, folder)
    table = read_body(local) if local is not None else None
    if table is None:
        return own, None
    both = [key for key, theirs in (("[body]", table.drag), ("centre_of_mass", table.centre_of_mass),
                                    ("rotor_interference", table.rotor_interference))
            if theirs is not None and key.strip("[]") in data]
    if both:
        raise VehicleFileError(f"{name}: {', '.join(both)} and params: {short_path(spec, quote=True)}'s [body] table "
                               f"gives {'it' if len(both) == 1 else 'them'} too (a flight fit's airframe), which the "
                               "vehicle commands would take in place of the file's: give one of them")
    return own, table


def _propeller(spec, folder: Path, where: str, diameter_in: float | None = None,
               n_blades: int | None = None) -> Propeller:
    """The rotor's propeller: a file relative to ``folder`` (or absolute), else a catalogue name, else a size
    designation (``"5x4.5x3"``, inches: a nominal blade)."""
    from ..io.catalogue import catalogue, catalogue_sizes, load_propeller
    from ..io.geometry_files import read_geometry

    if not isinstance(spec, str) or not spec.strip():
        raise VehicleFileError(f"{where}: propeller must be a geometry file, a catalogue name or a size (a string), "
                               f"got {short_repr(spec)}")
    local = _local_file(spec, folder)
    if local is not None:
        from ..io.geometry_files import SIZE_HINT

        try:
            return read_geometry(local, diameter_in=diameter_in, n_blades=n_blades)
        except ValueError as exc:  # (the reader's hint names the CLI's size option: a rotor's key is diameter_m)
            msg = str(exc).replace(SIZE_HINT, "give the rotor's diameter_m [m] (or name the file "
                                              "<family>_<D>x<P>_geom.txt: D in inches, in mm for the ef, kpf, pl and "
                                              "vp families)").replace("give it (--blades, n_blades)",
                                                                      "give the rotor's blades")
            # (a PE0 file's refusal of a size, said in the CLI's inches and option: a rotor's key is diameter_m)
            msg = re.sub(r"diameter_in = ([-+0-9.e]+) in", lambda m: f"diameter_m = {float(m[1]) * 0.0254:.6g} m", msg)
            msg = re.sub(r"\(diameter ([-+0-9.e]+) in\)", lambda m: f"(diameter {float(m[1]) * 0.0254:.6g} m)", msg)
            msg = msg.replace("leave the option out (it applies to UIUC files), or give that diameter, to fewer "
                              "decimals if you like (within 2%)", "leave diameter_m out (it is for UIUC geometry "
                              "files)")
            raise VehicleFileError(f"{where}: propeller: {msg}") from None
    if spec in catalogue():
        if diameter_in is not None or n_blades is not None:
            raise VehicleFileError(f"{where}: blades and diameter_m are for geometry files; {spec!r} is a catalogue "
                                   "propeller, whose geometry states them")
        return load_propeller(spec)
    from ..io.nominal_geometry import parse_size, propeller_from_size

    if parse_size(spec) is not None:  # ("5x4.5x3": a nominal blade, said in a warning)
        if diameter_in is not None:
            raise VehicleFileError(f"{where}: diameter_m is for geometry files; the size designation {spec.strip()!r} "
                                   "gives the diameter")
        try:
            return propeller_from_size(spec, n_blades=n_blades, catalogue_sizes=catalogue_sizes())
        except ValueError as exc:
            raise VehicleFileError(f"{where}: propeller: {str(exc).replace(': n_blades = ', ': blades = ')}") from None
    near = difflib.get_close_matches(spec, list(catalogue()), n=3)
    hint = f"; did you mean {', '.join(near)}?" if near else " ('propmap props' lists the catalogue)"
    shown = short_path(folder / spec, 300)
    raise VehicleFileError(f"{where}: propeller {short_path(spec, quote=True)} is neither a file ({shown}: a relative "
                           f"path is taken from the vehicle file's folder) nor a catalogue name, nor a size such as "
                           f"5x4.5 (D x P in inches: a nominal blade){hint}")


#: how a bundled example parameter file's name ends (an example vehicle's own set), which is not a vehicle
EXAMPLE_PARAMS_SUFFIX = ".params.toml"


def _example_vehicles() -> tuple[str, ...]:
    from ..io.catalogue import example_files

    return tuple(n for n in example_files() if n.endswith(".toml") and not n.endswith(EXAMPLE_PARAMS_SUFFIX))


def _bare(path) -> bool:
    """Whether ``path`` is a name without a folder as written (pathlib reads './quadrotor' as
    'quadrotor': a folder given, a file meant, a review found)."""
    text = os.fspath(path)
    return isinstance(text, str) and "/" not in text and os.sep not in text


def vehicle_path(path) -> Path:
    """The vehicle file ``path`` names: itself, or where no such file exists and it is the bare
    name of a bundled example vehicle, without a folder or an extension (``quadrotor``,
    ``neurobem_quadrotor``; :func:`propmap.example_files`), that example's installed file. A
    name with ``.toml`` is a file name, never an example's (a user in another folder would get
    the example's vehicle without a word: a review).

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    pathlib.Path

    Raises
    ------
    TypeError
        ``path`` not a str or os.PathLike.
    """
    given = as_path(path)
    if _bare(path) and not given.suffix and not os.path.lexists(given):
        from ..io.catalogue import example_file

        try:
            found = example_file(given.name)
        except ValueError:
            return given
        if found.name in _example_vehicles():  # (not an example vehicle's parameter file)
            return found
    return given


def read_vehicle(path) -> Vehicle:
    """Read a vehicle TOML file (format, ranges and propeller resolution in the module docstring).

    Parameters
    ----------
    path : str or Path
        The file; where no such file exists, the bare name of a bundled example vehicle,
        without ``.toml`` (``"quadrotor"``, ``"neurobem_quadrotor"``: :func:`vehicle_path`).

    Returns
    -------
    Vehicle

    Raises
    ------
    TypeError
        ``path`` not a str or os.PathLike.
    VehicleFileError
        Not a readable regular file (a directory, a device, over 16 MiB), not UTF-8,
        invalid TOML, missing ``mass`` or ``rotors``, an unknown key, a value of the wrong
        type (a bool or a string for a number, a rotor that is not a table), a mass,
        gravity, body area, inertia, drag area, position, blade count, diameter or rotor
        inertia out of range, an inertia that is not symmetric positive definite, an axis
        of zero, non-finite or overflowing length, a bad spin, a propeller that is neither a
        readable geometry file nor a catalogue name, or a ``params`` (the vehicle's or a rotor's)
        that is neither a readable parameter file nor a named set, a ``[body]`` table beside a
        ``params`` file that has one (or a ``centre_of_mass`` or ``rotor_interference`` beside
        one that gives it), or every rotor axis pointing down (z < 0 in
        the body frame x forward, y left, z up: a z-down frame's axes); the message names the
        file, the rotor and the key.

    Warns
    -----
    UserWarning
        As :func:`propmap.io.geometry_files.read_uiuc_geometry` for a rotor's geometry file; a
        rotor more than ARM_RADII_MAX of its radii from the centre of mass (positions in mm?),
        two rotors at one position, an inertia whose largest principal moment lies outside
        INERTIA_ARM_RANGE times mass x (largest arm)^2 (g cm^2?) or whose principal moments
        break the triangle inequality (once per tensor: :func:`propmap.vehicle.layout.check_inertia`),
        four or more rotors of
        parallel axes (within 10 deg) all spinning one way; rotors pointing down (within 45
        deg of -z) beside rotors pointing up; a rotor inertia above mass x R^2 (g cm^2?).
    """
    return _read_vehicle(path)[0]


def _read_vehicle(path) -> tuple[Vehicle, dict, Path, tuple | None]:
    """(vehicle, the file's TOML table, the file, (its own set, that set's [body] table or None) or
    None where it names none): :func:`read_vehicle` with what it read, so that
    :func:`propmap.vehicle.own_set.resolve_vehicle` takes the entries and the set from the same
    reading (it read the set's file twice more until 2026-12-01)."""
    given, path = path, vehicle_path(path)
    name = show_path(path)
    data = _vehicle_table(given, path)
    _unknown(data, VEHICLE_KEYS, name)  # (first: 'weight = 0.772' was told only "missing key 'mass'", an audit)
    # (the rotors' tables likewise, _rotor)
    for key in ("mass", "rotors"):
        if key not in data:
            raise VehicleFileError(f"{name}: missing key {key!r}")
    mass = _number(data["mass"], f"{name}: mass", "kg", MASS_RANGE)
    gravity = _number(data.get("gravity", 9.81), f"{name}: gravity", "m/s^2", GRAVITY_RANGE)
    area = _number(data.get("body_area", 0.0), f"{name}: body_area", "m^2", BODY_AREA_RANGE)
    inertia = _inertia(data["inertia"], f"{name}: inertia") if "inertia" in data else None
    body = _body(data["body"], name) if "body" in data else None
    cg = _vec3(data["centre_of_mass"], f"{name}: centre_of_mass") if "centre_of_mass" in data else np.zeros(3)
    if np.any(np.abs(cg) > POSITION_MAX):
        raise VehicleFileError(f"{name}: centre_of_mass must have components in [-{POSITION_MAX:g}, {POSITION_MAX:g}] "
                               f"m, got {short_repr(data['centre_of_mass'])}")
    tau = _number(data.get("motor_time_constant", 0.0), f"{name}: motor_time_constant", "s", MOTOR_TAU_RANGE)
    kappa = _number(data.get("rotor_interference", 0.0), f"{name}: rotor_interference", "", INTERFERENCE_RANGE)
    own = None
    if "params" in data:  # (checked, not applied: the vehicle commands' default of --params, module docstring)
        own = _own_params(data["params"], path.parent, name, data, path)
    rotors, props = [], {}
    if not isinstance(data["rotors"], list) or not data["rotors"]:
        raise VehicleFileError(f"{name}: 'rotors' must be a non-empty array of tables ([[rotors]])")
    for k, r in enumerate(data["rotors"], start=1):
        rotors.append(_rotor(r, f"{name}: rotor {k}", path, props))
    text = {k: str(data[k]) for k in ("name", "source") if isinstance(data.get(k), str)}
    if all(r.axis[2] < 0 for r in rotors):  # (every axis [0, 0, -1], a z-down frame's habit: wrench scored it, a fit
        # wrote a file: a flight-log audit, 2026-11-27; a horizontal axis, a fixed wing's or a tilt-rotor's, is read)
        raise VehicleFileError(f"{name}: every rotor's axis points down (z < 0): each rotor's thrust acts along its "
                               "axis in the body frame x forward, y left, z up, so this vehicle cannot lift itself; a "
                               "z-down frame's (FRD, PX4's) axis [0, 0, -1] is [0, 0, 1] here")
    _warn_implausible(name, rotors, mass, inertia, cg, kappa)
    # (the inertia's triangle, if broken, was warned of above naming the file, and is not again)
    return Vehicle(mass=mass, rotors=tuple(rotors), gravity=gravity, body_area=area, inertia=inertia, body_drag=body,
                   centre_of_mass=cg, motor_time_constant=tau, rotor_interference=kappa, **text), data, path, own


def _vehicle_table(given, path: Path) -> dict:
    """The vehicle file's TOML table; where the file cannot be read and ``given`` was a bare name, the
    message says so and names the bundled example vehicles (or that an example is named without
    .toml)."""
    try:
        return load_toml(path, VehicleFileError)
    except VehicleFileError as exc:
        if os.path.lexists(path) or not _bare(given):
            raise
        examples = [n[:-5] for n in _example_vehicles()]
        if path.suffix:  # (a file name: the bundled example of that stem is named without .toml, docs/flight.md)
            if path.suffix.lower() == ".toml" and path.stem in examples:
                raise VehicleFileError(f"{exc} here (the bundled example vehicle of that name is given without "
                                       f".toml: {path.stem})") from None
            raise
        raise VehicleFileError(f"{exc} (nor a bundled example vehicle: {', '.join(examples)})") from None


def _rotor(r, where: str, path: Path, props: dict) -> Rotor:
    """One ``[[rotors]]`` table as a :class:`Rotor` (``where``: the file and rotor, for messages); its
    propeller read once per (propeller, diameter, blades) of the file, its set per entry, in ``props``."""
    if not isinstance(r, dict):
        raise VehicleFileError(f"{where} must be a table ([[rotors]] with position, axis, spin, propeller), "
                               f"got {short_repr(r)}")
    _unknown(r, ROTOR_KEYS, where)  # (first: 'location' was told only "missing key 'position'", a review)
    for key in ("position", "axis", "spin", "propeller"):
        if key not in r:
            raise VehicleFileError(f"{where}: missing key {key!r}")
    position = _vec3(r["position"], f"{where} position")
    if np.any(np.abs(position) > POSITION_MAX):
        raise VehicleFileError(f"{where} position must have components in [-{POSITION_MAX:g}, {POSITION_MAX:g}] "
                               f"m, got {short_repr(r['position'])} (are the positions in metres?)")
    axis = _vec3(r["axis"], f"{where} axis")
    lo, hi = AXIS_LENGTH_RANGE
    scale = float(np.max(np.abs(axis)))
    length = scale * float(np.linalg.norm(axis / scale)) if scale > 0 else 0.0
    if not (lo <= length <= hi):
        raise VehicleFileError(f"{where}: axis must be non-zero with a length in [{lo:g}, {hi:g}] (a direction; "
                               f"it is normalised), got {short_repr(r['axis'])}")
    spin = r["spin"]
    spin = {"ccw": 1.0, "cw": -1.0}.get(spin.lower()) if isinstance(spin, str) else None
    if spin is None:
        raise VehicleFileError(f"{where}: spin must be 'cw' or 'ccw', got {short_repr(r['spin'])}")
    blades = _blades(r["blades"], where) if "blades" in r else None
    diameter = _number(r["diameter_m"], f"{where} diameter_m", "m", DIAMETER_RANGE) if "diameter_m" in r else None
    # (one object per propeller of the file: vehicle_wrench solves a propeller's rotors together by identity)
    spec = (repr(r["propeller"]), diameter, blades)
    if spec not in props:
        props[spec] = _propeller(r["propeller"], path.parent, where, None if diameter is None else diameter / INCH,
                                 blades)
    prop = props[spec]
    key = ("params", repr(r.get("params")))  # (a set the rotors share read once, as their propeller: stop 96)
    if "params" in r and key not in props:
        props[key] = _rotor_params(r["params"], path.parent, where, path)
    params = props[key] if "params" in r else None
    j_r = _number(r["inertia"], f"{where} inertia", "kg m^2", ROTOR_INERTIA_RANGE) if "inertia" in r else None
    return Rotor(position, axis, spin, prop, params=params, inertia=j_r)  # (Rotor normalises the axis)


def rotor_file_specs(path, key: str = "params") -> tuple[str | None, ...]:
    """Each rotor's ``params`` (or ``propeller``) entry as :func:`read_vehicle` resolves it, for
    labels, coverage and the inputs a command must not write over.

    Parameters
    ----------
    path : str or Path
        A vehicle file (read it with :func:`read_vehicle` for the full check).
    key : {"params", "propeller"}

    Returns
    -------
    tuple of (str or None)
        Per rotor, in the file's order: the file's path (relative to the vehicle's folder,
        where it exists) or the name (a named set, a catalogue propeller); None where the rotor
        has no such entry (``params``: it takes the set passed to the model).

    Raises
    ------
    VehicleFileError
        The file cannot be read as TOML.
    """
    path = vehicle_path(path)
    return _entry_specs(load_toml(path, VehicleFileError), path.parent, key)


def _entry_specs(data: dict, folder: Path, key: str) -> tuple[str | None, ...]:
    """:func:`rotor_file_specs` of a vehicle file's table ``data`` (its folder ``folder``)."""
    rotors = data.get("rotors")
    return tuple(_resolved_spec(r.get(key) if isinstance(r, dict) else None, folder)
                 for r in (rotors if isinstance(rotors, list) else ()))


def _resolved_spec(spec, folder: Path) -> str | None:
    """A ``propeller`` or ``params`` entry as the reader resolves it: the file's path (relative to
    ``folder``, where it exists there) or the name; None where it is no text."""
    if not isinstance(spec, str) or not spec.strip():
        return None
    local = _local_file(spec, folder)
    return _qprop_from(spec, folder) if local is None else str(local)
