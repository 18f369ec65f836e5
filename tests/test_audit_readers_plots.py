"""A mutation audit of io/readers.py (UIUC static and sweep files), plots.py (what each figure draws) and cli/demo.py
(what `propmap demo` writes and says), 2026-11-29: each test kills a hand-made mutant that survived the modules' own
test files, by the documented behaviour it changed."""

import re
import warnings
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from propmap.core.units import RPM_MAX
from propmap.io.readers import MeasurementFileError, looks_like_uiuc, read_uiuc_static, read_uiuc_sweep
import propmap.plots_flight as plots_flight

#: the UIUC vol. 1 files the package bundles (src/propmap/data/uiuc_v1; Brandt & Selig, AIAA 2011-1255)
UIUC = Path(str(resources.files("propmap") / "data" / "uiuc_v1"))
STATIC = "RPM    CT       CP\n2534   0.1083   0.0745\n2791   0.1071   0.0722\n"
#: a sweep whose eta is J CT / CP to 3 digits (ratio 1)
SWEEP_ROWS = [(0.2, 0.11, 0.07), (0.4, 0.09, 0.065), (0.6, 0.06, 0.05)]


def _write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text)
    return p


def _sweep(rows=SWEEP_ROWS, eta_scale=1.0, head=""):
    body = "".join(f"{J:.3f} {CT:.4f} {CP:.4f} {eta_scale * J * CT / CP:.4f}\n" for J, CT, CP in rows)
    return head + "J       CT       CP       eta\n" + body


def _eta_warnings(path):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sweep = read_uiuc_sweep(path)
    return sweep, [w for w in caught if "eta column" in str(w.message)]


# --- io/readers.py ----------------------------------------------------------------------------------------------

def test_a_static_file_reads_its_columns_in_order_with_its_run_id_and_source():
    """Mutants R8 (the run id before '_static_'), R9 (CT and CP swapped), R10 (the source names the stem): the
    bundled APC 8x6E static run, row by row."""
    run = read_uiuc_static(UIUC / "apce_8x6_static_2797rd.txt")
    assert run.run_id == "2797rd"
    assert (run.rpm[0], run.CT[0], run.CP[0]) == (2534.0, 0.1083, 0.0745)
    assert (run.rpm[1], run.CT[1], run.CP[1]) == (2791.0, 0.1071, 0.0722)
    assert run.source == "UIUC Propeller Data Site, apce_8x6_static_2797rd.txt"


def test_a_sweep_file_reads_its_run_id_and_nominal_rpm_from_its_name():
    """Mutants R17 (the run id from the last part, the rpm) and R18 (a two-part name's run id was its whole stem)."""
    sweep = read_uiuc_sweep(UIUC / "apce_8x6_2801rd_6023.txt")
    assert (sweep.run_id, sweep.rpm) == ("2801rd", 6023.0)
    assert sweep.J[0] == 0.114 and sweep.CT[0] == 0.1155 and sweep.CP[0] == 0.0731 and sweep.eta[0] == 0.181


def test_a_two_part_sweep_name_gives_its_first_part_as_the_run(tmp_path):
    """Mutant R18: ``len(parts) > 2`` took a two-part name's whole stem ('sweep_5000') as the run id."""
    assert read_uiuc_sweep(_write(tmp_path, "sweep_5000.txt", _sweep())).run_id == "sweep"


@pytest.mark.parametrize("row, match", [
    ("25.0 0.1 0.05 0.5", r"line 2: J = 25 is outside \[0, 20\]"),     # Mutant R4 (J_MAX 200)
    ("-0.5 0.1 0.05 0.5", r"line 2: J = -0.5 is outside \[0, 20\]"),   # Mutant R5 (J from -1)
    ("0.5 0.1 12.0 0.5", r"line 2: CP = 12 is outside \[-10, 10\]"),   # Mutant R7 (a sweep's CP unchecked)
])
def test_a_sweep_value_out_of_range_is_refused_naming_its_line_and_range(tmp_path, row, match):
    """Mutants R4, R5, R7: J in [0, 20] and CP in [-10, 10], as the module says."""
    with pytest.raises(MeasurementFileError, match=match):
        read_uiuc_sweep(_write(tmp_path, "a_8x6_r1_5000.txt", "J CT CP eta\n" + row + "\n"))
    assert read_uiuc_sweep(_write(tmp_path, "b_8x6_r1_5000.txt", "J CT CP eta\n20 0.1 0.05 40\n")).J[0] == 20


def test_a_static_cp_out_of_range_is_refused(tmp_path):
    """Mutant R6: a static file's CP column unchecked (CP = 12 read as a coefficient)."""
    with pytest.raises(MeasurementFileError, match=r"line 4: CP = 12 is outside \[-10, 10\]"):
        read_uiuc_static(_write(tmp_path, "x_static_r1.txt", STATIC + "3000 0.11 12\n"))


@pytest.mark.parametrize("value, ok", [("0", False), (repr(RPM_MAX), True), ("954930", False)])
def test_a_sweep_rate_line_takes_0_exclusive_to_rpm_max_inclusive(tmp_path, value, ok):
    """Mutants R13 (a rate of 0 read) and R14 (RPM_MAX itself refused): the range is (0, 954929]."""
    f = _write(tmp_path, "a_8x6_r1_5000.txt", _sweep(head=f"RPM average = {value}\n"))
    if ok:
        assert read_uiuc_sweep(f).rpm == RPM_MAX == 954929.0
    else:
        match = rf"line 1: RPM average = '{value}' is outside \(0, 954929\] rpm"
        with pytest.raises(MeasurementFileError, match=match):
            read_uiuc_sweep(f)


def test_a_low_measured_rate_is_read_and_only_a_name_below_100_rpm_refused(tmp_path):
    """Mutants R15 (the 100 rpm floor applied to a measured 'RPM average' line) and R16 (the floor at 10 rpm): the
    floor guards only the file name's rate (a copy's suffix)."""
    assert read_uiuc_sweep(_write(tmp_path, "a_8x6_r1_5000.txt", _sweep(head="RPM average = 50\n"))).rpm == 50.0
    with pytest.raises(MeasurementFileError, match=r"the rpm '50' at the end of the file name is 50, below 100 rpm"):
        read_uiuc_sweep(_write(tmp_path, "a_8x6_r1_50.txt", _sweep()))
    assert read_uiuc_sweep(_write(tmp_path, "a_8x6_r1_100.txt", _sweep())).rpm == 100.0


@pytest.mark.parametrize("key", ["rpm", "Average RPM", "average_rpm", "RPM_average"])
def test_each_spelling_of_the_rate_line_sets_the_rate(tmp_path, key):
    """Mutants R25 ('rpm' not a rate key) and R26 ('average rpm' not a rate key): the measured rate, not the name's."""
    f = _write(tmp_path, "a_8x6_r1_5000.txt", _sweep(head=f"{key} = 4998\n"))
    assert read_uiuc_sweep(f).rpm == 4998.0


def test_the_eta_check_warns_beyond_10_percent_and_names_the_caller(tmp_path):
    """Mutants R20 (ETA_MISMATCH 0.5: eta 30% off said nothing) and R24 (stacklevel 2: the warning blamed
    readers.py, not the caller)."""
    _, said = _eta_warnings(_write(tmp_path, "a_8x6_r1_5000.txt", _sweep(eta_scale=1.3)))
    assert len(said) == 1 and "the eta column is 1.3 times J CT / CP in the median" in str(said[0].message)
    assert Path(said[0].filename).name == Path(__file__).name
    _, said = _eta_warnings(_write(tmp_path, "b_8x6_r1_5000.txt", _sweep(eta_scale=1.05)))
    assert said == []


def test_the_eta_check_needs_two_points_and_skips_small_eta(tmp_path):
    """Mutants R21 (one point judged) and R36 (eta below 0.5 not judged): eta 0.2-0.4 at 1.5 times J CT / CP warns;
    one judged point does not."""
    small = [(0.1, 0.11, 0.07), (0.15, 0.11, 0.07), (0.2, 0.10, 0.07)]  # eta 0.24, 0.35, 0.43
    _, said = _eta_warnings(_write(tmp_path, "a_8x6_r1_5000.txt", _sweep(rows=small, eta_scale=1.5)))
    assert len(said) == 1 and "1.5 times" in str(said[0].message)
    one = [(0.0, 0.11, 0.07), (0.4, 0.09, 0.065)]  # J = 0: not judged
    _, said = _eta_warnings(_write(tmp_path, "b_8x6_r1_5000.txt", _sweep(rows=one, eta_scale=1.5)))
    assert said == []


def test_a_real_sweep_reads_without_an_eta_warning():
    """Mutant R22 (CT and CP exchanged in the ratio): the bundled apce_8x6 sweeps are consistent."""
    for f in sorted(UIUC.glob("apce_8x6_28*rd_*.txt")):
        _, said = _eta_warnings(f)
        assert said == [], f


@pytest.mark.parametrize("text, expect", [
    ("# a\n" * 9 + "RPM CT CP\n2534 0.1 0.07\n", True),                       # Mutant R28 (first 5 lines only)
    ("\ufeffRPM CT CP\n2534 0.1 0.07\n", True),                                  # Mutant R29 (the BOM kept)
    ("# " + "x" * 300 + "\nJ CT CP eta\n0.1 0.1 0.07 0.14\n", True),             # Mutant R33 (first 256 bytes)
    ("CT RPM CP thrust\n0.1 2534 0.07 3\n", False),                              # Mutant R30 (a 4th column not eta)
    ("CT RPM CP thrust torque\n0.1 2534 0.07 3 0.1\n", False),                   # Mutant R31 (five columns)
    ("CP CT RPM\n0.07 0.1 2534\n", True),
])
def test_looks_like_uiuc_reads_the_header_where_it_is(tmp_path, text, expect):
    """Mutants R28, R29, R30, R31, R33: UIUC's columns in any order, and exactly those (eta the only 4th)."""
    p = tmp_path / "f.txt"
    p.write_bytes(text.encode("utf-8"))
    assert looks_like_uiuc(p) is expect


# --- plots.py ---------------------------------------------------------------------------------------------------

@pytest.fixture
def drawn(monkeypatch):
    """The figures the plot functions would save (plots._save replaced: nothing written)."""
    import propmap.plots as plots

    figs = []

    def keep(fig, path):
        figs.append(fig)
        return Path(path)

    monkeypatch.setattr(plots, "_save", keep)
    yield plots, figs  # (each figure on its own canvas, not pyplot's: nothing to close)


def _lines(ax):
    """(label, x, y, linestyle, marker, markerfacecolor) of each line of ``ax``."""
    return [(ln.get_label(), np.asarray(ln.get_xdata(), float), np.asarray(ln.get_ydata(), float), ln.get_linestyle(),
             ln.get_marker(), ln.get_markerfacecolor()) for ln in ax.get_lines()]


def _run(kind, label, J, CT, CTm, CP, CPm, run_id="r"):
    from types import SimpleNamespace

    return SimpleNamespace(kind=kind, label=label, run_id=run_id, J=np.array(J), CT=np.array(CT),
                           CT_model=np.array(CTm), CP=np.array(CP), CP_model=np.array(CPm),
                           CT_hover=np.array([0.11]), CP_hover=np.array([0.07]))


def test_plot_validation_draws_measured_and_model_of_each_run_and_the_hover_model(drawn, tmp_path):
    """Mutants P1 (a static run's markers drew the model), P2 (a sweep's model line unsorted in J), P3 (the CT and
    CP hover lines exchanged), P4 (the citation added to a title that holds 'Data:'), P5 (the static model's
    markers labelled measured)."""
    from types import SimpleNamespace

    plots, figs = drawn
    static = _run("static", "static 2797rd", [0, 0], [0.108, 0.107], [0.100, 0.101], [0.074, 0.072], [0.070, 0.071])
    sweep = _run("sweep", "2801rd", [0.5, 0.1, 0.3], [0.08, 0.11, 0.10], [0.081, 0.112, 0.098],
                 [0.06, 0.07, 0.068], [0.061, 0.071, 0.066])
    v = SimpleNamespace(runs=[static, sweep], CT_hover=0.109, CP_hover=0.073, propeller="apce_8x6",
                        citation="UIUC (Brandt & Selig 2011)")
    plots.plot_validation(v, tmp_path / "v.png")
    ct, cp = figs[0].axes[0], figs[0].axes[1]
    lines = {ln[0]: ln for ln in _lines(ct)}
    assert list(lines["static 2797rd (measured)"][2]) == [0.108, 0.107] and lines["static 2797rd (measured)"][4] == "s"
    assert list(lines["static 2797rd (model)"][2]) == [0.100, 0.101] and lines["static 2797rd (model)"][4] == "x"
    assert list(lines["2801rd (measured)"][2]) == [0.08, 0.11, 0.10]
    model = [ln for ln in _lines(ct) if ln[3] == "-" and ln[1].size == 3][0]
    assert list(model[1]) == [0.1, 0.3, 0.5] and list(model[2]) == [0.112, 0.098, 0.081]
    assert list(lines["hover model (measured static)"][2]) == [0.109, 0.109]
    assert list({ln[0]: ln for ln in _lines(cp)}["hover model (measured static)"][2]) == [0.073, 0.073]
    assert (ct.get_xlabel(), ct.get_ylabel(), cp.get_ylabel()) == ("J = V/(n D)", "CT", "CP")
    assert figs[0]._suptitle.get_text() == "apce_8x6: model vs measured\nData: UIUC (Brandt & Selig 2011)"
    plots.plot_validation(v, tmp_path / "w.png", title="mine\nData: elsewhere")
    assert figs[1]._suptitle.get_text() == "mine\nData: elsewhere"


def test_plot_envelope_draws_sorted_curves_and_the_error_in_percent_of_the_largest_hover_thrust(drawn, tmp_path):
    """Mutants P6 (the error's sign T - T_hover), P7 (the error not in %), P8 (the scale the largest signed, not
    |T_hover|), P9 (the drag panel drew thrust), P10 (the rows unsorted in airspeed), P11 (the hover line at the
    first row's thrust), P12 (the error panel's unit)."""
    import pandas as pd

    plots, figs = drawn
    table = pd.DataFrame({"airspeed": [10.0, 0.0, 5.0, 0.0, 5.0, 10.0], "incidence_deg": [0.0, 0.0, 0.0, 90, 90, 90],
                          "thrust": [-1.0, -2.0, -1.5, -2.0, -2.1, -2.4], "drag": [0.0, 0.0, 0.0, 0.0, 0.3, 0.6],
                          "thrust_hover": [-2.0] * 6})
    plots.plot_envelope(table, tmp_path / "e.png", title="t")
    thrust, drag, err = figs[0].axes
    curves = _lines(thrust)
    assert curves[0][0] == "incidence 0 deg" and list(curves[0][1]) == [0.0, 5.0, 10.0]
    assert list(curves[0][2]) == [-2.0, -1.5, -1.0]
    assert curves[-1][0] == "hover model T = k_T Omega^2" and list(curves[-1][2]) == [-2.0, -2.0]
    assert list(_lines(drag)[1][2]) == [0.0, 0.3, 0.6]
    assert _lines(err)[0][2] == pytest.approx([0.0, -25.0, -50.0])  # 100 (T_hover - T) / max |T_hover|
    assert _lines(err)[1][2] == pytest.approx([0.0, 5.0, 20.0])
    assert err.get_ylabel() == "hover-model thrust error [% of hover T]" and thrust.get_ylabel() == "thrust T [N]"
    assert all(ax.get_xlabel() == "airspeed V [m/s]" for ax in figs[0].axes)


def test_plot_cv_summary_draws_each_protocols_cumulative_distribution_in_percent(drawn, tmp_path):
    """Mutants P13 (the errors not in %), P14 (the fractions from 0, not 1/n), P15 (the CT and CP panels exchanged),
    P16 (a linear x axis), P17 (the title counted the protocols, not the propellers)."""
    plots, figs = drawn
    rows = [{"blind": {"rms_ct": ct, "rms_cp": cp}} for ct, cp in ((0.04, 0.10), (0.02, 0.05), (0.08, 0.20))]
    plots.plot_cv_summary({"summary": {"blind": {}}, "propellers": rows}, tmp_path / "c.png")
    ct, cp = figs[0].axes
    label, x, y, *_ = _lines(ct)[0]
    assert label == "blind" and list(x) == pytest.approx([2.0, 4.0, 8.0])
    assert list(y) == pytest.approx([1 / 3, 2 / 3, 1])
    assert list(_lines(cp)[0][1]) == pytest.approx([5.0, 10.0, 20.0])
    assert ct.get_xscale() == "log" and ct.get_xlabel() == "rms |dCT| / static CT on held-out data [%]"
    assert figs[0]._suptitle.get_text().startswith("propmap cross-validation over 3 catalogue propellers\n")


def test_plot_flight_timeseries_draws_each_axis_of_measured_predicted_and_others(drawn, tmp_path):
    """Mutants P18 (the measured line drew the prediction), P19 (an 'other' lacking a log: KeyError, not skipped),
    P20 (the force axis without its unit)."""
    plots, figs = drawn
    t = {"a": np.array([0.0, 1.0]), "b": np.array([0.0, 0.5])}
    meas = {k: np.array([[1.0, 2.0, -9.0], [1.5, 2.5, -9.5]]) for k in t}
    pred = {k: np.array([[1.1, 2.1, -9.1], [1.4, 2.4, -9.4]]) for k in t}
    other = {"k Omega^2": {"a": pred["a"] * 2}}
    plots_flight.plot_flight_timeseries(t, meas, pred, tmp_path / "f.png", title="x", other=other)
    axes = figs[0].axes  # 3 rows x 2 columns, row-major
    z_a = {ln[0]: ln for ln in _lines(axes[4])}
    assert list(z_a["measured m a"][2]) == [-9.0, -9.5] and list(z_a["propmap"][2]) == [-9.1, -9.4]
    assert list(z_a["k Omega^2"][2]) == [-18.2, -18.8]
    assert [ln[0] for ln in _lines(axes[5])] == ["measured m a", "propmap"]  # log b: no 'other' line
    assert [axes[k].get_ylabel() for k in (0, 2, 4)] == ["Fx [N]", "Fy [N]", "Fz [N]"]


def test_plot_flight_speed_bins_medians_of_three_samples_or_more_per_metre_per_second(drawn, tmp_path):
    """Mutants P21 (a bin of 2 samples drawn), P22 (a sample at an edge in two bins), P23 (means, not medians),
    P24 (the last bin, holding the fastest samples, dropped), P25 (the hover line drew the model), P35 (the first
    vertical error drawn dashed)."""
    plots, figs = drawn
    speed = np.array([0.2, 0.5, 0.8, 1.2, 1.6, 2.0, 2.4, 2.5, 2.9])
    model = np.array([1.0, 2.0, 9.0, 5.0, 5.0, 7.0, 1.0, 2.0, 3.0])
    hover = -model
    loads = {"thrust": model, "drag": model, "torque": model}
    plots_flight.plot_flight_speed(speed, loads, {k: hover for k in loads}, {"fitted": model, "k Omega^2": hover},
                            tmp_path / "s.png")
    thrust = figs[0].axes[0]
    fitted, hov = _lines(thrust)[:2]
    assert list(fitted[1]) == [0.5, 1.5, 2.5]
    # medians (1, 2, 9 and 7, 1, 2, 3); [1, 2) holds 2 samples (2.0 is the next bin's): none drawn
    assert fitted[2][0] == 2.0 and np.isnan(fitted[2][1]) and fitted[2][2] == 2.5
    assert hov[2][0] == -2.0 and hov[2][2] == -2.5
    first, second = _lines(figs[0].axes[3])[:2]
    assert (first[0], first[3], first[4]) == ("fitted", "-", "o") and (second[3], second[4]) == ("--", "s")
    assert figs[0].axes[3].get_ylabel() == "vertical force error [N] (median)"


def test_plot_load_parity_draws_held_points_open_and_the_unit_line_from_zero(drawn, tmp_path):
    """Mutants P26 (the y = x line from the smallest measurement, not 0), P27 (held and used points exchanged),
    P28 (torque in N)."""
    from types import SimpleNamespace

    plots, figs = drawn
    data = SimpleNamespace(measured={"thrust": np.array([1.0, 2.0, 3.0]), "torque": np.array([0.01, 0.02, 0.03])})
    model = {"fitted": {"thrust": np.array([1.1, 2.1, 2.9]), "torque": np.array([0.011, 0.019, 0.03])}}
    plots.plot_load_parity(data, model, np.array([False, False, True]), tmp_path / "p.png", title="t")
    thrust, torque = figs[0].axes
    used, held, unit = _lines(thrust)
    assert list(used[1]) == [1.0, 2.0] and list(used[2]) == [1.1, 2.1] and used[0] == "fitted"
    assert list(held[1]) == [3.0] and held[5] == "none"
    assert list(unit[1]) == pytest.approx([0.0, 3.15])
    assert (torque.get_xlabel(), torque.get_ylabel()) == ("measured torque [N m]", "model torque [N m]")
    assert figs[0]._suptitle.get_text() == "t (open markers: held out)"


def test_plot_load_fit_draws_held_out_runs_open_and_model_lines_sorted(drawn, tmp_path):
    """Mutants P29 (held-out runs filled, the fitted ones open) and P36 (the fitted model's line unsorted in J)."""
    plots, figs = drawn
    a = _run("sweep", "2801rd", [0.5, 0.1], [0.08, 0.11], [0.081, 0.112], [0.06, 0.07], [0.061, 0.071], "2801rd")
    b = _run("sweep", "2798rd", [0.2, 0.4], [0.10, 0.09], [0.101, 0.091], [0.068, 0.064], [0.069, 0.065], "2798rd")
    plots.plot_load_fit([a, b], [a, b], {"2801rd"}, tmp_path / "l.png")
    lines = _lines(figs[0].axes[0])
    held = [ln for ln in lines if ln[0] == "2801rd (held out)"][0]
    used = [ln for ln in lines if ln[0] == "2798rd"][0]
    assert held[5] == "none" and used[5] != "none"
    fitted = [ln for ln in lines if ln[3] == "-" and ln[1].size == 2][0]
    assert list(fitted[1]) == [0.1, 0.5] and list(fitted[2]) == [0.112, 0.081]


def test_plot_cases_draws_the_hover_model_dashed(drawn, tmp_path):
    """Mutant P30: the APC 10x7E panel's hover model drawn solid like the models."""
    from types import SimpleNamespace

    plots, figs = drawn
    q = {"CT": np.array([0.1, 0.08]), "CQ": np.array([0.01, 0.009])}
    a = SimpleNamespace(x=np.array([0.0, 0.4]), measured=q, predicted={"hover model": q, "propmap": q},
                        notes="axial J sweep; x", citation="cite")
    plots.plot_cases({"apc10x7e": a}, tmp_path / "c.png")
    styles = {ln[0]: ln[3] for ln in _lines(figs[0].axes[0])}
    assert styles["hover model"] == "--" and styles["propmap"] == "-"


def test_a_figure_is_written_in_the_format_of_its_extension(tmp_path):
    """Mutant P31: every figure written as PNG, whatever its extension (an .svg held PNG bytes)."""
    import pandas as pd

    from propmap.plots import plot_envelope

    table = pd.DataFrame({"airspeed": [0.0, 5.0], "incidence_deg": [0.0, 0.0], "thrust": [2.0, 1.8],
                          "drag": [0.0, 0.1], "thrust_hover": [2.0, 2.0]})
    svg = plot_envelope(table, tmp_path / "e.svg")
    assert b"<svg" in svg.read_bytes()[:2000]
    assert plot_envelope(table, tmp_path / "e.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_map_contours_draws_the_hover_error_as_static_minus_thrust(drawn, tmp_path):
    """Mutant P32: the hover-model error drawn T - T_hover (its contour levels all negative where thrust falls)."""
    import xarray as xr

    plots, figs = drawn
    V, inc = np.array([0.0, 5.0, 10.0]), np.array([0.0, 90.0])
    thrust = np.array([[[4.0, 4.0], [3.0, 3.8], [2.0, 3.5]]])  # (rpm, airspeed, incidence)
    dims = ("rpm", "airspeed", "incidence_deg")
    flags = np.zeros_like(thrust, bool)
    ds = xr.Dataset({"thrust": (dims, thrust), "drag": (dims, thrust / 10), "torque": (dims, thrust / 100),
                     "vortex_ring": (dims, flags), "multiple_roots": (dims, flags), "converged": (dims, ~flags)},
                    coords={"rpm": [6000.0], "airspeed": V, "incidence_deg": inc})
    plots.plot_map_contours(ds, 6000.0, tmp_path / "m.png", title="m")
    hover = figs[0].axes[3]
    levels = hover.collections[0].levels
    assert levels.min() >= 0.0 and levels.max() >= 2.0
    assert figs[0].axes[-1].get_ylabel() == "hover model error T_hover - T [N]"


def test_plot_level_flight_fit_draws_pitch_in_degrees_and_the_hover_error(drawn, tmp_path):
    """Mutants P33 (pitch in rad under a [deg] axis) and P34 (the hover model's error T_h + weight)."""
    from types import SimpleNamespace

    from propmap.plots_flight import plot_level_flight_fit

    _, figs = drawn
    data = SimpleNamespace(airspeed=np.array([8.0, 2.0]), pitch=np.radians([-20.0, -5.0]))
    forces = {"thrust": np.ones((2, 4)), "drag": np.zeros((2, 4)), "torque": np.ones((2, 4)),
              "vertical": np.array([10.5, 9.9])}
    plot_level_flight_fit(data, forces, np.array([9.0, 9.8]), 10.0, tmp_path / "l.png")
    assert list(_lines(figs[0].axes[4])[0][2]) == pytest.approx([-5.0, -20.0])
    err = {ln[0]: ln for ln in _lines(figs[0].axes[3])}
    assert list(err["hover model"][2]) == pytest.approx([-0.2, -1.0]) and list(err["BET+BEMT"][2]) == pytest.approx(
        [-0.1, 0.5])


# --- cli/demo.py ------------------------------------------------------------------------------------------------

def test_demo_envelope_table_holds_the_models_loads_and_the_hover_model_at_the_rpm():
    """Mutants D2 (11 airspeeds), D3 (no edgewise incidence), D4 (rpm taken as rad/s), D5 (T_hover the hover
    torque), D6 (Q_hover the hover thrust), D8 (incidence in deg given as rad), D9 (drag and torque exchanged),
    D26 (the rpm column in rad/s)."""
    import propmap as pm
    from propmap.cli.demo import envelope_table
    from propmap.core.solver import rotor_loads
    from propmap.core.units import RPM

    prop, params = pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc")
    table = envelope_table(prop, params, 8000.0)
    assert len(table) == 84 and sorted(set(table.incidence_deg)) == [0.0, 30.0, 60.0, 90.0]
    assert sorted(set(table.airspeed)) == [float(v) for v in range(21)] and set(table.rpm) == {8000.0}
    om = 8000.0 * RPM
    hover = rotor_loads(prop, params, om, 0.0, 0.0)
    assert table.thrust_hover.iloc[0] == pytest.approx(float(hover.thrust), rel=1e-6)
    assert table.torque_hover.iloc[0] == pytest.approx(float(hover.torque), rel=1e-6)
    assert 2.0 < table.thrust_hover.iloc[0] < 8.0  # the APC 8x6E's static thrust at 8000 rpm [N]
    row = table[(table.airspeed == 10.0) & (table.incidence_deg == 90.0)].iloc[0]
    edge = rotor_loads(prop, params, om, 10.0, np.radians(90.0))
    assert (row.thrust, row.drag, row.torque) == pytest.approx(
        (float(edge.thrust), float(edge.drag), float(edge.torque)), rel=1e-6)
    assert row.drag > 0.05


@pytest.fixture(scope="module")
def demo_run(tmp_path_factory):
    """`propmap demo` run once (default rpm), with what it handed plot_validation, fit_loads and coverage_messages
    recorded: (exit code, stdout, out folder, records)."""
    import contextlib
    import io

    import propmap.cli._coverage as coverage
    import propmap.identify as identify
    import propmap.plots as plots
    from propmap.cli.main import main

    rec = {"validation": [], "fit": [], "coverage": []}
    out_dir = tmp_path_factory.mktemp("demo") / "d"
    real_plot, real_fit, real_cov = plots.plot_validation, identify.fit_loads, coverage.coverage_messages

    def plot_validation(v, path, **kw):
        rec["validation"].append(v)
        return real_plot(v, path, **kw)

    def fit_loads(data, prop, **kw):
        rec["fit"].append(kw)
        return real_fit(data, prop, **kw)

    def coverage_messages(*args, **kw):
        rec["coverage"].append(args)
        return real_cov(*args, **kw)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plots, "plot_validation", plot_validation)
        mp.setattr(identify, "fit_loads", fit_loads)
        mp.setattr(coverage, "coverage_messages", coverage_messages)
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            code = main(["demo", "--out-dir", str(out_dir)])
    return code, buf.getvalue(), out_dir, rec


def test_demo_writes_figures_and_a_fitted_file_with_its_coverage(demo_run):
    """`propmap demo` writes its table and figures, prints the paper's Table I model beside the hover model,
    and its fitted file records what the fitted data covered, as fit loads' files do (it had no [coverage]:
    used at J = 1.85, where the data reach 0.97, it said nothing). (Moved from tests/test_cli.py, which ran
    the demo a second time.)"""
    from propmap.io.params_file import read_coverage

    code, out, out_dir, _ = demo_run
    assert code == 0
    for name in ("envelope.csv", "envelope.png", "validation.png"):
        assert (out_dir / name).is_file()
    assert "Table I" in out and "hover" in out
    cov = read_coverage(out_dir / "fitted_params.toml")
    assert cov["J_max"] == pytest.approx(0.974, abs=1e-3) and (cov["rpm_min"], cov["rpm_max"]) == (2534.0, 6713.0)


def test_demo_envelope_rows_print_the_hover_error_in_n_and_percent_of_t_hover(demo_run):
    """Mutants D10 (the % of T, not of T_hover), D11 (the error T - T_hover), D12 (no 10 m/s rows), D17 (the default
    rpm 6000), D23 (the T_hover said the first row's thrust)."""
    import pandas as pd

    code, out, out_dir, _ = demo_run
    assert code == 0
    table = pd.read_csv(out_dir / "envelope.csv")
    t_hover = table.thrust_hover.iloc[0]
    assert f"1. Envelope at 8000 rpm, cambered model vs hover model (T_hover = {t_hover:.3f} N, D = 0)" in out
    row = r"^ +(\d+) +(\d+) +(-?\d+\.\d{3}) +(-?\d+\.\d{3}) +(-?\d+\.\d{4}) *([+-]\d+\.\d{3}) N +([+-]\d+)%"
    rows = re.findall(row, out, re.M)
    assert [(int(v), int(b)) for v, b, *_ in rows] == [(v, b) for b in (0, 30, 60, 90) for v in (0, 10, 20)]
    for v, b, thrust, _, _, err, pct in rows:
        assert float(err) == pytest.approx(t_hover - float(thrust), abs=2e-3)
        assert int(pct) == pytest.approx(100 * (t_hover - float(thrust)) / t_hover, abs=0.6)
    assert any(int(p) <= -5 for *_, p in rows) or any(int(p) >= 5 for *_, p in rows)


def test_demo_validation_rows_are_each_runs_and_the_pooled_errors_of_both_models(demo_run):
    """Mutants D15 (the figure drew the paper's validation), D18 (the paper's pooled CT and CP exchanged), D19 (the
    CT bias said the rms), D27 (a run's cambered CP the paper's), D28 (one run's row only)."""
    import propmap as pm
    from propmap.io.catalogue import get_entry
    from propmap.validation import validate

    code, out, _, rec = demo_run
    v_gen = rec["validation"][0]
    paper = validate(get_entry("apce_8x6"), pm.load_propeller("apce_8x6"), pm.preset("gill2017-apc"))
    for rp, rg in zip(paper.runs, v_gen.runs):
        ep, eg = rp.errors("model"), rg.errors("model")
        assert (f"{rp.label:<22}{ep['ct_rmse']:>10.4f}{ep['cp_rmse']:>10.4f}{eg['ct_rmse']:>13.4f}"
                f"{eg['cp_rmse']:>13.4f}") in out
    assert len(v_gen.runs) == 8 and len(re.findall(r"^   (static|\d{4}rd)", out, re.M)) >= 8
    sp, sg = paper.summary("model"), v_gen.summary("model")
    assert sg["ct_rmse"] < sp["ct_rmse"]  # the figure's validation is the cambered model's, not the paper's
    assert (f"{'all ' + str(sp['n_points']) + ' points':<22}{sp['ct_rmse']:>10.4f}{sp['cp_rmse']:>10.4f}"
            f"{sg['ct_rmse']:>13.4f}{sg['cp_rmse']:>13.4f}") in out
    assert f"bias: paper CT {sp['ct_bias']:+.4f}, CP {sp['cp_bias']:+.4f}; cambered CT {sg['ct_bias']:+.4f}" in out


def test_demo_fits_hold_out_both_6000_rpm_sweeps_with_a_prior_that_never_saw_the_family(demo_run):
    """Mutants D14 (the paper's model fitted from the cambered set), D16 (one sweep held out), D20 (the fitted
    cambered CT and CP exchanged), D21 (the hover model's row the unfitted set's), D22 (the tip Mach checked at
    1000 rpm), D24 (the prior of the whole catalogue, apce_8x6's family in it)."""
    import propmap as pm
    from propmap.cli._coverage import envelope_extremes
    from propmap.io.calibration import generic_without, population
    from propmap.io.catalogue import get_entry
    from propmap.io.params_file import read_params
    from propmap.io.readers import read_uiuc_sweep
    from propmap.validation import holdout_comparison

    code, out, out_dir, rec = demo_run
    held = sum(read_uiuc_sweep(f).J.size for f in UIUC.glob("apce_8x6_280[12]rd_*.txt"))
    assert f"held-out {held} points, rms error of the coefficients" in out
    prop = pm.load_propeller("apce_8x6")
    generic = generic_without("apce_8x6")[0]
    fitted = read_params(out_dir / "fitted_params.toml")
    params = fitted[0] if isinstance(fitted, tuple) else fitted
    cmp_c = holdout_comparison(get_entry("apce_8x6"), prop, params, generic, ("2801rd", "2802rd"))
    f, h = cmp_c["fitted"], cmp_c["hover_model"]
    assert f"{'cambered model, fitted':<36}{f['ct_rmse']:>8.4f}{f['cp_rmse']:>8.4f}" in out
    assert f"{'hover model (measured static)':<36}{h['ct_rmse']:>8.4f}{h['cp_rmse']:>8.4f}" in out
    assert rec["fit"][1]["base"] == pm.preset("gill2017-apc") != rec["fit"][0]["base"]
    prior = rec["fit"][0]["options"].population["covariance"]
    assert np.array_equal(prior, population(without="apce_8x6")["covariance"])
    assert not np.array_equal(prior, population()["covariance"])
    assert rec["coverage"][0][3] == envelope_extremes(prop, 8000.0, 20.0, 90.0)[0]


@pytest.mark.parametrize("rpm", ["10", "954929"])
def test_demo_takes_rpm_from_10_to_rpm_max_inclusive(capsys, tmp_path, monkeypatch, rpm):
    """Mutant D1: --rpm at its lowest (10 since 2026-11-30, DEMO_RPM_MIN; 1, RPM_MIN, before) refused; the
    folder check stands in for the rest of the demo."""
    import propmap.cli.demo as demo
    from propmap.cli._common import InputError
    from propmap.cli.main import main

    def reached(*args):
        raise InputError("the rpm passed")

    monkeypatch.setattr(demo, "check_out_dir", reached)
    code = main(["demo", "--rpm", rpm, "--out-dir", str(tmp_path / "d")])
    err = capsys.readouterr().err
    assert code == 2 and "the rpm passed" in err and "--rpm" not in err
