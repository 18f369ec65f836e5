"""A mutation audit of identify/data.py and identify/flight.py (2026-11-29): each test kills a hand-made mutant that
survived the modules' own test files, by the documented behaviour it changed."""

import pytest

from propmap.identify.data import loads_from_uiuc_files


def test_uiuc_files_must_be_given_as_a_sequence_and_a_generator_keeps_their_names(tmp_path):
    """loads_from_uiuc_files takes a sequence of paths: one path alone is a TypeError naming ``paths`` (a str was read
    one character at a time, a Path raised from inside); a generator's file names reach the source."""
    p = tmp_path / "s_9x6_static_r1.txt"
    p.write_text("RPM CT CP\n3000 0.1 0.05\n6000 0.1 0.05\n")
    for one in (str(p), p):
        with pytest.raises(TypeError, match=r"^paths must be a sequence of file paths, got .* \(give a list"):
            loads_from_uiuc_files(one, 0.2)
    data = loads_from_uiuc_files((f for f in [p]), 0.2)
    assert data.n == 2 and data.source == "UIUC-format files s_9x6_static_r1.txt"
