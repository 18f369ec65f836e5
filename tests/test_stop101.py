"""Stop 101: defects found by an audit of the C export, the simulator export and the trims' API
edges (a helper's, each reproduced before the fix); every test fails on the code before it."""

import errno
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def map_file(small_map, tmp_path_factory):
    """small_map written as a file with its sidecar, and opened from it: (RotorMap, path)."""
    from propmap.maps import RotorMap, write_map

    path = tmp_path_factory.mktemp("m") / "m.nc"
    write_map(small_map[2], path)
    return RotorMap.open(path), path


@pytest.fixture(scope="module")
def cal():
    """apce_8x6's calibrated set (UIUC vol. 1, APC PE0 geometry)."""
    return pm.default_params("apce_8x6")


# ---- the C export ----------------------------------------------------------------------------------------------
def test_write_c_header_refuses_the_maps_own_file_its_link_and_its_sidecar(map_file, tmp_path):
    """write_c_header(rm, "m.nc") replaced the map it was opened from with the header text (through a link too);
    the CLI refused it, the API did not."""
    from propmap.export_c import write_c_header

    rm, path = map_file
    before = path.read_bytes()
    link = tmp_path / "l.h"
    link.symlink_to(path)
    for target in (path, link, Path(str(path) + ".json")):
        with pytest.raises(ValueError, match="the map's own file"):
            write_c_header(rm, target)
    assert path.read_bytes() == before
    assert write_c_header(rm, tmp_path / "ok.h").read_text().startswith("/* ok.h")


def test_write_c_header_and_write_export_refuse_an_empty_path(small_map):
    """An empty path met 'Device or resource busy' of a temporary file renamed onto '.' (write_c_header) and
    "PosixPath('.') has an empty name" (write_export)."""
    import warnings

    from propmap.export_c import write_c_header
    from propmap.maps import RotorMap
    from propmap.simexport import export_sim, write_export

    with pytest.raises(ValueError, match="path is empty"):
        write_c_header(RotorMap(small_map[2]), "")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = export_sim("rotorpy", small_map[0], small_map[1], n_points=40)
    with pytest.raises(ValueError, match="path is empty"):
        write_export(res, "")


def test_an_unwritable_folder_is_named_not_the_temporary_file(tmp_path, monkeypatch):
    """A read-only folder's error named the hidden temporary file ('.x.h.g97ddgx8.tmp'), not the file asked for."""
    from propmap.io.atomic import atomic_write

    def refuse(*args, **kwargs):
        raise OSError(errno.EROFS, "Read-only file system", str(tmp_path / ".x.h.abcdefgh.tmp"))

    monkeypatch.setattr(tempfile, "mkstemp", refuse)
    with pytest.raises(OSError) as info:
        with atomic_write(tmp_path / "x.h") as fh:
            fh.write("a")
    assert info.value.errno == errno.EROFS and info.value.filename == str(tmp_path / "x.h")


def test_c_prefix_refuses_what_cpp_reserves_and_makes_none_by_default():
    """The header is valid C++11 too (docs/simulators.md), where every identifier with a double underscore is
    reserved: 'a__b' and a prefix ending in '_' (x_ -> x__loads) were taken, and '.h' made 'pm__h'."""
    from propmap.export_c import c_prefix

    for name in ("a__b", "x_"):
        with pytest.raises(ValueError, match="double underscore"):
            c_prefix("m.h", name)
    assert c_prefix(".h") == "pm_h"
    assert c_prefix("a--b_.h") == "pm_a_b"
    assert c_prefix("__.h") == "pm"
    assert c_prefix("out/My-Map 2.h") == "pm_my_map_2"  # (unchanged)


def test_c_header_text_checks_the_vehicle_and_cites_the_propeller(small_map):
    """vehicle='quad' met an AttributeError; a map built in Python without citation= wrote 'Data: -' although its
    propeller_source holds the APC PE0 + UIUC citation; the radius and the table's units were unsaid."""
    from propmap.export_c import c_header_text
    from propmap.maps import RotorMap

    rm = RotorMap(small_map[2])
    with pytest.raises(TypeError, match="vehicle must be a propmap Vehicle"):
        c_header_text(rm, "x.h", vehicle="quad")
    text = c_header_text(rm, "x.h")
    assert "Data: geometry: APC Propellers PE0 geometry" in text and "Data: -" not in text
    assert "/* the rotor radius R [m] */" in text and "N m / (m/s)^2" in text


# ---- the simulator export ----------------------------------------------------------------------------------------
def test_export_sim_records_the_sets_label_and_the_propellers_citation(small_map):
    """Without params_label the file's head said '(cambered)' of calibrated:apce_8x6 and cited no data."""
    import warnings

    from propmap.simexport import export_sim, write_export

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = export_sim("rotorpy", small_map[0], small_map[1], n_points=40)
        with pytest.raises(TypeError, match="params_label must be a str"):
            export_sim("rotorpy", small_map[0], small_map[1], n_points=40, params_label=5)
    assert res.meta["params"] == "calibrated:apce_8x6"
    assert res.meta["citation"].startswith("geometry: APC Propellers PE0")
    with tempfile.TemporaryDirectory() as tmp:
        head = write_export(res, Path(tmp) / "r.py")[0].read_text().splitlines()[0]
    assert "(calibrated:apce_8x6)" in head and "data: geometry: APC" in head


def test_simexport_arguments_of_the_wrong_type_are_type_errors():
    """default_envelope(None) and write_export(None, ...) met AttributeErrors."""
    from propmap.simexport import default_envelope, write_export

    with pytest.raises(TypeError, match="propeller must be a Propeller"):
        default_envelope(None)
    with pytest.raises(TypeError, match="res must be a SimExport"):
        write_export(None, "x.py")


def test_predict_checks_its_inputs_as_rotor_loads_does():
    """A negative airspeed gave a negative drag (-0.1705 N), NaN gave NaN loads and the text '800' was 800 rad/s."""
    from propmap.simexport.forms import predict

    c = {"k_eta": 5e-6, "k_m": 8e-8, "k_d": 1e-5, "k_z": 1e-5, "k_h": 1e-3}
    T, D, _, _ = predict("rotorpy", c, 800.0, 5.0, 1.0)
    assert T > 0 and D > 0
    for args, name in (((800.0, -5.0, 1.0), "airspeed"), ((800.0, np.nan, 1.0), "airspeed"),
                       (("800", 5.0, 1.0), "omega"), ((800.0, 5.0, 4.0), "incidence")):
        with pytest.raises(ValueError, match=f"^{name} must"):
            predict("rotorpy", c, *args)


# ---- the trims ---------------------------------------------------------------------------------------------------
def test_trim_collective_names_its_branch_on_the_falling_side(apc8x6, cal):
    """A solution on the falling branch (falling=True) was described as 'the first upward crossing on the grid'."""
    from propmap.core.trim import BRANCH, FALLING_BRANCH, MIXED_BRANCH, trim_collective

    bounds = (math.radians(5), math.radians(30))
    r = trim_collective(apc8x6, cal, 1.6, 5000 * RPM, bounds=bounds)
    assert bool(r.falling) and r.branch == FALLING_BRANCH
    low = trim_collective(apc8x6, cal, 1.0, 5000 * RPM)
    assert not bool(low.falling) and low.branch == BRANCH
    both = trim_collective(apc8x6, cal, [1.6, 4.76], [5000 * RPM, 9000 * RPM], bounds=bounds)
    assert list(both.falling) == [True, False] and both.branch == MIXED_BRANCH


def test_trims_name_the_thrust_and_suspect_the_air_before_grams(apc8x6, cal):
    """A ragged thrust met NumPy's words alone; in air of 1e-6 kg/m^3 the thrust was asked whether it was in grams."""
    from propmap.core.trim import trim_collective, trim_omega

    with pytest.raises(ValueError, match="^thrust must be a number or a rectangular array"):
        trim_collective(apc8x6, cal, [[1.0, 2.0], [3.0]], 800.0)
    thin = pm.Air(rho=1e-6)
    for call in (lambda: trim_collective(apc8x6, cal, 2.0, 800.0, air=thin),
                 lambda: trim_omega(apc8x6, cal, 2.0, air=thin)):
        with pytest.raises(pm.TrimError, match="the air's density is 1e-06 kg/m\\^3") as info:
            call()
        assert "grams" not in str(info.value)
    with pytest.raises(pm.TrimError, match="grams"):  # (sea-level air: the grams are suspected still)
        trim_collective(apc8x6, cal, 300.0, 800.0)


def test_torque_change_names_the_operating_point_without_a_hover_reference(apc8x6, cal):
    """In a slow descent (800 rad/s, 1 m/s at 180 deg) the thrust, 4.07 N, is above hover's most at that rate: the
    TrimError named the hover trim's airspeed 0 and incidence 0, and one such point stopped a whole array."""
    V = np.array([0.0, 1.0, 3.0, 12.0])
    with pytest.raises(pm.TrimError, match=r"no hover reference .*airspeed=1 m/s, incidence=180 deg"):
        pm.torque_change_at_constant_thrust(apc8x6, cal, 800.0, V, math.pi)
    d, loads, hover = pm.torque_change_at_constant_thrust(apc8x6, cal, 800.0, V, math.pi, on_missing="nan")
    assert np.isnan(d[1]) and np.isnan(hover.collective[1]) and hover.n_solutions[1] == 0
    assert np.isnan(hover.loads.thrust[1]) and np.isfinite(loads.thrust[1])
    rest, _, _ = pm.torque_change_at_constant_thrust(apc8x6, cal, 800.0, V[[0, 2, 3]], math.pi)
    np.testing.assert_allclose(d[[0, 2, 3]], rest, rtol=0, atol=1e-12)
    assert d[0] == 0.0  # hover itself
    assert d[2] == pytest.approx(-2.0432e-4, rel=1e-3)  # regression value (2026-12-01), 3 m/s of descent
    with pytest.raises(ValueError, match="on_missing must be"):
        pm.torque_change_at_constant_thrust(apc8x6, cal, 800.0, 0.0, 0.0, on_missing="skip")


# ---- the scripts -------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("script", ["tools/make_example_flight.py", "tools/build_catalogue.py",
                                    "tools/flight_design_table.py", "benchmarks/bench_solver.py"])
def test_scripts_answer_help_without_running(script, tmp_path):
    """`--help` rewrote the package's example data (make_example_flight.py), was taken as the data folder
    (build_catalogue.py), as a table row (flight_design_table.py: KeyError) or started the full benchmark."""
    example = ROOT / "src/propmap/data/examples/level_flight_synthetic.csv"
    stamp = os.stat(example).st_mtime_ns
    res = subprocess.run([sys.executable, str(ROOT / script), "--help"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=120)
    assert res.returncode == 0 and res.stdout.startswith("usage: "), res.stderr[-500:]
    assert os.stat(example).st_mtime_ns == stamp and not any(tmp_path.iterdir())
