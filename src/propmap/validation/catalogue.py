"""Held-out errors of the calibration protocols on load data in the catalogue's metric (rms |dCT| /
static CT, |dCP| / static CP): :func:`coefficient_errors`, :func:`cross_validate`.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.airfoil import Air, SectionParams
from ..core.geometry import Propeller
from ..core.solver import DEFAULT_DISCRETIZATION, Discretization, model_air, rotor_loads
from ..identify._checks import boolean_mask
from ..identify.load_data import STATIC_AIRSPEED, LoadData
from ._checks import check_inputs, check_names

__all__ = ["PROTOCOLS", "PROTOCOL_TEXT", "coefficient_errors", "cross_validate", "rpm_groups"]

PROTOCOLS = ("loso", "loro", "lowest", "static", "blind")
PROTOCOL_TEXT = {
    "loso": "leave one sweep out: fit on the static run and the other sweeps, predict the held-out sweep",
    "loro": "leave one rpm out: fit on the static run and the sweeps at other rpm, predict all sweeps at that rpm",
    "lowest": "fit on the static run and the lowest-rpm sweeps, predict the sweeps at higher rpm",
    "static": "fit on the static run only, predict the sweeps",
    "blind": "no fit: the generic set derived without this propeller's family, predict the sweeps",
}
#: sweeps whose mean rotation rates differ by less than this fraction form one rpm group
SAME_RPM = 0.03


def _coefficients(data, propeller: Propeller, air: Air):
    """Measured CT, CP (propeller convention) of load data; NaN where not measured."""
    n = data.omega / (2 * math.pi)
    D = propeller.diameter
    CT = data.measured["thrust"] / (air.rho * n**2 * D**4) if "thrust" in data.measured else np.full(data.n, np.nan)
    CP = (data.measured["torque"] * 2 * math.pi / (air.rho * n**2 * D**5) if "torque" in data.measured
          else np.full(data.n, np.nan))
    return CT, CP


def _static_mean(C, static, what: str) -> float:
    """The mean measured coefficient ``what`` of the static points where it was measured (NaN:
    not measured there, LoadData's convention); NaN where it was measured at no point at all
    (its errors are then None), an error where it was measured but at no static point or its
    mean there is 0."""
    known = np.isfinite(C)
    if not known.any():
        return math.nan
    if not np.any(known & static):
        raise ValueError(f"no static point (airspeed up to {STATIC_AIRSPEED:g} m/s) has {what} measured, to "
                         "normalise its errors by")
    value = float(np.mean(C[known & static]))
    if value == 0.0:  # (its errors would all be inf, and then left out as not measured)
        raise ValueError(f"the mean static {what} coefficient is 0: no normalisation of its errors")
    return value


def _scores(dct, dcp) -> dict:
    """rms and bias of the CT and CP errors over the points where each was measured (None where
    none was)."""
    ct, cp = dct[np.isfinite(dct)], dcp[np.isfinite(dcp)]

    def rms(e):
        return float(np.sqrt(np.mean(e**2))) if e.size else None

    def bias(e):
        return float(np.mean(e)) if e.size else None

    return {"rms_ct": rms(ct), "rms_cp": rms(cp), "bias_ct": bias(ct), "bias_cp": bias(cp)}


def coefficient_errors(data, propeller: Propeller, params: SectionParams, *, air: Air | None = None, mask=None,
                       discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """rms |dCT| / static CT and rms |dCP| / static CP of ``params`` on load data.

    The normalisation is the mean measured CT and CP of the static points (airspeed up to
    0.3 m/s, ``STATIC_AIRSPEED``: a stand's pitot noise, as in load_errors and the fits)
    of ``data`` (all of them, also when ``mask`` selects other points), so that errors of
    propellers of any size and pitch compare.

    Parameters
    ----------
    data : LoadData
        Must contain static points with thrust and torque.
    propeller : Propeller
    params : AirfoilParams or CamberedParams
    air : Air, optional
        The air of the model and of the coefficients' normalisation (default: the parameter
        set's own ``.air``).
    discretization : Discretization, optional
        The model's radial and azimuthal nodes (default 48 x 16).
    mask : array_like of bool, optional
        Points to evaluate (default all).

    Returns
    -------
    dict
        ``rms_ct``, ``rms_cp`` [-], ``bias_ct``, ``bias_cp`` [-] (mean signed error over
        the same normalisation), ``n_points``. A load not measured at a point (NaN in
        ``data.measured``) is left out of its figures; one measured at no point (torque of a
        thrust-only stand) gives None.

    Raises
    ------
    ValueError
        No static points, a load measured but at no static point (or of mean 0 there), or the
        mask not booleans of shape (N,), or selecting none.
    SolverError
        From the model.
    TypeError
        ``data`` not a LoadData, ``propeller`` not a Propeller, ``params`` not a parameter set.
    """
    check_inputs(propeller, {"params": params}, data=data)
    air = model_air(params, air)
    CT, CP = _coefficients(data, propeller, air)
    static = data.static
    if not static.any():
        raise ValueError(f"coefficient_errors needs static points (airspeed up to {STATIC_AIRSPEED:g} m/s) to "
                         "normalise by")
    CT0, CP0 = _static_mean(CT, static, "thrust"), _static_mean(CP, static, "torque")
    # ("abc" and True ran every point as n_points 1, a list of indices met NumPy's IndexError, stop 104)
    m = np.ones(data.n, bool) if mask is None else boolean_mask("coefficient_errors", mask, data.n)
    if not m.any():
        raise ValueError("the mask selects no point")
    r = rotor_loads(propeller, params, data.omega[m], data.airspeed[m], data.incidence[m], air=air,
                    discretization=discretization)
    return {**_scores((r.CT - CT[m]) / CT0, (r.CP - CP[m]) / CP0), "n_points": int(m.sum())}


def rpm_groups(data) -> list[list[str]]:
    """The sweeps of load data grouped by rotation rate (within SAME_RPM), lowest first.

    UIUC often measures two sweeps at one rpm that split the advance-ratio range.

    Parameters
    ----------
    data : LoadData
        Load data; a group whose points are all static (airspeed up to 0.3 m/s) is not a
        sweep.

    Returns
    -------
    list of list of str
        The sweeps' group names, one list per rotation rate.

    Raises
    ------
    TypeError
        ``data`` not a LoadData.
    """
    if not isinstance(data, LoadData):  # ("'NoneType' object has no attribute 'static'", stop 104)
        raise TypeError(f"data must be a propmap LoadData, got {type(data).__name__}")
    static = data.static
    sweeps = [g for g in dict.fromkeys(data.group) if not np.all(static[data.group == g])]
    rate = {g: float(np.mean(data.omega[data.group == g])) for g in sweeps}
    groups: list[list[str]] = []
    for g in sorted(sweeps, key=rate.get):
        if groups and rate[g] <= rate[groups[-1][0]] * (1 + SAME_RPM):
            groups[-1].append(g)
        else:
            groups.append([g])
    return groups


def _splits(data, protocol: str):
    """(train mask, test mask) pairs of a protocol (every test mask holds sweep points only)."""
    static = data.static
    groups = rpm_groups(data)
    if protocol == "loso":
        return [(data.group != g, data.group == g) for grp in groups for g in grp]
    if protocol == "loro":
        return [(~np.isin(data.group, grp), np.isin(data.group, grp)) for grp in groups]
    if protocol == "lowest":
        train = static | np.isin(data.group, groups[0])
        return [(train, ~train)]
    if protocol == "static":
        return [(static, ~static)]
    return [(None, ~static)]


def cross_validate(data, propeller: Propeller, generic: SectionParams, *, protocols=PROTOCOLS, air: Air | None = None,
                   population: dict | None = None,
                   discretization: Discretization = DEFAULT_DISCRETIZATION) -> dict:
    """Held-out errors of the calibration protocols for one propeller's static run and sweeps.

    Every fit uses :func:`propmap.identify.fit_loads` with its defaults for the data it
    sees (parameters chosen by the data, population prior) and ``generic`` as start,
    prior mean and constants; the errors are pooled over all held-out points of the
    protocol (``loso``: every sweep held out in turn).

    Parameters
    ----------
    data : LoadData
        Static points (airspeed up to 0.3 m/s) and axial sweeps at two rotation rates at least, with
        thrust and torque; ``group`` labels the runs.
    propeller : Propeller
    generic : SectionParams
        The set used blind and as the fits' base. For honest numbers it must not have
        been fitted to this propeller's data (the shipped ``generic_folds``).
    protocols : sequence of str
        Any of :data:`PROTOCOLS`.
    population : dict, optional
        The fits' prior statistics (io.calibration.population); for honest numbers, those
        of the catalogue without this propeller's family (``population(without=name)``).
    air : Air, optional
        The air of the model and of the coefficients' normalisation (default: the parameter
        set's own ``.air``).
    discretization : Discretization, optional
        The model's radial and azimuthal nodes (default 48 x 16).

    Returns
    -------
    dict
        protocol -> ``{"rms_ct", "rms_cp", "bias_ct", "bias_cp", "n_points", "n_fits"}``,
        the errors as :func:`coefficient_errors` pools them (a load not measured at a point
        left out; None for one measured at no point).

    Raises
    ------
    ValueError
        An unknown protocol, ``protocols`` one str or empty, no static points, a load measured
        but at no static point, or fewer than two sweeps.
    SolverError
        From the model.
    TypeError
        ``data`` not a LoadData, ``propeller`` not a Propeller, ``generic`` not a parameter set.
    """
    check_inputs(propeller, {"generic": generic}, data=data)
    air = model_air(generic, air, name="generic")
    from ..identify import FitOptions, fit_loads

    protocols = check_names("protocols", protocols)  # ("blind" ran as b, l, i, n, d; [] returned {})
    bad = [p for p in protocols if p not in PROTOCOLS]
    if bad:
        raise ValueError(f"unknown protocol(s) {', '.join(bad)}; valid: {', '.join(PROTOCOLS)}")
    static = data.static
    if not static.any() or len(rpm_groups(data)) < 2:
        raise ValueError("cross_validate needs static points and sweeps at two rotation rates at least")
    CT, CP = _coefficients(data, propeller, air)
    CT0, CP0 = _static_mean(CT, static, "thrust"), _static_mean(CP, static, "torque")
    out = {}
    for protocol in protocols:
        dct, dcp = [], []
        splits = _splits(data, protocol)
        for train, test in splits:
            params = generic
            if train is not None:
                params = fit_loads(data.subset(train), propeller, base=generic, air=air,
                                   options=FitOptions(population=population, discretization=discretization)).params
            r = rotor_loads(propeller, params, data.omega[test], data.airspeed[test], data.incidence[test], air=air,
                            discretization=discretization)
            dct.append((r.CT - CT[test]) / CT0)
            dcp.append((r.CP - CP[test]) / CP0)
        out[protocol] = {**_scores(np.concatenate(dct), np.concatenate(dcp)), "n_points": int(sum(map(len, dct))),
                         "n_fits": sum(t is not None for t, _ in splits)}
    return out
