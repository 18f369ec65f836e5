"""The checks of load data's in-plane loads (identify/sanity.py's, split from it by responsibility):
the measured in-plane force's (drag's) sign against the model's at incidence (refused where it is
fitted and DRAG_SIGN_REFUSED of the points disagree, warned of from DRAG_SIGN_WARNED of them), its
size (beyond DRAG_SIZE_WARN times the model's: a unit not given?), the loads read in wind axes
(:func:`~propmap.identify.incidence_checks._wind_axes`) and a drag in axial flow (an incidence the
file does not give?) (:func:`_drag_checks`); the hub rolling moment's sign and size the same way,
against the model's rigid blades' where the model flaps (:func:`_rolling_moment_checks`). The sign
conventions are docs/conventions.md's, the model's in-plane loads against tunnels'
docs/validation.md's. :func:`propmap.identify.sanity.sanity_check` runs them.
"""

from __future__ import annotations

import numpy as np

from .csvfile import DataError
from .incidence_checks import _wind_axes
from .load_data import LoadData

__all__ = ["DRAG_SIZE_WARN", "DRAG_SIGN_REFUSED", "DRAG_SIGN_WARNED"]


#: the factor beyond which (or below whose inverse) a measured in-plane force against the model's is warned of as a unit
DRAG_SIZE_WARN = 5.0
#: the share of the points at incidence where a measured in-plane force of the other sign than the model's is refused
#: (from DRAG_SIGN_WARNED of them it is warned of)
DRAG_SIGN_REFUSED = 0.95
#: the share from which a measured in-plane force of the other sign is warned of (0.8 until 2026-11-30, when a sweep
#: through negative angles given as magnitudes, about half of its points of the other sign, was fitted without a word,
#: alpha_L0 at its bound: a wind-tunnel data audit)
DRAG_SIGN_WARNED = 0.25


def _sure(model: np.ndarray, measured: np.ndarray) -> np.ndarray:
    """The points where a load's sign and size can be judged: both finite and the model's
    magnitude above a tenth of its largest (those below are noise about zero)."""
    return np.isfinite(model) & np.isfinite(measured) & (np.abs(model) > 0.1 * np.nanmax(np.abs(model), initial=0))


def _drag_checks(data: LoadData, at_rpm, checked, warnings_: list):
    """sanity_check's in-plane force: its sign against the model's at incidence (the DataError to raise
    once the thrust and torque are checked, or None; a warning where most points disagree but it is
    not fitted) and a drag in axial flow (an incidence the file does not give?), warned of in
    ``warnings_``. Returns (that DataError or None, whether the loads were warned of as wind-axis
    ones: :func:`_wind_axes`)."""
    if "drag" not in data.measured:
        return None, False
    refused = None
    # the sign convention of the in-plane force (a fit of the other sign is nonsense)
    D = at_rpm.drag
    sure = _sure(D, data.measured["drag"])
    opposite = int(np.sum(np.sign(data.measured["drag"][sure]) == -np.sign(D[sure])))
    said = (f"the measured drag has the other sign than the model's in-plane force at {opposite} of "
            f"{int(sure.sum())} points at incidence: propmap's drag points along the in-plane airspeed (against "
            "the disk's in-plane motion, docs/conventions.md); negate the column if the file uses the other "
            "convention")
    if "drag" in checked and sure.sum() >= 3 and opposite >= DRAG_SIGN_REFUSED * sure.sum():
        # (fitted anyway it put alpha_L0, cd_min and the compliance at their bounds, exit 0: a user-level audit;
        # raised after the thrust and torque checks, whose unit slips are said first)
        refused = DataError(f"load data: {data.source}: {said} (a normal force of a body-fixed balance, or a "
                            "sweep through negative angles given as magnitudes, has it on one side)")
    elif sure.sum() >= 3 and opposite >= DRAG_SIGN_WARNED * sure.sum():
        warnings_.append(said + ("" if opposite >= 0.8 * sure.sum() else
                                 " (at part of the points: a sweep through negative angles given as magnitudes, or a "
                                 "body-fixed balance's normal force whose sign follows the angle's?)"))
    # its size: an in-plane force in gf under a bare 'drag' header, read as N, was 102 times the model's and fitted,
    # the flapping at its bound, with no word on the unit (a review, 2026-11-30); the model's in-plane force is within
    # 0.5-2x of tunnels' (docs/validation.md), so only DRAG_SIZE_WARN beyond that is said
    size = float(np.median(np.abs(data.measured["drag"][sure]) / np.abs(D[sure]))) if sure.sum() >= 3 else 1.0
    if "drag" not in data.converted and not (1 / DRAG_SIZE_WARN <= size <= DRAG_SIZE_WARN):
        warnings_.append(f"the measured in-plane force (drag) is {size:.3g} times the model's in the median at "
                         f"{int(sure.sum())} points at incidence: is its unit given? it is read in N (a header "
                         "'drag (gf)', 'drag_kgf' or 'Drag (lbf)' converts it)")
    wind = _wind_axes(data, at_rpm, warnings_)
    # an in-plane force without an in-plane airspeed: an incidence the file does not give?
    Dm = data.measured["drag"]
    axial = ~(data.airspeed * np.abs(np.sin(data.incidence)) > 1e-12 * data.airspeed) & np.isfinite(Dm)
    scale = (np.abs(data.measured["thrust"]) if "thrust" in data.measured
             else np.full(data.n, np.nanmax(np.abs(Dm), initial=0)))
    large = axial & (np.abs(Dm) > 0.05 * np.nan_to_num(scale))
    if large.sum() >= 3 and large.sum() >= 0.5 * axial.sum():
        of = "thrust" if "thrust" in data.measured else "largest drag"
        warnings_.append(f"the measured drag exceeds 5% of the {of} at {int(large.sum())} of {int(axial.sum())} "
                         "points in axial flow (no in-plane airspeed), where the in-plane force is 0: is the "
                         "incidence missing (an 'incidence_deg' column)?")
    return refused, wind


def _rolling_moment_checks(data: LoadData, at_rpm, checked, warnings_: list, rigid=None):
    """sanity_check's hub rolling moment: its sign against the model's at incidence, as the drag's
    (:func:`_drag_checks`: the DataError to raise where it is fitted and DRAG_SIGN_REFUSED of the
    points disagree, else a warning from DRAG_SIGN_WARNED of them), and its size (beyond
    DRAG_SIZE_WARN times the model's in the median: a unit not given?), against ``rigid``, the
    model's loads without flapping, where the model flaps (a set flapping at 3-10 rad/(N m) passes
    0.01-0.38 of a tunnel's rolling moment to the hub, docs/validation.md: a file in the
    right unit was asked 'is its unit given?' at 103 times a compliance of 10's, a review,
    2026-12-01). Returns that DataError or None."""
    if "rolling_moment" not in data.measured:
        return None
    M, Mm = at_rpm.rolling_moment, data.measured["rolling_moment"]
    sure = _sure(M, Mm) & data.inplane
    if sure.sum() < 3:
        return None
    opposite = int(np.sum(np.sign(Mm[sure]) == -np.sign(M[sure])))
    said = (f"the measured rolling moment has the other sign than the model's at {opposite} of {int(sure.sum())} "
            "points at incidence: propmap's rolling moment is positive where the advancing side carries more thrust "
            "(for a rotor turning counter-clockwise about its thrust axis and moving along +x, a moment about -x; "
            "docs/conventions.md); negate the column if the file uses the other convention")
    if "rolling_moment" in checked and opposite >= DRAG_SIGN_REFUSED * sure.sum():
        return DataError(f"load data: {data.source}: {said}")
    if opposite >= DRAG_SIGN_WARNED * sure.sum():
        warnings_.append(said)
    if rigid is not None:  # (the size against rigid blades', where the model's flapping takes the moment away)
        M = rigid.rolling_moment
        sure = _sure(M, Mm) & data.inplane
        if sure.sum() < 3:
            return None
    size = float(np.median(np.abs(Mm[sure]) / np.abs(M[sure])))
    if "rolling_moment" not in data.converted and not (1 / DRAG_SIZE_WARN <= size <= DRAG_SIZE_WARN):
        warnings_.append(f"the measured rolling moment is {size:.3g} times the model's"
                         + (" without flapping (rigid blades)" if rigid is not None else "") + " in the median at "
                         f"{int(sure.sum())} points at incidence: is its unit given? it is read in N m (a header "
                         "'rolling moment (N mm)' or 'rolling_moment_Nmm' converts it)")
    return None
