"""Warnings of a model run beyond its data (docs/cli.md, Warnings), printed as the commands'
warning lines: :func:`propmap.io.coverage.coverage_warnings`' lines, which the API's
:func:`propmap.maps.build_map` warns as a :class:`~propmap.io.coverage.CoverageWarning`."""

from __future__ import annotations

from ..io.coverage import J_SLACK, RATE_SLACK, airspeed_beyond, coverage_warnings, envelope_extremes
from ._common import warn

__all__ = ["coverage_messages", "envelope_extremes", "airspeed_beyond", "J_SLACK", "RATE_SLACK", "j_max"]


def coverage_messages(prop, label, air, tip_speed, J, incidence_deg, rpm=None, airspeed=None) -> None:
    """One warning line on stderr per risk of a model run beyond its data: each line of
    :func:`propmap.io.coverage.coverage_warnings` (its parameters), the tip Mach number from 0.7
    included.

    Parameters
    ----------
    prop : Propeller
    label : str
        The parameter set's label (a catalogue set or a parameter file).
    air : Air
    tip_speed, J, incidence_deg : float
        The run's extremes (:func:`envelope_extremes`) [m/s, -, deg].
    rpm : float or (float, float), optional
        One rate or a (low, high) range [rpm].
    airspeed : float, optional
        The run's largest airspeed [m/s].
    """
    for line in coverage_warnings(prop, label, air, tip_speed, J, incidence_deg, rpm=rpm, airspeed=airspeed):
        warn(line)


def j_max(axial_speed, n, diameter) -> float:
    """A fit's [coverage] ``J_max``: the largest climb advance ratio V cos(beta) / (n D) of its
    data (arrays that broadcast; [m/s], [rev/s], [m]), 0 for data all in descent, and at most the
    table's bound (io/params_tables.COVERAGE_KEYS: a row at 40 rpm and 20 m/s gave 118, and the
    file a fit wrote could not be read back; a review, 2026-12-01)."""
    import numpy as np

    from ..io.params_tables import COVERAGE_KEYS

    with np.errstate(divide="ignore", invalid="ignore"):
        J = np.asarray(axial_speed) / (np.asarray(n) * np.asarray(diameter))
    top = COVERAGE_KEYS["J_max"][1]
    return min(max(0.0, float(np.nanmax(J, initial=0.0))), top)
