"""Decisions made on an exception's or a warning's structure, not on its message text.

Each of these was decided by reading a message (``"expected columns" in str(exc)``, ...) until
2026-12-01: a file or folder whose name held those words was misread, and a change of wording
would have changed behaviour without a test noticing. Each test pins the structured
information, that the user-visible message is what it was, and (where it can) that the decision
survives a reworded message.
"""

import dataclasses
import pickle

import numpy as np
import pytest

import propmap as pm

import propmap.io.readers as readers
from propmap.identify import DataError, loads_from_uiuc_files, read_loads
from propmap.identify.result import FitResult, _identifiability
from propmap.io.inputs import decode_input_text
from propmap.io.geometry_files import GeometryFileError, read_uiuc_geometry
from propmap.io.readers import MeasurementFileError, read_uiuc_static, read_uiuc_sweep

STATIC = "RPM CT CP\n3000 0.11 0.05\n4000 0.11 0.05\n"
SWEEP = "J CT CP eta\n0.2 0.09 0.05 0.36\n0.4 0.06 0.045 0.53\n"


def _write(folder, name, text):
    folder.mkdir(parents=True, exist_ok=True)
    p = folder / name
    p.write_text(text)
    return p


# ---- 1. a UIUC file's kind: MeasurementFileError.found_header -------------------------------------------------


def test_a_missing_header_is_the_errors_found_header_and_the_message_is_unchanged(tmp_path):
    p = _write(tmp_path, "x_9x6_static_r1.txt", SWEEP)
    with pytest.raises(MeasurementFileError) as info:
        read_uiuc_static(p)
    assert info.value.found_header == "'J CT CP eta'"
    assert str(info.value) == f"{p}: expected columns RPM CT CP, found header 'J CT CP eta'"
    q = _write(tmp_path, "x_9x6_r1_4000.txt", STATIC)
    with pytest.raises(MeasurementFileError) as info:
        read_uiuc_sweep(q)
    assert info.value.found_header == "'RPM CT CP'"
    assert str(info.value) == f"{q}: expected columns J CT CP eta, found header 'RPM CT CP'"
    g = _write(tmp_path, "geom.txt", "r/R c/R\n0.2 0.1\n0.5 0.1\n")
    with pytest.raises(GeometryFileError) as info:
        read_uiuc_geometry(g)
    assert info.value.found_header == "'r/R c/R'"
    assert str(info.value) == f"{g}: expected columns r/R c/R beta, found header 'r/R c/R'"
    back = pickle.loads(pickle.dumps(info.value))  # (kept across processes: validate-all's workers)
    assert back.found_header == "'r/R c/R'" and str(back) == str(info.value)


@pytest.mark.parametrize("text", ["", "RPM CT CP\n3000 x 0.05\n", "RPM CT CP\n", "RPM CT CP\n3000 0.11 11\n"])
def test_every_other_problem_has_no_found_header(tmp_path, text):
    p = _write(tmp_path, "x_9x6_static_r1.txt", text)
    with pytest.raises(MeasurementFileError) as info:
        read_uiuc_static(p)
    assert info.value.found_header is None
    assert MeasurementFileError("anything").found_header is None


@pytest.mark.parametrize("name, text, said", [
    ("x_9x6_static_r1.txt", "RPM CT CP\n3000 zz 0.05\n", "line 2: non-numeric value 'zz' in column CT"),
    ("x_9x6_r1_4000.txt", "J CT CP eta\n0.2 zz 0.05 0.36\n", "line 2: non-numeric value 'zz' in column CT"),
])
def test_a_folder_named_like_the_message_does_not_change_the_files_kind(tmp_path, name, text, said):
    """A static (or sweep) file with a bad value, in a folder whose name holds "expected columns" and
    "found header ": read by the message's text, both errors looked like a missing header and the
    file was called neither kind, its header the folder's name."""
    p = _write(tmp_path / "expected columns, found header here", name, text)
    with pytest.raises(DataError) as info:
        loads_from_uiuc_files([p], 0.2286)
    assert str(info.value) == f"{p}, {said}"


def test_the_kind_is_decided_on_found_header_whatever_the_messages_say(tmp_path, monkeypatch):
    """The readers' messages reworded: the decision (and so which message is shown) is the same."""
    p = _write(tmp_path, "x.txt", "anything\n")

    def failing(header, message):
        def read(path):
            exc = MeasurementFileError(message)
            exc.found_header = header
            raise exc
        return read

    # the static reader failed on a value, the sweep reader on the header: the static reader's error
    monkeypatch.setattr(readers, "read_uiuc_static", failing(None, "static: a value is wrong"))
    monkeypatch.setattr(readers, "read_uiuc_sweep", failing("'RPM CT CP'", "sweep: no such columns"))
    with pytest.raises(DataError, match="^static: a value is wrong$"):
        loads_from_uiuc_files([p], 0.2286)
    # both failed on the header: neither kind, naming the header found
    monkeypatch.setattr(readers, "read_uiuc_static", failing("'a b c'", "static: no such columns"))
    monkeypatch.setattr(readers, "read_uiuc_sweep", failing("'a b c'", "sweep: no such columns"))
    with pytest.raises(DataError) as info:
        loads_from_uiuc_files([p], 0.2286)
    assert str(info.value) == (f"{p}: not a UIUC static (RPM CT CP) or wind-tunnel (J CT CP eta) file: its header is "
                               "'a b c'; UIUC's columns come in that order, a wind-tunnel run with its eta column")
    # the sweep reader failed on a value (a file of its header): its error, whatever the wording
    monkeypatch.setattr(readers, "read_uiuc_sweep", failing(None, "sweep: expected columns, found header 'x'"))
    with pytest.raises(DataError, match="^sweep: expected columns, found header 'x'$"):
        loads_from_uiuc_files([p], 0.2286)


# ---- 2. the CSV reader's Windows-1252 fallback: DataError.not_utf8 --------------------------------------------

LOADS = "rpm,thrust (N),torque (N m)\n" + "".join(f"{r},{r * 1e-4:.3f},{r * 1e-6:.5f}\n"
                                                  for r in range(3000, 9000, 500))


def test_bytes_that_are_not_utf8_are_the_errors_not_utf8_and_the_message_is_unchanged(tmp_path):
    raw = b"a,b\n1,caf\xe9\n"
    with pytest.raises(DataError) as info:
        decode_input_text(raw, "f.csv", DataError)
    assert info.value.not_utf8 is True
    assert str(info.value) == "f.csv, line 2: byte 0xe9 (byte 6 of the line) is not UTF-8; save the file as UTF-8"
    for other, said in ((b"\xff\xfea\x00", "f.csv: UTF-16 text; save it as UTF-8"),
                        (b"\xff\xfe\x00\x00a\x00\x00\x00", "f.csv: UTF-32 text; save it as UTF-8"),
                        (b"a\x00b", "f.csv, line 1: NUL byte: a binary file, not text")):
        with pytest.raises(DataError) as info:
            decode_input_text(other, "f.csv", DataError)
        assert info.value.not_utf8 is False and str(info.value) == said
    assert DataError("anything").not_utf8 is False


def test_windows_1252_is_still_read_with_its_note(tmp_path):
    p = _write(tmp_path, "w.csv", "")
    p.write_bytes(LOADS.replace("torque (N m)", "torque (N\u00b7m)").encode("cp1252"))
    d = read_loads(p)
    assert f"{p} is not UTF-8: read as Windows-1252 (a spreadsheet's save on Windows)" in d.notes


@pytest.mark.parametrize("encode, said", [
    (lambda t: t.encode("utf-16"), ": UTF-16 text; save it as UTF-8"),
    (lambda t: t.encode().replace(b"3000", b"30\x0000"), ", line 2: NUL byte: a binary file, not text"),
])
def test_a_folder_named_like_the_message_does_not_read_the_file_as_windows_1252(tmp_path, encode, said):
    """UTF-16 text or a NUL byte in a folder named '... is not UTF-8 ...': read by the message's text, the
    fallback took the file for Windows-1252 and said it had no rotation-speed column (found 'ÿþr\\x00p...'), or
    that '30\\x0000' was not a number."""
    folder = tmp_path / "this file is not UTF-8"
    p = _write(folder, "l.csv", "")
    p.write_bytes(encode(LOADS))
    with pytest.raises(DataError) as info:
        read_loads(p)
    assert str(info.value) == f"load data: {p}{said}"


# ---- 3. the fit commands' report on standard output: written without the warnings, not filtered by text ------


def _fit(warnings=(), idf_warnings=()):
    """A FitResult of a synthetic fit (as tests/test_audit_section_report.py's), with these warnings."""
    names, x = ("cl_alpha", "alpha_L0", "cd_min"), np.array([5.5, -0.06, 0.02])
    rng = np.random.default_rng(7)
    jac, residuals = rng.standard_normal((12, 3)), 1e-3 * rng.standard_normal(12)
    idf = _identifiability(names, x, jac, residuals)
    idf = dataclasses.replace(idf, warnings=tuple(idf_warnings), warning_kinds=())
    return FitResult(params=pm.CamberedParams(), air=pm.Air(), names=names, x=x, residuals=residuals,
                     cost=0.5 * float(residuals @ residuals), nfev=10, n_model_points=100, elapsed_s=0.5,
                     success=True, message="ok", starts=[], identifiability=idf, warnings=tuple(warnings))


def _outputs(tmp_path, capsys, res, **kw):
    from propmap.cli.fit import _write_outputs

    capsys.readouterr()
    _write_outputs(res, tmp_path / "p.toml", "generic", False, **kw)
    return capsys.readouterr(), (tmp_path / "p.report.txt").read_text()


def test_the_printed_report_is_report_txt_without_the_warnings(tmp_path, capsys):
    """As before for ordinary warnings: report.txt has every line, standard output all but the fit's
    warnings and the data's (said on standard error), the identifiability's kept."""
    res = _fit(warnings=("fit warning a", "fit warning b"), idf_warnings=("poorly determined: cd_min",))
    (out, err), text = _outputs(tmp_path, capsys, res, header="a header", extra_text="extra 1\nextra 2",
                                data_warnings=["a data warning"])
    lines = text.splitlines()
    assert lines[0] == "a header" and "extra 1" in lines and lines[-1] == "DATA WARNING: a data warning"
    assert {"WARNING: fit warning a", "WARNING: fit warning b", "WARNING: poorly determined: cd_min"} <= set(lines)
    gone = {"WARNING: fit warning a", "WARNING: fit warning b", "DATA WARNING: a data warning"}
    assert out == "\n".join(line for line in lines if line not in gone) + "\n"  # (the old filter's output)
    assert "propmap: warning: fit warning a\npropmap: warning: fit warning b\n" in err


def test_a_line_that_reads_like_a_warning_is_printed_and_a_two_line_warning_is_not(tmp_path, capsys):
    """Filtered by the lines' text, an identifiability warning that read as a fit warning and an extra line
    that read 'WARNING: <a fit warning>' were dropped from standard output, and a fit warning over two
    lines printed its second line there."""
    res = _fit(warnings=("same words", "first line\nsecond line"), idf_warnings=("same words",))
    (out, err), text = _outputs(tmp_path, capsys, res, extra_text="WARNING: same words")
    assert text.count("WARNING: same words") == 3  # the fit's, the identifiability's, the extra line
    assert out.count("WARNING: same words") == 2  # the identifiability's and the extra line
    assert "second line" in text and "second line" not in out
    assert "propmap: warning: same words\n" in err and "propmap: warning: first line\nsecond line\n" in err


# ---- 4. sanity_check names wind axes first in a refusal on _wind_axes' answer, not on the warnings' text -------


def _wind_data(scale=1.0, wind=True):
    """Loads of an APC 10x7 at 20-160 deg: a tunnel's force along the flow under 'thrust' and its lift
    under 'drag' (``wind``), or the rotor's own loads times ``scale``."""
    prop = pm.load_propeller("apce_10x7")
    omega = np.full(16, 6000 * np.pi / 30)
    V, inc = np.tile([6.0, 12.0], 8), np.radians(np.repeat(np.linspace(20, 160, 8), 2))
    r = pm.rotor_loads(prop, pm.generic_params(), omega, V, inc)
    along, lift = r.thrust * np.cos(inc) - r.drag * np.sin(inc), r.thrust * np.sin(inc) + r.drag * np.cos(inc)
    T, D = (along, lift) if wind else (scale * r.thrust, scale * r.drag)
    return prop, pm.identify.LoadData(omega, V, inc, {"thrust": T, "drag": D}, np.full(16, "a", dtype=object))


WIND_FIRST = "likely loads in wind axes, not the rotor's (thrust = L sin i - D_w"


def test_wind_axes_are_named_first_whatever_the_warning_says(monkeypatch):
    import propmap.identify.sanity as sanity
    import propmap.identify.sanity_inplane as sanity_inplane

    prop, data = _wind_data()
    with pytest.raises(DataError, match=WIND_FIRST.replace("(", r"\(")):  # (as before)
        sanity.sanity_check(data, prop)
    real = sanity._wind_axes

    def reworded(data, at_rpm, warnings_):
        n = len(warnings_)
        said = real(data, at_rpm, warnings_)
        if len(warnings_) > n:
            warnings_[-1] = "reworded: the loads look like a tunnel's"
        return said

    # (_drag_checks, which calls _wind_axes, is identify/sanity_inplane.py's since the split of sanity.py)
    monkeypatch.setattr(sanity_inplane, "_wind_axes", reworded)
    with pytest.raises(DataError) as info:
        sanity.sanity_check(data, prop)
    assert WIND_FIRST in str(info.value)  # (read by the warnings' text: not said)


def test_words_of_the_wind_warning_in_another_warning_do_not_name_wind_axes(monkeypatch):
    import propmap.identify.sanity as sanity
    import propmap.identify.sanity_inplane as sanity_inplane

    prop, data = _wind_data(scale=20.0, wind=False)
    with pytest.raises(DataError) as info:
        sanity.sanity_check(data, prop)
    plain = str(info.value)
    assert WIND_FIRST not in plain

    def quoting(data, at_rpm, warnings_):
        warnings_.append("a run named 'are the loads in wind axes?'")  # (not the wind-axes warning)
        return False

    # (_drag_checks, which calls _wind_axes, is identify/sanity_inplane.py's since the split of sanity.py)
    monkeypatch.setattr(sanity_inplane, "_wind_axes", quoting)
    with pytest.raises(DataError) as info:
        sanity.sanity_check(data, prop)
    assert str(info.value) == plain  # (read by the warnings' text: wind axes named first)


# ---- 5. map_columns drops the note of a column that gives way by the column, not by the note's text ------------


@pytest.mark.parametrize("names", [["rpm", "Thrust avg (kgf)", "Thrust (lbf)", "torque (N m)"],
                                   ["rpm", "Thrust (lbf)", "Thrust avg (kgf)", "torque (N m)"]])
def test_the_conversion_note_of_a_column_that_gives_way_is_dropped(names):
    """Guard (passes on the code before too: no column name was found that broke the old match of
    the note's text): the note of the column that gives way is dropped, the kept column's stays."""
    from propmap.identify.stand import map_columns

    cm = map_columns(names)
    assert cm.columns["thrust"][0] == "Thrust (lbf)"
    assert sorted(cm.notes) == ["'Thrust (lbf)' converted to N (x 4.44822)",
                                "column 'Thrust avg (kgf)' is not read: the thrust is read from 'Thrust (lbf)'"]
