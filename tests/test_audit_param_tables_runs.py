"""A mutation audit of io/param_sets.py, io/params_tables.py, validation/runs.py and cli/export_sim.py
(2026-11-29): each test kills a hand-made mutant that survived the modules' own test files, by the documented
behaviour it changed."""

from __future__ import annotations

import pytest
from cli_helpers import run

from propmap.io.param_sets import named_sets, resolve_params, section_preset, section_presets
from propmap.io.params_file import ParamsFileError

# ------------------------------------------------------------------ io/param_sets.py


def test_a_section_preset_resolves_with_its_own_name_as_label():
    """Kills PS2 (the label lost its ``section:`` prefix) and PS4 (the name after the prefix cut by one)."""
    for name in section_presets():
        p = resolve_params("section:" + name)
        assert p.label == "section:" + name
        assert p == section_preset(name)
        assert type(p).__name__ == "CamberedParams"


def test_an_unknown_section_preset_lists_the_valid_ones():
    """Kills PS1 (the unknown name's check dropped: a bare KeyError of the name, no valid names)."""
    with pytest.raises(KeyError, match=r"unknown section preset 'naca9999'; valid: naca0012, naca0015, naca0018"):
        resolve_params("section:naca9999")


def test_named_sets_include_the_section_presets():
    """Kills PS6 (named_sets, which the messages and help list, without the section presets)."""
    names = named_sets()
    assert {"section:naca0012", "section:naca0015", "section:naca0018"} <= set(names)
    with pytest.raises(KeyError, match=r"section:naca0015.* nor an existing file"):
        resolve_params("no-such-set")


def test_a_folder_given_as_params_is_read_as_a_file_and_named_a_directory(tmp_path):
    """Kills PS5 (a name that exists but is no regular file read as 'not a named set')."""
    folder = tmp_path / "a_folder"
    folder.mkdir()
    with pytest.raises(ParamsFileError, match="is a directory, not a file"):
        resolve_params(str(folder))


def test_an_uncalibrated_catalogue_name_is_a_key_error_with_near_names():
    """Kills PS8 (no calibrated set read as one: an AttributeError of None)."""
    with pytest.raises(KeyError, match=r"'apce_8x7' has no calibrated set; did you mean .*apce_8x6"):
        resolve_params("calibrated:apce_8x7")


# ------------------------------------------------------------------ io/params_tables.py (through a file's round trip)


def _cov(**table):
    from propmap.io.params_tables import coverage_from_dict

    return coverage_from_dict({"coverage": table}, where="p.toml")


def _body(**table):
    from propmap.io.params_tables import body_from_dict

    return body_from_dict({"body": table}, where="p.toml")


def test_a_coverage_table_round_trips_through_a_parameter_file(tmp_path):
    """Kills PT1 (J_max's range cut to [0, 10]), PT6 (rpm_min equal to rpm_max refused), PT8 (n_blades read as a
    float) and PT9 (groups read as a list): a fit's table written and read back as it was, each key its type."""
    from propmap.io.params_file import read_coverage, write_params

    cov = {"J_max": 50.0, "rpm_min": 6000.0, "rpm_max": 6000.0, "diameter_m": 0.2032, "n_blades": 2,
           "re75_min": 5.0e4, "re75_max": 5.0e4, "theta75_deg": 14.5, "data": "apce_8x6",
           "groups": ["a", "b"], "held_out": ["c"], "propeller": "apce_8x6"}
    path = tmp_path / "fit.toml"
    write_params(path, resolve_params("gill2017-apc"), coverage=cov)
    back = read_coverage(path)
    assert back == {**cov, "groups": ("a", "b"), "held_out": ("c",)}
    assert type(back["n_blades"]) is int and type(back["J_max"]) is float
    assert type(back["groups"]) is tuple and type(back["held_out"]) is tuple
    with pytest.raises(ValueError, match=r"p\.toml: coverage\.J_max must be a finite number in \[0, 100\], got 101"):
        _cov(J_max=101.0)


def test_a_zero_diameter_in_coverage_is_refused_its_interval_open_below():
    """Kills PT2 (diameter_m no longer open below), PT3 (no key open below) and PT17 (an open lower end read closed):
    cli.md/nomenclature: a hand-edited diameter_m = 0 silenced the size check."""
    for key in ("diameter_m", "re75_min", "re75_max"):
        with pytest.raises(ValueError, match=rf"p\.toml: coverage\.{key} must be a finite number in \(0, "):
            _cov(**{key: 0.0})
    assert _cov(J_max=0.0, rpm_min=0.0) == {"J_max": 0.0, "rpm_min": 0.0}  # (closed ends take their bound)


def test_a_fractional_blade_count_in_coverage_is_refused():
    """Kills PT4 (n_blades = 2.5 read as 2 blades)."""
    with pytest.raises(ValueError, match=r"p\.toml: \[coverage\] n_blades must be a whole number, got 2\.5"):
        _cov(n_blades=2.5)


def test_coverage_texts_of_exactly_1000_characters_are_kept_and_longer_refused():
    """Kills PT5 (a text of exactly the documented 1,000 characters refused)."""
    assert _cov(data="x" * 1000, groups=["g" * 1000])["data"] == "x" * 1000
    with pytest.raises(ValueError, match=r"\[coverage\] data must be a text of at most 1000 characters"):
        _cov(data="x" * 1001)
    with pytest.raises(ValueError, match=r"\[coverage\] groups must be a list of texts of at most 1000 characters"):
        _cov(groups=["g" * 1001])


def test_a_reynolds_span_upside_down_is_refused():
    """Kills PT7 (re75_min above re75_max accepted, as rpm_min above rpm_max is not)."""
    with pytest.raises(ValueError, match=r"p\.toml: \[coverage\] re75_min 200000 exceeds re75_max 100000"):
        _cov(re75_min=2e5, re75_max=1e5)
    with pytest.raises(ValueError, match=r"rpm_min 9000 exceeds rpm_max 3000"):
        _cov(rpm_min=9000.0, rpm_max=3000.0)


def test_coverage_refuses_unknown_keys_infinities_bools_and_quoted_numbers():
    """Kills PT16 (True read as 1), PT19 (an infinite value within any range), PT22 (an unknown key accepted)
    and PT23 (the quoted number's hint dropped)."""
    with pytest.raises(ValueError, match=r"\[coverage\] unknown key\(s\) bogus \(valid: J_max, incidence_deg_max"):
        _cov(bogus=1.0)
    with pytest.raises(ValueError, match=r"coverage\.airspeed_max must be a finite number in \[0, 500\], got inf"):
        _cov(airspeed_max=float("inf"))
    with pytest.raises(ValueError, match=r"coverage\.J_max must be a number, got True$"):
        _cov(J_max=True)
    with pytest.raises(ValueError, match=r"got '0\.5' \(a quoted string: write the number without quotes\)"):
        _cov(J_max="0.5")


def test_a_body_table_round_trips_and_its_ranges_are_enforced(tmp_path):
    """Kills PT10 (a drag_area of 4 numbers read), PT11 (centre_of_mass beyond [-100, 100] m since stop 102, a
    vehicle file's range, [-1, 1] m before), PT12 (a missing
    wash_factor read as 1, not 0), PT13 (rotor_interference beyond [0, 3]) and PT14 (a missing drag_area not named)."""
    import numpy as np

    from propmap.io.params_file import read_body

    path = tmp_path / "flight.toml"
    import tomli_w

    from propmap.io.params_file import params_to_dict

    data = {**params_to_dict(resolve_params("gill2017-apc")),
            "body": {"drag_area": [0.004, 0.005, 0.008], "centre_of_mass": [0.0, 0.01, -0.02],
                     "rotor_interference": 0.8}}
    path.write_bytes(tomli_w.dumps(data).encode())
    body = read_body(path)
    assert body.drag.drag_area == (0.004, 0.005, 0.008) and body.drag.wash_factor == 0.0
    np.testing.assert_array_equal(body.centre_of_mass, [0.0, 0.01, -0.02])
    assert body.rotor_interference == 0.8
    with pytest.raises(ValueError, match=r"p\.toml: \[body\]: drag_area must be 3 numbers \[m\^2\], got \[0\.1, "):
        _body(drag_area=[0.1, 0.1, 0.1, 0.1])
    with pytest.raises(ValueError, match=r"\[body\] centre_of_mass\[2\] must be a finite number in \[-100, 100\] m, "
                                         r"got 101"):
        _body(drag_area=[0.1] * 3, centre_of_mass=[0, 0, 101])
    assert _body(drag_area=[0.1] * 3, centre_of_mass=[0, 0, 100]).centre_of_mass[2] == 100.0
    with pytest.raises(ValueError, match=r"\[body\] rotor_interference must be a finite number in \[0, 3\], got 4"):
        _body(drag_area=[0.1] * 3, rotor_interference=4)
    with pytest.raises(ValueError, match=r"p\.toml: \[body\]: missing key 'drag_area'"):
        _body(wash_factor=1.0)


def test_check_number_open_upper_ends_and_huge_integers():
    """Kills PT18 (an open upper end read closed: alpha0_deg = 90 accepted), PT20 (an integer too big for a float,
    negative, read as +inf) and PT21 (an unranged key taking inf)."""
    from propmap.io.params_tables import check_number

    with pytest.raises(ValueError, match=r"w: x must be a finite number in \[0, 1\) deg, got 1\.0"):
        check_number(1.0, "x", "w", (0.0, 1.0, False, True, "deg"))
    check_number(0.999, "x", "w", (0.0, 1.0, False, True, "deg"))
    with pytest.raises(ValueError, match=r"w: x must be a finite number, got inf"):
        check_number(float("inf"), "x", "w", None)
    with pytest.raises(ValueError, match=r"w: x must be a finite number, got an integer of 401 digits"):
        check_number(-10**400, "x", "w", None)
    from propmap.io.params_file import params_from_dict, params_to_dict

    data = {**params_to_dict(resolve_params("gill2017-apc")), "alpha0_deg": 90.0}
    with pytest.raises(ValueError, match=r"p\.toml: alpha0_deg must be a finite number in \(0, 90\) deg, got 90\.0"):
        params_from_dict(data, where="p.toml")


# ------------------------------------------------------------------ validation/runs.py (apce_8x6's UIUC runs)

COARSE = (16, 8)  # (radial, azimuthal nodes: axial flight, where the azimuth does not enter)


@pytest.fixture(scope="module")
def apce_validation():
    import propmap as pm
    from propmap.core.solver import Discretization
    from propmap.io.catalogue import get_entry
    from propmap.validation.runs import validate

    entry, prop = get_entry("apce_8x6"), pm.load_propeller("apce_8x6")
    params = resolve_params("calibrated:apce_8x6")
    disc = Discretization(*COARSE)
    return entry, prop, params, disc, validate(entry, prop, params, discretization=disc)


def test_validation_runs_hold_the_measured_uiuc_data_beside_the_model_at_its_operating_points(apce_validation):
    """Kills RU11 (the static runs solved 5% too fast) and RU12 (the sweeps' airspeed J n R, not J n D):
    each run's model column is the model at the measured rpm and advance ratio, beside the measured column."""
    import math

    import numpy as np

    from propmap.core.solver import rotor_loads
    from propmap.core.units import RPM

    entry, prop, params, disc, v = apce_validation
    static, sweep = v.runs[0], v.runs[3]
    assert (static.kind, static.run_id, sweep.kind, sweep.run_id) == ("static", "2797rd", "sweep", "2800rd")
    measured = entry.static_runs()[0]
    np.testing.assert_array_equal(static.CT, measured.CT)  # (UIUC's measured CT, beside the model)
    r = rotor_loads(prop, params, measured.rpm * RPM, 0.0, 0.0, air=params.air, discretization=disc)
    np.testing.assert_allclose(static.CT_model, r.CT, rtol=1e-12)
    w = entry.sweeps()[2]
    n = w.rpm / 60.0
    r = rotor_loads(prop, params, 2 * math.pi * n, w.J * n * prop.diameter, 0.0, air=params.air, discretization=disc)
    np.testing.assert_allclose(sweep.CP_model, r.CP, rtol=1e-12)
    np.testing.assert_array_equal(sweep.J, w.J)
    # the calibrated set is within 0.006 of every measured CT of apce_8x6 (docs/validation.md's scale)
    assert v.summary("model")["ct_max_abs"] < 0.01


def test_run_errors_are_model_minus_measured(apce_validation):
    """Kills RU2 (measured minus model), RU3 (mean |error| for rms), RU4 (largest error, not largest |error|),
    RU5 (cp_bias of CT's errors) and RU18 (the median error for the bias)."""
    import numpy as np

    *_, v = apce_validation
    for r in v.runs:
        for which, ct, cp in (("model", r.CT_model, r.CP_model), ("hover_model", r.CT_hover, r.CP_hover)):
            e = r.errors(which)
            dct, dcp = ct - r.CT, cp - r.CP
            assert e == pytest.approx({"ct_rmse": np.sqrt(np.mean(dct**2)), "cp_rmse": np.sqrt(np.mean(dcp**2)),
                                       "ct_max_abs": np.abs(dct).max(), "cp_max_abs": np.abs(dcp).max(),
                                       "ct_bias": dct.mean(), "cp_bias": dcp.mean()}, rel=1e-12, abs=0)
    # the hover model (the static CT) over-predicts thrust at the sweeps' advance ratios: a positive bias
    s = v.summary("hover_model")
    assert s["ct_bias"] > 0.03 and s["cp_bias"] > 0.01


def test_labels_summaries_and_the_json_form(apce_validation):
    """Kills RU1 ('static ' dropped from the label), RU6 (a single run id as a string read letter by letter),
    RU7 (an unknown id among known ones ignored), RU8 (the hover model's CT given as CP) and RU9 (a sweep's
    point count one short)."""
    import numpy as np

    entry, *_, v = apce_validation
    assert v.runs[0].label == "static 2797rd"
    assert v.runs[1].label == "2798rd @ 4009 rpm"
    one = v.summary("model", "2797rd")
    assert one["n_points"] == 16 == entry.static_runs()[0].CT.size
    assert one == v.summary("model", ["2797rd"])
    with pytest.raises(ValueError, match=r"run_ids \['nope'\] name no run of apce_8x6 \(its runs: 2797rd, 2798rd"):
        v.summary("model", ["2797rd", "nope"])
    with pytest.raises(ValueError, match=r"which must be 'model' or 'hover_model', got 'hover'"):
        v.summary("hover")
    d = v.to_dict()
    assert d["hover_model"]["CT"] == pytest.approx(float(np.mean(entry.static_runs()[0].CT)), rel=1e-15)
    assert d["hover_model"]["CP"] == pytest.approx(float(np.mean(entry.static_runs()[0].CP)), rel=1e-15)
    assert [s["n_points"] for s in d["sweeps"]] == [16, 17, 17, 11, 17, 16, 17, 20]
    assert sum(s["n_points"] for s in d["sweeps"]) == d["model"]["n_points"] == 131


def test_holdout_comparison_pools_only_the_held_out_runs_once(apce_validation):
    """Kills RU14 (a duplicated held-out id kept twice), RU15 (the baseline's errors those of the fitted set)
    and RU16 (the hover model's errors pooled over every run, not the held-out ones)."""
    from propmap.validation.runs import holdout_comparison

    entry, prop, params, disc, v = apce_validation
    baseline = resolve_params("gill2017-apc")
    out = holdout_comparison(entry, prop, params, baseline, ["2804rd", "2800rd", "2804rd"], discretization=disc)
    assert out["holdout"] == ["2800rd", "2804rd"]
    assert out["fitted"] == v.summary("model", ["2800rd", "2804rd"])
    assert out["fitted"]["n_points"] == out["hover_model"]["n_points"] == out["baseline"]["n_points"] == 31
    assert out["baseline"] == out["validation_baseline"].summary("model", ["2800rd", "2804rd"])
    # the paper's Table I APC set without a fit errs more on the held-out sweeps than the calibrated set
    assert out["baseline"]["ct_rmse"] > 2 * out["fitted"]["ct_rmse"]
    assert out["hover_model"] == v.summary("hover_model", ["2800rd", "2804rd"])


# ------------------------------------------------------------------ cli/export_sim.py


def test_export_sim_json_on_stdout_the_files_on_stderr(capsys, tmp_path):
    """Kills ES4 (--points 20, the documented lower end, refused), ES5 (an upper-case .SDF refused), ES11 (the
    catalogue's citation left out) and ES14 (the 'wrote' line on stdout, after the JSON)."""
    import json

    out = tmp_path / "motor.SDF"
    code, stdout, err = run(capsys, "export-sim", "apce_8x6", "--target", "gz-sim", "--out", str(out),
                            "--points", "20", "--json")
    assert code == 0, err
    rep = json.loads(stdout)  # (stdout the JSON alone)
    assert rep["target"] == "gz-sim" and rep["check_points"] == 20
    assert "UIUC Propeller Data Site" in rep["citation"] and "APC" in rep["citation"]
    assert rep["coefficients"]["motorConstant"] > 0
    assert err.splitlines()[-1] == f"wrote {out}, {tmp_path / 'motor.report.json'}"
    assert out.is_file() and (tmp_path / "motor.report.json").is_file()


@pytest.mark.parametrize("envelope, match", [
    ("rpm=3000:6000:9000", "--envelope: 'rpm=3000:6000:9000' is not NAME=LOW:HIGH with NAME rpm, airspeed or "
                           "incidence_deg"),
    ("rpm=3000:6000,airspeed=0:5,rpm=4000:8000", "--envelope: rpm given more than once; give one range per name"),
])
def test_export_sim_envelope_forms_refused_with_one_line(capsys, tmp_path, envelope, match):
    """Kills ES1 (three numbers read as LOW:HIGH's failure to parse, not as the wrong form) and ES2 (a name given twice,
    cli.md, taken as its last range)."""
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "multinomial", "--out",
                       str(tmp_path / "c.json"), "--points", "20", "--envelope", envelope)
    assert code == 2 and err.count("\n") == 1 and match in err, err
    assert list(tmp_path.iterdir()) == []


def test_export_sim_envelope_names_any_case_and_the_hyphen():
    """Kills ES17 (incidence-deg, the map option's spelling, no longer a name) and ES18 (RPM in capitals refused)."""
    import propmap as pm
    from propmap.cli.export_sim import parse_envelope

    env = parse_envelope("RPM=3000:9000,incidence-deg=0:90, Airspeed=0:12", pm.load_propeller("apce_8x6"))
    assert tuple(env.rpm) == (3000.0, 9000.0) and tuple(env.incidence_deg) == (0.0, 90.0)
    assert tuple(env.airspeed) == (0.0, 12.0)


def test_export_sim_says_an_incidence_range_ending_at_pi_looks_like_radians(capsys, tmp_path):
    """Kills ES3 (the radians note of cli.md dropped for --envelope incidence_deg=)."""
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "multinomial", "--out",
                       str(tmp_path / "c.json"), "--points", "20", "--envelope", "incidence_deg=0:3.14")
    assert code == 0, err
    assert "--envelope incidence_deg: the incidences end at 3.14 deg: radians?" in err


def test_export_sim_refuses_an_out_named_like_a_report(capsys, tmp_path):
    """Kills ES6 (--out x.report.json, cli.md: refused since it wrote over another export's report)."""
    out = tmp_path / "x.report.json"
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "multinomial", "--out", str(out),
                       "--points", "20")
    assert code == 2 and err.count("\n") == 1, err
    assert "a name ending in .report.json is an export's report" in err
    assert list(tmp_path.iterdir()) == []


def test_export_sim_refuses_a_vehicle_hovering_beyond_tip_mach_0_8(capsys, tmp_path):
    """Kills ES9 (the tip-Mach refusal of a vehicle's hover loosened to twice 0.8): the NeuroBEM quadrotor at
    50 kg hovers at tip Mach 1.38, beyond the model's physics (docs/simulators.md), and nothing is written."""
    import re
    import shutil
    from pathlib import Path

    import propmap as pm

    examples = Path(pm.__file__).parent / "data" / "examples"
    shutil.copy(examples / "neurobem_5.1x4.8_geom.txt", tmp_path)
    text = (examples / "neurobem_quadrotor.toml").read_text().replace('params = "neurobem_quadrotor.params.toml"\n', "")
    assert "mass = 0.772" in text
    (tmp_path / "heavy.toml").write_text(text.replace("mass = 0.772", "mass = 50.0", 1))
    out = tmp_path / "h.sdf"
    code, _, err = run(capsys, "export-sim", str(tmp_path / "neurobem_5.1x4.8_geom.txt"), "--blades", "3",
                       "--target", "gz-sim", "--out", str(out), "--vehicle", str(tmp_path / "heavy.toml"),
                       "--envelope", "rpm=1000:900000", "--points", "20")
    assert code == 2, err
    assert re.fullmatch(r"propmap: error: --vehicle: it hovers at \d+ rpm, a blade tip Mach number of 1\.\d+ "
                        r"\(> 0\.8, beyond the model's physics\): is its mass \(50 kg\) in kg, and are its rotors "
                        r"the ones it flies\?\n", err), err
    assert not out.exists()
