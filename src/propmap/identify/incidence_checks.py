"""The checks of load data at incidence (identify/sanity.py's, split from it by responsibility): the
loads read in wind axes instead of the rotor's (:func:`_wind_axes`), and an incidence read the other
way round, 180 deg minus it, or from the disk plane, 90 deg minus it, or descent data read as climb
(:func:`_mirrored_incidence`). Each compares the measured loads with the model's at the file's reading
and at the other, from the points at incidence, and warns where the other fits far better."""

from __future__ import annotations

import numpy as np

from .load_data import STATIC_AIRSPEED, LoadData

__all__ = ["MIRROR_MISFIT", "WIND_AXES_MISFIT"]


#: the misfit of the rotor-axis reading (rms over the points at incidence, in units of the measured thrust's rms)
#: above which a wind-axis reading of the loads is looked for, and the share of it that reading must reach
WIND_AXES_MISFIT = (0.2, 0.5)


def _incidence_misfit(data: LoadData, at_rpm, on, torque: bool = False):
    """(points, misfit) of the checks of loads at incidence (:func:`_wind_axes`,
    :func:`_mirrored_incidence`): the points of ``on`` where the measured and the model's thrust
    (and in-plane force, and with ``torque`` the torque, where measured) are finite, and
    ``misfit(thrust, drag, torque=None)``, the rms of a reading's thrust and drag (model arrays
    over all points) less the measured ones there, in units of the measured thrust's rms, with
    the torque's error in units of the measured torque's rms added where given; None where fewer
    than 3 points or no thrust remain."""
    Tm, Dm = data.measured["thrust"], data.measured.get("drag")
    Qm = data.measured.get("torque") if torque else None
    on = on & np.isfinite(Tm) & np.isfinite(at_rpm.thrust)
    if Dm is not None:
        on &= np.isfinite(Dm) & np.isfinite(at_rpm.drag)
    if Qm is not None:
        on &= np.isfinite(Qm) & np.isfinite(at_rpm.torque)
    scale = float(np.sqrt(np.mean(Tm[on] ** 2))) if on.sum() >= 3 else 0.0
    q_scale = float(np.sqrt(np.mean(Qm[on] ** 2))) if Qm is not None and on.sum() >= 3 else 0.0
    if not scale > 0:
        return None

    def misfit(thrust, drag, torque_=None) -> float:
        sq = (Tm[on] - thrust[on]) ** 2 + (0.0 if Dm is None else (Dm[on] - drag[on]) ** 2)
        if Qm is not None and torque_ is not None and q_scale > 0:
            sq = sq + ((Qm[on] - torque_[on]) * (scale / q_scale)) ** 2
        return float(np.sqrt(np.mean(sq))) / scale

    return on, misfit


def _wind_axes(data: LoadData, at_rpm, warnings_: list) -> bool:
    """Warn where the thrust and in-plane force read as wind-axis loads match the model much
    better than as rotor-axis ones: a tunnel's force along the flow, T cos i - D sin i, under
    'thrust' with its lift, T sin i + D cos i, under 'normal force', or its drag, -(T cos i -
    D sin i), under 'drag' (both fitted with exit 0, parameters at their bounds, the first said
    only as a thrust 0.46 times the model's: a wind-tunnel data audit, 2026-11-30). Judged on
    the points at an incidence of 12-168 deg, 3 or more. Returns whether it warned (sanity_check
    names the wind axes first in a refusal on it, not on the warnings' text)."""
    if not {"thrust", "drag"} <= set(data.measured):
        return False
    s, c = np.sin(data.incidence), np.cos(data.incidence)
    judged = _incidence_misfit(data, at_rpm, s > 0.2)
    if judged is None:
        return False
    on, misfit = judged
    T, D = at_rpm.thrust, at_rpm.drag
    along, lift = T * c - D * s, T * s + D * c  # (the model's force along the flow and across it)
    rotor = misfit(T, D)
    wind = {"'thrust' the force along the flow (T cos i - D sin i) and the in-plane column its lift (T sin i + "
            "D cos i)": misfit(along, lift),
            "the in-plane column the tunnel's drag along the flow (D sin i - T cos i)": misfit(T, -along)}
    said, best = min(wind.items(), key=lambda kv: kv[1])
    lo, share = WIND_AXES_MISFIT
    if rotor > lo and best < share * rotor:
        warnings_.append(f"the thrust and in-plane force miss the model by {rotor:.2g} of the thrust (rms at "
                         f"{int(on.sum())} points at incidence) read in the rotor's axes, {best:.2g} read in wind "
                         f"axes, {said}: are the loads in wind axes? propmap reads them in the rotor's: thrust = "
                         "L sin i - D_w cos i, in-plane force = L cos i + D_w sin i (L the lift, D_w the drag along "
                         "the flow, i the incidence)")
        return True
    return False


#: the misfit of the thrust (and in-plane force, and torque) at the file's incidence, in units of the measured loads'
#: rms, above which the mirrored incidence 180 deg - i is tried, and the share of it that the mirror must reach to be
#: said
MIRROR_MISFIT = (0.2, 0.5)


def _mirrored_incidence(data: LoadData, at_rpm, loads_at, warnings_: list) -> None:
    """Warn where the loads at incidence match the model much better at 180 deg minus the file's
    incidence: a disk angle of attack alpha_d written as 90 - alpha_d, or a tilt measured from
    the other side (validated at 38% thrust error without a word: a wind-tunnel data audit,
    2026-11-30); and where a file whose every point is at incidence 0 matches it much better in
    axial descent (a descent rate read as a climb's airspeed, blamed on an airspeed in km/h: a
    wind-tunnel data audit, 2026-11-30, later that day). Judged on the points with an airspeed
    (above STATIC_AIRSPEED) at 10 deg or more from edgewise (at 90 deg the two readings are
    one), 3 or more, from the thrust and, where measured, the in-plane force and the torque (a
    0-180 deg sweep read the other way round missed by 0.15 of the thrust, below the limit, and
    80% in torque: the same audit). A file whose incidences all lie within 0-90 deg is also read at
    90 deg minus them, where 180 deg minus them does not fit: an angle from the disk plane (0
    edgewise, 90 axial), a 0-90 deg sweep so written told only that its in-plane force in axial
    flow suggested a missing incidence (a wind-tunnel data audit, 2026-11-30)."""
    if "thrust" not in data.measured:
        return
    c = np.cos(data.incidence)
    judged = _incidence_misfit(data, at_rpm, (data.airspeed > STATIC_AIRSPEED) & (np.abs(c) > np.sin(np.radians(10.0))),
                               torque=True)
    if judged is None:
        return
    on, misfit = judged
    lo, share = MIRROR_MISFIT
    # judged with the torque and without it (a slow flyer's torque, off in the model, hid its mirror: the forces alone
    # tell it; a 0-180 deg sweep's forces missed by 0.15 where its torque missed by 80%: with the torque)
    read = {k: misfit(at_rpm.thrust, at_rpm.drag, at_rpm.torque if k else None) for k in (True, False)}
    if not max(read.values()) > lo:  # (the file fits: no mirror solved, which cost 0.3 s per 5,000 points, a review)
        return
    readings = [(np.pi, "180")]
    if np.any(data.incidence) and np.all(data.incidence <= np.pi / 2 + 1e-9):  # (0-90 deg: the disk plane's angle too)
        readings.append((np.pi / 2, "90"))
    for top, deg in readings:
        mirror = loads_at(data.omega, incidence=top - data.incidence)
        mirrored = {k: misfit(mirror.thrust, mirror.drag, mirror.torque if k else None) for k in (True, False)}
        told = [k for k in (True, False)
                if read[k] > lo and np.isfinite(mirrored[k]) and mirrored[k] < share * read[k]]
        if told:
            break
    else:
        return
    read, mirrored = read[told[0]], mirrored[told[0]]
    said = [q for q in ("thrust", "in-plane force", "torque")
            if {"in-plane force": "drag"}.get(q, q) in data.measured and (told[0] or q != "torque")]
    of = (", ".join(said[:-1]) + " and " + said[-1] if len(said) > 1 else said[0]) + (" miss" if len(said) > 1
                                                                                       else " misses")
    if not np.any(data.incidence):
        warnings_.append(f"at {int(on.sum())} points at airspeed the {of} the model by {read:.2g} (rms, in units "
                         f"of the measured loads) in axial climb, where the file has every point (at incidence 0), "
                         f"and by {mirrored:.2g} in axial descent: are these descent data (a descent rate as the "
                         "airspeed)? write incidence_deg 180 for descending points (0 for climbing ones)")
        return
    if deg == "90":
        warnings_.append(f"at {int(on.sum())} points at incidence the {of} the model by {read:.2g} (rms, in units "
                         f"of the measured loads) at the file's incidence and by {mirrored:.2g} at 90 deg minus it: "
                         "is the incidence the angle to the disk plane (0 edgewise, 90 axial)? propmap's incidence is "
                         "the angle between the airspeed and the rotor axis (0 climb, 90 edgewise, 180 axial "
                         "descent); if so, write incidence_deg as 90 minus the file's value")
        return
    warnings_.append(f"at {int(on.sum())} points at incidence the {of} the model by {read:.2g} (rms, in units "
                     f"of the measured loads) at the file's incidence and by {mirrored:.2g} at 180 deg minus it: is "
                     "the incidence a disk angle of attack, or a tilt measured from the other side? propmap's "
                     "incidence is the angle between the airspeed and the rotor axis (0 climb, 90 edgewise, 180 axial "
                     "descent); a disk angle of attack alpha_d (0 edgewise, positive with the disk tilted back "
                     "against the airspeed) is incidence_deg = 90 + alpha_d; if so, write incidence_deg as 180 minus "
                     "the file's value")
