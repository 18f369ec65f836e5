"""A mutation audit of maps.py, rotormap.py and simexport/ (2026-11-29): each test kills a hand-made mutant that
survived the modules' own test files, by the documented behaviour it changed."""

import math

import numpy as np
import pytest


@pytest.mark.parametrize("target, omega", [("multinomial", 0.0), ("multinomial", -500.0), ("rotorpy", -500.0),
                                           ("gz-sim", np.array([600.0, -1.0])), ("gazebo-classic", math.nan)])
def test_predict_refuses_a_rotation_rate_its_model_cannot_take(target, omega):
    """predict refuses Omega < 0 or NaN (and 0 for the multinomial) by name, not NaN or wrong-sign loads."""
    from propmap.simexport import predict

    c = {"k_eta": 1e-5, "k_m": 1e-7, "k_d": 1e-4, "k_z": 1e-5, "k_h": 0.0, "motorConstant": 1e-5,
         "momentConstant": 0.01, "rotorDragCoefficient": 1e-4, "rollingMomentCoefficient": 1e-6, "R": 0.1, "rho": 1.2,
         "CT": [0.01] * 6, "CH": [0.001] * 4, "CQ": [0.001] * 6, "CR": [0.001] * 4}
    with pytest.raises(ValueError, match=rf"omega must be >=? 0 rad/s for the {target} model"):
        predict(target, c, omega, 5.0, 1.0)
    T, D, Q, MR = predict(target, c, 600.0, 5.0, 1.0)
    assert T > 0 and D > 0 and Q > 0 and np.isfinite(MR)
    if target != "multinomial":  # a stopped rotor of the simulators' models: no thrust, drag or torque
        assert predict(target, c, 0.0, 5.0, 1.0)[1:3] == (0.0, 0.0)
