"""Section-parameter files (TOML) and named parameter sets.

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

The cambered polar (``section_model = "cambered"``); every key is optional and defaults to
the ``CamberedParams`` default, so a file normally lists them all (``write_params`` does)::

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

Either model also takes ``rho``, ``mu`` and ``speed_of_sound`` (the air) and the free
text keys ``comment`` and ``source``.
"""

from __future__ import annotations

import math
from dataclasses import fields
from pathlib import Path

import tomli_w

from ..core.airfoil import PRESETS, Air, AirfoilParams, CamberedParams, SectionParams
from .atomic import atomic_write
from .toml_file import load_toml

__all__ = ["ParamsFileError", "read_params", "write_params", "resolve_params", "params_to_dict",
           "params_from_dict", "named_sets", "SECTION_MODELS"]

SECTION_MODELS = ("gill2017", "cambered")
REQUIRED = {"gill2017": ("cl1", "cl2", "cd", "alpha0_deg"), "cambered": ()}
AIR_KEYS = ("rho", "mu", "speed_of_sound")
TEXT_KEYS = ("comment", "source", "section_model")
#: keys holding an angle in degrees in files, and the field they set [rad]
DEG_KEYS = {"alpha0_deg": "alpha0", "alpha_L0_deg": "alpha_L0", "alpha_L0_re_deg": "alpha_L0_re"}


class ParamsFileError(ValueError):
    """A parameter file is malformed; the message names the file and the key."""


def _record(model: str):
    return AirfoilParams if model == "gill2017" else CamberedParams


def _file_keys(model: str) -> dict[str, str]:
    """file key -> field name of the model's record (angles with ``_deg``)."""
    deg = {v: k for k, v in DEG_KEYS.items()}
    return {deg.get(f.name, f.name): f.name for f in fields(_record(model))}


def params_from_dict(data: dict, *, where: str = "parameters") -> tuple[SectionParams, Air]:
    """Build (params, air) from a file-form dict (angles in degrees, ``section_model`` key).

    Raises
    ------
    ValueError
        Unknown ``section_model``, a missing required key, an unknown key, a value of the
        wrong type or out of range; the message starts with ``where``.
    """
    model = data.get("section_model", "gill2017")
    if model not in SECTION_MODELS:
        raise ValueError(f"{where}: section_model must be one of {', '.join(SECTION_MODELS)}, got {model!r}")
    missing = [k for k in REQUIRED[model] if k not in data]
    if missing:
        raise ValueError(f"{where}: missing key(s) {', '.join(missing)} (required for section_model "
                         f"{model!r}: {', '.join(REQUIRED[model])})")
    keys = _file_keys(model)
    unknown = sorted(set(data) - set(keys) - set(AIR_KEYS) - set(TEXT_KEYS))
    if unknown:
        raise ValueError(f"{where}: unknown key(s) {', '.join(unknown)} for section_model {model!r}")
    kw = {}
    for key, name in keys.items():
        if key not in data:
            continue
        value = data[key]
        if key in DEG_KEYS:
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise ValueError(f"{where}: {key} must be a number, got {value!r}")
            try:
                value = math.radians(value)
            except OverflowError:
                raise ValueError(f"{where}: {key} must be a finite number, got {data[key]!r}") from None
        kw[name] = value
    try:
        params = _record(model)(**kw)
        air = Air(**{k: data[k] for k in AIR_KEYS if k in data})
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{where}: {exc}") from None
    return params, air


def params_to_dict(params: SectionParams, air: Air = Air()) -> dict:
    """The file form of ``params`` and ``air``: every field, angles in degrees.

    ``params_from_dict(params_to_dict(p, air))`` gives back equal records (angles to
    the last bit of a degree-radian round trip).
    """
    data = {"section_model": params.section_model}
    keys = _file_keys(params.section_model)
    for key, name in keys.items():
        value = getattr(params, name)
        data[key] = math.degrees(value) if key in DEG_KEYS else value
    data.update({k: getattr(air, k) for k in AIR_KEYS})
    return data


def read_params(path) -> tuple[SectionParams, Air]:
    """Read a parameter file (either section model; format in the module docstring).

    Returns
    -------
    (AirfoilParams or CamberedParams, Air)

    Raises
    ------
    ParamsFileError
        Unreadable or invalid TOML, a missing required key, an unknown key, a value of the
        wrong type (a quoted number, a bool for a number) or out of range; the message
        names the file.
    """
    path = Path(path)
    data = load_toml(path, ParamsFileError)
    try:
        return params_from_dict(data, where=str(path))
    except ValueError as exc:
        raise ParamsFileError(str(exc)) from None


def write_params(path, params: SectionParams, air: Air = Air(), *, comment: str = "") -> None:
    """Write ``params`` and ``air`` (every field) atomically to ``path``.

    Reading the file back with :func:`read_params` gives equal records.
    """
    data = params_to_dict(params, air)
    if comment:
        data["comment"] = comment
    with atomic_write(path, "wb") as fh:
        tomli_w.dump(data, fh)


def named_sets() -> tuple[str, ...]:
    """Names :func:`resolve_params` accepts besides files."""
    return (*PRESETS, "generic", "calibrated:<catalogue name>")


def resolve_params(spec: str) -> tuple[SectionParams, Air]:
    """A named parameter set or a parameter file path.

    Named sets: the paper's Table I (``gill2017-soft``, ``gill2017-stiff``,
    ``gill2017-apc``), the catalogue-fitted ``generic`` cambered set, and
    ``calibrated:<name>``, a catalogue propeller's own calibrated set.

    Raises
    ------
    KeyError
        Neither a named set nor an existing file.
    ParamsFileError
        Malformed file.
    """
    from . import calibration

    if spec in PRESETS:
        return PRESETS[spec], Air()
    if spec == calibration.GENERIC:
        g = calibration.calibration()["generic"]
        return g.params, g.air
    if spec.startswith("calibrated:"):
        c = calibration.calibrated(spec.split(":", 1)[1])
        if c is None:
            raise KeyError(f"unknown parameters {spec!r}: {spec.split(':', 1)[1]!r} has no calibrated set "
                           "('propmap props' lists the calibrated propellers)")
        return c.params, c.air
    if Path(spec).is_file():
        return read_params(spec)
    raise KeyError(f"unknown parameters {spec!r}: not a named set ({', '.join(named_sets())}) nor an existing file")
