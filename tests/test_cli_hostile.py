"""The command line under hostile use: no input ever overwritten, no traceback, nothing
computed for bad input, files written with normal permissions (regression tests of the
hardening audit: each case below was mishandled before)."""

import csv
import io
import json
import os
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest
from cli_helpers import one_line_error, run

from propmap.cli.main import main

POINTS = "rpm,airspeed,incidence_deg\n8000,0,0\n8000,10,90\n"


@pytest.fixture
def points(tmp_path):
    f = tmp_path / "x.csv"
    f.write_text(POINTS)
    return f


# ---- never lose data: an output that resolves to an input is refused before any work ----

@pytest.mark.parametrize("variant", ["same", "dotdot", "dot", "absolute", "symlink", "hardlink", "symlinked_dir"])
def test_loads_out_resolving_to_the_points_file_is_refused(capsys, tmp_path, points, monkeypatch, variant):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    out = {"same": "x.csv", "dotdot": "sub/../x.csv", "dot": "./x.csv", "absolute": str(points),
           "symlink": "link.csv", "hardlink": "hard.csv", "symlinked_dir": "d/x.csv"}[variant]
    if variant == "symlink":
        os.symlink(points, tmp_path / "link.csv")
    if variant == "hardlink":
        os.link(points, tmp_path / "hard.csv")
    if variant == "symlinked_dir":
        os.symlink(tmp_path, tmp_path / "d")
    before = points.read_bytes()
    code, out_text, err = run(capsys, "loads", "apce_8x6", "--points", "x.csv", "--out", out)
    assert one_line_error(code, err, "--out"), err
    assert points.read_bytes() == before


def test_loads_out_resolving_to_the_geometry_file_is_refused(capsys, tmp_path, points, shared_data):
    geom = tmp_path / "apce_9x6_geom.txt"
    geom.write_bytes((shared_data / "uiuc_propdb/v1/apce_9x6_geom.txt").read_bytes())
    before = geom.read_bytes()
    code, _, err = run(capsys, "loads", geom, "--points", points, "--out", geom)
    assert one_line_error(code, err, "--out") and geom.read_bytes() == before


def test_loads_out_resolving_to_the_params_file_is_refused(capsys, tmp_path, points):
    import propmap as pm

    p = tmp_path / "p.toml"
    pm.write_params(p, pm.preset("gill2017-apc"))
    before = p.read_bytes()
    code, _, err = run(capsys, "loads", "apce_8x6", "--params", p, "--points", points, "--out", p)
    assert one_line_error(code, err, "--out") and p.read_bytes() == before


def test_fit_outputs_beside_out_may_not_be_the_data(capsys, tmp_path):
    """fit writes <out>, <stem>.report.json, <stem>.report.txt and <stem>.png: none may be an input."""
    data = tmp_path / "f.png"  # the figure a fit to --out f.toml would write
    data.write_text("rpm,thrust\n5000,1.0\n6000,1.5\n7000,2.0\n")
    before = data.read_bytes()
    code, _, err = run(capsys, "fit", "loads", data, "--prop", "apce_8x6", "--out", tmp_path / "f.toml")
    assert one_line_error(code, err), err
    assert data.read_bytes() == before and sorted(p.name for p in tmp_path.iterdir()) == ["f.png"]


def test_validate_figure_may_not_be_the_params_file(capsys, tmp_path):
    import propmap as pm

    p = tmp_path / "p.toml"
    pm.write_params(p, pm.preset("gill2017-apc"))
    before = p.read_bytes()
    code, _, err = run(capsys, "validate", "apce_8x6", "--params", p, "--figure", p)
    assert one_line_error(code, err, "--figure") and p.read_bytes() == before


# ---- unusable output paths: exit 2 at once, nothing written, no stray files ----

@pytest.mark.parametrize("kind", ["directory", "under_a_file", "empty", "unwritable"])
def test_unusable_out_path_exits_2_before_any_work(capsys, tmp_path, points, kind):
    (tmp_path / "adir").mkdir()
    locked = tmp_path / "locked"
    locked.mkdir()
    out = {"directory": tmp_path / "adir", "under_a_file": points / "y.csv", "empty": "",
           "unwritable": locked / "y.csv"}[kind]
    if kind == "unwritable":
        locked.chmod(0o500)
        if os.geteuid() == 0:  # root writes through permission bits: a file system that refuses files
            out = "/proc/y.csv" if os.path.isdir("/proc/self") else pytest.skip("no /proc")
    t0 = time.perf_counter()
    try:
        code, _, err = run(capsys, "loads", "apce_8x6", "--points", points, "--out", out)
    finally:
        locked.chmod(0o700)
    assert one_line_error(code, err, "--out"), err
    assert time.perf_counter() - t0 < 30  # refused, not computed (a generous bound, not a benchmark)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["adir", "locked", "x.csv"]
    assert list((tmp_path / "adir").iterdir()) == [] and list(locked.iterdir()) == []


def test_fit_with_an_unusable_out_leaves_no_stray_figure(capsys, tmp_path):
    (tmp_path / "adir").mkdir()
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--out", tmp_path / "adir")
    assert one_line_error(code, err, "--out")
    assert [p.name for p in tmp_path.iterdir()] == ["adir"] and list((tmp_path / "adir").iterdir()) == []


def test_demo_out_dir_that_is_a_file_exits_2(capsys, tmp_path, points):
    code, _, err = run(capsys, "demo", "--out-dir", points)
    assert one_line_error(code, err, "--out-dir") and points.read_text() == POINTS


def test_validate_writes_no_figure_unless_asked(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, _ = run(capsys, "validate", "apce_8x6")
    assert code == 0 and list(tmp_path.iterdir()) == []


# ---- outputs get normal permissions; a stopped run leaves no temporary file ----

def test_new_output_respects_the_umask_and_an_existing_file_keeps_its_mode(capsys, tmp_path, points):
    old = os.umask(0o022)
    try:
        dst = tmp_path / "new.csv"
        assert run(capsys, "loads", "apce_8x6", "--points", points, "--out", dst)[0] == 0
        assert stat.S_IMODE(dst.stat().st_mode) == 0o644
        kept = tmp_path / "kept.csv"
        kept.write_text("old")
        kept.chmod(0o664)
        assert run(capsys, "loads", "apce_8x6", "--points", points, "--out", kept)[0] == 0
        assert stat.S_IMODE(kept.stat().st_mode) == 0o664 and kept.read_text().startswith("rpm,")
    finally:
        os.umask(old)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept.csv", "new.csv", "x.csv"]


def test_the_umask_is_read_without_changing_it():
    """The new file's mode comes from the process' umask, read from /proc/self/status (Linux)
    rather than set and restored (which another thread's new file would see)."""
    from propmap.io.atomic import _umask

    for mask in (0o022, 0o077, 0o002):
        old = os.umask(mask)
        try:
            assert _umask() == mask
        finally:
            os.umask(old)
    if os.path.exists("/proc/self/status"):  # read, not set: the umask is not touched meanwhile
        calls = []
        real = os.umask
        try:
            os.umask = lambda m: calls.append(m) or real(m)
            _umask()
        finally:
            os.umask = real
        assert calls == []


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP])
def test_sigterm_during_a_long_run_leaves_no_temporary_file(tmp_path, signum):
    """SIGTERM, and SIGHUP as it (a closed terminal: it killed the run without a word and left
    map --all's parts folder until stop 100), stop the run: exit 128 + n, no temporary file."""
    src = tmp_path / "many.csv"
    src.write_text("rpm,airspeed,incidence_deg\n" + "8000,10,45\n" * 400_000)
    dst = tmp_path / "out.csv"
    proc = subprocess.Popen([sys.executable, "-m", "propmap", "loads", "apce_8x6", "--points", str(src),
                             "--out", str(dst)], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    # wait until the output's temporary file exists (the computation has started), then stop it
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if any(p.name.startswith(".out.csv.") for p in tmp_path.iterdir()):
            break
        time.sleep(0.05)
    assert proc.poll() is None, "the run ended before it could be stopped"
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 128 + signum, err
    assert b"Traceback" not in err
    assert [p.name for p in tmp_path.iterdir()] == ["many.csv"]


# ---- every bad value: exit 2, one line naming the input and its range ----

@pytest.mark.parametrize(
    "argv, match",
    [
        (["loads", "apce_8x6", "--rpm", "999999"], "[1, 954929]"),
        (["loads", "apce_8x6", "--rpm", "1e-200"], "rpm must be finite and in [1,"),
        (["loads", "apce_8x6", "--rpm", "0", "--airspeed", "5"], "parked propeller"),
        (["loads", "apce_8x6", "--rpm", "8000", "--incidence-deg", "-30"], "symmetric"),
        (["demo", "--rpm", "0"], "--rpm"),
        (["demo", "--rpm", "nan"], "--rpm"),
        (["demo", "--rpm", "inf"], "--rpm"),
        (["demo", "--rpm", "-1"], "--rpm"),
        (["loads", "apce_8x6", "--rpm", "8000", "--blades", "3"], "catalogue propeller"),
        (["loads", "apce_8x6", "--rpm", "8000", "--diameter-in", "9"], "catalogue propeller"),
        (["loads", "apce_8x6", "--rpm", "8000", "--out", "y.csv"], "--out"),
        (["fit", "loads", "apce_8x6", "--out", "f.toml", "--base", "nosuchset"], "--base"),
    ],
)
def test_bad_values_exit_2_naming_the_input(capsys, tmp_path, monkeypatch, argv, match):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert one_line_error(code, err, match), err
    assert out == "" and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "extra, match",
    [
        (["--blades", "1e30"], "--blades"),
        (["--blades", "1000"], "--blades must be an integer in [1, 20]"),
        (["--diameter-in", "-9"], "--diameter-in must be finite and in [0.5, 100] in, got -9.0"),
    ],
)
def test_geometry_file_options_are_checked_in_the_units_typed(capsys, shared_data, extra, match):
    code, _, err = run(capsys, "loads", shared_data / "uiuc_propdb/v1/apce_9x6_geom.txt", "--rpm", "8000", *extra)
    assert one_line_error(code, err, match), err


def test_points_with_single_point_options_is_refused(capsys, tmp_path, points):
    for extra in (["--airspeed", "5"], ["--incidence-deg", "30"], ["--rpm", "8000"], ["--json"]):
        code, _, err = run(capsys, "loads", "apce_8x6", "--points", points, "--out", tmp_path / "y.csv", *extra)
        assert one_line_error(code, err, extra[0]), (extra, err)
    assert not (tmp_path / "y.csv").exists()
    # --json without --out: the --json is what is wrong (it was told "--out is required": a user-level audit)
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", points, "--json")
    assert one_line_error(code, err, "--json applies to a single point"), err


# ---- hostile points files ----

@pytest.mark.parametrize(
    "content, match",
    [
        (b"rpm,airspeed,incidence_deg\n8000,0,0\n8000,\xff\xfe,0\n", "UTF-8"),
        (b"\xff\xferpm,airspeed,incidence_deg\n", "UTF-8"),
        (b"rpm,airspeed,incidence_deg,rpm\n8000,0,0,1\n", "duplicate"),
        (b"rpm,airspeed,incidence_deg\n8000,\"0,0\n8000,1,0\n", "--points"),
        (b"rpm,airspeed,incidence_deg\n8000,0," + b"9" * 131_072 + b"\n", "line 2: incidence_deg"),
        (b"rpm_\xc2\xb2,airspeed,incidence_deg\n8000,0,0\n", "column 'rpm_²': unknown unit '²' for rpm"),
        (b"", "--points"),
    ],
)
def test_hostile_points_file_exits_2_and_writes_nothing(capsys, tmp_path, content, match):
    src = tmp_path / "in.csv"
    src.write_bytes(content)
    dst = tmp_path / "out.csv"
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", src, "--out", dst)
    assert one_line_error(code, err, match), err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv"] and src.read_bytes() == content


def test_points_from_dev_zero_is_refused_quickly(capsys, tmp_path):
    if not os.path.exists("/dev/zero"):
        pytest.skip("no /dev/zero")
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", "/dev/zero", "--out", tmp_path / "y.csv")
    assert one_line_error(code, err, "--points")


def test_excel_points_file_bom_semicolons_and_case_are_read(capsys, tmp_path):
    src = tmp_path / "in.csv"
    src.write_bytes("\ufeffRPM ; Airspeed ; Incidence_Deg ; note\r\n8000;10;90;a\r\n6000;0;0;b\r\n".encode())
    code, out, err = run(capsys, "loads", "apce_8x6", "--points", src, "--out", "-")
    assert code == 0, err
    rows = list(csv.DictReader(out.splitlines()))
    assert [r["note"] for r in rows] == ["a", "b"]  # extra columns kept, in order
    assert float(rows[0]["drag"]) > 0 and float(rows[1]["drag"]) == 0.0  # D = 0 in axial flow


def test_points_output_column_named_like_an_input_gets_a_suffix(capsys, tmp_path):
    src = tmp_path / "in.csv"
    src.write_text("rpm,airspeed,incidence_deg,thrust\n8000,0,0,4.2\n")
    code, out, err = run(capsys, "loads", "apce_8x6", "--points", src, "--out", "-")
    rows = list(csv.DictReader(out.splitlines()))
    assert code == 0 and rows[0]["thrust"] == "4.2" and float(rows[0]["thrust_model"]) > 0


def test_points_stream_in_chunks_gives_the_same_table(capsys, tmp_path, monkeypatch):
    """The streamed two-pass writer (chunks of CHUNK rows) gives the table of one pass."""
    import propmap.cli.loads as cl

    src = tmp_path / "in.csv"
    src.write_text("rpm,airspeed,incidence_deg\n" + "".join(f"{5000 + 100 * i},{i % 13},{(17 * i) % 181}\n"
                                                             for i in range(57)))
    code, whole, said = run(capsys, "loads", "apce_8x6", "--points", src, "--out", "-")
    monkeypatch.setattr(cl, "CHUNK", 10)
    code2, chunked, said2 = run(capsys, "loads", "apce_8x6", "--points", src, "--out", "-")
    assert code == code2 == 0 and chunked == whole and len(whole.splitlines()) == 58
    # the closing line counts each flag over every chunk
    table = list(csv.DictReader(io.StringIO(whole)))
    n_vrs = sum("vortex_ring" in r["flags"].split(";") for r in table)
    assert n_vrs > 0 and f"{n_vrs} vortex_ring" in said.splitlines()[-1] and said2 == said, said


# ---- only propmap's own warnings reach stderr, each once ----

def test_library_runtime_warnings_do_not_leak(capsys, monkeypatch):
    import warnings

    import propmap.cli.loads as cl

    real = cl.coverage_messages

    def noisy(*a, **k):
        warnings.warn("overflow encountered", RuntimeWarning)
        return real(*a, **k)

    monkeypatch.setattr(cl, "coverage_messages", noisy)
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "8000")
    assert code == 0 and "overflow" not in err


def test_risky_point_gets_a_one_line_warning(capsys):
    code, out, err = run(capsys, "loads", "apce_8x6", "--rpm", "40000", "--json")
    assert code == 0 and json.loads(out)["thrust"] > 0
    assert err.count("propmap: warning: tip Mach number up to") == 1


def test_the_console_entry_point_exits_fast_with_complete_output_and_the_exit_code(tmp_path):
    """run() ends the process with os._exit after flushing (skipping ~0.3 s of interpreter
    teardown): the output must still be complete and the exit code kept."""
    ok = subprocess.run([sys.executable, "-m", "propmap", "loads", "apce_8x6", "--rpm", "8000", "--json"],
                        capture_output=True, text=True)
    assert ok.returncode == 0 and json.loads(ok.stdout)["thrust"] > 0
    bad = subprocess.run([sys.executable, "-m", "propmap", "loads", "apce_8x6", "--rpm", "-1"],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and bad.stdout == ""
    # the module path too (it ran nothing and exited 0 whatever the arguments: a user-level audit, 2026-11-28)
    bad = subprocess.run([sys.executable, "-m", "propmap.cli.main", "loads", "apce_8x6", "--rpm", "-1"],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and bad.stdout == ""
    src = tmp_path / "in.csv"
    src.write_text("rpm,airspeed,incidence_deg\n" + "8000,5,30\n" * 3000)
    piped = subprocess.run(f"{sys.executable} -m propmap loads apce_8x6 --points {src} --out - | head -2",
                           shell=True, capture_output=True, text=True)
    assert len(piped.stdout.splitlines()) == 2 and "Traceback" not in piped.stderr


# ---- regression tests of the review of the hardening (each was mishandled) ----

@pytest.fixture
def replace_only_in(tmp_path, monkeypatch):
    """A safety net for the tests that name a system or package file as an output: should the refusal
    regress, io.atomic's final os.replace would put the output there (as root, a mutation audit's mutant
    replaced /dev/null, 2026-11-29); any replace outside tmp_path fails the test instead."""
    real = os.replace

    def replace(src, dst, *args, **kwargs):
        assert Path(os.path.abspath(dst)).is_relative_to(tmp_path), f"an output replaced {dst}"
        return real(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "replace", replace)


@pytest.mark.usefixtures("replace_only_in")
def test_an_existing_device_or_dangling_link_is_never_replaced(capsys, tmp_path, points):
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", points, "--out", "/dev/null")
    assert one_line_error(code, err, "not a regular file") and not os.path.isfile("/dev/null")
    os.symlink(tmp_path / "missing" / "x", tmp_path / "dang")
    for out in (tmp_path / "dang", tmp_path / "dang" / "o.csv"):
        code, _, err = run(capsys, "loads", "apce_8x6", "--points", points, "--out", out)
        assert one_line_error(code, err, "symbolic link"), err
    assert os.path.islink(tmp_path / "dang") and not (tmp_path / "missing").exists()


@pytest.mark.usefixtures("replace_only_in")
def test_the_package_data_is_never_an_output(capsys, tmp_path, points):
    from importlib import resources

    target = Path(str(resources.files("propmap") / "data" / "calibration.json"))
    before = target.read_bytes()
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", points, "--out", target)
    assert one_line_error(code, err, "file of the propmap package") and target.read_bytes() == before


def test_two_outputs_of_one_command_may_not_be_the_same_file(capsys, tmp_path):
    """A fit's --out f.png was its own figure (refused as two outputs of one name); since 2026-11-26 a
    parameter file's name must end in .toml, so no fit output can be another's (--out f.report.json
    wrote TOML over another fit's report: a JSON audit)."""
    for name in ("f.png", "g.report.json"):
        code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--out", tmp_path / name)
        assert one_line_error(code, err, "--out: a parameter file is TOML: give a name ending in .toml")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "text, match",
    [
        ("rpm,airspeed,incidence_deg\n5000,5,0,9\n", "line 2 has more fields than the header"),
        ("rpm;airspeed;incidence_deg\n5000;5;0;1\n6000;5;0\n", "line 2 has more fields than the header"),
        ("rpm,airspeed,incidence_deg\n5000,5,0\n6000,5,0,9\n", "--points"),
        ("rpm,airspeed,incidence_deg\n\n\n5000,5,0\n\n6000,5,-1\n", "line 6: incidence_deg"),
        ("rpm,airspeed," + "x" * 256 + ",incidence_deg\n5000,5,1,0\n", "a column name of 256 characters"),
        ("rpm,airspeed,incidence_deg\n5000,5,-30\n", "symmetric"),
        # (a disk angle of attack, negative in forward flight, is not a negative incidence)
        ("rpm,airspeed,incidence_deg\n5000,5,-10\n", "a disk angle of attack alpha_d, 0 edgewise and positive "
                                                        "with the disk tilted back against the airspeed, is "
                                                        "incidence 90 + alpha_d deg"),
    ],
)
def test_points_rows_are_checked_field_by_field_with_true_line_numbers(capsys, tmp_path, text, match):
    src = tmp_path / "in.csv"
    src.write_text(text)
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", src, "--out", "-")
    assert one_line_error(code, err, match), err


def test_points_quoted_header_and_input_cells_written_as_read(capsys, tmp_path):
    src = tmp_path / "in.csv"
    src.write_text('"rpm","airspeed","incidence_deg","thrust","thrust_model"\n5000.000,5.25,0,1.5,MYDATA\n')
    code, out, err = run(capsys, "loads", "apce_8x6", "--points", src, "--out", "-")
    assert code == 0, err
    row = list(csv.DictReader(out.splitlines()))[0]
    assert (row["rpm"], row["airspeed"], row["thrust"], row["thrust_model"]) == ("5000.000", "5.25", "1.5", "MYDATA")
    assert float(row["thrust_model_model"]) > 0  # the model's thrust, under a free name


def test_geometry_options_are_never_silently_ignored(capsys, tmp_path, shared_data):
    from importlib import resources

    pe0 = next(Path(str(resources.files("propmap") / "data" / "apc_pe0")).glob("*.PE0"))
    code, _, err = run(capsys, "loads", pe0, "--rpm", "8000", "--diameter-in", "20")
    assert one_line_error(code, err, "a PE0 file gives its own radius")
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--blades", "3", "--out", tmp_path / "o.toml")
    assert one_line_error(code, err, "catalogue propeller") and list(tmp_path.iterdir()) == []


def test_long_names_are_named_with_their_option(capsys, tmp_path, points):
    long = "a" * 300
    cases = [(["loads", long, "--rpm", "8000"], "PROP: "),
             (["loads", "apce_8x6", "--rpm", "8000", "--params", tmp_path / f"{long}.toml"], "--params: "),
             (["loads", "apce_8x6", "--points", tmp_path / f"{long}.csv", "--out", tmp_path / "o.csv"], "--points: "),
             (["loads", "apce_8x6", "--points", points, "--out", tmp_path / f"{long}.csv"], "--out: ")]
    for argv, prefix in cases:
        code, _, err = run(capsys, *argv)
        assert one_line_error(code, err, prefix) and "too long" in err.lower(), err


def test_bare_commands_print_their_help(capsys):
    for argv in ([], ["fit"]):
        code, out, err = run(capsys, *argv)
        assert code == 0 and out.startswith("Usage: propmap") and err == ""


def test_validate_figure_format_follows_the_extension(capsys, tmp_path):
    code, _, err = run(capsys, "validate", "apce_8x6", "--figure", tmp_path / "v.xyz")
    assert one_line_error(code, err, ".png, .pdf or .svg") and list(tmp_path.iterdir()) == []
    code, _, err = run(capsys, "validate", "apce_8x6", "--figure", tmp_path / "v.pdf")
    assert code == 0 and (tmp_path / "v.pdf").read_bytes()[:4] == b"%PDF"
    code, _, err = run(capsys, "validate", "apce_8x6", "--protocols", "loso")
    assert one_line_error(code, err, "--protocols applies to --all")


def test_pe0_chord_beyond_the_radius_is_refused_naming_the_line(capsys, tmp_path):
    from importlib import resources

    pe0 = Path(str(resources.files("propmap") / "data" / "apc_pe0" / "10x4-PERF.PE0"))
    lines = pe0.read_text(encoding="latin-1").splitlines(keepends=True)
    k = next(i for i, ln in enumerate(lines) if "STATION" in ln and "TWIST" in ln) + 3
    cells = lines[k].split()
    cells[1] = "1e300"
    lines[k] = "  ".join(cells) + "\n"
    bad = tmp_path / "10x4-PERF.PE0"
    bad.write_text("".join(lines), encoding="latin-1")
    code, _, err = run(capsys, "loads", bad, "--rpm", "8000")
    assert one_line_error(code, err, f"line {k + 1}: CHORD = 1e+300 in is outside"), err


def test_a_long_non_ascii_name_is_measured_in_bytes(capsys, tmp_path):
    """The name limit is in bytes: 120 accented characters (240 bytes) were said to be '120
    characters ... give at most 241 characters' (a JSON/pipeline audit, 2026-11-26)."""
    code, _, err = run(capsys, "fit", "loads", "apce_8x6", "--out", tmp_path / ("é" * 120 + ".toml"))
    assert one_line_error(code, err, "--out: ") and "(245 bytes, 125 characters) is too long" in err, err
    assert "bytes" in err.split("give at most")[1]


def test_an_output_that_is_a_link_is_written_through_and_the_package_and_blanks_are_refused(tmp_path, capsys,
                                                                                            monkeypatch):
    """--out naming a symbolic link to a file replaced the link with a regular file and left its
    target as it was (/dev/stdout too, run as root); an --out under the package's code (cli/main.py)
    was written over (only data/ was protected); loads --out ' ' wrote a file named with a blank
    (a CLI audit)."""
    import propmap

    monkeypatch.chdir(tmp_path)
    (tmp_path / "in.csv").write_text("rpm,airspeed,incidence_deg\n5000,0,0\n", encoding="utf-8")
    (tmp_path / "target.csv").write_text("old\n", encoding="utf-8")
    (tmp_path / "link.csv").symlink_to("target.csv")
    assert main(["loads", "apce_8x6", "--points", "in.csv", "--out", "link.csv"]) == 0
    assert (tmp_path / "link.csv").is_symlink()
    assert (tmp_path / "target.csv").read_text(encoding="utf-8").startswith("rpm,airspeed,incidence_deg,thrust")
    code = Path(propmap.__file__).parent / "cli" / "main.py"  # (protected; the test aims at a new name beside it,
    new = code.with_name("not_an_output.csv")                 # so that a regression writes no source file over)
    before = code.read_bytes()
    for out, said in ((str(new), "is a file of the propmap package (its code or bundled data)"),
                      (" ", "the path ' ' is only blanks"), ("\t", "the path '\\t' is only blanks")):
        capsys.readouterr()
        assert main(["loads", "apce_8x6", "--points", "in.csv", "--out", out]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and said in err[0], err
    assert code.read_bytes() == before and not new.exists() and not (tmp_path / " ").exists()


def test_an_output_that_is_a_standard_stream_is_refused(tmp_path, capsys, monkeypatch):
    """Written through, `--out /dev/stdout >> log.txt` replaced log.txt (an atomic rename of the
    file the stream was redirected to; a review): a stream or an open descriptor, or a link to
    one, is refused, pointing to '-'."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "in.csv").write_text("rpm,airspeed,incidence_deg\n5000,0,0\n", encoding="utf-8")
    (tmp_path / "mystd").symlink_to("/proc/self/fd/1")
    (tmp_path / "la").symlink_to("lb")  # (a loop of links: the stream check follows at most 40)
    (tmp_path / "lb").symlink_to("la")
    assert main(["loads", "apce_8x6", "--points", "in.csv", "--out", "la"]) == 2
    assert "a symbolic link to a missing file" in capsys.readouterr().err
    for out in ("/dev/stdout", "/dev/fd/1", "/proc/self/fd/1", "mystd"):
        capsys.readouterr()
        assert main(["loads", "apce_8x6", "--points", "in.csv", "--out", out]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and "is a standard stream or an open file descriptor" in err[0], err


def test_a_params_path_that_is_no_regular_file_is_named_as_such(tmp_path, capsys):
    """--params /dev/null or a folder read as 'not a named set nor an existing file' (a CLI audit)."""
    for spec, said in (("/dev/null", "/dev/null: not a regular file (a device, pipe or socket)"),
                       (str(tmp_path), "is a directory, not a file")):
        capsys.readouterr()
        assert main(["loads", "apce_8x6", "--rpm", "5000", "--params", spec]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and said in err[0], err


def test_the_error_is_the_last_line_after_the_warnings(capsys, tmp_path):
    """A vehicle file's warning was printed after the command's error line, so that stderr's last
    line was a warning (an input fuzzing audit, 2026-11-27: a mass in grams)."""
    from propmap.cli.main import main

    veh = (Path(__file__).parents[1] / "src" / "propmap" / "data" / "examples" / "quadrotor.toml").read_text()
    assert "mass = 0.8" in veh
    v = tmp_path / "veh.toml"
    v.write_text(veh.replace("mass = 0.8", "mass = 800"))  # grams: warned of
    data = tmp_path / "lf.csv"
    data.write_text("airspeed,pitch_deg,rpm_1,rpm_2,rpm_3,rpm_4\n1,0,5000,5000,5000,5000\n")  # one row: refused
    assert main(["fit", "level-flight", str(data), "--vehicle", str(v), "--out", str(tmp_path / "p.toml")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) >= 2 and err[-1].startswith("propmap: error: ") and all(
        ln.startswith("propmap: warning: ") for ln in err[:-1]), err


# ---- a fresh installation's first model command compiles for minutes: said on a terminal ----

def test_a_terminal_is_told_once_when_the_kernels_compile_and_a_pipe_is_not(monkeypatch, capsys):
    import numba

    from propmap.cli.main import COMPILE_NOTICE, _compile_notice

    def kernel(x):  # compiled in the test, as a kernel of propmap's (the notice is for propmap's own compiles)
        return x + 1.0

    def other(x):
        return x - 1.0

    kernel.__module__ = "propmap.core._probe"
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    with _compile_notice(["loads", "apce_8x6", "--rpm", "5000"]):
        numba.njit(other)(1.0)  # another package's compile: nothing
        assert capsys.readouterr().err == ""
        assert numba.njit(kernel)(1.0) == 2.0
        numba.njit(kernel)(1)  # a second compile (another function object, another signature): said once
    assert capsys.readouterr().err == COMPILE_NOTICE + "\n"
    assert "once" in COMPILE_NOTICE and "cache" in COMPILE_NOTICE
    with _compile_notice(["props"]):  # a command that never runs the model: no listener
        numba.njit(kernel)(2.0)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: False)
    with _compile_notice(["loads", "apce_8x6", "--rpm", "5000"]):  # a pipe or a file: scripts get nothing
        numba.njit(kernel)(3.0)
    assert capsys.readouterr().err == ""
