"""Stop 100: defects found by audits and the closing review of stop 99's list, each test failing
on the code before its fix."""

import numpy as np
import pytest

import propmap as pm


@pytest.fixture(scope="module")
def apce_8x6():
    return pm.load_propeller("apce_8x6")


def test_a_scalar_call_gives_0d_arrays_for_power_and_state_name(apce_8x6):
    # shape S = () for one point: power was a NumPy scalar (0-d arrays multiply to one) and
    # state_name a bare str, where the other per-point properties are 0-d arrays
    r = pm.rotor_loads(apce_8x6, pm.generic_params(), 600.0, 5.0, 0.3)
    for name in ("thrust", "power", "CP", "state_name", "v_i_over_v_h"):
        value = getattr(r, name)
        assert isinstance(value, np.ndarray) and value.shape == (), name
    assert r.state_name[()] == "normal working"
    assert float(r.power) == pytest.approx(float(r.torque) * 600.0, rel=1e-15)
    many = pm.rotor_loads(apce_8x6, pm.generic_params(), [600.0, 700.0], 5.0, 0.3)
    assert many.state_name.shape == (2,) and many.power.shape == (2,)
