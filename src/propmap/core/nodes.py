"""The blade's quadrature nodes and the kernel's constants of a model (propeller, section
parameters, air, discretization), cached: what :func:`propmap.rotor_loads` and the
derivatives hand the compiled kernels (core/_kernel.py with core/_annulus.py, core/_sensitivity.py).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from . import _flags
from . import _physics as ph
from . import _momentum as mo
from .airfoil import Air, CamberedParams, SectionParams
from .polar import _model_constants
from .geometry import Propeller
from .states import BAND_ARRAY, K_WINDMILL

__all__ = []


@dataclass(frozen=True)
class _Nodes:
    """Quadrature nodes and every per-annulus constant the kernel needs (read-only arrays).

    ``sc``: section constant (gill2017: Blasius factor 2 * 1.02 c_p sqrt(mu/(rho c));
    cambered: ln(rho c / (mu Re_ref))); ``cy2`` = (c/y)^2. ``ct``, ``ch``: tip- and hub-loss constants
    (N_b/2)(R - y)/y and (N_b/2)(y - r_hub)/r_hub, -1 where that loss is off. ``theta``
    includes the collective offset. ``sinpsi``, ``cospsi``: the full circle of 2 n_azimuth
    midpoints from -pi/2, whose first half is the half circle the uniform inflow needs.
    ``chord_r3``: int c r^3 dr over the blade [m^5] (0-d), for the flap damping. ``rows``:
    y, w, theta, sin_th, cos_th, sc, cy2, cfac, mfac, ct, ch as one array (the rows of
    _physics.NODE_Y ... NODE_CH, of which those fields are views), ``azimuth``: sinpsi and
    cospsi as one (2, 2 n_azimuth) array: what the compiled kernels take.
    """

    y: np.ndarray
    w: np.ndarray
    theta: np.ndarray
    sin_th: np.ndarray
    cos_th: np.ndarray
    sc: np.ndarray
    cy2: np.ndarray
    cfac: np.ndarray
    mfac: np.ndarray
    ct: np.ndarray
    ch: np.ndarray
    sinpsi: np.ndarray
    cospsi: np.ndarray
    chord_r3: np.ndarray
    rows: np.ndarray
    azimuth: np.ndarray


@functools.lru_cache(maxsize=64)
def _nodes(prop: Propeller, n_radial: int, n_azimuth: int, air: Air, params: SectionParams) -> _Nodes:
    x, wx = np.polynomial.legendre.leggauss(n_radial)
    half = 0.5 * (prop.radius - prop.r_hub)
    y = prop.r_hub + half * (x + 1.0)
    w = half * wx
    c = prop.chord_at(y)
    th = prop.theta_at(y) + params.collective
    cpos = np.maximum(c, 1e-300)
    if isinstance(params, CamberedParams):
        # a zero chord carries no load (cfac = 0); its Reynolds number is set to Re_ref so
        # that the factors stay finite (ln 0 would overflow them)
        sc = np.where(c > 0, np.log(air.rho * cpos / (air.mu * params.re_ref)), 0.0)
    else:
        sc = np.where(c > 0, 2.0 * 1.02 * params.cp_blasius * np.sqrt(air.mu / (air.rho * cpos)), 0.0)
    half_b = 0.5 * prop.n_blades
    ct = half_b * (prop.radius - y) / y if params.tip_loss else np.full(n_radial, -1.0)
    ch = half_b * (y - prop.r_hub) / prop.r_hub if params.hub_loss else np.full(n_radial, -1.0)
    psi = -0.5 * np.pi + (np.arange(2 * n_azimuth) + 0.5) * np.pi / n_azimuth
    rows = np.empty((ph.N_NODE_ROWS, n_radial))
    for k, a in ((ph.NODE_Y, y), (ph.NODE_W, w), (ph.NODE_TH, th), (ph.NODE_STH, np.sin(th)),
                 (ph.NODE_CTH, np.cos(th)), (ph.NODE_SC, sc), (ph.NODE_CY2, (c / y) ** 2),
                 (ph.NODE_CFAC, prop.n_blades * 0.5 * air.rho * c), (ph.NODE_MFAC, 4.0 * np.pi * air.rho * y),
                 (ph.NODE_CT, ct), (ph.NODE_CH, ch)):
        rows[k] = a
    azimuth = np.stack([np.sin(psi), np.cos(psi)])
    out = _Nodes(y=rows[ph.NODE_Y], w=rows[ph.NODE_W], theta=rows[ph.NODE_TH], sin_th=rows[ph.NODE_STH],
                 cos_th=rows[ph.NODE_CTH], sc=rows[ph.NODE_SC], cy2=rows[ph.NODE_CY2], cfac=rows[ph.NODE_CFAC],
                 mfac=rows[ph.NODE_MFAC], ct=rows[ph.NODE_CT], ch=rows[ph.NODE_CH], sinpsi=azimuth[0],
                 cospsi=azimuth[1], chord_r3=np.array(np.sum(w * c * y**3)), rows=rows, azimuth=azimuth)
    for a in vars(out).values():
        a.setflags(write=False)
    return out


def _lift_slope_name(params: SectionParams) -> str:
    """The parameter that is the section's attached-flow lift slope: cl_alpha (cambered), cl1
    (eq 3) or, for footnote 1's sin-cos lift, cl2 (its slope at alpha = 0)."""
    if isinstance(params, CamberedParams):
        return "cl_alpha"
    return "cl2" if params.lift_model == "sincos" else "cl1"


def _lift_slope(params: SectionParams) -> float:
    """Attached-flow lift slope of the section [1/rad] (:func:`_lift_slope_name`)."""
    return getattr(params, _lift_slope_name(params))


#: the kernel's model arguments of recent (propeller, params, air, discretization), by identity:
#: the records are immutable, so a call with the same objects (a controller's or a fitting loop's
#: single points) skips hashing them for _nodes and rebuilding the constant vectors
_PREPARED: dict = {}


_PREPARED_MAX = 64


def _prepared(propeller: Propeller, params: SectionParams, air: Air, discretization):
    """(nodes, model code, pk, cam, inflow code, empirical descent, the flags' constants cls) of a
    model (``discretization`` a :class:`~propmap.core.solver.Discretization`), cached by identity
    (the cache holds the objects, so an id is not reused while its entry lives)."""
    key = (id(propeller), id(params), id(air), id(discretization))
    hit = _PREPARED.get(key)
    if hit is not None and hit[0] is propeller and hit[1] is params and hit[2] is air and hit[3] is discretization:
        return hit[4]
    nd = _nodes(propeller, discretization.n_radial, discretization.n_azimuth, air, params)
    model, pk = _model_constants(params)
    cam = _cambered_args(params, air)
    cls = np.empty(_flags.CLS_BAND + BAND_ARRAY.size)  # _flags.point_flags' constants
    cls[_flags.CLS_RHO], cls[_flags.CLS_RADIUS], cls[_flags.CLS_R_HUB] = air.rho, propeller.radius, propeller.r_hub
    cls[_flags.CLS_K_WINDMILL], cls[_flags.CLS_BAND:] = K_WINDMILL, BAND_ARRAY
    cls[_flags.CLS_INPLANE] = pk[ph.PK_INPLANE]  # the reverse-flow radius' in-plane airspeed
    for a in (pk, cam, cls):
        a.setflags(write=False)
    prep = (nd, model, pk, cam, mo.INFLOW_CODES[params.inflow], bool(mo.DESCENT_CODES[params.descent]), cls)
    if len(_PREPARED) >= _PREPARED_MAX:
        _PREPARED.clear()
    _PREPARED[key] = (propeller, params, air, discretization, prep)
    return prep


def _cambered_args(params: SectionParams, air: Air) -> np.ndarray:
    """``cam`` argument of the kernel: (cl_alpha, re_exp, re_exp_lift, compressible, 1/a^2,
    re_exp_stall, stall_delay, alpha_L0_re)."""
    if not isinstance(params, CamberedParams):
        return np.zeros(8)
    return np.array([params.cl_alpha, params.re_exp, params.re_exp_lift, float(params.compressibility),
                     1.0 / air.speed_of_sound**2, params.re_exp_stall, params.stall_delay, params.alpha_L0_re])
