"""The ``gill2019`` validation case's data and models (cases.py's, split from it by responsibility):
four catalogue propellers (APC 8x6E, 8x8E, 10x7E, 10x4.7SF) in oblique flow, as the published
coefficients of a multinomial model fitted to the wind-tunnel data (Gill & D'Andrea, Drones 2019,
Appendix A; data/published): the slopes of the in-plane H-force and of the rolling and pitching
moments against propmap's loads fitted the same way (:func:`multinomial_fit`), and the rise of
thrust and torque with edgewise speed against propmap's own. The case itself runs from
:func:`propmap.cases.run_case`, which also re-exports this module's public names.

:func:`gill2019_loads` turns those published fits into load data (thrust, in-plane force,
torque) for fitting tests (tools/incidence_fit.py, docs/identification.md).
"""

from __future__ import annotations

import csv
import math
from importlib import resources

import numpy as np

from .core._numbers import checked
from .core.units import RPM
from .core.airfoil import Air, SectionParams
from .core.geometry import Propeller
from .core.solver import AIRSPEED_MAX, check_model_args, model_air, rotor_loads

__all__ = ["gill2019_coefficients", "gill2019_loads", "gill2019_incidence_fits", "multinomial_fit", "GILL2019_FILE",
           "GILL2019_RPM", "GILL2019_ADVANCE", "GILL2019_INCIDENCE_DEG", "GILL2019_FITS", "GILL2019_FIT_MR",
           "GILL2019_MU_RISE", "GILL2019_QUANTITIES"]

GILL2019_FILE = "gill2019_oblique_coefficients.csv"
#: the rotation rate at which propmap's coefficients are fitted [rpm] (the published ones
#: are dimensionless; the H-force slope's ratio moves by 0.06-0.07 between 4000 and 8000 rpm,
#: docs/validation.md)
GILL2019_RPM = 6000.0
#: the grid of that fit: total advance ratio sqrt(mu^2 + lambda_c^2) and incidence [deg]
#: (the published data reach mu and lambda_c of about 0.24), plus the static point
GILL2019_ADVANCE = (0.04, 0.08, 0.12, 0.16, 0.2, 0.24)
GILL2019_INCIDENCE_DEG = (0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0)


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
        ``name`` without published coefficients, or an rpm that is not a number (text included)
        in range.
    TypeError
        ``name`` not a str, ``air`` not an :class:`Air`, ``rolling_moment`` not a bool.
    """
    from .identify.data import LoadData
    from .io.catalogue import load_propeller

    # (a list as name met "unhashable type", air=None "'NoneType' object has no attribute 'rho'", "no" was taken as
    # a rolling moment asked for, "6000" read as 6000: a bad-input audit, stop 104)
    for arg, value, kind, what in (("name", name, str, "a catalogue name (str)"), ("air", air, Air, "a propmap Air"),
                                   ("rolling_moment", rolling_moment, (bool, np.bool_), "a bool")):
        if not isinstance(value, kind):
            raise TypeError(f"{arg} must be {what}, got {type(value).__name__}")
    published = gill2019_coefficients()
    if name not in published:
        raise ValueError(f"no published gill2019 coefficients for {name!r:.60}; known: {', '.join(published)}")
    given = np.atleast_1d(np.asarray(rpm, dtype=object))
    if given.ndim != 1 or given.size == 0 or not all(isinstance(x, (int, float, np.integer, np.floating))
                                                     and not isinstance(x, (bool, np.bool_)) for x in given):
        raise ValueError(f"rpm must be rotation rates in [100, 50000] rpm, at least one, got {rpm!r:.60}")
    rpm = given.astype(float)
    if not np.all((rpm >= 100.0) & (rpm <= 50000.0)):
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
        Rotation rate [rad/s], in [1, 1e5] and at most AIRSPEED_MAX / (0.24 R), so that the
        grid's fastest point (advance ratio 0.24) stays within the model's 500 m/s.
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
    # (NumPy numbers too, core._numbers; above 500 m/s / (0.24 R) the error named an airspeed the caller never
    # gave, a bad-input audit, stop 104)
    omega = checked("omega", omega, 1.0, min(1e5, AIRSPEED_MAX / (max(GILL2019_ADVANCE) * prop.radius)),
                    unit="rad/s")
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv, inc = np.concatenate([[0.0], adv.ravel()]), np.concatenate([[0.0], inc.ravel()])
    R = prop.radius
    # (at omega's bound, 0.24 omega R is 500 m/s to round-off: 500.00000000000006 met the model's range, a review)
    r = rotor_loads(prop, p, omega, np.minimum(adv * omega * R, AIRSPEED_MAX), inc, air=air, radial=False)
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
