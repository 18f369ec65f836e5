"""A mutation audit of the map interpolation kernel and the C header export (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""

import math
import re
import shutil
import subprocess

import numpy as np
import pytest

import propmap as pm
from propmap.export_c import c_header_text, write_c_header
from propmap.maps import RotorMap, build_map

from .conftest import RPM
from .test_maps import _synthetic_map
from .test_maps_c import DRIVER  # (the C driver reading points from stdin)

CC = shutil.which("cc") or shutil.which("gcc")

# non-uniform axes: a geometric rpm axis, irregular airspeed and incidence axes (the header bisects them)
OMEGA = np.array([3000.0, 4500.0, 7000.0, 9000.0]) * RPM
SPEED = np.array([0.0, 2.0, 5.0, 6.0, 10.0])
BETA = np.radians([0.0, 20.0, 70.0, 90.0, 150.0, 180.0])


def _poly(O, V, B):
    """A function quadratic in each axis (scaled so that the loads stay within a map's ranges)."""
    return 1e-7 * (1 + 1e-4 * O**2 - 0.02 * V**2 + 0.3 * B**2 + 1e-5 * O * V * B**2 + 0.1 * O * V - 0.2 * B)


@pytest.fixture(scope="module")
def tiny():
    """A 4 x 5 x 6 map on non-uniform axes, its loads replaced by _poly x (Omega R)^2 + V^2: (dataset, R)."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    return _synthetic_map(build_map(prop, params, OMEGA, SPEED, BETA, air=params.air, params_label=params.label,
                                    n_check=0), _poly)


def _queries(rm, n=300, seed=5):
    """Random points inside the grid, every node, and points outside it on each side."""
    rng = np.random.default_rng(seed)
    O = rng.uniform(rm.omega[0], rm.omega[-1], n)
    V = rng.uniform(rm.airspeed[0], rm.airspeed[-1], n)
    B = rng.uniform(rm.incidence[0], rm.incidence[-1], n)
    No, Nv, Nb = (a.ravel() for a in np.meshgrid(rm.omega, rm.airspeed, rm.incidence, indexing="ij"))
    inf = math.inf
    out_o = np.array([rm.omega[0] / 2, rm.omega[-1] * 1.2, rm.omega[1], rm.omega[2], 0.0, inf, 500.0, 500.0])
    out_v = np.array([3.0, 4.0, 12.0, 7.0, 1.0, 5.0, inf, 5.0])
    out_b = np.array([0.5, 1.0, 2.0, 0.3, 1.2, 1.0, 1.0, inf])
    return np.concatenate([O, No, out_o]), np.concatenate([V, Nv, out_v]), np.concatenate([B, Nb, out_b])


@pytest.mark.parametrize("interpolation", ["linear", "cubic"])
def test_lookups_at_the_nodes_of_non_uniform_axes_are_the_node_values(tiny, interpolation):
    """At every node of non-uniform axes the lookup returns the node's loads (to rounding), in both paths."""
    ds, _ = tiny
    rm = RotorMap(ds, interpolation)
    O, V, B = np.meshgrid(rm.omega, rm.airspeed, rm.incidence, indexing="ij")
    got = rm.loads(O, V, B)
    for k in ("thrust", "drag", "torque", "rolling_moment"):
        np.testing.assert_allclose(getattr(got, k), ds[k].values, rtol=1e-13, atol=0)
    one = rm.loads(float(O[1, 2, 3]), float(V[1, 2, 3]), float(B[1, 2, 3]))
    assert one.thrust == pytest.approx(float(ds["thrust"].values[1, 2, 3]), rel=1e-13)
    assert got.inside.all() and not got.flagged.any()


def test_the_cubic_reproduces_quadratics_on_non_uniform_axes_in_three_dimensions(tiny):
    """The cubic lookup on three non-uniform axes reproduces a function quadratic in each axis to 1e-10."""
    ds, R = tiny
    rm = RotorMap(ds, "cubic")
    O, V, B = _queries(rm)[0][:300], _queries(rm)[1][:300], _queries(rm)[2][:300]
    got = rm.loads(O, V, B)
    ref = _poly(O, V, B) * ((O * R) ** 2 + V**2)
    np.testing.assert_allclose(got.thrust, ref, rtol=1e-10)
    np.testing.assert_allclose(got.rolling_moment, 4 * ref, rtol=1e-10)


def test_clip_holds_the_edge_value_and_scales_below_the_lowest_rpm(tiny):
    """Under clip a query beyond an axis takes the edge's value, and below Omega_min the row's times (Omega/min)^2."""
    ds, R = tiny
    rm = RotorMap(ds, "linear")
    edge = rm.loads(rm.omega[-1], 10.0, 1.0).thrust
    assert rm.loads(rm.omega[-1] * 1.3, 10.0, 1.0, out_of_grid="clip").thrust == edge
    assert rm.loads(rm.omega[-1], 14.0, 1.0, out_of_grid="clip").thrust == edge
    low = rm.loads(rm.omega[0], 5.0, 1.0).thrust
    half = rm.loads(rm.omega[0] / 2, 5.0, 1.0, out_of_grid="clip")
    assert half.thrust == pytest.approx(low / 4, rel=1e-14)
    assert not half.inside and half.flagged


@pytest.mark.parametrize("interpolation", ["linear", "cubic"])
def test_the_headers_opening_comment_states_the_grid_in_rpm_and_degrees(tiny, interpolation):
    """The header's Grid line gives the rpm range in rpm and the incidence range in degrees."""
    ds, _ = tiny
    text = c_header_text(RotorMap(ds, interpolation), "map.h")
    assert " * Grid: 4 rpm (3000-9000 rpm) x 5 airspeed (0-10 m/s) x 6 incidence\n * (0-180 deg);" in text
    assert f"{interpolation} interpolation" in text
    part = c_header_text(RotorMap(ds.isel(incidence_deg=[1, 2, 3, 4, 5]), interpolation), "map.h")
    assert " x 6 incidence\n * (20-180 deg);" in part.replace(" x 5 incidence", " x 6 incidence")


def _run_c(tmp_path, rm, stdin, dtype="double", driver=DRIVER):
    """The header's loads (or what ``driver`` prints), compiled with the system compiler, at each line of
    stdin (o v b policy for the loads' driver)."""
    write_c_header(rm, tmp_path / "map.h", dtype=dtype)
    (tmp_path / "driver.c").write_text(driver)
    exe = tmp_path / "driver"
    subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(exe),
                    str(tmp_path / "driver.c"), "-lm"], check=True, capture_output=True, text=True)
    out = subprocess.run([str(exe)], input=stdin, capture_output=True, text=True, check=True).stdout
    return np.array([line.split() for line in out.splitlines()], dtype=float)


@pytest.mark.skipif(CC is None, reason="no C compiler")
@pytest.mark.parametrize("interpolation", ["linear", "cubic"])
def test_the_c_header_on_non_uniform_axes_equals_the_python_lookup(tmp_path, tiny, interpolation):
    """On bisected and geometric axes (infinite queries clipped too) the double header is RotorMap.loads to 1e-12."""
    ds, _ = tiny
    rm = RotorMap(ds, interpolation)
    O, V, B = _queries(rm)
    stdin = "".join(f"{float(o)!r} {float(v)!r} {float(b)!r} 0\n" for o, v, b in zip(O, V, B))
    rows = _run_c(tmp_path, rm, stdin)
    ref = rm.loads(O, V, B, out_of_grid="clip")
    for k, name in enumerate(("thrust", "drag", "torque", "rolling_moment")):
        np.testing.assert_allclose(rows[:, 1 + k], getattr(ref, name), rtol=1e-12, atol=1e-300)
    np.testing.assert_array_equal(rows[:, 0], np.where(ref.inside, 0, 2))


TWO_UNITS = r"""
#include "map.h"
double {name}(double o) {{ double out[4]; pm_map_loads(o, 5.0, 1.0, PM_MAP_CLIP, out); return out[0]; }}
"""


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_the_header_links_into_two_translation_units_unoptimised(tmp_path, tiny):
    """Its tables and functions are static (const): two units including it link at -O0 and agree with Python."""
    from propmap.core.body import BodyDrag
    from propmap.vehicle import Rotor, Vehicle

    ds, _ = tiny
    rm = RotorMap(ds, "cubic")
    prop = pm.load_propeller("apce_8x6")
    rotors = tuple(Rotor(np.array([0.1, y, 0.0]), np.array([0.0, 0.0, 1.0]), s, prop)
                   for y, s in ((0.1, 1), (-0.1, -1)))
    veh = Vehicle(mass=0.3, rotors=rotors, body_drag=BodyDrag((0.01, 0.01, 0.02)), name="pair")
    write_c_header(rm, tmp_path / "map.h", vehicle=veh)
    (tmp_path / "a.c").write_text(TWO_UNITS.format(name="fa"))
    (tmp_path / "b.c").write_text(TWO_UNITS.format(name="fb"))
    (tmp_path / "main.c").write_text("#include <stdio.h>\ndouble fa(double);\ndouble fb(double);\n"
                                     "int main(void) { printf(\"%.17g %.17g\\n\", fa(700.0), fb(700.0)); return 0; }\n")
    exe = tmp_path / "two"
    subprocess.run([CC, "-std=c99", "-O0", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(exe),
                    *(str(tmp_path / f) for f in ("a.c", "b.c", "main.c")), "-lm"], check=True, capture_output=True,
                   text=True)
    a, b = (float(x) for x in subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.split())
    assert a == b == pytest.approx(rm.loads(700.0, 5.0, 1.0).thrust, rel=1e-6)
    # and the data is read-only: every table at file scope is declared static const
    text = c_header_text(rm, "map.h", vehicle=veh)
    tables = dict((n, d) for d, n in re.findall(r"^(.*?)\b(pm_map_\w+)(?:\[\w*\])+\s*=", text, flags=re.M))
    assert {"pm_map_table", "pm_map_slope0", "pm_map_rotor_pos", "pm_map_body_cd"} <= set(tables)
    assert all(d.startswith("static const ") for d in tables.values()), tables


def test_the_cubic_header_at_the_nodes_of_a_two_node_axis_is_linear(tmp_path, tiny):
    """An axis of 2 nodes is interpolated linearly by both the kernel and the header's cubic."""
    ds, R = tiny
    two = ds.isel(airspeed=[1, 2])
    rm = RotorMap(two, "cubic")
    v = 2.0 + 3.0 * 0.25
    lo, hi = rm.loads(5000 * RPM, 2.0, 1.0), rm.loads(5000 * RPM, 5.0, 1.0)
    s = lambda V: (5000 * RPM * R) ** 2 + V**2  # noqa: E731
    want = (0.75 * lo.thrust / s(2.0) + 0.25 * hi.thrust / s(5.0)) * s(v)
    assert rm.loads(5000 * RPM, v, 1.0).thrust == pytest.approx(want, rel=1e-13)
    if CC is None:
        pytest.skip("no C compiler")
    rows = _run_c(tmp_path, rm, f"{5000 * RPM!r} {v!r} 1.0 0\n")
    assert rows[0, 1] == pytest.approx(want, rel=1e-12)
    assert math.isfinite(rows[0, 1])


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_the_headers_edge_rules_are_pythons_just_beyond_the_snap_and_at_the_hover_speed(tmp_path, tiny):
    """An incidence 1e-6 rad past the axis is outside (NaN) in both; at exactly 1e-6 m/s any incidence is inside."""
    ds, _ = tiny
    rm = RotorMap(ds.isel(incidence_deg=[1, 2, 3, 4, 5]), "linear")  # 20-180 deg: 0 deg lies off the axis
    o = 5000 * RPM
    q = [(o, 3.0, math.pi + 1e-6, 1), (o, 3.0, math.radians(20) - 1e-6, 1), (o, 3.0, math.pi + 1e-7, 1),
         (o, 1e-6, 0.0, 1), (o, 1e-6, 0.0, 0)]
    rows = _run_c(tmp_path, rm, "".join(f"{a!r} {b!r} {c!r} {p}\n" for a, b, c, p in q))
    assert rows[:, 0].tolist() == [2, 2, 0, 0, 0]
    assert np.isnan(rows[:2, 1:]).all()
    for (a, b, c, p), row in zip(q[2:], rows[2:]):
        ref = rm.loads(a, b, c, out_of_grid="nan" if p else "clip")
        assert ref.inside and row[1] == pytest.approx(ref.thrust, rel=1e-12)
    assert np.isnan(rm.loads(o, 3.0, math.pi + 1e-6, out_of_grid="nan").thrust)
    # on an airspeed axis from 5e-7 m/s (not from 0) an incidence off its axis is outside, even at 1e-6 m/s
    rm = RotorMap(ds.isel(incidence_deg=[1, 2, 3, 4, 5]).assign_coords(airspeed=[5e-7, 2.0, 5.0, 6.0, 10.0]), "linear")
    rows = _run_c(tmp_path, rm, f"{o!r} 1e-06 0.0 1\n")
    assert rows[0, 0] == 2 and np.isnan(rows[0, 1]) and not rm.loads(o, 1e-6, 0.0, out_of_grid="nan").inside


def geometric_map_flagged_at(k: int) -> RotorMap:
    """apce_8x6's linear map on a geometric rpm axis (6 nodes, 2000-9000 rpm; 3 airspeeds, 3 incidences)
    with every flag cleared but vortex_ring on rpm node k: a cell's flag spans its neighbours' nodes."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.geomspace(2000, 9000, 6) * RPM, [0.0, 5.0, 10.0], np.radians([0.0, 90.0, 180.0]),
                   air=params.air, params_label=params.label, n_check=0).copy(deep=True)
    ds["converged"].values[...] = True
    for flag in ("vortex_ring", "multiple_roots"):
        ds[flag].values[...] = False
    ds["vortex_ring"].values[k] = True
    return RotorMap(ds, "linear")


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_the_header_finds_each_nodes_cell_and_flag_as_python_on_a_geometric_axis(tmp_path):
    """At every node of a geometric rpm axis (cells found by arithmetic) the header's status is Python's flag."""
    rm = geometric_map_flagged_at(5)  # the top rpm row: cells 3 and 4 flagged, 0-2 not
    O, V, B = (a.ravel() for a in np.meshgrid(rm.omega, rm.airspeed, rm.incidence, indexing="ij"))
    rows = _run_c(tmp_path, rm, "".join(f"{float(o)!r} {float(v)!r} {float(b)!r} 0\n" for o, v, b in zip(O, V, B)))
    ref = rm.loads(O, V, B)
    assert ref.flagged.any() and not ref.flagged.all()
    np.testing.assert_array_equal(rows[:, 0], ref.flagged.astype(float))
    np.testing.assert_allclose(rows[:, 1], ref.thrust, rtol=1e-12)


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_a_nearly_uniform_axis_is_bisected_and_the_header_equals_python(tmp_path):
    """Steps of 1.25 then 0.75 m/s (within 25% of their mean, drifting 1.5 cells) are bisected: C = Python to 1e-12."""
    from propmap.export_c import _inverse_step

    speeds = np.concatenate([np.arange(7) * 1.25, 7.5 + np.arange(1, 7) * 0.75])
    assert _inverse_step(speeds) == "0.0"
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.array([3000.0, 6000.0]) * RPM, speeds, np.radians([0.0, 90.0, 180.0]),
                   air=params.air, params_label=params.label, n_check=0)
    rm = RotorMap(ds, "linear")
    v = np.linspace(0.0, 12.0, 41)
    rows = _run_c(tmp_path, rm, "".join(f"{4000 * RPM!r} {float(x)!r} 1.0 0\n" for x in v))
    np.testing.assert_allclose(rows[:, 1], rm.loads(4000 * RPM, v, 1.0).thrust, rtol=1e-12)
