"""Defects found by a user-level audit of the command line (2026-11-30): an option given twice,
loads too small for the printed decimals, the demo's lowest rpm, a catalogue propeller without
a calibrated set."""

from __future__ import annotations

import json

import click
import pytest

from cli_helpers import one_line_error, run
from propmap import resolve_params
from propmap.cli._common import Command, fixed
from propmap.cli.main import cli


def _commands(group=cli, path=()):
    for name, cmd in group.commands.items():
        if isinstance(cmd, click.Group):
            yield from _commands(cmd, path + (name,))
        else:
            yield path + (name,), cmd


def test_every_command_refuses_an_option_given_twice():
    """Every command is a propmap Command (a new one that forgets it would take the last value)."""
    found = dict(_commands())
    assert {("loads",), ("trim",), ("fit", "loads"), ("fit", "flight"), ("demo",)} <= set(found)
    assert [p for p, c in found.items() if not isinstance(c, Command)] == []


ONE = "given more than once (it takes one value)"
FLAG = "given more than once (it is a flag: give it once)"


@pytest.mark.parametrize("argv, message", [
    (("loads", "apce_8x6", "--rpm", "5000", "--rpm", "6000"), f"--rpm {ONE}"),
    (("loads", "apce_8x6", "--rpm=5000", "--airspeed", "3", "--rpm", "6000"), f"--rpm {ONE}"),
    (("loads", "apce_8x6", "--rpm", "5000", "--json", "--json"), f"--json {FLAG}"),
    (("trim", "apce_8x6", "--thrust", "2", "--thrust", "3"), f"--thrust {ONE}"),
    (("props", "--json", "--json"), f"--json {FLAG}"),
    (("trim", "apce_8x6", "--thrust", "2", "--rpm", "6000", "--range-deg", "-5", "5", "--range-deg", "-3", "3"),
     "--range-deg given more than once (it takes one set of 2 values)"),
])
def test_an_option_given_twice_is_refused(capsys, argv, message):
    """`loads --rpm 5000 --rpm 6000` ran at 6000 rpm, exit 0."""
    code, out, err = run(capsys, *argv)
    assert one_line_error(code, err, message), err
    assert out == ""


def test_options_that_take_several_values_may_repeat():
    """`multiple` and counting options are not refused (no propmap command has one today; a toy
    command checks the rule), nor is --help after an option."""
    from click.testing import CliRunner

    @click.command(cls=Command)
    @click.option("--name", multiple=True)
    @click.option("-v", count=True)
    @click.option("--rpm", type=float)
    def toy(name, v, rpm):
        click.echo(f"{name} {v} {rpm}")

    r = CliRunner().invoke(toy, ["--name", "a", "--name", "b", "-v", "-v", "--rpm", "5"])
    assert r.exit_code == 0 and r.output == "('a', 'b') 2 5.0\n"
    r = CliRunner().invoke(toy, ["--rpm", "5", "--rpm", "6"])
    assert r.exit_code == 2 and "--rpm given more than once" in r.output
    for argv in (["--rpm", "5", "--help"], ["--rpm", "5", "--rpm", "6", "--help"]):  # the help, as asked
        r = CliRunner().invoke(toy, argv)
        assert r.exit_code == 0 and "--rpm" in r.output and "more than once" not in r.output


def test_an_on_off_flag_given_twice_names_both_spellings():
    """`--x --no-x` is one option given twice; the message names both of its spellings (a toy
    command: no propmap command has an on/off pair today)."""
    from click.testing import CliRunner

    @click.command(cls=Command)
    @click.option("--tip-loss/--no-tip-loss", default=True)
    def toy(tip_loss):
        click.echo(f"{tip_loss}")

    r = CliRunner().invoke(toy, ["--tip-loss", "--no-tip-loss"])
    assert r.exit_code == 2 and f"--tip-loss/--no-tip-loss {FLAG}" in r.output


@pytest.mark.parametrize("x, decimals, text", [
    (1.23456, 4, "1.2346"), (0.0020, 4, "0.0020"), (0.0, 4, "0.0000"), (-0.0, 2, "-0.00"),
    (5.0e-5, 4, "5.000e-05"), (-5.0e-5, 4, "-5.000e-05"), (2.72e-3, 2, "2.720e-03"), (0.1, 2, "0.10"),
])
def test_fixed_keeps_two_significant_digits(x, decimals, text):
    """A nonzero value that fixed decimals would show with fewer than two digits is written in
    scientific notation; an exact zero (the drag in hover) stays fixed."""
    assert fixed(x, decimals) == text


def test_small_loads_are_printed_with_their_digits(capsys):
    """`loads cfnq_45p1 --rpm 3000` (a 45 mm propeller) printed 'power P = 0.00 W'."""
    code, out, _ = run(capsys, "loads", "cfnq_45p1", "--rpm", "3000")
    assert code == 0
    power = float(out.split("power P = ")[1].split()[0])
    _, js, _ = run(capsys, "loads", "cfnq_45p1", "--rpm", "3000", "--json")
    exact = json.loads(js)["power"]
    assert 0 < exact < 0.005 and power == pytest.approx(exact, rel=1e-3)
    assert "drag D = 0.0000 N" in out  # axial flow: exactly no H-force


def test_the_demo_refuses_an_rpm_its_hover_model_cannot_take(capsys, tmp_path):
    """`demo --rpm 1` began, then failed naming omega in rad/s, leaving an empty folder."""
    out_dir = tmp_path / "demo"
    code, out, err = run(capsys, "demo", "--rpm", "9", "--out-dir", out_dir)
    assert one_line_error(code, err, "--rpm must be finite and in [10, 954929], got 9.0"), err
    assert out == "" and not out_dir.exists()


def test_a_catalogue_propeller_without_a_calibrated_set_is_not_offered_as_its_own_spelling(capsys):
    """'cfnq_45p1' has no calibrated set; did you mean cfnq_45p1?"""
    code, _, err = run(capsys, "loads", "cfnq_45p1", "--rpm", "20000", "--params", "calibrated:cfnq_45p1")
    assert one_line_error(code, err, "the catalogue's 'cfnq_45p1' has no calibrated set"), err
    assert "did you mean" not in err and "'generic'" in err
    with pytest.raises(KeyError, match="did you mean apce_8x8"):  # a misspelling: calibrated names near it
        resolve_params("calibrated:apce_8x7")
