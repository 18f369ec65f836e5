"""The NumPy PCHIP of the blade geometry is SciPy's PchipInterpolator (written out so that
a single-point CLI call need not import scipy.interpolate); Propeller.same_geometry."""

import subprocess
import sys

import numpy as np
import pytest
from scipy.interpolate import PchipInterpolator

import propmap as pm
from propmap.core._pchip import Pchip


@pytest.mark.parametrize("seed", range(5))
def test_pchip_equals_scipy_inside_and_near_the_ends(seed):
    rng = np.random.default_rng(seed)
    for n in (2, 3, 4, 7, 30):
        x = np.sort(rng.uniform(0, 1, n)) + np.arange(n) * 1e-3
        for y in (rng.normal(size=n), np.cumsum(rng.uniform(0, 1, n)), np.r_[rng.normal(size=n - 1), 0.0]):
            xq = np.r_[np.linspace(x[0], x[-1], 101), x[0] - 0.01, x[-1] + 0.01]
            np.testing.assert_allclose(Pchip(x, y)(xq), PchipInterpolator(x, y, extrapolate=True)(xq),
                                       rtol=0, atol=1e-12 * max(1.0, np.max(np.abs(y))))


def test_pchip_keeps_monotone_data_monotone_and_flat_data_flat():
    x = np.array([0.1, 0.2, 0.4, 0.5, 0.9])
    up = Pchip(x, [0.0, 0.1, 0.1, 0.5, 2.0])(np.linspace(0.1, 0.9, 401))
    assert np.all(np.diff(up) >= -1e-15)  # no overshoot, unlike a cubic spline
    np.testing.assert_allclose(Pchip(x, [0.1, 0.1, 0.3, 0.3, 0.3])(np.linspace(0.4, 0.9, 50)), 0.3, atol=1e-15)


def test_catalogue_geometry_at_the_solver_nodes_equals_scipy():
    prop = pm.load_propeller("apce_8x6")
    y = np.linspace(prop.r_hub, prop.radius, 97)
    np.testing.assert_allclose(prop.chord_at(y), np.maximum(PchipInterpolator(prop.r, prop.chord)(y), 0),
                               rtol=1e-13, atol=1e-16)
    np.testing.assert_allclose(prop.theta_at(y), PchipInterpolator(prop.r, prop.theta)(y), rtol=1e-13)


@pytest.mark.parametrize("argv", [["--help"], ["props"], ["loads", "apce_8x6", "--rpm", "8000"]])
def test_everyday_commands_do_not_import_what_they_do_not_need(argv):
    """propmap --help and props import neither numba nor SciPy nor pandas nor matplotlib; a
    single point imports numba but not scipy.interpolate, pandas or matplotlib (the import
    costs measured in benchmarks/README.md; a count of modules, not a timing)."""
    code = ("import sys\nfrom propmap.cli.main import main\nmain(%r)\n"
            "print(' '.join(m for m in ('numba', 'scipy', 'scipy.interpolate', 'pandas', 'matplotlib') "
            "if m in sys.modules), file=sys.stderr)" % argv)
    err = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stderr
    loaded = err.strip().splitlines()[-1].split() if err.strip() else []
    if argv[0] == "loads":
        assert "numba" in loaded
        assert not {"scipy.interpolate", "pandas", "matplotlib"} & set(loaded), loaded
    else:
        assert loaded == [], loaded


def test_same_geometry_compares_blades_not_names():
    import dataclasses

    a = pm.load_propeller("apce_8x6")
    assert a.same_geometry(pm.load_propeller("apce_8x6")) and a.same_geometry(dataclasses.replace(a, name="other"))
    assert not a.same_geometry(dataclasses.replace(a, n_blades=3))
    assert not a.same_geometry(dataclasses.replace(a, theta=a.theta + 1e-6))
    assert not a.same_geometry(pm.load_propeller("apce_10x7"))  # other stations too


def test_same_size_compares_a_recorded_diameter_and_blade_count():
    a = pm.load_propeller("apce_8x6")  # 0.2032 m, 2 blades
    assert a.same_size(0.2032, 2) and a.same_size(0.2032 * 1.009, 2.0) and a.same_size(None, None)
    assert a.same_size(float("nan"), 2)  # an unknown diameter is not compared
    assert not a.same_size(0.2032 * 1.011, 2) and not a.same_size(0.2032, 3) and not a.same_size(0.254, None)
    assert a.same_size(0.2032 * 1.04, 2, rtol=0.05)
    assert a.same_size(0.0, float("nan")) and not a.same_size(0.0, 3)  # (0, NaN: not compared)
