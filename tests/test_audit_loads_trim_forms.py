"""Mutation audit of cli/loads.py (``propmap loads``), cli/trim.py (``propmap trim``) and
simexport/forms.py (the simulators' model forms), 2026-11-29: each test pins a rule that a
hand-made mutant of the source changed without any other test failing (the mutant is named in
each docstring)."""

import dataclasses
import json
import math

import numpy as np
import pandas as pd
import pytest
from cli_helpers import run

import propmap as pm
from propmap.core.units import RPM
from propmap.simexport import forms


def _loads(capsys, *argv):
    return run(capsys, "loads", "apce_8x6", *argv)


def _points(tmp_path, text, name="p.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


def _set_with_collective(tmp_path, deg):
    from propmap.io.params_file import write_params

    f = tmp_path / "c.toml"
    write_params(f, dataclasses.replace(pm.default_params("apce_8x6"), collective=math.radians(deg)))
    return f


# ---------------------------------------------------------------- propmap loads --points


def test_a_long_row_after_a_good_one_is_named_with_its_field_counts(tmp_path, capsys):
    """Mutant L8: the parse error's counts swapped ('line 3 has 3 fields, but the header has 4')."""
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n5000,0,0\n5000,5,0,9\n")
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 2
    assert "line 3 has 4 fields, but the header has 3" in err
    assert not (tmp_path / "o.csv").exists()


def test_an_incidence_beyond_180_deg_is_refused(tmp_path, capsys):
    """Mutant L9: the points file's incidence limit 180 deg widened (180.5 deg solved)."""
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n5000,5,180\n5000,5,180.5\n")
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 2
    assert "line 3: incidence_deg must be a finite number in [0, 180], got '180.5'" in err


def test_a_negative_incidence_down_to_minus_180_is_told_to_give_its_magnitude(tmp_path, capsys):
    """Mutant L12: the hint of a negative incidence only from -90 deg (at -120 deg it was left out)."""
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n5000,5,-120\n")
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 2
    assert "line 2: incidence_deg must be a finite number in [0, 180], got '-120'" in err
    assert "give the magnitude of a negative incidence" in err


def test_a_collective_column_beyond_the_sum_limit_says_the_sets_collective_is_added(tmp_path, capsys):
    """Mutant L13: the reason of a collective column's shifted limits (the set's collective added) left out."""
    f = _set_with_collective(tmp_path, 3.0)
    p = _points(tmp_path, "rpm,airspeed,incidence_deg,collective_deg\n6000,0,0,43\n")
    code, _, err = _loads(capsys, "--params", str(f), "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 2
    assert "[-48, 42], got '43' (the parameter set's collective 3 deg is added to it, the sum within [-45, 45])" in err


def test_a_tab_separated_file_with_decimal_commas_is_read(tmp_path, capsys, apc8x6):
    """Mutant L14: decimal commas read only in ';' files (a tab file's '2,5' refused as not a number)."""
    p = _points(tmp_path, "rpm\tairspeed\tincidence_deg\n6000\t2,5\t0\n")
    out = tmp_path / "o.csv"
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(out))
    assert code == 0, err
    ref = pm.rotor_loads(apc8x6, pm.default_params("apce_8x6"), 6000 * RPM, 2.5, 0.0)
    got = pd.read_csv(out, sep=",")
    assert float(got["thrust"].iloc[0]) == pytest.approx(float(ref.thrust), rel=1e-8)


def test_a_cell_of_two_commas_is_not_a_number_not_a_decimal_comma(tmp_path, capsys):
    """Mutant L15: a cell with several commas taken for a decimal comma (the file then refused for mixing decimal
    commas and points, instead of naming the bad cell)."""
    p = _points(tmp_path, "rpm;airspeed;incidence_deg\n6000;0.5;0\n6000;1,000,5;0\n")
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 2
    assert "line 3: airspeed must be a finite number in [0, 500], got '1,000,5'" in err


def test_a_reverse_flow_point_is_flagged_as_such_in_the_column_and_the_summary(tmp_path, capsys, apc8x6):
    """Mutant L19: the flag bits of multiple_roots and reverse_flow swapped (an edgewise point at 2000 rpm and
    20 m/s, whose blade root sees the air from behind, was flagged multiple_roots)."""
    assert pm.rotor_loads(apc8x6, pm.default_params("apce_8x6"), 2000 * RPM, 20.0, math.pi / 2).flags() == [
        "reverse_flow"]
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n2000,20,90\n6000,0,0\n")
    out = tmp_path / "o.csv"
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(out))
    assert code == 0
    got = pd.read_csv(out, keep_default_na=False)
    assert list(got["flags"]) == ["reverse_flow", ""]
    assert "flagged: 1 reverse_flow" in err


def test_lambda2_is_negative_in_climb(capsys, apc8x6):
    """Mutant L20: lambda2 below 1e-12 (every climb) written 0, where only |lambda2| < 1e-12 is; in climb
    lambda2 = -V cos(incidence) / v_h with v_h = sqrt(T / (2 rho A))."""
    code, out, _ = _loads(capsys, "--rpm", "8000", "--airspeed", "5", "--json")
    assert code == 0
    j = json.loads(out)
    v_h = math.sqrt(j["thrust"] / (2 * j["air"]["rho"] * math.pi * (apc8x6.diameter / 2) ** 2))
    assert j["lambda2"] == pytest.approx(-5.0 / v_h, rel=1e-6)
    assert j["lambda2"] < -0.5


def test_an_output_named_like_an_input_column_in_another_case_gets_model_appended(tmp_path, capsys):
    """Mutant L24: the clash of output and input column names tested case-sensitively (an input 'ct' column beside
    the output 'CT': two columns one reader takes for the same)."""
    p = _points(tmp_path, "rpm,airspeed,incidence_deg,ct,Thrust\n6000,0,0,0.1,3\n")
    out = tmp_path / "o.csv"
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(out))
    assert code == 0, err
    got = pd.read_csv(out)
    assert list(got.columns[:5]) == ["rpm", "airspeed", "incidence_deg", "ct", "Thrust"]
    assert {"CT_model", "thrust_model"} <= set(got.columns) and "CT" not in got.columns
    assert got["ct"].iloc[0] == 0.1 and 0.05 < got["CT_model"].iloc[0] < 0.2


# ---------------------------------------------------------------- simexport.forms


OM = np.array([600.0, 900.0, 1200.0])  # [rad/s]
V, BETA = 10.0, math.radians(60.0)
VIP, VZ = V * math.sin(BETA), V * math.cos(BETA)


def test_rotorpy_form_term_by_term():
    """Mutants F7 (sin and cos swapped), F8 (k_z's sign), F9 (k_h's term dropped), F10 (drag on V, not V_ip),
    F11 (yaw moment on Omega, not Omega^2), F24 (M_R a scalar, not of Omega's shape): RotorPy's
    T = k_eta W^2 + k_h V_ip^2 - k_z W V_z, D = k_d W V_ip, Q = k_m W^2."""
    c = {"k_eta": 1e-5, "k_h": 0.01, "k_z": 2e-4, "k_d": 3e-4, "k_m": 2e-7}
    T, D, Q, MR = forms.predict("rotorpy", c, OM, V, BETA)
    np.testing.assert_allclose(T, 1e-5 * OM**2 + 0.01 * VIP**2 - 2e-4 * OM * VZ, rtol=1e-12)
    np.testing.assert_allclose(D, 3e-4 * OM * VIP, rtol=1e-12)
    np.testing.assert_allclose(Q, 2e-7 * OM**2, rtol=1e-12)
    assert np.shape(MR) == OM.shape and not np.any(MR)


GZ = {"motorConstant": 1e-5, "momentConstant": 0.016, "rotorDragCoefficient": 2e-4, "rollingMomentCoefficient": 3e-6}


@pytest.mark.parametrize("beta_deg, fade", [(60.0, 1 - 5.0 / 25.0), (120.0, 1 - 5.0 / 25.0), (0.0, 0.6),
                                             (180.0, 0.6)])
def test_gazebo_classic_fades_thrust_with_the_axial_speed_magnitude(beta_deg, fade):
    """Mutants F4 (the fade speed 25 m/s changed), F12 (the fade of V_z, not |V_z|: descent's thrust
    grew), F15 (the drag torque on the faded thrust): T = motorConstant W^2 clamp(1 - |V_z| / 25, 0, 1),
    Q = momentConstant motorConstant W^2 (unfaded)."""
    b = math.radians(beta_deg)
    T, D, Q, MR = forms.predict("gazebo-classic", GZ, OM, V, b)
    T0 = 1e-5 * OM**2
    np.testing.assert_allclose(T, T0 * fade, rtol=1e-12)
    np.testing.assert_allclose(Q, 0.016 * T0, rtol=1e-12)
    np.testing.assert_allclose(D, 2e-4 * OM * V * math.sin(b), rtol=1e-12)
    np.testing.assert_allclose(MR, 3e-6 * OM * V * math.sin(b), rtol=1e-12)


def test_gazebo_classic_thrust_is_zero_beyond_25_m_s_axial_and_gz_sim_does_not_fade():
    """Mutants F13 (the clamp's floor -1: negative thrust beyond 25 m/s), F14 (gz-sim faded too), F16 (rolling
    moment on V, not V_ip)."""
    for b in (0.0, math.pi):
        T, *_ = forms.predict("gazebo-classic", GZ, OM, 40.0, b)
        np.testing.assert_array_equal(T, 0.0)
    T, D, Q, MR = forms.predict("gz-sim", GZ, OM, 20.0, math.radians(30.0))
    np.testing.assert_allclose(T, 1e-5 * OM**2, rtol=1e-12)
    np.testing.assert_allclose(MR, 3e-6 * OM * 20.0 * 0.5, rtol=1e-12)


def _multinomial(R=0.1, rho=1.2):
    return {"R": R, "rho": rho, "CT": [0.01, -0.02, 0.03, 0.05, -0.07, 0.11], "CQ": [1e-3, 2e-3, -3e-3, 4e-3, 5e-3,
            -6e-3], "CH": [0.013, -0.017, 0.019, 0.023], "CR": [-0.029, 0.031, 0.037, -0.041]}


def test_multinomial_form_term_by_term():
    """Mutants F17 (mu and lambda swapped), F18 (q without R^2 in (Omega R)^2), F20 (lambda mu^2 term), F21 (mu^3
    term), F22 (Q without the factor R), F23 (C_H and C_R swapped), F30 (mu lambda's sign): X = rho pi R^2
    (Omega R)^2 C_X, Q and M_R times R; mu = V_ip / (Omega R), lambda = V_z / (Omega R)."""
    c = _multinomial()
    R = c["R"]
    mu, lam = VIP / (OM * R), VZ / (OM * R)
    q = 1.2 * math.pi * R**2 * (OM * R) ** 2
    even = [1, lam, lam**2, mu**2, lam**3, lam * mu**2]
    odd = [mu, mu * lam, mu * lam**2, mu**3]
    T, D, Q, MR = forms.predict("multinomial", c, OM, V, BETA)
    np.testing.assert_allclose(T, q * sum(k * t for k, t in zip(c["CT"], even)), rtol=1e-12)
    np.testing.assert_allclose(Q, q * R * sum(k * t for k, t in zip(c["CQ"], even)), rtol=1e-12)
    np.testing.assert_allclose(D, q * sum(k * t for k, t in zip(c["CH"], odd)), rtol=1e-12)
    np.testing.assert_allclose(MR, q * R * sum(k * t for k, t in zip(c["CR"], odd)), rtol=1e-12)


@pytest.mark.parametrize("name", ["lambda^2", "mu^2", "lambda mu^2", "lambda^3"])
def test_each_even_term_name_is_the_term_predict_evaluates(name):
    """Mutants F19, F26: the JSON file's terms_even names (EVEN_TERMS) and predict's terms must agree: a
    coefficient of 1 on the term named NAME gives C_T = that term."""
    R = 0.1
    om = 500.0
    mu, lam = VIP / (om * R), VZ / (om * R)
    value = {"lambda^2": lam**2, "mu^2": mu**2, "lambda mu^2": lam * mu**2, "lambda^3": lam**3}[name]
    c = {**_multinomial(R, 1.0), "CT": [1.0 if t == name else 0.0 for t in forms.EVEN_TERMS]}
    T, *_ = forms.predict("multinomial", c, om, V, BETA)
    assert T == pytest.approx(math.pi * R**2 * (om * R) ** 2 * value, rel=1e-12)


def test_omega_checks_and_their_messages():
    """Mutants F5 (the multinomial accepting Omega = 0: NaN loads), F6 (NaN accepted), F25 (the message's '>'
    for the multinomial)."""
    c = _multinomial()
    with pytest.raises(ValueError, match=r"omega must be > 0 rad/s for the multinomial model.*got 0\.0"):
        forms.predict("multinomial", c, 0.0, 5.0, 0.0)
    for target, coef in (("rotorpy", {"k_eta": 1, "k_h": 0, "k_z": 0, "k_d": 0, "k_m": 0}), ("gz-sim", GZ)):
        assert np.all(np.asarray(forms.predict(target, coef, 0.0, 5.0, 0.0)[0]) == 0.0)
        # (checked as rotor_loads checks omega since 2026-12-01: its words)
        with pytest.raises(ValueError, match=r"omega must be finite and in \[0, 100000\] rad/s; got nan"):
            forms.predict(target, coef, [100.0, float("nan")], 5.0, 0.0)
        with pytest.raises(ValueError, match=r"omega must be finite and in \[0, .*got -1\.0 \(a signed rotation"):
            forms.predict(target, coef, -1.0, 5.0, 0.0)


def test_target_names_and_former_names():
    """Mutants F1 and F28 (gill2019's FutureWarning gone, or another category), F2 (an unknown target accepted),
    F3 and F29 (the former name 'gazebo' mapped elsewhere, or not mapped), F27 (a list as target: TypeError, not
    the ValueError naming the targets)."""
    with pytest.warns(FutureWarning, match="now called 'multinomial'"):
        assert forms.canonical_target("gill2019") == "multinomial"
    assert forms.canonical_target("gazebo") == "gazebo-classic"
    for bad in ("gazebo_classic", ["rotorpy"], None):
        with pytest.raises(ValueError, match="target must be one of rotorpy, gazebo-classic, gz-sim, multinomial"):
            forms.canonical_target(bad)


# ---------------------------------------------------------------- propmap loads, one point


def test_a_negative_total_collective_beyond_45_deg_is_refused(tmp_path, capsys):
    """Mutant L31: the sum of the set's collective and --collective-deg checked only above +45 deg (-3 - 44 = -47
    deg solved)."""
    f = _set_with_collective(tmp_path, -3.0)
    code, _, err = _loads(capsys, "--rpm", "6000", "--params", str(f), "--collective-deg", "-44")
    assert code == 2
    assert "the parameter set's collective -3 deg plus -44 deg must be within [-45, 45] deg, got -47" in err


def test_a_collective_option_below_minus_45_deg_is_refused_by_its_own_check(capsys):
    """Mutant L32: --collective-deg checked only above +45 deg (-50 deg refused only as a sum, by another
    message)."""
    code, _, err = _loads(capsys, "--rpm", "6000", "--collective-deg", "-50")
    assert code == 2
    assert "--collective-deg must be finite and in [-45, 45] deg, got -50.0" in err


def test_one_slow_row_among_fast_ones_is_warned_of(tmp_path, capsys):
    """Mutant L35: the slow-rpm warning on the largest rate (a row of 50 rpm beside 5000 rpm unsaid)."""
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n5000,0,0\n50,0,0\n")
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 0, err
    assert "rpm as low as 50, below 100 rpm" in err


# ---------------------------------------------------------------- propmap trim


def _trim(capsys, *argv):
    return run(capsys, "trim", "apce_8x6", *argv)


@pytest.mark.parametrize("argv, message", [
    (["--rpm", "0.5", "--thrust", "1"], "--rpm must be finite and in [1, "),
    (["--rpm", "6000", "--thrust", "-2e5"], "--thrust must be finite and in [-1e5, 1e5] N, got -200000.0"),
    (["--rpm", "6000", "--thrust", "nan"], "--thrust must be finite and in [-1e5, 1e5] N, got nan"),
    (["--rpm", "6000", "--thrust", "2", "--range-deg", "-50", "10"],
     "--range-deg must be two angles LOW < HIGH within [-45, 45] deg, got -50.0 10.0"),
    (["--thrust", "2", "--rpm-range", "0", "5000"], "--rpm-range must be two rates LOW < HIGH within (0, "),
    (["--thrust", "2", "--rpm-range", "1000", "2e6"], "got 1000.0 2000000.0"),
])
def test_trim_refuses_out_of_range_options(capsys, argv, message):
    """Mutants T1 (--rpm unchecked), T2 (a thrust below -1e5 N taken), T3 (a NaN thrust taken), T6 (--range-deg
    beyond +-45 deg taken), T7 (--rpm-range from 0 rpm taken), T8 (--rpm-range beyond RPM_MAX taken)."""
    code, _, err = _trim(capsys, *argv)
    assert code == 2
    assert message in err


def test_an_unreachable_thrust_names_the_default_range_and_exits_2(capsys):
    """Mutants T17 (the default collective range -20..30 deg changed), T19 (a thrust out of reach an exit 1, not a
    usage error)."""
    code, _, err = _trim(capsys, "--rpm", "6000", "--thrust", "3")
    assert code == 2
    assert "--thrust: no collective in [-20, 30] deg makes thrust=3 N" in err


def test_trim_json_collective_is_the_total_in_degrees_and_reproduces_the_thrust(tmp_path, capsys, apc8x6):
    """Mutants T10 (the added collective in radians), T13 (collective_deg without the set's), T16 (thrust_target the
    thrust made), T18 (the incidence taken as radians), T21 (rpm's unit), T22 (the set's collective said 0), T28
    (lambda2 of another ratio): the total collective given back to rotor_loads makes the target thrust."""
    f = _set_with_collective(tmp_path, 2.0)
    code, out, err = _trim(capsys, "--rpm", "6000", "--thrust", "2", "--airspeed", "8", "--incidence-deg", "90",
                           "--params", str(f), "--json")
    assert code == 0, err
    j = json.loads(out)
    assert j["thrust_target"] == 2.0 and j["params_collective_deg"] == 2.0
    assert j["collective_deg"] == pytest.approx(2.0 + j["added_collective_deg"], abs=1e-12)
    assert j["units"]["rpm"] == "rpm" and j["units"]["collective_deg"] == "deg"
    assert j["lambda2"] == 0.0 and j["v_i_over_v_h"] > 0.1
    r = pm.rotor_loads(apc8x6, pm.default_params("apce_8x6"), 6000 * RPM, 8.0, math.pi / 2,
                       collective=math.radians(j["collective_deg"]))
    assert float(r.thrust) == pytest.approx(2.0, rel=1e-6) and j["thrust"] == pytest.approx(2.0, rel=1e-6)


def test_hover_reference_is_cq_minus_the_hover_cq_at_the_same_thrust_and_rpm(capsys):
    """Mutants T11 (the hover reference taken at collective 0, not the trimmed one), T26 (dCQ's sign): dCQ = CQ at
    the point minus CQ of the hover trimmed to the same thrust and rpm (trimmed here by trim itself)."""
    code, out, err = _trim(capsys, "--rpm", "6000", "--thrust", "2", "--airspeed", "8", "--incidence-deg", "150",
                           "--hover-reference", "--json")
    assert code == 0, err
    j = json.loads(out)
    code, out, err = _trim(capsys, "--rpm", "6000", "--thrust", f"{j['thrust']!r}", "--json")
    assert code == 0, err
    hover = json.loads(out)
    assert j["dCQ_constant_thrust"] == pytest.approx(j["CQ"] - hover["CQ"], rel=1e-5, abs=1e-9)
    assert abs(j["dCQ_constant_thrust"]) > 1e-5


def test_range_deg_bounds_the_search(capsys):
    """Mutant T25: --range-deg ignored by the trim (the default range searched)."""
    code, _, err = _trim(capsys, "--rpm", "6000", "--thrust", "2", "--range-deg", "10", "20")
    assert code == 2
    assert "no collective in [10, 20] deg makes thrust=2 N" in err


def test_a_negative_thrust_has_no_hover_induced_velocity_and_its_ratios_are_null(capsys):
    """Mutant T20: the ratios of a negative thrust (NaN: no hover induced velocity) written as NaN, not null."""
    code, out, err = _trim(capsys, "--rpm", "6000", "--thrust", "-0.2", "--range-deg", "-45", "0", "--json")
    assert code == 0, err
    j = json.loads(out)
    assert j["thrust"] == pytest.approx(-0.2, rel=1e-6) and j["collective_deg"] < -20
    assert j["v_i_over_v_h"] is None and j["lambda2"] is None


def test_trim_warns_of_the_tip_mach_number_at_the_trimmed_point(capsys):
    """Mutant T27: trim's coverage warnings dropped (a tip Mach number of 0.94 at 30000 rpm unsaid)."""
    code, _, err = _trim(capsys, "--rpm", "30000", "--thrust", "30")
    assert code == 0, err
    assert "tip Mach number up to 0.94 (> 0.7)" in err


def test_trim_text_says_the_sets_share_of_the_collective_only_where_the_set_has_one(tmp_path, capsys):
    """Mutant T23: the line "(the set's C deg + A deg)" printed for a set without a collective, and not for one
    with it."""
    code, out, err = _trim(capsys, "--rpm", "6000", "--thrust", "2", "--params", str(_set_with_collective(tmp_path, 2)))
    assert code == 0, err
    assert "(the set's 2 deg + " in out
    code, out, err = _trim(capsys, "--rpm", "6000", "--thrust", "2")
    assert code == 0, err
    assert "the set's" not in out and "collective " in out


def test_the_radians_check_ignores_the_incidence_of_static_rows(tmp_path, capsys):
    """Mutant L37: static rows' incidences (no airspeed: any angle gives the same loads) taken as evidence of
    radians (1.5708 and 0.7854 at 0 m/s warned of)."""
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n6000,0,1.5708\n6000,0,0.7854\n6000,5,0\n")
    code, _, err = _loads(capsys, "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 0
    assert "warning" not in err and "wrote 3 points" in err


def test_the_airspeed_beyond_a_sets_coverage_is_the_files_largest(tmp_path, capsys):
    """Mutant L36: the points file's smallest airspeed checked against the set's [coverage] airspeed_max (10 m/s
    beside 0 m/s unsaid)."""
    from propmap.io.params_file import write_params

    f = tmp_path / "cov.toml"
    write_params(f, pm.default_params("apce_8x6"), coverage={})  # (none: the set's own is written by default)
    f.write_text(f.read_text() + "\n[coverage]\nairspeed_max = 3.0\n")
    p = _points(tmp_path, "rpm,airspeed,incidence_deg\n6000,0,0\n6000,10,90\n")
    code, _, err = _loads(capsys, "--params", str(f), "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 0, err
    assert f"airspeed up to 10 m/s: the data behind {f} reach 3 m/s" in err


def _set_fitted_5_deg_up(tmp_path, apc8x6):
    """apce_8x6's set in a file whose [coverage] says it was fitted to this blade set 5 deg up at 0.75 R:
    (the file, that angle [deg])."""
    from propmap.cli._common import theta75_deg
    from propmap.io.params_file import write_params

    fitted = theta75_deg(apc8x6) + 5.0
    f = tmp_path / "fitted.toml"
    write_params(f, pm.default_params("apce_8x6"), coverage={})  # (none: the set's own is written by default)
    f.write_text(f.read_text() + f"\n[coverage]\ndiameter_m = {apc8x6.diameter!r}\nn_blades = 2\n"
                 f"theta75_deg = {fitted!r}\n")
    return f, fitted


def test_a_collective_column_that_sets_the_blade_as_fitted_is_not_warned_of(tmp_path, capsys, apc8x6):
    """Mutant L39: a points file's collective column not passed to the fitted-blade check (its rows checked at
    0 deg: a set fitted to this blade 5 deg up, run with collectives 0 to 5 deg, warned of)."""
    f, fitted = _set_fitted_5_deg_up(tmp_path, apc8x6)
    p = _points(tmp_path, "rpm,airspeed,incidence_deg,collective_deg\n6000,0,0,0\n6000,0,0,5\n")
    code, _, err = _loads(capsys, "--params", str(f), "--points", str(p), "--out", str(tmp_path / "o.csv"))
    assert code == 0, err
    assert "fitted to the blade set at" not in err and "wrote 2 points" in err
    code, _, err = _loads(capsys, "--params", str(f), "--rpm", "6000")  # (the check is live: 0 deg is 5 deg off)
    assert code == 0 and f"fitted to the blade set at {fitted:.1f} deg at 0.75 R" in err


def test_trim_warns_of_a_set_fitted_to_the_blade_at_another_angle(tmp_path, capsys, apc8x6):
    """Mutant T24: trim's section/fitted-propeller check dropped (a set fitted to this blade 5 deg up unsaid)."""
    f, fitted = _set_fitted_5_deg_up(tmp_path, apc8x6)
    code, _, err = _trim(capsys, "--rpm", "6000", "--thrust", "2", "--params", str(f))
    assert code == 0, err
    assert f"fitted to the blade set at {fitted:.1f} deg at 0.75 R" in err
