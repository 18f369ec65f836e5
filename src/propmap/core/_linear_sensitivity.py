"""Compiled (numba) implicit derivatives of the loads with a linear inflow model (Drees,
Pitt-Peters; _physics.inflow_gradients).

With a linear inflow each operating point is solved twice (core/_kernel.py): the uniform
inflow first, whose area-weighted mean inflow v_u sets the wake skew and so the gradients
(k_x, k_y) = k(mu, lambda), mu = V sin(beta) / (Omega R), lambda = (V cos(beta) + v_u) /
(Omega R); then, on the full circle, every annulus' mean inflow v solves

    G(v, x, g) = dT_BET(v (1 + g_x cos psi + g_y sin psi)) - F dT_BEMT(v) = 0,
    g_x = k_x y / R, g_y = k_y y / R

(eq 11 with the linear inflow at every azimuth node; with RotorOptions.inplane_induction the
blades' in-plane airspeed is V sin(beta) + u_x(v, V sin beta, V cos beta), the skewed wake's
in-plane induction at the annulus' mean inflow v, as in the kernel). Its loads L(v, x, g) (T, D, Q, M_R, the
side force Y and the pitching moment M_P, _annulus.annulus_loads) change with an input or a
section parameter x as (the implicit function theorem on each annulus' converged root, as
core/_sensitivity.py does for the uniform inflow; A. Ning, "Using blade element momentum
methods with gradient-based design optimization", Structural and Multidisciplinary
Optimization 64, 2021)

    dL/dx = L_x + L_g dg/dx + L_v dv/dx,    dv/dx = -(G_x + G_g dg/dx) / G_v,
    dg/dx = (y / R) (k_mu dmu/dx + k_lambda dlambda/dx),

with dlambda/dx carrying dv_u/dx, the uniform solve's mean-inflow derivative (row
``v_i_mean`` of core/_sensitivity.sensitivities at the uniform roots). The partial derivatives
at the fixed root (no root solve in them) in v, Omega, V sin beta, V cos beta, the blade angle,
g_x and g_y are analytic: one evaluation per node of the element with its partials in U_T,
U_P, the section constants' slope in U2 and the blade angle (core/_tangents.py, as the uniform
inflow's), weighted by each variable's chain (:func:`_input_partials`). Those in the section
parameters and the density's Reynolds constant start from the constants stepped by the caller
(one-sided, as for the uniform inflow): for the cambered section the element's derivative
along that change, one evaluation per node (:func:`_direction_partials`), for the paper's the
annulus' loads at the stepped constants less the base (_annulus.annulus_loads: the blade's
sums). The momentum side's are _momentum_sensitivity's (analytic but at the empirical descent
model's switch). The gradients' own partials k_mu, k_lambda are central differences
of _physics.inflow_gradients (step 1e-6), one-sided (second order) at mu = 0, where they are
defined for mu >= 0 only: an axial point (V sin beta = 0, solved with the uniform inflow only,
where g = 0) gets the right-hand slope in V sin beta, the one that the in-plane loads, odd in
V sin beta, share on both sides.
"""

from __future__ import annotations

import numba
import numpy as np

from ._annulus import _FM, CAMBERED, GILL_SINCOS, _inflow_gradients, annulus_loads
from ._jitcache import CACHE
from ._momentum_sensitivity import STEP, _momentum_derivatives, _momentum_side, _ray_slope
from ._physics import PK_INPLANE, PK_RADIAL_DRAG
from ._sensitivity import (
    N_STATE,
    _airspeed_components,
    _cambered_direction,
    _cambered_state,
    _cambered_tangent,
    _constants_slopes,
    _direction,
    _gill_tangent,
    _inplane_partials,
    _input_directions,
    _node_rows,
    _start_point,
    _stored_state,
)
from ._sensitivity import _constants as _constants_inline

#: the loads of annulus_loads, in the rows of the output (row 4 is v_i,mean, as core/_sensitivity's)
LOAD_ROWS = (0, 1, 2, 3, 5, 6)
#: rows of the output: T, D, Q, M_R, v_i,mean, Y, M_P
N_ROWS = 7
#: step of the gradients' partials in mu and lambda
K_STEP = 1e-6


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
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
def _loads(v, y, Om, Vs, Vc, th, sec, cfac, azim, gx, gy, naz, model, pk):
    """The annulus' six load densities over the full circle (_annulus.annulus_loads, no swirl)."""
    return annulus_loads(v, y, Om, 0.0, Vs, Vc, (th, np.sin(th), np.cos(th)), sec, cfac, azim, gx, gy, naz, model, pk,
                         False)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _constants(Om, Vs, Vc, y, sc, cy2, model, cam):
    """The section constants at an operating point (core/_sensitivity._constants)."""
    return _constants_inline(Om, Vs, Vc, y, sc, cy2, model, cam)


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def _integrands(q, sk, ck, kr):
    """The six loads' integrands at one node (annulus_loads' sums) from the element's (qT, qH,
    C_D,p U) ``q`` or a derivative of it: qT, qH sin psi + kr C_D,p U cos^2 psi, qH, qT sin psi,
    -qH cos psi + kr C_D,p U cos psi sin psi, -qT cos psi (kr: the radial drag's factor times the
    blades' in-plane airspeed V_b)."""
    return (q[0], q[1] * sk + kr * q[2] * ck * ck, q[1], q[0] * sk, -q[1] * ck + kr * q[2] * ck * sk, -q[0] * ck)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _input_partials(P, v, op, y, th, sec, cfac, azim, g, model, pk):
    """Rows 0-6 of ``P``: the annulus' six load densities' partials at its fixed root in v,
    Omega, V sin beta, V cos beta, the blade angle, g_x and g_y, from one evaluation per node of
    the element with its analytic partials in U_T, U_P, the section constants' slope in U2 and
    the blade angle (core/_tangents.py, as core/_sensitivity._partials for the uniform inflow),
    over the full circle: at node psi, U_T = Omega y + V_b sin psi, U_P = V cos beta +
    v (1 + g_x cos psi + g_y sin psi), U2 = (Omega y)^2 + V sin^2 beta / 2 + V cos^2 beta (the
    constants', with the free stream's V sin beta), and the radial drag's factor V_b, where V_b =
    V sin beta + u_x(v, V sin beta, V cos beta) is the blades' in-plane airspeed (u_x the skewed
    wake's in-plane induction at the annulus' mean inflow v, 0 without the option; its partials
    enter the rows of v, V sin beta and V cos beta by the chain rule). ``op`` = (Omega, V sin beta,
    V cos beta), ``sec`` = (the section constants, their slopes in U2), ``g`` = (g_x, g_y)."""
    Om, Vs, Vc = op
    gx, gy = g
    s, u = sec
    sinpsi = azim[0]
    cospsi = azim[1]
    naz = sinpsi.shape[0]
    krad = pk[PK_RADIAL_DRAG]
    # the blades' in-plane airspeed vb = V sin beta + u_x(v, V sin beta, V cos beta) at the annulus' mean inflow v
    # (_physics.inplane_induction, 0 without the option) and u_x's partials; the constants keep V sin beta
    vb, uxs, uxc, uxv = _inplane_partials(pk[PK_INPLANE], v, Vs, Vc)
    kr = krad * vb
    # the sums of the integrands of the element's partials: 0-2 U_P's (weights 1, cos, sin), 3-4 U_T's (1, sin),
    # 5 the constants' slope's, 6 the blade angle's; 7 the radial drag's base (C_D,p U cos^2, cos sin)
    S = np.zeros((8, 6))
    zero = (0.0, 0.0, 0.0)
    for k in range(naz):
        sk = sinpsi[k]
        ck = cospsi[k]
        UT = Om * y + vb * sk
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


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _direction_partials(P, dS, dC, spans, stw, v, op, y, th, sec, cfac, azim, g, pk):
    """Rows 7, 8, ... of ``P``: the cambered element's derivatives along each section parameter's
    and the density's direction (row m of ``dS``, shape (n_m, 4), and ``dC``, shape (n_m, 8):
    the stepped value's section constants and polar constants less the base's), divided by the
    step ``spans[m]``, from one evaluation per node (core/_tangents.make_cambered_direction, as
    core/_sensitivity._parameter_partials for the uniform inflow), summed into the six loads over
    the full circle. ``stw`` shape (N_STATE, >= the node count): scratch for the nodes' states."""
    Om, Vs, Vc = op
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
        st = _cambered_state(Om * y + vb * sinpsi[k], Vc + v * (1.0 + gx * cospsi[k] + gy * sinpsi[k]), th, sth, cth,
                             sec, con)
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
        P[7 + m, 0] = f * a0
        P[7 + m, 1] = f * a1
        P[7 + m, 2] = f * y * a2
        P[7 + m, 3] = f * y * a3
        P[7 + m, 4] = f * a4
        P[7 + m, 5] = f * y * a5


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _annulus_partials(P, v, op, th, ann, azim, g, model, pk, cam, par, dens, stw):
    """The annulus' load partials at its fixed root, into ``P`` (rows: v, Omega, V sin beta,
    V cos beta, the blade angle, g_x, g_y (:func:`_input_partials`), then each section
    parameter and the density's Reynolds part: for the cambered section along each one's
    direction (:func:`_direction_partials`), for the paper's one-sided differences of the
    blade's sums at the stepped constants; columns the six loads of annulus_loads). ``op`` =
    (Omega, V sin beta, V cos beta), ``ann`` = (y, sc, cy2, cfac, sc at the stepped density),
    ``g`` = (g_x, g_y), ``dens`` = (the stepped sc of every annulus, the density's step; 0: not
    asked), ``stw`` the cambered directions' scratch (N_STATE, the node count)."""
    Om, Vs, Vc = op
    y, sc, cy2, cfac, scj = ann
    gx, gy = g
    naz = azim.shape[1]
    s, u = _constants_slopes((Om * y) ** 2 + 0.5 * Vs * Vs + Vc * Vc, sc, cy2, model, cam)
    _input_partials(P, v, op, y, th, (s, u), cfac, azim, g, model, pk)
    n_m = P.shape[0] - 7  # the section parameters' and the density's
    if n_m == 0:
        return
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
        return
    base = _loads(v, y, Om, Vs, Vc, th, s, cfac, azim, gx, gy, naz, model, pk)
    for m in range(n_m):  # one-sided: the constants at the stepped value
        if m == n_par:  # the density, through the Reynolds constant sc
            a = _loads(v, y, Om, Vs, Vc, th, _constants(Om, Vs, Vc, y, scj, cy2, model, cam), cfac, azim, gx, gy, naz,
                       model, pk)
            span = hrho
        else:
            sa = s if cam_same[m] else _constants(Om, Vs, Vc, y, sc, cy2, model, campm[m])
            a = _loads(v, y, Om, Vs, Vc, th, sa, cfac, azim, gx, gy, naz, model, pkpm[m])
            span = hpar[m]
        for q in range(6):
            P[7 + m, q] = (a[q] - base[q]) / span


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM, forceinline=True)
def _point(i, Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens, out):
    vu, dvu, radius = uni
    scpm, hrho = dens
    y, w, th0, sc, cy2, cfac, mfac, ct, ch = _node_rows(nodes)
    nr = y.shape[0]
    n_par = par[3].shape[0]
    n_all = n_in + n_par + (1 if hrho != 0.0 else 0)
    n_cols = out.shape[1]  # n_all, or 3 more: the slopes at rest along three rays (core/_sensitivity.py)
    wy = _start_point(out, i, ok, N_ROWS, w, y)
    if not ok[i]:
        return
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
    # the gradients and their change along every column, through mu, lambda and the uniform mean inflow
    OmR = om * radius
    mu = vs / OmR
    lam = (vc + vu[i]) / OmR
    kx, ky, kx_mu, ky_mu, kx_lam, ky_lam = _k_partials(mu, lam, inflow)
    dk = np.empty((n_cols, 2))
    for c in range(n_cols):
        dmu = e[c, 1] / OmR - mu * e[c, 0] / om
        dlam = (e[c, 2] + dvu[c, i]) / OmR - lam * e[c, 0] / om
        dk[c, 0] = kx_mu * dmu + kx_lam * dlam
        dk[c, 1] = ky_mu * dmu + ky_lam * dlam
    h_ray = STEP * (om * y[nr - 1] + V[i])  # at V = 0: the momentum side's step along the ray (as _sensitivity)
    P = np.empty((7 + n_all - n_in, 6))
    stw = np.empty((N_STATE, azim.shape[1] if model == CAMBERED and n_all > n_in else 0))
    dL = np.empty(6)
    scj = 0.0
    for j in range(nr):
        vj = roots[i, j]
        yj = y[j]
        gx = kx * yj / radius
        gy = ky * yj / radius
        if hrho != 0.0:
            scj = scpm[j]
        _annulus_partials(P, vj, (om, vs, vc), th0[j] + dth, (yj, sc[j], cy2[j], cfac[j], scj), azim, (gx, gy), model,
                          pk, cam, par, dens, stw)
        mv, m_om, m_vs, m_vc = _momentum_derivatives(vj, om, om, vs, vc, yj, mfac[j], ct[j], ch[j], emp, one_sided)
        Gv = P[0, 0] - mv
        m0 = _momentum_side(vj, om, 0.0, 0.0, yj, mfac[j], ct[j], ch[j], emp) if one_sided else 0.0
        for c in range(n_cols):
            if c == 2 and n_in > 2 and one_sided:
                continue  # the incidence does nothing at V = 0
            ray = c >= n_all
            if ray and not one_sided:
                continue  # the slopes at rest: 0 at the points with V > 0
            par_col = n_in <= c < n_all
            if (c == 1 and n_in > 1 and one_sided) or ray:  # the airspeed from rest along its ray: one-sided
                dmom = _ray_slope(m0, vj, om, e[c, 1] if ray else sb, e[c, 2] if ray else cb, h_ray, yj, mfac[j],
                                  ct[j], ch[j], emp)
            else:
                dmom = m_om * e[c, 0] + m_vs * e[c, 1] + m_vc * e[c, 2]
            dgx = dk[c, 0] * yj / radius
            dgy = dk[c, 1] * yj / radius
            for q in range(6):
                d = P[5, q] * dgx + P[6, q] * dgy
                if par_col:
                    d += P[7 + c - n_in, q]
                else:
                    d += P[1, q] * e[c, 0] + P[2, q] * e[c, 1] + P[3, q] * e[c, 2] + P[4, q] * e[c, 3]
                dL[q] = d
            dv = -(dL[0] - dmom) / Gv
            for q in range(6):
                out[LOAD_ROWS[q], c, i] += w[j] * (dL[q] + P[0, q] * dv)
            out[4, c, i] += w[j] * yj * dv / wy


@numba.njit(parallel=True, cache=CACHE, error_model="numpy", fastmath=_FM)
def linear_sensitivities(Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens,
                         out):
    """d(T, D, Q, M_R, v_i,mean, Y, M_P)/d(Omega, V, beta[, collective], section parameters, rho) at
    every point, with the linear inflow model ``inflow`` (module docstring).

    Inputs as core/_sensitivity.sensitivities, with ``roots`` shape (n, nr) the linear
    inflow's converged roots (the uniform ones at the axial points, where the kernel solves
    once), ``azim`` the full circle's nodes, and ``uni`` = (v_u, dv_u, R): the uniform solve's
    mean inflow shape (n,), its derivative along every output column shape (n_cols, n)
    (core/_sensitivity.sensitivities' row v_i,mean at the uniform roots, the same columns) and
    the rotor radius [m]. ``out`` shape (7, n_cols, n): the rows T, D, Q, M_R, v_i,mean (as
    core/_sensitivity's), then Y and M_P; ``dens`` = (``scpm``, ``hrho``) of
    core/_sensitivity.sensitivities: the density's column is the Reynolds part (the caller adds
    L / rho). No swirl.
    """
    for i in numba.prange(Om.shape[0]):
        _point(np.int64(i), Om, V, b, coll, roots, ok, uni, nodes, azim, model, pk, cam, inflow, emp, n_in, par, dens,
               out)
