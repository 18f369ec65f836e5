"""Rotor-rotor interference (core/interference.py): the vortex ring against Lamb's closed
forms and a direct Biot-Savart sum, the skewed wake against Coleman's disk mean and its
published limits, and the vehicle model with it (hover unchanged, downstream rotors lose
thrust, mirror symmetry, the file key and the fit name)."""

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.interference import (CHI_NODES, PSI_NODES, InterferenceTable, _wake_normal_velocity,
                                       interference_inflow, ring_normal_velocity, wake_ratio)
from propmap.vehicle import VehicleFileError, read_vehicle, vehicle_wrench

NEUROBEM = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"


def _biot_savart_ring(rho, z, n=20000):
    """u_z of a unit-circulation ring of radius 1 at (rho, 0, z) by summing n straight segments."""
    t = np.linspace(0.0, 2 * np.pi, n + 1)
    pts = np.stack([np.cos(t), np.sin(t), np.zeros_like(t)], axis=1)
    mid = 0.5 * (pts[1:] + pts[:-1])
    dl = np.diff(pts, axis=0)
    r = np.array([rho, 0.0, z]) - mid
    u = np.cross(dl, r) / (4 * np.pi * np.linalg.norm(r, axis=1)[:, None] ** 3)
    return u.sum(axis=0)[2]


def test_ring_velocity_closed_forms_and_biot_savart():
    """Centre 1/(2R); on the axis R^2 / (2 (R^2 + z^2)^(3/2)) (Lamb 1932, Sec. 161); off the
    axis, inside and outside the ring, against a direct Biot-Savart sum."""
    assert ring_normal_velocity(0.0, 0.0, 2.0) == pytest.approx(0.25, rel=1e-12)
    for z in (0.3, 1.0, 4.0):
        assert ring_normal_velocity(0.0, z) == pytest.approx(1 / (2 * (1 + z * z) ** 1.5), rel=1e-12)
    for rho, z in ((0.5, 0.2), (1.6, 0.0), (2.5, -1.0), (0.9, 0.5)):
        assert ring_normal_velocity(rho, z) == pytest.approx(_biot_savart_ring(rho, z), rel=1e-5, abs=1e-8)


@pytest.mark.parametrize("chi_deg", [0.0, 20.0, 45.0, 70.0])
def test_own_disk_mean_is_gamma_over_two_at_any_skew(chi_deg):
    """The disk's mean normal velocity of a skewed ring-vortex wake is gamma / 2 whatever its
    skew (Coleman, Feingold and Stempin 1945; the normalisation of f)."""
    assert wake_ratio(math.radians(chi_deg), (0.0, 0.0, 0.0)) == pytest.approx(1.0, abs=2e-3)


def test_wake_field_limits_and_signs():
    """Hover: no normal velocity outside the wake in the disk's plane; forward flight: downwash
    downstream growing with the skew, upwash upstream and beside; coaxial below: the far
    wake's 2 v_i approached."""
    for offset in ((2.4, 0.0, 0.0), (0.0, 3.1, 0.0), (-2.4, 0.0, 0.0)):
        assert abs(wake_ratio(0.0, offset)) < 2e-3
    down = [wake_ratio(math.radians(c), (2.41, 0.0, 0.0)) for c in (10, 20, 45, 75)]
    assert all(b > a > 0 for a, b in zip(down, down[1:]))
    assert down[1] == pytest.approx(0.049, abs=0.005)  # regression value (this model, 2026-11-23)
    assert wake_ratio(math.radians(45), (-2.41, 0.0, 0.0)) < 0
    assert wake_ratio(math.radians(45), (0.0, 3.09, 0.0)) < 0
    # inside the wake on its axis: (gamma / 2) (1 + z / sqrt(z^2 + R^2)), momentum theory's 2 v_i far below
    for depth in (2.0, 20.0):
        u = _wake_normal_velocity(0.0, np.zeros(1), np.zeros(1), np.array([-depth]))[0]
        assert u == pytest.approx(1 + depth / math.hypot(depth, 1.0), rel=1e-3)


def test_table_matches_direct_evaluation_and_is_mirror_symmetric():
    tab = InterferenceTable(2.41, 0.0, 1.0)
    chi, psi = math.radians(31.0), math.radians(20.0)
    direct = wake_ratio(chi, (2.41 * math.cos(psi), 2.41 * math.sin(psi), 0.0))
    # between the nodes (0.12% off here; 0.01 of the table's largest value, 13.1 at chi = 90 deg, was
    # 168% of this one until stop 104, so that any interpolation passed)
    assert tab(chi, psi) == pytest.approx(direct, rel=5e-3)
    assert tab(chi, -psi) == pytest.approx(tab(chi, psi), rel=1e-12)
    c, p = CHI_NODES[10], PSI_NODES[3]  # at a node: the direct value itself
    assert tab(c, p) == pytest.approx(wake_ratio(c, (2.41 * math.cos(p), 2.41 * math.sin(p), 0.0)), rel=1e-9)


@pytest.fixture(scope="module")
def neurobem():
    return read_vehicle(NEUROBEM)


@pytest.fixture(scope="module")
def generic():
    return pm.generic_params()


def test_hover_and_axial_flight_are_unchanged(neurobem, generic):
    """f = 0 at zero skew: in hover and axial climb the interference changes nothing (to the
    quadrature's 1e-4 of v_i)."""
    on = replace(neurobem, rotor_interference=1.0)
    v = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 3.0]])
    om = np.full((2, 4), 1100.0)
    a = vehicle_wrench(neurobem, generic, v, np.zeros(3), om)
    b = vehicle_wrench(on, generic, v, np.zeros(3), om)
    np.testing.assert_allclose(b.rotor_force, a.rotor_force, rtol=1e-4, atol=1e-9)


def test_forward_flight_downstream_rotors_lose_thrust(neurobem, generic):
    """Flying forward (+x), the rear rotors (1 and 3, in the front ones' wakes) make less
    thrust than without interference, the front ones a little more (upwash); left-right
    mirror symmetry holds; the loss grows with the factor."""
    om = np.full(4, 1150.0)
    v = np.array([6.0, 0.0, 0.0])
    T = {}
    for k in (0.0, 1.0, 2.0):
        w = vehicle_wrench(replace(neurobem, rotor_interference=k), generic, v, np.zeros(3), om)
        T[k] = np.array([ld.thrust[0] for ld in w.loads])
    rear, front = [0, 2], [1, 3]
    assert np.all(T[1.0][rear] < T[0.0][rear]) and np.all(T[2.0][rear] < T[1.0][rear])
    assert np.all(T[1.0][front] > T[0.0][front])
    assert T[1.0][0] == pytest.approx(T[1.0][2], rel=0.02)  # the spins differ, the wakes are mirror images
    loss = 1 - T[1.0][rear].mean() / T[0.0][rear].mean()
    assert 0.005 < loss < 0.2


def test_inflow_helper_shapes_and_zero_factor():
    pos = np.array([[0.1, 0.0, 0.0], [-0.1, 0.0, 0.0]])
    axes = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    V = np.zeros((3, 2, 3))
    V[:, :, 0] = 5.0  # the air goes to -x: rotor 2 is downstream of rotor 1
    v_i = np.full((3, 2), 8.0)
    assert not interference_inflow(pos, axes, np.full(2, 0.06), V, v_i, 0.0).any()
    out = interference_inflow(pos, axes, np.full(2, 0.06), V, v_i, 1.0)
    assert out.shape == (3, 2, 3)
    assert np.all(out[:, 1, 2] < 0) and np.all(out[:, 0, 2] > 0)  # downwash behind, upwash ahead
    assert not out[..., :2].any()
    tilted = axes.copy()
    tilted[1] = [math.sin(0.3), 0.0, math.cos(0.3)]  # 17 deg apart: not parallel, no interaction
    assert not interference_inflow(pos, tilted, np.full(2, 0.06), V, v_i, 1.0).any()


def test_vehicle_file_key_and_range(tmp_path, neurobem, generic):
    text = NEUROBEM.read_text()
    p = tmp_path / "v.toml"
    for name in ("neurobem_5.1x4.8_geom.txt", "neurobem_quadrotor.params.toml"):
        (tmp_path / name).write_text((NEUROBEM.parent / name).read_text())
    p.write_text("rotor_interference = 1.5\n" + text)
    assert read_vehicle(p).rotor_interference == 1.5
    p.write_text("rotor_interference = 4.0\n" + text)
    with pytest.raises(VehicleFileError, match="rotor_interference must be >= 0 and <= 3"):
        read_vehicle(p)
    with pytest.raises(ValueError, match=r"Vehicle.rotor_interference must be a finite number in \[0, 3\]"):
        replace(neurobem, rotor_interference=-1.0)  # (a Vehicle built in Python is checked too)


def test_params_file_carries_a_fitted_factor(tmp_path, generic):
    from propmap.core.body import BodyDrag
    from propmap.io.params_file import BodyTable, ParamsFileError, read_body, write_params

    p = tmp_path / "fitted.toml"
    write_params(p, generic, body=BodyTable(BodyDrag((0.02, 0.02, 0.0), 1.2), np.zeros(3), 0.7))
    assert read_body(p).rotor_interference == 0.7
    # (no [coverage]: the generic set's own is written by default, and the line below would land in it)
    write_params(p, generic, body=BodyTable(BodyDrag((0.02, 0.02, 0.0), 1.2), None), coverage={})
    assert read_body(p).rotor_interference is None
    p.write_text(p.read_text() + "rotor_interference = 5.0\n")
    with pytest.raises(ParamsFileError, match=r"\[body\] rotor_interference.*3"):
        read_body(p)


def test_the_interference_factor_is_a_flight_fit_parameter_bounded_0_to_3():
    """The names and bounds only; a fit that frees it and recovers it: tests/test_audit_split_helpers.py."""
    from propmap.identify.options import AIRFRAME_BOUNDS
    from propmap.identify.flight import AIRFRAME_NAMES

    assert "rotor_interference" in AIRFRAME_NAMES and AIRFRAME_BOUNDS["rotor_interference"] == (0.0, 3.0)


def test_descending_wake_is_the_mirror_image():
    """In descent (V . a + v_i < 0) the wake rises above the disk: a rotor at height h sees
    what a rotor at -h sees of the falling wake at the same skew (module docstring)."""
    R, v_i, h = 0.06, 4.0, 0.5
    pos = np.array([[0.0, 0.0, 0.0], [-2.4 * R, 0.0, h * R]])
    axes = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    V = np.zeros((2, 2, 3))
    V[:, :, 0] = 5.0  # the air goes to -x: rotor 2 downstream
    V[0, :, 2] = 2.0  # climbing: V . a + v_i = 6
    V[1, :, 2] = -10.0  # descending: V . a + v_i = -6, the same skew
    out = interference_inflow(pos, axes, np.full(2, R), V, np.full((2, 2), v_i), 1.0)
    chi = math.atan2(5.0, 6.0)
    f_climb, f_descent = -out[:, 1, 2] / v_i
    assert f_climb == pytest.approx(wake_ratio(chi, (2.4, 0.0, h)), abs=0.003)
    assert f_descent == pytest.approx(wake_ratio(chi, (2.4, 0.0, -h)), abs=0.003)
    assert f_descent - f_climb > 0.02


def test_inflow_pairs_each_wake_with_its_own_rotor_size_and_strength():
    """Rotors of unequal size (R 0.05 m in front at x = +0.1 m, 0.10 m behind at -0.1 m), 5 m/s
    forward, mean inflows 8 and 4 m/s: each rotor sees -k_I f v_i of the OTHER rotor's wake, f
    from that rotor's skew, with the offset and radius ratio in that rotor's radii. Rotors of one
    size and one inflow hid swapped sources, an inverted radius ratio and the offset in the wrong
    rotor's radii (a mutation audit, 2026-11-27: -0.1425, -0.0995 and -1.882 m/s there)."""
    out = interference_inflow(np.array([[0.1, 0.0, 0.0], [-0.1, 0.0, 0.0]]), np.array([[0.0, 0.0, 1.0]] * 2),
                              np.array([0.05, 0.10]), np.array([[[5.0, 0.0, 0.0], [5.0, 0.0, 0.0]]]),
                              np.array([[8.0, 4.0]]), 1.0)
    # the rear rotor in the front one's wake (offset 4 front radii, twice its radius): pushed down
    assert out[0, 1, 2] == pytest.approx(-8.0 * wake_ratio(math.atan2(5.0, 8.0), (4.0, 0.0, 0.0), 2.0), rel=0.02)
    assert out[0, 1, 2] == pytest.approx(-0.2850, rel=1e-3)  # (regression value, the interpolated table)
    # the front rotor ahead of the rear one's wake (offset 2 rear radii upstream, half its radius): an upwash
    assert out[0, 0, 2] == pytest.approx(-4.0 * wake_ratio(math.atan2(5.0, 4.0), (-2.0, 0.0, 0.0), 0.5), rel=0.02)
    assert out[0, 0, 2] > 0 and np.all(out[0, :, :2] == 0.0)


def test_a_failed_rotor_induces_nothing_on_the_others(monkeypatch, generic):
    """A rotor whose solve failed (on_failure="flag": NaN loads) puts no wake on the others: its
    NaN inflow is taken as 0, so the others' loads are those with its inflow set to 0, not NaN
    spread to every rotor (a mutation audit, 2026-11-27: the guard's removal survived the
    suite). The failure is injected into the first solve's loads, whose inflow the wakes carry."""
    import propmap.vehicle.model as model

    veh = replace(read_vehicle("quadrotor"), rotor_interference=1.0)
    v, w, om = np.array([[4.0, 0.0, -0.5]]), np.zeros((1, 3)), np.full((1, 4), 1000.0)
    real = model._rotor_wrenches

    def run(fill):
        first = []

        def injected(*args, **kw):
            F, M, loads, batches = real(*args, **kw)
            if fill is not None and not first:
                loads = list(loads)
                loads[0] = replace(loads[0], v_i_mean=np.full_like(loads[0].v_i_mean, fill))
            first.append(True)
            return F, M, loads, batches

        monkeypatch.setattr(model, "_rotor_wrenches", injected)
        return vehicle_wrench(veh, generic, v, w, om, on_failure="flag").rotor_force

    failed, silent, normal = run(np.nan), run(0.0), run(None)
    assert np.all(np.isfinite(failed)) and np.array_equal(failed, silent)
    assert np.abs(silent - normal).max() > 1e-4  # rotor 0's wake matters to the others here
