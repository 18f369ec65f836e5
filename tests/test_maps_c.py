"""The C export of a map: compiled with the system C compiler and compared with the Python
evaluator (RotorMap.loads) on random points, inside and outside the grid, for every policy
and both interpolations."""

import math
import shutil
import subprocess

import numpy as np
import pytest

import propmap as pm
from propmap.export_c import write_c_header
from propmap.maps import RotorMap, build_map

from .conftest import RPM

CC = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")

DRIVER = r"""
#include <stdio.h>
#include "map.h"
int main(void)
{
    double o, v, b, out[4];
    int policy, status;
    while (scanf("%lf %lf %lf %d", &o, &v, &b, &policy) == 4) {
        out[0] = out[1] = out[2] = out[3] = -12345.0;
        status = pm_map_loads(o, v, b, policy, out);
        printf("%d %.17g %.17g %.17g %.17g\n", status, out[0], out[1], out[2], out[3]);
    }
    return 0;
}
"""


@pytest.fixture(scope="module")
def rotor_map():
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    air, label = params.air, params.label
    ds = build_map(prop, params, np.geomspace(3000, 9000, 6) * RPM, np.linspace(0, 15, 7),
                   np.radians(np.linspace(0, 180, 19)), air=air, params_label=label, n_check=200)
    return RotorMap(ds)


def _compile(tmp_path, rm, dtype):
    write_c_header(rm, tmp_path / "map.h", dtype=dtype)
    (tmp_path / "driver.c").write_text(DRIVER)
    exe = tmp_path / "driver"
    subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(exe),
                    str(tmp_path / "driver.c"), "-lm"], check=True, capture_output=True, text=True)
    return exe


@pytest.mark.skipif(CC is None, reason="no C compiler")
@pytest.mark.parametrize("interpolation", ["cubic", "linear"])
@pytest.mark.parametrize("dtype, rtol", [("float", 1e-6), ("double", 1e-12)])
def test_c_header_compiles_cleanly_and_matches_the_python_evaluator(tmp_path, rotor_map, dtype, rtol, interpolation):
    rm = RotorMap(rotor_map.dataset, interpolation)
    exe = _compile(tmp_path, rm, dtype)
    rng = np.random.default_rng(4)
    n = 400
    om = rng.uniform(rm.omega[0] * 0.8, rm.omega[-1] * 1.1, n)  # some outside the grid
    om[:6] = (0.0, 0.0, rm.omega[0] / 2, rm.omega[0] / 2, -3.0, -3.0)  # stopped, spin-up, signed
    V = rng.uniform(0, 18, n)
    b = rng.uniform(0, math.pi, n)
    policy = rng.integers(0, 3, n)
    policy[:6] = (0, 1, 0, 1, 0, 1)
    # queries on the nodes of the uniform and geometric axes, whose cells the header finds by arithmetic: the same
    # cell (and flag) as the bisection of the Python evaluator
    V[6:46] = rm.airspeed[rng.integers(0, rm.airspeed.size, 40)]
    b[6:46] = rm.incidence[rng.integers(0, rm.incidence.size, 40)]
    om[30:60] = rm.omega[rng.integers(0, rm.omega.size, 30)]
    stdin = "".join(f"{float(o)!r} {float(v)!r} {float(x)!r} {int(p)}\n" for o, v, x, p in zip(om, V, b, policy))
    rows = np.array([line.split() for line in subprocess.run([str(exe)], input=stdin, capture_output=True, text=True,
                                                             check=True).stdout.splitlines()], dtype=float)
    status, c_out = rows[:, 0].astype(int), rows[:, 1:]
    assert np.all(status[om < 0] == -1)  # a signed omega is refused, as RotorMap refuses it
    assert np.all(c_out[0] == 0.0) and status[0] == 2  # a stopped rotor under CLIP: zero loads
    for name, code in (("clip", 0), ("nan", 1)):
        m = (policy == code) & (om >= 0)
        got = rm.loads(om[m], V[m], b[m], out_of_grid=name)
        py = np.column_stack([got.thrust, got.drag, got.torque, got.rolling_moment])
        # relative to each load's own largest value (T, D, Q, M_R apart)
        scale = np.nanmax(np.abs(py), axis=0)
        assert np.array_equal(np.isnan(c_out[m]), np.isnan(py))
        ok = np.isnan(py) | (np.abs(c_out[m] - py) <= rtol * (np.abs(py) + scale))
        assert ok.all(), np.nanmax(np.abs(c_out[m] - py) / scale)
        expect = np.where(~got.inside, 2, np.where(got.flagged, 1, 0))
        np.testing.assert_array_equal(status[m], expect)
    m = (policy == 2) & (om >= 0)  # error policy: -1 outside and the outputs untouched, as "raise" refuses them
    inside = (om >= rm.omega[0]) & (om <= rm.omega[-1]) & (V <= rm.airspeed[-1])
    assert np.all(status[m & ~inside] == -1) and np.all(c_out[m & ~inside] == -12345.0)
    assert np.all(status[m & inside] >= 0)
    header = (tmp_path / "map.h").read_text()
    assert f"; {interpolation} interpolation." in header and ("_weights(" in header) == (interpolation == "cubic")
    # the arithmetic cell lookup is on for the fixture's geometric rpm and uniform airspeed/incidence axes
    for k in range(3):
        assert f"#define PM_MAP_U{k} 0.0\n" not in header and f"#define PM_MAP_U{k} " in header


WRENCH_DRIVER = r"""
#include <stdio.h>
#include "map.h"
int main(void)
{
    double v[3], a[3], o, f[3], m[3];
    int spin, policy, status;
    while (scanf("%lf %lf %lf %lf %lf %lf %lf %d %d", &v[0], &v[1], &v[2], &a[0], &a[1], &a[2], &o, &spin,
                 &policy) == 9) {
        f[0] = f[1] = f[2] = m[0] = m[1] = m[2] = -12345.0;
        status = pm_map_wrench(v, a, o, spin, policy, f, m);
        printf("%d %.17g %.17g %.17g %.17g %.17g %.17g\n", status, f[0], f[1], f[2], m[0], m[1], m[2]);
    }
    return 0;
}
"""


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_c_wrench_equals_the_python_wrench(tmp_path, rotor_map):
    """pm_map_wrench (velocity, axis, omega, spin -> force and moment vectors) against RotorMap.wrench with the
    same interpolation: random directions and speeds, both spins, axial and zero velocity; bad inputs -1."""
    write_c_header(rotor_map, tmp_path / "map.h", dtype="double")
    (tmp_path / "w.c").write_text(WRENCH_DRIVER)
    exe = tmp_path / "w"
    subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(exe),
                    str(tmp_path / "w.c"), "-lm"], check=True, capture_output=True, text=True)
    rng = np.random.default_rng(7)
    rows = []
    for i in range(200):
        d = rng.normal(size=3)
        v = d / np.linalg.norm(d) * rng.uniform(0, 14)
        a = rng.normal(size=3) * rng.uniform(0.1, 5)
        if i == 0:
            v = np.zeros(3)
        if i == 1:
            v = 3.0 * a / np.linalg.norm(a)  # axial: e_ip = 0
        if 2 <= i < 40:  # nearly axial, climb and descent: the incidence's rounding (arccos of a cosine
            v = a * rng.uniform(-4.0, 4.0)  # rounded to 1 - 1e-16 was 1.5e-8 rad; an audit, 2026-11-27)
        rows.append((*v, *a, float(rng.uniform(rotor_map.omega[0], rotor_map.omega[-1])), int(rng.choice([1, -1]))))
    bad = [(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 500.0, 1), (math.nan, 0.0, 0.0, 0.0, 0.0, 1.0, 500.0, 1),
           (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 500.0, 2), (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, -5.0, 1)]
    stdin = "".join(" ".join(repr(float(x)) for x in r[:7]) + f" {r[7]} 0\n" for r in rows + bad)
    out = np.array([line.split() for line in subprocess.run([str(exe)], input=stdin, capture_output=True, text=True,
                                                            check=True).stdout.splitlines()], dtype=float)
    for r, o in zip(rows, out):
        w = rotor_map.wrench(np.array(r[:3]), np.array(r[3:6]), r[6], r[7], out_of_grid="clip")
        expect = 2 if not w.loads.inside else (1 if w.loads.flagged else 0)
        assert int(o[0]) == expect
        np.testing.assert_allclose(o[1:4], w.force, rtol=1e-12, atol=1e-13)
        np.testing.assert_allclose(o[4:7], w.torque, rtol=1e-12, atol=1e-13)
    assert np.all(out[len(rows):, 0] == -1) and np.all(out[len(rows):, 1:] == -12345.0)
    header = (tmp_path / "map.h").read_text()
    assert "force = T z - D e_ip; moment = -spin (Q z + M_R e_ip)" in header


VEHICLE_DRIVER = r"""
#include <stdio.h>
#include "map.h"
int main(void)
{
    double v[3], w[3], o[4], f[3], m[3];
    int status;
    while (scanf("%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &w[0], &w[1], &w[2], &o[0], &o[1],
                 &o[2], &o[3]) == 10) {
        status = pm_map_vehicle_wrench(v, w, o, PM_MAP_CLIP, f, m);
        printf("%d %.17g %.17g %.17g %.17g %.17g %.17g\n", status, f[0], f[1], f[2], m[0], m[1], m[2]);
    }
    return 0;
}
"""


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_c_vehicle_wrench_equals_the_python_vehicle_map(tmp_path, rotor_map):
    """pm_map_vehicle_wrench (a quadrotor of four apce_8x6 with rotor inertias, an offset centre of mass and an
    airframe) against propmap.VehicleMap.wrench on the same map: random velocities, rates and rotor speeds."""
    from propmap.core.body import BodyDrag
    from propmap.vehicle import VehicleMap
    from propmap.vehicle import Rotor, Vehicle

    prop = pm.load_propeller("apce_8x6")
    d = 0.106
    rotors = tuple(Rotor(np.array(p), np.array([0.0, 0.0, 1.0]), s, prop, inertia=2e-5)
                   for p, s in zip([(d, d, 0.0), (d, -d, 0.0), (-d, -d, 0.0), (-d, d, 0.0)], (1, -1, 1, -1)))
    veh = Vehicle(mass=0.8, rotors=rotors, body_drag=BodyDrag((0.01, 0.012, 0.02)), centre_of_mass=np.array(
        [0.004, 0.0, -0.01]), name="X */ quad")
    write_c_header(rotor_map, tmp_path / "map.h", dtype="double", vehicle=veh)
    (tmp_path / "v.c").write_text(VEHICLE_DRIVER)
    exe = tmp_path / "v"
    subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(exe),
                    str(tmp_path / "v.c"), "-lm"], check=True, capture_output=True, text=True)
    rng = np.random.default_rng(9)
    n = 100
    v, w = rng.normal(0, 4, (n, 3)), rng.normal(0, 1, (n, 3))
    om = rng.uniform(rotor_map.omega[0] * 0.5, rotor_map.omega[-1], (n, 4))  # some spinning up below the grid
    stdin = "".join(" ".join(repr(float(x)) for x in (*a, *b, *c)) + "\n" for a, b, c in zip(v, w, om))
    out = np.array([line.split() for line in subprocess.run([str(exe)], input=stdin, capture_output=True, text=True,
                                                            check=True).stdout.splitlines()], dtype=float)
    ref = VehicleMap(veh, rotor_map).wrench(v, w, om, out_of_grid="clip")
    np.testing.assert_allclose(out[:, 1:4], ref.force, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(out[:, 4:7], ref.moment, rtol=1e-10, atol=1e-12)
    np.testing.assert_array_equal(out[:, 0] > 0, ref.flagged)
    with pytest.raises(ValueError, match=r"rotor 1 carries apce_9x6 \(0.2286 m, 2 blades\), not the map's apce_8x6 "
                                         r"\(0.2032 m"):
        write_c_header(rotor_map, tmp_path / "x.h", vehicle=Vehicle(mass=1.0, rotors=(
            Rotor(np.zeros(3), np.array([0.0, 0.0, 1.0]), 1, pm.load_propeller("apce_9x6")),)))


def test_bad_dtype_and_name_are_refused(tmp_path, rotor_map):
    with pytest.raises(ValueError, match="dtype"):
        write_c_header(rotor_map, tmp_path / "m.h", dtype="half")
    with pytest.raises(ValueError, match="C identifier"):
        write_c_header(rotor_map, tmp_path / "m.h", name="1bad-name")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_header_included_unused_twice_and_beside_another_map(tmp_path, rotor_map):
    """static inline: an unused include compiles under -Werror; the same header twice is
    skipped by its guard; two different maps under one prefix fail to compile (never one
    silently standing in for the other); an unknown policy returns -1."""
    flags = ["-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-c", "-o", str(tmp_path / "x.o")]
    write_c_header(rotor_map, tmp_path / "a.h", name="pm_rotor")
    (tmp_path / "unused.c").write_text('#include "a.h"\n#include "a.h"\nint f(void) { return 0; }\n')
    subprocess.run([CC, *flags, str(tmp_path / "unused.c")], check=True, capture_output=True)
    other = RotorMap(rotor_map.dataset.isel(rpm=slice(0, 4)))
    write_c_header(other, tmp_path / "b.h", name="pm_rotor")
    (tmp_path / "both.c").write_text('#include "a.h"\n#include "b.h"\nint f(void) { return 0; }\n')
    assert subprocess.run([CC, *flags, str(tmp_path / "both.c")], capture_output=True).returncode != 0
    (tmp_path / "policy.c").write_text('''#include <stdio.h>
#include "a.h"
int main(void) { double out[4] = {0, 0, 0, 0}; printf("%d", pm_rotor_loads(500.0, 5.0, 0.5, 7, out)); return 0; }
''')
    subprocess.run([CC, "-std=c99", "-o", str(tmp_path / "policy"), str(tmp_path / "policy.c"), "-lm"], check=True)
    assert subprocess.run([str(tmp_path / "policy")], capture_output=True, text=True).stdout == "-1"


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_nan_inputs_are_refused_under_fast_math(tmp_path, rotor_map):
    """-ffast-math lets the compiler drop x != x, the header's NaN test until 2026-11-26 (a NaN
    airspeed then returned 2 with the loads at 25 m/s): the test by the bits survives it."""
    write_c_header(rotor_map, tmp_path / "map.h", dtype="double")
    for name, driver in (("d", DRIVER), ("w", WRENCH_DRIVER)):
        (tmp_path / f"{name}.c").write_text(driver)
        subprocess.run([CC, "-std=c99", "-O2", "-ffast-math", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o",
                        str(tmp_path / name), str(tmp_path / f"{name}.c"), "-lm"], check=True, capture_output=True,
                       text=True)
    loads = subprocess.run([str(tmp_path / "d")], input="nan 5 1 0\n900 nan 1 0\n900 5 nan 0\n900 5 1 0\n"
                           "-900 5 1 0\n900 -1 1 0\n900 -1 1 1\n", capture_output=True, text=True,
                           check=True).stdout.split("\n")
    status = [int(line.split()[0]) for line in loads[:7]]
    # a negative rate or airspeed (magnitudes): refused under every policy, as the Python map (the airspeed was
    # clipped to still air, the hover's loads returned with status 2, until 2026-11-28: a user-level audit)
    assert status[:3] == [-1, -1, -1] and status[3] >= 0 and status[4:] == [-1, -1, -1]
    wrench = subprocess.run([str(tmp_path / "w")], input="nan 0 0 0 0 1 500 1 0\n1 0 0 0 nan 1 500 1 0\n"
                            "1 0 0 0 0 1 500 1 0\n", capture_output=True, text=True, check=True).stdout.split("\n")
    status = [int(line.split()[0]) for line in wrench[:3]]
    assert status[:2] == [-1, -1] and status[2] >= 0


def test_a_map_of_descent_only_gives_hover_at_any_incidence(tmp_path):
    """At airspeed 0 (up to 1e-6 m/s) the incidence names the same still air: a map whose incidence axis leaves
    out 0 (descent only, 90-180 deg) refused hover (V = 0, incidence 0) under "raise" and the C
    ERROR policy, and gave it outside and flagged under "clip" (a descent audit, 2026-11-26). It
    is the map's airspeed-0 row, inside, at every incidence and in every path (flagged as the
    cell at 90 deg is: this coarse grid's first airspeed cell holds the vortex ring)."""
    prop = pm.load_propeller("apce_8x6")
    rm = RotorMap(build_map(prop, pm.default_params("apce_8x6"), np.array([3000.0, 6000.0, 9000.0]) * RPM,
                            np.array([0.0, 5.0, 10.0]), np.radians([90.0, 135.0, 180.0]), n_check=0))
    om = 6000.0 * RPM
    ref = rm.loads(om, 0.0, math.pi / 2)
    for beta in (0.0, 0.3, math.pi):
        for out_of_grid in ("raise", "clip", "nan"):
            ml = rm.loads(om, 0.0, beta, out_of_grid=out_of_grid)
            assert ml.inside and ml.flagged == ref.flagged and ml.thrust == ref.thrust and ml.torque == ref.torque
        batch = rm.loads(np.full(2, om), np.zeros(2), np.full(2, beta))
        assert np.all(batch.inside) and np.all(batch.thrust == ref.thrust)
    w = rm.wrench([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], om)
    assert w.loads.inside and w.force[2] == pytest.approx(float(ref.thrust), rel=1e-12)
    for vz in (1e-9, -1e-9):  # (a simulator's rest is rarely exactly 0: up to 1e-6 m/s is still air)
        w = rm.wrench([0.0, 0.0, vz], [0.0, 0.0, 1.0], om)
        assert w.loads.inside and w.force[2] == pytest.approx(float(ref.thrust), rel=1e-6)
    for out_of_grid in ("raise", "clip", "nan"):  # (a NaN incidence at rest is refused, as anywhere: a review)
        with pytest.raises(ValueError, match="incidence must not be NaN"):
            rm.loads(om, 0.0, float("nan"), out_of_grid=out_of_grid)
    with pytest.raises(ValueError, match="incidence = 0.2 is outside"):  # (moving air: the axis holds)
        rm.loads(om, 1.0, 0.2)
    if CC is not None:
        exe = _compile(tmp_path, rm, "double")
        out = subprocess.run([str(exe)], input=f"{om!r} 0 0 2\n{om!r} 1 0 2\n", capture_output=True, text=True,
                             check=True).stdout.split("\n")
        status, thrust = int(out[0].split()[0]), float(out[0].split()[1])
        assert status == int(ref.flagged) and thrust == pytest.approx(float(ref.thrust), rel=1e-12)  # (not 2: inside)
        assert int(out[1].split()[0]) == -1


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_tiny_velocities_and_single_precision_pi_in_c_and_python(tmp_path):
    """A review, 2026-11-27: on a map whose airspeed axis starts above 0 (clipped there), a hub
    velocity below 1e-162 m/s had its speed and e_ip underflow: the C wrench took still air's
    incidence (Fz 0.8% off Python's) and both dropped the drag from the force (-Fx / D 0 instead of
    1). Single precision's pi (8.7e-8 rad above pi) was outside the grid in C and RotorMap.loads; so
    was an airspeed an ulp beyond an end of the axis."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    rm = RotorMap(build_map(prop, params, np.array([5000.0, 8000.0]) * RPM, np.array([2.0, 8.0, 15.0]),
                            np.radians(np.linspace(0, 180, 7)), params_label=params.label, n_check=0))
    write_c_header(rm, tmp_path / "map.h", dtype="double")
    (tmp_path / "w.c").write_text(WRENCH_DRIVER)
    exe = tmp_path / "w"
    subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(exe),
                    str(tmp_path / "w.c"), "-lm"], check=True, capture_output=True, text=True)
    rows = [((s, 0.0, 0.0), (0.0, 0.0, 1.0)) for s in (1e-150, 1e-160, 1e-200, 1e-320)]
    rows += [((-1.38e-321, -6.02e-321, -5.24e-322), (1.78192639, -1.15807171, -0.31791111))]
    stdin = "".join(" ".join(repr(float(x)) for x in v + a) + " 700.0 1 0\n" for v, a in rows)
    out = np.array([line.split() for line in subprocess.run([str(exe)], input=stdin, capture_output=True, text=True,
                                                            check=True).stdout.splitlines()], dtype=float)
    for (v, a), o in zip(rows, out):
        one = rm.wrench(list(v), list(a), 700.0, out_of_grid="clip")
        arr = rm.wrench(np.array([v]), np.array([a]), np.array([700.0]), out_of_grid="clip")
        np.testing.assert_allclose(o[1:4], one.force, rtol=1e-12, atol=1e-13)
        np.testing.assert_allclose(arr.force[0], one.force, rtol=1e-12, atol=1e-13)
        if v[1] == 0.0:  # along x: the drag along -x, the whole of it
            assert float(one.loads.drag) > 0.05 and -one.force[0] / float(one.loads.drag) == pytest.approx(1.0, 1e-12)
    # single precision's pi: on the incidence axis's end in C and in Python (under "raise" too)
    (tmp_path / "driver.c").write_text(DRIVER)
    subprocess.run([CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-o", str(tmp_path / "d"),
                    str(tmp_path / "driver.c"), "-lm"], check=True, capture_output=True, text=True)
    pi32 = float(np.float32(np.pi))
    res = subprocess.run([str(tmp_path / "d")], input=f"{600.0!r} 8.0 {pi32!r} 2\n{600.0!r} 8.0 {math.pi!r} 2\n",
                         capture_output=True, text=True, check=True).stdout.splitlines()
    c32, c64 = (np.array(r.split(), dtype=float) for r in res)
    assert c32[0] in (0, 1) and np.array_equal(c32, c64)
    for L in (rm.loads(600.0, 8.0, pi32), rm.loads(600.0, 8.0, np.float32(np.pi), out_of_grid="clip"),
              rm.loads(np.array([600.0]), 8.0, np.deg2rad(np.array([180.0], dtype=np.float32)))):
        assert bool(np.all(L.inside)) and np.all(L.thrust == rm.loads(600.0, 8.0, math.pi).thrust)
    # an airspeed an ulp beyond an end of the axis (|V| of a velocity, rounded: a mutation audit, 2026-11-28) is on
    # it in C and in Python, under the raising policy too; a thousandth beyond is outside
    for end, out in ((15.0, 15.0 * (1 + 1e-3)), (2.0, 2.0 * (1 - 1e-3))):
        near = float(np.nextafter(end, out))
        lines = "".join(f"600.0 {x!r} 1.0 2\n" for x in (near, end, out))
        res = subprocess.run([str(tmp_path / "d")], input=lines, capture_output=True, text=True,
                             check=True).stdout.splitlines()
        c_near, c_end = (np.array(r.split(), dtype=float) for r in res[:2])
        assert c_near[0] in (0, 1) and np.array_equal(c_near, c_end) and float(res[2].split()[0]) == -1
        for L in (rm.loads(600.0, near, 1.0), rm.loads(np.array([600.0]), near, 1.0)):
            assert bool(np.all(L.inside)) and np.all(L.thrust == rm.loads(600.0, end, 1.0).thrust)
        with pytest.raises(ValueError, match="airspeed"):
            rm.loads(600.0, out, 1.0)


@pytest.mark.parametrize("dtype", ["float", "double"])
def test_the_headers_table_holds_the_maps_values_to_the_last_bit(tmp_path, rotor_map, dtype):
    """The table as printed reads back as the map's own (float32 or float64) values, every one
    exactly: 9 significant digits for a float, 17 for a double (with 7, 212 of 448 floats of a
    small map came back different, inside the C comparison's 1e-6: a mutation audit, 2026-11-27)."""
    import re

    write_c_header(rotor_map, tmp_path / "map.h", dtype=dtype)
    text = (tmp_path / "map.h").read_text()
    body = re.search(r"_table\[(\d+)\] = \{(.*?)\};", text, re.S)
    values = np.array([float(v.rstrip("f")) for v in re.findall(r"[-+0-9.eE]+f?", body.group(2))])
    want = rotor_map._table.astype(np.float32 if dtype == "float" else np.float64).ravel()
    assert int(body.group(1)) == values.size == want.size
    got = values.astype(np.float32) if dtype == "float" else values
    assert np.array_equal(got, want)
