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

:func:`gill2019_loads` turns those published fits into load data (thrust, in-plane force,
torque) for fitting tests (tools/incidence_fit.py, docs/identification.md).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

from .core._numbers import checked
from .core.units import RPM
from .core.airfoil import COLLECTIVE_MAX, Air, SectionParams
from .core.geometry import Propeller
from .core.hover import HoverModel
from .core.solver import check_model_args, model_air, rotor_loads

__all__ = ["CaseResult", "CASES", "run_case", "beaver_propeller", "dji9443_propeller", "gill2019_coefficients",
           "multinomial_fit"]

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
GILL2019_FILE = "gill2019_oblique_coefficients.csv"
#: the rotation rate at which propmap's coefficients are fitted [rpm] (the published ones
#: are dimensionless; the H-force slope's ratio moves by 0.06-0.07 between 4000 and 8000 rpm,
#: docs/validation.md)
GILL2019_RPM = 6000.0
#: the grid of that fit: total advance ratio sqrt(mu^2 + lambda_c^2) and incidence [deg]
#: (the published data reach mu and lambda_c of about 0.24), plus the static point
GILL2019_ADVANCE = (0.04, 0.08, 0.12, 0.16, 0.2, 0.24)
GILL2019_INCIDENCE_DEG = (0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0)


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


def gill2019_coefficients() -> dict[str, dict[str, float]]:
    """The published multinomial coefficients (data/published), by catalogue propeller name.

    Returns
    -------
    dict
        name -> ``CT_static``, ``k1`` ... ``k5``, ``CQ_static``, ``k6`` ... ``k8``, ``k9``,
        ``k10`` (rolling moment) and ``k11``, ``k12`` (pitching moment) (Gill & D'Andrea 2019,
        Appendix A, eqs 95 and 99-102; normalised by (rho/2) pi R^2 (Omega R)^2, the moments
        times R; the pitching moment's sign convention is not in the transcription, GILL2019_FILE).
    """
    text = (resources.files("propmap") / "data" / "published" / GILL2019_FILE).read_text(encoding="utf-8")
    rows = list(csv.reader(line for line in text.splitlines() if line.strip() and not line.startswith("#")))
    head = rows[0]
    return {r[0]: {k: float(v) for k, v in zip(head[2:], r[2:])} for r in rows[1:]}


def gill2019_loads(name: str, rpm=(5000.0, 7000.0), *, air: Air = Air(), rolling_moment: bool = False):
    """Loads of a gill2019 propeller from its published multinomial model, as load data.

    Thrust, in-plane force and torque (and with ``rolling_moment`` the hub's rolling moment,
    C_MR = k9 mu + k10 lambda_c mu) at the static point and on the grid of total advance
    ratio (GILL2019_ADVANCE, within the 0.24 the fits cover) and incidence
    (GILL2019_INCIDENCE_DEG) at each rotation rate, dimensional with (rho/2) pi R^2
    (Omega R)^2 (R with the moments). They stand in for the wind-tunnel data behind the
    fits, which are not in the repository: smooth (a fit's, without its scatter) and
    independent of the rotation rate in coefficient form, which real data are not.

    Parameters
    ----------
    name : str
        A catalogue propeller with published coefficients (:func:`gill2019_coefficients`).
    rpm : sequence of float
        Rotation rates [rpm], at least one, each in [100, 50000].
    air : Air
        The density that makes the coefficients dimensional.
    rolling_moment : bool
        Include the rolling moment (propmap's sign: the published k9 is positive, the advancing
        side carrying more thrust).

    Returns
    -------
    LoadData
        ``thrust``, ``drag``, ``torque`` (and ``rolling_moment``); ``group`` ``"inc<deg>"``, the
        static points in ``"inc00"`` with the axial ones.

    Raises
    ------
    ValueError
        ``name`` without published coefficients, or an rpm out of range.
    """
    from .identify.data import LoadData
    from .io.catalogue import load_propeller

    published = gill2019_coefficients()
    if name not in published:
        raise ValueError(f"no published gill2019 coefficients for {name!r:.60}; known: {', '.join(published)}")
    rpm = np.atleast_1d(np.asarray(rpm, float))
    if rpm.ndim != 1 or rpm.size == 0 or not np.all((rpm >= 100.0) & (rpm <= 50000.0)):
        raise ValueError(f"rpm must be rotation rates in [100, 50000] rpm, got {rpm!r:.60}")
    c, R = published[name], load_propeller(name).radius
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv, inc = np.concatenate([[0.0], adv.ravel()]), np.concatenate([[0.0], inc.ravel()])
    omega = np.repeat(rpm * RPM, adv.size)
    adv, inc = np.tile(adv, rpm.size), np.tile(inc, rpm.size)
    mu, lam = adv * np.sin(inc), adv * np.cos(inc)
    q = 0.5 * air.rho * math.pi * R**2 * (omega * R) ** 2
    measured = {"thrust": q * (c["CT_static"] + c["k1"] * lam + c["k2"] * mu**2 + c["k3"] * lam**2),
                "drag": q * (c["k4"] * mu + c["k5"] * lam * mu),
                "torque": q * R * (c["CQ_static"] + c["k6"] * lam + c["k7"] * mu**2 + c["k8"] * lam**2)}
    if rolling_moment:
        measured["rolling_moment"] = q * R * (c["k9"] * mu + c["k10"] * lam * mu)
    group = np.array([f"inc{round(math.degrees(b)):02d}" for b in inc])
    return LoadData(omega, adv * omega * R, inc, measured, group,
                    f"{name}: Gill & D'Andrea 2019 (Drones 3(4):77), Appendix A multinomial model")


#: the fits :func:`gill2019_incidence_fits` compares: the section alone (identify.options.CAMBERED_FIT, a
#: rigid rotor) and the defaults
GILL2019_FITS = ("section alone (rigid)", "default (section + flapping)")
#: the fit of :func:`gill2019_incidence_fits` with the rolling moment fitted too
GILL2019_FIT_MR = "default, with the rolling moment"


def gill2019_incidence_fits(protocol: str = "incidence", rpm=(5000.0, 7000.0), *, rolling_moment: bool = False) -> dict:
    """Fits to the gill2019 propellers' loads at incidence (:func:`gill2019_loads`), held out.

    Each propeller's loads are fitted from the generic set without its family and under that
    fold's prior (as validation does), once with the section's five level parameters alone
    and once with the defaults, which also free the flapping (identify.options.INPLANE_FIT),
    and predicted where they were held out (:func:`propmap.validation.holdout_loads`). With
    ``rolling_moment`` the loads include the published rolling moment: those two fit the
    thrust, in-plane force and torque and are scored on the rolling moment too, and a third,
    GILL2019_FIT_MR, fits all four (docs/identification.md, Load data at incidence).

    Parameters
    ----------
    protocol : {"incidence", "speed"}
        ``"incidence"``: each incidence 15-90 deg held out in turn; ``"speed"``: the total
        advance ratios 0.16-0.24 predicted from those up to 0.12.
    rpm : sequence of float
        As :func:`gill2019_loads`.
    rolling_moment : bool
        Score (and in a third fit, fit) the rolling moment as well.

    Returns
    -------
    dict
        propeller -> fit label (GILL2019_FITS, and GILL2019_FIT_MR with ``rolling_moment``) ->
        :func:`~propmap.validation.holdout_loads`'s dict.

    Raises
    ------
    ValueError
        An unknown protocol, or as :func:`gill2019_loads`.
    """
    from .identify.options import CAMBERED_FIT
    from .io.calibration import generic_without, population
    from .io.catalogue import load_propeller
    from .validation import holdout_loads

    if protocol not in ("incidence", "speed"):
        raise ValueError(f"protocol must be 'incidence' or 'speed', got {protocol!r:.60}")
    air = Air(rho=1.225)
    out = {}
    for name in gill2019_coefficients():
        prop, data = load_propeller(name), gill2019_loads(name, rpm, air=air, rolling_moment=rolling_moment)
        inc = np.round(np.degrees(data.incidence)).astype(int)
        if protocol == "speed":
            folds = [data.airspeed / (data.omega * prop.radius) < 0.14]
        else:
            folds = [inc != held for held in sorted(set(inc[inc > 0]))]
        base, pop = generic_without(name)[0], population(without=name)
        forces = ("thrust", "drag", "torque") if rolling_moment else None
        out[name] = {label: holdout_loads(data, prop, base, folds, names=names, population=pop, air=air,
                                          quantities=forces)
                     for label, names in zip(GILL2019_FITS, (CAMBERED_FIT, None))}
        if rolling_moment:
            out[name][GILL2019_FIT_MR] = holdout_loads(data, prop, base, folds, population=pop, air=air)
    return out


def multinomial_fit(prop: Propeller, p: SectionParams, omega: float, *, air: Air | None = None) -> dict[str, float]:
    """propmap's loads fitted with Gill & D'Andrea's (2019, Sec. 5) multinomial model.

    The model's loads on a grid of total advance ratio (GILL2019_ADVANCE) and incidence
    (GILL2019_INCIDENCE_DEG, 0: axial climb, 90: edgewise) plus the static point, in their
    normalisation ((rho/2) pi R^2 (Omega R)^2, moments times R; mu = V sin(incidence) /
    (Omega R), lambda_c = V cos(incidence) / (Omega R)), fitted by least squares with
    C_FT = CT_static + k1 lambda_c + k2 mu^2 + k3 lambda_c^2, C_FH = k4 mu + k5 lambda_c mu,
    C_MQ = CQ_static + k6 lambda_c + k7 mu^2 + k8 lambda_c^2, and the rolling and pitching
    moments (``rolling_moment``, ``pitching_moment``: docs/conventions.md) C_MR = k9 mu + k10
    lambda_c mu and C_MP = k11 mu + k12 lambda_c mu (the paper's eqs 101 and 102).

    Parameters
    ----------
    prop : Propeller
    p : AirfoilParams or CamberedParams
    omega : float
        Rotation rate [rad/s], in [1, 1e5].
    air : Air, optional
        Default: the parameter set's own (``p.air``); the coefficients depend on it through
        the Reynolds and Mach numbers only.

    Returns
    -------
    dict
        ``CT_static``, ``k1`` ... ``k5``, ``CQ_static``, ``k6`` ... ``k8``, and ``k4_mu_only``: the
        H-force fitted as C_FH = k4 mu alone (k5 held at 0), the form of the published fits,
        whose k5 lambda_c mu is below 1e-6 of k4 mu over the data's lambda_c <= 0.24
        (|k5| 1.4e-9 to 5.3e-8 against k4 0.025-0.055, GILL2019_FILE), as if fitted with
        k5 = 0 (a free least-squares k5 of measured data would hardly be that small), so that
        their k4 is the H-force's mean slope over the data's lambda_c; this one is the mean over
        this function's grid, which need not weight lambda_c as the authors' test points did;
        ``k9`` ... ``k12``, and ``k9_mu_only``, ``k11_mu_only``: the moments fitted in the published
        fits' form too (their k10 lambda_c mu and k12 lambda_c mu are below 1e-5 of k9 mu and
        k11 mu over lambda_c <= 0.24).

    Raises
    ------
    ValueError
        ``omega`` not a number in range.
    TypeError
        A propeller, parameter set or air of the wrong type.
    SolverError
        From the model.
    """
    check_model_args(prop, p)  # (a propeller of None met "'NoneType' object has no attribute 'radius'")
    air = model_air(p, air, name="p")
    omega = checked("omega", omega, 1.0, 1e5, unit="rad/s")  # (NumPy numbers too, core._numbers)
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv, inc = np.concatenate([[0.0], adv.ravel()]), np.concatenate([[0.0], inc.ravel()])
    R = prop.radius
    r = rotor_loads(prop, p, omega, adv * omega * R, inc, air=air, radial=False)
    q = 0.5 * air.rho * math.pi * R**2 * (omega * R) ** 2
    mu, lam = adv * np.sin(inc), adv * np.cos(inc)
    one = np.ones_like(mu)
    thrust = np.linalg.lstsq(np.column_stack([one, lam, mu**2, lam**2]), r.thrust / q, rcond=None)[0]
    h = np.linalg.lstsq(np.column_stack([mu, lam * mu]), r.drag / q, rcond=None)[0]
    k4_mu_only = np.linalg.lstsq(mu[:, None], r.drag / q, rcond=None)[0][0]
    torque = np.linalg.lstsq(np.column_stack([one, lam, mu**2, lam**2]), r.torque / (q * R), rcond=None)[0]
    moments = [np.linalg.lstsq(np.column_stack([mu, lam * mu]), m / (q * R), rcond=None)[0]
               for m in (r.rolling_moment, r.pitching_moment)]
    mu_only = [np.linalg.lstsq(mu[:, None], m / (q * R), rcond=None)[0][0]
               for m in (r.rolling_moment, r.pitching_moment)]
    names = ("CT_static", "k1", "k2", "k3", "k4", "k5", "CQ_static", "k6", "k7", "k8", "k4_mu_only", "k9", "k10",
             "k11", "k12", "k9_mu_only", "k11_mu_only")
    return dict(zip(names, map(float, (*thrust, *h, *torque, k4_mu_only, *moments[0], *moments[1], *mu_only))))


#: the in-plane advance ratio at which the gill2019 case compares the edgewise rise of thrust and torque
GILL2019_MU_RISE = 0.2
#: the quantities the gill2019 case compares, each dimensionless and free of the normalisation
GILL2019_QUANTITIES = ("H_slope", "H_slope_mu_only", "thrust_rise", "torque_rise", "MR_slope", "MP_slope")


def _gill2019_published(c: dict) -> dict[str, float]:
    mu2 = GILL2019_MU_RISE**2
    return {"H_slope": c["k4"] / c["CT_static"], "H_slope_mu_only": c["k4"] / c["CT_static"],
            "thrust_rise": c["k2"] * mu2 / c["CT_static"], "torque_rise": c["k7"] * mu2 / c["CQ_static"],
            "MR_slope": c["k9"] / c["CT_static"], "MP_slope": c["k11"] / c["CT_static"]}


def _gill2019_model(prop: Propeller, p: SectionParams, omega: float, air: Air) -> dict[str, float]:
    f = multinomial_fit(prop, p, omega, air=air)
    r = rotor_loads(prop, p, omega, np.array([0.0, GILL2019_MU_RISE * omega * prop.radius]),
                    np.array([0.0, math.pi / 2]), air=air, radial=False)
    return {"H_slope": f["k4"] / f["CT_static"], "H_slope_mu_only": f["k4_mu_only"] / f["CT_static"],
            "thrust_rise": float(r.thrust[1] / r.thrust[0] - 1),
            "torque_rise": float(r.torque[1] / r.torque[0] - 1),
            "MR_slope": f["k9_mu_only"] / f["CT_static"],
            "MP_slope": f["k11_mu_only"] / f["CT_static"] + 0.0}  # (+ 0.0: a rigid rotor's -0.0 from lstsq is 0)


def _gill2019_errors(prop: Propeller, p: SectionParams, data, c: dict, air: Air) -> dict[str, np.ndarray]:
    """propmap's loads less the published fits' (``c``) on their grid (:func:`gill2019_loads`' points),
    thrust and in-plane force in units of the published static thrust, torque of the static torque,
    the rolling and pitching moments of the static thrust times R."""
    r = rotor_loads(prop, p, data.omega, data.airspeed, data.incidence, air=air, radial=False)
    static = data.airspeed == 0
    T0, Q0 = np.mean(data.measured["thrust"][static]), np.mean(data.measured["torque"][static])
    R = prop.radius
    tip_speed = data.omega * R
    mu, lam = data.airspeed * np.sin(data.incidence) / tip_speed, data.airspeed * np.cos(data.incidence) / tip_speed
    qR = 0.5 * air.rho * math.pi * R**2 * (data.omega * R) ** 2 * R
    return {"thrust": (r.thrust - data.measured["thrust"]) / T0, "drag": (r.drag - data.measured["drag"]) / T0,
            "torque": (r.torque - data.measured["torque"]) / Q0,
            "rolling_moment": (r.rolling_moment - data.measured["rolling_moment"]) / (T0 * R),
            "pitching_moment": (r.pitching_moment - qR * (c["k11"] * mu + c["k12"] * lam * mu)) / (T0 * R)}


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
        The viscosity and speed of sound of every set's model (default ISA sea level); the
        density is each test's own (below).

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
        Unknown case, or a callable among ``param_sets`` for a case other than gill2019.
    SolverError
        From the model.
    """
    if case != "gill2019" and any(callable(p) for p in param_sets.values()):
        raise ValueError(f"case {case!r} takes parameter sets, not callables (only gill2019 takes a callable)")
    if case == "apc10x7e":
        return _apc10x7e(param_sets, air)
    if case == "dji9443":
        return _dji9443(param_sets, air)
    if case == "beaver":
        return _beaver(param_sets, air)
    if case == "gill2019":
        return _gill2019(param_sets, air)
    raise ValueError(f"unknown case {case!r}; valid: {', '.join(CASES)}")


def _apc10x7e(param_sets: dict, air: Air) -> CaseResult:
    """The APC 10x7E's CT and CQ against J at 9200 rpm (McCrink & Gregory 2017), each set's and the
    hover model's rms and largest error in units of the first point's (:func:`run_case`)."""
    from .io.catalogue import load_propeller

    prop = load_propeller("apce_10x7")
    ct, cq = np.array(_rows("apc10x7E_mccrink_gregory2017_CT_vs_J.csv")), np.array(
        _rows("apc10x7E_mccrink_gregory2017_CQ_vs_J.csv"))
    J = ct[:, 0]
    CQm = np.interp(J, cq[:, 0], cq[:, 1])
    n = 9200 / 60
    pred, metrics = {}, {}
    for label, p in param_sets.items():
        r = rotor_loads(prop, p, 2 * math.pi * n, J * n * prop.diameter, 0.0, air=air, radial=False)
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
                      "9200 rpm; hover model: the measured coefficients at the lowest J", metrics)


def _dji9443(param_sets: dict, air: Air) -> CaseResult:
    """The DJI 9443's hover CT at 5400 rpm against the measured 0.072 (:func:`run_case`)."""
    prop = dji9443_propeller()
    n = 5400 / 60
    pred, metrics = {}, {}
    for label, p in param_sets.items():
        r = rotor_loads(prop, p, 2 * math.pi * n, 0.0, 0.0, air=air, radial=False)
        CT, CQ = r.CT, r.CQ
        pred[label] = {"CT": np.atleast_1d(CT), "CQ": np.atleast_1d(CQ)}
        metrics[label] = {"CT": float(CT), "rel_err_ct": float(CT / 0.072 - 1)}
    return CaseResult("dji9443", "rpm", np.array([5400.0]), {"CT": np.array([0.072])}, pred, CITATIONS["dji9443"],
                      "hover; measured CT 0.072 (standard deviation 0.0018)", metrics)


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
    h = HoverModel.from_model(prop, first, 2 * math.pi * n, air=tunnel)
    pred["hover model"] = {"CT": np.full(inc.size, h.CT(prop.diameter, air=tunnel)) * np.cos(np.radians(true))}
    return CaseResult("beaver", "incidence_deg", inc, {"CT": d[:, 1]}, pred, CITATIONS["beaver"],
                      f"wind-axis CT (T cos a - H sin a), J = 0.896, V = 40 m/s, rho = {BEAVER_RHO} kg/m^3 "
                      f"({n * 60:.0f} rpm); hover model calibrated on the {next(iter(param_sets))} model at V = 0",
                      metrics)
