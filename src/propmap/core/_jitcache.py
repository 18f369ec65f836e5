"""The compiled kernels' disk cache, keyed on every module each kernel compiles in.

numba stamps a cached function with a hash of the file that defines it only. The solver
kernel (``_kernel.py``, with the annuli's root solve of ``_annulus.py`` and their loads of
``_annulus_loads.py``) inlines functions from
``_physics.py``, ``_momentum.py`` and ``_fastmath.py`` and calls those of ``_flags.py``, and the sensitivity
kernel (``_sensitivity.py``, calling the momentum side's partials of
``_momentum_sensitivity.py`` and inlining the elements' partials of ``_tangents.py`` and the
swirl's linear algebra of ``_swirl_sensitivity.py``) compiles
in those and ``_annulus.py``, and the linear inflow models' (``_linear_sensitivity.py``)
those and ``_sensitivity.py``'s, so an edit there would leave numba serving a kernel compiled
from the old physics (module constants such as the Reynolds clamp are compiled in). The
locators below serve the kernels' own files (``_kernel.py``, ``_annulus.py``, ``_flags.py``,
whose reverse-flow radius compiles in ``_momentum.py``'s in-plane induction since 2026-11-25,
``_sensitivity.py``, ``_momentum_sensitivity.py``, ``_linear_sensitivity.py``, and the maps'
``_interp.py``, which inlines the disk frame of ``_frame.py``) and stamp
each one's cache with a SHA-256 over the contents of every file it compiles in
(:data:`KERNEL_SOURCES`, :data:`SENSITIVITY_SOURCES`, :data:`LINEAR_SOURCES`,
:data:`INTERP_SOURCES`), so that editing
any of them recompiles. They are registered
ahead of numba's own locators (numba.core.caching, an internal API); if that API is not found,
:data:`CACHE` is False and the kernels are compiled in every process instead of risking a
stale one. Where numba can write no cache folder, one in the temporary folder is given to it
(:func:`_writable_cache`).
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

__all__ = ["CACHE", "CACHE_FALLBACK", "INTERP_SOURCES", "KERNEL_SOURCES", "LINEAR_SOURCES", "SENSITIVITY_SOURCES",
           "sources_stamp"]

_HERE = Path(__file__).resolve().parent
#: the files whose code the compiled solver kernel contains
KERNEL_SOURCES = (_HERE / "_kernel.py", _HERE / "_annulus.py", _HERE / "_physics.py", _HERE / "_momentum.py",
                  _HERE / "_fastmath.py", _HERE / "_flags.py", _HERE / "_annulus_loads.py")
#: the files whose code the compiled sensitivity kernel contains
SENSITIVITY_SOURCES = (_HERE / "_sensitivity.py", _HERE / "_momentum_sensitivity.py",
                       _HERE / "_parameter_sensitivity.py", _HERE / "_delayed_sensitivity.py", _HERE / "_tangents.py",
                       _HERE / "_swirl_sensitivity.py", *KERNEL_SOURCES)
#: the files whose code the compiled sensitivity kernel of the linear inflow models contains
LINEAR_SOURCES = (_HERE / "_linear_sensitivity.py", *SENSITIVITY_SOURCES)
#: the files whose code the maps' compiled kernels contain (the disk frame's arithmetic inlined from _frame.py)
INTERP_SOURCES = (_HERE / "_interp.py", _HERE / "_frame.py")
#: the cached files, each with the sources its stamp covers
_STAMPED = {os.path.realpath(p): KERNEL_SOURCES for p in (*KERNEL_SOURCES[:2], _HERE / "_flags.py")}
_STAMPED[os.path.realpath(INTERP_SOURCES[0])] = INTERP_SOURCES
_STAMPED.update({os.path.realpath(p): SENSITIVITY_SOURCES for p in SENSITIVITY_SOURCES[:3]})
_STAMPED[os.path.realpath(LINEAR_SOURCES[0])] = LINEAR_SOURCES


def sources_stamp(paths=KERNEL_SOURCES) -> bytes:
    """SHA-256 over the contents of ``paths`` (the kernel cache's stamp)."""
    h = hashlib.sha256()
    for p in paths:
        h.update(Path(p).read_bytes())
    return h.digest()


def _install() -> bool:
    try:
        from numba.core import caching

        bases = [caching.UserProvidedCacheLocator, caching.InTreeCacheLocator, caching.UserWideCacheLocator]
        impl = getattr(caching, "CacheImpl", None) or caching._CacheImpl
        impl._locator_classes  # noqa: B018 (the attribute must exist)
    except (ImportError, AttributeError):
        return False

    def make(base):
        class KernelLocator(base):
            def get_source_stamp(self):
                return sources_stamp(self._propmap_sources)

            @classmethod
            def from_function(cls, py_func, py_file):
                sources = _STAMPED.get(os.path.realpath(py_file))
                if sources is None:
                    return None
                locator = super().from_function(py_func, py_file)
                if locator is not None:
                    locator._propmap_sources = sources
                return locator

        KernelLocator.__name__ = f"PropmapKernel{base.__name__}"
        return KernelLocator

    if not any(getattr(c, "__name__", "").startswith("PropmapKernel") for c in impl._locator_classes):
        impl._locator_classes[:0] = [make(b) for b in bases]
    return True


def _probe() -> None:  # a function of this folder, whose cache locations _writable_cache tries
    pass


def _writable_cache() -> str | None:
    """Give numba a cache folder where it has none: where neither the package's folder nor the
    user's cache folder can be written (a read-only install run without a home, e.g. as
    ``nobody``: "cannot cache function ...: no locator available", an internal error of every
    command), or NUMBA_CACHE_DIR names a folder that cannot be written, NUMBA_CACHE_DIR (the
    environment's, which numba reads again when its configuration is reloaded, and numba's
    CACHE_DIR) is set to ``<temp folder>/propmap-numba-<uid>``, a folder of this user's only
    (created mode 700; one that exists is used only where it is this user's, not a link, and
    private: numba's cache index is a pickle, so a folder another user can write is never used),
    else to a new private folder (tempfile.mkdtemp). Returns the folder set, or None (numba's own
    locations serve, or numba's internals are not the ones known: the kernels then fail as numba
    says)."""
    import stat
    import tempfile

    try:
        import numba
        from numba.core import caching

        # NUMBA_CACHE_DIR where it is set, then (as numba falls through) the package's folder or the user's
        # cache: where none can be written, an unwritable NUMBA_CACHE_DIR ended every command with an internal
        # error (a parallel-use audit, 2026-11-27)
        locators = (((caching.UserProvidedCacheLocator,) if numba.config.CACHE_DIR else ())
                    + (caching.InTreeCacheLocator, caching.UserWideCacheLocator))
        for locator in locators:
            try:
                if locator.from_function(_probe, __file__) is not None:
                    return None
            except Exception:  # noqa: BLE001 (a locator that fails is one that cannot serve)
                continue
    except (ImportError, AttributeError):
        return None
    uid = os.getuid() if hasattr(os, "getuid") else None
    folder = os.path.join(tempfile.gettempdir(), f"propmap-numba-{uid if uid is not None else 'user'}")
    try:
        os.makedirs(folder, mode=0o700, exist_ok=True)
        st = os.lstat(folder)
        private = (stat.S_ISDIR(st.st_mode) and (uid is None or st.st_uid == uid)
                   and not st.st_mode & (stat.S_IRWXG | stat.S_IRWXO))
        if not private:
            folder = tempfile.mkdtemp(prefix="propmap-numba-")
    except OSError:
        return None
    os.environ["NUMBA_CACHE_DIR"] = folder
    numba.config.CACHE_DIR = folder
    return folder


#: whether the kernel may use numba's disk cache (only with the stamping locators installed)
CACHE = _install()
#: the cache folder set where numba had no writable one (None: numba's own)
CACHE_FALLBACK = _writable_cache()
