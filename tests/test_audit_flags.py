"""Behaviour of core/_flags.py that a mutation audit found unpinned (2026-11-29, a helper session: the 10
mutants of _flags.py not run by the audit of tests/test_audit_vehicle_map_inputs.py, F03-F14 there).
Each test names the mutants it kills. The boundaries below are the documented ones (core/states.py's
module docstring, the Loads docstring of core/loads.py), taken exactly where floating point allows."""

import math

import numpy as np

import propmap as pm
from propmap.core.states import STATES, _classify, descent_state

RHO, R = 1.225, 0.1016  # sea-level air, an 8 in propeller's radius
T = 3.0  # N: v_h = sqrt(T / (2 rho pi R^2)) = 6.14 m/s
V_H = math.sqrt(T / (2.0 * RHO * math.pi * (R * R)))  # (the compiled rules' own arithmetic, to the bit)


def test_the_windmill_brake_starts_at_a_descent_ratio_of_exactly_two():
    """Axial descent (beta = pi) at V = 2 v_h, k = 2 exactly: the windmill brake (k >= 2, momentum theory
    valid again); one ulp slower, k just below 2 and above the band's exit 1.5: the turbulent wake
    (F03: k > 2 taken, k = 2 left in the turbulent wake)."""
    V = np.array([2.0 * V_H, np.nextafter(2.0 * V_H, 0.0)])
    state, vh, k, m = descent_state(T, V, math.pi, 0.0, RHO, R)
    assert vh[0] == V_H and k[0] == 2.0 and k[1] < 2.0 and np.all(m < 1e-15)
    assert [STATES[s] for s in state] == ["windmill brake", "turbulent wake"]


def test_a_fast_descent_with_no_net_flow_through_the_disk_is_not_the_windmill_brake():
    """A descent fast in-plane (m = 2.6 >= 0.95, k = 1.5: past the band's closing speed) is the windmill
    brake only with the mean flow through the disk upward, V cos(beta) + v_mean < 0 (core/states.py);
    with v_mean = -V cos(beta) exactly there is no flow through the disk: normal working (F04: <= 0
    taken, zero net flow put in the windmill brake). 1 mm/s either side decides it."""
    V, b = np.full(3, 3.0 * V_H), np.full(3, math.radians(120.0))
    vz = V * np.cos(b)  # (as descent_state computes it, shape for shape)
    vm = -vz + np.array([0.0, 1e-3, -1e-3])
    assert vz[0] + vm[0] == 0.0
    state, _, k, m = descent_state(T, V, b, vm, RHO, R)
    np.testing.assert_allclose(k, 1.5, rtol=1e-12)
    np.testing.assert_allclose(m, 1.5 * math.sqrt(3.0), rtol=1e-12)
    assert [STATES[s] for s in state] == ["normal working", "normal working", "windmill brake"]


def test_the_empirical_descent_is_flagged_only_below_a_descent_ratio_of_two():
    """The empirical descent momentum is flagged (inflow_extrapolated) at 0.45 <= k < 2 with its in-plane
    fade exp(-(vx / v_mean)^2) between 5% and 95% (vx / v_mean = 0.3: fade 0.914); at k = 2 exactly the
    rotor is in the windmill brake, where momentum theory holds again: not flagged (F07: k <= 2 taken).
    (The compiled rules of rotor_loads' states and flags, core/_flags.working_states, called directly:
    the solver cannot be steered to k = 2 to the bit.)"""
    n = 3
    vz = np.array([-2.0 * V_H, np.nextafter(-2.0 * V_H, 0.0), -1.0 * V_H])
    state, vh, k, m, extrap = _classify(np.full(n, T), np.full(n, 0.3 * V_H), vz, np.full(n, V_H), RHO, R,
                                        linear=False, empirical=True)
    assert k[0] == 2.0 and k[1] < 2.0
    assert [STATES[s] for s in state] == ["windmill brake", "turbulent wake", "vortex ring"]
    assert list(extrap) == [False, True, True]
    # the same points with Glauert's momentum (empirical=False): nothing to flag
    assert not _classify(np.full(n, T), np.full(n, 0.3 * V_H), vz, np.full(n, V_H), RHO, R)[4].any()


def test_the_empirical_descent_fade_is_flagged_between_5_and_95_percent():
    """apce_8x6, calibrated (empirical descent), 700 rad/s, 4 m/s of descent tilted from axial (180 deg) to
    140 deg: the vortex ring (k 0.49-0.64). inflow_extrapolated is exactly where the fade with the in-plane
    speed, exp(-(V sin(beta) / v_mean)^2), is between 5% and 95% (the Loads docstring); 166-150 deg puts it
    between 95% and 99%, unflagged (F06: 99% taken as the upper end)."""
    prop, p = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    V, b = 4.0, np.radians(np.arange(180.0, 139.0, -2.0))
    r = pm.rotor_loads(prop, p, 700.0, V, b)
    assert r.converged.all() and r.vortex_ring.all()
    fade = np.exp(-(V * np.sin(b) / np.abs(r.v_i_mean)) ** 2)
    np.testing.assert_array_equal(r.inflow_extrapolated, (0.05 < fade) & (fade < 0.95))
    assert np.count_nonzero((fade > 0.95) & (fade < 0.99)) >= 5 and r.inflow_extrapolated.sum() >= 3


def test_the_fade_is_even_in_the_mean_inflow():
    """The fade exp(-(V sin(beta) / v_mean)^2) is even in v_mean: a rotor at -25 deg collective (apce_8x6,
    calibrated, 800 rad/s, 0.5 m/s at 103-108 deg) makes a little thrust with a net upward mean inflow,
    v_mean < 0, at 0.45 <= k < 2 (the windmill brake: m >= 0.95 with upflow), and is flagged where that
    fade is between 5% and 95% (F13: v_mean not taken in magnitude, its fade 0 there, nothing flagged)."""
    prop, p = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    V, b = 0.5, np.radians(np.arange(103.0, 108.5, 1.0))
    r = pm.rotor_loads(prop, p, 800.0, V, b, collective=math.radians(-25.0))
    assert r.converged.all() and np.all(r.thrust > 0) and np.all(r.v_i_mean < 0)
    k = r.descent_ratio
    assert np.all((k >= 0.45) & (k < 2.0))
    fade = np.exp(-(V * np.sin(b) / r.v_i_mean) ** 2)
    np.testing.assert_array_equal(r.inflow_extrapolated, (0.05 < fade) & (fade < 0.95))
    assert r.inflow_extrapolated.sum() >= 2, fade
