"""The vehicle model: its wrench against rotor_wrench summed by hand, hover equilibrium,
gyroscopic and spin-up moments, airframe drag, and the vehicle file's new keys."""

import math
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag, body_drag_force
from propmap.vehicle import VehicleFileError, hover_omega, read_vehicle, vehicle_wrench
from propmap.vehicle import Rotor, Vehicle

DATA = Path(pm.__file__).parent / "data"
NEUROBEM = DATA / "examples" / "neurobem_quadrotor.toml"


@pytest.fixture(scope="module")
def quad():
    return read_vehicle(DATA / "examples" / "quadrotor.toml")


@pytest.fixture(scope="module")
def generic():
    return pm.generic_params()


@pytest.mark.parametrize("w", [[0.0, 0.0, 0.0], [0.5, -1.0, 2.0]])
def test_wrench_is_the_rotor_wrenches_summed_by_hand(quad, generic, w):
    """F = sum F_i, M = sum r_i x F_i + M_i, with hub velocities v + w x r_i; both spins."""
    v = np.array([[4.0, -1.0, -0.5], [0.0, 0.0, 2.0]])
    om = np.array([[800.0, 820.0, 780.0, 810.0], [700.0, 700.0, 700.0, 700.0]])
    res = vehicle_wrench(quad, generic, v, w, om)
    F = np.zeros((2, 3))
    M = np.zeros((2, 3))
    for i, r in enumerate(quad.rotors):
        V = v + np.cross(w, r.position)
        rw = pm.rotor_wrench(r.propeller, generic, V, r.axis, om[:, i], r.spin)
        F += rw.force
        M += np.cross(r.position, rw.force) + rw.torque
    np.testing.assert_allclose(res.force, F, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(res.moment, M, rtol=1e-12, atol=1e-12)
    assert res.rotor_force.shape == (2, 4, 3) and res.loads[0].thrust.shape == (2,)


def test_spin_senses_mirror_the_yaw_moment(quad, generic):
    """Reversing every spin leaves the force and negates the shaft-torque (yaw) moment in hover."""
    om = np.full(4, 800.0)
    a = vehicle_wrench(quad, generic, [0, 0, 0], [0, 0, 0], om * [1, 1.05, 1, 1.05])
    flipped = Vehicle(mass=quad.mass, rotors=tuple(Rotor(r.position, r.axis, -r.spin, r.propeller)
                                                   for r in quad.rotors))
    b = vehicle_wrench(flipped, generic, [0, 0, 0], [0, 0, 0], om * [1, 1.05, 1, 1.05])
    np.testing.assert_allclose(a.force, b.force, rtol=1e-12)
    np.testing.assert_allclose(a.moment[:, 2], -b.moment[:, 2], rtol=1e-12)
    assert abs(a.moment[0, 2]) > 1e-4


def test_hover_equilibrium_of_the_neurobem_vehicle(generic):
    """Equal rotor speeds at rest: a pure vertical force, no moment (the layout is symmetric
    and the spins cancel); the speed that carries the weight exists and hover_omega finds it."""
    veh = read_vehicle(NEUROBEM)
    params = generic.replace(collective=math.radians(8))
    lo = hover_omega(veh, params)
    res = vehicle_wrench(veh, params, [0, 0, 0], [0, 0, 0], [lo] * 4)
    assert res.force[0, 2] == pytest.approx(veh.weight, rel=1e-9)
    np.testing.assert_allclose(res.force[0, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(res.moment[0], 0.0, atol=1e-12)
    assert 800 < lo < 2000  # the logs hover near 1100-1250 rad/s
    # rotors that cannot lift it: refused, naming why
    sideways = Vehicle(mass=1.0, rotors=tuple(Rotor(r.position, np.array([1.0, 0.0, 0.0]), r.spin, r.propeller)
                                              for r in veh.rotors))
    with pytest.raises(ValueError, match="no rotor's axis has an upward component"):
        hover_omega(sideways, params)
    # (the search doubles up to the solver's limit itself: it stopped at 5.12e4 rad/s until 2026-12-01)
    with pytest.raises(ValueError, match=r"needs more than 1e\+05 rad/s of its rotors \(the solver.s limit\)"):
        hover_omega(Vehicle(mass=1e6, rotors=veh.rotors), params)


def test_hover_carries_the_airframe_drag_in_the_slipstream(generic):
    """An airframe in the rotors' wash (wash_factor > 0) is pushed down in hover: hover_omega
    left that out (1282 rad/s, where vehicle_wrench's force is 4.4% short of the weight;
    export-sim --vehicle pinned its hover there)."""
    import dataclasses

    veh = read_vehicle(NEUROBEM)
    bare = hover_omega(veh, generic)
    washed = dataclasses.replace(veh, body_drag=BodyDrag((0.004, 0.004, 0.008), wash_factor=1.0))
    om = hover_omega(washed, generic)
    res = vehicle_wrench(washed, generic, [0, 0, 0], [0, 0, 0], [om] * 4)
    assert res.force[0, 2] == pytest.approx(washed.weight, rel=1e-9)
    assert res.body_force[0, 2] < -0.1  # (the drag of the 8e-3 m^2 area in the wash: -0.33 N at the bare hover)
    assert om > 1.01 * bare
    # without the wash the airframe has no force at rest: the same hover as without an airframe
    dry = dataclasses.replace(veh, body_drag=BodyDrag((0.004, 0.004, 0.008), wash_factor=0.0))
    assert hover_omega(dry, generic) == pytest.approx(bare, rel=1e-12)


def test_rotors_of_one_propeller_are_solved_together(generic, monkeypatch):
    """A vehicle file reads each rotor's propeller on its own: grouped by identity, the NeuroBEM
    quadrotor's four rotors took four solves a sample (1.6 ms against 1.1 ms in one batch)."""
    import dataclasses

    import propmap.vehicle.model as vm

    veh = read_vehicle(NEUROBEM)
    assert all(r.propeller is veh.rotors[0].propeller for r in veh.rotors)  # (the file's reader shares it now)
    # rotors built apart (the file's reader gave each its own object before): grouped by value
    veh = dataclasses.replace(veh, rotors=tuple(dataclasses.replace(r, propeller=dataclasses.replace(r.propeller))
                                                for r in veh.rotors))
    assert veh.rotors[0].propeller is not veh.rotors[1].propeller
    calls = []
    real = vm.rotor_loads
    monkeypatch.setattr(vm, "rotor_loads", lambda *a, **k: calls.append(np.shape(a[2])) or real(*a, **k))
    res = vehicle_wrench(veh, generic, [3.0, 0.5, -0.2], [0.1, 0.0, 0.2], [1200.0, 1210.0, 1190.0, 1205.0])
    assert calls == [(1, 4)]
    # another set on one rotor, or another blade count: solved apart, the same wrench as rotor by rotor
    other = generic.replace(cl_alpha=generic.cl_alpha + 0.3)
    p3 = dataclasses.replace(veh.rotors[1].propeller, n_blades=2)
    rotors = (veh.rotors[0], dataclasses.replace(veh.rotors[1], propeller=p3),
              dataclasses.replace(veh.rotors[2], params=other), veh.rotors[3])
    mixed = dataclasses.replace(veh, rotors=rotors)
    calls.clear()
    res = vehicle_wrench(mixed, generic, [3.0, 0.5, -0.2], [0.1, 0.0, 0.2], [1200.0, 1210.0, 1190.0, 1205.0])
    assert sorted(calls) == [(1, 1), (1, 1), (1, 2)]
    for i, r in enumerate(mixed.rotors):
        V = np.array([3.0, 0.5, -0.2]) + np.cross([0.1, 0.0, 0.2], r.position)
        rw = pm.rotor_wrench(r.propeller, r.params or generic, V, r.axis, [1200.0, 1210.0, 1190.0, 1205.0][i], r.spin)
        np.testing.assert_allclose(res.rotor_force[0, i], rw.force, rtol=1e-12, atol=1e-14)


def test_derivatives_with_a_stopped_rotor_name_it(generic):
    """A motor-failure linearisation: the refusal named no rotor (rotor_loads' message)."""
    veh = read_vehicle(NEUROBEM)
    with pytest.raises(ValueError, match=r"every rotor_omega >= 0.1 rad/s .* got 0 for rotor 3 \(sample 2\)"):
        vehicle_wrench(veh, generic, [0, 0, 0], [0, 0, 0], [[1200.0] * 4, [1200.0, 1200.0, 0.0, 1200.0]],
                       derivatives=True)
    vehicle_wrench(veh, generic, [0, 0, 0], [0, 0, 0], [1200.0, 1200.0, 0.0, 1200.0])  # (without derivatives: fine)


def test_numpy_booleans_ask_for_the_derivatives_as_python_ones(generic):
    """np.True_ was refused as 'not a sequence of names' (a derivative audit, 2026-11-27)."""
    veh = read_vehicle(NEUROBEM)
    args = (veh, generic, [3.0, 0.0, 0.0], [0, 0, 0], [1200.0] * 4)
    np.testing.assert_array_equal(vehicle_wrench(*args, derivatives=np.True_).force_domega,
                                  vehicle_wrench(*args, derivatives=True).force_domega)
    assert vehicle_wrench(*args, derivatives=np.False_).force_domega is None


def test_gyroscopic_and_spin_up_moments():
    """A single rotor with inertia J: M = ... - w x h - s J dOmega/dt a, h = s J Omega a."""
    prop = pm.load_propeller("apce_8x6")
    J = 2e-5
    rot = Rotor(np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]), 1.0, prop, inertia=J)
    veh = Vehicle(mass=1.0, rotors=(rot,))
    p = pm.generic_params()
    w = np.array([1.0, 0.0, 0.0])
    base = vehicle_wrench(Vehicle(mass=1.0, rotors=(Rotor(rot.position, rot.axis, 1.0, prop),)), p, [0, 0, 0], w,
                          [800.0])
    res = vehicle_wrench(veh, p, [0, 0, 0], w, [800.0], rotor_acceleration=[100.0])
    h = J * 800.0 * np.array([0.0, 0.0, 1.0])
    expected = base.moment[0] - np.cross(w, h) - J * 100.0 * np.array([0.0, 0.0, 1.0])
    np.testing.assert_allclose(res.moment[0], expected, rtol=1e-12)
    # the gyroscopic moment of a spinning rotor rolled about x acts about y
    assert abs(res.moment[0, 1] - base.moment[0, 1]) == pytest.approx(J * 800.0, rel=1e-12)


def test_body_drag_download_and_linear_in_plane_drag():
    """In hover the wash gives a download (rho/2) C_D A_z (kappa v)^2; at low speed V the
    in-plane drag is (rho/2) C_D A_x kappa v V, linear in V."""
    b = BodyDrag(drag_area=(0.01, 0.01, 0.02), wash_factor=2.0)
    wash = np.array([0.0, 0.0, 8.0])
    F = body_drag_force(b, [0.0, 0.0, 0.0], wash, 1.2)
    assert F[2] == pytest.approx(-0.5 * 1.2 * 0.02 * 16.0**2)
    small = [body_drag_force(b, [V, 0.0, 0.0], wash, 1.2)[0] for V in (0.1, 0.2)]
    assert small[1] / small[0] == pytest.approx(2.0, rel=1e-3)
    assert small[0] == pytest.approx(-0.5 * 1.2 * 0.01 * 16.0 * 0.1, rel=1e-3)
    with pytest.raises(ValueError, match="wash_factor"):
        BodyDrag(drag_area=(0, 0, 0), wash_factor=-1)
    with pytest.raises(ValueError, match="drag_area"):
        BodyDrag(drag_area=(0, 0))


def test_vehicle_body_drag_enters_the_total_force(quad, generic):
    b = BodyDrag(drag_area=(0.01, 0.01, 0.01), wash_factor=0.0)
    a = vehicle_wrench(quad, generic, [5, 0, 0], [0, 0, 0], [800] * 4)
    c = vehicle_wrench(quad, generic, [5, 0, 0], [0, 0, 0], [800] * 4, body_drag=b)
    np.testing.assert_allclose(c.force - a.force, c.body_force)
    assert c.body_force[0, 0] == pytest.approx(-0.5 * 1.225 * 0.01 * 25)
    np.testing.assert_allclose(c.moment, a.moment)  # drag acts at the centre of mass


def test_wrench_inputs_are_checked(quad, generic):
    with pytest.raises(ValueError, match="rotor_omega must have shape"):
        vehicle_wrench(quad, generic, [0, 0, 0], [0, 0, 0], [800] * 3)
    with pytest.raises(ValueError, match="same number of samples"):
        vehicle_wrench(quad, generic, np.zeros((2, 3)), np.zeros((3, 3)), [800] * 4)
    with pytest.raises(ValueError, match="velocity must be finite"):
        vehicle_wrench(quad, generic, [np.nan, 0, 0], [0, 0, 0], [800] * 4)
    with pytest.raises(ValueError, match=r"rotor_omega must be >= 0 rad/s .* got -5 for rotor 3 \(sample 2\)"):
        vehicle_wrench(quad, generic, [0, 0, 0], [0, 0, 0], [[800] * 4, [800, 800, -5, 800]])


def test_extended_vehicle_file(tmp_path, generic):
    veh = read_vehicle(NEUROBEM)
    assert veh.mass == 0.772 and veh.inertia[2, 2] == 0.0043 and len(veh.rotors) == 4
    r = veh.rotors[0]
    assert r.propeller.n_blades == 3 and r.propeller.radius == pytest.approx(0.06477, rel=1e-4)
    assert r.inertia == 9.3575e-6 and r.spin == -1.0
    (tmp_path / "p.toml").write_text('section_model = "cambered"\ncollective_deg = 5.0\n')
    (tmp_path / "v.toml").write_text(
        'mass = 1.0\ninertia = [[0.01, 0.0, 0.0], [0.0, 0.02, 0.001], [0.0, 0.001, 0.03]]\n'
        '[body]\ndrag_area = [0.01, 0.02, 0.03]\nwash_factor = 1.5\n'
        '[[rotors]]\nposition = [0.1, 0, 0]\naxis = [0, 0, 1]\nspin = "ccw"\npropeller = "apce_8x6"\n'
        'params = "p.toml"\ninertia = 1e-5\n')
    v = read_vehicle(tmp_path / "v.toml")
    assert v.inertia[1, 2] == 0.001 and v.body_drag.wash_factor == 1.5
    assert v.rotors[0].params.collective == pytest.approx(math.radians(5))


@pytest.mark.parametrize("text, match", [
    ("inertia = [1, 2]", "inertia must be"),
    ("inertia = [[1, 0, 0], [1, 1, 0], [0, 0, 1]]", "symmetric"),
    ("inertia = [1, -1, 1]", "positive definite"),
    ("[body]\nwash_factor = 1", "drag_area"),
    ("[body]\ndrag_area = [0, 0, 100]", "drag_area"),
    ("[body]\ndrag_area = [0, 0, 0]\nwash = 1", "unknown key"),
])
def test_vehicle_file_errors_name_the_key(tmp_path, text, match):
    rotor = '[[rotors]]\nposition = [0.1, 0, 0]\naxis = [0, 0, 1]\nspin = "ccw"\npropeller = "apce_8x6"\n'
    top, _, table = text.partition("[body]")
    body = "[body]" + table if table else ""
    (tmp_path / "v.toml").write_text(f"mass = 1.0\n{top}\n{body}\n{rotor}")
    with pytest.raises(VehicleFileError, match=match):
        read_vehicle(tmp_path / "v.toml")


@pytest.mark.parametrize("line, match", [
    ("blades = 0", "blades must be an integer"),
    ("blades = 3", "catalogue propeller"),
    ("params = \"nope\"", "params"),
    ("inertia = -1", "inertia"),
])
def test_rotor_keys_errors(tmp_path, line, match):
    (tmp_path / "v.toml").write_text('mass = 1.0\n[[rotors]]\nposition = [0.1, 0, 0]\naxis = [0, 0, 1]\n'
                                     f'spin = "ccw"\npropeller = "apce_8x6"\n{line}\n')
    with pytest.raises(VehicleFileError, match=match):
        read_vehicle(tmp_path / "v.toml")


def test_the_documented_vehicle_file_reads(tmp_path):
    """docs/flight.md's vehicle-file example reads as written (it once gave a geometry file's
    blades and diameter_m to a catalogue propeller, which read_vehicle refuses)."""
    text = (Path(__file__).resolve().parents[1] / "docs" / "flight.md").read_text(encoding="utf-8")
    start = text.index("```toml\n") + len("```toml\n")
    f = tmp_path / "v.toml"
    f.write_text(text[start:text.index("```", start)])
    v = read_vehicle(f)
    assert v.mass == 0.8 and len(v.rotors) == 1 and v.inertia is not None and v.body_drag.wash_factor == 1.0
    assert v.rotor_interference == 1.0 and v.rotors[0].spin > 0


@pytest.mark.parametrize("change, match", [
    ({"spin": 2.0}, r"Rotor.spin must be \+1 or 'ccw'"),  # (it scaled the torque and rolling moment: 2x)
    ({"spin": 0}, r"Rotor.spin must be"),  # (the torque vanished)
    ({"spin": float("nan")}, r"Rotor.spin must be"),
    ({"inertia": -1.0}, r"Rotor.inertia must be a finite number >= 0"),
    ({"inertia": float("nan")}, r"Rotor.inertia must be a finite number >= 0"),
    ({"position": [0.1, float("nan"), 0.0]}, r"Rotor.position must be 3 finite numbers"),
    ({"position": [0.1, 0.2]}, r"Rotor.position must be 3 finite numbers"),
    ({"axis": [0, 0, 0]}, r"Rotor.axis must be a direction, got a zero vector"),
    ({"propeller": "apce_8x6"}, r"Rotor.propeller must be a Propeller, got str"),
])
def test_a_rotor_built_in_python_is_checked(change, match):
    """A Rotor built by hand gets the vehicle file's checks (each gave a silently wrong or NaN
    wrench, or NumPy's error, before); 'cw'/'ccw' and a non-unit axis are accepted."""
    prop = pm.load_propeller("apce_8x6")
    ok = dict(position=[0.1, 0.1, 0.0], axis=[0, 0, 2.0], spin="cw", propeller=prop)
    r = Rotor(**ok)
    assert r.spin == -1.0 and np.array_equal(r.axis, [0, 0, 1.0])
    with pytest.raises(ValueError, match=match):
        Rotor(**{**ok, **change})


def test_a_vehicle_built_in_python_is_checked():
    prop = pm.load_propeller("apce_8x6")
    rotor = Rotor([0.1, 0.1, 0.0], [0, 0, 1.0], 1, prop)
    v = Vehicle(mass=1.0, rotors=[rotor], inertia=[0.01, 0.01, 0.02])
    assert v.rotors == (rotor,) and v.inertia.shape == (3, 3) and v.inertia[2, 2] == 0.02
    for kw, match in (({"rotors": ()}, "Vehicle.rotors must be a non-empty sequence of Rotor"),
                      ({"mass": 0.0}, r"Vehicle.mass must be a finite number > 0"),
                      ({"inertia": [[1.0, 0.0]]}, "Vehicle.inertia must be a 3x3 tensor or its diagonal"),
                      ({"centre_of_mass": [0.0, 0.0]}, "Vehicle.centre_of_mass must be 3 finite numbers")):
        with pytest.raises(ValueError, match=match):
            Vehicle(**{"mass": 1.0, "rotors": (rotor,), **kw})
