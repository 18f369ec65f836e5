"""A mutation audit of identify/data.py and identify/flight.py (2026-11-29): each test kills a hand-made mutant that
survived the modules' own test files, by the documented behaviour it changed."""

import math
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.solver import Discretization
from propmap.identify import FitOptions
from propmap.identify.data import DataError, LoadData, loads_from_uiuc_files, sanity_check
from propmap.identify.flight import FlightSamples, fit_flight, predict_flight

VEHICLE = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
COARSE = Discretization(12, 8)


def _loads(prop, rpm, f_thrust=1.0, f_torque=1.0, airspeed=0.0, group="run"):
    """The generic set's static (or axial) thrust and torque of ``prop`` at ``rpm``, times the factors, as LoadData."""
    omega = np.asarray(rpm, float) * math.pi / 30
    r = pm.rotor_loads(prop, pm.generic_params(), omega, airspeed, 0.0)
    return LoadData(omega, np.full(omega.size, float(airspeed)), np.zeros(omega.size),
                    {"thrust": f_thrust * r.thrust, "torque": f_torque * r.torque}, np.full(omega.size, group),
                    "synthetic")


def _samples(vehicle, params, n, seed=3, moment=False, logs=None):
    """n synthetic samples at 10 Hz (of one log, or of logs of the sizes ``logs``), the force (and moment) the
    model's own."""
    rng = np.random.default_rng(seed)
    sizes = logs or [n]
    n = sum(sizes)
    index = np.repeat(np.arange(len(sizes)), sizes)
    s = FlightSamples(log_names=tuple(f"log{k}" for k in range(len(sizes))), log_index=index,
                      t=np.concatenate([np.arange(m) * 0.1 for m in sizes]),
                      velocity=rng.uniform(-6, 6, (n, 3)) * [1, 1, 0.4], angular_velocity=rng.uniform(-1, 1, (n, 3)),
                      rotor_omega=rng.uniform(900, 1500, (n, 4)), rotor_acceleration=np.zeros((n, 4)),
                      force=np.zeros((n, 3)), moment=None, reference_force=None, reference_moment=None, rate_hz=10.0)
    w = predict_flight(s, vehicle, params, discretization=COARSE)
    return replace(s, force=w.force, moment=w.moment if moment else None)


def test_a_ten_metre_diameter_is_inside_the_documented_range_and_converts_the_coefficients(tmp_path):
    """loads_from_uiuc_files takes a diameter in (0, 10] m, 10 included: T = CT rho n^2 D^4, Q = CP rho n^2 D^5/2pi."""
    p = tmp_path / "big_static_r1.txt"
    p.write_text("RPM CT CP\n60 0.1 0.05\n120 0.1 0.05\n")
    data = loads_from_uiuc_files([p], 10.0)
    rho = pm.Air().rho
    np.testing.assert_allclose(data.measured["thrust"], 0.1 * rho * np.array([1.0, 4.0]) * 1e4, rtol=1e-12)
    np.testing.assert_allclose(data.measured["torque"], 0.05 * rho * np.array([1.0, 4.0]) * 1e5 / (2 * math.pi),
                               rtol=1e-12)
    with pytest.raises(DataError, match=r"diameter must be a finite number in \(0, 10\] m, got 10.001"):
        loads_from_uiuc_files([p], 10.001)


def test_samples_two_per_parameter_are_refused_as_documented():
    """fit_flight refuses SAMPLES_PER_PARAMETER (2) samples per fitted parameter or fewer, saying how many it needs."""
    veh = pm.read_vehicle(VEHICLE)
    s = _samples(veh, pm.generic_params(), 6)
    with pytest.raises(ValueError, match=r"^6 samples cannot identify 3 parameters \(at least 7: 2 per parameter\)$"):
        fit_flight(s, veh, options=FitOptions(names=("collective", "drag_area_x", "drag_area_y"), prior=False),
                   discretization=COARSE)


def test_the_hover_torque_check_compares_at_the_slowest_tenths_median_speed_and_reads_the_yaw_channel():
    """hover_torque_check: Omega_hover the median rotor speed of the slowest tenth, ratio Q_fitted / Q_reference (the
    generic set trimmed to the same thrust, collective in deg), k_Q from M_z = -sum s_i (k_Q Omega^2 + J dOmega/dt)."""
    from propmap.identify.flight import FLIGHT_DISCRETIZATION, hover_torque_check

    veh = pm.read_vehicle(VEHICLE)
    generic = pm.generic_params()
    fitted = generic.replace(cd_min=2 * generic.cd_min)
    rng = np.random.default_rng(5)
    s = _samples(veh, generic, 40)
    acc = rng.uniform(-2e4, 2e4, (s.n, 4))
    spins = np.array([r.spin for r in veh.rotors])
    J = np.array([r.inertia for r in veh.rotors])
    kq = 2e-8
    mz = -(spins * (kq * s.rotor_omega**2 + J * acc)).sum(axis=1)
    s = replace(s, rotor_acceleration=acc, moment=np.column_stack([np.full(s.n, 0.3), np.full(s.n, -0.2), mz]))
    slow = s.speed <= np.quantile(s.speed, 0.1)
    assert slow.sum() == 4
    om_h = float(np.median(s.rotor_omega[slow]))
    air = pm.Air(rho=1.0)
    ht = hover_torque_check(fitted, veh, s, air=air)
    assert ht["omega_hover"] == om_h and abs(om_h - np.median(s.rotor_omega)) > 1
    r = pm.rotor_loads(veh.rotors[0].propeller, fitted, om_h, 0.0, 0.0, air=air, discretization=FLIGHT_DISCRETIZATION)
    assert ht["thrust_hover"] == pytest.approx(float(r.thrust), rel=1e-12)
    assert ht["torque_model"] == pytest.approx(float(r.torque), rel=1e-12)
    assert ht["ratio"] == pytest.approx(ht["torque_model"] / ht["torque_reference"], rel=1e-12)
    assert ht["ratio"] > 1.1  # (twice the fitted set's profile drag: more torque than the generic set's)
    assert hover_torque_check(fitted, veh, s, air=air, reference=fitted)["ratio"] == pytest.approx(1.0, abs=1e-6)
    pitched = hover_torque_check(generic.replace(collective=math.radians(3.0)), veh, s, air=air)
    assert pitched["ratio"] == pytest.approx(1.0, abs=1e-4)
    assert pitched["reference_collective_deg"] == pytest.approx(3.0, abs=1e-4)  # (the generic set's own is 0)
    assert ht["k_Q"] == pytest.approx(kq, rel=1e-9)
    assert ht["yaw_r"] == pytest.approx(1.0, abs=1e-9)
    assert ht["torque_yaw_channel"] == pytest.approx(kq * om_h**2, rel=1e-9)


def test_cross_validation_pools_held_out_errors_and_jackknifes_the_folds():
    """cross_validate_flight: each log predicted by the fitted vehicle of the others (its centre of mass), the baselines
    refitted on the training logs, F pooled by samples, the folds' estimates' jackknife; fewer than 2 logs refused."""
    from propmap.identify.flight import (baseline_force, cross_validate_flight, fit_baselines, flight_errors,
                                         shift_centre_of_mass)
    from propmap.identify.dependence import jackknife_std_error

    veh = pm.read_vehicle(VEHICLE)
    truth = pm.generic_params().replace(collective=math.radians(5.0))
    opts = FitOptions(names=("cg_x", "cg_y"), prior=False)
    s = _samples(veh, truth, 0, logs=[12, 18, 24])
    w = predict_flight(s, shift_centre_of_mass(veh, [0.004, -0.002]), truth, discretization=COARSE)
    s = replace(s, force=w.force, moment=w.moment)
    cv = cross_validate_flight(s, veh, base=truth, options=opts, moments=True, discretization=COARSE)
    assert [f["log"] for f in cv["folds"]] == ["log0", "log1", "log2"]
    for k, f in enumerate(cv["folds"]):
        assert f["x"]["cg_x"] == pytest.approx(0.004, abs=1e-8) and f["x"]["cg_y"] == pytest.approx(-0.002, abs=1e-8)
        assert f["model"]["F"] < 1e-6 and f["model"]["n"] == (12, 18, 24)[k]
        assert f["model"]["M"] < 1e-6
        train = s.select(s.log_index != k)
        for key, bl in fit_baselines(train, veh).items():  # (refitted without the held-out log)
            assert f[key]["F"] == pytest.approx(flight_errors(baseline_force(bl, s.of_log(k), veh), s.of_log(k))["F"],
                                                rel=1e-9)
    for key in cv["pooled"]:
        F = np.array([f[key]["F"] for f in cv["folds"]])
        n = np.array([f[key]["n"] for f in cv["folds"]])
        assert cv["pooled"][key] == pytest.approx(math.sqrt(np.sum(F**2 * n) / n.sum()), rel=1e-12)
    assert cv["pooled"]["k_omega2"] != pytest.approx(float(np.mean([f["k_omega2"]["F"] for f in cv["folds"]])),
                                                      rel=1e-6)
    # logs of centres of mass 0, 2 and 6 mm forward: the folds' estimates spread, the jackknife is theirs
    forces, moments = [], []
    for k, cx in enumerate((0.0, 0.002, 0.006)):
        w = predict_flight(s.of_log(k), shift_centre_of_mass(veh, [cx, 0.0]), truth, discretization=COARSE)
        forces.append(w.force), moments.append(w.moment)
    spread = replace(s, force=np.concatenate(forces), moment=np.concatenate(moments))
    cv = cross_validate_flight(spread, veh, base=truth, options=opts, moments=True, discretization=COARSE)
    x = [[f["x"]["cg_x"], f["x"]["cg_y"]] for f in cv["folds"]]
    se = jackknife_std_error(x)
    assert cv["jackknife_std_error"]["cg_x"] == pytest.approx(se[0], rel=1e-12) and se[0] > 1e-3
    with pytest.raises(ValueError, match="cross-validation needs samples of at least 2 logs, got 1"):
        cross_validate_flight(s.of_log(0), veh, base=truth, options=opts, moments=True, discretization=COARSE)


def test_the_papers_model_frees_no_cambered_lift_terms_by_default():
    """default_flight_names: FLIGHT_FIT for a cambered base, less cl_alpha and alpha_L0_re for the paper's model."""
    from propmap.identify.flight import FLIGHT_FIT, default_flight_names

    assert default_flight_names(pm.generic_params()) == FLIGHT_FIT
    paper = pm.AirfoilParams(cl1=5.5, cl2=4.0, cd=0.02, alpha0=0.3)
    assert default_flight_names(paper) == ("collective", "drag_area_x", "drag_area_y", "wash_factor")


def test_converted_loads_below_the_range_are_refused_naming_the_file_and_value(tmp_path):
    """Converted loads outside [-1e5, 1e5] N are refused on either side: a negative CT at 900,000 rpm too."""
    p = tmp_path / "s_9x6_static_r1.txt"
    p.write_text("RPM CT CP\n900000 -9 5\n")
    with pytest.raises(DataError, match=r"thrust -3.969e\+10 N \(from the coefficients, the rpm and the diameter 2 m\) "
                                         r"is outside \[-100000, 100000\] N"):
        loads_from_uiuc_files([p], 2.0)


def test_the_centre_of_mass_moves_in_three_axes_or_two():
    """shift_centre_of_mass takes (3,) or (2,) values (z then the vehicle's) and returns a copy."""
    from propmap.identify.flight import shift_centre_of_mass

    veh = replace(pm.read_vehicle(VEHICLE), centre_of_mass=np.array([0.001, 0.002, 0.003]))
    np.testing.assert_array_equal(shift_centre_of_mass(veh, [0.01, -0.02, 0.03]).centre_of_mass, [0.01, -0.02, 0.03])
    np.testing.assert_array_equal(shift_centre_of_mass(veh, [0.01, -0.02]).centre_of_mass, [0.01, -0.02, 0.003])
    np.testing.assert_array_equal(veh.centre_of_mass, [0.001, 0.002, 0.003])


def test_loads_beyond_three_times_the_models_are_refused_and_inside_warned_of():
    """sanity_check refuses a median ratio to the model beyond SANITY_FACTOR (3x) and only warns inside it."""
    prop = pm.load_propeller("apce_8x6")
    rpm = np.linspace(3000, 9000, 7)
    with pytest.raises(DataError, match=r"the measured thrust 3.5 times what the model predicts for .* "
                                        r"\(expected within 0.33-3x\)"):
        sanity_check(_loads(prop, rpm, f_thrust=3.5), prop)
    (w,) = sanity_check(_loads(prop, rpm, f_thrust=2.8), prop)
    assert "the measured thrust is 2.8 times (outside 0.714-1.4x)" in w


@pytest.mark.filterwarnings("ignore:a blade tip meets the air")
def test_a_tip_mach_number_above_0_7_is_warned_of_and_above_1_asks_whether_the_rpm_is_electrical():
    """sanity_check warns of a tip Mach number above 0.7 in the data, asking of the electrical rpm only above 1."""
    prop = pm.load_propeller("apce_8x6")
    (w,) = sanity_check(_loads(prop, [5000, 10000, 24000]), prop)
    assert w.startswith("tip Mach number up to 0.75 in the data (> 0.7)") and "electrical" not in w
    (w,) = sanity_check(_loads(prop, [5000, 20000, 36000]), prop)
    assert w.startswith("tip Mach number up to 1.13 in the data (> 0.7)") and w.endswith("or is the rpm electrical?")
    assert sanity_check(_loads(prop, [5000, 10000, 20000]), prop) == []


def test_a_run_below_2000_in_chord_reynolds_number_and_1000_rpm_is_warned_of_by_name():
    """sanity_check warns of each run whose chord Reynolds number at 0.75 R stays below RE75_FLOOR (2000) below
    1000 rpm (rev/s read as rpm?), naming the run; a run reaching 2000 is not warned of."""
    prop = pm.load_propeller("apce_8x6")
    slow, fast = _loads(prop, [40, 60, 80, 100, 150], group="slow"), _loads(prop, [3000, 6000, 9000], group="fast")
    data = LoadData(np.concatenate([slow.omega, fast.omega]), np.zeros(8), np.zeros(8),
                    {k: np.concatenate([slow.measured[k], fast.measured[k]]) for k in ("thrust", "torque")},
                    np.concatenate([slow.group, fast.group]), "synthetic")
    (w,) = sanity_check(data, prop)
    assert w.startswith("the chord Reynolds number at 0.75 R is 318-1.19e+03 (40-150 rpm) in slow, below 2000")
    assert sanity_check(_loads(prop, [100, 200, 400], group="reaching"), prop) == []  # (1.9e3 to 3.2e3)


def test_uiuc_files_must_be_given_as_a_sequence_and_a_generator_keeps_their_names(tmp_path):
    """loads_from_uiuc_files takes a sequence of paths: one path alone is a TypeError naming ``paths`` (a str was read
    one character at a time, a Path raised from inside); a generator's file names reach the source."""
    p = tmp_path / "s_9x6_static_r1.txt"
    p.write_text("RPM CT CP\n3000 0.1 0.05\n6000 0.1 0.05\n")
    for one in (str(p), p):
        with pytest.raises(TypeError, match=r"^paths must be a sequence of file paths, got .* \(give a list"):
            loads_from_uiuc_files(one, 0.2)
    data = loads_from_uiuc_files((f for f in [p]), 0.2)
    assert data.n == 2 and data.source == "UIUC-format files s_9x6_static_r1.txt"


def test_the_moment_errors_are_divided_by_the_mean_in_plane_rotor_arm():
    """fit_flight with moments divides the moment errors by the mean rotor arm in the rotor plane (the NeuroBEM
    quadrotor's rotors sit 27 mm below its origin: their 3-D distance is 2% longer)."""
    veh = pm.read_vehicle(VEHICLE)
    truth = pm.generic_params().replace(collective=math.radians(5.0))
    s = _samples(veh, truth, 10, moment=True)
    s = replace(s, moment=s.moment + [0.01, -0.02, 0.005])
    res = fit_flight(s, veh, base=truth, moments=True, options=FitOptions(names=("drag_area_z",), prior=False),
                     discretization=COARSE)
    arm = float(np.mean([math.hypot(r.position[0], r.position[1]) for r in veh.rotors]))
    assert res.extra["moment_arm_m"] == pytest.approx(arm, rel=1e-12) and arm == pytest.approx(0.126823, abs=1e-6)
    np.testing.assert_allclose(res.residuals[3 * s.n:3 * s.n + 3], -np.array([0.01, -0.02, 0.005]) / arm, rtol=1e-6)


def test_a_tenth_of_the_points_in_the_vortex_ring_is_warned_of():
    """sanity_check warns where 10% of the points or more lie in the vortex-ring or turbulent-wake state by the model
    (here about a fifth: descent points among static ones)."""
    prop, params = pm.load_propeller("apce_10x7"), pm.generic_params()
    V = np.concatenate([np.linspace(0.0, 14.0, 29), np.zeros(40)])
    om = np.concatenate([np.full(29, 5000.0), np.linspace(3000, 7000, 40)]) * math.pi / 30
    inc = np.where(V > 0, math.pi, 0.0)
    r = pm.rotor_loads(prop, params, om, V, inc)
    n = int(np.sum(np.isin(r.state_name, ("vortex ring", "turbulent wake")) & r.converged))
    assert 0.1 * V.size <= n < 0.5 * V.size
    group = np.where(V > 0, "descent", "static")
    data = LoadData(om, V, inc, {"thrust": r.thrust, "torque": r.torque}, group, "x")
    (w,) = [w for w in sanity_check(data, prop) if "vortex-ring or turbulent-wake" in w]
    assert w.startswith(f"{n} of 69 points lie in the vortex-ring or turbulent-wake state by the model "
                        "(groups descent)")


def test_the_sanity_check_compares_at_the_density_the_data_logged():
    """sanity_check's model runs at LoadData.air_density where the data logged one (given no air): loads measured at
    0.8 kg/m^3 are this propeller's, while against sea-level air their thrust is 0.63 times the model's (warned)."""
    prop = pm.load_propeller("apce_8x6")
    rpm = np.linspace(3000, 9000, 7)
    omega = rpm * math.pi / 30
    thin = pm.Air(rho=0.8)
    r = pm.rotor_loads(prop, pm.generic_params(), omega, 0.0, 0.0, air=thin)
    data = LoadData(omega, np.zeros(7), np.zeros(7), {"thrust": r.thrust, "torque": r.torque}, np.full(7, "run"),
                    "thin air", air_density=0.8)
    assert sanity_check(data, prop) == []
    (w,) = sanity_check(data, prop, air=pm.Air())
    assert w.startswith("the measured thrust is 0.626 times (outside 0.714-1.4x) and torque is 0.646 times")


def test_section_parameters_are_not_fitted_for_rotors_that_carry_their_own_sets():
    """fit_flight refuses section parameters for a vehicle whose rotors carry their own sets (Rotor.params), naming
    the rotors; the airframe alone may still be fitted."""
    veh = pm.read_vehicle(VEHICLE)
    own = replace(veh, rotors=tuple(replace(r, params=pm.generic_params()) if k in (1, 3) else r
                                    for k, r in enumerate(veh.rotors)))
    s = _samples(veh, pm.generic_params(), 10)
    with pytest.raises(ValueError, match=r"^rotor\(s\) 2, 4 of the vehicle carry their own parameter sets, which the "
                                         "fitted section parameters would not reach"):
        fit_flight(s, own, options=FitOptions(names=("collective", "drag_area_x"), prior=False), discretization=COARSE)
    res = fit_flight(s, own, options=FitOptions(names=("drag_area_x",), prior=False), discretization=COARSE)
    assert res.names == ("drag_area_x",)


def test_a_unit_slip_search_at_rates_the_model_cannot_solve_still_names_the_slip(monkeypatch):
    """The unit-slip search of sanity_check tries the data's rates divided by 2-14 pole pairs; where the model
    gives no finite load at such a rate (on_failure="flag": NaN), that count is skipped. Until 2026-11-29 the
    pole-pair search raised ValueError (max() of an empty sequence) there instead of refusing the data with its
    factor (found by a review of the refactor that shared the five searches' test). Loads 10x the generic
    set's, the solver made to fail below 2500 rpm."""
    import propmap.core.solver as solver

    prop = pm.load_propeller("apce_8x6")
    data = _loads(prop, [3000, 4000, 5000, 6000, 7000, 8000], f_thrust=10.0, f_torque=10.0)
    real = solver.rotor_loads

    def failing_below_2500_rpm(prop, params, omega, *args, **kwargs):
        r = real(prop, params, omega, *args, **kwargs)
        if np.max(omega) < 2500 * math.pi / 30:
            r = replace(r, thrust=np.full_like(r.thrust, np.nan), torque=np.full_like(r.torque, np.nan))
        return r

    monkeypatch.setattr(solver, "rotor_loads", failing_below_2500_rpm)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # the all-NaN counts skipped without NumPy's warning
        with pytest.raises(DataError, match=r"the measured thrust 10 times; torque 10 times what the model predicts"):
            sanity_check(data, prop)
