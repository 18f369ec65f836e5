"""The blade-element integrand and the momentum balance, written once for both back ends.

Only arithmetic, NumPy ufuncs and the injected atan2/exp are used, so the same functions
run elementwise on NumPy arrays (the vectorised reference in ``_reference.py``) and on
scalars inside numba-compiled loops (``_annulus.py``). Every other piece of physics is
built on them.

Gill & D'Andrea (2017), eqs (1)-(7). With phi = atan2(U_P, U_T) (four-quadrant, the
physical choice in reverse flow; docs/conventions.md) we have exactly U cos(phi) = U_T
and U sin(phi) = U_P, so the rotations of eqs (5)-(7) need no trigonometry:

    U^2 (C_L cos phi - C_D sin phi) = U (C_L U_T - C_D U_P)      (thrust, eq 5)
    U^2 (C_L sin phi + C_D cos phi) = U (C_L U_P + C_D U_T)      (in-plane, eqs 6, 7)

and sin(alpha), cos(alpha) of alpha = theta - phi follow from sin/cos of theta.

Two section models share the element (``model`` selects, see ``SECTION_*``):

* the paper's eqs (3)-(4) (``GILL_SIGMOID``) and footnote 1's sin-cos lift
  (``GILL_SINCOS``); the per-annulus value ``s0`` is the Blasius factor of eq (4);
* the cambered polar (``CAMBERED``, airfoil.CamberedParams): linear lift from the
  zero-lift angle, quadratic drag polar about the minimum-drag lift coefficient, both
  blended by eq (3)'s sigmoid into flat-plate post-stall behaviour. The per-annulus
  lift slope and drag factor carry the Reynolds and Mach corrections, computed once per
  operating point by ``cambered_annulus``.

The compiled kernel chooses the model once per residual, outside the azimuth loop: a
branch inside it stops LLVM from vectorising cleanly (measured: +30% per point).

The elements are built by ``make_element`` / ``make_cambered_element(atan2, exp_sat)`` so
that each back end supplies its own angle and exponential: NumPy's ufuncs here, the branch-free polynomials of
``_fastmath.py`` in the compiled kernel (so that its azimuth loop vectorises).
"""

from __future__ import annotations

import math

import numpy as np

from ._fastmath import EXP_CLIP  # |exponent| beyond which the stall blend equals its limit

TWO_PI = 2.0 * np.pi
TWO_OVER_PI = 2.0 / np.pi

# section models (``model`` argument of the element)
GILL_SIGMOID = 0
GILL_SINCOS = 1
CAMBERED = 2

# layout of the constant parameter vector ``pk`` of each model
#   gill2017: cl1, cl2, cd, alpha0, M, cd0
#   cambered: alpha_L0, cd90, cd_min, cd2, cl_cdmin, M, stall angle above and below
#             the zero-lift line (cl_max / cl_alpha, cl_min / cl_alpha)
# and, for both, at PK_RADIAL_DRAG the factor on the radial flow's drag (1: RotorOptions.radial_drag,
# 0: off), which only the loads read (_annulus.annulus_loads), not the element, and at PK_INPLANE
# the factor on the skewed wake's in-plane induced velocity (1: RotorOptions.inplane_induction, 0: off;
# :func:`inplane_induction`), which the residual and the loads add to the blades' in-plane airspeed
PK_RADIAL_DRAG = 8
PK_INPLANE = 9
# and at PK_DYNSTALL Gormont's factor gamma of the quasi-steady dynamic stall (RotorOptions.dynamic_stall, 0: off;
# the cambered model in a uniform inflow only), which the residual and the loads pass to the delayed element
PK_DYNSTALL = 10
N_PK = 11
#: rows of the blade's node array (core/nodes._Nodes.rows, shape (N_NODE_ROWS, n_radial)), per annulus:
#: its radius y [m] and quadrature weight [m], the blade angle [rad] and its sine and cosine, the
#: section constant, (c/y)^2, the blade and momentum factors N_b rho c / 2 [kg/m^2] and 4 pi rho y
#: [kg/m^2], the tip- and hub-loss constants (-1: off). The angles' three rows are contiguous, so
#: that ``rows[NODE_TH:NODE_TH + 3]`` is the (3, n_radial) blade-angle array the root solve takes.
NODE_Y, NODE_W, NODE_TH, NODE_STH, NODE_CTH, NODE_SC, NODE_CY2, NODE_CFAC, NODE_MFAC, NODE_CT, NODE_CH = range(11)
N_NODE_ROWS = 11


def exp_sat_numpy(z):
    """``exp(clip(z, -40, 40))`` elementwise (the NumPy twin of ``_fastmath.exp_sat``)."""
    return np.exp(np.clip(z, -EXP_CLIP, EXP_CLIP))


def make_element(atan2, exp_sat, profile=False):
    """Return the paper's element (eqs 3-4) using the given arctangent and saturated exp; with
    ``profile`` it returns a third value, the profile drag's C_D,p U (:func:`make_profile_drag`,
    computed with the element's own terms; the implicit derivatives' radial drag)."""

    def element_gill(UT, UP, theta, sin_th, cos_th, kre, cl1, cl2, cd, alpha0, M, cd0, sincos):
        """Per-unit-span section loads of eqs (3)-(4), without the factor 0.5 rho c.

        Parameters
        ----------
        UT, UP : float or ndarray
            Tangential and perpendicular velocity seen by the section [m/s], eqs (1)-(2).
        theta, sin_th, cos_th : float or ndarray
            Blade angle [rad] and its sine and cosine.
        kre : float or ndarray
            Reynolds factor 2 * 1.02 c_p sqrt(mu / (rho c)) [sqrt(m/s)], so that the
            Blasius term of eq (4) is ``kre / sqrt(U)``.
        cl1, cl2, cd, alpha0, M, cd0 : float
            Airfoil parameters (eqs 3-4).
        sincos : bool
            Use footnote 1's ``C_L = cl2 sin a cos a`` instead of eq (3).

        Returns
        -------
        qT, qH : float or ndarray
            ``U (C_L U_T - C_D U_P)`` (along the rotor axis) and ``U (C_L U_P + C_D U_T)``
            (in the disk plane, opposing the blade's motion) [m^2/s^2].
        """
        U = np.sqrt(UT * UT + UP * UP + 1e-300)
        alpha = theta - atan2(UP, UT)
        # keep alpha in (-pi, pi] so that the linear pre-stall term sees the wrapped angle
        alpha = alpha - TWO_PI * (alpha > np.pi) + TWO_PI * (alpha < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        post = cl2 * sin_a * cos_a
        if sincos:
            CL = post
        else:
            # eq (3), sigma = 1 - 1/((1+p)(1+q)), p = exp(M(a - a0)), q = exp(-M(a + a0));
            # the exponents are clipped to +-40, where sigma equals its limits in double.
            p = exp_sat(M * (alpha - alpha0))
            q = exp_sat(-M * (alpha + alpha0))
            s = 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))
            CL = (1.0 - s) * cl1 * alpha + s * post
        cdp = kre / np.sqrt(U) + cd0
        CD = cd * sin_a * sin_a + cdp  # eq (4)
        if profile:  # (a constant of the closure: each compiled element has one return type)
            return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT), cdp * U
        return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT)

    return element_gill


def make_cambered_element(atan2, exp_sat, profile=False):
    """Return the cambered-polar element using the given arctangent and saturated exp; with
    ``profile`` it returns a third value, C_D,p U (as :func:`make_element`)."""

    def element_cambered(UT, UP, theta, sin_th, cos_th, a, cdf, g, dal0, alpha_L0, cd90, cd_min, cd2, cl_cdmin, M,
                         a_stall_pos, a_stall_neg):
        """Per-unit-span section loads of the cambered polar, without the factor 0.5 rho c.

        Parameters
        ----------
        UT, UP, theta, sin_th, cos_th
            As for the paper's element.
        a : float or ndarray
            Lift slope of the annulus (Reynolds/Mach-corrected) [1/rad].
        cdf : float or ndarray
            Reynolds factor of the profile drag [-].
        g : float or ndarray
            Factor on the stall angles of the annulus (Reynolds number, rotational stall
            delay) [-].
        dal0 : float or ndarray
            Reynolds shift of the zero-lift angle of the annulus [rad].
        alpha_L0, cd90, cd_min, cd2, cl_cdmin, M : float
            airfoil.CamberedParams.
        a_stall_pos, a_stall_neg : float
            Stall angles from the zero-lift line, cl_max / cl_alpha and cl_min / cl_alpha [rad].

        Returns
        -------
        qT, qH
            As for the paper's element [m^2/s^2].
        """
        U = np.sqrt(UT * UT + UP * UP + 1e-300)
        # angle from the zero-lift line, wrapped to (-pi, pi]
        ae = theta - (alpha_L0 + dal0) - atan2(UP, UT)
        ae = ae - TWO_PI * (ae > np.pi) + TWO_PI * (ae < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        # eq (3)'s blend, with separate positive and negative stall angles
        p = exp_sat(M * (ae - g * a_stall_pos))
        q = exp_sat(-M * (ae - g * a_stall_neg))
        s = 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))
        cl_att = a * ae
        dcl = cl_att - cl_cdmin
        CL = (1.0 - s) * cl_att + s * cd90 * sin_a * cos_a
        # profile drag (quadratic polar, Reynolds-scaled) + flat-plate drag past stall
        cdp = cdf * (cd_min + (1.0 - s) * cd2 * dcl * dcl)
        CD = cdp + s * cd90 * sin_a * sin_a
        if profile:
            return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT), cdp * U
        return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT)

    return element_cambered


#: the largest stall delay of the dynamic stall [rad] (20 deg; propmap's bound, not Gormont's): the delay grows
#: without limit as the section speed U falls (inboard, near the reverse-flow circle), to 140 deg at mu = 0.2 on an
#: APC 8x6E; bounded at 20 deg the thrust rise there is unchanged to the third digit (0.157), at 10 deg 0.149
DELAY_MAX = math.radians(20.0)


def make_delayed_cambered_element(atan2, exp_sat, halves=False):
    """Return the cambered element with Gormont's quasi-steady dynamic stall, node and mirror
    node together (RotorOptions.dynamic_stall; docs/models.md, Dynamic stall).

    Gormont (R. E. Gormont, "A Mathematical Model of Unsteady Aerodynamics and Radial Flow for
    Application to Helicopter Rotors", USAAMRDL TR 72-67, 1973; J. G. Leishman, Principles of
    Helicopter Aerodynamics, 2nd ed., 2006, Ch. 9) reads the static polar at
    alpha - gamma K1 sqrt(|c alpha_dot / (2 U)|) sign(alpha_dot), K1 = 1 while alpha rises and
    -1/2 while it falls. propmap shifts the stall blend's positive stall angle by that delay
    (the attached lift is unchanged; the negative stall angle and the drag's own factor, which
    Gormont takes smaller, are not delayed). With a uniform inflow the nodes psi and pi - psi see
    the same U_T and U_P, and alpha_dot = Omega U_P (dU_T/dpsi) / U^2 = Omega U_P V_b cos(psi) /
    U^2 of opposite signs: rising at one, falling at the other. C_L and C_D are linear in the
    blend, so the pair's mean loads are the element's with the mean of the two blends,
    s = 1 - (1/(1+p+) + 1/(1+p-)) / (2 (1+q)), p+- = exp(M (ae - g a_pos -+ K d)), K = 1 and
    -1/2, d = min(kd sqrt(|U_P vcos| / U^3), DELAY_MAX) with kd = gamma sqrt(c Omega / 2) (per
    annulus) and vcos = V_b cos(psi) (per node). d = 0 gives the static element exactly.

    Returns ``element(UT, UP, theta, sin_th, cos_th, a, cdf, g, dal0, alpha_L0, cd90, cd_min,
    cd2, cl_cdmin, M, a_stall_pos, a_stall_neg, kd, vcos)`` [m/s, rad, the cambered element's
    constants; kd [m^0.5 s^-0.5], vcos [m/s]] -> (qT, qH, C_D,p U) [m^2/s^2, m^2/s^2, m/s], the
    pair's means; with ``halves`` three more, half the rising node's less the falling node's
    (the fore-aft asymmetry that gives the pitching moment and the side force).
    """

    def element_cambered_delayed(UT, UP, theta, sin_th, cos_th, a, cdf, g, dal0, alpha_L0, cd90, cd_min, cd2,
                                 cl_cdmin, M, a_stall_pos, a_stall_neg, kd, vcos):
        U = np.sqrt(UT * UT + UP * UP + 1e-300)
        ae = theta - (alpha_L0 + dal0) - atan2(UP, UT)
        ae = ae - TWO_PI * (ae > np.pi) + TWO_PI * (ae < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        d = np.minimum(kd * np.sqrt(np.abs(UP * vcos)) / (U * np.sqrt(U)), DELAY_MAX)
        x = ae - g * a_stall_pos
        q1 = 1.0 + exp_sat(-M * (ae - g * a_stall_neg))
        s_rise = 1.0 - 1.0 / ((1.0 + exp_sat(M * (x - d))) * q1)
        s_fall = 1.0 - 1.0 / ((1.0 + exp_sat(M * (x + 0.5 * d))) * q1)
        s = 0.5 * (s_rise + s_fall)
        # from here the cambered element's own lines, with the mean blend (repeated, not shared: a helper
        # injected into both factories would change every call of the kernel's hot element)
        cl_att = a * ae
        dcl = cl_att - cl_cdmin
        CL = (1.0 - s) * cl_att + s * cd90 * sin_a * cos_a
        cdp = cdf * (cd_min + (1.0 - s) * cd2 * dcl * dcl)
        CD = cdp + s * cd90 * sin_a * sin_a
        if halves:  # linear in s: the half difference's loads are those of the blend's half difference
            hs = 0.5 * (s_rise - s_fall)
            hCL = hs * (cd90 * sin_a * cos_a - cl_att)
            hcdp = -hs * cdf * cd2 * dcl * dcl
            hCD = hcdp + hs * cd90 * sin_a * sin_a
            return (U * (CL * UT - CD * UP), U * (CL * UP + CD * UT), cdp * U,
                    U * (hCL * UT - hCD * UP), U * (hCL * UP + hCD * UT), hcdp * U)
        return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT), cdp * U

    return element_cambered_delayed


def make_profile_drag(atan2, exp_sat):
    """Return the profile (attached-flow) drag coefficient of either element, using the given
    arctangent and saturated exp: the part of C_D that the radial flow's drag scales
    (airfoil.RotorOptions.radial_drag; _annulus.annulus_loads)."""

    def profile_cd(UT, UP, theta, s0, s1, s2, s3, model, pk):
        """The element's friction and profile drag coefficient, without the pressure drag of stall.

        Parameters as :func:`element` (``s0 ... s3`` the annulus' section constants, ``pk`` the
        model's constants). Cambered: ``cdf (cd_min + (1 - s) cd2 (C_L,att - cl_cdmin)^2)``, the
        quadratic polar of the attached flow faded out by the stall blend s as in the element;
        the flat-plate term s cd90 sin^2 a, a pressure force normal to the chord, is left out.
        gill2017: eq (4)'s Blasius and form terms ``kre / sqrt(U) + cd0``, without its
        ``cd sin^2 a`` (stall) term. [-]
        """
        if model == CAMBERED:
            ae = theta - (pk[0] + s3) - atan2(UP, UT)
            ae = ae - TWO_PI * (ae > np.pi) + TWO_PI * (ae < -np.pi)
            p = exp_sat(pk[5] * (ae - s2 * pk[6]))
            q = exp_sat(-pk[5] * (ae - s2 * pk[7]))
            s = 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))
            dcl = s0 * ae - pk[4]
            return s1 * (pk[2] + (1.0 - s) * pk[3] * dcl * dcl)
        return s0 / np.sqrt(np.sqrt(UT * UT + UP * UP + 1e-300)) + pk[5]

    return profile_cd


element_gill = make_element(np.arctan2, exp_sat_numpy)
element_cambered = make_cambered_element(np.arctan2, exp_sat_numpy)
element_cambered_delayed = make_delayed_cambered_element(np.arctan2, exp_sat_numpy)
element_cambered_delayed_h = make_delayed_cambered_element(np.arctan2, exp_sat_numpy, halves=True)
profile_cd = make_profile_drag(np.arctan2, exp_sat_numpy)


def element(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, model, pk):
    """Either model's element (NumPy): ``s0, s1, s2`` per-annulus values, ``pk`` constants.

    gill2017: s0 = the Blasius factor kre, s1, s2 unused, pk = (cl1, cl2, cd, alpha0, M,
    cd0). cambered: s0 = lift slope, s1 = drag factor, s2 = stall-angle factor, s3 =
    zero-lift shift, pk = (alpha_L0, cd90, cd_min, cd2, cl_cdmin, M, stall angle +, stall angle -).
    Returns (qT, qH) [m^2/s^2].
    """
    if model == CAMBERED:
        return element_cambered(UT, UP, theta, sin_th, cos_th, s0, s1, s2, s3, *pk[:8])
    return element_gill(UT, UP, theta, sin_th, cos_th, s0, *pk[:6], model == GILL_SINCOS)


def make_prandtl(atan2, exp_sat):
    """Return ``prandtl(c, inv_sin)`` using the given arctangent and saturated exp."""

    def prandtl(c, inv_sin):
        """Prandtl's factor (2/pi) acos(exp(-f)), f = c / sin(phi), one of tip or hub.

        acos(x) = atan2(sqrt(1 - x^2), x). Branch-free, so that a loop over annuli
        vectorises.
        """
        # exp_sat may exceed 1 by 6e-14 for arguments near 0: clamp, or sqrt would give NaN
        x = np.minimum(exp_sat(-c * inv_sin), 1.0)
        return TWO_OVER_PI * atan2(np.sqrt(1.0 - x * x), x)

    return prandtl


def inverse_sin_phi(UP, wy):
    """1 / sin(phi) of the azimuth-averaged inflow angle, sqrt(U_P^2 + (Omega y)^2) / |U_P|."""
    up = np.abs(UP)
    return np.sqrt(up * up + wy * wy) / (up + 1e-300)


def make_loss_factor(prandtl):
    """Return ``loss_factor`` built on the given ``prandtl`` (from ``make_prandtl``)."""

    def loss_factor(UP, wy, ct, ch):
        """Prandtl's tip- and hub-loss factor F = F_tip F_hub at one annulus.

        ``F = (2/pi) acos(exp(-f))`` with ``f_tip = (N_b/2)(R - y)/(y sin phi)`` and
        ``f_hub = (N_b/2)(y - r_hub)/(r_hub sin phi)`` (Prandtl, in Glauert 1935; the hub
        form of Moriarty & Hansen, NREL/TP-500-36881, 2005). ``sin phi`` is the inflow angle
        of the azimuth-averaged velocities, |U_P| / sqrt(U_P^2 + (Omega y)^2): the vortex
        sheets' spacing normal to the disk is set by the axial velocity U_P and the blade
        passage period, while the in-plane component only translates them (so F -> 1 as
        U_P -> 0, e.g. in fast edgewise flight).

        Parameters
        ----------
        UP : float
            Axial velocity through the annulus V cos(beta) + v [m/s].
        wy : float
            Omega y [m/s], > 0.
        ct, ch : float
            (N_b/2)(R - y)/y and (N_b/2)(y - r_hub)/r_hub; a negative value switches that
            factor off (F = 1).
        """
        up = np.abs(UP)
        inv_sin = np.sqrt(up * up + wy * wy) / (up + 1e-300)  # as inverse_sin_phi
        F = 1.0
        if ct >= 0.0:
            F = F * prandtl(ct, inv_sin)
        if ch >= 0.0:
            F = F * prandtl(ch, inv_sin)
        return F

    return loss_factor


prandtl_numpy = make_prandtl(np.arctan2, exp_sat_numpy)


def loss_factor_numpy(UP, wy, ct, ch):
    """Array form of ``loss_factor`` (NumPy reference): ct, ch may be arrays with -1 = off."""
    inv_sin = inverse_sin_phi(UP, wy)
    F = np.ones(np.broadcast(UP, wy, ct, ch).shape)
    for c in (ct, ch):
        F = F * np.where(np.asarray(c) >= 0, prandtl_numpy(np.maximum(c, 0.0), inv_sin), 1.0)
    return F


def inplane_induction(v, Vs, Vc):
    """The skewed wake's in-plane induced velocity at an annulus [m/s], along the in-plane airspeed.

    u_x = v tan(chi / 2), with v the annulus' inflow and chi the wake's skew from the disk's
    axis, tan(chi) = Vs / |W| with W = Vc + v the flow through the disk, written without the
    angle as u_x = v Vs / (sqrt(Vs^2 + W^2) + |W|): 0 in axial flow, Vs / 2 at small skew in
    hover (Vs << |W|), v edgewise at W = 0. In descent (Vc < 0) W is taken as v, the skew
    of a hovering disk at the same in-plane speed: propmap's choice, as the model holds for
    a wake that convects away below, which in descent it does less and less (the
    vortex-ring state), and with Vc + v its tan(chi / 2) would change from Vs / (2 |W|) to 1
    over |Vc + v| ~ Vs there (root folds). Where the flow through the disk is upward the
    model's wake leaves above and its u_x is -v tan(chi / 2), upstream: propmap keeps the
    sign of v and a continuous u_x through the vortex-ring state instead (docs/models.md).
    Continuous at Vc = 0, where its slope in Vc has a kink (exactly edgewise, as the
    empirical descent model's switch). Vs >= 0; scalars (the kernels;
    :func:`inplane_induction_numpy` for arrays).

    Source: the wake of a uniformly loaded disk as a semi-infinite skewed cylinder of ring
    vortices (W. Castles and J. H. De Leeuw, NACA Report 1184, 1954; its normal velocity at
    the disk is Glauert's momentum value v on the azimuthal mean, R. P. Coleman, A. M.
    Feingold and C. W. Stempin, NACA ARR L5E10, 1945). Its in-plane velocity, averaged over
    the azimuth at a radius inside the cylinder, is v tan(chi / 2) and 0 outside it, so that
    with the loading varying along the radius (nested cylinders) each annulus sees its own v
    times tan(chi / 2): propmap's Biot-Savart evaluation of that model (integrated in
    tests/test_inplane_induction.py), the component that momentum theory, which keeps only
    the normal one, leaves out. The skew is taken per annulus, as the annulus' momentum is.
    """
    W = Vc + v if Vc >= 0.0 else v
    d = np.sqrt(Vs * Vs + W * W) + abs(W)
    return v * Vs / d if d > 0.0 else 0.0


def inplane_induction_numpy(v, Vs, Vc):
    """:func:`inplane_induction` elementwise over broadcast arrays."""
    W = np.where(Vc >= 0.0, Vc + v, v)
    d = np.sqrt(Vs * Vs + W * W) + np.abs(W)
    return np.where(d > 0.0, v * Vs / np.where(d > 0.0, d, 1.0), 0.0)


def momentum_thrust(v, mom_fac, Vs, Vc):
    """dT_BEMT/dy of eq (10), Glauert mass flow, no extra sign flip (docs/conventions.md).

    ``mom_fac = 4 pi rho y``; returns ``mom_fac * v * sqrt(Vs^2 + (Vc + v)^2)`` [N/m].
    The loss factor F multiplies it where tip/hub loss is on.
    """
    return mom_fac * v * np.sqrt(Vs * Vs + (Vc + v) * (Vc + v))


# The empirical induced velocity of a rotor in axial descent through the vortex-ring and
# turbulent-wake states: J. G. Leishman, Principles of Helicopter Aerodynamics, 2nd ed., 2006,
# Ch. 2, a fit to the wind-tunnel measurements on four model rotors of W. Castles and R. B.
# Gray, NACA TN 2474, 1951:  v/v_h = kappa + 1.125 k - 1.372 k^2 + 1.718 k^3 - 0.655 k^4,
# k = -V_c / v_h in [0, 2], with kappa = 1 here (Leishman's 1.15 is the measured rotors'
# induced-power factor; the BEMT computes those losses itself: docs/models.md, Descent).
# propmap subtracts EMPIRICAL_SHIFT k (1.3% at k = 2) so that the curve meets Glauert's
# windmill-brake branch (v/v_h = 1 at k = 2) as it meets hover at k = 0.
EMPIRICAL_SHIFT = 0.0130
EMPIRICAL_C1 = 1.125 - EMPIRICAL_SHIFT
EMPIRICAL_C2 = -1.372
EMPIRICAL_C3 = 1.718
EMPIRICAL_C4 = -0.655
#: v / (-V_c) above which the curve is taken at hover (Glauert's form; k < 1e-8)
EMPIRICAL_HOVER_RATIO = 1e8
#: Newton steps of the curve's inversion (converged to round-off from k = min(d/v, 2) in tests)
EMPIRICAL_NEWTON = 8


def empirical_k(r):
    """The descent ratio k in [1e-12, 2] of the empirical curve at v / (-V_c) = r >= 1/2: the root
    of f(k) = r k (f(k)/k falls monotonically from infinity at k = 0 to 1/2 at k = 2), by
    EMPIRICAL_NEWTON clipped Newton steps from k = min(1/r, 2) (scalars)."""
    k = min(1.0 / r, 2.0)
    for _ in range(EMPIRICAL_NEWTON):
        f = 1.0 + k * (EMPIRICAL_C1 + k * (EMPIRICAL_C2 + k * (EMPIRICAL_C3 + k * EMPIRICAL_C4)))
        fp = EMPIRICAL_C1 + k * (2.0 * EMPIRICAL_C2 + k * (3.0 * EMPIRICAL_C3 + 4.0 * EMPIRICAL_C4 * k))
        k = min(max(k - (f - r * k) / (fp - r), 1e-12), 2.0)
    return k


def make_axial_mass_flow(root):
    """Return ``axial_mass_flow`` built on the given ``root`` (:func:`empirical_k`, or its
    compiled copy)."""

    def axial_mass_flow(v, Vc, Vs):
        """Axial velocity of the mass flow through an annulus, empirical in descent [m/s] (scalars).

        Glauert's momentum (eq 10) carries the mass flow rho A W with W = sqrt(Vs^2 + (Vc + v)^2);
        this returns its axial part. Outside descent, and in descent for v <= |Vc|/2 (the
        windmill-brake branch, where momentum theory holds), it is Glauert's |Vc + v|. For
        v > |Vc|/2 in descent (the vortex-ring and turbulent-wake states) the empirical curve
        above replaces it: with d = -Vc, the curve's k solves v/d = f(k)/k (f(k)/k falls
        monotonically from infinity at k = 0 to 1/2 at k = 2), the annulus' hover inflow is
        v_h = d/k, and the mass-flow velocity that gives dT = 4 pi rho r v_h^2 is v_h^2 / v.
        The curve was measured in axial descent; a vortex ring only forms while the in-plane
        velocity cannot carry the wake away, so the empirical part fades with exp(-(Vs/v)^2)
        (propmap's choice: half gone at Vs = 0.83 v, nearly all at Vs = 2 v) and Glauert's form
        holds in forward flight. Continuous in v, Vc and Vs, and v sqrt(Vs^2 + W^2) grows with v
        (checked on a grid of descent and in-plane speeds): one root per annulus from the
        momentum side (docs/models.md, Descent). With tip loss, Prandtl's factor takes its inflow
        angle from this velocity in descent (the kernel's loss loop), so that it does not jump
        where U_P = Vc + v passes through 0.
        """
        d = -Vc
        glauert = abs(Vc + v)
        if d <= 0.0 or v <= 0.5 * d or v > EMPIRICAL_HOVER_RATIO * d:
            # beyond EMPIRICAL_HOVER_RATIO the curve is at hover (k < 1e-8, where it differs from
            # Glauert's by O(k)); the Newton solve would clip k there and lose the thrust
            return glauert
        vh = d / root(v / d)
        s = Vs / v
        return glauert + (vh * vh / v - glauert) * np.exp(-s * s)

    return axial_mass_flow


axial_mass_flow = make_axial_mass_flow(empirical_k)


def momentum_scale(B0, mom_fac, Vs, Vc):
    """Inflow scale v_m [m/s] used to size the root march.

    Approximates |v| solving ``v sqrt(W^2 + v^2) = |B0| / mom_fac`` with W^2 = Vs^2 + Vc^2:
    ``v_m = k / sqrt(W^2 + k)``, k = |B0|/mom_fac, exact in hover (sqrt k) and in fast
    flight (k / W). A floor of 1e-6 m/s keeps the step positive.
    """
    k = np.abs(B0) / mom_fac
    return np.maximum(k / np.sqrt(Vs * Vs + Vc * Vc + k + 1e-300), 1e-6)


# inflow models (``inflow`` of the section records): the paper's azimuth-independent inflow,
# and two linear inflow models v(r, psi) = v0(r) (1 + k_x (r/R) cos psi + k_y (r/R) sin psi)
INFLOW_UNIFORM = 0
INFLOW_DREES = 1
INFLOW_PITT_PETERS = 2
INFLOW_CODES = {"uniform": INFLOW_UNIFORM, "drees": INFLOW_DREES, "pitt-peters": INFLOW_PITT_PETERS}
# momentum in descent (``descent`` of the section records): Glauert's everywhere (the paper's),
# or the empirical curve in the vortex-ring and turbulent-wake states (axial_mass_flow)
DESCENT_CODES = {"glauert": 0, "empirical": 1}
#: the advance ratio at which Drees's gradients are held (propmap's bound): his model is one of
#: helicopter rotors in forward flight (mu up to about 0.5), and its k_y = -2 mu is unbounded,
#: so that a slow or parked rotor in a flow (mu of hundreds) had inflows hundreds of times its
#: mean across the disk and in-plane loads of kN (a user-level audit, 2026-11-26); beyond it
#: RotorLoads.inflow_extrapolated is set
DREES_MU_MAX = 0.5


def inflow_gradients(mu, lam, model):
    """First-harmonic gradients (k_x, k_y) of a linear inflow model [-].

    v(r, psi) = v0(r) (1 + k_x (r/R) cos psi + k_y (r/R) sin psi), psi = 0 downstream
    (the blade parallel to the in-plane velocity, trailing), psi = 90 deg the advancing
    blade; v0(r) is the annulus' mean (the root of eq 11). The wake skew angle is
    chi = atan2(mu, lambda), lambda = (V cos beta + v_mean) / (Omega R) the inflow ratio
    through the disk and mu = V sin beta / (Omega R).

    * Drees (1949): k_x = (4/3) (1 - cos chi - 1.8 mu^2) / sin chi, k_y = -2 mu;
    * Pitt & Peters (1981): k_x = (15 pi / 32) tan(chi / 2), k_y = 0;

    both as tabulated by J. G. Leishman, Principles of Helicopter Aerodynamics, 2nd ed.,
    Cambridge University Press, 2006, Sec. 3.4 (linear inflow models). Both are derived for
    a wake skewed behind the rotor (chi <= 90 deg, the normal working state); for a wake
    above the disk (lambda < 0, descent) propmap evaluates them at the mirrored skew angle
    pi - chi, so that the gradient vanishes again in axial descent (the modification of
    Coleman's model used by wind-turbine codes for skew beyond 90 deg), an extrapolation
    that ``RotorLoads.inflow_extrapolated`` flags. k_x is held >= 0 (a wake skewed
    backwards has the larger inflow at the rear). Drees's mu terms are held at
    ``DREES_MU_MAX`` (0.5) beyond it, also flagged. Scalars only (once per operating point).
    """
    if model == INFLOW_UNIFORM or mu <= 0.0:
        return 0.0, 0.0
    chi = np.arctan2(mu, abs(lam))  # in [0, pi/2]: the mirrored angle where lam < 0
    if model == INFLOW_DREES:
        m = min(mu, DREES_MU_MAX)
        kx = (4.0 / 3.0) * (1.0 - np.cos(chi) - 1.8 * m * m) / max(np.sin(chi), 1e-12)
        return max(kx, 0.0), -2.0 * m
    return (15.0 * np.pi / 32.0) * np.tan(0.5 * chi), 0.0


# Swirl (RotorOptions.swirl): the tangential induced velocity u of an annulus, from its angular
# momentum. The blade sees the tangential speed Omega y - u (+ V sin beta sin psi); the wake
# carries away the angular momentum the torque puts in, dQ/dy = F 4 pi rho y^2 W u (the mass
# flow of eq 10 times the swirl 2u far behind the disk, u at the disk): the rotational
# interference factor a' = u / (Omega y) of blade-element momentum theory (H. Glauert, "Airplane
# Propellers", in W. F. Durand (ed.), Aerodynamic Theory, vol. IV, div. L, Springer, 1935; the
# same balance in the wind-turbine form of S. A. Ning, "A simple solution method for the blade
# element momentum equations with guaranteed convergence", Wind Energy 17, 2014). Where eq 11
# holds, dT/dy = F 4 pi rho y v W, so u = v (dQ/dy / y) / (dT/dy), free of F and W.
#: outer iterations of the swirl around the root solve (a bracketed secant in u per annulus)
SWIRL_MAX_ITER = 40
#: iterations after which a bracketed annulus bisects (the secant converges in 4-6 where a
#: balance exists; where the root jumps, bisection closes a bracket of 1e-3 Omega y in 14)
SWIRL_SECANT_ITER = 8
#: the swirl iteration stops when every annulus' |u_target - u| <= SWIRL_TOL Omega y: an error
#: of that size moves v by about as much as the root solve's own tolerance (XTOL = 1e-7 of the
#: inflow scale), and that tolerance's noise in the target is far smaller
SWIRL_TOL = 1e-7
#: |u| <= SWIRL_LIMIT Omega y (the blade keeps half its speed; reached only at a rotor stopped in
#: a flow, or at annuli of near-zero thrust and finite torque)
SWIRL_LIMIT = 0.5


def swirl_target(v, dT, dQ, y):
    """The swirl u [m/s] that balances an annulus' angular momentum at a root of eq 11
    (scalars): u = v dQ / (y dT) from the annulus' mean inflow v [m/s], thrust and torque
    densities dT [N/m] and dQ [N] at radius y [m]; 0 where dT = 0."""
    if dT == 0.0:
        return 0.0
    return v * dQ / (y * dT)


def swirl_step(u, g, u_prev, g_prev, lo, hi, first, bisect, limit):
    """The next swirl iterate (scalars): the secant through (u_prev, g_prev) and (u, g), with
    g = target - u; a plain step u + g on the first iteration, for a flat secant or a
    non-finite one. Once iterates with g > 0 (the latest, ``lo``) and g < 0 (``hi``) are known
    (NaN until then), a sign change of g lies between them, and a step that leaves that
    bracket is replaced by its midpoint, as is every step with ``bisect`` (from iteration
    SWIRL_SECANT_ITER on: a secant creeps along a jump of g), so that the bracket shrinks to a
    balance or, where the selected root jumps between branches as u moves, to the jump.
    Clipped to [-limit, limit]."""
    nxt = u + g
    if not first:
        den = g - g_prev
        if den != 0.0:
            sec = u - g * (u - u_prev) / den
            if sec == sec and abs(sec) < 1e300:
                nxt = sec
    if lo == lo and hi == hi and (bisect or not (min(lo, hi) < nxt < max(lo, hi))):
        nxt = 0.5 * (lo + hi)
    return min(max(nxt, -limit), limit)


#: the Reynolds corrections are held constant outside Re_ref * exp([LN_RE_MIN, LN_RE_MAX]),
#: i.e. Re in [1e4, 5e5] for Re_ref = 1e5: vol. 1's data span 14,500-125,000 at 0.75 R, and a
#: power or log law is not extrapolated further; vol. 2's reach 3,600, and acting down to 3e3
#: was measured and not adopted (docs/models.md)
LN_RE_MIN = -2.302585092994046
LN_RE_MAX = 1.6094379124341003


def cambered_annulus(U2, ln_re_c, cy2, mach2_c, cl_alpha, re_exp, re_exp_lift, compressible, re_exp_stall,
                     stall_delay, alpha_L0_re):
    """Per-annulus Reynolds-, Mach- and rotation-corrected constants of the cambered section.

    The Reynolds number of an annulus is rho U c / mu with U^2 = (Omega y)^2 +
    (V sin beta)^2 / 2 + (V cos beta)^2, the azimuth mean of the section's U^2 without
    the induced inflow (computing it per element would cost a pow per element
    evaluation; v_i changes the factors by < 0.3% over the outer blade in hover).
    ln(Re / Re_ref) is clamped to [LN_RE_MIN, LN_RE_MAX]: the corrections are held
    constant beyond the Reynolds numbers the calibration saw.

    Parameters
    ----------
    U2 : float or ndarray
        Mean square section speed [m^2/s^2].
    ln_re_c : float or ndarray
        ln(rho c / (mu Re_ref)) [ln(s/m)], so that ln(Re / Re_ref) = ln_re_c + ln U.
    cy2 : float or ndarray
        (c / y)^2 of the annulus [-].
    mach2_c : float
        1 / a^2 [s^2/m^2] (a the speed of sound).
    cl_alpha, re_exp, re_exp_lift, re_exp_stall, stall_delay, alpha_L0_re : float
        Section parameters (airfoil.CamberedParams).
    compressible : bool
        Apply the Prandtl-Glauert factor 1/sqrt(1 - Ma^2) to the lift (Ma capped at 0.9).

    Returns
    -------
    a, cdf, g, dal0
        Lift slope cl_alpha (Re/Re_ref)^re_exp_lift / sqrt(1 - Ma^2) [1/rad], drag factor
        (Re/Re_ref)^re_exp [-], stall-angle factor
        (Re/Re_ref)^re_exp_stall (1 + stall_delay (c/y)^2) [-] and zero-lift shift
        alpha_L0_re ln(Re/Re_ref) [rad].
    """
    ln_re = np.minimum(np.maximum(ln_re_c + 0.5 * np.log(U2 + 1e-300), LN_RE_MIN), LN_RE_MAX)
    a = cl_alpha * np.exp(re_exp_lift * ln_re)
    if compressible:
        a = a / np.sqrt(1.0 - np.minimum(U2 * mach2_c, 0.81))
    g = 1.0 + stall_delay * cy2
    if re_exp_stall != 0.0:  # 0 by default: skip an exponential per annulus
        g = g * np.exp(re_exp_stall * ln_re)
    return a, np.exp(re_exp * ln_re), g, alpha_L0_re * ln_re
