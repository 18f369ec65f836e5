"""Edges of identification from a thrust stand's or a user's files (a user-level audit,
2026-11-26): a pitot's noise on a static stand, a torque cell the stand does not have, an
optical probe's dropouts, a static run at exactly the rpm span of the rule, options that
would be ignored, and parameter files refused before their fill is said."""

import math
import warnings

import numpy as np
import pytest
from click.testing import CliRunner

import propmap as pm
from propmap.cli.main import cli
from propmap.identify import DataError, LoadData, read_loads
from propmap.identify.data import sanity_check
from propmap.identify.fit import _data_kind
from propmap.identify.load_data import STATIC_AIRSPEED
from propmap.io.params_file import read_params

from stand_exports import write_steps_export

STEPS = tuple(range(1100, 2001, 100))


def _static(rpm, airspeed=0.0, params=None, torque=True):
    prop = pm.load_propeller("apce_8x6")
    om = np.asarray(rpm, float) * math.pi / 30
    V = np.broadcast_to(np.asarray(airspeed, float), om.shape).copy()
    r = pm.rotor_loads(prop, params or pm.default_params("apce_8x6"), om, V, 0.0)
    measured = {"thrust": r.thrust, "torque": r.torque if torque else np.zeros_like(r.torque)}
    return prop, LoadData(om, V, np.zeros_like(om), measured, np.full(om.size, "all", dtype=object), "test")


def test_a_static_stand_with_a_pitots_noise_is_static():
    """Airspeeds up to STATIC_AIRSPEED (0.3 m/s) are a static run's: which parameters a fit frees
    does not turn on a pitot reading 0.09 m/s of noise (it did: the sweep fit, all 8 parameters)."""
    rpm = np.linspace(3000, 9000, 8)
    assert _data_kind(_static(rpm)[1]) == "static"
    noise = np.linspace(0.0, 0.09, rpm.size)
    assert _data_kind(_static(rpm, noise)[1]) == "static"
    assert _data_kind(_static(rpm, np.full(rpm.size, STATIC_AIRSPEED + 1.0))[1]) != "static"


def test_a_static_run_spanning_the_rule_within_rounding_counts_as_spanning():
    """A static run spanning STATIC_RPM_SPAN (1.5x) decides whether a few-rate sweep fits the
    Reynolds terms; rounding a unit's conversion (Hz, 7 digits) must not move it across."""
    rpm = np.concatenate([np.linspace(4000.0, 6000.0 * (1 - 1e-9), 5), [5000.0, 5000.0, 5000.0]])
    V = np.concatenate([np.zeros(5), [5.0, 8.0, 11.0]])
    prop, data = _static(rpm, V)
    assert _data_kind(data) == "rates"
    _, fewer = _static(np.concatenate([np.linspace(4000.0, 5800.0, 5), [5000.0] * 3]), V)
    assert _data_kind(fewer) == "few_rates"


def test_a_torque_the_stand_does_not_measure_is_checked_only_when_fitted():
    prop, data = _static(np.linspace(3000, 9000, 8), torque=False)
    assert sanity_check(data, prop, quantities=("thrust",)) == []
    with pytest.raises(DataError, match=r"torque is 0 at every point: not measured\? .*--quantities thrust"):
        sanity_check(data, prop)


def test_an_optical_probes_dropouts_take_the_electrical_speed(tmp_path, monkeypatch):
    """Rows where the optical speed reads 0 while the electrical one runs take the electrical
    speed (where the two agree elsewhere); without that, the step they cover is averaged from
    its settling rows."""
    path = tmp_path / "s.csv"
    write_steps_export(path, params=pm.default_params("apce_8x6"), steps=STEPS)
    text = path.read_text(encoding="utf-8-sig").splitlines()
    head = text[0].split(",")
    k = next(i for i, h in enumerate(head) if h.startswith("Motor Optical"))
    e = next(i for i, h in enumerate(head) if h.startswith("Motor Electrical"))
    rows = [r.split(",") for r in text[1:]]
    # the electrical column of the export is the stand's from its pole setting: make it agree with the optical one
    for r in rows:
        r[e] = r[k]
    full = tmp_path / "full.csv"
    full.write_text("\n".join([text[0]] + [",".join(r) for r in rows]) + "\n", encoding="utf-8")
    for r in rows[70:90]:  # the steady half of the fourth step
        r[k] = "0"
    gaps = tmp_path / "gaps.csv"
    gaps.write_text("\n".join([text[0]] + [",".join(r) for r in rows]) + "\n", encoding="utf-8")
    a, b = read_loads(full), read_loads(gaps)
    assert b.n == a.n and any("probe dropout" in n for n in b.notes)
    np.testing.assert_allclose(b.omega, a.omega, rtol=1e-12)
    import propmap.identify.loads_csv as loads_csv

    # a raw electrical rpm (7 pole pairs) beside the optical one: the dropouts take it divided by 7
    raw = [list(r) for r in rows]
    for r, r_full in zip(raw, (x.split(",") for x in text[1:])):
        r[e] = f"{7 * float(r_full[k]):.1f}"
    seven = tmp_path / "seven.csv"
    seven.write_text("\n".join([text[0]] + [",".join(r) for r in raw]) + "\n", encoding="utf-8")
    c = read_loads(seven)
    assert c.n == a.n and any("divided by 7, the motor's pole pairs" in n for n in c.notes)
    np.testing.assert_allclose(c.omega, a.omega, rtol=1e-4)
    monkeypatch.setattr(loads_csv, "_optical_gaps", lambda optical, *args: optical)
    biased = read_loads(gaps)  # the step's settling rows alone: its speed 1.6% low
    assert abs(biased.omega[2] / a.omega[2] - 1) > 0.01


def test_options_a_catalogue_source_would_ignore_are_refused(tmp_path):
    out = str(tmp_path / "p.toml")
    for extra, match in ((["--pole-pairs", "7"], "--pole-pairs: applies to a thrust-stand CSV"),
                         (["--rpm-source", "optical"], "--rpm-source: applies to a thrust-stand CSV"),
                         (["--prop", "apce_8x6"], "--prop: SOURCE 'apce_8x6' is a catalogue propeller")):
        res = CliRunner().invoke(cli, ["fit", "loads", "apce_8x6", *extra, "--out", out])
        assert res.exit_code == 2 and match in res.output, res.output
        assert "Traceback" not in res.output and not (tmp_path / "p.toml").exists()


@pytest.mark.parametrize("body, match", [
    ('section_model = "cambered"\ncl_alpha = -5\n', "cl_alpha must be a finite number in"),
    ('section_model = "cambered"\ncomment = 5\n', "comment must be text"),
    ('section_model = "cambered"\nspeed_of_sound = 1\n', r"speed_of_sound must be a finite number in \[100, 10000\]"),
])
def test_a_refused_parameter_file_gets_its_error_alone(tmp_path, body, match):
    """The warning that names the keys taken from the generic set comes only for a file that is
    read (it came before the error: two lines for one refusal)."""
    path = tmp_path / "p.toml"
    path.write_text(body)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(ValueError, match=match):
            read_params(path)
    assert not caught
    path.write_text('section_model = "cambered"\ncl_alpha = 6.0\n')
    with pytest.warns(UserWarning, match="not in the file: taken from the generic set"):
        read_params(path)


def test_a_pulse_width_under_a_percent_header_is_read_as_one():
    """'Throttle (%)' holding 1100-1900 was read as percent (labels step1_1100pct, a 0.2 tolerance):
    a user-level audit, 2026-11-26."""
    from propmap.identify.steps import esc_form

    form, note = esc_form("Throttle (%)", "%", np.array([1100.0, 1500.0, 1900.0]))
    assert form == "us" and "not percent" in note
    assert esc_form("Throttle (%)", "%", np.array([10.0, 50.0, 100.0])) == ("pct", None)
    assert esc_form("Throttle (%)", "%", np.array([10.0, 50.0, 100.5])) == ("pct", None)  # (an overshoot)
