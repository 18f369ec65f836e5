"""The vehicle commands' default parameter set for a rotor without one of its own (stop 91): its
propeller's default as `loads`, `map` and `export-sim` take it, a catalogue propeller's calibrated
set, else the generic set. Before, `trim-vehicle` and `wrench` gave every such rotor the generic
set: the bundled example quadrotor (four APC 8x6E, UIUC vol. 1's calibrated set) hovered at 5187
rpm in `trim-vehicle` and at 5387 rpm in `export-sim --vehicle`."""

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

import propmap as pm
from propmap.cli.main import cli
from propmap.core.units import RPM

EXAMPLE = Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml"


def _run(*args):
    r = CliRunner().invoke(cli, list(args))
    assert r.exit_code == 0, r.output
    return r


def _trim(vehicle, *extra):
    return json.loads(_run("trim-vehicle", "--vehicle", str(vehicle), "--json", *extra).stdout)


def test_trim_vehicle_hovers_the_example_at_the_export_hover_rpm(tmp_path):
    """trim-vehicle's hover equals export-sim --vehicle's for the same rotors (one set: the
    calibrated apce_8x6), and both equal the hover of the calibrated set through the API."""
    t = _trim("quadrotor")
    assert t["params"] == "calibrated:apce_8x6"
    rpm = t["trims"][0]["rotor_rpm"]
    out = tmp_path / "rp.py"
    e = json.loads(_run("export-sim", "apce_8x6", "--vehicle", "quadrotor", "--target", "rotorpy", "--out",
                        str(out), "--json").stdout)
    assert rpm == pytest.approx([e["envelope"]["hover_rpm"]] * 4, rel=1e-6)
    veh = pm.read_vehicle(EXAMPLE)
    w = pm.hover_omega(veh, pm.resolve_params("calibrated:apce_8x6"))
    assert rpm == pytest.approx([w / RPM] * 4, rel=1e-6)
    assert rpm[0] == pytest.approx(5386.76, abs=0.05)  # regression value (calibration of 2026-11-29)


def test_an_explicit_generic_set_keeps_its_own_hover():
    """--params generic gives every rotor the generic set: a lower hover rpm than the calibrated
    set's (the generic lift is larger on this propeller), regression value 5187.1 rpm."""
    t = _trim("quadrotor", "--params", "generic")
    assert t["params"] == "generic"
    assert t["trims"][0]["rotor_rpm"][0] == pytest.approx(5187.1, abs=0.05)


def test_a_vehicle_of_two_catalogue_propellers_takes_each_ones_calibrated_set(tmp_path):
    """Rotors 3 and 4 of the example given APC 8x4E: each rotor takes its own propeller's calibrated
    set (the label names both), and its hover thrust is that set's on that propeller."""
    text = EXAMPLE.read_text()
    parts = text.split("[[rotors]]")
    for k in (3, 4):
        parts[k] = parts[k].replace('"apce_8x6"', '"apce_8x4"')
    veh_file = tmp_path / "mixed.toml"
    veh_file.write_text("[[rotors]]".join(parts))
    r = _run("trim-vehicle", "--vehicle", str(veh_file))
    assert re.search(r"params the vehicle's rotor sets: calibrated:apce_8x6, calibrated:apce_8x4\)", r.stdout)
    t = _trim(veh_file)
    assert "calibrated:apce_8x6" in t["params"] and "calibrated:apce_8x4" in t["params"]
    assert t["rotor_params"] == ["calibrated:apce_8x6"] * 2 + ["calibrated:apce_8x4"] * 2  # (each rotor's)
    # each rotor's thrust at the trim is that of its own calibrated set at its rpm
    veh = pm.read_vehicle(veh_file)
    for k, rpm in enumerate(t["trims"][0]["rotor_rpm"]):
        name = veh.rotors[k].propeller.name
        ld = pm.rotor_loads(pm.load_propeller(name), pm.resolve_params(f"calibrated:{name}"), rpm * RPM, 0.0, 0.0,
                            air=pm.resolve_params(f"calibrated:{name}").air)
        share = float(ld.thrust)
        assert share == pytest.approx(veh.weight / 4, rel=0.05)  # near a quarter of the weight (offset arms)
    # the same vehicle with one set for all (generic) trims elsewhere
    g = _trim(veh_file, "--params", "generic")
    assert g["trims"][0]["rotor_rpm"] != pytest.approx(t["trims"][0]["rotor_rpm"], rel=1e-3)


def test_a_rotor_not_in_the_catalogue_keeps_the_generic_set(tmp_path):
    """The NeuroBEM quadrotor's lumped blade is no catalogue propeller: without the vehicle file's own
    set (its top-level params, the example's since 2026-11-30: tests/test_vehicle_params.py), the
    generic set, as before."""
    examples = EXAMPLE.parent
    (tmp_path / "neurobem_5.1x4.8_geom.txt").write_bytes((examples / "neurobem_5.1x4.8_geom.txt").read_bytes())
    text = (examples / "neurobem_quadrotor.toml").read_text()
    line = 'params = "neurobem_quadrotor.params.toml"\n'
    assert text.count(line) == 1
    (tmp_path / "v.toml").write_text(text.replace(line, ""))
    t = _trim(tmp_path / "v.toml")
    assert t["params"] == "generic"
    assert t["trims"][0]["rotor_rpm"][0] == pytest.approx(1282.4 / RPM, abs=0.5)  # docs/flight.md's hover
