"""What stop 95 left alone, fixed at stop 96 (2026-12-01). Each test fails on the code before its
fix; the guards say so. Data: the bundled example vehicles (the example quadrotor on the
catalogue's APC 8x6E, APC PE0 geometry; the NeuroBEM quadrotor's flight fit, docs/flight.md)."""

import json
import re

import numpy as np
import pytest

import propmap as pm

from .cli_helpers import example_quad as _quad
from .cli_helpers import run

GRID = ["--rpm", "2000:12000:4", "--airspeed", "0:10:3", "--incidence-deg", "0:180:4", "--check-points", "0"]


def _header_set(path):
    """The parameter set a C header names ("Parameters: NAME; air ...") and its airframe's drag row."""
    text = path.read_text()
    return (re.search(r"Parameters: ([^;]+);", text).group(1),
            re.search(r"_body_cd\[3\] = \{([^}]*)\}", text).group(1))


@pytest.mark.parametrize("given", [None, "generic"])
def test_a_c_header_takes_a_vehicle_whose_rotors_all_name_the_map_s_set(tmp_path, capsys, given):
    """`map --format c --vehicle` refused every rotor with a set of its own, even the map's own set:
    a vehicle whose rotors all name `generic` had no header, with or without `--params generic`
    (stop 96). Now the set every rotor names is the map's default, as in export-sim and
    trim-vehicle, and a rotor's set that is the map's is taken."""
    veh = _quad(tmp_path, rotor_params=["generic"] * 4)
    args = [] if given is None else ["--params", given]
    code, out, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID, *args,
                         "--out", tmp_path / "m.h")
    assert code == 0, err
    label, cd = _header_set(tmp_path / "m.h")
    assert label == "generic" and cd == "0, 0, 0"  # (the example quadrotor has no airframe drag table)


def test_a_c_header_refuses_a_rotor_set_other_than_the_map_s_naming_both(tmp_path, capsys):
    """Without --params, a rotor whose own set is not the map's is refused before the build, saying
    both sets and that --params gives one set for every rotor (which drops the rotors' own sets,
    said, as trim-vehicle and wrench drop them: tests/test_audit_vehicle_rule_stop96.py)."""
    veh = _quad(tmp_path, rotor_params=["generic", "gill2017-apc", "gill2017-apc", "gill2017-apc"])
    code, out, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID,
                         "--out", tmp_path / "m.h")
    assert code == 2 and err.count("\n") == 1
    assert err == ("propmap: error: --vehicle: rotor 1 carries its own parameter set (generic), not the map's, "
                   "calibrated:apce_8x6: a C header holds one map and one set (give --params, the set of every "
                   "rotor)\n")
    assert not (tmp_path / "m.h").exists()


def test_the_exports_take_the_rotors_one_set_before_the_vehicle_s_as_trim_vehicle_does(tmp_path, capsys):
    """A vehicle with its own set (a NeuroBEM flight fit) whose rotors all name gill2017-apc:
    trim-vehicle hovers on gill2017-apc (the set every rotor names comes first,
    propmap.resolve_vehicle), but export-sim --vehicle took the vehicle's own set and then refused
    the rotors' sets as not its own, and the C header refused them too (stop 96). Now both take the
    rotors' set, with the vehicle's own set's [body] table (the airframe's drag); the export's hover
    is trim-vehicle's."""
    veh = _quad(tmp_path, top='params = "fit.toml"', rotor_params=["gill2017-apc"] * 4)
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", veh, "--json", "--airspeed", "0")
    assert code == 0, err
    trim = json.loads(out)
    assert trim["params"] == "gill2017-apc"
    hover_rpm = trim["trims"][0]["rotor_rpm"][0]
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--target", "rotorpy",
                         "--out", tmp_path / "q.py", "--json")
    assert code == 0, err
    report = json.loads((tmp_path / "q.report.json").read_text())
    assert report["params"] == "gill2017-apc"
    assert report["errors"]["hover"]["rpm"] == pytest.approx(hover_rpm, rel=1e-6)
    code, out, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID,
                         "--out", tmp_path / "m.h")
    assert code == 0, err
    label, cd = _header_set(tmp_path / "m.h")
    body = pm.read_vehicle_with_params(veh)[0].body_drag  # (the flight fit's airframe, from the vehicle's own set)
    assert label == "gill2017-apc" and body is not None
    assert [float(x) for x in cd.split(",")] == pytest.approx(
        [1.225 * a / 2 for a in body.drag_area], rel=1e-12)


def test_a_rotor_naming_a_written_copy_of_the_map_s_set_is_that_set(tmp_path):
    """A set written to a parameter file and read back differs from the set in memory by the
    degrees' rounding of its angles (1 ulp in alpha_L0 for the generic set): compared exactly, a
    vehicle whose rotors name the written file was refused a map built with the set in memory,
    by VehicleMap and the C header (an audit, stop 96). Now the comparison is to 1e-12; another
    set is still refused."""
    from propmap.export_c import c_header_text
    from propmap.maps import build_map

    g = pm.resolve_params("generic")
    pm.write_params(tmp_path / "g.toml", g)
    assert pm.resolve_params(str(tmp_path / "g.toml")).alpha_L0 != g.alpha_L0  # (the rounding this is about)
    veh = _quad(tmp_path, rotor_params=[str(tmp_path / "g.toml")] * 4)
    ds = build_map(pm.load_propeller("apce_8x6"), g, [300.0, 600.0, 900.0], [0.0, 5.0], [0.0, 1.5], n_check=0)
    vehicle = pm.read_vehicle(veh)
    vm = pm.VehicleMap(vehicle, pm.RotorMap(ds))
    assert np.all(np.isfinite(vm.wrench([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [600.0] * 4).force))
    assert "vehicle_wrench" in c_header_text(pm.RotorMap(ds), tmp_path / "m.h", vehicle=vehicle)
    other = _quad(tmp_path, rotor_params=["gill2017-apc"] * 4)
    with pytest.raises(ValueError, match="rotor 1 has its own parameter set"):
        pm.VehicleMap(pm.read_vehicle(other), pm.RotorMap(ds))


def test_a_qprop_set_is_an_input_no_output_may_overwrite(tmp_path, capsys):
    """`loads --params qprop:q.csv --out q.csv` wrote its table over the QPROP file it read the set
    from (stop 96, found on reading the change): qprop:FILE's FILE is an input like any other."""
    from .test_qprop_file import propfile

    q = propfile(tmp_path / "q.csv")
    before = q.read_text()
    (tmp_path / "pts.csv").write_text("rpm,airspeed,incidence_deg\n5000,0,0\n")
    code, out, err = run(capsys, "loads", "apce_8x6", "--params", f"qprop:{q}", "--points", tmp_path / "pts.csv",
                         "--out", q)
    assert code == 2 and "--out: " in err and "refusing to overwrite an input" in err, err
    assert q.read_text() == before


def test_a_vehicle_rotor_s_qprop_set_is_read_from_the_vehicle_s_folder(tmp_path, capsys, monkeypatch):
    """A rotor's `params = "qprop:FILE"` was read from the working folder, where every other file a
    vehicle names is read from the vehicle file's (stop 96): run from elsewhere, the vehicle was
    refused ("no such file"). Now it is the vehicle's folder's, and an input of the commands."""
    from propmap.vehicle.own_set import vehicle_files

    from .test_qprop_file import propfile

    folder = tmp_path / "a"
    folder.mkdir()
    propfile(folder / "p.qprop")
    veh = _quad(folder, rotor_params=["qprop:p.qprop"] * 4)
    monkeypatch.chdir(tmp_path)
    r = pm.resolve_vehicle(veh)
    assert r.params.label == f"qprop:{folder / 'p.qprop'}" and r.params.cl_alpha == 5.8
    assert folder / "p.qprop" in vehicle_files(veh)
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", veh, "--json", "--airspeed", "0")
    assert code == 0, err
    assert json.loads(out)["params"] == f"qprop:{folder / 'p.qprop'}"
