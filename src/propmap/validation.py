"""The model against measurements: per run, and cross-validated over the catalogue.

* :func:`validate`: the model (either section model) and the hover model
  T = k_T Omega^2, calibrated on the MEASURED static CT and CP (mean over the static runs),
  against a catalogue propeller's UIUC static runs and J-sweeps, as in Fig. 7 of Gill &
  D'Andrea (2017).
* :func:`cross_validate`: held-out errors of the calibration protocols (leave one sweep
  out, static-only calibration, static + lowest-rpm sweep, blind prediction with a generic
  set that never saw the propeller), in the metric rms |dCT| / static CT and
  |dCP| / static CP.
* :func:`holdout_loads`: held-out errors of fits to load data at incidence (thrust, in-plane
  force, torque), each fold's training points fitted with the defaults or given names.
* :func:`load_errors`: a parameter set against a user's own load data (a thrust stand's, a
  wind tunnel's), overall and per group (``propmap validate DATA --prop GEOM``).

Measurements: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .core.airfoil import Air, SectionParams
from .core.geometry import Propeller
from .core.solver import DEFAULT_DISCRETIZATION, Discretization, model_air, rotor_loads
from .core.states import STATES
from .io.catalogue import CatalogueEntry

__all__ = ["SweepComparison", "Validation", "validate", "coefficient_errors", "cross_validate", "holdout_loads",
           "load_errors", "PROTOCOLS"]


@dataclass(frozen=True)
class SweepComparison:
    """One measured run beside the model and the hover model.

    Attributes
    ----------
    kind : {"static", "sweep"}
    run_id : str
    rpm : ndarray
        Rotation rate of each point [rpm].
    J : ndarray
        Advance ratio of each point (0 for static runs).
    CT, CP : ndarray
        Measured coefficients.
    CT_model, CP_model : ndarray
        Full model.
    CT_hover, CP_hover : ndarray
        Hover model (constant CT, CP).
    source : str
    """

    kind: str
    run_id: str
    rpm: np.ndarray
    J: np.ndarray
    CT: np.ndarray
    CP: np.ndarray
    CT_model: np.ndarray
    CP_model: np.ndarray
    CT_hover: np.ndarray
    CP_hover: np.ndarray
    source: str

    @property
    def label(self) -> str:
        """Display name: 'static <run>' or '<run> @ <rpm> rpm'."""
        if self.kind == "static":
            return f"static {self.run_id}"
        return f"{self.run_id} @ {np.median(self.rpm):.0f} rpm"

    def errors(self, which: str) -> dict:
        """The errors of the model or the hover model on this run, in coefficient units.

        Parameters
        ----------
        which : {"model", "hover_model"}

        Returns
        -------
        dict
            ``ct_rmse``, ``cp_rmse`` (rms of predicted - measured CT, CP), ``ct_max_abs``,
            ``cp_max_abs`` (largest |error|) and ``ct_bias``, ``cp_bias`` (mean error).

        Raises
        ------
        ValueError
            If ``which`` is neither.
        """
        ct, cp = _predicted(self, which)
        return _errors(ct - self.CT, cp - self.CP)


def _predicted(run: SweepComparison, which: str) -> tuple[np.ndarray, np.ndarray]:
    """CT, CP of ``which`` ("model" or "hover_model") on ``run``."""
    if which == "model":
        return run.CT_model, run.CP_model
    if which == "hover_model":
        return run.CT_hover, run.CP_hover
    raise ValueError(f"which must be 'model' or 'hover_model', got {which!r}")


def _errors(dct, dcp) -> dict:
    return {
        "ct_rmse": float(np.sqrt(np.mean(dct**2))),
        "cp_rmse": float(np.sqrt(np.mean(dcp**2))),
        "ct_max_abs": float(np.max(np.abs(dct))),
        "cp_max_abs": float(np.max(np.abs(dcp))),
        "ct_bias": float(np.mean(dct)),
        "cp_bias": float(np.mean(dcp)),
    }


@dataclass(frozen=True)
class Validation:
    """Result of :func:`validate`: a propeller's measured runs beside the model and the hover model.

    Attributes
    ----------
    propeller : str
        Catalogue name.
    runs : list of SweepComparison
        Every bundled run of the propeller (static runs and J-sweeps), in the catalogue's order.
    CT_hover, CP_hover : float
        The hover model's constant coefficients: the measured static CT and CP, averaged over
        every point of the static runs.
    citation : str
        Source of the measurements.
    params : dict
        The section parameters the model used (their file form).
    """

    propeller: str
    runs: list[SweepComparison]
    CT_hover: float
    CP_hover: float
    citation: str
    params: dict = field(default_factory=dict)

    def summary(self, which: str, run_ids=None) -> dict:
        """Errors pooled over the measured points, for the model or the hover model.

        Parameters
        ----------
        which : {"model", "hover_model"}
        run_ids : iterable of str, optional
            Pool only the runs with these ids (e.g. held-out sweeps); default every run.

        Returns
        -------
        dict
            The keys of :meth:`SweepComparison.errors` over the pooled points, and
            ``n_points``.

        Raises
        ------
        ValueError
            If ``which`` is neither, or an id of ``run_ids`` names no run of the propeller.
        """
        ids = None if run_ids is None else ({run_ids} if isinstance(run_ids, str) else set(run_ids))
        runs = [r for r in self.runs if ids is None or r.run_id in ids]
        unknown = sorted(ids - {r.run_id for r in self.runs}) if ids is not None else []
        if unknown or not runs:
            raise ValueError(f"run_ids {unknown or sorted(ids)} name no run of {self.propeller} "
                             f"(its runs: {', '.join(dict.fromkeys(r.run_id for r in self.runs))})")
        pred = [_predicted(r, which) for r in runs]
        ct = np.concatenate([ct - r.CT for (ct, _), r in zip(pred, runs)])
        cp = np.concatenate([cp - r.CP for (_, cp), r in zip(pred, runs)])
        out = _errors(ct, cp)
        out["n_points"] = int(ct.size)
        return out

    def to_dict(self) -> dict:
        """The JSON form printed by ``propmap validate --json``."""
        return {
            "propeller": self.propeller,
            "citation": self.citation,
            "params": self.params,
            "model": self.summary("model"),
            "hover_model": {**self.summary("hover_model"), "CT": self.CT_hover, "CP": self.CP_hover},
            "sweeps": [
                {"kind": r.kind, "run_id": r.run_id, "rpm": float(np.median(r.rpm)), "n_points": int(r.CT.size),
                 "source": r.source, "model": r.errors("model"), "hover_model": r.errors("hover_model")}
                for r in self.runs
            ],
        }


def validate(entry: CatalogueEntry, propeller: Propeller, params: SectionParams, *, air: Air | None = None,
             discretization: Discretization = DEFAULT_DISCRETIZATION) -> Validation:
    """Compare the model and the hover model with every bundled measurement of ``entry``.

    Parameters
    ----------
    entry : CatalogueEntry
        Gives the measurements (UIUC static runs and J-sweeps).
    propeller : Propeller
        The geometry to use (normally ``load_propeller(entry.name)``).
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: the parameter set's own (``.air``).
        Density used to convert coefficients; UIUC coefficients are density-normalised,
        so air only enters through the Reynolds term.
    discretization : Discretization, optional
        The model's radial and azimuthal nodes (default 48 x 16).

    Returns
    -------
    Validation

    Raises
    ------
    ValueError
        The entry has no static run (the hover model needs one) or no measurements.
    SolverError
        From the solver.
    """
    air = model_air(params, air)
    statics = entry.static_runs()
    sweeps = entry.sweeps()
    if not statics:
        raise ValueError(f"{entry.name} has no bundled static run to calibrate the hover model on")
    CT_h = float(np.mean(np.concatenate([s.CT for s in statics])))
    CP_h = float(np.mean(np.concatenate([s.CP for s in statics])))
    D = propeller.diameter
    runs = []
    for s in statics:
        om = s.rpm * 2 * math.pi / 60
        r = rotor_loads(propeller, params, om, 0.0, 0.0, air=air, discretization=discretization)
        runs.append(SweepComparison("static", s.run_id, s.rpm, np.zeros_like(s.rpm), s.CT, s.CP,
                                    r.CT, r.CP, np.full_like(s.CT, CT_h), np.full_like(s.CP, CP_h), s.source))
    for w in sweeps:
        n = w.rpm / 60.0
        r = rotor_loads(propeller, params, 2 * math.pi * n, w.J * n * D, 0.0, air=air, discretization=discretization)
        runs.append(SweepComparison("sweep", w.run_id, np.full_like(w.J, w.rpm), w.J, w.CT, w.CP,
                                    r.CT, r.CP, np.full_like(w.CT, CT_h), np.full_like(w.CP, CP_h), w.source))
    from .io.params_file import params_to_dict

    return Validation(entry.name, runs, CT_h, CP_h, entry.citation, params=params_to_dict(params, air))


def holdout_comparison(entry: CatalogueEntry, propeller: Propeller, fitted: SectionParams, baseline: SectionParams,
                       holdout, *, air: Air | None = None,
                       discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """Held-out CT and CP errors of a fitted model, a baseline parameter set and the hover model.

    The hover model uses the measured static CT and CP. ``holdout`` names UIUC run ids.

    Returns
    -------
    dict
        ``{"holdout": [...], "fitted": {...}, "baseline": {...}, "hover_model": {...}}``, each
        error dict as :meth:`Validation.summary` pooled over the held-out runs, plus
        ``"validation_fitted"`` and ``"validation_baseline"`` (:class:`Validation`) for figures.

    Raises
    ------
    ValueError
        As :func:`validate`.
    SolverError
        From the model.
    """
    air = model_air(fitted, air, name="fitted")
    vf = validate(entry, propeller, fitted, air=air, discretization=discretization)
    vb = validate(entry, propeller, baseline, air=air, discretization=discretization)
    held = sorted(set(holdout))
    return {"holdout": held, "fitted": vf.summary("model", held), "baseline": vb.summary("model", held),
            "hover_model": vf.summary("hover_model", held), "validation_fitted": vf, "validation_baseline": vb}


# ------------------------------------------------------------------ cross-validation

#: the calibration protocols of :func:`cross_validate`
PROTOCOLS = ("loso", "loro", "lowest", "static", "blind")
PROTOCOL_TEXT = {
    "loso": "leave one sweep out: fit on the static run and the other sweeps, predict the held-out sweep",
    "loro": "leave one rpm out: fit on the static run and the sweeps at other rpm, predict all sweeps at that rpm",
    "lowest": "fit on the static run and the lowest-rpm sweeps, predict the sweeps at higher rpm",
    "static": "fit on the static run only, predict the sweeps",
    "blind": "no fit: the generic set derived without this propeller's family, predict the sweeps",
}
#: sweeps whose mean rotation rates differ by less than this fraction form one rpm group
SAME_RPM = 0.03


def _coefficients(data, propeller: Propeller, air: Air):
    """Measured CT, CP (propeller convention) of load data; NaN where not measured."""
    n = data.omega / (2 * math.pi)
    D = propeller.diameter
    CT = data.measured["thrust"] / (air.rho * n**2 * D**4) if "thrust" in data.measured else np.full(data.n, np.nan)
    CP = (data.measured["torque"] * 2 * math.pi / (air.rho * n**2 * D**5) if "torque" in data.measured
          else np.full(data.n, np.nan))
    return CT, CP


def coefficient_errors(data, propeller: Propeller, params: SectionParams, *, air: Air | None = None, mask=None,
                       discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """rms |dCT| / static CT and rms |dCP| / static CP of ``params`` on load data.

    The normalisation is the mean measured CT and CP of the static points (airspeed 0)
    of ``data`` (all of them, also when ``mask`` selects other points), so that errors of
    propellers of any size and pitch compare.

    Parameters
    ----------
    data : LoadData
        Must contain static points with thrust and torque.
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    air : Air, optional
        The air of the model and of the coefficients' normalisation (default: the parameter
        set's own ``.air``).
    discretization : Discretization, optional
        The model's radial and azimuthal nodes (default 48 x 16).
    mask : array_like of bool, optional
        Points to evaluate (default all).

    Returns
    -------
    dict
        ``rms_ct``, ``rms_cp`` [-], ``bias_ct``, ``bias_cp`` [-] (mean signed error over
        the same normalisation), ``n_points``.

    Raises
    ------
    ValueError
        No static points, or the mask selects none.
    SolverError
        From the model.
    """
    air = model_air(params, air)
    CT, CP = _coefficients(data, propeller, air)
    static = data.airspeed == 0
    if not static.any():
        raise ValueError("coefficient_errors needs static points (airspeed 0) to normalise by")
    CT0, CP0 = float(np.nanmean(CT[static])), float(np.nanmean(CP[static]))
    m = np.ones(data.n, bool) if mask is None else np.asarray(mask, bool)
    if not m.any():
        raise ValueError("the mask selects no point")
    r = rotor_loads(propeller, params, data.omega[m], data.airspeed[m], data.incidence[m], air=air,
                    discretization=discretization)
    dct = (r.CT - CT[m]) / CT0
    dcp = (r.CP - CP[m]) / CP0
    return {"rms_ct": float(np.sqrt(np.nanmean(dct**2))), "rms_cp": float(np.sqrt(np.nanmean(dcp**2))),
            "bias_ct": float(np.nanmean(dct)), "bias_cp": float(np.nanmean(dcp)), "n_points": int(m.sum())}


def rpm_groups(data) -> list[list[str]]:
    """The sweeps of load data grouped by rotation rate (within SAME_RPM), lowest first.

    UIUC often measures two sweeps at one rpm that split the advance-ratio range.
    """
    static = data.airspeed == 0
    sweeps = [g for g in dict.fromkeys(data.group) if not np.all(static[data.group == g])]
    rate = {g: float(np.mean(data.omega[data.group == g])) for g in sweeps}
    groups: list[list[str]] = []
    for g in sorted(sweeps, key=rate.get):
        if groups and rate[g] <= rate[groups[-1][0]] * (1 + SAME_RPM):
            groups[-1].append(g)
        else:
            groups.append([g])
    return groups


def _splits(data, protocol: str):
    """(train mask, test mask) pairs of a protocol (every test mask holds sweep points only)."""
    static = data.airspeed == 0
    groups = rpm_groups(data)
    if protocol == "loso":
        return [(data.group != g, data.group == g) for grp in groups for g in grp]
    if protocol == "loro":
        return [(~np.isin(data.group, grp), np.isin(data.group, grp)) for grp in groups]
    if protocol == "lowest":
        train = static | np.isin(data.group, groups[0])
        return [(train, ~train)]
    if protocol == "static":
        return [(static, ~static)]
    return [(None, ~static)]


def cross_validate(data, propeller: Propeller, generic: SectionParams, *, protocols=PROTOCOLS, air: Air | None = None,
                   population: dict | None = None,
                   discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """Held-out errors of the calibration protocols for one propeller's static run and sweeps.

    Every fit uses :func:`propmap.identify.fit_loads` with its defaults for the data it
    sees (parameters chosen by the data, population prior) and ``generic`` as start,
    prior mean and constants; the errors are pooled over all held-out points of the
    protocol (``loso``: every sweep held out in turn).

    Parameters
    ----------
    data : LoadData
        Static points (airspeed 0) and axial sweeps at two rotation rates at least, with
        thrust and torque; ``group`` labels the runs.
    propeller : Propeller
    generic : SectionParams
        The set used blind and as the fits' base. For honest numbers it must not have
        been fitted to this propeller's data (the shipped ``generic_folds``).
    protocols : sequence of str
        Any of :data:`PROTOCOLS`.
    population : dict, optional
        The fits' prior statistics (io.calibration.population); for honest numbers, those
        of the catalogue without this propeller's family (``population(without=name)``).
    air : Air, optional
        The air of the model and of the coefficients' normalisation (default: the parameter
        set's own ``.air``).
    discretization : Discretization, optional
        The model's radial and azimuthal nodes (default 48 x 16).

    Returns
    -------
    dict
        protocol -> ``{"rms_ct", "rms_cp", "bias_ct", "bias_cp", "n_points", "n_fits"}``.

    Raises
    ------
    ValueError
        An unknown protocol, no static points or fewer than two sweeps.
    SolverError
        From the model.
    """
    air = model_air(generic, air, name="generic")
    from .identify import FitOptions, fit_loads

    bad = [p for p in protocols if p not in PROTOCOLS]
    if bad:
        raise ValueError(f"unknown protocol(s) {', '.join(bad)}; valid: {', '.join(PROTOCOLS)}")
    static = data.airspeed == 0
    if not static.any() or len(rpm_groups(data)) < 2:
        raise ValueError("cross_validate needs static points and sweeps at two rotation rates at least")
    CT, CP = _coefficients(data, propeller, air)
    CT0, CP0 = float(np.mean(CT[static])), float(np.mean(CP[static]))
    out = {}
    for protocol in protocols:
        dct, dcp = [], []
        splits = _splits(data, protocol)
        for train, test in splits:
            params = generic
            if train is not None:
                params = fit_loads(data.subset(train), propeller, base=generic, air=air,
                                   options=FitOptions(population=population, discretization=discretization)).params
            r = rotor_loads(propeller, params, data.omega[test], data.airspeed[test], data.incidence[test], air=air,
                            discretization=discretization)
            dct.append((r.CT - CT[test]) / CT0)
            dcp.append((r.CP - CP[test]) / CP0)
        dct, dcp = np.concatenate(dct), np.concatenate(dcp)
        out[protocol] = {"rms_ct": float(np.sqrt(np.mean(dct**2))), "rms_cp": float(np.sqrt(np.mean(dcp**2))),
                         "bias_ct": float(np.mean(dct)), "bias_cp": float(np.mean(dcp)), "n_points": int(dct.size),
                         "n_fits": sum(t is not None for t, _ in splits)}
    return out


def holdout_loads(data, propeller: Propeller, base: SectionParams, folds, *, names=None, population: dict | None = None,
                  air: Air | None = None) -> dict:
    """Held-out errors of fits to load data with thrust, in-plane force and torque.

    Each fold's training points are fitted with :func:`propmap.identify.fit_loads` (from
    ``base``, under ``population``'s prior, ``names`` or the defaults, which free the flapping
    where the data measure the in-plane force at incidence) and its held-out points predicted.

    Parameters
    ----------
    data : LoadData
        With ``thrust``, ``drag`` and ``torque`` measured, and static points (airspeed 0).
    propeller : Propeller
    base : AirfoilParams or CamberedParams
    folds : sequence of array_like of bool
        Each fold's training mask, shape (N,); its complement is predicted (not empty).
    names : tuple of str, optional
        The parameters to fit (default: the fit's own choice).
    population : dict, optional
        The prior's statistics (io.calibration.population).
    air : Air, optional
        Default: ``base.air``.

    Returns
    -------
    dict
        ``rms_thrust`` and ``rms_drag`` (of the mean measured static thrust), ``rms_torque``
        (of the static torque), pooled over the folds' held-out points; ``flap_compliance``,
        each fold's fitted value [rad/(N m)]; ``n_points``.

    Raises
    ------
    ValueError
        A quantity not measured, no static point, an empty fold, or as ``fit_loads``.
    SolverError
        From the model.
    """
    from .identify import FitOptions, fit_loads

    air = model_air(base, air, name="base")
    missing = [k for k in ("thrust", "drag", "torque") if k not in data.measured]
    static = data.airspeed == 0
    if missing or not static.any():
        raise ValueError(f"holdout_loads needs thrust, drag and torque and static points; missing "
                         f"{', '.join(missing) or 'static points'}")
    T0, Q0 = float(np.mean(data.measured["thrust"][static])), float(np.mean(data.measured["torque"][static]))
    err = {"thrust": [], "drag": [], "torque": []}
    compliance = []
    for train in folds:
        train = np.asarray(train, bool)
        if train.all() or not train.any():
            raise ValueError("every fold needs training and held-out points")
        p = fit_loads(data.subset(train), propeller, base=base, air=air,
                      options=FitOptions(population=population, names=names)).params
        compliance.append(float(p.flap_compliance))
        r = rotor_loads(propeller, p, data.omega[~train], data.airspeed[~train], data.incidence[~train], air=air,
                        collective=None if data.collective is None else data.collective[~train])
        for k, scale in (("thrust", T0), ("drag", T0), ("torque", Q0)):
            err[k].append((getattr(r, k) - data.measured[k][~train]) / scale)
    out = {f"rms_{k}": float(np.sqrt(np.mean(np.concatenate(v) ** 2))) for k, v in err.items()}
    return {**out, "flap_compliance": compliance, "n_points": int(sum(len(v) for v in err["thrust"]))}


def load_errors(data, propeller: Propeller, params: SectionParams, *, air: Air | None = None,
                discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """A parameter set against load measurements, in coefficient form, overall and per group.

    Each measured load is compared as a coefficient, so that every rate weighs alike: thrust
    and in-plane force as F / (rho n^2 D^4), torque as Q / (rho n^2 D^5); the errors are in
    units of a reference coefficient: the mean measured static thrust coefficient for thrust
    and in-plane force and the static torque coefficient for torque (the points at an airspeed
    up to 0.3 m/s), as the catalogue's metric (docs/validation.md), or, without static points,
    the rms of the measured coefficient. The in-plane force is scored where the rotor has an
    in-plane airspeed above 0.3 m/s (elsewhere model and measurement should both be zero; all
    points where none has one); points where the solver did not converge are left out (counted).

    Parameters
    ----------
    data : LoadData
        From :func:`propmap.identify.read_loads` or the UIUC readers; any of thrust, drag
        (the in-plane force), torque measured.
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: ``params.air`` at the density the data logged (``LoadData.air_density``)
        where they logged one.
    discretization : Discretization, optional

    Returns
    -------
    dict
        ``reference``: quantity -> (what it is, its value); ``overall``, ``groups`` (group
        label -> the same) and ``states`` (the model's working state, :data:`propmap.core.states.STATES`,
        -> the same; empty where every converged point is in normal working): quantity ->
        {``rms``, ``bias`` (mean model - measured), ``max`` (largest magnitude), in units of the
        reference [-]; ``rms_si``, the rms error in N or N m; ``n``, the points scored};
        ``n_points``; ``converged`` (points the solver converged on; the others are left out of
        every figure). A load not measured at a point (NaN in ``data.measured``) is left out
        of that quantity's figures (``n`` counts the points scored).

    Raises
    ------
    ValueError
        No load measured, or a reference of zero (every measured value 0).
    SolverError
        From the model.
    """
    from .identify.load_data import STATIC_AIRSPEED, data_air

    air = data_air(data, air, params.air)[0]  # (the density the data logged, where no air is given)
    keys = [k for k in ("thrust", "drag", "torque") if k in data.measured]
    if not keys:
        raise ValueError("no load measured (thrust, drag or torque)")
    r = rotor_loads(propeller, params, data.omega, data.airspeed, data.incidence, air=air,
                    discretization=discretization, collective=data.collective, on_failure="flag")
    n = data.omega / (2 * math.pi)
    D = propeller.diameter
    scale = {"thrust": air.rho * n**2 * D**4, "drag": air.rho * n**2 * D**4, "torque": air.rho * n**2 * D**5}
    model = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque}
    static = data.airspeed <= STATIC_AIRSPEED
    coeff = {k: data.measured[k] / scale[k] for k in keys}
    inplane = data.airspeed * np.abs(np.sin(data.incidence)) > STATIC_AIRSPEED
    reference = {}
    for k in keys:
        own = "thrust" if k in ("thrust", "drag") and "thrust" in coeff else k
        known = np.isfinite(coeff[own])  # (NaN: not measured at that point)
        if own == "drag" and inplane.any():  # (a drag without a thrust: its static mean is 0, once 'mean static CQ')
            known &= inplane
        if own != "drag" and np.any(static & known):
            value, what = float(np.mean(coeff[own][static & known])), f"mean static {'CT' if own == 'thrust' else 'CQ'}"
        else:
            value, what = float(np.sqrt(np.mean(coeff[own][known] ** 2))), f"rms measured {own} coefficient"
        if not (math.isfinite(value) and value != 0.0):
            raise ValueError(f"the {what} is {value:g}: no reference for the {k} errors")
        reference[k] = (what, value)

    ok = np.asarray(r.converged, bool) & np.all([np.isfinite(model[k]) for k in keys], axis=0)
    # a load not measured at a point (NaN in LoadData.measured) is left out of its errors (it gave NaN rms)
    where = {k: (ok & inplane if k == "drag" and inplane.any() else ok) & np.isfinite(data.measured[k]) for k in keys}

    def summary(mask) -> dict:
        out = {}
        for k in keys:
            m = mask & where[k]
            e = (model[k][m] / scale[k][m] - coeff[k][m]) / reference[k][1]
            si = model[k][m] - data.measured[k][m]
            out[k] = ({"rms": float(np.sqrt(np.mean(e**2))), "bias": float(np.mean(e)), "max": float(np.max(np.abs(e))),
                       "rms_si": float(np.sqrt(np.mean(si**2))), "n": int(m.sum())} if m.any() else
                      {"rms": None, "bias": None, "max": None, "rms_si": None, "n": 0})
        return out

    everything = np.ones(data.n, bool)
    groups = {str(g): summary(data.group == g) for g in dict.fromkeys(data.group)} if len(set(data.group)) > 1 else {}
    # by the model's working state, where the data reach beyond normal working (descent: where momentum theory is
    # not predictive, the vortex ring and the turbulent wake, a descent audit asked to see the errors apart)
    names = r.state_name
    states = ({str(s): summary(ok & (names == s)) for s in STATES if np.any(ok & (names == s))}
              if np.any(ok & (names != STATES[0])) else {})
    return {"reference": reference, "overall": summary(everything), "groups": groups, "states": states,
            "n_points": data.n, "converged": int(np.sum(r.converged))}
