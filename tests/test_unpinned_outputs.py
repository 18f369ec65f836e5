"""Outputs no test pinned, found by a mutation audit (2026-11-27: 133 mutants of simexport,
core/hover.py, io/uncertainty.py, identify/flight_scores.py, identify/engine.py and
continuation.py, cli/validate.py; each test below fails with the mutant it was written for).
Values marked "regression" were measured on the code of that day; the others are exact or
physical (by hand, a bound, a published quantile)."""

from __future__ import annotations

import json
import math
import re
import runpy
import warnings
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.identify.flight import FlightSamples, baseline_force, flight_errors, speed_band_errors
from propmap.simexport import Envelope, export_sim, predict, write_export
from propmap.simexport.files import error_lines
from propmap.vehicle import Rotor, Vehicle


ENV = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 12.0), incidence_deg=(0.0, 120.0))


@pytest.fixture(scope="module")
def model():
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    return prop, params, params.air


def _ex(model, target, env=ENV, n=600, seed=3, **kw):
    prop, params, air = model
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return export_sim(target, prop, params, air=air, envelope=env, n_points=n, seed=seed, **kw)


# ---- simexport
@pytest.mark.parametrize(
    "target, load", [("rotorpy", "drag"), ("multinomial", "torque"), ("multinomial", "rolling_moment")]
)
def test_sim_fit_close_to_full_model(model, target, load):
    assert _ex(model, target).errors[load]["rms"] < 0.05  # measured 0.0239 / 0.0184 / 0.0090


def test_sim_determined_threshold(model):
    res = _ex(model, "rotorpy", env=Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 0.02)), n=200, seed=0)
    assert set(res.fixed) == {"k_h", "k_z", "k_d"}  # lambda, mu peak 4.2e-4: between 1e-4 and 1e-3


def test_sim_held_message_value(model):
    prop, params, air = model
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = export_sim("rotorpy", prop, params.replace(inplane_induction=False), air=air, n_points=600)
    v = float(re.search(r"the unbounded fit gives (\S+)\)", res.held["k_h"]).group(1))
    assert v == pytest.approx(-1.63e-4, rel=0.01)  # regression value


def test_sim_text_numbers(model, tmp_path):
    res = _ex(
        model,
        "gz-sim",
        env=Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 15.0), incidence_deg=(0.0, 120.0), hover_rpm=8000.0),
        n=100,
        seed=0,
        params_label=model[1].label,
    )
    e, t = res.errors, res.meta["model_uncertainty"]["edgewise_trend"]
    line = error_lines(res, "#")[0]
    assert (
        f"static thrust and torque within {e['static']['thrust_max']:.2%} and {e['static']['torque_max']:.2%}" in line
    )
    text = write_export(res, tmp_path / "m.sdf")[0].read_text()
    assert f"{t['this_set']:+.1%} with this set, {t['generic']:+.1%} with the generic set" in text
    assert text.count(repr(-res.coefficients["rollingMomentCoefficient"])) == 2


def test_sim_label_newline_stays_in_comment(model, tmp_path):
    res = _ex(
        model,
        "rotorpy",
        env=Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 10.0), incidence_deg=(0.0, 90.0)),
        n=60,
        seed=0,
        params_label="x\nprint('INJECTED')  # -->",
    )
    text = write_export(res, tmp_path / "c.py")[0].read_text()
    assert not any(l.startswith("print(") for l in text.splitlines())


def test_sim_quad_params_inertia_and_tau(model, tmp_path):
    prop = model[0]
    d = 0.15 / math.sqrt(2)
    pos = [(d, d, 0.0), (d, -d, 0.0), (-d, -d, 0.0), (-d, d, 0.0)]
    rotors = tuple(Rotor(np.array(p), np.array([0.0, 0.0, 1.0]), s, prop) for p, s in zip(pos, (1, -1, 1, -1)))
    I = np.array([[0.01, 0.001, 0.002], [0.001, 0.011, 0.003], [0.002, 0.003, 0.02]])
    veh = Vehicle(mass=1.2, rotors=rotors, inertia=I, motor_time_constant=0.0, name="X")
    res = _ex(model, "rotorpy", n=100, seed=0)
    path = write_export(res, tmp_path / "c.py", vehicle=veh)[0]
    q = runpy.run_path(str(path))["quad_params"]
    assert (q["Ixx"], q["Iyy"], q["Izz"], q["Ixy"], q["Iyz"], q["Ixz"]) == (0.01, 0.011, 0.02, 0.001, 0.003, 0.002)
    assert q["tau_m"] == 0.005 and "NOT in the vehicle file" in path.read_text()


def test_sim_gazebo_classic_torque_does_not_fade(model):
    c = _ex(model, "gazebo-classic", n=100, seed=0).coefficients
    assert float(predict("gazebo-classic", c, 700.0, 20.0, 0.0)[2]) == pytest.approx(
        c["momentConstant"] * c["motorConstant"] * 700.0**2, rel=1e-12
    )


# ---- hover
def test_hover_edges():
    from propmap.core.hover import HoverModel

    with pytest.raises(ValueError, match="rho must be a positive"):
        HoverModel(1e-5, 1e-7, rho=0.0)
    with pytest.raises(ValueError, match="CT and CP must be within"):
        HoverModel.from_coefficients(0.1, 2000.0, 0.2)
    h = HoverModel.from_coefficients(0.11, 0.074, 0.2032)
    assert h.CT(0.4064) == pytest.approx(0.11 / 16, rel=1e-12)
    a = pm.Air.isa(3000.0)
    h3 = HoverModel.from_coefficients(0.11, 0.074, 0.2032, air=a)
    assert h3.rho == a.rho and h3.CT() == pytest.approx(0.11, rel=1e-12)


# ---- uncertainty
def test_uncertainty_texts(tmp_path):
    from propmap.io.uncertainty import model_uncertainty

    u = model_uncertainty("calibrated:apce_8x6")
    assert "rms CT error 2.5 / 4.9 / 11.0% of static CT" in u["axial"]
    assert f"in-sample rms CT error {100 * u['in_sample_rms_ct']:.1f}%" in u["axial"]  # 2.7%
    assert model_uncertainty("fit.TOML")["axial"].startswith("a parameter file")


# ---- flight scores
VEH = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"


def _S(v, w=None, om=None, moment=None):
    n = len(v)
    return FlightSamples(
        log_names=("x",),
        log_index=np.zeros(n, int),
        t=np.arange(n * 1.0),
        velocity=np.asarray(v, float),
        angular_velocity=np.zeros((n, 3)) if w is None else np.asarray(w, float),
        rotor_omega=np.full((n, 4), 1000.0) if om is None else np.asarray(om, float),
        rotor_acceleration=np.zeros((n, 4)),
        force=np.zeros((n, 3)),
        moment=moment,
        reference_force=None,
        reference_moment=None,
        rate_hz=1.0,
    )


def test_speed_bands():
    sp = [0.0, 2.5, 3.0, 5.9, 6.0, 9.0, 12.0]
    rows = speed_band_errors(np.array([[k + 1.0, 0, 0] for k in range(7)]), _S([[x, 0, 0] for x in sp]))
    assert [r["band_m_s"] for r in rows] == [[0.0, 3.0], [3.0, 6.0], [6.0, 9.0], [9.0, None]]
    assert [r["n"] for r in rows] == [2, 2, 1, 2]
    assert [r["F"] for r in rows] == pytest.approx(
        [math.sqrt(5 / 6), math.sqrt(25 / 6), math.sqrt(25 / 3), math.sqrt(85 / 6)]
    )


def test_flight_errors_axes_and_moments():
    m = np.array([[1.0, 2.0, 3.0]] * 2)
    e = flight_errors(m, _S([[0, 0, 0]] * 2, moment=m), np.zeros((2, 3)))
    assert (e["Fx"], e["Fy"], e["Fz"], e["Mx"], e["My"], e["Mz"]) == (1.0, 2.0, 3.0, 1.0, 2.0, 3.0)
    assert e["M_zero"] == pytest.approx(math.sqrt(14 / 3))


def test_baseline_columns_by_hand():
    veh = pm.read_vehicle(VEH)
    from propmap.vehicle import rotor_geometry

    arms = rotor_geometry(veh)[0]
    om = np.array([[1000.0, 1100.0, 1200.0, 1300.0]])

    def F(v, w, coef):
        return baseline_force({"terms": ["thrust", "drag", "kz"], "coefficients": coef}, _S([v], [w], om), veh)[0]

    np.testing.assert_allclose(F([0, 0, -2.0], [0, 0, 0], [0, 0, 1.0]), [0, 0, 9200.0])  # descent raises thrust
    np.testing.assert_allclose(
        F([3.0, 0, 2.0], [0, 0, 0], [0, 1.0, 0]), [-13800.0, 0, 0]
    )  # drag in-plane only, opposing
    np.testing.assert_allclose(
        F([0, 0, 0], [0, 0, 1.0], [0, 1.0, 0]),
        -sum(om[0, k] * np.cross([0, 0, 1.0], arms[k]) for k in range(4)),
        atol=1e-9,
    )  # (40, -15.6, 0)


# ---- engine / continuation
@pytest.fixture(scope="module")
def static_fit():
    from propmap.identify import fit_loads, loads_from_catalogue

    prop = pm.load_propeller("apce_8x6")
    data = loads_from_catalogue(pm.catalogue()["apce_8x6"], prop.diameter)
    st = data.subset(data.airspeed == 0)
    return st, prop, fit_loads(st, prop)


def test_directions_intervals(static_fit):
    from scipy import stats
    from propmap.identify import FitOptions
    from propmap.identify.engine import _bounds

    st, prop, r = static_fit
    ci, se = r.identifiability.ci95, r.identifiability.std_error
    lb, ub = _bounds(r.names, FitOptions())
    assert np.all(ci[:, 0] >= lb) and np.all(ci[:, 1] <= ub)
    assert ci[r.names.index("cd_min"), 0] == lb[r.names.index("cd_min")]  # linearised: -0.0087
    k = r.names.index("cl_alpha")
    assert (ci[k, 1] - ci[k, 0]) / (2 * se[k]) == pytest.approx(
        stats.t.ppf(0.975, r.residuals.size - 3), rel=1e-9
    )  # 2.04523


def test_directions_weak_warning(static_fit):
    from propmap.identify import FitOptions, fit_loads

    st, prop, _ = static_fit
    r5 = fit_loads(st, prop, options=FitOptions(directions=5))
    assert r5.extra["directions"]["std_error_data_only"][4] == pytest.approx(1.59, rel=0.02)  # regression value
    assert any(w.startswith("direction_5 is determined less well") for w in r5.identifiability.warnings)


def test_limit_warning_first_with_a_bound():
    from tests.test_identify_cambered import TRUE, synthetic
    from propmap.identify import FitOptions, fit_loads

    prop = pm.load_propeller("apce_8x6")
    d = synthetic(prop, TRUE, noise=0.005, seed=4)
    s = fit_loads(d, prop, options=FitOptions(prior=False, max_nfev=2, bounds={"cd_min": (0.03, 0.2)}))
    assert s.at_bound == ("cd_min",) and s.warnings[0].startswith("the fit stopped at its evaluation limit (2)")


def test_multistart_polishes_the_two_best_screened():
    from propmap.identify import FitOptions, fit_level_flight, simulate_level_flight, read_vehicle

    quad = read_vehicle(str(resources.files("propmap") / "data" / "examples" / "quadrotor.toml"))
    V = np.linspace(0, 14, 20)
    low = simulate_level_flight(quad, pm.preset("gill2017-apc").replace(M=30.0), V, -1.0 * V)
    g = fit_level_flight(low, quad, options=FitOptions(M=30.0, multistart=4))
    screen = sorted((e for e in g.starts if e["stage"] == "screen"), key=lambda e: e["cost"])
    polish = [e for e in g.starts if e["stage"] == "polish"]
    np.testing.assert_array_equal(polish[0]["x0"], screen[0]["x"])
    np.testing.assert_array_equal(polish[1]["x0"], screen[1]["x"])


def test_continuation_report_values():
    from propmap.identify import fit_level_flight, simulate_level_flight, read_vehicle

    veh = read_vehicle(str(resources.files("propmap") / "data/examples/quadrotor.toml"))
    V = np.linspace(0, 14, 20)
    r = fit_level_flight(simulate_level_flight(veh, pm.preset("gill2017-apc"), V, -2.5 * V), veh)
    c = r.extra["M_continuation"]
    assert c["rms_residual_first"] == pytest.approx(0.005587, rel=1e-2)  # regression value (rms, not mean square)
    assert (
        c["x_first"][1] == pytest.approx(1.1664, rel=1e-3) and abs(c["x_first"][1] - r.x[1]) > 0.5
    )  # M = 30 optimum, not the final


# ---- cli validate


def test_validate_table_matches_json(capsys):
    assert main(["validate", "apce_8x6", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert main(["validate", "apce_8x6"]) == 0
    out = capsys.readouterr().out

    def nums(prefix):
        row = next(l for l in out.splitlines() if l.startswith(prefix))
        return [float(x) for x in row.replace("|", " ").split()[-4:]]

    s = d["sweeps"][0]
    assert nums("static 2797rd") == pytest.approx(
        [s["model"]["ct_rmse"], s["model"]["cp_rmse"], s["hover_model"]["ct_rmse"], s["hover_model"]["cp_rmse"]],
        abs=5e-5,
    )
    assert nums("all points") == pytest.approx(
        [d["model"]["ct_rmse"], d["model"]["cp_rmse"], d["hover_model"]["ct_rmse"], d["hover_model"]["cp_rmse"]],
        abs=5e-5,
    )
    assert "`propmap validate --all` gives held-out errors" in out


def test_validate_generic_says_in_sample_and_bias(capsys):
    assert main(["validate", "apce_8x6", "--params", "generic"]) == 0
    out = capsys.readouterr().out
    assert "model bias: CT -0.0061, CP -0.0106." in out  # regression values (the calibration of 2026-11-29)
    assert "generic was fitted to these runs (with the whole catalogue's): in-sample" in out


def test_validate_files_percent_units_and_convergence(tmp_path, capsys):
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    rows = ["rpm,airspeed,thrust,torque,group"]
    for rpm in (5000.0, 6000.0, 7000.0):
        r = pm.rotor_loads(prop, params, rpm * math.pi / 30, 0.0, 0.0)
        rows.append(f"{rpm},0.0,{float(r.thrust) * 1.1!r},{float(r.torque) * 0.95!r},g")
    f = tmp_path / "t.csv"
    f.write_text("\n".join(rows) + "\n")
    assert main(["validate", str(f), "--prop", "apce_8x6"]) == 0
    out = capsys.readouterr().out
    assert "9.09%    -9.09%     9.22%     3        5.26%    +5.26%     5.27%     3" in out
    assert "torque 0.002584 N m" in out and "did not converge" not in out
