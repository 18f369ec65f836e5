"""Parameter identification, Gill & D'Andrea (2017) Section III, with the robustness the
paper lacked (NUMERICS.md, "Fitting"): bounds, an optional smoother stall blend (M),
a multistart stage and an identifiability report.

* Level flight (eqs 16-18): residual_j = vertical component of the summed rotor forces
  (+ optional body lift, Sec. III-A) - m g, per steady condition j.
* Loads: residuals (model - measured) / RMS(measured) for each measured quantity.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np
from scipy import optimize, stats
from scipy.stats import qmc

from ..core.airfoil import Air, AirfoilParams, sigmoid_blend
from ..core.hover import HoverModel
from ..core.solver import DEFAULT_DISCRETIZATION, Discretization, rotor_loads
from ..core.vector import rotor_wrench
from .data import LevelFlightData, LoadData, body_to_world, rotor_kinematics
from .vehicle import Vehicle

__all__ = ["FitOptions", "FitResult", "Identifiability", "X0_PAPER", "fit_level_flight", "fit_loads",
           "level_flight_forces", "param_names"]

#: the paper's initial guess (c_l1, c_l2, c_d, alpha_0) = (2 pi, 2, 0, 0.47)
X0_PAPER = (2 * math.pi, 2.0, 0.0, 0.47)
#: default bounds for (cl1, cl2, cd, alpha0 [rad]); wide but physical
BOUNDS = {"cl1": (0.5, 15.0), "cl2": (0.0, 6.0), "cd": (0.0, 10.0), "alpha0": (math.radians(3), math.radians(60))}
BODY_BOUNDS = {"cl1_body": (0.0, 10.0), "cl2_body": (0.0, 5.0), "alpha0_body": (math.radians(3), math.radians(60))}
BODY_X0 = (0.0, 0.0, 0.47)
POOR_REL_STD = 0.10  # relative std error above which a parameter is reported poorly determined
SCREEN_NFEV = 12  # residual evaluations per start in the multistart screening stage


def param_names(lift_model: str) -> tuple[str, ...]:
    """Fitted airfoil parameters: all four for eq 3, (cl2, cd) for footnote 1's sin-cos lift."""
    return ("cl1", "cl2", "cd", "alpha0") if lift_model == "sigmoid" else ("cl2", "cd")


@dataclass(frozen=True)
class FitOptions:
    """Options of a fit.

    Parameters
    ----------
    x0 : tuple
        Start (cl1, cl2, cd, alpha0 [rad]); the paper's (2 pi, 2, 0, 0.47) by default.
        For ``lift_model="sincos"`` only cl2 and cd are used.
    bounds : dict, optional
        name -> (low, high); defaults :data:`BOUNDS`.
    M : float, optional
        Sigmoid sharpness used while fitting (None: that of the base parameters, 50 by
        default). M = 30 removes the root-branch jumps that make the objective
        discontinuous at M = 50 (NUMERICS.md).
    lift_model : {"sigmoid", "sincos"}
    multistart : int
        Extra starts from a scrambled Sobol sequence inside the bounds (0: x0 only). With
        starts, every start gets a short screening run (SCREEN_NFEV evaluations) and the
        two best are polished to convergence.
    body_lift : bool
        Level flight only: append the body-lift term of Sec. III-A (needs the vehicle's
        ``body_area``). The model without body lift is fitted first and the full fit
        starts from its optimum with zero body lift, so the residual can only shrink.
    max_nfev : int
        Residual evaluations allowed per start.
    seed : int
    progress : bool
        Show a tqdm progress bar (on a terminal).
    discretization : Discretization
    """

    x0: tuple = X0_PAPER
    bounds: dict | None = None
    M: float | None = None
    lift_model: str = "sigmoid"
    multistart: int = 0
    body_lift: bool = False
    max_nfev: int = 200
    seed: int = 0
    progress: bool = False
    discretization: Discretization = DEFAULT_DISCRETIZATION


@dataclass(frozen=True)
class Identifiability:
    """Local identifiability at the optimum, from the residual Jacobian J.

    J is a central-difference Jacobian at the optimum. Covariance s^2 (J^T J)^-1 (from the
    SVD of J, no cut-off) with s^2 = |r|^2 / (N - p); 95% intervals use Student's t with
    N - p degrees of freedom. A parameter is "poorly determined" when its std error
    exceeds POOR_REL_STD (10%) of its estimate, i.e. its 95% interval is wider than about
    +-20%. ``singular_values`` are those of J diag(max(|x|, 0.1)),
    i.e. of the Jacobian with respect to relative parameter changes.
    """

    names: tuple[str, ...]
    std_error: np.ndarray
    ci95: np.ndarray
    correlation: np.ndarray
    singular_values: np.ndarray
    poorly_determined: tuple[str, ...]
    warnings: tuple[str, ...]

    def to_dict(self) -> dict:
        """JSON-ready form (alpha0 entries in rad)."""
        return {
            "std_error": dict(zip(self.names, map(float, self.std_error))),
            "ci95": {n: [float(a), float(b)] for n, (a, b) in zip(self.names, self.ci95)},
            "correlation": [[float(c) for c in row] for row in self.correlation],
            "singular_values": [float(s) for s in self.singular_values],
            "poorly_determined": list(self.poorly_determined),
            "warnings": list(self.warnings),
        }


@dataclass(frozen=True)
class FitResult:
    """Result of :func:`fit_level_flight` or :func:`fit_loads`.

    Attributes
    ----------
    params : AirfoilParams
        The fitted parameters (with the M and lift model used in the fit).
    air : Air
    names : tuple of str
        Fitted parameter names (``alpha0`` in rad); body-lift names appended if used.
    x : ndarray
        Fitted values, in ``names`` order.
    residuals : ndarray
        Residual per condition at the optimum (level flight: N; loads: dimensionless).
    cost : float
        0.5 |residuals|^2.
    nfev : int
        Residual evaluations over all starts (each one batched model call).
    n_model_points : int
        Rotor operating points evaluated over the whole fit.
    elapsed_s : float
    success : bool
    message : str
    starts : list of dict
        Every start: x0, final x, cost, nfev.
    identifiability : Identifiability
    extra : dict
        Problem-specific information (body-lift verdict, held-out errors, ...).
    """

    params: AirfoilParams
    air: Air
    names: tuple[str, ...]
    x: np.ndarray
    residuals: np.ndarray
    cost: float
    nfev: int
    n_model_points: int
    elapsed_s: float
    success: bool
    message: str
    starts: list
    identifiability: Identifiability
    extra: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        """The JSON report (angles in degrees, as labelled in ``units``)."""
        p = self.params
        return {
            "params": {"cl1": p.cl1, "cl2": p.cl2, "cd": p.cd, "alpha0_deg": math.degrees(p.alpha0), "M": p.M,
                       "cd0": p.cd0, "cp_blasius": p.cp_blasius, "lift_model": p.lift_model,
                       "rho": self.air.rho, "mu": self.air.mu},
            "fitted": {n: (math.degrees(v) if n.startswith("alpha0") else float(v)) for n, v in zip(self.names, self.x)},
            "units": {"alpha0": "deg", "alpha0_body": "deg"},
            "cost": self.cost, "rms_residual": float(np.sqrt(np.mean(self.residuals**2))),
            "residuals": [float(r) for r in self.residuals],
            "nfev": self.nfev, "n_model_points": self.n_model_points, "elapsed_s": self.elapsed_s,
            "success": self.success, "message": self.message,
            "starts": [{k: ([float(a) for a in v] if isinstance(v, np.ndarray) else v) for k, v in s.items()}
                       for s in self.starts],
            "identifiability": self.identifiability.to_dict(),
            **self.extra,
        }

    def report_text(self) -> str:
        """Plain-text report: estimates, 95% intervals, correlations, warnings."""
        idf = self.identifiability
        lines = [f"{'parameter':<13}{'estimate':>10}{'std err':>10}{'95% interval':>24}"]
        for k, n in enumerate(self.names):
            deg = n.startswith("alpha0")
            f = math.degrees if deg else float
            lo, hi = idf.ci95[k]
            lines.append(f"{n + (' [deg]' if deg else ''):<13}{f(self.x[k]):>10.4g}{f(idf.std_error[k]):>10.3g}"
                         f"{'[' + format(f(lo), '.4g') + ', ' + format(f(hi), '.4g') + ']':>24}")
        lines.append("correlation: " + "; ".join(
            f"{self.names[i]}-{self.names[j]} {idf.correlation[i, j]:+.2f}"
            for i in range(len(self.names)) for j in range(i + 1, len(self.names))))
        lines.append("scaled Jacobian singular values: " + ", ".join(f"{s:.3g}" for s in idf.singular_values))
        unit = " N" if self.extra.get("kind") == "level_flight" else " (scaled)"
        lines.append(f"residual per condition{unit}: " + ", ".join(f"{r:+.3g}" for r in self.residuals))
        lines.append(f"rms residual {np.sqrt(np.mean(self.residuals ** 2)):.4g}; {self.nfev} evaluations "
                     f"({self.n_model_points} rotor points) in {self.elapsed_s:.2f} s; {len(self.starts)} start(s)")
        eff = self.extra.get("M_effect")
        if eff:
            lines.append(f"stall-blend smoothing: fitted with M = {eff['M_fit']:g}; the same parameters give rms "
                         f"residual {eff['rms_residual_at_M_fit']:.4g} at M = {eff['M_fit']:g} and "
                         f"{eff['rms_residual_at_M_base']:.4g} at M = {eff['M_base']:g} (the base value)")
        lines.extend(f"WARNING: {w}" for w in idf.warnings)
        return "\n".join(lines)


def _identifiability(names, x, jac, residuals) -> Identifiability:
    N, p = jac.shape
    dof = max(N - p, 1)
    s2 = float(residuals @ residuals) / dof
    # covariance from the SVD of J with no cut-off: a weak direction gets a large
    # variance (a pseudo-inverse with a cut-off would report it as perfectly known)
    _, sig, Vt = np.linalg.svd(jac, full_matrices=False)
    with np.errstate(divide="ignore"):
        inv_sig2 = np.where(sig > 0, 1.0 / sig**2, np.inf)
    cov = s2 * (Vt.T * inv_sig2) @ Vt
    std = np.sqrt(np.clip(np.diag(cov), 0, None))
    t = stats.t.ppf(0.975, dof)
    ci = np.column_stack([x - t * std, x + t * std])
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(std, std)
    corr = np.where(np.isfinite(corr), corr, 0.0)
    np.fill_diagonal(corr, 1.0)
    scale = np.maximum(np.abs(x), 0.1)
    sv = np.linalg.svd(jac * scale, compute_uv=False)
    poor, warns = [], []
    for k, n in enumerate(names):
        rel = std[k] / max(abs(x[k]), 1e-12)
        if rel > POOR_REL_STD:
            poor.append(n)
            shown = f"{math.degrees(std[k]):.3g} deg" if n.startswith("alpha0") else f"{std[k]:.3g}"
            warns.append(f"{n} is poorly determined: std error {shown} is {100 * rel:.0f}% of its estimate")
    for i in range(p):
        for j in range(i + 1, p):
            if abs(corr[i, j]) > 0.95:
                warns.append(f"{names[i]} and {names[j]} are strongly correlated ({corr[i, j]:+.2f}): "
                             "the data constrain mainly a combination of them")
    if sv.size and sv[-1] < 1e-6 * sv[0]:
        warns.append("the Jacobian is nearly singular: some direction in parameter space is not identifiable")
    return Identifiability(tuple(names), std, ci, corr, sv, tuple(poor), tuple(warns))


def _bounds(names, options: FitOptions):
    table = {**BOUNDS, **BODY_BOUNDS, **(options.bounds or {})}
    lb = np.array([table[n][0] for n in names], float)
    ub = np.array([table[n][1] for n in names], float)
    return lb, ub


def _x0(names, options: FitOptions):
    full = dict(zip(("cl1", "cl2", "cd", "alpha0"), options.x0))
    full.update(zip(("cl1_body", "cl2_body", "alpha0_body"), BODY_X0))
    return np.array([full[n] for n in names], float)


def _m_effect(residual, best, base: AirfoilParams, options: FitOptions) -> dict:
    """When the fit used a smoother M than the base parameters, report what that did:
    the rms residual of the fitted parameters under the fit's M and under the base M."""
    if options.M is None or options.M == base.M:
        return {"M_used": base.M if options.M is None else options.M}
    r_base = residual(best.x, replace(options, M=base.M))
    return {"M_used": options.M, "M_effect": {
        "M_fit": options.M, "M_base": base.M,
        "rms_residual_at_M_fit": float(np.sqrt(np.mean(best.fun**2))),
        "rms_residual_at_M_base": float(np.sqrt(np.mean(r_base**2)))}}


def _jacobian(residual, x, lb, ub):
    """Central-difference Jacobian at x (one-sided at a bound), step 1e-4 max(|x_k|, 0.1).

    The floor 0.1 matters: a purely relative step (SciPy's ``diff_step``) is 1e-14 at
    the paper's start c_d = 0, far below the root solve's tolerance, and gives a
    derivative that is pure round-off.
    """
    cols = []
    for k in range(x.size):
        h = 1e-4 * max(abs(x[k]), 0.1)
        hi, lo = x.copy(), x.copy()
        hi[k] = min(x[k] + h, ub[k])
        lo[k] = max(x[k] - h, lb[k])
        cols.append((residual(hi) - residual(lo)) / (hi[k] - lo[k]))
    return np.column_stack(cols)


def _params_from(x, names, base: AirfoilParams, options: FitOptions) -> AirfoilParams:
    kw = {n: float(v) for n, v in zip(names, x) if not n.endswith("_body")}
    kw["lift_model"] = options.lift_model
    if options.M is not None:
        kw["M"] = float(options.M)
    return base.replace(**kw)


def _solve(residual, names, options: FitOptions, label: str, x0=None):
    """Bounded least squares from x0 (default ``options.x0``) and ``options.multistart``
    Sobol starts; best cost wins."""
    from tqdm import tqdm

    lb, ub = _bounds(names, options)
    x0 = np.clip(_x0(names, options) if x0 is None else np.asarray(x0, float), lb, ub)
    starts = [x0]
    if options.multistart > 0:
        sob = qmc.Sobol(len(names), scramble=True, seed=options.seed).random(options.multistart)
        starts += list(lb + sob * (ub - lb))
    counter = {"n": 0}
    bar = tqdm(desc=label, unit="eval", disable=None if options.progress else True, leave=False)  # None: off unless a terminal

    def fun(x):
        counter["n"] += 1
        bar.update(1)
        return residual(x)

    def jac(x):
        return _jacobian(fun, np.array(x, float), lb, ub)

    def run(x_start, max_nfev):
        r = optimize.least_squares(fun, x_start, jac=jac, bounds=(lb, ub), method="trf", x_scale="jac",
                                   max_nfev=max_nfev, xtol=1e-10, ftol=1e-10, gtol=1e-10)
        log.append({"x0": np.array(x_start), "x": r.x.copy(), "cost": float(r.cost), "nfev": int(r.nfev),
                    "stage": "polish" if max_nfev == options.max_nfev else "screen"})
        bar.set_postfix(best_cost=f"{min(e['cost'] for e in log):.3g}")
        return r

    log = []
    t0 = time.perf_counter()
    try:
        if len(starts) == 1:
            best = run(starts[0], options.max_nfev)
        else:
            # global stage: short runs from every start, then polish the two best to convergence
            screened = sorted((run(s, SCREEN_NFEV) for s in starts), key=lambda r: r.cost)
            polished = [run(r.x, options.max_nfev) for r in screened[:2]]
            best = min(polished, key=lambda r: r.cost)
        # best.jac is _jacobian at best.x: least_squares evaluates jac after every
        # accepted step and returns it unchanged for the default linear loss
    finally:
        bar.close()
    return best, log, counter["n"], time.perf_counter() - t0


# ---------------------------------------------------------------- level flight (eqs 16-18)

def level_flight_forces(params: AirfoilParams, data: LevelFlightData, vehicle: Vehicle, *, air: Air = Air(),
                        discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """Rotor loads of every rotor at every condition and the net vertical force (eq 16).

    Uses the vector form (:func:`rotor_wrench`) on V_i = V_vehicle + omega x r_i; for rotor
    axes along body z, no rates and no roll this is exactly eq 16,
    sum_i T_i sin(beta_i) + D_i cos(beta_i).

    Returns
    -------
    dict with ``thrust``, ``drag``, ``torque`` (shape (N, n_rotors)) [N, N, N m],
    ``vertical`` (shape (N,)) [N] and ``beta`` (shape (N, n_rotors)) [rad].
    """
    R, vel = rotor_kinematics(data, vehicle)
    n_rot = len(vehicle.rotors)
    T = np.empty((data.n, n_rot))
    D = np.empty_like(T)
    Q = np.empty_like(T)
    vertical = np.zeros(data.n)
    groups: dict[int, list[int]] = {}
    for i, rotor in enumerate(vehicle.rotors):
        groups.setdefault(id(rotor.propeller), []).append(i)
    for idx in groups.values():
        prop = vehicle.rotors[idx[0]].propeller
        axes = np.stack([vehicle.rotors[i].axis for i in idx])
        spins = np.array([vehicle.rotors[i].spin for i in idx])
        w = rotor_wrench(prop, params, vel[:, idx, :], np.broadcast_to(axes, (data.n, len(idx), 3)),
                         data.omega[:, idx], np.broadcast_to(spins, (data.n, len(idx))), air=air,
                         discretization=discretization)
        T[:, idx], D[:, idx], Q[:, idx] = w.loads.thrust, w.loads.drag, w.loads.torque
        vertical += np.einsum("nj,nkj->n", R[:, 2, :], w.force)
    beta = np.arccos(np.clip(np.einsum("nkj,kj->nk", vel, np.stack([r.axis for r in vehicle.rotors]))
                             / np.maximum(np.linalg.norm(vel, axis=-1), 1e-300), -1, 1))
    return {"thrust": T, "drag": D, "torque": Q, "vertical": vertical, "beta": beta}


def body_lift(xb, data: LevelFlightData, vehicle: Vehicle, M: float, air: Air) -> np.ndarray:
    """Body lift of Sec. III-A [N]: 0.5 rho V^2 C_L^body(beta_body - pi/2) S_body, eq 3 form."""
    cl1b, cl2b, a0b = xb
    z_world = body_to_world(data.pitch, data.roll)[:, :, 2]  # body z in world
    beta_body = np.arccos(np.clip(z_world[:, 0], -1, 1))  # angle between velocity (world x) and body z
    a = beta_body - math.pi / 2
    s = sigmoid_blend(a, a0b, M)
    CL = (1 - s) * cl1b * a + s * cl2b * np.sin(a) * np.cos(a)
    return 0.5 * air.rho * data.airspeed**2 * CL * vehicle.body_area


def fit_level_flight(data: LevelFlightData, vehicle: Vehicle, *, base: AirfoilParams | None = None,
                     air: Air = Air(), options: FitOptions = FitOptions()) -> FitResult:
    """Identify (c_l1, c_l2, c_d, alpha_0) from steady level flight, eqs (16)-(18).

    Parameters
    ----------
    data : LevelFlightData
    vehicle : Vehicle
    base : AirfoilParams, optional
        Supplies the constants (M, c_d0, c_p) not fitted; gill2017-apc's footnote 2
        values by default.
    air : Air
    options : FitOptions

    Returns
    -------
    FitResult
        ``residuals`` is eq 17 per condition [N]; ``extra`` holds the hover-model
        comparison and, with ``options.body_lift``, the body-lift verdict.

    Raises
    ------
    ValueError
        Fewer conditions than parameters + 1, or body lift requested without body_area.
    SolverError
        From the rotor model.
    """
    from ..core.airfoil import preset

    base = base or preset("gill2017-apc")
    names = param_names(options.lift_model)
    if options.body_lift:
        if vehicle.body_area <= 0:
            raise ValueError("body_lift needs the vehicle's body_area > 0 m^2")
        names = names + ("cl1_body", "cl2_body", "alpha0_body")
    if data.n <= len(names):
        raise ValueError(f"{data.n} conditions cannot identify {len(names)} parameters; need at least {len(names) + 1}")
    M_used = options.M if options.M is not None else base.M
    n_rot = len(vehicle.rotors)

    def residual(x, opts=options):
        p = _params_from(x, names, base, opts)
        f = level_flight_forces(p, data, vehicle, air=air, discretization=opts.discretization)
        r = f["vertical"] - vehicle.weight
        if opts.body_lift:
            r = r + body_lift(x[-3:], data, vehicle, p.M, air)
        return r

    x0 = None
    if options.body_lift:
        # the model without body lift first; the full fit starts from its optimum with
        # zero body lift (BODY_X0), so that it can only improve on it (nested models)
        without = fit_level_flight(data, vehicle, base=base, air=air,
                                   options=replace(options, body_lift=False, progress=False))
        x0 = np.concatenate([without.x, BODY_X0])
    best, log, nfev, elapsed = _solve(residual, names, options, "fit level-flight", x0)
    params = _params_from(best.x, names, base, options)
    idf = _identifiability(names, best.x, best.jac, best.fun)
    extra = {"kind": "level_flight", "n_conditions": data.n, "weight_N": vehicle.weight,
             **_m_effect(residual, best, base, options)}
    if options.body_lift:
        L = body_lift(best.x[-3:], data, vehicle, M_used, air)
        # nested-model F-test: do the 3 body-lift parameters reduce the residual more than
        # fitting noise would? (the paper's Sec. III-A check, made quantitative)
        rss1, rss0 = float(best.fun @ best.fun), float(without.residuals @ without.residuals)
        dof1 = data.n - len(names)
        F = ((rss0 - rss1) / 3) / (rss1 / dof1) if rss1 > 0 and dof1 > 0 else math.inf
        p_value = float(stats.f.sf(F, 3, dof1)) if dof1 > 0 else float("nan")
        extra["body_lift"] = {
            "max_abs_N": float(np.max(np.abs(L))), "max_abs_over_weight": float(np.max(np.abs(L)) / vehicle.weight),
            "rms_residual_with": float(np.sqrt(rss1 / data.n)), "rms_residual_without": float(np.sqrt(rss0 / data.n)),
            "F": float(F), "p_value": p_value, "matters": bool(p_value < 0.05),
        }
    return FitResult(params, air, names, best.x, best.fun, float(best.cost), nfev, nfev * data.n * n_rot, elapsed,
                     bool(best.success), str(best.message), log, idf, extra)


def hover_vertical_force(params: AirfoilParams, data: LevelFlightData, vehicle: Vehicle, *, air: Air = Air()):
    """Vertical force of the hover model (T = k_T Omega^2 along each rotor axis, D = 0) [N], shape (N,).

    k_T of each propeller from the model at V = 0 at the mean rotor speed of the
    slowest condition (the hover point of the data set).
    """
    R = body_to_world(data.pitch, data.roll)
    j0 = int(np.argmin(data.airspeed))
    out = np.zeros(data.n)
    for i, rotor in enumerate(vehicle.rotors):
        h = HoverModel.from_model(rotor.propeller, params, float(np.mean(data.omega[j0])), air=air)
        out += h.thrust(data.omega[:, i]) * np.einsum("nj,j->n", R[:, 2, :], rotor.axis)
    return out


# ---------------------------------------------------------------- loads

def fit_loads(data: LoadData, propeller, *, base: AirfoilParams | None = None, air: Air = Air(),
              quantities: tuple[str, ...] | None = None, options: FitOptions = FitOptions()) -> FitResult:
    """Identify the airfoil parameters from direct load measurements of one propeller.

    Residuals are compared in coefficient form so that every rpm weighs alike: for each
    fitted quantity k, (model_k - measured_k) / (rho n^2 D^m_k) / RMS(measured coefficient),
    m = 4 for thrust and drag (CT), 5 for torque (CQ); the residuals of all k are stacked.

    Parameters
    ----------
    data : LoadData
    propeller : Propeller
    base : AirfoilParams, optional
        Constants not fitted; gill2017-apc's (footnote 2) by default.
    air : Air
    quantities : tuple of str, optional
        Which measured quantities to fit (default: all in ``data.measured``).
    options : FitOptions

    Raises
    ------
    ValueError
        Unknown or unmeasured quantity, fewer residuals than parameters + 1, or a
        measured quantity that is zero everywhere.
    SolverError
        From the rotor model.
    """
    from ..core.airfoil import preset

    base = base or preset("gill2017-apc")
    names = param_names(options.lift_model)
    keys = list(quantities or data.measured)
    for k in keys:
        if k not in data.measured:
            raise ValueError(f"quantity {k!r} is not measured; measured: {', '.join(data.measured)}")
    n = data.omega / (2 * math.pi)
    norm = {k: air.rho * n**2 * propeller.diameter ** (5 if k == "torque" else 4) for k in keys}
    scales = {k: float(np.sqrt(np.mean((data.measured[k] / norm[k]) ** 2))) for k in keys}
    for k, s in scales.items():
        if s == 0:
            raise ValueError(f"measured {k} is zero everywhere; cannot scale its residuals")
    if data.n * len(keys) <= len(names):
        raise ValueError(f"{data.n} points cannot identify {len(names)} parameters")

    def residual(x, opts=options):
        p = _params_from(x, names, base, opts)
        r = rotor_loads(propeller, p, data.omega, data.airspeed, data.incidence, air=air,
                        discretization=opts.discretization)
        model = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque}
        return np.concatenate([(model[k] - data.measured[k]) / norm[k] / scales[k] for k in keys])

    best, log, nfev, elapsed = _solve(residual, names, options, "fit loads")
    params = _params_from(best.x, names, base, options)
    idf = _identifiability(names, best.x, best.jac, best.fun)
    extra = {"kind": "loads", "n_points": data.n, "quantities": keys, "coefficient_scales": scales,
             **_m_effect(residual, best, base, options)}
    return FitResult(params, air, names, best.x, best.fun, float(best.cost), nfev, nfev * data.n, elapsed,
                     bool(best.success), str(best.message), log, idf, extra)
