"""Compiled (numba) BEMT kernel over a batch of operating points: per point the annuli's
section constants, their root solves (core/_annulus.py: eq 11 by the root-selection rule,
documented there and in docs/solver.md), the linear inflow's second solve and the swirl's
iteration (_momentum.swirl_target) around them, then the loads integrated over the annuli
(eqs 13-15) and the point's states and flags (core/_flags.py).
"""

from __future__ import annotations

import numba
import numpy as np

from ._annulus import (_FM, CAMBERED, NO_SWIRL_BALANCE, OK, _cambered_annulus, _inflow_gradients, _skew_inflow_ratio,
                       _swirl_step, _swirl_target, delay_factor, solve_annuli)
from ._annulus_loads import annulus_loads
from ._flags import point_flags
from ._jitcache import CACHE  # before the decorators: installs the cache locators
from ._physics import NODE_CFAC, NODE_CTH, NODE_CY2, NODE_SC, NODE_STH, NODE_TH, NODE_W, NODE_Y
from ._momentum import INFLOW_DREES, INFLOW_UNIFORM, SWIRL_LIMIT, SWIRL_MAX_ITER, SWIRL_SECANT_ITER, SWIRL_TOL


@numba.njit(error_model="numpy", fastmath=_FM, forceinline=True)
def _swirl_iterate(us, sw, v, code, multiple, nodes, blade, Om, Vs, Vc, sect, azim, grad, naz, model, pk, axial, it):
    """One swirl step of an operating point after its root solve with the swirl ``us``: every
    annulus' target (_momentum.swirl_target, from its loads at the roots ``v``) and imbalance
    g. An annulus is done when it balances to SWIRL_TOL Omega y, or when the iterates with
    g > 0 and g < 0 close in on each other to that width without a balance: the selected root
    jumps between branches there as u moves (a fold of eq 11), no balance exists on it, and
    the annulus keeps that u with its ``multiple`` flag raised. Others move to the next
    iterate (_momentum.swirl_step); ``sw`` (4, nr) keeps each annulus' previous iterate, its
    imbalance and the bracket's ends (NaN until known). True when every annulus is done (``us``
    is then the swirl the roots were solved with); on the last iteration those that are not
    get NO_SWIRL_BALANCE. ``nodes``, ``blade``, ``sect``, ``azim``, ``grad`` as
    _annulus.solve_annuli."""
    y = nodes[NODE_Y]
    cfac = nodes[NODE_CFAC]
    cy2 = nodes[NODE_CY2]
    nr = y.shape[0]
    all_done = True
    for j in range(nr):
        if code[j] != OK:
            continue
        t, _, q, _, _, _ = annulus_loads(v[j], y[j], Om, us[j], Vs, Vc, (blade[0, j], blade[1, j], blade[2, j]),
                                         (sect[0, j], sect[1, j], sect[2, j], sect[3, j]), cfac[j], azim, grad[0, j],
                                         grad[1, j], naz, model, pk, axial, delay_factor(pk, Om, y[j], cy2[j]))
        tol = SWIRL_TOL * Om * y[j]
        lim = SWIRL_LIMIT * Om * y[j]
        u = us[j]
        g = min(max(_swirl_target(v[j], t, q, y[j]), -lim), lim) - u
        lo = u if g > 0.0 else sw[2, j]
        hi = u if g < 0.0 else sw[3, j]
        nxt = u
        if abs(g) > tol:
            if lo == lo and hi == hi and abs(hi - lo) <= tol:
                multiple[j] = True  # the root jumps at this u: no balance on it
            else:
                all_done = False
                if it + 1 >= SWIRL_MAX_ITER:
                    code[j] = NO_SWIRL_BALANCE
                nxt = _swirl_step(u, g, sw[0, j], sw[1, j], lo, hi, it == 0, it >= SWIRL_SECANT_ITER, lim)
        sw[0, j] = u
        sw[1, j] = g
        sw[2, j] = lo
        sw[3, j] = hi
        us[j] = nxt
    return all_done


#: rows of the packed outputs of solve_batch: ``out`` (N_OUT, n), ``rad`` (N_RAD, rows, nr),
#: ``counts`` (N_COUNTS, n) and ``flags`` (N_FLAGS, n)
N_OUT = 11  # T, D, Q, M_R, Y, M_P, mean inflow; v_h, descent ratio k, in-plane ratio m, reverse-flow radius
N_RAD = 9  # v_i, dT, dD, dQ, dM_R, dY, dM_P, the swirl u (0 without it), the uniform solve's roots (linear inflow)
RAD_SWIRL = 7  # rad's row of the swirl u
RAD_UNIFORM = 8  # rad's row of the uniform solve's roots (a linear inflow model; else unused)
N_COUNTS = 5  # status, annuli with multiple roots, annuli in vortex ring, residual evaluations, working state
N_FLAGS = 5  # converged, vortex ring, multiple roots, reverse flow, inflow extrapolated


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM, forceinline=True)
def _solve_point(i, Om, Vs, Vc, coll, nodes, azim, model, pk, cam, inflow, emp, swirl, radius, radial, out, rad,
                 counts):
    """Solve the operating point ``i`` of a batch; results are written into column ``i`` of the
    output arrays.

    A function of its own, so that numba compiles its body once for :func:`solve_batch` and
    :func:`solve_batch_serial`, and outside the parallel region's passes; ``forceinline``
    has LLVM inline the compiled body into both loops. Measured on the 2-core AMD EPYC,
    2026-11-25 (benchmarks/README.md, "Compile time"): the cold compile of the parallel and
    the serial kernel took 229 + 124 s with the body inlined into each by numba, 18 + 65 s
    now; forward-flight points run 0.95x the time in the parallel kernel and 0.58x in the
    serial one, axial batches about 8% slower in the parallel kernel. A plain call instead
    (no ``forceinline``) compiled fastest but ran forward-flight batches 1.63x slower.

    Inputs Om, Vs, Vc and coll (a collective offset added to every blade angle [rad]) have
    shape (n,); ``nodes`` shape (N_NODE_ROWS, nr), the blade's node rows (_physics.NODE_Y ...;
    core/nodes.py): per annulus y, the weight w, the blade angle and its sine and cosine, the
    section constant sc (gill2017: the Blasius factor; cambered: ln(rho c / (mu Re_ref))),
    cy2 = (c/y)^2, cfac, mfac and the tip- and hub-loss constants ct, ch (negative: off);
    ``azim`` shape (2, 2 n_azimuth): sin psi and cos psi of the full circle of azimuth nodes, whose
    first half covers [-pi/2, pi/2] (enough for the uniform inflow, where every integrand
    depends on psi through sin psi only). ``model``, ``pk``: section model and
    constants (_physics); ``cam`` = (cl_alpha, re_exp, re_exp_lift, compressible, 1/a^2,
    re_exp_stall, stall_delay, alpha_L0_re) of the cambered model. ``inflow``: the inflow
    model (_momentum.INFLOW_*); ``emp``: the empirical momentum in descent (_momentum.DESCENT_CODES);
    with a linear model each point is solved twice: with the
    uniform inflow, whose mean inflow gives the wake skew angle and the gradients
    (_momentum.inflow_gradients), then with the linear inflow over the full circle.
    ``swirl``: the annuli's swirl u (_momentum.swirl_target) is iterated around these solves,
    by a bracketed secant per annulus from u = 0, until every annulus' angular momentum balances
    to SWIRL_TOL Omega y or its selected root is found to jump there (flagged as multiple roots;
    :func:`_swirl_iterate`); an annulus that does neither within SWIRL_MAX_ITER solves fails
    with NO_SWIRL_BALANCE. Without it u = 0 and each point is solved once.
    ``radius``: R [m]. Outputs (packed, to keep the argument list short):
    ``out`` shape (N_OUT, n), the rows T, D, Q, the rolling moment M_R,
    the side force Y, the pitching moment M_P and the area-weighted mean inflow (rows 7-10,
    the flags', are written by :func:`point_flags`); ``rad``
    shape (N_RAD, n, nr), the rows v_i, dT, dD, dQ, dM_R, dY, dM_P, the swirl u the roots
    were solved with (row RAD_SWIRL, 0 without swirl) and, with a linear inflow model, the
    uniform solve's roots of the last swirl iteration (row RAD_UNIFORM, which the caller need
    not allocate for the uniform inflow; NaN where that solve failed; the final ones at an
    axial point, solved once), whose mean inflow set the gradients
    (the derivatives' start, core/_linear_sensitivity.py), per annulus when ``radial``, else
    unused (pass shape (N_RAD, 1, nr)); ``counts`` shape (N_COUNTS, n) int64, the rows status,
    annuli with multiple roots, annuli in vortex ring, residual evaluations (row 4, the
    working state, is :func:`point_flags`').
    ``status`` is 0 when every annulus converged, else 1 + (first failing annulus index) *
    4 + (annulus status code).
    """
    y = nodes[NODE_Y]
    w = nodes[NODE_W]
    sc = nodes[NODE_SC]
    cy2 = nodes[NODE_CY2]
    cfac = nodes[NODE_CFAC]
    nr = y.shape[0]
    naz_half = azim.shape[1] // 2
    # the point's scratch in one block: rows 0-2 the blade angle, its sine and cosine; 3-6 the
    # section constants s0 ... s3; 7-8 the linear inflow's gradients gx, gy; 9-10 the roots and
    # the swirl when not written into ``rad``; 11-14 the swirl iteration's state (_swirl_iterate)
    work = np.empty((15 if swirl else 11, nr))
    blade = work[0:3]
    if coll[i] == 0.0:
        for j in range(nr):
            blade[0, j] = nodes[NODE_TH, j]
            blade[1, j] = nodes[NODE_STH, j]
            blade[2, j] = nodes[NODE_CTH, j]
    else:  # a per-point collective
        for j in range(nr):
            blade[0, j] = nodes[NODE_TH, j] + coll[i]
            blade[1, j] = np.sin(blade[0, j])
            blade[2, j] = np.cos(blade[0, j])
    axial = Vs[i] == 0.0
    # the roots are written straight into the output row, or into scratch
    v = rad[0, i] if radial else work[9]
    status = np.empty((2, nr), dtype=np.int64)  # per annulus: code, residual evaluations
    code = status[0]
    nev = status[1]
    multiple = np.empty(nr, dtype=np.bool_)
    sect = work[3:7]
    s0 = sect[0]
    s1 = sect[1]
    s2 = sect[2]
    s3 = sect[3]
    grad = work[7:9]
    gx = grad[0]
    gy = grad[1]
    sw = work[11:]
    sw[:] = np.nan
    if model == CAMBERED:
        # Reynolds, Mach and rotation corrections, once per point and annulus
        w2 = 0.5 * Vs[i] * Vs[i] + Vc[i] * Vc[i]
        for j in range(nr):
            s0[j], s1[j], s2[j], s3[j] = _cambered_annulus((Om[i] * y[j]) ** 2 + w2, sc[j], cy2[j], cam[4],
                                                           cam[0], cam[1], cam[2], cam[3] != 0.0, cam[5], cam[6],
                                                           cam[7])
    else:
        for j in range(nr):
            s0[j] = sc[j]
            s1[j] = 0.0
            s2[j] = 0.0
            s3[j] = 0.0
    us = rad[RAD_SWIRL, i] if radial else work[10]  # the annuli's swirl [m/s] (kept for the derivatives)
    us[:] = 0.0
    ne = 0
    for it in range(SWIRL_MAX_ITER if swirl else 1):
        naz = 1 if axial else naz_half  # axial: the integrand is independent of psi
        grad[:] = 0.0  # the uniform inflow first
        solve_annuli(Om[i], Vs[i], Vc[i], nodes, blade, us, sect, azim, grad, naz, model, pk, emp, v, status,
                     multiple)
        for j in range(nr):
            ne += nev[j]
        if inflow != INFLOW_UNIFORM and not axial:
            # the uniform solution's mean inflow sets the wake skew, then the linear inflow
            # is solved over the full circle (a second, independent root solve per annulus)
            vsum = 0.0
            wsum = 0.0
            for j in range(nr):
                vsum += w[j] * y[j] * v[j]
                wsum += w[j] * y[j]
            OmR = Om[i] * radius
            kx, ky = _inflow_gradients(Vs[i] / OmR, _skew_inflow_ratio(Vc[i], vsum / wsum, OmR), inflow)
            for j in range(nr):
                gx[j] = kx * y[j] / radius
                gy[j] = ky * y[j] / radius
            naz = 2 * naz_half
            if radial:  # the uniform roots, kept for the derivatives (into rad's row RAD_UNIFORM below)
                for j in range(nr):
                    work[9, j] = v[j] if code[j] == OK else np.nan
            solve_annuli(Om[i], Vs[i], Vc[i], nodes, blade, us, sect, azim, grad, naz, model, pk, emp, v, status,
                         multiple)
            for j in range(nr):
                ne += nev[j]
        if swirl and _swirl_iterate(us, sw, v, code, multiple, nodes, blade, Om[i], Vs[i], Vc[i], sect, azim, grad,
                                    naz, model, pk, axial, it):
            break
    Ti = 0.0
    Di = 0.0
    Qi = 0.0
    Ri = 0.0
    Yi = 0.0
    Pi = 0.0
    vsum = 0.0
    wsum = 0.0
    st = 0
    nm = 0
    nv = 0
    for j in range(nr):
        if multiple[j]:
            nm += 1
        if code[j] != OK:
            if st == 0:
                st = 1 + j * 4 + code[j]
            if radial:
                for q in range(1, RAD_SWIRL):  # the loads (the swirl and the uniform roots are kept)
                    rad[q, i, j] = np.nan
            continue
        if Vc[i] < 0.0 and Vc[i] + v[j] > 0.0:
            nv += 1
        t, d, q, rm, yf, pm = annulus_loads(v[j], y[j], Om[i], us[j], Vs[i], Vc[i],
                                            (blade[0, j], blade[1, j], blade[2, j]), (s0[j], s1[j], s2[j], s3[j]),
                                            cfac[j], azim, gx[j], gy[j], naz, model, pk, axial,
                                            delay_factor(pk, Om[i], y[j], cy2[j]))
        if radial:
            rad[1, i, j] = t
            rad[2, i, j] = d
            rad[3, i, j] = q
            rad[4, i, j] = rm
            rad[5, i, j] = yf
            rad[6, i, j] = pm
        Ti += w[j] * t
        Di += w[j] * d
        Qi += w[j] * q
        Ri += w[j] * rm
        Yi += w[j] * yf
        Pi += w[j] * pm
        vsum += w[j] * y[j] * v[j]
        wsum += w[j] * y[j]
    if radial and inflow != INFLOW_UNIFORM:  # the uniform roots (docstring)
        for j in range(nr):
            rad[RAD_UNIFORM, i, j] = v[j] if axial else work[9, j]
    out[0, i] = Ti if st == 0 else np.nan
    out[1, i] = Di if st == 0 else np.nan
    out[2, i] = Qi if st == 0 else np.nan
    out[3, i] = Ri if st == 0 else np.nan
    out[4, i] = Yi if st == 0 else np.nan
    out[5, i] = Pi if st == 0 else np.nan
    out[6, i] = vsum / wsum if st == 0 else np.nan
    counts[0, i] = st
    counts[1, i] = nm
    counts[2, i] = nv
    counts[3, i] = ne


@numba.njit(parallel=True, cache=CACHE, error_model="numpy", fastmath=_FM)
def solve_batch(Om, Vs, Vc, coll, nodes, azim, model, pk, cam, inflow, emp, swirl, radius, radial, cls, out, rad,
                counts, flags):
    """Solve every operating point (:func:`_solve_point`, in parallel over the cores by
    ``prange``), then :func:`point_flags` (``cls``, ``flags`` as there)."""
    for i in numba.prange(Om.shape[0]):  # i is unsigned here: cast, so that one compiled _solve_point serves both
        _solve_point(np.int64(i), Om, Vs, Vc, coll, nodes, azim, model, pk, cam, inflow, emp, swirl, radius, radial,
                     out, rad, counts)
    point_flags(out, counts, Vs, Vc, Om, cls, inflow != INFLOW_UNIFORM, emp, flags, inflow == INFLOW_DREES)


@numba.njit(cache=CACHE, error_model="numpy", fastmath=_FM)
def solve_batch_serial(Om, Vs, Vc, coll, nodes, azim, model, pk, cam, inflow, emp, swirl, radius, radial, cls, out, rad,
                       counts, flags):
    """:func:`solve_batch` on the calling thread: for small batches (solver.PARALLEL_MIN_POINTS),
    where starting the parallel region would cost more than the work; a process that only
    solves small batches then never starts the thread pool."""
    for i in range(Om.shape[0]):
        _solve_point(i, Om, Vs, Vc, coll, nodes, azim, model, pk, cam, inflow, emp, swirl, radius, radial, out, rad,
                     counts)
    point_flags(out, counts, Vs, Vc, Om, cls, inflow != INFLOW_UNIFORM, emp, flags, inflow == INFLOW_DREES)
