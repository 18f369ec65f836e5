"""The user documentation's Python examples run as written.

Every fenced ```python block of README.md and docs/*.md is read from the markdown (so a new
block is picked up without touching this file) and executed, the blocks of one file in their
order in one namespace (docs/simulators.md's second block uses the first's ``rm``), in a
temporary working directory holding the files the examples name:

* ``my_geom.txt``: a UIUC geometry file (``r/R c/R beta``), the bundled DA4022 5x3.75 blade
  (UIUC vol. 2), whose 3-blade hub the examples' ``n_blades=3`` matches; read at their 9 in it
  is that blade scaled.
* ``run.csv``: a loads CSV (``rpm, airspeed, thrust, torque, group``) from the bundled UIUC
  static run and J-sweeps of that 3-blade hub (``da4022_5x3.75_3b``), converted by propmap's
  UIUC reader at the 9 in diameter (T = CT rho n^2 D^4, Q = CP rho n^2 D^5 / (2 pi), V = J n D):
  the measurements of the blade the geometry file describes, at the scale the example reads it
  (their Reynolds numbers are the 5 in runs').
* ``apce_8x6.nc``: a rotor map made by the documented command (``propmap map apce_8x6 --out
  apce_8x6.nc``) on a small grid (4 x 4 x 7 nodes), so that the test is quick.

A failing block's traceback names the markdown file and its line (``.../docs/simulators.md:286``).
The examples print or evaluate expressions whose values are not checked; a few outcomes are
(``_CHECKS``). Everything used is bundled with the package: no ``../shared`` data is needed.
The ``propmap ...`` lines of the shell blocks are not run (some take minutes or need files a
user brings), but each must name a command and options that exist.
"""

from __future__ import annotations

import csv
import math
import re
import shutil
from pathlib import Path

import numpy as np
import pytest

import propmap as pm
from propmap.core.units import RPM

REPO = Path(__file__).resolve().parents[1]
DOCS = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
PACKAGE_DATA = Path(pm.__file__).parent / "data"
#: an opening fence (CommonMark: up to 3 spaces of indent, 3 or more backticks or tildes, an info string)
_OPEN = re.compile(r"^(?P<indent> {0,3})(?P<fence>`{3,}|~{3,})(?P<info>.*)$")


def fenced_blocks(path: Path) -> list[tuple[str, int, str]]:
    """The fenced code blocks of a markdown file: (language, line of the opening fence, code).

    A block ends at a closing fence of the same character, at least as long, with nothing after
    it (or at the end of the file); the opening fence's indent is removed from its lines.
    """
    lines = path.read_text(encoding="utf-8").splitlines()
    blocks, i = [], 0
    while i < len(lines):
        m = _OPEN.match(lines[i])
        if not m or (m["fence"][0] == "`" and "`" in m["info"]):
            i += 1
            continue
        fence, indent = m["fence"], len(m["indent"])
        close = re.compile(r"^ {0,3}" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}\s*$")
        body, j = [], i + 1
        while j < len(lines) and not close.match(lines[j]):
            line = lines[j]
            body.append(line[min(indent, len(line) - len(line.lstrip(" "))):])
            j += 1
        words = m["info"].split()
        blocks.append((words[0].lower() if words else "", i + 1, "\n".join(body) + "\n"))
        i = j + 1
    return blocks


def python_blocks(path: Path) -> list[tuple[int, str]]:
    return [(line, code) for lang, line, code in fenced_blocks(path) if lang in ("python", "py")]


EXAMPLES = {p: python_blocks(p) for p in DOCS}
WITH_EXAMPLES = [p for p, blocks in EXAMPLES.items() if blocks]


def test_the_parser_finds_the_examples():
    """Guards the test below against a parser that finds nothing: the blocks known on 2026-11-29."""
    counts = {p.relative_to(REPO).as_posix(): len(b) for p, b in EXAMPLES.items() if b}
    assert counts.get("README.md", 0) >= 1 and counts.get("docs/identification.md", 0) >= 1
    assert counts.get("docs/simulators.md", 0) >= 2
    blocks = fenced_blocks(REPO / "docs" / "simulators.md")
    assert {"python", "c", ""} <= {lang for lang, _, _ in blocks}  # the C and shell blocks are read, not run
    assert all(not code.lstrip().startswith("```") for _, code in EXAMPLES[REPO / "README.md"])


def test_fence_parsing_rules(tmp_path):
    md = tmp_path / "x.md"
    md.write_text("text\n```python\na = 1\n```\n  ~~~~ Python extra\n  b = a\n   c = 2\n  ~~~~\n"
                  "````\n```python\nnot code\n````\n```py\nd = 3\n", encoding="utf-8")
    assert fenced_blocks(md) == [("python", 2, "a = 1\n"), ("python", 5, "b = a\n c = 2\n"),
                                 ("", 9, "```python\nnot code\n"), ("py", 13, "d = 3\n")]
    assert python_blocks(md) == [(2, "a = 1\n"), (5, "b = a\n c = 2\n"), (13, "d = 3\n")]


@pytest.fixture(scope="module")
def inputs(tmp_path_factory) -> Path:
    """A folder with the files the examples name (module docstring)."""
    from propmap.cli.main import main
    from propmap.identify.data import loads_from_uiuc_files

    folder = tmp_path_factory.mktemp("doc_inputs")
    shutil.copyfile(PACKAGE_DATA / "uiuc_v2" / "da4022_5x3.75_geom.txt", folder / "my_geom.txt")
    runs = sorted((PACKAGE_DATA / "uiuc_v2").glob("da4022_5x3.75_3b_*.txt"))
    assert len(runs) == 4  # its static run and three J-sweeps
    data = loads_from_uiuc_files(runs, 9 * 0.0254)
    with open(folder / "run.csv", "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f)
        out.writerow(["rpm", "airspeed", "thrust", "torque", "group"])
        for om, V, T, Q, g in zip(data.omega, data.airspeed, data.measured["thrust"], data.measured["torque"],
                                  data.group):
            out.writerow([f"{om / RPM:.8g}", f"{V:.8g}", f"{T:.8g}", f"{Q:.8g}", g])
    code = main(["map", "apce_8x6", "--rpm", "4000:10000:4", "--airspeed", "0:15:4", "--incidence-deg", "0:180:7",
                 "--check-points", "0", "--out", str(folder / "apce_8x6.nc")])
    assert code == 0 and (folder / "apce_8x6.nc").is_file()
    return folder


def _finite(*values) -> bool:
    return all(np.all(np.isfinite(np.asarray(v, dtype=float))) for v in values)


def _check_readme(ns):
    r, d, w, t, hover = ns["r"], ns["d"], ns["w"], ns["t"], ns["hover"]
    assert r.thrust.shape == (2,) and _finite(r.thrust, r.torque, r.power) and np.all(r.thrust > 0)
    assert r.thrust[1] > r.thrust[0]  # faster, more thrust
    assert d.derivative("thrust", "omega") > 0
    assert np.shape(w.force) == (3,) and _finite(w.force, w.torque)
    assert t.power > 0 and _finite(t.roll, t.pitch, t.rotor_omega) and t.pitch < 0  # flying forward: nose down
    assert hover.k_T > 0


def _check_identification(ns):
    res = ns["res"]
    assert len(ns["data"].omega) >= 6
    back = pm.read_params("p.toml")
    assert back.section_model == res.params.section_model
    for name in ("cl_alpha", "cd_min") if res.params.section_model == "cambered" else ("cl1", "cd"):
        assert math.isclose(getattr(back, name), getattr(res.params, name), rel_tol=1e-12)


def _check_simulators(ns):
    L, W = ns["L"], ns["W"]
    assert _finite(L.thrust, L.drag, L.torque, L.power) and L.thrust > 0 and L.torque > 0 and L.inside
    assert np.shape(W.force) == (1, 3) and np.shape(W.moment) == (1, 3) and _finite(W.force, W.moment)
    assert W.force[0, 2] > 0  # four rotors at 900 rad/s lift the quadrotor
    assert np.shape(ns["rm"].wrench(velocity=[8.0, 0.0, -1.0], axis=[0.0, 0.0, 1.0], omega=900.0).force) == (3,)


#: cheap checks of what a file's examples computed, by the names they use (a renamed variable
#: in an example fails here, naming it)
_CHECKS = {"README.md": _check_readme, "docs/identification.md": _check_identification,
           "docs/simulators.md": _check_simulators}


@pytest.mark.parametrize("doc", WITH_EXAMPLES, ids=lambda p: p.relative_to(REPO).as_posix())
def test_python_examples_run(doc, inputs, tmp_path, monkeypatch):
    for f in inputs.iterdir():
        shutil.copy(f, tmp_path / f.name)
    monkeypatch.chdir(tmp_path)
    name = doc.relative_to(REPO).as_posix()
    namespace = {"__name__": "__main__"}
    for line, code in EXAMPLES[doc]:
        # (padded so that a traceback gives the markdown file's own line numbers)
        exec(compile("\n" * line + code, str(doc), "exec"), namespace)  # the documentation's own code
    check = _CHECKS.get(name)
    if check is not None:
        check(namespace)


def _command_options(command) -> set[str]:
    """The option names (``--x``, ``-x``) a click command takes, its subcommands' included."""
    import click

    names = {"--help", "-h"}
    for p in command.params:
        if isinstance(p, click.Option):
            names.update(p.opts + p.secondary_opts)
    for sub in getattr(command, "commands", {}).values():
        names |= _command_options(sub)
    return names


def test_documented_command_lines_name_existing_commands_and_options():
    """Every ``propmap ...`` line of the docs' shell blocks names a command and options that exist
    (a renamed option left the docs' lines behind: found by running them, 2026-11-29)."""
    from propmap.cli.main import cli

    checked = 0
    for doc in DOCS:
        for lang, first, code in fenced_blocks(doc):
            if lang not in ("", "sh", "bash", "console", "shell"):
                continue
            for k, line in enumerate(code.splitlines()):
                words = line.split("#", 1)[0].split()
                if len(words) < 2 or words[0] != "propmap" or words[1].startswith("-"):
                    continue
                where = f"{doc.relative_to(REPO).as_posix()}:{first + 1 + k}"
                assert words[1] in cli.commands, f"{where}: no command {words[1]!r}"
                command = cli.commands[words[1]]
                if words[1] == "fit" and len(words) > 2 and words[2] in command.commands:
                    command = command.commands[words[2]]
                known = _command_options(command)
                for w in words[2:]:
                    opt = w.strip("[]|").split("=", 1)[0]
                    if re.fullmatch(r"--?[a-z][a-z0-9-]*", opt):
                        assert opt in known, f"{where}: {words[1]} has no option {opt}"
                checked += 1
    assert checked >= 40  # 45 lines on 2026-11-29, 25 of them in the README
