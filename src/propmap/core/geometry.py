"""Propeller geometry: tip radius, blade count, chord c(r) and blade angle theta(r).

The paper (Section II) takes c and theta as spline interpolants of measured blade
stations. We use PCHIP (piecewise cubic Hermite) interpolation: C1-smooth and
shape-preserving, so a monotone run of stations gives a monotone curve and no
overshoot creates a negative chord between stations.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from ._numbers import integer, real as _real
from ._pchip import Pchip

__all__ = ["Propeller", "rotor_like"]

INCH = 0.0254  # [m]


def refuse_masked(name: str, value) -> None:
    """Refuse a masked array with masked entries, naming the input: NumPy would compute them
    as if given (``np.asarray`` drops the mask).

    Parameters
    ----------
    name : str
        The input's name, for the message.
    value : object
        Anything; only a ``numpy.ma.MaskedArray`` with a masked entry is refused.

    Raises
    ------
    ValueError
        ``value`` a masked array with masked entries.
    """
    if isinstance(value, np.ma.MaskedArray) and np.ma.getmaskarray(value).any():
        raise ValueError(f"{name}: a masked array with masked entries (they would be computed as if given); pass "
                         "the points to compute, e.g. its .compressed()")


def _sequence(value) -> bool:
    """A sequence NumPy unpacks into an array's elements: a list, a tuple or any other
    ``collections.abc.Sequence`` (a deque, a range), not a string."""
    return isinstance(value, (list, tuple)) or (isinstance(value, Sequence) and not isinstance(value, (str, bytes)))


def has_bool(value) -> bool:
    """Whether a (nested) list, tuple or other sequence, or an object array, holds a bool or a
    boolean array (NumPy would read it as 0 or 1, so that ``[800.0, True]`` became a rotation
    rate of 1 rad/s): the array inputs refuse it. A list is scanned by the types of its items
    (20 ms for 10^6 floats), descending only into the sequences and arrays among them. (A
    ``collections.deque`` was not looked into until 2026-11-29: a mutation audit.)"""
    if isinstance(value, np.ndarray):
        return value.dtype.kind == "b" or (value.dtype.kind == "O" and any(has_bool(v) for v in value.flat))
    if isinstance(value, (float, int, np.generic)):  # a number (or bool), before the sequence test (an ABC's, slower)
        return isinstance(value, (bool, np.bool_))
    if _sequence(value):
        types = set(map(type, value))
        if bool in types or np.bool_ in types:
            return True
        if all(t in (float, int, np.float64, np.int64) for t in types):  # the common case: plain numbers
            return False
        return any(has_bool(v) for v in value if _sequence(v) or isinstance(v, np.ndarray))
    return False


def broadcast_readonly(*arrays: np.ndarray) -> list[np.ndarray]:
    """The arrays broadcast to one shape, as ``np.broadcast_arrays`` does, but as read-only views
    (``np.broadcast_to``; an array already of that shape is returned as it is): NumPy's writeable
    broadcast views warn of a future change (a FutureWarning) whenever their flags are read, which
    numba and ``np.require`` do.

    Raises
    ------
    ValueError
        Shapes that do not broadcast (``np.broadcast_shapes``' message).
    """
    shape = np.broadcast_shapes(*(a.shape for a in arrays))
    return [a if a.shape == shape else np.broadcast_to(a, shape) for a in arrays]


def short_repr(value, n: int = 60) -> str:
    """``repr(value)`` as one line of at most ``n`` characters, for an error message.

    Parameters
    ----------
    value : object
        Anything; a NumPy array or scalar is shown as its ``tolist()`` (an array's first ``n``
        elements only; a masked array by its repr, which marks the masked ones), an integer of 30
        digits or more by its number of digits (its repr can take seconds to build, or fail).
    n : int
        The longest text returned, > 4.

    Returns
    -------
    str
        The repr, newlines as spaces, cut to its first ``n - 4`` characters and " ..." where longer.
    """
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**30:
        if value.bit_length() < 14000:  # (str() refuses ints of more than 4300 digits: Python's limit)
            return f"an integer of {len(str(abs(value)))} digits"
        return f"an integer of about {int(abs(value).bit_length() * math.log10(2)) + 1} digits"
    if isinstance(value, np.ndarray) and not isinstance(value, np.ma.MaskedArray):
        value = value.reshape(-1)[:n].tolist() if value.size > n else value.tolist()
    elif isinstance(value, np.generic):
        value = value.tolist()
    r = repr(value).replace("\n", " ")
    return r if len(r) <= n else r[: n - 4] + " ..."


def _station_values(key: str, value) -> np.ndarray:
    """A :class:`Propeller` station field (``r``, ``chord`` or ``theta``) as a read-only 1-D float
    array; refused unless a 1-D array of finite numbers (no bools, strings, objects or masks)."""
    refuse_masked(key, value)  # (a masked chord of 99 m was read as given: a mutation audit, 2026-11-29)
    try:
        # no bools, strings or objects read as numbers
        numeric = np.asarray(value).dtype.kind in "iuf" and not has_bool(value)
        ndim = np.ndim(value)
        a = np.array(value, dtype=float, copy=True).reshape(-1)
    except (TypeError, ValueError, OverflowError):
        numeric = False
    if not numeric:
        raise ValueError(f"{key} must be an array of numbers, got {short_repr(value)}")
    if ndim != 1:  # (a (1, n) array was flattened without a word)
        raise ValueError(f"{key} must be a 1-D array (one value per blade station), got {ndim} dimensions")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{key} must be finite at every blade station")
    a.setflags(write=False)
    return a


def _check_stations(r: np.ndarray, chord: np.ndarray, theta: np.ndarray, radius: float) -> None:
    """Refuse stations of unequal lengths, fewer than 2, not strictly increasing or outside
    (0, radius], a negative chord or none > 0, or a blade angle beyond 90 deg."""
    if not (len(r) == len(chord) == len(theta)):
        raise ValueError(
            f"r, chord and theta must have equal lengths, got {len(r)}, {len(chord)}, {len(theta)}"
        )
    if len(r) < 2:
        raise ValueError(f"at least 2 blade stations are needed, got {len(r)}")
    if np.any(np.diff(r) <= 0):
        i = int(np.argmax(np.diff(r) <= 0))
        raise ValueError(
            f"r must be strictly increasing; station {i + 1} ({r[i + 1]:.6g} m) "
            f"does not exceed station {i} ({r[i]:.6g} m)"
        )
    if r[0] <= 0 or r[-1] > radius * (1 + 1e-9):
        raise ValueError(f"r must lie in (0, radius={radius:.6g}] m, got [{r[0]:.6g}, {r[-1]:.6g}]")
    if np.any(chord < 0):
        raise ValueError("chord must be >= 0 m at every station")
    if not np.any(chord > 0):
        raise ValueError("chord must be > 0 m at some station: a blade of zero chord everywhere has no loads")
    if np.any(np.abs(theta) > math.pi / 2 + 1e-12):
        raise ValueError("theta must be in [-90, 90] deg at every station")


@dataclass(frozen=True, eq=False)
class Propeller:
    """A fixed-pitch propeller.

    Parameters
    ----------
    name : str
        Identifier, e.g. a catalogue name such as ``"apce_8x6"``.
    radius : float
        Tip radius R [m], > 0.
    n_blades : int
        Blade count N_b, >= 1.
    r : array_like, shape (k,)
        Radii of the measured blade stations [m], strictly increasing, k >= 2,
        within (0, radius]. The blade is taken to start at ``r[0]`` (the paper's
        integral over [0, R] is replaced by [r_hub, R], docs/numerics.md item 5).
    chord : array_like, shape (k,)
        Chord c at the stations [m], >= 0.
    theta : array_like, shape (k,)
        Blade angle theta at the stations [rad], in [-pi/2, pi/2], measured from
        the disk plane.
    pitch : float, optional
        Nominal pitch [m] (catalogue information only).
    source : str, optional
        Where the geometry came from (citation).

    Raises
    ------
    ValueError
        Naming the argument: a value of the wrong type (a bool, a string; a non-integer
        ``n_blades``; a ``name`` or ``source`` that is not a string; stations not 1-D; a masked array with
        masked entries, whose values NumPy would use as if given), non-finite values,
        ``radius <= 0``, ``n_blades < 1``, a non-finite ``pitch``, arrays of different length
        or fewer than 2 stations, radii not strictly increasing or outside (0, radius],
        negative chord or zero chord at every station, blade angle outside [-90, 90] deg, or
        stations that stop short of the tip where the extrapolation of the last ones (PCHIP's
        end polynomials) to the tip leaves chord <= radius or |theta| <= 90 deg (or overflows).

    Notes
    -----
    The records are immutable and the input arrays are copied, never modified.
    """

    name: str
    radius: float
    n_blades: int
    r: np.ndarray
    chord: np.ndarray
    theta: np.ndarray
    pitch: float | None = None
    source: str = ""
    _chord_spline: Pchip = field(init=False, repr=False)
    _theta_spline: Pchip = field(init=False, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):  # (None or 5 reached maps and reports as a name)
            raise ValueError(f"name must be a string, got {type(self.name).__name__}")
        if not isinstance(self.source, str):  # (as the name: maps and exports cite it)
            raise ValueError(f"source must be a string, got {type(self.source).__name__}")
        radius = _real(self.radius)
        if radius is None or not (math.isfinite(radius) and radius > 0):
            raise ValueError(f"radius must be finite and > 0 m, got {short_repr(self.radius)}")
        nb = integer("n_blades", self.n_blades, 1)
        if self.pitch is not None:
            pitch = _real(self.pitch)
            if pitch is None or not math.isfinite(pitch):
                raise ValueError(f"pitch must be a finite number [m] or None, got {short_repr(self.pitch)}")
            object.__setattr__(self, "pitch", pitch)
        arrays = {key: _station_values(key, getattr(self, key)) for key in ("r", "chord", "theta")}
        r, chord, theta = arrays["r"], arrays["chord"], arrays["theta"]
        _check_stations(r, chord, theta, radius)
        object.__setattr__(self, "radius", radius)
        object.__setattr__(self, "n_blades", nb)
        for key, a in arrays.items():
            object.__setattr__(self, key, a)
        object.__setattr__(self, "_chord_spline", Pchip(r, chord))
        object.__setattr__(self, "_theta_spline", Pchip(r, theta))
        if r[-1] < radius:  # the end polynomials carry the blade to the tip: they must give a blade
            y = np.linspace(r[-1], radius, 65)
            c_max, th_max = float(np.max(self._chord_spline(y))), float(np.max(np.abs(self._theta_spline(y))))
            if not (c_max <= radius and th_max <= math.pi / 2):  # (NaN too: an overflowing spline passed)
                raise ValueError(
                    f"the blade from the last station (r = {r[-1]:.6g} m, {r[-1] / radius:.4g} R) to the tip "
                    f"extrapolates to a chord of {c_max / radius:.3g} R and a blade angle of "
                    f"{math.degrees(th_max):.4g} deg (valid: chord <= R, |angle| <= 90 deg): give stations to the "
                    "tip (are the radii in another unit?)")

    @property
    def diameter(self) -> float:
        """Diameter D = 2R [m]."""
        return 2.0 * self.radius

    @property
    def r_hub(self) -> float:
        """Radius where the blade starts [m] (the first station)."""
        return float(self.r[0])

    def chord_at(self, y) -> np.ndarray:
        """Chord c(y) [m] at radii ``y`` [m] (PCHIP through the stations).

        Outside the stations PCHIP extrapolates its end polynomial (the solver only
        evaluates [r_hub, R]); clipped at 0.

        Parameters
        ----------
        y : float or array_like
            Radii [m], any shape.

        Returns
        -------
        ndarray
            c(y) [m] >= 0, shaped like ``y``.
        """
        return np.maximum(self._chord_spline(np.asarray(y, dtype=float)), 0.0)

    def theta_at(self, y) -> np.ndarray:
        """Blade angle theta(y) [rad] at radii ``y`` [m] (PCHIP through the stations).

        Parameters
        ----------
        y : float or array_like
            Radii [m], any shape (outside the stations PCHIP extrapolates its end polynomial).

        Returns
        -------
        ndarray
            theta(y) [rad], from the blade-angle datum of the geometry, shaped like ``y``.
        """
        return self._theta_spline(np.asarray(y, dtype=float))

    def theta_75(self) -> float:
        """The blade angle at 0.75 R [rad], the reference station of a propeller's pitch (the
        DA-series and NR640 designs', UIUC vol. 2; a fitted set's [coverage] ``theta75_deg``).

        Returns
        -------
        float
            theta(0.75 R) [rad] (:meth:`theta_at`), from the geometry's blade-angle datum.
        """
        return float(self.theta_at(0.75 * self.radius))

    def reynolds_75(self, omega, air) -> np.ndarray:
        """The chord Reynolds number at 0.75 R in static rotation, rho (0.75 Omega R) c(0.75 R) / mu
        [-], the catalogue's measure of a propeller's Reynolds number (docs/validation.md).

        Parameters
        ----------
        omega : float or array_like
            Omega [rad/s], any shape.
        air : Air
            Its density rho [kg/m^3] and dynamic viscosity mu [Pa s].

        Returns
        -------
        ndarray
            Shaped like ``omega``.
        """
        y = 0.75 * self.radius
        return air.rho * np.asarray(omega, dtype=float) * y * float(self.chord_at(y)) / air.mu

    def solidity(self) -> float:
        """Rotor solidity sigma = N_b * (blade area) / (pi R^2) [-].

        Returns
        -------
        float
            sigma, the blade area the integral of c(y) from r_hub to R (adaptive quadrature of
            :meth:`chord_at`).
        """
        from scipy.integrate import quad

        area, _ = quad(lambda y: float(self.chord_at(y)), self.r_hub, self.radius, limit=200)
        return self.n_blades * area / (math.pi * self.radius**2)

    def same_geometry(self, other: Propeller) -> bool:
        """Whether ``other`` is the same blade geometry: blade count, radius and the stations'
        r, chord and blade angle to 1e-9 relative (the name is not compared: a name alone does not
        say, e.g. a geometry file read with another blade count).

        Parameters
        ----------
        other : Propeller

        Returns
        -------
        bool

        Raises
        ------
        TypeError
            ``other`` not a Propeller.
        """
        if not isinstance(other, Propeller):
            raise TypeError(f"other must be a Propeller, got {type(other).__name__}")
        return (self.n_blades == other.n_blades and math.isclose(self.radius, other.radius, rel_tol=1e-9)
                and all(np.shape(x) == np.shape(y) and np.allclose(x, y, rtol=1e-9, atol=0.0)
                        for x, y in ((self.r, other.r), (self.chord, other.chord), (self.theta, other.theta))))

    def same_size(self, diameter: float | None, n_blades: float | None, rtol: float = 0.01) -> bool:
        """Whether a recorded diameter and blade count (a map's or a fitted file's, either
        possibly unknown: None or NaN) are this propeller's: the diameter within ``rtol``, the
        blade count equal (rounded).

        Parameters
        ----------
        diameter : float or None
            [m]. None, NaN or <= 0: not compared.
        n_blades : float or None
            None or NaN: not compared.
        rtol : float, optional
            Relative tolerance on the diameter (default 1%).

        Returns
        -------
        bool
        """
        d = float("nan") if diameter is None else float(diameter)
        b = float("nan") if n_blades is None else float(n_blades)
        d_ok = not (math.isfinite(d) and d > 0) or abs(self.diameter / d - 1.0) <= rtol
        return d_ok and (not math.isfinite(b) or int(round(b)) == self.n_blades)

    def __repr__(self) -> str:
        return (f"Propeller(name={self.name!r}, radius={self.radius:.4g} m, n_blades={self.n_blades}, "
                f"stations={len(self.r)}, r_hub={self.r_hub / self.radius:.3f} R)")


#: a blade angle at 0.75 R below this looks like a rotor's (every catalogue propeller has >= 7.4 deg)
ROTOR_BETA75_MAX = math.radians(5.0)
#: a twist from 0.3 R to the tip below this looks like a rotor's (catalogue propellers: >= 9.1 deg)
ROTOR_TWIST_MAX = math.radians(6.0)


def rotor_like(propeller: Propeller) -> str | None:
    """Why ``propeller``'s blade angles look like a helicopter-style rotor's, or None.

    A propeller's blades are strongly twisted to a pitch (the 108 UIUC catalogue
    propellers: blade angle at 0.75 R >= 7.4 deg, twist from 0.3 R to the tip >= 9.1 deg);
    a rotor's are nearly untwisted and set by a collective. The test: blade angle at
    0.75 R below 5 deg, or twist from 0.3 R (or the first station) to the tip below
    6 deg. Used to warn when a rotor is run with the propeller-camber generic set.

    Parameters
    ----------
    propeller : Propeller
        Its blade angles ``theta`` [rad] at its stations ``r`` [m].

    Returns
    -------
    str or None
        A sentence naming the angles, or None for a propeller-like blade.

    Raises
    ------
    TypeError
        ``propeller`` not a Propeller.
    """
    if not isinstance(propeller, Propeller):
        raise TypeError(f"propeller must be a Propeller, got {type(propeller).__name__}")
    R = propeller.radius
    root = max(0.3 * R, propeller.r_hub)
    b75, broot, btip = propeller.theta_75(), float(propeller.theta_at(root)), float(propeller.theta_at(R))
    if b75 < ROTOR_BETA75_MAX or broot - btip < ROTOR_TWIST_MAX:
        return (f"blade angle {math.degrees(b75):.1f} deg at 0.75 R and twist {math.degrees(broot - btip):.1f} deg "
                f"from {root / R:.2f} R to the tip: a rotor's blade, not a propeller's")
    return None

