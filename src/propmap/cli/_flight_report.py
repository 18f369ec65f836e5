"""``propmap fit flight``'s and ``propmap wrench``'s report: the scores of propmap, the
baselines and the logs' own predictions on the training samples and on each held-out log,
the error tables, and the errors by speed band (cli/flight.py runs the commands)."""

from __future__ import annotations


#: said under a table with the "log's own" rows: what those columns are, and whose
NEUROBEM_REFERENCE = ("log's own: the prediction in the log's columns, NeuroBEM's BEM + neural network (L. Bauersfeld, "
                      "E. Kaufmann, P. Foehn, S. Sun and D. Scaramuzza, \"NeuroBEM: Hybrid Aerodynamic Quadrotor "
                      "Model\", Robotics: Science and Systems 2021)")


def _reference_rows(refs: dict, mass: float, own: str) -> list:
    """Table rows of the logs' own prediction (identify.flight.reference_errors' dict), labelled
    ``own`` as logged and at the vehicle's ``mass`` [kg]."""
    labels = {"reference": f"{own} (NeuroBEM BEM+NN)", "reference_at_vehicle_mass": f"{own}, at {mass:g} kg"}
    return [(labels[k], e) for k, e in refs.items()]


def _reference_mass_note(masses, mass: float) -> str:
    """The line under a table with a "log's own, at <mass> kg" row: why that row is there."""
    made = " and ".join(f"{m:.4g}" for m in sorted(masses))
    return (f"log's own, at {mass:g} kg: the log's prediction was made for {made} kg (its force plus its residual "
            f"columns is that mass times the specific force), where the vehicle file says {mass:g} kg and the "
            f"measured force is {mass:g} kg times the specific force: this row scales its force by {mass:g} / {made}, "
            "scoring it in acceleration as propmap's; the row above scores it as logged (docs/flight.md)")


def _label_width(rows) -> int:
    """The label column's width of a table of (label, ...) rows: 44, or wider for a longer label (held-out
    log names are long), so that labels stay whole."""
    return max([44] + [len(label) + 1 for label, _ in rows])


def _table(rows: list[tuple[str, dict]]) -> str:
    """Rows of force (and moment) errors as text; a column widens for numbers longer than its 7
    characters, so that they never run together."""
    width = _label_width(rows)
    moments = any("M" in r for _, r in rows)
    forces = ("Fx", "Fy", "Fz", "F")
    keys = forces + (("Mx", "My", "Mz", "M") if moments else ())

    def cell(k, v):
        return f"{v:.3f}" if k in forces else f"{v:.4f}"

    col = {k: max([7] + [len(cell(k, r[k])) + 1 for _, r in rows if k in r]) for k in keys}
    head = f"{'':<{width}}" + "".join(f"{k:>{col[k]}}" for k in forces)
    if moments:
        head += "   " + "".join(f"{k:>{col[k]}}" for k in keys[4:])
    lines = [head + ("   [N]; [N m]" if moments else "   [N]")]
    for label, r in rows:
        line = f"{label:<{width}}" + "".join(f"{cell(k, r[k]):>{col[k]}}" for k in forces)
        if moments and "M" in r:
            line += "   " + "".join(f"{cell(k, r[k]):>{col[k]}}" for k in keys[4:])
        lines.append(line)
    return "\n".join(lines)


def _scores(samples, names, held_idx, pred, baselines, veh):
    """fit flight's errors of the model, the baselines and the logs' own references on the
    training samples and on each held-out log: (the table's rows, the report's "training" and
    "held_out" entries, the masses the logs' own predictions were made for where not the
    vehicle's)."""
    import numpy as np

    from ..identify.flight import baseline_force, flight_errors, reference_errors, speed_band_errors

    rows, reference_masses = [], set()

    def score(label, mask):
        sub = samples.select(mask)
        e = {"model": flight_errors(pred.force[mask], sub, pred.moment[mask])}
        rows.append((f"{label}: propmap", e["model"]))
        e["speed_bands_baselines"] = {}
        for k, bl in baselines.items():
            force = baseline_force(bl, sub, veh)
            e[k] = flight_errors(force, sub)
            e["speed_bands_baselines"][k] = speed_band_errors(force, sub)
            rows.append((f"{label}: {bl['label']}", e[k]))
        refs, masses = reference_errors(sub, veh.mass)
        e.update(refs)
        rows.extend((f"{label}: {name}", errs) for name, errs in _reference_rows(refs, veh.mass, "log's own"))
        reference_masses.update(masses)
        e["speed_bands"] = speed_band_errors(pred.force[mask], sub)
        return e

    report = {"training": score("training", ~np.isin(samples.log_index, held_idx)),
              "held_out": {names[k]: score(f"held out {names[k]}", samples.log_index == k) for k in held_idx}}
    return rows, report, reference_masses


def hover_torque_warning(ht: dict | None) -> str | None:
    """The warning where a flight fit's hover torque check (:func:`propmap.identify.flight.hover_torque_check`'s
    dict, or None) has a ratio outside ``HOVER_TORQUE_TARGET``; None where it is inside, or the check is absent or
    unavailable. (A ratio of 0.71 was printed beside its target with no warning: a nominal blade's fit to the
    NeuroBEM logs, a helper's run of 2026-12-02.)"""
    from ..identify.flight import HOVER_TORQUE_TARGET

    if not ht or "ratio" not in ht or HOVER_TORQUE_TARGET[0] <= ht["ratio"] <= HOVER_TORQUE_TARGET[1]:
        return None
    return (f"the fitted set's hover torque is {ht['ratio']:.2f} times the thrust-stand-calibrated generic set's at "
            f"the same thrust ({ht['torque_model']:.4f} against {ht['torque_reference']:.4f} N m), outside "
            f"{HOVER_TORQUE_TARGET[0]:g}-{HOVER_TORQUE_TARGET[1]:g}: the logs hold no torque, so the fitted section "
            "drag at hover is not a physical one (docs/flight.md)")


def _report_lines(samples, names, held, n_train: int, rows, report: dict, reference_masses, mass: float) -> list[str]:
    """fit flight's printed report: the samples and logs fitted, the error table (``rows``), the
    logs' own references, the errors by speed band (training and held out, the baselines beside),
    the hover torque against the thrust-stand-calibrated generic set, and leave-one-log-out where
    it ran."""
    import numpy as np

    from ..identify.flight import HOVER_TORQUE_TARGET

    # each log's samples' own rate (1 / their median step; a log left with one sample has none)
    rates = sorted({round(1.0 / float(np.median(np.diff(t))), 4)
                    for t in (samples.t[samples.log_index == k] for k in range(len(names))) if t.size > 1}) or [
                        samples.rate_hz]
    rate = f"{rates[0]:.4g}" if len(rates) == 1 else f"{rates[0]:.4g}-{rates[-1]:.4g}"
    text = [f"{samples.n} samples at {rate} Hz from {len(names)} log(s); fitted on "
            f"{n_train} ({', '.join(n for n in names if n not in held)})", _table(rows)]
    if samples.reference_force is not None:
        text.append(NEUROBEM_REFERENCE)
    if reference_masses:
        text.append(_reference_mass_note(reference_masses, mass))
    text.append(_band_table(report))
    ht = report["hover_torque"]
    if ht and "unavailable" in ht:
        text.append(f"hover torque at {ht['omega_hover']:.0f} rad/s, T = {ht['thrust_hover']:.3f} N: fitted "
                    f"{ht['torque_model']:.4f} N m; the check against the generic reference set is unavailable: it "
                    f"cannot make that thrust ({ht['unavailable']})")
    elif ht:
        text.append(f"hover torque at {ht['omega_hover']:.0f} rad/s, T = {ht['thrust_hover']:.3f} N: fitted "
                    f"{ht['torque_model']:.4f} N m, the thrust-stand-calibrated generic set at the same thrust "
                    f"{ht['torque_reference']:.4f} N m (ratio {ht['ratio']:.2f}; target {HOVER_TORQUE_TARGET[0]:g}-"
                    f"{HOVER_TORQUE_TARGET[1]:g})")
    if ht and "yaw_r" in ht:
        text.append(f"  yaw channel: k_Q Omega^2 = {ht['torque_yaw_channel']:.4f} N m, correlation r = "
                    f"{ht['yaw_r']:.2f}" + (" (|r| < 0.5: the regression is attenuated and says nothing)"
                                             if abs(ht["yaw_r"]) < 0.5 else ""))
    if "cross_validation" in report:
        cv = report["cross_validation"]
        text.append("leave-one-log-out (each log predicted by a fit to the others), pooled F [N]: "
                    + ", ".join(f"{k} {v:.3f}" for k, v in cv["pooled"].items()))
        text.append(_table([(f"held out {f['log']}", f["model"]) for f in cv["folds"]]))
    return text


def _band_name(band: dict) -> str:
    """A speed band's name: '0-3 m/s', '>9 m/s' for the open one."""
    lo, hi = band["band_m_s"]
    return f">{lo:g} m/s" if hi is None else f"{lo:g}-{hi:g} m/s"


def _band_cell(band: dict) -> str:
    """A speed band's F [N] and its samples in brackets ('n/a' where it has none)."""
    return ("n/a" if band["F"] is None else f"{band['F']:.3f}") + f" ({band['n']})"


def _band_table(report: dict) -> str:
    """F [N] by speed band (the samples in brackets) of propmap and each baseline, on the training
    samples and on each held-out log (issue 14's report: the errors by speed band next to the
    baselines'; the leave-one-log-out folds of --cross-validate and the logs' own predictions are
    scored in the error tables, not by band)."""
    labels = {k: b["label"] for k, b in report.get("baselines", {}).items()}
    rows = []
    for where, e in [("training", report["training"]), *((f"held out {n}", e) for n, e in report["held_out"].items())]:
        rows.append((f"{where}: propmap", e["speed_bands"]))
        rows.extend((f"{where}: {labels.get(k, k)}", b) for k, b in e.get("speed_bands_baselines", {}).items())
    width = _label_width(rows)
    cell = _band_cell
    col = [max(len(_band_name(b)), *(len(cell(r[k])) for _, r in rows)) + 2 for k, b in enumerate(rows[0][1])]
    lines = ["F [N] by speed band (samples in brackets):",
             f"{'':<{width}}" + "".join(f"{_band_name(b):>{c}}" for b, c in zip(rows[0][1], col))]
    lines += [f"{label:<{width}}" + "".join(f"{cell(b):>{c}}" for b, c in zip(r, col)) for label, r in rows]
    return "\n".join(lines)


def band_line(bands: list) -> str:
    """One line of propmap's pooled force error F [N] by speed band (the samples in brackets;
    `wrench`'s, as `fit flight`'s table gives it per log: how the error grows with speed on a
    log faster than the training ones)."""
    return "F [N] by speed band: " + ", ".join(f"{_band_name(b)} {_band_cell(b)}" for b in bands)
