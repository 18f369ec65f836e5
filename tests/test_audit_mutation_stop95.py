"""A mutation audit of stop 95 (2026-12-01): the mutants of the change that its tests let through,
each killed here. Each test names the mutant it kills (the mutation, on the code of stop 95) and
passes on that code. Data: the bundled example vehicles and their files (docs/flight.md)."""

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.vehicle.own_set import with_set_body

from .cli_helpers import run

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
FIT = EXAMPLES / "neurobem_quadrotor.params.toml"  # (a flight fit: a [body] table, rho 1.204)


def _quad(tmp_path, top="", rotor=("", "", "", "")):
    """The example quadrotor (four catalogue apce_8x6) with a top-level entry and per-rotor lines."""
    text = (EXAMPLES / "quadrotor.toml").read_text()
    head, *rotors = text.split("[[rotors]]")
    text = head + top + "\n" + "".join("[[rotors]]" + r.rstrip("\n") + "\n" + extra + "\n"
                                       for r, extra in zip(rotors, rotor))
    path = tmp_path / "v.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_resolve_vehicle_takes_a_cambered_section_set():
    """Kills V01 (resolve_vehicle's given set checked as an AirfoilParams only: a CamberedParams,
    the other section set, was refused as 'another type')."""
    cam = pm.CamberedParams()
    r = pm.resolve_vehicle("quadrotor", cam)
    assert r.params is cam and r.sets == ("the given set",) * 4 and r.air == cam.air and r.body_from is None


def test_resolve_vehicle_takes_a_path_to_a_parameter_file(tmp_path):
    """Kills V02 (a params given as a pathlib.Path, an os.PathLike, refused as 'another type'; the
    docstring names str or Path): the flight fit's set for every rotor and its airframe."""
    path = _quad(tmp_path)
    r = pm.resolve_vehicle(path, FIT)
    assert r.params == pm.read_params(FIT) and r.sets == (str(FIT),) * 4 and r.air.rho == 1.204
    assert r.body_from == str(FIT) and r.vehicle.body_drag is not None


def test_a_set_every_rotor_names_comes_before_the_vehicle_s_own_even_the_generic_one(tmp_path, capsys):
    """Kills V16 (``mixed`` without ``any(own)``: rotors that all name the generic set were taken as
    mixed, so the vehicle's own set, a flight fit in air of rho 1.204, was ``params`` and its air the
    rotors', where resolve_vehicle's rule, a set every rotor names before the vehicle's, gives the
    generic set and its 1.225). The vehicle's set still gives its [body] table. (trim-vehicle before
    stop 95 solved this vehicle in the vehicle's set's air, 1.204, and warned of the rotors' other
    air: this pins stop 95's rule, a change of the command's output the audit reports.)"""
    shutil.copy(FIT, tmp_path / "fit.toml")
    path = _quad(tmp_path, top='params = "fit.toml"', rotor=('params = "generic"',) * 4)
    r = pm.resolve_vehicle(path)
    assert r.label == "generic" and r.sets == ("generic",) * 4 and r.params == pm.generic_params()
    assert r.air.rho == pm.generic_params().air.rho == 1.225
    assert r.body_from is not None and r.vehicle.body_drag is not None
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", path, "--json", "--airspeed", "0")
    assert code == 0, err
    assert json.loads(out)["rho_kg_m3"] == 1.225 and json.loads(out)["params"] == "generic"


def test_a_parameter_file_without_a_body_table_gives_no_airframe(tmp_path):
    """Kills W01 (with_set_body's source named for any parameter file, a [body] table or not):
    a loads fit's file (no [body]) leaves the airframe as it is and names no source, in
    with_set_body and in resolve_vehicle's ``body_from``."""
    plain = tmp_path / "plain.toml"
    pm.write_params(plain, pm.preset("gill2017-apc"))
    veh = pm.read_vehicle("quadrotor")
    assert with_set_body(veh, plain) == (veh, None)
    r = pm.resolve_vehicle("quadrotor", plain)
    assert r.body_from is None and r.vehicle.body_drag is None and r.params == pm.read_params(plain)


def test_the_air_s_words_keep_their_digits():
    """Kills A01 (air_words' rho at 5 significant digits by default, where the exports' heads
    write 6: stop 95's regression value 1.2041 reads the same at 5), and with it A02 (mu at 3)
    and A04 (air_label at the exports' 6 digits, not 4), which older tests kill too: values whose
    digits tell them apart."""
    from propmap.cli._air import air_label
    from propmap.core.air import air_words
    from propmap.export_c import _air_words as c_words
    from propmap.simexport.files import _air_words as sim_words

    assert air_words(1.204123, 1.8137e-5, 343.21) == "rho 1.20412 kg/m^3, mu 1.814e-05 Pa s, speed of sound 343.2 m/s"
    assert c_words({"rho_kg_m3": 1.204123}) == "; air rho 1.20412 kg/m^3"
    assert sim_words({"rho": 1.204123, "mu": 1.8137e-5}) == " in air of rho 1.20412 kg/m^3, mu 1.814e-05 Pa s"
    air = pm.Air(rho=1.204123, mu=1.8137e-5, speed_of_sound=343.21)
    assert air_label(air) == "rho 1.204 kg/m^3, mu 1.814e-05 Pa s, speed of sound 343.2 m/s"


def _paired_model(calls):
    """A smooth two-parameter model of (cl_alpha, cd_min), optimum (5.5, 0.02) inside the bounds,
    that records each kind of call in ``calls`` (its residual, its Jacobian, the two together, as
    engine._attach_jacobian gives a model with implicit derivatives)."""
    def r(x):
        return np.array([x[0] - 5.5, 10.0 * (x[1] - 0.02), 0.1 * x[0] * x[1] - 0.011, 0.3 * (x[0] - 5.5) ** 2])

    def J(x):
        return np.array([[1.0, 0.0], [0.0, 10.0], [0.1 * x[1], 0.1 * x[0]], [0.6 * (x[0] - 5.5), 0.0]])

    def residual(x):
        calls.append("residual")
        return r(np.asarray(x, float))

    def with_jacobian(x):
        calls.append("with_jacobian")
        x = np.asarray(x, float)
        return r(x), J(x)

    def jacobian(x):
        calls.append("jacobian")
        return J(np.asarray(x, float))

    residual.jacobian, residual.with_jacobian = jacobian, with_jacobian
    return residual


def test_the_continuation_counts_every_model_call_of_both_residuals():
    """Kills K04 (the first Gauss-Newton try made without the implicit derivatives, on a
    differenced exact Jacobian across the M = 50 residual's jumps, where the continuation keeps to
    Nelder-Mead: the tests of the continuation all had the derivatives or stopped before it); and
    with it K01 (the smooth model's differenced Jacobian left out of the count), K03 (stage 2 on
    the exact model's Jacobian, not the smooth one's),
    K02 (the optimum's residual and Jacobian counted twice: in the calls and in the 2 n + 1) and
    K05 (2 n, not 2 n + 1), which older tests kill too: without derivatives, the count
    _polish_at_base_M reports is every
    call of the exact residual and of the smooth one (the optimum's residual and differenced
    Jacobian are 2 n + 1 of them)."""
    from propmap.identify import FitOptions
    from propmap.identify.continuation import M_SMOOTH, _polish_at_base_M

    names = ("cl_alpha", "cd_min")
    seen = {}

    def make_residual(opts):
        calls = seen.setdefault(opts.M, [])
        model = _paired_model(calls)

        def plain(x):  # (no derivatives: the continuation differences the smooth model)
            return model(x)

        return plain

    options = FitOptions(names=names, multistart=0, prior=False)
    result, count = _polish_at_base_M(make_residual, names, options, 50.0, np.array([5.0, 0.03]), "test")
    assert set(seen) == {50.0, M_SMOOTH}
    assert count == sum(len(c) for c in seen.values())
    assert len(seen[50.0]) > 1 and result.x == pytest.approx([5.5, 0.02], abs=1e-4)
    # stage 2 steps with the smooth model's Jacobian (differenced: 2 n calls each), not the exact one's (K03);
    # Gauss-Newton is tried only with the exact model's implicit derivatives, absent here (K04)
    assert len(seen[M_SMOOTH]) >= 2 * 2 * len(names)
    assert result.message.endswith("then Nelder-Mead at M = 50"), result.message


def test_a_level_flight_fit_says_its_optimum_s_flapping_once():
    """Kills E05 (fit_level_flight without engine._warn_at_optimum: its model's FlappingWarning,
    held at the trial points, never said; its residual's ``at_optimum``, new at stop 95, reached by
    no test). The example quadrotor at 10-15 m/s and 120-160 rad/s with a set of flap_compliance 40
    (not fitted: the fit frees cd_min) flaps past 0.25 rad: said once."""
    import warnings

    from propmap.core.solver import Discretization
    from propmap.identify import FitOptions
    from propmap.identify.level_flight import LevelFlightData
    from propmap.identify.level_flight_fit import fit_level_flight

    n = 8
    omega = np.random.default_rng(3).uniform(120, 160, (n, 4))
    data = LevelFlightData(np.linspace(10, 15, n), np.full(n, -0.3), np.zeros(n), omega, np.zeros((n, 3)))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = fit_level_flight(data, pm.read_vehicle("quadrotor"),
                               base=pm.generic_params().replace(flap_compliance=40.0),
                               options=FitOptions(names=("cd_min",), prior=False, discretization=Discretization(12, 8)))
    said = [str(w.message) for w in caught if issubclass(w.category, pm.FlappingWarning)]
    assert res.params.flap_compliance == 40.0
    assert len(said) == 1 and "flap_compliance 40 rad/(N m)" in said[0], said


@pytest.mark.parametrize("paired", [True, False])
def test_the_progress_bar_counts_the_model_calls_the_fit_reports(monkeypatch, paired):
    """Kills O14 (_solve's CountedResidual without ``on_call=bar.update``: the progress bar of a
    fit on a terminal stood at 0 evaluations; off a terminal tqdm is disabled, so no test saw it).
    The bar is a recorder here: its updates add up to the count the fit reports, with the model's
    derivatives and with differences."""
    import tqdm

    from propmap.identify import FitOptions
    from propmap.identify.optimizer import _solve

    ticks = []

    class Bar:
        def __init__(self, *args, **kwargs):
            pass

        def update(self, k=1):
            ticks.append(k)

        def set_postfix(self, **kwargs):
            pass

        def close(self):
            pass

    monkeypatch.setattr(tqdm, "tqdm", Bar)
    names, calls = ("cl_alpha", "cd_min"), []
    model = _paired_model(calls)
    residual = model if paired else (lambda x: model(x))
    _, _, nfev, _, _ = _solve(residual, names, FitOptions(names=names, multistart=0, prior=False, progress=True),
                              "test", np.array([4.0, 0.05]))
    assert nfev == len(calls) == sum(ticks) > 0


def test_a_geometry_file_s_other_problems_have_no_found_header(tmp_path):
    """Kills S14 (GeometryFileError.found_header '' by default, not None: its record says None for
    every problem but a missing header; stop 95 tested that of MeasurementFileError only)."""
    from propmap.io.geometry_files import GeometryFileError, read_uiuc_geometry

    for text in ("", "r/R c/R beta\n0.2 x 20\n0.5 0.1 15\n"):
        g = tmp_path / "geom.txt"
        g.write_text(text)
        with pytest.raises(GeometryFileError) as info:
            read_uiuc_geometry(g)
        assert info.value.found_header is None, str(info.value)
    assert GeometryFileError("anything").found_header is None


def test_a_fit_along_directions_takes_each_jacobian_with_its_residual():
    """Kills E01 (engine._fit_along_directions taking the residual and the model's Jacobian as two
    model calls where the model brings them from one, ``with_jacobian``: twice the count, twice
    the solves). A linear model of the cambered set's five parameters, its Jacobian with it: every
    call is of the two together, and the count reported is those calls."""
    from propmap.identify import FitOptions
    from propmap.identify.engine import _fit_along_directions
    from propmap.identify.options import CAMBERED_FIT

    names, calls = CAMBERED_FIT, []
    A = np.random.default_rng(5).standard_normal((12, len(names)))
    target = np.array([5.9, -0.05, 1.1, 0.025, 0.06])

    def make_data(opts):
        def residual(x):
            calls.append("residual")
            return A @ (np.asarray(x, float) - target)

        def with_jacobian(x):
            calls.append("with_jacobian")
            return A @ (np.asarray(x, float) - target), A

        residual.jacobian = lambda x: (calls.append("jacobian"), A)[1]
        residual.with_jacobian = with_jacobian
        return residual

    _, log, nfev, _, _, extra = _fit_along_directions(make_data, names, pm.CamberedParams(), FitOptions(), 2)
    assert extra["directions"]["count"] == 2 and log[0]["nfev"] >= 1
    assert set(calls) == {"with_jacobian"} and nfev == len(calls)


def test_a_set_every_rotor_names_is_the_set_not_the_vehicle_s_own(tmp_path, capsys):
    """Kills V20 (``spec != mine``: where every rotor names one set other than the vehicle's own,
    the vehicle's flight fit was ``params`` under the rotors' label). stop 95's case of it compared
    resolve_vehicle with trim-vehicle, which calls it: the set is checked here against the named
    one itself, and the command's rpm against a trim with it."""
    import math

    shutil.copy(FIT, tmp_path / "fit.toml")
    path = _quad(tmp_path, top='params = "fit.toml"', rotor=('params = "gill2017-apc"',) * 4)
    gill = pm.resolve_params("gill2017-apc")
    r = pm.resolve_vehicle(path)
    assert r.label == "gill2017-apc" and r.params == gill and r.air == gill.air
    assert r.body_from is not None  # (the vehicle's own set still gives its airframe)
    code, out, err = run(capsys, "trim-vehicle", "--vehicle", path, "--json", "--airspeed", "0")
    assert code == 0, err
    d = json.loads(out)
    want = pm.trim_vehicle(r.vehicle, gill, 0.0)
    assert d["rho_kg_m3"] == gill.air.rho
    assert d["trims"][0]["rotor_rpm"] == pytest.approx(list(want.rotor_omega * 30 / math.pi), rel=1e-9)


@pytest.mark.parametrize("propeller", ["geometry file", "cfnq_45p1"])
def test_a_rotor_of_no_set_and_no_calibrated_propeller_is_left_to_the_generic_params(tmp_path, propeller):
    """Kills V27 (a mixed vehicle's rotor with no set of its own, no vehicle's set and no
    calibrated catalogue propeller given its propeller's default, the generic set, as a set of its
    own) and V12 (the generic default of an uncalibrated catalogue propeller, cfnq_45p1, not taken
    for no set: the same for such a rotor): ResolvedVehicle's record says such a rotor keeps none
    and takes ``params``; the trims are the same, the vehicle returned is not. Rotor 1 on
    gill2017-apc; the others on the NeuroBEM geometry file (not in the catalogue), or on a
    catalogue propeller without a calibrated set."""
    if propeller == "geometry file":
        text = (EXAMPLES / "neurobem_quadrotor.toml").read_text()
        shutil.copy(EXAMPLES / "neurobem_5.1x4.8_geom.txt", tmp_path / "neurobem_5.1x4.8_geom.txt")
        geom = 'propeller = "neurobem_5.1x4.8_geom.txt"'
        text = text.replace('params = "neurobem_quadrotor.params.toml"', "").replace(
            geom, geom + '\nparams = "gill2017-apc"', 1)
        path = tmp_path / "v.toml"
        path.write_text(text, encoding="utf-8")
    else:
        path = _quad(tmp_path, rotor=('params = "gill2017-apc"', "", "", ""))
        head, first, rest = path.read_text().partition('propeller = "apce_8x6"')
        path.write_text(head + first + rest.replace('propeller = "apce_8x6"', f'propeller = "{propeller}"'),
                        encoding="utf-8")
    r = pm.resolve_vehicle(path)
    assert r.sets == ("gill2017-apc", "generic", "generic", "generic") and r.params == pm.generic_params()
    assert r.vehicle.rotors[0].params == pm.resolve_params("gill2017-apc")
    assert [rotor.params for rotor in r.vehicle.rotors[1:]] == [None] * 3



@pytest.mark.parametrize("command", [("trim-vehicle", "--airspeed", "0"), ("wrench",)])
def test_an_unknown_params_of_a_vehicle_command_is_told_as_every_command_tells_it(tmp_path, capsys, command):
    """Kills C02 (cli/_vehicle._vehicle_sets without ``load_params(params_spec)`` in its error path:
    an unknown --params was told with the KeyError's repr, in quotes, not as every other command
    tells it; no test gave a vehicle command an unknown set)."""
    args = [*command, "--vehicle", "quadrotor", "--params", "nosuchset"]
    if command == ("wrench",):
        log = tmp_path / "log.csv"
        log.write_text("t,vx,vy,vz,p,q,r,rpm_1,rpm_2,rpm_3,rpm_4\n0,0,0,0,0,0,0,5000,5000,5000,5000\n")
        args = ["wrench", log, *args[1:], "--out", tmp_path / "w.csv"]
    code, _, err = run(capsys, *args)
    assert code == 2
    assert "propmap: error: --params: unknown parameters 'nosuchset': not a named set" in err, err


def test_a_malformed_vehicle_file_is_told_by_its_option_in_wrench(tmp_path, capsys):
    """Kills P01 (cli/_paths.vehicle_inputs letting the vehicle reader's error through, not its
    best effort's []: wrench, which checks its output against the vehicle's files first, then told
    a vehicle file that is not TOML without naming --vehicle)."""
    vehicle = tmp_path / "broken.toml"
    vehicle.write_text("mass = [\n", encoding="utf-8")
    log = tmp_path / "log.csv"
    log.write_text("t,vx\n0,0\n", encoding="utf-8")
    code, _, err = run(capsys, "wrench", log, "--vehicle", vehicle, "--out", tmp_path / "w.csv")
    assert code == 2
    assert err.startswith(f"propmap: error: --vehicle: {vehicle}: not valid TOML"), err
