"""A mutation audit of identify/stand.py, identify/steps.py and io/inputs.py (2026-11-29): each test kills a
hand-made mutant that survived the modules' own test files, by the documented behaviour it changed."""

import math

import numpy as np
import pytest

from propmap.identify import read_loads
from propmap.io.inputs import header_separator


def test_a_semicolon_file_with_units_after_commas_and_decimal_commas_is_read(tmp_path):
    """'Zeit, s;Schub, N;Drehmoment, N m;Drehzahl, U/min' over '1,5;2,25;0,025;3000,0' is ';'-separated."""
    assert header_separator("Zeit, s;Schub, N;Drehmoment, N m;Drehzahl, U/min", "1,5;2,25;0,025;3000,0") == ";"
    rpm = np.arange(3000.0, 9000.0, 1000.0)
    rows = [f"{k},5;{r * r / 2e7:.4f};{r * r / 1e9:.5f};{r:.1f}".replace(".", ",") for k, r in enumerate(rpm)]
    path = tmp_path / "eu.csv"
    path.write_text("Zeit, s;Schub, N;Drehmoment, N m;Drehzahl, U/min\n" + "\n".join(rows) + "\n", encoding="utf-8")
    d = read_loads(path)
    assert d.omega * 30 / math.pi == pytest.approx(rpm)
    assert d.measured["thrust"] == pytest.approx(np.round(rpm ** 2 / 2e7, 4))
    assert d.measured["torque"] == pytest.approx(np.round(rpm ** 2 / 1e9, 5))
