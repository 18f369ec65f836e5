"""The delete-a-run jackknife of a load fit (``fit loads --jackknife``): the fit again without
each run, the spread of the estimates as the parameters' jackknife std error
(:func:`propmap.identify.dependence.jackknife_report`; docs/identification.md, A report that tells
the truth).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..core.solver import SolverError
from .fit import fit_loads
from .load_data import LoadData
from .dependence import jackknife_report
from .result import FitResult

__all__ = ["jackknife_loads", "jackknife_runs"]


def jackknife_runs(data: LoadData) -> list:
    """The runs a load fit's jackknife leaves out.

    Every run (``data.group``), or only the sweeps (runs with a point that is not
    ``data.static``) where static runs are in the data too: the static run is not one of a
    kind with them (it alone holds J = 0), and a fit without it is another estimator, not the
    same one on less data (a sweep jackknife of apce_8x6 gives cd_min 0.0033, one leaving the
    static run out too 0.0068, 2026-11-27).

    Parameters
    ----------
    data : LoadData

    Returns
    -------
    list of str
        In the data's order.
    """
    group = np.asarray(data.group)
    runs = list(dict.fromkeys(group.tolist()))
    static = data.static
    moving = [r for r in runs if not np.all(static[group == r])]
    return moving if moving and len(moving) < len(runs) else runs


def jackknife_loads(result: FitResult, data: LoadData, prop, *, base=None, air=None, quantities=None,
                    options=None) -> dict:
    """The jackknife of :func:`propmap.identify.fit_loads`'s fit: the fit again without each of
    :func:`jackknife_runs` (3 or more), with the fit's own arguments.

    The folds fit the fit's parameters (``result.names``) or, where it freed parameter
    directions (``result.extra["directions"]``), as many directions: the same estimator on
    less data (a fold's default names could differ: its data without a run at incidence).

    Parameters
    ----------
    result : FitResult
        ``fit_loads(data, prop, base=base, air=air, quantities=quantities, options=options)``.
    data : LoadData
        The data it was fitted to.
    prop : Propeller
    base, air, quantities, options
        As given to :func:`fit_loads` for ``result``.

    Returns
    -------
    dict
        :func:`propmap.identify.dependence.jackknife_report` with ``by = "run"``; also stored in
        ``result.extra["jackknife"]``, where the report shows it.

    Raises
    ------
    ValueError
        Fewer than 3 runs to leave out, or a fold that cannot be fitted (the message names its
        run).
    SolverError
        From the rotor model.
    """
    from .optimizer import _bounds
    from .options import FitOptions

    runs = jackknife_runs(data)
    if len(runs) < 3:
        raise ValueError(f"the jackknife leaves each fitted run out in turn (the sweeps where static runs are fitted "
                         f"too) and needs at least 3; the data have {len(runs)} "
                         f"({', '.join(map(str, runs)) or 'none'})")
    options = options or FitOptions()
    dirs = result.extra.get("directions")
    fold_options = (replace(options, directions=dirs["count"]) if dirs else
                    replace(options, names=tuple(result.names), directions=None))
    group = np.asarray(data.group)
    folds, bound = [], []
    for run in runs:
        try:
            f = fit_loads(data.subset(group != run), prop, base=base, air=air, quantities=quantities,
                          options=fold_options)
        except (ValueError, SolverError) as exc:
            raise type(exc)(f"the jackknife's fit without run {run} fails: {exc}") from None
        folds.append({n: float(v) for n, v in zip(f.names, f.x)})
        bound.append(f.at_bound)
    result.extra["jackknife"] = report = jackknife_report(result, folds, "run", runs, bound,
                                                          _bounds(result.names, options))
    return report
