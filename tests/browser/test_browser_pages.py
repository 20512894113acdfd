"""Every page of the built book in headless Chromium (issue 17, item 4).

Loads each page of ``book/_build/html`` once (one browser, three tabs) and fails a page on
a JavaScript error, a request that leaves the machine, an image or figure that does not
load, untypeset math, a Chinese character drawn as a missing glyph, or an animation or
3-D view that does not respond (see ``_crawl.py``). A screenshot of every page goes to
``book/_build/screenshots/`` and the counts to ``book/_build/screenshots/report.json``.

Without a build the test skips, unless ``MECH_BROWSER_TEST=required`` or ``CI=true``
(``.ci/run`` sets the first, after ``make book``), where it fails.
"""

import json
import time
from pathlib import Path

import pytest

import _crawl
from conftest import unavailable

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "book" / "_build" / "html"
SHOTS = ROOT / "book" / "_build" / "screenshots"
PAGES = _crawl.built_pages(HTML) if (HTML / "index.html").is_file() else []


@pytest.fixture(scope="session")
def crawl(chromium):
    if not PAGES:
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    t0 = time.perf_counter()
    results = _crawl.check_pages(HTML, PAGES, screenshot_dir=SHOTS, executable=chromium)
    seconds = time.perf_counter() - t0
    def spread(values):
        values = sorted(values)
        return {"median": values[len(values) // 2], "max": values[-1]} if values else {}

    infos = [info for _, info in results.values()]
    report = {
        "pages": len(results),
        "seconds": round(seconds, 1),
        "bytes_loaded": spread(info.get("bytes", 0) for info in infos),
        "bytes_loaded_outside_static": spread(info.get("ownBytes", 0) for info in infos),
        "html_bytes": spread((HTML / page).stat().st_size for page in results),
        "animations": sum(info.get("animations", 0) for info in infos),
        "views3d": sum(info.get("views3d", 0) for info in infos),
        "results": {page: {"problems": p, **info} for page, (p, info) in sorted(results.items())},
    }
    (SHOTS / "report.json").write_text(json.dumps(report, indent=1, ensure_ascii=False), encoding="utf-8")
    return results


def test_book_is_built():
    if not PAGES:
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    assert len(PAGES) >= 20


@pytest.mark.parametrize("page", PAGES or ["(no build)"])
def test_page_in_browser(crawl, page):
    problems, info = crawl[page]
    assert problems == [], f"{page}:\n" + "\n".join(problems)
    if "redirect" not in info:
        assert (SHOTS / (page.removesuffix(".html").replace("/", "__") + ".jpg")).is_file()


def test_chinese_terms_were_checked(crawl):
    """The glossary is full of Chinese terms: the glyph check must have seen them."""
    glossary = [page for page in crawl if page.endswith("glossary.html")]
    assert glossary and crawl[glossary[0]][1]["hanChecked"] >= 50
