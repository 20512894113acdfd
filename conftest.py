"""Collection rules for the whole repository (pytest's `testpaths` are tests/ and mech/)."""

import importlib.util
import os
from pathlib import Path

import pytest
from hypothesis import settings

# The numba kernels are an optional extra (`mech[fast]`); without numba their modules cannot
# be imported, so their doctests are not collected. tests/test_backends.py skips likewise.
collect_ignore_glob = [] if importlib.util.find_spec("numba") else ["mech/_generated/*_numba.py"]

# Under CI the property-based tests draw the same examples on every run, so a landing's
# result does not depend on luck; a developer's run keeps exploring new examples.
settings.register_profile("ci", derandomize=True)
if os.environ.get("CI"):
    settings.load_profile("ci")


# Tests measured as slow are listed in tests/slow_tests.txt (one test function a line, all its
# parameters together; written by `python tests/slow_list.py`), and marked `slow` here, so
# that `make test-fast` (`pytest -m "not slow"`) stays short without a marker in each file.
# `make test` runs them all.
_SLOW_LIST = Path(__file__).resolve().parent / "tests" / "slow_tests.txt"


def _slow_functions():
    if not _SLOW_LIST.exists():
        return set()
    return {line.split("\t")[-1].strip() for line in _SLOW_LIST.read_text().splitlines()
            if line.strip() and not line.startswith("#")}


def pytest_collection_modifyitems(config, items):
    slow = _slow_functions()
    for item in items:
        if item.nodeid.split("[")[0] in slow:
            item.add_marker(pytest.mark.slow)
