"""Rotor working states in descent: normal working, vortex ring, turbulent wake, windmill brake.

A rotor's state is a property of the whole rotor, judged from its descent rate and in-plane
speed against its hover induced velocity at the thrust it makes,
v_h = sqrt(T / (2 rho pi R^2)) (W. Johnson, Helicopter Theory, 1980, Sec. 4.1; J. G. Leishman,
Principles of Helicopter Aerodynamics, 2nd ed., 2006, Ch. 2):

    k = -V cos(beta) / v_h   (the descent ratio, lambda_2 in vertical descent),
    m = V sin(beta) / v_h    (the in-plane ratio).

* **windmill brake**: k >= 2, where momentum theory holds again (the flow through the disk is
  upward and smooth) and the empirical curve of the descent model meets Glauert's branch;
  also a descent fast enough in-plane (m >= 0.95, the band's closing speed below) with the mean
  flow through the disk upward (V cos beta + v_mean < 0): the wake is swept away, momentum
  theory holds and the rotor takes energy from the flow (an autogyro's state);
* **turbulent wake**: between the vortex-ring band and the windmill brake at low in-plane
  speed (m < 0.95, k < 2, outside the band on its high-descent side: k above its exit edge),
  which includes ideal autorotation (v_mean = -V cos beta, k about 1.8 in axial descent);
* **vortex ring**: inside the band in which the rotor's thrust fluctuates and the wake
  recirculates: the boundary of W. Johnson's vortex-ring-state model ("Model for Vortex Ring
  State Influence on Rotorcraft Flight Dynamics", NASA/TP-2005-213477, 2005, pp. 23-24; a
  boundary the report defines by the stability of the aircraft's vertical motion), which
  narrows with in-plane speed: with c = (k_N + k_X) / 2, h = (k_X - k_N) / 2,

      k_onset(m) = c - h (1 - (m / m_M)^2)^0.2,   k_exit(m) = c + h (1 - (m / m_M)^2)^1.5,

  k_N = 0.45 and k_X = 1.5 the onset and exit descent ratios in axial descent and m_M = 0.95
  the in-plane ratio at which the band closes (at k = 0.975). (Johnson's constants V_zN =
  -0.45, V_zX = -1.5, V_xM = 0.95 in units of v_h, as transcribed in the LADAC flight-dynamics
  library of TU Braunschweig, aerodynamics/rotorcraft/induced_velocity, not re-read from the
  report's pages.) A forward flight with a slight descent (m >= 0.95, or k < 0.45) is not in
  it;
* **normal working**: everything else (climb, hover, forward flight, slow descent).

The constants are in :data:`VRS_BAND`, the boundary in :func:`vrs_boundary`;
tests/test_states.py checks the region against them.
"""

from __future__ import annotations

import numpy as np

from . import _flags

__all__ = ["STATES", "VRS_BAND", "K_WINDMILL", "descent_state", "vrs_boundary"]

#: state names, in the order of the integer codes of ``descent_state``
STATES = ("normal working", "vortex ring", "turbulent wake", "windmill brake")
#: the vortex-ring boundary (Johnson 2005, module docstring): onset and exit descent ratios in
#: axial descent, the in-plane ratio at which the band closes, and the exponents of the onset
#: and exit edges
VRS_BAND = {"k_onset": 0.45, "k_exit": 1.5, "m_max": 0.95, "onset_exponent": 0.2, "exit_exponent": 1.5}
#: from this descent ratio on, the windmill-brake state (momentum theory valid again; Johnson's
#: end of the vortex-ring model in axial descent, V_zE = -2 v_h)
K_WINDMILL = 2.0


def vrs_boundary(m):
    """The vortex-ring band's edges at in-plane ratio ``m`` (Johnson 2005, module docstring).

    Parameters
    ----------
    m : array_like
        In-plane ratio V sin(beta) / v_h [-], >= 0 (any shape).

    Returns
    -------
    (k_onset, k_exit) : ndarray
        Descent ratios -V cos(beta) / v_h at which the band starts and ends, shape of ``m``;
        NaN where ``m >= VRS_BAND["m_max"]`` (no vortex ring at that in-plane speed) or ``m``
        is NaN.
    """
    b = VRS_BAND
    m = np.asarray(m, float)
    c = 0.5 * (b["k_onset"] + b["k_exit"])
    h = 0.5 * (b["k_exit"] - b["k_onset"])
    with np.errstate(invalid="ignore"):
        u = np.where(np.abs(m) < b["m_max"], 1.0 - (m / b["m_max"]) ** 2, np.nan)
        return c - h * u ** b["onset_exponent"], c + h * u ** b["exit_exponent"]


#: :data:`VRS_BAND` as the compiled kernel takes it
BAND_ARRAY = np.array([VRS_BAND[k] for k in ("k_onset", "k_exit", "m_max", "onset_exponent", "exit_exponent")])


def _classify(T, vx, vz, v_mean, rho, radius, linear=False, empirical=False):
    """The compiled rules (core/_flags.working_states) on flat float arrays of the thrust, the
    in-plane and axial speeds V sin(beta), V cos(beta) and the mean inflow: (state, v_h, k, m,
    inflow-validity flag)."""
    n = T.size
    state, vh, k, m = np.empty(n, np.int64), np.empty(n), np.empty(n), np.empty(n)
    extrap = np.empty(n, np.bool_)
    _flags.working_states(T, vx, vz, v_mean, float(rho), float(radius), BAND_ARRAY, K_WINDMILL, bool(linear),
                           bool(empirical), state, vh, k, m, extrap)
    return state, vh, k, m, extrap


def descent_state(thrust, airspeed, incidence, v_mean, rho: float, radius: float):
    """The working state of a rotor (module docstring).

    Parameters
    ----------
    thrust : array_like
        T [N].
    airspeed, incidence : array_like
        V [m/s] and beta [rad].
    v_mean : array_like
        Mean induced inflow over the disk [m/s]. The four broadcast together to a shape S.
    rho : float
        Air density [kg/m^3].
    radius : float
        R [m].

    Returns
    -------
    (state, v_h, k, m)
        ``state``: int codes into :data:`STATES`; ``v_h`` the hover induced velocity at the
        thrust [m/s] (0 where T <= 0); ``k`` the descent ratio and ``m`` the in-plane ratio
        (NaN where T <= 0). All shape S.
    """
    T, V, b, vm = np.broadcast_arrays(*(np.asarray(a, float) for a in (thrust, airspeed, incidence, v_mean)))
    shape = T.shape
    flat = [np.array(a, copy=True).reshape(-1) for a in (T, V * np.sin(b), V * np.cos(b), vm)]
    state, vh, k, m, _ = _classify(*flat, rho, radius)
    state, vh, k, m = (a.reshape(shape) for a in (state, vh, k, m))
    return state, vh, k, m
