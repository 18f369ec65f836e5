"""Parameter-file rules the module documents (a second mutation audit, 2026-11-27: a preset that
overrode the file's keys, dynamic_stall warned of when absent, mu = 0 accepted, the [body]
table's centre of mass not written, read_body checking only its table: each survived)."""

import math
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag
from propmap.io.params_file import BodyTable, params_from_dict, params_to_dict, read_body, write_params


def test_a_files_keys_override_the_section_preset():
    """module docstring: section = "naca0015" takes every key of the preset, 'and the file's other keys override it'"""
    p = params_from_dict({"section": "naca0015", "cl_max": 1.2, "alpha_L0_deg": -2.0})
    assert p.cl_max == 1.2 and p.alpha_L0 == pytest.approx(math.radians(-2.0))
    assert p.cl_alpha == 6.302536  # the preset's


def test_a_cambered_file_without_dynamic_stall_is_filled_silently():
    """OFF_WHEN_ABSENT: dynamic_stall is off where the key is absent, unnamed by the fill warning"""
    d = params_to_dict(pm.generic_params())
    d.pop("dynamic_stall")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = params_from_dict(d, fill=True)
    assert p.dynamic_stall == 0.0


def test_zero_viscosity_is_refused_by_the_file_range():
    """docstring: mu in (0, 10] Pa s"""
    with pytest.raises(ValueError, match=r"mu must be a finite number in \(0, 10\]"):
        params_from_dict({"cl1": 5.3, "cl2": 1.7, "cd": 1.8, "alpha0_deg": 20.6, "mu": 0.0})


def test_body_table_round_trip(tmp_path):
    """write_params' [body] table read back by read_body: drag, centre of mass, interference"""
    p = tmp_path / "p.toml"
    write_params(p, pm.generic_params(),
                 body=BodyTable(BodyDrag((0.02, 0.01, 0.0), 1.2), np.array([0.002, -0.001, 0.0]), 0.7))
    b = read_body(p)
    assert b.drag.drag_area == (0.02, 0.01, 0.0) and b.drag.wash_factor == 1.2
    np.testing.assert_array_equal(b.centre_of_mass, [0.002, -0.001, 0.0])
    assert b.rotor_interference == 0.7


def test_read_body_checks_the_whole_file(tmp_path):
    """read_body docstring: the whole file is checked, as read_params does"""
    from propmap.io.params_file import ParamsFileError
    p = tmp_path / "bad.toml"
    p.write_text('cl1 = 5.3\ncl2 = 1.7\ncd = 1.8\nalpha0_deg = 120.0\n[body]\ndrag_area = [0.01, 0.01, 0.0]\n')
    with pytest.raises(ParamsFileError, match="alpha0_deg"):
        read_body(p)


def test_boolean_options_must_be_booleans():
    with pytest.raises(ValueError, match="tip_loss must be true or false"):
        params_from_dict({"cl1": 5.3, "cl2": 1.7, "cd": 1.8, "alpha0_deg": 20.6, "tip_loss": 1})


def test_coverage_keeps_twelve_digits(tmp_path):
    from propmap.io.params_file import read_coverage
    p = tmp_path / "c.toml"
    write_params(p, pm.generic_params(), coverage={"rpm_min": 1974.9999999999998, "rpm_max": 6543.21987654321})
    c = read_coverage(p)
    assert c["rpm_min"] == 1975.0 and c["rpm_max"] == 6543.21987654
