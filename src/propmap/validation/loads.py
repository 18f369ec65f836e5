"""Errors in newtons on load data at incidence and a user's own measurements: :func:`holdout_loads`
(held-out fits), :func:`load_errors` (a parameter set against the data).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.airfoil import Air, SectionParams
from ..core.geometry import Propeller
from ..core.solver import DEFAULT_DISCRETIZATION, Discretization, model_air, rotor_loads
from ..core.states import STATES
from ._checks import check_inputs

__all__ = ["holdout_loads", "load_errors"]


def holdout_loads(data, propeller: Propeller, base: SectionParams, folds, *, names=None, population: dict | None = None,
                  air: Air | None = None, quantities=None) -> dict:
    """Held-out errors of fits to load data with thrust, in-plane force and torque.

    Each fold's training points are fitted with :func:`propmap.identify.fit_loads` (from
    ``base``, under ``population``'s prior, ``names`` or the defaults, which free the flapping
    where the data measure the in-plane force at incidence; without the profile likelihood of
    the flapping's interval, which the predictions do not use) and its held-out points predicted.

    Parameters
    ----------
    data : LoadData
        With ``thrust``, ``drag`` and ``torque`` measured, and static points (airspeed up
        to 0.3 m/s).
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
    quantities : tuple of str, optional
        The quantities fitted (as :func:`propmap.identify.fit_loads`; default: every measured
        one); every measured one is scored.

    Returns
    -------
    dict
        ``rms_thrust`` and ``rms_drag`` (of the mean measured static thrust), ``rms_torque``
        (of the static torque) and, where measured, ``rms_rolling_moment`` (of the static
        thrust times R), pooled over the folds' held-out points (the in-plane force and the
        rolling moment where the rotor has an in-plane airspeed, ``LoadData.inplane``); ``flap_compliance``,
        each fold's fitted value [rad/(N m)]; ``n_points``, the held-out points. A load not
        measured at a point (NaN in ``data.measured``) is left out of its figure; one measured
        at no held-out point gives None.

    Raises
    ------
    ValueError
        A quantity not measured, no static point (with thrust and torque measured), no fold
        or an empty one, or as ``fit_loads``.
    SolverError
        From the model.
    TypeError
        ``data`` not a LoadData, ``propeller`` not a Propeller, ``base`` not a parameter set.
    """
    from ..identify import FitOptions, fit_loads
    from ..identify.load_data import INPLANE_KEYS

    check_inputs(propeller, {"base": base}, data=data)
    air = model_air(base, air, name="base")
    if not hasattr(folds, "__iter__") or not (folds := list(folds)):  # ([] met NumPy's "need at least one array")
        raise ValueError(f"folds must be a list of one boolean training mask per fold, at least one, got "
                         f"{folds!r:.60}")
    missing = [k for k in ("thrust", "drag", "torque") if k not in data.measured]
    static = data.static
    if missing or not static.any():
        raise ValueError(f"holdout_loads needs thrust, drag and torque and static points; missing "
                         f"{', '.join(missing) or 'static points'}")
    # the static loads where measured (NaN: not measured at that point)
    T_static, Q_static = (data.measured[k][static & np.isfinite(data.measured[k])] for k in ("thrust", "torque"))
    if not (T_static.size and Q_static.size):
        raise ValueError("holdout_loads needs static points with thrust and torque measured, to normalise by")
    T0, Q0 = float(np.mean(T_static)), float(np.mean(Q_static))
    err = {k: [] for k in ("thrust", "drag", "torque", *(("rolling_moment",) if "rolling_moment" in data.measured
                                                        else ()))}
    scales = {"thrust": T0, "drag": T0, "torque": Q0, "rolling_moment": T0 * propeller.radius}
    compliance = []
    for train in folds:
        train = np.asarray(train, bool)
        if train.all() or not train.any():
            raise ValueError("every fold needs training and held-out points")
        p = fit_loads(data.subset(train), propeller, base=base, air=air, quantities=quantities,
                      options=FitOptions(population=population, names=names, profile_likelihood=False)).params
        compliance.append(float(p.flap_compliance))
        r = rotor_loads(propeller, p, data.omega[~train], data.airspeed[~train], data.incidence[~train], air=air,
                        collective=None if data.collective is None else data.collective[~train])
        inplane = data.inplane[~train]
        for k in err:
            e = (getattr(r, k) - data.measured[k][~train]) / scales[k]
            # the in-plane force where the rotor has an in-plane airspeed, as the fit and load_errors take it (its
            # axial rows' zero errors were counted until 2026-12-01: 0.0079 for 0.0087, a fit-statistics audit)
            err[k].append(e[inplane] if k in INPLANE_KEYS else e)
    out = {}
    for k, v in err.items():
        e = np.concatenate(v)
        e = e[np.isfinite(e)]  # (a load not measured at a point, LoadData's NaN, is left out: it gave a NaN rms)
        out[f"rms_{k}"] = float(np.sqrt(np.mean(e**2))) if e.size else None
    return {**out, "flap_compliance": compliance, "n_points": int(sum(len(v) for v in err["thrust"]))}


def load_errors(data, propeller: Propeller, params: SectionParams, *, air: Air | None = None,
                discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """A parameter set against load measurements, in coefficient form, overall and per group.

    Each measured load is compared as a coefficient, so that every rate weighs alike: thrust
    and in-plane force as F / (rho n^2 D^4), torque and rolling moment as M / (rho n^2 D^5);
    the errors are in units of a reference coefficient: the mean measured static thrust
    coefficient for thrust and in-plane force, half of it for the rolling moment (the static
    thrust times R), and the static torque coefficient for torque (the points at an airspeed
    up to 0.3 m/s), as the catalogue's metric (docs/validation.md), or, without static points,
    the rms of the measured coefficient (the thrust's for the in-plane force, and half of it for
    the rolling moment, where a thrust is measured). The in-plane force and the rolling moment are scored
    where the rotor has an in-plane airspeed above 0.3 m/s (elsewhere model and measurement
    should both be zero; all points where none has one); points where the solver did not
    converge are left out (counted).

    Parameters
    ----------
    data : LoadData
        From :func:`propmap.identify.read_loads` or the UIUC readers; any of thrust, drag
        (the in-plane force), torque, rolling moment measured.
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
    TypeError
        ``data`` not a LoadData, ``propeller`` not a Propeller, ``params`` not a parameter set.
    """
    from ..identify.load_data import INPLANE_KEYS, LOAD_KEYS, data_air

    check_inputs(propeller, {"params": params}, data=data)  # (params=None met 'no attribute air', stop 104)
    air = data_air(data, air, params.air)[0]  # (the density the data logged, where no air is given)
    keys = [k for k in LOAD_KEYS if k in data.measured]
    if not keys:
        raise ValueError("no load measured (thrust, drag, torque or rolling_moment)")
    r = rotor_loads(propeller, params, data.omega, data.airspeed, data.incidence, air=air,
                    discretization=discretization, collective=data.collective, on_failure="flag")
    n = data.omega / (2 * math.pi)
    D = propeller.diameter
    scale = {"thrust": air.rho * n**2 * D**4, "drag": air.rho * n**2 * D**4, "torque": air.rho * n**2 * D**5,
             "rolling_moment": air.rho * n**2 * D**5}
    model = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque, "rolling_moment": r.rolling_moment}
    static = data.static
    coeff = {k: data.measured[k] / scale[k] for k in keys}
    inplane = data.inplane
    reference = {}
    for k in keys:
        own = "thrust" if k in ("thrust", *INPLANE_KEYS) and "thrust" in coeff else k
        known = np.isfinite(coeff[own])  # (NaN: not measured at that point)
        if own in INPLANE_KEYS and inplane.any():  # (without a thrust: its static mean is 0, once 'mean static CQ')
            known &= inplane
        if own not in INPLANE_KEYS and np.any(static & known):
            value, what = float(np.mean(coeff[own][static & known])), f"mean static {'CT' if own == 'thrust' else 'CQ'}"
            if k == "rolling_moment":  # (a moment: of the static thrust times R)
                value, what = value / 2, "mean static CT / 2 (the static thrust times R)"
        else:
            value, what = float(np.sqrt(np.mean(coeff[own][known] ** 2))), f"rms measured {own} coefficient"
            if k == "rolling_moment" and own == "thrust":  # (the thrust times R here too: it was times D)
                value, what = value / 2, "rms measured thrust coefficient / 2 (the thrust times R)"
        if not (math.isfinite(value) and value != 0.0):
            raise ValueError(f"the {what} is {value:g}: no reference for the {k} errors")
        reference[k] = (what, value)

    ok = np.asarray(r.converged, bool) & np.all([np.isfinite(model[k]) for k in keys], axis=0)
    # a load not measured at a point (NaN in LoadData.measured) is left out of its errors (it gave NaN rms)
    where = {k: (ok & inplane if k in INPLANE_KEYS and inplane.any() else ok) & np.isfinite(data.measured[k])
             for k in keys}

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
