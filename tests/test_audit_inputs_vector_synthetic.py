"""A mutation audit of io/inputs, io/toml_file, io/provenance, identify/synthetic and core/vector
(stop 87, 2026-11-30, a helper session: 53 mutants, 21 surviving the suite, 14 of them changing
what a user sees; each test below fails on its mutant, three re-checked by hand):

- reading input files: the Latin-1 fallback of legacy files, a file of exactly the size limit
  read, UTF-32 text named as such, a 1 MiB limit said in MiB, a file name with a newline quoted
  in a TOML error's one line;
- the source digest leaves out __pycache__ and numba's cache files (they come and go);
- simulate_level_flight refuses a 2-d airspeed and names the condition it cannot trim;
- rotor_wrench: a spin other than +-1 or of another shape refused, spin words case-blind in a
  list, exactly 500 m/s accepted ("at most"), a huge velocity refused with its own magnitude, and
  the lateral slope dF_y/dV_y = -D / V_s (the loads depend on |V| and beta only) at a small
  in-plane speed.
"""

from __future__ import annotations

import codecs
import hashlib
import sys

import numpy as np
import pytest

from propmap.io import provenance
from propmap.io.inputs import decode_input_text, read_input_bytes
from propmap.io.toml_file import load_toml


class Err(ValueError):
    pass


# ---- io/inputs.py -------------------------------------------------------------------------------
def test_latin1_fallback_decodes_legacy_bytes():
    # 0xE9 is 'é' in Latin-1 and no valid UTF-8 by itself
    assert decode_input_text(b"caf\xe9 10x7\n", "x.dat", Err, latin1=True) == "caf\u00e9 10x7\n"
    with pytest.raises(Err, match="not UTF-8"):
        decode_input_text(b"caf\xe9 10x7\n", "x.dat", Err)


def test_a_file_of_exactly_the_limit_is_read(tmp_path):
    p = tmp_path / "f.csv"
    p.write_bytes(b"x" * 10)
    assert read_input_bytes(p, Err, limit=10) == b"x" * 10
    with pytest.raises(Err, match="larger than"):
        read_input_bytes(p, Err, limit=9)


def test_utf32_text_is_named_utf32_not_utf16():
    for bom, enc in ((codecs.BOM_UTF32_LE, "utf-32-le"), (codecs.BOM_UTF32_BE, "utf-32-be")):
        with pytest.raises(Err, match="UTF-32 text; save it as UTF-8"):
            decode_input_text(bom + "a,b\n".encode(enc), "x.csv", Err)


def test_the_limit_of_one_mib_is_said_in_mib(tmp_path):
    p = tmp_path / "big.txt"
    p.write_bytes(b"x" * (2**20 + 1))
    with pytest.raises(Err) as exc:
        read_input_bytes(p, Err, limit=2**20)
    assert "is larger than 1 MiB, the limit" in str(exc.value), str(exc.value)


# ---- io/toml_file.py ----------------------------------------------------------------------------
@pytest.mark.skipif(sys.platform == "win32", reason="a file name with a newline: POSIX only")
def test_a_toml_name_with_a_newline_is_quoted_in_the_message(tmp_path):
    p = tmp_path / "bad\nname.toml"
    p.write_text("x = \n")
    with pytest.raises(Err) as exc:
        load_toml(p, Err)
    msg = str(exc.value)
    assert "\n" not in msg and repr(str(p)) in msg, msg


# ---- io/provenance.py ---------------------------------------------------------------------------
def _tree_digest(root):
    """The documented rule, computed independently: sorted relative posix paths, length-prefixed path and bytes."""
    h = hashlib.sha256()
    for rel in sorted(p.relative_to(root).as_posix() for p in root.rglob("*") if p.is_file()):
        data = (root / rel).read_bytes()
        h.update(len(rel.encode()).to_bytes(8, "little") + rel.encode() + len(data).to_bytes(8, "little") + data)
    return h.hexdigest()


@pytest.fixture
def fake_package(tmp_path, monkeypatch):
    root = tmp_path / "pkg"
    (root / "io").mkdir(parents=True)
    (root / "a.py").write_text("x = 1\n")
    (root / "io" / "provenance.py").write_text("# stand-in\n")
    monkeypatch.setattr(provenance, "__file__", str(root / "io" / "provenance.py"))
    return root


def test_pycache_folders_do_not_enter_the_digest(fake_package, tmp_path):
    expected = _tree_digest(fake_package)
    assert provenance.source_digest.__wrapped__() == expected
    cache = fake_package / "__pycache__"
    cache.mkdir()
    (cache / "a.cpython-311.pyc.140234").write_bytes(b"\x00partial")  # importlib's temporary name
    (cache / "index.json").write_text("{}")
    assert provenance.source_digest.__wrapped__() == expected


def test_numba_cache_files_do_not_enter_the_digest(fake_package):
    expected = _tree_digest(fake_package)
    (fake_package / "io" / "kern.f-33.py311.nbi").write_bytes(b"index")
    (fake_package / "io" / "kern.f-33.py311.1.nbc").write_bytes(b"code")
    assert provenance.source_digest.__wrapped__() == expected


# ---- identify/synthetic.py ----------------------------------------------------------------------
@pytest.fixture(scope="module")
def quad():
    from importlib import resources

    from propmap.identify import read_vehicle
    return read_vehicle(str(resources.files("propmap") / "data/examples/quadrotor.toml"))


def test_simulate_refuses_a_two_dimensional_airspeed(quad):
    import propmap as pm
    from propmap.identify import simulate_level_flight
    with pytest.raises(ValueError, match=r"must be numbers of one shape \(N,\).*shapes \(1, 2\) and \(2,\)"):
        simulate_level_flight(quad, pm.preset("gill2017-apc"), [[5.0, 6.0]], [-2.0, -3.0])


def test_an_untrimmable_condition_is_named_by_its_index(quad):
    import propmap as pm
    from propmap.identify import simulate_level_flight
    # a bracket of 1 rad/s far below hover's rate trims nothing: the first condition is named
    with pytest.raises(ValueError, match=r"trims condition 0 \(V=3 m/s, pitch=-2 deg\)"):
        simulate_level_flight(quad, pm.preset("gill2017-apc"), [3.0, 4.0], [-2.0, -3.0], omega_bounds=(10.0, 11.0))


# ---- core/vector.py -----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def rotor():
    import propmap as pm
    return pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")


@pytest.mark.parametrize("spin", [2, 0.5, 0, [1.0, 2.0]])
def test_a_spin_other_than_plus_or_minus_one_is_refused(rotor, spin):
    from propmap.core.vector import rotor_wrench
    V = [3.0, 0.0, 1.0] if np.ndim(spin) == 0 else [[3.0, 0.0, 1.0], [0.0, 2.0, 1.0]]
    with pytest.raises(ValueError, match="spin must be 'ccw', 'cw', \\+1 or -1"):
        rotor_wrench(*rotor, V, [0.0, 0.0, 1.0], 600.0, spin=spin)


def test_a_spin_array_of_another_shape_is_refused_by_name(rotor):
    from propmap.core.vector import rotor_wrench
    V = [[3.0, 0.0, 1.0], [0.0, 2.0, 1.0]]
    for spin in ([1.0, -1.0, 1.0], [[1.0, -1.0]]):
        with pytest.raises(ValueError, match=r"spin of shape .* does not broadcast to the shape \(2,\) of the loads"):
            rotor_wrench(*rotor, V, [0.0, 0.0, 1.0], 600.0, spin=spin)


@pytest.mark.filterwarnings("ignore:a blade tip meets the air")  # (Mach 1.5 at 500 m/s: refused or not is the point)
def test_a_speed_of_exactly_the_airspeed_limit_is_accepted(rotor):
    from propmap.core.solver import AIRSPEED_MAX
    from propmap.core.vector import rotor_wrench
    w = rotor_wrench(*rotor, [[0.0, 0.0, AIRSPEED_MAX]], [0.0, 0.0, 1.0], 600.0)  # "at most 500 m/s"
    assert np.all(np.isfinite(w.force))
    with pytest.raises(ValueError, match="at most 500 m/s"):
        rotor_wrench(*rotor, [[0.0, 0.0, AIRSPEED_MAX * (1 + 1e-12)]], [0.0, 0.0, 1.0], 600.0)


def test_a_huge_velocity_is_refused_with_its_own_magnitude(rotor):
    from propmap.core.vector import rotor_wrench
    for V in ([0.0, 0.0, 1e200], [1e200, 0.0, 0.0]):  # one point, as the array path names it
        with pytest.raises(ValueError, match=r"got 1e\+200 m/s"):
            rotor_wrench(*rotor, V, [0.0, 0.0, 1.0], 600.0)


def test_the_lateral_velocity_slope_is_the_drag_over_the_in_plane_speed(rotor):
    """Turning an edgewise velocity in the disk plane turns the drag with it (the loads depend on
    |V| and beta only): dF_y/dV_y = -D / V_s exactly, also at V_s = 5e-4 of the blade speed."""
    import propmap as pm
    from propmap.core.vector import rotor_wrench
    prop, params = rotor
    omega, vs = 600.0, 0.03
    D = float(pm.rotor_loads(prop, params, omega, vs, np.pi / 2).drag)
    w = rotor_wrench(prop, params, [vs, 0.0, 0.0], [0.0, 0.0, 1.0], omega, derivatives=("velocity",))
    dF = w.jacobian[("force", "velocity")]
    assert dF[1, 1] == pytest.approx(-D / vs, rel=1e-10), (dF[1, 1], -D / vs)
    assert dF[0, 1] == pytest.approx(0.0, abs=1e-12) and dF[1, 0] == pytest.approx(0.0, abs=1e-12)


def test_spin_words_in_a_list_are_case_blind_as_a_single_word(rotor):
    from propmap.core.vector import rotor_wrench
    V = [[3.0, 0.0, 1.0], [0.0, 2.0, 1.0]]
    words = rotor_wrench(*rotor, V, [0.0, 0.0, 1.0], 600.0, spin=["CW", "Ccw"])
    signs = rotor_wrench(*rotor, V, [0.0, 0.0, 1.0], 600.0, spin=[-1, 1])
    np.testing.assert_array_equal(words.torque, signs.torque)
    # and the cw rotor's shaft torque points along +z (it reacts against a rotation about -z)
    assert signs.torque[0, 2] > 0 > signs.torque[1, 2]
