"""What an installed propmap ships: every data file of the source tree is named by pyproject.toml's
package-data patterns, so that a wheel carries it.

The suite runs on the editable install (``make test``), which reads the source tree, so a data file
that no pattern names would pass every other test and be missing from a wheel (the catalogue, the
calibration and the demo's data are read at run time; README.md, Data). Checked 2026-11-30 on a wheel
built from this tree: ``propmap demo`` ran from it, installed apart from the source.
"""

from __future__ import annotations

import fnmatch
import tomllib
from pathlib import Path

import propmap

PACKAGE = Path(propmap.__file__).parent
PYPROJECT = PACKAGE.parent.parent / "pyproject.toml"


def _patterns() -> list[str]:
    config = tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))
    return config["tool"]["setuptools"]["package-data"]["propmap"]


def _data_files() -> list[str]:
    """The package's files that are not Python sources or caches, relative to the package, with '/'."""
    out = []
    for path in PACKAGE.rglob("*"):
        rel = path.relative_to(PACKAGE)
        if (path.is_file() and path.suffix not in (".py", ".pyc", ".nbi", ".nbc")
                and "__pycache__" not in rel.parts and not _stray(path.name)):
            out.append(rel.as_posix())
    return sorted(out)


def _stray(name: str) -> bool:
    """A file no checkout tracks: hidden (.DS_Store), an editor's backup or swap file."""
    return name.startswith(".") or name.endswith(("~", ".swp", ".bak", ".orig"))


def _named(rel: str, patterns: list[str]) -> bool:
    # setuptools matches a pattern within its directory: "data/*.txt" does not take data/x/y.txt
    return any(rel.count("/") == p.count("/") and fnmatch.fnmatchcase(rel, p) for p in patterns)


def test_every_data_file_is_named_by_a_package_data_pattern():
    patterns = _patterns()
    files = _data_files()
    assert len(files) > 1000  # the UIUC catalogue alone has 1,122 files
    assert [f for f in files if not _named(f, patterns)] == []


def test_every_package_data_pattern_names_a_file():
    files = _data_files()
    assert [p for p in _patterns() if not any(_named(f, [p]) for f in files)] == []


def test_the_matching_is_by_directory():
    """The check's own rule: a pattern names files of its directory only, as setuptools globs it."""
    assert _named("data/uiuc_v1/a.txt", ["data/uiuc_v1/*.txt"])
    assert not _named("data/uiuc_v1/sub/a.txt", ["data/uiuc_v1/*.txt"])
    assert not _named("data/new/a.csv", ["data/*.csv"])
    assert not _named("data/a.csv", ["data/examples/*.csv"])
    assert _stray(".DS_Store") and _stray("catalogue.json~") and not _stray("calibration.json")
