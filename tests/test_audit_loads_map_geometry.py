"""A mutation audit of identify/loads_csv.py, io/mapfile.py and core/geometry.py (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""

import math
import warnings

import numpy as np
import pytest

from propmap.identify import DataError, read_loads

RPM = [3000.0, 4000.0, 5000.0, 6000.0, 7000.0, 8000.0]


def _csv(tmp_path, header, rows, name="loads.csv"):
    p = tmp_path / name
    p.write_text(header + "\n" + "\n".join(",".join(x if isinstance(x, str) else f"{x:g}" for x in r) for r in rows)
                 + "\n", encoding="utf-8")
    return p


def _read(path, **kw):
    """(data, the warnings' texts) of read_loads(path)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        data = read_loads(path, **kw)
    return data, [str(w.message) for w in caught]


# --- identify/loads_csv.py ---------------------------------------------------------------------------------------

def test_five_distinct_points_written_in_seven_rows_are_too_few_for_a_fit(tmp_path):
    """The minimum (6) is of distinct operating points: 7 rows at 5 points are refused, 6 at 6 read."""
    rows = [(r, 1e-7 * r**2) for r in RPM[:5]] + [(RPM[0], 1.01e-7 * RPM[0] ** 2), (RPM[1], 1.01e-7 * RPM[1] ** 2)]
    with pytest.raises(DataError, match=r"has 7 points at 5 distinct operating points; a fit needs at least 6"):
        read_loads(_csv(tmp_path, "rpm,thrust", rows))
    assert read_loads(_csv(tmp_path, "rpm,thrust", [(r, 1e-7 * r**2) for r in RPM])).n == 6


def test_a_small_advance_ratio_column_without_airspeed_is_refused(tmp_path):
    """A bare J of values other than 0 where no airspeed is read is refused (J up to 0.05: a slow sweep), a J of
    zeros is read as static."""
    rows = [(r, 1e-7 * r**2, j) for r, j in zip(RPM, (0.0, 0.01, 0.02, 0.03, 0.04, 0.05))]
    with pytest.raises(DataError, match=r"column 'J' looks like an advance ratio"):
        read_loads(_csv(tmp_path, "rpm,thrust,J", rows))
    d = read_loads(_csv(tmp_path, "rpm,thrust,J", [(r, t, 0.0) for r, t, _ in rows]))
    assert np.all(d.airspeed == 0.0)


def test_a_propeller_column_naming_one_propeller_in_two_cases_is_one_propeller(tmp_path):
    """A propeller column is refused where it names several propellers; 'APC 10x7' and 'apc 10x7' are one, noted."""
    rows = [(r, 1e-7 * r**2, "APC 10x7" if i % 2 else "apc 10x7") for i, r in enumerate(RPM)]
    d = read_loads(_csv(tmp_path, "rpm,thrust,propeller", rows))
    assert d.n == 6 and any("'propeller' names" in n and "10x7 on every row" in n for n in d.notes), d.notes
    rows[0] = (RPM[0], 1e-7 * RPM[0] ** 2, "APC 10x8")
    with pytest.raises(DataError, match=r"column 'propeller' names 2 propellers \(APC 10x7, APC 10x8\)"):
        read_loads(_csv(tmp_path, "rpm,thrust,propeller", rows))


def test_a_torque_negative_at_points_of_exactly_the_static_airspeed_is_a_reaction_at_the_static_points(tmp_path):
    """Points at airspeed *at most* STATIC_AIRSPEED (0.3 m/s) are static for the torque's sign rule too: a torque
    negative there is negated as the stand's reaction torque, the note naming the static points."""
    rows = [(r, v, 1e-7 * r**2, -1e-9 * r**2) for r, v in zip(RPM, (0.3, 0.3, 0.3, 5.0, 10.0, 15.0))]
    d = read_loads(_csv(tmp_path, "rpm,airspeed,thrust,torque", rows))
    np.testing.assert_allclose(d.measured["torque"], [1e-9 * r**2 for r in RPM])
    assert any(n.startswith("torque negated: it is the stand's reaction torque (negative at the static points)")
               for n in d.notes), d.notes



def test_a_reaction_torque_without_a_static_point_needs_the_thrust_pulling_at_every_nearest_point(tmp_path):
    """Without a static point the torque is negated only where it is negative at every point nearest to static and
    the thrust positive at all of them: here one of the two (the same advance, 4 m/s at 4000 rpm and 5 m/s at 5000)
    pushes, so the torque is read as written, and negative where the thrust is positive in climb it is refused."""
    rows = [(3000, 6, 1), (4000, 4, 1), (5000, 5, -1), (6000, 12, 1), (7000, 14, 1), (8000, 16, 1)]
    rows = [(r, v, s * 1e-7 * r**2, -1e-9 * r**2) for r, v, s in rows]
    with pytest.raises(DataError, match=r"column 'torque' is negative at 6 points, 5 of them with positive thrust in "
                                        r"climb or edgewise flow"):
        read_loads(_csv(tmp_path, "rpm,airspeed,thrust,torque", rows))


def test_a_negative_torque_where_the_thrust_pulls_edgewise_is_refused(tmp_path):
    """Edgewise flow (incidence 90 deg, V cos(incidence) = 0) counts with climb: a negative torque where the thrust is
    positive there is refused, not read as windmilling."""
    rows = [(3000, 0, 0, 1), (4000, 0, 0, 1), (5000, 0, 0, 1), (6000, 10, 90, 1), (7000, 10, 90, 1), (8000, 20, 90, -1)]
    rows = [(r, v, a, 1e-7 * r**2, s * 1e-9 * r**2) for r, v, a, s in rows]
    with pytest.raises(DataError, match=r"negative at 1 points, 1 of them with positive thrust in climb or edgewise"):
        read_loads(_csv(tmp_path, "rpm,airspeed,incidence_deg,thrust,torque", rows))


def test_a_negative_speed_within_one_percent_of_the_largest_is_a_stopped_motor(tmp_path):
    """A negative rotation speed within 1% of the column's largest magnitude (-40 rpm beside 8000) is a stopped
    motor's noise: the row is skipped as stopped, not refused as a speed of the other sign."""
    rows = [(r, 1e-7 * r**2) for r in RPM] + [(-40.0, 0.0)]
    d = read_loads(_csv(tmp_path, "rpm,thrust", rows))
    assert d.n == 6 and any(n.startswith("1 rows with rpm 0 (or empty or NaN) skipped") for n in d.notes), d.notes


SPEEDS = "Motor Optical Speed (RPM),Motor Electrical Speed (RPM),Thrust (N)"


def test_an_optical_dropout_is_not_filled_from_an_electrical_speed_10_percent_off(tmp_path):
    """The optical probe's dropouts take the electrical speed only where the two agree within 3% elsewhere (median
    ratio): at 1.1 the row stays a stopped motor's, skipped, with a note."""
    rows = [(r, 1.1 * r, 1e-7 * r**2) for r in RPM] + [(0.0, 5500.0, 1e-7 * 5000.0**2)]
    d = read_loads(_csv(tmp_path, SPEEDS, rows))
    assert d.n == 6
    assert any("not filled from it, which reads 1.1 times the optical speed" in n for n in d.notes), d.notes


def test_an_optical_dropout_at_a_fifth_of_the_typical_speed_is_filled(tmp_path):
    """A dropout is a row whose electrical speed runs above 5% of its median: 1000 rpm beside a median of 6000 is
    running, and takes the electrical speed."""
    rows = [(r, r, 1e-7 * r**2) for r in RPM] + [(0.0, 1000.0, 1e-7 * 1000.0**2)]
    d = read_loads(_csv(tmp_path, SPEEDS, rows))
    assert d.n == 7 and d.omega.min() == pytest.approx(1000.0 * math.pi / 30)
    assert any("reads 0 or nothing in 1 rows where the electrical speed runs (a probe dropout)" in n for n in d.notes)


def test_a_speed_of_0_with_a_fifth_of_the_largest_thrust_is_a_missing_reading(tmp_path):
    """A row of rpm 0 whose thrust is above 5% of the largest is a speed reading missing while the motor ran."""
    rows = [(r, 1e-7 * r**2) for r in RPM] + [(0.0, 0.2 * 1e-7 * 8000.0**2)]
    d = read_loads(_csv(tmp_path, "rpm,thrust", rows))
    assert any("1 of them with a thrust above 5% of the largest: a speed reading missing" in n for n in d.notes)


def test_a_load_at_rest_above_twice_its_scatter_is_a_zero_offset(tmp_path):
    """The stopped rows' thrust 0.04-0.06 N (median 0.05, scatter 0.008) is a stand's zero offset: noted."""
    rows = [(0.0, 0.04), (0.0, 0.05), (0.0, 0.06)] + [(r, 1e-7 * r**2) for r in RPM]
    d = read_loads(_csv(tmp_path, "rpm,thrust", rows))
    assert any("their thrust reads 0.05 N in the median" in n and "tare it first" in n for n in d.notes), d.notes


def test_a_sampled_log_whose_only_load_is_empty_in_every_running_row_is_refused(tmp_path):
    rows = [(0.1 * k, r, "") for k, r in enumerate(RPM)]
    with pytest.raises(DataError, match=r"'Thrust \(N\)' empty \(or NaN\) in every running row: no loads to read"):
        read_loads(_csv(tmp_path, "Time (s),rpm,Thrust (N)", rows))


def test_a_time_column_makes_a_log_whose_empty_load_cell_is_a_dropout(tmp_path):
    """A file with a time column is a sampled log: a running row with an empty load cell is skipped with a note."""
    rows = [(0.1 * k, r, f"{1e-7 * r**2:g}") for k, r in enumerate(RPM)] + [(0.7, 5500.0, "")]
    d = read_loads(_csv(tmp_path, "Time (s),rpm,Thrust (N)", rows))
    assert d.n == 6 and any("1 of 7 running rows skipped: 'Thrust (N)' empty or NaN there" in n for n in d.notes)


def test_a_pitot_reading_0_3_to_1_5_m_s_at_every_point_is_warned_of(tmp_path):
    """Warned: an airspeed column reading 0.3-1.5 m/s at every point; not where some points are static."""
    rows = [(r, v, 1e-7 * r**2) for r, v in zip(RPM, (1.1, 1.2, 1.3, 1.2, 1.1, 1.2))]
    _, said = _read(_csv(tmp_path, "rpm,airspeed,thrust", rows))
    assert any("'airspeed' reads 1.1-1.3 m/s at every point: a static stand's pitot" in w for w in said), said
    rows = [(r, v, 1e-7 * r**2) for r, v in zip(RPM, (0.0, 0.0, 0.0, 0.5, 1.0, 1.2))]
    _, said = _read(_csv(tmp_path, "rpm,airspeed,thrust", rows))
    assert not any("pitot" in w for w in said), said


def test_one_row_written_twice_is_warned_of(tmp_path):
    rows = [(r, 1e-7 * r**2) for r in RPM]
    _, said = _read(_csv(tmp_path, "rpm,thrust", rows + rows[:1]))
    assert any("1 row(s) repeat another row to every digit" in w for w in said), said


def test_an_esc_signal_within_one_tolerance_while_the_speed_runs_is_refused(tmp_path):
    """A steps log whose ESC signal spans 3 us (within 2 tolerances of 2 us) while the speed runs 3000-4800 rpm (more
    than 10%) is refused, naming the signal."""
    rows = [(1500 + k % 4, 3000 + 300 * k, 1e-7 * (3000 + 300 * k) ** 2) for k in range(7)]
    with pytest.raises(DataError, match=r"the ESC signal 'ESC signal \(µs\)' stays within 3 us over the whole log"):
        read_loads(_csv(tmp_path, "ESC signal (µs),rpm,thrust", rows))

# --- core/geometry.py --------------------------------------------------------------------------------------------

def _blade(r=(0.02, 0.05, 0.1), chord=(0.02, 0.02, 0.02), theta_deg=(20.0, 15.0, 10.0), **kw):
    from propmap.core.geometry import Propeller

    kw.setdefault("radius", 0.1)
    kw.setdefault("n_blades", 2)
    return Propeller("audit", r=np.asarray(r, float), chord=np.asarray(chord, float),
                     theta=np.radians(np.asarray(theta_deg, float)), **kw)


@pytest.mark.parametrize("kw, match", [
    (dict(radius=0.0), r"radius must be finite and > 0 m, got 0\.0"),
    (dict(n_blades=0), r"n_blades must be an integer >= 1, got 0"),
    (dict(chord=(0.02, float("nan"), 0.02)), r"chord must be finite at every blade station"),
    (dict(theta_deg=(20.0, 15.0)), r"r, chord and theta must have equal lengths, got 3, 3, 2"),
    (dict(r=(0.02, 0.05, 0.05)), r"r must be strictly increasing; station 2 \(0\.05 m\) does not exceed station 1"),
    (dict(r=(0.0, 0.05, 0.1)), r"r must lie in \(0, radius=0\.1\] m, got \[0, 0\.1\]"),
    (dict(r=(0.02, 0.05, 0.1005)), r"r must lie in \(0, radius=0\.1\] m, got \[0\.02, 0\.1005\]"),
    (dict(chord=(0.02, -1e-4, 0.02)), r"chord must be >= 0 m at every station"),
    (dict(theta_deg=(91.0, 15.0, 10.0)), r"theta must be in \[-90, 90\] deg at every station"),
    (dict(r=(0.01, 0.02, 0.03), chord=(0.01, 0.025, 0.04)), r"extrapolates to a chord of 1\.45 R"),
    (dict(r=(0.01, 0.02, 0.03), theta_deg=(10.0, 50.0, 85.0)), r"and a blade angle of 162\.2 deg"),
])
def test_propeller_refusals_name_the_argument(kw, match):
    """Propeller's documented refusals, each at its edge, with its message."""
    with pytest.raises(ValueError, match=match):
        _blade(**kw)


def test_the_chord_beyond_the_stations_is_clipped_at_zero():
    """chord_at: outside the stations PCHIP extrapolates its end polynomial, clipped at 0 (a chord falling linearly
    to 0 at 0.095 m is 0 at the tip, not negative)."""
    p = _blade(r=(0.02, 0.05, 0.08), chord=(0.05, 0.03, 0.01))
    assert float(p.chord_at(0.1)) == 0.0 and float(p.chord_at(0.09)) == pytest.approx(0.01 / 3)


@pytest.mark.parametrize("value", [np.array([True, False]), np.array([800.0, True], dtype=object), [800.0, np.True_],
                                   [[800.0, True]], [np.array([800.0]), (1.0, np.True_)], np.True_, True])
def test_has_bool_finds_a_bool_at_any_depth(value):
    """has_bool: a (nested) list or tuple, or an object array, holding a bool or a boolean array."""
    from propmap.core.geometry import has_bool

    assert has_bool(value)


def test_has_bool_of_plain_numbers_is_false():
    from propmap.core.geometry import has_bool

    assert not has_bool([800.0, 1, np.float64(2.0)]) and not has_bool(np.array([1.0, 0.0])) and not has_bool(1)


def test_broadcast_readonly_returns_an_array_of_the_shape_as_it_is():
    from propmap.core.geometry import broadcast_readonly

    a, b = np.ones(3), np.ones((2, 3))
    ra, rb = broadcast_readonly(a, b)
    assert rb is b and rb.flags.writeable
    assert ra.shape == (2, 3) and not ra.flags.writeable


def test_short_repr_cuts_at_n_and_names_a_huge_integer_by_its_digits():
    """short_repr: the repr cut to its first n - 4 characters and ' ...' where longer; an integer of 30 digits or more
    by its number of digits (its sign not one); a masked array by its repr, on one line, marking the masked ones."""
    from propmap.core.geometry import short_repr

    assert short_repr("x" * 100, n=20) == "'" + "x" * 15 + " ..."
    assert short_repr("x" * 18, n=20) == "'" + "x" * 18 + "'"
    assert short_repr(10**30) == short_repr(-(10**30)) == "an integer of 31 digits"
    assert short_repr(10**30 - 1) == repr(10**30 - 1)
    masked = short_repr(np.ma.masked_array([[1.0, 2.0], [3.0, 4.0]], mask=[[0, 1], [0, 0]]), n=400)
    assert "\n" not in masked and "--" in masked and "None" not in masked


def test_pitch_is_kept_as_a_float():
    p = _blade(pitch=np.float32(0.125))
    assert type(p.pitch) is float and p.pitch == 0.125


def test_solidity_integrates_the_chord_from_the_hub():
    """sigma = N_b * (blade area from r_hub to R) / (pi R^2) = 2 * 0.02 * 0.08 / (pi 0.01) for a constant chord."""
    assert _blade().solidity() == pytest.approx(2 * 0.02 * 0.08 / (math.pi * 0.01), rel=1e-9)


def test_same_size_rules():
    """same_size: a diameter <= 0 is not compared; the blade count rounded; the diameter within 1% by default."""
    p = _blade(n_blades=3)  # D = 0.2 m
    assert p.same_size(0.0, 3) and p.same_size(-1.0, None)
    assert p.same_size(None, 2.9) and not p.same_size(None, 2.4)
    assert p.same_size(0.2 * 1.009, None) and not p.same_size(0.2 * 1.015, None)


def test_rotor_like_measures_the_twist_from_the_first_station_beyond_0_3_r():
    """Blade angle 10 deg at 0.5 R falling linearly to 5 deg at the tip: twist 5 deg from the first station (0.5 R),
    a rotor's (6 deg is the least twist of a propeller); from 0.3 R (extrapolated) it would be 7."""
    from propmap.core.geometry import rotor_like

    why = rotor_like(_blade(r=(0.05, 0.075, 0.1), theta_deg=(10.0, 7.5, 5.0)))
    assert why is not None and "twist 5.0 deg from 0.50 R to the tip" in why


def test_rotor_like_on_either_rule():
    """A blade angle at 0.75 R below 5 deg is a rotor's however twisted; 6 deg with a propeller's twist is not."""
    from propmap.core.geometry import rotor_like

    low = _blade(r=(0.02, 0.03, 0.075, 0.1), chord=(0.02,) * 4, theta_deg=(12.0, 11.0, 3.0, 0.0))
    assert "blade angle 3.0 deg at 0.75 R" in rotor_like(low)
    assert rotor_like(_blade(r=(0.02, 0.03, 0.075, 0.1), chord=(0.02,) * 4, theta_deg=(20.0, 18.0, 6.0, 2.0))) is None


def test_the_stations_are_copied_and_the_input_left_writeable():
    r = np.array([0.02, 0.05, 0.1])
    p = _blade(r=r)
    assert r.flags.writeable
    r[0] = 0.03
    assert p.r[0] == 0.02 and not p.r.flags.writeable


# --- io/mapfile.py -----------------------------------------------------------------------------------------------

def _map(names=None, **attrs):
    """A small map (2 x 2 x 2 nodes, the thrust, torque and flags; over the propellers ``names`` if given)."""
    import xarray as xr

    from propmap.io.mapcheck import FLAGS

    dims = ("rpm", "airspeed", "incidence_deg")
    shape = (2, 2, 2)
    if names is not None:
        dims, shape = ("prop", *dims), (len(names), *shape)
    size = math.prod(shape)
    ds = xr.Dataset(
        {"thrust": (dims, np.arange(size, dtype=float).reshape(shape), {"units": "N"}),
         "torque": (dims, np.full(shape, 0.01), {"units": "N m"}),
         **{f: (dims, np.ones(shape, bool)) for f in FLAGS}},
        coords={"rpm": [3000.0, 6000.0], "airspeed": [0.0, 10.0], "incidence_deg": [0.0, 90.0],
                "omega": ("rpm", [100 * math.pi, 200 * math.pi]), "incidence": ("incidence_deg", [0.0, math.pi / 2])},
        attrs={"propeller": "p", **attrs})
    if names is not None:
        ds = ds.assign_coords(prop=np.array(names, dtype=object))
    return ds


def _several(tmp_path, names=("a", "b"), per_prop=None, name="several.nc"):
    import json

    from propmap.io.mapfile import write_map

    per_prop = {n: {"propeller": n, "diameter_m": [0.2]} for n in names} if per_prop is None else per_prop
    path = tmp_path / name
    write_map(_map(list(names), propeller="several", per_prop_json=json.dumps(per_prop)), path, sidecar=False)
    return path


def test_a_map_over_several_propellers_answers_for_the_one_named(tmp_path):
    """read_dataset(prop=): that propeller's map with its own metadata as attributes (lists as arrays, its entries
    over the file's), without the others' JSON; an unknown or missing name refused, not wrapped as unreadable."""
    from propmap.io.mapfile import read_dataset

    path = _several(tmp_path)
    ds = read_dataset(path, "b")
    assert ds.attrs["propeller"] == "b" and "per_prop_json" not in ds.attrs
    assert isinstance(ds.attrs["diameter_m"], np.ndarray) and ds.attrs["diameter_m"].tolist() == [0.2]
    np.testing.assert_array_equal(ds["thrust"].values.ravel(), np.arange(8.0, 16.0))
    for prop in ("c", None):
        with pytest.raises(ValueError, match=r"several\.nc: a map of 2 propellers; give prop= one of them "
                                             rf"\(e\.g\. a, b\), got {prop!r}") as err:
            read_dataset(path, prop)
        assert "not a readable" not in str(err.value)


def test_a_map_over_several_propellers_without_their_metadata_or_with_a_name_twice_is_refused(tmp_path):
    from propmap.io.mapfile import read_dataset

    path = _several(tmp_path, per_prop={"a": {"propeller": "a"}})
    with pytest.raises(ValueError, match=r"needs the attribute per_prop_json, a JSON object with an object for 'b'"):
        read_dataset(path, "b")
    path = _several(tmp_path, names=("a", "a"), name="twice.nc")
    with pytest.raises(ValueError, match=r"twice\.nc: the prop coordinate must hold distinct propeller names"):
        read_dataset(path, "a")


def test_read_dataset_and_map_props_refuse_arguments_of_the_wrong_type(tmp_path):
    from propmap.io.mapfile import map_props, read_dataset, write_map

    path = tmp_path / "m.nc"
    write_map(_map(), path, sidecar=False)
    with pytest.raises(TypeError, match=r"prop must be a propeller name \(str\) or None, got int"):
        read_dataset(path, 5)
    with pytest.raises(TypeError, match=r"path must be a str or os.PathLike \(a map file\), got int"):
        map_props(5)
    assert map_props(path) is None


def test_read_dataset_reads_only_a_maps_variables_and_refuses_one_on_other_dimensions(tmp_path):
    import netCDF4

    from propmap.io.mapfile import read_dataset, write_map

    path = tmp_path / "m.nc"
    write_map(_map(), path, sidecar=False)
    with netCDF4.Dataset(path, "a") as nc:
        nc.createDimension("x", 3)
        nc.createVariable("junk", "f8", ("x",))[:] = [1.0, 2.0, 3.0]
    ds = read_dataset(path)
    assert "junk" not in ds.variables and "thrust" in ds.data_vars
    with netCDF4.Dataset(path, "a") as nc:
        nc.createVariable("drag", "f8", ("x",))[:] = [1.0, 2.0, 3.0]
    with pytest.raises(ValueError, match=r"m\.nc: variable drag of dimensions x \(3\) is not a map's"):
        read_dataset(path)


def test_a_memory_error_is_not_called_a_damaged_file(tmp_path, monkeypatch):
    """read_dataset turns what the libraries raise into a ValueError, but a MemoryError (too large for the memory)
    passes as it is."""
    import xarray as xr

    from propmap.io.mapfile import read_dataset, write_map

    path = tmp_path / "m.nc"
    write_map(_map(), path, sidecar=False)

    def no_memory(*args, **kwargs):
        raise MemoryError("test")

    monkeypatch.setattr(xr, "open_dataset", no_memory)
    with pytest.raises(MemoryError):
        read_dataset(path)


def test_a_prop_coordinate_of_no_names_is_refused(tmp_path):
    import netCDF4

    from propmap.io.mapfile import map_props

    path = tmp_path / "none.nc"
    with netCDF4.Dataset(path, "w") as nc:
        nc.createDimension("prop", 0)
        nc.createDimension("nchar", 1)
        nc.createVariable("prop", "S1", ("prop", "nchar"))._Encoding = "utf-8"
    with pytest.raises(ValueError, match="distinct propeller names"):
        map_props(path)


def test_propeller_names_of_up_to_256_bytes_are_written_and_read(tmp_path):
    """write_map: a name of the prop coordinate longer than MAX_NAME_CHARS (256) bytes in UTF-8 is refused (129 'é'
    are 258 bytes); one of 256 is written, and read back."""
    from propmap.io.mapfile import map_props, write_map

    longest = "n" * 256
    path = _several(tmp_path, names=(longest, "b"))
    assert map_props(path) == (longest, "b")
    with pytest.raises(ValueError, match=r"is 258 bytes long \(UTF-8\); a map file holds names of at most 256"):
        write_map(_map(["é" * 129, "b"]), tmp_path / "long.nc", sidecar=False)


def test_write_map_refuses_what_it_cannot_write(tmp_path):
    from propmap.io.mapfile import write_map

    with pytest.raises(TypeError, match=r"ds must be an xarray.Dataset \(a map from build_map\), got dict"):
        write_map({}, tmp_path / "m.nc")
    with pytest.raises(ValueError, match="path is empty"):
        write_map(_map(), "")
    with pytest.raises(ValueError, match=r"unknown map format 'nc' \(netcdf or csv\)"):
        write_map(_map(), tmp_path / "m.nc", "nc")
    assert not list(tmp_path.iterdir())


def test_write_map_compresses_at_level_4_and_without_a_sidecar_writes_one_file(tmp_path):
    import netCDF4

    from propmap.io.mapfile import write_map

    path = tmp_path / "m.nc"
    assert write_map(_map(), path, sidecar=False) == [path]
    assert [p.name for p in tmp_path.iterdir()] == ["m.nc"]
    with netCDF4.Dataset(path) as nc:
        assert nc["thrust"].filters()["zlib"] and nc["thrust"].filters()["complevel"] == 4


def test_the_sidecar_names_the_map_file_its_sizes_and_units_and_nulls_every_non_finite_value(tmp_path):
    from propmap.io.mapfile import map_metadata, read_sidecar, write_map

    path = tmp_path / "m.nc"
    write_map(_map(), path)
    meta = read_sidecar(path)
    assert meta["describes"]["file"] == "m.nc"
    assert meta["dims"] == {"rpm": 2, "airspeed": 2, "incidence_deg": 2}
    assert meta["variables"]["thrust"] == "N" and meta["variables"]["torque"] == "N m"
    meta = map_metadata(_map(err=float("inf"), pair=(1.0, float("nan")), low=-math.inf))
    assert meta["err"] is None and meta["pair"] == [1.0, None] and meta["low"] is None


def test_read_sidecar_refuses_a_sidecar_that_describes_no_file(tmp_path):
    """write_sidecar writes no 'describes' entry: read_sidecar refuses it with a ValueError, as any sidecar that does
    not describe the map as it is."""
    from propmap.io.mapfile import read_sidecar, sidecar_path, write_map, write_sidecar

    path = tmp_path / "m.nc"
    write_map(_map(), path, sidecar=False)
    write_sidecar(_map(), sidecar_path(path))
    with pytest.raises(ValueError, match=r"does not describe .*m\.nc as it is now"):
        read_sidecar(path)


def test_a_map_written_through_a_link_has_its_sidecar_beside_the_file(tmp_path):
    from propmap.io.mapfile import read_sidecar, write_map

    target = tmp_path / "real" / "m.nc"
    target.parent.mkdir()
    target.write_bytes(b"")
    link = tmp_path / "link.nc"
    link.symlink_to(target)
    write_map(_map(), link)
    assert (tmp_path / "real" / "m.nc.json").is_file() and not (tmp_path / "link.nc.json").exists()
    assert read_sidecar(target)["describes"]["file"] == "m.nc"


def test_a_variable_of_exactly_max_nodes_nodes_is_read(tmp_path):
    """read_dataset refuses a variable declaring *more than* MAX_NODES (20,000,000) nodes: one of exactly that many is
    read (a file of no data: every node the fill value)."""
    import netCDF4

    from propmap.io.mapfile import MAX_NODES, read_dataset

    path = tmp_path / "exact.nc"
    sizes = {"rpm": 5000, "airspeed": 4000, "incidence_deg": 1}
    assert math.prod(sizes.values()) == MAX_NODES
    with netCDF4.Dataset(path, "w") as nc:
        for d, n in sizes.items():
            nc.createDimension(d, n)
        nc.createVariable("thrust", "f4", tuple(sizes), chunksizes=(1000, 1000, 1), zlib=True)
    assert read_dataset(path)["thrust"].size == MAX_NODES


def test_a_propeller_refuses_masked_stations_naming_the_argument():
    """A masked array with masked entries is refused, naming the argument: np.asarray drops the mask, and a masked
    chord of 99 m (a fill value) was taken as a station's chord (a defect found by this audit)."""
    from propmap.core.geometry import Propeller

    good = dict(r=[0.02, 0.05, 0.1], chord=[0.02, 0.02, 0.02], theta=[0.3, 0.2, 0.1])
    for key, value in (("chord", [0.02, 99.0, 0.02]), ("r", [0.02, 0.05, 0.1]), ("theta", [0.3, 0.2, 0.1])):
        args = {**good, key: np.ma.masked_array(value, mask=[False, True, False])}
        with pytest.raises(ValueError, match=rf"^{key}: a masked array with masked entries"):
            Propeller("audit", 0.1, 2, **args)
    p = Propeller("audit", 0.1, 2, **{**good, "chord": np.ma.masked_array(good["chord"], mask=[False] * 3)})
    assert p.chord.tolist() == [0.02, 0.02, 0.02] and type(p.chord) is np.ndarray
