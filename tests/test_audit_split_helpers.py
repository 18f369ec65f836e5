"""A mutation audit of the helpers split out of four long functions (2026-11-30): identify/flight.py
(_flight_names, _start_values, _FlightModel), identify/level_flight_fit.py (_level_flight_names,
_level_flight_residual, _select_body_lift), cli/map.py (_check_options, _check_vehicle_rotors
(_one_map_vehicle since stop 96), _with_collective, _write_c_header) and cli/trim.py
(_check_options, _trim, _echo_text). Each test kills a hand-made mutant that survived the
modules' own test files, by the documented behaviour it changed."""

import json
import math
from dataclasses import replace
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag
from propmap.core.solver import Discretization
from propmap.identify import FitOptions, fit_level_flight, read_vehicle, simulate_level_flight
from propmap.identify.flight import FlightSamples, fit_flight, predict_flight
from propmap.identify.level_flight import LevelFlightData
from propmap.identify.level_flight_fit import body_lift

from cli_helpers import one_line_error, run

VEHICLE = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
COARSE = Discretization(12, 8)


def _samples(vehicle, n=24, seed=3):
    """n synthetic samples of one log at 10 Hz, the force the model's own for ``vehicle`` (generic set)."""
    rng = np.random.default_rng(seed)
    s = FlightSamples(log_names=("synthetic",), log_index=np.zeros(n, int), t=np.arange(n) * 0.1,
                      velocity=rng.uniform(-6, 6, (n, 3)) * [1, 1, 0.4], angular_velocity=rng.uniform(-1, 1, (n, 3)),
                      rotor_omega=rng.uniform(900, 1500, (n, 4)), rotor_acceleration=np.zeros((n, 4)),
                      force=np.zeros((n, 3)), moment=None, reference_force=None, reference_moment=None, rate_hz=10.0)
    return replace(s, force=predict_flight(s, vehicle, pm.generic_params(), discretization=COARSE).force)


# ---------------------------------------------------------------- identify/flight.py


def test_a_fitted_rotor_interference_starts_at_1_and_is_recovered():
    """Mutants F6 (rotor_interference started at 0 where the vehicle has none, not 1), F10 (the fitted
    interference never reaching the model's vehicle) and F13 (the implicit Jacobian used with rotor_interference
    fitted, which vehicle_wrench's derivatives do not reach): data made with interference 0.8, a vehicle without
    any; the fit starts at 1 (fit_flight's documented start), recovers 0.8 and reports it."""
    veh = pm.read_vehicle(VEHICLE)
    assert veh.rotor_interference == 0
    s = _samples(replace(veh, rotor_interference=0.8), n=12)
    res = fit_flight(s, veh, options=FitOptions(names=("rotor_interference",), prior=False), discretization=COARSE)
    assert res.starts[0]["x0"].tolist() == [1.0]
    assert res.x[0] == pytest.approx(0.8, abs=1e-6)
    assert res.extra["rotor_interference"] == pytest.approx(0.8, abs=1e-6)
    assert np.sqrt(np.mean(res.residuals**2)) < 1e-6


def test_the_airframe_terms_start_small_but_non_zero_and_the_centre_of_mass_at_the_vehicles():
    """Mutant F5 (wash_factor started at 0 where the airframe has none, not 1): the airframe's terms start at the
    body's values, a drag area of 0 at 1e-3 m^2 and a wash factor of 0 at 1 (every Jacobian column alive), the
    centre of mass at the vehicle's."""
    veh = replace(pm.read_vehicle(VEHICLE), centre_of_mass=np.array([0.004, -0.002, 0.0]))
    s = _samples(veh)
    names = ("drag_area_x", "drag_area_y", "drag_area_z", "wash_factor", "cg_x", "cg_y")
    body = BodyDrag(drag_area=(0.01, 0.0, 0.02), wash_factor=0.0)
    res = fit_flight(s, veh, body=body, options=FitOptions(names=names, prior=False, max_nfev=1),
                     discretization=COARSE)
    np.testing.assert_allclose(res.starts[0]["x0"], [0.01, 1e-3, 0.02, 1.0, 0.004, -0.002], rtol=1e-12)


# ---------------------------------------------------------------- cli/trim.py


def test_trim_takes_a_thrust_of_1e5_n_to_the_trim_and_refuses_one_above(capsys):
    """Mutant T1 (|thrust| = 1e5 N refused as out of range): 1e5 N is inside [-1e5, 1e5] and reaches the trim,
    which says no collective makes it; 1.00001e5 N is refused by the option's range."""
    code, _, err = run(capsys, "trim", "apce_8x6", "--rpm", "6000", "--thrust", "1e5")
    assert one_line_error(code, err, "--thrust: no collective in [-20, 30] deg makes thrust=100000 N"), err
    code, _, err = run(capsys, "trim", "apce_8x6", "--rpm", "6000", "--thrust", "100001")
    assert one_line_error(code, err, "--thrust must be finite and in [-1e5, 1e5] N, got 100001.0"), err


def test_trim_refuses_an_empty_collective_range(capsys):
    """Mutant T2 (LOW == HIGH let through as a collective range): --range-deg 5 5 searches nothing; refused."""
    code, _, err = run(capsys, "trim", "apce_8x6", "--thrust", "2", "--rpm", "6000", "--range-deg", "5", "5")
    assert one_line_error(code, err, "--range-deg must be two angles LOW < HIGH within [-45, 45] deg, got 5.0 5.0"), err


def test_trim_searches_rates_up_to_the_cli_maximum(capsys):
    """Mutant T8 (--rpm-range's HIGH at RPM_MAX refused): the rates up to RPM_MAX (954929 rpm) are within
    (0, RPM_MAX]; the search from 1000 rpm to there finds the rate that makes 2 N (5436 rpm)."""
    code, out, err = run(capsys, "trim", "apce_8x6", "--thrust", "2", "--rpm-range", "1000", "954929", "--json")
    assert code == 0, err
    j = json.loads(out)
    assert j["rpm"] == pytest.approx(5436.44, rel=1e-5) and j["thrust"] == pytest.approx(2.0, abs=1e-6)


def test_trim_text_gives_the_trimmed_rate_in_rad_s_and_a_tiny_climb_ratio_without_a_minus_sign(capsys):
    """Mutants T7 (the rad/s in the rpm trim's text the rpm's number) and T6 (lambda2 = -3.5e-5, a climb at 89.99
    deg incidence, printed "-0.000"): 5436.44 rpm is 569.3 rad/s; lambda2 is printed as loads prints it, 0.000."""
    code, out, err = run(capsys, "trim", "apce_8x6", "--thrust", "2", "--rpm-range", "1000", "9000")
    assert code == 0, err
    assert "5436.4 rpm (569.3 rad/s) makes T = 2.0000 N" in out, out
    code, out, err = run(capsys, "trim", "apce_8x6", "--thrust", "2", "--rpm", "6000", "--airspeed", "1",
                         "--incidence-deg", "89.99", "--json")
    assert code == 0 and -1e-4 < json.loads(out)["lambda2"] < 0, out
    code, out, err = run(capsys, "trim", "apce_8x6", "--thrust", "2", "--rpm", "6000", "--airspeed", "1",
                         "--incidence-deg", "89.99")
    assert code == 0 and "lambda2 = V_descent/v_h = 0.000)" in out and "-0.000" not in out, out


def test_trim_hover_reference_searches_the_given_collective_range(capsys):
    """Mutant T9 (the hover reference trimmed over the default -20..30 deg, not --range-deg): 0.1 N at 6000 rpm
    needs about -24 deg, edgewise at 5 m/s and in hover; with --range-deg -45 0 both trims find it, and dCQ is CQ
    minus the hover's CQ at that thrust and rpm (trimmed here by trim itself)."""
    argv = ["trim", "apce_8x6", "--thrust", "0.1", "--rpm", "6000", "--range-deg", "-45", "0", "--json"]
    code, out, err = run(capsys, *argv, "--airspeed", "5", "--incidence-deg", "90", "--hover-reference")
    assert code == 0, err
    j = json.loads(out)
    code, out, err = run(capsys, *argv)
    assert code == 0, err
    hover = json.loads(out)
    assert hover["collective_deg"] < -20 and j["collective_deg"] < -20
    assert j["dCQ_constant_thrust"] == pytest.approx(j["CQ"] - hover["CQ"], rel=1e-5, abs=1e-9)
    assert j["dCQ_constant_thrust"] == pytest.approx(2.8e-4, rel=0.05)  # (regression value, 2026-11-30)


# ---------------------------------------------------------------- identify/level_flight_fit.py


@pytest.fixture(scope="module")
def quad():
    return read_vehicle(resources.files("propmap") / "data" / "examples" / "quadrotor.toml")


def _with_body_lift(quad, scale, n=12):
    """Level flight at n speeds 0-14 m/s (pitch -2.5 deg per m/s) where the body carries part of the weight: the
    rotors trimmed (gill2017-apc, M = 30) to W - L, L the body lift of cl1_body = 2 scale, cl2_body = scale,
    alpha0_body = 15 deg; then 0.5% rpm noise (seed 5)."""
    true = pm.preset("gill2017-apc").replace(M=30.0)
    V = np.linspace(0, 14, n)
    pitch = -2.5 * V
    probe = LevelFlightData(V, np.radians(pitch), np.zeros(n), np.full((n, 4), 1000.0), np.zeros((n, 3)))
    L = body_lift((2.0 * scale, 1.0 * scale, math.radians(15.0)), probe, quad, 30.0, true.air)
    parts = [simulate_level_flight(replace(quad, mass=(quad.weight - L[j]) / quad.gravity), true, V[j:j + 1],
                                   pitch[j:j + 1]) for j in range(n)]
    omega = np.concatenate([p.omega for p in parts])
    rng = np.random.default_rng(5)
    return replace(probe, omega=omega * (1 + 0.005 * rng.standard_normal(omega.shape)))


def test_body_lift_matters_at_a_p_value_between_1_and_5_percent(quad):
    """Mutants L9 (the F-test's level 0.05 made 0.01) and L13 (alpha0_body_deg in radians): data with a weak body
    lift give p = 0.014, below the paper's 5% level: body lift matters and the fit with it (seven parameters) is
    the one selected, its body terms reported as fitted (alpha0_body in degrees)."""
    r = fit_level_flight(_with_body_lift(quad, 1.0), quad, options=FitOptions(M=30.0, body_lift=True))
    bl = r.extra["body_lift"]
    assert 0.01 < bl["p_value"] < 0.05, bl
    assert bl["matters"] and bl["selected"] == "with"
    assert r.names == ("cl1", "cl2", "cd", "alpha0", "cl1_body", "cl2_body", "alpha0_body")
    # Mutant L13 (alpha0_body reported in radians under its _deg name): the verdict's body terms are the fit's
    assert bl["body_terms"] == {"cl1_body": r.x[4], "cl2_body": r.x[5], "alpha0_body_deg": math.degrees(r.x[6])}
    assert abs(r.x[6]) > 0.05


def test_the_fit_without_body_lift_selected_counts_the_full_fits_evaluations_too(quad):
    """Mutant L11 (the fit selected without body lift reporting only its own evaluations): data without body lift
    (p = 0.95): the selected fit is the one without it, and its nfev counts both fits run, more than that fit alone
    (the same fit run plainly, deterministic) took."""
    d = _with_body_lift(quad, 0.0)
    r = fit_level_flight(d, quad, options=FitOptions(M=30.0, body_lift=True))
    plain = fit_level_flight(d, quad, options=FitOptions(M=30.0))
    assert r.extra["body_lift"]["selected"] == "without" and r.extra["body_lift"]["p_value"] > 0.5
    np.testing.assert_allclose(r.x, plain.x, rtol=1e-12)
    assert r.nfev > plain.nfev


# ---------------------------------------------------------------- cli/map.py

GRID = ["--rpm", "3000:9000:3", "--airspeed", "0:10:2", "--incidence-deg", "0:90:2", "--check-points", "0"]


def _quad_with(tmp_path, rotor, old, new):
    """The bundled quadrotor.toml with ``old`` replaced by ``new`` in rotor ``rotor``'s table (1-based)."""
    parts = (resources.files("propmap") / "data" / "examples" / "quadrotor.toml").read_text().split("[[rotors]]")
    assert old in parts[rotor]
    parts[rotor] = parts[rotor].replace(old, new, 1)
    p = tmp_path / f"veh{rotor}.toml"
    p.write_text("[[rotors]]".join(parts))
    return p


def test_map_refuses_a_vehicle_rotor_with_its_own_set_before_the_build_naming_it(tmp_path, capsys):
    """Mutants M6 (a rotor's own parameter set let through
    _check_vehicle_rotors, now _one_map_vehicle: refused only after the build, by
    the header's writer, in other words) and M7 (the rotor numbered from 0): rotor 3 of the quadrotor with the
    generic set of its own is refused before any map is built, as rotor 3, and nothing is written."""
    veh = _quad_with(tmp_path, 3, 'propeller = "apce_8x6"', 'propeller = "apce_8x6"\nparams = "generic"')
    code, _, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID, "--out", tmp_path / "m.h")
    assert one_line_error(code, err, "--vehicle: rotor 3 carries its own parameter set (generic), not the map's, "
                                     "calibrated:apce_8x6: a C header holds one map and one set (give --params, the "
                                     "set of every rotor)"), err
    assert not (tmp_path / "m.h").exists()


def test_map_names_a_vehicle_rotor_of_another_size_without_the_chord_note(tmp_path, capsys):
    """Mutant M8 (", another chord or blade angle"'s place taken by a note for a rotor of another size): rotor 4 of
    another propeller (APC 10x7, 0.254 m) is named with its size only."""
    veh = _quad_with(tmp_path, 4, 'propeller = "apce_8x6"', 'propeller = "apce_10x7"')
    code, _, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID, "--out", tmp_path / "m.h")
    assert one_line_error(code, err, "--vehicle: rotor 4 carries apce_10x7 (0.254 m, 2 blades), not the map's "
                                     "apce_8x6 (0.2032 m, 2 blades): a C header holds one map and one set"), err


def test_map_c_header_sidecar_records_the_given_c_name(tmp_path, capsys):
    """Mutant M12 (the sidecar's c_prefix the one --out makes, not --c-name's): the header's identifiers and its
    sidecar's c_prefix are --c-name's rotor_a."""
    out = tmp_path / "t.h"
    code, _, err = run(capsys, "map", "apce_8x6", "--format", "c", "--c-name", "rotor_a", *GRID, "--out", out)
    assert code == 0, err
    attrs = json.loads((tmp_path / "t.h.json").read_text())
    assert (attrs["c_prefix"], attrs["c_interpolation"], attrs["c_type"]) == ("rotor_a", "linear", "float")
    assert "rotor_a_" in out.read_text() and "pm_t_" not in out.read_text()


def test_map_takes_a_million_check_points(tmp_path, capsys, monkeypatch):
    """Mutant M1 (--check-points 1000000 refused, the bound's end left out): 10^6 is inside [0, 1000000]; the run
    goes on to the next refusal, a --plot-rpm off the map's rpm axis (raised once the axes are read, before any
    map is built)."""
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "map", "apce_8x6", "--out", "m.nc", *GRID[:-2], "--check-points", "1000000", "--plot",
                       "plots", "--plot-rpm", "1")
    assert one_line_error(code, err, "--plot-rpm: 1 is outside the map's rpm axis"), err
    assert not (tmp_path / "m.nc").exists()
