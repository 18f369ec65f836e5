"""Behaviour a mutation audit found unpinned (2026-11-29, a helper session: 88 mutants of
vehicle/file.py (24), vehicle/trim.py (20), vehicle/layout.py (20) and io/flightlog_checks.py (24), 40
survived the test files that exercise them, 4 of those equivalent: trim A and F, layout R, flog W).
Each test names the audit's mutants it kills (letters per module)."""

import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.vehicle import VehicleFileError, read_vehicle

EXAMPLES = Path(pm.__file__).parent / "data" / "examples"
ROTOR = '[[rotors]]\nposition = [{x}, {y}, 0.0]\naxis = {axis}\nspin = "{spin}"\npropeller = "apce_8x6"\n'


def _quad(axes=("[0, 0, 1]",) * 4, spins=("ccw", "cw", "ccw", "cw")):
    """An X quadrotor of APC 8x6E rotors, 0.15 m arms (the bundled quadrotor's layout)."""
    xy = ((0.106, 0.106), (0.106, -0.106), (-0.106, -0.106), (-0.106, 0.106))
    return "".join(ROTOR.format(x=x, y=y, axis=a, spin=s) for (x, y), a, s in zip(xy, axes, spins))


def _read(tmp_path, text, name="v.toml"):
    (tmp_path / name).write_text(text)
    return read_vehicle(tmp_path / name)


# ---- vehicle/file.py ----------------------------------------------------------------------------------------------

def test_every_range_includes_its_documented_upper_end(tmp_path):
    """The module docstring's ranges are closed above: mass (0, 1e4], gravity (0, 100], body_area,
    motor_time_constant, rotor_interference and a rotor's inertia at their ends read. Kills file B."""
    text = ("mass = 10000\ngravity = 100\nbody_area = 100\nmotor_time_constant = 1\nrotor_interference = 3\n"
            + _quad() + "inertia = 100\n")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (a 10 t vehicle on 8 in propellers is warned of elsewhere)
        v = _read(tmp_path, text)
    assert (v.mass, v.gravity, v.body_area, v.motor_time_constant, v.rotor_interference) == (1e4, 100, 100, 1, 3)
    assert v.rotors[3].inertia == 100.0 and v.weight == 1e6


@pytest.mark.parametrize("inertia, match", [
    ("[0.0025, 0.0021, 0.0]", r"inertia must be positive definite \(all principal moments > 0\)"),
    ("[2e6, 2e6, 3e6]", r"inertia must have finite elements within \+-1e\+06 kg m\^2"),
])
def test_a_singular_or_huge_inertia_is_refused(tmp_path, inertia, match):
    """A principal moment of zero (a missing entry typed as 0) is not positive definite; an
    element beyond 1e6 kg m^2 is refused. Kills file E (eigenvalue < 0 only) and F (no bound)."""
    with pytest.raises(VehicleFileError, match=match):
        _read(tmp_path, f"mass = 1.0\ninertia = {inertia}\n{_quad()}")


def test_a_body_without_wash_factor_has_no_slipstream_drag(tmp_path):
    """[body] with drag_area only: wash_factor 0 (core/body.py's default), not the docstring
    example's 1.0; the hover's download is then zero. Kills file G."""
    v = _read(tmp_path, f"mass = 1.0\n[body]\ndrag_area = [0.004, 0.004, 0.008]\n{_quad()}")
    assert v.body_drag.wash_factor == 0.0 and v.body_drag.drag_area == (0.004, 0.004, 0.008)


def test_a_geometry_file_of_one_blade_reads_and_diameters_make_two_propellers(tmp_path):
    """blades is in [1, 100]: a one-bladed rotor (a mono-blade) reads; two rotors of one geometry
    file with other diameter_m values get propellers of those radii, rotors of one diameter the
    same object. Kills file H (blades 1 refused) and K (propellers cached without the diameter)."""
    (tmp_path / "blade.txt").write_bytes((EXAMPLES / "neurobem_5.1x4.8_geom.txt").read_bytes())
    rotors = "".join(f'[[rotors]]\nposition = [{x}, {y}, 0.0]\naxis = [0, 0, 1]\nspin = "{s}"\n'
                     f'propeller = "blade.txt"\nblades = {b}\ndiameter_m = {d}\n'
                     for x, y, s, b, d in ((0.2, 0.2, "ccw", 1, 0.13), (0.2, -0.2, "cw", 1, 0.2),
                                           (-0.2, -0.2, "ccw", 1, 0.13), (-0.2, 0.2, "cw", 1, 0.2)))
    v = _read(tmp_path, f"mass = 1.0\n{rotors}")
    assert [r.propeller.n_blades for r in v.rotors] == [1] * 4
    assert [r.propeller.radius for r in v.rotors] == pytest.approx([0.065, 0.1, 0.065, 0.1], rel=1e-12)
    assert v.rotors[0].propeller is v.rotors[2].propeller and v.rotors[0].propeller is not v.rotors[1].propeller


def test_a_centre_of_mass_beyond_100_m_is_refused(tmp_path):
    """centre_of_mass components lie in [-100, 100] m (a position in mm). Kills file J."""
    with pytest.raises(VehicleFileError, match=r"centre_of_mass must have components in \[-100, 100\] m, got "
                                               r"\[150, 0, 0\]"):
        _read(tmp_path, f"mass = 1.0\ncentre_of_mass = [150, 0, 0]\n{_quad()}")


def test_spin_is_read_in_either_case_and_one_downward_rotor_is_read(tmp_path):
    """'CW' and 'Ccw' are the spins 'cw' and 'ccw'; a vehicle with one rotor pointing down (a
    pusher-like or inverted rotor) is read: only every axis down is a z-down frame's. Kills file
    L (case-sensitive spins) and N (any axis down refused)."""
    v = _read(tmp_path, "mass = 1.0\n" + _quad(spins=("Ccw", "CW", "ccw", "cw")))
    assert [r.spin for r in v.rotors] == [1.0, -1.0, 1.0, -1.0]
    v = _read(tmp_path, "mass = 1.0\n" + _quad(axes=("[0, 0, 1]",) * 3 + ("[0, 0, -1]",)), "down.toml")
    assert v.rotors[3].axis.tolist() == [0.0, 0.0, -1.0] and v.rotors[0].axis.tolist() == [0.0, 0.0, 1.0]


def test_the_files_name_and_source_reach_the_vehicle():
    """The bundled NeuroBEM file's free-text name and source are the Vehicle's. Kills file O."""
    v = read_vehicle("neurobem_quadrotor")
    assert v.name == "NeuroBEM quadrotor (Bauersfeld et al., RSS 2021)"
    assert v.source.startswith("NeuroBEM authors' published values")


def test_a_rotor_30_radii_out_is_warned_of_once_without_the_inertias_ratio(tmp_path):
    """Arms of 3.11 m on 8 in rotors (30.6 radii, over ARM_RADII_MAX = 20) are warned of, and then
    only they: beside arms in other units the inertia's ratio to m r^2 says nothing. Kills file P
    (ARM_RADII_MAX 40) and Q (the inertia judged beside far arms)."""
    text = "mass = 0.8\ninertia = [0.0035, 0.0035, 0.0067]\n" + _quad().replace("0.106", "2.2")
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        _read(tmp_path, text)
    said = [str(w.message) for w in got]
    assert len(said) == 1 and "rotor 1's hub lies 3.111 m from the centre of mass, 30.6 of its radii" in said[0], said


@pytest.mark.parametrize("inertia, warned", [
    ("[0.0035, 0.0035, 0.0067]", None),  # the bundled quadrotor's: 0.37
    ("[5e-6, 5e-6, 9e-6]", "0.000501"),  # (regression value: 9e-6 / (0.8 kg x (0.1499 m)^2))
    ("[0.1, 0.1, 0.2]", "11.1"),
])
def test_the_inertia_is_judged_against_mass_times_arm_squared(tmp_path, inertia, warned):
    """INERTIA_ARM_RANGE = (1e-3, 10): outside it the largest principal moment over m r^2 is
    warned of, with the ratio. Kills file W (lower end 1e-4)."""
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        _read(tmp_path, f"mass = 0.8\ninertia = {inertia}\n{_quad()}")
    said = [str(w.message) for w in got]
    if warned is None:
        assert said == []
    else:
        assert len(said) == 1 and f"largest principal moment is {warned} times the mass" in said[0], said


def test_a_tricopter_spinning_one_way_is_not_warned_of_but_a_quadrotor_is(tmp_path):
    """Three parallel rotors all ccw (a tricopter balances yaw by tilting its tail rotor), or four
    of which two are pushers, read without a word; four parallel are warned of. Kills file R
    (three rotors warned) and X (axes not compared)."""
    tri = "".join(ROTOR.format(x=f"{0.25 * math.cos(a):.4f}", y=f"{0.25 * math.sin(a):.4f}", axis="[0, 0, 1]",
                               spin="ccw") for a in (0.0, 2 * math.pi / 3, 4 * math.pi / 3))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert len(_read(tmp_path, f"mass = 1.0\n{tri}").rotors) == 3
        pushers = _quad(axes=("[0, 0, 1]", "[1, 0, 0]", "[0, 0, 1]", "[1, 0, 0]"), spins=("ccw",) * 4)
        assert _read(tmp_path, f"mass = 1.0\n{pushers}", "vtol.toml").rotors[1].axis.tolist() == [1.0, 0.0, 0.0]
    with pytest.warns(UserWarning, match="every rotor spins ccw: their torques cannot balance in yaw"):
        _read(tmp_path, "mass = 1.0\n" + _quad(spins=("ccw",) * 4), "quad.toml")


def test_free_text_comments_are_allowed_and_a_slow_motor_is_refused(tmp_path):
    """'comment' is a free-text key at the top, in [body] and in a rotor; motor_time_constant lies
    in [0, 1] s (1.5: milliseconds read as seconds?). Kills file V (comment refused) and U (up to
    10 s)."""
    v = _read(tmp_path, 'mass = 1.0\ncomment = "built 2026"\n[body]\ndrag_area = [0.01, 0.01, 0.02]\n'
                        'comment = "measured"\n' + _quad() + 'comment = "the spare motor"\n')
    assert len(v.rotors) == 4 and v.body_drag is not None
    with pytest.raises(VehicleFileError, match=r"motor_time_constant must be >= 0 and <= 1 s, got 1.5"):
        _read(tmp_path, f"mass = 1.0\nmotor_time_constant = 1.5\n{_quad()}", "slow.toml")


# ---- vehicle/trim.py ----------------------------------------------------------------------------------------------

def test_a_trim_warns_of_the_advancing_tip_beyond_mach_0_8():
    """The NeuroBEM quadrotor at 11 kg hovers at tip Mach 0.78 (no warning); at 20 m/s its rotors
    turn slower (4013 rad/s, 0.76) but the advancing tip meets the air at Omega R + V: Mach 0.823,
    warned of (regression values, generic set, 2026-11-29). Kills trim H (the airspeed left out of
    the tip speed) and R (the warning from Mach 1.6)."""
    vehicle, params = dataclasses.replace(read_vehicle("neurobem_quadrotor"), mass=11.0), pm.generic_params()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pm.trim_vehicle(vehicle, params, 0.0)
    with pytest.warns(UserWarning, match=r"at Mach 0\.823 in this trim \(airspeed 20 m/s, rotors up to 401\d rad/s\)"):
        trim = pm.trim_vehicle(vehicle, params, 20.0)
    tip = max(trim.rotor_omega) * vehicle.rotors[0].propeller.radius
    assert tip / params.air.speed_of_sound < 0.8 < (tip + 20.0) / params.air.speed_of_sound


# ---- io/flightlog_checks.py ---------------------------------------------------------------------------------------

def _log(rate=400.0, duration=2.0, climb=0.0, **change):
    """A consistent flight log: hovering (climbing at ``climb`` m/s^2 from rest) while yawing at
    1 + cos(pi t) rad/s, so that the rate, angular-acceleration, gravity and kinematics checks all
    judge it; ``change`` replaces its fields."""
    from propmap.io.flightlog import FlightLog
    from propmap.io.flightlog_checks import G

    t = np.arange(0.0, duration + 0.5 / rate, 1.0 / rate)
    z, yaw = 0.0 * t, t + np.sin(math.pi * t) / math.pi
    fields = dict(t=t, angular_velocity=np.column_stack([z, z, 1.0 + np.cos(math.pi * t)]),
                  angular_acceleration=np.column_stack([z, z, -math.pi * np.sin(math.pi * t)]),
                  specific_force=np.column_stack([z, z, z + G + climb]), velocity=np.column_stack([z, z, climb * t]),
                  attitude=np.column_stack([z, z, np.sin(yaw / 2), np.cos(yaw / 2)]),
                  rotor_omega=np.full((t.size, 4), 1100.0), rotor_acceleration=None)
    return FlightLog(name="f.csv", path="f.csv", format="neurobem", **{**fields, **change})


def _check(log):
    from propmap.io.flightlog_checks import check_log
    check_log(log, "f.csv")


def test_a_consistent_climbing_log_passes_every_check_silently():
    """A log accelerating upwards at 2 m/s^2 (the accelerometer reads g + 2 along z): the gravity
    check expects g plus the velocity's change over the log. Kills flog K (g minus it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _check(_log())
        _check(_log(climb=2.0))


def test_rates_beyond_200_rad_s_and_a_quaternion_of_norm_1_1_are_refused():
    """RATE_MAX = 200 rad/s (rates in deg/s of a flip); the attitude quaternion's norm within 0.05
    of 1 (a column mistake). Kills flog E (RATE_MAX 2000) and H (QUAT_TOLERANCE 0.5)."""
    log = _log()
    w = log.angular_velocity.copy()
    w[100] = [0.0, 300.0, 1.0]
    with pytest.raises(ValueError, match=r"f.csv: sample 101: angular_velocity \[0.0, 300.0, 1.0\] beyond \+-200 "
                                         r"rad/s \(a unit or column mistake\?\)"):
        _check(dataclasses.replace(log, angular_velocity=w))
    q = log.attitude.copy()
    q[7] *= 1.1
    with pytest.raises(ValueError, match=r"f.csv: sample 8: attitude quaternion .* has norm 1.1, not 1 \(within "
                                         r"0.05\)"):
        _check(dataclasses.replace(log, attitude=q))


def test_a_vibrating_accelerometer_without_gravity_is_refused_by_the_gravity_check():
    """Gravity removed (the reading 0 in hover) under 4 m/s^2 rms of vibration: the mean's
    tolerance is 0.2 g plus three standard errors of the mean (3 x 4 / sqrt(801) = 0.42 m/s^2),
    not three standard deviations (12 m/s^2, which let it through to another check's message).
    Kills flog L."""
    log = _log()
    f = log.specific_force.copy()
    f[:, 2] = np.random.default_rng(7).normal(0.0, 4.0, log.n)
    with pytest.raises(ValueError, match=r"f.csv: the accelerometer reads -?0.\d+ m/s\^2 upwards on average .* asks "
                                         r"for 9.807 .*within 2.\d+\): accelerations in g, gravity removed"):
        _check(dataclasses.replace(log, specific_force=f))


def test_rates_of_the_other_sign_are_refused_as_another_frame():
    """Rates (and their logged derivative) negated: ratio -1 to the attitude's, below -0.5.
    Kills flog M (RATE_RATIO_AGAINST -1.5)."""
    log = _log()
    with pytest.raises(ValueError, match=r"f.csv: the logged body rates turn against the logged attitude \(ratio "
                                         r"-1(\.00)?\): rates in another body frame"):
        _check(dataclasses.replace(log, angular_velocity=-log.angular_velocity,
                                   angular_acceleration=-log.angular_acceleration))


def test_a_gap_of_50_steps_is_warned_of_and_a_small_motor_step_is_no_spike():
    """A 0.125 s gap (50 median steps, over GAP_STEPS = 20) is warned of with its place; a motor
    speed stepping 150 rad/s (14% of 1100, under SPIKE_OMEGA = 30%) for one sample is no spike:
    a spike must be 30% and 100 rad/s away. Kills flog S (GAP_STEPS 200) and U (either)."""
    log = _log()
    keep = np.r_[0:400, 449:log.n]
    cut = {f: getattr(log, f)[keep] for f in ("t", "angular_velocity", "angular_acceleration", "specific_force",
                                              "velocity", "attitude", "rotor_omega")}
    with pytest.warns(UserWarning, match=r"f.csv: a gap of 0.125 s in the log's time at t = 0.9975 s \(50 median "
                                         r"steps\): the samples either side are read as they are$") as got:
        _check(dataclasses.replace(log, **cut))
    assert len(got) == 1
    om = log.rotor_omega.copy()
    om[300, 2] = 1250.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _check(dataclasses.replace(log, rotor_omega=om))


def test_rates_in_deg_per_s_of_a_5_hz_wobble_are_refused():
    """A yaw wobble of 0.05 rad at 5 Hz with its rates logged in deg/s (90 deg/s peak, under
    RATE_MAX): over RATE_WINDOW = 0.02 s the attitude turns, ratio 57 -> refused; over 0.2 s, one
    period, it would not turn and the rates would go unjudged. Kills flog X (RATE_WINDOW 0.2)."""
    log = _log()
    t, z = log.t, 0.0 * log.t
    yaw, rate = 0.05 * np.sin(10 * math.pi * t), 0.5 * math.pi * np.cos(10 * math.pi * t)
    wobble = dataclasses.replace(log, attitude=np.column_stack([z, z, np.sin(yaw / 2), np.cos(yaw / 2)]),
                                 angular_velocity=np.column_stack([z, z, np.degrees(rate)]), angular_acceleration=None)
    with pytest.raises(ValueError, match=r"f.csv: the logged body rates are 5\d.\d times those of the logged "
                                         r"attitude's change: are they in deg/s\?"):
        _check(wobble)


# ---- vehicle/layout.py --------------------------------------------------------------------------------------------

def test_a_rotors_axis_is_a_unit_vector_and_its_inertia_may_be_zero():
    """Rotor.axis is the unit thrust direction (a 45 deg cant [1, 0, 1] is [0.7071, 0, 0.7071], not
    [1, 0, 1] over its largest component); an inertia of 0 kg m^2 is a rotor without gyroscopic
    moments, read. Kills layout A (axis scaled, not normalised) and C (inertia 0 refused)."""
    r = pm.Rotor([0.1, 0.1, 0.0], [1.0, 0.0, 1.0], "ccw", pm.load_propeller("apce_8x6"), inertia=0.0)
    np.testing.assert_allclose(r.axis, [math.sqrt(0.5), 0.0, math.sqrt(0.5)], rtol=1e-15)
    assert r.inertia == 0.0 and isinstance(r.inertia, float)


@pytest.mark.parametrize("field, value, match", [
    ("spin", True, r"Rotor.spin must be \+1 or 'ccw' .* got True"),  # (True == 1: it would read as ccw)
    ("spin", np.True_, r"Rotor.spin must be \+1 or 'ccw'"),
    ("position", [True, 0, 0], r"Rotor.position must be 3 finite numbers \(body axes\), got \[True, 0, 0\]"),
    ("mass", True, r"Vehicle.mass must be a finite number > 0, got True"),
])
def test_numpy_and_python_booleans_are_no_numbers(field, value, match):
    """A bool where a number belongs (a mask passed for a value) is refused, NumPy's too. Kills
    layout D (Python bools numbers) and E (bools inside a vector)."""
    prop = pm.load_propeller("apce_8x6")
    rotor = dict(position=[0.1, 0.1, 0.0], axis=[0, 0, 1.0], spin=1, propeller=prop)
    with pytest.raises(ValueError, match=match):
        if field == "mass":
            pm.Vehicle(mass=value, rotors=(pm.Rotor(**rotor),))
        else:
            pm.Rotor(**{**rotor, field: value})


def test_on_the_moon_the_weight_and_the_hover_speed_follow_gravity(tmp_path):
    """gravity = 1.62 m/s^2: the weight is m g = 1.296 N for 0.8 kg, and the hover speed about
    sqrt(1.62 / 9.81) = 0.41 of the Earth's (thrust ~ Omega^2; the blades' Reynolds number moves
    it a little). Kills layout L (the weight with 9.81)."""
    text = (EXAMPLES / "quadrotor.toml").read_text()
    moon = _read(tmp_path, text.replace("gravity = 9.81", "gravity = 1.62", 1))
    assert moon.weight == pytest.approx(0.8 * 1.62, rel=1e-15)
    params = pm.generic_params()
    ratio = pm.hover_omega(moon, params) / pm.hover_omega(read_vehicle("quadrotor"), params)
    assert ratio == pytest.approx(math.sqrt(1.62 / 9.81), rel=0.05)


@pytest.mark.parametrize("change, match", [
    ({"body_area": -0.01}, r"Vehicle.body_area must be a finite number in \[0, inf\], got -0.01"),
    ({"rotors": "ROTORS+x"}, r"Vehicle.rotors must be a non-empty sequence of Rotor"),
    ({"body_drag": (0.01, 0.01, 0.02)}, r"Vehicle.body_drag must be a BodyDrag or None, got tuple"),
])
def test_a_vehicle_built_in_python_refuses_what_its_file_would(change, match):
    """A negative body area, a rotor list with an item that is not a Rotor, a drag area given
    without its BodyDrag: refused naming the field. Kills layout H, I and K (each check dropped)."""
    rotor = pm.Rotor([0.1, 0.1, 0.0], [0, 0, 1.0], 1, pm.load_propeller("apce_8x6"))
    if change.get("rotors") == "ROTORS+x":
        change = {"rotors": [rotor, "x"]}
    with pytest.raises(ValueError, match=match):
        pm.Vehicle(**{"mass": 1.0, "rotors": (rotor,), **change})


def test_body_to_world_rolls_about_the_pitched_body_axis():
    """R = R_y(-pitch) R_x(roll), the aircraft's Euler sequence at zero yaw: pitched 0.3 rad and
    rolled 0.5 rad, the nose stays in the heading's vertical plane, [cos 0.3, 0, sin 0.3], and the
    right side is down by cos 0.3 sin 0.5. Kills layout Q (R_x R_y, which swings the nose sideways)."""
    R = pm.vehicle.layout.body_to_world(0.3, 0.5)
    np.testing.assert_allclose(R @ [1.0, 0.0, 0.0], [math.cos(0.3), 0.0, math.sin(0.3)], atol=1e-15)
    assert (R @ [0.0, -1.0, 0.0])[2] == pytest.approx(-math.cos(0.3) * math.sin(0.5), rel=1e-14)
