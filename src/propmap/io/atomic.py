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
import errno
import hashlib
import os
import signal
import stat
import tempfile
import threading
from pathlib import Path

__all__ = ["atomic_path", "atomic_paths", "atomic_write", "check_file_name", "file_sha256", "normal_mode",
           "signals_held", "temp_affixes"]


@contextlib.contextmanager
def signals_held():
    """Hold SIGINT, SIGTERM and SIGHUP while the block runs, then deliver the first that arrived to
    the handlers of before (the CLI's turn them into KeyboardInterrupt and SystemExit).

    For a library call that must not be interrupted by a Python exception: netCDF's HDF5
    writer holds a lock, and an exception raised inside ``Dataset.to_netcdf`` by a signal
    handler deadlocked ``propmap map`` in 5 of 6 SIGTERMs that landed there (a user-level
    audit, 2026-11-26: the process hung, its temporary files left). Outside the main thread
    (where signals cannot be handled) the block runs as it is.

    Yields
    ------
    None

    Raises
    ------
    KeyboardInterrupt, SystemExit
        After the block, from the handlers of before, when a signal arrived during it.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pending: list[int] = []

    def hold(signum, frame):
        pending.append(signum)

    before = {}
    try:
        for s in (getattr(signal, n) for n in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, n)):
            # (None: a handler not installed from Python, which cannot be put back; SIG_IGN, nohup's SIGHUP: held, it
            # took the place of a later SIGTERM, which was then lost, a review, stop 100)
            if signal.getsignal(s) not in (None, signal.SIG_IGN):
                before[s] = signal.signal(s, hold)
        yield
    finally:
        for s, handler in before.items():
            signal.signal(s, handler)
        if pending:
            signal.raise_signal(pending[0])  # (the handler of before runs now, outside the library)


def normal_mode(path: Path) -> int:
    """The permission bits a plain ``open(path, "w")`` would leave: the existing file's, or
    0o666 & ~umask for a new file.

    Parameters
    ----------
    path : str or Path
        The target; a path that cannot be stat'ed (missing, unreadable folder) counts as a
        new file. A symbolic link gives its target's bits.

    Returns
    -------
    int
        The permission bits (``stat.S_IMODE``), e.g. ``0o644``.
    """
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except OSError:
        return 0o666 & ~_umask()


def _umask() -> int:
    """The process' umask: read from /proc/self/status where the kernel reports it (Linux >= 4.7),
    which leaves it untouched; else set and restored (os.umask has no read-only form), which a
    file created by another thread in between would see."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    umask = os.umask(0)
    os.umask(umask)
    return umask


def file_sha256(path) -> str:
    """The SHA-256 of a file's bytes (hex), read in 1 MiB blocks.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    str
        64 lower-case hexadecimal digits.

    Raises
    ------
    OSError
        The file cannot be opened or read.
    """
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def temp_affixes(name: str) -> tuple[str, str]:
    """(prefix, suffix) of the temporary file written beside a target called ``name``
    (``tempfile.mkstemp`` puts 8 random characters between them).

    Parameters
    ----------
    name : str
        The target's file name (no folder), e.g. ``"map.nc"``.

    Returns
    -------
    (str, str)
        ``("." + name + ".", ".tmp")``: a hidden ``.map.nc.<random>.tmp``.
    """
    return f".{name}.", ".tmp"


def check_file_name(path) -> None:
    """Refuse a ``path`` (str or os.PathLike; others are left to the caller's type check) that
    is empty or names no file (``""``, ``Path("")``, which is ``"."``, ``".."``, a trailing
    separator): ValueError.

    Parameters
    ----------
    path : str or os.PathLike

    Raises
    ------
    ValueError
        An empty path, or one that names no file.
    """
    text = os.fspath(path) if isinstance(path, (str, os.PathLike)) else None
    # (a trailing separator names a folder: "new/" wrote a file called "new", a review)
    if text is not None and (not text or Path(text).name in ("", "..") or text.endswith((os.sep, os.sep + "."))):
        raise ValueError(f"path is empty or names no file ({text!r}): give the file to write")


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
        Passed to ``open`` (``newline``, ``encoding``); text is UTF-8 unless ``encoding``
        says otherwise (not the locale's encoding).

    Yields
    ------
    file object
        The temporary file, opened with ``mode`` and ``kwargs``; closed before the rename.

    Raises
    ------
    OSError
        The folder cannot be created or written, or the rename fails.
    ValueError
        An empty ``path``, or one that names no file.
    """
    if "b" not in mode:
        kwargs.setdefault("encoding", "utf-8")
    with atomic_path(path) as tmp, open(tmp, mode, **kwargs) as fh:
        yield fh


@contextlib.contextmanager
def atomic_path(path):
    """:func:`atomic_write` for writers that take a file name (netCDF, compilers): yields a
    temporary path in ``path``'s folder (the file exists, empty); on success it replaces
    ``path`` with normal permissions, on an exception it is removed.

    Parameters
    ----------
    path : str or Path
        The target; its folder is created if missing.

    Yields
    ------
    Path
        The temporary file (hidden, beside the target: :func:`temp_affixes`).

    Raises
    ------
    OSError
        As :func:`atomic_write`.
    """
    with atomic_paths([path]) as (tmp,):
        yield tmp


@contextlib.contextmanager
def atomic_paths(paths):
    """:func:`atomic_path` for files that belong together (a map and its sidecar): yields
    one temporary path per target; on success the targets are replaced one after another
    while holding an exclusive lock (``flock``) on each target's folder, so that two
    propmap runs writing the same files never interleave their renames (the last run's
    files all win); on an exception every temporary file is removed.

    A reader that does not take the lock can still see the first file replaced and not
    yet the second for a moment: files that describe another (a sidecar) carry its
    SHA-256 to check (``propmap.maps.read_sidecar``).

    Parameters
    ----------
    paths : sequence of str or Path
        The targets; their folders are created if missing. A target that is a symbolic link
        to an existing file is written through: the file it points to is replaced, the link
        kept.

    Yields
    ------
    tuple of Path
        One temporary file per target, in the order of ``paths`` (each exists, empty).

    Raises
    ------
    OSError
        As :func:`atomic_write`, naming the target (not its temporary file); IsADirectoryError
        for a target that is a folder.
    ValueError
        An empty path, or one that names no file (``"."``, ``".."``).
    """
    for p in paths:  # (renamed onto "." or a folder: "Device or resource busy" of a hidden temporary name)
        check_file_name(p)
        if isinstance(p, (str, os.PathLike)) and os.path.isdir(p):
            raise IsADirectoryError(errno.EISDIR, "is a folder, not a file", os.fspath(p))
    # a symbolic link to a file is written through: its target replaced, the link kept (the rename replaced the
    # link itself with a regular file and left the target as it was; /dev/stdout too, run as root: an audit)
    paths = [Path(os.path.realpath(p)) if os.path.islink(p) and os.path.exists(p) else Path(p) for p in paths]
    tmps = []
    try:
        for path in paths:
            path.parent.mkdir(parents=True, exist_ok=True)
            prefix, suffix = temp_affixes(path.name)
            with signals_held():  # (a SIGTERM between the file's creation and its listing here left it behind)
                try:
                    fd, tmp = tempfile.mkstemp(prefix=prefix, suffix=suffix, dir=path.parent)
                except OSError as exc:  # (said of the target, not of a hidden temporary name: an export audit)
                    raise type(exc)(exc.errno, exc.strerror, str(path)) from None
                tmps.append(Path(tmp))
                os.close(fd)
        yield tuple(tmps)
        perms = [normal_mode(p) for p in paths]
        with _folder_locks({p.parent for p in paths}):
            for tmp, path, perm in zip(tmps, paths, perms):
                os.chmod(tmp, perm)
                try:
                    os.replace(tmp, path)
                except OSError as exc:  # (said of the target, not of its temporary file)
                    raise type(exc)(exc.errno, exc.strerror, str(path)) from None
    except BaseException:
        for tmp in tmps:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(tmp)
        raise


@contextlib.contextmanager
def _folder_locks(folders):
    """Exclusive ``flock`` locks on ``folders`` (in a fixed order: no deadlock between two
    writers); a folder that cannot be opened for reading, or a file system without flock
    (some network mounts), goes unlocked."""
    fds = []
    try:
        # (one lock a folder, however its targets name it: `export-sim --out c.json`, a link to a file beside it,
        # named the folder '.' for the report and by its full path for the file, and blocked on its own lock)
        for folder in sorted({os.path.realpath(f) for f in folders}):
            try:
                fd = os.open(folder, os.O_RDONLY)
            except OSError:  # a folder that can be written but not read: no lock
                continue
            fds.append(fd)
            try:
                import fcntl

                fcntl.flock(fd, fcntl.LOCK_EX)
            except (ImportError, OSError):
                pass
        yield
    finally:
        for fd in fds:
            os.close(fd)  # closing releases the lock
