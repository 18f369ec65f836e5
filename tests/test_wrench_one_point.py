"""rotor_wrench at one operating point takes a path in Python floats (a controller's call): the
same force and moment as the array path, the same errors (user-level audit, 2026-11-26: one
call cost 290 us against the loads' 115 us, the rest building the frame and vectors)."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core import vector


@pytest.mark.parametrize("options", [{}, {"flap_compliance": 3.0}, {"inflow": "pitt-peters"}])
def test_one_point_matches_the_array_path(options):
    """Random velocities (axial, zero, edgewise and oblique), axes, rates and both spins; a flapping
    set and a linear inflow give the side force and pitching moment too."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.generic_params().replace(**options)
    rng = np.random.default_rng(3)
    side = 0.0
    for k in range(40):
        a = rng.normal(size=3)
        v = rng.normal(size=3) * rng.choice([1.0, 5.0, 15.0])
        v = a * 2.0 if k % 7 == 0 else np.zeros(3) if k % 11 == 0 else v
        om, spin = float(rng.uniform(300, 1200)), ["cw", "ccw", 1, -1.0][k % 4]
        one = pm.rotor_wrench(prop, params, list(v), tuple(a), om, spin)
        arr = pm.rotor_wrench(prop, params, v[None], a[None], np.array([om]), np.array([vector._spin_sign(spin)]))
        assert one.force.shape == (3,) and one.torque.shape == (3,) and one.loads.thrust.shape == ()
        np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-13, atol=1e-13 * abs(arr.loads.thrust[0]))
        np.testing.assert_allclose(one.torque, arr.torque[0], rtol=1e-13, atol=1e-13 * abs(arr.loads.torque[0]))
        side = max(side, abs(float(one.loads.side_force)))
    assert (side > 0) == bool(options)  # the side-load terms were exercised where the set makes them


def test_one_point_has_the_array_paths_errors():
    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    with pytest.raises(ValueError, match="axis must be non-zero"):
        pm.rotor_wrench(prop, params, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], 800.0)
    with pytest.raises(ValueError, match="velocity must be finite"):
        pm.rotor_wrench(prop, params, [math.nan, 0.0, 0.0], [0.0, 0.0, 1.0], 800.0)
    with pytest.raises(ValueError, match="velocity must be numbers"):
        pm.rotor_wrench(prop, params, [True, 0.0, 0.0], [0.0, 0.0, 1.0], 800.0)
    with pytest.raises(ValueError, match="spin must be"):
        pm.rotor_wrench(prop, params, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 800.0, spin="left")
    with pytest.raises(ValueError, match="omega"):
        pm.rotor_wrench(prop, params, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], -5.0)
    # D = 0 in hover and axial flow, the thrust along the axis
    w = pm.rotor_wrench(prop, params, [0.0, 0.0, 3.0], [0.0, 0.0, 2.0], 800.0)
    assert w.force[0] == 0.0 and w.force[1] == 0.0 and w.force[2] == pytest.approx(float(w.loads.thrust))


def test_the_one_point_path_is_taken_and_the_odd_inputs_go_the_array_way(monkeypatch):
    """One velocity, axis, rate and spin never reach disk_frame; an integer beyond int64, a masked
    array, an array spin or derivatives do, with the array path's own errors."""
    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()

    def no(*args):
        raise AssertionError("the array path")

    with monkeypatch.context() as m:
        m.setattr(vector, "disk_frame", no)
        w = pm.rotor_wrench(prop, params, np.array([6.0, 0.0, 0.0]), (0, 0, 1), 800, "cw")  # exactly edgewise
        assert w.force[0] == pytest.approx(-float(w.loads.drag)) and w.loads.incidence == pytest.approx(math.pi / 2)
        pm.rotor_wrench(prop, params, [1, 2, 3], [0.0, 1.0, 1.0], np.float64(700.0), -1, derivatives=())
        pm.rotor_wrench(prop, params, [1, 2, 3], [0.0, 1.0, 1.0], 700.0, np.int64(-1))  # (a NumPy spin)
    for bad, match in (([10**20, 0, 0], "velocity must be numbers"), ([10**400, 0, 0], "velocity must be numbers")):
        with pytest.raises(ValueError, match=match):
            pm.rotor_wrench(prop, params, bad, [0.0, 0.0, 1.0], 800.0)
    with pytest.raises(ValueError, match="omega must be finite .* got a number beyond any float"):  # (since 2026-12-01)
        pm.rotor_wrench(prop, params, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 10**400)
    # a speed past the model's 500 m/s names velocity, this function's argument, on both paths (it said
    # "airspeed must be finite and in [0, 500] m/s", rotor_loads' argument: a physics audit, 2026-11-28)
    for velocity, derivatives in (([600.0, 0.0, 0.0], ()), ([[300.0, 0.0, 0.0], [0.0, 450.0, 300.0]], ()),
                                  ([600.0, 0.0, 0.0], True)):
        with pytest.raises(ValueError, match=r"^velocity: the rotor's airspeed \|velocity\| must be at most 500 "
                                             r"m/s \(the model's range\); got (600|540.833) m/s$"):
            pm.rotor_wrench(prop, params, velocity, [0.0, 0.0, 1.0], 800.0, derivatives=derivatives)
    # a None among the rates is no number (it read "got nan": the array's None cast to NaN)
    for omega in (None, [800.0, None], np.array([800.0, None])):
        with pytest.raises(ValueError, match="omega must be a number or an array of numbers, got .*None"):
            pm.rotor_loads(prop, params, omega, 2.0, 1.0)
    with pytest.raises(ValueError, match="axis must be non-zero"):  # before the spin, as the array path
        pm.rotor_wrench(prop, params, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0], 800.0, spin="left")
    with pytest.raises(ValueError, match="derivatives must be True, False or a sequence of names"):
        pm.rotor_wrench(prop, params, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 800.0, derivatives="")
    masked = pm.rotor_wrench(prop, params, np.ma.array([5.0, 0.0, 1.0]), [0.0, 0.0, 1.0], 800.0)
    np.testing.assert_allclose(masked.force, pm.rotor_wrench(prop, params, [5.0, 0.0, 1.0], [0.0, 0.0, 1.0],
                                                              800.0).force, rtol=1e-13)


@pytest.mark.parametrize("speed", [1e-320, 1e-291, 1e-160, 3e-12])
def test_one_point_speed_does_not_underflow(speed):
    """A tiny |V| scaled first, as the array path's disk_frame does (a physics audit, 2026-11-27:
    V = 1e-160 m/s gave a speed of 9.99994e-161, V = 1e-291 m/s a speed of 0 and the loads of
    still air, where the array path gives the parked rotor's 5.3e-8 N; a first fix, dividing by
    the largest component, gave NaN at 1e-320 under fastmath's reciprocal)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    rel = 1e-15 if speed > 1e-300 else 1e-3  # (a subnormal number carries few digits)
    for v in ([0.0, 0.0, speed], [speed, -speed, 0.0]):
        one = pm.rotor_wrench(prop, params, v, [0.0, 0.0, 1.0], 0.0)
        arr = pm.rotor_wrench(prop, params, np.array([v]), np.array([[0.0, 0.0, 1.0]]), np.array([0.0]))
        exact = float(np.linalg.norm(np.array(v) / speed)) * speed
        assert math.isclose(float(one.loads.airspeed), exact, rel_tol=rel, abs_tol=0.0)
        assert math.isclose(float(one.loads.airspeed), float(arr.loads.airspeed[0]), rel_tol=rel, abs_tol=0.0)
        np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-13, atol=1e-13 * abs(float(arr.force[0, 2])))



def test_a_velocity_along_the_axis_has_zero_incidence_to_the_last_digits():
    """beta = arccos(V . z / |V|) is computed as atan2(|V - (V . z) z|, V . z): the arccos of a cosine
    rounded to 1 - 1e-16 was 1.5e-8 rad, the scalar and array paths' roundings 1e-8 rad apart (a
    simulator-developer audit, 2026-11-27, with the C header's wrench)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    rng = np.random.default_rng(11)
    for _ in range(30):
        a = rng.normal(size=3) * rng.uniform(0.1, 5.0)
        c = rng.uniform(-4.0, 4.0)
        v = a * c
        one = pm.rotor_wrench(prop, params, v, a, 700.0)
        arr = pm.rotor_wrench(prop, params, v[None], a[None], np.array([700.0]))
        axial = 0.0 if c > 0 else math.pi
        for b in (float(one.loads.incidence), float(arr.loads.incidence[0])):
            assert abs(b - axial) < 1e-14


def test_rotor_loads_takes_numpy_scalars_by_the_one_point_path(monkeypatch):
    """A float64 taken from an array (a simulator's state vector) ran the array path, 1.45x a float's
    call, until 2026-11-28 (a review of the peer benchmark): the one-point check compared type(x) with
    np.floating and np.integer, which no scalar's type is. The same loads either way; a bool or a 0-d
    array still takes the array path, and its errors."""
    from propmap.core import _inputs

    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    ref = pm.rotor_loads(prop, params, 800.0, 6.0, 0.7)

    def no(*args, **kwargs):
        raise AssertionError("the array path")

    with monkeypatch.context() as m:
        m.setattr(_inputs, "_as_array", no)
        for args in ((np.float64(800.0), np.float64(6.0), np.float64(0.7)), (np.int64(800), np.int32(6), 0.7),
                     (800, np.float32(6.0), np.float64(0.7))):
            got = pm.rotor_loads(prop, params, *args)
            assert float(got.thrust) == pytest.approx(float(ref.thrust), rel=1e-12, abs=0.0)
        with pytest.raises(AssertionError, match="the array path"):
            pm.rotor_loads(prop, params, np.array(800.0), 6.0, 0.7)
    with pytest.raises(ValueError, match="omega"):
        pm.rotor_loads(prop, params, np.True_, 6.0, 0.7)
    with pytest.raises(ValueError, match="omega"):
        pm.rotor_loads(prop, params, np.float64(-5.0), 6.0, 0.7)


def test_the_array_paths_frame_and_vectors_are_the_one_point_arithmetic_to_the_bit():
    """disk_frame and wrench_vectors (the array paths of rotor_wrench, vehicle_wrench and the maps)
    loop over core/_frame.py's one-point functions, which the one-point paths call: the same speed,
    incidence, axis and vectors to the last bit, over speeds from 1e-200 to 1e140 m/s (a velocity from
    1e100 m/s up scaled by 2^-600 in the loop, exactly) and nearly axial ones of 1e-300 m/s, where NumPy's
    expressions of before rounded differently by an ulp or two."""
    from propmap.core._frame import point_frame, point_vectors
    from propmap.core.vector import disk_frame, wrench_vectors

    rng = np.random.default_rng(5)
    n = 3000
    V = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-200, 140, (n, 1))
    a = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-5, 5, (n, 1))
    # nearly axial and tiny: an in-plane part of 1e-40 to 1e-10 of speeds of 1e-300 to 1e-150 (the loop's speed
    # from unscaled squares was 0 there, and its e_ip a full in-plane direction: a review, 2026-11-29)
    V[:500] = a[:500] * 10.0 ** rng.uniform(-300, -150, (500, 1))
    V[:500] += rng.normal(size=(500, 3)) * np.abs(V[:500]).max(axis=1, keepdims=True) * 10.0 ** rng.uniform(-40, -10,
                                                                                                              (500, 1))
    loads = rng.normal(size=(6, n))
    spin = rng.choice([-1.0, 1.0], n)
    Vb, z, speed, beta = disk_frame(V, a)
    F, M = wrench_vectors(*loads[:4], Vb, z, spin, side_force=loads[4], pitching_moment=loads[5])
    for i in range(n):
        zx, zy, zz, s, axial, b = point_frame(*V[i], *a[i])
        assert (s, b, zx, zy, zz) == (speed[i], beta[i], *z[i]), i
        if s < 1e100:  # (the one-point path refuses larger velocities; the loop scales them)
            assert point_vectors(*V[i], zx, zy, zz, s, axial, *loads[:, i], spin[i]) == (*F[i], *M[i]), i
