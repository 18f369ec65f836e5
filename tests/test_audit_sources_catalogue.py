"""A mutation audit of cli/_sources.py and io/catalogue.py (2026-11-29): each test kills a hand-made mutant that
survived the modules' own test files, by the documented behaviour it changed."""

import shutil
from importlib import resources
from pathlib import Path



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
