"""The vehicle model's derivatives (``vehicle_wrench(derivatives=...)``, vehicle/model.py): each
rotor's implicit load derivatives (docs/solver.md) carried through the vector sums, the arms,
the gyroscopic moment and the airframe drag (core/body.py), and the Jacobians with respect to
the vehicle's motion and centre of mass through the hub velocities V_i = v + w x r_i - wind.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..core.body import BodyDrag
from ..core.vector import velocity_gradient, velocity_jacobian, wrench_vectors

if TYPE_CHECKING:  # (model.py imports this module)
    from .layout import Vehicle

__all__ = ["BODY_DRAG_NAMES", "MOTION_NAMES", "cross_matrix", "drag_jacobian", "hub_velocity_jacobians",
           "load_derivatives", "motion_derivatives", "requested_derivatives"]

#: the airframe terms vehicle_wrench differentiates (core/body.py)
BODY_DRAG_NAMES = ("drag_area_x", "drag_area_y", "drag_area_z", "wash_factor")
#: the vehicle's motion and its centre of mass, whose Jacobians (shape (N, 3, 3)) vehicle_wrench gives
MOTION_NAMES = ("velocity", "angular_velocity", "centre_of_mass")


def requested_derivatives(derivatives, vehicle: Vehicle, params=None) -> tuple:
    """The names ``vehicle_wrench(derivatives=...)`` asks for (() for none); with ``params``
    a name that is neither the vehicle's nor a field of the set is refused here (the section
    parameters' values are checked by rotor_loads)."""
    if isinstance(derivatives, np.bool_):  # (np.True_ was refused as not a sequence: an audit)
        derivatives = bool(derivatives)
    if derivatives is False or derivatives is None:
        return ()
    if derivatives is True:
        return ("omega",)
    if isinstance(derivatives, str) or not hasattr(derivatives, "__iter__"):
        raise ValueError(f"derivatives must be True, False or a sequence of names, got {derivatives!r:.60}")
    wrt = tuple(dict.fromkeys(derivatives))
    bad = [n for n in wrt if n in ("airspeed", "incidence")]
    if bad:
        raise ValueError(f"derivatives: {bad[0]!r} is a rotor's input, not the vehicle's; use 'omega', "
                         "'velocity', 'angular_velocity', 'centre_of_mass', a section parameter or an airframe term")
    own = ("omega", "rho", *BODY_DRAG_NAMES, *MOTION_NAMES)
    if params is not None:
        from dataclasses import fields

        field_names = {f.name for f in fields(params)}
        unknown = [n for n in wrt if n not in own and n not in field_names]
        if unknown:
            raise ValueError(f"derivatives: unknown name {unknown[0]!r:.60}; valid for a vehicle: {', '.join(own)} "
                             f"or a numeric field of {type(params).__name__}")
    if any(n not in own for n in wrt) and any(r.params is not None for r in vehicle.rotors):
        raise ValueError("derivatives with respect to a section parameter need every rotor on the set passed "
                         "(a rotor of this vehicle has its own)")
    return wrt


def load_derivatives(wrt, vehicle, loads, batches, axes, pos, w, body, v_air, wash, rho):
    """(dF/dOmega_i, dM/dOmega_i) of shape (N, 3, n_rot) where "omega" is asked (else None), and
    {("force" | "moment", name): shape (N, 3)} for the other names (else None): the rotors'
    load derivatives through the vector form (linear in the scalar loads), the arms, the
    gyroscopic moment -w x (s_i J_i a_i) and the airframe drag (core/body.py). ``batches`` as
    :func:`hub_velocity_jacobians`: each rotor's disk frame is its batch's column."""
    n_rot = len(vehicle.rotors)
    others = [n for n in wrt if n != "omega" and n not in MOTION_NAMES]
    if "omega" not in wrt and not others:  # the motion names only: motion_derivatives
        return None, None, None
    frames = [None] * n_rot
    for idx, _, Vd, z in batches:
        for k, i in enumerate(idx):
            frames[i] = (Vd[:, k], z[:, k])
    N = frames[0][0].shape[0]
    spins = [np.full(N, 1.0 if r.spin > 0 else -1.0) for r in vehicle.rotors]
    if any(n in BODY_DRAG_NAMES for n in wrt):  # the drag's derivatives hold at zero drag areas too
        body = body if body is not None else BodyDrag()
        if wash is None:
            wash = np.mean([loads[i].v_i_mean[:, None] * axes[i] for i in range(n_rot)], axis=0)
    drag_active = wash is not None and body is not None
    if drag_active:
        u = v_air + body.wash_factor * wash
        speed = np.linalg.norm(u, axis=1, keepdims=True)
        area = np.asarray(body.drag_area)
        drag_du = drag_jacobian(u, area, rho)

        def body_du(du):
            return np.einsum("nij,nj->ni", drag_du, du)

    def rotor_vectors(i, name):
        ld = loads[i]
        F, M = wrench_vectors(*(ld.derivative(q, name) for q in ("thrust", "drag", "torque", "rolling_moment")),
                              *frames[i], spins[i], side_force=ld.derivative("side_force", name),
                              pitching_moment=ld.derivative("pitching_moment", name))
        return F, M + np.cross(pos[i], F)

    dF = dM = jac = None
    if "omega" in wrt:
        dF = np.empty((N, 3, n_rot))
        dM = np.empty((N, 3, n_rot))
        for i, rot in enumerate(vehicle.rotors):
            F, M = rotor_vectors(i, "omega")
            if rot.inertia:
                M = M - np.cross(w, (rot.spin * rot.inertia) * axes[i])
            if drag_active and body.wash_factor > 0:
                F = F + body_du((body.wash_factor / n_rot) * loads[i].derivative("v_i_mean", "omega")[:, None]
                                * axes[i])
            dF[:, :, i] = F
            dM[:, :, i] = M
    if others:
        jac = {}
        for name in others:
            if name in BODY_DRAG_NAMES:
                M = np.zeros((N, 3))
                if not drag_active:
                    F = np.zeros((N, 3))
                elif name == "wash_factor":
                    F = body_du(wash)
                else:
                    k = BODY_DRAG_NAMES.index(name)
                    F = np.zeros((N, 3))
                    F[:, k] = -0.5 * rho * speed[:, 0] * u[:, k]
            else:
                F = np.zeros((N, 3))
                M = np.zeros((N, 3))
                dwash = np.zeros((N, 3))
                for i in range(n_rot):
                    Fi, Mi = rotor_vectors(i, name)
                    F += Fi
                    M += Mi
                    dwash += loads[i].derivative("v_i_mean", name)[:, None] * axes[i] / n_rot
                if drag_active and body.wash_factor > 0:
                    F = F + body_du(body.wash_factor * dwash)
                if name == "rho" and drag_active:  # the drag's own proportionality to rho
                    F = F - 0.5 * area * speed * u
            jac[("force", name)] = F
            jac[("moment", name)] = M
    return dF, dM, jac


def drag_jacobian(u: np.ndarray, area: np.ndarray, rho: float) -> np.ndarray:
    """d(-(rho/2) C |u| u)/du = -(rho/2) C (|u| I + u u^T / |u|), shape (N, 3, 3): the airframe
    drag's (core/body.py, per-axis drag areas C [m^2]) Jacobian in its air speed u (N, 3) [m/s]
    (0 at u = 0)."""
    speed = np.linalg.norm(u, axis=1)[:, None, None]
    outer = u[:, :, None] * u[:, None, :] / np.where(speed > 0, speed, 1.0)
    return -0.5 * rho * np.asarray(area)[None, :, None] * (speed * np.eye(3) + outer)


def cross_matrix(r: np.ndarray) -> np.ndarray:
    """[r]x, shape r.shape + (3,): the matrix with [r]x u = r x u."""
    m = np.zeros(r.shape + (3,))
    m[..., 0, 1], m[..., 0, 2], m[..., 1, 2] = -r[..., 2], r[..., 1], -r[..., 0]
    m[..., 1, 0], m[..., 2, 0], m[..., 2, 1] = r[..., 2], -r[..., 1], r[..., 0]
    return m


def hub_velocity_jacobians(vehicle, batches, om):
    """Each rotor's (dF_i/dV_i, dtau_i/dV_i, dvbar_i/dV_i), shapes (N, n_rot, 3, 3) twice and
    (N, n_rot, 3): its force's, hub moment's and mean inflow's derivatives with respect to its
    hub velocity (core/vector.velocity_jacobian), from its loads' derivatives with respect to
    VELOCITY_INPUTS (at V_i = 0 the slopes along three rays, core/vector.still_air_slopes).
    ``batches``: the solver calls of model._rotor_wrenches, (rotor indices, their loads of shape
    (N, k), the disks' in-plane velocity and axis), each taken whole (one rotor at a time cost
    a one-sample linearisation of a quadrotor 1.6 ms more, 2026-11-28)."""
    N, n_rot = om.shape
    dF = np.empty((N, n_rot, 3, 3))
    dtau = np.empty((N, n_rot, 3, 3))
    dvi = np.empty((N, n_rot, 3))
    spin = np.array([1.0 if r.spin > 0 else -1.0 for r in vehicle.rotors])
    for idx, loads, Vd, z in batches:
        dF[:, idx], dtau[:, idx] = velocity_jacobian(loads, Vd, z, np.broadcast_to(spin[idx], (N, len(idx))))
        dvi[:, idx] = velocity_gradient(loads, "v_i_mean", Vd, z)
    return dF, dtau, dvi


def motion_derivatives(wrt, hub_jac, axes, pos, h, om, w, rotor_force, body, v_air, wash, rho) -> dict:
    """{("force" | "moment", name): shape (N, 3, 3)} for the MOTION_NAMES in ``wrt``: the rotors'
    hub Jacobians through V_i = v + w x r_i - wind with r_i = p_i - c (dV_i/dv = I, dV_i/dw =
    -[r_i]x, dV_i/dc = -[w]x), the arms (d(r_i x F_i)/dc adds [F_r]x, F_r = ``rotor_force``,
    the rotors' total force, shape (N, 3)), the gyroscopic moment -w x (s_i J_i Omega_i a_i)
    and the airframe drag, whose air speed v - wind + k_w (mean of v_i,mean a_i) moves with the
    rotors' inflow too."""
    dF_hub, dtau_hub, dvi = hub_jac
    N, n_rot = om.shape
    arm = cross_matrix(pos)  # (n_rot, 3, 3)
    dM_hub = dtau_hub + arm[None] @ dF_hub  # moment about the centre of mass per unit hub velocity
    out = {}
    drag_active = wash is not None and body is not None
    if drag_active:
        drag_du = drag_jacobian(v_air + body.wash_factor * wash, body.drag_area, rho)
        # d wash/dV_i = a_i (dvbar_i/dV_i)^T / n_rot
        dwash = axes[None, :, :, None] * dvi[:, :, None, :] / n_rot  # (N, n_rot, 3, 3)
    for name in MOTION_NAMES:
        if name not in wrt:
            continue
        # dV_i/dx, (N, n_rot, 3, 3): I for the velocity, -[r_i]x for the angular velocity, -[w]x (the same for
        # every rotor) for the centre of mass
        if name == "centre_of_mass":
            dV = -cross_matrix(np.broadcast_to(w, (N, 3)))[:, None]
        else:
            dV = (np.eye(3) if name == "velocity" else -arm)[None]
        dV = np.broadcast_to(dV, (N, n_rot, 3, 3))
        F = np.einsum("nrij,nrjk->nik", dF_hub, dV)
        M = np.einsum("nrij,nrjk->nik", dM_hub, dV)
        if name == "angular_velocity":  # the gyroscopic moment: d(-w x h_i Omega_i)/dw = [h_i Omega_i]x
            M = M + cross_matrix(np.einsum("ri,nr->ni", h, om))
        if name == "centre_of_mass":  # the arms' moment: d(r_i x F_i)/dc = -dc x F_r
            M = M + cross_matrix(rotor_force)
        if drag_active:
            du = np.einsum("nrij,nrjk->nik", body.wash_factor * dwash, dV)
            if name == "velocity":
                du = du + np.eye(3)
            F = F + drag_du @ du
        out[("force", name)] = F
        out[("moment", name)] = M
    return out
