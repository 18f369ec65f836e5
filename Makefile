# Set-up contract: `make demo` and `make test` work on a machine with only Python and make.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test bench env clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[test]"
	touch $(STAMP)

env: $(STAMP)

demo: $(STAMP)
	$(BIN)/propmap demo

# the kernel's disk cache is stamped with every module it compiles in (core/_jitcache.py),
# so it is kept between runs: the first propmap call after make test or make demo is fast
NUMBA_CACHE := find src -name '*.nbi' -o -name '*.nbc'

# the suite in parallel processes, one per logical CPU, at most 4 (pytest-xdist): the kernels'
# first compile is much of a fresh checkout's time; the workers share it out before they collect
# (tests/kernel_warmup.py; benchmarks/README.md, Compile time)
test: $(STAMP)
	$(BIN)/python -m pytest -q -n logical --maxprocesses 4

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_solver.py
	$(BIN)/python benchmarks/bench_fit.py
	$(BIN)/python benchmarks/bench_everyday.py
	$(BIN)/python benchmarks/bench_maps.py

clean:
	$(NUMBA_CACHE) | xargs rm -f
	rm -rf $(VENV) propmap-demo
