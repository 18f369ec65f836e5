"""Figures (matplotlib, imported lazily so the core never depends on it).

Each figure is drawn on its own Agg canvas, not through ``matplotlib.pyplot``: drawing one
neither selects nor changes the session's backend and leaves no figure open, also where the
drawing or the writing fails. A figure's format is its file's extension (.png, .pdf, .svg).
The flight figures are in :mod:`propmap.plots_flight`.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from .core._numbers import checked
from .io.atomic import atomic_write, check_file_name
from .io.inputs import as_path

__all__ = ["require_matplotlib", "plot_validation", "plot_envelope", "plot_load_fit", "plot_load_parity",
           "plot_cv_summary", "plot_cases", "plot_map_contours"]


def require_matplotlib():
    """matplotlib, imported; a clear error where the environment keeps it from importing.

    propmap draws on matplotlib's Agg canvas directly (:class:`matplotlib.figure.Figure`), not
    through ``matplotlib.pyplot``: it neither selects nor changes the session's backend, and
    keeps no figure open. The CLI calls this before a command's work where a figure is asked
    for, so that such an error comes before any output is written.

    Returns
    -------
    module
        ``matplotlib``.

    Raises
    ------
    ValueError
        Where ``import matplotlib`` refuses the environment variable ``MPLBACKEND`` (a name
        matplotlib does not know): the error names the variable and its value.
    """
    try:
        import matplotlib
    except ValueError:  # (matplotlib validates $MPLBACKEND on import, an audit, stop 102)
        backend = os.environ.get("MPLBACKEND")
        if backend is None:
            raise
        raise ValueError(f"the environment variable MPLBACKEND={backend!r} is not a matplotlib backend, so "
                         "matplotlib does not import: unset it or name one (propmap's figures need none)") from None
    return matplotlib


def _figure(nrows: int, ncols: int, figsize, **subplots):
    """A new figure on its own Agg canvas and its axes (``Figure.subplots``): no pyplot state."""
    require_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, layout="constrained")
    FigureCanvasAgg(fig)
    return fig, fig.subplots(nrows, ncols, **subplots)


def _colors() -> list:
    """The colour cycle of the session's matplotlib style."""
    return require_matplotlib().rcParams["axes.prop_cycle"].by_key()["color"]


#: figure formats by file extension (any other is refused)
FIGURE_FORMATS = ("png", "pdf", "svg")


def _format(path) -> str:
    """The figure format of ``path`` by its extension; ValueError for an extension that is not
    one of :data:`FIGURE_FORMATS` (a ``.jpg`` got PNG bytes under its name until stop 104), a path
    that names no file or a folder (found after drawing until then), TypeError for a path that
    is not one (pathlib's words, naming nothing, until then)."""
    p = as_path(path, "path")
    check_file_name(path)  # (the path as given: a Path drops a trailing separator, "new.png/")
    if p.is_dir():
        raise ValueError(f"path {os.fspath(path)!r:.200} is a folder: give the figure's file")
    fmt = p.suffix.lower().lstrip(".")
    if fmt not in FIGURE_FORMATS:
        raise ValueError(f"path {str(path)!r:.200}: a figure's extension gives its format, one of "
                         f"{', '.join('.' + f for f in FIGURE_FORMATS)}; got {('.' + fmt) if fmt else 'none'}")
    return fmt


def _save(fig, path) -> Path:
    path = Path(path)
    with atomic_write(path, "wb") as fh:
        fig.savefig(fh, format=_format(path), dpi=120)
    return path


def plot_validation(validation, path, *, title: str = "") -> Path:
    """CT and CP against J: measured (markers), model (lines), hover model (dashed).

    Like Fig. 7 of Gill & D'Andrea (2017), for axial J-sweeps (static runs at J = 0).
    Writes the figure atomically (its format by ``path``'s extension) and returns its path.

    Parameters
    ----------
    validation : Validation
        :func:`propmap.validation.validate`'s result: each run's J, measured and modelled
        CT and CP, the hover model's CT and CP, the propeller's name and the data's citation.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str
        Default ``"<propeller>: model vs measured"``; the data's citation is added below it
        unless it holds ``"Data:"``.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing).
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    _format(path)
    fig, axes = _figure(1, 2, (11, 4.2))
    colors = _colors()
    for k, run in enumerate(validation.runs):
        c = colors[k % len(colors)]
        for ax, meas, mod in ((axes[0], run.CT, run.CT_model), (axes[1], run.CP, run.CP_model)):
            if run.kind == "static":
                ax.plot(run.J, meas, "s", color=c, ms=4, mfc="none", label=f"{run.label} (measured)")
                ax.plot(run.J, mod, "x", color=c, ms=5, label=f"{run.label} (model)")
            else:
                order = np.argsort(run.J)
                ax.plot(run.J, meas, "o", color=c, ms=4, label=f"{run.label} (measured)")
                ax.plot(run.J[order], mod[order], "-", color=c, lw=1.2)
    for ax, h, name in ((axes[0], validation.CT_hover, "CT"), (axes[1], validation.CP_hover, "CP")):
        ax.axhline(h, color="k", ls="--", lw=1, label="hover model (measured static)")
        ax.plot([], [], "-", color="gray", label="BET+BEMT model")
        ax.set_xlabel("J = V/(n D)")
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7, loc="lower left")
    # the data's citation once, under the title (a title that already cites the data is kept as given)
    title = title or f"{validation.propeller}: model vs measured"
    fig.suptitle(title if "Data:" in title else title + "\nData: " + validation.citation, fontsize=9)
    return _save(fig, path)


def plot_envelope(table, path, *, title: str = "") -> Path:
    """Thrust and drag vs airspeed for several incidences, model beside the hover model.

    ``table`` is a pandas DataFrame with columns airspeed, incidence_deg, thrust, drag,
    thrust_hover (one rpm). Writes the figure atomically (its format by the extension).

    Parameters
    ----------
    table : pandas.DataFrame
        One row per (airspeed [m/s], incidence_deg [deg]) at one rpm: ``thrust``, ``drag``
        and the hover model's ``thrust_hover`` [N] (as ``propmap demo`` makes it);
        one curve per incidence, the hover-model error in % of the largest
        ``|thrust_hover|``.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    TypeError
        ``path`` neither a str nor an os.PathLike.
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing), or where a column is missing, no row has a finite thrust
        (nothing to draw) or the largest ``|thrust_hover|`` is 0 or not finite.
    """
    _format(path)
    missing = [c for c in ("airspeed", "incidence_deg", "thrust", "drag", "thrust_hover") if c not in table]
    if missing:
        raise ValueError(f"table: no column {', '.join(missing)} (plot_envelope draws propmap demo's envelope table)")
    if not np.isfinite(np.asarray(table["thrust"], float)).any():  # (empty panels were written, stop 102)
        raise ValueError(f"table: no finite thrust among its {len(table)} rows: nothing to draw")
    T_hover = float(table.thrust_hover.abs().max())  # one scale for every curve (the rpm's hover thrust)
    if not (math.isfinite(T_hover) and T_hover > 0):  # (its panel was inf or empty, stop 104)
        raise ValueError(f"table: the largest |thrust_hover| must be finite and > 0, got {T_hover}: the hover "
                         "model's error panel has no scale")
    fig, axes = _figure(1, 3, (14, 4.2))
    for inc, g in table.groupby("incidence_deg"):
        g = g.sort_values("airspeed")
        line, = axes[0].plot(g.airspeed, g.thrust, "-", label=f"incidence {inc:g} deg")
        axes[1].plot(g.airspeed, g.drag, "-", color=line.get_color())
        axes[2].plot(g.airspeed, 100 * (g.thrust_hover - g.thrust) / T_hover, "-", color=line.get_color())
    axes[0].axhline(float(table.thrust_hover.iloc[0]), color="k", ls="--", lw=1, label="hover model T = k_T Omega^2")
    axes[0].set_ylabel("thrust T [N]")
    axes[1].set_ylabel("rotor drag D [N] (hover model: 0)")
    axes[2].set_ylabel("hover-model thrust error [% of hover T]")
    for ax in axes:
        ax.set_xlabel("airspeed V [m/s]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(title, fontsize=9)
    return _save(fig, path)


def plot_load_fit(runs_fitted, runs_baseline, holdout, path, *, title: str = "",
                  baseline_label: str = "Table I") -> Path:
    """Like Fig. 7 of Gill & D'Andrea (2017) for a load fit: CT and CP vs J, measured
    (filled: used in the fit, open: held out), fitted model (solid), baseline parameters
    (dotted) and the hover model (dashed).

    Parameters
    ----------
    runs_fitted, runs_baseline : list of SweepComparison
        The same runs (static and J-sweeps, in one order) evaluated with the fitted and with
        the baseline parameters: J, measured and modelled CT and CP, the hover model's.
    holdout : set of str
        The run ids held out of the fit (drawn with open markers).
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str
    baseline_label : str
        The baseline parameters' name in the legend.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing); the two lists not the same runs in one order or empty;
        ``holdout`` not a set of run ids.
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    _format(path)
    runs_fitted, runs_baseline = list(runs_fitted), list(runs_baseline)
    # ([] met an IndexError, a shorter baseline was cut to it, a str holdout matched as a substring, stop 104)
    ids = [[r.run_id for r in runs] for runs in (runs_fitted, runs_baseline)]
    if not runs_fitted or ids[0] != ids[1]:
        raise ValueError(f"runs_fitted and runs_baseline must be the same runs in one order, at least one; got "
                         f"{len(runs_fitted)} and {len(runs_baseline)} runs ({', '.join(ids[0][:4])}; "
                         f"{', '.join(ids[1][:4])})")
    ids_given = hasattr(holdout, "__iter__") and not isinstance(holdout, (str, bytes))
    if not ids_given or not all(isinstance(h, str) for h in holdout):
        raise ValueError(f"holdout must be a set of run ids (str), got {holdout!r:.60}")
    fig, axes = _figure(1, 2, (11, 4.2))
    colors = _colors()
    for k, (rf, rb) in enumerate(zip(runs_fitted, runs_baseline)):
        c = colors[k % len(colors)]
        held = rf.run_id in holdout
        o = np.argsort(rf.J)
        for ax, meas, fit, bl in ((axes[0], rf.CT, rf.CT_model, rb.CT_model),
                                  (axes[1], rf.CP, rf.CP_model, rb.CP_model)):
            ax.plot(rf.J, meas, "o", color=c, ms=4, mfc="none" if held else c,
                    label=f"{rf.label}{' (held out)' if held else ''}")
            style = "x" if rf.kind == "static" else "-"
            ax.plot(rf.J[o], fit[o], style, color=c, lw=1.3)
            ax.plot(rf.J[o], bl[o], ":" if rf.kind != "static" else "+", color=c, lw=1)
    for ax, h, name in ((axes[0], runs_fitted[0].CT_hover[0], "CT"), (axes[1], runs_fitted[0].CP_hover[0], "CP")):
        ax.axhline(h, color="k", ls="--", lw=1, label="hover model")
        ax.plot([], [], "-", color="gray", label="fitted model")
        ax.plot([], [], ":", color="gray", label=f"{baseline_label} parameters")
        ax.set_xlabel("J = V/(n D)")
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=6.5, loc="lower left")
    fig.suptitle(title, fontsize=9)
    return _save(fig, path)


def plot_load_parity(data, model: dict, held_mask, path, *, title: str = "") -> Path:
    """Measured vs modelled loads, one panel per measured quantity (open markers: held out).

    Parameters
    ----------
    data : LoadData
        The measurements: ``measured`` maps a quantity (thrust, drag [N], torque,
        rolling_moment [N m]) to shape (N,).
    model : dict
        Label (e.g. "fitted", "gill2017-apc") -> {quantity -> the model's values, shape (N,)}.
    held_mask : array_like of bool, shape (N,)
        The points held out of the fit.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing); ``held_mask`` not booleans of shape (N,); ``model``
        empty or without a measured quantity.
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    _format(path)
    keys = list(data.measured)
    n = len(data.measured[keys[0]]) if keys else 0
    from .identify._checks import boolean_mask  # (here: identify imports the solver, numba and SciPy)

    held_mask = boolean_mask("plot_load_parity", held_mask, n, "held_mask")  # (a list met "unary ~", stop 104)
    missing = [k for m in model.values() for k in keys if k not in m]
    if not model or missing or not keys:  # (an empty figure was written, stop 104)
        raise ValueError(f"model: give label -> loads with each measured one ({', '.join(keys) or 'none measured'})"
                         f"; got {len(model)} sets{', missing ' + ', '.join(sorted(set(missing))) if missing else ''}")
    fig, axes = _figure(1, len(keys), (4.5 * len(keys), 4), squeeze=False)
    units = {"thrust": "N", "drag": "N", "torque": "N m", "rolling_moment": "N m"}
    for ax, k in zip(axes[0], keys):
        meas = data.measured[k]
        for label, m in model.items():
            line, = ax.plot(meas[~held_mask], m[k][~held_mask], "o", ms=4, label=label)
            ax.plot(meas[held_mask], m[k][held_mask], "o", ms=4, mfc="none", color=line.get_color())
        lim = [min(meas.min(), 0), meas.max() * 1.05]
        ax.plot(lim, lim, "k-", lw=0.8)
        ax.set_xlabel(f"measured {k} [{units[k]}]")
        ax.set_ylabel(f"model {k} [{units[k]}]")
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    # (said only where points are held out: a fit of every point said it too, a new-user audit)
    fig.suptitle(title + (" (open markers: held out)" if np.any(held_mask) else ""), fontsize=9)
    return _save(fig, path)


def plot_cv_summary(catalogue_result: dict, path, *, title: str = "") -> Path:
    """Cumulative distributions over the propellers of the held-out errors of each protocol.

    ``catalogue_result`` as returned by ``cli.validate_all.run_catalogue``. Writes the figure
    atomically and returns its path.

    Parameters
    ----------
    catalogue_result : dict
        Its ``summary`` keys (the protocols) each give a curve, from the ``rms_ct`` and
        ``rms_cp`` (fractions) of that key in every row of ``propellers``; a row without the
        key, or with None there (a propeller the protocol did not score), is left out.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str
        Default: the number of propellers and the citations of the UIUC volumes and APC's
        geometry.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing); no rms error to draw, or one not finite
        and positive (the axes are logarithmic).
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    _format(path)
    require_matplotlib()
    from matplotlib import ticker

    from .io.catalogue import APC_CITATION, UIUC_CITATION, UIUC_V2_CITATION

    rows = catalogue_result["propellers"]
    # (a propeller a protocol did not score, None, is left out of its curve, an audit, stop 102)
    curves = {(key, q): np.sort([100 * r[key][q] for r in rows if r.get(key) and r[key].get(q) is not None])
              for key in catalogue_result["summary"] for q in ("rms_ct", "rms_cp")}
    bad = sum(int(np.sum(~(np.isfinite(v) & (v > 0)))) for v in curves.values())
    if bad or not any(v.size for v in curves.values()):  # (an empty figure or a log axis' nothing, stop 104)
        raise ValueError(f"catalogue_result: {bad} rms errors not finite and positive (a log axis), among "
                         f"{sum(v.size for v in curves.values())}: give finite rms > 0 of at least one propeller")
    fig, axes = _figure(1, 2, (11, 4.2))
    for key in catalogue_result["summary"]:
        for ax, q in zip(axes, ("rms_ct", "rms_cp")):
            v = curves[key, q]
            ax.step(v, np.arange(1, v.size + 1) / v.size, where="post", label=key)
    for ax, q in zip(axes, ("|dCT| / static CT", "|dCP| / static CP")):
        ax.set_xlabel(f"rms {q} on held-out data [%]")
        ax.set_ylabel("fraction of propellers")
        ax.set_xscale("log")
        # (plain numbers, the minor ticks labelled sparsely within a decade: a few propellers' 2-9% ran the
        # default's 2x10^0 3x10^0 ... into each other, an audit, stop 100)
        ax.xaxis.set_major_formatter(ticker.FuncFormatter(lambda x, _: f"{x:g}"))
        ax.xaxis.set_minor_formatter(ticker.LogFormatter(labelOnlyBase=False, minor_thresholds=(1, 0.4)))
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    # (APC's geometry cited too, as the report and the table cite it: 29 propellers take it, an audit, stop 100)
    fig.suptitle(title or f"propmap cross-validation over {len(rows)} catalogue propellers\n"
                          f"Data: {UIUC_CITATION}; {UIUC_V2_CITATION}; geometry: {APC_CITATION} where UIUC has none",
                 fontsize=9)
    return _save(fig, path)


def _wrap(text: str, width: int = 60) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(text, width))


def plot_cases(cases: dict, path) -> Path:
    """The published cases (cases.run_case results): measured points, model lines; gill2019's
    H-force slopes as bars.

    Parameters
    ----------
    cases : dict
        Case name -> :class:`propmap.cases.CaseResult`; ``"apc10x7e"``, ``"dji9443"``,
        ``"beaver"`` and ``"gill2019"`` are drawn (a panel left empty where one is absent),
        other keys ignored.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing); ``cases`` without one of the
        four cases drawn.
    TypeError
        ``path`` neither a str nor an os.PathLike; ``cases`` not a dict.
    """
    _format(path)
    if not isinstance(cases, dict):
        raise TypeError(f"cases must be a dict of case name -> CaseResult, got {type(cases).__name__}")
    if not {"apc10x7e", "dji9443", "beaver", "gill2019"} & set(cases):  # (an empty figure was written, stop 104)
        raise ValueError(f"cases: none of apc10x7e, dji9443, beaver, gill2019 among {sorted(map(str, cases))[:6]}: "
                         "nothing to draw")
    fig, axes = _figure(1, 5, (21, 4.2))
    a = cases.get("apc10x7e")
    if a is not None:
        for ax, q in zip(axes[:2], ("CT", "CQ")):
            ax.plot(a.x, a.measured[q], "ko", ms=4, label="measured")
            for label, pred in a.predicted.items():
                ax.plot(a.x, pred[q], "--" if label == "hover model" else "-", label=label)
            ax.set_xlabel("J")
            ax.set_ylabel(q)
            ax.set_title(_wrap(f"APC 10x7E, {a.notes.split(';')[0]}. {a.citation}"), fontsize=7)
        axes[0].legend(fontsize=7)
    d = cases.get("dji9443")
    if d is not None:
        labels = ["measured", *d.predicted]
        values = [float(d.measured["CT"][0]), *(float(p["CT"][0]) for p in d.predicted.values())]
        axes[2].bar(range(len(values)), values, color=["k"] + ["C0", "C1", "C2"][: len(values) - 1])
        axes[2].errorbar([0], [values[0]], yerr=[0.0018], color="r", capsize=4)
        axes[2].set_xticks(range(len(values)), labels, fontsize=7, rotation=15)
        axes[2].set_ylabel("hover CT")
        axes[2].set_title(_wrap(f"DJI 9443 at 5400 rpm. {d.citation}"), fontsize=7)
    b = cases.get("beaver")
    if b is not None:
        axes[3].plot(b.x, b.measured["CT"], "ko", ms=4, label="measured")
        for label, pred in b.predicted.items():
            axes[3].plot(b.x, pred["CT"], "--" if label == "hover model" else "-", label=label)
        axes[3].set_xlabel("incidence [deg]")
        axes[3].set_ylabel("CT")
        axes[3].set_title(_wrap(f"Beaver propeller, {b.notes.split(' (')[0]}. {b.citation}"), fontsize=7)
        axes[3].legend(fontsize=7)
    g = cases.get("gill2019")
    if g is not None:
        from .cases import gill2019_coefficients

        names = list(gill2019_coefficients())  # x indexes them, in this order
        width = 0.8 / (1 + len(g.predicted))
        axes[4].bar(g.x - 0.4 + width / 2, g.measured["H_slope"], width, color="k", label="measured (fit)")
        for k, (label, pred) in enumerate(g.predicted.items()):
            axes[4].bar(g.x - 0.4 + (k + 1.5) * width, pred["H_slope"], width, label=label)
        axes[4].set_xticks(g.x, names, fontsize=7, rotation=15)
        axes[4].set_ylabel("dC_H/dmu / CT_static")
        axes[4].set_title(_wrap(f"In-plane H-force slope in oblique flow. {g.citation}"), fontsize=7)
        axes[4].legend(fontsize=7)
    return _save(fig, path)


def plot_map_contours(ds, rpm: float, path, *, title: str = "") -> Path:
    """Contours of a rotor map at the grid rpm nearest ``rpm``: T, D, Q, and the hover
    model's thrust error T_hover - T (T_hover: the map's static thrust at that rpm), over
    (airspeed, incidence), with the flagged nodes (vortex ring, multiple roots, not converged)
    hatched.

    Parameters
    ----------
    ds : xarray.Dataset
        A map (propmap.maps.build_map) with at least two airspeed and two incidence nodes.
        The hover-model panel is drawn only where its airspeed axis has a node at 0 m/s (the
        static thrust); a map whose axis starts above 0 gets the other three panels.
    rpm : float
        [rpm]; the nearest grid row is drawn.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    TypeError
        ``path`` neither a str nor an os.PathLike; ``ds`` neither a map's Dataset nor a RotorMap.
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing); ``rpm`` not a number within the map's rpm axis; the map
        has fewer than two airspeed or incidence nodes or no finite thrust at that rpm (no
        contour to draw).
    """
    _format(path)
    ds = getattr(ds, "dataset", ds)  # (a RotorMap's: AttributeError 'sel' until stop 104)
    if not all(hasattr(ds, a) for a in ("sel", "data_vars")) or "rpm" not in getattr(ds, "coords", ()):
        raise TypeError(f"ds must be a map (an xarray Dataset of propmap.maps.build_map, or a RotorMap), got "
                        f"{type(ds).__name__}")
    axis = np.asarray(ds["rpm"].values, float)
    # (None met xarray's KeyError, -5 and inf drew the nearest row without a word, stop 104; the axis' ends to
    # round-off, a node given in rpm and stored through rad/s)
    rpm = checked("rpm", rpm, 0.0, low_open=True, unit="rpm")
    if not axis.min() * (1 - 1e-9) <= rpm <= axis.max() * (1 + 1e-9):
        raise ValueError(f"rpm must lie within the map's rpm axis [{axis.min():g}, {axis.max():g}], got {rpm:g}")
    row = ds.sel(rpm=rpm, method="nearest")
    V = row["airspeed"].values
    inc = row["incidence_deg"].values
    if V.size < 2 or inc.size < 2:
        raise ValueError(f"a contour figure needs at least two airspeed and two incidence nodes; the map has "
                         f"{V.size} and {inc.size}")
    if not np.isfinite(row["thrust"].values).any():  # (an empty figure was written, stop 104)
        raise ValueError(f"the map has no finite thrust at {float(row['rpm']):.6g} rpm: nothing to draw")
    panels = [("thrust", row["thrust"].values, "thrust T [N]"), ("drag", row["drag"].values, "rotor drag D [N]"),
              ("torque", row["torque"].values, "torque Q [N m]")]
    # the hover model's static thrust is the map's at 0 m/s: where the axis has no such node the panel is left
    # out (the nearest node, 5 m/s of an axis 5:15, drew its own error as 0, an audit, stop 102)
    static = np.flatnonzero(V == 0.0)
    if static.size:
        t_static = float(row["thrust"].sel(airspeed=0.0).values.flat[0])
        panels.append(("hover", t_static - row["thrust"].values, "hover model error T_hover - T [N]"))
    flagged = (row["vortex_ring"].values | row["multiple_roots"].values | ~row["converged"].values).astype(float)
    fig, axes = _figure(1, len(panels), (4.5 * len(panels), 4.2))
    for ax, (key, z, label) in zip(axes, panels):
        cmap = "RdBu_r" if key == "hover" else "viridis"
        lim = np.nanmax(np.abs(z)) if key == "hover" else None
        cs = ax.contourf(inc, V, z, levels=21, cmap=cmap, vmin=-lim if lim else None, vmax=lim)
        fig.colorbar(cs, ax=ax, label=label)
        if flagged.any():
            ax.contourf(inc, V, flagged, levels=[0.5, 1.5], colors="none", hatches=["//"])
        ax.set_xlabel("incidence [deg] (0 climb, 90 edgewise, 180 descent)")
        ax.set_ylabel("airspeed V [m/s]")
    # (wrapped to the figure's width, the note on its own line: the three panels' figure cut both, a review)
    lines = _wrap(f"{title} at {float(row['rpm']):.0f} rpm (hatched: vortex ring, multiple roots or not converged)",
                  int(12 * fig.get_size_inches()[0]))
    if not static.size:
        lines += f"\nno hover-model panel: the airspeed axis starts at {V.min():g} m/s"
    fig.suptitle(lines, fontsize=9)
    return _save(fig, path)
