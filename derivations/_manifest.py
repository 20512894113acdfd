"""The freshness manifest: which notebook code and which generator produced each generated module.

Re-running every notebook (``python -m derivations --check``) is the full freshness check, and
it takes minutes. The manifest ``derivations/manifest.json`` lets the fast test run check the
same thing by hashes alone: for each notebook that writes code it records

- ``code``: the SHA-256 of the notebook's code cells (prose edits do not count),
- ``generator``: the SHA-256 of the generator's own source (every ``derivations/*.py`` but this
  file and the runner ``__main__.py``), since a changed template or printer changes what the
  notebooks write,
- ``modules``: the SHA-256 of each module the notebook wrote (``<stem>.py`` and, where it has
  kernels, ``<stem>_numba.py``), as they stood after the notebook ran.

``python -m derivations`` (which runs the notebooks and rewrites stale modules) refreshes the
entries of the notebooks it ran; ``--check`` writes nothing. A fast test compares the manifest
with the files on disk; the slow test re-runs the notebooks and then asks the same question.

The check record. ``make book`` executes every derivation notebook with ``MECH_CODEGEN=check``
and ``MECH_CODEGEN_RECORD`` naming a file: each ``_codegen.write`` that passed its check there
appends the notebook's entry as it stood then (one JSON line). A notebook whose recorded entry
equals its entry now was checked, numbers against mpmath included, on exactly this code, this
generator and these modules, so the slow test does not run it again (``checked``).
"""

import ast
import hashlib
import json
import os
import re
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
MANIFEST = HERE / "manifest.json"
# the check record of `python -m derivations --check` on this checkout (not committed)
LOCAL_RECORD = HERE / ".checked.jsonl"
# the packages of the repository whose source a notebook's checks can depend on
PROJECT_PACKAGES = ("mech", "derivations", "figures")
GENERATED_DIR = HERE.parent / "mech" / "_generated"

__all__ = ["MANIFEST", "LOCAL_RECORD", "RECORD_ENV", "written_stems", "entry", "read", "record",
           "stale", "imported_files", "check_entry", "note_checked", "checked"]

RECORD_ENV = "MECH_CODEGEN_RECORD"


def _sha(data):
    return "sha256:" + hashlib.sha256(data).hexdigest()


def written_stems(path):
    """The stems that a notebook passes to ``_codegen.write``, in order of appearance."""
    return re.findall(r"_codegen\.write\(\s*\"([a-z0-9_]+)\"", Path(path).read_text())


def _code_hash(path):
    from derivations.__main__ import code_cells

    # the cells joined with a separator that no cell contains, so that moving a line from one
    # cell to the next still changes the hash
    return _sha("\n\x00\n".join(code_cells(path)).encode())


# the runner, this bookkeeping and the proof helper do not shape what a notebook writes
NOT_GENERATOR = ("__main__.py", "_manifest.py", "_zero.py")


def _generator_hash():
    parts = []
    for p in sorted(HERE.glob("*.py")):
        if p.name not in NOT_GENERATOR:
            parts.append(p.name.encode() + b"\x00" + p.read_bytes())
    return _sha(b"\x00\x00".join(parts))


def _module_files(stem):
    files = [GENERATED_DIR / f"{stem}.py"]
    numba = GENERATED_DIR / f"{stem}_numba.py"
    return files + [numba] if numba.exists() else files


def entry(path):
    """The manifest entry that the notebook at ``path`` and the files on disk call for now."""
    modules = {}
    for stem in written_stems(path):
        for f in _module_files(stem):
            modules[f.name] = _sha(f.read_bytes()) if f.exists() else "missing"
    return {"code": _code_hash(path), "generator": _generator_hash(), "modules": modules}


def _key(path):
    return Path(path).resolve().relative_to(HERE).as_posix()


def read():
    """The recorded manifest, ``{notebook relative to derivations/: entry}``."""
    return json.loads(MANIFEST.read_text()) if MANIFEST.exists() else {}


def record(paths):
    """Refresh the entries of the notebooks at ``paths`` (after they ran and wrote)."""
    data = read()
    for path in paths:
        if written_stems(path):
            data[_key(path)] = entry(path)
    # one notebook a block, sorted: concurrent edits of different notebooks merge cleanly
    MANIFEST.write_text(json.dumps(dict(sorted(data.items())), indent=1, sort_keys=True) + "\n")


def stale(path):
    """Why the notebook at ``path`` does not match its manifest entry ("" when it does)."""
    recorded = read().get(_key(path))
    if recorded is None:
        return f"{_key(path)} has no entry in derivations/manifest.json"
    now = entry(path)
    reasons = []
    if recorded["code"] != now["code"]:
        reasons.append("its code cells changed")
    if recorded["generator"] != now["generator"]:
        reasons.append("the generator (derivations/*.py) changed")
    for name in sorted(set(recorded["modules"]) | set(now["modules"])):
        if recorded["modules"].get(name) != now["modules"].get(name):
            reasons.append(f"mech/_generated/{name} differs from the one it wrote")
    if not reasons:
        return ""
    return (f"{_key(path)}: " + "; ".join(reasons)
            + " since the manifest was recorded: run `python -m derivations " + _key(path) + "`")


def _module_file(name):
    base = ROOT.joinpath(*name.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


def _project_imports(source, package):
    """The dotted names of the project's modules that ``source`` imports (``package``: the
    package that relative imports start from)."""
    names = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parent = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(parent + ([base] if base else []))
            names.add(base)
            # `from mech.planar import _fourbar` imports a module, `... import FourBar` a name
            names.update(f"{base}.{alias.name}" for alias in node.names)
    wanted = set()
    for name in names:
        parts = name.split(".")
        if parts[0] in PROJECT_PACKAGES:
            # importing a.b.c runs a/__init__.py and a/b/__init__.py first
            wanted.update(".".join(parts[: k + 1]) for k in range(len(parts)))
    return wanted


def imported_files(path):
    """The project's source files that the notebook at ``path`` imports, directly or through
    the modules it imports (static ``import`` statements, followed through the repository)."""
    from derivations.__main__ import code_cells

    lines = [ln for cell in code_cells(path) for ln in cell.splitlines()
             if not ln.lstrip().startswith(("%", "!"))]
    todo, files = list(_project_imports("\n".join(lines), "")), set()
    seen = set()
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        f = _module_file(name)
        if f is None or f in files:
            continue
        files.add(f)
        package = name if f.name == "__init__.py" else name.rpartition(".")[0]
        todo.extend(_project_imports(f.read_text(), package))
    return sorted(files)


def check_entry(path):
    """What a passed check of the notebook at ``path`` stands for: its manifest entry and
    the source of every project module its code imports (the checks compare with them)."""
    parts = [f.relative_to(ROOT).as_posix().encode() + b"\x00" + f.read_bytes()
             for f in imported_files(path)]
    return {**entry(path), "imports": _sha(b"\x00\x00".join(parts))}


def note_checked(notebook):
    """Append the entry of ``notebook`` (relative to the repository) to the check record.

    Called by ``_codegen.write`` after a check passed in check mode; does nothing unless the
    environment variable ``MECH_CODEGEN_RECORD`` names the record file.
    """
    target = os.environ.get(RECORD_ENV)
    if not target:
        return
    path = ROOT / notebook
    line = json.dumps({"notebook": _key(path), "entry": check_entry(path)}, sort_keys=True)
    # one short line in append mode: notebooks executed side by side do not interleave
    with open(target, "a") as f:
        f.write(line + "\n")


def checked(path, record_file):
    """Whether ``record_file`` holds a passed check of the notebook at ``path`` with the
    entry that its code, the generator, its modules and the project modules it imports call
    for now."""
    record_file = Path(record_file)
    if not record_file.exists():
        return False
    key, now = _key(path), check_entry(path)
    for line in record_file.read_text().splitlines():
        try:
            item = json.loads(line)
        except json.JSONDecodeError:
            continue
        if item.get("notebook") == key and item.get("entry") == now:
            return True
    return False
