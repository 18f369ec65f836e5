"""Stop 102: defects found by audits of the figures (plots.py and the commands that draw) and of the
files propmap writes and reads back (parameter files, maps), each test failing on the code before
its fix."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM
import propmap.plots_flight as plots_flight


def _map_ds(V, inc=(0.0, 90.0)):
    """A hand-made one-rpm map dataset: thrust falling with airspeed (rpm, airspeed, incidence)."""
    import xarray as xr

    V, inc = np.asarray(V, float), np.asarray(inc, float)
    thrust = 4.0 - 0.2 * V[None, :, None] * (1 + 0 * inc[None, None, :])
    dims = ("rpm", "airspeed", "incidence_deg")
    flags = np.zeros_like(thrust, bool)
    return xr.Dataset({"thrust": (dims, thrust), "drag": (dims, thrust / 10), "torque": (dims, thrust / 100),
                       "vortex_ring": (dims, flags), "multiple_roots": (dims, flags), "converged": (dims, ~flags)},
                      coords={"rpm": [6000.0], "airspeed": V, "incidence_deg": inc})


@pytest.fixture
def drawn(monkeypatch):
    """The figures the plot functions would save (plots._save replaced: nothing written)."""
    import propmap.plots as plots

    figs = []
    monkeypatch.setattr(plots, "_save", lambda fig, path: figs.append(fig) or Path(path))
    return plots, figs


# --- figures ----------------------------------------------------------------------------------------------------

def test_a_figure_neither_switches_the_sessions_backend_nor_stays_open(tmp_path):
    """plots switched the caller's backend to Agg (matplotlib.use) and kept each figure in pyplot's registry,
    which a failed save never closed (a loop of failing calls leaked them)."""
    import matplotlib
    import pandas as pd
    from matplotlib import _pylab_helpers

    from propmap.plots import plot_envelope

    table = pd.DataFrame({"airspeed": [0.0, 5.0], "incidence_deg": [0.0, 0.0], "thrust": [2.0, 1.8],
                          "drag": [0.0, 0.1], "thrust_hover": [2.0, 2.0]})
    before = matplotlib.get_backend()
    try:
        matplotlib.use("svg")
        open_before = len(_pylab_helpers.Gcf.figs)
        for _ in range(3):
            with pytest.raises(OSError):
                plot_envelope(table, "/proc/propmap-no-such-folder/e.png")
        assert plot_envelope(table, tmp_path / "e.png").read_bytes()[:4] == b"\x89PNG"
        assert matplotlib.get_backend() == "svg"
        assert len(_pylab_helpers.Gcf.figs) == open_before
    finally:
        matplotlib.use(before)


def test_an_unknown_mplbackend_is_named_before_the_map_is_built(tmp_path):
    """MPLBACKEND=bogus: the map and its sidecar were written, then the run failed at its figure with
    matplotlib's "Key backend: 'bogus' ..."; now it stops before any work, naming the variable."""
    env = dict(os.environ, MPLBACKEND="bogus")
    out = tmp_path / "m.nc"
    r = subprocess.run([sys.executable, "-m", "propmap", "map", "apce_8x6", "--out", str(out), "--rpm", "4000:8000:3",
                        "--airspeed", "0:15:4", "--incidence-deg", "0:180:7", "--check-points", "0", "--plot",
                        str(tmp_path / "pl")], env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == 2
    assert "MPLBACKEND='bogus'" in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert not out.exists() and not list(tmp_path.iterdir())


def test_require_matplotlib_names_mplbackend():
    code = ("import propmap.plots as p\ntry:\n    p.require_matplotlib()\nexcept ValueError as e:\n    print(e)\n")
    r = subprocess.run([sys.executable, "-c", code], env=dict(os.environ, MPLBACKEND="bogus"), capture_output=True,
                       text=True, timeout=120)
    assert "MPLBACKEND='bogus' is not a matplotlib backend" in r.stdout


def test_the_hover_panel_needs_a_static_node(drawn, tmp_path):
    """An airspeed axis from 5 m/s drew the hover model's error against the thrust at 5 m/s (0 there, no word)."""
    plots, figs = drawn
    plots.plot_map_contours(_map_ds([5.0, 10.0, 15.0]), 6000.0, tmp_path / "a.png", title="m")
    labels = [ax.get_ylabel() for ax in figs[0].axes]
    assert "hover model error T_hover - T [N]" not in labels
    assert "no hover-model panel: the airspeed axis starts at 5 m/s" in figs[0]._suptitle.get_text()
    assert "not converged" in figs[0]._suptitle.get_text()
    plots.plot_map_contours(_map_ds([0.0, 5.0, 10.0]), 6000.0, tmp_path / "b.png", title="m")
    hover = figs[1].axes[3]
    assert figs[1].axes[-1].get_ylabel() == "hover model error T_hover - T [N]"
    assert hover.collections[0].levels.max() >= 2.0  # 4.0 at 0 m/s less 2.0 at 10 m/s


def test_a_contour_needs_two_nodes_on_each_axis(drawn, tmp_path):
    plots, _ = drawn
    with pytest.raises(ValueError, match="at least two airspeed and two incidence nodes"):
        plots.plot_map_contours(_map_ds([0.0, 5.0], inc=[90.0]), 6000.0, tmp_path / "a.png")


def test_map_plot_warns_of_an_axis_without_the_static_node(tmp_path, capsys):
    from propmap.cli.map import _plot_files

    rpm, V, inc = np.array([4000.0, 6000.0]), np.array([5.0, 10.0]), np.array([0.0, 90.0])
    files = _plot_files(tmp_path / "pl", (rpm, V, inc), None, [])
    assert [n for n, _ in files] == [6000.0]
    assert "starts at 5 m/s, without the static node" in capsys.readouterr().err
    from propmap.cli._common import InputError

    with pytest.raises(InputError, match="at least two nodes"):
        _plot_files(tmp_path / "pl", (rpm, V, inc[:1]), None, [])


def test_cv_summary_leaves_out_a_propeller_not_scored(drawn, tmp_path):
    """A row with None (``_summaries``' "a propeller not scored") raised TypeError."""
    plots, figs = drawn
    rows = [{"blind": {"rms_ct": 0.02, "rms_cp": 0.04}}, {"blind": {"rms_ct": None, "rms_cp": None}},
            {"blind": {"rms_ct": 0.05, "rms_cp": 0.06}}]
    plots.plot_cv_summary({"summary": {"blind": {}}, "propellers": rows}, tmp_path / "c.png")
    x = np.asarray(figs[0].axes[0].get_lines()[0].get_xdata(), float)
    assert sorted(set(x)) == pytest.approx([2.0, 5.0])


def test_envelope_and_speed_figures_refuse_nothing_to_draw(drawn, tmp_path):
    """An empty table raised IndexError, an all-NaN one wrote empty panels; NaN speeds raised
    "arange: cannot compute length"."""
    import pandas as pd

    plots, _ = drawn
    cols = ("airspeed", "incidence_deg", "thrust", "drag", "thrust_hover")
    with pytest.raises(ValueError, match="no finite thrust among its 0 rows"):
        plots.plot_envelope(pd.DataFrame({c: [] for c in cols}), tmp_path / "e.png")
    with pytest.raises(ValueError, match="no finite thrust among its 2 rows"):
        plots.plot_envelope(pd.DataFrame({c: [np.nan, np.nan] for c in cols}), tmp_path / "e.png")
    with pytest.raises(ValueError, match="no column drag"):
        plots.plot_envelope(pd.DataFrame({c: [1.0] for c in cols if c != "drag"}), tmp_path / "e.png")
    loads = {k: np.ones(3) for k in ("thrust", "drag", "torque")}
    with pytest.raises(ValueError, match="1 of them not finite"):
        plots_flight.plot_flight_speed([1.0, np.nan, 2.0], loads, loads, {"m": np.zeros(3)}, tmp_path / "s.png")


def test_the_speed_figures_hover_thrust_is_along_each_rotor_axis(apc8x6, apc_params):
    """The collective-thrust panel drew the hover model's thrust projected on body z beside the fitted
    model's thrust along each rotor's axis: a tilted rotor's hover thrust fell by cos(tilt)."""
    from propmap.cli.flight import _hover_loads
    from propmap.core.air import Air

    tilt = np.radians(20.0)
    rotors = [SimpleNamespace(propeller=apc8x6, params=None, axis=np.array([0.0, 0.0, 1.0])),
              SimpleNamespace(propeller=apc8x6, params=None, axis=np.array([np.sin(tilt), 0.0, np.cos(tilt)]))]
    om = np.full((4, 2), 6000 * RPM)
    h = _hover_loads(apc_params, SimpleNamespace(rotors=rotors), SimpleNamespace(rotor_omega=om, n=4), Air())
    one = pm.HoverModel.from_model(apc8x6, apc_params, 6000 * RPM).thrust(6000 * RPM)
    assert h["thrust"] == pytest.approx(np.full(4, 2 * one), rel=1e-12)
    assert h["vertical"] == pytest.approx(np.full(4, one * (1 + np.cos(tilt))), rel=1e-12)


# --- parameter files and maps written and read back --------------------------------------------------------------

def _body(cg=None, kappa=None):
    from propmap.core.body import BodyDrag
    from propmap.io.params_file import BodyTable

    return BodyTable(BodyDrag(drag_area=(0.004, 0.004, 0.008), wash_factor=1.0),
                     None if cg is None else np.asarray(cg, float), kappa)


def test_a_body_table_is_written_only_as_the_reader_takes_it(tmp_path):
    """fit flight wrote the vehicle file's centre of mass (z 1.5 m: the vehicle file allows 100 m) into a [body]
    table that took only 1 m, and write_params wrote NaN, 2 components or rotor_interference 5 unchecked: every
    reader then refused the file."""
    from propmap.io.params_file import read_body, write_params

    p = pm.generic_params()
    write_params(tmp_path / "a.toml", p, body=_body([0.0, 0.0, 1.5]))
    assert read_body(tmp_path / "a.toml").centre_of_mass == pytest.approx([0.0, 0.0, 1.5])
    for body, what in ((_body([150.0, 0.0, 0.0]), r"centre_of_mass\[0\]"), (_body([np.nan, 0, 0]), "centre_of_mass"),
                       (_body([0.0, 0.0]), "centre_of_mass must be 3 numbers"),
                       (_body(kappa=5.0), "rotor_interference"), (_body(kappa=np.nan), "rotor_interference")):
        with pytest.raises(ValueError, match=what):
            write_params(tmp_path / "b.toml", p, body=body)
        assert not (tmp_path / "b.toml").exists()


def test_a_body_comment_must_be_text(tmp_path):
    from propmap.io.params_file import ParamsFileError, read_body

    f = tmp_path / "c.toml"
    f.write_text('section_model = "cambered"\n[body]\ndrag_area = [0.01, 0.01, 0.01]\ncomment = [1, 2]\n')
    with pytest.raises(ParamsFileError, match=r"\[body\] comment must be text"):
        read_body(f)


def test_a_named_set_written_to_a_file_keeps_its_coverage(tmp_path):
    """write_params of calibrated:apce_8x6 dropped what its data covered: the file's loads beyond 6713 rpm
    warned of nothing, the set's did. Only a shipped set, unchanged, carries its own: a set changed without a new
    label, or one read from a file (whose path may name another file later), carries none (a review)."""
    import dataclasses

    from propmap.io.params_file import read_coverage, read_params, set_coverage, write_params

    p = pm.default_params("apce_8x6")
    write_params(tmp_path / "c.toml", p)
    written = read_coverage(tmp_path / "c.toml")
    assert {k: written[k] for k in set_coverage("calibrated:apce_8x6")} == set_coverage("calibrated:apce_8x6")
    assert set_coverage("calibrated:apce_8x6")["rpm_max"] == 6713.0
    # with its propeller's blade and Reynolds span, which the label calibrated:apce_8x6 gives the commands (a review:
    # at 10 km the set warned of its Reynolds numbers, the file did not)
    from propmap.io.coverage import coverage_warnings

    assert written["propeller"] == "apce_8x6" and written["n_blades"] == 2
    prop, thin = pm.load_propeller("apce_8x6"), pm.Air.isa(10000.0)
    said = [coverage_warnings(prop, label, thin, 100.0, 0.5, 0.0, rpm=(4000.0, 5000.0))
            for label in ("calibrated:apce_8x6", str(tmp_path / "c.toml"))]
    assert said[0] and [w.replace(str(tmp_path / "c.toml"), "calibrated:apce_8x6") for w in said[1]] == said[0]
    write_params(tmp_path / "g.toml", pm.generic_params())
    assert read_coverage(tmp_path / "g.toml") == {"J_max": pytest.approx(1.552), "incidence_deg_max": 0.0}
    for other in (dataclasses.replace(p, cl_alpha=2 * p.cl_alpha), p.replace(collective=0.01)):
        write_params(tmp_path / "d.toml", other)
        assert read_coverage(tmp_path / "d.toml") is None
    # a set read from a file and written unchanged keeps that file's table (a second review)
    write_params(tmp_path / "copy.toml", read_params(tmp_path / "c.toml"))
    assert read_coverage(tmp_path / "copy.toml") == read_coverage(tmp_path / "c.toml")
    (tmp_path / "c.toml").write_text((tmp_path / "g.toml").read_text())  # the path now names another set
    write_params(tmp_path / "copy2.toml", read_params(tmp_path / "copy.toml").replace(label=str(tmp_path / "c.toml")))
    assert read_coverage(tmp_path / "copy2.toml") is None
    write_params(tmp_path / "e.toml", p, coverage={})
    assert read_coverage(tmp_path / "e.toml") is None


def test_map_collective_zero_leaves_the_set_and_its_label():
    """--collective-deg 0 rounded the set's collective to 12 digits and relabelled it (which lost its model
    uncertainty)."""
    from propmap.cli.map import _with_collective

    p = pm.generic_params().replace(collective=0.0805207446773284)
    q, label = _with_collective(p, "mine.toml", 0.0)
    assert q is p and label == "mine.toml"
    q, label = _with_collective(p, "mine.toml", 1.0)
    assert label == "mine.toml + collective 1 deg" and q.collective == pytest.approx(p.collective + np.radians(1.0))


def test_toml_errors_name_the_line_and_unknown_keys_the_valid_ones(tmp_path):
    from propmap.io.params_file import ParamsFileError, read_params

    f = tmp_path / "dup.toml"
    f.write_text('section_model = "cambered"\ncl_alpha = 5.0\ncl_alpha = 6.0\n')
    with pytest.raises(ParamsFileError, match=r"at line 3.*; line 3: cl_alpha = 6.0$"):
        read_params(f)
    g = tmp_path / "unk.toml"
    g.write_text('section_model = "gill2017"\ncl1 = 5.0\ncl2 = 1.0\ncd = 1.0\nalpha0_deg = 20\ncd_0 = 0.01\n')
    with pytest.raises(ParamsFileError, match=r"unknown key\(s\) cd_0 .*did you mean cd0\? \(its keys: M, alpha0_deg"):
        read_params(g)


def test_a_group_label_too_long_for_the_coverage_is_refused_on_reading(tmp_path):
    """A 1001-character group label was refused only after the whole fit, naming [coverage]."""
    from propmap.identify.csvfile import DataError
    from propmap.identify.loads_csv import read_loads

    f = tmp_path / "long.csv"
    f.write_text("rpm,thrust,group\n" + "".join(f"{w},{t},{'g' * 1001 if k == 4 else 'a'}\n" for k, (w, t) in
                                                 enumerate(zip(range(3000, 9000, 1000), np.linspace(1, 4, 6)))))
    with pytest.raises(DataError, match="column 'group' holds a label of 1001 characters at line 6: at most 1000"):
        read_loads(f)


def test_a_map_stored_in_single_precision_opens(small_map, tmp_path):
    """A map re-saved with every float as float32 was refused: 'coordinate omega must equal rpm in rad/s'."""
    from propmap.io.mapcheck import check_attributes, check_dataset
    from propmap.maps import RotorMap

    _, _, ds = small_map
    d32 = ds.copy()
    for k in list(d32.data_vars) + list(d32.coords):
        if d32[k].dtype == np.float64:
            d32[k] = d32[k].astype(np.float32)
    check_dataset(d32)
    r32 = RotorMap(d32).loads(6000 * RPM, 7.0, 1.0).thrust
    assert r32 == pytest.approx(RotorMap(ds).loads(6000 * RPM, 7.0, 1.0).thrust, rel=1e-5)
    bad = ds.copy()
    bad["omega"] = bad["omega"] * (1 + 1e-6)
    with pytest.raises(ValueError, match="coordinate omega must equal rpm"):
        check_dataset(bad)
    with pytest.raises(ValueError, match="speed_of_sound_m_s"):
        check_attributes({**ds.attrs, "speed_of_sound_m_s": 50.0})


def test_an_air_a_file_cannot_hold_is_refused_before_writing_or_building(tmp_path):
    """write_params wrote Air(speed_of_sound=50), which read_params refuses; build_map solved the whole grid, then
    refused to record that air, hinting at the axes (a review)."""
    from propmap.io.params_file import write_params
    from propmap.maps import build_map

    with pytest.raises(ValueError, match=r"w\.toml \(not written\): speed_of_sound must be a finite number in \[100"):
        write_params(tmp_path / "w.toml", pm.generic_params(), pm.Air(speed_of_sound=50.0))
    assert not (tmp_path / "w.toml").exists()
    with pytest.raises(ValueError, match=r"^air: .*speed_of_sound_m_s must be a number in \[100, 10000\] m/s"):
        build_map(pm.load_propeller("apce_8x6"), pm.generic_params(), np.array([4e3, 6e3]) * RPM, [0.0, 5.0],
                  [0.0, 1.0], air=pm.Air(speed_of_sound=50.0), n_check=0)


def test_a_toml_error_line_shows_control_characters_escaped(tmp_path):
    from propmap.io.params_file import ParamsFileError, read_params

    f = tmp_path / "esc.toml"
    f.write_text('section_model = "cambered"\ncl_alpha = 5.0\ncl_alpha = 6.0 # \x1b[31m\x07\n')
    with pytest.raises(ParamsFileError) as exc:
        read_params(f)
    assert "\x1b" not in str(exc.value) and "\x07" not in str(exc.value)
    assert str(exc.value).endswith(r"line 3: cl_alpha = 6.0 # \x1b[31m\x07")


def test_a_negative_hover_thrust_at_rest_is_not_called_the_windmill_brake(apc8x6):
    """torque_change_at_constant_thrust said "(a negative thrust: the windmill brake)" of any negative thrust, also
    of a rotor at rest at -30 deg collective (reverse pitch; a mutation audit)."""
    from propmap.core.trim import TrimError

    p = pm.default_params("apce_8x6")
    with pytest.raises(TrimError, match=r"below the least hover makes there, about 2\.12\d* N \(a negative thrust\)$"):
        pm.torque_change_at_constant_thrust(apc8x6, p, 1200.0, 0.0, 0.0, collective=np.radians(-30.0))
    with pytest.raises(TrimError, match=r"\(a negative thrust\)$"):  # edgewise (cos(90 deg) is 6e-17: a review)
        pm.torque_change_at_constant_thrust(apc8x6, p, 1200.0, 10.0, np.radians(90.0), collective=np.radians(-30.0))
    with pytest.raises(TrimError, match=r"\(a negative thrust: the windmill brake\)$"):  # a climb's
        pm.torque_change_at_constant_thrust(apc8x6, p, 800.0, 26.0, 0.0)
