"""``propmap fit flight`` and ``propmap wrench``: flight logs against the vehicle model."""

from __future__ import annotations

import math
from pathlib import Path

import click

from ..core.units import RPM
from ._air import air_label, air_record, resolve_air, with_air_options

from ._common import Command, InputError, PathArg, load_params, parse_names, warn, with_warnings
from ._coverage import J_SLACK, RATE_SLACK, airspeed_beyond, j_max
from ._flight_report import (NEUROBEM_REFERENCE, _reference_mass_note, _reference_rows, _report_lines, _scores, _table,
                             band_line, hover_torque_warning)
from ._paths import check_outputs, refuse_copies, vehicle_inputs
from ._vehicle import (_check_rotor_sets, _descent_state_warning, _layout_warnings, _one_set, _rotor_coverage,
                       _vehicle, _vehicle_sets)
from .fit import _options, _out_files, _run_fit, _vehicle_propeller, _write_outputs, with_fit_options


MOTOR_MAP_HELP = ("PX4 ULog: the motor speed [rpm] = A + B * actuator_outputs output, given as A,B (the ESC's "
                  "calibration; used even where the log has esc_status rpm); motor m is the output the log's "
                  "PWM_MAIN_FUNCn (or another driver's FUNCn) parameters assign Motor m, else output m (in "
                  "Betaflight's order with MOT_ORDERING=1).")


def _motor_map(text: str | None):
    """``--motor-map A,B`` as two finite numbers, B not 0 (None where not given)."""
    if text is None:
        return None
    try:
        a, b = (float(x) for x in text.split(","))
    except ValueError:
        raise InputError(f"--motor-map must be two numbers A,B (rpm = A + B * output), got {text!r:.60}") from None
    if not (math.isfinite(a) and math.isfinite(b) and b != 0):
        raise InputError(f"--motor-map: A and B must be finite and B not 0, got {text!r:.60}")
    return a, b


def _logs(paths, motor_map=None, n_motors=None):
    from ..io.flightlog import FlightLogError, read_flight_log

    if motor_map is not None and not any(Path(p).suffix.lower() == ".ulg" for p in paths):
        raise InputError("--motor-map applies to PX4 .ulg logs only, and no LOG is one (a NeuroBEM log gives the motor "
                         "speeds)")
    logs = []
    for p in paths:
        # (the map for the .ulg logs only: a NeuroBEM log and a ULog without esc_status could not be fitted together,
        # a flight-log audit, 2026-12-01)
        ulg = Path(p).suffix.lower() == ".ulg"
        try:
            logs.append(read_flight_log(p, motor_map=motor_map if ulg else None, n_motors=n_motors if ulg else None))
        except FlightLogError as exc:
            raise InputError(f"LOG: {exc}") from None
        if logs[-1].motor_order.startswith("PX4"):  # (which output or ESC entry is which motor: checkable)
            click.echo(f"propmap: note: {logs[-1].name}: motor speeds from {logs[-1].motor_order}", err=True)
    return logs


def _refuse_same_flight(logs) -> None:
    """Refuse two logs of one flight in other forms (a .mat and its .csv: not copies by their
    bytes, yet a held-out one would train its own fit; a flight audit): the same times and motor
    speeds, to a CSV's rounding; or a log whose motor speeds and accelerometer are a stretch of
    another's, sample by sample, whatever its time (a piece of it, or it with its time shifted:
    :func:`_repeated_in`)."""
    import numpy as np

    seen = {}
    for lg in logs:
        step = float(np.median(np.diff(lg.t)))  # (a '%g' export rounds speeds by 4e-6 and times past 100 s)
        for other in seen.get(lg.n, ()):
            if (np.allclose(lg.t, other.t, rtol=0, atol=0.1 * step)
                    and np.allclose(lg.rotor_omega, other.rotor_omega, rtol=1e-4, atol=1e-6)):
                raise InputError(f"LOG: {lg.name} and {other.name} hold the same flight (times and motor speeds): its "
                                 "samples would count twice (and a held-out log would train its own fit)")
        seen.setdefault(lg.n, []).append(lg)
    # a piece of another log, or the same with its time shifted (a held-out piece of a training log was scored as new
    # data: a flight-log audit, 2026-11-27): its motor speeds and accelerometer, sample by sample, inside the other's
    for k, short in enumerate(logs):
        piece = _repeated_in(short, [lg for j, lg in enumerate(logs) if j != k and
                                     (lg.n > short.n or (lg.n == short.n and j < k))])
        if piece is not None:
            long, i = piece
            raise InputError(f"LOG: {short.name} repeats the motor speeds and accelerations of {long.name} from its "
                             f"sample {i + 1} on, sample by sample ({short.n} samples: a piece or a copy of it, its "
                             "time shifted?): its samples would count twice (and a held-out log would train its own "
                             "fit)")


def _repeated_in(short, others):
    """(other log, its sample index) where ``short``'s motor speeds and specific force recur
    sample by sample (to a CSV's rounding) in one of ``others``, or None. Anchored at the sample
    where ``short``'s motor speeds change most (a log at constant speeds, two runs of one
    commanded speed, is never one: its speeds do not vary); the 64 samples around the anchor
    are compared before the whole."""
    import numpy as np

    om = short.rotor_omega
    step = np.max(np.abs(np.diff(om, axis=0)), axis=1) if short.n > 1 else np.zeros(0)
    if not step.size or step.max() <= 1e-3 * max(float(np.max(np.abs(om))), 1e-300):
        return None
    a = int(np.argmax(step)) + 1  # the anchor: the sample after the largest change

    def same(x, y):
        return np.allclose(x, y, rtol=1e-4, atol=1e-6)

    for long in others:
        lo = long.rotor_omega
        cand = np.flatnonzero(np.all(np.isclose(lo[a: long.n - short.n + a + 1], om[a], rtol=1e-4, atol=1e-6), axis=1))
        for c in cand[:1000]:
            i = int(c)  # the piece would start at sample i of the long log
            head = slice(max(0, a - 32), min(short.n, a + 32))
            if not same(lo[i + head.start:i + head.stop], om[head]):
                continue
            if same(lo[i:i + short.n], om) and same(long.specific_force[i:i + short.n], short.specific_force):
                return long, i
    return None


def _samples(logs, veh, rate_hz):
    """flight_samples of the logs, its left-out samples said as warnings (once each)."""
    from ..identify.flight import flight_samples

    try:
        samples = flight_samples(logs, veh, rate_hz=rate_hz)
    except ValueError as exc:  # (a log's own error starts with its name)
        about_a_log = any(str(exc).startswith(f"{lg.name}:") for lg in logs)
        raise InputError(f"LOG: {exc}" if about_a_log else str(exc)) from None
    for note in samples.notes:
        click.echo(f"propmap: warning: {note}", err=True)
    return samples


def _write_columns(fh, cols: dict, exact=("t",)) -> None:
    """Write equal-length float columns as CSV: a header of their names, then one row per sample,
    each number as %.6g (those of the ``exact`` columns, the time, to the last digit: a log's
    time of 1,200 s or a Unix time needs more than six) and an empty cell for NaN; the csv module,
    not pandas, so that ``wrench`` does not import pandas (0.18 s of its 1.9)."""
    import csv

    import numpy as np

    names = list(cols)
    table = np.column_stack([np.asarray(cols[n], float) for n in names])
    writer = csv.writer(fh, lineterminator="\n")
    writer.writerow(names)
    nan = np.isnan(table)
    form = [repr if n in exact else "{:.6g}".format for n in names]
    writer.writerows(["" if miss else f(x) for f, x, miss in zip(form, row, nanrow)]
                     for row, nanrow in zip(table.tolist(), nan.tolist()))


def _flight_out_files(out: Path) -> list:
    """fit._out_files and the speed figure beside them."""
    stem = Path(out).with_suffix("")
    return _out_files(out) + [("--out (report/figure beside it)", stem.with_name(stem.name + ".speed.png"))]


@click.command("flight", cls=Command)
@click.argument("log_paths", metavar="LOG...", nargs=-1, required=True, type=PathArg())
@click.option("--vehicle", type=PathArg(text=True), required=True,
              help="Vehicle TOML, its rotors in the logs' motor order.")
@click.option("--holdout", default=None, help="Comma-separated LOG file names to hold out (scored, not fitted).")
@click.option("--base", "base_spec", default="generic", show_default=True,
              help="Start and constants not fitted: a named set or a parameter file.")
@click.option("--rate-hz", type=float, default=25.0, show_default=True,
              help="Samples per second taken from the logs, in (0, 10000].")
@click.option("--moments", is_flag=True,
              help="Fit the measured moments too (I dw/dt + w x I w; the vehicle file needs its inertia).")
@click.option("--cross-validate", "cross_validate", is_flag=True,
              help="Also leave each training log out in turn (one fit per log) and report the held-out errors.")
@click.option("--motor-map", "motor_map", default=None, metavar="A,B", help=MOTOR_MAP_HELP)
@with_fit_options
@with_air_options
def fit_flight_command(log_paths, vehicle, holdout, base_spec, rate_hz, moments, cross_validate, motor_map, out,
                       as_json, fit_choice, air_choice):
    """Fit the rotor and airframe parameters to flight logs (eqs 16-18 in three axes).

    LOG: NeuroBEM .mat or .csv, or PX4 .ulg; the vehicle file lists its rotors in the logs'
    motor order. The measured force is the mass times the logged specific force.
    """
    import numpy as np

    from ..identify.flight import (AIRFRAME_NAMES, cross_validate_flight, default_flight_names, fit_baselines,
                                   fit_flight, fitted_body_drag, fitted_vehicle, hover_torque_check, predict_flight)
    from ..identify.dependence import jackknife_report
    from ..io.params_file import BodyTable

    check_outputs(_flight_out_files(out), [*log_paths, vehicle, base_spec])
    veh = _vehicle(vehicle)
    check_outputs(_flight_out_files(out), vehicle_inputs(vehicle))
    if not (math.isfinite(rate_hz) and 0 < rate_hz <= 1e4):
        raise InputError(f"--rate-hz must be in (0, 10000] Hz, got {rate_hz!r}")
    if moments and veh.inertia is None:  # (before the logs are read: it was said after every log was sampled)
        raise InputError("--moments: the vehicle file gives no inertia, so the logs' moments cannot be measured")
    base, air, base_label = load_params(base_spec, option="--base")
    # (a --base file's [body] table is the airframe to start from and hold where not fitted, as --params' is in wrench;
    # it was dropped without a word, its z drag written as 0: a user-level audit, 2026-12-01)
    from ..io.inputs import short_path
    from ..vehicle.own_set import with_set_body

    veh, body_from = with_set_body(veh, base_spec)
    if body_from:
        click.echo(f"propmap: note: --base {short_path(body_from)}: its [body] table (airframe drag, and the centre of "
                   "mass and rotor interference where it gives them) replaces the vehicle's airframe, the start of "
                   "the airframe terms fitted and the value of those not", err=True)
    _check_rotor_sets(veh, [base_label] * len(veh.rotors))
    air = resolve_air(air, air_choice)
    refuse_copies(log_paths, "LOG", "its samples would count twice (and a held-out log would train its own fit)")
    names = _log_names(log_paths)
    veh = _one_set(veh, "fit flight fits one set for every rotor")
    held = _held_logs(holdout, names, cross_validate)
    logs = _logs(log_paths, _motor_map(motor_map), len(veh.rotors))  # (the names' checks before the reads)
    _refuse_same_flight(logs)
    for line in _layout_warnings(logs, veh):
        warn(line)
    samples = _samples(logs, veh, rate_hz)
    log_rate = min(lg.rate_hz for lg in logs)
    if rate_hz > 1.01 * log_rate:  # (flight_samples takes every k-th sample, k = round(log rate / rate) >= 1)
        click.echo(f"propmap: note: --rate-hz {rate_hz:g}: a log is sampled at {log_rate:.4g} Hz, so every sample of "
                   "it is taken", err=True)
    held_idx = [k for k, n in enumerate(names) if n in held]
    train = samples.select(~np.isin(samples.log_index, held_idx))
    opts = _options(fit_choice, base=base, base_label=base_label,
                    extra_names=AIRFRAME_NAMES)
    n_names = len(opts.names) if opts.names else len(default_flight_names(base))
    _check_training_samples(train, logs, held, n_names, rate_hz, cross_validate)
    res = _run_fit(fit_flight, train, veh, base=base, air=air, options=opts, moments=moments)
    body = fitted_body_drag(res)
    veh_in = veh
    veh = fitted_vehicle(veh, res)
    pred = predict_flight(samples, veh, res.params, body=body, air=air)
    baselines = fit_baselines(train, veh)
    rows, report, reference_masses = _scores(samples, names, held_idx, pred, baselines, veh)
    report["baselines"] = baselines
    report["hover_torque"] = hover_torque_check(res.params, veh, train, air=air)
    report["body_drag"] = res.extra.get("body_drag")
    if cross_validate:
        cv = _run_fit(cross_validate_flight, train, veh_in, base=base, air=air, options=opts, moments=moments)
        report["cross_validation"] = _cv_report(cv)
        if set(cv["folds"][0]["x"]) == set(res.names):  # (the report's jackknife column: the spread between logs)
            from ..identify.optimizer import _bounds

            res.extra["jackknife"] = jackknife_report(res, [f["x"] for f in cv["folds"]], "log",
                                                      [f["log"] for f in cv["folds"]],
                                                      [f["at_bound"] for f in cv["folds"]], _bounds(res.names, opts))
    res.extra["flight_report"] = report
    text = _report_lines(samples, names, held, train.n, rows, report, reference_masses, veh.mass)
    from dataclasses import replace

    ht = report["hover_torque"]
    if ht and "unavailable" in ht:
        res = replace(res, warnings=res.warnings + ("the hover torque check is unavailable: the generic reference set "
                                                    "cannot make the fitted set's hover thrust",))
    elif (off := hover_torque_warning(ht)) is not None:
        res = replace(res, warnings=res.warnings + (off,))
    from ._sources import file_digests

    # (the training logs' digests: wrench tells one of them by its content, not by a name that PX4's HH_MM_SS.ulg
    # repeats from day to day)
    coverage = {**_flight_coverage([lg for lg in logs if lg.name not in held], veh, res.air), "data": "flight logs",
                "groups": [n for n in names if n not in held], "held_out": sorted(held),
                "files_sha256": file_digests([p for p, n in zip(log_paths, names) if n not in held])}
    beyond = _held_beyond(logs, held, coverage, veh, res.air)
    if cross_validate:  # (each fold's log against the other training logs: said for --holdout only, a docs audit,
        # 2026-12-02)
        kept = [lg for lg in logs if lg.name not in held]
        for lg in kept:
            beyond += _held_beyond([lg], {lg.name}, _flight_coverage([o for o in kept if o is not lg], veh, res.air),
                                   veh, res.air, "cross-validation: the fold of")
    # (the samples fitted, then each held-out log's, with a rotor descending into its own wake)
    beyond += _descent_state_warning(pred.loads, "the training logs", ~np.isin(samples.log_index, held_idx))
    for k in held_idx:
        beyond += _descent_state_warning(pred.loads, f"held-out log {names[k]}", samples.log_index == k)
    res = replace(res, warnings=res.warnings + tuple(beyond))
    _write_outputs(res, out, base_label, as_json, "\n".join(text),
                   figure=_figures(samples, names, held, pred, baselines, veh, res.params, air, vehicle),
                   figure_suffixes=(".png", ".speed.png"), coverage=coverage,
                   body=BodyTable(body, veh.centre_of_mass if {"cg_x", "cg_y"} & set(res.names) else None,
                                  veh.rotor_interference if "rotor_interference" in res.names else None))


def _figures(samples, names, held, pred, baselines, veh, params, air, vehicle):
    """fit flight's figures, drawn once the outputs are written: measured against predicted body
    force over time (with the last baseline and the logs' own prediction), and the paper's Fig. 6
    (thrust, drag, torque and vertical-force error against speed, the hover model beside)."""

    def figures(png):
        import numpy as np

        from ..identify.flight import BASELINES, baseline_force
        from ..plots_flight import plot_flight_speed, plot_flight_timeseries

        t = {n: samples.t[samples.log_index == k] for k, n in enumerate(names)}
        meas = {n: samples.force[samples.log_index == k] for k, n in enumerate(names)}
        model = {n: pred.force[samples.log_index == k] for k, n in enumerate(names)}
        key, label, _ = BASELINES[-1]
        other = {label[:40]: {n: baseline_force(baselines[key], samples.of_log(k), veh) for k, n in enumerate(names)}}
        if samples.reference_force is not None:
            other["NeuroBEM BEM+NN (log)"] = {n: samples.reference_force[samples.log_index == k]
                                              for k, n in enumerate(names)}
        shown = veh.name or Path(vehicle).name
        plot_flight_timeseries(t, meas, model, png, other=other,
                               title=f"fit flight: measured m a vs predicted body force ({shown}); "
                                     f"held out: {', '.join(sorted(held)) or 'none'}")
        hover = _hover_loads(params, veh, samples, air)
        loads = {"thrust": sum(lo.thrust for lo in pred.loads), "drag": sum(lo.drag for lo in pred.loads),
                 "torque": sum(np.abs(lo.torque) for lo in pred.loads)}
        vertical = {"BET+BEMT (fitted)": pred.force[:, 2] - samples.force[:, 2],
                    "hover model": hover["vertical"] - samples.force[:, 2]}
        stem = png.with_suffix("")
        try:  # (refused since stop 104 where no 1 m/s bin holds 3 samples: a warning, the outputs being written)
            plot_flight_speed(samples.speed, loads, hover, vertical, stem.with_name(stem.name + ".speed.png"),
                              title=f"as Fig. 6 of Gill & D'Andrea (2017), from flight samples binned by speed "
                                    f"({shown}); held out: {', '.join(sorted(held)) or 'none'}")
        except ValueError as exc:
            warn(f"the speed figure is not drawn: {exc}")
            return (".png",)
        return (".png", ".speed.png")

    return figures


def _log_names(log_paths) -> list[str]:
    """The logs' names, their file names (a log's name, FlightLog.name, is its file name): two
    logs of one name are refused, since --holdout and the report's rows tell them apart by it."""
    names = [Path(p).name for p in log_paths]
    if len(set(names)) != len(names):
        twin = next(n for n in names if names.count(n) > 1)
        where = ", ".join(str(p) for p, n in zip(log_paths, names) if n == twin)
        raise InputError(f"LOG: two logs are named {twin!r} ({where}): the logs are told apart by their file name "
                         "(--holdout, the report's per-log rows); link or copy one under another name")
    return names


def _held_logs(holdout, names: list[str], cross_validate: bool) -> set[str]:
    """--holdout's logs by name: each one of the LOGs, at least one log left to fit (two with
    --cross-validate, which leaves each training log out in turn)."""
    held = parse_names("--holdout", holdout, what="log") or ()
    unknown = [h for h in held if Path(h).name not in names]
    if unknown:
        raise InputError(f"--holdout: {unknown[0]!r} is not one of the LOGs ({', '.join(names)})")
    held = {Path(h).name for h in held}
    if len(held) == len(names):
        raise InputError("--holdout: every LOG is held out; keep at least one to fit")
    if cross_validate and len(names) - len(held) < 2:
        raise InputError(f"--cross-validate leaves each training log out in turn: it needs at least 2 training logs, "
                         f"got {len(names) - len(held)}")
    return held


def _check_training_samples(train, logs, held, n_names: int, rate_hz: float, cross_validate: bool) -> None:
    """More than SAMPLES_PER_PARAMETER training samples per fitted parameter at --rate-hz, in the
    whole fit and, with --cross-validate, in the fold that leaves out the largest training log
    (checked before any fit, a review)."""
    import numpy as np

    from ..identify.flight import SAMPLES_PER_PARAMETER

    if train.n <= SAMPLES_PER_PARAMETER * n_names:
        total = sum(lg.n for lg in logs if lg.name not in held)
        raise InputError(f"--rate-hz {rate_hz:g}: {train.n} training sample(s) at that rate cannot identify {n_names} "
                         + (f"parameters; raise --rate-hz (the training logs hold {total} samples)" if train.n < total
                            else f"parameters: the training logs hold only {total} samples"))
    if cross_validate:
        per_log = np.bincount(np.asarray(train.log_index), minlength=len(logs))
        fold = train.n - int(per_log.max())
        if fold <= SAMPLES_PER_PARAMETER * n_names:
            raise InputError(f"--cross-validate at --rate-hz {rate_hz:g}: a fold keeps {fold} training sample(s), "
                             f"which cannot identify {n_names} parameters (more than {SAMPLES_PER_PARAMETER} per "
                             "parameter); raise --rate-hz")


def _flight_coverage(logs, veh, air) -> dict:
    """What the training logs' rotors covered, every sample at the logs' own rate (as `wrench` runs
    them; the fit's samples are a subsample), for the written file's [coverage] table: `wrench` and
    `loads` with the file then warn of faster flights. The rotors' operating points as
    vehicle_wrench forms them: hub velocity v + w x r_i, its incidence to the axis, the lagged speed.
    Where every rotor carries one propeller geometry, also that propeller (name, diameter, blade
    count) and its chord Reynolds numbers at 0.75 R in the fit's ``air``, as a load fit records
    them: a file fitted to a quadrotor's 5.1 in rotors ran an 8 in propeller unwarned (a user-level
    audit, 2026-11-26)."""
    import numpy as np

    from ..core.vector import disk_frame
    from ..identify.flight import flight_samples
    from ..vehicle import hub_velocities, rotor_geometry

    s = flight_samples(logs, veh, rate_hz=1e4)
    arms, axes, _, _ = rotor_geometry(veh)
    V_hub = hub_velocities(s.velocity, s.angular_velocity, arms)  # (N, n_rot, 3)
    _, _, speed, inc = disk_frame(V_hub, axes[None, :, :])  # (the hub's airspeed and incidence, as rotor_wrench's)
    axial = speed * np.cos(inc)
    n = s.rotor_omega / (2 * math.pi)
    D = np.array([r.propeller.diameter for r in veh.rotors])[None, :]
    # (the incidence of samples whose airspeed exceeds 1% of the tip speed, as _coverage.envelope_extremes reads it)
    moving = speed > 0.01 * s.rotor_omega * D / 2
    return {"J_max": j_max(axial, n, D),
            "incidence_deg_max": float(np.degrees(np.max(inc[moving]))) if moving.any() else 0.0,
            "rpm_min": float(np.min(s.rotor_omega) / RPM), "rpm_max": float(np.max(s.rotor_omega) / RPM),
            "airspeed_max": float(np.max(speed)),
            **_vehicle_propeller(veh, float(np.min(s.rotor_omega)), float(np.max(s.rotor_omega)), air)}


def _cv_report(cv: dict) -> dict:
    """:func:`propmap.identify.flight.cross_validate_flight`'s result with the folds' parameters
    and their jackknife std errors in the report's names and units (an angle as
    ``collective_deg`` in deg, as the report's ``fitted``: they were in rad under the bare name
    beside the report's degrees, a docs audit, 2026-12-02)."""
    from ..identify.options import report_name, report_value

    def named(x: dict) -> dict:
        return {report_name(n): report_value(n, v) for n, v in x.items()}

    folds = [{**f, "x": named(f["x"]), "at_bound": [report_name(n) for n in f["at_bound"]]} for f in cv["folds"]]
    return {**cv, "folds": folds, "jackknife_std_error": named(cv["jackknife_std_error"])}


def _held_beyond(logs, held, coverage: dict, veh, air, what: str = "held-out log") -> list[str]:
    """A warning per held-out log whose rotors go beyond what the training logs covered (the
    written file's [coverage]: airspeed, advance ratio, rpm), by `wrench --params`' margins
    (cli/_coverage: J_SLACK, RATE_SLACK, airspeed_beyond): its scores extrapolate the fit (said
    of none until 2026-11-30, where `wrench` with the written file warned of the same log: a
    flight-log audit). ``what`` names the log in the warning (a cross-validation fold's)."""
    out = []
    for lg in logs:
        if lg.name not in held:
            continue
        c = _flight_coverage([lg], veh, air)
        # (wrench's margins, cli/_coverage: a review found 5% and 2% here, and no floor near 0 m/s)
        over = [f"{c['airspeed_max']:.3g} m/s at a hub (the training logs' {coverage['airspeed_max']:.3g})"
                if airspeed_beyond(c["airspeed_max"], coverage["airspeed_max"]) else "",
                f"J {c['J_max']:.2g} (theirs {coverage['J_max']:.2g})" if c["J_max"] > coverage["J_max"] + J_SLACK
                else "",
                f"{c['rpm_min']:.0f}-{c['rpm_max']:.0f} rpm (theirs {coverage['rpm_min']:.0f}-"
                f"{coverage['rpm_max']:.0f})" if (c["rpm_max"] > coverage["rpm_max"] * (1 + RATE_SLACK)
                                                  or c["rpm_min"] < coverage["rpm_min"] * (1 - RATE_SLACK)) else ""]
        if any(over):
            out.append(f"{what} {lg.name} reaches {', '.join(o for o in over if o)}: its scores extrapolate "
                       "the fit beyond the flights it saw")
    return out


def _hover_loads(params, veh, samples, air):
    """The hover model of every rotor (T = k_T Omega^2, D = 0, Q = k_Q Omega^2), summed: its thrust
    along each rotor's axis (as the fitted model's collective thrust beside it) and, as "vertical",
    its body-z component (as the vertical-force error needs; the thrust panel drew that, an audit,
    stop 102)."""
    import numpy as np

    from ..core.hover import HoverModel

    om = samples.rotor_omega
    T = np.zeros(samples.n)
    Z = np.zeros(samples.n)
    Q = np.zeros(samples.n)
    for i, r in enumerate(veh.rotors):
        h = HoverModel.from_model(r.propeller, r.params or params, float(np.median(om[:, i])), air=air)
        T_i = h.thrust(om[:, i])
        T += T_i
        Z += T_i * r.axis[2]
        Q += np.abs(h.torque(om[:, i]))
    return {"thrust": T, "vertical": Z, "drag": np.zeros(samples.n), "torque": Q}


def _fitted_to(sets, log_path, log_name: str) -> str:
    """How the one parameter file in ``sets`` (the rotors' set labels) was fitted to the log at
    ``log_path``: "by its content" where a flight fit's ``[coverage]`` lists the log's digest among
    its training logs' (``files_sha256``, since 2026-11-30), "by its name" where a file without
    digests lists ``log_name`` among them (``groups``: the held-out ones are not there), else ""
    (the set's coverage as the coverage warnings read it, once: :func:`set_coverage`)."""
    from ..io.atomic import file_sha256
    from ..io.params_file import set_coverage

    cov = (set_coverage(next(iter(sets))) or {}) if len(sets) == 1 else {}
    if cov.get("data") != "flight logs":
        return ""
    if cov.get("files_sha256"):
        return "by its content" if file_sha256(Path(log_path)) in cov["files_sha256"] else ""
    return "by its name" if log_name in cov.get("groups", ()) and log_name not in cov.get("held_out", ()) else ""


@click.command("wrench", cls=Command)
@click.argument("log_path", metavar="LOG", type=PathArg())
@click.option("--vehicle", type=PathArg(text=True), required=True,
              help="Vehicle TOML, its rotors in the log's motor order.")
@click.option("--params", "params_spec", default=None,
              help="Parameter set (a file, e.g. from fit flight, or a named set); default: the vehicle's rotor sets, "
                   "else the vehicle file's own params, else each rotor's catalogue propeller's calibrated set, else "
                   "'generic'.")
@click.option("--out", type=PathArg(file=True), required=True, help="CSV to write.")
@click.option("--json", "as_json", is_flag=True, help="Print the error table as JSON.")
@click.option("--motor-map", "motor_map", default=None, metavar="A,B", help=MOTOR_MAP_HELP)
@with_air_options
def wrench_command(log_path, vehicle, params_spec, out, as_json, motor_map, air_choice):
    """Predicted body force and moment at every sample of a flight log.

    Writes t, Fx, Fy, Fz, Mx, My, Mz (body frame: x forward, y left, z up; N, N m) and, when
    the log measures them, Fx_measured ... Mz_measured (m a_s and I dw/dt + w x I w); prints
    the rms errors. The rotors are solved at the flight fit's 24 x 8 nodes (within 0.1% of
    the rotors' thrust of 48 x 16; docs/flight.md).
    """
    from ..io.atomic import atomic_write
    from ..identify.flight import flight_errors, reference_errors
    from ..identify.flight_scores import speed_band_errors

    if str(out) == "-":
        raise InputError("--out: '-' (standard output) is not taken here: wrench prints its error table there; give "
                         "a file (PRED.csv)")
    if Path(out).suffix.lower() != ".csv":  # (as map, export-sim and fit hold their outputs to their format)
        raise InputError(f"--out: {out}: wrench writes a CSV, named *.csv")
    check_outputs([("--out", out)], [log_path, vehicle, params_spec])
    check_outputs([("--out", out)], vehicle_inputs(vehicle))
    # (with a fit's [body] table: its airframe drag, centre of mass)
    veh, params, air, label, sets = _vehicle_sets(vehicle, params_spec, air_choice)
    body = veh.body_drag
    (log,) = _logs([log_path], _motor_map(motor_map), len(veh.rotors))
    for line in _layout_warnings([log], veh):
        warn(line)
    samples = _samples([log], veh, 1e4)  # every sample
    from ..vehicle import vehicle_wrench

    from ..identify.flight import FLIGHT_DISCRETIZATION

    # the flight fit's nodes (24 x 8): on the fastest shared log, forces within 0.008 N (0.07% of the rotors'
    # thrust) and moments within 0.0006 N m of 48 x 16 (under 3% of the model's errors, 0.29 N and 0.03 N m),
    # at a quarter of the cost
    w = _run_fit(vehicle_wrench, veh, params, samples.velocity, samples.angular_velocity, samples.rotor_omega,
                 rotor_acceleration=samples.rotor_acceleration, body_drag=body, air=air,
                 discretization=FLIGHT_DISCRETIZATION)
    cols = {"t": samples.t}
    for k, a in enumerate("xyz"):
        cols[f"F{a}"] = w.force[:, k]
    for k, a in enumerate("xyz"):
        cols[f"M{a}"] = w.moment[:, k]
    for k, a in enumerate("xyz"):
        cols[f"F{a}_measured"] = samples.force[:, k]
    if samples.moment is not None:
        for k, a in enumerate("xyz"):
            cols[f"M{a}_measured"] = samples.moment[:, k]
    with atomic_write(out, "w", newline="") as fh:
        _write_columns(fh, cols)
    err = flight_errors(w.force, samples, w.moment)
    # (how the error grows with speed, in fit flight's 3 m/s bands through the log's fastest sample: its open band
    # above 9 m/s would lump a faster flight's 9-18 m/s together)
    top = float(samples.speed.max()) if samples.n else 0.0
    bands = speed_band_errors(w.force, samples, tuple((3.0 * k, 3.0 * k + 3.0) for k in range(int(top // 3) + 1)))
    refs, masses = reference_errors(samples, veh.mass)
    rows = [(f"propmap ({label})", err)] + _reference_rows(refs, veh.mass, "log's own prediction")
    in_fit = _fitted_to(set(sets), log_path, log.name)
    if as_json:  # (printed last: its warnings are the run's, those of the log's coverage and descents among them)
        record = {"params": label, "rho": air.rho, "air": air_record(air), "errors": dict(rows), "speed_bands": bands,
                  "samples": samples.n, "left_out": log.n - samples.n, "in_fit": bool(in_fit)}
    else:
        left = log.n - samples.n
        click.echo(f"{samples.n} samples of {log.name} ({left} left out: a rotor stopped or the vehicle on the "
                   f"ground), params {label}; air {air_label(air)}")
        if in_fit:
            click.echo(f"{log.name} is one of the logs the parameter set was fitted to ({in_fit} in the set's "
                       "[coverage]): these errors are in-sample, not a prediction")
        click.echo(_table(rows))
        click.echo(f"propmap's {band_line(bands)}")
        if samples.reference_force is not None:
            click.echo(NEUROBEM_REFERENCE)
        if masses:
            click.echo(_reference_mass_note(set(masses), veh.mass))
        if "M_zero" in err:
            click.echo(f"zero-moment predictor: M {err['M_zero']:.4f} N m")
    click.echo(f"wrote {out}", err=True)
    # the log's rotor operating points beyond the data behind the parameters (a fitted file's [coverage])
    _rotor_coverage(veh, sets, [[ld] for ld in w.loads], air)
    for line in _descent_state_warning(w.loads, log.name):
        warn(line)
    if as_json:
        import json

        click.echo(json.dumps(with_warnings(record), indent=2))
