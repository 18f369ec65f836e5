"""``propmap fit loads``' comparisons of the fitted set with its base set: the held-out runs' or
groups' rmse and the quantities a ``--quantities`` subset leaves unfitted, each warned of where
the fitted set predicts them 25% or more worse (docs/identification.md, A report that tells the
truth; docs/cli.md, Warnings)."""

from __future__ import annotations

from ._common import warn

__all__ = ["held_out_worse"]


def held_out_worse(fitted: dict, base: dict, largest: dict, quantities) -> list[str]:
    """The ``quantities`` whose rmse exceeds the base set's by 25% and by more than 2% of the
    quantity's largest measured magnitude: what ``fit loads`` warns of (not noise: below either
    margin it is not said), for the fitted quantities on the held-out groups (``--holdout``) and
    for the measured quantities a ``--quantities`` subset leaves unfitted, on every point.

    Parameters
    ----------
    fitted, base : dict
        ``{q + "_rmse": rmse}`` of the fitted and the base set on the points judged [N, N m; or
        CT, CP] (None: no such point measures it, never said).
    largest : dict
        ``{q: largest measured |value|}``, in the rmse's units.
    quantities : iterable of str
        The quantities judged (``thrust``, ``drag``, ``torque``, ``rolling_moment``).

    Returns
    -------
    list of str
        Those quantities, in order.
    """
    pairs = {q: (fitted.get(q + "_rmse"), base.get(q + "_rmse")) for q in quantities}
    return [q for q, (f, b) in pairs.items()
            if f is not None and b is not None and f > 1.25 * b and f - b > 0.02 * largest[q]]


def _warn_held_out(held, base_label: str, said: str, what: str) -> None:
    """The warning of held-out ``what`` (runs, groups) that the fitted set predicts 25% or more worse
    than the base set (:func:`held_out_worse`; ``said``: their rmse, fitted against base)."""
    warn(f"the fitted set predicts the held-out {', '.join(held)} 25% or more worse than {base_label} does ({said}): "
         f"what it learned from the fitted {what} does not carry to these")


#: the units of each load quantity's rmse in fit loads' lines
_LOAD_UNITS = {"thrust": "N", "drag": "N", "torque": "N m", "rolling_moment": "N m"}


def _unfitted_worse(res, fitted: dict, base: dict, largest: dict, measured, base_label: str, units: dict) -> str:
    """Where ``--quantities`` left measured quantities unfitted: their rmse over every point, fitted
    and base set, in ``res.extra["unfitted"]`` and in the line returned for the report ("" where
    every measured quantity was fitted, or no point judges those left: None), and a warning for
    those the fitted set predicts 25% or more worse than the base set (:func:`held_out_worse`'s
    margins). A set fitted to the rolling moment alone predicted apce_10x7's tunnel thrust at
    0.90 N rms against the generic set's 0.34 N (2026-12-01), and the catalogue's apce_10x7
    fitted to its thrust alone its CP at 0.0084 rms, both without a word."""
    from ..identify.load_data import INPLANE_KEYS

    chosen = res.extra.get("quantities", list(measured))
    # (a quantity no point judges, the in-plane force measured in axial flow only, is not the subset's: the fit
    # leaves it out and its note says why; it was listed with no rmse, 'drag -', without --quantities too, until
    # 2026-12-01, a review)
    unfitted = [k for k in measured if k not in chosen and fitted[f"{k}_rmse"] is not None]
    if not unfitted:
        return ""
    res.extra["unfitted"] = {"quantities": unfitted, **{name: {f"{k}_rmse": rms[f"{k}_rmse"] for k in unfitted}
                                                        for name, rms in (("fitted", fitted), (base_label, base))}}
    def where(which) -> str:
        """Where the in-plane loads are judged, said where ``which`` names one."""
        return "the in-plane loads where the rotor has an in-plane airspeed" if set(which) & set(INPLANE_KEYS) else ""

    worse = held_out_worse(fitted, base, largest, unfitted)
    if worse:
        said = "; ".join(f"{k} rmse {fitted[k + '_rmse']:.4g} against {base[k + '_rmse']:.4g}{units[k]}"
                         for k in worse)
        warn(f"the fitted set predicts the unfitted {', '.join(worse)} 25% or more worse than {base_label} does over "
             f"every point that measures them ({'; '.join(filter(None, (said, where(worse))))}): fitted to "
             f"{', '.join(chosen)} alone, it does not carry to them; fit them too (--quantities) or use the set for "
             "those quantities only")
    head = "not fitted, rmse over every point" + (f" ({where(unfitted)})" if where(unfitted) else "")
    return head + ": " + "; ".join(f"{name}: " + ", ".join(f"{k} {rms[f'{k}_rmse']:.4g}{units[k]}" for k in unfitted)
                                   for name, rms in (("fitted", fitted), (base_label, base)))


def _catalogue_comparison(res, entry, prop, base, base_label: str, held, air, label: str):
    """fit loads of a catalogue propeller: (the held-out runs' CT and CP rmse line, fitted
    against the base set and the hover model, and the unfitted quantity's (:func:`_unfitted_worse`),
    or ""; the figure's writer, the fit against the catalogue's runs), the comparison stored in
    ``res.extra["holdout"]`` (the base set keyed by its label, as a file's), and a warning where the
    fitted set predicts the held-out runs 25% or more worse than the base set
    (:func:`held_out_worse`)."""
    import numpy as np

    from ..plots import plot_load_fit
    from ..validation import holdout_comparison, validate

    extra = ""
    if held:
        cmp = holdout_comparison(entry, prop, res.params, base, held, air=air)
        vf, vb = cmp["validation_fitted"], cmp["validation_baseline"]
    else:
        vf, vb = validate(entry, prop, res.params, air=air), validate(entry, prop, base, air=air)
    largest = {"thrust": max(float(np.max(np.abs(r.CT))) for r in vf.runs),
               "torque": max(float(np.max(np.abs(r.CP))) for r in vf.runs)}
    if held:
        # (the base set keyed by its label, as a file's and the unfitted quantities' are; "baseline" until 2026-12-01)
        res.extra["holdout"] = {"holdout": cmp["holdout"], "fitted": cmp["fitted"], base_label: cmp["baseline"],
                                "hover_model": cmp["hover_model"]}
        fit, blind = cmp["fitted"], cmp["baseline"]
        extra = f"held-out ({', '.join(held)}) " + "; ".join(
            f"{c.upper()} rmse: fitted {fit[c + '_rmse']:.4f}, {base_label} {blind[c + '_rmse']:.4f}, hover model "
            f"{cmp['hover_model'][c + '_rmse']:.4f}" for c in ("ct", "cp")) + " (coefficients [-], absolute)"
        # (said as a file's are: apce_8x6 fitted to its static run predicted its sweeps' CT at 0.0140 rmse against
        # 0.0109 (generic), apcsp_10x10's CP at 0.0075 against 0.0043, without a word until 2026-12-01)
        coefficient = {"thrust": "ct", "torque": "cp"}
        worse = held_out_worse(*({f"{q}_rmse": s[f"{c}_rmse"] for q, c in coefficient.items()} for s in (fit, blind)),
                               largest, res.extra.get("quantities", list(coefficient)))
        if worse:
            said = "; ".join(f"{coefficient[q].upper()} rmse {fit[coefficient[q] + '_rmse']:.4f} against "
                             f"{blind[coefficient[q] + '_rmse']:.4f}" for q in worse)
            _warn_held_out(held, base_label, said, "runs")
    rmse = [{"thrust_rmse": s["ct_rmse"], "torque_rmse": s["cp_rmse"]} for s in (vf.summary("model"),
                                                                               vb.summary("model"))]
    unfitted = _unfitted_worse(res, *rmse, largest, ("thrust", "torque"), base_label,
                               {"thrust": " (CT)", "torque": " (CP)"})
    extra = "\n".join(line for line in (extra, unfitted) if line)

    def figure(png):
        plot_load_fit(vf.runs, vb.runs, set(held), png, baseline_label=base_label,
                      title=f"{label}: load fit vs measured\nData: {entry.citation}")
    return extra, figure


def _file_comparison(res, data, prop, base, base_label: str, held, air, label: str):
    """fit loads of a file's data: (the held-out groups' rmse line and the unfitted quantities' (a
    ``--quantities`` subset: :func:`_unfitted_worse`), fitted and base set, or ""; the parity figure's
    writer), the rmse stored in ``res.extra["holdout"]``, a warning where the fitted set predicts the
    held-out groups 25% or more worse than the base set; points where either set's solve failed are
    left out of both rmse, with a warning."""
    import numpy as np

    from ..core.solver import rotor_loads
    from ..identify.load_data import INPLANE_KEYS
    from ..plots import plot_load_parity

    extra = ""
    model = {}
    for name, p in (("fitted", res.params), (base_label, base)):
        r = rotor_loads(prop, p, data.omega, data.airspeed, data.incidence, air=air, on_failure="flag",
                        collective=data.collective)
        model[name] = {"thrust": r.thrust, "drag": r.drag, "torque": r.torque, "rolling_moment": r.rolling_moment}
    held_mask = np.isin(data.group, held)
    # (the in-plane loads where the rotor has an in-plane airspeed, as the fit and validate take them: the in-plane
    # force's axial rows' zero errors were counted until 2026-12-01, a fit-statistics audit)
    judged = {k: np.isfinite(data.measured[k]) & (data.inplane if k in INPLANE_KEYS else True) for k in data.measured}
    # (a point where either set's solve failed, flagged NaN, is left out of both sets' rmse, and said: it made the
    # rmse NaN and skipped the warnings without a word until 2026-12-01, a review)
    solved = {k: np.isfinite(model["fitted"][k]) & np.isfinite(model[base_label][k]) for k in data.measured}
    failed = sorted({int(i) for k in data.measured for i in np.flatnonzero(judged[k] & ~solved[k])})
    if failed:
        warn(f"the model's solve failed at {len(failed)} point(s) of the data (the first: row {failed[0] + 1} of the "
             "points read), flagged: left out of the fitted and the base set's rmse")
    judged = {k: judged[k] & solved[k] for k in data.measured}

    def rmse(where) -> dict:
        """Each set's rmse of each measured quantity over the points ``where`` (None: no such point)."""
        return {name: {f"{k}_rmse": (float(np.sqrt(np.mean((m[k] - data.measured[k])[where & judged[k]] ** 2)))
                                     if (where & judged[k]).any() else None) for k in data.measured}
                for name, m in model.items()}

    top = {k: float(np.nanmax(np.abs(data.measured[k]), initial=0.0)) for k in data.measured}
    every = rmse(np.ones(data.n, bool))
    unfitted = _unfitted_worse(res, every["fitted"], every[base_label], top, data.measured, base_label,
                               {k: " " + u for k, u in _LOAD_UNITS.items()})
    if held:
        res.extra["holdout"] = {"holdout": list(held), **rmse(held_mask)}
        extra = f"held-out ({', '.join(held)}) rmse: " + "; ".join(
            f"{name}: " + ", ".join(f"{k} " + ("- (no held-out point)" if v is None else
                                                 f"{v:.4g} {_LOAD_UNITS[k.removesuffix('_rmse')]}")
                                    for k, v in res.extra["holdout"][name].items())
            for name in model)
        fitted, blind = res.extra["holdout"]["fitted"], res.extra["holdout"][base_label]
        worse = held_out_worse(fitted, blind, top, res.extra.get("quantities", list(data.measured)))
        if worse:  # (said: a fit that predicts its held-out groups worse than its unfitted base learned the others)
            said = "; ".join(f"{k} rmse {fitted[k + '_rmse']:.4g} against {blind[k + '_rmse']:.4g}" for k in worse)
            _warn_held_out(held, base_label, said, "groups")
    extra = "\n".join(line for line in (extra, unfitted) if line)

    def figure(png):
        plot_load_parity(data, model, held_mask, png, title=f"load fit of {label} ({prop.name})")
    return extra, figure
