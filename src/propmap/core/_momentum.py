"""The momentum side of the blade-element momentum balance, and the wake's induced velocities.

Glauert's mass flow in eq (10) (:func:`momentum_thrust`; Gill & D'Andrea 2017), its empirical
replacement in the vortex-ring and turbulent-wake states of descent (:func:`axial_mass_flow`),
the inflow scale that sizes the root march (:func:`momentum_scale`), the linear inflow models'
gradients (:func:`inflow_gradients`), the skewed wake's in-plane induced velocity
(:func:`inplane_induction`) and the swirl's angular-momentum balance (:func:`swirl_target`,
:func:`swirl_step`). The blade side (the elements, the loss factor, the section constants) is
in ``_physics.py``. As there, only arithmetic and NumPy ufuncs, so that the same functions run
on scalars inside the compiled kernels (``_annulus.py``) and, where written for arrays, in the
NumPy reference (``_reference.py``).
"""

from __future__ import annotations

import numpy as np


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
#: v / (-V_c) above which the curve is taken at its first order in k = -V_c / v_h (k < 1e-8): v_h^2 / v =
#: v / f(k)^2 = v - 2 EMPIRICAL_C1 d + O(d^2 / v), d = -V_c, exact to round-off there; it was Glauert's |V_c + v|
#: until 2026-12-01, whose slope in V_c (1, not 2 EMPIRICAL_C1) gave the derivatives of a descent of 1e-9 m/s the
#: climb's slope mirrored (apce_8x6, generic set: dT/dV 0.0402 against 0.0062 at rest and at 1e-6 m/s: an API audit)
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
        if d <= 0.0 or v <= 0.5 * d:
            return glauert
        if v > EMPIRICAL_HOVER_RATIO * d:
            # the curve at its first order in k < 1e-8 (EMPIRICAL_HOVER_RATIO), where the Newton solve
            # would clip k and lose the thrust
            w = v - 2.0 * EMPIRICAL_C1 * d
        else:
            vh = d / root(v / d)
            w = vh * vh / v
        s = Vs / v
        return glauert + (w - glauert) * np.exp(-s * s)

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


def skew_inflow_ratio(Vc, v_mean, OmR):
    """The inflow ratio that sets a linear inflow model's wake skew [-].

    lambda = (Vc + v_mean) / (Omega R), the flow through the disk, in climb and edgewise flight
    (Vc >= 0); v_mean / (Omega R) in descent (Vc < 0): the skew of a hovering disk at the same
    in-plane speed, the rule of :func:`inplane_induction`. With the flow through the disk
    itself, a descent near the rotor's own autorotation (Vc + v_mean ~ 0) put the skew at 90
    deg for any in-plane speed and 0 at none: the loads jumped between axial descent and 0.01
    deg off it (thrust -8.5%, gwsdd_5x3 at 12,000 rpm and 15.05 m/s with Pitt-Peters) and the
    torque spiked by 11% over 0.2 m/s of descent rate (an envelope audit, 2026-11-27). Continuous
    at Vc = 0, where its slope in Vc has a kink (as u_x's). Scalars.
    """
    return (Vc + v_mean if Vc >= 0.0 else v_mean) / OmR


def inflow_gradients(mu, lam, model):
    """First-harmonic gradients (k_x, k_y) of a linear inflow model [-].

    v(r, psi) = v0(r) (1 + k_x (r/R) cos psi + k_y (r/R) sin psi), psi = 0 downstream
    (the blade parallel to the in-plane velocity, trailing), psi = 90 deg the advancing
    blade; v0(r) is the annulus' mean (the root of eq 11). The wake skew angle is
    chi = atan2(mu, lambda), lambda the inflow ratio of :func:`skew_inflow_ratio` ((V cos beta
    + v_mean) / (Omega R) through the disk; v_mean / (Omega R) in descent) and mu = V sin beta
    / (Omega R).

    * Drees (1949): k_x = (4/3) (1 - cos chi - 1.8 mu^2) / sin chi, k_y = -2 mu;
    * Pitt & Peters (1981): k_x = (15 pi / 32) tan(chi / 2), k_y = 0;

    both as tabulated by J. G. Leishman, Principles of Helicopter Aerodynamics, 2nd ed.,
    Cambridge University Press, 2006, Sec. 3.4 (linear inflow models). Both are derived for
    a wake skewed behind the rotor (chi <= 90 deg, the normal working state); a lambda < 0
    (a rotor making negative thrust, its v_mean < 0) is evaluated at the mirrored skew angle
    pi - chi (the modification of Coleman's model used by wind-turbine codes for skew beyond
    90 deg). Where the flow through the disk is upward, ``RotorLoads.inflow_extrapolated``
    flags the point. k_x is held >= 0 (a wake skewed
    backwards has the larger inflow at the rear). Drees's mu terms are held at
    ``DREES_MU_MAX`` (0.5) beyond it, also flagged. Scalars only (once per operating point).
    """
    if model == INFLOW_UNIFORM or mu <= 0.0:
        return 0.0, 0.0
    chi = np.arctan2(mu, abs(lam))  # in [0, pi/2]: the mirrored angle where lam < 0
    if model == INFLOW_DREES:
        m = min(mu, DREES_MU_MAX)
        # 1 - cos chi as 2 sin^2(chi / 2): it lost its digits as chi -> 0 (0 below chi ~ 1e-8; an audit, 2026-11-27)
        kx = (4.0 / 3.0) * (2.0 * np.sin(0.5 * chi) ** 2 - 1.8 * m * m) / max(np.sin(chi), 1e-12)
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
    Until both are known, a secant step against the sign of g is replaced by a step along g of
    at least twice the last step's length: where the target's slope in u is below 1 (0.015-0.25
    mostly, docs/models.md) g falls with u and a balance lies on g's side, and a secant through
    iterates on either side of a jump of the selected root can point back, so that iterating
    between the branches it never bracketed the balance beyond the jump (a windmilling annulus
    of gwsdd_4x2.5 with the paper's section, g < 0 on both sides of the jump: a user-level
    audit, 2026-11-26); near an annulus of zero thrust the slope can exceed 1 (g with a maximum
    just below 0 before the balance: a review found nr640_5_15deg_4b at 6000 rpm, 20.5 m/s),
    where plain steps u + g would crawl, so the step grows until g changes sign.
    Clipped to [-limit, limit]."""
    nxt = u + g
    bracket = lo == lo and hi == hi
    if not first:
        den = g - g_prev
        if den != 0.0:
            sec = u - g * (u - u_prev) / den
            if sec == sec and abs(sec) < 1e300:
                if bracket or (sec - u) * g >= 0.0:
                    nxt = sec
                else:  # against g without a bracket: along g, growing
                    nxt = u + np.copysign(max(abs(g), 2.0 * abs(u - u_prev)), g)
    if bracket and (bisect or not (min(lo, hi) < nxt < max(lo, hi))):
        nxt = 0.5 * (lo + hi)
    return min(max(nxt, -limit), limit)
