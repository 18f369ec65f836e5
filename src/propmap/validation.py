"""The model against a catalogue propeller's measurements (UIUC static runs and J-sweeps).

Compares (a) the full model of Gill & D'Andrea (2017) and (b) the hover model
T = k_T Omega^2 calibrated on the MEASURED static CT and CP (mean over the static runs),
as in the paper's Fig. 7. Measurements: UIUC Propeller Data Site vol. 1 (Brandt & Selig,
AIAA 2011-1255).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .core.airfoil import Air, AirfoilParams
from .core.geometry import Propeller
from .core.solver import DEFAULT_DISCRETIZATION, Discretization, rotor_loads
from .io.catalogue import CatalogueEntry

__all__ = ["SweepComparison", "Validation", "validate"]


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
        """RMSE and max |error| of CT and CP for ``which`` in {"model", "hover_model"}."""
        ct = self.CT_model if which == "model" else self.CT_hover
        cp = self.CP_model if which == "model" else self.CP_hover
        return _errors(ct - self.CT, cp - self.CP)


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
    """Result of :func:`validate`."""

    propeller: str
    runs: list[SweepComparison]
    CT_hover: float
    CP_hover: float
    citation: str
    params: dict = field(default_factory=dict)

    def summary(self, which: str, run_ids=None) -> dict:
        """Errors pooled over the measured points, for "model" or "hover_model".

        ``run_ids`` (optional): pool only the runs with these ids (e.g. held-out sweeps).
        """
        runs = [r for r in self.runs if run_ids is None or r.run_id in set(run_ids)]
        ct = np.concatenate([(r.CT_model if which == "model" else r.CT_hover) - r.CT for r in runs])
        cp = np.concatenate([(r.CP_model if which == "model" else r.CP_hover) - r.CP for r in runs])
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


def validate(entry: CatalogueEntry, propeller: Propeller, params: AirfoilParams, *, air: Air = Air(),
             discretization: Discretization = DEFAULT_DISCRETIZATION) -> Validation:
    """Compare the model and the hover model with every bundled measurement of ``entry``.

    Parameters
    ----------
    entry : CatalogueEntry
        Gives the measurements (UIUC static runs and J-sweeps).
    propeller : Propeller
        The geometry to use (normally ``load_propeller(entry.name)``).
    params : AirfoilParams
    air : Air
        Density used to convert coefficients; UIUC coefficients are density-normalised,
        so air only enters through the Reynolds term.

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
    return Validation(entry.name, runs, CT_h, CP_h, entry.citation,
                      params={"cl1": params.cl1, "cl2": params.cl2, "cd": params.cd,
                              "alpha0_deg": math.degrees(params.alpha0)})


def holdout_comparison(entry: CatalogueEntry, propeller: Propeller, fitted: AirfoilParams, baseline: AirfoilParams,
                       holdout, *, air: Air = Air(), discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """Held-out CT and CP errors of a fitted model, a baseline parameter set and the hover model.

    The hover model uses the measured static CT and CP. ``holdout`` names UIUC run ids.

    Returns
    -------
    dict
        ``{"holdout": [...], "fitted": {...}, "baseline": {...}, "hover_model": {...}}``, each
        error dict as :meth:`Validation.summary` pooled over the held-out runs, plus
        ``"validation_fitted"`` and ``"validation_baseline"`` (:class:`Validation`) for figures.
    """
    vf = validate(entry, propeller, fitted, air=air, discretization=discretization)
    vb = validate(entry, propeller, baseline, air=air, discretization=discretization)
    held = sorted(set(holdout))
    return {"holdout": held, "fitted": vf.summary("model", held), "baseline": vb.summary("model", held),
            "hover_model": vf.summary("hover_model", held), "validation_fitted": vf, "validation_baseline": vb}
