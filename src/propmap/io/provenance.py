"""What produced an output: the package's version and a digest of its installed code and data.

The version string alone does not tell two builds apart (the calibration and the defaults
changed many times under one version): every map, simulator export and fit report records
:func:`source_digest` beside it (docs/numerics.md, Reproducibility).
"""

from __future__ import annotations

import functools
import hashlib
from pathlib import Path

__all__ = ["source_digest"]

#: files under the package that are not its code or data: byte-code and the kernels' disk cache
_SKIPPED_SUFFIXES = (".pyc", ".pyo", ".nbi", ".nbc")


@functools.lru_cache(maxsize=1)
def source_digest() -> str:
    """SHA-256 of the installed package's code and bundled data.

    Every file under the package's folder (sorted by its path relative to it, "/"-separated),
    its path and its bytes, except byte-code and the compiled kernels' cache
    (``__pycache__`` folders, ``.pyc``, ``.nbi``, ``.nbc``). Computed once per process (about
    7 MB read).

    Returns
    -------
    str
        64 hexadecimal digits.
    """
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    files = sorted(p for p in root.rglob("*") if p.is_file() and "__pycache__" not in p.parts
                   and not p.name.endswith(_SKIPPED_SUFFIXES))
    for p in files:
        rel = p.relative_to(root).as_posix().encode()
        h.update(len(rel).to_bytes(8, "little") + rel)
        data = p.read_bytes()
        h.update(len(data).to_bytes(8, "little") + data)
    return h.hexdigest()
