"""Compiled (numba) loads of one annulus at its solved inflow (eqs 5-7, azimuth-averaged):
thrust, in-plane force, torque, rolling moment, side force and pitching moment densities, with the
radial flow's drag and the dynamic stall's fore-aft terms. The root solve that gives the inflow is
core/_annulus.py's; core/_kernel.py and core/_linear_sensitivity.py call :func:`annulus_loads`.
"""

from __future__ import annotations

import numba
import numpy as np

from ._annulus import _FM, _atan2, _element, _exp_sat, _inplane_induction, _jit_inline, _stall_blend
from ._physics import (CAMBERED, PK_INPLANE, PK_RADIAL_DRAG, make_delayed_cambered_element,
                       make_profile_drag)

# the profile drag C_D,p U of the radial flow's drag; the delayed element's half differences (dynamic stall)
_profile_cd = _jit_inline(make_profile_drag(_atan2, _stall_blend))
_element_cambered_dh = _jit_inline(make_delayed_cambered_element(_atan2, _exp_sat, halves=True))


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def annulus_loads(v, y, Om, u, Vs, Vc, bl, sec, cfac, azim, gx, gy, naz, model, pk, axial, kd=0.0):
    """dT/dy, dD/dy, dQ/dy, dM_R/dy, dY/dy, dM_P/dy [N/m, N/m, N, N, N/m, N] at mean inflow v
    (eqs 5-7, azimuth-averaged; linear inflow, ``bl``, ``sec`` and ``azim`` as ``_annulus._residual``);
    ``u`` the annulus' swirl [m/s].

    dM_R/dy is the rolling moment density: the thrust density's first azimuthal moment,
    y <dT(psi) sin psi>, positive when the advancing side (psi = 90 deg) carries more.
    dY/dy, the side force toward the advancing side, -<dH(psi) cos psi>, and dM_P/dy,
    the pitching moment density -y <dT(psi) cos psi> (positive when the upstream half,
    psi = 180 deg, carries more), are zero by symmetry with a uniform inflow and the static
    polar and are only accumulated with a linear one (gx or gy non-zero, full-circle nodes) or
    with the dynamic stall (``kd``), whose rising and falling halves differ.

    With ``pk[PK_RADIAL_DRAG]`` = 1 (airfoil.RotorOptions.radial_drag) the radial flow's drag
    C_D,p U u_R (u_R = V sin beta cos psi, per unit 0.5 rho c; C_D,p the profile drag,
    _physics.make_profile_drag) adds its components along the airspeed, cos psi, to dD/dy and
    toward the advancing side, sin psi, to dY/dy; it passes through the shaft. With
    ``pk[PK_INPLANE]`` = 1 the blades' in-plane airspeed, and so u_R, includes the skewed
    wake's in-plane induced velocity at v, as in ``_annulus._residual``. ``kd`` > 0 (``_annulus.delay_factor``,
    uniform inflow): each node and its mirror node through the delayed element, as ``_annulus._residual``.
    """
    th, sth, cth = bl
    s0, s1, s2, s3 = sec
    sinpsi = azim[0]
    cospsi = azim[1]
    aT = 0.0
    aD = 0.0
    aQ = 0.0
    aR = 0.0
    aY = 0.0
    aP = 0.0
    UP = Vc + v
    if not axial and pk[PK_INPLANE] != 0.0:
        Vs = Vs + pk[PK_INPLANE] * _inplane_induction(v, Vs, Vc)
    kr = 0.0 if axial else pk[PK_RADIAL_DRAG] * Vs  # the radial flow's drag: u_R = kr cos psi
    if gx == 0.0 and gy == 0.0 and kd != 0.0 and not axial and model == CAMBERED:
        # each half-circle node (cos psi > 0) with its mirror pi - psi: the same sin psi, U_T and U_P, the opposite
        # cos psi and alpha_dot; the node rises where U_P V_b > 0 (sg), so node - mirror = sg (rise - fall), which
        # gives the fore-aft terms (the pitching moment, the side force) the static polar's symmetry makes zero
        sg = 1.0 if UP * Vs >= 0.0 else -1.0
        for k in range(naz):
            UT = Om * y - u + Vs * sinpsi[k]
            qT, qH, cdpU, hT, hH, hC = _element_cambered_dh(UT, UP, th, sth, cth, s0, s1, s2, s3, pk[0], pk[1], pk[2],
                                                            pk[3], pk[4], pk[5], pk[6], pk[7], kd, Vs * cospsi[k])
            aT += qT
            aD += qH * sinpsi[k] + kr * cdpU * cospsi[k] * cospsi[k]
            aQ += qH
            aR += qT * sinpsi[k]
            aP -= sg * hT * cospsi[k]
            aY += sg * (kr * hC * sinpsi[k] - hH) * cospsi[k]
    elif gx == 0.0 and gy == 0.0:
        for k in range(naz):  # once per annulus: the model branch inside the loop costs little here
            UT = Om * y - u + Vs * sinpsi[k]
            qT, qH = _element(UT, UP, th, sth, cth, s0, s1, s2, s3, model, pk)
            aT += qT
            aD += qH * sinpsi[k]
            aQ += qH
            aR += qT * sinpsi[k]
            if kr != 0.0:  # (its side force cancels over the full circle, psi <-> 180 deg - psi: not accumulated)
                aD += (kr * _profile_cd(UT, UP, th, s0, s1, s2, s3, model, pk) * np.sqrt(UT * UT + UP * UP)
                       * cospsi[k] * cospsi[k])
    else:
        vx = v * gx
        vy = v * gy
        for k in range(naz):
            UT = Om * y - u + Vs * sinpsi[k]
            UPk = UP + vx * cospsi[k] + vy * sinpsi[k]
            qT, qH = _element(UT, UPk, th, sth, cth, s0, s1, s2, s3, model, pk)
            aT += qT
            aD += qH * sinpsi[k]
            aQ += qH
            aR += qT * sinpsi[k]
            aY -= qH * cospsi[k]
            aP -= qT * cospsi[k]
            if kr != 0.0:
                gR = kr * _profile_cd(UT, UPk, th, s0, s1, s2, s3, model, pk) * np.sqrt(UT * UT + UPk * UPk) * cospsi[k]
                aD += gR * cospsi[k]
                aY += gR * sinpsi[k]
    dD = 0.0 if axial else cfac * aD / naz  # exactly 0 by symmetry in axial flow
    dR = 0.0 if axial else y * cfac * aR / naz
    return cfac * aT / naz, dD, y * cfac * aQ / naz, dR, cfac * aY / naz, y * cfac * aP / naz
