"""Working states in descent (core/states.py) and the vortex-ring flag: the band's limits,
ordinary forward flight with a slight descent not flagged, the states of an axial descent."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.states import STATES, VRS_BAND, descent_state

RHO, R = 1.225, 0.1


def _at(k, m, v_mean=None):
    """descent_state at descent ratio k and in-plane ratio m for a rotor with v_h = 5 m/s; the
    mean inflow on the empirical curve v/v_h = 1 + 1.125 k - 1.372 k^2 + 1.718 k^3 - 0.655 k^4
    (k in [0, 2]) unless given."""
    T = 2 * RHO * math.pi * R**2 * 25.0
    vz, vx = -5.0 * k, 5.0 * m
    V, b = math.hypot(vz, vx), math.atan2(vx, vz)
    kk = min(max(k, 0.0), 2.0)
    curve = 5.0 * (1 + 1.125 * kk - 1.372 * kk**2 + 1.718 * kk**3 - 0.655 * kk**4)
    return descent_state(np.array(T), np.array(V), np.array(b), np.array(curve if v_mean is None else v_mean), RHO, R)


@pytest.mark.parametrize("k, m, state", [
    (0.0, 0.0, "normal working"), (0.25, 0.0, "normal working"), (0.35, 0.0, "vortex ring"),
    (1.45, 0.0, "vortex ring"), (0.9, 0.85, "vortex ring"), (0.9, 0.95, "normal working"),
    (2.5, 0.0, "windmill brake"), (-1.0, 0.0, "normal working"), (0.1, 3.0, "normal working"),
])
def test_band_limits(k, m, state):
    """Descent rates 0.3-1.5 v_h in axial descent, closing at in-plane 0.9 v_h."""
    code, vh, kk, mm = _at(k, m)
    assert STATES[int(code)] == state
    assert float(vh) == pytest.approx(5.0) and float(kk) == pytest.approx(k) and float(mm) == pytest.approx(m)
    assert VRS_BAND == {"k_min": 0.3, "k_max": 1.5, "m_max": 0.9}


def test_turbulent_wake_lies_between_the_band_and_the_windmill_brake_at_low_in_plane_speed():
    assert STATES[int(_at(1.8, 0.0, v_mean=8.0)[0])] == "turbulent wake"  # V_z + v = -9 + 8 < 0
    # beyond the band with the flow still down (k 1.5 to ideal autorotation): not normal working
    assert STATES[int(_at(1.6, 0.0)[0])] == "turbulent wake"
    assert STATES[int(_at(1.8, 0.0, v_mean=10.0)[0])] == "turbulent wake"
    assert STATES[int(_at(1.3, 0.8)[0])] == "turbulent wake"  # oblique, outside the band's upper side
    assert STATES[int(_at(0.4, 0.8)[0])] == "normal working"  # outside its lower side: slow descent


def test_fast_descent_in_forward_flight_is_never_a_turbulent_wake():
    """In-plane speed beyond the band's closing speed carries the wake away: normal working
    with the flow down through the disk, windmill brake with it up (an autogyro)."""
    assert STATES[int(_at(1.0, 3.7, v_mean=3.0)[0])] == "windmill brake"  # V_z + v = -5 + 3 < 0
    assert STATES[int(_at(1.0, 3.7, v_mean=6.0)[0])] == "normal working"
    prop = pm.load_propeller("apce_8x6")
    r = pm.rotor_loads(prop, pm.generic_params(), 8000 * math.pi / 30, [30.0, 20.0, 20.0],
                       np.radians([100.0, 100.0, 120.0]))
    assert "turbulent wake" not in list(r.state_name) and not r.vortex_ring.any()


def test_states_of_an_axial_descent_are_ordered_without_gaps():
    """Axial descent: normal working, vortex ring, turbulent wake, windmill brake, each once
    and in that order (between k = 1.5 and ideal autorotation the state was reported as
    normal working)."""
    prop = pm.load_propeller("apce_8x6")
    r = pm.rotor_loads(prop, pm.generic_params(), 6000 * math.pi / 30, np.linspace(0.0, 25.0, 251), math.pi)
    names = list(r.state_name)
    runs = [n for i, n in enumerate(names) if i == 0 or n != names[i - 1]]
    assert runs == list(STATES)
    k = r.descent_ratio
    assert np.all(k[np.array(names) == "turbulent wake"] >= 0.9) and np.all(k[np.array(names) == "turbulent wake"] < 2)


def test_forward_flight_with_slight_descent_is_not_a_vortex_ring():
    """The quadrotor case of the issue: 20 m/s at 92.5 deg incidence, and 5 m/s forward with
    0.3 m/s down, are ordinary flight."""
    prop = pm.load_propeller("apce_8x6")
    g = pm.generic_params()
    r = pm.rotor_loads(prop, g, 8000 * math.pi / 30, [20.0, math.hypot(5.0, 0.3)],
                       [math.radians(92.5), math.atan2(5.0, -0.3)])
    assert not r.vortex_ring.any()
    assert list(r.state_name) == ["normal working", "normal working"]


def test_states_through_an_axial_descent():
    """A propeller at fixed speed descending axially passes normal working, vortex ring and
    the windmill brake in order; v_i/v_h and the descent ratio are reported."""
    prop = pm.load_propeller("apce_8x6")
    g = pm.generic_params()
    V = np.linspace(0.0, 20.0, 81)
    r = pm.rotor_loads(prop, g, 6000 * math.pi / 30, V, math.pi)
    names = list(r.state_name)
    assert names[0] == "normal working" and "vortex ring" in names and names[-1] == "windmill brake"
    first = {n: names.index(n) for n in set(names)}
    assert first["normal working"] < first["vortex ring"] < first["windmill brake"]
    assert np.all(np.diff(r.descent_ratio) > 0)
    assert r.inflow_ratio[0] == pytest.approx(float(r.v_i_mean[0] / r.v_h[0]))


def test_the_empirical_descent_flags_its_blend_with_forward_speed_only():
    """inflow_extrapolated marks where the empirical descent curve (measured in axial
    descent) is blended by propmap's in-plane fade: oblique descent in the vortex-ring range;
    not axial descent (the measurements' own range), not fast forward flight with a slight
    descent, not Glauert's model."""
    prop = pm.load_propeller("apce_8x6")
    p = pm.default_params("apce_8x6")
    V = np.array([2.0, 4.0, 6.0])[:, None]
    b = np.radians([180.0, 150.0, 120.0, 95.0])[None, :]
    r = pm.rotor_loads(prop, p, 700.0, V, b)
    flagged = r.inflow_extrapolated
    assert not flagged[:, 0].any()  # axial descent
    assert not flagged[:, 3].any()  # 95 deg: forward flight, slight descent
    assert flagged[1:, 1:3].any()  # oblique descent at 0.3 <= lambda2 < 2
    assert np.all(~flagged | ((r.descent_ratio >= 0.3) & (r.descent_ratio < 2)))
    g = pm.rotor_loads(prop, p.replace(descent="glauert"), 700.0, V, b)
    assert not g.inflow_extrapolated.any()


@pytest.mark.parametrize("name", ["apce_8x6", "apce_10x7"])
def test_a_vanishing_descent_rate_gives_the_hover_loads(name):
    """Regression (issue 19 audit): at 1e-300 to 1e-11 m/s of descent the empirical curve's
    inversion clipped its descent ratio at 1e-12 and returned a thrust near 0, converged and
    unflagged; the loads must tend to hover's."""
    prop = pm.load_propeller(name)
    p = pm.default_params(name)
    V = np.array([0.0, 1e-300, 1e-100, 1e-14, 1e-12, 1e-11, 1e-9])
    for b in (math.pi, math.radians(135.0)):
        r = pm.rotor_loads(prop, p, 5500 * math.pi / 30, V, b)
        np.testing.assert_allclose(r.thrust, r.thrust[0], rtol=1e-8)
        np.testing.assert_allclose(r.torque, r.torque[0], rtol=1e-8)
