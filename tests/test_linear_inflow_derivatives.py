"""Implicit derivatives with a linear inflow model (Drees, Pitt-Peters; core/_linear_sensitivity.py):
against central differences of the whole solver across the envelope, for the three inputs,
section parameters and the density, the side force and pitching moment included; the vehicle's
Jacobians; a fit reaching the differencing fit's optimum; swirl with it (since 2026-11-26); the
node-changing names that stay refused."""

import math
from pathlib import Path

import numpy as np
import pytest

import propmap as pm

DISC = pm.Discretization(24, 8)
LOADS = ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "v_i_mean")
FORCES = ("thrust", "drag", "side_force")


@pytest.fixture(scope="module")
def prop():
    return pm.load_propeller("apce_8x6")


@pytest.fixture(scope="module", params=[("generic", "pitt-peters"), ("paper", "drees"), ("generic_inplane", "drees"),
                                        ("paper_inplane", "pitt-peters"), ("generic_inplane_swirl", "drees"),
                                        ("paper_swirl", "pitt-peters")], ids=lambda p: "-".join(p))
def params(request):
    """The sets with a linear inflow, with the skewed wake's in-plane induced velocity
    (RotorOptions.inplane_induction: the blades' in-plane airspeed depends on the annulus'
    root, the airspeed and the incidence), and with swirl (each annulus' swirl balances the
    linear solve's angular momentum and enters both solves: core/_linear_sensitivity.py)."""
    model, inflow = request.param
    base = pm.generic_params() if model.startswith("generic") else pm.preset("gill2017-apc")
    return base.replace(inflow=inflow, inplane_induction="_inplane" in model, swirl=model.endswith("_swirl"))


def _scale(r, q):
    """The unit of an error of quantity q: the point's thrust (forces), torque (moments) or
    mean inflow."""
    if q == "v_i_mean":
        return abs(float(r.v_i_mean))
    return abs(float(r.thrust)) if q in FORCES else abs(float(r.torque))


def _differences(prop, params, base, key, h):
    """Central differences of the solver in ``base[key]`` (one-sided, second order, at an end of
    the input's range: V = 0, beta = 0 or pi)."""
    def at(**kw):
        x = base | kw
        return pm.rotor_loads(prop, params, x["om"], x["V"], x["b"], discretization=DISC)

    x0 = base[key]
    if (key in ("V", "b") and x0 == 0) or (key == "b" and x0 == math.pi):
        s = 1.0 if x0 == 0 else -1.0
        f0, f1, f2 = at(), at(**{key: x0 + s * h}), at(**{key: x0 + 2 * s * h})
        return {q: s * (4 * float(getattr(f1, q)) - float(getattr(f2, q)) - 3 * float(getattr(f0, q))) / (2 * h)
                for q in LOADS}
    a, c = at(**{key: x0 + h}), at(**{key: x0 - h})
    return {q: (float(getattr(a, q)) - float(getattr(c, q))) / (2 * h) for q in LOADS}


@pytest.mark.parametrize("om, V, beta_deg", [
    (800.0, 0.0, 0.0),  # hover: solved with the uniform inflow (no gradient), its slopes one-sided
    (800.0, 0.0, 180.0),  # hover, along the descent ray: the empirical curve's slope at hover
    (800.0, 0.0, 130.0),  # hover, an oblique descending ray: the gradients' and the curve's slopes from rest
    (800.0, 5.0, 0.0),  # axial climb, likewise
    (800.0, 3.0, 180.0),  # axial descent (empirical momentum)
    (800.0, 6.0, 80.0),  # edgewise, climbing slightly: the wake skew near its largest
    (800.0, 12.0, 100.0),  # edgewise, descending
    (800.0, 4.0, 150.0),  # oblique descent
    (1200.0, 25.0, 30.0),  # fast climb at incidence
    (500.0, 8.0, 60.0),
    (800.0, 0.5, 30.0),  # mu = 0.003: the gradients' partials at small mu
])
def test_input_derivatives_match_finite_differences(prop, params, om, V, beta_deg):
    """Each derivative of T, D, Q, M_R, Y, M_P and v_i,mean within 2e-5 of central differences
    of the whole solver, in units of the point's thrust (forces), torque (moments) or mean inflow
    per unit of the input's scale; Y and M_P are not zero in forward flight (the fore-aft
    gradient's)."""
    base = {"om": om, "V": V, "b": math.radians(beta_deg)}
    r = pm.rotor_loads(prop, params, om, V, base["b"], discretization=DISC, derivatives=True)
    for wrt, key, h, scale_x in (("omega", "om", 1e-4 * om, om), ("airspeed", "V", 1e-4 * max(V, 1.0), max(V, 1.0)),
                                 ("incidence", "b", 1e-4, 1.0)):
        fd = _differences(prop, params, base, key, h)
        for q in LOADS:
            err = abs(float(r.derivative(q, wrt)) - fd[q]) * scale_x / _scale(r, q)
            assert err < 2e-5, (wrt, q, float(r.derivative(q, wrt)), fd[q])
    if 0 < beta_deg < 180 and V > 1:
        assert abs(float(r.derivative("pitching_moment", "airspeed"))) > 1e-3 * abs(float(r.torque)) / V


def test_section_parameter_and_density_derivatives(prop, params):
    """d(load)/d(section parameter) and d(load)/d(rho) against central differences of the solver
    with the parameter (or the air's density) moved, within 1e-5 of the loads per unit of
    max(|p|, 0.01); at hover, in forward flight and in oblique descent."""
    names = (("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2", "re_exp_lift", "alpha_L0_re", "M")
             if isinstance(params, pm.CamberedParams) else ("cl1", "cl2", "cd", "alpha0", "M"))
    om, V, b = np.array([800.0, 900.0, 1200.0]), np.array([0.0, 8.0, 6.0]), np.radians([0.0, 70.0, 130.0])
    r = pm.rotor_loads(prop, params, om, V, b, discretization=DISC, derivatives=(*names, "rho"))
    for n in (*names, "rho"):
        x = params.air.rho if n == "rho" else getattr(params, n)
        h = 1e-4 * max(abs(x), 0.01)

        def moved(dx, n=n, x=x):
            if n == "rho":
                return pm.rotor_loads(prop, params, om, V, b, discretization=DISC, air=pm.Air(rho=x + dx))
            return pm.rotor_loads(prop, params.replace(**{n: x + dx}), om, V, b, discretization=DISC)

        a, c = moved(h), moved(-h)
        for q in LOADS[:-1]:
            unit = np.abs(r.thrust if q in FORCES else r.torque) / max(abs(x), 0.01)
            err = np.abs(r.derivative(q, n) - (getattr(a, q) - getattr(c, q)) / (2 * h)) / unit
            assert err.max() < 1e-5, (n, q, err)


@pytest.mark.parametrize("swirl", [False, True])
def test_vehicle_jacobians_with_pitt_peters_inflow(swirl):
    """vehicle_wrench's velocity, angular-velocity and rotor-speed Jacobians with Pitt-Peters
    inflow, with and without swirl (the rotors' side force and pitching moment enter the
    moments) against central differences of vehicle_wrench (NeuroBEM quadrotor, tilted rotors,
    airframe drag; forward flight with body rates, slow climb, hover): the motion Jacobians
    within 2e-5 of the largest entry (measured 2026-11-26: 1.06e-5 without swirl, 8.7e-6 with
    it; a review's copy that dropped the swirl's share of the wake-skew coupling gave 1.74e-4),
    the rotor-speed ones within 1e-5."""
    from dataclasses import replace

    from propmap.core.body import BodyDrag

    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml")
    tilts = ([0.2, 0.0, 2.0], [0.0, -0.3, 1.0], [-0.1, 0.1, 3.0], [0.0, 0.0, 1.0])
    veh = replace(veh, rotors=tuple(replace(r, axis=np.array(a)) for r, a in zip(veh.rotors, tilts)))
    g = pm.generic_params().replace(inflow="pitt-peters", swirl=swirl)
    v = np.array([[6.0, -1.0, -0.5], [0.5, 0.0, 1.0], [0.0, 0.0, 0.0]])
    w = np.array([[0.5, -1.0, 2.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    om = np.array([[1100.0, 1150.0, 1080.0, 1200.0], [1000.0] * 4, [1000.0] * 4])
    body = BodyDrag((0.02, 0.01, 0.03), 1.2)

    def wrench(v_, w_, om_, **kw):
        return pm.vehicle_wrench(veh, g, v_, w_, om_, body_drag=body, discretization=DISC, **kw)

    r = wrench(v, w, om, derivatives=("velocity", "angular_velocity"))
    for name in ("velocity", "angular_velocity"):
        for j in range(3):
            fd = {}
            # Richardson: the tilted hubs cross the kink at V_c = 0 in hover; steps 1e-3 and 5e-4 (2e-3 met, with swirl,
            # a step of 1e-10 N m in rotor 2's moment near V_c = -0.21 m/s at the root solve's tolerance: the difference
            # with h = 2e-3 was 1.3e-7 off the derivative, those with 1e-3 to 2.5e-4 9e-9; measured 2026-11-27)
            for h in (1e-3, 5e-4):
                d = np.eye(3)[j] * h
                a, c = ((wrench(v + d, w, om), wrench(v - d, w, om)) if name == "velocity"
                        else (wrench(v, w + d, om), wrench(v, w - d, om)))
                fd[h] = {"force": (a.force - c.force) / (2 * h), "moment": (a.moment - c.moment) / (2 * h)}
            for key in ("force", "moment"):
                J = r.jacobian[(key, name)]
                for n in range(3):
                    np.testing.assert_allclose(J[n, :, j], 2 * fd[5e-4][key][n] - fd[1e-3][key][n], rtol=0,
                                               atol=2e-5 * np.abs(J[n]).max(), err_msg=f"{key} {name} {n} {j}")
    r = wrench(v, w, om, derivatives=True)
    for i in range(4):
        h = 1e-3 * om[0, i]
        a, c = om.copy(), om.copy()
        a[:, i] += h
        c[:, i] -= h
        fa, fc = wrench(v, w, a), wrench(v, w, c)
        np.testing.assert_allclose(r.force_domega[:, :, i], (fa.force - fc.force) / (2 * h), rtol=0,
                                   atol=1e-5 * np.abs(r.force_domega).max())
        np.testing.assert_allclose(r.moment_domega[:, :, i], (fa.moment - fc.moment) / (2 * h), rtol=0,
                                   atol=1e-5 * np.abs(r.moment_domega).max())


@pytest.mark.parametrize("swirl", [False, True])
def test_level_flight_fit_with_pitt_peters_uses_the_implicit_jacobian(swirl):
    """fit_level_flight with Pitt-Peters inflow, with and without swirl (the paper's vehicle and
    section, synthetic level flight to 14 m/s at pitch to -35 deg, where the wake skew couples
    the annuli): the implicit Jacobian and differences of the solver reach the truth and the
    same parameters (1e-6 relative), the implicit one in fewer model calls."""
    from importlib import resources

    from propmap.identify import FitOptions, fit_level_flight, simulate_level_flight

    quad = pm.read_vehicle(str(resources.files("propmap") / "data" / "examples" / "quadrotor.toml"))
    truth = pm.preset("gill2017-apc").replace(M=30.0, inflow="pitt-peters", swirl=swirl)
    V = np.linspace(0, 14, 12)
    data = simulate_level_flight(quad, truth, V, -2.5 * V)
    fits = {j: fit_level_flight(data, quad, base=truth, options=FitOptions(M=30.0, jacobian=j))
            for j in ("implicit", "differences")}
    np.testing.assert_allclose(fits["implicit"].x, [truth.cl1, truth.cl2, truth.cd, truth.alpha0], rtol=1e-6)
    np.testing.assert_allclose(fits["implicit"].x, fits["differences"].x, rtol=1e-6)
    assert fits["implicit"].nfev < fits["differences"].nfev


@pytest.mark.parametrize("compliance", [2.0, 0.0])
def test_flapping_blades_with_a_linear_inflow(prop, params, compliance):
    """Flapping acts on the rigid loads, whose side force and pitching moment a linear inflow
    makes nonzero (core/flapping.flapping_derivatives in its general form): the flapping
    rotor's derivatives, the compliance's and the lift slope's included, within 1e-5 of central
    differences of the solver (2e-5 with the in-plane induction: measured 2026-11-25, at most
    1.1e-5, d(side force)/d(incidence) of the paper's set at 80 deg, where Richardson-extrapolated
    differences of the rigid rotor differ from the derivative by 7.7e-6 with the option and by
    up to 2e-5 on other loads without it); at compliance 0 (one-sided there) the rigid pitching
    moment makes the drag and the rolling moment linear in the compliance, no longer quadratic.
    With swirl the differences' steps are 10 times larger, as the swirl's stopping tolerance
    (1e-7 Omega y) is in the differences (not in the derivatives), and the third point is at
    140 deg: at 150 deg the paper's set with Pitt-Peters inflow and swirl balances within that
    tolerance of a jump of an annulus' root, where the loads are not smooth (flagged
    multiple_roots with the tolerances tightened to 1e-13; measured 2026-11-26)."""
    from .conftest import moved_loads

    p = params.replace(flap_compliance=compliance)
    slope = "cl_alpha" if isinstance(params, pm.CamberedParams) else "cl1"
    om, V = np.array([600.0, 800.0, 1000.0]), np.array([5.0, 10.0, 8.0])
    b = np.radians([30.0, 80.0, 140.0 if params.swirl else 150.0])
    wrt = ("omega", "airspeed", "incidence", "collective", "rho", "flap_compliance", slope)
    r = pm.rotor_loads(prop, p, om, V, b, derivatives=wrt, discretization=DISC)
    tol = 2e-5 if params.inplane_induction else 1e-5
    steps = {"omega": 1e-2, "airspeed": 1e-4, "incidence": 1e-6, "collective": 1e-6, "rho": 1e-5,
             "flap_compliance": 1e-5, slope: 1e-5}
    if not params.swirl and params.inflow == "pitt-peters" and isinstance(params, pm.CamberedParams):
        # (since the calibration of 2026-11-29: at 150 deg, in the vortex-ring band, the generic set's loads with
        # Pitt-Peters inflow carry the root tolerance's noise: steps of 1e-4 m/s, 1e-6 rad and 1e-5 in cl_alpha
        # gave differences 1.1e-5, 1.9e-5 and 1.7e-5 of the largest from the derivatives; 6.8e-7 and 2.3e-6 at
        # 1e-3 m/s and 1e-5 rad)
        steps = {k: (h if k == "omega" else 10 * h) for k, h in steps.items()}
    if params.swirl:
        steps = {k: 10 * h for k, h in steps.items()}
        # the swirl's stopping tolerance in the loads: at 140 deg (descent, the wake skew of a hovering disk since
        # 2026-11-27) dQ/dV is -6.02e-5 N s against differences converged to -6.0237e-5 (h 1e-2 to 1e-4), 3e-4
        # apart, and 3e-5 with the tolerance SWIRL_TOL at 1e-13 (measured 2026-11-27): 3.2e-5 of the largest here
        tol = 4e-5
    assert np.all(np.abs(r.pitching_moment) > 1e-3 * np.abs(r.torque))  # (rigid or flapping, Y and M_P)
    for w in wrt:
        h = steps[w]
        hi = moved_loads(prop, p, om, V, b, w, h, DISC)
        if w == "flap_compliance" and compliance == 0:  # one-sided, second order
            hi2 = moved_loads(prop, p, om, V, b, w, 2 * h, DISC)
        else:
            lo = moved_loads(prop, p, om, V, b, w, -h, DISC)
        for q in ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment"):
            if w == "flap_compliance" and compliance == 0:
                fd = (4 * getattr(hi, q) - getattr(hi2, q) - 3 * getattr(r, q)) / (2 * h)
            else:
                fd = (getattr(hi, q) - getattr(lo, q)) / (2 * h)
            assert np.max(np.abs(r.derivative(q, w) - fd)) <= tol * np.max(np.abs(fd)) + 1e-12, (w, q)
    if compliance == 0:
        assert np.all(np.abs(r.derivative("drag", "flap_compliance")) > 0)


def test_every_linear_inflow_set_is_differentiable(prop):
    """The fits' differentiable() accepts a linear inflow with and without swirl (since
    2026-11-26 with swirl too) and with flapping blades."""
    from propmap.core.derivatives import differentiable

    pp = pm.generic_params().replace(inflow="pitt-peters")
    assert differentiable(pp, ("cl_alpha", "collective", "flap_compliance"))
    assert differentiable(pp.replace(flap_compliance=2.0), ("cl_alpha",))
    assert differentiable(pp.replace(swirl=True), ("cl_alpha", "rho"))
    assert not differentiable(pp.replace(swirl=True), ("re_ref",))
