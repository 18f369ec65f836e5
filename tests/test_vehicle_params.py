"""A vehicle file's own parameter set (its top-level ``params``, since 2026-11-30): what the vehicle
commands take without --params, as a catalogue propeller's calibrated set is what `loads` takes.
The bundled NeuroBEM quadrotor names the set fitted to its four flight segments
(``neurobem_quadrotor.params.toml``; Bauersfeld et al., "NeuroBEM", RSS 2021): without it, its
commands ran the generic set (fitted to thrust stands) on the authors' lumped blade, 16% fast in
hover and 1.6 N rms off in force on the race track against 0.48 N."""

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.body import BodyDrag
from propmap.io.params_file import BodyTable, read_body, read_coverage
from propmap.vehicle import VehicleFileError

from .cli_helpers import one_line_error, run

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
OWN = "neurobem_quadrotor.params.toml"
LINE = f'params = "{OWN}"\n'
SLOW = "bemnn20210223104803seg2.mat"  # the slow figure-8 (29.4 s, 3.5 m/s at most)
LOGS = ("bemnn20210218170320seg2.mat", "bemnn20210218171908seg2.mat", SLOW, "bemnn20210223114138seg3.mat")


def _copy(tmp_path, text=None, params=True) -> Path:
    """The NeuroBEM vehicle file in tmp_path beside its blade (and its own set, with ``params``)."""
    shutil.copy(EXAMPLES / "neurobem_5.1x4.8_geom.txt", tmp_path)
    if params:
        shutil.copy(EXAMPLES / OWN, tmp_path)
    path = tmp_path / "v.toml"
    path.write_text((EXAMPLES / "neurobem_quadrotor.toml").read_text() if text is None else text)
    return path


def test_the_example_names_its_flight_fit_and_python_reads_it():
    assert (EXAMPLES / "neurobem_quadrotor.toml").read_text().count(LINE) == 1
    path = pm.vehicle_params_file("neurobem_quadrotor")
    assert Path(path) == EXAMPLES / OWN
    p = pm.read_params(path)
    # regression values (fit flight on the four shared segments, 2026-11-30, refitted 2026-12-01; the file's header
    # gives the command)
    assert math.degrees(p.collective) == pytest.approx(4.6135, abs=1e-4) and p.cl_alpha == pytest.approx(3.6940,
                                                                                                        abs=1e-4)
    assert p.air.rho == 1.204
    # read_vehicle checks the key but leaves the model's set to the caller (the rotors carry none)
    assert all(r.params is None for r in pm.read_vehicle("neurobem_quadrotor").rotors)
    assert pm.vehicle_params_file("quadrotor") is None
    # the parameter file is no example vehicle
    with pytest.raises(VehicleFileError, match=r"nor a bundled example vehicle: neurobem_quadrotor, quadrotor\)"):
        pm.read_vehicle("neurobem_quadrotor_params")


def test_trim_vehicle_hovers_with_the_vehicles_set_and_params_generic_as_before(capsys):
    """The logs' rotors turn at 1107-1132 rad/s in near-hover (docs/flight.md); the vehicle's set
    hovers at 1115.4 rad/s, the generic set at 1282.4 (12,246 rpm)."""
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--json")
    assert code == 0, err
    d = json.loads(out)
    assert d["params"].endswith(OWN) and d["rotor_params"] == [d["params"]] * 4
    want = pm.hover_omega(pm.read_vehicle("neurobem_quadrotor"), pm.read_params(pm.vehicle_params_file(
        "neurobem_quadrotor")))
    assert d["trims"][0]["rotor_rpm"] == pytest.approx([want * 30 / math.pi] * 4, rel=1e-9)
    assert want == pytest.approx(1115.43, abs=0.01)  # regression value
    code, out, _ = run(capsys, "trim-vehicle", "--vehicle", "neurobem_quadrotor", "--json", "--params", "generic")
    assert code == 0 and json.loads(out)["trims"][0]["rotor_rpm"][0] == pytest.approx(12246.2, abs=0.1)


@pytest.mark.slow
def test_wrench_takes_the_vehicles_set_and_its_airframe_and_says_a_training_log_is_in_sample(
        tmp_path, capsys, shared_data):
    log = shared_data / "neurobem_flights" / SLOW
    code, out, err = run(capsys, "wrench", log, "--vehicle", "neurobem_quadrotor", "--out", tmp_path / "a.csv")
    assert code == 0, err
    assert f"{SLOW} is one of the logs the parameter set was fitted to" in out and "in-sample" in out
    # the same as the file given as --params: its section set and its [body] table (the airframe's drag)
    code, out2, err = run(capsys, "wrench", log, "--vehicle", "neurobem_quadrotor", "--params",
                          pm.vehicle_params_file("neurobem_quadrotor"), "--out", tmp_path / "b.csv")
    assert code == 0, err
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes() and out2 == out
    code, out, _ = run(capsys, "wrench", log, "--vehicle", "neurobem_quadrotor", "--out", tmp_path / "c.csv",
                       "--json")
    d = json.loads(out)
    assert d["in_fit"] is True and d["params"].endswith(OWN)
    # regression value: F in sample on the slow figure-8 (the generic set: over 3x as large)
    assert d["errors"][f"propmap ({d['params']})"]["F"] == pytest.approx(0.0977, abs=0.001)
    code, out, _ = run(capsys, "wrench", log, "--vehicle", "neurobem_quadrotor", "--out", tmp_path / "d.csv",
                       "--json", "--params", "generic")
    g = json.loads(out)
    assert g["in_fit"] is False and g["errors"]["propmap (generic)"]["F"] > 3 * d["errors"][
        f"propmap ({d['params']})"]["F"]


@pytest.mark.slow
def test_a_log_is_told_in_sample_by_its_content_where_the_set_has_digests(tmp_path, capsys, shared_data):
    """A flight fit's [coverage] lists its training logs' digests (files_sha256, since 2026-11-30):
    a log of a training log's name but other content (PX4 names its logs HH_MM_SS.ulg, day after
    day) is no training log, and a renamed copy of one is; a file without digests is read by name."""
    slow = shared_data / "neurobem_flights" / SLOW
    digest = read_coverage(EXAMPLES / OWN)["files_sha256"]
    assert len(digest) == 4

    def said(log, fit):
        code, out, err = run(capsys, "wrench", log, "--vehicle", "neurobem_quadrotor", "--params", fit, "--out",
                             tmp_path / "w.csv")
        assert code == 0, err
        return [ln for ln in out.splitlines() if "in-sample" in ln]

    fit = tmp_path / "p.toml"
    for held, want in ((False, ["by its content"]), (True, [])):
        pm.write_params(fit, pm.generic_params(), coverage={"data": "flight logs", "groups": [] if held else [SLOW],
                                                            "held_out": [SLOW] if held else [],
                                                            "files_sha256": digest[2:3] if not held else digest[:2]})
        got = said(slow, fit)
        assert len(got) == len(want) and all(w in g for w, g in zip(want, got))
    # the same content under another name: in-sample; another log under a training log's name: not
    pm.write_params(fit, pm.generic_params(), coverage={"data": "flight logs", "groups": [SLOW],
                                                        "files_sha256": digest})
    shutil.copy(slow, tmp_path / "renamed.mat")
    assert said(tmp_path / "renamed.mat", fit)
    shutil.copy(shared_data / "neurobem_flights" / LOGS[0], tmp_path / SLOW)
    pm.write_params(fit, pm.generic_params(), coverage={"data": "flight logs", "groups": [SLOW],
                                                        "files_sha256": [digest[2]]})
    assert not said(tmp_path / SLOW, fit)
    # without digests, by name (a file written before 2026-11-30); held out: never
    pm.write_params(fit, pm.generic_params(), coverage={"data": "flight logs", "groups": [SLOW]})
    assert "by its name" in said(tmp_path / SLOW, fit)[0]
    pm.write_params(fit, pm.generic_params(), coverage={"data": "flight logs", "groups": [], "held_out": [SLOW]})
    assert not said(slow, fit)


def test_a_rotors_own_set_is_kept_beside_the_vehicles(tmp_path, capsys):
    """Rotor 1 names the generic set, the others take the vehicle's: the trim is the function's of
    that vehicle (read_vehicle_with_params: the vehicle's airframe and set) at the vehicle set's air
    (a review found the generic set's 1.225 kg/m^3 there, and a test that checked the labels only)."""
    text = (EXAMPLES / "neurobem_quadrotor.toml").read_text()
    geom = 'propeller = "neurobem_5.1x4.8_geom.txt"'
    path = _copy(tmp_path, text.replace(geom, geom + '\nparams = "generic"', 1))
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", path, "--json", "--airspeed", "0,8")
    assert code == 0, err
    d = json.loads(out)
    assert d["rotor_params"][0] == "generic" and all(s.endswith(OWN) for s in d["rotor_params"][1:])
    veh, own = pm.read_vehicle_with_params(path)
    # (each rotor carries its set, as the command resolves them: resolve_vehicle)
    assert veh.rotors[0].params == pm.generic_params() and all(r.params == own for r in veh.rotors[1:])
    assert d["rho_kg_m3"] == own.air.rho == 1.204
    for row, speed in zip(d["trims"], (0.0, 8.0)):
        with pytest.warns(UserWarning, match=r"rotor 1 has its own parameter set in other air \(rho 1.225"):
            want = pm.trim_vehicle(veh, own, speed)
        assert row["rotor_rpm"] == pytest.approx(list(want.rotor_omega * 30 / math.pi), rel=1e-9)
        assert row["pitch_deg"] == pytest.approx(math.degrees(want.pitch), abs=1e-9)
    assert d["trims"][0]["rotor_rpm"][0] != pytest.approx(d["trims"][0]["rotor_rpm"][2], rel=1e-3)


def test_the_vehicle_file_checks_its_own_set(tmp_path):
    text = (EXAMPLES / "neurobem_quadrotor.toml").read_text()
    with pytest.raises(VehicleFileError, match=r"v.toml: params: unknown parameters 'neurobem_quadrotor.params.toml'"
                                               r".* \(.*neurobem_quadrotor.params.toml: a relative path is taken "
                                               r"from the vehicle file's folder\)"):
        pm.read_vehicle(_copy(tmp_path, params=False))
    with pytest.raises(VehicleFileError, match="params must be a parameter file or a named set"):
        pm.read_vehicle(_copy(tmp_path, text.replace(LINE, "params = 3\n")))
    # a named set is taken; one that does not exist is no file looked for
    assert pm.read_vehicle(_copy(tmp_path, text.replace(LINE, 'params = "generic"\n'))).mass == 0.772
    with pytest.raises(VehicleFileError, match="calibrated:nosuch") as info:
        pm.read_vehicle(_copy(tmp_path, text.replace(LINE, 'params = "calibrated:nosuch"\n')))
    assert "relative path" not in str(info.value)
    # beside the file's own [body]: the set's [body] table would replace it without a word
    with pytest.raises(VehicleFileError, match=r": \[body\] and params: 'neurobem_quadrotor.params.toml''s \[body\] "
                                               r"table gives it too"):
        pm.read_vehicle(_copy(tmp_path, text + "\n[body]\ndrag_area = [0.01, 0.01, 0.02]\n"))
    # so for a centre of mass or a rotor interference the set's table gives (a review: replaced without a word)
    fit = tmp_path / "fit.toml"
    pm.write_params(fit, pm.generic_params(), body=BodyTable(BodyDrag((0.02, 0.02, 0.0), 1.0), np.zeros(3), 0.0))
    mine = text.replace(LINE, 'params = "fit.toml"\nrotor_interference = 2.0\ncentre_of_mass = [-0.02, 0.0, 0.0]\n')
    with pytest.raises(VehicleFileError, match=r": centre_of_mass, rotor_interference and params: 'fit.toml''s "
                                               r"\[body\] table gives them too"):
        pm.read_vehicle(_copy(tmp_path, mine))
    pm.write_params(fit, pm.generic_params(), body=BodyTable(BodyDrag((0.02, 0.02, 0.0), 1.0), None, None))
    veh, _ = pm.read_vehicle_with_params(_copy(tmp_path, mine))  # (the table without them: the file's stay)
    assert veh.rotor_interference == 2.0 and list(veh.centre_of_mass) == [-0.02, 0.0, 0.0]
    assert veh.body_drag.drag_area == (0.02, 0.02, 0.0)


def test_the_vehicles_set_is_an_input_no_output_may_overwrite(tmp_path, capsys, shared_data):
    path = _copy(tmp_path)
    before = (tmp_path / OWN).read_bytes()
    code, _, err = run(capsys, "fit", "flight", shared_data / "neurobem_flights" / SLOW, "--vehicle", path,
                       "--out", tmp_path / OWN, "--rate-hz", "5")
    assert one_line_error(code, err, "refusing to overwrite an input"), err
    assert (tmp_path / OWN).read_bytes() == before


@pytest.mark.slow
def test_fit_flight_fits_from_base_whatever_the_vehicle_names(tmp_path, capsys, shared_data):
    """The vehicle's own set is the vehicle commands' default, not the fit's start: the same file is
    written with the vehicle's set named and without it."""
    log = shared_data / "neurobem_flights" / SLOW
    written = []
    for k, keep in enumerate((True, False)):
        sub = tmp_path / str(k)
        sub.mkdir()
        text = (EXAMPLES / "neurobem_quadrotor.toml").read_text()
        path = _copy(sub, text if keep else text.replace(LINE, ""), params=keep)
        code, _, err = run(capsys, "fit", "flight", log, "--vehicle", path, "--rate-hz", "5", "--out", sub / "p.toml")
        assert code == 0, err
        assert "are not used" not in err
        written.append(pm.read_params(sub / "p.toml"))
    assert written[0] == written[1]


@pytest.mark.slow
def test_the_shipped_set_is_what_its_command_fits(tmp_path, capsys, shared_data):
    """The file's header states the command that wrote it: run again on the four shared segments, it
    gives the shipped parameters (a model or calibration change that moves them asks for a refit)."""
    logs = [shared_data / "neurobem_flights" / name for name in LOGS]
    code, _, err = run(capsys, "fit", "flight", *logs, "--vehicle", "neurobem_quadrotor", "--rho", "1.204",
                       "--out", tmp_path / "p.toml")
    assert code == 0, err
    fresh, shipped = pm.read_params(tmp_path / "p.toml"), pm.read_params(EXAMPLES / OWN)
    for name in ("collective", "cl_alpha", "alpha_L0_re", "cd_min", "alpha_L0"):
        assert getattr(fresh, name) == pytest.approx(getattr(shipped, name), rel=1e-6, abs=1e-9), name
    fresh_body, shipped_body = read_body(tmp_path / "p.toml").drag, read_body(EXAMPLES / OWN).drag
    assert fresh_body.drag_area == pytest.approx(shipped_body.drag_area, rel=1e-6)
    assert fresh_body.wash_factor == pytest.approx(shipped_body.wash_factor, rel=1e-6)
    assert read_coverage(tmp_path / "p.toml")["files_sha256"] == read_coverage(EXAMPLES / OWN)["files_sha256"]


def test_export_sim_takes_the_vehicles_set_for_its_own_propeller_only(tmp_path, capsys):
    """export-sim PROP --vehicle: the vehicle's own set is its rotors', so it is --params' default
    where PROP is their propeller, and PROP's own default otherwise (a review found apce_8x6
    exported with the NeuroBEM rotors' flight fit, and its warning of a set fitted to another
    propeller)."""
    own = ["export-sim", EXAMPLES / "neurobem_5.1x4.8_geom.txt", "--blades", "3", "--target", "rotorpy",
           "--vehicle", "neurobem_quadrotor", "--json"]
    code, out, err = run(capsys, *own, "--out", tmp_path / "a.py")
    assert code == 0, err
    d = json.loads(out)
    assert d["params"].endswith(OWN) and d["envelope"]["hover_rpm"] == pytest.approx(10651.57, abs=0.01)
    code, out, err = run(capsys, "export-sim", "apce_8x6", "--target", "rotorpy", "--vehicle", "neurobem_quadrotor",
                         "--hover-rpm", "6000", "--json", "--out", tmp_path / "b.py")
    assert code == 0, err
    assert json.loads(out)["params"] == "calibrated:apce_8x6" and "fitted to data of neurobem" not in err


def test_the_c_vehicle_export_takes_the_vehicles_set_and_airframe(tmp_path, capsys):
    grid = ["--rpm", "8000:20000:3", "--airspeed", "0:10:3", "--incidence-deg", "0:180:5", "--check-points", "0"]
    base = ["map", EXAMPLES / "neurobem_5.1x4.8_geom.txt", "--blades", "3", "--format", "c", "--vehicle",
            "neurobem_quadrotor", *grid]
    cd = {}
    for name, extra in (("own", []), ("generic", ["--params", "generic"])):
        code, _, err = run(capsys, *base, *extra, "--out", tmp_path / f"{name}.h")
        assert code == 0, err
        line = next(r for r in (tmp_path / f"{name}.h").read_text().splitlines() if "_body_cd[3]" in r)
        cd[name] = [float(x) for x in line.split("{")[1].split("}")[0].split(",")]
    # the fit's drag area along x times rho / 2 at the set's air (1.204 kg/m^3); none without the set
    area = read_body(EXAMPLES / OWN).drag.drag_area[0]
    assert area == pytest.approx(0.02024, rel=1e-3)  # (regression value: the fit of 2026-11-30, refitted 2026-12-01)
    assert cd["own"][0] == pytest.approx(0.5 * 1.204 * area, rel=1e-9) and cd["generic"][0] == 0.0
    assert OWN in (tmp_path / "own.h").read_text() and OWN not in (tmp_path / "generic.h").read_text()
