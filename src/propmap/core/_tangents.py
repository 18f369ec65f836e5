"""The blade elements with their analytic partial derivatives (forward mode, by hand).

The implicit derivatives (core/_sensitivity.py) need, at every azimuth node of an annulus
at its converged root, the element's loads and their partial derivatives with respect to
U_T, U_P, the blade angle and the annulus' section constants. Until 2026-11-25 they were
one-sided differences, an element evaluation per direction (four per node for the three
inputs and the inflow, five with the collective). Here one evaluation gives the loads and
every partial: the element's own terms (those of _physics.make_element /
make_cambered_element; a few products are grouped differently, so the loads agree with the
element's to rounding, 1e-13 relative in the tests, not to the bit) carried with their
derivatives along each direction,

* U_T and U_P: dU = U_T / U, U_P / U; the angle of attack alpha = theta - phi, with
  phi = atan2(U_P, U_T), moves by +U_P / U^2 and -U_T / U^2, and sin(alpha), cos(alpha) by
  cos(alpha) dalpha and -sin(alpha) dalpha (the element takes them from U_T, U_P and the
  blade angle: U cos phi = U_T, U sin phi = U_P exactly);
* the blade angle: dalpha = 1;
* the section constants of the cambered polar (lift slope, drag factor, stall-angle factor,
  zero-lift shift) along a given direction (their change with the annulus' mean square speed,
  _sensitivity._constants_slopes): the angle from the zero-lift line moves by minus the
  shift's change, the chord's angle not at all;
* the cambered polar's constants pk[:8] and the section constants together
  (:func:`make_cambered_direction`: a section parameter's or the air density's step), every
  direction from one evaluation of the element's state at the node.

The stall blend s = 1 - 1 / ((1 + p)(1 + q)) moves by (dp (1 + q) + (1 + p) dq) / ((1 + p)
(1 + q))^2 with dp = M p (da_e - dg a_stall+), dq = -M q (da_e - dg a_stall-); where the
exponential saturates (|exponent| >= 40, _fastmath.exp_sat) this is M e^-40 of the blend's
range instead of 0. The blend is evaluated here as p and q, two exponentials (the element
since 2026-11-27 takes one, _physics.make_stall_blend: the same sigma to 1e-13); beyond them
one atan2 and one sqrt (the paper's section's Blasius term one more sqrt), so the partials
cost arithmetic only (the tangent-linear, or forward, mode of A. Griewank and A. Walther,
"Evaluating Derivatives", 2nd ed., SIAM, 2008, Ch. 3, applied by hand). Checked against
central differences of the element (tests/test_derivatives.py) and, through the implicit
derivatives, against the solver.
"""

from __future__ import annotations

import numpy as np

from ._physics import DELAY_MAX, exp_sat_numpy

TWO_PI = 2.0 * np.pi


def _loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, dUT, dUP, dU, dCL, dCD, dcdp):
    """The derivatives of qT = U (C_L U_T - C_D U_P), qH = U (C_L U_P + C_D U_T) and the profile
    drag's C_D,p U along one direction, from those of U_T, U_P, U, C_L, C_D and C_D,p
    (FT, FH: the brackets)."""
    dqT = dU * FT + U * (dCL * UT + CL * dUT - dCD * UP - CD * dUP)
    dqH = dU * FH + U * (dCL * UP + CL * dUP + dCD * UT + CD * dUT)
    return dqT, dqH, dcdp * U + cdp * dU


def make_cambered_direction(atan2, exp_sat, loads_tangent):
    """Return ``(state, direction)`` for the cambered element's derivatives along any direction in
    its section constants and polar constants (a section parameter's or the air density's step),
    using the given arctangent, saturated exp and :func:`_loads_tangent`: ``state`` evaluates the
    element once at a node, ``direction`` gives the derivative of its loads along one direction
    from that state (arithmetic only), so that many directions share one evaluation."""

    def state(UT, UP, theta, sin_th, cos_th, sec, con):
        """The cambered element's terms at one node (arguments as :func:`make_cambered_tangent`'s
        ``cambered_tangent``), packed for ``direction`` (N_STATE values)."""
        a, cdf, g, dal0 = sec
        alpha_L0, cd90, cd_min, cd2, cl_cdmin, M, asp, asn = con
        U = np.sqrt(UT * UT + UP * UP + 1e-300)
        ae = theta - (alpha_L0 + dal0) - atan2(UP, UT)
        ae = ae - TWO_PI * (ae > np.pi) + TWO_PI * (ae < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        zp = ae - g * asp
        zq = ae - g * asn
        p = exp_sat(M * zp)
        q = exp_sat(-M * zq)
        P = 1.0 + p
        Q = 1.0 + q
        s = 1.0 - 1.0 / (P * Q)
        cl_att = a * ae
        dcl = cl_att - cl_cdmin
        sc = sin_a * cos_a
        s2 = sin_a * sin_a
        CL = (1.0 - s) * cl_att + s * cd90 * sc
        inner = cd_min + (1.0 - s) * cd2 * dcl * dcl
        cdp = cdf * inner
        CD = cdp + s * cd90 * s2
        w = 1.0 / (P * Q * P * Q)
        return (U, UT, UP, CL, CD, CL * UT - CD * UP, CL * UP + CD * UT, cdp, ae, zp, zq, p * Q * w, q * P * w, s,
                cl_att, dcl, sc, s2, inner, a, cdf, g, cd90, cd2, M, asp, asn, cos_a * cos_a - s2)

    def direction(st, dsec, dcon):
        """The derivatives of (qT, qH [m^2/s^2], C_D,p U [m/s]) along ``dsec`` (4: the section
        constants, as ``cambered_tangent``'s) and ``dcon`` (8: the polar's constants, pk[:8])
        at the node of ``st`` (``state``'s), per unit of the direction."""
        (U, UT, UP, CL, CD, FT, FH, cdp, ae, zp, zq, pw, qw, s, cl_att, dcl, sc, s2, inner, a, cdf, g, cd90, cd2, M,
         asp, asn, _) = st
        da, dcdf, dg, ddal0 = dsec
        d_aL0, d_cd90, d_cd_min, d_cd2, d_cl_cdmin, d_M, d_asp, d_asn = dcon
        dae = -(d_aL0 + ddal0)
        # ds = (dp Q + P dq) / (PQ)^2, dp = p d(M zp), dq = -q d(M zq)
        ds = pw * (d_M * zp + M * (dae - dg * asp - g * d_asp)) - qw * (d_M * zq + M * (dae - dg * asn - g * d_asn))
        dcla = da * ae + a * dae
        dCL = -ds * cl_att + (1.0 - s) * dcla + (d_cd90 * s + cd90 * ds) * sc
        dinner = d_cd_min - ds * cd2 * dcl * dcl + (1.0 - s) * dcl * (d_cd2 * dcl + 2.0 * cd2 * (dcla - d_cl_cdmin))
        dcdp = dcdf * inner + cdf * dinner
        dCD = dcdp + (d_cd90 * s + cd90 * ds) * s2
        return loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 0.0, 0.0, 0.0, dCL, dCD, dcdp)

    return state, direction


def make_cambered_tangent(state, direction, loads_tangent):
    """Return the cambered element with its partials, from :func:`make_cambered_direction`'s
    ``state`` and ``direction`` and :func:`_loads_tangent` (each back end's own)."""
    zero = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)

    def cambered_tangent(UT, UP, theta, sin_th, cos_th, sec, dsec, con):
        """The cambered polar's element (_physics.make_cambered_element with ``profile``) and
        its partial derivatives.

        Parameters
        ----------
        UT, UP, theta, sin_th, cos_th : float
            As for the element [m/s, rad].
        sec : tuple of 4 float
            The annulus' section constants (lift slope [1/rad], drag factor [-], stall-angle
            factor [-], zero-lift shift [rad]).
        dsec : tuple of 4 float
            A direction in those constants (their change for a step of the annulus' mean
            square speed).
        con : tuple of 8 float
            The polar's constants alpha_L0, cd90, cd_min, cd2, cl_cdmin, M and the stall angles
            above and below the zero-lift line (pk[:8]).

        Returns
        -------
        base, d_UT, d_UP, d_sec, d_theta : tuple of 3 float each
            (qT [m^2/s^2], qH [m^2/s^2], C_D,p U [m/s]) and their derivatives with respect to
            U_T and U_P (per m/s), along ``dsec`` (per unit of it) and with respect to the
            blade angle (per rad).
        """
        st = state(UT, UP, theta, sin_th, cos_th, sec, con)
        (U, _, _, CL, CD, FT, FH, cdp, _, _, _, pw, qw, s, cl_att, dcl, sc, s2, _, a, cdf, _, cd90, cd2, M, _, _,
         c2) = st
        # U_T, U_P and the blade angle move alpha and the angle from the zero-lift line alike (dalpha = dae) and leave
        # the constants: ds, dC_L, dC_D, dC_D,p per unit dalpha (c2 = d(sin a cos a) / dalpha)
        ds = M * (pw - qw)
        dCLa = -ds * cl_att + (1.0 - s) * a + cd90 * (ds * sc + s * c2)
        dcdpa = cdf * cd2 * dcl * (2.0 * (1.0 - s) * a - ds * dcl)
        dCDa = dcdpa + cd90 * (ds * s2 + 2.0 * s * sc)
        U2 = U * U
        at = UP / U2  # dalpha/dU_T
        ap = -UT / U2  # dalpha/dU_P
        d_ut = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 1.0, 0.0, UT / U, dCLa * at, dCDa * at, dcdpa * at)
        d_up = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 0.0, 1.0, UP / U, dCLa * ap, dCDa * ap, dcdpa * ap)
        d_th = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 0.0, 0.0, 0.0, dCLa, dCDa, dcdpa)
        return (U * FT, U * FH, cdp * U), d_ut, d_up, direction(st, dsec, zero), d_th

    return cambered_tangent


def make_gill_tangent(atan2, exp_sat, loads_tangent):
    """Return the paper's element (eqs 3-4) with its partials, using the given arctangent,
    saturated exp and :func:`_loads_tangent`."""

    def gill_tangent(UT, UP, theta, sin_th, cos_th, kre, con, sincos):
        """The paper's element (_physics.make_element with ``profile``) and its partials.

        Parameters
        ----------
        UT, UP, theta, sin_th, cos_th : float
            As for the element [m/s, rad].
        kre : float
            The annulus' Blasius factor [sqrt(m/s)] (no Reynolds terms: no direction in it).
        con : tuple of 6 float
            cl1, cl2, cd, alpha0, M, cd0 (pk[:6]).
        sincos : bool
            Footnote 1's sin-cos lift instead of eq (3).

        Returns
        -------
        base, d_UT, d_UP, d_theta : tuple of 3 float each
            As :func:`make_cambered_tangent`'s, without the constants' direction.
        """
        cl1, cl2, cd, alpha0, M, cd0 = con
        U2 = UT * UT + UP * UP + 1e-300
        U = np.sqrt(U2)
        alpha = theta - atan2(UP, UT)
        alpha = alpha - TWO_PI * (alpha > np.pi) + TWO_PI * (alpha < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        sc = sin_a * cos_a
        s2 = sin_a * sin_a
        c2 = cos_a * cos_a - s2
        post = cl2 * sc
        if sincos:
            CL = post
            dCLa = cl2 * c2
        else:
            p = exp_sat(M * (alpha - alpha0))
            q = exp_sat(-M * (alpha + alpha0))
            P = 1.0 + p
            Q = 1.0 + q
            s = 1.0 - 1.0 / (P * Q)
            ds = M * (p * Q - q * P) / (P * Q * P * Q)
            CL = (1.0 - s) * cl1 * alpha + s * post
            dCLa = ds * (post - cl1 * alpha) + (1.0 - s) * cl1 + s * cl2 * c2
        rU = 1.0 / np.sqrt(U)
        cdp = kre * rU + cd0
        CD = cd * s2 + cdp
        FT = CL * UT - CD * UP
        FH = CL * UP + CD * UT
        base = (U * FT, U * FH, cdp * U)
        dCDa = 2.0 * cd * sc
        kU = -0.5 * kre * rU / U  # dC_D,p/dU
        at = UP / U2
        ap = -UT / U2
        ut = UT / U
        up = UP / U
        d_ut = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 1.0, 0.0, ut, dCLa * at, dCDa * at + kU * ut, kU * ut)
        d_up = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 0.0, 1.0, up, dCLa * ap, dCDa * ap + kU * up, kU * up)
        d_th = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, 0.0, 0.0, 0.0, dCLa, dCDa, 0.0)
        return base, d_ut, d_up, d_th

    return gill_tangent


def make_delayed_direction(atan2, exp_sat, loads_tangent):
    """Return ``(state, direction)`` for the cambered element with Gormont's dynamic stall
    (_physics.make_delayed_cambered_element, node and mirror node together), its pair's mean
    loads and their half difference, along any direction, using the given arctangent,
    saturated exp and :func:`_loads_tangent`.

    The delayed element reads the static polar with the mean of two blends, s = 1 - A / Q with
    A = (1 / P1 + 1 / P2) / 2, P1 = 1 + exp(M z1), P2 = 1 + exp(M z2), Q = 1 + exp(-M zq),
    z1 = ae - g a_pos - d (rising), z2 = ae - g a_pos + d / 2 (falling), zq = ae - g a_neg, and
    the half difference hs = (1 / P2 - 1 / P1) / (2 Q). Along a direction, with w1 = p1 / (2 P1^2
    Q), w2 = p2 / (2 P2^2 Q), wq = A q / Q^2 and hq = hA q / Q^2 (hA = (1 / P2 - 1 / P1) / 2):
    ds = w1 d(M z1) + w2 d(M z2) - wq d(M zq) and dhs = w1 d(M z1) - w2 d(M z2) + hq d(M zq).
    C_L, C_D and C_D,p are linear in the blend (their slopes in it C_L,s = cd90 sin a cos a -
    C_L,att, C_D,p,s = -cdf cd2 (C_L,att - cl_cdmin)^2, C_D,s = C_D,p,s + cd90 sin^2 a), so the
    half difference's coefficients are hs times those slopes. The delay d = kd sqrt(|U_P vcos|)
    / U^1.5 (below DELAY_MAX; constant above it) moves with U_T by -1.5 d U_T / U^2, with U_P by
    d (1 / (2 U_P) - 1.5 U_P / U^2) (unbounded as U_P -> 0, where d -> 0: taken as 0 at U_P = 0),
    and with ln kd and ln vcos by d and d / 2.
    """

    def state(UT, UP, theta, sin_th, cos_th, sec, con, kd, vcos):
        """The delayed element's terms at one node (``sec``, ``con`` as :func:`make_cambered_tangent`'s
        ``cambered_tangent``; ``kd`` [m^0.5 s^-0.5] and ``vcos`` [m/s] as the delayed element's),
        packed for ``direction`` as three tuples (of 7, 23 and 19 values: a tuple of more than 30
        compiles to a list in CPython 3.11, which numba does not take back); the first holds the
        loads (qT, qH, C_D,p U) and their half difference (rising less falling, halved), then the
        delay's change per unit ln kd (d below DELAY_MAX, else 0) [rad]."""
        a, cdf, g, dal0 = sec
        alpha_L0, cd90, cd_min, cd2, cl_cdmin, M, asp, asn = con
        # (the static state's first lines, as every element's: sharing them would need one more injected function)
        U = np.sqrt(UT * UT + UP * UP + 1e-300)
        ae = theta - (alpha_L0 + dal0) - atan2(UP, UT)
        ae = ae - TWO_PI * (ae > np.pi) + TWO_PI * (ae < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        raw = kd * np.sqrt(np.abs(UP * vcos)) / (U * np.sqrt(U))
        free = 1.0 * (raw < DELAY_MAX)  # the delay's partials vanish where it is bounded
        d = np.minimum(raw, DELAY_MAX)
        dfree = d * free
        d_ut = -1.5 * dfree * UT / (U * U)
        d_up = dfree * (0.5 / (UP + 1.0 * (UP == 0.0)) - 1.5 * UP / (U * U))
        x = ae - g * asp
        z1 = x - d
        z2 = x + 0.5 * d
        zq = ae - g * asn
        p1 = exp_sat(M * z1)
        p2 = exp_sat(M * z2)
        q = exp_sat(-M * zq)
        P1 = 1.0 + p1
        P2 = 1.0 + p2
        Q = 1.0 + q
        A = 0.5 * (1.0 / P1 + 1.0 / P2)
        hA = 0.5 * (1.0 / P2 - 1.0 / P1)
        s = 1.0 - A / Q
        hs = hA / Q
        w1 = p1 / (2.0 * P1 * P1 * Q)
        w2 = p2 / (2.0 * P2 * P2 * Q)
        wq = A * q / (Q * Q)
        hq = hA * q / (Q * Q)
        cl_att = a * ae
        dcl = cl_att - cl_cdmin
        sc = sin_a * cos_a
        s2 = sin_a * sin_a
        CLs = cd90 * sc - cl_att
        cdps = -cdf * cd2 * dcl * dcl
        CDs = cdps + cd90 * s2
        CL = (1.0 - s) * cl_att + s * cd90 * sc
        inner = cd_min + (1.0 - s) * cd2 * dcl * dcl
        cdp = cdf * inner
        CD = cdp + s * cd90 * s2
        hCL = hs * CLs
        hcdp = hs * cdps
        hCD = hs * CDs
        FT = CL * UT - CD * UP
        FH = CL * UP + CD * UT
        hFT = hCL * UT - hCD * UP
        hFH = hCL * UP + hCD * UT
        return ((U * FT, U * FH, cdp * U, U * hFT, U * hFH, hcdp * U, dfree),
                (U, UT, UP, CL, CD, FT, FH, cdp, hCL, hCD, hFT, hFH, hcdp, s, hs, ae, z1, z2, zq, w1, w2, wq, hq),
                (cl_att, dcl, sc, s2, cos_a * cos_a - s2, inner, CLs, cdps, CDs, a, cdf, g, cd90, cd2, M, asp, asn,
                 d_ut, d_up))

    def direction(st, dUT, dUP, dth, dd, dsec, dcon):
        """The derivatives of the loads (qT, qH [m^2/s^2], C_D,p U [m/s]) and of their half
        difference at the node of ``st`` (``state``'s) along a direction: ``dUT``, ``dUP`` [m/s],
        ``dth`` [rad] (the blade angle), ``dd`` [rad] (the delay's change beyond U_T's and U_P's:
        ``st[0][6]`` times the change of ln kd, or of ln vcos over 2), ``dsec`` (4) and ``dcon`` (8)
        as :func:`make_cambered_direction`'s; per unit of the direction."""
        U, UT, UP, CL, CD, FT, FH, cdp, hCL, hCD, hFT, hFH, hcdp, s, hs, ae, z1, z2, zq, w1, w2, wq, hq = st[1]
        cl_att, dcl, sc, s2, c2, inner, CLs, cdps, CDs, a, cdf, g, cd90, cd2, M, asp, asn, d_ut, d_up = st[2]
        da, dcdf, dg, ddal0 = dsec
        d_aL0, d_cd90, d_cd_min, d_cd2, d_cl_cdmin, d_M, d_asp, d_asn = dcon
        dU = (UT * dUT + UP * dUP) / U
        dal = (UP * dUT - UT * dUP) / (U * U) + dth  # the angle from the chord
        dae = dal - (d_aL0 + ddal0)
        ddel = dd + d_ut * dUT + d_up * dUP
        dx = dae - dg * asp - g * d_asp
        m1 = d_M * z1 + M * (dx - ddel)
        m2 = d_M * z2 + M * (dx + 0.5 * ddel)
        mq = d_M * zq + M * (dae - dg * asn - g * d_asn)
        ds = w1 * m1 + w2 * m2 - wq * mq
        dhs = w1 * m1 - w2 * m2 + hq * mq
        dsc = c2 * dal
        ds2 = 2.0 * sc * dal
        dcla = da * ae + a * dae
        dCL = ds * CLs + (1.0 - s) * dcla + s * (d_cd90 * sc + cd90 * dsc)
        dinner = d_cd_min - ds * cd2 * dcl * dcl + (1.0 - s) * dcl * (d_cd2 * dcl + 2.0 * cd2 * (dcla - d_cl_cdmin))
        dcdp = dcdf * inner + cdf * dinner
        dCD = dcdp + ds * cd90 * s2 + s * (d_cd90 * s2 + cd90 * ds2)
        dCLs = d_cd90 * sc + cd90 * dsc - dcla
        dcdps = -(dcdf * cd2 + cdf * d_cd2) * dcl * dcl - 2.0 * cdf * cd2 * dcl * (dcla - d_cl_cdmin)
        dCDs = dcdps + d_cd90 * s2 + cd90 * ds2
        full = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, dUT, dUP, dU, dCL, dCD, dcdp)
        half = loads_tangent(U, UT, UP, hCL, hCD, hFT, hFH, hcdp, dUT, dUP, dU, dhs * CLs + hs * dCLs,
                             dhs * CDs + hs * dCDs, dhs * cdps + hs * dcdps)
        return full[0], full[1], full[2], half[0], half[1], half[2]

    return state, direction


def make_delayed_tangent(state, direction, loads_tangent):
    """Return the delayed element with its partials in U_T, U_P, the blade angle, the constants'
    direction and ln kd, from :func:`make_delayed_direction`'s ``state`` and ``direction`` and
    :func:`_loads_tangent`: the four moves that change only the angle of attack and the delay
    share their slopes in both (the constants' direction is ``direction``'s)."""

    def delayed_tangent(UT, UP, theta, sin_th, cos_th, sec, dsec, con, kd, vcos):
        """The delayed element's loads and half difference (6 values, as ``state``'s first) and
        their partials: with respect to U_T and U_P (per m/s), along ``dsec`` (per unit), with
        respect to the blade angle (per rad) and ln kd (6 values each); arguments as ``state``'s
        and ``dsec`` as :func:`make_cambered_tangent`'s."""
        st = state(UT, UP, theta, sin_th, cos_th, sec, con, kd, vcos)
        U, UT, UP, CL, CD, FT, FH, cdp, hCL, hCD, hFT, hFH, hcdp, s, hs, ae, z1, z2, zq, w1, w2, wq, hq = st[1]
        cl_att, dcl, sc, s2, c2, inner, CLs, cdps, CDs, a, cdf, g, cd90, cd2, M, asp, asn, d_ut, d_up = st[2]
        # the blends' slopes in the angle of attack (z1, z2, zq alike) and in the delay (z1 by -1, z2 by 1/2)
        s_a = M * (w1 + w2 - wq)
        h_a = M * (w1 - w2 + hq)
        s_d = M * (0.5 * w2 - w1)
        h_d = -M * (w1 + 0.5 * w2)
        # the coefficients' slopes at a fixed blend in the angle of attack (sin a cos a by c2, sin^2 a by 2 sc)
        CL_a = (1.0 - s) * a + s * cd90 * c2
        cdp_a = cdf * (1.0 - s) * cd2 * 2.0 * dcl * a
        CD_a = cdp_a + s * cd90 * 2.0 * sc
        CLs_a = cd90 * c2 - a
        cdps_a = -2.0 * cdf * cd2 * dcl * a
        CDs_a = cdps_a + cd90 * 2.0 * sc

        def move(dUT, dUP, dal, ddel):
            ds = s_a * dal + s_d * ddel
            dhs = h_a * dal + h_d * ddel
            dU = (UT * dUT + UP * dUP) / U
            full = loads_tangent(U, UT, UP, CL, CD, FT, FH, cdp, dUT, dUP, dU, CL_a * dal + ds * CLs,
                                 CD_a * dal + ds * CDs, cdp_a * dal + ds * cdps)
            half = loads_tangent(U, UT, UP, hCL, hCD, hFT, hFH, hcdp, dUT, dUP, dU, dhs * CLs + hs * CLs_a * dal,
                                 dhs * CDs + hs * CDs_a * dal, dhs * cdps + hs * cdps_a * dal)
            return full[0], full[1], full[2], half[0], half[1], half[2]

        U2 = U * U
        zero = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        return (st[0], move(1.0, 0.0, UP / U2, d_ut), move(0.0, 1.0, -UT / U2, d_up),
                direction(st, 0.0, 0.0, 0.0, 0.0, dsec, zero), move(0.0, 0.0, 1.0, 0.0), move(0.0, 0.0, 0.0, st[0][6]))

    return delayed_tangent


# the NumPy twins (tests)
cambered_state, cambered_direction = make_cambered_direction(np.arctan2, exp_sat_numpy, _loads_tangent)
cambered_tangent = make_cambered_tangent(cambered_state, cambered_direction, _loads_tangent)
gill_tangent = make_gill_tangent(np.arctan2, exp_sat_numpy, _loads_tangent)
delayed_state, delayed_direction = make_delayed_direction(np.arctan2, exp_sat_numpy, _loads_tangent)
delayed_tangent = make_delayed_tangent(delayed_state, delayed_direction, _loads_tangent)
