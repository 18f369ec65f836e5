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

import contextlib
import contextvars
from typing import NamedTuple

import numpy as np

__all__ = ["FlapResult", "flap_damping", "flapping", "flapping_derivatives", "rigid_compliance_derivatives",
           "warn_large_flapping", "FlappingWarning", "flapping_warning_held", "large_flapping",
           "flapping_message", "COMPLIANCE", "FLAP_ANGLE_WARN"]

#: the name of the flap compliance 1 / K_beta among the derivatives' inputs
COMPLIANCE = "flap_compliance"
#: the flapping angle [rad] beyond which the small-angle model is warned of (14 deg: sin and cos then
#: 1% and 3% from their small-angle forms). A stopped or slow rotor's flap damping, which grows as
#: Omega^2, no longer holds the blades: with 50 rad/(N m) a stopped apce_8x6 at 50 m/s edgewise flapped
#: 4.25 rad, its side force 4.25 times its thrust (an edge-of-range audit, 2026-11-30); in forward
#: flight with 2 rad/(N m) at 800 rad/s, 0-20 m/s and 80 deg its largest is 0.11 rad.
FLAP_ANGLE_WARN = 0.25


class FlapResult(NamedTuple):
    """Loads of a flapping rotor (arrays of the input shape S).

    Attributes
    ----------
    drag, side_force : ndarray
        [N], as :class:`RotorLoads`, with the thrust tilted by the flapping.
    rolling_moment, pitching_moment : ndarray
        [N m], as :class:`RotorLoads`, the flap springs' moments.
    beta_1c, beta_1s : ndarray
        [rad] the longitudinal and lateral flapping (beta_1c < 0: tip-path plane tilted
        away from the in-plane motion).
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


class FlappingWarning(UserWarning):
    """Blades that flap beyond the first-harmonic flapping's small-angle range (:func:`warn_large_flapping`).

    A category of its own, for a user's warning filters; a search held by
    :func:`flapping_warning_held` does not raise it at its trial points.
    """


#: set by flapping_warning_held (per thread and task: a context variable, not the global warning filters)
_FLAPPING_HELD = contextvars.ContextVar("propmap_flapping_warning_held", default=False)


@contextlib.contextmanager
def flapping_warning_held():
    """Within the block, :func:`propmap.rotor_loads` does not warn of large flapping.

    For callers that try many parameter sets or rates on their way to one answer, and then say
    the warning once at the answer: a fit's trial points (a load fit that freed the flapping
    warned 21 times with other numbers, a wind-tunnel data audit, 2026-11-30), a trim's search
    (``propmap trim`` four times, a mutation audit, 2026-12-01). A context variable, as
    :func:`propmap.core.solver.supersonic_tips_allowed`: other threads keep their warning.

    Yields
    ------
    None
    """
    token = _FLAPPING_HELD.set(True)
    try:
        yield
    finally:
        _FLAPPING_HELD.reset(token)


def warn_large_flapping(beta_1c, beta_1s, compliance: float, stacklevel: int = 3) -> None:
    """Warn where a flapping angle exceeds :data:`FLAP_ANGLE_WARN`: the first-harmonic model is
    linear in the angles (the thrust tilted by them, module docstring), so there the in-plane
    loads D and Y and the hub moments grow without the bound a real blade's would have.

    Parameters
    ----------
    beta_1c, beta_1s : ndarray
        Flapping angles [rad] (:func:`flapping`), any common shape.
    compliance : float
        1 / K_beta [rad/(N m)], for the message.
    stacklevel : int
        As :func:`warnings.warn` (3: the caller of the function that calls this one).

    Warns
    -----
    FlappingWarning
        A UserWarning naming how many points and the largest angle.
    """
    import warnings

    if _FLAPPING_HELD.get():
        return
    n, largest = large_flapping(beta_1c, beta_1s)
    if n:
        warnings.warn(flapping_message(n, largest, compliance), FlappingWarning, stacklevel=stacklevel)


def large_flapping(beta_1c, beta_1s) -> tuple[int, float]:
    """How many points flap beyond FLAP_ANGLE_WARN, and the largest angle.

    For :func:`warn_large_flapping` and a caller that sums them over chunks of points
    (``propmap loads --points``).

    Parameters
    ----------
    beta_1c, beta_1s : array_like
        Flapping angles [rad], any common shape.

    Returns
    -------
    (int, float)
        The count of points whose flapping magnitude exceeds FLAP_ANGLE_WARN, and the largest
        magnitude [rad] (0 and 0.0 where there are no points).
    """
    big = np.hypot(np.asarray(beta_1c, float), np.asarray(beta_1s, float))
    return int(np.count_nonzero(big > FLAP_ANGLE_WARN)), float(np.max(big, initial=0.0))


def flapping_message(n: int, largest: float, compliance: float) -> str:
    """The text of a :class:`FlappingWarning`.

    Parameters
    ----------
    n : int
        Points flapping beyond FLAP_ANGLE_WARN.
    largest : float
        The largest flapping magnitude [rad].
    compliance : float
        The blades' flap compliance [rad/(N m)].

    Returns
    -------
    str
        The message, one line.
    """
    return (f"flapping: {n} point(s) flap by more than {FLAP_ANGLE_WARN:g} rad (largest {largest:.3g} rad, "
            f"flap_compliance {compliance:g} rad/(N m)): the first-harmonic flapping is a small-angle model, so their "
            "drag, side force and hub moments there are beyond it (a stopped or slow rotor's flap damping, which "
            "grows as Omega^2, no longer holds the blades; docs/models.md, Blade flapping)")


def flapping_derivatives(jac: dict, thrust, rolling_moment, damping, compliance: float, n_blades: int, *, omega,
                         rho: float, lift_slope: tuple, pitching_moment=0.0) -> dict:
    """The flapping rotor's load derivatives from the rigid rotor's, by the chain rule.

    :func:`flapping` is applied to the converged rigid loads and changes the drag, the side
    force and both hub moments: with M_1s = 2 M_R / N_b, M_1c = -2 M_P / N_b (the rigid
    rotor's moments), det = K^2 + D_beta^2,

        beta_1c = (K M_1c - D_beta M_1s) / det,   beta_1s = (K M_1s + D_beta M_1c) / det,
        D_flap = D - T beta_1c,   Y_flap = Y - T beta_1s,
        M_R,flap = (N_b / 2) K beta_1s,   M_P,flap = -(N_b / 2) K beta_1c,

    differentiated term by term, with D_beta = (rho a / 2) Omega^2 int c r^3 dr changing with
    Omega, rho and the lift slope a. With respect to the compliance c = 1 / K (dK/dc = -K^2,
    the rigid loads and D_beta fixed): d beta_1c/dK = (M_1c - 2 K beta_1c) / det and
    d beta_1s/dK = (M_1s - 2 K beta_1s) / det; thrust, torque and the mean inflow do not
    depend on it. With the uniform inflow the rigid M_P and Y vanish (M_1c = 0); a linear
    inflow model gives them (core/_linear_sensitivity.py). (At c = 0, rigid blades:
    :func:`rigid_compliance_derivatives`.)

    Parameters
    ----------
    jac : dict
        {(load, name): derivative} of the rigid rotor (core/derivatives._jacobian), loads
        among ``thrust, drag, torque, rolling_moment, v_i_mean`` and, where the rigid rotor has
        them (a linear inflow), ``side_force, pitching_moment`` (absent: 0); flat arrays of N
        points. Changed in place and returned, with ``(load, "flap_compliance")`` added when
        ``COMPLIANCE`` is among the names (pass its entries as zeros), and
        ``("side_force", name)`` and ``("pitching_moment", name)`` for every name.
    thrust, rolling_moment : ndarray, shape (N,)
        The rigid rotor's T [N] and M_R [N m].
    damping : ndarray, shape (N,)
        D_beta [N m/rad] (:func:`flap_damping`).
    compliance : float
        1 / K_beta [rad/(N m)], > 0.
    n_blades : int
    omega : ndarray, shape (N,)
        Rotation rates [rad/s] (D_beta grows as Omega^2).
    rho : float
        Air density [kg/m^3] (D_beta grows with it).
    lift_slope : (str, ndarray)
        The parameter that is the lift slope a of D_beta (``cl_alpha``, ``cl1`` or ``cl2``;
        core/nodes._lift_slope_name) and dD_beta/da = (rho / 2) Omega^2 int c r^3 dr
        [N m], shape (N,) (:func:`flap_damping` with a = 1).
    pitching_moment : ndarray, shape (N,), or float
        The rigid rotor's M_P [N m] (0, default: the uniform inflow's).

    Returns
    -------
    dict
        ``jac`` with the flapping rotor's drag, side-force, rolling-moment and
        pitching-moment derivatives.

    Raises
    ------
    ZeroDivisionError
        ``compliance`` 0 (rigid blades have no flapping to differentiate: do not call).
    """
    K = 1.0 / compliance
    T, Db = np.asarray(thrust), np.asarray(damping)
    M1s = 2.0 * np.asarray(rolling_moment) / n_blades
    M1c = -2.0 * np.asarray(pitching_moment) / n_blades
    det = K * K + Db * Db
    b1c = (K * M1c - Db * M1s) / det
    b1s = (K * M1s + Db * M1c) / det
    half = 0.5 * n_blades
    # dD_beta/dx of what it depends on
    a = {"omega": 2.0 * Db / np.asarray(omega), "rho": Db / rho, lift_slope[0]: np.asarray(lift_slope[1])}
    names = list(dict.fromkeys(w for (_, w) in jac))  # (in the caller's order: a set's depended on the hash seed)
    for w in names:
        if w == COMPLIANCE:
            kk = -K * K  # dK/dc
            db1c = kk * (M1c - 2.0 * K * b1c) / det
            db1s = kk * (M1s - 2.0 * K * b1s) / det
            jac[("drag", w)] = -T * db1c
            jac[("side_force", w)] = -T * db1s
            jac[("rolling_moment", w)] = half * (kk * b1s + K * db1s)
            jac[("pitching_moment", w)] = -half * (kk * b1c + K * db1c)
            continue
        dDb = a.get(w, 0.0)
        dM1s = 2.0 * jac[("rolling_moment", w)] / n_blades
        dM1c = -2.0 * jac.get(("pitching_moment", w), 0.0) / n_blades
        ddet = 2.0 * Db * dDb
        db1c = (K * dM1c - dDb * M1s - Db * dM1s - b1c * ddet) / det
        db1s = (K * dM1s + dDb * M1c + Db * dM1c - b1s * ddet) / det
        dT = jac[("thrust", w)]
        jac[("drag", w)] = jac[("drag", w)] - dT * b1c - T * db1c
        jac[("side_force", w)] = jac.get(("side_force", w), 0.0) - dT * b1s - T * db1s
        jac[("rolling_moment", w)] = half * K * db1s
        jac[("pitching_moment", w)] = -half * K * db1c
    return jac


def rigid_compliance_derivatives(thrust, rolling_moment, damping, n_blades: int, pitching_moment=0.0) -> dict:
    """Rigid blades' (compliance 0) load derivatives with respect to ``flap_compliance``.

    As c = 1 / K -> 0 the flap angles grow as c (:func:`flapping_derivatives`' notation):
    beta_1c = c M_1c, beta_1s = c M_1s to first order, and the hub moments change as
    M_R = (N_b / 2) (M_1s + c D_beta M_1c), M_P = -(N_b / 2) (M_1c - c D_beta M_1s), so
    dD/dc = -T M_1c = 2 T M_P / N_b, dY/dc = -T M_1s = -2 T M_R / N_b, dM_R/dc = -D_beta M_P
    and dM_P/dc = D_beta M_R (with the uniform inflow M_P = 0: the drag and the rolling moment
    change as c^2, derivative 0).

    Parameters
    ----------
    thrust, rolling_moment, damping : ndarray, shape (N,)
        The rigid rotor's T [N], M_R [N m] and D_beta [N m/rad] (:func:`flap_damping`).
    n_blades : int
    pitching_moment : ndarray, shape (N,), or float
        The rigid rotor's M_P [N m] (0, default: the uniform inflow's).

    Returns
    -------
    dict
        {(load, "flap_compliance"): shape (N,)} for thrust, drag, torque, rolling_moment,
        v_i_mean (zeros), side_force and pitching_moment.
    """
    T, R = np.asarray(thrust, float), np.asarray(rolling_moment, float)
    P = np.broadcast_to(np.asarray(pitching_moment, float), T.shape)
    Db = np.asarray(damping)
    zero = np.zeros(T.shape)
    out = {(q, COMPLIANCE): zero.copy() for q in ("thrust", "torque", "v_i_mean")}
    out[("drag", COMPLIANCE)] = 2.0 * T * P / n_blades
    out[("rolling_moment", COMPLIANCE)] = -Db * P
    out[("side_force", COMPLIANCE)] = -2.0 * T * R / n_blades
    out[("pitching_moment", COMPLIANCE)] = Db * R
    return out
