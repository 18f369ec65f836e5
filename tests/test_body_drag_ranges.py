"""BodyDrag's documented ranges, its 'active' rule and its refusal of booleans (a second mutation
audit, 2026-11-27: each survived the suite)."""

import numpy as np
import pytest
from propmap.core.body import BodyDrag


def test_zero_drag_area_is_inactive():
    assert not BodyDrag().active
    assert not BodyDrag((0.0, 0.0, 0.0), 1.2).active
    assert BodyDrag((0.0, 0.0, 1e-6)).active


def test_documented_range_ends_are_accepted():
    # drag_area each in [0, 10] m^2, wash_factor in [0, 3] (docstring, params-file docs)
    b = BodyDrag((10.0, 5.0, 2.0), 3.0)
    assert b.drag_area == (10.0, 5.0, 2.0) and b.wash_factor == 3.0
    with pytest.raises(ValueError, match=r"drag_area\[0\]"):
        BodyDrag((10.000001, 0.0, 0.0))


@pytest.mark.parametrize("bad", [True, np.True_])
def test_booleans_are_not_numbers(bad):
    with pytest.raises(ValueError, match=r"drag_area\[0\]"):
        BodyDrag((bad, 0.0, 0.0))
    with pytest.raises(ValueError, match="wash_factor"):
        BodyDrag((0.01, 0.0, 0.0), bad)
