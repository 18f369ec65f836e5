"""A mutation audit of the core physics (stop 97): hand-made mutants of the element and section physics
(core/_physics.py, polar.py), the momentum side (_momentum.py), the annulus root solve and loads (_annulus.py,
_annulus_loads.py), the kernel's sums (_kernel.py), the flags (_flags.py), the nodes (nodes.py), the disk frame
(_frame.py), flapping.py, interference.py, states.py, air.py and geometry.py, run against the tests of those
modules. Each test here fails on the mutant named in its comment and passes on the code; it asserts physics
(a documented invariant of the model, a symmetry, a value written out from its definition) or a regression
value labelled as such, not how the code computes it. Of 68 mutants the existing tests killed 61; three are
equivalent (P8: Prandtl's clamp of exp(-f) at 1 acts only for f < 6e-14, which no Gauss node reaches; A8:
sqrt((|Vc| + v)^2) is |Vc + v| for Vc >= 0; AIR3: the ISA's layers meet at 11 km to 8.8e-7); the four
survivors that are gaps (P1, P10, FR1, FR3) are killed here, and two tests pin values whose mutants were killed
before only through derivative checks (the linear inflow's loads, the flapping). Data: the catalogue's
apce_8x6 and the paper's and the generic sets."""

from __future__ import annotations

import math

import numpy as np
import pytest

import propmap as pm

from .conftest import RPM

GILL = pm.preset("gill2017-apc")
GENERIC = pm.generic_params()


@pytest.fixture(scope="module")
def apc8x6_prop():
    return pm.load_propeller("apce_8x6")


# --- the section (core/_physics.py through core/polar.py)

@pytest.mark.parametrize("M", [1.0, 3.0])
def test_the_papers_lift_is_periodic_in_the_angle_of_attack(M):
    """P1 (the element's wrap of alpha into (-pi, pi] dropped): eq (3)'s C_L is a function of the flow's
    direction, so C_L(alpha + 2 pi) = C_L(alpha); with a soft blend (small M) the attached term cl1 alpha is
    still felt at |alpha| ~ pi, where the unwrapped angle gave it the other sign (reverse flow in descent)."""
    p = GILL.replace(M=M)
    a = np.radians(np.arange(-175.0, 180.0, 5.0))
    for k in (-1, 1):
        np.testing.assert_allclose(pm.lift_coefficient(a + 2 * k * np.pi, p), pm.lift_coefficient(a, p),
                                   rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(pm.drag_coefficient(a + 2 * k * np.pi, 1e5, p), pm.drag_coefficient(a, 1e5, p),
                                   rtol=1e-12, atol=1e-12)


def test_the_cambered_polars_compressibility_is_capped_at_mach_0_9():
    """P10 (the cap of Ma^2 at 0.81 raised to 0.99): the Prandtl-Glauert factor 1 / sqrt(1 - Ma^2) on the lift
    slope stops at Mach 0.9 (airfoil.CamberedParams, compressibility), so C_L at Mach 0.95 is C_L at 0.9; below
    the cap the lift's change with Mach is (1 - s) C_L,att (1/sqrt(1 - Ma^2) - 1), whose ratio between two Mach
    numbers is that of the factors whatever the stall blend s."""
    a = np.radians([-2.0, 2.0, 6.0, 10.0])
    cl = {m: pm.lift_coefficient(a, GENERIC, 1e5, m) for m in (0.0, 0.5, 0.8, 0.9, 0.95)}
    np.testing.assert_array_equal(cl[0.95], cl[0.9])
    pg = {m: 1 / math.sqrt(1 - m * m) - 1 for m in (0.5, 0.8)}
    np.testing.assert_allclose((cl[0.8] - cl[0.0]) / (cl[0.5] - cl[0.0]), pg[0.8] / pg[0.5], rtol=1e-10)


# --- the linear inflow's loads (core/_kernel.py's gradients, core/_annulus_loads.py's full-circle sums)

def _linear_inflow_rows_written_out(prop, params, om, V, beta, disc):
    """The six load densities of every annulus written out from their definitions at the solver's roots v_i(r)
    (the kernel's own nodes): the wake skew from the uniform solve's area-weighted mean inflow
    (_momentum.skew_inflow_ratio), the gradients k_x, k_y (_momentum.inflow_gradients) times y/R, the inflow
    v (1 + g_x cos psi + g_y sin psi) over the full circle, the blades' in-plane airspeed plus the skewed wake's
    in-plane induction (inplane_induction), the radial flow's profile drag C_D,p U u_R (u_R = V_b cos psi) and
    dT, dD = <dH sin psi + radial cos psi>, dQ = y <dH>, dM_R = y <dT sin psi>, dY = <-dH cos psi + radial sin
    psi>, dM_P = -y <dT cos psi> (annulus_loads' docstring). Returns (the loads, those rows)."""
    from propmap.core import _momentum as mo
    from propmap.core import _physics as ph
    from propmap.core.nodes import _nodes
    from propmap.core.polar import _model_constants

    r = pm.rotor_loads(prop, params, om, V, beta, discretization=disc, radial=True)
    uni = pm.rotor_loads(prop, params.replace(inflow="uniform"), om, V, beta, discretization=disc)
    nd = _nodes(prop, disc.n_radial, disc.n_azimuth, params.air, params)
    model, pk = _model_constants(params)
    Vs, Vc, OmR = V * math.sin(beta), V * math.cos(beta), om * prop.radius
    kx, ky = mo.inflow_gradients(Vs / OmR, mo.skew_inflow_ratio(Vc, float(uni.v_i_mean), OmR),
                                 mo.INFLOW_CODES[params.inflow])
    y, v = nd.y[:, None], np.asarray(r.v_i)[:, None]
    sp, cp = nd.sinpsi[None, :], nd.cospsi[None, :]
    Vb = Vs + (mo.inplane_induction_numpy(v, Vs, Vc) if params.inplane_induction else 0.0)
    UT = om * y + Vb * sp
    UP = Vc + v * (1 + kx * y / prop.radius * cp + ky * y / prop.radius * sp)
    if model == ph.CAMBERED:
        a = params.air
        sec = ph.cambered_annulus((om * nd.y) ** 2 + 0.5 * Vs * Vs + Vc * Vc, nd.sc, nd.cy2, 1 / a.speed_of_sound ** 2,
                                  params.cl_alpha, params.re_exp, params.re_exp_lift, params.compressibility,
                                  params.re_exp_stall, params.stall_delay, params.alpha_L0_re)
    else:
        sec = (nd.sc, 0.0 * nd.sc, 0.0 * nd.sc, 0.0 * nd.sc)
    sec = [np.asarray(s)[:, None] * np.ones_like(sp) for s in sec]
    th = (nd.theta[:, None], nd.sin_th[:, None], nd.cos_th[:, None])
    qT, qH = ph.element(UT, UP, *th, *sec, model, pk)
    radial = 0.0
    if params.radial_drag:
        radial = Vb * ph.profile_cd(UT, UP, th[0], *sec, model, pk) * np.sqrt(UT * UT + UP * UP) * cp
    c = nd.cfac[:, None]
    rows = {"dT_dr": c * qT, "dD_dr": c * (qH * sp + radial * cp), "dQ_dr": y * c * qH, "dMR_dr": y * c * qT * sp,
            "dY_dr": c * (radial * sp - qH * cp), "dMP_dr": -y * c * qT * cp}
    return r, nd, {k: a.mean(axis=1) for k, a in rows.items()}


@pytest.mark.parametrize("params, V, beta_deg", [
    (GILL.replace(inflow="drees"), 8.0, 90.0), (GILL.replace(inflow="pitt-peters"), 12.0, 60.0),
    (GENERIC.replace(inflow="pitt-peters"), 10.0, 75.0), (GENERIC.replace(inflow="drees"), 6.0, 120.0)])
def test_linear_inflow_loads_are_their_full_circle_quadrature(apc8x6_prop, params, V, beta_deg):
    """K1 (the wake skew from the uniform roots' plain mean, not the area-weighted one), K2 (g_x = k_x, not
    k_x y/R), K3 (g_y = -k_y y/R), L2 (the side force's -dH cos psi summed with +), L3 (the pitching moment's
    -dT cos psi summed with +), L4 (the radial drag's side-force part gR sin psi with -): with a linear inflow
    model the NumPy reference does not apply, so each annulus' six densities and the totals (their Gauss sums)
    are written out here from the model's definitions at the kernel's roots; they agree to 1e-9. (The six mutants
    were killed before only by test_audit_kernel_roots' slope check of the derivatives at edgewise flight: no
    test pinned these loads' values.)"""
    disc = pm.Discretization(24, 12)
    r, nd, rows = _linear_inflow_rows_written_out(apc8x6_prop, params, 7000 * RPM, V, math.radians(beta_deg), disc)
    totals = {"dT_dr": "thrust", "dD_dr": "drag", "dQ_dr": "torque", "dMR_dr": "rolling_moment",
              "dY_dr": "side_force", "dMP_dr": "pitching_moment"}
    for k, load in totals.items():
        big = float(np.max(np.abs(rows[k])))
        np.testing.assert_allclose(np.asarray(getattr(r, k)), rows[k], rtol=1e-9, atol=1e-9 * big, err_msg=k)
        assert float(getattr(r, load)) == pytest.approx(float(rows[k] @ nd.w), rel=1e-9, abs=1e-9 * big), load
    assert abs(float(r.pitching_moment)) > 1e-3 * float(r.torque)  # (the case: the cos psi terms are not zero)


# --- flapping (core/flapping.py, core/nodes.py's int c r^3 dr)

@pytest.mark.parametrize("inflow", ["uniform", "pitt-peters"])
def test_flapping_is_the_harmonic_balance_of_the_flap_equation(apc8x6_prop, inflow):
    """FL1 (M_1c = +2 M_P / N_b), FL2 (beta_1s with -D M_1c), FL3 (D_beta with Omega, not Omega^2), FL5 (the
    side force tilted with +T beta_1s), N5 (int c r^3 dr summed as int c r^2 dr): the first harmonics of the flap
    equation, K beta_1c + D beta_1s = M_1c and -D beta_1c + K beta_1s = M_1s (core/flapping.py's docstring), with
    K = 1 / compliance, the rigid blades' M_1s = 2 M_R / N_b, M_1c = -2 M_P / N_b and the aerodynamic damping
    D = (rho a / 2) Omega^2 int c r^3 dr (the integral by adaptive quadrature of the chord here); the thrust
    tilts with the tip-path plane (D - T beta_1c, Y - T beta_1s) and the hub moments become the springs'. With a
    linear inflow the rigid rotor has a pitching moment, so M_1c enters too. (FL5 and N5 were killed before only
    by derivative checks, FL1-FL3 by the rigid and articulated limits and the Lock-number form of D.)"""
    from scipy.integrate import quad

    prop, comp = apc8x6_prop, 2.0
    rigid = GILL.replace(inflow=inflow)
    om, V, beta = 7000 * RPM, np.array([4.0, 10.0]), math.radians(80.0)
    rig = pm.rotor_loads(prop, rigid, om, V, beta)
    fl = pm.rotor_loads(prop, rigid.replace(flap_compliance=comp), om, V, beta)
    K, nb, T = 1 / comp, prop.n_blades, rig.thrust
    int_cr3 = quad(lambda y: float(prop.chord_at(y)) * y ** 3, prop.r_hub, prop.radius, limit=200)[0]
    D = 0.5 * GILL.air.rho * GILL.cl1 * int_cr3 * om ** 2
    m1s, m1c = 2 * rig.rolling_moment / nb, -2 * rig.pitching_moment / nb
    b1c, b1s = fl.flap_1c, fl.flap_1s
    tol = 1e-4 * np.abs(m1s).max()  # (the kernel integrates c r^3 by its Gauss nodes: 2e-5 apart)
    np.testing.assert_allclose(K * b1c + D * b1s, m1c, rtol=1e-4, atol=tol)
    np.testing.assert_allclose(-D * b1c + K * b1s, m1s, rtol=1e-4, atol=tol)
    np.testing.assert_allclose(fl.thrust, T, rtol=1e-14)
    np.testing.assert_allclose(fl.drag, rig.drag - T * b1c, rtol=1e-12)
    np.testing.assert_allclose(fl.side_force, rig.side_force - T * b1s, rtol=1e-12, atol=1e-12 * T.max())
    np.testing.assert_allclose(fl.rolling_moment, 0.5 * nb * K * b1s, rtol=1e-12)
    np.testing.assert_allclose(fl.pitching_moment, -0.5 * nb * K * b1c, rtol=1e-12)
    assert np.all(np.abs(b1c) > 1e-3) and np.all(np.abs(b1s) > 1e-4)  # (the case: the blades flap)
    if inflow != "uniform":
        assert np.all(np.abs(m1c) > 0.02 * np.abs(m1s))


# --- the disk frame's vectors (core/_frame.py)

@pytest.mark.parametrize("spin", ["ccw", "cw"])
def test_the_side_force_and_pitching_moment_vectors_are_where_their_lever_arms_put_them(apc8x6_prop, spin):
    """FR1 (the pitching moment's vector M_P (e_ip x z) with the other sign) and FR3 (the side force's vector
    without the spin): a rotor on +z moving along +x with a linear inflow (which gives M_P and Y). The upstream
    half (psi = 180 deg) is at +x, so more thrust there (M_P > 0) acts at the lever arm +x: x X z = -y, the
    nose-up moment, whatever the spin; the advancing blade is at -y for "ccw" and at +y for "cw"
    (Omega z x r along +x), so the side force toward the advancing side Y > 0 is along -spin y
    (docs/conventions.md)."""
    p = GILL.replace(inflow="pitt-peters")
    om, vel = 7000 * RPM, np.array([8.0, 0.0, 1.0])
    w = pm.rotor_wrench(apc8x6_prop, p, vel, [0.0, 0.0, 1.0], om, spin)
    r = pm.rotor_loads(apc8x6_prop, p, om, float(np.linalg.norm(vel)), math.atan2(8.0, 1.0))
    s = 1.0 if spin == "ccw" else -1.0
    T, D, Q, MR, Y, MP = (float(getattr(r, k)) for k in ("thrust", "drag", "torque", "rolling_moment", "side_force",
                                                          "pitching_moment"))
    assert MP > 1e-4 and abs(Y) > 1e-4  # (the case: both present)
    np.testing.assert_allclose(w.force, [-D, -s * Y, T], rtol=1e-12, atol=1e-12 * T)
    np.testing.assert_allclose(w.torque, [-s * MR, -MP, -s * Q], rtol=1e-12, atol=1e-12 * Q)
