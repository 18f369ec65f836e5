"""UIUC-format files as a user-level audit of propellers outside the catalogue wrote them
(2026-11-30). Data: the bundled UIUC Propeller Data Site vol. 1 files of the APC 9x6E (Brandt &
Selig, AIAA 2011-1255), copied under a name the catalogue does not hold; each test fails on the
code before its change."""

import shutil

import pytest

from propmap.io.readers import looks_like_uiuc, read_uiuc_sweep

from .test_cli_hostile_maps import one_line_error, run
from .test_uiuc_names import _copies, _fit


def test_a_sweep_headed_eff_reads_as_eta(tmp_path):
    """'J CT CP eff' (another tool's name for eta) was not a UIUC-format file, and beside a good
    static run the error blamed the geometry's blade count."""
    files, geom = _copies(tmp_path)
    sweep = files[1]
    text = sweep.read_text()
    sweep.write_text(text.replace("J       CT       CP       eta", "J       CT       CP       eff", 1)
                     if "J       CT       CP       eta" in text else text.replace(" eta", " eff", 1))
    assert " eff" in sweep.read_text() and " eta" not in sweep.read_text()
    assert looks_like_uiuc(sweep)
    assert read_uiuc_sweep(sweep).J.size > 5


def test_a_geometry_headed_beta_deg_reads(tmp_path, capsys):
    """A geometry file headed 'r/R c/R beta(deg)' was refused while 'beta [deg]' read."""
    _, geom = _copies(tmp_path)
    lines = geom.read_text().splitlines()
    k = next(i for i, ln in enumerate(lines) if ln.split()[:1] == ["r/R"])
    plain = run(capsys, "loads", geom, "--diameter-in", "9", "--blades", "2", "--rpm", "5000", "--json")
    lines[k] = "r/R c/R beta(deg)"
    geom.write_text("\n".join(lines) + "\n")
    deg = run(capsys, "loads", geom, "--diameter-in", "9", "--blades", "2", "--rpm", "5000", "--json")
    assert plain[0] == deg[0] == 0 and plain[1] == deg[1], deg[2]


def test_a_file_not_in_uiucs_format_is_named_before_the_geometrys_blade_count(tmp_path, capsys):
    """One SOURCE not in UIUC's format among UIUC files: the error named the geometry's missing
    blade count first; it names the file."""
    files, geom = _copies(tmp_path)
    bad = tmp_path / "newco_9x6_rd9999_4000.txt"
    bad.write_text("J CT CP thrust\n0.1 0.1 0.05 1.0\n")
    code, _, err = run(capsys, "validate", files[0], bad, "--prop", geom)
    assert one_line_error(code, err, "SOURCE: ") and "newco_9x6_rd9999_4000.txt is not a UIUC-format" in err, err


def test_a_name_that_does_not_parse_is_said_as_the_reason_for_no_blade_count(tmp_path, capsys):
    """A browser's copy, 'NAME_RUN_RPM (1).txt', gives no blade count from the names: a note says
    which file's name did not parse before the geometry asks for --blades."""
    files, geom = _copies(tmp_path)
    copy = tmp_path / (files[1].stem + " (1).txt")
    shutil.move(files[1], copy)
    code, _, err = run(capsys, "validate", files[0], copy, "--prop", geom)
    assert code == 2
    assert f"the blade count is not taken from the UIUC data files' names: {copy.name} is not named as UIUC's are" \
        in err, err


@pytest.mark.parametrize("how", ["case", "static"])
def test_holdout_takes_a_runs_id_in_any_case_and_a_static_runs_bare_id(tmp_path, capsys, how):
    """--holdout 0702rd beside files named ..._0702RD_... was refused (only the upper case was
    taken), and so was a static run's bare id (only static_<id>)."""
    files, geom = _copies(tmp_path)
    if how == "case":
        upper = [f.with_name(f.stem.upper() + ".txt") for f in files]
        for f, u in zip(files, upper):
            shutil.move(f, u)
        files, given = upper, upper[1].name.split("_")[2].lower()  # (NEWCO_9X6_RD0988_4003: rd0988)
        held = upper[1].name.split("_")[2]
    else:
        given = files[0].stem.split("_static_")[1]
        held = f"static_{given}"
    code, err, report = _fit(capsys, tmp_path, files, geom, "--blades", "2", "--holdout", given)
    assert code == 0, err
    assert report["holdout"]["holdout"] == [held]


def test_a_size_without_its_decimal_point_is_suggested(tmp_path, capsys):
    """A geometry named 'xx_125x75_geom.txt' (12.5 x 7.5 in with the point dropped) was refused
    as a 125 in diameter, saying only to give one; the message now suggests --diameter-in 12.5."""
    _, geom = _copies(tmp_path, geom="ancf_125x75_geom.txt")
    code, _, err = run(capsys, "loads", geom, "--blades", "2", "--rpm", "5000")
    assert one_line_error(code, err, "diameter 125 in from the file name is not plausible"), err
    assert "a name may drop the decimal point (125 for 12.5 in: --diameter-in 12.5?)" in err, err
