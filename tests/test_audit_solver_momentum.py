"""Mutation audit of core/solver.py (Discretization's checks, the argument checks, the spin-up's
scaling, the dynamic stall's cusp warning, the solver error's message, rotor_loads' fields) and
core/_momentum.py (Glauert's mass flow, the empirical descent curve, the skewed wake, the linear
inflow gradients, the swirl's target): each test names the mutant it kills."""

import math
import re
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.core import _momentum as mo
from propmap.core import solver as so
from propmap.core.air import Air
from propmap.core.units import RPM

RHO = 1.225
DISC = pm.Discretization(16, 8)


@pytest.fixture(scope="module")
def prop(apc8x6):
    return apc8x6


@pytest.fixture(scope="module")
def params(apc_params):
    return apc_params


def _leishman(k, shift=0.013):
    """v / v_h of the empirical curve (Leishman 2006, Ch. 2) with kappa = 1 and propmap's shift."""
    return 1.0 + (1.125 - shift) * k - 1.372 * k**2 + 1.718 * k**3 - 0.655 * k**4


# ---------------------------------------------------------------- _momentum: the empirical descent curve


def test_empirical_curve_meets_hover_and_the_windmill_brake_branch():
    """Mutants M4 (no shift), M5 (C2 changed): the curve's value is 1 at k = 0 and meets Glauert's
    windmill-brake branch, v / v_h = 1, at k = 2; at k = 1 it is Leishman's 1.816 less the shift."""
    def f(k):
        return 1.0 + k * (mo.EMPIRICAL_C1 + k * (mo.EMPIRICAL_C2 + k * (mo.EMPIRICAL_C3 + k * mo.EMPIRICAL_C4)))
    assert f(0.0) == 1.0
    assert f(2.0) == pytest.approx(1.0, abs=1e-12)
    assert f(1.0) == pytest.approx(1.816 - 0.013, abs=1e-12)
    assert f(1.0) == pytest.approx(_leishman(1.0), abs=1e-12)


@pytest.mark.parametrize("k", [1e-3, 0.2, 0.5, 1.0, 1.5, 1.9, 2.0])
def test_empirical_k_inverts_the_curve(k):
    """Mutants M6 (one Newton step), M20 (start at k = r): empirical_k(f(k) / k) gives k back."""
    r = _leishman(k) / k
    assert mo.empirical_k(r) == pytest.approx(k, rel=1e-9)


def test_axial_mass_flow_on_the_curve_in_axial_descent():
    """Mutant M9 (v_h^2 / d): at k = 1 (v_h = d = 10 m/s, v = f(1) d) the mass-flow velocity is
    v_h^2 / v, so that dT = 4 pi rho r v W is 4 pi rho r v_h^2; Glauert's |Vc + v| in climb and
    hover, and on the windmill-brake branch (v <= d / 2)."""
    d = 10.0
    v = _leishman(1.0) * d
    w = mo.axial_mass_flow(v, -d, 0.0)
    assert w == pytest.approx(d * d / v, rel=1e-9)
    assert v * w == pytest.approx(d * d, rel=1e-9)  # the hover thrust of v_h = d
    assert mo.axial_mass_flow(3.0, 2.0, 0.0) == 5.0 and mo.axial_mass_flow(3.0, 0.0, 4.0) == 3.0
    assert mo.axial_mass_flow(4.0, -10.0, 0.0) == 6.0  # windmill brake: Glauert's |Vc + v|


def test_axial_mass_flow_switches_to_the_curve_just_above_half_the_descent_rate():
    """Mutant M7 (switch at v = 0.6 d): at v = 0.55 d the curve's k solves f(k)/k = 0.55, not
    Glauert's |Vc + v| = 0.45 d; at v = d / 2 both give d / 2 (continuous)."""
    d = 10.0
    v = 0.55 * d
    k = mo.empirical_k(v / d)
    assert _leishman(k) / k == pytest.approx(0.55, rel=1e-9)
    w = mo.axial_mass_flow(v, -d, 0.0)
    assert w == pytest.approx((d / k) ** 2 / v, rel=1e-9)
    assert abs(w - 0.45 * d) > 0.1
    assert mo.axial_mass_flow(0.5 * d, -d, 0.0) == pytest.approx(0.5 * d, rel=1e-12)


def test_axial_mass_flow_fades_with_the_square_of_the_in_plane_ratio():
    """Mutant M8 (exp(-s) for exp(-s^2)): at Vs = 2 v the empirical part keeps exp(-4) of its
    difference from Glauert's."""
    d = 10.0
    v = _leishman(1.0) * d
    glauert = v - d
    w = mo.axial_mass_flow(v, -d, 2.0 * v)
    assert w == pytest.approx(glauert + (d * d / v - glauert) * math.exp(-4.0), rel=1e-9)


def test_axial_mass_flow_near_hover_follows_the_curve_to_high_ratios():
    """Mutant M18 (hover ratio 1e3): at v / d = 1e4 the curve still holds (v_h = d / k, k ~ 1e-4),
    1.2e-4 below Glauert's v - d; beyond 1e8 its first order, v - 2 C1 d (Glauert's until 2026-12-01)."""
    d = 1e-3
    v = 1e4 * d
    k = mo.empirical_k(v / d)
    w = mo.axial_mass_flow(v, -d, 0.0)
    assert w == pytest.approx((d / k) ** 2 / v, rel=1e-9)
    assert abs(w / (v - d) - 1.0) > 5e-5
    assert mo.axial_mass_flow(2e8 * d, -d, 0.0) == pytest.approx(2e8 * d - 2 * mo.EMPIRICAL_C1 * d, rel=1e-15)


# ---------------------------------------------------------------- _momentum: Glauert's mass flow, the wake


def test_momentum_thrust_is_glauerts_mass_flow_and_gives_the_hover_inflow():
    """Mutant M3 ((Vc + v)(Vc - v)): mom_fac v sqrt(Vs^2 + (Vc + v)^2); in hover, integrated over the
    disk (mom_fac = 4 pi rho y), T = 2 rho A v^2, so v = sqrt(T / (2 rho A))."""
    assert mo.momentum_thrust(2.0, 1.5, 3.0, 1.0) == pytest.approx(1.5 * 2.0 * math.sqrt(9.0 + 9.0), rel=1e-14)
    R, v = 0.1, 4.0
    y = np.linspace(0.0, R, 20001)
    dT = mo.momentum_thrust(v, 4 * np.pi * RHO * y, 0.0, 0.0)
    T = float(np.sum(0.5 * (dT[1:] + dT[:-1]) * np.diff(y)))
    assert math.sqrt(T / (2 * RHO * math.pi * R**2)) == pytest.approx(v, rel=1e-8)


def test_inplane_induction_limits():
    """Mutants M1 (W = Vc + v in descent), M2 (no |W| in the denominator): u_x = v tan(chi / 2) is 0
    in axial flow, Vs / 2 at small skew in hover, v edgewise at W = 0, and in descent the hover
    disk's skew (W = v)."""
    assert mo.inplane_induction(5.0, 0.0, 3.0) == 0.0
    assert mo.inplane_induction(5.0, 1e-4, 0.0) == pytest.approx(0.5e-4, rel=1e-6)
    assert mo.inplane_induction(0.0, 2.0, 0.0) == 0.0
    chi = math.atan2(3.0, 4.0)
    assert mo.inplane_induction(4.0, 3.0, 10.0) == pytest.approx(4.0 * math.tan(0.5 * math.atan2(3.0, 14.0)), rel=1e-12)
    assert mo.inplane_induction(4.0, 3.0, -4.0) == pytest.approx(4.0 * math.tan(0.5 * chi), rel=1e-12)
    np.testing.assert_allclose(mo.inplane_induction_numpy(np.array([4.0]), 3.0, -4.0), [4.0 * math.tan(0.5 * chi)])


def test_skew_inflow_ratio_takes_the_hover_disk_in_descent():
    """Mutant M10 (Vc + v_mean in descent): (Vc + v) / (Omega R) for Vc >= 0, v / (Omega R) below."""
    assert mo.skew_inflow_ratio(2.0, 3.0, 100.0) == pytest.approx(0.05)
    assert mo.skew_inflow_ratio(-2.0, 3.0, 100.0) == pytest.approx(0.03)


def test_drees_gradients_against_their_formula():
    """Mutants M11 (3/4), M12 (k_y = +2 mu), M21 (1.6 mu^2), M13 (mu not held at 0.5): Drees's
    k_x = (4/3)(1 - cos chi - 1.8 mu^2)/sin chi and k_y = -2 mu, chi = atan2(mu, lambda)."""
    mu, lam = 0.3, 0.05
    chi = math.atan2(mu, lam)
    kx, ky = mo.inflow_gradients(mu, lam, mo.INFLOW_DREES)
    assert kx == pytest.approx((4 / 3) * (1 - math.cos(chi) - 1.8 * mu * mu) / math.sin(chi), rel=1e-12)
    assert ky == pytest.approx(-0.6, rel=1e-14)
    kx2, ky2 = mo.inflow_gradients(2.0, 0.05, mo.INFLOW_DREES)
    chi2 = math.atan2(2.0, 0.05)
    assert ky2 == -1.0  # held at mu = 0.5
    assert kx2 == pytest.approx((4 / 3) * (1 - math.cos(chi2) - 1.8 * 0.25) / math.sin(chi2), rel=1e-12)
    assert mo.inflow_gradients(0.0, 0.05, mo.INFLOW_DREES) == (0.0, 0.0)
    assert mo.inflow_gradients(0.3, 0.05, mo.INFLOW_UNIFORM) == (0.0, 0.0)


def test_drees_kx_is_held_non_negative():
    """Mutant M19 (no clip): at small skew and mu = 0.3 Drees's k_x is negative, held at 0."""
    mu, lam = 0.3, 5.0
    chi = math.atan2(mu, lam)
    assert (1 - math.cos(chi) - 1.8 * mu * mu) < 0
    assert mo.inflow_gradients(mu, lam, mo.INFLOW_DREES)[0] == 0.0


def test_pitt_peters_gradient_and_the_mirrored_skew():
    """Mutants M14 (15 pi / 23), M15 (atan2(mu, lambda) without |lambda|): k_x = (15 pi / 32)
    tan(chi / 2), the same at -lambda (the mirrored skew pi - chi)."""
    mu, lam = 0.2, 0.1
    kx, ky = mo.inflow_gradients(mu, lam, mo.INFLOW_PITT_PETERS)
    assert kx == pytest.approx(15 * math.pi / 32 * math.tan(0.5 * math.atan2(mu, lam)), rel=1e-14) and ky == 0.0
    assert mo.inflow_gradients(mu, -lam, mo.INFLOW_PITT_PETERS) == (kx, ky)
    assert mo.inflow_gradients(mu, -lam, mo.INFLOW_DREES) == mo.inflow_gradients(mu, lam, mo.INFLOW_DREES)


def test_swirl_target_is_the_angular_momentum_balance():
    """Mutant M16 (no y): u = v dQ / (y dT); 0 where dT = 0."""
    assert mo.swirl_target(2.0, 10.0, 0.5, 0.05) == pytest.approx(2.0 * 0.5 / (0.05 * 10.0), rel=1e-14)
    assert mo.swirl_target(2.0, 0.0, 0.5, 0.05) == 0.0


# ---------------------------------------------------------------- solver: checks


def test_discretization_ranges_and_types():
    """Mutants S1 (n >= 1), S2 (n < hi), S3 (no integer check), S4 (48.0 kept a float), S5 (n_radial
    up to 1000): counts in [2, 10000] and [2, 1000], whole numbers kept as int."""
    for bad in ({"n_radial": 1}, {"n_azimuth": 1}, {"n_radial": 10001}, {"n_azimuth": 1001}, {"n_radial": 2.5}):
        name = next(iter(bad))
        with pytest.raises(ValueError, match=rf"{name} must be an integer in \[2, "):
            pm.Discretization(**bad)
    d = pm.Discretization(n_radial=10000, n_azimuth=1000)
    assert (d.n_radial, d.n_azimuth) == (10000, 1000)
    d = pm.Discretization(48.0, np.int64(8))
    assert type(d.n_radial) is int and type(d.n_azimuth) is int and d == pm.Discretization(48, 8)
    assert pm.Discretization(2, 2).n_radial == 2 and pm.Discretization(5000).n_radial == 5000


def test_model_argument_checks_name_the_argument(prop, params):
    """Mutants S14, S15, S16, S18, S17: TypeErrors for a wrong propeller, discretization, air, a set's
    name (with the hint); model_air keeps a given air."""
    with pytest.raises(TypeError, match="propeller must be a Propeller.*got str"):
        so.check_model_args("apce_8x6", params)
    with pytest.raises(TypeError, match="discretization must be a propmap.Discretization, got int"):
        so.check_model_args(prop, params, discretization=48)
    with pytest.raises(TypeError, match="resolve it with propmap.resolve_params"):
        so.check_model_args(prop, "generic")
    with pytest.raises(TypeError, match=r"air must be a propmap.Air, got float"):
        so.check_model_args(prop, params, air=1.2)
    with pytest.raises(TypeError, match=r"air must be a propmap.Air, got float"):
        so.check_air(1.2)
    air = Air(rho=1.0)
    assert so.model_air(params, air) is air and so.model_air(params) is params.air
    so.check_model_args(prop, params, params.air, DISC)  # no error


def test_rotor_loads_uses_the_air_given(prop, params):
    """Mutants S32 (air argument ignored), S34 (rho field from params.air): thrust scales with the
    density given, and the result carries it."""
    om, V, b = 8000 * RPM, 5.0, 0.3
    a = pm.rotor_loads(prop, params, om, V, b, discretization=DISC)
    c = pm.rotor_loads(prop, params, om, V, b, air=Air(rho=0.6125), discretization=DISC)
    assert c.rho == 0.6125 and a.rho == params.air.rho
    assert float(c.thrust) == pytest.approx(float(a.thrust) * 0.6125 / params.air.rho, rel=0.02)


# ---------------------------------------------------------------- solver: the spin-up's scaling


def test_spin_up_in_still_air_scales_loads_and_inflows(prop, params):
    """Mutants S9 (v_i_mean by f^2), S11 (radial v_i by f^2), S12 (radial densities by f), S30 (omega
    reported as 0.1), S31 (v_h from the unscaled thrust): at Omega = 0.05 rad/s in still air the
    loads are a quarter of those at 0.1 rad/s and the inflows half."""
    ref = pm.rotor_loads(prop, params, so.OMEGA_MIN, 0.0, 0.0, discretization=DISC, radial=True)
    half = pm.rotor_loads(prop, params, 0.5 * so.OMEGA_MIN, 0.0, 0.0, discretization=DISC, radial=True)
    assert float(ref.thrust) > 0
    assert float(half.omega) == 0.5 * so.OMEGA_MIN
    for f in ("thrust", "torque"):
        assert float(getattr(half, f)) == pytest.approx(0.25 * float(getattr(ref, f)), rel=1e-12)
    assert float(half.v_i_mean) == pytest.approx(0.5 * float(ref.v_i_mean), rel=1e-12)
    assert float(half.v_h) == pytest.approx(0.5 * float(ref.v_h), rel=1e-9)
    np.testing.assert_allclose(half.v_i, 0.5 * ref.v_i, rtol=1e-12)
    np.testing.assert_allclose(half.dT_dr, 0.25 * ref.dT_dr, rtol=1e-12)
    np.testing.assert_allclose(half.dQ_dr, 0.25 * ref.dQ_dr, rtol=1e-12)
    zero = pm.rotor_loads(prop, params, 0.0, 0.0, 0.0, discretization=DISC)
    assert float(zero.thrust) == 0.0 and float(zero.v_i_mean) == 0.0


def test_spin_up_in_a_flow_holds_the_loads(prop, params):
    """Mutant S8 (scaled in a flow too): a parked rotor in a 5 m/s flow has the loads solved at
    0.1 rad/s."""
    ref = pm.rotor_loads(prop, params, so.OMEGA_MIN, 5.0, 1.0, discretization=DISC)
    slow = pm.rotor_loads(prop, params, 0.02, 5.0, 1.0, discretization=DISC)
    assert float(slow.omega) == 0.02
    assert float(slow.drag) == pytest.approx(float(ref.drag), rel=1e-12) and float(ref.drag) != 0.0
    assert float(slow.thrust) == pytest.approx(float(ref.thrust), rel=1e-12)


def test_derivatives_are_refused_below_the_parked_rate(prop, params):
    """Mutant S27: derivatives need omega >= 0.1 rad/s."""
    with pytest.raises(ValueError, match=r"derivatives need omega >= 0.1 rad/s"):
        pm.rotor_loads(prop, params, 0.05, 0.0, 0.0, discretization=DISC, derivatives=True)


# ---------------------------------------------------------------- solver: packed fields, flags, options


def test_row_fields_map_the_kernel_rows(prop, params):
    """Mutants S6 (n_evaluations from the vortex-ring count), S7 (vortex_ring and multiple_roots
    swapped): a hover point's evaluations are counted; an axial descent at about v_h is flagged
    vortex ring, in one point, a 1-d batch and a 2-d batch alike."""
    p = params.replace(descent="empirical")
    om = 8000 * RPM
    h = pm.rotor_loads(prop, p, om, 0.0, 0.0, discretization=DISC)
    assert int(h.n_evaluations) > DISC.n_radial and not bool(h.vortex_ring)
    V = float(h.v_h)
    d = pm.rotor_loads(prop, p, om, V, math.pi, discretization=DISC)
    assert bool(d.vortex_ring) and 0.45 < float(d.descent_ratio) < 1.5 and int(d.n_evaluations) > DISC.n_radial
    b = pm.rotor_loads(prop, p, np.full((2, 2), om), np.array([[0.0, V], [V, 0.0]]), math.pi, discretization=DISC)
    np.testing.assert_array_equal(b.vortex_ring, [[False, True], [True, False]])
    mh, md = bool(h.multiple_roots), bool(d.multiple_roots)
    np.testing.assert_array_equal(b.multiple_roots, [[mh, md], [md, mh]])
    assert np.all(b.n_evaluations > DISC.n_radial)
    one = pm.rotor_loads(prop, p, [om], [V], [math.pi], discretization=DISC)
    assert bool(one.vortex_ring[0]) and one.multiple_roots[0] == d.multiple_roots


def test_on_failure_and_radial_values_are_refused(prop, params):
    """Mutants S25, S26: on_failure other than 'raise'/'flag' and a radial of 'yes' are ValueErrors."""
    with pytest.raises(ValueError, match="on_failure must be 'raise' or 'flag', got 'ignore'"):
        pm.rotor_loads(prop, params, 800.0, 0.0, 0.0, on_failure="ignore", discretization=DISC)
    with pytest.raises(ValueError, match="radial must be True or False, got 'yes'"):
        pm.rotor_loads(prop, params, 800.0, 0.0, 0.0, radial="yes", discretization=DISC)


# ---------------------------------------------------------------- solver: the dynamic stall's cusp warning


def _cusp(V, Vs, b, wrt):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        so._warn_dynamic_stall_cusp(np.asarray(V, float), np.asarray(Vs, float), np.asarray(b, float), wrt)
    return [str(x.message) for x in w]


def test_dynamic_stall_cusp_warning_where_and_how_many():
    """Mutants S19 (rest counted as axial flow), S20 (airspeed from rest along the axis), S21 (no
    warning for one point): the warning counts the points with no in-plane airspeed whose
    derivatives cross the cusp."""
    assert _cusp([5.0], [0.0], [0.0], ("incidence",))[0].startswith("dynamic_stall: 1 point(s)")
    assert _cusp([0.0], [0.0], [0.0], ("incidence",)) == []  # at rest: no incidence cusp
    assert _cusp([0.0], [0.0], [0.0], ("airspeed",)) == []  # from rest along the axis: no in-plane airspeed
    assert _cusp([0.0], [0.0], [1.0], ("airspeed",))[0].startswith("dynamic_stall: 1 point(s)")
    assert _cusp([5.0, 0.0, 3.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.3], ("incidence", "omega"))[0].startswith(
        "dynamic_stall: 1 point(s)")
    assert _cusp([5.0, 5.0], [0.0, 0.0], [0.0, 0.0], ("omega",)) == []


def test_no_cusp_warning_without_dynamic_stall(prop, params):
    """Mutant S33 (warned with dynamic_stall = 0): axial-flow derivatives of the static section
    give no cusp warning."""
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        pm.rotor_loads(prop, params, 8000 * RPM, 5.0, 0.0, discretization=DISC, derivatives=["incidence"])
    assert not [x for x in w if "dynamic_stall" in str(x.message)]


# ---------------------------------------------------------------- solver: the failure's message


def test_solver_error_names_the_point_annulus_and_reason():
    """Mutants S22 (status not less 1), S23 (omega of the first point), S24 (flat index): the
    message gives the first failed point's multi-index and inputs, the annulus and the reason."""
    y_R = np.array([0.2, 0.4, 0.6, 0.8, 0.95])
    status = np.array([0, 1 + 4 * 3 + 2, 1 + 4 * 0 + 1, 0])
    om, V, b = np.array([100.0, 200.0, 300.0, 400.0]), np.array([1.0, 2.0, 3.0, 4.0]), np.radians([0, 90, 180, 0])
    e = so._solver_error(status, (2, 2), om, V, b, y_R)
    assert isinstance(e, pm.SolverError)
    msg = str(e)
    assert re.search(r"operating point \(np\.int64\(0\), np\.int64\(1\)\)|operating point \(0, 1\)", msg)
    assert "omega=200 rad/s, airspeed=2 m/s, incidence=90 deg" in msg
    assert "annulus r/R=0.8000: the refinement of the bracket did not converge" in msg
    e = so._solver_error(np.array([1 + 4 * 4 + 3]), (1,), om[:1], V[:1], b[:1], y_R)
    assert "r/R=0.9500: the swirl did not balance" in str(e) and f"within {mo.SWIRL_MAX_ITER} root" in str(e)
    assert "no sign change of F found" in str(so._solver_error(np.array([2]), (1,), om, V, b, y_R))


def _fail_point(monkeypatch, point: int, status: int) -> None:
    """The serial kernel made to report a failure (``status``: 1 + 4 annulus + reason) at ``point`` of a batch."""
    from propmap.core import _kernel

    real = _kernel.solve_batch_serial

    def failing(*args):
        real(*args)
        out, counts, flags = args[-4], args[-2], args[-1]
        counts[0, point] = status
        flags[0, point] = False
        out[:, point] = np.nan

    monkeypatch.setattr(_kernel, "solve_batch_serial", failing)


def test_a_failure_at_a_later_point_of_a_batch_raises(prop, params, monkeypatch):
    """Mutant S29 (only the first point's status read): a batch whose second point fails raises
    SolverError naming that point, and with on_failure='flag' returns it unconverged."""
    _fail_point(monkeypatch, 1, 1 + 4 * 2 + 2)
    with pytest.raises(pm.SolverError, match=r"operating point \((np\.int64\()?1\)?,\) .*omega=900 rad/s.*refinement"):
        pm.rotor_loads(prop, params, [800.0, 900.0], 0.0, 0.0, discretization=DISC)
    r = pm.rotor_loads(prop, params, [800.0, 900.0], 0.0, 0.0, discretization=DISC, on_failure="flag")
    np.testing.assert_array_equal(r.converged, [True, False])
    assert r.thrust[0] > 0 and np.isnan(r.thrust[1])


def test_derivatives_without_radial_outputs_match_those_with(prop, params):
    """Mutant S28 (roots not kept for the derivatives): dT/dOmega and dT/dV are the same with and
    without ``radial``, and agree with a central difference."""
    om, V, b = 8000 * RPM, 6.0, 0.8
    a = pm.rotor_loads(prop, params, om, V, b, discretization=DISC, derivatives=True)
    r = pm.rotor_loads(prop, params, om, V, b, discretization=DISC, derivatives=True, radial=True)
    assert a.v_i is None and r.v_i is not None
    for w in ("omega", "airspeed"):
        assert float(a.derivative("thrust", w)) == pytest.approx(float(r.derivative("thrust", w)), rel=1e-12)
    h = 0.5
    dT = (float(pm.rotor_loads(prop, params, om + h, V, b, discretization=DISC).thrust)
          - float(pm.rotor_loads(prop, params, om - h, V, b, discretization=DISC).thrust)) / (2 * h)
    assert float(a.derivative("thrust", "omega")) == pytest.approx(dT, rel=1e-4)


def test_swirl_of_a_parked_rotor_in_a_flow_is_held_at_half_the_blade_speed(prop, params):
    """Mutant M17 (SWIRL_LIMIT 0.9): a parked rotor (0.1 rad/s) and a slowly turning one in an axial
    flow, with swirl, where each annulus' swirl is clipped at 0.5 Omega y: their thrust and torque
    (values of the clean source, 2026-11-29) and no drag in axial flow."""
    p = params.replace(swirl=True)
    for om, V, T, Q in ((0.1, 10.0, -0.23359397512779997, -0.0052211714392293215),
                        (50.0, 15.0, -0.48802658077654026, -0.010505255249897706)):
        r = pm.rotor_loads(prop, p, om, V, 0.0, discretization=DISC)
        assert float(r.thrust) == pytest.approx(T, rel=1e-6) and float(r.torque) == pytest.approx(Q, rel=1e-6)
        assert float(r.drag) == 0.0 and float(r.side_force) == 0.0


def test_a_parked_points_failure_names_the_rate_given(prop, params, monkeypatch):
    """A failure at a parked point (omega below OMEGA_MIN, solved at 0.1 rad/s) names the rate the
    caller gave and says it was solved as parked blades; it named 0.1 rad/s until 2026-11-29 (the
    clamped rate, noticed by the audit of core/solver.py)."""
    _fail_point(monkeypatch, 0, 1 + 4 * 1 + 1)
    with pytest.raises(pm.SolverError, match=r"\(omega=0\.05 rad/s, solved at 0\.1 rad/s as parked blades, "
                                             r"airspeed=5 m/s, .*no sign change"):
        pm.rotor_loads(prop, params, [0.05, 900.0], 5.0, 0.0, discretization=DISC)
    with pytest.raises(pm.SolverError, match=r"\(omega=900 rad/s, airspeed=5 m/s"):
        pm.rotor_loads(prop, params, [900.0, 0.05], 5.0, 0.0, discretization=DISC)
