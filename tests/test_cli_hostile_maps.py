"""map, export-sim, validate --all and the fit options under hostile use: regression tests
of issue 19's cases (each was mishandled before: an input overwritten, an absurd
coefficient, an internal error, a hang, an option silently ignored or meaning "all"). The
property every case checks: exit 2 and one ``propmap: error:`` line naming the input,
before anything is written, inputs unchanged; or, where the input is valid but the
envelope cannot determine a coefficient, exit 0 with the coefficient fixed and said."""

import ast
import json
import os
import signal
import subprocess
import sys
import time
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from cli_helpers import one_line_error, run
from hypothesis import given, settings
from hypothesis import strategies as st

from propmap.cli.main import main
from propmap.io.inputs import short_path

#: a tiny grid: a map in well under a second
TINY = ["--rpm", "3000:9000:4", "--airspeed", "0:10:3", "--incidence-deg", "0:180:5", "--check-points", "0"]
EXAMPLES = Path(str(resources.files("propmap") / "data" / "examples"))
UIUC = Path(str(resources.files("propmap") / "data" / "uiuc_v1"))


def files(folder: Path) -> dict:
    """Every file under ``folder`` with its bytes (what a refused command must leave as it was)."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


# ---- (1) map --plot never replaces an input; (6) --plot-rpm checked before the build ----

def test_map_plot_never_replaces_an_input(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "plots").mkdir()
    geom = tmp_path / "plots" / "map_contours_5000rpm.png"  # a geometry file under the name of a plot
    geom.write_bytes((UIUC / "apce_9x6_geom.txt").read_bytes())
    before = files(tmp_path)
    code, _, err = run(capsys, "map", geom, "--diameter-in", "9", "--blades", "2", *TINY, "--out", "m.nc", "--plot",
                       "plots", "--plot-rpm", "5000")
    assert one_line_error(code, err, "--plot: plots/map_contours_5000rpm.png is the input file"), err
    assert files(tmp_path) == before


@pytest.mark.parametrize("value, match", [
    ("abc", "'abc' is not a number"), ("nan", "nan is outside the map's rpm axis [3000, 9000]"),
    ("-5", "-5 is outside"), ("1e300", "1e300 is outside"), ("", "'' is not a number"),
    ("5000,", "'' is not a number"), ("5000,5001", "5001 falls on the node 5000 rpm of another value"),
])
def test_plot_rpm_is_checked_before_the_map_is_built(capsys, tmp_path, monkeypatch, value, match):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "map", "apce_8x6", *TINY, "--out", "m.nc", "--plot", "plots", "--plot-rpm", value)
    assert one_line_error(code, err, f"--plot-rpm: {match}"), err
    assert list(tmp_path.iterdir()) == []


def test_plot_rpm_draws_the_nearest_nodes(capsys, tmp_path):
    code, _, err = run(capsys, "map", "apce_8x6", *TINY, "--out", tmp_path / "m.nc", "--plot", tmp_path / "p",
                       "--plot-rpm", "3100,8900")
    assert code == 0, err
    assert sorted(p.name for p in (tmp_path / "p").iterdir()) == ["map_contours_3000rpm.png",
                                                                  "map_contours_9000rpm.png"]
    # said, not silent (was: --plot-rpm 8000 drew 8165 rpm without a word)
    assert "propmap: warning: --plot-rpm 3100: drawn at the nearest node of the rpm axis, 3000 rpm" in err
    assert "--plot-rpm 8900: drawn at the nearest node of the rpm axis, 9000 rpm" in err


# ---- (2) export-sim: coefficients the envelope cannot determine are fixed and said, or refused ----

def _coefficients(path: Path) -> dict:
    tree = ast.parse(path.read_text())
    return ast.literal_eval(next(n.value for n in tree.body if isinstance(n, ast.Assign)))


@pytest.mark.parametrize("envelope, fixed", [
    ("airspeed=0:1e-300", {"k_h", "k_z", "k_d"}),  # was k_z = -1.3e294
    ("incidence_deg=0:1e-9", {"k_h", "k_d"}),  # was k_h = -1.1e19
])
def test_export_sim_fixes_and_names_what_the_envelope_cannot_determine(capsys, tmp_path, envelope, fixed):
    out = tmp_path / "c.py"
    code, text, err = run(capsys, "export-sim", "apce_8x6", "--target", "rotorpy", "--out", out, "--envelope",
                          envelope, "--points", "200")
    assert code == 0, err
    c = _coefficients(out)
    assert {k for k in ("k_h", "k_z", "k_d") if c[k] == 0.0} == fixed
    report = json.loads((tmp_path / "c.report.json").read_text())
    assert set(report["fixed_at_zero"]) == fixed
    for name in fixed:
        assert f"propmap: warning: {name} fixed at 0: its term's size" in err
        assert f"{name} fixed at 0" in text and f"# {name} fixed at 0" in out.read_text()
    # what is fitted stays the hover model's size: k_eta near the static k_T of the envelope
    assert 1e-8 < c["k_eta"] < 1e-5 and 1e-10 < c["k_m"] < 1e-6


def test_export_sim_refuses_an_envelope_without_gazebo_thrust(capsys, tmp_path):
    """|V_z| >= 25 m/s everywhere: the plugin's thrust fade is 0, its thrust 0 whatever motorConstant (was a
    motorConstant of 0; with hover pinned it would be written and give no thrust anywhere in the envelope)."""
    code, _, err = run(capsys, "export-sim", "apce_8x6", "--target", "gazebo", "--out", tmp_path / "c.sdf",
                       "--envelope", "airspeed=30:40,incidence_deg=0:10", "--points", "100")
    assert one_line_error(code, err, "--envelope: the plugin's thrust fade 1 - |V_z| / 25 m/s is 0 at every point"), err
    assert list(tmp_path.iterdir()) == []


def test_export_sim_all_flagged_envelope_says_n_a(capsys, tmp_path):
    """Descent in the vortex ring (3-5 m/s at 5000-6000 rpm: descent ratios 0.55-1.11, inside Johnson's band): every
    point flagged, no error outside flagged regions (was rms nan%)."""
    code, text, err = run(capsys, "export-sim", "apce_8x6", "--target", "rotorpy", "--out", tmp_path / "c.py",
                          "--envelope", "rpm=5000:6000,airspeed=3:5,incidence_deg=170:180", "--points", "60")
    assert code == 0, err
    assert "nan" not in text.lower() and "rms     n/a  max     n/a" in text
    assert "propmap: warning: every one of the 60 check points of the envelope is flagged" in err
    report = json.loads((tmp_path / "c.report.json").read_text(), parse_constant=pytest.fail)
    assert report["errors"]["thrust"]["rms"] is None and report["errors"]["thrust"]["max_flagged"] > 0


# ---- (4) a pipe is refused, never read ----

def test_map_check_of_a_fifo_is_refused_at_once(tmp_path):
    fifo = tmp_path / "m.nc"
    os.mkfifo(fifo)
    proc = subprocess.run([sys.executable, "-m", "propmap", "map", "--check", str(fifo)], capture_output=True,
                          text=True, timeout=120)  # a hang would hit the timeout
    assert proc.returncode == 2 and "not a regular file" in proc.stderr and proc.stderr.count("\n") == 1


# ---- (5) size limits before any work ----

def test_map_all_too_large_is_refused_before_any_work(capsys, tmp_path):
    t0 = time.perf_counter()
    code, _, err = run(capsys, "map", "--all", "--rpm", "1000:20000:200", "--airspeed", "0:40:200",
                       "--incidence-deg", "0:180:500", "--out", tmp_path / "all.nc")
    assert one_line_error(code, err, "points for each of 147 propellers (2,940,000,000 in all); at most 20,000,000")
    assert time.perf_counter() - t0 < 30 and list(tmp_path.iterdir()) == []


def test_map_all_streams_its_parts_and_removes_them(capsys, tmp_path, monkeypatch):
    """Each propeller's map goes to disk as built; the combined file is written from them
    (lazily, one propeller at a time) and the parts are removed."""
    import propmap.cli.map as cm

    seen = {}
    real = cm._catalogue_maps

    def spy(*args, **kwargs):
        with real(*args, **kwargs) as ds:
            seen["chunked"] = ds["thrust"].chunks is not None
            seen["parts"] = sorted(p.name for p in tmp_path.iterdir() if p.name.endswith(".parts"))
            yield ds

    monkeypatch.setattr(cm, "_catalogue_maps", __import__("contextlib").contextmanager(spy))
    code, _, err = run(capsys, "map", "--all", "--props", "apce_8x6,apce_10x7", *TINY, "--out", tmp_path / "all.nc")
    assert code == 0, err
    assert seen["chunked"] and len(seen["parts"]) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["all.nc", "all.nc.json"]


# ---- (7) fit parameter names; (11) options that would be ignored ----

@pytest.mark.parametrize("argv, match", [
    (["--fit-params", "alpha0"],
     "--fit-params: cannot fit alpha0 with the cambered model: its parameters are cl_alpha"),
    (["--fit-params", "foo"], "--fit-params: cannot fit foo with the cambered model"),
    (["--fit-params", "cl1,cl1"], "--fit-params: cl1 given more than once"),
    (["--fit-params", "cl_alpha,"], "--fit-params: an empty parameter name"),
    (["--fit-params", ""], "--fit-params: no parameter name"),
    (["--fit-params", "cl_alpha", "--base", "gill2017-apc"],
     "cannot fit cl_alpha with the paper's model: its parameters are cl1, cl2, cd, alpha0"),
    (["--fit-params", "cl1_body"], "--body-lift"),
    (["--base", "gill2017-apc", "--no-prior"], "--no-prior applies to the cambered model"),
    (["--lift-model", "sincos"], "--lift-model applies to the paper's model; --base generic"),
    (["--holdout", ""], "--holdout: no run"),
    (["--quantities", ","], "--quantities: no quantity"),
    (["--quantities", "thrust,lift"], "--quantities: unknown lift"),
])
def test_fit_loads_option_errors(capsys, tmp_path, argv, match):
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--out", tmp_path / "p.toml", *argv)
    assert one_line_error(code, err, match), err
    assert list(tmp_path.iterdir()) == []


def test_fit_level_flight_no_prior_with_the_papers_model_is_refused(capsys, tmp_path):
    code, _, err = run(capsys, "fit", "level-flight", EXAMPLES / "level_flight_synthetic.csv", "--vehicle",
                       EXAMPLES / "quadrotor.toml", "--out", tmp_path / "p.toml", "--no-prior")
    assert one_line_error(code, err, "--no-prior applies to the cambered model (its population prior); "
                                     "--base gill2017-apc"), err


# ---- (8) an empty value never means "default" or "all"; (11) ignored options refused ----

@pytest.mark.parametrize("argv, match", [
    (["validate", "--all", "--protocols", ""], "--protocols: no protocol"),
    (["validate", "--all", "--protocols", "loso,,static"], "--protocols: an empty protocol"),
    (["validate", "--all", "--props", ","], "--props: no propeller name"),
    (["validate", "--all", "--props", "apce_8x6", "--out-dir", ""], "--out-dir': the path is empty"),
    (["map", "apce_8x6", "--out", "m.nc", "--rpm", ""], "--rpm: '' is not start:stop:count"),
    (["map", "apce_8x6", "--out", "m.nc", "--airspeed", ""], "--airspeed: '' is not start:stop:count"),
    (["map", "apce_8x6", "--out", "m.nc", "--incidence-deg", ""], "--incidence-deg: '' is not"),
    (["map", "apce_8x6", "--out", "m.h", "--format", "c", "--c-name", ""], "--c-name: the C name prefix is empty"),
    (["map", "apce_8x6", "--out", ""], "--out': the path is empty"),
    (["map", "--all", "--props", "", "--out", "m.nc"], "--props: no propeller name"),
    (["map", "--check", ""], "--check': the path is empty"),
    (["map", "apce_8x6", "--out", "m.nc", "--plot", ""], "--plot': the path is empty"),
    (["export-sim", "apce_8x6", "--target", "rotorpy", "--out", "c.py", "--envelope", ""], "--envelope: ''"),
    (["export-sim", "apce_8x6", "--target", "rotorpy", "--out", "c.py", "--envelope", "rpm=5000:6000,rpm=7000:8000"],
     "--envelope: rpm given more than once"),
    (["export-sim", "apce_8x6", "--target", "rotorpy", "--out", "c.py", "--envelope", "incidence_deg=0:90,"
      "incidence-deg=0:30"], "--envelope: incidence_deg given more than once"),
    (["demo", "--out-dir", ""], "--out-dir': the path is empty"),
    (["loads", "apce_8x6", "--points", "", "--out", "o.csv"], "--points': the path is empty"),
    (["map", "--all", "--plot", "p", "--out", "m.nc"], "--plot does not apply to --all"),
    (["map", "--all", "--diameter-in", "9", "--out", "m.nc"], "--diameter-in does not apply to --all"),
    (["map", "--check", "m.nc", "--c-name", "x", "--format", "c"], "--format, --c-name do not apply"),
    (["map", "--check", "m.nc", "--scheduler", "tcp://h:1"], "--scheduler does not apply"),
    (["map", "apce_8x6", "--out", "m.nc", "--c-type", "float"], "--c-type applies to --format c"),
    (["map", "apce_8x6", "--out", "m.h", "--format", "c", "--c-name", "fp"],
     "--c-name: the C name prefix 'fp' would define FP_CLIP, FP_NAN, FP_ERROR, ...: names reserved by <math.h>"),
    (["map", "apce_8x6", "--out", "m.h", "--format", "c", "--c-name", "_rotor"], "beginning with an underscore"),
    (["map", "apce_8x6", "--out", "m.h", "--format", "c", "--c-name", "sig"], "<signal.h>"),
    (["map", "apce_8x6", "--out", "m.h", "--format", "c", "--c-name", "err"], "<errno.h>"),
])
def test_empty_and_ignored_options_exit_2_before_any_work(capsys, tmp_path, monkeypatch, argv, match):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert one_line_error(code, err, match), err
    assert out == "" and list(tmp_path.iterdir()) == []


# ---- (12) errors early and naming the input ----

def test_out_name_too_long_for_its_temporary_file_is_refused_before_solving(capsys, tmp_path):
    src = tmp_path / "p.csv"
    src.write_text("rpm,airspeed,incidence_deg\n8000,0,0\n")
    name = "a" * 250 + ".csv"  # a valid name, too long once the temporary file's affixes are added
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", src, "--out", tmp_path / name)
    assert one_line_error(code, err, "--out: the name 'aaaa"), err
    assert "too long with the temporary file's affixes; give at most 241 bytes" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.csv"]


def test_fit_out_empty_and_long_source_are_named(capsys, tmp_path):
    code, _, err = run(capsys, "fit", "level-flight", EXAMPLES / "level_flight_synthetic.csv", "--vehicle",
                       EXAMPLES / "quadrotor.toml", "--out", "")
    assert one_line_error(code, err, "Invalid value for '--out': the path is empty"), err
    code, _, err = run(capsys, "fit", "loads", "b" * 300, "--prop", "apce_8x6", "--out", tmp_path / "f.toml")
    assert one_line_error(code, err, "SOURCE: 'bbbb"), err
    assert "is neither a catalogue propeller nor a file (a name of 300 characters)" in err


def test_several_sources_name_the_one_that_is_not_uiuc(capsys, tmp_path):
    # in a folder deep enough that the path is longer than a message shows (before 2026-11-28 the message
    # cut the path's end: "SOURCE: /tmp/.../loads... is not", without the file's name)
    folder = tmp_path / "wind_tunnel_campaign_2026" / "stand_exports_after_calibration"
    folder.mkdir(parents=True)
    csv = folder / "loads.csv"
    csv.write_text("rpm,thrust\n5000,1.0\n6000,1.5\n")
    assert len(str(csv)) > 80
    code, _, err = run(capsys, "fit", "loads", UIUC / "apce_10x5_static_pg0819.txt", csv, "--prop", "apce_10x5",
                       "--out", tmp_path / "f.toml")
    assert one_line_error(code, err, f"SOURCE: {str(csv)[:19]}"), err
    assert "...el_campaign_2026/stand_exports_after_calibration/loads.csv is not a UIUC-format static" in err, err


@settings(max_examples=300, deadline=None)
@given(st.text(st.characters(codec="utf-8"), max_size=300).filter(str.isprintable), st.integers(8, 200))
def test_a_path_in_a_message_keeps_its_start_and_its_end(path, n):
    from propmap.io.inputs import short_path

    s = short_path(path, n)
    if len(path) <= n:
        assert s == path
    else:
        head = (n - 3) // 4
        assert len(s) == n and s == path[:head] + "..." + path[len(path) - (n - 3 - head):]
    assert short_path("/home/alice/" + "campaign/" * 9 + "apce_10x7.nc").endswith("/campaign/apce_10x7.nc")
    assert short_path("a\nb.nc") == repr("a\nb.nc")  # a control character: quoted, as show_path does
    long = "/data/" + "x" * 100 + "/b\x1b[2J.nc"  # a long one with a terminal escape: its repr, cut, both quotes kept
    assert short_path(long) == repr(long)[:19] + "..." + repr(long)[-58:] and short_path(long).endswith(".nc'")
    assert short_path(Path("/d") / ("y" * 90) / "m.nc").endswith("yyy/m.nc")  # a Path, as its text
    assert short_path(os.fsencode("/d/" + "z" * 90 + "/m.nc")).endswith("zzz/m.nc")  # bytes, decoded
    assert short_path(b"/d/\xff" + b"z" * 90).startswith("'/d/\\udcff")  # undecodable bytes: escaped in a repr
    assert short_path("/tmp/x.nc", quote=True) == "'/tmp/x.nc'"  # quoted, for a name beside other text
    assert short_path("a\nb.nc", quote=True) == repr("a\nb.nc")  # (not quoted twice)
    q = short_path("/d/" + "q" * 100 + "/m.nc", 40, quote=True)
    assert len(q) == 40 and q.startswith("'/d/") and q.endswith("/m.nc'")
    with pytest.raises(ValueError, match="n must be at least 8"):
        short_path("/tmp/x.nc", 2)


@pytest.mark.parametrize("address, match", [
    ("garbage", "--scheduler: scheduler must be an address PROTOCOL://HOST:PORT"),
    ("tcp://127.0.0.1:99999", "port in [1, 65535]"),
    ("tcp://127.0.0.1:1", "--scheduler: scheduler: no scheduler answered at tcp://127.0.0.1:1 within 1 s"),
])
def test_scheduler_is_checked_and_named_before_any_work(capsys, tmp_path, monkeypatch, address, match):
    import propmap.maps as maps

    monkeypatch.setattr(maps, "SCHEDULER_TIMEOUT", 1.0)
    code, _, err = run(capsys, "map", "apce_8x6", *TINY, "--out", tmp_path / "m.nc", "--scheduler", address)
    assert one_line_error(code, err, match), err
    assert list(tmp_path.iterdir()) == []


def test_scheduler_empty_is_refused(capsys, tmp_path):
    code, _, err = run(capsys, "map", "apce_8x6", *TINY, "--out", tmp_path / "m.nc", "--scheduler", "")
    assert one_line_error(code, err, "--scheduler: scheduler must be an address"), err


# ---- (9) edited maps refused by --check, naming the file and the attribute ----

@pytest.fixture(scope="module")
def tiny_map(tmp_path_factory):
    from propmap.maps import RotorMap

    d = tmp_path_factory.mktemp("tiny")
    assert main(["map", "apce_8x6", *TINY[:-2], "--check-points", "20", "--out", str(d / "m.nc")]) == 0
    return RotorMap.open(d / "m.nc").dataset


@pytest.mark.parametrize("edit, match", [
    (lambda ds: ds.assign_coords(incidence_deg=ds["incidence_deg"] * 2), "axis incidence_deg must lie within [0, 180]"),
    (lambda ds: ds.assign_coords(rpm=ds["rpm"] - 3000), "axis rpm must lie within [0.95493, 954930] rpm"),
    (lambda ds: ds.assign(thrust=ds["thrust"] * np.nan), "thrust is not finite at a converged node"),
    (lambda ds: ds.assign_attrs(n_blades=1e30), "attribute n_blades must be an integer in [1, 100], got 1e+30"),
    (lambda ds: ds.assign_attrs(diameter_m=1e308), "attribute diameter_m must be a number in [0.0127, 2.54] m"),
    (lambda ds: ds.assign_attrs(diameter_m=np.array([0.2, 0.3])), "attribute diameter_m must be a number"),
    (lambda ds: ds.assign_attrs(check_seed="x"), "attribute check_seed must be an integer in [0, "),
    (lambda ds: ds.assign_attrs(params_json='{"section_model": "cambered", "cl_alpha": 1e9}'),
     "attribute params_json: cl_alpha must be a finite number in"),
    (lambda ds: ds.assign_attrs(rho_kg_m3=-1.0), "attribute rho_kg_m3 must be a number in [0.001, 2000] kg/m^3"),
])
def test_edited_map_is_refused_by_check_naming_the_file(capsys, tmp_path, tiny_map, edit, match):
    path = tmp_path / "edited.nc"
    edit(tiny_map.copy(deep=True)).to_netcdf(path)
    before = path.read_bytes()
    code, out, err = run(capsys, "map", "--check", path, "--check-points", "10")
    assert one_line_error(code, err, f"--check: {short_path(path)}: "), err
    assert match in err, err
    assert out == "" and path.read_bytes() == before


def test_check_of_a_map_in_a_deep_folder_names_the_file(capsys, tmp_path, tiny_map):
    folder = tmp_path / "quadrotor_maps_2026" / "campaign_3_after_the_new_motors"
    folder.mkdir(parents=True)
    path = folder / "apce_10x7_map.nc"
    tiny_map.assign_attrs(rho_kg_m3=-1.0).to_netcdf(path)
    assert len(str(path)) > 80
    code, out, err = run(capsys, "map", "--check", path, "--check-points", "10")
    # the name kept (before 2026-11-28: "campaign_3_after_the_new_motors/apce_10x7_m: attribute ...")
    assert one_line_error(code, err, "...maps_2026/campaign_3_after_the_new_motors/apce_10x7_map.nc: attribute "
                                     "rho_kg_m3"), err


# ---- (13) SIGTERM of validate --all: no resource-tracker noise ----

def test_sigterm_of_validate_all_ends_quietly(tmp_path):
    # the whole catalogue (a minute or more), so that the run is still going when it is stopped: three
    # propellers took 3.2 s once the fits had implicit derivatives
    proc = subprocess.Popen([sys.executable, "-m", "propmap", "validate", "--all", "--protocols", "loso"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=tmp_path)
    # wait until the worker processes run (their tqdm locks were the leaked semaphores)
    deadline = time.monotonic() + 120
    children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children")
    while time.monotonic() < deadline and proc.poll() is None:
        if children.exists() and len(children.read_text().split()) >= 2:
            break
        time.sleep(0.1)
    time.sleep(3)  # the workers import and start fitting
    assert proc.poll() is None, "the run ended before it could be stopped"
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 128 + signal.SIGTERM, err
    assert b"leaked" not in err and b"resource_tracker" not in err and b"Traceback" not in err, err


CALLBACK = """
import signal, sys, time
from propmap.cli import main as m
signal.signal(signal.SIGTERM, m._on_sigterm)
# C calling back into Python (as llvmlite does while numba compiles): a SIGTERM there
# must not be raised (it would be printed and dropped) but delivered after the callback
src = ("def _raw_object_cache_notify():\\n    import os, signal\\n    os.kill(os.getpid(), signal.SIGTERM)\\n"
       "    for _ in range(10000): pass\\n_raw_object_cache_notify()\\n")
exec(compile(src, "/site-packages/llvmlite/binding/executionengine.py", "exec"))
print("callback returned", flush=True)
t = time.monotonic()
try:
    time.sleep(10)  # a blocking call: the re-delivered signal must interrupt it
except SystemExit as exc:
    print("stopped", exc.code, m._terminated, round(time.monotonic() - t, 2), flush=True)
"""


def test_sigterm_inside_a_c_callback_is_delivered_after_it(tmp_path):
    out = subprocess.run([sys.executable, "-c", CALLBACK], capture_output=True, text=True, timeout=60,
                         cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.split("\n")
    assert lines[0] == "callback returned" and lines[1].startswith("stopped 143 [15"), out.stdout
    assert float(lines[1].split()[-1]) < 1.0, out.stdout  # within the re-delivery's 50 ms, not after the sleep
    assert "Exception ignored" not in out.stderr and "Traceback" not in out.stderr, out.stderr


HELD = """
import os, signal, sys
import numpy as np, xarray as xr
import propmap as pm
from propmap.cli import main as m
from propmap.maps import build_map, write_map
signal.signal(signal.SIGTERM, m._on_sigterm)
ds = build_map(pm.load_propeller("apce_8x6"), pm.generic_params(), np.array([300.0, 600.0]), np.array([0.0, 5.0]),
               np.radians([0.0, 90.0]), n_check=0)
real = xr.Dataset.to_netcdf
def to_netcdf(self, *a, **k):  # a SIGTERM that lands inside the netCDF write (HDF5 holds a lock there)
    os.kill(os.getpid(), signal.SIGTERM)
    out = real(self, *a, **k)
    print("write finished", flush=True)
    return out
xr.Dataset.to_netcdf = to_netcdf
try:
    write_map(ds, sys.argv[1])
except SystemExit as exc:
    print("stopped", exc.code, sorted(os.listdir(os.path.dirname(sys.argv[1]))), flush=True)
"""


def test_a_sigterm_during_the_netcdf_write_is_held_until_it_ends(tmp_path):
    """A SIGTERM that landed inside the netCDF write raised SystemExit inside HDF5, which holds a
    lock: propmap map deadlocked in 5 of 6 tries, its temporary files left (a user-level audit,
    2026-11-26). It is held until the write returns, then stops the run; nothing is left."""
    (tmp_path / "out").mkdir()
    out = subprocess.run([sys.executable, "-c", HELD, str(tmp_path / "out" / "m.nc")], capture_output=True, text=True,
                         timeout=600, cwd=tmp_path)  # (minutes: the child compiles the kernels the cache lacks)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split("\n")[:2] == ["write finished", "stopped 143 []"], out.stdout


# ---- (15) the map and its sidecar are a pair ----

def test_sidecar_names_the_map_it_describes(capsys, tmp_path, tiny_map):
    from propmap.maps import read_sidecar, write_map

    path = tmp_path / "m.nc"
    write_map(tiny_map, path)
    meta = read_sidecar(path)
    assert meta["describes"]["file"] == "m.nc" and meta["propeller"] == "apce_8x6"
    # the map replaced without its sidecar (another build, or the moment between the two
    # renames): the sidecar no longer describes it, and says so
    write_map(tiny_map.assign_attrs(params_label="other"), path, sidecar=False)
    with pytest.raises(ValueError, match="does not describe .*m.nc as it is now"):
        read_sidecar(path)


WRITER = """
import sys
from propmap.maps import RotorMap, write_map
ds = RotorMap.open(sys.argv[1]).dataset.assign_attrs(params_label=sys.argv[3])
for _ in range(6):
    write_map(ds, sys.argv[2])
"""


def test_concurrent_writers_leave_a_matching_pair(tmp_path, tiny_map):
    """Two processes replacing the same map and sidecar over and over: the renames of one
    write never interleave with the other's (folder lock), so the last pair matches."""
    from propmap.maps import RotorMap, read_sidecar, write_map

    src = tmp_path / "src" / "m.nc"
    write_map(tiny_map, src, sidecar=False)
    path = tmp_path / "out" / "m.nc"
    procs = [subprocess.Popen([sys.executable, "-c", WRITER, str(src), str(path), f"writer {k}"]) for k in range(2)]
    assert all(p.wait(timeout=300) == 0 for p in procs)
    assert read_sidecar(path)["params_label"] == RotorMap.open(path).attrs["params_label"]
    assert sorted(p.name for p in path.parent.iterdir()) == ["m.nc", "m.nc.json"]


def test_a_check_that_measures_nothing_does_not_pass(capsys, tmp_path):
    """A grid whose every cell is flagged (3 nodes an axis, the vortex ring within reach of all):
    --check measured nothing and said "passed", exit 0 (a CLI audit, 2026-11-26)."""
    path = tmp_path / "m.nc"
    assert main(["map", "apce_8x6", "--rpm", "3000:6000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:180:3",
                 "--check-points", "20", "--out", str(path)]) == 0
    capsys.readouterr()
    code, out, err = run(capsys, "map", "--check", path, "--check-points", "30")
    assert code == 3 and "not tested, every check point in a flagged cell" in out, out
    code, out, err = run(capsys, "map", "--check", path, "--check-points", "30", "--json")
    rep = json.loads(out)
    assert code == 3 and rep["passed"] is False and rep["untested"] is True and rep["exceeded"] == []


def test_a_map_built_twice_is_the_same_file(tmp_path):
    """The wall-clock build time was stored in the map (`build_seconds`): two builds of one map
    differed in 8-10 bytes and in the sidecar's digest (a reproducibility audit, 2026-11-27). It
    is reported, not stored."""
    import hashlib

    import xarray as xr

    digests = []
    for k in range(2):
        out = tmp_path / f"m{k}.nc"
        assert main(["map", "apce_8x6", *TINY[:-2], "--check-points", "20", "--out", str(out)]) == 0
        digests.append(hashlib.sha256(out.read_bytes()).hexdigest())
        with xr.open_dataset(out) as ds:
            assert "build_seconds" not in ds.attrs
    assert digests[0] == digests[1]
