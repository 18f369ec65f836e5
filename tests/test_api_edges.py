"""The Python API used as a researcher uses it in a notebook (user-level audit, 2026-11-26):
results that shared the caller's arrays, rpm given as rad/s below tip Mach 1, load data in other
units fitted without a word, a hover model's coefficients at the wrong air, typos that returned
the generic set or a TypeError, and result objects that could not be indexed or compared."""

import copy
import dataclasses
import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.identify import FitOptions, LoadData, fit_loads, loads_from_catalogue
from propmap.io.catalogue import catalogue
from propmap.io.params_file import read_body, read_coverage


@pytest.fixture(scope="module")
def apc():
    return pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")


def test_results_do_not_share_the_callers_arrays(apc):
    """om *= 2 after the call changed r.power from [66.6, 95.2] to [133, 190] and r.CT 4x."""
    prop, params = apc
    om = np.array([800.0, 900.0])
    r = pm.rotor_loads(prop, params, om, 10.0, 1.0)
    power, ct = r.power.copy(), r.CT.copy()
    om *= 2
    assert not np.shares_memory(r.omega, om)
    np.testing.assert_array_equal(r.power, power)
    np.testing.assert_array_equal(r.CT, ct)
    np.testing.assert_array_equal(r.omega, [800.0, 900.0])


def test_rpm_given_as_rad_per_s_is_warned_from_tip_mach_0_8():
    """An 11 in propeller at 1500-2400 'rad/s' (rpm) made 106-137 times the thrust at tip Mach
    0.6-0.98 without a warning (only Mach 1 was warned); at its true 157-251 rad/s, none."""
    prop = pm.load_propeller("apce_11x10")
    params = pm.default_params("apce_11x10")
    with pytest.warns(UserWarning, match=r"at Mach 0\.9[89] \(> 0\.8\): .*is omega given in rpm"):
        pm.rotor_loads(prop, params, np.array([1500.0, 2000.0, 2400.0]), 0.0, 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pm.rotor_loads(prop, params, np.array([1500.0, 2000.0, 2400.0]) * math.pi / 30, 0.0, 0.0)
    # a racing punch-out at Mach 0.81 (NeuroBEM's 5.1 in rotor at 35,000 rpm, 40 m/s edgewise): warned without the
    # rpm hint, which misled there (a user-level audit)
    rotor = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml").rotors[0]
    with pytest.warns(UserWarning, match=r"at Mach 0\.8[12] \(> 0\.8\)") as caught:
        pm.rotor_loads(rotor.propeller, pm.generic_params(), 35000 * math.pi / 30, 40.0, math.pi / 2)
    assert not any("rpm" in str(w.message) for w in caught)


def test_a_fit_of_data_past_tip_mach_0_8_warns_once_not_at_every_evaluation():
    """Load data of a 10 in propeller at 2300-2800 rpm given as rad/s (blade tips at Mach 0.9-1.1):
    fit_loads warned at each of its model evaluations under an "always" filter (7 warnings);
    now once, naming the data, with the rpm hint past Mach 1. Data below Mach 0.8: none."""
    prop = pm.load_propeller("apce_10x7")
    params = pm.default_params("apce_10x7")
    zero = np.zeros(8)
    for omega, said in ((np.linspace(2300.0, 2800.0, 8), True), (np.linspace(300.0, 900.0, 8), False)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = pm.rotor_loads(prop, params, omega, zero, zero)
        data = LoadData(omega, zero, zero, {"thrust": r.thrust, "torque": r.torque}, np.full(8, "a", dtype=object),
                        "stand.csv")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            fit_loads(data, prop)
        tips = [str(w.message) for w in caught if "Mach" in str(w.message)]
        if said:
            assert len(tips) == 1 and re.search(r"at Mach 1(\.\d+)? \(> 0\.8\) in stand\.csv: .*said once for the fit; "
                                                r"is the rotation speed given in rpm", tips[0]), tips
        else:
            assert tips == []


@pytest.mark.parametrize("kw, said", [
    (dict(body_drag=0.1), "body_drag must be a propmap.BodyDrag or None, got float"),
    (dict(vehicle=None), "vehicle must be a propmap Vehicle .*got NoneType"),
    (dict(params=None), "params must be AirfoilParams or CamberedParams .*got NoneType"),
    (dict(air=1.2), "air must be a propmap.Air, got float"),
])
def test_vehicle_wrench_names_an_argument_of_the_wrong_type(kw, said):
    """Each was an AttributeError from inside ('float' object has no attribute 'active'; a
    property-based audit)."""
    args = {"vehicle": pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml"),
            "params": pm.generic_params(), **kw}
    with pytest.raises(TypeError, match=said):
        pm.vehicle_wrench(args.pop("vehicle"), args.pop("params"), [5.0, 0, 0], [0, 0, 0], [1200.0] * 4, **args)


@pytest.mark.parametrize("axis", [[0, 0, 1e-320], [0, 0, 1e-310], [0, 0, 1e300]])
def test_rotor_wrench_scales_a_tiny_or_huge_axis(apc, axis):
    """A one-point rotor_wrench with the axis [0, 0, 1e-320] refused an 'incidence nan' (its
    length underflowed); the array path scaled it: both now give the unit axis' wrench."""
    prop, params = apc
    np.testing.assert_array_equal(pm.rotor_wrench(prop, params, [1.0, 0, 0], axis, 800.0).force,
                                  pm.rotor_wrench(prop, params, [1.0, 0, 0], [0, 0, 1.0], 800.0).force)


def test_a_masked_array_with_masked_entries_is_refused(apc):
    prop, params = apc
    with pytest.raises(ValueError, match=r"omega: a masked array with masked entries"):
        pm.rotor_loads(prop, params, np.ma.masked_array([800.0, 900.0], mask=[0, 1]), 10.0, 1.0)
    r = pm.rotor_loads(prop, params, np.ma.masked_array([800.0, 900.0], mask=[0, 0]), 10.0, 1.0)
    assert r.thrust.shape == (2,)
    # the wrenches and a map: they computed masked entries as if given (a property-based audit)
    M = np.ma.masked_array
    veh = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    rm = pm.RotorMap(pm.build_map(prop, params, [500.0, 1000.0], [0.0, 10.0], [0.0, math.pi], n_check=0))
    for name, call in (
            ("velocity", lambda: pm.rotor_wrench(prop, params, M([5.0, 0, -1], mask=[1, 0, 0]), [0, 0, 1], 800.0)),
            ("axis", lambda: pm.rotor_wrench(prop, params, [5.0, 0, -1], M([0, 0, 1.0], mask=[0, 1, 0]), 800.0)),
            ("omega", lambda: pm.rotor_wrench(prop, params, [5.0, 0, -1], [0, 0, 1], M([800.0, 900], mask=[0, 1]))),
            ("velocity", lambda: pm.vehicle_wrench(veh, params, M([1.0, 0, 0], mask=[1, 0, 0]), [0, 0, 0],
                                                   [900.0] * 4)),
            ("rotor_omega", lambda: pm.vehicle_wrench(veh, params, [1.0, 0, 0], [0, 0, 0],
                                                      M([900.0] * 4, mask=[0, 0, 0, 1]))),
            ("omega", lambda: rm.loads(M([800.0, 900], mask=[0, 1]), 5.0, 1.0)),
            ("velocity", lambda: rm.wrench(M([5.0, 0, -1], mask=[1, 0, 0]), [0, 0, 1], 800.0)),
            ("omega", lambda: rm.wrench([5.0, 0, -1], [0, 0, 1], M(800.0, mask=True)))):
        with pytest.raises(ValueError, match=rf"^{name}: a masked array with masked entries"):
            call()


@pytest.mark.parametrize("key, scale, said", [
    ("torque", 100.0, r"measured static CQ is 0\.\d+ in the median, outside the 0\.001-0\.1 .* is the torque in N m\?"),
    ("thrust", 1000 / 9.80665, r"measured static CT is \d+\.?\d* in the median, .* is the thrust in N\?"),
    ("torque", -1.0, r"measured static torque is negative .* give its magnitude"),
])
def test_load_data_in_other_units_is_warned_about(key, scale, said):
    """Torque in N cm fitted with success=True and no warning (the fit divides each quantity by its
    own RMS, so it was in effect left out); the 147 catalogue propellers' static CT 0.054-0.246 and
    CQ 0.0037-0.027 are not warned about (UIUC Propeller Data Site vol. 1, apce_9x6)."""
    entry = catalogue()["apce_9x6"]
    prop = pm.load_propeller("apce_9x6")
    data = loads_from_catalogue(entry, prop.diameter)
    static = data.airspeed == 0
    data = data.subset(static)
    right = fit_loads(data, prop, options=FitOptions(multistart=0))
    assert not any("measured static" in w for w in right.warnings), right.warnings
    measured = dict(data.measured)
    measured[key] = measured[key] * scale
    wrong = fit_loads(dataclasses.replace(data, measured=measured), prop, options=FitOptions(multistart=0))
    assert any(re.search(said, w) for w in wrong.warnings), wrong.warnings


def test_quantities_given_as_one_string_is_refused():
    entry = catalogue()["apce_9x6"]
    prop = pm.load_propeller("apce_9x6")
    data = loads_from_catalogue(entry, prop.diameter)
    with pytest.raises(ValueError, match=r"quantities must be a tuple of names, e\.g\. \('thrust',\)"):
        fit_loads(data, prop, quantities="thrust")


def test_hover_model_keeps_its_air_and_checks_its_rates(apc):
    """CT of a model built at 3,000 m was computed at sea level (0.0827 against 0.1115); thrust of
    NaN and '800' rad/s returned numbers."""
    prop, params = apc
    air = pm.Air.isa(3000.0)
    h = pm.HoverModel.from_model(prop, params, 1000.0, air=air)
    r = pm.rotor_loads(prop, params, 1000.0, 0.0, 0.0, air=air)
    assert h.CT() == pytest.approx(float(r.CT), rel=1e-12) and h.CP() == pytest.approx(float(r.CP), rel=1e-12)
    assert h.CT(prop.diameter, air=pm.Air()) == pytest.approx(float(r.CT) * air.rho / pm.Air().rho, rel=1e-12)
    for bad in (float("nan"), "800", [800.0, float("inf")]):
        with pytest.raises(ValueError, match="omega"):
            h.thrust(bad)
    assert h.thrust(-800.0) == h.thrust(800.0)  # (a simulator's signed rate: its magnitude)
    for flag in (True, [800.0, True]):  # (True was 1 rad/s: k_T returned)
        with pytest.raises(ValueError, match="not booleans"):
            h.thrust(flag)
    assert h == pm.HoverModel(h.k_T, h.k_Q)  # (the recorded air and diameter are context, not the model)
    with pytest.raises(ValueError, match="diameter is needed"):
        pm.HoverModel(1e-5, 1e-7).CT()


def test_near_names_and_unknown_fields_are_said(apc):
    """'APCE_8x6', 'apce_8x6 ' and 'apce_8x7' returned the generic set without a word; replace()
    with a typo raised __init__'s TypeError."""
    for name, near in (("APCE_8x6", "apce_8x6"), ("apce_8x6 ", "apce_8x6"), ("apce_8x7", "apce_8x6")):
        with pytest.warns(UserWarning, match=rf"{name!r} is not a catalogue propeller.*did you mean .*{near}"):
            assert pm.default_params(name).label == "generic"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert pm.default_params("neurobem_5.1x4.8").label == "generic"
    params = apc[1]
    with pytest.raises(ValueError, match=r"unknown parameter\(s\) cl_alpah of CamberedParams; valid: .*cl_alpha"):
        params.replace(cl_alpah=5.0)
    with pytest.raises(ValueError, match=r"alpha_L0_deg .*angles are in rad here"):
        params.replace(alpha_L0_deg=-3.0)
    with pytest.raises(ValueError, match=r"unknown parameter\(s\) cl_alpha of AirfoilParams"):
        pm.preset("gill2017-apc").replace(cl_alpha=3.0)


def test_loads_of_several_axes_are_indexed_whole_and_compared_by_identity(apc):
    prop, params = apc
    r = pm.rotor_loads(prop, params, np.full((2, 3), 800.0), 5.0, 1.0)
    assert r.flags((1, 2)) == []
    with pytest.raises(IndexError, match=r"index 0 into loads of shape \(2, 3\): give one integer per axis"):
        r.flags(0)
    assert r == r and not (r == copy.deepcopy(r))


def test_loads_become_a_dataframe_and_print_as_a_summary(apc):
    """pd.DataFrame(vars(r)) failed (the radial nodes beside the points) and a one-point repr ran
    to 1.5k characters of radial arrays."""
    prop, params = apc
    r = pm.rotor_loads(prop, params, np.full((2, 3), 800.0), np.array([0.0, 5.0, 10.0]), 1.0)
    df = r.to_dataframe()
    assert df.shape == (6, 24) and df.attrs["units"]["torque"] == "N m" and df.attrs["diameter"] == prop.diameter
    np.testing.assert_array_equal(df["thrust"], r.thrust.reshape(-1))
    np.testing.assert_array_equal(df["CT"], r.CT.reshape(-1))
    assert list(df["state"]) == list(r.state_name.reshape(-1))
    assert (df.loc[df.airspeed == 0, "drag"] == 0).all()  # (D = 0 in hover)
    one = repr(pm.rotor_loads(prop, params, 800.0, 0.0, 0.0))
    assert one.startswith("RotorLoads(shape (), thrust 4.0") and "flags raised: none" in one and len(one) < 200


def test_a_changed_set_is_not_labelled_as_the_named_one(apc):
    """replace() kept the label: a calibrated set with another cl_alpha still reported the
    catalogue's validation figures for that propeller's set (io.uncertainty, by label)."""
    from propmap.io.uncertainty import model_uncertainty

    params = apc[1]
    assert params.label == "calibrated:apce_8x6"
    changed = params.replace(cl_alpha=params.cl_alpha + 0.5)
    assert changed.label == "modified calibrated:apce_8x6"
    assert "in-sample" in model_uncertainty(params.label)["axial"]
    assert model_uncertainty(changed.label)["axial"].startswith("unknown")
    assert changed.replace(cd_min=0.02).label == "modified calibrated:apce_8x6"  # (not "modified modified")
    # the same values, the air, or a label given: the name stays or is the caller's
    assert params.replace(cl_alpha=params.cl_alpha).label == params.label
    assert params.replace(air=pm.Air(rho=1.1)).label == params.label
    assert params.replace(cl_alpha=5.0, label="mine").label == "mine"
    assert pm.preset("gill2017-apc").replace(M=30.0).label == "modified gill2017-apc"


def test_a_derivative_is_a_new_array_and_power_a_0d_one_like_the_others(apc):
    """derivative() returned the stored array: setting it to 0 changed every later call; the
    power's derivative of one point was a NumPy scalar where the others are 0-d arrays (a
    property-based audit)."""
    prop, params = apc
    r = pm.rotor_loads(prop, params, 800.0, 10.0, 1.0, derivatives=True)
    first = float(r.derivative("thrust", "omega"))
    d = r.derivative("thrust", "omega")
    d[...] = 0.0
    assert float(r.derivative("thrust", "omega")) == first != 0.0
    for q in ("thrust", "power"):
        assert isinstance(r.derivative(q, "airspeed"), np.ndarray) and r.derivative(q, "airspeed").shape == ()


@pytest.mark.parametrize("name, error, said", [
    (None, TypeError, r"name must be a propeller's name \(str\), got NoneType"),
    (5, TypeError, r"got int"),
    ("", ValueError, r"got an empty one"),
    ("  ", ValueError, r"got an empty one"),
])
def test_default_params_refuses_a_name_that_is_none(name, error, said):
    """default_params(None), (5) and ("") returned the generic set without a word (a
    property-based audit); a Propeller is named as such. Any other name still gets the generic set."""
    with pytest.raises(error, match=said):
        pm.default_params(name)
    with pytest.raises(TypeError, match=r"a Propeller: give its \.name"):
        pm.default_params(pm.load_propeller("apce_8x6"))
    assert pm.default_params("my_own_prop").label == "generic"


@pytest.mark.parametrize("call, error, said", [
    (lambda p: pm.resolve_params(None), TypeError, r"spec must be a set's name or a parameter file's path .*NoneType"),
    (lambda p: pm.resolve_params(5), TypeError, r"spec must be .*got int"),
    (lambda p: pm.read_params(None), TypeError, r"path must be a file path \(str or os.PathLike\), got NoneType"),
    # the parameter file's other readers named nothing (pathlib's own error; a review, 2026-11-29)
    (lambda p: read_body(None), TypeError, r"path must be a file path \(str or os.PathLike\), got NoneType"),
    (lambda p: read_coverage(3), TypeError, r"path must be a file path .*got int"),
    (lambda p: pm.read_geometry(None), TypeError, r"path must be a file path .*got NoneType"),
    (lambda p: pm.read_vehicle(5), TypeError, r"path must be a file path .*got int"),
    (lambda p: pm.rotor_like(None), TypeError, r"propeller must be a Propeller, got NoneType"),
    (lambda p: pm.lift_coefficient(0.1, None), TypeError, r"params must be AirfoilParams or CamberedParams"),
    # the two orders differ: a swapped call says so (a nomenclature audit, 2026-11-27)
    (lambda p: pm.drag_coefficient(0.1, pm.generic_params(), 1e5), TypeError,
     r"got float \(the orders are lift_coefficient\(alpha, params, reynolds\) and drag_coefficient\(alpha, reynolds, "
     r"params\)\)"),
    (lambda p: pm.lift_coefficient(0.1, 1e5, pm.generic_params()), TypeError, r"the orders are lift_coefficient"),
    (lambda p: pm.lift_coefficient("a", p), ValueError, r"alpha must be a number or an array of numbers, got 'a'"),
    (lambda p: pm.lift_coefficient(True, p), ValueError, r"alpha must be a number"),
    (lambda p: pm.lift_coefficient(np.nan, p), ValueError, r"alpha must be finite \[rad\] everywhere, got nan"),
    (lambda p: pm.lift_coefficient(0.1, p, mach=-1), ValueError, r"mach must be finite and >= 0 everywhere, got -1"),
    (lambda p: pm.lift_coefficient(0.1, p, reynolds=np.inf), ValueError, r"reynolds must be finite and > 0"),
    (lambda p: pm.lift_coefficient(0.1, p, reynolds="1e5"), ValueError, r"reynolds must be a number"),
    (lambda p: pm.drag_coefficient([0.1, 0.2], [1e5, 2e5, 3e5], p), ValueError,
     r"alpha, reynolds and mach must broadcast together, got shapes \(2,\), \(3,\), \(\)"),
])
def test_helpers_name_an_argument_of_the_wrong_type_or_value(apc, call, error, said, tmp_path):
    """Each was an AttributeError, pathlib's or NumPy's error naming nothing, or a silent NaN,
    or a negative Mach number read as 0.9's factor (a property-based audit)."""
    with pytest.raises(error, match=said):
        call(apc[1])
    pm.write_params(Path(tmp_path) / "g.toml", pm.generic_params())  # a Path is read as a parameter file
    assert pm.resolve_params(Path(tmp_path) / "g.toml").label.endswith("g.toml")


def test_radial_must_be_a_bool(apc):
    """radial='yes' was read as True (a property-based audit)."""
    prop, params = apc
    with pytest.raises(ValueError, match=r"radial must be True or False, got 'yes'"):
        pm.rotor_loads(prop, params, 800.0, 1.0, 1.0, radial="yes")
    assert pm.rotor_loads(prop, params, 800.0, 1.0, 1.0, radial=np.True_).v_i.shape == (48,)


from propmap.vehicle.model import hover_omega  # noqa: E402 (beside its test)


@pytest.mark.parametrize("call, said", [
    (lambda p: pm.trim_collective(p[0], None, 5.0, 800.0), r"^params must be AirfoilParams or CamberedParams"),
    (lambda p: pm.trim_collective(p[0], {"cl_alpha": 5.0}, 5.0, 800.0), r"^params must be .*got dict"),
    (lambda p: pm.trim_collective(p[0], "generic", 5.0, 800.0), r"^params must be .*resolve it with"),
    (lambda p: pm.trim_collective(p[0], p[1], 5.0, 800.0, air=1.2), r"^air must be a propmap.Air, got float"),
    (lambda p: hover_omega(pm.read_vehicle("quadrotor"), None), r"^params must be AirfoilParams"),
    (lambda p: pm.HoverModel.from_coefficients(0.1, 0.05, 0.2, air=1.2), r"^air must be a propmap.Air, got float"),
])
def test_a_parameter_set_of_the_wrong_type_is_named(apc, call, said):
    """Each was an AttributeError ("'NoneType' object has no attribute 'air'") from the line that
    takes the set's air (a docstring audit, 2026-11-27): core.solver.model_air checks it first."""
    with pytest.raises(TypeError, match=said):
        call(apc)


def test_validation_errors_refuse_an_unknown_model_or_run(apc):
    """``which`` other than "model" silently gave the hover model's errors, and run ids that name
    no run NumPy's "need at least one array to concatenate" (a docstring audit, 2026-11-27)."""
    from propmap.io.catalogue import get_entry
    from propmap.validation import validate
    v = validate(get_entry("apce_8x6"), apc[0], apc[1])
    with pytest.raises(ValueError, match=r"which must be 'model' or 'hover_model', got 'modle'"):
        v.summary("modle")
    with pytest.raises(ValueError, match=r"which must be 'model' or 'hover_model', got 'hover'"):
        v.runs[0].errors("hover")
    with pytest.raises(ValueError, match=r"run_ids \['2801'\] name no run of apce_8x6 \(its runs: .*2801rd"):
        v.summary("model", ["2801"])
    with pytest.raises(ValueError, match=r"run_ids \['2801'\] name no run"):  # beside a good one, not dropped
        v.summary("model", ["2801rd", "2801"])
    one = v.summary("model", "2801rd")  # one id as text is that run, not its characters
    assert one == v.summary("model", ["2801rd"])
    assert one["n_points"] == sum(r.CT.size for r in v.runs if r.run_id == "2801rd")
    assert v.summary("hover_model")["ct_rmse"] != v.summary("model")["ct_rmse"]


def test_read_only_strided_and_fortran_inputs_compile_nothing_more():
    """numba compiles a kernel once per array type, and a read-only, strided or Fortran-ordered array
    is another type: a user's such input (a memory-mapped log, a column of a state array) gave a
    compile of 0.2-1.6 s in the middle of a run (rotor_loads' range check of a strided array did,
    2026-11-28). rotor_loads, rotor_wrench, vehicle_wrench and hub_velocities, one point and batches, with
    such inputs add no compiled signature to any of propmap's kernels and give the same loads."""
    import sys

    import numba

    from propmap.vehicle import hub_velocities, read_vehicle, vehicle_wrench

    def signatures():
        return {f"{m}.{k}": len(f.signatures) for m in list(sys.modules) if m.startswith("propmap")
                for k, f in vars(sys.modules[m]).items() if isinstance(f, numba.core.registry.CPUDispatcher)}

    def frozen(a):
        a = np.array(a, dtype=float)
        a.flags.writeable = False
        return a

    def strided(a):
        s = np.zeros(np.shape(a) + (2,))
        s[..., 0] = a
        return s[..., 0]

    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    veh = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    om, V, b = np.full(4, 800.0), np.linspace(0.0, 10.0, 4), np.full(4, 0.7)
    vel, axis = np.array([[3.0, 0.5, -0.2]] * 4), np.array([0.0, 0.0, 1.0])
    w, rot = np.array([[0.1, 0.0, 0.2]] * 4), np.full((4, 4), 800.0)
    calls = (lambda f: pm.rotor_loads(prop, params, f(om), f(V), f(b)).thrust,
             lambda f: pm.rotor_loads(prop, params, f(om), f(V), f(b), derivatives=True).derivative("thrust", "omega"),
             lambda f: pm.rotor_wrench(prop, params, f(vel), f(axis), f(om)).force,
             lambda f: pm.rotor_wrench(prop, params, f(vel[0]), f(axis), 800.0).force,
             lambda f: vehicle_wrench(veh, params, f(vel), f(w), f(rot)).force,
             lambda f: vehicle_wrench(veh, params, f(vel[0]), f(w[0]), f(rot[0])).force,
             # (hub_velocities, which the fits, the flight scores and VehicleMap's batches call: a mutation audit's
             # K11, its contiguous, writeable copy removed, compiled its loop once more)
             lambda f: hub_velocities(f(vel), f(w), f(np.array([[0.1, 0.1, 0.0], [-0.1, 0.1, 0.02]])), wind=f(axis)))
    ref = [c(np.array) for c in calls]
    before = signatures()
    for make in (frozen, strided, np.asfortranarray):
        for c, r in zip(calls, ref):
            np.testing.assert_allclose(c(make), r, rtol=1e-14, atol=0.0)
    assert signatures() == before
