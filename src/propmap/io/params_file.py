"""Section-parameter files (TOML); the named sets that resolve to them are io/param_sets.py's.

Two section models (airfoil.py), chosen by ``section_model``. SI units except angles,
which carry ``_deg`` in the key.

The paper's model (``section_model = "gill2017"``, the default when the key is absent)::

    cl1 = 5.3            # pre-stall lift slope [1/rad]
    cl2 = 1.7            # post-stall amplitude [-]
    cd = 1.8             # drag amplitude [-]
    alpha0_deg = 20.6    # stall angle [deg]
    # optional (footnote 2 defaults of Gill & D'Andrea 2017):
    M = 50.0             # sigmoid sharpness [1/rad]
    cd0 = 0.01           # form drag [-]
    cp_blasius = 1.328   # Blasius skin-friction constant [-]
    lift_model = "sigmoid"   # or "sincos" (footnote 1, uses cl2)
    tip_loss = false     # Prandtl tip loss (not in the paper)
    hub_loss = false

The cambered polar (``section_model = "cambered"``); every key is optional: a key the file
lacks takes the shipped ``generic`` set's value (with a warning naming the keys), so that a
file holding, say, only ``rho`` means "the generic set in this air"; ``write_params`` writes
them all::

    section_model = "cambered"
    cl_alpha = 5.4          # lift slope at re_ref [1/rad]
    alpha_L0_deg = -5.5     # zero-lift angle [deg]
    cl_max = 1.85
    cl_min = -0.5
    cd_min = 0.022
    cd2 = 0.063
    cl_cdmin = 0.5
    cd90 = 1.98
    re_ref = 1e5
    re_exp = -0.65          # drag ~ Re^re_exp
    re_exp_lift = 0.026     # lift slope ~ Re^re_exp_lift
    re_exp_stall = 0.0      # stall angles ~ Re^re_exp_stall
    stall_delay = 0.0       # stall angles x (1 + stall_delay (c/r)^2)
    alpha_L0_re_deg = -2.9  # d alpha_L0 / d ln(Re) [deg]
    M = 20.0
    compressibility = true
    tip_loss = true
    hub_loss = false

Either model also takes the rotor options (``RotorOptions``; docs/models.md), whose defaults
are the paper's rigid blades in an azimuth-independent inflow (the paper's section model's
defaults shown; the cambered model's are ``descent = "empirical"``, ``radial_drag = true`` and
``inplane_induction = true``, which a cambered file without those keys gets, with the warning
that names every key taken from the generic set)::

    inflow = "uniform"        # or "drees", "pitt-peters" (linear inflow models)
    descent = "glauert"       # or "empirical" (measured inflow in the vortex-ring state)
    flap_compliance = 0.0     # 1 / K_beta [rad/(N m)] of flapping blades, in [0, 1000]; 0 = rigid
    collective_deg = 0.0      # blade-angle offset [deg], in [-30, 30]
    swirl = false             # the annuli's swirl (tangential induced velocity; not in the paper)
    radial_drag = false       # the radial flow's drag in edgewise flow (in-plane force; not in the paper)
    inplane_induction = false # the skewed wake's in-plane induced velocity (edgewise flow; not in the paper)
    dynamic_stall = 0.0       # Gormont's gamma of the cambered model's dynamic stall, in [0, 5] (about 1.5; 0 = off,
                              # also where the key is absent; not in the paper)

A cambered file may start from a named section instead of the ``CamberedParams`` defaults:
``section = "naca0015"`` takes every key of that section preset (:func:`propmap.io.param_sets.section_preset`;
symmetric NACA sections fitted to Sheldahl & Klimas, Sandia SAND80-2114, 1981), and the
file's other keys override it. ``--params section:naca0015`` names the preset alone.

``rho``, ``mu`` and ``speed_of_sound`` (the air) and the free text keys ``comment`` and
``source``. A flight fit (``propmap fit flight``) adds the airframe drag it identified, which
``propmap wrench`` uses and the single-rotor commands ignore::

    [body]
    drag_area = [0.004, 0.004, 0.008]   # (C_D A) along body x, y, z [m^2], each in [0, 10]
    wash_factor = 1.0                   # optional (default 0), slipstream factor, in [0, 3] (core/body.py)
    centre_of_mass = [0.002, -0.001, 0.0]   # [m], each in [-100, 100]: the fitted centre of mass in
                                            # the vehicle file's frame (optional)
    rotor_interference = 1.0            # optional, in [0, 3]: the fitted factor on the inflow the
                                        # rotors' wakes induce at each other (core/interference.py)
    comment = "..."                     # optional free text

Every number must be a TOML integer or float (a quoted ``"5.3"`` or a ``true`` is refused,
never converted), finite, and within its range: the cambered keys as ``CamberedParams``
(angles in degrees here: ``alpha_L0_deg`` in [-20, 10], ``alpha_L0_re_deg`` in [-5, 5]);
the paper's keys and the air within :data:`FILE_RANGES`, which only refuse absurd values
(``cl1 = 1e300``): ``cl1``, ``cl2``, ``cd``, ``cp_blasius`` in [0, 100], ``cd0`` in
[0, 10], ``M`` in (0, 1e6], ``alpha0_deg`` in (0, 90); ``rho`` in [0.001, 2000] kg/m^3 (Mars' surface air is 0.02),
``mu`` in (0, 10] Pa s, ``speed_of_sound`` in [100, 1e4] m/s (no gas is slower than about
100 m/s: sulphur hexafluoride 134 m/s, dry air at -120 degC 248 m/s; below, the compressibility
term 1/a^2 grows without meaning, and a speed of sound near 0, 1e-300, divided by zero). The
text keys (``comment``, ``source``) must be TOML strings.
"""

from __future__ import annotations

import contextlib
import functools
import math
import os
import warnings
from dataclasses import fields
from pathlib import Path

import tomli_w

from ..core._numbers import real
from ..core.air import check_air
from ..core.airfoil import (DESCENT_MODELS, INFLOW_MODELS, LIFT_MODELS, RECORD_META, Air, AirfoilParams,
                             CamberedParams, SectionParams)
from .atomic import atomic_write
from .inputs import as_path, show_path
from .params_tables import (BODY_TABLE, COVERAGE_KEYS, COVERAGE_SINGLE_TEXTS, COVERAGE_TABLE, COVERAGE_TEXT_KEYS,
                            BodyTable, body_from_dict, check_number, coverage_from_dict, short_repr)
from .toml_file import did_you_mean, load_toml

__all__ = ["ParamsFileError", "BodyTable", "read_params", "read_body", "write_params", "params_to_dict",
           "params_from_dict", "body_from_dict", "coverage_from_dict", "read_coverage", "set_coverage",
           "SECTION_MODELS"]

SECTION_MODELS = ("gill2017", "cambered")
REQUIRED = {"gill2017": ("cl1", "cl2", "cd", "alpha0_deg"), "cambered": ()}
AIR_KEYS = ("rho", "mu", "speed_of_sound")
TEXT_KEYS = ("comment", "source", "section_model", "section")
#: prefix of the named section presets in ``--params`` (``section:naca0015``)
SECTION_PREFIX = "section:"
#: keys holding an angle in degrees in files, and the field they set [rad]
DEG_KEYS = {"alpha0_deg": "alpha0", "alpha_L0_deg": "alpha_L0", "alpha_L0_re_deg": "alpha_L0_re",
            "collective_deg": "collective"}
#: the rotor options' file ranges (both section models)
_ROTOR_RANGES = {"collective_deg": (-30.0, 30.0, False, False, "deg"),
                 "flap_compliance": (0.0, 1e3, False, False, "rad/(N m)")}
#: valid ranges of file keys checked here, (low, high, low open, high open, unit); the
#: records check the rest (CamberedParams.RANGES)
FILE_RANGES = {
    "gill2017": {"cl1": (0.0, 100.0, False, False, ""), "cl2": (0.0, 100.0, False, False, ""),
                 "cd": (0.0, 100.0, False, False, ""), "cd0": (0.0, 10.0, False, False, ""),
                 "cp_blasius": (0.0, 100.0, False, False, ""), "M": (0.0, 1e6, True, False, "1/rad"),
                 "alpha0_deg": (0.0, 90.0, True, True, "deg"), **_ROTOR_RANGES},
    "cambered": {"alpha_L0_deg": (-20.0, 10.0, False, False, "deg"),
                 "alpha_L0_re_deg": (-5.0, 5.0, False, False, "deg"), **_ROTOR_RANGES},
    "air": {"rho": (1e-3, 2000.0, False, False, "kg/m^3"), "mu": (0.0, 10.0, True, False, "Pa s"),
            "speed_of_sound": (100.0, 1e4, False, False, "m/s")},
}


class ParamsFileError(ValueError):
    """A parameter file is malformed; the message names the file and the key."""


def _record(model: str):
    return AirfoilParams if model == "gill2017" else CamberedParams


def _file_keys(model: str) -> dict[str, str]:
    """file key -> field name of the model's record (angles with ``_deg``; the set's air is
    written as AIR_KEYS, its label not at all)."""
    deg = {v: k for k, v in DEG_KEYS.items()}
    return {deg.get(f.name, f.name): f.name for f in fields(_record(model)) if f.name not in RECORD_META}


def params_from_dict(data: dict, *, where: str = "parameters", label: str = "", fill: bool = False) -> SectionParams:
    """Build the parameter record, with its air, from a file-form dict (angles in degrees,
    ``section_model`` key).

    ``fill``: the cambered keys the dict lacks take the shipped generic set's values, and a
    warning names them (parameter files; the module docstring); otherwise the record's
    defaults.

    Parameters
    ----------
    data : dict
        File form (:func:`params_to_dict`; module docstring): the model's keys, the air's
        (``rho``, ``mu``, ``speed_of_sound``), the text keys, ``section`` (a named preset,
        the other keys on top) and the ``[body]`` and ``[coverage]`` tables, which are
        checked here too (:func:`body_from_dict`, :func:`coverage_from_dict`) but not
        returned.
    where : str
        Starts every error message (a file's path).
    label : str
        The record's ``.label``.
    fill : bool
        Fill a cambered set's missing keys from the generic set (ignored with ``section``
        or for the paper's model).

    Returns
    -------
    AirfoilParams or CamberedParams
        Angles in rad, carrying the dict's air (``.air``; footnote 2's values for the keys
        it lacks).

    Warns
    -----
    UserWarning
        With ``fill``, the keys taken from the generic set.

    Raises
    ------
    ValueError
        Unknown ``section_model``, a missing required key, an unknown key, a value of the
        wrong type (a string or a bool for a number), non-finite or out of range (the
        module docstring gives the ranges); the message starts with ``where`` and names the
        key and the valid range.
    """
    if not isinstance(data, dict):
        raise ValueError(f"{where}: expected a table of keys, got {short_repr(data)}")
    fill = fill and "section" not in data and data.get("section_model", "gill2017") == "cambered"
    if "section" in data:  # a named section preset, the file's keys on top
        name = data["section"]
        presets = _section_tables()
        if not isinstance(name, str) or name not in presets:
            raise ValueError(f"{where}: section must be one of {', '.join(presets)}, got {short_repr(name)}")
        if data.get("section_model", "cambered") != "cambered":
            raise ValueError(f"{where}: section = {name!r} is a cambered-model preset; section_model must be "
                             f"'cambered', got {short_repr(data.get('section_model'))}")
        base = {k: v for k, v in presets[name].items() if k not in ("source", "comment")}
        data = {**base, **{k: v for k, v in data.items() if k != "section"}}
    model = data.get("section_model", "gill2017")
    if not isinstance(model, str) or model not in SECTION_MODELS:
        raise ValueError(f"{where}: section_model must be one of {', '.join(SECTION_MODELS)}, got {short_repr(model)}")
    missing = [k for k in REQUIRED[model] if k not in data]
    if missing:
        raise ValueError(f"{where}: missing key(s) {', '.join(missing)} (required for section_model "
                         f"{model!r}: {', '.join(REQUIRED[model])})")
    keys = _file_keys(model)
    unknown = sorted(map(str, set(data) - set(keys) - set(AIR_KEYS) - set(TEXT_KEYS) - {BODY_TABLE, COVERAGE_TABLE}))
    if unknown:
        shown = ", ".join(short_repr(k, 40) if not k.isidentifier() else k for k in unknown[:5])
        more = f" and {len(unknown) - 5} more" if len(unknown) > 5 else ""
        known = sorted(set(keys) | set(AIR_KEYS) | set(TEXT_KEYS) | {BODY_TABLE, COVERAGE_TABLE})
        hint = did_you_mean(unknown, known)  # (the valid keys named, an audit, stop 102)
        raise ValueError(f"{where}: unknown key(s) {shown}{more} for section_model {model!r}{hint} (its keys: "
                         f"{', '.join(known)})")
    for key in ("comment", "source"):
        if key in data and not isinstance(data[key], str):
            raise ValueError(f"{where}: {key} must be text (a TOML string), got {short_repr(data[key])}")
    types = {f.name: f.type if isinstance(f.type, str) else f.type.__name__ for f in fields(_record(model))}
    types = {k: types[n] for k, n in keys.items()}  # file key -> "float", "bool" or "str"
    ranges = {**FILE_RANGES[model], **FILE_RANGES["air"]}
    choices = {"lift_model": LIFT_MODELS, "inflow": INFLOW_MODELS, "descent": DESCENT_MODELS}
    for key in sorted(set(data) & (set(keys) | set(AIR_KEYS))):
        kind = types.get(key, "float")
        if kind == "float":
            check_number(data[key], key, where, ranges.get(key))
        elif kind == "bool" and not isinstance(data[key], bool):
            raise ValueError(f"{where}: {key} must be true or false, got {short_repr(data[key])}")
        elif key in choices and data[key] not in choices[key]:
            raise ValueError(f"{where}: {key} must be one of {', '.join(choices[key])}, got {short_repr(data[key])}")
    _radian_like(data, where)
    kw, filled = {}, None
    if fill:
        kw, filled = _generic_fill(data, keys, where)
    for key, name in keys.items():
        if key not in data:
            continue
        value = data[key]
        if key in DEG_KEYS:
            value = math.radians(value)
        kw[name] = value
    try:
        air = Air(**{k: data[k] for k in AIR_KEYS if k in data})
        params = _record(model)(**kw, air=air, label=label)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{where}: {exc}") from None
    body_from_dict(data, where=where)  # validated here too, so that every reader refuses a bad table
    coverage_from_dict(data, where=where)
    if filled:  # said once the file is known to be valid (a refused file gets its error alone)
        import warnings

        warnings.warn(filled, UserWarning, stacklevel=3)
    return params


#: below these magnitudes [deg] an angle key's value looks like radians (warned): the paper's stall angle
#: alpha0_deg (its Table I: 20.4-27.5 deg; 0.36 rad is 20.6 deg). (Not alpha_L0_deg: the catalogue's
#: calibrated sets span -10.1 to +2.2 deg, one at 0.19 deg, so a radian value cannot be told apart.)
RADIAN_LIKE_DEG = {"alpha0_deg": 2.0}


def _radian_like(data: dict, where: str) -> None:
    """Warn of an angle key whose value looks like radians (RADIAN_LIKE_DEG); it is read as degrees."""
    import warnings

    for key, small in RADIAN_LIKE_DEG.items():
        v = data.get(key)
        if isinstance(v, (int, float)) and not isinstance(v, bool) and 0 < abs(v) < small:
            warnings.warn(f"{where}: {key} = {v:g} deg is small for the angle it is: radians? ({v:g} rad = "
                          f"{math.degrees(v):.3g} deg; read as degrees)", UserWarning, stacklevel=4)


def read_coverage(path) -> dict | None:
    """The ``[coverage]`` table of a parameter file (what the data behind a fitted set
    covered), or None.

    Parameters
    ----------
    path : str or Path
        A parameter file (module docstring).

    Returns
    -------
    dict or None
        As :func:`coverage_from_dict`. Only the table is checked, not the file's other
        keys.

    Raises
    ------
    ParamsFileError
        As :func:`read_params`.
    TypeError
        ``path`` not a str or os.PathLike.
    """
    path = as_path(path)
    with _reading(path) as data:
        return coverage_from_dict(data, where=show_path(path))


# (a context manager, not a function given the parser: the parser's warnings keep their stacklevel)
@contextlib.contextmanager
def _reading(path: Path):
    """Yield the parameter file ``path`` parsed; a ValueError in the block is raised as a ParamsFileError."""
    data = load_toml(path, ParamsFileError)
    try:
        yield data
    except ValueError as exc:
        raise ParamsFileError(str(exc)) from None


def set_coverage(label: str) -> dict | None:
    """What the data behind a parameter set covered, for warnings: a parameter file's
    ``[coverage]`` table (:func:`read_coverage`; None without one, or for a file that does
    not read), else the shipped set's (:func:`propmap.io.calibration.coverage`).

    Parameters
    ----------
    label : str
        A parameter file's path, ``"generic"``, ``"generic without <family>"`` or
        ``"calibrated:<name>"``.

    Returns
    -------
    dict or None
        ``J_max``, ``incidence_deg_max`` and, for a fitted file, ``rpm_min``, ``rpm_max``
        [rpm], ``airspeed_max`` [m/s], a load fit's ``propeller``, ``diameter_m`` [m],
        ``n_blades``, ``re75_min``, ``re75_max`` [-] (since 2026-11-26) and the text keys
        (``data``, ``data_sha256``, ``files_sha256``, ``groups``, ``held_out``), each where the
        file gives it; None
        where propmap does not know the data (Table I, other files).
    """
    from .calibration import coverage

    if label and os.path.isfile(label):  # (Path.is_file raised on a label past 255 characters: a review)
        st = Path(label).stat()  # (by content's stamp: a command reads it for several checks, once)
        found = _file_coverage(str(Path(label).resolve()), st.st_mtime_ns, st.st_size)
        return None if found is None else dict(found)
    return coverage(label)


@functools.lru_cache(maxsize=16)
def _file_coverage(path: str, mtime_ns: int, size: int) -> dict | None:
    """:func:`read_coverage` of ``path`` (None for a file that does not read), remembered for its
    modification time and size: a command's checks (the fitted propeller, the envelope, the
    model uncertainty, validate's labels) each asked for it (``loads`` and ``validate`` with a
    fitted file read it twice, once since; measured 2026-11-26)."""
    try:
        return read_coverage(path)
    except ValueError:
        return None


#: rotor options a file without the key has off, silently (they came later than the files written before them)
OFF_WHEN_ABSENT = ("dynamic_stall",)


def _generic_fill(data: dict, keys: dict, where: str) -> tuple[dict, str | None]:
    """The generic set's values (field name -> value) of the cambered keys ``data`` lacks, and
    the warning naming them, or None (OFF_WHEN_ABSENT: left at the record's default, 0, unnamed)."""
    from .calibration import generic_params

    g = generic_params()
    missing = [k for k in keys if k not in data and k not in OFF_WHEN_ABSENT]
    message = None
    if missing:
        given = sorted(k for k in data if k in keys or k in AIR_KEYS)
        message = (f"{where}: {', '.join(missing)} not in the file: taken from the generic set (the file gives "
                   f"{', '.join(given) or 'no model key'})")
    return {keys[k]: getattr(g, keys[k]) for k in missing}, message


def params_to_dict(params: SectionParams, air: Air | None = None) -> dict:
    """The file form of ``params`` and ``air``: every field, angles in degrees.

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: the set's own (``params.air``).

    Returns
    -------
    dict
        ``section_model`` and every field under its file key (``alpha0_deg``,
        ``alpha_L0_deg``, ``alpha_L0_re_deg``, ``collective_deg`` in degrees), and ``rho``, ``mu``,
        ``speed_of_sound``. ``params_from_dict`` gives back the record with its angles
        equal to within the degree-radian round trip (relative 2e-16).

    Raises
    ------
    TypeError
        ``params`` not a parameter set or ``air`` not an :class:`Air`.
    """
    if not isinstance(params, (AirfoilParams, CamberedParams)):
        raise TypeError(f"params must be AirfoilParams or CamberedParams, got {type(params).__name__}")
    air = params.air if air is None else air
    check_air(air)
    data = {"section_model": params.section_model}
    keys = _file_keys(params.section_model)
    for key, name in keys.items():
        value = getattr(params, name)
        data[key] = math.degrees(value) if key in DEG_KEYS else value
    data.update({k: getattr(air, k) for k in AIR_KEYS})
    return data


def read_params(path) -> SectionParams:
    """Read a parameter file (either section model; format in the module docstring).

    Parameters
    ----------
    path : str or Path
        The TOML parameter file (``propmap fit`` writes them; :func:`write_params`).

    Returns
    -------
    AirfoilParams or CamberedParams
        Carrying the file's air (``.air``; footnote 2's where the file gives none) and its
        path as ``.label``.

    Warns
    -----
    UserWarning
        A cambered file that lacks keys: they are the generic set's (named).

    Raises
    ------
    ParamsFileError
        Not a readable regular file (a directory, a device, over 16 MiB), not UTF-8,
        invalid TOML, a missing required key, an unknown key, a value of the wrong type (a
        quoted number, a bool for a number), non-finite or out of range (ranges in the
        module docstring); the message names the file and the key.
    TypeError
        ``path`` not a str or os.PathLike.
    """
    path = as_path(path)
    with _reading(path) as data:
        return params_from_dict(data, where=show_path(path), label=str(path), fill=True)


def write_params(path, params: SectionParams, air: Air | None = None, *, comment: str = "", body=None,
                 coverage: dict | None = None) -> None:
    """Write ``params`` and its air (every field) atomically to ``path``.

    Reading the file back with :func:`read_params` gives the same record, its angles to
    within the degree-radian round trip (relative 2e-16).

    Parameters
    ----------
    path : str or Path
    params : AirfoilParams or CamberedParams
    air : Air, optional
        Default: the set's own (``params.air``).
    comment : str
        Written as the file's ``comment``.
    body : BodyTable, optional
        Airframe drag and centre of mass, written as the ``[body]`` table (:func:`read_body`
        reads it).
    coverage : dict, optional
        What the data behind a fitted set covered (keys of :data:`COVERAGE_KEYS`, and of
        :data:`COVERAGE_TEXT_KEYS`: the data's label and the groups fitted and held out),
        written as the ``[coverage]`` table: later uses of the file warn beyond it, and
        ``propmap validate`` labels its groups in-sample or held out. Default (None): a
        shipped set's own (``calibrated:<name>``, ``generic``, its folds; where ``params`` is
        that set by value: :func:`propmap.io.calibration.shipped_coverage`), or the table of
        the file the set was read from (its label), where that file still holds this set by
        value; so that the file warns as the set does. None for any other set (a fit's result:
        give its ``coverage``). ``{}`` writes none.

    Raises
    ------
    OSError
        The file cannot be written.
    TypeError
        ``params`` not a parameter set, ``air`` not an :class:`Air`, ``body`` not a
        ``BodyTable`` (:func:`read_body`'s), ``coverage`` not a dict (each named; they met
        AttributeErrors, a user-level audit, 2026-11-30), ``comment`` not a str, ``path``
        not a path.
    ValueError
        A file :func:`read_params` (:func:`read_body`) would refuse: a ``coverage`` or ``body``
        with an unknown key, a value out of its range or not finite, a list of texts given as
        one text, a centre of mass without 3 components; an ``air`` outside a file's ranges
        (module docstring); named; nothing is written.
    """
    path = as_path(path)  # (a path of 5 met a bare 'lstat' TypeError: an API audit, 2026-12-01)
    if not isinstance(comment, str):  # (123 was written, and read_params refused the file it made)
        raise TypeError(f"comment must be a str, got {type(comment).__name__}")
    if body is not None and not isinstance(body, BodyTable):
        raise TypeError(f"body must be a BodyTable (propmap.io.params_file.read_body) or None, got "
                        f"{type(body).__name__}")
    if coverage is not None and not isinstance(coverage, dict):
        raise TypeError(f"coverage must be a dict or None, got {type(coverage).__name__}")
    data = params_to_dict(params, air)
    if coverage is None:  # (calibrated:apce_8x6 written to a file lost its warnings beyond its data, stop 102)
        from .calibration import shipped_coverage

        coverage = shipped_coverage(params)
        if coverage is None:  # (a fitted file copied through the API lost its table, a review)
            coverage = _read_set_coverage(params)
    if comment:
        data["comment"] = comment
    if body is not None:
        data[BODY_TABLE] = {"drag_area": [float(v) for v in body.drag.drag_area],
                            "wash_factor": float(body.drag.wash_factor)}
        if body.centre_of_mass is not None:
            data[BODY_TABLE]["centre_of_mass"] = [float(v) for v in body.centre_of_mass]
        if body.rotor_interference is not None:
            data[BODY_TABLE]["rotor_interference"] = float(body.rotor_interference)
    if coverage:
        data[COVERAGE_TABLE] = _coverage_table(coverage)
    # the whole file checked as read_params reads it: a [body] centre of mass of 1.5 m (a vehicle file's, fit flight)
    # or NaN, a rotor_interference of 5, an air of 50 m/s sound speed were written, and every reader then refused
    # the file (an audit and a review, stop 102)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (what a reader warns of, it says when the file is read)
        params_from_dict(data, where=f"{show_path(path)} (not written)")
    with atomic_write(path, "wb") as fh:
        tomli_w.dump(data, fh)


def _read_set_coverage(params: SectionParams) -> dict | None:
    """The ``[coverage]`` of the parameter file ``params`` was read from (its label the file's
    path), where that file still holds this set by value (:meth:`SectionParams.same_section`:
    a path that names another file now, or a set changed since, gets None); None otherwise."""
    label = getattr(params, "label", "") or ""
    if not label or not os.path.isfile(label):
        return None
    try:
        path = as_path(label)
        with warnings.catch_warnings(), _reading(path) as data:  # (parsed once for the set and its table)
            warnings.simplefilter("ignore")  # (the file's warnings were said when it was read)
            own = params_from_dict(data, where=show_path(path), label=label, fill=True)
            return coverage_from_dict(data, where=show_path(path)) if own.same_section(params) else None
    except (ValueError, OSError):
        return None


def _coverage_table(coverage: dict) -> dict:
    """``write_params``' ``coverage`` as the file's ``[coverage]`` table, checked as
    :func:`read_params` reads it (params_tables.coverage_from_dict): an unknown key, a number
    out of range, a text list given as one text are refused here, naming the key (they were
    dropped, written so that the file could not be read back, or split into characters until
    2026-12-01: an API audit). Numbers are written to 12 digits, for every producer: 1975 rpm,
    not the 1974.9999999999998 of rad/s and back."""
    table = {}
    for k, v in coverage.items():
        if k in COVERAGE_TEXT_KEYS and k not in COVERAGE_SINGLE_TEXTS:
            if isinstance(v, (str, bytes)) or not hasattr(v, "__iter__"):
                raise ValueError(f"coverage: {k} must be a list of texts, got {v!r:.60}")
            table[k] = [str(x) for x in v]  # (a group label of 1, a Path: their text, as before)
        elif k in COVERAGE_SINGLE_TEXTS and isinstance(v, (str, os.PathLike)):
            table[k] = str(v)
        elif k in COVERAGE_KEYS and real(v) is not None:
            x = real(v)
            table[k] = int(x) if k == "n_blades" and x.is_integer() else float(f"{x:.12g}")
        else:
            table[k] = v  # (the reader's check below names what is wrong with it)
    coverage_from_dict({COVERAGE_TABLE: table}, where="coverage")
    return table


def read_body(path) -> BodyTable | None:
    """The ``[body]`` table (airframe drag, centre of mass) of a parameter file, or None.

    Parameters
    ----------
    path : str or Path
        A parameter file (module docstring); the whole file is checked, as
        :func:`read_params` does, with its warnings (an angle that looks like radians), but
        without filling missing keys.

    Returns
    -------
    BodyTable or None
        ``drag`` (a ``BodyDrag``: ``drag_area`` [m^2] along body x, y, z and
        ``wash_factor``, 0 where the table gives none), ``centre_of_mass`` [m], shape (3,),
        and ``rotor_interference``; None where the file has no ``[body]`` table.

    Raises
    ------
    ParamsFileError
        As :func:`read_params`.
    TypeError
        ``path`` not a str or os.PathLike.
    """
    path = as_path(path)
    with _reading(path) as data:
        params_from_dict(data, where=show_path(path))
        return body_from_dict(data, where=show_path(path))


_SECTIONS: dict | None = None


def _section_tables() -> dict:
    """The shipped section presets, file form (data/sections/presets.toml), read once."""
    global _SECTIONS
    if _SECTIONS is None:
        import tomllib
        from importlib.resources import files

        _SECTIONS = tomllib.loads(files("propmap").joinpath("data/sections/presets.toml").read_text("utf-8"))
    return _SECTIONS
