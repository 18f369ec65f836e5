"""Flight-log readers: the shared NeuroBEM logs (Bauersfeld et al., RSS 2021), their CSV form,
synthetic PX4 ULogs, and malformed logs (one-line errors; exit 2 from the CLI)."""

import math
from pathlib import Path

import warnings

import numpy as np
import pytest
import scipy.io

import propmap as pm
from propmap.cli.main import main
from propmap.io.flightlog import NEUROBEM_COLUMNS, FlightLogError, read_flight_log

from .ulog_writer import hover_ulog

SEGMENTS = ("bemnn20210218170320seg2.mat", "bemnn20210218171908seg2.mat", "bemnn20210223104803seg2.mat",
            "bemnn20210223114138seg3.mat")


@pytest.fixture(scope="module")
def seg(shared_data):
    return shared_data / "neurobem_flights" / SEGMENTS[2]


def test_the_shared_neurobem_segments_read(shared_data):
    """Four segments at 400 Hz; hovering figure-8: specific force about +g along body z, motor
    speeds 985-1250 rad/s (PROVENANCE.md), NeuroBEM's own prediction carried along."""
    durations = []
    for name in SEGMENTS:
        log = read_flight_log(shared_data / "neurobem_flights" / name)
        assert log.n_motors == 4 and log.format == "neurobem"
        assert np.median(np.diff(log.t)) == pytest.approx(0.0025, rel=1e-6)
        assert log.reference_force is not None and log.reference_force.shape == (log.n, 3)
        durations.append(log.duration)
    np.testing.assert_allclose(durations, [35.76, 31.81, 29.37, 28.58], atol=0.01)
    log = read_flight_log(shared_data / "neurobem_flights" / SEGMENTS[2])
    assert np.mean(log.specific_force[:, 2]) == pytest.approx(9.84, abs=0.05)
    assert log.rotor_omega.min() == pytest.approx(985.1, abs=0.1) and log.rotor_omega.max() == pytest.approx(1250.0,
                                                                                                              abs=0.1)
    # the logged motor accelerations are the motor speeds' rate of change, and the log's own moment prediction
    # follows the measured I dw/dt + w x I w (columns four and three places off passed: a mutation audit, 2026-11-27)
    win = 40  # 0.1 s means at 400 Hz: the logged dOmega/dt is noisy sample to sample
    n = log.n // win * win
    mean = lambda a: a[:n].reshape(-1, win, *a.shape[1:]).mean(axis=1)  # noqa: E731
    d_log, d_num = mean(log.rotor_acceleration), mean(np.gradient(log.rotor_omega, log.t, axis=0))
    ratio = np.sum(d_log * d_num, axis=0) / np.sum(d_num * d_num, axis=0)
    np.testing.assert_allclose(ratio, 1.0, atol=0.05)
    veh = pm.read_vehicle("neurobem_quadrotor")
    w, dw = log.angular_velocity, log.angular_acceleration
    measured = dw @ veh.inertia.T + np.cross(w, w @ veh.inertia.T)
    corr = [np.corrcoef(mean(log.reference_moment)[:, k], mean(measured)[:, k])[0, 1] for k in range(3)]
    assert min(corr) > 0.4, corr


@pytest.mark.parametrize("header", [True, False, "numbers"])
def test_csv_form_reads_as_the_mat(tmp_path, seg, header):
    """With the NeuroBEM names, without a header, or under pandas' header of column numbers 0-40
    (read as data and refused for its 'quaternion' [7, 8, 9, 10] until 2026-11-27)."""
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:500]
    path = tmp_path / "log.csv"
    top = {True: [",".join(NEUROBEM_COLUMNS)], False: [], "numbers": [",".join(map(str, range(41)))]}[header]
    lines = top + [",".join(repr(float(x)) for x in row) for row in arr]
    path.write_text("\n".join(lines) + "\n")
    log = read_flight_log(path)
    ref = read_flight_log(seg)
    np.testing.assert_array_equal(log.rotor_omega, ref.rotor_omega[:500])
    np.testing.assert_array_equal(log.specific_force, ref.specific_force[:500])


def test_csv_header_in_another_column_order(tmp_path, seg):
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:50]
    order = list(range(41))[::-1]
    path = tmp_path / "log.csv"
    path.write_text(",".join(NEUROBEM_COLUMNS[j] for j in order) + "\n"
                    + "\n".join(",".join(repr(float(row[j])) for j in order) for row in arr) + "\n")
    np.testing.assert_array_equal(read_flight_log(path).velocity, read_flight_log(seg).velocity[:50])


def test_ulog_from_esc_status(tmp_path):
    """PX4 frames: FRD body / NED world turned into propmap's x forward, y left, z up."""
    truth = hover_ulog(tmp_path / "f.ulg", rpm=12000.0)
    log = read_flight_log(tmp_path / "f.ulg")
    yaw, pitch = truth["yaw"], truth["pitch"]
    # 2 m/s north seen from a body yawed 30 deg (east of north) and pitched 5 deg up
    np.testing.assert_allclose(log.velocity[0], [2 * math.cos(yaw) * math.cos(pitch), 2 * math.sin(yaw),
                                                 -2 * math.cos(yaw) * math.sin(pitch)], atol=1e-6)
    np.testing.assert_allclose(log.specific_force[0], [0.5, -0.2, 9.9], atol=1e-5)
    np.testing.assert_allclose(log.angular_velocity[0], [0.1, 0.0, 0.0], atol=1e-7)
    np.testing.assert_allclose(log.rotor_omega[0], 12000 * 2 * math.pi / 60)
    assert "esc_status" in log.motor_order
    # the attitude (body to a z-up world: north, west, up): the nose 30 deg east of north, 5 deg up (untested before:
    # a quaternion component of the wrong sign passed the suite; a mutation audit, 2026-11-27)
    from scipy.spatial.transform import Rotation

    nose = Rotation.from_quat(log.attitude[0]).apply([1.0, 0.0, 0.0])
    np.testing.assert_allclose(nose, [math.cos(yaw) * math.cos(pitch), -math.sin(yaw) * math.cos(pitch),
                                      math.sin(pitch)], atol=1e-6)
    left = Rotation.from_quat(log.attitude[0]).apply([0.0, 1.0, 0.0])
    np.testing.assert_allclose(left, [math.sin(yaw), math.cos(yaw), 0.0], atol=1e-6)  # (no roll: level wings)


def test_ulog_a_nan_logged_angular_acceleration_is_refused_naming_the_file(tmp_path):
    """A NaN in vehicle_angular_velocity's xyz_derivative passed the reader and surfaced as
    'FlightSamples.moment must be finite (sample 500 ...)', naming neither the file nor the
    sample of the log (a flight audit)."""
    hover_ulog(tmp_path / "f.ulg", rpm=12000.0, nan_derivative_at=57)
    with pytest.raises(FlightLogError, match=r"f\.ulg: sample 58: angular_acceleration \[nan, -?0\.0, -?0\.0\] is not "
                                             r"finite"):
        read_flight_log(tmp_path / "f.ulg")


def test_ulog_motor_map(tmp_path):
    hover_ulog(tmp_path / "f.ulg", rpm=12000.0, with_esc=False)
    with pytest.raises(FlightLogError, match="esc_status' not in the log.*--motor-map"):
        read_flight_log(tmp_path / "f.ulg")
    # declared but never logged: said so (it read 'not in the log' where the topic list names it; a fuzzing audit)
    hover_ulog(tmp_path / "e.ulg", rpm=12000.0, esc_empty=True)
    with pytest.raises(FlightLogError, match=r"esc_status' has no message in the log \(its format is declared\).*"
                                             "--motor-map"):
        read_flight_log(tmp_path / "e.ulg")
    log = read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0))
    np.testing.assert_allclose(log.rotor_omega[0], 12000 * 2 * math.pi / 60, rtol=1e-6)


def test_ulog_quaternion_sign_flips_are_one_attitude(tmp_path):
    """q and -q alternating (PX4 may log either), the attitude sampled between the others: the
    same body velocity as without flips (the components were interpolated through 0: NaN)."""
    hover_ulog(tmp_path / "f.ulg")
    hover_ulog(tmp_path / "q.ulg", q_flip=True)
    flipped = read_flight_log(tmp_path / "q.ulg").velocity  # (the topics overlap on one sample fewer)
    np.testing.assert_allclose(flipped, read_flight_log(tmp_path / "f.ulg").velocity[:len(flipped)], atol=1e-6)


def test_ulog_motor_map_takes_the_vehicles_motors_of_more_outputs(tmp_path):
    hover_ulog(tmp_path / "f.ulg", rpm=12000.0, with_esc=False, n_outputs=8)
    assert read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0)).n_motors == 8
    log = read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=4)
    assert log.n_motors == 4
    np.testing.assert_allclose(log.rotor_omega, 12000 * 2 * math.pi / 60, rtol=1e-6)
    with pytest.raises(FlightLogError, match="has 8 outputs; the vehicle has 12 rotors"):
        read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=12)


def test_cli_motor_map_reads_a_ulog_without_esc_status(tmp_path, capsys):
    """--motor-map A,B on wrench (and fit flight): the error that names it, then the option itself."""
    from pathlib import Path

    import propmap as pm
    from propmap.cli.main import main

    vehicle = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    hover_ulog(tmp_path / "f.ulg", rpm=12000.0, with_esc=False, n_outputs=8)
    out = tmp_path / "w.csv"
    assert main(["wrench", str(tmp_path / "f.ulg"), "--vehicle", str(vehicle), "--out", str(out)]) == 2
    assert "(--motor-map a,b)" in capsys.readouterr().err
    for bad, match in (("10", "two numbers A,B"), ("0,0", "B not 0")):
        assert main(["wrench", str(tmp_path / "f.ulg"), "--vehicle", str(vehicle), "--out", str(out),
                     "--motor-map", bad]) == 2
        assert match in capsys.readouterr().err
    assert main(["wrench", str(tmp_path / "f.ulg"), "--vehicle", str(vehicle), "--out", str(out),
                 "--motor-map", "0,10"]) == 0
    capsys.readouterr()
    assert out.is_file()


def test_ulog_missing_topic_is_named_with_those_found(tmp_path):
    from .ulog_writer import write_ulog

    write_ulog(tmp_path / "f.ulg", {"vehicle_acceleration": ([("uint64_t", "timestamp"), ("float[3]", "xyz")],
                                                             [(1000, 0.0, 0.0, -9.8), (2000, 0.0, 0.0, -9.8)])})
    with pytest.raises(FlightLogError, match="'vehicle_angular_velocity' not in the log .topics found: "
                                             "vehicle_acceleration"):
        read_flight_log(tmp_path / "f.ulg")


def test_ulog_without_accelerations_names_both_topics(tmp_path):
    from .ulog_writer import write_ulog

    write_ulog(tmp_path / "f.ulg", {"vehicle_attitude": ([("uint64_t", "timestamp"), ("float[4]", "q")],
                                                         [(1000, 1.0, 0.0, 0.0, 0.0), (2000, 1.0, 0.0, 0.0, 0.0)])})
    with pytest.raises(FlightLogError, match="neither topic 'vehicle_acceleration' nor 'sensor_combined' is in the "
                                             r"log \(topics found: vehicle_attitude\)"):
        read_flight_log(tmp_path / "f.ulg")


def _bad_mat(tmp_path, arr, name="bad.mat"):
    scipy.io.savemat(tmp_path / name, {"x": arr})
    return tmp_path / name


@pytest.mark.parametrize("mutate, match", [
    (lambda a: a[:, :40], "N x 41"),
    (lambda a: a[:1], "at least 2"),
    (lambda a: np.vstack([a[:1], a[:1]]), "time does not increase at sample 2"),
    (lambda a: np.where(np.arange(41) == 21, np.nan, a), "not a finite number"),
    (lambda a: np.where(np.arange(41) == 20, -5.0, a), "negative motor speed"),
    (lambda a: np.where(np.arange(41) == 13, 1e4, a), "specific_force .* beyond"),
])
def test_malformed_mat_logs(tmp_path, seg, mutate, match):
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:20].copy()
    with pytest.raises(FlightLogError, match=match):
        read_flight_log(_bad_mat(tmp_path, mutate(arr)))


def test_the_29_measured_columns_alone_are_read(tmp_path, seg):
    """The dataset's 29 measured columns without NeuroBEM's prediction and residuals, as an
    N x 29 .mat or a headerless CSV, were refused ('must be an N x 41 numeric array'; a
    flight-log audit, 2026-11-30): read as the 41-column log's first 29, with no prediction to
    score; 30 columns stay refused."""
    arr = next(v for k, v in scipy.io.loadmat(seg).items() if not k.startswith("__"))[:400].copy()
    whole = read_flight_log(_bad_mat(tmp_path, arr, "whole.mat"))
    assert whole.reference_force is not None
    np.savetxt(tmp_path / "m29.csv", arr[:, :29], delimiter=",", fmt="%.17g")
    for log in (read_flight_log(_bad_mat(tmp_path, arr[:, :29], "m29.mat")), read_flight_log(tmp_path / "m29.csv")):
        assert log.n == whole.n and log.reference_force is None and log.reference_moment is None
        for field in ("t", "angular_velocity", "attitude", "specific_force", "velocity", "rotor_omega"):
            np.testing.assert_array_equal(getattr(log, field), getattr(whole, field))
    # pandas' to_csv of an unnamed frame heads it with the column numbers 0-28 (a review, 2026-11-30)
    np.savetxt(tmp_path / "p29.csv", arr[:, :29], delimiter=",", fmt="%.17g", comments="",
               header=",".join(str(k) for k in range(29)))
    np.testing.assert_array_equal(read_flight_log(tmp_path / "p29.csv").rotor_omega, whole.rotor_omega)
    np.savetxt(tmp_path / "m30.csv", arr[:, :30], delimiter=",", fmt="%.17g")
    with pytest.raises(FlightLogError, match=r"30 columns; the NeuroBEM layout has 41 \(29 without the prediction"):
        read_flight_log(tmp_path / "m30.csv")


@pytest.mark.parametrize("content, name, match", [
    (b"not a mat file at all", "x.mat", "not a readable MATLAB"),
    (b"t,ang acc x\n1,2\n", "x.csv", "header lacks the NeuroBEM column"),
    ((";".join(NEUROBEM_COLUMNS) + "\n" + ";".join(["0,5"] * 41) + "\n").encode(), "x.csv",
     "separated by ';'; a flight-log CSV is separated by ','"),
    (("\n".join(" ".join(["0.5"] * 41) for _ in range(3)) + "\n").encode(), "x.csv",  # (it named the data as the
     "separated by blanks; a flight-log CSV is separated by ','"),  # header's missing columns: a fuzzing audit)
    (b"1,2,3\n4,5,6\n", "x.csv", "3 columns"),
    (b"ULog garbage", "x.ulg", "not a readable ULog"),
    (b"", "x.csv", "empty file"),
    ((",".join(NEUROBEM_COLUMNS) + "\n").encode(), "x.csv", r"no data rows after the header \(line 1\)"),
    (b"1,2", "x.bin", "unknown flight-log format"),
])
def test_malformed_files(tmp_path, content, name, match):
    (tmp_path / name).write_bytes(content)
    with pytest.raises(FlightLogError, match=match):
        read_flight_log(tmp_path / name)


def test_cli_bad_log_exits_2_with_one_line(tmp_path, capsys, shared_data):
    import propmap as pm

    (tmp_path / "x.mat").write_bytes(b"junk")
    veh = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    code = main(["wrench", str(tmp_path / "x.mat"), "--vehicle", str(veh), "--out", str(tmp_path / "p.csv")])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and err[0].startswith("propmap: error:")
    assert not (tmp_path / "p.csv").exists()


def test_fit_flight_refuses_one_flight_given_as_a_mat_and_its_csv(tmp_path, capsys, seg, shared_data):
    """A .mat and its CSV form are no byte copies, yet a held-out one trained its own fit (the
    in-sample error reported as held out; a flight audit): the same times and motor speeds are
    refused as one flight."""
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:1200]
    mat = tmp_path / "one.mat"
    scipy.io.savemat(mat, {"data": arr})
    csv = tmp_path / "one.csv"
    csv.write_text(",".join(NEUROBEM_COLUMNS) + "\n" + "\n".join(",".join(f"{x:.9g}" for x in row) for row in arr)
                   + "\n")
    other = shared_data / "neurobem_flights" / SEGMENTS[0]
    code = main(["fit", "flight", str(mat), str(csv), str(other), "--vehicle", "neurobem_quadrotor", "--holdout",
                 "one.csv", "--rate-hz", "5", "--out", str(tmp_path / "p.toml")])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and err[-1].startswith("propmap: error: LOG: one.csv and one.mat hold the same flight")
    assert not (tmp_path / "p.toml").exists()


def test_a_gap_in_a_logs_time_is_warned_of(tmp_path, seg):
    """A 5 s jump inside a log was read without a word (a flight audit)."""
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:400].copy()
    arr[200:, 0] += 5.0
    path = tmp_path / "gap.csv"
    path.write_text(",".join(NEUROBEM_COLUMNS) + "\n" + "\n".join(",".join(repr(float(x)) for x in row) for row in arr)
                    + "\n")
    with pytest.warns(UserWarning, match=r"gap\.csv: a gap of 5 s in the log's time at t = .* the samples either side"):
        read_flight_log(path)


@pytest.mark.parametrize("form", ["comment", "trailing comma", "trailing comma, header without"])
def test_a_leading_comment_and_a_trailing_comma_read_as_the_plain_csv(tmp_path, seg, form):
    """A leading '# comment' line was taken as the header, and a trailing comma on every line (a
    spreadsheet's) refused as a 42nd column (a flight audit)."""
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:300]
    header = ",".join(NEUROBEM_COLUMNS)
    rows = [",".join(repr(float(x)) for x in row) for row in arr]
    if form == "comment":
        text = "# a NeuroBEM log\n# exported by hand\n" + header + "\n" + "\n".join(rows)
    else:
        text = header + ("" if form.endswith("without") else ",") + "\n" + "\n".join(r + "," for r in rows)
    (tmp_path / "x.csv").write_text(text + "\n")
    np.testing.assert_array_equal(read_flight_log(tmp_path / "x.csv").rotor_omega,
                                  read_flight_log(seg).rotor_omega[:300])


def test_a_header_written_as_a_comment_is_the_header(tmp_path, seg):
    """numpy.savetxt writes its header as '# t,ang acc x,...': skipped as a comment, the columns
    were read by position (a review found two motor columns swapped read without a word)."""
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:300]
    order = list(range(41))
    order[20], order[23] = order[23], order[20]  # mot 1 and mot 4 swapped, named so
    np.savetxt(tmp_path / "h.csv", arr[:, order], delimiter=",", header=",".join(NEUROBEM_COLUMNS[j] for j in order))
    assert (tmp_path / "h.csv").read_text().startswith("# t,")
    np.testing.assert_array_equal(read_flight_log(tmp_path / "h.csv").rotor_omega,
                                  read_flight_log(seg).rotor_omega[:300])


def test_fit_flight_cross_validation_folds_are_checked_before_any_fit(tmp_path, capsys, shared_data):
    """Each fold leaves a training log out: with 11 + 10 samples (--rate-hz 0.3) a fold of 10
    failed after the main fit, its error naming no option (a review)."""
    logs = [str(shared_data / "neurobem_flights" / s) for s in SEGMENTS[:2]]
    code = main(["fit", "flight", *logs, "--vehicle", "neurobem_quadrotor", "--rate-hz", "0.3", "--cross-validate",
                 "--out", str(tmp_path / "p.toml")])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and err[-1].startswith("propmap: error: --cross-validate at --rate-hz 0.3: a fold keeps 10 ")
    assert not (tmp_path / "p.toml").exists()


def test_the_same_flight_as_a_mat_and_a_six_digit_csv_is_one_flight(tmp_path, capsys, seg, shared_data):
    """A '%g' export rounds the motor speeds by up to 4e-6: the 1e-6 tolerance missed it (a review)."""
    a = scipy.io.loadmat(seg)
    arr = next(v for k, v in a.items() if not k.startswith("__"))[:1200]
    scipy.io.savemat(tmp_path / "one.mat", {"data": arr})
    (tmp_path / "one.csv").write_text(",".join(NEUROBEM_COLUMNS) + "\n"
                                      + "\n".join(",".join(f"{x:g}" for x in row) for row in arr) + "\n")
    other = shared_data / "neurobem_flights" / SEGMENTS[0]
    code = main(["fit", "flight", str(tmp_path / "one.mat"), str(tmp_path / "one.csv"), str(other), "--vehicle",
                 "neurobem_quadrotor", "--rate-hz", "5", "--out", str(tmp_path / "p.toml")])
    assert code == 2 and "hold the same flight" in capsys.readouterr().err


def _px4_topics(n=400, hz=100.0):
    """The four topics besides the motors of a level, steady ULog (timestamps in us from 1 s)."""
    t = [1_000_000 + int(i * 1e6 / hz) for i in range(n)]
    xyz = [("uint64_t", "timestamp"), ("float[3]", "xyz")]
    return t, {
        "vehicle_acceleration": (xyz, [(ti, 0.0, 0.0, -9.80665) for ti in t]),
        "vehicle_angular_velocity": (xyz, [(ti, 0.0, 0.0, 0.0) for ti in t]),
        "vehicle_attitude": ([("uint64_t", "timestamp"), ("float[4]", "q")], [(ti, 1.0, 0.0, 0.0, 0.0) for ti in t]),
        "vehicle_local_position": ([("uint64_t", "timestamp"), ("float", "vx"), ("float", "vy"), ("float", "vz")],
                                   [(ti, 1.0, 0.0, 0.0) for ti in t])}


def _esc(t, rpm_of, functions=None, keep=lambda ti: True):
    """esc_status of four ESCs: channel k at rpm_of(ti, k), esc[k].actuator_function = functions[k]."""
    fields = [("uint64_t", "timestamp"), ("int32_t", "esc_rpm")] + ([("uint8_t", "actuator_function")]
                                                                     if functions else [])
    rows = [(ti, 4, *sum(([ti, rpm_of(ti, k)] + ([functions[k]] if functions else []) for k in range(4)), []))
            for ti in t if keep(ti)]
    return ([("uint64_t", "timestamp"), ("uint8_t", "esc_count"), ("esc_report[4]", "esc")], rows), \
        {"esc_report": fields}


def test_ulog_motor_order_follows_the_escs_actuator_function(tmp_path):
    """PX4 fills esc[] by output channel and names each channel's motor in actuator_function
    (101 = Motor1): outputs MAIN1-4 driving motors 4, 1, 2, 3 were read as [5400, 5100, 5200,
    5300] rpm for motors 1-4 (a PX4 audit, 2026-11-27)."""
    from .ulog_writer import write_ulog

    t, topics = _px4_topics()
    fn = [104, 101, 102, 103]
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000 + 100 * (fn[k] - 100), fn)
    write_ulog(tmp_path / "f.ulg", topics, nested)
    log = read_flight_log(tmp_path / "f.ulg")
    np.testing.assert_allclose(log.rotor_omega[0] * 30 / math.pi, [5100, 5200, 5300, 5400], rtol=1e-12)
    assert "actuator_function" in log.motor_order and "entries 1, 2, 3, 0" in log.motor_order
    fn2 = [101, 102, 0, 0]  # (motor 3 assigned to no channel)
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, fn2)
    write_ulog(tmp_path / "g.ulg", topics, nested)
    with pytest.raises(FlightLogError, match="assigns motor.s. 1, 2 to its entries, not motor 3 of the 4"):
        read_flight_log(tmp_path / "g.ulg", n_motors=4)


def _restamp(raw: bytearray, topic_id: int, k: int, stamp_us: int) -> int:
    """Set the timestamp (after the message id) of topic ``topic_id``'s k-th data message in the
    ULog bytes ``raw`` to ``stamp_us``; return the message's offset."""
    import struct

    pos, seen = 16, 0
    while pos < len(raw):
        size, kind = struct.unpack_from("<HB", raw, pos)
        if kind == ord("D") and struct.unpack_from("<H", raw, pos + 3)[0] == topic_id:
            seen += 1
            if seen == k:
                raw[pos + 5:pos + 13] = struct.pack("<Q", stamp_us)
                return pos
        pos += 3 + size
    raise AssertionError(f"topic {topic_id} has fewer than {k} data messages")


def test_ulog_other_topics_gaps_and_stale_stamps(tmp_path):
    """Only the accelerations' gaps and time order were checked (a PX4 audit, 2026-11-27): a 1.7 s
    dropout of esc_status was interpolated across without a word, a message stamped 0 fed
    np.interp decreasing times (an rpm of 11 read for 0.5 above the truth)."""
    import struct

    from .ulog_writer import write_ulog

    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, keep=lambda ti: not 1.9e6 < ti < 3.6e6)
    write_ulog(tmp_path / "gap.ulg", topics, nested)
    with pytest.warns(UserWarning, match=r"topic 'esc_status': a gap of 1.7 s at 1.9 s since boot"):
        read_flight_log(tmp_path / "gap.ulg")
    t, topics = _px4_topics()
    rows = topics["vehicle_local_position"][1]
    rows[250] = (rows[250][0], 9.0, 9.0, 9.0)  # to be stamped 0 below, out of time order in the file
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000 + 10 * k)
    write_ulog(tmp_path / "stale.ulg", topics, nested)
    raw = bytearray((tmp_path / "stale.ulg").read_bytes())
    pos = _restamp(raw, list(topics).index("vehicle_local_position"), 251, 0)
    (tmp_path / "stale.ulg").write_bytes(bytes(raw))
    with pytest.warns(UserWarning, match=r"'vehicle_local_position': 1 message.s. out of time order left out "
                                         r"\(the first, message 251, stamped 0 s since boot\)"):
        log = read_flight_log(tmp_path / "stale.ulg")
    np.testing.assert_allclose(log.velocity, np.tile([1.0, 0.0, 0.0], (log.n, 1)), atol=1e-6)  # (NED north: x)
    # one stamped forward (1001 s) is left out alone (it left out the rest of its topic: a review)
    raw[pos + 5:pos + 13] = struct.pack("<Q", 1_001_000_000)
    (tmp_path / "fwd.ulg").write_bytes(bytes(raw))
    with pytest.warns(UserWarning, match=r"1 message.s. out of time order left out \(the first, message 251, "
                                         r"stamped 1001 s"):
        log = read_flight_log(tmp_path / "fwd.ulg")
    np.testing.assert_allclose(log.velocity, np.tile([1.0, 0.0, 0.0], (log.n, 1)), atol=1e-6)
    # the accelerations' own stale stamp: left out as the other topics' (it was refused, the others filtered)
    acc = list(topics).index(next(k for k in topics if k in ("vehicle_acceleration", "sensor_combined")))
    raw = bytearray((tmp_path / "gap.ulg").read_bytes())
    _restamp(raw, acc, 251, 0)
    (tmp_path / "acc.ulg").write_bytes(bytes(raw))
    with pytest.warns(UserWarning, match=r"1 message.s. out of time order left out \(the first, message 251, "
                                         r"stamped 0 s"):
        assert read_flight_log(tmp_path / "acc.ulg").n == 399  # (the 400 samples but the stale one)
    # PX4 logs topics at exactly 10 Hz (a review: warned of as slow by a microsecond's jitter)
    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, keep=lambda ti: (ti - 1_000_000) % 100_000 == 0)
    topics["esc_status"][1][:] = [(r[0] + (3 if i % 2 else 0),) + r[1:] for i, r in enumerate(topics["esc_status"][1])]
    write_ulog(tmp_path / "ten.ulg", topics, nested)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_flight_log(tmp_path / "ten.ulg")
    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, keep=lambda ti: (ti - 1_000_000) % 250_000 == 0)
    write_ulog(tmp_path / "slow.ulg", topics, nested)
    with pytest.warns(UserWarning, match=r"topic 'esc_status' logged at 4 Hz"):
        read_flight_log(tmp_path / "slow.ulg")


def _refusal_within(path, seconds: float) -> str:
    """The FlightLogError message of reading ``path`` in a thread that must end within ``seconds``
    (a reader that hangs fails the test instead of the session; the thread is a daemon)."""
    import threading

    result = {"error": ""}

    def read():
        try:
            read_flight_log(path)
        except FlightLogError as exc:
            result["error"] = str(exc)

    worker = threading.Thread(target=read, daemon=True)
    worker.start()
    worker.join(seconds)
    assert not worker.is_alive(), f"reading {path} did not end within {seconds} s"
    return result["error"]


def test_ulog_a_damaged_file_is_refused_or_warned_of_never_hangs(tmp_path, capsys):
    """A damaged message header (size 0xffff) hung the reader at full CPU: pyulog stepped back
    before the start of an in-memory file, which io.BytesIO allows, and read the definitions again
    without end (a PX4 audit, 2026-11-27); a damaged data section printed pyulog's notices on
    standard output (the CLI's --json) and was read without a word."""
    import struct

    from propmap.cli.main import main

    bad = tmp_path / "hang.ulg"
    bad.write_bytes(b"ULog\x01\x125\x01" + bytes(8) + struct.pack("<HB", 0xFFFF, 0xFF))
    assert "not a readable ULog file" in _refusal_within(bad, 60.0)
    assert main(["wrench", str(bad), "--vehicle", "quadrotor", "--out", str(tmp_path / "o.csv")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "hang.ulg: not a readable ULog file" in err[0]
    # zeros over part of the data section: pyulog reads on; warned of, nothing on standard output
    hover_ulog(tmp_path / "f.ulg")
    raw = bytearray((tmp_path / "f.ulg").read_bytes())
    raw[len(raw) // 2:len(raw) // 2 + 64] = bytes(64)
    (tmp_path / "d.ulg").write_bytes(bytes(raw))
    capsys.readouterr()
    with pytest.warns(UserWarning, match=r"d.ulg: a damaged ULog file \("):
        read_flight_log(tmp_path / "d.ulg")
    assert capsys.readouterr().out == ""
    # cut inside a message (power lost, a full card): pyulog stops there without a flag; warned of, the whole
    # messages before the cut read as logged (a flight-log audit, 2026-11-28: exit 0 and a third of a log unsaid)
    whole = read_flight_log(tmp_path / "f.ulg")
    raw = (tmp_path / "f.ulg").read_bytes()
    (tmp_path / "cut.ulg").write_bytes(raw[:int(len(raw) * 0.7)])
    with pytest.warns(UserWarning, match=r"cut.ulg: the file ends inside a message \(cut short"):
        cut = read_flight_log(tmp_path / "cut.ulg")
    assert 0 < cut.n < whole.n
    np.testing.assert_array_equal(cut.rotor_omega[:cut.n // 2], whole.rotor_omega[:cut.n // 2])
    # cut right after a message's 3-byte header, its payload missing (read as nothing: missed, a review)
    import struct

    at, bounds = 16, []  # (the file header, then messages of a 3-byte header: uint16 size, uint8 type)
    while at < len(raw):
        bounds.append(at)
        at += 3 + struct.unpack_from("<H", raw, at)[0]
    (tmp_path / "cut3.ulg").write_bytes(raw[:bounds[int(len(bounds) * 0.7)] + 3])
    with pytest.warns(UserWarning, match=r"cut3.ulg: the file ends inside a message"):
        read_flight_log(tmp_path / "cut3.ulg")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_flight_log(tmp_path / "f.ulg")  # (the whole file: not said)


def test_ulog_esc_functions_that_do_not_match_the_vehicle_are_refused(tmp_path):
    """Six ESCs assigned Motor1-6 read against a quadrotor were accepted as its four (a review,
    2026-11-27; refused before the actuator_function order), a motor on two channels kept the last."""
    from .ulog_writer import write_ulog

    t, topics = _px4_topics()
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, [101, 102, 103, 105])
    write_ulog(tmp_path / "five.ulg", topics, nested)
    with pytest.raises(FlightLogError, match="assigns motors up to 5; the vehicle has 4 rotors"):
        read_flight_log(tmp_path / "five.ulg", n_motors=4)
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, [101, 101, 102, 103])
    write_ulog(tmp_path / "twice.ulg", topics, nested)
    with pytest.raises(FlightLogError, match="assigns motor 1 to two entries"):
        read_flight_log(tmp_path / "twice.ulg")
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000 + 100 * k, [0, 102, 101, 0])  # (no vehicle: 2 motors)
    write_ulog(tmp_path / "two.ulg", topics, nested)
    np.testing.assert_allclose(read_flight_log(tmp_path / "two.ulg").rotor_omega[0] * 30 / math.pi, [5200, 5100])


def test_ulog_large_damaged_file_notices_and_warnings_after_refusals(tmp_path, capsys):
    """A damaged header more than 64 KiB into the definitions hung pyulog (it steps back by the
    message's size field, here within the file); a notice that is not damage (a newer format
    version) was called a damaged file; a refused log printed its warnings too (a review,
    2026-11-27). pyulog's notices never reach standard output, which stays the caller's."""
    import struct
    import sys

    from .ulog_writer import _msg

    raw = bytearray(b"ULog\x01\x125\x01" + bytes(8))
    for k in range(400):
        raw += _msg(b"I", bytes([11]) + b"char[8] k%05d" % k + b"x" * 200)
    raw += struct.pack("<HB", 0xFFFF, 0xFF)
    assert len(raw) > 65536
    (tmp_path / "big.ulg").write_bytes(bytes(raw))
    assert "not a readable ULog file" in _refusal_within(tmp_path / "big.ulg", 60.0)
    hover_ulog(tmp_path / "f.ulg")
    v2 = bytearray((tmp_path / "f.ulg").read_bytes())
    v2[7] = 2  # the format version
    (tmp_path / "v2.ulg").write_bytes(bytes(v2))
    stdout = sys.stdout
    with pytest.warns(UserWarning, match=r"v2.ulg: pyulog: Warning: unknown file version") as rec:
        read_flight_log(tmp_path / "v2.ulg")
    assert not any("a damaged ULog" in str(w.message) for w in rec) and sys.stdout is stdout
    assert capsys.readouterr().out == ""
    # accelerations in g and esc_status at 4 Hz: the refusal alone
    t, topics = _px4_topics()
    topics["vehicle_acceleration"][1][:] = [(r[0], 0.0, 0.0, -1.0) for r in topics["vehicle_acceleration"][1]]
    topics["esc_status"], nested = _esc(t, lambda ti, k: 5000, keep=lambda ti: (ti - 1_000_000) % 250_000 == 0)
    from .ulog_writer import write_ulog

    write_ulog(tmp_path / "g.ulg", topics, nested)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        with pytest.raises(FlightLogError, match="accelerometer reads"):
            read_flight_log(tmp_path / "g.ulg")
    assert not rec



# PX4's output functions (control allocation): motor m on output i where <PREFIX>_FUNC<i> = 100 + m
_OUT = [510.0, 520.0, 530.0, 540.0] + [0.0] * 12  # rpm / 10 on outputs 1-4: 5100, 5200, 5300, 5400 rpm


def _rpm(log):
    return np.round(log.rotor_omega[0] * 60 / (2 * math.pi), 3).tolist()


def test_ulog_actuator_outputs_follow_the_logs_output_functions(tmp_path):
    """Motor m is read from the output whose PWM_MAIN_FUNC is PX4's Motor m (101 = Motor1), not
    from output m: a quadrotor whose outputs 1-4 drive motors 2, 1, 4, 3 was read as [5100,
    5200, 5300, 5400] rpm for [5200, 5100, 5400, 5300] (a leftover of the PX4 audit: the first
    outputs were taken as the motors)."""
    params = {"PWM_MAIN_FUNC1": 102, "PWM_MAIN_FUNC2": 101, "PWM_MAIN_FUNC3": 104, "PWM_MAIN_FUNC4": 103,
              "PWM_MAIN_FUNC5": 0, "PWM_AUX_FUNC1": 201}
    hover_ulog(tmp_path / "f.ulg", with_esc=False, n_outputs=8, outputs=_OUT, params=params)
    log = read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=4)
    assert _rpm(log) == [5200.0, 5100.0, 5400.0, 5300.0]
    assert "output[1, 0, 3, 2] for Motor1..Motor4 (by PWM_MAIN_FUNCn)" in log.motor_order
    # motors on outputs 5-8, servos on 1-4 (a VTOL's layout): the first outputs are not motors
    out = [1500.0] * 4 + _OUT[:4] + [0.0] * 8
    params = {f"PWM_MAIN_FUNC{i}": 200 + i for i in range(1, 5)} | {f"PWM_MAIN_FUNC{i}": 96 + i for i in range(5, 9)}
    hover_ulog(tmp_path / "v.ulg", with_esc=False, n_outputs=8, outputs=out, params=params)
    assert _rpm(read_flight_log(tmp_path / "v.ulg", motor_map=(0.0, 10.0), n_motors=4)) == [5100.0, 5200.0,
                                                                                              5300.0, 5400.0]
    # without the vehicle's rotor count: the motors the parameters assign
    assert read_flight_log(tmp_path / "v.ulg", motor_map=(0.0, 10.0)).n_motors == 4


def test_ulog_output_functions_that_cannot_be_read_are_refused(tmp_path):
    def read(params, n_motors=4, changed=None):
        hover_ulog(tmp_path / "f.ulg", with_esc=False, n_outputs=8, outputs=_OUT, params=params, changed=changed)
        return read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=n_motors)

    quad = {f"PWM_MAIN_FUNC{i}": 100 + i for i in range(1, 5)}
    with pytest.raises(FlightLogError, match=r"no output driver carries motors 1\.\.4 \(PWM_AUX_FUNCn: motor\(s\) "
                                             r"3, 4; PWM_MAIN_FUNCn: motor\(s\) 1, 2\)"):
        read({"PWM_MAIN_FUNC1": 101, "PWM_MAIN_FUNC2": 102, "PWM_AUX_FUNC1": 103, "PWM_AUX_FUNC2": 104})
    with pytest.raises(FlightLogError, match=r"PWM_MAIN_FUNCn assign\(s\) motors up to 6; the vehicle has 4"):
        read(quad | {"PWM_MAIN_FUNC5": 105, "PWM_MAIN_FUNC6": 106})
    with pytest.raises(FlightLogError, match=r"assign no output a motor \(Motor1\.\.Motor12 = 101\.\.112\)"):
        read({f"PWM_MAIN_FUNC{i}": 200 + i for i in range(1, 9)})
    with pytest.raises(FlightLogError, match=r"puts a motor on output 12; topic 'actuator_outputs' \(instance 0\) "
                                             r"has 8 outputs"):
        read({"PWM_MAIN_FUNC1": 101, "PWM_MAIN_FUNC2": 102, "PWM_MAIN_FUNC3": 103, "PWM_MAIN_FUNC12": 104})
    with pytest.raises(FlightLogError, match="parameter PWM_MAIN_FUNC2 changes during the log"):
        read(quad, changed=[(1_500_000, "PWM_MAIN_FUNC2", 103)])
    # a parameter logged again with its value is no change
    assert _rpm(read(quad, changed=[(1_500_000, "PWM_MAIN_FUNC2", 102)])) == [5100.0, 5200.0, 5300.0, 5400.0]


def test_ulog_mixer_files_read_the_first_outputs_or_betaflights_order(tmp_path):
    """PX4 v1.13 with SYS_CTRL_ALLOC = 0 (mixer files) ignores the FUNC parameters: the first
    outputs are the motors, in Betaflight's order with MOT_ORDERING = 1 (PX4's
    MixingOutput::reorderOutputs puts motor 4 on output 1, motors 1-3 on outputs 2-4)."""
    legacy = {"SYS_CTRL_ALLOC": 0, "PWM_MAIN_FUNC1": 104, "PWM_MAIN_FUNC4": 101}
    hover_ulog(tmp_path / "f.ulg", with_esc=False, n_outputs=8, outputs=_OUT, params=legacy)
    assert _rpm(read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=4)) == [5100.0, 5200.0,
                                                                                              5300.0, 5400.0]
    hover_ulog(tmp_path / "b.ulg", with_esc=False, n_outputs=8, outputs=_OUT, params={"MOT_ORDERING": 1})
    log = read_flight_log(tmp_path / "b.ulg", motor_map=(0.0, 10.0), n_motors=4)
    assert _rpm(log) == [5200.0, 5300.0, 5400.0, 5100.0]
    assert "MOT_ORDERING = 1" in log.motor_order


def test_ulog_the_motors_instance_is_the_one_whose_outputs_vary(tmp_path):
    """Two actuator_outputs instances (the log does not say which driver is which): the motors on
    PWM_AUX (instance 1), PWM_MAIN driving servos at a constant 1500 us (instance 0). The
    motors were read from instance 0: [1500, 1500, 1500, 1500] rpm (a review); now from the
    lowest instance whose motor outputs vary, with a warning naming it."""
    servos = [150.0] * 4 + [0.0] * 12
    params = {f"PWM_MAIN_FUNC{i}": 200 + i for i in range(1, 5)} | {f"PWM_AUX_FUNC{i}": 100 + i for i in range(1, 5)}
    hover_ulog(tmp_path / "f.ulg", with_esc=False, n_outputs=8, outputs=servos, params=params, second_outputs=_OUT)
    with pytest.warns(UserWarning, match=r"read from instance 1, the lowest whose motor outputs vary"):
        log = read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=4)
    np.testing.assert_allclose(log.rotor_omega * 60 / (2 * math.pi), [[5100, 5200, 5300, 5400]] * log.n, rtol=1e-4)


def test_ulog_betaflight_order_is_the_mixer_files_only(tmp_path):
    """MOT_ORDERING acts with mixer files; with SYS_CTRL_ALLOC = 1 (v1.13's dynamic mixing) it
    does not (a review: it was applied there)."""
    hover_ulog(tmp_path / "f.ulg", with_esc=False, n_outputs=8, outputs=_OUT,
               params={"SYS_CTRL_ALLOC": 1, "MOT_ORDERING": 1})
    assert _rpm(read_flight_log(tmp_path / "f.ulg", motor_map=(0.0, 10.0), n_motors=4)) == [5100.0, 5200.0,
                                                                                              5300.0, 5400.0]


def test_ulog_velocity_messages_flagged_invalid_are_left_out(tmp_path):
    """An estimate flagged invalid (v_xy_valid, v_z_valid 0: no GPS, indoors) of 0 m/s was read as
    the velocity (an input fuzzing audit, 2026-11-27): the flagged messages are left out, with a
    note; a log with no valid one is read as logged, with a note (PX4's EKF2 flags the velocity
    with the horizontal position: a flight without position aiding has none valid; a review), and
    the kinematic check judges it."""
    valid = np.ones(200, bool)
    valid[40:60] = False
    hover_ulog(tmp_path / "f.ulg", rpm=12000.0, velocity_valid=valid)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        log = read_flight_log(tmp_path / "f.ulg")
    assert any("20 of 200 velocity messages flagged invalid (v_xy_valid, v_z_valid) left out" in str(w.message)
               for w in caught)
    np.testing.assert_allclose(np.linalg.norm(log.velocity, axis=1), 2.0, rtol=1e-6)  # (no sample at 0 m/s)
    hover_ulog(tmp_path / "g.ulg", rpm=12000.0, velocity_valid=np.zeros(200, bool))  # (its velocity 0: consistent)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        read_flight_log(tmp_path / "g.ulg")
    assert any("flagged invalid (v_xy_valid, v_z_valid) in all 200 messages (a flight without position aiding"
               in str(w.message) for w in caught)


def test_an_integer_or_sparse_mat_log_is_named_as_such(tmp_path):
    """An int16 log (time truncated to whole seconds) was refused as 'time does not increase at
    sample 2', and a sparse matrix as 'found 0 variable(s) (none)' (a flight-log fuzzing audit,
    2026-11-27)."""
    import scipy.sparse

    a = np.arange(41 * 5, dtype=np.int16).reshape(5, 41)
    scipy.io.savemat(tmp_path / "i.mat", {"x": a})
    with pytest.raises(FlightLogError, match=r"i\.mat: variable 'x' holds int16 values; a flight log's are "
                                             r"floating-point"):
        read_flight_log(tmp_path / "i.mat")
    scipy.io.savemat(tmp_path / "s.mat", {"x": scipy.sparse.csc_matrix(a.astype(float))})
    with pytest.raises(FlightLogError, match=r"s\.mat: expected one N x 41 array, found 0 variable\(s\) \(none\); "
                                             r"not read: x \(a sparse matrix\)"):
        read_flight_log(tmp_path / "s.mat")


def test_the_mass_a_logs_own_prediction_was_made_for(shared_data, tmp_path):
    """NeuroBEM's prediction plus its residual is 0.752 kg times the specific force (the mass first
    published; the vehicle file has the corrected 0.772 kg) to 1.4e-6 N: the reader gives that mass,
    and the scores scale the prediction to the vehicle's mass (0.244 N pooled on the melon log as
    logged, 0.151 N scaled: a flight-log audit, 2026-11-28). Without the residual columns, or with
    columns that are not a mass times the specific force, no mass; at the vehicle's own mass (within
    0.5%) no scaled row."""
    import dataclasses

    import scipy.io

    from propmap.identify.flight import flight_samples, reference_at_vehicle_mass

    path = shared_data / "neurobem_flights" / "bemnn20210223114138seg3.mat"
    log = read_flight_log(path)
    assert log.reference_mass == pytest.approx(0.752, abs=1e-5)
    veh = pm.read_vehicle("neurobem_quadrotor")
    s = flight_samples([log], veh)
    scaled, masses = reference_at_vehicle_mass(s, veh.mass)
    np.testing.assert_allclose(scaled, s.reference_force * veh.mass / log.reference_mass, rtol=1e-12)
    assert masses == (pytest.approx(0.752, abs=1e-5),)
    assert reference_at_vehicle_mass(s, log.reference_mass * 1.004) is None
    a = scipy.io.loadmat(path)
    a = next(v for k, v in a.items() if not k.startswith("__")).astype(float)
    for change in ("zero residual", "noise"):
        b = a.copy()
        b[:, 35:38] = 0.0 if change == "zero residual" else np.random.default_rng(0).normal(size=(len(b), 3))
        scipy.io.savemat(tmp_path / "b.mat", {"log": b})
        other = read_flight_log(tmp_path / "b.mat")
        assert other.reference_force is not None and other.reference_mass is None
        assert reference_at_vehicle_mass(flight_samples([other], veh), veh.mass) is None
    assert reference_at_vehicle_mass(dataclasses.replace(s, reference_mass=()), veh.mass) is None


@pytest.mark.parametrize("scaled, said", [
    ((4, 7), r"the logged angular acceleration is 0\.017\d* times the logged rates' change \(within 0\.3-3 expected\): "
             r"are the rates in deg/s \(the ratio near 1/57\.3\)\?"),
    ((1, 7), r"agrees with the rates read in deg/s: are they in deg/s\? A log's rates are read in rad/s")])
def test_rates_in_deg_per_s_on_a_slow_log_are_named(tmp_path, shared_data, scaled, said):
    """On the slow figure-8 (3.5 m/s) the rates' own deg/s check does not judge (its rates are
    small), and rates in deg/s were told 'zeros or another quantity?' (the angular acceleration
    left in rad/s^2) or 'is the velocity in the body frame?' (both in degrees): now deg/s is named
    (a flight-log audit, 2026-11-30)."""
    import pandas as pd

    a = next(v for k, v in scipy.io.loadmat(shared_data / "neurobem_flights" / SEGMENTS[2]).items()
             if not k.startswith("__")).copy()
    a[:, scaled[0]:scaled[1]] *= 180 / np.pi
    pd.DataFrame(a, columns=NEUROBEM_COLUMNS).to_csv(tmp_path / "deg.csv", index=False)
    with pytest.raises(FlightLogError, match=said):
        read_flight_log(tmp_path / "deg.csv")
