"""Edges of the vehicle commands found by a user-level audit (2026-11-26): a vehicle's own
propeller file is an input of every command given the vehicle; a flight fit's [body] table
reaches the simulator exports; `wrench --out -`; two logs of one name; a rate in rpm given as
rad/s through the API; a diameter-less geometry file in a vehicle file; an angle column
without its unit."""

import math
import re
import shutil
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.core.body import BodyDrag
from propmap.core.solver import supersonic_tips_allowed
from propmap.io.params_file import BodyTable, read_body, write_params
from propmap.vehicle import VehicleFileError, hover_omega

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
VEHICLE = EXAMPLES / "neurobem_quadrotor.toml"
OWN_PARAMS = "neurobem_quadrotor.params.toml"  # (the vehicle file's own set, its top-level params)
GEOMETRY = "neurobem_5.1x4.8_geom.txt"


@pytest.fixture()
def own_vehicle(tmp_path):
    """The NeuroBEM vehicle beside a copy of its geometry file (the file the audit overwrote) and of
    its own parameter file."""
    shutil.copy(EXAMPLES / GEOMETRY, tmp_path / GEOMETRY)
    shutil.copy(EXAMPLES / OWN_PARAMS, tmp_path / OWN_PARAMS)
    shutil.copy(VEHICLE, tmp_path / "v.toml")
    return tmp_path / "v.toml", tmp_path / GEOMETRY


def test_exports_refuse_to_write_over_the_vehicles_propeller_file(own_vehicle, capsys):
    vehicle, geometry = own_vehicle
    before = geometry.read_bytes()
    # (the geometry renamed with the export's suffix, as a user might have it)
    json_geom = geometry.with_name("geom.json")
    shutil.copy(geometry, json_geom)
    text = vehicle.read_text().replace(GEOMETRY, "geom.json").replace("blades = 3", "blades = 3\ndiameter_m = 0.12954")
    vehicle.write_text(text)
    # the vehicle's own propeller (its geometry under the other name) and no --hover-rpm: the command is valid
    # but for its output (with --out elsewhere it writes the export; before 2026-11-28 this test gave apce_8x6
    # with --hover-rpm, which export-sim refuses beside --vehicle for this target whatever the output)
    assert main(["export-sim", str(geometry), "--blades", "3", "--diameter-in", "5.1", "--target", "multinomial",
                 "--vehicle", str(vehicle), "--out", str(json_geom)]) == 2
    assert "refusing to overwrite an input" in capsys.readouterr().err
    assert json_geom.read_bytes() == before
    header = geometry.with_name("nb_geom.h")
    shutil.copy(geometry, header)
    vehicle.write_text(text.replace("geom.json", "nb_geom.h"))
    assert main(["map", str(EXAMPLES / GEOMETRY), "--blades", "3", "--format", "c", "--vehicle", str(vehicle),
                 "--rpm", "8000:20000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:180:3", "--out",
                 str(header)]) == 2
    assert "refusing to overwrite an input" in capsys.readouterr().err
    assert header.read_bytes() == before


def test_a_flight_fits_airframe_drag_reaches_rotorpys_quad_params(tmp_path, capsys):
    """export-sim --vehicle --params FIT.toml: the fit's [body] drag areas are RotorPy's c_D, as
    `wrench` takes them (they were the vehicle file's, 0 here, without a word); without --params,
    those of the vehicle file's own set (its top-level params, since 2026-11-30)."""
    fit = tmp_path / "fit.toml"
    write_params(fit, pm.generic_params(), body=BodyTable(BodyDrag((0.05, 0.02, 0.0), 1.0), None, None))
    out = {}
    for name, params in (("file", ["--params", "generic"]), ("fit", ["--params", str(fit)]), ("own", [])):
        assert main(["export-sim", str(EXAMPLES / GEOMETRY), "--blades", "3",
                     "--target", "rotorpy", "--vehicle", str(VEHICLE), *params,
                     "--out", str(tmp_path / f"{name}.py")]) == 0
        ns: dict = {}
        exec((tmp_path / f"{name}.py").read_text(), ns)
        out[name] = ns["quad_params"]
    capsys.readouterr()
    rho = out["fit"]["c_Dx"] / 0.05 * 2
    assert 1.0 < rho < 1.3
    assert out["fit"]["c_Dy"] == pytest.approx(0.5 * rho * 0.02) and out["fit"]["c_Dz"] == 0.0
    assert out["file"]["c_Dx"] != out["fit"]["c_Dx"]
    assert "drag areas of the [body] table of fit.toml" in (tmp_path / "fit.py").read_text()
    assert "drag areas of the vehicle file" in (tmp_path / "file.py").read_text()
    path = pm.vehicle_params_file("neurobem_quadrotor")
    own, area = pm.read_params(path), read_body(path).drag.drag_area[0]
    assert area == pytest.approx(0.02024, rel=1e-3)  # (regression value: the fit of 2026-11-30, refitted 2026-12-01)
    assert out["own"]["c_Dx"] == pytest.approx(0.5 * own.air.rho * area, rel=1e-9)
    assert "drag areas of the [body] table of neurobem_quadrotor.params.toml" in (tmp_path / "own.py").read_text()


def test_a_flight_fits_airframe_drag_reaches_the_c_vehicle_export(tmp_path, capsys):
    fit = tmp_path / "fit.toml"
    write_params(fit, pm.generic_params(), body=BodyTable(BodyDrag((0.05, 0.02, 0.0), 1.0), None, None))
    rho = pm.generic_params().air.rho
    for name, params, cd in (("file", [], None), ("fit", ["--params", str(fit)], 0.5 * rho * 0.05)):
        assert main(["map", str(EXAMPLES / GEOMETRY), "--blades", "3", "--format", "c", "--vehicle", str(VEHICLE),
                     *params, "--rpm", "8000:20000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:180:5",
                     "--check-points", "0", "--out", str(tmp_path / f"{name}.h")]) == 0
        text = (tmp_path / f"{name}.h").read_text()
        line = next(row for row in text.splitlines() if "_body_cd[3]" in row)
        values = [float(x) for x in line.split("{")[1].split("}")[0].split(",")]
        if cd is not None:
            assert values[0] == pytest.approx(cd, rel=1e-12) and values[2] == 0.0
        else:
            assert values[0] != pytest.approx(0.5 * rho * 0.05, rel=1e-6)
    capsys.readouterr()


def test_wrench_refuses_standard_output_and_twin_log_names_are_explained(tmp_path, capsys, shared_data):
    log = shared_data / "neurobem_flights" / "bemnn20210218170320seg2.mat"
    assert main(["wrench", str(log), "--vehicle", str(VEHICLE), "--out", "-"]) == 2
    assert "'-' (standard output) is not taken here" in capsys.readouterr().err
    assert not Path("-").exists()
    # a CSV named .nc (a user-level audit, 2026-11-27; map, export-sim and fit hold their formats' names)
    assert main(["wrench", str(log), "--vehicle", str(VEHICLE), "--out", str(tmp_path / "w.nc")]) == 2
    assert "wrench writes a CSV, named *.csv" in capsys.readouterr().err and not (tmp_path / "w.nc").exists()
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    other = shared_data / "neurobem_flights" / "bemnn20210223104803seg2.mat"
    (tmp_path / "a" / "x.mat").symlink_to(log)
    (tmp_path / "b" / "x.mat").symlink_to(other)
    assert main(["fit", "flight", str(tmp_path / "a" / "x.mat"), str(tmp_path / "b" / "x.mat"), "--vehicle",
                 str(VEHICLE), "--out", str(tmp_path / "p.toml")]) == 2
    err = capsys.readouterr().err
    assert "two logs are named 'x.mat'" in err and "another name" in err


def test_a_supersonic_tip_is_warned_of_by_the_api():
    """8000 given as rad/s for rpm: the tip at Mach 2.4, loads of 972 N from a 2.5 N propeller;
    the API said nothing (the CLI warns above Mach 0.7)."""
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    with pytest.warns(UserWarning, match=r"Mach 2.[34]\d? \(> 0\.8\): .*mean nothing.*is omega given in rpm"):
        pm.rotor_loads(prop, params, 8000.0, 0.0, 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with supersonic_tips_allowed():  # on purpose: silent
            pm.rotor_loads(prop, params, 8000.0, 0.0, 0.0)
    with pytest.warns(UserWarning, match="Mach"):
        pm.rotor_loads(prop, params, np.array([800.0, 8000.0]), 0.0, 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pm.rotor_loads(prop, params, 800.0, 20.0, 1.0)
        heavy = replace(pm.read_vehicle(VEHICLE), mass=10.0)  # hovers near Mach 0.74: its bracket probes past 1
        assert 0.5 < hover_omega(heavy, pm.generic_params()) * 0.0648 / 340.3 < 0.8
    with pytest.warns(UserWarning, match=r"Mach 1\.\d+ in this hover"):  # (the hover itself beyond Mach 0.8 is said)
        hover_omega(replace(pm.read_vehicle(VEHICLE), mass=40.0), pm.generic_params())
    # a hover below the solver's 0.1 rad/s: named, not SciPy's "f(a) and f(b) must have different signs"
    with pytest.raises(ValueError, match=r"weight 9\.81e-09 N is carried below 0\.1 rad/s .* mass \(1e-09 kg\)"):
        hover_omega(replace(pm.read_vehicle(VEHICLE), mass=1e-9), pm.generic_params())


def test_the_cli_says_a_high_tip_mach_number_once_in_its_own_terms(tmp_path, capsys):
    """The commands take rpm and warn from Mach 0.7 themselves: the API's "rpm for rad/s?" hint
    would be wrong there, and a second line."""
    assert main(["loads", "apce_8x6", "--rpm", "60000"]) == 0
    err = capsys.readouterr().err
    assert "tip Mach number up to" in err and "blade tip meets the air" not in err


def test_a_vehicles_diameter_less_geometry_names_the_vehicle_key(own_vehicle):
    vehicle, geometry = own_vehicle
    geometry.rename(geometry.with_name("geom.txt"))
    vehicle.write_text(vehicle.read_text().replace(GEOMETRY, "geom.txt"))
    with pytest.raises(VehicleFileError, match=r"give the rotor's diameter_m \[m\]") as info:
        pm.read_vehicle(vehicle)
    assert "diameter_in" not in str(info.value)
    # and a blade-less one the vehicle's blades key (it named the CLI's --blades and n_blades)
    geometry.with_name("geom.txt").rename(geometry.with_name("own_5.1x4.8_geom.txt"))
    vehicle.write_text(vehicle.read_text().replace("geom.txt", "own_5.1x4.8_geom.txt").replace("blades = 3\n", ""))
    with pytest.raises(VehicleFileError, match=r"does not state the blade count: give the rotor's blades;"):
        pm.read_vehicle(vehicle)


def test_a_diameter_less_geometry_file_says_how_to_give_the_size(tmp_path, capsys):
    """`loads` named a vehicle file's rule, not the command's option first (a new-user audit,
    2026-11-27)."""
    geometry = tmp_path / "mygeom.txt"
    geometry.write_text("r/R c/R beta\n0.15 0.14 40\n0.5 0.2 20\n1.0 0.07 10\n")
    assert main(["loads", str(geometry), "--rpm", "9000"]) == 2
    err = capsys.readouterr().err
    assert ("mygeom.txt: diameter unknown; give the diameter (--diameter-in; read_geometry's diameter_in) or name "
            "the file <family>_<D>x<P>_geom.txt (D in inches, in mm for the ef, kpf, pl and vp families)") in err, err
    assert "vehicle" not in err
    assert main(["loads", str(geometry), "--rpm", "9000", "--diameter-in", "5", "--blades", "3"]) == 0


def test_an_angle_column_without_its_unit_is_refused(tmp_path, capsys):
    (tmp_path / "p.csv").write_text("rpm,airspeed,incidence\n8000,10,1.0\n")
    assert main(["loads", "apce_8x6", "--points", str(tmp_path / "p.csv"), "--out", str(tmp_path / "o.csv")]) == 2
    assert "'incidence' gives no unit" in capsys.readouterr().err
    (tmp_path / "q.csv").write_text("rpm,airspeed,incidence (rad)\n8000,10,1.0\n")
    assert main(["loads", "apce_8x6", "--points", str(tmp_path / "q.csv"), "--out", str(tmp_path / "o.csv")]) == 0
    capsys.readouterr()
    row = (tmp_path / "o.csv").read_text().splitlines()
    assert len(row) == 2 and math.isclose(float(row[1].split(",")[2]), 1.0)


def _vehicle_text(rotor_lines: dict, body: str = "") -> str:
    """The NeuroBEM vehicle file with extra lines in the rotors numbered in ``rotor_lines`` (and
    without its own parameter set, whose [body] table a ``body`` given would meet)."""
    text = VEHICLE.read_text().replace(f'params = "{OWN_PARAMS}"\n', "")
    parts = text.split("[[rotors]]")
    for k, extra in rotor_lines.items():
        parts[k] = parts[k].rstrip("\n") + "\n" + extra + "\n\n"
    return "[[rotors]]".join(parts) + body


def test_heterogeneous_vehicle_exports_say_what_they_leave_out(tmp_path, capsys):
    """A second user-level audit (2026-11-26): export-sim pinned the hover of a vehicle whose rotor
    had its own set (+14% thrust in RotorPy's model); the C header compared rotor names only (a
    blade-count mismatch passed through the API, an identical geometry copy was refused after
    the build); the airframe's drag in the slipstream left the C function and RotorPy's model
    without a word (+39% of the weight at hover)."""
    shutil.copy(EXAMPLES / GEOMETRY, tmp_path / GEOMETRY)
    shutil.copy(EXAMPLES / OWN_PARAMS, tmp_path / OWN_PARAMS)
    own = tmp_path / "own.toml"
    own.write_text(_vehicle_text({2: 'params = "section:naca0015"'}))
    args = ["export-sim", str(tmp_path / GEOMETRY), "--blades", "3", "--target", "rotorpy", "--vehicle", str(own)]
    assert main([*args, "--out", str(tmp_path / "a.py")]) == 2
    assert "rotor(s) 2 carry their own parameter set" in capsys.readouterr().err
    assert main([*args, "--hover-rpm", "12000", "--out", str(tmp_path / "b.py")]) == 0
    assert "warning: --vehicle: rotor(s) 2 carry their own parameter set" in capsys.readouterr().err
    # an identical copy of the geometry under another name: the header is written (the geometry compared)
    shutil.copy(EXAMPLES / GEOMETRY, tmp_path / "copy_geom.txt")
    twin = tmp_path / "twin.toml"
    twin.write_text(VEHICLE.read_text().replace(GEOMETRY, "copy_geom.txt", 1))
    grid = ["--rpm", "8000:20000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:180:5", "--check-points", "0"]
    assert main(["map", str(tmp_path / GEOMETRY), "--blades", "3", "--format", "c", "--vehicle", str(twin), *grid,
                 "--out", str(tmp_path / "twin.h")]) == 0
    # the slipstream's download: said by both exports
    washed = tmp_path / "washed.toml"
    washed.write_text(_vehicle_text({}, "\n[body]\ndrag_area = [0.01, 0.012, 0.03]\nwash_factor = 2.0\n"))
    assert main(["map", str(tmp_path / GEOMETRY), "--blades", "3", "--format", "c", "--vehicle", str(washed),
                 *grid, "--out", str(tmp_path / "w.h")]) == 0
    assert "(wash_factor 2) is left out of the C vehicle function" in capsys.readouterr().err
    assert main(["export-sim", str(tmp_path / GEOMETRY), "--blades", "3", "--target", "rotorpy", "--vehicle",
                 str(washed), "--out", str(tmp_path / "w.py")]) == 0
    err = capsys.readouterr().err
    assert "(wash_factor 2) pushes it down by" in err and "% of its weight)" in err
    # no vertical drag area, no download: not warned of as "pushes it down by 0 N" (a user-level audit, 2026-11-28)
    flat = tmp_path / "flat.toml"
    flat.write_text(_vehicle_text({}, "\n[body]\ndrag_area = [0.01, 0.012, 0.0]\nwash_factor = 2.0\n"))
    assert main(["export-sim", str(tmp_path / GEOMETRY), "--blades", "3", "--target", "rotorpy", "--vehicle",
                 str(flat), "--out", str(tmp_path / "f.py")]) == 0
    assert "pushes it down" not in capsys.readouterr().err


def test_the_c_header_compares_the_maps_geometry(tmp_path):
    """The C vehicle block compared rotor names only: a blade-count mismatch passed through the
    API. It compares the blade geometry the map records (not the name)."""
    from propmap.export_c import c_header_text
    from propmap.maps import build_map

    veh = pm.read_vehicle(VEHICLE)
    prop = veh.rotors[0].propeller
    g = pm.generic_params()
    rm = pm.RotorMap(build_map(prop, g, np.array([900.0, 1500.0, 2100.0]), np.array([0.0, 10.0]),
                               np.radians([0.0, 90.0, 180.0]), n_check=0))
    two = replace(veh, rotors=(replace(veh.rotors[0], propeller=replace(prop, n_blades=2)), *veh.rotors[1:]))
    with pytest.raises(ValueError, match=r"rotor 1 carries .* 2 blades\), not the map's .* 3 blades\)"):
        c_header_text(rm, tmp_path / "x.h", vehicle=two)
    twisted = replace(veh, rotors=(veh.rotors[0], replace(veh.rotors[1], propeller=replace(
        prop, theta=prop.theta + 0.02)), *veh.rotors[2:]))
    with pytest.raises(ValueError, match=r"rotor 2 carries .* 3 blades, another chord or blade angle\)"):
        c_header_text(rm, tmp_path / "x.h", vehicle=twisted)
    renamed = replace(veh, rotors=tuple(replace(r, propeller=replace(prop, name="other")) for r in veh.rotors))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert "_vehicle_wrench" in c_header_text(rm, tmp_path / "x.h", vehicle=renamed)  # (the same blade)


def test_a_rotors_own_set_in_other_air_is_warned_of():
    veh = pm.read_vehicle(VEHICLE)
    g = pm.generic_params()
    thin = replace(veh, rotors=(veh.rotors[0], replace(veh.rotors[1], params=g.replace(air=pm.Air(rho=1.0))),
                                *veh.rotors[2:]))
    with pytest.warns(UserWarning, match=r"rotor 2 has its own parameter set in other air \(rho 1 kg/m\^3\)"):
        pm.vehicle_wrench(thin, g, [0, 0, 0], [0, 0, 0], [1200.0] * 4)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pm.vehicle_wrench(replace(veh, rotors=(veh.rotors[0], replace(veh.rotors[1], params=g), *veh.rotors[2:])),
                          g, [0, 0, 0], [0, 0, 0], [1200.0] * 4)
        pm.vehicle_wrench(thin, g, [0, 0, 0], [0, 0, 0], [1200.0] * 4, air=pm.Air(rho=1.1))  # (air chosen)


def test_flight_commands_check_each_rotors_set(capsys):
    """wrench and fit flight never asked whether a rotor's set was calibrated on another propeller
    (`loads` does for one; a user-level audit read it in the code)."""
    from propmap.cli._vehicle import _check_rotor_sets

    veh = pm.read_vehicle(VEHICLE)
    _check_rotor_sets(veh, ["calibrated:apce_8x6"] * 4)
    err = capsys.readouterr().err
    assert err.count("runs with calibrated:apce_8x6, the set calibrated on another propeller") == 1  # (once)
    _check_rotor_sets(veh, ["generic"] * 4)
    assert "calibrated on another" not in capsys.readouterr().err


@pytest.mark.slow
def test_a_bundled_example_is_found_by_name_wherever_propmap_is_installed(tmp_path, monkeypatch, capsys):
    """An installed user had no path to the example vehicles (they live in site-packages; the
    README's `read_vehicle("src/propmap/data/examples/...")` worked only in a checkout: a
    packaging audit). `example_file` gives an example's path, `read_vehicle` and `--vehicle`
    take a bundled vehicle's bare name where no such file exists; a local file of that name wins."""
    names = pm.example_files()
    assert {"quadrotor.toml", "neurobem_quadrotor.toml", "level_flight_synthetic.csv"} <= set(names)
    assert pm.example_file("neurobem_quadrotor") == pm.example_file("neurobem_quadrotor.toml")
    assert pm.example_file("level_flight_synthetic.csv").is_file()
    with pytest.raises(ValueError, match=r"'quad' is not a bundled example; they are level_flight_synthetic.csv, "):
        pm.example_file("quad")
    monkeypatch.chdir(tmp_path)
    assert pm.read_vehicle("neurobem_quadrotor").mass == 0.772
    assert pm.read_vehicle(Path("quadrotor")).mass == 0.8
    # a file's name, never the example's; the example named (docs/flight.md wrote neurobem_quadrotor.toml, which
    # failed: a docs audit, 2026-11-27)
    with pytest.raises(pm.vehicle.VehicleFileError, match=r"^quadrotor.toml: no such file here \(the bundled example "
                                                         r"vehicle of that name is given without .toml: quadrotor\)$"):
        pm.read_vehicle("quadrotor.toml")
    with pytest.raises(pm.vehicle.VehicleFileError, match=r"^quad.toml: no such file$"):
        pm.read_vehicle("quad.toml")
    with pytest.raises(pm.vehicle.VehicleFileError, match=r"^quadrotor: no such file$"):  # a folder given (a review)
        pm.read_vehicle("./quadrotor")
    with pytest.raises(pm.vehicle.VehicleFileError, match=r"^quad: no such file \(nor a bundled example vehicle: "
                                                         r"neurobem_quadrotor, quadrotor\)"):
        pm.read_vehicle("quad")
    with pytest.raises(pm.vehicle.VehicleFileError, match=r"no such file$"):  # a path is a path
        pm.read_vehicle(tmp_path / "quadrotor.toml")
    data = pm.example_file("level_flight_synthetic.csv")
    assert main(["fit", "level-flight", str(data), "--vehicle", "quadrotor", "--out", "lf.toml"]) == 0
    capsys.readouterr()
    # './quadrotor' on the command line is a file (click's Path made it 'quadrotor': a review)
    assert main(["fit", "level-flight", str(data), "--vehicle", "./quadrotor", "--out", "lf2.toml"]) == 2
    assert "--vehicle: quadrotor: no such file" in capsys.readouterr().err
    local = pm.example_file("quadrotor.toml").read_text(encoding="utf-8").replace("mass = 0.8", "mass = 0.9")
    assert "mass = 0.9" in local
    (tmp_path / "quadrotor").write_text(local, encoding="utf-8")  # a file of that name here: it is read
    assert pm.read_vehicle("quadrotor").mass == 0.9


def test_export_sim_names_a_vehicle_mass_in_grams_and_an_unused_vehicle(own_vehicle, capsys):
    """A vehicle-designer audit (2026-11-28): a mass in grams failed on the envelope ("hover_rpm
    must be within [...]; widen --envelope"), whose advice wrote coefficients pinned at tip Mach
    4.3 (the CLI keeps the API's tip-Mach hint, which names the mass, to itself); --hover-rpm with
    --vehicle for gz-sim dropped the vehicle without a word."""
    vehicle, _ = own_vehicle
    grams = vehicle.with_name("grams.toml")
    grams.write_text(vehicle.read_text().replace("mass = 0.772", "mass = 772.0", 1))
    out = vehicle.with_name("o.sdf")
    base = ["export-sim", str(EXAMPLES / GEOMETRY), "--blades", "3", "--target", "gz-sim", "--out", str(out)]
    assert main([*base, "--vehicle", str(grams), "--envelope", "rpm=1000:900000"]) == 2
    err = capsys.readouterr().err.splitlines()[-1]
    assert re.fullmatch(r"propmap: error: --vehicle: it hovers at \d+ rpm, a blade tip Mach number of [\d.]+ "
                        r"\(> 0.8, beyond the model's physics\): is its mass \(772 kg\) in kg, and are its rotors "
                        r"the ones it flies\?", err), err
    assert main([*base, "--vehicle", str(vehicle), "--hover-rpm", "20000"]) == 2
    err = capsys.readouterr().err
    assert "--vehicle: with --hover-rpm it has nothing to do in a gz-sim export" in err, err
    assert not out.exists()
    # the advice of a vehicle that cannot pin the hover runs for either kind of target (a review: gz-sim's said
    # "give --hover-rpm", which then refused the vehicle beside it)
    quad = ["export-sim", "apce_10x7", "--vehicle", "quadrotor"]
    assert main([*quad, "--target", "gz-sim", "--out", str(out)]) == 2
    assert capsys.readouterr().err.rstrip().endswith("or give --hover-rpm instead of --vehicle")
    assert main([*quad, "--target", "rotorpy", "--out", str(out.with_suffix(".py"))]) == 2
    assert capsys.readouterr().err.rstrip().endswith("or give --hover-rpm")
    assert main([*base, "--vehicle", str(vehicle), "--points", "300"]) == 0  # (the vehicle alone pins the hover)
    assert out.exists()


def test_trim_vehicle_refuses_a_supersonic_hover_asking_for_the_mass_in_kg(tmp_path, capsys):
    """The NeuroBEM quadrotor with its mass in grams (772) trimmed at a supersonic tip speed and
    printed it, exit 0, with a tip-Mach warning only (a flight-log audit, 2026-11-30): refused,
    asking whether the mass is in kg; the file as shipped trims as before (12,246 rpm)."""
    src = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    grams = tmp_path / "grams.toml"
    for f in [*src.parent.glob("neurobem_*_geom.txt"), src.parent / OWN_PARAMS]:  # (named relative to the file)
        shutil.copy(f, tmp_path / f.name)
    grams.write_text(src.read_text().replace("mass = 0.772", "mass = 772", 1))
    code = main(["trim-vehicle", "--vehicle", str(grams)])
    err = capsys.readouterr().err
    assert code == 2 and re.search(r"propmap: error: --airspeed 0: the rotors turn at up to \d+ rpm, a blade tip "
                                   r"Mach number of [\d.]+ \(supersonic, beyond the model's physics\): is the "
                                   r"vehicle's mass \(772 kg\) in kg", err), err
    assert main(["trim-vehicle", "--vehicle", str(src), "--params", "generic"]) == 0
    assert "12246.2" in capsys.readouterr().out


def test_a_vehicle_file_with_weight_for_mass_names_the_unknown_key(tmp_path, capsys):
    """'weight = 0.772' in place of 'mass' was told only "missing key 'mass'": the unknown key is
    named first, with the allowed ones (a flight-log audit, 2026-11-30)."""
    src = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    path = tmp_path / "w.toml"
    path.write_text(src.read_text().replace("mass = 0.772", "weight = 0.772", 1))
    code = main(["trim-vehicle", "--vehicle", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and "unknown key(s) weight (allowed: mass, " in err, err


def test_a_rotor_table_with_location_for_position_names_the_unknown_key(tmp_path, capsys):
    """A [[rotors]] table with 'location' in place of 'position' was told only "missing key
    'position'": the unknown key is named (a review, 2026-11-30)."""
    src = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    for f in [*src.parent.glob("neurobem_*_geom.txt"), src.parent / OWN_PARAMS]:
        shutil.copy(f, tmp_path / f.name)
    path = tmp_path / "loc.toml"
    path.write_text(src.read_text().replace("position =", "location =", 1))
    code = main(["trim-vehicle", "--vehicle", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and "rotor 1: unknown key(s) location: did you mean position? (allowed: " in err, err
