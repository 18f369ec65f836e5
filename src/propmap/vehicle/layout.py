"""A multirotor's description: its rotors (position, axis, spin, propeller, inertia), mass,
inertia, centre of mass and airframe, and the rotors' arms and axes about the centre of mass.

Body frame: x forward, y left, z up. The wrench of this vehicle is in vehicle/model.py.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ..core._numbers import real
from ..core.airfoil import SectionParams
from ..core.body import BodyDrag
from ..core.geometry import Propeller, has_bool

__all__ = ["Rotor", "Vehicle", "body_to_world", "rotor_geometry", "shift_centre_of_mass"]


@dataclass(frozen=True, eq=False)
class Rotor:
    """One rotor of a vehicle.

    Attributes
    ----------
    position : ndarray, shape (3,)
        Hub position p_i from the vehicle's origin, body axes [m]; its arm about the centre
        of mass is p_i - ``Vehicle.centre_of_mass`` (the origin unless given or fitted).
    axis : ndarray, shape (3,)
        Unit thrust direction, body axes.
    spin : float
        +1: ccw about ``axis`` (right-hand rule), -1: cw.
    propeller : Propeller
    params : AirfoilParams or CamberedParams, optional
        This rotor's own parameter set; None: the set passed to :func:`vehicle_wrench`.
    inertia : float, optional
        Rotor and motor inertia about the axis J_r [kg m^2] (gyroscopic and spin-up
        moments); None: not modelled.

    Raises
    ------
    ValueError
        Built with a ``position`` or ``axis`` that is not 3 finite numbers, an axis of zero
        length (a non-unit axis is normalised), a ``spin`` other than +1, -1, "ccw" or "cw"
        (stored as +1.0 or -1.0), an ``inertia`` that is not a finite number >= 0, a
        ``propeller`` that is not a Propeller or ``params`` that are not a parameter set; the
        message names the field. (:func:`propmap.vehicle.read_vehicle` checks a file's ranges.)
    """

    position: np.ndarray
    axis: np.ndarray
    spin: float
    propeller: Propeller
    params: SectionParams | None = None
    inertia: float | None = None

    def __post_init__(self):
        position = _vector3("Rotor.position", self.position)
        axis = _vector3("Rotor.axis", self.axis)
        scale = float(np.max(np.abs(axis)))
        if scale == 0.0:
            raise ValueError("Rotor.axis must be a direction, got a zero vector")
        axis = axis / scale
        axis = axis / float(np.linalg.norm(axis))
        spin = {"ccw": 1.0, "cw": -1.0}.get(self.spin.lower()) if isinstance(self.spin, str) else (
            float(self.spin) if _is_number(self.spin) and self.spin in (1, -1) else None)
        if spin is None:
            raise ValueError(f"Rotor.spin must be +1 or 'ccw' (counter-clockwise about the axis) or -1 or 'cw', got "
                             f"{self.spin!r:.40}")
        if not isinstance(self.propeller, Propeller):
            raise ValueError(f"Rotor.propeller must be a Propeller, got {type(self.propeller).__name__}")
        if self.params is not None and not isinstance(self.params, SectionParams):
            raise ValueError(f"Rotor.params must be a parameter set or None, got {type(self.params).__name__}")
        if self.inertia is not None and not (_is_number(self.inertia) and 0 <= self.inertia < np.inf):
            raise ValueError(f"Rotor.inertia must be a finite number >= 0 kg m^2 or None, got {self.inertia!r:.40}")
        object.__setattr__(self, "position", position)
        object.__setattr__(self, "axis", axis)
        object.__setattr__(self, "spin", spin)
        if self.inertia is not None:
            object.__setattr__(self, "inertia", float(self.inertia))


#: an inertia tensor's elements are refused beyond this [kg m^2]
INERTIA_MAX = 1e6
#: a rigid body's principal moments satisfy I1 + I2 >= I3 for each of them; a tensor that misses it by more than this
#: fraction of its largest principal moment is warned of (a flat airframe is near equality: NeuroBEM's quadrotor
#: 0.0025 + 0.0021 = 1.07 x 0.0043 kg m^2; published simulator values miss it, RotorS' firefly by 21%: not refused)
INERTIA_TRIANGLE_SLACK = 0.01


def check_inertia(m: np.ndarray, what: str) -> None:
    """Refuse an inertia tensor ``m`` (3 x 3, finite) with elements beyond +-INERTIA_MAX, not
    symmetric or not positive definite (ValueError naming ``what``: a zero tensor made the measured
    moments silently 0 and a negative one flipped their sign, a flight-log audit, 2026-12-01), and
    warn, once per tensor, where its principal moments break the triangle inequality by more than
    INERTIA_TRIANGLE_SLACK (no rigid body's: an element mistyped, or in another unit than the
    others)."""
    shown = "[" + ", ".join("[" + ", ".join(f"{float(x):.4g}" for x in row) + "]" for row in m) + "]"
    if np.any(np.abs(m) > INERTIA_MAX):
        raise ValueError(f"{what} must have finite elements within +-{INERTIA_MAX:g} kg m^2, got {shown}")
    if not np.allclose(m, m.T, rtol=1e-9, atol=1e-15):
        raise ValueError(f"{what} must be symmetric, got {shown}")
    p = np.linalg.eigvalsh(m)
    if p[0] <= 0:
        raise ValueError(f"{what} must be positive definite (all principal moments > 0), got {shown}")
    if p[2] > (1.0 + INERTIA_TRIANGLE_SLACK) * (p[0] + p[1]) and _first_warning(m):
        import warnings

        warnings.warn(f"{what}: its principal moments {p[0]:.4g}, {p[1]:.4g}, {p[2]:.4g} kg m^2 break the triangle "
                      f"inequality every rigid body's satisfy (the largest is {p[2] / (p[0] + p[1]):.3g} times the sum "
                      "of the other two): one element mistyped, or in another unit than the others?", UserWarning,
                      stacklevel=4)


#: the inertia tensors already warned of (as bytes): once each, whoever builds a Vehicle with one (a file's reader, then
#: the fits' copies of the vehicle, warned twice through the API: a review)
_TRIANGLE_WARNED: set = set()


def _first_warning(m: np.ndarray) -> bool:
    """Whether the inertia tensor ``m`` is warned of for the first time (and mark it so)."""
    key = np.ascontiguousarray(m, float).tobytes()
    first = key not in _TRIANGLE_WARNED
    _TRIANGLE_WARNED.add(key)
    return first


def _is_number(x) -> bool:
    """A real number, not a bool (a NumPy scalar or 0-d array of one too: core._numbers.real)."""
    return real(x) is not None


def _vector3(name: str, value) -> np.ndarray:
    """``value`` as 3 finite floats (a copy); ValueError naming ``name`` otherwise."""
    try:
        numeric = np.asarray(value).dtype.kind in "iuf" and not has_bool(value)
        a = np.array(value, dtype=float).reshape(-1) if numeric else None
    except (TypeError, ValueError, OverflowError):
        a = None
    if a is None or a.shape != (3,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be 3 finite numbers (body axes), got {value!r:.60}")
    return a


@dataclass(frozen=True, eq=False)
class Vehicle:
    """A multirotor.

    Attributes
    ----------
    mass : float
        [kg].
    rotors : tuple of Rotor
    gravity : float
        [m/s^2].
    body_area : float
        S_body of the paper's body-lift option (Sec. III-A) [m^2].
    inertia : ndarray, shape (3, 3), optional
        Inertia tensor about the centre of mass, body axes [kg m^2] (needed for measured
        moments, I dw/dt + w x I w).
    body_drag : BodyDrag, optional
        Airframe drag (core/body.py).
    centre_of_mass : ndarray, shape (3,)
        Position of the centre of mass relative to the origin of the rotor positions, body
        axes [m] (zeros: the rotor positions are taken from the centre of mass). Moments are
        taken about it: rotor i's arm is r_i - centre_of_mass.
    motor_time_constant : float
        tau [s] of the first-order lag from a log's motor speeds to the rotors' (0: the
        logged speeds are the rotors'; identify.flight.flight_samples).
    rotor_interference : float
        k_I [-], in [0, 3]: the factor on the inflow each rotor's skewed wake induces at
        the others (core/interference.py; 0: rotors do not interact, 1: the vortex-cylinder
        model as it is).
    name, source : str
        Free text (what the vehicle is, where its numbers come from).

    Raises
    ------
    ValueError
        Built with a mass or gravity not a finite number > 0, a negative body area or motor
        time constant, a rotor interference outside [0, 3], no rotors or an item of
        ``rotors`` that is not a Rotor (a list is stored as a tuple), a centre of mass that is
        not 3 finite numbers, an inertia that is not a finite 3x3 tensor or its diagonal
        (stored as the 3x3 tensor) or not symmetric positive definite (:func:`check_inertia`,
        which warns of one that breaks the triangle inequality), or a body drag that is not a
        BodyDrag; the message names the field.
        (:func:`propmap.vehicle.read_vehicle` checks a file's ranges.)
    """

    mass: float
    rotors: tuple[Rotor, ...]
    gravity: float = 9.81
    body_area: float = 0.0
    inertia: np.ndarray | None = None
    body_drag: BodyDrag | None = None
    centre_of_mass: np.ndarray = field(default_factory=lambda: np.zeros(3))
    motor_time_constant: float = 0.0
    rotor_interference: float = 0.0
    name: str = ""
    source: str = ""

    def __getstate__(self) -> dict:
        """Pickle and copy without the kept rotor geometry (:func:`cached_rotor_geometry`: its arrays
        would come back writeable, another type to the compiled kinematics; a review)."""
        state = dict(self.__dict__)
        state.pop("_rotor_geometry", None)
        return state

    def __post_init__(self):
        for name, low in (("mass", 0.0), ("gravity", 0.0)):
            v = getattr(self, name)
            if not (_is_number(v) and low < v < np.inf):
                raise ValueError(f"Vehicle.{name} must be a finite number > 0, got {v!r:.40}")
            object.__setattr__(self, name, real(v))
        for name, (lo, hi) in (("body_area", (0.0, np.inf)), ("motor_time_constant", (0.0, np.inf)),
                               ("rotor_interference", (0.0, 3.0))):
            v = getattr(self, name)
            if not (_is_number(v) and lo <= v <= hi and np.isfinite(v)):
                raise ValueError(f"Vehicle.{name} must be a finite number in [{lo:g}, {hi:g}], got {v!r:.40}")
            object.__setattr__(self, name, real(v))
        rotors = tuple(self.rotors) if isinstance(self.rotors, (list, tuple)) else None
        if not rotors or not all(isinstance(r, Rotor) for r in rotors):
            raise ValueError(f"Vehicle.rotors must be a non-empty sequence of Rotor, got {self.rotors!r:.60}")
        object.__setattr__(self, "rotors", rotors)
        object.__setattr__(self, "centre_of_mass", _vector3("Vehicle.centre_of_mass", self.centre_of_mass))
        if self.inertia is not None:
            try:
                inertia = np.array(self.inertia, dtype=float)
            except (TypeError, ValueError):
                inertia = np.full(1, np.nan)
            inertia = np.diag(inertia) if inertia.shape == (3,) else inertia
            if inertia.shape != (3, 3) or not np.all(np.isfinite(inertia)):
                raise ValueError(f"Vehicle.inertia must be a 3x3 tensor or its diagonal (3 numbers) [kg m^2], finite, "
                                 f"got {self.inertia!r:.60}")
            check_inertia(inertia, "Vehicle.inertia")
            object.__setattr__(self, "inertia", inertia)
        if self.body_drag is not None and not isinstance(self.body_drag, BodyDrag):
            raise ValueError(f"Vehicle.body_drag must be a BodyDrag or None, got {type(self.body_drag).__name__}")

    @property
    def weight(self) -> float:
        """m g [N]."""
        return self.mass * self.gravity


def check_vehicle(vehicle, name: str = "vehicle") -> None:
    """TypeError naming ``name`` unless ``vehicle`` is a :class:`Vehicle` (the entry points that take
    one call it first: a wrong object met an AttributeError deep inside, a docstring-contract audit)."""
    if not isinstance(vehicle, Vehicle):
        raise TypeError(f"{name} must be a propmap Vehicle (propmap.read_vehicle), got {type(vehicle).__name__}")


def rotor_geometry(vehicle: Vehicle) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The rotors' arms, unit axes, spins and angular momentum per unit speed.

    Parameters
    ----------
    vehicle : Vehicle

    Returns
    -------
    arms : ndarray, shape (n_rotors, 3)
        Hub positions from the centre of mass, r_i [m] (the file's positions less
        ``centre_of_mass``).
    axes : ndarray, shape (n_rotors, 3)
        Unit rotor axes a_i (normalised here: a Rotor built in Python may not be).
    spins : ndarray, shape (n_rotors,)
        s_i, +1 ccw about a_i, -1 cw.
    h : ndarray, shape (n_rotors, 3)
        s_i J_i a_i [kg m^2]: the rotor's angular momentum per rad/s (0 where J_i is unknown).
    """
    arms = np.array([r.position for r in vehicle.rotors], float) - np.asarray(vehicle.centre_of_mass, float)
    axes = np.array([r.axis for r in vehicle.rotors], float)
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    spins = np.array([1.0 if r.spin > 0 else -1.0 for r in vehicle.rotors])
    h = np.array([(r.spin * r.inertia if r.inertia else 0.0) for r in vehicle.rotors])[:, None] * axes
    return arms, axes, spins, h


def cached_rotor_geometry(vehicle: Vehicle) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`rotor_geometry`'s arrays, read-only, kept on the vehicle and computed again only when
    what they come from changed: the rotors' positions, axes, spins and inertias and the centre of
    mass, compared by value (a Rotor's arrays can be written in place). For
    :func:`propmap.vehicle.vehicle_wrench`, whose one-sample step spent about 40 us of 700 building
    them (11 us alone, about four times that inside the step, where the solver's data fill the
    caches; 2026-11-29, Intel Xeon; the comparison costs about a quarter of it). Not pickled
    (Vehicle.__getstate__)."""
    key = (vehicle.centre_of_mass.tobytes(),) + tuple((r.position.tobytes(), r.axis.tobytes(), r.spin, r.inertia)
                                                      for r in vehicle.rotors)
    kept = vehicle.__dict__.get("_rotor_geometry")
    if kept is not None and kept[0] == key and not kept[1][0].flags.writeable:  # (read-only as kept: not unpickled)
        return kept[1]
    geometry = rotor_geometry(vehicle)
    for a in geometry:
        a.setflags(write=False)
    object.__setattr__(vehicle, "_rotor_geometry", (key, geometry))  # (the frozen dataclass' own __dict__)
    return geometry


def body_to_world(pitch, roll) -> np.ndarray:
    """Rotation matrices R (shape (N, 3, 3)) taking body vectors to the level world frame.

    Frames: x forward, y left, z up (heading along world x). Nose-up pitch is a rotation
    about +y by -pitch; right-wing-down roll a rotation about +x by +roll; R = Ry(-pitch) Rx(roll).

    Parameters
    ----------
    pitch, roll : array_like, shape (N,)
        Attitude [rad], nose-up and right-wing-down positive (a level-flight data set's, a
        trim's: docs/nomenclature.md).
        Any shape, the two the same (they do not broadcast against each other; scalars
        give one matrix).

    Returns
    -------
    ndarray, shape (N, 3, 3)
        R, with ``v_world = R @ v_body`` (``pitch.shape + (3, 3)`` in general).
    """
    p = -np.asarray(pitch, float)
    r = np.asarray(roll, float)
    cp, sp, cr, sr = np.cos(p), np.sin(p), np.cos(r), np.sin(r)
    z, o = np.zeros_like(p), np.ones_like(p)
    Ry = np.stack([np.stack([cp, z, sp], -1), np.stack([z, o, z], -1), np.stack([-sp, z, cp], -1)], -2)
    Rx = np.stack([np.stack([o, z, z], -1), np.stack([z, cr, -sr], -1), np.stack([z, sr, cr], -1)], -2)
    return Ry @ Rx


def shift_centre_of_mass(vehicle: Vehicle, cg) -> Vehicle:
    """The vehicle with its centre of mass moved.

    Parameters
    ----------
    vehicle : Vehicle
    cg : array_like, shape (3,) or (2,)
        The centre of mass from the origin of the vehicle file's rotor positions, body axes
        [m]; with two values its z stays the vehicle's.

    Returns
    -------
    Vehicle
        A copy; every rotor's arm (``position - centre_of_mass``) moves with it.
    """
    c = np.array(vehicle.centre_of_mass, float)
    c[: len(cg)] = cg
    return replace(vehicle, centre_of_mass=c)
