SHELL := /bin/bash
# Everything runs inside .venv, created on first use from requirements.txt (exact pins).
PYTHON ?= python3.11
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: setup book generate check-generated test test-fast bench clean

$(STAMP): requirements.txt pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -r requirements.txt
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation -e .
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 >/dev/null
	touch $(STAMP)

setup: $(STAMP)

## Set everything up and build the book (fails on any warning or failing cell).
book: $(STAMP)
	set -o pipefail; PYTHONPATH=$(CURDIR) $(BIN)/jupyter-book build book -n -W --keep-going 2>&1 | tee $(VENV)/book-build.log
	$(BIN)/python book/_check_offline.py book/_build/html

## Regenerate mech/_generated from the derivation notebooks.
generate: $(STAMP)
	PYTHONPATH=$(CURDIR) $(BIN)/python -m derivations

check-generated: $(STAMP)
	PYTHONPATH=$(CURDIR) $(BIN)/python -m derivations --check

## The test suite (doctests included).
test: $(STAMP)
	$(BIN)/python -m pytest

test-fast: $(STAMP)
	$(BIN)/python -m pytest -m "not slow"

## Benchmarks need pylinkage and numba (not in requirements.txt); results go to benchmarks/results.
bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -r benchmarks/requirements.txt
	$(BIN)/python benchmarks/bench_coupler_curve.py

clean:
	rm -rf book/_build
