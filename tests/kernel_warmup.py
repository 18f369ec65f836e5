"""The compiled kernels' first compile shared among pytest-xdist's workers (tests/conftest.py).

A fresh checkout has no kernel cache, and each worker compiled what its first tests asked for:
both workers compiled the serial loads kernel at once, then whichever kernel their tests met
first (benchmarks/README.md, Compile time). Here the workers, before they collect a test,
share the kernel families out (each family's first call, which numba then writes to the
package's cache): a worker takes the first family that no other has taken and whose
dependencies are compiled, until every family is taken; every later first call, in any worker,
loads the kernel from the cache instead of compiling it. With a warm cache each family takes a
fraction of a second. Without pytest-xdist (one process) nothing is done here: the tests compile
what they need as they go.

A family that fails here (it cannot: these are the calls the tests make) is left to the tests,
which then compile it themselves and report the failure; a family whose dependencies are not
compiled within ``WAIT_S`` (a worker that died) is left to the tests too.
"""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

import numpy as np

WAIT_S = 900.0


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


def _mark(folder: Path, name: str, state: str) -> bool:
    """Create ``folder/<family>.<state>`` if it does not exist yet; False if another worker had."""
    try:
        os.close(os.open(folder / f"{name.replace(' ', '_')}.{state}", os.O_CREAT | os.O_EXCL | os.O_WRONLY))
        return True
    except FileExistsError:
        return False


def _has(folder: Path, name: str, state: str) -> bool:
    return (folder / f"{name.replace(' ', '_')}.{state}").exists()


def warm(folder: Path, wait_s: float = WAIT_S) -> list[str]:
    """Compile, in this worker, each family of ``FAMILIES`` that no other worker of the run has
    claimed and whose dependencies are compiled, until every family is claimed: then the worker
    goes on to its tests (the last families may still compile elsewhere; a test that needs one
    of them first compiles it too, which costs no more than waiting for it).

    The workers share ``folder``: a family is claimed by the file ``<name>.claimed`` (created
    exclusively) and said compiled by ``<name>.done``. Returns the names of the families that
    failed here (left to the tests)."""
    folder.mkdir(parents=True, exist_ok=True)
    failed = []
    end = time.monotonic() + wait_s
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        while time.monotonic() < end:
            free = [f for f in FAMILIES if not _has(folder, f[0], "claimed")]
            if not free:
                break
            ready = [f for f in free if all(_has(folder, d, "done") for d in f[2])]
            if not ready:
                time.sleep(0.2)
                continue
            name, call, _ = ready[0]
            if not _mark(folder, name, "claimed"):
                continue
            try:
                call()
            except Exception:  # noqa: BLE001 (the tests meet it again and report it)
                failed.append(name)
            _mark(folder, name, "done")
    return failed


def maybe_warm(config) -> None:
    """``warm`` in a pytest-xdist worker (``config.workerinput`` is set there), nothing elsewhere."""
    info = getattr(config, "workerinput", None)
    if info is None:
        return
    # the workers' temporary folders are <run's folder>/popen-gw<k>; the run's own id where they are not
    base = config.option.basetemp
    folder = (Path(base).parent if base else Path(tempfile.gettempdir())) / f"kernel-warmup-{info['testrunuid']}"
    warm(folder)
