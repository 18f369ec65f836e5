"""Figures (matplotlib, imported lazily so the core never depends on it)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .io.atomic import atomic_write

__all__ = ["plot_validation", "plot_envelope"]


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig, path) -> Path:
    path = Path(path)
    with atomic_write(path, "wb") as fh:
        fig.savefig(fh, format="png", dpi=120)
    _pyplot().close(fig)
    return path


def plot_validation(validation, path, *, title: str = "") -> Path:
    """CT and CP against J: measured (markers), model (lines), hover model (dashed).

    Like Fig. 7 of Gill & D'Andrea (2017), for axial J-sweeps (static runs at J = 0).
    Writes a PNG atomically and returns its path.
    """
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, run in enumerate(validation.runs):
        c = colors[k % len(colors)]
        for ax, meas, mod in ((axes[0], run.CT, run.CT_model), (axes[1], run.CP, run.CP_model)):
            if run.kind == "static":
                ax.plot(run.J, meas, "s", color=c, ms=4, mfc="none", label=f"{run.label} (measured)")
                ax.plot(run.J, mod, "x", color=c, ms=5)
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
    fig.suptitle((title or f"{validation.propeller}: model vs measured") + "\nData: " + validation.citation,
                 fontsize=9)
    return _save(fig, path)


def plot_envelope(table, path, *, title: str = "") -> Path:
    """Thrust and drag vs airspeed for several incidences, model beside the hover model.

    ``table`` is a pandas DataFrame with columns airspeed, incidence_deg, thrust, drag,
    thrust_hover (one rpm). Writes a PNG atomically.
    """
    plt = _pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2), constrained_layout=True)
    for inc, g in table.groupby("incidence_deg"):
        g = g.sort_values("airspeed")
        line, = axes[0].plot(g.airspeed, g.thrust, "-", label=f"incidence {inc:g} deg")
        axes[1].plot(g.airspeed, g.drag, "-", color=line.get_color())
        axes[2].plot(g.airspeed, 100 * (g.thrust_hover - g.thrust) / g.thrust.abs().max(), "-",
                     color=line.get_color())
    axes[0].axhline(float(table.thrust_hover.iloc[0]), color="k", ls="--", lw=1, label="hover model T = k_T Omega^2")
    axes[0].set_ylabel("thrust T [N]")
    axes[1].set_ylabel("rotor drag D [N] (hover model: 0)")
    axes[2].set_ylabel("hover-model thrust error [% of max T]")
    for ax in axes:
        ax.set_xlabel("airspeed V [m/s]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(title, fontsize=9)
    return _save(fig, path)
