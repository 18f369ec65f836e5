"""The vendor baseline of docs/validation.md (tools/apc_baseline.py): APC's published
performance files (PER3, v2022-0915; APC's own blade-element predictions, in ../shared) read
and interpolated as the tool does, against values in the file and UIUC's measured static
thrust coefficient (UIUC Propeller Data Site vol. 1, Brandt & Selig AIAA 2011-1255)."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _tool():
    spec = importlib.util.spec_from_file_location("apc_baseline", ROOT / "tools" / "apc_baseline.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_catalogue_names_map_to_apc_file_names():
    t = _tool()
    assert t.per3_name("apce_10x4.7") == "PER3_10x47E.dat"
    assert t.per3_name("apcsf_8x3.8") == "PER3_8x38SF.dat"
    assert t.per3_name("apcsp_9x6") == "PER3_9x6.dat"
    assert t.per3_name("gwsdd_5x4.3") is None and t.per3_name("apce") is None


def test_per3_blocks_and_their_interpolation(shared_data):
    t = _tool()
    blocks = t.read_per3(shared_data / "apc_vendor_data" / "performance_PER3" / "PER3_8x6E.dat")
    assert min(blocks) == 1000.0 and all(b.shape[1] == 3 for b in blocks.values())
    b1 = blocks[1000.0]
    assert b1[0].tolist() == [0.0, 0.1395, 0.0817]  # the file's first row at 1000 rpm (J, Ct, Cp)
    assert b1[1].tolist() == [0.0305, 0.1380, 0.0825]
    assert np.all(np.diff(b1[:, 0]) > 0)
    # on a tabulated point exactly; between blocks linear in rpm; beyond a block's J range NaN
    ct, cp = t.apc_coefficients(blocks, np.array([1000.0]), np.array([0.0305]))
    assert ct[0] == pytest.approx(0.1380, abs=1e-12) and cp[0] == pytest.approx(0.0825, abs=1e-12)
    b2 = blocks[2000.0]
    ct, _ = t.apc_coefficients(blocks, np.array([1500.0]), np.array([0.0]))
    assert ct[0] == pytest.approx(0.5 * (b1[0, 1] + b2[0, 1]), abs=1e-12)
    ct, _ = t.apc_coefficients(blocks, np.array([1000.0, 500.0]), np.array([b1[-1, 0] + 0.1, 0.0]))
    assert np.all(np.isnan(ct))
    # APC's static prediction against UIUC's measured 0.107-0.118 (PROVENANCE of the shared data): well above
    ct, _ = t.apc_coefficients(blocks, np.array([4000.0, 6000.0]), np.zeros(2))
    assert np.all((ct > 0.13) & (ct < 0.15))


def test_apc_predictions_against_uiuc_and_propmap_blind(shared_data):
    """docs/validation.md, A vendor's prediction as a baseline: on the 54 catalogue APC
    propellers with a file, APC's predictions over-predict UIUC's measured thrust (signed
    medians +6.7% of static CT on the sweeps, +14.3% at rest) and propmap blind is closer on
    the sweeps' thrust (medians, regression values of 2026-11-28: 8.8% against 7.0%)."""
    from propmap.io.catalogue import catalogue

    t = _tool()
    names = sorted(n for n, e in catalogue().items() if t.per3_name(n) and e.static_files and e.sweep_files)
    rows = [r for r in map(t.one, names) if r is not None]
    assert len(rows) == 54
    med = {k: np.median([r[part][k] for r in rows]) for part in ("sweeps",) for k in ("apc_ct", "propmap_ct")}
    assert med["apc_ct"] == pytest.approx(0.088, abs=0.001) and med["propmap_ct"] == pytest.approx(0.070, abs=0.001)
    assert np.median([r["sweeps"]["apc_bias_ct"] for r in rows]) == pytest.approx(0.067, abs=0.002)
    assert np.median([r["static"]["apc_bias_ct"] for r in rows]) == pytest.approx(0.143, abs=0.002)
