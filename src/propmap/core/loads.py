"""The loads of one propeller at a batch of operating points, as :func:`propmap.rotor_loads`
returns them: :class:`RotorLoads`, with its derived quantities and derivatives.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, fields

import numpy as np

from .derivatives import DERIVATIVE_LOADS, FLAPPING_LOADS
from .states import STATES

__all__ = ["RotorLoads"]


@dataclass(frozen=True, eq=False)  # (== of the arrays' fields raised NumPy's "truth value ... ambiguous": identity)
class RotorLoads:
    """Loads of one propeller at a batch of operating points.

    Array attributes have the broadcast shape ``S`` of the inputs; per-annulus fields
    have shape ``S + (n_radial,)`` with the radial axis last.

    Attributes
    ----------
    omega, airspeed, incidence : ndarray, shape S
        The operating points: Omega [rad/s], V [m/s], incidence beta [rad].
    thrust : ndarray
        T [N] along the rotor axis (eq 13).
    drag : ndarray
        Rotor drag D [N] in the disk plane, against the in-plane velocity (eq 14);
        0 exactly in axial flow and at V = 0.
    torque : ndarray
        Q [N m] opposing the rotation (what the motor supplies) (eq 15).
    rolling_moment : ndarray
        M_R [N m], the in-plane hub moment from the advancing/retreating asymmetry of the
        thrust: the moment of the thrust distribution about the in-plane velocity
        direction, (N_b / 2 pi) int int r dT(r, psi) sin psi dpsi dr, positive when the
        advancing blade (psi = 90 deg) carries more thrust; 0 exactly in axial flow and
        at V = 0. Its vector is -spin M_R e_ip (:func:`rotor_wrench`; docs/conventions.md).
        Computed from the same azimuth nodes as eqs 13-15. Because the inflow v_i(r) does
        not depend on azimuth (paper Section II), every integrand depends on psi through
        sin psi only: the side force and the pitching moment (the cos psi moments) are
        zero by symmetry in this model (not with a linear inflow, flapping or the dynamic
        stall, below).
    side_force : ndarray
        Y [N], in the disk plane, normal to the in-plane velocity, positive toward the
        advancing side. 0 exactly with the paper's uniform inflow and rigid blades (every
        integrand then depends on psi through sin psi only); non-zero with a linear inflow
        model, with flapping or with the dynamic stall, whose angle of attack rises on one half
        of the disk and falls on the other (:class:`~propmap.core.airfoil.RotorOptions`).
    pitching_moment : ndarray
        M_P [N m], the moment of the thrust distribution about the disk's lateral axis,
        -(N_b / 2 pi) int int r dT(r, psi) cos psi dpsi dr, positive when the upstream half
        (psi = 180 deg) carries more thrust (nose-up for a disk moving forward; the vector
        is M_P e_ip x z_hat). 0 with the uniform inflow and rigid blades, without the dynamic
        stall.
    v_i_mean : ndarray
        Mean induced inflow over the disk [m/s] (v_i(r) weighted by the annulus area).
    flap_1c, flap_1s : ndarray
        First-harmonic flapping beta_1c, beta_1s [rad] (0 for rigid blades): the
        tip-path-plane normal is z_hat + beta_1c e_ip + spin beta_1s (z_hat x e_ip), so that
        beta_1c < 0 tilts the disk away from its in-plane motion (core/flapping.py).
    power : ndarray
        P = Q Omega [W].
    CT, CP, CQ : ndarray
        Propeller-convention coefficients T/(rho n^2 D^4), P/(rho n^3 D^5),
        Q/(rho n^2 D^5), n = Omega/(2 pi) [rev/s], D the diameter; NaN for a stopped rotor
        (Omega = 0), where they are undefined (the loads are not).
    J : ndarray
        Advance ratio V/(n D) [-] (total airspeed); NaN for a stopped rotor.
    r : ndarray, shape (n_radial,)
        Radial nodes [m].
    v_i : ndarray, shape S + (n_radial,), or None
        Induced inflow v_i(r) [m/s] along the rotor axis, positive with the thrust
        (through the disk in the thrust-opposite direction, i.e. into the slipstream).
        None when computed with ``radial=False`` (as the three below).
    dT_dr, dD_dr, dQ_dr, dMR_dr, dY_dr, dMP_dr : ndarray, shape S + (n_radial,), or None
        Per-unit-radius thrust [N/m], drag [N/m], torque [N] (eqs 5-7), rolling moment
        [N], side force [N/m] and pitching moment [N] of the rigid blades.
    converged : ndarray of bool
        Every annulus root converged.
    vortex_ring : ndarray of bool
        The rotor is in the vortex-ring state (``state == 1``, core/states.py: Johnson's
        boundary, descent rates 0.45-1.5 v_h in axial descent narrowing to 0.975 v_h at an
        in-plane speed of 0.95 v_h): the wake recirculates through the
        disk and the loads fluctuate; the mean loads come from the empirical descent
        momentum (``descent = "empirical"``) or, with Glauert's, are not predictive.
    state : ndarray of int
        Working state, codes into ``propmap.core.states.STATES``: 0 normal working, 1 vortex
        ring, 2 turbulent wake, 3 windmill brake (:attr:`state_name` gives the names).
    v_h : ndarray
        Hover induced velocity at the thrust made, sqrt(T / (2 rho pi R^2)) [m/s] (0 where
        T <= 0).
    descent_ratio : ndarray
        k = -V cos(beta) / v_h [-] (lambda_2 in vertical descent; NaN where T <= 0).
    multiple_roots : ndarray of bool
        Some annulus has a further root of eq (11) near the selected one.
    reverse_flow : ndarray of bool
        Part of the blade sees reverse flow (U_T < 0) on the retreating side.
    reverse_flow_radius : ndarray
        V_b / Omega [m]: radius inside which the retreating blade sees reverse flow, V_b the
        blades' in-plane airspeed: V sin(beta), plus the skewed wake's in-plane induced
        velocity at the mean inflow v_i_mean with ``inplane_induction`` (the cambered
        default; _momentum.inplane_induction).
    inflow_extrapolated : ndarray of bool
        The inflow model was used outside the measurements behind it: a linear inflow model
        with the flow through the disk upward (V cos(beta) + v_i_mean < 0; in descent the
        wake skew is that of a hovering disk, propmap's extension: _momentum.skew_inflow_ratio,
        inflow_gradients), Drees's model beyond an advance ratio of 0.5, where its
        gradients are held (_momentum.DREES_MU_MAX), or the empirical descent momentum (``descent =
        "empirical"``) in the vortex-ring or turbulent-wake range (0.45 <= lambda2 < 2) with an
        in-plane speed that puts its fade with V sin(beta) (propmap's, not measured) between
        5% and 95%.
    n_evaluations : ndarray of int
        Residual evaluations (each n_azimuth element evaluations) spent on the point.
    rho : float
        Air density used [kg/m^3].
    diameter : float
        Propeller diameter [m].
    jacobian : dict or None
        With ``rotor_loads(..., derivatives=...)``: {(quantity, wrt): ndarray of shape S}
        (:meth:`derivative`); else None.
    """

    omega: np.ndarray
    airspeed: np.ndarray
    incidence: np.ndarray
    thrust: np.ndarray
    drag: np.ndarray
    torque: np.ndarray
    rolling_moment: np.ndarray
    side_force: np.ndarray
    pitching_moment: np.ndarray
    v_i_mean: np.ndarray
    flap_1c: np.ndarray
    flap_1s: np.ndarray
    r: np.ndarray
    v_i: np.ndarray | None
    dT_dr: np.ndarray | None
    dD_dr: np.ndarray | None
    dQ_dr: np.ndarray | None
    dMR_dr: np.ndarray | None
    dY_dr: np.ndarray | None
    dMP_dr: np.ndarray | None
    converged: np.ndarray
    vortex_ring: np.ndarray
    multiple_roots: np.ndarray
    reverse_flow: np.ndarray
    reverse_flow_radius: np.ndarray
    inflow_extrapolated: np.ndarray
    state: np.ndarray
    v_h: np.ndarray
    descent_ratio: np.ndarray
    n_evaluations: np.ndarray
    rho: float
    diameter: float
    jacobian: dict | None = None

    def derivative(self, quantity: str, wrt: str) -> np.ndarray:
        """d(quantity)/d(wrt) at every point, by the implicit function theorem (core/_sensitivity.py;
        core/_linear_sensitivity.py with a linear inflow model).

        Parameters
        ----------
        quantity : {"thrust", "drag", "torque", "rolling_moment", "v_i_mean", "side_force", "pitching_moment", \
"power"}
            The side force and pitching moment are those of flapping blades, of a linear
            inflow model or of the dynamic stall (0 for rigid blades with the uniform inflow;
            core/flapping.py). The power P = Q Omega's by the product rule from the torque's:
            Omega dQ/dx, plus Q for x = omega [W per unit of x].
        wrt : str
            "omega" [rad/s], "airspeed" [m/s], "incidence" [rad], "collective" [rad], "rho"
            [kg/m^3] or a section parameter's name (in its SI unit); as asked of
            :func:`rotor_loads` (``derivatives``).

        Returns
        -------
        ndarray, shape S
            [N or N m per unit of ``wrt``], a new array (0-d for one point); NaN where the
            point did not converge. At
            points with ``multiple_roots`` the derivative is that of the selected root's
            branch; the loads jump where the selection changes.

        Raises
        ------
        ValueError
            The loads were computed without derivatives, or an unknown quantity or input
            (naming the valid ones).
        """
        if self.jacobian is None:
            raise ValueError("these loads have no derivatives: call rotor_loads(..., derivatives=True)")
        if not isinstance(wrt, str):  # (a list met a bare 'unhashable type': an API audit, 2026-12-01)
            raise ValueError(f"wrt must be the name of one input or parameter (a str), got {wrt!r:.60}")
        if quantity == "power":  # P = Q Omega: an MPC's energy cost
            dQ = self.derivative("torque", wrt)
            return np.asarray(self.omega * dQ + (self.torque if wrt == "omega" else 0.0))  # (0-d as the others)
        if quantity not in DERIVATIVE_LOADS + FLAPPING_LOADS:
            raise ValueError(f"quantity must be one of {', '.join(DERIVATIVE_LOADS + FLAPPING_LOADS + ('power',))}, "
                             f"got {quantity!r:.60}")
        if (quantity, wrt) not in self.jacobian:
            have = sorted({w for _, w in self.jacobian if not w.startswith("_")})  # not the internal ones
            if not have:
                raise ValueError(f"these loads have no derivative with respect to {wrt!r:.60}: ask rotor_loads(..., "
                                 "derivatives=...) for it")
            raise ValueError(f"wrt must be one of {', '.join(have)} (the derivatives asked of rotor_loads; ask "
                             f"for others with derivatives=[...]), got {wrt!r:.60}")
        return self.jacobian[(quantity, wrt)].copy()  # (a view let a caller's edit change the stored derivative)

    @property
    def state_name(self) -> np.ndarray:
        """The working state's name at every point (array of str, shape S)."""
        # (np.asarray again: indexing with a 0-d index returns the bare str, not the documented array)
        return np.asarray(np.asarray(STATES, dtype=object)[np.asarray(self.state)], dtype=object)

    @property
    def v_i_over_v_h(self) -> np.ndarray:
        """v_i,mean / v_h [-], shape S (NaN where T <= 0): the mean induced inflow in units of the
        hover induced velocity at the thrust made (the CLI's ``v_i_over_v_h``)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.v_h > 0, self.v_i_mean / np.where(self.v_h > 0, self.v_h, 1.0), np.nan)

    @property
    def inflow_ratio(self) -> np.ndarray:
        """Deprecated name of :attr:`v_i_over_v_h` (warns): in rotorcraft usage the inflow ratio
        is lambda = (V cos(beta) + v_i) / (Omega R), which this never was."""
        warnings.warn("RotorLoads.inflow_ratio is v_i,mean / v_h, not the inflow ratio lambda = (V cos(beta) + v_i) / "
                      "(Omega R): use RotorLoads.v_i_over_v_h (the name inflow_ratio will be removed)",
                      DeprecationWarning, stacklevel=2)
        return self.v_i_over_v_h

    @property
    def power(self) -> np.ndarray:
        """P = Q Omega [W], shape S."""
        return np.asarray(self.torque * self.omega)  # (0-d arrays multiply to a NumPy scalar)

    @property
    def _n(self) -> np.ndarray:
        """n = Omega / (2 pi) [rev/s], shape S."""
        return self.omega / (2.0 * np.pi)

    @property
    def CT(self) -> np.ndarray:
        """T / (rho n^2 D^4) [-], propeller convention, shape S (NaN for a stopped rotor, Omega = 0,
        or one below about 1e-150 rad/s, where n^2 underflows; as CQ, CP and J: they are
        referred to n)."""
        return self._per_n(self.thrust, self.rho * self._n**2 * self.diameter**4)

    def _per_n(self, a, b) -> np.ndarray:
        """a / b, NaN where b = 0 (Omega = 0, or so small that n^2 underflows) without a
        division warning."""
        b = np.asarray(b)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(b > 0, a / np.where(b > 0, b, 1.0), np.nan)

    @property
    def CQ(self) -> np.ndarray:
        """Q / (rho n^2 D^5) [-], propeller convention, shape S."""
        return self._per_n(self.torque, self.rho * self._n**2 * self.diameter**5)

    @property
    def CP(self) -> np.ndarray:
        """P / (rho n^3 D^5) [-], propeller convention, shape S: 2 pi CQ (P = Q Omega), computed so
        (n^3 underflowed first: NaN at 1e-120 rad/s and 2% off at 1e-105 where CT and CQ were
        right, an API audit)."""
        return np.asarray(2.0 * np.pi * self.CQ)  # (an array, 0-d for one point, as the others)

    @property
    def J(self) -> np.ndarray:
        """V / (n D) [-], total airspeed, shape S."""
        return self._per_n(self.airspeed, self._n * self.diameter)

    def to_dataframe(self):
        """The per-point quantities as a pandas DataFrame, one row per point (shape S flattened
        in C order), SI units as the fields: omega [rad/s], airspeed [m/s], incidence [rad],
        thrust, drag, side_force [N], torque, rolling_moment, pitching_moment [N m], power [W],
        CT, CQ, CP, J [-], v_i_mean [m/s], flap_1c, flap_1s [rad], state (its name), the flags
        (converged, vortex_ring, multiple_roots, reverse_flow, inflow_extrapolated) and
        n_evaluations. The per-annulus arrays and the derivatives are left out; ``rho``
        [kg/m^3], ``diameter`` [m] and the columns' ``units`` are in ``DataFrame.attrs``.

        Returns
        -------
        pandas.DataFrame
        """
        import pandas as pd

        cols = {name: np.asarray(getattr(self, name)).reshape(-1) for name in _FRAME_COLUMNS}
        cols["state"] = np.asarray(self.state_name).reshape(-1)
        frame = pd.DataFrame(cols)
        frame.attrs.update(rho=self.rho, diameter=self.diameter,
                           units={k: u for k, u in _FRAME_UNITS.items() if k in frame.columns})
        return frame

    def __repr__(self) -> str:
        """A summary (shape, ranges of T, D, Q, the flags raised), not every array."""
        shape = np.shape(self.thrust)

        def span(a, unit):
            a = np.asarray(a)
            if a.size == 0:
                return "none"
            lo, hi = float(np.nanmin(a)), float(np.nanmax(a))
            return f"{lo:.4g} {unit}" if lo == hi else f"{lo:.4g} to {hi:.4g} {unit}"

        raised = [k for k in ("vortex_ring", "multiple_roots", "reverse_flow", "inflow_extrapolated")
                  if np.any(getattr(self, k))]
        if not np.all(self.converged):
            raised.insert(0, "not_converged")
        return (f"RotorLoads(shape {shape}, thrust {span(self.thrust, 'N')}, drag {span(self.drag, 'N')}, torque "
                f"{span(self.torque, 'N m')}, flags raised: {', '.join(raised) or 'none'})")

    def flags(self, index=()) -> list[str]:
        """Names of the raised status flags at one point (``index`` into shape S; on scalar
        loads, shape (), ``()`` or ``0``).

        Returns
        -------
        list of str
            Among "not_converged", "vortex_ring", "multiple_roots", "reverse_flow" and
            "inflow_extrapolated" (docs/solver.md), in that order; empty where none is raised.

        Raises
        ------
        IndexError
            ``index`` outside shape S (on scalar loads: anything but ``()``, 0 or -1).
        """
        conv = np.asarray(self.converged)
        if conv.ndim == 0:
            if not (index == () or (isinstance(index, (int, np.integer)) and index in (0, -1))):
                raise IndexError(f"index {index!r} into loads of one point (shape ()): give () or 0")
            index = ()
        else:
            full = index if isinstance(index, tuple) else (index,)
            if len(full) != conv.ndim or not all(isinstance(i, (int, np.integer)) for i in full):
                raise IndexError(f"index {index!r} into loads of shape {conv.shape}: give one integer per axis "
                                 f"({conv.ndim})")
            index = full
        names = []
        if not bool(conv[index]):
            names.append("not_converged")
        for key in ("vortex_ring", "multiple_roots", "reverse_flow", "inflow_extrapolated"):
            if bool(np.asarray(getattr(self, key))[index]):
                names.append(key)
        return names


_LOADS_FIELDS = frozenset(f.name for f in fields(RotorLoads))
#: RotorLoads.to_dataframe's numeric columns and every column's unit
_FRAME_COLUMNS = ("omega", "airspeed", "incidence", "thrust", "drag", "side_force", "torque", "rolling_moment",
                  "pitching_moment", "power", "CT", "CQ", "CP", "J", "v_i_mean", "flap_1c", "flap_1s", "converged",
                  "vortex_ring", "multiple_roots", "reverse_flow", "inflow_extrapolated", "n_evaluations")
_FRAME_UNITS = {"omega": "rad/s", "airspeed": "m/s", "incidence": "rad", "thrust": "N", "drag": "N",
                "side_force": "N", "torque": "N m", "rolling_moment": "N m", "pitching_moment": "N m", "power": "W",
                "CT": "-", "CQ": "-", "CP": "-", "J": "-", "v_i_mean": "m/s", "flap_1c": "rad", "flap_1s": "rad",
                "converged": "-", "vortex_ring": "-", "multiple_roots": "-", "reverse_flow": "-",
                "inflow_extrapolated": "-", "n_evaluations": "-", "state": "-"}


def _new_loads(values: dict) -> RotorLoads:
    """A RotorLoads from a dict of all its fields, without the frozen dataclass's per-field
    ``object.__setattr__`` (a few microseconds of a single point's call); the fields must be
    exactly :class:`RotorLoads`'s (checked by tests/test_invariants.py)."""
    obj = object.__new__(RotorLoads)
    obj.__dict__.update(values)
    return obj
