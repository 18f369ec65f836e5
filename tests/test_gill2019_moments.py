"""The rolling and pitching moments of four catalogue propellers in oblique flow (Gill & D'Andrea,
Drones 3(4):77, 2019, Appendix A: the multinomial model's k9-k12, eqs 101-102; data/published).

The published fits give the hub moments the tunnel's balance measured, which propmap predicts
(``rolling_moment``, ``pitching_moment``) but had not compared with a measurement: the rolling
moment of a rigid rotor comes out 1.2-1.8 times the measured slope, and the blade flapping that
brings the in-plane force up to the tunnel's takes the rolling moment down to 0-40% of it
(docs/validation.md, gill2019 case, Rolling and pitching moments).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import propmap as pm
from propmap.cases import (GILL2019_ADVANCE, GILL2019_INCIDENCE_DEG, gill2019_coefficients, gill2019_loads,
                           multinomial_fit, run_case)

NAMES = ("apce_8x6", "apce_8x8", "apce_10x7", "apcsf_10x4.7")


def test_the_moment_coefficients_are_the_published_ones():
    # Gill & D'Andrea (2019), Appendix A, Sec. 5 oblique-flow fits, as transcribed (data/published)
    c = gill2019_coefficients()
    assert [c[n]["k9"] for n in NAMES] == [0.032, 0.039, 0.029, 0.026]
    assert [c[n]["k11"] for n in NAMES] == [4.5e-3, 4.2e-3, 6.6e-3, 0.015]
    assert c["apce_8x6"]["k10"] == -2.1e-8 and c["apcsf_10x4.7"]["k12"] == 5.4e-8
    # as with the H-force's k5, the lambda_c terms are zero in effect (below 1e-5 of the mu terms over
    # lambda_c <= 0.24): the published moments are k9 mu and k11 mu
    for n in NAMES:
        assert abs(c[n]["k10"]) * 0.24 < 1e-5 * c[n]["k9"] and abs(c[n]["k12"]) * 0.24 < 1e-5 * c[n]["k11"], n


def _grid(prop, om):
    adv, inc = np.meshgrid(GILL2019_ADVANCE, np.radians(GILL2019_INCIDENCE_DEG))
    adv, inc = np.concatenate([[0.0], adv.ravel()]), np.concatenate([[0.0], inc.ravel()])
    return adv * om * prop.radius, inc, adv * np.sin(inc), adv * np.cos(inc)


@pytest.mark.parametrize("flap", [0.0, 1.0])
def test_multinomial_fit_moments_are_the_least_squares_of_the_models_moments(flap):
    prop, om = pm.load_propeller("apce_10x7"), 600.0
    p = pm.default_params("apce_10x7").replace(flap_compliance=flap)
    f = multinomial_fit(prop, p, om)
    V, inc, mu, lam = _grid(prop, om)
    r = pm.rotor_loads(prop, p, om, V, inc, air=p.air)
    qR = 0.5 * p.air.rho * math.pi * prop.radius**3 * (om * prop.radius) ** 2
    for m, k, k_lam, k_mu in ((r.rolling_moment, "k9", "k10", "k9_mu_only"),
                              (r.pitching_moment, "k11", "k12", "k11_mu_only")):
        both = np.linalg.lstsq(np.column_stack([mu, lam * mu]), m / qR, rcond=None)[0]
        assert (f[k], f[k_lam]) == pytest.approx(tuple(both), rel=1e-9, abs=1e-15)
        assert f[k_mu] == pytest.approx(float(np.sum(mu * m / qR) / np.sum(mu**2)), rel=1e-9, abs=1e-15)
    # the rolling moment grows with mu (more thrust on the advancing side) and, as the H-force, with lambda_c
    assert f["k9"] > 0 and f["k10"] > 0
    if flap == 0.0:  # a rigid rotor with the paper's uniform inflow has no pitching moment (docs/conventions.md)
        assert f["k11"] == 0.0 and f["k12"] == 0.0
    else:  # flapping blades tilt back: a nose-up hub moment (positive M_P), growing with mu
        assert f["k11"] > 0.1 * f["k9"]


def test_a_rigid_rotor_rolls_more_and_flapping_blades_far_less_than_the_wind_tunnel_measured():
    sets = {"rigid": pm.default_params, "flap 0.5": lambda n: pm.default_params(n).replace(flap_compliance=0.5),
            "flap 10": lambda n: pm.default_params(n).replace(flap_compliance=10.0),
            "pitt-peters": lambda n: pm.default_params(n).replace(inflow="pitt-peters")}
    m = run_case("gill2019", sets)
    c = gill2019_coefficients()
    assert m.measured["MR_slope"].tolist() == pytest.approx([c[n]["k9"] / c[n]["CT_static"] for n in NAMES])
    assert m.measured["MP_slope"][3] == pytest.approx(0.015 / 0.032)
    rigid, flap, pp = m.metrics["rigid"], m.metrics["flap 10"], m.metrics["pitt-peters"]
    for n in NAMES:
        # each calibrated set (fitted to its UIUC axial data): the rolling moment's slope above the tunnel's, the
        # H-force's below it, no pitching moment (the published ones are 11-58% of the rolling moment)
        assert 1.1 < rigid[f"MR_slope_ratio_{n}"] < 1.9 and rigid[f"H_slope_mu_only_ratio_{n}"] < 0.75
        assert rigid[f"MP_slope_ratio_{n}"] == 0.0
        # blades flapping enough to reach the tunnel's in-plane force transmit almost no rolling moment to the hub
        assert flap[f"H_slope_mu_only_ratio_{n}"] > 1.0 and flap[f"MR_slope_ratio_{n}"] < 0.06
        assert m.metrics["flap 0.5"][f"MR_slope_ratio_{n}"] < rigid[f"MR_slope_ratio_{n}"]
        # Pitt-Peters' fore-aft gradient makes a nose-up pitching moment of the published size (0.2-0.9 of it)
        # and leaves the rolling moment and the H-force as they were (within 1%)
        assert 0.2 < pp[f"MP_slope_ratio_{n}"] < 0.9
        assert pp[f"MR_slope_ratio_{n}"] == pytest.approx(rigid[f"MR_slope_ratio_{n}"], rel=0.01)
    # regression values (2026-12-01, the calibration of 2026-11-29; docs/validation.md): the calibrated sets' rolling
    # moment slope 1.17-1.77 times the tunnel's, 0.78-1.25 with a flapping compliance of 0.5 rad/(N m)
    assert [rigid[f"MR_slope_ratio_{n}"] for n in NAMES] == pytest.approx([1.336, 1.166, 1.266, 1.765], abs=0.005)
    assert m.metrics["flap 0.5"]["MR_slope_ratio_min"] == pytest.approx(0.78, abs=0.01)
    assert m.metrics["flap 0.5"]["MR_slope_ratio_max"] == pytest.approx(1.25, abs=0.01)
    # the moments' rms against the published fits on their grid, of the static thrust times R (regression values,
    # 2026-12-01), and one of them recomputed
    assert rigid["rms_rolling_moment"] == pytest.approx(0.0456, abs=0.001)
    assert rigid["rms_pitching_moment"] == pytest.approx(0.0299, abs=0.001)
    assert pp["rms_pitching_moment"] < 0.6 * rigid["rms_pitching_moment"]
    d, prop = gill2019_loads("apce_8x8", (6000.0,)), pm.load_propeller("apce_8x8")
    r = pm.rotor_loads(prop, pm.default_params("apce_8x8"), d.omega, d.airspeed, d.incidence, air=pm.Air())
    R, k = prop.radius, c["apce_8x8"]
    mu = d.airspeed * np.sin(d.incidence) / (d.omega * R)
    lam = d.airspeed * np.cos(d.incidence) / (d.omega * R)
    published = 0.5 * 1.225 * math.pi * R**3 * (d.omega * R) ** 2 * (k["k9"] * mu + k["k10"] * lam * mu)
    T0 = d.measured["thrust"][d.airspeed == 0].mean()
    assert rigid["rms_rolling_moment_apce_8x8"] == pytest.approx(
        float(np.sqrt(np.mean(((r.rolling_moment - published) / (T0 * R)) ** 2))), rel=1e-12)
