"""Mutation audit of the blade-element integrand (core/_physics.py) and the per-point driver of
the compiled solver (core/_kernel.py).

The NumPy reference shares the element physics, so these tests pin it independently: the element
written out here from Gill & D'Andrea (2017) eqs (1)-(7) and the cambered polar's documented
corrections (airfoil.CamberedParams), Prandtl's loss factor from its definition, the momentum balance
of eq (11) in axial flow, and the totals as the quadrature of the per-annulus rows.
"""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.nodes import _nodes

from .conftest import RPM

GENERIC = pm.generic_params()
# the generic set with every per-annulus correction switched on (Reynolds shifts of the stall and the zero-lift
# angle, the rotational stall delay), so that each of cambered_annulus' terms moves the loads
CAM_ALL = GENERIC.replace(re_exp_stall=0.3, stall_delay=3.0, alpha_L0_re=math.radians(-2.0))


def _cambered_by_hand(p, air, c, y, theta, UT, UP, U2mean, delay=None):
    """qT, qH of the cambered polar (per unit 0.5 rho c), written from airfoil.CamberedParams' docs; with ``delay``
    (Gormont's d [rad]) the mean of the rising (stall angle + d) and the falling (- d / 2) blends."""
    ln_re = np.clip(np.log(air.rho * c * np.sqrt(U2mean) / (air.mu * p.re_ref)), math.log(0.1), math.log(5.0))
    a = p.cl_alpha * (np.exp(ln_re)) ** p.re_exp_lift
    if p.compressibility:
        a = a / np.sqrt(1.0 - np.minimum(U2mean / air.speed_of_sound**2, 0.81))
    cdf = np.exp(ln_re) ** p.re_exp
    g = (1.0 + p.stall_delay * (c / y) ** 2) * np.exp(ln_re) ** p.re_exp_stall
    phi = np.arctan2(UP, UT)
    ae = theta - p.alpha_L0 - p.alpha_L0_re * ln_re - phi
    alpha = theta - phi
    x = ae - g * p.cl_max / p.cl_alpha
    q1 = 1.0 + np.exp(-p.M * (ae - g * p.cl_min / p.cl_alpha))
    s = 1.0 - 1.0 / ((1.0 + np.exp(p.M * x)) * q1)
    if delay is not None:
        s = 1.0 - 0.5 * (1.0 / (1.0 + np.exp(p.M * (x - delay))) + 1.0 / (1.0 + np.exp(p.M * (x + 0.5 * delay)))) / q1
    CL = (1.0 - s) * a * ae + s * p.cd90 * np.sin(alpha) * np.cos(alpha)
    cdp = cdf * (p.cd_min + (1.0 - s) * p.cd2 * (a * ae - p.cl_cdmin) ** 2)  # the profile drag
    CD = cdp + s * p.cd90 * np.sin(alpha) ** 2
    U = np.hypot(UT, UP)
    return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT), cdp


def _edgewise(prop, p, om, V):
    """The solved loads at an edgewise point (radial rows kept) and its annuli's radii y, chords c, the half
    circle's 16 azimuth nodes psi and the blade's UT, UP there (UP the solved v_i)."""
    r = pm.rotor_loads(prop, p, om, V, math.pi / 2, radial=True)
    y = _nodes(prop, 48, 16, p.air, p).y
    psi = -0.5 * math.pi + (np.arange(16) + 0.5) * math.pi / 16
    UT = om * y[:, None] + V * np.sin(psi)[None, :]
    return r, y, prop.chord_at(y), psi, UT, np.broadcast_to(r.v_i[:, None], UT.shape)


@pytest.mark.parametrize("gamma", [0.0, 1.5])
def test_dynamic_stall_thrust_density_is_gormonts_delay_written_out(apc8x6, gamma):
    """Mutants M8 (Gormont's falling-blade delay + d / 2 instead of - d / 2) and M30 (the delay's bound DELAY_MAX
    30 deg instead of 20): at 5000 rpm, 16 m/s edgewise (mu 0.3)
    with the dynamic stall (uniform inflow, no in-plane induction or radial drag) each annulus' thrust density at the
    solved v_i is the azimuth mean of the polar written out with the blend's positive stall angle delayed by
    + d (rising) and - d / 2 (falling), d = min(gamma sqrt(c Omega / 2) sqrt(|v_i V cos psi|) / U^1.5, 20 deg);
    gamma = 0 is the static polar."""
    p = CAM_ALL.replace(inplane_induction=False, radial_drag=False, dynamic_stall=gamma)
    air = p.air
    om, V = 5000 * RPM, 16.0
    r, y, c, psi, UT, UP = _edgewise(apc8x6, p, om, V)
    c = c[:, None]
    d = np.minimum(gamma * np.sqrt(c * om / 2) * np.sqrt(np.abs(UP * V * np.cos(psi))) / np.hypot(UT, UP) ** 1.5,
                   math.radians(20.0))
    qT, _, _ = _cambered_by_hand(p, air, c, y[:, None], apc8x6.theta_at(y)[:, None], UT, UP,
                              ((om * y) ** 2 + 0.5 * V**2)[:, None], delay=d)
    dT = apc8x6.n_blades * 0.5 * air.rho * c[:, 0] * qT.mean(axis=1)
    np.testing.assert_allclose(r.dT_dr, dT, rtol=1e-9, atol=1e-9 * np.max(np.abs(dT)))
    if gamma:  # the delay acts at this point, and its 20 deg bound inboard
        assert np.max(d) > math.radians(5.0) and np.mean(d >= math.radians(20.0)) > 0.1


def _gill_by_hand(p, air, c, theta, UT, UP):
    """qT, qH of eqs (3)-(4) (per unit 0.5 rho c)."""
    U = np.hypot(UT, UP)
    alpha = theta - np.arctan2(UP, UT)
    s = 1.0 - 1.0 / ((1.0 + np.exp(p.M * (alpha - p.alpha0))) * (1.0 + np.exp(-p.M * (alpha + p.alpha0))))
    CL = (1.0 - s) * p.cl1 * alpha + s * p.cl2 * np.sin(alpha) * np.cos(alpha)
    re = air.rho * U * c / air.mu
    CD = p.cd * np.sin(alpha) ** 2 + 2.0 * 1.02 * p.cp_blasius / np.sqrt(re) + p.cd0
    return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT)


def _prandtl(f, UP, wy):
    """(2/pi) acos(exp(-f / sin phi)), sin phi = |U_P| / sqrt(U_P^2 + (Omega y)^2)."""
    sin_phi = np.abs(UP) / np.hypot(UP, wy)
    return 2.0 / math.pi * np.arccos(np.exp(-f / sin_phi))


@pytest.mark.parametrize("rpm, V, beta", [(8000.0, 0.0, 0.0), (6000.0, 9.0, 0.0), (20000.0, 0.0, 0.0),
                                          (5000.0, 6.0, math.pi), (7000.0, 22.0, 0.0)])
def test_cambered_axial_annulus_loads_are_the_polar_written_out(apc8x6, rpm, V, beta):
    """Mutants M2 (the flat-plate drag s cd90 sin a cos a), M3 (the Reynolds zero-lift shift's sign), M4 (Re from
    U^2 instead of U), M5 (Prandtl-Glauert multiplying) and M13 (the stall blend's half-width without the stall-angle
    factor g): in axial flow (one azimuth node, U_T = Omega y, U_P = V cos beta + v_i) dT/dr and dQ/dr at the solved
    v_i are N_b rho c / 2 times the element of the cambered polar, its Reynolds, Mach and stall-delay factors computed
    here from airfoil.CamberedParams' definitions (hover, climb, a 0.63-Mach tip, descent past stall, a windmilling
    inner blade)."""
    air = CAM_ALL.air
    r = pm.rotor_loads(apc8x6, CAM_ALL, rpm * RPM, V, beta, radial=True)
    nd = _nodes(apc8x6, 48, 16, air, CAM_ALL)
    y, om = nd.y, rpm * RPM
    c = apc8x6.chord_at(y)
    Vc = V * math.cos(beta)
    UT, UP = om * y, Vc + r.v_i
    qT, qH, _ = _cambered_by_hand(CAM_ALL, air, c, y, apc8x6.theta_at(y), UT, UP, (om * y) ** 2 + Vc**2)
    cfac = apc8x6.n_blades * 0.5 * air.rho * c
    scale = np.max(np.abs(cfac * qT))
    np.testing.assert_allclose(r.dT_dr, cfac * qT, rtol=1e-9, atol=1e-9 * scale)
    np.testing.assert_allclose(r.dQ_dr, y * cfac * qH, rtol=1e-9, atol=1e-9 * np.max(np.abs(y * cfac * qH)))
    assert float(r.drag) == 0.0


def test_cambered_edgewise_loads_use_the_azimuth_mean_square_speed_and_the_radial_drag(apc8x6):
    """Mutants M11 (the kernel's per-annulus mean U^2 with V_s^2 instead of V_s^2 / 2) and M29 (the radial flow's
    profile drag without the stall blend's (1 - s) on the quadratic polar): at 8000 rpm, 15 m/s edgewise (uniform
    inflow, no in-plane induction, so that each annulus is eq 5's half-circle midpoint sum) the thrust density at the
    solved v_i is the azimuth mean of the polar written out with U^2 = (Omega y)^2 + V^2 / 2 in its Reynolds and Mach
    factors, and the drag density that mean of dH sin psi plus the radial flow's C_D,p U V cos^2 psi."""
    p = CAM_ALL.replace(inplane_induction=False, radial_drag=True)
    air = p.air
    om, V = 8000 * RPM, 15.0
    r, y, c, psi, UT, UP = _edgewise(apc8x6, p, om, V)
    qT, qH, cdp = _cambered_by_hand(p, air, c[:, None], y[:, None], apc8x6.theta_at(y)[:, None], UT, UP,
                                    ((om * y) ** 2 + 0.5 * V**2)[:, None])
    cfac = apc8x6.n_blades * 0.5 * air.rho * c
    dT = cfac * qT.mean(axis=1)
    np.testing.assert_allclose(r.dT_dr, dT, rtol=1e-9, atol=1e-9 * np.max(np.abs(dT)))
    dD = cfac * (qH * np.sin(psi) + V * cdp * np.hypot(UT, UP) * np.cos(psi) ** 2).mean(axis=1)
    np.testing.assert_allclose(r.dD_dr, dD, rtol=1e-9, atol=1e-9 * np.max(np.abs(dD)))


def test_gill_edgewise_drag_with_the_radial_flows_profile_drag_written_out(apc8x6, apc_params):
    """Mutant M21 (the paper's profile drag with kre / U instead of kre / sqrt(U) in the radial flow's drag): at 7000
    rpm, 12 m/s edgewise with ``radial_drag`` each annulus' drag density at the solved v_i is the half-circle mean of
    eq (6)'s in-plane force times sin psi plus the radial flow's C_D,p U V cos^2 psi, C_D,p = eq (4)'s Blasius and
    form terms 2 * 1.02 c_p / sqrt(Re) + cd0 written out."""
    p = apc_params.replace(radial_drag=True)
    air = p.air
    om, V = 7000 * RPM, 12.0
    r, y, c, psi, UT, UP = _edgewise(apc8x6, p, om, V)
    c = c[:, None]
    _, qH = _gill_by_hand(p, air, c, apc8x6.theta_at(y)[:, None], UT, UP)
    U = np.hypot(UT, UP)
    cdp = 2.0 * 1.02 * p.cp_blasius / np.sqrt(air.rho * U * c / air.mu) + p.cd0
    dD = apc8x6.n_blades * 0.5 * air.rho * c[:, 0] * (qH * np.sin(psi) + V * cdp * U * np.cos(psi) ** 2).mean(axis=1)
    np.testing.assert_allclose(r.dD_dr, dD, rtol=1e-9, atol=1e-9 * np.max(np.abs(dD)))


def test_a_sharp_stall_blend_is_post_stall_at_large_negative_angles(apc_params):
    """Mutant M1 (the blend's p = exp(z - h) without |z|): eq (3)'s sigma is even in alpha, so with a sharp blend
    (M = 400) at -0.5 rad, far below -alpha0, the lift is footnote 1's post-stall cl2 sin a cos a as at +0.5 rad,
    not the attached cl1 alpha (the saturated exp(z - h) loses the q = exp(-M(a + a0)) side)."""
    p = apc_params.replace(M=400.0)
    for a in (-0.5, 0.5, -1.2):
        assert pm.lift_coefficient(a, p) == pytest.approx(p.cl2 * math.sin(a) * math.cos(a), rel=1e-12)
    c = pm.generic_params().replace(M=400.0)
    ae = -0.6  # from the zero-lift line, far below the negative stall angle cl_min / cl_alpha
    a = c.alpha_L0 + ae
    assert pm.lift_coefficient(a, c) == pytest.approx(c.cd90 * math.sin(a) * math.cos(a), rel=1e-9)


@pytest.mark.parametrize("hub", [False, True])
@pytest.mark.parametrize("V", [0.0, 7.0])
def test_axial_momentum_balance_with_prandtls_factor_written_out(apc8x6, hub, V):
    """Mutants M6 (Prandtl's exp(-f sin phi) for exp(-f / sin phi)) and M25 (asin for acos in Prandtl's factor): in
    hover and axial climb each annulus' blade-element thrust equals eq (10) with Prandtl's factor,
    F 4 pi rho y v_i (V + v_i), F = F_tip F_hub from their definitions (2/pi) acos(exp(-f / sin phi))."""
    p = GENERIC.replace(hub_loss=hub)
    air = p.air
    om = 7000 * RPM
    r = pm.rotor_loads(apc8x6, p, om, V, 0.0, radial=True)
    y = _nodes(apc8x6, 48, 16, air, p).y
    R, rh, nb = apc8x6.radius, apc8x6.r_hub, apc8x6.n_blades
    UP = V + r.v_i
    F = _prandtl(0.5 * nb * (R - y) / y, UP, om * y)
    if hub:
        F = F * _prandtl(0.5 * nb * (y - rh) / rh, UP, om * y)
    assert F[-1] < 0.5 and (not hub or F[0] < 0.5)  # the losses matter at these annuli
    dT = F * 4 * math.pi * air.rho * y * r.v_i * UP
    np.testing.assert_allclose(r.dT_dr, dT, rtol=1e-5, atol=1e-6 * np.max(dT))


@pytest.mark.parametrize("opts", [dict(inflow="drees"), dict(inflow="pitt-peters", swirl=True),
                                  dict(dynamic_stall=1.0)])
def test_totals_are_the_quadrature_of_the_annulus_rows(apc8x6, opts):
    """Mutants M9 (the side force summed from the pitching-moment rows) and M14 (v_i_mean not area-weighted): in
    forward flight with a linear inflow or the dynamic stall, where Y and M_P are not zero, each of the six totals is
    the Gauss-Legendre sum of its per-annulus row, and v_i_mean the area-weighted mean sum w y v_i / sum w y."""
    p = GENERIC.replace(**opts)
    r = pm.rotor_loads(apc8x6, p, np.array([6000.0, 9000.0]) * RPM, np.array([8.0, 14.0]),
                       np.radians([60.0, 100.0]), radial=True)
    nd = _nodes(apc8x6, 48, 16, p.air, p)
    w, y = nd.w, nd.y
    assert np.all(np.abs(r.side_force) > 1e-4) and np.all(np.abs(r.pitching_moment) > 1e-5)
    for total, row in ((r.thrust, r.dT_dr), (r.drag, r.dD_dr), (r.torque, r.dQ_dr), (r.rolling_moment, r.dMR_dr),
                       (r.side_force, r.dY_dr), (r.pitching_moment, r.dMP_dr)):
        np.testing.assert_allclose(total, row @ w, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(r.v_i_mean, (r.v_i * y) @ w / (y @ w), rtol=1e-12)
    assert not np.allclose(r.v_i_mean, r.v_i @ w / w.sum(), rtol=1e-3)  # the two weightings differ here


def test_a_linear_inflow_counts_both_of_its_root_solves(apc8x6):
    """Mutant M15 (the linear inflow's second solve left out of n_evaluations): at forward-flight points the
    Drees inflow solves every annulus twice, with the uniform inflow (exactly the uniform model's solve) and then
    with its gradients, so it counts at least 2 evaluations per annulus more than the uniform model."""
    om, V, b = np.array([6000.0, 9000.0]) * RPM, np.array([8.0, 14.0]), np.radians([60.0, 100.0])
    uni = pm.rotor_loads(apc8x6, GENERIC, om, V, b)
    lin = pm.rotor_loads(apc8x6, GENERIC.replace(inflow="drees"), om, V, b)
    assert np.all(lin.n_evaluations >= uni.n_evaluations + 2 * pm.DEFAULT_DISCRETIZATION.n_radial)
    # and axial points are solved once (the gradients vanish there): the same count as the uniform model
    ax_u = pm.rotor_loads(apc8x6, GENERIC, om, V, 0.0)
    ax_l = pm.rotor_loads(apc8x6, GENERIC.replace(inflow="drees"), om, V, 0.0)
    np.testing.assert_array_equal(ax_l.n_evaluations, ax_u.n_evaluations)
