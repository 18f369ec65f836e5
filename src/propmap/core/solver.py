"""Rotor loads T, D, Q from hybrid blade-element momentum theory in forward flight.

Gill & D'Andrea (2017), Section II: eqs (1)-(7) blade elements, (10) Glauert momentum,
(11) per-annulus inflow, (13)-(15) integration. Conventions follow
docs/numerics.md and are listed in docs/conventions.md.
"""

from __future__ import annotations

import functools
import math
import operator
from dataclasses import dataclass, fields
from dataclasses import replace as dc_replace

import numpy as np

from . import _kernel
from . import _physics as ph
from .airfoil import RECORD_META, Air, AirfoilParams, CamberedParams, SectionParams, _model_constants
from .flapping import flap_damping, flapping
from .geometry import Propeller
from .states import BAND_ARRAY, K_WINDMILL, STATES

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
        Gauss-Legendre nodes on [r_hub, R], in [2, 10000].
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
        from .geometry import _real

        for name, hi in (("n_radial", 10000), ("n_azimuth", 1000)):
            v = getattr(self, name)
            x = _real(v)
            if x is None or not (math.isfinite(x) and x.is_integer() and 2 <= x <= hi):
                raise ValueError(f"{name} must be an integer in [2, {hi}], got {v!r:.60}")


DEFAULT_DISCRETIZATION = Discretization()

#: batches smaller than this run on one thread: starting the parallel region costs more
#: than it saves for them on a loaded machine (benchmarks/README.md)
PARALLEL_MIN_POINTS = 32


@dataclass(frozen=True)
class _Nodes:
    """Quadrature nodes and every per-annulus constant the kernel needs (read-only arrays).

    ``sc``: section constant (gill2017: Blasius factor 2 * 1.02 c_p sqrt(mu/(rho c));
    cambered: ln(rho c / (mu Re_ref))); ``cy2`` = (c/y)^2. ``ct``, ``ch``: tip- and hub-loss constants
    (N_b/2)(R - y)/y and (N_b/2)(y - r_hub)/r_hub, -1 where that loss is off. ``theta``
    includes the collective offset. ``sinpsi``, ``cospsi``: the full circle of 2 n_azimuth
    midpoints from -pi/2, whose first half is the half circle the uniform inflow needs.
    ``chord_r3``: int c r^3 dr over the blade [m^5] (0-d), for the flap damping.
    """

    y: np.ndarray
    w: np.ndarray
    theta: np.ndarray
    sin_th: np.ndarray
    cos_th: np.ndarray
    sc: np.ndarray
    cy2: np.ndarray
    cfac: np.ndarray
    mfac: np.ndarray
    ct: np.ndarray
    ch: np.ndarray
    sinpsi: np.ndarray
    cospsi: np.ndarray
    chord_r3: np.ndarray


@functools.lru_cache(maxsize=64)
def _nodes(prop: Propeller, n_radial: int, n_azimuth: int, air: Air, params: SectionParams) -> _Nodes:
    x, wx = np.polynomial.legendre.leggauss(n_radial)
    half = 0.5 * (prop.radius - prop.r_hub)
    y = prop.r_hub + half * (x + 1.0)
    w = half * wx
    c = prop.chord_at(y)
    th = prop.theta_at(y) + params.collective
    cpos = np.maximum(c, 1e-300)
    if isinstance(params, CamberedParams):
        # a zero chord carries no load (cfac = 0); its Reynolds number is set to Re_ref so
        # that the factors stay finite (ln 0 would overflow them)
        sc = np.where(c > 0, np.log(air.rho * cpos / (air.mu * params.re_ref)), 0.0)
    else:
        sc = np.where(c > 0, 2.0 * 1.02 * params.cp_blasius * np.sqrt(air.mu / (air.rho * cpos)), 0.0)
    half_b = 0.5 * prop.n_blades
    ct = half_b * (prop.radius - y) / y if params.tip_loss else np.full(n_radial, -1.0)
    ch = half_b * (y - prop.r_hub) / prop.r_hub if params.hub_loss else np.full(n_radial, -1.0)
    psi = -0.5 * np.pi + (np.arange(2 * n_azimuth) + 0.5) * np.pi / n_azimuth
    out = _Nodes(y=y, w=w, theta=th, sin_th=np.sin(th), cos_th=np.cos(th), sc=sc, cy2=(c / y) ** 2,
                 cfac=prop.n_blades * 0.5 * air.rho * c, mfac=4.0 * np.pi * air.rho * y, ct=ct, ch=ch,
                 sinpsi=np.sin(psi), cospsi=np.cos(psi), chord_r3=np.array(np.sum(w * c * y**3)))
    for a in vars(out).values():
        a.setflags(write=False)
    return out


def _lift_slope(params: SectionParams) -> float:
    """Attached-flow lift slope of the section [1/rad]: cl_alpha (cambered), c_l1 (eq 3) or,
    for footnote 1's sin-cos lift, c_l2 (its slope at alpha = 0)."""
    if isinstance(params, CamberedParams):
        return params.cl_alpha
    return params.cl2 if params.lift_model == "sincos" else params.cl1


#: the kernel's model arguments of recent (propeller, params, air, discretization), by identity:
#: the records are immutable, so a call with the same objects (a controller's or a fitting loop's
#: single points) skips hashing them for _nodes and rebuilding the constant vectors
_PREPARED: dict = {}
_PREPARED_MAX = 64


def _prepared(propeller: Propeller, params: SectionParams, air: Air, discretization: Discretization):
    """(nodes, model code, pk, cam, inflow code, empirical descent, the flags' constants cls) of a
    model, cached by identity
    (the cache holds the objects, so an id is not reused while its entry lives)."""
    key = (id(propeller), id(params), id(air), id(discretization))
    hit = _PREPARED.get(key)
    if hit is not None and hit[0] is propeller and hit[1] is params and hit[2] is air and hit[3] is discretization:
        return hit[4]
    nd = _nodes(propeller, discretization.n_radial, discretization.n_azimuth, air, params)
    model, pk = _model_constants(params)
    cam = _cambered_args(params, air)
    cls = np.empty(_kernel.CLS_BAND + BAND_ARRAY.size)  # _kernel.point_flags' constants
    cls[_kernel.CLS_RHO], cls[_kernel.CLS_RADIUS], cls[_kernel.CLS_R_HUB] = air.rho, propeller.radius, propeller.r_hub
    cls[_kernel.CLS_K_WINDMILL], cls[_kernel.CLS_BAND:] = K_WINDMILL, BAND_ARRAY
    for a in (pk, cam, cls):
        a.setflags(write=False)
    prep = (nd, model, pk, cam, ph.INFLOW_CODES[params.inflow], bool(ph.DESCENT_CODES[params.descent]), cls)
    if len(_PREPARED) >= _PREPARED_MAX:
        _PREPARED.clear()
    _PREPARED[key] = (propeller, params, air, discretization, prep)
    return prep


def _cambered_args(params: SectionParams, air: Air) -> np.ndarray:
    """``cam`` argument of the kernel: (cl_alpha, re_exp, re_exp_lift, compressible, 1/a^2,
    re_exp_stall, stall_delay, alpha_L0_re)."""
    if not isinstance(params, CamberedParams):
        return np.zeros(8)
    return np.array([params.cl_alpha, params.re_exp, params.re_exp_lift, float(params.compressibility),
                     1.0 / air.speed_of_sound**2, params.re_exp_stall, params.stall_delay, params.alpha_L0_re])


@dataclass(frozen=True)
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
        zero by symmetry in this model.
    side_force : ndarray
        Y [N], in the disk plane, normal to the in-plane velocity, positive toward the
        advancing side. 0 exactly with the paper's uniform inflow and rigid blades (every
        integrand then depends on psi through sin psi only); non-zero with a linear inflow
        model or with flapping (:class:`~propmap.core.airfoil.RotorOptions`).
    pitching_moment : ndarray
        M_P [N m], the moment of the thrust distribution about the disk's lateral axis,
        -(N_b / 2 pi) int int r dT(r, psi) cos psi dpsi dr, positive when the upstream half
        (psi = 180 deg) carries more thrust (nose-up for a disk moving forward; the vector
        is M_P e_ip x z_hat). 0 with the uniform inflow and rigid blades.
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
        Q/(rho n^2 D^5), n = Omega/(2 pi) [rev/s], D the diameter.
    J : ndarray
        Advance ratio V/(n D) [-] (total airspeed).
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
        V sin(beta) / Omega [m]: radius inside which the retreating blade sees reverse flow.
    inflow_extrapolated : ndarray of bool
        The inflow model was used outside the measurements behind it: a linear inflow model
        with the wake above the disk (inflow ratio < 0, the model's mirrored extrapolation;
        _physics.inflow_gradients), or the empirical descent momentum (``descent =
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
        """d(quantity)/d(wrt) at every point, by the implicit function theorem (core/_sensitivity.py).

        Parameters
        ----------
        quantity : {"thrust", "drag", "torque", "rolling_moment", "v_i_mean"}
        wrt : str
            "omega" [rad/s], "airspeed" [m/s], "incidence" [rad], "collective" [rad], "rho"
            [kg/m^3] or a section parameter's name (in its SI unit); as asked of
            :func:`rotor_loads` (``derivatives``).

        Returns
        -------
        ndarray, shape S
            [N or N m per unit of ``wrt``]; NaN where the point did not converge. At
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
        if quantity not in DERIVATIVE_LOADS:
            raise ValueError(f"quantity must be one of {', '.join(DERIVATIVE_LOADS)}, got {quantity!r:.60}")
        if (quantity, wrt) not in self.jacobian:
            have = sorted({w for _, w in self.jacobian})
            raise ValueError(f"wrt must be one of {', '.join(have)} (the derivatives asked of rotor_loads), "
                             f"got {wrt!r:.60}")
        return self.jacobian[(quantity, wrt)]

    @property
    def state_name(self) -> np.ndarray:
        """The working state's name at every point (array of str, shape S)."""
        return np.asarray(STATES, dtype=object)[np.asarray(self.state)]

    @property
    def inflow_ratio(self) -> np.ndarray:
        """v_i,mean / v_h [-], shape S (NaN where T <= 0)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.v_h > 0, self.v_i_mean / np.where(self.v_h > 0, self.v_h, 1.0), np.nan)

    @property
    def power(self) -> np.ndarray:
        """P = Q Omega [W], shape S."""
        return self.torque * self.omega

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
        """P / (rho n^3 D^5) [-], propeller convention, shape S."""
        return self._per_n(self.power, self.rho * self._n**3 * self.diameter**5)

    @property
    def J(self) -> np.ndarray:
        """V / (n D) [-], total airspeed, shape S."""
        return self._per_n(self.airspeed, self._n * self.diameter)

    def flags(self, index=()) -> list[str]:
        """Names of the raised status flags at one point (``index`` into shape S; on scalar
        loads, shape (), ``()`` or ``0``).

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
        names = []
        if not bool(conv[index]):
            names.append("not_converged")
        for key in ("vortex_ring", "multiple_roots", "reverse_flow", "inflow_extrapolated"):
            if bool(np.asarray(getattr(self, key))[index]):
                names.append(key)
        return names


_LOADS_FIELDS = frozenset(f.name for f in fields(RotorLoads))


def _new_loads(**kw) -> RotorLoads:
    """A RotorLoads from all its fields, without the frozen dataclass's per-field
    ``object.__setattr__`` (a few microseconds of a single point's call); the fields must be
    exactly :class:`RotorLoads`'s (checked by tests/test_invariants.py)."""
    obj = object.__new__(RotorLoads)
    obj.__dict__.update(kw)
    return obj


#: what ``rotor_loads(derivatives=...)`` differentiates, and with respect to what
DERIVATIVE_LOADS = ("thrust", "drag", "torque", "rolling_moment", "v_i_mean")
DERIVATIVE_INPUTS = ("omega", "airspeed", "incidence", "collective")
#: the air density, differentiated besides the inputs and the section parameters
RHO = "rho"
#: internal (core/vector.py): at the points with V = 0, the loads' slopes in the velocity along three rays
#: from the same roots (:func:`_still_air_jacobian`); 0 elsewhere
STILL_AIR = "_still_air"
#: the loads odd in V sin(beta), whose slope at rest is the edgewise one
_ODD_LOADS = ("drag", "rolling_moment")

#: the rotation rates [rad/s]: [0, OMEGA_MAX]; below OMEGA_MIN the blades are parked: the loads are the
#: solution at OMEGA_MIN (in still air scaled by (Omega / OMEGA_MIN)^2 to 0 at Omega = 0); the solver
#: itself, whose coefficients are referred to n^2, runs from OMEGA_MIN
OMEGA_MIN = 0.1
OMEGA_MAX = 1e5
AIRSPEED_MAX = 500.0
#: the per-point collective's range [rad] (the blade-angle offset of ``rotor_loads(collective=)``)
COLLECTIVE_RANGE = math.radians(45.0)
_RANGES = {"omega": (0.0, OMEGA_MAX, "rad/s"), "airspeed": (0.0, AIRSPEED_MAX, "m/s"),
           "incidence": (0.0, math.pi, "rad"), "collective": (-COLLECTIVE_RANGE, COLLECTIVE_RANGE, "rad")}


#: a 1-element array's 0-d view (a[0, ...])
_ZERO_D = operator.itemgetter((0, Ellipsis))


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
        rad[1:] *= f2[None, :, None]
    return (*scaled, rad)


def _range_error(name: str, value) -> ValueError:
    lo, hi, unit = _RANGES[name]
    why = ""
    if name == "omega" and isinstance(value, float) and value < 0:
        why = " (a signed rotation rate is refused: give its magnitude, and the sense as the rotor's spin)"
    if name == "incidence" and isinstance(value, float) and -math.pi <= value < 0:
        why = " (the model is symmetric in the incidence: give its magnitude)"
    return ValueError(f"{name} must be finite and in [{lo:g}, {hi:g}] {unit}; got {value!r}{why}")


def _as_array(name: str, value) -> np.ndarray:
    """``value`` as a float array, checked against ``_RANGES[name]``; strings and bools refused."""
    lo, hi, _ = _RANGES[name]
    try:
        a = np.asarray(value)
    except (ValueError, OverflowError) as exc:  # ragged nesting, ints beyond int64
        raise ValueError(f"{name} must be a number or a rectangular array of numbers ({exc})") from None
    if a.dtype.kind == "O":
        try:
            a = a.astype(float)
        except (TypeError, ValueError, OverflowError):
            raise ValueError(f"{name} must be a number or an array of numbers, got {value!r:.60}") from None
    if a.dtype.kind not in "fiu":
        raise ValueError(f"{name} must be a number or an array of numbers, got {value!r:.60}")
    a = a.astype(float, copy=False)
    with np.errstate(invalid="ignore"):
        bad = ~((a >= lo) & (a <= hi))  # also catches NaN
    if bad.any():
        raise _range_error(name, float(a.reshape(-1)[int(np.argmax(bad.reshape(-1)))]))
    return a


def _scalar(name: str, value) -> float:
    """Fast path for a Python or NumPy real scalar (no array machinery)."""
    lo, hi, _ = _RANGES[name]
    try:
        x = float(value)
    except OverflowError:  # an int beyond the float range
        raise _range_error(name, math.inf) from None
    if not lo <= x <= hi:
        raise _range_error(name, x)
    return x


_REAL_SCALARS = (float, int, np.floating, np.integer)


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
    if not isinstance(params, (AirfoilParams, CamberedParams)):
        hint = " (a set's name: resolve it with propmap.resolve_params)" if isinstance(params, str) else ""
        raise TypeError(f"params must be AirfoilParams or CamberedParams (propmap.default_params, generic_params, "
                        f"read_params){hint}, got {type(params).__name__}")
    if air is not _UNCHECKED and not isinstance(air, Air):
        raise TypeError(f"air must be a propmap.Air, got {type(air).__name__}")
    if discretization is not _UNCHECKED and not isinstance(discretization, Discretization):
        raise TypeError(f"discretization must be a propmap.Discretization, got {type(discretization).__name__}")


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
    induced inflow v_i solves dT_BET = dT_BEMT (eq 11, Glauert mass flow eq 10,
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
        at Omega = 0, the induced velocities by Omega / 0.1.
    airspeed : float or array_like
        Speed V of the disk relative to the air [m/s], finite, in [0, 500].
    incidence : float or array_like
        beta [rad] in [0, pi]: the angle between the freestream seen by the disk
        and the rotor axis (0 axial climb, pi/2 edgewise, pi axial descent);
        docs/numerics.md item 1. Irrelevant when V = 0.
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
        True: also the derivatives of T, D, Q, M_R and v_i,mean with respect to ``omega``,
        ``airspeed`` and ``incidence`` (:meth:`RotorLoads.derivative`); a sequence names
        the inputs, ``"collective"`` among them (the blade-angle offset, the same for
        ``params.collective`` and ``collective``), section parameters (numeric fields of
        ``params`` other than :data:`NODE_FIELDS` and ``flap_compliance``) and ``"rho"``
        (the air density [kg/m^3]). By the implicit function theorem on each annulus'
        converged root (core/_sensitivity.py), not by differencing the
        solver; for the uniform inflow and rigid blades (the paper's rotor) and Omega >=
        0.1 rad/s. False (default): none.

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
        shapes that do not broadcast (the message names it and the range).
        With ``derivatives``: an unknown input name, a node-changing parameter
        (:data:`NODE_FIELDS`) or ``flap_compliance``, a linear inflow model or flapping
        blades, or an Omega below 0.1 rad/s.
    SolverError
        A root solve failed and ``on_failure="raise"``; the message names the point,
        the radius and the reason.
    """
    air = getattr(params, "air", None) if air is None else air  # checked below
    check_model_args(propeller, params, air, discretization)
    if on_failure not in ("raise", "flag"):
        raise ValueError(f"on_failure must be 'raise' or 'flag', got {on_failure!r}")
    if (type(omega) in _REAL_SCALARS and type(airspeed) in _REAL_SCALARS  # noqa: E721 (bool excluded)
            and type(incidence) in _REAL_SCALARS and (collective is None or type(collective) in _REAL_SCALARS)):
        shape = ()
        w0 = _scalar("omega", omega)
        any_slow = w0 < OMEGA_MIN
        v0, b0 = _scalar("airspeed", airspeed), _scalar("incidence", incidence)
        vs0, vc0 = v0 * math.sin(b0), v0 * math.cos(b0)  # Python floats: no ufunc calls on 1-element arrays
        if abs(vs0) < 1e-12 * max(v0, 1e-300):  # exact axial flow at beta = 0, pi
            vs0 = 0.0
        x = np.array([w0, v0, b0, 0.0 if collective is None else _scalar("collective", collective), vs0, vc0])
        om1, V1, b1, c1, Vs, Vc = x[0:1], x[1:2], x[2:3], x[3:4], x[4:5], x[5:6]  # one-point views
    else:
        arrays = [_as_array("omega", omega), _as_array("airspeed", airspeed), _as_array("incidence", incidence)]
        if collective is not None:
            arrays.append(_as_array("collective", collective))
        try:
            arrays = np.broadcast_arrays(*arrays)
        except ValueError as exc:
            if "broadcast" in str(exc):
                what = "omega, airspeed, incidence and collective" if collective is not None else \
                    "omega, airspeed and incidence"
                raise ValueError(f"{what} must broadcast together: {exc}") from None
            raise
        om = arrays[0]
        shape = om.shape
        om1 = np.ascontiguousarray(om.reshape(-1))
        V1 = arrays[1].reshape(-1)
        b1 = arrays[2].reshape(-1)
        c1 = (np.ascontiguousarray(arrays[3].reshape(-1), dtype=float) if collective is not None
              else np.zeros(om1.size))
        any_slow = bool((om1 < OMEGA_MIN).any())
        Vs = np.ascontiguousarray(V1 * np.sin(b1))
        Vc = np.ascontiguousarray(V1 * np.cos(b1))
        Vs[np.abs(Vs) < 1e-12 * np.maximum(V1, 1e-300)] = 0.0  # exact axial flow at beta = 0, pi

    wrt = _derivative_inputs(derivatives, params, any_slow)
    keep_radial = radial or bool(wrt)  # the derivatives need the roots
    om_in = om1
    if any_slow:  # spin-up and stopped rotors: solved at OMEGA_MIN, scaled below
        om1 = np.maximum(om1, OMEGA_MIN)
    nd, model, pk, cam, inflow, empirical, cls = _prepared(propeller, params, air, discretization)
    n, nr = om1.size, nd.y.size
    out = np.empty((_kernel.N_OUT, n))  # T, D, Q, M_R, Y, M_P, mean inflow, v_h, k, m, reverse-flow radius
    rows = n if keep_radial else 1  # unused (1, nr) scratch when the per-annulus outputs are not kept
    rad = np.empty((_kernel.N_RAD, rows, nr))  # v_i, dT, dD, dQ, dM_R, dY, dM_P
    counts = np.empty((_kernel.N_COUNTS, n), dtype=np.int64)  # status, multiple, in vortex ring, evaluations, state
    flags = np.empty((_kernel.N_FLAGS, n), dtype=np.bool_)  # converged, vortex ring, multiple, reverse, extrapolated
    # (row 1 of counts, the annuli with multiple roots, is read by point_flags; row 2, those in vortex ring, unused)
    (T, D, Q, R, Y, P, vbar, v_h, k_desc, _, rfr), (status, _, _, nev, state) = out, counts
    # a small batch runs on the calling thread: starting the parallel region would cost more
    # than the work (and a single call need not load the thread pool at all). The kernel also
    # writes the working state, v_h, the descent ratio, the reverse-flow radius and the flags
    # (_kernel.point_flags: no NumPy calls on one-point arrays here)
    batch = _kernel.solve_batch if n >= PARALLEL_MIN_POINTS else _kernel.solve_batch_serial
    batch(om1, Vs, Vc, c1, nd.y, nd.w, nd.theta, nd.sin_th, nd.cos_th, nd.sc, nd.cy2, nd.cfac, nd.mfac, nd.ct, nd.ch,
          nd.sinpsi, nd.cospsi, model, pk, cam, inflow, empirical, propeller.radius, keep_radial, cls, out, rad,
          counts, flags)
    if on_failure == "raise" and (status[0] != 0 if n == 1 else status.any()):  # .any() costs 0.8 us
        i = int(np.argmax(status != 0))
        code = int(status[i]) - 1
        j, reason = divmod(code, 4)
        why = {1: "no sign change of F found (no bracket)", 2: "the refinement of the bracket did not converge"}[reason]
        raise SolverError(
            f"inflow root solve failed at operating point {np.unravel_index(i, shape)} "
            f"(omega={om1[i]:.6g} rad/s, airspeed={V1[i]:.6g} m/s, incidence={math.degrees(b1[i]):.6g} deg) "
            f"on annulus r/R={nd.y[j] / propeller.radius:.4f}: {why}"
        )
    if params.flap_compliance > 0:
        damping = flap_damping(air.rho, _lift_slope(params), float(nd.chord_r3), om1)
        D, Y, R, P, b1c, b1s = flapping(T, D, Y, R, P, damping, params.flap_compliance, propeller.n_blades)
    else:
        b1c = b1s = np.zeros(n)
    if any_slow:
        T, D, Q, R, Y, P, vbar, b1c, b1s, rad = _spin_up_scaled(om_in, V1, T, D, Q, R, Y, P, vbar, b1c, b1s, rad,
                                                                radial)
        om1 = om_in
        # the states and flags again, for the scaled thrust and inflow and the rates asked for (a stopped
        # rotor: its whole retreating side in reverse flow, radius inf, with in-plane flow)
        out[0], out[6] = T, vbar
        _kernel.point_flags(out, counts, Vs, Vc, om1, cls, inflow != ph.INFLOW_UNIFORM, empirical, flags)
    # (working state, v_h, descent ratio and the inflow-validity flag: a linear inflow model with net
    # upflow; the empirical descent curve blended in forward flight by propmap's fade)
    converged, vring, multiple, reverse, extrapolated = flags
    if len(shape) == 1:  # the common case: no reshaping
        def s(a):
            return a
    elif shape == ():  # one point: 0-d views, by a C-level getter (half a reshape's cost; 22 fields)
        s = _ZERO_D
    else:
        def s(a):
            return a.reshape(shape)
    jac = None
    if wrt:
        jac = {k: s(a) for k, a in _jacobian(wrt, om1, V1, b1, c1, rad[0], converged, nd, model, pk, cam,
                                                 empirical, params, air, propeller, discretization,
                                                 (T, D, Q, R)).items()}
    radial_out = ([a.reshape(shape + (nr,)) for a in rad] if radial else [None] * _kernel.N_RAD)
    return _new_loads(
        omega=s(om1), airspeed=s(V1), incidence=s(b1),
        thrust=s(T), drag=s(D), torque=s(Q), rolling_moment=s(R), side_force=s(Y), pitching_moment=s(P),
        v_i_mean=s(vbar), flap_1c=s(b1c), flap_1s=s(b1s), r=nd.y,
        v_i=radial_out[0], dT_dr=radial_out[1], dD_dr=radial_out[2], dQ_dr=radial_out[3], dMR_dr=radial_out[4],
        dY_dr=radial_out[5], dMP_dr=radial_out[6],
        converged=s(converged), vortex_ring=s(vring), multiple_roots=s(multiple),
        reverse_flow=s(reverse), reverse_flow_radius=s(rfr), inflow_extrapolated=s(extrapolated),
        state=s(state), v_h=s(v_h), descent_ratio=s(k_desc),
        n_evaluations=s(nev),
        rho=air.rho, diameter=propeller.diameter, jacobian=jac,
    )


def differentiable(params: SectionParams, names) -> bool:
    """Whether :func:`rotor_loads` gives implicit derivatives of ``params``'s loads with respect
    to every name in ``names`` (what the fits ask before using them).

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
    names : sequence of str
        Inputs (:data:`DERIVATIVE_INPUTS`), ``"rho"`` or section parameters' names.

    Returns
    -------
    bool
        False for a linear inflow model or flapping blades, or a name that is not a numeric
        field entering the section's constants (:data:`NOT_CONSTANTS`, switches, text);
        the rotation rates' range is the caller's to check (>= 0.1 rad/s).
    """
    if params.inflow != "uniform" or params.flap_compliance > 0:
        return False
    own = {f.name for f in fields(params)} - set(RECORD_META)
    return all(n in DERIVATIVE_INPUTS or n == RHO
               or (n in own and n not in NOT_CONSTANTS and isinstance(getattr(params, n), float)) for n in names)


def _derivative_inputs(derivatives, params, any_slow: bool) -> tuple:
    """The inputs and section parameters ``rotor_loads(derivatives=...)`` asks for, checked
    (() for none)."""
    if derivatives is False or derivatives is None:
        return ()
    if derivatives is True:
        wrt = DERIVATIVE_INPUTS[:3]
    else:
        if isinstance(derivatives, str) or not hasattr(derivatives, "__iter__"):
            raise ValueError(f"derivatives must be True, False or a sequence of input or parameter names "
                             f"({', '.join(DERIVATIVE_INPUTS)}, or a field of the parameter set), "
                             f"got {derivatives!r:.60}")
        wrt = tuple(dict.fromkeys(derivatives))
        own = ({f.name for f in fields(params)} - set(RECORD_META)) | {RHO, STILL_AIR}
        bad = [w for w in wrt if w not in DERIVATIVE_INPUTS and w not in own]
        if bad:
            raise ValueError(f"derivatives: unknown input or parameter {bad[0]!r:.60}; valid: "
                             f"{', '.join(DERIVATIVE_INPUTS)} or a field of {type(params).__name__}")
    if params.inflow != "uniform" or params.flap_compliance > 0:
        raise ValueError("derivatives are implemented for the uniform inflow and rigid blades (the paper's rotor); "
                         f"this set has inflow={params.inflow!r}, flap_compliance={params.flap_compliance:g}")
    if any_slow:
        raise ValueError(f"derivatives need omega >= {OMEGA_MIN:g} rad/s (below it the blades are parked)")
    return wrt


#: the parameter set's fields that _nodes reads (the blade angle, the Reynolds reference, the Blasius
#: factor, the loss switches): not differentiable as section constants (tests/test_derivatives.py checks
#: that every other numeric field leaves the nodes unchanged)
NODE_FIELDS = ("collective", "re_ref", "cp_blasius", "tip_loss", "hub_loss")
#: fields that enter neither the element's nor the annulus' constants: refused as derivatives
NOT_CONSTANTS = (*NODE_FIELDS, "flap_compliance")
#: a section parameter's step is _sensitivity.ONE_SIDED of max(|value|, PARAM_FLOOR)
PARAM_FLOOR = 0.01


def _parameter_constants(names, params, air):
    """(pk, cam, step) of each section parameter in ``names``: the element and annulus
    constants at the parameter's value + its step (- its step where + leaves the parameter's
    range), and that step (either sign), for the kernel's one-sided differences.

    Raises
    ------
    ValueError
        A parameter that is not a number, one that changes the blade's nodes (the
        Reynolds reference, the Blasius factor, the loss switches; ``collective`` is the
        input of that name) rather than the section's constants, ``flap_compliance``
        (flapping is not differentiated), or one that admits no step within its range.
    """
    from ._sensitivity import ONE_SIDED

    n = len(names)
    pks = np.empty((n, ph.N_PK))
    cams = np.empty((n, 8))
    step = np.empty(n)
    for k, name in enumerate(names):
        if name == "flap_compliance":  # enters neither pk nor cam: its difference would say 0
            raise ValueError("derivatives with respect to flap_compliance are not supported: flapping is not "
                             "differentiated")
        if name in NOT_CONSTANTS:
            raise ValueError(f"derivatives with respect to {name} are not supported: it changes the blade's nodes, "
                             "not the section's constants (for the blade angle, use 'collective')")
        x = getattr(params, name)
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            raise ValueError(f"derivatives: {name} is not a number of the parameter set ({x!r:.40})")
        h = ONE_SIDED * max(abs(float(x)), PARAM_FLOOR)
        for dx in (h, -h):
            try:
                stepped = params.replace(**{name: float(x) + dx})
            except ValueError:  # beyond the parameter's range: the other side
                continue
            break
        else:
            raise ValueError(f"derivatives: {name} = {x!r} admits no step within its range")
        pks[k] = _model_constants(stepped)[1]
        cams[k] = _cambered_args(stepped, air)
        step[k] = (float(x) + dx) - float(x)  # the step as represented
    return pks, cams, step


def _jacobian(wrt, om, V, b, coll, v, converged, nd, model, pk, cam, empirical, params, air, propeller,
              discretization, loads) -> dict:
    """{(load, input or parameter): derivative} at every point (flat arrays), from the kernel
    (core/_sensitivity.py)."""
    from . import _sensitivity

    if STILL_AIR in wrt:
        others = tuple(w for w in wrt if w != STILL_AIR)
        out = _jacobian(others, om, V, b, coll, v, converged, nd, model, pk, cam, empirical, params, air, propeller,
                        discretization, loads) if others else {}
        return out | _still_air_jacobian(om, V, coll, v, converged, nd, model, pk, cam, empirical, params, air,
                                         propeller, discretization, loads)
    inputs = [w for w in wrt if w in DERIVATIVE_INPUTS]
    names = [w for w in wrt if w not in DERIVATIVE_INPUTS and w != RHO]
    scp = nd.sc
    hrho = 0.0
    if RHO in wrt:  # the section constant sc holds the Reynolds number's density (rho c / mu)
        rho_step = air.rho + _sensitivity.ONE_SIDED * air.rho
        hrho = rho_step - air.rho  # the step as represented
        scp = _nodes(propeller, discretization.n_radial, discretization.n_azimuth, dc_replace(air, rho=rho_step),
                     params).sc
    n_in = 4 if "collective" in inputs else (3 if inputs else 0)  # the kernel's inputs come in this order
    pks, cams, step = _parameter_constants(names, params, air)
    raw = np.empty((len(DERIVATIVE_LOADS), n_in + len(names) + (RHO in wrt), om.size))
    om, V, b, coll = (np.ascontiguousarray(a, dtype=float) for a in (om, V, b, coll))  # no broadcast views
    _sensitivity.sensitivities(om, V, b, coll, v, converged, nd.y, nd.w, nd.theta, nd.sc, nd.cy2, nd.cfac, nd.mfac,
                               nd.ct, nd.ch, nd.sinpsi, model, pk, cam, empirical, n_in, pks, cams,
                               np.all(cams == cam, axis=1), step, np.ascontiguousarray(scp, dtype=float), hrho, raw)
    col = {w: DERIVATIVE_INPUTS.index(w) for w in inputs} | {w: n_in + k for k, w in enumerate(names)}
    if RHO in wrt:
        col[RHO] = n_in + len(names)
        for q, a in enumerate(loads):  # cfac and mfac scale with rho: L / rho at the same root
            raw[q, col[RHO]] += a / air.rho
    return {(load, w): raw[q, col[w]] for q, load in enumerate(DERIVATIVE_LOADS) for w in wrt}


def _still_air_jacobian(om, V, coll, v, converged, nd, model, pk, cam, empirical, params, air, propeller,
                        discretization, loads) -> dict:
    """{(load, STILL_AIR): slope}: at the points with V = 0 the loads' slopes in the velocity, from the
    kernel's one-sided airspeed derivatives along three rays at the same roots (at rest the root does
    not depend on the incidence): edgewise (beta = pi/2) for D and M_R, odd in V sin(beta), so that
    this one-sided slope is the derivative; for T, Q and v_i,mean the mean of the climb (beta = 0) and
    descent (beta = pi) slopes, the limit of central differences (core/vector.still_air_slopes). 0 at
    the points with V > 0."""
    rest = np.flatnonzero(V == 0.0)
    k = rest.size
    slopes = np.zeros((len(DERIVATIVE_LOADS), om.size))
    if k:
        idx = np.tile(rest, 3)
        rays = np.repeat([0.0, 0.5 * np.pi, np.pi], k)  # climb, edgewise, descent
        d = _jacobian(("airspeed",), om[idx], np.zeros(3 * k), rays, coll[idx], v[idx], converged[idx], nd, model,
                      pk, cam, empirical, params, air, propeller, discretization, tuple(a[idx] for a in loads))
        for q, load in enumerate(DERIVATIVE_LOADS):
            a = d[(load, "airspeed")].reshape(3, k)
            slopes[q, rest] = a[1] if load in _ODD_LOADS else 0.5 * (a[0] - a[2])  # dV_c = -dV along beta = pi
    return {(load, STILL_AIR): slopes[q] for q, load in enumerate(DERIVATIVE_LOADS)}
