"""The workers' shared first compile (tests/kernel_warmup.py), on stand-in families that only
record when they ran: each family runs once among all workers, never before its dependencies
have finished, a failing one is named and does not hold up those that depend on it, nor does a
dead worker's claim; and the real families, each of which runs."""

import os
import subprocess
import sys
import threading
import time
from types import SimpleNamespace

import kernel_warmup


def _families(log, fail=()):
    def family(name, seconds):
        def call():
            log.append(("start", name, time.monotonic()))
            time.sleep(seconds)
            log.append(("end", name, time.monotonic()))
            if name in fail:
                raise RuntimeError(name)
        return call
    return (("a", family("a", 0.3), ()), ("b", family("b", 0.2), ("a",)), ("c", family("c", 0.2), ("b",)),
            ("d", family("d", 0.1), ("a",)), ("e", family("e", 0.1), ()))


def _when(log, event, name):
    return [t for e, n, t in log if e == event and n == name][0]


def test_two_workers_run_each_family_once_after_its_dependencies(tmp_path, monkeypatch):
    log = []
    monkeypatch.setattr(kernel_warmup, "FAMILIES", _families(log))
    results = []
    workers = [threading.Thread(target=lambda: results.append(kernel_warmup.warm(tmp_path, wait_s=30.0)))
               for _ in range(2)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    assert results == [[], []]
    assert sorted(n for e, n, _ in log if e == "start") == ["a", "b", "c", "d", "e"]
    for name, deps in (("b", "a"), ("c", "b"), ("d", "a")):
        assert _when(log, "start", name) >= _when(log, "end", deps), (name, log)
    assert _when(log, "start", "e") < _when(log, "end", "a")  # the other worker did not wait for a
    marks = sorted(f"{n}.{s}" for n in "abcde" for s in ("claimed", "done"))
    assert sorted(p.name for p in tmp_path.iterdir()) == marks


def test_a_failing_family_is_named_and_its_dependents_still_run(tmp_path, monkeypatch):
    log = []
    monkeypatch.setattr(kernel_warmup, "FAMILIES", _families(log, fail=("a",)))
    assert kernel_warmup.warm(tmp_path, wait_s=30.0) == ["a"]
    assert [n for e, n, _ in log if e == "start"] == ["a", "b", "c", "d", "e"]


def test_a_dependency_that_never_finishes_is_waited_for_no_longer_than_told(tmp_path, monkeypatch):
    log = []
    monkeypatch.setattr(kernel_warmup, "FAMILIES", _families(log))
    (tmp_path / "a.claimed").touch()  # another worker took a, its id not written yet
    t = time.monotonic()
    assert kernel_warmup.warm(tmp_path, wait_s=1.0) == []
    assert time.monotonic() - t < 5.0
    assert [n for e, n, _ in log if e == "start"] == ["e"]


def test_a_dead_workers_claim_does_not_hold_up_its_dependents(tmp_path, monkeypatch):
    log = []
    monkeypatch.setattr(kernel_warmup, "FAMILIES", _families(log))
    gone = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    (tmp_path / "a.claimed").write_text(gone.stdout.strip())  # a worker took a and died compiling it
    t = time.monotonic()
    assert kernel_warmup.warm(tmp_path, wait_s=30.0) == []
    assert time.monotonic() - t < 10.0
    assert sorted(n for e, n, _ in log if e == "start") == ["b", "c", "d", "e"]


def test_a_worker_goes_on_once_all_is_claimed_and_claims_exclusively(tmp_path, monkeypatch):
    """e claimed by a live worker (this process) and not done: the others run, and the worker
    returns at once instead of waiting for e; a second claim of a family is refused."""
    log = []
    monkeypatch.setattr(kernel_warmup, "FAMILIES", _families(log))
    assert kernel_warmup._claim(tmp_path, "e") and not kernel_warmup._claim(tmp_path, "e")
    assert (tmp_path / "e.claimed").read_text() == str(os.getpid())
    t = time.monotonic()
    assert kernel_warmup.warm(tmp_path, wait_s=30.0) == []
    assert time.monotonic() - t < 10.0
    assert [n for e, n, _ in log if e == "start"] == ["a", "b", "c", "d"]
    assert not (tmp_path / "e.done").exists()


def test_the_real_families_depend_on_earlier_named_ones_and_each_runs():
    """Each dependency names a family listed before it (so none waits for a name that does not
    exist, nor in a cycle), and each family's call runs (compiled by now where the suite runs
    under pytest-xdist; here it may compile). Outside a pytest-xdist worker nothing is warmed."""
    names = [f[0] for f in kernel_warmup.FAMILIES]
    assert len(set(names)) == len(names)
    position = {n: i for i, n in enumerate(names)}
    for name, _, deps in kernel_warmup.FAMILIES:
        assert all(d in position for d in deps), (name, deps)
    order = sorted(kernel_warmup.FAMILIES, key=lambda f: max([position[d] for d in f[2]], default=-1))
    done = set()
    for name, _, deps in order:  # a topological order exists
        assert set(deps) <= done, (name, deps)
        done.add(name)
    for name, call, _ in kernel_warmup.FAMILIES:
        call()
    assert kernel_warmup.maybe_warm(SimpleNamespace(option=SimpleNamespace(collectonly=False))) is None
