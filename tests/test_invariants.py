"""Physical limits and invariants of the rotor model (Gill & D'Andrea 2017, Section II)."""

import math
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.hover import HoverModel
from propmap.core.nodes import _nodes

from .conftest import RPM


def test_drag_is_zero_in_hover_and_axial_flow(apc8x6, apc_params):
    om = 8000 * RPM
    r = pm.rotor_loads(apc8x6, apc_params, om, [0.0, 10.0, 10.0, 3.0], [1.0, 0.0, math.pi, math.pi], radial=True)
    assert np.all(r.drag == 0.0)
    assert np.all(r.converged)
    # and it goes to 0 there, linearly in the incidence (the exact zeros above are the solver's axial shortcut; this
    # is the physics on either side of it)
    b = np.array([1e-3, 2e-3, math.pi - 2e-3, math.pi - 1e-3])
    d = pm.rotor_loads(apc8x6, apc_params, om, 10.0, b).drag
    edgewise = float(pm.rotor_loads(apc8x6, apc_params, om, 10.0, math.pi / 2).drag)
    assert np.all(d > 0) and np.all(d < 0.01 * edgewise)
    assert d[1] / d[0] == pytest.approx(2.0, rel=1e-3) and d[2] / d[3] == pytest.approx(2.0, rel=1e-3)


def test_drag_positive_and_linear_at_low_edgewise_speed(apc8x6, apc_params):
    r = pm.rotor_loads(apc8x6, apc_params, 8000 * RPM, [0.5, 1.0], math.pi / 2, radial=True)
    assert np.all(r.drag > 0)
    # D ~ V for small mu (paper Section IV: "linear relationship with vehicle speed")
    assert r.drag[1] / r.drag[0] == pytest.approx(2.0, rel=0.05)


def test_thrust_and_torque_continuous_in_incidence(apc8x6, apc_params):
    b = np.radians(np.linspace(0, 180, 721))
    r = pm.rotor_loads(apc8x6, apc_params, 8000 * RPM, 8.0, b, radial=True)
    h = pm.rotor_loads(apc8x6, apc_params, 8000 * RPM, 0.0, 0.0, radial=True)
    T0, Q0 = float(h.thrust), float(h.torque)
    dT, dQ = np.abs(np.diff(r.thrust)), np.abs(np.diff(r.torque))
    # 0.25 deg steps. Outside the region where Glauert's momentum is not predictive (some annulus
    # with V cos b < 0 < V cos b + v_i: the paper's model keeps Glauert's momentum in descent,
    # whose per-annulus branches jump there) the only jumps are stall-fold branch switches of
    # single annuli (measured max 0.27% of static thrust at 0-90 deg)
    Vc = (8.0 * np.cos(b))[:, None]
    invalid = np.any((Vc < 0) & (Vc + r.v_i > 0), axis=1)
    ok = ~(invalid[:-1] | invalid[1:])
    assert ok[: 360].all()
    assert np.max(dT[ok]) < 0.005 * T0
    assert np.max(dQ[ok]) < 0.005 * Q0
    # there momentum theory is not predictive (docs/numerics.md); T may jump between root
    # branches but stays bounded
    assert np.max(dT) < 0.03 * T0


def test_cambered_default_is_continuous_through_descent(apc8x6):
    """The cambered model's default (empirical momentum in descent) over 0-180 deg at
    8 m/s, 8000 rpm in 0.25 deg steps: no step above 0.1% of the static thrust (measured
    max 0.086%), the vortex-ring band included."""
    g = pm.generic_params()
    b = np.radians(np.linspace(0, 180, 721))
    r = pm.rotor_loads(apc8x6, g, 8000 * RPM, 8.0, b)
    T0 = float(pm.rotor_loads(apc8x6, g, 8000 * RPM, 0.0, 0.0).thrust)
    assert r.vortex_ring.any() and np.max(np.abs(np.diff(r.thrust))) < 0.001 * T0


def test_momentum_consistency_sum_dT_BEMT_equals_T(apc8x6, apc_params, envelope_points):
    """Sum over annuli of eq (10) at the solved v_i equals T from eq (13)."""
    om, V, b = envelope_points
    r = pm.rotor_loads(apc8x6, apc_params, om, V, b, radial=True)
    nd = _nodes(apc8x6, 48, 16, pm.Air(), apc_params)
    Vs = (V * np.sin(b))[:, None]
    Vc = (V * np.cos(b))[:, None]
    # eq (10)'s factor 4 pi rho y written here, not taken from the solver's nodes (a momentum factor 2 pi rho y in the
    # solver passed this test when it used the nodes' own: a mutation audit, 2026-11-27)
    mfac = 4 * math.pi * pm.Air().rho * nd.y
    np.testing.assert_allclose(nd.mfac, mfac, rtol=1e-14)
    dT_bemt = mfac * r.v_i * np.sqrt(Vs**2 + (Vc + r.v_i) ** 2)
    T_bemt = dT_bemt @ nd.w
    T0 = float(pm.rotor_loads(apc8x6, apc_params, 12000 * RPM, 0, 0, radial=True).thrust)
    assert np.max(np.abs(T_bemt - r.thrust)) < 1e-6 * T0
    # and the per-annulus BET thrust integrates to T
    np.testing.assert_allclose(r.dT_dr @ nd.w, r.thrust, rtol=1e-12, atol=1e-12)


def test_hover_model_equals_full_model_at_zero_speed(apc8x6, apc_params):
    om = 7000 * RPM
    h = HoverModel.from_model(apc8x6, apc_params, om)
    r = pm.rotor_loads(apc8x6, apc_params, om, 0.0, 0.0, radial=True)
    assert h.thrust(om) == pytest.approx(float(r.thrust), rel=1e-12)
    assert h.torque(om) == pytest.approx(float(r.torque), rel=1e-12)
    # CT is nearly rpm-independent at V = 0 (only the Reynolds term changes it)
    r2 = pm.rotor_loads(apc8x6, apc_params, 2 * om, 0.0, 0.0, radial=True)
    assert float(r2.CT) == pytest.approx(h.CT(apc8x6.diameter), rel=0.03)


def test_hover_model_from_coefficients_roundtrip():
    h = HoverModel.from_coefficients(0.11, 0.074, 0.2032)
    # k_T = CT rho D^4 / (2 pi)^2, k_Q = CP rho D^5 / (2 pi)^3 (propeller convention, ISA sea level)
    assert h.k_T == pytest.approx(0.11 * 1.225 * 0.2032**4 / (2 * math.pi) ** 2, rel=1e-12)
    assert h.k_Q == pytest.approx(0.074 * 1.225 * 0.2032**5 / (2 * math.pi) ** 3, rel=1e-12)
    assert h.CT(0.2032) == pytest.approx(0.11)
    assert h.CP(0.2032) == pytest.approx(0.074)


def test_thrust_scales_with_omega_squared_in_hover(apc8x6, apc_params):
    r = pm.rotor_loads(apc8x6, apc_params, np.array([5000, 10000]) * RPM, 0.0, 0.0, radial=True)
    # only the Reynolds skin-friction term breaks exact Omega^2 scaling
    assert r.thrust[1] / r.thrust[0] == pytest.approx(4.0, rel=0.03)
    assert r.CP[1] < r.CP[0]  # less skin friction at higher Reynolds number


def test_axial_climb_reduces_thrust(apc8x6, apc_params):
    r = pm.rotor_loads(apc8x6, apc_params, 8000 * RPM, [0.0, 5.0], [0.0, 0.0], radial=True)
    assert r.thrust[1] < r.thrust[0]


def test_power_and_coefficients_definitions(apc8x6, apc_params):
    om = 6000 * RPM
    r = pm.rotor_loads(apc8x6, apc_params, om, 5.0, 0.3, radial=True)
    n = om / (2 * math.pi)
    D = apc8x6.diameter
    assert float(r.power) == pytest.approx(float(r.torque) * om)
    assert float(r.CT) == pytest.approx(float(r.thrust) / (1.225 * n**2 * D**4))
    assert float(r.CP) == pytest.approx(float(r.power) / (1.225 * n**3 * D**5))
    assert float(r.CP) == pytest.approx(2 * math.pi * float(r.CQ))
    assert float(r.J) == pytest.approx(5.0 / (n * D))


def test_shapes_scalar_1d_and_broadcast(apc8x6, apc_params):
    s = pm.rotor_loads(apc8x6, apc_params, 800.0, 5.0, 1.0, radial=True)
    assert s.thrust.shape == () and s.v_i.shape == (48,)
    one = pm.rotor_loads(apc8x6, apc_params, [700.0, 800.0, 900.0], 5.0, 1.0, radial=True)
    assert one.thrust.shape == (3,) and one.v_i.shape == (3, 48)
    grid = pm.rotor_loads(apc8x6, apc_params, np.array([700.0, 800.0])[:, None], np.array([0.0, 5.0, 10.0]), 1.0,
                          radial=True)
    assert grid.thrust.shape == (2, 3) and grid.dD_dr.shape == (2, 3, 48)
    assert grid.thrust[1, 1] == pytest.approx(float(s.thrust), rel=1e-12)


def test_inputs_are_not_modified(apc8x6, apc_params):
    om = np.array([700.0, 800.0])
    V = np.array([1.0, 2.0])
    b = np.array([0.1, 0.2])
    copies = om.copy(), V.copy(), b.copy()
    pm.rotor_loads(apc8x6, apc_params, om, V, b, radial=True)
    for a, c in zip((om, V, b), copies):
        np.testing.assert_array_equal(a, c)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(omega=-1.0), "omega"),
        (dict(omega=-1e-9), "a signed rotation rate is refused"),
        (dict(omega=np.nan), "omega"),
        (dict(airspeed=-0.1), "airspeed"),
        (dict(airspeed=np.inf), "airspeed"),
        (dict(incidence=3.2), "incidence"),
        (dict(incidence=-0.01), "incidence"),
    ],
)
def test_bad_operating_points_raise_naming_the_argument(apc8x6, apc_params, kwargs, match):
    args = dict(omega=800.0, airspeed=5.0, incidence=0.5) | kwargs
    with pytest.raises(ValueError, match=match):
        pm.rotor_loads(apc8x6, apc_params, **args, radial=True)


def test_stopped_and_parked_rotor(apc8x6, apc_params):
    """Omega = 0 in still air: exactly zero loads (and NaN coefficients, which are referred to
    n); in a flow: the parked blades' loads, continuous with the spinning rotor's (the
    solution at 0.1 rad/s, within 3% of 1 rad/s); a vehicle with a stopped rotor evaluates."""
    r = pm.rotor_loads(apc8x6, apc_params, np.array([0.0, 0.05]), 0.0, 0.0, radial=True)
    assert r.thrust[0] == 0.0 and r.torque[0] == 0.0 and r.drag[0] == 0.0 and r.v_i[0].max() == 0.0
    assert 0 < r.thrust[1] < 1e-7
    assert np.isnan(r.CT[0]) and np.isfinite(r.CT[1])
    assert r.converged.all()
    V, beta = 8.0, math.radians(97.0)
    parked = pm.rotor_loads(apc8x6, apc_params, np.array([0.0, 0.1, 1.0]), V, beta)
    assert parked.drag[0] > 0.005  # the parked blades' drag in an 8 m/s stream (not zero)
    assert parked.thrust[0] == parked.thrust[1]
    np.testing.assert_allclose(parked.drag[2], parked.drag[0], rtol=0.03)
    assert np.isinf(parked.reverse_flow_radius[0]) and parked.reverse_flow[0]
    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    w = pm.vehicle_wrench(veh, apc_params, [5.0, 0.0, 0.0], np.zeros(3), [0.0, 800.0, 800.0, 800.0])
    assert np.isfinite(w.force).all() and abs(w.loads[0].thrust[0]) < 0.05 * w.loads[1].thrust[0]


def test_vector_form_matches_scalar_loads_and_rotates(apc8x6, apc_params):
    om = 8000 * RPM
    V = np.array([10.0, 0.0, -5.0])  # moving forward and down
    z = np.array([0.0, 0.0, 1.0])
    w = pm.rotor_wrench(apc8x6, apc_params, V, z, om, "ccw")
    beta = math.acos(-5.0 / np.linalg.norm(V))
    s = pm.rotor_loads(apc8x6, apc_params, om, np.linalg.norm(V), beta, radial=True)
    np.testing.assert_allclose(w.force, [-float(s.drag), 0.0, float(s.thrust)], rtol=1e-12, atol=1e-12)
    # shaft torque against the ccw spin; the rolling moment along -e_ip (the advancing side,
    # where the extra thrust acts, is at -z x e_ip = -y here), no pitching moment
    np.testing.assert_allclose(w.torque, [-float(s.rolling_moment), 0.0, -float(s.torque)], rtol=1e-12)
    assert float(s.rolling_moment) > 0
    # a rigid rotation of velocity and axis rotates the wrench
    c, sn = math.cos(0.7), math.sin(0.7)
    R = np.array([[c, 0, sn], [0, 1, 0], [-sn, 0, c]]) @ np.array([[c, -sn, 0], [sn, c, 0], [0, 0, 1]])
    w2 = pm.rotor_wrench(apc8x6, apc_params, R @ V, R @ z, om, "cw")
    np.testing.assert_allclose(w2.force, R @ w.force, atol=1e-12)
    np.testing.assert_allclose(w2.torque, -(R @ w.torque), atol=1e-12)  # cw mirrors both moments


def test_vector_form_at_zero_velocity(apc8x6, apc_params):
    w = pm.rotor_wrench(apc8x6, apc_params, np.zeros((2, 3)), [[0, 0, 1], [1, 0, 0]], 900.0, [1, -1])
    T = float(pm.rotor_loads(apc8x6, apc_params, 900.0, 0.0, 0.0, radial=True).thrust)
    np.testing.assert_allclose(w.force, [[0, 0, T], [T, 0, 0]], atol=1e-12)
    assert np.all(np.isfinite(w.torque))


def test_vector_form_bad_input(apc8x6, apc_params):
    with pytest.raises(ValueError, match="axis"):
        pm.rotor_wrench(apc8x6, apc_params, [1.0, 0, 0], [0, 0, 0], 900.0)
    with pytest.raises(ValueError, match="spin"):
        pm.rotor_wrench(apc8x6, apc_params, [1.0, 0, 0], [0, 0, 1], 900.0, spin="left")
    with pytest.raises(ValueError, match="length 3"):
        pm.rotor_wrench(apc8x6, apc_params, [1.0, 0], [0, 0, 1], 900.0)


def test_simplified_lift_model_runs_and_differs(apc8x6, apc_params):
    simple = apc_params.replace(lift_model="sincos", cl2=2.0)
    a = pm.rotor_loads(apc8x6, simple, 8000 * RPM, 5.0, 1.0, radial=True)
    b = pm.rotor_loads(apc8x6, apc_params, 8000 * RPM, 5.0, 1.0, radial=True)
    assert a.converged and a.thrust > 0 and a.thrust != b.thrust


@pytest.mark.parametrize("nr, naz, match", [(1, 16, "n_radial must be an integer in \\[2, 10000\\]"),
                                            (48.5, 16, "n_radial"),
                                            (48, 1, "n_azimuth must be an integer in \\[2, 1000\\]"),
                                            (48, 1001, "n_azimuth")])
def test_discretization_rejects_counts_outside_their_range(nr, naz, match):
    # one azimuth node (psi = 0) would silently give D = 0 in edgewise flight
    with pytest.raises(ValueError, match=match):
        pm.Discretization(nr, naz)


def test_a_whole_float_count_is_kept_as_an_int(apc8x6, apc_params):
    """Discretization(48.0, 16) was accepted and then failed inside NumPy's Gauss-Legendre nodes
    (a property-based audit): the counts are ints, the loads those of (48, 16)."""
    d = pm.Discretization(48.0, np.int64(16))
    assert type(d.n_radial) is int and type(d.n_azimuth) is int and d == pm.Discretization()
    assert pm.rotor_loads(apc8x6, apc_params, 800.0, 10.0, 1.0, discretization=d).thrust == \
        pm.rotor_loads(apc8x6, apc_params, 800.0, 10.0, 1.0).thrust


def test_api_edge_cases_raise_value_errors_naming_the_argument(apc8x6, apc_params):
    """Regression tests of the hardening audit: each was a wrong result or another exception."""
    import warnings

    with pytest.raises(ValueError, match="omega"):
        pm.rotor_loads(apc8x6, apc_params, 10**400, 5.0, 0.5)  # an int beyond float: not OverflowError
    with pytest.raises(ValueError, match="omega"):
        pm.rotor_loads(apc8x6, apc_params, [[800.0, 900.0], [800.0]], 5.0, 0.5)  # ragged
    for bad in ("800", True):
        with pytest.raises(ValueError, match="omega"):
            pm.rotor_loads(apc8x6, apc_params, bad, 5.0, 0.5)
    with pytest.raises(ValueError, match="spin"):
        pm.rotor_wrench(apc8x6, apc_params, [5.0, 0, 0], [0, 0, 1], 800.0, spin=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no overflow RuntimeWarning on the way
        with pytest.raises(ValueError, match=r"velocity: the rotor.s airspeed \|velocity\| must be at most 500 "
                                             r"m/s \(the model.s range\); got 1.41421e\+200 m/s"):
            pm.rotor_wrench(apc8x6, apc_params, [1e200, 1e200, 0.0], [0, 0, 1], 800.0)
    with pytest.raises(ValueError, match="diameter"):
        pm.HoverModel.from_coefficients(0.1, 0.05, -0.2)
    with pytest.raises(ValueError, match="diameter"):
        pm.HoverModel.from_coefficients(0.1, 0.05, 1e200)


def test_huge_axis_keeps_the_thrust_direction_and_spins_by_name(apc8x6, apc_params):
    w = pm.rotor_wrench(apc8x6, apc_params, [0.0, 0.0, 0.0], [0.0, 1e200, 1e200], 800.0)
    T = float(pm.rotor_loads(apc8x6, apc_params, 800.0, 0.0, 0.0).thrust)
    np.testing.assert_allclose(w.force, [0.0, T / math.sqrt(2), T / math.sqrt(2)], rtol=1e-12)
    two = pm.rotor_wrench(apc8x6, apc_params, [[5.0, 0, 0]] * 2, [0, 0, 1], 800.0, spin=["ccw", "cw"])
    np.testing.assert_allclose(two.torque[0], -two.torque[1], rtol=1e-12)


def test_a_single_point_equals_the_same_point_in_a_batch(apc8x6, apc_params):
    """The scalar fast path of rotor_loads (one operating point: its own input handling and
    result construction) gives the batch's numbers bit for bit, every field of RotorLoads set,
    shape ()."""
    from dataclasses import fields

    from propmap.core.loads import _LOADS_FIELDS, RotorLoads

    om, V, b = 8000 * RPM, np.array([0.0, 10.0, 10.0, 6.0]), np.radians([0.0, 0.0, 60.0, 175.0])
    batch = pm.rotor_loads(apc8x6, apc_params, om, V, b)
    for i in range(V.size):
        one = pm.rotor_loads(apc8x6, apc_params, om, float(V[i]), float(b[i]))
        assert set(vars(one)) == _LOADS_FIELDS == {f.name for f in fields(RotorLoads)}
        for f in fields(RotorLoads):
            a = getattr(one, f.name)
            if isinstance(a, np.ndarray) and f.name != "r":
                assert a.shape == ()
                np.testing.assert_array_equal(a, getattr(batch, f.name)[i], err_msg=f.name)
    assert pm.rotor_loads(apc8x6, apc_params, om, 6.0, math.radians(175.0)).state_name == "vortex ring"


def test_the_parallel_and_the_serial_kernel_agree(apc8x6, apc_params):
    """A batch of PARALLEL_MIN_POINTS or more runs the parallel kernel, smaller ones the serial
    one (solver.PARALLEL_MIN_POINTS); both run the same compiled point (_kernel._solve_point,
    inlined by LLVM into each loop), so the same points take the same iterations and give the
    same loads to rounding (reassociation may differ between the two loops: 2.3e-16 relative
    measured with the paper's APC set, 2026-11-25; up to 9e-16 with the cambered sets,
    2026-11-27, docs/numerics.md, Reproducibility), in hover, axial climb and descent and
    oblique flow, with that set and the generic cambered one."""
    from propmap.core import solver

    rng = np.random.default_rng(1)
    n = 48
    om, V, b = rng.uniform(300.0, 1200.0, n), rng.uniform(0.0, 20.0, n), rng.uniform(0.0, np.pi, n)
    V[::5] = 0.0  # hover
    b[1::6] = 0.0  # axial climb
    b[2::6] = np.pi  # axial descent
    assert n >= solver.PARALLEL_MIN_POINTS > 8
    for params in (apc_params, pm.generic_params()):
        whole = pm.rotor_loads(apc8x6, params, om, V, b)
        parts = [pm.rotor_loads(apc8x6, params, om[k:k + 8], V[k:k + 8], b[k:k + 8]) for k in range(0, n, 8)]
        for f in ("n_evaluations", "state", "converged"):
            np.testing.assert_array_equal(getattr(whole, f), np.concatenate([getattr(q, f) for q in parts]),
                                          err_msg=f)
        for f in ("thrust", "drag", "torque", "rolling_moment", "v_i_mean"):
            np.testing.assert_allclose(getattr(whole, f), np.concatenate([getattr(q, f) for q in parts]),
                                       rtol=1e-13, atol=1e-15, err_msg=f)
        assert whole.converged.all()


@pytest.mark.parametrize("inflow", ["uniform", "pitt-peters"])
def test_the_parallel_and_the_serial_derivative_kernels_agree(apc8x6, inflow):
    """The implicit derivatives of a small batch (under solver.PARALLEL_MIN_POINTS) run on the
    calling thread (core/_sensitivity.sensitivities_serial, _linear_sensitivity's likewise: one
    point's took 0.30-1.67 ms in parallel with the second core busy, 0.14-0.30 ms serial,
    2026-11-28), a large batch's in
    parallel: the same compiled point, so the same derivatives to rounding, at rest (with the
    three rays of a velocity Jacobian), in hover, climb, descent and oblique flow, with the
    collective and a section parameter."""
    from propmap.core import solver
    from propmap.core.derivatives import STILL_AIR

    rng = np.random.default_rng(2)
    n = 40
    om, V, b = rng.uniform(300.0, 1200.0, n), rng.uniform(0.0, 20.0, n), rng.uniform(0.0, np.pi, n)
    V[::5] = 0.0
    b[1::6] = 0.0
    b[2::6] = np.pi
    assert n >= solver.PARALLEL_MIN_POINTS > 8
    params = pm.generic_params().replace(inflow=inflow)
    wrt = ("omega", "airspeed", "incidence", "collective", "cd_min", STILL_AIR)
    disc = pm.Discretization(24, 8)
    whole = pm.rotor_loads(apc8x6, params, om, V, b, derivatives=wrt, discretization=disc)
    parts = [pm.rotor_loads(apc8x6, params, om[k:k + 8], V[k:k + 8], b[k:k + 8], derivatives=wrt, discretization=disc)
             for k in range(0, n, 8)]
    for key, d in whole.jacobian.items():
        part = np.concatenate([q.jacobian[key] for q in parts])
        np.testing.assert_allclose(d, part, rtol=1e-12, atol=1e-14 * (np.abs(d).max() + 1e-300), err_msg=str(key))
    assert np.any(whole.derivative("thrust", STILL_AIR) != 0.0)


def test_a_ragged_vehicle_input_is_named():
    """A ragged velocity list gave NumPy's own error, which names no argument (a user-level
    audit, 2026-11-28): vehicle_wrench names it and the shape it wants."""
    from propmap.vehicle import read_vehicle, vehicle_wrench

    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    for name, bad in (("velocity", [[1.0, 0.0, 0.0], [1.0, 0.0]]), ("rotor_omega", [[800.0] * 4, [800.0] * 3])):
        args = {"velocity": [0.0, 0.0, 0.0], "angular_velocity": [0.0, 0.0, 0.0], "rotor_omega": [800.0] * 4}
        args[name] = bad
        with pytest.raises(ValueError, match=rf"^{name} must be a rectangular array of numbers of shape \(N, \d\)"):
            vehicle_wrench(veh, pm.generic_params(), **args)


def test_a_bool_inside_an_input_list_is_refused():
    """NumPy reads [800.0, True] as [800.0, 1.0]: rotor_loads ran a rotor at 1 rad/s (T = -0.057 N);
    a scalar bool was already refused. Every array input now refuses one, naming it."""
    from propmap.vehicle import read_vehicle, vehicle_wrench

    p, g = pm.load_propeller("apce_8x6"), pm.generic_params()
    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml")
    for call, name in ((lambda: pm.rotor_loads(p, g, [800.0, True], 5.0, 0.3), "omega"),
                       (lambda: pm.rotor_wrench(p, g, [True, 0, 0], [0, 0, 1], 800.0), "velocity"),
                       (lambda: vehicle_wrench(veh, g, [0, 0, 0], [True, 0, 0], [900.0] * 4), "angular_velocity"),
                       (lambda: vehicle_wrench(veh, g, [0, 0, 0], [0, 0, 0], [True, 900.0, 900.0, 900.0]),
                        "rotor_omega")):
        with pytest.raises(ValueError, match=f"^{name} must be "):
            call()


def test_vehicle_and_rotor_wrench_messages_name_their_own_arguments():
    """Messages that named rotor_loads' arguments (omega, airspeed, 'omega, airspeed and
    incidence') for vehicle_wrench's and rotor_wrench's inputs now name those inputs."""
    from propmap.vehicle import read_vehicle, vehicle_wrench

    p, g = pm.load_propeller("apce_8x6"), pm.generic_params()
    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml")
    with pytest.raises(ValueError, match=r"rotor_omega must be <= 100000 rad/s, got 200000 for rotor 2 \(sample 1"):
        vehicle_wrench(veh, g, [0, 0, 0], [0, 0, 0], [900.0, 2e5, 900.0, 900.0])
    with pytest.raises(ValueError, match=r"rotor 1's hub airspeed \|v \+ w x r - wind\| is 600 m/s at sample 1"):
        vehicle_wrench(veh, g, [600.0, 0, 0], [0, 0, 0], [900.0] * 4)
    with pytest.raises(ValueError, match="derivatives: unknown name 'foo'; valid for a vehicle: omega, rho"):
        vehicle_wrench(veh, g, [0, 0, 0], [0, 0, 0], [900.0] * 4, derivatives=["foo"])
    with pytest.raises(ValueError, match="valid: omega, airspeed, incidence, collective, rho or a numeric field"):
        pm.rotor_loads(p, g, 800.0, 5.0, 0.3, derivatives=["foo"])
    with pytest.raises(ValueError, match=r"omega \(shape \(2,\)\) must broadcast with velocity's samples"):
        pm.rotor_wrench(p, g, np.zeros((3, 3)), [0, 0, 1], [800.0, 900.0])
    with pytest.raises(TypeError, match="name must be a catalogue propeller's name"):
        pm.load_propeller(None)
    with pytest.raises(ValueError, match="omega must be a number or a rectangular array"):  # (ragged: rotor_loads')
        pm.rotor_wrench(p, g, np.zeros((2, 3)), [0, 0, 1], [[800.0, 900.0], [3.0]])


def test_a_propellers_name_is_a_string_and_its_stations_one_dimensional(apc8x6):
    """name=None or 5 was accepted, and an r of shape (1, n) flattened without a word (a
    property-based audit)."""
    import dataclasses

    for kw, said in ((dict(name=None), "name must be a string, got NoneType"),
                     (dict(name=5), "name must be a string, got int"),
                     (dict(r=apc8x6.r[None, :]), r"r must be a 1-D array \(one value per blade station\), got 2")):
        with pytest.raises(ValueError, match=said):
            dataclasses.replace(apc8x6, **kw)
    np.testing.assert_array_equal(dataclasses.replace(apc8x6, r=list(apc8x6.r)).r, apc8x6.r)


def test_single_precision_pi_is_axial_descent():
    """np.float32(np.pi), 8.7e-8 rad above pi, was refused as outside [0, pi] (a physics audit,
    2026-11-27); it is read as pi, scalar and array alike, and the caller's array is not written."""
    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    ref = pm.rotor_loads(prop, params, 900.0, 10.0, math.pi)
    b = np.deg2rad(np.array([180.0, 90.0], dtype=np.float32))
    kept = b.copy()
    for inc in (np.float32(np.pi), float(np.float32(np.pi))):
        r = pm.rotor_loads(prop, params, 900.0, 10.0, inc)
        assert float(r.incidence) == math.pi and float(r.thrust) == float(ref.thrust) and float(r.drag) == 0.0
    arr = pm.rotor_loads(prop, params, 900.0, 10.0, b)
    assert arr.incidence[0] == math.pi and arr.thrust[0] == float(ref.thrust)
    np.testing.assert_array_equal(b, kept)
    with pytest.raises(ValueError, match="incidence must be finite and in"):  # beyond float32's rounding
        pm.rotor_loads(prop, params, 900.0, 10.0, math.pi + 1e-6)
    # the scalar path snaps the low end as the array path does (it refused -1e-8, the array took it as 0)
    zero = pm.rotor_loads(prop, params, 900.0, 10.0, 0.0)
    for r in (pm.rotor_loads(prop, params, 900.0, 10.0, -1e-8), pm.rotor_loads(prop, params, 900.0, 10.0, [-1e-8])):
        assert float(np.ravel(r.incidence)[0]) == 0.0 and float(np.ravel(r.thrust)[0]) == float(zero.thrust)
    # a map's incidence axis and load data in single precision (a review, 2026-11-27: refused)
    from propmap.identify.load_data import LoadData
    from propmap.maps import build_map

    axis32 = np.deg2rad(np.linspace(0, 180, 3, dtype=np.float32))
    ds = build_map(prop, params, np.array([800.0, 900.0]), np.array([0.0, 10.0]), axis32, n_check=0)
    assert float(ds["incidence_deg"].values[-1]) == 180.0
    d = LoadData(np.array([900.0]), np.array([10.0]), b[:1], {"thrust": np.array([1.0])}, np.array(["a"], dtype=object))
    assert d.incidence[0] == math.pi
    with pytest.raises(ValueError, match="incidence must be in"):
        LoadData(np.array([900.0]), np.array([10.0]), np.array([math.pi + 1e-6]), {"thrust": np.array([1.0])},
                 np.array(["a"], dtype=object))


@pytest.mark.parametrize("beta_deg", [90.0, 60.0, 30.0])
def test_rotor_drag_at_small_mu_is_the_first_order_blade_element_h_force(beta_deg):
    """At small in-plane speed V_s = mu Omega R the rotor drag is, to first order in mu,
    D = (V_s / 2) sum_annuli (rho/2) N_b c dq_H/dU_T dr, with q_H = U (C_L U_P + C_D U_T) the
    element's in-plane load (the lift's tilt and the profile drag; eqs 1-4 of Gill & D'Andrea
    2017, averaged over the azimuth: U_T = Omega r + V_s sin psi) at the annulus' inflow U_P.
    The section loads are computed here from eqs (3)-(4) on their own; the error is O(mu^2).
    (A check that the forward-flight H-force is the blade-element theory's: measured at mu =
    0.002-0.02 within 8.4e-6 to 1.9e-3, 2026-11-27; the wind tunnels' larger H, docs/validation.md,
    is not a quadrature error.)"""
    prop = pm.load_propeller("apce_8x6")
    p = pm.preset("gill2017-apc").replace(cp_blasius=0.0)
    nd = _nodes(prop, 48, 16, p.air, p)
    om = 8000 * RPM
    b = math.radians(beta_deg)

    def q_H(UT, UP):
        alpha = nd.theta - np.arctan2(UP, UT)
        e1 = np.exp(np.clip(p.M * (alpha - p.alpha0), -40, 40))
        e2 = np.exp(np.clip(-p.M * (alpha + p.alpha0), -40, 40))
        s = 1.0 - 1.0 / ((1.0 + e1) * (1.0 + e2))
        CL = (1.0 - s) * p.cl1 * alpha + s * p.cl2 * np.sin(alpha) * np.cos(alpha)
        CD = p.cd * np.sin(alpha) ** 2 + p.cd0
        return np.hypot(UT, UP) * (CL * UP + CD * UT)

    err = []
    for mu in (0.005, 0.01):
        Vs = mu * om * prop.radius
        V = Vs / math.sin(b)
        r = pm.rotor_loads(prop, p, om, V, b, radial=True)
        UP = V * math.cos(b) + np.asarray(r.v_i).reshape(-1)
        UT = om * nd.y
        h = 1e-5 * UT
        dq = (q_H(UT + h, UP) - q_H(UT - h, UP)) / (2 * h)
        D1 = float(np.sum(nd.cfac * 0.5 * Vs * dq * nd.w))
        err.append(float(r.drag) / D1 - 1.0)
    assert abs(err[0]) < 2e-4 and abs(err[1]) < 8e-4
    assert 2.5 < err[1] / err[0] < 7.0  # O(mu^2) (measured 3.97-5.24): doubling mu about quadruples it
