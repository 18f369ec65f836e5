"""The compiled kernel's disk cache never serves a kernel built from older physics.

numba alone stamps the cache with the kernel file only; propmap's locators
(core/_jitcache.py) stamp it with every module the kernel compiles in.
"""

import ast
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from propmap.core import _jitcache, _kernel

SRC = Path(_kernel.__file__).resolve().parents[1]  # .../propmap

#: the paper's model at one point, with its torque's Omega derivative and that derivative's
#: central difference (h = 1 rad/s: they agree to 1e-7): the solver kernel and the sensitivity
#: kernel, each with its cache statistics (hits, misses)
SCRIPT = ("import propmap as pm; from propmap.core import _kernel as K, _sensitivity as S; "
          "p, s = pm.load_propeller('apce_8x6'), pm.preset('gill2017-apc'); "
          "r = pm.rotor_loads(p, s, 800.0, 5.0, 1.0, derivatives=('omega',)); "
          "fd = (pm.rotor_loads(p, s, 801.0, 5.0, 1.0).torque - pm.rotor_loads(p, s, 799.0, 5.0, 1.0).torque) / 2; "
          "k, d = K.solve_batch_serial.stats, S.sensitivities_serial.stats; "
          "print(repr(float(r.torque)), repr(float(r.derivative('torque', 'omega'))), repr(float(fd)), "
          "sum(k.cache_hits.values()), sum(k.cache_misses.values()), "
          "sum(d.cache_hits.values()), sum(d.cache_misses.values()))")
#: how many compiled overloads each kernel's cache index would serve to this process (numba's
#: own loader, numba.core.caching.IndexDataCacheFile: none when the index's stamp differs from
#: the sources'); it compiles nothing
SERVED = ("from propmap.core import _kernel as K, _sensitivity as S; "
          "print(*(len(f._cache._cache_file._load_index()) for f in (K.solve_batch_serial, S.sensitivities_serial)))")


def _sibling_imports(path: Path) -> set[str]:
    """The core modules a kernel file imports (``from ._x import ...``), but the cache's own."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    named = {f"{n.module}.py" for n in ast.walk(tree)
             if isinstance(n, ast.ImportFrom) and n.level == 1 and n.module and n.module != "_jitcache"}
    # ``from . import _x`` as well
    return named | {f"{a.name}.py" for n in ast.walk(tree)
                    if isinstance(n, ast.ImportFrom) and n.level == 1 and not n.module for a in n.names}


def test_sibling_imports_sees_both_import_forms(tmp_path):
    # the stamp check below relies on it: a kernel module imported as ``from . import x`` counts too
    f = tmp_path / "k.py"
    f.write_text("from . import _a, _b\nfrom ._c import f\nfrom ._jitcache import CACHE\nimport numpy\n")
    assert _sibling_imports(f) == {"_a.py", "_b.py", "_c.py"}


def test_the_stamp_covers_every_module_the_kernel_compiles_in(tmp_path):
    names = {p.name for p in _jitcache.KERNEL_SOURCES}
    assert names == {"_kernel.py", "_annulus.py", "_physics.py", "_momentum.py", "_fastmath.py", "_flags.py",
                     "_annulus_loads.py"}
    sensitivity = names | {"_sensitivity.py", "_momentum_sensitivity.py", "_parameter_sensitivity.py",
                           "_delayed_sensitivity.py", "_tangents.py", "_swirl_sensitivity.py"}
    assert {p.name for p in _jitcache.SENSITIVITY_SOURCES} == sensitivity
    # every module the kernels import is in their stamp (a new kernel module must be added there)
    core = SRC / "core"
    assert _sibling_imports(core / "_kernel.py") | {"_kernel.py"} <= names
    assert _sibling_imports(core / "_annulus.py") <= names
    assert _sibling_imports(core / "_annulus_loads.py") <= names
    assert _sibling_imports(core / "_flags.py") <= names
    assert _sibling_imports(core / "_sensitivity.py") <= sensitivity
    assert _sibling_imports(core / "_momentum_sensitivity.py") <= names
    assert _sibling_imports(core / "_tangents.py") <= names
    assert _sibling_imports(core / "_swirl_sensitivity.py") <= names
    assert _sibling_imports(core / "_delayed_sensitivity.py") <= sensitivity
    assert _sibling_imports(core / "_parameter_sensitivity.py") <= sensitivity
    assert {p.name for p in _jitcache.LINEAR_SOURCES} == sensitivity | {"_linear_sensitivity.py"}
    assert _sibling_imports(core / "_linear_sensitivity.py") <= sensitivity
    # the maps' kernels inline the disk frame of _frame.py (which imports no sibling with compiled code)
    assert {p.name for p in _jitcache.INTERP_SOURCES} == {"_interp.py", "_frame.py"}
    assert _sibling_imports(core / "_interp.py") - {"_jitcache.py"} <= {"_frame.py"}
    assert _sibling_imports(core / "_frame.py") - {"_jitcache.py"} == set()
    # the kernels' own files are served by the stamping locators, each with its sources
    assert {Path(k).name for k in _jitcache._STAMPED} == {"_kernel.py", "_annulus.py", "_flags.py", "_sensitivity.py",
                                                          "_momentum_sensitivity.py", "_parameter_sensitivity.py",
                                                          "_linear_sensitivity.py", "_interp.py"}
    assert _jitcache.CACHE
    a, b = tmp_path / "a.py", tmp_path / "b.py"
    a.write_text("x = 1\n")
    b.write_text("y = 2\n")
    before = _jitcache.sources_stamp([a, b])
    b.write_text("y = 3\n")
    assert _jitcache.sources_stamp([a, b]) != before


@pytest.mark.slow
def test_editing_the_physics_recompiles_instead_of_serving_the_cached_kernels(tmp_path):
    """A warm cache, then edit _physics.py (here: eq 4's form drag doubled): neither kernel, the
    solver's nor the sensitivities' (which was stamped with its own file only until 2026-11-23
    and then served the old model's derivatives), is served from the cache any more.

    The copy takes the package's cache files along (warm where the suite has compiled both
    kernels by now, which another test process under pytest-xdist may not have: then the first
    run compiles them; the stamp is over the sources' contents, so a copied cache is warm),
    leaving out the temporary files numba writes a cache file through (another process's,
    mid-write), and after the
    edit it asks numba's own index loader what it would serve instead of compiling both kernels
    again (that took 216 of the suite's 338 s, 2026-11-24)."""
    pkg = tmp_path / "propmap"
    shutil.copytree(SRC, pkg, ignore=shutil.ignore_patterns("*.tmp.*"))
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "NUMBA_CACHE_DIR": ""}

    def run(script):
        return subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, cwd=tmp_path,
                              check=True).stdout.split()

    q0, dq0, fd0 = map(float, run(SCRIPT)[:3])  # from the copied cache, or compiled and cached here
    assert abs(dq0 - fd0) <= 1e-4 * abs(fd0)
    out = run(SCRIPT)
    q1, dq1, hits, misses, dhits, dmisses = float(out[0]), float(out[1]), *(int(x) for x in out[3:])
    assert (q1, dq1) == (q0, dq0) and hits == 1 and misses == 0 and dhits == 1 and dmisses == 0  # from the cache
    assert min(int(x) for x in run(SERVED)) >= 1  # (the copied cache may hold more overloads than this script's)
    physics = pkg / "core" / "_physics.py"
    text = physics.read_text()
    assert "cdp = kre / np.sqrt(U) + cd0\n" in text  # eq (4)'s form drag
    physics.write_text(text.replace("cdp = kre / np.sqrt(U) + cd0\n", "cdp = kre / np.sqrt(U) + 2.0 * cd0\n"))
    assert [int(x) for x in run(SERVED)] == [0, 0]  # both stale: a call compiles the edited physics
    physics.write_text(text)  # and the unedited sources are served again: the stamp is the contents
    assert min(int(x) for x in run(SERVED)) >= 1
