"""A mutation audit of validation/loads, cases, vehicle/_kinematics, io/uncertainty and
identify/sanity (stop 87, 2026-11-30, a helper session: 58 mutants, 26 surviving the suite, 21 of
them changing what a user sees; each test below fails on its mutant, three re-checked by hand):

- load_errors: the in-plane force in units of the mean static CT beside a measured thrust, an
  unconverged point left out even with finite loads, and out of the state table; holdout_loads
  refuses a fold with nothing held out;
- multinomial_fit's torque coefficients k6-k8 against an independent least-squares solve; the
  gill2019 case's ratio minima and maxima over every propeller, its torque rise as the model's;
- hub_velocities refuses a scalar or a 3-d velocity by name;
- model_uncertainty: a user's file named like a shipped set (generic_fit.toml) is a parameter
  file; a calibrated set's sentence states its CP error;
- sanity_check's unit-slip, column-swap, blade-count, pole-pair, drag-sign and airspeed-unit
  thresholds at their edges (the messages a user reads when the data are off).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import propmap as pm
from propmap.identify.load_data import LoadData

from .conftest import RPM


@pytest.fixture(scope="module")
def apc():
    return pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")


@pytest.fixture(scope="module")
def made(apc):
    prop, params = apc
    om = np.array([5000, 7000, 5000, 7000, 6000, 6000, 6000, 6000.0]) * RPM
    V = np.array([0, 0, 4, 6, 5, 8, 5, 8.0])
    b = np.radians([0, 0, 30, 60, 45, 90, 45, 90.0])
    return om, V, b, pm.rotor_loads(prop, params, om, V, b)


# --- validation/loads.py ---------------------------------------------------------------------------------------------

def test_load_errors_drag_beside_thrust_is_in_units_of_the_mean_static_ct(made, apc):
    """Mutant L1 (drag's reference taken as its own rms coefficient when thrust is measured): the in-plane force is
    scored in units of the mean static CT, as the docstring and catalogue metric say."""
    from propmap.validation import load_errors
    prop, params = apc
    om, V, b, r = made
    f = np.array([0, 0, 0.05, -0.02, 0.03, 0.01, -0.04, 0.02])
    data = LoadData(om, V, b, {"thrust": r.thrust, "drag": r.drag * (1 + f)}, np.array(["a"] * 8))
    e = load_errors(data, prop, params)
    n = om / (2 * math.pi)
    scale = 1.225 * n**2 * prop.diameter**4
    ct0 = float(np.mean(r.thrust[:2] / scale[:2]))
    assert e["reference"]["drag"] == ("mean static CT", pytest.approx(ct0, rel=1e-12))
    inpl = V * np.abs(np.sin(b)) > 0.3
    err = (-f * r.drag / scale / ct0)[inpl]
    assert e["overall"]["drag"]["n"] == 6
    assert e["overall"]["drag"]["rms"] == pytest.approx(math.sqrt(np.mean(err**2)), rel=1e-9)


def test_load_errors_leave_out_an_unconverged_point_even_with_finite_loads(made, apc, monkeypatch):
    """Mutant L2 (convergence flag ignored): a point the solver flags unconverged is left out of every figure,
    even where its loads are finite."""
    from propmap.validation import loads as validation
    prop, params = apc
    om, V, b, r = made
    data = LoadData(om, V, b, {"thrust": r.thrust * 1.0}, np.array(["a"] * 8))
    real = validation.rotor_loads

    def flagged(*args, **kwargs):
        out = real(*args, **kwargs)
        out.converged[3] = False
        out.thrust[3] = out.thrust[3] * 2.0  # (a finite but wrong value)
        return out

    monkeypatch.setattr(validation, "rotor_loads", flagged)
    e = validation.load_errors(data, prop, params)
    assert e["converged"] == 7
    assert e["overall"]["thrust"]["n"] == 7 and e["overall"]["thrust"]["rms"] < 1e-9


def test_holdout_loads_refuses_a_fold_with_nothing_held_out(made, apc):
    """Mutant L3 (only an empty training set refused): a fold that trains on every point has nothing to predict."""
    from propmap.validation import holdout_loads
    prop, params = apc
    om, V, b, r = made
    data = LoadData(om, V, b, {"thrust": r.thrust, "drag": r.drag, "torque": r.torque}, np.array(["a"] * 8))
    with pytest.raises(ValueError, match="every fold needs training and held-out points"):
        holdout_loads(data, prop, params, [np.ones(8, bool)], names=("cd",))


# --- cases.py --------------------------------------------------------------------------------------------------------

def test_multinomial_fit_torque_coefficients_are_the_least_squares_of_the_models_torque():
    """Mutants C1 (mu for mu^2 in the torque fit), C2 (lambda_c and lambda_c^2 swapped): k6-k8 are the least-squares
    fit C_MQ = CQ_static + k6 lambda_c + k7 mu^2 + k8 lambda_c^2 of the model's torque / (q R) on the static point and
    the advance-ratio x incidence grid, checked by an independent NumPy solve and by the residual's orthogonality."""
    from propmap.cases import GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, multinomial_fit
    prop, p = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    om, R, air = 600.0, prop.radius, pm.Air()
    f = multinomial_fit(prop, p, om)
    adv = np.r_[0.0, np.repeat(np.asarray(GILL2019_ADVANCE, float)[None, :], len(GILL2019_INCIDENCE_DEG), 0).ravel()]
    inc = np.r_[0.0, np.repeat(np.radians(GILL2019_INCIDENCE_DEG)[:, None], len(GILL2019_ADVANCE), 1).ravel()]
    r = pm.rotor_loads(prop, p, om, adv * om * R, inc, air=air)
    q = 0.5 * air.rho * math.pi * R**2 * (om * R) ** 2
    mu, lam = adv * np.sin(inc), adv * np.cos(inc)
    A = np.column_stack([np.ones_like(mu), lam, mu**2, lam**2])
    y = r.torque / (q * R)
    k = np.linalg.solve(A.T @ A, A.T @ y)  # (the normal equations)
    got = np.array([f["CQ_static"], f["k6"], f["k7"], f["k8"]])
    np.testing.assert_allclose(got, k, rtol=1e-6, atol=1e-12)
    assert np.max(np.abs(A.T @ (y - A @ got))) < 1e-9 * np.max(np.abs(A.T @ y))
    assert f["k7"] > 0  # (the torque rises edgewise)


@pytest.fixture(scope="module")
def gill_case():
    from propmap.cases import run_case
    g = pm.generic_params()
    # "mix": the last propeller without the in-plane induction, so that its H slope ratio is the lowest (0.51)
    return run_case("gill2019", {"g": g, "mix": lambda n: g.replace(inplane_induction=False) if n == "apcsf_10x4.7"
                                 else g})


def test_gill2019_ratio_min_and_max_span_every_propeller_and_quantity(gill_case):
    """Mutant C8 (the last propeller left out of the min): each quantity's ratio_min/ratio_max are the min/max of its
    per-propeller ratios, which are predicted / published."""
    from propmap.cases import GILL2019_QUANTITIES, gill2019_coefficients
    names = list(gill2019_coefficients())
    for label in ("g", "mix"):
        m = gill_case.metrics[label]
        for qn in GILL2019_QUANTITIES:
            ratios = np.array([m[f"{qn}_ratio_{n}"] for n in names])
            np.testing.assert_allclose(ratios, gill_case.predicted[label][qn] / gill_case.measured[qn], rtol=1e-12)
            assert m[f"{qn}_ratio_min"] == ratios.min() and m[f"{qn}_ratio_max"] == ratios.max(), (label, qn)
    assert np.argmin([gill_case.metrics["mix"][f"H_slope_ratio_{n}"] for n in names]) == 3


def test_gill2019_torque_rise_is_the_models_edgewise_torque_over_static(gill_case):
    """Mutant C9 (the model's torque rise scaled): torque_rise = Q(mu = 0.2, edgewise) / Q(static) - 1 at 6000 rpm,
    per propeller."""
    from propmap.cases import gill2019_coefficients
    for k, name in enumerate(gill2019_coefficients()):
        prop = pm.load_propeller(name)
        om = 6000 * math.pi / 30
        r = pm.rotor_loads(prop, pm.generic_params(), om, np.array([0.0, 0.2 * om * prop.radius]),
                           np.array([0.0, math.pi / 2]), air=pm.Air())
        assert gill_case.predicted["g"]["torque_rise"][k] == pytest.approx(r.torque[1] / r.torque[0] - 1, rel=1e-9)


# --- vehicle/_kinematics.py ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("bad", [5.0, np.zeros((2, 3, 3))])
def test_hub_velocities_refuse_a_scalar_or_a_3d_velocity_by_name(bad):
    """Mutant K12 (the ndim test dropped from _samples): a scalar or a (2, 3, 3) velocity is refused with the
    documented ValueError naming the input and its shape, not an IndexError or a numba typing error."""
    from propmap.vehicle._kinematics import hub_velocities
    with pytest.raises(ValueError, match=r"velocity must have shape \(N, 3\) or \(3,\), got"):
        hub_velocities(bad, np.zeros(3), np.eye(3))


# --- io/uncertainty.py -----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("label", ["generic_fit.toml", "gill_tunnel.toml", "sections.toml"])
def test_a_parameter_file_named_like_a_shipped_kind_is_a_parameter_file(label):
    """Mutants U1 (startswith("generic")), U7 (startswith("gill")), U8 (startswith("section")): a user's parameter
    file whose name merely begins like a shipped set's label is a parameter file, with no cross-validated figure."""
    from propmap.io.uncertainty import OFF_AXIS, model_uncertainty
    u = model_uncertainty(label)
    assert u["axial"].startswith("a parameter file") and "axial_ct" not in u and u["off_axis"] == OFF_AXIS


def test_a_calibrated_sets_sentence_states_its_cp_error():
    """Mutant U4 (the CP figures left out of the sentence): a calibrated set's axial sentence gives CP's cross-validated
    median / 90th percentile / worst, 2.8 / 4.3 / 13.0% (docs/validation.md), beside CT's."""
    from propmap.io.uncertainty import model_uncertainty
    u = model_uncertainty("calibrated:apce_8x6")
    assert "rms CT error 2.5 / 4.9 / 11.0% of static CT (median / 90th percentile / worst), CP 2.8 / 4.3 / 13.0%" \
        in u["axial"]
    assert u["axial_cp"] == [0.028, 0.043, 0.130]


def test_load_errors_state_table_leaves_out_a_state_met_only_at_unconverged_points(monkeypatch):
    """Mutant L7 (the state table built from every point, converged or not): a state the model reaches only at points
    the solver flags unconverged gets no row (its row had n = 0 and None figures)."""
    from propmap.validation import loads as validation
    prop, params = pm.load_propeller("apce_10x7"), pm.default_params("apce_10x7")
    V = np.linspace(0.0, 14.0, 29)
    om = np.full(V.size, 5000 * math.pi / 30)
    inc = np.where(V > 0, math.pi, 0.0)
    r0 = pm.rotor_loads(prop, params, om, V, inc)
    assert {"vortex ring", "windmill brake"} <= set(r0.state_name)
    brake = r0.state_name == "windmill brake"
    data = LoadData(om, V, inc, {"thrust": r0.thrust, "torque": r0.torque}, np.array(["d"] * V.size, dtype=object))
    real = validation.rotor_loads

    def flagged(*args, **kwargs):
        out = real(*args, **kwargs)
        out.converged[brake] = False  # (finite loads, flagged)
        return out

    monkeypatch.setattr(validation, "rotor_loads", flagged)
    e = validation.load_errors(data, prop, params)
    assert "windmill brake" not in e["states"] and "vortex ring" in e["states"]
    assert sum(row["thrust"]["n"] for row in e["states"].values()) == V.size - int(brake.sum())


# --- identify/sanity.py ----------------------------------------------------------------------------------------------

def _generic_loads(prop, om, V, inc):
    return pm.rotor_loads(prop, pm.generic_params(), om, V, inc)


def test_sanity_a_thrust_5_5_times_the_model_is_not_blamed_on_kgf():
    """Mutant S8 (a unit slip's window widened from 0.6-1.6x to 0.5-2x): a thrust 5.5 times the model's, the torque
    as modelled, is refused without naming 'thrust in N declared as kgf' (5.5 / 9.81 = 0.56, outside 0.6-1.6x)."""
    from propmap.identify.csvfile import DataError
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_10x7")
    om = np.array([4000, 5000, 6000, 7000.0]) * RPM
    r = _generic_loads(prop, om, np.zeros(4), np.zeros(4))
    data = LoadData(om, np.zeros(4), np.zeros(4), {"thrust": 5.5 * r.thrust, "torque": r.torque.copy()},
                    np.array(["a"] * 4))
    with pytest.raises(DataError, match="thrust 5.5 times") as exc:
        sanity_check(data, prop)
    assert "declared as kgf" not in str(exc.value)


def test_sanity_a_drag_of_the_other_sign_at_85_percent_of_points_is_warned_of():
    """Mutant S3 (the warning's share raised from 0.8 to 0.9): an unfitted in-plane force of the other sign than the
    model's at 17 of 20 points at incidence (85%) is warned of, naming the count."""
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_10x7")
    om = np.full(20, 6000 * RPM)
    V = np.linspace(3.0, 12.0, 20)
    inc = np.full(20, math.radians(60))
    r = _generic_loads(prop, om, V, inc)
    drag = r.drag * np.where(np.arange(20) < 17, -1.0, 1.0)
    data = LoadData(om, V, inc, {"thrust": r.thrust, "torque": r.torque, "drag": drag}, np.array(["a"] * 20))
    said = sanity_check(data, prop, quantities=("thrust", "torque"))
    sure = np.abs(r.drag) > 0.1 * np.max(np.abs(r.drag))
    assert sure.all()  # (every point's in-plane force is well away from 0)
    assert any("other sign than the model's in-plane force at 17 of 20 points" in w for w in said), said


def test_sanity_a_drag_in_axial_flow_at_a_minority_of_points_is_not_warned_of():
    """Mutant S4 ('at most points' dropped): a drag above 5% of the thrust at 3 of 10 axial points (a minority) is
    not warned of; at 6 of 10 it is."""
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_10x7")
    om = np.linspace(4000, 7000, 10) * RPM
    r = _generic_loads(prop, om, np.zeros(10), np.zeros(10))
    for n_large, warned in ((3, False), (6, True)):
        drag = np.where(np.arange(10) < n_large, 0.2 * r.thrust, 0.0)
        data = LoadData(om, np.zeros(10), np.zeros(10), {"thrust": r.thrust, "torque": r.torque, "drag": drag},
                        np.array(["a"] * 10))
        said = sanity_check(data, prop, quantities=("thrust", "torque"))
        assert any(f"5% of the thrust at {n_large} of 10 points in axial flow" in w for w in said) == warned, said


def test_sanity_a_two_blade_propellers_data_made_with_one_blade_suggest_one_blade():
    """Mutant S15 (blade counts below 2 not tried): the loads of a 1-blade version of a 2-blade propeller are warned
    of as a moderate mismatch, and '1 blade would give' the data (the model's own loads: 1.00/1.00x)."""
    from dataclasses import replace
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_10x7")
    assert prop.n_blades == 2
    om = np.linspace(4000, 7000, 6) * RPM
    r = _generic_loads(replace(prop, n_blades=1), om, np.zeros(6), np.zeros(6))
    data = LoadData(om, np.zeros(6), np.zeros(6), {"thrust": r.thrust, "torque": r.torque}, np.array(["a"] * 6))
    said = sanity_check(data, prop)
    assert any("1 blade would give 1.00/1.00x" in w for w in said), said


def test_sanity_columns_14_times_off_are_not_called_swapped():
    """Mutant S9 (the swap window widened from 12x to 30x): a thrust column holding 14 times the model's torque (0.29
    of its thrust: T/Q is 48 here) and a torque column holding the model's thrust is refused, but not as 'columns
    swapped' (14x is beyond a unit slip's 12x); at 5x it is."""
    from propmap.identify.csvfile import DataError
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_10x7")
    om = np.linspace(4000, 7000, 6) * RPM
    r = _generic_loads(prop, om, np.zeros(6), np.zeros(6))
    data = LoadData(om, np.zeros(6), np.zeros(6), {"thrust": 14 * r.torque, "torque": r.thrust.copy()},
                    np.array(["a"] * 6))
    with pytest.raises(DataError) as exc:
        sanity_check(data, prop)
    assert float(np.median(14 * r.torque / r.thrust)) < 1 / 3  # (the thrust is refused as too small)
    assert "thrust 0.29" in str(exc.value) and "swapped" not in str(exc.value)
    data = LoadData(om, np.zeros(6), np.zeros(6), {"thrust": 5 * r.torque, "torque": r.thrust.copy()},
                    np.array(["a"] * 6))
    with pytest.raises(DataError, match="columns swapped"):  # (5x: within a unit slip of its own)
        sanity_check(data, prop)


def test_sanity_an_airspeed_in_mph_at_two_moving_points_is_not_judged():
    """Mutant S2 (two moving points taken as enough): the airspeed unit is judged at 3 moving points or more; at two
    nothing is said, at three the mph slip is."""
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_9x6")
    for V, said_mph in (((0.0, 0.0, 6.0, 12.0), False), ((0.0, 0.0, 4.0, 8.0, 12.0), True)):
        V = np.array(V)
        om = np.full(V.size, 6000.0 * RPM)
        r = _generic_loads(prop, om, V, np.zeros(V.size))
        data = LoadData(om, V / 0.44704, np.zeros(V.size), {"thrust": r.thrust, "torque": r.torque},
                        np.array(["a"] * V.size))
        said = sanity_check(data, prop)
        assert any("airspeed read as mph" in w for w in said) == said_mph, said


def test_sanity_an_electrical_rpm_of_14_pole_pairs_names_14():
    """Mutant S7 (pole-pair counts tried up to 13): data whose rpm is a 14-pole-pair motor's electrical speed are
    refused naming a range of counts that includes the true 14 (neighbours 12-13 lie within the model's 1.6x)."""
    from propmap.identify.csvfile import DataError
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_10x7")
    om = np.linspace(2000, 3000, 6) * RPM
    r = _generic_loads(prop, om, np.zeros(6), np.zeros(6))
    data = LoadData(14 * om, np.zeros(6), np.zeros(6), {"thrust": r.thrust, "torque": r.torque}, np.array(["a"] * 6))
    with pytest.raises(DataError, match=r"likely the electrical rpm of a motor with 12-14 pole pairs"):
        sanity_check(data, prop)


def test_sanity_an_airspeed_1_4_times_m_per_s_is_not_called_knots():
    """Mutant S1 (a unit named where it halves the misfit -> where it cuts it by a fifth): an airspeed 1.4 times the
    true m/s (no listed unit: knots would be 1.94x, mph 2.24x) is not said to be in knots; the same data in mph
    (2.237x) are said to be. (Which side of the threshold 1.4x falls is a regression value, 2026-11-30: knots then
    cuts the m/s misfit by more than a fifth but less than half.)"""
    from propmap.identify.sanity import sanity_check
    prop = pm.load_propeller("apce_9x6")
    V = np.array([0, 0, 3, 6, 9, 12.0])
    om = np.full(6, 6000 * RPM)
    r = _generic_loads(prop, om, V, np.zeros(6))
    for c, unit in ((1.4, None), (1 / 0.44704, "mph")):
        data = LoadData(om, V * c, np.zeros(6), {"thrust": r.thrust, "torque": r.torque}, np.array(["a"] * 6))
        said = [w for w in sanity_check(data, prop) if "airspeed read as" in w]
        assert (said == []) if unit is None else any(f"airspeed read as {unit} " in w for w in said), (c, said)
