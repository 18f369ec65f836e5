"""Gormont's quasi-steady dynamic stall (RotorOptions.dynamic_stall; docs/models.md, Dynamic stall):
zero effect in axial flow and at gamma 0, the element's node-and-mirror mean, the edgewise thrust
rise against the wind tunnel's (Gill & D'Andrea, Drones 3(4):77, 2019, Appendix A; the
gill2019 case), the options it refuses, and the parameter file.

The kernel against the NumPy reference with the option is in tests/test_solver_roots.py.
"""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core._physics import element_cambered, element_cambered_delayed
from propmap.core.derivatives import differentiable

RPM = math.pi / 30


@pytest.fixture(scope="module")
def apce8x6():
    return pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")


def test_axial_flow_and_gamma_zero_are_the_static_polar_exactly(apce8x6):
    prop, p = apce8x6
    om = np.full(5, 6000 * RPM)
    V = np.array([0.0, 5.0, 10.0, 8.0, 12.0])
    inc = np.array([0.0, 0.0, 0.0, math.pi, math.pi / 3])
    base = pm.rotor_loads(prop, p, om, V, inc)
    ds = pm.rotor_loads(prop, p.replace(dynamic_stall=1.5), om, V, inc)
    axial = np.array([True, True, True, True, False])
    for q in ("thrust", "drag", "torque", "rolling_moment"):
        np.testing.assert_array_equal(getattr(ds, q)[axial], getattr(base, q)[axial])  # alpha_dot = 0 there
    assert ds.thrust[~axial][0] != base.thrust[~axial][0]
    zero = pm.rotor_loads(prop, p.replace(dynamic_stall=0.0), om, V, inc)
    np.testing.assert_array_equal(zero.thrust, base.thrust)


def test_the_delayed_element_is_the_mean_of_the_rising_and_the_falling_blend():
    """d = 0 gives the static element (to rounding: the static blend takes one exponential since
    2026-11-27, _physics.make_stall_blend, the delayed one's two each); otherwise the mean of the element
    with the stall angle moved up by d (the angle rising) and down by d / 2 (falling), C_L and C_D being
    linear in the blend (checked against a direct evaluation with shifted stall angles)."""
    UT, UP = np.array([30.0, 45.0, 60.0]), np.array([8.0, 9.0, 7.0])
    th, a, cdf, g, dal0 = 0.35, 5.8, 1.1, 1.0, -0.01
    pk = (-0.08, 1.98, 0.012, 0.065, 0.5, 12.0, 0.3, -0.08)
    static = element_cambered(UT, UP, th, math.sin(th), math.cos(th), a, cdf, g, dal0, *pk)
    same = element_cambered_delayed(UT, UP, th, math.sin(th), math.cos(th), a, cdf, g, dal0, *pk, 0.0, 5.0)
    np.testing.assert_allclose(same[0], static[0], rtol=1e-14, atol=0)
    kd, vcos = 2.0, 6.0
    got = element_cambered_delayed(UT, UP, th, math.sin(th), math.cos(th), a, cdf, g, dal0, *pk, kd, vcos)
    d = kd * np.sqrt(np.abs(UP * vcos) / np.hypot(UT, UP) ** 3)
    shifted = [element_cambered(UT, UP, th, math.sin(th), math.cos(th), a, cdf, g, dal0, *pk[:6], pk[6] + s * d / g,
                                pk[7]) for s in (1.0, -0.5)]
    for k in range(2):
        np.testing.assert_allclose(got[k], 0.5 * (shifted[0][k] + shifted[1][k]), rtol=1e-12)


def test_the_edgewise_thrust_rise_comes_near_the_tunnels(apce8x6):
    """APC 8x6E, its calibrated set, 6000 rpm, mu = 0.2 edgewise: the tunnel's thrust rises by
    16.5% (Gill & D'Andrea 2019's k2 mu^2 / CT_static), the static polar's by 6.2%, Gormont's
    gamma = 1.5 (published, not fitted) by 15.7% (regression values, 2026-11-26); the torque rise
    5.5% -> 10.3% (tunnel 15.2%)."""
    prop, p = apce8x6
    om = 6000 * RPM
    V = np.array([0.0, 0.2 * om * prop.radius])
    inc = np.array([0.0, math.pi / 2])
    r0 = pm.rotor_loads(prop, p, om, V, inc)
    r1 = pm.rotor_loads(prop, p.replace(dynamic_stall=1.5), om, V, inc)
    assert r0.thrust[1] / r0.thrust[0] - 1 == pytest.approx(0.062, abs=0.002)
    assert r1.thrust[1] / r1.thrust[0] - 1 == pytest.approx(0.157, abs=0.002)
    assert r1.torque[1] / r1.torque[0] - 1 == pytest.approx(0.103, abs=0.002)


def test_below_mu_0_2_the_square_root_overshoots_and_makes_a_cusp_at_hover(apce8x6):
    """Why the option is not the default (docs/models.md, Dynamic stall): Gormont's delay grows as
    the square root of the pitch rate, so the thrust gain from hover as sqrt(V) (exponent 0.4-0.65
    between 0.01 and 0.1 m/s edgewise) where the static polar's grows as V^2; at mu = 0.05 the rise
    is 7.0% against the tunnel's 1.03% (Gill & D'Andrea 2019's k2 mu^2 / CT_static) and the static
    polar's 0.79% (regression values, 2026-11-26)."""
    prop, p = apce8x6
    om = 6000 * RPM
    V = np.array([0.0, 0.01, 0.1, 0.05 * om * prop.radius])
    inc = np.full(4, math.pi / 2)
    for gamma, lo, hi in ((1.5, 0.4, 0.65), (0.0, 1.9, 2.1)):
        r = pm.rotor_loads(prop, p.replace(dynamic_stall=gamma), om, V, inc)
        gain = r.thrust / r.thrust[0] - 1.0
        assert lo < math.log10(gain[2] / gain[1]) < hi
        assert gain[3] == pytest.approx(0.0696 if gamma else 0.0079, rel=0.03)
    assert abs(float(r.side_force[1])) == 0.0
    ds = pm.rotor_loads(prop, p.replace(dynamic_stall=1.5), om, 0.01, math.pi / 2)
    assert abs(float(ds.side_force)) > 5 * float(ds.drag)  # at 1 cm/s: a side force ten times the drag


def test_what_the_option_refuses(apce8x6):
    prop, p = apce8x6
    with pytest.raises(ValueError, match="dynamic_stall applies to the cambered section model"):
        pm.preset("gill2017-apc").replace(dynamic_stall=1.5)
    with pytest.raises(ValueError, match="dynamic_stall needs the uniform inflow"):
        p.replace(dynamic_stall=1.5, inflow="pitt-peters")
    with pytest.raises(ValueError, match="dynamic_stall"):
        p.replace(dynamic_stall=6.0)
    ds = p.replace(dynamic_stall=1.5)
    assert differentiable(ds, ("omega", "cl_alpha", "rho")) and not differentiable(ds, ("dynamic_stall",))
    with pytest.raises(ValueError, match="derivatives with respect to dynamic_stall"):
        pm.rotor_loads(prop, ds, 600.0, 5.0, 1.0, derivatives=("dynamic_stall",))


def test_the_delayed_elements_partials_match_central_differences():
    """core/_tangents.make_delayed_direction (the NumPy twin of the kernel's) against Richardson-
    extrapolated central differences of the delayed element with its halves, along random
    directions in U_T, U_P, the blade angle, ln kd and the section's and polar's constants, on
    random states over both signs of U_T, U_P and the node's cos psi, through stall and through
    the delay's bound; the loads it carries are the element's."""
    from propmap.core._physics import element_cambered_delayed_h
    from propmap.core._tangents import delayed_direction, delayed_state

    rng = np.random.default_rng(3)
    n = 2000
    UT, UP, th = rng.uniform(-20, 120, n), rng.uniform(-30, 30, n), rng.uniform(-0.3, 0.9, n)
    sec = (rng.uniform(3, 6, n), rng.uniform(0.5, 2, n), rng.uniform(0.5, 1.5, n), rng.uniform(-0.05, 0.05, n))
    con = (-0.08, 1.8, 0.02, 0.05, 0.3, 12.0, 0.2, -0.15)
    kd, vcos = rng.uniform(0.0, 3.0, n), rng.uniform(-20, 20, n)
    dsec = tuple(rng.normal(size=(4, n)) * np.array([0.5, 0.1, 0.1, 0.01])[:, None])
    dcon = tuple(rng.normal(size=(8, n)) * np.array([0.01, 0.1, 0.005, 0.01, 0.05, 2.0, 0.02, 0.02])[:, None])
    speed = np.maximum(np.hypot(UT, UP), 1.0)
    dUT, dUP, dth, dlk = rng.normal(size=(4, n)) * np.array([1.0, 1.0, 0.0, 0.0])[:, None] * speed \
        + rng.normal(size=(4, n)) * np.array([0.0, 0.0, 1.0, 1.0])[:, None]

    def f(t):
        tt = th + t * dth
        return np.array(element_cambered_delayed_h(UT + t * dUT, UP + t * dUP, tt, np.sin(tt), np.cos(tt),
                                                   *(s + t * d for s, d in zip(sec, dsec)),
                                                   *(c + t * d for c, d in zip(con, dcon)), kd * np.exp(t * dlk),
                                                   vcos))
    st = delayed_state(UT, UP, th, np.sin(th), np.cos(th), sec, con, kd, vcos)
    f0 = f(0.0)
    np.testing.assert_allclose(np.array(st[0][:6]), f0, rtol=1e-13, atol=1e-11)
    assert 0 < np.sum(st[0][6] == 0.0) < n  # some delays at their bound (and their partials 0)
    got = np.array(delayed_direction(st, dUT, dUP, dth, st[0][6] * dlk, dsec, dcon))
    h = 1e-5
    fd = (4 * (f(h / 2) - f(-h / 2)) / h - (f(h) - f(-h)) / (2 * h)) / 3
    # of each output's largest value over the states (5.6e-8 seen: the square root of |U_P| is steep near U_P = 0)
    assert np.max(np.abs(got - fd) / (np.abs(f0).max(axis=1, keepdims=True) + 1e-9)) < 2e-7


@pytest.mark.parametrize("options", [{}, {"swirl": True}, {"flap_compliance": 0.5}], ids=["rigid", "swirl", "flap"])
def test_implicit_derivatives_with_the_dynamic_stall(apce8x6, options):
    """Issue 20's implicit derivatives with the option (core/_delayed_sensitivity.py) against
    central differences of the solver: T, D, Q, M_R and the side force and pitching moment of the
    rising and falling halves, with respect to omega, the airspeed, the incidence, section
    parameters and the air density, at 6000-10000 rpm, mu 0.1-0.3, with the delay active (each
    within 2e-6 of the point's thrust or torque per unit of the input's scale; the differences
    carry the root tolerance over their step)."""
    prop, p = apce8x6
    p = p.replace(dynamic_stall=1.5, **options)
    disc = pm.Discretization(24, 8)
    names = ("cl_alpha", "alpha_L0", "cd_min", "M")
    loads = ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment")
    for rpm, mu, inc_deg in ((6000, 0.2, 80.0), (10000, 0.1, 45.0), (7000, 0.3, 100.0)):
        om = rpm * RPM
        V, b = mu * om * prop.radius, math.radians(inc_deg)
        r = pm.rotor_loads(prop, p, om, V, b, discretization=disc,
                           derivatives=("omega", "airspeed", "incidence", *names, "rho"))
        assert abs(float(r.pitching_moment)) > 0.01 * float(r.torque)  # the halves are there
        scale = np.array([float(r.thrust)] * 2 + [float(r.torque)] * 2 + [float(r.thrust), float(r.torque)])

        def at(**kw):
            x = {"om": om, "V": V, "b": b, "p": p} | kw
            q = pm.rotor_loads(prop, x["p"], x["om"], x["V"], x["b"], discretization=disc)
            return np.array([float(getattr(q, k)) for k in loads])
        steps = {"omega": (lambda d: at(om=om + d), 1e-4 * om, om), "airspeed": (lambda d: at(V=V + d), 1e-4 * V, V),
                 "incidence": (lambda d: at(b=b + d), 1e-4, 1.0),
                 "rho": (lambda d: at(p=p.replace(air=pm.Air(rho=p.air.rho + d, mu=p.air.mu))), 1e-4, p.air.rho)}
        for name in names:
            x0 = getattr(p, name)
            steps[name] = (lambda d, name=name, x0=x0: at(p=p.replace(**{name: x0 + d})),
                           1e-4 * max(abs(x0), 0.01), max(abs(x0), 0.01))
        for wrt, (f, h, sx) in steps.items():
            fd = (f(h) - f(-h)) / (2 * h)
            got = np.array([float(r.derivative(q, wrt)) for q in loads])
            np.testing.assert_array_less(np.abs(got - fd) * sx / scale, 2e-6, err_msg=f"{rpm} rpm, mu {mu}, {wrt}")


def test_the_parameter_file_carries_it_and_an_older_file_has_it_off(tmp_path, recwarn):
    p = pm.generic_params().replace(dynamic_stall=1.5)
    pm.write_params(tmp_path / "p.toml", p)
    assert pm.read_params(tmp_path / "p.toml").dynamic_stall == 1.5
    text = (tmp_path / "p.toml").read_text()
    (tmp_path / "old.toml").write_text("\n".join(line for line in text.splitlines()
                                                 if not line.startswith("dynamic_stall")))
    old = pm.read_params(tmp_path / "old.toml")
    assert old.dynamic_stall == 0.0
    assert not any("dynamic_stall" in str(w.message) for w in recwarn)  # off where absent, unnamed


@pytest.mark.parametrize("rpm, mu, incidence_deg", [(6000, 0.2, 90.0), (6000, 0.1, 60.0), (4000, 0.3, 120.0)])
def test_loads_against_an_independent_full_circle(apce8x6, rpm, mu, incidence_deg):
    """The kernel's loads with the dynamic stall against the static element evaluated on the full
    circle of azimuth nodes at the kernel's own inflow, each node's stall angle moved by
    +d where alpha_dot = Omega U_P V_b cos(psi) / U^2 > 0 and -d/2 where it is < 0 (Gormont's
    K1), d bounded at DELAY_MAX: thrust, torque, rolling moment, and the pitching moment and side
    force that the rising and falling halves make (reported as 0 in a first version: a review,
    2026-11-26). The descent case (120 deg) has U_P < 0 on most annuli, which turns the halves."""
    from propmap.core._physics import (CAMBERED, DELAY_MAX, PK_INPLANE, PK_RADIAL_DRAG, cambered_annulus,
                                       make_cambered_element, stall_blend_numpy)
    from propmap.core._momentum import inplane_induction_numpy
    from propmap.core.polar import _model_constants
    from propmap.core.nodes import _cambered_args, _nodes

    prop, p = apce8x6
    p = p.replace(dynamic_stall=1.5, descent="glauert")
    om = rpm * RPM
    V, inc = mu * om * prop.radius, math.radians(incidence_deg)
    r = pm.rotor_loads(prop, p, om, V, inc, radial=True)
    model, pk = _model_constants(p)
    assert model == CAMBERED
    nd = _nodes(prop, r.r.size, 16, p.air, p)
    y, v = nd.y, np.asarray(r.v_i)
    Vs, Vc = V * math.sin(inc), V * math.cos(inc)
    cam = _cambered_args(p, p.air)
    U2 = (om * y) ** 2 + 0.5 * Vs**2 + Vc**2
    s0, s1, s2, s3 = cambered_annulus(U2, nd.sc, nd.cy2, cam[4], cam[0], cam[1], cam[2], cam[3] != 0.0, cam[5], cam[6],
                                      cam[7])
    sp, cp = nd.sinpsi[None, :], nd.cospsi[None, :]  # the full circle
    Vb = (Vs + pk[PK_INPLANE] * inplane_induction_numpy(v, Vs, Vc))[:, None]
    UT, UP = om * y[:, None] + Vb * sp, (Vc + v)[:, None] + 0.0 * sp
    U = np.hypot(UT, UP)
    adot = om * UP * Vb * cp / U**2
    d = np.minimum(1.5 * np.sqrt(y[:, None] * np.sqrt(nd.cy2)[:, None] * np.abs(adot) / (2 * U)), DELAY_MAX)
    shift = np.where(adot >= 0, d, -0.5 * d)
    element = make_cambered_element(np.arctan2, stall_blend_numpy, profile=True)
    geo = (nd.theta[:, None], nd.sin_th[:, None], nd.cos_th[:, None], s0[:, None], s1[:, None], s2[:, None],
           s3[:, None])
    qT, qH, cdpU = element(UT, UP, *geo, *pk[:6], pk[6] + shift / s2[:, None], pk[7])
    w, cf = nd.w, nd.cfac
    radial = pk[PK_RADIAL_DRAG] * cdpU * Vb * cp  # the radial drag, u_R = V_b cos psi (_annulus_loads.annulus_loads)
    full = {"thrust": np.sum(w * cf * qT.mean(1)), "torque": np.sum(w * y * cf * qH.mean(1)),
            "rolling_moment": np.sum(w * y * cf * (qT * sp).mean(1)),
            "pitching_moment": np.sum(w * y * cf * (-qT * cp).mean(1)),
            "side_force": np.sum(w * cf * (-qH * cp + radial * sp).mean(1)),
            "drag": np.sum(w * cf * (qH * sp + radial * cp).mean(1))}
    T0 = float(r.thrust)
    for q, x in full.items():
        scale = T0 if q in ("thrust", "drag", "side_force") else T0 * prop.radius
        assert float(getattr(r, q)) == pytest.approx(x, abs=2e-6 * scale), q
    assert abs(full["pitching_moment"]) > 0.05 * abs(full["rolling_moment"])  # the halves differ


def test_derivatives_across_the_cusp_of_axial_flow_are_warned_of(apce8x6):
    """With the option the loads grow as sqrt(V sin(beta)) from axial flow: dT/dbeta at 180 deg is
    unbounded (one-sided differences -0.15, -0.49, -1.58 N/rad at h = 1e-2, 1e-3, 1e-4: a
    user-level audit), where the kernel returns the static section's ~0. Said, not silent."""
    import warnings

    prop, p = apce8x6
    ds = p.replace(dynamic_stall=1.5)
    with pytest.warns(UserWarning, match=r"dynamic_stall: 1 point\(s\) have no in-plane airspeed"):
        r = pm.rotor_loads(prop, ds, 1250.0, 3.0, math.pi, derivatives=True)
    steps = [abs(float(pm.rotor_loads(prop, ds, 1250.0, 3.0, math.pi - h).thrust - r.thrust)) / h
             for h in (1e-2, 1e-4)]
    assert steps[1] > 5 * steps[0] > 0  # the one-sided slope grows as h^-1/2
    with pytest.warns(UserWarning, match="no in-plane airspeed"):  # the wrench's velocity Jacobian at rest
        pm.rotor_wrench(prop, ds, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1250.0, derivatives=("velocity",))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pm.rotor_loads(prop, ds, 1250.0, 3.0, 1.0, derivatives=True)  # in-plane flow: smooth
        pm.rotor_loads(prop, ds, 1250.0, 3.0, math.pi, derivatives=("omega",))  # not across the cusp
        pm.rotor_loads(prop, p, 1250.0, 3.0, math.pi, derivatives=True)  # without the option
        pm.rotor_loads(prop, ds, 1250.0, 0.0, 0.0, derivatives=True)  # from rest along the axis: smooth
        pm.rotor_loads(prop, ds, 1250.0, 0.0, math.pi, derivatives=("airspeed",))  # (sin pi = 1.2e-16)
    with pytest.warns(UserWarning, match="no in-plane airspeed"):  # from rest along a ray with an in-plane part
        pm.rotor_loads(prop, ds, 1250.0, 0.0, 1.0, derivatives=("airspeed",))
