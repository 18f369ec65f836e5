"""Behaviour a mutation audit found unpinned (2026-11-28, a helper session: 75 mutants run, 25 of
vehicle/mapped.py, 33 of core/_inputs.py, 13 of core/states.py and 4 of core/_flags.py, each of whose
mutants recompiles the solver kernel, so 10 more planned there were not run; 21 survived the suite of
then, 20 of them visible to users; one more, not run, is equivalent: states._classify's linear and
empirical flags swapped, which descent_state discards). Each test names the audit's mutants it kills
(V: mapped, I: _inputs, S: states, F: _flags); F11 was run against the new tests only."""

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag
from propmap.maps import RotorMap, build_map
from propmap.vehicle import Rotor, Vehicle, VehicleMap, read_vehicle

DATA = Path(pm.__file__).parent / "data"


@pytest.fixture(scope="module")
def quad():
    """The example quadrotor (four apce_8x6) and a coarse map of its propeller (600-1300 rad/s, 0-12 m/s)."""
    veh = read_vehicle(DATA / "examples" / "quadrotor.toml")
    ds = build_map(veh.rotors[0].propeller, pm.default_params("apce_8x6"), np.linspace(600, 1300, 4),
                   np.linspace(0, 12, 4), np.radians(np.linspace(0, 180, 7)), n_check=0)
    return veh, RotorMap(ds)


# ---------------------------------------------------------------- vehicle/mapped.py


def test_vehicle_map_refuses_what_is_not_a_vehicle_and_more_maps_than_rotors(quad):
    """A non-Vehicle is refused by name with the TypeError of every entry point that takes a vehicle
    (not an AttributeError from inside; V01); five maps for four rotors are refused, not the fifth
    silently dropped by zip (V02)."""
    veh, rm = quad
    with pytest.raises(TypeError, match=r"vehicle must be a propmap Vehicle \(propmap.read_vehicle\), got dict"):
        VehicleMap({"rotors": veh.rotors}, rm)
    with pytest.raises(ValueError, match=r"maps must be one RotorMap or one per rotor \(4\), got 5"):
        VehicleMap(veh, [rm] * 5)


def test_a_duck_typed_map_that_records_no_diameter_is_refused(quad):
    """The maps are duck-typed (anything with a wrench and attrs): one whose attrs hold no diameter
    cannot be checked against the rotor's propeller and is refused (same_size alone does not compare
    an unknown diameter: without the isfinite guard it was taken; V03)."""
    veh, rm = quad

    class Duck:
        attrs = {k: v for k, v in rm.attrs.items() if k != "diameter_m"}

        def wrench(self, *args, **kwargs):
            return rm.wrench(*args, **kwargs)

    with pytest.raises(ValueError, match=r"rotor 1's map is of apce_8x6 \(nan m, 2 blades\)"):
        VehicleMap(veh, Duck())


def test_the_hub_bound_uses_the_longest_arm(quad):
    """Body rates whose product with the longest arm (1 m) reaches 1e150 m/s are refused by VehicleMap's
    own check, naming the bound, though the short arm (0.1 m) alone would stay below it (V04: the
    shortest arm; the map's own refusal then answered in other terms)."""
    veh, rm = quad
    prop = veh.rotors[0].propeller
    z = np.array([0.0, 0.0, 1.0])
    lopsided = Vehicle(mass=1.0, rotors=(Rotor(np.array([0.1, 0.0, 0.0]), z, 1, prop),
                                         Rotor(np.array([0.0, 1.0, 0.0]), z, -1, prop)))
    vm = VehicleMap(lopsided, rm)
    for n in (1, 2):
        with pytest.raises(ValueError, match=r"hub's velocity of up to 2e\+150 m/s .* must stay below 1e\+150"):
            vm.wrench(np.zeros((n, 3)), np.tile([0.0, 0.0, 2e150], (n, 1)), np.full((n, 2), 900.0),
                      out_of_grid="clip")


def test_an_idle_airframe_or_interference_factor_is_not_warned_of(quad):
    """A slipstream factor on an airframe without drag area, a zero slipstream factor or zero rotor
    interference leave nothing out: no warning (V07, V08, V09); a real one is warned of."""
    veh, rm = quad
    quiet = [Vehicle(mass=1.0, rotors=veh.rotors, body_drag=BodyDrag((0.0, 0.0, 0.0), 1.2)),
             Vehicle(mass=1.0, rotors=veh.rotors, body_drag=BodyDrag((0.01, 0.01, 0.02), 0.0)),
             Vehicle(mass=1.0, rotors=veh.rotors, rotor_interference=0.0)]
    for v in quiet:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            VehicleMap(v, rm)
    with pytest.warns(UserWarning, match=r"rotors' interference \(factor 0.5\) is left out"):
        VehicleMap(Vehicle(mass=1.0, rotors=veh.rotors, rotor_interference=0.5), rm)


def test_the_airframe_drag_takes_the_given_density(quad):
    """rho= sets the airframe drag's density (V10: the map's density always): the drag is linear in
    rho, 0.5 rho CdA |V| V, on the one-step and the batch path."""
    veh, rm = quad
    body = BodyDrag((0.01, 0.012, 0.02))
    v = Vehicle(mass=1.0, rotors=veh.rotors, body_drag=body)
    bare = VehicleMap(Vehicle(mass=1.0, rotors=veh.rotors), rm)
    rho0 = float(rm.attrs["rho_kg_m3"])
    vel, w, om = np.array([6.0, -2.0, 1.0]), np.zeros(3), np.full(4, 900.0)
    expect = -0.5 * np.array(body.drag_area) * np.linalg.norm(vel) * vel
    for rho in (None, 0.5 * rho0):
        vm = VehicleMap(v, rm, rho=rho)
        for args in ((vel, w, om), (np.tile(vel, (2, 1)), np.zeros((2, 3)), np.full((2, 4), 900.0))):
            drag = vm.wrench(*args).force - bare.wrench(*args).force
            np.testing.assert_allclose(drag, np.broadcast_to(expect * (rho or rho0), drag.shape), rtol=1e-9)


def test_sample_counts_that_do_not_match_are_refused_by_name(quad):
    """Two velocities with three rotor-speed rows: refused naming the inputs and their counts (V16:
    NumPy's broadcast error instead)."""
    veh, rm = quad
    vm = VehicleMap(veh, rm)
    with pytest.raises(ValueError, match=r"must have the same number of samples \(or one\), got \[2, 1, 3, 1\]"):
        vm.wrench(np.zeros((2, 3)), np.zeros(3), np.full((3, 4), 900.0))


# ---------------------------------------------------------------- core/_inputs.py


@pytest.fixture(scope="module")
def apc():
    return pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")


def test_a_negative_incidence_is_refused_with_the_symmetry_hint(apc):
    """-0.01 rad: refused, the message saying the model is symmetric in the incidence (I02); below -pi
    (not a magnitude's sign) no such hint."""
    prop, params = apc
    for b in (-0.01, np.array([0.2, -0.01])):
        with pytest.raises(ValueError, match=r"incidence must be finite and in \[0, 3.14159\] rad; got -0.01 "
                                             r"\(the model is symmetric in the incidence: give its magnitude\)"):
            pm.rotor_loads(prop, params, 800.0, 5.0, b)
    with pytest.raises(ValueError, match=r"got -4.0$"):
        pm.rotor_loads(prop, params, 800.0, 5.0, -4.0)


def test_an_array_names_its_first_value_out_of_range(apc):
    """Of several bad values the message names the first, as the docstring of _outside says (I05: the last)."""
    prop, params = apc
    with pytest.raises(ValueError, match=r"airspeed must be finite and in \[0, 500\] m/s; got 600.0$"):
        pm.rotor_loads(prop, params, 800.0, np.array([5.0, 600.0, np.nan, 700.0]), 0.3)
    with pytest.raises(ValueError, match=r"omega .* got -2.0 \(a signed rotation rate"):
        pm.rotor_loads(prop, params, np.array([[800.0, -2.0], [-3.0, 900.0]]), 5.0, 0.3)


def test_only_the_incidence_is_snapped_on_the_array_path(apc):
    """A rate or airspeed a hair below zero is refused on the array path as on the scalar one; the
    incidence alone is taken onto its end within INCIDENCE_SNAP (I09: every input snapped, -1e-9 rad/s
    taken as 0)."""
    prop, params = apc
    for kw in (dict(omega=-1e-9), dict(airspeed=-1e-9)):
        args = dict(omega=800.0, airspeed=5.0, incidence=0.3) | kw
        name = next(iter(kw))
        for a in (args, args | {name: np.array([1.0, kw[name]])}):
            with pytest.raises(ValueError, match=rf"^{name} must be finite and in \[0, "):
                pm.rotor_loads(prop, params, **a)


def test_the_tip_speed_warned_of_adds_the_in_plane_airspeed_on_both_paths():
    """NeuroBEM's 5.1 in rotor at 35,000 rpm, 40 m/s edgewise: Omega R = 237 m/s (Mach 0.70) alone,
    the advancing tip Omega R + V = 277 m/s (Mach 0.81): warned on the array path as on the scalar one
    (I07: the array path dropped |V_s|); attributed to the caller's line (I23). In axial flow at the
    same rate, V = 40 m/s: hypot(237, 40) = 240 m/s, Mach 0.71, no warning."""
    rotor = read_vehicle(DATA / "examples" / "neurobem_quadrotor.toml").rotors[0]
    om = 35000 * math.pi / 30
    for omega in (om, np.array([100.0, om])):
        with pytest.warns(UserWarning, match=r"at Mach 0\.8[12] \(> 0\.8\): near the end of the model's "
                                             r"compressibility") as caught:
            pm.rotor_loads(rotor.propeller, pm.generic_params(), omega, 40.0, math.pi / 2)
        assert [w.filename for w in caught if "Mach" in str(w.message)] == [__file__]
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            pm.rotor_loads(rotor.propeller, pm.generic_params(), omega, 40.0, 0.0)


def test_mach_0_98_is_past_the_end_of_compressibility_not_meaningless():
    """An 11 in propeller at 2400 'rad/s' (rpm): tip Mach 0.98-0.99 (default air), subsonic: the warning
    says the model is past the end of its compressibility (its Prandtl-Glauert factor held at Mach
    0.9; "near the end" until 2026-12-01) and hints at rpm, not that the loads mean nothing (I21);
    past Mach 1 (2600 'rad/s') it says they mean nothing."""
    prop, params = pm.load_propeller("apce_11x10"), pm.default_params("apce_11x10")
    with pytest.warns(UserWarning, match=r"at Mach 0\.9[89] \(> 0\.8\): past the end .*is omega given in rpm"):
        pm.rotor_loads(prop, params, 2400.0, 0.0, 0.0)
    with pytest.warns(UserWarning, match=r"at Mach 1\.1 \(> 0\.8\): .*these loads mean nothing; is omega given"):
        pm.rotor_loads(prop, params, 2600.0, 0.0, 0.0)


def test_derivatives_are_refused_below_omega_min_only(apc):
    """Below OMEGA_MIN = 0.1 rad/s the blades are parked (the loads held at 0.1 rad/s): derivatives are
    refused there, naming the bound, and given from it on (I28: a bound of 0.2 refused 0.15 rad/s)."""
    prop, params = apc
    r = pm.rotor_loads(prop, params, 0.15, 5.0, 0.5, derivatives=True)
    assert np.isfinite(r.derivative("thrust", "omega"))
    for om in (0.05, np.array([0.05, 800.0])):
        with pytest.raises(ValueError, match=r"derivatives need omega >= 0.1 rad/s \(below it the blades are parked"):
            pm.rotor_loads(prop, params, om, 5.0, 0.5, derivatives=True)


# ---------------------------------------------------------------- core/states.py


def test_descent_state_keeps_the_broadcast_shape_of_its_inputs():
    """Inputs broadcast to (3, 4): every output has that shape and each element is the state of its own
    point (S13: the outputs reshaped to (4, 3)); T <= 0 gives v_h = 0 and NaN ratios, as the docstring
    says (F01: |T| taken, a negative thrust had the v_h of its magnitude)."""
    from propmap.core.states import STATES, descent_state

    rho, R = 1.2, 0.1
    T = np.array([[2.0], [0.0], [-2.0]])  # (3, 1)
    V = np.array([0.0, 4.0, 12.0, 20.0])  # (4,), axial descent
    st, vh, k, m = descent_state(T, V, math.pi, 0.0, rho, R)
    assert st.shape == vh.shape == k.shape == m.shape == (3, 4)
    v_h = math.sqrt(2.0 / (2 * rho * math.pi * R * R))  # 5.15 m/s
    np.testing.assert_allclose(vh[0], v_h, rtol=1e-14)
    np.testing.assert_allclose(k[0], V / v_h, rtol=1e-14)
    # k = 0, 0.78, 2.33, 3.9
    assert [STATES[s] for s in st[0]] == ["normal working", "vortex ring", "windmill brake", "windmill brake"]
    assert np.all(vh[1:] == 0.0) and np.isnan(k[1:]).all() and np.isnan(m[1:]).all()


def test_a_stopped_rotor_in_still_air_is_in_normal_working(apc):
    """No thrust and no axial flow (Omega = 0, V = 0, so v_h = 0): normal working, not the windmill
    brake that a zero v_h means in descent (F02: vz <= 0 taken as descent); in a descent it is."""
    from propmap.core.states import descent_state

    assert descent_state(0.0, 0.0, 0.0, 0.0, 1.2, 0.1)[0] == 0
    prop, params = apc
    r = pm.rotor_loads(prop, params, np.array([0.0, 0.0]), np.array([0.0, 3.0]), math.pi)
    assert r.thrust[0] == 0.0 and list(r.state_name) == ["normal working", "windmill brake"]


# ---------------------------------------------------------------- core/_flags.py


def test_inflow_extrapolated_only_where_a_linear_model_leaves_its_range():
    """Axial descent in the windmill brake (V cos(beta) + v_mean < 0, no in-plane flow): no wake skew, the
    linear models are the uniform one, not extrapolated (F05: the in-plane guard dropped); past Drees's
    advance ratio 0.5 only Drees's model is held, the uniform inflow and Pitt-Peters are not (F11)."""
    prop, g = pm.load_propeller("apce_8x6"), pm.generic_params()
    om, V, b = np.array([300.0, 300.0, 300.0]), np.array([20.0, 25.0, 20.0]), np.array([math.pi, math.pi, 1.5])
    mu = V[2] * math.sin(b[2]) / (om[2] * prop.radius)  # 0.65
    assert mu > 0.5
    for inflow in ("uniform", "pitt-peters", "drees"):
        r = pm.rotor_loads(prop, g.replace(inflow=inflow), om, V, b)
        assert np.all(-V[:2] + r.v_i_mean[:2] < 0) and list(r.state_name[:2]) == ["windmill brake"] * 2
        assert list(r.inflow_extrapolated) == [False, False, inflow == "drees"]
