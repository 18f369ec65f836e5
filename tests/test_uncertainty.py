"""The model's own uncertainty attached to maps and exports: what each kind of parameter set
states, its figures held to docs/validation.md, and where it is written."""

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.export_c import c_header_text
from propmap.io.uncertainty import AXIAL_VALIDATION, model_uncertainty
from propmap.maps import RotorMap, build_map
from propmap.simexport import Envelope, export_sim, write_export

DOCS = Path(__file__).resolve().parents[1] / "docs"
RPM = math.pi / 30


def _pct(t):
    return " / ".join(f"{100 * v:.1f}" for v in t) + "%"


def test_figures_are_those_of_docs_validation():
    """The stated cross-validated errors are docs/validation.md's (all 143 propellers together)."""
    text = " ".join((DOCS / "validation.md").read_text().split())
    assert f"leave one sweep out {_pct(AXIAL_VALIDATION['calibrated']['ct'])} (CP " \
           f"{_pct(AXIAL_VALIDATION['calibrated']['cp'])})" in text
    assert f"blind {_pct(AXIAL_VALIDATION['generic']['ct'])}" in text
    assert f"the paper's Table I without a fit {_pct(AXIAL_VALIDATION['paper']['ct'])}" in text


@pytest.mark.parametrize("label, expect", [
    ("calibrated:apce_8x6", "leave one sweep out"), ("generic", "blind"), ("generic without apce", "blind"),
    ("gill2017-apc", "Table I"), ("section:naca0012", "not validated on propellers"),
    ("my_fit.toml", "its own fit report"), ("something", "unknown"),
])
def test_each_kind_of_set_says_what_is_known(label, expect):
    u = model_uncertainty(label)
    assert expect in u["axial"] and u["params"] == label
    assert u["off_axis"].startswith("not validated at incidence")
    assert ("axial_ct" in u) == (label.split(":")[0] in ("calibrated", "generic", "generic without apce",
                                                         "gill2017-apc"))
    if label == "calibrated:apce_8x6":  # its own in-sample figure (data/calibration.json)
        assert 0.01 < u["in_sample_rms_ct"] < 0.05 and "in-sample rms CT error" in u["axial"]


def test_maps_and_their_c_header_carry_it_and_the_header_stays_a_comment():
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.array([4000.0, 6000.0, 8000.0]) * RPM, np.array([0.0, 5.0, 10.0]),
                   np.radians([0.0, 90.0, 180.0]), air=params.air, params_label=params.label, n_check=0)
    assert ds.attrs["model_uncertainty_axial"] == model_uncertainty(params.label)["axial"]
    assert "not validated at incidence" in ds.attrs["model_uncertainty_off_axis"]
    rm = RotorMap(ds)
    text = c_header_text(rm, Path("m.h"))
    opening = text[:text.index("*/")]
    assert "The model against measurements: axial: cross-validated" in " ".join(opening.split())
    # an edited map's text cannot close the comment and inject code into the header
    ds2 = ds.copy()
    ds2.attrs["params_label"] = "x */ int injected; /* y"
    ds2.attrs["model_uncertainty_off_axis"] = "z */ int also; /*"
    text2 = c_header_text(RotorMap(ds2), Path("m.h"))
    first = text2.index("*/")
    assert "int injected" in text2[:first] and "int also" in text2[:first]  # still inside the opening comment


def test_exports_report_it_with_the_sets_forward_flight_spread(tmp_path):
    """The export states the set's and the generic set's thrust change edgewise beside the axial figures (issue
    17: the calibrated apce_8x6 lost thrust, -6.8% against the generic set's +5.2% at 8000 rpm, 15 m/s; with the
    stall blend M = 12 calibration of 2026-11-24 both gain, +1.4% and +6.8%, as the wind tunnel's apce_8x6 does,
    docs/validation.md, case gill2019; with the skewed wake's in-plane induction, the cambered default since
    2026-11-25, +3.2% and +8.8%)."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 15.0), incidence_deg=(0.0, 120.0), hover_rpm=8000.0)
    res = export_sim("gz-sim", prop, params, envelope=env, n_points=100, params_label=params.label)
    u = res.meta["model_uncertainty"]
    t = u["edgewise_trend"]
    assert t["rpm"] == 8000.0 and t["airspeed"] == 15.0
    assert 0.02 < t["this_set"] < 0.045 and 0.07 < t["generic"] < 0.11  # regression values (2026-11-25)
    path, report = write_export(res, tmp_path / "m.sdf")
    assert re.search(r"thrust change from hover to 15 m/s edgewise at 8000 rpm: \+\d\.\d% with this set, "
                     r"\+\d\.\d% with the generic set", path.read_text())
    assert json.loads(report.read_text())["model_uncertainty"]["axial_ct"] == list(AXIAL_VALIDATION["calibrated"]["ct"])
