"""Shared bank of named propellers, parameters and operating points for the tests."""

import os
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM  # noqa: F401  (rad/s per rpm, for the tests)

SHARED = Path(__file__).resolve().parents[2] / "shared" / "data"


def pytest_collection_modifyitems(config, items):
    """The tests marked ``slow`` (each 9 s or more in a fresh checkout on the 2-core machine) first,
    the others in their order: pytest-xdist hands tests out as the workers free up, so that the
    workers now end together. Collected last, the shipped flight set's refit (56 s) kept one
    worker busy 69 s after the other had finished (2026-12-02). ``-m "not slow"`` leaves them out
    of a quick local run."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)


def pytest_sessionstart(session):
    """Under pytest-xdist, the kernels' first compile shared among the workers (tests/kernel_warmup.py)."""
    from kernel_warmup import maybe_warm

    maybe_warm(session.config)


# variables that every later subprocess of a test process inherits: a test that leaves one changed
# makes them run elsewhere (a NUMBA_CACHE_DIR left naming a test's empty folder made every later
# subprocess compile the kernels anew, 70-100 s each: found 2026-12-02)
_INHERITED = ("NUMBA_CACHE_DIR", "NUMBA_NUM_THREADS", "NUMBA_THREADING_LAYER", "MPLBACKEND", "PYTHONPATH")


@pytest.fixture(autouse=True)
def _environment_left_as_found():
    before = {k: os.environ.get(k) for k in _INHERITED}
    yield
    after = {k: os.environ.get(k) for k in _INHERITED}
    if after != before:
        changed = {k: (before[k], after[k]) for k in _INHERITED if before[k] != after[k]}
        pytest.fail(f"the test left the environment changed (before, after): {changed}")


@pytest.fixture(scope="session")
def shared_data() -> Path:
    if not SHARED.is_dir():
        if os.environ.get("CI", "").lower() in ("1", "true", "yes"):  # (CI has ../shared: a skip would hide tests)
            pytest.fail(f"../shared/data is not beside the checkout ({SHARED}), and CI is set")
        pytest.skip("../shared/data is not beside the checkout")
    return SHARED


@pytest.fixture(scope="session")
def apc8x6():
    """APC 8x6 Thin Electric, APC PE0 geometry (the paper's wind-tunnel propeller)."""
    return pm.load_propeller("apce_8x6")


@pytest.fixture(scope="session")
def apce():
    """apce_8x6 (APC PE0 geometry) and its bundled UIUC load data (vol. 1, Brandt & Selig): (propeller, LoadData)."""
    from propmap.identify import loads_from_catalogue

    prop = pm.load_propeller("apce_8x6")
    return prop, loads_from_catalogue(pm.catalogue()["apce_8x6"], prop.diameter)


@pytest.fixture(scope="session")
def apc_params():
    """Gill & D'Andrea (2017) Table I, APC column."""
    return pm.preset("gill2017-apc")


@pytest.fixture(scope="session")
def envelope_points():
    """200 random points over rpm 3000-12000, V 0-25 m/s, incidence 0-180 deg (seeded)."""
    rng = np.random.default_rng(2017)
    n = 200
    return (rng.uniform(3000, 12000, n) * RPM, rng.uniform(0, 25, n), np.radians(rng.uniform(0, 180, n)))


@pytest.fixture(scope="module")
def small_map():
    """apce_8x6, calibrated parameters, a coarse map (5 x 6 x 13), 300 check points: (prop, params, dataset)."""
    from propmap.maps import build_map

    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    air, label = params.air, params.label
    ds = build_map(prop, params, np.linspace(4000, 9000, 5) * RPM, np.linspace(0, 15, 6),
                   np.radians(np.linspace(0, 180, 13)), air=air, params_label=label, n_check=300)
    return prop, params, ds


@pytest.fixture(scope="module")
def flapping_map():
    """apce_8x6, the generic set with flapping blades (a side force and a pitching moment), 4 x 4 x 7:
    (prop, params, dataset)."""
    from propmap.maps import build_map

    prop = pm.load_propeller("apce_8x6")
    params = pm.generic_params().replace(flap_compliance=2.0)
    ds = build_map(prop, params, np.linspace(5000, 8000, 4) * RPM, np.linspace(0, 12, 4),
                   np.radians(np.linspace(0, 180, 7)), n_check=100)
    return prop, params, ds


def moved_loads(prop, p, om, V, b, w, h, disc):
    """rotor_loads with one input or parameter moved by h: omega, airspeed, incidence, the
    collective, rho or a field of ``p`` (the derivative tests' central differences)."""
    kw = dict(discretization=disc)
    if w == "omega":
        return pm.rotor_loads(prop, p, om + h, V, b, **kw)
    if w == "airspeed":
        return pm.rotor_loads(prop, p, om, V + h, b, **kw)
    if w == "incidence":
        return pm.rotor_loads(prop, p, om, V, b + h, **kw)
    if w == "collective":
        return pm.rotor_loads(prop, p, om, V, b, collective=h, **kw)
    if w == "rho":
        return pm.rotor_loads(prop, p, om, V, b, air=pm.Air(rho=p.air.rho + h), **kw)
    return pm.rotor_loads(prop, p.replace(**{w: getattr(p, w) + h}), om, V, b, **kw)
