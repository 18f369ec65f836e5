"""Mutation audit of the simulator export's fit (propmap.simexport.fit) and of `propmap validate`'s
report helpers (propmap.cli.validate, propmap.cli.validate_all): the envelope's bounds, the fit's
sampling, the least squares with its fixed and held terms, the error metrics and the summaries."""

import json
import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest
from cli_helpers import run

import propmap as pm
from propmap.cli import validate_all as VA
from propmap.core.units import RPM
from propmap.simexport import Envelope
from propmap.simexport import fit as F


@pytest.fixture(scope="module")
def model():
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    return prop, params, params.air


# ---------------------------------------------------------------- Envelope


def test_envelope_refuses_a_range_of_zero_width():
    """Mutant F1 (low < high relaxed to low <= high): a range of one value is refused."""
    with pytest.raises(ValueError, match=r"envelope rpm must satisfy 1 <= low < high <= 954929, got 5000.0, 5000.0"):
        Envelope(rpm=(5000.0, 5000.0))
    with pytest.raises(ValueError, match=r"envelope airspeed must satisfy 0 <= low < high <= 500"):
        Envelope(rpm=(4000.0, 5000.0), airspeed=(3.0, 3.0))


@pytest.mark.parametrize("kwargs, name", [
    ({"rpm": (0.5, 5000.0)}, "rpm"),  # Mutant F2: rpm's lower bound 1
    ({"rpm": (1000.0, 954930.0)}, "rpm"),
    ({"rpm": (1000.0, 5000.0), "airspeed": (0.0, 500.5)}, "airspeed"),  # Mutant F3: airspeed's upper bound 500 m/s
    ({"rpm": (1000.0, 5000.0), "airspeed": (-0.1, 5.0)}, "airspeed"),
    ({"rpm": (1000.0, 5000.0), "incidence_deg": (0.0, 180.5)}, "incidence_deg"),  # Mutant F4: incidence <= 180 deg
    ({"rpm": (1000.0, 5000.0), "incidence_deg": (-1.0, 90.0)}, "incidence_deg"),
])
def test_envelope_refuses_a_range_past_its_bounds(kwargs, name):
    """Mutants F2, F3, F4: each range's bounds (rpm [1, 954929], airspeed [0, 500] m/s, incidence [0, 180] deg)."""
    with pytest.raises(ValueError, match=f"envelope {name} must satisfy"):
        Envelope(**kwargs)


def test_envelope_accepts_its_bounds_exactly():
    """Mutants F2-F4 (the other side): the bounds themselves are accepted and stored as floats."""
    env = Envelope(rpm=(1, 954929), airspeed=(0, 500), incidence_deg=(0, 180))
    assert env.rpm == (1.0, 954929.0) and env.airspeed == (0.0, 500.0) and env.incidence_deg == (0.0, 180.0)
    assert env.hover == pytest.approx(math.sqrt(954929.0))


@pytest.mark.parametrize("hover", [999.0, 2000.5, math.nan])
def test_envelope_refuses_a_hover_rpm_outside_its_rpm_range(hover):
    """Mutant F5 (the hover rpm's upper check dropped): a hover rpm above, below or NaN is refused."""
    with pytest.raises(ValueError, match=r"hover_rpm must be a number within its rpm range \[1000, 2000\]"):
        Envelope(rpm=(1000.0, 2000.0), hover_rpm=hover)
    assert Envelope(rpm=(1000.0, 2000.0), hover_rpm=2000).hover == 2000.0


# ---------------------------------------------------------------- sampling


def test_samples_refuse_fewer_than_ten_converged_points(model):
    """Mutant F10 (MIN_POINTS check weakened): 9 points, all converged, are too few to fit."""
    prop, params, air = model
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 5.0))
    with pytest.raises(ValueError, match=r"only 9 of the envelope's 9 points converged; at least 10"):
        F._samples(prop, params, air, env, 9, 0)
    assert F._samples(prop, params, air, env, 10, 0)["omega"].size == 10


def test_samples_refuse_a_static_thrust_of_zero(model, monkeypatch):
    """Mutant F11 (static thrust > 0 relaxed to >= 0): a static thrust of exactly 0 cannot normalise the fit."""
    prop, params, air = model
    real = F.rotor_loads

    def zero_static(*args, **kwargs):
        r = real(*args, **kwargs)
        if np.ndim(args[3]) == 0 and args[3] == 0.0:  # the static call (V = 0): its thrust made 0
            r.thrust[...] = 0.0
        return r

    monkeypatch.setattr(F, "rotor_loads", zero_static)
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 5.0))
    with pytest.raises(ValueError, match=r"static thrust is not positive at every rpm of the envelope \(0\)"):
        F._samples(prop, params, air, env, 20, 0)


def test_samples_flag_multiple_roots_apart_from_vortex_ring(model):
    """Mutant F12 (flagged = vortex ring only): points with multiple roots outside vortex ring are flagged too
    (apce_8x6, 3000-9000 rpm, 0-15 m/s, 0-180 deg, seed 0: 7 of 400 such points, measured 2026-11-29)."""
    prop, params, air = model
    env = Envelope(rpm=(3000.0, 9000.0), airspeed=(0.0, 15.0))
    s = F._samples(prop, params, air, env, 400, 0)
    rng = np.random.default_rng(0)
    om = rng.uniform(*env.rpm, 400) * RPM
    V = rng.uniform(*env.airspeed, 400)
    b = np.radians(rng.uniform(*env.incidence_deg, 400))
    r = pm.rotor_loads(prop, params, om, V, b, air=air, on_failure="flag")
    ok = r.converged
    only_roots = (r.multiple_roots & ~r.vortex_ring)[ok]
    assert only_roots.sum() >= 3
    assert np.array_equal(s["flagged"], (r.vortex_ring | r.multiple_roots)[ok])
    assert s["flagged"][only_roots].all()


# ---------------------------------------------------------------- least squares


def _columns():
    rng = np.random.default_rng(1)
    x = rng.uniform(0.0, 1.0, 50)
    return rng, x


def test_a_term_whose_size_reaches_determined_is_fitted():
    """Mutant F14 (peak >= DETERMINED made >): a term whose size reaches 1e-3 exactly is fitted, not fixed."""
    _, x = _columns()
    fixed, held = {}, {}
    size = np.linspace(0.0, F.DETERMINED, 50)
    (k,) = F._lstsq([("k_d", 10 * x, size, "mu")], 2.0 * 10 * x, fixed, held)
    assert k == pytest.approx(2.0, rel=1e-12) and fixed == {} and held == {}
    (k,) = F._lstsq([("k_d", 10 * x, size * 0.999, "mu")], 2.0 * 10 * x, fixed, held)
    assert k == 0.0 and "stays below 0.001" in fixed["k_d"] and "at most 0.001" in fixed["k_d"]


def test_terms_the_envelope_cannot_separate_are_named():
    """Mutant F16 (the names in the message: |v| > 0.1 made > 0.9): two collinear terms are both named."""
    rng, x = _columns()
    terms = [("k_h", x, np.full(50, 0.5), "mu^2"), ("k_z", x * (1 + 1e-9 * rng.standard_normal(50)), np.full(50, 0.5),
                                                   "lambda")]
    with pytest.raises(ValueError, match=r"the envelope cannot separate k_h, k_z \(condition number"):
        F._lstsq(terms, x, {}, {})


def test_only_a_coefficient_whose_unbounded_fit_is_negative_is_said_held():
    """Mutant F18 (held without f < 0): k_h, whose unbounded fit is +2, ends at 0 beside k_d (unbounded -3), but only
    k_d is said held at its sign's bound."""
    rng, x = _columns()
    c1, c2 = x, x + 0.05 * rng.standard_normal(50)
    fixed, held = {}, {}
    out = F._lstsq([("k_h", c1, np.full(50, 0.5), "mu^2"), ("k_d", c2, np.full(50, 0.5), "mu")], 2 * c1 - 3 * c2,
                   fixed, held)
    assert out == [0.0, 0.0] and fixed == {}
    assert set(held) == {"k_d"} and held["k_d"].endswith("(the unbounded fit gives -3)")


def test_held_message_gives_the_unbounded_coefficient_in_its_units():
    """Mutant F19 (the unbounded value not divided by the column's scale): a column of peak ~10 whose fit is -2.5
    is said as -2.5, not -25."""
    rng, x = _columns()
    held = {}
    (k,) = F._lstsq([("k_d", 10 * x, x, "mu")], -2.5 * 10 * x + 0.01 * rng.standard_normal(50), {}, held)
    assert k == 0.0 and held["k_d"].endswith("(the unbounded fit gives -2.5)")


def test_relative_difference_is_relative_to_the_full_model():
    """Mutant F29 (_rel divided by the export's value): the hover errors are relative to the full model's (b)."""
    assert F._rel(1.0, 2.0) == 0.5 and F._rel(3.0, 2.0) == 0.5 and F._rel(-1.0, 4.0) == 1.25


def test_multinomial_moment_terms_carry_the_radius(model):
    """Mutant F27 (the moments' scale without R): the multinomial's CQ and CR speed terms are fitted per q R, so that
    its torque and rolling moment follow the full model (apce_8x6, 4000-9000 rpm, 0-12 m/s, 0-120 deg: rms 1.8% and
    1.1% clean, 76% and 34% with the mutant, measured 2026-11-29)."""
    prop, params, air = model
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 12.0), incidence_deg=(0.0, 120.0))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = F.export_sim("multinomial", prop, params, air=air, envelope=env, n_points=300, seed=0)
    assert r.errors["torque"]["rms"] < 0.05 and r.errors["rolling_moment"]["rms"] < 0.05
    assert r.errors["thrust"]["rms"] < 0.05 and r.errors["drag"]["rms"] < 0.05


# ---------------------------------------------------------------- export_sim's report


@pytest.fixture(scope="module")
def rotorpy_small(model):
    prop, params, air = model
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 12.0), incidence_deg=(0.0, 120.0), hover_rpm=6000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return env, F.export_sim("rotorpy", prop, params, air=air, envelope=env, n_points=100, seed=7)


def test_hover_errors_give_the_hover_rpm_in_rpm(rotorpy_small):
    """Mutant F33 (the hover rpm reported in rad/s): errors["hover"]["rpm"] is the envelope's hover rpm."""
    env, r = rotorpy_small
    assert r.errors["hover"]["rpm"] == pytest.approx(6000.0, rel=1e-12) == env.hover


def test_edgewise_trend_is_the_thrust_change_at_90_degrees(model, rotorpy_small):
    """Mutants F35 (incidence 0 instead of 90 deg) and F36 (the ratio without - 1): the edgewise trend is
    T(V_top, 90 deg) / T(hover) - 1 at the hover rpm, for this set and for the generic set."""
    prop, params, air = model
    env, r = rotorpy_small
    trend = r.meta["model_uncertainty"]["edgewise_trend"]
    assert trend["rpm"] == 6000.0 and trend["airspeed"] == 12.0
    for key, p in (("this_set", params), ("generic", pm.generic_params())):
        t = pm.rotor_loads(prop, p, np.array([6000.0 * RPM] * 2), np.array([0.0, 12.0]), math.pi / 2, air=air).thrust
        assert trend[key] == pytest.approx(t[1] / t[0] - 1, rel=1e-9)
    # the calibrated set's thrust rises edgewise (the in-plane induction, docs/validation.md): a few per cent
    assert 0.0 < trend["this_set"] < 0.5


def test_export_sim_refuses_an_envelope_of_the_wrong_type(model):
    """Mutant F39 (the Envelope type check dropped): a tuple is refused with the type's name."""
    prop, params, air = model
    with pytest.raises(ValueError, match=r"envelope must be an Envelope or None, got tuple"):
        F.export_sim("rotorpy", prop, params, air=air, envelope=(4000.0, 9000.0), n_points=100)


def test_meta_records_the_fit_and_check_seeds(rotorpy_small):
    """Mutant F43 (the recorded seed off by one): meta's seed is the fit's, its check_seed the next one."""
    _, r = rotorpy_small
    assert r.meta["seed"] == 7 and r.meta["check_seed"] == 8 == F.check_seed(7)


# ---------------------------------------------------------------- validate --all's report helpers


def test_summarize_gives_median_p90_worst_and_count():
    """Mutants A1 (mean for median), A2 (95th percentile), A3 (count off by one): ten errors 1%..10% and one 40%."""
    s = VA.summarize([0.01 * k for k in range(1, 11)] + [0.40])
    assert s == {"median": pytest.approx(0.06), "p90": pytest.approx(0.10), "worst": 0.40, "n_propellers": 11}
    assert isinstance(s["n_propellers"], int)


def _row(name, ct, cp, volume=1, family="apce"):
    return {"propeller": name, "generic_used": "generic without x", "volume": volume, "family": family,
            **{k: {"rms_ct": ct, "rms_cp": cp} for k in ("static", "blind", "paper_table_i", "hover_model")}}


def test_summaries_keep_ct_and_cp_apart():
    """Mutant A4 (CP summarised from the CT errors): each key's cp summary is of rms_cp."""
    rows = [_row("a", 0.01, 0.05), _row("b", 0.03, 0.07)]
    out = VA._summaries(rows, ["static"])
    assert out["static"]["ct"]["median"] == pytest.approx(0.02) and out["static"]["cp"]["median"] == pytest.approx(0.06)
    assert out["static"]["cp"]["worst"] == 0.07 and out["static"]["ct"]["n_propellers"] == 2


def test_pct_writes_a_fraction_as_percent():
    """Mutant A5 (_pct without the factor 100): 0.0312 is '  3.1%'."""
    assert VA._pct(0.0312) == "  3.1%" and VA._pct(1.0) == "100.0%"


def test_write_json_refuses_nan_and_ends_with_a_newline(tmp_path):
    """Mutants A6 (allow_nan) and A7 (no final newline): NaN is not JSON; the file ends with one newline."""
    p = tmp_path / "v.json"
    VA.write_json(p, {"a": [1, 0.5]})
    text = p.read_text()
    assert text.endswith("}\n") and not text.endswith("\n\n") and json.loads(text) == {"a": [1, 0.5]}
    with pytest.raises(ValueError, match="Out of range float values are not JSON compliant"):
        VA.write_json(tmp_path / "nan.json", {"a": math.nan})
    assert not (tmp_path / "nan.json").exists()


def test_csv_has_ct_and_cp_columns_and_each_rows_citation(tmp_path):
    """Mutant A8 (only rms_ct written): the table has every key's rms_ct and rms_cp, and the row's citation."""
    import pandas as pd

    p = tmp_path / "t.csv"
    VA._csv(p, {"propellers": [_row("apce_8x6", 0.0123, 0.0456)]})
    df = pd.read_csv(p)
    assert df.loc[0, "static_rms_cp"] == 0.0456 and df.loc[0, "blind_rms_ct"] == 0.0123
    assert df.loc[0, "hover_model_rms_cp"] == 0.0456 and "UIUC Propeller Data Site" in df.loc[0, "citation"]


def _report_inputs(name="apce_8x6"):
    rows = [_row(name, 0.02, 0.04), _row("grcp_10x8", 0.05, 0.08, volume=2, family="grcp")]
    cat = {"propellers": rows, "summary": VA._summaries(rows, ["static", "blind", "paper_table_i", "hover_model"]),
           "by_volume": {"vol. 1": VA._summaries(rows[:1], ["static", "blind"])}}
    cases = {"apc10x7e": SimpleNamespace(notes="n", citation="c", metrics={"generic": {"rms_ct": 0.012345}})}
    incidence = {"apce_8x6": {"default": {"rms_thrust": 0.02, "rms_drag": 0.1, "rms_torque": 0.03,
                                          "flap_compliance": [0.7, 1.9]}}}
    return cat, cases, incidence


def test_print_report_summary_reads_median_p90_worst(capsys):
    """Mutant A9 (p90 and worst swapped in the summary line): 'CT median / p90 / worst' in that order."""
    cat, cases, incidence = _report_inputs()
    VA.print_report(cat, cases, incidence)
    out = capsys.readouterr().out
    # static CT over 2% and 5%: median 3.5%, p90 4.7%, worst 5.0%; CP over 4% and 8%: 6.0%, 7.6%, 8.0%
    assert "  static        CT   3.5% /   4.7% /   5.0%   CP   6.0% /   7.6% /   8.0%   (" in out
    assert "vol. 1     n=1    static 2.0%/2.0%/2.0%  blind 2.0%/2.0%/2.0%" in out
    assert "flap compliance 0.7-1.9 rad/(N m)" in out  # Mutant A12: the fits' compliance range
    assert "generic                          rms_ct 0.01235" in out


def test_print_report_columns_widen_for_a_long_name(capsys):
    """Mutant A11 (the name column fixed at 16): a longer name keeps one blank before the first cell."""
    cat, cases, _ = _report_inputs("a_propeller_name_of_30_chars_")
    VA.print_report(cat, cases)
    lines = capsys.readouterr().out.splitlines()
    row = next(line for line in lines if line.startswith("a_propeller_name_of_30_chars_"))
    head = next(line for line in lines if line.startswith("propeller"))
    assert row.index("2.0%") == head.index("static CT") + len("static CT") - len("2.0%")
    assert row.startswith("a_propeller_name_of_30_chars_ ")


def test_run_all_refuses_an_empty_protocol_list(tmp_path):
    """Mutant A10 (an empty list let through): run_all([]) is refused before any propeller is run."""
    with pytest.raises(VA.InputError, match=r"--protocols: unknown or empty ; valid: loso, loro"):
        VA.run_all([], ["nope_1x1"], None, True)
    with pytest.raises(VA.InputError, match=r"--protocols: unknown or empty nope"):
        VA.run_all(["static", "nope"], ["nope_1x1"], None, True)


# ---------------------------------------------------------------- propmap validate's argument checks


@pytest.fixture
def no_catalogue_run(monkeypatch):
    """validate --all's catalogue run replaced by a recorder: a check that lets a bad call through fails at once."""
    calls = []
    monkeypatch.setattr(VA, "run_all", lambda *a, **k: calls.append(a))
    return calls


@pytest.mark.parametrize("argv, match", [
    (["apce_8x6", "--all"], "give PROP (or SOURCE files) or --all, not both"),  # Mutant V4
    (["--all", "--params", "generic"], "--params applies to a single PROP"),  # Mutant V5
    (["--all", "--figure", "{tmp}/f.png"], "--figure applies to a single PROP"),  # Mutant V6
])
def test_validate_all_refuses_options_of_a_single_prop(capsys, tmp_path, no_catalogue_run, argv, match):
    """Mutants V4, V5, V6 (each check of --all's options dropped): refused with exit 2, the catalogue not run."""
    code, _, err = run(capsys, "validate", *[a.format(tmp=tmp_path) for a in argv])
    assert code == 2 and match in err and no_catalogue_run == []


def test_validate_all_reaches_the_catalogue_run_with_its_options(capsys, no_catalogue_run):
    """The recorder above is reached by a good call (so the refusals above are the checks', not the stub's)."""
    code, _, err = run(capsys, "validate", "--all", "--protocols", "static", "--props", "apce_8x6")
    assert code == 0, err
    assert no_catalogue_run == [(["static"], ["apce_8x6"], None, False)]


def test_validate_prop_refuses_pole_pairs(capsys):
    """Mutant V3 (--pole-pairs dropped from the SOURCE-only options): a catalogue PROP takes no --pole-pairs."""
    code, _, err = run(capsys, "validate", "apce_8x6", "--pole-pairs", "7")
    assert code == 2 and "--pole-pairs applies to SOURCE files (give --prop with them)" in err


def test_validate_figure_refuses_a_format_it_cannot_write(capsys, tmp_path):
    """Mutant V7 (.txt let through as a figure format): refused by its suffix before the validation runs."""
    code, _, err = run(capsys, "validate", "apce_8x6", "--figure", tmp_path / "f.txt")
    assert code == 2 and "give a .png, .pdf or .svg file name (the format follows it)" in err
    assert not (tmp_path / "f.txt").exists()


def test_validate_prop_refuses_out_dir(capsys, tmp_path):
    """Mutant V8 (--out-dir dropped from the --all-only options): a single PROP writes no folder, so it is refused."""
    code, _, err = run(capsys, "validate", "apce_8x6", "--out-dir", tmp_path / "o")
    assert code == 2 and "--out-dir applies to --all" in err and not (tmp_path / "o").exists()


def test_check_points_count_the_check_samples_not_the_fitted(model, monkeypatch):
    """Mutant F41 (check_points from the fitted samples): where points fail to converge (here: made to fail above
    9 m/s), the fitted and the check points' counts differ, and each is reported as its own."""
    prop, params, air = model
    real = F.rotor_loads

    def fail_fast(*args, **kwargs):
        r = real(*args, **kwargs)
        if np.ndim(args[3]) == 1 and np.size(args[3]) == 100:
            r.converged[np.asarray(args[3]) > 9.0] = False
        return r

    monkeypatch.setattr(F, "rotor_loads", fail_fast)
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 12.0), incidence_deg=(0.0, 120.0))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = F.export_sim("rotorpy", prop, params, air=air, envelope=env, n_points=100, seed=8)

    def count(seed):  # _samples' draws: rpm, then airspeed
        rng = np.random.default_rng(seed)
        rng.uniform(4000.0, 9000.0, 100)
        return int(np.sum(rng.uniform(0.0, 12.0, 100) <= 9.0))

    n_fit, n_check = count(8), count(9)
    assert n_fit != n_check  # (the two seeds' draws differ, so the mutant's count is told apart)
    assert r.n_points == n_fit and r.meta["check_points"] == n_check


def test_validate_a_misspelt_prop_gives_suggestions(capsys):
    """Mutant V18 (the misspelt-name check skipped): a name that is neither a catalogue propeller nor a file is
    answered with the catalogue's nearest names."""
    code, _, err = run(capsys, "validate", "apce_8x66")
    assert code == 2
    assert "PROP: unknown propeller 'apce_8x66'; did you mean apce_8x6" in err and "SOURCE files with --prop" in err


def test_bundled_owner_needs_every_file_to_be_that_propellers():
    """Mutant V20 (subset made intersection): one of apce_8x6's bundled files beside a foreign file has no owner;
    apce_8x6's files alone are its."""
    from propmap.cli.validate import _bundled_owner
    from propmap.io.atomic import file_sha256

    files = pm.catalogue()["apce_8x6"].data_paths()
    own = {file_sha256(f) for f in files[:2]}
    assert _bundled_owner(own) == "apce_8x6"
    assert _bundled_owner(own | {"0" * 64}) is None and _bundled_owner(set()) is None
