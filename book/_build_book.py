"""``jupyter-book build`` with Sphinx's parallel jobs: the pages are read, and their notebooks
executed, on every core.

Jupyter Book 1's ``build_sphinx`` takes a ``jobs`` argument, but its command line never passes
one, so a build reads (and executes) one page after another. This runs the same command with
``jobs`` set: ``MECH_BOOK_JOBS`` processes (default: the machine's cores). Every extension the
book loads declares itself safe for parallel reading.

    python book/_build_book.py book -n -W --keep-going      # the arguments of `jupyter-book build`
"""

import functools
import os
import sys

from jupyter_book import sphinx as jb_sphinx
from jupyter_book.cli import main as jb_main


def jobs():
    value = os.environ.get("MECH_BOOK_JOBS", "")
    if value:
        if not value.isdigit() or int(value) < 1:
            raise SystemExit(f"MECH_BOOK_JOBS must be a positive whole number, got {value!r}")
        return int(value)
    return os.cpu_count() or 1


def main(argv=None):
    # the command imports `build_sphinx` from its module when it runs, so the module's name
    # is the one to replace
    jb_sphinx.build_sphinx = functools.partial(jb_sphinx.build_sphinx, jobs=jobs())
    jb_main.main(["build", *(sys.argv[1:] if argv is None else argv)])


if __name__ == "__main__":
    main()
