"""Tests for the gaps a mutation audit of stop 94's change found (helper, 2026-12-01: 71 mutants, 21
survivors). Each test fails on the mutant named in its comment. Data: loads made by propmap's
model for the catalogue's APC 8x6E with its calibrated set."""

import json
import math
from dataclasses import replace

import numpy as np
import pytest

import propmap as pm
from cli_helpers import run
from propmap.identify.load_data import LoadData
from propmap.identify.sanity import sanity_check

PROP = "apce_8x6"


def _static(rpm):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pm.TipMachWarning)
        r = pm.rotor_loads(pm.load_propeller(PROP), pm.default_params(PROP), np.asarray(rpm) * math.pi / 30, 0.0,
                           0.0)
    return r.thrust, r.torque


def test_an_optical_speed_seven_times_high_is_told_to_name_the_electrical_column():  # SAN1 (!= "rpm")
    rpm = np.arange(3000.0, 9000.0, 1000.0)
    T, Q = _static(rpm)
    data = LoadData(7 * rpm * math.pi / 30, np.zeros(rpm.size), np.zeros(rpm.size), {"thrust": T, "torque": Q},
                    np.full(rpm.size, "all", dtype=object), "x.csv", speed_source="optical")
    with pytest.raises(ValueError) as e:
        sanity_check(data, pm.load_propeller(PROP))
    assert "name the column 'Motor Electrical Speed (RPM)'" in str(e.value)
    assert "give that count as --pole-pairs" not in str(e.value)


def _sweep(tmp_path, header, airspeed_factor=1.0, thrust_factor=1.0, torque_factor=1.0):
    """Points at 6000 and 8000 rpm, 0-12 m/s axial, written with the factors, unlabelled."""
    p, prop = pm.default_params(PROP), pm.load_propeller(PROP)
    rows = []
    for rpm in (6000.0, 8000.0):
        for V in (0.0, 3.0, 6.0, 9.0, 12.0):
            r = pm.rotor_loads(prop, p, rpm * math.pi / 30, V, 0.0)
            rows.append(f"{rpm:.0f},{V * airspeed_factor:.6g},0,{float(r.thrust) * thrust_factor:.6g},"
                        f"{float(r.torque) * torque_factor:.6g}")
    path = tmp_path / "s.csv"
    path.write_text(header + "\n" + "\n".join(rows) + "\n")
    return path


def test_an_airspeed_in_km_h_is_named(tmp_path):  # SAN5 (the km/h slip's factor)
    from propmap.identify import read_loads

    path = _sweep(tmp_path, "rpm,airspeed,incidence_deg,thrust,torque", airspeed_factor=3.6)
    with pytest.raises(ValueError, match=r"an airspeed in km/h read as m/s"):
        sanity_check(read_loads(path), pm.load_propeller(PROP))


def test_thrust_in_ozf_with_torque_in_oz_in_is_named(tmp_path):  # SAN6 (OZF = LBF / 12)
    from propmap.identify import read_loads, sanity

    # (the slip's band, 0.6-1.6 of the model, takes 16/12 too: the factors themselves, 1 ozf = 0.27801385 N)
    assert sanity.OZF == pytest.approx(0.278013850953781, rel=1e-12) and sanity.GF == pytest.approx(9.80665e-3)

    ozf = 4.4482216152605 / 16
    path = _sweep(tmp_path, "rpm,airspeed,incidence_deg,thrust,torque", thrust_factor=1 / ozf,
                  torque_factor=1 / (ozf * 0.0254))
    with pytest.raises(ValueError, match=r"thrust in ozf and torque in ozf in read as N and N m"):
        sanity_check(read_loads(path), pm.load_propeller(PROP))


def test_a_level_flight_fit_with_partial_interference_takes_differences():  # LFF3 (interference < 1)
    from propmap.identify import FitOptions, fit_level_flight, simulate_level_flight

    quad, true = pm.read_vehicle("quadrotor"), pm.preset("gill2017-apc").replace(M=30.0)
    V = np.linspace(0.0, 14.0, 12)
    veh = replace(quad, rotor_interference=0.5)
    data = simulate_level_flight(veh, true, V, -2.5 * V)
    x = np.array([true.cl1, true.cl2, true.cd, true.alpha0])
    r = fit_level_flight(data, veh, options=FitOptions(M=30.0), start=1.02 * x)
    assert np.allclose(r.x, x, rtol=1e-6)


def _samples(n=40):
    from propmap.identify.flight import FlightSamples

    return FlightSamples(log_names=("x",), log_index=np.zeros(n, int), t=np.arange(n) * 0.1,
                         velocity=np.zeros((n, 3)), angular_velocity=np.zeros((n, 3)),
                         rotor_omega=np.full((n, 4), 1000.0), rotor_acceleration=np.zeros((n, 4)),
                         force=np.zeros((n, 3)), moment=None, reference_force=None, reference_moment=None, rate_hz=10.0)


@pytest.mark.parametrize("kw, match", [({"options": "x"}, "options must be a propmap.identify.FitOptions"),  # FL2
                                       ({"body": {"drag_area": 0.1}}, "body must be a propmap.BodyDrag"),  # FL4
                                       ({"base": 1.0}, "base must be AirfoilParams or CamberedParams")])  # FL1
def test_fit_flight_refuses_other_wrong_types(kw, match):
    from propmap.identify.flight import fit_flight

    with pytest.raises(TypeError, match=match):
        fit_flight(_samples(), pm.read_vehicle("neurobem_quadrotor"), **kw)


def test_the_jackknife_cuts_a_low_end_at_its_bound():  # DEP2 (the low end left uncut)
    from types import SimpleNamespace

    from propmap.identify.dependence import jackknife_report

    result = SimpleNamespace(names=("cd_min", "cl_max"), x=np.array([0.01, 1.2]),
                             identifiability=SimpleNamespace(std_error=np.array([0.004, 0.1])))
    folds = [{"cd_min": v, "cl_max": c} for v, c in ((0.002, 1.1), (0.018, 1.3), (0.006, 1.25), (0.014, 1.15))]
    rep = jackknife_report(result, folds, "run", ["a", "b", "c", "d"], bounds=(np.array([0.002, 0.2]),
                                                                                np.array([0.2, 1.25])))
    assert rep["ci95"]["cd_min"][0] == 0.002 and rep["ci95_cut_at_bound"]["cd_min"] == [True, False]
    assert rep["ci95"]["cl_max"][1] == 1.25 and rep["ci95_cut_at_bound"]["cl_max"] == [False, True]


def test_a_level_flight_report_counts_conditions():  # RES1 ("residuals" for level flight)
    from test_audit_section_report import _fit

    auto = {"lag1": 0.3, "n_effective": 50.0, "n": 100}
    text = _fit(extra={"kind": "level_flight", "residual_autocorrelation": auto}).report_text()
    assert "the information of about 50 independent conditions of 100" in text


def _loads_csv(tmp_path, with_static_group=True):
    prop, p = pm.load_propeller(PROP), pm.default_params(PROP)
    # (group a holds six distinct points: a fit needs six, held-out groups aside, since 2026-12-01)
    om = np.array([5000, 7000, 5000, 7000, 6000, 6000, 5500, 6500]) * math.pi / 30
    V = np.array([0, 0, 4, 6, 5, 8.0, 3, 7])
    b = np.radians([0, 0, 30, 60, 45, 90.0, 15, 75])
    r = pm.rotor_loads(prop, p, om, V, b)
    group = ["s", "s", "a", "a", "a", "a", "a", "a"]
    rows = "".join(f"{g},{o * 30 / math.pi:.6f},{v},{math.degrees(i):.6f},{t:.8g},{d:.8g},{q:.8g}\n"
                   for g, o, v, i, t, d, q in zip(group, om, V, b, r.thrust, r.drag, r.torque))
    path = tmp_path / "d.csv"
    path.write_text("group,rpm,airspeed,incidence_deg,thrust,drag,torque\n" + rows)
    return path


def test_a_held_out_static_group_has_no_in_plane_score(tmp_path, capsys):  # CF2 (an empty row set scored)
    path = _loads_csv(tmp_path)
    code, out, err = run(capsys, "fit", "loads", path, "--prop", PROP, "--base", f"calibrated:{PROP}", "--holdout",
                         "s", "--skip-sanity-check", "--fit-params", "cd_min,alpha_L0", "--out", tmp_path / "p.toml")
    assert code == 0, err
    held = json.loads((tmp_path / "p.report.json").read_text())["holdout"]
    assert held["fitted"]["drag_rmse"] is None and held["fitted"]["thrust_rmse"] is not None
    assert "drag_rmse - (no held-out point)" in (tmp_path / "p.report.txt").read_text()


def _two_set_vehicle(tmp_path, top=False):
    """The example quadrotor, rotors 1-2 on one parameter file, 3-4 on another (``top``: the vehicle
    file's own set as well)."""
    from propmap.io.params_file import write_params

    p = pm.default_params(PROP)
    write_params(tmp_path / "a.toml", p.replace(air=pm.Air(rho=1.0)))
    write_params(tmp_path / "b.toml", p.replace(air=pm.Air(rho=1.1)))
    blocks = pm.example_file("quadrotor.toml").read_text().split("[[rotors]]")
    head = blocks[0] + ('params = "b.toml"\n' if top else "")
    text = head + "".join("[[rotors]]" + b.replace('propeller = "apce_8x6"\n',
                                                   f'propeller = "apce_8x6"\nparams = "{name}"\n')
                          for b, name in zip(blocks[1:], ("a.toml", "a.toml", "b.toml" if not top else "a.toml",
                                                         "b.toml" if not top else "a.toml")))
    (tmp_path / "q.toml").write_text(text)
    return tmp_path / "q.toml"


def test_export_sim_takes_no_rotor_set_where_they_differ_and_the_vehicles_own_first(tmp_path, capsys):  # CV3, CV4
    path = _two_set_vehicle(tmp_path)
    code, out, err = run(capsys, "export-sim", PROP, "--target", "rotorpy", "--vehicle", path, "--hover-rpm", "5400",
                         "--json", "--out", tmp_path / "x.py")
    assert code == 0, err
    assert json.loads(out)["params"] == f"calibrated:{PROP}" and json.loads(out)["rho"] == 1.225
    other = tmp_path / "top"
    other.mkdir()
    path = _two_set_vehicle(other, top=True)
    code, out, err = run(capsys, "export-sim", PROP, "--target", "rotorpy", "--vehicle", path, "--hover-rpm", "5400",
                         "--json", "--out", other / "x.py")
    assert code == 0, err
    # (every rotor names a.toml: since stop 96, 2026-12-01, the rotors' one set comes before the vehicle file's own,
    # b.toml, as propmap.resolve_vehicle and trim-vehicle take it; this case expected b.toml, and failed from 02b6f16)
    assert json.loads(out)["params"].endswith("a.toml") and json.loads(out)["rho"] == 1.0


def test_export_sims_rotor_air_and_interference_warnings_go_where_they_belong(tmp_path, capsys):  # ES2, ES4
    from propmap.io.params_file import write_params

    write_params(tmp_path / "thin.toml", pm.default_params(PROP).replace(air=pm.Air(rho=1.0)))
    blocks = pm.example_file("quadrotor.toml").read_text().split("[[rotors]]")
    text = blocks[0].replace("mass = 0.8\n", "mass = 0.8\nrotor_interference = 1.0\n") + "".join(
        "[[rotors]]" + (b.replace('propeller = "apce_8x6"\n', 'propeller = "apce_8x6"\nparams = "thin.toml"\n')
                        if k < 2 else b) for k, b in enumerate(blocks[1:]))
    (tmp_path / "q.toml").write_text(text)
    code, _, err = run(capsys, "export-sim", PROP, "--target", "rotorpy", "--vehicle", tmp_path / "q.toml",
                       "--hover-rpm", "5400", "--out", tmp_path / "x.py")
    assert code == 0 and "has no RotorPy term" in err, err
    code, _, err = run(capsys, "export-sim", PROP, "--target", "gz-sim", "--vehicle", tmp_path / "q.toml",
                       "--out", tmp_path / "x.sdf")
    assert code == 0 and "RotorPy" not in err, err
    # (rotors 1 and 2 on a set of their own, 3 and 4 on none: no one set; the hover from the vehicle, in PROP's
    # set's air, which the two rotors' set is not in)
    code, _, err = run(capsys, "export-sim", PROP, "--target", "rotorpy", "--vehicle", tmp_path / "q.toml",
                       "--out", tmp_path / "y.py")
    assert code == 0 and "rotor(s) 1, 2 carry parameter sets in other air (rho 1 kg/m^3)" in err, err


def test_a_vehicle_map_of_another_size_is_not_said_to_differ_in_chord(tmp_path):  # VM3
    import warnings

    from propmap.maps import build_map
    from propmap.rotormap import RotorMap

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m = RotorMap(build_map(pm.load_propeller("apce_10x7"), pm.default_params("apce_10x7"),
                               np.linspace(400.0, 800.0, 3), np.array([0.0, 5.0]), np.radians([0.0, 90.0, 180.0]),
                               n_check=0))
    with pytest.raises(ValueError) as e:
        pm.VehicleMap(pm.read_vehicle("quadrotor"), m)
    assert "map is of apce_10x7" in str(e.value) and "another chord" not in str(e.value)


def test_the_load_fit_says_its_tip_mach_as_a_tip_mach_warning():  # FIT1 (a UserWarning)
    from propmap.identify import FitOptions, fit_loads

    prop = pm.load_propeller(PROP)
    rpm = np.array([10000.0, 20000.0, 30000.0, 32000.0, 34000.0, 36000.0])
    T, Q = _static(rpm)
    data = LoadData(rpm * math.pi / 30, np.zeros(rpm.size), np.zeros(rpm.size), {"thrust": T, "torque": Q},
                    np.full(rpm.size, "all", dtype=object))
    with pytest.warns(pm.TipMachWarning, match="said once for the fit"):
        fit_loads(data, prop, base=pm.default_params(PROP), options=FitOptions(names=("cd_min",), prior=False))


def test_the_json_of_trim_vehicle_and_wrench_and_the_exports_head_give_the_whole_air(tmp_path, capsys,
                                                                                  shared_data):  # TRV1, CFL2, SF2
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "quadrotor", "--rho", "1.1", "--json")
    assert code == 0, err
    assert json.loads(out)["air"] == {"rho": 1.1, "mu": 1.983e-05, "speed_of_sound": 340.3}
    log = shared_data / "neurobem_flights" / "bemnn20210223104803seg2.mat"
    code, out, err = run(capsys, "wrench", log, "--vehicle", "neurobem_quadrotor", "--json", "--out",
                         tmp_path / "w.csv")
    assert code == 0, err
    assert json.loads(out)["air"] == {"rho": 1.204, "mu": 1.983e-05, "speed_of_sound": 340.3}
    code, _, err = run(capsys, "export-sim", PROP, "--target", "rotorpy", "--altitude-m", "1000", "--out",
                       tmp_path / "e.py")
    assert code == 0, err
    head = (tmp_path / "e.py").read_text()
    assert "in air of rho 1.11" in head and "mu 1.758e-05 Pa s" in head and "speed of sound 336.4 m/s" in head


def test_validate_with_a_users_data_names_the_air(tmp_path, capsys):  # VAL2
    path = _loads_csv(tmp_path)
    code, out, err = run(capsys, "validate", path, "--prop", PROP, "--rho", "1.1")
    assert code == 0, err
    assert "air rho 1.1 kg/m^3, mu 1.983e-05 Pa s" in out
