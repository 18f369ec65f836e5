"""Notes of a load file (stop 91): a wind-tunnel balance's side force and hub moments are not
read (propmap fits and validates the thrust, the in-plane force and the torque), and now said in
a note, where they were left out without a word (a wind-tunnel data audit, 2026-11-30); a
throttle's percent cells within 1 get one note, not two that contradict each other."""

import pytest

from propmap.identify import read_loads

HEAD = "rpm,airspeed (m/s),incidence_deg,thrust (N),normal force (N),torque (N m)"
ROWS = ["6000,5,30,3.0,0.3,0.05", "6000,8,45,2.5,0.5,0.05", "6000,10,60,2.2,0.6,0.05"]


@pytest.mark.parametrize("extra", ["side force (N)", "Side_Force_N", "Pitching moment [N m]", "yawing_moment_nm",
                                   "Rolling Moment (N·m)", "Side force, N", "side_force_lbf", "rolling_moment_N_m"])
def test_a_side_load_column_is_named_in_a_note(tmp_path, extra):
    f = tmp_path / "tunnel.csv"
    quoted = f'"{extra}"' if "," in extra else extra  # (a CSV header's comma inside quotes)
    f.write_text("\n".join([HEAD + "," + quoted] + [r + ",0.01" for r in ROWS]) + "\n")
    data = read_loads(f, min_points=1)
    said = [n for n in data.notes if "are not compared with measurements" in n]
    assert len(said) == 1 and said[0].startswith(f"{extra!r} is not read")
    assert set(data.measured) == {"thrust", "drag", "torque"}  # (read as before)


def test_a_file_without_one_has_no_such_note(tmp_path):
    f = tmp_path / "tunnel.csv"
    f.write_text("\n".join([HEAD + ",side slip (deg)"] + [r + ",0" for r in ROWS]) + "\n")
    assert not [n for n in read_loads(f, min_points=1).notes if "are not compared with measurements" in n]


def test_percent_cells_within_one_get_one_note(tmp_path):
    """A throttle column over 0.3%-0.8% cells got a note that it is read in percent and then one that
    it is read as a fraction (an audit of stop 90): now only the fraction's; 30%-80% keep the
    percent's, and both group the rows by the same steps."""
    notes = {}
    for cells in (["0.3%", "0.4%", "0.5%", "0.6%", "0.7%", "0.8%"], ["30%", "40%", "50%", "60%", "70%", "80%"]):
        f = tmp_path / "steps.csv"
        f.write_text("Throttle,rpm,Thrust (g),Torque (N m)\n" + "".join(
            f"{c},{4000 + 1000 * k},{100 + 80 * k},{0.01 + 0.005 * k}\n" for k, c in enumerate(cells)))
        data = read_loads(f)
        notes[cells[0]] = [n for n in data.notes if n.startswith("'Throttle'")]
        assert len(set(data.group)) == 6
    assert notes["0.3%"] == ["'Throttle': read as a throttle fraction (0-1), not percent: its values reach only 0.8"]
    assert notes["30%"] == ["'Throttle': its values end in %: read as a throttle in percent"]


def test_a_hub_moment_beside_no_torque_column_is_said_to_be_the_torque_if_about_the_axis(tmp_path):
    """A balance's 'rolling moment' in a file with no torque column: the note adds that the moment
    about the rotor axis is the torque (a review); with a torque column it does not."""
    f = tmp_path / "t.csv"
    f.write_text("rpm,airspeed (m/s),incidence_deg,thrust (N),rolling moment (N m)\n"
                 "6000,5,30,3.0,0.05\n6000,8,45,2.5,0.05\n")
    said = [n for n in read_loads(f, min_points=1).notes if "are not compared with measurements" in n]
    assert said and said[0].endswith("a balance's moment about the rotor axis is the torque: name that column "
                                     "'torque'")
    f.write_text("rpm,airspeed (m/s),incidence_deg,thrust (N),torque (N m),rolling moment (N m)\n"
                 "6000,5,30,3.0,0.05,0.01\n6000,8,45,2.5,0.05,0.01\n")
    said = [n for n in read_loads(f, min_points=1).notes if "are not compared with measurements" in n]
    assert said and "is the torque" not in said[0]
