"""The Beaver propeller at incidence (Sinnige et al., J. Aircraft 56(1), 2019), compared in the
wind axes its balance measured: CT_w = (T cos a - H sin a) / (rho n^2 D^4)."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.cases import BEAVER_N, BEAVER_RHO, beaver_propeller, run_case


def test_beaver_is_compared_in_wind_axes():
    g = pm.generic_params().replace(alpha_L0=math.radians(-2.0))
    m = run_case("beaver", {"g": g})
    r = m.metrics["g"]
    # at zero incidence wind and shaft axes agree; at incidence H lowers the wind-axis thrust
    prop = beaver_propeller()
    air = pm.Air(rho=BEAVER_RHO)
    loads = pm.rotor_loads(prop, g, 2 * math.pi * BEAVER_N, 40.0, np.radians([0.0, 20.0]), air=air)
    assert r["CT0"] == pytest.approx(float(loads.CT[0]), rel=1e-12)
    ctw20 = (loads.thrust[1] * math.cos(math.radians(20)) - loads.drag[1] * math.sin(math.radians(20))) / (
        air.rho * BEAVER_N**2 * prop.diameter**4)
    assert r["ratio_20"] == pytest.approx(ctw20 / r["CT0"], rel=1e-12)
    assert r["ratio_20"] < r["shaft_ratio_20"]
    # regression values (2026-11-22, the generic set of both UIUC volumes), docs/validation.md: the measured rise is not reached
    assert m.metrics["measured"]["ratio_20"] == pytest.approx(1.351, abs=0.001)
    assert r["CT0"] == pytest.approx(0.0754, abs=0.0002)
    assert r["ratio_10"] == pytest.approx(1.051, abs=0.002) and r["ratio_20"] == pytest.approx(1.189, abs=0.002)


def test_beaver_with_its_zero_incidence_thrust_matched():
    # one measurement (CT_w at 0 deg) fixes one parameter, the collective; the incidence
    # response is then the model's physics apart from its thrust level
    g = pm.generic_params()
    m = run_case("beaver", {"generic": g, "a0": g.replace(alpha_L0=math.radians(-2.0))}).metrics
    measured = m["measured"]
    prop = beaver_propeller()
    air = pm.Air(rho=BEAVER_RHO)
    for label, base in (("generic", g), ("a0", g.replace(alpha_L0=math.radians(-2.0)))):
        r = m[label]
        p = base.replace(collective=base.collective + math.radians(r["matched_collective_deg"]))
        loads = pm.rotor_loads(prop, p, 2 * math.pi * BEAVER_N, 40.0, 0.0, air=air)
        assert float(loads.CT) == pytest.approx(measured["CT0"], rel=1e-6)
        # matching the level moves the ratios towards the measured ones: a lightly loaded
        # propeller's rise with incidence does not grow with its level at zero incidence
        for a in (10, 20):
            assert abs(r[f"matched_ratio_err_{a}"]) < abs(r[f"ratio_err_{a}"])
    # whichever parameter made the level wrong, the matched response is the same to 0.002
    assert m["generic"]["matched_ratio_20"] == pytest.approx(m["a0"]["matched_ratio_20"], abs=0.002)
    # regression values (2026-11-23, docs/validation.md): still short of the measured rise
    # (1.127, 1.351), with a larger in-plane force than the ratio can take
    assert m["generic"]["matched_collective_deg"] == pytest.approx(-3.40, abs=0.02)
    assert m["generic"]["matched_ratio_10"] == pytest.approx(1.080, abs=0.002)
    assert m["generic"]["matched_ratio_20"] == pytest.approx(1.295, abs=0.002)
    assert m["generic"]["matched_H_over_T_20"] == pytest.approx(0.239, abs=0.002)
