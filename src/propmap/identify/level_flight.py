"""Level-flight conditions (Gill & D'Andrea 2017, eqs 16-18): the data, their CSV reader and
the rotors' kinematics (the CSV rules and errors: identify/csvfile.py).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from ..vehicle import Vehicle, hub_velocities, rotor_geometry
from ..vehicle.layout import body_to_world, check_vehicle  # (body_to_world re-exported: the level-flight fit's)
from ._checks import first_length, float_array
from ..core._numbers import integer
from ..core.units import RPM
from .cells import _short
from .csvfile import _ROTOR_RE, RANGES, DataError, _Csv

__all__ = ["LevelFlightData", "read_level_flight", "body_to_world", "rotor_kinematics"]


@dataclass(frozen=True)
class LevelFlightData:
    """Steady level-flight conditions, one row each (Gill & D'Andrea 2017, Sec. III).

    Attributes
    ----------
    airspeed : ndarray, shape (N,)
        Horizontal speed along the heading [m/s], >= 0.
    pitch, roll : ndarray, shape (N,)
        Attitude [rad]; pitch nose-up positive (forward flight negative), roll right-wing-down positive.
    omega : ndarray, shape (N, n_rotors)
        Rotor rotation rates [rad/s], > 0, in the vehicle's rotor order.
    rates : ndarray, shape (N, 3)
        Body rates p, q, r [rad/s] (x forward, y left, z up).

    Raises
    ------
    ValueError
        Built by hand with an array that is not numbers of its shape (N the length of
        ``airspeed``, at least one rotor), a non-finite value, ``airspeed`` < 0 m/s, |pitch|
        or |roll| >= pi/2 rad (radians, not degrees) or ``omega`` <= 0 rad/s; the message
        names the field. (:func:`read_level_flight` checks the file's ranges too.)
    """

    airspeed: np.ndarray
    pitch: np.ndarray
    roll: np.ndarray
    omega: np.ndarray
    rates: np.ndarray

    def __post_init__(self):
        n = first_length("LevelFlightData", "airspeed", self.airspeed)
        rotors = np.shape(self.omega)[1] if np.ndim(self.omega) == 2 and np.shape(self.omega)[1] >= 1 else "n_rotors"
        shapes = {"airspeed": (n,), "pitch": (n,), "roll": (n,), "omega": (n, rotors), "rates": (n, 3)}
        arrays = {name: float_array("LevelFlightData", name, getattr(self, name), shape, row="condition")
                  for name, shape in shapes.items()}
        omega = arrays["omega"]
        if np.any(arrays["airspeed"] < 0):
            raise ValueError("LevelFlightData.airspeed must be >= 0 m/s (the speed along the heading)")
        for name in ("pitch", "roll"):
            a = arrays[name]
            if np.any(np.abs(a) >= np.pi / 2):
                raise ValueError(f"LevelFlightData.{name} must be in (-pi/2, pi/2) rad (radians, not degrees), "
                                 f"got {a[np.abs(a) >= np.pi / 2][0]:g}")
        if np.any(omega <= 0):
            raise ValueError(f"LevelFlightData.omega must be > 0 rad/s, got {omega[omega <= 0][0]:g}")
        for name, a in arrays.items():
            object.__setattr__(self, name, a)

    @property
    def n(self) -> int:
        """Number of conditions N."""
        return self.airspeed.size


def _rotor_order(column: str):
    """Sort key of rotor columns: rpm_1, rpm_2, ..., rpm_10, then any malformed name."""
    m = _ROTOR_RE.fullmatch(column)
    return (0, int(m.group(1)), column) if m else (1, 0, column)


#: the quantities read, and what a column of one of them in another unit or under its bare stem must be called
_READ = {"airspeed": "airspeed [m/s]", "pitch": "pitch_deg", "roll": "roll_deg", "p": "p, q, r [rad/s]",
         "q": "p, q, r [rad/s]", "r": "p, q, r [rad/s]"}
#: units after a stem that make a column one of those quantities (roll (deg), p_deg_s, airspeed_kmh)
_UNIT_SUFFIX = re.compile(r"[\s_(\[]*(deg|degs|degrees|°|rad|rads|radians|deg/s|degs/s|rad/s|deg_s|rad_s|dps|rps|"
                          r"km/?h|kmh|kph|mph|kn|kt|knots|m/s|ms|mps|ft/s|fps)[\s)\]]*")


def _refuse_near_misses(f: _Csv, what: str) -> None:
    """Refuse a column that is one of the quantities read in another unit or under its bare stem
    (``roll (deg)``, ``roll``, ``p (deg/s)``, ``airspeed_kmh``): it was ignored, its values read
    as 0 (an input fuzzing audit, 2026-11-27: a roll of 10 deg fitted as level). Other names on
    those stems (``pitch_cmd``, ``q (Pa)``, ``airspeed_std``) are not the quantity and stay
    unread, as is a column whose right name is already there."""
    for j, c in enumerate(f.columns):
        m = re.match(r"(airspeed|pitch|roll|p|q|r)(?![a-z0-9])(.*)", c)
        if not m or c in ("airspeed", "pitch_deg", "roll_deg", "p", "q", "r"):
            continue
        stem, rest = m.groups()
        want = _READ[stem]
        if "rate" in c:  # (pitch_rate, roll rate (deg/s): a body rate)
            stem, rest, want = "q", re.sub(r"[\s_]*rate", "", rest), _READ["p"]
        present = {"airspeed": "airspeed", "pitch": "pitch_deg", "roll": "roll_deg"}.get(stem, stem)
        if (rest == "" or _UNIT_SUFFIX.fullmatch(rest)) and present not in f.index:
            raise f.error(f"column {f.header[j]!r} is not read: the level-flight columns are airspeed [m/s], "
                          f"pitch_deg and roll_deg [deg], p, q, r [rad/s] and rpm_1 .. rpm_n [rpm], without other "
                          f"units; give this one as {want}", f.header_line)


def read_level_flight(path, vehicle: Vehicle, *, min_conditions: int = 6) -> LevelFlightData:
    """Read level-flight conditions: columns ``airspeed, pitch_deg, rpm_1 .. rpm_n``,
    optional ``roll_deg`` and body rates ``p, q, r`` [rad/s] (all three or none).

    Format and valid ranges in the module docstring.

    Parameters
    ----------
    path : str or Path
    vehicle : Vehicle
        Gives the rotor count n.
    min_conditions : int
        The fewest rows accepted, >= 1 (6 for a fit).

    Returns
    -------
    LevelFlightData

    Raises
    ------
    DataError
        Not a readable regular file (a directory, a device, over 200 MiB or 10,000,000
        lines), not UTF-8, a malformed CSV (unterminated quote, more fields than the
        header), a missing, duplicated or over-long column, a rotor count that does not
        match the vehicle, only some of ``p, q, r``, an empty, non-numeric or non-finite
        value, a value out of range (rpm outside (0, 954929], airspeed outside [0, 500] m/s, |pitch| or |roll|
        >= 90 deg, |p|, |q|, |r| > 100 rad/s), fewer than ``min_conditions`` rows, or all
        rows identical; the message names the file, the line and the column.
    ValueError
        ``min_conditions`` not an integer >= 1 (before the file is read).
    TypeError
        ``vehicle`` not a :class:`propmap.Vehicle`.
    """
    check_vehicle(vehicle)  # (None met an AttributeError after the file was read)
    min_conditions = integer("min_conditions", min_conditions, 1)
    what = "level-flight data"
    f = _Csv(path, what)
    p = f.name
    rpm_cols = sorted((c for c in f.index if c.startswith("rpm_")), key=_rotor_order)
    n_rot = len(vehicle.rotors)
    if rpm_cols != [f"rpm_{k}" for k in range(1, n_rot + 1)]:
        shown = ", ".join(_short(c) for c in rpm_cols[:8]) + (", ..." if len(rpm_cols) > 8 else "")
        raise DataError(f"{what}: {p} has rotor columns {'[' + shown + ']' if rpm_cols else 'none'}; the vehicle has "
                        f"{n_rot} rotors, so rpm_1 .. rpm_{n_rot} are needed")
    missing = [c for c in ("airspeed", "pitch_deg") if c not in f.index]
    if missing:
        raise DataError(f"{what}: {p} lacks column(s) {', '.join(missing)}")
    _refuse_near_misses(f, what)
    rates_given = [c for c in ("p", "q", "r") if c in f.index]
    if rates_given and len(rates_given) < 3:
        raise DataError(f"{what}: {p} has body-rate column(s) {', '.join(rates_given)} but not "
                        f"{', '.join(c for c in 'pqr' if c not in rates_given)}: give all of p, q, r or none")
    cols = ["airspeed", "pitch_deg", *rpm_cols, *(["roll_deg"] if "roll_deg" in f.index else []), *rates_given]
    v, _, lines = f.read(cols)
    f.check_ranges(v, lines, RANGES)
    n = lines.size
    if n < min_conditions:
        raise DataError(f"{what}: {p} has {n} conditions; at least {min_conditions} are needed")
    base = np.column_stack([v[c] for c in ["airspeed", "pitch_deg", *rpm_cols]])
    if np.all(np.ptp(base, axis=0) == 0):
        raise DataError(f"{what}: {p}: all conditions are identical; the parameters cannot be identified")
    roll = v["roll_deg"] if "roll_deg" in v else np.zeros(n)
    rates = np.column_stack([v[c] for c in "pqr"]) if rates_given else np.zeros((n, 3))
    rpm = base[:, 2:]
    return LevelFlightData(v["airspeed"], np.radians(v["pitch_deg"]), np.radians(roll), rpm * RPM, rates)


#: a rotor this many times slower or faster than its condition's median rotor speed is named
ROTOR_SPREAD = 3.0


def level_flight_warnings(data: LevelFlightData, vehicle: Vehicle) -> list[str]:
    """What in level-flight data looks mistyped, as warnings (none of it is refused: a vehicle
    may carry rotors of different sizes, a condition may be flown far from hover).

    Parameters
    ----------
    data : LevelFlightData
    vehicle : Vehicle

    Returns
    -------
    list of str
        A condition with a rotor more than ROTOR_SPREAD times slower or faster than the
        condition's median rotor speed (a truncated or mistyped value: 646 among 6470 rpm, an
        input fuzzing audit, 2026-11-27); rotor speeds whose rms over the conditions lies
        outside HOVER_RANGE (0.5-2.5) times the vehicle's hover speed with the generic set
        (rad/s in the rpm columns, the mass in grams), as the flight logs' check.
    """
    from .flight_samples import HOVER_RANGE, _hover_speed

    out = []
    om = np.asarray(data.omega, float)
    ratio = om / np.median(om, axis=1, keepdims=True)
    odd = np.argwhere((ratio > ROTOR_SPREAD) | (ratio < 1 / ROTOR_SPREAD))
    if odd.size:
        i, k = (int(v) for v in odd[0])
        out.append(f"data row {i + 1}: rpm_{k + 1} = {om[i, k] / RPM:.6g} is {ratio[i, k]:.2g} times the row's "
                   f"median rotor speed ({odd.shape[0]} such value(s)): a truncated or mistyped value?")
    hover = _hover_speed(vehicle)
    if hover > 0:
        rms = float(np.sqrt(np.mean(om**2)))
        if not HOVER_RANGE[0] * hover <= rms <= HOVER_RANGE[1] * hover:
            out.append(f"the rotors' rms speed is {rms / RPM:.5g} rpm, {rms / hover:.2g} times the vehicle's hover "
                       f"speed {hover / RPM:.5g} rpm (its mass {vehicle.mass:g} kg, the generic set): are the rpm "
                       "columns in rpm (not rad/s or rev/s) and the mass in kg?")
    return out


def check_level_flight(data, vehicle) -> None:
    """TypeError unless ``data`` is :class:`LevelFlightData` (:func:`read_level_flight`) and ``vehicle`` a
    :class:`propmap.Vehicle` (a wrong object met an AttributeError inside: a docstring-contract audit)."""
    if not isinstance(data, LevelFlightData):
        raise TypeError(f"data must be LevelFlightData (propmap.identify.read_level_flight), got {type(data).__name__}")
    check_vehicle(vehicle)


def rotor_kinematics(data: LevelFlightData, vehicle: Vehicle):
    """Body-frame hub velocities of every rotor: V_i = R^T V_vehicle + omega x r_i (Sec. III).

    Parameters
    ----------
    data : LevelFlightData
        N conditions: ``airspeed`` [m/s] along world x, ``pitch``, ``roll`` [rad] and body
        ``rates`` [rad/s], shape (N, 3).
    vehicle : Vehicle
        Its rotors' positions r_i [m] about its centre of mass, body frame.

    Returns
    -------
    R : ndarray, shape (N, 3, 3)
        Body-to-world rotations.
    velocity : ndarray, shape (N, n_rotors, 3)
        Hub velocity relative to still air, body frame [m/s].

    Raises
    ------
    TypeError
        ``data`` not :class:`LevelFlightData` or ``vehicle`` not a :class:`propmap.Vehicle`.
    """
    check_level_flight(data, vehicle)
    R = body_to_world(data.pitch, data.roll)
    v_world = np.stack([data.airspeed, np.zeros(data.n), np.zeros(data.n)], -1)
    v_body = np.einsum("nji,nj->ni", R, v_world)  # R^T v
    pos = rotor_geometry(vehicle)[0]  # (n_rot, 3), about the centre of mass
    vel = hub_velocities(v_body, data.rates, pos)
    return R, vel
