"""The build step that cuts the theme's shared files (book/_ext/page_weight.py), on the
theme's own files: the icon subset, the icon font subset and the search-script removal.
The browser test (tests/browser) checks the built pages themselves.
"""

import shutil
import sys
from pathlib import Path

import pytest

theme = pytest.importorskip("pydata_sphinx_theme")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))
import page_weight  # noqa: E402

STATIC = Path(theme.__file__).parent / "theme" / "pydata_sphinx_theme" / "static"

PAGE = """<html><head>
    <script src="_static/searchtools.js"></script>
    <script src="_static/language_data.js"></script>
    <script src="searchindex.js"></script>
</head><body>
<button><i class="fa-solid fa-magnifying-glass fa-lg"></i></button>
<span class="fa-solid fa-bars"></span>
<a class="theme-switch-button"><i class="theme-switch fa-solid fa-sun fa-lg"></i></a>
<i class="fab fa-github"></i>
</body></html>"""


@pytest.fixture
def site(tmp_path):
    """A build folder with the theme's static files and two pages."""
    shutil.copytree(STATIC, tmp_path / "_static")
    (tmp_path / "page.html").write_text(PAGE, encoding="utf-8")
    (tmp_path / "search.html").write_text(PAGE, encoding="utf-8")
    return tmp_path


def test_icons_found_in_pages_and_scripts():
    assert page_weight.icons_in_html(PAGE) == {
        ("fas", "magnifying-glass"), ("fas", "bars"), ("fas", "sun"), ("fab", "github")}
    assert page_weight.icons_in_script('r.classList="fa-solid fa-xmark",o.onclick=L') == {("fas", "xmark")}


def test_icon_script_holds_only_the_icons_in_use(site):
    kept = page_weight.subset_icons(site, [site / "page.html"])
    assert {"fas magnifying-glass", "fas bars", "fas sun", "fab github", "fas xmark"} <= set(kept)
    script = (site / page_weight.ICON_JS).read_text(encoding="utf-8")
    assert len(script) < 20_000  # from 1.49 MB
    assert '"bars":[448,512,"M0 96' in script  # the outline and view box of fa-bars (448 x 512)
    assert "fa-solid" in script and "MutationObserver" in script
    # A second run (an incremental build) leaves it as it is.
    assert page_weight.subset_icons(site, [site / "page.html"]) is None


def test_an_unknown_icon_stops_the_build(site):
    (site / "page.html").write_text('<i class="fa-solid fa-no-such-icon"></i>', encoding="utf-8")
    with pytest.raises(page_weight.PageWeightError, match="no-such-icon"):
        page_weight.subset_icons(site, [site / "page.html"])


def test_icon_font_keeps_the_code_points_of_the_css(site):
    from fontTools.ttLib import TTFont

    points = page_weight.css_code_points(site)
    assert 0xF05A in points  # --pst-icon-info-circle, the admonition icon
    assert len(points) < 40  # the 1,900 .fa-<name>:before rules do not count
    before, after = page_weight.subset_font(site, points)
    assert before > 100_000 and after < 10_000
    cmap = TTFont(site / page_weight.SOLID_FONT).getBestCmap()
    assert 0xF05A in cmap and 0xF0C9 not in cmap  # info-circle kept, bars (an SVG now) gone


def test_icon_name_rules_are_removed_from_the_css(site):
    css = site / "_static" / "styles" / "pydata-sphinx-theme.css"
    before = css.read_text(encoding="utf-8")
    assert ".fa-bars:before" in before
    page_weight.strip_icon_name_rules(site)
    after = css.read_text(encoding="utf-8")
    assert ".fa-bars:before" not in after and "--pst-icon-info-circle" in after
    assert len(after) < len(before) - 50_000


def test_search_scripts_stay_on_the_search_page_only(site):
    assert page_weight.drop_search_scripts(site / "page.html", site) is True
    assert "searchindex.js" not in (site / "page.html").read_text(encoding="utf-8")
    assert page_weight.drop_search_scripts(site / "search.html", site) is False
    assert "searchindex.js" in (site / "search.html").read_text(encoding="utf-8")


def test_a_page_with_part_of_the_search_scripts_stops_the_build(site):
    (site / "page.html").write_text('<script src="searchindex.js"></script>', encoding="utf-8")
    with pytest.raises(page_weight.PageWeightError, match="1 of the 3"):
        page_weight.drop_search_scripts(site / "page.html", site)
