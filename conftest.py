"""Collection rules for the whole repository (pytest's `testpaths` are tests/ and mech/)."""

import importlib.util
import os

from hypothesis import settings

# The numba kernels are an optional extra (`mech[fast]`); without numba their modules cannot
# be imported, so their doctests are not collected. tests/test_backends.py skips likewise.
collect_ignore_glob = [] if importlib.util.find_spec("numba") else ["mech/_generated/*_numba.py"]

# Under CI the property-based tests draw the same examples on every run, so a landing's
# result does not depend on luck; a developer's run keeps exploring new examples.
settings.register_profile("ci", derandomize=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
