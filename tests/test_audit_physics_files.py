"""A mutation audit of core/flapping.py, core/body.py, core/hover.py and io/params_file.py
(2026-11-29): each test kills a hand-made mutant that survived the suite, by the physics or the
documented behaviour it changed."""

import math
import tomllib
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag
from propmap.core.hover import HoverModel
from propmap.io.param_sets import section_preset
from propmap.io.params_file import ParamsFileError, read_params, write_params

PAPER = 'cl1 = 5.3\ncl2 = 1.7\ncd = 1.8\nalpha0_deg = 20.6\n'


def _file(tmp_path, text, name="p.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


# ---- core/flapping.py
@pytest.mark.parametrize("compliance", [0.0, 2.0])
def test_the_mean_inflow_does_not_depend_on_the_flap_compliance(compliance):
    """Flapping tilts the thrust, not its magnitude (module docstring), so the momentum inflow,
    the thrust and the torque do not move with the compliance, rigid blades (0) included;
    rigid_compliance_derivatives documents the zeros (the v_i_mean entry was droppable)."""
    prop = pm.load_propeller("apce_8x6")
    p = pm.generic_params().replace(flap_compliance=compliance)
    r = pm.rotor_loads(prop, p, 800.0, 8.0, 1.0, derivatives=("omega", "flap_compliance"))
    for q in ("thrust", "torque", "v_i_mean"):
        assert float(r.derivative(q, "flap_compliance")) == 0.0, q
    assert float(r.derivative("v_i_mean", "omega")) > 0.0  # (the entries are there and alive)


# ---- core/body.py
@pytest.mark.parametrize("bad", [(0.01, 0.01), (0.01, 0.01, 0.01, 0.01), "abc", b"\x01\x02\x03"])
def test_drag_area_is_three_numbers_one_per_body_axis(bad):
    """BodyDrag's drag_area: '(C_D A) along body x, y, z', a sequence of 3 floats: a fourth axis,
    a string or bytes (whose items are small integers) are refused as such."""
    with pytest.raises(ValueError, match=r"drag_area must be 3 numbers \[m\^2\] \(x, y, z\)"):
        BodyDrag(bad)


# ---- core/hover.py
@pytest.mark.parametrize("bad", [True, math.inf, -math.inf, math.nan])
def test_hover_constants_must_be_finite_numbers(bad):
    """HoverModel: k_T, k_Q 'finite'; a bool is not a number (thrust() refuses booleans too)."""
    with pytest.raises(ValueError, match="k_T must be a finite number"):
        HoverModel(bad, 1e-7)
    with pytest.raises(ValueError, match="k_Q must be a finite number"):
        HoverModel(1e-5, bad)


@pytest.mark.parametrize("name", ["rho", "diameter"])
def test_hover_context_must_be_finite(name):
    """rho and diameter: 'a positive finite number (or None)'."""
    with pytest.raises(ValueError, match=f"{name} must be a positive finite number"):
        HoverModel(1e-5, 1e-7, **{name: math.inf})


def test_hover_model_calibrates_down_to_one_rad_per_s():
    """from_model: omega '>= 1' rad/s; below it k_T = T / Omega^2 has no spinning rotor to come from."""
    prop, params = pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")
    h = HoverModel.from_model(prop, params, 1.0)
    r = pm.rotor_loads(prop, params, 1.0, 0.0, 0.0)
    assert h.k_T == float(r.thrust) > 0.0 and h.k_Q == float(r.torque) > 0.0  # Omega^2 = 1
    for slow in (0.5, 0.999):
        with pytest.raises(ValueError, match="at least 1 rad/s"):
            HoverModel.from_model(prop, params, slow)


def test_hover_coefficient_ranges_include_their_ends():
    """from_coefficients: CT and CP in [-1000, 1000], the diameter in (0, 1000] m (closed ends);
    the coefficients come back from CT() and CP() in the same air."""
    h = HoverModel.from_coefficients(1000.0, -1000.0, 1000.0)
    assert h.CT() == pytest.approx(1000.0, rel=1e-12) and h.CP() == pytest.approx(-1000.0, rel=1e-12)
    h = HoverModel.from_coefficients(-1000.0, 1000.0, 0.2)
    assert h.CT() == pytest.approx(-1000.0, rel=1e-12) and h.CP() == pytest.approx(1000.0, rel=1e-12)


@pytest.mark.parametrize("d", [0.0, -0.2, math.inf])
def test_hover_coefficients_refuse_a_diameter_that_is_not_positive(d):
    """CT(), CP(): 'a diameter that is not a positive finite number' is a ValueError (0 divided by zero)."""
    h = HoverModel.from_coefficients(0.11, 0.074, 0.2032)
    for f in (h.CT, h.CP):
        with pytest.raises(ValueError, match="diameter must be a positive finite number"):
            f(d)


# ---- io/params_file.py
def test_a_paper_file_without_its_stall_angle_names_the_key(tmp_path):
    """alpha0_deg is required for section_model 'gill2017'; the message names the file's key (not the field)."""
    p = _file(tmp_path, PAPER.replace("alpha0_deg = 20.6\n", ""))
    with pytest.raises(ParamsFileError, match=r"p\.toml: missing key\(s\) alpha0_deg \(required"):
        read_params(p)


def test_speed_of_sound_range_is_the_files(tmp_path):
    """speed_of_sound in [100, 1e4] m/s: no gas is slower than about 100 m/s (module docstring)."""
    assert read_params(_file(tmp_path, PAPER + "speed_of_sound = 100\n")).air.speed_of_sound == 100.0
    for slow in ("99.0", "1e-300"):
        with pytest.raises(ParamsFileError, match=r"speed_of_sound must be a finite number in \[100, 10000\] m/s"):
            read_params(_file(tmp_path, PAPER + f"speed_of_sound = {slow}\n"))


def test_collective_out_of_range_is_named_in_degrees(tmp_path):
    """collective_deg in [-30, 30] deg: the message names the file's key and its range in degrees,
    not the record's field in radians."""
    with pytest.raises(ParamsFileError, match=r"collective_deg must be a finite number in \[-30, 30\] deg, got 45"):
        read_params(_file(tmp_path, PAPER + "collective_deg = 45.0\n"))


@pytest.mark.parametrize("text", ['section = "naca0015"\n', 'section = "naca0015"\nsection_model = "cambered"\n'])
def test_a_section_file_is_the_named_preset(tmp_path, text):
    """section = "naca0015" takes every key of that preset (fill is ignored with section), with or
    without its section_model: the file is the preset --params section:naca0015 names, without the
    generic set's values or its warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = read_params(_file(tmp_path, text))
    assert got == section_preset("naca0015")


@pytest.mark.parametrize("key", ["comment", "source"])
def test_text_keys_must_be_strings(tmp_path, key):
    """'The text keys (comment, source) must be TOML strings.'"""
    with pytest.raises(ParamsFileError, match=rf"{key} must be text \(a TOML string\), got 5"):
        read_params(_file(tmp_path, PAPER + f"{key} = 5\n"))


@pytest.mark.parametrize("table, match", [("[body]\ndrag_area = [0.01, 0.01]\n", r"\[body\]: drag_area must be 3"),
                                          ("[coverage]\nJ_max = -1.0\n", r"coverage\.J_max")])
def test_read_params_checks_the_side_tables(tmp_path, table, match):
    """params_from_dict checks the [body] and [coverage] tables too, 'so that every reader refuses a bad table'."""
    with pytest.raises(ParamsFileError, match=match):
        read_params(_file(tmp_path, PAPER + table))


def test_a_stall_angle_of_a_radian_warns(tmp_path):
    """alpha0_deg = 1.2: a stall angle of 1.2 deg is no section's (Table I: 20.4-27.5 deg) and
    1.2 rad = 68.8 deg is within the file's (0, 90) deg: below 2 deg it warns (RADIAN_LIKE_DEG)."""
    p = _file(tmp_path, PAPER.replace("alpha0_deg = 20.6", "alpha0_deg = 1.2"))
    with pytest.warns(UserWarning, match=r"alpha0_deg = 1.2 deg is small .*radians\? \(1.2 rad = 68.8 deg"):
        read_params(p)


def test_write_params_writes_the_comment(tmp_path):
    """write_params: comment 'Written as the file's comment'; the file still reads back as the same set."""
    p = tmp_path / "w.toml"
    params = pm.preset("gill2017-apc")
    write_params(p, params, comment="fitted to run 7")
    assert tomllib.loads(p.read_text("utf-8"))["comment"] == "fitted to run 7"
    back = read_params(p)
    assert back.replace(alpha0=params.alpha0) == params and np.isclose(back.alpha0, params.alpha0, rtol=2e-16)


@pytest.mark.parametrize("bad", [b"800", ["800"], np.array(["800"]), [800.0, "800"],
                                 np.array([800.0, "800"], dtype=object)])
def test_hover_rates_refuse_text_in_every_form(bad):
    """thrust(), torque(): 'a string' is not a rate (the test of '800' above); NumPy read bytes, a list
    of texts and a text array as 800 rad/s, and rotor_loads refuses them all (a bug found by the audit)."""
    h = HoverModel(1e-5, 1e-7)
    for f in (h.thrust, h.torque):
        with pytest.raises(ValueError, match=r"omega must be (finite numbers|a number)"):
            f(bad)
    # (rotor_loads read a text in an object array as a number too, until the same day)
    with pytest.raises(ValueError, match="omega must be a number or an array of numbers"):
        pm.rotor_loads(pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc"), bad, 0.0, 0.0)
