"""Rotor working states in descent: normal working, vortex ring, turbulent wake, windmill brake.

A rotor's state is a property of the whole rotor, judged from its descent rate and in-plane
speed against its hover induced velocity at the thrust it makes,
v_h = sqrt(T / (2 rho pi R^2)) (W. Johnson, Helicopter Theory, 1980, Sec. 4.1; J. G. Leishman,
Principles of Helicopter Aerodynamics, 2nd ed., 2006, Ch. 2):

    k = -V cos(beta) / v_h   (the descent ratio, lambda_2 in vertical descent),
    m = V sin(beta) / v_h    (the in-plane ratio).

* **windmill brake**: k >= 2, where momentum theory holds again (the flow through the disk is
  upward and smooth) and the empirical curve of the descent model meets Glauert's branch;
  also a descent fast enough in-plane (m >= 0.9, the band's closing speed below) with the mean
  flow through the disk upward (V cos beta + v_mean < 0): the wake is swept away, momentum
  theory holds and the rotor takes energy from the flow (an autogyro's state);
* **turbulent wake**: between the vortex-ring band and the windmill brake at low in-plane
  speed (m < 0.9, k < 2, outside the band on its high-descent side: k above the band's centre),
  which includes ideal autorotation (v_mean = -V cos beta, k about 1.8 in axial descent);
* **vortex ring**: inside the band in which the measured rotors' thrust fluctuates and the
  wake recirculates: an ellipse in (m, k) through descent rates 0.3 v_h and 1.5 v_h in axial
  descent, closing at an in-plane speed of 0.9 v_h (the classical band that summaries of the
  measured boundaries give, e.g. W. Johnson, "Model for Vortex Ring State Influence on
  Rotorcraft Flight Dynamics", NASA/TP-2005-213477, 2005; the ellipse's shape between those
  limits is propmap's). A forward flight with a slight descent (m >= 0.9, or k < 0.3) is not
  in it;
* **normal working**: everything else (climb, hover, forward flight, slow descent).

The constants are in :data:`VRS_BAND`; tests/test_states.py checks the region against them.
"""

from __future__ import annotations

import numpy as np

__all__ = ["STATES", "VRS_BAND", "descent_state"]

#: state names, in the order of the integer codes of ``descent_state``
STATES = ("normal working", "vortex ring", "turbulent wake", "windmill brake")
#: the vortex-ring band: descent ratio k from 0.3 to 1.5 in axial descent, in-plane ratio m
#: below 0.9 (summaries of the measured boundaries, module docstring)
VRS_BAND = {"k_min": 0.3, "k_max": 1.5, "m_max": 0.9}
#: from this descent ratio on, the windmill-brake state (momentum theory valid again)
K_WINDMILL = 2.0


def descent_state(thrust, airspeed, incidence, v_mean, rho: float, radius: float):
    """The working state of a rotor (module docstring).

    Parameters
    ----------
    thrust : ndarray
        T [N] (any shape S).
    airspeed, incidence : ndarray
        V [m/s] and beta [rad], shape S.
    v_mean : ndarray
        Mean induced inflow over the disk [m/s], shape S.
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
    T = np.asarray(thrust, float)
    V = np.asarray(airspeed, float)
    b = np.asarray(incidence, float)
    vz = V * np.cos(b)
    vx = V * np.sin(b)
    with np.errstate(invalid="ignore", divide="ignore"):
        vh = np.sqrt(np.maximum(T, 0.0) / (2.0 * rho * np.pi * radius**2))
        k = np.where(vh > 0, -vz / vh, np.nan) + 0.0  # + 0.0: no -0 in hover
        m = np.where(vh > 0, vx / vh, np.nan)
        band = VRS_BAND
        centre = 0.5 * (band["k_min"] + band["k_max"])
        half = 0.5 * (band["k_max"] - band["k_min"])
        in_ellipse = ((k - centre) / half) ** 2 + (m / band["m_max"]) ** 2 <= 1.0
    state = np.zeros(np.shape(T), dtype=np.int64)
    descending = (vz < 0) & (vh > 0)
    slow = m < band["m_max"]  # NaN (no thrust) compares False
    upflow = vz + np.asarray(v_mean, float) < 0
    state = np.where(descending & slow & in_ellipse, 1, state)
    state = np.where(descending & slow & ~in_ellipse & (k > centre), 2, state)
    state = np.where(descending & ~slow & upflow, 3, state)
    state = np.where((vz < 0) & ((vh == 0) | (k >= K_WINDMILL)), 3, state)
    return state, vh, k, m
