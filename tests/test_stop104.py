"""Stop 104: a figure's file extension gives its format, and any other extension is refused before drawing
(a ``.jpg`` path got PNG bytes under its name, and an extension-less path a PNG, until stop 104)."""

from __future__ import annotations

import inspect

import numpy as np
import pytest
from cli_helpers import run

import propmap as pm
import propmap.plots as plots
import propmap.plots_flight as plots_flight

#: every public figure function, by the module that holds it
FIGURES = [getattr(m, n) for m in (plots, plots_flight) for n in m.__all__ if n.startswith("plot_")]


def test_every_figure_function_is_listed():
    """The list above misses none: every ``plot_*`` function of both modules is in its ``__all__``."""
    found = {n for m in (plots, plots_flight) for n, f in vars(m).items()
             if n.startswith("plot_") and inspect.isfunction(f) and f.__module__ == m.__name__}
    assert found == {f.__name__ for f in FIGURES}
    assert len(FIGURES) == 10


@pytest.mark.parametrize("name", ["fig.jpg", "fig", "fig.png.txt", "fig.eps"])
@pytest.mark.parametrize("figure", FIGURES, ids=lambda f: f.__name__)
def test_an_extension_that_is_not_png_pdf_or_svg_is_refused_before_drawing(figure, name, tmp_path, monkeypatch):
    def no_drawing(*args, **kw):
        raise AssertionError("drew a figure it then could not write")

    monkeypatch.setattr(plots, "_figure", no_drawing)
    n_args = sum(p.default is p.empty and p.kind == p.POSITIONAL_OR_KEYWORD
                 for p in inspect.signature(figure).parameters.values())
    args = [None] * (n_args - 1) + [tmp_path / name]  # (the path is each one's last positional argument)
    suffix = name.rpartition(".")[2] if "." in name else "none"
    with pytest.raises(ValueError, match=rf"a figure's extension gives its format, one of \.png, \.pdf, \.svg; "
                                         rf"got \.?{suffix}"):
        figure(*args)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name, magic", [("f.PNG", b"\x89PNG"), ("f.pdf", b"%PDF"), ("f.Svg", b"<?xml")])
def test_the_extension_in_any_case_gives_the_format_written(name, magic, tmp_path):
    loads = {k: np.linspace(1.0, 2.0, 6) for k in ("thrust", "drag", "torque")}
    out = plots_flight.plot_flight_speed(np.linspace(0.0, 2.0, 6), loads, loads, {"m": np.zeros(6)}, tmp_path / name)
    assert out == tmp_path / name
    assert out.read_bytes().startswith(magic)


# ---- a catalogue set of the same blade on another hub (UIUC vol. 2's _3b and _4b) -----------------------------------

def test_a_set_calibrated_on_the_same_blade_on_another_hub_is_warned_of_as_such(capsys):
    """``calibrated:da4022_5x3.75`` on ``da4022_5x3.75_3b`` was warned of as "no better than the generic set", where it
    predicts the 3-blade hub's runs to 2.5% of static CT and the generic set to 12.7% (docs/validation.md); the
    warning now says what such sets did on UIUC's other hubs. Its errors are not labelled in-sample either: the data
    are the 3-blade hub's own."""
    code, out, err = run(capsys, "validate", "da4022_5x3.75_3b", "--params", "calibrated:da4022_5x3.75")
    assert code == 0
    assert "calibrated on the same blade on another hub: such a set predicted UIUC's 3- and 4-blade hubs" in err
    assert "no better than the generic set" not in err
    assert "in-sample" not in out  # (the set was not fitted to these runs)
    code, out, err = run(capsys, "validate", "da4022_5x3.75", "--params", "calibrated:da4022_5x3.75")
    assert code == 0 and "in-sample" in out and "another hub" not in err  # (its own runs: its fit's residual)
    code, _, err = run(capsys, "validate", "da4022_5x3.75_3b", "--params", "calibrated:apce_8x6")
    assert code == 0 and "no better than the generic set" in err and "another hub" not in err


def test_the_hub_rule_compares_the_blade_not_only_the_size():
    """Blades equal but for their count: the other hub; another blade of the same size and count: not."""
    from propmap.cli._common import _catalogue_geometry

    three = pm.load_propeller("da4022_5x3.75_3b")
    assert _catalogue_geometry("da4022_5x3.75", three) == "other hub"
    assert _catalogue_geometry("da4022_5x3.75_3b", three) is True
    assert _catalogue_geometry("nr640_5_15deg", pm.load_propeller("nr640_5_15deg_4b")) == "other hub"
    assert _catalogue_geometry("apce_8x6", three) is False
    assert _catalogue_geometry("no_such_propeller", three) is False
