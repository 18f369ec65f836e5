"""Section polars (eqs 3-4), presets (Table I) and the parameter file format."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.airfoil import sigmoid_blend
from propmap.io import ParamsFileError, read_params, write_params


def test_table_i_presets():
    p = pm.preset("gill2017-apc")
    assert (p.cl1, p.cl2, p.cd, math.degrees(p.alpha0)) == pytest.approx((5.3, 1.7, 1.8, 20.6))
    assert (p.M, p.cd0, p.cp_blasius) == (50.0, 0.01, 1.328)  # footnote 2
    assert pm.preset("gill2017-stiff").cl1 == 4.2 and pm.preset("gill2017-soft").cd == 3.7
    with pytest.raises(KeyError, match="gill2017-apc"):
        pm.preset("nope")


def test_lift_limits():
    p = pm.preset("gill2017-apc")
    a = np.radians([1.0, 5.0])
    np.testing.assert_allclose(pm.lift_coefficient(a, p), p.cl1 * a, rtol=1e-6)  # pre-stall: linear
    b = np.radians([45.0, 70.0])
    np.testing.assert_allclose(pm.lift_coefficient(b, p), p.cl2 * np.sin(b) * np.cos(b), rtol=1e-6)
    assert pm.lift_coefficient(0.0, p) == 0.0
    np.testing.assert_allclose(pm.lift_coefficient(-a, p), -pm.lift_coefficient(a, p))  # odd


def test_sigmoid_matches_paper_form_and_survives_overflow():
    a = np.linspace(-1.5, 1.5, 301)
    a0, M = 0.36, 50.0
    e1, e2 = np.exp(-M * (a - a0)), np.exp(M * (a + a0))
    paper = (1 + e1 + e2) / ((1 + e1) * (1 + e2))
    np.testing.assert_allclose(sigmoid_blend(a, a0, M), paper, atol=1e-12)
    assert sigmoid_blend(np.array([3.0, -3.0]), a0, 5000.0).tolist() == [1.0, 1.0]


def test_drag_coefficient():
    p = pm.preset("gill2017-apc")
    assert pm.drag_coefficient(0.0, 1e4, p) == pytest.approx(2 * 1.02 * 1.328 / 100 + 0.01)
    assert pm.drag_coefficient(math.pi / 2, 1e4, p) == pytest.approx(1.8 + 2 * 1.02 * 1.328 / 100 + 0.01)
    with pytest.raises(ValueError, match="reynolds"):
        pm.drag_coefficient(0.0, 0.0, p)


@pytest.mark.parametrize("kw, match", [(dict(cl1=-1.0), "cl1"), (dict(alpha0=2.0), "alpha0"),
                                       (dict(M=0.0), "M"), (dict(cd=float("nan")), "cd"),
                                       (dict(lift_model="x"), "lift_model")])
def test_bad_params(kw, match):
    base = dict(cl1=5.3, cl2=1.7, cd=1.8, alpha0=0.36)
    with pytest.raises(ValueError, match=match):
        pm.AirfoilParams(**(base | kw))


def test_params_file_round_trip(tmp_path):
    p = pm.preset("gill2017-stiff").replace(M=30.0)
    air = pm.Air(rho=1.1)
    f = tmp_path / "p.toml"
    write_params(f, p, air)
    q = read_params(f)
    air2 = q.air
    assert air2 == air
    for k in ("cl1", "cl2", "cd", "M", "cd0", "cp_blasius", "lift_model"):
        assert getattr(q, k) == getattr(p, k)
    assert q.alpha0 == pytest.approx(p.alpha0, rel=1e-15)
    assert "alpha0_deg = 27.5" in f.read_text()


def test_minimal_params_file_uses_footnote_2_defaults(tmp_path):
    f = tmp_path / "p.toml"
    f.write_text("cl1 = 5.3\ncl2 = 1.7\ncd = 1.8\nalpha0_deg = 20.6\n")
    q = read_params(f)
    air = q.air
    ref = pm.preset("gill2017-apc")
    assert (q.cl1, q.cl2, q.cd, q.M, q.cd0, q.cp_blasius) == (ref.cl1, ref.cl2, ref.cd, 50.0, 0.01, 1.328)
    assert q.alpha0 == pytest.approx(ref.alpha0, rel=1e-15)
    assert air == pm.Air()


@pytest.mark.parametrize("text, match", [("cl1 = 5.3\n", "missing"), ("cl1 = [\n", "TOML"),
                                         ("cl1=1\ncl2=1\ncd=1\nalpha0_deg=20\nfoo=1\n", "unknown"),
                                         ("cl1=1\ncl2=1\ncd=1\nalpha0_deg=120\n", "alpha0")])
def test_bad_params_files(tmp_path, text, match):
    f = tmp_path / "p.toml"
    f.write_text(text)
    with pytest.raises(ParamsFileError, match=match):
        read_params(f)
