"""Mutation audit of identify/flight_scores.py (the flight fit's scores) and cli/flight.py
(`propmap fit flight`, `propmap wrench`): each test names the mutant it kills."""

from __future__ import annotations

import dataclasses
import json
import math
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.identify.flight import (FlightSamples, baseline_force, fit_baselines, flight_errors,
                                     reference_at_vehicle_mass, reference_errors)

VEHICLE = Path(str(resources.files("propmap") / "data" / "examples" / "neurobem_quadrotor.toml"))


def _S(force, v=None, moment=None, ref=None, ref_moment=None, ref_mass=(), om=None, w=None, names=("x",),
       index=None):
    force = np.asarray(force, float)
    n = len(force)
    return FlightSamples(log_names=names, log_index=np.zeros(n, int) if index is None else np.asarray(index),
                         t=np.arange(n * 1.0), velocity=np.zeros((n, 3)) if v is None else np.asarray(v, float),
                         angular_velocity=np.zeros((n, 3)) if w is None else np.asarray(w, float),
                         rotor_omega=np.full((n, 4), 1000.0) if om is None else np.asarray(om, float),
                         rotor_acceleration=np.zeros((n, 4)), force=force, moment=moment, reference_force=ref,
                         reference_moment=ref_moment, reference_mass=tuple(ref_mass), rate_hz=1.0)


def test_flight_errors_count_and_pool_the_moments_and_the_zero_predictor():
    """Mutants A4 (n off by one), A5 (M_zero from the prediction's error, not the measured
    moment), A6 (pooled M over two axes), A7 (a predicted moment scored without a measured one)."""
    meas = np.array([[1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [1.0, 2.0, 3.0]])
    pred = np.array([[0.0, 0.0, 6.0]] * 3)  # errors -1, -2, +3 per axis
    e = flight_errors(np.zeros((3, 3)), _S(np.zeros((3, 3)), moment=meas), pred)
    assert e["n"] == 3
    assert (e["Mx"], e["My"], e["Mz"]) == pytest.approx((1.0, 2.0, 3.0))
    assert e["M"] == pytest.approx(math.sqrt(14 / 3))
    assert e["M_zero"] == pytest.approx(math.sqrt(14 / 3))
    e = flight_errors(np.zeros((3, 3)), _S(np.zeros((3, 3)), moment=meas), meas)  # an exact prediction
    assert e["M"] == 0.0 and e["M_zero"] == pytest.approx(math.sqrt(14 / 3))
    e = flight_errors(np.zeros((3, 3)), _S(np.zeros((3, 3))), pred)  # no measured moment: no moment scored
    assert "M" not in e and "M_zero" not in e and e["F"] == 0.0


def test_flight_errors_of_no_samples_are_nan():
    """Mutant A21 (the empty-prediction guard dropped): an empty band scores NaN quietly."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        e = flight_errors(np.zeros((0, 3)), _S(np.zeros((0, 3))))
    assert e["n"] == 0 and math.isnan(e["F"]) and math.isnan(e["Fx"])


def test_reference_scaled_to_the_vehicle_mass_by_hand():
    """Mutants A8 (0.5% threshold made 5%), A9 (m_ref / m, not m / m_ref), A12 (the masses
    not rounded to the 4 digits said)."""
    ref = np.array([[0.0, 0.0, 10.0], [1.0, 0.0, 10.0]])
    s = _S(np.zeros((2, 3)), ref=ref, ref_mass=(0.75213,))
    scaled, used = reference_at_vehicle_mass(s, 0.772)
    np.testing.assert_allclose(scaled, ref * 0.772 / 0.75213)
    assert used == (0.7521,)
    scaled, _ = reference_at_vehicle_mass(s, 0.75213 * 1.02)  # 2% off: scaled
    np.testing.assert_allclose(scaled[:, 2], 10.0 * 1.02)
    assert reference_at_vehicle_mass(s, 0.75213 * 1.004) is None


def test_reference_is_not_scaled_for_an_unknown_or_miscounted_mass():
    """Mutants A10 (a NaN mass scaled) and A11 (a mass per log not checked against the logs)."""
    ref = np.ones((2, 3))
    assert reference_at_vehicle_mass(_S(np.zeros((2, 3)), ref=ref, ref_mass=(math.nan,)), 0.772) is None
    two = _S(np.zeros((2, 3)), ref=ref, ref_mass=(0.752,), names=("a", "b"), index=[0, 1])
    assert reference_at_vehicle_mass(two, 0.772) is None


def test_reference_errors_score_the_logs_own_moment_both_rows():
    """Mutants A13 and A14 (the log's own moment left out of the scaled / logged row)."""
    ref = np.array([[0.0, 0.0, 10.0]] * 2)
    s = _S(np.zeros((2, 3)), moment=np.zeros((2, 3)), ref=ref, ref_moment=np.full((2, 3), 0.2), ref_mass=(0.752,))
    out, masses = reference_errors(s, 0.772)
    assert masses == (0.752,)
    assert out["reference"]["Fz"] == pytest.approx(10.0) and out["reference"]["M"] == pytest.approx(0.2)
    assert out["reference_at_vehicle_mass"]["Fz"] == pytest.approx(10.0 * 0.772 / 0.752)
    assert out["reference_at_vehicle_mass"]["M"] == pytest.approx(0.2)


def test_thrust_baseline_follows_an_inverted_rotor_axis():
    """Mutant A17 (the thrust column along |a_i|): a rotor pointing down pushes down."""
    veh = pm.read_vehicle(VEHICLE)
    rotors = list(veh.rotors)
    rotors[0] = dataclasses.replace(rotors[0], axis=np.array([0.0, 0.0, -1.0]))
    veh = dataclasses.replace(veh, rotors=tuple(rotors))
    om = np.array([[1000.0, 1000.0, 1000.0, 1000.0]])
    f = baseline_force({"terms": ["thrust"], "coefficients": [1e-6]}, _S(np.zeros((1, 3)), om=om), veh)[0]
    np.testing.assert_allclose(f, [0.0, 0.0, 2.0], atol=1e-12)  # 3 up, 1 down, 1 N each


def test_baselines_recover_thrust_on_exact_data():
    """Mutants A15-A17, A20: the baselines fitted to k Omega^2 data return k (and no drag)."""
    veh = pm.read_vehicle(VEHICLE)
    rng = np.random.default_rng(1)
    om = rng.uniform(900, 1500, (40, 4))
    f = np.zeros((40, 3))
    f[:, 2] = 8e-6 * (om**2).sum(axis=1)
    s = _S(f, v=rng.uniform(-3, 3, (40, 3)), w=rng.uniform(-1, 1, (40, 3)), om=om)
    bl = fit_baselines(s, veh)
    assert bl["k_omega2"]["coefficients"] == pytest.approx([8e-6])
    assert bl["rotorpy"]["coefficients"] == pytest.approx([8e-6, 0.0, 0.0], abs=1e-12)


# ---- the CLI: short logs cut from a shared NeuroBEM segment (400 Hz), written as CSV


@pytest.fixture(scope="module")
def short_logs(tmp_path_factory, request):
    """Two 3 s pieces of one NeuroBEM segment (1200 samples each at 400 Hz), as CSV files."""
    import scipy.io

    from propmap.io.flightlog import NEUROBEM_COLUMNS

    shared = request.getfixturevalue("shared_data")
    a = scipy.io.loadmat(shared / "neurobem_flights" / "bemnn20210223104803seg2.mat")
    rows = np.asarray(next(v for k, v in a.items() if not k.startswith("__")), float)
    d = tmp_path_factory.mktemp("logs")
    out = []
    for name, part in (("a.csv", rows[:1200]), ("b.csv", rows[1200:2400])):
        p = d / name
        p.write_text(",".join(NEUROBEM_COLUMNS) + "\n"
                     + "\n".join(",".join(repr(float(x)) for x in r) for r in part) + "\n")
        out.append(p)
    return out


@pytest.mark.parametrize("extra, message", [
    (["--rate-hz", "nan"], "--rate-hz must be in (0, 10000] Hz, got nan"),  # (B2 is equivalent: NaN fails 0 < r)
    (["--rate-hz", "20000"], "--rate-hz must be in (0, 10000] Hz, got 20000.0"),  # B3
    (["--motor-map", "0,0"], "--motor-map: A and B must be finite and B not 0"),  # B1
    (["--motor-map", "0,1"], "--motor-map applies to PX4 .ulg logs only"),  # B9
    (["--holdout", "a.csv,b.csv"], "--holdout: every LOG is held out; keep at least one to fit"),  # B4
    (["--holdout", "b.csv", "--cross-validate"], "it needs at least 2 training logs, got 1"),  # B5
    (["--holdout", "c.csv"], "--holdout: 'c.csv' is not one of the LOGs (a.csv, b.csv)"),  # B11
])
def test_fit_flight_refuses_before_reading_or_fitting(tmp_path, capsys, short_logs, extra, message):
    """Mutants B1 (B = 0 taken), B3 (no upper bound on the rate), B4 (every
    log held out), B5 (cross-validation with one training log), B9 (--motor-map on a NeuroBEM
    log), B11 (an unknown --holdout name): each refused with exit 2 and its message."""
    code = main(["fit", "flight", *map(str, short_logs), "--vehicle", str(VEHICLE), "--out",
                 str(tmp_path / "p.toml"), *extra])
    err = capsys.readouterr().err
    assert code == 2 and message in err, err
    assert not (tmp_path / "p.toml").exists()


def test_wrench_prints_and_writes_the_moments_and_the_mass_note(tmp_path, capsys, short_logs):
    """Mutants B12 (the scaled row's mass to one decimal), B13 (the note's ratio inverted), B18
    (the moment columns written from the force), B19 (the zero-moment line dropped), B14 (an
    upper-case .CSV suffix refused), B15 (the moments printed to 3 decimals)."""
    import csv

    out = tmp_path / "w.CSV"
    assert main(["wrench", str(short_logs[0]), "--vehicle", str(VEHICLE), "--out", str(out)]) == 0
    said = capsys.readouterr().out
    assert "log's own prediction, at 0.772 kg" in said
    assert "this row scales its force by 0.772 / 0.752," in said
    with open(out, newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 1200
    col = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    # the moments are N m, two orders below the ~7.6 N of thrust: never the force columns
    assert np.mean(col["Fz"]) > 5.0 and np.max(np.abs(col["Mz"])) < 0.5
    m_zero = math.sqrt(np.mean([col[f"M{a}_measured"] ** 2 for a in "xyz"]))
    own = next(ln for ln in said.splitlines() if ln.startswith("propmap ("))
    assert all(len(c.split(".")[1]) == 4 for c in own.split("   ")[-1].split())  # moments to 0.1 mN m (B15)
    line = next(ln for ln in said.splitlines() if ln.startswith("zero-moment predictor: M "))
    assert float(line.split()[-3]) == pytest.approx(m_zero, abs=6e-5)


def test_fit_flight_holds_out_a_log_and_records_the_training_coverage(tmp_path, capsys, short_logs):
    """Mutants B30 (the held-out log trained on too), B23 (the band's upper bound left out of the
    report's text), B25 (the held-out log listed among the coverage's groups), B26 (J from the
    airspeed, not its axial part), B27 (rpm_max in rad/s) and B28 (the incidence only of hubs
    faster than 10% of the tip speed, not 1%), B16 (the label column not widened for long labels:
    the F column no longer under its header)."""
    import tomllib

    from propmap.identify.flight import flight_samples
    from propmap.io.flightlog import read_flight_log

    out = tmp_path / "p.toml"
    code = main(["fit", "flight", *map(str, short_logs), "--vehicle", str(VEHICLE), "--out", str(out),
                 "--holdout", "b.csv", "--rate-hz", "10", "--fit-params", "collective"])
    cap = capsys.readouterr()
    assert code == 0, cap.err
    text = (tmp_path / "p.report.txt").read_text()
    assert "60 samples at 10 Hz from 2 log(s); fitted on 30 (a.csv)" in text
    # the bands of propmap and the three baselines, on the training samples and the held-out log: every sample
    # is below 3 m/s, so each row's 0-3 m/s F is that score's pooled F
    table = text[text.index("F [N] by speed band (samples in brackets):"):].splitlines()
    assert table[1].split() == ["0-3", "m/s", "3-6", "m/s", "6-9", "m/s", ">9", "m/s"]
    report = json.loads((tmp_path / "p.report.json").read_text())["flight_report"]
    keys = ("model", "k_omega2", "rotor_drag", "rotorpy")
    labels = ("propmap", "T = k Omega^2", "k Omega^2 + linear rotor drag c Omega v_ip",
              "k Omega^2 - k_z Omega v_z + c Omega v_ip (RotorPy's terms)")
    scored = (("training", report["training"]), ("held out b.csv", report["held_out"]["b.csv"]))
    rows = [(f"{w}: {label}", where, key) for w, where in scored for key, label in zip(keys, labels)]
    for (label, where, key), line in zip(rows, table[2:10], strict=True):
        assert line.startswith(label + " ") and line.endswith("n/a (0)  n/a (0)  n/a (0)"), line
        assert line.split()[-8:-6] == [f"{where[key]['F']:.3f}", "(30)"], (line, where[key]["F"])
    for where in (report["training"], report["held_out"]["b.csv"]):
        bands = [where["speed_bands"], *where["speed_bands_baselines"].values()]
        assert [b[0]["F"] for b in bands] == pytest.approx([where[k]["F"] for k in keys], rel=1e-12)
    import re

    lines = text.splitlines()
    head = next(k for k, ln in enumerate(lines) if ln.rstrip().endswith("[N]; [N m]") or ln.rstrip().endswith("[N]"))
    end = lines[head].rfind(" F") + 2  # where the pooled F column ends
    bands = lines.index("F [N] by speed band (samples in brackets):")  # (its rows are the band table's)
    rows = [ln for ln in lines[head + 1:bands] if ln.startswith(("training: ", "held out b.csv: "))]
    assert any(len(ln.split(": ", 1)[0]) + len(ln.split(": ", 1)[1].split("  ")[0]) > 44 for ln in rows)
    for ln in rows:  # every row's F under the header's F, however long its label
        assert re.fullmatch(r"\d+\.\d{3}", ln[end - 7:end].strip()), (ln, end)
    cov = tomllib.loads(out.read_text())["coverage"]
    assert cov["groups"] == ["a.csv"] and cov["held_out"] == ["b.csv"]
    veh = pm.read_vehicle(VEHICLE)
    s = flight_samples([read_flight_log(short_logs[0])], veh, rate_hz=1e4)
    assert cov["rpm_max"] == pytest.approx(float(s.rotor_omega.max()) * 60 / (2 * math.pi), rel=1e-6)
    arms = np.array([r.position for r in veh.rotors]) - np.asarray(veh.centre_of_mass)
    v_axial = s.velocity[:, None, 2] + np.cross(s.angular_velocity[:, None, :], arms[None])[..., 2]  # axes +z
    D = veh.rotors[0].propeller.diameter
    v_hub = s.velocity[:, None, :] + np.cross(s.angular_velocity[:, None, :], arms[None])
    speed = np.linalg.norm(v_hub, axis=2)
    moving = speed > 0.01 * s.rotor_omega * D / 2  # faster than 1% of the tip speed
    inc = np.degrees(np.arccos(np.clip(v_hub[..., 2] / np.where(moving, speed, 1.0), -1, 1)))
    assert moving.any() and cov["incidence_deg_max"] == pytest.approx(float(inc[moving].max()), abs=1e-6)
    assert cov["J_max"] == pytest.approx(max(0.0, float(np.max(v_axial / (s.rotor_omega / (2 * math.pi) * D)))),
                                         rel=1e-6)


def test_fit_flight_notes_a_rate_just_above_the_logs(tmp_path, capsys, short_logs, monkeypatch):
    """Mutant B6 (the note only above twice the log's rate): --rate-hz 500 on a 400 Hz log takes
    every sample, and says so; 400 Hz says nothing. (Each run stops at the training samples'
    check, after the samples are taken: until 2026-12-01 --moments on a vehicle without inertia
    stopped it there, now refused before the logs are read.)"""
    from propmap.cli import flight
    from propmap.cli._common import InputError

    def stop(*args):
        raise InputError("stopped after the samples were taken")

    monkeypatch.setattr(flight, "_check_training_samples", stop)
    for rate, noted in (("500", True), ("400", False)):
        code = main(["fit", "flight", str(short_logs[0]), "--vehicle", str(VEHICLE), "--out",
                     str(tmp_path / "p.toml"), "--rate-hz", rate])
        err = capsys.readouterr().err
        assert code == 2 and "stopped after the samples were taken" in err, err
        assert ("--rate-hz 500: a log is sampled at 400 Hz, so every sample of it is taken" in err) == noted, err


def _hover_log(path: Path, n: int, t0: float, omega: float = 1000.0) -> Path:
    """A NeuroBEM CSV of n samples at 400 Hz from t0: level, still, every motor at ``omega``."""
    from propmap.io.flightlog import NEUROBEM_COLUMNS

    rows = np.zeros((n, len(NEUROBEM_COLUMNS)))
    rows[:, 0] = t0 + np.arange(n) / 400.0
    rows[:, 10] = 1.0  # quat w
    rows[:, 13] = 9.80665  # acc z
    rows[:, 20:24] = omega
    path.write_text(",".join(NEUROBEM_COLUMNS) + "\n" + "\n".join(",".join(repr(float(x)) for x in r) for r in rows)
                    + "\n")
    return path


def test_two_hovers_at_one_commanded_speed_are_not_one_flight(tmp_path):
    """Mutant B21 (the constant-speed guard of _repeated_in dropped): two runs at one commanded
    speed, still and level, repeat each other sample by sample yet are two flights."""
    from propmap.cli.flight import _refuse_same_flight
    from propmap.io.flightlog import read_flight_log

    _refuse_same_flight([read_flight_log(_hover_log(tmp_path / "h1.csv", 80, 0.0)),
                         read_flight_log(_hover_log(tmp_path / "h2.csv", 50, 30.0))])  # (no InputError raised)


def test_same_times_other_motor_speeds_are_two_flights(tmp_path, short_logs):
    """Mutant B22 (the same-flight check on the times alone): two logs timed alike whose motor
    speeds differ are both kept."""
    from propmap.cli.flight import _refuse_same_flight
    from propmap.io.flightlog import read_flight_log

    a = read_flight_log(short_logs[0])
    b = read_flight_log(short_logs[1])
    b = dataclasses.replace(b, t=a.t.copy())
    _refuse_same_flight([a, b])
    from propmap.cli._common import InputError

    with pytest.raises(InputError, match="hold the same flight"):
        _refuse_same_flight([a, dataclasses.replace(b, rotor_omega=a.rotor_omega.copy())])
