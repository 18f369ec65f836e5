"""Flight-log readers: the NeuroBEM layout (MATLAB .mat or CSV) and PX4 ULog.

Every reader returns a :class:`FlightLog` in propmap's body frame (x forward, y left, z up;
SI units), with the rotor speeds in the log's motor order: a vehicle file that goes with a
log lists its rotors in that order (rotor k of the file is motor k of the log).

* **NeuroBEM** (L. Bauersfeld, E. Kaufmann, P. Foehn, S. Sun, D. Scaramuzza, "NeuroBEM:
  Hybrid Aerodynamic Quadrotor Model", RSS 2021): one N x 41 float array, as the authors'
  CSV files or converted to MATLAB v5 (``.mat``, one array of any name). Columns (the
  authors' names, :data:`NEUROBEM_COLUMNS`): t [s]; angular acceleration [rad/s^2],
  angular velocity [rad/s], quaternion (x, y, z, w), specific force (linear acceleration
  including gravity) [m/s^2], velocity [m/s], all in the body frame; position [m]; four
  motor speeds [rad/s] and their derivatives [rad/s^2]; battery voltage; NeuroBEM's
  predicted body force [N] and moment [N m]; residuals (the first 29 columns alone, N x 29,
  are read too: no prediction to score beside). A CSV may have a header line with those
  names, or none. Motor order: back-right, front-right, back-left, front-left.
* **PX4 ULog** (read with pyulog; io/ulog.py): accelerations, rates, attitude, velocity and
  motor speeds from their topics, interpolated to the timestamps of the acceleration topic
  over the time they all cover and turned from PX4's forward-right-down body frame into
  propmap's. Motor order: PX4's motor numbering of the airframe.

Errors are :class:`FlightLogError` (a ValueError) with one line naming the file and, for a
missing topic or column, what was looked for and what was found.
"""

from __future__ import annotations

import io
import re
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core._numbers import integer
from .flightlog_checks import GAP_STEPS, MIN_SAMPLES, FlightLogError, check_log
from .inputs import MAX_FILE_BYTES, as_path, decode_input_text, header_separator, read_input_bytes, show_path
from .ulog import read_ulog

__all__ = ["FlightLog", "FlightLogError", "read_flight_log", "NEUROBEM_COLUMNS", "FORMATS"]

#: the NeuroBEM dataset's 41 columns (the names of the authors' CSV loader)
NEUROBEM_COLUMNS = (
    "t", "ang acc x", "ang acc y", "ang acc z", "ang vel x", "ang vel y", "ang vel z",
    "quat x", "quat y", "quat z", "quat w", "acc x", "acc y", "acc z", "vel x", "vel y", "vel z",
    "pos x", "pos y", "pos z", "mot 1", "mot 2", "mot 3", "mot 4", "dmot 1", "dmot 2", "dmot 3", "dmot 4", "vbat",
    "model_fx", "model_fy", "model_fz", "model_tx", "model_ty", "model_tz",
    "residual_fx", "residual_fy", "residual_fz", "residual_tx", "residual_ty", "residual_tz",
)
FORMATS = ("neurobem", "ulog")
#: the layout's measured columns (time to the battery voltage), which an array or a headerless CSV may hold alone
#: (N x 29: the dataset without NeuroBEM's prediction and residuals; refused until 2026-11-30, a flight-log audit)
N_MEASURED = 29
MEASURED_WIDTHS = (N_MEASURED, len(NEUROBEM_COLUMNS))
#: columns of the layout propmap does not use (the position, the battery voltage): a header may leave them out and
#: a sample may hold NaN there (motion capture losing the vehicle for 3 samples refused the log: a flight-log audit,
#: 2026-11-27)
UNUSED_COLUMNS = ("pos x", "pos y", "pos z", "vbat")


@dataclass(frozen=True)
class FlightLog:
    """One flight log in propmap's body frame (x forward, y left, z up), N samples.

    Attributes
    ----------
    name : str
        The file's name (without folder), for reports.
    path : str
    format : str
        ``"neurobem"`` or ``"ulog"``.
    t : ndarray, shape (N,)
        Time [s], strictly increasing.
    angular_velocity : ndarray, shape (N, 3)
        Body rates w [rad/s].
    angular_acceleration : ndarray, shape (N, 3), or None
        dw/dt [rad/s^2] as logged; None when the log has none (computed from w then).
    specific_force : ndarray, shape (N, 3)
        Acceleration minus gravity, body axes [m/s^2] (what an accelerometer reads: +g
        along z in hover). Times the mass, the measured aerodynamic force.
    velocity : ndarray, shape (N, 3)
        Velocity over the ground, body axes [m/s].
    attitude : ndarray, shape (N, 4)
        Unit quaternion (x, y, z, w) of the body relative to a z-up world frame.
    rotor_omega : ndarray, shape (N, n_motors)
        Motor speeds Omega [rad/s], in the log's motor order.
    rotor_acceleration : ndarray, shape (N, n_motors), or None
        dOmega/dt [rad/s^2] as logged, or None.
    reference_force, reference_moment : ndarray, shape (N, 3), or None
        A model's prediction carried by the log (NeuroBEM's BEM + neural network, columns
        30-35), for comparison on the same samples; None otherwise.
    reference_mass : float or None
        The mass [kg] the prediction was made for, where the log carries its residual too
        (NeuroBEM's columns 36-38) and the two add up to a mass times the specific force
        (within 1e-3 of it rms; the NeuroBEM segments: 0.752 kg, the mass first published, to
        1.4e-6 N): the least-squares m in prediction + residual = m a_s. None otherwise.
    motor_order : str
        What the motor columns are.
    rotor_layout : ndarray, shape (n_motors, 3), or None
        Each motor's hub position, x forward and y left [m], and spin (+1 counter-clockwise
        seen from above, -1 clockwise), as the log's own vehicle geometry gives them (a PX4
        log's control allocation, ``CA_ROTOR<i>_PX``, ``_PY``, ``_KM``); None where the log
        gives none.
    """

    name: str
    path: str
    format: str
    t: np.ndarray
    angular_velocity: np.ndarray
    angular_acceleration: np.ndarray | None
    specific_force: np.ndarray
    velocity: np.ndarray
    attitude: np.ndarray
    rotor_omega: np.ndarray
    rotor_acceleration: np.ndarray | None
    reference_force: np.ndarray | None = None
    reference_moment: np.ndarray | None = None
    reference_mass: float | None = None
    motor_order: str = ""
    rotor_layout: np.ndarray | None = None

    @property
    def n(self) -> int:
        """Number of samples N."""
        return self.t.size

    @property
    def n_motors(self) -> int:
        """Number of motor-speed columns."""
        return self.rotor_omega.shape[1]

    @property
    def duration(self) -> float:
        """t[-1] - t[0] [s]."""
        return float(self.t[-1] - self.t[0])

    @property
    def rate_hz(self) -> float:
        """The sampling rate, 1 / the median time step [Hz] (a log has at least 2 samples)."""
        return 1.0 / float(np.median(np.diff(self.t)))


#: the most motors ``n_motors`` may name (a plausibility limit: PX4 names Motor1..12 and logs 8 or 16 outputs, and a
#: vehicle of more rotors meets the reader's own words, which motors no output carries)
N_MOTORS_MAX = 64


def _checked_motor_args(motor_map, n_motors, fmt: str):
    """``motor_map`` as two finite floats (a, b), b not 0, and ``n_motors`` as an int in [1,
    N_MOTORS_MAX], each None where not given; both for a ULog only. ValueError naming the argument
    (motor_map=(0, 0) made every motor speed a, "0,10" met a bare unpacking error, n_motors=2.5 a
    TypeError and 0 "no outputs": a flight-log audit, 2026-12-01)."""
    if fmt != "ulog" and (motor_map is not None or n_motors is not None):
        raise ValueError(f"motor_map and n_motors apply to PX4 ULog files only (a {fmt} log gives the motor speeds)")
    if motor_map is not None:
        try:
            if isinstance(motor_map, (str, bytes)):  # ("05" would unpack as 0 and 5)
                raise TypeError
            a, b = (float(x) for x in motor_map)
        except (TypeError, ValueError):
            raise ValueError(f"motor_map must be two numbers (a, b): rpm = a + b * output, "
                             f"got {motor_map!r:.60}") from None
        if not (np.isfinite(a) and np.isfinite(b) and b != 0):
            raise ValueError(f"motor_map's a and b must be finite and b not 0, got {motor_map!r:.60}")
        motor_map = (a, b)
    if n_motors is not None:
        n_motors = integer("n_motors", n_motors, 1, N_MOTORS_MAX, whole_float=False)
    return motor_map, n_motors


def read_flight_log(path, *, format: str | None = None, motor_map: tuple[float, float] | None = None,
                    n_motors: int | None = None) -> FlightLog:
    """Read a flight log (module docstring).

    Parameters
    ----------
    path : str or Path
    format : {"neurobem", "ulog"}, optional
        Default from the suffix: ``.mat`` and ``.csv`` NeuroBEM, ``.ulg`` ULog.
    motor_map : (a, b), optional
        ULog without ``esc_status`` rpm: motor speed [rpm] = a + b * actuator_outputs
        output (the ESC's calibration, stated by the user; the CLI's ``--motor-map a,b``).
    n_motors : int, optional
        With ``motor_map``: the vehicle's rotor count. Motor m is read from the output the
        log's parameters assign PX4's Motor m (``PWM_MAIN_FUNC<i>`` = 100 + m and the other
        drivers' ``<PREFIX>_FUNC<i>``; ``MOT_ORDERING`` = 1 with mixer files), else from
        output m (default: the motors the parameters assign, else all the topic's
        ``noutputs``; a flight controller logs 8 or 16).

    Returns
    -------
    FlightLog

    Raises
    ------
    TypeError
        ``path`` not a str or os.PathLike.
    ValueError
        ``motor_map`` not two finite numbers with b not 0, ``n_motors`` not an integer in [1,
        64], or either given for a NeuroBEM log.
    FlightLogError
        Not a readable regular file (size limit 200 MiB), an unknown format, a malformed
        file, a missing topic or column (named, with those found), fewer than 2 samples,
        time not strictly increasing or sampled below MIN_RATE_HZ (10 Hz: a time in ms or us) or
        above MAX_RATE_HZ (10 kHz), a motor acceleration beyond +-1e6 rad/s^2 or unlike the motor
        speeds' change,
        non-finite values (named as such), motor speeds outside [0, 1e5]
        rad/s, accelerations beyond 2000 m/s^2, rates beyond 200 rad/s or speeds beyond
        500 m/s (likely a unit mistake), a CSV without a header (or a .mat array) that does not
        have the 41 columns of the NeuroBEM layout or its first 29, the measured ones; an
        attitude quaternion not of unit norm, an accelerometer whose mean upward reading is not g
        plus the log's mean vertical acceleration (accelerations in g, gravity removed, a z-down frame), rates that are
        57 times or the negative of the attitude's change (deg/s, another frame).
    """
    p = as_path(path)
    name = show_path(p)
    fmt = format
    if p.is_dir():
        raise FlightLogError(f"{name}: a folder, not a flight log (give its log files)")
    if fmt is None:
        fmt = {".mat": "neurobem", ".csv": "neurobem", ".ulg": "ulog"}.get(p.suffix.lower())
        if fmt is None:
            raise FlightLogError(f"{name}: unknown flight-log format (suffix {p.suffix or 'none'!s}); give a NeuroBEM "
                                 ".mat or .csv file or a PX4 .ulg file, named with its format's suffix (or, in Python, "
                                 "read_flight_log's format)")
    if fmt not in FORMATS:
        raise FlightLogError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    motor_map, n_motors = _checked_motor_args(motor_map, n_motors, fmt)
    raw = read_input_bytes(p, FlightLogError, limit=MAX_FILE_BYTES,
                           too_large=": split the flight into logs under it (at 400 Hz an uncompressed NeuroBEM .mat "
                                     "holds about 26 minutes; fit flight takes several logs)")
    said = []
    if fmt == "ulog":
        fields, said = read_ulog(raw, name, motor_map, n_motors, error=FlightLogError, min_samples=MIN_SAMPLES,
                                 gap_steps=GAP_STEPS)
        log = FlightLog(name=p.name, path=str(p), format="ulog", **fields)
    elif p.suffix.lower() == ".mat":
        log = _neurobem(_mat_array(raw, name), p, name)
    else:
        arr, lines = _csv_array(raw, p, name)
        log = _neurobem(arr, p, name, lines)
    check_log(log, name)
    for text in said:  # (after the refusals: a refused log printed these too, a review)
        warnings.warn(text, UserWarning, stacklevel=2)
    return log


# ---------------------------------------------------------------------------- NeuroBEM

def _mat_array(raw: bytes, name: str) -> np.ndarray:
    from scipy.io import loadmat

    try:
        data = loadmat(io.BytesIO(raw))
    except NotImplementedError:
        raise FlightLogError(f"{name}: MATLAB v7.3 (HDF5) file; save it as MATLAB v5 (-v7 or older)") from None
    except MemoryError:  # (the input too large for the memory, not a damaged file: the CLI says so)
        raise
    except Exception as exc:  # scipy raises many types for a corrupt file
        raise FlightLogError(f"{name}: not a readable MATLAB v5 file ({type(exc).__name__}: "
                             f"{str(exc)[:120]})") from None
    arrays = {k: v for k, v in data.items() if not k.startswith("__") and isinstance(v, np.ndarray)}
    other = [f"{k} ({'a sparse matrix' if hasattr(v, 'toarray') else type(v).__name__})" for k, v in data.items()
             if not k.startswith("__") and not isinstance(v, np.ndarray)]  # (a sparse one was reported as none)
    if len(arrays) != 1:
        raise FlightLogError(f"{name}: expected one N x {len(NEUROBEM_COLUMNS)} array, found "
                             f"{len(arrays)} variable(s) ({', '.join(sorted(arrays))[:200] or 'none'})"
                             + (f"; not read: {', '.join(other)[:200]} (save it as a full double array)" if other
                                else ""))
    (key, a), = arrays.items()
    if a.ndim != 2 or a.shape[1] not in MEASURED_WIDTHS or a.dtype.kind not in "iuf":
        raise FlightLogError(f"{name}: variable {key!r} must be an N x {len(NEUROBEM_COLUMNS)} numeric array "
                             f"(the NeuroBEM layout; N x {N_MEASURED}: its measured columns alone), got shape "
                             f"{a.shape} of {a.dtype}")
    if a.dtype.kind != "f":  # (int16 time truncated to whole seconds was refused as 'time does not increase')
        raise FlightLogError(f"{name}: variable {key!r} holds {a.dtype} values; a flight log's are floating-point "
                             "(its time in seconds, its rates in rad/s): save it as double")
    out = np.full((a.shape[0], len(NEUROBEM_COLUMNS)), np.nan)  # (N x 29: no prediction, NaN there)
    out[:, :a.shape[1]] = a
    return out


def _csv_array(raw: bytes, p: Path, name: str) -> tuple[np.ndarray, list[int]]:
    """The N x 41 array of a NeuroBEM CSV (columns by its header, else by position) and each row's
    line in the file (1-based, for messages)."""
    text = decode_input_text(raw, p, FlightLogError)
    lines, first = _csv_lines(text, name)
    skip, order = _csv_columns(lines, first, name)
    numbered, a = _csv_numbers(lines, skip, name)
    if skip == first:  # (no header: by position, the 29 measured columns alone or all 41)
        order = list(range(a.shape[1]))
    if a.shape[1] <= max(order) or (skip == first and a.shape[1] not in MEASURED_WIDTHS):
        # without a header the columns are the layout's by position: another count (an index column) shifts them
        raise FlightLogError(f"{name}: {a.shape[1]} columns; the NeuroBEM layout has {len(NEUROBEM_COLUMNS)} "
                             f"({N_MEASURED} without the prediction and its residuals, or a header naming them)")
    out = np.full((a.shape[0], len(NEUROBEM_COLUMNS)), np.nan)
    for k, j in enumerate(order):
        if j >= 0:
            out[:, k] = a[:, j]
    return out, [n for n, _ in numbered]


def _csv_lines(text: str, name: str) -> tuple[list[str], int]:
    """The CSV's lines, a header written as a comment uncommented and a trailing comma on every line
    taken off, and the index of its first line that is not blank or a comment (the header, or the
    first data row)."""
    lines = text.splitlines()
    # a header written as a comment ('# t,ang acc x,...': numpy.savetxt's header) is the header (skipped as a comment,
    # the columns were read by position without a word: a review)
    for k, line in enumerate(lines):
        if not line.strip():
            continue
        if not line.lstrip().startswith("#"):
            break
        names = [c.strip().strip('"').lower() for c in line.lstrip()[1:].split(",")]
        if "t" in names and sum(c in names for c in NEUROBEM_COLUMNS[:29]) >= 3:
            lines[k] = line.lstrip()[1:]
            break
    # (a leading '# comment' line was taken as the header; '#' lines are skipped among the data too)
    first = next((i for i, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")), None)
    if first is None:
        raise FlightLogError(f"{name}: empty file" if not any(line.strip() for line in lines) else
                             f"{name}: only comment lines ('#')")
    body = [line for line in lines[first:] if line.strip() and not line.lstrip().startswith("#")]
    if len(body) > 1 and all(line.rstrip().endswith(",") for line in body[1:]):
        # (a spreadsheet's trailing comma on every line, the header's too or not: it was refused as a 42nd column)
        lines = lines[:first] + [line.rstrip()[:-1] if line.rstrip().endswith(",") and not line.lstrip().startswith("#")
                                 else line for line in lines[first:]]
    return lines, first


def _csv_columns(lines: list[str], first: int, name: str) -> tuple[int, list[int]]:
    """Where the data rows start (the index of the first line after a header) and the CSV column of
    each of the layout's columns (-1: absent): by the header's names, else by position; a header of
    another separator, without the layout's columns, with a fifth motor or a column twice refused."""
    head = [c.strip().strip('"').lower() for c in lines[first].split(",")]
    skip = first
    order = list(range(len(NEUROBEM_COLUMNS)))
    try:
        numbers = [float(c) for c in head]
        width = len(numbers)
        if width in MEASURED_WIDTHS and numbers in (list(range(width)), list(range(1, width + 1))):
            # (a header of column numbers, pandas' to_csv of an unnamed frame: it was read as data and refused for
            # its 'quaternion' [7, 8, 9, 10]: a flight-log fuzzing audit; 29 of them too since 2026-11-30)
            skip, order = first + 1, list(range(width))
    except ValueError:  # a header line: map the columns by name
        skip = first + 1
        missing = [c for c in NEUROBEM_COLUMNS[:29] if c not in head and c not in UNUSED_COLUMNS]
        sep = header_separator(lines[first])
        blanks = lines[first].split()
        if missing and sep == "," and "," not in lines[first] and len(blanks) >= len(NEUROBEM_COLUMNS[:29]):
            raise FlightLogError(f"{name}: the columns are separated by blanks; a flight-log CSV is separated by ','"
                                 " (the NeuroBEM layout), with '.' as its decimal point") from None
        if missing and sep != "," and lines[first].count(sep) >= len(NEUROBEM_COLUMNS[:29]) - 1:
            said = "';'" if sep == ";" else "tabs"
            raise FlightLogError(f"{name}: the columns are separated by {said}; a flight-log CSV is separated by ','"
                                 " (the NeuroBEM layout), with '.' as its decimal point") from None
        if missing:
            raise FlightLogError(f"{name}: header lacks the NeuroBEM column(s) {', '.join(missing[:6])}"
                                 f"{' ...' if len(missing) > 6 else ''}; found {', '.join(head)[:200]}") from None
        more = [c for c in head if re.fullmatch(r"d?mot \d+", c) and c not in NEUROBEM_COLUMNS]
        if more:  # (read as the layout, they would be dropped: a hexacopter fitted as a quadrotor)
            raise FlightLogError(f"{name}: column(s) {', '.join(more[:4])}: the NeuroBEM layout carries 4 motor "
                                 "speeds (mot 1-4); a vehicle of more rotors needs a PX4 ULog") from None
        dup = sorted({c for c in head if head.count(c) > 1 and c in NEUROBEM_COLUMNS})
        if dup:
            raise FlightLogError(f"{name}: column(s) {', '.join(dup)} appear twice in the header") from None
        order = [head.index(c) if c in head else -1 for c in NEUROBEM_COLUMNS]
    return skip, order


def _csv_numbers(lines: list[str], skip: int, name: str) -> tuple[list[tuple[int, str]], np.ndarray]:
    """The data lines from index ``skip`` on (with their 1-based line numbers) and their numbers;
    a row of another column count or a cell that is not numeric refused, naming its line."""
    # the data lines with their numbers in the file (1-based), so that an error names the file's line
    numbered = [(k + 1, line) for k, line in enumerate(lines) if k >= skip and line.strip()
                and not line.lstrip().startswith("#")]
    if not numbered:  # (a header alone read as '1 columns', and NumPy's own warning came as a second line)
        raise FlightLogError(f"{name}: no data rows after the header (line {skip})")
    try:
        # (every field quoted, '"9.33"', as some exporters write numbers: refused as not numeric, a flight-log audit)
        a = np.loadtxt(io.StringIO("\n".join(line.replace('"', "") for _, line in numbered)), delimiter=",", ndmin=2)
    except ValueError as exc:
        msg = str(exc).splitlines()[0][:160]
        changed = re.search(r"number of columns changed from (\d+) to (\d+) at row (\d+)", msg)
        row = re.search(r" at row (\d+)", msg)
        if changed and 0 < int(changed.group(3)) <= len(numbered):  # (NumPy counts this row from 1)
            raise FlightLogError(f"{name}: line {numbered[int(changed.group(3)) - 1][0]} has {changed.group(2)} "
                                 f"columns where the data's first line has {changed.group(1)}") from None
        if row and int(row.group(1)) < len(numbered):  # (a cell it cannot convert: counted from 0)
            raise FlightLogError(f"{name}: line {numbered[int(row.group(1))][0]}: not numeric "
                                 f"({msg.replace(row.group(0), '').rstrip('.')})") from None
        raise FlightLogError(f"{name}: not a numeric CSV after line {skip} ({msg})") from None
    return numbered, a


def _neurobem(a: np.ndarray, p: Path, name: str, lines=None) -> FlightLog:
    """The NeuroBEM array ``a`` as a FlightLog (``lines``: each sample's line in a CSV, for messages)."""
    if a.shape[0] < MIN_SAMPLES:
        raise FlightLogError(f"{name}: {a.shape[0]} sample(s); a log needs at least {MIN_SAMPLES}")
    core = a[:, :29].copy()
    core[:, [NEUROBEM_COLUMNS.index(c) for c in UNUSED_COLUMNS]] = 0.0  # (not read: NaN allowed)
    if not np.all(np.isfinite(core)):
        i, j = np.argwhere(~np.isfinite(core))[0]
        at = "" if lines is None else f" (line {lines[i]})"
        raise FlightLogError(f"{name}: sample {i + 1}{at}, column {NEUROBEM_COLUMNS[j]!r}: not a finite number")
    ref = a[:, 29:35]
    # (zeros throughout: a user's log without NeuroBEM's prediction, scored as its F 4.4 N: a flight-log fuzzing audit)
    has_ref = bool(np.all(np.isfinite(ref))) and bool(np.any(ref != 0.0))
    gaps = int(np.sum(~np.isfinite(ref).all(axis=1)))
    # (its rows left out of the tables without a word before; a column absent throughout, NaN in every sample, is not
    # a gap: a CSV with the prediction's force and not its moment, a review)
    if gaps and np.isfinite(ref).any(axis=0).all() and np.any(np.isfinite(ref) & (ref != 0.0)):
        warnings.warn(f"{name}: {gaps} sample(s) of the log's own prediction (columns 30-35, NeuroBEM's BEM + neural "
                      "network) are not finite numbers: that prediction is not read, nor scored beside propmap's",
                      UserWarning, stacklevel=3)
    return FlightLog(
        name=p.name, path=str(p), format="neurobem", t=a[:, 0].copy(), angular_acceleration=a[:, 1:4].copy(),
        reference_mass=_reference_mass(a) if has_ref else None,
        angular_velocity=a[:, 4:7].copy(), attitude=a[:, 7:11].copy(), specific_force=a[:, 11:14].copy(),
        velocity=a[:, 14:17].copy(), rotor_omega=a[:, 20:24].copy(), rotor_acceleration=a[:, 24:28].copy(),
        reference_force=a[:, 29:32].copy() if has_ref else None,
        reference_moment=a[:, 32:35].copy() if has_ref else None,
        motor_order="NeuroBEM: back-right, front-right, back-left, front-left")


def _reference_mass(a: np.ndarray) -> float | None:
    """The mass the NeuroBEM array's prediction (columns 30-32) was made for: its force plus its
    residual (columns 36-38) is that mass times the specific force (columns 12-14). None where the
    residual is missing or the sum is not a mass times the specific force within 1e-3 rms."""
    if a.shape[1] < 38:
        return None
    total, f = a[:, 29:32] + a[:, 35:38], a[:, 11:14]
    if not (np.all(np.isfinite(total)) and np.any(a[:, 35:38] != 0.0)):
        return None
    ff = float(np.sum(f * f))
    if not ff > 0:
        return None
    m = float(np.sum(total * f)) / ff
    miss = float(np.sqrt(np.mean((total - m * f) ** 2)))
    scale = float(np.sqrt(np.mean(total**2)))
    return m if m > 0 and miss <= 1e-3 * scale else None
