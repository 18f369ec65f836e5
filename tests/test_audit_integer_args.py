"""Integer arguments (counts, seeds, limits) pass one check, core/_numbers.integer, with one wording.

Stop 87 (2026-11-30): ``read_loads(min_points="6")`` and ``read_level_flight(min_conditions="6")``
met a TypeError from a comparison after the file was read; ``check_seed(-1)`` returned 0, the
seed of other points; a seed of 2**63 - 1, inside the documented range, was refused (its float
rounds up past the bound).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core._numbers import SEED_MAX, integer
from propmap.identify import FitOptions, read_level_flight, read_loads
from propmap.simexport.fit import check_seed

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"


@pytest.mark.parametrize("value, whole_float, expected", [
    (5, True, 5), (np.int64(5), False, 5), (np.array(5), False, 5), (5.0, True, 5),
    (np.float32(5.0), True, 5), (SEED_MAX, True, SEED_MAX), (SEED_MAX, False, SEED_MAX)])
def test_integer_accepts_integers_and_whole_floats_where_allowed(value, whole_float, expected):
    n = integer("seed", value, 0, SEED_MAX, whole_float=whole_float)
    assert n == expected and type(n) is int


@pytest.mark.parametrize("value", [True, np.bool_(True), "5", 5.5, float("nan"), float("inf"), -1, SEED_MAX + 1,
                                   None, np.array([5]), [5]])
def test_integer_refuses_what_is_not_an_integer_in_range(value):
    with pytest.raises(ValueError, match=r"^seed must be an integer in \[0, 9223372036854775807\], got "):
        integer("seed", value, 0, SEED_MAX)


def test_integer_without_whole_floats_and_without_an_upper_bound():
    with pytest.raises(ValueError, match=r"^max_nfev must be an integer in \[1, 10\], got 5.0$"):
        integer("max_nfev", 5.0, 1, 10, whole_float=False)
    assert integer("min_points", 10**30, 1) == 10**30
    with pytest.raises(KeyError, match=r"min_points must be an integer >= 1, got 0"):
        integer("min_points", 0, 1, error=KeyError)


def test_the_largest_documented_seed_is_accepted_and_check_seed_refuses_a_negative_one():
    assert FitOptions(seed=SEED_MAX).seed == SEED_MAX
    assert check_seed(0) == 1 and check_seed(SEED_MAX - 1) == SEED_MAX
    for bad in (-1, SEED_MAX, 1.5, "3"):
        with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 9223372036854775806\]"):
            check_seed(bad)


@pytest.mark.parametrize("bad", ["6", 0, 2.5, True])
def test_read_loads_and_read_level_flight_refuse_a_bad_minimum_before_reading(tmp_path, bad):
    missing = tmp_path / "not_there.csv"  # (the argument is checked first: no file error)
    with pytest.raises(ValueError, match=r"^min_points must be an integer >= 1, got "):
        read_loads(missing, min_points=bad)
    veh = pm.read_vehicle(EXAMPLES / "quadrotor.toml")
    with pytest.raises(ValueError, match=r"^min_conditions must be an integer >= 1, got "):
        read_level_flight(missing, veh, min_conditions=bad)


def test_fit_options_store_the_checked_int_and_huge_ints_are_exact():
    """A 0-d array passed FitOptions' check and was stored as it was: the fit then failed in NumPy's
    seeding ("array(3) cannot be used to seed") and hash(options) raised (the session's review)."""
    o = FitOptions(seed=np.array(3), multistart=np.array(1), max_nfev=np.int64(50))
    assert (o.seed, o.multistart, o.max_nfev) == (3, 1, 50)
    assert all(type(v) is int for v in (o.seed, o.multistart, o.max_nfev)) and isinstance(hash(o), int)
    assert integer("min_points", 10**400, 1) == 10**400  # (beyond a float: checked as an int)
    for bad in (np.array(True), np.array(3.0)):
        with pytest.raises(ValueError, match="seed must be an integer"):
            FitOptions(seed=bad)

