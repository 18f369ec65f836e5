"""Hostile input to every file reader: each case of the robustness issue, one test each.

Every reader either returns a valid result or raises its documented error class (a
ValueError) with a one-line message naming the file (and the line, column or key, and the
valid range where it applies): never UnicodeDecodeError, OverflowError, TypeError, ...,
never a hang, never a silent NaN, never a change to the input file.
"""

import math
import os
import re
import threading
import time
import warnings
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.identify import (DataError, VehicleFileError, loads_from_uiuc_files, read_level_flight, read_loads,
                              read_vehicle)
from propmap.io import ParamsFileError, read_params
from propmap.io.readers import (GeometryFileError, MeasurementFileError, looks_like_uiuc, read_apc_pe0, read_geometry,
                                read_uiuc_geometry, read_uiuc_static, read_uiuc_sweep)
from propmap.io.toml_file import load_toml

DATA = Path(str(resources.files("propmap") / "data"))
UIUC = DATA / "uiuc_v1"
PE0 = (DATA / "apc_pe0" / "8x6-PERF.PE0").read_text(encoding="latin-1")
QUAD = (DATA / "examples" / "quadrotor.toml").read_text()
FLIGHT = (DATA / "examples" / "level_flight_synthetic.csv").read_text()
GEOM = "r/R c/R beta\n0.2 0.1 30\n0.5 0.12 20\n1.0 0.05 10\n"
PARAMS = "cl1 = 5.3\ncl2 = 1.7\ncd = 1.8\nalpha0_deg = 20.6\n"
LOADS = "rpm,airspeed,incidence_deg,thrust,torque\n" + "".join(
    f"{5000 + 100 * k},{k},{10 * k},{1 + 0.1 * k},{0.01 + 0.001 * k}\n" for k in range(8))
ROTOR = "[[rotors]]\nposition = [0, 0, 0]\naxis = [0, 0, 1]\nspin = 'cw'\npropeller = 'apce_8x6'\n"
#: the same rotor with a UIUC geometry file, which needs its blade count
GEOM_ROTOR = ("mass = 1\n[[rotors]]\nposition = [0, 0, 0]\naxis = [0, 0, 1]\nspin = 'cw'\nblades = 2\n"
              "propeller = 'apce_8x6'\n")
VEHICLE = "mass = 1\n" + ROTOR


@pytest.fixture(scope="module")
def quad():
    return read_vehicle(DATA / "examples" / "quadrotor.toml")


def _write(tmp_path, name, content) -> Path:
    p = tmp_path / name
    p.write_bytes(content.encode() if isinstance(content, str) else content)
    return p


def refused(error, fn, path, *args, match=None, **kw) -> str:
    """The one-line message of ``error`` raised by ``fn(path, ...)``; it names the file."""
    before = _state(path)
    with pytest.raises(error) as info:
        fn(path, *args, **kw)
    msg = str(info.value)
    assert "\n" not in msg and len(msg) < 600, msg
    assert str(path) in msg, f"message does not name the file: {msg}"
    if match is not None:
        assert re.search(match, msg), msg
    assert _state(path) == before  # never modified
    return msg


def _state(path: Path):
    """What a reader must not change: a small regular file's bytes, else its size and times."""
    if not path.is_file() or path.is_fifo():
        return None
    st = path.stat()
    return (st.st_size, st.st_mtime_ns, path.read_bytes() if st.st_size < 2**20 else None)


# --- encodings ----------------------------------------------------------------------------

def test_non_utf8_loads_csv_names_file_and_line(tmp_path):
    """Windows-1252 (a spreadsheet's save on Windows) is read as such, with a note, since
    2026-11-26 (a stand export re-saved by Excel was refused); a byte it leaves undefined is
    refused naming the line."""
    p = _write(tmp_path, "l.csv", LOADS.encode().replace(b"5300,3", b"5300\x81,3"))
    msg = refused(DataError, read_loads, p, match=r"line 5: byte 0x81 .* not UTF-8")
    assert "load data" in msg
    p = _write(tmp_path, "w.csv", LOADS.encode().replace(b"5300,3", b"5300\xe9,3"))
    refused(DataError, read_loads, p, match=r"line 5")  # (read as 1252: 5300é is not a number)


def test_non_utf8_level_flight_csv(tmp_path, quad):
    p = _write(tmp_path, "d.csv", b"airspeed,pitch_deg,rpm_1,rpm_2,rpm_3,rpm_4,note\n"
               + b"1,-1,5000,5000,5000,5000,caf\x81\n" * 8)
    refused(DataError, read_level_flight, p, quad, match="line 2: byte 0x81")


def test_non_utf8_vehicle_toml(tmp_path):
    p = _write(tmp_path, "v.toml", b"# caf\xe9\n" + VEHICLE.encode())
    refused(VehicleFileError, read_vehicle, p, match="line 1: byte 0xe9.*UTF-8")


def test_non_utf8_params_toml(tmp_path):
    p = _write(tmp_path, "p.toml", PARAMS.encode() + b"comment = 'r\xe9glage'\n")
    refused(ParamsFileError, read_params, p, match="line 5: byte 0xe9")


def test_utf16_and_nul_bytes_are_refused(tmp_path):
    p = _write(tmp_path, "l.csv", LOADS.encode("utf-16"))
    refused(DataError, read_loads, p, match="UTF-16 text; save it as UTF-8")
    p = _write(tmp_path, "p.toml", PARAMS.encode() + b"\x00")
    refused(ParamsFileError, read_params, p, match="NUL byte")
    p = _write(tmp_path, "g_9x6_geom.txt", GEOM.encode("utf-16-le"))  # no BOM: NUL bytes
    refused(GeometryFileError, read_uiuc_geometry, p, match="NUL byte")


def test_utf8_bom_is_accepted_everywhere(tmp_path, quad):
    bom = "\ufeff"
    loads = read_loads(_write(tmp_path, "l.csv", bom + LOADS))  # Excel's "CSV UTF-8"
    assert loads.n == 8 and loads.omega[0] == pytest.approx(5000 * math.pi / 30)
    assert read_level_flight(_write(tmp_path, "d.csv", bom + FLIGHT), quad).n > 6
    assert read_params(_write(tmp_path, "p.toml", bom + PARAMS)).cl1 == 5.3
    assert read_vehicle(_write(tmp_path, "v.toml", bom + VEHICLE)).mass == 1.0
    assert read_uiuc_geometry(_write(tmp_path, "g_9x6_geom.txt", bom + GEOM)).n_blades == 2
    radius = read_geometry(_write(tmp_path, "h_9x6_geom.txt", bom + GEOM), n_blades=2).radius
    assert radius == pytest.approx(4.5 * 0.0254)
    static = _write(tmp_path, "x_9x6_static_r1.txt", bom + "RPM CT CP\n3000 0.1 0.05\n")
    assert looks_like_uiuc(static) and read_uiuc_static(static).rpm[0] == 3000


# --- not a regular file ---------------------------------------------------------------------

READERS = [
    (read_uiuc_geometry, GeometryFileError, {}),
    (read_apc_pe0, GeometryFileError, {}),
    (read_geometry, GeometryFileError, {}),
    (read_uiuc_static, MeasurementFileError, {}),
    (read_uiuc_sweep, MeasurementFileError, {}),
    (read_params, ParamsFileError, {}),
    (read_vehicle, VehicleFileError, {}),
    (read_loads, DataError, {}),
]


@pytest.mark.parametrize("reader, error, kw", READERS, ids=lambda x: getattr(x, "__name__", ""))
def test_directory_missing_file_and_device_are_refused(tmp_path, reader, error, kw):
    refused(error, reader, tmp_path, match="is a directory, not a file", **kw)
    refused(error, reader, tmp_path / "nope.txt", match="no such file", **kw)
    if os.path.exists("/dev/zero"):  # would never end if read
        refused(error, reader, Path("/dev/zero"), match="not a regular file", **kw)


def test_level_flight_and_uiuc_files_refuse_a_directory(tmp_path, quad):
    refused(DataError, read_level_flight, tmp_path, quad, match="directory")
    with pytest.raises(DataError, match="directory"):
        loads_from_uiuc_files([tmp_path], 0.2)
    assert looks_like_uiuc(tmp_path) is False
    assert looks_like_uiuc("/dev/zero") is False
    assert looks_like_uiuc(tmp_path / "nope") is False
    assert looks_like_uiuc("a\x00b") is False


def _finishes(fn, seconds=10.0):
    """Run ``fn`` in a thread; return (finished, exception)."""
    out = {}

    def target():
        try:
            fn()
        except Exception as exc:  # noqa: BLE001 - returned to the test
            out["exc"] = exc

    t = threading.Thread(target=target, daemon=True)
    t.start()
    t.join(seconds)
    return not t.is_alive(), out.get("exc")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes on this OS")
def test_a_named_pipe_does_not_hang(tmp_path):
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    for fn, error in ((read_loads, DataError), (read_params, ParamsFileError), (read_uiuc_geometry, GeometryFileError),
                      (read_uiuc_static, MeasurementFileError)):
        done, exc = _finishes(lambda: fn(fifo))
        assert done, f"{fn.__name__} hangs on a named pipe"
        assert isinstance(exc, error) and "not a regular file" in str(exc)
    done, _ = _finishes(lambda: looks_like_uiuc(fifo))
    assert done and looks_like_uiuc(fifo) is False


def test_files_over_the_size_limit_are_refused_before_reading(tmp_path):
    big = tmp_path / "big.csv"
    with open(big, "wb") as fh:  # sparse: no disk space used
        fh.truncate(201 * 2**20)
    toml = tmp_path / "big.toml"
    with open(toml, "wb") as fh:
        fh.truncate(17 * 2**20)
    t0 = time.perf_counter()
    refused(DataError, read_loads, big, match="201 MiB is larger than 200 MiB")
    refused(ParamsFileError, read_params, toml, match="larger than 16 MiB")
    refused(GeometryFileError, read_geometry, toml, match="larger than 16 MiB")
    refused(MeasurementFileError, read_uiuc_static, toml, match="larger than 16 MiB")
    assert time.perf_counter() - t0 < 0.5  # nothing was read
    lines = _write(tmp_path, "lines.csv", b"rpm,thrust\n" + b"\n" * 10_000_000)
    t0 = time.perf_counter()
    refused(DataError, read_loads, lines, match="10,000,001 lines; a data file may have at most 10,000,000")
    assert time.perf_counter() - t0 < 2.0


# --- CSV structure ----------------------------------------------------------------------------

def test_field_of_131072_characters(tmp_path):
    p = _write(tmp_path, "l.csv", LOADS.replace("5300,3,30", "5300," + "3" * 131072 + ",30"))
    refused(DataError, read_loads, p, match=r"line 5: column 'airspeed' is '333.*' \(131072 characters\), not a finite")
    p = _write(tmp_path, "l.csv", LOADS.replace("5300,3,30", "5300," + "x" * 131072 + ",30"))
    refused(DataError, read_loads, p, match=r"line 5: column 'airspeed': 'xxx.*' \(131072 characters\) is not a number")
    p = _write(tmp_path, "l.csv", LOADS.replace("5300,3,30", "5300," + "x" * 131073 + ",30"))
    refused(DataError, read_loads, p, match="line 5: a field longer than 131072 characters")


def test_long_header_name(tmp_path):
    p = _write(tmp_path, "l.csv", LOADS.replace("torque\n", "torque," + "n" * 256 + "\n", 1))
    refused(DataError, read_loads, p, match=r"line 1: column 6 has a name of 256 characters \(at most 255\)")
    assert read_loads(_write(tmp_path, "ok.csv", LOADS.replace("torque\n", "torque," + "n" * 255 + "\n", 1))).n == 8


def test_non_ascii_column_names(tmp_path, quad):
    p = _write(tmp_path, "l.csv", LOADS.replace("rpm,", "rpm_\u00b2,", 1))
    refused(DataError, read_loads, p, match="column 'rpm_²': unknown unit '²' for rpm")
    p = _write(tmp_path, "d.csv", FLIGHT.replace("rpm_4", "rpm_\u00b2", 1))
    refused(DataError, read_level_flight, p, quad, match=r"rotor columns \['rpm_1', 'rpm_2', 'rpm_3', 'rpm_\u00b2'\]")
    p = _write(tmp_path, "d.csv", FLIGHT.replace("rpm_4", "rpm_\u0664", 1))  # Arabic-Indic digit four
    refused(DataError, read_level_flight, p, quad, match="rpm_1 .. rpm_4 are needed")


def test_duplicate_columns_are_refused(tmp_path, quad):
    p = _write(tmp_path, "l.csv", LOADS.replace("torque", "thrust", 1))
    refused(DataError, read_loads, p, match=r"line 1: column 'thrust' appears twice \(columns 4 and 5\)")
    p = _write(tmp_path, "d.csv", FLIGHT.replace("rpm_4", "rpm_3", 1))
    refused(DataError, read_level_flight, p, quad, match="column 'rpm_3' appears twice")


def test_unterminated_quote(tmp_path):
    p = _write(tmp_path, "l.csv", LOADS.replace("5300,", '"5300,', 1))
    refused(DataError, read_loads, p, match="line 5: unterminated quote")


def test_csv_line_numbers_count_blank_lines_and_quoted_newlines(tmp_path):
    text = LOADS.replace("5300,", "\n\n5300,", 1).replace("5500,5,50,1.5", "5500,5,50,abc")
    msg = refused(DataError, read_loads, _write(tmp_path, "l.csv", text))
    assert "line 9: column 'thrust': 'abc' is not a number" in msg


def test_more_fields_than_the_header(tmp_path):
    p = _write(tmp_path, "l.csv", LOADS + "5900,9,90,2,0.02,7\n")
    refused(DataError, read_loads, p, match="line 10: 6 fields, but the header \\(line 1\\) has 5")
    # trailing empty cells (Excel) are accepted; CRLF line ends too
    assert read_loads(_write(tmp_path, "x.csv", LOADS.replace("\n", ",,\r\n"))).n == 8


def test_numbers_must_be_plain_ascii(tmp_path):
    for bad in ("1_000", "\uff11", "0x10", "nan", "inf", "1e400"):
        p = _write(tmp_path, "l.csv", LOADS.replace("5300,3,30", f"5300,3,{bad}"))
        refused(DataError, read_loads, p, match="line 5: column 'incidence_deg'")


# --- values out of range -------------------------------------------------------------------------

@pytest.mark.parametrize("column, value, match", [
    ("thrust", "1e300", r"thrust must be in \[-100000, 100000\] N, got 1e\+300"),
    ("torque", "-2e4", r"torque must be in \[-10000, 10000\] N m"),
    ("rpm", "1e6", r"rpm must be > 0 and <= 954929 .*got rpm = 1e\+06"),
    ("airspeed", "600", r"airspeed must be in \[0, 500\] m/s"),
    ("incidence_deg", "181", r"incidence_deg must be in \[0, 180\] deg"),
])
def test_loads_out_of_physical_range(tmp_path, column, value, match):
    cols = LOADS.splitlines()[0].split(",")
    rows = [r.split(",") for r in LOADS.splitlines()[1:]]
    rows[3][cols.index(column)] = value
    p = _write(tmp_path, "l.csv", ",".join(cols) + "\n" + "".join(",".join(r) + "\n" for r in rows))
    refused(DataError, read_loads, p, match="line 5: " + match)


def test_loads_rows_of_a_stopped_motor_are_skipped_and_said(tmp_path):
    """rpm 0 (a thrust stand's motor off) is not a point of the model: skipped, with a note."""
    cols = LOADS.splitlines()[0].split(",")
    rows = [r.split(",") for r in LOADS.splitlines()[1:]]
    rows.append(list(rows[0]))
    rows[-1][cols.index("rpm")] = "0"
    d = read_loads(_write(tmp_path, "l.csv", ",".join(cols) + "\n" + "".join(",".join(r) + "\n" for r in rows)))
    assert d.n == len(rows) - 1 and any("1 rows with rpm 0" in n for n in d.notes)


def test_level_flight_ranges_and_partial_body_rates(tmp_path, quad):
    lines = FLIGHT.splitlines()
    head, rows = lines[0], lines[1:]
    bad = rows[:]
    bad[2] = "1,95," + bad[2].split(",", 2)[2]
    refused(DataError, read_level_flight, _write(tmp_path, "d.csv", "\n".join([head, *bad])), quad,
            match=r"line 4: pitch_deg must be in \(-90, 90\) deg, got 95")
    with_p = [head + ",p"] + [r + ",0" for r in rows]
    refused(DataError, read_level_flight, _write(tmp_path, "d.csv", "\n".join(with_p)), quad,
            match="body-rate column\\(s\\) p but not q, r")
    rates = [head + ",p,q,r"] + [r + ",0,0,0" for r in rows]
    rates[5] = rates[5][:-1] + "1e3"
    refused(DataError, read_level_flight, _write(tmp_path, "d.csv", "\n".join(rates)), quad,
            match=r"line 6: r must be in \[-100, 100\] rad/s")


# --- TOML -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("line, match", [
    ("cl1 = " + "1" * 400, r"cl1 must be a finite number in \[0, 100\], got an integer of 400 digits"),
    ('cl1 = "5.3"', "cl1 must be a number, got '5.3' \\(a quoted string"),
    ("cl1 = true", "cl1 must be a number, got True"),
    ("cl1 = 1e300", r"cl1 must be a finite number in \[0, 100\]"),
    ("cl1 = inf", "cl1 must be a finite number"),
    ("cl1 = nan", "cl1 must be a finite number"),
    ("cl1 = [5.3]", "cl1 must be a number"),
    ("alpha0_deg = 120", r"alpha0_deg must be a finite number in \(0, 90\) deg, got 120"),
    ("rho = 1e9", r"rho must be a finite number in \[0.001, 2000\] kg/m\^3"),
    ("rho = 1e-300", r"rho must be a finite number in \[0.001, 2000\] kg/m\^3"),
    ("tip_loss = 1", "tip_loss must be true or false, got 1"),
    ("lift_model = 3", "lift_model must be one of sigmoid, sincos"),
    ("section_model = 1", "section_model must be one of gill2017, cambered, got 1"),
])
def test_params_wrong_types_and_absurd_values(tmp_path, line, match):
    key = line.split(" ")[0]
    text = "".join(ln + "\n" for ln in PARAMS.splitlines() if not ln.startswith(key + " ")) + line + "\n"
    refused(ParamsFileError, read_params, _write(tmp_path, "p.toml", text), match=match)


def test_cambered_params_angles_are_checked_in_degrees(tmp_path):
    p = _write(tmp_path, "p.toml", 'section_model = "cambered"\nalpha_L0_deg = -45\n')
    refused(ParamsFileError, read_params, p, match=r"alpha_L0_deg must be a finite number in \[-20, 10\] deg")
    p = _write(tmp_path, "p.toml", 'section_model = "cambered"\ncl_alpha = ' + "9" * 400 + "\n")
    refused(ParamsFileError, read_params, p, match="cl_alpha must be a finite number, got an integer of 400 digits")


def test_toml_deep_nesting_and_huge_integers(tmp_path):
    p = _write(tmp_path, "p.toml", "x = " + "[" * 5000 + "]" * 5000 + "\n")
    refused(ParamsFileError, load_toml, p, ParamsFileError, match="nested too deeply")
    p = _write(tmp_path, "v.toml", "mass = " + "1" * 5000 + "\n")
    refused(VehicleFileError, read_vehicle, p, match="integer of more than 4300 digits")
    p = _write(tmp_path, "p.toml", "cl1 = 5.3\ncl1 = 5.3\n")
    refused(ParamsFileError, read_params, p, match=r"not valid TOML \(.*line 2")


@pytest.mark.parametrize("edit, match", [
    (("mass = 1", "mass = true"), "mass must be a number > 0 and <= 10000 kg, got True"),
    (("mass = 1", "mass = 1e300"), "mass must be > 0 and <= 10000 kg, got 1e\\+300"),
    (("mass = 1", "mass = " + "7" * 400), "mass must be > 0 and <= 10000 kg, got an integer of 400 digits"),
    (("mass = 1", "mass = '1'"), "mass must be a number"),
    (("mass = 1", "mass = 1\ngravity = 0"), "gravity must be > 0 and <= 100 m/s\\^2"),
    (("mass = 1", "mass = 1\nbody_area = -1"), "body_area must be >= 0 and <= 100 m\\^2"),
    (("mass = 1", "mass = 1\ngravty = 3.7"), "unknown key\\(s\\) gravty"),
    (("position = [0, 0, 0]", "position = [true, false, true]"), "rotor 1 position must be 3 numbers"),
    (("position = [0, 0, 0]", "position = [1e3, 0, 0]"), r"rotor 1 position must have components in \[-100, 100\] m"),
    (("axis = [0, 0, 1]", "axis = [1e300, 0, 1]"),
     r"rotor 1: axis must be non-zero with a length in \[1e-06, 1e\+06\]"),
    (("axis = [0, 0, 1]", "axis = [0, 0, 0]"), "axis must be non-zero"),
    (("axis = [0, 0, 1]", "axis = [nan, 0, 1]"), "axis must be 3 finite numbers"),
    (("spin = 'cw'", "spin = true"), "spin must be 'cw' or 'ccw', got True"),
    (("propeller = 'apce_8x6'", "propeller = 5"), "propeller must be a geometry file, a catalogue name or a size"),
    (("propeller = 'apce_8x6'", "propeller = 'apce_8x7'"), "nominal blade\\); did you mean apce_8x8, apce_8x6"),
    (("propeller = 'apce_8x6'", "propeller = 'apce_8x6'\ndiameter_in = 8"), "rotor 1: unknown key\\(s\\) diameter_in"),
])
def test_vehicle_wrong_types_and_absurd_values(tmp_path, edit, match):
    p = _write(tmp_path, "v.toml", VEHICLE.replace(*edit))
    refused(VehicleFileError, read_vehicle, p, match=match)


@pytest.mark.parametrize("text, match", [
    ("mass = 1\nrotors = [1, 2]\n", r"rotor 1 must be a table \(\[\[rotors\]\]"),
    ("mass = 1\nrotors = 'four'\n", "'rotors' must be a non-empty array of tables"),
    ("mass = 1\nrotors = []\n", "'rotors' must be a non-empty array of tables"),
])
def test_vehicle_rotors_must_be_tables(tmp_path, text, match):
    refused(VehicleFileError, read_vehicle, _write(tmp_path, "v.toml", text), match=match)


def test_vehicle_propeller_path_is_relative_to_the_vehicle_file(tmp_path, monkeypatch):
    (tmp_path / "craft").mkdir()
    (tmp_path / "elsewhere").mkdir()
    _write(tmp_path / "craft", "my_9x6_geom.txt", GEOM)
    v = _write(tmp_path / "craft", "v.toml", GEOM_ROTOR.replace("'apce_8x6'", "'my_9x6_geom.txt'"))
    monkeypatch.chdir(tmp_path / "elsewhere")
    veh = read_vehicle(v)
    assert veh.rotors[0].propeller.radius == pytest.approx(4.5 * 0.0254)
    # a file beside the working directory but not beside the vehicle file is not used
    _write(tmp_path / "elsewhere", "cwd_9x6_geom.txt", GEOM)
    v2 = _write(tmp_path / "craft", "v2.toml", GEOM_ROTOR.replace("'apce_8x6'", "'cwd_9x6_geom.txt'"))
    msg = refused(VehicleFileError, read_vehicle, v2, match="relative path is taken from the vehicle file's folder")
    assert str(tmp_path / "craft" / "cwd_9x6_geom.txt") in msg
    # a subfolder and an absolute path work; a broken geometry file is named
    (tmp_path / "craft" / "props").mkdir()
    _write(tmp_path / "craft" / "props", "sub_10x5_geom.txt", GEOM)
    v3 = _write(tmp_path / "craft", "v3.toml", GEOM_ROTOR.replace("'apce_8x6'", "'props/sub_10x5_geom.txt'"))
    assert read_vehicle(v3).rotors[0].propeller.radius == pytest.approx(5 * 0.0254)
    absolute = (tmp_path / "craft" / "props" / "sub_10x5_geom.txt").as_posix()
    v4 = _write(tmp_path / "elsewhere", "v4.toml", GEOM_ROTOR.replace("'apce_8x6'", f"'{absolute}'"))
    assert read_vehicle(v4).rotors[0].propeller.radius == pytest.approx(5 * 0.0254)
    _write(tmp_path / "craft", "bad_9x6_geom.txt", "r/R c/R beta\n0.2 0.1 nan\n")
    v5 = _write(tmp_path / "craft", "v5.toml", VEHICLE.replace("'apce_8x6'", "'bad_9x6_geom.txt'"))
    refused(VehicleFileError, read_vehicle, v5, match="rotor 1: propeller: .*bad_9x6_geom.txt, line 2: non-finite")
    v6 = _write(tmp_path / "craft", "v6.toml", VEHICLE.replace("'apce_8x6'", "'.'"))
    refused(VehicleFileError, read_vehicle, v6, match="is a directory")


# --- APC PE0 ----------------------------------------------------------------------------------------

def _pe0_with(tmp_path, old, new, count=1):
    assert old in PE0
    return _write(tmp_path, "x-PERF.PE0", PE0.replace(old, new, count))


def test_pe0_nan_in_pitch_column(tmp_path):
    p = _pe0_with(tmp_path, "5.1063", "nan")
    refused(GeometryFileError, read_apc_pe0, p, match=r"line \d+: column 3 \(PITCH\) is 'nan', not a finite number")
    refused(GeometryFileError, read_geometry, p, match="not a finite number")


def test_pe0_blade_count_is_the_files(tmp_path):
    # a PE0 file states its blade count: another is refused, not silently used (+44% thrust)
    p = _pe0_with(tmp_path, "5.1063", "5.1063")
    assert read_geometry(p).n_blades == 2 and read_geometry(p, n_blades=2).n_blades == 2
    refused(GeometryFileError, read_geometry, p, n_blades=3, match="n_blades = 3, but the PE0 file states BLADES: 2")


def test_pe0_malformed_radius_and_blades(tmp_path):
    line = PE0[:PE0.index("RADIUS:")].count("\n") + 1
    p = _pe0_with(tmp_path, "RADIUS:  4.00", "RADIUS:  4.0.0")
    refused(GeometryFileError, read_apc_pe0, p, match=f"line {line}: RADIUS '4.0.0' is not a number")
    p = _pe0_with(tmp_path, "RADIUS:  4.00", "RADIUS:  400")
    refused(GeometryFileError, read_apc_pe0, p, match=r"RADIUS .400. in is outside \[0.25, 50\] in")
    p = _pe0_with(tmp_path, "BLADES:  2", "BLADES:  0")
    refused(GeometryFileError, read_apc_pe0, p, match=r"BLADES '0' is not an integer in \[1, 100\]")
    p = _pe0_with(tmp_path, "BLADES:  2", "BLADES:  " + "9" * 5000)
    refused(GeometryFileError, read_apc_pe0, p, match="BLADES '999")
    p = _pe0_with(tmp_path, "36.4607", "95.0000")
    refused(GeometryFileError, read_apc_pe0, p, match=r"TWIST = 95 deg is outside \[-90, 90\] deg")
    p = _pe0_with(tmp_path, "0.7040", "abc")
    refused(GeometryFileError, read_apc_pe0, p, match="non-numeric value 'abc' in the station table")


# --- UIUC -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("family", ["ef", "kpf", "pl", "vp", "EF"])
def test_uiuc_millimetre_families(tmp_path, family):
    p = _write(tmp_path, f"{family}_130x70_geom.txt", GEOM)
    with pytest.warns(UserWarning, match=f"{re.escape(str(p))}: diameter 130 mm = 5.118 in from the file name"):
        prop = read_uiuc_geometry(p)
    assert prop.diameter == pytest.approx(0.130)  # not 130 in = 3.3 m (57,409 N at 8000 rpm)
    assert prop.pitch == pytest.approx(0.070)
    assert "130 mm" in prop.source and "millimetres" in prop.source
    with pytest.warns(UserWarning, match="millimetres"):
        assert read_geometry(p, n_blades=2).diameter == pytest.approx(0.130)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # an explicit diameter: no guess, no warning
        assert read_uiuc_geometry(p, diameter_in=5.0).diameter == pytest.approx(5 * 0.0254)
        assert read_uiuc_geometry(_write(tmp_path, "apce_9x6_geom.txt", GEOM)).diameter == pytest.approx(9 * 0.0254)


@pytest.mark.parametrize("name, match", [
    ("foo_130x70_geom.txt", "diameter 130 in from the file name is not plausible"),
    ("foo_0.2x1_geom.txt", "diameter 0.2 in from the file name is not plausible"),
    ("ef_10x5_geom.txt", "diameter 10 mm from the file name is not plausible"),
    ("foo_" + "9" * 200 + "x6_geom.txt", "is not plausible"),
])
def test_implausible_diameter_from_name(tmp_path, name, match):
    p = _write(tmp_path, name, GEOM)
    msg = refused(GeometryFileError, read_uiuc_geometry, p, match=match)
    assert r"[0.5, 100] in" in msg and "--diameter-in" in msg


def test_blade_angles_in_radians_warn(tmp_path):
    p = _write(tmp_path, "rad_9x6_geom.txt", "r/R c/R beta\n0.2 0.1 0.52\n0.5 0.12 0.35\n1.0 0.05 0.17\n")
    with pytest.warns(UserWarning, match=f"{re.escape(str(p))}: every blade angle beta is below 1.6 .*radians"):
        read_uiuc_geometry(p)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_uiuc_geometry(_write(tmp_path, "deg_9x6_geom.txt", GEOM))


def test_a_chord_column_in_another_unit_warns(tmp_path, shared_data):
    """The c/R column written as the chord in inches (8 in blade) or as c/D gave 3.4x or half the
    thrust without a word; the largest c/R outside [0.12, 0.6] now warns (the catalogue's 147
    propellers: 0.15-0.39). None of the UIUC geometry files of vol. 1 and 2 in the shared data warns
    (nor, checked once, the 138 shipped in the package)."""
    good = "r/R c/R beta\n0.15 0.12 30\n0.5 0.2 20\n1.0 0.06 10\n"
    for factor, shown in ((4.0, "0.8"), (0.5, "0.1")):
        rows = [line.split() for line in good.splitlines()[1:]]
        text = "r/R c/R beta\n" + "".join(f"{r} {float(c) * factor:g} {b}\n" for r, c, b in rows)
        with pytest.warns(UserWarning, match=f"the largest c/R is {shown}, where the 147 catalogue propellers' lie "
                                             r"within 0.15-0.39: is the c/R column the chord in another unit, or "
                                             r"c/D\?"):
            read_uiuc_geometry(_write(tmp_path, f"x{factor:g}_9x6_geom.txt", text))
    files = sorted((shared_data / "uiuc_propdb").glob("*/*geom*.txt"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (the diameter given here differs from most names')
        warnings.filterwarnings("error", message=".*largest c/R")
        for f in files:
            read_uiuc_geometry(f, diameter_in=9)
    assert len(files) > 100


def test_key_value_lines_of_a_geometry_file_are_said_unread_and_a_title_reads(tmp_path):
    """``blades = 3`` above the table was dropped silently (run as 2 blades); a title or comment
    line above the header read with read_uiuc_geometry but not with read_geometry (by content)."""
    p = _write(tmp_path, "meta_9x6_geom.txt", "diameter_in = 10\nblades = 3\n" + GEOM)
    with pytest.warns(UserWarning, match=r"diameter_in = 10 \(line 1\), blades = 3 \(line 2\) not read: a UIUC "
                                         r"geometry file is its r/R c/R beta table"):
        assert read_uiuc_geometry(p).n_blades == 2
    titled = _write(tmp_path, "titled_9x6_geom.txt", "# my propeller, measured 2024\nMy prop\n" + GEOM
                    + "# a comment between rows\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_geometry(titled, n_blades=2).same_geometry(read_uiuc_geometry(titled))


def test_stations_short_of_the_tip_warn(tmp_path):
    # the blade beyond the last station is extrapolated: said, not silent (r/R 0.8 here)
    p = _write(tmp_path, "part_9x6_geom.txt", "r/R c/R beta\n0.15 0.1 30\n0.3 0.12 25\n0.8 0.1 20\n")
    with pytest.warns(UserWarning, match=f"{re.escape(str(p))}: the stations stop at r/R = 0.8: .*extrapolated"):
        read_uiuc_geometry(p)
    p = _write(tmp_path, "half_9x6_geom.txt", "r/R c/R beta\n0.15 0.1 30\n0.3 0.12 25\n0.5 0.1 20\n")
    refused(GeometryFileError, read_uiuc_geometry, p, match=r"the stations stop at r/R = 0.5: the outer blade, which "
                                                             r"makes most of the thrust, is not given")


def test_stations_far_short_of_the_tip_are_refused(tmp_path):
    """The APC 8x6E's stations (its PE0 file, in the catalogue) with the radii written in metres in
    the r/R column (0.024-0.1016): PCHIP's end polynomials carried the blade to a chord of 2.8e6 R
    and a blade angle of 4.4e5 deg at the tip, with a warning only (with the chord in metres too,
    the audit of 2026-11-26 measured T = -9 N and P = 7.7 MW). Refused by the reader (stations
    inside 0.7 R) and, built by hand, by Propeller (the extrapolation is no blade). The same blade
    measured to 0.84 R still reads, with the warning."""
    p8 = pm.load_propeller("apce_8x6")
    R = p8.radius
    rows = list(zip(p8.r / R, p8.chord / R, np.degrees(p8.theta)))
    metres = "r/R c/R beta\n" + "".join(f"{r * R:.6f} {c:.5f} {b:.3f}\n" for r, c, b in rows)
    p = _write(tmp_path, "m_8x6_geom.txt", metres)
    refused(GeometryFileError, read_uiuc_geometry, p, match=r"the stations stop at r/R = 0.1016: the outer blade")
    with pytest.raises(ValueError, match=r"the blade from the last station \(r = 0.0103226 m, 0.1016 R\) to the tip "
                                         r"extrapolates to a chord of 2.75e\+06 R and a blade angle of 4.442e\+05 deg "
                                         r"\(valid: chord <= R, \|angle\| <= 90 deg\)"):
        pm.Propeller("m", R, 2, p8.r * R, p8.chord, p8.theta)  # (the same, built by hand)
    near = "r/R c/R beta\n" + "".join(f"{r:.6f} {c:.5f} {b:.3f}\n" for r, c, b in rows if r <= 0.84)
    with pytest.warns(UserWarning, match="the stations stop at r/R = 0.8"):
        read_uiuc_geometry(_write(tmp_path, "n_8x6_geom.txt", near))


def test_a_pe0_radius_printed_rounded_reads(shared_data):
    """APC prints RADIUS to 0.01 in: 42x2-PERF.PE0 has RADIUS 2.09 and a last STATION 2.0915 in
    (refused as beyond the radius before); the radius is taken at that station."""
    from propmap.io.geometry_files import read_geometry

    for name in ("42x2-PERF.PE0", "42x4-PERF.PE0"):
        p = read_apc_pe0(shared_data / "apc_vendor_data" / "geometry_PE0" / name)
        assert p.radius == pytest.approx(2.0915 * 0.0254, rel=1e-12) and p.r[-1] == pytest.approx(p.radius)
    path = shared_data / "apc_vendor_data" / "geometry_PE0" / "42x2-PERF.PE0"
    assert read_geometry(path, diameter_in=4.183).radius == pytest.approx(2.0915 * 0.0254)  # to 1e-3
    # (the nominal 4.2 in, the file's 4.183 to one decimal, is taken since 2026-11-30: the file's radius is used)
    assert read_geometry(path, diameter_in=4.2).radius == pytest.approx(2.0915 * 0.0254)
    with pytest.raises(GeometryFileError, match=r"diameter_in = 4.3 in, but a PE0 file gives its own radius "
                                                r"\(diameter 4.183 in\)"):
        read_geometry(path, diameter_in=4.3)


def test_a_pe0_last_station_exactly_half_a_digit_beyond_radius_is_the_tip(tmp_path, shared_data):
    """A last STATION beyond RADIUS by half its last printed digit is within APC's rounding (read_apc_pe0:
    refused only 'by more than half'): RADIUS 2.09 and STATION 2.0950 read with the radius 2.095 in
    (refused before: 2.09 + 0.005 is 2.0949999999999998 in floating point; 592 of the 4975 radii 0.25-49.99
    in so printed were; a mutation audit of the readers, 2026-11-29); 2.0951 stays refused."""
    text = (shared_data / "apc_vendor_data" / "geometry_PE0" / "42x2-PERF.PE0").read_text(encoding="latin-1")
    tip = "      2.0915      0.0001"
    assert text.count(tip) == 1
    p = read_apc_pe0(_write(tmp_path, "h-PERF.PE0", text.replace(tip, "      2.0950      0.0001")))
    assert p.radius == pytest.approx(2.095 * 0.0254, rel=1e-12)
    beyond = _write(tmp_path, "o-PERF.PE0", text.replace(tip, "      2.0951      0.0001"))
    refused(GeometryFileError, read_apc_pe0, beyond,
            match=r"STATION = 2.0951 in is outside \(0, 2.09\] in \(RADIUS\)")


def test_uiuc_geometry_ranges(tmp_path):
    p = _write(tmp_path, "g_9x6_geom.txt", GEOM.replace("0.12 20", "1.5 20"))
    refused(GeometryFileError, read_uiuc_geometry, p, match=r"line 3: c/R = 1.5 is outside \[0, 1\]")
    p = _write(tmp_path, "g_9x6_geom.txt", GEOM.replace("0.12 20", "0.12 -120"))
    refused(GeometryFileError, read_uiuc_geometry, p, match=r"line 3: beta = -120 is outside \[-90, 90\] deg")
    p = _write(tmp_path, "g_9x6_geom.txt", "r/R c/R beta\n0.2 0.1 30\n")
    refused(GeometryFileError, read_uiuc_geometry, p, match="at least 2 blade stations")
    with pytest.raises(GeometryFileError, match="diameter_in must be a number, got True"):
        read_uiuc_geometry(_write(tmp_path, "x.txt", GEOM), diameter_in=True)
    with pytest.raises(GeometryFileError, match="diameter_in must be finite and > 0 in, got .nan."):
        read_uiuc_geometry(_write(tmp_path, "x.txt", GEOM), diameter_in=float("nan"))


def test_uiuc_metadata_lines(tmp_path):
    p = _write(tmp_path, "s_9x6_r1_5000.txt", "Date: 1.2.3\nRPM average = 4.0.0\nJ CT CP eta\n0.1 0.1 0.05 0.2\n")
    refused(MeasurementFileError, read_uiuc_sweep, p, match="line 2: RPM average = '4.0.0' is not a number")
    p = _write(tmp_path, "s_9x6_r1_5000.txt", "Date: 1.2.3\nRPM average = 1e999\nJ CT CP eta\n0.1 0.1 0.05 0.2\n")
    refused(MeasurementFileError, read_uiuc_sweep, p, match=r"line 2: RPM average = '1e999' is outside \(0, 954929\]")
    p = _write(tmp_path, "s_9x6_r1_5e500.txt", "J CT CP eta\n0.1 0.1 0.05 0.2\n")
    refused(MeasurementFileError, read_uiuc_sweep, p, match="the rpm '5e500' at the end of the file name is outside")
    p = _write(tmp_path, "s_9x6_r1_5000.txt", "Date: 1.2.3\nJ CT CP eta\n0.1 0.1 0.05 0.2\n")
    assert read_uiuc_sweep(p).rpm == 5000  # an unrelated key: value line is ignored
    p = _write(tmp_path, "s_9x6_static_r1.txt", "RPM CT CP\n1e9 0.1 0.05\n")
    refused(MeasurementFileError, read_uiuc_static, p, match=r"line 2: RPM = 1e\+09 is outside \(0, 954929\]")
    p = _write(tmp_path, "s_9x6_r1_5000.txt", "J CT CP eta\n0.1 50 0.05 0.2\n")
    refused(MeasurementFileError, read_uiuc_sweep, p, match=r"line 2: CT = 50 is outside \[-10, 10\]")


def test_long_lines_are_linear_time(tmp_path):
    """A 131,072-character line of spaces (once a regex backtracking trap) is refused fast."""
    p = _write(tmp_path, "g_9x6_geom.txt", "a" + " " * 131072 + "b\n" + GEOM)
    t0 = time.perf_counter()
    assert read_uiuc_geometry(p).n_blades == 2  # a header line, then the table
    p = _write(tmp_path, "s_9x6_r1_5000.txt", "J CT CP eta\n" + "a" + " " * 131072 + "=b\n")
    refused(MeasurementFileError, read_uiuc_sweep, p, match="line 2: expected 4 columns, found 2")
    assert time.perf_counter() - t0 < 2.0


def test_uiuc_files_converted_to_out_of_range_loads(tmp_path):
    p = _write(tmp_path, "s_9x6_static_r1.txt", "RPM CT CP\n900000 9 5\n")
    with pytest.raises(DataError, match=r"static_r1.txt: thrust .* N .* is outside \[-100000, 100000\] N") as info:
        loads_from_uiuc_files([p], 2.0)
    assert str(info.value).startswith(f"{p}: thrust 3.969e+10 N")
    with pytest.raises(DataError, match=r"diameter must be a finite number in \(0, 10\] m"):
        loads_from_uiuc_files([p], float("inf"))
    q = _write(tmp_path, "notes.txt", "hello\n")
    with pytest.raises(DataError, match="notes.txt: not a UIUC static"):
        loads_from_uiuc_files([q], 0.2)


# --- the Propeller record ----------------------------------------------------------------------------

@pytest.mark.parametrize("kw, match", [
    ({"radius": True}, "radius must be finite and > 0 m, got True"),
    ({"radius": "0.1"}, "radius must be finite"),
    ({"radius": 10**400}, "radius must be finite"),
    ({"n_blades": math.inf}, "n_blades must be an integer >= 1, got inf"),
    ({"n_blades": math.nan}, "n_blades must be an integer"),
    ({"n_blades": 2.5}, "n_blades must be an integer"),
    ({"n_blades": None}, "n_blades must be an integer"),
    ({"n_blades": True}, "n_blades must be an integer"),
    ({"r": ["a", "b"]}, "r must be an array of numbers"),
    ({"r": [True, 2]}, "r must be an array of numbers"),
    ({"chord": [[0.01], [0.01, 0.02]]}, "chord must be an array of numbers"),
    ({"theta": [10**400, 0.2]}, "theta must be an array of numbers"),
    ({"pitch": math.nan}, "pitch must be a finite number"),
])
def test_propeller_refuses_wrong_types_with_value_error(kw, match):
    args = dict(name="x", radius=0.1, n_blades=2, r=[0.01, 0.1], chord=[0.01, 0.01], theta=[0.3, 0.2])
    with pytest.raises(ValueError, match=match) as info:
        pm.Propeller(**{**args, **kw})
    assert type(info.value) is ValueError
    p = pm.Propeller(**{**args, "n_blades": 3.0, "radius": np.float32(0.1), "pitch": 0.05})
    assert p.n_blades == 3 and isinstance(p.n_blades, int) and p.pitch == 0.05


def test_a_stall_angle_in_radians_warns(tmp_path):
    """alpha0_deg = 0.36 (20.6 deg in radians) gave 0.40x the thrust of the paper's set without a
    word; a stall angle below 2 deg now warns (Table I: 20.4-27.5 deg)."""
    p = _write(tmp_path, "p.toml", PARAMS.replace("alpha0_deg = 20.6", "alpha0_deg = 0.36"))
    with pytest.warns(UserWarning, match=r"alpha0_deg = 0.36 deg is small for the angle it is: radians\? "
                                         r"\(0.36 rad = 20.6 deg; read as degrees\)"):
        read_params(p)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_params(_write(tmp_path, "q.toml", PARAMS))


def test_a_sweep_whose_eta_is_not_j_ct_over_cp_warns(tmp_path):
    """CT and CP swapped in a UIUC sweep fitted without a word (exit 0, only a bound warning);
    eta, computed by UIUC from the file's own J, CT and CP (within 0.33% in the median on the
    1,051 sweep files of both volumes that have two points or more to judge), now exposes it."""
    rows = [(0.2, 0.10, 0.050), (0.4, 0.08, 0.046), (0.6, 0.05, 0.038)]
    good = "J CT CP eta\n" + "".join(f"{j} {ct} {cp} {j * ct / cp:.4f}\n" for j, ct, cp in rows)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_uiuc_sweep(_write(tmp_path, "p_9x6_ab0001_5000.txt", good))
    swapped = "J CT CP eta\n" + "".join(f"{j} {cp} {ct} {j * ct / cp:.4f}\n" for j, ct, cp in rows)
    with pytest.warns(UserWarning, match=r"the eta column is .* times J CT / CP in the median: are the CT and CP "
                                         r"columns swapped or out of order\?"):
        read_uiuc_sweep(_write(tmp_path, "q_9x6_ab0002_5000.txt", swapped))


def test_a_row_with_more_fields_than_the_header_is_refused(tmp_path):
    """A static row '3211 0.1033 0 .0540' (a value split by a blank) was read as CP = 0, the
    extra field dropped; no UIUC file of either volume has such a row."""
    p = _write(tmp_path, "s_9x6_static_ab0001.txt", "RPM CT CP\n3000 0.1030 0.0530\n3211 0.1033 0 .0540\n")
    refused(MeasurementFileError, read_uiuc_static, p, match=r"line 3: 4 fields where the header has 3 \(a value "
                                                             r"split by a blank\?\)")


def test_a_pe0_files_stations_are_checked_as_a_uiuc_files(tmp_path):
    """The PE0 reader skipped the station checks: the APC 8x6E cut at 0.59 R read silently with
    20% more thrust (a user-level audit)."""
    from propmap.io.geometry_files import read_geometry

    src = resources.files("propmap") / "data" / "apc_pe0" / "8x6E-PERF.PE0"
    text = src.read_text()
    lines = text.splitlines(keepends=True)
    head = next(i for i, ln in enumerate(lines) if "STATION" in ln.split() and "TWIST" in ln.split())
    radius = 4.0  # [in] (the 8x6E's RADIUS)

    def cut(lo, hi):  # the station table kept between lo and hi r/R (the units line under the header kept)
        out = lines[:head + 2]
        for ln in lines[head + 2:]:
            parts = ln.split()
            try:
                x = float(parts[0]) / radius if len(parts) >= 13 else None
            except ValueError:
                x = None
            if x is None:
                out.append(ln)
            elif lo <= x <= hi:
                out.append(ln)
        return "".join(out)

    short = tmp_path / "to060-PERF.PE0"
    short.write_text(cut(0.0, 0.60))
    refused(GeometryFileError, read_geometry, short, match=r"the stations stop at r/R = 0\.5\d+: the outer blade")
    part = tmp_path / "to080-PERF.PE0"
    part.write_text(cut(0.0, 0.80))
    with pytest.warns(UserWarning, match=r"the stations stop at r/R = 0\.7\d+: .*extrapolated"):
        read_geometry(part)
    late = tmp_path / "from050-PERF.PE0"
    late.write_text(cut(0.5, 1.0))
    with pytest.warns(UserWarning, match=r"the stations start at r/R = 0\.5\d*: the blade inside it makes no load"):
        read_geometry(late)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_geometry(src)  # (the whole file: quiet)


def test_a_windows_1252_level_flight_csv_is_still_refused(tmp_path, quad):
    """Only load data are read as Windows-1252 (with a note in their notes); a level-flight CSV,
    whose data carry no notes, stays refused naming the byte."""
    p = _write(tmp_path, "d.csv", b"airspeed,pitch_deg,rpm_1,rpm_2,rpm_3,rpm_4,note\n"
               + b"1,-1,5000,5000,5000,5000,caf\xe9\n" * 8)
    refused(DataError, read_level_flight, p, quad, match="line 2: byte 0xe9")


def test_uiuc_columns_in_another_order_are_named(tmp_path):
    """A UIUC static file with its columns reordered, or a sweep without its eta column, fell to the
    CSV reader, which said it found no rotation speed (a user-level audit, 2026-11-26)."""
    p = _write(tmp_path, "x_9x6_static_0001rd.txt", b"RPM  CP  CT\n3000 0.05 0.11\n4000 0.05 0.11\n")
    q = _write(tmp_path, "x_9x6_0002rd_4000.txt", b"J CT CP\n0.2 0.09 0.05\n0.4 0.06 0.045\n")
    csv = _write(tmp_path, "t.tsv", b"J\tCT\tCP\tRPM\tthrust (N)\n0.2\t0.09\t0.05\t4000\t3.1\n")
    assert not looks_like_uiuc(csv)  # (those columns first, then a CSV's own: a CSV, read by the CSV reader)
    # UIUC's own orders with a CSV's columns after them: CSVs too (read as UIUC files, the thrust column dropped
    # without a word, until 2026-11-29: a mutation audit)
    for i, head in enumerate((b"RPM\tCT\tCP\tthrust (N)\n4000\t0.09\t0.05\t3.1\n",
                              b"J CT CP eta RPM\n0.2 0.09 0.05 0.36 4000\n")):
        assert not looks_like_uiuc(_write(tmp_path, f"c{i}.tsv", head))
    for path, header in ((p, "RPM  CP  CT"), (q, "J CT CP")):
        assert looks_like_uiuc(path)
        refused(DataError, lambda f, d: loads_from_uiuc_files([f], d), path, 0.2286,
                match=f"not a UIUC static .* its header is '{header}'; UIUC's columns come in that order")


@pytest.mark.parametrize("stem", ["hq_6x4.5x3_geom", "hq_6x4.5_3b_geom", "hq_6x4.5x3"])
def test_a_blade_count_in_a_geometry_files_name_is_compared(tmp_path, stem):
    """A tri-blade's geometry named 'hq_6x4.5x3_geom.txt' or '..._3b_geom.txt' ran with --blades 2
    unwarned (a new-family audit, 2026-11-26)."""
    import warnings

    p = _write(tmp_path, f"{stem}.txt", b"r/R c/R beta\n0.2 0.15 30\n0.5 0.2 20\n0.75 0.18 14\n1.0 0.08 10\n")
    with pytest.warns(UserWarning, match=r"2 blades \(n_blades, --blades\), not the 3 of the file name"):
        read_geometry(p, n_blades=2)
    # (no count given: the name's, with a warning, since 2026-12-02; refused before, for want of a count it gives)
    with pytest.warns(UserWarning, match=r"3 blades, from the file name"):
        assert read_geometry(p).n_blades == 3
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_geometry(p, n_blades=3).diameter == pytest.approx(6 * 0.0254)


@pytest.mark.parametrize("name, want", [("roll (deg)", "roll_deg"), ("roll", "roll_deg"), ("Roll_rad", "roll_deg"),
                                        ("q [deg/s]", "p, q, r"), ("p (deg/s)", "p, q, r"), ("p_deg_s", "p, q, r"),
                                        ("pitch_rate", "p, q, r"), ("roll rate (deg/s)", "p, q, r"),
                                        ("q (Pa)", None), ("q_dyn", None), ("pitch_cmd", None), ("roll_sp", None),
                                        ("airspeed_std", None), ("airspeed_kmh", None), ("r_hub", None),
                                        ("pitch", None)])
def test_level_flight_refuses_a_known_quantity_under_another_name(tmp_path, quad, name, want):
    """A roll or a body rate under its bare stem or in another unit was ignored and read as 0 (a
    roll of 10 deg fitted as level flight; an input fuzzing audit, 2026-11-27). Other names on
    those stems (a command, a dynamic pressure, a spread) or a column whose right name is there
    (airspeed beside airspeed_kmh, pitch_deg beside pitch) stay unread (a review)."""
    lines = FLIGHT.strip().splitlines()
    text = "\n".join([lines[0] + f",{name}"] + [ln + ",10" for ln in lines[1:]]) + "\n"
    if want is None:
        assert read_level_flight(_write(tmp_path, "d.csv", text), quad).n == len(lines) - 1
        return
    msg = refused(DataError, read_level_flight, _write(tmp_path, "d.csv", text), quad,
                  match=f"line 1: column '{re.escape(name)}' is not read")
    assert f"give this one as {want}" in msg


def test_level_flight_warns_of_a_mistyped_rotor_and_of_speeds_far_from_hover(tmp_path, quad):
    """A truncated value (646 among 6470 rpm) and rotor speeds in rad/s were fitted without a word
    (an input fuzzing audit, 2026-11-27); the bundled example gets no warning."""
    from propmap.identify.level_flight import level_flight_warnings
    assert level_flight_warnings(read_level_flight(DATA / "examples" / "level_flight_synthetic.csv", quad), quad) == []
    lines = FLIGHT.strip().splitlines()
    cut = lines[:4] + [lines[4].rsplit(",", 1)[0] + ",529"] + lines[5:]
    w = level_flight_warnings(read_level_flight(_write(tmp_path, "d.csv", "\n".join(cut) + "\n"), quad), quad)
    assert len(w) == 1 and w[0].startswith("data row 4: rpm_4 = 529 is 0.1 times the row's median rotor speed")
    head, rows = lines[0], [ln.split(",") for ln in lines[1:]]
    radps = [",".join(r[:2] + [f"{float(x) * math.pi / 30:.3f}" for x in r[2:]]) for r in rows]
    w = level_flight_warnings(read_level_flight(_write(tmp_path, "r.csv", "\n".join([head] + radps) + "\n"), quad),
                              quad)
    assert len(w) == 1 and "0.11 times the vehicle's hover speed" in w[0] and "(not rad/s or rev/s)" in w[0]


@pytest.mark.parametrize("damage", ["blank", "short", "decimal commas"])
def test_a_pe0_station_table_cut_short_by_a_damaged_row_is_refused(tmp_path, damage):
    """A blank, short or decimal-comma row near the tip ended the station table there: the rows
    after it were dropped and the tip extrapolated, +0.4% thrust, without a word (an input
    fuzzing audit, 2026-11-27). The intact file reads all its stations."""
    lines = PE0.splitlines(keepends=True)
    rows = [k for k, ln in enumerate(lines) if len(ln.split()) >= 13 and ln.split()[0][0].isdigit()]
    whole = read_apc_pe0(_write(tmp_path, "8x6-PERF.PE0", PE0))
    assert whole.r.size == len(rows)
    k = rows[-3]
    cut = {"blank": "\n", "short": " ".join(lines[k].split()[:12]) + "\n",
           "decimal commas": lines[k].replace(".", ",")}[damage]
    bad = _write(tmp_path, "8x6b-PERF.PE0", "".join(lines[:k] + [cut] + lines[k + 1:]))
    refused(GeometryFileError, read_apc_pe0, bad, match=f"line {k + 1}: the station table breaks off here .* goes "
                                                        f"on at line {k + 2}: repair line {k + 1}")


@pytest.mark.parametrize("line", ["RPM average = 4,998", "RPM average = 4998 rpm", "rpm: 4 998"])
def test_a_sweep_rate_line_that_is_not_a_plain_number_is_refused(tmp_path, line):
    """'RPM average = 4,998' was not read as the rate, and the file name's nominal rpm (0.4% off)
    taken without a word (an input fuzzing audit, 2026-11-27)."""
    body = (UIUC / "apce_8x6_2798rd_4009.txt").read_text()
    f = _write(tmp_path, "apce_8x6_2801rd_4004.txt", line + "\n" + body)
    refused(MeasurementFileError, read_uiuc_sweep, f, match=f"line 1: '{re.escape(line)}': the rate must be a plain "
                                                            "number")
    assert read_uiuc_sweep(_write(tmp_path, "b_8x6_r_4004.txt", "RPM average = 4998\n" + body)).rpm == 4998
    assert read_uiuc_sweep(_write(tmp_path, "c_8x6_r_4004.txt", "RPM_average = 4998\n" + body)).rpm == 4998


def test_a_copy_suffix_in_a_sweep_file_name_is_not_its_rate(tmp_path):
    """apce_10x7_pg0813_5018_2.txt was read at 2 rpm (an input fuzzing audit, 2026-11-27)."""
    body = (UIUC / "apce_8x6_2798rd_4009.txt").read_text()
    f = _write(tmp_path, "apce_8x6_2801rd_4004_2.txt", body)
    refused(MeasurementFileError, read_uiuc_sweep, f, match=r"the rpm '2' at the end of the file name is 2, below "
                                                            r"100 rpm: not a sweep's rate \(a copy's suffix\?\)")
