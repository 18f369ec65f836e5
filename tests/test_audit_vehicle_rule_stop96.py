"""An audit of the one rule for a vehicle's parameter sets (propmap.resolve_vehicle) against every
entry point that takes a vehicle, stop 96 (2026-12-01). Each test failed on the code before its
fix (commit 02b6f16), but the guards; the last one settled a design question the audit left open. Data: the example
quadrotor (four catalogue apce_8x6) with added entries, and the NeuroBEM flight fit as a parameter
file (its [body] table, rho 1.204)."""

import json
import math
import re
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
import propmap.io.params_file as params_file
import propmap.io.toml_file as toml_file
import propmap.vehicle.file as vehicle_file
import propmap.vehicle.own_set as own_set

from .cli_helpers import example_quad as _quad
from .cli_helpers import run

PE0 = Path(pm.__file__).parent / "data" / "apc_pe0" / "8x6E-PERF.PE0"  # (the catalogue apce_8x6's geometry file)
GRID = ["--rpm", "2000:12000:4", "--airspeed", "0:10:3", "--incidence-deg", "0:180:4", "--check-points", "0"]


def _report(path):
    return json.loads(path.with_name(path.stem + ".report.json").read_text())


def test_a_one_propeller_export_of_mixed_rotor_sets_takes_the_vehicle_s_own_set(tmp_path, capsys):
    """Rotors 2-4 take the vehicle's fit (rho 1.204); export-sim took calibrated:apce_8x6 (1.225), refusals too."""
    veh = _quad(tmp_path, top='params = "fit.toml"', rotor_params=["gill2017-apc", "", "", ""])
    assert pm.resolve_vehicle(veh).sets[1:] == (str(tmp_path / "fit.toml"),) * 3
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--target", "rotorpy", "--hover-rpm",
                         "5000", "--points", "200", "--out", tmp_path / "q.py")
    assert code == 0, err
    report = _report(tmp_path / "q.py")
    assert report["params"] == str(tmp_path / "fit.toml") and report["rho"] == 1.204
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--target", "gz-sim", "--points", "200",
                         "--out", tmp_path / "g.sdf")
    assert code == 2 and f"rotor(s) 1 carry their own parameter set, not {tmp_path / 'fit.toml'}," in err, err
    code, out, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID, "--out", tmp_path / "m.h")
    assert code == 2 and f"(gill2017-apc), not the map's, {tmp_path / 'fit.toml'}:" in err, err


def test_an_export_of_the_rotors_geometry_from_a_file_takes_their_calibrated_set(tmp_path, capsys):
    """quadrotor from 8x6E-PERF.PE0: export-sim pinned 5187.09 rpm (generic), trim-vehicle 5386.76 (calibrated)."""
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "quadrotor", "--json", "--airspeed", "0")
    assert code == 0, err
    hover = json.loads(out)["trims"][0]["rotor_rpm"][0]
    assert hover == pytest.approx(5386.76, abs=0.01)
    code, out, err = run(capsys, "export-sim", PE0, "--vehicle", "quadrotor", "--target", "rotorpy", "--points",
                         "200", "--out", tmp_path / "q.py")
    assert code == 0, err
    report = _report(tmp_path / "q.py")
    assert report["params"] == "calibrated:apce_8x6"
    assert report["errors"]["hover"]["rpm"] == pytest.approx(hover, rel=1e-9)


def _generic_map():
    prop = pm.load_propeller("apce_8x6")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = pm.build_map(prop, pm.generic_params(), np.linspace(2000, 12000, 4) * math.pi / 30,
                          np.linspace(0, 10, 3), np.radians(np.linspace(0, 180, 4)), params_label="generic",
                          n_check=0)
    return pm.RotorMap(ds)


def test_the_c_header_takes_a_resolved_vehicle_whose_rotors_carry_the_map_s_set(tmp_path):
    """Rotors all on generic, a generic map: VehicleMap and `map --format c` took them, c_header_text raised."""
    from propmap.export_c import c_header_text

    veh, params = pm.read_vehicle_with_params(_quad(tmp_path, rotor_params=["generic"] * 4))
    assert params == pm.generic_params() and veh.rotors[0].params == params
    rm = _generic_map()
    pm.VehicleMap(veh, rm)  # (accepted)
    text = c_header_text(rm, tmp_path / "m.h", vehicle=veh)
    assert "_vehicle_wrench" in text
    # (the map's set in other air on a rotor: taken, in the map's air, and said, as VehicleMap says it)
    thin_set = pm.generic_params().replace(air=pm.Air(rho=1.0))
    thin = replace(veh, rotors=tuple(replace(r, params=thin_set) for r in veh.rotors))
    for make in (lambda: pm.VehicleMap(thin, rm), lambda: c_header_text(rm, tmp_path / "m.h", vehicle=thin)):
        with pytest.warns(UserWarning, match=r"rotor 1 has its own parameter set in other air \(rho 1 kg/m\^3\)"):
            make()


def test_the_c_header_still_refuses_a_rotor_set_other_than_the_map_s(tmp_path):
    """Guard (passes before too): a rotor whose own set is not the map's is refused, as VehicleMap refuses it."""
    from propmap.export_c import c_header_text

    veh = pm.read_vehicle(_quad(tmp_path, rotor_params=["gill2017-apc", "", "", ""]))
    rm = _generic_map()
    with pytest.raises(ValueError, match="rotor 1"):
        pm.VehicleMap(veh, rm)
    with pytest.raises(ValueError, match=r"rotor 1 has its own parameter set"):
        c_header_text(rm, tmp_path / "m.h", vehicle=veh)


def _count_parses(monkeypatch):
    calls = []
    real = toml_file.load_toml

    def counted(path, *args, **kwargs):
        calls.append(Path(path).name)
        return real(path, *args, **kwargs)

    for module in (toml_file, vehicle_file, own_set, params_file):
        monkeypatch.setattr(module, "load_toml", counted)
    return calls


def test_a_set_every_rotor_names_is_read_once(tmp_path, monkeypatch):
    """Rotors all naming fit.toml: resolve_vehicle parsed it 5 times (once a rotor, then again), trim-vehicle 6."""
    veh = _quad(tmp_path, rotor_params=["fit.toml"] * 4)
    calls = _count_parses(monkeypatch)
    r = pm.resolve_vehicle(veh)
    assert calls.count("fit.toml") == 1, calls
    assert r.params == pm.read_params(tmp_path / "fit.toml") and r.air.rho == 1.204
    assert all(rotor.params is r.params for rotor in r.vehicle.rotors)  # (one object, as the rotors' propeller)


@pytest.mark.parametrize("command", ["export-sim", "map"])
def test_the_one_propeller_exports_read_the_vehicle_file_as_often_as_wrench(tmp_path, capsys, monkeypatch, command):
    """Vehicle file parses: export-sim and map --format c 6 each, trim-vehicle 1, wrench 2 (counted)."""
    veh = _quad(tmp_path, top='params = "fit.toml"')
    calls = _count_parses(monkeypatch)
    if command == "export-sim":
        args = ["export-sim", "apce_8x6", "--vehicle", veh, "--target", "gz-sim", "--points", "200", "--out",
                tmp_path / "g.sdf"]
    else:
        args = ["map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID, "--out", tmp_path / "m.h"]
    code, out, err = run(capsys, *args)
    assert code == 0, err
    assert calls.count("v.toml") <= 2, calls
    header = (tmp_path / "m.h").read_text() if command == "map" else ""
    if command == "map":  # (the vehicle's own set and its airframe, as before)
        assert re.search(r"Parameters: ([^;]+);", header).group(1) == str(tmp_path / "fit.toml")


def test_a_given_set_replaces_the_rotors_own_sets_in_every_vehicle_command(tmp_path, capsys):
    """Rotors all on generic, --params gill2017-apc: trim-vehicle hovers at 5272.55 rpm, export-sim exited 2 (a
    design question the audit left open; settled at stop 96: --params gives every rotor's set in the exports too,
    the rotors' own dropped and said)."""
    veh = _quad(tmp_path, rotor_params=["generic"] * 4)
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", veh, "--params", "gill2017-apc", "--json")
    assert code == 0 and "are not used: --params gives every rotor's set" in err, err
    hover = json.loads(out)["trims"][0]["rotor_rpm"][0]
    assert hover == pytest.approx(5272.55, abs=0.01)
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--params", "gill2017-apc", "--target",
                         "gz-sim", "--points", "200", "--out", tmp_path / "g.sdf")
    assert code == 0, err
    assert "rotor(s) 1, 2, 3, 4 are not used: --params gives every rotor's set" in err, err
    assert _report(tmp_path / "g.sdf")["errors"]["hover"]["rpm"] == pytest.approx(hover, rel=1e-9)
    code, out, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, "--params", "gill2017-apc",
                         *GRID, "--out", tmp_path / "m.h")
    assert code == 0 and "are not used: --params gives every rotor's set" in err, err
    assert re.search(r"Parameters: ([^;]+);", (tmp_path / "m.h").read_text()).group(1) == "gill2017-apc"
