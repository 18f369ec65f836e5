"""The map file's documented rules (a third mutation audit, 2026-11-27: read_dataset's check of
a single map's propeller name, map_props' duplicate names and the MAX_NODES limit each survived
the suite; the other tests here pin the sidecar, CSV and JSON forms). apce_8x6 from the UIUC
Propeller Data Site vol. 1, as bundled."""

import csv
import json
import math

import numpy as np
import pytest

import propmap as pm
from propmap.io.mapfile import map_metadata, read_dataset, read_sidecar, write_map, write_sidecar
from propmap.maps import FLAGS, build_map

RPM = math.pi / 30


@pytest.fixture(scope="module")
def tiny():
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    return build_map(prop, params, np.linspace(3000, 9000, 4) * RPM, np.linspace(0, 10, 3),
                     np.radians(np.linspace(0, 180, 5)), air=params.air, params_label=params.label, n_check=20)


def test_sidecar_axes_span_first_to_last_grid_value(tiny):
    """Documented rule (map_metadata): ``axes`` holds each axis' first and last value."""
    meta = map_metadata(tiny)
    for d in ("rpm", "airspeed", "incidence_deg"):
        assert meta["axes"][d] == [float(tiny[d].values[0]), float(tiny[d].values[-1])]
    assert meta["axes"]["rpm"][1] == pytest.approx(9000.0)


def test_read_sidecar_refuses_a_map_rewritten_without_it(tiny, tmp_path):
    """Documented rule (read_sidecar): a sidecar whose SHA-256 differs from the map's is refused."""
    path = tmp_path / "m.nc"
    write_map(tiny, path)
    assert read_sidecar(path)["describes"]["file"] == "m.nc"
    write_map(tiny.assign_attrs(note="changed"), path, sidecar=False)
    with pytest.raises(ValueError, match="SHA-256 differs"):
        read_sidecar(path)


def test_csv_form_keeps_flags_and_ten_significant_digits(tiny, tmp_path):
    """Invariant (write_map docstring): the CSV holds every node's values to 10 significant digits
    and flags as true/false."""
    path = tmp_path / "m.csv"
    write_map(tiny, path, "csv", sidecar=False)
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    table = tiny.drop_vars(["omega", "incidence"]).to_dataframe().reset_index()
    assert len(rows) == len(table)
    np.testing.assert_allclose([float(r["thrust"]) for r in rows], table["thrust"].to_numpy(), rtol=1e-9, atol=0)
    for f in FLAGS:
        assert [r[f] for r in rows] == ["true" if b else "false" for b in table[f].to_numpy(bool)]


def test_read_dataset_refuses_another_propellers_name_for_a_map_of_one(tiny, tmp_path):
    """Documented rule (read_dataset): prop= naming another propeller than a single map's is refused."""
    path = tmp_path / "m.nc"
    write_map(tiny, path, sidecar=False)
    assert read_dataset(path, tiny.attrs["propeller"]).sizes == tiny.sizes
    with pytest.raises(ValueError, match="not of 'other_prop'"):
        read_dataset(path, "other_prop")


def test_non_finite_metadata_is_written_as_json_null(tiny, tmp_path):
    """Documented rule (write_sidecar): a value that is not finite is written as null (strict JSON)."""
    p = write_sidecar(tiny.assign_attrs(max_err_test=float("nan")), tmp_path / "s.json")
    assert json.loads(p.read_text(encoding="utf-8"))["max_err_test"] is None


def test_a_file_declaring_just_over_max_nodes_is_refused_before_reading(tmp_path):
    """Documented rule (read_dataset): a map variable declaring more than MAX_NODES (20,000,000) nodes is refused."""
    import netCDF4

    from propmap.io.mapfile import MAX_NODES

    path = tmp_path / "big.nc"
    sizes = {"rpm": 5001, "airspeed": 4000, "incidence_deg": 1}
    assert MAX_NODES < math.prod(sizes.values()) < 2 * MAX_NODES
    with netCDF4.Dataset(path, "w") as nc:
        for d, n in sizes.items():
            nc.createDimension(d, n)
        nc.createVariable("thrust", "f4", tuple(sizes), chunksizes=(100, 100, 1), zlib=True)
    with pytest.raises(ValueError, match=r"is not a map's"):
        read_dataset(path)


def test_map_props_refuses_a_prop_coordinate_naming_a_propeller_twice(tmp_path):
    """Documented rule (map_props): a prop coordinate that holds a name twice is refused."""
    import netCDF4

    from propmap.io.mapfile import map_props

    good, dup = tmp_path / "good.nc", tmp_path / "dup.nc"
    for path, names in ((good, ["a", "b"]), (dup, ["a", "a"])):
        with netCDF4.Dataset(path, "w") as nc:
            nc.createDimension("prop", 2)
            nc.createDimension("nchar", 1)
            v = nc.createVariable("prop", "S1", ("prop", "nchar"))
            v._Encoding = "utf-8"
            v[:] = np.array(names, dtype="S1")
    assert map_props(good) == ("a", "b")
    with pytest.raises(ValueError, match="distinct propeller names"):
        map_props(dup)
