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
kernels' serial forms (a batch under solver.PARALLEL_MIN_POINTS) start no region and take no
lock.
"""

from __future__ import annotations

import threading

__all__ = ["PARALLEL_LOCK"]

#: held around every launch of a parallel kernel (module docstring); re-entrant, although no
#: kernel calls back into Python
PARALLEL_LOCK = threading.RLock()
