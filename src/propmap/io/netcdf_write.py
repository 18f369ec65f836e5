"""The netCDF write of a map (:func:`to_netcdf_here`), with a full disk said as such (moved from
io/mapfile.py, which had reached 625 lines; the callers hold io.mapfile.NETCDF_LOCK)."""

from __future__ import annotations

import os
import sys
from pathlib import Path


def to_netcdf_here(ds, path, **kwargs) -> None:
    """``ds.to_netcdf(path, engine="netcdf4", **kwargs)`` with a lazy (dask) dataset's tasks run in
    this thread, which holds :data:`propmap.io.mapfile.NETCDF_LOCK` (the caller's): on dask's threads or a cluster's
    workers they read and store outside it, and a task that reads a map waited for the lock
    without end, SIGTERM held (a review, 2026-11-27).

    Parameters
    ----------
    ds : xarray.Dataset
        In memory or lazy (dask arrays).
    path : str or os.PathLike
        The netCDF file written (a temporary one: the callers replace the output atomically).
    **kwargs
        Passed to ``xarray.Dataset.to_netcdf`` (e.g. ``encoding``).

    Raises
    ------
    OSError
        The netCDF/HDF5 library's write failed (its bare ``RuntimeError: NetCDF: HDF error``,
        once an "internal error" with a traceback from the file's clean-up, or a
        ``PermissionError`` on creating the file): ENOSPC naming the folder where it has less
        free space than the map's size plus 1 MiB (a full disk: an audit, stop 100), else the
        PermissionError as raised, or EIO with the library's words.
    Exception
        Whatever else xarray and the netCDF/HDF5 libraries raise.
    """
    failure = None
    hook = sys.unraisablehook

    def quiet(unraisable):  # (the failed file's clean-up, xarray's file manager closing it, fails the same way:
        # its traceback was printed as "Exception ignored in ... CachingFileManager.__del__")
        if not (unraisable.exc_type is RuntimeError
                and "CachingFileManager" in getattr(unraisable.object, "__qualname__", "")):
            hook(unraisable)

    sys.unraisablehook = quiet
    try:
        try:
            ds.to_netcdf(path, engine="netcdf4", compute=False, **kwargs).compute(scheduler="synchronous")
        except (RuntimeError, PermissionError) as exc:  # (netCDF-C says a full disk as EACCES creating the file)
            # (its words only: the exception's traceback held the failed file open, its clean-up then failing
            # after the hook was back, on a real full disk: a review, stop 100)
            failure = ((exc.errno, exc.strerror) + ((exc.filename,) if exc.filename is not None else ())
                       if isinstance(exc, PermissionError) else str(exc))
        if failure is not None:
            import gc

            gc.collect()  # (the failed file closed now, its space given back, its clean-up's failure quiet)
    finally:
        sys.unraisablehook = hook
    if failure is None:
        return
    import errno
    import shutil

    folder = Path(path).parent
    try:
        free = shutil.disk_usage(folder).free
    except OSError:
        free = None
    if free is not None and free < ds.nbytes + 2**20:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(folder)) from None
    if isinstance(failure, tuple):
        raise PermissionError(*failure)
    raise OSError(errno.EIO, f"the netCDF library could not write the map ({failure})", str(path)) from None
