"""The hub's rolling moment as measured load data (since 2026-12-01): read from a load file beside a
torque, fitted and validated as the thrust, in-plane force and torque are, its sign checked.

Gill & D'Andrea's oblique-flow fits (Drones 3(4):77, 2019, Appendix A; data/published) give the
rolling moment with the other loads: fitted to thrust, in-plane force and torque alone, the
flapping carries the in-plane force with compliances of 2-50 rad/(N m) and leaves 0-37% of the
measured rolling moment (tests/test_gill2019_moments.py); with the rolling moment in the fit the
compliance comes out near the centrifugal cap of a cantilevered blade (0.4-1.5) and both moments
and forces follow (docs/identification.md, Load data at incidence).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import propmap as pm
from propmap.cases import gill2019_loads, multinomial_fit
from propmap.identify import DataError, FitOptions, LoadData, fit_loads, read_loads, sanity_check
from propmap.io.calibration import generic_without, population
from propmap.validation import holdout_loads, load_errors

AIR = pm.Air(rho=1.225)


@pytest.fixture(scope="module")
def tunnel():
    """The APC 10x7E's published oblique-flow loads with the rolling moment, at 5000 and 7000 rpm."""
    return pm.load_propeller("apce_10x7"), gill2019_loads("apce_10x7", (5000.0, 7000.0), air=AIR, rolling_moment=True)


def _fit(prop, data, quantities=None):
    return fit_loads(data, prop, base=generic_without(prop.name)[0], air=AIR, quantities=quantities,
                     options=FitOptions(population=population(without=prop.name)))


def _slopes(prop, params):
    f = multinomial_fit(prop, params, 6000 * math.pi / 30, air=AIR)
    return f["k4_mu_only"] / f["CT_static"], f["k9_mu_only"] / f["CT_static"]


def test_the_published_rolling_moment_as_load_data(tunnel):
    prop, data = tunnel
    c = pm.cases.gill2019_coefficients()["apce_10x7"]
    assert set(data.measured) == {"thrust", "drag", "torque", "rolling_moment"}
    R, mu = prop.radius, data.airspeed * np.sin(data.incidence) / (data.omega * prop.radius)
    q = 0.5 * 1.225 * math.pi * R**2 * (data.omega * R) ** 2
    lam = data.airspeed * np.cos(data.incidence) / (data.omega * R)
    np.testing.assert_allclose(data.measured["rolling_moment"], q * R * (c["k9"] * mu + c["k10"] * lam * mu),
                               rtol=1e-12)
    assert "rolling_moment" not in gill2019_loads("apce_10x7", (5000.0,)).measured  # (the default, as before)


def test_the_rolling_moment_pins_the_flapping_that_the_in_plane_force_alone_overdoes(tunnel):
    prop, data = tunnel
    without = _fit(prop, data, quantities=("thrust", "drag", "torque"))
    both = _fit(prop, data)
    assert without.extra["quantities"] == ["thrust", "drag", "torque"]
    assert both.extra["quantities"] == ["thrust", "drag", "torque", "rolling_moment"]
    assert any("the in-plane force and the rolling moment at incidence" in w for w in both.warnings)
    assert not any("a rolling-moment column pins it" in w for w in both.warnings)
    # fitted to the forces alone, the note says the compliance is an equivalent one that the rolling moment would pin
    assert any("without the hub's rolling moment it is an equivalent compliance" in w
               and w.endswith("a rolling-moment column pins it") for w in without.warnings)
    h0, m0 = _slopes(prop, without.params)
    h1, m1 = _slopes(prop, both.params)
    measured_h, measured_m = 0.034 / 0.029, 0.029 / 0.029  # (k4 and k9 over CT_static, published)
    # without the rolling moment: the in-plane force's slope matched, the rolling moment's a tenth of the tunnel's
    assert h0 / measured_h == pytest.approx(1.0, abs=0.05) and m0 / measured_m < 0.2
    # with it both follow, with a compliance a third of the other (regression values, 2026-12-01: 1.95 and 0.445
    # rad/(N m); slopes 1.02 and 0.10, 0.87 and 1.02 of the tunnel's)
    assert 0.8 < h1 / measured_h < 0.95 and 0.95 < m1 / measured_m < 1.1
    assert without.params.flap_compliance == pytest.approx(1.95, rel=0.05)
    assert both.params.flap_compliance == pytest.approx(0.445, rel=0.05)


def test_a_known_compliance_is_recovered_from_loads_with_the_rolling_moment():
    # loads made by the model itself (the calibrated APC 10x7E with a compliance of 0.8 rad/(N m)) are fitted back
    # from the generic set without the family: the compliance within 5%
    prop = pm.load_propeller("apce_10x7")
    truth = pm.default_params("apce_10x7").replace(flap_compliance=0.8)
    V, inc = np.meshgrid([4.0, 8.0, 12.0, 16.0], np.radians([0.0, 30.0, 60.0, 90.0]))
    V, inc = np.concatenate([[0.0], V.ravel()]), np.concatenate([[0.0], inc.ravel()])
    omega = np.repeat([5000 * math.pi / 30, 7000 * math.pi / 30], V.size)
    V, inc = np.tile(V, 2), np.tile(inc, 2)
    r = pm.rotor_loads(prop, truth, omega, V, inc, air=AIR)
    data = LoadData(omega, V, inc, {"thrust": r.thrust, "drag": r.drag, "torque": r.torque,
                                    "rolling_moment": r.rolling_moment}, np.array(["all"] * V.size))
    fit = _fit(prop, data)
    assert fit.params.flap_compliance == pytest.approx(0.8, rel=0.05)


def test_a_rolling_moment_of_the_other_sign_is_refused_and_one_in_the_wrong_unit_warned_of(tunnel):
    prop, data = tunnel
    flipped = LoadData(data.omega, data.airspeed, data.incidence,
                       {**data.measured, "rolling_moment": -data.measured["rolling_moment"]}, data.group)
    with pytest.raises(DataError, match="the measured rolling moment has the other sign than the model's at 63 of "
                                        "63 points at incidence: propmap's rolling moment is positive where the "
                                        "advancing"):
        sanity_check(flipped, prop)
    # not fitted (quantities without it): warned of, not refused
    said = sanity_check(flipped, prop, quantities=("thrust", "drag", "torque"))
    assert any(w.startswith("the measured rolling moment has the other sign") for w in said)
    milli = LoadData(data.omega, data.airspeed, data.incidence,
                     {**data.measured, "rolling_moment": 1e3 * data.measured["rolling_moment"]}, data.group)
    said = sanity_check(milli, prop)
    assert any("the measured rolling moment is" in w and "times the model's in the median" in w
               and "is its unit given?" in w for w in said)
    assert not any("rolling moment" in w for w in sanity_check(data, prop))


def test_a_rolling_moment_without_an_in_plane_airspeed_is_not_fitted():
    prop = pm.load_propeller("apce_10x7")
    w = np.linspace(400.0, 800.0, 8)
    r = pm.rotor_loads(prop, pm.default_params("apce_10x7"), w, 0.0, 0.0, air=AIR)
    axial = LoadData(w, np.zeros(8), np.zeros(8), {"thrust": r.thrust, "torque": r.torque,
                                                   "rolling_moment": np.full(8, 1e-4)}, np.array(["s"] * 8))
    fit = fit_loads(axial, prop, air=AIR)
    assert fit.extra["quantities"] == ["thrust", "torque"]
    assert any(n.startswith("the measured rolling moment is not fitted: no point has an in-plane airspeed")
               for n in fit.warnings)
    with pytest.raises(ValueError, match=r"the rolling moment \(rolling_moment\) cannot be fitted: no point has an "
                                         "in-plane airspeed above 0.3 m/s"):
        fit_loads(axial, prop, air=AIR, quantities=("rolling_moment",))


def test_load_errors_and_holdout_loads_score_the_rolling_moment(tunnel):
    prop, data = tunnel
    p = pm.default_params("apce_10x7")
    e = load_errors(data, prop, p, air=AIR)
    assert e["reference"]["rolling_moment"][0] == "mean static CT / 2 (the static thrust times R)"
    assert e["reference"]["rolling_moment"][1] == pytest.approx(e["reference"]["thrust"][1] / 2, rel=1e-12)
    assert e["overall"]["rolling_moment"]["n"] == int(data.inplane.sum())
    # independently: the rms of (model - measured) / (rho n^2 D^5) over the in-plane points, of CT_static / 2
    r = pm.rotor_loads(prop, p, data.omega, data.airspeed, data.incidence, air=AIR)
    n, D = data.omega / (2 * math.pi), prop.diameter
    ip = data.inplane
    coef = (r.rolling_moment - data.measured["rolling_moment"])[ip] / (1.225 * n[ip] ** 2 * D**5)
    assert e["overall"]["rolling_moment"]["rms"] == pytest.approx(
        float(np.sqrt(np.mean(coef**2))) / e["reference"]["rolling_moment"][1], rel=1e-9)
    # the calibrated set's rigid blades roll more than the tunnel's: the bias is positive
    assert e["overall"]["rolling_moment"]["bias"] > 0
    fold = [np.round(np.degrees(data.incidence)) != 45]
    held = holdout_loads(data, prop, generic_without("apce_10x7")[0], fold, population=population(without="apce_10x7"),
                         air=AIR)
    assert held["rms_rolling_moment"] is not None and held["rms_rolling_moment"] < 0.05
    # the forces alone fitted (quantities=), the rolling moment still scored: its held-out error several times larger
    forces = holdout_loads(data, prop, generic_without("apce_10x7")[0], fold,
                           population=population(without="apce_10x7"), air=AIR, quantities=("thrust", "drag", "torque"))
    assert forces["rms_rolling_moment"] > 3 * held["rms_rolling_moment"]
    assert forces["flap_compliance"][0] > 2 * held["flap_compliance"][0]
    assert "rms_rolling_moment" not in holdout_loads(
        gill2019_loads("apce_10x7", (5000.0, 7000.0), air=AIR), prop, generic_without("apce_10x7")[0],
        [np.round(np.degrees(data.incidence)) != 45], population=population(without="apce_10x7"), air=AIR)


def test_the_command_line_reads_fits_and_validates_a_rolling_moment_column(tmp_path, tunnel, capsys):
    from propmap.cli.main import main

    prop, data = tunnel
    f = tmp_path / "tunnel.csv"
    rows = ["rpm,airspeed (m/s),incidence_deg,thrust (N),normal force (N),torque (N m),rolling moment (N mm),group"]
    for i in range(data.n):
        rows.append(f"{data.omega[i] * 30 / math.pi:.1f},{data.airspeed[i]:.5f},{math.degrees(data.incidence[i]):.1f},"
                    f"{data.measured['thrust'][i]:.6f},{data.measured['drag'][i]:.6f},{data.measured['torque'][i]:.7f},"
                    f"{1e3 * data.measured['rolling_moment'][i]:.5f},{data.group[i]}")
    f.write_text("\n".join(rows) + "\n")
    read = read_loads(f)
    np.testing.assert_allclose(read.measured["rolling_moment"], data.measured["rolling_moment"], atol=1e-8)
    out = tmp_path / "p.toml"
    assert main(["fit", "loads", str(f), "--prop", "apce_10x7", "--out", str(out), "--holdout", "inc45"]) == 0
    text = capsys.readouterr().out
    assert "rolling_moment_rmse" in text
    assert pm.read_params(out).flap_compliance == pytest.approx(0.45, abs=0.05)
    assert main(["validate", str(f), "--prop", "apce_10x7", "--params", str(out)]) == 0
    text = capsys.readouterr().out
    assert "rolling_moment: mean static CT / 2 (the static thrust times R)" in text
    assert "  rolling_moment rms" in text and "rolling_moment " in text.split("rms errors in SI: ")[1]
    assert main(["fit", "loads", str(f), "--prop", "apce_10x7", "--out", str(tmp_path / "q.toml"),
                 "--quantities", "thrust,torque,rolling_moment"]) == 0
