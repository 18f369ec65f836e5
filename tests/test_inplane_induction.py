"""The skewed wake's in-plane induced velocity (RotorOptions.inplane_induction, docs/models.md).

Its source checked by Biot-Savart integration of the skewed ring-vortex wake (W. Castles and
J. H. De Leeuw, NACA Report 1184, 1954); its limits in the solver (nothing in axial flow or
hover; the blades' in-plane airspeed 3/2 of the flight's at small skew, so the in-plane force
too); the kernel against the NumPy reference is in tests/test_solver_roots.py. Rotor: UIUC
apce_8x6 (APC PE0 geometry) with its calibrated set.
"""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core._momentum import inplane_induction_numpy
from propmap.core.derivatives import differentiable
from propmap.identify import FitOptions, LoadData, fit_loads
from propmap.io.params_file import read_params, write_params


def _skewed_cylinder_velocity(P, chi, nth=96, ds=0.025, smax=24.0, above=False):
    """Velocity at points P (M, 3) [units of the cylinder's strength gamma] induced by a
    semi-infinite cylinder of unit radius made of rings parallel to the disk z = 0, with
    gamma per unit length along its axis, which leaves the disk downward (``above``: upward,
    the windmill-brake state's wake) skewed by chi towards +x; the rings' sense makes a
    downwash (-z) at the centre. Biot-Savart over straight segments."""
    th = np.linspace(0.0, 2 * np.pi, nth + 1)
    out = np.zeros_like(P)
    for s in np.arange(ds / 2, smax, ds):  # s: distance along the axis
        c = np.array([s * math.sin(chi), 0.0, (s if above else -s) * math.cos(chi)])
        pts = c + np.stack([np.cos(th), -np.sin(th), np.zeros_like(th)], 1)  # clockwise from above: downwash
        a, b = pts[:-1], pts[1:]
        r1 = P[:, None, :] - a[None]
        r2 = P[:, None, :] - b[None]
        cr = np.cross(r1, r2)
        n1 = np.linalg.norm(r1, axis=2)
        n2 = np.linalg.norm(r2, axis=2)
        dot = np.einsum("ij,mij->mi", b - a, r1 / n1[..., None] - r2 / n2[..., None])
        out += ds / (4 * np.pi) * np.sum(cr * (dot / np.einsum("mij,mij->mi", cr, cr))[..., None], axis=1)
    return out


@pytest.mark.parametrize("chi_deg", [30.0, 60.0])
def test_the_skewed_wake_induces_v_tan_half_chi_in_plane_inside_and_nothing_outside(chi_deg):
    """The formula's source: averaged over the azimuth at a radius inside the cylinder, the
    normal velocity is gamma / 2 = v (Coleman's result, momentum theory's value) and the
    in-plane one v tan(chi / 2) downstream; outside the cylinder both average to zero, so
    that nested cylinders (a loading varying along the radius) give each annulus its own v
    times tan(chi / 2)."""
    chi = math.radians(chi_deg)
    psi = np.radians(np.arange(0.0, 360.0, 30.0))
    for r, inside in ((0.5, True), (1.6, False)):
        P = np.stack([r * np.cos(psi), r * np.sin(psi), np.zeros_like(psi)], 1)
        u = _skewed_cylinder_velocity(P, chi).mean(axis=0)
        v = 0.5 if inside else 0.0
        assert u[2] == pytest.approx(-v, abs=2e-3)  # downwash
        assert u[0] == pytest.approx(v * math.tan(chi / 2), abs=2e-3)
        assert abs(u[1]) < 1e-9
    # a wake leaving above the disk (the flow through it upward) induces the opposite in-plane velocity,
    # upstream: where propmap's u_x, which keeps the sign of v, departs from the model (docs/models.md)
    P = np.stack([0.5 * np.cos(psi), 0.5 * np.sin(psi), np.zeros_like(psi)], 1)
    u = _skewed_cylinder_velocity(P, chi, above=True).mean(axis=0)
    assert u[0] == pytest.approx(-0.5 * math.tan(chi / 2), abs=2e-3)
    # propmap's closed form is v tan(chi / 2), tan chi = Vs / |UP|, UP = Vc + v, without the angle (Vc >= 0)
    v, Vs, UP = 3.0, 4.0, np.array([5.0, 3.0 + 1e-9, 3.0])
    np.testing.assert_allclose(inplane_induction_numpy(v, Vs, UP - v), v * np.tan(np.arctan2(Vs, np.abs(UP)) / 2),
                               rtol=1e-12)
    assert inplane_induction_numpy(v, 0.0, UP - v).tolist() == [0.0] * 3  # axial flow
    assert inplane_induction_numpy(v, 1e-6, 0.0) == pytest.approx(0.5e-6, rel=1e-6)  # small skew in hover: Vs / 2
    assert float(inplane_induction_numpy(0.0, 0.0, 0.0)) == 0.0
    # in descent the skew of a hovering disk at the same in-plane speed (W = v): continuous at Vc = 0
    hover = v * Vs / (math.hypot(Vs, v) + v)
    np.testing.assert_allclose(inplane_induction_numpy(v, Vs, np.array([-1.0, -4.0, -40.0, 0.0])), hover, rtol=1e-12)


@pytest.fixture(scope="module")
def rotor():
    """The APC 8x6E with its calibrated set without the option (the cambered default has it)."""
    p = pm.default_params("apce_8x6")
    assert p.inplane_induction and not pm.preset("gill2017-apc").inplane_induction  # the defaults
    return pm.load_propeller("apce_8x6"), p.replace(inplane_induction=False)


def test_nothing_changes_in_axial_flow_and_hover(rotor):
    prop, p = rotor
    q = p.replace(inplane_induction=True)
    om = np.linspace(3000, 12000, 7) * math.pi / 30
    for V, inc in ((0.0, 0.0), (8.0, 0.0), (8.0, math.pi), (0.0, math.pi / 2)):
        a, b = (pm.rotor_loads(prop, s, om, V, inc) for s in (p, q))
        for k in ("thrust", "torque", "drag", "rolling_moment", "v_i_mean"):
            np.testing.assert_array_equal(getattr(b, k), getattr(a, k))


def test_at_small_skew_the_blades_meet_three_halves_of_the_in_plane_airspeed(rotor):
    """u_x -> Vs / 2 as the skew vanishes, and the in-plane force is linear in the blades'
    in-plane airspeed there: D with the option -> 1.5 D without, at any incidence, while the
    thrust changes only to second order; at speed the ratio falls as the skew grows."""
    prop, p = rotor
    q = p.replace(inplane_induction=True)
    om = 6000 * math.pi / 30
    for inc in (math.pi / 2, math.radians(60), math.radians(120), math.radians(150)):
        a, b = (pm.rotor_loads(prop, s, om, 1e-3, inc) for s in (p, q))
        assert float(b.drag / a.drag) == pytest.approx(1.5, rel=1e-4)
        assert float(b.thrust / a.thrust) == pytest.approx(1.0, abs=1e-8)
    mu = np.array([0.05, 0.1, 0.2])
    a, b = (pm.rotor_loads(prop, s, np.full(3, om), mu * om * prop.radius, math.pi / 2) for s in (p, q))
    ratio = b.drag / a.drag
    assert np.all(np.diff(ratio) < 0) and np.all(ratio > 1.1)
    # regression values (2026-11-25, calibrated apce_8x6 at 6000 rpm edgewise): D ratio and the thrust's
    np.testing.assert_allclose(ratio, [1.458, 1.353, 1.168], atol=0.005)
    np.testing.assert_allclose(b.thrust / a.thrust, [1.0035, 1.0108, 1.0192], atol=0.002)


def test_the_reverse_flow_radius_takes_the_blades_in_plane_airspeed(rotor):
    """The retreating blade meets V sin(beta) + u_x - Omega r: reverse flow inside (V sin beta +
    u_x) / Omega, with u_x at the mean inflow (the flag's approximation of the annuli's own);
    without the option V sin(beta) / Omega, and 0 in axial flow either way."""
    prop, p = rotor
    q = p.replace(inplane_induction=True)
    om = np.array([300.0, 600.0, 600.0, 600.0, 600.0])
    V = np.array([8.0, 8.0, 20.0, 8.0, 14.0])  # the last: V sin(beta) / Omega just inside the hub, 0.0233 m
    b = np.radians([90.0, 60.0, 120.0, 0.0, 90.0])
    a, r = (pm.rotor_loads(prop, s, om, V, b) for s in (p, q))
    Vs, Vc = V * np.sin(b), V * np.cos(b)
    Vs[3] = 0.0
    np.testing.assert_allclose(a.reverse_flow_radius, Vs / om, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(r.reverse_flow_radius, (Vs + inplane_induction_numpy(r.v_i_mean, Vs, Vc)) / om,
                               rtol=1e-12, atol=1e-15)
    moving = Vs > 0
    assert np.all(r.reverse_flow_radius[moving] > 1.05 * a.reverse_flow_radius[moving])
    assert r.reverse_flow_radius[3] == 0.0
    np.testing.assert_array_equal(r.reverse_flow, r.reverse_flow_radius > prop.r_hub)
    assert np.any(r.reverse_flow & ~a.reverse_flow)  # a point the free stream alone would not flag


def test_derivatives_with_the_uniform_inflow_and_a_fit_that_uses_them(rotor, tmp_path):
    """Implicit derivatives with the uniform inflow, a linear inflow, swirl or both
    (tests/test_derivatives.py, test_linear_inflow_derivatives.py and test_swirl.py check them
    against differences of the solver): the fits take them. A fit of loads at incidence
    recovers the set it was made with."""
    prop, p = rotor
    q = p.replace(inplane_induction=True)
    for other in (q, q.replace(inflow="pitt-peters"), q.replace(swirl=True),
                  q.replace(inflow="pitt-peters", swirl=True)):
        assert differentiable(other, ("cl_alpha",))
        # and rotor_loads gives them: a steeper lift slope makes more thrust in oblique climb
        d = pm.rotor_loads(prop, other, 600.0, 5.0, math.radians(30.0), derivatives=("cl_alpha",))
        assert 0.0 < float(d.derivative("thrust", "cl_alpha")) < math.inf
    inc = np.radians(np.repeat([0.0, 30.0, 60.0, 90.0], 4))
    V = np.tile([2.0, 5.0, 8.0, 11.0], 4)
    om = np.full(V.size, 6000 * math.pi / 30)
    r = pm.rotor_loads(prop, q, om, V, inc)
    data = LoadData(om, V, inc, {"thrust": r.thrust, "torque": r.torque, "drag": r.drag},
                    np.full(V.size, "all", dtype=object), "synthetic")
    fit = fit_loads(data, prop, base=q.replace(cl_alpha=0.8 * q.cl_alpha),
                    options=FitOptions(names=("cl_alpha",), prior=False))
    assert fit.params.cl_alpha == pytest.approx(q.cl_alpha, rel=1e-6)
    assert fit.params.inplane_induction
    # the parameter file carries it either way; a cambered file without the key gets the generic set's (on),
    # with the warning that names the keys taken from it
    path = tmp_path / "p.toml"
    for on in (True, False):
        write_params(path, q.replace(inplane_induction=on))
        assert read_params(path).inplane_induction is on
    path.write_text("\n".join(line for line in path.read_text().splitlines() if "inplane_induction" not in line))
    with pytest.warns(UserWarning, match="inplane_induction not in the file: taken from the generic set"):
        assert read_params(path).inplane_induction is True
    # the paper's model without the key: off (the paper's inflow), without a warning
    import warnings

    path.write_text('section_model = "gill2017"\ncl1 = 5.0\ncl2 = 1.0\ncd = 0.02\nalpha0_deg = 20.0\n')
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert read_params(path).inplane_induction is False
