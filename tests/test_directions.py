"""Static fits along the data's leading directions against the population prior
(identify/directions.py): the directions' algebra, the fit on real UIUC static runs (Brandt &
Selig, UIUC Propeller Data Site vol. 1; Deters, Ananda & Selig, vol. 2), its report and the
CLI."""

import json
import math

import numpy as np
import pytest
from click.testing import CliRunner

import propmap as pm
from propmap.cli.main import cli
from propmap.identify import FitOptions, fit_loads, loads_from_catalogue
from propmap.identify.directions import STATIC_DIRECTIONS, leading_directions


def _static(name):
    prop = pm.load_propeller(name)
    data = loads_from_catalogue(pm.catalogue()[name], prop.diameter)
    return data.subset(data.airspeed == 0), prop


def _static_csv(path):
    """apce_8x6's static run (UIUC vol. 1) as a thrust-stand CSV (rpm, N, N m)."""
    st, _ = _static("apce_8x6")
    rows = ["rpm,thrust,torque"] + [f"{o * 30 / math.pi:.3f},{t:.6g},{q:.6g}" for o, t, q in
                                    zip(st.omega, st.measured["thrust"], st.measured["torque"])]
    path.write_text("\n".join(rows) + "\n")
    return path


def test_leading_directions_are_the_data_information_eigenvectors_in_the_prior_metric():
    """B^T Sigma^-1 B = I (one prior standard deviation per unit), the eigenvalues fall, B's first
    column maximises |J b| over b^T Sigma^-1 b = 1, and a direction the data do not see comes last."""
    rng = np.random.default_rng(0)
    p = 5
    A = rng.standard_normal((p, p))
    sigma = A @ A.T + p * np.eye(p)
    L = np.linalg.cholesky(sigma)
    J = rng.standard_normal((20, p))
    J[:, 4] = 0.0  # the data do not see the 5th parameter
    B, lam = leading_directions(J, L, 0.5, 3)
    assert B.shape == (p, 3) and lam.shape == (p,)
    np.testing.assert_allclose(B.T @ np.linalg.inv(sigma) @ B, np.eye(3), atol=1e-10)
    assert np.all(np.diff(lam) <= 1e-12)
    best = np.linalg.norm(J @ B[:, 0])
    for _ in range(200):  # no unit (prior-metric) direction sees more of the data
        b = L @ rng.standard_normal(p)
        b /= math.sqrt(b @ np.linalg.solve(sigma, b))
        assert np.linalg.norm(J @ b) <= best * (1 + 1e-12)
    np.testing.assert_allclose(lam[0], (best / 0.5) ** 2, rtol=1e-10)
    # a zero-information direction exists (the 5th parameter's): the smallest eigenvalue is 0
    assert abs(lam[-1]) < 1e-10 * lam[0]
    with pytest.raises(ValueError, match=r"k must be in \[1, 5\]"):
        leading_directions(J, L, 0.5, 0)
    with pytest.raises(ValueError, match="must have shape"):
        leading_directions(J[:, :4], L, 0.5, 2)


def test_static_fit_frees_three_directions_with_finite_intervals():
    """UIUC apce_8x6's static run: 3 free directions (issue 18: at most 3), the data determining
    each one (finite data-only std errors, fewer than the 8 parameters' 3.8 effective), the
    parameters the base set moved along them, no warning; FitOptions(directions=0) fits the
    8 under the prior as before."""
    st, prop = _static("apce_8x6")
    r = fit_loads(st, prop)
    d = r.extra["directions"]
    assert d["count"] == STATIC_DIRECTIONS == 3
    assert d["names"] == [n + "_deg" if n in ("alpha_L0", "alpha_L0_re") else n for n in r.names]
    to_si = np.array([math.radians(1.0) if n in d["units"] else 1.0 for n in d["names"]])  # (angles in degrees)
    base = np.array(d["base"]) * to_si
    B = np.array(d["loadings"]).T * to_si[:, None]
    np.testing.assert_allclose(r.x, base + B @ np.array(d["coefficients"]), rtol=1e-12, atol=1e-15)
    idf = r.identifiability
    assert 2.5 < idf.effective_parameters <= 3.0
    assert np.all(np.isfinite(idf.std_error)) and idf.std_error_data is None  # the data determine directions
    assert np.all(np.array(d["std_error_data_only"]) < 0.2)  # in prior standard deviations: well determined
    # the parameters' error keeps the population's spread along the held directions: within it, above 0
    pop_sd = np.array(d["prior_std"]) / np.array([math.degrees(1.0) if n in d["units"] else 1.0 for n in d["names"]])
    assert np.all(idf.std_error <= pop_sd * (1 + 1e-9)) and np.all(idf.std_error > 0.05 * pop_sd)
    assert not idf.warnings and not r.warnings
    text = r.report_text()
    assert "free: 3 directions of the 8 parameters" in text and "direction_3" in text
    assert "the data determine 3.0 of the 3 free directions" in text
    json.dumps(r.to_dict())  # JSON-ready (angles in degrees, as "fitted")
    assert r.to_dict()["directions"]["units"] == {"alpha_L0_deg": "deg", "alpha_L0_re_deg": "deg"}
    diff = fit_loads(st, prop, options=FitOptions(jacobian="differences"))  # the same fit, differencing the solver
    np.testing.assert_allclose(diff.x, r.x, rtol=1e-5, atol=1e-8)
    # in-sample: the static thrust and torque within 2% rms (the measured scatter is about 1%)
    assert float(np.sqrt(np.mean(r.residuals**2))) < 0.02
    full = fit_loads(st, prop, options=FitOptions(directions=0))
    assert "directions" not in full.extra and full.identifiability.std_error_data is not None
    assert 3.5 < full.identifiability.effective_parameters < 4.2  # the 8 under the prior, as before
    one = fit_loads(st, prop, options=FitOptions(directions=1))
    assert one.extra["directions"]["count"] == 1 and one.cost > r.cost
    for bad in (-1, True, 1.5):
        with pytest.raises(ValueError, match="directions must be None or an integer >= 0"):
            FitOptions(directions=bad)


def test_static_direction_fit_leaving_the_range_falls_back_to_the_full_fit():
    """MicroInvent mi_4x2.7 (UIUC vol. 2, 4 in, chord Reynolds numbers near 2e4): the 3
    directions' optimum puts cl_max beyond its bound, so the fit frees the 8 under the prior
    instead and says so."""
    st, prop = _static("mi_4x2.7")
    r = fit_loads(st, prop)
    assert "directions" not in r.extra
    assert any("left the allowed range (cl_max " in w and "all 8 parameters fitted under the prior instead" in w
               for w in r.warnings)
    assert "free directions" not in r.report_text() and "WARNING: the optimum along" in r.report_text()
    json.dumps(r.to_dict())
    # a population prior that leaves a fitted name out: no fit along directions (the MAP fit, as before)
    from propmap.io.calibration import population

    pop = population()
    keep = [i for i, n in enumerate(pop["names"]) if n != "re_exp"]
    part = dict(pop, names=[pop["names"][i] for i in keep],
                covariance=np.asarray(pop["covariance"])[np.ix_(keep, keep)].tolist())
    st8, prop8 = _static("apce_8x6")
    r = fit_loads(st8, prop8, options=FitOptions(population=part))
    assert "directions" not in r.extra and "prior" in r.extra
    r = fit_loads(st8, prop8, options=FitOptions(directions=3, names=("alpha_L0", "cd_min")))
    assert "directions" not in r.extra and any("directions ignored" in w for w in r.warnings)


def test_cli_static_fit_reports_directions(tmp_path):
    """`propmap fit loads` on a static CSV: the report names the 3 free directions; --directions 0
    the full fit; --directions N on rich data frees N; with --fit-params it is refused (exit 2,
    since 2026-11-26: it was ignored with a note); out of range exits 2."""
    csv = _static_csv(tmp_path / "static.csv")
    run = CliRunner().invoke
    r = run(cli, ["fit", "loads", str(csv), "--prop", "apce_8x6", "--out", str(tmp_path / "p.toml")])
    assert r.exit_code == 0, r.output
    assert "free: 3 directions" in r.output
    report = json.loads((tmp_path / "p.report.json").read_text())
    assert report["directions"]["count"] == 3 and len(report["directions"]["loadings"]) == 3
    r = run(cli, ["fit", "loads", str(csv), "--prop", "apce_8x6", "--directions", "0",
                  "--out", str(tmp_path / "q.toml")])
    assert r.exit_code == 0 and "directions" not in json.loads((tmp_path / "q.report.json").read_text())
    r = run(cli, ["fit", "loads", "apce_8x6", "--directions", "2", "--out", str(tmp_path / "s.toml")])
    assert r.exit_code == 0 and "free: 2 directions" in r.output  # (all of UIUC's data: given, it applies)
    r = run(cli, ["fit", "loads", str(csv), "--prop", "apce_8x6", "--directions", "2", "--fit-params",
                  "alpha_L0,cd_min", "--out", str(tmp_path / "f.toml")])
    assert r.exit_code == 2 and "--fit-params chooses the parameters instead" in r.output
    r = run(cli, ["fit", "loads", str(csv), "--prop", "apce_8x6", "--directions", "9",
                  "--out", str(tmp_path / "x.toml")])
    assert r.exit_code == 2 and "--directions" in r.output


def test_one_sweep_rate_frees_the_directions_the_data_know_ten_times_better():
    """UIUC apce_8x6, the static run and the lowest-rpm sweep (one rotation rate): the directions
    with eigenvalue >= DATA_OVER_PRIOR are freed; with two sweep rates every parameter is fitted
    under the prior."""
    from propmap.identify.directions import DATA_OVER_PRIOR
    from propmap.validation import rpm_groups

    prop = pm.load_propeller("apce_8x6")
    data = loads_from_catalogue(pm.catalogue()["apce_8x6"], prop.diameter)
    groups = rpm_groups(data)
    one = data.subset((data.airspeed == 0) | np.isin(data.group, groups[0]))
    r = fit_loads(one, prop)
    d = r.extra["directions"]
    lam = np.array(d["eigenvalues"])
    assert 3 <= d["count"] < 8  # more than a static run determines, fewer than all
    assert lam[d["count"] - 1] >= DATA_OVER_PRIOR > lam[d["count"]]
    two = data.subset((data.airspeed == 0) | np.isin(data.group, groups[0] + groups[1]))
    assert "directions" not in fit_loads(two, prop).extra


def test_a_fitted_files_coverage_is_checked_by_every_later_use(tmp_path):
    """Issue 18: a file fitted to a static run records its data's coverage (J 0, axial, its rpm
    span); `loads`, `map` and `export-sim` each warn, one line per risk, where they go beyond it,
    and say nothing inside it."""
    csv = _static_csv(tmp_path / "static.csv")
    run = CliRunner().invoke  # (its output holds stderr's warnings too)
    p = tmp_path / "p.toml"
    assert run(cli, ["fit", "loads", str(csv), "--prop", "apce_8x6", "--out", str(p)]).exit_code == 0
    inside = run(cli, ["loads", "apce_8x6", "--params", str(p), "--rpm", "5000"])
    assert inside.exit_code == 0 and "the data behind" not in inside.output and "axial data only" not in inside.output
    outside = run(cli, ["loads", "apce_8x6", "--params", str(p), "--rpm", "5000", "--airspeed", "10",
                        "--incidence-deg", "60"])
    assert outside.exit_code == 0
    assert "advance ratio up to" in outside.output and "fitted to axial data only" in outside.output
    m = run(cli, ["map", "apce_8x6", "--params", str(p), "--rpm", "3000:9000:4", "--airspeed", "0:10:3",
                  "--incidence-deg", "0:90:3", "--out", str(tmp_path / "m.nc")])
    assert m.exit_code == 0, m.output
    assert "3000-9000 rpm: the data behind" in m.output and "fitted to axial data only" in m.output
    e = run(cli, ["export-sim", "apce_8x6", "--target", "rotorpy", "--params", str(p), "--envelope",
                  "rpm=3000:6000,airspeed=0:5,incidence_deg=0:30", "--points", "200",
                  "--out", str(tmp_path / "x.py")])
    assert e.exit_code == 0, e.output
    assert "advance ratio up to" in e.output and "axial data only" in e.output and "rpm: the data" not in e.output
    t = run(cli, ["trim", "apce_8x6", "--thrust", "3", "--rpm", "8000", "--airspeed", "10", "--incidence-deg", "60",
                  "--params", str(p)])
    assert t.exit_code == 0 and "8000 rpm: the data behind" in t.output and "axial data only" in t.output


def test_a_calibrated_sets_rpm_span_is_checked_too():
    """The shipped calibrated sets know their propeller's UIUC rates (apce_8x6: static runs and
    sweeps 2534-6713 rpm, UIUC vol. 1, Brandt & Selig 2011): a rate beyond them is said, one
    inside is not (the warning only fired for fitted files before)."""
    run = CliRunner().invoke
    out = run(cli, ["loads", "apce_8x6", "--rpm", "20000"])
    assert out.exit_code == 0 and "20000 rpm: the data behind calibrated:apce_8x6 span 2534-6713 rpm" in out.output
    inside = run(cli, ["loads", "apce_8x6", "--rpm", "5000"])
    assert inside.exit_code == 0 and "rpm: the data behind" not in inside.output


def test_wrench_checks_the_coverage_once_per_propeller(tmp_path, shared_data):
    """`propmap wrench` on a NeuroBEM log (Bauersfeld et al. 2021) with a static stand fit: the log's
    incidences and rpm lie beyond the fit's data, said once (the quadrotor's four rotors share
    one propeller)."""
    from pathlib import Path

    p = tmp_path / "p.toml"
    run = CliRunner().invoke
    assert run(cli, ["fit", "loads", str(_static_csv(tmp_path / "s.csv")), "--prop", "apce_8x6",
                     "--out", str(p)]).exit_code == 0
    log = sorted((shared_data / "neurobem_flights").glob("*.mat"))[0]
    veh = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    w = run(cli, ["wrench", str(log), "--vehicle", str(veh), "--params", str(p), "--out", str(tmp_path / "w.csv")])
    assert w.exit_code == 0, w.output
    assert w.output.count("fitted to axial data only") == 1 and w.output.count("rpm: the data behind") == 1


def test_coverage_messages_for_one_rate_and_a_range(capsys, tmp_path):
    """A fitted file's rpm span: a range partly outside it warns once with the range; one rate
    inside, or a range inside, says nothing; the extremes take the advancing tip's speed."""
    from propmap.cli._coverage import coverage_messages, envelope_extremes
    from propmap.io.params_file import set_coverage

    prop = pm.load_propeller("apce_8x6")
    label = str(tmp_path / "p.toml")
    fitted = CliRunner().invoke(cli, ["fit", "loads", str(_static_csv(tmp_path / "s.csv")), "--prop", "apce_8x6",
                                      "--out", label])
    assert fitted.exit_code == 0
    capsys.readouterr()

    cov = set_coverage(label)
    lo, hi = cov["rpm_min"], cov["rpm_max"]
    coverage_messages(prop, label, pm.Air(), 50.0, 0.0, 0.0, rpm=(lo + 1, hi - 1))
    coverage_messages(prop, label, pm.Air(), 50.0, 0.0, 0.0, rpm=0.5 * (lo + hi))
    assert capsys.readouterr().err == ""
    coverage_messages(prop, label, pm.Air(), 50.0, 0.0, 0.0, rpm=(lo / 2, hi - 1))
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{lo / 2:.0f}-{hi - 1:.0f} rpm" in err
    tip, J, inc = envelope_extremes(prop, np.array([10000.0]), np.array([0.0, 20.0])[:, None],
                                    np.array([0.0, 90.0, 180.0]))
    om_r = 10000 * math.pi / 30 * prop.radius
    assert tip == pytest.approx(om_r + 20.0) and inc == 180.0
    assert J == pytest.approx(20.0 / (10000 / 60 * prop.diameter))
    # the incidence of points whose airspeed is below 1% of the tip speed means nothing (a hovering vehicle's drift:
    # every real flight log warned of its 179.97 deg, 2026-11-27); 0.5 m/s at 10000 rpm is 0.6% of 106 m/s
    inc = envelope_extremes(prop, np.array([10000.0]), np.array([0.5, 20.0]), np.array([180.0, 30.0]))[2]
    assert inc == 30.0
    assert envelope_extremes(prop, np.array([10000.0]), np.array([1.5, 20.0]), np.array([180.0, 30.0]))[2] == 180.0


def test_a_few_thrust_only_steps_are_enough_for_the_directions():
    """A Series 1520 stand measures no torque: 6 static thrust-only steps (UIUC apce_8x6, every
    third point) identify the 3 directions, where all 8 parameters under the prior need more than
    8 residuals; 3 points are refused, naming the directions."""
    st, prop = _static("apce_8x6")
    six = st.subset(np.arange(st.n) % 3 == 0)
    assert six.n == 6
    r = fit_loads(six, prop, quantities=("thrust",))
    assert r.extra["directions"]["count"] == 3 and 1.0 < r.identifiability.effective_parameters <= 3.0
    with pytest.raises(ValueError, match="6 points cannot identify 8 parameters"):
        fit_loads(six, prop, quantities=("thrust",), options=FitOptions(directions=0))
    with pytest.raises(ValueError, match="3 points of thrust cannot identify 3 parameter directions"):
        fit_loads(six.subset(np.arange(6) < 3), prop, quantities=("thrust",))


def test_a_hand_written_coverage_table_may_give_some_keys(tmp_path):
    """A [coverage] table with only J_max is checked for J alone (every command stopped with an
    internal KeyError on the missing keys before); rpm_min or rpm_max alone checks its end."""
    base = tmp_path / "p.toml"
    run = CliRunner().invoke
    assert run(cli, ["fit", "loads", str(_static_csv(tmp_path / "s.csv")), "--prop", "apce_8x6",
                     "--out", str(base)]).exit_code == 0
    text = base.read_text().split("[coverage]")[0]
    part = tmp_path / "part.toml"
    part.write_text(text + "[coverage]\nJ_max = 0.5\n")
    out = run(cli, ["loads", "apce_8x6", "--params", str(part), "--rpm", "5000", "--airspeed", "20"])
    assert out.exit_code == 0, out.output
    assert "advance ratio up to 1.18: the data behind" in out.output and "rpm: the data" not in out.output
    half = tmp_path / "half.toml"
    half.write_text(text + "[coverage]\nrpm_max = 4000.0\n")  # (one end of the span: that end is checked)
    out = run(cli, ["loads", "apce_8x6", "--params", str(half), "--rpm", "5000"])
    assert out.exit_code == 0 and "5000 rpm: the data behind" in out.output and "span up to 4000 rpm" in out.output
    half.write_text(text + "[coverage]\nrpm_min = 3000.0\n")
    out = run(cli, ["loads", "apce_8x6", "--params", str(half), "--rpm", "2000"])
    assert out.exit_code == 0 and "span from 3000 rpm up" in out.output


def test_directions_stay_fewer_than_the_residuals():
    """One J point (thrust and torque: 2 residuals) fitted 2 directions, no degree of freedom left,
    where docs/identification.md says a fit of K directions needs more than K residuals."""
    from propmap.identify import LoadData

    prop = pm.load_propeller("apce_8x6")
    truth = pm.rotor_loads(prop, pm.default_params("apce_8x6"), 4000 * math.pi / 30, 3.0, 0.0)
    d = LoadData(np.array([4000 * math.pi / 30]), np.array([3.0]), np.array([0.0]),
                 {"thrust": np.array([float(truth.thrust)]), "torque": np.array([float(truth.torque)])},
                 np.array(["sweep"], dtype=object))
    r = fit_loads(d, prop)
    assert r.extra["directions"]["count"] == 1
