"""The whole book as one PDF (issue 26): built by ``make book`` with ``book/_pdf.py``.

The PDF must hold every page of the contents in order (one bookmark per page), be linked
from the landing page, and its pages must be drawn (pdftoppm renders them with ink).
"""

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import unavailable

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "book" / "_build" / "html"
sys.path.insert(0, str(ROOT / "book"))
import _pdf  # noqa: E402


def test_toc_order_starts_with_the_landing_page():
    pages = _pdf.toc_pages()
    assert pages[0] == "intro"
    assert len(pages) == len(set(pages)) >= 90
    # a derivation comes right after the worked page it is nested under
    assert pages.index("derivations/planar/grashof") == pages.index("structure/index") + 1


@pytest.fixture(scope="module")
def pdf():
    path = HTML / _pdf.PDF_NAME
    if not path.is_file():
        unavailable(f"no {path.relative_to(ROOT)} (run `make book` first)")
    return path


def test_pdf_holds_every_page_in_order(pdf):
    pypdf = pytest.importorskip("pypdf")
    reader = pypdf.PdfReader(pdf)
    pages = [p for p in _pdf.toc_pages() if (HTML / f"{p}.html").is_file()]
    outline = [item for item in reader.outline if not isinstance(item, list)]
    assert len(outline) == len(pages)
    starts = [reader.get_destination_page_number(item) for item in outline]
    assert starts == sorted(starts) and len(set(starts)) == len(starts)
    assert len(reader.pages) >= len(pages)
    text = reader.pages[starts[pages.index("derivations/planar/grashof")]].extract_text()
    assert "Grashof" in text


def test_landing_page_links_the_pdf(pdf):
    assert f'href="{_pdf.PDF_NAME}"' in (HTML / "intro.html").read_text(encoding="utf-8")


def test_pdf_pages_are_drawn(pdf, tmp_path):
    if not shutil.which("pdftoppm"):
        unavailable("no pdftoppm (make browser-deps installs poppler-utils)")
    PIL = pytest.importorskip("PIL.Image")
    subprocess.run(["pdftoppm", "-r", "40", "-f", "1", "-l", "3", "-png", str(pdf), str(tmp_path / "p")],
                   check=True, timeout=120)
    shots = sorted(tmp_path.glob("p*.png"))
    assert len(shots) == 3
    for shot in shots:
        gray = PIL.open(shot).convert("L")
        dark = sum(1 for v in gray.getdata() if v < 128)
        assert dark > 0.002 * gray.width * gray.height, f"{shot.name} is blank"
