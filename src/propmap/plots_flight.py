"""Figures of a vehicle's flight (matplotlib, imported lazily): the level-flight fit and a
flight-log fit against speed and time, after Fig. 6 of Gill & D'Andrea (2017).

Drawn as :mod:`propmap.plots` draws (its own Agg canvas, no pyplot state), through that module's
helpers.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from . import plots

__all__ = ["plot_level_flight_fit", "plot_flight_timeseries", "plot_flight_speed"]

#: the speed figure's largest speed [m/s]: a flight log's velocity components reach 500 m/s each, their norm 866
SPEED_MAX = 1000.0


def plot_level_flight_fit(data, forces, hover_vertical, weight, path, *, title: str = "") -> Path:
    """Like Fig. 6 of Gill & D'Andrea (2017): the model (BET+BEMT) against speed, the hover
    model beside it where it has a value (rotor drag 0, the vertical-force error).

    Panels: collective thrust, collective drag, sum of |torque|, vertical-force error
    (eq 17; the ground truth is 0), pitch.

    Parameters
    ----------
    data : LevelFlightData
        The level-flight samples: ``airspeed`` [m/s] and ``pitch`` [rad], shape (N,).
    forces : dict
        ``level_flight_forces``' result: ``"thrust"``, ``"drag"`` [N] and ``"torque"`` [N m],
        shape (N, n_rotors), and ``"vertical"`` [N], shape (N,).
    hover_vertical : array_like, shape (N,)
        The hover model's vertical force [N].
    weight : float or array_like, shape (N,)
        The vehicle's weight [N].
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
        ``.svg`` (checked before drawing); ``forces``, ``hover_vertical`` or ``weight`` of
        another shape than the samples', or a weight not finite.
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    plots._format(path)
    V = data.airspeed
    n = len(V)
    for key, shape in (("thrust", 2), ("drag", 2), ("torque", 2), ("vertical", 1)):  # (NumPy's AxisError, stop 104)
        got = np.shape(forces.get(key)) if isinstance(forces, dict) and key in forces else None
        if got is None or len(got) != shape or got[0] != n:
            raise ValueError(f"forces[{key!r}] must have shape ({n}{', n_rotors' if shape == 2 else ''}) "
                             f"(level_flight_forces' result), got {got}")
    hover_vertical = np.asarray(hover_vertical, float)
    weight = np.asarray(weight, float)
    if hover_vertical.shape != (n,) or weight.shape not in ((), (n,)) or not np.isfinite(weight).all():
        raise ValueError(f"hover_vertical must have shape ({n},) and weight be finite, of shape () or ({n},); got "
                         f"{hover_vertical.shape} and {weight.shape}")
    o = np.argsort(V)
    fig, axes = plots._figure(1, 5, (17, 3.6))
    T_h = hover_vertical  # hover thrust is vertical-only in level flight up to the tilt
    axes[0].plot(V[o], forces["thrust"].sum(1)[o], "o-", ms=3, label="BET+BEMT")
    axes[0].set_ylabel("collective thrust [N]")
    axes[1].plot(V[o], forces["drag"].sum(1)[o], "o-", ms=3)
    axes[1].axhline(0, color="k", ls="--", lw=1)
    axes[1].set_ylabel("collective rotor drag [N] (hover: 0)")
    axes[2].plot(V[o], np.abs(forces["torque"]).sum(1)[o], "o-", ms=3)
    axes[2].set_ylabel("sum |torque| [N m]")
    axes[3].plot(V[o], (forces["vertical"] - weight)[o], "o-", ms=3, label="BET+BEMT")
    axes[3].plot(V[o], (T_h - weight)[o], "s--", ms=3, label="hover model")
    axes[3].axhline(0, color="r", lw=1, label="ground truth")
    axes[3].set_ylabel("vertical force error (eq 17) [N]")
    axes[3].legend(fontsize=7)
    axes[4].plot(V[o], np.degrees(data.pitch)[o], "o-", ms=3)
    axes[4].set_ylabel("pitch [deg]")
    for ax in axes:
        ax.set_xlabel("V [m/s]")
        ax.grid(alpha=0.3)
    fig.suptitle(title, fontsize=9)
    return plots._save(fig, path)


def plot_flight_timeseries(t_by_log: dict, measured: dict, predicted: dict, path, *, title: str = "",
                           other: dict | None = None) -> Path:
    """Measured against predicted body force over time, one column per log, one row per axis.

    ``t_by_log``, ``measured``, ``predicted``: log name -> time [s] (N,), force [N] (N, 3);
    ``other``: optional label -> {log name -> force (N, 3)} drawn thin (baselines, references).

    Parameters
    ----------
    t_by_log : dict
        Log name -> sample times [s], shape (N,) (N per log); its order gives the columns.
    measured, predicted : dict
        Log name -> body force [N], shape (N, 3) (x, y, z), for every log of ``t_by_log``.
    path : str or Path
        Figure file, written atomically; its extension gives the format: ``.png``, ``.pdf``
        or ``.svg`` (in any case; another is refused).
    title : str
    other : dict, optional
        Label -> {log name -> body force [N], shape (N, 3)}; a log it lacks is skipped.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ValueError
        Where ``path`` names no file or a folder, or its extension is not ``.png``, ``.pdf`` or
        ``.svg`` (checked before drawing); no log in ``t_by_log``, or a log without a measured,
        predicted (or, where ``other`` has it, other) force of shape (N, 3).
    TypeError
        ``path`` neither a str nor an os.PathLike.
    """
    plots._format(path)
    names = list(t_by_log) if isinstance(t_by_log, dict) else []
    # ({} met matplotlib's "Number of columns must be a positive integer", forces of another shape NumPy's
    # IndexError or "x and y must have same first dimension", stop 104)
    for name in names:
        n = np.shape(t_by_log[name])
        for what, forces in (("measured", measured), ("predicted", predicted),
                             *((f"other[{k!r}]", f) for k, f in (other or {}).items() if name in f)):
            if name not in forces or np.shape(forces[name]) != (*n, 3) or len(n) != 1:
                raise ValueError(f"{what}: log {name!r:.60} needs a body force of shape ({n[0] if n else 'N'}, 3), "
                                 f"one row per sample of t_by_log's, got "
                                 f"{np.shape(forces[name]) if name in forces else 'none'}")
    if not names:
        raise ValueError(f"t_by_log must be a dict of at least one log name -> sample times, got {t_by_log!r:.60}")
    fig, axes = plots._figure(3, len(names), (4.2 * len(names), 7), squeeze=False, sharey="row")
    for j, name in enumerate(names):
        t = t_by_log[name]
        for k, axis in enumerate("xyz"):
            ax = axes[k, j]
            ax.plot(t, measured[name][:, k], color="k", lw=1.0, label="measured m a")
            ax.plot(t, predicted[name][:, k], color="C0", lw=1.0, label="propmap")
            for i, (label, forces) in enumerate((other or {}).items()):
                if name in forces:
                    ax.plot(t, forces[name][:, k], lw=0.7, alpha=0.8, color=f"C{i + 1}", label=label)
            ax.set_ylabel(f"F{axis} [N]")
            ax.grid(alpha=0.3)
        axes[0, j].set_title(name, fontsize=8)
        axes[2, j].set_xlabel("t [s]")
    axes[0, 0].legend(fontsize=7)
    import textwrap

    # (wrapped: a vehicle's name with its citation ran off both edges, a citation audit)
    fig.suptitle("\n".join(textwrap.wrap(title, max(40, int(12 * fig.get_size_inches()[0])))), fontsize=9)
    return plots._save(fig, path)


def plot_flight_speed(speed, loads: dict, hover: dict, vertical_error: dict, path, *, title: str = "") -> Path:
    """Like Fig. 6 of Gill & D'Andrea (2017), from flight samples binned by speed.

    ``loads``: "thrust", "drag", "torque" -> (N,) collective rotor thrust, in-plane force
    and sum of |torque| of the fitted model; ``hover``: the hover model's (T = k_T Omega^2,
    D = 0, Q = k_Q Omega^2) same keys; ``vertical_error``: label -> (N,) body-z force error
    (model - measured) [N]. Medians in 1 m/s bins.

    Parameters
    ----------
    speed : array_like, shape (N,)
        Each sample's speed [m/s], finite, in [0, SPEED_MAX] (1000): 1 m/s bins [k, k + 1) from
        0 to the one holding the largest, a bin of fewer than 3 samples left empty (at least one
        must hold 3).
    loads, hover : dict
        ``"thrust"``, ``"drag"`` [N] and ``"torque"`` [N m] -> shape (N,).
    vertical_error : dict
        Label -> body-z force error [N], shape (N,); the first drawn solid, the rest dashed.
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
        ``.svg`` (checked before drawing), or where ``speed`` is empty, holds a value that is not
        finite or outside [0, SPEED_MAX] m/s, or puts fewer than 3 samples in every bin.
    """
    plots._format(path)
    speed = np.asarray(speed, float)
    if speed.size == 0 or not np.isfinite(speed).all():  # ("arange: cannot compute length", stop 102)
        raise ValueError(f"speed: give finite speeds [m/s] of at least one sample, got {speed.size} samples, "
                         f"{int(np.sum(~np.isfinite(speed)))} of them not finite")
    if speed.min() < 0.0 or speed.max() > SPEED_MAX:  # (2e7 m/s drew 2e7 bins for minutes, stop 104)
        raise ValueError(f"speed: give speeds [m/s] in [0, {SPEED_MAX:g}], got {speed.min():.6g} to "
                         f"{speed.max():.6g}")
    # 1 m/s bins [k, k + 1) up to the one holding the largest speed (a largest speed of 2.0 fell in none until stop 104)
    edges = np.arange(0.0, max(np.floor(speed.max()) + 1.0, 1.0) + 1.0, 1.0)
    centre = 0.5 * (edges[1:] + edges[:-1])
    if np.bincount(np.floor(speed).astype(int)).max() < 3:  # (an empty figure was written, stop 104)
        raise ValueError(f"speed: no 1 m/s bin holds the 3 samples a median needs (of {speed.size} samples): "
                         "nothing to draw")

    def binned(y):
        out = np.full(centre.size, np.nan)
        for i in range(centre.size):
            m = (speed >= edges[i]) & (speed < edges[i + 1])
            if m.sum() >= 3:
                out[i] = np.median(np.asarray(y)[m])
        return out

    fig, axes = plots._figure(1, 4, (15, 3.6))
    labels = (("thrust", "collective thrust [N]"), ("drag", "collective in-plane force [N]"),
              ("torque", "sum |torque| [N m]"))
    for ax, (key, ylabel) in zip(axes, labels):
        ax.plot(centre, binned(loads[key]), "o-", ms=3, label="BET+BEMT (fitted)")
        ax.plot(centre, binned(hover[key]), "s--", ms=3, label="hover model")
        ax.set_ylabel(ylabel)
    for i, (label, err) in enumerate(vertical_error.items()):
        axes[3].plot(centre, binned(err), "o-" if i == 0 else "s--", ms=3, label=label)
    axes[3].axhline(0, color="r", lw=1, label="ground truth")
    axes[3].set_ylabel("vertical force error [N] (median)")
    for ax in axes:
        ax.set_xlabel("speed [m/s]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title, fontsize=9)
    return plots._save(fig, path)
