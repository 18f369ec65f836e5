"""Stop 106: defects found by this stop's audits and rereads, each test failing on the code before its fix, except the
guards said so (what a fix must keep: files that read before). Data: synthetic load files (a collective sweep of the
catalogue's APC 10x7E, UIUC geometry)."""

import re

import pytest

from propmap.cli.main import main
from propmap.identify import DataError, read_loads


# ---- a blade pitch column with the station it is taken at (identify/unread.py) ------------------------------------
def _sweep(path, name, airspeed=False):
    """A collective and rpm sweep whose blade angle is in column ``name`` (and a 5 m/s airspeed column)."""
    head = "rpm," + ("airspeed (m/s)," if airspeed else "") + f"{name},thrust (N),torque (N m)\n"
    v = "5," if airspeed else ""
    rows = "".join(f"{4000 + 500 * c},{v}{20 + c},{1 + 0.1 * c},{0.02 + 0.001 * c}\n" for c in range(6))
    path.write_text(head + rows)
    return path


@pytest.mark.parametrize("name", ["Blade angle 75% (deg)", "blade_pitch_75_deg", "Pitch at 0.75R (deg)",
                                  "pitch 3/4 (°)", "blade setting angle (deg)", "collective pitch"])
@pytest.mark.parametrize("airspeed", [False, True])
def test_a_blade_pitch_with_its_station_is_refused_as_a_blade_pitch(tmp_path, name, airspeed):
    """A variable-pitch propeller's sweep with its blade angle as 'Blade angle 75% (deg)' or 'blade_pitch_75_deg' was
    read at collective 0 without a word in a static file (the measured thrust then 1.65x the model's; only the
    thrust's size was warned of), and refused as a flow angle beside an airspeed (2026-12-02)."""
    with pytest.raises(DataError, match=f"column '{re.escape(name)}' looks like a blade pitch setting, which propmap "
                                        r"reads only as 'collective_deg'.*less the geometry's at the same station"):
        read_loads(_sweep(tmp_path / "s.csv", name, airspeed))


def test_a_points_file_with_a_blade_pitch_at_a_station_is_refused(tmp_path, capsys):
    """loads --points solved a 'blade_pitch_75_deg' column's rows at collective 0."""
    pts = tmp_path / "p.csv"
    pts.write_text("rpm,airspeed,incidence_deg,blade_pitch_75_deg\n5000,0,0,24\n")
    assert main(["loads", "apce_10x7", "--points", str(pts), "--out", str(tmp_path / "o.csv")]) == 2
    assert "column 'blade_pitch_75_deg' looks like a blade pitch setting" in capsys.readouterr().err


def test_a_blade_pitch_word_among_others_is_noted(tmp_path):
    """'pitch trim (deg)' may be a blade pitch setting: a note names collective_deg, the file reads."""
    data = read_loads(_sweep(tmp_path / "s.csv", "pitch trim (deg)"))
    assert data.collective is None and data.n == 6
    assert any("column 'pitch trim (deg)' is not read; if it is a blade pitch setting, name it 'collective_deg'" in n
               for n in data.notes), data.notes


@pytest.mark.parametrize("name", ["angle_pitch", "pitch rate (deg/s)", "Pitching moment (N m)", "prop_pitch_in",
                                  "pitch (in)", "vehicle pitch (deg)"])
def test_other_pitches_read_as_before(tmp_path, name):
    """Guard (passed before the fix): an attitude's pitch, a rate, a moment and a pitch in inches are no blade pitch
    setting: the file reads, with no note on a blade pitch."""
    data = read_loads(_sweep(tmp_path / "s.csv", name))
    assert data.collective is None and data.n == 6
    assert not any("blade pitch" in n for n in data.notes), data.notes


@pytest.mark.parametrize("name", ["Pitch (deg)", "sting pitch (deg)"])
def test_a_bare_pitch_beside_an_airspeed_is_still_refused_as_a_flow_angle(tmp_path, name):
    """Guard (passed before the fix): beside an airspeed a bare 'Pitch (deg)' may be a tunnel sting's, the flow's
    angle: refused as a flow angle, whose message names collective_deg too."""
    with pytest.raises(DataError, match=f"column '{re.escape(name)}' looks like a flow angle.*'collective_deg'"):
        read_loads(_sweep(tmp_path / "s.csv", name, airspeed=True))


# ---- unknown keys of a parameter file's tables and a vehicle file: the nearest valid one (io/toml_file.py) -----------
@pytest.mark.parametrize("table, typo, meant", [("body", "wash_factr", "wash_factor"), ("coverage", "J_maxx", "J_max"),
                                                ("vehicle", "gravty", "gravity"), ("rotor", "Spin", "spin")])
def test_an_unknown_key_in_a_table_names_the_nearest_valid_one(tmp_path, capsys, table, typo, meant):
    """A parameter file's top level said 'did you mean cl_alpha?' for 'cl_alhpa', its [body] and [coverage] tables and
    the vehicle file only listed every valid key (2026-12-02)."""
    from pathlib import Path

    import propmap as pm

    examples = Path(pm.__file__).parent / "data" / "examples"
    if table in ("body", "coverage"):
        text = (examples / "neurobem_quadrotor.params.toml").read_text()
        key = {"body": "wash_factor =", "coverage": "J_max ="}[table]
        path = tmp_path / "p.toml"
        path.write_text(text.replace(key, f"{typo} =", 1))
        args = ["loads", "apce_8x6", "--rpm", "5000", "--params", str(path)]
    else:
        text = (examples / "quadrotor.toml").read_text()
        key = {"vehicle": "gravity =", "rotor": "spin ="}[table]
        path = tmp_path / "v.toml"
        path.write_text(text.replace(key, f"{typo} =", 1))
        args = ["trim-vehicle", "--vehicle", str(path), "--airspeed", "0"]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert re.search(rf"unknown key\(s\) '?{typo}'?: did you mean {meant}\? \((allowed|valid): ", err), err
