"""The dynamic stall's part of the implicit derivatives (core/_sensitivity.py): the delayed
element's partials over an annulus' nodes, the side force and pitching moment they give, and
the chain rule through Gormont's delay.

With ``RotorOptions.dynamic_stall`` (the cambered section, the uniform inflow, in-plane
flow) every half-circle node and its mirror node pass through the delayed element
(_physics.make_delayed_cambered_element): the pair's mean loads give T, D, Q, M_R as the static
element's do, and half their difference the side force Y and the pitching moment M_P
(_annulus_loads.annulus_loads: dY/dy = (cfac / naz) sum sg cos psi (kr C_D,p,h U sin psi - qH,h),
dM_P/dy = -(y cfac / naz) sum sg cos psi qT,h, sg the sign of U_P V_b, kr the radial drag's
factor times V_b). Beyond U_T, U_P, the blade angle and the section constants, the delay
d = kd sqrt(|U_P V_b cos psi|) / U^1.5 depends on the annulus' kd = gamma sqrt(c Omega / 2)
and on the blades' in-plane airspeed V_b: d moves with ln kd by d, hence with Omega by
d / (2 Omega) and with V_b by d / (2 V_b) (below the delay's bound DELAY_MAX; 0 above it). So
each node's element is evaluated once with its partials along U_T, U_P, the blade angle, the
constants' slope in U2 and ln kd (core/_tangents.make_delayed_direction), and the sums below
carry them into :func:`_sensitivity._point`'s chain rule, which adds the Omega and V_b parts
of the delay to T, D, Q, M_R and takes Y and M_P's rows from :func:`delayed_rows`.

The delay grows as sqrt(V_b) from rest and as sqrt(|U_P|) from U_P = 0 (Gormont's square root
of the pitch rate), so its slopes there are unbounded: at V = 0 the element is the static one
(no delay) and the slopes at rest (derivatives.STILL_AIR) are those of the static polar; at
U_P = 0 the delay's U_P partial is taken as 0.
"""

from __future__ import annotations

import numba

from ._annulus import _FM, _atan2, _exp_sat
from ._swirl_sensitivity import _swirl_solve
from ._tangents import _loads_tangent as _loads_tangent_py
from ._tangents import make_delayed_direction, make_delayed_tangent

_jit_inline = numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
_loads_tangent = _jit_inline(_loads_tangent_py)
_delayed_state, _delayed_direction = (_jit_inline(f) for f in make_delayed_direction(_atan2, _exp_sat,
                                                                                        _loads_tangent))
_delayed_tangent = _jit_inline(make_delayed_tangent(_delayed_state, _delayed_direction, _loads_tangent))

# the extra sums of one annulus (:func:`delayed_node`), not divided by the node count:
# along ln kd, qT, qT sin, qH, qH sin and the radial drag's C_D,p U cos^2 psi
E_T, E_TS, E_H, E_HS, E_R = 0, 1, 2, 3, 4
# the half differences' sums sg cos psi (qT,h, qH,h, C_D,p,h U sin psi) along U_T, U_P, the constants' slope in U2,
# the blade angle and ln kd (three each from these offsets), along U_T once more weighted by sin psi, and the base's
# radial drag half (sg cos psi sin psi C_D,p,h U)
H_UT, H_UP, H_U2, H_TH, H_E, H_UTS, H_C0 = 5, 8, 11, 14, 17, 20, 23
N_EX = 24


#: the blades' in-plane airspeed V_b [m/s] below which the derivatives take the dynamic stall's delay as none, as at
#: V_b = 0 (the cusp of Gormont's delay, docs/solver.md): its partials divide by V_b, and 1e-310 m/s overflowed them
#: to NaN without a word (an API audit, 2026-12-01); below it the delay changes the loads by about sqrt(V_b)
DELAY_VB_FLOOR = 1e-150

@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def delayed_node(ea, UT, UP, th, sth, cth, sec, dsec, con, kd, vb, sk, ck, sg):
    """One node of the delayed element (node and mirror node) with its partials: returns the
    ln kd sums and the half differences' sums ``ea`` (a tuple of N_EX, carried through the node
    loop so that it vectorises; written to the array ``ex`` after it) with this node's added and,
    as core/_tangents.make_cambered_tangent's ``cambered_tangent`` does, the mean loads (qT, qH,
    C_D,p U) and their partials in U_T, U_P, along ``dsec`` and in the blade angle. ``vb`` the
    blades' in-plane airspeed [m/s], ``sk``, ``ck`` sin psi and cos psi (>= 0) of the node,
    ``sg`` the sign of U_P V_b (the node's pitch rate)."""
    base, d_t, d_p, d_u, d_c, d_e = _delayed_tangent(UT, UP, th, sth, cth, sec, dsec, con, kd, vb * ck)
    c2 = 1.0 - sk * sk
    wc = sg * ck
    ws = wc * sk
    ea = (ea[0] + d_e[0], ea[1] + d_e[0] * sk, ea[2] + d_e[1], ea[3] + d_e[1] * sk, ea[4] + d_e[2] * c2,
          ea[5] + wc * d_t[3], ea[6] + wc * d_t[4], ea[7] + ws * d_t[5],
          ea[8] + wc * d_p[3], ea[9] + wc * d_p[4], ea[10] + ws * d_p[5],
          ea[11] + wc * d_u[3], ea[12] + wc * d_u[4], ea[13] + ws * d_u[5],
          ea[14] + wc * d_c[3], ea[15] + wc * d_c[4], ea[16] + ws * d_c[5],
          ea[17] + wc * d_e[3], ea[18] + wc * d_e[4], ea[19] + ws * d_e[5],
          ea[20] + ws * d_t[3], ea[21] + ws * d_t[4], ea[22] + ws * sk * d_t[5], ea[23] + ws * base[5])
    return ea, ((base[0], base[1], base[2]), (d_t[0], d_t[1], d_t[2]), (d_p[0], d_p[1], d_p[2]),
                (d_u[0], d_u[1], d_u[2]), (d_c[0], d_c[1], d_c[2]))


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def delay_partials(ex, cf, cq, kr, vb, kd, b0, b1, b2, b3):
    """d(T, D, Q, M_R)/d(ln kd) of one annulus [N/m, N/m, N, N] from its sums ``ex``
    (:func:`delayed_node`; ``cf`` = cfac / naz, ``cq`` = y cf, ``kr`` the radial drag's
    factor times V_b), and the loads' partials in V_b ``b0`` ... ``b3`` with the delay's part
    added (d moves with V_b as with ln kd / (2 V_b)); zeros and the b's unchanged where ``kd``
    is 0 (no dynamic stall)."""
    if kd == 0.0:
        return 0.0, 0.0, 0.0, 0.0, b0, b1, b2, b3
    e0, e1, e2, e3 = ex[E_T] * cf, (ex[E_HS] + kr * ex[E_R]) * cf, ex[E_H] * cq, ex[E_TS] * cq
    hv = 0.5 / vb
    return e0, e1, e2, e3, b0 + hv * e0, b1 + hv * e1, b2 + hv * e2, b3 + hv * e3


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _halves_row(ex, at, cf, cq, kr):
    """(dY/dy, dM_P/dy)'s partials along the direction whose sums start at ``ex[at]``."""
    return cf * (kr * ex[at + 2] - ex[at + 1]), -cq * ex[at]


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def delayed_rows(dB, Lv, ex, cf, cq, krad, kr, vb, om, y, uxv, fs, vs, dc, vc):
    """Rows 4 (Y) and 5 (M_P) of an annulus' partials at its fixed root: ``dB[4:6]`` in (Omega,
    V sin beta, V cos beta, the blade angle) and ``Lv[4:6]`` in its inflow v, as
    core/_sensitivity._point's rows 0-3 (``uxv``, ``fs``, ``dc``: the in-plane induction's
    factors there; ``vs``, ``vc``: V sin beta, V cos beta; ``krad``: 1 with the radial drag).
    Returns the rows' U_T partials (Y_t, M_P,t), the swirl's coupling."""
    Yt, Pt = _halves_row(ex, H_UT, cf, cq, kr)
    Yp, Pp = _halves_row(ex, H_UP, cf, cq, kr)
    Yu, Pu = _halves_row(ex, H_U2, cf, cq, kr)
    Yc, Pc = _halves_row(ex, H_TH, cf, cq, kr)
    Ye, Pe = _halves_row(ex, H_E, cf, cq, kr)
    Ys, Ps = _halves_row(ex, H_UTS, cf, cq, kr)
    bY = Ys + krad * cf * ex[H_C0] + 0.5 * Ye / vb  # d/dV_b at fixed v: U_T by sin psi, kr, the delay
    bP = Ps + 0.5 * Pe / vb
    _chain_row(dB, Lv, 4, bY, Yt, Yp, Yu, Yc, Ye, om, y, uxv, fs, vs, dc, vc)
    _chain_row(dB, Lv, 5, bP, Pt, Pp, Pu, Pc, Pe, om, y, uxv, fs, vs, dc, vc)
    return Yt, Pt


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _chain_row(dB, Lv, q, b, t, p, u, c, e, om, y, uxv, fs, vs, dc, vc):
    """Row ``q`` of :func:`delayed_rows` from the load's partials in V_b (``b``), U_T, U_P, U2, the
    blade angle and ln kd (as core/_sensitivity._point's rows 0-3)."""
    f = 2.0 * om * y * y
    Lv[q] = p + uxv * b
    dB[q, 0] = y * t + f * u + 0.5 * e / om
    dB[q, 1] = fs * b + vs * u
    dB[q, 2] = Lv[q] + dc * b + 2.0 * vc * u
    dB[q, 3] = c


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def add_input_halves(out, p, i, wj, dB, Lv, halves_t, e, dv, du):
    """Add annulus' share (weight ``wj``) of dY/dx and dM_P/dx to ``out[5:7, p, i]`` for input p
    of direction ``e[p]`` in (Omega, V sin beta, V cos beta, collective), from :func:`delayed_rows`'
    ``dB[4:6]``, ``Lv[4:6]`` and ``halves_t``, and the root's (and swirl's) change ``dv``, ``du``."""
    for q in range(2):
        dL = dB[4 + q, 0] * e[p, 0] + dB[4 + q, 1] * e[p, 1] + dB[4 + q, 2] * e[p, 2] + dB[4 + q, 3] * e[p, 3]
        out[5 + q, p, i] += wj * (dL + Lv[4 + q] * dv - halves_t[q] * du)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def add_fixed_root_halves(out, p, i, wj, Lv, halves_t, sw, ps, k, scales, span):
    """_sensitivity._add_fixed_root's rows for Y and M_P (``out`` rows 5 and 6): the k-th section
    parameter (or the density) moves the blade's sums only, by the differences of row 1 + k of
    ``ps`` (T: column 0, Q: 2, the halves: 5-7; _parameter_sensitivity.delayed_parameter_partials)
    from its row 0, over ``span``; ``scales`` = (cfac / naz, y cfac / naz, the radial drag's
    factor times V_b); ``Lv`` the annulus' v partials (rows 4, 5: Y, M_P), ``halves_t`` their U_T
    partials (the swirl's coupling)."""
    cf, cq, kr = scales
    dt = (ps[1 + k, 0] - ps[0, 0]) * cf
    dq = (ps[1 + k, 2] - ps[0, 2]) * cq
    dY = cf * (kr * (ps[1 + k, 7] - ps[0, 7]) - (ps[1 + k, 6] - ps[0, 6]))
    dP = -cq * (ps[1 + k, 5] - ps[0, 5])
    k2 = 1.0 / span
    dv, du = _swirl_solve(sw, dt * k2, dt * k2, dq * k2, 0.0)
    out[5, p, i] += wj * (dY * k2 + Lv[4] * dv - halves_t[0] * du)
    out[6, p, i] += wj * (dP * k2 + Lv[5] * dv - halves_t[1] * du)
