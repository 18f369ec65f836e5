"""Scores of a flight-log prediction (identify/flight.py fits and predicts): the force and
moment errors in NeuroBEM's Table II metric, the simple baselines fitted by linear least
squares (T = k Omega^2; + a linear rotor drag; + RotorPy's k_z) and the errors by speed band
(docs/flight.md).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..vehicle import Vehicle, hub_velocities, rotor_geometry

if TYPE_CHECKING:  # the samples' type only: flight.py imports this module
    from .flight_samples import FlightSamples

__all__ = ["flight_errors", "fit_baselines", "baseline_force", "speed_band_errors", "reference_at_vehicle_mass",
           "reference_errors", "SPEED_BANDS", "BASELINES"]

#: speed bands of the report [m/s]
SPEED_BANDS = ((0.0, 3.0), (3.0, 6.0), (6.0, 9.0), (9.0, math.inf))


def flight_errors(predicted_force, samples: FlightSamples, predicted_moment=None) -> dict:
    """Rms errors of a prediction against the measured force (and moment).

    The pooled force error is NeuroBEM's Table II metric: F = sqrt(mean of the three
    axes' mean square errors) [N]; likewise M [N m].

    Parameters
    ----------
    predicted_force : array_like, shape (N, 3)
        Predicted body force at the samples [N], body axes.
    samples : FlightSamples
        Their ``force`` [N] (and ``moment`` [N m]), shape (N, 3), are the measurement.
    predicted_moment : array_like, shape (N, 3), optional
        Predicted body moment [N m]; scored only where ``samples.moment`` is not None.

    Returns
    -------
    dict
        ``Fx, Fy, Fz, F`` [N], ``n``, and with moments ``Mx, My, Mz, M`` [N m] and
        ``M_zero`` (the zero-moment predictor's pooled error).
    """
    e = np.asarray(predicted_force) - samples.force
    ms = np.mean(e**2, axis=0) if e.size else np.full(3, np.nan)
    out = {"Fx": float(np.sqrt(ms[0])), "Fy": float(np.sqrt(ms[1])), "Fz": float(np.sqrt(ms[2])),
           "F": float(np.sqrt(np.mean(ms))), "n": int(samples.n)}
    if predicted_moment is not None and samples.moment is not None:
        em = np.asarray(predicted_moment) - samples.moment
        mm = np.mean(em**2, axis=0)
        out.update({"Mx": float(np.sqrt(mm[0])), "My": float(np.sqrt(mm[1])), "Mz": float(np.sqrt(mm[2])),
                    "M": float(np.sqrt(np.mean(mm))),
                    "M_zero": float(np.sqrt(np.mean(samples.moment**2)))})
    return out


def reference_at_vehicle_mass(samples: FlightSamples, mass: float):
    """The logs' own prediction (``samples.reference_force``) scaled to the vehicle's mass, where
    it was made for another: F_ref m / m_ref per log, so that it is scored, as propmap's force,
    against m a_s (a comparison in acceleration). The NeuroBEM segments' columns were made for
    0.752 kg, the mass first published, where the vehicle file has the corrected 0.772 kg:
    scored as logged they carry a 2.6% error of scale, 0.244 N pooled on the melon log against
    0.151 N scaled (a flight-log audit, 2026-11-28).

    Parameters
    ----------
    samples : FlightSamples
        With ``reference_force`` and ``reference_mass`` (per log).
    mass : float
        The vehicle's mass m [kg], the one ``samples.force`` was made with.

    Returns
    -------
    (ndarray, shape (N, 3), tuple of float) or None
        The scaled force [N] and the masses [kg] the logs' predictions were made for; None
        where there is no prediction, a log's mass is unknown, or every one lies within 0.5%
        of ``mass``.
    """
    if samples.reference_force is None or len(samples.reference_mass) != len(samples.log_names):
        return None
    m_ref = np.asarray(samples.reference_mass, float)[samples.log_index]
    if samples.n == 0 or not np.all(np.isfinite(m_ref)) or np.all(np.abs(mass / m_ref - 1.0) <= 0.005):
        return None
    used = tuple(sorted({float(f"{m:.4g}") for m in m_ref}))  # (to the digits said: 0.752 from every segment)
    return samples.reference_force * (mass / m_ref)[:, None], used


def reference_errors(samples: FlightSamples, mass: float) -> tuple[dict, tuple]:
    """The logs' own prediction scored as :func:`flight_errors` scores a model: as logged
    ("reference") and, where it was made for another mass, at the vehicle's
    ("reference_at_vehicle_mass", :func:`reference_at_vehicle_mass`).

    Parameters
    ----------
    samples : FlightSamples
    mass : float
        The vehicle's mass [kg].

    Returns
    -------
    (dict, tuple of float)
        key -> :func:`flight_errors`' dict ({} where the samples have no prediction), and the
        masses [kg] the predictions were made for where one is scaled (else ()).
    """
    if samples.reference_force is None:
        return {}, ()
    out = {"reference": flight_errors(samples.reference_force, samples, samples.reference_moment)}
    scaled = reference_at_vehicle_mass(samples, mass)
    if scaled is None:
        return out, ()
    out["reference_at_vehicle_mass"] = flight_errors(scaled[0], samples, samples.reference_moment)
    return out, scaled[1]


def _hub_velocities(samples: FlightSamples, arms: np.ndarray) -> np.ndarray:
    """v + w x r_i, shape (N, n_rotors, 3): the hubs' velocities from their arms about the centre of mass."""
    return hub_velocities(samples.velocity, samples.angular_velocity, arms)


#: the baselines of the report: (key, label, terms)
BASELINES = (("k_omega2", "T = k Omega^2", ("thrust",)),
             ("rotor_drag", "k Omega^2 + linear rotor drag c Omega v_ip", ("thrust", "drag")),
             ("rotorpy", "k Omega^2 - k_z Omega v_z + c Omega v_ip (RotorPy's terms)", ("thrust", "drag", "kz")))


def _baseline_columns(samples: FlightSamples, vehicle: Vehicle, terms) -> np.ndarray:
    """Design matrix, shape (N, 3, n_terms): each term's body force per unit coefficient."""
    arms, axes, _, _ = rotor_geometry(vehicle)  # about the centre of mass; unit axes (n_rot, 3)
    om = samples.rotor_omega
    V = _hub_velocities(samples, arms)
    v_ax = np.einsum("nkj,kj->nk", V, axes)
    v_ip = V - v_ax[..., None] * axes[None]
    cols = []
    for t in terms:
        if t == "thrust":
            cols.append(np.einsum("nk,kj->nj", om**2, axes))
        elif t == "drag":
            cols.append(-np.einsum("nk,nkj->nj", om, v_ip))
        else:  # RotorPy's k_z: thrust reduced by k_z Omega v_z along each axis
            cols.append(-np.einsum("nk,kj->nj", om * v_ax, axes))
    return np.stack(cols, axis=-1)


def fit_baselines(train: FlightSamples, vehicle: Vehicle) -> dict:
    """The simple models, fitted by linear least squares to the training samples' force.

    Parameters
    ----------
    train : FlightSamples
        Their ``force`` [N], ``rotor_omega`` [rad/s], ``velocity`` [m/s] and
        ``angular_velocity`` [rad/s] (the hubs' velocities from the rotors' arms about the
        centre of mass).
    vehicle : Vehicle
        Its rotors' arms [m] and axes (:func:`propmap.vehicle.rotor_geometry`), in the samples'
        rotor order.

    Returns
    -------
    dict
        key -> {"label", "terms", "coefficients"} for each of :data:`BASELINES`.
    """
    out = {}
    for key, label, terms in BASELINES:
        X = _baseline_columns(train, vehicle, terms).reshape(-1, len(terms))
        coef = np.linalg.lstsq(X, train.force.reshape(-1), rcond=None)[0]
        out[key] = {"label": label, "terms": list(terms), "coefficients": [float(c) for c in coef]}
    return out


def baseline_force(baseline: dict, samples: FlightSamples, vehicle: Vehicle) -> np.ndarray:
    """A fitted baseline's body force at the samples [N], shape (N, 3).

    Parameters
    ----------
    baseline : dict
        One value of :func:`fit_baselines`' result: its ``"terms"`` and ``"coefficients"``.
    samples : FlightSamples
        N samples: rotor speeds [rad/s], body velocity [m/s] and rates [rad/s].
    vehicle : Vehicle
        Its rotors' positions [m] and axes, in the samples' rotor order.

    Returns
    -------
    ndarray, shape (N, 3)
        The body force [N], body axes.
    """
    X = _baseline_columns(samples, vehicle, baseline["terms"])
    return X @ np.asarray(baseline["coefficients"])


def speed_band_errors(predicted_force, samples: FlightSamples, bands=SPEED_BANDS) -> list:
    """Pooled force error F [N] in each speed band (None where a band is empty).

    Parameters
    ----------
    predicted_force : array_like, shape (N, 3)
        Predicted body force at the samples [N].
    samples : FlightSamples
        Its speed ``|v|`` [m/s] puts each sample in a band (lower bound included, upper
        excluded).
    bands : sequence of (float, float)
        The bands [m/s], in order (default :data:`SPEED_BANDS`, issue 14's; ``math.inf`` for
        an open one).

    Returns
    -------
    list of dict
        One per band, in order: ``band_m_s`` ``[low, high]`` [m/s] (high None for the
        open band), ``n`` (samples in the band) and ``F`` [N] (as :func:`flight_errors`;
        None where the band is empty).
    """
    sp = samples.speed
    rows = []
    for lo, hi in bands:
        m = (sp >= lo) & (sp < hi)
        rows.append({"band_m_s": [lo, None if math.isinf(hi) else hi], "n": int(m.sum()),
                     "F": flight_errors(np.asarray(predicted_force)[m], samples.select(m))["F"] if m.any() else None})
    return rows
