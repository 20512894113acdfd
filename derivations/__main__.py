"""Regenerate every module of ``mech/_generated`` (and its JavaScript twin in
``book/_static/kernels``) from the derivation notebooks.

    python -m derivations            # run every notebook; rewrite modules whose inputs changed
    python -m derivations --check    # run them without writing; fail if any module is stale
    python -m derivations planar/grashof.md   # only the named notebooks

A run that writes also refreshes the notebooks' entries in ``derivations/manifest.json``
(see ``_manifest.py``), which the fast test run checks by hashes instead of re-running.

Each notebook's code cells are run in order in a fresh namespace, without a Jupyter kernel;
the notebook's own asserts (its proofs) and its final ``_codegen.write`` call do the work.
A full run takes about 20 minutes on a quiet two-core machine: name the notebooks you
changed to regenerate only those.
"""

import argparse
import os
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


def notebooks():
    """Every derivation notebook, in a stable order."""
    return sorted(p for p in HERE.rglob("*.md") if p.parent != HERE)


def code_cells(path):
    import jupytext

    nb = jupytext.read(path)
    return [c.source for c in nb.cells if c.cell_type == "code"]


def run(path):
    """Execute the code cells of one notebook, with the notebook's folder as working dir."""
    import matplotlib

    matplotlib.use("Agg")
    namespace = {"__name__": "__derivation__", "__file__": str(path)}
    cwd = os.getcwd()
    os.chdir(path.parent)
    try:
        for i, source in enumerate(code_cells(path)):
            lines = [ln for ln in source.splitlines() if not ln.lstrip().startswith(("%", "!"))]
            exec(compile("\n".join(lines), f"{path.name}[cell {i}]", "exec"), namespace)
    finally:
        os.chdir(cwd)
    return namespace


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m derivations", description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="check freshness, write nothing")
    parser.add_argument("names", nargs="*", help="notebooks relative to derivations/")
    args = parser.parse_args(argv)
    if args.check:
        os.environ["MECH_CODEGEN"] = "check"
    paths = [HERE / n for n in args.names] if args.names else notebooks()
    for path in paths:
        start = time.perf_counter()
        run(path)
        print(f"{path.relative_to(HERE)}: ok ({time.perf_counter() - start:.1f} s)")
    if not args.check:
        from derivations import _manifest

        _manifest.record(paths)
    return 0


if __name__ == "__main__":
    sys.exit(main())
