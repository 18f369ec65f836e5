"""Direct load measurements of one propeller (:class:`LoadData`): the data kind that
``fit loads`` identifies from, written by the thrust-stand reader (identify/loads_csv.py) and the
catalogue's and UIUC files' readers (identify/data.py).
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field

import numpy as np

from ..core.geometry import short_repr
from ..core._interp import snap_incidence
from ..core.solver import COLLECTIVE_RANGE, OMEGA_MAX
from ._checks import boolean_mask, first_length, float_array

#: where a rotation rate can come from (LoadData.speed_source)
SPEED_SOURCES = ("rpm", "optical", "electrical")


@dataclass(frozen=True)
class LoadData:
    """Direct load measurements of one propeller.

    Attributes
    ----------
    omega, airspeed, incidence : ndarray, shape (N,)
        Operating points [rad/s, m/s, rad]; an incidence within 2.5e-7 rad of 0 or pi is
        stored as it (single precision's pi).
    measured : dict[str, ndarray]
        Any non-empty subset of ``thrust`` [N], ``drag`` [N], ``torque`` [N m] and
        ``rolling_moment`` [N m] (the hub's moment about the in-plane airspeed, positive where the
        advancing side carries more thrust: docs/conventions.md; since 2026-12-01), each shape (N,).
    group : ndarray of str, shape (N,)
        Run label of each point (for hold-out).
    source : str
    collective : ndarray, shape (N,), or None
        Blade-angle offset of each point [rad] (a collective sweep of a variable-pitch
        rotor); None: none.
    notes : tuple of str
        What the reader decided (units converted, rows skipped, steps averaged, a sign
        turned), for the user.
    air_density : float or None
        The air density the file logged [kg/m^3] (the median of a density column), > 0; None:
        not logged. ``fit loads`` fits at it where no air option is given.
    converted : dict
        The factor each load column was multiplied by to SI, from the unit its header gave
        (quantity -> factor, e.g. ``{"thrust": 0.00980665}`` for ``Thrust (g)``; a column read
        as written is absent), for the sanity check's causes (a unit slip of an unlabelled
        column is no cause of a converted one).
    comma_thousands : tuple of str
        The loads (thrust, drag, torque) of whose cells the reader took commas as thousands
        separators (a comma-separated file's quoted ``"1,100"``: 1100, or a decimal comma's
        1.1?), for the sanity check's causes; default none.
    speed_source : {"rpm", "optical", "electrical"}
        The column the rotation rate was read from: a rotation-speed column, or a thrust stand's
        optical or electrical speed (:func:`propmap.identify.read_loads`' ``rpm_source``), for
        the sanity check's causes; default "rpm".

    Raises
    ------
    ValueError
        Built by hand with an array that is not numbers of shape (N,) (the length of
        ``omega``), a non-finite value (in ``measured`` NaN marks a load not measured at a
        point; an infinity is refused), ``omega`` <= 0 rad/s, ``airspeed`` < 0 m/s,
        ``incidence`` outside [0, pi] rad, an empty ``measured`` or a key of it other than
        thrust, drag, torque, rolling_moment, an ``air_density`` that is not a finite number
        > 0, a ``converted`` that is not a dict of those quantities to finite factors > 0, a
        ``comma_thousands`` that is not a tuple of them, a ``speed_source`` not among its three; the message
        names the field; ``omega`` above 1e5 rad/s, a ``collective`` beyond +-pi/4 rad (degrees?),
        a ``group`` label that is not a string or a number (or is NaN). (The readers check the
        signs and the ranges of the loads themselves.)
    """

    omega: np.ndarray
    airspeed: np.ndarray
    incidence: np.ndarray
    measured: dict
    group: np.ndarray
    source: str = ""
    collective: np.ndarray | None = None
    notes: tuple = ()
    air_density: float | None = None
    converted: dict = field(default_factory=dict)
    comma_thousands: tuple = ()
    speed_source: str = "rpm"

    def __post_init__(self):
        n = first_length("LoadData", "omega", self.omega)
        omega = float_array("LoadData", "omega", self.omega, (n,), row="point")
        fields_ = {"omega": omega}
        for name in ("airspeed", "incidence") + (("collective",) if self.collective is not None else ()):
            fields_[name] = float_array("LoadData", name, getattr(self, name), (n,), row="point")
        if np.any(omega <= 0):
            raise ValueError(f"LoadData.omega must be > 0 rad/s, got {omega[omega <= 0][0]:g}")
        if self.air_density is not None:
            rho = self.air_density
            if (isinstance(rho, (bool, np.bool_)) or not isinstance(rho, (int, float, np.integer, np.floating))
                    or not (math.isfinite(rho) and rho > 0)):
                raise ValueError(f"LoadData.air_density must be a finite number > 0 kg/m^3 or None, got {rho!r:.40}")
            object.__setattr__(self, "air_density", float(rho))
        if not isinstance(self.converted, dict) or any(
                k not in LOAD_KEYS or isinstance(f, (bool, np.bool_)) or not isinstance(f, numbers.Real)
                or not (math.isfinite(f) and f > 0) for k, f in self.converted.items()):
            raise ValueError(f"LoadData.converted must be a dict of {', '.join(LOAD_KEYS)} to finite factors > 0, "
                             f"got {short_repr(self.converted)}")
        if not isinstance(self.comma_thousands, tuple) or any(k not in LOAD_KEYS for k in self.comma_thousands):
            raise ValueError(f"LoadData.comma_thousands must be a tuple of {', '.join(LOAD_KEYS)}, "
                             f"got {short_repr(self.comma_thousands)}")
        if self.speed_source not in SPEED_SOURCES:
            raise ValueError(f"LoadData.speed_source must be one of {', '.join(SPEED_SOURCES)}, "
                             f"got {short_repr(self.speed_source)}")
        if np.any(fields_["airspeed"] < 0):
            raise ValueError("LoadData.airspeed must be >= 0 m/s (a descent is an incidence above 90 deg)")
        fields_["incidence"] = snap_incidence(fields_["incidence"])  # (float32's pi: 8.7e-8 rad above pi)
        if np.any((fields_["incidence"] < 0) | (fields_["incidence"] > np.pi)):
            raise ValueError("LoadData.incidence must be in [0, pi] rad (radians, not degrees)")
        if not isinstance(self.measured, dict) or not self.measured:
            raise ValueError("LoadData.measured must be a non-empty dict of thrust, drag, torque or rolling_moment "
                             "arrays")
        bad = [k for k in self.measured if k not in LOAD_KEYS]
        if bad:
            raise ValueError(f"LoadData.measured: unknown quantity {bad[0]!r} (valid: {', '.join(LOAD_KEYS)})")
        # NaN: not measured there (the fits refuse it)
        measured = {k: float_array("LoadData", f"measured[{k!r}]", v, (n,), row="point", nan=True)
                    for k, v in self.measured.items()}
        group = np.empty(n, dtype=object)  # (a tuple label was spread over an axis of its own)
        try:
            if isinstance(self.group, (str, bytes)):  # (a string would be spread into its characters)
                raise TypeError
            group[:] = list(self.group)
        except (TypeError, ValueError):
            raise ValueError(f"LoadData.group must be {n} labels (one per point), "
                             f"got {short_repr(self.group)}") from None
        for g in group:  # (NaN labels, e.g. pandas' empty cells, never equal themselves: the rate count fell to 0)
            if isinstance(g, (bool, np.bool_)) or not isinstance(g, (str, numbers.Real)) or g != g:
                raise ValueError(f"LoadData.group: each label must be a string or a number (not NaN), got {g!r:.40}")
        if "collective" in fields_ and np.any(np.abs(fields_["collective"]) > COLLECTIVE_RANGE):
            raise ValueError(f"LoadData.collective must be in [-{COLLECTIVE_RANGE:.6g}, {COLLECTIVE_RANGE:.6g}] rad "
                             "(radians, not degrees)")
        if np.any(omega > OMEGA_MAX):
            raise ValueError(f"LoadData.omega must be <= {OMEGA_MAX:g} rad/s, got {omega.max():g}")
        for name, a in {**fields_, "measured": measured, "group": group}.items():
            object.__setattr__(self, name, a)

    @property
    def n(self) -> int:
        """Number of points N."""
        return self.omega.size

    @property
    def static(self) -> np.ndarray:
        """Which points are static, shape (N,) of bool: an airspeed of at most
        :data:`STATIC_AIRSPEED` (0.3 m/s: a stand's pitot noise), as the fits, the readers'
        sign rules and the validation metrics take them."""
        return self.airspeed <= STATIC_AIRSPEED

    @property
    def inplane(self) -> np.ndarray:
        """Which points have an in-plane airspeed V |sin(incidence)| above
        :data:`STATIC_AIRSPEED`, shape (N,) of bool: where the in-plane force and the rolling
        moment (INPLANE_KEYS) are fitted and scored (elsewhere model and measurement should both
        be zero: a tunnel's normal force at axial points is its noise), by the fits,
        ``validate``, ``fit loads --holdout`` and :func:`propmap.validation.holdout_loads` alike."""
        return self.airspeed * np.abs(np.sin(self.incidence)) > STATIC_AIRSPEED

    def tip_mach(self, propeller, air) -> float:
        """The largest Mach number at a blade tip over the points, |(Omega R + V sin beta,
        V cos beta)| / a: the measure of the solver's TIP_MACH_WARN (core/_inputs.py).

        Parameters
        ----------
        propeller : Propeller
            Its radius R [m].
        air : Air
            Its speed of sound a [m/s].

        Returns
        -------
        float
            Mach number [-]; 0 for data without points.
        """
        return float(np.max(np.hypot(self.omega * propeller.radius + self.airspeed * np.sin(self.incidence),
                                     self.airspeed * np.cos(self.incidence)), initial=0.0)) / air.speed_of_sound

    def subset(self, mask) -> LoadData:
        """The points where ``mask`` is True.

        Parameters
        ----------
        mask : array_like of bool, shape (N,)

        Returns
        -------
        LoadData
            Every per-point array cut to those points, in their order; source, notes, air
            density, the conversions, ``comma_thousands`` and ``speed_source`` kept.

        Raises
        ------
        ValueError
            ``mask`` not booleans (integer indices are refused) or not of shape (N,).
        """
        mask = boolean_mask("LoadData.subset", mask, self.omega.shape[0])
        return LoadData(self.omega[mask], self.airspeed[mask], self.incidence[mask],
                        {k: v[mask] for k, v in self.measured.items()}, self.group[mask], self.source,
                        None if self.collective is None else self.collective[mask], self.notes, self.air_density,
                        dict(self.converted), self.comma_thousands, self.speed_source)


def data_air(data: LoadData, air, base_air):
    """The air a fit or comparison of ``data`` uses, and a note or None: ``air`` where given;
    else ``base_air`` (the parameter set's) with the density the data logged
    (``LoadData.air_density``) where they logged one, said in the note (the command line fitted
    at the file's density, the Python functions at the set's: a user-level audit, 2026-11-26).

    Parameters
    ----------
    data : LoadData
    air : Air or None
        The air the caller gave (None: none).
    base_air : Air
        The parameter set's air (its viscosity and speed of sound are kept).

    Returns
    -------
    (Air, str or None)
        The air, and a note saying the data's density is used (None where it is not).

    Raises
    ------
    Nothing: ``LoadData`` has checked its density.
    """
    from dataclasses import replace

    if air is not None or data.air_density is None:
        return (base_air if air is None else air), None
    return (replace(base_air, rho=data.air_density),
            f"the air density is the data's, {data.air_density:.4g} kg/m^3 (LoadData.air_density; give air= for "
            "another)")


LOAD_KEYS = ("thrust", "drag", "torque", "rolling_moment")
#: the loads that are zero in axial flow (by symmetry), fitted and scored only where the rotor has an in-plane
#: airspeed (LoadData.inplane): the in-plane force and the hub's rolling moment
INPLANE_KEYS = ("drag", "rolling_moment")
#: those loads in words, for messages
INPLANE_WORDS = {"drag": "the in-plane force", "rolling_moment": "the rolling moment"}
#: a point at an airspeed up to this [m/s] is static: for the thrust's sign rule of a CSV
#: (loads_csv.read_loads) and for which parameters a fit frees (fit._data_kind: a stand's pitot
#: noise does not make its static run a sweep)
STATIC_AIRSPEED = 0.3


def radians_hint(incidence_deg, airspeed, column: str = "incidence_deg") -> str | None:
    """A warning for incidences that look like radians in a degrees column, or None.

    Parameters
    ----------
    incidence_deg, airspeed : array_like, the same shape
        The file's incidences as read [deg] and airspeeds [m/s].
    column : str, optional
        The column's name as written, for the message.

    Returns
    -------
    str or None
        The message where the points with an airspeed above :data:`STATIC_AIRSPEED` (two or
        more) have incidences no larger than pi rounded up to 3.15, some above 0 and some not
        whole degrees, and every one of them, read as radians, within 0.035 deg of a whole degree
        (0-1.5708 "deg": a tunnel's 0-90 deg written in radians, to 3-4 decimals); None otherwise
        (a measured misalignment of 0.12 deg, a sweep of 0.5-2.5 deg).
    """
    inc = np.asarray(incidence_deg, float)[np.asarray(airspeed, float) > STATIC_AIRSPEED]
    if inc.size < 2 or not 0.0 < inc.max() <= 3.15:
        return None
    if not np.any(np.abs(inc - np.round(inc)) > 1e-6):
        return None
    as_deg = np.degrees(inc)
    if np.any(np.abs(as_deg - np.round(as_deg)) > 0.035):
        return None
    top = float(inc.max())
    return (f"{column}: incidences up to {top:g} deg at airspeed: radians? ({top:g} rad = {math.degrees(top):.4g} "
            "deg); give degrees, or say the unit in the header, e.g. 'incidence (rad)'")
