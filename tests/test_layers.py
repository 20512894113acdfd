"""The layers of ``ARCHITECTURE.md``, enforced on the import graph of ``mech``.

The graph is read statically with `ast`, from every ``import`` and ``from ... import`` of
the package's source: at module level AND inside functions, since an import inside a
function still makes the importing module depend on the imported one (it only hides a cycle
until the function runs). Imports of other libraries (NumPy, SciPy, Matplotlib, Dask,
numba, SymPy) are not edges: only ``mech`` modules are nodes.

Three rules, each with a test that it holds and a test that it can fail (on a small
package planted in a temporary folder):

- no cycle among ``mech`` modules;
- no upward import: a module imports only from its own layer or lower ones, in the order
  that ``ARCHITECTURE.md`` lists (a package's ``__init__`` may also import its own
  submodules, which it re-exports);
- no private name (``_x``) imported from another subpackage, except from the internal
  modules that ``ARCHITECTURE.md`` lists.
"""

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
ARCHITECTURE = ROOT / "ARCHITECTURE.md"


# ----------------------------------------------------------------------------- the graph
def modules(package_dir):
    """``{dotted name: (path, is_package)}`` of every ``.py`` file under `package_dir`."""
    out = {}
    base = package_dir.parent
    for path in sorted(package_dir.rglob("*.py")):
        parts = list(path.relative_to(base).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        if is_package:
            parts = parts[:-1]
        out[".".join(parts)] = (path, is_package)
    return out


def _absolute(module, is_package, node):
    """The absolute module named by an ``ImportFrom`` node (relative imports resolved)."""
    if not node.level:
        return node.module
    base = module.split(".") if is_package else module.split(".")[:-1]
    base = base[:len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _known(name, mods):
    """`name`, or the nearest enclosing module of it that is in `mods` (None if none)."""
    while name and name not in mods:
        name = name.rpartition(".")[0]
    return name or None


def import_edges(package_dir):
    """Every import between modules of the package: a list of dicts.

    Keys: ``src``, ``dst`` (modules of the package), ``name`` (the name imported by a
    ``from`` import, ``None`` for a module), ``line``, ``in_function`` (the import is
    inside a function or method).
    """
    mods = modules(package_dir)
    top = package_dir.name
    edges = []
    for module, (path, is_package) in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        nested = set()
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                nested.update(id(sub) for sub in ast.walk(node) if sub is not node)
        for node in ast.walk(tree):
            inside = id(node) in nested
            if isinstance(node, ast.Import):
                for alias in node.names:
                    dst = _known(alias.name, mods)
                    if alias.name.split(".")[0] == top and dst and dst != module:
                        edges.append(dict(src=module, dst=dst, name=None, line=node.lineno, in_function=inside))
            elif isinstance(node, ast.ImportFrom):
                base = _absolute(module, is_package, node)
                if not base or base.split(".")[0] != top:
                    continue
                for alias in node.names:
                    full = f"{base}.{alias.name}"
                    if full in mods:                 # a submodule imported by name
                        dst, name = full, None
                    else:
                        dst, name = _known(base, mods), alias.name
                    if dst and dst != module:
                        edges.append(dict(src=module, dst=dst, name=name, line=node.lineno, in_function=inside))
    return edges


# ----------------------------------------------------------------------------- the rules
def cycles(edges):
    """The strongly connected components of more than one module (Tarjan), each sorted."""
    graph = {}
    for e in edges:
        graph.setdefault(e["src"], set()).add(e["dst"])
        graph.setdefault(e["dst"], set())
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(v):
        # iterative depth-first search: the package is deep enough to strain recursion
        work = [(v, iter(sorted(graph[v])))]
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    comp.append(w)
                    if w == node:
                        break
                if len(comp) > 1:
                    out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(out)


def layer_of(module, layers):
    """Index of the layer of `module`: the layer holding its longest matching prefix."""
    best, found = -1, None
    for k, prefixes in enumerate(layers):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and len(prefix) > best:
                best, found = len(prefix), k
    return found


def upward(edges, layers, packages):
    """Edges from a module to a higher layer (a package's ``__init__`` into its own subtree excepted)."""
    bad = []
    for e in edges:
        src, dst = e["src"], e["dst"]
        if src in packages and dst.startswith(src + "."):
            continue
        if layer_of(dst, layers) > layer_of(src, layers):
            bad.append(e)
    return bad


def subpackage(module, packages):
    return module if module in packages else module.rpartition(".")[0]


def private_crossings(edges, packages, internal):
    """Imports of a private name from another subpackage, not from an internal module."""
    return [e for e in edges
            if e["name"] is not None and e["name"].startswith("_") and not e["name"].startswith("__")
            and subpackage(e["src"], packages) != subpackage(e["dst"], packages)
            and not any(e["dst"] == m or e["dst"].startswith(m + ".") for m in internal)]


def declared(text=None):
    """The layers (bottom first, each a list of module prefixes) and the internal modules
    that ``ARCHITECTURE.md`` declares, read from its numbered list under "## Layers" and its
    bullet list under "## Internal modules"."""
    text = ARCHITECTURE.read_text(encoding="utf-8") if text is None else text
    sections = dict(re.findall(r"^## (.+?)\n(.*?)(?=^## |\Z)", text, flags=re.M | re.S))
    layers = [re.findall(r"`(mech[\w.]*)`", line.split(":")[0])
              for line in sections["Layers"].splitlines() if re.match(r"\d+\. ", line)]
    internal = [re.findall(r"`(mech[\w.]*)`", line)[0]
                for line in sections["Internal modules"].splitlines() if line.startswith("- `")]
    return layers, internal


def _show(edges):
    return "\n".join(f"  {e['src']}:{e['line']} -> {e['dst']}" + (f" ({e['name']})" if e["name"] else "")
                     + (" [in a function]" if e["in_function"] else "") for e in edges)


# ----------------------------------------------------------------------------- the package
PACKAGE = ROOT / "mech"
EDGES = import_edges(PACKAGE)
MODULES = modules(PACKAGE)
PACKAGES = {m for m, (_, is_package) in MODULES.items() if is_package}
LAYERS, INTERNAL = declared()


def test_architecture_declares_layers_and_internal_modules():
    assert len(LAYERS) >= 10 and all(LAYERS)
    assert "mech._validate" in INTERNAL and "mech._geometry" in INTERNAL
    for module in INTERNAL:
        assert module in MODULES, f"ARCHITECTURE.md lists {module}, which does not exist"


def test_every_module_has_a_layer():
    missing = sorted(m for m in MODULES if layer_of(m, LAYERS) is None)
    assert not missing, f"modules in no layer of ARCHITECTURE.md: {missing}"


def test_no_import_cycle():
    found = cycles(EDGES)
    assert not found, "import cycles (function-level imports counted):\n" + "\n".join(map(str, found))


def test_no_upward_import():
    bad = upward(EDGES, LAYERS, PACKAGES)
    assert not bad, "imports of a higher layer:\n" + _show(bad)


def test_no_private_name_across_subpackages():
    bad = private_crossings(EDGES, PACKAGES, INTERNAL)
    assert not bad, "private names imported across subpackages:\n" + _show(bad)


def test_graph_sees_function_level_imports():
    # the lazy import of a slow optional dependency is not an edge; one of mech is
    inside = [e for e in EDGES if e["in_function"]]
    assert inside, "no function-level import of a mech module found: the walk missed them"
    assert all(e["dst"].split(".")[0] == "mech" for e in EDGES)


# ----------------------------------------------------------------------------- the rules can fail
def _plant(tmp_path, files):
    for name, text in files.items():
        path = tmp_path / "pkg" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return tmp_path / "pkg"


PLANTED = {
    "__init__.py": "from pkg.high import _api\n",
    "_low.py": "import numpy\n\ndef f():\n    from pkg.high._api import g   # upward, and closes a cycle\n    return g\n",
    "_other.py": "from pkg._low import f\n",
    "high/__init__.py": "from pkg.high._api import g\n",
    "high/_api.py": "from pkg._low import f\nfrom pkg._other import _secret\n\ndef g():\n    import scipy\n",
}
PLANTED_LAYERS = [["pkg._low", "pkg._other"], ["pkg.high"], ["pkg"]]


def test_planted_cycle_is_found(tmp_path):
    edges = import_edges(_plant(tmp_path, PLANTED))
    assert cycles(edges) == [["pkg._low", "pkg._other", "pkg.high._api"]]
    # without the function-level import there is none: the function-level edge is what counts
    assert cycles([e for e in edges if not e["in_function"]]) == []


def test_planted_upward_import_is_found(tmp_path):
    package = _plant(tmp_path, PLANTED)
    edges = import_edges(package)
    packages = {m for m, (_, p) in modules(package).items() if p}
    bad = upward(edges, PLANTED_LAYERS, packages)
    assert [(e["src"], e["dst"], e["in_function"]) for e in bad] == [("pkg._low", "pkg.high._api", True)]


def test_planted_private_crossing_is_found(tmp_path):
    package = _plant(tmp_path, PLANTED)
    edges = import_edges(package)
    packages = {m for m, (_, p) in modules(package).items() if p}
    bad = private_crossings(edges, packages, internal=[])
    assert [(e["src"], e["dst"], e["name"]) for e in bad] == [("pkg.high._api", "pkg._other", "_secret")]
    assert private_crossings(edges, packages, internal=["pkg._other"]) == []


def test_declared_reads_the_lists():
    text = ("# A\n\n## Layers\n\n1. `mech._a`, `mech._b`: bottom\n2. `mech.top`: the rest (not `mech.x`)\n\n"
            "## Internal modules\n\n- `mech._a`: helpers\n- `mech._b` (and `mech.y`)\n\n## Other\n\n- `mech.z`\n")
    assert declared(text) == ([["mech._a", "mech._b"], ["mech.top"]], ["mech._a", "mech._b"])


@pytest.mark.parametrize("module, layer", [("mech._validate", 0), ("mech.planar.kinematics._fourbar", 2)])
def test_layer_of_uses_the_longest_prefix(module, layer):
    assert layer_of(module, [["mech._validate", "mech._geometry"], ["mech.planar.structure"],
                             ["mech.planar.kinematics"], ["mech.planar", "mech"]]) == layer
