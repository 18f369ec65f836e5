"""Quasi-static first-harmonic blade flapping of a centre-spring equivalent rotor.

Each blade flaps about the hub against a spring K_beta (the centre-spring equivalent rotor
of G. D. Padfield, Helicopter Flight Dynamics, 2nd ed., Blackwell, 2007, Sec. 3.2.1). Its
flap equation, with psi the azimuth and ' = d/dpsi, is

    I_beta Omega^2 (beta'' + nu^2 beta) = M_aero(psi),   nu^2 = 1 + K_beta / (I_beta Omega^2)

(W. Johnson, Helicopter Theory, Princeton University Press, 1980, Sec. 5.2 and 9.2). At the
rotation frequency (1/rev) the centrifugal stiffness I_beta Omega^2 and the blade inertia
cancel, so the steady first harmonics beta = beta_1c cos psi + beta_1s sin psi depend only
on the spring and on the aerodynamics. Linearised about the rigid blade, the aerodynamic
moment is the rigid blade's plus the damping of the flap velocity, whose element moment
r dT changes by d(dT)/dU_P r Omega beta' with d(dT)/dU_P = -(rho/2) c a U_T (attached flow,
U_T ~ Omega r):

    M_aero = M_rigid(psi) - D_beta beta',   D_beta = (rho a / 2) Omega^2 int c r^3 dr

(for a constant chord and a blade from the hub D_beta = I_beta Omega^2 gamma / 8, gamma the
Lock number). Balancing the cos psi and sin psi terms:

    K beta_1c + D beta_1s = M_1c,   -D beta_1c + K beta_1s = M_1s,

with M_1c, M_1s the first harmonics of one rigid blade's flap moment, which the azimuth
integration gives as the pitching moment and the rolling moment of the rigid rotor:
M_1s = 2 M_R / N_b, M_1c = -2 M_P / N_b (docs/conventions.md). The coning, the flap-lag
coupling, the aerodynamic spring mu beta cos psi and the change of the inflow with the
tip-path-plane tilt are left out (second order in the flap angles or in mu).

Consequences, small angles (n the tip-path-plane normal, e_ip the in-plane direction of
the disk's motion):

* the thrust acts along n = z + beta_1c e_ip + spin beta_1s (z x e_ip): the rotor drag
  grows by -T beta_1c and the side force (toward the advancing side) by -T beta_1s;
* the hub moment is the springs': M_R = (N_b/2) K beta_1s, M_P = -(N_b/2) K beta_1c.

K -> infinity (compliance 0) gives back the rigid blade exactly; K = 0 an articulated rotor
without hinge offset, whose longitudinal flapping beta_1c = -M_1s / D_beta is the classical
blow-back of the disk away from the in-plane motion (Johnson 1980, Sec. 5.2).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["FlapResult", "flap_damping", "flapping"]


class FlapResult(NamedTuple):
    """Loads of a flapping rotor (arrays of the input shape).

    drag, side_force [N], rolling_moment, pitching_moment [N m]: as RotorLoads, with the
    tilted thrust and the spring moments; beta_1c, beta_1s [rad]: the longitudinal and
    lateral flapping (beta_1c < 0: tip-path plane tilted away from the in-plane motion).
    """

    drag: np.ndarray
    side_force: np.ndarray
    rolling_moment: np.ndarray
    pitching_moment: np.ndarray
    beta_1c: np.ndarray
    beta_1s: np.ndarray


def flap_damping(rho: float, lift_slope: float, chord_r3: float, omega):
    """Aerodynamic flap damping D_beta = (rho a / 2) Omega^2 int c r^3 dr [N m/rad].

    Parameters
    ----------
    rho : float
        Air density [kg/m^3].
    lift_slope : float
        Attached-flow section lift slope a [1/rad].
    chord_r3 : float
        int c(r) r^3 dr over the blade [m^5].
    omega : float or ndarray
        Rotation rate Omega [rad/s].

    Returns
    -------
    float or ndarray
        D_beta, the shape of ``omega``.
    """
    return 0.5 * rho * lift_slope * chord_r3 * np.asarray(omega) ** 2


def flapping(thrust, drag, side_force, rolling_moment, pitching_moment, damping, compliance: float,
             n_blades: int) -> FlapResult:
    """Loads of a rotor whose blades flap against a hub spring (module docstring).

    Parameters
    ----------
    thrust, drag, side_force, rolling_moment, pitching_moment : ndarray
        The rigid rotor's loads [N, N m] (RotorLoads), any common shape S.
    damping : ndarray
        D_beta [N m/rad] (:func:`flap_damping`), shape S or broadcastable.
    compliance : float
        1 / K_beta [rad/(N m)], > 0 (0 means rigid: do not call).
    n_blades : int

    Returns
    -------
    FlapResult
        Arrays of shape S.
    """
    K = 1.0 / compliance
    D = np.asarray(damping)
    M1s = 2.0 * np.asarray(rolling_moment) / n_blades
    M1c = -2.0 * np.asarray(pitching_moment) / n_blades
    det = K * K + D * D
    b1c = (K * M1c - D * M1s) / det
    b1s = (K * M1s + D * M1c) / det
    T = np.asarray(thrust)
    half = 0.5 * n_blades * K
    return FlapResult(drag=np.asarray(drag) - T * b1c, side_force=np.asarray(side_force) - T * b1s,
                      rolling_moment=half * b1s, pitching_moment=-half * b1c, beta_1c=b1c, beta_1s=b1s)
