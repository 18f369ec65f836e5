"""What stop 94 left alone, fixed at stop 95 (2026-12-01). Each test fails on the code before its
fix; the guards say so. Data: the bundled example vehicles (the NeuroBEM quadrotor's layout and
flight fit, docs/flight.md; the example quadrotor on the catalogue's APC 8x6E)."""

import json
import math
import shutil
from pathlib import Path

import pytest

import propmap as pm
import propmap.io.toml_file as toml_file
import propmap.vehicle.file as vehicle_file
from propmap.vehicle.own_set import with_set_body

from .cli_helpers import run

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"


def test_the_api_resolves_a_catalogue_rotor_s_set_as_the_commands_do(capsys):
    """read_vehicle_with_params("quadrotor") gave no set (the example names none of its own), where
    trim-vehicle and wrench take the rotors' catalogue propeller's calibrated set: a user who took
    the generic set instead hovered at 5187 rpm against the commands' 5387 (measured)."""
    veh, params = pm.read_vehicle_with_params("quadrotor")
    assert params is not None and params.label == "calibrated:apce_8x6"
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "quadrotor", "--json", "--airspeed", "0,10")
    assert code == 0, err
    d = json.loads(out)
    assert d["params"] == params.label and d["rotor_params"] == [params.label] * 4
    for row, speed in zip(d["trims"], (0.0, 10.0)):
        want = pm.trim_vehicle(veh, params, speed)
        assert row["rotor_rpm"] == pytest.approx(list(want.rotor_omega * 30 / math.pi), rel=1e-9)
    assert d["trims"][0]["rotor_rpm"][0] == pytest.approx(5386.76, abs=0.01)  # (regression value, 2026-12-01)


def test_resolve_vehicle_with_a_given_set_drops_the_rotors_own_sets(tmp_path):
    """With ``params`` (as --params) every rotor takes that set; the rotors whose own sets it
    replaced are named (the command's warning), and the vehicle's own flight fit's airframe is
    not applied (the given set is a name, not a file with a [body] table)."""
    text = (EXAMPLES / "neurobem_quadrotor.toml").read_text()
    geom = 'propeller = "neurobem_5.1x4.8_geom.txt"'
    for name in ("neurobem_quadrotor.params.toml", "neurobem_5.1x4.8_geom.txt"):
        shutil.copy(EXAMPLES / name, tmp_path / name)
    path = tmp_path / "v.toml"
    path.write_text(text.replace(geom, geom + '\nparams = "generic"', 1), encoding="utf-8")
    mixed = pm.resolve_vehicle(path)
    assert mixed.sets[0] == "generic" and len(set(mixed.sets)) == 2 and mixed.body_from is not None
    assert mixed.vehicle.body_drag is not None and mixed.air.rho == 1.204  # (the vehicle's set's air)
    given = pm.resolve_vehicle(path, "gill2017-apc")
    assert given.dropped == (1,) and all(r.params is None for r in given.vehicle.rotors)
    assert given.label == "gill2017-apc" and given.sets == ("gill2017-apc",) * 4 and given.body_from is None
    assert given.vehicle.body_drag == pm.read_vehicle(path).body_drag


def test_resolve_vehicle_reads_the_vehicle_file_once(monkeypatch):
    """The vehicle commands parsed the vehicle file 4-8 times each (a helper's count, stop 94):
    read_vehicle_with_params read it twice; the resolution reads it once."""
    calls = []
    real = toml_file.load_toml

    def counted(path, *args, **kwargs):
        calls.append(Path(path).name)
        return real(path, *args, **kwargs)

    monkeypatch.setattr(vehicle_file, "load_toml", counted)
    monkeypatch.setattr(toml_file, "load_toml", counted)
    import propmap.vehicle.own_set as own_set

    monkeypatch.setattr(own_set, "load_toml", counted)
    pm.read_vehicle_with_params("neurobem_quadrotor")
    assert calls.count("neurobem_quadrotor.toml") == 1


def test_with_set_body_leaves_a_named_set_s_vehicle_as_it_is():
    """Guard (passes before too, as the CLI's copy): a named set has no [body] table."""
    veh = pm.read_vehicle("neurobem_quadrotor")
    assert with_set_body(veh, "generic") == (veh, None) and with_set_body(veh, None) == (veh, None)
    fitted, source = with_set_body(veh, EXAMPLES / "neurobem_quadrotor.params.toml")
    assert source.endswith("neurobem_quadrotor.params.toml") and fitted.body_drag != veh.body_drag


def test_a_vehicle_s_named_files_come_from_one_reading(monkeypatch):
    """The commands' inputs that no output may overwrite (cli/_paths.vehicle_inputs) are the
    files the vehicle names, read from one parsing of it (three before: its own set, then the
    rotors' propellers and sets)."""
    from propmap.cli._paths import vehicle_inputs
    import propmap.vehicle.own_set as own_set

    calls = []
    real = toml_file.load_toml
    monkeypatch.setattr(own_set, "load_toml", lambda p, *a, **k: calls.append(Path(p).name) or real(p, *a, **k))
    monkeypatch.setattr(vehicle_file, "load_toml", lambda p, *a, **k: calls.append(Path(p).name) or real(p, *a, **k))
    files = vehicle_inputs("neurobem_quadrotor")
    assert calls == ["neurobem_quadrotor.toml"]
    assert [f.name for f in files] == ["neurobem_quadrotor.params.toml"] + ["neurobem_5.1x4.8_geom.txt"] * 4


@pytest.mark.parametrize("args, match", [
    ((10**400, 0.0, 0.0), r"omega must be finite and in \[0, 100000\] rad/s; got an integer of about 401 digits, "),
    ((800.0, -10**400, 0.0), r"airspeed must be finite and in \[0, 500\] m/s; got an integer of about 401 digits"),
    ((10**5000, 0.0, 0.0), r"omega .* got an integer of about 5001 digits, beyond any float"),
    (([800.0, 10**400], 0.0, 0.0), r"omega must be finite and in \[0, 100000\] rad/s; got a number beyond any float"),
])
def test_an_integer_beyond_any_float_is_said_so(args, match):
    """rotor_loads(prop, p, 10**400, ...) said "got inf" of a finite integer, and in a list said
    that it was not a number (an API audit, stop 94); 10**5000 is counted without its text, which
    Python refuses past 4300 digits (a review found that message)."""
    with pytest.raises(ValueError, match=match):
        pm.rotor_loads(pm.load_propeller("apce_8x6"), pm.generic_params(), *args)


def test_the_air_in_words_is_one_text_for_commands_and_exports():
    """The commands' line, the C header's head and the simulator exports' head wrote the air with
    three formatters (export_c._air_words, simexport.files._air_words, cli/_air.air_label); one
    now, core.air.air_words. Regression values of the text (2026-12-01)."""
    from propmap.cli._air import air_label
    from propmap.core.air import air_words
    from propmap.export_c import _air_words as c_words
    from propmap.simexport.files import _air_words as sim_words

    air = pm.Air(rho=1.204, mu=1.81e-5, speed_of_sound=343.2)
    assert air_label(air) == "rho 1.204 kg/m^3, mu 1.81e-05 Pa s, speed of sound 343.2 m/s"
    assert c_words({"rho_kg_m3": 1.2041, "mu_Pa_s": 1.81e-5}) == "; air rho 1.2041 kg/m^3, mu 1.81e-05 Pa s"
    assert (sim_words({"rho": 1.2041, "speed_of_sound": 343.2})
            == " in air of rho 1.2041 kg/m^3, speed of sound 343.2 m/s")
    assert c_words({}) == sim_words({}) == ""
    assert air_words(1.2041, rho_digits=4) == "rho 1.204 kg/m^3"


def test_the_flight_fits_jackknife_interval_is_cut_at_the_bounds(tmp_path, capsys, shared_data, monkeypatch):
    """`fit flight --cross-validate` passes the bounds to the jackknife (its interval cut there, as
    every interval of the report), a path no test reached (stop 94's mutation audit: only a 400 s
    cross-validation did). The folds' collectives are pulled +-10 deg apart so that the interval
    (t of 1 degree of freedom, 12.7) spans past +-15 deg: cut at the bounds, and said so."""
    import propmap.identify.flight as flight

    real = flight.cross_validate_flight

    def spread(*args, **kwargs):
        cv = real(*args, **kwargs)
        for f, sign in zip(cv["folds"], (-1.0, 1.0)):
            f["x"] = {**f["x"], "collective": f["x"]["collective"] + sign * math.radians(10.0)}
        return cv

    monkeypatch.setattr(flight, "cross_validate_flight", spread)
    segments = ("bemnn20210218170320seg2.mat", "bemnn20210218171908seg2.mat", "bemnn20210223104803seg2.mat")
    logs = [str(shared_data / "neurobem_flights" / s) for s in segments]
    from propmap.cli.main import main

    code = main(["fit", "flight", *logs, "--vehicle", "neurobem_quadrotor", "--out", str(tmp_path / "p.toml"),
                 "--rate-hz", "1", "--holdout", segments[2], "--cross-validate", "--fit-params", "collective"])
    assert code == 0, capsys.readouterr().err
    jk = json.loads((tmp_path / "p.report.json").read_text())["jackknife"]
    assert jk["ci95"]["collective_deg"] == pytest.approx([-15.0, 15.0], abs=1e-9)
    assert jk["ci95_cut_at_bound"]["collective_deg"] == [True, True]


def _quad(tmp_path, name="v.toml", top="", rotor=("", "", "", ""), folder=None):
    """The example quadrotor (four catalogue apce_8x6) with a top-level entry and per-rotor lines."""
    text = (EXAMPLES / "quadrotor.toml").read_text()
    head, *rotors = text.split("[[rotors]]")
    text = head + top + "\n" + "".join("[[rotors]]" + r.rstrip("\n") + "\n" + extra + "\n"
                                       for r, extra in zip(rotors, rotor))
    where = tmp_path if folder is None else tmp_path / folder
    where.mkdir(parents=True, exist_ok=True)
    (where / name).write_text(text, encoding="utf-8")
    return where / name


FIT = EXAMPLES / "neurobem_quadrotor.params.toml"  # (a flight fit: a [body] table, rho 1.204)


@pytest.mark.parametrize("top, rotor, params, rotor_params", [
    ("", ("", "", "", ""), None, ["calibrated:apce_8x6"] * 4),
    ('params = "fit.toml"', ("", "", "", ""), None, ["FIT"] * 4),
    ('params = "fit.toml"', ('params = "gill2017-apc"',) * 4, None, ["gill2017-apc"] * 4),  # (the rotors' one set)
    ('params = "fit.toml"', ('params = "generic"', "", "", ""), None, ["generic", "FIT", "FIT", "FIT"]),
    ("", ('params = "gill2017-apc"', "", "", ""), None, ["gill2017-apc"] + ["calibrated:apce_8x6"] * 3),
    ('params = "fit.toml"', ('params = "generic"', "", "", ""), "gill2017-soft", ["gill2017-soft"] * 4),
    ("", ("", "", "", ""), "FIT", ["FIT"] * 4),
])
def test_resolve_vehicle_gives_each_rotor_the_set_trim_vehicle_gives_it(tmp_path, capsys, top, rotor, params,
                                                                        rotor_params):
    """resolve_vehicle against the command that calls it, case by case (a review found only the
    example quadrotor compared): each rotor's set, the one set, the air, the airframe."""
    shutil.copy(FIT, tmp_path / "fit.toml")
    path = _quad(tmp_path, top=top, rotor=rotor)
    given = str(tmp_path / "fit.toml") if params == "FIT" else params
    r = pm.resolve_vehicle(path, given)
    args = ["--params", given] if given is not None else []
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", path, "--json", "--airspeed", "5", *args)
    assert code == 0, err
    d = json.loads(out)
    assert [Path(s).name if s.endswith("fit.toml") else s for s in d["rotor_params"]] == [
        "fit.toml" if s == "FIT" else s for s in rotor_params]
    assert list(r.sets) == d["rotor_params"] and r.label == d["params"] and r.air.rho == d["rho_kg_m3"]
    fitted_body = (params is None and "fit.toml" in top) or params == "FIT"
    assert (r.body_from is not None) == fitted_body and (r.vehicle.body_drag is not None) == fitted_body
    want = pm.trim_vehicle(r.vehicle, r.params, 5.0)
    assert d["trims"][0]["rotor_rpm"] == pytest.approx(list(want.rotor_omega * 30 / math.pi), rel=1e-9)
    assert r.dropped == ((1,) if params is not None and 'params = "generic"' in rotor[0] else ())


def test_the_vehicle_s_own_set_is_read_from_its_folder_once(tmp_path, monkeypatch, capsys):
    """A vehicle given as a/v.toml naming params = "p.toml": the set is a/p.toml, as read_vehicle
    checked it; the resolution looked in a/a/p.toml first (the folder added twice, a review), so a
    file there of other air was taken (rho 1.0 against 1.204: a hover 176 rpm off)."""
    monkeypatch.chdir(tmp_path)
    _quad(tmp_path, top='params = "p.toml"', folder="a")
    shutil.copy(FIT, tmp_path / "a" / "p.toml")
    other = pm.read_params(FIT)
    pm.write_params(tmp_path / "a" / "a" / "p.toml", other.replace(air=pm.Air(rho=1.0)))
    r = pm.resolve_vehicle(Path("a") / "v.toml")
    assert r.air.rho == 1.204 and r.params == pm.read_params(FIT)
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "a/v.toml", "--json", "--airspeed", "0")
    assert code == 0, err
    assert json.loads(out)["rho_kg_m3"] == 1.204


def test_resolve_vehicle_takes_a_section_set_and_names_another_type():
    """A SectionParams for every rotor (the API's natural argument); another type is named (it met
    pathlib's 'expected str, bytes or os.PathLike object', a review)."""
    soft = pm.preset("gill2017-soft")
    r = pm.resolve_vehicle("quadrotor", soft)
    assert r.params is soft and r.sets == (soft.label or "the given set",) * 4 and r.body_from is None
    with pytest.raises(TypeError, match="params must be a named set, a parameter file or a section parameter set, "
                                        "got int"):
        pm.resolve_vehicle("quadrotor", 3)


def test_trim_vehicle_reads_the_vehicle_file_once(monkeypatch, capsys):
    """The command parsed it five times before resolve_vehicle (counted)."""
    import propmap.vehicle.own_set as own_set

    calls = []
    real = toml_file.load_toml
    counted = (lambda p, *a, **k: calls.append(Path(p).name) or real(p, *a, **k))
    monkeypatch.setattr(own_set, "load_toml", counted)
    monkeypatch.setattr(vehicle_file, "load_toml", counted)
    code, _, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--airspeed", "0")
    assert code == 0, err
    assert calls.count("neurobem_quadrotor.toml") == 1


@pytest.mark.parametrize("rows, said", [
    ('6000,0,0\n"12,000",5,90\n', "got '12,000' (a thousands separator? write 12000: a points file is read without"),
    ("rpm,m/s,deg\n6000,0,0\n", "line 2: rpm must be a finite number in [1, 954929], got 'rpm' (a units row? give "
                                "each unit in its column's name"),
    ("6000,0,0\n7000,x,90\n", "line 3: airspeed must be a finite number in [0, 500], got 'x'"),  # (no cause guessed)
])
def test_a_points_cell_that_is_no_number_names_its_likely_cause(tmp_path, capsys, rows, said):
    """`loads --points` refuses thousands separators and a units row (the load files read both:
    two CSV front ends, stop 94's noticed-and-left); its refusal now says which, where it is one."""
    path = tmp_path / "p.csv"
    path.write_text("rpm,airspeed (m/s),incidence_deg\n" + rows, encoding="utf-8")
    code, out, err = run(capsys, "loads", "apce_8x6", "--points", path, "--out", tmp_path / "o.csv")
    assert code == 2 and said in err and err.count("\n") == 1, err
    assert not (tmp_path / "o.csv").exists()
    if "x" in rows:
        assert err.rstrip().endswith("got 'x'")
