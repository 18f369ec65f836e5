"""The shipped calibration: the generic cambered parameter set and per-propeller sets.

``data/calibration.json`` is written by ``tools/calibrate_catalogue.py`` from the bundled
UIUC measurements (vol. 1: Brandt & Selig, AIAA 2011-1255; vol. 2: Deters, Ananda & Selig,
AIAA 2014-2151; see data/CITATION.md):

* ``generic``: one cambered parameter set fitted jointly to every catalogue propeller
  (:func:`propmap.identify.fit_loads_joint`). The default for geometry files and for
  propellers without measurements (blind prediction).
* ``generic_folds``: the same derivation without each propeller family in turn
  (``generic without <family>``), so that a propeller can be predicted by a generic set
  and a prior that never saw its family (validation: leave-one-family-out).
* ``population``: the covariance of the parameters fitted to each catalogue propeller
  and their median rms residual: the fits' population prior (identify.FitOptions), also
  per fold.
* ``single_fits``: each propeller's free 8-parameter fit (the statistics' input).
* ``propellers``: for every catalogue propeller with measurements, the parameters fitted
  to all its bundled data, starting from ``generic``, with the fit's rms errors. The
  default for that propeller.

Each set is stored as its record's fields in SI units (:func:`params_to_si`, angles in
radians, ``section_model`` added), so that it reloads to the identical record (a
degree-radian round trip would change the last bit of an angle).
"""

from __future__ import annotations

import functools
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from types import MappingProxyType

from ..core.airfoil import RECORD_META, Air, AirfoilParams, CamberedParams, SectionParams
from ..core.units import RPM

__all__ = ["Calibration", "calibration", "generic_params", "generic_without", "calibrated", "default_params",
           "population", "population_from_dict", "coverage", "propeller_coverage", "shipped_coverage", "params_to_si",
           "params_from_si", "GENERIC"]

#: name of the generic set (``--params generic``)
GENERIC = "generic"


@dataclass(frozen=True)
class Calibration:
    """One shipped parameter set.

    Attributes
    ----------
    params : SectionParams
    air : Air
    name : str
        ``"generic"``, ``"generic without <family>"`` or ``"calibrated:<name>"`` (also the
        label its ``params`` carry).
    rms_ct, rms_cp : float
        The fit's rms |dCT| / static CT and |dCP| / static CP over the data it was
        fitted to [-] (in-sample).
    n_points : int
        Measured points it was fitted to.
    source : str
        What it was fitted to (data and command).
    """

    params: SectionParams
    air: Air
    name: str
    rms_ct: float
    rms_cp: float
    n_points: int
    source: str


def coverage(label: str) -> dict | None:
    """What the data behind a shipped parameter set covered, for warnings.

    Parameters
    ----------
    label : str
        ``"generic"``, ``"generic without <family>"`` or ``"calibrated:<name>"`` (a parameter
        file's table: :func:`propmap.io.params_file.set_coverage`).

    Returns
    -------
    dict or None
        ``J_max`` (largest advance ratio in the data) and ``incidence_deg_max`` (0: the
        UIUC data are axial), and for a calibrated set ``rpm_min`` and ``rpm_max`` (its
        propeller's UIUC static rates and sweeps' nominal rates); None for other labels (Table I, and since 2026-11-23 a
        parameter file's path: :func:`propmap.io.params_file.set_coverage` reads its table),
        whose data this module does not know.
    """
    raw = _raw()
    if label == GENERIC or label.startswith("generic without") or label.startswith("generic fold"):
        cov = raw["generic"].get("coverage")
        return None if cov is None else dict(cov)  # (a copy: the cached file's own dict was returned, a review)
    if label.startswith("calibrated:"):
        name = label.split(":", 1)[1]
        entry = raw["propellers"].get(name)
        if entry is None or entry.get("coverage") is None:
            return None
        return {**entry["coverage"], **_rpm_span(name)}
    return None


def propeller_coverage(prop, omega_min: float, omega_max: float, air: Air) -> dict:
    """The ``[coverage]`` keys of the propeller behind a set: its name, diameter [m], blade
    count, blade angle at 0.75 R [deg] and the chord Reynolds numbers at 0.75 R of the rates
    ``omega_min``..``omega_max`` [rad/s] in ``air`` (:meth:`Propeller.reynolds_75`).

    A load fit writes them (``propmap fit loads``), and :func:`shipped_coverage` for a
    calibrated set: later runs warn on another propeller or beyond the data's Reynolds numbers.

    Parameters
    ----------
    prop : Propeller
    omega_min, omega_max : float
        The data's lowest and highest rates [rad/s].
    air : Air
        The data's air.

    Returns
    -------
    dict
        ``propeller``, ``diameter_m``, ``n_blades``, ``theta75_deg``, ``re75_min``, ``re75_max``.
    """
    re75 = prop.reynolds_75([omega_min, omega_max], air)
    return {"propeller": prop.name, "diameter_m": prop.diameter, "n_blades": int(prop.n_blades),
            "theta75_deg": math.degrees(prop.theta_75()), "re75_min": float(re75[0]), "re75_max": float(re75[1])}


def shipped_coverage(params: SectionParams) -> dict | None:
    """:func:`coverage` of the shipped set ``params`` is: its label's, where the set is that
    shipped set by value (:meth:`SectionParams.same_section`: its air and label aside); for a
    calibrated set with its propeller's keys (:func:`propeller_coverage`: the Reynolds span and
    the blade, which the commands derive from the label ``calibrated:<name>`` and a file's
    path does not carry, a review).

    What :func:`propmap.io.params_file.write_params` writes by default, so that a shipped set
    written to a file warns beyond its data as the set does (``calibrated:apce_8x6`` written lost
    its warnings: an audit, stop 102). A set changed without a new label
    (``dataclasses.replace``) is not the shipped set and gets None, as does every label that
    does not name a shipped set (a file's path, Table I, a fit's ``"modified ..."``).

    Parameters
    ----------
    params : AirfoilParams or CamberedParams

    Returns
    -------
    dict or None
        :func:`coverage`'s keys (``J_max``, ``incidence_deg_max`` [deg], a calibrated set's
        ``rpm_min``, ``rpm_max`` [rpm]), with a calibrated set's :func:`propeller_coverage`
        keys; None where ``params`` is no shipped set.
    """
    label = getattr(params, "label", "") or ""
    cov = coverage(label)
    if cov is None:
        return None
    if label.startswith("calibrated:"):
        name = label.split(":", 1)[1]
        entry = calibrated(name)
        if entry is None or not entry.params.same_section(params):
            return None
        from .catalogue import load_propeller

        try:
            own = load_propeller(name)
        except (KeyError, ValueError, OSError):
            return cov
        return {**cov, **propeller_coverage(own, cov["rpm_min"] * RPM, cov["rpm_max"] * RPM, entry.air)}
    sets = [calibration()["generic"]] + [entry for entry, _, _ in calibration()["generic_folds"]]
    shipped = next((entry.params for entry in sets if entry.name == label), None)
    return cov if shipped is not None and shipped.same_section(params) else None


@functools.lru_cache(maxsize=64)
def _rpm_span(name: str) -> dict:
    """``rpm_min`` and ``rpm_max`` of a catalogue propeller's bundled UIUC runs (its static runs'
    rates and its sweeps' nominal ones); empty where it has none."""
    from .catalogue import catalogue

    entry = catalogue().get(name)
    if entry is None:
        return {}
    rates = [float(r) for run in entry.static_runs() for r in run.rpm] + [float(sw.rpm) for sw in entry.sweeps()]
    return {"rpm_min": min(rates), "rpm_max": max(rates)} if rates else {}


@functools.lru_cache(maxsize=1)
def _raw() -> dict:
    return json.loads((resources.files("propmap") / "data" / "calibration.json").read_text(encoding="utf-8"))


def params_to_si(params: SectionParams) -> dict:
    """The record's model fields (SI, angles in rad) plus ``section_model``: exact in JSON (the
    set's air and label are not stored: the shipped sets use footnote 2's air).

    Parameters
    ----------
    params : AirfoilParams or CamberedParams

    Returns
    -------
    dict
        ``section_model`` (``"gill2017"`` or ``"cambered"``) and every field but ``air``
        and ``label`` (``params.as_dict()``), angles in rad.
    """
    return {"section_model": params.section_model, **params.as_dict()}


def params_from_si(d: dict) -> SectionParams:
    """Inverse of :func:`params_to_si`.

    Parameters
    ----------
    d : dict
        Field name -> value (SI, angles in rad) and ``section_model`` (default
        ``"gill2017"``); ``air`` and ``label`` keys are ignored.

    Returns
    -------
    AirfoilParams or CamberedParams
        With the record's default air (footnote 2's) and an empty label.

    Raises
    ------
    ValueError
        Unknown section model or invalid fields.
    TypeError
        A key that is not a field of the record, or a required field missing (the
        record's constructor).
    """
    d = {k: v for k, v in d.items() if k not in RECORD_META}
    model = d.pop("section_model", "gill2017")
    record = {"gill2017": AirfoilParams, "cambered": CamberedParams}.get(model)
    if record is None:
        raise ValueError(f"unknown section_model {model!r}")
    return record(**d)


def _entry(name: str, d: dict, source: str) -> Calibration:
    try:
        params = params_from_si(d["params"]).replace(label=name)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"calibration.json [{name}]: {exc}") from None
    return Calibration(params, Air(), name, float(d["rms_ct"]), float(d["rms_cp"]), int(d["n_points"]), source)


def _tuples(value):
    """``value`` with every list in it a tuple (nested), for the read-only calibration."""
    return tuple(_tuples(v) for v in value) if isinstance(value, (list, tuple)) else value


@functools.lru_cache(maxsize=1)
def calibration() -> Mapping:
    """The shipped calibration: ``{"generic": Calibration, "propellers": {name: Calibration}, ...}``.

    Returns
    -------
    Mapping
        Read once per process (cached) from the package's calibration file, read-only (it and
        its ``propellers`` and ``population`` are ``types.MappingProxyType``, the population's
        lists and ``generic_folds`` tuples), as every caller in the process shares it.

    Raises
    ------
    ValueError
        The packaged file is malformed (an installation problem).
    """
    raw = _raw()

    def frozen(pop):  # (its lists as tuples too: population()'s covariance was writable through it, a review)
        return None if pop is None else MappingProxyType({k: _tuples(v) for k, v in pop.items()})

    return MappingProxyType({
        "generic": _entry(GENERIC, raw["generic"], raw["generic"]["source"]),
        "generic_folds": tuple((_entry(d.get("label", f"generic fold {k}"), d, raw["generic"]["source"]),
                                frozenset(d["propellers"]), frozen(d.get("population")))
                               for k, d in enumerate(raw.get("generic_folds", []))),
        "population": frozen(raw.get("population")),
        "propellers": MappingProxyType({n: _entry(f"calibrated:{n}", d, raw["propeller_source"])
                                        for n, d in raw["propellers"].items()}),
        "citation": raw["citation"],
        "created_by": raw["created_by"],
    })


def generic_params() -> SectionParams:
    """The generic cambered set fitted to the catalogue (the default for propellers without data).

    Returns
    -------
    CamberedParams

    Raises
    ------
    ValueError
        The packaged calibration file is malformed (an installation problem).
    """
    return calibration()["generic"].params


def generic_without(name: str) -> tuple[SectionParams, str]:
    """A generic set fitted without propeller ``name``'s family, and its label.

    The fold of ``generic_folds`` that does not contain ``name`` (``"generic without
    <family>"``); for a propeller outside the calibration, the full generic set (which never
    saw it either).

    Parameters
    ----------
    name : str
        A propeller's name (a catalogue name for a fold to apply).

    Returns
    -------
    params : CamberedParams
        The first fold's set whose propellers exclude ``name``, else the generic set.
    label : str
        Its name, ``"generic without <family>"`` (the fold's label), or ``"generic"``.

    Raises
    ------
    ValueError
        The packaged calibration file is malformed (an installation problem).
    """
    folds = calibration()["generic_folds"]
    if any(name in members for _, members, _ in folds):
        for entry, members, _ in folds:
            if name not in members:
                return entry.params, entry.name
    return generic_params(), GENERIC


def population(without: str | None = None) -> dict:
    """Statistics of the per-propeller fits: the fits' population prior.

    Parameters
    ----------
    without : str, optional
        A catalogue propeller: the statistics of the fold that excludes its family (the fold
        whose set :func:`generic_without` gives); for a propeller outside the calibration, the
        full statistics (which never saw it either), as :func:`generic_without` gives the full
        generic set.

    Returns
    -------
    dict
        ``names`` (the parameters), ``covariance`` (ndarray, SI units, angles in rad),
        ``sigma_data`` (median rms residual of the per-propeller fits, in fit_loads'
        normalisation), ``source``.

    Raises
    ------
    ValueError
        The shipped calibration has no population statistics.
    """
    cal = calibration()
    raw = cal["population"]
    # (only for a propeller in a fold: every fold excludes one outside the calibration, which got the first
    # fold's statistics, those without the apc29ff family, beside generic_without's full set: a mutation audit)
    if without is not None and any(without in members for _, members, _ in cal["generic_folds"]):
        for _, members, pop in cal["generic_folds"]:
            if without not in members and pop is not None:
                raw = pop
                break
    if raw is None:
        raise ValueError("the shipped calibration has no population statistics (run tools/calibrate_catalogue.py)")
    return population_from_dict(raw)


def population_from_dict(raw: dict) -> dict:
    """The population prior's statistics from their file form (calibration.json's
    ``population``, a fold's, or tools/calibrate_catalogue.py's), as :func:`population` returns them.

    Parameters
    ----------
    raw : dict
        ``names`` (sequence of str), ``covariance`` (nested lists, shape (k, k), SI units,
        angles in rad), ``sigma_data`` (number), ``source`` (str).

    Returns
    -------
    dict
        The same keys: ``names`` a list, ``covariance`` an ndarray of float, ``sigma_data`` a float.

    Raises
    ------
    KeyError
        A key missing from ``raw``.
    """
    import numpy as np

    return {"names": list(raw["names"]), "covariance": np.asarray(raw["covariance"], float),
            "sigma_data": float(raw["sigma_data"]), "source": raw["source"]}


def calibrated(name: str) -> Calibration | None:
    """The calibrated set of catalogue propeller ``name``, or None if it has none.

    Parameters
    ----------
    name : str
        A catalogue propeller's name (``propmap props``), e.g. ``"apce_8x6"``.

    Returns
    -------
    Calibration or None
        Its set (``.params`` labelled ``"calibrated:<name>"``), the set's air and the fit's
        rms errors; None for a name without measurements or outside the catalogue.

    Raises
    ------
    ValueError
        The packaged calibration file is malformed (an installation problem).
    """
    return calibration()["propellers"].get(name)


def default_params(name: str) -> SectionParams:
    """The parameters propmap uses for a propeller when none are given.

    Parameters
    ----------
    name : str
        A catalogue propeller's name (``propmap props``); any other name (a geometry file's
        propeller) gets the generic set.

    Returns
    -------
    CamberedParams
        The propeller's calibrated set if the catalogue has one (``.label``
        ``"calibrated:<name>"``), else the generic set (``.label`` ``"generic"``); either
        carries its air (``.air``).

    Raises
    ------
    TypeError
        ``name`` not a string (a Propeller: give its ``.name``).
    ValueError
        An empty or blank name.

    Warns
    -----
    UserWarning
        A name that is not a catalogue propeller's but close to one (another case, blanks
        around it, a near spelling: ``difflib``'s ratio 0.8 or more): the generic set is
        returned, and the message names the catalogue's near names (a typo once gave the
        generic set without a word).
    """
    if not isinstance(name, str):  # (None, 5 and a Propeller got the generic set without a word)
        hint = " (a Propeller: give its .name)" if hasattr(name, "diameter") else ""
        raise TypeError(f"name must be a propeller's name (str){hint}, got {type(name).__name__}")
    if not name.strip():
        raise ValueError("name must be a propeller's name, got an empty one")
    c = calibrated(name)
    if c is not None:
        return c.params
    if isinstance(name, str) and name.strip():
        import warnings

        from .catalogue import catalogue, near

        found = [] if name in catalogue() else near(name, catalogue(), cutoff=0.8)
        if found:
            warnings.warn(f"default_params: {name!r} is not a catalogue propeller, so this is the generic set; "
                          f"did you mean {', '.join(found)}?", UserWarning, stacklevel=2)
    return calibration()["generic"].params
