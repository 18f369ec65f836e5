"""The rolling moment M_R: the hub moment of the advancing/retreating thrust asymmetry.

Checked against an independent full-circle quadrature of the blade-element thrust at the
solver's inflow, and for the invariants of the model: M_R = 0 in axial flow and hover,
the side force and pitching moment (the cos psi moments) vanish because the inflow does
not depend on azimuth, and the vector form puts it along -spin e_ip.
"""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core._physics import element
from propmap.core.polar import _model_constants
from propmap.core.nodes import _nodes

from .conftest import RPM


def _full_circle_moments(prop, params, omega, V, beta, n_psi=720):
    """(M_R, pitching moment, side force) by a midpoint rule over the whole circle at the
    solver's v_i(r) (Gauss nodes in r as the solver's), for the paper's model."""
    r = pm.rotor_loads(prop, params, omega, V, beta, discretization=pm.Discretization(48, 16), radial=True)
    nd = _nodes(prop, 48, 16, pm.Air(), params)
    model, pk = _model_constants(params)
    psi = (np.arange(n_psi) + 0.5) * 2 * math.pi / n_psi
    Vs, Vc = V * math.sin(beta), V * math.cos(beta)
    UT = omega * nd.y[:, None] + Vs * np.sin(psi)[None, :]
    UP = (Vc + r.v_i)[:, None] * np.ones_like(psi)[None, :]
    zero = np.zeros_like(nd.sc)[:, None]
    qT, qH = element(UT, UP, nd.theta[:, None], nd.sin_th[:, None], nd.cos_th[:, None], nd.sc[:, None], zero, zero,
                     zero, model, pk)
    dT = nd.cfac[:, None] * qT  # thrust per unit radius at each azimuth (blade-averaged)
    dH = nd.cfac[:, None] * qH
    roll = np.sum(nd.w * nd.y * np.mean(dT * np.sin(psi), axis=1))
    pitch = np.sum(nd.w * nd.y * np.mean(dT * np.cos(psi), axis=1))
    side = np.sum(nd.w * np.mean(dH * np.cos(psi), axis=1))
    return r, roll, pitch, side


@pytest.mark.parametrize("V, beta_deg", [(5.0, 90.0), (15.0, 60.0), (20.0, 120.0), (10.0, 30.0)])
def test_rolling_moment_equals_a_full_circle_quadrature(apc8x6, apc_params, V, beta_deg):
    r, roll, pitch, side = _full_circle_moments(apc8x6, apc_params, 8000 * RPM, V, math.radians(beta_deg))
    assert float(r.rolling_moment) == pytest.approx(roll, rel=2e-3)
    # azimuth-independent inflow: no pitching moment, no side force, the library's as the quadrature's (to
    # round-off; until stop 104 only the quadrature's own were checked, which vanish whatever the library returns)
    assert float(r.pitching_moment) == pytest.approx(pitch, abs=1e-12 * abs(roll) + 1e-15)
    assert float(r.side_force) == pytest.approx(side, abs=1e-12 * float(r.drag) + 1e-15)


def test_rolling_moment_is_zero_in_axial_flow_and_hover(apc8x6, apc_params):
    for params in (apc_params, pm.CamberedParams()):
        r = pm.rotor_loads(apc8x6, params, 8000 * RPM, [0.0, 10.0, 10.0, 5.0], np.radians([0.0, 0.0, 180.0, 180.0]),
                           radial=True)
        assert np.all(r.rolling_moment == 0.0)


def test_rolling_moment_grows_with_edgewise_speed_and_is_continuous_in_incidence(apc8x6):
    p = pm.CamberedParams()
    r = pm.rotor_loads(apc8x6, p, 8000 * RPM, np.linspace(1, 20, 20), math.pi / 2, radial=True)
    assert np.all(r.rolling_moment > 0) and np.all(np.diff(r.rolling_moment) > 0)
    # the advancing side's extra thrust: M_R is a fraction of T R
    assert np.all(r.rolling_moment < 0.5 * r.thrust * apc8x6.radius)
    inc = np.radians(np.linspace(0.0, 2.0, 5))
    near_axial = pm.rotor_loads(apc8x6, p, 8000 * RPM, 10.0, inc, radial=True).rolling_moment
    steps = np.diff(near_axial)  # linear in the in-plane speed: no jump at the axial switch (beta = 0)
    np.testing.assert_allclose(steps, steps[1], rtol=0.01)


def test_vector_rolling_moment_follows_the_spin(apc8x6):
    """ccw about +z moving along +x: the advancing blade is at -y, so the moment points
    along -x; cw mirrors it. The force does not depend on the spin."""
    p = pm.CamberedParams()
    om = 8000 * RPM
    ccw = pm.rotor_wrench(apc8x6, p, [12.0, 0.0, 0.0], [0, 0, 1], om, "ccw")
    cw = pm.rotor_wrench(apc8x6, p, [12.0, 0.0, 0.0], [0, 0, 1], om, "cw")
    MR = float(ccw.loads.rolling_moment)
    assert MR > 0
    np.testing.assert_allclose(ccw.torque, [-MR, 0.0, -float(ccw.loads.torque)], rtol=1e-12)
    np.testing.assert_allclose(cw.torque, -ccw.torque, rtol=1e-12)
    np.testing.assert_allclose(cw.force, ccw.force, rtol=1e-12)
