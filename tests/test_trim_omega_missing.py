"""trim_omega with on_missing="nan": every load field of an unreachable thrust is NaN, the rate
included (a third mutation audit, 2026-11-27: omega left at the bound survived the suite)."""

import numpy as np
import pytest

import propmap as pm
from propmap.core.trim import trim_omega


@pytest.fixture(scope="module")
def rotor():
    return pm.load_propeller("apce_8x6"), pm.resolve_params("calibrated:apce_8x6")


def test_unreachable_thrust_with_nan_leaves_every_load_field_nan_including_omega(rotor):
    """Documented rule (on_missing='nan'): NaN rate *and loads* where no rate makes the thrust, so
    loads.omega is NaN too."""
    prop, p = rotor
    r = trim_omega(prop, p, [2.0, 300.0], on_missing="nan")
    assert np.isfinite(r.loads.omega[0])
    assert np.isnan(r.loads.omega[1])
    for f in ("thrust", "drag", "torque", "rolling_moment", "side_force", "pitching_moment", "v_i_mean"):
        assert np.isnan(np.asarray(getattr(r.loads, f))[1]), f
