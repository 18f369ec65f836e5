"""Property-based tests of every file reader (hypothesis).

For each reader, files are generated (random bytes; random text under a plausible header;
valid files with random mutations: deleted, duplicated, swapped or inserted lines,
garbled cells, NaN / inf / huge / non-ASCII numbers, wrong TOML types, BOMs, CRLF or CR
line ends, truncation, stray bytes) and the property is:

    the reader returns a valid result (every number in it finite) or raises its documented
    error class with a one-line message that names the file; nothing else (no
    UnicodeDecodeError, OverflowError, TypeError, IndexError, RuntimeWarning...), and the
    file is left unchanged.

Derandomized (a fixed sequence of examples, no example database) so that CI is
reproducible; 14-21 s on a 2-core machine (300 examples per reader).
"""

import dataclasses
import math
import warnings
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import propmap as pm
from propmap.identify import (DataError, VehicleFileError, loads_from_uiuc_files, read_level_flight, read_loads,
                              read_vehicle)
from propmap.io import ParamsFileError, read_params, write_params
from propmap.io.readers import (GeometryFileError, MeasurementFileError, looks_like_uiuc, read_apc_pe0, read_geometry,
                                read_uiuc_geometry, read_uiuc_static, read_uiuc_sweep)

DATA = Path(str(resources.files("propmap") / "data"))
UIUC = DATA / "uiuc_v1"

FUZZ = settings(derandomize=True, database=None, deadline=None, max_examples=300, print_blob=True,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.function_scoped_fixture])


# --- base files ----------------------------------------------------------------------------------

def _text(path: Path) -> str:
    return path.read_text(encoding="latin-1")


GEOM = _text(UIUC / "apce_9x6_geom.txt")
STATIC = _text(UIUC / "apce_10x5_static_pg0819.txt")
SWEEP = _text(UIUC / "apce_10x5_kt0821_5000.txt")
PE0 = _text(DATA / "apc_pe0" / "8x6-PERF.PE0")
QUAD = _text(DATA / "examples" / "quadrotor.toml")
FLIGHT = "".join(_text(DATA / "examples" / "level_flight_synthetic.csv").splitlines(keepends=True)[:10])
LOADS = "rpm,airspeed,incidence_deg,thrust,drag,torque,group\n" + "".join(
    f"{4000 + 250 * k},{k % 5},{15 * k % 181},{1 + 0.1 * k},{0.05 * k},{0.01 + 0.002 * k},run{k % 3}\n"
    for k in range(10))


def _params_text(params) -> str:
    import io

    import tomli_w

    from propmap.io.params_file import params_to_dict

    buf = io.BytesIO()
    tomli_w.dump(params_to_dict(params), buf)
    return buf.getvalue().decode()


PARAMS_GILL = _params_text(pm.preset("gill2017-apc"))
PARAMS_CAMBERED = _params_text(pm.CamberedParams())


# --- strategies ----------------------------------------------------------------------------------

NASTY_NUMBERS = ["", " ", "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e300", "-1e300", "1e400", "-1e400",
                 "1e-400", "0", "-0", "0.0", "1" + "0" * 400, "9" * 5000, "1_000", "\uff11\uff12", "\u0664", "\u00b2",
                 "0x10", "+", "-", ".", "e5", "1e", "1.2.3", "None", "true", "NULL", '"', '""', '"1"', "a,b", "\t",
                 "\x00", "\ufeff", "\u2028", "\x85", "1\r2", "#", "=", ":", "[", "{", "1,", "-1", "1e5", "1e9", "360",
                 "-90", "95", "954930", "1e-300", "x" * 300, "5" * 131072]
NASTY_TOML = ['"5.3"', "true", "false", "[1, 2]", "[true, false, true]", "{a = 1}", "1e400", "-1e400", "nan", "inf",
              "-inf", "1" + "0" * 400, "-" + "9" * 400, "1979-05-27", "07:32:00", "1e300", "-1", "0", "'cw'", '""',
              "[]", "[[1]]", "[1e300, 0, 1]", "[0, 0, 0]", "[nan, 0, 1]", '"apce_8x6"', '"."', '"/dev/zero"',
              '"nope_1x1"', '"x" ', "[", "=", '"\\u0000"', "0.5", "2", "20.6", "1e-300"]
WORDS = ["rpm", "airspeed", "incidence_deg", "thrust", "drag", "torque", "group", "pitch_deg", "roll_deg", "rpm_1",
         "rpm_2", "rpm_3", "rpm_4", "rpm_5", "p", "q", "r", "rpm_\u00b2", "RPM", "CT", "CP", "J", "eta", "r/R", "c/R",
         "beta", "STATION", "TWIST", "RADIUS:", "BLADES:", "RPM average = 5000", "mass", "=", "n" * 300,
         "RPM average = 4.0.0", "RPM average = 1e999", "Date: 1.2.3", "x = e", "RADIUS: 4.0.0", "RADIUS: 1e400",
         "BLADES: " + "9" * 5000, "BLADES: 0"]

floats = st.floats(allow_nan=True, allow_infinity=True, width=64)
cells = st.one_of(st.sampled_from(NASTY_NUMBERS), floats.map(repr), st.integers(-10**30, 10**30).map(str),
                  st.text(max_size=12))


@st.composite
def mutated(draw, base: str, sep: str | None, values=cells, *, toml: bool = False):
    """``base`` with a few random line and cell mutations, line ends, BOM and encoding.

    ``toml``: a cell mutation replaces the value after the ``=`` (the key stays) and line
    ends are LF or CRLF (TOML has no bare CR), so that most files parse and reach the
    readers' own checks.
    """
    lines = base.splitlines()
    for _ in range(draw(st.integers(0, 4))):
        op = draw(st.sampled_from(["cell", "cell", "cell", "delete", "duplicate", "swap", "insert", "truncate"]))
        if not lines:
            lines = [""]
        i = draw(st.sampled_from(range(len(lines))))  # uniform (integers favour 0: the header)
        if op == "cell":
            parts = lines[i].split(sep) if sep else lines[i].split()
            j = len(parts) - 1 if toml else draw(st.sampled_from(range(max(len(parts), 1))))
            value = draw(values)
            if parts:
                parts[j] = value
            else:
                parts = [value]
            lines[i] = (sep or " ").join(parts)
        elif op == "delete":
            del lines[i]
        elif op == "duplicate":
            lines.insert(i, lines[i])
        elif op == "swap":
            k = draw(st.sampled_from(range(len(lines))))
            lines[i], lines[k] = lines[k], lines[i]
        elif op == "insert":
            lines.insert(i, draw(st.one_of(st.text(max_size=40), st.sampled_from(WORDS), values)))
        else:
            lines = lines[: i + 1]
    eol = draw(st.sampled_from(["\n", "\r\n"] if toml else ["\n", "\n", "\r\n", "\r"]))
    text = eol.join(lines) + draw(st.sampled_from(["", eol, eol * 3, " ", "\x1a"]))
    encoding = draw(st.sampled_from(["utf-8"] * 6 + ["utf-8-sig", "utf-8-sig", "latin-1", "utf-16"]))
    raw = text.encode(encoding, errors="replace")
    if draw(st.integers(0, 9)) == 0:  # stray bytes
        at = draw(st.integers(0, len(raw)))
        raw = raw[:at] + draw(st.binary(min_size=1, max_size=8)) + raw[at:]
    return raw


def plausible_table(header_words, sep: str):
    """A random header from ``header_words`` over random rows of random cells."""
    header = st.lists(st.sampled_from(header_words), min_size=1, max_size=8)
    rows = st.lists(st.lists(cells, min_size=0, max_size=9), max_size=12)
    return st.builds(lambda h, rs: (sep.join(h) + "\n" + "".join(sep.join(r) + "\n" for r in rs)).encode(), header,
                     rows)


def files(base: str, sep: str | None, header_words, values=cells):
    """Random bytes, a plausible random table, or a mutated valid file."""
    return _weighted([(1, st.binary(max_size=2000)), (1, plausible_table(header_words, sep or " ")),
                      (6, mutated(base, sep, values))])


def _weighted(choices):
    """One of the strategies, drawn with the given weights (st.one_of weighs distinct strategies equally)."""
    pool = [k for k, (w, _) in enumerate(choices) for _ in range(w)]
    return st.sampled_from(pool).flatmap(lambda k: choices[k][1])


# --- the property ----------------------------------------------------------------------------------

def assert_finite(obj, where="result"):
    """Every number reachable from ``obj`` is finite."""
    if isinstance(obj, pm.Propeller):
        for name in ("radius", "r", "chord", "theta"):
            assert_finite(getattr(obj, name), f"{where}.{name}")
        if obj.pitch is not None:
            assert_finite(obj.pitch, f"{where}.pitch")
        y = np.linspace(obj.r_hub, obj.radius, 7)
        assert_finite(obj.chord_at(y), f"{where}.chord_at")
        assert_finite(obj.theta_at(y), f"{where}.theta_at")
        assert 0 < obj.radius and obj.n_blades >= 1
    elif dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            assert_finite(getattr(obj, f.name), f"{where}.{f.name}")
    elif isinstance(obj, np.ndarray):
        if obj.dtype.kind in "iuf":
            assert np.all(np.isfinite(obj)), f"{where} has a non-finite value"
    elif isinstance(obj, dict):
        for k, v in obj.items():
            assert_finite(v, f"{where}[{k!r}]")
    elif isinstance(obj, (list, tuple)):
        for k, v in enumerate(obj):
            assert_finite(v, f"{where}[{k}]")
    elif isinstance(obj, float):
        assert math.isfinite(obj), f"{where} = {obj!r}"


def check(reader, path: Path, raw: bytes, error, *args, **kw):
    """Write ``raw`` to ``path``, read it: a finite result or ``error`` naming the file."""
    path.write_bytes(raw)
    before = path.stat().st_mtime_ns
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = reader(path, *args, **kw)
        except error as exc:
            msg = str(exc)
            assert msg and "\n" not in msg and "\r" not in msg and len(msg) < 1000, msg
            assert str(path) in msg, f"the message does not name the file: {msg}"
            result = None
    for w in caught:  # numpy overflow (RuntimeWarning) would mean an unchecked value
        assert issubclass(w.category, UserWarning), w
    assert path.read_bytes() == raw and path.stat().st_mtime_ns == before, "the input file was modified"
    if result is not None:
        assert_finite(result)
    return result


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("fuzz")


@pytest.fixture(scope="module")
def quad():
    return read_vehicle(DATA / "examples" / "quadrotor.toml")


# --- one test per reader ------------------------------------------------------------------------------

@FUZZ
@given(raw=files(GEOM, None, WORDS), name=st.sampled_from(["apce_9x6_geom.txt", "ef_130x70_geom.txt",
                                                          "kpf_1000x2_geom.txt", "x_0.1x1_geom.txt", "geom.txt",
                                                          "foo_" + "9" * 100 + "x6_geom.txt"]))
def test_fuzz_read_uiuc_geometry(folder, raw, name):
    prop = check(read_uiuc_geometry, folder / name, raw, GeometryFileError)
    if prop is not None:
        assert 0.5 * 0.0254 <= prop.diameter <= 100 * 0.0254 and np.all(np.diff(prop.r) > 0)


#: the PE0 summary lines, with a random value
pe0_summary = st.tuples(st.sampled_from(["RADIUS:  4.00", "BLADES:  2"]), cells).map(
    lambda kv: PE0.replace(kv[0], kv[0].split()[0] + "  " + kv[1], 1).encode("utf-8", errors="replace"))


@FUZZ
@given(raw=st.one_of(files(PE0, None, WORDS), pe0_summary))
def test_fuzz_read_apc_pe0(folder, raw):
    prop = check(read_apc_pe0, folder / "8x6-PERF.PE0", raw, GeometryFileError)
    if prop is not None:
        assert 0.25 * 0.0254 <= prop.radius <= 50 * 0.0254 and 1 <= prop.n_blades <= 100


@FUZZ
@given(raw=st.one_of(files(GEOM, None, WORDS), files(PE0, None, WORDS)),
       diameter_in=st.one_of(st.none(), st.floats(0.1, 200)), n_blades=st.one_of(st.none(), st.integers(1, 6)))
def test_fuzz_read_geometry(folder, raw, diameter_in, n_blades):
    check(read_geometry, folder / "any_9x6_geom.txt", raw, GeometryFileError, diameter_in=diameter_in,
          n_blades=n_blades)


@FUZZ
@given(raw=files(STATIC, None, WORDS))
def test_fuzz_read_uiuc_static(folder, raw):
    run = check(read_uiuc_static, folder / "apce_10x5_static_pg0819.txt", raw, MeasurementFileError)
    if run is not None:
        assert np.all((run.rpm > 0) & (run.rpm <= 954929))


@FUZZ
@given(raw=files(SWEEP, None, WORDS), name=st.sampled_from(["apce_10x5_kt0821_5000.txt", "s_9x6_r1_5e500.txt",
                                                           "s_9x6_r1_nan.txt", "sweep.txt", "s_9x6_r1_-5.txt"]))
def test_fuzz_read_uiuc_sweep(folder, raw, name):
    sweep = check(read_uiuc_sweep, folder / name, raw, MeasurementFileError)
    if sweep is not None:
        assert 0 < sweep.rpm <= 954929


@FUZZ
@given(raw=st.one_of(st.binary(max_size=3000), files(STATIC, None, WORDS), files(SWEEP, None, WORDS)))
def test_fuzz_looks_like_uiuc(folder, raw):
    p = folder / "maybe.txt"
    p.write_bytes(raw)
    assert looks_like_uiuc(p) in (True, False)
    assert p.read_bytes() == raw


@FUZZ
@given(raws=st.lists(st.one_of(files(STATIC, None, WORDS), files(SWEEP, None, WORDS)), min_size=1, max_size=2),
       diameter=st.sampled_from([0.254, 0.05, 2.0]))
def test_fuzz_loads_from_uiuc_files(folder, raws, diameter):
    names = ["apce_10x5_static_pg0819.txt", "apce_10x5_kt0821_5000.txt"]
    paths = [folder / n for n in names[: len(raws)]]
    for p, raw in zip(paths, raws):
        p.write_bytes(raw)
    try:
        loads = loads_from_uiuc_files(paths, diameter)
    except DataError as exc:
        msg = str(exc)
        assert "\n" not in msg and any(str(p) in msg or p.name in msg for p in paths), msg
    else:
        assert_finite(loads)
        assert np.all(np.abs(loads.measured["thrust"]) <= 1e5) and np.all(loads.airspeed <= 500)
    assert [p.read_bytes() for p in paths] == raws


@FUZZ
@given(raw=files(LOADS, ",", WORDS))
def test_fuzz_read_loads(folder, raw):
    data = check(read_loads, folder / "loads.csv", raw, DataError)
    if data is not None:
        assert data.n >= 6 and np.all(data.omega > 0) and np.all(data.omega <= 1e5 + 1e-6)
        assert all(np.all(np.abs(v) <= 1e5) for v in data.measured.values())


@FUZZ
@given(raw=files(FLIGHT, ",", WORDS))
def test_fuzz_read_level_flight(folder, quad, raw):
    data = check(read_level_flight, folder / "flight.csv", raw, DataError, quad)
    if data is not None:
        assert data.omega.shape == (data.n, 4) and np.all(np.abs(data.pitch) < math.pi / 2)


TOML_VALUES = st.one_of(st.sampled_from(NASTY_TOML), floats.map(repr),
                        st.text(max_size=10).map(lambda s: '"' + s.replace("\\", "").replace('"', "") + '"'))


def toml_files(base: str):
    """TOML with random key = value lines: values of every type, duplicated or deleted lines."""
    base = "\n".join(ln.split("#")[0].rstrip() for ln in base.splitlines() if ln.split("#")[0].strip())
    value = TOML_VALUES.map(lambda v: " " + v)
    return _weighted([(1, st.binary(max_size=1000)), (6, mutated(base, "=", value, toml=True)),
                      (1, mutated(base, None, st.sampled_from(NASTY_NUMBERS + NASTY_TOML)))])


@FUZZ
@given(raw=st.one_of(toml_files(PARAMS_GILL), toml_files(PARAMS_CAMBERED)))
def test_fuzz_read_params(folder, raw):
    result = check(read_params, folder / "params.toml", raw, ParamsFileError)
    if result is not None:
        air = result.air
        assert all(math.isfinite(v) for v in (air.rho, air.mu, air.speed_of_sound))


@FUZZ
@given(raw=toml_files(QUAD))
def test_fuzz_read_vehicle(folder, raw):
    veh = check(read_vehicle, folder / "vehicle.toml", raw, VehicleFileError)
    if veh is not None:
        assert 0 < veh.mass <= 1e4 and veh.rotors
        for r in veh.rotors:
            assert np.linalg.norm(r.axis) == pytest.approx(1.0)


def test_the_generators_reach_valid_files(folder, quad):
    """The base files are valid, so the properties above also see successful reads."""
    for name, text, reader, args in [("apce_9x6_geom.txt", GEOM, read_uiuc_geometry, ()),
                                     ("8x6-PERF.PE0", PE0, read_apc_pe0, ()),
                                     ("apce_10x5_static_pg0819.txt", STATIC, read_uiuc_static, ()),
                                     ("apce_10x5_kt0821_5000.txt", SWEEP, read_uiuc_sweep, ()),
                                     ("loads.csv", LOADS, read_loads, ()),
                                     ("flight.csv", FLIGHT, read_level_flight, (quad,)),
                                     ("params.toml", PARAMS_GILL, read_params, ()),
                                     ("cambered.toml", PARAMS_CAMBERED, read_params, ()),
                                     ("vehicle.toml", QUAD, read_vehicle, ())]:
        assert check(reader, folder / name, text.encode(), ValueError, *args) is not None, name
    p = folder / "p.toml"
    write_params(p, pm.preset("gill2017-apc"))
    assert read_params(p) == pm.preset("gill2017-apc")
