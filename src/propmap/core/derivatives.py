"""Implicit derivatives of the rotor loads (docs/solver.md, Derivatives): which inputs and
section parameters :func:`propmap.rotor_loads` differentiates, their constants, and the
call of the sensitivity kernel (core/_sensitivity.py) at the converged roots.
"""

from __future__ import annotations

import contextlib
import functools
from dataclasses import fields
from dataclasses import replace as dc_replace

import numpy as np

from . import _physics as ph
from . import _momentum as mo
from ._parallel import parallel_region
from .airfoil import RECORD_META, SectionParams
from .polar import _model_constants
from .flapping import COMPLIANCE
from .nodes import _cambered_args, _nodes

__all__ = ["DERIVATIVE_LOADS", "FLAPPING_LOADS", "DERIVATIVE_INPUTS", "RHO", "NODE_FIELDS", "NOT_CONSTANTS",
           "PARAM_FLOOR", "differentiable"]


#: what ``rotor_loads(derivatives=...)`` differentiates, and with respect to what
DERIVATIVE_LOADS = ("thrust", "drag", "torque", "rolling_moment", "v_i_mean")
DERIVATIVE_INPUTS = ("omega", "airspeed", "incidence", "collective")
#: the air density, differentiated besides the inputs and the section parameters
RHO = "rho"
#: internal (core/vector.py): at the points with V = 0, the loads' slopes in the velocity along three rays
#: from the same roots, in the same kernel pass (:func:`_jacobian`); 0 elsewhere
STILL_AIR = "_still_air"
#: the loads that flapping blades add (core/flapping.py), differentiated by the chain rule after the kernel's;
#: zero with rigid blades and the uniform inflow
FLAPPING_LOADS = ("side_force", "pitching_moment")
#: the loads odd in V sin(beta), whose slope at rest is the edgewise one
_ODD_LOADS = ("drag", "rolling_moment", *FLAPPING_LOADS)


def differentiable(params: SectionParams, names) -> bool:
    """Whether :func:`rotor_loads` gives implicit derivatives of ``params``'s loads with respect
    to every name in ``names`` (what the fits ask before using them).

    Parameters
    ----------
    params : AirfoilParams or CamberedParams
    names : sequence of str
        Inputs (:data:`DERIVATIVE_INPUTS`), ``"rho"``, ``"flap_compliance"`` or section
        parameters' names.

    Returns
    -------
    bool
        False for a name that is not a numeric field entering the section's constants
        (:data:`NOT_CONSTANTS`, switches, text), other than ``flap_compliance``
        (differentiated through the flapping, core/flapping.py, for rigid and flapping blades
        alike); every inflow model, with or without swirl, has them (since 2026-11-26 a linear
        inflow with swirl too); the rotation rates' range is the caller's to check (>= 0.1 rad/s).
        False for ``dynamic_stall`` itself (Gormont's gamma is not differentiated).
    """
    own = {f.name for f in fields(params)} - set(RECORD_META)
    return all(n in DERIVATIVE_INPUTS or n == RHO or n == COMPLIANCE
               or (n in own and n not in NOT_CONSTANTS and isinstance(getattr(params, n), float)) for n in names)


def _derivative_inputs(derivatives, params) -> tuple:
    """The inputs and section parameters ``rotor_loads(derivatives=...)`` asks for, checked
    (() for none)."""
    if isinstance(derivatives, np.bool_):  # (np.True_ was refused as not a sequence: an audit)
        derivatives = bool(derivatives)
    if derivatives is False or derivatives is None:
        return ()
    if derivatives is True:
        wrt = DERIVATIVE_INPUTS[:3]
    else:
        if isinstance(derivatives, str) or not hasattr(derivatives, "__iter__"):
            raise ValueError(f"derivatives must be True, False or a sequence of input or parameter names "
                             f"({', '.join(DERIVATIVE_INPUTS)}, or a field of the parameter set), "
                             f"got {derivatives!r:.60}")
        wrt = tuple(dict.fromkeys(derivatives))
        own = ({f.name for f in fields(params)} - set(RECORD_META)) | {RHO, STILL_AIR}
        bad = [w for w in wrt if w not in DERIVATIVE_INPUTS and w not in own]
        if bad:
            raise ValueError(f"derivatives: unknown input or parameter {bad[0]!r:.60}; valid: "
                             f"{', '.join((*DERIVATIVE_INPUTS, RHO))} or a numeric field of "
                             f"{type(params).__name__}")
    return wrt


#: the parameter set's fields that _nodes reads (the blade angle, the Reynolds reference, the Blasius
#: factor, the loss switches): not differentiable as section constants (tests/test_derivatives.py checks
#: that every other numeric field leaves the nodes unchanged)
NODE_FIELDS = ("collective", "re_ref", "cp_blasius", "tip_loss", "hub_loss")
#: fields that enter neither the element's nor the annulus' constants: refused as derivatives
NOT_CONSTANTS = (*NODE_FIELDS, "flap_compliance", "dynamic_stall")
#: a section parameter's step is _sensitivity.ONE_SIDED of max(|value|, PARAM_FLOOR)
PARAM_FLOOR = 0.01


def _parameter_constants(names, params, air):
    """:func:`_stepped_constants`, remembered for the last 64 (names, parameter set, air): a
    controller or a fit asks for the same parameters' derivatives call after call, and the
    stepped sets' validation cost about 68 us per parameter, more than a single point's solve
    (a user-level audit, 2026-11-26). Copies, so that no caller shares the remembered arrays."""
    try:
        pks, cams, step = _stepped_constants_cached(tuple(names), params, air)
    except TypeError:  # (an unhashable field: not remembered)
        return _stepped_constants(names, params, air)
    return pks.copy(), cams.copy(), step.copy()


@functools.lru_cache(maxsize=64)
def _stepped_constants_cached(names, params, air):
    return _stepped_constants(names, params, air)


def _stepped_constants(names, params, air):
    """(pk, cam, step) of each section parameter in ``names``: the element and annulus
    constants at the parameter's value + its step (- its step where + leaves the parameter's
    range), and that step (either sign), for the kernel's one-sided differences.

    Raises
    ------
    ValueError
        A parameter that is not a number, one that changes the blade's nodes (the
        Reynolds reference, the Blasius factor, the loss switches; ``collective`` is the
        input of that name) rather than the section's constants, ``flap_compliance`` (not a
        constant: rotor_loads differentiates the flapping itself, core/flapping.py), or one
        that admits no step within its range.
    """
    from ._sensitivity import ONE_SIDED

    n = len(names)
    pks = np.empty((n, ph.N_PK))
    cams = np.empty((n, 8))
    step = np.empty(n)
    for k, name in enumerate(names):
        if name == COMPLIANCE:  # enters neither pk nor cam: rotor_loads differentiates the flapping itself
            raise ValueError("flap_compliance is not a section constant (core/flapping.flapping_derivatives)")
        if name == "dynamic_stall":
            raise ValueError("derivatives with respect to dynamic_stall (Gormont's gamma) are not supported: "
                             "difference the solver")
        if name in NOT_CONSTANTS:
            hint = {"collective": " (the blade angle: give the input 'collective')",
                    "re_ref": " (the Reynolds reference: the Reynolds terms' own slopes are re_exp, re_exp_lift, "
                              "re_exp_stall and alpha_L0_re; difference the solver for re_ref)"}.get(
                name, " (difference the solver)")
            raise ValueError(f"derivatives with respect to {name} are not supported: it changes the blade's nodes "
                             f"(their precomputed Reynolds factors or losses), not the section's constants{hint}")
        x = getattr(params, name)
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            raise ValueError(f"derivatives: {name} is not a number of the parameter set ({x!r:.40})")
        h = ONE_SIDED * max(abs(float(x)), PARAM_FLOOR)
        for dx in (h, -h):
            try:
                stepped = params.replace(**{name: float(x) + dx})
            except ValueError:  # beyond the parameter's range: the other side
                continue
            break
        else:
            raise ValueError(f"derivatives: {name} = {x!r} admits no step within its range")
        pks[k] = _model_constants(stepped)[1]
        cams[k] = _cambered_args(stepped, air)
        step[k] = (float(x) + dx) - float(x)  # the step as represented
    return pks, cams, step


def _jacobian(wrt, om, V, b, coll, roots, converged, nd, model, pk, cam, empirical, params, air, propeller,
              discretization, loads, uniform_roots=None, *, serial=False) -> dict:
    """{(load, input or parameter): derivative} at every point (flat arrays), from one call of
    the sensitivity kernel (core/_sensitivity.py); with a linear inflow model, of
    core/_linear_sensitivity.py at ``roots`` and ``uniform_roots`` (shape (n, nr): the kernel's
    uniform solve, core/_kernel._solve_point), which also gives the side force and the pitching
    moment. ``roots`` shape (1, n, nr), or (2, n, nr) with swirl (the roots and the swirl).
    With :data:`STILL_AIR`, at the points with
    V = 0 the loads' slopes in the velocity, from the kernel's one-sided airspeed derivatives
    along three rays at the same roots (at rest the root does not depend on the incidence):
    edgewise (beta = pi/2) for D and M_R, odd in V sin(beta), so that this one-sided slope is
    the derivative; for T, Q and v_i,mean the mean of the climb (beta = 0) and descent
    (beta = pi) slopes, the limit of central differences (core/vector.still_air_slopes); 0 at
    the points with V > 0. ``serial``: run the kernel on the calling thread (a small batch:
    solver.PARALLEL_MIN_POINTS)."""
    from . import _linear_sensitivity, _sensitivity

    rays = STILL_AIR in wrt
    inputs = [w for w in wrt if w in DERIVATIVE_INPUTS]
    names = [w for w in wrt if w not in DERIVATIVE_INPUTS and w not in (RHO, STILL_AIR)]
    scp = nd.sc
    hrho = 0.0
    if RHO in wrt:  # the section constant sc holds the Reynolds number's density (rho c / mu)
        rho_step = air.rho + _sensitivity.ONE_SIDED * air.rho
        hrho = rho_step - air.rho  # the step as represented
        if hrho == 0.0:  # (the kernel tells the density's column by a nonzero step)
            raise ValueError(f"derivatives: rho = {air.rho!r} kg/m^3 is too small to be stepped")
        scp = _nodes(propeller, discretization.n_radial, discretization.n_azimuth, dc_replace(air, rho=rho_step),
                     params).sc
    # the kernel's inputs come in this order; the rays need its input passes
    n_in = 4 if "collective" in inputs else (3 if inputs or rays else 0)
    pks, cams, step = _parameter_constants(names, params, air)
    par = (pks, cams, np.all(cams == cam, axis=1), step)
    n_cols = n_in + len(names) + (RHO in wrt)
    om, V, b, coll = (np.ascontiguousarray(a, dtype=float) for a in (om, V, b, coll))  # no broadcast views
    scp = np.ascontiguousarray(scp, dtype=float)
    # the dynamic stall's rising and falling halves give a side force and a pitching moment: their rows too
    n_rows = len(DERIVATIVE_LOADS) + (len(FLAPPING_LOADS) if getattr(params, "dynamic_stall", 0.0) > 0.0 else 0)
    raw = np.empty((n_rows, n_cols + (3 if rays else 0), om.size))
    inflow = mo.INFLOW_CODES[params.inflow]
    if inflow == mo.INFLOW_UNIFORM:
        run = _sensitivity.sensitivities_serial if serial else _sensitivity.sensitivities
        with contextlib.nullcontext() if serial else parallel_region():  # (core/_parallel.py)
            run(om, V, b, coll, roots, converged, nd.rows, nd.azimuth, model, pk, cam, empirical, n_in, par, scp, hrho,
                raw)
    else:  # both solves' annuli together, the uniform one's mean inflow setting the gradients
        # (core/_linear_sensitivity.py) at the uniform solve's roots kept by the kernel (core/_kernel._solve_point),
        # shape (n, nr), NaN where that solve failed
        uniform_roots = np.ascontiguousarray(uniform_roots)
        converged_u = np.isfinite(uniform_roots).all(axis=1)
        half = np.ascontiguousarray(nd.azimuth[:, :nd.azimuth.shape[1] // 2])  # the uniform solve's half circle
        raw = np.empty((_linear_sensitivity.N_ROWS,) + raw.shape[1:])
        run = _linear_sensitivity.linear_sensitivities_serial if serial else _linear_sensitivity.linear_sensitivities
        with contextlib.nullcontext() if serial else parallel_region():  # (core/_parallel.py)
            run(om, V, b, coll, roots, converged & converged_u,
                (uniform_roots, half, np.ascontiguousarray(half[:, [0, -1]]), float(propeller.radius)), nd.rows,
                nd.azimuth, model, pk, cam, inflow, empirical, n_in, par, (scp, hrho), raw)
    col = {w: DERIVATIVE_INPUTS.index(w) for w in inputs} | {w: n_in + k for k, w in enumerate(names)}
    if RHO in wrt:
        col[RHO] = n_in + len(names)
        for q, a in zip((0, 1, 2, 3, 5, 6), loads):  # cfac and mfac scale with rho: L / rho at the same root
            if q < raw.shape[0]:
                raw[q, col[RHO]] += a / air.rho
    names_out = DERIVATIVE_LOADS + (FLAPPING_LOADS if raw.shape[0] > len(DERIVATIVE_LOADS) else ())
    out = {(load, w): raw[q, col[w]] for q, load in enumerate(names_out) for w in wrt if w != STILL_AIR}
    if rays:  # climb, edgewise, descent (dV_c = -dV along beta = pi)
        for q, load in enumerate(names_out):
            out[(load, STILL_AIR)] = (raw[q, n_cols + 1] if load in _ODD_LOADS
                                      else 0.5 * (raw[q, n_cols] - raw[q, n_cols + 2]))
    return out
