"""Derive propmap's symmetric-section presets from published section data.

Fits the cambered polar (propmap.CamberedParams: lift slope, stall limit, blend sharpness,
profile drag, drag curvature and their Reynolds exponents; zero-lift angle 0 and
cl_min = -cl_max for a symmetric section) to Sheldahl & Klimas (Sandia SAND80-2114, 1981),
tables of NACA 0015 and NACA 0018 at chord Reynolds numbers 1.6e5-1e6 and of NACA 0012 at
3.6e5, angles of attack 0-20 deg (src/propmap/data/sections/sheldahl_klimas_1981.csv), by
least squares on C_L (0-20 deg) and C_D (attached flow, below the tabulated drag break),
and writes src/propmap/data/sections/presets.toml with the fit's rms errors. A section
tabulated at one Reynolds number only (NACA 0012) cannot give Reynolds exponents: it takes
those of the nearest thickness fitted from several (NACA 0015, the same report), and its
preset says so.

    .venv/bin/python tools/fit_section_presets.py

The presets and their fit: docs/models.md, Section presets for symmetric rotor blades.

The reference Reynolds number is 3.6e5 (model rotors of 0.6-0.9 m radius; a small
propeller's sections sit near 1e5, where the presets are extrapolated in Re).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.optimize import least_squares

import propmap as pm
from propmap.core.polar import drag_coefficient, lift_coefficient
from propmap.io.atomic import atomic_write

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "src/propmap/data/sections/sheldahl_klimas_1981.csv"
OUT = ROOT / "src/propmap/data/sections/presets.toml"
RE_REF = 3.6e5
CD90 = 1.80  # the report's drag at 90 deg (every Reynolds number)
SOURCE = ("Sheldahl & Klimas, Sandia SAND80-2114 (1981), NACA {name} {tables} at {span}, 0-20 deg; "
          "fitted by tools/fit_section_presets.py")
#: weight of the attached-flow drag errors against the lift errors in the stall fit
DRAG_WEIGHT = 10.0
#: largest stall-blend sharpness allowed [1/rad]: sharper blends fold C_L(alpha) so that an
#: annulus has several inflow roots in the windmill brake and the thrust of a descending rotor
#: steps by 2-3% of its hover thrust from one descent rate to the next (measured on an untwisted
#: and a -16 deg twisted 0.6 m rotor at 6-12 deg collective: M = 38 gives 785 multiple-root
#: points of 1803 and 2.9% steps, M = 25 292 and 1.4%, M = 20 none and 0.44%, the step of the
#: sweep itself); 20 is also the cambered model's default (docs/models.md)
M_MAX = 20.0
#: a stall is abrupt (leading-edge) when C_L falls below half its maximum within this many
#: degrees past it; the lift is then fitted up to and including its first point past the break (fit)
ABRUPT_DEG = 3.0
NAMES = ("cl_alpha", "cl_max", "M", "cd_min", "cd2", "re_exp", "re_exp_lift", "re_exp_stall")


def params_from(x) -> pm.CamberedParams:
    d = dict(zip(NAMES, x))
    return pm.CamberedParams(alpha_L0=0.0, cl_min=-d["cl_max"], cl_cdmin=0.0, cd90=CD90, re_ref=RE_REF,
                             tip_loss=True, compressibility=True, **d)


def fit(table: pd.DataFrame, exponents: dict | None = None):
    """Staged fit: the attached-flow constants by linear regression, then the stall.

    ``exponents`` (``re_exp``, ``re_exp_stall``): given for a table at one Reynolds number,
    whose own data cannot determine them; they are then held.

    1. ``cl_alpha``: slope of C_L over 0-4 deg at the reference Reynolds number (the
       tables give the same slope at every Re, so ``re_exp_lift`` = 0);
       ``cd_min`` and ``re_exp``: C_D at 0 deg against Re (log-log line through the
       reference); ``cd2``: (C_D - C_D(0)) against C_L^2 over 0-8 deg, all Reynolds numbers.
    2. ``cl_max``, ``M`` and ``re_exp_stall``: least squares on C_L over 0-20 deg (for an
       abrupt stall, :data:`ABRUPT_DEG`, up to and including its first point past the break)
       and on C_D in attached flow (below the
       tabulated drag break), the rest held; M at most :data:`M_MAX` (no root folds).
    """
    a = np.radians(table.alpha_deg.to_numpy())
    re = table.reynolds.to_numpy(float)
    cl, cd = table.cl.to_numpy(), table.cd.to_numpy()
    ref = np.isclose(re, RE_REF)
    lin = ref & (a <= np.radians(4.0)) & (a > 0)
    cl_alpha = float(np.sum(a[lin] * cl[lin]) / np.sum(a[lin] ** 2))
    zero = a == 0
    if exponents is None:
        re_exp, ln_cd = np.polyfit(np.log(re[zero] / RE_REF), np.log(cd[zero]), 1)
    else:
        re_exp = exponents["re_exp"]
        ln_cd = float(np.mean(np.log(cd[zero]) - re_exp * np.log(re[zero] / RE_REF)))
    cd_min = float(np.exp(ln_cd))
    low = (a > 0) & (a <= np.radians(8.0))
    cd0_at = cd_min * (re / RE_REF) ** re_exp
    cd2 = float(np.sum(cl[low] ** 2 * (cd[low] - cd0_at[low])) / np.sum(cl[low] ** 4))
    # attached drag: below the tabulated break (the first jump of cd by > 2x between rows)
    attached = np.ones(a.size, bool)
    for r in np.unique(re):
        k = np.flatnonzero(re == r)
        jump = np.flatnonzero(cd[k][1:] > 2 * cd[k][:-1])
        if jump.size:
            attached[k[jump[0] + 1:]] = False
    # lift: over 0-20 deg, but a leading-edge stall (the tabulated C_L falls below half its
    # maximum within ABRUPT_DEG past it, NACA 0012 at Re 3.6e5: 0.98 at 10 deg, 0.48 at 12 deg)
    # only up to and including the first angle past the break: no blend with M <= M_MAX follows
    # the collapse, and fitted through it the blend's lift is 12-24% low at 6-10 deg, where a
    # rotor's sections work; the first point past the break is kept because it bounds cl_max
    # (without it the stall limit runs to its bound)
    lifted = np.ones(a.size, bool)
    for r in np.unique(re):
        k = np.flatnonzero(re == r)
        top = int(np.argmax(cl[k]))
        drop = np.flatnonzero((a[k] > a[k][top]) & (a[k] <= a[k][top] + np.radians(ABRUPT_DEG))
                              & (cl[k] < 0.5 * cl[k][top]))
        if drop.size:  # drop indexes k: keep the break's first point, leave out the rest
            lifted[k[drop[0] + 1:]] = False
    fixed = dict(cl_alpha=cl_alpha, cd_min=cd_min, cd2=cd2, re_exp=float(re_exp), re_exp_lift=0.0)

    stall_exp = None if exponents is None else exponents["re_exp_stall"]

    def make(y):
        return params_from([fixed["cl_alpha"], y[0], y[1], fixed["cd_min"], fixed["cd2"], fixed["re_exp"],
                            0.0, y[2] if stall_exp is None else stall_exp])

    def residual(y):
        p = make(y)
        return np.concatenate([lift_coefficient(a[lifted], p, re[lifted]) - cl[lifted],
                               DRAG_WEIGHT * (drag_coefficient(a[attached], re[attached], p) - cd[attached])])

    y0, lo, hi, scale = [1.1, 0.5 * M_MAX, 0.15], [0.5, 5.0, -0.5], [2.5, M_MAX, 0.5], [0.1, 10.0, 0.1]
    n_free = 3 if stall_exp is None else 2
    res = least_squares(residual, y0[:n_free], bounds=(lo[:n_free], hi[:n_free]), x_scale=scale[:n_free])
    p = make(res.x)
    e_cl = lift_coefficient(a, p, re) - cl
    e_cd = drag_coefficient(a[attached], re[attached], p) - cd[attached]
    pre = a <= np.radians(8.0)
    return p, {"cl_rms": float(np.sqrt(np.mean(e_cl**2))),
               "cl_rms_0_8deg": float(np.sqrt(np.mean(e_cl[pre]**2))),
               "cd_rms_attached": float(np.sqrt(np.mean(e_cd**2))),
               "cd_rms_attached_relative": float(np.sqrt(np.mean((e_cd / cd[attached])**2))),
               "cd_rms_0_8deg_relative": float(np.sqrt(np.mean((e_cd / cd[attached])[pre[attached]]**2))),
               "points": int(a.size)}


def main() -> None:
    import tomli_w

    data = pd.read_csv(DATA, comment="#")
    out, donors = {}, {}  # donors: the fits of sections tabulated at several Reynolds numbers
    # sections with several Reynolds numbers first: a single-Re table borrows their exponents
    groups = sorted(data.groupby("section"), key=lambda g: g[1].reynolds.nunique() == 1)
    for section, table in groups:
        key = section.lower().replace(" ", "")
        single = table.reynolds.nunique() == 1
        donor = None
        if single:
            if not np.isclose(table.reynolds.iloc[0], RE_REF):
                raise ValueError(f"{section}: a single-Reynolds table must be at the reference Re {RE_REF:g}")
            if not donors:
                raise ValueError(f"{section}: no section tabulated at several Reynolds numbers to take exponents from")
            donor = min(donors, key=lambda k: abs(int(k[-2:]) - int(key[-2:])))  # nearest thickness
            exponents = {"re_exp": donors[donor].re_exp, "re_exp_stall": donors[donor].re_exp_stall}
        p, err = fit(table, exponents if single else None)
        if not single:
            donors[key] = p
        d = {k: float(getattr(p, k)) for k in NAMES}
        d.update(alpha_L0_deg=0.0, cl_min=-d["cl_max"], cl_cdmin=0.0, cd90=CD90, re_ref=RE_REF)
        res = sorted(table.reynolds.unique())
        span = f"Re {res[0]:.2g}" if single else f"Re {res[0]:.2g}-{res[-1]:.2g}"
        source = SOURCE.format(name=section.split()[-1], span=span.replace("e+0", "e"),
                               tables="table" if single else "tables")
        if single:
            donor_name = donor.upper().replace("NACA", "NACA ")
            source += (f"; its Reynolds exponents (re_exp, re_exp_stall) are the {donor_name} "
                       "fit's: one Reynolds number cannot determine them")
        out[key] = {"section_model": "cambered", **{k: round(v, 6) for k, v in d.items()},
                    "compressibility": True, "tip_loss": True, "descent": "empirical",
                    "source": source,
                    "comment": "fit errors against the tables: " + ", ".join(f"{k} {v:.4g}" for k, v in err.items())}
        print(key, {k: round(v, 4) for k, v in d.items()}, err)
    with atomic_write(OUT, "wb") as fh:
        fh.write(("# Symmetric-section presets (propmap --params section:NAME, or section = \"NAME\" in a\n"
                  "# parameter file); written by tools/fit_section_presets.py, do not edit by hand. Fitted to the\n"
                  "# tables of R. E. Sheldahl and P. C. Klimas, SAND80-2114, Sandia National Laboratories, 1981\n"
                  "# (sheldahl_klimas_1981.csv; CITATION.md).\n").encode())
        tomli_w.dump(dict(sorted(out.items())), fh)


if __name__ == "__main__":
    argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    main()
