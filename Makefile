SHELL := /bin/bash
# Everything runs inside .venv, created on first use from requirements.txt (exact pins).
PYTHON ?= python3.11
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: setup browser-deps node-deps book generate check-generated test test-fast test-exhaustive bench clean

$(STAMP): requirements.txt pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -r requirements.txt
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation -e .
	# The project's own environment (not the wheel) also sees the source tree's `derivations`
	# and `figures`, so a derivation notebook downloaded from the book runs from any folder.
	$(BIN)/python -c "import sysconfig, pathlib; pathlib.Path(sysconfig.get_paths()['purelib'], 'mech-source-tree.pth').write_text('$(CURDIR)\n')"
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 >/dev/null
	touch $(STAMP)

setup: $(STAMP)

## Set everything up and build the book (fails on any warning or failing cell): `jupyter-book
## build` with Sphinx's parallel jobs (book/_build_book.py), pages read and executed on every core.
book: $(STAMP) browser-deps node-deps
	# The derivation pages run in check mode: a stale generated module fails the build (it is
	# never rewritten by it), and each passed check goes to a record the slow freshness test reads.
	mkdir -p book/_build
	set -o pipefail; MECH_CODEGEN=check MECH_CODEGEN_RECORD=$(CURDIR)/book/_build/codegen-checks.jsonl \
	  PYTHONPATH=$(CURDIR) $(BIN)/python book/_build_book.py book -n -W --keep-going 2>&1 | tee $(VENV)/book-build.log
	$(BIN)/python book/_check_offline.py book/_build/html
	# the whole book as one PDF, printed offline by Chromium (book/_pdf.py), linked from the landing page
	$(BIN)/python book/_pdf.py book/_build/html

## Regenerate mech/_generated from the derivation notebooks whose inputs changed (a hash of each
## notebook's code, the generator and its modules; ARGS=--all runs every one).
## (and book/_static/kernels, the JavaScript backend, checked under Node when installed)
generate: $(STAMP) node-deps
	PYTHONPATH=$(CURDIR) $(BIN)/python -m derivations $(ARGS)

## Check every generated module against its notebook, writing nothing: only the notebooks not
## yet checked on this checkout with the same inputs and imported modules (ARGS=--all: all).
check-generated: $(STAMP) node-deps
	PYTHONPATH=$(CURDIR) $(BIN)/python -m derivations --check $(ARGS)

## Debian's nodejs: runs the generated JavaScript kernels in tests/generated/test_js_kernels.py
## and in the generator's numeric check, and draws the live design figures' first state when
## the book is built (figures/live_design.py); installed with apt-get only when missing.
node-deps:
	@if command -v node >/dev/null; then :; \
	elif [ "$$(id -u)" = 0 ]; then \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y nodejs; \
	elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then \
	  sudo apt-get update && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y nodejs; \
	else \
	  echo "node-deps: node is missing and apt-get needs root; the JavaScript kernel test will skip"; \
	fi

## System packages of the browser test (tests/browser): Debian's chromium, a CJK font and
## an OpenType math font for the MathML (Latin Modern Math), and poppler-utils (pdftotext and
## pdftoppm: the book's PDF and the exercise sheets' PDFs are read back as text and pictures in
## the tests), installed with apt-get only when missing (as root, or with password-less sudo).
## `make book` needs them too: the book's PDF is printed by Chromium.
CHROME_DEBS := chromium fonts-noto-cjk fonts-lmodern poppler-utils
browser-deps:
	@if command -v chromium >/dev/null && command -v pdftotext >/dev/null && command -v pdftoppm >/dev/null \
	    && fc-list :lang=zh 2>/dev/null | grep -q . && fc-list 2>/dev/null | grep -q "Latin Modern Math"; then :; \
	elif [ "$$(id -u)" = 0 ]; then \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y $(CHROME_DEBS); \
	elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then \
	  sudo apt-get update && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y $(CHROME_DEBS); \
	else \
	  echo "browser-deps: chromium, a CJK font or the math font is missing and apt-get needs root;" \
	       "the browser test will skip (and fail with MECH_BROWSER_TEST=required)"; \
	fi

## The test suite (doctests included), the browser test of the built book among them, on every
## core (pytest-xdist); a file's tests stay in one process, so a file's session fixture (the
## crawl of the built book) runs once.
XDIST := -n auto --dist loadfile
# the slowest tests of the run are listed at its end, so a CI log shows where the time goes
DURATIONS := --durations=30
test: $(STAMP) browser-deps node-deps
	$(BIN)/python -m pytest $(XDIST) $(DURATIONS)

test-fast: $(STAMP) node-deps
	$(BIN)/python -m pytest $(XDIST) -m "not slow and not exhaustive"

## The acceptance sweeps left out of `make test` (a whole class of 30 for every exercise,
## 1,000 seeds of every exercise): tens of minutes.
test-exhaustive: $(STAMP) browser-deps node-deps
	$(BIN)/python -m pytest $(XDIST) -m exhaustive

## Benchmarks need pylinkage and numba (not in requirements.txt); results go to benchmarks/results.
bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -r benchmarks/requirements.txt
	$(BIN)/python benchmarks/bench_coupler_curve.py

clean:
	rm -rf book/_build
