"""One lock around numba's parallel regions (the kernels compiled with ``parallel=True``:
core/_kernel.solve_batch, core/_sensitivity.sensitivities and
core/_linear_sensitivity.linear_sensitivities).

numba's ``workqueue`` threading layer, which numba uses where neither OpenMP nor TBB is
installed (or where ``NUMBA_THREADING_LAYER`` names it), is not thread-safe: two Python threads
launching parallel regions at once abort the process ("Concurrent access has been detected";
a parallel-use audit of 2026-11-27 found it with two threads calling ``rotor_loads`` on 32
points or more, and docs/simulators.md said to call batches from one thread). Every launch
from propmap holds :data:`PARALLEL_LOCK`, so that concurrent calls run one after the other
whatever the layer; each region already spreads over every core numba is given, so the other
threads lose nothing but the overlap of two regions competing for the same cores. The
kernels' serial forms (a batch under solver.PARALLEL_MIN_POINTS, and every batch in a child
forked after its parent launched a region: :func:`serial_only`) start no region and take no
lock.
"""

from __future__ import annotations

import contextlib
import os
import threading

__all__ = ["PARALLEL_LOCK", "parallel_region", "serial_only"]

#: held around every launch of a parallel kernel (module docstring); re-entrant, although no
#: kernel calls back into Python
PARALLEL_LOCK = threading.RLock()

#: whether this process launched a parallel region, and whether it is a child forked after its
#: parent did (then every batch runs serially: below)
_STATE = {"launched": False, "forked_after_launch": False}


@contextlib.contextmanager
def parallel_region():
    """Hold :data:`PARALLEL_LOCK` around one launch of a parallel kernel and record it."""
    with PARALLEL_LOCK:
        _STATE["launched"] = True
        yield


def serial_only() -> bool:
    """Whether this process must run every batch on the calling thread: a child forked after its
    parent launched a parallel region. GNU OpenMP (numba's ``omp`` layer) does not survive a
    fork: such a child's first parallel region terminated it ("fork() called from a process
    already using GNU OpenMP, this is unsafe") and a ``multiprocessing.Pool`` with the ``fork``
    start method waited on it forever (docs/simulators.md); the serial kernels compute the same
    loads without it (one core per worker, as a process pool wants)."""
    return _STATE["forked_after_launch"]


def _after_fork_in_child() -> None:
    _STATE["forked_after_launch"] = _STATE["launched"]


if hasattr(os, "register_at_fork"):  # (POSIX; Windows has no fork)
    os.register_at_fork(after_in_child=_after_fork_in_child)
