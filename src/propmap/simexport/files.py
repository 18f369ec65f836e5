"""Simulator coefficient files: each target's own format, and the JSON report beside it."""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path

import numpy as np

from ..core.air import air_words
from ..core.units import RPM
from .. import __version__
from ..io.atomic import atomic_paths, check_file_name, file_sha256
from ..io.inputs import as_path
from ..vehicle.layout import check_vehicle
from .fit import LOADS, SimExport
from .forms import EVEN_TERMS, GAZEBO_AXIAL_SPEED, ODD_TERMS

__all__ = ["check_rotorpy_vehicle", "error_lines", "report_path", "rotorpy_directions", "write_export"]


def report_path(path) -> Path:
    """The report written beside an export: ``<stem>.report.json`` (``c.json`` gets
    ``c.report.json``, not ``c.json.json``; the fit commands' convention).

    Parameters
    ----------
    path : str or Path
        The export file.

    Returns
    -------
    Path

    Raises
    ------
    ValueError
        An empty ``path`` or one that names no file (``"."``, a trailing separator: pathlib's "has
        an empty name", or ``dir/`` read as ``dir.report.json``, until stop 104).
    TypeError
        ``path`` not a str or os.PathLike.
    """
    check_file_name(path)  # (the path as given: a Path drops a trailing separator)
    path = as_path(path)
    return path.with_name(path.stem + ".report.json")


def _pct(value: float) -> str:
    """A fraction as a percentage; n/a for NaN (no point to measure it on)."""
    return "n/a" if math.isnan(value) else f"{value:.2%}"


def _text(value) -> str:
    """Free text (a label, a propeller name) made safe inside the written files' comments: one
    line (a newline would end a Python comment and run the rest as code), no "--" (which ends
    an XML comment early, "-->")."""
    text = re.sub(r"[\x00-\x1f\x7f\x85\u2028\u2029]", " ", str(value))
    while "--" in text:
        text = text.replace("--", "- -")
    return text


def error_lines(res: SimExport, comment: str = "") -> list[str]:
    """The error table and the model's uncertainty as text lines, each starting with
    ``comment`` (and a space); the label in them is made one-line (:func:`_text`).

    Parameters
    ----------
    res : SimExport
    comment : str
        The comment marker of the file the lines go into ("#" for Python, "" for SDF).

    Returns
    -------
    list of str
    """
    e, env = res.errors, res.envelope
    h = e["hover"]
    lines = [f"{comment} hover pinned at {h['rpm']:.6g} rpm: thrust {h['thrust']:.6g} N (error "
             f"{_pct(h['thrust_error'])}), torque {h['torque']:.6g} N m (error {_pct(h['torque_error'])}); static "
             f"thrust and torque within {_pct(e['static']['thrust_max'])} and {_pct(e['static']['torque_max'])} "
             f"over rpm {env.rpm[0]:g}-{env.rpm[1]:g}",
             f"{comment} error against the full model over the envelope (rpm {env.rpm[0]:g}-{env.rpm[1]:g}, "
             f"V {env.airspeed[0]:g}-{env.airspeed[1]:g} m/s, incidence {env.incidence_deg[0]:g}-"
             f"{env.incidence_deg[1]:g} deg), on {res.meta.get('check_points', res.n_points)} check points other "
             f"than the {res.n_points} fitted ({e['points_flagged']} flagged):"]
    fitted = e.get("fitted_points", {})
    for k in LOADS:
        on_fit = (f"; fitted points: rms {_pct(fitted[k]['rms'])}, max {_pct(fitted[k]['max'])}" if k in fitted
                  else "")
        lines.append(f"{comment}   {k:<15} rms {_pct(e[k]['rms']):>7}  max {_pct(e[k]['max']):>7}  "
                     f"(flagged: rms {_pct(e[k]['rms_flagged'])}, max {_pct(e[k]['max_flagged'])}{on_fit})")
    lines.append(f"{comment} normalised: {e['normalisation']}")
    for name, why in res.fixed.items():
        lines.append(f"{comment} {name} fixed at 0: {why}")
    for name, why in res.held.items():
        lines.append(f"{comment} {name} {why}")
    u = res.meta.get("model_uncertainty")
    if u:  # the model's own error against measurements, beside the simple model's against it
        lines.append(f"{comment} the model against measurements ({_text(u['params'])}): axial: {u['axial']}")
        lines.append(f"{comment}   off-axis: {u['off_axis']}")
        t = u.get("edgewise_trend")
        if t and not math.isnan(t["this_set"]):
            lines.append(f"{comment}   thrust change from hover to {t['airspeed']:g} m/s edgewise at "
                         f"{t['rpm']:.0f} rpm: "
                         f"{t['this_set']:+.1%} with this set, {t['generic']:+.1%} with the generic set")
    return lines


def rotorpy_directions(spins) -> list[int]:
    """RotorPy's ``rotor_directions`` for propmap spins.

    RotorPy's yaw moment on the body is ``rotor_directions[i] k_m Omega_i^2`` about +z
    (``Multirotor.compute_body_wrench``), the reaction to the rotor's rotation: a rotor
    spinning ccw about +z (propmap spin "ccw", +1) gives -1 there, a cw one +1.

    Parameters
    ----------
    spins : sequence of {"ccw", "cw", +1, -1}

    Returns
    -------
    list of int

    Raises
    ------
    ValueError
        A spin that is none of those; ``spins`` one str (its letters were read as spins) or not
        a sequence.
    """
    if isinstance(spins, (str, bytes)) or not hasattr(spins, "__iter__"):  # ("ccw": spins[0] 'c', stop 104)
        raise ValueError(f"spins must be a sequence of spins, one per rotor, got {spins!r:.40}")
    out = []
    for k, s in enumerate(spins):
        sign = {"ccw": 1, "cw": -1}.get(s, s) if isinstance(s, str) else s
        if isinstance(sign, bool) or sign not in (1, -1):
            raise ValueError(f"spins[{k}] must be 'ccw', 'cw', +1 or -1, got {s!r:.40}")
        out.append(-int(sign))
    return out


def _air_words(meta: dict) -> str:
    """The air an export was fitted in, for its file's head (the coefficients scale with the density:
    the file named its set only, whose own air another was used instead of with --rho, an
    air-consistency audit, 2026-12-01)."""
    if "rho" not in meta:
        return ""
    return " in air of " + air_words(meta["rho"], meta.get("mu"), meta.get("speed_of_sound"))


def _rotorpy_text(res: SimExport, head: str, vehicle, vehicle_label: str, airframe_label: str = "") -> str:
    c = res.coefficients
    rotor = [f"    'k_eta': {c['k_eta']!r},  # thrust coefficient N/(rad/s)**2",
             f"    'k_m': {c['k_m']!r},  # yaw moment coefficient Nm/(rad/s)**2",
             f"    'k_d': {c['k_d']!r},  # rotor drag coefficient N/(rad*m/s**2) = kg/rad",
             f"    'k_z': {c['k_z']!r},  # induced inflow coefficient N/(rad*m/s**2) = kg/rad",
             f"    'k_h': {c['k_h']!r},  # translational lift coefficient N/(m/s)**2",
             f"    'k_flap': {c['k_flap']!r},  # flapping moment coefficient Nm/(rad*m/s**2)",
             f"    'rotor_radius': {c['rotor_radius']!r},  # m"]
    lines = [f"# {head}", *error_lines(res, "#"),
             "# RotorPy (release 3.0.0, rotorpy/vehicles/multirotor.py): T = k_eta w^2 + k_h V_ip^2 - k_z w V_z,",
             "# H = -w k_d V_ip, yaw moment rotor_directions k_m w^2 about +z. k_flap = 0: the rigid-blade model",
             "# has no moment about z x e_ip; its rolling moment about e_ip has no RotorPy term (its error above).",
             "# rotor_directions: -1 for a rotor spinning ccw about its (upward) thrust axis, seen from above",
             "# (propmap spin 'ccw'), +1 for cw: the sign of its reaction torque on the body about +z.",
             "import numpy as np", "", "rotor_params = {", *rotor, "}"]
    if vehicle is not None:
        lines += _quad_params(res, vehicle, vehicle_label, airframe_label)
    return "\n".join(lines) + "\n"


def _quad_params(res: SimExport, vehicle, label: str, airframe_label: str = "") -> list[str]:
    """A complete RotorPy ``quad_params`` for ``vehicle`` (checked by :func:`check_rotorpy_vehicle`)."""
    inertia = np.asarray(vehicle.inertia, float).tolist()  # Python floats: their repr is plain
    rho = float(res.meta["rho"])
    drag = vehicle.body_drag.drag_area if vehicle.body_drag is not None else (0.0, 0.0, 0.0)
    from ..vehicle import rotor_geometry

    arms, _, spins, _ = rotor_geometry(vehicle)
    positions = arms.tolist()  # Python floats: their repr is plain
    directions = rotorpy_directions([int(s) for s in spins])
    tau = vehicle.motor_time_constant
    rpm_max = res.envelope.rpm[1]
    out = ["", "# " + _text(f"quad_params for RotorPy's Multirotor: {vehicle.name or 'vehicle'} "
                            f"({Path(label).name or 'vehicle file'})."),
           "# Body axes x forward, y left, z up (RotorPy's and propmap's); rotor positions from the centre of mass; "
           "parasitic drag",
           "# " + _text(f"c_D = rho (C_D A) / 2 from the drag areas of {airframe_label or 'the vehicle file'}"),
           f"# at rho = {rho!r} kg/m^3 (the slipstream",
           "# factor has no RotorPy term).",
           "quad_params = {",
           f"    'mass': {float(vehicle.mass)!r},  # kg",
           f"    'Ixx': {inertia[0][0]!r}, 'Iyy': {inertia[1][1]!r}, 'Izz': {inertia[2][2]!r},  # kg m^2",
           f"    'Ixy': {inertia[0][1]!r}, 'Iyz': {inertia[1][2]!r}, 'Ixz': {inertia[0][2]!r},  # kg m^2",
           f"    'num_rotors': {len(vehicle.rotors)},",
           f"    'rotor_radius': {res.coefficients['rotor_radius']!r},  # m",
           "    'rotor_pos': {"]
    out += [f"        'r{k + 1}': np.array([{p[0]!r}, {p[1]!r}, {p[2]!r}]),  # m" for k, p in enumerate(positions)]
    out += ["    },",
            f"    'rotor_directions': np.array({directions!r}),",
            "    'rI': np.array([0.0, 0.0, 0.0]),  # IMU at the centre of mass",
            *(f"    'c_D{ax}': {0.5 * rho * float(a)!r},  # N/(m/s)**2" for ax, a in zip("xyz", drag)),
            "    **rotor_params,",
            (f"    'tau_m': {float(tau)!r},  # s, the vehicle file's motor time constant" if tau > 0 else
             "    'tau_m': 0.005,  # s: NOT in the vehicle file (motor_time_constant = 0); RotorPy needs one > 0, "
             "set yours"),
            "    'rotor_speed_min': 0.0,  # rad/s",
            f"    'rotor_speed_max': {rpm_max * RPM!r},  # rad/s, the envelope's highest rpm, not your motors': "
            "RotorPy saturates there (set theirs; --envelope rpm=LOW:HIGH fits up to it)",
            "    'motor_noise_std': 0.0,  # rad/s",
            "}"]
    return out


def check_rotorpy_vehicle(vehicle) -> None:
    """Whether RotorPy's Multirotor can represent ``vehicle``.

    Parameters
    ----------
    vehicle : Vehicle

    Returns
    -------
    None

    Raises
    ------
    ValueError
        Not 4 rotors (RotorPy's Multirotor inverts a 4 x n control allocation matrix: a
        quadrotor's), no inertia tensor in the vehicle file, or a rotor whose axis is not
        body +z (RotorPy assumes every rotor thrusts along +z).
    TypeError
        ``vehicle`` not a :class:`propmap.Vehicle`.
    """
    check_vehicle(vehicle)  # (None met an AttributeError, a docstring-contract audit)
    if len(vehicle.rotors) != 4:
        raise ValueError(f"the vehicle has {len(vehicle.rotors)} rotors: RotorPy's Multirotor (3.0) inverts a 4 x n "
                         "control allocation matrix, so its quad_params must describe 4 rotors (gz-sim and "
                         "gazebo-classic take any number)")
    if vehicle.inertia is None:
        raise ValueError("the vehicle file has no inertia: RotorPy's quad_params needs Ixx, Iyy, Izz (the vehicle "
                         "file's key inertia = [Ixx, Iyy, Izz] or a 3 x 3 list, kg m^2)")
    for k, r in enumerate(vehicle.rotors):
        if not np.allclose(np.asarray(r.axis, float), (0.0, 0.0, 1.0), atol=1e-9):
            axis = ", ".join(f"{float(a):.6g}" for a in r.axis)
            raise ValueError(f"rotor {k + 1}'s axis [{axis}] is not body +z: RotorPy's Multirotor assumes every rotor "
                             "thrusts along +z")


def _gazebo_text(res: SimExport, head: str) -> str:
    c = res.coefficients
    if res.target == "gazebo-classic":
        notes = [f"  PX4-SITL_gazebo-classic's gazebo_motor_model: thrust fades with axial speed as 1 - |V_z| / "
                 f"{GAZEBO_AXIAL_SPEED:g} m/s",
                 "  (not a parameter); the drag torque, momentConstant times the unfaded thrust, does not fade.",
                 "  The rolling moment is signed by turning_direction (since the plugin's PR #809, 2021): the same",
                 "  rollingMomentCoefficient is right for both turning directions.",
                 "  Paste these elements into each rotor's gazebo_motor_model plugin."]
        elements = [f"<rollingMomentCoefficient>{c['rollingMomentCoefficient']!r}</rollingMomentCoefficient>"]
    else:
        notes = ["  gz-sim's MulticopterMotorModel: no axial fade of the thrust; the drag torque is momentConstant",
                 "  times the thrust. Its rolling moment is NOT signed by turningDirection: the value below is right",
                 "  for a ccw rotor (<turningDirection>ccw</turningDirection>); give a cw rotor its negative,",
                 f"  {-c['rollingMomentCoefficient']!r}.",
                 "  Paste these elements into each rotor's MulticopterMotorModel system."]
        elements = [f"<!-- ccw rotors; cw rotors: <rollingMomentCoefficient>{-c['rollingMomentCoefficient']!r}"
                    "</rollingMomentCoefficient> -->",
                    f"<rollingMomentCoefficient>{c['rollingMomentCoefficient']!r}</rollingMomentCoefficient>"]
    lines = ["<!--", f"  {head}", *(" " + ln for ln in error_lines(res, "")), *notes, "-->",
             f"<motorConstant>{c['motorConstant']!r}</motorConstant>",
             f"<momentConstant>{c['momentConstant']!r}</momentConstant>",
             f"<rotorDragCoefficient>{c['rotorDragCoefficient']!r}</rotorDragCoefficient>", *elements]
    return "\n".join(lines) + "\n"


#: the multinomial file's sign conventions (docs/conventions.md), written into it
MULTINOMIAL_CONVENTIONS = {
    "beta": "the angle between the rotor axis (thrust direction) and the hub's velocity through the air: 0 axial "
            "climb, 90 deg edgewise, 180 deg axial descent",
    "lambda_c": "positive in climb (the air comes from ahead of the disk along the axis)",
    "T": "along the rotor axis, positive in the thrust direction",
    "H": "in the disk plane, positive against the in-plane motion (force T z - H e_ip, e_ip the in-plane velocity's "
         "direction)",
    "Q": "about the axis, positive opposing the rotation (what the motor supplies)",
    "M_R": "about e_ip, positive with more thrust on the advancing side; moment vector -spin (Q z + M_R e_ip), "
           "spin +1 for a rotation about +z",
}


def write_export(res: SimExport, path, *, vehicle=None, vehicle_label: str = "",
                 airframe_label: str = "") -> list[Path]:
    """Write the coefficients in the target's own format (atomically), and a JSON report
    ``<stem>.report.json`` with the coefficients, the envelope and the errors.

    rotorpy: a Python file defining ``rotor_params`` (keys of RotorPy's ``quad_params``)
    and, with ``vehicle``, a complete ``quad_params``; gazebo-classic and gz-sim: an SDF
    fragment of the plugin's coefficient elements; multinomial: JSON.

    The two are written as a pair (io.atomic.atomic_paths); the report records the
    file's SHA-256 (``describes``), the coefficients fixed at 0 (``fixed_at_zero``) and
    those held at 0 by their physical sign (``held_at_sign_bound``).

    Parameters
    ----------
    res : SimExport
    path : path-like
    vehicle : Vehicle, optional
        rotorpy only: write ``quad_params`` for it (:func:`check_rotorpy_vehicle`).
    vehicle_label : str
        Where the vehicle came from, for the file's comment; a file it names is never
        overwritten (nor one ``airframe_label`` names).
    airframe_label : str
        Where the vehicle's airframe drag areas came from where not its file (a flight fit's
        parameter file with a ``[body]`` table), for the comment on RotorPy's c_D.

    Returns
    -------
    list of Path
        ``[path, report]``: the coefficient file and its report (:func:`report_path`).

    Raises
    ------
    ValueError
        ``vehicle`` with another target, or one RotorPy cannot represent; an empty ``path``, one
        named ``*.report.json`` (an export's report: it would replace another export's), or the
        file ``vehicle_label`` or ``airframe_label`` names (an input).
    TypeError
        ``res`` not a :class:`SimExport`; ``vehicle`` given and not a :class:`propmap.Vehicle`;
        ``path`` not a str or os.PathLike; a label neither text nor a path.
    OSError
        The files cannot be written.
    """
    if vehicle is not None:
        check_vehicle(vehicle)
    if not isinstance(res, SimExport):
        raise TypeError(f"res must be a SimExport (propmap.export_sim), got {type(res).__name__}")
    check_file_name(path)
    path = as_path(path)
    labels = [vehicle_label, airframe_label]
    if not all(isinstance(x, (str, os.PathLike)) for x in labels):  # ({} met pathlib's TypeError)
        raise TypeError(f"vehicle_label and airframe_label must be text or a path, got {type(vehicle_label).__name__} "
                        f"and {type(airframe_label).__name__}")
    vehicle_label, airframe_label = (os.fspath(x) for x in labels)
    for label in (vehicle_label, airframe_label):  # (the API overwrote the vehicle file it was given, stop 104)
        for out in (path, report_path(path)):  # (os.path.isfile: False for free text too long for a file name)
            if label and os.path.isfile(label) and out.exists() and out.samefile(label):
                raise ValueError(f"path: {out} is {label}, the file the vehicle or airframe came from: an input is "
                                 "never overwritten; name the export otherwise")
    if path.name.lower().endswith(".report.json"):
        raise ValueError(f"path: {path.name}: a name ending in .report.json is an export's report (written beside its "
                         "coefficient file); name the coefficient file otherwise")
    head = _text(f"propmap {__version__} (source sha256 {res.meta.get('propmap_source_sha256', 'not recorded')}): "
                 f"{res.target} coefficients of {res.meta.get('propeller')} ({res.meta.get('params')}), fitted to the "
                 "full model" + _air_words(res.meta) + (f"; data: {res.meta['citation']}" if res.meta.get("citation")
                                                        else ""))
    if vehicle is not None:
        if res.target != "rotorpy":
            raise ValueError(f"vehicle: a vehicle block is written for the rotorpy target only, not {res.target}")
        check_rotorpy_vehicle(vehicle)
    if res.target == "rotorpy":
        text = _rotorpy_text(res, head, vehicle, vehicle_label, airframe_label)
    elif res.target in ("gazebo-classic", "gz-sim"):
        text = _gazebo_text(res, head)
    else:
        # (the signs and the source were in the report and the docs only: a simulator-user audit, 2026-11-30)
        text = json.dumps({"model": "multinomial in mu = V sin(beta)/(Omega R), lambda_c = V cos(beta)/(Omega R)",
                           "terms_even": list(EVEN_TERMS), "terms_odd": list(ODD_TERMS),
                           "normalisation": "T, H = rho pi R^2 (Omega R)^2 C; Q, M_R = rho pi R^3 (Omega R)^2 C",
                           "conventions": MULTINOMIAL_CONVENTIONS,
                           "propeller": res.meta.get("propeller"), "params": res.meta.get("params"),
                           **res.coefficients, "fixed_at_zero": res.fixed}, indent=2) + "\n"
    from ..io.mapfile import _json_safe

    report = report_path(path)
    # the file and its report as a pair; the report names the file's SHA-256
    with atomic_paths([path, report]) as (tmp, tmp_report):
        tmp.write_text(text, encoding="utf-8")
        tmp_report.write_text(json.dumps(_json_safe({
            "target": res.target, "coefficients": res.coefficients, "fixed_at_zero": res.fixed,
            "held_at_sign_bound": res.held, "errors": res.errors,
            "envelope": {"rpm": list(res.envelope.rpm), "airspeed": list(res.envelope.airspeed),
                         "incidence_deg": list(res.envelope.incidence_deg), "hover_rpm": res.envelope.hover},
            "n_points": res.n_points, **res.meta, "describes": {"file": path.name, "sha256": file_sha256(tmp)}}),
            indent=2, allow_nan=False), encoding="utf-8")
    return [path, report]
