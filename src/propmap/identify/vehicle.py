"""Multirotor vehicle description for level-flight identification (Gill & D'Andrea 2017, Sec. III).

TOML format (body frame: x forward, y left, z up; SI units)::

    mass = 0.8            # [kg]
    gravity = 9.81        # [m/s^2], optional
    body_area = 0.02      # [m^2], optional: S_body of the body-lift option (Sec. III-A)

    [[rotors]]
    position = [0.08, -0.08, 0.0]   # [m], hub relative to the centre of mass
    axis = [0.0, 0.0, 1.0]          # thrust direction
    spin = "ccw"                    # about +axis (right-hand rule), or "cw"
    propeller = "apce_8x6"          # catalogue name or geometry file (relative to this file)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.geometry import Propeller
from ..io.catalogue import resolve_propeller
from ..io.toml_file import load_toml

__all__ = ["Rotor", "Vehicle", "VehicleFileError", "read_vehicle"]


class VehicleFileError(ValueError):
    """A vehicle file is malformed; the message names the file and the entry."""


@dataclass(frozen=True, eq=False)
class Rotor:
    """One rotor: hub position [m] and unit axis in the body frame, spin (+1 ccw, -1 cw), propeller."""

    position: np.ndarray
    axis: np.ndarray
    spin: float
    propeller: Propeller


@dataclass(frozen=True, eq=False)
class Vehicle:
    """A multirotor: mass [kg], gravity [m/s^2], rotors, optional body area [m^2] for body lift."""

    mass: float
    rotors: tuple[Rotor, ...]
    gravity: float = 9.81
    body_area: float = 0.0

    @property
    def weight(self) -> float:
        """m g [N]."""
        return self.mass * self.gravity


def _vec3(value, what: str) -> np.ndarray:
    try:
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise VehicleFileError(f"{what} must be 3 numbers, got {value!r}") from None
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        raise VehicleFileError(f"{what} must be 3 finite numbers, got {value!r}")
    return a


def read_vehicle(path) -> Vehicle:
    """Read a vehicle TOML file (format in the module docstring).

    Raises
    ------
    VehicleFileError
        Unreadable TOML, missing ``mass`` or ``rotors``, non-positive mass or gravity,
        a bad position/axis/spin, or an unknown propeller.
    """
    path = Path(path)
    data = load_toml(path, VehicleFileError)
    for key in ("mass", "rotors"):
        if key not in data:
            raise VehicleFileError(f"{path}: missing key {key!r}")
    try:
        mass = float(data["mass"])
        gravity = float(data.get("gravity", 9.81))
        area = float(data.get("body_area", 0.0))
    except (TypeError, ValueError):
        raise VehicleFileError(f"{path}: mass, gravity and body_area must be numbers") from None
    if not (math.isfinite(mass) and mass > 0):
        raise VehicleFileError(f"{path}: mass must be > 0 kg, got {mass!r}")
    if not (math.isfinite(gravity) and gravity > 0):
        raise VehicleFileError(f"{path}: gravity must be > 0 m/s^2, got {gravity!r}")
    if not (math.isfinite(area) and area >= 0):
        raise VehicleFileError(f"{path}: body_area must be >= 0 m^2, got {area!r}")
    rotors = []
    if not isinstance(data["rotors"], list) or not data["rotors"]:
        raise VehicleFileError(f"{path}: 'rotors' must be a non-empty array of tables ([[rotors]])")
    for k, r in enumerate(data["rotors"], start=1):
        where = f"{path}: rotor {k}"
        for key in ("position", "axis", "spin", "propeller"):
            if key not in r:
                raise VehicleFileError(f"{where}: missing key {key!r}")
        axis = _vec3(r["axis"], f"{where} axis")
        if np.linalg.norm(axis) == 0:
            raise VehicleFileError(f"{where}: axis must be non-zero")
        spin = {"ccw": 1.0, "cw": -1.0}.get(str(r["spin"]).lower())
        if spin is None:
            raise VehicleFileError(f"{where}: spin must be 'cw' or 'ccw', got {r['spin']!r}")
        spec = str(r["propeller"])
        local = path.parent / spec
        try:
            prop = resolve_propeller(str(local) if local.is_file() else spec)
        except (KeyError, ValueError) as exc:
            raise VehicleFileError(f"{where}: propeller: {exc.args[0] if exc.args else exc}") from None
        rotors.append(Rotor(_vec3(r["position"], f"{where} position"), axis / np.linalg.norm(axis), spin, prop))
    return Vehicle(mass=mass, rotors=tuple(rotors), gravity=gravity, body_area=area)
