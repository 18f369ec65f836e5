"""A review of the QPROP propeller file reader (io/qprop_file.py) against QPROP 1.22's own reading
(M. Drela, qprop.f and io.f: RREAD/GETFLT) and against propfiles as real tools write them. Every
file here is written by the test; the layouts follow propfile writers found in public code (a
QPROP driver writing ``Nblades PropR hubR`` on line 2 and 13-column station rows to ten digits;
multirotor propellers named by size, "1045"; QMIL's input file, which starts as a propfile does)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from propmap.io.geometry_files import GeometryFileError, geometry_format, read_geometry
from propmap.io.qprop_file import read_qprop_geometry, read_qprop_params

from .cli_helpers import one_line_error, run

STATIONS = [(0.02, 0.020, 30.0), (0.05, 0.025, 22.0), (0.08, 0.022, 16.0), (0.11, 0.016, 12.0), (0.125, 0.010, 11.0)]
AERO = "0.4 6.0 -0.5 1.3 0.012 0.03 0.03 0.5 100000 -0.5"


def write(path, *, name="myprop", blades="2 0.127", cd="0.012 0.03 0.03 0.5", rows=None):
    rows = [f"{r:g} {c:g} {b:g}" for r, c, b in STATIONS] if rows is None else rows
    path.write_text("\n".join([name, f"{blades}  ! Nblades [R]", "", "0.4  6.0  ! CL0 CL_a",
                               "-0.5  1.3  ! CLmin CLmax", "", f"{cd}  ! CD0 CD2u CD2l CLCD0",
                               "100000  -0.5  ! REref REexp", "", "1.0  1.0  1.0  ! Rfac Cfac Bfac",
                               "0.0  0.0  0.0  ! Radd Cadd Badd", "", "#  r  chord  beta", *rows]) + "\n")
    return path


def _error(path) -> str:
    with pytest.raises(GeometryFileError) as info:
        read_geometry(path)
    return str(info.value)


def test_line_2_with_values_beyond_nblades_and_R_is_a_qprop_file(tmp_path):
    """QPROP reads two values of line 2 (RREAD with NVAL = 2) and ignores the rest: a driver's
    ``Nblades PropR hubR`` line is a QPROP file's, not an unrecognised format."""
    f = write(tmp_path / "hub.prop", blades="2 0.127 0.015")
    assert geometry_format(f) == "qprop"
    p = read_geometry(f)
    assert p.n_blades == 2 and p.radius == 0.127
    assert p.same_geometry(read_geometry(write(tmp_path / "plain.prop")))


def test_a_name_line_that_is_a_number_is_a_qprop_files_name(tmp_path):
    """QPROP takes any text for the name (FREAD): a multirotor propeller named by its size, 1045."""
    f = write(tmp_path / "p1045.prop", name="1045")
    assert geometry_format(f) == "qprop" and read_geometry(f).n_blades == 2
    g = write(tmp_path / "p10.prop", name="10 4.5")
    assert geometry_format(g) == "qprop"


def test_a_wrong_blade_count_is_the_lines_error_not_an_unrecognised_format(tmp_path):
    for blades in ("0", "0 0.127", "200 0.127"):
        msg = _error(write(tmp_path / "b.prop", blades=blades))
        assert "b.prop, line 2: Nblades = " in msg and "whole number in [1, 100]" in msg, msg


def test_tables_are_still_no_qprop_files(tmp_path):
    """Tables of three or more columns under a header line (a points CSV, a UIUC data file, a flight
    log, a load CSV) have no two-value lines 3, 4 and 6: never a QPROP file."""
    rows = [f"{5 + i},{3000 + 100 * i},{10 * i}" for i in range(12)]
    cases = {"points.csv": "rpm,airspeed,incidence_deg\n" + "\n".join(rows),
             "uiuc_perf.txt": "J CT CP eta\n" + "\n".join(f"{0.05 * i:.2f} 0.1 0.05 0.5" for i in range(12)),
             "spaced.txt": "a b c\n" + "\n".join(f"{1 + i} {2 + i} {3 + i}" for i in range(12)),
             "log.csv": "t,rpm1,rpm2,ax,ay,az\n" + "\n".join(f"{i},5000,5100,0.1,0.2,9.8" for i in range(1, 12)),
             "two.csv": "airspeed,rpm\n" + "\n".join(f"{5 + i},{4000 + i}" for i in range(12))}
    for name, text in cases.items():
        f = tmp_path / name
        f.write_text(text + "\n")
        assert geometry_format(f) is None, name


def test_values_beyond_column_128_are_warned(tmp_path):
    """QPROP reads a line into a 128-character buffer (CHARACTER*128 LINE): a station row written to
    ten decimals in 13 columns has CD2l cut at column 128 and loses the values after it. propmap reads them all
    and says so, naming the line and the value."""
    long = [f"{r:.10f}  {c:.10f}  {b:.10f}  " + "  ".join(f"{float(x):.10f}" for x in AERO.split())
            for r, c, b in STATIONS]
    assert all(len(s) > 128 for s in long)
    f = write(tmp_path / "long.prop", rows=long)
    with pytest.warns(UserWarning, match=r"long.prop, line 14: .*past column 128 .*first 128 characters.*cuts CD2l"):
        p = read_qprop_geometry(f)
    np.testing.assert_allclose(p.r, [s[0] for s in STATIONS])
    with warnings.catch_warnings():  # a file within 128 columns: no such warning
        warnings.simplefilter("error")
        read_qprop_geometry(write(tmp_path / "short.prop", rows=[f"{r:g} {c:g} {b:g} {AERO}" for r, c, b in
                                                                  STATIONS]))


def test_a_number_beyond_the_float_range_is_named_so(tmp_path):
    msg = _error(write(tmp_path / "big.prop", cd="0.012 1e400 0.03 0.5"))
    assert "line 7: CD2u = '1e400'" in msg and "is not a finite number" in msg, msg


def test_an_indented_hash_line_says_the_comment_must_start_the_line(tmp_path):
    f = write(tmp_path / "ind.prop")
    f.write_text(f.read_text().replace("#  r  chord  beta", "   #  r  chord  beta"))
    msg = _error(f)
    assert "ind.prop, line 13: " in msg and "first column" in msg, msg


def test_a_qmil_input_file_is_named_as_such(tmp_path):
    """QMIL's input file starts as a propfile does (name, Nblades, the section lines), then gives
    XIdes, CLdes and one-value lines (hub radius, tip radius, ...): its error says what it is."""
    f = tmp_path / "qmil.txt"
    f.write_text("temp prop\n\n2 !Nblades\n\n0.0 6.2832 ! CL0 CL_A\n-0.8 1.2 ! CLmin CLmax\n\n"
                 "0.01 0.008 0.006 0.4 ! CD0 CD2u CD2l CLCD0\n150000 -0.5 ! Reref REexp\n\n"
                 "0.0 0.5 1.0 ! XIdes\n0.6 0.5 0.4 ! CLdes\n\n0.15 ! hub radius(m)\n1.0 ! tip radius (m)\n"
                 "10 ! speed (m/s)\n2000 ! rpm\n\n30 ! Thrust(N)\n0 ! Power(W)\n\n0 0 ! Ldes KQdes\n")
    msg = _error(f)
    assert "qmil.txt, line 14: " in msg and "QMIL" in msg, msg


def test_params_from_a_file_of_another_format_say_which(tmp_path, capsys):
    uiuc = tmp_path / "x_geom.txt"
    uiuc.write_text("r/R c/R beta\n" + "".join(f"{r / 0.127:.4f} {c / 0.127:.4f} {b:g}\n" for r, c, b in STATIONS))
    with pytest.raises(GeometryFileError, match=r"x_geom.txt: .*UIUC geometry file.*not a QPROP propeller file"):
        read_qprop_params(uiuc)
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", "--params", f"qprop:{uiuc}")
    assert one_line_error(code, err, "not a QPROP propeller file"), err


def test_a_reref_that_varies_along_the_blade_is_said_not_to_be_qprops_own(tmp_path):
    """QPROP 1.22's TQCALC calls CDFUN with the array REREF where the station's REREF(I) belongs, so
    every station's drag is scaled with the first computed station's REref: a REref varying along
    the blade (a propfile writer that gives each station its Reynolds number) is not QPROP's own."""
    rows = [f"{r:g} {c:g} {b:g} 0.4 6.0 -0.5 1.3 0.012 0.03 0.03 0.5 {60000 + 20000 * i} -0.5"
            for i, (r, c, b) in enumerate(STATIONS)]
    with pytest.warns(UserWarning, match=r"0.75 R are taken; QPROP 1.22 itself applies one REref at every station"):
        q = read_qprop_params(write(tmp_path / "re.prop", rows=rows))
    assert q.cl_alpha == 6.0
    same = [f"{r:g} {c:g} {b:g} 0.4 6.0 -0.5 1.3 0.012 0.03 0.03 0.5 100000 -0.5" for r, c, b in STATIONS]
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        read_qprop_params(write(tmp_path / "same.prop", rows=same))
    assert got and not any("applies one REref" in str(w.message) for w in got)


def test_qprop_without_a_file_says_so(capsys):
    """``qprop:`` with no file read Path(""), the working directory: "--params: .: is a directory"."""
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", "--params", "qprop:")
    assert one_line_error(code, err, "'qprop:' names no file: give qprop:FILE"), err


def test_a_three_value_drag_line_names_the_older_layout(tmp_path):
    """Propfile writers in public code still write line 5 as ``CD0 CD2 CLCD0`` (three values):
    QPROP 1.22 reads them as CD0 CD2u CD2l and leaves CLCD0 unset. The set's refusal says so."""
    f = write(tmp_path / "old.prop", cd="0.028 0.050 0.5")
    assert read_geometry(f).n_blades == 2
    with pytest.raises(GeometryFileError, match=r"old.prop, line 7: .*without CLCD0.*CD0 CD2 CLCD0.*CD2l"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            read_qprop_params(f)
