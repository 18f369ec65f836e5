"""A mutation audit of stop 96 (5b91912..d4d13db): the one rule for a vehicle's parameter sets in the
one-propeller exports (cli/_vehicle.py, cli/map.py, cli/export_sim.py, vehicle/own_set.py,
export_c.py), SectionParams.same_section, and the QPROP propeller-file reader (io/qprop_file.py,
--params qprop:FILE). Each test asserts documented behaviour that a mutant of the changed lines broke
while the stop's own tests passed; the mutant is named in the test. Data: the example quadrotor
(four catalogue apce_8x6), the NeuroBEM flight fit, and QPROP files written here."""

from __future__ import annotations

import json
import math
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

import propmap as pm

from .cli_helpers import one_line_error, run

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
FIT = EXAMPLES / "neurobem_quadrotor.params.toml"  # (a flight fit: a [body] table, rho 1.204)
GRID = ["--rpm", "2000:12000:4", "--airspeed", "0:10:3", "--incidence-deg", "0:180:4", "--check-points", "0"]


def _quad(tmp_path, top="", rotor_params=None, first_propeller=None):
    """The example quadrotor with a top-level entry, each rotor's ``params`` (None: none) and, where
    given, another propeller on rotor 1."""
    head, *rotors = (EXAMPLES / "quadrotor.toml").read_text().split("[[rotors]]")
    if first_propeller is not None:
        assert 'propeller = "apce_8x6"' in rotors[0]
        rotors[0] = rotors[0].replace('propeller = "apce_8x6"', f'propeller = "{first_propeller}"')
    extra = [""] * 4 if rotor_params is None else [f'params = "{p}"' if p else "" for p in rotor_params]
    text = head + top + "\n" + "".join("[[rotors]]" + r.rstrip("\n") + "\n" + e + "\n" for r, e in zip(rotors, extra))
    shutil.copy(FIT, tmp_path / "fit.toml")
    (tmp_path / "v.toml").write_text(text, encoding="utf-8")
    return tmp_path / "v.toml"


# --- SectionParams.same_section (core/airfoil.py)

def test_same_section_is_equality_to_1e_12_but_for_air_and_label():
    """Mutants: the tolerance 1e-12 -> 1e-3, abs_tol 1e-300 -> 1e-6, the type check dropped (None and
    a set of another model raised AttributeError / KeyError instead of False)."""
    g = pm.resolve_params("generic")
    assert g.same_section(g.replace(air=pm.Air(rho=1.0), label="elsewhere"))
    assert g.same_section(g.replace(cl_alpha=g.cl_alpha * (1 + 1e-13)))  # (a written copy's rounding)
    assert not g.same_section(g.replace(cl_alpha=g.cl_alpha * (1 + 1e-9)))  # (6.4e-9 apart: another set)
    assert not g.same_section(g.replace(cd_min=g.cd_min * (1 + 1e-6)))
    apc = pm.resolve_params("gill2017-apc")
    for other in (None, "generic", apc):
        assert g.same_section(other) is False
    assert apc.same_section(g) is False and apc.same_section(apc.replace(air=pm.Air(rho=1.0)))


# --- the C header (export_c.py) and map --format c --vehicle (cli/map.py)

def test_a_c_header_of_a_map_without_its_set_recorded_refuses_any_rotor_set(tmp_path):
    """export_c: "any set of its own for a map that does not record its set" is refused (mutant: a
    map without the record took every rotor's set)."""
    from propmap.export_c import c_header_text

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = pm.build_map(pm.load_propeller("apce_8x6"), pm.generic_params(),
                          np.linspace(2000, 12000, 4) * math.pi / 30, np.linspace(0, 10, 3),
                          np.radians(np.linspace(0, 180, 4)), params_label="generic", n_check=0)
    bare = ds.copy()
    del bare.attrs["params_json"]  # (a map that does not record its model)
    veh, params = pm.read_vehicle_with_params(_quad(tmp_path, rotor_params=["generic"] * 4))
    assert veh.rotors[0].params == params == pm.generic_params()
    assert "_vehicle_wrench" in c_header_text(pm.RotorMap(ds), tmp_path / "m.h", vehicle=veh)  # (recorded: taken)
    with pytest.raises(ValueError, match="rotor 1 has its own parameter set: a C header holds one map"):
        c_header_text(pm.RotorMap(bare), tmp_path / "m.h", vehicle=veh)
    assert "_vehicle_wrench" in c_header_text(pm.RotorMap(bare), tmp_path / "m.h",
                                              vehicle=pm.read_vehicle(EXAMPLES / "quadrotor.toml"))


def test_map_c_takes_the_rotors_sets_off_so_rho_gives_every_rotors_air_without_a_warning(tmp_path, capsys):
    """Rotors all on generic, `map --format c --vehicle --rho 1.0`: the rotors' own set (the map's) is
    taken off the rotors, every rotor is in the map's air, chosen by --rho, and nothing is said of
    "other air" (mutant: the rotors kept their sets and the header warned of rho 1.225 on all four)."""
    veh = _quad(tmp_path, rotor_params=["generic"] * 4)
    code, out, err = run(capsys, "map", "apce_8x6", "--format", "c", "--vehicle", veh, *GRID, "--rho", "1.0",
                         "--out", tmp_path / "m.h")
    assert code == 0, err
    assert "other air" not in err, err
    text = (tmp_path / "m.h").read_text()
    assert "Parameters: generic;" in text and "vehicle_wrench" in text


def test_map_c_names_another_chord_for_a_rotor_of_the_maps_size(tmp_path, capsys):
    """apce_8x4 and the quadrotor's apce_8x6 are both 8 in, two-bladed: the refusal says the blade
    differs (mutant: the hint dropped, the message read as if the sizes were the point)."""
    code, out, err = run(capsys, "map", "apce_8x4", "--format", "c", "--vehicle", "quadrotor", *GRID,
                         "--out", tmp_path / "m.h")
    assert one_line_error(code, err, "--vehicle: rotor 1 carries apce_8x6 (0.2032 m, 2 blades, another chord or "
                                     "blade angle), not the map's apce_8x4 (0.2032 m, 2 blades)"), err
    assert not (tmp_path / "m.h").exists()


# --- export-sim --vehicle (cli/export_sim.py, cli/_vehicle.py, vehicle/own_set.py)

def test_export_sim_refusal_of_the_rotors_own_sets_names_params(tmp_path, capsys):
    """Without --params, the refusal names --params as the way to one set (mutant: it named only
    --hover-rpm)."""
    veh = _quad(tmp_path, top='params = "fit.toml"', rotor_params=["gill2017-apc", "", "", ""])
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--target", "gz-sim", "--points", "200",
                         "--out", tmp_path / "g.sdf")
    assert one_line_error(code, err, "so the vehicle's hover is not apce_8x6's with it: give --params (the set of "
                                     "every rotor), or --hover-rpm instead of --vehicle"), err


def test_export_sim_airframe_is_the_vehicle_files_where_its_set_has_no_body_table(tmp_path, capsys):
    """The vehicle's own set a parameter file without a [body] table: the rotorpy file's drag comes
    from the vehicle file, and no flight fit's table is claimed (mutant: "the [body] table of g.toml
    (a flight fit)")."""
    pm.write_params(tmp_path / "g.toml", pm.resolve_params("generic"))
    veh = _quad(tmp_path, top=f'params = "{tmp_path / "g.toml"}"')
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--target", "rotorpy", "--points",
                         "200", "--out", tmp_path / "q.py", "--json")
    assert code == 0, err
    assert json.loads(out)["params"] == str(tmp_path / "g.toml")
    text = (tmp_path / "q.py").read_text()
    assert "from the drag areas of the vehicle file" in text and "[body] table" not in text


def test_export_sim_of_a_vehicle_with_another_propeller_takes_props_own_default(tmp_path, capsys):
    """Rotor 1 on apce_8x4, every rotor naming gill2017-apc: PROP (apce_8x6) is not every rotor's
    propeller, so the export takes PROP's default set, calibrated:apce_8x6, at --hover-rpm, and says
    the rotors carry their own set (mutant: all -> any, which took gill2017-apc from rotors 2-4)."""
    veh = _quad(tmp_path, rotor_params=["gill2017-apc"] * 4, first_propeller="apce_8x4")
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--vehicle", veh, "--target", "rotorpy", "--hover-rpm",
                         "5000", "--points", "200", "--out", tmp_path / "q.py", "--json")
    assert code == 0, err
    assert json.loads(out)["params"] == "calibrated:apce_8x6"
    assert "rotor(s) 1, 2, 3, 4 carry their own parameter set" in err and "apce_8x4" in err, err
