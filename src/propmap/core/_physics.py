"""The blade-element integrand, written once for both back ends (the momentum side of the
balance, the empirical descent, the inflow models and the swirl are in ``_momentum.py``).

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

The elements are built by ``make_element`` / ``make_cambered_element(atan2, stall_blend)`` so
that each back end supplies its own angle and exponential (the blend's, ``make_stall_blend``): NumPy's ufuncs here,
the branch-free polynomials of ``_fastmath.py`` in the compiled kernel (so that its azimuth loop vectorises).
"""

from __future__ import annotations

import math

import numpy as np

from ._fastmath import EXP_CLIP, EXP_WIDE  # |exponent| beyond which exp_sat / exp_wide saturate

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
# 0: off), which only the loads read (_annulus_loads.annulus_loads), not the element, and at PK_INPLANE
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


def exp_wide_numpy(z):
    """``exp(clip(z, -320, 320))`` elementwise (the NumPy twin of ``_fastmath.make_exp_wide``'s)."""
    return np.exp(np.clip(z, -EXP_WIDE, EXP_WIDE))


def make_stall_blend(exp_sat, exp_wide):
    """Return eq (3)'s sigmoid with one exponential per element, using the given saturated exps.

    Gill & D'Andrea (2017), eq (3): sigma = 1 - 1 / ((1 + p)(1 + q)) with p = exp(z - h),
    q = exp(-z - h), where z = M (alpha - centre) is the angle from the middle of the two stall
    angles and h = M (half their distance) (the paper's section: centre 0, h = M alpha_0; the
    cambered polar: centre and half-width of g a_stall+ and g a_stall-). sigma is even in z
    and p q = exp(-2 h) = K2 depends on the annulus only, so with p the larger of the two,
    p = exp(|z| - h), and q = K2 / p: sigma = 1 - p / ((1 + p)(p + K2)). One exponential per
    element instead of two (K2 depends on the annulus only: the compiled residual's azimuth
    loop hoists it). The saturations keep every limit: p is clipped at exp(+-40) as each
    exponential was before (beyond, sigma equals 1, or is within exp(-40) of 0 as before,
    since |z| - h < -40 means h > 40 and K2 / p < exp(-40)), and K2 at exp(+-320), where it
    is negligible against p >= exp(-40) (or, for h < -160, sigma is 1 in double either way),
    with no overflow for any h
    (a first version, clipping exp(|z|) and exp(-h) at 320 each, gave sigma = 1/2 for h >= 320,
    reachable with M near its bound; a review, 2026-11-27).

    Parameters
    ----------
    exp_sat, exp_wide : callable
        ``exp(clip(z, -40, 40))`` and ``exp(clip(z, -320, 320))`` (_fastmath.exp_sat and
        make_exp_wide's in the compiled kernel, :func:`exp_sat_numpy` and :func:`exp_wide_numpy`
        for NumPy).

    Returns
    -------
    callable
        ``stall_blend(z, h)`` -> sigma in [0, 1]: z = M (alpha - centre) and h = M (half-width)
        [-], floats or arrays that broadcast.
    """

    def stall_blend(z, h):
        p = exp_sat(abs(z) - h)
        return 1.0 - p / ((1.0 + p) * (p + exp_wide(-2.0 * h)))

    return stall_blend


stall_blend_numpy = make_stall_blend(exp_sat_numpy, exp_wide_numpy)


def make_element(atan2, stall_blend, profile=False):
    """Return the paper's element (eqs 3-4) using the given arctangent and stall blend
    (:func:`make_stall_blend`); with
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
            # eq (3), sigma = 1 - 1/((1+p)(1+q)), p = exp(M(a - a0)), q = exp(-M(a + a0))
            s = stall_blend(M * alpha, M * alpha0)
            CL = (1.0 - s) * cl1 * alpha + s * post
        cdp = kre / np.sqrt(U) + cd0
        CD = cd * sin_a * sin_a + cdp  # eq (4)
        if profile:  # (a constant of the closure: each compiled element has one return type)
            return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT), cdp * U
        return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT)

    return element_gill


def make_cambered_element(atan2, stall_blend, profile=False):
    """Return the cambered-polar element using the given arctangent and stall blend
    (:func:`make_stall_blend`); with
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
        # eq (3)'s blend, with separate positive and negative stall angles: p = exp(M (ae - g a_stall_pos)),
        # q = exp(-M (ae - g a_stall_neg))
        s = stall_blend(M * (ae - 0.5 * g * (a_stall_pos + a_stall_neg)), 0.5 * M * g * (a_stall_pos - a_stall_neg))
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
    annulus) and vcos = V_b cos(psi) (per node). d = 0 gives the static element to rounding (1 ulp:
    its blend is evaluated with two exponentials per blend, the static element's with one, :func:`make_stall_blend`).

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


def make_profile_drag(atan2, stall_blend):
    """Return the profile (attached-flow) drag coefficient of either element, using the given
    arctangent and stall blend (:func:`make_stall_blend`): the part of C_D that the radial flow's drag scales
    (airfoil.RotorOptions.radial_drag; _annulus_loads.annulus_loads)."""

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
            s = stall_blend(pk[5] * (ae - 0.5 * s2 * (pk[6] + pk[7])), 0.5 * pk[5] * s2 * (pk[6] - pk[7]))
            dcl = s0 * ae - pk[4]
            return s1 * (pk[2] + (1.0 - s) * pk[3] * dcl * dcl)
        return s0 / np.sqrt(np.sqrt(UT * UT + UP * UP + 1e-300)) + pk[5]

    return profile_cd


element_gill = make_element(np.arctan2, stall_blend_numpy)
element_cambered = make_cambered_element(np.arctan2, stall_blend_numpy)
element_cambered_delayed = make_delayed_cambered_element(np.arctan2, exp_sat_numpy)
element_cambered_delayed_h = make_delayed_cambered_element(np.arctan2, exp_sat_numpy, halves=True)
profile_cd = make_profile_drag(np.arctan2, stall_blend_numpy)


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
