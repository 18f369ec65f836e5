"""read_loads' documented rules at their edges (a third mutation audit, 2026-11-27: the static
airspeed's "at most", the 1% stop-noise rule, the density column's median and the mmHg factor
each survived the suite)."""

import numpy as np
import pytest

from propmap.identify import DataError, read_loads
from propmap.identify.load_data import STATIC_AIRSPEED


def _csv(tmp_path, header, rows):
    p = tmp_path / "loads.csv"
    p.write_text(header + "\n" + "\n".join(",".join(f"{x:g}" for x in r) for r in rows) + "\n")
    return p


RPM = [3000.0, 4000.0, 5000.0, 6000.0, 7000.0, 8000.0]


def test_thrust_negative_at_exactly_static_airspeed_is_negated(tmp_path):
    """Documented rule: points with airspeed *at most* STATIC_AIRSPEED are static, so a thrust
    negative at all of them is negated."""
    rows = [(r, STATIC_AIRSPEED, -1e-7 * r**2) for r in RPM]
    d = read_loads(_csv(tmp_path, "rpm,airspeed,thrust", rows))
    assert np.all(d.measured["thrust"] > 0)
    np.testing.assert_allclose(d.measured["thrust"], [1e-7 * r**2 for r in RPM])


def test_negative_rpm_beyond_one_percent_of_the_largest_is_refused(tmp_path):
    """Documented rule: a rotation speed negative in some rows and positive in others is refused;
    only |rpm| < 1% of the largest is stop noise."""
    rows = [(r, 1e-7 * r**2) for r in RPM] + [(-0.05 * 8000.0, 0.0)]
    with pytest.raises(DataError, match="rotation speed must be positive"):
        read_loads(_csv(tmp_path, "rpm,thrust", rows))


def test_air_density_column_is_read_as_its_median(tmp_path):
    """Documented rule (read_loads docstring): LoadData.air_density is the median of the density column."""
    rhos = [1.2, 1.2, 1.2, 1.2, 1.2, 2.0]
    rows = [(r, 1e-7 * r**2, rho) for r, rho in zip(RPM, rhos)]
    d = read_loads(_csv(tmp_path, "rpm,thrust,air density", rows))
    assert d.air_density == pytest.approx(1.2, rel=1e-12)


def test_temperature_and_pressure_in_mmhg_give_standard_sea_level_density(tmp_path):
    """Physical value: 15 degC and 760 mmHg (101325 Pa) is the ISA sea-level density, rho = p / (R T) = 1.225 kg/m^3."""
    rows = [(r, 1e-7 * r**2, 15.0, 760.0) for r in RPM]
    d = read_loads(_csv(tmp_path, "rpm,thrust,temperature (C),pressure (mmHg)", rows))
    assert d.air_density == pytest.approx(1.225, rel=2e-3)


def test_points_are_counted_as_distinct_operating_points_and_a_repeated_row_is_said(tmp_path):
    """The minimum of six is of distinct operating points (rows were counted: three points written
    twice were fitted); a row that repeats another to every digit is warned of (a table pasted
    twice fitted without a word, its standard errors shrunk by sqrt(2): a user-level audit,
    2026-11-28), a replicate measurement at the same point (other loads) is not."""
    import warnings

    three = [(r, 1e-7 * r**2, 1e-9 * r**2) for r in RPM[:3]]
    with pytest.raises(DataError, match=r"has 6 points at 3 distinct operating points; a fit needs at least 6 "
                                        r"distinct operating points"):
        read_loads(_csv(tmp_path, "rpm,thrust,torque", three + three))
    six = [(r, 1e-7 * r**2, 1e-9 * r**2) for r in RPM]
    with pytest.warns(UserWarning, match=r"loads.csv: 2 row\(s\) repeat another row to every digit .* pasted twice"):
        d = read_loads(_csv(tmp_path, "rpm,thrust,torque", six + six[:2]))
    assert d.omega.size == 8
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        read_loads(_csv(tmp_path, "rpm,thrust,torque", six + [(r, 1.01e-7 * r**2, 1e-9 * r**2) for r in RPM[:2]]))


def test_a_row_cut_short_before_a_column_it_needs_is_refused_not_taken_for_a_stopped_motor(tmp_path):
    """A stand export's row cut short (``7,9.0`` of five fields) ended before its speed column, which
    read as empty: a stopped motor's row, skipped with only a note (a thrust-stand export audit,
    2026-11-29). It is an error naming the line and the column it ends before; a row that ends
    after the columns read (a missing voltage) is read."""
    head = "Time (s),Thrust (N),Torque (N m),Motor Electrical Speed (RPM),Voltage (V)"
    rows = ["1,1.00,0.020,3000,12", "2,1.80,0.035,4000,12", "3,2.80,0.055,5000", "4,4.0,0.080,6000,12",
            "5,5.4,0.11,7000,12", "6,7.1,0.14,8000,12", "8,9.0,0.18,9000,12"]
    p = tmp_path / "stand.csv"
    p.write_text("\n".join([head, *rows]) + "\n", encoding="utf-8")
    data = read_loads(p)
    assert data.n == 7 and data.omega[2] == pytest.approx(5000 * np.pi / 30)
    p.write_text("\n".join([head, *rows[:6], "7,9.0", rows[6]]) + "\n", encoding="utf-8")
    with pytest.raises(DataError, match=r"stand.csv, line 8: 2 fields, but the header \(line 1\) has 5: the row ends "
                                        r"before column 'Torque \(N m\)'"):
        read_loads(p)
