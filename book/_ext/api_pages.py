"""The API reference (``book/api/``) and the links to it from the pages that use the package.

Two parts:

- The directive ``mech-api`` (written in a page as ```` ```{mech-api} mech.planar.forces ```` ````)
  documents one public package from its ``__all__``: a summary table of every name
  (``sphinx.ext.autosummary``), then the docstring of each name whose home is this package
  (``sphinx.ext.autodoc``, numpy-style sections read by ``sphinx.ext.napoleon``). A name that
  several packages export (``mech.planar.FourBar`` is ``mech.planar.kinematics.FourBar``) is
  documented once, in its home: the deepest public package that exports it and whose name
  starts its defining module's name (else the deepest that exports it); the other tables
  link there.
- On ``doctree-read`` every other page gets a box "Functions used on this page" at its end,
  linking each name of the package that its code (the executed cells and the code blocks)
  reaches: ``import mech.planar as pl`` then ``pl.FourBar(...)``, ``from mech.spherical import
  guidance``, ``mech.planar.grashof(...)``. Only names of the API pages are linked.

Nothing here is specific to a page: a new public name appears once it is in ``__all__``, and
``tests/test_api_pages.py`` checks that every name of every ``__all__`` has a home page.
"""

import ast
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

from docutils import nodes
from docutils.statemachine import StringList
from sphinx import addnodes
from sphinx.util.docutils import SphinxDirective

API_PREFIX = "api/"
ROOT_PACKAGE = "mech"


def public_packages():
    """Every public package of ``mech`` (no name part starting with "_"), parents first."""
    root = importlib.import_module(ROOT_PACKAGE)
    names = [ROOT_PACKAGE]
    for info in pkgutil.walk_packages(root.__path__, ROOT_PACKAGE + "."):
        if info.ispkg and not any(part.startswith("_") for part in info.name.split(".")):
            names.append(info.name)
    return sorted(names, key=lambda n: (n.count("."), n))


def public_modules(package):
    """The public modules of ``package`` that are not packages (``mech.exercises.chapter2``)."""
    module = importlib.import_module(package)
    return [f"{package}.{info.name}" for info in pkgutil.iter_modules(module.__path__)
            if not info.ispkg and not info.name.startswith("_")]


def _exports(package):
    module = importlib.import_module(package)
    return [(n, getattr(module, n)) for n in getattr(module, "__all__", [])
            if not inspect.ismodule(getattr(module, n))]


def key(name, obj):
    """What identifies a public object: itself, or for a value (a number, a table) also its
    name, since two constants may be one object (``1`` is ``1``)."""
    return (id(obj), None) if inspect.isclass(obj) or callable(obj) else (id(obj), name)


def homes():
    """``{key(name, object): (package, name)}``: where each public object is documented."""
    found = {}
    for package in public_packages():
        for name, obj in _exports(package):
            found.setdefault(key(name, obj), []).append((package, name, obj))
    result = {}
    for k, places in found.items():
        obj = places[0][2]
        defined = getattr(obj, "__module__", None) or ""
        own = [p for p in places if defined == p[0] or defined.startswith(p[0] + ".")]
        package, name, _ = max(own or places, key=lambda p: p[0].count("."))
        result[k] = (package, name)
    return result


def _kind(obj):
    if inspect.isclass(obj):
        return "autoclass", ["   :members:"]
    if callable(obj):
        return "autofunction", []
    return "autodata", ["   :annotation:"]


class MechApi(SphinxDirective):
    """Document one public package: a summary table, then each name whose home it is."""

    required_arguments = 1

    def run(self):
        package = self.arguments[0]
        where = self.env.app.mech_api_homes
        lines = [f".. py:module:: {package}", "", ".. autosummary::", "   :nosignatures:", ""]
        own = []
        for name, obj in _exports(package):
            home, home_name = where[key(name, obj)]
            # autosummary reads names relative to the package (a home in a subpackage as
            # `path.CouplerOctic`), and the package's own names bare
            target = f"{home}.{home_name}"
            if target.startswith(package + "."):
                target = target[len(package) + 1:]
            lines.append(f"   ~{target}")
            if home == package:
                own.append((name, obj))
        lines.append("")
        for name, obj in own:
            directive, options = _kind(obj)
            lines += [f".. {directive}:: {package}.{name}", *options, ""]
        # public modules that are not packages (``mech.exercises.chapter2``): their docstring
        for name in public_modules(package):
            lines += [f".. automodule:: {name}", ""]
        # the pages are MyST, whose nested parse reads Markdown: the reStructuredText of the
        # autodoc directives (and of the docstrings they pull in) goes through `eval-rst`
        lines = ["```{eval-rst}", *lines, "```"]
        container = nodes.container(classes=["mech-api"])
        self.state.nested_parse(StringList(lines, source=f"<mech-api {package}>"), self.content_offset, container)
        return container.children


_MAGIC = re.compile(r"^\s*[%!]")


def _aliases_and_chains(source):
    """The names bound to ``mech`` objects by imports, and every dotted name the code uses."""
    source = "\n".join("" if _MAGIC.match(line) else line for line in source.splitlines())
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return {}, []
    aliases, chains = {}, []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                if a.name.split(".")[0] == ROOT_PACKAGE:
                    if a.asname:
                        aliases[a.asname] = a.name
                    else:
                        aliases[ROOT_PACKAGE] = ROOT_PACKAGE
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0 \
                and node.module.split(".")[0] == ROOT_PACKAGE:
            for a in node.names:
                if a.name != "*":
                    aliases[a.asname or a.name] = f"{node.module}.{a.name}"
                    chains.append(f"{node.module}.{a.name}")
        elif isinstance(node, ast.Attribute):
            parts = []
            while isinstance(node, ast.Attribute):
                parts.append(node.attr)
                node = node.value
            if isinstance(node, ast.Name):
                chains.append(".".join([node.id, *reversed(parts)]))
        elif isinstance(node, ast.Name):
            chains.append(node.id)
    return aliases, chains


def _resolve(dotted, aliases):
    """The ``(name, object)`` pairs along a dotted name (``pl.FourBar.solve``: ``FourBar``, ...)."""
    head, _, rest = dotted.partition(".")
    if head not in aliases:
        return []
    parts = aliases[head].split(".") + (rest.split(".") if rest else [])
    obj, found = None, []
    for i, part in enumerate(parts):
        if i == 0:
            obj = importlib.import_module(part)
            continue
        try:
            obj = getattr(obj, part)
        except AttributeError:
            try:
                obj = importlib.import_module(".".join(parts[: i + 1]))
            except ImportError:
                break
        found.append((part, obj))
    return found


def used_names(sources, where):
    """The documented ``(package, name)`` pairs that code ``sources`` reach, sorted."""
    aliases, chains = {}, []
    for source in sources:
        a, c = _aliases_and_chains(source)
        aliases.update(a)
        chains += c
    seen = {}
    for chain in chains:
        for name, obj in _resolve(chain, aliases):
            if key(name, obj) in where:
                seen.setdefault(where[key(name, obj)], None)
    return sorted(seen, key=lambda p: (p[0], p[1].lower()))


_CELL = re.compile(r"^(`{3,})\{code-cell\}[^\n]*\n(.*?)^\1\s*$", re.S | re.M)
_FENCE = re.compile(r"^(`{3,})(?:python|python3|ipython3|py)\s*\n(.*?)^\1\s*$", re.S | re.M)


def _cell_body(text):
    """A code cell without its options (``:tags: [...]`` lines or a ``---`` block)."""
    lines = text.splitlines()
    if lines and lines[0].strip() == "---":
        end = next((i for i, ln in enumerate(lines[1:], 1) if ln.strip() == "---"), 0)
        lines = lines[end + 1:]
    while lines and lines[0].startswith(":"):
        lines = lines[1:]
    return "\n".join(lines)


def _code_sources(doctree, path):
    """The page's code: every cell of its source (hidden ones included: a page often imports
    in a removed cell) and every Python block that the doctree shows."""
    if path is not None and path.suffix == ".md" and path.exists():
        text = path.read_text(encoding="utf-8")
        yield from (_cell_body(m.group(2)) for m in _CELL.finditer(text))
        yield from (m.group(2) for m in _FENCE.finditer(text))
    elif path is not None and path.suffix == ".ipynb" and path.exists():
        import json

        for cell in json.loads(path.read_text(encoding="utf-8")).get("cells", []):
            if cell.get("cell_type") == "code":
                source = cell.get("source", "")
                yield "".join(source) if isinstance(source, list) else source
    for block in doctree.findall(nodes.literal_block):
        language = (block.get("language") or "").lower()
        if language in ("python", "ipython3", "ipython", "python3", "py", "pycon"):
            yield block.astext()


def add_used_box(app, doctree):
    docname = app.env.docname
    if docname.startswith(API_PREFIX):
        return
    path = Path(app.env.doc2path(docname))
    used = used_names(_code_sources(doctree, path), app.mech_api_homes)
    if not used:
        return
    box = nodes.admonition(classes=["seealso", "mech-api-used"])
    box += nodes.title(text="Functions used on this page")
    para = nodes.paragraph()
    for i, (package, name) in enumerate(used):
        if i:
            para += nodes.Text(", ")
        ref = addnodes.pending_xref("", refdomain="py", reftype="obj", reftarget=f"{package}.{name}",
                                    refexplicit=True, refwarn=True)
        ref += nodes.literal(text=f"{package}.{name}", classes=["xref", "py", "py-obj"])
        para += ref
    box += para
    sections = [s for s in doctree.children if isinstance(s, nodes.section)]
    (sections[-1] if sections else doctree).append(box)


def _setup_homes(app):
    app.mech_api_homes = homes()


#: How the docstrings are rendered. Types stay text ("float or array", "complex array"): the
#: strict build (``-n``) would call each one an unresolved class reference, and there is no
#: intersphinx (the book builds offline). The summary tables link to entries on the pages,
#: so autosummary writes no stub files.
SETTINGS = {
    "napoleon_numpy_docstring": True,
    "napoleon_google_docstring": False,
    "napoleon_use_param": False,
    "napoleon_use_rtype": False,
    "napoleon_use_ivar": False,
    "napoleon_preprocess_types": False,
    # the attributes of a result class are listed like parameters: names, types as text
    "napoleon_custom_sections": [("Attributes", "params_style")],
    "autodoc_typehints": "none",
    "autodoc_member_order": "bysource",
    # defaults as written in the source ("np.radians(30)"), not as evaluated
    # ("np.float64(0.5235987755982988)", a long word a phone cannot wrap), issue 26
    "autodoc_preserve_defaults": True,
    # a long signature one parameter per line, so that it reads down the column
    "python_maximum_signature_line_length": 72,
    "autosummary_generate": False,
    "add_module_names": False,
}


def _drop_type_docstring(app, what, name, obj, options, lines):
    """A constant without a doc comment would show its type's docstring (``dict``'s, say)."""
    if what in ("data", "attribute") and lines and inspect.getdoc(type(obj)) \
            and "\n".join(lines).strip() == inspect.getdoc(type(obj)).strip():
        lines.clear()


def _configure(app, config):
    for name, value in SETTINGS.items():
        config[name] = value


def setup(app):
    for extension in ("sphinx.ext.autodoc", "sphinx.ext.autosummary", "sphinx.ext.napoleon"):
        app.setup_extension(extension)
    app.connect("config-inited", _configure)
    app.connect("autodoc-process-docstring", _drop_type_docstring)
    app.connect("builder-inited", _setup_homes)
    app.add_directive("mech-api", MechApi)
    app.connect("doctree-read", add_used_box)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
