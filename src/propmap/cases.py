"""Published measurements outside the UIUC catalogue, digitized, as validation cases.

Each case builds its propeller from the bundled geometry and compares any number of
parameter sets (and the hover model) with the digitized measurements. Sources and the
digitization (FLOWUnsteady, MIT) are in data/CITATION.md:

* ``apc10x7e``: APC 10x7 Thin Electric, axial wind tunnel, CT and CQ against J (McCrink &
  Gregory, J. Aircraft 2017), at 9200 rpm; geometry from the UIUC catalogue (apce_10x7).
* ``dji9443``: DJI 9443 hover CT 0.072 at 5400 rpm (Zawodny & Boyd, AHS Forum 2016).
* ``beaver``: TU Delft Beaver propeller, CT against the angle of incidence at J = 0.9,
  V = 40 m/s (Sinnige et al., J. Aircraft 2019): the only digitized incidence data.
* ``gill2019``: four catalogue propellers (APC 8x6E, 8x8E, 10x7E, 10x4.7SF) in oblique flow,
  as the published coefficients of a multinomial model fitted to the wind-tunnel data (Gill &
  D'Andrea, Drones 2019, Appendix A; data/published): the slopes of the in-plane H-force and of
  the rolling and pitching moments against propmap's loads fitted the same way, and the rise of
  thrust and torque with edgewise speed against propmap's own.

The gill2019 case's data and models (:func:`gill2019_coefficients`, :func:`gill2019_loads`,
:func:`gill2019_incidence_fits`, :func:`multinomial_fit` and the GILL2019_* constants) live in
cases_gill2019.py and are re-exported here. :func:`gill2019_loads` turns those published fits
into load data (thrust, in-plane force, torque) for fitting tests (tools/incidence_fit.py,
docs/identification.md).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

from .core.units import RPM
from .core.airfoil import COLLECTIVE_MAX, Air, SectionParams
from .core.geometry import Propeller
from .core.hover import HoverModel
from .core.solver import rotor_loads
from .cases_gill2019 import (GILL2019_ADVANCE, GILL2019_FILE, GILL2019_FIT_MR, GILL2019_FITS,
                             GILL2019_INCIDENCE_DEG, GILL2019_MU_RISE, GILL2019_QUANTITIES, GILL2019_RPM,
                             _gill2019_errors, _gill2019_model, _gill2019_published, gill2019_coefficients,
                             gill2019_incidence_fits, gill2019_loads, multinomial_fit)

__all__ = ["CaseResult", "CASES", "run_case", "beaver_propeller", "dji9443_propeller", "gill2019_coefficients",
           "multinomial_fit", "gill2019_loads", "gill2019_incidence_fits", "GILL2019_FILE", "GILL2019_RPM",
           "GILL2019_ADVANCE", "GILL2019_INCIDENCE_DEG", "GILL2019_FITS", "GILL2019_FIT_MR", "GILL2019_MU_RISE",
           "GILL2019_QUANTITIES"]

CASES = ("apc10x7e", "dji9443", "beaver", "gill2019")
#: the Beaver polar's test conditions (Sinnige et al. 2019 as published with the data): rotation
#: rate [rev/s] and air density [kg/m^3]
BEAVER_N = 188.3
BEAVER_RHO = 1.198
DIGITIZED = "FLOWUnsteady (byuflowlab, MIT), digitized"
CITATIONS = {
    "apc10x7e": "McCrink & Gregory, J. Aircraft 54(1), 2017, Figs. 16, 20; " + DIGITIZED,
    "dji9443": "Zawodny & Boyd, AHS 72nd Forum, 2016 (hover CT 0.072 +- 0.0018 at 5400 rpm); geometry " + DIGITIZED,
    "beaver": "Sinnige et al., J. Aircraft 56(1), 2019, Fig. 10; " + DIGITIZED,
    "gill2019": ("Gill & D'Andrea, Drones 3(4):77, 2019, Appendix A (multinomial model fitted to their oblique-flow "
                 "wind-tunnel data)"),
}


def _rows(name: str) -> list[list[float]]:
    """Numeric rows of a bundled digitized CSV (comment and header lines skipped)."""
    text = (resources.files("propmap") / "data" / "digitized" / name).read_text(encoding="utf-8")
    rows = []
    for row in csv.reader(line for line in text.splitlines() if line.strip() and not line.startswith("#")):
        try:
            rows.append([float(x) for x in row[:2]])
        except ValueError:
            continue  # the header
    return rows


def _properties(name: str) -> dict[str, float]:
    text = (resources.files("propmap") / "data" / "digitized" / name).read_text(encoding="utf-8")
    out = {}
    for row in csv.reader(text.splitlines()[1:]):
        try:
            out[row[0].strip()] = float(row[1])
        except (ValueError, IndexError):
            continue
    return out


def _from_distributions(name, props_file, chord_file, angle_file, source) -> Propeller:
    p = _properties(props_file)
    R, r_hub, B = p["Rtip"], p["Rhub"], int(p["B"])
    c = np.array(_rows(chord_file))
    a = np.array(_rows(angle_file))
    keep = c[:, 0] * R >= r_hub  # stations on the blade
    x = c[keep, 0]
    theta = np.interp(x, a[:, 0], a[:, 1])
    return Propeller(name=name, radius=R, n_blades=B, r=x * R, chord=c[keep, 1] * R, theta=np.radians(theta),
                     source=source)


def beaver_propeller() -> Propeller:
    """TU Delft Beaver propeller: 4 blades, R = 0.1185 m (Sinnige et al. 2019; FLOWUnsteady database).

    Returns
    -------
    Propeller
        Chord and blade-angle distributions of the bundled digitized files, on the
        stations outboard of the hub radius 0.0175 m.
    """
    return _from_distributions("beaver", "beaver.csv", "beaver_chorddist.csv", "beaver_twistdist.csv",
                               "TU Delft Beaver propeller, " + DIGITIZED)


def dji9443_propeller() -> Propeller:
    """DJI 9443: 2 blades, R = 0.12 m (FLOWUnsteady database).

    Returns
    -------
    Propeller
        Chord and blade-angle distributions of the bundled digitized files, on the
        stations outboard of the hub radius 0.00624 m.
    """
    return _from_distributions("dji9443", "DJI9443.csv", "DJI9443_chorddist.csv", "DJI9443_pitchdist.csv",
                               "DJI 9443, " + DIGITIZED)


@dataclass(frozen=True)
class CaseResult:
    """Measured and predicted curves of one case.

    Attributes
    ----------
    case : str
    x_name : str
        The abscissa: ``"J"``, ``"rpm"``, ``"incidence_deg"`` or (gill2019) ``"propeller"``
        (``x`` then indexes the propellers).
    x : ndarray
    measured : dict[str, ndarray]
        ``"CT"`` and, where digitized, ``"CQ"``; gill2019: the quantities of
        GILL2019_QUANTITIES per propeller.
    predicted : dict[str, dict[str, ndarray]]
        label -> quantity -> values at ``x`` (one entry per parameter set, plus
        ``"hover model"`` except in gill2019).
    citation : str
    notes : str
    metrics : dict
        label -> summary numbers (see :func:`run_case`).
    """

    case: str
    x_name: str
    x: np.ndarray
    measured: dict
    predicted: dict
    citation: str
    notes: str = ""
    metrics: dict = field(default_factory=dict)


def _beaver_ctw(prop: Propeller, p: SectionParams, air: Air, incidence_deg) -> tuple[np.ndarray, object]:
    """Wind-axis CT_w = (T cos a - H sin a) / (rho n^2 D^4) of the Beaver at J = 0.896, and the loads."""
    a = np.radians(np.asarray(incidence_deg, float))
    r = rotor_loads(prop, p, 2 * math.pi * BEAVER_N, 40.0, a, air=air, radial=False)
    return (r.thrust * np.cos(a) - r.drag * np.sin(a)) / (air.rho * BEAVER_N**2 * prop.diameter**4), r


def _beaver_matched(prop: Propeller, p: SectionParams, air: Air, CT0m: float, ratio_m: dict) -> dict:
    """The incidence response with the zero-incidence thrust matched to the measurement.

    One measurement fixes one parameter: the blade-angle offset ``collective`` (added to the
    set's own) that makes CT_w(0) equal the measured value, the rest of the set kept. The
    ratios CT_w(a) / CT_w(0) then test the model's incidence physics apart from its thrust
    level (a lightly loaded propeller's rise with incidence does not grow with that level, so
    a level too high shrinks the relative rise; docs/validation.md). Returns
    ``matched_collective_deg``, ``matched_ratio_10``, ``matched_ratio_20``,
    ``matched_ratio_err_*`` and ``matched_H_over_T_20``; empty where no offset of up to
    15 deg (the total within +-COLLECTIVE_MAX) reaches the measured thrust.
    """
    from scipy.optimize import brentq  # imported where used: `propmap validate` starts without it

    base = p.collective
    # offsets of up to 15 deg, the total within the record's range
    lo, hi = max(-COLLECTIVE_MAX - base, math.radians(-15.0)), min(COLLECTIVE_MAX - base, math.radians(15.0))

    def miss(dc: float) -> float:
        return float(_beaver_ctw(prop, p.replace(collective=base + dc), air, [0.0])[0][0]) - CT0m

    if miss(lo) * miss(hi) > 0.0:
        return {}
    dc = brentq(miss, lo, hi, xtol=1e-9)
    ctw, r = _beaver_ctw(prop, p.replace(collective=base + dc), air, [0.0, 10.0, 20.0])
    out = {"matched_collective_deg": math.degrees(dc)}
    for k, a in enumerate((10.0, 20.0)):
        out[f"matched_ratio_{a:g}"] = float(ctw[k + 1] / ctw[0])
        out[f"matched_ratio_err_{a:g}"] = float(ctw[k + 1] / ctw[0] - ratio_m[a])
    out["matched_H_over_T_20"] = float(r.drag[2] / r.thrust[2])
    return out


def _gill2019(param_sets: dict, air: Air) -> CaseResult:
    from .io.catalogue import load_propeller

    published = gill2019_coefficients()
    names = list(published)
    measured = {q: np.array([_gill2019_published(published[n])[q] for n in names]) for q in GILL2019_QUANTITIES}
    omega = GILL2019_RPM * RPM
    props = {n: load_propeller(n) for n in names}
    grids = {n: gill2019_loads(n, (GILL2019_RPM,), air=air, rolling_moment=True) for n in names}
    pred, metrics = {}, {}
    for label, sets in param_sets.items():
        params = {n: sets(n) if callable(sets) else sets for n in names}
        model = [_gill2019_model(props[n], params[n], omega, air) for n in names]
        pred[label] = {q: np.array([m[q] for m in model]) for q in GILL2019_QUANTITIES}
        m = {}
        for q in GILL2019_QUANTITIES:
            ratio = pred[label][q] / measured[q]
            m.update({f"{q}_ratio_{n}": float(x) for n, x in zip(names, ratio)})
            m[f"{q}_ratio_min"], m[f"{q}_ratio_max"] = float(np.min(ratio)), float(np.max(ratio))
        errors = [_gill2019_errors(props[n], params[n], grids[n], published[n], air) for n in names]
        # rms over each propeller's grid, then over all four pooled
        for q in ("thrust", "drag", "torque", "rolling_moment", "pitching_moment"):
            m.update({f"rms_{q}_{n}": float(np.sqrt(np.mean(e[q] ** 2))) for n, e in zip(names, errors)})
            m[f"rms_{q}"] = float(np.sqrt(np.mean(np.concatenate([e[q] for e in errors]) ** 2)))
        metrics[label] = m
    return CaseResult("gill2019", "propeller", np.arange(len(names)), measured, pred, CITATIONS["gill2019"],
                      f"{', '.join(names)}; H_slope: k4 / CT_static of the published multinomial fits against "
                      f"propmap's loads fitted the same way (advance ratios to 0.24, incidence 0-90 deg); "
                      f"H_slope_mu_only: propmap's fitted with k5 = 0, the published fits' form in effect "
                      f"(their k5 lambda_c mu is below 1e-6 of k4 mu); "
                      f"thrust_rise, torque_rise: T / T_static - 1 and Q / Q_static - 1 edgewise at mu = "
                      f"{GILL2019_MU_RISE:g} (published: k2 mu^2 / CT_static, k7 mu^2 / CQ_static); "
                      f"MR_slope, MP_slope: the rolling and pitching moments' k9 and k11 / CT_static, fitted as "
                      f"H_slope_mu_only (M_P positive nose-up; the published sign convention is not stated); "
                      f"rms_thrust, rms_drag, rms_torque, rms_rolling_moment, rms_pitching_moment: propmap's loads "
                      f"less the published fits' on their grid (the static point, advance ratios to 0.24 at 0-90 "
                      f"deg), of the static thrust or torque (moments: static thrust times R), per propeller and "
                      f"pooled; {GILL2019_RPM:.0f} rpm", metrics)


def run_case(case: str, param_sets: dict, *, air: Air = Air()) -> CaseResult:
    """Predict a published case with each parameter set.

    Parameters
    ----------
    case : {"apc10x7e", "dji9443", "beaver", "gill2019"}
    param_sets : dict
        label -> parameters (e.g. the paper's Table I, the generic set); for ``gill2019``
        a value may also be a callable, catalogue name -> parameters (e.g.
        ``propmap.default_params``: each propeller's calibrated set).
    air : Air, optional
        The model's air (default ``Air()``: footnote 2 of the paper, rho 1.225 kg/m^3, mu
        1.983e-5 Pa s, speed of sound 340.3 m/s), its density included for apc10x7e, dji9443
        and gill2019; beaver takes its tunnel's density (1.198 kg/m^3) with ``air``'s viscosity
        and speed of sound. (Said until 2026-12-01: "ISA sea level", "each test's own density".)

    Returns
    -------
    CaseResult
        ``metrics[label]``: apc10x7e: rms and max |dCT| / CT(first point) and
        |dCQ| / CQ(first point); dji9443: CT and its error relative to 0.072; beaver:
        the wind-axis CT_w = (T cos a - H sin a) / (rho n^2 D^4) that the tunnel's balance
        measured (Sinnige et al. 2019, Sec. III.A), at the test's rho and n: CT_w(0) and its
        relative error, CT_w(a)/CT_w(0) at 10 and 20 deg and their errors against the
        measured ratio (interpolated), the shaft ratios and H/T, and the same ratios with
        CT_w(0) matched to the measurement by a collective offset (``matched_*``,
        :func:`_beaver_matched`). ``air`` sets the viscosity and speed of sound (the density
        is the test's). gill2019: per propeller and quantity (GILL2019_QUANTITIES: the
        H-force slope k4 / CT_static from :func:`multinomial_fit`, with k5 free and with k5 = 0
        (``H_slope_mu_only``, the published fits' form; the published k4 in both), the edgewise rise of
        thrust and torque at mu = GILL2019_MU_RISE, and the rolling and pitching moments' slopes
        k9 / CT_static and k11 / CT_static, ``MR_slope`` and ``MP_slope``, in the published
        fits' form) the ratio of propmap's value to the published one,
        ``<quantity>_ratio_<name>``, and their ``_min`` and ``_max``; and the rms of propmap's
        loads less the published fits' over their grid (:func:`gill2019_loads` at
        GILL2019_RPM), thrust and in-plane force of the static thrust, torque of the static
        torque, the moments of the static thrust times R,
        ``rms_<thrust|drag|torque|rolling_moment|pitching_moment>_<name>`` and pooled over the
        four, ``rms_<...>``;
        ``measured`` and ``predicted`` hold the values per propeller (``x`` indexes the
        propellers, in the file's order).

    Raises
    ------
    ValueError
        Unknown case, no parameter set, or a callable among ``param_sets`` for a case other
        than gill2019.
    TypeError
        ``param_sets`` not a dict, ``air`` not an :class:`Air`.
    SolverError
        From the model.
    """
    if case not in CASES:
        raise ValueError(f"unknown case {case!r}; valid: {', '.join(CASES)}")
    # (a list met "'list' object has no attribute 'values'", air=None an AttributeError in two cases and was taken
    # by the other two: a bad-input audit, stop 104)
    if not isinstance(param_sets, dict):
        raise TypeError(f"param_sets must be a dict of label -> parameters, got {type(param_sets).__name__}")
    if not isinstance(air, Air):
        raise TypeError(f"air must be a propmap Air, got {type(air).__name__}")
    if not param_sets:  # (beaver's raised a bare StopIteration: an audit, stop 100)
        raise ValueError("param_sets: give at least one parameter set (label -> parameters)")
    if case != "gill2019" and any(callable(p) for p in param_sets.values()):
        raise ValueError(f"case {case!r} takes parameter sets, not callables (only gill2019 takes a callable)")
    if case == "apc10x7e":
        return _apc10x7e(param_sets, air)
    if case == "dji9443":
        return _dji9443(param_sets, air)
    if case == "beaver":
        return _beaver(param_sets, air)
    return _gill2019(param_sets, air)


def _apc10x7e(param_sets: dict, air: Air) -> CaseResult:
    """The APC 10x7E's CT and CQ against J at 9200 rpm (McCrink & Gregory 2017), each set's and the
    hover model's rms and largest error in units of the first point's (:func:`run_case`)."""
    from .io.catalogue import load_propeller

    prop = load_propeller("apce_10x7")
    ct, cq = np.array(_rows("apc10x7E_mccrink_gregory2017_CT_vs_J.csv")), np.array(
        _rows("apc10x7E_mccrink_gregory2017_CQ_vs_J.csv"))
    J = ct[:, 0]
    CQm = np.interp(J, cq[:, 0], cq[:, 1])
    rpm = 9200.0
    n = rpm / 60
    pred, metrics = {}, {}
    for label, p in param_sets.items():
        r = rotor_loads(prop, p, rpm * RPM, J * n * prop.diameter, 0.0, air=air, radial=False)
        CT, CQ = r.CT, r.CQ
        pred[label] = {"CT": CT, "CQ": CQ}
        dct, dcq = (CT - ct[:, 1]) / ct[0, 1], (CQ - CQm) / CQm[0]
        metrics[label] = {"rms_ct": float(np.sqrt(np.mean(dct**2))), "max_ct": float(np.max(np.abs(dct))),
                          "rms_cq": float(np.sqrt(np.mean(dcq**2))), "max_cq": float(np.max(np.abs(dcq)))}
    pred["hover model"] = {"CT": np.full(J.size, ct[0, 1]), "CQ": np.full(J.size, CQm[0])}
    dct, dcq = (ct[0, 1] - ct[:, 1]) / ct[0, 1], (CQm[0] - CQm) / CQm[0]
    metrics["hover model"] = {"rms_ct": float(np.sqrt(np.mean(dct**2))), "max_ct": float(np.max(np.abs(dct))),
                              "rms_cq": float(np.sqrt(np.mean(dcq**2))), "max_cq": float(np.max(np.abs(dcq)))}
    return CaseResult("apc10x7e", "J", J, {"CT": ct[:, 1], "CQ": CQm}, pred, CITATIONS["apc10x7e"],
                      "9200 rpm; hover model: the measured coefficients at the lowest J; rms_ct, max_ct, rms_cq, "
                      "max_cq: of CT and CQ at the lowest J (fractions)", metrics)


def _dji9443(param_sets: dict, air: Air) -> CaseResult:
    """The DJI 9443's hover CT at 5400 rpm against the measured 0.072 (:func:`run_case`)."""
    prop = dji9443_propeller()
    rpm = 5400.0
    pred, metrics = {}, {}
    for label, p in param_sets.items():
        r = rotor_loads(prop, p, rpm * RPM, 0.0, 0.0, air=air, radial=False)
        CT, CQ = r.CT, r.CQ
        pred[label] = {"CT": np.atleast_1d(CT), "CQ": np.atleast_1d(CQ)}
        metrics[label] = {"CT": float(CT), "rel_err_ct": float(CT / 0.072 - 1)}
    return CaseResult("dji9443", "rpm", np.array([5400.0]), {"CT": np.array([0.072])}, pred, CITATIONS["dji9443"],
                      "hover; measured CT 0.072 (standard deviation 0.0018); rel_err_ct: CT / 0.072 - 1", metrics)


def _beaver(param_sets: dict, air: Air) -> CaseResult:
    """The Beaver propeller's wind-axis CT against incidence at J = 0.896 (Sinnige et al. 2019), each
    set's CT_w(0) and its ratios at 10 and 20 deg, also with CT_w(0) matched (:func:`run_case`)."""
    # Sinnige et al. (2019) measured the force with an external balance in WIND axes:
    # CT_w = (T cos a - H sin a) / (rho n^2 D^4), H the in-plane (drag) force; their test
    # conditions: rho = 1.198 kg/m^3, n = 188.3 Hz (J = 0.896), V = 40 m/s, and the
    # nominal -0.2 deg is the true 0 (setup misalignment): a = nominal + 0.2 deg.
    prop = beaver_propeller()
    d = np.array(_rows("sinnige2019_CT_vs_incidence_J0.9.csv"))
    inc = d[:, 0]
    n = BEAVER_N
    tunnel = Air(rho=BEAVER_RHO, mu=air.mu, speed_of_sound=air.speed_of_sound)
    pred, metrics = {}, {}
    CT0m = float(d[0, 1])
    ratio_m = {a: float(np.interp(a + inc[0], inc, d[:, 1]) / CT0m) for a in (10.0, 20.0)}
    true = inc - inc[0]
    for label, p in param_sets.items():
        CTw, r = _beaver_ctw(prop, p, tunnel, np.concatenate([[0.0, 10.0, 20.0], true]))
        pred[label] = {"CT": CTw[3:], "CT_shaft": r.CT[3:]}
        metrics[label] = {"CT0": float(CTw[0]), "rel_err_ct0": float(CTw[0] / CT0m - 1),
                          **{f"ratio_{a:g}": float(CTw[k + 1] / CTw[0]) for k, a in enumerate((10.0, 20.0))},
                          **{f"ratio_err_{a:g}": float(CTw[k + 1] / CTw[0] - ratio_m[a])
                             for k, a in enumerate((10.0, 20.0))},
                          **{f"shaft_ratio_{a:g}": float(r.CT[k + 1] / r.CT[0])
                             for k, a in enumerate((10.0, 20.0))},
                          **{f"H_over_T_{a:g}": float(r.drag[k + 1] / r.thrust[k + 1])
                             for k, a in enumerate((10.0, 20.0))}}
        metrics[label].update(_beaver_matched(prop, p, tunnel, CT0m, ratio_m))
    metrics["measured"] = {"CT0": CT0m, **{f"ratio_{a:g}": r for a, r in ratio_m.items()}}
    first = next(iter(param_sets.values()))
    h = HoverModel.from_model(prop, first, 2 * math.pi * n, air=tunnel)  # (n [Hz]: the paper's, not an rpm)
    pred["hover model"] = {"CT": np.full(inc.size, h.CT(prop.diameter, air=tunnel)) * np.cos(np.radians(true))}
    return CaseResult("beaver", "incidence_deg", inc, {"CT": d[:, 1]}, pred, CITATIONS["beaver"],
                      f"wind-axis CT (T cos a - H sin a), J = 0.896, V = 40 m/s, rho = {BEAVER_RHO} kg/m^3 "
                      f"({n * 60:.0f} rpm); hover model calibrated on the {next(iter(param_sets))} model at V = 0",
                      metrics)
