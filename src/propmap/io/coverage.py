"""What the data behind a parameter set covered, against a run of the model: the run's extreme
operating points, the tip Mach number, and the advance ratio, incidence, airspeed, rates and
Reynolds numbers against the set's [coverage] (docs/cli.md, Warnings). The commands print these
lines (cli/_coverage.py); :func:`propmap.maps.build_map` warns them as :class:`CoverageWarning`."""

from __future__ import annotations

import math

from ..core.units import RPM
from .params_file import set_coverage

__all__ = ["CoverageWarning", "coverage_warnings", "envelope_extremes", "airspeed_beyond", "J_SLACK", "RATE_SLACK"]


class CoverageWarning(UserWarning):
    """A model run beyond the data behind its parameter set (:func:`coverage_warnings`)."""


def envelope_extremes(prop, rpm, airspeed, incidence_deg) -> tuple[float, float, float]:
    """The extremes of operating points that :func:`coverage_warnings` checks.

    The advancing tip meets the air at sqrt((Omega R + V sin b)^2 + (V cos b)^2), not
    sqrt((Omega R)^2 + V^2): 20 m/s edgewise at Omega R = 100 m/s is 120 m/s, not 102.

    Parameters
    ----------
    prop : Propeller
    rpm, airspeed, incidence_deg : array_like
        Operating points [rpm, m/s, deg], broadcast together (a grid by broadcasting axes).

    Returns
    -------
    tuple of float
        The largest advancing-tip speed [m/s], advance ratio of the axial flow V cos(beta) /
        (n D) [-] and incidence [deg] (of the points whose airspeed exceeds 1% of the tip speed
        Omega R: 0 where none does).
    """
    import numpy as np

    rpm, airspeed, incidence_deg = (np.atleast_1d(np.asarray(a, float)) for a in (rpm, airspeed, incidence_deg))
    n, omega = rpm / 60, rpm * RPM
    b = np.radians(incidence_deg)
    # (in still air the incidence means nothing; nor at an airspeed below 1% of the tip speed, where a hovering
    # vehicle's drift turns it anywhere: every real flight log warned of its 179.97 deg, a flight-log audit)
    shape = np.broadcast_shapes(rpm.shape, airspeed.shape, incidence_deg.shape)
    moving = np.broadcast_to(airspeed, shape) > np.broadcast_to(0.01 * omega * prop.radius, shape)
    incidences = np.broadcast_to(incidence_deg, shape)[moving]
    return (float(np.max(np.hypot(omega * prop.radius + airspeed * np.sin(b), airspeed * np.cos(b)))),
            float(np.max(airspeed * np.cos(np.radians(incidence_deg)) / (n * prop.diameter))),
            float(np.max(incidences)) if incidences.size else 0.0)


#: how far beyond a [coverage] table a run must go to be warned of: J by its printed 0.01, the rates by 1e-6 relative
#: (a file's 6999.999999999999 rpm from rad/s), the airspeed by 1% and 0.1 m/s (airspeed_beyond), the incidence
#: by INCIDENCE_SLACK_DEG
J_SLACK = 0.005
RATE_SLACK = 1e-6
#: the incidence by 0.1 deg (a log's vertical descent at 180 deg beside training logs' 179.971 deg was warned of, the
#: only line said, which told nothing: an audit of faster flights, 2026-12-02)
INCIDENCE_SLACK_DEG = 0.1


def airspeed_beyond(airspeed: float, airspeed_max: float) -> bool:
    """Whether ``airspeed`` [m/s] goes beyond a [coverage] table's ``airspeed_max`` by more than
    1% and 0.1 m/s (what :func:`coverage_warnings` says).

    Parameters
    ----------
    airspeed, airspeed_max : float
        A run's largest airspeed and the data's [m/s].

    Returns
    -------
    bool
    """
    return airspeed > 1.01 * airspeed_max + 0.1


def coverage_warnings(prop, label, air, tip_speed, J, incidence_deg, rpm=None, airspeed=None, *,
                      tip_mach: bool = True) -> list[str]:
    """One warning line per risk of a model run beyond its data (docs/cli.md, Warnings).

    Parameters
    ----------
    prop : Propeller
    label : str
        The parameter set's label: a catalogue set or a parameter file, whose data coverage
        (io.params_file.set_coverage: a fitted file's [coverage] table) is checked; other sets
        only for the tip Mach number.
    air : Air
        For the speed of sound.
    tip_speed, J, incidence_deg : float
        The run's extremes (:func:`envelope_extremes`) [m/s, -, deg].
    rpm : float or (float, float), optional
        One rate or a (low, high) range [rpm], checked against the data's rpm span.
    airspeed : float, optional
        The run's largest airspeed [m/s], checked against the data's (``airspeed_max``; a flight
        fit's edgewise speed shows in no advance ratio).
    tip_mach : bool
        Whether the tip Mach number is checked too (the solver warns of one from 0.8 itself).

    Returns
    -------
    list of str
        The warnings, one line each, in this order: tip Mach number above 0.7 (compressibility
        beyond Prandtl-Glauert), advance ratio beyond the data's largest, incidence beyond the
        data's (axial data: the off-axis loads rest on the BET/BEMT physics), rates outside the
        data's span, an airspeed beyond the data's largest (by more than 1% and 0.1 m/s), and,
        with the rates within the span, a chord Reynolds number at 0.75 R beyond the data's by
        5% (:meth:`Propeller.reynolds_75` of ``prop`` in ``air``: another air or size,
        :func:`_reynolds_warning`). None where the set's data are unknown (Table I, other
        files) but for the tip Mach number.
    """
    out: list[str] = []
    mach = tip_speed / air.speed_of_sound
    if tip_mach and mach > 0.7:
        out.append(f"tip Mach number up to {mach:.2f} (> 0.7): compressibility beyond Prandtl-Glauert "
                   "is not modelled")
    cov = set_coverage(label)
    if cov is None:
        return out
    # each key is optional (a hand-written [coverage] table may give some of them)
    # beyond the data by more than rounding: J by its printed 0.01 (cos 90 deg is 6e-17, not 0), the rates by 1e-6
    # relative (the file's 6999.999999999999 rpm from rad/s)
    beyond_J = "J_max" in cov and J > cov["J_max"] + J_SLACK
    if beyond_J:
        out.append(f"advance ratio up to {J:.2f}: the data behind {label} reach J = {cov['J_max']:.2f}")
    beyond_incidence = "incidence_deg_max" in cov and incidence_deg > cov["incidence_deg_max"] + INCIDENCE_SLACK_DEG
    if beyond_incidence:
        axial = cov["incidence_deg_max"] == 0
        descent = ("; beyond 90 deg the rotor descends, beyond the climb data: the momentum of rotors in descent, "
                   "docs/models.md" if incidence_deg > 90 else "")
        out.append(f"incidence up to {incidence_deg:g} deg: {label} was fitted to "
                   + ("axial data only; off-axis loads rest on the BET/BEMT physics (docs/validation.md: the Beaver "
                      f"and gill2019 cases){descent}" if axial else f"data up to {cov['incidence_deg_max']:g} deg"))
    # (a flight fit's edgewise speed shows in no advance ratio; said beside those lines too since 2026-12-02: a log
    # at 15-18 m/s on a set fitted to 11.5 m/s was told only of J 0.25 against 0.24, an audit of faster flights)
    # (not beside the J line of static data, airspeed_max 0, which says the same: a review)
    if (airspeed is not None and "airspeed_max" in cov and airspeed_beyond(airspeed, cov["airspeed_max"])
            and not (beyond_J and cov["airspeed_max"] == 0)):
        out.append(f"airspeed up to {airspeed:.3g} m/s: the data behind {label} reach {cov['airspeed_max']:.3g} m/s")
    if rpm is not None:
        lo, hi = (rpm, rpm) if not hasattr(rpm, "__len__") else (min(rpm), max(rpm))
        # (a hand-written table may give one of the rates, or none: its Reynolds span is checked all the same; it
        # was not without the rates, an audit, 2026-11-29)
        low, high = cov.get("rpm_min", 0.0), cov.get("rpm_max", math.inf)
        if lo < low * (1 - RATE_SLACK) or hi > high * (1 + RATE_SLACK):
            shown = f"{lo:g}" if lo == hi else f"{lo:.0f}-{hi:.0f}"
            span = (f"{low:.0f}-{high:.0f} rpm" if math.isfinite(high) and low > 0 else
                    f"up to {high:.0f} rpm" if math.isfinite(high) else f"from {low:.0f} rpm up")
            out.append(f"{shown} rpm: the data behind {label} span {span} (Reynolds numbers beyond them are "
                       "extrapolated)")
        else:  # (the rates within the data's: in other air or on another propeller the Reynolds number need not be)
            out += _reynolds_warning(prop, label, air, cov, (lo, hi))
    return out


def _reynolds_warning(prop, label: str, air, cov: dict, rpm_span) -> list[str]:
    """The warning (a list of none or one) where the run's Reynolds numbers at 0.75 R leave the
    span of the data behind the set (beyond 5%): its [coverage] ``re75_min``, ``re75_max`` (a
    load fit's, since 2026-11-26), or a calibrated set's rpm span on its own propeller in its own
    air. The rpm check alone missed a set used at altitude or on another size (a user-level
    audit: at 10,000 m the same rpm ran at a third of the data's Reynolds number without a
    word)."""
    if "re75_min" in cov and "re75_max" in cov:
        span = (cov["re75_min"], cov["re75_max"])
    elif label.startswith("calibrated:") and "rpm_min" in cov and "rpm_max" in cov:
        from .calibration import calibrated
        from .catalogue import load_propeller

        owner = label.split(":", 1)[1]
        entry = calibrated(owner)
        try:
            own = load_propeller(owner)
        except (KeyError, ValueError):
            return []
        set_air = entry.air if entry is not None else air
        span = tuple(float(own.reynolds_75(cov[k] * RPM, set_air)) for k in ("rpm_min", "rpm_max"))
    else:
        return []
    lo, hi = (float(prop.reynolds_75(r * RPM, air)) for r in rpm_span)
    if lo < span[0] / 1.05 or hi > span[1] * 1.05:
        shown = f"{lo:.3g}" if lo == hi else f"{lo:.3g}-{hi:.3g}"
        return [f"Reynolds number at 0.75 R {shown} in this air and on {prop.name}: the data behind {label} span "
                f"{span[0]:.3g}-{span[1]:.3g} (the section's Reynolds terms are extrapolated; another air or another "
                "propeller size than the data's)"]
    return []
