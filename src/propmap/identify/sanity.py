"""The sanity check of load data against the model (:func:`sanity_check`): the refusals of
data that cannot be this propeller's in these units, with the likely cause (a unit slip of the
thrust, torque, airspeed or rotation rate, an electrical rpm, swapped columns, a diameter far
off; a measured load that is 0 at every point; a fitted drag of the other sign), and the
warnings of risks (a tip Mach number above 0.7, low Reynolds numbers, the vortex-ring state, a
moderate mismatch, a drag of the other sign or a drag in axial flow, an airspeed in another
unit). Importable from identify/data.py too. The in-plane loads' checks (the drag's and the
rolling moment's sign and size) are identify/sanity_inplane.py's, those of loads at incidence
(wind axes, a mirrored incidence) identify/incidence_checks.py's.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.units import RPM
from ..core.airfoil import Air
from .csvfile import DataError
from .headers import G0, INCH, LBF, UNITS
from .incidence_checks import MIRROR_MISFIT, WIND_AXES_MISFIT, _mirrored_incidence, _wind_axes  # noqa: F401
from .load_data import LoadData, data_air, radians_hint
from .sanity_inplane import (DRAG_SIGN_REFUSED, DRAG_SIGN_WARNED, DRAG_SIZE_WARN,  # noqa: F401
                             _drag_checks, _rolling_moment_checks)

__all__ = ["sanity_check", "SANITY_FACTOR", "SANITY_WARN", "RE75_FLOOR", "DRAG_SIGN_REFUSED"]


#: measured over predicted (generic set, the data's geometry) beyond which load data are refused
SANITY_FACTOR = 3.0
#: a run whose chord Reynolds number at 0.75 R stays below this, below 1000 rpm, is warned of (UIUC vol. 2's lowest is
#: 3,600; a static run with its rpm in rev/s read as rpm, 60 times slow, was fitted without a word: a user-level audit)
RE75_FLOOR = 2000.0
#: beyond these factors (inside SANITY_FACTOR) a median load ratio to the model is warned of: the generic set's
#: ratios to the catalogue's own data lie beyond them for 7 of its 147 propellers (2026-11-26)
SANITY_WARN = {"thrust": 1.4, "torque": 1.5}
GF, OZF = G0 * 1e-3, LBF / 16  # [N]
#: unit slips of load data: (factor on the measured thrust, on the measured torque, cause)
_UNIT_SLIPS = [
    (G0, 1.0, "thrust in kgf read as N (name the column thrust_kgf or 'Thrust (kgf)')"),
    (GF, 1.0, "thrust in gf read as N (name the column thrust_gf or 'Thrust (gf)')"),
    (LBF, 1.0, "thrust in lbf read as N (name the column thrust_lbf)"),
    (1 / G0, 1.0, "thrust in N declared as kgf"),
    (1 / LBF, 1.0, "thrust in N declared as lbf"),
    (1e-3, 1.0, "thrust in gf declared as kgf (g as kg)"),
    (LBF, LBF * INCH, "thrust in lbf and torque in lbf in read as N and N m"),
    # (a maker's pairs of units, both unlabelled: kgf with kgf cm was told "the columns swapped", gf with gf cm "a
    # diameter far off": a thrust-stand data audit, 2026-11-30)
    (G0, G0 * 1e-2, "thrust in kgf and torque in kgf cm read as N and N m"),
    (GF, GF * 1e-2, "thrust in gf and torque in gf cm read as N and N m"),
    (G0, G0, "thrust in kgf and torque in kgf m read as N and N m"),
    (GF, 1e-3, "thrust in gf and torque in N mm read as N and N m"),
    (G0, 1e-3, "thrust in kgf and torque in N mm read as N and N m"),
    (GF, 0.01, "thrust in gf and torque in N cm read as N and N m"),
    (OZF, OZF * INCH, "thrust in ozf and torque in ozf in read as N and N m"),
    (1.0, 1e3, "torque in N m declared as N mm"),
    (1.0, 1e-3, "torque in N mm read as N m (name the column torque_Nmm)"),
    (1.0, 0.01, "torque in N cm read as N m (name the column 'torque (N cm)')"),
    (1.0, G0 * 1e-2, "torque in kgf cm read as N m (name the column torque_kgfcm)"),
    (1.0, LBF * INCH, "torque in lbf in read as N m (name the column 'torque (lbf in)')"),
    (1.0, OZF * INCH, "torque in ozf in read as N m (name the column 'torque (oz in)')"),
    (1.0, -1.0, ("a torque of the opposite sign (a CSV's reader turns it only in a run it can orient: a static "
                 "point, or positive thrust where the propeller is nearest to static; a UIUC file's CP is read as "
                 "written): negate the torque column")),
    (-1.0, 1.0, ("thrust of the opposite sign (a pusher mount, or a stand mounted the other way round; the reader "
                 "negates it only where it is negative at every static point): negate the "
                 "thrust column")),
]

#: the factors of _UNIT_SLIPS that read an unlabelled thrust column as N (kgf, gf, lbf: its first three)
_READ_AS_N = tuple(fT for fT, _, _ in _UNIT_SLIPS[:3])


#: airspeed units an unlabelled airspeed column may be in, as m/s per unit (mph and knots read as m/s fitted with
#: exit 0 and six parameters at their bounds; identification audit, 2026-11-26)
_AIRSPEED_SLIPS = tuple((UNITS["speed"][key], unit) for key, unit in (("mph", "mph"), ("knots", "knots"),
                                                                      ("kmh", "km/h"), ("fts", "ft/s")))


def _airspeed_slip(data: LoadData, at_rpm, loads_at, checked) -> str | None:
    """The unit of _AIRSPEED_SLIPS in which the moving points' measured thrust matches the model
    best, where that is less than half the misfit of m/s (rms of (model - measured) over the
    largest measured thrust, at 3 moving points or more, the model scaled to the data's static
    thrust where the data have static points) and the misfit in m/s exceeds 0.1; else None. In
    a file whose every point is at incidence 0, "descent" where the airspeed read in m/s as an
    axial descent's matches best (descent data without an incidence column were told of an
    airspeed in km/h: a wind-tunnel data audit, 2026-11-30)."""
    moving = ~data.static
    if "thrust" not in data.measured or "thrust" not in checked or moving.sum() < 3:
        return None
    measured = data.measured["thrust"][moving]
    scale = float(np.nanmax(np.abs(measured), initial=0.0))
    if not scale > 0:
        return None

    # the model at the data's static level (the measured static thrust over the model's, in the median): a propeller
    # the generic set under-predicts was told its m/s airspeed matched better in knots (a user-level audit)
    static = data.static & np.isfinite(data.measured["thrust"]) & (np.abs(at_rpm.thrust) > 0)
    level = float(np.median(data.measured["thrust"][static] / at_rpm.thrust[static])) if static.any() else 1.0
    level = level if math.isfinite(level) and level > 0 else 1.0

    def misfit(r) -> float:
        return float(np.sqrt(np.nanmean(((level * r.thrust[moving] - measured) / scale) ** 2)))

    base = misfit(at_rpm)
    descent = None
    if not np.any(data.incidence) and (base > 0.1 or _thrust_rises(data, at_rpm)):
        descent = misfit(loads_at(data.omega, data.airspeed, incidence=np.full(data.n, np.pi)))
        if base <= 0.1:  # (thrust rising with airspeed: a descent read as climb misfits by 0.07 only, stop 93)
            return "descent" if descent < 0.5 * base else None
    if not base > 0.1:
        return None
    found = {unit: misfit(loads_at(data.omega, data.airspeed * f)) for f, unit in _AIRSPEED_SLIPS}
    if descent is not None:
        found["descent"] = descent
    unit = min(found, key=found.get)
    return unit if found[unit] < 0.5 * base else None


def _thrust_rises(data: LoadData, at_rpm) -> bool:
    """Whether the measured thrust rises with the airspeed at one rotation rate (within 1%) where the
    model's, in axial climb, falls: in two thirds of such runs or more (two airspeeds 1 m/s apart
    at least, static points included). In climb a propeller's thrust falls as the airspeed grows,
    in slow axial descent it rises: descent data written without an incidence column (descent
    rates 1-6 m/s at 4000-7000 rpm, the APC 8x6E) misfit the climb by 0.07 of the largest thrust,
    below the 0.1 from which the airspeed's unit is judged, and were fitted as climb without a word
    (stop 93, 2026-12-01)."""
    T, Tm, V = at_rpm.thrust, data.measured["thrust"], data.airspeed
    order = np.argsort(data.omega)
    runs, start = [], 0
    for k in range(1, order.size + 1):
        if k == order.size or data.omega[order[k]] > 1.01 * data.omega[order[start]]:
            runs.append(order[start:k])
            start = k
    votes = []
    for run in runs:
        run = run[np.isfinite(Tm[run]) & np.isfinite(T[run])]
        if run.size < 3 or np.ptp(V[run]) < 1.0:
            continue
        measured, model = np.polyfit(V[run], Tm[run], 1)[0], np.polyfit(V[run], T[run], 1)[0]
        if model < 0:
            votes.append(measured > 0)
    return bool(votes) and 3 * sum(votes) >= 2 * len(votes)


def _other_counts(ratio: dict, data, propeller, ratios, loads_at, pole_pairs, where) -> list[str]:
    """What would bring the median thrust and torque ratios within 1.15x: one blade more or
    fewer (the model solved again), another pole-pair count (with ``pole_pairs``, the count the
    data's electrical rpm was divided by), a thrust in lbf under a kgf name or the reverse (2.2
    times, inside the refused range: a thrust-stand export audit, 2026-11-27, found it warned of
    as a blade count or diameter); e.g. ["3 blades would give 0.98/1.02x"] (thrust/torque)."""
    from dataclasses import replace

    keys = [k for k in ("thrust", "torque") if k in ratio]

    def miss(rat):
        return max(abs(math.log(max(abs(rat.get(k, 0.0)), 1e-300))) for k in keys)

    def shown(rat):
        return "/".join(f"{rat[k]:.2f}" for k in keys) + "x"

    found = []
    # (only where the thrust column was declared in the unit: a 'Thrust (N)' 2.2 times off was told of lbf under kgf)
    declared = {u: math.isclose(data.converted.get("thrust", 1.0), f) for u, f in (("kgf", G0), ("lbf", LBF))}
    for factor, why, unit in ((LBF / G0, "a thrust in lbf under a kgf name (name its unit lbf)", "kgf"),
                              (G0 / LBF, "a thrust in kgf under an lbf name (name its unit kgf)", "lbf")):
        if "thrust" in ratio and declared[unit]:
            rat = {**ratio, "thrust": ratio["thrust"] * factor}
            if miss(rat) < math.log(1.15):
                found.append(f"{why} would give {shown(rat)}")
    for b in (propeller.n_blades - 1, propeller.n_blades + 1):
        if b >= 1:
            rat = ratios(data.omega, r=loads_at(data.omega, prop=replace(propeller, n_blades=b)), where=where)
            if miss(rat) < math.log(1.15):
                found.append(f"{b} blade{'s' if b > 1 else ''} would give {shown(rat)}")
    if pole_pairs:
        alt = {pp: ratios(data.omega * pole_pairs / pp, where=where) for pp in range(1, 15) if pp != pole_pairs}
        pp = min(alt, key=lambda k: miss(alt[k]))
        if miss(alt[pp]) < math.log(1.15):
            found.append(f"--pole-pairs {pp} would give {shown(alt[pp])}")
    return found


def _moderate_mismatch(data, propeller, at_rpm, ratios, loads_at, pole_pairs, label: str) -> list[str]:
    """sanity_check's warning of a median thrust or torque ratio beyond SANITY_WARN inside the
    refused range, with :func:`_other_counts`, over the points where the model's thrust is at
    least 30% of its static thrust at the same rate (near zero thrust, a windmilling run's,
    the ratios say nothing of the blade count). A user-level audit: a 3-blade propeller fitted
    as 4 blades, or with 5 pole pairs for 7, was fitted without a word (its sections absorbed
    the error)."""
    loaded = np.abs(at_rpm.thrust) >= 0.3 * np.abs(loads_at(data.omega, np.zeros(data.n)).thrust)
    if loaded.sum() < 2:
        return []
    ratio = ratios(data.omega, r=at_rpm, where=loaded)
    off = {k: v for k, v in ratio.items() if not 1 / SANITY_WARN[k] <= v <= SANITY_WARN[k]}
    if not off:
        return []
    found = _other_counts(ratio, data, propeller, ratios, loads_at, pole_pairs, loaded)
    said = " and ".join(f"{k} is {v:.3g} times (outside {1 / SANITY_WARN[k]:.3g}-{SANITY_WARN[k]:g}x)"
                        for k, v in off.items())
    catalogue = (" (the generic set is outside these for 5% of the catalogue's propellers)"
                 if label == "the generic set" else "")
    return [f"the measured {said} what {label} predicts for {propeller.name} in the median{catalogue}: check the "
            f"blade count, the diameter ({propeller.diameter:.4g} m) and the rpm"
            + (f" ({'; '.join(found)})" if found else "")
            + ("; a fit would absorb the difference into the section parameters" if label == "the generic set"
               else ", or whether the parameters are this propeller's")]


def _plausible(rat: dict, lo: float = 1 / SANITY_FACTOR, hi: float = SANITY_FACTOR) -> bool:
    """Whether every median load ratio of ``rat`` lies in [lo, hi]."""
    return all(lo <= v <= hi for v in rat.values())


class _ModelAt:
    """The model at the data's operating points, as sanity_check compares them: the loads at
    given rates (in the data's unit, right or wrong: the tip Mach number is said apart), the
    median measured-over-model ratios of the checked thrust and torque, and whether rates
    scaled by a unit slip bring them within a unit slip's 1.6x."""

    def __init__(self, data: LoadData, propeller, params, air: Air, checked: tuple):
        self.data, self.propeller, self.params, self.air, self.checked = data, propeller, params, air, checked

    def loads_at(self, omega, airspeed=None, prop=None, incidence=None):
        """rotor_loads at the data's incidence (or ``incidence``, one per point) and collective
        (failures flagged, any tip speed)."""
        from ..core.solver import rotor_loads, supersonic_tips_allowed

        data = self.data
        with supersonic_tips_allowed():
            return rotor_loads(self.propeller if prop is None else prop, self.params, omega,
                               data.airspeed if airspeed is None else airspeed,
                               data.incidence if incidence is None else incidence, air=self.air,
                               on_failure="flag", collective=data.collective)

    def ratios(self, omega, r=None, where=True) -> dict:
        """{quantity: median measured / model} over the points where the model's load is at least
        5% of its largest ({} for rates beyond the solver's range: a scaling tried)."""
        from ..core.solver import OMEGA_MAX

        if r is None and np.max(omega) > OMEGA_MAX:
            return {}
        r = self.loads_at(omega) if r is None else r
        out = {}
        for key, model in (("thrust", r.thrust), ("torque", r.torque)):
            if key not in self.data.measured or key not in self.checked:
                continue
            finite = np.isfinite(model)
            if not finite.any():  # (no load solved at these rates: nothing to compare, and no NumPy warning)
                continue
            ok = (finite & np.isfinite(self.data.measured[key])
                  & (np.abs(model) > 0.05 * np.max(np.abs(model[finite]))) & where)
            if ok.sum() >= 2:
                out[key] = float(np.median(self.data.measured[key][ok] / model[ok]))
        return out

    def near(self, omega) -> bool:
        """Whether the loads at these rates lie within a unit slip's 1.6x of the measured ones."""
        misses = [abs(math.log(max(abs(v), 1e-300))) for v in self.ratios(omega).values()]
        return max(misses, default=math.inf) < math.log(1.6)


def _run_warnings(data: LoadData, propeller, air: Air) -> list[str]:
    """sanity_check's warnings of the rates: a tip Mach number above 0.7, and runs below
    RE75_FLOOR and 1000 rpm (rev/s read as rpm keeps CT and CP, so the load check cannot see it;
    per run, since one such run among sweeps at the right rpm was fitted too)."""
    warnings_ = []
    tip = data.tip_mach(propeller, air)
    if tip > 0.7:
        warnings_.append(f"tip Mach number up to {tip:.2f} in the data (> 0.7): compressibility beyond "
                         "Prandtl-Glauert is not modelled" + (" - or is the rpm electrical?" if tip > 1 else ""))
    re75 = propeller.reynolds_75(data.omega, air)
    slow = [g for g in dict.fromkeys(data.group) if np.max(re75[data.group == g]) < RE75_FLOOR
            and np.max(data.omega[data.group == g]) / RPM < 1000]  # (a small propeller's low ESC step is no
    # slip: rev/s read as rpm is 60 times slow, below 1000 "rpm" for any propeller up to 60,000 rpm; a review)
    if slow:
        at = np.isin(data.group, slow)
        warnings_.append(f"the chord Reynolds number at 0.75 R is {np.min(re75[at]):.3g}-{np.max(re75[at]):.3g} "
                         f"({np.min(data.omega[at]) / RPM:.4g}-{np.max(data.omega[at]) / RPM:.4g} "
                         f"rpm) in {', '.join(map(str, slow[:3]))}{' ...' if len(slow) > 3 else ''}, below "
                         f"{RE75_FLOOR:g} (the catalogue's lowest data: 3,600): is the rotation speed in rev/s (Hz) "
                         "read as rpm? Name its unit; UIUC files give rpm")
    return warnings_


def _vortex_ring_warning(data: LoadData, at_rpm) -> list[str]:
    """sanity_check's warning where 10% of the points or more lie in the vortex-ring or
    turbulent-wake state by the model (a descent audit: such data were fitted and scored
    without a word)."""
    vrs = np.isin(at_rpm.state_name, ("vortex ring", "turbulent wake")) & np.asarray(at_rpm.converged, bool)
    if vrs.sum() < max(2, 0.1 * data.n):
        return []
    groups = list(dict.fromkeys(str(g) for g in data.group[vrs]))
    # (a file without groups is one group, 'all', which --holdout refuses: 'hold them out' misled, a data audit)
    one = len(set(str(g) for g in data.group)) == 1
    where = "" if one else f" (groups {', '.join(groups[:4])}{' ...' if len(groups) > 4 else ''})"
    todo = ("leave them out of a fit (a 'group' column lets --holdout hold them out)" if one else
            "hold them out or leave them out of a fit")
    return [f"{int(vrs.sum())} of {data.n} points lie in the vortex-ring or turbulent-wake state by the "
            f"model{where}, where momentum theory is not predictive (docs/models.md): a fit's section parameters "
            f"would absorb their errors at every other point; {todo} (validate lists the errors by state)"]


def _rate_causes(data: LoadData, model: _ModelAt, n_blades: int) -> tuple[list[str], list[str]]:
    """The rotation-rate slips that bring the loads within 1.6x of the model's: (a rate in rad/s
    read as rpm, said first of all causes; the others: rpm read as rad/s, rev/s read as rpm,
    rates in thousands, an optical tachometer counting every one of the ``n_blades`` blades, an
    electrical rpm and its pole-pair counts)."""
    first, causes = [], []
    # an optical or laser tachometer that counts each blade passing (2 per revolution on a 2-blade propeller: told of
    # pole pairs and of a lbf thrust only, a thrust-stand export audit, 2026-11-30)
    if n_blades >= 2 and model.near(data.omega / n_blades):
        causes.append(f"an optical tachometer counting every blade read as the rpm ({n_blades} pulses per revolution: "
                      f"set it to {n_blades} blades, or divide the rpm column by {n_blades})")
    # a rate in rpm read as rad/s (an omega column holding rpm): 9.55 times too fast, said before the pole pairs
    if model.near(data.omega * RPM):
        causes.append("a rotation rate in rpm read as rad/s (an 'omega' column holding rpm: name it rpm)")
    # and the reverse, an rpm column holding rad/s (9.55 times slow: blamed on an airspeed in km/h, a wind-tunnel data
    # audit, 2026-11-27)
    if model.near(data.omega / RPM):
        first.append("a rotation rate in rad/s read as rpm (an rpm column holding rad/s: name it omega or "
                     "'speed (rad/s)')")
    if model.near(data.omega * 60):
        causes.append("a rotation rate in rev/s (Hz) read as rpm (name its unit, e.g. 'rotation speed (Hz)')")
    # rates in thousands: 1.975 for 1975 rpm (a thousands separator read as a decimal point, or krpm; the message
    # blamed the diameter: a fuzzing audit, 2026-11-27)
    if model.near(data.omega * 1000):
        causes.append("rotation rates in thousands read as rpm (1.975 for 1975: a thousands separator read as a "
                      "decimal point, or krpm; write the rpm in full)")
    # the electrical speed of a motor with pp pole pairs: every pp that brings the loads as close as a unit slip (the
    # model's own error spans neighbouring counts, whose thrusts differ by (8/7)^2 = 1.31: the best one alone named 8
    # for a 7-pole-pair motor, and its advice, --pole-pairs on a plain rpm column, was refused: a user-level audit)
    close = [pp for pp in range(2, 15) if model.near(data.omega / pp)]
    if close:
        counts = (f"{close[0]}" if len(close) == 1 else f"{close[0]}-{close[-1]}" if close[-1] - close[0] == len(
            close) - 1 else ", ".join(map(str, close)))
        # (read from the stand's electrical column already, only the count is missing: the advice to name the column
        # so was the name it had, a user-level audit, 2026-11-28)
        electrical = data.speed_source == "electrical"
        causes.append(f"the electrical rpm of a motor with {counts} pole pairs read as the propeller's (the loads "
                      "cannot tell neighbouring counts apart: count the motor's magnets, half of them; then "
                      + ("give that count as --pole-pairs (pole_pairs), or give the optical speed)" if electrical else
                         "name the column 'Motor Electrical Speed (RPM)' and give --pole-pairs, divide it by the "
                         "count, or give the optical speed)"))
    return first, causes


def _swapped_columns(data: LoadData, at_rpm) -> bool:
    """Whether the measured thrust and torque each lie near the other's model, to within a unit
    slip of its own (a torque in N m under 'Thrust (kgf)' reads 9.8 times large)."""
    T, Q = at_rpm.thrust, at_rpm.torque
    ok = np.isfinite(T) & np.isfinite(Q) & (np.abs(T) > 0.05 * np.nanmax(np.abs(T))) & (np.abs(Q) > 0)
    return bool(ok.sum() >= 2 and all(1 / 12 <= float(np.median(m[ok] / other[ok])) <= 12
                                      for m, other in ((data.measured["thrust"], Q), (data.measured["torque"], T))))


def _static_off(data: LoadData, at_rpm) -> bool:
    """Whether the data's static points (two or more) miss the model's thrust beyond SANITY_FACTOR
    in the median: then no airspeed's unit is the cause (a rotation rate in rev/s read as rpm was
    told 'an airspeed in km/h' first: a wind-tunnel data audit, 2026-11-30)."""
    if "thrust" not in data.measured:
        return False
    T, Tm = at_rpm.thrust, data.measured["thrust"]
    st = data.static & np.isfinite(T) & np.isfinite(Tm) & (np.abs(T) > 0)
    return st.sum() >= 2 and not _plausible({"thrust": float(np.median(Tm[st] / T[st]))})


def _refusal(data: LoadData, propeller, ratio: dict, at_rpm, model: _ModelAt, speed_slip,
             wind: bool = False, mirror: bool = False) -> DataError:
    """sanity_check's refusal of load data beyond SANITY_FACTOR of the model, with its likely cause
    (``wind``: the loads read in wind axes match the model, :func:`_wind_axes`; ``mirror``: they
    match it at 180 deg minus the incidence, :func:`_mirrored_incidence`: said first)."""
    bad = {k: v for k, v in ratio.items() if not (1 / SANITY_FACTOR <= v <= SANITY_FACTOR)}
    absent = [k for k in bad if not np.any(np.nan_to_num(data.measured[k]))]
    if absent:  # a column of zeros (a sensor the stand lacks): said before the 13 solves of the unit-slip search
        fit = [k for k in data.measured if k not in absent]
        return DataError(f"load data: {data.source}: the measured {' and '.join(absent)} is 0 at every point: not "
                         f"measured? leave it out of the fit (--quantities {','.join(fit) or 'thrust'}, or "
                         "quantities= in the API)")
    # a slip of a quantity the data lack is no cause ('torque in lbf in' of a thrust-only file), nor an unlabelled
    # thrust read as N where the header gave its unit ('Thrust (g)', converted: a thrust-stand export audit, 2026-11-30)
    declared = "thrust" in data.converted
    causes = [why for fT, fQ, why in _UNIT_SLIPS
              if not (fT != 1.0 and "thrust" not in ratio) and not (fQ != 1.0 and "torque" not in ratio)
              and not (declared and fT in _READ_AS_N)
              and _plausible({k: v * (fT if k == "thrust" else fQ) for k, v in ratio.items()}, 0.6, 1.6)]
    if any(k in data.comma_thousands and _plausible({k: v * 1e-3})
           for k, v in ratio.items()):  # ("1,100" in quotes: 1.1 or 1100?)
        causes.insert(0, "decimal commas read as thousands separators (a quoted '1,100' in a comma-separated file "
                         "is read as 1100, as the note says: write 1.100, or separate the cells with ';')")
    if speed_slip and _static_off(data, at_rpm):
        speed_slip = None  # (the static points, which no airspeed moves, are off too: _static_off)
    if speed_slip == "descent":
        causes.append("descent data read as climb (no incidence column: write incidence_deg 180 for descending "
                      "points)")
    elif speed_slip:
        causes.append(f"an airspeed in {speed_slip} read as m/s (name its unit, e.g. 'airspeed ({speed_slip})')")
    first, rates = _rate_causes(data, model, propeller.n_blades)
    if mirror:  # (a mirrored file at 15-45 deg was refused as 'an airspeed in km/h read as m/s': a review)
        first.insert(0, "an incidence read the other way round (the loads match the model at 180 deg minus the "
                        "file's incidence: a disk angle of attack alpha_d is incidence_deg = 90 + alpha_d)")
    if wind:
        first.insert(0, "loads in wind axes, not the rotor's (thrust = L sin i - D_w cos i, in-plane force = L cos i + "
                        "D_w sin i: L the lift, D_w the drag along the flow, i the incidence)")
    causes = first + causes + rates
    if not causes and bad.get("thrust", 1.0) < 1 / SANITY_FACTOR and bad.get("torque", 1.0) > SANITY_FACTOR:
        # the columns swapped (no unit slip explains the two)
        if _swapped_columns(data, at_rpm):
            causes.append("the thrust and torque columns swapped (then check their units too)")
    if not causes:
        far = max(abs(math.log(max(abs(v), 1e-300))) for v in bad.values())
        if far > math.log(1e4):  # (thrust ~ D^4: a diameter 25.4 times off is 4e5)
            small = max(bad.values(), key=lambda v: abs(math.log(max(abs(v), 1e-300)))) < 1  # (the model too large)
            causes.append(f"a diameter far off ({propeller.diameter:.4g} m: "
                          + ("one in mm given as inches?)" if small else "one in m or cm given as inches?)"))
    said = "; ".join(f"{k} {v:.3g} times" for k, v in bad.items())
    return DataError(f"load data: {data.source}: the measured {said} what the model predicts for {propeller.name} "
                     f"at the measured rpm (expected within {1 / SANITY_FACTOR:.2g}-{SANITY_FACTOR:g}x): "
                     + (f"likely {' or '.join(causes[:2])}" if causes else
                        f"check the units, the rpm and the geometry (its diameter, {propeller.diameter:.4g} m, and "
                        f"blade count, {propeller.n_blades})"))


def sanity_check(data: LoadData, propeller, *, params=None, air: Air | None = None, quantities=None,
                 pole_pairs: int | None = None) -> list[str]:
    """Refuse load data that cannot be this propeller's in these units; warn of risks.

    The measured thrust and torque are compared with the model's at the measured operating
    points (the generic set by default: hobby-propeller sections, accurate to about 10% blind,
    docs/validation.md): a median ratio beyond 1/3 to 3, or a thrust or torque of the other
    sign, is refused with the likely cause (thrust in kgf, gf or lbf read as N where the
    header gave no unit or N, none converted in ``LoadData.converted``; torque in N mm; an optical tachometer counting
    every blade; the electrical rpm of a motor with pole pairs; a reaction torque; a pusher's
    thrust in data the reader left as written; no slip of a quantity the data lack); so is a
    fitted in-plane force (drag) or rolling moment of the
    other sign than the model's at DRAG_SIGN_REFUSED of the points at incidence.

    Parameters
    ----------
    data : LoadData
    propeller : Propeller
    params : SectionParams, optional
        The model compared with (default: the generic set).
    air : Air, optional
        Default: the set's, at the density the data logged (``LoadData.air_density``) where
        they logged one.
    quantities : sequence of str, optional
        The quantities to be fitted (default: every measured one): a measured quantity left
        out of the fit (a stand's torque column of zeros) is not held to the model.
    pole_pairs : int, optional
        The pole pairs the data's electrical rpm was divided by (``--pole-pairs``): another
        count that brings the loads far closer to the model's is named.

    Returns
    -------
    list of str
        Warnings: a run below :data:`RE75_FLOOR` in chord Reynolds number at 0.75 R and below
        1000 rpm (a rotation speed in rev/s read as rpm?); 10% of the points or more in the
        vortex-ring or turbulent-wake state by the model; a thrust or torque beyond
        :data:`SANITY_WARN` (1.4x, 1.5x) times the
        model's in the median, inside the refused range (a wrong blade count, diameter or
        pole-pair count is no unit slip; the generic set is within them for 95% of the
        catalogue's propellers, docs/identification.md); a tip Mach number above 0.7 in the
        data; a measured in-plane force (drag) of the other sign than the model's at most
        points at incidence (propmap's D points along the in-plane airspeed, against the
        disk's in-plane motion: docs/conventions.md) at DRAG_SIGN_WARNED of the points or more;
        a measured drag above 5% of the thrust at most points without an in-plane airspeed (an
        incidence the file does not give); a measured rolling moment of the other sign than the
        model's at DRAG_SIGN_WARNED of the points at incidence or more, or beyond DRAG_SIZE_WARN
        times its size (a unit not given; the size of the set's rigid blades' moment where the
        set flaps, which passes little of it to the hub); a thrust and drag that match the model far better
        read in wind axes (:func:`_wind_axes`; said first among the causes where the data are
        refused); loads that match the model far better at 180 deg minus the incidence, or, in
        a 0-90 deg file, at 90 deg minus it, or in axial descent where every point is at incidence
        0 (identify/incidence_checks.py: a disk angle of attack read the other way round, an angle
        to the disk plane, descent data read as climb).

    Raises
    ------
    DataError
        The data are off by more than :data:`SANITY_FACTOR` (the message gives the factor and
        the likely cause), or a checked load beyond it is 0 at every point (not measured?), or
        a fitted drag or rolling moment has the other sign than the model's at
        :data:`DRAG_SIGN_REFUSED` of the points at incidence.
    TypeError
        ``propeller``, ``params`` or ``air`` of the wrong type (a set's name included).
    """
    from ..core.solver import check_model_args
    from ..io.calibration import generic_params

    label = "the model" if params else "the generic set"
    params = params or generic_params()
    # (params="generic" met "'str' object has no attribute 'air'", a docstring-contract audit)
    check_model_args(propeller, params, **({} if air is None else {"air": air}))
    air = data_air(data, air, params.air)[0]  # (the density the data logged, where no air is given)
    checked = tuple(data.measured) if quantities is None else tuple(quantities)
    model = _ModelAt(data, propeller, params, air, checked)
    warnings_ = _run_warnings(data, propeller, air)
    at_rpm = model.loads_at(data.omega)  # (the drag's sign and the ratios at the measured rpm)
    drag_refused, wind = _drag_checks(data, at_rpm, checked, warnings_)
    rigid = (_ModelAt(data, propeller, params.replace(flap_compliance=0.0), air, checked).loads_at(data.omega)
             if "rolling_moment" in data.measured and params.flap_compliance > 0 else None)
    drag_refused = drag_refused or _rolling_moment_checks(data, at_rpm, checked, warnings_, rigid)
    said = len(warnings_)
    _mirrored_incidence(data, at_rpm, model.loads_at, warnings_)
    mirror = len(warnings_) > said
    if not mirror:  # (the working states of a mirrored file are judged at the wrong incidence: a review)
        warnings_ += _vortex_ring_warning(data, at_rpm)
    # (incidences that look like radians, which the reader warns of, make the thrust at airspeed misfit too: the
    # airspeed's unit was blamed as a second cause, km/h, a user-level audit; so did a mirrored incidence, a review)
    speed_slip = (None if mirror or radians_hint(np.degrees(data.incidence), data.airspeed)
                  else _airspeed_slip(data, at_rpm, model.loads_at, checked))
    ratio = model.ratios(data.omega, r=at_rpm)
    if not _plausible(ratio):  # (wind-axis loads said first where they fit: the rpm's slips were named, a test;
        # decided on _wind_axes' answer, not on the warnings' text, until 2026-12-01)
        raise _refusal(data, propeller, ratio, at_rpm, model, speed_slip, wind, mirror)
    if drag_refused is not None:
        raise drag_refused
    warnings_ += _moderate_mismatch(data, propeller, at_rpm, model.ratios, model.loads_at, pole_pairs, label)
    if speed_slip == "descent":
        return warnings_ + ["the measured thrust at airspeed matches the model far better in axial descent "
                            "(incidence 180 deg) than in climb, where the file has every point (at incidence 0): are "
                            "these descent data (a descent rate as the airspeed)? write incidence_deg 180 for "
                            "descending points and 0 for climbing ones"]
    return warnings_ + ([f"the measured thrust at airspeed matches the model far better with the airspeed read as "
                         f"{speed_slip} (is the airspeed column in {speed_slip}? name its unit, e.g. "
                         f"'airspeed ({speed_slip})'; it is read in m/s)"] if speed_slip else [])
