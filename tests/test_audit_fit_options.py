"""A mutation audit of identify/options.py, identify/continuation.py, identify/jackknife.py, identify/directions.py and io/uncertainty.py (2026-11-29): each test kills a hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""  # noqa: E501

import math
from importlib import resources

import numpy as np
import pytest

import propmap as pm
from propmap.identify import FitOptions, LoadData, fit_level_flight, fit_loads, read_vehicle, simulate_level_flight
from propmap.identify.continuation import _gauss_newton
from propmap.identify.directions import leading_directions
from propmap.identify.jackknife import jackknife_loads
from propmap.identify.options import CAMBERED_FIT, CAMBERED_FIT_RE

PROP = pm.load_propeller("apce_8x6")
TRUE = pm.default_params("apce_8x6")  # the calibrated set of UIUC vol. 1's APC 8x6E (Brandt & Selig 2011)


def _sweeps(params, rpms=(4000.0, 6000.0, 8000.0), n=6, incidence_deg=0.0, quantities=("thrust", "torque")):
    """Loads of ``params`` (propmap-generated) along n airspeeds 2-10 m/s at each of ``rpms``, a run each."""
    om = np.repeat(np.asarray(rpms) * math.pi / 30, n)
    V = np.tile(np.linspace(2.0, 10.0, n), len(rpms))
    b = np.full(om.size, math.radians(incidence_deg))
    r = pm.rotor_loads(PROP, params, om, V, b)
    group = np.repeat([f"g{i}" for i in range(len(rpms))], n).astype(object)
    return LoadData(om, V, b, {k: getattr(r, k) for k in quantities}, group, "synthetic (propmap)")


def _one_rate(noise=0.003, seed=1):
    """A static run at 3000-8000 rpm and three sweeps at 6000 rpm (runs s1-s3), 0.3% noise."""
    om = np.concatenate([np.linspace(3000.0, 8000.0, 6), np.full(15, 6000.0)]) * math.pi / 30
    V = np.concatenate([np.zeros(6), np.linspace(1.0, 15.0, 15)])
    b = np.zeros(om.size)
    r = pm.rotor_loads(PROP, TRUE, om, V, b)
    rng = np.random.default_rng(seed)
    m = {k: getattr(r, k) * (1 + noise * rng.standard_normal(om.size)) for k in ("thrust", "torque")}
    group = np.array(["static"] * 6 + ["s1"] * 5 + ["s2"] * 5 + ["s3"] * 5, dtype=object)
    return LoadData(om, V, b, m, group, "synthetic (propmap)")


# ---- identify/options.py: FitOptions' checks (its docstring's Raises)

@pytest.mark.parametrize("mutant, bounds, said", [
    ("O20", {"cl_alpha": (5.0, 5.0)}, r"bounds\['cl_alpha'\] must be finite with low < high, got \(5.0, 5.0\)"),
    ("O21", {"cd_min": (0.0, math.inf)}, r"bounds\['cd_min'\] must be finite with low < high, got \(0.0, inf\)"),
])
def test_bounds_must_be_finite_with_low_below_high(mutant, bounds, said):
    """O20 (low == high accepted), O21 (an infinite bound accepted): FitOptions refuses both, naming the bound."""
    with pytest.raises(ValueError, match=said):
        FitOptions(bounds=bounds)


def test_jacobian_outside_its_two_values_is_refused():
    """O30 (the jacobian check dropped): 'exact' is neither 'implicit' nor 'differences'."""
    with pytest.raises(ValueError, match=r"jacobian must be 'implicit' or 'differences', got 'exact'"):
        FitOptions(jacobian="exact")


@pytest.mark.parametrize("mutant, x0", [("O38", (6.28, 2.0, 0.0, 0.47, 1.0)), ("O39", (6.28, math.nan, 0.0, 0.47))])
def test_x0_must_be_four_finite_numbers(mutant, x0):
    """O38 (five numbers accepted), O39 (a NaN accepted)."""
    with pytest.raises(ValueError, match=r"x0 must be 4 finite numbers \(cl1, cl2, cd, alpha0 \[rad\]\)"):
        FitOptions(x0=x0)


@pytest.mark.parametrize("mutant, options, said", [
    ("O23", FitOptions(names=("cl_alpha", "cd_min", "cl_alpha")),
     "cannot fit cl_alpha twice: give each parameter once"),
    ("O24", FitOptions(names=()), "names is empty: give the parameters to fit, or None for the default"),
    ("O27", FitOptions(M=20.0, names=("cl_alpha", "M")),
     r"M is fixed at 20 by the fit's options \(--M\) and cannot also be fitted"),
])
def test_names_a_fit_cannot_honour_are_refused(mutant, options, said):
    """O23 (a name given twice), O24 (no name), O27 (M fitted while options.M fixes it) were fitted."""
    with pytest.raises(ValueError, match=said):
        fit_loads(_sweeps(TRUE), PROP, base=TRUE, options=options)


def test_a_rotor_option_is_fitted_with_the_cambered_model_and_reported_in_degrees():
    """O26 (ROTOR_BOUNDS' names refused with the cambered model: docs/identification.md, '--fit-params
    ... or a rotor option: collective, flap_compliance'), O14 (the collective, an angle, reported in
    rad): loads of a 1 deg collective offset are fitted back as collective_deg = 1."""
    d = _sweeps(TRUE.replace(collective=math.radians(1.0)))
    r = fit_loads(d, PROP, base=TRUE, options=FitOptions(names=("cl_alpha", "collective"), prior=False))
    fitted = r.to_dict()["fitted"]
    assert fitted["collective_deg"] == pytest.approx(1.0, abs=1e-6)
    assert fitted["cl_alpha"] == pytest.approx(TRUE.cl_alpha, rel=1e-6)


def test_a_cambered_field_given_bounds_can_be_fitted():
    """O25 (only CAMBERED_BOUNDS' names fittable): _check_names takes any field of the cambered set that
    options.bounds bounds (re_ref here); without bounds it is refused, naming the model's parameters."""
    d = _sweeps(TRUE)
    r = fit_loads(d, PROP, base=TRUE, options=FitOptions(names=("cl_alpha", "re_ref"), prior=False, max_nfev=2,
                                                         bounds={"re_ref": (1e4, 1e6)}))
    assert r.names == ("cl_alpha", "re_ref") and 1e4 <= r.x[1] <= 1e6
    with pytest.raises(ValueError, match="cannot fit re_ref with the cambered model"):
        fit_loads(d, PROP, base=TRUE, options=FitOptions(names=("cl_alpha", "re_ref"), prior=False))


def test_flap_compliance_is_fitted_from_rigid_blades_up_to_its_bound_50():
    """O12 (flap_compliance's upper bound 5, not ROTOR_BOUNDS' 50: docs, 'its range is [0, 50]'),
    O41 (FLAP_START 0: from rigid blades the loads are flat in the compliance, the fit never leaves 0):
    at-incidence loads of compliance 8 rad/(N m) are fitted back from a rigid base."""
    d = _sweeps(TRUE.replace(flap_compliance=8.0), incidence_deg=60.0, quantities=("thrust", "drag", "torque"))
    r = fit_loads(d, PROP, base=TRUE, options=FitOptions(names=("flap_compliance",), prior=False))
    assert r.at_bound == () and r.x[0] == pytest.approx(8.0, rel=1e-6)


def test_sweeps_at_two_rates_keep_the_reynolds_terms_three_free_them():
    """O09 (MIN_RATES_FOR_RE 2): docs/identification.md's table, sweeps at 1-2 rotation rates (no static
    run) fit the 5 level parameters, at >= 3 rates all 8."""
    two = fit_loads(_sweeps(TRUE, rpms=(4000.0, 6000.0)), PROP, options=FitOptions(max_nfev=1))
    three = fit_loads(_sweeps(TRUE), PROP, options=FitOptions(max_nfev=1))
    assert two.names == CAMBERED_FIT == ("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2")
    assert three.names == CAMBERED_FIT_RE == CAMBERED_FIT + ("re_exp_lift", "re_exp", "alpha_L0_re")


# ---- identify/continuation.py: the continuation in M (docs/identification.md, Robustness)

@pytest.fixture(scope="module")
def level_flight():
    veh = read_vehicle(str(resources.files("propmap") / "data/examples/quadrotor.toml"))
    V = np.linspace(0, 14, 20)
    return veh, simulate_level_flight(veh, pm.preset("gill2017-apc"), V, -2.5 * V)


def test_no_continuation_at_a_base_m_of_30_or_below(level_flight):
    """C02 (the continuation for any M): 'With no --M, a base with M > 30 is fitted in three stages';
    a base at M = 20 is fitted once, at 20, and the report has no continuation."""
    veh, data = level_flight
    r = fit_level_flight(data, veh, base=pm.preset("gill2017-apc").replace(M=20.0))
    assert "M_continuation" not in r.extra and r.params.M == 20.0
    assert [s["stage"] for s in r.starts] == ["polish"]


def test_no_continuation_for_the_sin_cos_lift(level_flight):
    """C04 (the continuation for lift_model='sincos' too): footnote 1's sin-cos lift has no stall blend
    for M to sharpen; its fit of (cl2, cd) runs once."""
    veh, data = level_flight
    r = fit_level_flight(data, veh, options=FitOptions(lift_model="sincos"))
    assert r.names == ("cl2", "cd") and "M_continuation" not in r.extra
    assert [s["stage"] for s in r.starts] == ["polish"]


def test_a_continued_fit_counts_the_evaluations_of_both_stages(level_flight):
    """C15 (nfev without stage 1's): FitResult.nfev is the residual evaluations over all starts, the
    M = 30 stage's and the continuation's."""
    veh, data = level_flight
    r = fit_level_flight(data, veh)
    stages = [s["stage"] for s in r.starts]
    assert stages[-1] == "continuation to M = 50" and len(stages) >= 2
    assert r.nfev == sum(s["nfev"] for s in r.starts) > r.starts[-1]["nfev"]


def _linear(nan_beyond=math.inf):
    """r(x) = A x - b (least-squares optimum near (1, -2)), NaN where x[0] > nan_beyond."""
    A = np.array([[2.0, 0.0], [1.0, 1.0], [0.0, 3.0]])
    b = A @ np.array([1.0, -2.0]) + np.array([0.1, -0.2, 0.05])  # a residual left at the optimum

    def evaluate(x):
        r = A @ x - b
        return (np.full(3, np.nan) if x[0] > nan_beyond else r), A

    return evaluate


def test_gauss_newton_ends_a_try_at_a_step_whose_residual_is_not_finite():
    """C05 (a step kept unless its cost is higher: a NaN one kept): the try ends at the best point met."""
    lb, ub = np.full(2, -10.0), np.full(2, 10.0)
    x0 = np.array([0.0, 0.0])
    x, cost, converged = _gauss_newton(_linear(nan_beyond=0.5), x0, lb, ub)
    r0, _ = _linear()(x0)
    assert np.array_equal(x, x0) and cost == pytest.approx(0.5 * float(r0 @ r0)) and not converged


def test_gauss_newton_started_at_the_optimum_has_converged():
    """C07 (a step below GN_STEP_TOL that no longer lowers the cost reported as a stall): 'or was all
    that was left and no longer lowered the cost (rounding): the piece's optimum'. At the exact
    optimum of a residual that vanishes there the step is 0 and the cost stays 0."""
    A = np.array([[2.0, 0.0], [1.0, 1.0], [0.0, 3.0]])
    x_star = np.array([1.0, -2.0])
    b = A @ x_star

    def evaluate(x):
        return A @ x - b, A

    x, cost, converged = _gauss_newton(evaluate, x_star.copy(), np.full(2, -10.0), np.full(2, 10.0))
    assert converged and np.array_equal(x, x_star) and cost == 0.0


# ---- identify/jackknife.py (docs/identification.md, A report that tells the truth)

def _jackknife_se(values):
    """sqrt((g - 1) / g sum (theta_i - mean theta)^2) (Efron & Tibshirani 1993, eq. 11.5)."""
    v = np.asarray(values, float)
    return math.sqrt((v.size - 1) / v.size * float(np.sum((v - v.mean()) ** 2)))


def test_the_folds_of_a_fit_along_directions_free_as_many_directions():
    """J05 (each fold's direction count by the rule again): the fit frees 5 directions; without s3 the
    rule would free 4. The report's std error is that of folds fitted along 5, computed here."""
    d = _one_rate()
    r = fit_loads(d, PROP)
    assert r.extra["directions"]["count"] == 5
    rep = jackknife_loads(r, d, PROP)
    folds = [fit_loads(d.subset(d.group != g), PROP, options=FitOptions(directions=5)) for g in ("s1", "s2", "s3")]
    assert rep["groups"] == ["s1", "s2", "s3"]
    for name in ("cl_alpha", "cd_min"):
        k = r.names.index(name)
        assert rep["std_error"][name] == pytest.approx(_jackknife_se([f.x[k] for f in folds]), rel=1e-6)


def test_a_fold_that_cannot_be_fitted_is_named():
    """J06 (the fold's error re-raised without its run): 'a fold that cannot be fitted (the message
    names its run)'. Three runs of two thrust points fit 5 parameters; without a run, 4 points cannot."""
    d = _sweeps(TRUE, n=2, quantities=("thrust",))
    options = FitOptions(names=CAMBERED_FIT, prior=False, max_nfev=3)
    r = fit_loads(d, PROP, base=TRUE, options=options)
    with pytest.raises(ValueError, match="the jackknife's fit without run g0 fails: 4 points cannot identify 5"):
        jackknife_loads(r, d, PROP, base=TRUE, options=options)


def test_folds_ending_at_a_bound_are_named():
    """J07 (the folds' at_bound dropped): cl_alpha bounded at 5 below the data's 6.36 ends there in every
    fold, which the report names (its spread understated)."""
    d = _sweeps(TRUE)
    options = FitOptions(names=("cl_alpha", "cd_min"), prior=False, bounds={"cl_alpha": (2.0, 5.0)})
    r = fit_loads(d, PROP, base=TRUE, options=options)
    assert r.at_bound == ("cl_alpha",)
    rep = jackknife_loads(r, d, PROP, base=TRUE, options=options)
    assert rep["at_bound"] == {"g0": ["cl_alpha"], "g1": ["cl_alpha"], "g2": ["cl_alpha"]}


# ---- identify/directions.py

def test_one_sweep_rate_frees_the_directions_with_eigenvalue_at_least_10():
    """D02 (DATA_OVER_PRIOR 3): 'such a fit frees the directions whose eigenvalue is at least
    DATA_OVER_PRIOR = 10'. These data have one eigenvalue between 3 and 10 (4.8), not freed."""
    r = fit_loads(_one_rate(), PROP)
    lam = np.asarray(r.extra["directions"]["eigenvalues"])
    assert np.any((lam >= 3.0) & (lam < 10.0))
    assert r.extra["directions"]["count"] == int(np.sum(lam >= 10.0)) == 5


def test_each_directions_largest_whitened_component_is_positive():
    """D05 (the sign convention flipped): 'each u_i's largest component is positive (a reproducible
    sign)'; u_i = L^-1 B[:, i]."""
    rng = np.random.default_rng(3)
    jac = rng.standard_normal((12, 4))
    chol = np.linalg.cholesky(np.cov(rng.standard_normal((4, 30))) + np.eye(4))
    B, lam = leading_directions(jac, chol, 0.5, 4)
    U = np.linalg.solve(chol, B)
    for i in range(4):
        assert U[np.argmax(np.abs(U[:, i])), i] > 0
    assert np.allclose(U.T @ U, np.eye(4), atol=1e-12) and np.all(np.diff(lam) <= 0)


# ---- io/uncertainty.py

def test_a_flight_fits_coverage_is_not_load_data_at_incidence(tmp_path):
    """U07 (a flight fit's incidence_deg_max read as load data at incidence): a flight fit's rotors sit
    near 180 deg in any sink; its file keeps the axial off-axis sentence, while a load fit's says its range."""
    from propmap.io.params_file import write_params
    from propmap.io.uncertainty import OFF_AXIS, model_uncertainty

    flight, loads = tmp_path / "flight.toml", tmp_path / "loads.toml"
    write_params(flight, TRUE, coverage={"data": "flight logs", "incidence_deg_max": 178.0})
    write_params(loads, TRUE, coverage={"data": "tunnel.csv", "incidence_deg_max": 60.0})
    assert model_uncertainty(str(flight))["off_axis"] == OFF_AXIS
    assert model_uncertainty(str(loads))["off_axis"].startswith("fitted to load data at incidence up to 60 deg")
