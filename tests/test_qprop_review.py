"""A review of the QPROP propeller file reader (io/qprop_file.py) against QPROP 1.22's own reading
(M. Drela, qprop.f and io.f: RREAD/GETFLT) and against propfiles as real tools write them. Every
file here is written by the test; the layouts follow propfile writers found in public code (a
QPROP driver writing ``Nblades PropR hubR`` on line 2 and 13-column station rows to ten digits;
multirotor propellers named by size, "1045"; QMIL's input file, which starts as a propfile does)."""

from __future__ import annotations

import pytest

from propmap.io.geometry_files import GeometryFileError, geometry_format, read_geometry

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
