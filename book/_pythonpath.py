"""Sphinx extension: the repository root on the path of the build and of every kernel.

`derivations` (the code generator) and `figures` (the plot scripts) are not installed with
`mech`: the wheel holds `mech` alone. The book's pages import them from the source tree, so
this extension, loaded first through ``local_extensions`` in ``_config.yml``, puts the
repository root on ``sys.path`` and at the front of ``PYTHONPATH``, which the notebook
kernels inherit.
"""

import os
import sys
from pathlib import Path

ROOT = str(Path(__file__).resolve().parent.parent)


def setup(app):
    if ROOT not in sys.path:
        sys.path.insert(0, ROOT)
    parts = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    if ROOT not in parts:
        os.environ["PYTHONPATH"] = os.pathsep.join([ROOT] + parts)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
