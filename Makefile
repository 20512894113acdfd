SHELL := /bin/bash
# Everything runs inside .venv, created on first use from requirements.txt (exact pins).
PYTHON ?= python3.11
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: setup browser-deps book generate check-generated test test-fast bench clean

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

## Set everything up and build the book (fails on any warning or failing cell).
book: $(STAMP)
	set -o pipefail; PYTHONPATH=$(CURDIR) $(BIN)/jupyter-book build book -n -W --keep-going 2>&1 | tee $(VENV)/book-build.log
	$(BIN)/python book/_check_offline.py book/_build/html
	# the whole book as one PDF, printed offline by Chromium (book/_pdf.py), linked from the landing page
	$(BIN)/python book/_pdf.py book/_build/html

## Regenerate mech/_generated from the derivation notebooks.
generate: $(STAMP)
	PYTHONPATH=$(CURDIR) $(BIN)/python -m derivations

check-generated: $(STAMP)
	PYTHONPATH=$(CURDIR) $(BIN)/python -m derivations --check

## System packages of the browser test (tests/browser): Debian's chromium, a CJK font and
## an OpenType math font for the MathML (Latin Modern Math), and poppler-utils (pdftoppm, to look
## at the book's PDF as pictures), installed with apt-get only
## when missing (as root, or with password-less sudo).
CHROME_DEBS := chromium fonts-noto-cjk fonts-lmodern poppler-utils
browser-deps:
	@if command -v chromium >/dev/null && fc-list :lang=zh 2>/dev/null | grep -q . \
	    && fc-list 2>/dev/null | grep -q "Latin Modern Math" && command -v pdftoppm >/dev/null; then :; \
	elif [ "$$(id -u)" = 0 ]; then \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y $(CHROME_DEBS); \
	elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then \
	  sudo apt-get update && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y $(CHROME_DEBS); \
	else \
	  echo "browser-deps: chromium, a CJK font or the math font is missing and apt-get needs root;" \
	       "the browser test will skip (and fail with MECH_BROWSER_TEST=required)"; \
	fi

## The test suite (doctests included), the browser test of the built book among them.
test: $(STAMP) browser-deps
	$(BIN)/python -m pytest

test-fast: $(STAMP)
	$(BIN)/python -m pytest -m "not slow"

## Benchmarks need pylinkage and numba (not in requirements.txt); results go to benchmarks/results.
bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -r benchmarks/requirements.txt
	$(BIN)/python benchmarks/bench_coupler_curve.py

clean:
	rm -rf book/_build
