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
    """d = 0 gives the static element; otherwise the mean of the element with the stall angle
    moved up by d (the angle rising) and down by d / 2 (falling), C_L and C_D being linear in the
    blend (checked against a direct evaluation with shifted stall angles)."""
    UT, UP = np.array([30.0, 45.0, 60.0]), np.array([8.0, 9.0, 7.0])
    th, a, cdf, g, dal0 = 0.35, 5.8, 1.1, 1.0, -0.01
    pk = (-0.08, 1.98, 0.012, 0.065, 0.5, 12.0, 0.3, -0.08)
    static = element_cambered(UT, UP, th, math.sin(th), math.cos(th), a, cdf, g, dal0, *pk)
    same = element_cambered_delayed(UT, UP, th, math.sin(th), math.cos(th), a, cdf, g, dal0, *pk, 0.0, 5.0)
    np.testing.assert_array_equal(same[0], static[0])
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


def test_what_the_option_refuses(apce8x6):
    prop, p = apce8x6
    with pytest.raises(ValueError, match="dynamic_stall applies to the cambered section model"):
        pm.preset("gill2017-apc").replace(dynamic_stall=1.5)
    with pytest.raises(ValueError, match="dynamic_stall needs the uniform inflow"):
        p.replace(dynamic_stall=1.5, inflow="pitt-peters")
    with pytest.raises(ValueError, match="dynamic_stall"):
        p.replace(dynamic_stall=6.0)
    ds = p.replace(dynamic_stall=1.5)
    assert not differentiable(ds, ("omega",)) and differentiable(p, ("omega",))
    with pytest.raises(ValueError, match="not implemented with the dynamic stall"):
        pm.rotor_loads(prop, ds, 600.0, 5.0, 1.0, derivatives=True)


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
                                       exp_sat_numpy, inplane_induction_numpy, make_cambered_element)
    from propmap.core.airfoil import _model_constants
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
    element = make_cambered_element(np.arctan2, exp_sat_numpy, profile=True)
    geo = (nd.theta[:, None], nd.sin_th[:, None], nd.cos_th[:, None], s0[:, None], s1[:, None], s2[:, None],
           s3[:, None])
    qT, qH, cdpU = element(UT, UP, *geo, *pk[:6], pk[6] + shift / s2[:, None], pk[7])
    w, cf = nd.w, nd.cfac
    radial = pk[PK_RADIAL_DRAG] * cdpU * Vb * cp  # the radial flow's drag u_R = V_b cos psi (_annulus.annulus_loads)
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
