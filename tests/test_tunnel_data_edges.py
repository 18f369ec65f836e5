"""A wind-tunnel user's load data at incidence (a user-level audit, 2026-11-26): an in-plane
force measured at axial points is not fitted there (its noise, scaled by its own rms, swamped
the uncertainty report), a normal force of the other sign is refused, the residuals name the
incidence, the data's warnings reach the fit reports, a negative incidence says what to do,
and a parameter file fitted at incidence is not called unvalidated there."""

import math

import numpy as np
import pytest

import propmap as pm
from propmap.cli.main import main
from propmap.core.units import RPM
from propmap.identify import FitOptions, fit_loads, read_loads
from propmap.identify.data import DataError, sanity_check
from propmap.identify.load_data import LoadData


@pytest.fixture(scope="module")
def tunnel():
    """APC 10x7E with its calibrated set and flapping blades (3 rad/(N m)): 4000-8000 rpm, a
    static point and 5-15 m/s at 0-90 deg each, 0.7% noise of the static loads (the audit's)."""
    prop = pm.load_propeller("apce_10x7")
    true = pm.resolve_params("calibrated:apce_10x7").replace(flap_compliance=3.0)
    rng = np.random.default_rng(0)
    om, V, inc = [], [], []
    for rpm in (4000, 6000, 8000):
        for v, a in [(0.0, 0.0)] + [(v, a) for v in (5.0, 10.0, 15.0) for a in range(0, 91, 15)]:
            om.append(rpm * math.pi / 30), V.append(v), inc.append(math.radians(a))
    om, V, inc = map(np.array, (om, V, inc))
    r = pm.rotor_loads(prop, true, om, V, inc)
    st = pm.rotor_loads(prop, true, om, 0.0, 0.0)
    noise = lambda s: 0.007 * s * rng.standard_normal(om.size)  # noqa: E731
    measured = {"thrust": r.thrust + noise(st.thrust), "drag": r.drag + noise(st.thrust),
                "torque": r.torque + noise(st.torque)}
    return prop, LoadData(om, V, inc, measured, np.array(["tunnel"] * om.size), source="tunnel.csv")


def _subset(data, keep):
    return LoadData(data.omega[keep], data.airspeed[keep], data.incidence[keep],
                    {k: v[keep] for k, v in data.measured.items()}, data.group[keep], source=data.source)


def test_a_normal_force_at_axial_points_only_is_not_fitted(tunnel):
    prop, data = tunnel
    axial = _subset(data, data.incidence == 0.0)
    opts = FitOptions(multistart=0)
    with_drag = fit_loads(axial, prop, options=opts)
    without = fit_loads(axial, prop, quantities=("thrust", "torque"), options=opts)
    assert with_drag.extra["quantities"] == ["thrust", "torque"]
    assert any("drag is not fitted" in w for w in with_drag.warnings)
    np.testing.assert_allclose(with_drag.x, without.x, rtol=1e-6)  # (cl_alpha std error 1.29 before, 0.16 now)
    with pytest.raises(ValueError, match="drag\\) cannot be fitted: no point has an in-plane airspeed"):
        fit_loads(axial, prop, quantities=("drag",), options=opts)
    # at incidence the drag residuals are its in-plane points only, each named with its incidence
    res = fit_loads(data, prop, options=opts)
    labels = res.extra["residual_labels"]
    inplane = int(np.sum(data.airspeed * np.abs(np.sin(data.incidence)) > 0.3))
    assert sum(lab.startswith("drag") for lab in labels) == inplane == 54
    assert len(labels) == 2 * data.n + inplane
    assert any(lab.endswith("at 45 deg") for lab in labels)
    assert float(np.sqrt(np.mean(np.asarray(res.residuals)[:len(labels)] ** 2))) < 0.05


def test_a_normal_force_of_the_other_sign_is_refused(tunnel):
    prop, data = tunnel
    flipped = LoadData(data.omega, data.airspeed, data.incidence, {**data.measured, "drag": -data.measured["drag"]},
                       data.group, source="flip.csv")
    with pytest.raises(DataError, match=r"the measured drag has the other sign .* at 4\d of 4\d points"):
        sanity_check(flipped, prop)
    sanity_check(flipped, prop, quantities=("thrust", "torque"))  # (not fitted: not held to the model)


def test_the_data_warnings_reach_the_reports_and_incidence_fits_are_said(tunnel, tmp_path, capsys):
    prop, data = tunnel
    f = tmp_path / "rad.csv"
    keep = data.incidence <= math.radians(60)
    rows = np.column_stack([data.omega[keep] * 30 / math.pi, data.airspeed[keep], data.incidence[keep],
                            data.measured["thrust"][keep], data.measured["drag"][keep], data.measured["torque"][keep]])
    np.savetxt(f, rows, delimiter=",", header="rpm,airspeed,incidence_deg,thrust,drag,torque", comments="",
               fmt="%.10g")  # (the incidences in radians under a degrees header)
    assert main(["fit", "loads", str(f), "--prop", "apce_10x7", "--out", str(tmp_path / "p.toml")]) == 0
    err = capsys.readouterr().err
    assert err.index("radians?") < err.index("wrote ")  # said before the fit, not after its files
    assert "DATA WARNING: " in (tmp_path / "p.report.txt").read_text()
    import json

    assert any("radians?" in w for w in json.loads((tmp_path / "p.report.json").read_text())["data_warnings"])
    # a file fitted at incidence: its own fit speaks for it there
    from propmap.io.uncertainty import model_uncertainty

    good = tmp_path / "good.csv"
    rows[:, 2] = np.degrees(rows[:, 2])
    np.savetxt(good, rows, delimiter=",", header="rpm,airspeed,incidence_deg,thrust,drag,torque", comments="",
               fmt="%.10g")
    assert main(["fit", "loads", str(good), "--prop", "apce_10x7", "--out", str(tmp_path / "g.toml")]) == 0
    capsys.readouterr()
    assert model_uncertainty(str(tmp_path / "g.toml"))["off_axis"].startswith(
        "fitted to load data at incidence up to 60 deg")
    assert model_uncertainty("calibrated:apce_10x7")["off_axis"].startswith("not validated at incidence")


def test_a_negative_incidence_says_what_to_do(tmp_path, capsys):
    f = tmp_path / "neg.csv"
    f.write_text("rpm,airspeed,incidence_deg,thrust,drag,torque\n6000,0,0,3.0,0,0.05\n6000,5,-30,3.1,0.1,0.05\n")
    assert main(["fit", "loads", str(f), "--prop", "apce_10x7", "--out", str(tmp_path / "n.toml")]) == 2
    err = capsys.readouterr().err
    assert "got -30; the incidence is the angle between the airspeed and the rotor axis" in err
    assert "negate it on those rows" in err


def test_a_joint_fit_reports_each_propellers_residuals_over_its_own_rows(tunnel):
    """fit_loads_joint sliced n x quantities residuals per propeller: with the in-plane force at its
    in-plane points only, a dataset after one with drag was scored on the other's residuals (a
    review)."""
    from propmap.identify import fit_loads_joint

    prop, data = tunnel
    a = _subset(data, data.omega < 5000 * math.pi / 30)  # 4000 rpm: 22 points, 18 with an in-plane airspeed
    b = LoadData(a.omega, a.airspeed, a.incidence, {k: a.measured[k] for k in ("thrust", "torque")}, a.group)
    res = fit_loads_joint([(a, prop), (b, prop)], options=FitOptions(multistart=0))
    assert np.asarray(res.residuals).size >= 22 * 2 + 18 + 22 * 2
    per = res.extra["per_propeller"]
    r = np.asarray(res.residuals)
    mb = 22 * 2
    # the second dataset's rms from the last of its own rows (the data residuals come first)
    k0 = 22 * 2 + 18
    # (the weight sqrt(w N / (W n)): 1 for two data sets of one size, since stop 100; 1/sqrt(n) before)
    rms_b = float(np.sqrt(np.mean((r[k0:k0 + mb] / math.sqrt((a.n + b.n) / (2 * b.n))) ** 2)))
    assert per[1]["rms_residual"] == pytest.approx(rms_b, rel=1e-12)


def test_a_fitted_file_says_which_propeller_and_warns_on_another(tmp_path, capsys):
    """A fitted file recorded no propeller, and ran another one without a word (a user-level
    audit: an 8x6E, a 10x7E and a 12 in three-blade propeller with a 9 in fit)."""
    from propmap.io.params_file import read_coverage

    prop = pm.load_propeller("apce_10x7")
    p = pm.default_params("apce_10x7")
    rows = ["rpm,airspeed,thrust,torque"]
    for rpm in (3000, 4000, 5000, 6000):
        for V in (0.0, 3.0, 6.0, 9.0):
            r = pm.rotor_loads(prop, p, rpm * math.pi / 30, V, 0.0)
            rows.append(f"{rpm},{V},{float(r.thrust)!r},{float(r.torque)!r}")
    (tmp_path / "st.csv").write_text("\n".join(rows) + "\n")
    fit = tmp_path / "f.toml"
    assert main(["fit", "loads", str(tmp_path / "st.csv"), "--prop", "apce_10x7", "--out", str(fit)]) == 0
    cov = read_coverage(fit)
    assert (cov["propeller"], cov["diameter_m"], cov["n_blades"]) == ("apce_10x7", pytest.approx(0.254), 2)
    assert type(cov["n_blades"]) is int and "\nn_blades = 2\n" in fit.read_text()  # (a count: 2.0 was written)
    assert cov["re75_max"] / cov["re75_min"] == pytest.approx(2.0)  # (3000-6000 rpm)
    capsys.readouterr()
    assert main(["loads", "apce_8x6", "--params", str(fit), "--rpm", "5000"]) == 0
    assert "runs with f.toml, fitted to data of apce_10x7 (0.254 m, 2 blades)" in capsys.readouterr().err
    assert main(["loads", "apce_10x7", "--params", str(fit), "--rpm", "5000"]) == 0
    assert "fitted to data of" not in capsys.readouterr().err
    # a pitch sibling of the same size (a new-family audit: unsaid, where calibrated:apce_10x7 was warned of)
    assert main(["loads", "apce_10x5", "--params", str(fit), "--rpm", "5000"]) == 0
    assert ("apce_10x5 runs with f.toml, fitted to data of apce_10x7 (the same diameter and blade count): if that "
            "is another propeller (a pitch sibling)") in capsys.readouterr().err
    # a propeller of the same size and pitch under another name (APC's PE0 file of a 10x7) is no sibling (a review)
    from importlib import resources

    pe0 = resources.files("propmap") / "data" / "apc_pe0" / "10x7-PERF.PE0"
    assert main(["loads", str(pe0), "--params", str(fit), "--rpm", "5000"]) == 0
    assert "pitch sibling" not in capsys.readouterr().err


def test_reynolds_numbers_beyond_the_datas_are_said_in_other_air(capsys):
    """Only the rpm span was checked: a set used at 10,000 m ran at a third of its data's Reynolds
    number without a word (a user-level audit). The chord Reynolds number at 0.75 R is checked
    against the data's: a calibrated set's rpm span on its own propeller in its own air."""
    prop = pm.load_propeller("apce_10x7")
    air = pm.default_params("apce_10x7").air
    # (regression value: the data's low end, 1975 rpm)
    assert float(prop.reynolds_75(1975.0 * math.pi / 30, air)) == pytest.approx(19937, rel=1e-3)
    assert main(["loads", "apce_10x7", "--rpm", "2600", "--altitude-m", "10000"]) == 0
    err = capsys.readouterr().err
    assert "Reynolds number at 0.75 R 1.2e+04 in this air and on apce_10x7: the data behind calibrated:apce_10x7 " \
           "span 1.99e+04-6.6e+04" in err
    assert main(["loads", "apce_10x7", "--rpm", "2600"]) == 0  # (sea level: within the data's)
    assert "Reynolds number" not in capsys.readouterr().err


@pytest.mark.parametrize("header, match", [
    ("rpm,J,thrust,torque", r"column 'J' looks like an advance ratio, which propmap reads only as 'airspeed' "
                            r"\[m/s\] \(V = J n D"),
    ("rpm,mu,incidence_deg,thrust,drag,torque", r"lacks column airspeed \(is 'mu' an advance ratio\? give the "
                                                r"airspeed, V = J n D"),
    ("rpm,Vz,thrust,torque", r"column 'Vz' looks like a climb or descent rate, which propmap reads only as "
                             r"'airspeed' \(its magnitude, in its unit: 'airspeed \(mph\)' is read as such\) with "
                             r"'incidence_deg' 0 \(climb\) or 180"),
    ("rpm,airspeed,descent_rate,thrust,torque", r"columns 'descent_rate' \(a descent rate\) and 'airspeed' both give "
                                                r"the flow"),
    ("rpm,V_c,thrust,torque", r"column 'V_c' looks like a climb or descent rate"),
    ("rpm,airspeed,flow angle,thrust,torque", r"column 'flow angle' looks like a flow angle"),
    ("rpm,airspeed,alpha_p,thrust,torque", r"column 'alpha_p' looks like a flow angle"),
    ("rpm,airspeed,tilt angle,thrust,torque", r"column 'tilt angle' looks like a flow angle"),
    ("propeller,rpm,thrust,torque", r"column 'propeller' names 2 propellers \(apce_10x7, apce_8x6\): propmap fits "
                                    r"one propeller's loads"),
    ("Propeller (name),rpm,thrust,torque", r"column 'Propeller \(name\)' names 2 propellers"),
])
def test_a_tunnel_files_unread_advance_ratio_rate_angle_or_propellers_are_refused(tmp_path, header, match):
    """Each was read with at most a note and fitted with exit 0 (a wind-tunnel data audit,
    2026-11-27): an axial sweep's J as static (thrust 11-23% off), a descent rate as static or a
    climb, an angle without a unit as axial flow, two propellers' rows as one propeller (the
    audit's figures)."""
    names = header.split(",")
    rows = []
    for k in range(8):
        cells = {"rpm": f"{4000 + 500 * k}", "thrust": f"{1.0 + 0.1 * k}", "torque": f"{0.02 + 0.001 * k}",
                 "drag": "0.01", "incidence_deg": "45", "airspeed": "5", "propeller": ("apce_8x6", "apce_10x7")[k % 2]}
        cells["Propeller (name)"] = cells["propeller"]
        rows.append(",".join(cells.get(n, f"{0.1 * k:.2f}") for n in names))
    path = tmp_path / "t.csv"
    path.write_text("\n".join([header, *rows]) + "\n")
    with pytest.raises(DataError, match=match):
        read_loads(path)


def test_a_propeller_size_column_is_not_a_propeller_name(tmp_path):
    """'Prop (in)' holds a size: read as a name column, two sizes were refused as two propellers
    (a review of 'Propeller (name)' matching)."""
    path = tmp_path / "sizes.csv"
    path.write_text("rpm,Prop (in),thrust,torque\n" + "".join(f"{4000 + 500 * k},{(8, 10)[k % 2]},{1 + 0.1 * k},"
                                                               f"{0.02 + 0.001 * k}\n" for k in range(8)))
    data = read_loads(path)
    assert data.omega.size == 8


def test_a_negative_airspeed_or_an_rpm_column_in_rad_s_says_what_it_is(tmp_path, tunnel):
    """A descent as a negative airspeed was refused with the range only; an rpm column holding
    rad/s was blamed on an airspeed in km/h (a wind-tunnel data audit, 2026-11-27)."""
    path = tmp_path / "neg.csv"
    path.write_text("rpm,airspeed,thrust,torque\n" + "".join(f"{5000 + 100 * k},{-k},1.0,0.02\n" for k in range(8)))
    with pytest.raises(DataError, match=r"airspeed must be in \[0, 500\] m/s, got -1; a descent given as a negative "
                                        r"airspeed\? give its magnitude with incidence_deg 180"):
        read_loads(path)
    # a negative incidence: its magnitude, or 90 + a disk angle of attack (not "its magnitude" alone)
    path.write_text("rpm,airspeed,incidence_deg,thrust,torque\n" + "".join(f"{5000 + 100 * k},5,{-5 * k},1.0,0.02\n"
                                                                        for k in range(8)))
    with pytest.raises(DataError, match=r"line 3: incidence_deg must be in \[0, 180\] deg, got -5; .* give its "
                                        r"magnitude.*a disk angle of attack alpha_d \(0 edgewise, positive with the "
                                        r"disk tilted back against the airspeed\) is incidence_deg = 90 \+ alpha_d"):
        read_loads(path)
    prop, data = tunnel
    as_rpm = LoadData(data.omega * RPM, data.airspeed, data.incidence, data.measured, data.group, source="rads.csv")
    with pytest.raises(DataError, match=r"likely a rotation rate in rad/s read as rpm \(an rpm column holding rad/s"):
        sanity_check(as_rpm, prop)


@pytest.mark.parametrize("header, values, noted", [
    ("rpm,J,thrust,torque", {"J": "0"}, "column 'J' is not read; if it is an advance ratio"),
    ("rpm,rho,mu,thrust,torque", {"rho": "1.2", "mu": "1.8e-5"}, "column 'mu' is not read"),
    ("rpm,tilt angle,thrust,torque", {"tilt angle": "5"}, "column 'tilt angle' is not read; if it is a flow angle"),
    ("rpm,airspeed,incidence_deg,Vz,thrust,drag,torque", {"airspeed": "5", "incidence_deg": "60", "Vz": "2.5"},
     "column 'Vz' (a climb or descent rate) is not read: the airspeed and the incidence give the flow"),
])
def test_harmless_columns_beside_a_static_or_complete_file_are_noted(tmp_path, header, values, noted):
    """A review (2026-11-27) of the refusals above: a static file's J of 0, a viscosity mu, a
    stand's tilt angle in still air, or a climb rate beside the airspeed and incidence that
    give it, are read with a note, as before."""
    names = header.split(",")
    rows = []
    for k in range(8):
        cells = {"rpm": f"{4000 + 500 * k}", "thrust": f"{1.0 + 0.1 * k}", "torque": f"{0.02 + 0.001 * k}",
                 "drag": "0.01", **values}
        rows.append(",".join(cells[n] for n in names))
    path = tmp_path / "h.csv"
    path.write_text("\n".join([header, *rows]) + "\n")
    data = read_loads(path)
    assert data.n == 8 and any(noted in n for n in data.notes), data.notes
