"""The swirl's part of the implicit derivatives (core/_sensitivity.py for the uniform inflow,
core/_linear_sensitivity.py for the linear inflow models): each annulus' two equations in its
inflow v and swirl u, linearised at the converged (v, u), and their solution for one input.

With ``RotorOptions.swirl`` the root solves eq 11 at the blade speed Omega y - u, G(v, u, x) =
0, and the swirl balances the annulus' angular momentum, S(v, u, x) = u - v dQ / (y dT) = 0
(_momentum.swirl_target: the rotational interference factor a' = u / (Omega y) of blade-element
momentum theory; H. Glauert, "Airplane Propellers", in W. F. Durand (ed.), Aerodynamic Theory,
vol. IV, div. L, Springer, 1935), or is held at its clip +-SWIRL_LIMIT Omega y. The implicit
function theorem on both (A. Ning, "Using blade element momentum methods with gradient-based
design optimization", Structural and Multidisciplinary Optimization 64, 2021) gives (dv/dx,
du/dx) from the 2 x 2 Jacobian in (v, u); without swirl the identity S = u leaves dv/dx =
-G_x / G_v.
"""

from __future__ import annotations

import numba

from ._annulus import _FM
from ._momentum import SWIRL_LIMIT


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _swirl_system(swirl, v, y, Om, T0, Q0, Tv, Qv, Tt, Dt, Qt, Rt, mom_wy, Gv):
    """One annulus' linearised equations in its unknowns (v, u), the inflow and the swirl.

    The root solves G(v, u, x) = dT_BET - F dT_BEMT = 0 (eq 11) at the blade speed Omega y - u,
    and with swirl u balances the angular momentum, S(v, u, x) = u - v dQ / (y dT) = 0
    (_momentum.swirl_target; dT, dQ the annulus' thrust and torque densities), or is held at its
    clip +-SWIRL_LIMIT Omega y. Given the loads' partials at the fixed (v, u): ``Tv``, ``Qv``
    (d/dv of dT, dQ), ``Tt``, ``Dt``, ``Qt``, ``Rt`` (d/dU_T of dT, dD, dQ, dM_R: the swirl's
    partials are their negatives), ``mom_wy`` (d/d(Omega y) of the momentum side: its swirl
    partial is the negative) and ``Gv``; ``T0``, ``Q0`` the thrust and torque densities at the
    root. Returns (G_u, S_v, S_u, a, T0, Q0 [or the clip's
    dS/dOmega in a's place, T0 = 0], Tt, Dt, Qt, Rt, Gv) for :func:`_swirl_solve`; without swirl
    the identity S = u (u held at 0): G_u = S_v = 0, S_u = 1 and the U_T partials zeroed.
    """
    if not swirl:
        return 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, Gv
    Gu = -Tt + mom_wy
    if T0 == 0.0:  # no thrust: the target is 0 (_momentum.swirl_target), S = u
        return Gu, 0.0, 1.0, 0.0, 0.0, 0.0, Tt, Dt, Qt, Rt, Gv
    target = v * Q0 / (y * T0)
    lim = SWIRL_LIMIT * Om * y
    if abs(target) >= lim:  # held at the clip, S = u -+ SWIRL_LIMIT Omega y: it moves with Omega only
        return Gu, 0.0, 1.0, (-SWIRL_LIMIT * y if target > 0.0 else SWIRL_LIMIT * y), 0.0, 0.0, Tt, Dt, Qt, Rt, Gv
    a = v / (y * T0 * T0)
    Sv = -Q0 / (y * T0) - a * (Qv * T0 - Q0 * Tv)
    Su = 1.0 + a * (Qt * T0 - Q0 * Tt)
    return Gu, Sv, Su, a, T0, Q0, Tt, Dt, Qt, Rt, Gv


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _swirl_solve(sw, Gx, Tx, Qx, e_om):
    """(dv/dx, du/dx) of one annulus from its :func:`_swirl_system` ``sw`` and an input's
    partials at the fixed (v, u): ``Gx`` of the residual, ``Tx``, ``Qx`` of the thrust and
    torque densities, ``e_om`` the input's Omega component (moves a clipped swirl); without
    swirl dv = -Gx / G_v, du = 0."""
    Gu, Sv, Su, a, T0, Q0, _, _, _, _, Gv = sw
    if T0 != 0.0:
        Sx = -a * (Qx * T0 - Q0 * Tx)
    else:  # held at 0 or at its clip (a: the clip's dS/dOmega)
        Sx = a * e_om
    det = Gv * Su - Gu * Sv
    return -(Gx * Su - Gu * Sx) / det, -(Gv * Sx - Sv * Gx) / det
