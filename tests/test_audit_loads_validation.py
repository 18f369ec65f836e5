"""Mutation audit (2026-11-29) of core/loads.py (RotorLoads' derived quantities, flags, summary and frame),
validation/loads.py (holdout_loads, load_errors) and validation/catalogue.py (coefficient_errors,
cross_validate): each test pins what a surviving hand-made mutant changed (named in its docstring).
apce_8x6 and grcp_10x8 of the bundled catalogue; synthetic load data made by the model itself.
"""

import dataclasses
import math

import numpy as np
import pytest

import propmap as pm
from propmap.identify import loads_from_catalogue
from propmap.identify.load_data import LoadData
from propmap.io.calibration import generic_params, population
from propmap.validation import coefficient_errors, cross_validate, holdout_loads, load_errors

COARSE = pm.Discretization(n_radial=12, n_azimuth=8)
RPM = 2 * math.pi / 60


@pytest.fixture(scope="module")
def two_points(apc8x6, apc_params):
    """Hover at 600 rad/s and 8 m/s at 60 deg incidence, 800 rad/s."""
    return pm.rotor_loads(apc8x6, apc_params, np.array([600.0, 800.0]), np.array([0.0, 8.0]),
                          np.radians([0.0, 60.0]))


def test_coefficients_power_and_advance_ratio_by_hand(two_points, apc8x6, apc_params):
    """Mutants L9-L12, L14-L18: P = Q Omega, n = Omega / 2 pi, CT = T/(rho n^2 D^4), CQ = Q/(rho n^2 D^5),
    CP = P/(rho n^3 D^5), J = V/(n D) with the total airspeed (not its axial part)."""
    r = two_points
    rho, D = apc_params.air.rho, apc8x6.diameter
    assert rho == 1.225 and D == pytest.approx(0.2032)
    n = np.array([600.0, 800.0]) / (2 * math.pi)
    np.testing.assert_allclose(r.power, r.torque * np.array([600.0, 800.0]), rtol=1e-14)
    np.testing.assert_allclose(r.CT, r.thrust / (rho * n**2 * D**4), rtol=1e-12)
    np.testing.assert_allclose(r.CQ, r.torque / (rho * n**2 * D**5), rtol=1e-12)
    np.testing.assert_allclose(r.CP, 2 * math.pi * r.CQ, rtol=1e-12)
    np.testing.assert_allclose(r.J, [0.0, 8.0 / (n[1] * D)], rtol=1e-12)
    assert float(r.J[1]) == pytest.approx(0.30919, abs=1e-4)  # 8 m/s at 7639 rpm on 8 in


def test_a_stopped_rotor_has_no_coefficients(two_points):
    """Mutant L13 (_per_n's b > 0 -> b >= 0): at Omega = 0 CT, CQ, CP and J are NaN, not the load itself."""
    r = dataclasses.replace(two_points, omega=np.array([0.0, 800.0]))
    for k in ("CT", "CQ", "CP", "J"):
        v = getattr(r, k)
        assert np.isnan(v[0]) and np.isfinite(v[1]), k


def test_flags_name_every_raised_flag_in_order_and_check_the_index(two_points):
    """Mutants L19-L22, L24: the flags' order, not_converged where the root failed (only there), the index's
    length checked; the summary says not_converged where one point of two failed."""
    r = dataclasses.replace(two_points, converged=np.array([False, True]), vortex_ring=np.array([True, False]),
                            multiple_roots=np.array([True, False]), reverse_flow=np.array([True, False]),
                            inflow_extrapolated=np.array([True, False]))
    assert r.flags(0) == ["not_converged", "vortex_ring", "multiple_roots", "reverse_flow", "inflow_extrapolated"]
    assert r.flags(1) == [] and r.flags((1,)) == []
    for index in ((0, 0), ()):
        with pytest.raises(IndexError, match="one integer per axis"):
            r.flags(index)
    assert repr(r).endswith("flags raised: not_converged, vortex_ring, multiple_roots, reverse_flow, "
                            "inflow_extrapolated)")
    assert "flags raised: none" in repr(two_points)


def test_one_points_flags_take_0_and_minus_1(apc8x6, apc_params):
    """Mutant L20 (index in (0, -1) -> (0,)): on scalar loads -1 is the point, 1 is refused."""
    r = pm.rotor_loads(apc8x6, apc_params, 600.0, 5.0, 0.3)
    assert r.flags(-1) == r.flags(0) == r.flags() == []
    with pytest.raises(IndexError, match="give \\(\\) or 0"):
        r.flags(1)


def test_the_summary_gives_one_value_or_a_range(apc8x6, apc_params, two_points):
    """Mutant L23 (lo == hi -> lo != hi): one point shows its thrust, a batch 'lo to hi'."""
    one = pm.rotor_loads(apc8x6, apc_params, 600.0, 0.0, 0.0)
    assert f"thrust {float(one.thrust):.4g} N," in repr(one)
    lo, hi = float(two_points.thrust.min()), float(two_points.thrust.max())
    assert f"thrust {lo:.4g} to {hi:.4g} N," in repr(two_points)


def test_the_frame_keeps_the_diameter_units_and_state_names(two_points, apc8x6):
    """Mutants L25-L27: DataFrame.attrs' diameter [m], power's unit W, the state's name (normal working)."""
    f = two_points.to_dataframe()
    assert f.attrs["diameter"] == apc8x6.diameter and f.attrs["rho"] == 1.225
    assert f.attrs["units"]["power"] == "W" and f.attrs["units"]["torque"] == "N m"
    assert list(f["state"]) == ["normal working", "normal working"]
    np.testing.assert_allclose(f["power"], two_points.power, rtol=0)


# --- validation/loads.py -----------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def made(apc8x6, apc_params):
    """Two static points, two trained and four held-out points at incidence, loads made by the model."""
    om = np.array([5000, 7000, 5000, 7000, 6000, 6000, 6000, 6000.0]) * RPM
    V = np.array([0, 0, 4, 6, 5, 8, 5, 8.0])
    b = np.radians([0, 0, 30, 60, 45, 90, 45, 90.0])
    return om, V, b, pm.rotor_loads(apc8x6, apc_params, om, V, b)


def test_holdout_loads_errors_are_the_held_out_offsets_over_the_static_loads(made, apc8x6, apc_params):
    """Mutants V1, V4, V6, V7: a fit of exact training data (from the set that made them) predicts the model's loads,
    so the held-out errors are the offsets added to the measurements: rms over the mean static thrust (thrust and
    in-plane force) and torque; n_points counts points, not folds."""
    om, V, b, r = made
    d = np.array([0, 0, 0, 0, 1, -1, 1, -1.0])
    dd = 0.02 * d * np.array([0, 0, 0, 0, 1, 1, 3, 3])
    data = LoadData(om, V, b, {"thrust": r.thrust + 0.1 * d, "drag": r.drag + dd, "torque": r.torque + 0.001 * d},
                    np.array(["s"] * 2 + ["a"] * 6))
    e = holdout_loads(data, apc8x6, apc_params, [d == 0], names=("cd",))
    T0, Q0 = float(r.thrust[:2].mean()), float(r.torque[:2].mean())
    assert T0 == pytest.approx(2.6116, abs=1e-3)
    assert e["rms_thrust"] == pytest.approx(0.1 / T0, rel=1e-6)
    assert e["rms_drag"] == pytest.approx(0.02 * math.sqrt(5) / T0, rel=1e-6)
    assert e["rms_torque"] == pytest.approx(0.001 / Q0, rel=1e-6)
    assert e["n_points"] == 4 and e["flap_compliance"] == [0.0]


def test_holdout_loads_refuses_data_without_static_points_and_a_fold_without_training(made, apc8x6, apc_params):
    """Mutants V2, V3: no static point (no scale) and a fold that trains on nothing are refused."""
    om, V, b, r = made
    meas = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque}
    moving = LoadData(om[2:], V[2:], b[2:], {k: v[2:] for k, v in meas.items()}, np.array(["a"] * 6))
    with pytest.raises(ValueError, match="missing static points"):
        holdout_loads(moving, apc8x6, apc_params, [np.arange(6) < 3], names=("cd",))
    data = LoadData(om, V, b, meas, np.array(["a"] * 8))
    with pytest.raises(ValueError, match="every fold needs training and held-out points"):
        holdout_loads(data, apc8x6, apc_params, [np.zeros(8, bool)], names=("cd",))


def test_load_errors_by_hand(made, apc8x6, apc_params):
    """Mutants V14-V16, V19: the errors in units of the mean static CT: rms, bias (model - measured), max (the
    largest magnitude, of a negative error here), rms_si in newtons; one group gives no groups."""
    om, V, b, r = made
    f = np.array([0, 0, 0.02, 0.06, 0.01, 0.0, -0.01, 0.03])  # measured = model (1 + f)
    data = LoadData(om, V, b, {"thrust": r.thrust * (1 + f)}, np.array(["a"] * 8))
    e = load_errors(data, apc8x6, apc_params)
    n = om / (2 * math.pi)
    scale = 1.225 * n**2 * apc8x6.diameter**4
    ref = float(np.mean(r.thrust[:2] / scale[:2]))
    err = -f * r.thrust / scale / ref
    t = e["overall"]["thrust"]
    assert e["reference"]["thrust"] == ("mean static CT", pytest.approx(ref, rel=1e-12))
    assert t["rms"] == pytest.approx(math.sqrt(np.mean(err**2)), rel=1e-9)
    assert t["bias"] == pytest.approx(np.mean(err), rel=1e-9) and t["bias"] == pytest.approx(-0.013406, abs=1e-5)
    assert t["max"] == pytest.approx(np.max(np.abs(err)), rel=1e-9) and np.argmax(np.abs(err)) == 3 and err[3] < 0
    assert t["rms_si"] == pytest.approx(math.sqrt(np.mean((f * r.thrust) ** 2)), rel=1e-9)
    assert t["n"] == 8 and e["groups"] == {} and e["states"] == {} and e["converged"] == 8


def test_load_errors_reference_is_the_static_ct_and_cq_up_to_0_3_m_s(apc8x6, apc_params):
    """Mutants V9, V11: the references are the mean measured CT = T/(rho n^2 D^4) and CQ = Q/(rho n^2 D^5) of the
    points at an airspeed up to 0.3 m/s (0 and 0.2 m/s here), not of those at exactly 0 only."""
    om = np.array([5000, 6000, 6000, 6000.0]) * RPM
    V = np.array([0.0, 0.2, 5.0, 8.0])
    r = pm.rotor_loads(apc8x6, apc_params, om, V, np.zeros(4))
    T, Q = r.thrust * np.array([1, 1.1, 1, 1.02]), r.torque * np.array([1.05, 1, 1.01, 1])
    e = load_errors(LoadData(om, V, np.zeros(4), {"thrust": T, "torque": Q}, np.array(["a"] * 4)),
                    apc8x6, apc_params)
    n, D = om / (2 * math.pi), apc8x6.diameter
    CT, CQ = T / (1.225 * n**2 * D**4), Q / (1.225 * n**2 * D**5)
    assert e["reference"]["thrust"] == ("mean static CT", pytest.approx(CT[:2].mean(), rel=1e-12))
    assert e["reference"]["torque"] == ("mean static CQ", pytest.approx(CQ[:2].mean(), rel=1e-12))
    assert CQ[:2].mean() == pytest.approx(0.01008, abs=2e-4)  # (CP = 2 pi CQ = 0.063, UIUC-like)
    dq = (r.torque - Q) / (1.225 * n**2 * D**5) / CQ[:2].mean()
    assert e["overall"]["torque"]["rms"] == pytest.approx(math.sqrt(np.mean(dq**2)), rel=1e-9)


def test_load_errors_refuse_a_zero_reference(made, apc8x6, apc_params):
    """Mutant V13 (value != 0 dropped): a measured static thrust of zero gives no reference (not inf errors)."""
    om, V, b, r = made
    data = LoadData(om[:2], V[:2], b[:2], {"thrust": np.zeros(2)}, np.array(["a"] * 2))
    with pytest.raises(ValueError, match="mean static CT is 0: no reference for the thrust errors"):
        load_errors(data, apc8x6, apc_params)


# --- validation/catalogue.py -------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def uiuc():
    """apce_8x6 and grcp_10x8: (propeller, load data) of the bundled catalogue."""
    out = {}
    for name in ("apce_8x6", "grcp_10x8"):
        prop = pm.load_propeller(name)
        out[name] = prop, loads_from_catalogue(pm.catalogue()[name], prop.diameter)
    return out


@pytest.mark.parametrize("name", ["apce_8x6", "grcp_10x8"])
def test_coefficient_errors_cp_by_hand(uiuc, name):
    """Mutants C1, C2, C3, C5: measured CP = 2 pi Q / (rho n^2 D^5), n = Omega / 2 pi, normalised by the static
    points' mean measured CP (CT by its own), a few sweep points at a coarse discretization."""
    prop, data = uiuc[name]
    g = generic_params()
    static = data.airspeed == 0
    mask = ~static & (np.cumsum(~static) % 9 == 1)
    ce = coefficient_errors(data, prop, g, mask=mask, discretization=COARSE)
    n = data.omega / (2 * math.pi)
    D, rho = prop.diameter, g.air.rho
    CP = data.measured["torque"] * n * 2 * math.pi / (rho * n**3 * D**5)
    CT = data.measured["thrust"] / (rho * n**2 * D**4)
    r = pm.rotor_loads(prop, g, data.omega[mask], data.airspeed[mask], data.incidence[mask], discretization=COARSE)
    dcp = (r.CP - CP[mask]) / CP[static].mean()
    dct = (r.CT - CT[mask]) / CT[static].mean()
    assert ce["n_points"] == int(mask.sum()) >= 5
    assert ce["rms_cp"] == pytest.approx(math.sqrt(np.mean(dcp**2)), rel=1e-9)
    assert ce["bias_cp"] == pytest.approx(np.mean(dcp), rel=1e-9)
    assert ce["rms_ct"] == pytest.approx(math.sqrt(np.mean(dct**2)), rel=1e-9)


def test_coefficient_errors_refuse_no_static_point_and_an_empty_mask(uiuc):
    """Mutants C4, C6: without static points there is no normalisation; a mask selecting nothing is refused."""
    prop, data = uiuc["apce_8x6"]
    g = generic_params()
    with pytest.raises(ValueError, match="needs static points"):
        coefficient_errors(data.subset(data.airspeed > 0), prop, g, discretization=COARSE)
    with pytest.raises(ValueError, match="the mask selects no point"):
        coefficient_errors(data, prop, g, mask=np.zeros(data.n, bool), discretization=COARSE)


def test_cross_validate_refuses_an_unknown_protocol_and_predicts_at_its_discretization(uiuc):
    """Mutants C11, C16: an unknown protocol is named (not run as blind); the blind prediction uses the
    discretization given (coarse: equal to coefficient_errors' at it, not at the default 48 x 16)."""
    prop, data = uiuc["grcp_10x8"]
    g = generic_params()
    with pytest.raises(ValueError, match="unknown protocol\\(s\\) nope; valid: loso, loro"):
        cross_validate(data, prop, g, protocols=("blind", "nope"))
    cv = cross_validate(data, prop, g, protocols=("blind",), discretization=COARSE)["blind"]
    ce = coefficient_errors(data, prop, g, mask=data.airspeed > 0, discretization=COARSE)
    fine = coefficient_errors(data, prop, g, mask=data.airspeed > 0)
    assert abs(fine["rms_ct"] - ce["rms_ct"]) > 1e-4  # (the test can tell the two discretizations apart)
    for k in ("rms_ct", "rms_cp", "bias_ct", "bias_cp"):
        assert cv[k] == pytest.approx(ce[k], rel=1e-12), k


def test_cross_validate_fits_under_the_population_given(uiuc):
    """Mutant C15 (the fits' population dropped: the shipped one): under a prior a million times tighter than
    the shipped population's the static-run fit stays at the generic set, so the static protocol scores as the
    blind one (with the shipped prior it moves: rms CT 0.122 against 0.095)."""
    prop, data = uiuc["apce_8x6"]
    g = generic_params()
    pop = population()
    tight = dict(pop, covariance=np.asarray(pop["covariance"]) * 1e-6)
    cv = cross_validate(data, prop, g, protocols=("static", "blind"), population=tight, discretization=COARSE)
    assert cv["static"]["n_fits"] == 1 and cv["blind"]["n_fits"] == 0
    assert cv["blind"]["rms_ct"] == pytest.approx(0.09518, abs=1e-4)
    for k in ("rms_ct", "rms_cp", "bias_ct", "bias_cp"):
        assert cv["static"][k] == pytest.approx(cv["blind"][k], abs=1e-4), k


# --- a load not measured at a point (LoadData's NaN) ---------------------------------------------------------------

def test_holdout_loads_leaves_a_load_not_measured_out_of_its_figure(made, apc8x6, apc_params):
    """A defect the audit found (2026-11-29): a NaN in ``measured`` ("not measured at that point",
    LoadData's convention, which load_errors follows) made holdout_loads' rms NaN. Exact data from
    the set that made them, one held-out in-plane force not measured: every figure is ~0; measured
    at no held-out point: None; static torque not measured: no normalisation, refused."""
    om, V, b, r = made
    drag = r.drag.copy()
    drag[5] = np.nan
    data = LoadData(om, V, b, {"thrust": r.thrust, "drag": drag, "torque": r.torque}, np.array(["a"] * 8))
    e = holdout_loads(data, apc8x6, apc_params, [np.arange(8) < 4], names=("cd",))
    assert e["n_points"] == 4
    for k in ("rms_thrust", "rms_drag", "rms_torque"):
        assert e[k] is not None and 0.0 <= e[k] < 1e-9, (k, e[k])
    unmeasured = LoadData(om, V, b, {"thrust": r.thrust, "drag": np.where(np.arange(8) < 4, r.drag, np.nan),
                                     "torque": r.torque}, np.array(["a"] * 8))
    assert holdout_loads(unmeasured, apc8x6, apc_params, [np.arange(8) < 4], names=("cd",))["rms_drag"] is None
    no_static_torque = LoadData(om, V, b, {"thrust": r.thrust, "drag": r.drag,
                                           "torque": np.where(V == 0, np.nan, r.torque)}, np.array(["a"] * 8))
    with pytest.raises(ValueError, match="static points with thrust and torque measured"):
        holdout_loads(no_static_torque, apc8x6, apc_params, [np.arange(8) < 4], names=("cd",))


def test_cross_validate_leaves_a_load_not_measured_out_as_coefficient_errors_does(uiuc):
    """The same defect in cross_validate: one sweep torque not measured gave rms_cp NaN, where
    coefficient_errors (which the blind protocol equals, docs/validation.md) leaves it out. A load
    measured at no point (a thrust-only stand) gives None; one measured but at no static point
    cannot be normalised and is refused."""
    prop, data = uiuc["grcp_10x8"]
    g = generic_params()
    Q = data.measured["torque"].copy()
    Q[np.flatnonzero(data.airspeed > 0)[0]] = np.nan
    one = LoadData(data.omega, data.airspeed, data.incidence, {"thrust": data.measured["thrust"], "torque": Q},
                   data.group)
    cv = cross_validate(one, prop, g, protocols=("blind",), discretization=COARSE)["blind"]
    ce = coefficient_errors(one, prop, g, mask=one.airspeed > 0, discretization=COARSE)
    assert cv["n_points"] == ce["n_points"] == int(np.sum(data.airspeed > 0))
    for k in ("rms_ct", "rms_cp", "bias_ct", "bias_cp"):
        assert cv[k] is not None and math.isfinite(cv[k]) and cv[k] == pytest.approx(ce[k], rel=1e-12), k
    thrust_only = LoadData(data.omega, data.airspeed, data.incidence, {"thrust": data.measured["thrust"]}, data.group)
    ce = coefficient_errors(thrust_only, prop, g, mask=data.airspeed > 0, discretization=COARSE)
    assert ce["rms_cp"] is None and ce["bias_cp"] is None and ce["rms_ct"] > 0.01
    sweeps_only = LoadData(data.omega, data.airspeed, data.incidence,
                           {"thrust": data.measured["thrust"], "torque": np.where(data.airspeed == 0, np.nan, Q)},
                           data.group)
    with pytest.raises(ValueError, match="no static point \\(airspeed up to 0.3 m/s\\) has torque measured"):
        cross_validate(sweeps_only, prop, g, protocols=("blind",), discretization=COARSE)
    zero_static = LoadData(data.omega, data.airspeed, data.incidence,
                           {"thrust": np.where(data.airspeed == 0, 0.0, data.measured["thrust"]), "torque": Q},
                           data.group)
    with pytest.raises(ValueError, match="the mean static thrust coefficient is 0"):
        coefficient_errors(zero_static, prop, g, mask=data.airspeed > 0, discretization=COARSE)
