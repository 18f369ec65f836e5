"""The ``propmap`` command line: a thin layer over the public API."""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
import threading
import warnings

import click

from ..core.air import TipMachWarning
from ..io.coverage import CoverageWarning
from .. import __version__
from ._common import RUN_WARNINGS, one_line as _one_line, package_warning
from .demo import demo
from .export_sim import export_sim_command
from .fit import fit
from .flight import fit_flight_command, wrench_command
from .loads import loads
from .map import map_command
from .props import props
from .trim import trim_command
from .trim_vehicle import trim_vehicle_command
from .validate import validate


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="propmap")
def cli() -> None:
    """Thrust, rotor drag and torque of small propellers (Gill & D'Andrea 2017)."""


for _cmd in (props, loads, trim_command, trim_vehicle_command, wrench_command, map_command, export_sim_command,
             validate, fit, demo):
    cli.add_command(_cmd)
fit.add_command(fit_flight_command)


# Python code that C calls back into (llvmlite's object-cache hooks while numba compiles):
# an exception raised there is printed as "Exception ignored ..." with its traceback and
# dropped, and the run went on to exit 0 (seen once in CI, a SIGTERM during a worker's
# compilation). Those hooks, by file and name:
_CALLBACKS = (("/llvmlite/", "_raw_object_cache_notify"), ("/llvmlite/", "_raw_object_cache_getbuffer"))
_terminated: list[int] = []  # the signal that stopped the run, once one has
_redelivery: list[threading.Timer] = []  # the pending re-delivery, cancelled when the run ends


def _in_callback(frame) -> bool:
    while frame is not None:
        code = frame.f_code
        if any(d in code.co_filename and code.co_name == name for d, name in _CALLBACKS):
            return True
        frame = frame.f_back
    return False


def _redeliver(signum: int) -> None:
    # a real signal to the main thread (it also interrupts a blocking call there), and only
    # while this handler is still the one installed: after the run the caller's is back
    if signal.getsignal(signum) is _on_sigterm:
        signal.pthread_kill(threading.main_thread().ident, signum)


def _on_sigterm(signum, frame):  # pragma: no cover (exercised in a subprocess test)
    _terminated.append(signum)
    if _in_callback(frame):  # deliver it again after the callback
        timer = threading.Timer(0.05, _redeliver, (signum,))
        timer.daemon = True
        _redelivery.append(timer)
        timer.start()
        return
    raise SystemExit(128 + signum)


def main(argv: list[str] | None = None) -> int:
    """Run the CLI with ``argv``; return the exit code.

    0 ok; 1 a solver failure, an unexpected internal error or standard output closed by
    its reader; 2 bad input, an unusable file or out of memory; 130 interrupted; 128 + n stopped by
    signal n. Every error is one line
    ``propmap: error: ...`` on stderr, never a traceback. propmap's own warnings are printed
    as ``propmap: warning: ...`` lines; other libraries' warnings (NumPy's and SciPy's
    numerical RuntimeWarnings, deprecation notices) are not printed (the results carry their
    own flags). SIGTERM, and SIGHUP where it is not ignored (``nohup``), stop the run like an
    exception, so that no temporary output file is left behind (one that arrives while C
    code calls back into Python, as numba's compiler does, is delivered again after it).
    On a terminal a run that compiles the model's kernels (a fresh installation's first) says
    so first, in one line that is neither a warning nor an error (:data:`COMPILE_NOTICE`).
    """
    _terminated.clear()
    words = sys.argv[1:] if argv is None else list(argv)
    if words and words[0] in _RECORDING:  # (the source digest they record: of the code that runs, taken now)
        from ..io.provenance import source_digest

        source_digest()
    with _compile_notice(words):
        code = _main(argv)
    return 128 + _terminated[-1] if _terminated else code


#: said once, on a terminal, when a run compiles the model's kernels: a fresh installation's first model command
#: compiles for 36 s (loads) up to about 3 minutes (every kernel family, 174 s) on a 2-core machine (docs/cli.md,
#: benchmarks/README.md), silent until then, which a user could take for a hang
COMPILE_NOTICE = ("propmap: compiling the model's kernels for this machine, once (under a minute to a few minutes; "
                  "later runs load them from the cache)")
#: the commands and options that never run the model: no listener (numba's import, 0.3 s) for them
_NO_MODEL = ("props", "-h", "--help", "--version")


@contextlib.contextmanager
def _compile_notice(words):
    """While the run lasts, :data:`COMPILE_NOTICE` on stderr at the first compile of a propmap
    kernel (numba's compile event, which a kernel served from the cache does not raise), when
    stderr is a terminal; nothing for a pipe or a file (scripts, tests), nothing where numba's
    event API is missing. Compiles in other processes (``validate --all --jobs``' workers, a
    dask cluster's) are not seen."""
    try:
        interactive = sys.stderr.isatty()
    except (AttributeError, ValueError, OSError):  # (closed or replaced)
        interactive = False
    if not interactive or not words or any(w in _NO_MODEL for w in words):
        yield
        return
    try:
        from numba.core import event
    except ImportError:  # pragma: no cover (numba without its event API)
        yield
        return

    class Notice(event.Listener):
        said = False

        def on_start(self, ev):
            dispatcher = ev.data.get("dispatcher") if isinstance(ev.data, dict) else None
            module = getattr(getattr(dispatcher, "py_func", None), "__module__", "") or ""
            if not self.said and module.startswith("propmap."):
                self.said = True
                try:
                    click.echo(COMPILE_NOTICE, err=True)
                except OSError:  # (the terminal gone: the run goes on, as the compile does)
                    pass

        def on_end(self, ev):
            pass

    with event.install_listener("numba:compile", Notice()):
        yield


#: the commands whose outputs record the package's source digest (io/provenance.py)
_RECORDING = ("map", "export-sim", "fit", "demo")


def _main(argv: list[str] | None) -> int:
    previous = {}
    # SIGHUP (a closed terminal, a dropped ssh session) as SIGTERM where it is not ignored (nohup): it killed a run
    # without a word and left map --all's parts folder behind (an audit, stop 100)
    stops = [signal.SIGTERM]
    if hasattr(signal, "SIGHUP") and signal.getsignal(signal.SIGHUP) is signal.SIG_DFL:
        stops.append(signal.SIGHUP)
    try:
        for s in stops:
            previous[s] = signal.signal(s, _on_sigterm)
    except ValueError:  # not the main thread
        pass
    caught: list = []
    RUN_WARNINGS.update(said=[], caught=[], active=True)
    said: list[str] = []  # the error line, printed after the warnings (the last line is the error)
    try:
        with warnings.catch_warnings(record=True) as caught:
            RUN_WARNINGS["caught"] = caught  # (the --json outputs' warnings: _common.run_warnings)
            warnings.simplefilter("always")
            # the API's supersonic-tip warning (with its "rpm for rad/s?" hint): the commands take rpm and warn
            # from tip Mach 0.7 themselves (cli._coverage.coverage_messages)
            warnings.filterwarnings("ignore", category=TipMachWarning)
            # the API's warnings of a run beyond its set's data (build_map's): the commands say them as theirs
            warnings.filterwarnings("ignore", category=CoverageWarning)
            code = cli.main(args=argv, prog_name="propmap", standalone_mode=False)
        if isinstance(code, int) and code:  # click returns (not raises) an Exit's code in this mode
            return code
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except click.exceptions.Abort:
        said.append("propmap: aborted")
        return 130
    except click.exceptions.NoArgsIsHelpError as exc:  # `propmap` or `propmap fit` alone: the help
        click.echo(exc.ctx.get_help() if exc.ctx else cli.get_help(click.Context(cli)))
        return 0
    except click.UsageError as exc:  # unknown option, bad type, missing argument: exit 2
        said.append(f"propmap: error: {_one_line(exc.format_message())}")
        return 2
    except click.ClickException as exc:
        said.append(f"propmap: error: {_one_line(exc.format_message())}")
        return exc.exit_code
    except KeyboardInterrupt:
        said.append("propmap: interrupted")
        return 130
    except OSError as exc:  # an unusable file the commands did not name (the system's reason and the file)
        from ..io.inputs import short_path

        name = short_path(exc.filename) if exc.filename else ""
        said.append(f"propmap: error: {exc.strerror or _one_line(exc)}{': ' + name if name else ''}")
        return 2
    except ValueError as exc:  # bad input that reached the library
        said.append(f"propmap: error: {_one_line(exc)}")
        return 2
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else 1
    except MemoryError as exc:  # (an input too large for this machine, not a bug: it read "please report it")
        said.append(f"propmap: error: out of memory ({_one_line(exc) or 'MemoryError'}): the input is too large for "
                    "this machine's memory; give less at once (a shorter log, fewer points, a lower --rate-hz or a "
                    "smaller grid)")
        return 2
    except Exception as exc:  # a bug: still one line, and how to report it
        said.append(f"propmap: error: internal error ({type(exc).__name__}: {_one_line(exc)}); "
                    "please report it with the command line")
        return 1
    finally:
        for timer in _redelivery:
            timer.cancel()
        _redelivery.clear()
        for s, handler in previous.items():
            signal.signal(s, handler)
        # (those warn() printed: a library warning of the same text, on one line, is not said twice; the --json outputs'
        # warnings are told apart the same way, _common.run_warnings)
        seen = {_one_line(m) for _, m in RUN_WARNINGS["said"]}
        RUN_WARNINGS.update(said=[], caught=[], active=False)  # (a command function called later, directly: none)
        for w in filter(package_warning, caught):
            line = _one_line(w.message)
            if line in seen:
                continue
            seen.add(line)
            click.echo(f"propmap: warning: {line}", err=True)
        for line in said:
            click.echo(line, err=True)
    return 0


def run() -> None:
    """Console-script entry point: :func:`main`, then a fast exit.

    The standard streams are flushed and the atexit handlers run (llvmlite's, numba's,
    weakref finalizers, logging), then the process ends with ``os._exit``, skipping the
    interpreter's teardown: with numba and SciPy loaded that teardown alone took 0.35 s
    of a 1.2 s single-point ``propmap loads`` (measured, median of 10 runs on the 2-core
    machine; benchmarks/README.md). Every output file is written and closed by then.
    """
    code = main()
    try:
        sys.stdout.flush()
    except BrokenPipeError:  # the reader of a pipe went away (e.g. `| head`); click exits 1 then
        code = code or 1
    try:
        sys.stderr.flush()
    except OSError:
        pass
    run_exitfuncs = getattr(atexit, "_run_exitfuncs", None)
    if run_exitfuncs is None:  # not CPython: the normal exit
        sys.exit(code)
    run_exitfuncs()
    os._exit(code)


if __name__ == "__main__":  # ``python -m propmap.cli.main`` as ``python -m propmap`` (it ran nothing and exited 0)
    run()
