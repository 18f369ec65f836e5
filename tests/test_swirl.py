"""Swirl (RotorOptions.swirl): the annuli's tangential induced velocity from angular momentum.

Checked against an independent solve of the two momentum balances per annulus (thrust and
torque, SciPy's fsolve on the section's own element), against the NumPy reference, and
against the physics it adds: it takes thrust and torque, more with more blades of the same
blade, least where the rotor is lightly loaded, and it is off in the paper's model.
"""

import math

import numpy as np
import pytest
from scipy.optimize import fsolve

import propmap as pm
from propmap.core._physics import NODE_TH, element
from propmap.core._momentum import momentum_thrust
from propmap.core._reference import solve_reference
from propmap.core.polar import _model_constants
from propmap.core.nodes import _nodes

from .conftest import RPM, moved_loads

LOADS = ("thrust", "drag", "torque", "rolling_moment")


def test_swirl_balances_thrust_and_angular_momentum(apc8x6, apc_params):
    # the paper's section (no per-annulus Reynolds constants), no tip loss: per annulus, the
    # blade's thrust and torque equal the axial and angular momentum of the wake,
    # cfac qT(Omega y - u, V + v) = 4 pi rho y v (V + v), cfac qH = 4 pi rho y u (V + v)
    p = apc_params.replace(swirl=True)
    om, V = 9000 * RPM, np.array([0.0, 6.0])
    r = pm.rotor_loads(apc8x6, p, om, V, 0.0, radial=True)
    plain = pm.rotor_loads(apc8x6, apc_params, om, V, 0.0, radial=True)
    nd = _nodes(apc8x6, 48, 16, pm.Air(), p)
    pk = _model_constants(p)
    checked = 0
    for i, Vc in enumerate(V):
        for j in range(0, 48, 6):
            def balances(x, j=j, Vc=Vc):
                v, u = x
                qT, qH = element(om * nd.y[j] - u, Vc + v, nd.theta[j], nd.sin_th[j], nd.cos_th[j], nd.sc[j], 0.0,
                                 0.0, 0.0, *pk)
                W = abs(Vc + v)
                return [nd.cfac[j] * qT - momentum_thrust(v, nd.mfac[j], 0.0, Vc),
                        nd.cfac[j] * qH - nd.mfac[j] * u * W]

            x, info, ok, msg = fsolve(balances, [plain.v_i[i, j], 0.0], xtol=1e-13, full_output=True)
            assert ok == 1, msg
            assert r.v_i[i, j] == pytest.approx(x[0], rel=1e-6, abs=1e-9)
            u = x[1]
            assert 0 < u < 0.5 * om * nd.y[j]  # the wake turns with the blade and less than it
            checked += 1
    assert checked == 16
    # swirl takes thrust and torque (here 2-6%)
    assert np.all(r.thrust < plain.thrust) and np.all(r.torque < plain.torque)
    assert np.all(r.thrust > 0.9 * plain.thrust)


@pytest.mark.parametrize("tip_hub", [False, True])
def test_swirl_matches_numpy_reference(apc8x6, envelope_points, tip_hub):
    p = pm.CamberedParams(descent="glauert", swirl=True, tip_loss=tip_hub, hub_loss=tip_hub)
    om, V, b = (a[:60] for a in envelope_points)
    b = np.where(b > math.pi / 2, math.pi - b, b)  # climb and forward flight
    V = V.copy()
    V[:6] = 0.0
    r = pm.rotor_loads(apc8x6, p, om, V, b, radial=True)
    assert r.converged.all()
    nd = _nodes(apc8x6, 48, 16, pm.Air(), p)
    Vs, Vc = V * np.sin(b), V * np.cos(b)
    Vs[np.abs(Vs) < 1e-12 * np.maximum(V, 1e-300)] = 0.0
    T, D, Q, vi, conv = solve_reference(om, Vs, Vc, nd, p)
    assert conv.all()
    T0 = float(pm.rotor_loads(apc8x6, p, 12000 * RPM, 0, 0).thrust)
    Q0 = float(pm.rotor_loads(apc8x6, p, 12000 * RPM, 0, 0).torque)
    np.testing.assert_allclose(r.thrust, T, rtol=0, atol=1e-7 * T0)
    np.testing.assert_allclose(r.drag, D, rtol=0, atol=1e-7 * T0)
    np.testing.assert_allclose(r.torque, Q, rtol=0, atol=1e-7 * Q0)
    np.testing.assert_allclose(r.v_i, vi, rtol=1e-5, atol=1e-6)
    # the swirl iteration's cost is counted: several root solves per point
    plain = pm.rotor_loads(apc8x6, p.replace(swirl=False), om, V, b)
    assert np.all(r.n_evaluations > 2 * plain.n_evaluations)


def test_swirl_grows_with_blade_count_and_loading():
    # the same NR640 blade (UIUC vol. 2) on 2-, 3- and 4-blade hubs, generic section, 6000 rpm
    g = pm.CamberedParams(tip_loss=True)
    om = 6000 * RPM
    ratios = []
    for name in ("nr640_5_15deg", "nr640_5_15deg_3b", "nr640_5_15deg_4b"):
        prop = pm.load_propeller(name)
        V = np.array([0.0, 0.3]) * om / (2 * math.pi) * prop.diameter  # J = 0 and 0.3
        on = pm.rotor_loads(prop, g.replace(swirl=True), om, V, 0.0)
        off = pm.rotor_loads(prop, g, om, V, 0.0)
        ratios.append(on.thrust / off.thrust)
    ratios = np.array(ratios)  # (blades, J)
    assert np.all(ratios < 1.0)
    assert np.all(np.diff(ratios, axis=0) < -0.009)  # each added blade takes > 0.9% more thrust
    assert np.all(ratios[:, 1] > ratios[:, 0] + 0.025)  # the static run, loaded most, loses most
    # regression values (2026-11-23): thrust with swirl / without, 2, 3, 4 blades, J = 0 and 0.3
    np.testing.assert_allclose(ratios, [[0.9264, 0.9601], [0.9141, 0.9452], [0.9035, 0.9317]], atol=5e-4)


def test_swirl_is_off_by_default_and_checked():
    assert pm.CamberedParams().swirl is False
    assert pm.preset("gill2017-apc").swirl is False
    with pytest.raises(ValueError, match="swirl must be true or false"):
        pm.CamberedParams(swirl=1)


SWIRL_POINTS = [  # (omega [rad/s], V [m/s], incidence [deg])
    (800.0, 0.0, 0.0),  # hover
    (800.0, 5.0, 0.0),  # axial climb
    (800.0, 3.0, 180.0),  # axial descent (the cambered default's empirical momentum)
    (800.0, 12.0, 100.0),  # edgewise, descending
    (1200.0, 25.0, 30.0),  # fast climb at incidence
    (500.0, 8.0, 60.0),
    (800.0, 4.0, 150.0),  # oblique descent
]


@pytest.mark.parametrize("model", ["cambered", "gill2017", "cambered_inplane"])
def test_swirl_implicit_derivatives_match_differences(apc8x6, model):
    """With swirl each annulus solves two equations in (v, u), the root and the angular momentum
    balance (core/_swirl_sensitivity._swirl_system): the implicit derivatives with respect to the
    inputs, the collective, a section parameter and the density agree with central differences
    of the whole solver (swirl iteration included) within 2e-5 of the point's thrust (forces) or
    torque (moments) per unit of the input's scale (measured 2026-11-25: at most 2.6e-6 for the
    inputs, 2.0e-7 for the parameter and the density), and differ from the derivatives without
    swirl (the balance is not ignored)."""
    p = (pm.generic_params() if model.startswith("cambered") else pm.preset("gill2017-apc")).replace(
        swirl=True, inplane_induction=model.endswith("_inplane"))  # (with the skewed wake's in-plane induction)
    par = "cd_min" if model.startswith("cambered") else "cd"
    disc = pm.Discretization(24, 8)
    wrt = ("omega", "airspeed", "incidence", "collective", par, "rho")
    for om, V, beta_deg in SWIRL_POINTS:
        b = np.radians(beta_deg)
        r = pm.rotor_loads(apc8x6, p, om, V, b, discretization=disc, derivatives=wrt)
        plain = pm.rotor_loads(apc8x6, p.replace(swirl=False), om, V, b, discretization=disc, derivatives=("omega",))
        assert abs(float(r.derivative("thrust", "omega")) / float(plain.derivative("thrust", "omega")) - 1) > 1e-3

        def moved(w, h):
            return moved_loads(apc8x6, p, om, V, b, w, h, disc)

        scales = {"omega": om, "airspeed": max(V, 1.0), "incidence": 1.0, "collective": 1.0, par: getattr(p, par),
                  "rho": p.air.rho}
        for w in wrt:
            h = (1e-6 if w == "collective" else 1e-4) * scales[w]  # (the paper's M = 50 stall curves the thrust)
            if (w == "airspeed" and V == 0.0) or (w == "incidence" and beta_deg in (0.0, 180.0)):
                sgn = -1.0 if beta_deg == 180.0 and w == "incidence" else 1.0  # one-sided at an end of the range
                f0, f1, f2 = moved(w, 0.0), moved(w, sgn * h), moved(w, 2 * sgn * h)
                fd = {q: sgn * (4 * float(getattr(f1, q)) - float(getattr(f2, q)) - 3 * float(getattr(f0, q)))
                      / (2 * h) for q in LOADS}
            else:
                hi, lo = moved(w, h), moved(w, -h)
                fd = {q: (float(getattr(hi, q)) - float(getattr(lo, q))) / (2 * h) for q in LOADS}
            for q in LOADS:
                scale = abs(float(r.thrust)) if q in ("thrust", "drag") else abs(float(r.torque))
                err = abs(float(r.derivative(q, w)) - fd[q]) * scales[w] / scale
                assert err < 2e-5, (om, V, beta_deg, w, q, float(r.derivative(q, w)), fd[q])


@pytest.mark.parametrize("inflow", ["uniform", "drees"])
def test_swirl_is_differentiable_and_its_fits_take_implicit_derivatives(apc8x6, inflow):
    """differentiable() accepts swirl (with a linear inflow model too, since 2026-11-26); a loads
    fit with swirl takes the implicit Jacobian and reaches the optimum that differences reach
    (the UIUC data are axial: there the linear inflow's gradient vanishes, but its derivatives in
    the parameters go through core/_linear_sensitivity.py all the same)."""
    from propmap.core.derivatives import differentiable
    from propmap.identify import FitOptions, fit_loads, loads_from_catalogue

    p = pm.CamberedParams(swirl=True, inflow=inflow)
    assert differentiable(p, ("collective", "cl_alpha"))
    data = loads_from_catalogue(pm.catalogue()["apce_8x6"], apc8x6.diameter)
    disc = pm.Discretization(24, 8)
    fits = [fit_loads(data, apc8x6, base=pm.generic_params().replace(swirl=True, inflow=inflow),
                      options=FitOptions(jacobian=j, discretization=disc)) for j in ("implicit", "differences")]
    np.testing.assert_allclose(fits[0].x, fits[1].x, rtol=1e-5, atol=1e-7)
    assert fits[0].nfev < fits[1].nfev / 4


def test_swirl_round_trips_through_a_parameter_file(tmp_path):
    from propmap.io.params_file import read_params, write_params

    p = pm.CamberedParams(swirl=True, tip_loss=True)
    write_params(tmp_path / "p.toml", p)
    assert "swirl = true" in (tmp_path / "p.toml").read_text()
    back = read_params(tmp_path / "p.toml")
    assert back.swirl is True
    assert back == p


def test_swirl_gives_up_with_its_own_code(apc8x6, apc_params):
    # one swirl step on an axial point's annuli from u = 0 (out of balance): an intermediate step
    # moves u to the balance's target; the last allowed step marks the annuli NO_SWIRL_BALANCE
    from propmap.core import _kernel
    from propmap.core._momentum import SWIRL_MAX_ITER

    p = apc_params.replace(swirl=True)
    r = pm.rotor_loads(apc8x6, apc_params, 900.0, 0.0, 0.0, discretization=pm.Discretization(6, 2), radial=True)
    nd = _nodes(apc8x6, 6, 2, pm.Air(), p)
    model, pk = _model_constants(p)
    zeros = np.zeros(6)

    def step(it):
        us, code, multiple = zeros.copy(), np.zeros(6, np.int64), np.zeros(6, bool)
        sect = np.stack([nd.sc, zeros, zeros, zeros])  # the paper's section: s0 the Blasius factor
        blade = nd.rows[NODE_TH:NODE_TH + 3]  # theta, its sine and cosine
        done = _kernel._swirl_iterate.py_func(us, np.full((4, 6), np.nan), r.v_i, code, multiple, nd.rows, blade,
                                              900.0, 0.0, 0.0, sect, nd.azimuth, np.zeros((2, 6)), 1, model, pk, True,
                                              it)
        assert not multiple.any()
        return done, us, code

    done, us, code = step(0)
    assert not done and np.all(code == _kernel.OK)
    target = r.v_i * r.dQ_dr / (nd.y * r.dT_dr)
    np.testing.assert_allclose(us, target, rtol=1e-12)
    assert np.all(us > 0)
    done, _, code = step(SWIRL_MAX_ITER - 1)
    assert not done and np.all(code == _kernel.NO_SWIRL_BALANCE)


def test_swirl_failure_message(apc8x6, monkeypatch):
    # the solver's message for an annulus whose swirl did not balance (status code 3)
    from propmap.core import _kernel

    real = _kernel.solve_batch_serial

    def failing(*args):
        real(*args)
        args[-2][0, :] = 1 + 2 * 4 + _kernel.NO_SWIRL_BALANCE  # counts row 0: the third annulus

    monkeypatch.setattr(_kernel, "solve_batch_serial", failing)
    with pytest.raises(pm.SolverError, match="swirl did not balance the annulus' angular momentum"):
        pm.rotor_loads(apc8x6, pm.CamberedParams(swirl=True), 900.0, 5.0, 0.2)


def test_swirl_where_the_selected_root_jumps_is_kept_at_the_jump_and_flagged():
    # the NeuroBEM quadrotor's rotor (the authors' lumped blade) in a steep oblique descent with
    # Glauert's momentum: near the tip the root selected by the rule jumps between two branches
    # as the swirl moves, so no balance exists on it. The iteration closes in on the jump
    # (bisection), keeps the root there and flags the point; without swirl the same point has no
    # such flag. (113 deg until 2026-11-24; with the generic set of the stall blend M = 12 the
    # point without swirl has several roots there, so the case moved to 103 deg: 38 such points
    # at 6-14.5 m/s, 100-134 deg.)
    from importlib import resources

    from propmap.io.calibration import generic_params
    from propmap.vehicle import read_vehicle

    vehicle = read_vehicle(resources.files("propmap") / "data" / "examples" / "neurobem_quadrotor.toml")
    prop = vehicle.rotors[0].propeller
    g = generic_params().replace(descent="glauert")
    om, V, b = 668.0, 10.5, math.radians(103.0)
    plain = pm.rotor_loads(prop, g, om, V, b)
    r = pm.rotor_loads(prop, g.replace(swirl=True), om, V, b)
    assert plain.converged and not plain.multiple_roots
    assert r.converged and r.multiple_roots
    assert 0.9 * plain.thrust < r.thrust < plain.thrust


def test_swirl_balances_past_a_jump_with_imbalance_of_one_sign():
    """gwsdd_4x2.5 with the paper's section windmilling in axial climb (12000 rpm, 12 m/s): at
    the hub annulus the selected root jumps (v -3.80 -> -2.11 m/s at u = -0.078 Omega y) with
    the imbalance g < 0 on both sides, and the balance lies past the jump (u = -0.22 Omega y).
    The secant through iterates on either side pointed back and the iteration failed after 40
    solves on 91 of 1505 axial points (a user-level audit, 2026-11-26); without a bracket a
    step against g's sign now takes the plain step."""
    from propmap.core._reference import solve_reference
    from propmap.core.nodes import _nodes

    prop = pm.load_propeller("gwsdd_4x2.5")
    p = pm.preset("gill2017-apc").replace(swirl=True)
    om = 12000 * RPM
    r = pm.rotor_loads(prop, p, om, np.arange(11.9, 13.0, 0.1), 0.0, on_failure="flag")
    assert r.converged.all() and r.thrust.max() < 0  # (windmilling)
    nd = _nodes(prop, 48, 16, pm.Air(), p)
    T, D, Q, vi, ok = solve_reference(np.array([om]), np.array([0.0]), np.array([12.0]), nd, p)
    assert ok.all()  # the NumPy reference, with the same step rule, balances too and agrees
    assert abs(float(T[0]) - float(r.thrust[1])) < 1e-6 * abs(float(r.thrust[1]))
    assert abs(float(Q[0]) - float(r.torque[1])) < 1e-6 * abs(float(r.torque[1]))
    # near an annulus of zero thrust the target's slope exceeds 1 and g has a maximum just below 0
    # before the balance: plain steps u + g crawled there and the point failed (a review of the first
    # version); the step along g grows. Regression value of the rule before either change: -1.122840 N
    nr = pm.rotor_loads(pm.load_propeller("nr640_5_15deg_4b"), p, 6000 * RPM, 20.5, 0.0, on_failure="flag")
    assert nr.converged and float(nr.thrust) == pytest.approx(-1.122840, abs=2e-6)


def test_swirl_with_a_linear_inflow_and_in_descent(apc8x6):
    # Pitt-Peters' gradient vanishes in axial flow: there the linear inflow with swirl is the
    # uniform one with swirl, exactly; in forward flight swirl still takes thrust. The default
    # (empirical) descent converges with swirl over a descent grid.
    g = pm.CamberedParams(tip_loss=True, swirl=True)
    pp = g.replace(inflow="pitt-peters")
    om = 8000 * RPM
    axial = [pm.rotor_loads(apc8x6, p, om, 6.0, 0.0) for p in (g, pp)]
    assert float(axial[0].thrust) == float(axial[1].thrust)
    fwd = pm.rotor_loads(apc8x6, pp, om, 10.0, math.radians(60.0))
    fwd_plain = pm.rotor_loads(apc8x6, pp.replace(swirl=False), om, 10.0, math.radians(60.0))
    assert fwd.converged and 0.9 * fwd_plain.thrust < fwd.thrust < fwd_plain.thrust
    V, b = np.meshgrid([2.0, 5.0, 10.0, 15.0], np.radians([100.0, 135.0, 160.0, 180.0]))
    r = pm.rotor_loads(apc8x6, g, np.array([4000.0, 10000.0])[:, None, None] * RPM, V, b)
    assert r.converged.all()
