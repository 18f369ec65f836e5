"""Identification data: level-flight conditions (eqs 16-18) and load measurements.

Readers raise :class:`DataError` (a ValueError) naming the file, line or column.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..core.airfoil import Air
from ..io.catalogue import CatalogueEntry
from .vehicle import Vehicle

__all__ = ["DataError", "LevelFlightData", "LoadData", "read_level_flight", "read_loads", "loads_from_catalogue",
           "loads_from_uiuc_files", "body_to_world", "rotor_kinematics"]

RPM = 2 * math.pi / 60


class DataError(ValueError):
    """Bad identification data; the message names the problem."""


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
    """

    airspeed: np.ndarray
    pitch: np.ndarray
    roll: np.ndarray
    omega: np.ndarray
    rates: np.ndarray

    @property
    def n(self) -> int:
        """Number of conditions N."""
        return self.airspeed.size


def _frame(path, what) -> pd.DataFrame:
    try:
        df = pd.read_csv(path, skipinitialspace=True)
    except FileNotFoundError:
        raise DataError(f"{what}: no such file {path}") from None
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise DataError(f"{what}: cannot parse {path} ({str(exc).splitlines()[0]})") from None
    df.columns = [str(c).strip() for c in df.columns]
    return df


def _numeric(df: pd.DataFrame, cols, path, what) -> np.ndarray:
    out = []
    for c in cols:
        v = pd.to_numeric(df[c], errors="coerce").to_numpy(float)
        bad = ~np.isfinite(v)
        if bad.any():
            line = int(np.argmax(bad)) + 2  # header is line 1
            raise DataError(f"{what}: {path}, line {line}: column {c!r} is missing, NaN or non-numeric")
        out.append(v)
    return np.column_stack(out)


def read_level_flight(path, vehicle: Vehicle, *, min_conditions: int = 6) -> LevelFlightData:
    """Read level-flight conditions: columns ``airspeed, pitch_deg, rpm_1 .. rpm_n``,
    optional ``roll_deg`` and body rates ``p, q, r`` [rad/s].

    Raises
    ------
    DataError
        Missing columns, NaN or non-numeric values (naming the line), a rotor count that
        does not match the vehicle, fewer than ``min_conditions`` rows, all rows identical,
        or values out of range (rpm <= 0, airspeed < 0, |pitch| or |roll| >= 90 deg).
    """
    what = "level-flight data"
    df = _frame(path, what)
    rpm_cols = sorted((c for c in df.columns if c.startswith("rpm_")), key=lambda c: int(c[4:]) if c[4:].isdigit() else 0)
    n_rot = len(vehicle.rotors)
    if len(rpm_cols) != n_rot or rpm_cols != [f"rpm_{k}" for k in range(1, n_rot + 1)]:
        raise DataError(f"{what}: {path} has rotor columns {rpm_cols or 'none'}; the vehicle has {n_rot} rotors, "
                        f"so rpm_1 .. rpm_{n_rot} are needed")
    missing = [c for c in ("airspeed", "pitch_deg") if c not in df.columns]
    if missing:
        raise DataError(f"{what}: {path} lacks column(s) {', '.join(missing)}")
    base = _numeric(df, ["airspeed", "pitch_deg", *rpm_cols], path, what)
    roll = _numeric(df, ["roll_deg"], path, what)[:, 0] if "roll_deg" in df.columns else np.zeros(len(df))
    rates = _numeric(df, ["p", "q", "r"], path, what) if {"p", "q", "r"} <= set(df.columns) else np.zeros((len(df), 3))
    if len(df) < min_conditions:
        raise DataError(f"{what}: {path} has {len(df)} conditions; at least {min_conditions} are needed")
    if np.all(np.ptp(base, axis=0) == 0):
        raise DataError(f"{what}: {path}: all conditions are identical; the parameters cannot be identified")
    V, pitch_deg, rpm = base[:, 0], base[:, 1], base[:, 2:]
    if np.any(rpm <= 0):
        raise DataError(f"{what}: {path}, line {int(np.argmax(np.any(rpm <= 0, axis=1))) + 2}: rpm must be > 0")
    if np.any(V < 0):
        raise DataError(f"{what}: {path}, line {int(np.argmax(V < 0)) + 2}: airspeed must be >= 0 m/s")
    if np.any(np.abs(pitch_deg) >= 90) or np.any(np.abs(roll) >= 90):
        raise DataError(f"{what}: {path}: pitch_deg and roll_deg must be in (-90, 90)")
    return LevelFlightData(V, np.radians(pitch_deg), np.radians(roll), rpm * RPM, rates)


def body_to_world(pitch, roll) -> np.ndarray:
    """Rotation matrices R (shape (N, 3, 3)) taking body vectors to the level world frame.

    Frames: x forward, y left, z up (heading along world x). Nose-up pitch is a rotation
    about +y by -pitch; right-wing-down roll a rotation about +x by +roll; R = Ry(-pitch) Rx(roll).
    """
    p = -np.asarray(pitch, float)
    r = np.asarray(roll, float)
    cp, sp, cr, sr = np.cos(p), np.sin(p), np.cos(r), np.sin(r)
    z, o = np.zeros_like(p), np.ones_like(p)
    Ry = np.stack([np.stack([cp, z, sp], -1), np.stack([z, o, z], -1), np.stack([-sp, z, cp], -1)], -2)
    Rx = np.stack([np.stack([o, z, z], -1), np.stack([z, cr, -sr], -1), np.stack([z, sr, cr], -1)], -2)
    return Ry @ Rx


def rotor_kinematics(data: LevelFlightData, vehicle: Vehicle):
    """Body-frame hub velocities of every rotor: V_i = R^T V_vehicle + omega x r_i (Sec. III).

    Returns
    -------
    R : ndarray, shape (N, 3, 3)
        Body-to-world rotations.
    velocity : ndarray, shape (N, n_rotors, 3)
        Hub velocity relative to still air, body frame [m/s].
    """
    R = body_to_world(data.pitch, data.roll)
    v_world = np.stack([data.airspeed, np.zeros(data.n), np.zeros(data.n)], -1)
    v_body = np.einsum("nji,nj->ni", R, v_world)  # R^T v
    pos = np.stack([r.position for r in vehicle.rotors])  # (n_rot, 3)
    vel = v_body[:, None, :] + np.cross(data.rates[:, None, :], pos[None, :, :])
    return R, vel


@dataclass(frozen=True)
class LoadData:
    """Direct load measurements of one propeller.

    Attributes
    ----------
    omega, airspeed, incidence : ndarray, shape (N,)
        Operating points [rad/s, m/s, rad].
    measured : dict[str, ndarray]
        Any non-empty subset of ``thrust`` [N], ``drag`` [N], ``torque`` [N m], each shape (N,).
    group : ndarray of str, shape (N,)
        Run label of each point (for hold-out).
    source : str
    """

    omega: np.ndarray
    airspeed: np.ndarray
    incidence: np.ndarray
    measured: dict
    group: np.ndarray
    source: str = ""

    @property
    def n(self) -> int:
        """Number of points N."""
        return self.omega.size

    def subset(self, mask) -> "LoadData":
        """The points where ``mask`` is True."""
        mask = np.asarray(mask, bool)
        return LoadData(self.omega[mask], self.airspeed[mask], self.incidence[mask],
                        {k: v[mask] for k, v in self.measured.items()}, self.group[mask], self.source)


LOAD_KEYS = ("thrust", "drag", "torque")


def read_loads(path, *, min_points: int = 6) -> LoadData:
    """Read load measurements: a wind-tunnel or a thrust-stand CSV.

    Columns ``rpm`` and at least one of ``thrust`` [N], ``drag`` [N], ``torque`` [N m];
    ``airspeed`` [m/s] and ``incidence_deg`` (both default 0: a static thrust stand);
    optional ``group`` (run label).

    Raises
    ------
    DataError
        Missing columns, NaN (naming the line), out-of-range operating points, fewer than
        ``min_points`` rows, all rows identical.
    """
    what = "load data"
    df = _frame(path, what)
    if "rpm" not in df.columns:
        raise DataError(f"{what}: {path} lacks column rpm")
    if ("incidence_deg" in df.columns) and ("airspeed" not in df.columns):
        raise DataError(f"{what}: {path} has incidence_deg but lacks column airspeed")
    for c in ("airspeed", "incidence_deg"):
        if c not in df.columns:
            df[c] = 0.0  # a static thrust stand
    keys = [k for k in LOAD_KEYS if k in df.columns]
    if not keys:
        raise DataError(f"{what}: {path} has none of the load columns {', '.join(LOAD_KEYS)}")
    a = _numeric(df, ["rpm", "airspeed", "incidence_deg", *keys], path, what)
    if len(df) < min_points:
        raise DataError(f"{what}: {path} has {len(df)} points; at least {min_points} are needed")
    if np.all(np.ptp(a[:, :3], axis=0) == 0):
        raise DataError(f"{what}: {path}: all operating points are identical")
    if np.any(a[:, 0] <= 0) or np.any(a[:, 1] < 0) or np.any((a[:, 2] < 0) | (a[:, 2] > 180)):
        raise DataError(f"{what}: {path}: need rpm > 0, airspeed >= 0 m/s, incidence_deg in [0, 180]")
    group = df["group"].astype(str).to_numpy() if "group" in df.columns else np.full(len(df), "all")
    return LoadData(a[:, 0] * RPM, a[:, 1], np.radians(a[:, 2]), {k: a[:, 3 + i] for i, k in enumerate(keys)},
                    group, f"{path}")


def loads_from_catalogue(entry: CatalogueEntry, diameter: float, *, air: Air = Air()) -> LoadData:
    """UIUC static runs and axial J-sweeps of a catalogue propeller as thrust and torque.

    T = CT rho n^2 D^4, Q = CP rho n^2 D^5 / (2 pi), V = J n D, incidence 0; groups are
    the UIUC run ids (e.g. ``"2801rd"``; static runs ``"static_<id>"``).

    Raises
    ------
    DataError
        The entry has no bundled measurements.
    """
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
        Propeller diameter [m] (the coefficients' reference length).

    Raises
    ------
    DataError
        A file that is neither kind, or malformed (the message names it).
    """
    from pathlib import Path

    from ..io.readers import MeasurementFileError, read_uiuc_static, read_uiuc_sweep

    statics, sweeps = [], []
    for p in paths:
        p = Path(p)
        try:
            try:
                statics.append(read_uiuc_static(p))
            except MeasurementFileError as static_exc:
                try:
                    sweeps.append(read_uiuc_sweep(p))
                except MeasurementFileError as sweep_exc:
                    if "expected columns" in str(sweep_exc) and "expected columns" not in str(static_exc):
                        raise static_exc from None
                    if "expected columns" in str(sweep_exc):
                        raise DataError(f"{p}: not a UIUC static (RPM CT CP) or wind-tunnel (J CT CP eta) "
                                        "file") from None
                    raise
        except MeasurementFileError as exc:
            raise DataError(str(exc)) from None
    return _loads_from_runs(statics, sweeps, diameter, air, "UIUC files",
                            "UIUC-format files " + ", ".join(Path(p).name for p in paths))


def _loads_from_runs(statics, sweeps, diameter, air, name, source) -> LoadData:
    om, V, T, Q, grp = [], [], [], [], []
    for s in statics:
        n = s.rpm / 60
        om.append(2 * math.pi * n), V.append(0 * n), grp.append(np.full(n.size, f"static_{s.run_id}"))
        T.append(s.CT * air.rho * n**2 * diameter**4), Q.append(s.CP * air.rho * n**2 * diameter**5 / (2 * math.pi))
    for w in sweeps:
        n = np.full(w.J.size, w.rpm / 60)
        om.append(2 * math.pi * n), V.append(w.J * n * diameter), grp.append(np.full(n.size, w.run_id))
        T.append(w.CT * air.rho * n**2 * diameter**4), Q.append(w.CP * air.rho * n**2 * diameter**5 / (2 * math.pi))
    if not om:
        raise DataError(f"{name} has no measurements")
    omega = np.concatenate(om)
    return LoadData(omega, np.concatenate(V), np.zeros(omega.size),
                    {"thrust": np.concatenate(T), "torque": np.concatenate(Q)}, np.concatenate(grp), source)
