"""Airframe drag of a multirotor: quadratic per body axis, in the rotors' slipstream.

The force on the airframe is F_a = -(rho / 2) (C_D A)_a |u| u_a for each body axis a, with
u the velocity of the airframe relative to the air around it. Quadratic drag with a
constant drag area per axis is the flat-plate/bluff-body law (S. F. Hoerner, Fluid-Dynamic
Drag, 1965, Ch. 3); a per-axis drag area is the usual multirotor body-drag model (e.g. the
NeuroBEM authors' simulator: L. Bauersfeld et al., RSS 2021).

The airframe of a multirotor sits partly in its rotors' slipstream. Momentum theory puts
the slipstream velocity between v_i at the disk and 2 v_i far downstream (J. G. Leishman,
Principles of Helicopter Aerodynamics, 2nd ed., 2006, Sec. 2.2); the air around the
airframe therefore moves, relative to the rotors, along -axis at kappa v_i, kappa the
``wash_factor`` (0: the freestream alone). With the mean induced inflow of the rotors,
v_w = kappa <v_i,mean a_i> (a_i the rotor axes), u = V + v_w, V the airframe's velocity
relative to the undisturbed air. In hover this is the download -(rho/2) (C_D A)_z (kappa
v_i)^2; at a forward speed V much smaller than kappa v_i the in-plane drag is
-(rho/2) (C_D A)_x kappa v_i V, linear in V and growing with the rotor loading like the
measured "rotor drag" of small multirotors, and quadratic in V at speeds well above the
slipstream's. The combination is propmap's; its value was measured on real flights
(docs/flight.md), its drag areas and kappa are fitted there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._numbers import checked

__all__ = ["BodyDrag", "body_drag_force"]

#: valid ranges
DRAG_AREA_MAX = 10.0  # [m^2], each axis
WASH_FACTOR_MAX = 3.0  # [-]


@dataclass(frozen=True)
class BodyDrag:
    """Airframe drag: drag areas per body axis and the slipstream factor (module docstring).

    Parameters
    ----------
    drag_area : sequence of 3 floats
        (C_D A) along body x, y, z [m^2], each in [0, 10].
    wash_factor : float
        kappa [-], in [0, 3]: the slipstream velocity around the airframe in units of the
        rotors' mean induced inflow (0: freestream only; momentum theory: 1 at the disk, 2
        far downstream).

    Raises
    ------
    ValueError
        A value of the wrong type, non-finite or out of range (naming it).
    """

    drag_area: tuple = (0.0, 0.0, 0.0)
    wash_factor: float = 0.0

    def __post_init__(self) -> None:
        a = self.drag_area
        if isinstance(a, (str, bytes)) or not hasattr(a, "__len__") or len(a) != 3:
            raise ValueError(f"drag_area must be 3 numbers [m^2] (x, y, z), got {a!r:.60}")
        object.__setattr__(self, "drag_area", tuple(checked(f"drag_area[{k}]", v, 0.0, DRAG_AREA_MAX, unit="m^2")
                                                    for k, v in enumerate(a)))
        object.__setattr__(self, "wash_factor", checked("wash_factor", self.wash_factor, 0.0, WASH_FACTOR_MAX))

    @property
    def active(self) -> bool:
        """Whether any drag area is non-zero."""
        return any(v > 0 for v in self.drag_area)


def body_drag_force(body: BodyDrag, velocity, wash, rho: float) -> np.ndarray:
    """Airframe drag force in body axes [N] (module docstring).

    Parameters
    ----------
    body : BodyDrag
    velocity : ndarray, shape S + (3,)
        Velocity of the airframe relative to the undisturbed air, body axes [m/s].
    wash : ndarray, shape S + (3,)
        <v_i,mean a_i> over the rotors [m/s] (body axes): the rotors' mean induced inflow
        along their axes; the slipstream moves the air along -wash.
    rho : float
        Air density [kg/m^3].

    Returns
    -------
    ndarray, shape S + (3,)
        -(rho / 2) (C_D A) |u| u with u = velocity + kappa wash.
    """
    u = np.asarray(velocity, float) + body.wash_factor * np.asarray(wash, float)
    speed = np.linalg.norm(u, axis=-1, keepdims=True)
    return -0.5 * rho * np.asarray(body.drag_area) * speed * u
