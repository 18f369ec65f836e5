"""A mutation audit of core/derivatives.py, core/polar.py, core/nodes.py and core/interference.py (2026-11-29): each
test kills a hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.core.derivatives import differentiable

DISC = pm.Discretization(16, 6)


@pytest.fixture(scope="module")
def prop():
    return pm.load_propeller("apce_8x6")


def test_switches_and_text_fields_are_not_differentiable(prop):
    """Mutant D2 (differentiable's ``isinstance(..., float)`` dropped): a switch or a text field is
    not a section constant, so differentiable() says False and rotor_loads refuses it."""
    g = pm.generic_params()
    for name in ("radial_drag", "compressibility", "inplane_induction", "inflow", "descent"):
        assert not differentiable(g, (name,)), name
    assert not differentiable(pm.preset("gill2017-apc"), ("lift_model",))
    assert differentiable(g, ("cl_alpha", "rho", "omega"))
    with pytest.raises(ValueError, match="radial_drag is not a number"):
        pm.rotor_loads(prop, g, 800.0, 5.0, 0.5, discretization=DISC, derivatives=("radial_drag",))


def test_derivatives_true_are_the_three_inputs_only(prop):
    """Mutant D6 (True also differentiating the collective): ``derivatives=True`` gives the
    derivatives with respect to omega, airspeed and incidence (docs/solver.md, Derivatives), the
    collective only when named."""
    r = pm.rotor_loads(prop, pm.generic_params(), 800.0, 5.0, 0.5, discretization=DISC, derivatives=True)
    assert {w for _, w in r.jacobian} == {"omega", "airspeed", "incidence"}
    with pytest.raises(ValueError, match="wrt must be one of airspeed, incidence, omega "):
        r.derivative("thrust", "collective")


def test_derivatives_none_is_no_derivatives(prop):
    """Mutant D7 (None no longer read as no derivatives): rotor_loads takes ``derivatives=None``
    as rotor_wrench does (tests/test_derivatives.py), loads without a Jacobian."""
    r = pm.rotor_loads(prop, pm.generic_params(), 800.0, 5.0, 0.5, discretization=DISC, derivatives=None)
    assert r.jacobian is None or not r.jacobian
    with pytest.raises(ValueError, match="no derivatives"):
        r.derivative("thrust", "omega")


def test_a_parameter_at_its_upper_bound_is_stepped_downward(prop):
    """Mutant D13 (the step recorded as +h where the parameter was stepped down): at the upper
    bound of its range (cl_alpha = 20) the step is downward (docs/solver.md, Derivatives), and
    the derivative still matches a one-sided difference of the solver from below."""
    g = pm.generic_params().replace(cl_alpha=20.0)
    r = pm.rotor_loads(prop, g, 800.0, 5.0, 0.3, discretization=DISC, derivatives=("cl_alpha",))
    h = 1e-3
    lo = pm.rotor_loads(prop, g.replace(cl_alpha=20.0 - h), 800.0, 5.0, 0.3, discretization=DISC)
    lo2 = pm.rotor_loads(prop, g.replace(cl_alpha=20.0 - 2 * h), 800.0, 5.0, 0.3, discretization=DISC)
    for q in ("thrust", "torque"):
        fd = (3 * float(getattr(r, q)) - 4 * float(getattr(lo, q)) + float(getattr(lo2, q))) / (2 * h)
        assert float(r.derivative(q, "cl_alpha")) == pytest.approx(fd, rel=1e-3), q
        assert abs(fd) > 1e-4 * abs(float(getattr(r, q)))  # (a slope that the sign error would show)


def test_polar_refuses_a_negative_mach_number():
    """Mutant P8 (mach's check loosened to > -1): a negative Mach number is an error naming the
    argument and its range (lift_coefficient and drag_coefficient, Raises)."""
    g = pm.generic_params()
    with pytest.raises(ValueError, match=r"mach must be finite and >= 0 everywhere, got -0.2"):
        pm.lift_coefficient(0.1, g, mach=-0.2)
    with pytest.raises(ValueError, match=r"mach must be finite and >= 0 everywhere, got -0.2"):
        pm.drag_coefficient(0.1, 1e5, g, mach=[0.1, -0.2])
    assert np.isfinite(pm.lift_coefficient(0.1, g, mach=0.0))


def test_still_air_slopes_alone_match_differences_of_the_solver(prop):
    """Mutant D16 (no input passes when the slopes at rest are asked alone): still_air_slopes
    (core/vector.py) asks rotor_loads for them alone; the edgewise drag slope (odd in V sin beta)
    and the thrust's mean of the climb and descent slopes match differences of the solver, and
    the slopes asked with the inputs."""
    from propmap.core.derivatives import STILL_AIR
    from propmap.core.vector import still_air_slopes

    g = pm.generic_params()
    s = still_air_slopes(prop, g, 800.0, 0.0, discretization=DISC)
    both = pm.rotor_loads(prop, g, 800.0, 0.0, 0.0, discretization=DISC, derivatives=("airspeed", STILL_AIR))
    for q in ("thrust", "drag", "torque", "rolling_moment"):
        assert float(s[q]) == pytest.approx(float(both.derivative(q, STILL_AIR)), rel=1e-9, abs=1e-12), q
    h = 1e-3
    f0 = pm.rotor_loads(prop, g, 800.0, 0.0, 0.0, discretization=DISC)
    edge = [pm.rotor_loads(prop, g, 800.0, k * h, 0.5 * math.pi, discretization=DISC) for k in (1, 2)]
    fd_drag = (4 * float(edge[0].drag) - float(edge[1].drag) - 3 * float(f0.drag)) / (2 * h)
    assert float(s["drag"]) == pytest.approx(fd_drag, rel=1e-3)
    climb, descent = (pm.rotor_loads(prop, g, 800.0, h, b, discretization=DISC) for b in (0.0, math.pi))
    assert float(s["thrust"]) == pytest.approx((float(climb.thrust) - float(descent.thrust)) / (2 * h), rel=1e-3)


def test_power_derivative_is_the_product_rule(prop):
    """Mutant L1 (dP/domega without its Q term): RotorLoads.derivative("power", "omega") is
    Omega dQ/dOmega + Q, against central differences of P = Q Omega; other inputs Omega dQ/dx."""
    g = pm.generic_params()
    om, V, b = 800.0, 6.0, 0.8
    r = pm.rotor_loads(prop, g, om, V, b, discretization=DISC, derivatives=True)
    h = 1e-4 * om
    a, c = (pm.rotor_loads(prop, g, om + s, V, b, discretization=DISC) for s in (h, -h))
    fd = (float(a.torque) * (om + h) - float(c.torque) * (om - h)) / (2 * h)
    assert float(r.derivative("power", "omega")) == pytest.approx(fd, rel=1e-5)
    assert float(r.derivative("power", "airspeed")) == pytest.approx(om * float(r.derivative("torque", "airspeed")))


def test_derivative_returns_a_new_array(prop):
    """Mutant L2 (the stored array returned): derivative() gives a new array, so that a caller's
    edit does not change the next call's answer."""
    r = pm.rotor_loads(prop, pm.generic_params(), np.array([700.0, 900.0]), 5.0, 0.5, discretization=DISC,
                       derivatives=True)
    d = r.derivative("thrust", "omega")
    first = d.copy()
    d[:] = -1.0
    np.testing.assert_array_equal(r.derivative("thrust", "omega"), first)
    assert np.all(first > 0)


def test_polar_refuses_booleans_among_numbers():
    """Mutant P9 (the bool check dropped): a list mixing numbers and booleans, which NumPy
    would read as floats, is refused naming the argument."""
    g = pm.generic_params()
    with pytest.raises(ValueError, match="alpha must be a number or an array of numbers"):
        pm.lift_coefficient([0.1, True], g)
    with pytest.raises(ValueError, match="reynolds must be a number or an array of numbers"):
        pm.drag_coefficient(0.1, [1e5, False], g)


def test_lift_coefficient_reads_its_default_reynolds_number_from_re_ref():
    """Mutant P11 (the default Reynolds number fixed at 1e5): lift_coefficient's default
    Reynolds number is the set's re_ref (its docstring), where the Reynolds terms vanish."""
    g = pm.generic_params().replace(re_ref=3e5)
    alpha = np.radians([-4.0, 2.0, 6.0])
    np.testing.assert_array_equal(pm.lift_coefficient(alpha, g), pm.lift_coefficient(alpha, g, reynolds=3e5))
    assert not np.allclose(pm.lift_coefficient(alpha, g), pm.lift_coefficient(alpha, g, reynolds=1e5), rtol=1e-4)


def test_polar_errors_name_the_offending_value():
    """Mutant P12 (the error's value taken where the check passed): the message gives the
    value that broke the rule."""
    g = pm.generic_params()
    with pytest.raises(ValueError, match=r"reynolds must be finite and > 0 everywhere, got -3.0"):
        pm.drag_coefficient(0.1, [1e5, 2e5, -3.0], g)
    with pytest.raises(ValueError, match=r"alpha must be finite \[rad\] everywhere, got inf"):
        pm.lift_coefficient([0.1, np.inf], g)


def test_dynamic_stall_reaches_the_element(prop):
    """Mutant P13 (the element's dynamic-stall constant left 0): with Gormont's gamma the rising
    and falling halves give a negative side force and pitching moment edgewise (docs/models.md,
    Dynamic stall), and axial flow is unchanged to the last bit."""
    g = pm.generic_params()
    ds = g.replace(dynamic_stall=1.0)
    edge = pm.rotor_loads(prop, ds, 900.0, 12.0, math.radians(80.0), discretization=DISC)
    static = pm.rotor_loads(prop, g, 900.0, 12.0, math.radians(80.0), discretization=DISC)
    assert float(edge.side_force) < -0.01 and float(edge.pitching_moment) < -0.005
    assert float(static.side_force) == 0.0 and float(edge.thrust) != float(static.thrust)
    axial = [pm.rotor_loads(prop, p, 900.0, 5.0, 0.0, discretization=DISC) for p in (g, ds)]
    assert float(axial[0].thrust) == float(axial[1].thrust)


def test_interference_table_angles_are_taken_modulo_the_mirror_symmetry():
    """Mutant I8 (psi not wrapped into [0, pi]): InterferenceTable reads psi modulo 2 pi and
    mirrored about the wake's plane, so psi, -psi and 2 pi - psi give the same f."""
    from propmap.core.interference import interference_table

    t = interference_table(2.41, 0.0, 1.0)
    chi = np.radians([20.0, 45.0, 75.0])
    psi = np.radians(17.0)
    base = t(chi, psi)
    for other in (-psi, 2 * math.pi - psi, 2 * math.pi + psi):
        np.testing.assert_allclose(t(chi, other), base, rtol=1e-12)
    assert np.all(base > 0)  # a downwash behind
    assert float(t(math.radians(75.0), 0.0)) == pytest.approx(0.75, abs=0.01)  # docs/models.md's table


def test_interference_table_reaches_straight_ahead():
    """Mutant I16 (the psi index held one cell short of 180 deg): at psi = pi (the other disk
    straight ahead of the wake) the table gives the direct evaluation there, the weak upwash of
    docs/models.md's table (-0.045 at 45 deg, 2.41 R ahead)."""
    from propmap.core.interference import interference_table, wake_ratio

    t = interference_table(2.41, 0.0, 1.0)
    for chi in np.radians([21.0, 45.0, 75.0]):  # table nodes (every 3 deg)
        assert float(t(chi, math.pi)) == pytest.approx(wake_ratio(chi, (-2.41, 0.0, 0.0)), rel=1e-9, abs=1e-12)
    assert float(t(math.radians(45.0), math.pi)) == pytest.approx(-0.045, abs=0.002)


def test_hub_loss_constant_is_prandtls(prop):
    """Mutant N2 (the hub-loss constant divided by y, not r_hub): the nodes' hub constant is
    (N_b/2)(y - r_hub)/r_hub, f_hub times sin phi (docs/models.md, Prandtl's tip and hub loss;
    _Nodes); the tip constant (N_b/2)(R - y)/y."""
    from propmap.core.nodes import _nodes

    g = pm.generic_params().replace(hub_loss=True)
    nd = _nodes(prop, 16, 6, g.air, g)
    np.testing.assert_allclose(nd.ch, 0.5 * prop.n_blades * (nd.y - prop.r_hub) / prop.r_hub, rtol=1e-14)
    np.testing.assert_allclose(nd.ct, 0.5 * prop.n_blades * (prop.radius - nd.y) / nd.y, rtol=1e-14)
    off = _nodes(prop, 16, 6, g.air, g.replace(hub_loss=False))
    assert np.all(off.ch == -1.0)


def test_sincos_flapping_damping_uses_its_lift_slope_cl2(prop):
    """Mutant N4 (cl1 taken as every paper set's lift slope): footnote 1's lift C_L = cl2 sin a
    cos a has the slope cl2 at alpha = 0 and no cl1, so a flapping rotor with it (whose flap
    damping scales with the lift slope, core/flapping.py) does not depend on cl1."""
    p = pm.preset("gill2017-apc").replace(lift_model="sincos", flap_compliance=2.0)
    assert float(pm.lift_coefficient(1e-6, p)) / 1e-6 == pytest.approx(p.cl2, rel=1e-6)
    a, b = (pm.rotor_loads(prop, p.replace(cl1=c), 900.0, 10.0, math.radians(70.0), discretization=DISC)
            for c in (5.3, 2.0))
    assert abs(float(a.side_force)) > 1e-3 and abs(float(a.pitching_moment)) > 1e-4  # the blades flap
    for q in ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment"):
        assert float(getattr(a, q)) == float(getattr(b, q)), q


def test_reverse_flow_radius_carries_the_in_plane_induction(prop):
    """Mutant N6 (the flags' in-plane switch left 0): with the skewed wake's in-plane induction
    the reverse-flow radius is (V sin beta + u_x) / Omega, u_x at the mean inflow
    (_flags.point_flags); without it V sin beta / Omega."""
    from propmap.core._momentum import inplane_induction_numpy

    om, V, b = 900.0, 12.0, math.radians(80.0)
    vx, vz = V * math.sin(b), V * math.cos(b)
    on = pm.rotor_loads(prop, pm.generic_params(), om, V, b, discretization=DISC)
    ux = float(inplane_induction_numpy(float(on.v_i_mean), vx, vz))
    assert ux > 0.05 * vx
    assert float(on.reverse_flow_radius) == pytest.approx((vx + ux) / om, rel=1e-12)
    off = pm.rotor_loads(prop, pm.generic_params().replace(inplane_induction=False), om, V, b, discretization=DISC)
    assert float(off.reverse_flow_radius) == pytest.approx(vx / om, rel=1e-12)
