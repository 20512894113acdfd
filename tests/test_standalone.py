"""The repository stands alone: its documents are in it, and no page, notebook, module or test
cites a file outside it, a line number of the textbook's source text, or a figure script."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FOLDERS = ("book", "derivations", "mech", "tests", "benchmarks", "figures")

#: A path outside the repository (the reference material the project was built from). The
#: folder's name is assembled so that a plain grep of the repository for it finds nothing.
_SHARED = "sha" + "red"
OUTSIDE = re.compile(rf"\.\./{_SHARED}\b|\b{_SHARED}/(?:catalog|seeds|CONVENTIONS|STYLE|DESIGN)|\bseeds/\d")
#: A line number of the source text: "l.2113", "l. 3038", "line 117", "lines 503-509".
SOURCE_LINE = re.compile(r"(?<![\w.])l\.\s?\d{2,4}\b|\b[Ll]ines? \d{3,4}\b")
#: A figure script named where the reader sees it (a caption or the page's prose).
FIGURE_SCRIPT = re.compile(r"figures/\w+\.py")


def _files(suffixes=(".md", ".py", ".yml", ".toml")):
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix in suffixes and "_build" not in path.parts and path.is_file() \
                    and path.resolve() != Path(__file__).resolve():
                yield path


def _pages():
    yield from sorted((ROOT / "book").rglob("*.md"))
    yield from sorted((ROOT / "derivations").glob("*/*.md"))


def _prose(text):
    """The Markdown outside code cells, plus the captions of figure cells."""
    out, fence = [], None
    for line in text.splitlines():
        m = re.match(r"^\s*(`{3,}|:{3,})", line)
        if fence is None and m:
            fence = m.group(1)
            continue
        if fence is not None:
            if line.strip() == fence:
                fence = None
            elif re.match(r"^:?\s*caption:", line) or (out and out[-1].startswith("CAPTION")
                                                       and line.startswith(":      ")):
                out.append("CAPTION " + line)
            continue
        out.append(line)
    return "\n".join(out)


def test_patterns_can_fail():
    assert OUTSIDE.search(f"see ../{_SHARED}/STYLE.md item 4")
    assert OUTSIDE.search(f"the catalog in {_SHARED}/catalog/exercises.md")
    assert SOURCE_LINE.search("Example 2-15 (l.2113) gives") and SOURCE_LINE.search("line 117")
    assert not SOURCE_LINE.search("§2.4 I, Table 2-3, eq. (2-19), 3 lines below")
    assert FIGURE_SCRIPT.search("Drawn by figures/spherical_octic.py")
    assert "Drawn" not in _prose("```{code-cell}\nfig = draw()  # Drawn by figures/a.py\n```\n")
    assert "figures/a.py" in _prose("```{code-cell}\n---\nmystnb:\n  figure:\n    caption: figures/a.py\n---\n```\n")


def test_no_path_outside_the_repository():
    found = [f"{p.relative_to(ROOT)}:{n}" for p in _files()
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if OUTSIDE.search(line)]
    assert not found, f"Expected no path outside the repository, got {found[:10]}"


def test_pages_cite_no_source_line_and_no_figure_script():
    found = []
    for page in _pages():
        prose = _prose(page.read_text(encoding="utf-8"))
        for pattern in (SOURCE_LINE, FIGURE_SCRIPT):
            found += [f"{page.relative_to(ROOT)}: {m.group(0)!r}" for m in pattern.finditer(prose)]
    assert not found, f"Expected textbook sections, equations and figures instead, got {found[:10]}"


def test_pages_cite_the_conventions_page_not_the_file():
    labels = set(re.findall(r"^\((conventions-[a-z]+)\)=", (ROOT / "book" / "conventions.md")
                            .read_text(encoding="utf-8"), re.M))
    assert labels == {"conventions-units", "conventions-errors", "conventions-planar",
                      "conventions-spatial", "conventions-spherical", "conventions-synthesis"}
    cited = set()
    for page in _pages():
        text = page.read_text(encoding="utf-8")
        if page.name != "conventions.md":
            assert "CONVENTIONS.md" not in _prose(text), page
        cited |= set(re.findall(r"<(conventions-[a-z]+)>`", text))
    assert cited and cited <= labels, cited - labels


@pytest.mark.parametrize("part", ["units", "errors", "planar", "spatial", "spherical", "synthesis"])
def test_conventions_page_includes_each_part_of_the_file(part):
    conventions = (ROOT / "CONVENTIONS.md").read_text(encoding="utf-8")
    page = (ROOT / "book" / "conventions.md").read_text(encoding="utf-8")
    assert f"<!-- part: {part} -->" in conventions
    assert f":start-after: <!-- part: {part} -->" in page


def test_contributor_documents_are_in_the_repository():
    guide = (ROOT / "CONTRIBUTING.md").read_text(encoding="utf-8")
    for command in ("make generate", "make check-generated", "make test-fast", "make test",
                    "make book"):
        assert command in guide, command
    for link in ("CONVENTIONS.md", "STYLE.md", "ARCHITECTURE.md", "derivations/README.md"):
        assert f"]({link}" in guide, link
    assert "## Checklist" in guide
    for name in ("CONVENTIONS.md", "STYLE.md"):
        assert (ROOT / name).is_file()
    # the code's citations of CONVENTIONS.md name sections that the file has
    sections = {m.split()[0] for m in re.findall(r"^## (.+)$", (ROOT / "CONVENTIONS.md")
                                                  .read_text(encoding="utf-8"), re.M)}
    for path in _files((".py",)):
        for section in re.findall(r"CONVENTIONS\.md``?,? section (\w+)", path.read_text(encoding="utf-8")):
            assert section in sections, (path, section)
