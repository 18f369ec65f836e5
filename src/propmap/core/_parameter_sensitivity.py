"""The section parameters' (and the air density's) partials of the elements over an annulus'
nodes for the implicit derivatives (core/_sensitivity.py, core/_linear_sensitivity.py): each
parameter's step moves the polar's constants pk[:8] and the annulus' section constants by
known amounts, and the element's derivative along that direction is analytic
(core/_tangents.make_cambered_direction, make_delayed_direction with the dynamic stall), every
direction from one evaluation of the element's state per node, stored so that each
direction's loop runs over the nodes (SIMD), as the element's own loops do.
"""

from __future__ import annotations

import numba

from ._annulus import _FM, _atan2, _exp_sat
from ._delayed_sensitivity import _delayed_direction, _delayed_state
from ._jitcache import CACHE
from ._tangents import _loads_tangent as _loads_tangent_py
from ._tangents import make_cambered_direction

_jit_inline = numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
_loads_tangent = _jit_inline(_loads_tangent_py)
# the cambered element's state at a node and its derivative along any direction in its constants (the section
# parameters', one evaluation per node for all; core/_sensitivity's element with its partials is built on them)
_cambered_state, _cambered_direction = (_jit_inline(f) for f in make_cambered_direction(_atan2, _exp_sat,
                                                                                          _loads_tangent))

#: the values of the cambered element's state at a node (_tangents.make_cambered_direction)
N_STATE = 28
#: the values of the delayed element's state at a node (_tangents.make_delayed_direction: 7 + 23 + 19)
N_DSTATE = 49


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)  # in numba's IR: _annulus._jit_inline
def _stored_state(stw, k):
    """The cambered element's state at node ``k`` (a tuple of N_STATE floats) from the scratch
    ``stw`` shape (N_STATE, >= k + 1) that :func:`_parameter_partials` fills."""
    return (stw[0, k], stw[1, k], stw[2, k], stw[3, k], stw[4, k], stw[5, k], stw[6, k],
            stw[7, k], stw[8, k], stw[9, k], stw[10, k], stw[11, k], stw[12, k], stw[13, k],
            stw[14, k], stw[15, k], stw[16, k], stw[17, k], stw[18, k], stw[19, k], stw[20, k],
            stw[21, k], stw[22, k], stw[23, k], stw[24, k], stw[25, k], stw[26, k], stw[27, k])


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _direction(dS, dC, m):
    """Direction ``m`` as (its section constants' change, its polar constants' change): rows m of
    ``dS`` shape (n, 4) and ``dC`` shape (n, 8) as tuples (:func:`_parameter_partials`)."""
    return ((dS[m, 0], dS[m, 1], dS[m, 2], dS[m, 3]),
            (dC[m, 0], dC[m, 1], dC[m, 2], dC[m, 3], dC[m, 4], dC[m, 5], dC[m, 6], dC[m, 7]))


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)  # called, not inlined (compile time)
def _parameter_partials(ps, dS, dC, n_m, stw, Om, Vs, UP, y, th, sth, cth, s, sinpsi, naz, pk):
    """The cambered element's derivatives along ``n_m`` directions over the nodes of one annulus,
    from one evaluation per node (core/_tangents.make_cambered_direction): row m of ``dS``
    (shape (n_m, 4)) and ``dC`` (shape (n_m, 8)) the m-th direction in the annulus' section
    constants and in the polar's constants pk[:8] (a section parameter's or the density's step,
    stepped value less base). Writes into row 1 + m of ``ps`` the sums qT, qT sin, qH, qH sin
    and the radial drag's (C_D,p U cos^2 psi), not divided by the step or the node count, as
    core/_sensitivity._pass gives them as differences. ``stw`` shape (N_STATE, >= naz): scratch for the
    nodes' element states, so that each direction's loop runs over the nodes (SIMD), as the
    element's own loops do."""
    con = (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7])
    sec = (s[0], s[1], s[2], s[3])
    for k in range(naz):
        st = _cambered_state(Om * y + Vs * sinpsi[k], UP, th, sth, cth, sec, con)
        for c in range(N_STATE):  # unrolled: the state is a tuple of floats
            stw[c, k] = st[c]
    for m in range(n_m):
        dsec, dcon = _direction(dS, dC, m)
        aT = aTs = aH = aHs = aR = 0.0
        for k in range(naz):
            sk = sinpsi[k]
            st = _stored_state(stw, k)
            dqT, dqH, dgR = _cambered_direction(st, dsec, dcon)
            aT += dqT
            aTs += dqT * sk
            aH += dqH
            aHs += dqH * sk
            aR += dgR * (1.0 - sk * sk)
        ps[1 + m, 0] = aT
        ps[1 + m, 1] = aTs
        ps[1 + m, 2] = aH
        ps[1 + m, 3] = aHs
        ps[1 + m, 4] = aR


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)
def delayed_parameter_partials(ps, dS, dC, n_m, stw, Om, Vs, UP, y, th, sth, cth, s, sinpsi, cospsi, naz, pk, kd,
                               sg):
    """:func:`_parameter_partials` for the delayed element: rows 1 + m of ``ps`` (shape
    (>= 1 + n_m, 8)) get the sums qT, qT sin, qH, qH sin, the radial drag's, and the half
    differences' sg cos psi (qT,h, qH,h, C_D,p,h U sin psi) along direction m; ``stw`` shape
    (N_DSTATE, >= naz) scratch for the nodes' states."""
    con = (pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7])
    sec = (s[0], s[1], s[2], s[3])
    for k in range(naz):
        st = _delayed_state(Om * y + Vs * sinpsi[k], UP, th, sth, cth, sec, con, kd, Vs * cospsi[k])
        for c in range(7):  # unrolled: the state is three tuples of floats
            stw[c, k] = st[0][c]
        for c in range(23):
            stw[7 + c, k] = st[1][c]
        for c in range(19):
            stw[30 + c, k] = st[2][c]
    for m in range(n_m):
        dsec = (dS[m, 0], dS[m, 1], dS[m, 2], dS[m, 3])
        dcon = (dC[m, 0], dC[m, 1], dC[m, 2], dC[m, 3], dC[m, 4], dC[m, 5], dC[m, 6], dC[m, 7])
        a0 = a1 = a2 = a3 = a4 = a5 = a6 = a7 = 0.0  # (scalars: the loop vectorises over the nodes)
        for k in range(naz):
            sk = sinpsi[k]
            st = ((stw[0, k], stw[1, k], stw[2, k], stw[3, k], stw[4, k], stw[5, k], stw[6, k]),
                  (stw[7, k], stw[8, k], stw[9, k], stw[10, k], stw[11, k], stw[12, k], stw[13, k], stw[14, k],
                   stw[15, k], stw[16, k], stw[17, k], stw[18, k], stw[19, k], stw[20, k], stw[21, k], stw[22, k],
                   stw[23, k], stw[24, k], stw[25, k], stw[26, k], stw[27, k], stw[28, k], stw[29, k]),
                  (stw[30, k], stw[31, k], stw[32, k], stw[33, k], stw[34, k], stw[35, k], stw[36, k], stw[37, k],
                   stw[38, k], stw[39, k], stw[40, k], stw[41, k], stw[42, k], stw[43, k], stw[44, k], stw[45, k],
                   stw[46, k], stw[47, k], stw[48, k]))
            dd = _delayed_direction(st, 0.0, 0.0, 0.0, 0.0, dsec, dcon)
            wc = sg * cospsi[k]
            a0 += dd[0]
            a1 += dd[0] * sk
            a2 += dd[1]
            a3 += dd[1] * sk
            a4 += dd[2] * (1.0 - sk * sk)
            a5 += wc * dd[3]
            a6 += wc * dd[4]
            a7 += wc * sk * dd[5]
        ps[1 + m, 0], ps[1 + m, 1], ps[1 + m, 2], ps[1 + m, 3] = a0, a1, a2, a3
        ps[1 + m, 4], ps[1 + m, 5], ps[1 + m, 6], ps[1 + m, 7] = a4, a5, a6, a7
