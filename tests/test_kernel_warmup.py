"""The workers' shared first compile (tests/kernel_warmup.py), on stand-in families that only
record when they ran: each family runs once among all workers, never before its dependencies
have finished, and a failing one is named and does not hold up those that depend on it."""

import threading
import time

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
    (tmp_path / "a.claimed").touch()  # another worker took a and died
    t = time.monotonic()
    assert kernel_warmup.warm(tmp_path, wait_s=1.0) == []
    assert time.monotonic() - t < 5.0
    assert [n for e, n, _ in log if e == "start"] == ["e"]
