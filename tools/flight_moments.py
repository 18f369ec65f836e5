"""Where propmap's body moments go wrong on the NeuroBEM flight logs, measured.

Data: the four NeuroBEM segments (Bauersfeld et al., "NeuroBEM: Hybrid Aerodynamic
Quadrotor Model", RSS 2021; ../shared/data/neurobem_flights), the bundled vehicle
data/examples/neurobem_quadrotor.toml, the generic set's air (rho = 1.225 kg/m^3; the CLI
examples in docs/flight.md use the logs' 1.204). The rotor and airframe parameters are the
default flight fit to the forces of all four logs (``fit_flight``, 25 samples a second), so
the moments are predicted by a model that never saw them.

    .venv/bin/python tools/flight_moments.py      # 30-80 s on 2 cores (78 s under load, 2026-12-02)

The default fit carries the vehicle file's motor lag (33 ms); items 4 and 5 also run without it.

Prints the numbers of docs/flight.md, "Moments: what the errors are made of":

1. roll and pitch moment rms of propmap, the zero predictor and NeuroBEM's BEM + NN (the
   logs' columns 33-35, trained on these flights);
2. the pitching-moment error against forward speed (|v_y| < 1.5 m/s) with the logged
   rear-minus-front rotor speed, and the rolling-moment error against lateral speed;
3. the same moments with the optional physics at the default fit's parameters (not
   refitted): Pitt-Peters and Drees inflow, flapping blades;
4. how much of the error a linear correction in the body velocity, a gain on the predicted
   moment and the body rates removes, each log predicted by the correction fitted on the
   other three (what a missing term of that form could give), with and without the lag;
5. the motor lag: force error and moment correlation with and without the 33 ms lag, and
   near hover the ratio of measured to predicted roll moment, by regressing each on the
   other (an error in the prediction pulls the first down, one in the measurement the
   second up);
6. the rotor arms the moment channel implies near hover (|v| < 0.5 m/s, 100 samples a
   second, no lag): the measured roll and pitch moments regressed on the thrust differences
   of T_i = k Omega_i^2 (k fitted to the measured vertical force of the same samples), with
   the body velocity and a constant, each way round, against the vehicle file's arms;
7. the rigid-body constants such errors could point to, fitted leave-one-log-out to the roll
   and pitch moments: an inertia scale per axis and the centre of mass' height (which gives
   the in-plane forces an arm).
"""

from __future__ import annotations

import argparse
from dataclasses import replace
from pathlib import Path

import numpy as np

from propmap.identify.flight import fit_flight, fitted_body_drag, fitted_vehicle, flight_samples, predict_flight
from propmap.io.flightlog import read_flight_log
from propmap.vehicle import read_vehicle
from _neurobem import log_paths  # (tools/, the script's folder)

ROOT = Path(__file__).resolve().parents[1]
VEHICLE = ROOT / "src" / "propmap" / "data" / "examples" / "neurobem_quadrotor.toml"


def rms(a) -> float:
    """Root mean square over every entry."""
    return float(np.sqrt(np.mean(np.square(a))))


def main() -> None:
    vehicle = read_vehicle(VEHICLE)
    logs = [read_flight_log(p) for p in log_paths()]
    s = flight_samples(logs, vehicle)
    res = fit_flight(s, vehicle)
    body, veh = fitted_body_drag(res), fitted_vehicle(vehicle, res)
    w = predict_flight(s, veh, res.params, body=body)
    e = w.moment - s.moment
    print(f"{s.n} samples; force F {rms(w.force - s.force):.3f} N (in-sample)")
    nn = rms(s.reference_moment[:, :2] - s.moment[:, :2])
    print(f"1. roll+pitch moment rms [N m]: propmap {rms(e[:, :2]):.4f} (roll {rms(e[:, 0]):.4f}, pitch "
          f"{rms(e[:, 1]):.4f}); zero {rms(s.moment[:, :2]):.4f}; NeuroBEM BEM + NN {nn:.4f}")

    vx, vy = s.velocity[:, 0], s.velocity[:, 1]
    om = s.rotor_omega  # back-right, front-right, back-left, front-left
    print("2. pitching-moment error by forward speed (|v_y| < 1.5 m/s): v_x [m/s], n, error [N m], measured "
          "[N m], rear - front Omega [rad/s]")
    for lo in range(-5, 6):
        m = (vx >= lo) & (vx < lo + 1) & (np.abs(vy) < 1.5)
        if m.sum() >= 10:
            d = (om[m][:, [0, 2]].mean(1) - om[m][:, [1, 3]].mean(1)).mean()
            print(f"   {lo:+d}..{lo + 1:+d}  {m.sum():4d}  {e[m, 1].mean():+.4f}  {s.moment[m, 1].mean():+.4f}  "
                  f"{d:+6.1f}")
    X = np.c_[s.velocity, np.ones(s.n)]
    c = [np.linalg.lstsq(X, e[:, k], rcond=None)[0] for k in (0, 1)]
    print(f"   slopes: pitch error {c[1][0]:+.4f} N m per m/s of v_x, roll error {c[0][1]:+.4f} per m/s of v_y")

    print("3. optional physics at the default fit's parameters (F [N], roll+pitch moment rms [N m], pitch slope):")
    for inflow, comp in (("uniform", 0.0), ("pitt-peters", 0.0), ("drees", 0.0), ("uniform", 4.0),
                         ("pitt-peters", 2.0)):
        p = replace(res.params, inflow=inflow, flap_compliance=comp)
        wp = predict_flight(s, veh, p, body=body)
        ep = wp.moment - s.moment
        slope = np.linalg.lstsq(X, ep[:, 1], rcond=None)[0][0]
        print(f"   {inflow:<12} flap_compliance {comp:g}: F {rms(wp.force - s.force):.3f}, M {rms(ep[:, :2]):.4f}, "
              f"{slope:+.4f}")

    print("4. linear corrections of the roll and pitch errors, each log predicted from the other three [N m]:")
    for tau in (vehicle.motor_time_constant, 0.0):
        sl = flight_samples(logs, vehicle, motor_time_constant=tau)
        wl = predict_flight(sl, veh, res.params, body=body)
        one = np.ones((sl.n, 1))
        terms = {"velocity": lambda k: np.c_[sl.velocity, one],
                 "gain on the predicted moment, velocity": lambda k: np.c_[wl.moment[:, k], sl.velocity, one],
                 "gain, velocity, body rates": lambda k: np.c_[wl.moment[:, k], sl.velocity, sl.angular_velocity, one]}
        for name, design in terms.items():
            out = np.empty((sl.n, 2))
            for k in (0, 1):
                A, err = design(k), wl.moment[:, k] - sl.moment[:, k]
                for j in range(len(sl.log_names)):
                    tr, te = sl.log_index != j, sl.log_index == j
                    out[te, k] = err[te] - A[te] @ np.linalg.lstsq(A[tr], err[tr], rcond=None)[0]
            print(f"   motor lag {tau * 1e3:4.1f} ms, after {name}: {rms(out):.4f}")

    print("5. motor lag (first-order, on the logged speeds):")
    for tau in (0.0, vehicle.motor_time_constant):
        sl = flight_samples(logs, vehicle, motor_time_constant=tau)
        wl = predict_flight(sl, veh, res.params, body=body)
        r = [np.corrcoef(wl.moment[:, k], sl.moment[:, k])[0, 1] for k in (0, 1)]
        slow = sl.speed < 1.0
        a, b = wl.moment[slow, 0], sl.moment[slow, 0]
        print(f"   tau {tau * 1e3:4.1f} ms: F {rms(wl.force - sl.force):.3f} N; correlation of predicted and "
              f"measured roll {r[0]:.2f}, pitch {r[1]:.2f}; below 1 m/s the roll moments' correlation "
              f"{np.corrcoef(a, b)[0, 1]:.2f}, measured / predicted {(a @ b) / (a @ a):.2f} (measured regressed "
              f"on predicted) to {(b @ b) / (a @ b):.2f} (the reverse)")

    print("6. arms implied by the moments near hover (|v| < 0.5 m/s, 100 Hz, no lag) [m]:")
    sh = flight_samples(logs, vehicle, rate_hz=100.0, motor_time_constant=0.0)
    sh = sh.select(sh.speed < 0.5)
    om2 = sh.rotor_omega**2
    k = float(om2.sum(axis=1) @ sh.force[:, 2] / (om2.sum(axis=1) @ om2.sum(axis=1)))
    pos = np.array([r.position for r in vehicle.rotors])
    for axis, label, sign, arm in ((0, "lateral (roll)", np.sign(pos[:, 1]), np.abs(pos[:, 1]).mean()),
                                   (1, "fore-aft (pitch)", -np.sign(pos[:, 0]), np.abs(pos[:, 0]).mean())):
        x = (k * om2 * sign).sum(axis=1)  # the moment per metre of arm [N]
        y = sh.moment[:, axis]
        V = np.c_[sh.velocity, np.ones(sh.n)]  # the velocity and a constant partialled out of both
        x = x - V @ np.linalg.lstsq(V, x, rcond=None)[0]
        y = y - V @ np.linalg.lstsq(V, y, rcond=None)[0]
        print(f"   {label:<16}: {(x @ y) / (x @ x):.4f} (moment on thrust difference) to {(y @ y) / (x @ y):.4f} "
              f"(the reverse), correlation {np.corrcoef(x, y)[0, 1]:.2f}; the vehicle file's {arm:.3f}; {sh.n} "
              f"samples, k = {k:.3e} N s^2")

    print("7. rigid-body constants, each log predicted with those fitted on the other three [N m]:")
    rigid_body_constants(s, w)


def rigid_body_constants(s, w) -> None:
    """Item 7: the two vehicle constants that a moment error of this shape could point to,
    fitted by least squares to the roll and pitch moments of three logs and scored on the
    fourth. An inertia scale per axis, I_true = s_a I_file: the moment computed from the rates
    with the file's inertia is then the model's divided by s_a (a gain 1 / s_a on the predicted
    moment; the gyroscopic cross terms left as the file's). The centre of mass' height: moving
    it by dz moves every force's arm, M -> M + (dz F_y, -dz F_x, 0) with F the model's total
    aerodynamic force, so that the in-plane forces (rotor and airframe drag) make a moment that
    grows with speed."""
    from scipy.optimize import least_squares

    Mp, Mm = w.moment[:, :2], s.moment[:, :2]
    lever = np.stack([w.force[:, 1], -w.force[:, 0]], axis=1)
    variants = {"inertia scales and centre-of-mass height": (lambda p: p, [1.0, 1.0, 0.0]),
                "inertia scales": (lambda p: [*p, 0.0], [1.0, 1.0]),
                "centre-of-mass height": (lambda p: [1.0, 1.0, p[0]], [0.0])}
    for name, (full, start) in variants.items():
        out, fitted = np.empty_like(Mm), []
        for j in range(len(s.log_names)):
            tr, te = s.log_index != j, s.log_index == j
            q = full(least_squares(lambda p: (np.multiply(full(p)[:2], Mp[tr] + full(p)[2] * lever[tr])
                                              - Mm[tr]).ravel(), start).x)
            out[te] = np.multiply(q[:2], Mp[te] + q[2] * lever[te]) - Mm[te]
            fitted.append(f"{1 / q[0]:.1f}, {1 / q[1]:.1f}, {q[2] * 1e3:+.0f} mm")
        print(f"   {name}: {rms(out):.4f} (zero {rms(Mm):.4f}); I_xx / file's, I_yy / file's, dz per fold: "
              f"{'; '.join(fitted)}")


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
