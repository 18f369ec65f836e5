"""Wrong objects are TypeErrors naming the argument (stop 87, 2026-11-30): a path of 5 to the UIUC
readers met pathlib's "expected str, bytes or os.PathLike object", naming nothing (the other
readers said "path must be a file path"); ``preset(["x"])`` met "unhashable type"; a non-Vehicle
given to VehicleMap was a ValueError where every other entry point that takes a vehicle raises a
TypeError (tests/test_audit_vehicle_map_inputs.py).
"""

from __future__ import annotations

import pytest

import propmap as pm
from propmap.io import read_uiuc_static, read_uiuc_sweep


@pytest.mark.parametrize("reader", [read_uiuc_static, read_uiuc_sweep])
def test_the_uiuc_readers_name_a_path_that_is_not_one(reader):
    with pytest.raises(TypeError, match=r"^path must be a file path \(str or os.PathLike\), got int$"):
        reader(5)


def test_preset_names_a_name_that_is_not_a_string():
    with pytest.raises(TypeError, match=r"^name must be a preset's name \(str; valid: gill2017-soft, "):
        pm.preset(["gill2017-apc"])
    with pytest.raises(KeyError, match="unknown parameter preset 'x'"):
        pm.preset("x")
