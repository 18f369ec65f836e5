"""The compiled kernels' first compile shared among pytest-xdist's workers (tests/conftest.py).

A fresh checkout has no kernel cache, and each worker compiled what its first tests asked for:
both workers compiled the serial loads kernel at once, then whichever kernel their tests met
first (benchmarks/README.md, Compile time). Here the workers, before they collect a test,
share the kernel families out (each family's first call, which numba then writes to the
package's cache): a worker takes the first family that no other has taken and whose
dependencies are compiled, until every family is taken, then goes on to its tests; a first call
in any worker then loads the kernel from the cache (or, for the last families, which may still
be compiling in another worker, compiles it as well). With a warm cache each family takes a
fraction of a second. Without pytest-xdist (one process) nothing is done here: the tests compile
what they need as they go.

A family that fails here (it cannot: these are the calls the tests make) is left to the tests,
which then compile it themselves and report the failure; so is a family whose claimer died
before it was compiled, and one whose dependencies are not settled within ``WAIT_S``.
"""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

import numpy as np

WAIT_S = 600.0


def _points(n):
    rng = np.random.default_rng(0)
    return rng.uniform(300.0, 1200.0, n), rng.uniform(0.0, 20.0, n), rng.uniform(0.0, np.pi, n)


def _loads(n, linear=False, **kw):
    def call():
        import propmap as pm

        prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
        if linear:
            params = params.replace(inflow="pitt-peters")
        pm.rotor_loads(prop, params, *_points(n), **kw)
    return call


def _maps_and_vehicle():
    import propmap as pm
    from propmap.maps import build_map
    from propmap.vehicle.file import read_vehicle

    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params()
    ds = build_map(prop, params, np.linspace(300.0, 1200.0, 4), np.linspace(0.0, 15.0, 4),
                   np.radians(np.linspace(0.0, 180.0, 5)), n_check=0)
    rmap = pm.RotorMap(ds)
    rmap.loads(600.0, 5.0, 0.5)
    rmap.loads(*(np.clip(x, 300.0, 1200.0) for x in _points(8)[:1]), np.full(8, 5.0), np.full(8, 0.5))
    rmap.wrench(np.array([5.0, 0.0, 0.0]), np.array([0.0, 0.0, -1.0]), 600.0)
    vehicle = read_vehicle(Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml")
    pm.VehicleMap(vehicle, rmap).wrench(np.array([3.0, 0.0, 0.0]), np.zeros(3), np.full(4, 600.0))
    pm.vehicle_wrench(vehicle, params, np.array([[3.0, 0.0, 0.0]]), np.zeros((1, 3)), np.full((1, 4), 600.0))


# (name, first call, the families whose compiled functions it calls), the critical path first: a
# family whose functions another is still compiling would compile them a second time (one
# process, empty cache, 2026-11-28: loads serial 40 s, parallel 27 s; derivatives 33 / 17 s;
# the linear inflow's 33 / 25 s, each after those it calls)
FAMILIES = (
    ("loads, serial kernel", _loads(4), ()),
    ("derivatives, serial", _loads(4, derivatives=True), ("loads, serial kernel",)),
    ("linear inflow derivatives, serial", _loads(4, linear=True, derivatives=True), ("derivatives, serial",)),
    ("linear inflow derivatives, parallel", _loads(64, linear=True, derivatives=True),
     ("linear inflow derivatives, serial",)),
    ("loads, parallel kernel", _loads(64), ("loads, serial kernel",)),
    ("derivatives, parallel", _loads(64, derivatives=True), ("derivatives, serial",)),
    ("section-parameter derivatives", _loads(4, derivatives=("omega", "cl_alpha", "cd_min")),
     ("derivatives, serial",)),
    ("maps and the vehicle's kernels", _maps_and_vehicle, ("loads, serial kernel", "loads, parallel kernel")),
)


def _path(folder: Path, name: str, state: str) -> Path:
    return folder / f"{name.replace(' ', '_')}.{state}"


def _claim(folder: Path, name: str) -> bool:
    """Create ``<family>.claimed`` holding this process' id; False if another worker had."""
    try:
        fd = os.open(_path(folder, name, "claimed"), os.O_CREAT | os.O_EXCL | os.O_WRONLY)
    except FileExistsError:
        return False
    with os.fdopen(fd, "w") as f:
        f.write(str(os.getpid()))
    return True


def _settled(folder: Path, name: str) -> bool:
    """The family is compiled (``<family>.done``), or its claimer died before it was: a worker that
    dies mid-compile leaves its family to the tests, not to a wait of ``WAIT_S``."""
    if _path(folder, name, "done").exists():
        return True
    try:
        pid = int(_path(folder, name, "claimed").read_text() or "0")
    except (OSError, ValueError):
        return False
    if pid <= 0:  # claimed a moment ago, its id not yet written
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    except PermissionError:  # another user's process of that id: alive
        return False
    return False


def warm(folder: Path, wait_s: float = WAIT_S) -> list[str]:
    """Compile, in this worker, each family of ``FAMILIES`` that no other worker of the run has
    claimed and whose dependencies are settled, until every family is claimed: then the worker
    goes on to its tests (the last families may still compile elsewhere; a test that needs one
    of them first compiles it too, which costs no more than waiting for it).

    The workers share ``folder``: a family is claimed by the file ``<name>.claimed`` (created
    exclusively, holding the claimer's process id) and said compiled by ``<name>.done``; a
    dependency is settled when it is done or its claimer has died. Waits at most ``wait_s`` [s]
    for dependencies. Returns the names of the families that failed here (left to the tests)."""
    folder.mkdir(parents=True, exist_ok=True)
    failed = []
    end = time.monotonic() + wait_s
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        while time.monotonic() < end:
            free = [f for f in FAMILIES if not _path(folder, f[0], "claimed").exists()]
            if not free:
                break
            ready = [f for f in free if all(_settled(folder, d) for d in f[2])]
            if not ready:
                time.sleep(0.2)
                continue
            name, call, _ = ready[0]
            if not _claim(folder, name):
                continue
            try:
                call()
            except Exception:  # noqa: BLE001 (the tests meet it again and report it)
                failed.append(name)
            _path(folder, name, "done").touch()
    return failed


def maybe_warm(config) -> list[str] | None:
    """``warm`` in a pytest-xdist worker (``config.workerinput`` is set there), nothing elsewhere
    or with ``--collect-only``. Every family is compiled whatever tests are selected (with a warm
    cache, 3.8 s for all eight in one process, 2026-12-02). Returns ``warm``'s failures, None where it did not run."""
    info = getattr(config, "workerinput", None)
    if info is None or config.option.collectonly:
        return None
    # the workers' temporary folders are <run's folder>/popen-gw<k>; the run's own id where they are not
    base = config.option.basetemp
    folder = (Path(base).parent if base else Path(tempfile.gettempdir())) / f"kernel-warmup-{info['testrunuid']}"
    return warm(folder)
