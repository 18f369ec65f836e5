"""Working states in descent (core/states.py) and the vortex-ring flag: the band's limits,
ordinary forward flight with a slight descent not flagged, the states of an axial descent."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.states import STATES, VRS_BAND, descent_state, vrs_boundary

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
    (0.0, 0.0, "normal working"), (0.44, 0.0, "normal working"), (0.46, 0.0, "vortex ring"),
    (1.49, 0.0, "vortex ring"), (1.51, 0.0, "turbulent wake"), (0.9, 0.94, "vortex ring"),
    (0.9, 0.96, "normal working"), (0.49, 0.6, "normal working"), (0.52, 0.6, "vortex ring"),
    (1.21, 0.6, "vortex ring"), (1.23, 0.6, "turbulent wake"),
    (2.5, 0.0, "windmill brake"), (-1.0, 0.0, "normal working"), (0.1, 3.0, "normal working"),
])
def test_band_limits(k, m, state):
    """Johnson's boundary (NASA/TP-2005-213477, pp. 23-24): descent rates 0.45-1.5 v_h in axial
    descent, 0.501-1.220 v_h at an in-plane 0.6 v_h, closing at 0.95 v_h."""
    code, vh, kk, mm = _at(k, m)
    assert STATES[int(code)] == state
    assert float(vh) == pytest.approx(5.0) and float(kk) == pytest.approx(k) and float(mm) == pytest.approx(m)


def test_boundary_against_its_source():
    """The edges at Johnson's constants: onset 0.45 and exit 1.5 in axial descent (V_zN, V_zX),
    both 0.975 where the band closes at m = 0.95 (V_xM), the edges of the formula at m = 0.6 and
    0.9, and no band beyond."""
    assert VRS_BAND == {"k_onset": 0.45, "k_exit": 1.5, "m_max": 0.95, "onset_exponent": 0.2, "exit_exponent": 1.5}
    on, ex = vrs_boundary(np.array([0.0, 0.6, 0.9, 0.95 - 1e-12, 0.95, 2.0, np.nan]))
    np.testing.assert_allclose(on[:3], [0.45, 0.5008, 0.6421], atol=1e-4)
    np.testing.assert_allclose(ex[:3], [1.5, 1.2197, 0.9922], atol=1e-4)
    assert on[3] == pytest.approx(0.975, abs=3e-3) and ex[3] == pytest.approx(0.975, abs=1e-9)  # the closing point
    assert np.all(np.isnan(on[4:])) and np.all(np.isnan(ex[4:]))
    m = np.linspace(0.0, 0.94, 95)
    on, ex = vrs_boundary(m)
    assert np.all(np.diff(on) >= 0) and np.all(np.diff(ex) <= 0) and np.all(on < ex)  # narrows with m


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
    assert r.v_i_over_v_h[0] == pytest.approx(float(r.v_i_mean[0] / r.v_h[0]))
    # the former name, which rotorcraft usage gives to lambda = (V cos(beta) + v_i) / (Omega R), warns
    # (a nomenclature audit, 2026-11-27)
    with pytest.warns(DeprecationWarning, match="not the inflow ratio lambda"):
        assert np.array_equal(r.inflow_ratio, r.v_i_over_v_h, equal_nan=True)


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
    assert flagged[1:, 1:3].any()  # oblique descent at 0.45 <= lambda2 < 2
    assert np.all(~flagged | ((r.descent_ratio >= 0.45) & (r.descent_ratio < 2)))
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


def test_the_compiled_states_follow_the_published_boundary_on_a_grid():
    """descent_state (the compiled rules) puts a descending rotor in the vortex ring exactly
    where vrs_boundary (Johnson's formula) says, on a fine (m, k) grid, and in the turbulent
    wake just beyond the exit edge at low in-plane speed."""
    mg, kg = np.meshgrid(np.linspace(0.0, 1.2, 121), np.linspace(0.01, 1.99, 199))
    code, _, k, m = (np.array(a, float) for a in zip(*(_at(a, b) for a, b in zip(kg.ravel(), mg.ravel()))))
    on, ex = vrs_boundary(m)  # at the ratios the rules saw (k, m recomputed from T and V)
    inside = (k >= on) & (k <= ex)
    assert np.array_equal(code == 1, inside)
    assert np.array_equal(code == 2, (m < 0.95) & (k > ex))
