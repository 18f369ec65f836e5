"""Every command's --json output carries the run's warnings (``warnings``), as standard error says
them: a script reading the JSON saw none of them (noticed since stop 99, done 2026-12-02)."""

from __future__ import annotations

import json
import shutil
import warnings
from pathlib import Path

import pytest

import propmap as pm
from tests.cli_helpers import example_quad, run
from tests.test_simexport import _vehicle_toml

PREFIX = "propmap: warning: "


def _said(err: str) -> list[str]:
    return [line[len(PREFIX):] for line in err.splitlines() if line.startswith(PREFIX)]


@pytest.mark.parametrize("argv, expect", [
    # a propeller known only by its size: the nominal blade's warning (and no other)
    (["loads", "9x4.5", "--rpm", "6000", "--json"], ["nominal blade"]),
    # beyond the calibrated set's data: the advance ratio, the rpm
    (["loads", "apce_8x6", "--rpm", "1000", "--airspeed", "15", "--json"], ["advance ratio", "rpm"]),
    (["trim", "5x4.5x3", "--thrust", "2", "--airspeed", "3", "--json"], ["nominal blade"]),
    # none: an empty list, not a missing key
    (["loads", "apce_8x6", "--rpm", "5000", "--airspeed", "5", "--json"], []),
])
def test_the_json_warnings_are_the_lines_standard_error_says(capsys, argv, expect):
    code, out, err = run(capsys, *argv)
    assert code == 0, err
    record = json.loads(out)
    assert record["warnings"] == _said(err)
    assert len(record["warnings"]) >= len(expect)
    for word in expect:
        assert any(word in w for w in record["warnings"]), (word, record["warnings"])
    assert all("\n" not in w for w in record["warnings"])


def test_a_vehicle_files_warnings_reach_trim_vehicles_json(tmp_path, capsys):
    """A library warning (the vehicle file's, raised while it is read, printed at the run's end) is
    in the JSON once, in the order the warnings arose: before the trim's own, which standard error
    says first."""
    path = example_quad(tmp_path, first_propeller="9x6")
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", path, "--airspeed", "0,4", "--json")
    assert code == 0, err
    got, said = json.loads(out)["warnings"], _said(err)
    assert sorted(got) == sorted(said) and len(got) == len(set(got)) >= 2
    # the nominal blade's (the vehicle file's, read first) and the trim's incidence beyond the set's data
    order = [[next(k for k, w in enumerate(ws) if word in w) for word in ("nominal blade", "incidence up to")]
             for ws in (got, said)]
    assert order[0][0] < order[0][1] and order[1][0] > order[1][1], order


def test_a_fits_report_gives_the_runs_warnings_then_its_own(tmp_path, capsys, shared_data):
    """fit loads: the nominal blade's warning (the run's) and the fit's own, in the printed JSON
    and in the .report.json beside the parameters (UIUC vol. 1 apce_8x6, fitted as a nominal 8x6)."""
    files = sorted((shared_data / "uiuc_propdb" / "v1").glob("apce_8x6_*.txt"))
    code, out, err = run(capsys, "fit", "loads", *files, "--prop", "8x6", "--out", tmp_path / "p.toml", "--json")
    assert code == 0, err
    printed = json.loads(out)
    written = json.loads((tmp_path / "p.report.json").read_text())
    assert printed["warnings"] == written["warnings"]
    assert any("nominal blade" in w for w in printed["warnings"])
    said = [w for w in _said(err) if " more in p.report.txt" not in w]
    assert set(said) <= set(printed["warnings"]), set(said) - set(printed["warnings"])
    assert len(printed["warnings"]) == len(set(printed["warnings"]))


def test_map_and_validate_give_theirs(tmp_path, capsys, shared_data):
    """map (a grid beyond the calibrated set's data) and validate (UIUC vol. 1 apce_8x6's static run
    against a nominal 8x6): the JSON's warnings are standard error's."""
    grid = ["--rpm", "1000:3000:2", "--airspeed", "0:20:2", "--incidence-deg", "0:90:2", "--check-points", "50"]
    static = shared_data / "uiuc_propdb" / "v1" / "apce_8x6_static_2797rd.txt"
    # (the coarse map misses its targets: a warning said after the JSON until 2026-12-02, a review)
    for argv, word in ((["map", "apce_8x6", *grid, "--out", tmp_path / "m.nc"], "the map misses the targets"),
                       (["validate", static, "--prop", "8x6"], "nominal blade")):
        code, out, err = run(capsys, *argv, "--json")
        assert code == 0, err
        got = json.loads(out)["warnings"]
        assert got == _said(err) and any(word in w for w in got), (argv[0], got)


def _fit_result(own: tuple):
    """A load fit's result (apce_8x6's model-made static loads, two evaluations) whose own warnings are ``own``."""
    import dataclasses

    import numpy as np

    from propmap.identify import FitOptions, LoadData, fit_loads

    prop = pm.load_propeller("apce_8x6")
    omega = np.linspace(4000.0, 8000.0, 6) * np.pi / 30
    r = pm.rotor_loads(prop, pm.generic_params(), omega, 0.0, 0.0)
    data = LoadData(omega, np.zeros(6), np.zeros(6), {"thrust": r.thrust, "torque": r.torque},
                    np.full(6, "all", dtype=object), "model-made")
    return dataclasses.replace(fit_loads(data, prop, options=FitOptions(max_nfev=2)), warnings=own)


def _in_a_run(monkeypatch, said=()):
    """The warnings' record as cli.main's run of a command leaves it, with ``said`` (index, text) pairs."""
    from propmap.cli import _common

    monkeypatch.setitem(_common.RUN_WARNINGS, "active", True)
    monkeypatch.setitem(_common.RUN_WARNINGS, "said", list(said))
    monkeypatch.setitem(_common.RUN_WARNINGS, "caught", [])


def test_a_warning_said_while_the_figures_are_drawn_is_in_the_fits_report(tmp_path, capsys, monkeypatch):
    """A fit's figures are drawn before its report is written, so that a warning they give (fit flight's speed
    figure with nothing to draw: tests/test_stop104.py) is in the report's warnings, before the fit's own (a
    review of 2026-12-02 found it on standard error only)."""
    from propmap.cli._common import warn
    from propmap.cli.fit import _write_outputs

    res = _fit_result(("the fit's own",))
    _in_a_run(monkeypatch)

    def figure(png):
        warn("the speed figure is not drawn: an example")
        return (".png",)

    _write_outputs(res, tmp_path / "p.toml", "generic", True, figure=figure)
    out, err = capsys.readouterr()
    want = ["the speed figure is not drawn: an example", "the fit's own"]
    assert json.loads(out)["warnings"] == want == json.loads((tmp_path / "p.report.json").read_text())["warnings"]
    assert _said(err) == want


def test_a_runs_warnings_do_not_outlive_it(capsys):
    """run_warnings() is empty once cli.main's run has ended (a command function called directly later, as tests
    do, got the last run's warnings in its report: a review)."""
    from propmap.cli._common import RUN_WARNINGS, run_warnings

    code, _, err = run(capsys, "loads", "9x4.5", "--rpm", "6000")
    assert code == 0 and "nominal blade" in err
    assert run_warnings() == [] and RUN_WARNINGS["said"] == [] and not RUN_WARNINGS["active"]


# ---- a mutation audit's cases (2026-12-02): what the tests above let through -------------------------------------

def test_export_sims_warnings_are_listed_in_the_order_they_arose(tmp_path, capsys):
    """A warn() line (the rotors' interference), a library warning (the hover beyond RotorPy's limits: stderr says it
    last) and the coverage's, in that order: the library's were listed before the command's."""
    p = Path(_vehicle_toml(tmp_path / "v.toml", 4))
    p.write_text(p.read_text().replace("mass = 1.0", "mass = 6.0\nrotor_interference = 1.0"))
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--target", "rotorpy", "--out", tmp_path / "v.py",
                         "--vehicle", p, "--points", "300", "--json")
    assert code == 0, err
    got, said = json.loads(out)["warnings"], _said(err)
    assert sorted(got) == sorted(said)
    at = [next(k for k, w in enumerate(got) if w.startswith(start))
          for start in ("--vehicle: its rotors' interference", "--vehicle: it hovers at", "incidence up to")]
    assert at == sorted(at), (at, got)


def test_a_warning_raised_twice_is_listed_once(tmp_path, capsys):
    """PROP 9x6 and the vehicle's 9x6 rotors each raise the nominal blade's warning."""
    q = _vehicle_toml(tmp_path / "q.toml", 4, prop="9x6")
    code, out, err = run(capsys, "export-sim", "9x6", "--target", "rotorpy", "--out", tmp_path / "q.py",
                         "--vehicle", q, "--points", "300", "--json")
    assert code == 0, err
    got = json.loads(out)["warnings"]
    assert got == _said(err) and sum("nominal blade" in w for w in got) == 1


def test_a_warning_quoting_a_path_with_a_line_break_is_one_line(tmp_path, capsys):
    """A parameter file in a folder whose name holds a line break, quoted by the coverage warnings: one line on
    standard error (it was two) and in the JSON."""
    folder = tmp_path / "a\nb"
    folder.mkdir()
    shutil.copy(pm.example_file("neurobem_quadrotor.params.toml"), folder / "p.toml")
    code, out, err = run(capsys, "loads", "apce_8x6", "--params", folder / "p.toml", "--rpm", "30000", "--airspeed",
                         "25", "--json")
    assert code == 0, err
    got = json.loads(out)["warnings"]
    assert got == _said(err) and any("a b/p.toml" in w for w in got), got


def test_other_warnings_are_neither_said_nor_listed(capsys, monkeypatch):
    """Another module's UserWarning, and a RuntimeWarning raised in propmap's own code."""
    import propmap.core.solver as solver

    real = solver.rotor_loads

    def rotor_loads(*args, **kwargs):
        warnings.warn("a foreign library's UserWarning", UserWarning)  # (from this file: not propmap's)
        warnings.warn("a RuntimeWarning in propmap's code", RuntimeWarning, stacklevel=2)  # (cli/loads.py's)
        return real(*args, **kwargs)

    monkeypatch.setattr(solver, "rotor_loads", rotor_loads)
    code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", "--airspeed", "5", "--json")
    assert code == 0, err
    assert json.loads(out)["warnings"] == [] and "foreign" not in err and "RuntimeWarning" not in err, err


def test_outside_a_run_nothing_is_kept_or_listed(monkeypatch, capsys):
    from propmap.cli._common import RUN_WARNINGS, run_warnings, warn, with_warnings

    warn("said outside a run")
    assert RUN_WARNINGS["said"] == [] and "said outside a run" in capsys.readouterr().err
    monkeypatch.setitem(RUN_WARNINGS, "said", [(0, "stale")])
    assert run_warnings() == [] and with_warnings({})["warnings"] == []


def test_a_fits_own_warning_already_said_is_in_its_report_once(tmp_path, capsys, monkeypatch):
    from propmap.cli._common import warn
    from propmap.cli.fit import _write_outputs

    res = _fit_result(("twice  said", "own", "own"))
    _in_a_run(monkeypatch)
    warn("twice said")
    _write_outputs(res, tmp_path / "p.toml", "generic", True)
    assert json.loads((tmp_path / "p.report.json").read_text())["warnings"] == ["twice said", "own"]


def test_a_records_own_warnings_are_kept(monkeypatch):
    """with_warnings adds the run's to a record without them (export-sim's report, written with them, keeps its)."""
    from propmap.cli._common import with_warnings

    _in_a_run(monkeypatch, said=[(0, "later")])
    assert with_warnings({"warnings": ["as written"]}) == {"warnings": ["as written"]}
    assert with_warnings({"a": 1}) == {"a": 1, "warnings": ["later"]}
