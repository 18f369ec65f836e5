"""A mutation audit of ``propmap map`` (cli/map.py), ``propmap map --check`` (cli/map_check.py) and
``propmap props`` (cli/props.py): the axes' ranges, the refusals, what a map file and a check say,
and the catalogue listing, each pinned by a number, a message or a file the command writes."""

import dataclasses
import json
import math

import numpy as np
import pytest
from cli_helpers import one_line_error, run

import propmap as pm
from propmap.cli.main import main
from propmap.cli.map import _catalogue_summary
from propmap.cli.map_check import _pct
from propmap.io.calibration import calibrated
from propmap.io.catalogue import catalogue
from propmap.io.params_file import write_params
from propmap.maps import RotorMap, default_axes

TINY = ["--rpm", "3000:9000:5", "--airspeed", "0:15:2", "--incidence-deg", "0:90:2", "--check-points", "0"]
# an error raised after the axes are parsed (a --plot-rpm off the rpm axis): nothing is built
LATE_ERROR = ["--plot", "plots", "--plot-rpm", "1"]


def refused(capsys, tmp_path, monkeypatch, *argv):
    """Run ``propmap ARGV`` in an empty folder; (exit code, stderr), after checking that nothing was written."""
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert list(tmp_path.iterdir()) == []
    return code, err


@pytest.fixture(scope="module")
def checked_map(tmp_path_factory):
    """apce_8x6 on a 5 x 3 x 5 grid with 40 stored check points: the map file."""
    out = tmp_path_factory.mktemp("map") / "m.nc"
    code = main(["map", "apce_8x6", "--rpm", "3000:9000:5", "--airspeed", "0:15:3", "--incidence-deg",
                 "0:180:5", "--check-points", "40", "--out", str(out)])
    assert code == 0
    return out


# --- the axes ---------------------------------------------------------------------------------------------

def test_an_axis_whose_start_equals_its_stop_is_refused(capsys, tmp_path, monkeypatch):
    """Mutant M1: ``lo <= a < b <= hi`` relaxed to ``a <= b`` (a constant axis) was not caught."""
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--rpm", "3000:3000:5")
    assert one_line_error(code, err, "--rpm: need 1 <= start < stop <= 954929 rpm, got 3000:3000"), err


def test_an_axis_of_more_than_2000_values_is_refused(capsys, tmp_path, monkeypatch):
    """Mutant M3: MAX_AXIS 2000 -> 20000 (a count of 2001 accepted) was not caught."""
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--airspeed", "0:25:2001",
                        *LATE_ERROR)
    assert one_line_error(code, err, "--airspeed: count must be in [2, 2000], got 2001"), err


def test_a_geometric_airspeed_axis_from_zero_is_refused(capsys, tmp_path, monkeypatch):
    """Mutant M4: ``a <= 0`` -> ``a < 0`` (geomspace from 0 m/s let through) was not caught."""
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--airspeed", "0:25:5:log")
    assert one_line_error(code, err, "--airspeed: a geometric axis needs start > 0, got 0"), err


def test_airspeeds_up_to_500_m_per_s_are_taken(capsys, tmp_path, monkeypatch):
    """Mutant M19: the airspeed bound 500 -> 50 m/s was not caught: 0:60:3 passes the axis check
    (the run stops later, at the --plot-rpm off the axis), and 0:501:3 does not."""
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--airspeed", "0:60:3",
                        *LATE_ERROR)
    assert one_line_error(code, err, "--plot-rpm: 1 is outside the map's rpm axis"), err
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--airspeed", "0:501:3")
    assert one_line_error(code, err, "--airspeed: need 0 <= start < stop <= 500 m/s, got 0:501"), err


def test_a_geometric_rpm_axis_is_geometric_in_the_map(capsys, tmp_path):
    """Mutant M5: ``:log`` ignored (a linear axis) was not caught: the nodes are 1000, 2000, 4000 rpm."""
    out = tmp_path / "g.nc"
    code, _, err = run(capsys, "map", "apce_8x6", "--rpm", "1000:4000:3:log", *TINY[2:], "--out", out)
    assert code == 0, err
    np.testing.assert_allclose(RotorMap.open(out).dataset["rpm"].values, [1000.0, 2000.0, 4000.0], rtol=1e-12)


@pytest.mark.parametrize("stop, warned", [("1.5708", True), ("3.1416", True), ("1.6", False), ("3.1", False)])
def test_an_incidence_range_ending_at_half_pi_is_called_radians(capsys, tmp_path, monkeypatch, stop, warned):
    """Mutants M6 (only pi checked, not pi / 2) and M7 (tolerance 0.005 -> 0.05: 1.6 and 3.1 deg
    called radians) were not caught."""
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "map", "apce_8x6", "--out", "m.nc", "--incidence-deg", f"0:{stop}:3", *LATE_ERROR)
    assert code == 2 and "--plot-rpm: 1 is outside" in err
    assert (f"--incidence-deg: the incidences end at {stop} deg: radians?" in err) is warned, err


# --- refusals -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("argv, match", [
    (["map", "apce_8x6", "--out", "m.nc", "--max-error-pct", "5", *LATE_ERROR], "--max-error-pct applies to --check"),
    (["map", "apce_8x6", "--out", "m.nc", "--props", "apce_8x6", *LATE_ERROR], "--props applies to --all"),  # M10
    (["map", "apce_8x6", "--out", "m.nc", "--check-points", "1000001", *LATE_ERROR],
     "--check-points must be in [0, 1000000], got 1000001"),  # M11
    (["map", "apce_8x6", "--out", "m.nc", *TINY, "--plot-rpm", "6000"], "--plot-rpm applies to --plot"),  # M14
    (["map", "--all", "--props", "apce_8x6,nosuch_9x9", "--out", "m.nc"],
     "--props: unknown propeller(s) nosuch_9x9"),  # M22
    (["map", "apce_8x6", "--out", "m.nc", *TINY, "--plot", "p", "--plot-rpm", "3000,3000.1"],
     "--plot-rpm: 3000.1 falls on the node 3000 rpm of another value"),  # M24, M25
])
def test_options_that_do_not_apply_or_are_out_of_range_are_refused(capsys, tmp_path, monkeypatch, argv, match):
    """Mutants M8 (--max-error-pct without --check), M10 (--props without --all), M11 (--check-points
    bound 10^6 -> 10^7), M14 (--plot-rpm without --plot), M22 (an unknown --props name), M24 (a
    --plot-rpm at the axis' first node refused) and M25 (two --plot-rpm on one node) were not caught."""
    code, err = refused(capsys, tmp_path, monkeypatch, *argv)
    assert one_line_error(code, err, match), err


def test_a_collective_summing_to_exactly_30_deg_is_taken(capsys, tmp_path, monkeypatch):
    """Mutant M16: ``abs(total) <= limit`` -> ``<`` (the documented bound 30 deg refused) was not caught;
    30.001 deg is refused."""
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--collective-deg", "30",
                        *LATE_ERROR)
    assert one_line_error(code, err, "--plot-rpm: 1 is outside"), err
    code, err = refused(capsys, tmp_path, monkeypatch, "map", "apce_8x6", "--out", "m.nc", "--collective-deg",
                        "-30.001", *LATE_ERROR)
    assert one_line_error(code, err, "--collective-deg: the parameter set's collective 0 deg plus -30.001 deg must be "
                                     "within [-30, 30] deg"), err


def test_a_parameter_sets_collective_is_added_to_the_option(capsys, tmp_path):
    """Mutants M17 (the set's collective left out of the range check) and M18 (the map built at the
    option's collective alone, not the sum) were not caught: a set at 3 deg plus 2 deg maps at 5 deg."""
    f = tmp_path / "c.toml"
    write_params(f, dataclasses.replace(pm.default_params("apce_8x6"), collective=math.radians(3.0)))
    code, _, err = run(capsys, "map", "apce_8x6", "--params", f, "--collective-deg", "28", "--out", tmp_path / "x.nc")
    assert one_line_error(code, err, "the parameter set's collective 3 deg plus 28 deg must be within [-30, 30] deg, "
                                     "got 31"), err
    out = tmp_path / "m.nc"
    code, _, err = run(capsys, "map", "apce_8x6", "--params", f, "--collective-deg", "2", *TINY, "--out", out)
    assert code == 0, err
    rm = RotorMap.open(out)
    om = 6000 * math.pi / 30
    ref = pm.rotor_loads(pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6"), om, 0.0, 0.0,
                         collective=math.radians(5.0))
    assert rm.loads(om, 0.0, 0.0).thrust == pytest.approx(float(ref.thrust), rel=1e-9)


# --- what a build writes ----------------------------------------------------------------------------------

def test_an_upper_case_suffix_is_taken_and_the_default_contour_is_the_middle_rpm(capsys, tmp_path):
    """Mutants M15 (the suffix compared case-sensitively: M.NC refused) and M26 (the default contour
    map at the first rpm node, not the middle one) were not caught."""
    out = tmp_path / "M.NC"
    code, _, err = run(capsys, "map", "apce_8x6", *TINY, "--out", out, "--plot", tmp_path / "plots")
    assert code == 0, err
    assert RotorMap.open(out).dataset["rpm"].values.tolist() == [3000.0, 4500.0, 6000.0, 7500.0, 9000.0]
    assert [p.name for p in (tmp_path / "plots").iterdir()] == ["map_contours_6000rpm.png"]


def test_a_c_headers_missed_targets_are_said_for_its_linear_interpolation(capsys, tmp_path):
    """Mutant M28: the warning of a linear C header measured with the cubic errors (``method = "cubic"``)
    was not caught: the header interpolates linearly, and the warning says so."""
    code, out, err = run(capsys, "map", "apce_8x6", *TINY[:-1], "40", "--format", "c", "--out", tmp_path / "m.h")
    assert code == 0 and "this C header interpolates linear)" in out
    assert "the map misses the targets at its check points (linear, outside flagged regions" in err, err


def test_map_all_default_axes_follow_the_median_diameter(capsys, tmp_path):
    """Mutant M23: the shared grid's default axes from the smallest propeller instead of the median
    one was not caught: three APC props, the rpm axis is apce_10x7's default."""
    out = tmp_path / "all.nc"
    code, _, err = run(capsys, "map", "--all", "--props", "apce_8x6,apce_10x7,apce_11x7", "--airspeed", "0:5:2",
                       "--incidence-deg", "0:90:2", "--check-points", "0", "--out", out)
    assert code == 0, err
    want = default_axes(pm.load_propeller("apce_10x7"))[0]
    assert want[0] != default_axes(pm.load_propeller("apce_8x6"))[0][0]
    np.testing.assert_allclose(RotorMap.open(out, prop="apce_8x6").dataset["rpm"].values, want, rtol=1e-12)


def test_the_catalogue_summary_ranks_a_miss_by_its_ratio_to_its_target():
    """Mutant M31: the worst load of a propeller picked by its error in % rather than by the error over
    its target (drag's is 2%) was not caught: torque 1.5% (1.5 x its target) beats drag 2.5% (1.25 x)."""
    per = {"a": {"check_cubic_thrust_max": 0.001, "check_cubic_torque_max": 0.015, "check_cubic_drag_max": 0.025}}
    assert "worst a torque 1.5%" in _catalogue_summary(json.dumps(per))
    # drag's target is 2%: 1.5% of the largest drag is no miss (C5: a drag target of 1%)
    ok = {"check_cubic_thrust_max": 0.001, "check_cubic_torque_max": 0.001, "check_cubic_drag_max": 0.015}
    assert _catalogue_summary(json.dumps({"a": ok})).startswith("every one of the 1 checked propellers' maps meets")


# --- map --check ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("option, value, match", [
    ("--check-points", "0", "--check-points must be in [1, 1000000] with --check, got 0"),  # C1
    ("--max-error-pct", "0", "--max-error-pct must be in (0, 100], got 0.0"),  # C2
    ("--max-error-pct", "150", "--max-error-pct must be in (0, 100], got 150.0"),  # C3
    ("--props", "apce_8x6", "m.nc is a map of one propeller; --props applies to a map over several"),  # C10
])
def test_check_options_out_of_range_are_refused(capsys, checked_map, option, value, match):
    """Mutants C1 (0 check points taken), C2 (a 0% threshold taken), C3 (a threshold up to 1000%)
    and C10 (--props taken with a map of one propeller) were not caught."""
    code, _, err = run(capsys, "map", "--check", checked_map, option, value)
    assert one_line_error(code, err, match), err


def test_check_draws_fresh_points_and_applies_its_thresholds(capsys, checked_map):
    """Mutants C4 (default threshold 2%), C6 (the stored check's seed reused: no fresh points),
    C7 (drag not given twice the threshold), C8 (the threshold taken as a fraction, not %) and C16
    (the verdict's drag threshold printed as 1x) were not caught."""
    code, text, _ = run(capsys, "map", "--check", checked_map, "--check-points", "30", "--json",
                        "--max-error-pct", "100")
    first = json.loads(text)
    stored_seed = RotorMap.open(checked_map).attrs["check_seed"]
    assert code == 0 and first["recomputed"]["check_seed"] == int(stored_seed) + 1
    rec = first["recomputed"]
    thrust, drag = rec["check_cubic_thrust_max"], rec["check_cubic_drag_max"]
    assert thrust > 0 and drag > 0
    # thrust at half its error: a miss; drag at 0.75 of its error: within twice the threshold
    limit = 50 * thrust
    code, text, _ = run(capsys, "map", "--check", checked_map, "--check-points", "30", "--json",
                        "--max-error-pct", f"{limit!r}")
    assert code == 3 and "thrust" in json.loads(text)["exceeded"]
    limit = 75 * drag
    code, text, _ = run(capsys, "map", "--check", checked_map, "--check-points", "30", "--json",
                        "--max-error-pct", f"{limit!r}")
    assert "drag" not in json.loads(text)["exceeded"]
    code, text, _ = run(capsys, "map", "--check", checked_map, "--check-points", "30", "--json")
    assert json.loads(text)["max_error_pct"] == 1.0
    code, text, _ = run(capsys, "map", "--check", checked_map, "--check-points", "30", "--max-error-pct", "50")
    assert code == 0 and ("threshold: cubic max outside flagged regions <= 50% of static thrust and torque, 100% of "
                          "the largest drag: passed") in text


def test_a_percentage_past_1000_is_given_to_three_figures():
    """Mutant C15: the switch to three figures moved from 1000% to 10000% was not caught."""
    assert (_pct(12.3456), _pct(9.87654), _pct(float("nan"), 6)) == ("1.23e+03%", "987.654%", "   n/a")


# --- props ----------------------------------------------------------------------------------------------

def test_props_rows_carry_the_catalogue_and_calibration_values(capsys):
    """Mutants P2 (static runs counted as sweeps), P3 (the table's fit rms as a fraction, not %),
    P4 (fit_rms_cp given CT's) and P7 (the citation replaced) were not caught."""
    code, out, _ = run(capsys, "props", "--json")
    rows = {r["name"]: r for r in json.loads(out)}
    c, entry = calibrated("apce_8x6"), catalogue()["apce_8x6"]
    row = rows["apce_8x6"]
    assert code == 0 and (row["static_runs"], row["sweeps"]) == (1, 7)
    assert row["fit_rms_cp"] == c.rms_cp != c.rms_ct
    assert row["citation"] == entry.citation and "Brandt & Selig, AIAA 2011-1255" in row["citation"]
    code, out, _ = run(capsys, "props")
    line = next(s for s in out.splitlines() if s.startswith("apce_8x6 "))
    assert line.split()[-3:] == ["yes", f"({100 * c.rms_ct:.1f}%,", f"{100 * c.rms_cp:.1f}%)"] == ["yes", "(2.7%,",
                                                                                                   "2.7%)"]
