"""The compiled kinematics of a vehicle step (propmap/vehicle/_kinematics.py) give the numbers of
the NumPy expressions they replaced, to the bit: hub velocities v - wind + w x r_i, and hub
moments r_i x F_i + M_i - w x (Omega_i h_i) - (dOmega_i/dt) h_i, with one-row inputs standing
for every sample."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.vector import cross3
from propmap.vehicle import read_vehicle, vehicle_wrench
from propmap.vehicle._kinematics import hub_moments, hub_velocity_loop

QUAD = Path(pm.__file__).parent / "data/examples/quadrotor.toml"


def _spread(rng, shape):
    """Numbers over many magnitudes and both signs, with exact zeros (signed) among them."""
    x = rng.normal(size=shape) * 10.0 ** rng.integers(-8, 8, size=shape)
    x[rng.random(shape) < 0.1] = 0.0
    x[rng.random(shape) < 0.05] = -0.0
    return x


def _signed_units(rng, shape):
    """-1, -0, +0 and +1 only: the sums and differences of which decide a zero's sign (a term left
    in or out, a subtraction of 0, changes it in about a fifth of such samples)."""
    return np.array([-1.0, -0.0, 0.0, 1.0])[rng.integers(0, 4, shape)]


@pytest.mark.parametrize("rows", [(7, 7, 7), (7, 1, 7), (1, 7, 1), (1, 1, 7), (7, 7, 1)])
def test_hub_velocities_equal_numpy_expression(rows):
    rng = np.random.default_rng(sum(rows))
    n_v, n_wind, n_w = rows
    N, n_rot = max(rows), 5
    v, wind, w = _spread(rng, (n_v, 3)), _spread(rng, (n_wind, 3)), _spread(rng, (n_w, 3))
    arms = _spread(rng, (n_rot, 3))
    got = np.empty((N, n_rot, 3))
    hub_velocity_loop(v, wind, w, arms, got)
    want = (np.broadcast_to(v, (N, 3)) - np.broadcast_to(wind, (N, 3)))[:, None, :] \
        + cross3(np.broadcast_to(w, (N, 3))[:, None, :], arms[None, :, :])
    assert got.tobytes() == want.tobytes()  # (bit for bit, signed zeros included)


@pytest.mark.parametrize("values", [_spread, _signed_units])
@pytest.mark.parametrize("gyro", [True, False])
@pytest.mark.parametrize("rows", [(6, 6, 6), (1, 6, 1), (6, 1, 6), (1, 1, 1), (6, 6, 0), (1, 1, 0)])
def test_hub_moments_equal_numpy_expression(gyro, rows, values):
    """(n_acc = 0: no rotor acceleration given, whose term the expressions left out.) With -1, -0, 0
    and 1 only, a term subtracted where it was left out (0 for a rotor of unknown inertia, or no
    acceleration) changes zeros' signs in about a fifth of the samples."""
    rng = np.random.default_rng(len(rows) + 10 * gyro + sum(rows))
    N, n_rot = max(rows) * (1 if values is _spread else 400), 4
    n_w, n_om, n_acc = (N if k > 1 else k for k in rows)
    arms, force, moment = values(rng, (n_rot, 3)), values(rng, (N, n_rot, 3)), values(rng, (N, n_rot, 3))
    w, om, acc = values(rng, (n_w, 3)), np.abs(values(rng, (n_om, n_rot))), values(rng, (n_acc, n_rot))
    h = values(rng, (n_rot, 3)) if gyro else np.zeros((n_rot, 3))
    got = moment.copy()
    hub_moments(arms, force, got, w, om, h, acc)
    want = moment + cross3(arms[None, :, :], force)
    if gyro:  # (as vehicle_wrench computed them until 2026-11-29; without a known inertia, not subtracted)
        want -= cross3(np.broadcast_to(w, (N, 3))[:, None, :], np.broadcast_to(om, (N, n_rot))[:, :, None] * h[None])
        if n_acc:
            want -= np.broadcast_to(acc, (N, n_rot))[:, :, None] * h[None]
    assert got.tobytes() == want.tobytes()


def test_vehicle_gyroscopic_and_spin_up_moments():
    """A rotor of inertia J spinning at Omega in a body turning at w adds -w x (s J Omega a) to the
    body moment, and spinning up at dOmega/dt adds -s J (dOmega/dt) a (the reaction); the force
    does not change (physics, not a regression value)."""
    veh = read_vehicle(QUAD)
    J = 3e-5
    spun = dataclasses.replace(veh, rotors=tuple(dataclasses.replace(r, inertia=J) for r in veh.rotors))
    params = pm.preset("gill2017-apc")
    v, w = np.array([[2.0, -1.0, 0.5]]), np.array([[0.4, -0.3, 1.2]])
    om, acc = np.array([[800.0, 830.0, 790.0, 815.0]]), np.array([[50.0, -20.0, 10.0, 0.0]])
    base = vehicle_wrench(veh, params, v, w, om)
    got = vehicle_wrench(spun, params, v, w, om, rotor_acceleration=acc)
    h = np.array([r.spin * J * r.axis for r in veh.rotors])  # s_i J a_i
    want = base.moment - np.cross(w, om[0] @ h) - acc[0] @ h
    np.testing.assert_allclose(got.moment, want, rtol=0, atol=1e-12 * np.abs(base.moment).max())
    assert np.array_equal(got.force, base.force)


def test_kept_geometry_follows_rotors_written_in_place():
    """vehicle_wrench keeps each vehicle's arms, axes and inertias (vehicle.layout.cached_rotor_geometry)
    and builds them again when a rotor's arrays or the centre of mass are written in place: the step
    then equals a new vehicle's (not the kept geometry's)."""
    from propmap.vehicle.layout import Vehicle, cached_rotor_geometry, rotor_geometry

    veh = read_vehicle(QUAD)
    params = pm.preset("gill2017-apc")
    v, w, om = [2.0, 1.0, -0.5], [0.3, -0.2, 0.9], [800.0, 830.0, 790.0, 815.0]
    first = vehicle_wrench(veh, params, v, w, om)
    kept = cached_rotor_geometry(veh)
    assert all(not a.flags.writeable for a in kept) and cached_rotor_geometry(veh) is kept
    assert all(a.flags.writeable for a in rotor_geometry(veh))  # (the public function's arrays are the caller's)
    veh.rotors[0].position[0] += 0.05
    veh.centre_of_mass[2] = 0.01
    moved = vehicle_wrench(veh, params, v, w, om)
    fresh = Vehicle(mass=veh.mass, rotors=tuple(dataclasses.replace(r) for r in veh.rotors),
                    centre_of_mass=veh.centre_of_mass.copy())
    assert np.array_equal(moved.moment, vehicle_wrench(fresh, params, v, w, om).moment)
    assert not np.array_equal(moved.moment, first.moment)
    spun = dataclasses.replace(veh.rotors[1], inertia=1e-4)
    object.__setattr__(veh, "rotors", (veh.rotors[0], spun) + veh.rotors[2:])  # (a rotor swapped: its inertia read)
    assert cached_rotor_geometry(veh)[3][1].any()


@pytest.mark.parametrize("edit", ["centre_of_mass", "axis", "spin", "inertia"])
def test_kept_geometry_follows_each_of_its_sources(edit):
    """Each thing the kept geometry comes from, changed alone, is seen: the centre of mass and a
    rotor's axis written in place, a rotor's spin and inertia set on the frozen object; the kept
    arrays then equal rotor_geometry's of the changed vehicle."""
    from propmap.vehicle.layout import cached_rotor_geometry, rotor_geometry

    veh = read_vehicle(QUAD)
    cached_rotor_geometry(veh)
    rot = veh.rotors[2]
    if edit == "centre_of_mass":
        veh.centre_of_mass[0] = 0.02
    elif edit == "axis":
        rot.axis[:] = [0.0, 0.6, 0.8]
    elif edit == "spin":
        object.__setattr__(rot, "spin", -rot.spin)
    else:
        object.__setattr__(rot, "inertia", 2e-5)
    for kept, fresh in zip(cached_rotor_geometry(veh), rotor_geometry(veh)):
        assert np.array_equal(kept, fresh)


def test_pickled_vehicle_keeps_no_geometry():
    """A vehicle pickled or deep-copied after a step carries no kept geometry (its arrays would come
    back writeable, another compiled type); the copy's step equals the original's."""
    import copy
    import pickle

    from propmap.vehicle.layout import cached_rotor_geometry

    veh = read_vehicle(QUAD)
    params = pm.preset("gill2017-apc")
    step = ([2.0, 1.0, -0.5], [0.3, -0.2, 0.9], [800.0, 830.0, 790.0, 815.0])
    first = vehicle_wrench(veh, params, *step)
    for other in (pickle.loads(pickle.dumps(veh)), copy.deepcopy(veh)):
        assert "_rotor_geometry" not in vars(other)
        assert not cached_rotor_geometry(other)[0].flags.writeable
        assert np.array_equal(vehicle_wrench(other, params, *step).moment, first.moment)


def test_hub_velocities_public_function():
    """propmap.vehicle.hub_velocities, which the fits, the flight scores and VehicleMap's batches use:
    (v - wind) + w x r_i as NumPy computes it, to the bit; a vector stands for every sample; read-only
    and strided inputs accepted; wrong shapes and unmatched sample counts refused by name."""
    from propmap.vehicle import hub_velocities

    rng = np.random.default_rng(3)
    v, w, wind, arms = _spread(rng, (9, 3)), _spread(rng, (9, 3)), _spread(rng, (3,)), _spread(rng, (4, 3))
    want = (v - wind)[:, None, :] + np.cross(w[:, None, :], arms[None])
    assert hub_velocities(v, w, arms, wind=wind).tobytes() == want.tobytes()
    ro = np.broadcast_to(w[:1], (9, 3))  # (read-only, zero-strided)
    assert np.array_equal(hub_velocities(v, ro, arms), v[:, None, :] + np.cross(w[:1, None, :], arms[None]))
    assert hub_velocities([1, 2, 3], [0, 0, 1.0], [[0.1, 0, 0]]).tolist() == [[[1.0, 2.1, 3.0]]]
    assert hub_velocities(np.zeros((0, 3)), np.zeros(3), arms).shape == (0, 4, 3)
    with pytest.raises(ValueError, match=r"same number of samples \(or one\), got 2, 3 and 1"):
        hub_velocities(np.zeros((2, 3)), np.zeros((3, 3)), arms)
    with pytest.raises(ValueError, match=r"arms must have shape \(N, 3\) or \(3,\), got \(4, 2\)"):
        hub_velocities(v, w, np.zeros((4, 2)))
    with pytest.raises(ValueError, match=r"wind must be finite"):
        hub_velocities(v, w, arms, wind=[0.0, np.nan, 0.0])
    with pytest.raises(ValueError, match=r"angular_velocity must be numbers of shape \(N, 3\) or \(3,\), got "
                                         r"\[0.0, True, 0.0\]"):
        hub_velocities(v, [0.0, True, 0.0], arms)
    with pytest.raises(ValueError, match=r"velocity must be numbers"):
        hub_velocities("fast", w, arms)


def test_overflowing_hub_velocity_refused_by_name():
    """A hub velocity that overflows (w x r = inf - inf: NaN) is refused as such, naming the rotor and
    the sample, also beside a sample that is only too fast (a NaN speed passed the speed check and
    reached the solver, which named the airspeed NaN; a review); a speed past 500 m/s names its value."""
    veh = dataclasses.replace(read_vehicle(QUAD), centre_of_mass=[0.0, -1e3, -1e3])
    params = pm.preset("gill2017-apc")
    rates = [800.0] * 4
    with pytest.raises(ValueError, match=r"rotor 1's hub velocity v \+ w x r - wind is not finite at sample 1"):
        vehicle_wrench(veh, params, [[0, 0, 0], [600, 0, 0]], [[0, 1e306, 1e306], [0, 0, 0]], rates)
    with pytest.raises(ValueError, match=r"rotor 1's hub airspeed \|v \+ w x r - wind\| is 600 m/s at sample 2, "
                                         r"beyond the model's 500 m/s"):
        vehicle_wrench(veh, params, [[0, 0, 0], [600, 0, 0]], [[0, 0, 0], [0, 0, 0]], rates)
