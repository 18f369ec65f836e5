"""Property-based tests of the command line's entry points and of rotor_loads (hypothesis).

Arguments are generated (numbers of every kind: negative, zero, tiny, huge, NaN, inf, text,
empty; points files of random rows; option combinations) and the property is:

    the command exits 0 with finite numbers (or a point flagged as not converged), or exits
    2 (bad input) or 1 (a solver failure) with exactly one ``propmap: error:`` line on
    stderr; never a traceback, never a NaN printed as a result, no file left behind on
    failure, inputs unchanged.

For the API: ``rotor_loads`` returns finite loads or raises ValueError naming the argument.
Derandomized (a fixed sequence of examples, no example database), so CI is reproducible.
"""

import json
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

import propmap as pm
from propmap.cli.main import main

FUZZ = settings(derandomize=True, database=None, deadline=None, max_examples=200, print_blob=True,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])

NUMBER_TEXT = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.floats(min_value=-1e6, max_value=1e6).map(lambda x: f"{x:.6g}"),
    st.integers(-10**6, 10**400).map(str),
    st.sampled_from(["", " ", "nan", "-inf", "1e-200", "1e308", "0", "-0", "abc", "8000rpm", "1,5", "0x10", "½"]),
)


def _check(code, out, err):
    assert "Traceback" not in err and "Traceback" not in out
    errors = [line for line in err.splitlines() if line.startswith("propmap: error:")]
    if code == 0:
        assert errors == []
    else:
        assert code in (1, 2), (code, err)
        assert len(errors) == 1 and err.strip().splitlines()[-1] == errors[0], err


def _in(text, lo, hi):
    """Whether ``text`` parses (as click parses a FLOAT) to a finite number in [lo, hi]."""
    try:
        v = float(text)
    except ValueError:
        return False
    return math.isfinite(v) and lo <= v <= hi


def _mostly(lo, hi):
    """Half plausible values in [lo, hi] (so that the solver runs), half anything."""
    return st.one_of(st.floats(lo, hi).map(repr), st.sampled_from([repr(float(lo)), repr(float(hi))]), NUMBER_TEXT)


@FUZZ
@given(rpm=_mostly(1, 954929), airspeed=_mostly(0, 500), incidence=_mostly(0, 180),
       params=st.sampled_from([None, "generic", "gill2017-apc", "calibrated:apce_8x6", "gill2017-soft"]))
def test_single_point(capsys, rpm, airspeed, incidence, params):
    argv = ["loads", "apce_8x6", "--rpm", rpm, "--airspeed", airspeed, "--incidence-deg", incidence, "--json"]
    if params:
        argv += ["--params", params]
    code = main(argv)
    out, err = capsys.readouterr()
    _check(code, out, err)
    valid = _in(rpm, 1, 954929) and _in(airspeed, 0, 500) and _in(incidence, 0, 180)
    assert (code == 2) == (not valid), (code, err)  # bad input exactly when an input is out of range
    if code == 0:
        d = json.loads(out)
        assert d["converged"] is True
        for k in ("thrust", "drag", "torque", "power", "CT", "CP"):
            assert math.isfinite(d[k]), (k, d)


@FUZZ
@given(rpm=st.floats(1, 954929), airspeed=st.floats(0, 500), incidence=st.floats(0, 180),
       params=st.sampled_from([None, "generic", "gill2017-apc"]))
def test_single_point_in_range_is_always_solved(capsys, rpm, airspeed, incidence, params):
    """Every in-range point (up to the solver's limits: 954,929 rpm, 500 m/s) gets finite
    loads and exit 0 (or a solver failure, exit 1, named as such): the property above is
    not vacuous."""
    argv = ["loads", "apce_8x6", "--rpm", repr(rpm), "--airspeed", repr(airspeed), "--incidence-deg",
            repr(incidence), "--json"] + (["--params", params] if params else [])
    code = main(argv)
    out, err = capsys.readouterr()
    _check(code, out, err)
    assert code in (0, 1), err
    if code == 0:
        d = json.loads(out)
        assert all(math.isfinite(d[k]) for k in ("thrust", "drag", "torque", "rolling_moment", "power"))
    else:
        assert "root solve failed" in err


PLAUSIBLE = st.tuples(st.floats(100, 30000).map(repr), st.floats(0, 40).map(repr), st.floats(0, 180).map(repr))
ROW = st.one_of(PLAUSIBLE, PLAUSIBLE, st.tuples(NUMBER_TEXT, NUMBER_TEXT, NUMBER_TEXT),
                st.lists(NUMBER_TEXT, min_size=0, max_size=5).map(tuple))  # ragged rows too
EXTRA = st.sampled_from(["note", "thrust", "thrust_model", "CT", "RPM2", "flags"])


@FUZZ
@given(rows=st.lists(st.one_of(ROW, st.just(None)), min_size=0, max_size=12),  # None: a blank line
       sep=st.sampled_from([",", ";"]), extras=st.lists(EXTRA, max_size=2, unique=True),
       quoted=st.booleans(), upper=st.booleans(), bom=st.booleans())
def test_points_file(capsys, tmp_path_factory, rows, sep, extras, quoted, upper, bom):
    """Documented error and nothing written, or a table whose input columns come back
    unchanged, in order, one row per data row, with finite loads where converged."""
    d = tmp_path_factory.mktemp("pts")
    src = d / "in.csv"
    names = ["rpm", "airspeed", "incidence_deg"] + extras
    header = [(n.upper() if upper else n) for n in names]
    header = [f'"{h}"' if quoted else h for h in header]
    lines = [sep.join(header)]
    for r in rows:
        lines.append("" if r is None else sep.join(list(r) + ["x"] * (len(extras) if len(r) == 3 else 0)))
    text = ("\ufeff" if bom else "") + "\n".join(lines) + "\n"
    src.write_text(text, encoding="utf-8")
    dst = d / "out.csv"
    code = main(["loads", "apce_8x6", "--points", str(src), "--out", str(dst)])
    out, err = capsys.readouterr()
    _check(code, out, err)
    assert src.read_text(encoding="utf-8") == text
    if code == 0:
        import pandas as pd

        data = [r for r in rows if r is not None and any(c != "" for c in r)]  # blank rows are skipped
        table = pd.read_csv(dst, dtype=str, keep_default_na=False)
        assert len(table) == len(data)
        assert [c.lower() for c in table.columns[:len(names)]] == [n.lower() for n in names]
        for k, col in enumerate(("rpm", "airspeed", "incidence_deg")):
            np.testing.assert_array_equal(table.iloc[:, k].astype(float).to_numpy(), [float(r[k]) for r in data])
        assert len(set(table.columns)) == len(table.columns)  # no output overwrote an input column
        ok = table.iloc[:, len(names) + 8].str.lower() == "true"  # the converged column, by place
        loads = table.iloc[:, len(names):len(names) + 4].astype(float).to_numpy()
        assert np.all(np.isfinite(loads[ok.to_numpy()]))
    else:
        assert sorted(p.name for p in d.iterdir()) == ["in.csv"]


@FUZZ
@given(rpm=NUMBER_TEXT)
def test_demo_rpm_is_checked_before_any_work(capsys, tmp_path_factory, rpm):
    try:
        value = float(rpm)
    except ValueError:
        value = math.nan
    if math.isfinite(value) and 1 <= value <= 954929:
        return  # a valid rpm runs the whole demo (tests/test_cli.py runs it once)
    d = tmp_path_factory.mktemp("demo")
    code = main(["demo", "--rpm", rpm, "--out-dir", str(d / "out")])
    out, err = capsys.readouterr()
    _check(code, out, err)
    assert code == 2 and not (d / "out").exists()


@FUZZ
@given(diameter=_mostly(0.5, 100), blades=st.one_of(st.integers(1, 20).map(str), NUMBER_TEXT))
def test_geometry_file_options(capsys, shared_data, diameter, blades):
    code = main(["loads", str(shared_data / "uiuc_propdb/v1/apce_9x6_geom.txt"), "--rpm", "6000",
                 "--diameter-in", diameter, "--blades", blades, "--json"])
    out, err = capsys.readouterr()
    _check(code, out, err)
    if code == 0:
        assert math.isfinite(json.loads(out)["thrust"])


ANY = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**30, 10**30), st.booleans(),
                st.text(max_size=5), st.none(), st.lists(st.floats(-1e3, 1e4), min_size=0, max_size=3))


@FUZZ
@given(omega=ANY, airspeed=ANY, incidence=ANY)
def test_rotor_loads_finite_or_value_error_naming_the_argument(apc8x6, apc_params, omega, airspeed, incidence):
    try:
        r = pm.rotor_loads(apc8x6, apc_params, omega, airspeed, incidence, on_failure="flag")
    except ValueError as exc:
        assert any(name in str(exc) for name in ("omega", "airspeed", "incidence")), str(exc)
        return
    except pm.SolverError:  # documented: a failed root solve names the point and radius
        return
    ok = np.asarray(r.converged)
    for k in ("thrust", "drag", "torque"):
        assert np.all(np.isfinite(np.asarray(getattr(r, k))[ok])), k
    spinning = ok & (np.asarray(r.omega) > 1e-100)
    for k in ("CT", "CP"):  # referred to n: finite while the rotor turns, NaN when it is stopped (documented)
        c = np.asarray(getattr(r, k))
        assert np.all(np.isfinite(c[spinning])), k
        assert np.all(np.isnan(c[np.asarray(r.omega) == 0])), k


FIT_NAMES = ["cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2", "re_exp", "re_exp_lift", "alpha_L0_re", "cl1",
             "cl2", "cd", "alpha0", "nonsense", "", " "]


@settings(derandomize=True, database=None, deadline=None, max_examples=40, print_blob=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(M=st.one_of(st.none(), st.sampled_from(["20", "50"]), NUMBER_TEXT),
       multistart=st.one_of(st.sampled_from(["0", "1"]), NUMBER_TEXT),
       fit_params=st.one_of(st.none(), st.lists(st.sampled_from(FIT_NAMES), min_size=1, max_size=3).map(",".join)),
       quantities=st.one_of(st.none(), st.lists(st.sampled_from(["thrust", "torque", "drag", "lift", ""]),
                                                min_size=1, max_size=2).map(",".join)),
       holdout=st.one_of(st.none(), st.sampled_from(["2801rd", "2801rd,2802rd", "nosuchrun", "", ","])),
       base=st.sampled_from([None, "generic", "gill2017-apc", "nosuchset"]))
def test_fit_loads_options(capsys, tmp_path_factory, M, multistart, fit_params, quantities, holdout, base):
    d = tmp_path_factory.mktemp("fit")
    argv = ["fit", "loads", "apce_8x6", "--out", str(d / "p.toml"), "--multistart", multistart]
    for opt, v in (("--M", M), ("--fit-params", fit_params), ("--quantities", quantities), ("--holdout", holdout),
                   ("--base", base)):
        if v is not None:
            argv += [opt, v]
    code = main(argv)
    out, err = capsys.readouterr()
    _check(code, out, err)
    written = sorted(p.name for p in d.iterdir())
    if code == 0:
        assert written == ["p.png", "p.report.json", "p.report.txt", "p.toml"]
        params = pm.read_params(d / "p.toml")  # the parameters written read back as the report states them
        report = json.loads((d / "p.report.json").read_text())
        cambered = report["params"]["section_model"] == "cambered"
        for name in ("cl_alpha", "cd_min", "re_exp") if cambered else ("cl1", "cd"):
            assert getattr(params, name) == pytest.approx(report["params"][name], rel=1e-12)
    else:
        assert written == []


@settings(derandomize=True, database=None, deadline=None, max_examples=40, print_blob=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(prop=st.one_of(st.sampled_from(["apce_8x6", "ma_11x4", "apce_8x6 ", "APCE_8X6", "", "../x", "nosuch"]),
                      st.text(max_size=12)),
       params=st.one_of(st.none(), st.sampled_from(["generic", "gill2017-apc", "calibrated:nosuch", "x.toml"])),
       as_json=st.booleans())
def test_validate_single_propeller(capsys, prop, params, as_json):
    argv = ["validate", prop] + (["--params", params] if params else []) + (["--json"] if as_json else [])
    code = main(argv)
    out, err = capsys.readouterr()
    _check(code, out, err)
    if code == 0 and as_json:
        d = json.loads(out)
        assert all(math.isfinite(d["model"][k]) for k in ("ct_rmse", "cp_rmse"))


# (8 examples, 15 until 2026-12-02: each is a whole level-flight fit, 1.7 s, and CI's 15 minutes are near)
@pytest.mark.slow
@settings(derandomize=True, database=None, deadline=None, max_examples=8, print_blob=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(M=st.one_of(st.none(), st.sampled_from(["30"]), NUMBER_TEXT),
       base=st.sampled_from([None, "gill2017-apc", "generic", "nosuch"]),
       fit_params=st.one_of(st.none(), st.sampled_from(["cl2,cd", "cl1", "nonsense", "cl_alpha"])),
       body_lift=st.booleans())
def test_fit_level_flight_options(capsys, tmp_path_factory, M, base, fit_params, body_lift):
    from importlib import resources

    ex = resources.files("propmap") / "data" / "examples"
    d = tmp_path_factory.mktemp("lf")
    argv = ["fit", "level-flight", str(ex / "level_flight_synthetic.csv"), "--vehicle", str(ex / "quadrotor.toml"),
            "--out", str(d / "p.toml")]
    for opt, v in (("--M", M), ("--base", base), ("--fit-params", fit_params)):
        if v is not None:
            argv += [opt, v]
    if body_lift:
        argv.append("--body-lift")
    code = main(argv)
    out, err = capsys.readouterr()
    _check(code, out, err)
    written = sorted(p.name for p in d.iterdir())
    assert written == (["p.png", "p.report.json", "p.report.txt", "p.toml"] if code == 0 else [])


# ---- map and export-sim (issue 19): options of every kind, nothing written unless it succeeds ----

AXIS_TEXT = st.one_of(
    st.tuples(st.floats(0, 1e6).map(repr), st.floats(0, 1e6).map(repr), st.integers(-3, 6).map(str)).map(":".join),
    st.tuples(st.floats(0, 180).map(repr), st.floats(0, 180).map(repr), st.integers(2, 4).map(str)).map(":".join),
    st.sampled_from(["", ":", "1:2", "1:2:3:4", "1:2:3:log", "0:10:3:log", "a:b:c", "nan:1:3", "1:inf:3", "3:1:3",
                     "1e300:1e301:2", "0:180:2.5", "0:180:1e9", " 0 : 10 : 3 "]),
    NUMBER_TEXT)
SMALL_AXES = {"--rpm": "3000:9000:3", "--airspeed": "0:10:2", "--incidence-deg": "0:180:3"}
MAP_LIMITS = {"--rpm": (1, 954929), "--airspeed": (0, 500), "--incidence-deg": (0, 180)}


def _axis_ok(option, text):
    parts = text.split(":")
    if len(parts) == 4 and parts[3].strip().lower() == "log":
        parts = parts[:3]
    elif len(parts) != 3:
        return False
    try:
        a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
    except ValueError:
        return False
    lo, hi = MAP_LIMITS[option]
    return math.isfinite(a) and math.isfinite(b) and lo <= a < b <= hi and 2 <= n <= 6 and (
        len(text.split(":")) == 3 or a > 0)


VALID_AXIS = st.sampled_from(["0:180:2", "1000:5000:3", "0:20:4", "10:100:2:log", "0.5:1.5:2", "3000:9000:3"])
VALID_PLOT_RPM = st.sampled_from([None, "3000", "6000,9000", " 9000 "])
VALID_C_NAME = st.sampled_from([None, "rotor", "ok_name", "pm_front"])
HOSTILE_PLOT_RPM = st.one_of(st.sampled_from(["nan", "", "1e300", "-1", "abc", "6000,6001", ",", "inf"]), NUMBER_TEXT)
HOSTILE_C_NAME = st.sampled_from(["fp", "", "_x", "9x", "sig", "\u00e9", "ERR", "a b", "lc", "x" * 300])


@settings(derandomize=True, database=None, deadline=None, max_examples=30, print_blob=True,  # (50 until 2026-12-02)
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(option=st.sampled_from(list(SMALL_AXES)), data=st.data(),
       hostile=st.sampled_from(["none", "axis", "plot_rpm", "c_name"]))
def test_map_options(capsys, tmp_path_factory, option, data, hostile):
    """exit 0 with the map, sidecar and plots written, or exit 2 (one line) with nothing
    written; a valid axis is built, an invalid one refused. One option at a time is drawn
    from hostile values (or none), the others from valid ones."""
    axis = data.draw(AXIS_TEXT if hostile == "axis" else VALID_AXIS, "axis")
    plot_rpm = data.draw(HOSTILE_PLOT_RPM if hostile == "plot_rpm" else VALID_PLOT_RPM, "plot_rpm")
    c_name = data.draw(HOSTILE_C_NAME if hostile == "c_name" else VALID_C_NAME, "c_name")
    d = tmp_path_factory.mktemp("map")
    axes = {**SMALL_AXES, option: axis}
    fmt = ["--format", "c", "--c-name", c_name] if c_name is not None else []
    out = d / ("m.h" if c_name is not None else "m.nc")
    argv = ["map", "apce_8x6", *[x for kv in axes.items() for x in kv], "--check-points", "0", "--out", str(out),
            *fmt] + (["--plot", str(d / "p"), "--plot-rpm", plot_rpm] if plot_rpm is not None else [])
    code = main(argv)
    text, err = capsys.readouterr()
    _check(code, text, err)
    event(f"exit {code}")
    written = sorted(str(p.relative_to(d)) for p in d.rglob("*") if p.is_file())
    if code == 0:
        assert _axis_ok(option, axis), (axis, err)
        assert {out.name, out.name + ".json"} <= set(written)
        from propmap.maps import read_sidecar

        assert read_sidecar(out)["describes"]["file"] == out.name
    else:
        assert code == 2 and written == [], (written, err)


ENVELOPE_ITEM = st.tuples(st.sampled_from(["rpm", "airspeed", "incidence_deg", "incidence-deg", "speed", ""]),
                          st.one_of(st.tuples(st.floats(0, 2e4).map(repr), st.floats(0, 2e4).map(repr))
                                    .map(":".join), st.sampled_from(["0:1e-300", "0:1e-9", "30:40", "1:2:3", "a:b",
                                                                     "", ":", "nan:1", "0:inf"]))).map("=".join)


@settings(derandomize=True, database=None, deadline=None, max_examples=40, print_blob=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture,
                                 HealthCheck.filter_too_much])
@given(target=st.sampled_from(["rotorpy", "gazebo-classic", "gz-sim", "multinomial", "gazebo"]), data=st.data(),
       hostile=st.sampled_from(["none", "envelope", "points"]))
def test_export_sim_options(capsys, tmp_path_factory, target, data, hostile):
    """exit 0 with finite coefficients (a fixed one said on stderr) and the file and its
    report, or exit 2 (one line) with nothing written. Degenerate envelopes (airspeed to
    1e-300, incidence to 1e-9, all |V_z| >= 25 m/s, all in the vortex ring) among the valid
    ones; one option at a time drawn from hostile values."""
    envelope = data.draw(st.lists(ENVELOPE_ITEM, min_size=0, max_size=3).map(",".join) if hostile == "envelope" else
                         st.sampled_from([None, "rpm=4000:9000", "airspeed=0:10,incidence_deg=0:90",
                                          "airspeed=0:1e-300", "incidence_deg=0:1e-9", "airspeed=30:40",
                                          "rpm=5000:6000,airspeed=2:4,incidence_deg=170:180"]), "envelope")
    # valid counts kept small (each point is a model solve)
    points = data.draw(NUMBER_TEXT.filter(lambda t: not (t.isdigit() and 100 < int(t) <= 1_000_000))
                       if hostile == "points" else st.sampled_from(["20", "40", "100"]), "points")
    d = tmp_path_factory.mktemp("sim")
    out = d / {"rotorpy": "c.py", "multinomial": "c.json"}.get(target, "c.sdf")
    argv = ["export-sim", "apce_8x6", "--target", target, "--out", str(out), "--points", points, "--json"]
    if envelope is not None:
        argv += ["--envelope", envelope]
    code = main(argv)
    text, err = capsys.readouterr()
    _check(code, text, err)
    event(f"exit {code}")
    written = sorted(p.name for p in d.iterdir())
    if code == 0:
        d_out = json.loads(text)
        values = [v for c in d_out["coefficients"].values() for v in (c if isinstance(c, list) else [c])]
        assert all(math.isfinite(v) for v in values), d_out
        for name in d_out["fixed_at_zero"]:
            assert f"propmap: warning: {name} fixed at 0" in err
        for name in d_out["held_at_sign_bound"]:
            assert f"propmap: warning: {name} held at 0, the bound of its physical sign" in err
        assert written == sorted([out.name, out.stem + ".report.json"])
    else:
        assert code == 2 and written == [], (written, err)
