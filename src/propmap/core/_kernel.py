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
        qT, qH = _element(Om * y + Vs * sinpsi[k], UP, th, sth, cth, kre,
                          cl1, cl2, cd, a0, M, cd0, sincos)
        acc += qT
    return cfac * acc / naz - _momentum_thrust(v, mfac, Vs, Vc)


@numba.njit(cache=True, error_model="numpy", fastmath=_FM)
def solve_annulus(y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz,
                  cl1, cl2, cd, a0, M, cd0, sincos):
    """Root of eq (11) on one annulus by the rule in the module docstring.

    Returns (v_i [m/s], status, n_evaluations, multiple_roots).
    """
    F0 = _residual(0.0, y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
    nev = 1
    if F0 == 0.0:
        return 0.0, OK, nev, False
    s = 1.0 if F0 > 0.0 else -1.0
    vm = _momentum_scale(F0, mfac, Vs, Vc)
    h = vm / MARCH_STEPS
    a = 0.0
    fa = F0
    b = 0.0
    fb = F0
    found = False
    kb = 0
    for k in range(1, MAX_MARCH + 1):
        b = s * k * h
        fb = _residual(b, y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
        nev += 1
        if fb * s <= 0.0:
            found = True
            kb = k
            break
        a = b
        fa = fb
    if not found:
        for _ in range(MAX_DOUBLING):
            b = 2.0 * b
            fb = _residual(b, y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
            nev += 1
            if fb * s <= 0.0:
                found = True
                break
            a = b
            fa = fb
    if not found:
        return np.nan, NO_BRACKET, nev, False
    multiple = False
    if kb > 0:
        for m in range(1, EXTRA_SCAN + 1):
            fm = _residual(s * (kb + m) * h, y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
            nev += 1
            if fm * s > 0.0:
                multiple = True
                break
    if fb == 0.0:
        return b, OK, nev, multiple
    # Illinois refinement on [a, b], fa * fb < 0
    xtol = XTOL * vm
    ftol = FTOL * abs(F0)
    for _ in range(MAX_REFINE):
        c = (a * fb - b * fa) / (fb - fa)
        fc = _residual(c, y, Om, Vs, Vc, th, sth, cth, kre, cfac, mfac, sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
        nev += 1
        if fc * fb < 0.0:
            a = b
            fa = fb
        else:
            fa = 0.5 * fa
        b = c
        fb = fc
        if abs(fb) <= ftol or abs(b - a) <= xtol:
            return b, OK, nev, multiple
    return b, NO_CONVERGENCE, nev, multiple


@numba.njit(cache=True, error_model="numpy", fastmath=_FM)
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
        Ti = 0.0
        Di = 0.0
        Qi = 0.0
        st = 0
        nm = 0
        nv = 0
        ne = 0
        for j in range(nr):
            v, code, nev, multiple = solve_annulus(
                y[j], Om[i], Vs[i], Vc[i], th[j], sth[j], cth[j], kre[j], cfac[j], mfac[j],
                sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos)
            ne += nev
            if multiple:
                nm += 1
            if code != OK:
                if st == 0:
                    st = 1 + j * 4 + code
                vi[i, j] = v
                dT[i, j] = np.nan
                dD[i, j] = np.nan
                dQ[i, j] = np.nan
                continue
            if Vc[i] < 0.0 and Vc[i] + v > 0.0:
                nv += 1
            t, d, q = annulus_loads(v, y[j], Om[i], Vs[i], Vc[i], th[j], sth[j], cth[j], kre[j],
                                    cfac[j], sinpsi, naz, cl1, cl2, cd, a0, M, cd0, sincos, axial)
            vi[i, j] = v
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
