"""Harvest the textbook references that the repository declares.

Nothing here is a hand-kept list. Each source says which numbers it covers in a place it
already has:

- a derivation notebook (``derivations/<topic>/<stem>.md``) or a book page (``book/...``):
  its title, its section headings, its figure captions, its exercise labels (``ex-2-7``),
  its ``\\tag{2-53}`` equations, the equations passed to ``_codegen.write``, and an optional
  ``textbook:`` key in its front matter for what none of these carries;
- a public function, class or method (``__all__`` of the public packages): its docstring,
  and the docstring of the module that defines it;
- a registered exercise: ``Exercise(number="2-27", ...)`` in ``mech/exercises``;
- a test: its name (``test_example_2_3_limit_positions``) and its docstring. Where the
  docstring names the same number as another kind ("Exercise 2-4" under
  ``test_example_2_4_...``), the docstring wins.

Mentions in running prose are not declarations and are not read. Standard library only:
modules are parsed with :mod:`ast`, never imported.
"""

import ast
import re
from dataclasses import dataclass, field
from pathlib import Path

from mech.index._refs import parse, parse_test_name

__all__ = ["Place", "harvest", "make_id", "page_html"]


def _public_packages(root):
    """The subpackages ``mech/__init__.py`` lists in ``__all__`` (this index excluded)."""
    init = root / "mech" / "__init__.py"
    if not init.is_file():
        return []
    return [f"mech.{name}" for name in _all_names(_tree(init))
            if name != "index" and (root / "mech" / name / "__init__.py").is_file()]


@dataclass(frozen=True)
class Place:
    """Where a number is covered.

    Attributes
    ----------
    role : str
        "derivation", "book", "function" or "test".
    path : str
        File, relative to the repository root.
    name : str
        Page title, qualified public name, or pytest node id.
    how : str
        What declares it: "title", "heading", "caption", "label", "tag", "codegen",
        "front matter", "docstring", "module docstring", "registry" or "test name".
    line : int
        1-based line of the declaration.
    anchor : str or None
        HTML id on the built page, or None (top of the page).
    html : str or None
        Built page, relative to ``book/_build/html``, or None.
    """

    role: str
    path: str
    name: str
    how: str
    line: int
    anchor: str | None = None
    html: str | None = field(default=None)

    @property
    def url(self):
        """``html#anchor`` (or ``html``) for book and derivation pages, else None."""
        if self.html is None:
            return None
        return f"{self.html}#{self.anchor}" if self.anchor else self.html


# --------------------------------------------------------------------------- pages
_NON_ID = re.compile(r"[^a-z0-9]+")
_NON_ID_AT_ENDS = re.compile(r"^[-0-9]+|-+$")


def make_id(text):
    """The HTML id docutils gives a section titled ``text`` (``docutils.nodes.make_id``).

    >>> make_id("Example 2-2: an oscillating guide-bar with $K = 2$")
    'example-2-2-an-oscillating-guide-bar-with-k-2'
    >>> make_id("Rotating guide-bar (转动导杆机构, Fig. 2-58)")
    'rotating-guide-bar-fig-2-58'
    """
    import unicodedata

    if not isinstance(text, str):
        raise TypeError(f"Expected `text` to be a string, got {text!r} of type {type(text).__name__}")
    text = _plain(text)
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")
    text = _NON_ID.sub("-", " ".join(text.lower().split()))
    return _NON_ID_AT_ENDS.sub("", text)


def _plain(text):
    """Heading Markdown as rendered text: math and code keep their source, links their text."""
    text = re.sub(r"\{[a-z:-]+\}`([^`]*)`", r"\1", text)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = text.replace("$", "").replace("`", "")
    text = re.sub(r"(\*\*|__|\*|_)(\S.*?\S|\S)\1", r"\2", text)
    return text


def page_html(rel):
    """The built HTML file of a page, relative to ``book/_build/html``."""
    rel = Path(rel)
    if rel.parts[0] == "book":
        rel = Path(*rel.parts[1:])
    return str(rel.with_suffix(".html"))


def _front_matter(lines):
    """(end line index, textbook declarations) of the leading ``---`` block."""
    if not lines or lines[0].strip() != "---":
        return 0, []
    decl = []
    for i in range(1, len(lines)):
        line = lines[i]
        if line.strip() == "---":
            return i + 1, decl
        m = re.match(r"^textbook:\s*(.*)$", line)
        if m:
            if m.group(1).strip():
                decl.append((i + 1, m.group(1).strip().strip("'\"")))
            j = i + 1
            while j < len(lines) and re.match(r"^\s+-\s+", lines[j]):
                decl.append((j + 1, re.sub(r"^\s+-\s+", "", lines[j]).strip().strip("'\"")))
                j += 1
    return 0, []


_FENCE = re.compile(r"^(\s*)(`{3,}|:{3,})(.*)$")
_HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
_LABEL = re.compile(r"^\(([^()\s]+)\)=\s*$")
_LABEL_REF = re.compile(r"^(ex|exercise|fig|eq|table|example)-2-(\d{1,3})$")
_LABEL_KIND = {"ex": "exercise", "exercise": "exercise", "fig": "fig", "eq": "eq",
               "table": "table", "example": "example"}


def _caption_blocks(cell):
    """(line offset, caption text, figure name) for each figure of a code cell."""
    out = []
    lines = [re.sub(r"^:", "", line) if line.startswith(":") else line for line in cell]
    name = None
    for line in lines:
        m = re.match(r"^\s*name:\s*(\S+)", line)
        if m:
            name = m.group(1)
    for k, line in enumerate(lines):
        m = re.match(r"^(\s*)caption:\s*(?:[>|]-?)?\s*(.*)$", line)
        if not m:
            continue
        indent = len(m.group(1))
        text = [m.group(2)]
        for nxt in lines[k + 1:]:
            if not nxt.strip():
                break
            if len(nxt) - len(nxt.lstrip()) <= indent:
                break                        # the next key (name:, ...) ends the caption
            text.append(nxt.strip())
        out.append((k, " ".join(text), name))
    return out


def _page(root, rel, role, spherical, known_sections):
    """Declarations of one MyST page: yields ((kind, number), Place)."""
    text = (root / rel).read_text(encoding="utf-8")
    lines = text.splitlines()
    html = page_html(rel)
    start, decl = _front_matter(lines)
    title = None
    for line in lines[start:]:
        m = _HEADING.match(line)
        if m and len(m.group(1)) == 1:
            title = _plain(m.group(2))
            break
    title = title or rel
    rel = str(rel)

    def place(how, line, anchor=None):
        return Place(role, rel, title, how, line, anchor, html)

    def refs(s):
        return parse(s, spherical=spherical, known_sections=known_sections)

    for line_no, item in decl:
        for ref in refs(item):
            yield ref, place("front matter", line_no)
    used_ids = set()
    label = None
    fence = None
    cell = []
    cell_start = 0
    for i in range(start, len(lines)):
        line = lines[i]
        if fence is not None:
            if re.match(rf"^\s*{re.escape(fence)}\s*$", line):
                for k, caption, name in _caption_blocks(cell):
                    for ref in refs(caption):
                        yield ref, place("caption", cell_start + k + 2, name)
                fence = None
                continue
            cell.append(line)
            m = re.match(r"^:label:\s*(\S+)", line)
            if m:
                lm = _LABEL_REF.match(m.group(1))
                if lm:
                    yield (_LABEL_KIND[lm.group(1)], f"2-{lm.group(2)}"), \
                        place("label", i + 1, m.group(1))
                used_ids.add(m.group(1))
            for tag in re.findall(r"\\tag\{2-(\d{1,3})\}", line):
                yield ("eq", f"2-{tag}"), place("tag", i + 1)
            m = re.search(r"_codegen\.write\(\s*\"[^\"]*\",\s*\"[^\"]*\",\s*\"([^\"]*)\"", line)
            if m:
                for ref in refs(m.group(1)):
                    yield ref, place("codegen", i + 1)
            continue
        m = _FENCE.match(line)
        if m:
            fence, cell, cell_start = m.group(2), [], i
            continue
        for tag in re.findall(r"\\tag\{2-(\d{1,3})\}", line):
            yield ("eq", f"2-{tag}"), place("tag", i + 1)
        m = _LABEL.match(line)
        if m:
            label = m.group(1)
            used_ids.add(label)
            continue
        m = _HEADING.match(line)
        if m:
            level, heading = len(m.group(1)), m.group(2)
            slug = make_id(heading)
            if label:
                anchor = label
            elif slug and slug not in used_ids:
                anchor = slug
            else:
                anchor = None
            used_ids.add(slug)
            how = "title" if level == 1 else "heading"
            for ref in refs(heading):
                yield ref, place(how, i + 1, None if level == 1 else anchor)
        if line.strip():
            label = None


def _toc_pages(root):
    """Pages of ``book/_toc.yml``, as paths relative to the root (``book/...md``)."""
    toc = root / "book" / "_toc.yml"
    if not toc.is_file():
        return []
    pages = []
    for m in re.finditer(r"(?:file|root):\s*(\S+)", toc.read_text(encoding="utf-8")):
        rel = Path("book") / (m.group(1) + ("" if m.group(1).endswith(".md") else ".md"))
        if (root / rel).is_file():
            pages.append(rel)
    return pages


# --------------------------------------------------------------------------- modules
def _module_file(root, module):
    base = root.joinpath(*module.split("."))
    if (base / "__init__.py").is_file():
        return base / "__init__.py"
    if base.with_suffix(".py").is_file():
        return base.with_suffix(".py")
    return None


_TREES = {}


def _tree(path):
    if path not in _TREES:
        _TREES[path] = ast.parse(path.read_text(encoding="utf-8"))
    return _TREES[path]


def _reexported(root, module, tree):
    """The modules a package re-exports with ``__all__ = reexport(globals(), ...)``
    (``mech._exports``): their names are the package's public names."""
    path = _module_file(root, module)
    imported = {}
    for node in tree.body:
        if isinstance(node, ast.ImportFrom):
            source = _absolute(module, node, path is not None and path.name == "__init__.py")
            for alias in node.names:
                imported[alias.asname or alias.name] = f"{source}.{alias.name}"
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
            # `__all__ = reexport(...)` or `__all__ = ["Name", *reexport(...)]`
            for call in ast.walk(node.value):
                if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and call.func.id == "reexport":
                    return [imported[a.id] for a in call.args[1:] if isinstance(a, ast.Name) and a.id in imported]
    return []


def _all_names(tree, root=None, module=None):
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
            try:
                return list(ast.literal_eval(node.value))
            except ValueError:
                if root is None:
                    return []
                names = [e.value for e in getattr(node.value, "elts", ())
                         if isinstance(e, ast.Constant) and isinstance(e.value, str)]
                for sub in _reexported(root, module, tree):
                    sub_path = _module_file(root, sub)
                    if sub_path is not None:
                        names += [n for n in _all_names(_tree(sub_path), root, sub) if n not in names]
                return names
    return []


def _absolute(module, node, is_package):
    if not node.level:
        return node.module
    parts = module.split(".")
    base = parts if is_package else parts[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _definition(root, module, name, depth=0):
    """(module, file, ast node) where ``module.name`` is defined, following imports."""
    path = _module_file(root, module)
    if path is None or depth > 8:
        return None
    tree = _tree(path)
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and node.name == name:
            return module, path, node
        if isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == name for t in node.targets):
            return module, path, node
    for node in tree.body:
        if isinstance(node, ast.ImportFrom):
            for alias in node.names:
                if (alias.asname or alias.name) == name:
                    source = _absolute(module, node, path.name == "__init__.py")
                    if _module_file(root, f"{source}.{alias.name}") is not None:
                        return None          # a submodule, not a function
                    return _definition(root, source, alias.name, depth + 1)
    for sub in _reexported(root, module, tree):
        sub_path = _module_file(root, sub)
        if sub_path is not None and name in _all_names(_tree(sub_path), root, sub):
            return _definition(root, sub, name, depth + 1)
    return None


def _public_objects(root):
    """Yield (qualified public name, module, file, node) for every public object."""
    seen = {}
    packages = []
    for top in _public_packages(root):
        path = _module_file(root, top)
        if path is None:
            continue
        packages.append(top)
        for sub in sorted(path.parent.glob("*/__init__.py")):
            if not sub.parent.name.startswith("_"):
                packages.append(f"{top}.{sub.parent.name}")
    for package in packages:
        tree = _tree(_module_file(root, package))
        for name in _all_names(tree, root, package):
            found = _definition(root, package, name)
            if found is None:
                continue
            module, path, node = found
            key = (module, name)
            if key not in seen:              # the shortest public path wins
                seen[key] = (f"{package}.{name}", module, path, node)
    return seen.values()


def _docstring(node):
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Module)):
        return ast.get_docstring(node) or ""
    return ""


def _functions(root, known_sections):
    modules = {}
    for qualname, module, path, node in _public_objects(root):
        rel = str(path.relative_to(root))
        spherical = "spherical" in rel
        refs_of = lambda s: parse(s, spherical=spherical, known_sections=known_sections)  # noqa: E731
        for ref in refs_of(_docstring(node)):
            yield ref, Place("function", rel, qualname, "docstring", node.lineno)
        if isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)) and \
                        not item.name.startswith("_"):
                    for ref in refs_of(_docstring(item)):
                        yield ref, Place("function", rel, f"{qualname}.{item.name}",
                                         "docstring", item.lineno)
        modules.setdefault((module, rel), set()).add(qualname)
    for (module, rel), names in sorted(modules.items()):
        # A module docstring names the monograph chapter or sections the whole module covers.
        doc = _docstring(_tree(root / rel))
        for ref in parse(doc, spherical="spherical" in rel, known_sections=known_sections):
            if ref[0] in ("chapter", "section"):
                yield ref, Place("function", rel, f"{module} ({', '.join(sorted(names)[:3])}"
                                 f"{', ...' if len(names) > 3 else ''})", "module docstring", 1)


def _exercises(root):
    folder = root / "mech" / "exercises"
    for path in sorted(folder.glob("*.py")):
        for node in ast.walk(_tree(path)):
            if isinstance(node, ast.Call) and getattr(node.func, "id", "").endswith("Exercise"):
                for kw in node.keywords:
                    if kw.arg == "number" and isinstance(kw.value, ast.Constant):
                        number = kw.value.value
                        yield ("exercise", number), Place(
                            "function", str(path.relative_to(root)),
                            f'mech.exercises.get("{number}")', "registry", node.lineno)


def _tests(root, known_sections):
    for path in sorted((root / "tests").rglob("test_*.py")):
        rel = str(path.relative_to(root))
        spherical = "spherical" in rel
        bare = "exercise" if "exercises" in path.parts else None

        def walk(body, prefix):
            for node in body:
                if isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
                    yield from walk(node.body, f"{prefix}::{node.name}")
                elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and \
                        node.name.startswith("test_"):
                    yield node, f"{prefix}::{node.name}"

        for node, nodeid in walk(_tree(path).body, rel):
            doc = parse(_docstring(node), spherical=spherical, known_sections=known_sections)
            named = parse_test_name(node.name, bare_kind=bare)
            doc_numbers = {number for _, number in doc}
            for ref in doc:
                yield ref, Place("test", rel, nodeid, "docstring", node.lineno)
            for ref in named:
                if ref in doc or ref[1] in doc_numbers:
                    continue
                yield ref, Place("test", rel, nodeid, "test name", node.lineno)


def harvest(root, *, known_sections=()):
    """Every declaration in the repository at ``root``: a list of ((kind, number), Place)."""
    root = Path(root)
    _TREES.clear()
    out = []
    derivations = sorted((root / "derivations").glob("*/*.md"))
    for path in derivations:
        rel = path.relative_to(root)
        html = Path("book") / rel
        for ref, place in _page(root, rel, "derivation", "spherical" in str(rel), known_sections):
            out.append((ref, Place(place.role, place.path, place.name, place.how, place.line,
                                   place.anchor, page_html(html))))
    for rel in _toc_pages(root):
        if rel.parts[1] == "derivations" or rel.name == "index-by-number.md":
            continue
        out += list(_page(root, rel, "book", "spherical" in str(rel), known_sections))
    if (root / "mech").is_dir():
        out += list(_functions(root, known_sections))
        out += list(_exercises(root))
    if (root / "tests").is_dir():
        out += list(_tests(root, known_sections))
    return out
