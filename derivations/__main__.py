"""Regenerate every module of ``mech/_generated`` (and its JavaScript twin in
``book/_static/kernels``) from the derivation notebooks.

    python -m derivations            # run the notebooks whose manifest entry is stale
    python -m derivations --check    # run, writing nothing, those not checked on these inputs
    python -m derivations --all      # every notebook (also with --check)
    python -m derivations planar/grashof.md   # only the named notebooks

A run that writes also refreshes the notebooks' entries in ``derivations/manifest.json``
(see ``_manifest.py``), which the fast test run checks by hashes instead of re-running. A
writing run skips a notebook whose code, generator and generated modules still match its
entry (it would write nothing). A check skips a notebook that an earlier check on this
checkout passed on the same code, generator, generated modules and imported project modules
(the record ``derivations/.checked.jsonl``, not committed).

Each notebook's code cells are run in order in a fresh namespace, without a Jupyter kernel;
the notebook's own asserts (its proofs) and its final ``_codegen.write`` call do the work.
A full run costs about four minutes of CPU time (each notebook alone, measured under load:
the 34 notebooks measured before and after the cheaper identity proofs of ``_zero.py`` went
from 309 to about 230 CPU seconds), so about that long on a quiet machine: name the notebooks
you changed to regenerate only those.
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
    parser.add_argument("--all", action="store_true", help="run every notebook, changed or not")
    parser.add_argument("names", nargs="*", help="notebooks relative to derivations/")
    args = parser.parse_args(argv)
    from derivations import _manifest

    if args.check:
        os.environ["MECH_CODEGEN"] = "check"
        os.environ.setdefault(_manifest.RECORD_ENV, str(_manifest.LOCAL_RECORD))
    paths = [HERE / n for n in args.names] if args.names else notebooks()
    if not (args.all or args.names):
        if args.check:
            todo = [p for p in paths if not _manifest.checked(p, os.environ[_manifest.RECORD_ENV])]
        else:
            todo = [p for p in paths if _manifest.written_stems(p) and _manifest.stale(p)]
        for path in sorted(set(paths) - set(todo)):
            print(f"{path.relative_to(HERE)}: unchanged since its last "
                  + ("check" if args.check else "run") + " (--all runs it)")
        paths = todo
    for path in paths:
        start = time.perf_counter()
        run(path)
        if args.check and not _manifest.written_stems(path):
            # a notebook that writes is noted by its own check; one that does not, here
            _manifest.note_checked(path.relative_to(HERE.parent).as_posix())
        print(f"{path.relative_to(HERE)}: ok ({time.perf_counter() - start:.1f} s)")
    if not args.check:
        _manifest.record(paths)
    return 0


if __name__ == "__main__":
    sys.exit(main())
