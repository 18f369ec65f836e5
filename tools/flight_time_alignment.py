"""Are the NeuroBEM logs' body moments and motor speeds misaligned in time? Measured.

Data: the four NeuroBEM segments (Bauersfeld et al., "NeuroBEM: Hybrid Aerodynamic Quadrotor
Model", RSS 2021; ../shared/data/neurobem_flights, 400 Hz) and the bundled vehicle
data/examples/neurobem_quadrotor.toml (mass, inertia, hub positions and spins, the authors'
values). The rotor model is the simplest one that carries the control moments: T_i = k Omega_i^2
at the hubs, k fitted through 0 to the measured vertical force m a_z (so nothing here is fitted to
the moments). Measured moment: I dw/dt + w x I w from the logs' angular acceleration.

    .venv/bin/python tools/flight_time_alignment.py      # about 6 s on 2 cores

Prints the numbers of docs/flight.md, "Not a time offset":

1. the shift of the predicted roll and pitch moments (and of k sum Omega^2 against m a_z) that
   maximises their correlation with the measured ones, pooled over the logs, raw and in a 2-15 Hz
   band (the same zero-phase Butterworth filter on both signals), with the correlation and the
   least-squares gain (measured on predicted) at 0 and at that shift; a positive shift means the
   measured signal lags the motor speeds;
2. the logs' angular acceleration against the central difference of their rates: gain and delay
   by frequency (the logs' own filtering); the measured m a_z against k sum Omega^2 (amplitude
   ratio by frequency) and the vertical force's rms in sample with the prediction as it is, through
   the vehicle file's 33 ms first-order lag and through a zero-phase smoothing of 120 ms (the same
   first-order filter forward and backward); the coherence of the measured and predicted moments
   by frequency;
3. each log predicted with the shift, or a first-order low-pass of 5-60 ms, chosen per axis on
   the other three logs, with and without a gain per axis fitted there: roll and pitch rms against
   the zero predictor's.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from scipy import signal

from propmap.io.flightlog import read_flight_log
from propmap.vehicle import read_vehicle
from _neurobem import log_paths  # (tools/, the script's folder)

ROOT = Path(__file__).resolve().parents[1]
VEHICLE = ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml"
RATE = 400.0  # the logs' sample rate [Hz]
EDGE = 80  # samples trimmed at each end, so that every shift scores the same samples (200 ms)
SHIFTS = np.arange(-EDGE, EDGE + 1)  # [samples], 2.5 ms apart
TAUS = np.arange(5, 65, 5) * 1e-3  # the low-pass' time constants [s]


def rms(a) -> float:
    """Root mean square over every entry."""
    return float(np.sqrt(np.mean(np.square(a))))


def interior(x):
    return x[EDGE:len(x) - EDGE]


def delayed(x, s: int):
    """x delayed by s samples, on the interior samples."""
    return x[EDGE - s:len(x) - EDGE - s]


def lowpass(x, tau: float):
    """A causal first-order low-pass of time constant tau [s], started at rest at x[0]."""
    a = 1.0 - np.exp(-1.0 / (RATE * tau))
    return signal.lfilter([a], [1.0, a - 1.0], x, axis=0, zi=np.full((1,) + x.shape[1:], (1.0 - a) * x[0]))[0]


def band(x):
    """2-15 Hz, zero phase (fourth-order Butterworth, forward and backward)."""
    return signal.sosfiltfilt(signal.butter(4, (2.0, 15.0), "bandpass", fs=RATE, output="sos"), x, axis=0)


def read(path, vehicle):
    """The log's measured (roll, pitch) moment and m a_z, and per unit k the predicted ones."""
    log = read_flight_log(path)
    inertia = np.asarray(vehicle.inertia, dtype=float)
    w, dw = log.angular_velocity, log.angular_acceleration
    moment = dw @ inertia.T + np.cross(w, w @ inertia.T)
    pos = np.array([r.position for r in vehicle.rotors])
    om2 = log.rotor_omega ** 2
    per_k = np.c_[om2 @ pos[:, 1], -(om2 @ pos[:, 0])]  # sum y_i Omega_i^2, -sum x_i Omega_i^2
    return {"M": moment[:, :2], "Fz": vehicle.mass * log.specific_force[:, 2], "Mk": per_k,
            "Fk": om2.sum(axis=1), "w": w, "dw": dw}


def fit_k(logs) -> float:
    """k [N s^2] through 0: m a_z on sum Omega^2."""
    return sum(lg["Fk"] @ lg["Fz"] for lg in logs) / sum(lg["Fk"] @ lg["Fk"] for lg in logs)


def best_shift(pred, meas):
    """(corr at 0, gain at 0, best shift [ms], corr there, gain there), each log shifted apart."""
    cc, gg = [], []
    y = np.concatenate([interior(m) for m in meas])
    for s in SHIFTS:
        x = np.concatenate([delayed(p, s) for p in pred])
        cc.append(np.corrcoef(x, y)[0, 1])
        gg.append(x @ y / (x @ x))
    b, z = int(np.argmax(cc)), EDGE
    return cc[z], gg[z], 1e3 * SHIFTS[b] / RATE, cc[b], gg[b]


def held_out(logs, k_of, kind: str, gain: bool):
    """Roll and pitch errors of each log, the shift or time constant (and gain) chosen per axis on the others."""
    grid = SHIFTS if kind == "shift" else TAUS

    def pred(lg, k, val):
        p = k * lg["Mk"]
        return delayed(p, val) if kind == "shift" else interior(lowpass(p, val))

    errors = []
    for j, test in enumerate(logs):
        train = [lg for i, lg in enumerate(logs) if i != j]
        k = k_of(train)
        best = [None, None]
        for val in grid:
            P = np.concatenate([pred(lg, k, val) for lg in train])
            Y = np.concatenate([interior(lg["M"]) for lg in train])
            g = (P * Y).sum(0) / (P * P).sum(0) if gain else np.ones(2)
            for ax in range(2):
                r = rms(g[ax] * P[:, ax] - Y[:, ax])
                if best[ax] is None or r < best[ax][0]:
                    best[ax] = (r, val, g[ax])
        errors.append(np.c_[[best[ax][2] * pred(test, k, best[ax][1])[:, ax] - interior(test["M"])[:, ax]
                             for ax in range(2)]].T)
    return np.concatenate(errors)


def main() -> None:
    vehicle = read_vehicle(VEHICLE)
    logs = [read(p, vehicle) for p in log_paths()]
    k = fit_k(logs)
    print(f"k = {k:.4e} N s^2 (m a_z on sum Omega^2, all logs)")
    print("1. best shift (positive: the measured signal lags the motor speeds), pooled")
    print("   channel | band | corr at 0 | gain at 0 | best shift [ms] | corr there | gain there")
    for filt, name in ((lambda x: x, "raw"), (band, "2-15 Hz")):
        for label, ax in (("roll", 0), ("pitch", 1), ("m a_z", None)):
            if ax is None:
                pred = [filt(k * lg["Fk"]) for lg in logs]
                meas = [filt(lg["Fz"]) for lg in logs]
            else:
                pred = [filt(k * lg["Mk"][:, ax]) for lg in logs]
                meas = [filt(lg["M"][:, ax]) for lg in logs]
            c0, g0, sh, cb, gb = best_shift(pred, meas)
            print(f"   {label} | {name} | {c0:.3f} | {g0:.3f} | {sh:+.1f} | {cb:.3f} | {gb:.3f}")
    print("2. the logs' dw/dt against the central difference of their rates (all logs, three axes)")
    pxy = pxx = 0.0
    for lg in logs:
        diff = np.gradient(lg["w"], 1.0 / RATE, axis=0)
        for ax in range(3):
            f, c = signal.csd(diff[:, ax], lg["dw"][:, ax], fs=RATE, nperseg=1024)
            pxy, pxx = pxy + c, pxx + signal.welch(diff[:, ax], fs=RATE, nperseg=1024)[1]
    for fq in (5, 10, 15, 20, 30, 40, 60):
        i = int(np.argmin(np.abs(f - fq)))
        delay = -np.angle(pxy[i]) / (2 * np.pi * f[i]) * 1e3
        print(f"   {f[i]:5.1f} Hz: gain {abs(pxy[i]) / pxx[i]:.2f}, delay {delay:+.1f} ms")
    spectra = {}  # (cross, predicted, measured) power spectra summed over the logs, per channel
    for lg in logs:
        for name, x, y in (("m a_z", k * lg["Fk"], lg["Fz"]), ("roll", k * lg["Mk"][:, 0], lg["M"][:, 0]),
                           ("pitch", k * lg["Mk"][:, 1], lg["M"][:, 1])):
            f, c = signal.csd(x, y, fs=RATE, nperseg=512, detrend="linear")
            px = signal.welch(x, fs=RATE, nperseg=512, detrend="linear")[1]
            py = signal.welch(y, fs=RATE, nperseg=512, detrend="linear")[1]
            spectra[name] = tuple(a + b for a, b in zip(spectra.get(name, (0.0, 0.0, 0.0)), (c, px, py)))
    c, px, _ = spectra["m a_z"]
    print("   m a_z over k sum Omega^2: " + ", ".join(
        f"{abs(c[i]) / px[i]:.2f} at {f[i]:.1f} Hz" for i in (int(np.argmin(np.abs(f - q))) for q in (5, 10, 15, 20))))
    for name in ("roll", "pitch"):
        c, px, py = spectra[name]
        coh = np.abs(c) ** 2 / (px * py)
        print(f"   {name} moment coherence: below 1 Hz {coh[(f > 0) & (f < 1.0)].mean():.2f}, "
              f"3-12 Hz {coh[(f >= 3.0) & (f <= 12.0)].min():.2f}-{coh[(f >= 3.0) & (f <= 12.0)].max():.2f}")
    fz = np.concatenate([lg["Fz"] for lg in logs])
    for label, filt in (("as it is", lambda x: x), ("33 ms lag", lambda x: lowpass(x, 0.033)),
                        ("120 ms zero-phase", lambda x: lowpass(lowpass(x, 0.12)[::-1], 0.12)[::-1])):
        pred = np.concatenate([filt(k * lg["Fk"]) for lg in logs])
        print(f"   m a_z rms in sample, the prediction {label}: {rms(pred - fz):.3f} N")
    print("3. each log predicted with what the other three choose: roll / pitch rms [N m]")
    zero = np.concatenate([interior(lg["M"]) for lg in logs])
    print(f"   zero predictor: {rms(zero[:, 0]):.4f} / {rms(zero[:, 1]):.4f}")
    for kind in ("shift", "low-pass"):
        for gain in (False, True):
            e = held_out(logs, fit_k, "shift" if kind == "shift" else "lowpass", gain)
            print(f"   {kind}{' and a gain' if gain else ''}: {rms(e[:, 0]):.4f} / {rms(e[:, 1]):.4f}")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
