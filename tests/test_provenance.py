"""What produced an output: the version alone named 757 commits' builds (the calibration and
the defaults changed under "0.1.0"); every map, C header, simulator export and fit records the
installed package's source digest (io/provenance.py; a reproducibility audit, 2026-11-27)."""

import json
import re
from pathlib import Path

import numpy as np

import propmap as pm
from propmap.cli.main import main
from propmap.io.provenance import source_digest
from propmap.maps import build_map

RPM = np.pi / 30


def test_the_digest_is_of_the_packages_code_and_data():
    d = source_digest.__wrapped__()  # (computed afresh: the cached one is of the files when first asked)
    assert re.fullmatch(r"[0-9a-f]{64}", d) and source_digest.__wrapped__() == d
    # a change to a module's source changes it (the digest of a copy of the package, one byte edited)
    import hashlib

    root = Path(pm.__file__).resolve().parent
    files = sorted(p for p in root.rglob("*") if p.is_file() and "__pycache__" not in p.parts
                   and not p.name.endswith((".pyc", ".pyo", ".nbi", ".nbc")))
    files.sort(key=lambda p: p.relative_to(root).as_posix())  # (by the path string, whatever the platform)

    def digest(edit=None):
        h = hashlib.sha256()
        for p in files:
            rel = p.relative_to(root).as_posix().encode()
            data = p.read_bytes()
            if edit is not None and p.name == edit:
                data = data + b"#"
            h.update(len(rel).to_bytes(8, "little") + rel + len(data).to_bytes(8, "little") + data)
        return h.hexdigest()

    assert digest() == d  # (the rule as documented)
    assert digest("solver.py") != d


def test_outputs_record_it(tmp_path, capsys):
    prop, params = pm.load_propeller("apce_8x6"), pm.default_params("apce_8x6")
    ds = build_map(prop, params, np.array([4000.0, 8000.0]) * RPM, np.array([0.0, 10.0]), np.radians([0.0, 90.0]),
                   n_check=0)
    assert ds.attrs["propmap_source_sha256"] == source_digest()
    from propmap.export_c import c_header_text
    from propmap.maps import RotorMap

    assert f"(source sha256 {source_digest()})" in c_header_text(RotorMap(ds), tmp_path / "m.h")
    from propmap.simexport import export_sim

    res = export_sim("rotorpy", prop, params, n_points=200)
    assert res.meta["propmap_source_sha256"] == source_digest()
    assert main(["fit", "loads", "apce_8x6", "--fit-params", "alpha_L0", "--out", str(tmp_path / "p.toml")]) == 0
    assert json.loads((tmp_path / "p.report.json").read_text())["propmap_source_sha256"] == source_digest()
    assert f"source sha256 {source_digest()}" in (tmp_path / "p.toml").read_text()


def test_an_unreadable_file_enters_the_digest_as_such(monkeypatch):
    """A file under the package that cannot be read made every map, export and fit fail after
    its work (a review): it enters the digest as unreadable."""
    from pathlib import Path as P

    real = P.read_bytes

    def read_bytes(self):
        if self.name == "CITATION.md":
            raise PermissionError(13, "Permission denied", str(self))
        return real(self)

    before = source_digest.__wrapped__()
    monkeypatch.setattr(P, "read_bytes", read_bytes)
    after = source_digest.__wrapped__()
    assert re.fullmatch(r"[0-9a-f]{64}", after) and after != before


def test_out_of_memory_while_reading_a_log_is_said_so(tmp_path, capsys, monkeypatch, shared_data):
    """A MemoryError inside the .mat reader was 'not a readable MATLAB v5 file' (a review)."""
    import scipy.io

    def loadmat(*a, **k):
        raise MemoryError("Unable to allocate 1.9 GiB for an array")

    monkeypatch.setattr(scipy.io, "loadmat", loadmat)
    vehicle = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    log = shared_data / "neurobem_flights" / "bemnn20210218170320seg2.mat"
    assert main(["wrench", str(log), "--vehicle", str(vehicle), "--out", str(tmp_path / "w.csv")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("propmap: error: out of memory (Unable to allocate 1.9 GiB"), err


def test_outputs_cite_their_data(tmp_path, capsys):
    """fit loads' reports, export-sim's file and report cited nothing (a citation audit,
    2026-11-27); a geometry file of a catalogue propeller's name is the user's, not cited as the
    catalogue's (a review)."""
    assert main(["fit", "loads", "apce_8x6", "--fit-params", "alpha_L0", "--out", str(tmp_path / "p.toml")]) == 0
    out = capsys.readouterr().out
    assert "Data: geometry: APC Propellers PE0 geometry" in out and "Brandt & Selig, AIAA 2011-1255" in out
    assert "Brandt & Selig" in json.loads((tmp_path / "p.report.json").read_text())["data_citation"]
    assert main(["export-sim", "apce_8x6", "--target", "rotorpy", "--points", "200",
                 "--out", str(tmp_path / "r.py")]) == 0
    assert "data: geometry: APC Propellers PE0" in (tmp_path / "r.py").read_text().splitlines()[0]
    assert "Brandt & Selig" in json.loads((tmp_path / "r.report.json").read_text())["citation"]
    # a user's data on a catalogue geometry: the geometry cited, not the catalogue's measurements
    rows = ["rpm,thrust_N,torque_Nm"] + [f"{r},{2.4 * (r / 6000) ** 2:.5g},{0.048 * (r / 6000) ** 2:.5g}"
                                         for r in range(3000, 8001, 500)]
    (tmp_path / "stand.csv").write_text("\n".join(rows) + "\n")
    assert main(["fit", "loads", str(tmp_path / "stand.csv"), "--prop", "apce_8x6", "--out",
                 str(tmp_path / "s.toml")]) == 0
    cited = json.loads((tmp_path / "s.report.json").read_text())["data_citation"]
    assert cited == "geometry: APC Propellers PE0 geometry (v2022-0915)", cited
    own = tmp_path / "apce_8x6_geom.txt"  # (the user's file under a catalogue propeller's name)
    own.write_text("r/R c/R beta\n0.15 0.16 31.0\n0.5 0.18 22.0\n0.75 0.14 16.0\n1.0 0.06 11.0\n")
    assert main(["export-sim", str(own), "--blades", "2", "--target", "rotorpy", "--points", "200",
                 "--out", str(tmp_path / "u.py")]) == 0
    assert "data:" not in (tmp_path / "u.py").read_text().splitlines()[0]
    assert json.loads((tmp_path / "u.report.json").read_text()).get("citation") is None


def test_flight_tables_cite_neurobem(tmp_path, capsys, shared_data):
    """The flight tables' 'log's own' rows named no source (a citation audit, 2026-11-27)."""
    vehicle = Path(pm.__file__).parent / "data" / "examples" / "neurobem_quadrotor.toml"
    log = shared_data / "neurobem_flights" / "bemnn20210223104803seg2.mat"
    assert main(["wrench", str(log), "--vehicle", str(vehicle), "--out", str(tmp_path / "w.csv")]) == 0
    assert "NeuroBEM: Hybrid Aerodynamic Quadrotor Model\", Robotics: Science and Systems 2021" in \
        capsys.readouterr().out
