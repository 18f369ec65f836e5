"""A catalogue propeller's measured runs beside the model and the hover model (Fig. 7 of Gill &
D'Andrea 2017): :func:`validate`, :func:`holdout_comparison`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.units import RPM
from ..core.airfoil import Air, SectionParams
from ..core.geometry import Propeller
from ..core.solver import DEFAULT_DISCRETIZATION, Discretization, model_air, rotor_loads
from ..io.catalogue import CatalogueEntry
from ._checks import check_inputs, check_names

__all__ = ["SweepComparison", "Validation", "holdout_comparison", "validate"]


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
            If ``which`` is neither, an id of ``run_ids`` names no run of the propeller, or
            ``run_ids`` is neither one id nor a list of them.
        """
        # (5 met "'int' object is not iterable", stop 104)
        ids = None if run_ids is None else set(check_names("run_ids", [run_ids] if isinstance(run_ids, str)
                                                           else run_ids))
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
        """The JSON form printed by ``propmap validate --json``.

        Returns
        -------
        dict
            ``propeller``, ``citation``, ``params``; ``model`` and ``hover_model``, the error
            summaries (:meth:`summary`; the hover model's with its CT and CP); ``sweeps``, per
            run its kind, id, median rpm, point count, source and both models' errors
            (:meth:`SweepComparison.errors`).
        """
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
    TypeError
        ``entry`` not a CatalogueEntry, ``propeller`` not a Propeller, ``params`` not a
        parameter set.
    """
    check_inputs(propeller, {"params": params}, entry=entry)
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
        om = s.rpm * RPM
        r = rotor_loads(propeller, params, om, 0.0, 0.0, air=air, discretization=discretization)
        runs.append(SweepComparison("static", s.run_id, s.rpm, np.zeros_like(s.rpm), s.CT, s.CP,
                                    r.CT, r.CP, np.full_like(s.CT, CT_h), np.full_like(s.CP, CP_h), s.source))
    for w in sweeps:
        n = w.rpm / 60.0
        r = rotor_loads(propeller, params, w.rpm * RPM, w.J * n * D, 0.0, air=air, discretization=discretization)
        runs.append(SweepComparison("sweep", w.run_id, np.full_like(w.J, w.rpm), w.J, w.CT, w.CP,
                                    r.CT, r.CP, np.full_like(w.CT, CT_h), np.full_like(w.CP, CP_h), w.source))
    from ..io.params_file import params_to_dict

    return Validation(entry.name, runs, CT_h, CP_h, entry.citation, params=params_to_dict(params, air))


def holdout_comparison(entry: CatalogueEntry, propeller: Propeller, fitted: SectionParams, baseline: SectionParams,
                       holdout, *, air: Air | None = None,
                       discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """Held-out CT and CP errors of a fitted model, a baseline parameter set and the hover model.

    The hover model uses the measured static CT and CP.

    Parameters
    ----------
    entry : CatalogueEntry
        Gives the measurements (UIUC static runs and J-sweeps).
    propeller : Propeller
        The geometry to use (normally ``load_propeller(entry.name)``).
    fitted, baseline : AirfoilParams or CamberedParams
        The fitted set and the set it is compared with (e.g. the generic set).
    holdout : str or iterable of str
        The UIUC run ids whose errors are pooled (the runs the fit did not see), at least one;
        duplicates are read once.
    air : Air, optional
        Default: the fitted set's own (``.air``); used for both sets.
    discretization : Discretization, optional
        The model's radial and azimuthal nodes (default 48 x 16).

    Returns
    -------
    dict
        ``{"holdout": [...], "fitted": {...}, "baseline": {...}, "hover_model": {...}}``, each
        error dict as :meth:`Validation.summary` pooled over the held-out runs, plus
        ``"validation_fitted"`` and ``"validation_baseline"`` (:class:`Validation`) for figures.

    Raises
    ------
    ValueError
        As :func:`validate`; ``holdout`` neither a run id nor a list of them, or none given.
    SolverError
        From the model.
    TypeError
        ``entry`` not a CatalogueEntry, ``propeller`` not a Propeller, ``fitted`` or
        ``baseline`` not a parameter set.
    """
    check_inputs(propeller, {"fitted": fitted, "baseline": baseline}, entry=entry)
    # (one run id, as Validation.summary takes it: set("2804rd") split it into characters, stop 104)
    held = sorted(set(check_names("holdout", [holdout] if isinstance(holdout, str) else holdout)))
    air = model_air(fitted, air, name="fitted")
    vf = validate(entry, propeller, fitted, air=air, discretization=discretization)
    vb = validate(entry, propeller, baseline, air=air, discretization=discretization)
    return {"holdout": held, "fitted": vf.summary("model", held), "baseline": vb.summary("model", held),
            "hover_model": vf.summary("hover_model", held), "validation_fitted": vf, "validation_baseline": vb}


# ------------------------------------------------------------------ cross-validation

#: the calibration protocols of :func:`cross_validate`
