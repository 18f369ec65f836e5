"""Identification from flight logs: the paper's force balance (eqs 16-18) generalised to
agile flight.

Gill & D'Andrea (2017), Sec. III, identify the section parameters from steady level
flight, where the rotors' vertical force balances the weight (eq 16). An agile flight is
not steady, but a log measures the acceleration: the aerodynamic force on the vehicle is
F = m a_s, a_s the specific force (acceleration minus gravity, what the accelerometer
reads), and the moment about the centre of mass M = I dw/dt + w x I w. Every logged sample
is then an equation like eq 16, in three axes: the residual is the predicted aerodynamic
force (:func:`propmap.vehicle.vehicle_wrench`) minus m a_s, and eq 18's least squares runs
over all samples and axes. The fitting engine, its bounds, population prior,
identifiability report and multistart are those of the loads and level-flight fits
(identify/engine.py, continuation.py, options.py, result.py, dependence.py;
docs/identification.md).

What is fitted: any section parameter, the rotor options (``collective``,
``flap_compliance``), the airframe drag (``drag_area_x``, ``drag_area_y``,
``drag_area_z``, ``wash_factor``; core/body.py) and the centre of mass (``cg_x``,
``cg_y``: its offset from the vehicle file's origin in the rotor plane [m], which moves
every rotor's moment arm; a few millimetres decide the hover moment balance). The default
choice (:data:`FLIGHT_FIT`) was made by leave-one-log-out cross-validation on the
NeuroBEM logs (docs/flight.md). With ``moments``, the moment errors join the residual,
divided by the mean rotor arm so that they are forces too.

Samples are taken at ``rate_hz`` (25 Hz by default, from logs at hundreds of Hz): the
measured forces of the NeuroBEM logs carry no content above 2 Hz that a quasi-steady
rotor model can follow (docs/flight.md), and the cost of a fit is proportional to the
samples.

The samples of the logs (measured force and moment, the motor lag) are assembled in
identify/flight_samples.py and the scores of a prediction (errors, baselines, speed bands) are in
identify/flight_scores.py; their names are re-exported here.
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import replace

import numpy as np

from ..core.airfoil import Air, CamberedParams, SectionParams
from ..core.body import BodyDrag
from ..core.flapping import flapping_warning_held
from ..core.solver import Discretization, differentiable, model_air, rotor_loads
from ..vehicle import Vehicle, VehicleWrench, vehicle_wrench
from ..vehicle.layout import shift_centre_of_mass  # (this module's name since before it moved to the vehicle)
from .continuation import _fit_with_continuation
from .engine import _attach_jacobian, _finish, _m_effect, _params_from, _warn_at_optimum, _with_prior, _x0
from .flight_samples import OMEGA_STOPPED, FlightSamples, flight_samples
from .flight_scores import (BASELINES, SPEED_BANDS, baseline_force, fit_baselines, flight_errors,
                            reference_at_vehicle_mass, reference_errors, speed_band_errors)
from .options import AIRFRAME_BOUNDS, FitOptions, _check_lift_model, _check_names, refuse_unused_options
from .dependence import jackknife_std_error, lag1_autocorrelation
from .result import FitResult

__all__ = ["FlightSamples", "flight_samples", "default_flight_names", "OMEGA_STOPPED", "predict_flight", "fit_flight",
           "fitted_body_drag", "fitted_centre_of_mass", "fitted_vehicle", "shift_centre_of_mass", "flight_errors",
           "fit_baselines", "baseline_force", "speed_band_errors", "reference_at_vehicle_mass", "reference_errors",
           "cross_validate_flight", "hover_torque_check", "HOVER_TORQUE_TARGET",
           "FLIGHT_FIT", "FLIGHT_DISCRETIZATION", "SPEED_BANDS", "AIRFRAME_NAMES", "BASELINES"]

#: parameters fitted by default (docs/flight.md: chosen by leave-one-log-out cross-validation on the
#: NeuroBEM logs among 17 candidate sets): the collective offset of an uncertain blade, the lift
#: slope, the Reynolds zero-lift shift (whose catalogue value contradicts the logs' constant
#: T / Omega^2) and the in-plane airframe drag in the rotors' slipstream
FLIGHT_FIT = ("collective", "cl_alpha", "alpha_L0_re", "drag_area_x", "drag_area_y", "wash_factor")
AIRFRAME_NAMES = tuple(AIRFRAME_BOUNDS)
CG_NAMES = ("cg_x", "cg_y")
#: the solver's nodes for flight fits: against 48 x 16 nodes, forces within 0.2% of the
#: rotor thrust (docs/flight.md), far inside the flight data's model error
FLIGHT_DISCRETIZATION = Discretization(24, 8)


#: a flight fit needs more than this many samples per fitted parameter (three force components a
#: sample; 3 samples of three 8 s logs at 0.1 Hz fitted 6 parameters, the report itself saying the
#: data determine 2 of them: a flight audit, 2026-11-26)
SAMPLES_PER_PARAMETER = 2


def default_flight_names(base: SectionParams) -> tuple[str, ...]:
    """The parameters a flight fit frees by default.

    Parameters
    ----------
    base : SectionParams
        The set the fit starts from (``CamberedParams`` or the paper's ``AirfoilParams``).

    Returns
    -------
    tuple of str
        :data:`FLIGHT_FIT` (chosen by leave-one-log-out cross-validation, docs/flight.md), less
        the cambered section's ``cl_alpha`` and ``alpha_L0_re`` for the paper's model, which has
        neither.
    """
    return FLIGHT_FIT if isinstance(base, CamberedParams) else tuple(
        n for n in FLIGHT_FIT if n not in ("cl_alpha", "alpha_L0_re"))


def predict_flight(samples: FlightSamples, vehicle: Vehicle, params: SectionParams, *, body: BodyDrag | None = None,
                   air: Air | None = None, discretization: Discretization = FLIGHT_DISCRETIZATION,
                   derivatives=False) -> VehicleWrench:
    """The vehicle model's wrench at every sample (:func:`propmap.vehicle.vehicle_wrench`, no wind;
    ``derivatives`` as there).

    Parameters
    ----------
    samples : FlightSamples
        Velocity, angular velocity, rotor speeds and rotor accelerations per sample (N
        samples; :func:`flight_samples`).
    vehicle : Vehicle
    params : AirfoilParams or CamberedParams
        The rotors' section parameters.
    body : BodyDrag, optional
        Airframe drag; default the vehicle's.
    air : Air, optional
        Default: the parameter set's own (``.air``).
    discretization : Discretization
        The rotors' nodes; the flight fit's 24 x 8 by default (docs/flight.md, Speed).
    derivatives : bool or sequence of str
        As :func:`propmap.vehicle.vehicle_wrench` (``"centre_of_mass"`` included).

    Returns
    -------
    VehicleWrench
        Body force [N] and moment [N m] about the centre of mass, shape (N, 3), body axes.

    Raises
    ------
    SolverError
        From the rotor model.
    """
    air = model_air(params, air)
    return vehicle_wrench(vehicle, params, samples.velocity, samples.angular_velocity, samples.rotor_omega,
                          rotor_acceleration=samples.rotor_acceleration, body_drag=body, air=air,
                          discretization=discretization, derivatives=derivatives)


def fitted_centre_of_mass(result: FitResult) -> np.ndarray:
    """The centre of mass of a flight fit.

    Parameters
    ----------
    result : FitResult
        Of :func:`fit_flight`.

    Returns
    -------
    ndarray, shape (2,)
        x, y [m] from the vehicle file's origin (the vehicle's own where ``cg_x``, ``cg_y``
        were not fitted; [0, 0] for a result of another fit).
    """
    return np.asarray(result.extra.get("centre_of_mass", [0.0, 0.0]), float)


def fitted_vehicle(vehicle: Vehicle, result: FitResult) -> Vehicle:
    """The vehicle with a flight fit's centre of mass and rotor interference factor.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle the fit was run on.
    result : FitResult
        Of :func:`fit_flight` (its ``extra["centre_of_mass"]`` and
        ``extra["rotor_interference"]``; each the vehicle's own where the fit did not free it).

    Returns
    -------
    Vehicle
    """
    veh = shift_centre_of_mass(vehicle, fitted_centre_of_mass(result))
    return replace(veh, rotor_interference=float(result.extra.get("rotor_interference", veh.rotor_interference)))


def _mean_arm(vehicle: Vehicle) -> float:
    return float(np.mean([np.linalg.norm(r.position[:2]) for r in vehicle.rotors])) or 1.0


def _body_from(x, names, body: BodyDrag) -> BodyDrag:
    vals = dict(zip(names, x))
    area = [vals.get(f"drag_area_{a}", body.drag_area[k]) for k, a in enumerate("xyz")]
    return BodyDrag(drag_area=tuple(float(v) for v in area), wash_factor=float(vals.get("wash_factor",
                                                                                        body.wash_factor)))


def fit_flight(samples: FlightSamples, vehicle: Vehicle, *, base: SectionParams | None = None, air: Air | None = None,
               body: BodyDrag | None = None, options: FitOptions = FitOptions(), moments: bool = False,
               discretization: Discretization = FLIGHT_DISCRETIZATION) -> FitResult:
    """Identify the rotor and airframe parameters from flight logs (module docstring).

    Parameters
    ----------
    samples : FlightSamples
        The samples to fit (:func:`flight_samples`; select the training logs first).
    vehicle : Vehicle
    base : AirfoilParams or CamberedParams, optional
        The start and every parameter not fitted; the catalogue's ``generic`` set by default.
    air : Air, optional
        Default: the parameter set's own (``.air``).
    body : BodyDrag, optional
        Start of the airframe drag; default the vehicle's, else none (0).
    options : FitOptions
        ``names``: default :data:`FLIGHT_FIT` (``rotor_interference`` may be added: it starts
        at the vehicle's value, or at 1 where the vehicle has none). The population prior applies to the section
        parameters it knows, weighted as level flight's (by the vehicle's weight).
    moments : bool
        Fit the measured moments too (samples need them: the vehicle's inertia), each
        divided by the mean rotor arm [m].
    discretization : Discretization

    Returns
    -------
    FitResult
        ``residuals``: the force errors [N], samples x 3 axes (then, with ``moments``, the
        moment errors / arm [N]); ``extra["body_drag"]``: the fitted airframe drag;
        ``extra["centre_of_mass"]``: the centre-of-mass offset [m]; ``extra["kind"] ==
        "flight"``.

    Raises
    ------
    ValueError
        Unknown parameter names, :data:`SAMPLES_PER_PARAMETER` samples per fitted parameter
        or fewer, moments asked for without measured moments, section parameters fitted for a
        vehicle whose rotors carry their own parameter sets (``Rotor.params``), a
        ``lift_model`` other than the sigmoid with a cambered base.
    SolverError
        From the rotor model.
    TypeError
        ``samples``, ``vehicle``, ``base``, ``air``, ``body`` or ``options`` of the wrong type.

    Warns
    -----
    FlappingWarning
        Once, where the fitted set's blades flap beyond the small-angle range at the samples
        (the model's own warning, silenced at the fit's trial parameter sets).
    """
    from ..io.calibration import generic_params

    _check_flight_args(samples, vehicle, base, body, options)
    base = base or generic_params()
    air = model_air(base, air, name="base")
    names = _flight_names(samples, vehicle, base, options)
    if moments and samples.moment is None:
        raise ValueError("moments: the samples have no measured moment (the vehicle file needs its inertia)")
    body0 = body or vehicle.body_drag or BodyDrag()
    model = _FlightModel(samples, vehicle, base, names, body0, air, moments, discretization,
                         implicit=options.jacobian == "implicit")
    x0 = _x0(names, options, base, _start_values(vehicle, base, names, body0))
    make_residual, prior = _with_prior(model.make_residual, names, base, options, scale=vehicle.weight)
    best, log, nfev, elapsed, warns, extra = _fit_with_continuation(make_residual, names, base, options, "fit flight",
                                                                    x0)
    # (_m_effect: what a smoother --M cost, as loads and level flight say)
    extra = {"kind": "flight", "n_samples": samples.n, "logs": list(samples.log_names), "rate_hz": samples.rate_hz,
             "centre_of_mass": None, "rotor_interference": None, "moments_fitted": bool(moments),
             "moment_arm_m": model.arm, "discretization": [discretization.n_radial, discretization.n_azimuth],
             "body_drag": None, **extra, **_m_effect(model.make_residual, best, base, options)}
    if prior:
        extra["prior"] = prior
    result = _finish(names, base, options, best, log, nfev, elapsed, warns, nfev * samples.n * len(vehicle.rotors),
                     air, extra)
    # the airframe's terms as reported: an effect that ended at its absence is 0, not the optimiser's 1e-14 (which
    # reached the parameter file's [body] while the report said 0: a structural review)
    fitted_body = _body_from(result.x, names, body0)
    result.extra.update(
        centre_of_mass=model.centre_of_mass(result.x),
        rotor_interference=model.vehicle_at(result.x).rotor_interference,
        body_drag={"drag_area": list(fitted_body.drag_area), "wash_factor": fitted_body.wash_factor})
    # the force residuals' dependence from sample to sample within each log (the std errors assume none), in runs of
    # consecutive samples: samples left out (a stopped rotor, the ground) end a run (a review)
    result.extra["residual_autocorrelation"] = lag1_autocorrelation(
        result.residuals[:3 * samples.n].reshape(samples.n, 3), _consecutive_runs(samples))
    result.extra["residual_labels"] = _residual_labels(samples, moments)
    _warn_at_optimum(result, model.make_residual, options)
    return result


def _residual_labels(samples: FlightSamples, moments: bool) -> list[str]:
    """Each flight-fit residual's axis, log and time (the force errors sample by sample, then the
    moments' likewise), which the report shows beside the largest (bare indices, '#11333 -12.1',
    named no sample: an audit of faster flights, 2026-12-02)."""
    where = [f"{samples.log_names[k]}, t {t:.2f} s" for k, t in zip(samples.log_index, samples.t)]
    labels = [f"F{a}, {w}" for w in where for a in "xyz"]
    return labels + ([f"M{a} / arm, {w}" for w in where for a in "xyz"] if moments else [])


def _check_flight_args(samples, vehicle, base, body, options) -> None:
    """TypeErrors naming ``samples``, ``vehicle``, ``body`` or ``options`` of the wrong type (as
    fit_loads and fit_level_flight check theirs:
    ``samples="x"`` met "'str' object has no attribute 'n'", ``options=None`` "'NoneType' object
    has no attribute 'lift_model'": a structural review, 2026-12-01)."""
    from ..vehicle.layout import check_vehicle

    if not isinstance(samples, FlightSamples):
        raise TypeError(f"samples must be a FlightSamples (propmap.identify.flight_samples), got "
                        f"{type(samples).__name__}")
    check_vehicle(vehicle)  # (``base`` and ``air``: model_air's checks)
    if body is not None and not isinstance(body, BodyDrag):
        raise TypeError(f"body must be a propmap.BodyDrag, got {type(body).__name__}")
    if not isinstance(options, FitOptions):
        raise TypeError(f"options must be a propmap.identify.FitOptions, got {type(options).__name__}")


def _flight_names(samples: FlightSamples, vehicle: Vehicle, base: SectionParams,
                  options: FitOptions) -> tuple[str, ...]:
    """The fitted names (``options.names`` checked, or the default), refused where the samples are
    too few for them or where a rotor's own parameter set would not see the section's."""
    _check_lift_model(base, options)
    refuse_unused_options(options, "fit_flight")
    if options.names is not None:
        names = _check_names(options.names, base, options, extra=AIRFRAME_NAMES)
    else:
        names = default_flight_names(base)
    if samples.n <= SAMPLES_PER_PARAMETER * len(names):
        raise ValueError(f"{samples.n} samples cannot identify {len(names)} parameters (at least "
                         f"{SAMPLES_PER_PARAMETER * len(names) + 1}: {SAMPLES_PER_PARAMETER} per parameter)")
    own = [k + 1 for k, r in enumerate(vehicle.rotors) if r.params is not None]
    if own and any(n not in AIRFRAME_NAMES for n in names):
        raise ValueError(f"rotor(s) {', '.join(map(str, own))} of the vehicle carry their own parameter sets, which "
                         "the fitted section parameters would not reach: fit_flight fits one set for every rotor "
                         "(build the vehicle without the rotors' params)")
    return names


def _start_values(vehicle: Vehicle, base: SectionParams, names, body0: BodyDrag) -> dict:
    """Where each fitted name starts: the airframe's and the vehicle's values, then the base's."""
    # airframe terms start small but non-zero, so that every column of the Jacobian is alive
    start = {"drag_area_x": max(body0.drag_area[0], 1e-3), "drag_area_y": max(body0.drag_area[1], 1e-3),
             "drag_area_z": max(body0.drag_area[2], 1e-3), "wash_factor": body0.wash_factor or 1.0,
             "cg_x": float(vehicle.centre_of_mass[0]), "cg_y": float(vehicle.centre_of_mass[1]),
             "rotor_interference": vehicle.rotor_interference or 1.0}
    # every section parameter starts at the base's (the paper's model too: --base is the start, as documented)
    start.update({n: getattr(base, n) for n in names if n not in start and n != "flap_compliance" and hasattr(base, n)})
    return start


class _FlightModel:
    """The flight fit's model of the samples: the vehicle at a parameter vector (its centre of
    mass and rotor interference), and the residual (force, then moment / arm, errors) with, where
    the implicit derivatives reach every name, its Jacobian from the same model call."""

    def __init__(self, samples: FlightSamples, vehicle: Vehicle, base: SectionParams, names, body0: BodyDrag,
                 air: Air, moments: bool, discretization: Discretization, *, implicit: bool):
        self.samples, self.vehicle, self.base, self.names = samples, vehicle, base, names
        self.body0, self.air, self.moments, self.discretization = body0, air, moments, discretization
        self.arm = _mean_arm(vehicle)
        self.cg_idx = [names.index(n) if n in names else None for n in CG_NAMES]
        self.x0_cg = [float(c) for c in vehicle.centre_of_mass[:2]]
        self.k_int = names.index("rotor_interference") if "rotor_interference" in names else None
        section = [n for n in names if n not in AIRFRAME_NAMES]
        self.implicit = (implicit and self.k_int is None and vehicle.rotor_interference == 0
                         and differentiable(base, section) and not any(r.params is not None for r in vehicle.rotors))

    def centre_of_mass(self, x) -> list[float]:
        """The centre of mass in the rotor plane at ``x`` [m]: the fitted offsets, else the vehicle's."""
        return [c0 if k is None else float(x[k]) for k, c0 in zip(self.cg_idx, self.x0_cg)]

    def vehicle_at(self, x) -> Vehicle:
        """The vehicle with the centre of mass and the rotor interference at ``x``."""
        veh = shift_centre_of_mass(self.vehicle, self.centre_of_mass(x))
        return veh if self.k_int is None else replace(veh, rotor_interference=float(x[self.k_int]))

    def errors(self, w: VehicleWrench) -> np.ndarray:
        """The force (and moment / arm) errors of a prediction, flattened [N]."""
        r = (w.force - self.samples.force).ravel()
        if self.moments:
            r = np.concatenate([r, ((w.moment - self.samples.moment) / self.arm).ravel()])
        return r

    def make_residual(self, opts):
        """The residual at the parameter vector (the engine's ``make_residual``)."""

        def residual(x, opts=opts):
            return self.errors(self.predict(x, opts))

        if self.implicit:
            _attach_jacobian(residual, lambda x: self._with_jacobian(x, opts))
        residual.at_optimum = lambda x: self.predict(x, opts, trial=False)  # (engine._warn_at_optimum)
        return residual

    def predict(self, x, opts, derivatives=False, trial: bool = True):
        """The vehicle's wrench at the parameter vector, the model's warnings silenced at a
        trial point (core.flapping.flapping_warning_held) and said at the optimum (``trial=False``)."""
        p = _params_from(x, self.names, self.base, opts)
        with flapping_warning_held() if trial else contextlib.nullcontext():
            return predict_flight(self.samples, self.vehicle_at(x), p, body=_body_from(x, self.names, self.body0),
                                  air=self.air, discretization=self.discretization, derivatives=derivatives)

    def _with_jacobian(self, x, opts):
        """The residual and its Jacobian from one model call: vehicle_wrench's implicit
        derivatives for the section and airframe terms and, through the hub velocities'
        and the arms' chain rule, the centre of mass ("centre_of_mass")."""
        x = np.asarray(x, float)
        names = self.names
        wrt = [n for n in names if n not in CG_NAMES]
        if any(n in CG_NAMES for n in names):
            wrt.append("centre_of_mass")
        w = self.predict(x, opts, derivatives=wrt)
        cols = []
        for n in names:
            if n in CG_NAMES:
                k = CG_NAMES.index(n)
                force, moment = (w.jacobian[(key, "centre_of_mass")][:, :, k] for key in ("force", "moment"))
            else:
                force, moment = w.jacobian[("force", n)], w.jacobian[("moment", n)]
            c = force.ravel()
            if self.moments:
                c = np.concatenate([c, (moment / self.arm).ravel()])
            cols.append(c)
        return self.errors(w), np.column_stack(cols)


def _consecutive_runs(samples: FlightSamples) -> np.ndarray:
    """Per sample, the index of its run of consecutive samples: a new run at each log and
    after a step longer than 1.5 times the log's median step."""
    runs = np.zeros(samples.n, dtype=int)
    k = 0
    for log in np.unique(samples.log_index):
        idx = np.flatnonzero(samples.log_index == log)
        dt = np.diff(samples.t[idx])
        breaks = np.concatenate([[0], (dt > 1.5 * np.median(dt)).astype(int)]) if dt.size else np.zeros(1, int)
        runs[idx] = k + np.cumsum(breaks)
        k = runs[idx].max() + 1
    return runs


def fitted_body_drag(result: FitResult) -> BodyDrag | None:
    """The airframe drag of a flight fit.

    Parameters
    ----------
    result : FitResult
        Of any fit.

    Returns
    -------
    BodyDrag or None
        The fitted (or held) drag areas and slipstream factor; None for a result of another
        fit.
    """
    b = result.extra.get("body_drag")
    return None if b is None else BodyDrag(drag_area=tuple(b["drag_area"]), wash_factor=b["wash_factor"])


def cross_validate_flight(samples: FlightSamples, vehicle: Vehicle, *, base: SectionParams | None = None,
                          air: Air | None = None, options: FitOptions = FitOptions(), moments: bool = False,
                          discretization: Discretization = FLIGHT_DISCRETIZATION, progress=None) -> dict:
    """Leave-one-log-out: fit on all logs but one, score on it, for every log.

    The baselines are refitted the same way, so that every number is held out.

    Parameters
    ----------
    samples : FlightSamples
        Samples of two logs or more (``log_index`` tells them apart).
    vehicle : Vehicle
    base, air, options, moments, discretization
        As :func:`fit_flight`, for every fold.
    progress : callable, optional
        Called after each fold with its row of ``folds`` (below).

    Returns
    -------
    dict
        ``folds``: per held-out log its name and the errors (:func:`flight_errors`) of the
        model, of each baseline and of the log's reference prediction where it has one;
        ``pooled``: the pooled F over all folds (root mean of the folds' mean squares,
        weighted by samples) for the model and each baseline; each fold's ``x`` (its fitted
        parameters, as fitted: angles in rad) and ``at_bound``; ``jackknife_std_error``: the
        parameters' delete-a-log jackknife std error from the folds
        (:func:`propmap.identify.dependence.jackknife_std_error`, as fitted: angles in rad), the
        spread between flights that the fit's linearised std errors, which take the samples
        as independent, miss.

    Raises
    ------
    ValueError
        Samples of fewer than 2 logs (a log of ``log_names`` without samples, one held out
        by :meth:`FlightSamples.select`, is not a fold).
    """
    present = np.unique(samples.log_index)
    if present.size < 2:
        raise ValueError(f"cross-validation needs samples of at least 2 logs, got {present.size}")
    folds = []
    for k in present:
        k, name = int(k), samples.log_names[int(k)]
        train = samples.select(samples.log_index != k)
        test = samples.of_log(k)
        res = fit_flight(train, vehicle, base=base, air=air, options=options, moments=moments,
                         discretization=discretization)
        w = predict_flight(test, fitted_vehicle(vehicle, res), res.params,
                           body=fitted_body_drag(res), air=air, discretization=discretization)
        row = {"log": name, "model": flight_errors(w.force, test, w.moment),
               "x": {n: float(v) for n, v in zip(res.names, res.x)}, "at_bound": list(res.at_bound)}
        for key, bl in fit_baselines(train, vehicle).items():
            row[key] = flight_errors(baseline_force(bl, test, vehicle), test)
        row.update(reference_errors(test, vehicle.mass)[0])
        folds.append(row)
        if progress:
            progress(row)
    pooled = {}
    extra = [k for k in ("reference", "reference_at_vehicle_mass") if all(k in f for f in folds)]
    for key in ["model"] + [b[0] for b in BASELINES] + extra:
        ms = np.array([f[key]["F"] ** 2 * f[key]["n"] for f in folds])
        pooled[key] = float(np.sqrt(ms.sum() / sum(f[key]["n"] for f in folds)))
    names = list(folds[0]["x"])
    se = jackknife_std_error([[f["x"][n] for n in names] for f in folds])
    return {"folds": folds, "pooled": pooled, "jackknife_std_error": dict(zip(names, map(float, se)))}


#: the range of :func:`hover_torque_check`'s ratio within which a flight fit's section drag is taken as physical
#: (within 25% of the thrust-stand-calibrated generic set's hover torque at the same thrust; docs/flight.md)
HOVER_TORQUE_TARGET = (0.75, 1.25)


def hover_torque_check(params: SectionParams, vehicle: Vehicle, samples: FlightSamples, *, air: Air | None = None,
                       reference: SectionParams | None = None,
                       discretization: Discretization = FLIGHT_DISCRETIZATION) -> dict:
    """The fitted set's hover torque against a thrust-stand-like value.

    A flight log measures no rotor torque directly, so a refit of the section to forces
    alone could make the drag nonphysical. Two checks:

    * **against a static set** (``reference``, default the catalogue-calibrated generic set,
      fitted to the UIUC thrust stands): the reference's collective is trimmed
      (:func:`propmap.trim_collective`) so that it makes the fitted set's hover thrust at
      the same Omega; ``ratio`` = Q_fitted / Q_reference. Within 25% means the fit did
      not buy force accuracy with a nonphysical drag.
    * **from the yaw channel**: M_z = -sum_i s_i (k_Q Omega_i^2 + J_i dOmega_i/dt) fitted
      linearly to the measured yaw moment gives a flight k_Q, reported with its correlation
      ``yaw_r``: where the yaw moment hardly correlates with the rotors' torque imbalance
      (|r| < 0.5; the NeuroBEM logs: 0.07) the regression is attenuated towards 0 and
      says nothing.

    Omega_hover is the median rotor speed of the slowest tenth of the samples.

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
        The fitted set.
    vehicle : Vehicle
        Its rotors' propeller (the first rotor's), spins and inertias.
    samples : FlightSamples
        Their speeds pick the hover samples; with measured moments, the yaw channel.
    air : Air, optional
        Default: the fitted set's own (``.air``).
    reference : AirfoilParams or CamberedParams, optional
        The static set; default the catalogue's generic set.
    discretization : Discretization

    Returns
    -------
    dict
        ``omega_hover`` [rad/s], ``thrust_hover`` [N], ``torque_model`` and
        ``torque_reference`` [N m], ``ratio``, ``reference_collective_deg`` (the trim: the
        collective added to the reference set's own, as :func:`propmap.trim_collective` returns it),
        and, with measured moments, ``torque_yaw_channel`` [N m], ``k_Q`` and ``yaw_r``.
        Where no reference collective in [-20, 30] deg makes the fitted hover thrust, the
        three reference entries are replaced by ``unavailable`` (the trim's message); the yaw
        channel does not need them.
    """
    air = model_air(params, air)
    from ..core.trim import TrimError, trim_collective
    from ..io.calibration import generic_params

    reference = reference or generic_params()
    slow = samples.speed <= np.quantile(samples.speed, 0.1)
    om_h = float(np.median(samples.rotor_omega[slow]))
    prop = vehicle.rotors[0].propeller
    fit = rotor_loads(prop, params, om_h, 0.0, 0.0, air=air, discretization=discretization)
    out = {"omega_hover": om_h, "thrust_hover": float(fit.thrust), "torque_model": float(fit.torque)}
    try:
        ref = trim_collective(prop, reference, float(fit.thrust), om_h, air=air, discretization=discretization)
    except TrimError as exc:  # the reference cannot make that thrust: the check against it is unavailable
        out["unavailable"] = str(exc)
    else:
        out.update(torque_reference=float(ref.loads.torque), ratio=float(fit.torque) / float(ref.loads.torque),
                   reference_collective_deg=math.degrees(float(ref.collective)))
    if samples.moment is not None:
        spins = np.array([r.spin for r in vehicle.rotors])
        J = np.array([r.inertia or 0.0 for r in vehicle.rotors])
        az = np.array([r.axis[2] for r in vehicle.rotors])
        X = -(spins * az * samples.rotor_omega**2).sum(axis=1)
        y = samples.moment[:, 2] + (spins * az * J * samples.rotor_acceleration).sum(axis=1)
        kQ = float(X @ y / (X @ X))
        out.update(torque_yaw_channel=kQ * om_h**2, k_Q=kQ, yaw_r=float(np.corrcoef(X, y)[0, 1]))
    return out
