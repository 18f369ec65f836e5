"""build_map warns of a grid beyond the data behind its parameter set, as the `map` command does
(stop 91): a map built in Python over 3000-15000 rpm with APC 8x6E's calibrated set (fitted to
UIUC vol. 1 data at 2534-6713 rpm) was built without a word, where `propmap map` warns of it.
The lines are propmap.io.coverage.coverage_warnings', as a CoverageWarning; the command prints
them once."""

import warnings

import numpy as np

import propmap as pm
from propmap.cli.main import main
from propmap.io.coverage import CoverageWarning
from propmap.maps import build_map

RPM = np.pi / 30


def _built(rpm, incidence_deg, **kw):
    prop, p = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        build_map(prop, p, np.asarray(rpm) * RPM, np.array([0.0, 5.0]), np.radians(incidence_deg), n_check=0, **kw)
    return [str(w.message) for w in caught if issubclass(w.category, CoverageWarning)]


def test_an_rpm_axis_beyond_the_calibrated_sets_data_is_warned_of():
    said = _built([3000.0, 9000.0, 15000.0], [0.0, 1.0])
    assert "3000-15000 rpm: the data behind calibrated:apce_8x6 span 2534-6713 rpm" in said[-1]
    assert any(s.startswith("incidence up to 1 deg: calibrated:apce_8x6 was fitted to axial data only") for s in said)


def test_a_grid_within_the_data_is_not():
    """Guard: 3000-6000 rpm in axial flow (an incidence axis of 0 and 1e-9 deg), within the set's
    data (J up to 5 m/s / (50 rev/s x 0.2032 m) = 0.49, the data's 0.97)."""
    assert _built([3000.0, 6000.0], [0.0, 1e-9]) == []


def test_the_label_given_is_the_one_checked():
    """params_label names the set whose data are checked: a label without known data says nothing."""
    assert _built([3000.0, 15000.0], [0.0, 1.0], params_label="my own fit") == []


def test_the_map_command_says_each_line_once(tmp_path, capsys):
    code = main(["map", "apce_8x6", "--rpm", "3000:15000:3", "--airspeed", "0:5:2", "--incidence-deg", "0:1:2",
                 "--check-points", "0", "--out", str(tmp_path / "m.nc")])
    assert code == 0
    err = capsys.readouterr().err
    assert err.count("the data behind calibrated:apce_8x6 span 2534-6713 rpm") == 1, err


def test_a_long_label_is_no_file_name():
    """A params_label past 255 characters (no file) raised 'File name too long' from the coverage
    lookup (a review): it is a label without known data."""
    assert _built([3000.0, 15000.0], [0.0, 1.0], params_label="x" * 300) == []
