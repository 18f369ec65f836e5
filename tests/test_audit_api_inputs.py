"""Defects found by a user-level audit of the Python API (2026-11-30): a VehicleMap's density,
shared or aliased results (the catalogue, the calibration, a map's omega), NumPy scalars and 0-d
arrays refused where numbers are taken, text taken as a number, and obscure exceptions where a
wrong argument deserved a message naming it."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import propmap as pm
from propmap.identify import loads_from_catalogue, simulate_level_flight
from propmap.io.calibration import calibration
from propmap.io.catalogue import get_entry
from propmap.maps import RotorMap
from propmap.vehicle import VehicleMap, read_vehicle


@pytest.fixture(scope="module")
def quad(small_map):
    _, params, ds = small_map
    veh = dataclasses.replace(read_vehicle("quadrotor"), body_drag=pm.BodyDrag((0.01, 0.01, 0.02)))
    return veh, params, RotorMap(ds)


@pytest.mark.parametrize("rho, match", [(-1.0, r"rho must be a finite number in \(0, inf\) kg/m\^3, got -1.0"),
                                        (0.0, r"rho must be a finite number in \(0, inf\) kg/m\^3, got 0.0"),
                                        (math.nan, r"rho must be a finite number in \(0, inf\) kg/m\^3, got nan"),
                                        (math.inf, "got inf"),
                                        (True, r"rho must be a finite number in \(0, inf\) kg/m\^3, got True"),
                                        ("1.2", r"rho must be a finite number in \(0, inf\) kg/m\^3, got '1.2'")])
def test_a_vehicle_maps_density_is_checked(quad, rho, match):
    """-1 reversed the airframe drag, NaN made every force NaN, text was read as a number."""
    veh, _, m = quad
    with pytest.raises(ValueError, match=match):
        VehicleMap(veh, m, rho=rho)


def test_a_vehicle_maps_density_as_a_numpy_number_is_the_same_air(quad):
    veh, _, m = quad
    args = ([8.0, 0.0, 0.0], [0.0, 0.0, 0.0], [800.0] * 4)
    ref = VehicleMap(veh, m, rho=1.25).wrench(*args).force
    for rho in (np.float64(1.25), np.float32(1.25), np.array(1.25)):  # (1.25 is exact in float32)
        np.testing.assert_array_equal(VehicleMap(veh, m, rho=rho).wrench(*args).force, ref)
    # the airframe's drag is the one term rho scales here: doubling it doubles the difference to no airframe
    bare = VehicleMap(dataclasses.replace(veh, body_drag=None), m).wrench(*args).force
    twice = VehicleMap(veh, m, rho=2.5).wrench(*args).force
    np.testing.assert_allclose(twice - bare, 2 * (ref - bare), rtol=1e-12)
    assert (ref - bare)[0, 0] < 0  # drag opposes the flight along +x


def test_a_vehicle_map_without_maps_or_samples(quad):
    veh, _, m = quad
    with pytest.raises(ValueError, match=r"maps must be one RotorMap or one per rotor \(4\), got NoneType"):
        VehicleMap(veh, None)
    w = VehicleMap(veh, m).wrench(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros((0, 4)))
    assert w.force.shape == w.moment.shape == (0, 3) and w.flagged.shape == (0,)  # as vehicle_wrench's


def test_a_vehicle_map_keeps_the_vehicle_it_was_built_with(quad):
    """A rotor tilted in place afterwards: the VehicleMap kept the old geometry's forces while its
    .vehicle showed the tilt (a concurrency audit, 2026-11-30). Now .vehicle is its own snapshot."""
    veh, _, m = quad
    veh = dataclasses.replace(veh, rotors=tuple(dataclasses.replace(r) for r in veh.rotors))  # (the fixture's own)
    vm = VehicleMap(veh, m)
    args = ([2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [700.0] * 4)
    before = vm.wrench(*args).force
    veh.rotors[0].axis[:] = [0.5, 0.0, math.sqrt(0.75)]
    np.testing.assert_array_equal(vm.vehicle.rotors[0].axis, [0.0, 0.0, 1.0])
    np.testing.assert_array_equal(vm.wrench(*args).force, before)
    tilted = VehicleMap(veh, m).wrench(*args).force
    assert tilted[0, 0] - before[0, 0] > 1.0  # the tilted rotor's thrust, half of it along +x


def test_a_maps_result_does_not_share_the_callers_omega(quad):
    """Changing the caller's omega changed the result's (and its power); writing the result's
    wrote the caller's."""
    _, _, m = quad
    om = np.array([800.0, 900.0])
    ml = m.loads(om, 5.0, 1.0)
    power = ml.power.copy()
    om[:] = 1000.0
    np.testing.assert_array_equal(ml.omega, [800.0, 900.0])
    np.testing.assert_array_equal(ml.power, power)
    assert not np.shares_memory(ml.omega, om)


def test_the_catalogue_and_the_calibration_cannot_be_changed_through_their_results():
    """catalogue().pop('apce_10x7') made load_propeller('apce_10x7') unknown for the whole process."""
    c = pm.catalogue()
    c.pop("apce_10x7")
    assert "apce_10x7" in pm.catalogue() and pm.load_propeller("apce_10x7").name == "apce_10x7"
    cal = calibration()
    for mapping, key in ((cal, "generic"), (cal["propellers"], "apce_8x6"), (cal["population"], "names")):
        with pytest.raises(TypeError):
            mapping[key] = None
    assert isinstance(cal["generic_folds"], tuple)
    with pytest.raises(TypeError):  # (the population's lists were the cached file's: a review)
        cal["population"]["covariance"][0][0] = 123.0
    with pytest.raises(AttributeError):
        cal["population"]["names"].append("x")
    from propmap.io.calibration import coverage, population

    coverage("generic")["J_max"] = 99.0
    assert coverage("generic")["J_max"] != 99.0
    assert population()["covariance"][0, 0] != 123.0
    assert pm.default_params("apce_8x6").label == "calibrated:apce_8x6"


@pytest.mark.parametrize("omega", [np.float32(800.0), np.int64(800), np.array(800.0)])
def test_a_hover_model_takes_numpy_numbers(apc8x6, apc_params, omega):
    """np.float32 was refused with 'k_T must be a finite number', a value the user never gave."""
    ref = pm.HoverModel.from_model(apc8x6, apc_params, 800.0)
    h = pm.HoverModel.from_model(apc8x6, apc_params, omega)
    assert h == ref and type(h.k_T) is float
    assert pm.HoverModel(k_T=np.float32(1e-5), k_Q=np.int64(0), diameter=np.array(0.2)).diameter == 0.2
    c = pm.HoverModel.from_coefficients(np.float32(0.125), np.float32(0.0625), np.float32(0.25))
    assert c == pm.HoverModel.from_coefficients(0.125, 0.0625, 0.25)
    with pytest.raises(ValueError, match="k_T must be a finite number"):  # (a NumPy integer, but a time)
        pm.HoverModel(k_T=np.timedelta64(3), k_Q=0.0)


def test_the_trims_take_numpy_tolerances_and_refuse_text(apc8x6, apc_params):
    """np.float32(0.05) was refused as out of [8.7e-05, 0.87] rad; trim_vehicle read '5' as 5 m/s."""
    ref = pm.trim_collective(apc8x6, apc_params, 2.0, 800.0, grid_step=0.0625)
    r = pm.trim_collective(apc8x6, apc_params, 2.0, 800.0, grid_step=np.float32(0.0625), thrust_tol=np.float32(1e-6))
    assert float(r.collective) == pytest.approx(float(ref.collective), abs=1e-9)
    assert pm.trim_omega(apc8x6, apc_params, 2.0, thrust_tol=np.array(1e-6)).loads.thrust == pytest.approx(2.0,
                                                                                                         abs=1e-6)
    veh = read_vehicle("quadrotor")
    for kw, name in (({"airspeed": "5"}, "airspeed"), ({"airspeed": 5.0, "climb_rate": "1"}, "climb_rate")):
        with pytest.raises(ValueError, match=f"^{name} must be a finite number in"):
            pm.trim_vehicle(veh, apc_params, **kw)


@pytest.mark.parametrize("make, match", [
    (lambda: pm.Air(rho=np.array(1.2)), None),
    (lambda: pm.BodyDrag(np.array([0.01, 0.01, 0.02]), wash_factor=np.array(0.5)), None),
    (lambda: pm.Discretization(np.array(48), np.int64(16)), None),
    (lambda: pm.Air(rho=np.array([1.2, 1.3])), r"rho must be a finite number in \(0, inf\) kg/m\^3, got array"),
    (lambda: pm.Air(rho=np.array("1.2")), "rho must be a finite number in"),
])
def test_zero_d_arrays_are_numbers_and_arrays_of_several_are_not(make, match):
    if match is None:
        make()
    else:
        with pytest.raises(ValueError, match=match):
            make()


def test_a_propeller_radius_may_be_a_zero_d_array(apc8x6, shared_data):
    """It was refused with 'radius must be finite and > 0 m, got 0.1' (the value was in range); so
    were a vehicle's mass and a geometry file's diameter_in."""
    p = dataclasses.replace(apc8x6, radius=np.array(apc8x6.radius))
    assert type(p.radius) is float and p.radius == apc8x6.radius
    veh = dataclasses.replace(read_vehicle("quadrotor"), mass=np.array(0.8), gravity=np.float32(9.75))
    assert type(veh.mass) is float and veh.mass == 0.8 and veh.gravity == float(np.float32(9.75))
    with pytest.warns(UserWarning, match="diameter 8 in as given"):
        g = pm.read_geometry(shared_data / "uiuc_propdb" / "v1" / "apc29ff_9x5_geom.txt", diameter_in=np.array(8.0),
                             n_blades=2)
    assert g.radius == pytest.approx(4 * 0.0254, rel=1e-15)


def test_write_params_names_a_wrong_argument(tmp_path, apc_params):
    """An AttributeError each, until 2026-11-30; nothing is written."""
    path = tmp_path / "p.toml"
    for kw, match in (({"params": {}}, "^params must be AirfoilParams or CamberedParams, got dict"),
                      ({"air": 1.2}, "^air must be a propmap.Air, got float"),
                      ({"body": 5}, "^body must be a BodyTable"), ({"coverage": [1]}, "^coverage must be a dict")):
        args = {"params": apc_params, **kw}
        with pytest.raises(TypeError, match=match):
            pm.write_params(path, **args)
    assert not path.exists()


def test_the_synthetic_data_helpers_take_names_and_numbers(apc_params):
    """loads_from_catalogue('apce_8x6', ...) and simulate_level_flight('quadrotor', ...) met
    AttributeErrors, two numbers an IndexError."""
    by_name = loads_from_catalogue("apce_8x6", np.array(0.2032))
    by_entry = loads_from_catalogue(get_entry("apce_8x6"), 0.2032)
    np.testing.assert_array_equal(by_name.measured["thrust"], by_entry.measured["thrust"])
    with pytest.raises(KeyError, match="did you mean apce_8x6"):
        loads_from_catalogue("apce_8x6x", 0.2032)
    with pytest.raises(TypeError, match="entry must be a CatalogueEntry"):
        loads_from_catalogue(5, 0.2032)
    veh = read_vehicle("quadrotor")
    with pytest.raises(TypeError, match="^vehicle must be a propmap Vehicle"):
        simulate_level_flight("quadrotor", apc_params, 5.0, -3.0)
    one = simulate_level_flight(veh, apc_params, 5.0, -3.0)
    two = simulate_level_flight(veh, apc_params, [5.0, 5.0], -3.0)
    assert one.omega.shape == (1, 4) and two.omega.shape == (2, 4)
    np.testing.assert_array_equal(two.omega[1], one.omega[0])
    with pytest.raises(ValueError, match=r"got shapes \(2,\) and \(3,\)"):
        simulate_level_flight(veh, apc_params, [5.0, 6.0], [1.0, 2.0, 3.0])


def test_flapping_beyond_small_angles_is_warned_of(apc8x6):
    """A stopped rotor in a flow has no flap damping: with 50 rad/(N m) at 50 m/s edgewise the
    blades flapped 4.25 rad and the side force was 4.25 times the thrust, unflagged (an
    edge-of-range audit, 2026-11-30). Forward flight at speed stays below the limit, silently."""
    import warnings

    from propmap.core.flapping import FLAP_ANGLE_WARN

    s = pm.default_params("apce_8x6").replace(flap_compliance=50.0)
    with pytest.warns(UserWarning, match=r"^flapping: 1 point\(s\) flap by more than 0.25 rad \(largest 4.25 rad"):
        r = pm.rotor_loads(apc8x6, s, 0.0, 50.0, math.pi / 2)
    assert float(r.flap_1s) > FLAP_ANGLE_WARN
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = pm.rotor_loads(apc8x6, s.replace(flap_compliance=2.0), 800.0, np.linspace(0.0, 20.0, 21),
                           math.radians(80.0))
    assert 0.05 < np.hypot(r.flap_1c, r.flap_1s).max() < FLAP_ANGLE_WARN


# --- one range check for the model's scalar inputs (core._numbers.checked, 2026-11-30) ---------------------------

@pytest.mark.parametrize("value, kw, message", [
    (-1, dict(low=0.0, low_open=True, unit="kg/m^3"), "rho must be a finite number in (0, inf) kg/m^3, got -1"),
    (0.0, dict(low=0.0, low_open=True), "rho must be a finite number in (0, inf), got 0.0"),
    (5.0, dict(low=0.0, high=5.0, high_open=True), "rho must be a finite number in [0, 5), got 5.0"),
    (2.0, dict(high=1.0, unit="s"), "rho must be a finite number in (-inf, 1] s, got 2.0"),
    (math.nan, {}, "rho must be a finite number, got nan"),
    (math.inf, dict(unit="rad"), "rho must be a finite number [rad], got inf"),
    (True, dict(low=0.0, high=1.0), "rho must be a finite number in [0, 1], got True"),
    ("0.5", dict(low=0.0, high=1.0), "rho must be a finite number in [0, 1], got '0.5'"),
    (math.radians(31), dict(low=-math.radians(30), high=math.radians(30), unit="rad"),
     "rho must be a finite number in [-0.5235987755982988, 0.5235987755982988] rad, got 0.5410520681182421"),
])
def test_the_range_check_names_the_argument_the_exact_range_and_the_unit(value, kw, message):
    """A bound that ':g' would round (30 deg in rad) is shown in full: a value just above it must not
    read as inside the range printed."""
    from propmap.core._numbers import checked

    with pytest.raises(ValueError) as info:
        checked("rho", value, **kw)
    assert str(info.value) == message


def test_the_range_check_returns_a_float_and_takes_the_closed_ends_and_numpy_numbers():
    from propmap.core._numbers import checked
    from propmap.identify.data import DataError

    assert checked("x", np.float32(0.5), 0.0, 1.0) == 0.5 and type(checked("x", np.int64(1), 0.0, 1.0)) is float
    assert checked("x", 0.0, 0.0, 1.0) == 0.0 and checked("x", 1.0, 0.0, 1.0) == 1.0
    with pytest.raises(DataError, match=r"^diameter must be a finite number in \(0, 10\] m, got 0$"):
        checked("diameter", 0, 0.0, 10.0, low_open=True, unit="m", error=DataError)


@pytest.mark.parametrize("make, message", [
    (lambda: pm.Air(mu=-1.0), "mu must be a finite number in (0, inf) Pa s, got -1.0"),
    (lambda: pm.Air.isa(30000.0), "altitude must be a finite number in [-500, 20000] m, got 30000.0"),
    (lambda: pm.BodyDrag((0.1, 0.1, 11.0)), "drag_area[2] must be a finite number in [0, 10] m^2, got 11.0"),
    (lambda: pm.CamberedParams(flap_compliance=-1.0),
     "flap_compliance must be a finite number in [0, 1000] rad/(N m), got -1.0"),
])
def test_the_records_name_their_ranges_with_units(make, message):
    """Air's and the section records' messages named no range for a value that was not a number and
    no unit at all (\"rho must be a number, got True\"); one checker now words them all alike."""
    with pytest.raises(ValueError) as info:
        make()
    assert str(info.value) == message
