"""Blade-section aerodynamics: the polars of Gill & D'Andrea (2017) and a cambered polar.

Two section models, selected by the parameter record (``section_model``):

* ``"gill2017"`` (:class:`AirfoilParams`): eqs (3) and (4) of R. Gill and R. D'Andrea,
  "Propeller Thrust and Drag in Forward Flight", IEEE CCTA 2017,
  doi:10.1109/CCTA.2017.8062440 (footnotes 1 and 2, Table I). Exactly the paper's model.
* ``"cambered"`` (:class:`CamberedParams`): the lift and drag polar of Drela's XROTOR and
  QPROP (linear lift from a zero-lift angle, a drag polar quadratic in C_L about the
  minimum-drag lift coefficient, Reynolds scaling of drag (Re/Re_ref)^f), with lift and
  CL_max also Reynolds-scaled, optional Prandtl-Glauert compressibility, and eq (3)'s
  sigmoid blend into flat-plate post-stall behaviour (C_L = C_D90 sin a cos a,
  C_D = C_D90 sin^2 a; Hoerner, Fluid-Dynamic Drag, 1965, ch. 3) so that 90 deg and
  reverse flow stay physical. Sources: M. Drela, "QPROP Formulation", MIT, 2006;
  M. Drela, XROTOR User Guide, 2003 (the drag's Reynolds exponent and Prandtl-Glauert). The
  lift slope's and the stall's Reynolds power laws, the zero-lift angle's drift with ln Re
  and the stall delay's 1 + k (c/r)^2 on the stall angle (the (c/r)^2 of Snel, Houwink and
  Bosschers, ECN-C--93-052, 1994) are propmap's own empirical terms (docs/models.md, The
  cambered section).

Both records also carry the switches of Prandtl's tip and hub loss (``tip_loss``,
``hub_loss``; ``_physics.loss_factor``) and the rotor-level options of :class:`RotorOptions`
(inflow model, blade flapping, collective offset; docs/models.md), which default to the
paper's rigid blades with an azimuth-independent inflow. The records' air (:class:`Air`) is
defined in core/air.py and re-exported here. The polars are evaluated through the solver's own
element in core/polar.py (``lift_coefficient``, ``drag_coefficient``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import asdict, dataclass, field, fields, replace
from types import MappingProxyType
from typing import Self

import numpy as np

from ._numbers import checked
from .air import Air

__all__ = [
    "RotorOptions",
    "AirfoilParams",
    "CamberedParams",
    "SectionParams",
    "Air",
    "PRESETS",
    "preset",
]

LIFT_MODELS = ("sigmoid", "sincos")
#: inflow models (``RotorOptions.inflow``; _momentum.inflow_gradients)
INFLOW_MODELS = ("uniform", "drees", "pitt-peters")
#: momentum in descent (``RotorOptions.descent``; _momentum.axial_mass_flow)
DESCENT_MODELS = ("glauert", "empirical")
#: valid ranges of the rotor options (SI)
FLAP_COMPLIANCE_MAX = 1e3  # [rad/(N m)]
DYNAMIC_STALL_MAX = 5.0  # Gormont's gamma [-]
COLLECTIVE_MAX = math.radians(30.0)  # [rad]


#: the fields of the section records that are not model parameters: the set's air and label
RECORD_META = ("air", "label")


@dataclass(frozen=True, kw_only=True)
class RotorOptions:
    """Rotor-level physics beyond the paper, carried by both section records (keyword-only).

    Parameters
    ----------
    inflow : {"uniform", "drees", "pitt-peters"}
        Induced-inflow model. ``"uniform"`` (default): the paper's v_i(r), independent of
        azimuth, so that the side force and the pitching moment vanish. The linear models
        give every annulus v0(r) (1 + k_x (r/R) cos psi + k_y (r/R) sin psi), with the
        gradients of Drees (1949) or Pitt & Peters (1981) from the wake skew angle
        (_momentum.inflow_gradients; Leishman, Principles of Helicopter Aerodynamics, 2nd ed.,
        2006, Sec. 3.4); v0(r) is still the root of eq 11 (costs two root solves and twice
        the azimuth nodes per non-axial point).
    flap_compliance : float
        1 / K_beta [rad/(N m)], in [0, 1e3], of a blade flapping about the hub against a
        spring K_beta (the centre-spring equivalent rotor: G. D. Padfield, Helicopter Flight
        Dynamics, 2nd ed., 2007, Sec. 3.2.1; W. Johnson, Helicopter Theory, 1980, Ch. 5).
        0 (default): rigid blades, the paper's model. The first-harmonic flapping is solved
        quasi-statically from the rigid blades' first-harmonic flap moments with the
        aerodynamic flap damping (solver.flapping); the thrust tilts with the tip-path plane
        and the hub moment becomes the spring's.
    collective : float
        Blade-angle offset added to theta(r) [rad], in [-30, 30] deg (a geometry whose blade
        angles are uncertain, or a collective setting). Default 0.
    descent : {"glauert", "empirical"}
        Momentum in descent. ``"glauert"``: the paper's Glauert momentum in every state (each
        annulus may switch between the vortex-ring and windmill-brake branches on its own);
        the default of the paper's section model, which stays exactly the paper's.
        ``"empirical"``: in the vortex-ring and turbulent-wake states the measured induced
        velocity of rotors in axial descent (Leishman 2006, Ch. 2, fitted to Castles & Gray,
        NACA TN 2474, 1951), written as an axial mass flow that fades into Glauert's with the
        in-plane speed (_momentum.axial_mass_flow; docs/models.md); climb and hover unchanged;
        the default of the cambered model.
    swirl : bool
        The annuli's swirl: the tangential induced velocity u that the torque leaves in the
        wake, from each annulus' angular momentum, dQ/dy = F 4 pi rho y^2 W u, so that the
        blade meets Omega r - u (the rotational interference a' = u / (Omega r) of propeller
        blade-element momentum theory: H. Glauert, "Airplane Propellers", in Durand (ed.),
        Aerodynamic Theory, vol. IV, div. L, 1935; S. A. Ning, Wind Energy 17, 2014). It grows
        with the local solidity and the loading, so it takes thrust from many-bladed rotors and
        from the static run more than from the sweeps (docs/models.md, Swirl). Solved by a
        secant in u around the root solve (4-5 root solves per point in the median; where it
        closes in on a jump of the selected root in descent, more: 173 residual evaluations
        per annulus against 8.6 without swirl at tests/test_swirl.py's jump point); implicit
        derivatives since 2026-11-25 (docs/solver.md). False (default): the paper's model, which has no swirl.
    radial_drag : bool
        The profile drag of the radial flow along the blade (the yawed-flow drag of helicopter
        theory, W. Johnson, Helicopter Theory, Princeton University Press, 1980, Ch. 5: the
        skin friction acts along the blade's whole relative velocity, so the radial velocity
        u_R = V sin(beta) cos(psi) of edgewise flow gives a radial force D_p u_R / U). The
        chordwise loads keep the independence principle (lift and drag from U_T and U_P only)
        and the radial force (rho/2) c C_D,p U u_R adds to the in-plane force, to first order
        in u_R / U, with C_D,p the section's profile drag without the pressure drag of stall
        (_physics.make_profile_drag): it raises the profile part of the H-force by half at
        small mu (<cos^2 psi> = 1/2 of the chordwise term; the classical sigma C_D mu / 4
        becomes 3 sigma C_D mu / 8).
        It passes through the shaft: thrust, torque, the rolling and pitching moments and the
        root solve are unchanged, and so is everything in axial flow. True: the default of the
        cambered model (docs/models.md, Radial drag). False: the default of the paper's
        section model, which stays exactly the paper's.
    inplane_induction : bool
        The skewed wake's in-plane induced velocity: in edgewise flow the wake, a skewed
        cylinder of ring vortices (W. Castles and J. H. De Leeuw, NACA Report 1184, 1954),
        induces at each annulus besides the normal inflow v of momentum theory an in-plane
        velocity along the in-plane airspeed, v tan(chi / 2) on the azimuthal mean, chi the
        wake's skew (tan chi = V sin(beta) / |V cos(beta) + v|, in descent V sin(beta) / |v|):
        from V sin(beta) / 2 at small skew in hover to v as the skew nears 90 deg
        (_momentum.inplane_induction, docs/models.md; in descent propmap's interpolation, not
        the model's sign where the flow through the disk is upward). The blades meet
        V sin(beta) + v tan(chi / 2) in the disk plane; the momentum balance keeps Glauert's.
        Zero in axial flow and hover; implicit derivatives with every inflow model and swirl.
        True: the default of the cambered model since 2026-11-25 (docs/models.md: measured
        against the wind tunnel's in-plane force, the flight logs and fits at incidence).
        False: momentum theory's inflow, normal to the disk, the default of the paper's section
        model, which stays exactly the paper's.
    dynamic_stall : float
        Gormont's factor gamma [-], in [0, 5], of the quasi-steady dynamic stall in edgewise
        flow (R. E. Gormont, USAAMRDL TR 72-67, 1973; J. G. Leishman, Principles of Helicopter
        Aerodynamics, 2nd ed., 2006, Ch. 9): the positive stall angle is delayed by
        gamma sqrt(c |alpha_dot| / (2 U)) where the angle of attack rises once a revolution
        and advanced by half that where it falls (_physics.make_delayed_cambered_element);
        1.4 - 6 (0.06 - t/c) for the lift of a section of thickness t/c, about 1.5 at 8%.
        Axial flow is unchanged (alpha_dot = 0). The cambered model in a uniform inflow only;
        implicit derivatives with respect to every input and section parameter, not gamma itself
        (core/_delayed_sensitivity.py). 0 (default): the static polar. Not the default because
        the square root makes the thrust rise as sqrt(mu) from hover (a cusp there, a side
        force larger than the drag below 1 m/s edgewise) where the wind tunnel's rises as
        mu^2 (docs/models.md, Dynamic stall).
    air : Air
        The air the set goes with (a parameter file's ``rho``, ``mu``, ``speed_of_sound``;
        the shipped sets: footnote 2's): :func:`propmap.rotor_loads` and every other model
        function use it unless given an ``air`` of their own, so that a set never loses
        its air on the way. Default :class:`Air` ().
    label : str
        Where the set comes from (``"generic"``, ``"calibrated:apce_8x6"``,
        ``"section:naca0015"``, a file's path), for outputs; not part of equality.

    Raises
    ------
    ValueError
        An unknown inflow or descent model, a value outside its range, an ``air`` that is
        not an :class:`Air` or a ``label`` that is not text (the message names it), a
        ``dynamic_stall`` with the paper's section model or a linear inflow.
    """

    inflow: str = "uniform"
    flap_compliance: float = 0.0
    collective: float = 0.0
    descent: str = "empirical"
    swirl: bool = False
    radial_drag: bool = True
    inplane_induction: bool = True
    dynamic_stall: float = 0.0
    air: Air = field(default_factory=Air)
    label: str = field(default="", compare=False)

    def _check_rotor_options(self) -> None:
        if not isinstance(self.air, Air):
            raise ValueError(f"air must be a propmap.Air, got {type(self.air).__name__}")
        if not isinstance(self.label, str):
            raise ValueError(f"label must be text, got {type(self.label).__name__}")
        if not isinstance(self.inflow, str) or self.inflow not in INFLOW_MODELS:  # (an array compared element-wise)
            raise ValueError(f"inflow must be one of {', '.join(INFLOW_MODELS)}, got {self.inflow!r}")
        if not isinstance(self.descent, str) or self.descent not in DESCENT_MODELS:  # (an array compared element-wise)
            raise ValueError(f"descent must be one of {', '.join(DESCENT_MODELS)}, got {self.descent!r}")
        object.__setattr__(self, "flap_compliance",
                           checked("flap_compliance", self.flap_compliance, 0.0, FLAP_COMPLIANCE_MAX,
                                   unit="rad/(N m)"))
        object.__setattr__(self, "collective", checked("collective", self.collective, -COLLECTIVE_MAX,
                                                       COLLECTIVE_MAX, unit="rad"))
        object.__setattr__(self, "dynamic_stall", checked("dynamic_stall", self.dynamic_stall, 0.0,
                                                          DYNAMIC_STALL_MAX))
        if self.dynamic_stall > 0.0:
            if not isinstance(self, CamberedParams):
                raise ValueError("dynamic_stall applies to the cambered section model (CamberedParams); the paper's "
                                 "model has its own stall")
            if self.inflow != "uniform":
                raise ValueError(f"dynamic_stall needs the uniform inflow, got inflow={self.inflow!r} (a linear "
                                 "inflow's angle of attack varies around the azimuth otherwise: not modelled)")

    def side_load_sources(self) -> tuple[str, ...]:
        """The options of this set that give the rotor a side force Y and a pitching moment M_P.

        Rigid blades in the uniform inflow with the static polar have none (by symmetry, paper
        Section II). A map of such a set holds Y and M_P too (``side_force``,
        ``pitching_moment``); the simulator coefficients (``export-sim``), which have no terms
        for them, warn with these names, and the C header says it leaves them out.

        Returns
        -------
        tuple of str
            Among ``"blade flapping"`` (``flap_compliance > 0``), ``"a linear inflow"`` and
            ``"the dynamic stall"`` (``dynamic_stall > 0``); empty where Y = M_P = 0.
        """
        return tuple(name for name, on in (("blade flapping", self.flap_compliance > 0.0),
                                           ("a linear inflow", self.inflow != "uniform"),
                                           ("the dynamic stall", self.dynamic_stall > 0.0)) if on)

    def replace(self, **changes) -> Self:
        """Return a copy with ``changes`` applied (validated again). A copy whose model fields
        differ is labelled ``"modified <label>"`` unless ``label`` is given: the named set's
        validation figures and coverage are not its own.

        Returns
        -------
        same type as self

        Raises
        ------
        ValueError
            A name that is not a field (the message lists them), or a value out of its range.
        """
        return _replace(self, changes)

    def as_dict(self) -> dict:
        """Return the section and rotor fields as a plain dict (SI units, angles in rad; without
        ``air`` and ``label``, :data:`RECORD_META`)."""
        return {k: v for k, v in asdict(self).items() if k not in RECORD_META}

    def same_section(self, other) -> bool:
        """Whether ``other`` is this set but for its air and label: the same model and every
        section and rotor field equal, numbers to 1e-12 relative (a set written to a parameter
        file and read back differs in its angles by the degrees' rounding, 1 ulp: compared
        exactly, a vehicle rotor naming the file was refused a map built with the set in memory,
        an audit of stop 96).

        Parameters
        ----------
        other : object
            Any object; a set of another model, or no set, is not the same.

        Returns
        -------
        bool
        """
        if type(other) is not type(self):
            return False
        mine, theirs = self.as_dict(), other.as_dict()
        return all(a == b if not (isinstance(a, float) and isinstance(b, float)) else
                   math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-300) for a, b in
                   ((mine[k], theirs[k]) for k in mine))


@dataclass(frozen=True)
class AirfoilParams(RotorOptions):
    """Parameters of the section polars, eqs (3) and (4) of Gill & D'Andrea (2017).

    Parameters
    ----------
    cl1 : float
        Pre-stall lift slope c_l1 [1/rad], >= 0 (eq 3).
    cl2 : float
        Post-stall amplitude c_l2 [-], >= 0 (eq 3); also the c_l of footnote 1's
        simplified lift ``C_L = c_l sin(alpha) cos(alpha)`` when ``lift_model="sincos"``.
    cd : float
        Drag amplitude c_d [-], >= 0 (eq 4).
    alpha0 : float
        Stall angle alpha_0 [rad], in (0, pi/2) (eq 3).
    M : float
        Sigmoid sharpness [1/rad], > 0. Default 50 (footnote 2).
    cd0 : float
        Form-drag coefficient c_d0 [-], >= 0. Default 0.01 (footnote 2).
    cp_blasius : float
        Laminar skin-friction constant c_p of the Blasius term [-], >= 0.
        Default 1.328 (footnote 2).
    lift_model : {"sigmoid", "sincos"}
        ``"sigmoid"``: eq (3). ``"sincos"``: footnote 1, ``C_L = cl2 sin a cos a``
        (``cl1``, ``alpha0`` and ``M`` are then unused).
    tip_loss, hub_loss : bool
        Prandtl's tip / hub loss factor in the momentum balance (not in the paper;
        default False, so that the model is exactly the paper's).
    inflow : {"uniform", "drees", "pitt-peters"}, keyword-only
        Default ``"uniform"`` (the paper's v_i(r)).
    flap_compliance : float, keyword-only
        1 / K_beta [rad/(N m)], in [0, 1e3]; default 0 (rigid blades, the paper's).
    collective : float, keyword-only
        Blade-angle offset [rad], in [-30, 30] deg; default 0.
    descent : {"glauert", "empirical"}, keyword-only
        Default ``"glauert"`` (the paper's momentum in every state).
    swirl, radial_drag, inplane_induction : bool, keyword-only
        Default False (the paper's model has none of them).
    dynamic_stall : float, keyword-only
        Must stay 0 (the cambered model only).
    air : Air, keyword-only
        The air the set goes with; default :class:`Air` () (footnote 2's).
    label : str, keyword-only
        Where the set comes from, for outputs; not part of equality.

    The keyword-only fields are the rotor options of :class:`RotorOptions`, where each is
    described with its source; the defaults here keep the model exactly the paper's.

    Raises
    ------
    ValueError
        If a value is non-finite or outside the range above.

    Notes
    -----
    Immutable; derive variants with :meth:`replace` (which labels a changed set ``"modified
    <label>"``; :func:`dataclasses.replace` keeps the label).
    """

    cl1: float
    cl2: float
    cd: float
    alpha0: float
    M: float = 50.0
    cd0: float = 0.01
    cp_blasius: float = 1.328
    lift_model: str = "sigmoid"
    tip_loss: bool = False
    hub_loss: bool = False

    #: the paper's Glauert momentum in descent too (RotorOptions.descent), so the model stays the paper's
    descent: str = field(default="glauert", kw_only=True)
    #: and no radial drag (RotorOptions.radial_drag), which the paper's element leaves out
    radial_drag: bool = field(default=False, kw_only=True)
    #: nor the skewed wake's in-plane induced velocity (RotorOptions.inplane_induction): the paper's
    #: inflow is momentum theory's, normal to the disk
    inplane_induction: bool = field(default=False, kw_only=True)

    section_model = "gill2017"

    def __post_init__(self) -> None:
        _check_flags(self)
        self._check_rotor_options()
        for name in ("cl1", "cl2", "cd", "cd0", "cp_blasius"):
            object.__setattr__(self, name, checked(name, getattr(self, name), low=0.0))
        object.__setattr__(self, "M", checked("M", self.M, low=0.0, low_open=True))
        a0 = checked("alpha0", self.alpha0, unit="rad")
        if not 0.0 < a0 < math.pi / 2:
            raise ValueError(f"alpha0 must be in (0, pi/2) rad, got {a0!r}")
        object.__setattr__(self, "alpha0", a0)
        if not isinstance(self.lift_model, str) or self.lift_model not in LIFT_MODELS:  # (arrays: element-wise)
            raise ValueError(f"lift_model must be one of {LIFT_MODELS}, got {self.lift_model!r}")


def _differs(a, b) -> bool:
    """Whether a field's new value ``a`` differs from ``b`` (True where they do not compare)."""
    try:
        return bool(a != b)
    except (TypeError, ValueError):
        return True


def _replace(p, changes: dict):
    """``dataclasses.replace`` with an unknown name refused as a ValueError naming the valid ones
    (a TypeError of ``__init__`` before; ``cl_alpah``, or a file's ``alpha_L0_deg``)."""
    valid = [f.name for f in fields(p) if f.init]
    unknown = [k for k in changes if k not in valid]
    if unknown:
        hint = " (angles are in rad here; the _deg names are the parameter files')" if any(
            k.endswith("_deg") for k in unknown) else ""
        raise ValueError(f"unknown parameter(s) {', '.join(unknown)} of {type(p).__name__}{hint}; valid: "
                         f"{', '.join(valid)}")
    new = replace(p, **changes)
    # (the fields as the new record holds them, checked and converted: a float32 cl_max compared equal in float32 to
    # the float64 it changed, and the set kept its name, an API audit)
    moved = [k for k in changes if k not in RECORD_META and _differs(getattr(new, k), getattr(p, k))]
    if moved and "label" not in changes and p.label and not p.label.startswith("modified "):
        # a changed set is no longer the named one: its validation figures and coverage
        # (io.uncertainty, io.calibration.coverage, looked up by label) are not its own
        object.__setattr__(new, "label", f"modified {p.label}")  # (text, checked: not a second construction)
    return new


def _check_flags(p) -> None:
    for f in fields(p):
        if f.type in ("bool", bool) and not isinstance(getattr(p, f.name), (bool, np.bool_)):
            raise ValueError(f"{f.name} must be true or false, got {getattr(p, f.name)!r}")
        if f.type in ("bool", bool):
            object.__setattr__(p, f.name, bool(getattr(p, f.name)))


@dataclass(frozen=True)
class CamberedParams(RotorOptions):
    """Parameters of the cambered section polar (``section_model = "cambered"``).

    Attached flow (XROTOR / QPROP form, M. Drela):
    ``C_L = a (alpha - alpha_L0)`` and
    ``C_D = (cd_min + cd2 (C_L - cl_cdmin)^2) (Re / re_ref)^re_exp``,
    with ``a = cl_alpha (Re / re_ref)^re_exp_lift`` (divided by sqrt(1 - Ma^2) when
    ``compressibility``); Re / re_ref is held within [0.1, 5]. Stall: eq (3)'s sigmoid of
    sharpness ``M`` switches, at the angles ``cl_max / cl_alpha`` above and
    ``cl_min / cl_alpha`` below the zero-lift line (fixed angles, so the stall C_L follows
    the corrected slope a: Reynolds and Prandtl-Glauert factors included), to the flat
    plate ``C_L = cd90 sin a cos a``, ``C_D = cd90 sin^2 a`` (plus the
    profile drag), which holds at 90 deg and in reverse flow.

    Parameters
    ----------
    cl_alpha : float
        Lift-curve slope at ``re_ref`` [1/rad], in (0, 20].
    alpha_L0 : float
        Zero-lift angle from the blade-angle datum [rad], in [-20, 10] deg (negative for
        positive camber).
    cl_max, cl_min : float
        Stall limits of the attached lift line at ``re_ref`` [-]; cl_max in (0, 4],
        cl_min in [-4, 0).
    cd_min : float
        Minimum profile drag at ``re_ref`` [-], in [0, 1].
    cd2 : float
        Curvature of the drag polar dC_D/dC_L^2 [-], in [0, 10].
    cl_cdmin : float
        C_L of minimum drag [-], in [-2, 3].
    cd90 : float
        Flat-plate drag at 90 deg [-], in (0, 4] (about 2 for a plate of infinite span).
    re_ref : float
        Reference chord Reynolds number [-], in (0, 1e9].
    re_exp : float
        Reynolds exponent of the profile drag [-], in [-2, 1] (-0.5 laminar, -0.2
        turbulent; QPROP's REexp).
    re_exp_lift : float
        Reynolds exponent of the lift slope and CL_max [-], in [-1, 1].
    re_exp_stall : float
        Reynolds exponent of the stall angles [-], in [-1, 1].
    stall_delay : float
        Rotational stall delay: the stall angles grow by the factor
        1 + stall_delay (c/r)^2 [-], in [0, 20].
    alpha_L0_re : float
        Reynolds dependence of the zero-lift angle d alpha_L0 / d ln(Re) [rad], in
        [-5, 5] deg (negative, with alpha_L0 < 0: less effective camber at low Re).
    M : float
        Stall-blend sharpness [1/rad], in (0, 1000].
    compressibility : bool
        Prandtl-Glauert factor on the lift.
    tip_loss, hub_loss : bool
        Prandtl's tip / hub loss factor in the momentum balance.
    inflow : {"uniform", "drees", "pitt-peters"}, keyword-only
        Default ``"uniform"`` (the paper's v_i(r)).
    flap_compliance : float, keyword-only
        1 / K_beta [rad/(N m)], in [0, 1e3]; default 0 (rigid blades).
    collective : float, keyword-only
        Blade-angle offset [rad], in [-30, 30] deg; default 0.
    descent : {"glauert", "empirical"}, keyword-only
        Default ``"empirical"`` (the measured induced velocity of rotors in axial descent in
        the vortex-ring and turbulent-wake states).
    swirl : bool, keyword-only
        Default False.
    radial_drag, inplane_induction : bool, keyword-only
        Default True (docs/models.md: measured against the wind tunnel's in-plane force).
    dynamic_stall : float, keyword-only
        Gormont's gamma [-], in [0, 5]; default 0 (the static polar).
    air : Air, keyword-only
        The air the set goes with; default :class:`Air` ().
    label : str, keyword-only
        Where the set comes from, for outputs; not part of equality.

    The keyword-only fields are the rotor options of :class:`RotorOptions`, where each is
    described with its source.

    Raises
    ------
    ValueError
        A value non-finite, of the wrong type or outside the range above (the message
        names it and the range).
    """

    cl_alpha: float = 5.7
    alpha_L0: float = math.radians(-4.0)
    cl_max: float = 1.2
    cl_min: float = -0.5
    cd_min: float = 0.02
    cd2: float = 0.05
    cl_cdmin: float = 0.5
    cd90: float = 1.98
    re_ref: float = 1.0e5
    re_exp: float = -0.5
    re_exp_lift: float = 0.0
    re_exp_stall: float = 0.0
    stall_delay: float = 0.0
    alpha_L0_re: float = 0.0
    M: float = 20.0
    compressibility: bool = True
    tip_loss: bool = True
    hub_loss: bool = False

    section_model = "cambered"

    #: valid range of every float field (low, high), SI units
    RANGES = {
        "cl_alpha": (0.0, 20.0), "alpha_L0": (math.radians(-20.0), math.radians(10.0)),
        "cl_max": (0.0, 4.0), "cl_min": (-4.0, 0.0), "cd_min": (0.0, 1.0), "cd2": (0.0, 10.0),
        "cl_cdmin": (-2.0, 3.0), "cd90": (0.0, 4.0), "re_ref": (0.0, 1e9), "re_exp": (-2.0, 1.0),
        "re_exp_lift": (-1.0, 1.0), "re_exp_stall": (-1.0, 1.0), "stall_delay": (0.0, 20.0),
        "alpha_L0_re": (math.radians(-5.0), math.radians(5.0)), "M": (0.0, 1000.0),
    }
    _OPEN_LOW = ("cl_alpha", "cl_max", "cd90", "re_ref", "M")

    def __post_init__(self) -> None:
        _check_flags(self)
        self._check_rotor_options()
        for name, (lo, hi) in self.RANGES.items():
            x = checked(name, getattr(self, name), low=lo, high=hi, low_open=name in self._OPEN_LOW)
            object.__setattr__(self, name, x)
        if self.cl_min == 0.0:
            raise ValueError("cl_min must be in [-4, 0), got 0.0")


#: either section model's parameter record
SectionParams = AirfoilParams | CamberedParams


#: Table I of Gill & D'Andrea (2017); constants from footnote 2.
PRESETS: Mapping[str, AirfoilParams] = MappingProxyType({
    "gill2017-soft": AirfoilParams(cl1=6.9, cl2=2.0, cd=3.7, alpha0=math.radians(20.4)),
    "gill2017-stiff": AirfoilParams(cl1=4.2, cl2=2.0, cd=1.3, alpha0=math.radians(27.5)),
    "gill2017-apc": AirfoilParams(cl1=5.3, cl2=1.7, cd=1.8, alpha0=math.radians(20.6)),
})


def preset(name: str) -> AirfoilParams:
    """Return the named parameter preset.

    Parameters
    ----------
    name : str
        One of ``"gill2017-soft"``, ``"gill2017-stiff"``, ``"gill2017-apc"``
        (Table I of Gill & D'Andrea 2017: soft = Parrot AR.Drone 2.0,
        stiff = HQP 8x4.5, apc = APC 8x6).

    Returns
    -------
    AirfoilParams
        Carrying footnote 2's air and the label ``name``.

    Raises
    ------
    KeyError
        If ``name`` is not a preset; the message lists the valid names.
    TypeError
        ``name`` not a str (a list met "unhashable type").
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a preset's name (str; valid: {', '.join(PRESETS)}), got {type(name).__name__}")
    try:
        return PRESETS[name].replace(label=name)
    except KeyError:
        raise KeyError(f"unknown parameter preset {name!r}; valid: {', '.join(PRESETS)}") from None


def sigmoid_blend(alpha, alpha0: float, M: float):
    """Stall blend sigma(alpha) of eq (3), overflow-safe.

    ``sigma = 1 - 1 / ((1 + exp(M (alpha - alpha0))) (1 + exp(-M (alpha + alpha0))))``,
    algebraically equal to the paper's form; an overflowing exponential gives the
    correct limit 1 instead of inf/inf.

    Parameters
    ----------
    alpha : float or ndarray
        Angle of attack [rad].
    alpha0, M : float
        Stall angle [rad] and sharpness [1/rad].

    Returns
    -------
    float or ndarray
        sigma in [0, 1], same shape as ``alpha``.
    """
    with np.errstate(over="ignore"):
        p = np.exp(M * (alpha - alpha0))
        q = np.exp(-M * (alpha + alpha0))
    return 1.0 - 1.0 / ((1.0 + p) * (1.0 + q))
