"""One parameter set fitted to several propellers' load measurements at once
(:func:`fit_loads_joint`): each propeller's residuals are :func:`propmap.identify.fit_loads`'s
(identify/fit.py), weighted so that every propeller counts by its weight whatever its number
of points, and solved by the one fitting engine (identify/engine.py). This is how the
catalogue's ``generic`` set is made (tools/calibrate_catalogue.py).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..core.airfoil import Air, SectionParams
from .continuation import _fit_with_continuation
from .dependence import lag1_autocorrelation
from .engine import _attach_jacobian, _finish, _m_effect, _with_prior, _x0
from .fit import POOR_FIT, _check_fit_args, _fitted_rows, _load_keys, _load_residual, _poor_fit
from .load_data import data_air
from .options import FitOptions, _default_names, refuse_unused_options
from .result import FitResult

__all__ = ["fit_loads_joint"]


def fit_loads_joint(datasets, *, base: SectionParams | None = None, air: Air | None = None,
                    options: FitOptions = FitOptions(), weights=None) -> FitResult:
    """One parameter set fitted to the load measurements of several propellers at once.

    Each propeller's residuals (as :func:`fit_loads`, all measured quantities) are
    weighted by sqrt(w N / (W n)), n its number of points, N the points of all, W the sum of
    the weights, so that every propeller counts in proportion to its weight w whatever its
    number of measurements (alike by default), and the data together as their N points
    count in :func:`fit_loads`: against the population prior too, so that one data set is
    :func:`fit_loads`'s fit whatever its weight (until 2026-12-01 the weights were sqrt(w / n)
    and the prior n times as strong by default: an API audit). This is how the catalogue's
    ``generic`` set is made (tools/calibrate_catalogue.py; without the prior, where a common
    factor on the residuals changes nothing).

    Parameters
    ----------
    datasets : sequence of (LoadData, Propeller)
    base, air, options
        As :func:`fit_loads`, except that the parameters fitted are ``options.names`` or the
        model's full default (the cambered CAMBERED_FIT_RE), whatever the data: no fit along
        the data's directions and no flapping freed for data at incidence. The population
        prior applies where ``options.prior`` (the calibration fits without it). Without
        ``air``, each data set is solved at the density it logged (``LoadData.air_density``),
        else at ``base``'s.
    weights : sequence of float, optional
        One positive, finite weight per dataset, its share of the sum of squares (default:
        1 each).

    Returns
    -------
    FitResult
        ``residuals`` stacked over the propellers in order; ``extra["per_propeller"]``
        gives each propeller's name, point count, rms (unweighted) residual and the air
        density it was solved at (``rho``); the result's air is the one every data set was
        solved at, else ``air`` or the base's. As :func:`fit_loads`'s, ``extra`` holds
        ``residual_autocorrelation`` (within each propeller's runs, of its unweighted
        residuals) and ``M_used`` (with ``M_effect`` where the fit's M is not the base's).

    Raises
    ------
    ValueError
        No datasets, ``weights`` not one positive finite number per dataset, no more fitted
        load values than parameters, or as :func:`fit_loads`.
    TypeError
        A dataset that is not a (LoadData, Propeller) pair, or a model argument of the wrong
        type (as :func:`fit_loads`).
    SolverError
        From the rotor model.
    """
    from ..io.calibration import generic_params

    datasets = list(datasets)
    if not datasets:
        raise ValueError("fit_loads_joint needs at least one (data, propeller) pair")
    base = base or generic_params()
    for k, pair in enumerate(datasets):
        if not (isinstance(pair, (tuple, list)) and len(pair) == 2):
            raise TypeError(f"datasets[{k}] must be a (LoadData, Propeller) pair, got {type(pair).__name__}")
        _check_fit_args(*pair, base, air, options, where=f"datasets[{k}]: ")
    refuse_unused_options(options, "fit_loads_joint")
    w = _joint_weights(weights, len(datasets))
    names = _default_names(base, options)
    rows = sum(int(m.sum()) for data, _ in datasets for m in _fitted_rows(data, _load_keys(data, None)).values())
    if rows <= len(names):
        raise ValueError(f"datasets: {rows} fitted load values cannot identify {len(names)} parameters")
    makers, notes, airs = [], [], []
    n_all = sum(data.n for data, _ in datasets)
    share = w / np.max(w)  # (then by its sum: 1e307 and two of 1e308 overflowed w N and W, a review)
    share = share / np.sum(share)
    scale = [math.sqrt(sk * n_all / data.n) for (data, _), sk in zip(datasets, share)]
    for k, ((data, prop), sk) in enumerate(zip(datasets, scale)):
        data_air_k, note = data_air(data, air, base.air)  # (each data set at the density it logged)
        airs.append(data_air_k)
        if note:
            notes.append(f"{prop.name}: {note}")
        try:
            makers.append(_load_residual(data, prop, _load_keys(data, None), data_air_k, names, base, weight=sk)[0])
        except ValueError as exc:
            raise ValueError(f"datasets[{k}] ({prop.name}): {exc}") from None
    # the air recorded with the set: the one every data set was solved at, else the base's (each in per_propeller)
    air = airs[0] if all(a == airs[0] for a in airs) else (base.air if air is None else air)

    def make_data(opts):
        parts = [m(opts) for m in makers]

        def residual(x, opts=opts):
            return np.concatenate([f(x) for f in parts])

        if all(hasattr(f, "with_jacobian") for f in parts):  # each propeller's implicit Jacobian, stacked
            def with_jacobian(x):
                pairs = [f.with_jacobian(x) for f in parts]
                return np.concatenate([r for r, _ in pairs]), np.vstack([J for _, J in pairs])

            _attach_jacobian(residual, with_jacobian)
        return residual

    make_residual, prior = _with_prior(make_data, names, base, options)
    best, log, nfev, elapsed, warns, extra = _fit_with_continuation(make_residual, names, base, options,
                                                                    "fit loads (joint)", _x0(names, options, base))
    result = _finish(names, base, options, best, log, nfev, elapsed, [*notes, *warns],
                     nfev * sum(d.n for d, _ in datasets), air,
                     {"kind": "loads_joint", **extra, **({"prior": prior} if prior else {}),
                      **_m_effect(make_data, best, base, options)})
    result.extra["per_propeller"], r, keys = _per_propeller(best.fun, datasets, scale, airs)
    result.extra["residual_autocorrelation"] = lag1_autocorrelation(r, keys) if r.size else None
    # (fit_loads' poor-fit warning, each propeller's own: a propeller's thrust off by a factor of 10 left its rms
    # residual 0.338 without a word, the weighted headline 0.042: an API audit, stop 100)
    poor = [f"{p['propeller']}: {_poor_fit(p['rms_residual'])}: the model does not describe its data with the "
            "others' set (another geometry, a unit slip?)"
            for p in result.extra["per_propeller"] if p["rms_residual"] > POOR_FIT]
    if poor:
        result = replace(result, warnings=(*poor, *result.warnings))
    return result


def _joint_weights(weights, n: int) -> np.ndarray:
    """:func:`fit_loads_joint`'s ``weights`` as an array of ``n`` (ones where None), refused unless
    ``n`` positive finite numbers."""
    try:
        w = np.ones(n) if weights is None else np.asarray(weights, dtype=float)
    except (TypeError, ValueError):
        w = np.array([np.nan])
    if w.shape != (n,) or not np.all(np.isfinite(w) & (w > 0)):
        raise ValueError(f"weights must be {n} positive finite numbers (one per dataset), got {weights!r:.80}")
    return w


def _per_propeller(fun, datasets, scale, airs) -> tuple[list[dict], np.ndarray, np.ndarray]:
    """Each propeller's share of a joint fit's residuals ``fun`` (unweighted, divided by its
    ``scale``: its rms as its own fit's), its points and the air it was solved at; and the
    residuals with their run keys in each quantity's runs in the data's order, as fit_loads's
    (_traced_residuals), for the lag-1 autocorrelation."""
    per, k, runs, run_keys = [], 0, [], []
    for i, ((data, prop), sk) in enumerate(zip(datasets, scale)):
        keys = _load_keys(data, None)
        rows = _fitted_rows(data, keys)  # (the in-plane force at in-plane points only)
        m = sum(int(v.sum()) for v in rows.values())
        r = fun[k:k + m] / sk
        per.append({"propeller": prop.name, "n_points": data.n, "rms_residual": float(np.sqrt(np.mean(r ** 2))),
                    "rho": airs[len(per)].rho})
        k += m
        key = np.array([f"{i}\x00{q}\x00{data.group[j]}" for q in keys for j in np.flatnonzero(rows[q])])
        order = np.argsort(key, kind="stable")
        runs.append(r[order])
        run_keys.append(key[order])
    return per, np.concatenate(runs), np.concatenate(run_keys)
