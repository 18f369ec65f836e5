"""Atomic file output: write to a temporary file beside the target, then rename.

The target gets the permissions a normally created file would: an existing file keeps its
mode, a new one gets 0o666 minus the process umask (``tempfile.mkstemp`` alone would leave
0o600). A temporary file is removed when the write fails or the process is stopped by a
Python exception, KeyboardInterrupt or SIGTERM (the CLI turns SIGTERM into SystemExit);
SIGKILL cannot be caught: it can leave a hidden ``.<name>.<random>.tmp`` beside the target,
never a damaged target.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from pathlib import Path

__all__ = ["atomic_path", "atomic_write", "normal_mode"]


def normal_mode(path: Path) -> int:
    """The permission bits a plain ``open(path, "w")`` would leave: the existing file's, or
    0o666 & ~umask for a new file."""
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


@contextlib.contextmanager
def atomic_write(path, mode: str = "w", **kwargs):
    """Open a temporary file in ``path``'s folder; on success replace ``path`` with it.

    On an exception (including KeyboardInterrupt and SystemExit) the temporary file is
    removed and ``path`` is left untouched.

    Parameters
    ----------
    path : str or Path
        The target; its folder is created if missing.
    mode : {"w", "wb"}
    **kwargs
        Passed to ``open`` (``newline``, ``encoding``).

    Raises
    ------
    OSError
        The folder cannot be created or written, or the rename fails.
    """
    with atomic_path(path) as tmp, open(tmp, mode, **kwargs) as fh:
        yield fh


@contextlib.contextmanager
def atomic_path(path):
    """:func:`atomic_write` for writers that take a file name (netCDF, compilers): yields a
    temporary path in ``path``'s folder (the file exists, empty); on success it replaces
    ``path`` with normal permissions, on an exception it is removed.

    Raises
    ------
    OSError
        As :func:`atomic_write`.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    perm = normal_mode(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, perm)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise
