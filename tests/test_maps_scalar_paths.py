"""RotorMap's one-point paths against its array path, and core/_interp.py's edges: behaviours a
mutation audit of the maps' paths found unpinned (2026-11-28, a helper session: 79 mutants of
rotormap.py, core/_interp.py, core/_plain.py and core/vector.py, 31 missed by the suite of then,
3 of them equivalent: R32, "raise" handed the NaN policy, which sees only queries inside the
grid or in still air, which the kernel moves inside; I28, the still-air rule without its airspeed
axis starting at 0, where a speed below the axis is outside and clipped anyway; P01, np.bool_
dropped from plain_float's exclusion, which is neither np.integer nor np.floating). Each test
names the audit's mutants it kills (R: rotormap, I: _interp, P: _plain, V: vector)."""

import copy
import math
import pickle
import re

import numpy as np
import pytest

import propmap as pm
from propmap.maps import RotorMap, build_map

from .conftest import RPM


def _same(a, b):
    """Equal, NaN equal to NaN."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))


def _queries(rm, rng, n):
    """Points inside, on the edges and outside the grid on every axis (above, below, infinite)."""
    o0, o1, v0, v1, b0, b1 = rm._box
    for _ in range(n):
        yield (float(rng.choice([rng.uniform(o0, o1), rng.uniform(0, o0), rng.uniform(o1, 1.5 * o1), o0, o1, 0.0,
                                 math.inf])),
               float(rng.choice([rng.uniform(v0, v1), rng.uniform(v1, 1.5 * v1), v1, 0.0, math.inf])),
               float(rng.choice([rng.uniform(b0, b1), b0 - 0.2, b1 + 0.2, b1 + 1e-7, b0 - 1e-7])))


@pytest.mark.parametrize("interpolation", ["cubic", "linear"])
@pytest.mark.parametrize("which", ["rigid", "flapping"])
def test_scalar_loads_equal_the_array_path_in_and_out_of_the_grid(small_map, flapping_map, which, interpolation):
    """One point of floats (the scalar path, Python floats back) against the same point as arrays of one
    element: every field equal to the bit under every policy, inside, on the edges and outside the grid
    (kills R04: "nan" packed as "clip"; R12: "nan" outside left to the array path)."""
    ds = (small_map if which == "rigid" else flapping_map)[2]
    rm = RotorMap(ds, interpolation)
    rng = np.random.default_rng(11)
    seen = {"raise": 0, "clip": 0, "nan": 0}
    for om, V, b in _queries(rm, rng, 150):
        for policy in ("raise", "clip", "nan"):
            try:
                one = rm.loads(om, V, b, out_of_grid=policy)
            except ValueError as exc:
                with pytest.raises(ValueError, match=re.escape(str(exc))):
                    rm.loads(np.array([om]), np.array([V]), np.array([b]), out_of_grid=policy)
                continue
            arr = rm.loads(np.array([om]), np.array([V]), np.array([b]), out_of_grid=policy)
            assert type(one.thrust) is float and type(one.inside) is bool, (policy, om, V, b)  # the scalar path
            for field in one._fields:
                assert _same(getattr(one, field), np.squeeze(getattr(arr, field))), (field, policy, om, V, b)
            seen[policy] += not one.inside
    assert min(seen["clip"], seen["nan"]) > 50  # (outside points were asked)


@pytest.mark.parametrize("which", ["rigid", "flapping"])
def test_scalar_wrench_equals_the_array_path_in_and_out_of_the_grid(small_map, flapping_map, which):
    """One rotor (the compiled scalar path) against one-row arrays (core.vector's frame and vectors):
    the vectors to 1e-12 and the loads' fields, omega and power included, under every policy and
    both spins (kills R04; R23: omega above the grid under "clip" reported as the lowest rpm)."""
    ds = (small_map if which == "rigid" else flapping_map)[2]
    rm = RotorMap(ds)
    rng = np.random.default_rng(12)
    outside = 0
    for k, (om, V, b) in enumerate(_queries(rm, rng, 120)):
        V = 0.999 * V if V == rm._box[3] else V  # (|v| at the axis' end: test_..._airspeed_end below)
        axis = rng.normal(size=3)
        z = axis / np.linalg.norm(axis)
        e = np.cross(z, rng.normal(size=3))
        e /= np.linalg.norm(e)
        velocity = V * (math.cos(b) * z + math.sin(b) * e) if math.isfinite(V) else 1e3 * (z + e)
        spin = ("ccw", "cw", 1.0, -1)[k % 4]
        for policy in ("raise", "clip", "nan"):
            try:
                one = rm.wrench(list(velocity), tuple(axis), om, spin, out_of_grid=policy)
            except ValueError:
                with pytest.raises(ValueError):
                    rm.wrench(velocity[None], axis[None], np.array([om]), spin, out_of_grid=policy)
                continue
            arr = rm.wrench(velocity[None], axis[None], np.array([om]), spin, out_of_grid=policy)
            assert type(one.loads.thrust) is float  # the scalar path answered
            np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-12, atol=1e-14)
            np.testing.assert_allclose(one.torque, arr.torque[0], rtol=1e-12, atol=1e-14)
            for field in ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "omega",
                          "power"):
                np.testing.assert_allclose(getattr(one.loads, field), np.squeeze(getattr(arr.loads, field)),
                                           rtol=1e-12, atol=1e-14, err_msg=f"{field} {policy} {om} {V} {b}")
            assert one.loads.inside == arr.loads.inside[0] and one.loads.flagged == arr.loads.flagged[0]
            outside += not one.loads.inside
    assert outside > 50


def test_a_pickled_or_copied_map_keeps_its_array_path_and_side_table(flapping_map):
    """A copy's tables are views of its packed table again (__setstate__): the array path, the side
    loads and the C export of a pickled, copied or deep-copied map equal the original's (kills R09:
    __setstate__ without _views(); the scalar paths alone, which the suite checked, did not notice)."""
    from propmap.export_c import c_header_text

    rm = RotorMap(flapping_map[2])
    om, V, b = np.array([5200.0, 7700.0]) * RPM, np.array([3.0, 11.0]), np.array([0.4, 2.9])
    ref = rm.loads(om, V, b)
    assert np.abs(ref.side_force).max() > 0
    for other in (copy.copy(rm), copy.deepcopy(rm), pickle.loads(pickle.dumps(rm))):
        got = other.loads(om, V, b)
        for field in ref._fields:
            np.testing.assert_array_equal(getattr(got, field), getattr(ref, field))
        assert other._side_table is not None and np.shares_memory(other._table, other._tables)
        w = other.wrench(np.array([[1.0, 2.0, 3.0]] * 2), [0.0, 0.0, 1.0], om)
        np.testing.assert_array_equal(w.force, rm.wrench(np.array([[1.0, 2.0, 3.0]] * 2), [0.0, 0.0, 1.0], om).force)
    with pytest.warns(UserWarning):
        assert c_header_text(pickle.loads(pickle.dumps(rm)), "x.h") == c_header_text(rm, "x.h")


def test_a_rigid_maps_scalar_paths_give_zero_side_loads_whatever_the_buffer_holds(small_map):
    """A map without a side table writes no side row into its per-thread buffer: the scalar paths give
    Y = M_P = 0 exactly, not what the buffer held (kills R19 and R34, which read the unwritten row;
    np.empty is often zero, so the row is filled first)."""
    rm = RotorMap(small_map[2])
    for policy in ("raise", "clip", "nan"):
        rm._buffers.res[...] = 123.0  # (what another map or an earlier call could have left there)
        one = rm.loads(600.0, 5.0, 0.7, out_of_grid=policy)
        assert one.side_force == 0.0 and one.pitching_moment == 0.0 and type(one.side_force) is float
        rm._buffers.res[...] = 123.0
        w = rm.wrench([3.0, 1.0, 2.0], [0.0, 0.0, 1.0], 600.0, out_of_grid=policy)
        assert w.loads.side_force == 0.0 and w.loads.pitching_moment == 0.0
        ref = rm.wrench(np.array([[3.0, 1.0, 2.0]]), [0.0, 0.0, 1.0], np.array([600.0]), out_of_grid=policy)
        np.testing.assert_allclose(w.force, ref.force[0], rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("spin", [0, 0.0, 0.5, -2.0, np.float64(0.0)])
def test_the_scalar_wrench_refuses_a_spin_other_than_plus_or_minus_one(small_map, spin):
    """The spin is +1 or -1 (or its name) on both paths: 0 would silence the torque (kills R20)."""
    rm = RotorMap(small_map[2])
    with pytest.raises(ValueError, match="spin must be 'ccw', 'cw', \\+1 or -1"):
        rm.wrench((1.0, 0.0, 2.0), (0.0, 0.0, 1.0), 600.0, spin)


def test_each_scalar_wrench_returns_its_own_vectors(small_map):
    """The force and moment returned are rows of a new array each call (docs/simulators.md): a later call,
    in this thread, does not change an earlier answer (kills R26, a per-thread vectors buffer)."""
    rm = RotorMap(small_map[2])
    first = rm.wrench([3.0, 0.0, 2.0], [0.0, 0.0, 1.0], 600.0, "ccw")
    force, torque = first.force.copy(), first.torque.copy()
    second = rm.wrench([-6.0, 1.0, -1.0], [0.1, 0.0, 1.0], 800.0, "cw")
    assert not np.array_equal(second.force, force)
    np.testing.assert_array_equal(first.force, force)
    np.testing.assert_array_equal(first.torque, torque)
    assert not np.shares_memory(first.force, second.force)


@pytest.fixture(scope="module")
def descent_map():
    """apce_8x6, a map of descent only: incidence 90-180 deg (4 x 4 x 5)."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    return build_map(prop, params, np.geomspace(3000, 9000, 4) * RPM, np.linspace(0, 12, 4),
                     np.radians(np.linspace(90, 180, 5)), air=params.air, n_check=0)


def test_an_incidence_just_past_the_maps_own_axis_ends_is_on_them_in_both_paths(descent_map):
    """Within INCIDENCE_SNAP of the map's own incidence ends (here 90 deg, not 0 or pi) the query is on
    the end, for the array path as for the scalar one (kills R30: the array path snapped to [0, pi])."""
    rm = RotorMap(descent_map)
    lo, hi = float(rm.incidence[0]), float(rm.incidence[-1])
    assert lo == pytest.approx(math.pi / 2)
    for b, end in ((lo - 1e-7, lo), (hi + 1e-7, hi), (lo - 2.4e-7, lo)):
        ref = rm.loads(600.0, 5.0, end)
        one = rm.loads(600.0, 5.0, b)  # "raise": never outside
        arr = rm.loads(np.array([600.0, 600.0]), 5.0, np.array([b, end]))
        assert one.inside and bool(arr.inside.all())
        assert one.thrust == ref.thrust and np.all(arr.thrust == ref.thrust)
    with pytest.raises(ValueError, match="incidence"):  # and beyond it, outside
        rm.loads(np.array([600.0]), 5.0, np.array([lo - 3e-7]))


def test_a_velocity_whose_magnitude_is_the_airspeed_axis_end_is_inside_on_both_paths(flapping_map):
    """A hub speed equal to the grid's top airspeed (12 m/s) by construction: the scalar wrench
    (core._interp.point_frame, sqrt of the sum of squares) rounded |v| to 12.000000000000002 for about a
    quarter of directions and called it outside the grid (NaN vectors under "nan", inside = False under
    "clip"), the array path (core.vector.disk_frame, then scaled by the largest component) for others: the
    audit's one bug. Since then an airspeed within AIRSPEED_SNAP of an end is on it, on every path (and
    both paths share core/_frame.py's arithmetic)."""
    rm = RotorMap(flapping_map[2])
    top = float(rm.airspeed[-1])
    rng = np.random.default_rng(0)
    for _ in range(200):
        d = rng.normal(size=3)
        v = d / np.linalg.norm(d) * top
        arr = rm.wrench(v[None], [0.0, 0.0, 1.0], np.array([600.0]), out_of_grid="nan")
        one = rm.wrench(list(v), [0.0, 0.0, 1.0], 600.0, out_of_grid="nan")
        assert one.loads.inside and arr.loads.inside[0], list(v)
        np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-12, atol=1e-14)


def test_still_air_reaches_exactly_up_to_the_hover_speed_on_both_paths(descent_map):
    """On a map whose airspeed axis starts at 0, any incidence is inside up to 1e-6 m/s (HOVER_SPEED,
    docs/simulators.md) and not beyond, for the scalar and the array path, loads and wrench (kills R31:
    the array path's "raise" refusing 1e-6 itself; I03/I04: HOVER_SPEED moved)."""
    rm = RotorMap(descent_map)
    b = 0.5  # climb: outside the axis 90-180 deg
    still = rm.loads(600.0, 0.0, math.pi)
    for V in (0.0, 5e-7, 1e-6):
        one = rm.loads(600.0, V, b)
        arr = rm.loads(np.array([600.0]), np.array([V]), np.array([b]))
        assert type(one.thrust) is float and one.inside and bool(arr.inside[0])
        assert one.thrust == arr.thrust[0] and one.thrust == pytest.approx(still.thrust, rel=1e-6)
        w = rm.wrench([0.0, 0.0, V], [0.0, 0.0, 1.0], 600.0)  # axial climb at V: incidence 0
        assert w.loads.inside and w.loads.thrust == pytest.approx(still.thrust, rel=1e-6)
    for V in (1.5e-6, 1e-5):
        for call, args in ((rm.loads, (600.0, V, b)), (rm.loads, (np.array([600.0]), V, b)),
                           (rm.wrench, ([0.0, 0.0, V], [0.0, 0.0, 1.0], 600.0))):
            with pytest.raises(ValueError, match="incidence = .* is outside the map's grid"):
                call(*args)
        assert not rm.loads(600.0, V, b, out_of_grid="clip").inside
        assert np.isnan(rm.loads(np.array([600.0]), V, b, out_of_grid="nan").thrust[0])


@pytest.mark.parametrize("policy", ["raise", "clip", "nan"])
def test_a_velocity_component_of_exactly_velocity_max_is_refused(small_map, policy):
    """"A velocity component of VELOCITY_MAX (1e150 m/s) or more" is refused (RotorMap.wrench's
    docstring, as the C header): 1e150 itself on both paths, and just below it is no error under "clip"
    and "nan" (kills R33: ``>`` for ``>=``; I13: the kernel taking 1e150)."""
    from propmap.rotormap import VELOCITY_MAX

    rm = RotorMap(small_map[2])
    for v in ([VELOCITY_MAX, 0.0, 0.0], [0.0, -VELOCITY_MAX, 1.0]):
        for args in ((v, [0.0, 0.0, 1.0], 600.0), (np.array([v]), [0.0, 0.0, 1.0], np.array([600.0]))):
            with pytest.raises(ValueError, match=r"velocity: a component of 1e\+150 m/s"):
                rm.wrench(*args, out_of_grid=policy)
    if policy != "raise":
        below = rm.wrench([0.0, 0.0, np.nextafter(VELOCITY_MAX, 0.0)], [0.0, 0.0, 1.0], 600.0, out_of_grid=policy)
        assert not below.loads.inside and below.loads.flagged


@pytest.mark.parametrize("interpolation", ["cubic", "linear"])
def test_clip_takes_the_edge_and_nan_gives_nan_on_every_axis_and_side(flapping_map, interpolation):
    """Above and below each axis: "clip" gives the nearest boundary point's loads exactly (below the lowest
    rpm scaled by (Omega / Omega_min)^2), "nan" NaN in every load, the side loads included; both
    inside = False and flagged = True (docs/simulators.md's table), scalar and array (kills I05: "nan"
    unflagged, I06: the last load left finite, I33: the incidence unclamped above its axis)."""
    rm = RotorMap(flapping_map[2], interpolation)
    o0, o1, v0, v1, b0, b1 = rm._box
    mid = (0.5 * (o0 + o1), 0.5 * (v0 + v1), 0.5 * (b0 + b1))
    loads = ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment")
    for axis, (below, above, lo, hi) in enumerate(((0.5 * o0, 1.5 * o1, o0, o1), (None, 1.5 * v1, v0, v1),
                                                   (b0 - 0.3, b1 + 0.3, b0, b1))):
        for q, edge in ((below, lo), (above, hi)):
            if q is None:  # (a negative airspeed is refused, not clipped)
                continue
            point, at = list(mid), list(mid)
            point[axis], at[axis] = q, edge
            ref = rm.loads(*at)
            scale = (q / o0) ** 2 if axis == 0 and q < o0 else 1.0
            for args in (point, [np.array([x]) for x in point]):
                clip = rm.loads(*args, out_of_grid="clip")
                nan = rm.loads(*args, out_of_grid="nan")
                for k in loads:
                    assert float(np.squeeze(getattr(clip, k))) == pytest.approx(scale * getattr(ref, k), rel=1e-12,
                                                                               abs=1e-300), (k, axis, q)
                    assert math.isnan(float(np.squeeze(getattr(nan, k)))), (k, axis, q)
                for got in (clip, nan):
                    assert not bool(np.squeeze(got.inside)) and bool(np.squeeze(got.flagged))
    with pytest.raises(ValueError):  # (and "raise" refuses them)
        rm.loads(mid[0], mid[1], b1 + 0.3)


def test_the_cubic_on_an_axis_of_three_nodes_reproduces_quadratics():
    """An axis of 3 nodes is cubic (one-sided end slopes), not linear: only 2 nodes are (kills I02)."""
    from propmap.core._interp import _cubic_weights

    ax = np.array([0.0, 1.0, 3.0])
    for x in (0.3, 0.8, 1.5, 2.7):
        i, *w = _cubic_weights(ax, x)
        nodes = ax[np.clip(np.arange(i - 1, i + 3), 0, ax.size - 1)]
        assert float(np.dot(w, nodes**2)) == pytest.approx(x * x, rel=1e-13), x


def test_the_callers_query_arrays_are_never_written(small_map):
    """An incidence within INCIDENCE_SNAP past an end is read as the end, in a new array: the caller's
    array keeps its value (core._interp.snap_incidence's docstring; kills I23, a snap in place)."""
    rm = RotorMap(small_map[2])
    b = np.array([math.pi + 1e-7, -1e-7, 1.0])
    om, V = np.full(3, 600.0), np.full(3, 5.0)
    keep = b.copy(), om.copy(), V.copy()
    got = rm.loads(om, V, b)
    assert got.inside.all()
    for a, k in zip((b, om, V), keep):
        np.testing.assert_array_equal(a, k)
    from propmap.core._interp import snap_incidence

    c = np.array([math.pi + 1e-7])
    assert snap_incidence(c)[0] == math.pi and c[0] == math.pi + 1e-7


def test_a_nearly_axial_velocity_keeps_its_in_plane_direction_on_the_scalar_path(small_map):
    """In-plane speed down to 1e-12 of the speed still gives e_ip (core.vector.wrench_vectors' rule): the
    drag's direction, in the scalar path as in the array path (kills I17, a 1e-6 threshold)."""
    rm = RotorMap(small_map[2])
    for ratio in (1e-7, 1e-9):
        v = [ratio * 5.0, 0.0, 5.0]
        one = rm.wrench(v, [0.0, 0.0, 1.0], 600.0)
        arr = rm.wrench(np.array([v]), [0.0, 0.0, 1.0], np.array([600.0]))
        assert one.loads.drag > 0 and one.force[0] < 0  # the drag, against the in-plane velocity
        np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-12, atol=0.0)


def test_still_air_on_a_map_of_climb_only_takes_any_incidence():
    """A map whose incidence axis ends at 90 deg: at rest the incidence, 0-180 deg, is taken onto its axis
    (the still-air rule at the top end too; kills I31, which clamped only from below)."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.geomspace(3000, 9000, 4) * RPM, np.linspace(0, 12, 4),
                   np.radians(np.linspace(0, 90, 5)), air=params.air, n_check=0)
    rm = RotorMap(ds)
    ref = rm.loads(600.0, 0.0, 0.0)
    for b in (2.5, math.pi):
        for policy in ("raise", "clip", "nan"):
            one = rm.loads(600.0, 0.0, b, out_of_grid=policy)
            arr = rm.loads(np.array([600.0]), 0.0, np.array([b]), out_of_grid=policy)
            assert one.inside and bool(arr.inside[0]) and one.thrust == ref.thrust == arr.thrust[0]
    w = rm.wrench([0.0, 0.0, -1e-7], [0.0, 0.0, 1.0], 600.0, out_of_grid="nan")  # descending at 1e-7 m/s
    assert w.loads.inside and w.force[2] == pytest.approx(ref.thrust, rel=1e-6)


@pytest.mark.parametrize("policy", ["clip", "nan"])
def test_in_plane_velocities_on_a_tilted_axis_are_on_the_incidence_axis_end(descent_map, policy):
    """A velocity perpendicular to a tilted axis: the scalar wrench's incidence lands an ulp either side of
    90 deg, the end of a map of descent; within INCIDENCE_SNAP it is on it, inside and finite under "clip"
    and "nan" as in the array path (kills I14: wrench_point without snap_edge)."""
    rm = RotorMap(descent_map)
    rng = np.random.default_rng(5)
    for _ in range(300):
        axis = rng.normal(size=3)
        v = np.cross(axis, rng.normal(size=3))
        v *= rng.uniform(0.5, 11.0) / np.linalg.norm(v)
        one = rm.wrench(v, axis, 600.0, out_of_grid=policy)
        arr = rm.wrench(v[None], axis, np.array([600.0]), out_of_grid=policy)
        assert one.loads.inside and bool(arr.loads.inside[0]) and np.isfinite(one.force).all(), (list(v), list(axis))
        np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-12, atol=1e-14)


def test_a_rotor_at_rest_has_incidence_zero_whatever_the_signs_of_its_zeros():
    """V = 0 has incidence 0 (core.vector.disk_frame), also where V . z is -0.0 (a velocity of negative
    zeros, or an axis of negative components), where atan2(0, -0.0) is pi: on a map whose airspeed axis
    starts above 0 "clip" then takes the lowest airspeed at incidence 0, in both paths (kills I19)."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.geomspace(3000, 9000, 3) * RPM, [2.0, 6.0, 10.0],
                   np.radians(np.linspace(0, 180, 5)), air=params.air, n_check=0)
    rm = RotorMap(ds)
    ref = rm.loads(600.0, 2.0, 0.0)
    for v in ((0.0, 0.0, 0.0), (-0.0, -0.0, -0.0)):
        for axis in ((0.0, 0.0, 1.0), (1.0, 1.0, 1.0), (-1.0, -1.0, -1.0), (-0.3, -0.2, -0.9)):
            one = rm.wrench(v, axis, 600.0, out_of_grid="clip")
            arr = rm.wrench(np.array([v]), axis, np.array([600.0]), out_of_grid="clip")
            assert one.loads.thrust == ref.thrust and arr.loads.thrust[0] == ref.thrust, (v, axis)
            np.testing.assert_allclose(one.force, arr.force[0], rtol=1e-13, atol=0.0)


def test_plain_numbers_and_vectors_are_the_documented_ones():
    """core._plain's rules (its docstrings): a bool, an integer beyond a float's range, an array of bools, a
    subclass, a sequence of 2 or 4 are no plain number or 3-vector; an integer beyond int64 only under
    int64=True. And RotorMap.wrench refuses a 4-vector as the array path does (kills P03, P04, P05, P06)."""
    from propmap.core._plain import plain_float, plain_vector

    assert plain_float(3) == 3.0 and type(plain_float(np.float32(0.5))) is float and plain_float(np.int64(7)) == 7.0
    for x in (True, np.True_, 10**400, -(10**400), "1.0", None, np.array(1.0), 1j):
        assert plain_float(x) is None, x
    assert plain_float(2**63) == 2.0**63 and plain_float(2**63, int64=True) is None
    assert plain_float(2**63 - 1, int64=True) == 2.0**63
    v = np.array([1.0, 2.0, 3.0])
    assert plain_vector(v, 3) is v and plain_vector((1, 2, np.float32(3)), 3).tolist() == [1.0, 2.0, 3.0]
    assert plain_vector(np.array([1, 2, 3], dtype=np.int8), 3).dtype == np.float64
    for bad in (np.array([True, False, True]), [1.0, 2.0], [1.0, 2.0, 3.0, 4.0], (1.0, True, 2.0),
                np.ma.masked_array([1.0, 2.0, 3.0]), np.array([[1.0, 2.0, 3.0]]), np.array(["1", "2", "3"]),
                [1.0, 2.0, 10**400], [True, False, True], (True, 1, 2)):
        assert plain_vector(bad, 3) is None, bad
    assert plain_vector([1.0, 2.0, 3.0], 3).dtype == np.float64 and plain_vector((0.5, 1, 2.0), 3).tolist() == [
        0.5, 1.0, 2.0]  # (Python floats only go straight to an array; anything else number by number)


def test_the_maps_one_point_calls_refuse_what_the_array_path_refuses(small_map):
    """A 4-vector, a vector of bools, an integer beyond a float's range go the array way and its errors
    (never a silent first three components, a 1 m/s from True, or an infinite rate)."""
    rm = RotorMap(small_map[2])
    with pytest.raises(ValueError, match="last axis of length 3"):
        rm.wrench([1.0, 0.0, 2.0, 5.0], [0.0, 0.0, 1.0], 600.0)
    with pytest.raises(ValueError, match="velocity must be numbers"):
        rm.wrench(np.array([True, False, True]), [0.0, 0.0, 1.0], 600.0)
    with pytest.raises(ValueError, match="omega must be a number or an array of numbers"):
        rm.loads(10**400, 5.0, 0.5, out_of_grid="clip")


def test_rotor_wrench_takes_a_speed_of_exactly_its_airspeed_limit():
    """|velocity| "at most 500 m/s" (rotor_wrench's docstring, the model's range): 500 itself is taken by
    the one-point and the array path, a step beyond is refused naming velocity (kills V08, ``>=``)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    for v in ([0.0, 0.0, 500.0], [300.0, 0.0, -400.0]):
        with pytest.warns(UserWarning, match="Mach"):  # (a tip at Mach 1.5: the range's end, not physics)
            one = pm.rotor_wrench(prop, params, v, [0.0, 0.0, 1.0], 800.0, on_failure="flag")
        with pytest.warns(UserWarning, match="Mach"):
            arr = pm.rotor_wrench(prop, params, np.array([v]), [0.0, 0.0, 1.0], np.array([800.0]), on_failure="flag")
        assert float(one.loads.airspeed) == 500.0 and np.isfinite(arr.force).all()
    with pytest.raises(ValueError, match="velocity: the rotor's airspeed .* at most 500"):
        pm.rotor_wrench(prop, params, [0.0, 0.0, np.nextafter(500.0, 600.0)], [0.0, 0.0, 1.0], 800.0)


def test_a_map_pickled_before_its_tables_were_packed_is_built_again(flapping_map):
    """A RotorMap pickled before 2026-11-28 (separate tables, no packed grid) loads by being built
    again from its dataset (it failed with AttributeError '_tables'; a review)."""
    rm = RotorMap(flapping_map[2])
    state = rm.__getstate__()
    for k in ("_tables", "_grid"):
        del state[k]
    state["_table"], state["_side_table"] = rm._table.copy(), rm._side_table.copy()  # (the old layout's fields)
    old = RotorMap.__new__(RotorMap)
    old.__setstate__(state)
    assert old.side_loads and np.shares_memory(old._table, old._tables)
    assert tuple(old.loads(600.0, 5.0, 1.0)) == tuple(rm.loads(600.0, 5.0, 1.0))


def test_read_only_and_strided_queries_compile_nothing_more(small_map):
    """A read-only or strided float64 query is another type to numba: RotorMap.loads' array path (a
    read-only omega, which the query checks pass on unchanged), its one-point wrench and a vehicle step
    compiled their kernels once more for it (0.5-1.6 s in a simulator's step; a review, 2026-11-28).
    They now get contiguous, writeable copies: no new compiled signature, the same answers, the caller's
    arrays untouched."""
    from pathlib import Path

    import numba

    from propmap.core import _interp
    from propmap.core._plain import plain_vector
    from propmap.vehicle import VehicleMap, read_vehicle

    def signatures():
        return {k: len(f.signatures) for k, f in vars(_interp).items()
                if isinstance(f, numba.core.registry.CPUDispatcher)}

    def frozen(a):
        a = np.array(a, dtype=float)
        a.flags.writeable = False
        return a

    def strided(a):
        s = np.zeros((len(a), 2))
        s[:, 0] = a
        return s[:, 0]

    def unaligned(a):  # (a packed binary record's: numba types it as aligned, so only `p is not a` below sees it)
        u = np.zeros(8 * len(a) + 1, dtype=np.uint8)[1:].view(np.float64)
        u[:] = a
        assert not u.flags.aligned and u.flags.c_contiguous and u.flags.writeable
        return u

    rm = RotorMap(small_map[2])
    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")  # four apce_8x6
    vm = VehicleMap(veh, rm)
    om, V, b = np.full(5, 700.0), np.linspace(0.0, 10.0, 5), np.full(5, 0.5)
    vel, axis, w, rotors = np.array([3.0, -1.0, 0.5]), np.array([0.0, 0.0, 1.0]), np.array([0.1, 0.2, 0.0]), \
        np.array([700.0, 710.0, 720.0, 730.0])
    ref = (rm.loads(om, V, b), rm.wrench(vel, axis, 700.0), vm.wrench(vel, w, rotors))  # (compiled, or from the cache)
    before = signatures()
    for make in (frozen, strided, unaligned):
        given = [make(x) for x in (om, vel, axis, vel, w, rotors)]
        kept = [x.copy() for x in given]
        got = (rm.loads(given[0], V, b), rm.wrench(given[1], given[2], 700.0), vm.wrench(*given[3:]))
        assert all(np.array_equal(x, k) for x, k in zip(given, kept))
        np.testing.assert_array_equal(got[0].thrust, ref[0].thrust)
        np.testing.assert_array_equal(got[1].force, ref[1].force)
        np.testing.assert_array_equal(got[2].force, ref[2].force)
        np.testing.assert_array_equal(got[2].moment, ref[2].moment)
    assert signatures() == before
    x = frozen(vel)
    for a in (x, strided(vel), unaligned(vel)):
        p = plain_vector(a, 3)
        assert p is not a and p.flags.carray and p.tolist() == vel.tolist()


def test_broadcast_queries_warn_of_nothing(small_map):
    """A query of one array and plain numbers (broadcast against each other) gives no warning: NumPy's
    writeable broadcast views (np.broadcast_arrays) warn of a future change (FutureWarning) when their
    flags are read, which the contiguity check of the array path and numba do (a review, 2026-11-29: a
    new warning from RotorMap.loads(np.array([700.0]), 5.0, 0.5)); the same for trim_omega."""
    import warnings

    prop, params, ds = small_map
    rm = RotorMap(ds)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        one = rm.loads(np.array([700.0]), 5.0, 0.5)
        rm.loads(np.array([[700.0], [800.0]]), np.array([0.0, 5.0, 10.0]), 0.5)
        om = pm.trim_omega(prop, params, np.array([2.0, 3.0]), 5.0, 0.5).omega
    assert one.thrust.shape == (1,) and one.thrust[0] == rm.loads(700.0, 5.0, 0.5).thrust
    assert om.shape == (2,) and om[0] < om[1]


def test_the_scalar_path_returns_python_numbers_and_a_zero_d_query_arrays(small_map):
    """What MapLoads' docstring says (a docstring-contract audit, 2026-11-30, found it promising arrays
    for every query): one point of floats gets Python floats and bools, a 0-d array query 0-d arrays."""
    rm = RotorMap(small_map[2])
    o0, o1, v0, v1, b0, b1 = rm._box
    q = (0.5 * (o0 + o1), 0.5 * (v0 + v1), 0.5 * (b0 + b1))
    one = rm.loads(*q)
    assert type(one.thrust) is float and type(one.torque) is float and type(one.inside) is bool
    arr = rm.loads(*(np.array(x) for x in q))
    assert isinstance(arr.thrust, np.ndarray) and arr.thrust.shape == () and arr.inside.shape == ()
    assert float(arr.thrust) == one.thrust and bool(arr.inside) is one.inside
