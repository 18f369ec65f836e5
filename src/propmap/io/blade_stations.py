"""The checks of a blade's stations that the geometry readers share (UIUC ``r/R c/R beta`` files,
io/geometry_files.py, APC PE0 files, io/pe0.py, and QPROP propeller files, io/qprop_file.py), and
the error they raise.
"""

from __future__ import annotations

import warnings

__all__ = ["FIRST_STATION_MAX", "GeometryFileError", "LAST_STATION_MIN", "LAST_STATION_REFUSED"]


class GeometryFileError(ValueError):
    """A geometry file is malformed; the message names the file and the problem.

    Attributes
    ----------
    found_header : str or None
        Where a UIUC geometry file has no ``r/R c/R beta`` header: its first non-blank line,
        clipped as the message gives it; None for every other problem.
    """

    found_header: str | None = None


#: the largest c/R of a UIUC or QPROP file outside this range is warned (the catalogue's 147 propellers: 0.153-0.390;
#: APC's 66 PE0 files in the shared data: 0.161-0.235): a chord in inches gave 3.4x the thrust, c/D half
CHORD_MAX_PLAUSIBLE = (0.12, 0.6)
#: a UIUC file whose last station lies inside this r/R is extrapolated to the tip (warned)
LAST_STATION_MIN = 0.9
#: a UIUC file whose last station lies inside this r/R is refused: the outer blade, which makes most of
#: the thrust, would be the end polynomials' guess (a blade measured to 0.49 R made 7 times its thrust)
LAST_STATION_REFUSED = 0.7
#: a UIUC file whose first station lies outside this r/R is warned: the blade inside it makes no load (the
#: 147 catalogue propellers' files start at 0.15-0.30; a 10 in blade from 0.85 R: 20% of its thrust)
FIRST_STATION_MAX = 0.4


def _refuse_short_blade(where: str, r_over_R) -> None:
    """Refuse stations that stop inside LAST_STATION_REFUSED (UIUC and PE0 files alike)."""
    if len(r_over_R) >= 2 and r_over_R[-1] < LAST_STATION_REFUSED:
        raise GeometryFileError(f"{where}: the stations stop at r/R = {r_over_R[-1]:.4g}: the outer blade, which makes "
                                f"most of the thrust, is not given (at least r/R = {LAST_STATION_REFUSED:g} is needed; "
                                "is the r/R column radii in another unit?)")


def _warn_partial_blade(where: str, r_over_R) -> None:
    """Warn of stations that stop inside LAST_STATION_MIN or start outside FIRST_STATION_MAX (UIUC
    and PE0 files alike; a PE0 file was not checked: a blade cut at 0.59 R made 20% more thrust
    without a word, a user-level audit)."""
    if r_over_R[-1] < LAST_STATION_MIN:
        warnings.warn(f"{where}: the stations stop at r/R = {r_over_R[-1]:.4g}: the blade from there to the tip is "
                      "extrapolated from the last stations (chord and blade angle); give stations to r/R = 1",
                      UserWarning, stacklevel=4)
    if r_over_R[0] > FIRST_STATION_MAX:
        warnings.warn(f"{where}: the stations start at r/R = {r_over_R[0]:.4g}: the blade inside it makes no load "
                      "(the loads integrate from the first station; the catalogue's files start at 0.15-0.30); give "
                      "stations from the hub", UserWarning, stacklevel=4)
