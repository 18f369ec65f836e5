"""Compiled (numba) partial derivatives of an annulus' momentum side, F dT_BEMT/dy (eq 10 with
Prandtl's loss factor F, Glauert's mass flow or the empirical descent curve), at a fixed
inflow: the part of the implicit derivatives (core/_sensitivity.py) that has no azimuth sum.

The momentum side is one expression per annulus, so it is differentiated analytically:
through Glauert's |V cos beta + v|, through the empirical descent curve's inversion
(dk/dr = k / (f'(k) - r), _momentum.axial_mass_flow), and through Prandtl's factor of
1/sin phi = sqrt(w^2 + (Omega y)^2) / w (w the axial mass-flow velocity; with swirl the
caller passes Omega less u / y, the blade speed the loss factor sees). Where the empirical
model switches on at V > 0 (V cos beta = 0, v = -V cos beta / 2) the caller differences
:func:`_momentum_side` centrally instead. At V = 0 the airspeed's one-sided slope along a ray is
the analytic partials' chain rule, with the empirical curve's slope at hover on a descending
ray (:func:`_rest_slope`).
"""

from __future__ import annotations

import numba
import numpy as np

from ._annulus import _FM, _axial_mass_flow, _empirical_k, _inverse_sin_phi, _momentum_thrust, _prandtl
from ._jitcache import CACHE
from ._physics import TWO_OVER_PI
from ._momentum import EMPIRICAL_C1, EMPIRICAL_C2, EMPIRICAL_C3, EMPIRICAL_C4, EMPIRICAL_HOVER_RATIO

#: relative step of the momentum side's central differences at the fixed root
STEP = 1e-5


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _momentum_side(v, Om, Vs, Vc, y, mfac, ct, ch, emp):
    """F_loss dT_BEMT/dy of one annulus [N/m]: the residual's momentum side (as _annulus._residual,
    with the loss factor of _annulus.solve_annuli)."""
    floss = 1.0
    if ct >= 0.0 or ch >= 0.0:
        if emp and Vc < 0.0:
            inv_sin = _inverse_sin_phi(_axial_mass_flow(v, Vc, Vs), Om * y)
        else:
            inv_sin = _inverse_sin_phi(Vc + v, Om * y)
        if ct >= 0.0:
            floss = _prandtl(ct, inv_sin)
        if ch >= 0.0:
            floss *= _prandtl(ch, inv_sin)
    if emp:
        w_ax = _axial_mass_flow(v, Vc, Vs)
        return floss * mfac * v * np.sqrt(Vs * Vs + w_ax * w_ax)
    return floss * _momentum_thrust(v, mfac, Vs, Vc)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _rest_slope(m_vs, m_vc, v, sb, cb, emp):
    """d(F_loss dT_BEMT/dy)/dV from rest (V = 0) along the ray (V sin beta, V cos beta) = V (sb, cb),
    one-sided (V >= 0), from the analytic partials ``m_vs``, ``m_vc`` at V = 0 (Glauert's there:
    :func:`_momentum_partials`): their chain rule m_vs sb + m_vc cb, but on a descending ray (cb < 0)
    with the empirical descent curve (``emp``) and v > 0, which it switches on at once (for any
    d = -V cos beta > 0; beyond EMPIRICAL_HOVER_RATIO at its first order): there the mass-flow velocity is v_h^2 / v =
    v / f(k)^2 with k = d / v_h -> d / v, so dw/dd = -2 f'(0) = -2 EMPIRICAL_C1 (the curve's
    slope at hover, _momentum.axial_mass_flow; the in-plane fade exp(-(V sb / v)^2) is flat at
    V = 0) instead of Glauert's -1, and m_vc, linear in dw/dV cos beta, scales by 2 EMPIRICAL_C1."""
    if emp and cb < 0.0 and v > 0.0:
        return m_vs * sb + 2.0 * EMPIRICAL_C1 * m_vc * cb
    return m_vs * sb + m_vc * cb


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _prandtl_slope(c, inv_sin):
    """dF/d(1/sin phi) of Prandtl's factor F = (2/pi) acos(exp(-c / sin phi)) (_physics.make_prandtl)."""
    x = min(np.exp(-c * inv_sin), 1.0 - 1e-16)
    return TWO_OVER_PI * c * x / np.sqrt(1.0 - x * x)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _mass_flow_partials(v, Vc, Vs, emp):
    """The axial mass-flow velocity w [m/s] of one annulus and dw/d(v, V cos beta, V sin beta) [-]
    (inflow v and speeds [m/s]).

    Glauert's w = |Vc + v|, or with ``emp`` in the vortex-ring and turbulent-wake states the
    empirical curve of _momentum.axial_mass_flow, w = g + (v_h^2 / v - g) exp(-(Vs/v)^2),
    g = |Vc + v|, v_h = d / k, d = -Vc, where k solves f(k) = (v/d) k: differentiated
    through that equation (dk/dr = k / (f'(k) - r), r = v/d), not by differences.
    """
    UP = Vc + v
    sg = 1.0 if UP >= 0.0 else -1.0
    g = abs(UP)
    d = -Vc
    if not emp or d <= 0.0 or v <= 0.5 * d:
        return g, sg, sg, 0.0
    if v > EMPIRICAL_HOVER_RATIO * d:  # the curve's first order in k (_momentum.axial_mass_flow)
        A = v - 2.0 * EMPIRICAL_C1 * d
        dA_v = 1.0
        dA_vc = 2.0 * EMPIRICAL_C1
    else:
        r = v / d
        k = _empirical_k(r)
        fp = EMPIRICAL_C1 + k * (2.0 * EMPIRICAL_C2 + k * (3.0 * EMPIRICAL_C3 + 4.0 * EMPIRICAL_C4 * k))
        dk_dr = k / (fp - r)
        vh = d / k
        # d(v_h)/dv and d(v_h)/dVc (d = -Vc, r = v / d)
        dvh_v = -d / (k * k) * dk_dr / d
        dvh_vc = -(1.0 / k - d / (k * k) * dk_dr * (-v / (d * d)))
        A = vh * vh / v
        dA_v = 2.0 * vh * dvh_v / v - A / v
        dA_vc = 2.0 * vh * dvh_vc / v
    q = Vs / v
    E = np.exp(-q * q)
    dE_v = E * 2.0 * q * q / v
    dE_vs = -E * 2.0 * q / v
    w = g + (A - g) * E
    return w, sg * (1.0 - E) + dA_v * E + (A - g) * dE_v, sg * (1.0 - E) + dA_vc * E, (A - g) * dE_vs


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _momentum_partials(v, Om, Vs, Vc, y, mfac, ct, ch, emp):
    """d(F_loss dT_BEMT/dy)/d(v, Omega, V sin beta, V cos beta) of one annulus, analytic.

    The momentum side (_momentum_side) is mfac v sqrt(Vs^2 + w^2) times the loss factor of
    1/sin phi = sqrt(w^2 + (Omega y)^2) / w, w the axial mass-flow velocity
    (:func:`_mass_flow_partials`; |Vc + v| with Glauert's momentum).
    """
    w, w_v, w_vc, w_vs = _mass_flow_partials(v, Vc, Vs, emp)
    W = np.sqrt(Vs * Vs + w * w) + 1e-300
    m = mfac * v * W
    m_w = mfac * v * w / W  # dm/dw
    m_v = mfac * W + m_w * w_v
    m_vc = m_w * w_vc
    m_vs = mfac * v * Vs / W + m_w * w_vs
    floss = 1.0
    f_w = 0.0  # dF/dw and dF/d(Omega y)
    f_wy = 0.0
    if ct >= 0.0 or ch >= 0.0:
        wy = Om * y
        root = np.sqrt(w * w + wy * wy)
        inv_sin = root / (w + 1e-300)
        ds_w = -wy * wy / (w * w * root + 1e-300)
        ds_wy = wy / (w * root + 1e-300)
        ft = _prandtl(ct, inv_sin) if ct >= 0.0 else 1.0
        fh = _prandtl(ch, inv_sin) if ch >= 0.0 else 1.0
        dfs = (_prandtl_slope(ct, inv_sin) * fh if ct >= 0.0 else 0.0) + \
            (_prandtl_slope(ch, inv_sin) * ft if ch >= 0.0 else 0.0)
        floss = ft * fh
        f_w = dfs * ds_w
        f_wy = dfs * ds_wy
    return (floss * m_v + f_w * w_v * m, f_wy * y * m, floss * m_vs + f_w * w_vs * m, floss * m_vc + f_w * w_vc * m)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _momentum_derivatives(v, Om_e, Om, Vs, Vc, y, mfac, ct, ch, emp, one_sided):
    """d(F_loss dT_BEMT/dy)/d(v, Omega, V sin beta, V cos beta) of one annulus at its fixed root:
    :func:`_momentum_partials` (analytic), except where the empirical descent model switches on
    (V cos beta = 0 at V > 0, and v = -V cos beta / 2), where the momentum side is differenced
    centrally in v, Omega, V sin beta and V cos beta with steps :data:`STEP` of each variable's
    scale (not of the incidence, whose step would move V cos beta by only V STEP: at small
    airspeeds that stays on one side of the switch). At V = 0 (``one_sided``) the empirical model
    is Glauert's (d = -V cos beta = 0): analytic in all four; the airspeed's one-sided slope along
    a ray is then the caller's (:func:`_rest_slope`). ``Om_e``: the blade speed's Omega
    (Omega - u / y with swirl), ``Om`` the rotation rate (the step's scale)."""
    if not emp or one_sided or (Vc != 0.0 and abs(v + 0.5 * Vc) > 1e-6 * (abs(v) + abs(Vc))):
        return _momentum_partials(v, Om_e, Vs, Vc, y, mfac, ct, ch, emp)
    hv = STEP * (abs(v) + abs(Vc) + abs(Vs) + 0.01 * Om * y + 1e-9)
    mv = (_momentum_side(v + hv, Om_e, Vs, Vc, y, mfac, ct, ch, emp)
          - _momentum_side(v - hv, Om_e, Vs, Vc, y, mfac, ct, ch, emp)) / (2.0 * hv)
    ho = STEP * Om
    m_om = (_momentum_side(v, Om_e + ho, Vs, Vc, y, mfac, ct, ch, emp)
            - _momentum_side(v, Om_e - ho, Vs, Vc, y, mfac, ct, ch, emp)) / (2.0 * ho)
    m_vs = (_momentum_side(v, Om_e, Vs + hv, Vc, y, mfac, ct, ch, emp)
            - _momentum_side(v, Om_e, Vs - hv, Vc, y, mfac, ct, ch, emp)) / (2.0 * hv)
    m_vc = (_momentum_side(v, Om_e, Vs, Vc + hv, y, mfac, ct, ch, emp)
            - _momentum_side(v, Om_e, Vs, Vc - hv, y, mfac, ct, ch, emp)) / (2.0 * hv)
    return mv, m_om, m_vs, m_vc
