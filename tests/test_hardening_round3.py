"""Hardening from a user-level audit (2026-11-26) of the paths that real data not in the
repository take: wind-tunnel CSVs whose airspeed or incidence columns carry other names,
thrust-stand exports with their air density and other unit spellings, tab-separated files,
UIUC vol. 2 hub names and upper-case file names.

Loads are propmap's own (the calibrated apce_8x6 set, UIUC vol. 1, Brandt & Selig AIAA
2011-1255), labelled as such: these tests check what is read, not the model.
"""

import math
import re
import shutil
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.identify import DataError, read_loads
from propmap.identify.data import sanity_check
from propmap.identify.stand import map_columns

from test_cli_hostile_maps import one_line_error, run

RPM = math.pi / 30
UIUC_V1 = Path(str(resources.files("propmap") / "data" / "uiuc_v1"))


def _tunnel_csv(path: Path, header: list[str], incidence_deg=(0.0, 45.0, 90.0), scale=(1.0, 1.0, 1.0, 1.0),
                sep=",", density=None) -> np.ndarray:
    """A tunnel file of propmap's loads (apce_8x6, calibrated set): rpm, airspeed, incidence,
    thrust, drag, torque at 4000-7000 rpm, 0-12 m/s, written under ``header``'s names with each
    value divided by ``scale`` (rpm, airspeed, thrust-and-drag, torque: the columns' units)."""
    prop, p = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    rpm, V, inc = (a.ravel() for a in np.meshgrid([4000.0, 5500.0, 7000.0], [0.0, 6.0, 12.0], incidence_deg))
    r = pm.rotor_loads(prop, p, rpm * RPM, V, np.radians(inc))
    rows = np.column_stack([rpm / scale[0], V / scale[1], inc, r.thrust / scale[2], r.drag / scale[2],
                            r.torque / scale[3]])
    if density is not None:
        rows = np.column_stack([rows, np.full(len(rows), density)])
    lines = [sep.join(header)] + [sep.join(f"{x:.9g}" for x in row) for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return rows


NAMES = ["rpm", "airspeed (m/s)", "incidence (deg)", "thrust (N)", "drag (N)", "torque (N m)"]


@pytest.mark.parametrize("name", ["Air velocity (m/s)", "Flight speed (km/h)", "U (m/s)", "V (m/s)",
                                  "Forward speed (mph)"])
def test_an_airspeed_under_another_name_is_refused_by_its_unit(tmp_path, name):
    """A speed's unit says what the name does not: left unread, every point would be static
    (the audit's tunnel sweep was fitted as a static run, rms residual 0.22 against 0.023)."""
    path = tmp_path / "t.csv"
    _tunnel_csv(path, ["rpm", name, "incidence (deg)", "thrust (N)", "drag (N)", "torque (N m)"])
    with pytest.raises(DataError, match=rf"column '{re.escape(name)}' looks like an airspeed.*static"):
        read_loads(path)


def test_a_rotation_speed_in_a_linear_speed_unit_is_said_to_be_one():
    with pytest.raises(ValueError, match=r"'Speed \(m/s\)' is in m/s, a linear speed, not a rotation speed"):
        map_columns(["Speed (m/s)", "Thrust (N)"])


@pytest.mark.parametrize("name", ["Incidence angle (deg)", "Shaft angle (deg)", "beta (deg)", "Pitch angle (rad)"])
def test_an_angle_beside_an_airspeed_is_refused_by_its_unit(tmp_path, name):
    path = tmp_path / "t.csv"
    _tunnel_csv(path, ["rpm", "airspeed (m/s)", name, "thrust (N)", "drag (N)", "torque (N m)"])
    with pytest.raises(DataError, match=r"looks like a flow angle.*'incidence_deg'.*'collective_deg'.*axial flow"):
        read_loads(path)


def test_an_angle_on_a_static_stand_is_not_an_incidence():
    """Without an airspeed an angle cannot be the flow's: a static stand's (a servo's) is left unread."""
    cm = map_columns(["Time (s)", "Servo angle (deg)", "Thrust (N)", "Motor Optical Speed (RPM)"])
    assert "incidence_deg" not in cm.columns and "thrust" in cm.columns


@pytest.mark.parametrize("header, scale", [
    (["RPM", "airspeed_mps", "Incidence (°)", "Thrust (N)", "drag (N)", "torque_ozin"],
     (1.0, 1.0, 1.0, 4.4482216152605 / 16 * 0.0254)),
    (["rpm", "airspeed_kph", "Incidence [°]", "thrust (N)", "drag (N)", "torque_gcm"], (1.0, 1 / 3.6, 1.0, 9.80665e-5)),
    (["rpm", "airspeed (m/s)", "incidence (degrees)", "thrust (N)", "drag (N)", "Torque (kg·cm)"],
     (1.0, 1.0, 1.0, 9.80665e-2)),
    (["rpm", "airspeed (m/s)", "incidence (deg)", "thrust (N)", "drag (N)", "Torque (lb-in)"],
     (1.0, 1.0, 1.0, 4.4482216152605 * 0.0254)),
])
def test_common_unit_spellings_are_read(tmp_path, header, scale):
    path = tmp_path / "t.csv"
    rows = _tunnel_csv(path, header, scale=scale)
    d = read_loads(path)
    np.testing.assert_allclose(d.airspeed, rows[:, 1] * scale[1], rtol=1e-8)
    np.testing.assert_allclose(np.degrees(d.incidence), rows[:, 2], rtol=1e-8)
    np.testing.assert_allclose(d.measured["torque"], rows[:, 5] * scale[3], rtol=1e-8)


def test_a_tab_separated_file_with_decimal_commas_is_read(tmp_path):
    comma, tab = tmp_path / "c.csv", tmp_path / "t.tsv"
    _tunnel_csv(comma, NAMES)
    _tunnel_csv(tab, NAMES, sep="\t")
    tab.write_text(tab.read_text().replace(".", ","))
    a, b = read_loads(comma), read_loads(tab)
    np.testing.assert_allclose(b.omega, a.omega)
    np.testing.assert_allclose(b.measured["drag"], a.measured["drag"])


def test_the_air_density_column_is_read_and_the_fit_uses_it(tmp_path, capsys):
    """A stand's logged density (a Flight-Stand-style 'Air Density (kg/m³)') is the fit's air
    where no air option is given; beside a --rho that differs, a warning. (The audit's file at
    1.10 kg/m^3 was fitted at 1.225 with no word: alpha_L0 -3.57 deg against -4.24 deg.)"""
    path = tmp_path / "s.csv"
    _tunnel_csv(path, NAMES + ["Air Density (kg/m³)"], density=1.10)
    d = read_loads(path)
    assert d.air_density == pytest.approx(1.10)
    assert any("air density 1.1 kg/m^3 from 'Air Density (kg/m³)'" in n for n in d.notes)
    assert d.subset(d.omega > 0).air_density == pytest.approx(1.10)
    code, out, err = run(capsys, "fit", "loads", path, "--prop", "apce_8x6", "--out", tmp_path / "p.toml",
                         "--json")
    assert code == 0 and "the fit's air density is the file's, 1.1 kg/m^3" in err
    assert pm.read_params(tmp_path / "p.toml").air.rho == pytest.approx(1.10)
    code, out, err = run(capsys, "fit", "loads", path, "--prop", "apce_8x6", "--out", tmp_path / "q.toml", "--rho",
                         "1.225", "--json")
    assert code == 0 and "the air density from --rho, 1.225 kg/m^3, is not the file's 1.1 kg/m^3" in err
    bad = tmp_path / "b.csv"
    _tunnel_csv(bad, NAMES + ["rho"], density=1100.0)  # g/m^3 or a typo
    with pytest.raises(DataError, match=r"'rho' gives 1100 kg/m\^3; an air density must be in \[0.05, 5\]"):
        read_loads(bad)


def test_an_inplane_force_in_axial_flow_is_warned_of(tmp_path):
    """A drag column that is large where the points have no in-plane speed: the incidence is
    missing (here removed from a file at incidence), which the fit alone would not say."""
    path = tmp_path / "t.csv"
    _tunnel_csv(path, ["rpm", "airspeed (m/s)", "note", "thrust (N)", "drag (N)", "torque (N m)"],
                incidence_deg=(60.0, 90.0))
    d = read_loads(path)
    assert np.all(d.incidence == 0)
    w = sanity_check(d, pm.load_propeller("apce_8x6"))
    assert any("the measured drag exceeds 5% of the thrust" in x and "'incidence_deg'" in x for x in w), w
    honest = tmp_path / "h.csv"
    _tunnel_csv(honest, NAMES)
    assert not any("measured drag exceeds" in x for x in sanity_check(read_loads(honest),
                                                                        pm.load_propeller("apce_8x6")))


def test_upper_case_uiuc_names_give_the_diameter(tmp_path, capsys):
    geom = tmp_path / "NEWCO_9X6_GEOM.TXT"
    shutil.copyfile(resources.files("propmap") / "data" / "uiuc_v1" / "apce_9x6_geom.txt", geom)
    prop = pm.read_geometry(geom, n_blades=2)
    assert prop.diameter == pytest.approx(9 * 0.0254)


def test_a_hub_blade_count_in_the_run_names_is_checked_against_blades(tmp_path, capsys):
    """UIUC vol. 2 names the 3- and 4-blade hubs of one blade ``_3b``/``_4b`` and shares the
    2-blade geometry file: the count is compared with --blades (a 3-blade hub fitted as 2
    blades fitted as well, rms 0.0227 against 0.0234, the section absorbing the count), and the
    suffix alone, or a family geometry file, is not another propeller."""
    static = sorted(UIUC_V1.glob("apce_9x6_static_*.txt"))[0]
    sweep = sorted(UIUC_V1.glob("apce_9x6_rd*_*.txt"))[0]
    files = []
    for src in (static, sweep):
        dst = tmp_path / src.name.replace("apce_9x6_", "apce_9x6_3b_")
        shutil.copyfile(src, dst)
        files.append(dst)
    geom = tmp_path / "apce_9x6_geom.txt"
    shutil.copyfile(UIUC_V1 / "apce_9x6_geom.txt", geom)
    code, _, err = run(capsys, "fit", "loads", *files, "--prop", geom, "--blades", "2", "--out", tmp_path / "a.toml")
    assert code == 0 and "is named for a 3-blade hub ('_3b'), fitted with 2 blades: give --blades 3" in err
    code, _, err = run(capsys, "fit", "loads", *files, "--prop", geom, "--blades", "3", "--out", tmp_path / "b.toml")
    assert code == 0 and "named for" not in err, err
    family = tmp_path / "apce_geom.txt"  # a family geometry file covers its sizes
    shutil.copyfile(UIUC_V1 / "apce_9x6_geom.txt", family)
    code, _, err = run(capsys, "fit", "loads", static, "--prop", family, "--blades", "2", "--diameter-in", "9", "--out",
                       tmp_path / "c.toml")
    assert code == 0 and "named for" not in err, err


def test_the_fits_warnings_are_printed_once(tmp_path, capsys):
    """A fit's warning goes to standard error once; the report on standard output leaves it out
    (report.txt keeps it). The file at incidence with its incidence removed drives cd_min to its bound."""
    path = tmp_path / "t.csv"
    _tunnel_csv(path, ["rpm", "airspeed (m/s)", "note", "thrust (N)", "drag (N)", "torque (N m)"],
                incidence_deg=(60.0, 90.0))
    code, out, err = run(capsys, "fit", "loads", path, "--prop", "apce_8x6", "--out", tmp_path / "p.toml")
    assert code == 0
    said = [line for line in err.splitlines() if "ended at its lower bound" in line]
    assert len(said) == 1 and "ended at its lower bound" not in out, (err, out)
    assert "ended at its lower bound" in (tmp_path / "p.report.txt").read_text()
