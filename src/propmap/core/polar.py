"""The section polar evaluated through the solver's own element: the element's model code and
constants of a parameter set (:func:`_model_constants`, which the nodes, the derivatives and the
NumPy reference share) and C_L(alpha), C_D(alpha, Re) of either section model (Gill & D'Andrea
2017 eqs 3-4 and footnote 1, or the cambered polar of :class:`propmap.core.airfoil.CamberedParams`).
"""

from __future__ import annotations

import numpy as np

from . import _physics as ph
from .airfoil import CamberedParams, SectionParams

__all__ = ["drag_coefficient", "lift_coefficient"]


def _model_constants(params: SectionParams) -> tuple[int, np.ndarray]:
    """Section-model code and constant vector ``pk`` of the element (layout in _physics)."""
    pk = np.zeros(ph.N_PK)
    pk[ph.PK_RADIAL_DRAG] = 1.0 if params.radial_drag else 0.0
    pk[ph.PK_INPLANE] = 1.0 if params.inplane_induction else 0.0
    pk[ph.PK_DYNSTALL] = params.dynamic_stall
    if isinstance(params, CamberedParams):
        p = params
        pk[:8] = (p.alpha_L0, p.cd90, p.cd_min, p.cd2, p.cl_cdmin, p.M, p.cl_max / p.cl_alpha,
                  p.cl_min / p.cl_alpha)
        return ph.CAMBERED, pk
    p = params
    pk[:6] = (p.cl1, p.cl2, p.cd, p.alpha0, p.M, p.cd0)
    return (ph.GILL_SINCOS if p.lift_model == "sincos" else ph.GILL_SIGMOID), pk


def _section_cd_cl(alpha, reynolds, mach, params: SectionParams):
    """C_L, C_D of ``params`` at angle of attack ``alpha`` through the solver's own element.

    With U_T = 1, U_P = 0 the element's outputs are exactly C_L and C_D (theta = alpha).
    """
    alpha, reynolds, mach = _polar_inputs(alpha, reynolds, mach, params)
    model, pk = _model_constants(params)
    if model == ph.CAMBERED:
        # the solver's per-annulus factors with U = 1: Re / Re_ref = exp(ln_re_c), Ma^2 = mach2_c
        p = params
        s0, s1, s2, s3 = ph.cambered_annulus(1.0, np.log(reynolds / p.re_ref), 0.0, mach * mach, p.cl_alpha, p.re_exp,
                                             p.re_exp_lift, p.compressibility, p.re_exp_stall, 0.0, p.alpha_L0_re)
    else:
        # eq (4)'s Blasius term 2 * 1.02 c_p / sqrt(Re) = s0 / sqrt(U) with U = 1
        s0, s1, s2, s3 = 2.0 * 1.02 * params.cp_blasius / np.sqrt(reynolds), 0.0, 0.0, 0.0
    CL, CD = ph.element(1.0, 0.0, alpha, np.sin(alpha), np.cos(alpha), s0, s1, s2, s3, model, pk)
    return CL, CD


def _polar_inputs(alpha, reynolds, mach, params) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """alpha, reynolds and mach as float arrays of their broadcast shape, checked: numbers (no
    strings or bools), finite, Re > 0, Ma >= 0; params a section set (a property-based audit
    found NaN returned silently, a negative Mach number read as 0.9's factor, and errors from
    inside for the wrong types)."""
    from .airfoil import AirfoilParams
    from .geometry import has_bool

    if not isinstance(params, (AirfoilParams, CamberedParams)):
        # the two take their arguments in different orders (the Reynolds number is optional for the lift only)
        swapped = (" (the orders are lift_coefficient(alpha, params, reynolds) and drag_coefficient(alpha, "
                   "reynolds, params))" if isinstance(reynolds, (AirfoilParams, CamberedParams)) else "")
        raise TypeError(f"params must be AirfoilParams or CamberedParams, got {type(params).__name__}{swapped}")
    out = []
    for name, v, ok, rule in (("alpha", alpha, lambda a: np.isfinite(a), "finite [rad]"),
                              ("reynolds", reynolds, lambda a: np.isfinite(a) & (a > 0), "finite and > 0"),
                              ("mach", mach, lambda a: np.isfinite(a) & (a >= 0), "finite and >= 0")):
        try:
            a = np.asarray(v)
        except ValueError:  # a ragged list
            a = np.asarray(None)
        if a.dtype.kind not in "iuf" or has_bool(v):
            raise ValueError(f"{name} must be a number or an array of numbers, got {v!r:.60}")
        a = a.astype(float)
        if not np.all(ok(a)):
            raise ValueError(f"{name} must be {rule} everywhere, got {float(a.reshape(-1)[np.argmin(ok(a))])!r}")
        out.append(a)
    try:
        return tuple(np.broadcast_arrays(*out))
    except ValueError:
        raise ValueError(f"alpha, reynolds and mach must broadcast together, got shapes "
                         f"{', '.join(str(a.shape) for a in out)}") from None


def lift_coefficient(alpha, params: SectionParams, reynolds=None, mach=0.0):
    """Section lift coefficient C_L(alpha): eq (3) / footnote 1, or the cambered polar.

    Parameters
    ----------
    alpha : float or array_like
        Angle of attack from the blade-angle datum [rad]; any shape.
    params : AirfoilParams or CamberedParams
    reynolds : float or array_like, optional
        Chord Reynolds number [-], > 0 (cambered only; default its ``re_ref``; eq 3 has
        no Reynolds dependence).
    mach : float or array_like
        Section Mach number [-] (cambered with compressibility only).

    Returns
    -------
    ndarray
        C_L [-], the broadcast shape.

    Raises
    ------
    ValueError
        An input that is not numbers or not finite, a Reynolds number not positive, a
        negative Mach number, shapes that do not broadcast.
    TypeError
        ``params`` not a section set.
    """
    if reynolds is None:
        reynolds = getattr(params, "re_ref", 1e5)
    return _section_cd_cl(alpha, reynolds, mach, params)[0]


def drag_coefficient(alpha, reynolds, params: SectionParams, mach=0.0):
    """Section drag coefficient C_D(alpha, Re): eq (4), or the cambered polar.

    eq (4): ``C_D = c_d sin^2(alpha) + 2 * 1.02 c_p / sqrt(Re) + c_d0``.

    Parameters
    ----------
    alpha : float or array_like
        Angle of attack [rad].
    reynolds : float or array_like
        Chord Reynolds number rho U c / mu [-], > 0; broadcasts with ``alpha``.
    params : AirfoilParams or CamberedParams
    mach : float or array_like
        Section Mach number [-] (cambered with compressibility only: it changes C_L and
        thereby the polar's C_D).

    Returns
    -------
    ndarray
        C_D [-], the broadcast shape.

    Raises
    ------
    ValueError
        An input that is not numbers or not finite, a Reynolds number not positive, a
        negative Mach number, shapes that do not broadcast.
    TypeError
        ``params`` not a section set.
    """
    return _section_cd_cl(alpha, reynolds, mach, params)[1]
