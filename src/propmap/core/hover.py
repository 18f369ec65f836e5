"""The hover (static) model used by most multirotor work: T = k_T Omega^2, Q = k_Q Omega^2, D = 0.

Gill & D'Andrea (2017), Section IV compares it with the full model ("hover
approximation"); propmap keeps it for the same comparison.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._numbers import checked, real
from .air import check_air
from .airfoil import Air, AirfoilParams
from .geometry import Propeller, has_bool
from .solver import DEFAULT_DISCRETIZATION, Discretization, check_model_args, rotor_loads

__all__ = ["HoverModel"]


def _finite_rates(omega) -> np.ndarray:
    """``omega`` as a float array, refused (ValueError naming it) where not all finite numbers
    (text refused in every form: NumPy reads b"800", ["800"] and a text array as 800 rad/s)."""
    try:
        raw = np.asarray(omega)
        w = np.asarray(raw, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"omega must be a number or an array of numbers [rad/s], got {omega!r:.60}") from None
    text = raw.dtype.kind in "SU" or (raw.dtype.kind == "O" and any(isinstance(v, (str, bytes)) for v in raw.flat))
    if text or not np.all(np.isfinite(w)):
        raise ValueError(f"omega must be finite numbers [rad/s], got {omega!r:.60}")
    if has_bool(omega):  # (True read as 1 rad/s; from_model refuses it too)
        raise ValueError(f"omega must be numbers [rad/s], not booleans, got {omega!r:.60}")
    return w


@dataclass(frozen=True)
class HoverModel:
    """T = k_T Omega^2, Q = k_Q Omega^2, D = 0, whatever the airspeed and incidence.

    Parameters
    ----------
    k_T : float
        Thrust constant [N s^2/rad^2], finite.
    k_Q : float
        Torque constant [N m s^2/rad^2], finite.
    rho : float, optional
        The air density [kg/m^3] the constants hold for (recorded by :meth:`from_model` and
        :meth:`from_coefficients`); :meth:`CT` and :meth:`CP` use it unless given another air.
    diameter : float, optional
        The rotor diameter [m] (recorded likewise); the default of :meth:`CT` and :meth:`CP`.

    Raises
    ------
    ValueError
        ``k_T`` or ``k_Q`` not a finite number, ``rho`` or ``diameter`` not a positive finite
        number (or None).
    """

    k_T: float
    k_Q: float
    rho: float | None = field(default=None, compare=False)  # (the constants make the model; these are context)
    diameter: float | None = field(default=None, compare=False)

    def __post_init__(self) -> None:
        for name in ("k_T", "k_Q"):
            object.__setattr__(self, name, checked(name, getattr(self, name)))
        for name in ("rho", "diameter"):
            v = getattr(self, name)
            if v is not None:
                x = real(v)
                if x is None or not 0 < x < math.inf:
                    raise ValueError(f"{name} must be a positive finite number or None, got {v!r}")
                object.__setattr__(self, name, x)

    @classmethod
    def from_model(cls, propeller: Propeller, params: AirfoilParams, omega: float, *,
                   air: Air | None = None, discretization: Discretization = DEFAULT_DISCRETIZATION) -> "HoverModel":
        """Calibrate on the full model at V = 0 and rotation rate ``omega`` [rad/s].

        Then ``HoverModel.thrust(omega)`` equals the full model's T at V = 0 exactly at
        that ``omega`` (and within the Reynolds-number dependence elsewhere).

        Parameters
        ----------
        propeller : Propeller
        params : AirfoilParams or CamberedParams
        omega : float
            The rotation rate to calibrate at [rad/s], >= 1.
        air : Air, optional
            Default: the parameter set's own (``params.air``); recorded as ``rho``.
        discretization : Discretization, optional
            The model's nodes (default 48 x 16).

        Returns
        -------
        HoverModel
            With ``rho`` and ``diameter`` recorded.

        Raises
        ------
        ValueError
            ``omega`` not a single number (an array of several, a string, a bool), below
            1 rad/s (k_T = T / Omega^2 needs a spinning rotor; below 0.1 rad/s the model
            treats the blades as parked), or as :func:`propmap.rotor_loads` (its range).
        TypeError
            A model argument of the wrong type (:func:`propmap.core.solver.check_model_args`).
        """
        air = getattr(params, "air", None) if air is None else air  # checked below
        check_model_args(propeller, params, air, discretization)
        om = real(omega)  # (a float: np.float32's k_T = T / Omega^2 was a float32, then refused)
        if om is None:
            raise ValueError(f"omega must be one rotation rate [rad/s] (a number), got {omega!r:.60}")
        if not om >= 1.0:
            raise ValueError(f"omega must be at least 1 rad/s to calibrate a hover model "
                             f"(k_T = T / Omega^2), got {om!r}")
        r = rotor_loads(propeller, params, om, 0.0, 0.0, air=air, discretization=discretization)
        return cls(float(r.thrust) / om**2, float(r.torque) / om**2, rho=float(air.rho),
                   diameter=float(propeller.diameter))

    @classmethod
    def from_coefficients(cls, CT: float, CP: float, diameter: float, *, air: Air | None = None) -> "HoverModel":
        """From static propeller-convention coefficients (e.g. a measured static run).

        k_T = CT rho D^4 / (2 pi)^2 and k_Q = CP rho D^5 / (2 pi)^3, since
        T = CT rho n^2 D^4, Q = P/Omega = CP rho n^2 D^5 / (2 pi), n = Omega/(2 pi).

        Parameters
        ----------
        CT, CP : float
            Static thrust and power coefficients (propeller convention) [-].
        diameter : float
            Rotor diameter D [m].
        air : Air, optional
            The air the coefficients were measured in (default ISA sea level); recorded as ``rho``.

        Returns
        -------
        HoverModel

        Raises
        ------
        ValueError
            CT or CP not a finite number in [-1000, 1000], or the diameter not in (0, 1000] m.
        TypeError
            ``air`` neither None nor an :class:`Air`.
        """
        air = Air() if air is None else air
        check_air(air)
        CT, CP, diameter = checked("CT", CT), checked("CP", CP), checked("diameter", diameter)
        if not 0 < diameter <= 1e3:
            raise ValueError(f"diameter must be in (0, 1000] m, got {diameter!r}")
        if not (abs(CT) <= 1e3 and abs(CP) <= 1e3):
            raise ValueError(f"CT and CP must be within [-1000, 1000], got {CT!r}, {CP!r}")
        return cls(float(CT) * air.rho * diameter**4 / (2 * math.pi) ** 2,
                   float(CP) * air.rho * diameter**5 / (2 * math.pi) ** 3, rho=float(air.rho), diameter=float(diameter))

    def thrust(self, omega) -> np.ndarray:
        """T = k_T Omega^2 [N].

        Parameters
        ----------
        omega : float or array_like
            Rotation rate Omega [rad/s], any shape (a signed rate gives its magnitude's thrust).

        Returns
        -------
        ndarray
            Shaped like ``omega``.

        Raises
        ------
        ValueError
            A value that is not a finite number (NaN, a string, a bool).
        """
        return self.k_T * _finite_rates(omega) ** 2

    def torque(self, omega) -> np.ndarray:
        """Q = k_Q Omega^2 [N m].

        Parameters
        ----------
        omega : float or array_like
            Omega [rad/s], any shape.

        Returns
        -------
        ndarray
            Q [N m], shaped like ``omega``.

        Raises
        ------
        ValueError
            As :meth:`thrust`.
        """
        return self.k_Q * _finite_rates(omega) ** 2

    def _conditions(self, diameter, air) -> tuple[float, float]:
        d = self.diameter if diameter is None else diameter
        if d is None:
            raise ValueError("diameter is needed: this model records none (build it with from_model or "
                             "from_coefficients, or give it)")
        x = real(d)
        if x is None or not 0 < x < math.inf:
            raise ValueError(f"diameter must be a positive finite number [m], got {d!r}")
        d = x
        if air is not None:  # (air=1.2 met "'float' object has no attribute 'rho'")
            check_air(air)
        rho = (self.rho if self.rho is not None else Air().rho) if air is None else air.rho
        return float(d), float(rho)

    def CT(self, diameter: float | None = None, *, air: Air | None = None) -> float:
        """The (constant) thrust coefficient of this model, CT = k_T (2 pi)^2 / (rho D^4).

        Parameters
        ----------
        diameter : float, optional
            Rotor diameter D [m]; default the one recorded.
        air : Air, optional
            Default: the density recorded, else ISA sea level (before 2026-11-26 always sea
            level, 26% off for a model built at 3,000 m).

        Returns
        -------
        float

        Raises
        ------
        ValueError
            No diameter given and none recorded, or one that is not a positive finite number.
        TypeError
            ``air`` not an :class:`Air`.
        """
        d, rho = self._conditions(diameter, air)
        return self.k_T * (2 * math.pi) ** 2 / (rho * d**4)

    def CP(self, diameter: float | None = None, *, air: Air | None = None) -> float:
        """The (constant) power coefficient, CP = k_Q (2 pi)^3 / (rho D^5) (propeller convention).

        Parameters
        ----------
        diameter : float, optional
            As :meth:`CT`.
        air : Air, optional
            As :meth:`CT`.

        Returns
        -------
        float

        Raises
        ------
        ValueError
            As :meth:`CT`.
        """
        d, rho = self._conditions(diameter, air)
        return self.k_Q * (2 * math.pi) ** 3 / (rho * d**5)
