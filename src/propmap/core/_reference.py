"""Straightforward vectorised NumPy implementation of the same solver.

It exists for two reasons: it is the baseline that benchmarks/ times beside the
compiled kernel (the brief's "straightforward vectorised NumPy implementation"), and it
is an independent check of the kernel's control flow in the tests (same element
physics from ``_physics.py`` and ``_momentum.py``, same root-selection rule, but array masks instead of
scalar loops). Not part of the public API.
"""

from __future__ import annotations

import numpy as np

from . import _annulus as K
from ._physics import (CAMBERED, PK_DYNSTALL, PK_INPLANE, PK_RADIAL_DRAG, cambered_annulus, element,
                       element_cambered_delayed, loss_factor_numpy, profile_cd)
from ._momentum import (SWIRL_LIMIT, SWIRL_MAX_ITER, SWIRL_SECANT_ITER, SWIRL_TOL, inplane_induction_numpy,
                        momentum_scale, momentum_thrust, swirl_step, swirl_target)


def solve_reference(om, Vs, Vc, nodes, p, air=None):
    """Return (T, D, Q, v_i, converged) for flat arrays om, Vs, Vc (shape (n,)).

    ``nodes`` from ``nodes._nodes`` for the same parameters ``p`` and ``air``. The paper's
    uniform inflow and rigid blades only (``p.inflow == "uniform"``, no flapping); with
    ``p.swirl`` the swirl is iterated around the root solve by the kernel's bracketed secant,
    annulus by annulus (_momentum.swirl_target, swirl_step; _kernel._swirl_iterate), with NumPy
    arrays.
    """
    if not p.swirl:
        return _solve_u(om, Vs, Vc, nodes, p, air, None)[:5]
    om1 = np.asarray(om, float)
    Omy = om1[:, None] * nodes.y[None, :]
    tol, lim = SWIRL_TOL * Omy, SWIRL_LIMIT * Omy
    u = np.zeros_like(Omy)
    u_prev, g_prev = np.full_like(u, np.nan), np.full_like(u, np.nan)
    lo, hi = np.full_like(u, np.nan), np.full_like(u, np.nan)
    target = np.vectorize(swirl_target)
    step = np.vectorize(swirl_step)
    for it in range(SWIRL_MAX_ITER):
        T, D, Q, v, conv, dT, dQ = _solve_u(om, Vs, Vc, nodes, p, air, u)
        g = np.clip(target(v, dT, dQ, nodes.y[None, :]), -lim, lim) - u
        lo = np.where(g > 0, u, lo)
        hi = np.where(g < 0, u, hi)
        # balanced, or the root jumps there (the bracket closed without a balance; the kernel
        # flags it as multiple roots): the annulus keeps its u, as in the kernel
        done = (np.abs(g) <= tol) | (np.abs(hi - lo) <= tol)
        if done.all():
            return T, D, Q, v, conv
        with np.errstate(invalid="ignore"):  # NaN: a bracket end not known yet
            nxt = np.where(done, u, step(u, g, u_prev, g_prev, lo, hi, it == 0, it >= SWIRL_SECANT_ITER, lim))
        u, u_prev, g_prev = nxt, u, g
    return T, D, Q, v, conv & done.all(axis=1)


def _solve_u(om, Vs, Vc, nodes, p, air, u):
    """(T, D, Q, v_i, converged, dT/dy, dQ/dy) with the annuli's swirl ``u`` (n, nr) [m/s] or None."""
    if p.inflow != "uniform" or p.flap_compliance > 0:
        raise ValueError("the NumPy reference solves the uniform inflow of rigid blades only")
    from .airfoil import Air
    from .polar import _model_constants
    from .nodes import _cambered_args

    air = air or Air()
    model, pk = _model_constants(p)
    om1 = np.asarray(om, float)
    om = om1[:, None, None]
    Vs3 = np.asarray(Vs, float)[:, None, None]
    y = nodes.y[None, :, None]
    sinpsi = nodes.sinpsi[None, None, : nodes.sinpsi.size // 2]  # the half circle: uniform inflow only
    cospsi = nodes.cospsi[None, None, : nodes.cospsi.size // 2]
    wy3 = om * y - (0.0 if u is None else u[:, :, None])
    ux = pk[PK_INPLANE]  # the skewed wake's in-plane induced velocity on (1) or off (0)

    def blade_ut(v):  # the blades' U_T at inflow v (n, nr): the in-plane airspeed, plus u_x(v) with the option
        return wy3 + (Vs3 + ux * inplane_induction_numpy(v, Vs2, Vc2)[:, :, None]) * sinpsi

    UT = wy3 + Vs3 * sinpsi  # (n, nr, naz)
    cfac = nodes.cfac[None, :]
    mfac = nodes.mfac[None, :]
    Vs2 = np.asarray(Vs, float)[:, None]
    Vc2 = np.asarray(Vc, float)[:, None]
    if model == CAMBERED:
        cam = _cambered_args(p, air)
        U2 = (om1[:, None] * nodes.y[None, :]) ** 2 + 0.5 * Vs2**2 + Vc2**2
        s0, s1, s2, s3 = cambered_annulus(U2, nodes.sc[None, :], nodes.cy2[None, :], cam[4], cam[0], cam[1],
                                          cam[2], cam[3] != 0.0, cam[5], cam[6], cam[7])
    else:
        s0 = nodes.sc[None, :]
        s1 = s2 = s3 = 0.0 * s0
    geo = (nodes.theta[None, :, None], nodes.sin_th[None, :, None], nodes.cos_th[None, :, None],
           s0[..., None], s1[..., None], s2[..., None], s3[..., None])
    pars = (model, pk)
    wy = om1[:, None] * nodes.y[None, :] - (0.0 if u is None else u)
    lossy = bool(np.any(nodes.ct >= 0) or np.any(nodes.ch >= 0))

    # Gormont's dynamic stall (RotorOptions.dynamic_stall): kd = gamma sqrt(c Omega / 2) per point and annulus, the
    # node and its mirror node through the delayed element (_physics.make_delayed_cambered_element)
    kd = (pk[PK_DYNSTALL] * np.sqrt(0.5 * nodes.y * np.sqrt(nodes.cy2) * om1[:, None]) * (Vs2 != 0))[..., None]
    delayed = model == CAMBERED and pk[PK_DYNSTALL] != 0.0

    def elem(UTv, UPv, Vb, profile=True):
        """(qT, qH, C_D,p U or None) of the nodes; Vb the blades' in-plane airspeed (n, nr, 1)."""
        if delayed:
            return element_cambered_delayed(UTv, UPv, *geo, *pk[:8], kd, Vb * cospsi)
        qT, qH = element(UTv, UPv, *geo, *pars)
        return qT, qH, (profile_cd(UTv, UPv, *geo[:1], *geo[3:], model, pk) * np.sqrt(UTv**2 + UPv**2)
                        if profile else None)

    def F(v):  # v shape (n, nr)
        Vb = (Vs3 + ux * inplane_induction_numpy(v, Vs2, Vc2)[:, :, None]) if delayed else Vs3
        qT = elem(blade_ut(v) if ux else UT, (Vc2 + v)[:, :, None], Vb, profile=False)[0]
        mom = momentum_thrust(v, mfac, Vs2, Vc2)
        if lossy:
            mom = mom * loss_factor_numpy(Vc2 + v, wy, nodes.ct[None, :], nodes.ch[None, :])
        return cfac * qT.mean(axis=2) - mom

    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        F0 = F(np.zeros_like(cfac * Vs2))
        s = np.where(F0 >= 0, 1.0, -1.0)
        h = momentum_scale(F0, mfac, Vs2, Vc2)
        if lossy:  # the kernel's march sizing with the loss factor at the loss-free scale
            h = momentum_scale(F0, mfac * loss_factor_numpy(Vc2 + s * h, wy, nodes.ct[None, :], nodes.ch[None, :]),
                               Vs2, Vc2)
        h = h / K.MARCH_STEPS
        a = np.zeros_like(F0)
        fa = F0.copy()
        b = a.copy()
        fb = F0.copy()
        done = F0 == 0.0

        def advance(trial):
            """Evaluate F at ``trial`` where not done; keep the last point before a sign change."""
            nonlocal a, fa, b, fb, done
            ft = F(trial)
            hit = ~done & (ft * s <= 0)
            move = ~done & ~hit
            a = np.where(move, trial, a)
            fa = np.where(move, ft, fa)
            b = np.where(~done, trial, b)
            fb = np.where(~done, ft, fb)
            done = done | hit

        for k in range(1, K.MAX_MARCH + 1):  # the march of step h
            advance(np.where(done, b, s * k * h))
            if done.all():
                break
        for _ in range(K.MAX_DOUBLING):  # then doubling
            if done.all():
                break
            advance(np.where(done, b, 2 * b))
        converged = done.copy()
        xtol = K.XTOL * h * K.MARCH_STEPS
        ftol = K.FTOL * np.abs(F0)
        fin = ~done | (fb == 0) | (F0 == 0)
        for _ in range(K.MAX_REFINE):
            if fin.all():
                break
            c = np.where(fin, b, (a * fb - b * fa) / (fb - fa))
            fc = F(c)
            swap = ~fin & (fc * fb < 0)
            half = ~fin & ~swap
            a = np.where(swap, b, a)
            fa = np.where(swap, fb, np.where(half, 0.5 * fa, fa))
            b = np.where(fin, b, c)
            fb = np.where(fin, fb, fc)
            fin |= (np.abs(fb) <= ftol) | (np.abs(b - a) <= xtol)
        converged &= fin
        v = np.where(F0 == 0, 0.0, b)
        Vb = Vs3 + ux * inplane_induction_numpy(v, Vs2, Vc2)[:, :, None]  # the blades' in-plane airspeed
        UT = wy3 + Vb * sinpsi
        qT, qH, cdpU = elem(UT, (Vc2 + v)[:, :, None], Vb)
    axial = (np.asarray(Vs) == 0)[:, None]
    dT = cfac * qT.mean(axis=2)
    with np.errstate(invalid="ignore", divide="ignore"):  # the radial flow's drag (_annulus_loads.annulus_loads)
        radial = pk[PK_RADIAL_DRAG] * cdpU * Vb * cospsi**2
    dD = np.where(axial, 0.0, cfac * (qH * sinpsi + radial).mean(axis=2))
    dQ = nodes.y[None, :] * cfac * qH.mean(axis=2)
    w = nodes.w
    return dT @ w, dD @ w, dQ @ w, v, converged.all(axis=1), dT, dQ
