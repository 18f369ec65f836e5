"""What a fit frees, within which bounds and how: parameter names, ranges, scales and
:class:`FitOptions` (docs/identification.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from ..core._numbers import SEED_MAX, integer
from ..core.airfoil import LIFT_MODELS, AirfoilParams, CamberedParams, SectionParams
from ..core.solver import DEFAULT_DISCRETIZATION, Discretization

__all__ = ["FitOptions", "param_names", "X0_PAPER", "BOUNDS", "CAMBERED_BOUNDS", "CAMBERED_SCALE", "CAMBERED_FIT",
           "CAMBERED_FIT_RE", "CAMBERED_FIT_STATIC", "CAMBERED_FIT_COLLECTIVE", "MIN_RATES_FOR_RE",
           "RATE_STEP", "STATIC_RPM_SPAN", "BODY_BOUNDS", "ROTOR_BOUNDS", "AIRFRAME_BOUNDS", "ANGLES", "INPLANE_FIT",
           "FLAP_START", "FLAP_ARTICULATED", "ABSENT_AT_ZERO"]


#: the paper's initial guess (c_l1, c_l2, c_d, alpha_0) = (2 pi, 2, 0, 0.47)
X0_PAPER = (2 * math.pi, 2.0, 0.0, 0.47)
#: default bounds for (cl1, cl2, cd, alpha0 [rad]); wide but physical
BOUNDS = {"cl1": (0.5, 15.0), "cl2": (0.0, 6.0), "cd": (0.0, 10.0), "alpha0": (math.radians(3), math.radians(60))}
#: default bounds of the cambered polar's parameters (SI, angles in rad): the range of
#: low-Reynolds-number propeller sections, wide enough that the catalogue fits end inside
CAMBERED_BOUNDS = {
    "cl_alpha": (2.0, 9.0), "alpha_L0": (math.radians(-15), math.radians(5)), "cl_max": (0.4, 2.5),
    "cl_min": (-1.5, -0.05), "cd_min": (0.002, 0.2), "cd2": (0.0, 2.0), "cl_cdmin": (-0.5, 1.5),
    "cd90": (0.5, 3.0), "re_exp": (-1.5, 0.5), "re_exp_lift": (-0.3, 0.8), "re_exp_stall": (-0.5, 1.0),
    "stall_delay": (0.0, 15.0), "alpha_L0_re": (math.radians(-4), math.radians(4)), "M": (5.0, 100.0),
}
#: natural size of each cambered parameter: a standard error above POOR_REL_STD of
#: max(|estimate|, this) is "poorly determined" (parameters whose value may be ~0)
CAMBERED_SCALE = {"alpha_L0": math.radians(2), "cl_cdmin": 0.3, "re_exp": 0.3, "re_exp_lift": 0.1,
                  "re_exp_stall": 0.1, "stall_delay": 1.0, "alpha_L0_re": math.radians(1), "cd2": 0.05}
#: cambered parameters fitted by default from data with advance-ratio sweeps / static only /
#: sweeps at several Reynolds numbers (docs/identification.md has the measured choice)
CAMBERED_FIT = ("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2")
CAMBERED_FIT_RE = CAMBERED_FIT + ("re_exp_lift", "re_exp", "alpha_L0_re")
#: static-only data without the prior: two parameters (a static run has two or three degrees
#: of freedom; fitted freely, more parameters chase them)
CAMBERED_FIT_STATIC = ("alpha_L0", "cd_min")
#: a hover collective sweep (static points at several collectives) spans the angles of
#: attack: the lift slope, the stall and the drag polar are identified too (with the Reynolds
#: terms where its points span STATIC_RPM_SPAN in rpm, as a static run's). Until 2026-11-28
#: without cl_max: a sweep into the stall of a set whose cl_max differed from the base's put
#: cl_alpha at its bound (9 against 5.5) with 14 times the noise left, and sweeps from two
#: catalogue sets (apce_10x7, magf_10x8) came out 7-14 standard errors off with loads 1-3% off
#: and no warning (a user-level audit; the eight freed recovered them within their intervals)
CAMBERED_FIT_COLLECTIVE = ("cl_alpha", "alpha_L0", "cl_max", "cd_min", "cd2")
#: freed besides the section's parameters (cambered model, default names) when the data measure the
#: in-plane force D at incidence: the blades' flapping tilts the thrust and carries the in-plane
#: force that a rigid rotor under-predicts, instead of a section drag distorted to chase it.
#: Leave one incidence out on the four propellers of Gill & D'Andrea's oblique-flow fits
#: (Drones 2019; docs/identification.md): held-out D 1.9-4.4% -> 0.5-0.8% of static thrust, T 5.4-8.4% ->
#: 3.7-5.6%, Q 18-27% -> 4.3-11% of static torque
INPLANE_FIT = ("flap_compliance",)
#: the compliance such a fit starts from when the base's blades are rigid [rad/(N m)]: at 0 the
#: thrust, drag, torque and rolling moment are quadratic in it (their derivative is 0; the side
#: force and pitching moment are linear) and the flapping responds near 1 / D_beta, 0.3-4 rad/(N m)
#: for 8-10 in propellers at 4000-8000 rpm (the flight fit starts there too)
FLAP_START = 1.0
#: a fitted equivalent compliance above this [rad/(N m)] is a nearly articulated blade's, not a propeller's: warned
#: of (a stiff plastic blade's is about 0.1 by a beam estimate, and a cantilevered blade's centrifugal stiffening
#: caps the equivalent compliance near 1 at 8000 rpm; docs/validation.md). Gill & D'Andrea's oblique-flow fits
#: give 25-50 (APC 8x6E), 4.3-6.1 (8x8E), 1.7-3.1 (10x7E), 0.7-1.3 (10x4.7SF; docs/identification.md)
FLAP_ARTICULATED = 5.0
#: sweeps at this many distinct rotation rates (or more) let the fit estimate the
#: Reynolds terms (CAMBERED_FIT_RE); fewer keep them at the base values
MIN_RATES_FOR_RE = 3
#: a run's rotation rate counts as another one more than this factor above the last one counted (fit._sweep_rates)
RATE_STEP = 1.03
#: ... as does a static run over this ratio of rotation rates (a UIUC static run spans 2-8x):
#: with the static run and the lowest sweep, leave-one-family-out on both UIUC volumes
#: (docs/identification.md) gave a held-out median of 3.9% (vol. 1) and 5.0% (vol. 2) with the
#: Reynolds terms fitted, 3.5% and 7.7% with them held at the generic set's
STATIC_RPM_SPAN = 1.5
BODY_BOUNDS = {"cl1_body": (0.0, 10.0), "cl2_body": (0.0, 5.0), "alpha0_body": (math.radians(3), math.radians(60))}
BODY_X0 = (0.0, 0.0, 0.47)
#: bounds of the rotor options (RotorOptions) and of the airframe drag (core/body.py) when fitted
ROTOR_BOUNDS = {"collective": (math.radians(-15), math.radians(15)), "flap_compliance": (0.0, 50.0)}
AIRFRAME_BOUNDS = {"drag_area_x": (0.0, 0.05), "drag_area_y": (0.0, 0.05), "drag_area_z": (0.0, 0.05),
                   "wash_factor": (0.0, 3.0), "cg_x": (-0.05, 0.05), "cg_y": (-0.05, 0.05),
                   "rotor_interference": (0.0, 3.0)}
#: every fitted name's default bounds (a fit's table, FitOptions.bounds on top)
ALL_BOUNDS = {**BOUNDS, **CAMBERED_BOUNDS, **BODY_BOUNDS, **ROTOR_BOUNDS, **AIRFRAME_BOUNDS}
#: parameters whose value 0 is the effect's absence (no flapping, no airframe drag, no slipstream on it, no
#: interference, no body lift, no rotational stall delay): a fit that ends at that lower bound found none, which is
#: not suspect
ABSENT_AT_ZERO = ("flap_compliance", "drag_area_x", "drag_area_y", "drag_area_z", "wash_factor", "rotor_interference",
                  "cl1_body", "cl2_body", "stall_delay")
#: parameters that are angles [rad], reported in degrees
ANGLES = ("alpha0", "alpha0_body", "alpha_L0", "alpha_L0_re", "collective")


def param_names(lift_model: str) -> tuple[str, ...]:
    """Fitted parameters of the paper's model: all four of eqs 3-4, (cl2, cd) for footnote 1's sin-cos lift.

    Parameters
    ----------
    lift_model : {"sigmoid", "sincos"}
        The paper's lift model (``AirfoilParams.lift_model``).

    Returns
    -------
    tuple of str
        ``("cl1", "cl2", "cd", "alpha0")`` for ``"sigmoid"``, ``("cl2", "cd")`` for ``"sincos"``.

    Raises
    ------
    ValueError
        Another ``lift_model``.
    """
    if lift_model not in LIFT_MODELS:
        raise ValueError(f"lift_model must be 'sigmoid' or 'sincos', got {lift_model!r:.40}")
    return ("cl1", "cl2", "cd", "alpha0") if lift_model == "sigmoid" else ("cl2", "cd")


def _default_names(base: SectionParams, options: "FitOptions", data_kind: str = "rates") -> tuple[str, ...]:
    """The parameters fitted: ``options.names`` (checked), else the default for
    ``data_kind`` "static", "collective" (a static collective sweep; "collective_rates" at rates
    spanning STATIC_RPM_SPAN), "few_rates" or "rates"."""
    _check_lift_model(base, options)
    if options.names is not None:
        return _check_names(options.names, base, options)
    if isinstance(base, CamberedParams):
        if data_kind == "collective":
            return CAMBERED_FIT_COLLECTIVE
        if data_kind == "collective_rates":
            return CAMBERED_FIT_RE
        if data_kind == "static" and not options.prior:
            return CAMBERED_FIT_STATIC
        return CAMBERED_FIT if data_kind == "few_rates" else CAMBERED_FIT_RE
    return param_names(options.lift_model)


def _check_lift_model(base: SectionParams, options: "FitOptions") -> None:
    """Refuse the options of the other section model than the base's, which were ignored without
    a word: ``lift_model`` "sincos", an ``x0`` (the paper's start) or bounds on the paper's names
    with a cambered base; bounds on the cambered set's names with the paper's (an API audit,
    stop 100, for all but the first)."""
    cambered = isinstance(base, CamberedParams)
    if cambered and options.lift_model != "sigmoid":
        raise ValueError(f"lift_model={options.lift_model!r} applies to the paper's model (AirfoilParams), not the "
                         "cambered set given as the base")
    if cambered and tuple(options.x0) != X0_PAPER:
        raise ValueError("x0 is the start of the paper's model (cl1, cl2, cd, alpha0); a fit of the cambered set "
                         "starts from the base set: give its values in base (base.replace(...))")
    # (the other model's own names: a field both models have, such as M or the rotor options, is no other's)
    other = (set(BOUNDS) - set(CAMBERED_BOUNDS) if cambered
             else set(_NUMBER_FIELDS) - {f.name for f in fields(AirfoilParams)} - set(ROTOR_BOUNDS))
    unused = sorted(set(options.bounds or {}) & other)
    if unused:
        model = "the cambered set" if cambered else "the paper's model"
        raise ValueError(f"bounds on {', '.join(unused)}: not parameters of {model} given as the base (they would "
                         "be ignored)")


def refuse_unused_options(options: "FitOptions", fit: str, *, body_lift: bool = False,
                          directions: bool = False) -> None:
    """Refuse ``options.body_lift`` and ``options.directions`` in a fit that does not use them,
    each ignored without a word until stop 100 (an API audit).

    Parameters
    ----------
    options : FitOptions
    fit : str
        The fit's name, for the message (``"fit_loads"``).
    body_lift, directions : bool
        True where ``fit`` uses that option.

    Raises
    ------
    ValueError
        Naming the option, ``fit`` and the fit that takes it.
    """
    if options.body_lift and not body_lift:
        raise ValueError(f"body_lift applies to fit_level_flight (the airframe's lift in level flight), not {fit}")
    if options.directions is not None and not directions:
        raise ValueError(f"directions applies to fit_loads (the prior's directions for static runs and sweeps), "
                         f"not {fit}")


def _check_bounds(bounds) -> None:
    """Refuse a ``FitOptions.bounds`` that is not name -> (low, high) with finite low < high and
    a known name (a typo was ignored; inverted, equal or NaN bounds failed in SciPy without the
    name; a 3-tuple was cut to its first two values)."""
    known = ALL_BOUNDS
    if not isinstance(bounds, dict):
        raise ValueError(f"bounds must be a dict of name -> (low, high), got {type(bounds).__name__}")
    for name, b in bounds.items():
        if not isinstance(name, str):
            raise ValueError(f"bounds: a name must be a string, got {name!r:.40}")
        try:
            lo, hi = (float(v) for v in b)
        except (TypeError, ValueError):
            raise ValueError(f"bounds[{name!r}] must be two numbers (low, high), got {b!r:.60}") from None
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ValueError(f"bounds[{name!r}] must be finite with low < high, got ({lo!r}, {hi!r})")
        if name not in known and name not in _NUMBER_FIELDS:
            raise ValueError(f"bounds: unknown parameter {name!r}; fitted parameters are "
                             f"{', '.join(sorted(known))} (and the cambered set's other numbers: "
                             f"{', '.join(sorted(set(_NUMBER_FIELDS) - set(known)))})")


#: the cambered set's fields that are numbers (a fit can free them given bounds): its label, air, inflow model and
#: switches were taken as names too and failed inside the fit ("could not convert string to float: 'generic'";
#: a switch fitted as 0.9999999999: an API audit, stop 100)
_NUMBER_FIELDS = tuple(f.name for f in fields(CamberedParams) if f.type in ("float", float))


def check_population(population) -> None:
    """Refuse a prior's statistics (``FitOptions.population``) that the fit could not use: not a
    dict of ``names`` (str, each once), ``covariance`` (finite, symmetric, positive definite, one
    row per name), ``sigma_data`` (a finite number > 0) and ``source`` (text). Each was met
    inside the fit as a KeyError, SciPy's "not finite", a LinAlgError or an IndexError, and a
    negative sigma_data was taken (an API audit, stop 100).

    Parameters
    ----------
    population : dict
        As :func:`propmap.io.calibration.population` returns it: ``names`` (list or tuple of
        str, k of them), ``covariance`` (k x k, SI, angles in rad), ``sigma_data`` [-],
        ``source`` (text).

    Raises
    ------
    ValueError
        Naming the key and what it must be.
    """
    need = ("names", "covariance", "sigma_data", "source")  # (an empty dict was the shipped prior without a word)
    if not (isinstance(population, dict) and all(k in population for k in need)):
        raise ValueError(f"population must be None or a dict with {', '.join(need)} (io.calibration.population), "
                         f"got {population!r:.60}")
    names = population["names"]
    if isinstance(names, str) or not isinstance(names, (list, tuple)) or not all(isinstance(n, str) for n in names) \
            or len(set(names)) != len(names) or not names:
        raise ValueError(f"population['names'] must be parameter names (str), each once, got {names!r:.60}")
    try:
        cov = np.asarray(population["covariance"], float)
    except (TypeError, ValueError):
        raise ValueError("population['covariance'] must be a square array of numbers") from None
    k = len(names)
    if cov.shape != (k, k) or not np.all(np.isfinite(cov)) or not np.allclose(cov, cov.T, rtol=1e-9, atol=0.0):
        raise ValueError(f"population['covariance'] must be finite and symmetric, shape ({k}, {k}) for its {k} names, "
                         f"got shape {cov.shape}")
    try:
        np.linalg.cholesky(cov)
    except np.linalg.LinAlgError:
        raise ValueError("population['covariance'] must be positive definite (a variance <= 0, or rows that depend "
                         "on each other)") from None
    sigma = population["sigma_data"]
    if isinstance(sigma, bool) or not isinstance(sigma, (int, float, np.integer, np.floating)) \
            or not (math.isfinite(sigma) and sigma > 0):
        raise ValueError(f"population['sigma_data'] must be a finite number > 0, got {sigma!r:.40}")
    if not isinstance(population["source"], str):
        raise ValueError(f"population['source'] must be text, got {population['source']!r:.40}")


def _check_names(names, base: SectionParams, options: "FitOptions", extra=()) -> tuple[str, ...]:
    """``names`` as a tuple, refused unless each is a parameter of the base's model (the
    paper's: cl1, cl2, cd, alpha0; the cambered: CAMBERED_BOUNDS and any field given
    bounds in ``options.bounds``), a rotor option (ROTOR_BOUNDS) or one of ``extra`` (the
    kind of fit's own terms, e.g. the airframe's in a flight fit), given once.

    Raises
    ------
    ValueError
        Not a sequence of str, empty, a name given twice, a name the model does not
        have (a paper-model name with a cambered base, ``alpha0``, included), or ``M``
        fitted while ``options.M`` fixes it.
    """
    if isinstance(names, str) or not isinstance(names, (tuple, list)) or not all(isinstance(n, str) for n in names):
        raise ValueError(f"names must be a tuple of parameter names (str), got {names!r:.60}")
    if not names:
        raise ValueError("names is empty: give the parameters to fit, or None for the default")
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise ValueError(f"cannot fit {', '.join(twice)} twice: give each parameter once")
    if isinstance(base, CamberedParams):
        valid = (*CAMBERED_BOUNDS,
                 *(k for k in (options.bounds or {}) if k in _NUMBER_FIELDS and k not in CAMBERED_BOUNDS))
        model = "the cambered model"
    else:  # all four under either lift model (with sin-cos lift the report says cl1 and alpha0 do not enter)
        valid, model = tuple(BOUNDS), "the paper's model"
    valid = (*valid, *ROTOR_BOUNDS, *extra)
    unknown = [n for n in names if n not in valid]
    if unknown:
        hint = " (body-lift terms: body_lift=True, --body-lift)" if any(n in BODY_BOUNDS for n in unknown) else ""
        raise ValueError(f"cannot fit {', '.join(unknown)[:120]} with {model}: its parameters are "
                         f"{', '.join(valid)}{hint}")
    if options.M is not None and "M" in names:
        raise ValueError(f"M is fixed at {options.M:g} by the fit's options (--M) and cannot also be fitted: "
                         "drop one")
    return tuple(names)


def _is_angle(name: str) -> bool:
    return name in ANGLES


def report_name(name: str) -> str:
    """A fitted parameter's name in a report (JSON keys, text): an angle's with its unit, as in
    a parameter file (``alpha_L0`` -> ``alpha_L0_deg``), the others' as fitted (SI)."""
    return f"{name}_deg" if _is_angle(name) else name


def report_value(name: str, value) -> float | None:
    """``value`` of the fitted parameter ``name`` (SI: angles in rad) in the report's unit
    (:func:`report_name`: degrees for an angle); None where it is not finite (JSON null)."""
    v = float(value)
    if not math.isfinite(v):
        return None
    return math.degrees(v) if _is_angle(name) else v


@dataclass(frozen=True)
class FitOptions:
    """Options of a fit.

    Parameters
    ----------
    x0 : tuple
        Paper's model: start (cl1, cl2, cd, alpha0 [rad]); the paper's (2 pi, 2, 0, 0.47)
        by default. For ``lift_model="sincos"`` only cl2 and cd are used. The cambered
        model starts from the base parameters instead.
    bounds : dict, optional
        name -> (low, high); defaults :data:`BOUNDS` / :data:`CAMBERED_BOUNDS`.
    M : float, optional
        Sigmoid sharpness used while fitting (None: that of the base parameters). Paper's
        model, None: when the base M exceeds M_SMOOTH (30), the fit runs at M = 30 first
        (no root-branch jumps, a smooth objective) and then continues at the base M from
        that optimum (continuation in M).
    names : tuple of str, optional
        Parameters to fit. Default: :func:`param_names` for the paper's model; for the
        cambered model :data:`CAMBERED_FIT_RE` when the data are static only or contain
        sweeps at three or more rotation rates, else :data:`CAMBERED_FIT` (Reynolds terms
        kept at the base values), and :data:`CAMBERED_FIT_STATIC` for static data without
        the prior (docs/identification.md gives the measurements behind this rule);
        :func:`~propmap.identify.fit_loads` adds :data:`INPLANE_FIT` where the data measure
        the in-plane force at incidence.
    prior : bool
        Cambered model: add the population prior, pseudo-residuals
        sigma_d L^-1 (x - x_base) with L L^T the covariance of the parameters fitted to
        each catalogue propeller and sigma_d their median rms residual
        (io.calibration.population). The fit then moves a parameter away from the base
        only as far as the data warrant (a maximum a posteriori estimate; along the data's
        leading directions only, ``directions``); on sparse data (a static run) this
        measured better than a free fit (docs/identification.md).
    population : dict, optional
        The prior's statistics (``names``, ``covariance``, ``sigma_data``, ``source``);
        default the shipped ones (io.calibration.population). Validation passes the
        statistics of the catalogue without the family of the propeller it predicts.
    lift_model : {"sigmoid", "sincos"}
    multistart : int
        Extra starts from a scrambled Sobol sequence inside the bounds (0: x0 only). With
        starts, every start gets a short screening run (optimizer.SCREEN_NFEV evaluations) and the
        two best are polished to convergence.
    body_lift : bool
        Level flight only: append the body-lift term of Sec. III-A (needs the vehicle's
        ``body_area``). The model without body lift is fitted first and the full fit
        starts from its optimum with zero body lift, so the residual can only shrink.
    max_nfev : int
        Residual evaluations allowed per start, in [1, 10000000].
    seed : int
        Seed of the multistart's starts, in [0, 2**63 - 1].
    progress : bool
        Show a tqdm progress bar (on a terminal).
    discretization : Discretization
    directions : int, optional
        :func:`fit_loads` only. Cambered model under the prior, ``names`` not given, data
        other than a collective sweep: fit only this many of the
        parameter directions the data determine best against the prior
        (identify/directions.py), the others held at the base values; 0: every name under
        the prior. None (default): 3 (STATIC_DIRECTIONS) for a static run, those the data
        know DATA_OVER_PRIOR (10) times better than the prior for sweeps at one rotation
        rate, 0 for sweeps at two or more (the measurements: docs/identification.md).
    jacobian : {"implicit", "differences"}
        The residual Jacobian: ``"implicit"`` (default) the model's implicit derivatives
        (``rotor_loads``, ``rotor_wrench`` and ``vehicle_wrench`` with ``derivatives``;
        docs/solver.md) where it can give them for every section name (the uniform inflow
        or a linear inflow, with or without swirl, rigid or flapping blades, no
        node-changing name such as re_ref; the flight
        fit's centre of mass through ``vehicle_wrench``'s "centre_of_mass" Jacobian), the
        body-lift closed form by central differences; else, and always with ``"differences"``,
        central differences of the solver.
    profile_likelihood : bool
        :func:`fit_loads` with the flap compliance fitted: where its linearised 95% interval
        is too narrow (the flapping saturates), place its upper limit by the profile
        likelihood, 1-7 refits of the other parameters (default True). False keeps the
        linearised interval: for callers that use the fitted parameters only (the held-out
        fits of :func:`propmap.validation.holdout_loads`, which it made 2.7 times slower).

    Raises
    ------
    ValueError
        A ``lift_model``, ``jacobian`` or ``directions`` outside the values above, a
        ``profile_likelihood`` not a bool; ``max_nfev`` not an integer in [1, 1e7],
        ``multistart`` not one in [0, 256], ``seed`` not one >= 0; ``bounds`` not name ->
        (low, high) with finite low < high and a name the fits know (a fitted parameter, or
        a number of the cambered set: not its label, air, inflow model or switches); ``x0``
        not four finite numbers; a ``population`` the prior cannot use
        (:func:`check_population`).
    """

    x0: tuple = X0_PAPER
    bounds: dict | None = None
    M: float | None = None
    names: tuple | None = None
    prior: bool = True
    population: dict | None = None
    lift_model: str = "sigmoid"
    multistart: int = 0
    body_lift: bool = False
    max_nfev: int = 200
    seed: int = 0
    progress: bool = False
    discretization: Discretization = DEFAULT_DISCRETIZATION
    jacobian: str = "implicit"
    directions: int | None = None
    profile_likelihood: bool = True

    def __post_init__(self) -> None:
        if self.lift_model not in LIFT_MODELS:
            raise ValueError(f"lift_model must be 'sigmoid' or 'sincos', got {self.lift_model!r:.40}")
        if self.jacobian not in ("implicit", "differences"):
            raise ValueError(f"jacobian must be 'implicit' or 'differences', got {self.jacobian!r:.40}")
        if not isinstance(self.profile_likelihood, (bool, np.bool_)):
            raise ValueError(f"profile_likelihood must be True or False, got {self.profile_likelihood!r:.40}")
        d = self.directions
        if d is not None and (isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 0):
            raise ValueError(f"directions must be None or an integer >= 0, got {d!r:.40}")
        # (max_nfev=2.5 ran SciPy's least_squares without end; multistart=-1 counted as 0, 1.5 failed inside)
        for name, lo, hi in (("max_nfev", 1, 10**7), ("multistart", 0, 256), ("seed", 0, SEED_MAX)):
            # (stored as the int: a 0-d array passed the check and then failed in NumPy's seeding or in hash())
            object.__setattr__(self, name, integer(name, getattr(self, name), lo, hi, whole_float=False))
        if self.bounds is not None:
            _check_bounds(self.bounds)
        if self.population is not None:
            check_population(self.population)
        try:
            x0 = tuple(float(v) for v in self.x0)
        except (TypeError, ValueError):
            x0 = ()
        if len(x0) != 4 or not all(math.isfinite(v) for v in x0):
            raise ValueError(f"x0 must be 4 finite numbers (cl1, cl2, cd, alpha0 [rad]), got {self.x0!r:.60}")
