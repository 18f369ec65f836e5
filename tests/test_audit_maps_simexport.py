"""A mutation audit of maps.py, rotormap.py and simexport/ (2026-11-29): each test kills a hand-made mutant that
survived the modules' own test files, by the documented behaviour it changed."""

import math
import warnings

import numpy as np
import pytest

import propmap as pm
from propmap.maps import RotorMap, build_map

from .conftest import RPM

RPMS = np.array([4000.0, 6000.0, 8000.0])
SPEEDS = np.array([0.0, 5.0, 10.0])
INCIDENCES = np.array([0.0, 45.0, 90.0, 135.0, 180.0])


@pytest.fixture(scope="module")
def tiny():
    """apce_8x6 with its calibrated set on a 3 x 3 x 5 grid, no check points: (prop, params, dataset)."""
    prop = pm.load_propeller("apce_8x6")
    params = pm.default_params("apce_8x6")
    ds = build_map(prop, params, RPMS * RPM, SPEEDS, np.radians(INCIDENCES), n_check=0)
    return prop, params, ds


def test_map_power_and_coefficients_follow_their_definitions(tiny):
    """The map's power is Q Omega [W], CT = T / (rho n^2 D^4) and CP = P / (rho n^3 D^5), n in rev/s."""
    prop, params, ds = tiny
    n = ds["omega"].values[:, None, None] / (2 * math.pi)
    assert np.allclose(ds["rpm"].values, RPMS) and np.allclose(ds["omega"].values, RPMS * 2 * math.pi / 60)
    power = ds["torque"].values * ds["omega"].values[:, None, None]
    assert np.allclose(ds["power"].values, power, rtol=1e-12, atol=0)
    rho, D = params.air.rho, prop.diameter
    assert np.allclose(ds["CT"].values, ds["thrust"].values / (rho * n**2 * D**4), rtol=1e-12, atol=0)
    assert np.allclose(ds["CP"].values, power / (rho * n**3 * D**5), rtol=1e-12, atol=0)
    # hover at 6000 rpm, by the model itself
    r = pm.rotor_loads(prop, params, 6000 * RPM, 0.0, 0.0)
    assert float(ds["CT"].sel(rpm=6000.0, airspeed=0.0, incidence_deg=0.0)) == pytest.approx(
        r.thrust / (rho * 100.0**2 * D**4), rel=1e-9)


def test_export_sim_refuses_an_envelope_that_cannot_separate_the_terms():
    """export_sim raises (not fits to round-off) where the envelope cannot separate the terms (MAX_CONDITION)."""
    from propmap.simexport import Envelope, export_sim

    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    env = Envelope(rpm=(5000.0, 5000.001), airspeed=(10.0, 10.000001))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ValueError, match=r"the envelope cannot separate .*condition number"):
            export_sim("multinomial", prop, params, envelope=env, n_points=200)


@pytest.mark.parametrize("flag", ["multiple_roots", "vortex_ring", "converged"])
@pytest.mark.parametrize("interpolation", ["cubic", "linear"])
def test_a_bad_node_flags_the_cells_within_one_node_of_it(tiny, flag, interpolation):
    """A node in vortex ring, with multiple roots or not converged flags its cells and their neighbours, not beyond."""
    clean = _clean(tiny[2])  # (its own vortex ring at 135-180 deg cleared)
    ds = clean.copy(deep=True)
    ds[flag].loc[dict(rpm=6000.0, airspeed=5.0, incidence_deg=0.0)] = flag != "converged"
    rm, base = RotorMap(ds, interpolation), RotorMap(clean, interpolation)
    om, V = 5000 * RPM, 7.0
    b = np.radians([20.0, 60.0, 100.0, 120.0])  # cells 0, 1 (within one node of incidence 0) and 2 (not)
    assert not base.loads(om, V, b).flagged.any()
    assert list(rm.loads(om, V, b).flagged) == [True, True, False, False]
    assert [rm.loads(om, V, float(x)).flagged for x in b] == [True, True, False, False]  # the one-point path


def test_export_sim_warns_that_a_flapping_sets_side_loads_are_left_out():
    """export_sim warns that a set with a side force and pitching moment (flapping blades) has them left out."""
    from propmap.simexport import Envelope, export_sim

    prop, params = pm.load_propeller("apce_8x6"), pm.generic_params().replace(flap_compliance=2.0)
    env = Envelope(rpm=(5000.0, 8000.0), airspeed=(0.0, 10.0))
    with pytest.warns(UserWarning, match=r"side force and a pitching moment .*k_flap is written 0"):
        export_sim("rotorpy", prop, params, envelope=env, n_points=40)


@pytest.mark.parametrize("n_points", [19, 0, 20.5, True])
def test_export_sim_refuses_fewer_than_20_points(n_points):
    """export_sim's n_points must be an integer in [20, 1,000,000]: 19, 0, 20.5 and True are refused by name."""
    from propmap.simexport import Envelope, export_sim

    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    with pytest.raises(ValueError, match=r"n_points must be an integer in \[20, 1000000\]"):
        export_sim("gz-sim", prop, params, envelope=Envelope(rpm=(5000.0, 8000.0)), n_points=n_points)


@pytest.fixture(scope="module")
def rotorpy_export():
    """A rotorpy export of apce_8x6 over a small envelope (40 points)."""
    from propmap.simexport import Envelope, export_sim

    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return prop, params, export_sim("rotorpy", prop, params, envelope=Envelope(rpm=(4000.0, 9000.0),
                                                                                   airspeed=(0.0, 12.0)), n_points=40)


def _quad(prop, axis=(0.0, 0.0, 1.0), n=4, body_drag=None):
    """An X multirotor of ``n`` apce_8x6 rotors (alternating spins) with an inertia."""
    from propmap.vehicle import Rotor, Vehicle

    pos = [(0.1 * math.cos(a), 0.1 * math.sin(a), 0.0) for a in np.linspace(0, 2 * math.pi, n, endpoint=False)]
    rotors = tuple(Rotor(np.array(p), np.array(axis, float), (-1) ** k, prop) for k, p in enumerate(pos))
    return Vehicle(mass=1.2, rotors=rotors, inertia=np.diag([0.01, 0.011, 0.02]), motor_time_constant=0.02, name="X",
                   body_drag=body_drag)


def test_rotorpy_quad_params_parasitic_drag_is_half_rho_times_the_drag_area(tmp_path, rotorpy_export):
    """The written quad_params' c_Dx, c_Dy, c_Dz are rho (C_D A) / 2 from the vehicle's drag areas."""
    import runpy

    from propmap.core.body import BodyDrag
    from propmap.simexport import write_export

    prop, params, res = rotorpy_export
    veh = _quad(prop, body_drag=BodyDrag(drag_area=(0.004, 0.006, 0.01)))
    path, _ = write_export(res, tmp_path / "quad.py", vehicle=veh)
    q = runpy.run_path(str(path))["quad_params"]
    rho = params.air.rho
    assert res.meta["rho"] == rho
    assert (q["c_Dx"], q["c_Dy"], q["c_Dz"]) == pytest.approx((0.002 * rho, 0.003 * rho, 0.005 * rho), rel=1e-15)


@pytest.mark.parametrize("n, axis, match", [(6, (0.0, 0.0, 1.0), "the vehicle has 6 rotors"),
                                            (3, (0.0, 0.0, 1.0), "the vehicle has 3 rotors"),
                                            (4, (0.0, 0.6, 0.8), r"rotor 1's axis \[0, 0.6, 0.8\] is not body \+z")])
def test_rotorpy_refuses_a_vehicle_it_cannot_represent(tmp_path, rotorpy_export, n, axis, match):
    """write_export refuses, naming it, a vehicle RotorPy cannot run: not 4 rotors, or a rotor not along +z."""
    from propmap.simexport import write_export

    prop, _, res = rotorpy_export
    with pytest.raises(ValueError, match=match):
        write_export(res, tmp_path / "quad.py", vehicle=_quad(prop, axis, n))
    assert not (tmp_path / "quad.py").exists()


def test_export_sim_samples_the_envelopes_incidence_range():
    """An envelope of incidence 0 to 1e-9 deg (axial flow) cannot determine k_h or k_d: fixed at 0 and said."""
    from propmap.simexport import Envelope, export_sim

    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    env = Envelope(rpm=(4000.0, 9000.0), airspeed=(0.0, 12.0), incidence_deg=(0.0, 1e-9))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = export_sim("rotorpy", prop, params, envelope=env, n_points=40)
    said = [str(w.message) for w in caught]
    assert any(m.startswith("k_h fixed at 0: its term's size mu^2") for m in said), said
    assert any(m.startswith("k_d fixed at 0: its term's size mu ") for m in said), said
    assert set(res.fixed) == {"k_h", "k_d"} and res.coefficients["k_h"] == res.coefficients["k_d"] == 0.0
    assert res.coefficients["k_z"] > 0


def _clean(ds):
    """``ds`` with every node converged and none in vortex ring or with multiple roots."""
    clean = ds.copy(deep=True)
    for f in ("multiple_roots", "vortex_ring", "converged"):
        clean[f].values[...] = f == "converged"
    return clean


def test_check_map_counts_apart_the_points_the_model_flags(tiny, monkeypatch):
    """check_map counts apart the points the model flags: not converged or multiple roots, beside vortex ring."""
    import dataclasses

    import propmap.core.solver as solver
    from propmap.maps import check_map

    prop, params, ds = tiny
    seen = {}
    real = solver.rotor_loads

    def flagging(*args, **kwargs):
        r = real(*args, **kwargs)
        if np.ndim(args[3]) == 1:  # the check points (the static call has V = 0.0)
            V = np.asarray(args[3])
            r = dataclasses.replace(r, multiple_roots=V > 8.0, converged=~((V > 1.0) & (V < 2.0)))
            seen["r"] = r
        return r

    monkeypatch.setattr(solver, "rotor_loads", flagging)
    out = check_map(_clean(ds), 200, seed=3, propeller=prop, params=params, air=params.air,
                    discretization=pm.Discretization())
    r = seen["r"]
    assert (~r.converged).sum() > 5 and r.multiple_roots.sum() > 5
    assert out["check_points_flagged"] == int((~r.converged | r.multiple_roots | r.vortex_ring).sum())


def test_check_map_gives_the_largest_errors_point_in_rpm_ms_and_degrees(tiny):
    """check_map's check_<m>_<var>_max_at is the maximum's point [rpm, m/s, deg], inside the map's grid."""
    from propmap.maps import check_map

    out = check_map(tiny[2], 50, seed=1)
    at = {k: v for k, v in out.items() if k.endswith("_max_at")}
    assert len(at) == 2 * 5  # linear and cubic, T D Q M_R P
    for k, (rpm, V, deg) in at.items():
        assert 4000.0 <= rpm <= 8000.0 and 0.0 <= V <= 10.0 and 0.0 <= deg <= 180.0, (k, rpm, V, deg)


@pytest.mark.parametrize("target, omega", [("multinomial", 0.0), ("multinomial", -500.0), ("rotorpy", -500.0),
                                           ("gz-sim", np.array([600.0, -1.0])), ("gazebo-classic", math.nan)])
def test_predict_refuses_a_rotation_rate_its_model_cannot_take(target, omega):
    """predict refuses Omega < 0 or NaN (and 0 for the multinomial) by name, not NaN or wrong-sign loads."""
    from propmap.simexport import predict

    c = {"k_eta": 1e-5, "k_m": 1e-7, "k_d": 1e-4, "k_z": 1e-5, "k_h": 0.0, "motorConstant": 1e-5,
         "momentConstant": 0.01, "rotorDragCoefficient": 1e-4, "rollingMomentCoefficient": 1e-6, "R": 0.1, "rho": 1.2,
         "CT": [0.01] * 6, "CH": [0.001] * 4, "CQ": [0.001] * 6, "CR": [0.001] * 4}
    # (the multinomial's own words at 0; elsewhere rotor_loads' range, since 2026-12-01)
    with pytest.raises(ValueError, match=rf"omega must be > 0 rad/s for the {target} model" if np.all(omega == 0.0)
                       else r"omega must be finite and in \[0, 100000\] rad/s"):
        predict(target, c, omega, 5.0, 1.0)
    T, D, Q, MR = predict(target, c, 600.0, 5.0, 1.0)
    assert T > 0 and D > 0 and Q > 0 and np.isfinite(MR)
    if target != "multinomial":  # a stopped rotor of the simulators' models: no thrust, drag or torque
        assert predict(target, c, 0.0, 5.0, 1.0)[1:3] == (0.0, 0.0)


def test_lookup_power_is_torque_times_omega_and_held_at_the_top_row_under_clip(tiny):
    """MapLoads.power is Q Omega [W]: the map's power at a node; under "clip" above the grid, the top row's."""
    _, _, ds = tiny
    rm = RotorMap(ds)
    node = ds.sel(rpm=6000.0, airspeed=5.0, incidence_deg=90.0)
    for om in (6000 * RPM, np.array([6000 * RPM])):
        got = rm.loads(om, 5.0, math.radians(90.0))
        assert np.allclose(got.power, float(node["power"]), rtol=1e-12, atol=0)
    top = ds.sel(rpm=8000.0, airspeed=5.0, incidence_deg=90.0)
    for om in (9000 * RPM, np.array([9000 * RPM])):
        got = rm.loads(om, 5.0, math.radians(90.0), out_of_grid="clip")
        assert np.allclose(got.omega, 8000 * RPM, rtol=1e-15) and not np.any(got.inside)
        assert np.allclose(got.power, float(top["power"]), rtol=1e-12, atol=0)


@pytest.mark.parametrize("method", ["linear", "cubic"])
def test_check_map_normalises_thrust_and_torque_errors_by_their_static_values(tiny, method):
    """check_map's T and Q errors are |map - model| over the static thrust and torque at the point's Omega."""
    from propmap.maps import check_map

    prop, params, ds = tiny
    out = check_map(ds, 60, seed=2)
    rm = RotorMap(ds, method)
    for k in ("thrust", "torque"):
        rpm, V, deg = out[f"check_{method}_{k}_max_at"]
        om, b = rpm * RPM, math.radians(deg)
        full = pm.rotor_loads(prop, params, om, V, b)
        static = pm.rotor_loads(prop, params, om, 0.0, 0.0)
        err = abs(getattr(rm.loads(om, V, b), k) - getattr(full, k)) / abs(getattr(static, k))
        assert out[f"check_{method}_{k}_max"] == pytest.approx(err, rel=1e-6), k


@pytest.mark.parametrize("axes, match", [
    (([0.05, 400.0], [0.0, 5.0], [0.0, 1.0]), r"omega must be finite and within \[0.1, 100000\] rad/s, got \[0.05,"),
    (([400.0, 600.0], [-1.0, 5.0], [0.0, 1.0]), r"airspeed must be finite and within \[0, 500\] m/s, got \[-1, 5\]"),
    (([400.0, 600.0], [0.0, 5.0], [-0.1, 1.0]), r"incidence must be finite and within \[0, 3.14159\] rad"),
    (([400.0, 400.0, 600.0], [0.0, 5.0], [0.0, 1.0]), r"omega must be strictly increasing"),
    (([400.0, 600.0], [0.0, 5.0, 5.0], [0.0, 1.0]), r"airspeed must be strictly increasing"),
    (([400.0], [0.0, 5.0], [0.0, 1.0]), r"omega must be a 1-D axis of at least 2 values, got shape \(1,\)")])
def test_build_map_refuses_an_axis_below_its_range_or_not_strictly_increasing(tiny, axes, match):
    """build_map refuses, naming it, an axis below the model's range, with a repeated value, or of one value."""
    prop, params, _ = tiny
    with pytest.raises(ValueError, match=match):
        build_map(prop, params, *axes, n_check=0)


def test_map_rpm_axis_is_free_of_the_conversions_round_off_and_stays_strictly_increasing(tiny):
    """The rpm axis drops the rad/s round-off (1234.56789012 rpm is found by sel), never making two nodes equal."""
    prop, params, _ = tiny
    ax = (np.array([0.0, 5.0]), np.array([0.0, 1.0]))
    om = np.array([1234.56789012, 6000.0]) * RPM
    assert (om / RPM)[0] != 1234.56789012  # (the conversion's round-off)
    ds = build_map(prop, params, om, *ax, n_check=0)
    assert list(ds["rpm"].values) == [1234.56789012, 6000.0] and float(ds.sel(rpm=1234.56789012)["thrust"][0, 0]) > 0
    # two nodes 2 units in the last place apart: both within round-off of 6000, kept apart as they are
    om = np.array([6000.0 + np.spacing(6000.0), 6000.0 + 3 * np.spacing(6000.0)]) * RPM
    assert np.diff(om / RPM)[0] > 0 and np.all(np.abs(om / RPM - 6000.0) < 4 * np.spacing(6000.0))
    ds = build_map(prop, params, om, *ax, n_check=0)
    assert np.all(np.diff(ds["rpm"].values) > 0) and np.array_equal(ds["omega"].values, om)


def test_build_map_refuses_one_node_past_max_nodes_before_any_work(tiny):
    """build_map refuses a grid of more than MAX_NODES (20,000,000) nodes up front, naming the count."""
    from propmap.maps import MAX_NODES

    prop, params, _ = tiny
    # (a propeller a map cannot record, refused after the count: a count let through would end there, not solve)
    odd = pm.Propeller(name="x", radius=prop.radius, n_blades=200, r=prop.r, chord=prop.chord, theta=prop.theta)
    axes = (np.linspace(100.0, 1000.0, 1001), np.linspace(0.0, 10.0, 1001), np.linspace(0.0, 1.0, 20))
    assert 1001 * 1001 * 20 == 20_040_020 > MAX_NODES == 20_000_000
    with pytest.raises(ValueError, match=r"1001 x 1001 x 20 = 20,040,020 nodes; at most 20,000,000"):
        build_map(odd, params, *axes)
    with pytest.raises(ValueError, match=r"1 to 100 blades"):  # (at MAX_NODES the count passes)
        build_map(odd, params, axes[0][:1000], axes[1][:1000], axes[2])
