"""A wind-tunnel balance's side force and hub moments in a load file (stop 91): not read (propmap
fits and validates the thrust, the in-plane force and the torque), and now said in a note; they
were left out without a word (a wind-tunnel data audit, 2026-11-30)."""

import pytest

from propmap.identify import read_loads

HEAD = "rpm,airspeed (m/s),incidence_deg,thrust (N),normal force (N),torque (N m)"
ROWS = ["6000,5,30,3.0,0.3,0.05", "6000,8,45,2.5,0.5,0.05", "6000,10,60,2.2,0.6,0.05"]


@pytest.mark.parametrize("extra", ["side force (N)", "Side_Force_N", "Pitching moment [N m]", "yawing_moment_nm",
                                   "Rolling Moment (N·m)"])
def test_a_side_load_column_is_named_in_a_note(tmp_path, extra):
    f = tmp_path / "tunnel.csv"
    f.write_text("\n".join([HEAD + "," + extra] + [r + ",0.01" for r in ROWS]) + "\n")
    data = read_loads(f, min_points=1)
    said = [n for n in data.notes if "are not compared with measurements" in n]
    assert len(said) == 1 and said[0].startswith(f"{extra!r} is not read")
    assert set(data.measured) == {"thrust", "drag", "torque"}  # (read as before)


def test_a_file_without_one_has_no_such_note(tmp_path):
    f = tmp_path / "tunnel.csv"
    f.write_text("\n".join([HEAD + ",side slip (deg)"] + [r + ",0" for r in ROWS]) + "\n")
    assert not [n for n in read_loads(f, min_points=1).notes if "are not compared with measurements" in n]
