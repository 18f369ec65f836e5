"""Mutation audit of propmap.cases (the validation cases: which digitized data each reads, its units and
conversions, the Beaver's wind axes), propmap.simexport.files (the simulator coefficient files),
propmap.core.air (Air and the range checks) and propmap.core.units: each test names the mutant it kills."""

import dataclasses
import hashlib
import json
import math
import re
import warnings
from importlib import resources

import numpy as np
import pytest

import propmap as pm
from propmap.cases import dji9443_propeller, gill2019_coefficients, gill2019_loads, run_case
from propmap.core.airfoil import COLLECTIVE_MAX
from propmap.core.units import RPM
from propmap.simexport import Envelope, export_sim, rotorpy_directions, write_export
from propmap.simexport.files import check_rotorpy_vehicle, error_lines
from propmap.vehicle import Rotor, Vehicle


# ---- cases.py: the data each case reads, its units and conversions

def _digitized(name):
    """The numeric rows of a bundled digitized CSV, read here independently of propmap.cases."""
    text = (resources.files("propmap") / "data" / "digitized" / name).read_text(encoding="utf-8")
    rows = [ln.split(",") for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    return np.array([[float(x) for x in r[:2]] for r in rows[1:]])


def test_dji9443_stations_start_outboard_of_the_hub_radius_in_metres():
    """Mutant C4 (the hub test made r/R >= Rhub, mixing units): the DJI 9443's first digitized station,
    r/R 0.0406 (4.9 mm), lies inside its 6.24 mm hub and is dropped; the blade starts at r/R 0.0911."""
    prop = dji9443_propeller()
    chord = _digitized("DJI9443_chorddist.csv")
    assert (prop.radius, prop.n_blades) == (0.12, 2)
    assert prop.r.size == chord.shape[0] - 1 and prop.r.min() >= 0.00624
    assert prop.r[0] == pytest.approx(0.091114 * 0.12, rel=1e-12)
    assert prop.chord[0] == pytest.approx(chord[1, 1] * 0.12, rel=1e-12)


def test_dji9443_case_is_the_hover_ct_at_5400_rpm():
    """Mutants C35 (5000 rpm) and C36 (the relative error inverted): CT = T / (rho n^2 D^4) in hover at
    5400 rpm, against the measured 0.072."""
    g = pm.generic_params()
    m = run_case("dji9443", {"g": g})
    r = pm.rotor_loads(dji9443_propeller(), g, 5400 * RPM, 0.0, 0.0, air=pm.Air())
    ct = m.metrics["g"]["CT"]
    assert ct == pytest.approx(float(r.CT), rel=1e-12)
    assert m.metrics["g"]["rel_err_ct"] == pytest.approx(ct / 0.072 - 1, rel=1e-12)
    assert m.x.tolist() == [5400.0] and m.measured["CT"].tolist() == [0.072]


def test_apc10x7e_case_runs_the_tunnel_advance_ratios_at_9200_rpm():
    """Mutants C34 (V = J n R instead of J n D) and C42 (the CT errors normalised by the last point's CT
    instead of the first): the predicted CT at each digitized J is the model's at V = J n D, 9200 rpm."""
    g = pm.generic_params()
    m = run_case("apc10x7e", {"g": g})
    ct = _digitized("apc10x7E_mccrink_gregory2017_CT_vs_J.csv")
    prop = pm.load_propeller("apce_10x7")
    n = 9200 / 60
    r = pm.rotor_loads(prop, g, 2 * math.pi * n, ct[:, 0] * n * prop.diameter, 0.0, air=pm.Air())
    np.testing.assert_allclose(m.predicted["g"]["CT"], r.CT, rtol=1e-12)
    dct = (r.CT - ct[:, 1]) / ct[0, 1]
    assert m.metrics["g"]["rms_ct"] == pytest.approx(float(np.sqrt(np.mean(dct**2))), rel=1e-9)
    assert m.metrics["g"]["max_ct"] == pytest.approx(float(np.max(np.abs(dct))), rel=1e-9)
    # the hover model keeps the lowest J's coefficients: its CT error at J is 1 - CT(J) / CT(J_min)
    hover = (ct[0, 1] - ct[:, 1]) / ct[0, 1]
    assert m.metrics["hover model"]["max_ct"] == pytest.approx(float(np.max(np.abs(hover))), rel=1e-12)


def test_beaver_measured_ratios_are_taken_from_the_true_zero_incidence():
    """Mutant C38 (the measured ratio read at the nominal incidence, not nominal - 0.2 deg): the tunnel's
    nominal -0.2 deg is the true 0, so the measured CT_w(20)/CT_w(0) is the curve's value at nominal 19.8 deg.
    Mutant C40 (the hover model's CT not projected on the wind axis): the hover model's CT_w is CT cos(a).
    Mutant C13 (no check that the matching collective exists): a set already past the measured thrust at
    the largest collective has no matched_* metrics (brentq raised)."""
    d = _digitized("sinnige2019_CT_vs_incidence_J0.9.csv")
    assert d[0, 0] == -0.2
    g = pm.generic_params().replace(collective=COLLECTIVE_MAX)
    m = run_case("beaver", {"max": g})
    for a in (10.0, 20.0):
        assert m.metrics["measured"][f"ratio_{a:g}"] == pytest.approx(np.interp(a - 0.2, d[:, 0], d[:, 1]) / d[0, 1],
                                                                      rel=1e-12)
    hover = m.predicted["hover model"]["CT"]
    np.testing.assert_allclose(hover / hover[0], np.cos(np.radians(d[:, 0] + 0.2)), rtol=1e-12)
    assert hover[-1] < hover[0]
    r = m.metrics["max"]
    assert r["CT0"] > m.metrics["measured"]["CT0"] and "matched_collective_deg" not in r and "ratio_20" in r


def test_gill2019_loads_are_the_published_multinomial_model():
    """Mutants C17/C18/C19 (the rpm range test loosened or an empty rpm taken), C20 (an unknown name reaches a
    KeyError), C24 (H = k4 mu + k5 lambda_c, not k5 lambda_c mu) and C27 (group "inc0" for the static and axial
    points, not "inc00"): loads = (rho/2) pi R^2 (Omega R)^2 C at mu = J sin(a), lambda_c = J cos(a)."""
    c = gill2019_coefficients()["apce_8x6"]
    d = gill2019_loads("apce_8x6", (6000.0,))
    R = pm.load_propeller("apce_8x6").radius
    om = 6000.0 * RPM
    assert d.omega.size == 1 + 6 * 7 and np.all(d.omega == om)
    adv = d.airspeed / (om * R)
    mu, lam = adv * np.sin(d.incidence), adv * np.cos(d.incidence)
    q = 0.5 * 1.225 * math.pi * R**2 * (om * R) ** 2
    np.testing.assert_allclose(d.measured["drag"], q * (c["k4"] * mu + c["k5"] * lam * mu), rtol=1e-13, atol=0)
    np.testing.assert_allclose(d.measured["thrust"], q * (c["CT_static"] + c["k1"] * lam + c["k2"] * mu**2
                                                          + c["k3"] * lam**2), rtol=1e-13)
    assert sorted(set(d.group)) == [f"inc{a:02d}" for a in (0, 15, 30, 45, 60, 75, 90)]
    assert np.sum(d.group == "inc00") == 7  # the static point and the six axial ones
    for rpm in ((50.0,), (60000.0,), ()):
        with pytest.raises(ValueError, match=r"rpm must be rotation rates in \[100, 50000\] rpm"):
            gill2019_loads("apce_8x6", rpm)
    with pytest.raises(ValueError, match="no published gill2019 coefficients for 'apce_9x6'; known: apce_8x6"):
        gill2019_loads("apce_9x6")


def test_gill2019_published_rises_are_normalised_by_their_own_static_value():
    """Mutant C31 (the published torque rise divided by CT_static): torque_rise = k7 mu^2 / CQ_static at
    mu = 0.2, the thrust rise k2 mu^2 / CT_static."""
    m = run_case("gill2019", {"g": pm.generic_params()})
    for k, c in enumerate(gill2019_coefficients().values()):
        assert m.measured["torque_rise"][k] == pytest.approx(c["k7"] * 0.04 / c["CQ_static"], rel=1e-12)
        assert m.measured["thrust_rise"][k] == pytest.approx(c["k2"] * 0.04 / c["CT_static"], rel=1e-12)


# ---- core/air.py: Air's defaults and the range check the records share

def test_air_defaults_are_gill_dandrea_2017_footnote_2():
    """Mutants A8, A9, A10: the defaults rho 1.225 kg/m^3, mu 1.983e-5 Pa s (footnote 2 of Gill &
    D'Andrea 2017, not Sutherland's 1.789e-5 at 288.15 K) and the ISA sea-level speed of sound 340.3 m/s."""
    a = pm.Air()
    assert (a.rho, a.mu, a.speed_of_sound) == (1.225, 1.983e-5, 340.3)
    # the footnote's viscosity is 11% above the ISA's Sutherland value at sea level
    assert a.mu / pm.Air.isa(0.0).mu == pytest.approx(1.983e-5 / 1.7894e-5, rel=1e-3)


@pytest.mark.parametrize("bad", [True, False])
def test_air_refuses_a_bool_for_a_density(bad):
    """Mutant A1 (bool check dropped): Air(rho=True) became rho 1.0."""
    with pytest.raises(ValueError, match=r"^rho must be a finite number in \(0, inf\) kg/m\^3, got (True|False)$"):
        pm.Air(rho=bad)


def test_air_refuses_text_for_a_viscosity():
    """Mutant A2 (the Real check dropped): Air(mu="1.8e-5") became 1.8e-5 silently."""
    with pytest.raises(ValueError, match=r"^mu must be a finite number in \(0, inf\) Pa s, got '1\.8e-5'$"):
        pm.Air(mu="1.8e-5")


@pytest.mark.parametrize("bad", [math.nan, math.inf])
def test_air_refuses_a_non_finite_speed_of_sound(bad):
    """Mutant A3 (the finiteness check dropped): nan and inf pass the (0, inf) range test."""
    with pytest.raises(ValueError, match=r"^speed_of_sound must be a finite number in \(0, inf\) m/s, got (nan|inf)$"):
        pm.Air(speed_of_sound=bad)


@pytest.mark.parametrize("name", ["rho", "mu", "speed_of_sound"])
def test_air_refuses_zero_with_the_open_interval_in_its_message(name):
    """Mutants A4 (the open lower end dropped), A31 (Air's values checked on [0, inf)), A6 and A7 (the
    brackets of the message swapped): a zero density, viscosity or speed of sound is refused, the
    range printed (0, inf) with its unit."""
    with pytest.raises(ValueError, match=rf"^{name} must be a finite number in \(0, inf\) \S+( s)?, got 0\.0$"):
        pm.Air(**{name: 0.0})
    assert getattr(pm.Air(**{name: 1e-300}), name) == 1e-300  # the smallest positive value is taken


def test_the_closed_upper_end_of_a_records_range_is_taken():
    """Mutant A5 (x >= high refused): the collective of a parameter set may be exactly COLLECTIVE_MAX
    (30 deg); one ulp above is refused with the closed range printed."""
    g = pm.generic_params()
    assert g.replace(collective=COLLECTIVE_MAX).collective == math.radians(30.0)
    above = math.nextafter(COLLECTIVE_MAX, 1.0)
    pattern = rf"^collective must be a finite number in \[{-COLLECTIVE_MAX}, {COLLECTIVE_MAX}\] rad, got "
    with pytest.raises(ValueError, match=pattern):
        g.replace(collective=above)


@pytest.mark.parametrize("call", [lambda: pm.Air.isa(True), lambda: pm.Air.from_conditions(True, 1e5)])
def test_isa_and_measured_air_refuse_a_bool(call):
    """Mutant A28 (_check_range's bool check dropped): Air.isa(True) was the air at 1 m."""
    with pytest.raises(ValueError, match=r"must be a finite number in \["):
        call()


# ---- simexport/files.py: the simulator coefficient files

@pytest.fixture(scope="module")
def rotorpy_export():
    """A small rotorpy export of apce_8x6 with its calibrated set (60 points; no point flagged)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 10.0), incidence_deg=(0.0, 90.0))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return prop, export_sim("rotorpy", prop, params, air=params.air, envelope=env, n_points=60, seed=0)


def _quad(prop, axes=None, inertia=np.diag([0.01, 0.011, 0.02])):
    """An X quadrotor of four ``prop`` (spins ccw, cw, ccw, cw), its rotor axes ``axes`` (default +z)."""
    d = 0.15 / math.sqrt(2)
    pos = [(d, d, 0.0), (d, -d, 0.0), (-d, -d, 0.0), (-d, d, 0.0)]
    axes = axes or [(0.0, 0.0, 1.0)] * 4
    rotors = tuple(Rotor(np.array(p), np.array(a), s, prop) for p, a, s in zip(pos, axes, (1, -1, 1, -1)))
    return Vehicle(mass=1.2, rotors=rotors, inertia=inertia, motor_time_constant=0.02, name="X")


@pytest.mark.parametrize("spin", [0, 2, "up"])
def test_rotorpy_directions_refuse_a_spin_that_is_no_direction(spin):
    """Mutant F8 (0 taken as a spin): a spin of 0 gave rotor_directions 0, a rotor without yaw reaction."""
    with pytest.raises(ValueError, match=rf"^spins\[1\] must be 'ccw', 'cw', \+1 or -1, got {spin!r}$"):
        rotorpy_directions(["ccw", spin])


def test_rotorpy_needs_the_vehicles_inertia(rotorpy_export):
    """Mutant F15 (the inertia check dropped): a vehicle without inertia fails with a clear ValueError
    before anything is written, not a TypeError from inside the writer."""
    prop, _ = rotorpy_export
    with pytest.raises(ValueError, match="^the vehicle file has no inertia: RotorPy's quad_params needs Ixx"):
        check_rotorpy_vehicle(_quad(prop, inertia=None))


@pytest.mark.parametrize("k", [0, 3])
def test_rotorpy_refuses_a_rotor_tilted_by_a_tenth_of_a_radian(rotorpy_export, tmp_path, k):
    """Mutants F16 (the +z test loosened to 0.5) and F34 (the first rotor's axis not checked): a rotor tilted
    0.1 rad (5.7 deg) forward cannot be written as RotorPy's +z thrust, whichever rotor it is."""
    prop, res = rotorpy_export
    axes = [(0.0, 0.0, 1.0)] * 4
    axes[k] = (math.sin(0.1), 0.0, math.cos(0.1))
    with pytest.raises(ValueError, match=rf"^rotor {k + 1}'s axis \[0\.0998334, 0, 0\.995004\] is not body \+z"):
        write_export(res, tmp_path / "c.py", vehicle=_quad(prop, axes))
    assert not (tmp_path / "c.py").exists() and not (tmp_path / "c.report.json").exists()


def test_error_table_says_n_a_where_no_point_is_flagged(rotorpy_export):
    """Mutant F2 (NaN printed as a percentage): with no point in vortex ring or multiple roots the
    flagged columns read n/a, not nan%."""
    _, res = rotorpy_export
    assert res.errors["points_flagged"] == 0
    lines = error_lines(res, "#")
    table = [ln for ln in lines if ln.startswith("#   ") and "flagged: " in ln]
    assert len(table) == 4 and all("(flagged: rms n/a, max n/a; fitted points: rms " in ln for ln in table)
    assert not any("nan" in ln for ln in lines)


def test_a_unicode_line_break_in_a_label_stays_in_its_comment(rotorpy_export, tmp_path):
    """Mutant F4 (only ASCII control characters replaced): U+2028, U+2029 and NEL (U+0085) end a line for
    str.splitlines and many editors; the label's text after them must not start a line of its own."""
    _, res = rotorpy_export
    for k, brk in enumerate(("\u2028", "\u2029", "\x85")):
        labelled = dataclasses.replace(res, meta={**res.meta, "params": f"x{brk}print('INJECTED')"})
        text = write_export(labelled, tmp_path / f"c{k}.py")[0].read_text(encoding="utf-8")
        assert "x print('INJECTED')" in text
        assert not any(ln.startswith("print(") for ln in text.splitlines())


@pytest.mark.parametrize("name", ["c.REPORT.JSON", "c.Report.Json"])
def test_a_coefficient_file_named_like_a_report_is_refused_in_any_case(rotorpy_export, tmp_path, name):
    """Mutant F20 (the .report.json test case-sensitive): on a case-insensitive file system c.REPORT.JSON is
    another export's report."""
    _, res = rotorpy_export
    with pytest.raises(ValueError, match=rf"^path: {re.escape(name)}: a name ending in \.report\.json is an export"):
        write_export(res, tmp_path / name)
    assert list(tmp_path.iterdir()) == []


def _tiny(target, params=None, airspeed=(0.0, 0.02)):
    """An export over an envelope of (nearly) static points, 60 of them: most terms fixed at 0."""
    prop = pm.load_propeller("apce_8x6")
    params = params or pm.default_params("apce_8x6")
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=airspeed)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return export_sim(target, prop, params, air=params.air, envelope=env, n_points=60, seed=0)


def test_report_names_the_file_it_describes_and_the_terms_fixed(tmp_path):
    """Mutants F23 (the report's file named by its full path, which moves with the pair), F25 (the terms held
    at their sign bound reported as fixed) and F35 (the fixed terms left out of the file's comments): the
    report records the file's name and SHA-256 and the terms the static envelope cannot determine."""
    res = _tiny("rotorpy")
    assert set(res.fixed) == {"k_h", "k_z", "k_d"} and res.held == {}
    path, report = write_export(res, tmp_path / "c.py")
    rep = json.loads(report.read_text(encoding="utf-8"))
    assert report.name == "c.report.json"
    assert rep["describes"] == {"file": "c.py", "sha256": hashlib.sha256(path.read_bytes()).hexdigest()}
    assert rep["fixed_at_zero"] == res.fixed and rep["held_at_sign_bound"] == {}
    text = path.read_text(encoding="utf-8")
    for name, why in res.fixed.items():
        assert f"# {name} fixed at 0: {why}" in text


def test_multinomial_json_lists_the_terms_fixed_at_zero(tmp_path):
    """Mutant F26 (the multinomial file's fixed_at_zero emptied): a program reading the coefficients must
    know which of the zeros are not fitted (18 of the 22 terms over a static envelope)."""
    res = _tiny("multinomial")
    path, _ = write_export(res, tmp_path / "m.json")
    data = json.loads(path.read_text(encoding="utf-8"))
    assert data["fixed_at_zero"] == res.fixed and len(res.fixed) == 18 and "CT[lambda]" in data["fixed_at_zero"]
    assert data["CT"][0] > 0 and data["CT"][1:] == [0.0] * 5  # only the static thrust term is fitted


def test_a_vehicle_is_refused_for_a_gazebo_target(rotorpy_export, tmp_path):
    """Mutant F21 (the target check dropped): a vehicle given with gz-sim was ignored silently; it is
    refused, and nothing is written."""
    prop, _ = rotorpy_export
    res = _tiny("gz-sim")
    msg = "^vehicle: a vehicle block is written for the rotorpy target only, not gz-sim$"
    with pytest.raises(ValueError, match=msg):
        write_export(res, tmp_path / "g.sdf", vehicle=_quad(prop))
    assert list(tmp_path.iterdir()) == []


def test_error_lines_give_the_envelopes_rpm_span_and_the_held_terms(tmp_path):
    """Mutants F28 (the static errors' rpm span printed as 4000-4000) and F30, F36 (the terms held at their sign
    bound left out of the comments and the report): the held terms are said with the unbounded fit's value."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6").replace(inplane_induction=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = export_sim("rotorpy", prop, params, air=params.air, n_points=60, seed=0)  # the default envelope
    lines = error_lines(res, "#")
    assert lines[0].endswith("over rpm 4700-14100") and "(rpm 4700-14100, V 0-15 m/s," in lines[1]
    assert list(res.held) == ["k_z"] and res.held["k_z"].startswith("held at 0, the bound of its physical sign")
    assert f"# k_z {res.held['k_z']}" in lines
    rep = json.loads(write_export(res, tmp_path / "c.py")[1].read_text(encoding="utf-8"))
    assert rep["held_at_sign_bound"] == res.held


def test_an_edgewise_trend_the_model_could_not_compute_is_left_out(rotorpy_export):
    """Mutant F29 (the NaN test dropped): where the full model did not converge edgewise, export_sim records
    the trend as NaN; the comments then leave the line out instead of printing '+nan%'."""
    _, res = rotorpy_export
    u = res.meta["model_uncertainty"]
    assert any("thrust change from hover to 10 m/s edgewise at 6000 rpm: " in ln for ln in error_lines(res, "#"))
    failed = dataclasses.replace(res, meta={**res.meta, "model_uncertainty": {
        **u, "edgewise_trend": {**u["edgewise_trend"], "this_set": math.nan}}})
    lines = error_lines(failed, "#")
    assert not any("thrust change from hover" in ln or "nan" in ln for ln in lines)
    assert len(lines) == len(error_lines(res, "#")) - 1


def test_error_lines_count_the_check_points_apart_from_the_fitted(rotorpy_export):
    """Mutant F33 (the check points' count taken as the fitted points'): export_sim records how many check points
    converged (meta check_points), which may be fewer than the points fitted; the table says that number."""
    _, res = rotorpy_export
    assert res.meta["check_points"] == res.n_points == 60
    fewer = dataclasses.replace(res, meta={**res.meta, "check_points": 57})
    assert ", on 57 check points other than the 60 fitted (0 flagged):" in error_lines(fewer, "#")[1]
