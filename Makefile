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

# numba keys its disk cache on _kernel.py alone; drop it so that edits to the physics it
# inlines (_physics.py, _fastmath.py) are always compiled into what the tests run
NUMBA_CACHE := find src -name '*.nbi' -o -name '*.nbc'

test: $(STAMP)
	$(NUMBA_CACHE) | xargs rm -f
	$(BIN)/python -m pytest -q

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_solver.py
	$(BIN)/python benchmarks/bench_fit.py

clean:
	$(NUMBA_CACHE) | xargs rm -f
	rm -rf $(VENV) propmap-demo
