"""Mutation audit of core/_reference.py (the NumPy solver), core/_pchip.py, core/_fastmath.py,
core/_jitcache.py and core/_parallel.py: tests for the mutants the module's own tests let through."""

import math
import os
import stat
import tempfile
from importlib import resources
from pathlib import Path

import numba
import numpy as np
import pytest
from numba.core import caching
from scipy.interpolate import PchipInterpolator

import propmap as pm
from propmap.core import _annulus as K
from propmap.core import _interp, _jitcache, _kernel, _linear_sensitivity, _parallel, _sensitivity, solver
from propmap.core import _reference as R
from propmap.core._pchip import Pchip
from propmap.core.nodes import _nodes

ATMOS = pm.Air()


def _solve(prop, p, om, Vs, Vc):
    nd = _nodes(prop, 48, 16, ATMOS, p)
    return R.solve_reference(np.atleast_1d(np.asarray(om, float)), np.atleast_1d(np.asarray(Vs, float)),
                             np.atleast_1d(np.asarray(Vc, float)), nd, p)


def test_reference_refuses_flapping_blades(apc8x6, apc_params):
    """Mutant R7: the reference's check ``p.flap_compliance > 0`` deleted (it would solve the
    flapping rotor as a rigid one and return the rigid loads without a word)."""
    nd = _nodes(apc8x6, 48, 16, ATMOS, apc_params)
    with pytest.raises(ValueError, match="uniform inflow of rigid blades only"):
        R.solve_reference(np.array([800.0]), np.array([3.0]), np.array([2.0]), nd,
                          apc_params.replace(flap_compliance=2.0))


@pytest.mark.parametrize("cambered", [False, True], ids=["gill2017", "cambered"])
def test_reference_drag_in_axial_flow_is_exactly_zero(apc8x6, apc_params, cambered):
    """Mutant R13: ``np.where(axial, 0.0, ...)`` dropped from the reference's drag: by symmetry the
    half circle's sin(psi) average cancels only to ~1e-18 N, while the kernel returns an exact 0 in
    axial flow (hover and 5 m/s climb at 800 rad/s); the thrust and torque still agree."""
    p = pm.CamberedParams(descent="glauert") if cambered else apc_params
    T, D, Q, _, ok = _solve(apc8x6, p, [800.0, 800.0], [0.0, 0.0], [0.0, 5.0])
    r = pm.rotor_loads(apc8x6, p, 800.0, np.array([0.0, 5.0]), 0.0, radial=True)
    assert ok.all() and r.converged.all()
    assert np.array_equal(r.drag, [0.0, 0.0])
    assert np.array_equal(D, [0.0, 0.0])  # exactly, as the kernel
    np.testing.assert_allclose(T, r.thrust, rtol=1e-7)
    np.testing.assert_allclose(Q, r.torque, rtol=1e-7)
    assert T[0] > 2.0 and Q[0] > 0.05  # a working rotor (gill2017 4.12 N, cambered 2.63 N in hover)


def test_reference_flags_an_unfinished_root_refinement(apc8x6, apc_params, monkeypatch):
    """Mutant R12: ``converged &= fin`` deleted (a root refinement that ran out of steps was
    reported converged). With no refinement step allowed the bracketed roots are unfinished."""
    om, Vs, Vc = [800.0, 900.0], [3.0, 0.0], [2.0, 4.0]
    *_, ok = _solve(apc8x6, apc_params, om, Vs, Vc)
    assert ok.all()
    monkeypatch.setattr(K, "MAX_REFINE", 0)  # the reference reads it at run time
    T, _, _, _, ok = _solve(apc8x6, apc_params, om, Vs, Vc)
    assert np.all(np.isfinite(T)) and not ok.any()


def test_reference_flags_an_unfinished_swirl_iteration(apc8x6, monkeypatch):
    """Mutant R3: the swirl loop's ``conv & done.all(axis=1)`` returned as the root solve's
    ``conv`` only (a swirl iteration that ran out of iterations was reported converged)."""
    p = pm.CamberedParams(descent="glauert", swirl=True)
    T, _, Q, _, ok = _solve(apc8x6, p, 900.0, 3.0, 4.0)
    r = pm.rotor_loads(apc8x6, p, 900.0, 5.0, math.atan2(3.0, 4.0))
    assert ok.all() and r.converged
    np.testing.assert_allclose([T[0], Q[0]], [float(r.thrust), float(r.torque)], rtol=1e-6)
    monkeypatch.setattr(R, "SWIRL_MAX_ITER", 2)
    *_, ok = _solve(apc8x6, p, 900.0, 3.0, 4.0)
    assert not ok.any()


def test_reference_keeps_the_swirl_where_the_selected_root_jumps():
    """Mutant R2: ``| (np.abs(hi - lo) <= tol)`` dropped from the swirl loop's stop (the annulus
    whose selected root jumps, where no balance exists, was iterated to SWIRL_MAX_ITER and the
    point reported unconverged). tests/test_swirl.py's NeuroBEM point in steep oblique descent:
    the kernel converges, flags multiple roots, and the reference agrees on its loads."""
    vehicle = pm.read_vehicle(resources.files("propmap") / "data" / "examples" / "neurobem_quadrotor.toml")
    prop = vehicle.rotors[0].propeller
    p = pm.generic_params().replace(descent="glauert", swirl=True)
    om, V, b = 668.0, 10.5, math.radians(103.0)
    r = pm.rotor_loads(prop, p, om, V, b, radial=True)
    assert r.converged and r.multiple_roots
    T, D, Q, _, ok = _solve(prop, p, om, V * math.sin(b), V * math.cos(b))
    assert ok.all()
    np.testing.assert_allclose([T[0], D[0], Q[0]], [float(r.thrust), float(r.drag), float(r.torque)], rtol=1e-5)


def test_pchip_of_a_flat_stretch_written_with_negative_zeros_equals_scipy():
    """Mutant P5: ``(np.sign(m0) * np.sign(m1)) > 0`` made ``>= 0``: a flat stretch whose values
    include -0.0 (a table written as "-0.0", a rake or sweep column) gives secants +0.0 and -0.0,
    whose harmonic mean is inf - inf = NaN, where SciPy (and the clean source) set the slope 0."""
    x = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
    y = np.array([1.0, 0.5, 0.0, 0.0, -0.0, 0.3])
    xq = np.linspace(-0.2, 5.2, 109)
    got = Pchip(x, y)(xq)
    assert np.all(np.isfinite(got))
    np.testing.assert_allclose(got, PchipInterpolator(x, y, extrapolate=True)(xq), rtol=0, atol=1e-13)
    assert np.all(Pchip(x, y)(np.linspace(2.0, 4.0, 21)) == 0.0)  # flat where the data are


@pytest.mark.parametrize("kernel, sources", [
    (_kernel.solve_batch_serial, _jitcache.KERNEL_SOURCES),
    (_sensitivity.sensitivities_serial, _jitcache.SENSITIVITY_SOURCES),
    (_linear_sensitivity.linear_sensitivities_serial, _jitcache.LINEAR_SOURCES),
], ids=["solver", "sensitivity", "linear"])
def test_each_cached_kernel_is_stamped_over_its_own_sources(kernel, sources):
    """Mutant J4: every locator given KERNEL_SOURCES instead of its file's (the sensitivity kernels
    then served stale after an edit of _tangents.py, _sensitivity.py ...: the suite's recompile test
    edits _physics.py, which every stamp covers). Mutant J5: propmap's locators appended after
    numba's own instead of ahead of them (numba's file-only stamp then serves the kernels)."""
    locator = kernel._cache._impl._locator  # the locator numba picked for the kernel's disk cache
    assert type(locator).__name__.startswith("PropmapKernel")
    assert locator._propmap_sources == sources
    assert locator.get_source_stamp() == _jitcache.sources_stamp(sources)
    if sources is not _jitcache.KERNEL_SOURCES:
        assert locator.get_source_stamp() != _jitcache.sources_stamp(_jitcache.KERNEL_SOURCES)


def test_the_maps_kernels_are_stamped_over_the_disk_frame_too():
    """Mutant J4 on the maps' kernels (_interp.py inlines _frame.py): their stamp is INTERP_SOURCES'."""
    cached = [f for f in vars(_interp).values() if isinstance(f, numba.core.registry.CPUDispatcher) and f._cache
              and Path(f.py_func.__code__.co_filename).name == "_interp.py"]
    locators = [f._cache._impl._locator for f in cached]
    assert locators and all(type(loc).__name__.startswith("PropmapKernel") for loc in locators)
    assert all(loc._propmap_sources == _jitcache.INTERP_SOURCES for loc in locators)


def test_a_cache_folder_others_may_write_is_not_used(tmp_path, monkeypatch):
    """Mutant J6: the privacy check of the fallback folder reduced to the group's bits: a folder
    named propmap-numba-<uid> that every other user may write (mode 0o703; numba's index is a
    pickle) was used. Simulated in this process as tests/test_user_data_edges.py does in a fresh
    one: numba's package-folder and user-cache locators find no place."""
    for c in (caching.InTreeCacheLocator, caching.UserWideCacheLocator):
        monkeypatch.setattr(c, "from_function", classmethod(lambda cls, f, p: None))
    # set, then deleted, so that monkeypatch restores the variable's absence: _writable_cache sets it itself,
    # and a folder left in this process' environment made every later subprocess compile the kernels anew
    # (tests/conftest.py checks that no test leaves it changed)
    monkeypatch.setenv("NUMBA_CACHE_DIR", "")
    monkeypatch.delenv("NUMBA_CACHE_DIR")
    monkeypatch.setattr(numba.config, "CACHE_DIR", "")
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    named = tmp_path / f"propmap-numba-{os.getuid()}"
    named.mkdir()
    named.chmod(0o703)
    folder = _jitcache._writable_cache()
    assert folder is not None and Path(folder).parent == tmp_path and Path(folder) != named
    assert stat.S_IMODE(os.stat(folder).st_mode) == 0o700
    assert os.environ["NUMBA_CACHE_DIR"] == numba.config.CACHE_DIR == folder
    named.chmod(0o700)  # a private one of that name is used
    monkeypatch.delenv("NUMBA_CACHE_DIR")
    monkeypatch.setattr(numba.config, "CACHE_DIR", "")
    assert _jitcache._writable_cache() == str(named)


def test_the_parent_keeps_its_parallel_kernels_after_a_launch(apc8x6, apc_params):
    """Mutant L5: ``serial_only`` answering whether this process launched a region instead of
    whether it is a child forked after its parent did: every batch after the first parallel one
    then ran on one core, silently. Only a forked child's batches are serial."""
    n = solver.PARALLEL_MIN_POINTS
    r = pm.rotor_loads(apc8x6, apc_params, np.linspace(500.0, 1000.0, n), np.full(n, 5.0), np.full(n, 0.5))
    assert r.converged.all()
    assert _parallel._STATE["launched"]  # the batch ran the parallel kernel here
    assert _parallel.serial_only() is False
    assert not _parallel._STATE["forked_after_launch"]
