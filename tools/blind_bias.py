"""Issue 15: what does the blind CT error (the generic set fitted without the propeller's
family) correlate with, across the catalogue's UIUC propellers (Propeller Data Site, vol. 1
and 2)? Findings, dated: docs/validation.md, "What the blind error follows".

The error is computed as ``propmap validate --all`` does it (cli/validate_all.py ->
validation.cross_validate, protocol "blind"):
  air = Air(); prop = load_propeller(name)
  data = loads_from_catalogue(catalogue()[name], prop.diameter, air=air)
  generic, label = generic_without(name)
  rotor_loads(prop, generic, data.omega, data.airspeed, data.incidence, air=air)
  error = (CT_model - CT_meas) / CT0, CT0 = mean measured static CT (validation._coefficients)
over the sweep points (J > 0; the project's blind figures), the static points, and the
lowest-J point of every sweep.

    .venv/bin/python tools/blind_bias.py OUT_DIR [--recompute]

Stage 1 (seconds with the kernel cache warm, one process) writes OUT_DIR/props.csv (one row per propeller) and
OUT_DIR/points.npz, reused unless --recompute; stage 2 prints the tables (correlations,
binned medians, per family, leave-one-family-out tests of simple thrust corrections, the
trend with rpm inside each static run, paired propellers) and writes OUT_DIR/tables.md.
"""

from __future__ import annotations

import argparse
import csv
import math
from pathlib import Path

import numpy as np
from scipy import stats



def blind_cases():
    """Yield, for every propeller ``propmap validate --all`` scores (a static run and two sweeps
    or more), in name order: (name, catalogue entry, propeller, load data, the generic set
    without its family, that set's label, the measured CT and CP, the static points' mask, the
    air). Also tools/blind_washout.py's."""
    from propmap.core.airfoil import Air
    from propmap.identify import loads_from_catalogue
    from propmap.io.calibration import generic_without
    from propmap.io.catalogue import catalogue, load_propeller
    from propmap.validation.catalogue import _coefficients

    air = Air()
    cat = catalogue()
    for name in sorted(n for n, e in cat.items() if e.static_files and len(e.sweep_files) >= 2):
        e = cat[name]
        prop = load_propeller(name)
        data = loads_from_catalogue(e, prop.diameter, air=air)
        generic, label = generic_without(name)
        CT, CP = _coefficients(data, prop, air)
        yield name, e, prop, data, generic, label, CT, CP, data.airspeed == 0, air


# ---------------------------------------------------------------- stage 1
def compute(out: Path):
    from propmap.core.solver import rotor_loads

    rows, pts = [], {}
    for i, (name, e, prop, data, generic, label, CT, CP, static, air) in enumerate(blind_cases()):
        CT0, CP0 = float(np.mean(CT[static])), float(np.mean(CP[static]))
        r = rotor_loads(prop, generic, data.omega, data.airspeed, data.incidence, air=air)
        dct = (r.CT - CT) / CT0
        dcp = (r.CP - CP) / CP0
        n = data.omega / (2 * math.pi)
        J = data.airspeed / (n * prop.diameter)
        # lowest-J point of each sweep (run id = group)
        low = np.zeros(data.n, bool)
        for g in dict.fromkeys(data.group[~static]):
            idx = np.where(data.group == g)[0]
            low[idx[np.argmin(J[idx])]] = True
        R = prop.radius
        c75 = float(np.interp(0.75 * R, prop.r, prop.chord))
        th75 = float(np.interp(0.75 * R, prop.r, prop.theta))
        om_s = float(np.mean(data.omega[static]))
        re75 = air.rho * om_s * 0.75 * R * c75 / air.mu
        # geometric pitch at 0.75R from the blade angle (helical pitch / D)
        pd_geo = math.pi * 0.75 * math.tan(th75)
        sw = ~static
        rows.append({
            "name": name, "volume": e.volume, "family": e.family, "fold": label.replace("generic without ", ""),
            "D_m": prop.diameter, "P_D": (e.pitch_in / e.diameter_in) if e.pitch_in else float("nan"),
            "P_D_geo75": pd_geo, "theta75_deg": math.degrees(th75),
            "c75_R": c75 / R, "n_blades": prop.n_blades, "sigma75": prop.n_blades * c75 / (math.pi * R),
            "rpm_static": om_s * 60 / (2 * math.pi), "rpm_mean": float(np.mean(data.omega)) * 60 / (2 * math.pi),
            "Re75": re75, "Mtip": om_s * R / air.speed_of_sound,
            "CT0": CT0, "CP0": CP0,
            "bias_static": float(np.mean(dct[static])), "bias_static_cp": float(np.mean(dcp[static])),
            "bias_lowJ": float(np.mean(dct[low])), "Jlow_mean": float(np.mean(J[low])),
            "bias_sweep": float(np.mean(dct[sw])), "rms_sweep": float(np.sqrt(np.mean(dct[sw] ** 2))),
            "bias_sweep_cp": float(np.mean(dcp[sw])), "rms_sweep_cp": float(np.sqrt(np.mean(dcp[sw] ** 2))),
            # static trend with rpm inside the static run: slope of dct vs ln(rpm)
            "static_slope_lnrpm": float(np.polyfit(np.log(data.omega[static]), dct[static], 1)[0])
            if np.ptp(data.omega[static]) > 0 else float("nan"),
        })
        pts[name] = np.vstack([J, r.CT, CT, np.full(data.n, CT0), static, low, data.omega])
        print(f"{i + 1:3d} {name:22s} {label:28s} static {100 * rows[-1]['bias_static']:+6.1f}% "
              f"sweep rms {100 * rows[-1]['rms_sweep']:5.1f}% bias {100 * rows[-1]['bias_sweep']:+6.1f}%", flush=True)
    with open(out / "props.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    np.savez(out / "points.npz", **pts)


# ---------------------------------------------------------------- stage 2
def load(out: Path):
    with open(out / "props.csv") as f:
        rows = list(csv.DictReader(f))
    cols = {k: np.array([r[k] for r in rows]) for k in rows[0]}
    for k in cols:
        if k not in ("name", "family", "fold"):
            cols[k] = cols[k].astype(float)
    return cols


def pct(x):
    return f"{100 * x:+.1f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out_dir", type=Path)
    parser.add_argument("--recompute", action="store_true")
    args = parser.parse_args()
    out_dir = args.out_dir
    out_dir.mkdir(parents=True, exist_ok=True)
    if args.recompute or not (out_dir / "props.csv").exists():
        compute(out_dir)
    c = load(out_dir)
    pts = np.load(out_dir / "points.npz")
    c["logRe75"] = np.log10(c["Re75"])
    c["D_in"] = c["D_m"] / 0.0254
    vol = c["volume"].astype(int)
    L = []  # report lines
    p = L.append

    # ---- 1. reproduction
    p("## 1. Reproduction of the project's blind figures\n")
    p("Function path: `cli/validate_all._one_propeller` -> `validation.cross_validate(..., protocols=('blind',))`, "
      "i.e. `rotor_loads(prop, generic_without(name)[0], ...)` on `loads_from_catalogue` data; error "
      "(CT_model - CT_meas)/CT0, CT0 = mean measured static CT. The project's metric is over the sweep points "
      "(J > 0) only.\n")
    p("| set | n | rms sweep CT median / p90 / worst | signed sweep CT median | signed static CT median (mean) | "
      "signed lowest-J CT median | rms sweep CP median | signed sweep CP median |")
    p("|---|---|---|---|---|---|---|---|")
    for lab, m in (("vol. 1", vol == 1), ("vol. 2", vol == 2), ("all", vol > 0)):
        rs = c["rms_sweep"][m]
        p(f"| {lab} | {m.sum()} | {100 * np.median(rs):.1f} / {100 * np.percentile(rs, 90):.1f} / "
          f"{100 * rs.max():.1f}% "
          f"| {pct(np.median(c['bias_sweep'][m]))}% | {pct(np.median(c['bias_static'][m]))}% "
          f"({pct(np.mean(c['bias_static'][m]))}%) | {pct(np.median(c['bias_lowJ'][m]))}% "
          f"| {100 * np.median(c['rms_sweep_cp'][m]):.1f}% | {pct(np.median(c['bias_sweep_cp'][m]))}% |")
    p("")

    # ---- 2. per-propeller table
    p("## 2. Per-propeller table (sorted by volume, family, Re75)\n")
    p("errors in % of static CT, signed model - measured.\n")
    p("| name | vol | fold | D [in] | P/D | P/D geo(0.75R) | c75/R | B | rpm static | rpm mean | Re75 | "
      "static | lowest-J | sweep mean | sweep rms |")
    p("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    order = np.lexsort((c["Re75"], c["fold"], vol))
    for i in order:
        p(f"| {c['name'][i]} | {vol[i]} | {c['fold'][i]} | {c['D_in'][i]:.1f} | {c['P_D'][i]:.2f} | "
          f"{c['P_D_geo75'][i]:.2f} | {c['c75_R'][i]:.3f} | {int(c['n_blades'][i])} | {c['rpm_static'][i]:.0f} | "
          f"{c['rpm_mean'][i]:.0f} | {c['Re75'][i]:.0f} | {pct(c['bias_static'][i])} | {pct(c['bias_lowJ'][i])} | "
          f"{pct(c['bias_sweep'][i])} | {100 * c['rms_sweep'][i]:.1f} |")
    p("")

    # ---- 3. correlations
    vars_ = ["logRe75", "D_in", "P_D", "P_D_geo75", "theta75_deg", "c75_R", "sigma75", "n_blades", "rpm_static",
             "rpm_mean", "Mtip", "CT0", "CP0"]
    p("## 3. Correlation of the signed blind error with each variable\n")
    for tgt, tlab in (("bias_static", "static CT"), ("bias_lowJ", "lowest-J CT"), ("bias_sweep", "sweep-mean CT")):
        p(f"### target: signed {tlab} error\n")
        p("Spearman rho (p) ; OLS slope [%-points per unit] ; R^2. Pooled / vol. 1 / vol. 2.\n")
        p("| variable | pooled rho (p) | pooled slope, R2 | vol.1 rho (p) | vol.1 slope, R2 | vol.2 rho (p) | "
          "vol.2 slope, R2 |")
        p("|---|---|---|---|---|---|---|")
        for v in vars_:
            cells = []
            for m in (vol > 0, vol == 1, vol == 2):
                x, y = c[v][m], c[tgt][m]
                ok = np.isfinite(x) & np.isfinite(y)
                x, y = x[ok], y[ok]
                if np.ptp(x) == 0:
                    cells += ["-", "-"]
                    continue
                rho, pv = stats.spearmanr(x, y)
                lr = stats.linregress(x, y)
                cells += [f"{rho:+.2f} ({pv:.2g})", f"{100 * lr.slope:+.3g}, {lr.rvalue ** 2:.2f}"]
            p(f"| {v} | " + " | ".join(cells) + " |")
        p("")

    # ---- 4. binned medians in Re75
    p("## 4. Binned medians of signed static / lowest-J / sweep error vs Re75\n")
    edges = [0, 2e4, 3e4, 4e4, 5e4, 6e4, 8e4, 1e5, 1.5e5, 1e9]
    p("| Re75 bin | vol.1 n | vol.1 static / lowJ / sweep | vol.2 n | vol.2 static / lowJ / sweep |")
    p("|---|---|---|---|---|")
    for a, b in zip(edges[:-1], edges[1:]):
        cells = []
        for vv in (1, 2):
            m = (vol == vv) & (c["Re75"] >= a) & (c["Re75"] < b)
            if m.sum():
                keys = ("bias_static", "bias_lowJ", "bias_sweep")
                cells += [str(m.sum()), " / ".join(pct(np.median(c[k][m])) for k in keys)]
            else:
                cells += ["0", "-"]
        p(f"| {a:.0f}-{b:.0f} | " + " | ".join(cells) + " |")
    p("")
    p("### Binned medians vs D and vs P/D (all propellers)\n")
    for v, ed in (("D_in", [0, 5, 7, 9, 11, 13, 30]), ("P_D", [0, 0.45, 0.6, 0.75, 0.9, 2]),
                  ("c75_R", [0, 0.1, 0.13, 0.16, 0.2, 1])):
        p(f"| {v} bin | vol.1 n | vol.1 static / sweep | vol.2 n | vol.2 static / sweep |")
        p("|---|---|---|---|---|")
        for a, b in zip(ed[:-1], ed[1:]):
            cells = []
            for vv in (1, 2):
                m = (vol == vv) & (c[v] >= a) & (c[v] < b)
                cells += [str(m.sum()), " / ".join(pct(np.median(c[k][m])) for k in ("bias_static", "bias_sweep"))
                          if m.sum() else "-"]
            p(f"| {a}-{b} | " + " | ".join(cells) + " |")
        p("")

    # ---- 5. per family
    p("## 5. Per family (fold)\n")
    p("| fold | vol | n | Re75 median (range) | D [in] range | static signed median | lowest-J median | "
      "sweep signed median | sweep rms median | within-family Spearman(Re75, static) |")
    p("|---|---|---|---|---|---|---|---|---|---|")
    fams = sorted(set(zip(vol, c["fold"])))
    for vv, f in fams:
        m = (vol == vv) & (c["fold"] == f)
        rr = "-"
        if m.sum() >= 4:
            rr = f"{stats.spearmanr(c['Re75'][m], c['bias_static'][m])[0]:+.2f}"
        re = c["Re75"][m]
        p(f"| {f} | {vv} | {m.sum()} | {np.median(re):.0f} ({re.min():.0f}-{re.max():.0f}) | "
          f"{c['D_in'][m].min():.1f}-{c['D_in'][m].max():.1f} | {pct(np.median(c['bias_static'][m]))} | "
          f"{pct(np.median(c['bias_lowJ'][m]))} | {pct(np.median(c['bias_sweep'][m]))} | "
          f"{100 * np.median(c['rms_sweep'][m]):.1f} | {rr} |")
    p("")
    # vol.2 median without each family
    p("### vol. 2 signed sweep / static median with one family removed\n")
    p("| removed | n left | sweep signed median | static signed median | sweep rms median |")
    p("|---|---|---|---|---|")
    for f in ["(none)"] + sorted(set(c["fold"][vol == 2])):
        m = (vol == 2) & (c["fold"] != f)
        p(f"| {f} | {m.sum()} | {pct(np.median(c['bias_sweep'][m]))} | {pct(np.median(c['bias_static'][m]))} | "
          f"{100 * np.median(c['rms_sweep'][m]):.1f} |")
    p("")

    # ---- 6. multivariable: does log Re explain the volume offset? family fixed effects
    p("## 6. Regressions (OLS, signed error in %-points)\n")

    def ols(y, X, names):
        X = np.column_stack([np.ones(len(y))] + X)
        beta, *_ = np.linalg.lstsq(X, y, rcond=None)
        res = y - X @ beta
        dof = len(y) - X.shape[1]
        s2 = res @ res / dof
        cov = s2 * np.linalg.pinv(X.T @ X)
        se = np.sqrt(np.diag(cov))
        r2 = 1 - res @ res / np.sum((y - y.mean()) ** 2)
        terms = (f"{n} {100 * b:+.2f}±{100 * s:.2f}" for n, b, s in zip(["const"] + names, beta, se))
        return ", ".join(terms) + f"; R2 {r2:.2f}"

    v2 = (vol == 2).astype(float)
    fold_codes = sorted(set(c["fold"]))
    FE = [(c["fold"] == f).astype(float) for f in fold_codes[1:]]
    for tgt in ("bias_static", "bias_sweep"):
        y = c[tgt]
        p(f"**{tgt}**\n")
        p(f"- vol2 dummy only: {ols(y, [v2], ['vol2'])}")
        p(f"- log10 Re75 only: {ols(y, [c['logRe75']], ['log10Re75'])}")
        p(f"- log10 Re75 + vol2: {ols(y, [c['logRe75'], v2], ['log10Re75', 'vol2'])}")
        X5 = [c["logRe75"], c["P_D_geo75"], c["c75_R"], c["n_blades"], v2]
        p(f"- log10 Re75 + P/D + c75/R + B + vol2: {ols(y, X5, ['log10Re75', 'PDgeo', 'c75R', 'B', 'vol2'])}")
        # within-family slope (family fixed effects)
        p(f"- log10 Re75 with family fixed effects (within-family slope): "
          f"{ols(y, [c['logRe75']] + FE, ['log10Re75'] + fold_codes[1:]).split(', ' + fold_codes[1])[0]}")
        for vv in (1, 2):
            m = vol == vv
            fc = sorted(set(c["fold"][m]))
            fe = [(c["fold"][m] == f).astype(float) for f in fc[1:]]
            p(f"  - vol.{vv} only, family FE: "
              f"{ols(y[m], [c['logRe75'][m]] + fe, ['log10Re75'] + fc[1:]).split(', ' + fc[1])[0]}")
        p("")

    # ---- 7. leave-one-family-out test of a Re-based thrust correction
    p("## 7. Would a Re75-based thrust correction generalise? (leave-one-family-out)\n")
    p("Correction: CT_model * (1 - (a + b log10 Re75)), a,b fitted by OLS of the per-propeller signed static "
      "error on log10 Re75 over all OTHER families (the held-out family never seen), then the held-out "
      "family's sweep points re-scored (rms and mean signed / CT0). Also: fitted on vol. 1 only, applied to vol. 2.\n")

    def rescore(name, corr):
        J, CTm, CT, CT0, st, low, om = pts[name]
        st = st.astype(bool)
        d = (CTm * (1 - corr) - CT) / CT0
        sw = ~st
        return np.sqrt(np.mean(d[sw] ** 2)), np.mean(d[sw]), np.mean(d[st])

    def lofo_pred(i, preds, mask_extra=None):
        m = c["fold"] != c["fold"][i]
        if mask_extra is not None:
            m = m & mask_extra
        X = np.column_stack([np.ones(m.sum())] + [c[v][m] for v in preds])
        beta, *_ = np.linalg.lstsq(X, c["bias_static"][m], rcond=None)
        return float(np.r_[1.0, [c[v][i] for v in preds]] @ beta)

    res = {}
    for mode in ("geo", "geo_re"):
        preds = ["sigma75", "P_D_geo75", "n_blades"] + (["logRe75"] if mode == "geo_re" else [])
        res[mode] = np.array([rescore(name, lofo_pred(i, preds)) for i, name in enumerate(c["name"])])
    for mode in ("none", "lofo_all", "vol1_only", "lofo_const"):
        out = []
        for i, name in enumerate(c["name"]):
            if mode == "none":
                corr = 0.0
            elif mode == "lofo_all":
                m = c["fold"] != c["fold"][i]
                lr = stats.linregress(c["logRe75"][m], c["bias_static"][m])
                corr = lr.intercept + lr.slope * c["logRe75"][i]
            elif mode == "lofo_const":
                m = c["fold"] != c["fold"][i]
                corr = np.mean(c["bias_static"][m])
            else:
                m = (vol == 1) & (c["fold"] != c["fold"][i])
                lr = stats.linregress(c["logRe75"][m], c["bias_static"][m])
                corr = lr.intercept + lr.slope * c["logRe75"][i]
            out.append(rescore(name, corr))
        res[mode] = np.array(out)
    p("| correction | vol.1 sweep rms median / p90 | vol.1 signed sweep median | vol.2 sweep rms median / p90 | "
      "vol.2 signed sweep median | vol.2 signed static median |")
    p("|---|---|---|---|---|---|")
    for mode, lab in (("none", "none (project blind)"), ("lofo_const", "constant offset, LOFO"),
                      ("lofo_all", "a + b log10 Re75, LOFO on both volumes"),
                      ("vol1_only", "a + b log10 Re75, fitted on vol. 1 only (LOFO)"),
                      ("geo", "a + sigma75 + P/D_geo + B, LOFO on both volumes"),
                      ("geo_re", "a + sigma75 + P/D_geo + B + log10 Re75, LOFO")):
        r = res[mode]
        cells = []
        for vv in (1, 2):
            m = vol == vv
            cells.append(f"{100 * np.median(r[m, 0]):.1f} / {100 * np.percentile(r[m, 0], 90):.1f}")
            cells.append(pct(np.median(r[m, 1])))
        cells.append(pct(np.median(r[vol == 2, 2])))
        p(f"| {lab} | " + " | ".join(cells) + " |")
    lr1 = stats.linregress(c["logRe75"][vol == 1], c["bias_static"][vol == 1])
    lra = stats.linregress(c["logRe75"], c["bias_static"])
    p(f"\nFull-data fits of static signed error: vol.1 only {100 * lr1.intercept:+.1f} "
      f"{100 * lr1.slope:+.1f}*log10Re75 (R2 {lr1.rvalue ** 2:.2f}); both volumes {100 * lra.intercept:+.1f} "
      f"{100 * lra.slope:+.1f}*log10Re75 (R2 {lra.rvalue ** 2:.2f}).\n")

    # ---- 8. Reynolds inside one propeller: the static run spans ~3x (vol. 1) to ~6x (vol. 2) in rpm
    p("## 8. Reynolds dependence inside each static run (fixed geometry)\n")
    p("Per propeller, OLS slope of ln CT on ln rpm over its static points, measured and model (generic "
      "without family), and of the signed error on ln rpm. A missing low-Re loss in the model would show as "
      "a negative error slope (over-prediction growing as rpm falls).\n")
    rows8 = []
    for i, name in enumerate(c["name"]):
        J, CTm, CT, CT0, st, low, om = pts[name]
        st = st.astype(bool)
        if np.ptp(om[st]) <= 0:
            continue
        x = np.log(om[st])
        rows8.append((vol[i], np.polyfit(x, np.log(CT[st]), 1)[0], np.polyfit(x, np.log(CTm[st]), 1)[0],
                      np.polyfit(x, (CTm[st] - CT[st]) / CT0[0], 1)[0], np.log(om[st].max() / om[st].min()),
                      np.mean(((CTm - CT) / CT0)[st][x <= np.percentile(x, 33)]),
                      np.mean(((CTm - CT) / CT0)[st][x >= np.percentile(x, 67)]),
                      c["bias_sweep"][i]))
    rows8 = np.array(rows8)
    p("| set | n | measured dlnCT/dln rpm median (IQR) | model median (IQR) | error slope median | "
      "share error slope > 0 | median ln(rpm max/min) | static error, lowest-rpm third / highest-rpm third "
      "(medians) |")
    p("|---|---|---|---|---|---|---|---|")
    for vv in (1, 2):
        r8 = rows8[rows8[:, 0] == vv]
        def q(a):
            return f"{np.median(a):+.3f} ({np.percentile(a, 25):+.3f}..{np.percentile(a, 75):+.3f})"
        p(f"| vol. {vv} | {len(r8)} | {q(r8[:, 1])} | {q(r8[:, 2])} | {np.median(r8[:, 3]):+.3f} | "
          f"{np.mean(r8[:, 3] > 0):.0%} | {np.median(r8[:, 4]):.2f} | {pct(np.median(r8[:, 5]))} / "
          f"{pct(np.median(r8[:, 6]))} |")
    # the same across the sweeps: mean signed error per sweep rpm against ln rpm, within each propeller
    sl = {1: [], 2: []}
    for i, name in enumerate(c["name"]):
        J, CTm, CT, CT0, st, low, om = pts[name]
        sw = ~st.astype(bool)
        d = (CTm - CT) / CT0
        u = np.unique(np.round(om[sw], 1))
        if len(u) >= 2:
            e = [np.mean(d[sw][np.round(om[sw], 1) == w]) for w in u]
            sl[vol[i]].append(np.polyfit(np.log(u), e, 1)[0])
    for vv in (1, 2):
        a = np.array(sl[vv])
        p(f"\nvol. {vv}: slope of per-sweep mean signed error on ln rpm (within propeller, {len(a)} propellers): "
          f"median {np.median(a):+.3f}, {np.mean(a > 0):.0%} positive")
    for vv in (1, 2):
        r8 = rows8[rows8[:, 0] == vv]
        rho, pv = stats.spearmanr(r8[:, 1], r8[:, 7])
        p(f"\nvol. {vv}: Spearman(measured static dlnCT/dln rpm, signed sweep error) = {rho:+.2f} (p {pv:.2g})")
    p("")

    # ---- 9. paired: same diameter/pitch, different section and planform (da4002 constant chord vs da4052
    # tapered, the same c/R at 0.75 R), and blade count
    p("## 9. Paired comparisons at (nearly) the same geometry and Reynolds number\n")
    p("| pair | Re75 a / b | static a / b | sweep signed a / b |")
    p("|---|---|---|---|")
    idx = {n: i for i, n in enumerate(c["name"])}
    pairs = [(f"da4002_{s}", f"da4052_{s}") for s in ("5x1.58", "5x2.65", "5x4.92", "9x2.85", "9x4.76", "9x8.95")]
    pairs += [("da4022_5x3.75", "da4022_5x3.75_3b"), ("da4022_5x3.75", "da4022_5x3.75_4b"),
              ("nr640_5_15deg", "nr640_5_15deg_3b"), ("nr640_5_15deg", "nr640_5_15deg_4b")]
    for a, b in pairs:
        if a in idx and b in idx:
            i, j = idx[a], idx[b]
            p(f"| {a} vs {b} | {c['Re75'][i]:.0f} / {c['Re75'][j]:.0f} | {pct(c['bias_static'][i])} / "
              f"{pct(c['bias_static'][j])} | {pct(c['bias_sweep'][i])} / {pct(c['bias_sweep'][j])} |")
    p("")

    (out_dir / "tables.md").write_text("\n".join(L) + "\n")
    print("\n".join(L))


if __name__ == "__main__":
    main()
