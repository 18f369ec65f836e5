"""The per-annulus root solve of eq (11): convergence, the selection rule, flags.

Rule (docs/solver.md): the first root of F = dT_BET - dT_BEMT met going from v = 0
toward sign F(0), found by a march of step v_m/3. Checked here against a brute-force
dense scan of F and against the independent NumPy implementation.
"""

import math
import subprocess
import sys

import numpy as np
import pytest

import propmap as pm
from propmap.core._physics import NODE_TH, element
from propmap.core._momentum import momentum_thrust
from propmap.core._reference import solve_reference
from propmap.core.polar import _model_constants
from propmap.core.nodes import _nodes

from .conftest import RPM


def _grid():
    rpm, V, B = np.meshgrid([4000.0, 10000.0], [0.0, 5.0, 10.0, 20.0], np.radians(np.arange(0, 181, 30)),
                            indexing="ij")
    return rpm.ravel() * RPM, V.ravel(), B.ravel()


def _residual(nd, p, om, V, b, j, v):
    Vs, Vc = V * math.sin(b), V * math.cos(b)
    if abs(Vs) < 1e-12 * max(V, 1e-300):
        Vs = 0.0
    UT = om * nd.y[j] + Vs * nd.sinpsi[None, : nd.sinpsi.size // 2]  # the half circle (uniform inflow)
    with np.errstate(all="ignore"):
        qT, _ = element(UT, (Vc + v)[:, None], nd.theta[j], nd.sin_th[j], nd.cos_th[j], nd.sc[j], 0.0,
                        0.0, 0.0, *_model_constants(p))
    return nd.cfac[j] * qT.mean(axis=1) - momentum_thrust(v, nd.mfac[j], Vs, Vc)


def test_every_annulus_of_a_dense_grid_converges_including_descent(apc8x6, apc_params):
    rpm, V, B = np.meshgrid(np.linspace(3000, 12000, 4), np.linspace(0, 25, 6), np.radians(np.linspace(0, 180, 13)),
                            indexing="ij")
    r = pm.rotor_loads(apc8x6, apc_params, rpm * RPM, V, B, radial=True)
    assert r.converged.all()  # 312 points x 48 annuli
    assert np.all(np.isfinite(r.v_i)) and np.all(np.isfinite(r.thrust))
    assert r.vortex_ring.any()  # descent cases present in the grid


@pytest.mark.slow
def test_selected_root_is_the_first_sign_change_of_a_dense_scan(apc8x6, apc_params):
    om, V, B = _grid()
    r = pm.rotor_loads(apc8x6, apc_params, om, V, B, radial=True)
    nd = _nodes(apc8x6, 48, 16, pm.Air(), apc_params)
    misses, total, multi_scan = 0, 0, np.zeros(om.size, bool)
    for i in range(om.size):
        for j in range(nd.y.size):
            v = r.v_i[i, j]
            s = np.sign(_residual(nd, apc_params, om[i], V[i], B[i], j, np.array([0.0]))[0])
            grid = np.linspace(0.0, 3 * abs(v) + 5.0, 3001) * s
            f = _residual(nd, apc_params, om[i], V[i], B[i], j, grid)
            first = grid[np.nonzero(f * s <= 0)[0][0]]
            multi_scan[i] |= np.count_nonzero(np.diff(np.sign(f))) > 1
            total += 1
            if abs(v - first) > 1.01 * abs(grid[1]):
                misses += 1
                # the march (step v_m/3) can step over a fold narrower than a step; measured
                # to happen only in descent (vortex-ring region), documented in docs/solver.md
                assert B[i] > math.pi / 2, (om[i] / RPM, V[i], math.degrees(B[i]), j)
    assert total == 56 * 48
    assert misses <= 0.001 * total  # measured: 2 of 2688, both descent
    # no false alarms: every point flagged multiple_roots has several roots on the scan
    assert not np.any(r.multiple_roots & ~multi_scan)
    assert r.multiple_roots.any()
    # climb to edgewise: every point with several roots on the scan is flagged (measured 2
    # of 2); in descent the flag sees only folds within one march step (measured 6 of 12,
    # 2026-11-30; a regression value, 4 of 12 before the grazing check of 2026-11-28)
    ascent = B <= math.pi / 2 + 1e-9
    assert np.all(r.multiple_roots[multi_scan & ascent]) and np.any(multi_scan & ascent)
    descent = multi_scan & ~ascent
    assert np.count_nonzero(descent) == 12 and np.count_nonzero(r.multiple_roots[descent]) >= 6


def test_stall_fold_in_hover_picks_the_lower_root(apc8x6, apc_params):
    """docs/numerics.md: with M = 50, hover at 8000 rpm has a fold near r/R = 0.345 (v_i 5.35 -> 8.19 m/s)."""
    om = 8000 * RPM
    r48 = pm.rotor_loads(apc8x6, apc_params, om, 0.0, 0.0, radial=True)
    jump = np.argmax(np.abs(np.diff(r48.v_i)))
    assert r48.r[jump] / apc8x6.radius == pytest.approx(0.345, abs=0.01)
    assert r48.v_i[jump] == pytest.approx(5.35, abs=0.1) and r48.v_i[jump + 1] == pytest.approx(8.4, abs=0.3)
    disc = pm.Discretization(200, 8)
    nd = _nodes(apc8x6, 200, 8, pm.Air(), apc_params)
    r = pm.rotor_loads(apc8x6, apc_params, om, 0.0, 0.0, discretization=disc, radial=True)
    assert r.multiple_roots
    folds = 0
    for j in range(nd.y.size):
        grid = np.linspace(0.0, 15.0, 6001)
        f = _residual(nd, apc_params, om, 0.0, 0.0, j, grid)
        roots = grid[np.nonzero(np.diff(np.sign(f)))[0]]
        if roots.size > 1:
            folds += 1
            assert r.v_i[j] == pytest.approx(roots[0], abs=0.01)
            assert r.v_i[j] < roots[-1] - 1.0
    assert folds >= 1
    # the point-level flag is computed per annulus: the 200-node run sees the fold


@pytest.mark.parametrize("which", ["gill2017", "gill2017_radial", "cambered_tip_hub", "cambered_stall_terms",
                                   "gill2017_inplane", "cambered_inplane", "cambered_dynamic_stall"])
def test_kernel_matches_independent_numpy_implementation(apc8x6, apc_params, envelope_points, which):
    # the reference solves Glauert's momentum (the paper's): the cambered sets are asked for it; they
    # carry the radial flow's drag and the skewed wake's in-plane induced velocity (their defaults), and
    # gill2017_radial and gill2017_inplane give those to the paper's section. cambered_tip_hub is run
    # without the induction: with it, at one of the 200 points (8139 rpm, 19.9 m/s at 172 deg, Glauert's
    # momentum in the vortex-ring state) the march brackets three roots of the annulus next to the hub
    # (19.0, 20.7 and 22.6 m/s between 18.8 and 25.1), and the two refinements return different ones
    # (thrust 9.2e-5 apart; without the induction the same annulus has three roots too, and both return
    # the first): the rule's gap documented in docs/solver.md
    params = {"gill2017": apc_params, "gill2017_radial": apc_params.replace(radial_drag=True),
              "gill2017_inplane": apc_params.replace(inplane_induction=True),
              "cambered_inplane": pm.CamberedParams(tip_loss=True, descent="glauert"),
              "cambered_tip_hub": pm.CamberedParams(tip_loss=True, hub_loss=True, descent="glauert",
                                                    inplane_induction=False),
              "cambered_stall_terms": pm.CamberedParams(re_exp_stall=0.2, stall_delay=2.0, descent="glauert",
                                                        alpha_L0_re=math.radians(-1.5)),
              # Gormont's dynamic stall: the kernel's node-and-mirror element against the reference's (2026-11-26)
              "cambered_dynamic_stall": pm.CamberedParams(tip_loss=True, descent="glauert", dynamic_stall=1.5)}[which]
    assert params.inplane_induction == (which.endswith("_inplane") or which in ("cambered_stall_terms",
                                                                                 "cambered_dynamic_stall"))
    om, V, b = envelope_points
    r = pm.rotor_loads(apc8x6, params, om, V, b, radial=True)
    nd = _nodes(apc8x6, 48, 16, pm.Air(), params)
    Vs, Vc = V * np.sin(b), V * np.cos(b)
    Vs[np.abs(Vs) < 1e-12 * np.maximum(V, 1e-300)] = 0.0
    T, D, Q, vi, conv = solve_reference(om, Vs, Vc, nd, params)
    assert conv.all()
    static = pm.rotor_loads(apc8x6, params, 12000 * RPM, 0, 0, radial=True)
    T0, Q0 = float(static.thrust), float(static.torque)
    np.testing.assert_allclose(r.thrust, T, rtol=0, atol=1e-7 * T0)
    np.testing.assert_allclose(r.drag, D, rtol=0, atol=1e-7 * T0)
    np.testing.assert_allclose(r.torque, Q, rtol=0, atol=1e-7 * Q0)
    np.testing.assert_allclose(r.v_i, vi, rtol=1e-6, atol=1e-6)


def test_flags_agree_with_their_definitions(apc8x6, apc_params, envelope_points):
    om, V, b = envelope_points
    r = pm.rotor_loads(apc8x6, apc_params, om, V, b, radial=True)
    from propmap.core.states import descent_state

    state, vh, k, m = descent_state(r.thrust, V, b, r.v_i_mean, 1.225, apc8x6.radius)
    np.testing.assert_array_equal(r.vortex_ring, state == 1)
    np.testing.assert_array_equal(r.state, state)
    np.testing.assert_allclose(r.reverse_flow_radius, V * np.sin(b) / om, atol=1e-15)
    np.testing.assert_array_equal(r.reverse_flow, V * np.sin(b) / om > apc8x6.r_hub)
    i = int(np.argmax(r.vortex_ring))
    assert "vortex_ring" in r.flags(i)


def test_failed_solve_raises_or_flags_never_silent(apc8x6, apc_params, monkeypatch):
    from propmap.core import _kernel

    monkeypatch.setattr(_kernel, "solve_batch", _fail_everything)
    monkeypatch.setattr(_kernel, "solve_batch_serial", _fail_everything)
    with pytest.raises(pm.SolverError, match=r"annulus r/R=0\.\d+: .*bracket"):
        pm.rotor_loads(apc8x6, apc_params, 800.0, 1.0, 0.2, radial=True)
    r = pm.rotor_loads(apc8x6, apc_params, 800.0, 1.0, 0.2, on_failure="flag", radial=True)
    assert not r.converged and np.isnan(r.thrust) and "not_converged" in r.flags()


def _kernel_args():
    import inspect

    from propmap.core import _kernel

    return tuple(inspect.signature(_kernel.solve_batch_serial.py_func).parameters)


#: the kernel's argument names (read before any test replaces the kernel)
_KERNEL_ARGS = _kernel_args()


def _fail_everything(*args):
    # the kernel's outputs by name: out (T, D, Q, M_R, ...), rad (per annulus), counts (status, ...) and
    # flags (converged, ...); the states and flags as the kernel's point_flags writes them
    from propmap.core import _flags

    a = dict(zip(_KERNEL_ARGS, args))
    out, counts, flags = a["out"], a["counts"], a["flags"]
    out[...] = np.nan
    a["rad"][...] = 0
    counts[...] = 0
    counts[0] = 1 + 3 * 4 + 1  # status: annulus 3, no bracket
    _flags.point_flags(out, counts, a["Vs"], a["Vc"], a["Om"], a["cls"], a["inflow"] != 0, a["emp"], flags)


def test_a_second_process_loads_the_compiled_kernel_from_the_disk_cache(apc8x6, apc_params):
    """Issue: compiled kernels are cached on disk, so a new process pays no JIT time."""
    pm.rotor_loads(apc8x6, apc_params, 800.0, 5.0, 1.0, radial=True)  # this process compiled or loaded it
    code = ("import propmap as pm; from propmap.core import _kernel as K; "
            "pm.rotor_loads(pm.load_propeller('apce_8x6'), pm.preset('gill2017-apc'), 800.0, 5.0, 1.0, radial=True); "
            "s = K.solve_batch_serial.stats; print(sum(s.cache_hits.values()), sum(s.cache_misses.values()))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    hits, misses = map(int, out.split())
    assert (hits, misses) == (1, 0)


def _solve_annuli_python(nd, p, om, V, b):
    """The kernel's lockstep root solve run as plain Python (reads _annulus' constants now)."""
    from propmap.core import _annulus

    nr = nd.y.size
    v, status, mult = np.empty(nr), np.empty((2, nr), np.int64), np.empty(nr, bool)
    sect = np.stack([nd.sc, np.zeros(nr), np.zeros(nr), np.zeros(nr)])  # the paper's section: s0 the Blasius factor
    blade = nd.rows[NODE_TH:NODE_TH + 3]  # theta, its sine and cosine
    _annulus.solve_annuli.py_func(om, V * math.sin(b), V * math.cos(b), nd.rows, blade, np.zeros(nr), sect,
                                  nd.azimuth, np.zeros((2, nr)), nd.sinpsi.size // 2, *_model_constants(p), False, v,
                                  status, mult)
    return v, status[0], status[1]


def test_root_solve_failure_codes_of_the_state_machine(apc8x6, apc_params, monkeypatch):
    """The give-up paths (no bracket, no convergence) that feed SolverError's message."""
    from propmap.core import _annulus

    nd = _nodes(apc8x6, 6, 8, pm.Air(), apc_params)
    om, V, b = 800.0, 10.0, 1.0
    v, code, nev = _solve_annuli_python(nd, apc_params, om, V, b)
    r = pm.rotor_loads(apc8x6, apc_params, om, V, b, discretization=pm.Discretization(6, 8), radial=True)
    assert np.all(code == _annulus.OK)
    np.testing.assert_allclose(v, r.v_i, rtol=1e-12)  # same iterates as the compiled kernel
    assert nev.sum() == r.n_evaluations

    monkeypatch.setattr(_annulus, "MAX_MARCH", 1)  # the root lies ~3 march steps out
    monkeypatch.setattr(_annulus, "MAX_DOUBLING", 0)
    v, code, _ = _solve_annuli_python(nd, apc_params, om, V, b)
    assert np.all(code == _annulus.NO_BRACKET) and np.all(np.isnan(v))

    monkeypatch.setattr(_annulus, "MAX_MARCH", 64)
    monkeypatch.setattr(_annulus, "MAX_DOUBLING", 80)
    monkeypatch.setattr(_annulus, "MAX_REFINE", 1)
    v, code, nev = _solve_annuli_python(nd, apc_params, om, V, b)
    assert np.all(code == _annulus.NO_CONVERGENCE) and np.all(np.isfinite(v))


def test_refinement_entered_from_doubling_finds_the_same_root(apc8x6, apc_params, monkeypatch):
    """The bracket found by doubling (no extra-scan point: a secant first step) refines to
    the root the march finds, within the root tolerance."""
    from propmap.core import _annulus

    nd = _nodes(apc8x6, 6, 8, pm.Air(), apc_params)
    om, V, b = 800.0, 10.0, 1.0
    v_march, code, _ = _solve_annuli_python(nd, apc_params, om, V, b)
    monkeypatch.setattr(_annulus, "MAX_MARCH", 1)  # the root lies ~3 march steps out: doubling brackets it
    v_double, code2, _ = _solve_annuli_python(nd, apc_params, om, V, b)
    assert np.all(code == _annulus.OK) and np.all(code2 == _annulus.OK)
    np.testing.assert_allclose(v_double, v_march, rtol=0, atol=2e-7 * np.max(np.abs(v_march)))


def test_residual_evaluations_per_annulus(apc8x6, apc_params, envelope_points):
    """Machine-independent cost of the root solve on the 200 envelope points (regression
    values, 2026-11-25): the paper's set 8.14 per annulus and a bare CamberedParams 7.16 since
    the refinement may end on the secant's unevaluated root (8.59 and 7.68 before; 10.3 for the
    paper's set with the Illinois refinement); the march and the extra scan take ~5.8 of them."""
    om, V, b = envelope_points
    for p, expected in ((apc_params, 8.14), (pm.CamberedParams(), 7.16)):
        r = pm.rotor_loads(apc8x6, p, om, V, b, radial=True)
        per_annulus = r.n_evaluations.mean() / pm.DEFAULT_DISCRETIZATION.n_radial
        assert per_annulus == pytest.approx(expected, abs=0.1), per_annulus


def test_a_pair_of_roots_between_two_march_points_is_flagged():
    """Axial descent of the APC 10x7SF with its calibrated set at 7000 rpm (a physics audit,
    2026-11-28): between 16.8403 and 16.8404 m/s (16.8401 and 16.8402 before the calibration of
    2026-11-29) the annulus at r/R = 0.48
    switches from its root at 19.29 m/s to one at 15.91 m/s, where its residual F grazes zero
    between two march points, and the thrust steps by 0.31%, 60 times its neighbours' change.
    Both points were unflagged; the march's grazing check (core/_annulus.py, step 5) flags
    them, the roots unchanged (regression values of the thrust, the commit before)."""
    p = pm.load_propeller("apcsf_10x7")
    r = pm.rotor_loads(p, pm.default_params("apcsf_10x7"), 7000 * RPM, np.array([16.8403, 16.8404]), math.pi)
    np.testing.assert_allclose(r.thrust, [13.31362881, 13.27238465], rtol=1e-8)
    assert r.converged.all() and r.multiple_roots.all()
