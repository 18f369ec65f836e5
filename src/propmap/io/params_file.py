"""Airfoil-parameter files (TOML) and parameter presets.

Format (SI except the stall angle, which carries its unit in the key)::

    cl1 = 5.3            # pre-stall lift slope [1/rad]
    cl2 = 1.7            # post-stall amplitude [-]
    cd = 1.8             # drag amplitude [-]
    alpha0_deg = 20.6    # stall angle [deg]
    # optional constants (footnote 2 defaults of Gill & D'Andrea 2017):
    M = 50.0             # sigmoid sharpness [1/rad]
    cd0 = 0.01           # form drag [-]
    cp_blasius = 1.328   # Blasius skin-friction constant [-]
    lift_model = "sigmoid"   # or "sincos" (footnote 1, uses cl2)
    rho = 1.225          # air density [kg/m^3]
    mu = 1.983e-5        # air viscosity [Pa s]
"""

from __future__ import annotations

import math
from pathlib import Path

import tomli_w

from ..core.airfoil import PRESETS, Air, AirfoilParams
from .atomic import atomic_write
from .toml_file import load_toml

__all__ = ["ParamsFileError", "read_params", "write_params", "resolve_params"]

REQUIRED = ("cl1", "cl2", "cd", "alpha0_deg")
OPTIONAL = ("M", "cd0", "cp_blasius", "lift_model", "rho", "mu")


class ParamsFileError(ValueError):
    """A parameter file is malformed; the message names the file and the key."""


def read_params(path) -> tuple[AirfoilParams, Air]:
    """Read a parameter file.

    Returns
    -------
    (AirfoilParams, Air)

    Raises
    ------
    ParamsFileError
        Unreadable TOML, a missing required key, an unknown key or an invalid value.
    """
    path = Path(path)
    data = load_toml(path, ParamsFileError)
    missing = [k for k in REQUIRED if k not in data]
    if missing:
        raise ParamsFileError(f"{path}: missing key(s) {', '.join(missing)} (required: {', '.join(REQUIRED)})")
    unknown = sorted(set(data) - set(REQUIRED) - set(OPTIONAL) - {"comment", "source"})
    if unknown:
        raise ParamsFileError(f"{path}: unknown key(s) {', '.join(unknown)}")
    try:
        kw = {k: data[k] for k in ("cl1", "cl2", "cd", "M", "cd0", "cp_blasius", "lift_model") if k in data}
        params = AirfoilParams(alpha0=math.radians(float(data["alpha0_deg"])), **kw)
        air = Air(**{k: data[k] for k in ("rho", "mu") if k in data})
    except (TypeError, ValueError) as exc:
        raise ParamsFileError(f"{path}: {exc}") from None
    return params, air


def write_params(path, params: AirfoilParams, air: Air = Air(), *, comment: str = "") -> None:
    """Write ``params`` and ``air`` (all constants included) atomically to ``path``.

    Reading the file back with :func:`read_params` gives equal objects.
    """
    data = {
        "cl1": params.cl1, "cl2": params.cl2, "cd": params.cd,
        "alpha0_deg": math.degrees(params.alpha0),
        "M": params.M, "cd0": params.cd0, "cp_blasius": params.cp_blasius,
        "lift_model": params.lift_model, "rho": air.rho, "mu": air.mu,
    }
    if comment:
        data["comment"] = comment
    with atomic_write(path, "wb") as fh:
        tomli_w.dump(data, fh)


def resolve_params(spec: str) -> tuple[AirfoilParams, Air]:
    """A preset name (``gill2017-apc``, ...) or a parameter file path.

    Raises
    ------
    KeyError
        Neither a preset nor an existing file.
    ParamsFileError
        Malformed file.
    """
    if spec in PRESETS:
        return PRESETS[spec], Air()
    if Path(spec).is_file():
        return read_params(spec)
    raise KeyError(f"unknown parameters {spec!r}: not a preset ({', '.join(PRESETS)}) nor an existing file")
