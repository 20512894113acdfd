"""Every page of the built book in headless Chromium (issue 17, item 4).

Loads each page of ``book/_build/html`` once (one browser, three tabs) and fails a page on
a JavaScript error, a request that leaves the machine, an image or figure that does not
load, untypeset math, an icon not drawn, a Chinese character drawn as a missing glyph, an
animation or 3-D view that does not respond, or a page heavier than 2 MB (see
``_crawl.py``). A screenshot of every page goes to ``book/_build/screenshots/`` and the
counts and page weights to ``book/_build/screenshots/report.json``.

Page weight (issue 17): each page is loaded cold (an empty cache) from a server that sends
text files gzip-compressed, and the budget (any page under 2 MB, the median page under
500 kB) holds on two measures: the bytes Chromium received for the page and everything it
loaded, and the same files' own, uncompressed sizes.

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

    infos = [info for _, info in results.values() if "redirect" not in info]
    shared = {}
    for info in infos:
        for name, sizes in info.get("files", {}).items():
            if name.startswith("_static/") or name == "searchindex.js":
                shared[name.split("?")[0]] = sizes
    report = {
        "pages": len(results),
        "seconds": round(seconds, 1),
        "budget": {"page_max_bytes": _crawl.PAGE_BUDGET, "page_median_bytes": _crawl.MEDIAN_BUDGET,
                   "measure": "bytes received (transferSize: gzip bodies and headers) and uncompressed "
                              "(decodedBodySize), cold cache; both must hold"},
        "weight": _crawl.weight_summary(results),
        "bytes_loaded_outside_static": spread(info.get("ownBytes", 0) for info in infos),
        "html_bytes": spread((HTML / page).stat().st_size for page in results),
        "shared_files": {name: {"received": sizes[0], "uncompressed": sizes[1]}
                         for name, sizes in sorted(shared.items(), key=lambda kv: -kv[1][1])},
        "fit": _crawl.fit_summary(results),
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


def test_page_weight_budget(crawl):
    """Issue 17: a cold visit of any page under 2 MB, the median page under 500 kB, both
    received and uncompressed."""
    summary = _crawl.weight_summary(crawl)
    assert summary["pages"] >= 20
    assert _crawl.budget_problems(summary) == []
    # The server really compressed: what was received is well under the files' own size.
    assert summary["received"]["median"] < 0.6 * summary["uncompressed"]["median"]


def test_search_page_finds_a_term(chromium):
    """searchindex.js is loaded by search.html only; the search must still work there."""
    if not PAGES:
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    hits, errors = _crawl.search(HTML, "Grashof", executable=chromium)
    assert errors == []
    assert len(hits) >= 3, hits
    assert any("grashof" in hit.lower() for hit in hits), hits


def test_only_the_search_page_loads_the_search_index():
    if not PAGES:
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    loading = [page for page in PAGES if "searchindex.js" in (HTML / page).read_text(encoding="utf-8")]
    assert loading == ["search.html"]


def test_key_components_keep_their_styles(chromium):
    """The CSS purge (book/_ext/css_purge.py) left the theme's key components styled: the
    header, side bar, code cells, exercises, the drop-down, tooltip and search dialog that
    scripts open, dark mode and the phone layout (``_crawl.STYLE_CHECKS``)."""
    if not PAGES:
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    page = "forces/exercises.html"  # code cells, exercises with solutions, hidden cells
    assert page in PAGES
    assert _crawl.style_problems(HTML, page, executable=chromium) == []


def test_equations_and_pages_fit(crawl):
    """Issue 26: at most WIDE_DISPLAY_LIMIT display formulas wider than their column at
    1280 px in the whole book, and no page wider than a 400 px screen (each page that pans
    also fails its own test_page_in_browser, naming what sticks out)."""
    fit = _crawl.fit_summary(crawl)
    wide = fit[1280]
    assert wide["pages"] >= 20
    assert wide["wide_displays"] <= _crawl.WIDE_DISPLAY_LIMIT, wide["worst_displays"]
    assert fit[400]["panning_pages"] == []


def test_labels_never_collide(crawl):
    """Issue 26: no two labels of a moving or turnable figure overlap, in any frame (each
    page with a collision also fails its own test_page_in_browser, naming the labels);
    `_crawl.KNOWN_LABEL_OVERLAPS`, the collisions tolerated, is empty."""
    overlaps = {page: info["label_overlaps"] for page, (_, info) in crawl.items() if info.get("label_overlaps")}
    assert overlaps == {}
