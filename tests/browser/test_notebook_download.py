"""Pages as notebooks (issue 17, item 6; issue 26: every page, the run box folded).

Every derivation page of the built book offers its ``.ipynb`` in the download menu and
tells the reader how to run it; one downloaded notebook, copied to a temporary folder
outside the repository, runs from top to bottom with the installed package.
"""

import os
import re
import shutil
from pathlib import Path

import pytest

from conftest import unavailable

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "book" / "_build" / "html"
DERIVATIONS = sorted(
    p.relative_to(ROOT).with_suffix("").as_posix()
    for p in (ROOT / "derivations").rglob("*.md") if p.name != "README.md"
)
RUN_ME = "derivations/planar/transmission_angle"  # a short derivation


@pytest.fixture(scope="module")
def built():
    if not (HTML / "index.html").is_file():
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    return HTML


@pytest.mark.parametrize("page", DERIVATIONS)
def test_derivation_page_offers_its_notebook(built, page):
    nbformat = pytest.importorskip("nbformat")
    html = (built / f"{page}.html").read_text(encoding="utf-8")
    depth = page.count("/")
    href = "../" * depth + f"_sources/{page}.ipynb"
    assert re.search(rf'href="{re.escape(href)}"', html), f"no download link {href} on {page}.html"
    bs4 = pytest.importorskip("bs4")
    note = bs4.BeautifulSoup(html, "html.parser").select_one("section .mech-run-notebook")
    assert note is not None, f"no 'Run this derivation yourself' box on {page}.html"
    assert note.find_previous_sibling().name == "h1"  # right under the title
    text = " ".join(note.get_text(" ").split())
    assert f"jupyter execute {Path(page).name}.ipynb" in text and "make setup" in text
    notebook = nbformat.read(built / "_sources" / f"{page}.ipynb", as_version=4)
    nbformat.validate(notebook)
    sources = "\n".join(c.source for c in notebook.cells if c.cell_type == "code")
    assert "import" in sources and notebook.metadata.kernelspec.name == "python3"


@pytest.mark.parametrize("page", ["glossary", "intro", "kinematics/examples"])
def test_other_pages_offer_their_notebook_without_the_run_box(built, page):
    """Issue 26: every page is downloadable as a notebook (a page without code as text
    cells); only derivation pages carry the run box."""
    nbformat = pytest.importorskip("nbformat")
    html = (built / f"{page}.html").read_text(encoding="utf-8")
    href = "../" * page.count("/") + f"_sources/{page}.ipynb"
    assert f'href="{href}"' in html and "Run this derivation yourself" not in html
    notebook = nbformat.read(built / "_sources" / f"{page}.ipynb", as_version=4)
    nbformat.validate(notebook)
    assert len(notebook.cells) >= 1


def test_every_page_offers_a_notebook(built):
    pages = [p for p in built.rglob("*.html") if not {"_static", "_sources", "_images"} & set(p.parts)
             and p.name not in ("genindex.html", "search.html", "py-modindex.html")]
    missing = [p.relative_to(built).as_posix() for p in pages
               if 'http-equiv="refresh"' not in p.read_text(encoding="utf-8")[:2000].lower()
               and not (built / "_sources" / p.relative_to(built).with_suffix(".ipynb")).is_file()]
    assert len(pages) >= 20 and missing == []


def test_run_box_is_folded(built):
    html = (built / f"{RUN_ME}.html").read_text(encoding="utf-8")
    assert re.search(r'<details class="[^"]*mech-run-notebook[^"]*"><summary[^>]*>Run this derivation yourself</summary>', html)


@pytest.mark.slow
def test_downloaded_notebook_runs_outside_the_repository(built, tmp_path, monkeypatch):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    assert not tmp_path.resolve().is_relative_to(ROOT)
    target = tmp_path / "run" / f"{Path(RUN_ME).name}.ipynb"
    target.parent.mkdir()
    shutil.copy(built / "_sources" / f"{RUN_ME}.ipynb", target)
    notebook = nbformat.read(target, as_version=4)
    for cell in notebook.cells:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    # The reader's run regenerates nothing here: the test must not touch mech/_generated.
    monkeypatch.setenv("MECH_CODEGEN", "check")
    monkeypatch.chdir(target.parent)
    client = nbclient.NotebookClient(
        notebook, timeout=600, kernel_name="python3",
        resources={"metadata": {"path": str(target.parent)}})
    client.execute()
    errors = [
        out for cell in notebook.cells if cell.cell_type == "code" for out in cell.outputs
        if out.output_type == "error" or (out.output_type == "stream" and out.name == "stderr")
    ]
    assert errors == []
    ran = [cell for cell in notebook.cells if cell.cell_type == "code"]
    assert ran and all(cell.execution_count for cell in ran)
    assert os.listdir(target.parent) == [target.name]  # it wrote nothing beside itself
