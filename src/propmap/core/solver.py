"""Rotor loads T, D, Q from hybrid blade-element momentum theory in forward flight.

Gill & D'Andrea (2017), Section II: eqs (1)-(7) blade elements, (10) Glauert momentum,
(11) per-annulus inflow, (13)-(15) integration. Conventions follow
docs/numerics.md and are listed in docs/conventions.md.
"""

from __future__ import annotations

import math
import operator
import warnings
from dataclasses import dataclass

import numpy as np

from . import _flags, _kernel
from ._numbers import integer
from ._parallel import parallel_region, serial_only
from . import _momentum as mo
# (the inputs' ranges and the Mach warning's context are re-exported here, where the rest of the package takes them)
from ._inputs import (AIRSPEED_MAX, COLLECTIVE_RANGE, OMEGA_MAX, OMEGA_MIN, TIP_MACH_WARN,  # noqa: F401
                      operating_points, supersonic_tips_allowed, warn_tip_mach)
from .air import check_air
from .airfoil import Air, AirfoilParams, CamberedParams, SectionParams
from .derivatives import DERIVATIVE_LOADS, FLAPPING_LOADS, STILL_AIR, _derivative_inputs, _jacobian, differentiable
from .flapping import (COMPLIANCE, flap_damping, flapping, flapping_derivatives, rigid_compliance_derivatives,
                       warn_large_flapping)
from .geometry import Propeller
from .loads import RotorLoads, _new_loads
from .nodes import _lift_slope, _lift_slope_name, _prepared

__all__ = [
    "Discretization",
    "RotorLoads",
    "SolverError",
    "rotor_loads",
    "differentiable",
    "DEFAULT_DISCRETIZATION",
]


class SolverError(RuntimeError):
    """The inflow root solve failed; the message names the operating point and radius."""


@dataclass(frozen=True)
class Discretization:
    """Quadrature used by the solver.

    Parameters
    ----------
    n_radial : int
        Gauss-Legendre nodes on [r_hub, R], in [2, 10000] (a whole number of another type,
        48.0 or numpy.int64(48), is kept as an int). The first call with a given count
        computes its nodes (NumPy's ``leggauss``, kept for later calls), at a cost that grows
        as n^3: 0.13 s at 1,000, 0.59 s at 2,000, 10.9 s at 5,000 (2026-11-30, AMD EPYC;
        74-82 s at 10,000, an edge-of-range audit).
    n_azimuth : int
        Midpoint nodes on psi in [-pi/2, pi/2], in [2, 1000]. Every integrand depends on
        psi only through sin(psi), so n midpoints there equal a 2n-point periodic
        trapezoid rule on [0, 2 pi) (spectral convergence, docs/numerics.md). One node
        (psi = 0) would see no in-plane flow at all, hence the minimum 2. Multiples
        of 8 run fastest (SIMD lanes; benchmarks/README.md).

    Raises
    ------
    ValueError
        If a count is outside its range.
    """

    n_radial: int = 48
    n_azimuth: int = 16

    def __post_init__(self) -> None:
        for name, hi in (("n_radial", 10000), ("n_azimuth", 1000)):
            # (a whole float such as 48.0 kept as it was failed inside NumPy's Gauss-Legendre nodes)
            object.__setattr__(self, name, integer(name, getattr(self, name), 2, hi))


DEFAULT_DISCRETIZATION = Discretization()

#: batches smaller than this run on one thread: starting the parallel region costs more
#: than it saves for them on a loaded machine (benchmarks/README.md)
PARALLEL_MIN_POINTS = 32



#: a 1-element array's 0-d view (a[0, ...])
_ZERO_D = operator.itemgetter((0, Ellipsis))
#: the result's fields that are rows of the kernel's packed outputs: (row, field) of ``out``, ``counts`` and
#: ``flags`` (core/_kernel.solve_batch; out's row 9, the in-plane ratio m, and counts' rows 0-2 are not returned)
_OUT_FIELDS = ((0, "thrust"), (1, "drag"), (2, "torque"), (3, "rolling_moment"), (4, "side_force"),
               (5, "pitching_moment"), (6, "v_i_mean"), (7, "v_h"), (8, "descent_ratio"), (10, "reverse_flow_radius"))
_COUNTS_FIELDS = ((3, "n_evaluations"), (4, "state"))
_FLAGS_FIELDS = ((0, "converged"), (1, "vortex_ring"), (2, "multiple_roots"), (3, "reverse_flow"),
                 (4, "inflow_extrapolated"))
_PACKED_FIELDS = (_OUT_FIELDS, _COUNTS_FIELDS, _FLAGS_FIELDS)
_ROW_FIELDS = tuple(f for fields in _PACKED_FIELDS for _, f in fields)
#: each packed output's rows (1-d views) and, for one point, their 0-d views: one C-level call per array
_ROWS = tuple(operator.itemgetter(*(i for i, _ in fields)) for fields in _PACKED_FIELDS)
_ROWS_0D = tuple(operator.itemgetter(*((i, 0, Ellipsis) for i, _ in fields)) for fields in _PACKED_FIELDS)
#: the per-annulus fields, None unless ``radial``
_NO_RADIAL = dict.fromkeys(("v_i", "dT_dr", "dD_dr", "dQ_dr", "dMR_dr", "dY_dr", "dMP_dr"))


def _row_fields(shape: tuple, out: np.ndarray, counts: np.ndarray, flags: np.ndarray) -> dict:
    """The result's fields that are rows of the kernel's packed outputs, as views shaped ``shape``
    (for one point 0-d views, got by three C-level getters: a third of the cost of one per field)."""
    if shape == ():
        rows = _ROWS_0D[0](out) + _ROWS_0D[1](counts) + _ROWS_0D[2](flags)
    elif len(shape) == 1:
        rows = _ROWS[0](out) + _ROWS[1](counts) + _ROWS[2](flags)
    else:  # (each packed array reshaped once, not each of its rows)
        rows = (_ROWS[0](out.reshape(out.shape[:1] + shape)) + _ROWS[1](counts.reshape(counts.shape[:1] + shape))
                + _ROWS[2](flags.reshape(flags.shape[:1] + shape)))
    return dict(zip(_ROW_FIELDS, rows))


def _spin_up_scaled(om, V, T, D, Q, R, Y, P, vbar, b1c, b1s, rad, radial: bool):
    """The loads solved at OMEGA_MIN, taken to the rates ``om`` below it (parked blades): in
    still air (V = 0) loads and flap angles scale by (Omega / OMEGA_MIN)^2 and induced
    velocities by Omega / OMEGA_MIN, to exactly 0 at Omega = 0; in a flow they are held
    (Omega at or above OMEGA_MIN unchanged)."""
    f = np.where((om < OMEGA_MIN) & (V == 0.0), om / OMEGA_MIN, 1.0)
    f2 = f * f
    scaled = [a * f2 + 0.0 for a in (T, D, Q, R, Y, P)] + [vbar * f + 0.0, b1c * f2 + 0.0, b1s * f2 + 0.0]
    if radial:
        rad = rad.copy()
        rad[0] *= f[:, None]
        rad[1:_kernel.RAD_SWIRL] *= f2[None, :, None]
        rad[_kernel.RAD_SWIRL] *= f[:, None]  # the swirl, a velocity (the uniform roots only serve derivatives,
        # which are refused below OMEGA_MIN; that row is not allocated for the uniform inflow)
    return (*scaled, rad)


_UNCHECKED = object()


def check_model_args(propeller, params, air=_UNCHECKED, discretization=_UNCHECKED) -> None:
    """Refuse model arguments of the wrong type with a TypeError naming the argument (the
    public entry points call it first, so that a wrong object never surfaces as an
    AttributeError deep inside).

    Raises
    ------
    TypeError
        ``propeller`` not a :class:`Propeller`, ``params`` not an ``AirfoilParams`` or
        ``CamberedParams`` (a set's name such as ``"generic"`` included: resolve it with
        :func:`propmap.resolve_params`), ``air`` not an :class:`Air`, ``discretization`` not a
        :class:`Discretization` (each checked only when given).
    """
    if not isinstance(propeller, Propeller):
        raise TypeError(f"propeller must be a Propeller (propmap.load_propeller, read_geometry), "
                        f"got {type(propeller).__name__}")
    _check_params(params)
    if air is not _UNCHECKED:
        check_air(air)
    if discretization is not _UNCHECKED and not isinstance(discretization, Discretization):
        raise TypeError(f"discretization must be a propmap.Discretization, got {type(discretization).__name__}")


def _check_params(params, name: str = "params") -> None:
    if not isinstance(params, (AirfoilParams, CamberedParams)):
        hint = " (a set's name: resolve it with propmap.resolve_params)" if isinstance(params, str) else ""
        raise TypeError(f"{name} must be AirfoilParams or CamberedParams (propmap.default_params, generic_params, "
                        f"read_params){hint}, got {type(params).__name__}")


def model_air(params, air=None, *, name: str = "params") -> Air:
    """The air of a model call: ``air`` where given, else the parameter set's own.

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
    air : Air, optional
    name : str
        The argument's name in the caller, for the message.

    Returns
    -------
    Air

    Raises
    ------
    TypeError
        ``params`` not a parameter set (a set's name included), or ``air`` not an :class:`Air`.
    """
    _check_params(params, name)
    air = params.air if air is None else air
    check_air(air)
    return air


def _warn_dynamic_stall_cusp(V, Vs, b, wrt) -> None:
    """Warn of derivatives asked where the dynamic stall's loads have a cusp: with no in-plane
    airspeed (axial flow or rest) Gormont's delay grows as the square root of the in-plane
    airspeed, so the loads' slopes across it (the incidence in axial flow, the airspeed from
    rest, the in-plane velocity's at rest) are unbounded; the kernel returns the static
    section's there (docs/solver.md, Dynamic stall)."""
    from ._delayed_sensitivity import DELAY_VB_FLOOR

    none = np.zeros(V.shape, bool)
    # (an in-plane airspeed below DELAY_VB_FLOOR is none to the derivatives, core/_sensitivity.py)
    axial = (np.abs(Vs) <= DELAY_VB_FLOOR) & (V > 0.0) if "incidence" in wrt else none
    # from rest: along a ray with an in-plane part (airspeed), or the in-plane slopes (STILL_AIR)
    rest = (V <= DELAY_VB_FLOOR) & ((np.abs(np.sin(b)) > 1e-12) if "airspeed" in wrt else none) | (
        (V <= DELAY_VB_FLOOR) if STILL_AIR in wrt else none)
    n = int(np.count_nonzero(axial | rest))
    if n:
        warnings.warn(f"dynamic_stall: {n} point(s) have no in-plane airspeed (axial flow or rest), where the loads "
                      "grow as the square root of the in-plane airspeed (Gormont's delay): their derivatives across "
                      "it (incidence in axial flow, airspeed and in-plane velocity at rest) are unbounded; the values "
                      "returned are the static section's (docs/solver.md, Dynamic stall)", UserWarning, stacklevel=3)


def _solver_error(status, shape: tuple, om, V, b, y_R) -> SolverError:
    """The error of the first failed point of a batch: its inputs, the annulus and why
    (``status``: the kernel's per-point codes, 0 where solved, else 1 + 4 annulus + reason)."""
    i = int(np.argmax(status != 0))
    j, reason = divmod(int(status[i]) - 1, 4)
    why = {1: "no sign change of F found (no bracket)", 2: "the refinement of the bracket did not converge",
           3: f"the swirl did not balance the annulus' angular momentum within {mo.SWIRL_MAX_ITER} root solves, "
              "nor close in on a jump of its selected root"}[reason]
    parked = f", solved at {OMEGA_MIN:g} rad/s as parked blades" if om[i] < OMEGA_MIN else ""
    return SolverError(f"inflow root solve failed at operating point {np.unravel_index(i, shape)} "
                       f"(omega={om[i]:.6g} rad/s{parked}, airspeed={V[i]:.6g} m/s, "
                       f"incidence={math.degrees(b[i]):.6g} deg) on annulus r/R={y_R[j]:.4f}: {why}")


def rotor_loads(
    propeller: Propeller,
    params: SectionParams,
    omega,
    airspeed,
    incidence,
    *,
    air: Air | None = None,
    discretization: Discretization = DEFAULT_DISCRETIZATION,
    on_failure: str = "raise",
    radial: bool = False,
    collective=None,
    derivatives=False,
) -> RotorLoads:
    """Thrust, rotor drag and torque of a propeller at any operating point.

    Hybrid BET/BEMT of Gill & D'Andrea (2017), Section II: for every radial node the
    induced inflow v_i solves dT_BET = dT_BEMT (eq 11; eq 10 with Glauert's mass flow,
    root-selection rule in docs/solver.md), then eqs (13)-(15) are integrated over the
    blade [r_hub, R] with Gauss-Legendre in r and midpoints in azimuth. The section
    model is the paper's (eqs 3-4, :class:`AirfoilParams`) or the cambered polar
    (:class:`CamberedParams`); with ``tip_loss``/``hub_loss`` Prandtl's factor F
    multiplies the momentum side of eq (11), dT_BEMT = F 4 pi rho y v_i W.

    Parameters
    ----------
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    omega : float or array_like
        Rotation rate Omega [rad/s], finite, in [0, 1e5]. Below 0.1 rad/s the blades are
        taken as parked (a stopped rotor, the start of a spin-up): in a flow the loads are
        the solution at 0.1 rad/s, where every blade element sees the freestream (the
        parked blades' loads averaged over their azimuth: drag, and a thrust and torque
        of either sign); in still air (V = 0) they scale by (Omega / 0.1)^2 to exactly 0
        at Omega = 0, the induced velocities by Omega / 0.1. So below 0.1 rad/s the loads jump
        between V = 0 and V > 0 where V is not large against 0.1 rad/s times the radius (the
        solution at 0.1 rad/s is then the rotation's more than the freestream's).
    airspeed : float or array_like
        Speed V of the disk relative to the air [m/s], finite, in [0, 500].
    incidence : float or array_like
        beta [rad] in [0, pi]: the angle between the disk's velocity relative to the air
        and the rotor axis, the thrust's direction (0 axial climb, pi/2 edgewise, pi axial
        descent; the freestream the disk meets is the opposite of that velocity);
        docs/numerics.md item 1. Irrelevant when V = 0. A value outside [0, pi] by at most
        2.5e-7 (single precision's pi, 8.7e-8 above it) is taken as that end.
    air : Air, optional
        Density, viscosity, speed of sound. Default: the parameter set's (``params.air``).
    discretization : Discretization, optional
    on_failure : {"raise", "flag"}
        ``"raise"`` (default): raise SolverError if any annulus fails. ``"flag"``:
        return, with ``converged`` False and NaN loads at the failed points.
    radial : bool
        Keep the per-annulus outputs (``v_i``, ``dT_dr``, ``dD_dr``, ``dQ_dr``,
        ``dMR_dr``, ``dY_dr``, ``dMP_dr``; 7 n_radial doubles per point). False (the
        default): they are None.
    collective : float or array_like, optional
        A blade-angle offset per operating point [rad] in [-pi/4, pi/4], added to every
        blade angle theta(r) (on top of ``params.collective``): a variable-pitch rotor's
        collective, or a collective sweep of one geometry. Broadcast with ``omega``,
        ``airspeed`` and ``incidence``. None (default): no offset.
    derivatives : bool or sequence of str
        True: also the derivatives of T, D, Q, M_R, v_i,mean and (flapping blades, a linear
        inflow or the dynamic stall; zeros for rigid blades in the uniform inflow with the static
        polar) Y and M_P with respect to
        ``omega``, ``airspeed`` and ``incidence`` (:meth:`RotorLoads.derivative`); a sequence names
        the inputs, ``"collective"`` among them (the blade-angle offset, the same for
        ``params.collective`` and ``collective``), section parameters (numeric fields of
        ``params`` other than :data:`~propmap.core.derivatives.NODE_FIELDS`), ``"rho"``
        (the air density [kg/m^3]) and ``"flap_compliance"``. By the implicit function
        theorem on each annulus' converged root (core/_sensitivity.py), not by differencing
        the solver, and for flapping blades the chain rule through the flapping
        (core/flapping.flapping_derivatives); with swirl each annulus' root and angular
        momentum balance together (core/_swirl_sensitivity._swirl_system); with a linear inflow
        model through both of its solves, the gradients' change with the uniform solve's mean
        inflow included, with or without swirl (core/_linear_sensitivity.py); with the dynamic
        stall through Gormont's delay as well (core/_delayed_sensitivity.py); for
        Omega >= 0.1 rad/s. False (default): none. Memory: the derivatives need every
        annulus' root, so the call holds the per-annulus rows as ``radial`` does and a copy,
        about 9 n_radial doubles per point while it runs (3.4 kB at 48 nodes: 3.4 GB for
        10^6 points, against 0.19 kB without; measured 2026-11-27), 0.3 kB kept: give a
        large batch in parts.

    Returns
    -------
    RotorLoads
        Arrays of the broadcast shape of ``omega, airspeed, incidence``.

    Raises
    ------
    TypeError
        ``propeller``, ``params``, ``air`` or ``discretization`` of the wrong type
        (:func:`check_model_args`).
    ValueError
        An input that is not a number (a string, a bool), outside its range, or of
        shapes that do not broadcast (the message names it and the range); a masked
        array with masked entries; ``on_failure`` or ``radial`` (True or False) of
        another value. With ``derivatives``: an unknown input name, a node-changing parameter
        (:data:`~propmap.core.derivatives.NODE_FIELDS`), an Omega below 0.1 rad/s, with
        ``"rho"`` a density too small to be stepped, or ``dynamic_stall`` itself
        (:func:`~propmap.core.derivatives.differentiable`).
    SolverError
        A root solve failed and ``on_failure="raise"``; the message names the point,
        the radius and the reason.

    Warns
    -----
    UserWarning
        A blade tip meets the air above Mach 0.8 (:data:`TIP_MACH_WARN`; Omega R + V sin(beta)
        and V cos(beta)): the model's compressibility stops at Mach 0.9, and such a rate is
        most often one in rpm given as rad/s. Flapping blades that flap by more than 0.25 rad
        (:data:`~propmap.core.flapping.FLAP_ANGLE_WARN`: a stopped or slow rotor in a flow),
        beyond the small-angle flapping model.
    """
    air = getattr(params, "air", None) if air is None else air  # checked below
    check_model_args(propeller, params, air, discretization)
    if on_failure not in ("raise", "flag"):
        raise ValueError(f"on_failure must be 'raise' or 'flag', got {on_failure!r}")
    if radial is not False and radial is not True and not isinstance(radial, np.bool_):  # ('yes' was read as True)
        raise ValueError(f"radial must be True or False, got {radial!r:.60}")
    shape, om1, V1, b1, c1, Vs, Vc, any_slow, tip = operating_points(omega, airspeed, incidence, collective,
                                                                      propeller.radius)
    warn_tip_mach(tip, air.speed_of_sound)
    wrt = () if derivatives is False else _derivative_inputs(derivatives, params)
    if wrt and any_slow:
        raise ValueError(f"derivatives need omega >= {OMEGA_MIN:g} rad/s (below it the blades are parked)")
    if wrt and getattr(params, "dynamic_stall", 0.0) > 0.0 and ({"incidence", "airspeed", STILL_AIR} & set(wrt)):
        _warn_dynamic_stall_cusp(V1, Vs, b1, wrt)
    keep_radial = radial or bool(wrt)  # the derivatives need the roots
    om_in = om1
    if any_slow:  # spin-up and stopped rotors: solved at OMEGA_MIN, scaled below
        om1 = np.maximum(om1, OMEGA_MIN)
    nd, model, pk, cam, inflow, empirical, cls = _prepared(propeller, params, air, discretization)
    n, nr = om1.size, nd.y.size
    out = np.empty((_kernel.N_OUT, n))  # T, D, Q, M_R, Y, M_P, mean inflow, v_h, k, m, reverse-flow radius
    rows = n if keep_radial else 1  # unused (1, nr) scratch when the per-annulus outputs are not kept
    # v_i, dT, dD, dQ, dM_R, dY, dM_P, swirl and, with a linear inflow model only, the uniform solve's roots
    rad = np.empty((_kernel.N_RAD if inflow != mo.INFLOW_UNIFORM else _kernel.RAD_UNIFORM, rows, nr))
    counts = np.empty((_kernel.N_COUNTS, n), dtype=np.int64)  # status, multiple, in vortex ring, evaluations, state
    flags = np.empty((_kernel.N_FLAGS, n), dtype=np.bool_)  # converged, vortex ring, multiple, reverse, extrapolated
    # (row 1 of counts, the annuli with multiple roots, is read by point_flags; row 2, those in vortex ring, unused)
    # a small batch runs on the calling thread: starting the parallel region would cost more
    # than the work (and a single call need not load the thread pool at all). The kernel also
    # writes the working state, v_h, the descent ratio, the reverse-flow radius and the flags
    # (_flags.point_flags: no NumPy calls on one-point arrays here)
    args = (om1, Vs, Vc, c1, nd.rows, nd.azimuth, model, pk, cam, inflow, empirical, params.swirl, propeller.radius,
            keep_radial, cls, out, rad, counts, flags)
    serial = n < PARALLEL_MIN_POINTS or serial_only()  # (a child forked after a parallel region: core/_parallel.py)
    if serial:
        _kernel.solve_batch_serial(*args)
    else:
        with parallel_region():  # (numba's workqueue layer aborts on two threads' parallel regions: core/_parallel.py)
            _kernel.solve_batch(*args)
    status = counts[0]
    if on_failure == "raise" and (status[0] != 0 if n == 1 else status.any()):  # .any() costs 0.8 us
        raise _solver_error(status, shape, om_in, V1, b1, nd.y / propeller.radius)  # (the rates given, not OMEGA_MIN)
    if len(shape) == 1:  # the common case: no reshaping
        def s(a):
            return a
    elif shape == ():  # one point: 0-d views, by a C-level getter (half a reshape's cost)
        s = _ZERO_D
    else:
        def s(a):
            return a.reshape(shape)
    # the rows of out, counts and flags as the result's fields (views: the spin-up's flags below write into them)
    fields = _row_fields(shape, out, counts, flags)
    flapping_blades = params.flap_compliance > 0
    if flapping_blades or any_slow or wrt:
        T, D, Q, R, Y, P, vbar = out[:7]
        rigid = (T, D, Q, R)  # (rows of out: flapping below returns new arrays)
    if flapping_blades:
        per_slope = flap_damping(air.rho, 1.0, float(nd.chord_r3), om1)  # dD_beta / d(lift slope)
        damping = _lift_slope(params) * per_slope
        D, Y, R, P, b1c, b1s = flapping(T, D, Y, R, P, damping, params.flap_compliance, propeller.n_blades)
    else:  # (two arrays: the result's fields share no memory, so writing into one changes no other)
        b1c, b1s = np.zeros(n), np.zeros(n)
    if any_slow:
        T, D, Q, R, Y, P, vbar, b1c, b1s, rad = _spin_up_scaled(om_in, V1, T, D, Q, R, Y, P, vbar, b1c, b1s, rad,
                                                                radial)
        om1 = om_in
        # the states and flags again, for the scaled thrust and inflow and the rates asked for (a stopped
        # rotor: its whole retreating side in reverse flow, radius inf, with in-plane flow)
        out[0], out[6] = T, vbar
        _flags.point_flags(out, counts, Vs, Vc, om1, cls, inflow != mo.INFLOW_UNIFORM, empirical, flags,
                           inflow == mo.INFLOW_DREES)
        # (working state, v_h, descent ratio and the inflow-validity flag: a linear inflow model with net
        # upflow; the empirical descent curve blended in forward flight by propmap's fade)
    if flapping_blades:
        warn_large_flapping(b1c, b1s, params.flap_compliance)
    if flapping_blades or any_slow:  # (new arrays, not the rows of out)
        fields.update(thrust=s(T), drag=s(D), torque=s(Q), rolling_moment=s(R), side_force=s(Y),
                      pitching_moment=s(P), v_i_mean=s(vbar))
    jac = None
    if wrt:
        solved = tuple(w for w in wrt if w != COMPLIANCE)  # the compliance enters the flapping only
        # v_i (and the swirl), contiguous as the kernel is compiled for
        roots = rad[[0, _kernel.RAD_SWIRL]] if params.swirl else rad[:1]  # (a copy, contiguous)
        uniform = rad[_kernel.RAD_UNIFORM] if inflow != mo.INFLOW_UNIFORM else None  # (core/_kernel._solve_point)
        raw = (_jacobian(solved, om1, V1, b1, c1, roots, flags[0], nd, model, pk, cam, empirical, params, air,
                         propeller, discretization, rigid + (out[4], out[5]), uniform, serial=serial) if solved else {})
        if params.flap_compliance > 0:
            if COMPLIANCE in wrt:
                raw.update({(q, COMPLIANCE): np.zeros(n) for q in DERIVATIVE_LOADS})
            raw = flapping_derivatives(raw, T, rigid[3], damping, params.flap_compliance, propeller.n_blades,
                                       omega=om1, rho=air.rho, lift_slope=(_lift_slope_name(params), per_slope),
                                       pitching_moment=out[5])
        else:  # rigid blades with the uniform inflow and the static polar: no side force or pitching moment at any
            # input (a linear inflow's and the dynamic stall's are the kernel's)
            raw.update({(q, w): np.zeros(n) for q in FLAPPING_LOADS for w in solved if (q, w) not in raw})
            if COMPLIANCE in wrt:  # (Y and M_P linear in it; D and M_R too with a linear inflow, else quadratic)
                raw.update(rigid_compliance_derivatives(
                    T, rigid[3], _lift_slope(params) * flap_damping(air.rho, 1.0, float(nd.chord_r3), om1),
                    propeller.n_blades, pitching_moment=out[5]))
        jac = {k: s(a) for k, a in raw.items()}
    if radial:
        fields.update(zip(_NO_RADIAL, [a.reshape(shape + (nr,)) for a in rad[:_kernel.RAD_SWIRL]]))
    else:
        fields.update(_NO_RADIAL)
    fields.update(omega=s(om1), airspeed=s(V1), incidence=s(b1), flap_1c=s(b1c), flap_1s=s(b1s), r=nd.y,
                  rho=air.rho, diameter=propeller.diameter, jacobian=jac)
    return _new_loads(fields)


