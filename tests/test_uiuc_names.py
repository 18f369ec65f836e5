"""A UIUC geometry file states neither its blade count nor, as a family file, its size; UIUC's
data files named for it do (``geometry_from_uiuc_names``). Data: the bundled UIUC Propeller
Data Site vol. 1 files of the APC 9x6E (Brandt & Selig, AIAA 2011-1255), copied under a name
the catalogue does not hold, so that only the names can tell."""

import json
import shutil
from importlib import resources
from pathlib import Path

import pytest

from propmap.io.geometry_files import geometry_format

from .test_cli_hostile_maps import run

UIUC_V1 = Path(str(resources.files("propmap") / "data" / "uiuc_v1"))
APC_PE0 = Path(str(resources.files("propmap") / "data" / "apc_pe0"))


def _copies(tmp_path, prop="newco_9x6", geom="newco_9x6_geom.txt"):
    """The APC 9x6E's static run and one sweep as ``prop``'s UIUC files, its geometry as ``geom``."""
    static = sorted(UIUC_V1.glob("apce_9x6_static_*.txt"))[0]
    sweep = sorted(UIUC_V1.glob("apce_9x6_rd*_*.txt"))[0]
    files = []
    for src in (static, sweep):
        dst = tmp_path / src.name.replace("apce_9x6", prop)
        shutil.copyfile(src, dst)
        files.append(dst)
    shutil.copyfile(UIUC_V1 / "apce_9x6_geom.txt", tmp_path / geom)
    return files, tmp_path / geom


def _fit(capsys, tmp_path, files, geom, *options):
    out = tmp_path / "p.toml"
    code, _, err = run(capsys, "fit", "loads", *files, "--prop", geom, *options, "--out", out)
    report = json.loads((tmp_path / "p.report.json").read_text()) if code == 0 else None
    return code, err, report


def test_the_blade_count_from_uiuc_names(tmp_path, capsys):
    """A 2-blade propeller unless the name marks a hub: fitted without --blades, said in a note;
    the same files fitted with --blades 2 give the same parameters, without the note."""
    files, geom = _copies(tmp_path)
    code, err, report = _fit(capsys, tmp_path, files, geom)
    assert code == 0, err
    assert "note: 2 blades, from the UIUC data files' name (newco_9x6_static_" in err
    assert "UIUC's names mark only the 3- and 4-blade hubs" in err and "give --blades" in err
    code2, err2, given = _fit(capsys, tmp_path, files, geom, "--blades", "2")
    assert code2 == 0 and "from the UIUC data files' name" not in err2
    assert report["coverage"]["n_blades"] == given["coverage"]["n_blades"] == 2
    assert report["fitted"] == given["fitted"]


def test_a_hub_suffix_gives_its_count(tmp_path, capsys):
    files, geom = _copies(tmp_path, prop="newco_9x6_3b")
    code, err, report = _fit(capsys, tmp_path, files, geom)
    assert code == 0 and "note: 3 blades, from the UIUC data files' name" in err and "its hub suffix" in err, err
    assert report["coverage"]["n_blades"] == 3
    assert "named for a 3-blade hub" not in err  # (the count taken is the one the check compares with)


def test_a_family_geometry_file_takes_the_size_from_the_data(tmp_path, capsys):
    """``newco_geom.txt`` names no size: the data files' 9 in, said; --diameter-in overrides."""
    files, geom = _copies(tmp_path, geom="newco_geom.txt")
    code, err, report = _fit(capsys, tmp_path, files, geom)
    assert code == 0, err
    assert "note: diameter 9 in, from the UIUC data files' name" in err
    assert report["coverage"]["diameter_m"] == pytest.approx(9 * 0.0254)
    code, err, report = _fit(capsys, tmp_path, files, geom, "--diameter-in", "9.5")
    assert code == 0 and "note: diameter" not in err
    assert report["coverage"]["diameter_m"] == pytest.approx(9.5 * 0.0254)


@pytest.mark.parametrize("case", ["another propeller", "two propellers", "not UIUC names"])
def test_nothing_is_taken_from_names_that_do_not_say_it(tmp_path, capsys, case):
    """Files named for another propeller or for two, or not named as UIUC names its runs: the
    geometry reader asks for the count, as without data."""
    files, geom = _copies(tmp_path)
    if case == "another propeller":
        files = [f.rename(f.with_name(f.name.replace("newco_9x6", "other_9x6"))) for f in files]
    elif case == "two propellers":
        files[1] = files[1].rename(files[1].with_name(files[1].name.replace("newco_9x6", "newco_10x6")))
    else:
        files = [f.rename(f.with_name(f"run{i}.txt")) for i, f in enumerate(files)]
    code, err, _ = _fit(capsys, tmp_path, files, geom)
    assert code == 2 and "does not state the blade count: give it (--blades" in err, err


def test_two_hubs_of_one_blade_are_named(tmp_path, capsys):
    """A no-suffix static run (2 blades by UIUC's names) beside _3b sweeps: without --blades it was
    refused as a geometry lacking its count, not saying that the names disagree; with --blades 3
    the 2-blade run was compared without a word (a user-level audit, 2026-11-29)."""
    files, geom = _copies(tmp_path)
    files[1] = files[1].rename(files[1].with_name(files[1].name.replace("newco_9x6", "newco_9x6_3b")))
    code, err, _ = _fit(capsys, tmp_path, files, geom)
    assert code == 2 and "does not state the blade count" not in err, err
    assert ("the UIUC data files' names give two hubs of one blade, newco_9x6_static_" in err
            and "(no suffix: 2 blades) and newco_9x6_3b_" in err and "(_3b)" in err and "--blades" in err)
    code, err, _ = _fit(capsys, tmp_path, files, geom, "--blades", "3")
    assert code == 0 and "two hubs of one blade" in err and "every file is taken with 3 blades" in err, err
    # (one hub's files alone: no word of a mix)
    code, err, _ = _fit(capsys, tmp_path, [files[0]], geom, "--blades", "2")
    assert code == 0 and "two hubs" not in err, err


def test_a_csv_takes_nothing_from_names(tmp_path, capsys):
    """A loads CSV names no propeller, whatever its file name."""
    _, geom = _copies(tmp_path)
    csv = tmp_path / "newco_9x6_static_0001rd.csv"
    csv.write_text("rpm,thrust (N),torque (N m)\n" + "".join(f"{r},{1e-8 * r * r:.6g},{1e-10 * r * r:.6g}\n"
                                                             for r in range(3000, 7000, 500)))
    code, _, err = run(capsys, "fit", "loads", csv, "--prop", geom, "--out", tmp_path / "c.toml")
    assert code == 2 and "does not state the blade count" in err, err


def test_geometry_format(tmp_path):
    _, geom = _copies(tmp_path)
    assert geometry_format(geom) == "uiuc"
    assert geometry_format(APC_PE0 / "9x6-PERF.PE0") == "pe0"  # (it states its count: nothing is taken for it)
    (tmp_path / "x.txt").write_text("radius chord\n0.5 0.1\n")
    assert geometry_format(tmp_path / "x.txt") is None
    assert geometry_format(tmp_path / "missing.txt") is None
    assert geometry_format(tmp_path) is None  # a directory
    assert geometry_format(3) is None


def test_an_implausible_size_from_the_names_is_not_taken(tmp_path, capsys):
    """A size the geometry reader would refuse from its own name ([0.5, 100] in: ``newco_130x70``,
    millimetres of a family not known to give them) is not taken from the data's names either: it
    was, and the fit was refused as '--diameter-in must be ... in [0.5, 100] in, got 130.0', an
    option never given (a user-level audit, 2026-11-29)."""
    files, geom = _copies(tmp_path, prop="newco_130x70", geom="newco_geom.txt")
    code, err, _ = _fit(capsys, tmp_path, files, geom)
    assert code == 2 and "--diameter-in must be" not in err, err
    assert "gives a diameter of 130 in, outside the [0.5, 100] in taken from a name" in err
    assert "diameter unknown" in err


def test_a_family_file_of_another_pitch_is_warned_of(tmp_path, capsys):
    """A family geometry file is one blade at one pitch: data named for another pitch of the family
    (``newco_9x3`` with the 9x6's blade as ``newco_geom.txt``; UIUC vol. 2's ``da4052_5x2.65`` with
    ``da4052_geom.txt``, the design at a 0.75 P/D) were fitted with the file's blade angles and only
    the size taken from the names, without a word (da4052_5x1.58: refused as 0.285 times the torque;
    a user-level audit, 2026-11-29). The pitch the names give is compared at 0.75 R."""
    files, geom = _copies(tmp_path, prop="newco_9x3", geom="newco_geom.txt")
    code, err, _ = _fit(capsys, tmp_path, files, geom)
    assert code == 0 and "is named for a P/D of 0.333" in err and "a family file is one pitch" in err, err
    assert "check that the geometry is the propeller measured" in err
    assert err.count("a family file is one pitch") == 1
    same = tmp_path / "same"
    same.mkdir()
    files, geom = _copies(same, prop="newco_9x6", geom="newco_geom.txt")  # (its own pitch: nothing said)
    code, err, _ = _fit(capsys, same, files, geom)
    assert code == 0 and "one pitch" not in err, err


@pytest.mark.parametrize("name", ["newco_9x6.txt", "newco_9x6.dat", "NEWCO_9x6_geom.TXT"])
def test_a_geometry_named_without_geom_txt_is_the_same_propeller(tmp_path, capsys, name):
    """A geometry file named ``newco_9x6.txt`` (the reader names it by the whole file name) was
    taken as the data's propeller for the blade count and, in the same run, warned of as 'named for
    propeller 'newco_9x6', used with --prop 'newco_9x6.txt'' (a user-level audit, 2026-11-29)."""
    files, geom = _copies(tmp_path, geom=name)
    code, err, _ = _fit(capsys, tmp_path, files, geom)
    assert code == 0 and "note: 2 blades, from the UIUC data files' name" in err, err
    assert "named for propeller" not in err, err


UIUC_V2 = Path(str(resources.files("propmap") / "data" / "uiuc_v2"))


def test_a_catalogue_propellers_own_count_and_a_millimetre_family(tmp_path, capsys):
    """UIUC vol. 2's Plantraco files (Deters, Ananda & Selig, AIAA 2014-2151) with a family file
    (``pl_geom.txt``, a copy of pl_100x80's blade): the count is the catalogue's for the named
    propeller, the diameter 100 mm from the name of a millimetre family; and pl_triturbo's own
    files give its 3 blades, which UIUC's names do not mark."""
    files = [tmp_path / name for name in ("pl_100x80_static_0581rd.txt", "pl_100x80_0583rd_6039.txt")]
    for f in files:
        shutil.copyfile(UIUC_V2 / f.name, f)
    shutil.copyfile(UIUC_V2 / "pl_100x80_geom.txt", tmp_path / "pl_geom.txt")
    code, err, report = _fit(capsys, tmp_path, files, tmp_path / "pl_geom.txt")
    assert code == 0, err
    assert "note: 2 blades, from the UIUC data files' name (pl_100x80_static_0581rd.txt: the catalogue's count" in err
    assert "note: diameter 3.937 in = 100 mm, from the UIUC data files' name" in err
    assert report["coverage"]["diameter_m"] == pytest.approx(0.100)
    tri = sorted(UIUC_V2.glob("pl_triturbo_*.txt"))[:2]
    shutil.copyfile(UIUC_V2 / "pl_triturbo_geom.txt", tmp_path / "pl_triturbo_geom.txt")
    code, out, err = run(capsys, "validate", *tri, "--prop", tmp_path / "pl_triturbo_geom.txt", "--diameter-in", "2.52")
    assert code == 0 and "note: 3 blades, from the UIUC data files' name" in err and "catalogue's count" in err, err
    assert "against pl_triturbo (3 blades, D = 0.06401 m)" in out, out
    # without --diameter-in, the catalogue's (the names give none; "diameter unknown" until 2026-11-29)
    code, out, err = run(capsys, "validate", *tri, "--prop", tmp_path / "pl_triturbo_geom.txt")
    assert code == 0 and "note: diameter 2.52 in = 64 mm, the catalogue's for pl_triturbo (the names give none; " \
        "diameter 64 mm inferred from the wind tunnel's airspeed limit)" in err, err
    assert "against pl_triturbo (3 blades, D = 0.064 m)" in out, out
    # its blades on another hub (named pl_triturbo_4b_...): the same blade's diameter ("diameter unknown" until a
    # review, 2026-11-29), the count from the hub suffix
    hub4 = []
    for f in tri:
        hub4.append(tmp_path / Path(f).name.replace("pl_triturbo_", "pl_triturbo_4b_"))
        shutil.copyfile(f, hub4[-1])
    code, out, err = run(capsys, "validate", *hub4, "--prop", tmp_path / "pl_triturbo_geom.txt")
    assert code == 0, err
    assert "note: diameter 2.52 in = 64 mm, the catalogue's for pl_triturbo (the names give none" in err, err
    assert "note: 4 blades, from the UIUC data files' name" in err
    assert "against pl_triturbo (4 blades, D = 0.064 m)" in out


def test_validate_takes_the_same_and_a_given_count_is_kept(tmp_path, capsys):
    """``validate SOURCE... --prop GEOM`` reads the names as ``fit loads`` does; --blades given
    with a family file: only the diameter is taken."""
    files, geom = _copies(tmp_path)
    code, out, err = run(capsys, "validate", *files, "--prop", geom)
    assert code == 0 and "note: 2 blades, from the UIUC data files' name" in err, err
    assert "(2 blades, D = 0.2286 m)" in out, out
    family = tmp_path / "newco_geom.txt"
    shutil.copyfile(geom, family)
    code, out, err = run(capsys, "validate", *files, "--prop", family, "--blades", "3")
    assert code == 0 and "blades, from" not in err and "note: diameter 9 in, from the UIUC data files' name" in err
    assert "(3 blades, D = 0.2286 m)" in out, out


def test_no_advice_to_give_a_size_the_cli_refuses(tmp_path, capsys):
    """Data named ``newco_130x70`` (millimetres of a family not known to give them) with a family
    file and --diameter-in 5.1: the size comparison read the name as 130 in and advised 'give
    --diameter-in 130', which the CLI refuses (a review, 2026-11-29); a name's size outside
    [0.5, 100] in is no size, as for the geometry reader."""
    files, geom = _copies(tmp_path, prop="newco_130x70", geom="newco_geom.txt")
    code, err, report = _fit(capsys, tmp_path, files, geom, "--diameter-in", "5.1", "--blades", "2")
    assert code == 0 and "--diameter-in 130" not in err and "named for a 130 in" not in err, err
    assert report["coverage"]["diameter_m"] == pytest.approx(5.1 * 0.0254)


def test_nr640_names_give_the_diameter_and_the_blade_angle(tmp_path, capsys):
    """UIUC vol. 2 names its NR640 runs ``nr640_<D>_<angle>deg`` (the diameter in inches, the blade
    set to that angle at 0.75 R; Deters, Ananda & Selig, AIAA 2014-2151). Renamed out of the
    catalogue (zr640) with the NR640 design file (nr640_geom.txt) as a family file: the size is taken
    from the names; data at 20 deg set the blade to 20 deg, the file's being at 15 deg there (warned
    of until 2026-11-29), as the catalogue's nr640_9_20deg is. (The catalogue's nr640_5_20deg is the
    5 in blade measured at 15 deg, turned by the same 5 deg, since 2026-11-29: it predicts these runs
    blind to 3.87% of their rms CT, the design file 12.94%.)"""
    from propmap.io.geometry_files import blade_angle_from_name, name_without_blade_angle, size_from_name

    assert size_from_name("nr640_9_15deg_3b") == (9.0, None, "in", "nr640")
    assert blade_angle_from_name("nr640_5_20deg_geom") == 20.0 and blade_angle_from_name("apce_10x7") is None
    assert [name_without_blade_angle(n) for n in ("nr640_5_20deg", "NR640_9_15.5DEG_geom", "apce_10x7", "x_5_20deg9")] \
        == ["nr640_5", "NR640_9_geom", "apce_10x7", "x_5_20deg9"]
    shutil.copyfile(UIUC_V2 / "nr640_geom.txt", tmp_path / "zr640_geom.txt")  # (the design: 15.0 deg at 0.75 R)
    for angle in ("15", "20"):
        runs = [f for f in sorted(UIUC_V2.glob(f"nr640_5_{angle}deg_*.txt")) if "_geom" not in f.name][:2]
        files = [tmp_path / f.name.replace("nr640", "zr640") for f in runs]
        for src, dst in zip(runs, files):
            shutil.copyfile(src, dst)
        code, out, err = run(capsys, "validate", *files, "--prop", tmp_path / "zr640_geom.txt", "--params", "generic")
        assert code == 0 and "note: diameter 5 in, from the UIUC data files' name" in err, err
        assert "(2 blades, D = 0.127 m)" in out, out
        rotated = ("note: the blade set to 20 deg at 0.75 R, from the UIUC data files' name (zr640_5_20deg_" in err
                   and "zr640's 15.0 deg rotated by +5.00 deg at every station" in err)
        assert rotated == (angle == "20") and "is named for a blade angle" not in err, err
        if angle == "20":
            (row,) = [line.split() for line in out.splitlines() if line.startswith("all points")]
            assert row[2:4] == ["12.94%", "-12.54%"], row  # (regression values, the bundled data and generic set)


def test_apc_pe0_geometry_with_uiuc_data_of_that_propeller(tmp_path, capsys):
    """APC names its PE0 files 8x6E-PERF.PE0 where UIUC names the same propeller apce_8x6: the data
    were warned of as 'named for another propeller' (2026-11-29); the sport 8x6 is another one. The
    rule reproduces every pair of the catalogue's (UIUC data with APC PE0 geometry)."""
    from propmap.cli._sources import _apc_designation
    from propmap.io.catalogue import catalogue

    pairs = {n: Path(e.geometry_file).name for n, e in catalogue().items() if e.geometry_format != "uiuc"}
    assert len(pairs) >= 29
    for name, pe0 in pairs.items():
        assert _apc_designation(name) == pe0.lower().replace("-perf.pe0", ""), name
    assert _apc_designation("apce_9x7.5") == "9x75e" and _apc_designation("mi_4x2.7") is None
    static = sorted(UIUC_V1.glob("apce_8x6_static_*.txt"))[:1]
    shutil.copyfile(APC_PE0 / "8x6E-PERF.PE0", tmp_path / "8x6E.PE0")  # (renamed, as a user may)
    for geometry in (APC_PE0 / "8x6E-PERF.PE0", tmp_path / "8x6E.PE0"):
        code, out, err = run(capsys, "validate", *static, "--prop", geometry)
        assert code == 0 and "named for propeller" not in err, err
    code, out, err = run(capsys, "validate", *static, "--prop", APC_PE0 / "8x6-PERF.PE0")  # (APC's sport 8x6)
    assert code == 0 and "is named for propeller 'apce_8x6', used with --prop '8x6'" in err, err


def test_a_measured_blade_named_for_its_setting_is_set_by_the_names_difference(tmp_path, capsys):
    """The NR640 5 in blades are measured at their 15 deg setting (nr640_5_15deg_geom.txt, 16.6 deg
    at 0.75 R: its own datum) and run at 20 deg too (UIUC vol. 2, Deters, Ananda & Selig, AIAA
    2014-2151). Renamed out of the catalogue (zr640), the 20 deg runs with the 15 deg geometry: the
    blade rotated by the names' +5 deg (they were 'named for another propeller' and refused for the
    blade count until 2026-11-29). Blind (generic set): CT rms 2.50% of static CT rotated (the design
    file set to 20 deg: 6.9%; unrotated: 27.9%), line for line the catalogue's nr640_5_20deg, which is
    this blade turned by 5 deg since 2026-11-29. Runs of two settings: taken as the file is, and
    warned of."""
    shutil.copyfile(UIUC_V2 / "nr640_5_15deg_geom.txt", tmp_path / "zr640_5_15deg_geom.txt")
    runs = [f for f in sorted(UIUC_V2.glob("nr640_5_20deg_*.txt"))]
    files = [tmp_path / f.name.replace("nr640", "zr640") for f in runs]
    for src, dst in zip(runs, files):
        shutil.copyfile(src, dst)
    geom = tmp_path / "zr640_5_15deg_geom.txt"
    code, out, err = run(capsys, "validate", *files, "--prop", geom, "--params", "generic")
    assert code == 0, err
    assert ("note: the blade set to 20 deg at 0.75 R, from the UIUC data files' name (zr640_5_20deg_" in err
            and "zr640_5_15deg, set to 15 deg, rotated by +5.00 deg at every station" in err)
    assert "named for" not in err and "note: 2 blades" in err
    (row,) = [line.split() for line in out.splitlines() if line.startswith("all points")]
    assert row[2:4] == ["2.50%", "+1.17%"], row  # (regression values, the bundled data and the generic set)
    code, catalogued, _ = run(capsys, "validate", *runs, "--prop", "nr640_5_20deg", "--params", "generic")
    assert code == 0 and [line for line in catalogued.splitlines() if line.startswith("all points")] == [
        line for line in out.splitlines() if line.startswith("all points")]
    static15 = tmp_path / "zr640_5_15deg_static_0650rb.txt"
    shutil.copyfile(UIUC_V2 / "nr640_5_15deg_static_0650rb.txt", static15)
    code, out, err = run(capsys, "validate", *files, static15, "--prop", geom, "--params", "generic", "--blades", "2")
    assert code == 0 and "rotated" not in err, err
    assert "is named for the blades set to 20 deg at 0.75 R, used with the geometry zr640_5_15deg as it is" in err
    assert "give the runs of one setting" in err
    # a catalogue PROP is taken as it is: the catalogue's blade at the runs' setting is named
    code, out, err = run(capsys, "validate", *runs, "--prop", "nr640_5_15deg")
    assert code == 0 and "--prop nr640_5_20deg is the catalogue's blade at that setting" in err, err


def test_a_geometry_named_for_its_setting_without_geom(tmp_path, capsys):
    """A geometry file named for a setting without ``_geom`` (zr640_5_15deg.txt), as a UIUC file
    named mi_4x2.7.txt gives its size: its reader took no size from the name ('diameter unknown',
    the setting's runs refused; a review, 2026-11-29); the blade is set as from
    zr640_5_15deg_geom.txt, the same errors."""
    from propmap.io.geometry_files import blade_angle_from_name, size_from_name

    assert size_from_name("nr640_5_15deg.txt") == (5.0, None, "in", "nr640")
    assert blade_angle_from_name("nr640_5_15deg.txt") == 15.0
    shutil.copyfile(UIUC_V2 / "nr640_5_15deg_geom.txt", tmp_path / "zr640_5_15deg.txt")
    runs = sorted(UIUC_V2.glob("nr640_5_20deg_*.txt"))
    files = [tmp_path / f.name.replace("nr640", "zr640") for f in runs]
    for src, dst in zip(runs, files):
        shutil.copyfile(src, dst)
    code, out, err = run(capsys, "validate", *files, "--prop", tmp_path / "zr640_5_15deg.txt", "--params", "generic")
    assert code == 0 and "diameter unknown" not in err, err
    assert "set to 15 deg, rotated by +5.00 deg at every station" in err and "named for" not in err, err
    assert "(2 blades, D = 0.127 m)" in out, out
    (row,) = [line.split() for line in out.splitlines() if line.startswith("all points")]
    assert row[2:4] == ["2.50%", "+1.17%"], row


def test_a_named_angle_beyond_the_blade_angle_range_is_refused_naming_it(tmp_path, capsys):
    """Runs named for 80 deg with the NR640 design file (32.1 deg at r/R = 0.3, 15 deg at 0.75 R):
    the blade rotated by +65 deg passes 90 deg at the root; the error was the Propeller's bare
    'theta must be in [-90, 90] deg at every station', naming neither the file nor the angle."""
    shutil.copyfile(UIUC_V2 / "nr640_geom.txt", tmp_path / "zr640_geom.txt")
    runs = sorted(UIUC_V2.glob("nr640_5_20deg_*.txt"))
    files = [tmp_path / f.name.replace("nr640_5_20deg", "zr640_5_80deg") for f in runs]
    for src, dst in zip(runs, files):
        shutil.copyfile(src, dst)
    code, out, err = run(capsys, "validate", *files, "--prop", tmp_path / "zr640_geom.txt")
    assert code == 2 and "Traceback" not in err, err
    assert "error: SOURCE: zr640_5_80deg_" in err and "set to 80 deg at 0.75 R: zr640 rotated by +65.00 deg" in err, err
    assert "theta must be in [-90, 90] deg" in err.strip().splitlines()[-1], err


def _fit_nr640_20deg_with_the_family_file(tmp_path, capsys):
    """(the geometry, exit code, stderr) of `fit loads` on three of UIUC's nr640_5_20deg runs renamed zr640, with
    the NR640 design file as a family file (the blade set to 20 deg from the names), written to tmp_path/p.toml."""
    geom = tmp_path / "zr640_geom.txt"
    shutil.copyfile(UIUC_V2 / "nr640_geom.txt", geom)
    runs = [f for f in sorted(UIUC_V2.glob("nr640_5_20deg_*.txt"))][:3]
    files = [tmp_path / f.name.replace("nr640", "zr640") for f in runs]
    for src, dst in zip(runs, files):
        shutil.copyfile(src, dst)
    code, err, _ = _fit(capsys, tmp_path, files, geom)
    return geom, code, err


def test_a_fit_records_the_blade_angle_it_was_fitted_with(tmp_path, capsys):
    """A fit of UIUC's nr640_5_20deg runs (renamed zr640) with the family file sets the blade to 20 deg
    from their names; the parameter file records it ([coverage] theta75_deg), and running the family
    file's 15 deg blade with it is warned of, naming the +5 deg that sets it as fitted (it ran without
    a word, 13% less thrust: a review, 2026-11-29); with that collective nothing is said. The
    catalogue's nr640_5_20deg, the measured 5 in blade turned to its 20 deg setting, is 21.6 deg at
    0.75 R in that blade's own angle datum (16.6 deg at the 15 deg setting): warned of, -1.6 deg."""
    from propmap.io.params_file import read_coverage

    geom, code, err = _fit_nr640_20deg_with_the_family_file(tmp_path, capsys)
    assert code == 0 and "rotated by +5.00 deg" in err, err
    assert read_coverage(tmp_path / "p.toml")["theta75_deg"] == pytest.approx(20.0, abs=1e-9)
    base = ["loads", geom, "--diameter-in", "5", "--blades", "2", "--params", tmp_path / "p.toml", "--rpm", "6000"]
    code, _, err = run(capsys, *base)
    assert code == 0 and ("zr640 runs with p.toml, fitted to the blade set at 20.0 deg at 0.75 R; this one is at "
                          "15.0 deg there: if it is the same blade, +5.0 deg of collective sets it as fitted "
                          "(--collective-deg of loads and map)") in err
    code, _, err = run(capsys, *base, "--collective-deg", "5")
    assert code == 0 and "fitted to the blade set at" not in err, err
    code, _, err = run(capsys, "loads", "nr640_5_20deg", "--params", tmp_path / "p.toml", "--rpm", "6000")
    assert code == 0 and ("fitted to the blade set at 20.0 deg at 0.75 R; this one is at 21.6 deg there: if it is the "
                          "same blade, -1.6 deg of collective sets it as fitted") in err, err


def test_an_upper_case_static_run_is_labelled_by_its_run_id(tmp_path):
    """``NR640_5_20DEG_STATIC_1197GA.TXT`` (a UIUC name in upper case) is static run 1197GA: its id
    was the whole stem, the run labelled static_NR640_5_20DEG_STATIC_1197GA (a review, 2026-11-29)."""
    from propmap.io.readers import read_uiuc_static

    upper = tmp_path / "NR640_5_20DEG_STATIC_1197GA.TXT"
    shutil.copyfile(UIUC_V2 / "nr640_5_20deg_static_1197ga.txt", upper)
    assert read_uiuc_static(upper).run_id == "1197GA"
    assert read_uiuc_static(UIUC_V2 / "nr640_5_20deg_static_1197ga.txt").run_id == "1197ga"


def test_a_set_fitted_on_one_hub_run_on_another_is_told_what_hubs_measured(tmp_path, capsys):
    """A set fitted to the 2-blade DA4022 5x3.75's UIUC data, run on its 3-blade hub's data, was
    warned of as carrying to another propeller no better than the generic set; it predicts them to
    2.45% of static CT, the generic set 12.77% (regression values, bundled UIUC vol. 2 data; a review,
    2026-11-29). Now the warning gives the hubs' measured range."""
    geom = tmp_path / "da4022_5x3.75_geom.txt"
    shutil.copyfile(UIUC_V2 / "da4022_5x3.75_geom.txt", geom)
    two = [UIUC_V2 / "da4022_5x3.75_static_0642rb.txt", *sorted(UIUC_V2.glob("da4022_5x3.75_064[4-7]rb_*.txt"))]
    code, err, _ = _fit(capsys, tmp_path, two, geom)
    assert code == 0, err
    three = sorted(UIUC_V2.glob("da4022_5x3.75_3b_*.txt"))
    code, out, err = run(capsys, "validate", *three, "--prop", geom, "--params", tmp_path / "p.toml")
    assert code == 0 and "runs with p.toml, fitted to data of da4022_5x3.75 on 2 blades: if it is the same blade" in err
    assert "do not carry to another one reliably" not in err, err
    (row,) = [line.split() for line in out.splitlines() if line.startswith("all points")]
    assert row[2] == "2.45%", row


def test_a_points_files_collective_column_counts_in_the_blade_angle_check(tmp_path, capsys):
    """`loads GEOM --points P.csv` with a collective_deg column: the fitted blade's angle is checked against
    the rows' collectives, not 0 deg (the 15 deg design blade with rows at +5 deg, which set it as the fitted
    20 deg blade, was warned of: noticed 2026-11-29). Rows that never reach it are warned of, naming the
    column's span and the row nearest."""
    geom, code, err = _fit_nr640_20deg_with_the_family_file(tmp_path, capsys)
    assert code == 0, err
    base = ["loads", geom, "--diameter-in", "5", "--blades", "2", "--params", tmp_path / "p.toml"]
    for column, said in (([5.0, 5.0], None), ([-2.0, 8.0], None), ([0.0, 2.0], "2 deg (the column spans 0 to 2 deg)")):
        pts = tmp_path / "pts.csv"
        pts.write_text("rpm,airspeed,incidence_deg,collective_deg\n"
                       + "".join(f"6000,0,0,{c:g}\n" for c in column), encoding="utf-8")
        code, _, err = run(capsys, *base, "--points", pts, "--out", tmp_path / "out.csv")
        assert code == 0, err
        if said is None:
            assert "fitted to the blade set at" not in err, (column, err)
        else:
            assert ("fitted to the blade set at 20.0 deg at 0.75 R; this one is at 17.0 deg there with the points' "
                    f"collective_deg column's {said}: if it is the same blade, +3.0 deg") in err, err
