"""What a command may write and must not: its outputs checked before any work (never an input,
the package's own files, a folder, a path the system refuses), a file given twice, and the files a
vehicle file names (inputs too). The checks of docs/cli.md, "Outputs are never inputs"."""

from __future__ import annotations

import os
import re
from pathlib import Path

from ..io.qprop_file import _spec_file
from ._common import _SEPARATORS, InputError, _short

__all__ = ["check_out_dir", "check_outputs", "refuse_copies", "vehicle_inputs"]


def refuse_copies(paths, option: str, consequence: str) -> None:
    """Refuse a file given twice under two names: the same file (a symbolic or a hard link) or a
    byte-identical copy (io.inputs.first_copy), as ``option: X is the same file as Y:
    <consequence>``; a path that cannot be read, as ``option: X: no such file``."""
    from ..io.inputs import first_copy, short_path

    try:
        copy = first_copy(paths)
    except OSError as exc:  # (named as the option's, as its reader would)
        why = "no such file" if isinstance(exc, FileNotFoundError) else (exc.strerror or str(exc)).lower()
        raise InputError(f"{option}: {short_path(exc.filename)}: {why}") from None
    if copy is not None:
        p, what, earlier = copy
        raise InputError(f"{option}: {short_path(p)} is {what} {short_path(earlier)}: {consequence}")


def _same_file(a: Path, b: Path) -> bool:
    try:
        if os.path.realpath(a) == os.path.realpath(b):
            return True
        return a.exists() and b.exists() and os.path.samefile(a, b)  # hard links
    except (OSError, ValueError):
        return False


def _is_file(p) -> bool:
    """Path.is_file() that says False for names the system refuses (too long, NUL)."""
    try:
        return Path(p).is_file()
    except (OSError, ValueError):
        return False


#: the propmap package's folder (its code and bundled data): never an output (a mistyped --out once wrote a CSV
#: over cli/main.py; only data/ was protected)
_PACKAGE = os.path.realpath(Path(__file__).resolve().parents[1])


def vehicle_inputs(vehicle) -> list:
    """The files a vehicle TOML names (its own parameter file, its top-level ``params``, and its
    rotors' geometry and parameter files: ``[[rotors]] propeller`` and ``params`` entries that
    are files, as the vehicle reader resolves them, :func:`propmap.vehicle.own_set.vehicle_files`):
    inputs of any command given the vehicle, never to be written over. Best effort: the vehicle
    reader reports a malformed file; None or an unreadable file gives []."""
    from ..vehicle.file import VehicleFileError
    from ..vehicle.own_set import vehicle_files

    if vehicle is None:
        return []
    try:
        return vehicle_files(vehicle)
    except VehicleFileError:
        return []


def check_outputs(outputs, inputs) -> None:
    """Refuse, before any work, output paths that would lose data or fail late.

    Parameters
    ----------
    outputs : iterable of (str, str or Path)
        (option, path) of every file a command will write, including files written beside
        ``--out`` (reports, figures) or inside ``--out-dir``.
    inputs : iterable of str or Path
        Every file the command reads (missing ones are ignored; ``qprop:FILE``, a parameter
        set read from a QPROP file, is FILE).

    Raises
    ------
    InputError
        An empty or all-blank path, a name the system refuses (too long), an existing folder or other
        non-regular file (a device such as /dev/null, a pipe), a symbolic link to nothing,
        a path below a regular file or a dangling link, a folder that cannot be written,
        a file of the propmap package (its code, catalogue and calibration), two outputs that
        are the same file, or a path that resolves to an input file (also through ``..``,
        symbolic links or hard links). A symbolic link to a file is checked, and written,
        as that file.
    """
    from ..io.inputs import short_path

    inputs = [_spec_file(p) for p in inputs]  # (a --params qprop:FILE reads FILE)
    ins = [Path(p) for p in inputs if p is not None and str(p) != "" and _is_file(p)]
    seen: dict[str, str] = {}
    for option, path in outputs:
        if path is None:
            continue
        if str(path) == "":
            raise InputError(f"{option}: the path is empty")
        if not str(path).strip():  # (loads --out ' ' wrote a file named with a blank)
            raise InputError(f"{option}: the path {str(path)!r} is only blanks")
        if isinstance(path, str) and path.endswith(_SEPARATORS):  # (a Path has dropped the separator)
            raise InputError(f"{option}: {path} names a folder (it ends with {path[-1]!r}): give a file's name")
        p = Path(path)
        try:
            _check_output(option, p, ins)
            real = os.path.realpath(p)
        except OSError as exc:
            raise InputError(f"{option}: {exc.strerror or exc} ({short_path(p)})") from None
        if real in seen:
            raise InputError(f"{option}: {p} is also the file of {seen[real]}; give outputs different names")
        seen[real] = option


#: a process's open descriptor under /proc (/proc/self/fd/1, /proc/1234/fd/3, /proc/thread-self/fd/0)
_PROC_FD = re.compile(r"/proc/(self|thread-self|[0-9]+)(/task/[0-9]+)?/fd/")


def _stream(p: Path, depth: int = 0) -> bool:
    """Whether ``p`` names a standard stream or an open descriptor (/dev/stdout, /dev/fd/1,
    /proc/self/fd/1, or a link to one): written through, an atomic write would replace the
    redirected file (`--out /dev/stdout >> log.txt` emptied log.txt: a review)."""
    text = os.path.abspath(p)
    # (any path under /proc was called a stream: /proc/a.toml, which cannot be written, is a folder's refusal)
    if text in ("/dev/stdin", "/dev/stdout", "/dev/stderr") or text.startswith("/dev/fd/") or _PROC_FD.match(text):
        return True
    try:
        target = os.readlink(p) if os.path.islink(p) else ""
    except OSError:
        return False
    # (a loop of links ends here: 40 hops, the kernel's own limit; the later checks refuse it)
    return bool(target) and depth < 40 and _stream(Path(os.path.join(os.path.dirname(text), target)), depth + 1)


def _check_output(option: str, p: Path, ins) -> None:
    if _stream(p):
        raise InputError(f"{option}: {p} is a standard stream or an open file descriptor; give a file name (or '-' "
                         "for standard output, where the command takes it)")
    for inp in ins:
        if _same_file(p, inp):
            raise InputError(f"{option}: {p} is the input file {inp}; refusing to overwrite an input")
    real = os.path.realpath(p)
    if real == _PACKAGE or real.startswith(_PACKAGE + os.sep):
        raise InputError(f"{option}: {p} is a file of the propmap package (its code or bundled data); refusing to "
                         "write it")
    if p.is_dir():
        raise InputError(f"{option}: {p} is a folder; give a file name")
    if os.path.lexists(p):
        if p.is_symlink() and not p.exists():
            raise InputError(f"{option}: {p} is a symbolic link to a missing file; give a file name")
        if not p.is_file():
            raise InputError(f"{option}: {p} exists and is not a regular file (a device, pipe or socket); "
                             "give a file name")
        if p.is_symlink():  # (written through: its target is the file replaced, in the target's folder)
            p = Path(real)
    parent = p.parent
    while not os.path.lexists(parent):
        parent = parent.parent
    if parent.is_symlink() and not parent.exists():
        raise InputError(f"{option}: {p} lies below {parent}, a symbolic link to a missing folder")
    if not parent.is_dir():
        raise InputError(f"{option}: {p} lies below {parent}, which is a file, not a folder")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError(f"{option}: cannot write in {parent} (permission denied)")
    _probe(option, parent, p.name)


def _probe(option: str, folder: Path, name: str) -> None:
    """Create and remove, in ``folder``, the temporary file that writing ``name`` will use
    (io.atomic): what the access bits do not tell (a read-only file system, /proc, root on
    a folder without write permission), and a name too long once the temporary file's
    prefix and suffix are added, found now instead of after the work."""
    import errno
    import tempfile

    from ..io.atomic import signals_held, temp_affixes

    prefix, suffix = temp_affixes(name)
    # (SIGINT and SIGTERM held until the probe is gone: one that landed between its creation and its removal left
    # it behind, a hidden .NAME.<random>.tmp)
    with signals_held():
        try:
            fd, tmp = tempfile.mkstemp(prefix=prefix, suffix=suffix, dir=folder)
        except OSError as exc:
            if exc.errno == errno.ENAMETOOLONG:
                try:
                    name_max = os.pathconf(folder, "PC_NAME_MAX")
                except (OSError, ValueError):
                    name_max = 255
                # (the limit is in bytes of the file system's encoding: a name of 127 accented characters once read as
                # "at most 241 characters"; mkstemp adds 8 characters)
                size = len(os.fsencode(name))
                most = name_max - (len(os.fsencode(prefix)) + len(os.fsencode(suffix)) + 8 - size)
                raise InputError(f"{option}: the name {_short(name)!r} ({size} bytes, {len(name)} characters) is too "
                                 f"long with the temporary file's affixes; give at most {most} bytes") from None
            raise InputError(f"{option}: cannot write in {folder} ({exc.strerror})") from None
        try:
            os.close(fd)
        finally:
            os.unlink(tmp)


def check_out_dir(option: str, out_dir: Path, names, inputs=(), others=()) -> list[Path]:
    """:func:`check_outputs` for the files ``names`` a command writes inside ``out_dir``, with
    ``others``, (option, path) of the command's other outputs: the folder may not be one of them
    (``map --out q.nc --plot q.nc`` built the map, wrote it, then failed on the folder: an audit,
    stop 100), nor a file in it one of them."""
    from ..io.inputs import short_path

    if out_dir is None or str(out_dir) == "":
        raise InputError(f"{option}: the path is empty")
    for other, path in others:
        if path is not None and os.path.realpath(out_dir) == os.path.realpath(path):
            raise InputError(f"{option}: {out_dir} is also the file of {other}; give outputs different names")
    try:
        exists = out_dir.exists()
    except OSError as exc:  # a name too long for the system, a loop of links
        raise InputError(f"{option}: {short_path(out_dir)}: {exc.strerror or exc}") from None
    if exists and not out_dir.is_dir():
        raise InputError(f"{option}: {out_dir} exists and is not a folder")
    paths = [out_dir / n for n in names]
    check_outputs([*others, *[(option, p) for p in paths]], inputs)
    return paths
