"""What stop 93 left alone, fixed at stop 94 (2026-12-01). Each test fails on the code before its
fix; the guards say so. Data: loads made by propmap's model for the catalogue's APC 8x6E (UIUC
geometry) with its calibrated set, so that the right reading matches the model to the noise."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.identify import read_loads
from propmap.identify.load_data import LoadData
from propmap.identify.sanity import sanity_check

PROP = "apce_8x6"


def _static(rpm):
    r = pm.rotor_loads(pm.load_propeller(PROP), pm.resolve_params(f"calibrated:{PROP}"),
                       np.asarray(rpm) * math.pi / 30, 0.0, 0.0)
    return r.thrust, r.torque


def _grams_with_thousands(path, torque_factor=1.0):
    """A static run 12,000-17,000 rpm, its thrust in grams quoted with thousands separators
    ("1,068.2"), its torque in N m times ``torque_factor``."""
    rpm = np.arange(12000.0, 18000.0, 1000.0)
    T, Q = _static(rpm)
    assert np.all(T / 9.80665e-3 > 1000.0)  # (every thrust cell is grouped)
    path.write_text("rpm,thrust (g),torque (N m)\n" + "".join(
        f'{a:.0f},"{t / 9.80665e-3:,.1f}",{q * torque_factor:.6g}\n' for a, t, q in zip(rpm, T, Q)), encoding="utf-8")
    return path, T


def test_the_loads_read_with_thousands_separators_are_data_not_a_note(tmp_path):
    """The reader's thousands decision was found by the load check in the notes' words; the
    loads whose cells it read so are now a field of LoadData (and kept by ``subset``)."""
    path, T = _grams_with_thousands(tmp_path / "g.csv")
    data = read_loads(path)
    assert data.comma_thousands == ("thrust",)
    assert np.allclose(data.measured["thrust"], T, rtol=1e-4)
    assert data.subset(np.arange(T.size) < 3).comma_thousands == ("thrust",)
    sanity_check(data, pm.load_propeller(PROP))  # (read right: no refusal)


def test_a_torque_slip_beside_thousands_in_the_thrust_is_not_blamed_on_the_commas(tmp_path):
    """Torque in N mm under an N m header, beside a thrust read with thousands separators: the
    refusal named "decimal commas read as thousands separators" first, for a torque column that
    has no commas; it names the torque's unit now."""
    path, _ = _grams_with_thousands(tmp_path / "g.csv", torque_factor=1000.0)
    with pytest.raises(ValueError) as e:
        sanity_check(read_loads(path), pm.load_propeller(PROP))
    assert "the measured torque" in str(e.value) and "torque in N mm read as N m" in str(e.value)
    assert "decimal commas" not in str(e.value)


def test_a_note_alone_is_no_decimal_comma_cause():
    """The cause follows the field, not a note's words (a LoadData built by hand with the note's
    text and no such loads)."""
    rpm = np.arange(5000.0, 11000.0, 1000.0)
    T, Q = _static(rpm)
    note = "x.csv: column 'thrust': commas read as thousands separators (line 2: 1,734 read as 1734)"
    data = LoadData(rpm * math.pi / 30, np.zeros(rpm.size), np.zeros(rpm.size), {"thrust": T * 1000, "torque": Q},
                    np.full(rpm.size, "all", dtype=object), "x.csv", notes=(note,))
    with pytest.raises(ValueError) as e:
        sanity_check(data, pm.load_propeller(PROP))
    assert "decimal commas" not in str(e.value)
    marked = LoadData(data.omega, data.airspeed, data.incidence, data.measured, data.group, "x.csv",
                      comma_thousands=("thrust",))
    with pytest.raises(ValueError, match="likely decimal commas read as thousands separators"):
        sanity_check(marked, pm.load_propeller(PROP))


@pytest.mark.parametrize("bad", [("rpm",), ["thrust"], "thrust"])
def test_comma_thousands_refuses_what_is_not_a_tuple_of_loads(bad):
    with pytest.raises(ValueError, match="LoadData.comma_thousands must be a tuple of thrust, drag, torque"):
        LoadData(np.array([500.0]), np.zeros(1), np.zeros(1), {"thrust": np.ones(1)}, np.array(["a"], dtype=object),
                 comma_thousands=bad)
