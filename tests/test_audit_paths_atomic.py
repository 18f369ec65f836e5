"""A mutation audit of cli/_paths.py, io/atomic.py and cli/main.py's error handling (2026-11-29): each test kills a hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""  # noqa: E501

import errno
import os
import shutil
import stat
from importlib import resources
from pathlib import Path

import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.core.solver import SolverError

EXAMPLES = Path(str(resources.files("propmap") / "data" / "examples"))
UIUC = Path(str(resources.files("propmap") / "data" / "uiuc_v1"))
#: a tiny grid: a map in well under a second
TINY = ["--rpm", "3000:9000:4", "--airspeed", "0:10:3", "--incidence-deg", "0:180:5", "--check-points", "0"]


def error_line(capsys, argv) -> tuple[int, str]:
    """Run the CLI; (exit code, its one stderr line), asserting that stderr is one line and no traceback."""
    code = main([str(a) for a in argv])
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return code, lines[0]


def test_a_missing_log_is_named_no_such_file(capsys, tmp_path, monkeypatch):
    """Kills P01 (refuse_copies said the system's 'no such file or directory' where its docstring and the
    other readers say 'X: no such file'): a LOG that does not exist is named, as its option's."""
    monkeypatch.chdir(tmp_path)
    code, line = error_line(capsys, ["fit", "flight", "nolog.csv", "--vehicle", "quadrotor", "--out", "p.toml"])
    assert (code, line) == (2, "propmap: error: LOG: nolog.csv: no such file")
    assert list(tmp_path.iterdir()) == []


def test_a_copy_is_named_after_the_file_it_copies(capsys, tmp_path, monkeypatch):
    """Kills P05 (the two names swapped): 'SOURCE: X is a copy of Y' names the later file X as the copy of
    the earlier Y, in the order given, and nothing is written."""
    monkeypatch.chdir(tmp_path)
    static = sorted(UIUC.glob("apce_10x7_static_*.txt"))[0]
    shutil.copyfile(static, tmp_path / "first.txt")
    shutil.copyfile(static, tmp_path / "second.txt")
    for a, b in (("first.txt", "second.txt"), ("second.txt", "first.txt")):
        code, line = error_line(capsys, ["fit", "loads", a, b, "--prop", "apce_10x7", "--out", "p.toml"])
        assert (code, line) == (2, f"propmap: error: SOURCE: {b} is a copy of {a}: its data would count twice")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["first.txt", "second.txt"]


def test_a_rotor_parameter_file_of_the_vehicle_is_never_a_fit_output(capsys, tmp_path, monkeypatch):
    """Kills P11 (vehicle_inputs took the rotors' propeller files only): a vehicle's [[rotors]] params file is
    an input of `fit level-flight --vehicle`, refused as its --out before any work, its bytes unchanged."""
    monkeypatch.chdir(tmp_path)
    veh = (EXAMPLES / "quadrotor.toml").read_text(encoding="utf-8")
    assert veh.count('propeller = "apce_8x6"\n') == 4
    (tmp_path / "veh.toml").write_text(veh.replace('propeller = "apce_8x6"\n',
                                                   'propeller = "apce_8x6"\nparams = "rp.toml"\n'), encoding="utf-8")
    pm.write_params(tmp_path / "rp.toml", pm.preset("gill2017-apc"))
    before = (tmp_path / "rp.toml").read_bytes()
    code, line = error_line(capsys, ["fit", "level-flight", EXAMPLES / "level_flight_synthetic.csv", "--vehicle",
                                     "veh.toml", "--out", "rp.toml"])
    assert code == 2 and line.startswith("propmap: error: --out: rp.toml is the input file "), line
    assert line.endswith("rp.toml; refusing to overwrite an input"), line
    assert (tmp_path / "rp.toml").read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rp.toml", "veh.toml"]


def test_an_empty_out_is_said_to_be_empty(capsys, tmp_path, monkeypatch):
    """Kills P14 (the empty-path check dropped: `loads --out ''` read "the path '' is only blanks"): an empty
    --out (a plain option of loads, not a PathArg) is 'the path is empty', before the points are read."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n8000,0,0\n", encoding="utf-8")
    code, line = error_line(capsys, ["loads", "apce_8x6", "--points", "p.csv", "--out", ""])
    assert (code, line) == (2, "propmap: error: --out: the path is empty")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.csv"]


def test_a_sidecar_that_is_a_link_to_the_map_is_refused(capsys, tmp_path, monkeypatch):
    """Kills P17 (two outputs resolving to one file not refused): a map's sidecar name that is a symbolic link
    to the --out file is 'the same file as another output' (docs/cli.md); refused, the map left as it was."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "m.nc").write_bytes(b"old map")
    (tmp_path / "m.nc.json").symlink_to("m.nc")
    code, line = error_line(capsys, ["map", "apce_8x6", *TINY, "--out", "m.nc"])
    assert (code, line) == (2, "propmap: error: --out (sidecar): m.nc.json is also the file of --out; give outputs "
                               "different names")
    assert (tmp_path / "m.nc").read_bytes() == b"old map" and os.readlink(tmp_path / "m.nc.json") == "m.nc"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.nc", "m.nc.json"]


def test_a_folder_out_is_called_a_folder(capsys, tmp_path, monkeypatch):
    """Kills P26 (the folder check dropped: a folder read 'not a regular file (a device, pipe or socket)'):
    an existing folder as --out is refused as a folder, and nothing is written in it."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "adir").mkdir()
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n8000,0,0\n", encoding="utf-8")
    code, line = error_line(capsys, ["loads", "apce_8x6", "--points", "p.csv", "--out", "adir"])
    assert (code, line) == (2, "propmap: error: --out: adir is a folder; give a file name")
    assert list((tmp_path / "adir").iterdir()) == []


def test_a_link_to_a_file_is_checked_as_that_file(capsys, tmp_path, monkeypatch):
    """Kills P29 (a link's own folder and name probed, not its target's): an --out that is a symbolic link to a
    file whose name is too long once the temporary file's affixes are added is refused before any work (the
    mutant ran the work and failed at the write), the target left as it was."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n8000,0,0\n", encoding="utf-8")
    name = "t" * 246 + ".csv"  # (250 bytes: a valid name, too long with '.NAME.' + 8 characters + '.tmp')
    (tmp_path / name).write_text("old\n", encoding="utf-8")
    (tmp_path / "link.csv").symlink_to(name)
    code, line = error_line(capsys, ["loads", "apce_8x6", "--points", "p.csv", "--out", "link.csv"])
    assert code == 2 and line.startswith("propmap: error: --out: the name 'tttt"), line
    assert line.endswith("(250 bytes, 250 characters) is too long with the temporary file's affixes; give at most "
                         "241 bytes"), line
    assert (tmp_path / name).read_text(encoding="utf-8") == "old\n" and (tmp_path / "link.csv").is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([name, "link.csv", "p.csv"])


def test_missing_parent_folders_are_created(capsys, tmp_path, monkeypatch):
    """Kills P30 (the walk up to an existing folder stopped after one level: `--out a/b/o.csv` read 'lies below
    a, which is a file, not a folder'): missing parent folders, two levels here, are created (docs/cli.md)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n8000,0,0\n", encoding="utf-8")
    assert main(["loads", "apce_8x6", "--points", "p.csv", "--out", "a/b/o.csv"]) == 0, capsys.readouterr().err
    assert (tmp_path / "a" / "b" / "o.csv").read_text(encoding="utf-8").startswith("rpm,airspeed,incidence_deg,")
    assert sorted(p.name for p in (tmp_path / "a" / "b").iterdir()) == ["o.csv"]


def test_an_out_below_a_file_is_said_to_lie_below_a_file(capsys, tmp_path, monkeypatch):
    """Kills P32 (the check dropped: the line read 'cannot write in p.csv (permission denied)', from the access
    bits of a file, or the probe's 'Not a directory' for an executable one): an --out below a regular file is
    refused naming that file, before any work, the file unchanged."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n8000,0,0\n", encoding="utf-8")
    for mode in (0o644, 0o755):
        (tmp_path / "p.csv").chmod(mode)
        code, line = error_line(capsys, ["loads", "apce_8x6", "--points", "p.csv", "--out", "p.csv/sub/o.csv"])
        assert (code, line) == (2, "propmap: error: --out: p.csv/sub/o.csv lies below p.csv, which is a file, not a "
                                   "folder")
    assert (tmp_path / "p.csv").read_text(encoding="utf-8") == "rpm,airspeed,incidence_deg\n8000,0,0\n"


def test_an_out_dir_that_is_a_file_is_said_not_to_be_a_folder(capsys, tmp_path, monkeypatch):
    """Kills P39 (check_out_dir's own check dropped: the line named one of the figures, 'x.csv/envelope.csv lies
    below x.csv'): a --out-dir that is a regular file is refused as such, the file unchanged."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "x.csv").write_text("keep\n", encoding="utf-8")
    code, line = error_line(capsys, ["demo", "--out-dir", "x.csv"])
    assert (code, line) == (2, "propmap: error: --out-dir: x.csv exists and is not a folder")
    assert (tmp_path / "x.csv").read_text(encoding="utf-8") == "keep\n"


def test_a_new_output_takes_0o666_less_the_umask_whatever_the_umask(capsys, tmp_path, monkeypatch):
    """Kills A04 (a new file always 0o644, right for the common umask 022 only): a new output's mode is 0o666
    less the process' umask (docs/cli.md), here under the umasks 077 and 002."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n8000,0,0\n", encoding="utf-8")
    for mask, want in ((0o077, 0o600), (0o002, 0o664)):
        out = tmp_path / f"o{mask:o}.csv"
        old = os.umask(mask)
        try:
            code = main(["loads", "apce_8x6", "--points", "p.csv", "--out", out.name])
        finally:
            os.umask(old)
        assert code == 0, capsys.readouterr().err
        assert (stat.S_IMODE(out.stat().st_mode), out.read_text(encoding="utf-8")[:4]) == (want, "rpm,")


@pytest.mark.parametrize("raised, code, said", [
    # C03: a solver failure (click.ClickException) exits 1, not 2
    (SolverError("no inflow root at 5000 rpm, r/R = 0.70"), 1,
     "propmap: error: no inflow root at 5000 rpm, r/R = 0.70"),
    # C05, C06: an unusable file the command did not name: the system's reason and the file, exit 2
    (OSError(errno.ENOSPC, "No space left on device", "o.csv"), 2, "propmap: error: No space left on device: o.csv"),
    # C07, C01: bad input that reached the library: exit 2, on one line however the message breaks
    (ValueError("airspeed 31 m/s\n  beyond the table"), 2, "propmap: error: airspeed 31 m/s beyond the table"),
    # C09: out of memory is too large an input, exit 2, not a bug
    (MemoryError(), 2, "propmap: error: out of memory (MemoryError): the input is too large for this machine's memory; "
                       "give less at once (a shorter log, fewer points, a lower --rate-hz or a smaller grid)"),
    # C01, C10: a bug: still one line, and how to report it
    (RuntimeError("state\nlost"), 1, "propmap: error: internal error (RuntimeError: state lost); please report it "
                                     "with the command line"),
])
def test_each_kind_of_failure_has_its_exit_code_and_one_line(capsys, monkeypatch, raised, code, said):
    """Kills C01 (_one_line kept a message's line breaks), C03 (a ClickException's own exit code replaced by 2),
    C05 (an OSError's file not named), C06 and C07 (OSError and ValueError exited 1), C09 (MemoryError reported as
    an internal error) and C10 (an internal error exited 2): main()'s exit codes and its one stderr line
    (docs/cli.md; cli.main.main's docstring), for an exception raised where the model runs."""
    def fail(*args, **kwargs):
        raise raised

    monkeypatch.setattr("propmap.core.solver.rotor_loads", fail)
    assert error_line(capsys, ["loads", "apce_8x6", "--rpm", "5000"]) == (code, said)


def test_a_library_exit_with_a_message_is_a_failure(capsys, monkeypatch):
    """Kills C08 (a SystemExit whose code is not a number exited 0): a library's sys.exit('...') inside a command
    ends the run as a failure, exit 1 (as Python's own exit of a message), never as a success."""
    def fail(*args, **kwargs):
        raise SystemExit("a library gave up")

    monkeypatch.setattr("propmap.core.solver.rotor_loads", fail)
    assert main(["loads", "apce_8x6", "--rpm", "5000"]) == 1
    assert capsys.readouterr().out == ""


def test_a_reader_holding_the_folder_lock_keeps_the_files_as_they_are(tmp_path):
    """Kills A18 (the writers' lock on the folder taken shared): files are replaced under an exclusive flock of
    their folder (io.atomic.atomic_paths), so that a reader holding a shared lock sees them unchanged until it
    lets go; then the write completes."""
    import fcntl
    import threading
    import time

    from propmap.io.atomic import atomic_write

    target = tmp_path / "f.txt"
    target.write_text("old\n", encoding="utf-8")
    fd = os.open(tmp_path, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_SH)

        def write():
            with atomic_write(target) as fh:
                fh.write("new\n")

        writer = threading.Thread(target=write)
        writer.start()
        time.sleep(1.0)
        assert writer.is_alive() and target.read_text(encoding="utf-8") == "old\n"
    finally:
        os.close(fd)  # (releases the lock)
    writer.join(timeout=30)
    assert not writer.is_alive() and target.read_text(encoding="utf-8") == "new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["f.txt"]


def test_the_callers_sigterm_handler_is_back_after_a_run(capsys):
    """Kills C11 (main left its own SIGTERM handler installed): main() installs its handler for the run only;
    the caller's is back afterwards (for a program that calls main, or a second run in one process)."""
    import signal
    import threading

    assert threading.current_thread() is threading.main_thread()  # (signal handlers: the main thread's only)

    def mine(signum, frame):
        pass

    before = signal.signal(signal.SIGTERM, mine)
    try:
        assert main(["props"]) == 0
        assert signal.getsignal(signal.SIGTERM) is mine
    finally:
        signal.signal(signal.SIGTERM, before)
    assert "apce_8x6" in capsys.readouterr().out


def test_another_librarys_user_warning_is_not_printed(capsys, monkeypatch):
    """Kills C13 (every UserWarning printed, wherever it came from): only propmap's own warnings are printed as
    'propmap: warning:' lines; another library's (here raised from this file, outside the package) is not."""
    import warnings

    import propmap.core.solver as solver

    real = solver.rotor_loads

    def noisy(*args, **kwargs):
        warnings.warn("another library's notice", UserWarning)
        return real(*args, **kwargs)

    monkeypatch.setattr(solver, "rotor_loads", noisy)
    assert main(["loads", "apce_8x6", "--rpm", "5000"]) == 0
    out, err = capsys.readouterr()
    assert (err, out.splitlines()[0]) == ("", "apce_8x6 at 5000 rpm, V = 0 m/s, incidence 0 deg (params "
                                              "calibrated:apce_8x6)")



UNDELIVERED = r"""
import os, signal
import propmap.core.solver as solver
from propmap.cli import main as m
m._redeliver = lambda signum: None  # (the run ends before the re-delivery: modelled by none)
real = solver.rotor_loads
src = ("def _raw_object_cache_notify():\n    import os, signal\n    os.kill(os.getpid(), signal.SIGTERM)\n"
       "    for _ in range(10000): pass\n_raw_object_cache_notify()\n")
def loads(*args, **kwargs):  # a SIGTERM inside a C callback (llvmlite's, while numba compiles): not raised there
    exec(compile(src, "/site-packages/llvmlite/binding/executionengine.py", "exec"))
    return real(*args, **kwargs)
solver.rotor_loads = loads
print("code", m.main(["loads", "apce_8x6", "--rpm", "5000"]), flush=True)
"""


def test_a_run_that_got_a_sigterm_says_so_even_when_it_ended_first(tmp_path):
    """Kills C16 (main returned the command's own code): a SIGTERM that arrived while C code called back into
    Python is delivered again after the callback; a run that ends before that still exits 128 + 15, the code of
    a run stopped by SIGTERM (cli.main.main's docstring), not 0."""
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", UNDELIVERED], capture_output=True, text=True, timeout=300,
                         cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines()[-1] == "code 143", out.stdout
    assert "Traceback" not in out.stderr and "Exception ignored" not in out.stderr, out.stderr


TWO_SPELLINGS = """
import os, sys
from pathlib import Path
from propmap.io.atomic import atomic_paths
os.chdir(sys.argv[1])
with atomic_paths([Path("a.txt"), Path(sys.argv[1]) / "b.txt"]) as (ta, tb):
    ta.write_text("a", encoding="utf-8")
    tb.write_text("b", encoding="utf-8")
print(sorted(os.listdir(".")), flush=True)
"""


def test_a_pair_in_one_folder_named_two_ways_is_written(tmp_path):
    """A defect found by P17's mutant: _folder_locks took one exclusive flock per folder *name*, so that a pair
    whose folder was spelled two ways ('.' and its full path) locked the folder twice and waited on itself for
    ever (`propmap export-sim ... --out c.json` with c.json a link to a file in the working folder hung after
    the fit). One lock a folder; the pair is written (in a child process: the defect hangs)."""
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", TWO_SPELLINGS, str(tmp_path)], capture_output=True, text=True,
                         timeout=60)
    assert (out.returncode, out.stdout.strip()) == (0, "['a.txt', 'b.txt']"), out.stderr
    assert (tmp_path / "a.txt").read_text(encoding="utf-8") == "a" and (tmp_path / "b.txt").read_text() == "b"


LANDS_AFTER_MKSTEMP = r"""
import os, signal, sys, tempfile
from propmap.cli.main import main
folder, nth = sys.argv[1], int(sys.argv[2])
real = tempfile.mkstemp
calls = []
def mkstemp(*args, **kwargs):  # a SIGTERM that lands once the file exists, before mkstemp has returned its name
    fd, name = real(*args, **kwargs)
    calls.append(name)
    if len(calls) == nth:
        os.kill(os.getpid(), signal.SIGTERM)
        for _ in range(1000):  # (bytecode boundaries: where Python runs the handler)
            pass
    return fd, name
tempfile.mkstemp = mkstemp
code = main(["loads", "apce_8x6", "--points", os.path.join(folder, "p.csv"), "--out", os.path.join(folder, "o.csv")])
print(code, len(calls), sorted(os.listdir(folder)), flush=True)
"""


@pytest.mark.parametrize("nth, which", [(1, "the check's probe (cli._paths._probe)"),
                                        (2, "the output's temporary file (io.atomic.atomic_paths)")])
def test_a_sigterm_as_a_temporary_file_is_made_leaves_none(tmp_path, nth, which):
    """A defect found while auditing (an unrelated mutant's run failed test_cli_hostile's SIGTERM test with a
    '.out.csv.<random>.tmp' left): a SIGTERM that landed between a temporary file's creation and the code that
    removes it on failure learning its name left it behind (io.atomic's docstring: removed when the process is
    stopped by SIGTERM). Both temporary files, the probe of the output's folder and the output's own, are now made
    with SIGINT and SIGTERM held: the run stops (exit 143) and leaves nothing."""
    import subprocess
    import sys

    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence_deg\n5000,0,0\n", encoding="utf-8")
    out = subprocess.run([sys.executable, "-c", LANDS_AFTER_MKSTEMP, str(tmp_path), str(nth)], capture_output=True,
                         text=True, timeout=300, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == f"143 {nth} ['p.csv']", (which, out.stdout, out.stderr)
    assert "Traceback" not in out.stderr, out.stderr
