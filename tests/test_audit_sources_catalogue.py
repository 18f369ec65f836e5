"""A mutation audit of cli/_sources.py and io/catalogue.py (2026-11-29): each test kills a hand-made mutant that
survived the modules' own test files, by the documented behaviour it changed."""

import shutil
from importlib import resources
from pathlib import Path

import pytest

from propmap.cli._sources import catalogue_citation

from .test_cli_hostile_maps import one_line_error, run
from .test_uiuc_names import _copies

UIUC_V1 = Path(str(resources.files("propmap") / "data" / "uiuc_v1"))
UIUC_V2 = Path(str(resources.files("propmap") / "data" / "uiuc_v2"))


def test_a_decimal_comma_in_a_name_gives_no_size_not_the_digits_after_it(tmp_path, capsys):
    """``newco_9,5x6`` gives no size (it gave 5 in, silently: from the data files' and the geometry file's names)."""
    from propmap.io.geometry_files import size_from_name

    assert size_from_name("kp_4,9x3,1")[:2] == (None, None)
    assert size_from_name("kp_4.9x3.1") == (4.9, 3.1, "in", "kp")
    files, geom = _copies(tmp_path, prop="newco_9,5x6", geom="newco_geom.txt")
    code, _, err = run(capsys, "validate", *files, "--prop", geom)
    assert one_line_error(code, err, "newco_geom.txt: diameter unknown; give the diameter (--diameter-in"), err
    assert "note: diameter" not in err
    named = tmp_path / "newco_9,5x6_geom.txt"
    shutil.copyfile(geom, named)
    code, _, err = run(capsys, "validate", *files, "--prop", named, "--blades", "2")
    assert one_line_error(code, err, "newco_9,5x6_geom.txt: diameter unknown"), err
    code, out, err = run(capsys, "validate", *files, "--prop", geom, "--diameter-in", "9.5")
    assert code == 0 and "(2 blades, D = 0.2413 m)" in out, err


def test_a_catalogue_geometry_under_the_users_data_cites_its_geometry_alone():
    """The user's own data on a catalogue geometry cite the geometry's source, not the catalogue's measurements."""
    full = catalogue_citation("apce_9x6")
    assert full.startswith("geometry: ") and "; measurements: UIUC Propeller Data Site vol. 1" in full
    alone = catalogue_citation("apce_9x6", geometry_only=True)
    assert alone == full.split("; measurements:")[0] and "measurements" not in alone
    assert catalogue_citation("newco_9x6_geom.txt") == catalogue_citation(None) == ""


@pytest.mark.parametrize("first", [True, False])
def test_a_catalogue_name_beside_files_is_refused_without_prop(tmp_path, capsys, first):
    """A catalogue name beside files is refused (give it alone), in either order and without --prop."""
    static = sorted(UIUC_V1.glob("apce_10x7_static_*.txt"))[0]
    sources = ["apce_10x7", static] if first else [static, "apce_10x7"]
    code, _, err = run(capsys, "fit", "loads", *sources, "--out", tmp_path / "p.toml")
    assert one_line_error(code, err, "'apce_10x7' is a catalogue propeller: give it alone"), err
    assert "the propeller as --prop apce_10x7" in err  # (the way to give it with files: a user audit, 2026-11-30)
    assert not (tmp_path / "p.toml").exists()
    code, _, err = run(capsys, "validate", static)  # the files alone: where the propeller goes
    assert one_line_error(code, err, "needs the propeller, as --prop NAME or --prop GEOMETRY_FILE"), err


def test_a_csv_named_as_a_uiuc_run_takes_nothing_from_its_name(tmp_path, capsys):
    """A loads CSV named like a UIUC run (``..._static_0001rd.txt``) is no UIUC file: --blades is still asked."""
    _, geom = _copies(tmp_path)
    csv = tmp_path / "newco_9x6_static_0001rd.txt"
    csv.write_text("rpm,thrust (N),torque (N m)\n" + "".join(f"{r},{1e-8 * r * r:.6g},{1e-10 * r * r:.6g}\n"
                                                             for r in range(3000, 7000, 500)))
    code, _, err = run(capsys, "validate", csv, "--prop", geom)
    assert one_line_error(code, err, "does not state the blade count"), err
    assert "from the UIUC data files' name" not in err


def _upper(files):
    """The files renamed in upper case (``NEWCO_9X6_STATIC_0...RD.TXT``)."""
    return [f.rename(f.with_name(f.name.upper())) for f in files]


def test_upper_case_uiuc_run_names_give_the_count(tmp_path, capsys):
    """A UIUC name is read in any case: upper-case run files with the geometry give 2 blades and its 9 in."""
    files, geom = _copies(tmp_path)
    code, out, err = run(capsys, "validate", *_upper(files), "--prop", geom)
    assert code == 0 and "note: 2 blades, from the UIUC data files' name (NEWCO_9X6_STATIC_" in err, err
    assert "(2 blades, D = 0.2286 m)" in out and "named for propeller" not in err, out


def test_an_upper_case_hub_suffix_gives_its_count(tmp_path, capsys):
    """A hub suffix in upper case (``_3B``) gives 3 blades, as ``_3b`` does, not UIUC's 2 of a name without one."""
    files, geom = _copies(tmp_path, prop="newco_9x6_3b")
    code, out, err = run(capsys, "validate", *_upper(files), "--prop", geom)
    assert code == 0 and "note: 3 blades, from the UIUC data files' name (NEWCO_9X6_3B_STATIC_" in err, err
    assert "its hub suffix" in err and "(3 blades, D = 0.2286 m)" in out, out


def test_a_hub_suffix_beyond_4_gives_its_count(tmp_path, capsys):
    """A hub's blade count at the end of the name is read for any single digit (``_6b``: 6 blades), not taken as 2."""
    files, geom = _copies(tmp_path, prop="newco_9x6_6b")
    code, out, err = run(capsys, "validate", *files, "--prop", geom)
    assert code == 0 and "note: 6 blades, from the UIUC data files' name" in err and "its hub suffix" in err, err
    assert "(6 blades, D = 0.2286 m)" in out, out


def test_an_upper_case_geometry_name_is_the_datas_propeller(tmp_path, capsys):
    """A geometry named ``NEWCO_9X6_GEOM.TXT`` is the propeller of ``newco_9x6_...`` runs: the count is taken."""
    files, geom = _copies(tmp_path, geom="NEWCO_9X6_GEOM.TXT")
    code, out, err = run(capsys, "validate", *files, "--prop", geom)
    assert code == 0 and "note: 2 blades, from the UIUC data files' name" in err, err
    assert "(2 blades, D = 0.2286 m)" in out and "named for propeller" not in err, out


def test_another_pitch_whose_name_begins_as_the_geometrys_takes_nothing(tmp_path, capsys):
    """Runs of ``newco_9x6.5`` are another propeller than ``newco_9x6_geom.txt``'s: --blades is still asked."""
    files, geom = _copies(tmp_path)
    files = [f.rename(f.with_name(f.name.replace("newco_9x6", "newco_9x6.5"))) for f in files]
    code, _, err = run(capsys, "validate", *files, "--prop", geom)
    assert one_line_error(code, err, "does not state the blade count"), err
    assert "from the UIUC data files' name" not in err


def test_a_catalogue_propellers_runs_without_a_suffix_and_with_its_own_count_are_one_hub(tmp_path, capsys):
    """pl_triturbo's runs (3 blades, the catalogue's, no suffix) beside ``pl_triturbo_3b_...`` are one hub."""
    static, sweep = UIUC_V2 / "pl_triturbo_static_0566rd.txt", UIUC_V2 / "pl_triturbo_0568rd_10009.txt"
    files = [tmp_path / static.name, tmp_path / sweep.name.replace("pl_triturbo_", "pl_triturbo_3b_")]
    for src, dst in zip((static, sweep), files):
        shutil.copyfile(src, dst)
    geom = tmp_path / "pl_triturbo_geom.txt"
    shutil.copyfile(UIUC_V2 / geom.name, geom)
    code, out, err = run(capsys, "validate", *files, "--prop", geom, "--blades", "3", "--diameter-in", "2.52")
    assert code == 0 and "two hubs" not in err and "named for" not in err, err
    assert "against pl_triturbo (3 blades, D = 0.06401 m)" in out, out


def test_a_geometry_named_for_its_size_takes_no_size_from_the_data(tmp_path, capsys):
    """``nr640_5_15deg_geom.txt`` names its 5 in: with its _3b runs the count (3) is taken, no diameter note."""
    files = [tmp_path / n for n in ("nr640_5_15deg_3b_static_0696md.txt", "nr640_5_15deg_3b_0697rd_4002.txt")]
    for f in (*files, tmp_path / "nr640_5_15deg_geom.txt"):
        shutil.copyfile(UIUC_V2 / f.name, f)
    code, out, err = run(capsys, "validate", *files, "--prop", tmp_path / "nr640_5_15deg_geom.txt")
    assert code == 0 and "note: 3 blades, from the UIUC data files' name" in err, err
    assert "note: diameter" not in err and "(3 blades, D = 0.127 m)" in out, err + out


def test_a_named_angle_half_a_degree_from_the_family_files_is_set(tmp_path, capsys):
    """Runs named for 15.5 deg with the NR640 design file (15.0 deg at 0.75 R): the blade is rotated by +0.50 deg."""
    src = UIUC_V2 / "nr640_5_20deg_static_1197ga.txt"
    data = tmp_path / src.name.replace("nr640_5_20deg", "zr640_5_15.5deg")
    shutil.copyfile(src, data)
    shutil.copyfile(UIUC_V2 / "nr640_geom.txt", tmp_path / "zr640_geom.txt")
    code, out, err = run(capsys, "validate", data, "--prop", tmp_path / "zr640_geom.txt")
    assert code == 0 and "note: the blade set to 15.5 deg at 0.75 R, from the UIUC data files' name" in err, err
    assert "zr640's 15.0 deg rotated by +0.50 deg at every station" in err
    assert "(2 blades, D = 0.127 m)" in out, out


@pytest.mark.parametrize("pitch, warned", [("8.5", True), ("7.5", False)])
def test_a_family_files_pitch_is_held_to_4_degrees(tmp_path, capsys, pitch, warned):
    """The 9x6E blade (16.4 deg at 0.75 R) as a family file: 9x8.5 runs (+5.5 deg) are warned of, 9x7.5 (+3.1) not."""
    files, geom = _copies(tmp_path, prop=f"newco_9x{pitch}", geom="newco_geom.txt")
    code, _, err = run(capsys, "validate", *files, "--prop", geom)
    assert code == 0, err
    said = ("is named for a P/D of 0.944 (a helix's blade angle 21.8 deg at 0.75 R), used with the family geometry "
            "newco, whose blade angle there is 16.4 deg")
    assert (said in err) == warned and ("a family file is one pitch" in err) == warned, err


def test_a_hub_named_for_fewer_blades_than_given_is_warned_of(tmp_path, capsys):
    """``_3b`` runs used with --blades 4 are warned of, the advice naming the hub's count (--blades 3)."""
    files, geom = _copies(tmp_path, prop="newco_9x6_3b")
    code, out, err = run(capsys, "validate", *files, "--prop", geom, "--blades", "4")
    assert code == 0 and "(4 blades, D = 0.2286 m)" in out, err
    assert "is named for a 3-blade hub ('_3b'), used with 4 blades: give --blades 3 if that is the hub" in err, err


def test_a_diameter_given_11_percent_off_the_names_is_warned_of(tmp_path, capsys):
    """Runs named 9 in with a family file and --diameter-in 10 (11% off; 5% allowed) are warned of, naming 9."""
    files, geom = _copies(tmp_path, geom="newco_geom.txt")
    code, out, err = run(capsys, "validate", *files, "--prop", geom, "--diameter-in", "10")
    assert code == 0 and "(2 blades, D = 0.254 m)" in out, err
    assert "is named for a 9 in propeller, used with a 10 in one (newco): give --diameter-in 9 if" in err, err
    code, out, err = run(capsys, "validate", *files, "--prop", geom, "--diameter-in", "9.4")  # (4.4%: not said)
    assert code == 0 and "named for a 9 in" not in err, err


def test_a_geometry_named_for_its_size_is_not_held_to_its_names_pitch(tmp_path, capsys):
    """mi_4x2.7's own geometry (4.6 deg under its name's helix) with its runs: no pitch warning, only family files."""
    files = [tmp_path / n for n in ("mi_4x2.7_static_0564rd.txt", "mi_4x2.7_geom.txt")]
    for f in files:
        shutil.copyfile(UIUC_V2 / f.name, f)
    code, out, err = run(capsys, "validate", files[0], "--prop", files[1])
    assert code == 0 and "(2 blades, D = 0.1016 m)" in out, err
    assert "one pitch" not in err and "named for" not in err, err


def test_a_da_series_design_is_the_helix_of_its_catalogue_pitch():
    """A DA-series design without its own geometry is the helix atan(P / (2 pi r)) of its catalogue pitch (2.65 in)."""
    import numpy as np

    from propmap.io.catalogue import get_entry, load_propeller

    assert get_entry("da4052_5x2.65").helical_pitch_in == pytest.approx(2.65)
    prop = load_propeller("da4052_5x2.65")
    P = 2.65 * 0.0254
    assert prop.pitch == pytest.approx(P)
    np.testing.assert_allclose(prop.theta, np.arctan(P / (2 * np.pi * prop.r)), rtol=1e-12)
    assert np.degrees(np.arctan(P / (2 * np.pi * 0.75 * prop.radius))) == pytest.approx(12.68, abs=0.01)


def test_a_bare_size_names_six_of_its_propellers_and_counts_them():
    """A bare size (10x7) names the catalogue's propellers of that size, at most 6, and how many there are (7)."""
    from propmap.io.catalogue import catalogue, near_names

    assert near_names("10x7", catalogue()) == ("; did you mean apce_10x7, apcsf_10x7, apcsp_10x7, grsn_10x7, "
                                              "kyosho_10x7, mae_10x7? (7 in all: 'propmap props')")
    assert near_names("8x6", catalogue()) == "; did you mean apce_8x6, apcsf_8x6, apcsp_8x6?"


def test_a_bare_size_is_matched_whole():
    """A bare size matches a name's whole size: 1x7 is no size of the 8 11x7 propellers (difflib's one close name)."""
    from propmap.io.catalogue import catalogue, near_names

    assert near_names("1x7", catalogue()) == "; did you mean ma_11x7?"
    assert near_names("1x7", catalogue(), otherwise="") == "; did you mean ma_11x7?"
    assert near_names("nosuch.csv", catalogue()) == "; run 'propmap props' for the list"
    assert near_names("nosuch.csv", catalogue(), otherwise="") == ""


def test_a_catalogue_entrys_citation_names_each_source():
    """An APC PE0 geometry cites APC; a UIUC geometry its volume; an entry's note is cited beside its geometry."""
    from propmap.io.catalogue import catalogue

    cat = catalogue()
    v1 = "UIUC Propeller Data Site vol. 1, Brandt & Selig, AIAA 2011-1255"
    v2 = "UIUC Propeller Data Site vol. 2, Deters, Ananda & Selig, AIAA 2014-2151"
    assert cat["apce_8x6"].citation == f"geometry: APC Propellers PE0 geometry (v2022-0915); measurements: {v1}"
    assert cat["apce_9x6"].citation == f"geometry: {v1}; measurements: {v1}"
    assert cat["pl_triturbo"].citation == (f"geometry: {v2} (diameter 64 mm inferred from the wind tunnel's airspeed "
                                           f"limit (tools/build_catalogue.py)); measurements: {v2}")


def test_a_missing_geometry_file_is_said_to_be_one(tmp_path):
    """A missing ``*.txt`` is said to be no file (not an unknown propeller), with the catalogue's close names."""
    from propmap.io.catalogue import resolve_propeller

    with pytest.raises(KeyError, match=r"no file 'apce_9x6\.txt', and no catalogue propeller of that name; did you "
                                       r"mean the catalogue's apce_9x6, "):
        resolve_propeller("apce_9x6.txt")


def test_a_catalogue_name_that_is_also_a_file_here_is_warned_of(tmp_path, monkeypatch):
    """A catalogue name that is also a file in the working folder: the catalogue's is used, with a warning."""
    from propmap.io.catalogue import load_propeller, resolve_propeller

    monkeypatch.chdir(tmp_path)
    (tmp_path / "apce_9x6").write_text("not a geometry\n")
    with pytest.warns(UserWarning, match=r"'apce_9x6' is a catalogue propeller and a file here: the catalogue's is "
                                         r"used \(give \./apce_9x6 for the file\)"):
        prop = resolve_propeller("apce_9x6")
    assert prop is load_propeller("apce_9x6")


def test_a_family_files_pitch_warning_points_to_the_catalogues_blade_at_that_pitch(tmp_path, capsys):
    """da4052_5x2.65 runs with the family file da4052_geom.txt: the pitch warning names --prop da4052_5x2.65."""
    names = ("da4052_5x2.65_static_1142ga.txt", "da4052_5x2.65_1144ga_3991.txt", "da4052_geom.txt")
    files = [tmp_path / n for n in names]
    for f in files:
        shutil.copyfile(UIUC_V2 / f.name, f)
    code, _, err = run(capsys, "validate", *files[:2], "--prop", files[2])
    assert code == 0 and "note: diameter 5 in, from the UIUC data files' name" in err, err
    assert "is named for a P/D of 0.53 (a helix's blade angle 12.7 deg at 0.75 R)" in err
    assert ("; the catalogue's 'da4052_5x2.65' is that blade at the named pitch (--prop da4052_5x2.65)" in err), err


def test_a_blank_propeller_is_said_to_be_empty():
    """A propeller of blanks only is said to be empty, not an unknown catalogue name."""
    from propmap.io.catalogue import resolve_propeller

    with pytest.raises(KeyError, match="the propeller is empty: give a catalogue name, a geometry file or a size"):
        resolve_propeller("  ")


def test_a_catalogue_lookup_by_a_non_string_is_a_type_error():
    """get_entry of a name that is not a str raises TypeError naming its type (not an AttributeError or KeyError)."""
    from propmap.io.catalogue import get_entry

    with pytest.raises(TypeError, match=r"name must be a catalogue propeller's name \(str\), got int"):
        get_entry(3)


def test_pole_pairs_0_with_a_catalogue_name_is_refused_not_ignored(tmp_path, capsys):
    """--pole-pairs beside a catalogue name is refused, 0 too: its UIUC data give the rpm (an option ignored)."""
    code, _, err = run(capsys, "fit", "loads", "apce_9x6", "--pole-pairs", "0", "--out", tmp_path / "p.toml")
    assert one_line_error(code, err, "--pole-pairs: applies to a thrust-stand CSV"), err
    assert not (tmp_path / "p.toml").exists()


@pytest.mark.parametrize("source, said", [("APCE_8x6", "; did you mean apce_8x6?"),
                                          ("8x6", "; did you mean apce_8x6, apcsf_8x6, apcsp_8x6?"),
                                          ("nosuch.csv", "nor a file")])
def test_a_fit_source_near_a_catalogue_name_is_suggested(tmp_path, capsys, source, said):
    """`fit loads APCE_8x6` said only 'neither a catalogue propeller nor a file', where `validate` and `loads`
    suggest apce_8x6 (the audit's report, 2026-11-29); a file name near none is said as before."""
    code, _, err = run(capsys, "fit", "loads", source, "--out", tmp_path / "p.toml")
    assert one_line_error(code, err, "is neither a catalogue propeller nor a file") and err.strip().endswith(said), err


@pytest.mark.parametrize("command", ["fit", "validate"])
def test_a_folder_as_source_is_refused_naming_its_files(tmp_path, capsys, monkeypatch, command):
    """A UIUC download's folder given as SOURCE was 'neither a catalogue propeller nor a file': now
    the message says it is a folder and how to give its files (2026-11-30)."""
    monkeypatch.chdir(tmp_path)  # (a short path: a long one is shortened in messages)
    Path("uiuc").mkdir()
    args = ["fit", "loads", "uiuc", "--prop", "apce_8x6", "--out", "p.toml"] if command == "fit" else \
        ["validate", "uiuc", "--prop", "apce_8x6"]
    code, _, err = run(capsys, *args)
    assert one_line_error(code, err, "SOURCE: 'uiuc' is a folder: give the files in it, e.g. uiuc/*.txt (UIUC-format "
                                     "files), or one CSV in it"), err
    assert not (tmp_path / "p.toml").exists()
