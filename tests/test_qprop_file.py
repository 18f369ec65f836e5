"""QPROP propeller files (io/qprop_file.py): the format as QPROP 1.22 reads it (M. Drela, QPROP,
version 1.22, qprop.f and io.f), read as blade geometry through read_geometry and --prop, and
their section aero lines as a cambered set (qprop:FILE). Every file here is written by the test."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM
from propmap.io.geometry_files import GeometryFileError, geometry_format, read_geometry
from propmap.io.param_sets import named_sets, resolve_params
from propmap.io.qprop_file import read_qprop_geometry, read_qprop_params

from .cli_helpers import one_line_error, run

#: a hand-made 10 in two-blade propeller in inches: r [in], c [in], beta [deg]
STATIONS = [(1.0, 0.80, 35.0), (1.5, 0.95, 30.0), (2.0, 1.05, 25.5), (2.5, 1.10, 22.0), (3.0, 1.05, 19.2),
            (3.5, 0.95, 17.0), (4.0, 0.80, 15.2), (4.75, 0.45, 13.0)]
#: the line of the first station row in the files :func:`propfile` writes
FIRST_ROW = 16


def propfile(path, *, blades="2 0.127", cd="0.028 0.050 0.020 0.5", fac="0.0254 0.0254 1.0", add="0. 0. 0.",
             rows=None):
    """Write a QPROP file of the test blade (comments, blank lines and '!' notes as QPROP's own
    examples have them); line 4 is Nblades [R], the station rows start at line FIRST_ROW."""
    rows = [f" {r:g}  {c:g}  {b:g}" for r, c, b in STATIONS] if rows is None else rows
    lines = ["# a hand-made test blade, inches", " Test 10x6 two-blade   ! the name", "",
             f" {blades}    ! Nblades  [R]", "", " 0.50  5.8   ! CL0  CL_a", "-0.4  1.2    ! CLmin  CLmax", "",
             f" {cd}   ! CD0  CD2u  CD2l  CLCD0", " 70000  -0.7  ! REref  REexp", "",
             f" {fac}   ! Rfac  Cfac  Bfac", f" {add}   ! Radd  Cadd  Badd", "", "#  r    c    beta", *rows]
    assert lines[FIRST_ROW - 1] == rows[0]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_an_inch_blade_reads_scaled_to_metres(tmp_path):
    f = propfile(tmp_path / "t10x6.prop")
    assert geometry_format(f) == "qprop"
    p = read_geometry(f)
    raw = np.array(STATIONS)
    assert p.n_blades == 2 and p.radius == 0.127 and p.diameter == pytest.approx(0.254, abs=1e-15)
    np.testing.assert_allclose(p.r / p.radius, raw[:, 0] * 0.0254 / 0.127, rtol=1e-14)
    np.testing.assert_allclose(p.r / p.radius, [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.95], rtol=1e-12)
    np.testing.assert_allclose(p.chord / p.radius, raw[:, 1] * 0.0254 / 0.127, rtol=1e-14)
    np.testing.assert_allclose(np.degrees(p.theta), raw[:, 2], rtol=1e-14)
    assert p.name == "t10x6" and "QPROP propeller file t10x6.prop" in p.source and "Test 10x6 two-blade" in p.source
    assert read_qprop_geometry(f).same_geometry(p)


def test_without_R_the_last_station_is_the_tip_and_the_offsets_apply(tmp_path):
    """Line 2 without R (or R = 0): the tip is the last station's scaled radius; r Rfac + Radd,
    c Cfac + Cadd, beta Bfac + Badd (here millimetres, a chord offset and a pitch change)."""
    rows = [" 25  18  30", " 50  22  22", " 75  20  16", " 100  12  12"]
    for blades in ("3", "3 0"):
        f = propfile(tmp_path / f"mm{len(blades)}.txt", blades=blades, fac="0.001 0.001 0.5", add="0.002 0.001 4",
                     rows=rows)
        p = read_geometry(f)
        assert p.n_blades == 3 and p.radius == pytest.approx(0.102, rel=1e-14)
        np.testing.assert_allclose(p.r, [0.027, 0.052, 0.077, 0.102], rtol=1e-14)
        np.testing.assert_allclose(p.chord, [0.019, 0.023, 0.021, 0.013], rtol=1e-14)
        np.testing.assert_allclose(np.degrees(p.theta), [19.0, 15.0, 12.0, 10.0], rtol=1e-14)


def test_qprops_line_rules_comments_separators_and_exponents(tmp_path):
    """Comments ('#' or '!' in column 1, the rest of a line after '!'), blank lines, commas and tabs
    as separators, Fortran's 1.0d0, values beyond those QPROP reads and a trailing comma: the same
    blade as the plain file."""
    plain = read_geometry(propfile(tmp_path / "plain.prop"))
    rows = [f"{r:g},{c:g}\t{b:g}, " if i % 2 else f"! a note\n\n {r:g}d0 {c:g} {b:g}E0 ! station {i}"
            for i, (r, c, b) in enumerate(STATIONS)]
    f = propfile(tmp_path / "odd.prop", blades="2, 1.27d-1, blades", cd="0.028,0.050,0.020,0.5 4 5 6",
                 fac="2.54E-2\t0.0254\t1", rows=[rows[0].split("\n")[-1], *rows[1:]])
    odd = read_geometry(f)
    assert odd.same_geometry(plain) and odd.n_blades == 2 and odd.radius == plain.radius


def test_station_rows_with_their_own_aero_columns(tmp_path):
    """Columns 4-13 of a station row (CL0 CL_a CLmin CLmax CD0 CD2u CD2l CLCD0 REref REexp)
    replace lines 3-6 there: the geometry is the first three; the set takes the values at 0.75 R."""
    own = [f" {r:g} {c:g} {b:g}  {0.3 + 0.1 * i:g} 6.0 -0.5 1.3 0.02 0.04 0.04 0.6 {60000 + 10000 * i} -0.5"
           for i, (r, c, b) in enumerate(STATIONS)]
    f = propfile(tmp_path / "aero.prop", rows=own)
    p = read_geometry(f)
    assert p.same_geometry(read_geometry(propfile(tmp_path / "plain.prop")))
    with pytest.warns(UserWarning, match="station rows give their own CL0, CL_a, .*REexp .*0.75 R"):
        q = read_qprop_params(f)
    # 0.75 R lies between the stations at 0.7 R (i = 5) and 0.8 R (i = 6): halfway
    assert q.alpha_L0 == pytest.approx(-0.85 / 6.0, rel=1e-12) and q.cl_alpha == 6.0
    assert q.re_ref == pytest.approx(115000, rel=1e-12) and q.cd_min == 0.02 and q.cl_max == 1.3
    assert q.cl_cdmin == 0.6 and q.cd2 == 0.04 and q.re_exp == -0.5 and q.cl_min == -0.5


def test_the_section_lines_as_a_cambered_set(tmp_path):
    f = propfile(tmp_path / "set.prop")
    with pytest.warns(UserWarning, match="CD2u = 0.05 and CD2l = 0.02 differ.*cd2 = CD2u"):
        q = read_qprop_params(f)
    assert isinstance(q, pm.CamberedParams) and q.label == f"qprop:{f}" and q.air == pm.Air()
    assert (q.cl_alpha, q.cl_max, q.cl_min, q.cd_min, q.cd2, q.cl_cdmin, q.re_ref, q.re_exp) == (
        5.8, 1.2, -0.4, 0.028, 0.05, 0.5, 70000.0, -0.7)
    assert q.alpha_L0 == pytest.approx(-0.5 / 5.8, rel=1e-15)
    same = propfile(tmp_path / "same.prop", cd="0.028 0.050 0.050 0.5")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = resolve_params(f"qprop:{same}")
    assert r.label == f"qprop:{same}" and r.cd2 == 0.05 and "qprop:<QPROP propeller file>" in named_sets()
    with pytest.raises(GeometryFileError, match="no such file"):
        resolve_params(f"qprop:{tmp_path / 'missing.prop'}")
    # line 5 without CLCD0: QPROP leaves it undefined; the geometry does not need it, the set does
    bare = propfile(tmp_path / "bare.prop", cd="0.028 0.050 0.020")
    assert read_geometry(bare).n_blades == 2
    with pytest.raises(GeometryFileError, match=r"bare.prop, line 9: CD0 CD2u CD2l without CLCD0"):
        read_qprop_params(bare)
    positive = propfile(tmp_path / "pos.prop", cd="0.028 0.050 0.050 0.5")
    positive.write_text(positive.read_text().replace("-0.4  1.2", " 0.1  1.2"))
    with pytest.raises(GeometryFileError, match=r"pos.prop, line 7: CLmin = 0.1 is outside \[-4, 0\)"):
        read_qprop_params(positive)


def _message(path) -> str:
    with pytest.raises(GeometryFileError) as info:
        read_geometry(path)
    msg = str(info.value)
    assert "\n" not in msg and str(path) in msg
    return msg


@pytest.mark.parametrize("change, line, match", [
    (dict(rows=[" 1 0.8 35", " 2 1.0 25", " 2 0.9 20", " 4.75 0.45 13"]), FIRST_ROW + 2,
     "r = 2 (0.0508 m) does not exceed the previous station's 2"),
    (dict(rows=[" 1 0.8 35", " 2 -1.0 25", " 4.75 0.45 13"]), FIRST_ROW + 1, "chord of -0.0254 m"),
    (dict(rows=[" 1 0.8 35", " 2 0 25", " 4.75 0.45 13"]), FIRST_ROW + 1, "must be > 0 m (>= 0 at the last"),
    (dict(rows=[" 4.75 0.45 13"]), None, "1 station row (r c beta, after line 13): at least 2"),
    (dict(blades="2 0.1"), 4, "R = 0.1 m is inside the last station (r = 0.12065 m, line 23)"),
    (dict(blades="2 5"), 4, "stations stop at 0.12065 m = 0.0241 R"),
    (dict(blades="2.5 0.127"), 4, "Nblades = 2.5 is not a whole number in [1, 100]"),
    (dict(cd="0.028 O.050 0.020 0.5"), 9, "CD2u = 'O.050' is not a number"),
    (dict(cd="0.028 nan 0.020 0.5"), 9, "CD2u = 'nan' is not a finite number"),
    (dict(cd="0.028 0.050"), 9, "2 numbers where QPROP's data line 5 reads CD0 CD2u CD2l [CLCD0]"),
    (dict(fac="0.0254 , 0.0254 1.0"), 12, "an empty field where Cfac belongs"),
    (dict(fac="  ! Rfac Cfac Bfac\n 0.0254 0.0254 1.0"), 12, "no values before the '!', where QPROP's data line 7"),
    (dict(fac="1 0.0254 1", blades="2"), None,
     "diameter 2R = 9.5 m (374 in, from the last station's r (line 23)) is outside [0.5, 100] in: are Rfac and Radd"),
    (dict(fac="1 0.0254 1"), 4, "R = 0.127 m is inside the last station (r = 4.75 m, line 23): R must be >= it"),
    (dict(fac="0.0254 0.0254 3"), FIRST_ROW, "beta = 35 gives 105 deg"),
    (dict(add="-0.0254 0 0"), FIRST_ROW, "r = 1 gives 0 m"),
    (dict(rows=[" 1 0.8 35", " 2 1.0 25", " 4.75 0.45"]), FIRST_ROW + 2, "2 numbers where a station row reads r c"),
    (dict(rows=[" 1 0.8 35", " 2 1.0 25", " 4.75 0.45 13 end"]), FIRST_ROW + 2, "CL0 = 'end' is not a number"),
])
def test_a_malformed_file_is_one_error_naming_its_line(tmp_path, change, line, match):
    msg = _message(propfile(tmp_path / "bad.prop", **change))
    assert match in msg, msg
    if line is not None:
        assert f"bad.prop, line {line}: " in msg, msg


def test_a_ragged_table_taken_for_a_qprop_file_is_told_why(tmp_path):
    """A millimetre table of stations under a title, without its header line and with one row of
    two numbers, reads as a QPROP file (lines 2-8 in its pattern, not a table's equal rows: the
    mutation audit of stop 96): its refusal says it was read as one, and what a table needs."""
    table = tmp_path / "mm.txt"
    table.write_text("My blade, mm\n25.4 12.1 30\n40 14\n55 13.5 22\n70 12 18\n85 10 15\n101.6 8 13\n"
                     "110 6 12\n120 4 11\n")
    msg = _message(table)
    assert msg.endswith("line 2: Nblades = 25.4 is not a whole number in [1, 100] (read as a QPROP propeller "
                        "file, whose data line 2 gives the blade count; a table of stations is read with its header "
                        "line, r/R c/R beta)"), msg


def test_a_file_that_ends_early_and_a_tip_chord_of_zero(tmp_path):
    short = tmp_path / "short.prop"
    short.write_text("My prop\n2\n0.5 5.8\n-0.4 1.2\n")
    assert "the file ends after line 4, where QPROP reads CD0 CD2u CD2l CLCD0 next" in _message(short)
    p = read_geometry(propfile(tmp_path / "tip.prop", rows=[" 1 0.8 35", " 3 1.0 20", " 5 0 13"]))
    assert p.chord[-1] == 0 and p.radius == 0.127


def test_the_size_beside_the_file_is_its_own(tmp_path):
    f = propfile(tmp_path / "t.prop")
    assert read_geometry(f, n_blades=2, diameter_in=10).radius == 0.127
    with pytest.raises(GeometryFileError, match="n_blades = 3, but the QPROP file states Nblades"):
        read_geometry(f, n_blades=3)
    with pytest.raises(GeometryFileError, match="diameter_in = 9 in, but a QPROP file gives its own radius"):
        read_geometry(f, diameter_in=9)


def test_detection_by_content_beside_the_other_formats(tmp_path):
    f = propfile(tmp_path / "noext")
    f.write_text(f.read_text().replace("#  r    c    beta", "# STATION  CHORD  TWIST (a PE0's words in a comment)"))
    assert geometry_format(f) == "qprop" and read_geometry(f).n_blades == 2
    uiuc = tmp_path / "x_10x6_geom.txt"
    uiuc.write_text("Test 10x6\nr/R c/R beta\n" + "".join(f"{r / 5:g} {c / 5:g} {b:g}\n" for r, c, b in STATIONS))
    assert geometry_format(uiuc) == "uiuc"
    bare = tmp_path / "bare.txt"  # a headerless table under a title is no QPROP file (r/R 0.2 is no blade count)
    bare.write_text("Test 10x6\n" + "".join(f"{r / 5:g} {c / 5:g} {b:g}\n" for r, c, b in STATIONS))
    assert geometry_format(bare) is None
    mm = tmp_path / "mm.txt"  # nor one in millimetres (three numbers a row; QPROP's line 2 has one or two)
    mm.write_text("Test 10x6\n" + "".join(f"{25.4 * r:g} {25.4 * c:g} {b:g}\n" for r, c, b in STATIONS))
    assert geometry_format(mm) is None
    with pytest.raises(GeometryFileError, match="or a QPROP propeller file"):
        read_geometry(bare)


def test_static_thrust_is_positive_and_finite(tmp_path):
    f = propfile(tmp_path / "t.prop")
    p = read_geometry(f)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        own = read_qprop_params(f)
    for params in (pm.generic_params(), own):
        lo, hi = (pm.rotor_loads(p, params, rpm * RPM, 0.0, 0.0) for rpm in (4000.0, 6000.0))
        assert all(math.isfinite(x) for x in (lo.thrust, lo.torque, hi.thrust, hi.torque))
        assert 0 < lo.thrust < hi.thrust and 0 < lo.torque < hi.torque
        assert hi.thrust / lo.thrust == pytest.approx(2.25, rel=0.1)  # (about Omega^2 at static)


def test_cli_loads_runs_a_qprop_file(capsys, tmp_path):
    f = propfile(tmp_path / "t.prop")
    code, out, err = run(capsys, "loads", f, "--rpm", "5000", "--json")
    assert code == 0, err
    d = json.loads(out)
    assert d["thrust"] > 0 and d["n_blades"] == 2 and d["diameter_m"] == pytest.approx(0.254) and d["params"] == \
        "generic"
    code, out, err = run(capsys, "loads", f, "--rpm", "5000", "--json", "--params", f"qprop:{f}")
    assert code == 0, err
    assert json.loads(out)["params"] == f"qprop:{f}" and "CD2l = 0.02 differ" in err
    code, _, err = run(capsys, "loads", f, "--rpm", "5000", "--blades", "3")
    assert one_line_error(code, err, "the QPROP file states Nblades"), err
    bad = propfile(tmp_path / "bad.prop", blades="2 0.1")
    code, _, err = run(capsys, "loads", bad, "--rpm", "5000")
    assert one_line_error(code, err, "bad.prop, line 4: R = 0.1 m is inside the last station"), err


def test_a_vehicle_rotor_names_a_qprop_file(tmp_path):
    """A vehicle file's rotor ``propeller`` entry reads a QPROP file beside it as its geometry."""
    propfile(tmp_path / "t.prop")
    text = pm.example_file("quadrotor.toml").read_text()
    assert text.count('propeller = "apce_8x6"') == 4
    veh = tmp_path / "v.toml"
    veh.write_text(text.replace('propeller = "apce_8x6"', 'propeller = "t.prop"').replace("0.106", "0.2"))
    rotors = pm.read_vehicle(veh).rotors
    assert len(rotors) == 4 and all(r.propeller.radius == 0.127 and r.propeller.n_blades == 2 for r in rotors)
    assert rotors[0].propeller.same_geometry(read_geometry(tmp_path / "t.prop"))
