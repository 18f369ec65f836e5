"""The vehicle model from rotor maps (propmap.vehicle.VehicleMap): the same sums as
vehicle_wrench with each rotor's RotorMap.wrench, exact to round-off against those sums done
by hand, within the maps' error of the full model, and a stopped rotor under "clip"."""

import math
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag
from propmap.maps import RotorMap, build_map
from propmap.vehicle import VehicleMap, read_vehicle, vehicle_wrench
from propmap.vehicle import Rotor, Vehicle

DATA = Path(pm.__file__).parent / "data"
RPM = math.pi / 30


@pytest.fixture(scope="module")
def setup():
    veh = read_vehicle(DATA / "examples" / "quadrotor.toml")  # four apce_8x6, spins ccw/cw
    params = pm.default_params("apce_8x6")
    prop = veh.rotors[0].propeller
    ds = build_map(prop, params, np.geomspace(2000, 12000, 15) * RPM, np.linspace(0, 12, 13),
                   np.radians(np.linspace(0, 180, 37)), air=params.air, params_label=params.label, n_check=0)
    # rotor inertias and an airframe, so that every term of the sum is exercised
    rotors = tuple(Rotor(r.position, r.axis, r.spin, r.propeller, inertia=2e-5) for r in veh.rotors)
    veh = Vehicle(mass=veh.mass, rotors=rotors, body_drag=BodyDrag((0.01, 0.012, 0.02)),
                  centre_of_mass=np.array([0.005, 0.0, -0.01]))
    return veh, params, RotorMap(ds)


def _states(n, seed=2):
    rng = np.random.default_rng(seed)
    v = rng.normal(0, 3, (n, 3))
    w = rng.normal(0, 1.0, (n, 3))
    om = rng.uniform(500, 1100, (n, 4))
    return v, w, om


def test_equals_the_rotor_maps_summed_by_hand(setup):
    veh, params, rm = setup
    v, w, om = _states(50)
    got = VehicleMap(veh, rm).wrench(v, w, om)
    pos = np.array([r.position for r in veh.rotors]) - veh.centre_of_mass
    F = np.zeros((50, 3))
    M = np.zeros((50, 3))
    for i, r in enumerate(veh.rotors):
        vh = v + np.cross(w, pos[i])
        res = rm.wrench(vh, r.axis, om[:, i], r.spin)
        F += res.force
        M += np.cross(pos[i], res.force) + res.torque - np.cross(w, (r.spin * r.inertia * om[:, i])[:, None] * r.axis)
    F += -0.5 * rm.attrs["rho_kg_m3"] * np.array(veh.body_drag.drag_area) * np.linalg.norm(v, axis=1)[:, None] * v
    np.testing.assert_allclose(got.force, F, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(got.moment, M, rtol=1e-12, atol=1e-12)
    # one step at a time (a simulator's call: each rotor by RotorMap.wrench's one-rotor path) = the batch's rows
    vm = VehicleMap(veh, rm)
    for i in range(8):
        one = vm.wrench(v[i], w[i], om[i])
        assert one.force.shape == (1, 3) and one.flagged[0] == got.flagged[i]
        np.testing.assert_allclose(one.force[0], got.force[i], rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(one.moment[0], got.moment[i], rtol=1e-12, atol=1e-12)


def test_within_the_maps_error_of_the_full_model(setup):
    veh, params, rm = setup
    v, w, om = _states(40, seed=5)
    v[:, 2] = np.abs(v[:, 2])  # forward flight and climb: away from the vortex-ring cells, which are flagged
    got = VehicleMap(veh, rm).wrench(v, w, om)
    ref = vehicle_wrench(veh, params, v, w, om)
    keep = ~got.flagged  # the maps' bounds hold outside flagged cells
    assert keep.sum() >= 20
    # relative to the weight and its moment arm: 15 rpm nodes over 2000-12000 (13% steps), cubic
    err_F = np.max(np.abs(got.force - ref.force)[keep]) / veh.weight
    err_M = np.max(np.abs(got.moment - ref.moment)[keep]) / (veh.weight * 0.1)
    assert err_F < 0.01 and err_M < 0.01, (err_F, err_M)


def test_a_stopped_rotor_and_bad_input(setup):
    veh, params, rm = setup
    vm = VehicleMap(veh, [rm] * 4)
    om = np.array([[900.0, 0.0, 900.0, 900.0]])
    with pytest.raises(ValueError, match="outside the map's grid"):
        vm.wrench([0, 0, 0], [0, 0, 0], om)
    res = vm.wrench([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], om, out_of_grid="clip")
    alone = vm.wrench([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], np.array([[900.0, 900.0, 900.0, 900.0]]))
    assert res.force[0, 2] == pytest.approx(0.75 * alone.force[0, 2], rel=1e-12)  # the stopped rotor adds nothing
    assert res.flagged[0] and not alone.flagged[0]
    with pytest.raises(ValueError, match="maps must be one RotorMap or one per rotor"):
        VehicleMap(veh, [rm, rm])
    with pytest.raises(ValueError, match=r"rotor_omega must have shape \(N, 4\)"):
        vm.wrench([0, 0, 0], [0, 0, 0], [900.0, 900.0])
    with pytest.warns(UserWarning, match="slipstream factor"):
        VehicleMap(Vehicle(mass=1.0, rotors=veh.rotors, body_drag=BodyDrag((0.01, 0.01, 0.0), 1.2)), rm)


def test_a_velocity_beyond_1e150_is_refused_as_the_c_header_refuses_it(setup):
    """Under "clip" a hub velocity of 1e160 m/s once returned the thrust alone: the drag and rolling
    moment vectors overflowed to zero (W.force [0, 0, 5.6] beside loads.drag 0.61; user-level
    audit, 2026-11-26). The C header's wrench returns -1 there; Python refuses it, one point or
    many, and through VehicleMap (body rates of 1e200 rad/s)."""
    veh, params, rm = setup
    for velocity in ([1e160, 0.0, 0.0], np.array([[1e160, 0.0, 0.0], [1.0, 0.0, 0.0]])):
        with pytest.raises(ValueError, match=r"velocity: a component of 1e\+160 m/s; a hub velocity must be below"):
            rm.wrench(velocity, [0.0, 0.0, 1.0], 600.0, "cw", out_of_grid="clip")
    import propmap.rotormap
    from propmap.core.vector import VELOCITY_MAX

    assert propmap.rotormap.VELOCITY_MAX == VELOCITY_MAX == 1e150  # (the map's own copy: its import stays light)
    below = rm.wrench([0.99e150, 0.0, 0.0], [0.0, 0.0, 1.0], 600.0, "cw", out_of_grid="clip")
    assert np.all(np.isfinite(below.force)) and below.loads.drag > 0
    vm = VehicleMap(veh, rm)
    for n in (1, 2):
        said = (r"angular_velocity make a rotor hub's velocity of up to 1.\d+e\+199 m/s \(velocity - wind \+ "
                r"angular_velocity x arm\); it must stay below 1e\+150")
        with pytest.raises(ValueError, match=said):
            vm.wrench(np.zeros((n, 3)), np.tile([1e200, 0.0, 0.0], (n, 1)), np.full((n, 4), 900.0), out_of_grid="clip")


def test_a_query_just_outside_the_grid_is_shown_against_its_ends_in_full(setup):
    """omega = nextafter(the grid's top) was refused as 'outside [209.44, 1047.2]', which reads as
    inside (user-level audit, 2026-11-26): where rounding would hold the value, the ends are shown
    whole."""
    rm = setup[2]
    top = float(rm.omega[-1])
    with pytest.raises(ValueError, match=rf"omega = {float(np.nextafter(top, 2 * top))!r} is outside the map's grid "
                                         rf"\[{float(rm.omega[0])!r}, {top!r}\] rad/s"):
        rm.loads(np.nextafter(top, 2 * top), 1.0, 0.5)
    with pytest.raises(ValueError, match=r"airspeed = 13.0 is outside the map's grid \[0, 12\] m/s"):
        rm.loads(top, 13.0, 0.5)


def test_one_step_in_one_compiled_call_equals_each_rotor_by_its_map(setup):
    """A vehicle whose rotors share one map takes one step in one compiled call
    (core._interp.vehicle_point): the same force, moment and flag as each rotor through its
    map's one-rotor path (a VehicleMap of four copies of the map, which takes that path), with
    wind, rotor inertia and the airframe, under each policy, for arrays, lists and tuples; the
    inputs it does not take, and the ones it refuses, go to the general path's checks."""
    import copy

    veh, params, rm = setup
    one, each = VehicleMap(veh, rm), VehicleMap(veh, [copy.copy(rm) for _ in range(4)])
    assert one._one_map is rm and each._one_map is None
    v, w, om = _states(60, seed=7)
    om[:10] *= 1.5  # 750-1650 rad/s: some rotors above the grid's 1257 rad/s (clipped or NaN)
    wind = np.random.default_rng(3).normal(0, 2, (60, 3))
    n_flagged = 0
    for i in range(60):
        for policy in ("clip", "nan") if i < 10 else ("raise", "clip"):
            args = (v[i], w[i], om[i]) if i % 3 else (v[i].tolist(), tuple(w[i]), om[i].tolist())
            kw = dict(wind=wind[i] if i % 2 else None, out_of_grid=policy)
            a, b = one.wrench(*args, **kw), each.wrench(*args, **kw)
            assert a.force.shape == a.moment.shape == (1, 3) and a.flagged.shape == (1,)
            np.testing.assert_allclose(a.force, b.force, rtol=1e-13, atol=1e-13)
            np.testing.assert_allclose(a.moment, b.moment, rtol=1e-13, atol=1e-13)
            assert a.flagged[0] == b.flagged[0]
            n_flagged += bool(a.flagged[0])
            if policy == "nan" and i < 10 and om[i].max() > rm.omega[-1]:
                assert np.isnan(a.force).all() and a.flagged[0]
    assert 10 <= n_flagged < 100  # (both kinds of sample: the comparison covers the flag)
    # the result's arrays are its own: a second step leaves the first one's unchanged
    first = one.wrench(v[20], w[20], om[20])
    kept = first.force.copy()
    one.wrench(v[21], w[21], om[21])
    assert np.array_equal(first.force, kept)
    # refused as by the general path
    with pytest.raises(ValueError, match="velocity must be finite"):
        one.wrench([np.nan, 0.0, 0.0], [0.0, 0.0, 0.0], om[20])
    with pytest.raises(ValueError, match=r"omega = 1500\.0 is outside the map's grid"):
        one.wrench(v[20], w[20], [1500.0, 900.0, 900.0, 900.0])
    with pytest.raises(ValueError, match="omega must be >= 0"):
        one.wrench(v[20], w[20], [-1.0, 900.0, 900.0, 900.0], out_of_grid="clip")
    with pytest.raises(ValueError, match="out_of_grid must be one of"):
        one.wrench(v[20], w[20], om[20], out_of_grid="extrapolate")
    with pytest.raises(ValueError, match=r"rotor_omega must have shape \(N, 4\)"):
        one.wrench(v[20], w[20], om[20][:3])


def test_one_compiled_step_carries_the_side_force_and_pitching_moment(setup):
    """With flapping blades the map holds Y and M_P (a second table): the compiled step sums them
    as each rotor's one-rotor path does."""
    import copy

    veh = setup[0]
    prop = veh.rotors[0].propeller
    ds = build_map(prop, pm.generic_params().replace(flap_compliance=2.0), np.linspace(500, 1300, 4),
                   np.linspace(0, 12, 4), np.radians(np.linspace(0, 180, 7)), n_check=0)
    rm = RotorMap(ds)
    assert rm.side_loads
    one, each = VehicleMap(veh, rm), VehicleMap(veh, [copy.copy(rm) for _ in range(4)])
    v, w, om = _states(20, seed=11)
    for i in range(20):
        a, b = one.wrench(v[i], w[i], om[i], out_of_grid="clip"), each.wrench(v[i], w[i], om[i], out_of_grid="clip")
        np.testing.assert_allclose(a.force, b.force, rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(a.moment, b.moment, rtol=1e-13, atol=1e-13)
        assert a.flagged[0] == b.flagged[0]
    # the side force is not negligible at these steps, so the comparison covers its sum
    side = rm.wrench(v[0] + np.cross(w[0], one._pos[0]), one._axes[0], om[0, 0], one._spin_list[0],
                     out_of_grid="clip").loads
    assert abs(side.side_force) > 1e-3


def test_a_nan_in_any_component_is_refused_on_the_one_step_paths(setup):
    """numba's max() drops a NaN that is not its first argument: a NaN in the y or z component of
    the velocity, the wind or a rotor's axis passed the compiled paths' finiteness check, and
    VehicleMap.wrench (and RotorMap.wrench for one rotor) returned NaN vectors under "clip" where
    the array path refuses the input (a review, 2026-11-28). Each component, each path."""
    veh, params, rm = setup
    vm = VehicleMap(veh, rm)
    om = np.full(4, 700.0)
    for k in range(3):
        bad = [0.0, 0.0, 0.0]
        bad[k] = math.nan
        for policy in ("clip", "nan"):
            with pytest.raises(ValueError, match="velocity must be finite"):
                vm.wrench(bad, [0.0, 0.0, 0.0], om, out_of_grid=policy)
            with pytest.raises(ValueError, match="wind must be finite"):
                vm.wrench([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], om, wind=bad, out_of_grid=policy)
            with pytest.raises(ValueError, match="angular_velocity must be finite"):
                vm.wrench([0.0, 0.0, 0.0], bad, om, out_of_grid=policy)
            with pytest.raises(ValueError, match="velocity must be finite"):
                rm.wrench(bad, [0.0, 0.0, 1.0], 700.0, "ccw", out_of_grid=policy)
            axis = [0.0, 0.0, 1.0]
            axis[k] = math.nan
            with pytest.raises(ValueError, match="axis must be finite"):
                rm.wrench([1.0, 0.0, 0.0], axis, 700.0, "ccw", out_of_grid=policy)


def test_a_map_whose_wrench_is_overridden_is_called_rotor_by_rotor(setup):
    """The maps are duck-typed by their wrench: a RotorMap subclass (or an instance) with its own
    wrench is called for each rotor, not bypassed by the compiled one-step path (a review,
    2026-11-28: a subclass halving the vectors gave the unhalved sum)."""
    import copy

    veh, params, rm = setup

    class Halved(RotorMap):
        def wrench(self, *args, **kwargs):
            w = super().wrench(*args, **kwargs)
            return type(w)(w.force / 2, w.torque / 2, w.loads)

    half = Halved(rm.dataset, rm.interpolation)
    patched = RotorMap(rm.dataset, rm.interpolation)
    patched.wrench = half.wrench  # (an instance's own wrench)
    v, w, om = np.array([3.0, 0.5, -0.2]), np.array([0.1, -0.2, 0.05]), np.full(4, 700.0)
    by_rotor = VehicleMap(veh, [copy.copy(half) for _ in range(4)]).wrench(v, w, om)  # (four maps: per rotor)
    whole = VehicleMap(veh, rm).wrench(v, w, om)
    assert abs(by_rotor.force[0, 2] - whole.force[0, 2]) > 0.3 * abs(whole.force[0, 2])  # (the halving shows)
    for m in (half, patched):
        got = VehicleMap(veh, m).wrench(v, w, om)
        np.testing.assert_allclose(got.force, by_rotor.force, rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(got.moment, by_rotor.moment, rtol=1e-13, atol=1e-13)
