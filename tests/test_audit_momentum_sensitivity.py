"""Mutation audit (2026-11-29) of core/_momentum_sensitivity.py (the momentum side's partials of the
implicit derivatives), identify/synthetic.py, identify/_checks.py and io/provenance.py: each test
names the hand-made mutant it kills (the audit's report lists those the earlier tests killed)."""

import dataclasses
import hashlib
from collections import deque
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import propmap as pm
from propmap.identify import LoadData, simulate_level_flight
from propmap.identify.level_flight_fit import level_flight_forces
from propmap.io.provenance import source_digest

DISC = pm.Discretization(24, 8)


def _load_data(**change):
    ok = dict(omega=np.array([500.0, 600.0, 700.0]), airspeed=np.zeros(3), incidence=np.zeros(3),
              measured={"thrust": np.array([1.0, 2.0, 3.0])}, group=["a", "a", "b"])
    return LoadData(**{**ok, **change})


# ---------------------------------------------------------------- identify/_checks.py


def test_unsigned_integer_arrays_are_numbers():
    """Mutant C1: ``dtype.kind in "iuf"`` -> ``"if"`` (an unsigned integer array, as a logger's
    uint16 rpm, refused as not numbers)."""
    d = _load_data(omega=np.array([500, 600, 700], dtype=np.uint16))
    assert d.omega.dtype == np.float64 and d.omega.tolist() == [500.0, 600.0, 700.0]


def test_none_in_a_list_of_loads_is_a_point_not_measured():
    """Mutant C2: ``x is None or`` dropped (a None in a list, NumPy's NaN, refused as not numbers)."""
    d = _load_data(measured={"thrust": [1.0, None, 3.0]})
    t = d.measured["thrust"]
    assert np.isnan(t[1]) and t[0] == 1.0 and t[2] == 3.0


def test_a_bool_among_ints_is_refused_not_read_as_one():
    """Mutant C3: ``and not has_bool(value)`` dropped ([500, True, 700] is an int array to NumPy:
    a rotation rate of 1 rad/s)."""
    with pytest.raises(ValueError, match=r"LoadData\.omega must be numbers, got \[500, True, 700\]"):
        _load_data(omega=[500, True, 700])


def test_a_bool_in_a_deque_is_refused():
    """A bool in a sequence other than a list, tuple or array (a collections.deque, which NumPy unpacks
    like a list) was read as 1.0 until 2026-11-29 (has_bool looked into lists, tuples and arrays only;
    found by this audit): a point at 1 rad/s. The same for rotor_loads, whose inputs share the rule."""
    with pytest.raises(ValueError, match=r"LoadData\.omega must be numbers, got deque\(\[500\.0, True, 700\.0\]\)"):
        _load_data(omega=deque([500.0, True, 700.0]))
    with pytest.raises(ValueError, match="omega must be a number or an array of numbers, got deque"):
        pm.rotor_loads(pm.load_propeller("apce_8x6"), pm.generic_params(), deque([800.0, True]), 0.0, 0.0)
    assert _load_data(omega=deque([500.0, 600.0, 700.0])).omega.tolist() == [500.0, 600.0, 700.0]


def test_an_int_beyond_the_float_range_is_refused_as_not_numbers():
    """Mutant C4: ``OverflowError`` dropped from the caught errors (10**400 escaped as an
    OverflowError instead of the field's ValueError)."""
    with pytest.raises(ValueError, match=r"LoadData\.airspeed must be numbers, got \[0, 1000000"):
        _load_data(airspeed=[0, 10**400, 0])


def test_a_bool_in_an_object_series_is_refused():
    """Mutant C10: ``and not isinstance(x, (bool, np.bool_))`` dropped from the object arrays' rule
    (a pandas column of floats and a bool, object dtype, which has_bool does not look into: the
    bool read as 1 rad/s)."""
    with pytest.raises(ValueError, match=r"LoadData\.omega must be numbers"):
        _load_data(omega=pd.Series([500.0, True, 700.0]))


def test_a_scalar_first_field_is_refused_naming_its_shape():
    """Mutant C9: first_length's ``len(shape) != 1`` -> ``> 1`` (a scalar omega, shape (), an
    IndexError instead of the field's ValueError)."""
    with pytest.raises(ValueError, match=r"^LoadData\.omega must have shape \(N,\), got \(\)$"):
        _load_data(omega=500.0)


# ---------------------------------------------------------------- identify/synthetic.py


@pytest.fixture(scope="module")
def quad():
    return pm.read_vehicle("quadrotor")


def test_simulated_conditions_balance_the_weight_each_at_its_own_airspeed_and_pitch(quad):
    """Mutants S1 (the pitch not converted from degrees), S4 (Brent's xtol 1e-10 -> 1e-2), S6 (every
    condition trimmed at the first one's airspeed), S8 (trimmed to 0.9 of the weight), S9 (a roll of
    0.01 rad in the data): every condition's common rotor speed gives the weight to 1e-9 at the
    airspeed and pitch (radians) given, level and without body rates."""
    params = pm.preset("gill2017-apc")
    d = simulate_level_flight(quad, params, [0.0, 12.0], [0.0, -15.0])
    np.testing.assert_array_equal(d.airspeed, [0.0, 12.0])
    np.testing.assert_allclose(d.pitch, [0.0, math.radians(-15.0)], rtol=0, atol=1e-15)
    assert not d.roll.any() and not d.rates.any() and d.omega.shape == (2, 4)
    assert (d.omega == d.omega[:, :1]).all() and abs(d.omega[1, 0] - d.omega[0, 0]) > 5.0
    f = level_flight_forces(params, d, quad)["vertical"]
    np.testing.assert_allclose(f, quad.weight, rtol=1e-9)


def test_a_light_vehicle_trims_below_400_rad_s_inside_the_default_bracket(quad):
    """Mutant S2: the default bracket's bottom 200 -> 400 rad/s (a vehicle of 35 % of the quad's mass
    hovers at about 320 rad/s: refused as untrimmable)."""
    light = dataclasses.replace(quad, mass=0.35 * quad.mass)
    params = pm.preset("gill2017-apc")
    d = simulate_level_flight(light, params, [0.0], [0.0])
    assert 200.0 < d.omega[0, 0] < 400.0
    assert level_flight_forces(params, d, light)["vertical"][0] == pytest.approx(light.weight, rel=1e-9)


def test_a_condition_no_speed_in_the_bracket_trims_is_named_in_degrees(quad):
    """Mutants S3 (the bracket check deleted: SciPy's "f(a) and f(b) must have different signs"
    instead) and S7 (the pitch said in radians): the message names the bracket, the condition,
    its airspeed and its pitch in degrees."""
    with pytest.raises(ValueError, match=r"^no rotor speed in \(200\.0, 300\.0\) rad/s trims condition 0 "
                                         r"\(V=5 m/s, pitch=-5 deg\)$"):
        simulate_level_flight(quad, pm.preset("gill2017-apc"), [5.0], [-5.0], omega_bounds=(200.0, 300.0))


# ---------------------------------------------------------------- io/provenance.py


def _digest_as_documented(unreadable):
    """The digest by its documented rule, with the file named ``unreadable`` entering as b"unreadable"."""
    root = Path(pm.__file__).resolve().parent
    files = sorted((p.relative_to(root).as_posix(), p) for p in root.rglob("*") if p.is_file()
                   and "__pycache__" not in p.parts and not p.name.endswith((".pyc", ".pyo", ".nbi", ".nbc")))
    h = hashlib.sha256()
    for rel, p in files:
        data = b"unreadable" if p.name == unreadable else p.read_bytes()
        h.update(len(rel.encode()).to_bytes(8, "little") + rel.encode() + len(data).to_bytes(8, "little") + data)
    return h.hexdigest()


def test_a_file_removed_since_listed_enters_the_digest_as_the_word_unreadable(monkeypatch):
    """Mutants P2 (an unreadable file's bytes b"" instead of b"unreadable") and P6 (``except OSError``
    -> ``except PermissionError``: a file removed between the listing and the read, FileNotFoundError,
    failed the output)."""
    real = Path.read_bytes

    def read_bytes(self):
        if self.name == "CITATION.md":
            raise FileNotFoundError(2, "No such file or directory", str(self))
        return real(self)

    monkeypatch.setattr(Path, "read_bytes", read_bytes)
    got = source_digest.__wrapped__()
    monkeypatch.setattr(Path, "read_bytes", real)
    assert got == _digest_as_documented("CITATION.md") != _digest_as_documented(None)


# ---------------------------------------------------------------- core/_momentum_sensitivity.py


def _central(prop, params, om, V, b, key, h):
    args = {"om": om, "V": V, "b": b}
    hi = pm.rotor_loads(prop, params, *(args | {key: args[key] + h}).values(), discretization=DISC)
    lo = pm.rotor_loads(prop, params, *(args | {key: args[key] - h}).values(), discretization=DISC)
    return {q: (float(getattr(hi, q)) - float(getattr(lo, q))) / (2 * h) for q in ("thrust", "drag", "torque")}


@pytest.mark.parametrize("wrt, key, h, x", [("omega", "om", 0.08, 800.0), ("airspeed", "V", 1.2e-3, 12.0)])
def test_exactly_edgewise_the_differenced_momentum_side_gives_the_solvers_slopes(apc8x6, wrt, key, h, x):
    """Mutants M28 (the momentum side's Omega difference over one step, not two) and M29 (its
    V sin beta difference likewise): exactly edgewise (beta = 90 deg) the empirical model switches
    on, so every annulus' momentum partials are central differences of the momentum side; along
    Omega and along the airspeed (V cos beta stays 0: no kink crossed) the implicit derivatives of
    thrust, drag and torque match central differences of the solver to 1e-6 of the load per unit of
    the input's scale (they agree to 1e-8; tests/test_derivatives.py allows 1e-4 edgewise, where the
    incidence crosses the kink)."""
    params = pm.generic_params()
    b = math.pi / 2
    r = pm.rotor_loads(apc8x6, params, 800.0, 12.0, b, discretization=DISC, derivatives=True)
    fd = _central(apc8x6, params, 800.0, 12.0, b, key, h)
    for q in ("thrust", "drag", "torque"):
        scale = abs(float(r.thrust)) if q != "torque" else abs(float(r.torque))
        err = abs(float(r.derivative(q, wrt)) - fd[q]) * x / scale
        assert err < 1e-6, (q, float(r.derivative(q, wrt)), fd[q])


@pytest.mark.parametrize("beta_deg", [180.0, 130.0, 100.0])
def test_hover_slope_along_a_descending_ray_at_an_inflow_below_1_m_s(apc8x6, beta_deg):
    """Mutants M27 (_rest_slope's ``v > 0.0`` -> ``v > 1.0``: annuli of an inflow below 1 m/s given
    Glauert's slope, not the empirical curve's at hover, 2 EMPIRICAL_C1) and M41 (``cb < 0.0`` ->
    ``cb < -0.5``: a ray within 30 deg below the disk plane given Glauert's): hovering at 100 rad/s
    (mean inflow 0.92 m/s) the airspeed's one-sided slope from rest along a descending ray (axial,
    oblique, and 10 deg below edgewise: the curve's fade is flat at rest) matches second-order
    one-sided differences of the solver to 1e-4 of the thrust (torque) per m/s (they agree to 5e-6)."""
    params = pm.generic_params()
    b, h = math.radians(beta_deg), 1e-4
    r = pm.rotor_loads(apc8x6, params, 100.0, 0.0, b, discretization=DISC, derivatives=True)
    assert 0.5 < float(r.v_i_mean) < 1.0
    f0, f1, f2 = (pm.rotor_loads(apc8x6, params, 100.0, k * h, b, discretization=DISC) for k in (0, 1, 2))
    for q in ("thrust", "torque"):
        fd = (4 * float(getattr(f1, q)) - float(getattr(f2, q)) - 3 * float(getattr(f0, q))) / (2 * h)
        err = abs(float(r.derivative(q, "airspeed")) - fd) / abs(float(getattr(r, q)))
        assert err < 1e-4, (q, float(r.derivative(q, "airspeed")), fd)
