"""Compiled (numba) per-point states and flags of a solved batch: the rotor's working state
(core/states.py's rules) and the result's five flags, written into the kernel's packed
outputs after the solve (``_kernel.solve_batch`` calls :func:`point_flags`; core/states.py
calls :func:`working_states` on its own).
"""

from __future__ import annotations

import numba
import numpy as np

from ._jitcache import CACHE  # before the decorators: installs the cache locators
from ._momentum import DREES_MU_MAX, inplane_induction

__all__ = ["CLS_BAND", "CLS_INPLANE", "CLS_K_WINDMILL", "CLS_R_HUB", "CLS_RADIUS", "CLS_RHO", "point_flags",
           "working_states"]

_inplane_induction = numba.njit(error_model="numpy", forceinline=True)(inplane_induction)


@numba.njit(cache=CACHE, error_model="numpy")
def working_states(T, vx, vz, vbar, rho, radius, band, k_windmill, linear, empirical, state, vh, k, m, extrap):
    """Per point: the rotor's working state and the inflow model's validity flag (no fastmath:
    NaN thrust and the sign of zero are kept as NumPy keeps them).

    The rules of core/states.py (:func:`propmap.core.states.descent_state`, its docstring),
    from the thrust ``T``, the in-plane and axial speeds ``vx`` = V sin(beta) and ``vz`` =
    V cos(beta) and the mean inflow ``vbar``: ``band`` holds (k_onset, k_exit, m_max,
    onset_exponent, exit_exponent) of Johnson's vortex-ring boundary; ``state`` gets 0 normal
    working, 1 vortex ring, 2 turbulent wake, 3 windmill brake; ``vh`` the hover induced
    velocity at the thrust (NaN where the thrust is NaN), ``k`` and ``m`` the descent and
    in-plane ratios (NaN without thrust). ``extrap`` (the solver's ``inflow_extrapolated``): a
    linear inflow model (``linear``) with net upflow through the disk, vz + v_mean < 0, in
    forward flight; and the empirical descent momentum (``empirical``) where its fade with the
    in-plane speed, exp(-(vx / v_mean)^2), is between 5% and 95% at k_onset <= k < ``k_windmill``.
    """
    k_on, k_ex, m_max, e_on, e_ex = band[0], band[1], band[2], band[3], band[4]
    c = 0.5 * (k_on + k_ex)
    h = 0.5 * (k_ex - k_on)
    area2 = 2.0 * rho * np.pi * (radius * radius)
    for i in range(T.size):
        t = T[i]
        v = np.nan if t != t else np.sqrt(max(t, 0.0) / area2) + 0.0  # + 0.0: T = -0 gives +0
        if v > 0.0:
            ki = -vz[i] / v + 0.0  # + 0.0: no -0 in hover
            mi = vx[i] / v
        else:
            ki = np.nan
            mi = np.nan
        s = 0
        if vz[i] < 0.0:
            if v == 0.0 or ki >= k_windmill:
                s = 3
            elif v > 0.0:
                if mi < m_max:
                    u = 1.0 - (mi / m_max) ** 2
                    if ki > c + h * u**e_ex:
                        s = 2
                    elif ki >= c - h * u**e_on:
                        s = 1
                elif vz[i] + vbar[i] < 0.0:
                    s = 3
        state[i] = s
        vh[i] = v
        k[i] = ki
        m[i] = mi
        x = linear and vz[i] + vbar[i] < 0.0 and vx[i] != 0.0
        if empirical and not x and ki >= k_on and ki < k_windmill:
            fade = np.exp(-(vx[i] / max(abs(vbar[i]), 1e-12)) ** 2)
            x = 0.05 < fade < 0.95
        extrap[i] = x


#: layout of ``cls``, the per-model constants of :func:`point_flags`: rho [kg/m^3], R [m], r_hub [m],
#: the windmill-brake descent ratio and the vortex-ring band (core/states.py)
CLS_RHO, CLS_RADIUS, CLS_R_HUB, CLS_K_WINDMILL, CLS_INPLANE, CLS_BAND = 0, 1, 2, 3, 4, 5


@numba.njit(cache=CACHE, error_model="numpy")
def point_flags(out, counts, vx, vz, om, cls, linear, empirical, flags, drees=False):
    """The result's per-point states and flags from the loads, written into the packed outputs
    (compiled after the solve: one NumPy comparison on a one-point array costs as much as this
    whole loop; no fastmath, as :func:`working_states`).

    Reads ``out`` rows 0 (T) and 6 (mean inflow), ``counts`` rows 0 (status) and 1 (annuli
    with multiple roots), ``vx``, ``vz`` = V sin(beta), V cos(beta) and ``om``, the rates the
    loads are for [rad/s]; ``cls`` as ``CLS_*``. Writes ``out`` rows 7-10 (v_h, the descent
    and in-plane ratios k and m, the reverse-flow radius V_b / Omega [m], V_b the blades'
    in-plane airspeed: V sin(beta), plus the skewed wake's in-plane induction at the mean
    inflow where ``cls[CLS_INPLANE]`` is 1 (airfoil.RotorOptions.inplane_induction,
    _momentum.inplane_induction); for a stopped rotor, Omega = 0, inf with in-plane flow, else
    0), ``counts`` row 4 (the working state) and ``flags`` shape (N_FLAGS, n): converged
    (status 0), vortex ring (state 1), multiple roots, reverse flow (radius > r_hub), inflow
    extrapolated (:func:`working_states`; with ``drees``, Drees's linear inflow, also where the
    advance ratio V sin(beta) / (Omega R) exceeds _momentum.DREES_MU_MAX, at which its gradients
    are held).
    """
    working_states(out[0], vx, vz, out[6], cls[CLS_RHO], cls[CLS_RADIUS], cls[CLS_BAND:], cls[CLS_K_WINDMILL],
                   linear, empirical, counts[4], out[7], out[8], out[9], flags[4])
    r_hub = cls[CLS_R_HUB]
    kin = cls[CLS_INPLANE]
    for i in range(vx.size):
        flags[0, i] = counts[0, i] == 0
        flags[1, i] = counts[4, i] == 1
        flags[2, i] = counts[1, i] > 0
        vb = vx[i]
        if kin != 0.0 and vx[i] != 0.0 and out[6, i] == out[6, i]:  # (not where the solve failed: NaN inflow)
            vb += kin * _inplane_induction(out[6, i], vx[i], vz[i])
        if om[i] > 0.0:
            r = vb / om[i]
        else:
            r = np.inf if vx[i] > 0.0 else 0.0
        out[10, i] = r
        flags[3, i] = r > r_hub
        if drees and vx[i] > DREES_MU_MAX * om[i] * cls[CLS_RADIUS]:  # Drees's gradients held at mu = 0.5
            flags[4, i] = True
