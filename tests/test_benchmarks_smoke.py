"""The benchmarks' own code against the package it measures (not a timing: benchmarks/README.md
gives those). `make bench` failed at its first step, bench_solver's SIMD probe calling the
residual without its newest argument (found 2026-11-27; the figures it reports had not been
re-measured since the signature changed)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"


def _module(name: str):
    spec = importlib.util.spec_from_file_location(name, BENCHMARKS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_solver_benchmarks_simd_probe_compiles_the_residual_as_the_kernel_calls_it():
    widths = _module("bench_solver").simd_widths()
    assert widths and set(widths) <= {2, 4, 8}  # doubles per vector: SSE2, AVX2, AVX-512


def test_the_peer_benchmark_without_dynbem_says_how_to_install_it_and_exits_0(monkeypatch, capsys):
    """bench_peers.py is run from a checkout that may lack its optional peer: one line, exit 0."""
    import sys

    import pytest

    module = _module("bench_peers")
    monkeypatch.setitem(sys.modules, "dynbem", None)  # (import dynbem raises ImportError)
    monkeypatch.setattr(sys, "argv", ["bench_peers.py", "--points", "10"])
    with pytest.raises(SystemExit) as stop:
        module.main()
    assert stop.value.code == 0
    out = capsys.readouterr().out
    assert out.count("\n") == 1 and "pip install \"dynbem>=0.8,<0.9\"" in out


def test_the_single_call_benchmark_times_each_path_it_reports():
    """bench_everyday's one-point figures (the call, the kernel alone, rotor_wrench and, since
    2026-11-29, one full-model step of the example quadrotor) run against the package."""
    import propmap as pm

    res = _module("bench_everyday").single_call(pm.preset("gill2017-apc"), n=3)
    assert set(res) == {"rotor_loads_us_median", "kernel_us_median", "wrapper_us", "ratio_call_to_kernel",
                        "rotor_wrench_us_median", "ratio_wrench_to_loads", "vehicle_step_us_median",
                        "ratio_vehicle_step_to_loads"}
    assert all(v > 0 for k, v in res.items() if k != "wrapper_us")
