"""The compiled kernel's disk cache never serves a kernel built from older physics.

numba alone stamps the cache with the kernel file only; propmap's locators
(core/_jitcache.py) stamp it with every module the kernel compiles in.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from propmap.core import _jitcache, _kernel

SRC = Path(_kernel.__file__).resolve().parents[1]  # .../propmap

SCRIPT = ("import propmap as pm; from propmap.core import _kernel as K; "
          "r = pm.rotor_loads(pm.load_propeller('apce_8x6'), pm.preset('gill2017-apc'), 800.0, 5.0, 1.0); "
          "s = K.solve_batch_serial.stats; print(repr(float(r.torque)), sum(s.cache_hits.values()), "
          "sum(s.cache_misses.values()))")


def test_the_stamp_covers_every_module_the_kernel_compiles_in(tmp_path):
    names = {p.name for p in _jitcache.KERNEL_SOURCES}
    assert names == {"_kernel.py", "_physics.py", "_fastmath.py"}
    assert {p.name for p in _jitcache.SENSITIVITY_SOURCES} == names | {"_sensitivity.py"}
    assert _jitcache.CACHE
    a, b = tmp_path / "a.py", tmp_path / "b.py"
    a.write_text("x = 1\n")
    b.write_text("y = 2\n")
    before = _jitcache.sources_stamp([a, b])
    b.write_text("y = 3\n")
    assert _jitcache.sources_stamp([a, b]) != before


def test_editing_the_physics_recompiles_instead_of_serving_the_cached_kernel(tmp_path):
    """A warm cache, then edit _physics.py (here: eq 4's form drag doubled)."""
    pkg = tmp_path / "propmap"
    shutil.copytree(SRC, pkg, ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "NUMBA_CACHE_DIR": ""}

    def run():
        out = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, env=env, cwd=tmp_path,
                             check=True).stdout.split()
        return float(out[0]), int(out[1]), int(out[2])

    q0, hits, misses = run()
    assert misses >= 1 and hits == 0  # compiled and cached
    q1, hits, misses = run()
    assert q1 == q0 and hits == 1 and misses == 0  # served from the cache
    physics = pkg / "core" / "_physics.py"
    text = physics.read_text()
    assert "+ cd0  # eq (4)" in text
    physics.write_text(text.replace("+ cd0  # eq (4)", "+ 2.0 * cd0  # eq (4)"))
    q2, hits, misses = run()
    assert hits == 0 and q2 > q0  # recompiled: more form drag, more torque


SENS_SCRIPT = ("import propmap as pm; from propmap.core import _sensitivity as S; "
               "r = pm.rotor_loads(pm.load_propeller('apce_8x6'), pm.generic_params(), 800.0, 5.0, 1.0, "
               "derivatives=('cd_min',)); "
               "s = S.sensitivities.stats; print(repr(float(r.derivative('torque', 'cd_min'))), "
               "sum(s.cache_hits.values()), sum(s.cache_misses.values()))")


def test_editing_the_physics_recompiles_the_sensitivity_kernel(tmp_path):
    """The sensitivity kernel inlines the physics too (it was stamped with its own file only
    until 2026-11-23): a warm cache, then an edit of _physics.py (the cambered drag's
    Reynolds factor doubled) must recompile it, not serve the derivatives of the old model."""
    pkg = tmp_path / "propmap"
    shutil.copytree(SRC, pkg, ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "NUMBA_CACHE_DIR": ""}

    def run():
        out = subprocess.run([sys.executable, "-c", SENS_SCRIPT], capture_output=True, text=True, env=env,
                             cwd=tmp_path, check=True).stdout.split()
        return float(out[0]), int(out[1]), int(out[2])

    d0, hits, misses = run()
    assert misses >= 1 and hits == 0
    d1, hits, misses = run()
    assert d1 == d0 and hits == 1 and misses == 0
    physics = pkg / "core" / "_physics.py"
    text = physics.read_text()
    old = "return a, np.exp(re_exp * ln_re), g, alpha_L0_re * ln_re"
    assert old in text
    physics.write_text(text.replace(old, "return a, 2.0 * np.exp(re_exp * ln_re), g, alpha_L0_re * ln_re"))
    d2, hits, misses = run()
    assert hits == 0 and d2 > 1.5 * d0  # recompiled: the drag factor doubled doubles dQ/dcd_min

