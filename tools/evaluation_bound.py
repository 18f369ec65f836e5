"""How few residual evaluations per annulus a root solve could take with the same roots: a bound.

The kernel (core/_annulus.py) marches from v = 0 in steps of v_m / 3 to the first sign change
of F (the root-selection rule, docs/solver.md), then refines; issue 20 asks for 5 evaluations
per annulus. This measures what is left if a certificate could say that F is monotone on
[0, b], so that the march could be skipped, taking as such a certificate a 400-sample scan of
F on [0, b] (an ideal one: no certificate computable at the cost of an evaluation or two is
known to be as sharp):

1. F(0), F(v_m) (v_m = 3 h, the march's scale), doubling from v_m until F changes sign at b;
   then Chandrupatla's method (SciPy's find_root) on [0, b] with the kernel's tolerances
   (1e-7 v_m, 1e-9 |F(0)|); where the scan finds F monotone on [0, b];
2. the root of the annulus inward as the guess, bracketed by +-5% (two evaluations); where
   that does not bracket the root, scheme 1 after those two evaluations.

Both are compared with the rule's root (core/_reference.py); the multiple-roots flag's scan
(one evaluation beyond the root) comes on top of either, and where F is not monotone the
kernel's own mean on the same points stands in. 150 random points of apce_8x6 with its
calibrated set, rpm 3000-12000, V 0-25 m/s, incidence 0-90 deg (benchmarks/bench_solver.py's
ranges), 48 x 16 nodes.

    .venv/bin/python tools/evaluation_bound.py     # about 15 s on 2 cores

3. as 1, but the refinement interpolates only the blade elements' side of F (a polynomial
   through the newest three points) and solves it against the momentum side, which is exact
   and costs no element evaluation; the iterate moving less than 1e-7 v_m is returned
   unevaluated.

Measured 2026-11-26 (docs/solver.md; the residual with the skewed wake's in-plane induction,
the cambered default since 2026-11-25, which the tool's residual left out until then, so that
its roots had stopped matching the rule's): the kernel 7.40 evaluations per annulus on these
points; F monotone on 99.8% of the 7,200 annuli, the same root everywhere; scheme 1 6.62
where F is monotone (4.30 of them refining the wide bracket), 7.62 overall with the scan;
scheme 2 brackets 71.8% of the roots, 6.17 there, 7.80 overall; scheme 3 5.21 (every root
within 4.9e-8 v_m of the rule's), 6.21 with the scan. (2026-11-24, with the calibrated set of
the stall blend M = 20 and no induction: 7.88, 97.7%, 6.65, 7.66, 72.0%, 6.18, 7.85.)
"""
import argparse

import numpy as np
from scipy.optimize.elementwise import find_root

import propmap as pm
from propmap.core import _annulus as K
from propmap.core.nodes import _cambered_args, _nodes
from propmap.core._physics import PK_INPLANE, cambered_annulus, element, loss_factor_numpy
from propmap.core._momentum import inplane_induction_numpy, momentum_scale, momentum_thrust
from propmap.core.polar import _model_constants
from propmap.core._reference import solve_reference

# (a script: --help, and nothing else, before the measurement)
argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()

prop = pm.load_propeller("apce_8x6")
p = pm.default_params("apce_8x6")
air = pm.Air()
rng = np.random.default_rng(7); n = 150
om = rng.uniform(3000, 12000, n) * np.pi / 30; V = rng.uniform(0, 25, n); inc = np.radians(rng.uniform(0, 90, n))
Vs, Vc = V * np.sin(inc), V * np.cos(inc)
nd = _nodes(prop, 48, 16, air, p)
model, pk = _model_constants(p)
nr = nd.y.size; naz = nd.sinpsi.size // 2
y = np.broadcast_to(nd.y[None, :], (n, nr)).ravel()
Vs1 = np.repeat(Vs, nr); Vc1 = np.repeat(Vc, nr); om1 = np.repeat(om, nr)
cfac = np.tile(nd.cfac, n); mfac = np.tile(nd.mfac, n); ct = np.tile(nd.ct, n); ch = np.tile(nd.ch, n)
cam = _cambered_args(p, air)
U2 = (om1 * y) ** 2 + 0.5 * Vs1**2 + Vc1**2
s0, s1, s2, s3 = cambered_annulus(U2, np.tile(nd.sc, n), np.tile(nd.cy2, n), cam[4], cam[0], cam[1], cam[2],
                                  cam[3] != 0.0, cam[5], cam[6], cam[7])
th, sth, cth = np.tile(nd.theta, n), np.tile(nd.sin_th, n), np.tile(nd.cos_th, n)
wy = om1 * y

def momentum(v, idx):
    """The momentum side F_loss dT_BEMT/dy of eq 11 [N/m] (no blade element: cheap)."""
    idx = idx.astype(int)
    return momentum_thrust(v, mfac[idx], Vs1[idx], Vc1[idx]) * loss_factor_numpy(Vc1[idx] + v, wy[idx], ct[idx],
                                                                                   ch[idx])


def bet(v, idx):
    """The blade elements' side dT_BET/dy of eq 11 [N/m]: the residual evaluation's cost. The
    blades meet the in-plane airspeed plus the skewed wake's in-plane induced velocity where the
    set has it (the cambered default since 2026-11-25), as the kernel's residual does."""
    idx = idx.astype(int)
    vs = Vs1[idx] + pk[PK_INPLANE] * inplane_induction_numpy(v, Vs1[idx], Vc1[idx])
    UT = wy[idx][..., None] + vs[..., None] * nd.sinpsi[None, :naz]
    geo = (th[idx][..., None], sth[idx][..., None], cth[idx][..., None], s0[idx][..., None], s1[idx][..., None],
           s2[idx][..., None], s3[idx][..., None])
    qT, _ = element(UT, (Vc1[idx] + v)[..., None], *geo, model, pk)
    return cfac[idx] * qT.mean(axis=-1)


def F(v, idx):
    return bet(v, idx) - momentum(v, idx)


allidx = np.arange(n * nr).astype(float)
with np.errstate(all="ignore"):
    F0 = F(np.zeros(n * nr), allidx)
    s = np.where(F0 >= 0, 1.0, -1.0)
    h = momentum_scale(F0, mfac, Vs1, Vc1)
    h = momentum_scale(F0, mfac * loss_factor_numpy(Vc1 + s * h, wy, ct, ch), Vs1, Vc1) / K.MARCH_STEPS
    vm = 3 * h
    b = s * vm; fb = F(b, allidx)
    for _ in range(40):
        same = fb * s > 0
        if not same.any(): break
        b = np.where(same, 2 * b, b); fb2 = F(b[same], allidx[same]); fb[same] = fb2
    lo, hi = np.minimum(0, b), np.maximum(0, b)
    def G(u, idx):
        i = idx.astype(int)
        return F(u * vm[i], idx) / np.abs(F0[i])
    tol = dict(xatol=K.XTOL, fatol=K.FTOL, xrtol=0, frtol=0)
    res = find_root(G, (lo / vm, hi / vm), args=(allidx,), tolerances=tol)
    res.x = res.x * vm
    n_ideal = 2 + np.round(np.log2(np.abs(b / vm))) + (res.nfev - 2)   # F0, F(vm), doublings, refinement
    # an ideal certificate: F monotone on [0, b] (400 samples)
    t = np.linspace(0, 1, 401)[1:]
    Fs = np.stack([F(b * tk, allidx) for tk in t])
    mono = np.all(np.diff(np.vstack([F0[None], Fs]), axis=0) * s[None] <= 0, axis=0)
T, D, Q, vi, conv = solve_reference(om, Vs, Vc, nd, p)
vref = vi.ravel()
same_root = np.abs(res.x - vref) <= 1e-5 * vm + 1e-9
kernel = float(np.sum(pm.rotor_loads(prop, p, om, V, inc).n_evaluations)) / (n * nr)
print(f"annuli {n*nr}; the kernel on the same points: {kernel:.2f} evaluations per annulus")
print(f"F monotone on [0, bracket end] by the scan: {mono.mean():.3f}; same root as the rule {same_root.mean():.4f}; "
      f"same root where monotone {same_root[mono].mean():.4f}")
print(f"scheme 1, evaluations per annulus (incl. F0) where monotone {n_ideal[mono].mean():.2f}, of which refinement "
      f"{np.mean(res.nfev[mono] - 2):.2f}; +1 for the multiple-roots scan")
tot1 = np.where(mono, n_ideal + 1, kernel)
print(f"scheme 1 overall, with the scan and the kernel's mean where not monotone: {tot1.mean():.2f}")

# scheme 2: the guess is the annulus inward's root (same point), bracket [0.95 g, 1.05 g]
with np.errstate(all="ignore"):
    vr = vref.reshape(n, nr)
    g = np.empty_like(vr); g[:, 0] = vm.reshape(n, nr)[:, 0]; g[:, 1:] = vr[:, :-1]
    g = g.ravel()
    a1, b1 = 0.95 * g, 1.05 * g
    fa1, fb1 = F(a1, allidx), F(b1, allidx)
    ok = (fa1 * fb1 < 0) & mono
    lo1, hi1 = np.minimum(a1, b1), np.maximum(a1, b1)
    r2 = find_root(G, (lo1[ok] / vm[ok], hi1[ok] / vm[ok]), args=(allidx[ok],), tolerances=tol)
    n_nb = 3 + (r2.nfev - 2)
    same2 = np.mean(np.abs(r2.x * vm[ok] - vref[ok]) <= 1e-5 * vm[ok])
    print(f"scheme 2 (the neighbour's root +-5%): brackets {np.mean(fa1 * fb1 < 0):.3f} of the annuli, "
          f"{ok.mean():.3f} both bracketed and monotone; evaluations there (F0 + 2 + refinement) {n_nb.mean():.2f}, "
          f"refinement {np.mean(r2.nfev - 2):.2f}; same root {same2:.4f}")
    # where the guess does not bracket: its two evaluations spent, then scheme 1; not monotone: the kernel
    tot2 = np.where(mono, 2 + n_ideal + 1, kernel)
    tot2[ok] = n_nb + 1
    print(f"scheme 2 overall, with the scan, scheme 1 where the guess does not bracket and the kernel where F is "
          f"not monotone: {tot2.mean():.2f}")


# scheme 3: F(0), F(v_m) (doubling as scheme 1 where it does not change sign), then the blade elements'
# side alone interpolated by a polynomial through the newest three points (two at first), and the
# next iterate the root of that polynomial less the momentum side, which is exact and costs no
# element evaluation (found here by bisection inside the bracket); it stops when the iterate moves
# less than XTOL v_m, returning it unevaluated. The ideal certificate as scheme 1.
def _poly_root(xs, bs, lo, hi, idx):
    """Root in [lo, hi] of the polynomial through (xs, bs) (shape (k, n)) less the momentum side."""
    k = xs.shape[0]
    coef = np.linalg.solve(np.stack([xs.T**p for p in range(k - 1, -1, -1)], axis=-1), bs.T[..., None])[..., 0]

    def g(v):
        return sum(coef[:, j] * v ** (k - 1 - j) for j in range(k)) - momentum(v, idx)

    a, b, ga = lo.copy(), hi.copy(), g(lo)
    for _ in range(80):  # bisection to round-off: the momentum side is cheap
        m = 0.5 * (a + b)
        gm = g(m)
        left = np.sign(gm) == np.sign(ga)
        a, ga, b = np.where(left, m, a), np.where(left, gm, ga), np.where(left, b, m)
    return 0.5 * (a + b)


with np.errstate(all="ignore"):
    B0 = bet(np.zeros(n * nr), allidx)
    xs, bs = [np.zeros(n * nr), b], [B0, fb + momentum(b, allidx)]
    n3 = 2 + np.round(np.log2(np.abs(b / vm)))  # F0, F(v_m) and the doublings, as scheme 1
    lo3, hi3 = np.minimum(0, b), np.maximum(0, b)
    root3 = np.full(n * nr, np.nan)
    todo = np.arange(n * nr)
    X, Bv = np.stack(xs), np.stack(bs)
    for _ in range(30):
        if todo.size == 0:
            break
        k = min(3, X.shape[0])
        vnew = _poly_root(X[-k:, todo], Bv[-k:, todo], lo3[todo], hi3[todo], allidx[todo])
        step = np.abs(vnew - X[-1, todo])
        stop = (step <= K.XTOL * vm[todo]) & (X.shape[0] > 2)
        root3[todo[stop]] = vnew[stop]
        todo, vnew = todo[~stop], vnew[~stop]
        bnew = bet(vnew, allidx[todo])
        n3[todo] += 1
        fnew = bnew - momentum(vnew, allidx[todo])
        below = fnew * s[todo] > 0  # the root lies beyond vnew (in the direction of sign F(0))
        pos = s[todo] > 0
        lo3[todo] = np.where(below == pos, vnew, lo3[todo])
        hi3[todo] = np.where(below == pos, hi3[todo], vnew)
        Xn, Bn = X[-1].copy(), Bv[-1].copy()
        Xn[todo], Bn[todo] = vnew, bnew
        X, Bv = np.vstack([X, Xn[None]]), np.vstack([Bv, Bn[None]])
    err3 = np.abs(root3 - vref) / vm
    print(f"scheme 3 (the elements' side interpolated, the momentum side exact): evaluations per annulus (incl. F0) "
          f"where monotone {n3[mono].mean():.2f}, everywhere {n3.mean():.2f}; largest root error {np.nanmax(err3):.1e} "
          f"v_m, not converged {int(np.sum(np.isnan(root3)))}; +1 for the multiple-roots scan")
    tot3 = np.where(mono, n3 + 1, kernel)
    print(f"scheme 3 overall, with the scan and the kernel's mean where not monotone: {tot3.mean():.2f}")
