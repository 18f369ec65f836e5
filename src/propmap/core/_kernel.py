"""Compiled (numba) BEMT kernel: per-annulus root solve (eq 11) and integration (13-15).

Root-selection rule (documented in docs/solver.md, tested in tests/test_solver_roots.py)
-----------------------------------------------------------------------------------
F(v) = dT_BET(v) - dT_BEMT(v) on each annulus. We return the FIRST root met when v
moves from 0 in the direction of sign F(0): the equilibrium that a dynamic-inflow
relaxation m dv/dt = F(v), started from rest, settles on. It is therefore always a
stable root (F crosses zero downward in that direction). Concretely:

1. v_m = momentum_scale(F(0)); step h = v_m / MARCH_STEPS.
2. March v_k = s k h, k = 1..MAX_MARCH, s = sign F(0), until F changes sign.
   (A fold narrower than h can be stepped over; the rule is thus "first sign change
   on this march", which is deterministic and reproducible by the NumPy reference.)
3. If no sign change after MAX_MARCH steps: double v until one appears (a root always
   exists, NUMERICS.md "Root solve").
4. Refine the bracket with the Illinois method to |dv| <= XTOL * v_m or
   |F| <= FTOL * |F(0)|.
5. Multiple roots are flagged when F changes sign again within EXTRA_SCAN further
   march steps beyond the bracket.

``solve_annuli`` runs these steps for all annuli of an operating point in lockstep (one
residual sweep over the active annuli, then one state-machine step each), which gives
the same iterates as a per-annulus loop (tested against the NumPy reference) but lets
the CPU overlap the independent evaluations.
"""

from __future__ import annotations

import numba
import numpy as np

from ._fastmath import atan2_poly, exp_sat
from ._physics import make_element, momentum_scale, momentum_thrust

MARCH_STEPS = 3.0
MAX_MARCH = 64
MAX_DOUBLING = 80
EXTRA_SCAN = 1
MAX_REFINE = 100
XTOL = 1e-7
FTOL = 1e-9

# status codes of one annulus
OK = 0
NO_BRACKET = 1
NO_CONVERGENCE = 2

_FM = {"nsz", "arcp", "contract", "afn", "reassoc"}  # keeps inf/NaN semantics
_jit_inline = numba.njit(inline="always", error_model="numpy", fastmath=_FM)
# polynomial atan2/exp: no libm calls, so the azimuth loops below compile to SIMD code
_atan2 = _jit_inline(atan2_poly)
_exp_sat = _jit_inline(exp_sat)
_element = _jit_inline(make_element(_atan2, _exp_sat))
_momentum_thrust = _jit_inline(momentum_thrust)
_momentum_scale = _jit_inline(momentum_scale)


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def _residual(v, y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz,
              cl1, cl2, cd, a0, M, cd0, sincos):
    """F(v) = dT_BET/dy - dT_BEMT/dy [N/m] on one annulus (eq 11)."""
    acc = 0.0
    UP = Vc + v
    for k in range(naz):
        qT, _ = _element(Om * y + Vs * sinpsi[k], UP, th, sth, cth, kre,
                         cl1, cl2, cd, a0, M, cd0, sincos)
        acc += qT
    return cfac * acc / naz - _momentum_thrust(v, mfac, Vs, Vc)


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def _false_position(a, fa, b, fb):
    """Zero of the secant through (a, fa), (b, fb); fa * fb < 0."""
    return (a * fb - b * fa) / (fb - fa)


# phases of one annulus' root solve (solve_annuli)
_INIT = 0
_MARCH = 1
_DOUBLE = 2
_SCAN = 3
_REFINE = 4


@numba.njit(cache=True, error_model="numpy", fastmath=_FM)
def solve_annuli(Om, Vs, Vc, y, th, sth, cth, kre, cfac, mfac, sinpsi, naz,
                 cl1, cl2, cd, a0, M, cd0, sincos, v, code, nev, multiple):
    """Roots of eq (11) on every annulus of one operating point, by the module's rule.

    The annuli are independent, so they are solved in lockstep: each sweep evaluates
    F at the trial inflow of every annulus still active, then advances each annulus'
    state machine (march, doubling, extra scan, Illinois) by one step. Step for step
    this is the scalar algorithm of the module docstring, but the evaluations of one
    sweep do not wait on each other, so the CPU overlaps them (one F(v) at a time is
    latency-bound). Outputs, shape (nr,): v [m/s], code (OK, NO_BRACKET,
    NO_CONVERGENCE), nev (residual evaluations) and multiple (more roots seen).
    """
    nr = y.shape[0]
    trial = np.zeros(nr)
    f = np.empty(nr)
    a = np.zeros(nr)
    fa = np.empty(nr)
    b = np.zeros(nr)
    fb = np.empty(nr)
    sgn = np.empty(nr)
    h = np.empty(nr)
    xtol = np.empty(nr)
    ftol = np.empty(nr)
    phase = np.zeros(nr, dtype=np.int64)
    k = np.zeros(nr, dtype=np.int64)
    kb = np.zeros(nr, dtype=np.int64)
    cnt = np.zeros(nr, dtype=np.int64)
    active = np.arange(nr)
    for j in range(nr):
        nev[j] = 0
        multiple[j] = False
        code[j] = OK
    n_active = nr
    while n_active > 0:
        for q in range(n_active):  # independent evaluations
            j = active[q]
            f[j] = _residual(trial[j], y[j], Om, Vs, Vc, th[j], sth[j], cth[j], kre[j], cfac[j], mfac[j],
                             sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
            nev[j] += 1
        m = 0
        for q in range(n_active):
            j = active[q]
            fj = f[j]
            ph = phase[j]
            refine = False
            done = False
            if ph == _INIT:
                if fj == 0.0:
                    v[j] = 0.0
                    done = True
                else:
                    sgn[j] = 1.0 if fj > 0.0 else -1.0
                    vm = _momentum_scale(fj, mfac[j], Vs, Vc)
                    h[j] = vm / MARCH_STEPS
                    xtol[j] = XTOL * vm
                    ftol[j] = FTOL * abs(fj)
                    fa[j] = fj
                    fb[j] = fj
                    k[j] = 1
                    phase[j] = _MARCH
                    trial[j] = sgn[j] * h[j]
            elif ph == _MARCH:
                b[j] = trial[j]
                fb[j] = fj
                if fj * sgn[j] <= 0.0:
                    kb[j] = k[j]
                    if EXTRA_SCAN > 0:
                        phase[j] = _SCAN
                        cnt[j] = 1
                        trial[j] = sgn[j] * (kb[j] + 1) * h[j]
                    else:
                        refine = True
                else:
                    a[j] = b[j]
                    fa[j] = fj
                    k[j] += 1
                    if k[j] > MAX_MARCH:
                        phase[j] = _DOUBLE
                        cnt[j] = 0
                        trial[j] = 2.0 * b[j]
                    else:
                        trial[j] = sgn[j] * k[j] * h[j]
            elif ph == _DOUBLE:
                b[j] = trial[j]
                fb[j] = fj
                if fj * sgn[j] <= 0.0:
                    refine = True
                else:
                    a[j] = b[j]
                    fa[j] = fj
                    cnt[j] += 1
                    if cnt[j] >= MAX_DOUBLING:
                        v[j] = np.nan
                        code[j] = NO_BRACKET
                        done = True
                    else:
                        trial[j] = 2.0 * b[j]
            elif ph == _SCAN:
                if fj * sgn[j] > 0.0:
                    multiple[j] = True
                    refine = True
                else:
                    cnt[j] += 1
                    if cnt[j] > EXTRA_SCAN:
                        refine = True
                    else:
                        trial[j] = sgn[j] * (kb[j] + cnt[j]) * h[j]
            else:  # _REFINE: Illinois on [a, b], fa * fb < 0
                if fj * fb[j] < 0.0:
                    a[j] = b[j]
                    fa[j] = fb[j]
                else:
                    fa[j] = 0.5 * fa[j]
                b[j] = trial[j]
                fb[j] = fj
                if abs(fj) <= ftol[j] or abs(b[j] - a[j]) <= xtol[j]:
                    v[j] = b[j]
                    done = True
                else:
                    cnt[j] += 1
                    if cnt[j] >= MAX_REFINE:
                        v[j] = b[j]
                        code[j] = NO_CONVERGENCE
                        done = True
                    else:
                        trial[j] = _false_position(a[j], fa[j], b[j], fb[j])
            if refine:
                if fb[j] == 0.0:
                    v[j] = b[j]
                    done = True
                else:
                    phase[j] = _REFINE
                    cnt[j] = 0
                    trial[j] = _false_position(a[j], fa[j], b[j], fb[j])
            if not done:
                active[m] = j
                m += 1
        n_active = m


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)
def annulus_loads(v, y, Om, Vs, Vc, th, sth, cth, kre, cfac, sinpsi, naz,
                  cl1, cl2, cd, a0, M, cd0, sincos, axial):
    """dT/dy, dD/dy, dQ/dy [N/m, N/m, N] at inflow v (eqs 5-7, azimuth-averaged)."""
    aT = 0.0
    aD = 0.0
    aQ = 0.0
    UP = Vc + v
    for k in range(naz):
        qT, qH = _element(Om * y + Vs * sinpsi[k], UP, th, sth, cth, kre,
                          cl1, cl2, cd, a0, M, cd0, sincos)
        aT += qT
        aD += qH * sinpsi[k]
        aQ += qH
    dD = 0.0 if axial else cfac * aD / naz  # exactly 0 by symmetry in axial flow
    return cfac * aT / naz, dD, y * cfac * aQ / naz


@numba.njit(parallel=True, cache=True, error_model="numpy", fastmath=_FM)
def solve_batch(Om, Vs, Vc, y, w, th, sth, cth, kre, cfac, mfac, sinpsi,
                cl1, cl2, cd, a0, M, cd0, sincos,
                T, D, Q, vi, dT, dD, dQ, status, nmulti, nvrs, nevals):
    """Solve every operating point; results are written into the output arrays.

    Inputs Om, Vs, Vc have shape (n,); y, w, th, sth, cth, kre, cfac, mfac shape (nr,);
    sinpsi shape (naz,). Outputs T, D, Q, nmulti, nvrs, nevals, status shape (n,);
    vi, dT, dD, dQ shape (n, nr). ``status[i]`` is 0 when every annulus converged,
    else 1 + (first failing annulus index) * 4 + (annulus status code).
    """
    n = Om.shape[0]
    nr = y.shape[0]
    naz_full = sinpsi.shape[0]
    for i in numba.prange(n):
        axial = Vs[i] == 0.0
        naz = 1 if axial else naz_full  # the integrand is independent of psi
        v = vi[i]  # the roots are written straight into the output row
        code = np.empty(nr, dtype=np.int64)
        nev = np.empty(nr, dtype=np.int64)
        multiple = np.empty(nr, dtype=np.bool_)
        solve_annuli(Om[i], Vs[i], Vc[i], y, th, sth, cth, kre, cfac, mfac, sinpsi, naz,
                     cl1, cl2, cd, a0, M, cd0, sincos, v, code, nev, multiple)
        Ti = 0.0
        Di = 0.0
        Qi = 0.0
        st = 0
        nm = 0
        nv = 0
        ne = 0
        for j in range(nr):
            ne += nev[j]
            if multiple[j]:
                nm += 1
            if code[j] != OK:
                if st == 0:
                    st = 1 + j * 4 + code[j]
                dT[i, j] = np.nan
                dD[i, j] = np.nan
                dQ[i, j] = np.nan
                continue
            if Vc[i] < 0.0 and Vc[i] + v[j] > 0.0:
                nv += 1
            t, d, q = annulus_loads(v[j], y[j], Om[i], Vs[i], Vc[i], th[j], sth[j], cth[j], kre[j],
                                    cfac[j], sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos, axial)
            dT[i, j] = t
            dD[i, j] = d
            dQ[i, j] = q
            Ti += w[j] * t
            Di += w[j] * d
            Qi += w[j] * q
        T[i] = Ti if st == 0 else np.nan
        D[i] = Di if st == 0 else np.nan
        Q[i] = Qi if st == 0 else np.nan
        status[i] = st
        nmulti[i] = nm
        nvrs[i] = nv
        nevals[i] = ne
