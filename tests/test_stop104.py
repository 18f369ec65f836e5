"""Stop 104: a figure's file extension gives its format, and any other extension is refused before drawing
(a ``.jpg`` path got PNG bytes under its name, and an extension-less path a PNG, until stop 104)."""

from __future__ import annotations

import inspect

import numpy as np
import pytest

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
