"""The samples of flight logs for the force balance of identify/flight.py: the measured
aerodynamic force F = m a_s (a_s the specific force the accelerometer reads) and moment
M = I dw/dt + w x I w at a chosen rate, and the rotor speeds through the motors' first-order lag.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..core._numbers import checked
from ..core.air import G0
from ..core.units import RPM
from ..io.flightlog import FlightLog
from ..io.flightlog_checks import OMEGA_STOPPED
from ..vehicle import Vehicle
from ._checks import boolean_mask, first_length, float_array

__all__ = ["OMEGA_STOPPED", "GROUND_FRACTION", "GROUND_SPEED", "GROUND_RATE", "FlightSamples", "flight_samples"]

#: a motor whose median speed over a log lies beyond this factor of the median of the motors that turn the same
#: propeller is warned of (the four NeuroBEM segments: 0.976-1.021)
MOTOR_SPREAD = 1.4
#: a motor whose speed's standard deviation over a log is below this fraction of the largest of those motors' is
#: warned of as a frozen or held reading (the four NeuroBEM segments: 0.53-1 of the largest)
MOTOR_STILL = 0.1


def _motor_spread(log, omega: np.ndarray, vehicle) -> list[str]:
    """Notes for a log where a motor's median speed (over the samples kept) lies beyond
    MOTOR_SPREAD of the median of the three or more rotors that turn the same propeller (a
    sensor at half speed, a pole-pair count of its own, was scored without a word: a flight-log
    audit, 2026-11-27; a quadplane's pusher, another propeller, is not compared), and where a
    motor's speed varies less than MOTOR_STILL as much as the most varying of them (a reading
    frozen or held at one value while the others fly the vehicle: scored without a word before,
    2026-11-27)."""
    if omega.shape[0] < 10:
        return []
    med = np.median(omega, axis=0)
    spread = np.std(omega, axis=0)
    groups = {}
    for i, r in enumerate(vehicle.rotors):
        groups.setdefault(id(r.propeller), []).append(i)
    far_note = still_note = None  # (one of each per log)
    for members in groups.values():
        if len(members) < 3:
            continue
        ratio = med[members] / np.median(med[members])
        far = np.flatnonzero((ratio < 1 / MOTOR_SPREAD) | (ratio > MOTOR_SPREAD))
        if far.size and far_note is None:
            k = int(far[np.argmax(np.abs(np.log(ratio[far])))])
            far_note = (f"{log.name}: motor {members[k] + 1}'s median speed is {ratio[k]:.3g} times the median of the "
                        "motors that turn its propeller (a speed sensor or pole-pair count of its own, another rotor's "
                        "number?): it is read as logged")
        typical = np.max(spread[members])  # (the median was a frozen one's where most are frozen: a review)
        still = [i for i in members if spread[i] < MOTOR_STILL * typical]
        if still and still_note is None:
            k = still[0]
            still_note = (f"{log.name}: motor {k + 1}'s speed varies {spread[k] / typical:.2g} times as much as the "
                          f"most varying of the motors that turn its propeller (standard deviation {spread[k]:.3g} "
                          f"against {typical:.3g} rad/s): a reading frozen or held at one value? It is read as logged")
    return [n for n in (far_note, still_note) if n is not None]


#: a log whose measured moment about a body axis falls with what the rotor layout makes of its motor speeds, at a
#: t-statistic below this (its samples' correlation in time accounted for: _layout_note), is warned of. The four
#: NeuroBEM segments at 25 Hz (2026-11-27): +2.1 to +12.5 in the right order, and in windows of 5, 10 and 20 s of them
#: at 25, 100 and 400 Hz no lower than -3.2 (pitch, 5 s at 25 Hz: the rear rotors run faster at speed while the
#: measured pitching moment stays near 0, docs/flight.md); with the left and right motors swapped -4.2 to -12.5 about x
LAYOUT_T = -4.0
#: the rate the layout test thins its samples to [Hz] (the fit's default rate, at which LAYOUT_T was set)
LAYOUT_RATE_HZ = 25.0


def _layout_moments(vehicle, hover: float) -> np.ndarray | None:
    """G, shape (n_rotors, 3): the moment about the centre of mass per Omega^2 [N m s^2] that
    each rotor makes in hover by the vehicle file, its thrust's r_i x a_i k_T and its torque's
    reaction -s_i a_i k_Q (k_T, k_Q at the hover speed, the rotor's own set or the generic
    one); None where there is no hover speed or a solve fails."""
    from ..core.solver import SolverError, rotor_loads
    from ..io.calibration import generic_params
    from ..vehicle import rotor_geometry

    if not hover > 0:
        return None
    arms, axes, spins, _ = rotor_geometry(vehicle)
    per_omega2 = np.zeros((len(vehicle.rotors), 3))
    try:
        for k, r in enumerate(vehicle.rotors):
            loads = rotor_loads(r.propeller, r.params if r.params is not None else generic_params(), hover, 0.0, 0.0)
            per_omega2[k] = (float(loads.thrust) * np.cross(arms[k], axes[k])
                             - spins[k] * float(loads.torque) * axes[k]) / hover**2
    except (SolverError, ValueError, ArithmeticError):
        return None
    return per_omega2


def _layout_note(log, omega: np.ndarray, moment: np.ndarray, per_omega2: np.ndarray | None,
                 rate_hz: float = LAYOUT_RATE_HZ) -> list[str]:
    """A note where the log's measured moment runs against the rotor layout: about each body
    axis, the measured moment regressed on z = sum_i G_i Omega_i^2 (:func:`_layout_moments`)
    has a slope whose t-statistic lies below LAYOUT_T (a wrong motor order was scored without a
    word before, 2026-11-27). The samples are correlated in time, so the t-statistic is taken
    with the effective sample count of the residuals' lag-1 autocorrelation rho, n (1 - rho) /
    (1 + rho) (that of an AR(1) series; a review found a correct log's 10 s at -2.4 at 25 Hz,
    -3.6 at 100 Hz, -7.3 at 400 Hz with n alone), on the samples thinned to about
    LAYOUT_RATE_HZ from ``rate_hz``, theirs: with the AR(1) count alone the statistic fell
    about 2.5 times from 25 to 400 Hz instead (a smooth residual's lag-1 correlation nears 1
    faster than an AR(1) series' as the sampling gets finer), and `propmap wrench`, which
    scores every sample, missed left and right motors swapped in three of the four NeuroBEM
    logs that `fit flight` at 25 Hz named (a flight-log audit, 2026-11-28). The note asks, it
    does not refuse."""
    step = max(1, int(round(rate_hz / LAYOUT_RATE_HZ)))
    omega, moment = omega[::step], moment[::step]
    if per_omega2 is None or omega.shape[0] < 50:
        return []
    z = omega**2 @ per_omega2
    z = z - z.mean(axis=0)
    m = moment - moment.mean(axis=0)
    against = []
    for i, axis in enumerate("xyz"):
        zz = float(z[:, i] @ z[:, i])
        if not zz > 0:
            continue
        slope = float(z[:, i] @ m[:, i]) / zz
        rest = m[:, i] - slope * z[:, i]
        scatter = float(rest @ rest)  # (0 for a synthetic log's exact moments: no ZeroDivisionError, a test's)
        if scatter > 0:
            rho = min(max(float(rest[1:] @ rest[:-1]) / scatter, 0.0), 0.99)
            n_eff = max(len(z) * (1 - rho) / (1 + rho), 3.0)
            t = slope / math.sqrt(scatter / (len(z) - 2) / zz * len(z) / n_eff)  # (the slope's variance x n / n_eff)
        else:
            t = -math.inf if slope < 0 else 0.0
        if t < LAYOUT_T:
            against.append(f"{axis} (t = {t:.1f})")
    if not against:
        return []
    return [f"{log.name}: the measured moment about body {', '.join(against)} falls where the vehicle's rotor layout "
            "makes it rise with the logged motor speeds: are the rotors listed in the log's motor order, with their "
            "positions and spins (docs/flight.md)? The log is read as the vehicle file says"]


#: a sample is on the ground where the vehicle stands still (speed below GROUND_SPEED, rates below GROUND_RATE) with
#: the accelerometer reading g (within 20%) while its rotors' rms speed is below GROUND_FRACTION of the hover speed
#: (about half the weight or less, so that in flight the accelerometer would read 0.6 g or less: idling or spooling
#: up), the hover speed the log's own (_log_hover) where it lies within HOVER_RANGE of the generic set's, else that
GROUND_FRACTION = 0.7
#: a log whose rotors' rms speed stays below HOVER_RANGE[0] of the vehicle's hover speed (in its 95th percentile), or
#: runs above HOVER_RANGE[1] of it in the median, is refused: a mass in grams, motor speeds in rev/s (the generic
#: set's hover speed of the NeuroBEM vehicle is 1.16 times its logs' median)
HOVER_RANGE = (0.5, 2.5)
GROUND_SPEED = 0.5  # [m/s]
GROUND_RATE = 0.5  # [rad/s]
#: a log whose rotors' tip speed (each motor's 99th percentile) exceeds this Mach number (at SPEED_OF_SOUND) is
#: refused: no multirotor flies so, and a log of motor speeds in rpm read as rad/s (9.55x) reaches it
MAX_TIP_MACH = 1.0
#: the speed of sound of that check [m/s] (ISA sea level)
SPEED_OF_SOUND = 340.3


@dataclass(frozen=True)
class FlightSamples:
    """Samples of one or more flight logs for the force balance, N samples.

    Attributes
    ----------
    log_names : tuple of str
        The logs, in order.
    log_index : ndarray of int, shape (N,)
        Which log each sample comes from.
    t : ndarray, shape (N,)
        Time within its log [s].
    velocity, angular_velocity : ndarray, shape (N, 3)
        Body velocity over the ground [m/s] and rates [rad/s], body axes.
    rotor_omega, rotor_acceleration : ndarray, shape (N, n_rotors)
        Omega [rad/s] and dOmega/dt [rad/s^2] (zeros where the log has none), vehicle
        rotor order.
    force : ndarray, shape (N, 3)
        Measured aerodynamic force m a_s [N].
    moment : ndarray, shape (N, 3), or None
        Measured moment I dw/dt + w x I w [N m] (None without the vehicle's inertia).
    reference_force, reference_moment : ndarray, shape (N, 3), or None
        The logs' own model prediction (NeuroBEM's BEM + NN) where every log has one.
    reference_mass : tuple of float
        Per log (as ``log_names``), the mass [kg] its prediction was made for
        (``FlightLog.reference_mass``), NaN where unknown; () for samples built by hand.
    rate_hz : float
        Sampling rate of the samples [Hz]: the one asked for, or a log's own where it is
        lower (the median over the logs).
    notes : tuple of str
        The samples :func:`flight_samples` left out, per log and reason (a stopped rotor, the
        vehicle on the ground).

    Raises
    ------
    ValueError
        Built by hand with an array that is not numbers of its shape (N the length of
        ``t``; n_rotors >= 1, the same in both rotor arrays), a non-finite value, a
        ``rotor_omega`` <= 0 rad/s (:func:`flight_samples` leaves a stopped rotor's samples
        out), a ``log_index`` that is not an index of ``log_names``, or a ``rate_hz`` not > 0;
        the message names the field.
    """

    log_names: tuple[str, ...]
    log_index: np.ndarray
    t: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    rotor_omega: np.ndarray
    rotor_acceleration: np.ndarray
    force: np.ndarray
    moment: np.ndarray | None
    reference_force: np.ndarray | None
    reference_moment: np.ndarray | None
    rate_hz: float
    notes: tuple = ()
    reference_mass: tuple = ()

    def __post_init__(self):
        n = first_length("FlightSamples", "t", self.t)
        rotors = np.shape(self.rotor_omega)[1] if np.ndim(self.rotor_omega) == 2 else 0
        rotors = rotors or "n_rotors"  # at least one
        shapes = {"t": (n,), "velocity": (n, 3), "angular_velocity": (n, 3), "rotor_omega": (n, rotors),
                  "rotor_acceleration": (n, rotors), "force": (n, 3), "moment": (n, 3), "reference_force": (n, 3),
                  "reference_moment": (n, 3)}
        for name, shape in shapes.items():
            value = getattr(self, name)
            if value is not None or name not in ("moment", "reference_force", "reference_moment"):
                object.__setattr__(self, name, float_array("FlightSamples", name, value, shape, row="sample"))
        if np.any(self.rotor_omega <= 0):
            raise ValueError(f"FlightSamples.rotor_omega must be > 0 rad/s, got {self.rotor_omega.min():g} "
                             "(flight_samples leaves a stopped rotor's samples out)")
        index = np.array(self.log_index)  # (a copy: the frozen samples do not share the caller's array)
        if index.shape != (n,) or (n and (index.dtype.kind not in "iu" or index.min() < 0
                                          or index.max() >= len(self.log_names))):
            raise ValueError(f"FlightSamples.log_index must be N = {n} indices into log_names "
                             f"({len(self.log_names)} logs)")
        object.__setattr__(self, "log_index", index)
        rate = self.rate_hz
        if isinstance(rate, bool) or not isinstance(rate, (int, float, np.number)) or not 0 < rate < np.inf:
            raise ValueError(f"FlightSamples.rate_hz must be a rate > 0 Hz, got {rate!r:.60}")

    @property
    def n(self) -> int:
        """Number of samples N."""
        return self.t.size

    @property
    def speed(self) -> np.ndarray:
        """|v| [m/s], shape (N,)."""
        return np.linalg.norm(self.velocity, axis=1)

    def select(self, mask) -> "FlightSamples":
        """The samples where ``mask`` holds.

        Parameters
        ----------
        mask : array_like of bool, shape (N,)

        Returns
        -------
        FlightSamples
            Every per-sample array cut to the samples kept (the rest as they are).

        Raises
        ------
        ValueError
            ``mask`` not booleans (integer indices are refused) or not of shape (N,).
        """
        m = boolean_mask("FlightSamples.select", mask, self.t.shape[0])
        kw = {}
        for name in ("log_index", "t", "velocity", "angular_velocity", "rotor_omega", "rotor_acceleration", "force",
                     "moment", "reference_force", "reference_moment"):
            a = getattr(self, name)
            kw[name] = None if a is None else a[m]
        return replace(self, **kw)

    def of_log(self, k: int) -> "FlightSamples":
        """The samples of log ``k`` (an index into ``log_names``).

        Returns
        -------
        FlightSamples
        """
        return self.select(self.log_index == k)


def flight_samples(logs, vehicle: Vehicle, *, rate_hz: float = 25.0,
                   motor_time_constant: float | None = None) -> FlightSamples:
    """Samples of the logs at ``rate_hz`` with their measured force and moment.

    Parameters
    ----------
    logs : sequence of FlightLog
    vehicle : Vehicle
        Its rotors in each log's motor order; its mass (and inertia, for moments); its
        ``motor_time_constant``.
    rate_hz : float
        Sampling rate [Hz], in (0, 10000]: every k-th sample of a log, k = round(log rate /
        rate_hz) (at least 1). dw/dt, where a log has none, is differentiated from w at the
        log's own rate first.
    motor_time_constant : float, optional
        tau [s], in [0, 1]: the rotors' speed is the logged motor speed passed through a
        first-order lag, tau dOmega/dt = Omega_logged - Omega (at the log's own rate, from
        the first sample; dOmega/dt then that of the lagged speed). For logs whose motor
        speeds lead the rotors' (commands or the ESC's estimate: the NeuroBEM vehicle's
        motors have tau = 33 ms in its authors' simulator). Default the vehicle's (0: the
        logged speeds as they are).

    Returns
    -------
    FlightSamples

    Raises
    ------
    ValueError
        No logs, a log whose motor count differs from the vehicle's rotor count, a rotor
        whose tip speed (its speed's 99th percentile) exceeds Mach 1 (:data:`MAX_TIP_MACH`:
        motor speeds in rpm read as rad/s), a log whose rotors run far from the vehicle's hover
        speed (:data:`HOVER_RANGE`: a mass in grams, motor speeds in rev/s), a bad rate, or a
        log with no sample left (a rotor stopped, or the vehicle on the ground, in every
        sample; the message names it).

    Notes
    -----
    Samples are left out (``FlightSamples.notes`` says how many, per log) where a rotor is
    stopped, by its logged speed or through the motor lag (OMEGA_STOPPED), and where the
    vehicle stands on the ground (GROUND_FRACTION): there the measured force is the ground's
    reaction, which no rotor model makes (idling or spooling-up rotors with the accelerometer reading g).
    The notes also name, per log, a motor whose median speed lies beyond MOTOR_SPREAD of its
    propeller's other motors' or whose speed varies less than MOTOR_STILL as much as the most
    varying of them (a frozen reading), and, where the vehicle has an inertia, a measured
    moment that falls where the rotor layout makes it rise (LAYOUT_T: motor order, positions or
    spins); the samples are read as logged.
    """
    logs = list(logs)
    if not logs:
        raise ValueError("no flight logs given")
    # (a bool is not a rate: rate_hz=True was read as 1 Hz, motor_time_constant=True as 1 s, a mutation audit)
    rate_hz = checked("rate_hz", rate_hz, 0.0, 1e4, low_open=True, unit="Hz")  # (NumPy numbers too)
    given = vehicle.motor_time_constant if motor_time_constant is None else motor_time_constant
    tau = checked("motor_time_constant", given, 0.0, 1.0, unit="s")
    radii = np.array([r.propeller.radius for r in vehicle.rotors])
    parts, rates, notes, left_out = [], [], [], {}
    hover = _hover_speed(vehicle)
    layout = _layout_moments(vehicle, hover) if vehicle.inertia is not None else None
    for k, log in enumerate(logs):
        part, rate, said, left_out[log.name] = _log_part(k, log, vehicle, rate_hz, tau, radii, hover, layout)
        parts.append(part)
        rates.append(rate)
        notes += said
    out = {}
    for key in parts[0]:
        vals = [p[key] for p in parts]
        out[key] = None if any(v is None for v in vals) else np.concatenate(vals)
    empty = [log.name for k, log in enumerate(logs) if not np.any(out["log_index"] == k)]
    if empty:  # (said which: idling rotors on the ground were called stopped, a flight-log audit, 2026-11-27)
        n_stopped, n_ground = left_out.get(empty[0], (0, 0))
        raise ValueError(f"{empty[0]}: no samples left: {n_stopped} with a rotor stopped (below {OMEGA_STOPPED:g} "
                         f"rad/s) and {n_ground} on the ground (standing still, the accelerometer reading g, the "
                         f"rotors below {GROUND_FRACTION:g} of the hover speed)")
    return FlightSamples(log_names=tuple(log.name for log in logs), rate_hz=float(np.median(rates)),
                         notes=tuple(notes), reference_mass=tuple(math.nan if log.reference_mass is None else
                                                                  float(log.reference_mass) for log in logs), **out)


def _log_part(k: int, log, vehicle, rate_hz: float, tau: float, radii: np.ndarray, hover, layout):
    """One log's samples for flight_samples: (the FlightSamples fields of its samples kept, its
    sampling rate taken [Hz], its notes, (samples with a stopped rotor, samples on the ground)
    left out); ValueError for a log that is not a FlightLog, has another motor count than the
    vehicle's rotors, tips beyond MAX_TIP_MACH, no sample with every rotor turning, or rotor
    speeds far from the vehicle's hover speed (:func:`_check_hover`)."""
    n_rot = len(vehicle.rotors)
    if not isinstance(log, FlightLog):
        raise ValueError(f"logs must be FlightLog records (io.flightlog.read_flight_log), got {type(log).__name__}")
    if log.n_motors != n_rot:
        more = ("; the NeuroBEM layout carries 4 motors, a vehicle of more rotors needs a PX4 ULog"
                if log.format == "neurobem" and n_rot > 4 else "")
        raise ValueError(f"{log.name}: {log.n_motors} motor speeds but the vehicle has {n_rot} rotors (the "
                         f"vehicle file lists its rotors in the log's motor order{more})")
    step = max(1, int(round(log.rate_hz / rate_hz)))
    notes = []
    wdot = log.angular_acceleration if log.angular_acceleration is not None else np.gradient(
        log.angular_velocity, log.t, axis=0)
    # the 99th percentile of each motor's speed: one telemetry spike does not refuse a log
    om99 = np.percentile(log.rotor_omega, 99, axis=0) if log.n else np.zeros(n_rot)
    tip = om99 * radii
    if np.any(tip > MAX_TIP_MACH * SPEED_OF_SOUND):
        i = int(np.argmax(tip))
        cause = ("are the log's motor speeds in rpm? A CSV or .mat log's are read in rad/s" if log.format != "ulog"
                 else "check the ESC rpm or the motor map (docs/cli.md) and the vehicle's rotors")
        raise ValueError(f"{log.name}: motor {i + 1} runs at {om99[i]:.0f} rad/s (99th percentile), a tip speed "
                         f"of Mach {tip[i] / SPEED_OF_SOUND:.2f} on its {radii[i]:g} m rotor: {cause} "
                         "(docs/flight.md)")
    reference = _ground_reference(log, hover)
    sl = slice(None, None, step)
    om_full, omdot_full = _lagged(log, tau)
    om = om_full[sl]
    # a stopped rotor: the logged speed (the lagged one decays for a few time constants after a stop) or the lag's
    logged = log.rotor_omega[sl]
    stopped = ~(np.all(om >= OMEGA_STOPPED, axis=1) & np.all(logged >= OMEGA_STOPPED, axis=1))
    ground = ~stopped & _on_ground(logged, log.specific_force[sl], log.velocity[sl], log.angular_velocity[sl],
                                   stopped, reference)
    keep = ~(stopped | ground)
    if not keep.any() and stopped.all():  # name the motor and the likely cause (a fuzzing audit: 0-1 speeds)
        low = np.max(logged, axis=0) < OMEGA_STOPPED
        which = (f"motor(s) {', '.join(str(i + 1) for i in np.flatnonzero(low))} below {OMEGA_STOPPED:g} rad/s "
                 "in every sample" if low.any() else "some rotor stopped in every sample")
        raise ValueError(f"{log.name}: no samples left: {which} (largest logged speed {float(logged.max()):.3g} "
                         "rad/s): motor speeds normalised to 0-1, a throttle, or a motor not logged?")
    notes += _motor_spread(log, logged[keep], vehicle)
    _check_hover(log, logged[keep], vehicle, hover)
    if stopped.any():
        notes.append(f"{log.name}: {int(stopped.sum())} sample(s) with a stopped rotor (Omega < {OMEGA_STOPPED:g} "
                     "rad/s, logged or through the motor lag) left out")
    if ground.any():
        notes.append(f"{log.name}: {int(ground.sum())} sample(s) on the ground left out (standing still, the "
                     f"accelerometer reading g, the rotors below {GROUND_FRACTION:g} of the hover speed: the "
                     "ground's reaction, which no rotor model makes)")
    w = log.angular_velocity[sl][keep]
    if vehicle.inertia is not None:
        inertia = vehicle.inertia
        moment = wdot[sl][keep] @ inertia.T + np.cross(w, w @ inertia.T)
        notes += _layout_note(log, logged[keep], moment, layout, log.rate_hz / step)
    else:
        moment = None
    acc = omdot_full[sl][keep] if omdot_full is not None else np.zeros((keep.sum(), n_rot))
    part = dict(log_index=np.full(keep.sum(), k), t=log.t[sl][keep], velocity=log.velocity[sl][keep],
                angular_velocity=w, rotor_omega=om[keep], rotor_acceleration=acc,
                force=vehicle.mass * log.specific_force[sl][keep], moment=moment,
                reference_force=None if log.reference_force is None else log.reference_force[sl][keep],
                reference_moment=None if log.reference_moment is None else log.reference_moment[sl][keep])
    return part, log.rate_hz / step, notes, (int(stopped.sum()), int(ground.sum()))


def _on_ground(omega, specific_force, velocity, angular_velocity, stopped, hover) -> np.ndarray:
    """Samples where the ground carries the vehicle (GROUND_FRACTION, GROUND_SPEED, GROUND_RATE):
    standing still with the accelerometer reading g (within 20%) [m/s^2] while the rotors' rms
    speed is below GROUND_FRACTION of ``hover`` [rad/s] (:func:`_ground_reference`; where that
    is 0, the running samples' median rms speed): rotors idling or spooling up, which cannot
    carry half the weight."""
    g = G0
    rms = np.sqrt(np.mean(omega**2, axis=1))
    running = ~stopped
    if not running.any():
        return np.zeros(len(rms), dtype=bool)
    reference = hover if hover > 0 else float(np.median(rms[running]))
    f = np.linalg.norm(specific_force, axis=1)
    still = ((np.linalg.norm(velocity, axis=1) < GROUND_SPEED)
             & (np.linalg.norm(angular_velocity, axis=1) < GROUND_RATE))
    return still & (np.abs(f - g) < 0.2 * g) & (rms < GROUND_FRACTION * reference)


def _log_hover(log: FlightLog) -> float:
    """The log's own hover speed [rad/s]: the rms rotor speed at which the rotors would carry the
    vehicle, from the accelerometer's reading |f| against sum_i Omega_i^2 in the fastest quarter
    of the running samples (in flight |f| m = k sum_i Omega_i^2, whatever the mass; on the ground
    the reading is g at any speed, so the fastest samples are the flight's): sqrt(g / (n k)). 0
    without running samples."""
    running = np.all(log.rotor_omega >= OMEGA_STOPPED, axis=1)
    if not running.any():
        return 0.0
    sq = np.sum(log.rotor_omega[running] ** 2, axis=1)
    fast = sq >= np.percentile(sq, 75)
    k = float(np.median(np.linalg.norm(log.specific_force[running][fast], axis=1) / sq[fast]))
    return math.sqrt(G0 / (log.n_motors * k)) if k > 0 else 0.0


def _ground_reference(log: FlightLog, hover: float) -> float:
    """The hover speed the ground rule compares with [rad/s]: the log's own (:func:`_log_hover`)
    where it lies within HOVER_RANGE of the model's ``hover`` (the generic set's, 1.16 times the
    NeuroBEM logs' own), else the model's (a log all on the ground, or a mass in other units,
    which :func:`_check_hover` then refuses); the log's own where the model gives none."""
    own = _log_hover(log)
    if hover <= 0:
        return own
    return own if HOVER_RANGE[0] * hover <= own <= HOVER_RANGE[1] * hover else hover


def _check_hover(log: FlightLog, omega, vehicle: Vehicle, hover: float) -> None:
    """Refuse a log whose kept samples' rms rotor speed (``omega``, shape (N, n_rotors) [rad/s],
    neither stopped nor on the ground) is far from the vehicle's hover speed ``hover`` [rad/s]
    (HOVER_RANGE; not judged where that is 0)."""
    if hover <= 0 or not len(omega):
        return
    rms = np.sqrt(np.mean(np.asarray(omega) ** 2, axis=1))
    high, median = float(np.percentile(rms, 95)), float(np.median(rms))
    if high < HOVER_RANGE[0] * hover or median > HOVER_RANGE[1] * hover:
        units = ("are the motor speeds in rad/s (not rev/s)" if log.format != "ulog" else
                 "are the ESC rpm mechanical (electrical rpm is pole pairs times it) or the --motor-map right"
                 # (PX4's Gazebo bridge writes esc_rpm in rad/s: GZMixingInterfaceESC.cpp; refused without the cause,
                 # a PX4 audit, 2026-12-02)
                 + (", and rpm, not rad/s (PX4's Gazebo simulation logs esc_rpm in rad/s)"
                    if 0.8 * RPM < median / hover < 1.25 * RPM else ""))  # (rad/s read as rpm: RPM times too slow)
        raise ValueError(f"{log.name}: the rotors' rms speed is {median:.4g} rad/s in the median and {high:.4g} in "
                         f"its 95th percentile, {median / hover:.2g} and {high / hover:.2g} times the vehicle's hover "
                         f"speed {hover:.4g} rad/s (its mass {vehicle.mass:g} kg, the generic set): is the mass in kg "
                         f"and {units}? (docs/flight.md)")


#: the rotor speeds [rad/s] at which _hover_speed evaluates the static thrust, one batch (steps of 16%)
HOVER_GRID = np.geomspace(10.0, 1e5, 64)


def _hover_speed(vehicle: Vehicle) -> float:
    """The generic set's hover speed of the vehicle [rad/s], every rotor at one speed: sum_i T_i
    (a_i . e_z) = m g (:func:`propmap.vehicle.hover_omega` without an airframe in the slipstream
    or the rotors' interference, which it includes; on HOVER_GRID's 64 rates, 24 x 8
    nodes, interpolated in log T against log Omega, within 0.1% for T ~ Omega^2). One batch of the
    kernel the flight commands load anyway: hover_omega's root finder cost `wrench` 0.25 s of
    start-up (SciPy's import and the scalar kernel's cache). 0 where the rotors cannot carry the
    weight within the grid, or a solve fails."""
    from ..core.solver import Discretization, SolverError, rotor_loads, supersonic_tips_allowed
    from ..io.calibration import generic_params

    p = generic_params()
    lift = np.zeros(HOVER_GRID.size)
    try:
        with supersonic_tips_allowed():  # the search grid's top reaches supersonic tips: not a hover, not the user's
            for r in vehicle.rotors:
                up = float(r.axis[2]) / float(np.linalg.norm(r.axis))
                if up > 0:
                    lift += up * rotor_loads(r.propeller, r.params or p, HOVER_GRID, 0.0, 0.0,
                                             discretization=Discretization(24, 8)).thrust
    except (SolverError, ValueError, ArithmeticError):
        return 0.0
    k = int(np.argmax(lift >= vehicle.weight)) if np.any(lift >= vehicle.weight) else 0
    if k == 0 or not lift[k - 1] > 0:
        return 0.0
    t = np.log(vehicle.weight / lift[k - 1]) / np.log(lift[k] / lift[k - 1])
    return float(np.exp(np.log(HOVER_GRID[k - 1]) + t * np.log(HOVER_GRID[k] / HOVER_GRID[k - 1])))


def _lagged(log: FlightLog, tau: float):
    """(Omega, dOmega/dt) of the rotors: the logged speeds through a first-order lag of time
    constant ``tau``, d Omega/dt = (x - Omega) / tau, x the logged speed taken linear between
    samples (the lag's exact response to that input, a first-order hold)."""
    if tau == 0:
        return log.rotor_omega, log.rotor_acceleration
    # om_i = om_{i-1} + a (x_{i-1} - om_{i-1}) + b (x_i - x_{i-1}), a = 1 - exp(-h / tau), b = 1 - tau a / h, h the
    # step: exact for x linear over the step (a ramp's steady lag is tau times its slope). Until 2026-11-28 the step
    # applied x_i over the whole interval before it (om_i = om_{i-1} + a (x_i - om_{i-1})): a lag half a sample short,
    # and a log's prediction that moved with its sampling rate (the melon log at 50 Hz against 400 Hz: the lagged
    # speeds 3.3 rad/s rms apart, a flight-log audit; 0.77 rad/s rms, 5.7 at most, with this form). Sample by sample
    # in Python floats, 15-20 ms for a 30 s log at 400 Hz (scipy.signal.lfilter would need scipy.signal, whose import
    # alone takes 0.3-0.9 s of `propmap wrench`; NumPy row operations take 20x the loop)
    h = np.diff(log.t)
    a = -np.expm1(-h / tau)  # (without the cancellation of 1 - exp for a step far shorter than tau)
    with np.errstate(divide="ignore", invalid="ignore"):  # (a repeated time, h = 0, holds the speed: a = b = 0)
        b = np.where(h > 0, 1.0 - tau * a / np.where(h > 0, h, 1.0), 0.0)
    rows = log.rotor_omega.tolist()
    prev = rows[0]
    out = [prev]
    for i, (ai, bi) in enumerate(zip(a.tolist(), b.tolist()), start=1):
        prev = [p + ai * (u - p) + bi * (v - u) for p, u, v in zip(prev, rows[i - 1], rows[i])]
        out.append(prev)
    om = np.array(out)
    return om, (log.rotor_omega - om) / tau
