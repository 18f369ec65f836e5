"""C export of a rotor map: one self-contained C99 header (``propmap map --format c``).

The header holds the grid and the table as static const data (float or double) and one
function that evaluates T, D, Q and M_R from (Omega, V, beta) exactly as
:meth:`propmap.maps.RotorMap.loads` does (bisection on each axis, cubic or multilinear
interpolation of the loads divided by (Omega R)^2 + V^2, multiplied back), with the same
out-of-grid policies; no allocation, no global state, only <math.h> (for NAN).
"""

from __future__ import annotations

import hashlib
import os
import re
import textwrap
from dataclasses import replace
from pathlib import Path

import numpy as np

from .core.air import air_words
from .core.units import RPM
from .io.catalogue import catalogue_source
from .io.inputs import as_path
from ._c_templates import CUBIC_BODY, CUBIC_DECL, CUBIC_WEIGHTS, LINEAR_BODY, LINEAR_DECL, TEMPLATE, VEHICLE

__all__ = ["c_header_text", "c_prefix", "write_c_header"]


# the cubic Hermite weights of core/_interp.py (_cubic_weights), nodes i-1 .. i+2 clamped; the
# node slopes' coefficients of each cell (da: at its left node, db: at its right node, on the
# nodes i-1 .. i+2) are precomputed per axis (_slopes), so a call does no division but t's


def _inverse_step(ax: np.ndarray) -> str:
    """1 / the step of a uniform axis (steps equal to 1e-9 relative), or -1 / log of the
    ratio of a geometric one (positive nodes, ratios equal to 1e-9 relative), as C text;
    "0.0" for another, whose cells the header finds by bisection."""
    d = np.diff(ax)
    if d.size and np.all(np.abs(d - d.mean()) <= 1e-9 * d.mean()):
        return repr(float(1.0 / d.mean()))
    if d.size and ax[0] > 0:
        lr = np.diff(np.log(ax))
        if np.all(np.abs(lr - lr.mean()) <= 1e-9 * lr.mean()):
            return repr(float(-1.0 / lr.mean()))
    return "0.0"


def _slopes(ax: np.ndarray) -> np.ndarray:
    """Per cell i of an axis (n >= 3 nodes), the coefficients on the nodes i-1 .. i+2 of the
    node slopes at its left (4) and right (4) node: the three-point parabola's derivative,
    one-sided at the ends (core/_interp.py, _cubic_weights), shape (n - 1, 8). An axis of 2
    nodes is linear: zeros."""
    n = ax.size
    out = np.zeros((max(n - 1, 1), 8))
    if n < 3:
        return out
    for i in range(n - 1):
        h = ax[i + 1] - ax[i]
        da, db = out[i, :4], out[i, 4:]
        if i == 0:
            g = ax[2] - ax[1]
            c = h / (h + g)
            da[1], da[2], da[3] = -(1.0 + c) / h, (1.0 + c) / h + c / g, -c / g
        else:
            g = ax[i] - ax[i - 1]
            q = g + h
            da[0], da[1], da[2] = -h / (g * q), (h / g - g / h) / q, g / (h * q)
        if i + 1 == n - 1:
            g = ax[i] - ax[i - 1]
            c = h / (g + h)
            db[0], db[1], db[2] = c / g, -(1.0 + c) / h - c / g, (1.0 + c) / h
        else:
            g = ax[i + 2] - ax[i + 1]
            q = h + g
            db[1], db[2], db[3] = -g / (h * q), (g / h - h / g) / q, h / (g * q)
    return out


def _numbers(values, fmt: str, per_line: int = 6) -> str:
    items = [format(float(v), fmt) for v in values]
    return ",\n".join("    " + ", ".join(items[i:i + per_line]) for i in range(0, len(items), per_line))


#: the names the header defines after its prefix: functions and tables (prefix as given),
#: macros (prefix in upper case); the include guard adds _H_<hash>
_C_NAMES = ("loads", "locate", "weights", "omega", "airspeed", "incidence", "table", "cellflag", "wrench",
            "slope0", "slope1", "slope2",
            "vehicle_wrench", "rotor_pos", "rotor_axis", "rotor_spin", "rotor_h", "body_cd")
_C_MACROS = ("CLIP", "NAN", "ERROR", "N0", "N1", "N2", "RADIUS", "T", "H", "NROT", "U0", "U1", "U2")
#: names the C standard reserves (C11 7.1.3 and the future library directions 7.31, C23
#: 7.33): any identifier of file scope beginning with an underscore, and the macro
#: namespaces of the headers (the header includes <math.h>, whose FP_NAN a prefix ``fp``
#: would redefine). (pattern, what reserves it). The function and table names are static
#: (internal linkage), so the external-linkage reservations (is..., str...) do not apply.
_C_RESERVED = (
    (r"_.*", "C for identifiers of file scope beginning with an underscore"),
    (r"E[0-9A-Z].*", "<errno.h> (E followed by a digit or an uppercase letter)"),
    (r"FP_[A-Z].*", "<math.h> (FP_ followed by an uppercase letter: FP_NAN, FP_ZERO, ...)"),
    (r"FE_[A-Z].*", "<fenv.h> (FE_ followed by an uppercase letter)"),
    (r"LC_[A-Z].*", "<locale.h> (LC_ followed by an uppercase letter)"),
    (r"SIG_?[A-Z].*", "<signal.h> (SIG or SIG_ followed by an uppercase letter)"),
    (r"(PRI|SCN)[a-zX].*", "<inttypes.h> (PRI or SCN followed by a lowercase letter or X)"),
    (r"(ATOMIC|TIME)_[A-Z].*", "<stdatomic.h> and <time.h> (ATOMIC_ or TIME_ followed by an uppercase letter)"),
    (r"(DBL|FLT|LDBL)_[A-Z].*", "<float.h> (DBL_, FLT_ or LDBL_ followed by an uppercase letter)"),
)


def _pct(value) -> str:
    """A checked error as a percentage, or ``n/a`` where there was no point to measure it."""
    x = float(np.nan if value is None else value)
    return f"{x:.3%}" if np.isfinite(x) else "n/a"


def _reserved(identifier: str) -> str | None:
    """What reserves ``identifier`` in C (or POSIX <math.h>), or None."""
    for pattern, why in _C_RESERVED:
        if re.fullmatch(pattern, identifier):
            return why
    return None


def c_prefix(path, name: str | None = None) -> str:
    """The C identifier prefix of a header: ``name``, or ``pm_<file stem>`` (lower case; runs of
    underscores made one and none at the end, ``pm`` for a stem with no letter or digit).

    Parameters
    ----------
    path : str or Path
        The header file; only its stem is used, and only when ``name`` is None (its
        non-word characters become underscores).
    name : str, optional
        The prefix as given (its case kept); default ``pm_<stem>``.

    Returns
    -------
    str
        The checked prefix: ``name``, or ``"pm_"`` followed by the lower-cased stem.

    Raises
    ------
    ValueError
        ``name`` empty or not a string; the prefix is not a C identifier (ASCII letters,
        digits, underscores); or a name the header would define with it
        (``<prefix>_loads``, ``<PREFIX>_NAN``, ...) is reserved to the C library
        (``fp`` gives ``FP_NAN``, <math.h>'s; ``_x`` a file-scope name with an
        underscore) or to C++ (a double underscore: ``a__b``, or a prefix ending in ``_``):
        the message names them and the rule.
    TypeError
        ``path`` not a str or os.PathLike (where ``name`` is None).
    """
    if name is not None and not isinstance(name, str):
        raise ValueError(f"the C name prefix must be a string, got {name!r:.60}")
    if name == "":
        raise ValueError("the C name prefix is empty")
    if name is None:  # (runs of underscores made one, and none at the end: "pm__h" of ".h" is C++'s)
        stem = re.sub(r"_+", "_", re.sub(r"\W", "_", as_path(path).stem)).strip("_").lower()
        prefix = "pm_" + stem if stem else "pm"
    else:
        prefix = name
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", prefix):
        raise ValueError(f"the C name prefix must be a C identifier (ASCII letters, digits, underscores), "
                         f"got {prefix!r:.80}")
    defined = [f"{prefix}_{n}" for n in _C_NAMES] + [f"{prefix.upper()}_{m}" for m in _C_MACROS]
    if "__" in defined[0]:  # (the header is valid C++11 too, where every name with "__" is reserved: an audit)
        raise ValueError(f"the C name prefix {prefix!r} would define {defined[0]}: C++ reserves every identifier "
                         "that contains a double underscore; choose a prefix without one and not ending in '_'")
    clash = [(ident, _reserved(ident)) for ident in defined if _reserved(ident)]
    if clash:
        names = ", ".join(ident for ident, _ in clash[:3]) + (", ..." if len(clash) > 3 else "")
        raise ValueError(f"the C name prefix {prefix!r} would define {names}: names reserved by {clash[0][1]}; "
                         "choose another prefix")
    return prefix


def write_c_header(rotor_map, path, *, dtype: str = "float", name: str | None = None, vehicle=None) -> Path:
    """Write ``rotor_map`` as a self-contained C99 header (atomically): :func:`c_header_text`.

    Parameters
    ----------
    rotor_map : RotorMap
    path : str or Path
        The header file.
    dtype, name, vehicle
        As :func:`c_header_text`.

    Returns
    -------
    Path

    Raises
    ------
    ValueError
        An empty ``path``, or one that is (or links to) the map's own file or its sidecar
        (``RotorMap.open``'s: it would be overwritten); as :func:`c_header_text`.
    TypeError
        As :func:`c_header_text`.
    OSError
        The file cannot be written.
    """
    from .io.atomic import atomic_write, check_file_name
    from .io.mapfile import sidecar_path

    check_file_name(path)
    text = c_header_text(rotor_map, path, dtype=dtype, name=name, vehicle=vehicle)
    source = rotor_map.dataset.encoding.get("source")  # (the file the map was opened from, if any)
    if source:  # (the header replaced the map it was made from, through a link too: an export audit)
        for own in (Path(source), sidecar_path(source)):
            if os.path.realpath(path) == os.path.realpath(own):
                raise ValueError(f"path: {as_path(path).name} is the map's own file {own.name}: it would be "
                                 "overwritten; name the header otherwise (e.g. *.h)")
    with atomic_write(path) as fh:
        fh.write(text)
    return as_path(path)


def _comment(text) -> str:
    """Text from a map's attributes made safe inside a C block comment: one line, and no "*/"
    that would end the comment (an edited map must not inject code into the header)."""
    return " ".join(str(text).split()).replace("*/", "* /")


def _vehicle_block(vehicle, rm, prefix: str) -> str:
    """The C vehicle function of a header (:data:`VEHICLE`), for a vehicle whose every rotor
    carries the map's propeller.

    Raises
    ------
    ValueError
        A rotor with another propeller than the map's: another blade geometry than the one the
        map records (``Propeller.same_geometry``; the name is not compared), or, for a map
        without that record, another diameter (beyond 1%) or blade count, as
        :class:`propmap.vehicle.VehicleMap` (a header holds one map); a rotor with its own
        parameter set other than the one the map records (but for its air: the map's is used),
        or with any set of its own for a map without that record. (Until 2026-12-01 any rotor
        with a set of its own, as :func:`propmap.read_vehicle_with_params` gives the rotors that
        all name ``generic``, was refused with a generic map, which VehicleMap and ``map --format c
        --vehicle`` take: stop 96.)
    """
    import warnings

    from .io.mapcheck import map_model

    name = rm.attrs.get("propeller", "")
    d, b = float(rm.attrs.get("diameter_m", np.nan)), rm.attrs.get("n_blades")
    try:  # (the map's blade geometry, its stations, chords and blade angles, and its set)
        recorded, recorded_set = map_model(rm.attrs)[:2]
    except ValueError:
        recorded = recorded_set = None
    for k, r in enumerate(vehicle.rotors):
        p = r.propeller
        if recorded is not None and not p.same_geometry(recorded):
            other = (", another chord or blade angle" if recorded.same_size(p.diameter, p.n_blades, rtol=5e-5)
                     else "")
            raise ValueError(f"rotor {k + 1} carries {p.name} ({p.diameter:.4g} m, {p.n_blades} blades{other}), not "
                             f"the map's {name} ({d:.4g} m, {b} blades): a C header holds one map (use VehicleMap in "
                             "Python, with one map per rotor)")
        if recorded is None and (not np.isfinite(d) or not p.same_size(d, b)):
            raise ValueError(f"rotor {k + 1} carries {p.name} ({p.diameter:.4g} m, {p.n_blades} blades), not the "
                             f"map's {name} ({d:.4g} m, {b} blades): a C header holds one map (use VehicleMap in "
                             "Python, with one map per rotor)")
        if r.params is not None and (recorded_set is None or not recorded_set.same_section(r.params)):
            raise ValueError(f"rotor {k + 1} has its own parameter set: a C header holds one map")
    from .vehicle.mapped import _warn_map_air

    _warn_map_air([rm] * len(vehicle.rotors), vehicle)  # (a rotor's set in other air than the map's, as VehicleMap)
    if vehicle.body_drag is not None and vehicle.body_drag.wash_factor > 0:
        warnings.warn(f"the airframe's drag in the rotors' slipstream (wash_factor {vehicle.body_drag.wash_factor:g}) "
                      "is left out of the C vehicle function, which has the freestream's drag only: a map holds no "
                      "induced velocity (in hover the slipstream pushes the airframe down; VehicleMap leaves it out "
                      "too)", UserWarning, stacklevel=3)
    if vehicle.rotor_interference > 0:
        warnings.warn(f"the rotors' interference (factor {vehicle.rotor_interference:g}) is left out of the C "
                      "vehicle function: a map holds no induced velocity", UserWarning, stacklevel=2)
    rho = float(rm.attrs["rho_kg_m3"])
    from .vehicle import rotor_geometry

    pos, axes, spins, h = rotor_geometry(vehicle)
    body = vehicle.body_drag
    cda = np.zeros(3) if body is None else np.asarray(body.drag_area, float)

    def rows(a):
        return ", ".join("{" + ", ".join(format(float(x), ".17g") for x in row) + "}" for row in a)

    return VEHICLE.format(
        vname=_comment(vehicle.name or "(unnamed)"), nrot=len(vehicle.rotors), rho=rho, prefix=prefix,
        PREFIX=prefix.upper(), pos=rows(pos), axis=rows(axes), h=rows(h),
        spin=", ".join(str(int(x)) for x in spins),
        cd=", ".join(format(0.5 * rho * float(x), ".17g") for x in cda))


def c_header_text(rotor_map, path, *, dtype: str = "float", name: str | None = None, vehicle=None) -> str:
    """``rotor_map`` as the text of a self-contained C99 header.

    Parameters
    ----------
    rotor_map : RotorMap
        Its interpolation (``"cubic"`` or ``"linear"``) is the C function's.
    path : str or Path
        The header file, e.g. ``apce_8x6_map.h``.
    dtype : {"float", "double"}
        C type of the table (the axes are always double). float: 4 bytes a value, within
        1e-6 relative of the Python evaluator (tests/test_maps_c.py).
    name : str, optional
        The C identifier prefix; default from the file name (``pm_<stem>``). The include
        guard adds a hash of the table, so two different maps with one prefix collide
        at compile time instead of silently.
    vehicle : Vehicle, optional
        Add ``<prefix>_vehicle_wrench``: the vehicle's body force and moment from its
        rotors (all of this map's propeller), as :class:`propmap.VehicleMap`.

    Returns
    -------
    str

    Raises
    ------
    ValueError
        Unknown ``dtype``, a bad prefix (:func:`c_prefix`), or a vehicle rotor with another
        propeller or its own parameter set other than the map's (but for its air; any set of its
        own for a map that does not record its set), as :class:`propmap.VehicleMap`.
    TypeError
        ``rotor_map`` not a :class:`propmap.RotorMap` (a map Dataset: wrap it,
        ``RotorMap(ds)``); ``path`` not a str or os.PathLike; ``vehicle`` not a
        :class:`propmap.Vehicle`.

    Warns
    -----
    UserWarning
        A map that holds the side force and the pitching moment (``RotorMap.side_loads``):
        the header's functions give T, D, Q and M_R and leave them out; a vehicle rotor whose
        own set (the map's) carries other air than the map's (the map's is used), as
        :class:`propmap.VehicleMap` warns.
    """
    from .maps import RotorMap

    if not isinstance(rotor_map, RotorMap):
        raise TypeError(f"rotor_map must be a propmap.RotorMap (RotorMap(ds) or RotorMap.open(path)), "
                        f"got {type(rotor_map).__name__}")
    if rotor_map.side_loads:
        import warnings

        warnings.warn("the map holds a side force and a pitching moment (blade flapping, a linear inflow or the "
                      "dynamic stall); the C header's loads and wrench leave them out (T, D, Q and M_R only)",
                      UserWarning, stacklevel=2)
    if dtype not in ("float", "double"):
        raise ValueError(f"dtype must be 'float' or 'double', got {dtype!r}")
    path = as_path(path)
    prefix = c_prefix(path, name)
    if vehicle is not None:
        from .vehicle.layout import check_vehicle

        check_vehicle(vehicle)
    rm = rotor_map
    a = rm.attrs
    fmt_axis = ".17g"
    fmt_tab = ".9g" if dtype == "float" else ".17g"
    table = rm._table.astype(np.float32 if dtype == "float" else np.float64)
    n0, n1, n2 = rm.omega.size, rm.airspeed.size, rm.incidence.size
    template = _template(rm, prefix)
    check = f"check_{rm.interpolation}_"
    # the include guard carries a hash of the content: two different maps given the same
    # prefix then fail to compile (redefinitions) instead of one being skipped silently
    block = "" if vehicle is None else _vehicle_block(vehicle, rm, prefix)
    digest = hashlib.sha256(b"".join(np.ascontiguousarray(x).tobytes() for x in (
        rm.omega, rm.airspeed, rm.incidence, table, rm._cellflag)) + rm.interpolation.encode()
        + block.encode()).hexdigest()[:12]
    guard = f"{prefix.upper()}_H_{digest.upper()}"
    unc = _caveats(a, rm.side_loads)
    text = template.format(
        name=path.stem, propeller=_comment(a.get("propeller", "")), version=_comment(a.get("propmap_version", "")),
        source=_comment(a.get("propmap_source_sha256", "") or "not recorded"), model=_comment(a.get("model", "")),
        uncertainty=unc,
        params_label=_comment((a.get("params_label", "") or a.get("section_model", "")) + _air_words(a)),
        citation=_comment(a.get("citation", "") or _catalogue_citation(a) or "-"),
        n0=n0, n1=n1, n2=n2,
        rpm0=rm.omega[0] / RPM,
        rpm1=rm.omega[-1] / RPM, v0=rm.airspeed[0], v1=rm.airspeed[-1], b0=np.degrees(rm.incidence[0]),
        b1=np.degrees(rm.incidence[-1]), ctype=dtype, eT=_pct(a.get(check + "thrust_max")),
        eQ=_pct(a.get(check + "torque_max")), eD=_pct(a.get(check + "drag_max")),
        interpolation=rm.interpolation,
        npts=int(a.get("check_points", 0)), prefix=prefix, PREFIX=prefix.upper(), GUARD=guard,
        u0=_inverse_step(rm.omega), u1=_inverse_step(rm.airspeed), u2=_inverse_step(rm.incidence),
        radius=float(rm.radius), ax0=", ".join(format(float(x), fmt_axis) for x in rm.omega),
        ax1=", ".join(format(float(x), fmt_axis) for x in rm.airspeed),
        ax2=", ".join(format(float(x), fmt_axis) for x in rm.incidence), ntab=table.size,
        table=_numbers(table.reshape(-1), fmt_tab), ncell=rm._cellflag.size,
        cells=",\n".join("    " + ", ".join(str(int(c)) for c in row)
                         for row in rm._cellflag.reshape(-1, rm._cellflag.shape[-1])))
    if block:
        end = f"#endif /* {guard} */"
        text = text.replace(end, block.lstrip("\n") + "\n" + end)
    return text


def _catalogue_citation(attrs: dict) -> str:
    """The catalogue's citation of a map's propeller where the map records a catalogue propeller
    as :func:`propmap.load_propeller` gives it (:func:`propmap.io.catalogue.catalogue_source`; a
    map built in Python without ``citation=`` wrote "Data: -", an export audit), else ""."""
    from .io.mapcheck import map_model

    try:
        recorded = map_model(attrs)[0]
    except ValueError:  # (a map without that record)
        return ""
    return catalogue_source(replace(recorded, source=attrs.get("propeller_source", "")))


def _template(rm, prefix: str) -> str:
    """The header's template for ``rm``'s interpolation: the cubic's per-cell slope tables of each
    axis (_slopes) and weights, or the linear's declarations and body."""
    cubic = rm.interpolation == "cubic"
    slopes = ""
    if cubic:  # each axis's per-cell slope coefficients (_slopes), as static tables
        slopes = "".join(
            f"static const double {prefix}_slope{k}[{8 * max(ax.size - 1, 1)}] = {{\n"
            + _numbers(_slopes(ax).reshape(-1), ".17g", 8) + "\n};\n"
            for k, ax in enumerate((rm.omega, rm.airspeed, rm.incidence)))
    return (TEMPLATE.replace("{decl}", CUBIC_DECL if cubic else LINEAR_DECL)
            .replace("{body}", CUBIC_BODY if cubic else LINEAR_BODY)
            .replace("{weights_fn}", (slopes.replace("{", "{{").replace("}", "}}") + CUBIC_WEIGHTS)
                     if cubic else ""))


def _air_words(a: dict) -> str:
    """The map's air for the header's opening comment (rho, and mu and the speed of sound where
    recorded): the loads scale with the density (the comment named the set only until
    2026-12-01, an air-consistency audit)."""
    if "rho_kg_m3" not in a:
        return ""
    return "; air " + air_words(a["rho_kg_m3"], a.get("mu_Pa_s"), a.get("speed_of_sound_m_s"))


def _caveats(attrs: dict, side_loads: bool) -> str:
    """The header comment's lines on the model's own error against measurements (where the map's
    ``attrs`` record it) and on the side force and pitching moment that the functions leave out."""
    unc = ""
    if "model_uncertainty_axial" in attrs:  # the model's own error against measurements, beside the table's
        words = (f"The model against measurements: axial: {attrs['model_uncertainty_axial']}. "
                 f"Off-axis: {attrs['model_uncertainty_off_axis']}.")
        unc = "".join(f" * {line}\n" for line in textwrap.wrap(_comment(words), 90))
    if side_loads:  # (said in the header itself, not only in the warning at its build)
        words = ("This map's model makes a side force Y and a pitching moment M_P as well (blade flapping, a linear "
                 "inflow or the dynamic stall): the functions below leave them out, so the wrench differs from "
                 "propmap.rotor_wrench and RotorMap.wrench by them.")
        unc += "".join(f" * {line}\n" for line in textwrap.wrap(_comment(words), 90))
    return unc
