"""trim_omega and `propmap trim` without --rpm: the rotation rate that makes a thrust."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.core.trim import TrimError, default_omega_bounds, trim_collective, trim_omega


@pytest.fixture(scope="module")
def rotor():
    return pm.load_propeller("apce_8x6"), pm.resolve_params("calibrated:apce_8x6")


@pytest.mark.parametrize("omega0, V, beta_deg", [(600.0, 0.0, 0.0), (900.0, 8.0, 0.0), (700.0, 10.0, 90.0),
                                                 (800.0, 12.0, 45.0), (500.0, 1.0, 120.0)])
def test_the_rate_that_makes_a_models_own_thrust_is_its_rate(rotor, omega0, V, beta_deg):
    """A round trip: the thrust the model makes at omega0 is made at omega0 again (in still air,
    climb and edgewise flight the thrust rises with Omega from the windmilling rotor's, one
    solution)."""
    prop, p = rotor
    beta = math.radians(beta_deg)
    T0 = float(pm.rotor_loads(prop, p, omega0, V, beta).thrust)
    r = trim_omega(prop, p, T0, V, beta)
    assert float(r.omega) == pytest.approx(omega0, rel=1e-7) and int(r.n_solutions) == 1
    assert float(r.loads.thrust) == pytest.approx(T0, abs=1e-6)
    assert float(r.loads.omega) == float(r.omega)


def test_trimming_the_rate_then_the_collective_at_it_gives_the_sets_collective(rotor):
    """The two trims agree: at the rate trim_omega finds, trim_collective finds no offset."""
    prop, p = rotor
    r = trim_omega(prop, p, 2.5, 6.0, math.radians(60.0))
    c = trim_collective(prop, p, 2.5, float(r.omega), 6.0, math.radians(60.0))
    assert float(c.collective) == pytest.approx(0.0, abs=1e-7)


def test_static_rates_follow_the_square_root_of_thrust(rotor):
    """In still air T = CT rho n^2 D^4 with CT nearly constant: four times the thrust at about twice
    the rate (the Reynolds terms move CT by a few percent: 1.94 here, a regression value,
    2026-11-27)."""
    prop, p = rotor
    r = trim_omega(prop, p, [1.0, 4.0])
    assert r.omega.shape == (2,) and np.all(r.n_solutions == 1)
    assert r.omega[1] / r.omega[0] == pytest.approx(1.941, abs=2e-3)
    np.testing.assert_allclose(pm.rotor_loads(prop, p, r.omega, 0.0, 0.0).thrust, [1.0, 4.0], atol=1e-6)


def test_inputs_broadcast_with_the_collective(rotor):
    """With the generic set, below stall, a positive collective makes the thrust at a lower rate
    (apce_8x6's calibrated set sits at its static stall: there +2 deg needs 692.0 rad/s for 3 N
    against 691.3, docs/models.md, Collective pitch as an input, and trim)."""
    prop, _ = rotor
    p = pm.generic_params()
    T = np.array([[1.0], [2.0], [3.0]])
    r = trim_omega(prop, p, T, [0.0, 5.0], 0.0, collective=math.radians(2.0))
    assert r.omega.shape == (3, 2) and r.loads.thrust.shape == (3, 2)
    np.testing.assert_allclose(r.loads.thrust, np.broadcast_to(T, (3, 2)), atol=1e-6)
    np.testing.assert_allclose(pm.rotor_loads(prop, p, r.omega, [0.0, 5.0], 0.0, collective=math.radians(2.0)).thrust,
                               r.loads.thrust, rtol=1e-15)
    assert np.all(r.omega < trim_omega(prop, p, T, [0.0, 5.0], 0.0).omega)


def test_a_thrust_out_of_reach_is_refused_or_nan(rotor):
    prop, p = rotor
    lo, hi = default_omega_bounds(prop, p.air)
    assert lo == pytest.approx(1.0 / prop.radius) and hi == pytest.approx(0.9 * 340.3 / prop.radius, rel=1e-3)
    with pytest.raises(TrimError, match=r"no rotation rate in \[9.84252, 3014.\d+\] rad/s .* makes thrust=300 N .*is "
                                        r"the thrust in grams\? It is in N"):
        trim_omega(prop, p, 300.0)
    # below the range: the hint names what holds there (it blamed descent at every point, a static one too: a
    # user-level audit, 2026-11-28)
    for thrust in (0.0, -1.0):
        with pytest.raises(TrimError, match=r"spans \[0.000\d+, .*in still air a turning rotor's thrust is positive: "
                                            r"give a thrust above 0 N") as err:
            trim_omega(prop, p, thrust)
        assert "descent" not in str(err.value)
    with pytest.raises(TrimError, match="in descent the flow alone makes that much"):
        trim_omega(prop, p, 1e-4, airspeed=10.0, incidence=math.pi)
    with pytest.raises(TrimError, match=r"the slowest rate, 9.84252 rad/s, already makes 0.0\d+ N here"):
        trim_omega(prop, p, 1e-5, airspeed=10.0, incidence=math.pi / 2)
    r = trim_omega(prop, p, [2.0, 300.0], on_missing="nan")
    assert np.isfinite(r.omega[0]) and np.isnan(r.omega[1]) and list(r.n_solutions) == [1, 0]
    assert np.isnan(r.loads.thrust[1]) and np.isnan(r.loads.torque[1])


@pytest.mark.parametrize("kw, match", [
    (dict(thrust="2"), "thrust must be a number"),
    (dict(thrust=np.nan), "thrust must be finite"),
    (dict(thrust=2.0, bounds=(100.0, 50.0)), r"bounds must satisfy 0 < low < high <= 100000 rad/s"),
    (dict(thrust=2.0, bounds=(0.0, 50.0)), r"bounds must satisfy 0 < low"),
    (dict(thrust=2.0, bounds=(50.0, 50.0)), r"bounds must satisfy 0 < low < high"),
    (dict(thrust=2.0, bounds="fast"), "bounds must be two rotation rates"),
    (dict(thrust=2.0, on_missing="clip"), "on_missing must be 'raise' or 'nan'"),
    (dict(thrust=[1.0, 2.0], airspeed=[1.0, 2.0, 3.0]), "must broadcast together"),
])
def test_bad_arguments_name_themselves(rotor, kw, match):
    prop, p = rotor
    with pytest.raises(ValueError, match=match):
        trim_omega(prop, p, **kw)


def test_the_search_does_not_warn_of_fast_tips_but_a_fast_answer_does(rotor):
    """The grid reaches tip Mach 0.9 on purpose; the answer's tip Mach is warned of as
    rotor_loads warns (above 0.8)."""
    prop, p = rotor
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        trim_omega(prop, p, 2.0)
    with pytest.warns(UserWarning, match=r"a blade tip meets the air at Mach 0.8"):
        trim_omega(prop, p, 60.0)


def test_cli_trims_the_rpm_without_rpm(capsys):
    prop, p = pm.load_propeller("apce_8x6"), pm.resolve_params("calibrated:apce_8x6")
    expected = float(trim_omega(prop, p, 2.0).omega) * 30 / math.pi
    assert main(["trim", "apce_8x6", "--thrust", "2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["solved_for"] == "rpm" and out["rpm"] == pytest.approx(expected, rel=1e-12)
    assert out["thrust"] == pytest.approx(2.0, abs=1e-6) and out["added_collective_deg"] == 0.0
    assert out["rpm_range"] == pytest.approx([93.9891, 28786.1], rel=1e-5) and "range_deg" not in out
    assert main(["trim", "apce_8x6", "--thrust", "2", "--rpm-range", "1000", "9000"]) == 0
    text = capsys.readouterr().out
    assert f"{expected:.1f} rpm (" in text and "makes T = 2.0000 N at collective 0 deg" in text
    assert "1 solution(s) seen in [1000, 9000] rpm" in text
    # with --rpm the collective, as before
    assert main(["trim", "apce_8x6", "--thrust", "2", "--rpm", "6000", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["solved_for"] == "collective" and out["rpm"] == 6000.0 and out["range_deg"] == [-20.0, 30.0]


@pytest.mark.parametrize("argv, match", [
    (["--range-deg", "0", "5"], "--range-deg: the collective is trimmed only at a given --rpm"),
    (["--rpm", "6000", "--rpm-range", "1000", "9000"], "--rpm-range: with --rpm the collective is trimmed"),
    (["--rpm-range", "9000", "1000"], r"--rpm-range must be two rates LOW < HIGH within \(0, 954929\] rpm"),
    (["--rpm-range", "1000", "2000"], r"--thrust: no rotation rate in \[104.72, 209.44\] rad/s"),
])
def test_cli_rpm_trim_refusals(capsys, argv, match):
    import re

    assert main(["trim", "apce_8x6", "--thrust", "2", *argv]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and re.search(match, err), err


def test_trim_reaches_a_small_thrust_to_its_relative_tolerance():
    """The absolute 1e-6 N tolerance took 5e-5 N to 4.913e-5 (2% short) and both 2e-5 and 2.1e-5 N
    at 300 rpm to the same collective, 0; now within 1e-6 of the thrust asked (core/trim.THRUST_RTOL)."""
    prop = pm.load_propeller("cfnq_45p1")
    p = pm.resolve_params("generic")
    r = trim_omega(prop, p, [5e-5, 1e-4])
    assert r.loads.thrust == pytest.approx([5e-5, 1e-4], rel=1e-6)
    c = trim_collective(prop, p, [2e-5, 2.1e-5], 300 * math.pi / 30)
    assert c.loads.thrust == pytest.approx([2e-5, 2.1e-5], rel=1e-6)
    assert np.degrees(c.collective[1] - c.collective[0]) > 0.3


def test_each_point_of_a_trim_has_its_own_thrust_tolerance():
    """A first version took one tolerance for the batch from its smallest thrust: the 2 N point's
    rate moved by 3.65e-6 rad/s with a 1e-3 N point beside it, and 5e-324 N made it 0 (a review)."""
    prop = pm.load_propeller("apce_8x6")
    p = pm.resolve_params("generic")
    alone = trim_omega(prop, p, [2.0])
    beside = trim_omega(prop, p, [1e-3, 2.0, 5e-324], on_missing="nan")
    assert beside.omega[1] == alone.omega[0]
    assert beside.loads.thrust[0] == pytest.approx(1e-3, rel=1e-6)
