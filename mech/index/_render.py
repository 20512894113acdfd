"""Text for the terminal and Markdown for the book page. Standard library only."""

from mech.index._refs import KINDS

__all__ = ["entry_text", "markdown_tables", "summary_markdown"]

_HOW_ORDER = ("label", "heading", "caption", "tag", "codegen", "front matter", "title")
_FIGURE_ORDER = ("caption", "label", "heading", "tag", "codegen", "front matter", "title")


def _pages(places, kind=None):
    """One place per page: the most specific declaration (a figure's caption, another
    number's label or heading) first."""
    order = _FIGURE_ORDER if kind == "fig" else _HOW_ORDER
    best = {}
    for p in places:
        rank = order.index(p.how) if p.how in order else len(order)
        if not p.anchor:
            rank += len(_HOW_ORDER)
        if p.path not in best or rank < best[p.path][0]:
            best[p.path] = (rank, p)
    return [p for _, p in best.values()]


def _unique(names):
    out = []
    for n in names:
        if n not in out:
            out.append(n)
    return out


def entry_text(entry, html_root="book/_build/html"):
    """A few lines answering one entry on the terminal."""
    state = "covered" if entry.covered else "not yet covered"
    if entry.catalogued is False:
        state += "; not in the textbook data (mech/index/data)"
    name = f" ({entry.name})" if entry.name else ""
    if entry.item and "section" in entry.item:
        part = f" {entry.item['part']}" if "part" in entry.item else ""
        name = f" ({entry.name}; textbook §{entry.item['section']}{part})"
    elif entry.item and "page" in entry.item:
        name = f" ({entry.name}; p. {entry.item['page']})"
    lines = [f"{entry.title}{name}: {state}"]
    if entry.not_covered and not entry.covered:
        lines.append(f"  why: {entry.not_covered}")
    elif entry.stale:
        lines.append("  (listed in mech/index/_not_covered.py, but covered now: delete the entry)")
    for role, heading in (("derivation", "derivation"), ("function", "functions"),
                          ("book", "book page"), ("test", "tests")):
        places = entry.role(role)
        if role in ("derivation", "book"):
            for i, p in enumerate(_pages(places, entry.key[0])):
                lead = f"  {heading:11s}" if i == 0 else " " * 13
                lines.append(f"{lead}{p.name}")
                lines.append(f"{'':13s}  {p.path}:{p.line} ({p.how}) -> {html_root}/{p.url}")
            if not places:
                lines.append(f"  {heading:11s}-")
        else:
            names = _unique(p.name for p in places)
            if not names:
                lines.append(f"  {heading:11s}-")
            for i, name in enumerate(names):
                lead = f"  {heading:11s}" if i == 0 else " " * 13
                lines.append(f"{lead}{name}")
    return "\n".join(lines)


def _cell(text):
    return text.replace("|", "\\|").replace("\n", " ")


def _link(place, prefix=""):
    title = place.name.replace("$", "")
    return f'<a href="{prefix}{place.url}">{_cell(_escape(title))}</a>'


def _escape(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _names(places, limit):
    names = _unique(p.name for p in places)
    shown = ", ".join(f"`{n}`" for n in names[:limit])
    if len(names) > limit:
        shown += f" and {len(names) - limit} more"
    return _cell(shown)


def _tests(places, limit=2):
    names = _unique(p.name.split("::")[-1] for p in places)
    shown = ", ".join(f"`{n}`" for n in names[:limit])
    if len(names) > limit:
        shown += f" (+{len(names) - limit})"
    return _cell(shown)


def markdown_tables(index, kinds=None, *, prefix=""):
    """One Markdown table per kind: number, derivation, functions, book pages, tests.

    Links are HTML anchors into the built book (``prefix`` + page + ``#id``), so a reader
    goes straight to the section, figure or exercise.
    """
    blocks = []
    for kind in kinds or KINDS:
        entries = [e for e in index.kind(kind) if e.catalogued is not False or e.places]
        if not entries:
            continue
        rows = ["| number | derivation | functions | book page | tests |",
                "|---|---|---|---|---|"]
        for e in entries:
            label = e.title.split(" ", 1)[1] if kind != "chapter" else e.key[1]
            if kind.startswith(("chapter", "section")):
                label = e.title.replace("monograph ", "").replace("chapter ", "")
            if e.name:
                where = f", p. {e.item['page']}" if "page" in e.item else ""
                if "section" in e.item:
                    where = f" (§{e.item['section']}{' ' + e.item['part'] if 'part' in e.item else ''})"
                label = f"{label}: {_cell(_escape(e.name))}{where}"
            derivations = "; ".join(_link(p, prefix) for p in _pages(e.role("derivation"), kind))
            pages = "; ".join(_link(p, prefix) for p in _pages(e.role("book"), kind))
            if not e.covered and e.not_covered:
                derivations = (derivations + " " if derivations else "") + \
                    f"*not yet covered:* {_cell(e.not_covered)}"
            elif not e.covered:
                derivations = "*not covered, and no reason given*"
            rows.append(f"| {label} | {derivations} | {_names(e.role('function'), 3)} | "
                        f"{pages} | {_tests(e.role('test'))} |")
        blocks.append((kind, "\n".join(rows)))
    return blocks


def summary_markdown(index):
    """A table of how many catalogued numbers of each kind are covered."""
    rows = ["| kind | in the textbook | covered | not yet covered |", "|---|---:|---:|---:|"]
    for kind, (total, covered, gaps) in index.summary().items():
        rows.append(f"| {KINDS[kind]}s | {total} | {covered} | {gaps} |")
    return "\n".join(rows)
