"""Edges of a user's own measurements and geometry found by two user-level audits (2026-11-26):
a wind tunnel's airspeed and angle columns with an underscore unit, its wind-axis lift and drag,
incidences in radians under a degrees name, a vehicle whose rotors name their own parameter
file, coverage warnings at the data's own edge, geometry files with commas or stations that
start far out, a vehicle map of another propeller and shapes that do not broadcast."""

import math
import shutil
import warnings
import os
import re
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.identify import DataError, read_loads
from propmap.identify.load_data import radians_hint
from propmap.identify.stand import map_columns
from propmap.io.geometry_files import FIRST_STATION_MAX, GeometryFileError, read_geometry

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"


@pytest.mark.parametrize("name", ["freestream_mps", "V_inf_ms", "tunnel_speed_m_s", "freestream_kmh"])
def test_an_airspeed_under_another_name_with_an_underscore_unit_is_refused(name):
    """Every point would have been read as static (the audit's tunnel sweep fitted as a static run)."""
    with pytest.raises(ValueError, match=f"column '{name}' looks like an airspeed"):
        map_columns(["rpm", name, "thrust_kgf", "Torque (N m)"])


@pytest.mark.parametrize("name", ["alpha_deg", "aoa_deg", "disk_angle_deg", "AoA_rad", "flow_angle_deg",
                                  "angle_deg", "tilt_deg", "yaw_deg", "beta_deg", "pitch_deg", "beta_rad"])
def test_a_flow_angle_under_another_name_with_an_underscore_unit_is_refused(name):
    with pytest.raises(ValueError, match=f"column '{name}' looks like a flow angle"):
        map_columns(["rpm", "airspeed", name, "thrust"])


def test_a_temperature_in_degrees_is_not_a_flow_angle():
    cm = map_columns(["rpm", "airspeed", "temp_deg", "motor_temp_degrees", "thrust"])
    assert "incidence_deg" not in cm.columns


def test_a_known_name_written_with_underscores_is_read():
    cm = map_columns(["rpm", "wind_speed_mps", "thrust_kgf"])
    assert cm.columns["airspeed"][:2] == ("wind_speed_mps", 1.0)
    assert cm.columns["thrust"][1] == pytest.approx(9.80665)
    cm = map_columns(["rpm", "air_speed_kmh", "thrust"])
    assert cm.columns["airspeed"][1] == pytest.approx(1 / 3.6)


@pytest.mark.parametrize("name", ["lift (N)", "Lift_N", "lift"])
def test_a_wind_axis_lift_column_is_refused_with_the_conversion(name):
    """A tunnel's lift and drag were read as... the drag as the rotor's in-plane force and the lift
    not at all (the fit ran to its bounds, exit 0)."""
    with pytest.raises(ValueError, match=r"thrust = L sin\(i\) - D cos\(i\), in-plane force = L cos\(i\) \+ D sin"):
        map_columns(["rpm", "airspeed", "incidence_deg", name, "drag (N)", "torque (N m)"])


def test_the_lift_and_drag_conversion_inverts_the_wind_axes():
    """The message's conversion: the rotor's loads in wind axes (drag along the freestream, lift
    normal to it on the rotor axis' side, 90 deg: the thrust) and back give T and H."""
    prop = pm.load_propeller("apce_8x6")
    i = np.radians([0.0, 30.0, 60.0, 90.0, 120.0])
    r = pm.rotor_loads(prop, pm.generic_params(), 700.0, 8.0, i)
    a, e = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])  # rotor axis; in-plane direction of motion
    u = np.cos(i)[:, None] * a + np.sin(i)[:, None] * e  # direction of motion
    F = r.thrust[:, None] * a - r.drag[:, None] * e
    n = np.sin(i)[:, None] * a - np.cos(i)[:, None] * e
    L, D = np.sum(F * n, axis=1), -np.sum(F * u, axis=1)
    assert L[-2] == pytest.approx(r.thrust[-2])  # edgewise: the lift is the thrust
    assert D[0] == pytest.approx(-r.thrust[0])  # axial: the thrust is a negative drag
    np.testing.assert_allclose(L * np.sin(i) - D * np.cos(i), r.thrust, rtol=1e-12)
    np.testing.assert_allclose(L * np.cos(i) + D * np.sin(i), r.drag, rtol=1e-9, atol=1e-12)


def _tunnel_csv(path: Path, incidences, header="incidence_deg") -> Path:
    rows = ["rpm,airspeed," + header + ",thrust,drag,torque"]
    prop = pm.load_propeller("apce_8x6")
    for rpm in (5000.0, 7000.0):
        for V in (0.0, 5.0, 10.0):
            for inc in incidences:
                r = pm.rotor_loads(prop, pm.generic_params(), rpm * math.pi / 30, V, math.radians(inc))
                rows.append(f"{rpm},{V},{inc},{float(r.thrust)},{float(r.drag)},{float(r.torque)}")
    path.write_text("\n".join(rows) + "\n")
    return path


def test_incidences_in_radians_under_a_degrees_name_are_warned(tmp_path):
    rad = np.radians([0.0, 30.0, 60.0, 90.0])
    with pytest.warns(UserWarning, match=r"incidences up to 1.5708 deg at airspeed: radians\? \(1.5708 rad = 90 deg"):
        read_loads(_tunnel_csv(tmp_path / "rad.csv", rad))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_loads(_tunnel_csv(tmp_path / "deg.csv", [0.0, 30.0, 60.0, 90.0]))  # degrees: nothing said
        read_loads(_tunnel_csv(tmp_path / "unit.csv", rad, "incidence (deg)"))  # a unit given is believed
    assert radians_hint([0.0, 1.0], [5.0, 5.0]) is None  # whole degrees
    assert radians_hint([0.5, 1.2], [0.0, 0.0]) is None  # static: the angle does not matter
    assert radians_hint([0.5, 1.2, 45.0], [5.0] * 3) is None
    assert "up to 3.142 deg" in radians_hint([0.0, 1.571, 3.142], [5.0] * 3)  # to axial descent, rounded
    # degrees after all: a measured misalignment, a small-angle sweep (not whole degrees as radians)
    assert radians_hint([0.0, 0.0, 0.12, 0.12], [5.0, 10.0, 5.0, 10.0]) is None
    assert radians_hint([0.0, 0.5, 1.0, 1.5, 2.0, 2.5], [5.0] * 6) is None
    assert radians_hint([1.5, 1.5], [5.0, 5.0]) is None


def test_incidences_in_radians_are_not_also_blamed_on_the_airspeeds_unit(tmp_path):
    """Loads measured at 0-150 deg written with their incidences in radians under 'incidence_deg':
    the reader's radians warning is the cause; the sanity check's airspeed-unit search, whose
    thrust at airspeed misfits too, named km/h as well (a user-level audit, 2026-11-28)."""
    from propmap.identify import sanity_check

    prop = pm.load_propeller("apce_8x6")
    # (a section off the generic set's, as the audit's: with the generic set itself the misfit stays small)
    truth = pm.generic_params().replace(cl_alpha=5.5, alpha_L0=math.radians(-6), cl_max=1.6, cd_min=0.015, cd2=0.08)
    rows = ["rpm,airspeed,incidence_deg,thrust,torque"]
    for rpm in (5000.0, 7000.0, 9000.0):
        for V in (0.0, 4.0, 8.0, 12.0):
            for deg in (0.0, 30.0, 60.0, 90.0, 120.0, 150.0):
                r = pm.rotor_loads(prop, truth, rpm * math.pi / 30, V, math.radians(deg))
                rows.append(f"{rpm},{V},{math.radians(deg):.4f},{float(r.thrust)},{float(r.torque)}")
    path = tmp_path / "rad.csv"
    path.write_text("\n".join(rows) + "\n")
    with pytest.warns(UserWarning, match="radians"):
        data = read_loads(path)
    said = sanity_check(data, prop)
    assert not any("km/h" in w or "knots" in w or "mph" in w for w in said), said


def test_points_with_incidences_in_radians_are_warned(tmp_path, capsys):
    pts = tmp_path / "pts.csv"
    pts.write_text("rpm,airspeed,incidence_deg\n6000,5,0\n6000,5,0.5236\n6000,5,1.5708\n")
    assert main(["loads", "apce_8x6", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 0
    assert "incidence_deg: incidences up to 1.5708 deg at airspeed: radians?" in capsys.readouterr().err
    pts.write_text("rpm,airspeed,incidence (deg)\n6000,5,0\n6000,5,0.5236\n6000,5,1.5708\n")  # a unit stated
    assert main(["loads", "apce_8x6", "--points", str(pts), "--out", str(tmp_path / "o2.csv")]) == 0
    assert "radians?" not in capsys.readouterr().err


@pytest.mark.slow
def test_wrench_names_the_rotors_own_parameter_file(tmp_path, capsys, shared_data):
    """The vehicle file's rotors name their set: wrench used it but printed 'generic' and gave the
    generic set's coverage warnings, none of the file's."""
    shutil.copy(EXAMPLES / "neurobem_quadrotor.toml", tmp_path / "v.toml")
    shutil.copy(EXAMPLES / "neurobem_5.1x4.8_geom.txt", tmp_path / "neurobem_5.1x4.8_geom.txt")
    pm.write_params(tmp_path / "mine.toml", pm.generic_params().replace(cl_alpha=5.5))
    # (the rotors' sets alone, without the vehicle's own)
    text = (tmp_path / "v.toml").read_text().replace('params = "neurobem_quadrotor.params.toml"\n', "")
    (tmp_path / "v.toml").write_text(text.replace('propeller = "neurobem_5.1x4.8_geom.txt"',
                                                  'propeller = "neurobem_5.1x4.8_geom.txt"\nparams = "mine.toml"'))
    assert pm.vehicle.file.rotor_file_specs(tmp_path / "v.toml") == (str(tmp_path / "mine.toml"),) * 4
    geometry = str(tmp_path / "neurobem_5.1x4.8_geom.txt")
    assert pm.vehicle.file.rotor_file_specs(tmp_path / "v.toml", "propeller") == (geometry,) * 4
    log = shared_data / "neurobem_flights" / "bemnn20210223104803seg2.mat"
    assert main(["wrench", str(log), "--vehicle", str(tmp_path / "v.toml"), "--out", str(tmp_path / "w.csv")]) == 0
    out = capsys.readouterr().out
    assert f"params {tmp_path / 'mine.toml'}" in out and "mine.toml)" in out and "generic" not in out
    assert main(["wrench", str(log), "--vehicle", str(tmp_path / "v.toml"), "--params", str(tmp_path / "mine.toml"),
                 "--out", str(tmp_path / "w2.csv")]) == 0
    capsys.readouterr()
    assert (tmp_path / "w.csv").read_bytes() == (tmp_path / "w2.csv").read_bytes()
    # one rotor with its own set, whose data reach 2000 rpm, the others the generic set: each set's coverage
    pm.write_params(tmp_path / "low.toml", pm.generic_params(), coverage={"rpm_min": 1000.0, "rpm_max": 2000.0})
    mixed = text.replace('propeller = "neurobem_5.1x4.8_geom.txt"', 'propeller = "neurobem_5.1x4.8_geom.txt"\n'
                         'params = "low.toml"', 1)
    (tmp_path / "mixed.toml").write_text(mixed)
    assert main(["wrench", str(log), "--vehicle", str(tmp_path / "mixed.toml"), "--out", str(tmp_path / "w3.csv")]) == 0
    out, err = capsys.readouterr()
    assert "params the vehicle's rotor sets: " in out and "generic" in out
    assert f"the data behind {tmp_path / 'low.toml'} span 1000-2000 rpm" in err
    assert "generic was fitted to axial data only" in err


def test_no_coverage_warning_at_the_datas_own_edges(tmp_path, capsys):
    """A fit's [coverage] holds 6999.999999999999 rpm (from rad/s) and J = 0 for static data:
    7000 rpm, and exactly edgewise flight (cos 90 deg = 6e-17), are not beyond them."""
    p = tmp_path / "p.toml"
    pm.write_params(p, pm.default_params("apce_8x6"), coverage={"rpm_min": 3999.9999999999995, "J_max": 0.0,
                                                               "rpm_max": 6999.999999999999, "incidence_deg_max": 90.0})
    assert main(["loads", "apce_8x6", "--params", str(p), "--rpm", "7000", "--airspeed", "5", "--incidence-deg",
                 "90"]) == 0
    assert "warning" not in capsys.readouterr().err
    assert main(["loads", "apce_8x6", "--params", str(p), "--rpm", "7100", "--airspeed", "5", "--incidence-deg",
                 "80"]) == 0
    err = capsys.readouterr().err
    assert "7100 rpm: the data behind" in err and "advance ratio up to 0.04" in err  # 5 cos(80 deg) / (n D)


def test_geometry_with_commas_or_without_its_header_says_what_is_expected(tmp_path):
    g = tmp_path / "g.csv"
    g.write_text("r/R,c/R,beta\n0.15,0.1,30\n0.5,0.15,20\n1.0,0.05,10\n")
    with pytest.raises(GeometryFileError, match="separated by commas or semicolons: a UIUC file's are separated by "
                                                "blanks"):
        read_geometry(g, diameter_in=10, n_blades=2)
    g.write_text("0.15 0.1 30\n0.5 0.15 20\n1.0 0.05 10\n")
    with pytest.raises(GeometryFileError, match="starts with its header line 'r/R c/R beta'"):
        read_geometry(g, diameter_in=10, n_blades=2)


def test_geometry_starting_far_out_is_warned(tmp_path):
    g = tmp_path / "g_geom.txt"
    g.write_text("r/R c/R beta\n0.6 0.15 20\n0.8 0.12 15\n1.0 0.05 10\n")
    with pytest.warns(UserWarning, match="the stations start at r/R = 0.6: the blade inside it makes no load"):
        read_geometry(g, diameter_in=10, n_blades=2)
    g.write_text(f"r/R c/R beta\n{FIRST_STATION_MAX} 0.15 20\n0.8 0.12 15\n1.0 0.05 10\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_geometry(g, diameter_in=10, n_blades=2)


def test_a_vehicle_map_of_another_propeller_is_refused():
    """The NeuroBEM vehicle (5.1 in, 3 blades) with an APC 8x6E map gave 38 N at 1200 rad/s, 6x its rotors'."""
    prop = pm.load_propeller("apce_8x6")
    m = pm.build_map(prop, pm.generic_params(), np.linspace(400, 800, 4), np.linspace(0, 10, 4),
                     np.radians(np.linspace(0, 180, 4)), n_check=0)
    rm = pm.RotorMap(m)
    with pytest.raises(ValueError, match=r"rotor 1's map is of apce_8x6 \(0.2032 m, 2 blades\), its propeller "
                                         r"neurobem_5.1x4.8 is 0.1295 m with 3 blades"):
        pm.VehicleMap(pm.read_vehicle(EXAMPLES / "neurobem_quadrotor.toml"), rm)
    pm.VehicleMap(pm.read_vehicle(EXAMPLES / "quadrotor.toml"), rm)  # its APC 8x6E rotors


def test_rotor_wrench_names_shapes_that_do_not_broadcast():
    with pytest.raises(ValueError, match=r"velocity \(shape \(5, 3\)\) and axis \(shape \(4, 3\)\) must broadcast"):
        pm.rotor_wrench(pm.load_propeller("apce_8x6"), pm.generic_params(), np.zeros((5, 3)),
                        np.tile([0.0, 0.0, 1.0], (4, 1)), 800.0)


def test_the_c_headers_map_warning_uses_its_own_interpolation():
    from propmap.cli.map import _target_misses

    attrs = {"check_cubic_torque_max": 0.014, "check_linear_torque_max": 0.0131, "check_cubic_thrust_max": 0.002,
             "check_linear_thrust_max": 0.012}
    assert _target_misses(attrs) == {"torque": pytest.approx(1.4)}
    assert _target_misses(attrs, "linear") == {"thrust": pytest.approx(1.2), "torque": pytest.approx(1.31)}


def test_read_loads_refuses_a_lift_column_with_exit_2(tmp_path, capsys):
    f = tmp_path / "wind.csv"
    f.write_text("rpm,airspeed,incidence_deg,lift (N),drag (N),torque (N m)\n5000,5,30,3,1,0.05\n6000,5,60,4,1,0.06\n")
    with pytest.raises(DataError, match="column 'lift \\(N\\)'"):
        read_loads(f)
    assert main(["fit", "loads", str(f), "--prop", "apce_8x6", "--out", str(tmp_path / "o.toml")]) == 2
    assert not (tmp_path / "o.toml").exists()


def _incidence_data(compliance: float, noise: float, seed: int = 1):
    from propmap.identify import LoadData

    prop = pm.load_propeller("apce_10x7")
    truth = pm.default_params("apce_10x7").replace(flap_compliance=compliance)
    rpm, V, inc = (a.ravel() for a in np.meshgrid([4000.0, 5500.0, 7000.0], [0.0, 5.0, 10.0, 15.0],
                                                  np.radians([0.0, 30.0, 60.0, 90.0]), indexing="ij"))
    om = rpm * math.pi / 30
    r = pm.rotor_loads(prop, truth, om, V, inc)
    rng = np.random.default_rng(seed)
    measured = {k: getattr(r, k) * (1 + noise * rng.standard_normal(om.size)) for k in ("thrust", "drag", "torque")}
    return prop, LoadData(om, V, inc, measured, np.full(om.size, "all", dtype=object), "synthetic")


def test_a_saturated_flap_compliance_has_its_interval_to_the_bound():
    """Beyond a few rad/(N m) the blades flap nearly as articulated ones: 0.5% noise on loads made
    with a compliance of 20 cannot tell the fitted 30 from 50, and the interval says so instead of
    the local slope's (a user-level audit: 7-50 fitted for a true 15, each with about +-10%).
    (1% noise and seed 2 fitted 26 until the in-plane force's residuals left the axial points out,
    2026-11-26; since then 50, the bound: the case moved to 0.5%.)"""
    from propmap.identify import fit_loads
    from propmap.identify.engine import _bounds

    prop, data = _incidence_data(20.0, 0.005, seed=2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = fit_loads(data, prop, base=pm.default_params("apce_10x7"))
    j = res.names.index("flap_compliance")
    assert "flap_compliance" not in res.at_bound and 15.0 < res.x[j] < 40.0
    lo, hi = res.identifiability.ci95[j]
    assert hi == 50.0 and 0.0 <= lo < res.x[j]
    assert any("flapping saturates, so the 95% interval reaches the bound" in w for w in res.warnings)
    # every interval within its bounds (the compliance's linearised one reached below 0 here)
    lb, ub = _bounds(res.names, pm.identify.FitOptions())
    ci = res.identifiability.ci95
    assert np.all((ci[:, 0] >= lb) & (ci[:, 1] <= ub) | np.isnan(ci[:, 0]))
    # the report marks an end that is the bound's, not the data's (a new-user audit read "[7.565, 9]" as the data's)
    cut = res.identifiability.ci95_cut
    assert cut[j, 1] and cut[j, 0] == (lo == lb[j])
    assert np.all(~cut[:, 0] | (ci[:, 0] == lb)) and np.all(~cut[:, 1] | (ci[:, 1] == ub))
    text = res.report_text()
    assert ", 50*]" in text and "*: the interval ends at the parameter's bound, which it reaches" in text
    assert res.identifiability.to_dict()["ci95_cut_at_bound"]["flap_compliance"][1] is True


def test_a_determined_flap_compliance_keeps_its_interval():
    from propmap.identify import fit_loads

    prop, data = _incidence_data(1.0, 0.002)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = fit_loads(data, prop, base=pm.default_params("apce_10x7"))
    j = res.names.index("flap_compliance")
    lo, hi = res.identifiability.ci95[j]
    assert not res.identifiability.ci95_cut[j].any() and "*: the interval ends" not in res.report_text()
    assert res.x[j] == pytest.approx(1.0, rel=0.05) and lo <= res.x[j] <= hi < 2.0
    assert not any(w.startswith("flap_compliance:") for w in res.warnings)  # the linearised interval stands


def test_a_flap_compliance_interval_too_narrow_is_widened_by_the_profile():
    """Loads made with 15 rad/(N m), 1% noise (this draw): fitted 7.6, the linearised upper limit 9.7;
    the profile likelihood's cost rises by less than the 95% edge there, so its own limit (about 12,
    2026-11-26) replaces it. (The profile still excludes the true 15 on this draw.)"""
    from propmap.identify import fit_loads

    prop, data = _incidence_data(15.0, 0.01, seed=1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = fit_loads(data, prop, base=pm.default_params("apce_10x7"))
    j = res.names.index("flap_compliance")
    lo, hi = res.identifiability.ci95[j]
    said = [w for w in res.warnings if w.startswith("flap_compliance: its 95% interval's upper end")]
    assert len(said) == 1 and 6.0 < res.x[j] < 9.0 and 10.5 < hi < 14.0 and lo < res.x[j]
    linear = float(said[0].split("the linearised one, ")[1].split(",")[0])
    assert res.x[j] < linear < hi


@pytest.mark.slow
def test_a_flight_fit_records_its_coverage_and_a_faster_log_is_warned(tmp_path, capsys, shared_data):
    """A flight fit's file had no [coverage]: `wrench` on a faster flight than the fit's logs said
    nothing. Fitted on the slow figure-8 (985-1250 rad/s, 3.5 m/s), the race track (to 1912 rad/s)
    is warned of."""
    from propmap.io.params_file import set_coverage

    logs = shared_data / "neurobem_flights"
    out = tmp_path / "slow.toml"
    vehicle = str(EXAMPLES / "neurobem_quadrotor.toml")
    assert main(["fit", "flight", str(logs / "bemnn20210223104803seg2.mat"), "--vehicle", vehicle, "--rate-hz",
                 "10", "--out", str(out)]) == 0
    cov = set_coverage(str(out))
    assert 9000 < cov["rpm_min"] < cov["rpm_max"] < 12000 and 3.0 < cov["airspeed_max"] < 4.0
    assert 90 < cov["incidence_deg_max"] < 180 and 0 < cov["J_max"] < 0.1
    capsys.readouterr()
    assert main(["wrench", str(logs / "bemnn20210218171908seg2.mat"), "--vehicle", vehicle, "--params", str(out),
                 "--out", str(tmp_path / "race.csv")]) == 0
    err = capsys.readouterr().err
    assert f"rpm: the data behind {out} span" in err and "advance ratio up to" in err
    # its own log at the full rate is within the coverage (recorded from every sample, not the fit's 10 Hz)
    assert main(["wrench", str(logs / "bemnn20210223104803seg2.mat"), "--vehicle", vehicle, "--params", str(out),
                 "--out", str(tmp_path / "own.csv")]) == 0
    assert "the data behind" not in capsys.readouterr().err
    # edgewise faster than the logs: no advance ratio or incidence says it, the airspeed does
    assert main(["loads", str(EXAMPLES / "neurobem_5.1x4.8_geom.txt"), "--blades", "3", "--params", str(out), "--rpm",
                 "11000", "--airspeed", "25", "--incidence-deg", "90"]) == 0
    assert f"airspeed up to 25 m/s: the data behind {out} reach 3.4" in capsys.readouterr().err


def test_a_converted_value_out_of_range_is_named_as_written(tmp_path):
    f = tmp_path / "t.csv"
    f.write_text("rpm,airspeed,incidence (rad),thrust\n5000,5,0,3\n5000,5,15,2\n")
    with pytest.raises(DataError, match=r"line 3: incidence_deg must be in \[0, 180\] deg, got 'incidence \(rad\)' = "
                                        r"15, i.e. incidence_deg = 859.4"):
        read_loads(f)


def test_validate_takes_a_users_own_load_file(tmp_path, capsys):
    """`propmap validate DATA --prop GEOM [--params P]`: a set against one's own measurements, in
    coefficient form, per group: the data made by the calibrated set give zero thrust and torque
    error; the generic set gives its own, and the in-plane force of flapping blades is what a
    rigid set misses."""
    import json

    prop = pm.load_propeller("apce_8x6")
    truth = pm.default_params("apce_8x6").replace(flap_compliance=5.0)
    rows = ["rpm,airspeed,incidence_deg,thrust (N),drag (N),torque (N m),group"]
    for rpm in (4000.0, 6000.0):
        for V, inc in ((0.0, 0.0), (5.0, 45.0), (10.0, 90.0)):
            r = pm.rotor_loads(prop, truth, rpm * math.pi / 30, V, math.radians(inc))
            rows.append(f"{rpm},{V},{inc},{float(r.thrust)!r},{float(r.drag)!r},{float(r.torque)!r},r{rpm:.0f}")
    f = tmp_path / "tunnel.csv"
    f.write_text("\n".join(rows) + "\n")
    assert main(["validate", str(f), "--prop", "apce_8x6", "--json"]) == 0
    e = json.loads(capsys.readouterr().out)
    assert e["params_label"] == "calibrated:apce_8x6" and e["n_points"] == 6 and set(e["groups"]) == {"r4000", "r6000"}
    assert e["overall"]["thrust"]["rms"] < 1e-9 and e["overall"]["torque"]["rms"] < 1e-9  # flapping: T, Q alike
    assert 0.01 < e["overall"]["drag"]["rms"] < 0.5 and e["overall"]["drag"]["bias"] < 0  # the rigid set's H short
    assert e["reference"]["drag"][0] == "mean static CT"
    rigid = pm.rotor_loads(prop, pm.default_params("apce_8x6"), 6000 * math.pi / 30, 10.0, math.pi / 2)
    flap = pm.rotor_loads(prop, truth, 6000 * math.pi / 30, 10.0, math.pi / 2)
    n = 100.0
    ct0 = e["reference"]["thrust"][1]
    assert e["groups"]["r6000"]["drag"]["max"] == pytest.approx(
        abs(float(rigid.drag - flap.drag)) / (1.225 * n**2 * prop.diameter**4) / ct0, rel=1e-6)
    assert main(["validate", str(f), "--prop", "apce_8x6", "--params", "generic"]) == 0
    out = capsys.readouterr().out
    assert "params generic" in out and "all points" in out and "r4000" in out
    assert main(["validate", str(f)]) == 2
    assert "--prop: a file SOURCE needs the propeller" in capsys.readouterr().err
    assert main(["validate", str(f), "--prop", "apce_8x6", "--figure", str(tmp_path / "x.png")]) == 2
    assert main(["validate", "apce_8x6", "--blades", "2"]) == 2
    assert "--blades applies to SOURCE files" in capsys.readouterr().err


def test_validate_compares_a_few_or_repeated_points_and_says_a_unit_slip(tmp_path, capsys):
    """A comparison needs no six distinct points (a fit does): four points, or one hover point
    repeated, are compared; loads in gf and N mm under SI names are warned of (the comparison
    goes on: a fit refuses them); long group names are not cut."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")

    def row(rpm, V=0.0, group="g"):
        r = pm.rotor_loads(prop, params, rpm * math.pi / 30, V, 0.0)
        return f"{rpm},{V},{float(r.thrust)!r},{float(r.torque)!r},{group}"

    f = tmp_path / "few.csv"
    f.write_text("rpm,airspeed,thrust,torque,group\n" + "\n".join(
        [row(5000), row(6000), row(6000, 5.0, "tunnel_2026-11-22_morning_A"),
         row(7000, 5.0, "tunnel_2026-11-22_morning_B")]) + "\n")
    assert main(["validate", str(f), "--prop", "apce_8x6"]) == 0
    out = capsys.readouterr().out
    assert "tunnel_2026-11-22_morning_A " in out and "tunnel_2026-11-22_morning_B " in out
    assert "(4 points)" in out and "0.00%" in out
    f.write_text("rpm,thrust,torque\n" + "\n".join(",".join(row(6000).split(",")[:1] + row(6000).split(",")[2:4])
                                                  for _ in range(5)) + "\n")
    assert main(["validate", str(f), "--prop", "apce_8x6"]) == 0
    assert "(5 points)" in capsys.readouterr().out
    grams = tmp_path / "grams.csv"  # thrust in gf and torque in N mm, the header saying N and N m
    r = pm.rotor_loads(prop, params, np.array([5000.0, 6000.0, 7000.0]) * math.pi / 30, 0.0, 0.0)
    grams.write_text("rpm,thrust,torque\n" + "\n".join(
        f"{rpm},{float(t) / 9.80665e-3!r},{float(q) * 1e3!r}"
        for rpm, t, q in zip((5000, 6000, 7000), r.thrust, r.torque)) + "\n")
    assert main(["validate", str(grams), "--prop", "apce_8x6"]) == 0
    captured = capsys.readouterr()
    # (the pair named since 2026-12-01; "check the units" before)
    assert ("likely thrust in gf and torque in N mm read as N and N m" in captured.err
            and "the comparison below takes the file as written" in captured.err)


def test_load_errors_leave_out_unconverged_points_and_score_the_in_plane_force_at_incidence(monkeypatch):
    from propmap.validation import loads as validation
    from propmap.identify import LoadData

    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    om = np.full(4, 600.0)
    V = np.array([0.0, 5.0, 5.0, 5.0])
    inc = np.radians([0.0, 0.0, 60.0, 90.0])
    r = pm.rotor_loads(prop, params, om, V, inc)
    measured = {"thrust": r.thrust.copy(), "drag": r.drag + np.array([0.3, 0.3, 0.0, 0.0]), "torque": r.torque.copy()}
    data = LoadData(om, V, inc, measured, np.array(["a", "a", "b", "b"], dtype=object), "synthetic")
    e = validation.load_errors(data, prop, params)
    assert e["overall"]["drag"]["n"] == 2 and e["overall"]["drag"]["rms"] < 1e-9  # the axial points' 0.3 N not scored
    assert e["groups"]["a"]["drag"]["n"] == 0 and e["groups"]["a"]["drag"]["rms"] is None
    real = validation.rotor_loads

    def one_fails(*args, **kwargs):
        out = real(*args, **kwargs)
        out.thrust[2] = np.nan
        out.converged[2] = False
        return out

    monkeypatch.setattr(validation, "rotor_loads", one_fails)
    e = validation.load_errors(data, prop, params)
    assert e["converged"] == 3 and e["overall"]["thrust"]["n"] == 3 and np.isfinite(e["overall"]["thrust"]["rms"])


def test_a_two_blade_uiuc_run_used_with_three_blades_is_warned(capsys, shared_data):
    """UIUC's 2-blade runs carry no '_2b' in their names: a catalogue propeller's name tells the
    blade count (a 3-blade geometry with a 2-blade run gave +56% thrust error, silently)."""
    v2 = shared_data / "uiuc_propdb" / "v2"
    run, geom = str(v2 / "da4022_5x3.75_static_0642rb.txt"), str(v2 / "da4022_5x3.75_geom.txt")
    assert main(["validate", run, "--prop", geom, "--blades", "3"]) == 0
    assert ("named for the catalogue's 'da4022_5x3.75', a 2-blade propeller, used with 3 blades: give --blades 2"
            in capsys.readouterr().err)
    assert main(["validate", run, "--prop", geom, "--blades", "2"]) == 0
    assert "blade" not in capsys.readouterr().err


def _fitted_runs(tmp_path):
    """(runs.csv: three groups of apce_8x6's own loads, p.toml: its fit holding s2 out)."""
    prop = pm.load_propeller("apce_8x6")
    truth = pm.default_params("apce_8x6")
    rows = ["rpm,airspeed,thrust (N),torque (N m),group"]
    for rpm, group in ((3000.0, "s0"), (4000.0, "s0"), (5000.0, "s1"), (6000.0, "s1"), (7000.0, "s2"), (8000.0, "s2")):
        for V in (0.0, 4.0, 8.0):
            r = pm.rotor_loads(prop, truth, rpm * math.pi / 30, V, 0.0)
            rows.append(f"{rpm},{V},{float(r.thrust)!r},{float(r.torque)!r},{group}")
    f = tmp_path / "runs.csv"
    f.write_text("\n".join(rows) + "\n")
    out = tmp_path / "p.toml"
    assert main(["fit", "loads", str(f), "--prop", "apce_8x6", "--holdout", "s2", "--out", str(out)]) == 0
    return f, out


def test_validate_says_which_groups_a_parameter_files_fit_saw(tmp_path, capsys):
    """A fit's [coverage] records its data and the groups it fitted and held out; `validate` on
    the same data labels them (its in-sample rows are the fit's residual, not a held-out error)."""
    from propmap.io.params_file import read_coverage

    f, out = _fitted_runs(tmp_path)
    cov = read_coverage(out)
    assert cov["data"] == "runs.csv" and cov["groups"] == ("s0", "s1") and cov["held_out"] == ("s2",)
    capsys.readouterr()
    assert main(["validate", str(f), "--prop", "apce_8x6", "--params", str(out)]) == 0
    text = capsys.readouterr().out
    assert "s0 (fitted)" in text and "s2 (held out)" in text
    assert f"{out} was fitted to this data: s0, s1 in-sample (the fit's residual), held out: s2" in text
    assert main(["validate", str(f), "--prop", "apce_8x6", "--params", str(out), "--json"]) == 0
    import json

    assert json.loads(capsys.readouterr().out)["in_fit"] == {"s0": "fitted", "s1": "fitted", "s2": "held out"}
    # a copy under another name is the same data, by content (files_sha256, since 2026-11-26; by the name before)
    g = tmp_path / "other.csv"
    g.write_text(f.read_text())
    assert main(["validate", str(g), "--prop", "apce_8x6", "--params", str(out)]) == 0
    assert "s0 (fitted)" in capsys.readouterr().out
    # nor another day's file of the same name (the audit's otherday/runs.csv read as in-sample): its content differs
    other_day = tmp_path / "otherday"
    other_day.mkdir()
    (other_day / "runs.csv").write_text(f.read_text().replace("\n3000.0,0.0,", "\n3000.0,0.0,1", 1))
    assert len(cov["data_sha256"]) == 64
    from propmap.cli._sources import data_digest

    assert data_digest([f, g]) == data_digest([g, f]) != data_digest([f])  # (whatever the files' order)
    assert main(["validate", str(other_day / "runs.csv"), "--prop", "apce_8x6", "--params", str(out)]) == 0
    assert "(fitted)" not in capsys.readouterr().out


@pytest.mark.parametrize("bad, match", [('data = 5', "data must be a text"), ('groups = "s0"', "groups must be a list"),
                                        ('held_out = [1, 2]', "held_out must be a list of texts"),
                                        # (hand edits that silenced the checks: a JSON/pipeline audit, 2026-11-26)
                                        ('diameter_m = 0', r"diameter_m must be a finite number in \(0, 100\]"),
                                        ('n_blades = 2.5', "n_blades must be a whole number"),
                                        ('re75_min = 1e9\nre75_max = 5e4', "re75_min 1e\\+09 exceeds re75_max"),
                                        ('files_sha256 = "ab"', "files_sha256 must be a list")])
def test_coverage_text_keys_are_checked(tmp_path, bad, match):
    from propmap.io.params_file import ParamsFileError, read_coverage

    p = tmp_path / "p.toml"
    pm.write_params(p, pm.generic_params(), coverage={})  # (none: the set's own is written by default)
    p.write_text(p.read_text() + f"\n[coverage]\nJ_max = 0.5\n{bad}\n")
    with pytest.raises((ParamsFileError, ValueError), match=match):
        read_coverage(p)


@pytest.mark.parametrize("blades, diameter", [(2, None), (3, 5.3)])
def test_c_header_for_a_vehicle_whose_rotors_are_another_reading_of_the_geometry_is_refused(tmp_path, capsys,
                                                                                          blades, diameter):
    """The NeuroBEM rotors are 3-blade 5.1 in; a header built from their geometry file read with 2
    blades (or as 5.3 in) was written with its vehicle wrench: 4.10 N at 4 x 1115 rad/s against the
    3-blade header's 5.57 N, status 0 (user-level audit, 2026-11-26). Only the name was compared."""
    from propmap.cli.main import main

    examples = Path(pm.__file__).parent / "data" / "examples"
    args = ["map", str(examples / "neurobem_5.1x4.8_geom.txt"), "--blades", str(blades), "--rpm", "4000:20000:3",
            "--airspeed", "0:10:2", "--incidence-deg", "0:180:3", "--check-points", "0", "--format", "c",
            "--vehicle", str(examples / "neurobem_quadrotor.toml"), "--out", str(tmp_path / "nb.h")]
    if diameter:
        args += ["--diameter-in", str(diameter)]
    code = main(args)
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1, err
    assert "rotor 1 carries neurobem_5.1x4.8 (0.1295 m, 3 blades)" in err and f"{blades} blades): a C header" in err
    assert not list(tmp_path.iterdir())


def test_map_out_of_another_format_says_which_suffix_the_format_takes(tmp_path, capsys):
    """The README's map line with --format c and --out X.nc said '(or choose --format)' to a user who
    had chosen it (user-level audit, 2026-11-26)."""
    from propmap.cli.main import main

    code = main(["map", "apce_8x6", "--out", str(tmp_path / "a.nc"), "--format", "c"])
    err = capsys.readouterr().err
    assert code == 2 and "a c map is named *.h (--format c)" in err and len(err.strip().splitlines()) == 1, err
    code = main(["map", "apce_8x6", "--out", str(tmp_path / "a.txt")])
    err = capsys.readouterr().err
    assert code == 2 and "(or choose --format)" in err, err


@pytest.mark.parametrize("argv", [
    ["wrench", "{log}", "--vehicle", "{vehicle}", "--out", "{d}/w_dir/"],
    ["fit", "flight", "{log}", "--vehicle", "{vehicle}", "--out", "{d}/newfit/"],
    ["fit", "loads", "apce_8x6", "--out", "{d}/p/"],
    ["map", "apce_8x6", "--out", "{d}/m/"],
    ["export-sim", "apce_8x6", "--target", "rotorpy", "--out", "{d}/e/"],
    ["loads", "apce_8x6", "--points", "{points}", "--out", "{d}/l/"],
    ["validate", "apce_8x6", "--figure", "{d}/v/x.png/"],
])
def test_an_output_named_as_a_folder_that_does_not_exist_is_refused(tmp_path, capsys, shared_data, argv):
    """`--out DIR/` for a folder that does not exist wrote a file named DIR (and DIR.report.json ...):
    the trailing separator was dropped (user-level audit, 2026-11-26). Refused, one line, exit 2,
    nothing written."""
    from propmap.cli.main import main

    points = tmp_path / "pts.csv"
    points.write_text("rpm,airspeed,incidence_deg\n5000,5,90\n")
    subs = {"{log}": str(shared_data / "neurobem_flights" / "bemnn20210223104803seg2.mat"), "{d}": str(tmp_path),
            "{vehicle}": str(Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"),
            "{points}": str(points)}
    args = []
    for a in argv:
        for k, v in subs.items():
            a = a.replace(k, v)
        args.append(a)
    code = main(args)
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and "names a folder (it ends with '/')" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pts.csv"]


def _fallback_probe(tmp_path, module: str, checks: str = "") -> str:
    """Python code for a fresh process: numba's package-folder and user-cache locators find no
    place (as for a read-only install run as nobody; as root every folder is writable), propmap's
    cache fallback is asserted to be numba's cache folder, a tiny cached kernel ``module`` in
    tmp_path is compiled and called, ``checks`` run, and the fallback's folder name printed."""
    import textwrap

    (tmp_path / f"{module}.py").write_text("import numba\n\n@numba.njit(cache=True)\ndef twice(x):\n    return 2 * x\n")
    return textwrap.dedent(f"""
        import os, sys, tempfile
        from numba.core import caching
        for c in (caching.InTreeCacheLocator, caching.UserWideCacheLocator):
            c.from_function = classmethod(lambda cls, f, p: None)
        import propmap.core._jitcache as j
        import numba
        assert j.CACHE_FALLBACK == numba.config.CACHE_DIR == os.environ["NUMBA_CACHE_DIR"]
        assert os.path.dirname(j.CACHE_FALLBACK) == {str(tmp_path)!r}
        sys.path.insert(0, {str(tmp_path)!r})
        import {module}
        assert {module}.twice(21) == 42
    """) + textwrap.dedent(checks) + "\nprint(os.path.basename(j.CACHE_FALLBACK))\n"


def test_kernels_are_cached_where_numba_can_write_no_cache_folder(tmp_path):
    """A read-only install run without a writable home (as nobody) ended every command with an
    internal error, "cannot cache function ...: no locator available" (user-level audit,
    2026-11-26): numba is then given a private folder in the temporary folder (here tmp_path),
    never one another user can write (numba's index is a pickle). Simulated (as root every
    folder is writable) by locators that find no place, in fresh processes."""
    import subprocess
    import sys

    code = _fallback_probe(tmp_path, "tiny_kernel", 'assert oct(os.stat(j.CACHE_FALLBACK).st_mode)[-3:] == "700"')
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["TMPDIR"] = str(tmp_path)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0 and out.stdout.strip() == f"propmap-numba-{os.getuid()}", out.stderr[-2000:]
    # a folder of that name that others may write is not used: a new private one instead
    shared = tmp_path / f"propmap-numba-{os.getuid()}"
    shared.chmod(0o777)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0 and out.stdout.strip().startswith("propmap-numba-"), out.stderr[-2000:]
    assert out.stdout.strip() != shared.name
    # without the fallback the same tiny kernel is refused as the audit saw
    bare = code.replace("import propmap.core._jitcache as j", "j = None").split("assert j.CACHE_FALLBACK")[0]
    bare += f"\nsys.path.insert(0, {str(tmp_path)!r})\nimport tiny_kernel\n"
    out = subprocess.run([sys.executable, "-c", bare], capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode != 0 and "no locator available" in out.stderr, out.stderr[-2000:]


def test_an_unwritable_numba_cache_dir_falls_back_too(tmp_path):
    """NUMBA_CACHE_DIR naming what cannot be a cache folder (here a regular file), where the
    package's folder and the user's cache cannot be written either, ended every command with an
    internal error, "no locator available" (a parallel-use audit, 2026-11-27: propmap's fallback
    was skipped whenever the variable was set). The kernels are cached in the fallback folder."""
    import subprocess
    import sys

    (tmp_path / "not_a_folder").write_text("x")
    code = _fallback_probe(tmp_path, "tiny_kernel2", """
        cached = [f for _, _, fs in os.walk(j.CACHE_FALLBACK) for f in fs if f.startswith("tiny_kernel2")]
        assert any(f.endswith(".nbi") for f in cached), cached
    """)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "not_a_folder"), TMPDIR=str(tmp_path))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0 and out.stdout.strip() == f"propmap-numba-{os.getuid()}", out.stderr[-2000:]


@pytest.mark.parametrize("change, match", [
    (("position = [-0.078, -0.100, -0.027]", "position = [-78.0, -100.0, -27.0]"),
     r"rotor 1's hub lies 129.7 m from the centre of mass, 2e\+03 of its radii: are the positions in metres\?"),
    (("inertia = [0.0025, 0.0021, 0.0043]", "inertia = [25000.0, 21000.0, 43000.0]"),
     r"largest principal moment is 3.31e\+06 times the mass .* is the mass in kg and the inertia in kg m\^2\?"),
    (("position = [-0.078, -0.100, -0.027]", "position = [0.078, -0.100, -0.027]"),
     r"rotors 1 and 2 have the same position \[0.078, -0.1, -0.027\] m"),
    # disks closer than the sum of their radii: in one plane a strike, apart along the axis a coaxial pair that the
    # model solved as isolated rotors without a word (a vehicle-designer audit, 2026-11-28)
    (("position = [-0.078, -0.100, -0.027]", "position = [0.030, -0.100, -0.027]"),
     r"the disks of rotors 1 and 2 \(0.048 m apart across the axis, 0 m along it\) overlap in one plane, .*blades "
     r"would strike: is a diameter or a position in another unit\?"),
    (("position = [-0.078, -0.100, -0.027]", "position = [0.078, -0.100, 0.030]"),
     r"rotors 1 and 2 \(0 m apart across the axis, 0.057 m along it\) overlap seen along the axis \(a coaxial .*"
     r"each rotor is solved as if alone .* induced power 26-41% above"),
])
def test_a_vehicle_layout_in_other_units_is_warned_about(tmp_path, change, match):
    """Arms in mm, an inertia in g cm^2 and two rotors at one place were read without a word and
    made every moment wrong (moment errors of 47 N m; user-level audit, 2026-11-26)."""
    import warnings

    examples = Path(pm.__file__).parent / "data" / "examples"
    for f in examples.iterdir():
        (tmp_path / f.name).write_bytes(f.read_bytes())
    text = (examples / "neurobem_quadrotor.toml").read_text()
    assert change[0] in text
    (tmp_path / "v.toml").write_text(text.replace(change[0], change[1], 1))
    with pytest.warns(UserWarning, match=match):
        pm.read_vehicle(tmp_path / "v.toml")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pm.read_vehicle(examples / "neurobem_quadrotor.toml")
        pm.read_vehicle("quadrotor")


def test_rotors_of_crossed_axes_are_not_judged_for_overlap(tmp_path):
    """A pusher beside a lift rotor: seen along one axis or the other their disks overlap or not,
    so the warning depended on the rotors' order (a review, 2026-11-28); only (anti)parallel axes
    are judged, as the interference model's."""
    import warnings

    examples = Path(pm.__file__).parent / "data" / "examples"
    for f in examples.iterdir():
        (tmp_path / f.name).write_bytes(f.read_bytes())
    text = (examples / "neurobem_quadrotor.toml").read_text()
    # rotor 1 a pusher 57 mm above rotor 2's hub (the pusher first), then rotor 2 one above rotor 1's (second)
    for where, at in (("[-0.078, -0.100, -0.027]", "[0.078, -0.100, 0.030]"),
                      ("[0.078, -0.100, -0.027]", "[-0.078, -0.100, 0.030]")):
        pusher = text.replace(f"position = {where}\naxis = [0.0, 0.0, 1.0]",
                              f"position = {at}\naxis = [1.0, 0.0, 0.0]", 1)
        assert pusher != text
        (tmp_path / "v.toml").write_text(pusher)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            pm.read_vehicle(tmp_path / "v.toml")


def test_a_coaxial_pair_with_the_interference_model_is_said_to_be_outside_its_accuracy(tmp_path):
    examples = Path(pm.__file__).parent / "data" / "examples"
    for f in examples.iterdir():
        (tmp_path / f.name).write_bytes(f.read_bytes())
    text = (examples / "neurobem_quadrotor.toml").read_text()
    text = text.replace("position = [-0.078, -0.100, -0.027]", "position = [0.078, -0.100, 0.030]", 1)
    (tmp_path / "v.toml").write_text(text.replace("mass = 0.772", "mass = 0.772\nrotor_interference = 1.0", 1))
    with pytest.warns(UserWarning, match=r"rotor_interference models such pairs outside its accuracy"):
        assert pm.read_vehicle(tmp_path / "v.toml").rotor_interference == 1.0


def test_a_c_headers_sidecar_says_its_interpolation_table_type_and_prefix(tmp_path, capsys):
    """The sidecar of a C header carried the map's attributes only, not what the header chose
    (user-level audit, 2026-11-26)."""
    import json

    from propmap.cli.main import main

    out = tmp_path / "rotor.h"
    code = main(["map", "apce_8x6", "--rpm", "4000:8000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:90:3",
                 "--check-points", "0", "--format", "c", "--c-interpolation", "cubic", "--c-type", "double",
                 "--out", str(out)])
    assert code == 0, capsys.readouterr().err
    side = json.loads((tmp_path / "rotor.h.json").read_text())
    attrs = side.get("attrs", side)
    assert (attrs["c_interpolation"], attrs["c_type"], attrs["c_prefix"]) == ("cubic", "double", "pm_rotor")
    assert "int pm_rotor_loads(double omega" in out.read_text()


@pytest.mark.parametrize("argv, said", [
    (["map", "apce_8x6", "--rpm", "4000:8000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:3.14:5",
      "--check-points", "0", "--out", "{d}/m.nc"], "--incidence-deg: the incidences end at 3.14 deg: radians?"),
    (["export-sim", "apce_8x6", "--target", "multinomial", "--envelope", "incidence_deg=0:1.5708", "--points", "200",
      "--out", "{d}/e.json"], "--envelope incidence_deg: the incidences end at 1.5708 deg: radians?"),
])
def test_an_incidence_range_ending_at_pi_is_warned_about_as_radians(tmp_path, capsys, argv, said):
    """`--incidence-deg 0:3.14:5` built a map of 0-3.14 deg without a word (user-level audit,
    2026-11-26); 0:90:7 and 0:3:4 are believed."""
    from propmap.cli.main import main

    code = main([a.replace("{d}", str(tmp_path)) for a in argv])
    err = capsys.readouterr().err
    assert code == 0 and said in err, err
    code = main(["map", "apce_8x6", "--rpm", "4000:8000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:3:4",
                 "--check-points", "0", "--out", str(tmp_path / "w.nc")])
    assert code == 0 and "radians?" not in capsys.readouterr().err


def test_a_designers_slips_are_said(tmp_path, capsys):
    """A vehicle designer's audit (2026-11-26): a narrow --range-deg ended in an internal
    'grid_step' error; a thrust in grams got the stall's diagnosis; trim's text left out the
    descent ratios that docs/cli.md lists; map --json printed no propeller, set or grid; another
    propeller's calibrated set ran without a word; a mass in grams hovered at tip Mach 3.7 silently."""
    import dataclasses
    import json

    from propmap.cli.main import main
    from propmap.vehicle import hover_omega

    assert main(["trim", "apce_10x5", "--thrust", "3.2", "--rpm", "4816", "--range-deg", "-1", "1"]) == 0
    assert "collective" in capsys.readouterr().out
    assert main(["trim", "apce_10x5", "--thrust", "300", "--rpm", "4816"]) == 2
    err = capsys.readouterr().err
    assert "spans [-0.243082, 3.85859] N: 77.7 times the most it reaches; is the thrust in grams?" in err
    assert "stalls" not in err
    assert main(["trim", "apce_10x5", "--thrust", "2.9", "--rpm", "4816", "--airspeed", "4", "--incidence-deg",
                 "180"]) == 0
    assert "state: vortex ring (v_i/v_h = 1.6" in capsys.readouterr().out
    assert main(["map", "apce_8x6", "--rpm", "3000:8000:3", "--airspeed", "0:15:4", "--incidence-deg", "0:180:5",
                 "--check-points", "0", "--out", str(tmp_path / "m.nc"), "--json"]) == 0
    meta = json.loads(capsys.readouterr().out)["metadata"]
    assert (meta["propeller"], meta["params_label"]) == ("apce_8x6", "calibrated:apce_8x6")
    assert meta["dims"] == {"rpm": 3, "airspeed": 4, "incidence_deg": 5} and meta["rho_kg_m3"] == pytest.approx(1.225)
    assert main(["loads", "apce_10x7", "--rpm", "5000", "--params", "calibrated:apce_10x5"]) == 0
    said = capsys.readouterr().err
    assert "apce_10x7 runs with calibrated:apce_10x5, the set calibrated on another propeller" in said
    assert main(["loads", "apce_10x5", "--rpm", "5000", "--params", "calibrated:apce_10x5"]) == 0
    assert "another propeller" not in capsys.readouterr().err
    # the same blade under another name (the catalogue's APC PE0 file, copied) is no other propeller (a
    # vehicle-designer audit, 2026-11-28: it was warned of as one)
    import shutil

    from propmap.io.catalogue import _data_path, get_entry

    mine = tmp_path / "mine.PE0"
    shutil.copy(_data_path(get_entry("apce_8x6").geometry_file), mine)
    assert main(["loads", str(mine), "--rpm", "5000", "--params", "calibrated:apce_8x6"]) == 0
    assert "another propeller" not in capsys.readouterr().err
    assert main(["loads", str(mine), "--rpm", "5000", "--params", "calibrated:apce_10x5"]) == 0
    assert "mine.PE0 runs with calibrated:apce_10x5, the set calibrated on another propeller" in capsys.readouterr().err
    vehicle = pm.read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    with pytest.warns(UserWarning, match=r"at Mach 3\.\d+ in this hover .* is the vehicle's mass 1200 kg in kg"):
        hover_omega(dataclasses.replace(vehicle, mass=1200.0), pm.generic_params())


def test_uiuc_format_files_of_one_run_name_are_one_group_each(tmp_path, shared_data, capsys):
    """The docs' own example, `fit loads static.txt sweep_4000.txt sweep_6000.txt`, merged both
    sweeps into one group 'sweep' (the run name of <fam>_<D>x<P>_<run>_<RPM>.txt), so that
    --holdout sweep_6000 was refused and --holdout sweep left a static-only fit (audit,
    2026-11-26). Data: UIUC Propeller Data Site vol. 1, apce_9x6."""
    import shutil

    from propmap.cli.main import main
    from propmap.identify import loads_from_uiuc_files

    src = shared_data / "uiuc_propdb" / "v1"
    for name, new in (("apce_9x6_static_rd0987.txt", "static.txt"), ("apce_9x6_rd0988_4003.txt", "sweep_4000.txt"),
                      ("apce_9x6_rd0992_6015.txt", "sweep_6000.txt")):
        shutil.copy(src / name, tmp_path / new)
    files = [tmp_path / f for f in ("static.txt", "sweep_4000.txt", "sweep_6000.txt")]
    data = loads_from_uiuc_files(files, 9 * 0.0254)
    assert sorted(set(data.group)) == ["static_static", "sweep_4000", "sweep_6000"]
    code = main(["fit", "loads", *map(str, files), "--prop", "apce_9x6", "--out", str(tmp_path / "p.toml"),
                 "--holdout", "sweep_6000"])
    assert code == 0, capsys.readouterr().err


@pytest.mark.parametrize("columns, cells, rho", [
    ("Temperature (C),Pressure (Pa)", "25,90000", 90000 / (287.05 * 298.15)),
    ("air temp,baro", "298.15,900", 90000 / (287.05 * 298.15)),
    ("air temperature [F],pressure (inHg)", "59,29.92", 1.2250),
])
def test_a_load_files_temperature_and_pressure_give_its_air(tmp_path, columns, cells, rho):
    """A tunnel export's temperature and pressure were ignored: fitted at 1.225 kg/m^3 where they
    meant 1.052 (identification audit, 2026-11-26)."""
    from propmap.identify import read_loads

    rows = [f"rpm,airspeed,thrust (N),torque (N m),{columns}"]
    for rpm in (3000.0, 4000.0, 5000.0, 6000.0, 7000.0, 8000.0):
        rows.append(f"{rpm},0,{(rpm / 3000) ** 2},{(rpm / 3000) ** 2 / 50},{cells}")
    f = tmp_path / "tunnel.csv"
    f.write_text("\n".join(rows) + "\n")
    data = read_loads(f)
    assert data.air_density == pytest.approx(rho, rel=2e-3)
    assert any("air density" in n and "287.05" in n for n in data.notes)
    one = tmp_path / "one.csv"
    one.write_text("\n".join(r.rsplit(",", 1)[0] for r in rows) + "\n")
    data = read_loads(one)
    assert data.air_density is None and any("is not read without the other" in n for n in data.notes)
    # columns that are not the air's state are never refused, and never read as it (the review's cases): a bare
    # 'temp' (a motor's?) and 'pressure' (a tunnel's dynamic pressure) are not its names; 50 without a unit (degF or
    # degC?) is not guessed; a density beyond the air's is not used
    for header, cell in (("temp (C),pressure (Pa)", "20,101325"), ("temperature,baro (hPa)", "50,1013"),
                         ("temperature (C),pressure (Pa)", "25,735"), ("temperature (C),pressure", "25,735"),
                         ("temperature (C),baro (furlong)", "25,1")):
        f.write_text("\n".join([f"rpm,airspeed,thrust (N),torque (N m),{header}"] + [
            ",".join(r.split(",")[:4] + cell.split(",")) for r in rows[1:]]) + "\n")
        data = read_loads(f)
        assert data.air_density is None, (header, data.notes)


def test_of_two_temperature_columns_the_first_is_read_and_named(tmp_path):
    """Two air temperature columns (a tunnel's and the ambient): the first in the header gives the
    density, and the note names it (documented since 2026-11-29, docs/identification.md; reading the
    last instead survived a mutation audit of 2026-11-29)."""
    from propmap.identify import read_loads

    rows = ["rpm,airspeed,thrust (N),torque (N m),tunnel temperature (C),Pressure (Pa),ambient temperature (K)"]
    rows += [f"{rpm},0,{(rpm / 3000) ** 2},{(rpm / 3000) ** 2 / 50},40,90000,280"
             for rpm in (3000.0, 4000.0, 5000.0, 6000.0, 7000.0, 8000.0)]
    f = tmp_path / "tunnel.csv"
    f.write_text("\n".join(rows) + "\n")
    data = read_loads(f)
    assert data.air_density == pytest.approx(90000 / (287.05287 * 313.15), rel=1e-9)
    assert any("from 'tunnel temperature (C)' and 'Pressure (Pa)'" in n for n in data.notes), data.notes


@pytest.mark.parametrize("factor, unit", [(1 / 0.44704, "mph"), (1 / 0.514444, "knots")])
def test_an_unlabelled_airspeed_in_mph_or_knots_is_said(tmp_path, factor, unit):
    """An airspeed column in mph or knots without a unit was fitted with exit 0, six parameters at
    their bounds and J_max 1.87 in [coverage] for a 9x6 (identification audit, 2026-11-26). None
    of the 143 catalogue propellers' own data gets this warning (checked 2026-11-26)."""
    from propmap.identify import read_loads
    from propmap.identify.data import sanity_check

    prop, params = pm.load_propeller("apce_9x6"), pm.default_params("apce_9x6")
    rows = ["rpm,airspeed,thrust (N),torque (N m)"]
    for rpm in (3000.0, 4000.0, 5000.0, 6000.0):
        for V in (0.0, 3.0, 6.0, 9.0, 12.0):
            r = pm.rotor_loads(prop, params, rpm * math.pi / 30, V, 0.0)
            rows.append(f"{rpm},{V * factor},{float(r.thrust)!r},{float(r.torque)!r}")
    f = tmp_path / "v.csv"
    f.write_text("\n".join(rows) + "\n")
    said = sanity_check(read_loads(f), prop)
    assert any(f"airspeed read as {unit} (is the airspeed column in {unit}?" in w for w in said), said
    f.write_text("\n".join(r if i == 0 else ",".join([r.split(",")[0], repr(float(r.split(",")[1]) / factor),
                                                       *r.split(",")[2:]]) for i, r in enumerate(rows)) + "\n")
    assert not any("airspeed read as" in w for w in sanity_check(read_loads(f), prop))



GEOM_15X45 = ("r/R c/R beta\n" + "".join(f"{x} {c} {b}\n" for x, c, b in zip(
    (0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 1.0),
    (0.12, 0.1367, 0.1533, 0.17, 0.175, 0.18, 0.185, 0.19, 0.1825, 0.175, 0.1675, 0.16, 0.145, 0.13, 0.115, 0.1,
     0.075, 0.05),
    (32.48, 25.52, 20.91, 17.66, 15.26, 13.43, 11.98, 10.81, 9.85, 9.04, 8.36, 7.77, 7.26, 6.81, 6.41, 6.06, 5.74,
     5.45))))


def test_an_airspeed_in_m_per_s_is_not_called_knots_where_the_level_differs(tmp_path):
    """A 15 in slow flyer (a new-family audit's geometry) whose loads come from the APC slow flyer's
    calibrated set: the generic set under-predicts its thrust, and m/s data were said to match
    better in knots (the model then runs at half the airspeed). Compared at the data's static
    level, the shape decides: nothing said; the same data in knots still are."""
    from propmap.identify import read_loads
    from propmap.identify.data import sanity_check

    (tmp_path / "g.txt").write_text(GEOM_15X45)
    prop = pm.read_geometry(tmp_path / "g.txt", n_blades=2, diameter_in=15)
    params = pm.default_params("apcsf_10x4.7")
    for factor, said in ((1.0, False), (1 / 0.514444, True)):
        rows = ["rpm,airspeed,thrust (N),torque (N m)"]
        for V in (0.0, 3.0, 6.0, 9.0):
            for rpm in np.arange(2000.0, 5600.0, 400.0):
                r = pm.rotor_loads(prop, params, rpm * math.pi / 30, V, 0.0)
                rows.append(f"{rpm},{V * factor},{float(r.thrust)!r},{float(r.torque)!r}")
        (tmp_path / "v.csv").write_text("\n".join(rows) + "\n")
        warned = [w for w in sanity_check(read_loads(tmp_path / "v.csv"), prop) if "airspeed read as" in w]
        assert bool(warned) == said, warned


def test_a_fits_residuals_name_their_points_and_outliers_are_warned(tmp_path):
    """Residuals were listed as '#5 -0.615' (an index into the stacked vector), and three outliers
    at 7x the rms passed without a word (identification audit, 2026-11-26)."""
    from propmap.identify import FitOptions, fit_loads, read_loads

    prop, truth = pm.load_propeller("apce_9x6"), pm.default_params("apce_9x6")
    rows = ["rpm,airspeed,thrust (N),torque (N m),group"]
    for rpm in (3000.0, 4000.0, 5000.0, 6000.0):
        for V in (0.0, 2.0, 4.0, 6.0, 8.0, 10.0):
            r = pm.rotor_loads(prop, truth, rpm * math.pi / 30, V, 0.0)
            T = float(r.thrust) * (1.6 if (rpm, V) == (5000.0, 4.0) else 1.0)  # one outlier
            rows.append(f"{rpm},{V},{T!r},{float(r.torque)!r},r{rpm:.0f}")
    f = tmp_path / "runs.csv"
    f.write_text("\n".join(rows) + "\n")
    res = fit_loads(read_loads(f), prop, options=FitOptions(multistart=0))
    said = [w for w in res.warnings if "the largest misfits" in w]
    assert said and "thrust, r5000, 5000 rpm, 4 m/s" in said[0], res.warnings
    assert res.extra["residual_labels"][0] == "thrust, r3000, 3000 rpm, 0 m/s"
    assert "(thrust, r5000, 5000 rpm, 4 m/s)" in res.report_text()


@pytest.mark.parametrize("header, torque, rate, cause", [
    ("omega,airspeed,thrust (N),torque (N m)", 1.0, 1.0, "a rotation rate in rpm read as rad/s (an 'omega' column"),
    ("rpm,airspeed,thrust (N),torque", 100.0, 1.0, "torque in N cm read as N m"),
    ("rpm,airspeed,thrust (N),torque", 1 / 0.00706155181, 1.0, "torque in ozf in read as N m"),
    # 1.975 for 1975 rpm (a thousands separator read as a decimal point) was blamed on 'a diameter far off' (a
    # fuzzing audit, 2026-11-27)
    ("rpm,airspeed,thrust (N),torque (N m)", 1.0, 1e-3, "rotation rates in thousands read as rpm (1.975 for 1975"),
])
def test_the_sanity_checks_causes_name_rpm_as_rad_per_s_and_small_torque_units(tmp_path, header, torque, rate, cause):
    """omega holding rpm was diagnosed as 'the electrical rpm of a motor with 10 pole pairs', and a
    torque in N cm or oz in got only 'check the units' (identification audit, 2026-11-26)."""
    from propmap.identify import DataError, read_loads
    from propmap.identify.data import sanity_check

    prop, params = pm.load_propeller("apce_9x6"), pm.default_params("apce_9x6")
    rows = [header]
    for rpm in (3000.0, 4000.0, 5000.0, 6000.0):
        for V in (0.0, 4.0, 8.0):
            r = pm.rotor_loads(prop, params, rpm * math.pi / 30, V, 0.0)
            rows.append(f"{rpm * rate!r},{V},{float(r.thrust)!r},{float(r.torque) * torque!r}")
    f = tmp_path / "slip.csv"
    f.write_text("\n".join(rows) + "\n")
    with pytest.raises(DataError, match=re.escape(cause)) as e:
        sanity_check(read_loads(f), prop)
    assert "diameter far off" not in str(e.value)


def test_a_held_out_group_predicted_worse_than_by_the_base_set_is_said(tmp_path, capsys):
    """A CSV fit's held-out rmse against the base set was printed without comment where the fitted
    set did worse (identification audit, 2026-11-26). UIUC Propeller Data Site vol. 1, apce_9x6,
    written as a stand's CSV: the 6038-rpm sweep rd0991 (the fit better on both) is not said."""
    from propmap.cli.main import main
    from propmap.identify import loads_from_catalogue
    from propmap.io.catalogue import catalogue

    prop = pm.load_propeller("apce_9x6")
    d = loads_from_catalogue(catalogue()["apce_9x6"], prop.diameter)
    rows = ["rpm,airspeed,thrust (N),torque (N m),group"]
    rows += [f"{float(w * 30 / math.pi)!r},{float(V)!r},{float(T)!r},{float(Q)!r},{g}" for w, V, T, Q, g in
             zip(d.omega, d.airspeed, d.measured["thrust"], d.measured["torque"], d.group)]
    f = tmp_path / "runs.csv"
    f.write_text("\n".join(rows) + "\n")
    from propmap.cli._load_comparison import held_out_worse

    # the rule: 25% and 2% of the largest value worse, on a fitted quantity (the review found 40 of 338
    # leave-one-group-out fits warned without the 2% floor, many under 1-2% of the load)
    fitted, base = {"thrust_rmse": 0.30, "torque_rmse": 0.0014}, {"thrust_rmse": 0.10, "torque_rmse": 0.0004}
    largest = {"thrust": 8.0, "torque": 0.07}
    assert held_out_worse(fitted, base, largest, ["thrust", "torque"]) == ["thrust"]
    assert held_out_worse(fitted, base, largest, ["torque"]) == []
    assert held_out_worse(fitted, base, {"thrust": 8.0, "torque": 0.03}, ["thrust", "torque"]) == ["thrust", "torque"]
    assert main(["fit", "loads", str(f), "--prop", "apce_9x6", "--out", str(tmp_path / "b.toml"),
                 "--holdout", "rd0991"]) == 0
    assert "worse than" not in capsys.readouterr().err


def test_a_stands_thrust_at_rest_is_said_where_its_rows_are_skipped(tmp_path):
    """A stand's non-zero thrust at 0 rpm (a tare of 0.021 N, about 5% of the lowest step) was
    dropped with the stopped rows without a word (identification audit, 2026-11-26)."""
    from propmap.identify import read_loads

    rows = ["rpm,thrust (N),torque (N m)", "0,0.021,0", "0,0.020,0"]
    rows += [f"{r},{(r / 3000) ** 2 + 0.021},{(r / 3000) ** 2 / 50}" for r in range(3000, 9000, 1000)]
    f = tmp_path / "stand.csv"
    f.write_text("\n".join(rows) + "\n")
    said = [n for n in read_loads(f).notes if "rpm 0" in n]
    assert said and "their thrust reads 0.0205 N in the median" in said[0] and "tare it first" in said[0]
    f.write_text("\n".join(r.replace("0,0.021,0", "0,0,0").replace("0,0.020,0", "0,0,0") for r in rows) + "\n")
    assert not any("tare" in n for n in read_loads(f).notes)
    # a tared stand's rest rows scatter about 0 (the review's 0.3 gf drift in 0.5 gf of noise): not said
    f.write_text("\n".join([rows[0], "0,0.020,0", "0,-0.011,0", "0,0.018,0", "0,-0.010,0"] + rows[3:]) + "\n")
    assert not any("tare" in n for n in read_loads(f).notes)


def test_coverage_is_written_to_12_digits(tmp_path):
    """A fit's [coverage] read rpm_min = 1974.9999999999998 (rad/s and back; identification audit,
    2026-11-26): written to 12 digits for every producer (loads and flight fits)."""
    from propmap.io.params_file import read_coverage, write_params

    params = pm.generic_params()
    write_params(tmp_path / "p.toml", params, params.air, coverage={"rpm_min": 1974.9999999999998, "rpm_max": 6038.0,
                                                                    "J_max": 0.8040000000000001})
    cov = read_coverage(tmp_path / "p.toml")
    assert (cov["rpm_min"], cov["rpm_max"], cov["J_max"]) == (1975.0, 6038.0, 0.804)


def test_descent_data_in_the_vortex_ring_are_warned_of_and_scored_by_state():
    """Axial descent of the APC 10x7E through the vortex ring (a descent audit, 2026-11-26: such
    data were fitted and scored without a word, the fit moving the static thrust by -2.4%). The
    sanity check says how many points lie in the vortex-ring or turbulent-wake state; the
    errors are given by the model's working state too."""
    from propmap.identify import LoadData
    from propmap.identify.data import sanity_check
    from propmap.validation import load_errors

    prop, params = pm.load_propeller("apce_10x7"), pm.default_params("apce_10x7")
    V = np.linspace(0.0, 14.0, 29)
    om = np.full(V.size, 5000 * math.pi / 30)
    inc = np.where(V > 0, math.pi, 0.0)
    r = pm.rotor_loads(prop, params, om, V, inc)
    assert set(r.state_name) >= {"normal working", "vortex ring", "windmill brake"}
    data = LoadData(om, V, inc, {"thrust": r.thrust, "torque": r.torque}, np.array(["descent"] * V.size, dtype=object))
    (w,) = [w for w in sanity_check(data, prop) if "vortex-ring or turbulent-wake" in w]
    g = pm.rotor_loads(prop, pm.generic_params(), om, V, inc)  # (the check's model)
    n = int(np.sum(np.isin(g.state_name, ("vortex ring", "turbulent wake"))))
    assert w.startswith(f"{n} of {V.size} points")
    e = load_errors(data, prop, params)
    assert list(e["states"]) == [s for s in ("normal working", "vortex ring", "turbulent wake", "windmill brake")
                                 if s in set(r.state_name)]
    assert sum(row["thrust"]["n"] for row in e["states"].values()) == e["overall"]["thrust"]["n"] == V.size
    assert all(row["thrust"]["rms"] < 1e-9 for row in e["states"].values())  # (the model's own loads)
    climb = data.subset(V <= 2.0)  # (normal working only: no state table)
    climb = LoadData(climb.omega, climb.airspeed, np.zeros(climb.n), climb.measured, climb.group)
    assert load_errors(climb, prop, params)["states"] == {}


def test_a_run_with_its_rpm_in_rev_per_s_is_warned_of(tmp_path):
    """A UIUC static file whose RPM column holds rev/s keeps CT and CP, so the load check cannot
    see it; it was fitted without a word, alone or beside sweeps at the right rpm (a user-level
    audit, 2026-11-26). Its chord Reynolds number at 0.75 R (414-1240 here) is warned of."""
    from propmap.identify import loads_from_uiuc_files
    from propmap.identify.data import sanity_check
    from propmap.io.catalogue import _data_path, get_entry

    prop = pm.load_propeller("apce_10x7")
    e = get_entry("apce_10x7")
    static, sweep = _data_path(e.static_files[0]), _data_path(e.sweep_files[0])
    lines = static.read_text().splitlines()
    rows = (ln.split() for ln in lines[1:] if ln.strip())
    slow = [lines[0]] + [" ".join([f"{float(w[0]) / 60:.4f}", *w[1:]]) for w in rows]
    (tmp_path / "apce_10x7_static_9999rd.txt").write_text("\n".join(slow) + "\n")
    data = loads_from_uiuc_files([tmp_path / "apce_10x7_static_9999rd.txt", sweep], prop.diameter)
    (w,) = [w for w in sanity_check(data, prop) if "Reynolds" in w]
    assert "in static_9999rd" in w and "rev/s (Hz) read as rpm" in w
    assert not [w for w in sanity_check(loads_from_uiuc_files([static, sweep], prop.diameter), prop)
                if "Reynolds" in w]
    # a 45 mm propeller's low ESC step, 1500 rpm (Re75 1.4e3), is no slip (a review): not below 1000 rpm
    from propmap.identify import LoadData

    small = pm.load_propeller("cfnq_45p1")
    rpm = np.arange(1500.0, 22600.0, 1500.0)
    r = pm.rotor_loads(small, pm.default_params("cfnq_45p1"), rpm * math.pi / 30, 0.0, 0.0)
    steps = LoadData(rpm * math.pi / 30, np.zeros(rpm.size), np.zeros(rpm.size),
                     {"thrust": r.thrust, "torque": r.torque},
                     np.array([f"step{k + 1}" for k in range(rpm.size)], dtype=object))
    assert small.reynolds_75(rpm[0] * math.pi / 30, pm.Air()) < 2000
    assert not [w for w in sanity_check(steps, small) if "Reynolds" in w]


def test_validate_labels_the_fits_runs_among_other_files(tmp_path, capsys):
    """UIUC runs: a fit's files given in part, or among others, were not labelled (one digest over
    all files; a user-level audit, 2026-11-26): each file's digest tells its runs, and a mixed
    'all points' row is said to be one."""
    from propmap.io.catalogue import _data_path, get_entry

    e = get_entry("apce_10x7")
    files = [_data_path(e.static_files[0]), *(_data_path(f) for f in e.sweep_files[:3])]
    out = tmp_path / "p.toml"
    assert main(["fit", "loads", *map(str, files[:2]), "--prop", "apce_10x7", "--out", str(out)]) == 0
    capsys.readouterr()
    assert main(["validate", *map(str, files), "--prop", "apce_10x7", "--params", str(out)]) == 0
    text = capsys.readouterr().out
    static_run, first_sweep = files[0].stem.split("_static_")[1], files[1].stem.split("_")[2]
    assert f"static_{static_run} (fitted)" in text and f"{first_sweep} (fitted)" in text, text
    assert "mixes the fit's own groups with others" in text and "was fitted to part of this data" in text
    assert main(["validate", str(files[1]), "--prop", "apce_10x7", "--params", str(out)]) == 0
    text = capsys.readouterr().out
    assert "all points (fitted)" in text and f"was fitted to this data: {first_sweep} in-sample" in text, text


def test_validate_labels_runs_named_by_their_files_where_two_share_a_run_id(tmp_path, capsys):
    """Two sweeps copied as 'x_sweep_4007.txt' and 'x_sweep_6020.txt' share the run id 'sweep', so each
    is named by its stem; validated with a file the fit did not read, the fit's file was labelled
    by a run id the table did not have (a review, 2026-11-26)."""
    import json
    import shutil

    from propmap.io.catalogue import _data_path, get_entry

    e = get_entry("apce_10x7")
    static = _data_path(e.static_files[0])
    a, b = tmp_path / "apce_10x7_sweep_4007.txt", tmp_path / "apce_10x7_sweep_6020.txt"
    shutil.copyfile(_data_path(e.sweep_files[0]), a)
    shutil.copyfile(_data_path(e.sweep_files[1]), b)
    out = tmp_path / "f.toml"
    assert main(["fit", "loads", str(static), str(a), "--prop", "apce_10x7", "--out", str(out)]) == 0
    capsys.readouterr()
    assert main(["validate", str(a), str(b), "--prop", "apce_10x7", "--params", str(out), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["in_fit"] == {"apce_10x7_sweep_4007": "fitted"}


def test_validate_labels_the_catalogues_own_data_as_in_sample(tmp_path, capsys, shared_data):
    """`validate apce_8x6` with its calibrated set (fitted to all 131 points) printed the fit's
    residual as a plain error; a fit of the catalogue name labelled nothing when its bundled UIUC
    files were given, nor under `validate PROP --params` (a validation audit)."""
    from propmap.cli.main import main

    assert main(["validate", "apce_8x6"]) == 0
    assert "calibrated:apce_8x6 was fitted to these runs: in-sample" in capsys.readouterr().out
    fit = tmp_path / "fit.toml"
    assert main(["fit", "loads", "apce_8x6", "--holdout", "2803rd,2804rd", "--out", str(fit)]) == 0
    capsys.readouterr()
    assert main(["validate", "apce_8x6", "--params", str(fit)]) == 0
    out = capsys.readouterr().out
    assert "was fitted to runs static_2797rd, 2798rd, 2799rd, 2800rd, 2801rd, 2802rd: in-sample" in out
    assert "held out: 2803rd, 2804rd" in out
    files = sorted(str(p) for p in (shared_data / "uiuc_propdb" / "v1").glob("apce_8x6_*.txt"))
    assert main(["validate", *files, "--prop", "apce_8x6", "--params", str(fit)]) == 0
    out = capsys.readouterr().out
    assert "2803rd (held out)" in out and "2798rd (fitted)" in out
    assert main(["validate", *files, "--prop", "apce_8x6"]) == 0
    assert "2804rd (fitted)" in capsys.readouterr().out  # (the calibrated set saw every run)


def test_a_value_under_an_unnamed_column_is_refused_not_dropped(tmp_path, capsys):
    """A comma-separated file with decimal commas and a trailing separator in its header
    (``RPM,Thrust (gf),`` then ``1975,55,27``) was read as 55 gf, the decimals dropped in the
    unnamed column; a points file likewise read 10,5 m/s as 10 m/s (an input fuzzing audit,
    2026-11-27). A trailing separator with nothing under it, and a first unnamed column (a row
    index), stay read."""
    bad = tmp_path / "gf.csv"
    bad.write_text("RPM,Thrust (gf),\n1975,55,27\n2292,75,95\n")
    with pytest.raises(DataError, match=r"line 2: column 3 has no name in the header but holds '27' \(a number "
                                        r"with a decimal comma in a comma-separated file\?"):
        read_loads(bad)
    ok = tmp_path / "ok.csv"
    rpm, gf = np.arange(2000, 8000, 1000), np.arange(40.25, 46.25)
    ok.write_text(",RPM,Thrust (gf),\n" + "".join(f"{k},{r},{t},\n" for k, (r, t) in enumerate(zip(rpm, gf))))
    np.testing.assert_allclose(read_loads(ok).measured["thrust"], gf * 9.80665e-3)
    pts = tmp_path / "pts.csv"
    pts.write_text("rpm,airspeed,incidence_deg,\n5000,10,5,30\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 2
    assert capsys.readouterr().err.strip().endswith(
        "line 2: column 4 has no name in the header but holds '30' (a number with a decimal comma in a "
        "comma-separated file? save it with decimal points, or with ';' as the separator): name the column or "
        "remove it")
    pts.write_text(",rpm,airspeed,incidence_deg,\n0,5000,10.5,30,\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 0
    assert (tmp_path / "o.csv").read_text().startswith(",rpm,airspeed,incidence_deg,,thrust,")  # the names as written
    multi = tmp_path / "mi.csv"  # a pandas MultiIndex's two unnamed columns first
    multi.write_text(",,RPM,Thrust (gf)\n" + "".join(f"run1,{k},{r},{t}\n" for k, (r, t) in enumerate(zip(rpm, gf))))
    assert read_loads(multi).n == 6


@pytest.mark.parametrize("name", ["Pitch (deg)", "pitch", "blade_angle_deg", "Blade angle (°)", "pitch_angle_rad"])
def test_a_blade_pitch_column_under_another_name_is_refused(tmp_path, name):
    """A collective sweep whose blade angle was written as 'Pitch (deg)', 'pitch' or
    'blade_angle_deg' was fitted at collective 0 without a word (an input fuzzing audit,
    2026-11-27); a propeller's geometric pitch in inches is not a setting and stays unread."""
    rows = "".join(f"6000,{c},{1 + 0.1 * c},{0.02 + 0.001 * c}\n" for c in range(0, 12, 2))
    f = tmp_path / "sweep.csv"
    f.write_text(f"rpm,{name},thrust,torque\n" + rows)
    with pytest.raises(DataError, match=f"column '{re.escape(name)}' looks like a blade pitch setting, which "
                                        "propmap reads only as 'collective_deg'"):
        read_loads(f)
    f.write_text("rpm,pitch (in),thrust,torque\n" + "".join(f"{3000 + 500 * k},6,{1 + 0.1 * k},0.02\n"
                                                            for k in range(6)))
    assert read_loads(f).collective is None


def test_a_points_file_below_100_rpm_is_warned_of(tmp_path, capsys):
    """A ';'-separated points file written with thousands separators (5.000 for 5000 rpm) was
    solved at 5 rpm without a word (an input fuzzing audit, 2026-11-27)."""
    pts = tmp_path / "p.csv"
    pts.write_text("rpm;airspeed;incidence_deg\n5.000;0;0\n6.500;0;0\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 0
    assert "rpm as low as 5, below 100 rpm: a thousands separator read as a decimal point" in capsys.readouterr().err
    pts.write_text("rpm;airspeed;incidence_deg\n5000;0;0\n6500;0;0\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 0
    assert "below 100 rpm" not in capsys.readouterr().err


def test_messages_for_an_empty_file_and_a_long_row_name_them(tmp_path, capsys):
    """'a fit needs at least 1 distinct operating points (propmap validate compares any number)'
    from validate itself, and pandas' 'C error: Expected 3 fields in line 4, saw 4' (an input
    fuzzing audit, 2026-11-27)."""
    empty = tmp_path / "e.csv"
    empty.write_text("rpm,airspeed,thrust,torque\n")
    assert main(["validate", str(empty), "--prop", "apce_10x7"]) == 2
    assert capsys.readouterr().err.strip().endswith("has 0 points; no data rows under the header")
    pts = tmp_path / "p.csv"
    pts.write_text("rpm,airspeed,incidence_deg\n3000,0,0\n5000,5,0\n5000,10,30,7\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 2
    assert capsys.readouterr().err.strip().endswith(": line 4 has 4 fields, but the header has 3")


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le"])
def test_a_utf16_points_file_is_named_as_such(tmp_path, capsys, encoding):
    """Without a byte-order mark a UTF-16 points file was refused as lacking its columns (an input
    fuzzing audit, 2026-11-27)."""
    pts = tmp_path / "p.csv"
    pts.write_bytes("rpm,airspeed,incidence_deg\n5000,0,0\n".encode(encoding))
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 2
    assert capsys.readouterr().err.strip().endswith("NUL bytes in the text; it looks like UTF-16: save the file as "
                                                    "UTF-8 CSV")


def test_a_points_file_with_a_blade_pitch_column_under_another_name_is_refused(tmp_path, capsys):
    """loads --points solved a 'pitch (deg)' column's rows at collective 0 (a review, 2026-11-27)."""
    pts = tmp_path / "p.csv"
    pts.write_text("rpm,airspeed,incidence_deg,pitch (deg)\n5000,0,0,4\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 2
    assert "column 'pitch (deg)' looks like a blade pitch setting" in capsys.readouterr().err
    pts.write_text("rpm,airspeed,incidence_deg,pitch (in)\n5000,0,0,7\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 0


def test_validate_with_an_older_parameter_file_checks_the_data_digest(tmp_path, capsys):
    """A parameter file written before files_sha256: the fit's groups are labelled only where the
    file's data are the same (a mutation audit, 2026-11-27: the digest check removed passed)."""
    f, out = _fitted_runs(tmp_path)
    legacy = tmp_path / "legacy.toml"
    legacy.write_text(re.sub(r"(?ms)^files_sha256 = \[.*?\]\n", "", out.read_text()))
    (tmp_path / "otherday").mkdir()
    od = tmp_path / "otherday" / "runs.csv"
    od.write_text(f.read_text().replace("\n3000.0,0.0,", "\n3000.0,0.0,1", 1))
    capsys.readouterr()
    assert main(["validate", str(f), "--prop", "apce_8x6", "--params", str(legacy)]) == 0
    assert "s0 (fitted)" in capsys.readouterr().out
    assert main(["validate", str(od), "--prop", "apce_8x6", "--params", str(legacy)]) == 0
    assert "(fitted)" not in capsys.readouterr().out


def test_validate_labels_a_catalogue_propellers_runs_under_a_geometry_of_another_name(tmp_path, capsys):
    """The bundled runs of apce_10x7 validated against the same blade under another name (an APC
    PE0 file, here a copy of the catalogue's geometry) were shown without '(fitted)' and without
    the in-sample line, so the generic set's residual (2.8%) read as a prediction (a
    vehicle-designer audit, 2026-11-28); the runs are now told by their content."""
    import shutil

    from propmap.io.catalogue import _data_path, get_entry

    e = get_entry("apce_10x7")
    geom = tmp_path / "my_ten_by_seven.txt"
    shutil.copy(_data_path(e.geometry_file), geom)
    files = [str(_data_path(e.static_files[0])), str(_data_path(e.sweep_files[0]))]
    base = ["validate", *files, "--prop", str(geom), "--diameter-in", "10", "--blades", "2"]
    sweep = Path(files[1]).stem.split("_")[2]
    for params in ("generic", "calibrated:apce_10x7"):
        assert main([*base, "--params", params]) == 0
        text = capsys.readouterr().out
        assert f"{sweep} (fitted)" in text and f"{params} was fitted to this data:" in text, text
    assert main([*base, "--params", "calibrated:apce_8x6"]) == 0  # (another propeller's set: a prediction)
    text = capsys.readouterr().out
    assert "(fitted)" not in text and "was fitted to" not in text, text
    # another blade with these runs: its errors are no residual of any fit (a review: labelled in-sample)
    assert main(["validate", *files, "--prop", "apce_8x6", "--params", "generic"]) == 0
    text = capsys.readouterr().out
    assert "(fitted)" not in text and "was fitted to" not in text, text


def test_validate_holds_the_data_to_the_parameters_given_not_the_generic_set(tmp_path, capsys):
    """With --params, the units-and-counts check compares the data with those parameters: data
    that a fitted set predicts exactly were warned of against the generic set, and told that 'a
    fit would absorb the difference' (a user-level audit, 2026-11-29)."""
    from propmap.io.params_file import write_params

    prop = pm.load_propeller("apce_8x6")
    generic = pm.generic_params()
    draggy = generic.replace(cd_min=8 * generic.cd_min)  # (torque 1.53x the generic set's in the median, thrust 0.98x)
    rpm = np.array([4000.0, 5000.0, 6000.0, 7000.0])

    def write(name, params):
        r = pm.rotor_loads(prop, params, rpm * math.pi / 30, 0.0, 0.0)
        (tmp_path / name).write_text("rpm,thrust,torque\n" + "".join(
            f"{n},{float(T)!r},{float(Q)!r}\n" for n, T, Q in zip(rpm, r.thrust, r.torque)))
        return str(tmp_path / name)

    write_params(tmp_path / "draggy.toml", draggy)
    mine = write("mine.csv", draggy)
    assert main(["validate", mine, "--prop", "apce_8x6", "--params", str(tmp_path / "draggy.toml")]) == 0
    assert "warning" not in capsys.readouterr().err
    assert main(["validate", mine, "--prop", "apce_8x6"]) == 0  # (no --params: held to the generic set)
    err = capsys.readouterr().err
    assert "the measured torque is 1.53 times (outside 0.667-1.5x) what the generic set predicts" in err
    assert "a fit would absorb the difference" in err
    assert main(["validate", write("generic.csv", generic), "--prop", "apce_8x6",
                 "--params", str(tmp_path / "draggy.toml")]) == 0
    err = capsys.readouterr().err
    assert "the measured torque is 0.653 times (outside 0.667-1.5x) what the model predicts" in err
    assert "or whether the parameters are this propeller's" in err and "a fit would absorb" not in err
    # --params generic is the generic set: worded as without --params, not as a propeller's own set
    assert main(["validate", mine, "--prop", "apce_8x6", "--params", "generic"]) == 0
    err = capsys.readouterr().err
    assert "the measured torque is 1.53 times (outside 0.667-1.5x) what the generic set predicts" in err, err
    assert "a fit would absorb the difference" in err and "whether the parameters are this propeller's" not in err
