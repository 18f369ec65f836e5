"""Notes of a load file (stop 91): a wind-tunnel balance's side force and pitching and yawing
moments are not read (propmap fits and validates the thrust, the in-plane force, the torque and,
since 2026-12-01, beside a torque, the rolling moment), and now said in a note, where they were
left out without a word (a wind-tunnel data audit, 2026-11-30); a throttle's percent cells within 1
get one note, not two that contradict each other."""

import pytest

from propmap.identify import read_loads

HEAD = "rpm,airspeed (m/s),incidence_deg,thrust (N),normal force (N),torque (N m)"
ROWS = ["6000,5,30,3.0,0.3,0.05", "6000,8,45,2.5,0.5,0.05", "6000,10,60,2.2,0.6,0.05"]


@pytest.mark.parametrize("extra", ["side force (N)", "Side_Force_N", "Pitching moment [N m]", "yawing_moment_nm",
                                   "Side force, N", "side_force_lbf"])
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


def test_a_rolling_moment_beside_no_torque_column_is_said_to_be_the_torque_if_about_the_axis(tmp_path):
    """A balance's 'rolling moment' in a file with no torque column is not read, and the note says
    that the moment about the rotor axis is the torque (a review); with a torque column it is read
    as the hub's rolling moment (since 2026-12-01: noted as not read before), in N m from its unit."""
    f = tmp_path / "t.csv"
    f.write_text("rpm,airspeed (m/s),incidence_deg,thrust (N),rolling moment (N mm)\n"
                 "6000,5,30,3.0,50\n6000,8,45,2.5,50\n")
    data = read_loads(f, min_points=1)
    said = [n for n in data.notes if "rolling moment (N mm)' is not read" in n]
    assert len(said) == 1 and "its moment about the rotor axis, the torque: name that column 'torque'" in said[0]
    assert set(data.measured) == {"thrust"} and not [n for n in data.notes if "converted" in n]
    for name, factor in (("rolling moment (N m)", 1.0), ("Rolling Moment (N·m)", 1.0), ("rolling_moment_N_m", 1.0),
                         ("roll moment (N mm)", 1e-3)):
        f.write_text(f"rpm,airspeed (m/s),incidence_deg,thrust (N),torque (N m),{name}\n"
                     "6000,5,30,3.0,0.05,10\n6000,8,45,2.5,0.05,20\n")
        data = read_loads(f, min_points=1)
        assert not [n for n in data.notes if "not read" in n], name
        assert data.measured["rolling_moment"].tolist() == pytest.approx([10 * factor, 20 * factor]), name
