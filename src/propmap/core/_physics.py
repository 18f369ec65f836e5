"""The blade-element integrand, written once for both back ends.

Only arithmetic, NumPy ufuncs and the injected atan2/exp are used, so the same function
runs elementwise on NumPy arrays (the vectorised reference in ``_reference.py``) and on
scalars inside numba-compiled loops (``_kernel.py``). Every other piece of physics is
built on it.

Gill & D'Andrea (2017), eqs (1)-(7). With phi = atan2(U_P, U_T) (NUMERICS.md item 4:
the four-quadrant angle is the physical choice in reverse flow) we have exactly
U cos(phi) = U_T and U sin(phi) = U_P, so the rotations of eqs (5)-(7) need no
trigonometry:

    U^2 (C_L cos phi - C_D sin phi) = U (C_L U_T - C_D U_P)      (thrust, eq 5)
    U^2 (C_L sin phi + C_D cos phi) = U (C_L U_P + C_D U_T)      (in-plane, eqs 6, 7)

and sin(alpha), cos(alpha) of alpha = theta - phi follow from sin/cos of theta.

The element is built by ``make_element(atan2, exp_sat)`` so that each back end supplies
its own angle and exponential: NumPy's ufuncs here, the branch-free polynomials of
``_fastmath.py`` in the compiled kernel (so that its azimuth loop vectorises).
"""

from __future__ import annotations

import numpy as np

from ._fastmath import EXP_CLIP  # |exponent| beyond which the stall blend equals its limit

TWO_PI = 2.0 * np.pi


def exp_sat_numpy(z):
    """``exp(clip(z, -40, 40))`` elementwise (the NumPy twin of ``_fastmath.exp_sat``)."""
    return np.exp(np.clip(z, -EXP_CLIP, EXP_CLIP))


def make_element(atan2, exp_sat):
    """Return ``element`` using the given four-quadrant arctangent and saturated exp."""

    def element(UT, UP, theta, sin_th, cos_th, kre, cl1, cl2, cd, alpha0, M, cd0, sincos):
        """Per-unit-span section loads without the factor 0.5 rho c.

        Parameters
        ----------
        UT, UP : float or ndarray
            Tangential and perpendicular velocity seen by the section [m/s], eqs (1)-(2).
        theta, sin_th, cos_th : float or ndarray
            Blade angle [rad] and its sine and cosine.
        kre : float or ndarray
            Reynolds factor 2 * 1.02 c_p sqrt(mu / (rho c)) [sqrt(m/s)], so that the
            Blasius term of eq (4) is ``kre / sqrt(U)``.
        cl1, cl2, cd, alpha0, M, cd0 : float
            Airfoil parameters (eqs 3-4).
        sincos : bool
            Use footnote 1's ``C_L = cl2 sin a cos a`` instead of eq (3).

        Returns
        -------
        qT, qH : float or ndarray
            ``U (C_L U_T - C_D U_P)`` (along the rotor axis) and ``U (C_L U_P + C_D U_T)``
            (in the disk plane, opposing the blade's motion) [m^2/s^2].
        """
        U = np.sqrt(UT * UT + UP * UP + 1e-300)
        alpha = theta - atan2(UP, UT)
        # keep alpha in (-pi, pi] so that the linear pre-stall term sees the wrapped angle
        alpha = alpha - TWO_PI * (alpha > np.pi) + TWO_PI * (alpha < -np.pi)
        sin_a = (sin_th * UT - cos_th * UP) / U
        cos_a = (cos_th * UT + sin_th * UP) / U
        post = cl2 * sin_a * cos_a
        if sincos:
            CL = post
        else:
            # eq (3), sigma = 1 - 1/((1+p)(1+q)), p = exp(M(a - a0)), q = exp(-M(a + a0));
            # the exponents are clipped to +-40, where sigma equals its limits in double.
            p = exp_sat(M * (alpha - alpha0))
            q = exp_sat(-M * (alpha + alpha0))
            s = 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))
            CL = (1.0 - s) * cl1 * alpha + s * post
        CD = cd * sin_a * sin_a + kre / np.sqrt(U) + cd0  # eq (4)
        return U * (CL * UT - CD * UP), U * (CL * UP + CD * UT)

    return element


element = make_element(np.arctan2, exp_sat_numpy)


def momentum_thrust(v, mom_fac, Vs, Vc):
    """dT_BEMT/dy of eq (10), Glauert mass flow, no extra sign flip (NUMERICS.md item 3).

    ``mom_fac = 4 pi rho y``; returns ``mom_fac * v * sqrt(Vs^2 + (Vc + v)^2)`` [N/m].
    """
    return mom_fac * v * np.sqrt(Vs * Vs + (Vc + v) * (Vc + v))


def momentum_scale(B0, mom_fac, Vs, Vc):
    """Inflow scale v_m [m/s] used to size the root march.

    Approximates |v| solving ``v sqrt(W^2 + v^2) = |B0| / mom_fac`` with W^2 = Vs^2 + Vc^2:
    ``v_m = k / sqrt(W^2 + k)``, k = |B0|/mom_fac, exact in hover (sqrt k) and in fast
    flight (k / W). A floor of 1e-6 m/s keeps the step positive.
    """
    k = np.abs(B0) / mom_fac
    return np.maximum(k / np.sqrt(Vs * Vs + Vc * Vc + k + 1e-300), 1e-6)
