"""Compiled (numba) implicit derivatives of the loads with a linear inflow model (Drees,
Pitt-Peters; _momentum.inflow_gradients).

With a linear inflow each operating point is solved twice (core/_kernel.py): the uniform
inflow first, whose area-weighted mean inflow v_u sets the wake skew and so the gradients
(k_x, k_y) = k(mu, lambda), mu = V sin(beta) / (Omega R), lambda = (V cos(beta) + v_u) /
(Omega R) in climb and edgewise, v_u / (Omega R) in descent (_momentum.skew_inflow_ratio; its
slope in V cos beta the two sides' mean at V cos beta = 0); then, on the full circle, every
annulus' mean inflow v solves

    G(v, x, g) = dT_BET(v (1 + g_x cos psi + g_y sin psi)) - F dT_BEMT(v) = 0,
    g_x = k_x y / R, g_y = k_y y / R

(eq 11 with the linear inflow at every azimuth node; with RotorOptions.inplane_induction the
blades' in-plane airspeed is V sin(beta) + u_x(v, V sin beta, V cos beta), the skewed wake's
in-plane induction at the annulus' mean inflow v, as in the kernel). Its loads L(v, x, g) (T, D, Q, M_R, the
side force Y and the pitching moment M_P, _annulus_loads.annulus_loads) change with an input or a
section parameter x as (the implicit function theorem on each annulus' converged root, as
core/_sensitivity.py does for the uniform inflow; A. Ning, "Using blade element momentum
methods with gradient-based design optimization", Structural and Multidisciplinary
Optimization 64, 2021)

    dL/dx = L_x + L_g dg/dx + L_v dv/dx,    dv/dx = -(G_x + G_g dg/dx) / G_v,
    dg/dx = (y / R) (k_mu dmu/dx + k_lambda dlambda/dx),

with dlambda/dx carrying z = dv_u/dx, the uniform solve's mean-inflow derivative: the mean's
weighted sum (w y / sum w y) of each uniform annulus' dv_u,j/dx, from the implicit function
theorem on its own residual G^u at its root (kept by the kernel), with the half circle's
partials (two nodes of opposite sin psi in axial flow, where its thrust does not depend on
psi). With swirl (RotorOptions.swirl) each annulus' swirl u enters both solves (the kernel
solves the uniform and then the linear inflow at the same u) and balances the linear solve's
angular momentum, S(v, u, x, g) = u - v dQ / (y dT) = 0 (core/_swirl_sensitivity._swirl_system): per
annulus dv_u,j = a_j + b_j du_j (a_j = -G^u_x / G^u_v, b_j = -G^u_u / G^u_v), and (dv, du)
solve the 2 x 2 system of G and S, whose right-hand side is affine in z through dg. So every
annulus' share is summed at z = 0 and per unit z in one pass, and z = Z_0 + Z_1 z closes it
(Z_1 the swirl's part: 0 without swirl, where du = 0). The partial derivatives at the fixed
root (no root solve in them) in v, Omega, V sin beta, V cos beta, the blade angle, g_x, g_y and
u are analytic (u's those in U_T with the sign changed; the section constants stay the annulus'
at Omega y, as in the kernel): one evaluation per node of the element with its partials in U_T,
U_P, the section constants' slope in U2 and the blade angle (core/_tangents.py, as the uniform
inflow's), weighted by each variable's chain (:func:`_input_partials`). Those in the section
parameters and the density's Reynolds constant start from the constants stepped by the caller
(one-sided, as for the uniform inflow): for the cambered section the element's derivative along
that change, one evaluation per node (:func:`_direction_partials`), for the paper's the
annulus' loads at the stepped constants less the base (_annulus_loads.annulus_loads: the blade's
sums). The momentum side's are _momentum_sensitivity's (analytic but at the empirical descent
model's switch; its loss factor's partial in u is that in Omega divided by -y). The gradients'
own partials k_mu, k_lambda are central differences of _momentum.inflow_gradients (step 1e-6),
one-sided (second order) at mu = 0, where they are defined for mu >= 0 only: an axial point (V
sin beta = 0, solved with the uniform inflow only, where g = 0) gets the right-hand slope in V
sin beta, the one that the in-plane loads, odd in V sin beta, share on both sides.
"""

from __future__ import annotations

import numba
import numpy as np

from ._annulus import _FM, CAMBERED, GILL_SINCOS, _inflow_gradients, _skew_inflow_ratio
from ._annulus_loads import annulus_loads
from ._jitcache import CACHE
from ._momentum_sensitivity import _momentum_derivatives, _rest_slope
from ._physics import PK_INPLANE, PK_RADIAL_DRAG
from ._parameter_sensitivity import N_STATE, _cambered_direction, _cambered_state, _direction, _stored_state
from ._sensitivity import (
    _airspeed_components,
    _cambered_tangent,
    _constants_slopes,
    _gill_tangent,
    _inplane_partials,
    _input_directions,
    _node_rows,
    _start_point,
)
from ._sensitivity import _constants as _constants_inline
from ._swirl_sensitivity import _swirl_solve, _swirl_system

#: the loads of annulus_loads, in the rows of the output (row 4 is v_i,mean, as core/_sensitivity's)
LOAD_ROWS = (0, 1, 2, 3, 5, 6)
#: rows of the output: T, D, Q, M_R, v_i,mean, Y, M_P
N_ROWS = 7
#: step of the gradients' partials in mu and lambda
K_STEP = 1e-6
#: the partials' rows before the section parameters': v, Omega, V sin beta, V cos beta, the blade angle, g_x, g_y, u
N_FIXED = 8
#: the partials' row of the swirl u
ROW_U = 7


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _k_partials(mu, lam, inflow):
    """(k_x, k_y) and their partials in mu and lambda: (kx, ky, kx_mu, ky_mu, kx_lam, ky_lam)."""
    kx, ky = _inflow_gradients(mu, lam, inflow)
    h = K_STEP
    if mu > 2.0 * h:
        xp, yp = _inflow_gradients(mu + h, lam, inflow)
        xm, ym = _inflow_gradients(mu - h, lam, inflow)
        kx_mu, ky_mu = (xp - xm) / (2.0 * h), (yp - ym) / (2.0 * h)
    else:  # defined for mu >= 0 only: one-sided, second order
        x1, y1 = _inflow_gradients(mu + h, lam, inflow)
        x2, y2 = _inflow_gradients(mu + 2.0 * h, lam, inflow)
        kx_mu, ky_mu = (4.0 * x1 - x2 - 3.0 * kx) / (2.0 * h), (4.0 * y1 - y2 - 3.0 * ky) / (2.0 * h)
    xp, yp = _inflow_gradients(mu, lam + h, inflow)
    xm, ym = _inflow_gradients(mu, lam - h, inflow)
    return kx, ky, kx_mu, ky_mu, (xp - xm) / (2.0 * h), (yp - ym) / (2.0 * h)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined: compiled once, not 20 times
def _loads(v, y, Om, us, Vs, Vc, th, sec, cfac, azim, gx, gy, naz, model, pk):
    """The annulus' six load densities over the nodes of ``azim`` (_annulus_loads.annulus_loads, with
    the swirl ``us``)."""
    return annulus_loads(v, y, Om, us, Vs, Vc, (th, np.sin(th), np.cos(th)), sec, cfac, azim, gx, gy, naz, model, pk,
                         False)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _constants(Om, Vs, Vc, y, sc, cy2, model, cam):
    """The section constants at an operating point (core/_sensitivity._constants)."""
    return _constants_inline(Om, Vs, Vc, y, sc, cy2, model, cam)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _integrands(q, sk, ck, kr):
    """The six loads' integrands at one node (annulus_loads' sums) from the element's (qT, qH,
    C_D,p U) ``q`` or a derivative of it: qT, qH sin psi + kr C_D,p U cos^2 psi, qH, qT sin psi,
    -qH cos psi + kr C_D,p U cos psi sin psi, -qT cos psi (kr: the radial drag's factor times the
    blades' in-plane airspeed V_b)."""
    return (q[0], q[1] * sk + kr * q[2] * ck * ck, q[1], q[0] * sk, -q[1] * ck + kr * q[2] * ck * sk, -q[0] * ck)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _input_partials(P, v, op, y, th, sec, cfac, azim, g, model, pk):
    """Rows 0-7 of ``P``: the annulus' six load densities' partials at its fixed root in v,
    Omega, V sin beta, V cos beta, the blade angle, g_x, g_y and the swirl u, from one evaluation
    per node of the element with its analytic partials in U_T, U_P, the section constants' slope
    in U2 and the blade angle (core/_tangents.py, as core/_sensitivity._partials for the uniform
    inflow), over the nodes of ``azim`` (the full circle; its first half, [-pi/2, pi/2], for the
    uniform inflow's g = 0): at node psi, U_T = Omega y - u + V_b sin psi, U_P = V cos beta +
    v (1 + g_x cos psi + g_y sin psi), U2 = (Omega y)^2 + V sin^2 beta / 2 + V cos^2 beta (the
    constants', with the free stream's V sin beta), and the radial drag's factor V_b, where V_b =
    V sin beta + u_x(v, V sin beta, V cos beta) is the blades' in-plane airspeed (u_x the skewed
    wake's in-plane induction at the annulus' mean inflow v, 0 without the option; its partials
    enter the rows of v, V sin beta and V cos beta by the chain rule). ``op`` = (Omega, V sin beta,
    V cos beta, u), ``sec`` = (the section constants, their slopes in U2, at Omega y: the swirl
    does not enter them, as in the kernel), ``g`` = (g_x, g_y). Returns the annulus' thrust and
    torque densities at the root (T0, Q0), which the swirl's balance needs."""
    Om, Vs, Vc, us = op
    gx, gy = g
    s, u = sec
    sinpsi = azim[0]
    cospsi = azim[1]
    naz = sinpsi.shape[0]
    krad = pk[PK_RADIAL_DRAG]
    # the blades' in-plane airspeed vb = V sin beta + u_x(v, V sin beta, V cos beta) at the annulus' mean inflow v
    # (_momentum.inplane_induction, 0 without the option) and u_x's partials; the constants keep V sin beta
    vb, uxs, uxc, uxv = _inplane_partials(pk[PK_INPLANE], v, Vs, Vc)
    kr = krad * vb
    # the sums of the integrands of the element's partials: 0-2 U_P's (weights 1, cos, sin), 3-4 U_T's (1, sin),
    # 5 the constants' slope's, 6 the blade angle's; 7 the radial drag's base (C_D,p U cos^2, cos sin)
    S = np.zeros((8, 6))
    t0 = 0.0  # the element at the root: the thrust's and torque's sums
    q0 = 0.0
    zero = (0.0, 0.0, 0.0)
    wt = Om * y - us  # the blade speed
    for k in range(naz):
        sk = sinpsi[k]
        ck = cospsi[k]
        UT = wt + vb * sk
        UP = Vc + v * (1.0 + gx * ck + gy * sk)
        if model == CAMBERED:
            base, d_t, d_p, d_u, d_c = _cambered_tangent(UT, UP, th, np.sin(th), np.cos(th), (s[0], s[1], s[2], s[3]),
                                                         (u[0], u[1], u[2], u[3]),
                                                         (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7]))
        else:
            base, d_t, d_p, d_c = _gill_tangent(UT, UP, th, np.sin(th), np.cos(th), s[0],
                                                (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5]), model == GILL_SINCOS)
            d_u = zero
        lp = _integrands(d_p, sk, ck, kr)
        lt = _integrands(d_t, sk, ck, kr)
        lu = _integrands(d_u, sk, ck, kr)
        lc = _integrands(d_c, sk, ck, kr)
        for q in range(6):
            S[0, q] += lp[q]
            S[1, q] += lp[q] * ck
            S[2, q] += lp[q] * sk
            S[3, q] += lt[q]
            S[4, q] += lt[q] * sk
            S[5, q] += lu[q]
            S[6, q] += lc[q]
        S[7, 1] += base[2] * ck * ck
        S[7, 4] += base[2] * ck * sk
        t0 += base[0]
        q0 += base[1]
    cf = cfac / naz
    for q in range(6):
        f = cf * y if q == 2 or q == 3 or q == 5 else cf  # Q, M_R and M_P carry the radius
        sb = S[4, q] + krad * S[7, q]  # in the blades' in-plane airspeed vb: U_T by sin psi, the radial drag's factor
        P[0, q] = f * (S[0, q] + gx * S[1, q] + gy * S[2, q] + uxv * sb)  # dU_P/dv = 1 + g_x cos + g_y sin
        P[1, q] = f * (y * S[3, q] + 2.0 * Om * y * y * S[5, q])
        P[2, q] = f * ((1.0 + uxs) * sb + Vs * S[5, q])
        P[3, q] = f * (S[0, q] + 2.0 * Vc * S[5, q] + uxc * sb)
        P[4, q] = f * S[6, q]
        P[5, q] = f * v * S[1, q]
        P[6, q] = f * v * S[2, q]
        P[7, q] = -f * S[3, q]  # dU_T/du = -1
    return cf * t0, cf * y * q0


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _direction_partials(P, dS, dC, spans, stw, v, op, y, th, sec, cfac, azim, g, pk):
    """Rows 8, 9, ... of ``P``: the cambered element's derivatives along each section parameter's
    and the density's direction (row m of ``dS``, shape (n_m, 4), and ``dC``, shape (n_m, 8):
    the stepped value's section constants and polar constants less the base's), divided by the
    step ``spans[m]``, from one evaluation per node (core/_tangents.make_cambered_direction, as
    core/_sensitivity._parameter_partials for the uniform inflow), summed into the six loads over
    the nodes of ``azim``. ``stw`` shape (N_STATE, >= the node count): scratch for the nodes' states."""
    Om, Vs, Vc, us = op
    gx, gy = g
    sinpsi = azim[0]
    cospsi = azim[1]
    naz = sinpsi.shape[0]
    vb = _inplane_partials(pk[PK_INPLANE], v, Vs, Vc)[0]  # the blades' in-plane airspeed (:func:`_input_partials`)
    kr = pk[PK_RADIAL_DRAG] * vb
    con = (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7])
    sth = np.sin(th)
    cth = np.cos(th)
    for k in range(naz):
        st = _cambered_state(Om * y - us + vb * sinpsi[k], Vc + v * (1.0 + gx * cospsi[k] + gy * sinpsi[k]), th, sth,
                             cth, sec, con)
        for c in range(N_STATE):  # unrolled: the state is a tuple of floats
            stw[c, k] = st[c]
    cf = cfac / naz
    for m in range(dS.shape[0]):
        dsec, dcon = _direction(dS, dC, m)
        a0 = a1 = a2 = a3 = a4 = a5 = 0.0
        for k in range(naz):
            st = _stored_state(stw, k)
            l0, l1, l2, l3, l4, l5 = _integrands(_cambered_direction(st, dsec, dcon), sinpsi[k], cospsi[k], kr)
            a0 += l0
            a1 += l1
            a2 += l2
            a3 += l3
            a4 += l4
            a5 += l5
        f = cf / spans[m]
        P[N_FIXED + m, 0] = f * a0
        P[N_FIXED + m, 1] = f * a1
        P[N_FIXED + m, 2] = f * y * a2
        P[N_FIXED + m, 3] = f * y * a3
        P[N_FIXED + m, 4] = f * a4
        P[N_FIXED + m, 5] = f * y * a5


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _annulus_partials(P, v, op, th, ann, azim, g, model, pk, cam, par, dens, stw):
    """The annulus' load partials at its fixed root, into ``P`` (rows: v, Omega, V sin beta,
    V cos beta, the blade angle, g_x, g_y, the swirl u (:func:`_input_partials`), then each section
    parameter and the density's Reynolds part: for the cambered section along each one's
    direction (:func:`_direction_partials`), for the paper's one-sided differences of the
    blade's sums at the stepped constants; columns the six loads of annulus_loads) over the
    nodes of ``azim``. ``op`` = (Omega, V sin beta, V cos beta, u), ``ann`` = (y, sc, cy2, cfac,
    sc at the stepped density), ``g`` = (g_x, g_y), ``dens`` = (the stepped sc of every annulus,
    the density's step; 0: not asked), ``stw`` the cambered directions' scratch (N_STATE, the
    node count). Returns the thrust and torque densities at the root (:func:`_input_partials`)."""
    Om, Vs, Vc, us = op
    y, sc, cy2, cfac, scj = ann
    gx, gy = g
    naz = azim.shape[1]
    s, u = _constants_slopes((Om * y) ** 2 + 0.5 * Vs * Vs + Vc * Vc, sc, cy2, model, cam)
    base0 = _input_partials(P, v, op, y, th, (s, u), cfac, azim, g, model, pk)
    n_m = P.shape[0] - N_FIXED  # the section parameters' and the density's
    if n_m == 0:
        return base0
    pkpm, campm, cam_same, hpar = par
    n_par = hpar.shape[0]
    hrho = dens[1]
    if model == CAMBERED:
        dS = np.zeros((n_m, 4))
        dC = np.zeros((n_m, 8))
        spans = np.empty(n_m)
        for m in range(n_m):
            if m == n_par:  # the density, through the Reynolds constant sc
                sa = _constants(Om, Vs, Vc, y, scj, cy2, model, cam)
                spans[m] = hrho
            else:
                sa = s if cam_same[m] else _constants(Om, Vs, Vc, y, sc, cy2, model, campm[m])
                for c in range(8):
                    dC[m, c] = pkpm[m][c] - pk[c]
                spans[m] = hpar[m]
            for c in range(4):
                dS[m, c] = sa[c] - s[c]
        _direction_partials(P, dS, dC, spans, stw, v, op, y, th, s, cfac, azim, g, pk)
        return base0
    base = _loads(v, y, Om, us, Vs, Vc, th, s, cfac, azim, gx, gy, naz, model, pk)
    for m in range(n_m):  # one-sided: the constants at the stepped value
        if m == n_par:  # the density, through the Reynolds constant sc
            a = _loads(v, y, Om, us, Vs, Vc, th, _constants(Om, Vs, Vc, y, scj, cy2, model, cam), cfac, azim, gx, gy,
                       naz, model, pk)
            span = hrho
        else:
            sa = s if cam_same[m] else _constants(Om, Vs, Vc, y, sc, cy2, model, campm[m])
            a = _loads(v, y, Om, us, Vs, Vc, th, sa, cfac, azim, gx, gy, naz, model, pkpm[m])
            span = hpar[m]
        for q in range(6):
            P[N_FIXED + m, q] = (a[q] - base[q]) / span
    return base0


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM, forceinline=True)
def _point(i, Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens, out):
    vu_roots, azh, az2, radius = uni
    scpm, hrho = dens
    y, w, th0, sc, cy2, cfac, mfac, ct, ch = _node_rows(nodes)
    nr = y.shape[0]
    n_par = par[3].shape[0]
    n_all = n_in + n_par + (1 if hrho != 0.0 else 0)
    n_cols = out.shape[1]  # n_all, or 3 more: the slopes at rest along three rays (core/_sensitivity.py)
    wy = _start_point(out, i, ok, N_ROWS, w, y)
    if not ok[i]:
        return
    swirl = roots.shape[0] == 2
    om, dth = Om[i], coll[i]
    sb, cb, vs, vc = _airspeed_components(V[i], b[i])
    one_sided = V[i] == 0.0
    # each column's direction in (Omega, V sin beta, V cos beta, the blade angle): the inputs, then the
    # parameters and the density (0: they move the constants only), then the rays at rest
    e = np.zeros((n_cols, 4))
    if n_in > 0:
        _input_directions(e, n_in, V[i], sb, cb, vs)
    for k in range(n_cols - n_all):  # the rays beta = 0, pi/2, pi
        e[n_all + k, 1] = 1.0 if k == 1 else 0.0
        e[n_all + k, 2] = 1.0 - k if k != 1 else 0.0
    # the gradients from mu and lambda at the uniform solve's mean inflow v_u, and their change along every
    # column at a fixed v_u (dk) and per unit change of v_u (kz)
    vu = 0.0
    for j in range(nr):
        vu += w[j] * y[j] * vu_roots[i, j]
    vu /= wy
    OmR = om * radius
    mu = vs / OmR
    lam = _skew_inflow_ratio(vc, vu, OmR)
    # lambda's slope in V cos beta: 1 / (Omega R) in climb, 0 in descent (v_u alone), the two sides' mean at
    # V cos beta = 0 (as the in-plane induction's: _sensitivity._inplane_partials)
    lam_c = (1.0 if vc > 0.0 else (0.5 if vc == 0.0 else 0.0)) / OmR
    kx, ky, kx_mu, ky_mu, kx_lam, ky_lam = _k_partials(mu, lam, inflow)
    dk = np.empty((n_cols, 2))
    for c in range(n_cols):
        dmu = e[c, 1] / OmR - mu * e[c, 0] / om
        dlam = e[c, 2] * lam_c - lam * e[c, 0] / om
        dk[c, 0] = kx_mu * dmu + kx_lam * dlam
        dk[c, 1] = ky_mu * dmu + ky_lam * dlam
    kzx = kx_lam / OmR
    kzy = ky_lam / OmR
    P = np.empty((N_FIXED + n_all - n_in, 6))  # the linear solve's annulus
    Pu = np.empty((N_FIXED + n_all - n_in, 6))  # the uniform solve's (only its thrust column is used)
    stw = np.empty((N_STATE, azim.shape[1] if model == CAMBERED and n_all > n_in else 0))
    # every column is affine in z, the change of v_u along it: the loads' and v_i,mean's sums at z = 0 (acc[0]) and
    # per unit z (acc[1]); z itself solves z = zs[0] + zs[1] z, the uniform annuli's roots' change weighted as v_u
    acc = np.zeros((2, N_ROWS, n_cols))
    zs = np.zeros((2, n_cols))
    dA = np.empty(6)
    dB = np.empty(6)
    scj = 0.0
    for j in range(nr):
        vj = roots[0, i, j]
        vuj = vu_roots[i, j]
        uj = roots[1, i, j] if swirl else 0.0  # the annulus' swirl, the same in both solves (core/_kernel.py)
        yj = y[j]
        ome = om - uj / yj  # the blade speed's Omega, which the loss factor sees
        th = th0[j] + dth
        gx = kx * yj / radius
        gy = ky * yj / radius
        if hrho != 0.0:
            scj = scpm[j]
        ann = (yj, sc[j], cy2[j], cfac[j], scj)
        # the uniform solve's annulus (g = 0; the half circle, or in axial flow, where the thrust's integrand does
        # not depend on psi, two nodes of opposite sin psi): dv_u = au + bu du, au from the column's partials
        _annulus_partials(Pu, vuj, (om, vs, vc, uj), th, ann, az2 if vs == 0.0 else azh, (0.0, 0.0), model, pk, cam,
                          par, dens, stw)
        mvu, mu_om, mu_vs, mu_vc = _momentum_derivatives(vuj, ome, om, vs, vc, yj, mfac[j], ct[j], ch[j], emp,
                                                         one_sided)
        Gvu = Pu[0, 0] - mvu
        bu = -(Pu[ROW_U, 0] + mu_om / yj) / Gvu  # the momentum side's partial in u is -(its Omega partial) / y
        # the linear solve's annulus, and with swirl its angular momentum balance (_swirl_sensitivity._swirl_system)
        T0, Q0 = _annulus_partials(P, vj, (om, vs, vc, uj), th, ann, azim, (gx, gy), model, pk, cam, par, dens, stw)
        mv, m_om, m_vs, m_vc = _momentum_derivatives(vj, ome, om, vs, vc, yj, mfac[j], ct[j], ch[j], emp, one_sided)
        Gv = P[0, 0] - mv
        sw = _swirl_system(swirl, vj, yj, om, T0, Q0, P[0, 0], P[0, 2], -P[ROW_U, 0], -P[ROW_U, 1], -P[ROW_U, 2],
                           -P[ROW_U, 3], m_om / yj, Gv)
        wv = w[j] * yj / wy  # the mean inflow's weight
        dgxz = kzx * yj / radius  # the annulus' gradients per unit change of v_u
        dgyz = kzy * yj / radius
        for c in range(n_cols):
            if c == 2 and n_in > 2 and one_sided:
                continue  # the incidence does nothing at V = 0
            ray = c >= n_all
            if ray and not one_sided:
                continue  # the slopes at rest: 0 at the points with V > 0
            par_col = n_in <= c < n_all
            if (c == 1 and n_in > 1 and one_sided) or ray:  # the airspeed from rest along its ray: one-sided
                rs = e[c, 1] if ray else sb
                rc = e[c, 2] if ray else cb
                dmom = _rest_slope(m_vs, m_vc, vj, rs, rc, emp)
                dmomu = _rest_slope(mu_vs, mu_vc, vuj, rs, rc, emp)
            else:
                dmom = m_om * e[c, 0] + m_vs * e[c, 1] + m_vc * e[c, 2]
                dmomu = mu_om * e[c, 0] + mu_vs * e[c, 1] + mu_vc * e[c, 2]
            if par_col:
                au = -(Pu[N_FIXED + c - n_in, 0] - dmomu) / Gvu
            else:
                au = -(Pu[1, 0] * e[c, 0] + Pu[2, 0] * e[c, 1] + Pu[3, 0] * e[c, 2] + Pu[4, 0] * e[c, 3] - dmomu) / Gvu
            dgx = dk[c, 0] * yj / radius
            dgy = dk[c, 1] * yj / radius
            for q in range(6):
                d = P[5, q] * dgx + P[6, q] * dgy
                if par_col:
                    d += P[N_FIXED + c - n_in, q]
                else:
                    d += P[1, q] * e[c, 0] + P[2, q] * e[c, 1] + P[3, q] * e[c, 2] + P[4, q] * e[c, 3]
                dA[q] = d
                dB[q] = P[5, q] * dgxz + P[6, q] * dgyz
            dv0, du0 = _swirl_solve(sw, dA[0] - dmom, dA[0], dA[2], e[c, 0])
            dv1, du1 = _swirl_solve(sw, dB[0], dB[0], dB[2], 0.0)
            for q in range(6):
                acc[0, LOAD_ROWS[q], c] += w[j] * (dA[q] + P[0, q] * dv0 + P[ROW_U, q] * du0)
                acc[1, LOAD_ROWS[q], c] += w[j] * (dB[q] + P[0, q] * dv1 + P[ROW_U, q] * du1)
            acc[0, 4, c] += wv * dv0
            acc[1, 4, c] += wv * dv1
            zs[0, c] += wv * (au + bu * du0)
            zs[1, c] += wv * bu * du1
    for c in range(n_cols):
        z = zs[0, c] / (1.0 - zs[1, c])  # (zs[1] = 0 without swirl: the swirl's du is 0)
        for r in range(N_ROWS):
            out[r, c, i] += acc[0, r, c] + acc[1, r, c] * z


@numba.njit(parallel=True, cache=CACHE, error_model="numpy", fastmath=_FM)
def linear_sensitivities(Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens,
                         out):
    """d(T, D, Q, M_R, v_i,mean, Y, M_P)/d(Omega, V, beta[, collective], section parameters, rho) at
    every point, with the linear inflow model ``inflow`` (module docstring), with or without swirl.

    Inputs as core/_sensitivity.sensitivities, with ``roots`` shape (1, n, nr) the linear
    inflow's converged roots (the uniform ones at the axial points, where the kernel solves
    once), or (2, n, nr) with swirl: the roots and the swirl u of every annulus, ``azim`` the
    full circle's nodes, and ``uni`` = (v_u, azh, az2, R): the uniform solve's roots shape (n, nr)
    (with swirl, those of the kernel's last swirl iteration, solved at the same u), the half
    circle's nodes (the first half of ``azim``, [-pi/2, pi/2], contiguous: the uniform inflow's,
    as the kernel solves it), its first and last (shape (2, 2), of opposite sin psi: enough in
    axial flow) and the rotor radius [m]. ``out`` shape (7, n_cols, n): the rows T, D, Q, M_R, v_i,mean (as
    core/_sensitivity's), then Y and M_P; ``dens`` = (``scpm``, ``hrho``) of
    core/_sensitivity.sensitivities: the density's column is the Reynolds part (the caller adds
    L / rho).
    """
    for i in numba.prange(Om.shape[0]):
        _point(np.int64(i), Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens,
               out)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)
def linear_sensitivities_serial(Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par,
                                dens, out):
    """:func:`linear_sensitivities` on the calling thread, for small batches (as
    core/_sensitivity.sensitivities_serial)."""
    for i in range(Om.shape[0]):
        _point(i, Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens, out)
