"""The command line, called through main([...]); every bad input exits 2 with one line."""

import csv
import json
import math
import re

import pytest
from cli_helpers import run

import propmap as pm
from propmap.cli.main import main


def test_props_json(capsys):
    code, out, _ = run(capsys, "props", "--json")
    rows = json.loads(out)
    assert code == 0 and len(rows) == 147
    row = next(r for r in rows if r["name"] == "apce_8x6")
    assert row["diameter_in"] == 8 and row["pitch_in"] == 6 and row["sweeps"] == 7 and row["geometry"] == "APC PE0"


def test_props_table(capsys):
    code, out, _ = run(capsys, "props")
    assert code == 0 and "apce_8x6" in out and "147 propellers" in out


def test_loads_single_point_json_matches_api(capsys):
    code, out, _ = run(capsys, "loads", "apce_8x6", "--rpm", "8000", "--airspeed", "10", "--incidence-deg", "60",
                       "--json")
    d = json.loads(out)
    assert code == 0
    assert set(d) >= {"thrust", "drag", "torque", "power", "CT", "CP", "converged", "flags", "params"}
    # the default for a calibrated catalogue propeller is its own calibrated set, and it says so
    assert d["params"] == "calibrated:apce_8x6"
    params = pm.resolve_params("calibrated:apce_8x6")
    r = pm.rotor_loads(pm.load_propeller("apce_8x6"), params, 8000 * math.pi / 30, 10.0, math.radians(60))
    assert d["thrust"] == pytest.approx(float(r.thrust), rel=1e-12)
    assert d["drag"] == pytest.approx(float(r.drag), rel=1e-12)
    assert d["converged"] is True and d["flags"] == []


def test_loads_writes_the_torque_coefficient(capsys, tmp_path):
    """CQ beside CT and CP in every loads output (JSON, text, points file): the propeller convention's
    CQ = Q / (rho n^2 D^5), so CP = 2 pi CQ at every point (the torque of the API at the same point)."""
    code, out, _ = run(capsys, "loads", "apce_8x6", "--rpm", "8000", "--airspeed", "10", "--incidence-deg", "60",
                       "--json")
    d = json.loads(out)
    assert code == 0
    r = pm.rotor_loads(pm.load_propeller("apce_8x6"), pm.resolve_params("calibrated:apce_8x6"), 8000 * math.pi / 30,
                       10.0, math.radians(60))
    n, D = 8000 / 60, pm.load_propeller("apce_8x6").diameter
    assert d["CQ"] == pytest.approx(float(r.torque) / (d["air"]["rho"] * n**2 * D**5), rel=1e-12)
    assert d["CP"] == pytest.approx(2 * math.pi * d["CQ"], rel=1e-12)
    code, out, _ = run(capsys, "loads", "apce_8x6", "--rpm", "8000")
    assert code == 0 and re.search(r"CT = 0\.\d{4}  CQ = 0\.\d{5}  CP = 0\.\d{4}", out), out
    src, dst = tmp_path / "in.csv", tmp_path / "out.csv"
    src.write_text("rpm,airspeed,incidence_deg\n8000,0,0\n6000,12,90\n")
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", str(src), "--out", str(dst))
    assert code == 0, err
    rows = list(csv.DictReader(dst.open()))
    assert [c for c in rows[0] if c.startswith("C")] == ["CT", "CQ", "CP"]
    for row in rows:
        assert float(row["CP"]) == pytest.approx(2 * math.pi * float(row["CQ"]), rel=1e-9)


def test_loads_with_params_file_and_geometry_file(capsys, tmp_path, shared_data):
    f = tmp_path / "p.toml"
    pm.write_params(f, pm.preset("gill2017-stiff"))
    geom = str(shared_data / "uiuc_propdb/v1/apce_9x6_geom.txt")
    code, out, _ = run(capsys, "loads", geom, "--rpm", "6000", "--params", str(f), "--json", "--blades", "2")
    assert code == 0 and json.loads(out)["thrust"] > 0 and json.loads(out)["n_blades"] == 2
    # a UIUC geometry file does not state its blade count: it must be given
    code, _, err = run(capsys, "loads", geom, "--rpm", "6000", "--params", str(f))
    assert code == 2 and "does not state the blade count: give it (--blades" in err


def test_loads_points_csv(capsys, tmp_path):
    src = tmp_path / "in.csv"
    src.write_text("rpm,airspeed,incidence_deg\n8000,0,0\n8000,10,90\n6000,5,180\n")
    dst = tmp_path / "out.csv"
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", str(src), "--out", str(dst))
    assert code == 0, err
    rows = list(csv.DictReader(dst.open()))
    assert len(rows) == 3
    assert list(rows[0])[:3] == ["rpm", "airspeed", "incidence_deg"]
    assert float(rows[0]["drag"]) == 0.0 and float(rows[1]["drag"]) > 0
    assert rows[1]["converged"] == "true"
    assert "vortex_ring" in rows[2]["flags"].split(";")  # axial descent at 5 m/s, 6000 rpm: k = 0.92
    flagged = {f: sum(f in r["flags"].split(";") for r in rows) for f in ("vortex_ring", "reverse_flow")}
    assert flagged["vortex_ring"] == 1
    assert (f"wrote 3 points to {dst} (params calibrated:apce_8x6; air rho 1.225 kg/m^3, mu 1.983e-05 Pa s, speed of "
            "sound 340.3 m/s); flagged: 1 vortex_ring"
            + (f", {flagged['reverse_flow']} reverse_flow" if flagged["reverse_flow"] else "")
            + " (column flags, docs/cli.md)") in err, err


def test_loads_points_with_semicolons_and_decimal_commas(capsys, tmp_path):
    """A points file saved by a spreadsheet in a decimal-comma locale gives the loads of the
    same points written with decimal points, and the same output file: its operating columns
    echoed with decimal points (since 2026-11-30: '5,5' was echoed as quoted text beside the
    loads' numbers in the comma-separated output)."""
    loads, rows = {}, {}
    for name, text in (("en", "rpm,airspeed,incidence_deg\n8000,5.5,10\n6000,0,0.5\n"),
                       ("de", "rpm;airspeed;incidence_deg\r\n8000;5,5;10\r\n6000;0;0,5\r\n")):
        src, dst = tmp_path / f"{name}.csv", tmp_path / f"{name}_out.csv"
        src.write_text(text, newline="")
        code, _, err = run(capsys, "loads", "apce_8x6", "--points", str(src), "--out", str(dst))
        assert code == 0, err
        loads[name] = [(float(r["thrust"]), float(r["drag"])) for r in csv.DictReader(dst.open())]
        rows[name] = dst.read_text().splitlines()
    assert loads["de"] == loads["en"] and loads["en"][0][1] > 0
    assert rows["de"] == rows["en"] and rows["de"][1].startswith("8000,5.5,10,")


def test_validate_json_and_figure(capsys, tmp_path):
    fig = tmp_path / "v.png"
    code, out, _ = run(capsys, "validate", "apce_8x6", "--json", "--figure", str(fig))
    d = json.loads(out)
    assert code == 0 and fig.stat().st_size > 10_000
    assert {"ct_rmse", "cp_rmse"} <= set(d["model"]) and {"ct_rmse", "cp_rmse"} <= set(d["hover_model"])
    assert len(d["sweeps"]) == 8


@pytest.mark.parametrize(
    "argv, match",
    [
        (["loads", "apce_8x6", "--rpm", "-100"], "rpm"),
        (["loads", "apce_8x6", "--rpm", "nan"], "rpm"),
        (["loads", "apce_8x6", "--rpm", "8000", "--airspeed", "-1"], "airspeed"),
        (["loads", "apce_8x6", "--rpm", "8000", "--airspeed", "inf"], "airspeed"),
        (["loads", "apce_8x6", "--rpm", "8000", "--incidence-deg", "190"], "--incidence-deg"),
        (["loads", "apce_8x6", "--rpm", "8000", "--incidence-deg", "-5"], "--incidence-deg"),
        (["loads", "nosuchprop", "--rpm", "8000"], "unknown propeller"),
        (["loads", "no/such/geom.txt", "--rpm", "8000"], "no file 'no/such/geom.txt'"),
        (["loads", "missing_9x6_geom.txt", "--rpm", "8000"], "no file 'missing_9x6_geom.txt'"),
        (["loads", "/", "--rpm", "8000"], "'/' is a folder"),
        (["loads", "", "--rpm", "8000"], "the propeller is empty"),
        (["loads", "apce_8x6.txt", "--rpm", "8000"], "did you mean the catalogue's apce_8x6"),
        # (a bare size, 8x6, is a nominal blade since 2026-12-02, naming the catalogue's propellers of that size:
        # tests/test_nominal_geometry.py)
        (["loads", "apce_8x6", "--rpm", "8000", "--params", "nope"], "--params"),
        (["loads", "apce_8x6"], "--rpm"),
        (["loads", "apce_8x6", "--rpm", "abc"], "abc"),
        (["validate", "nosuchprop"], "unknown propeller"),
        (["frobnicate"], "frobnicate"),
    ],
)
def test_bad_input_exits_2_with_one_line(capsys, argv, match):
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert match in err and err.count("\n") == 1 and "Traceback" not in err


@pytest.mark.parametrize(
    "text, match",
    [
        ("r/R c/R\n0.2 0.1\n0.5 0.1\n", "expected columns"),
        ("r/R c/R beta\n0.5 0.1 30\n0.2 0.1 20\n", "strictly increasing"),
    ],
)
def test_bad_geometry_file_exits_2(capsys, tmp_path, text, match):
    f = tmp_path / "bad_9x6_geom.txt"
    f.write_text(text)
    code, _, err = run(capsys, "loads", str(f), "--rpm", "8000")
    assert code == 2 and match in err and err.count("\n") == 1


def test_points_csv_writes_no_negative_zero(capsys, tmp_path):
    """A hover point's descent ratio is 0, written "0" (it was "-0": -V cos(incidence) / v_h)."""
    src = tmp_path / "p.csv"
    src.write_text("rpm,airspeed,incidence_deg\n6000,0,0\n")
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", str(src), "--out", str(tmp_path / "o.csv"))
    assert code == 0, err
    row = list(csv.DictReader((tmp_path / "o.csv").open()))[0]
    assert row["lambda2"] == "0" and row["drag"] == "0" and not any(v == "-0" for v in row.values())


@pytest.mark.parametrize("args, match", [
    (("--airspeed", "-5"), "got -5.0 (the airspeed is a magnitude: a flow up through the disk, descent, is incidence "
                           "180 deg"),
    (("--airspeed", "600"), "--airspeed must be finite and in [0, 500] m/s, got 600.0\n"),
])
def test_a_negative_airspeed_points_to_the_descent_incidence(capsys, args, match):
    code, _, err = run(capsys, "loads", "apce_8x6", "--rpm", "5000", *args)
    assert code == 2 and match in err and err.count("\n") == 1


@pytest.mark.parametrize(
    "text, match",
    [
        ("rpm,airspeed\n8000,0\n", "incidence_deg"),
        # a static stand's measurements: told how to give the points, and where measured loads are compared (a
        # user-level audit, 2026-11-28)
        ("rpm,thrust_N,torque_Nm\n2534,0.40343,0.008975\n", "lacks column(s) airspeed, incidence_deg (needs rpm, "
         "airspeed, incidence_deg, any case, with or without a unit: RPM, airspeed (m/s), airspeed_kmh, incidence "
         "(deg)); a static stand's points have airspeed 0 and incidence_deg 0: add those columns, or compare measured "
         "loads with the model by 'propmap validate FILE --prop P --params SET'"),
        ("rpm,airspeed,incidence_deg\n8000,0,0\n8000,x,0\n", "line 3"),
        ("rpm,airspeed,incidence_deg\n8000,0,0\n8000,1\n", "line 3"),
        ("rpm,airspeed,incidence_deg\n8000,0,0\n-8000,1,0\n", "line 3: rpm"),
        ("rpm,airspeed,incidence_deg\n8000,0,200\n", "line 2: incidence_deg"),
        ("rpm,airspeed,incidence_deg\n", "no data rows"),
        # beside decimal commas a point is a thousands separator: refused, not read as 7 rpm
        ("rpm;airspeed;incidence_deg\n6000;5,5;10\n7.000;0;0\n", "(line 3, column rpm)"),
    ],
)
def test_malformed_points_csv_names_the_line_and_writes_nothing(capsys, tmp_path, text, match):
    src = tmp_path / "in.csv"
    src.write_text(text)
    dst = tmp_path / "out.csv"
    code, _, err = run(capsys, "loads", "apce_8x6", "--points", str(src), "--out", str(dst))
    assert code == 2 and match in err and err.count("\n") == 1
    assert not dst.exists() and list(tmp_path.iterdir()) == [src]


def test_hover_incidence_edgewise_lambda2_and_a_file_named_like_a_catalogue_propeller(tmp_path, capsys, monkeypatch):
    """In still air the incidence means nothing: no 'fitted to axial data only' warning at V = 0;
    lambda2 edgewise is 0, not cos(90 deg)'s -5.2e-17; a file in the working folder named like a
    catalogue propeller is said to be passed over."""
    assert main(["loads", "apce_8x6", "--rpm", "6000", "--incidence-deg", "60"]) == 0
    assert "axial data only" not in capsys.readouterr().err
    assert main(["loads", "apce_8x6", "--rpm", "6000", "--airspeed", "5", "--incidence-deg", "90", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["lambda2"] == 0.0
    monkeypatch.chdir(tmp_path)
    (tmp_path / "apce_8x6").write_text("r/R c/R beta\n0.2 0.1 30\n1.0 0.05 10\n")
    assert main(["loads", "apce_8x6", "--rpm", "6000"]) == 0
    assert "'apce_8x6' is a catalogue propeller and a file here: the catalogue's is used" in capsys.readouterr().err


def test_loads_and_trim_give_the_side_force_and_pitching_moment_where_the_set_makes_them(tmp_path, capsys):
    """A set with flapping blades and the Drees inflow has a side force Y and a pitching moment
    M_P edgewise (Y -0.050 N against D 0.18 N at 5000 rpm, 5 m/s, 90 deg): `loads` (text, JSON,
    --points) and `trim` gave neither, without a word, where a map and rotor_loads have them (a
    user-level audit, 2026-11-27); a set without them writes the columns as before."""
    params = pm.default_params("apce_8x6").replace(inflow="drees", flap_compliance=2.0)
    f = tmp_path / "drees.toml"
    pm.write_params(f, params)
    r = pm.rotor_loads(pm.load_propeller("apce_8x6"), params, 5000 * math.pi / 30, 5.0, math.pi / 2)
    assert float(r.side_force) < -0.03 and float(r.pitching_moment) > 0.005  # (not zero: the test can fail)
    code, out, _ = run(capsys, "loads", "apce_8x6", "--params", str(f), "--rpm", "5000", "--airspeed", "5",
                       "--incidence-deg", "90", "--json")
    rep = json.loads(out)
    assert code == 0 and rep["side_force"] == pytest.approx(float(r.side_force), rel=1e-9)
    assert rep["pitching_moment"] == pytest.approx(float(r.pitching_moment), rel=1e-9)
    assert rep["units"]["side_force"] == "N" and rep["units"]["pitching_moment"] == "N m"
    code, out, _ = run(capsys, "loads", "apce_8x6", "--params", str(f), "--rpm", "5000", "--airspeed", "5",
                       "--incidence-deg", "90")
    assert code == 0 and "side force Y = -0.0" in out and "(blade flapping, a linear inflow)" in out
    pts = tmp_path / "p.csv"
    pts.write_text("rpm,airspeed,incidence_deg,converged\n5000,5,90,x\n5000,0,0,y\n")
    code, out, err = run(capsys, "loads", "apce_8x6", "--params", str(f), "--points", str(pts), "--out", "-")
    rows = list(csv.DictReader(out.splitlines()))
    header = out.splitlines()[0].split(",")
    assert header[7:10] == ["rolling_moment", "side_force", "pitching_moment"]
    assert float(rows[0]["side_force"]) == pytest.approx(float(r.side_force), rel=1e-8)
    assert float(rows[1]["side_force"]) == 0.0 and float(rows[1]["pitching_moment"]) == 0.0  # (hover: none)
    assert "did not converge" not in err  # (the converged count found its column beside the input's 'converged')
    code, out, _ = run(capsys, "loads", "apce_8x6", "--points", str(pts), "--out", "-")
    assert "side_force" not in out.splitlines()[0]  # the default set makes none: the columns as before
    code, out, _ = run(capsys, "trim", "apce_8x6", "--params", str(f), "--rpm", "5000", "--airspeed", "5",
                       "--incidence-deg", "90", "--thrust", "1.5", "--json")
    rep = json.loads(out)
    assert code == 0 and rep["thrust"] == pytest.approx(1.5, rel=1e-6)
    assert rep["side_force"] < -0.02 and rep["pitching_moment"] > 0.005 and rep["rolling_moment"] > 0.005


def test_docs_cli_lists_every_command_and_its_options():
    """docs/cli.md's "Commands and their options" names every command and exactly the options
    it takes (export-sim --target, fit --M, --multistart, map --c-type and a dozen more were
    in no option list of docs/cli.md: a docs audit, 2026-11-27)."""
    import re
    from pathlib import Path

    import click

    from propmap.cli.main import cli

    text = (Path(__file__).resolve().parents[1] / "docs" / "cli.md").read_text()
    section = text.split("## Commands and their options", 1)[1].split("\n## ", 1)[0]
    listed = {}
    for item in re.split(r"\n\* ", "\n" + section)[1:]:
        name = re.match(r"`propmap ([a-z -]+?)(?: [A-Z\[].*?)?`", item).group(1).strip()
        listed[name] = set(re.findall(r"`(--[a-z0-9-]+|--M)`", item.split("Options:", 1)[1]))

    def commands(cmd, prefix=()):
        if isinstance(cmd, click.Group):
            for n, c in cmd.commands.items():
                yield from commands(c, (*prefix, n))
        else:
            yield " ".join(prefix), {max(p.opts, key=len) for p in cmd.params
                                     if isinstance(p, click.Option) and not p.hidden}

    actual = dict(commands(cli))
    assert set(listed) == set(actual)
    for name, opts in actual.items():
        assert listed[name] == opts, (name, opts ^ listed[name])
