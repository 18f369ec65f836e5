"""A mutation audit of the implicit derivatives' kernels (core/_sensitivity.py,
core/_delayed_sensitivity.py, core/_swirl_sensitivity.py): the derivatives of rotor_loads
against central differences of the solver at points that exercise the terms no other test
reached (the mutants named in each docstring survived the existing tests)."""

import math

import numpy as np
import pytest

import propmap as pm

from .conftest import moved_loads

DISC = pm.Discretization(24, 8)
LOADS = ("thrust", "drag", "torque", "rolling_moment")
KEYS = {"omega": "om", "airspeed": "V", "incidence": "b"}


def _at(prop, p, om, V, b, loads=LOADS):
    r = pm.rotor_loads(prop, p, om, V, b, discretization=DISC)
    return np.array([float(getattr(r, q)) for q in loads])


def _central(prop, p, x, wrt, h, loads=LOADS):
    """Central differences of the loads in one input (x: dict om, V, b)."""
    k = KEYS[wrt]
    hi = _at(prop, p, **(x | {k: x[k] + h}), loads=loads)
    lo = _at(prop, p, **(x | {k: x[k] - h}), loads=loads)
    return (hi - lo) / (2 * h)


def test_swirl_held_at_its_clip_moves_with_omega_only_and_in_its_own_sense(apc8x6):
    """Mutant M12 (_swirl_sensitivity._swirl_system: the clip's dS/dOmega with its sign flipped,
    +SWIRL_LIMIT y for a positive target): a windmilling rotor (30 rad/s in a 20 m/s flow at
    45 deg, the generic set with swirl) holds its inner annuli's swirl at +-0.5 Omega y; its
    omega, airspeed and incidence derivatives agree with central differences of the solver
    within 1e-6 of the largest (measured 4e-10 on the clean source)."""
    p = pm.generic_params().replace(swirl=True)
    x = {"om": 30.0, "V": 20.0, "b": math.radians(45.0)}
    r = pm.rotor_loads(apc8x6, p, x["om"], x["V"], x["b"], discretization=DISC, radial=True,
                       derivatives=("omega", "airspeed", "incidence"))
    y, v = np.ravel(r.r), np.ravel(r.v_i)
    target = v * np.ravel(r.dQ_dr) / (y * np.ravel(r.dT_dr))
    assert np.sum(np.abs(target) >= 0.5 * x["om"] * y) >= 3  # annuli held at the clip
    for wrt, h in (("omega", 1e-4), ("airspeed", 1e-4), ("incidence", 1e-5)):
        fd = _central(apc8x6, p, x, wrt, h)
        got = np.array([float(r.derivative(q, wrt)) for q in LOADS])
        assert np.max(np.abs(got - fd)) < 1e-6 * np.max(np.abs(fd)), (wrt, got, fd)


def test_the_lift_slopes_compressibility_slope_holds_up_to_mach_0_9(apc8x6):
    """Mutant M18 (_sensitivity._constants_slopes: the Prandtl-Glauert factor's slope in U2
    taken only below Mach 0.8, U2 / a^2 < 0.64, where the factor itself runs to Mach 0.9): at
    2800 rad/s (tip Mach 0.84, the model warns above 0.8) the generic set's omega, airspeed and
    incidence derivatives agree with central differences within 1e-5 of the largest."""
    p = pm.generic_params()
    x = {"om": 2800.0, "V": 5.0, "b": math.radians(30.0)}
    with pytest.warns(UserWarning, match="Mach"):
        r = pm.rotor_loads(apc8x6, p, x["om"], x["V"], x["b"], discretization=DISC,
                           derivatives=("omega", "airspeed", "incidence"))
    for wrt, h in (("omega", 1e-2), ("airspeed", 1e-4), ("incidence", 1e-5)):
        with pytest.warns(UserWarning, match="Mach"):
            fd = _central(apc8x6, p, x, wrt, h)
        got = np.array([float(r.derivative(q, wrt)) for q in LOADS])
        assert np.max(np.abs(got - fd)) < 1e-5 * np.max(np.abs(fd)), (wrt, got, fd)


def test_the_papers_density_pass_moves_the_radial_flows_drag(apc8x6):
    """Mutant M19 (_sensitivity._pass: the radial flow's drag summed without its cos^2 psi
    weight in the paper's section's one-sided passes, here the density's Reynolds part through
    the Blasius drag): with the radial drag on, the loads' derivatives in the air density agree
    with central differences of the solver within 1e-5 of the largest, on edgewise, oblique and
    slow points (the mutant is off by 0.9 % of dD/drho)."""
    p = pm.preset("gill2017-apc").replace(radial_drag=True)
    om, V, b = np.array([800.0, 1000.0, 400.0]), np.array([12.0, 8.0, 15.0]), np.radians([90.0, 60.0, 80.0])
    r = pm.rotor_loads(apc8x6, p, om, V, b, discretization=DISC, derivatives=("rho",))
    h = 1e-4 * p.air.rho
    hi, lo = (moved_loads(apc8x6, p, om, V, b, "rho", s * h, DISC) for s in (1.0, -1.0))
    for q in LOADS:
        fd = (np.asarray(getattr(hi, q)) - np.asarray(getattr(lo, q))) / (2 * h)
        assert np.max(np.abs(np.asarray(r.derivative(q, "rho")) - fd)) < 1e-5 * np.max(np.abs(fd)), (q, fd)
