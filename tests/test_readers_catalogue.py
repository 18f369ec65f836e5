"""Readers on every bundled geometry; malformed files; the catalogue."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.io import GeometryFileError, catalogue, read_apc_pe0, read_geometry, read_uiuc_geometry
from propmap.io.readers import MeasurementFileError, read_uiuc_static, read_uiuc_sweep


def test_catalogue_contents():
    cat = catalogue()
    assert len(cat) == 147
    v1 = [e for e in cat.values() if e.volume == 1]
    v2 = [e for e in cat.values() if e.volume == 2]
    assert len(v1) == 108 and sum(e.geometry_format == "uiuc" for e in v1) == 79 and len(v2) == 39
    e = cat["apce_8x6"]
    assert e.geometry_format == "apc_pe0" and len(e.static_files) == 1 and len(e.sweep_files) == 7
    assert "Brandt & Selig" in e.citation and "Deters, Ananda & Selig" in cat["da4002_5x1.58"].citation


def test_volume_2_names_sizes_and_hubs():
    """The vol. 2 naming rules (tools/build_catalogue.py, data/CITATION.md): millimetre
    families, the 3- and 4-blade hubs of one blade, the family design files."""
    cat = catalogue()
    assert cat["pl_100x80"].diameter_in == pytest.approx(100 / 25.4)
    assert cat["union_u80"].diameter_in == pytest.approx(80 / 25.4)
    assert cat["cfnq_45p1"].diameter_in == pytest.approx(45 / 25.4)
    assert cat["pl_triturbo"].n_blades == 3 and cat["pl_triturbo"].diameter_in == pytest.approx(64 / 25.4)
    for hub, n in (("", 2), ("_3b", 3), ("_4b", 4)):
        e = cat["nr640_5_15deg" + hub]
        assert e.n_blades == n and e.geometry_file.endswith("nr640_5_15deg_geom.txt")
        assert pm.load_propeller("nr640_5_15deg" + hub).n_blades == n
    # the 5 in blade measured at its 15 deg setting (16.631 deg at 0.75 R in its own datum) turned by +5 deg for the
    # 20 deg runs; the 9 in blade, not measured, is the design file (15 deg at 0.75 R) set to 20 deg
    p15, p20 = pm.load_propeller("nr640_5_15deg"), pm.load_propeller("nr640_5_20deg")
    np.testing.assert_allclose(p20.theta - p15.theta, math.radians(5.0), rtol=0, atol=1e-12)
    assert p20.r == pytest.approx(p15.r, abs=0)
    assert cat["nr640_5_20deg"].geometry_file.endswith("nr640_5_15deg_geom.txt")
    p9 = pm.load_propeller("nr640_9_20deg")
    assert math.degrees(np.interp(0.75 * p9.radius, p9.r, p9.theta)) == pytest.approx(20.0, abs=1e-9)
    # Propeller.theta_75: the blade angle at a station of the file (0.75 R) is the file's
    assert math.degrees(p9.theta_75()) == pytest.approx(20.0, abs=1e-9)
    assert math.degrees(p20.theta_75()) == pytest.approx(21.631, abs=5e-4)
    d = pm.load_propeller("da4052_9x4.76")  # the design's chord with the helix of the named pitch
    np.testing.assert_allclose(np.tan(d.theta) * 2 * np.pi * d.r, 4.76 * 0.0254, rtol=1e-12)
    assert cat["da4052_9x4.76"].note.startswith("no measured geometry")


@pytest.mark.parametrize("name", sorted(catalogue()))
def test_every_bundled_geometry_reads_and_solves(name):
    e = catalogue()[name]
    prop = pm.load_propeller(name)
    assert prop.radius == pytest.approx(0.5 * e.diameter_in * 0.0254, rel=0.02)
    assert prop.n_blades == e.n_blades and 0.05 < prop.r_hub / prop.radius < 0.35
    assert np.all(np.diff(prop.r) > 0) and np.all(prop.chord >= 0)
    assert 0 < np.degrees(prop.theta).max() < 90
    assert 0.03 < prop.solidity() < 0.4
    for run in e.static_runs():
        assert np.all((run.CT > 0) & (run.CT < 0.3))
    # static, and J = 0.15 at 69 deg incidence (a low-pitch propeller windmills at 10 m/s)
    r = pm.rotor_loads(prop, pm.preset("gill2017-apc"), 6000 * 2 * math.pi / 60, [0.0, 15.0 * prop.diameter],
                       [0.0, 1.2])
    assert r.converged.all() and np.all(r.thrust > 0)


def test_apc_pe0_8x6e(shared_data):
    p = read_apc_pe0(shared_data / "apc_vendor_data/geometry_PE0/8x6E-PERF.PE0")
    assert p.radius == pytest.approx(0.1016)
    assert p.r_hub / p.radius == pytest.approx(0.2384, abs=1e-3)  # docs/numerics.md: 0.238 R
    assert math.degrees(p.theta[0]) == pytest.approx(45.04) and math.degrees(p.theta[-1]) == pytest.approx(13.4906)
    assert p.chord.max() == pytest.approx(0.9412 * 0.0254)  # 23.9 mm
    assert p.pitch == pytest.approx(6 * 0.0254)


def test_uiuc_geometry_matches_shared_file(shared_data):
    p = read_uiuc_geometry(shared_data / "uiuc_propdb/v1/apce_9x6_geom.txt")
    assert p.radius == pytest.approx(4.5 * 0.0254)
    assert p.r[0] / p.radius == pytest.approx(0.15) and p.chord[0] / p.radius == pytest.approx(0.141)
    assert math.degrees(p.theta[0]) == pytest.approx(31.67)


def test_pchip_interpolation_passes_through_stations_without_overshoot(apc8x6):
    np.testing.assert_allclose(apc8x6.chord_at(apc8x6.r), apc8x6.chord, atol=1e-15)
    y = np.linspace(apc8x6.r_hub, apc8x6.radius, 2001)
    assert apc8x6.chord_at(y).max() <= apc8x6.chord.max() + 1e-12


@pytest.mark.parametrize(
    "text, match",
    [
        ("r/R c/R\n0.2 0.1\n0.5 0.1\n", "expected columns"),
        ("r/R c/R beta\n0.2 0.1 30\n0.5 0.1\n", "line 3"),
        ("r/R c/R beta\n0.5 0.1 30\n0.2 0.1 20\n",
         r"line 3: r/R = 0.2 does not exceed the previous station's 0.5 \(line 2\): the stations must be strictly"),
        ("r/R c/R beta\n0.2 0.1 30\n0.5 abc 20\n", "non-numeric"),
        ("r/R c/R beta\n0.2 0.1 30\n1.5 0.1 20\n", "radius"),
        ("", "empty"),
    ],
)
def test_bad_geometry_files(tmp_path, text, match):
    f = tmp_path / "bad_9x6_geom.txt"
    f.write_text(text)
    with pytest.raises(GeometryFileError, match=match):
        read_uiuc_geometry(f)


def test_geometry_without_diameter_needs_one(tmp_path):
    f = tmp_path / "myprop.txt"
    f.write_text("r/R c/R beta\n0.2 0.1 30\n0.5 0.12 20\n1.0 0.05 10\n")
    with pytest.raises(GeometryFileError, match="diameter"):
        read_geometry(f)
    p = read_geometry(f, diameter_in=9.0, n_blades=3)
    assert p.n_blades == 3 and p.radius == pytest.approx(4.5 * 0.0254)


def test_a_diameter_given_against_the_file_names_is_said(tmp_path):
    """The given diameter wins, with a warning when the file name says another (within 5%: none)."""
    import warnings

    f = tmp_path / "my_10x5_geom.txt"
    f.write_text("r/R c/R beta\n0.2 0.1 30\n0.5 0.12 20\n1.0 0.05 10\n")
    with pytest.warns(UserWarning, match="diameter 9 in as given, not the 10 in of the file name"):
        p = read_geometry(f, diameter_in=9.0, n_blades=2)
    assert p.radius == pytest.approx(4.5 * 0.0254)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_geometry(f, diameter_in=10.1, n_blades=2)


def test_unrecognised_geometry_format(tmp_path):
    f = tmp_path / "x.txt"
    f.write_text("hello\n")
    with pytest.raises(GeometryFileError, match="unrecognised"):
        read_geometry(f)


def test_measurement_readers(shared_data, tmp_path):
    s = read_uiuc_static(shared_data / "uiuc_propdb/v1/apce_8x6_static_2797rd.txt")
    assert s.rpm[0] == 2534 and s.CT[0] == pytest.approx(0.1083)
    w = read_uiuc_sweep(shared_data / "uiuc_propdb/v1/apce_8x6_2801rd_6023.txt")
    assert w.rpm == 6023 and w.J.size == 17
    bad = tmp_path / "p_8x6_run_x.txt"
    bad.write_text("J CT CP eta\n0.1 0.1 0.05 0.2\n")
    with pytest.raises(MeasurementFileError, match="nominal rpm"):
        read_uiuc_sweep(bad)


def test_propeller_validation_errors():
    with pytest.raises(ValueError, match="radius"):
        pm.Propeller("x", -1.0, 2, [0.01, 0.1], [0.01, 0.01], [0.3, 0.2])
    with pytest.raises(ValueError, match="n_blades"):
        pm.Propeller("x", 0.1, 0, [0.01, 0.1], [0.01, 0.01], [0.3, 0.2])
    with pytest.raises(ValueError, match="chord"):
        pm.Propeller("x", 0.1, 2, [0.01, 0.1], [0.01, -0.01], [0.3, 0.2])
    with pytest.raises(ValueError, match="chord must be > 0 m at some station"):  # (gave T = Q = 0 silently)
        pm.Propeller("x", 0.1, 2, [0.01, 0.1], [0.0, 0.0], [0.3, 0.2])
    pm.Propeller("x", 0.1, 2, [0.01, 0.1], [0.01, 0.0], [0.3, 0.2])  # a zero chord at the tip is a blade
    with pytest.raises(ValueError, match="equal lengths"):
        pm.Propeller("x", 0.1, 2, [0.01, 0.1], [0.01], [0.3, 0.2])


def test_unknown_catalogue_name_suggests():
    with pytest.raises(KeyError, match="apce_8x6"):
        pm.load_propeller("apce_8x7")
