"""flight_samples' ground rule and its decimated rate on hand-built logs (a second mutation audit,
2026-11-27: the log's own hover speed from its fastest quarter, and the rate reported, survived
the suite). The vehicle is the bundled NeuroBEM quadrotor (Bauersfeld et al. 2021)."""

from pathlib import Path
import numpy as np
import propmap as pm
from propmap.identify.flight import flight_samples
from propmap.identify.flight_samples import _hover_speed
from propmap.io.flightlog import FlightLog

VEHICLE = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
G = 9.80665


def test_ground_rule_uses_the_logs_own_hover_speed_from_its_fastest_quarter():
    """55% idling on the ground (0.2 H), 10% standing still at 0.8 H, 35% flying at 1.3 H (H the
    model's hover speed), the accelerometer reading g throughout. The log's own hover speed, from
    its fastest quarter, is 1.3 H (within HOVER_RANGE of H), so the ground threshold is
    0.7 x 1.3 H = 0.91 H: the 0.8 H samples are on the ground too -> 650 of 1000 left out."""
    veh = pm.read_vehicle(VEHICLE)
    H = _hover_speed(veh)
    assert H > 0
    n = 1000
    om = np.concatenate([np.full(550, 0.2 * H), np.full(100, 0.8 * H), np.full(350, 1.3 * H)])
    vel = np.zeros((n, 3)); vel[650:, 0] = 3.0
    log = FlightLog(name="synthetic", path="", format="neurobem", t=np.arange(n) * 0.01,
                    angular_velocity=np.zeros((n, 3)), angular_acceleration=np.zeros((n, 3)),
                    specific_force=np.tile([0.0, 0.0, G], (n, 1)), velocity=vel,
                    attitude=np.tile([1.0, 0, 0, 0], (n, 1)), rotor_omega=np.tile(om[:, None], (1, 4)),
                    rotor_acceleration=None)
    s = flight_samples([log], veh, rate_hz=100.0, motor_time_constant=0.0)
    assert s.n == 350
    assert any("650 sample(s) on the ground left out" in x for x in s.notes), s.notes


def test_rate_is_the_decimated_one():
    veh = pm.read_vehicle(VEHICLE)
    H = _hover_speed(veh)
    n = 800
    log = FlightLog(name="fast", path="", format="neurobem", t=np.arange(n) / 400.0,
                    angular_velocity=np.zeros((n, 3)), angular_acceleration=np.zeros((n, 3)),
                    specific_force=np.tile([0.0, 0.0, G], (n, 1)), velocity=np.tile([3.0, 0, 0], (n, 1)),
                    attitude=np.tile([1.0, 0, 0, 0], (n, 1)), rotor_omega=np.full((n, 4), H),
                    rotor_acceleration=None)
    s = flight_samples([log], veh, rate_hz=25.0, motor_time_constant=0.0)
    assert abs(s.rate_hz - 25.0) < 1e-9 and s.n == 50
