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

    Every file under the package's folder (sorted by its path relative to it, "/"-separated,
    as a string), its path and its bytes, except byte-code and the compiled kernels' cache
    (``__pycache__`` folders, ``.pyc``, ``.nbi``, ``.nbc``); a file that cannot be read
    enters as its path and the word "unreadable" (a digest that says so, not a failed
    output). Computed once per process (about 1,300 files, 3 MB, 0.03 s); the commands that
    record it compute it when they start, so that it is of the code that runs. The bytes as
    installed: a checkout with other line endings gives another digest.

    Returns
    -------
    str
        64 hexadecimal digits.
    """
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    files = sorted((p.relative_to(root).as_posix(), p) for p in root.rglob("*")
                   if p.is_file() and "__pycache__" not in p.parts and not p.name.endswith(_SKIPPED_SUFFIXES))
    for rel, p in files:
        h.update(len(rel.encode()).to_bytes(8, "little") + rel.encode())
        try:
            data = p.read_bytes()
        except OSError:  # (a file made unreadable or removed since: said in the digest, not a lost output)
            data = b"unreadable"
        h.update(len(data).to_bytes(8, "little") + data)
    return h.hexdigest()
