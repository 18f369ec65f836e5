"""Compiled (numba) physics of one annulus: the root solve of eq 11 by the selection rule (the
annulus' loads at the root, eqs 5-7, are core/_annulus_loads.py's); core/_kernel.py runs them over
the annuli and the points.

Root-selection rule (documented in docs/solver.md, tested in tests/test_solver_roots.py)
-----------------------------------------------------------------------------------
F(v) = dT_BET(v) - dT_BEMT(v) on each annulus. We return the FIRST root met when v
moves from 0 in the direction of sign F(0): the equilibrium that a dynamic-inflow
relaxation m dv/dt = F(v), started from rest, settles on. It is therefore always a
stable root (F crosses zero downward in that direction). Concretely:

1. v_m = momentum_scale(F(0)) (with tip/hub loss, of F(0) / F_loss(v_m0) where v_m0 is
   the loss-free scale); step h = v_m / MARCH_STEPS.
2. March v_k = s k h, k = 1..MAX_MARCH, s = sign F(0), until F changes sign.
   (A fold narrower than h can be stepped over; the rule is thus "first sign change
   on this march", which is deterministic and reproducible by the NumPy reference.)
3. If no sign change after MAX_MARCH steps: double v until one appears (a root always
   exists, docs/numerics.md "Root solve").
4. Refine the bracket with Chandrupatla's method (inverse quadratic interpolation where
   the three latest points admit it, else bisection; every step stays inside the
   bracket) until it is narrower than XTOL * v_m, |F| <= FTOL * |F(0)| or the secant
   through the two newest points puts the root within XTOL * v_m of the newest (the end
   point with the smaller |F| is returned), or until that secant's root lies inside the
   bracket and two estimates of its own error agree that it is within XTOL * v_m: the
   second divided difference through the three newest points gives |F''/(2 F')| est (est +
   |step|) <= XTOL v_m / 10, est its distance from the newest point and step the last one,
   and est |step| <= XTOL v_m^2 (a curvature of at most 1 / v_m); that root is returned
   without evaluating F there (one evaluation fewer in about half the annuli). Its first
   step interpolates through the bracket ends and the extra-scan point of step 5 (which
   lies beyond the bracket with the sign of F at its near end), so that evaluation also
   speeds the refinement. Every iterate (and the secant's root) stays in the bracket of
   step 2, so the root selected is that of the rule whatever the refinement (the NumPy
   reference refines with the Illinois method and selects the same roots).
5. Multiple roots are flagged when F changes sign again within EXTRA_SCAN further
   march steps beyond the bracket, or where F grazes zero on the march: where the parabola
   through three successive march points (F of the march's sign at the older two) is convex
   with its minimum between the outer two and within GRAZE |F(0)| of zero, F is evaluated at
   that minimum, and a sign change there (a pair of roots between two march points, which
   the march steps over: the selected root then jumps where the pair appears, a user-level
   physics audit, 2026-11-28) raises the flag; where the newest point has changed sign and the
   parabola turns back before it, F is evaluated as far beyond it as the minimum lies before
   it, and F of its first sign there raises the flag (past MAX_MARCH the parabola alone). The
   bracket is not moved, so the root selected is the same.

``solve_annuli`` runs these steps for all annuli of an operating point in lockstep (one
residual sweep over the active annuli, then one state-machine step each), which gives
the same iterates as a per-annulus loop (tested against the NumPy reference) but lets
the CPU overlap the independent evaluations.
"""

from __future__ import annotations

import numba
import numpy as np

from ._fastmath import atan2_poly, exp_sat, make_exp_wide
from ._jitcache import CACHE  # before the decorators: installs the cache locators
from ._physics import (CAMBERED, GILL_SINCOS, NODE_CFAC, NODE_CH, NODE_CT, NODE_CY2, NODE_MFAC, NODE_Y, PK_DYNSTALL,
                       PK_INPLANE, cambered_annulus, inverse_sin_phi, make_cambered_element,
                       make_delayed_cambered_element, make_element, make_loss_factor, make_prandtl, make_stall_blend)
from ._momentum import (empirical_k, inflow_gradients, inplane_induction, make_axial_mass_flow, momentum_scale,
                        momentum_thrust, skew_inflow_ratio, swirl_step, swirl_target)

MARCH_STEPS = 3.0
MAX_MARCH = 64
MAX_DOUBLING = 80
EXTRA_SCAN = 1
#: the march flags multiple roots where the parabola through three successive march points has its minimum between
#: them within this fraction of |F(0)| of zero (step 5 above; docs/solver.md, Flags)
GRAZE = 0.01
MAX_REFINE = 100
XTOL = 1e-7
FTOL = 1e-9

# status codes of one annulus
OK = 0
NO_BRACKET = 1
NO_CONVERGENCE = 2
NO_SWIRL_BALANCE = 3  # the swirl iteration (_momentum.swirl_target) did not balance within SWIRL_MAX_ITER solves

_FM = {"nsz", "arcp", "contract", "afn", "reassoc"}  # keeps inf/NaN semantics
# The helpers are compiled once each and inlined by LLVM (forceinline), not copied into their callers' numba IR
# (inline="always"), which numba redid at every call site and which was most of the kernels' first compile (2026-11-28,
# 2-core AMD EPYC: 429 -> 174 s for the six kernel families, tools/compile_times.py; benchmarks/README.md). Kept in
# numba's IR: the helpers that take arrays and run inside the vectorised loops (_element, _residual here,
# _sensitivity._add_node, _parameter_sensitivity._stored_state): _element as a call, even one LLVM inlines, ran
# forward flight 1.75x slower, and with its eight parameters as scalars instead of the array 1.04x and 1.09x slower
# with no shorter compile (2-core Intel Xeon, the same evening); the other three kept by the same rule, not measured.
_jit_inline = numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
# polynomial atan2/exp: no libm calls, so the azimuth loops below compile to SIMD code
_atan2 = _jit_inline(atan2_poly)
_exp_sat = _jit_inline(exp_sat)
# eq (3)'s stall blend with one exponential per element (_physics.make_stall_blend)
_exp_wide = _jit_inline(make_exp_wide(_exp_sat))
_stall_blend = _jit_inline(make_stall_blend(_exp_sat, _exp_wide))
_element_gill = _jit_inline(make_element(_atan2, _stall_blend))
_element_cambered = _jit_inline(make_cambered_element(_atan2, _stall_blend))
# the elements with their profile drag C_D,p U as a third value (the implicit derivatives' radial drag)
_element_gill_p = _jit_inline(make_element(_atan2, _stall_blend, profile=True))
_element_cambered_p = _jit_inline(make_cambered_element(_atan2, _stall_blend, profile=True))
# the cambered element with Gormont's dynamic stall, a node and its mirror node (RotorOptions.dynamic_stall): their
# means (the loads' half differences too: _annulus_loads)
_element_cambered_d = _jit_inline(make_delayed_cambered_element(_atan2, _exp_sat))
_prandtl = _jit_inline(make_prandtl(_atan2, _exp_sat))
_loss_factor = _jit_inline(make_loss_factor(_prandtl))
_inverse_sin_phi = _jit_inline(inverse_sin_phi)
_momentum_thrust = _jit_inline(momentum_thrust)
_momentum_scale = _jit_inline(momentum_scale)
_cambered_annulus = _jit_inline(cambered_annulus)
_inflow_gradients = _jit_inline(inflow_gradients)
_skew_inflow_ratio = _jit_inline(skew_inflow_ratio)
_empirical_k = _jit_inline(empirical_k)
_axial_mass_flow = _jit_inline(make_axial_mass_flow(_empirical_k))
_swirl_target = _jit_inline(swirl_target)
_swirl_step = _jit_inline(swirl_step)
_inplane_induction = _jit_inline(inplane_induction)


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)  # in numba's IR: above
def _element(UT, UP, th, sth, cth, s0, s1, s2, s3, model, pk):
    """Either model's element (scalar): the loads pass and the tests; the residual loops
    branch outside the element instead (docs/models.md, Cost)."""
    if model == CAMBERED:
        return _element_cambered(UT, UP, th, sth, cth, s0, s1, s2, s3, pk[0], pk[1], pk[2], pk[3], pk[4], pk[5],
                                 pk[6], pk[7])
    return _element_gill(UT, UP, th, sth, cth, s0, pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], model == GILL_SINCOS)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def delay_factor(pk, Om, y, cy2):
    """Gormont's kd = gamma sqrt(c Omega / 2) [m^0.5 s^-0.5] of an annulus of radius y [m] and
    (c/y)^2 ``cy2`` at Omega [rad/s] (0 without RotorOptions.dynamic_stall): the delayed
    element's per-annulus factor (_physics.make_delayed_cambered_element)."""
    if pk[PK_DYNSTALL] == 0.0:
        return 0.0
    return pk[PK_DYNSTALL] * np.sqrt(0.5 * y * np.sqrt(cy2) * Om)


@numba.njit(inline="always", error_model="numpy", fastmath=_FM)  # in numba's IR: above
def _residual(v, wy, Vs, Vc, bl, sec, cfac, mfac, floss, azim, gx, gy, naz, model, pk, emp, kd):
    """F(v) = dT_BET/dy - F_loss dT_BEMT/dy [N/m] on one annulus (eq 11); ``floss`` = F_loss(v).

    ``wy`` = Omega y - u [m/s], the blade's speed less the annulus' swirl u (0 without swirl);
    ``bl`` = (theta, sin theta, cos theta) and ``sec`` = (s0, s1, s2, s3), the annulus' blade
    angle and section constants; ``azim`` = (sin psi, cos psi) of the azimuth nodes, shape
    (2, 2 n_azimuth), of which the first ``naz`` columns are used.

    ``v`` is the annulus' mean inflow; with a linear inflow model (gx or gy non-zero) the
    element at azimuth psi_k sees v (1 + gx cos psi_k + gy sin psi_k), gx = k_x y/R,
    gy = k_y y/R, over the full circle of ``naz`` nodes. ``emp``: the momentum side uses the
    empirical axial mass flow in descent (_momentum.axial_mass_flow) instead of Glauert's.
    With ``pk[PK_INPLANE]`` = 1 (airfoil.RotorOptions.inplane_induction) the blades meet the
    in-plane airspeed Vs plus the skewed wake's in-plane induced velocity at v
    (_momentum.inplane_induction); the momentum side keeps Vs. ``kd`` > 0 (:func:`delay_factor`;
    the cambered model in a uniform inflow, RotorOptions.dynamic_stall): each half-circle node
    and its mirror node through the delayed element.
    """
    th, sth, cth = bl
    s0, s1, s2, s3 = sec
    sinpsi = azim[0]
    cospsi = azim[1]
    acc = 0.0
    UP = Vc + v
    Vm = Vs  # the momentum side's in-plane airspeed
    if pk[PK_INPLANE] != 0.0:  # the blades' (off: no square root per evaluation)
        Vs = Vs + pk[PK_INPLANE] * _inplane_induction(v, Vs, Vc)
    # one loop per section model and inflow, so that each compiles to straight-line SIMD code
    if gx == 0.0 and gy == 0.0:
        if model == CAMBERED and kd != 0.0 and Vs != 0.0:
            a0, a1, a2, a3, a4, a5, a6, a7 = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7]
            for k in range(naz):
                qT, _, _ = _element_cambered_d(wy + Vs * sinpsi[k], UP, th, sth, cth, s0, s1, s2, s3,
                                               a0, a1, a2, a3, a4, a5, a6, a7, kd, Vs * cospsi[k])
                acc += qT
        elif model == CAMBERED:
            a0, a1, a2, a3, a4, a5, a6, a7 = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7]
            for k in range(naz):
                qT, _ = _element_cambered(wy + Vs * sinpsi[k], UP, th, sth, cth, s0, s1, s2, s3,
                                          a0, a1, a2, a3, a4, a5, a6, a7)
                acc += qT
        else:
            g0, g1, g2, g3, g4, g5, sincos = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], model == GILL_SINCOS
            for k in range(naz):
                qT, _ = _element_gill(wy + Vs * sinpsi[k], UP, th, sth, cth, s0, g0, g1, g2, g3, g4, g5, sincos)
                acc += qT
    else:
        vx = v * gx
        vy = v * gy
        if model == CAMBERED:
            a0, a1, a2, a3, a4, a5, a6, a7 = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7]
            for k in range(naz):
                qT, _ = _element_cambered(wy + Vs * sinpsi[k], UP + vx * cospsi[k] + vy * sinpsi[k], th, sth,
                                          cth, s0, s1, s2, s3, a0, a1, a2, a3, a4, a5, a6, a7)
                acc += qT
        else:
            g0, g1, g2, g3, g4, g5, sincos = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], model == GILL_SINCOS
            for k in range(naz):
                qT, _ = _element_gill(wy + Vs * sinpsi[k], UP + vx * cospsi[k] + vy * sinpsi[k], th, sth, cth,
                                      s0, g0, g1, g2, g3, g4, g5, sincos)
                acc += qT
    if emp:
        w_ax = _axial_mass_flow(v, Vc, Vm)
        return cfac * acc / naz - floss * mfac * v * np.sqrt(Vm * Vm + w_ax * w_ax)
    return cfac * acc / naz - floss * _momentum_thrust(v, mfac, Vm, Vc)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _annulus_rows(nodes, blade, sect):
    """The per-annulus arrays of :func:`solve_annuli`'s packed arguments: y, cfac, mfac (rows
    of ``nodes``), theta, sin theta, cos theta (``blade``) and s0 ... s3 (``sect``)."""
    return (nodes[NODE_Y], nodes[NODE_CFAC], nodes[NODE_MFAC], blade[0], blade[1], blade[2], sect[0], sect[1], sect[2],
            sect[3])


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _residuals_axial(f, trial, nodes, blade, Om, us, Vc, sect, floss, model, pk, emp, active, n_active):
    """``_residual`` of every annulus at its trial inflow in axial flow (V sin beta = 0: one
    azimuth node), the annuli already solved included: branch-free loops over contiguous
    annuli, which compile to SIMD code across them (one annulus' residual at a time is a
    scalar chain). The empirical momentum in descent (a Newton solve per annulus) only for the
    ``n_active`` annuli in ``active``, one at a time. ``nodes``, ``blade``, ``sect`` as
    :func:`solve_annuli`; ``us``: the annuli's swirl [m/s]."""
    y, cfac, mfac, th, sth, cth, s0, s1, s2, s3 = _annulus_rows(nodes, blade, sect)
    nr = y.shape[0]
    if model == CAMBERED:
        a0, a1, a2, a3, a4, a5, a6, a7 = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], pk[6], pk[7]
        for j in range(nr):
            v = trial[j]
            qT, _ = _element_cambered(Om * y[j] - us[j], Vc + v, th[j], sth[j], cth[j], s0[j], s1[j], s2[j], s3[j],
                                      a0, a1, a2, a3, a4, a5, a6, a7)
            f[j] = cfac[j] * qT
    else:
        g0, g1, g2, g3, g4, g5, sincos = pk[0], pk[1], pk[2], pk[3], pk[4], pk[5], model == GILL_SINCOS
        for j in range(nr):
            v = trial[j]
            qT, _ = _element_gill(Om * y[j] - us[j], Vc + v, th[j], sth[j], cth[j], s0[j], g0, g1, g2, g3, g4, g5,
                                  sincos)
            f[j] = cfac[j] * qT
    if emp and Vc < 0.0:
        for q in range(n_active):
            j = active[q]
            v = trial[j]
            w_ax = _axial_mass_flow(v, Vc, 0.0)
            f[j] -= floss[j] * mfac[j] * v * np.sqrt(w_ax * w_ax)
    elif emp:  # Glauert's mass flow |Vc + v| outside descent, written as _residual writes it
        for j in range(nr):
            v = trial[j]
            w_ax = abs(Vc + v)
            f[j] -= floss[j] * mfac[j] * v * np.sqrt(w_ax * w_ax)
    else:
        for j in range(nr):
            f[j] -= floss[j] * _momentum_thrust(trial[j], mfac[j], 0.0, Vc)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _false_position(a, fa, b, fb):
    """Zero of the secant through (a, fa), (b, fb); fa * fb < 0."""
    return (a * fb - b * fa) / (fb - fa)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _chandrupatla_t(x1, f1, x2, f2, x3, f3, tol):
    """Fraction t of the next iterate x1 + t (x2 - x1) in Chandrupatla's method.

    (x1, f1) is the newest point, (x2, f2) the other end of the bracket (f1 f2 < 0) and
    (x3, f3) the point dropped last (beyond the bracket, f3 of the sign of f1). Inverse
    quadratic interpolation where the three points admit a monotone one, else bisection;
    t is kept tol / 2 away from the ends. Chandrupatla, "A new hybrid quadratic/bisection
    algorithm for finding the zero of a nonlinear function without using derivatives",
    Adv. Eng. Software 28 (1997) 145-149, Fig. 1 and eq. 1.
    """
    xi = (x1 - x2) / (x3 - x2)
    phi = (f1 - f2) / (f3 - f2)
    t = 0.5
    if 1.0 - np.sqrt(1.0 - xi) < phi and phi < np.sqrt(xi):
        alpha = (x3 - x1) / (x2 - x1)
        t = f1 / (f1 - f2) * f3 / (f3 - f2) - alpha * f1 / (f3 - f1) * f2 / (f2 - f3)
    tl = 0.5 * tol / abs(x2 - x1)
    return min(max(t, tl), 1.0 - tl)


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _secant_error(x1, f1, x2, f2, x3, f3, est, step):
    """Error estimate of the secant's root through (x1, f1), (x2, f2): |F''/(2 F')| est (est +
    |step|), F''/2 the second divided difference through the three points, est the root's
    distance from x1 and step = x1 - x2 (NaN where two points coincide)."""
    d1 = (f1 - f2) / (x1 - x2)
    d2 = (d1 - (f2 - f3) / (x2 - x3)) / (x1 - x3)
    return abs(d2 / d1) * est * (est + abs(step))


# phases of one annulus' root solve (solve_annuli)
_INIT = 0
_MARCH = 1
_DOUBLE = 2
_SCAN = 3
_REFINE = 4
_PROBE_MARCH = 5  # F at a grazing parabola's minimum, then the march goes on (c holds its next trial)
_PROBE_CROSS = 6  # F beyond a grazing sign change, then the extra scan


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)
def solve_annuli(Om, Vs, Vc, nodes, blade, us, sect, azim, grad, naz, model, pk, emp, v, status, multiple):
    """Roots of eq (11) on every annulus of one operating point, by the module's rule.

    The annuli are independent, so they are solved in lockstep: each sweep evaluates
    F at the trial inflow of every annulus still active, then advances each annulus'
    state machine (march, doubling, extra scan, Illinois) by one step. Step for step
    this is the scalar algorithm of the module docstring, but the evaluations of one
    sweep do not wait on each other, so the CPU overlaps them (one F(v) at a time is
    latency-bound). ``nodes`` (N_NODE_ROWS, nr): the blade's node rows (_physics.NODE_Y ...,
    core/nodes.py; the blade angle's rows are not read); ``blade`` (3, nr): this point's blade
    angle theta and its sine and cosine; ``us`` (nr,): the annuli's swirl u [m/s], subtracted
    from the blade speed Omega y (zeros without swirl); ``sect`` (4, nr): the section constants
    s0 ... s3 at this point; ``azim`` (2, 2 naz_half): sin psi and cos psi of the azimuth nodes;
    ``grad`` (2, nr): the linear inflow's gx, gy (zeros: uniform). Outputs: v (nr,) [m/s],
    ``status`` (2, nr) int64, the rows code (OK, NO_BRACKET, NO_CONVERGENCE) and nev (residual
    evaluations), and multiple (nr,) (more roots seen).
    """
    y, cfac, mfac, th, sth, cth, s0, s1, s2, s3 = _annulus_rows(nodes, blade, sect)
    ct = nodes[NODE_CT]
    ch = nodes[NODE_CH]
    gx = grad[0]
    gy = grad[1]
    code = status[0]
    nev = status[1]
    nr = y.shape[0]
    # the annuli's state in two blocks: two allocations per call instead of 20 (2026-11-27, tools/ab_kernel.py in
    # six processes: axial flow 0.96-0.98 the cost per point, forward flight 0.98-1.02, within the processes' spread)
    # (rows by index, not by unpacking the block: numba types an unpacked row as non-contiguous)
    fw = np.zeros((15, nr))
    trial, f, a, fa, b, fb, c, fc = fw[0], fw[1], fw[2], fw[3], fw[4], fw[5], fw[6], fw[7]
    sgn, h, xtol, ftol, floss, inv_sin, kds = fw[8], fw[9], fw[10], fw[11], fw[12], fw[13], fw[14]
    floss[:] = 1.0  # kds: Gormont's per-annulus factor (RotorOptions.dynamic_stall), 0 without it
    iw = np.zeros((5, nr), dtype=np.int64)
    phase, k, kb, cnt, active = iw[0], iw[1], iw[2], iw[3], iw[4]
    for j in range(nr):
        active[j] = j
    if pk[PK_DYNSTALL] != 0.0 and Vs != 0.0:
        cy2 = nodes[NODE_CY2]
        for j in range(nr):
            kds[j] = delay_factor(pk, Om, y[j], cy2[j])
    tip = ct[0] >= 0.0  # the switches hold for all annuli
    hub = ch[0] >= 0.0
    # axial flow (one node, uniform inflow): all annuli's blade elements in one vectorised loop, the solved
    # ones recomputed harmlessly (their roots are already stored)
    vector_axial = naz == 1 and Vs == 0.0 and gx[0] == 0.0 and gy[0] == 0.0
    for j in range(nr):
        nev[j] = 0
        multiple[j] = False
        code[j] = OK
    n_active = nr
    while n_active > 0:
        if tip or hub:
            # the loss factor at every trial first, in branch-free loops of their own over all
            # annuli (contiguous, so they vectorise; inside each residual it is a long scalar
            # chain). Annuli already solved are recomputed harmlessly.
            if emp and Vc < 0.0:
                # empirical descent: the vortex sheets are carried by the mass-flow velocity of
                # the closure (_momentum.axial_mass_flow), not by U_P, which passes through 0 near
                # the annulus' ideal autorotation and would make F(v) jump there (several roots)
                for j in range(nr):
                    inv_sin[j] = _inverse_sin_phi(_axial_mass_flow(trial[j], Vc, Vs), Om * y[j] - us[j])
            else:
                for j in range(nr):
                    inv_sin[j] = _inverse_sin_phi(Vc + trial[j], Om * y[j] - us[j])
            if tip:
                for j in range(nr):
                    floss[j] = _prandtl(ct[j], inv_sin[j])
            if hub:
                for j in range(nr):
                    floss[j] = (floss[j] if tip else 1.0) * _prandtl(ch[j], inv_sin[j])
        if vector_axial:  # every annulus, solved or not, in one SIMD loop
            _residuals_axial(f, trial, nodes, blade, Om, us, Vc, sect, floss, model, pk, emp, active, n_active)
            for q in range(n_active):
                nev[active[q]] += 1
        else:
            for q in range(n_active):  # independent evaluations
                j = active[q]
                f[j] = _residual(trial[j], Om * y[j] - us[j], Vs, Vc, (th[j], sth[j], cth[j]),
                                 (s0[j], s1[j], s2[j], s3[j]), cfac[j], mfac[j], floss[j], azim, gx[j], gy[j], naz,
                                 model, pk, emp, kds[j])
                nev[j] += 1
        m = 0
        for q in range(n_active):
            j = active[q]
            fj = f[j]
            ph = phase[j]
            refine = False
            done = False
            again = False  # the extra scan saw a second sign change (no third point for the first step)
            if ph == _INIT:
                if fj == 0.0:
                    v[j] = 0.0
                    done = True
                else:
                    sgn[j] = 1.0 if fj > 0.0 else -1.0
                    vm = _momentum_scale(fj, mfac[j], Vs, Vc)
                    if ct[j] >= 0.0 or ch[j] >= 0.0:
                        # the loss factor F scales the momentum side: size the march with F at
                        # the loss-free estimate (F falls with v, so this still undershoots)
                        vm = _momentum_scale(fj, mfac[j] * _loss_factor(Vc + sgn[j] * vm, Om * y[j] - us[j], ct[j],
                                                                        ch[j]), Vs, Vc)
                    if emp and Vc < 0.0:
                        # the empirical closure's root lies near the annulus' hover inflow (vortex
                        # ring) or below it (windmill brake): a march sized by it brackets the one root
                        vm = max(vm, np.sqrt(abs(fj) / mfac[j]))
                    h[j] = vm / MARCH_STEPS
                    xtol[j] = XTOL * vm
                    ftol[j] = FTOL * abs(fj)
                    fa[j] = fj
                    fb[j] = fj
                    fc[j] = fj  # (during the march: F at the march point before the previous one)
                    k[j] = 1
                    phase[j] = _MARCH
                    trial[j] = sgn[j] * h[j]
            elif ph == _MARCH:
                # the parabola through the three newest march points (s F > 0 at the older two): convex, with its
                # minimum between the outer points and within GRAZE |F(0)| of zero, F may graze zero there (a pair
                # of roots between two march points, which the march steps over); t its minimum's place from the
                # middle point in steps
                t = 2.0  # (none)
                if k[j] >= 2:
                    g0, g1, g2 = sgn[j] * fc[j], sgn[j] * fa[j], sgn[j] * fj
                    d2 = g2 - 2.0 * g1 + g0
                    if (d2 > 0.0 and abs(g0 - g2) < 2.0 * d2
                            and g1 - (g2 - g0) * (g2 - g0) / (8.0 * d2) <= GRAZE * ftol[j] / FTOL):
                        t = (g0 - g2) / (2.0 * d2)
                b[j] = trial[j]
                fb[j] = fj
                if fj * sgn[j] <= 0.0:
                    kb[j] = k[j]
                    if t < 1.0 and EXTRA_SCAN > 0:
                        # a sign change where the parabola already turns back: F beyond it, mirrored
                        # about the new point, then the extra scan
                        phase[j] = _PROBE_CROSS
                        trial[j] = 2.0 * b[j] - (a[j] + sgn[j] * t * h[j])  # (a: the middle point)
                    elif EXTRA_SCAN > 0:
                        phase[j] = _SCAN
                        cnt[j] = 1
                        trial[j] = sgn[j] * (kb[j] + 1) * h[j]
                    else:
                        refine = True
                else:
                    fc[j] = fa[j]
                    a[j] = b[j]
                    fa[j] = fj
                    k[j] += 1
                    if k[j] > MAX_MARCH:
                        phase[j] = _DOUBLE
                        cnt[j] = 0
                        trial[j] = 2.0 * b[j]
                        if t < 1.0:
                            multiple[j] = True  # (not probed: the march has ended)
                    elif t < 1.0:  # F at the parabola's minimum, then the march's next point
                        phase[j] = _PROBE_MARCH
                        c[j] = sgn[j] * k[j] * h[j]
                        trial[j] = b[j] + sgn[j] * (t - 1.0) * h[j]  # (b: the newest point, one step past the middle)
                    else:
                        trial[j] = sgn[j] * k[j] * h[j]
            elif ph == _PROBE_MARCH:
                if fj * sgn[j] <= 0.0:
                    multiple[j] = True  # a pair of roots between two march points, stepped over
                phase[j] = _MARCH
                trial[j] = c[j]
            elif ph == _PROBE_CROSS:
                if fj * sgn[j] > 0.0:
                    multiple[j] = True  # F back to its first sign beyond the sign change: more roots
                phase[j] = _SCAN
                cnt[j] = 1
                trial[j] = sgn[j] * (kb[j] + 1) * h[j]
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
                    again = True
                    refine = True
                else:
                    c[j] = trial[j]  # beyond the bracket, F of the sign of F(b): seeds the interpolation
                    fc[j] = fj
                    cnt[j] += 1
                    if cnt[j] > EXTRA_SCAN:
                        refine = True
                    else:
                        trial[j] = sgn[j] * (kb[j] + cnt[j]) * h[j]
            else:  # _REFINE: Chandrupatla on the bracket [a, b], fa * fb < 0, b the newest point
                # the secant through the two newest points estimates the root (xs) and its distance from the
                # newest point (est); the three newest points (trial, b, c) the secant root's own error
                # (_secant_error), computed only where the cheap estimate est |step| / v_m is within xtol
                step = trial[j] - b[j]
                dx = fj * step / (fj - fb[j])
                est = abs(dx)
                xs = trial[j] - dx
                tb, fbo, tc, fco = b[j], fb[j], c[j], fc[j]  # (the error estimate's, below)
                if fj * fb[j] > 0.0:
                    c[j] = b[j]
                    fc[j] = fb[j]
                else:
                    c[j] = a[j]
                    fc[j] = fa[j]
                    a[j] = b[j]
                    fa[j] = fb[j]
                b[j] = trial[j]
                fb[j] = fj
                if abs(fj) <= ftol[j] or abs(b[j] - a[j]) <= xtol[j] or est <= xtol[j]:
                    v[j] = b[j] if abs(fb[j]) <= abs(fa[j]) else a[j]
                    done = True
                elif (est * abs(step) <= xtol[j] * xtol[j] / XTOL and min(a[j], b[j]) < xs < max(a[j], b[j])
                      and _secant_error(trial[j], fj, tb, fbo, tc, fco, est, step) <= 0.1 * xtol[j]):
                    v[j] = xs  # the secant's root, unevaluated: by both estimates within xtol
                    done = True
                else:
                    cnt[j] += 1
                    if cnt[j] >= MAX_REFINE:
                        v[j] = b[j]
                        code[j] = NO_CONVERGENCE
                        done = True
                    else:
                        trial[j] = b[j] + _chandrupatla_t(b[j], fb[j], a[j], fa[j], c[j], fc[j],
                                                          xtol[j]) * (a[j] - b[j])
            if refine:
                if fb[j] == 0.0:
                    v[j] = b[j]
                    done = True
                else:
                    phase[j] = _REFINE
                    cnt[j] = 0
                    if ph == _SCAN and not again:
                        trial[j] = b[j] + _chandrupatla_t(b[j], fb[j], a[j], fa[j], c[j], fc[j],
                                                          xtol[j]) * (a[j] - b[j])
                    else:  # no third point of the right sign: a secant step first
                        c[j] = a[j]  # (the third point of the first error estimate)
                        fc[j] = fa[j]
                        tl = 0.5 * xtol[j] / abs(a[j] - b[j])
                        t = min(max(fb[j] / (fb[j] - fa[j]), tl), 1.0 - tl)
                        trial[j] = b[j] + t * (a[j] - b[j])
            if not done:
                active[m] = j
                m += 1
        n_active = m
