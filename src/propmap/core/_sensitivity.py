"""Compiled (numba) implicit derivatives of the loads: the implicit function theorem on each
annulus' converged root.

On annulus j the inflow v solves G(v, x) = dT_BET - F dT_BEMT = 0 (eq 11) for the inputs
x = (Omega, V sin beta, V cos beta, collective). Its loads L(v, x) (eqs 5-7 and the rolling
moment, azimuth-averaged) then change with x as

    dL/dx = dL/dx|_v + dL/dv|_x dv/dx,    dv/dx = -(dG/dx|_v) / (dG/dv|_x)

(the implicit function theorem; the approach of A. Ning, "Using blade element momentum
methods with gradient-based design optimization", Structural and Multidisciplinary
Optimization 64, 2021, there with algorithmic differentiation of the residual). The
partial derivatives at the fixed root (no root solve in them) come from the structure of
the blade element: at every azimuth node it depends on the inputs only through
U_T = Omega y + V sin(beta) sin(psi), U_P = V cos(beta) + v, the blade angle and the
section constants, which depend on the annulus' mean square speed U2 = (Omega y)^2 +
(V sin beta)^2 / 2 + (V cos beta)^2 only. So one pass over the nodes, evaluating the
element with its analytic partial derivatives in U_T, U_P, the blade angle and along the
constants' change with U2 (core/_tangents.py; that change from the constants' own power
laws, :func:`_constants_slopes`), gives every input's partials by the chain rule (Omega:
U_T by y, U2 by 2 Omega y^2; V sin beta: U_T by sin psi, U2 by V sin beta; V cos beta: U_P
by 1, U2 by 2 V cos beta; v: U_P by 1; the collective: the blade angle by 1): one element
evaluation per node for all of them. Until 2026-11-25 these partials were one-sided
differences (the element at the base and at U_T + h, U_P + h, the constants at U2 + h and
the blade angle + h, four or five evaluations per node, steps 1e-7 of each variable's
scale), whose O(h) error reached 8e-6 (cambered) and 3e-5 (the paper's section) of a
derivative against tightly converged differences of the solver on 9 points in climb, 1.1e-7
since (7.9e-7 and 5.2e-7 at two points in descent; docs/solver.md, tests/test_derivatives.py).
No root is re-solved, so the root's own tolerance (1e-7 of the inflow scale) does not enter,
whereas differencing the whole solver carries it divided by its step. The momentum side
F dT_BEMT (a scalar per annulus: no azimuth sum) is differentiated analytically (Glauert's mass flow or
the empirical descent curve, through its inversion, and Prandtl's factor:
core/_momentum_sensitivity.py); where the
empirical model switches on at V > 0 (V cos beta = 0, v = -V cos beta / 2) it is differenced
centrally in v, Omega, V sin beta and V cos beta with steps 1e-5 of their scales, whatever
the airspeed, so that the two sides of the switch are averaged. At V = 0, where the empirical
model is Glauert's, all four are analytic, and the airspeed's slope along a ray (V sin beta,
V cos beta) = V (sin beta, cos beta) from rest, for the point's ray and, when the output has
three columns more, for the rays beta = 0, pi/2 and pi (the slopes at rest,
core/derivatives.py), is their chain rule (the momentum side is even in V sin beta, and
Glauert's |V cos beta + v| is smooth at v != 0), with the empirical descent curve's slope at
hover on a descending ray, where that curve switches on at once
(_momentum_sensitivity._rest_slope). Until 2026-11-28 those slopes were
one-sided second-order differences of the momentum side (two more of its evaluations per ray
and annulus, and one at the base: nine per annulus at rest with the three rays, where the
element itself is one evaluation), agreeing with the analytic ones to 1.1e-7 of each
derivative's largest value (apce_8x6, 21 rates at rest, rays 0-180 deg and the three rays; the
paper's, generic and calibrated sets, a linear inflow, swirl; docs/solver.md).

A section parameter enters through the element's constants (pk) and the annulus'
Reynolds constants (cam) only, the density through the Reynolds constant sc: its step
(computed by the caller: +h, or -h at the upper bound of its range) moves the polar's
constants pk[:8] and the annulus' section constants (those recomputed at the stepped cam or
sc) by known amounts. For the cambered section the element's derivative along that direction
is analytic (core/_tangents.make_cambered_direction: every parameter's from one evaluation
per node, :func:`_parameter_partials`; since 2026-11-25), so only the constants' own change
is a difference (first order in h = 1e-7 of the parameter's scale); for the paper's section
it is a one-sided difference of the blade's sums between the base and the stepped constants,
one pass each (:func:`_pass`).

The loss factor and the momentum side are the solver's own (_annulus), the element's terms
too (core/_tangents.py evaluates them with their partials; the order of a few products
differs, so its loads agree with the solver's to rounding, not to the bit): uniform inflow
only, every azimuth node of the half circle where V sin beta is nonzero (the nodes
are symmetric in sin psi, which makes T even and D, M_R odd in V sin beta); in axial flow
one node, the integrand being independent of psi there: its partials stand for every
node's, with the half circle's mean sin(psi) (0) and mean sin(psi)^2 as the weights, so
that D and M_R change with V sin beta there and with nothing else.

The radial flow's drag (airfoil.RotorOptions.radial_drag, pk[PK_RADIAL_DRAG] = 1) adds
V sin(beta) times the node sums of C_D,p U cos^2 psi to D (_annulus_loads.annulus_loads; C_D,p the
profile drag). It depends on the inputs through U_T, U_P, the blade angle and the section
constants, as the element does, so the element's partials carry C_D,p U's as a third value
(and the section parameters' passes the element's own, _physics.make_element's ``profile``);
V sin(beta) enters it once more explicitly (its base sum; in axial flow the one node's value
times the half circle's mean cos^2 psi, 1 - mean sin^2 psi).

With Gormont's dynamic stall (airfoil.RotorOptions.dynamic_stall, in-plane flow) each node
and its mirror node pass through the delayed element, whose partials, delay and rows of the
side force and pitching moment (out[5:7]) come from core/_delayed_sensitivity.py; the section
parameters' directions of either cambered element from core/_parameter_sensitivity.py.
"""

from __future__ import annotations

import numba
import numpy as np

from ._annulus import _FM, CAMBERED, GILL_SINCOS, _atan2, _cambered_annulus, _element_gill_p, _exp_sat, delay_factor
from ._delayed_sensitivity import (DELAY_VB_FLOOR, N_EX, add_fixed_root_halves, add_input_halves, delay_partials,
                                   delayed_node, delayed_rows)
from ._jitcache import CACHE
from ._momentum_sensitivity import _momentum_derivatives, _rest_slope
from ._parameter_sensitivity import (N_DSTATE, N_STATE, _cambered_direction, _cambered_state, _parameter_partials,
                                     delayed_parameter_partials)
from ._physics import (LN_RE_MAX, LN_RE_MIN, NODE_CFAC, NODE_CH, NODE_CT, NODE_CY2, NODE_MFAC, NODE_SC, NODE_TH, NODE_W,
                       NODE_Y, PK_DYNSTALL, PK_INPLANE, PK_RADIAL_DRAG)
from ._swirl_sensitivity import _swirl_solve, _swirl_system
from ._tangents import _loads_tangent as _loads_tangent_py
from ._tangents import make_cambered_tangent, make_gill_tangent

_jit_inline = numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
_loads_tangent = _jit_inline(_loads_tangent_py)
# the elements with their analytic partials in U_T, U_P, the blade angle and the section constants; the cambered
# element's state at a node and its derivative along any direction in its constants (the section parameters', one
# evaluation per node for all)
_cambered_tangent = _jit_inline(make_cambered_tangent(_cambered_state, _cambered_direction, _loads_tangent))
_gill_tangent = _jit_inline(make_gill_tangent(_atan2, _exp_sat, _loads_tangent))

#: relative step of the section parameters' and the density's one-sided differences of the
#: annulus' and polar's constants (core/derivatives.py)
ONE_SIDED = 1e-7
#: inputs, in the order of the output's second axis
INPUTS = ("omega", "airspeed", "incidence", "collective")
#: loads, in the order of the output's first axis (and the mean induced velocity)
LOADS = ("thrust", "drag", "torque", "rolling_moment", "v_i_mean")


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _inplane_partials(kin, v, vs, vc):
    """The blades' in-plane airspeed vb = vs + kin u_x (u_x = v vs / (sqrt(vs^2 + W^2) + |W|),
    W = vc + v, or v in descent: _momentum.inplane_induction; kin 1 with the option, 0
    without) and kin times u_x's partial derivatives in vs, in vc at fixed v and in v at
    fixed vc. At vc = 0, where u_x's slope in vc has a kink, the two sides' mean (as for the
    empirical descent model's switch); where vs = W = 0 the partials are taken as 0."""
    if kin == 0.0:
        return vs, 0.0, 0.0, 0.0
    W = vc + v if vc >= 0.0 else v
    rq = np.sqrt(vs * vs + W * W)
    d = rq + abs(W)
    if d == 0.0:
        return vs, 0.0, 0.0, 0.0
    g = v * vs / d
    sg = 1.0 if W > 0.0 else (-1.0 if W < 0.0 else 0.0)
    g_s = v / d - (g * vs / (rq * d) if rq > 0.0 else 0.0)
    g_w = -g * (W / rq + sg) / d if rq > 0.0 else 0.0  # in W
    g_c = g_w if vc > 0.0 else (0.5 * g_w if vc == 0.0 else 0.0)  # W = vc + v in climb, v in descent
    return vs + kin * g, kin * g_s, kin * g_c, kin * (vs / d + g_w)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _constants_u2(U2, sc, cy2, model, cam):
    """The section constants (s0, s1, s2, s3) of an annulus of mean square speed U2 (as _kernel._solve_point)."""
    if model == CAMBERED:
        return _cambered_annulus(U2, sc, cy2, cam[4], cam[0], cam[1], cam[2], cam[3] != 0.0, cam[5], cam[6], cam[7])
    return sc, 0.0, 0.0, 0.0


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _constants_slopes(U2, sc, cy2, model, cam):
    """The section constants (s0, s1, s2, s3) of an annulus of mean square speed U2 (as
    :func:`_constants_u2`) and their derivatives with respect to U2 [1/(m/s)^2 times each
    constant's unit], analytic (the power laws of _physics.cambered_annulus; 0 where ln Re is
    clamped). The paper's section has no Reynolds terms (slopes 0)."""
    if model != CAMBERED:
        return (sc, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0)
    a, cdf, g, dal0 = _constants_u2(U2, sc, cy2, model, cam)
    ln_re = sc + 0.5 * np.log(U2 + 1e-300)
    dln = 0.5 / (U2 + 1e-300) if LN_RE_MIN < ln_re < LN_RE_MAX else 0.0  # d ln Re / dU2
    # cam: (cl_alpha, re_exp, re_exp_lift, compressible, 1/a^2, re_exp_stall, stall_delay, alpha_L0_re)
    da = a * cam[2] * dln
    if cam[3] != 0.0 and U2 * cam[4] < 0.81:
        da += a * 0.5 * cam[4] / (1.0 - U2 * cam[4])
    return (a, cdf, g, dal0), (da, cdf * cam[1] * dln, g * cam[5] * dln, cam[7] * dln)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _constants(Om, Vs, Vc, y, sc, cy2, model, cam):
    """The section constants (s0, s1, s2, s3) of an annulus at the inputs (as _kernel._solve_point)."""
    return _constants_u2((Om * y) ** 2 + 0.5 * Vs * Vs + Vc * Vc, sc, cy2, model, cam)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _add_fixed_root(out, p, i, wj, wvj, Lv, sw, dt, dd, dq, dr, span, axial):
    """Add one annulus' share of d(loads)/dp to ``out[:, p, i]`` for a quantity p that moves the
    blade's sums only (a section parameter, the density's Reynolds part): the differences
    (dt, dd, dq, dr) of its loads over ``span``, G's change being dt's (the loss factor and the
    momentum side do not depend on p); ``sw`` the annulus' swirl system
    (core/_swirl_sensitivity._swirl_system); ``wj`` the annulus' weight, ``wvj`` its mean-inflow
    weight; D and M_R stay 0 in axial flow."""
    k2 = 1.0 / span
    dv, du = _swirl_solve(sw, dt * k2, dt * k2, dq * k2, 0.0)
    out[0, p, i] += wj * (dt * k2 + Lv[0] * dv - sw[6] * du)
    out[2, p, i] += wj * (dq * k2 + Lv[2] * dv - sw[8] * du)
    if not axial:
        out[1, p, i] += wj * (dd * k2 + Lv[1] * dv - sw[7] * du)
        out[3, p, i] += wj * (dr * k2 + Lv[3] * dv - sw[9] * du)
    out[4, p, i] += wvj * dv


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _pass(q0, h0, r0, Om, Vs, UP, y, th, sth, cth, s, sinpsi, naz, model, pk):
    """One perturbed pass over the nodes of one annulus for the paper's section (the cambered
    one takes its parameters' derivatives from :func:`_parameter_partials`): the element at the
    given section constants and parameters (a section parameter's or the density's step), less
    the base (q0, h0, r0 of :func:`_partials`). Returns the differences' sums weighted as the
    loads need them (thrust, in-plane force, torque and rolling moment are sums of qT,
    qH sin(psi), qH and qT sin(psi), the radial drag's of C_D,p U cos^2 psi): qT, qT sin, qH,
    qH sin and the radial drag's (used only with it), not divided by the step or the node count.
    """
    aT = aTs = aH = aHs = aR = 0.0
    g0, g1, g2, g3, g4, g5, sincos = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], model == GILL_SINCOS
    for k in range(naz):
        sk = sinpsi[k]
        q, h, g = _element_gill_p(Om * y + Vs * sk, UP, th, sth, cth, s[0], g0, g1, g2, g3, g4, g5, sincos)
        d = q - q0[k]
        e = h - h0[k]
        aT += d
        aTs += d * sk
        aH += e
        aHs += e * sk
        aR += g * (1.0 - sk * sk) - r0[k]
    return aT, aTs, aH, aHs, aR


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)  # in numba's IR: _annulus._jit_inline
def _add_node(acc, q0, h0, r0, k, sk, base, d_t, d_p, d_u, d_c):
    """One node's element (``base``, written into ``q0``, ``h0``, ``r0``) and partials (in U_T, U_P,
    the constants' direction and the blade angle, each (qT, qH, C_D,p U)) added to the 24 sums
    :func:`_partials` returns, at sin psi = ``sk``."""
    (tT, tTs, tTs2, tH, tHs, tHs2, pT, pTs, pH, pHs, uT, uTs, uH, uHs, rB, rT, rTs, rP, rU, cT, cTs, cH, cHs,
     rC) = acc
    ck = 1.0 - sk * sk
    q0[k] = base[0]
    h0[k] = base[1]
    r0[k] = base[2] * ck
    return (tT + d_t[0], tTs + d_t[0] * sk, tTs2 + d_t[0] * sk * sk, tH + d_t[1], tHs + d_t[1] * sk,
            tHs2 + d_t[1] * sk * sk, pT + d_p[0], pTs + d_p[0] * sk, pH + d_p[1], pHs + d_p[1] * sk, uT + d_u[0],
            uTs + d_u[0] * sk, uH + d_u[1], uHs + d_u[1] * sk, rB + base[2] * ck, rT + d_t[2] * ck,
            rTs + d_t[2] * ck * sk, rP + d_p[2] * ck, rU + d_u[2] * ck, cT + d_c[0], cTs + d_c[0] * sk, cH + d_c[1],
            cHs + d_c[1] * sk, rC + d_c[2] * ck)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _partials(q0, h0, r0, v, Om, Vs, Vc, y, th, sth, cth, s, u, sinpsi, naz, model, pk, dyn):
    """The inputs' partials over the nodes of one annulus, from one evaluation per node of the
    element with its analytic partial derivatives (core/_tangents.py): the base (written into
    ``q0``, ``h0``, ``r0`` for :func:`_pass`) and the derivatives with respect to U_T, U_P, the
    blade angle and, for the cambered section, along the constants' slopes in U2, ``u`` (their
    derivative with respect to U2). Returns the U_T sums (qT, qT sin, qT sin^2, qH, qH sin,
    qH sin^2), then the U_P and the U2 sums (qT, qT sin, qH, qH sin each), not divided by the
    node count; the radial drag's (C_D,p U cos^2 psi, from the same evaluations; used only with
    it): its base sum, its U_T sums (plain and sin), its U_P and its U2 sum; and the blade
    angle's (qT, qT sin, qH, qH sin, the radial drag's). ``dyn`` = (cos psi of the nodes, kd, sg,
    ex): with the dynamic stall (kd != 0, the annulus' Gormont factor; sg the sign of U_P V_b) the
    delayed element's, and its own sums added to ``ex`` (core/_delayed_sensitivity.delayed_node).
    """
    cospsi, kd, sg, ex = dyn
    acc = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
           0.0, 0.0)  # the 24 sums (_add_node)
    UP = Vc + v
    if model == CAMBERED and kd != 0.0:
        con = (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7])
        sec = (s[0], s[1], s[2], s[3])
        dsec = (u[0], u[1], u[2], u[3])
        ea = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
              0.0, 0.0, 0.0)  # its own sums (N_EX)
        for k in range(naz):
            ea, (base, d_t, d_p, d_u, d_c) = delayed_node(ea, Om * y + Vs * sinpsi[k], UP, th, sth, cth, sec, dsec,
                                                          con, kd, Vs, sinpsi[k], cospsi[k], sg)
            acc = _add_node(acc, q0, h0, r0, k, sinpsi[k], base, d_t, d_p, d_u, d_c)
        for c in range(N_EX):  # unrolled: a tuple of floats
            ex[c] = ea[c]
    elif model == CAMBERED:
        con = (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7])
        sec = (s[0], s[1], s[2], s[3])
        dsec = (u[0], u[1], u[2], u[3])
        for k in range(naz):  # one loop per section model, each straight-line SIMD code
            base, d_t, d_p, d_u, d_c = _cambered_tangent(Om * y + Vs * sinpsi[k], UP, th, sth, cth, sec, dsec, con)
            acc = _add_node(acc, q0, h0, r0, k, sinpsi[k], base, d_t, d_p, d_u, d_c)
    else:
        con = (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5])
        sincos = model == GILL_SINCOS
        for k in range(naz):  # the paper's section has no Reynolds terms: no U2 sums
            base, d_t, d_p, d_c = _gill_tangent(Om * y + Vs * sinpsi[k], UP, th, sth, cth, s[0], con, sincos)
            acc = _add_node(acc, q0, h0, r0, k, sinpsi[k], base, d_t, d_p, (0.0, 0.0, 0.0), d_c)
    (tT, tTs, tTs2, tH, tHs, tHs2, pT, pTs, pH, pHs, uT, uTs, uH, uHs, rB, rT, rTs, rP, rU, cT, cTs, cH, cHs,
     rC) = acc
    return ((tT, tTs, tTs2, tH, tHs, tHs2, pT, pTs, pH, pHs, uT, uTs, uH, uHs), (rB, rT, rTs, rP, rU),
            (cT, cTs, cH, cHs, rC))


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _node_rows(nodes):
    """The rows of the blade's node array (shape (N_NODE_ROWS, n_radial), _physics.NODE_*) that
    the sensitivity passes read, each shape (n_radial,): y [m], the quadrature weight w [m],
    the blade angle [rad], the section constant sc, (c/y)^2, the blade and momentum factors
    cfac, mfac [kg/m^2] and the tip- and hub-loss constants ct, ch (-1: off)."""
    return (nodes[NODE_Y], nodes[NODE_W], nodes[NODE_TH], nodes[NODE_SC], nodes[NODE_CY2], nodes[NODE_CFAC],
            nodes[NODE_MFAC], nodes[NODE_CT], nodes[NODE_CH])


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _start_point(out, i, ok, n_rows, w, y):
    """Column ``i`` of rows 0 ... n_rows - 1 of ``out`` set to 0, or to NaN where the point did not
    converge (``ok[i]`` False: returns 0.0, nothing more to do); else the mean inflow's weight
    sum w y (as _kernel._solve_point: annulus area)."""
    fill = 0.0 if ok[i] else np.nan
    for q in range(n_rows):
        for p in range(out.shape[1]):
            out[q, p, i] = fill
    if not ok[i]:
        return 0.0
    wy = 0.0
    for j in range(y.shape[0]):
        wy += w[j] * y[j]
    return wy


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _airspeed_components(V, b):
    """(sin beta, cos beta, V sin beta, V cos beta), each speed snapped to 0 where it is below
    1e-12 V: exact axial flow at beta = 0, pi and exactly edgewise flow at pi/2 (cos(pi/2) is
    6e-17), where the empirical descent model switches (as rotor_loads)."""
    sb = np.sin(b)
    cb = np.cos(b)
    vs = V * sb
    vc = V * cb
    if abs(vs) < 1e-12 * V:
        vs = 0.0
    if abs(vc) < 1e-12 * V:
        vc = 0.0
    return sb, cb, vs, vc


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _input_directions(e, n, V, sb, cb, vs):
    """Rows 0 ... n - 1 (n = 3 or 4) of ``e``: the directions of omega, the airspeed, the
    incidence (and the collective) in (Omega, V sin beta, V cos beta, the blade angle); along
    the airspeed's ray exactly no in-plane speed where V sin beta was snapped to 0 at V > 0
    (:func:`_airspeed_components`)."""
    e[0, 0] = 1.0
    e[1, 1] = 0.0 if vs == 0.0 and V > 0.0 else sb
    e[1, 2] = cb
    e[2, 1] = V * cb
    e[2, 2] = -V * sb
    if n > 3:
        e[3, 3] = 1.0


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM, forceinline=True)  # as _kernel._solve_point
def _point(i, Om, V, b, coll, roots, ok, nodes, azim, model, pk, cam, emp, n_in, par, scpm, hrho, out):
    y, w, th0, sc, cy2, cfac, mfac, ct, ch = _node_rows(nodes)
    sinpsi = azim[0]
    pkpm, campm, cam_same, hpar = par
    naz_half = sinpsi.shape[0] // 2  # the half circle [-pi/2, pi/2]
    nr = y.shape[0]
    n_par = hpar.shape[0]
    n_all = n_in + n_par + (1 if hrho != 0.0 else 0)
    n_rays = out.shape[1] - n_all  # 3: the slopes at rest along three rays in the last columns (sensitivities)
    wy = _start_point(out, i, ok, out.shape[0], w, y)  # the mean inflow's weights
    if not ok[i]:
        return
    m2 = 0.0  # the mean of sin(psi)^2 over the half circle's nodes (the axial point's one node stands for them)
    for k in range(naz_half):
        m2 += sinpsi[k] * sinpsi[k]
    m2 /= naz_half
    om, dth = Om[i], coll[i]
    sb, cb, vs, vc = _airspeed_components(V[i], b[i])
    axial = vs == 0.0
    naz = 1 if axial else naz_half  # in axial flow the integrand does not depend on psi
    # the dynamic stall (in-plane flow: its rows of Y and M_P, out[5:7]); its per-annulus sums and partials
    dyn = model == CAMBERED and pk[PK_DYNSTALL] != 0.0 and not axial
    ex = np.zeros(N_EX)
    Lvh = np.zeros(6)  # (rows 4, 5: Y's and M_P's partials in v)
    # the nodes' sin psi for the passes; the axial point's one node at psi = 0 (its sin-weighted sums are replaced by
    # the half circle's means below, and its radial-drag weight cos^2 psi is then 1)
    sn = np.zeros(1) if axial else sinpsi
    e = np.zeros((4, 4))  # each input's direction in (Omega, V sin beta, V cos beta, collective)
    _input_directions(e, 4, V[i], sb, cb, vs)
    # at V = 0 the airspeed only grows: its derivative is the one-sided slope along the ray (the momentum side's
    # from its analytic partials: _momentum_sensitivity._rest_slope)
    one_sided = V[i] == 0.0
    dB = np.empty((6, 4))  # d(T, D, Q, R[, Y, M_P])/d(Omega, Vs, Vc, collective) at the fixed root, per annulus
    q0 = np.empty(naz_half)  # the element at the root, per node
    h0 = np.empty(naz_half)
    r0 = np.zeros(naz_half)  # the radial drag's C_D,p U cos^2 psi at the root, per node
    ps = np.zeros((2 + n_par, 8))  # the sums of the section parameters' and the density's passes (below)
    # the cambered section's parameter directions: in the section constants (per annulus, below) and in the
    # polar's constants (the same on every annulus)
    n_m = n_par + (1 if hrho != 0.0 else 0)  # the parameters' and the density's directions
    dS = np.zeros((n_par + 1, 4))
    dC = np.zeros((n_par + 1, 8))
    stw = np.empty((N_DSTATE if dyn else N_STATE, naz_half if model == CAMBERED and n_m > 0 else 0))
    for m in range(n_par):
        for c in range(8):
            dC[m, c] = pkpm[m][c] - pk[c]
    krad = pk[PK_RADIAL_DRAG]  # the radial flow's drag: D gains krad V sin(beta) times its sums
    kin = pk[PK_INPLANE]  # the skewed wake's in-plane induced velocity (with swirl too: u_x does not depend on u)
    swirl = roots.shape[0] == 2
    for j in range(nr):
        vj = roots[0, i, j]
        yj = y[j]
        # with swirl the element sees the blade speed Omega y - u (the annulus' swirl u): every element pass and
        # the loss factor take Omega less u / y, the section constants Omega itself (as _kernel._solve_point)
        uj = roots[1, i, j] if swirl else 0.0
        ome = om - uj / yj if swirl else om
        th = th0[j] + dth
        sth = np.sin(th)
        cth = np.cos(th)
        U2 = (om * yj) ** 2 + 0.5 * vs * vs + vc * vc
        s, u = _constants_slopes(U2, sc[j], cy2[j], model, cam)
        UP = vc + vj
        # the blades' in-plane airspeed vb = V sin beta + u_x(v, V sin beta, V cos beta) (_momentum.inplane_induction)
        # and u_x's partials in V sin beta, in V cos beta and in v; the Reynolds constants and the momentum side keep
        # V sin beta
        vb, uxs, uxc, uxv = _inplane_partials(kin, vj, vs, vc)
        # the dynamic stall's factor and the sign of its nodes' pitch rate (as _annulus._residual: none at V_b = 0, nor
        # below DELAY_VB_FLOOR, where its partials would overflow)
        kd = delay_factor(pk, om, yj, cy2[j]) if dyn and abs(vb) > DELAY_VB_FLOOR else 0.0
        sg = 1.0 if UP * vb >= 0.0 else -1.0
        # the element and its partials in U_T (-d/du as well, with swirl), U_P (d/dv), the blade angle and the
        # constants' direction, from one evaluation per node
        sums, rsums, csums = _partials(q0, h0, r0, vj, ome, vb, vc, yj, th, sth, cth, s, u, sn, naz, model, pk,
                                       (azim[1], kd, sg, ex))
        tT, tTs, tTs2, tH, tHs, tHs2, pT, pTs, pH, pHs, uT, uTs, uH, uHs = sums
        rB, rT, rTs, rP, rU = rsums
        cT, cTs, cH, cHs, rC = csums
        if model == CAMBERED and n_m > 0:
            # each section parameter's and the density's direction in the annulus' section constants (their
            # change at the parameter's stepped value) and in the polar's constants: the element's derivatives
            # along them from one evaluation per node (_parameter_partials), into rows 1 + k of ps (row 0 stays 0)
            for m in range(n_m):
                if m == n_par:  # the density, through the Reynolds constant sc
                    sa = _constants(om, vs, vc, yj, scpm[j], cy2[j], model, cam)
                elif not cam_same[m]:
                    sa = _constants(om, vs, vc, yj, sc[j], cy2[j], model, campm[m])
                else:
                    sa = s
                for c in range(4):
                    dS[m, c] = sa[c] - s[c]
            if kd != 0.0:
                delayed_parameter_partials(ps, dS, dC, n_m, stw, ome, vb, UP, yj, th, sth, cth, s, sn, azim[1], naz,
                                           pk, kd, sg)
            else:
                _parameter_partials(ps, dS, dC, n_m, stw, ome, vb, UP, yj, th, sth, cth, s, sn, naz, pk)
        elif n_m > 0:
            # the paper's section: one-sided differences, a pass each: 0 the base again (the parameters'
            # differences are then exactly 0 for one that does not enter), 1 + k the k-th section parameter's (the
            # element's constants pk, the annulus' cam), 1 + n_par the density's (through the Reynolds constant sc;
            # cfac and mfac scale out)
            for m in range(1 + n_m):
                sa, pka = s, pk
                if m == n_par + 1:
                    sa = _constants(om, vs, vc, yj, scpm[j], cy2[j], model, cam)
                elif m >= 1:
                    pka = pkpm[m - 1]
                    if not cam_same[m - 1]:
                        sa = _constants(om, vs, vc, yj, sc[j], cy2[j], model, campm[m - 1])
                ps[m, 0], ps[m, 1], ps[m, 2], ps[m, 3], ps[m, 4] = _pass(q0, h0, r0, ome, vb, UP, yj, th, sth, cth,
                                                                         sa, sn, naz, model, pka)
        cf = cfac[j] / naz
        cq = yj * cf
        if axial:  # one node: its sin(psi)-weighted sums are those of the half circle (mean sin 0, sin^2 m2)
            tTs, tTs2, tHs, tHs2, pTs, pHs, uTs, uHs, cTs, cHs = 0.0, tT * m2, 0.0, tH * m2, 0.0, 0.0, 0.0, 0.0, 0.0, \
                0.0
            rB *= 1.0 - m2  # the radial drag's base, cos^2 psi = 1 - sin^2 psi averaged the same way
        # the radial drag: D gains rr times its sums (0 in axial flow) and, through V sin beta, krad times the base's
        rr = krad * vb
        # d(T, D, Q, R)/d(the blades' in-plane airspeed) at fixed v: U_T by sin psi, and the radial drag's
        b0, b1, b2, b3 = tTs * cf, (tHs2 + rr * rTs + krad * rB) * cf, tHs * cq, tTs2 * cq
        # with the dynamic stall: d(T, D, Q, R)/d(ln kd), through V_b (above: as ln kd / 2 V_b) and Omega (below)
        e0, e1, e2, e3, b0, b1, b2, b3 = delay_partials(ex, cf, cq, rr, vb, kd, b0, b1, b2, b3)
        # d(T, D, Q, R)/dv = d/dU_P, and through u_x (0 without it), and d/dU2 (the loads' scales applied)
        Lv0, Lv1 = pT * cf + uxv * b0, (pHs + rr * rP) * cf + uxv * b1
        Lv2, Lv3 = pH * cq + uxv * b2, pTs * cq + uxv * b3
        uu0, uu1, uu2, uu3 = uT * cf, (uHs + rr * rU) * cf, uH * cq, uTs * cq
        # Omega: U_T by y, U2 by 2 Omega y^2
        f = 2.0 * om * yj * yj
        ho = 0.5 / om  # (kd grows as sqrt(Omega))
        dB[0, 0] = yj * tT * cf + f * uu0 + ho * e0
        dB[1, 0] = yj * (tHs + rr * rT) * cf + f * uu1 + ho * e1
        dB[2, 0] = yj * tH * cq + f * uu2 + ho * e2
        dB[3, 0] = yj * tTs * cq + f * uu3 + ho * e3
        # V sin beta: U_T by sin psi (times 1 + du_x/dV sin beta), U2 by V sin beta
        fs = 1.0 + uxs
        dB[0, 1] = fs * b0 + vs * uu0
        dB[1, 1] = fs * b1 + vs * uu1
        dB[2, 1] = fs * b2 + vs * uu2
        dB[3, 1] = fs * b3 + vs * uu3
        # V cos beta: U_P by 1 and u_x by its partial (Lv less u_x's part in v), U2 by 2 V cos beta
        dc = uxc - uxv
        dB[0, 2] = Lv0 + dc * b0 + 2.0 * vc * uu0
        dB[1, 2] = Lv1 + dc * b1 + 2.0 * vc * uu1
        dB[2, 2] = Lv2 + dc * b2 + 2.0 * vc * uu2
        dB[3, 2] = Lv3 + dc * b3 + 2.0 * vc * uu3
        dB[0, 3] = cT * cf
        dB[1, 3] = (cHs + rr * rC) * cf
        dB[2, 3] = cH * cq
        dB[3, 3] = cTs * cq
        halves_t = (0.0, 0.0)  # Y's and M_P's U_T partials (the swirl's coupling)
        if kd != 0.0:
            halves_t = delayed_rows(dB, Lvh, ex, cf, cq, krad, rr, vb, om, yj, uxv, fs, vs, dc, vc)
        # the momentum side's partials (analytic but at the empirical descent model's switch)
        mv, mom_om, mom_vs, mom_vc = _momentum_derivatives(vj, ome, om, vs, vc, yj, mfac[j], ct[j], ch[j], emp,
                                                           one_sided)
        Gv = Lv0 - mv
        # the swirl's balance (without swirl the identity du = 0, which leaves dv = -G_x / G_v)
        T0 = 0.0  # the thrust and torque densities at the root (with swirl)
        Q0 = 0.0
        if swirl:
            for k in range(naz):
                T0 += q0[k]
                Q0 += h0[k]
        sw = _swirl_system(swirl, vj, yj, om, T0 * cf, Q0 * cq, Lv0, Lv2, tT * cf, (tHs + rr * rT) * cf, tH * cq,
                           tTs * cq, mom_om / yj, Gv)
        for p in range(n_in):
            if p == 2 and V[i] == 0.0:
                continue  # the incidence does nothing at V = 0
            if p == 3:  # the collective moves no momentum side
                dmom = 0.0
            elif p == 1 and one_sided:  # along the airspeed's ray from rest
                dmom = _rest_slope(mom_vs, mom_vc, vj, sb, cb, emp)
            else:  # analytic or differenced above: the chain rule
                dmom = mom_om * e[p, 0] + mom_vs * e[p, 1] + mom_vc * e[p, 2]
            dL0 = dB[0, 0] * e[p, 0] + dB[0, 1] * e[p, 1] + dB[0, 2] * e[p, 2] + dB[0, 3] * e[p, 3]
            dL1 = dB[1, 0] * e[p, 0] + dB[1, 1] * e[p, 1] + dB[1, 2] * e[p, 2] + dB[1, 3] * e[p, 3]
            dL2 = dB[2, 0] * e[p, 0] + dB[2, 1] * e[p, 1] + dB[2, 2] * e[p, 2] + dB[2, 3] * e[p, 3]
            dL3 = dB[3, 0] * e[p, 0] + dB[3, 1] * e[p, 1] + dB[3, 2] * e[p, 2] + dB[3, 3] * e[p, 3]
            dv, du = _swirl_solve(sw, dL0 - dmom, dL0, dL2, e[p, 0])
            out[0, p, i] += w[j] * (dL0 + Lv0 * dv - sw[6] * du)
            out[2, p, i] += w[j] * (dL2 + Lv2 * dv - sw[8] * du)
            if not axial or (e[p, 1] != 0.0):
                out[1, p, i] += w[j] * (dL1 + Lv1 * dv - sw[7] * du)
                out[3, p, i] += w[j] * (dL3 + Lv3 * dv - sw[9] * du)
            out[4, p, i] += w[j] * yj * dv / wy
            if kd != 0.0:
                add_input_halves(out, p, i, w[j], dB, Lvh, halves_t, e, dv, du)
        if n_rays == 3 and n_in >= 3 and one_sided:  # at rest: the airspeed's one-sided slopes along beta = 0, pi/2, pi
            for k in range(3):
                rs = 1.0 if k == 1 else 0.0  # the ray's sin(beta), cos(beta)
                rc = 1.0 - k if k != 1 else 0.0
                dmom = _rest_slope(mom_vs, mom_vc, vj, rs, rc, emp)
                dT = dB[0, 1] * rs + dB[0, 2] * rc
                dQ = dB[2, 1] * rs + dB[2, 2] * rc
                dv, du = _swirl_solve(sw, dT - dmom, dT, dQ, 0.0)
                c = n_all + k
                out[0, c, i] += w[j] * (dT + Lv0 * dv - sw[6] * du)
                out[2, c, i] += w[j] * (dQ + Lv2 * dv - sw[8] * du)
                if rs != 0.0:
                    out[1, c, i] += w[j] * (dB[1, 1] * rs + dB[1, 2] * rc + Lv1 * dv - sw[7] * du)
                    out[3, c, i] += w[j] * (dB[3, 1] * rs + dB[3, 2] * rc + Lv3 * dv - sw[9] * du)
                out[4, c, i] += w[j] * yj * dv / wy
        Lv = (Lv0, Lv1, Lv2, Lv3)
        # section parameters and the density: the loss factor and the momentum side do not depend on them, so G
        # changes by the blade's thrust
        for k in range(n_par + (1 if hrho != 0.0 else 0)):
            span = hrho if k == n_par else hpar[k]
            _add_fixed_root(out, n_in + k, i, w[j], w[j] * yj / wy, Lv, sw, (ps[1 + k, 0] - ps[0, 0]) * cf,
                            (ps[1 + k, 3] - ps[0, 3] + rr * (ps[1 + k, 4] - ps[0, 4])) * cf,
                            (ps[1 + k, 2] - ps[0, 2]) * cq,
                            (ps[1 + k, 1] - ps[0, 1]) * cq, span, axial)
            if kd != 0.0:
                add_fixed_root_halves(out, n_in + k, i, w[j], Lvh, halves_t, sw, ps, k, (cf, cq, rr), span)


@numba.njit(parallel=True, cache=CACHE, error_model="numpy", fastmath=_FM)
def sensitivities(Om, V, b, coll, roots, ok, nodes, azim, model, pk, cam, emp, n_in, par, scpm, hrho, out):
    """d(T, D, Q, M_R, v_i,mean)/d(Omega, V, beta[, collective]) at every point.

    Inputs as _kernel._solve_point but the airspeed V and the incidence beta in place of
    (V sin beta, V cos beta), the blade angles of ``nodes`` without the per-point collective
    ``coll``; ``roots`` shape (1, n, nr): the converged roots v, or (2, n, nr) with swirl: the
    roots and the swirl u of every annulus (core/_swirl_sensitivity._swirl_system); ``ok`` shape
    (n,): the points whose every annulus converged (the others get NaN); ``n_in`` 0 (parameters only), 3 or 4 (with
    the collective).
    Section parameters, ``par`` = (pkpm, campm, cam_same, hpar) (packed, to keep the argument
    list short): ``pkpm`` shape (n_par, N_PK) and ``campm`` shape (n_par, 8), the element and
    annulus constants at each parameter's stepped value, ``cam_same`` shape (n_par,) bool:
    the parameter leaves ``cam`` unchanged (its annulus constants are not recomputed),
    ``hpar`` shape (n_par,) the step (stepped value - value, either sign; n_par may be 0).
    The air density (``hrho`` != 0, its step; 0: not asked): ``scpm`` shape (nr,), the
    section constant sc at the stepped density; the output's last row is then the Reynolds
    part of dL/drho (the caller adds L / rho, the part of cfac and mfac, which scale the
    residual and leave the root unchanged). ``out`` shape (5, n_in + n_par [+ 1], n), or
    with 3 columns more (and ``n_in`` >= 3): at the points with V = 0 the airspeed's one-sided
    derivatives along the rays beta = 0, pi/2 and pi from the same roots (the slopes at rest
    of derivatives.STILL_AIR; 0 at the other points). Each derivative is a directional one in
    (Omega, V sin beta, V cos beta, collective); at V = 0 the airspeed's is one-sided (V >= 0)
    along the point's beta and the incidence's is 0.
    """
    for i in numba.prange(Om.shape[0]):
        _point(np.int64(i), Om, V, b, coll, roots, ok, nodes, azim, model, pk, cam, emp, n_in, par, scpm, hrho, out)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)
def sensitivities_serial(Om, V, b, coll, roots, ok, nodes, azim, model, pk, cam, emp, n_in, par, scpm, hrho, out):
    """:func:`sensitivities` on the calling thread: for small batches (solver.PARALLEL_MIN_POINTS, as
    _kernel.solve_batch_serial), where starting the parallel region costs more than the work (one
    point's loads with derivatives, the second core held by another process: 0.14-0.30 ms here,
    0.30-1.67 ms in parallel; 2-core AMD EPYC, 2026-11-28)."""
    for i in range(Om.shape[0]):
        _point(i, Om, V, b, coll, roots, ok, nodes, azim, model, pk, cam, emp, n_in, par, scpm, hrho, out)
