"""A mutation audit of stop 96 (5b91912..d4d13db): the one rule for a vehicle's parameter sets in the
one-propeller exports (cli/_vehicle.py, cli/map.py, cli/export_sim.py, vehicle/own_set.py,
export_c.py), SectionParams.same_section, and the QPROP propeller-file reader (io/qprop_file.py,
--params qprop:FILE). Each test asserts documented behaviour that a mutant of the changed lines broke
while the stop's own tests passed; the mutant is named in the test. Data: the example quadrotor
(four catalogue apce_8x6), the NeuroBEM flight fit, and QPROP files written here."""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.io.geometry_files import GeometryFileError, geometry_format, read_geometry
from propmap.io.qprop_file import read_qprop_geometry, read_qprop_params

from .cli_helpers import example_quad as _quad
from .cli_helpers import one_line_error, run
from .test_qprop_file import FIRST_ROW, STATIONS, propfile

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
FIT = EXAMPLES / "neurobem_quadrotor.params.toml"  # (a flight fit: a [body] table, rho 1.204)
GRID = ["--rpm", "2000:12000:4", "--airspeed", "0:10:3", "--incidence-deg", "0:180:4", "--check-points", "0"]


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


# --- QPROP files (io/qprop_file.py, io/param_sets.py)

def _plain(tmp_path):
    return read_geometry(propfile(tmp_path / "plain.prop"))


def test_fortran_D_exponents_and_trailing_empty_fields_read_as_the_plain_file(tmp_path):
    """Fortran's 1.27D-1 (upper case, as Fortran writes it; mutants: the regex or the conversion
    without D) and station rows ending in empty fields ("commas at the end dropped"; mutant: kept,
    an empty field where CL0 belongs)."""
    plain = _plain(tmp_path)
    upper = read_geometry(propfile(tmp_path / "D.prop", blades="2 1.27D-1", fac="2.54D-2 2.54D-2 1D0"))
    assert upper.same_geometry(plain) and upper.radius == 0.127
    commas = read_geometry(propfile(tmp_path / "c.prop", rows=[f" {r:g},{c:g},{b:g},," for r, c, b in STATIONS]))
    assert commas.same_geometry(plain)
    blank = read_geometry(propfile(tmp_path / "b.prop", rows=[f" {r:g} {c:g} {b:g} ," for r, c, b in STATIONS]))
    assert blank.same_geometry(plain)


def test_a_value_cut_at_column_128_is_warned(tmp_path):
    """A value that straddles column 128 is read cut by QPROP (0.45 of 0.456789): warned, naming it
    (mutant: only values wholly past the column were)."""
    row = " 1 0.8 35"
    row += " " * (124 - len(row)) + "0.456789"  # (columns 125-132)
    rows = [row, *(f" {r:g}  {c:g}  {b:g}" for r, c, b in STATIONS[1:])]
    with pytest.warns(UserWarning, match=rf"cut.prop, line {FIRST_ROW}: its values run past column 128.*cuts CL0"):
        p = read_qprop_geometry(propfile(tmp_path / "cut.prop", rows=rows))
    assert p.same_geometry(_plain(tmp_path))


@pytest.mark.parametrize("change, line, match", [
    (dict(blades="2 -0.1"), 4, "R = -0.1 m is negative"),
    (dict(blades="2 0.1206"), 4, "R = 0.1206 m is inside the last station (r = 0.12065 m, line 23)"),
    (dict(rows=[" 1 0.8 35", " 2 1.0 -95", " 4.75 0.45 13"]), FIRST_ROW + 1,
     "beta = -95 gives -95 deg (scaled by line 12's factors and line 13's offsets), outside [-90, 90] deg"),
    (dict(blades="2 1.905", fac="0.381 0.381 1.0"), None,
     "the diameter 2R = 3.81 m (150 in, from line 4's R) is outside [0.5, 100] in"),
])
def test_the_readers_refusals_name_their_line(tmp_path, change, line, match):
    """Mutants: R < -1 for R < 0 (said "inside the last station"), R's tolerance 1e-9 -> 1e-3 and
    beta > 90 for |beta| > 90 (Propeller's own error, no line), the diameter's range on R (150 in read)."""
    with pytest.raises(GeometryFileError) as info:
        read_geometry(propfile(tmp_path / "bad.prop", **change))
    msg = str(info.value)
    assert match in msg and "\n" not in msg, msg
    if line is not None:
        assert f"bad.prop, line {line}: " in msg, msg


def test_a_blade_angle_of_90_degrees_is_in_range(tmp_path):
    """[-90, 90] deg is closed (mutant: >= 90 refused)."""
    rows = [" 1 0.8 90", " 1.5 0.95 30", " 2 1.05 25.5", " 4.75 0.45 13"]
    p = read_geometry(propfile(tmp_path / "b90.prop", rows=rows))
    assert p.theta[0] == pytest.approx(math.pi / 2, rel=1e-15)


def test_a_wrong_chord_factor_and_a_short_blade_are_warned(tmp_path):
    """read_qprop_geometry's Warns: the largest chord outside [0.12, 0.6] R (Cfac 0.1016 for 0.0254:
    0.88 R) and stations that stop inside 0.9 R (R = 0.15 m, last station 0.12065 m; mutants: each
    warning dropped)."""
    with pytest.warns(UserWarning, match=r"ch.prop: the largest chord is 0.88 R.*Cfac and Cadd \(lines 12, 13\)"):
        read_geometry(propfile(tmp_path / "ch.prop", fac="0.0254 0.1016 1.0"))
    with pytest.warns(UserWarning, match=r"short.prop: the stations stop at r/R = 0.8043"):
        p = read_geometry(propfile(tmp_path / "short.prop", blades="2 0.15"))
    assert p.radius == 0.15


def test_the_sets_range_refusals_name_their_line(tmp_path):
    """CL_a = 0 (an open bound; mutant: closed, then -CL0/CL_a divided by zero) and -CL0/CL_a outside
    [-20, 10] deg (mutant: unchecked, CamberedParams' error without the line)."""
    for name, line6, match in (("a0", " 0.50  0    ", "line 6: CL_a = 0 is outside (0, 20], the range of "
                                                    "propmap's cl_alpha"),
                               ("cl0", " 2.5  5.8   ", "line 6: CL0 = 2.5 with CL_a = 5.8 gives a zero-lift angle "
                                                     "-CL0/CL_a of -24.7 deg, outside [-20, 10] deg")):
        f = propfile(tmp_path / f"{name}.prop", cd="0.028 0.050 0.050 0.5")
        f.write_text(f.read_text().replace(" 0.50  5.8   ", line6))
        with pytest.raises(GeometryFileError) as info:
            read_qprop_params(f)
        assert f"{name}.prop, {match}" in str(info.value), str(info.value)


def test_a_qprop_sets_label_is_the_whole_spec(tmp_path):
    """qprop:FILE is labelled with the spec as given, not the path as Path spells it (mutant: the
    reader's default label, which drops the doubled slash)."""
    propfile(tmp_path / "t.prop", cd="0.028 0.050 0.050 0.5")
    spec = f"qprop:{tmp_path}//t.prop"
    assert pm.resolve_params(spec).label == spec


def test_ragged_tables_under_a_title_are_no_qprop_files(tmp_path):
    """A millimetre table under a title whose fourth row has four numbers, or two, is neither a QPROP
    file's header (no two-value line 3, 4 or 6) nor its line 2 (three numbers, not Nblades [R])
    (mutants: the two-value line not required; a line 2 of three numbers taken)."""
    rows = [f"{25.4 * r:g} {25.4 * c:g} {b:g}" for r, c, b in STATIONS]
    for name, k, row in (("four.txt", 3, rows[3] + " 7"), ("two.txt", 3, " ".join(rows[3].split()[:2]))):
        f = tmp_path / name
        f.write_text("Test 10x6 in mm\n" + "\n".join(rows[:k] + [row] + rows[k + 1:]) + "\n")
        assert geometry_format(f) is None, name
        with pytest.raises(GeometryFileError, match="unrecognised geometry format"):
            read_geometry(f)
