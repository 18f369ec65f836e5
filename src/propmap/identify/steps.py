"""A thrust stand's "steps" test as one averaged point per ESC step.

A thrust stand's software (RCbenchmark / Tyto Robotics; :mod:`propmap.identify.stand` maps
its columns) logs every sample of a test that holds the ESC signal at a sequence of levels.
:func:`stand_points` splits the rows into steps (one signal level and one operating
condition each), drops each step's settling and unsteady rows and the ramps between steps
and at a test's ends (up from idle, back to it), and averages the rest; :func:`esc_form`
reads whether the signal is a pulse width [us] or a throttle in percent or as a fraction.
"""

from __future__ import annotations

import math

import numpy as np

from .headers import _ESC_UNITS, _token

__all__ = ["esc_form", "stand_points", "condition_tolerances", "ESC_TOL", "CONDITION_TOL", "NOISE_K", "NOISY_ROWS"]

#: a new step starts where the ESC signal moves more than this from the step's first row [us]
#: (a measured pulse width jitters by about 1 us), or an operating condition moves more than
#: its tolerance (a tunnel run at one throttle and several airspeeds)
ESC_TOL_US = 2.0
#: the same tolerance for each form of the signal: a pulse width [us] (1000-2000 us), a
#: throttle in percent or as a fraction (2 us of the 1000 us span: 0.2% or 0.002)
ESC_TOL = {"us": ESC_TOL_US, "pct": 0.2, "fraction": 0.002}
CONDITION_TOL = {"airspeed": 0.3, "incidence_deg": 0.5, "collective_deg": 0.25}
#: a sampled log's noisy condition column (a tunnel's pitot: about 0.2 m/s rms at a few m/s,
#: where its dynamic pressure is a few pascals) splits steps only where the mean of NOISY_ROWS
#: rows moves more than this many times its rms noise over sqrt(NOISY_ROWS) from the step's mean
#: (_noisy_starts): on pure noise 6.6e-4 starts per row, 96% of them in a step's first 8 rows,
#: whose mean is itself noisy, and which _merge_steps joins back (measured 2026-12-01: 2,000 runs
#: of 200 rows, 0.2 rms, tolerance 1.0)
NOISE_K = 5.0
#: rows whose mean tells a noisy column's new level from its noise (_noisy_starts)
NOISY_ROWS = 8
#: a sampled log: its ESC signal holds a level for at least this many rows (the hold of its
#: median row, so that the one-row steps of a ramp between holds do not count)
_SAMPLED_HOLD = 10
#: noise is what moves a column by at most this share of its range or of its typical value
#: (larger sample-to-sample changes are the levels of a table, not noise)
_NOISE_SHARE = 0.1


def esc_form(name: str, unit: str | None, esc: np.ndarray) -> tuple[str, str | None]:
    """The form of an ESC-signal or throttle column: ("us" | "pct" | "fraction", note or None).

    By its unit where it gives one (us, µs, microseconds; %, pct, percent), unless the values
    contradict it (a note says so): a percentage whose values reach 500 is a pulse width, one
    whose values stay within (0, 1] a fraction, and a pulse width whose values stay within
    (0, 100] a throttle (by the rule below; an ESC's pulse is 1000-2000 us). Else by its values: at most 1 a fraction,
    at most 100 a percentage, else a pulse width in us (the note says which was taken, and names
    a unit it does not know, e.g. ``(PWM)`` or ``[0-1]``).

    Parameters
    ----------
    name : str
        The column's header as written (for the note).
    unit : str or None
        The unit its header gives (:func:`propmap.identify.stand.split_header`), or None.
    esc : ndarray
        The column's values (NaN ignored).

    Returns
    -------
    (str, str or None)
        The form, ``"us"``, ``"pct"`` or ``"fraction"``, and a note for the user where the
        form was read from the values or contradicts the unit, else None.
    """
    tok = None if unit is None else _token(unit)
    top = float(np.nanmax(np.abs(esc))) if esc.size and not np.all(np.isnan(esc)) else 0.0
    if tok in _ESC_UNITS:
        if _ESC_UNITS[tok] == "pct" and top >= 500.0:  # (a pulse width under a '%' header: a user-level audit)
            return "us", (f"{name!r}: read as a pulse width in us, not percent: its values reach {top:g} (a "
                          "percentage stays near 0-100)")
        if _ESC_UNITS[tok] == "pct" and 0 < top <= 1.0:  # (0.15-0.90 under '%': a thrust-stand export audit)
            return "fraction", (f"{name!r}: read as a throttle fraction (0-1), not percent: its values reach only "
                                f"{top:g}")
        if _ESC_UNITS[tok] == "us" and 0 < top <= 100.0:  # (no ESC takes a pulse of 100 us: a throttle under 'us')
            form = "fraction" if top <= 1.0 else "pct"
            return form, (f"{name!r}: read as a throttle {'fraction (0-1)' if form == 'fraction' else 'in percent'}, "
                          f"not a pulse width in us: its values reach only {top:g} (an ESC's pulse is 1000-2000 us)")
        return _ESC_UNITS[tok], None
    form = "fraction" if top <= 1.0 else ("pct" if top <= 100.0 else "us")
    what = {"fraction": "a throttle fraction (0-1)", "pct": "a throttle in percent", "us": "a pulse width in us"}[form]
    unknown = "" if unit is None else f"unit {unit!r} not known for an ESC signal (us or %): "
    return form, (f"{name!r}: {unknown}read as {what} by its values (they reach {top:g}; write us or % in its name "
                  "to say otherwise)")


def _widened(q: str, cond_tol: dict) -> bool:
    """Whether quantity ``q``'s tolerance was widened for its noise (:func:`condition_tolerances`)."""
    return cond_tol[q] > CONDITION_TOL[q]


def condition_tolerances(conditions: dict, esc: np.ndarray, labels=None,
                         tol: float = ESC_TOL_US) -> tuple[dict, dict]:
    """Each operating condition's step tolerance in a stand log, widened where the column is noisy.

    CONDITION_TOL, or ``NOISE_K`` times the column's rms noise where that is larger: a tunnel's
    pitot read at 0.2 m/s rms noise split 12 steps of a log into 62 points with the fixed
    0.3 m/s (a data audit, 2026-11-30; 14 at 0.1 m/s rms). The noise is estimated from the
    second differences of the rows within each ESC level (a hold of one signal and label, the
    pieces of a readback jittering by +-2 us joined: such jitter hid a noisy pitot, a mutation
    audit, 2026-12-01), and only in a sampled log (half its rows in holds of 10 rows or more; an
    export of averaged steps has one row per step), where the column changes at half its rows or
    more and turns back at half of its changes or more (noise: 2 in 3; a table's levels stay put
    or run one way) and where the noise is at most a tenth of the column's range or of its median
    size. :func:`_noisy_starts` then judges a new level on the mean of NOISY_ROWS rows.

    Parameters
    ----------
    conditions : dict
        quantity (a key of CONDITION_TOL) -> ndarray, shape (N,), rows in file order.
    esc : ndarray, shape (N,)
        The ESC signal.
    labels : sequence of str, shape (N,), optional
        A run label per row.
    tol : float
        The ESC signal's tolerance (ESC_TOL of its form).

    Returns
    -------
    (dict, dict)
        quantity -> tolerance (in the column's unit), and quantity -> rms noise for the
        columns whose tolerance was widened (empty where none was).
    """
    holds = _step_starts(esc, {}, labels, tol)  # the ESC signal's levels alone, a jittering readback's pieces joined
    bounds = _merge_steps(list(zip(holds, [*holds[1:], esc.size])), esc, {}, labels, tol, {})
    sizes = [b - a for a, b in bounds]
    out, noisy = dict(CONDITION_TOL), {}
    if not sizes or float(np.median(np.repeat(sizes, sizes))) < _SAMPLED_HOLD:  # (the hold of the median row)
        return {q: out[q] for q in conditions}, noisy
    for q, a in conditions.items():
        a = np.asarray(a, float)
        # within each hold, of finite nonzero rows (a pitot clipped at 0 at rest is not noise)
        rows = [x[np.isfinite(x) & (x != 0)] for x in (a[i:j] for i, j in bounds)]
        d1 = [np.diff(x) for x in rows if x.size >= 3]
        if not d1 or sum(d.size for d in d1) < 10:
            continue
        moves = np.concatenate([d[d != 0] for d in d1])
        turns = np.concatenate([np.sign(d[d != 0])[1:] != np.sign(d[d != 0])[:-1] for d in d1])
        # noise moves nearly every row and turns back 2 times in 3; a table's levels stay put or run one way
        if moves.size < 0.5 * sum(d.size for d in d1) or not turns.size or turns.mean() < 0.5:
            continue
        d2 = np.concatenate([np.diff(x, 2) for x in rows if x.size >= 3])
        sigma = float(1.4826 * np.median(np.abs(d2)) / np.sqrt(6.0))
        scale = max(float(np.nanmax(a) - np.nanmin(a)), float(np.median(np.abs(np.concatenate(rows)))))
        if NOISE_K * sigma > CONDITION_TOL[q] and sigma <= _NOISE_SHARE * scale:
            out[q], noisy[q] = NOISE_K * sigma, sigma
    return {q: out[q] for q in conditions}, noisy


def _step_starts(esc: np.ndarray, conditions: dict, labels, tol: float = ESC_TOL_US,
                 cond_tol: dict | None = None) -> np.ndarray:
    """Row index where each step starts (ESC signal within ``tol`` of the step's first row, the
    conditions within ``cond_tol`` (default CONDITION_TOL) of the step's first row, one label;
    then, inside each such step, a column whose tolerance was widened for its noise within it of
    the mean of the step's rows so far: :func:`_noisy_starts`); :func:`_merge_steps` joins the
    pieces of a jittering one."""
    cond_tol = cond_tol or CONDITION_TOL
    noisy = {q for q in conditions if _widened(q, cond_tol)}
    starts = [0]
    ref = 0
    cond = [(np.asarray(a, float), cond_tol[q]) for q, a in conditions.items() if q not in noisy]
    for i in range(1, esc.size):
        if (abs(esc[i] - esc[ref]) > tol or any(abs(a[i] - a[ref]) > c_tol for a, c_tol in cond)
                or (labels is not None and labels[i] != labels[ref])):
            starts.append(i)
            ref = i
    if not noisy:
        return np.array(starts)
    columns = [(np.asarray(conditions[q], float), cond_tol[q], CONDITION_TOL[q]) for q in noisy]
    return np.array([k for a, b in zip(starts, [*starts[1:], esc.size]) for k in _noisy_starts(columns, a, b)])


def _noisy_starts(columns: list, first: int, stop: int) -> list:
    """Step starts in rows [first, stop) by noisy columns ((values, widened tolerance, fixed
    tolerance) triples): a row starts a step where the mean of it and the next rows (NOISY_ROWS
    in all, fewer at the end) lies further from the mean of the step's rows before it than the
    widened tolerance over the root of their count (at least the fixed one), and the row itself
    lies nearer that new mean than the step's. A level held over 8 rows is so told from noise at
    5 sigma / sqrt 8 (a tunnel sweep at one throttle in 1 m/s levels with 0.25 m/s rms of noise
    was read as 5 points, 0.5 m/s levels as 2, while each row was judged alone: a review,
    2026-12-01), and a step starts at the row where the level changes. Searched in windows of
    rows that grow fourfold, in whole-array operations."""
    starts, ref, width = [first], first, 16
    while ref < stop - 1:
        end = min(stop, ref + 1 + width)  # candidates ref+1 .. end-1
        hi = min(stop, end + NOISY_ROWS - 1)
        start = np.zeros(end - ref - 1, bool)
        for a, c_tol, fixed in columns:
            seg = a[ref:hi]
            finite = np.isfinite(seg)
            x = np.where(finite, seg, 0.0)
            s1, n1 = np.concatenate([[0.0], np.cumsum(x)]), np.concatenate([[0], np.cumsum(finite)])
            k = np.arange(1, end - ref)  # candidate rows, relative to ref
            top = np.minimum(k + NOISY_ROWS, seg.size)
            with np.errstate(invalid="ignore", divide="ignore"):
                before = s1[k] / n1[k]
                count = n1[top] - n1[k]
                after = (s1[top] - s1[k]) / count
                shift = np.abs(after - before) > np.maximum(fixed, c_tol / np.sqrt(np.maximum(count, 1)))
                nearer = np.abs(seg[k] - after) < np.abs(seg[k] - before)  # (NaN compares False: no start)
            start |= shift & nearer
        hit = np.flatnonzero(start)
        if hit.size:
            ref += 1 + int(hit[0])
            starts.append(ref)
            width = 16
        elif end == stop:
            break
        else:
            width *= 4
    return starts


def _merge_steps(steps: list, esc: np.ndarray, conditions: dict, labels, tol: float, cond_tol: dict) -> list:
    """Neighbouring steps (row ranges [a, b)) joined where their medians agree within ``2 tol``
    (the ESC signal: two pieces of one step whose readback jitters by +-tol) and within
    ``cond_tol`` (the operating conditions) and their label is one: a +-2 us jitter split 16
    steps into 104 (a thrust-stand export audit, 2026-11-27; 16 again since). So signal levels
    closer than 2 tol (4 us, 0.4%, 0.004) are one step. For a column whose tolerance was widened
    for its noise the medians' own noise counts: within the widened tolerance times
    sqrt(1/n_a + 1/n_b) for pieces of n_a and n_b rows (at least the fixed one), so that a row of
    noise joins its step and two held levels 1 m/s apart stay two."""
    merged = [steps[0]] if steps else []

    def within(q, x, a, b, pa, pb):
        t = cond_tol[q]
        if _widened(q, cond_tol):
            t = max(CONDITION_TOL[q], t * float(np.sqrt(1.0 / (b - a) + 1.0 / (pb - pa))))
        return abs(np.median(x[a:b]) - np.median(x[pa:pb])) <= t

    for a, b in steps[1:]:
        pa, pb = merged[-1]
        if ((labels is None or labels[a] == labels[pa]) and abs(np.median(esc[a:b]) - np.median(esc[pa:pb])) <= 2 * tol
                and all(within(q, x, a, b, pa, pb) for q, x in conditions.items())):
            merged[-1] = (pa, b)
        else:
            merged.append((a, b))
    return merged


def _one_condition(x: np.ndarray, steps: list, q: str, cond_tol: dict) -> bool:
    """Whether the rows of ``steps`` (a ramp and the steps around it) are at one condition: their
    values of quantity ``q`` within its tolerance of each other, or, for a column whose tolerance
    was widened for its noise, each step's median within it of the first's."""
    tol = cond_tol[q]
    if not _widened(q, cond_tol):
        return bool(np.ptp(x[steps[0][0]:steps[-1][1]]) <= tol)
    first = np.median(x[steps[0][0]:steps[0][1]])
    return all(abs(np.median(x[a:b]) - first) <= tol for a, b in steps[1:])


def _ramps(steps: list, esc: np.ndarray, conditions: dict, labels, cond_tol: dict, time=None) -> set:
    """The indexes of the steps that are the signal ramping from one step to the next: a run of
    steps of one or two rows between two steps of five rows or more, at their operating
    condition and label, whose signals lie between the two's (each ramp row was a "step" of its
    own, taken with the motor still accelerating: 76 points from 16 steps in a thrust-stand
    export audit, 2026-11-27). Short steps anywhere else (an export that averaged its steps, a
    tunnel run's short airspeed steps after a long static one) stay points.

    So are the ramps at a test's ends in a sampled log: two or more such steps that begin a test
    and whose signals rise to the next step, held for _SAMPLED_HOLD rows or more (the ramp up
    from idle), or that end a test and fall from the step before, held as long (the ramp back to
    idle), at that step's operating condition and label, every signal below that step's and
    monotone (a readback's jitter within 2 tolerances is merged into the steps before: adjacent
    steps differ by more, :func:`_merge_steps`); both were points, 28 of 35 points in a
    thrust-stand export audit's log of 7 steps (2026-12-02). A test begins and ends at the rows'
    ends, where the label changes, and where the time jumps by more than 3 rows' median
    interval (the stopped motor's rows skipped before). Short steps
    rising after the last long step (a warm-up hold, then a table of short steps) and short
    steps beside steps held for fewer rows (a log at a few hertz, a table: a review found a
    2 Hz log's first ten steps dropped by a first version) stay points; so do the steps of a
    ramp slower than one tolerance a row (steps of three rows or more)."""
    size = [b - a for a, b in steps]
    level = [float(np.median(esc[a:b])) for a, b in steps]

    def same(first: int, last: int) -> bool:  # steps[first..last] at one label and operating condition
        return ((labels is None or len({labels[steps[i][0]] for i in range(first, last + 1)}) == 1)
                and all(_one_condition(x, steps[first:last + 1], q, cond_tol) for q, x in conditions.items()))

    cut = [True] * (len(steps) + 1)  # cut[j]: a test ends before step j (and cut[len]: after the last)
    dt = float(np.median(np.diff(time))) if time is not None and len(time) > 1 else math.nan
    for j in range(1, len(steps)):
        a = steps[j][0]
        cut[j] = ((labels is not None and labels[a] != labels[a - 1])
                  or (math.isfinite(dt) and dt > 0 and time[a] - time[a - 1] > 3 * dt))

    def between(before: int, after: int) -> bool:  # steps (before, after) a ramp from one long step to the other
        if before < 0 or after >= len(steps) or min(size[before], size[after]) < 5 or not same(before, after):
            return False
        lo, hi = sorted((level[before], level[after]))
        return lo < hi and all(lo < level[i] < hi for i in range(before + 1, after))

    def at_ends(j: int, end: int) -> set:  # the pieces of the run [j, end) that begin or end a test, not both
        found = set()
        inner = [k for k in range(j + 1, end) if cut[k]]  # (a test's end inside the run: its pieces)
        for first, last in zip([j, *inner], [*inner, end]):
            up, down = cut[first] and not cut[last], cut[last] and not cut[first]
            held = last if up else first - 1  # the long step it ramps to or from
            if not (up or down) or last - first < 2 or not 0 <= held < len(steps) or size[held] < _SAMPLED_HOLD:
                continue
            run = np.array(level[first:last])
            moves = np.diff(run) * (1 if up else -1)  # (along the ramp: up from idle, down to it)
            if same(min(first, held), max(last - 1, held)) and np.all(run < level[held]) and np.all(moves > 0):
                found.update(range(first, last))
        return found

    out = set()
    j = 0
    while j < len(steps):
        if size[j] > 2:
            j += 1
            continue
        end = j
        while end < len(steps) and size[end] <= 2:
            end += 1
        out.update(range(j, end) if between(j - 1, end) else at_ends(j, end) if end - j >= 2 else ())
        j = end
    return out


def stand_points(values: dict, esc: np.ndarray, time: np.ndarray | None, *, settle: float = 0.5,
                 steady: float = 0.02, labels=None, form: str = "us", cond_tol: dict | None = None):
    """One averaged point per ESC step of a thrust-stand "steps" test.

    Consecutive rows with one ESC signal (within ESC_TOL[form] of the step's first row) and one
    operating condition (airspeed, incidence, collective within ``cond_tol``; the same
    ``labels``) form a step; neighbouring steps whose signals' medians agree within twice its
    tolerance (a jittering readback) and whose conditions agree within theirs are one. Of each
    step the first ``settle``
    of its duration (its rows, without a time column) is dropped, the motor settling, and of
    the rest the rows whose rotation speed is within ``steady`` of the step's median;
    what remains is averaged. A step where fewer than half of the rows after settling are
    steady (a spin-down, a step too short for the motor) gives no point. A step of one or
    two rows is taken whole (an export that already averaged its steps), unless it is part of a
    ramp between two steps of five rows or more, or at a test's end beside a step held for
    _SAMPLED_HOLD rows or more (:func:`_ramps`): then its rows are dropped as transients.

    Parameters
    ----------
    values : dict
        quantity -> ndarray of shape (N,), rows in file order; must hold ``rpm``.
    esc : ndarray, shape (N,)
        ESC signal: a pulse width [us], or a throttle in percent or as a fraction (``form``).
    time : ndarray, shape (N,), or None
    settle, steady : float
    labels : sequence of str, shape (N,), optional
        A run label per row (a ``group`` column): a step never spans two labels, and its
        label becomes ``<label>_step<k>_<esc>us``.
    form : {"us", "pct", "fraction"}
        The ESC signal's form (:func:`esc_form`): its tolerance and the labels' unit
        (``step<k>_<esc>us``, ``step<k>_<esc>pct``, ``step<k>_<esc>``).
    cond_tol : dict, optional
        quantity -> tolerance of the operating conditions; default
        :func:`condition_tolerances` (CONDITION_TOL, widened for a noisy column of a sampled log).

    Returns
    -------
    (dict, ndarray of str, int, tuple of str)
        The averaged values (quantity -> shape (K,)), each step's group label
        ``step<k>_<esc>us``, the number of rows dropped as transients, and the labels of
        the steps dropped as unsteady.
    """
    conditions = {q: np.asarray(values[q], float) for q in CONDITION_TOL if q in values}
    if cond_tol is None:
        cond_tol = condition_tolerances(conditions, esc, labels, ESC_TOL[form])[0]
    starts = _step_starts(esc, conditions, labels, ESC_TOL[form], cond_tol)
    steps = _merge_steps(list(zip(starts, [*starts[1:], esc.size])), esc, conditions, labels, ESC_TOL[form],
                         cond_tol)
    ramp = _ramps(steps, esc, conditions, labels, cond_tol, time)
    out = {k: [] for k in values}
    groups, dropped, unsteady = [], 0, []
    k = 0
    for j, (a, b) in enumerate(steps):
        if j in ramp:
            dropped += b - a
            continue
        k += 1
        idx = np.arange(a, b)
        m = np.median(esc[a:b])
        level = {"us": f"{m:.0f}us", "pct": f"{m:.4g}pct", "fraction": f"{m:.4g}"}[form]
        label = (f"{labels[a]}_" if labels is not None else "") + f"step{k}_{level}"
        if idx.size > 2:
            if time is not None and time[b - 1] > time[a]:
                keep = idx[time[idx] >= time[a] + settle * (time[b - 1] - time[a])]
            else:
                keep = idx[int(settle * idx.size):]
            rpm = values["rpm"][keep]
            med = np.median(rpm)
            steady_rows = keep[np.abs(rpm - med) <= steady * max(abs(med), 1e-9)] if med > 0 else keep
            if steady_rows.size < 0.5 * keep.size:
                # the speed never settled (a spin-down, a step too short): no steady point
                unsteady.append(label)
                dropped += idx.size
                continue
            dropped += idx.size - steady_rows.size
            idx = steady_rows
        for q in values:
            out[q].append(float(np.mean(values[q][idx])))
        groups.append(label)
    return {q: np.array(v) for q, v in out.items()}, np.array(groups, dtype=object), dropped, tuple(unsteady)
