"""Behaviour a mutation audit found unpinned (a helper session: 93 mutants of vehicle/_kinematics.py,
vehicle/layout.py's rotor geometry and its cache, vehicle/model.py's vehicle_wrench, vehicle/_jacobians.py,
core/vector.py's frames and vectors, core/_interp.py's one-point fields and rotormap.py's one-point paths).
Each test names the mutants it kills (K: _kinematics, L: layout, M: model, J: _jacobians, V: vector,
I: _interp, R: rotormap); K11's test is tests/test_api_edges.py's, which calls hub_velocities too. 93
mutants, 69 killed by the suite, 23 user-visible survivors killed here, 1 equivalent (M20: the rotors'
columns copied instead of viewed when every rotor is one group, read only)."""

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.vehicle import Rotor, Vehicle, hub_velocities, read_vehicle, rotor_geometry, vehicle_wrench
from propmap.vehicle._kinematics import hub_moments
from propmap.vehicle.layout import cached_rotor_geometry

QUAD = Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml"


@pytest.fixture(scope="module")
def params():
    return pm.preset("gill2017-apc")


def _fresh(veh):
    """The same vehicle built anew from its rotors' current values (no kept geometry)."""
    rotors = tuple(dataclasses.replace(r, position=r.position.copy(), axis=r.axis.copy()) for r in veh.rotors)
    return dataclasses.replace(veh, rotors=rotors, centre_of_mass=veh.centre_of_mass.copy())


# ---- vehicle/_kinematics.py ---------------------------------------------------------------------------------------

def test_hub_velocities_wind_samples_count():
    """hub_velocities: a wind of N rows beside a one-row velocity and angular velocity gives N
    samples (each its own wind), and a wind of another count than the velocity's is refused.
    Kills K8 (the wind left out of the sample count)."""
    arms = np.array([[0.1, 0.0, 0.0], [0.0, -0.2, 0.05]])
    wind = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, -3.0]])
    got = hub_velocities([4.0, 0.0, 0.0], [0.0, 0.0, 1.0], arms, wind=wind)
    assert got.shape == (3, 2, 3)
    want = (np.array([4.0, 0.0, 0.0]) - wind)[:, None, :] + np.cross([0.0, 0.0, 1.0], arms)[None]
    np.testing.assert_array_equal(got, want)
    with pytest.raises(ValueError, match=r"got 2, 1 and 3"):
        hub_velocities(np.zeros((2, 3)), np.zeros(3), arms, wind=wind)


def test_hub_velocities_shape_message_names_the_input_shape():
    """A vector of the wrong length is named by its own shape, (2,), not the row it was promoted
    to. Kills K14."""
    with pytest.raises(ValueError, match=r"^velocity must have shape \(N, 3\) or \(3,\), got \(2,\)$"):
        hub_velocities([1.0, 2.0], [0.0, 0.0, 0.0], [[0.1, 0.0, 0.0]])


def _puller(inertia, spin=1.0):
    """One APC 8x6E rotor at the centre of mass thrusting forward (axis +x): its angular momentum
    s J Omega a lies along x only."""
    prop = pm.load_propeller("apce_8x6")
    return Vehicle(mass=1.0, rotors=(Rotor(np.zeros(3), np.array([1.0, 0.0, 0.0]), spin, prop, inertia=inertia),))


def test_gyroscopic_moment_of_a_rotor_along_x():
    """A rotor whose axis is body x (angular momentum along x only): yawing at r turns its angular
    momentum h = s J Omega x_hat, giving -w x h = -s J Omega r y_hat, and its spin-up -s J dOmega/dt x_hat;
    exactly the difference from the same rotor of unknown inertia (physics, hand-computed). Kills K15
    (the gyroscopic terms skipped unless some h_i has a y or z component)."""
    J, om, acc, r = 2e-5, 900.0, 40.0, 0.7
    p = pm.preset("gill2017-apc")
    v, w = [2.0, 0.0, 0.0], [0.0, 0.0, r]
    for spin in (1.0, -1.0):
        base = vehicle_wrench(_puller(None, spin), p, v, w, [om], rotor_acceleration=[acc])
        spun = vehicle_wrench(_puller(J, spin), p, v, w, [om], rotor_acceleration=[acc])
        want = base.moment[0] + np.array([-spin * J * acc, -spin * J * om * r, 0.0])
        np.testing.assert_allclose(spun.moment[0], want, rtol=0, atol=1e-15)
        assert abs(spun.moment[0, 1] - base.moment[0, 1]) == pytest.approx(J * om * r, rel=1e-12)


def test_hub_moments_without_inertia_keep_a_negative_zero():
    """hub_moments adds the gyroscopic and spin-up terms only where some rotor's inertia is known:
    without one, a moment that is -0.0 stays -0.0 (a spin-up term (-1) * 0 = -0.0 subtracted would
    make it +0.0; the module's claim of NumPy's numbers to the bit). Kills K25 (the terms always added)."""
    arms = np.array([[0.0, 1.0, 0.0]])
    force = np.array([[[0.0, 0.0, -0.0]]])  # r x F: x component 1 * (-0.0) - 0 * 0 = -0.0
    moment = np.array([[[-0.0, 0.0, 0.0]]])
    hub_moments(arms, force, moment, np.zeros((1, 3)), np.ones((1, 1)), np.zeros((1, 3)), np.full((1, 1), -1.0))
    assert moment[0, 0, 0] == 0.0 and np.signbit(moment[0, 0, 0])


# ---- vehicle/layout.py: rotor_geometry and its cache ------------------------------------------------------------

def _step(veh, params):
    """One sample with body rates (the arms matter to the hub velocities and the moment)."""
    return vehicle_wrench(veh, params, [2.0, 1.0, -0.5], [0.3, -0.2, 0.9], [800.0, 830.0, 790.0, 815.0])


def test_kept_geometry_follows_the_centre_of_mass_written_alone(params):
    """vehicle_wrench after the centre of mass alone is written in place equals a new vehicle's (the
    kept arms are built again). Kills L1 (the centre of mass left out of the cache's key)."""
    veh = read_vehicle(QUAD)
    first = _step(veh, params)
    veh.centre_of_mass[:] = [0.01, -0.02, 0.03]
    moved = _step(veh, params)
    assert np.array_equal(moved.moment, _step(_fresh(veh), params).moment)
    assert not np.array_equal(moved.moment, first.moment)
    np.testing.assert_array_equal(cached_rotor_geometry(veh)[0], rotor_geometry(veh)[0])


def test_kept_geometry_follows_a_position_written_alone(params):
    """A rotor's position alone written in place: the step equals a new vehicle's. Kills L2 (the
    positions left out of the cache's key)."""
    veh = read_vehicle(QUAD)
    first = _step(veh, params)
    veh.rotors[2].position[:] = [-0.2, -0.1, 0.02]
    moved = _step(veh, params)
    assert np.array_equal(moved.moment, _step(_fresh(veh), params).moment)
    assert not np.array_equal(moved.moment, first.moment)


def test_kept_geometry_follows_an_axis_written_alone(params):
    """A rotor's (unit) axis alone written in place, tilting it: the step's force equals a new
    vehicle's. Kills L3 (the axes left out of the cache's key)."""
    veh = read_vehicle(QUAD)
    first = _step(veh, params)
    veh.rotors[1].axis[:] = np.array([0.3, 0.0, 1.0]) / np.hypot(0.3, 1.0)
    moved = _step(veh, params)
    fresh = _step(_fresh(veh), params)
    assert np.array_equal(moved.force, fresh.force) and np.array_equal(moved.moment, fresh.moment)
    assert not np.array_equal(moved.force, first.force)


def test_kept_geometry_follows_a_spin_reversed(params):
    """A rotor of known inertia swapped for one of the other spin (same position, axis and inertia):
    its angular momentum s J a changes sign, and the step equals a new vehicle's. Kills L4 (the
    spins left out of the cache's key, which cached_rotor_geometry's docstring names)."""
    veh = read_vehicle(QUAD)
    veh = dataclasses.replace(veh, rotors=tuple(dataclasses.replace(r, inertia=3e-5) for r in veh.rotors))
    _step(veh, params)
    turned = dataclasses.replace(veh.rotors[0], spin=-veh.rotors[0].spin)
    object.__setattr__(veh, "rotors", (turned,) + veh.rotors[1:])  # (as the existing test swaps a rotor)
    np.testing.assert_array_equal(cached_rotor_geometry(veh)[3], rotor_geometry(veh)[3])
    assert cached_rotor_geometry(veh)[3][0, 2] == turned.spin * 3e-5
    assert np.array_equal(_step(veh, params).moment, _step(_fresh(veh), params).moment)


def test_rotor_geometry_normalises_an_axis_written_in_place(params):
    """rotor_geometry's axes are unit even where a Rotor's axis was written in place not unit, and
    h = s J a with that unit axis; vehicle_wrench's gyroscopic moment is the unit axis' (the same as
    a new vehicle's). Kills L11 (the normalisation in rotor_geometry removed)."""
    veh = read_vehicle(QUAD)
    veh = dataclasses.replace(veh, rotors=tuple(dataclasses.replace(r, inertia=3e-5) for r in veh.rotors))
    veh.rotors[0].axis[:] = [0.0, 0.0, 2.0]
    arms, axes, spins, h = rotor_geometry(veh)
    np.testing.assert_allclose(np.linalg.norm(axes, axis=1), 1.0, rtol=1e-15)
    np.testing.assert_array_equal(h[0], [0.0, 0.0, 3e-5])
    new = dataclasses.replace(veh, rotors=(dataclasses.replace(veh.rotors[0], axis=[0.0, 0.0, 1.0]),)
                              + veh.rotors[1:])
    assert np.array_equal(_step(veh, params).moment, _step(new, params).moment)


# ---- vehicle/model.py: vehicle_wrench -----------------------------------------------------------------------------

def test_rotor_omega_at_the_documented_limit_is_accepted(params):
    """rotor_omega is documented in [0, 1e5] rad/s: 1e5 itself is solved (with the tip-Mach warning),
    the next float up refused. Kills M6 (> OMEGA_MAX made >=)."""
    veh = read_vehicle(QUAD)
    with pytest.warns(UserWarning, match="Mach"):
        r = vehicle_wrench(veh, params, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1e5] * 4, on_failure="flag")
    assert r.force.shape == (1, 3)
    with pytest.raises(ValueError, match=r"rotor_omega must be <= 100000 rad/s"):
        vehicle_wrench(veh, params, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [np.nextafter(1e5, 2e5)] * 4)


def test_rotor_acceleration_samples_must_match(params):
    """rotor_acceleration of 3 samples beside one-sample motion and speeds is refused (not its first
    row taken silently), as every other input's count. Kills M8 (it left out of the sample count)."""
    veh = read_vehicle(QUAD)
    with pytest.raises(ValueError, match=r"same number of samples \(or one\), got \[1, 1, 2, 1, 3\]"):
        vehicle_wrench(veh, params, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [[800.0] * 4] * 2,
                       rotor_acceleration=np.zeros((3, 4)))


def test_hub_airspeed_limit_is_inclusive_and_names_rotor_and_sample(params):
    """A hub airspeed of exactly AIRSPEED_MAX (500 m/s) is solved; above it, the message names the
    rotor and the sample that exceed it (rotor 4, back-left, in sample 2 of 2: rotor and sample
    indices not swapped). Kills M10 (> made >=) and M28 (the indices swapped)."""
    veh = read_vehicle(QUAD)
    with pytest.warns(UserWarning, match="Mach"):
        r = vehicle_wrench(veh, params, [0.0, 0.0, 500.0], [0.0, 0.0, 0.0], [800.0] * 4, on_failure="flag")
    assert r.loads[0].airspeed[0] == 500.0
    d = -np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)  # rotor 4 at (-0.106, 0.106): w x r = (-0.212, -0.212, 0)
    v = np.array([np.zeros(3), 499.9 * d])  # rotor 4's hub: 499.9 + 0.3 m/s; the others' at most 499.9001
    with pytest.raises(ValueError, match=r"^rotor 4's hub airspeed \|v \+ w x r - wind\| is 500\.2 m/s at sample 2,"):
        vehicle_wrench(veh, params, v, [0.0, 0.0, 2.0], [800.0] * 4)


def test_one_rotor_with_interference_gives_its_derivatives(params):
    """Rotor interference couples two or more rotors' wakes; a one-rotor vehicle has no other wake,
    so its derivatives are given (those of the same rotor at k_I = 0). Kills M12 (refused for one
    rotor too)."""
    one = dataclasses.replace(read_vehicle(QUAD), rotors=read_vehicle(QUAD).rotors[:1], rotor_interference=1.0)
    v, w = [3.0, 1.0, 0.0], [0.2, 0.0, 0.1]
    a = vehicle_wrench(one, params, v, w, [800.0], derivatives=True)
    b = vehicle_wrench(dataclasses.replace(one, rotor_interference=0.0), params, v, w, [800.0], derivatives=True)
    np.testing.assert_array_equal(a.force_domega, b.force_domega)
    np.testing.assert_array_equal(a.moment_domega, b.moment_domega)


def test_derivatives_at_the_lowest_rotor_speed(params):
    """Derivatives need Omega_i >= 0.1 rad/s (documented): at 0.1 itself they are given, below it
    refused. Kills M13 (< OMEGA_MIN made <=)."""
    veh = read_vehicle(QUAD)
    r = vehicle_wrench(veh, params, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.1] * 4, derivatives=True)
    assert np.all(np.isfinite(r.force_domega)) and np.all(r.force_domega[0, 2] > 0)
    with pytest.raises(ValueError, match=r"derivatives need every rotor_omega >= 0.1 rad/s"):
        vehicle_wrench(veh, params, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.1, 0.1, 0.0999, 0.1], derivatives=True)


def test_body_drag_argument_overrides_the_vehicles(params):
    """vehicle_wrench(body_drag=...) replaces the vehicle's own airframe drag ("default the
    vehicle's"): the airframe force is the argument's, -(rho/2) C |u| u with u = v - wind (no
    slipstream), computed here by hand. Kills M18 (the vehicle's drag kept when both are given)."""
    from propmap.core.body import BodyDrag

    veh = dataclasses.replace(read_vehicle(QUAD), body_drag=BodyDrag((0.5, 0.5, 0.5), 0.0))
    mine = BodyDrag((0.01, 0.02, 0.03), 0.0)
    v, wind = np.array([6.0, -2.0, 1.0]), np.array([1.0, 1.0, 0.0])
    r = vehicle_wrench(veh, params, v, [0.0, 0.0, 0.0], [800.0] * 4, wind=wind, body_drag=mine)
    u = v - wind
    want = -0.5 * params.air.rho * np.array([0.01, 0.02, 0.03]) * np.linalg.norm(u) * u
    np.testing.assert_allclose(r.body_force[0], want, rtol=1e-14)
    np.testing.assert_allclose(r.force[0], r.rotor_force[0].sum(axis=0) + want, rtol=1e-14)


def test_an_inactive_airframe_drag_gives_plain_zeros(params):
    """A BodyDrag of zero areas is no airframe drag: body_force is zeros (+0.0, not the -0.0 of
    -(rho/2) 0 |u| u). Kills M19 (body.active not asked: the sign of zero only)."""
    from propmap.core.body import BodyDrag

    veh = dataclasses.replace(read_vehicle(QUAD), body_drag=BodyDrag((0.0, 0.0, 0.0), 1.0))
    r = vehicle_wrench(veh, params, [5.0, 2.0, -1.0], [0.0, 0.0, 0.0], [800.0] * 4)
    assert not np.signbit(r.body_force).any() and not r.body_force.any()


# ---- vehicle/_jacobians.py ----------------------------------------------------------------------------------------

def test_incidence_is_refused_as_a_rotor_input(params):
    """derivatives=("incidence",) is refused as a rotor's input (as "airspeed"), naming what to use
    instead, not as an unknown name. Kills J3 ("incidence" dropped from the rotor inputs)."""
    veh = read_vehicle(QUAD)
    with pytest.raises(ValueError, match=r"derivatives: 'incidence' is a rotor's input, not the vehicle's"):
        vehicle_wrench(veh, params, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [800.0] * 4, derivatives=("incidence",))


def test_airframe_drag_jacobian_is_zero_in_still_air(params):
    """The airframe drag -(rho/2) C |u| u is quadratic in its air speed u: its Jacobian is 0 at
    u = 0 (drag_jacobian's docstring), so at rest without slipstream (wash_factor 0) the vehicle's
    velocity Jacobians are the rotors' alone, finite and equal to those without an airframe.
    Kills J12 (speed >= 0 as the divisor's guard: 0/0)."""
    from propmap.core.body import BodyDrag
    from propmap.vehicle._jacobians import drag_jacobian

    np.testing.assert_array_equal(drag_jacobian(np.zeros((2, 3)), np.array([0.02, 0.02, 0.03]), 1.2), 0.0)
    veh = read_vehicle(QUAD)
    rest, om = np.zeros(3), [800.0] * 4
    body = BodyDrag((0.02, 0.02, 0.03), 0.0)
    a = vehicle_wrench(veh, params, rest, rest, om, body_drag=body, derivatives=("velocity", "angular_velocity"))
    b = vehicle_wrench(veh, params, rest, rest, om, derivatives=("velocity", "angular_velocity"))
    for key, J in a.jacobian.items():
        assert np.all(np.isfinite(J)), key
        np.testing.assert_array_equal(J, b.jacobian[key], err_msg=str(key))


def test_drag_area_derivatives_without_an_airframe(params):
    """A vehicle with no airframe drag still gets the drag areas' derivatives ("hold at zero drag
    areas too"): dF/dC_k = -(rho/2) |u| u_k e_k with u = v - wind (BodyDrag's default wash_factor 0),
    hand-computed, and a forward difference of the linear drag agrees; the moment's are zero.
    Kills J25 (no default BodyDrag: zeros)."""
    from propmap.core.body import BodyDrag

    veh = read_vehicle(QUAD)
    v, wind, om = np.array([6.0, -1.0, 2.0]), np.array([1.0, 0.0, 0.0]), [800.0] * 4
    names = ("drag_area_x", "drag_area_z")
    r = vehicle_wrench(veh, params, v, [0.0, 0.0, 0.0], om, wind=wind, derivatives=names)
    u = v - wind
    rho = params.air.rho
    np.testing.assert_allclose(r.jacobian[("force", "drag_area_x")][0], [-0.5 * rho * np.linalg.norm(u) * 5.0, 0, 0],
                               rtol=1e-14)
    np.testing.assert_allclose(r.jacobian[("force", "drag_area_z")][0], [0, 0, -0.5 * rho * np.linalg.norm(u) * 2.0],
                               rtol=1e-14)
    np.testing.assert_array_equal(r.jacobian[("moment", "drag_area_x")], 0.0)
    h = 1e-3
    a = vehicle_wrench(veh, params, v, [0.0, 0.0, 0.0], om, wind=wind, body_drag=BodyDrag((h, 0.0, 0.0)))
    b = vehicle_wrench(veh, params, v, [0.0, 0.0, 0.0], om, wind=wind)
    np.testing.assert_allclose((a.force - b.force) / h, r.jacobian[("force", "drag_area_x")], rtol=1e-9, atol=1e-12)


# ---- core/vector.py -----------------------------------------------------------------------------------------------

def test_a_zero_axis_is_refused_for_zero_samples_too():
    """rotor_wrench (core.vector.disk_frame) refuses a zero axis whether or not there is a sample to
    solve: a velocity of shape (0, 3) beside the axis [0, 0, 0] is refused as one sample is, while a
    non-zero axis gives an empty answer. Kills V3 (the check of an empty batch removed)."""
    prop, p = pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")
    with pytest.raises(ValueError, match="axis must be non-zero"):
        pm.rotor_wrench(prop, p, np.zeros((0, 3)), [0.0, 0.0, 0.0], np.zeros(0))
    with pytest.raises(ValueError, match="axis must be non-zero"):
        pm.rotor_wrench(prop, p, np.ones((1, 3)), [0.0, 0.0, 0.0], np.full(1, 800.0))
    assert pm.rotor_wrench(prop, p, np.zeros((0, 3)), [0.0, 0.0, 1.0], np.zeros(0)).force.shape == (0, 3)


# ---- rotormap.py: the one-point paths -----------------------------------------------------------------------------

def test_scalar_loads_snap_an_airspeed_just_beyond_the_axis_end():
    """RotorMap.loads at one point of floats: an airspeed within AIRSPEED_SNAP (1e-12, relative)
    above the airspeed axis' end is on it, inside the grid, as the array path has it, under every
    policy (finite loads under "nan", inside True under "clip"). Kills R3 (the scalar path's snap
    removed: NaN and inside False)."""
    from propmap.maps import RotorMap, build_map

    prop, p = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    ds = build_map(prop, p, np.array([500.0, 700.0, 900.0]), np.array([0.0, 5.0, 10.0]),
                   np.radians([0.0, 45.0, 90.0, 135.0, 180.0]), n_check=1)
    rm = RotorMap(ds)
    V = 10.0 * (1.0 + 5e-13)
    for policy in ("nan", "clip", "raise"):
        one = rm.loads(600.0, V, 1.0, out_of_grid=policy)
        arr = rm.loads(np.array([600.0]), np.array([V]), np.array([1.0]), out_of_grid=policy)
        assert type(one.thrust) is float and one.inside is True, policy
        assert one.thrust == arr.thrust[0] and np.isfinite(one.thrust), policy
