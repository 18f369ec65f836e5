"""Stop 105: defects found by this stop's audits, each test failing on the code before its fix. Data: synthetic
flight logs (NeuroBEM's layout); the catalogue's APC 8x6E (APC PE0 geometry)."""

import dataclasses
import math

import numpy as np
import pytest

from test_audit_mutation_stop101 import _check, _log


def test_a_motor_acceleration_is_judged_over_the_windows_kept_only():
    """_derivative_ratio judges the speeds' change by its rms over the windows it keeps: a log whose first 3 of 5 s
    carry no motor acceleration (all motors exactly 0: left out) and whose speeds then change by 13 rad/s^2 rms
    (judged: 10) has motor 1's column in rpm/s refused. Counting the left-out windows as zeros took the rms to 8.4
    rad/s^2 and the column was read without a word."""
    from propmap.io.flightlog_checks import FlightLogError

    log = _log(duration=5.0)
    phase = 2 * math.pi * log.t[:, None] + 0.7 * np.arange(4)[None, :]
    acc = 6.0 * math.pi * np.cos(phase)  # (the exact derivative of 1100 + 3 sin(phase): 13.3 rad/s^2 rms)
    acc[:, 0] *= 30.0 / math.pi
    acc[log.t < 3.0, :] = 0.0
    with pytest.raises(FlightLogError, match=r"motor 1's logged acceleration is 9.5\d times .* in rpm/s"):
        _check(dataclasses.replace(log, rotor_omega=1100.0 + 3.0 * np.sin(phase), rotor_acceleration=acc))
