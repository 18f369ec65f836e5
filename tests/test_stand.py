"""Thrust-stand exports read as written (issue 18): every RCbenchmark / Tyto series and thrust
unit, electrical and optical speed, reaction torque, stopped rows, ESC-step averaging; the
sanity check that refuses data in the wrong units; a held-out fit of a 1585 export.

The exports are written by tests/stand_exports.py from the stands' documented column sets,
with loads from propmap's calibrated apce_8x6 set (UIUC vol. 1, Brandt & Selig AIAA
2011-1255) plus 0.4% noise and the motor's settling at each step.
"""

import numpy as np
import pytest

import propmap as pm

from propmap.identify import DataError, FitOptions, fit_loads, read_loads
from propmap.identify.data import sanity_check

from stand_exports import COLUMNS, THRUST_UNITS, write_steps_export

STEPS = tuple(range(1100, 2001, 60))  # 16 ESC steps, 900-9000 rpm


@pytest.fixture(scope="module")
def truth_params():
    return pm.default_params("apce_8x6")


@pytest.mark.parametrize("series", sorted(COLUMNS))
@pytest.mark.parametrize("unit", sorted(THRUST_UNITS))
def test_every_series_and_thrust_unit_is_read_as_written(tmp_path, series, unit, truth_params):
    path = tmp_path / f"{series}_{unit}.csv"
    truth = write_steps_export(path, series=series, thrust_unit=unit, params=truth_params, steps=STEPS)
    data = read_loads(path)
    # one point per running ESC step, the stopped 1000 us step (if any) skipped
    assert data.n == len(truth)
    np.testing.assert_allclose(data.omega * 30 / np.pi, truth[:, 0], rtol=2e-3)
    np.testing.assert_allclose(data.measured["thrust"], truth[:, 1], rtol=0.01)
    if series == "1520":  # no torque cell
        assert "torque" not in data.measured
    else:
        np.testing.assert_allclose(data.measured["torque"], truth[:, 2], rtol=0.01)
        assert any("reaction torque" in n for n in data.notes)
    assert len(set(data.group)) == data.n and all(g.startswith("step") for g in data.group)
    assert any("ESC steps" in n for n in data.notes)
    if unit != "N":
        assert any(f"from {unit}" in n for n in data.notes)


def test_stopped_rows_and_a_spin_down_are_left_out_with_a_note(tmp_path, truth_params):
    """A test that starts stopped and ends with the motor cut: the stopped rows are skipped
    and the final step (the speed decaying, never steady) gives no point."""
    path = tmp_path / "s.csv"
    truth = write_steps_export(path, params=truth_params, steps=(1000, *STEPS[:8], 1000))
    data = read_loads(path)
    assert data.n == len(truth) == 8
    np.testing.assert_allclose(data.omega * 30 / np.pi, truth[:, 0], rtol=2e-3)
    assert any("rpm 0" in n or "stopped" in n for n in data.notes), data.notes
    assert any("never steady" in n and "_1000us" in n for n in data.notes), data.notes


def test_electrical_speed_with_pole_pairs(tmp_path, truth_params):
    path = tmp_path / "e.csv"
    truth = write_steps_export(path, params=truth_params, steps=STEPS, electrical_raw=True, pole_pairs=7,
                               optical=False)
    data = read_loads(path, rpm_source="electrical", pole_pairs=7)
    np.testing.assert_allclose(data.omega * 30 / np.pi, truth[:, 0], rtol=2e-3)
    assert any("7 pole pairs" in n for n in data.notes)
    # without the pole pairs the speed is 7x: refused before fitting, naming the cause
    raw = read_loads(path, rpm_source="electrical")
    with pytest.raises(DataError, match="7 pole pairs"):
        sanity_check(raw, pm.load_propeller("apce_8x6"))


def test_a_plain_csv_with_unit_suffixes_is_converted(tmp_path, truth_params):
    prop = pm.load_propeller("apce_8x6")
    rpm = np.linspace(3000, 9000, 7)
    r = pm.rotor_loads(prop, truth_params, rpm * np.pi / 30, 0.0, 0.0)
    lines = ["speed_rad_s,Thrust (lbf),torque_Nmm"]
    lines += [f"{w:.6f},{T / 4.4482216152605:.8g},{Q * 1e3:.8g}" for w, T, Q in zip(rpm * np.pi / 30, r.thrust,
                                                                                    r.torque)]
    (tmp_path / "u.csv").write_text("\n".join(lines) + "\n")
    data = read_loads(tmp_path / "u.csv")
    np.testing.assert_allclose(data.omega, rpm * np.pi / 30, rtol=1e-6)
    np.testing.assert_allclose(data.measured["thrust"], r.thrust, rtol=1e-6)
    np.testing.assert_allclose(data.measured["torque"], r.torque, rtol=1e-6)
    assert sanity_check(data, prop) == []


@pytest.mark.parametrize("thrust_factor, torque_factor, cause", [
    (1 / 9.80665, 1.0, "kgf read as N"),
    (1000 / 9.80665, 1.0, "gf read as N"),
    (1 / 4.4482216152605, 1.0, "lbf read as N"),
    (1.0, 1e3, "N mm read as N m"),
    (1.0, 1 / 0.0980665, "kgf cm read as N m"),
])
def test_wrong_units_are_refused_with_the_cause(tmp_path, truth_params, thrust_factor, torque_factor, cause):
    """Thrust and torque written in another unit under the plain (SI) column names."""
    prop = pm.load_propeller("apce_8x6")
    rpm = np.linspace(3000, 9000, 7)
    r = pm.rotor_loads(prop, truth_params, rpm * np.pi / 30, 0.0, 0.0)
    lines = ["rpm,thrust,torque"] + [f"{n:.1f},{T * thrust_factor:.8g},{Q * torque_factor:.8g}"
                                     for n, T, Q in zip(rpm, r.thrust, r.torque)]
    (tmp_path / "w.csv").write_text("\n".join(lines) + "\n")
    with pytest.raises(DataError, match=cause):
        sanity_check(read_loads(tmp_path / "w.csv"), prop)


def test_the_cli_refuses_wrong_units_in_one_line(tmp_path, truth_params):
    from click.testing import CliRunner

    from propmap.cli.main import cli

    path = tmp_path / "e.csv"
    write_steps_export(path, params=truth_params, steps=STEPS, electrical_raw=True, optical=False)
    res = CliRunner().invoke(cli, ["fit", "loads", str(path), "--prop", "apce_8x6", "--out", str(tmp_path / "p.toml")])
    assert res.exit_code == 2 and "pole pairs" in res.output and "Traceback" not in res.output
    assert not (tmp_path / "p.toml").exists()


def test_held_out_steps_of_a_1585_export_are_predicted(tmp_path, truth_params):
    """Fit every other ESC step of a 1585 export (thrust in gf) from the generic set, predict
    the others: thrust within 3%, torque within 5% (issue 18's target), and a report whose
    intervals are finite with the data determining fewer directions than parameters."""
    path = tmp_path / "s.csv"
    write_steps_export(path, series="1585", thrust_unit="gf", params=truth_params, steps=STEPS, seed=3)
    data = read_loads(path)
    prop = pm.load_propeller("apce_8x6")
    train = np.arange(data.n) % 2 == 0
    res = fit_loads(data.subset(train), prop, base=pm.generic_params(), options=FitOptions())
    held = data.subset(~train)
    r = pm.rotor_loads(prop, res.params, held.omega, 0.0, 0.0)
    dT = np.abs(r.thrust / held.measured["thrust"] - 1)
    dQ = np.abs(r.torque / held.measured["torque"] - 1)
    assert dT.max() < 0.03 and dQ.max() < 0.05, (dT, dQ)
    # blind (generic set) is off by more, so the fit did something
    b = pm.rotor_loads(prop, pm.generic_params(), held.omega, 0.0, 0.0)
    assert np.abs(b.torque / held.measured["torque"] - 1).max() > 2 * dQ.max()
    idf = res.identifiability
    assert np.all(np.isfinite(idf.ci95)) and idf.effective_parameters < len(res.names)
    assert len(res.warnings) + len(idf.warnings) <= 3
