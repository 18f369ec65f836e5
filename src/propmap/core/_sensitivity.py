"""Compiled (numba) implicit derivatives of the loads: the implicit function theorem on each
annulus' converged root.

On annulus j the inflow v solves G(v, x) = dT_BET - F dT_BEMT = 0 (eq 11) for the inputs
x = (Omega, V sin beta, V cos beta, collective). Its loads L(v, x) (eqs 5-7 and the rolling
moment, azimuth-averaged) then change with x as

    dL/dx = dL/dx|_v + dL/dv|_x dv/dx,    dv/dx = -(dG/dx|_v) / (dG/dv|_x)

(the implicit function theorem; the approach of A. Ning, "Using blade element momentum
methods with gradient-based design optimization", Structural and Multidisciplinary
Optimization 64, 2021, there with algorithmic differentiation of the residual). The
partial derivatives at the fixed root are central differences of the residual and loads
(no root solve in them): their error is the difference's, O(h^2) with h = 1e-5 of each
variable's scale, far below the root's own tolerance, whereas differencing the whole solver
would carry that tolerance (1e-7 of the inflow scale) divided by h. One evaluation of the
annulus gives G and L together (G's BET side is L's thrust), so each derivative costs two
element passes per annulus and the inflow's two more (the solve costs about 8 residual
evaluations and one loads pass; benchmarks/README.md has the measured ratio, 2.7x the
loads alone for the three inputs).

A section parameter enters through the element's constants (pk) and the annulus'
Reynolds constants (cam) only; its partial derivatives are the differences of the residual
and loads between the constants at its two values (central, or one-sided at a bound of its
range), computed by the caller.

The residual and the loads are the solver's own (_kernel._residual and annulus_loads, with
the loss factor and the cambered section's Reynolds constants recomputed at each perturbed
input): uniform inflow only, every azimuth node of the half circle where V sin beta is
nonzero or perturbed (the nodes are symmetric in sin psi, which makes T even and D, M_R odd
in V sin beta, so the differences at V sin beta = 0 are exact); in axial flow, where it is
not perturbed (Omega, V along the axis, the collective), one node, the integrand being
independent of psi there, with the D and M_R derivatives 0 by that symmetry.
"""

from __future__ import annotations

import numba
import numpy as np

from ._jitcache import CACHE
from ._kernel import (_FM, CAMBERED, GILL_SINCOS, _axial_mass_flow, _cambered_annulus, _element_cambered,
                      _element_gill, _inverse_sin_phi, _momentum_thrust, _prandtl)

#: relative step of the central differences at the fixed root
STEP = 1e-5
#: inputs, in the order of the output's second axis
INPUTS = ("omega", "airspeed", "incidence", "collective")
#: loads, in the order of the output's first axis (and the mean induced velocity)
LOADS = ("thrust", "drag", "torque", "rolling_moment", "v_i_mean")


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def _constants(Om, Vs, Vc, y, sc, cy2, model, cam):
    """The section constants (s0, s1, s2, s3) of an annulus at the inputs (as _solve_batch)."""
    if model == CAMBERED:
        return _cambered_annulus((Om * y) ** 2 + 0.5 * Vs * Vs + Vc * Vc, sc, cy2, cam[4], cam[0], cam[1], cam[2],
                                 cam[3] != 0.0, cam[5], cam[6], cam[7])
    return sc, 0.0, 0.0, 0.0


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined: many call sites (compile time)
def _blade_sums(v, Om, Vs, Vc, y, th, sth, cth, s0, s1, s2, s3, cfac, sinpsi, naz, model, pk):
    """(dT/dy, dD/dy, dQ/dy, dM_R/dy) of one annulus at inflow v and inputs (Om, Vs, Vc), blade
    angle th (its sine and cosine) and section constants s0..s3: _kernel.annulus_loads with the
    uniform inflow, one loop per section model (straight-line SIMD code, as _kernel._residual)."""
    aT = 0.0
    aD = 0.0
    aQ = 0.0
    aR = 0.0
    UP = Vc + v
    if model == CAMBERED:
        a0, a1, a2, a3, a4, a5, a6, a7 = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7]
        for k in range(naz):
            qT, qH = _element_cambered(Om * y + Vs * sinpsi[k], UP, th, sth, cth, s0, s1, s2, s3,
                                       a0, a1, a2, a3, a4, a5, a6, a7)
            aT += qT
            aD += qH * sinpsi[k]
            aQ += qH
            aR += qT * sinpsi[k]
    else:
        g0, g1, g2, g3, g4, g5, sincos = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], model == GILL_SINCOS
        for k in range(naz):
            qT, qH = _element_gill(Om * y + Vs * sinpsi[k], UP, th, sth, cth, s0, g0, g1, g2, g3, g4, g5, sincos)
            aT += qT
            aD += qH * sinpsi[k]
            aQ += qH
            aR += qT * sinpsi[k]
    return cfac * aT / naz, cfac * aD / naz, y * cfac * aQ / naz, y * cfac * aR / naz


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)
def _annulus(v, Om, Vs, Vc, y, th, sth, cth, s0, s1, s2, s3, cfac, mfac, ct, ch, sinpsi, naz, model, pk, emp):
    """(G, dT/dy, dD/dy, dQ/dy, dM_R/dy) of one annulus: :func:`_blade_sums` and the solver's
    residual G = dT/dy - F dT_BEMT/dy (_kernel._residual, with its loss factor F)."""
    t, d, q, r = _blade_sums(v, Om, Vs, Vc, y, th, sth, cth, s0, s1, s2, s3, cfac, sinpsi, naz, model, pk)
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
        mom = mfac * v * np.sqrt(Vs * Vs + w_ax * w_ax)
    else:
        mom = _momentum_thrust(v, mfac, Vs, Vc)
    return t - floss * mom, t, d, q, r


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def _add_fixed_root(out, p, i, wj, wvj, Lv, Gv, dt, dd, dq, dr, span, axial):
    """Add one annulus' share of d(loads)/dp to ``out[:, p, i]`` for a quantity p that moves the
    blade's sums only (a section parameter, the density's Reynolds part): the differences
    (dt, dd, dq, dr) of its loads over ``span``, G's change being dt's (the loss factor and the
    momentum side do not depend on p); ``wj`` the annulus' weight, ``wvj`` its mean-inflow
    weight; D and M_R stay 0 in axial flow."""
    k2 = 1.0 / span
    dv = -(dt * k2) / Gv
    out[0, p, i] += wj * (dt * k2 + Lv[0] * dv)
    out[2, p, i] += wj * (dq * k2 + Lv[2] * dv)
    if not axial:
        out[1, p, i] += wj * (dd * k2 + Lv[1] * dv)
        out[3, p, i] += wj * (dr * k2 + Lv[3] * dv)
    out[4, p, i] += wvj * dv


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def _point(i, Om, V, b, coll, v, ok, y, w, th0, sc, cy2, cfac, mfac, ct, ch, sinpsi, model, pk, cam, emp, n_in,
           pkpm, campm, cam_same, hpar, scpm, hrho, out):
    naz_half = sinpsi.shape[0] // 2  # the half circle [-pi/2, pi/2]
    nr = y.shape[0]
    n_par = hpar.shape[0]
    n_all = n_in + n_par + (1 if hrho > 0.0 else 0)
    if not ok[i]:
        for q in range(5):
            for p in range(n_all):
                out[q, p, i] = np.nan
        return
    for q in range(5):
        for p in range(n_all):
            out[q, p, i] = 0.0
    wy = 0.0  # the mean inflow's weights (as _solve_batch: annulus area)
    for j in range(nr):
        wy += w[j] * y[j]
    om, dth = Om[i], coll[i]
    sb = np.sin(b[i])
    cb = np.cos(b[i])
    vs = V[i] * sb
    vc = V[i] * cb
    if abs(vs) < 1e-12 * V[i]:
        vs = 0.0
    # each input's direction in (Omega, V sin beta, V cos beta, collective) and its step
    e = np.zeros((4, 4))
    e[0, 0] = 1.0
    e[1, 1] = sb
    e[1, 2] = cb
    e[2, 1] = V[i] * cb
    e[2, 2] = -V[i] * sb
    e[3, 3] = 1.0
    if vs == 0.0:  # axial: exactly no in-plane speed along the airspeed's ray
        e[1, 1] = 0.0
    hx = np.empty(4)
    hx[0] = STEP * om
    hx[1] = STEP * (om * y[nr - 1] + V[i])  # the tip's speed scale [m/s]
    hx[2] = STEP
    hx[3] = STEP
    # at V = 0 the airspeed only grows: a one-sided (second-order) difference along the ray
    one_sided = V[i] == 0.0
    dL = np.empty(4)
    Lv = np.empty(4)
    L0 = np.empty(5)
    for j in range(nr):
        vj = v[i, j]
        th = th0[j] + dth
        sth = np.sin(th)
        cth = np.cos(th)
        s0, s1, s2, s3 = _constants(om, vs, vc, y[j], sc[j], cy2[j], model, cam)
        # in axial flow the integrand does not depend on psi: one node, except where V sin beta is perturbed
        naz = 1 if vs == 0.0 else naz_half
        hv = STEP * (abs(vj) + abs(vc) + 0.01 * om * y[j] + 1e-9)
        gp, t1, d1, q1, r1 = _annulus(vj + hv, om, vs, vc, y[j], th, sth, cth, s0, s1, s2, s3, cfac[j], mfac[j],
                                      ct[j], ch[j], sinpsi, naz, model, pk, emp)
        gm, t2, d2, q2, r2 = _annulus(vj - hv, om, vs, vc, y[j], th, sth, cth, s0, s1, s2, s3, cfac[j], mfac[j],
                                      ct[j], ch[j], sinpsi, naz, model, pk, emp)
        Gv = (gp - gm) / (2.0 * hv)
        Lv[0] = (t1 - t2) / (2.0 * hv)
        Lv[1] = (d1 - d2) / (2.0 * hv)
        Lv[2] = (q1 - q2) / (2.0 * hv)
        Lv[3] = (r1 - r2) / (2.0 * hv)
        if vs == 0.0:  # exactly 0 by symmetry in axial flow (as annulus_loads)
            Lv[1] = 0.0
            Lv[3] = 0.0
        if one_sided:
            L0[0], L0[1], L0[2], L0[3], L0[4] = _annulus(vj, om, vs, vc, y[j], th, sth, cth, s0, s1, s2, s3, cfac[j],
                                                         mfac[j], ct[j], ch[j], sinpsi, naz, model, pk, emp)
            L0[2] = 0.0  # D and M_R vanish at V = 0
            L0[4] = 0.0
        for p in range(n_in):
            if p == 2 and V[i] == 0.0:
                continue  # the incidence does nothing at V = 0
            h = hx[p]
            k2 = 1.0 / (2.0 * h)
            if p == 1 and one_sided:
                s0a, s1a, s2a, s3a = _constants(om, h * sb, h * cb, y[j], sc[j], cy2[j], model, cam)
                s0b, s1b, s2b, s3b = _constants(om, 2 * h * sb, 2 * h * cb, y[j], sc[j], cy2[j], model, cam)
                nz = naz_half if sb != 0.0 else 1
                g1, t1, d1, q1, r1 = _annulus(vj, om, h * sb, h * cb, y[j], th, sth, cth, s0a, s1a, s2a, s3a, cfac[j],
                                              mfac[j], ct[j], ch[j], sinpsi, nz, model, pk, emp)
                g2, t2, d2, q2, r2 = _annulus(vj, om, 2 * h * sb, 2 * h * cb, y[j], th, sth, cth, s0b, s1b, s2b, s3b,
                                              cfac[j], mfac[j], ct[j], ch[j], sinpsi, nz, model, pk, emp)
                dv = -((4.0 * g1 - g2 - 3.0 * L0[0]) * k2) / Gv
                dL[0] = (4.0 * t1 - t2 - 3.0 * L0[1]) * k2
                dL[1] = (4.0 * d1 - d2 - 3.0 * L0[2]) * k2
                dL[2] = (4.0 * q1 - q2 - 3.0 * L0[3]) * k2
                dL[3] = (4.0 * r1 - r2 - 3.0 * L0[4]) * k2
                if nz == 1:  # along the axis: D and M_R stay 0
                    dL[1] = 0.0
                    dL[3] = 0.0
            else:
                a_om, a_vs, a_vc = om + h * e[p, 0], vs + h * e[p, 1], vc + h * e[p, 2]
                b_om, b_vs, b_vc = om - h * e[p, 0], vs - h * e[p, 1], vc - h * e[p, 2]
                if p == 3:
                    tha, thb = th + h, th - h
                    stha, ctha, sthb, cthb = np.sin(tha), np.cos(tha), np.sin(thb), np.cos(thb)
                    s0a, s1a, s2a, s3a = s0, s1, s2, s3
                    s0b, s1b, s2b, s3b = s0, s1, s2, s3
                else:
                    tha, thb, stha, ctha, sthb, cthb = th, th, sth, cth, sth, cth
                    s0a, s1a, s2a, s3a = _constants(a_om, a_vs, a_vc, y[j], sc[j], cy2[j], model, cam)
                    s0b, s1b, s2b, s3b = _constants(b_om, b_vs, b_vc, y[j], sc[j], cy2[j], model, cam)
                nz = naz_half if e[p, 1] != 0.0 else naz
                gp, t1, d1, q1, r1 = _annulus(vj, a_om, a_vs, a_vc, y[j], tha, stha, ctha, s0a, s1a, s2a, s3a, cfac[j],
                                              mfac[j], ct[j], ch[j], sinpsi, nz, model, pk, emp)
                gm, t2, d2, q2, r2 = _annulus(vj, b_om, b_vs, b_vc, y[j], thb, sthb, cthb, s0b, s1b, s2b, s3b, cfac[j],
                                              mfac[j], ct[j], ch[j], sinpsi, nz, model, pk, emp)
                dv = -((gp - gm) * k2) / Gv
                dL[0] = (t1 - t2) * k2
                dL[1] = (d1 - d2) * k2
                dL[2] = (q1 - q2) * k2
                dL[3] = (r1 - r2) * k2
                if nz == 1:  # in axial flow, V sin beta unchanged: D and M_R stay 0 (one node has no symmetry)
                    dL[1] = 0.0
                    dL[3] = 0.0
            for q in range(4):
                out[q, p, i] += w[j] * (dL[q] + Lv[q] * dv)
            out[4, p, i] += w[j] * y[j] * dv / wy
        for k in range(n_par):  # section parameters: the element's constants pk and the annulus' cam at +-
            # the loss factor and the momentum side do not depend on them: G changes by the blade's thrust
            if cam_same[k]:
                s0a, s1a, s2a, s3a, s0b, s1b, s2b, s3b = s0, s1, s2, s3, s0, s1, s2, s3
            else:
                s0a, s1a, s2a, s3a = _constants(om, vs, vc, y[j], sc[j], cy2[j], model, campm[0, k])
                s0b, s1b, s2b, s3b = _constants(om, vs, vc, y[j], sc[j], cy2[j], model, campm[1, k])
            t1, d1, q1, r1 = _blade_sums(vj, om, vs, vc, y[j], th, sth, cth, s0a, s1a, s2a, s3a, cfac[j], sinpsi, naz,
                                         model, pkpm[0, k])
            t2, d2, q2, r2 = _blade_sums(vj, om, vs, vc, y[j], th, sth, cth, s0b, s1b, s2b, s3b, cfac[j], sinpsi, naz,
                                         model, pkpm[1, k])
            _add_fixed_root(out, n_in + k, i, w[j], w[j] * y[j] / wy, Lv, Gv, t1 - t2, d1 - d2, q1 - q2, r1 - r2,
                            hpar[k], naz == 1)
        if hrho > 0.0:  # the air density through the Reynolds number: sc at rho +- (cfac, mfac scale out)
            s0a, s1a, s2a, s3a = _constants(om, vs, vc, y[j], scpm[0, j], cy2[j], model, cam)
            s0b, s1b, s2b, s3b = _constants(om, vs, vc, y[j], scpm[1, j], cy2[j], model, cam)
            t1, d1, q1, r1 = _blade_sums(vj, om, vs, vc, y[j], th, sth, cth, s0a, s1a, s2a, s3a, cfac[j], sinpsi, naz,
                                         model, pk)
            t2, d2, q2, r2 = _blade_sums(vj, om, vs, vc, y[j], th, sth, cth, s0b, s1b, s2b, s3b, cfac[j], sinpsi, naz,
                                         model, pk)
            _add_fixed_root(out, n_in + n_par, i, w[j], w[j] * y[j] / wy, Lv, Gv, t1 - t2, d1 - d2, q1 - q2, r1 - r2,
                            hrho, naz == 1)


@numba.njit(parallel=True, cache=CACHE, error_model="numpy", fastmath=_FM)
def sensitivities(Om, V, b, coll, v, ok, y, w, th, sc, cy2, cfac, mfac, ct, ch, sinpsi, model, pk, cam, emp, n_in,
                  pkpm, campm, cam_same, hpar, scpm, hrho, out):
    """d(T, D, Q, M_R, v_i,mean)/d(Omega, V, beta[, collective]) at every point.

    Inputs as _kernel._solve_batch but the airspeed V and the incidence beta in place of
    (V sin beta, V cos beta), ``th`` the blade angles without the per-point collective
    ``coll``; ``v`` shape (n, nr): the converged roots; ``ok`` shape (n,): the points whose
    every annulus converged (the others get NaN); ``n_in`` 0 (parameters only), 3 or 4 (with
    the collective).
    Section parameters (packed, so that the argument list stays short enough for numba's
    inliner): ``pkpm`` shape (2, n_par, N_PK) and ``campm`` shape (2, n_par, 8), the element
    and annulus constants at each parameter's upper [0] and lower [1] value,
    ``cam_same`` shape (n_par,) bool: the parameter leaves ``cam`` unchanged (its annulus
    constants are not recomputed), ``hpar`` shape (n_par,) the distance between the two
    values (n_par may be 0). The air density (``hrho`` > 0, the distance between its two
    values; 0: not asked): ``scpm`` shape (2, nr), the section constant sc at them; the
    output's last row is then the Reynolds part of dL/drho (the caller adds L / rho, the
    part of cfac and mfac, which scale the residual and leave the root unchanged). ``out`` shape
    (5, n_in + n_par, n). Each derivative is a directional one in (Omega, V sin
    beta, V cos beta, collective); at V = 0 the airspeed's is one-sided (V >= 0) and the
    incidence's is 0.
    """
    for i in numba.prange(Om.shape[0]):
        _point(i, Om, V, b, coll, v, ok, y, w, th, sc, cy2, cfac, mfac, ct, ch, sinpsi, model, pk, cam, emp, n_in,
               pkpm, campm, cam_same, hpar, scpm, hrho, out)
