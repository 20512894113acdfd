"""The build step that drops unused CSS rules (book/_ext/css_purge.py), on a small fixture
and on the theme's own stylesheet. The proof that the built book draws the same pixels is
tests/browser/compare_purge.py (run by hand on a build before and after the purge); the
browser test checks the purged book's key components have their styles.
"""

import sys
from pathlib import Path

import pytest

tinycss2 = pytest.importorskip("tinycss2")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))
import css_purge  # noqa: E402

PAGE = """<!DOCTYPE html><html><head>
<script>document.documentElement.dataset.mode = "dark"; const extra = "inline-only";</script>
</head><body class="page">
<div id="main" class='article wide'><p class=note>text</p></div>
<template><span class="in-template"></span></template>
</body></html>"""

SCRIPT = """
button.addEventListener("click", () => { menu.classList.toggle("js-open"); });
const placed = `bs-${name}-auto`;
"""

CSS = """@charset "UTF-8";
/*! licence: keep me */
/* an ordinary comment */
:root{--x:1px}
html,body{margin:0}
p{color:red}
[data-theme=dark] p{color:white}
.page .article{width:1px}
.unused-thing{color:blue}
.unused-a,.note{color:green}
#main>.wide{padding:0}
#nothing{padding:1px}
.menu.js-open{display:block}
.bs-tooltip-auto{top:0}
.gone:not(.article){color:red}
.article:not(.gone){color:teal}
:is(.gone, .article) p{margin:1px}
.in-template{color:olive}
.inline-only{color:navy}
@media (max-width:600px){.unused-thing{color:red}.note{color:black}}
@media print{.unused-thing{color:red}}
@supports (display:grid){.unused-thing{display:grid}}
@font-face{font-family:X;src:url(x.woff2)}
@keyframes spin{to{transform:rotate(1turn)}}
@keyframes fade{to{opacity:0}}
.article{animation:spin 1s}
.unused-thing{animation:fade 1s}
/*# sourceMappingURL=theme.css.map */
"""


@pytest.fixture
def purged():
    words = css_purge.words_of_html(PAGE) | css_purge.words_of_script(SCRIPT)
    return css_purge.purge_css(CSS, words)


@pytest.mark.parametrize("kept", [
    '@charset "UTF-8";', "/*! licence: keep me */", ":root{--x:1px}", "html,body{margin:0}", "p{color:red}",
    "[data-theme=dark] p{color:white}", ".page .article{width:1px}", ".unused-a,.note{color:green}",
    "#main>.wide{padding:0}", ".article:not(.gone){color:teal}", ":is(.gone, .article) p{margin:1px}",
    ".in-template{color:olive}", ".inline-only{color:navy}", "@font-face{font-family:X;src:url(x.woff2)}",
    "@keyframes spin{to{transform:rotate(1turn)}}", ".article{animation:spin 1s}",
    "@media (max-width:600px){.note{color:black}}",
    # classes that only a script adds: a plain string and a template literal's prefix
    ".menu.js-open{display:block}", ".bs-tooltip-auto{top:0}",
])
def test_rules_that_can_match_stay(purged, kept):
    assert kept in purged


@pytest.mark.parametrize("gone", [
    ".unused-thing", "#nothing", ".gone:not(.article)", "@media print", "@supports", "@keyframes fade",
    "an ordinary comment", "sourceMappingURL",
])
def test_rules_that_cannot_match_go(purged, gone):
    assert gone not in purged


def test_selector_needs_only_top_level_classes_and_ids():
    def needs(selector):
        return css_purge.selector_needs(tinycss2.parse_component_value_list(selector))

    assert needs("div.a > #b .c:hover::before") == {".a", "#b", ".c"}
    assert needs(".a:not(.b)") == {".a"}
    assert needs(":where(.a, .b) [class~=c]") == set()
    assert needs("input[type=checkbox]:checked+label") == set()


def test_known_names_and_prefixes():
    words = {"show", "bs-*"}
    assert css_purge.known("show", words)
    assert css_purge.known("bs-popover-auto", words)
    assert not css_purge.known("bsx-popover", words)
    assert not css_purge.known("hide", words)


def test_purge_files_once(tmp_path):
    """The build step on a folder: rewrites each stylesheet once, drops its source map."""
    (tmp_path / "_static" / "styles").mkdir(parents=True)
    (tmp_path / "page.html").write_text(PAGE, encoding="utf-8")
    (tmp_path / "_static" / "menu.js").write_text(SCRIPT, encoding="utf-8")
    sheet = tmp_path / "_static" / "styles" / "theme.css"
    sheet.write_text(CSS, encoding="utf-8")
    (tmp_path / "_static" / "styles" / "theme.css.map").write_text("{}", encoding="utf-8")
    sizes = css_purge.purge(tmp_path, [tmp_path / "page.html"])
    assert list(sizes) == ["_static/styles/theme.css"]
    before, after = sizes["_static/styles/theme.css"]
    assert after < before
    text = sheet.read_text(encoding="utf-8")
    assert ".menu.js-open{display:block}" in text and ".unused-thing" not in text
    assert not (tmp_path / "_static" / "styles" / "theme.css.map").exists()
    assert css_purge.purge(tmp_path, [tmp_path / "page.html"]) == {}  # an incremental build: done already
    assert sheet.read_text(encoding="utf-8") == text


def test_bad_stylesheet_stops_the_build():
    with pytest.raises(css_purge.CSSPurgeError):
        css_purge.purge_css("a{color:red}}", set())


def test_theme_stylesheet_purged_and_parsed_again():
    """pydata-sphinx-theme's own CSS: a page with none of its components keeps far less,
    and what is left parses with no error (the serialised rules are valid CSS)."""
    theme = pytest.importorskip("pydata_sphinx_theme")
    css = Path(theme.__file__).parent / "theme" / "pydata_sphinx_theme" / "static" / "styles" / "pydata-sphinx-theme.css"
    text = css.read_text(encoding="utf-8")
    purged = css_purge.purge_css(text, css_purge.words_of_html(PAGE))
    assert len(purged) < 0.5 * len(text)
    assert ":root" in purged
    rules = tinycss2.parse_stylesheet(purged, skip_whitespace=True, skip_comments=True)
    assert not [r for r in rules if r.type == "error"]
