"""Blade-section aerodynamics: the lift and drag polars of Gill & D'Andrea (2017).

Reference
---------
R. Gill and R. D'Andrea, "Propeller Thrust and Drag in Forward Flight",
IEEE Conference on Control Technology and Applications (CCTA), 2017,
doi:10.1109/CCTA.2017.8062440. Equations (3), (4), footnotes 1 and 2, Table I.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, replace

import numpy as np

__all__ = [
    "AirfoilParams",
    "Air",
    "PRESETS",
    "preset",
    "lift_coefficient",
    "drag_coefficient",
]

LIFT_MODELS = ("sigmoid", "sincos")


def _check_finite(name: str, value: float, *, low: float | None = None,
                  high: float | None = None, low_open: bool = False) -> float:
    """Return ``float(value)`` or raise ValueError naming ``name`` and the valid range."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x!r}")
    if low is not None and (x < low or (low_open and x == low)):
        bracket = "(" if low_open else "["
        hi = "inf)" if high is None else f"{high}]"
        raise ValueError(f"{name} must be in {bracket}{low}, {hi}, got {x!r}")
    if high is not None and x > high:
        lo = "(-inf" if low is None else ("(" if low_open else "[") + f"{low}"
        raise ValueError(f"{name} must be in {lo}, {high}], got {x!r}")
    return x


@dataclass(frozen=True)
class Air:
    """Air properties (footnote 2 of Gill & D'Andrea 2017).

    Parameters
    ----------
    rho : float
        Density [kg/m^3], > 0. Default 1.225.
    mu : float
        Dynamic viscosity [Pa s], > 0. Default 1.983e-5.

    Raises
    ------
    ValueError
        If a value is non-finite or not positive.
    """

    rho: float = 1.225
    mu: float = 1.983e-5

    def __post_init__(self) -> None:
        object.__setattr__(self, "rho", _check_finite("rho", self.rho, low=0.0, low_open=True))
        object.__setattr__(self, "mu", _check_finite("mu", self.mu, low=0.0, low_open=True))


@dataclass(frozen=True)
class AirfoilParams:
    """Parameters of the section polars, eqs (3) and (4) of Gill & D'Andrea (2017).

    Parameters
    ----------
    cl1 : float
        Pre-stall lift slope c_l1 [1/rad], >= 0 (eq 3).
    cl2 : float
        Post-stall amplitude c_l2 [-], >= 0 (eq 3); also the c_l of footnote 1's
        simplified lift ``C_L = c_l sin(alpha) cos(alpha)`` when ``lift_model="sincos"``.
    cd : float
        Drag amplitude c_d [-], >= 0 (eq 4).
    alpha0 : float
        Stall angle alpha_0 [rad], in (0, pi/2) (eq 3).
    M : float
        Sigmoid sharpness [1/rad], > 0. Default 50 (footnote 2).
    cd0 : float
        Form-drag coefficient c_d0 [-], >= 0. Default 0.01 (footnote 2).
    cp_blasius : float
        Laminar skin-friction constant c_p of the Blasius term [-], >= 0.
        Default 1.328 (footnote 2).
    lift_model : {"sigmoid", "sincos"}
        ``"sigmoid"``: eq (3). ``"sincos"``: footnote 1, ``C_L = cl2 sin a cos a``
        (``cl1``, ``alpha0`` and ``M`` are then unused).

    Raises
    ------
    ValueError
        If a value is non-finite or outside the range above.

    Notes
    -----
    Immutable; use :func:`dataclasses.replace` to derive variants.
    """

    cl1: float
    cl2: float
    cd: float
    alpha0: float
    M: float = 50.0
    cd0: float = 0.01
    cp_blasius: float = 1.328
    lift_model: str = "sigmoid"

    def __post_init__(self) -> None:
        for name in ("cl1", "cl2", "cd", "cd0", "cp_blasius"):
            object.__setattr__(self, name, _check_finite(name, getattr(self, name), low=0.0))
        object.__setattr__(self, "M", _check_finite("M", self.M, low=0.0, low_open=True))
        a0 = _check_finite("alpha0", self.alpha0)
        if not 0.0 < a0 < math.pi / 2:
            raise ValueError(f"alpha0 must be in (0, pi/2) rad, got {a0!r}")
        object.__setattr__(self, "alpha0", a0)
        if self.lift_model not in LIFT_MODELS:
            raise ValueError(f"lift_model must be one of {LIFT_MODELS}, got {self.lift_model!r}")

    def replace(self, **changes) -> "AirfoilParams":
        """Return a copy with ``changes`` applied (validated again)."""
        return replace(self, **changes)

    def as_dict(self) -> dict:
        """Return the fields as a plain dict (SI units, alpha0 in rad)."""
        return asdict(self)


#: Table I of Gill & D'Andrea (2017); constants from footnote 2.
PRESETS: dict[str, AirfoilParams] = {
    "gill2017-soft": AirfoilParams(cl1=6.9, cl2=2.0, cd=3.7, alpha0=math.radians(20.4)),
    "gill2017-stiff": AirfoilParams(cl1=4.2, cl2=2.0, cd=1.3, alpha0=math.radians(27.5)),
    "gill2017-apc": AirfoilParams(cl1=5.3, cl2=1.7, cd=1.8, alpha0=math.radians(20.6)),
}


def preset(name: str) -> AirfoilParams:
    """Return the named parameter preset.

    Parameters
    ----------
    name : str
        One of ``"gill2017-soft"``, ``"gill2017-stiff"``, ``"gill2017-apc"``
        (Table I of Gill & D'Andrea 2017: soft = Parrot AR.Drone 2.0,
        stiff = HQP 8x4.5, apc = APC 8x6).

    Raises
    ------
    KeyError
        If ``name`` is not a preset; the message lists the valid names.
    """
    try:
        return PRESETS[name]
    except KeyError:
        raise KeyError(f"unknown parameter preset {name!r}; valid: {', '.join(PRESETS)}") from None


def sigmoid_blend(alpha, alpha0: float, M: float):
    """Stall blend sigma(alpha) of eq (3), overflow-safe.

    ``sigma = 1 - 1 / ((1 + exp(M (alpha - alpha0))) (1 + exp(-M (alpha + alpha0))))``,
    algebraically equal to the paper's form; an overflowing exponential gives the
    correct limit 1 instead of inf/inf.

    Parameters
    ----------
    alpha : float or ndarray
        Angle of attack [rad].
    alpha0, M : float
        Stall angle [rad] and sharpness [1/rad].

    Returns
    -------
    float or ndarray
        sigma in [0, 1], same shape as ``alpha``.
    """
    with np.errstate(over="ignore"):
        p = np.exp(M * (alpha - alpha0))
        q = np.exp(-M * (alpha + alpha0))
    return 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))


def lift_coefficient(alpha, params: AirfoilParams):
    """Section lift coefficient C_L(alpha), eq (3) or footnote 1.

    Parameters
    ----------
    alpha : float or array_like
        Angle of attack [rad]; any shape.
    params : AirfoilParams

    Returns
    -------
    ndarray
        C_L [-], same shape as ``alpha``.
    """
    alpha = np.asarray(alpha, dtype=float)
    post = params.cl2 * np.sin(alpha) * np.cos(alpha)
    if params.lift_model == "sincos":
        return post
    s = sigmoid_blend(alpha, params.alpha0, params.M)
    return (1.0 - s) * params.cl1 * alpha + s * post


def drag_coefficient(alpha, reynolds, params: AirfoilParams):
    """Section drag coefficient C_D(alpha, Re), eq (4).

    ``C_D = c_d sin^2(alpha) + 2 * 1.02 c_p / sqrt(Re) + c_d0``.

    Parameters
    ----------
    alpha : float or array_like
        Angle of attack [rad].
    reynolds : float or array_like
        Chord Reynolds number rho U c / mu [-], > 0; broadcasts with ``alpha``.
    params : AirfoilParams

    Returns
    -------
    ndarray
        C_D [-], the broadcast shape.

    Raises
    ------
    ValueError
        If any Reynolds number is not positive.
    """
    alpha = np.asarray(alpha, dtype=float)
    reynolds = np.asarray(reynolds, dtype=float)
    if np.any(~(reynolds > 0)):
        raise ValueError("reynolds must be > 0 everywhere")
    return params.cd * np.sin(alpha) ** 2 + 2.0 * 1.02 * params.cp_blasius / np.sqrt(reynolds) + params.cd0
