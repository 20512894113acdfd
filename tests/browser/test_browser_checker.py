"""The browser checker itself, on small hand-made pages: it passes a good page and names
every fault planted in a bad one (so the book test can fail).

The good page carries a working animation and 3-D view written to the contract of issue 17
(``div.mech-anim[data-frame]`` with an svg, ``button.mech-play`` and
``input.mech-slider``; ``div.mech-view3d[data-yaw][data-pitch]`` turned by a pointer drag).
"""

import pytest

import _crawl
from conftest import unavailable

pytestmark = pytest.mark.slow

DOT_SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="20" height="20"><circle cx="10" cy="10" r="8"/></svg>'

WIDGETS = r"""
<div class="mech-anim" data-frame="0">
  <svg width="200" height="120"><circle class="pin" cx="20" cy="60" r="6"/></svg>
  <button class="mech-play">play</button>
  <input type="range" class="mech-slider" min="0" max="59" value="0">
</div>
<div class="mech-view3d" data-yaw="0.5" data-pitch="0.3">
  <svg width="200" height="200"><line x1="100" y1="100" x2="180" y2="100" stroke="black"/></svg>
</div>
<script>
for (const a of document.querySelectorAll('.mech-anim')) {
  const pin = a.querySelector('.pin'), s = a.querySelector('.mech-slider');
  const BROKEN = a.hasAttribute('data-broken');
  let timer = null;
  const draw = (k) => { a.dataset.frame = k; s.value = k; pin.setAttribute('cx', 20 + 2 * k); };
  s.addEventListener('input', () => { if (!BROKEN) draw(+s.value); });
  a.querySelector('.mech-play').addEventListener('click', () => {
    if (BROKEN) return;
    if (timer) { clearInterval(timer); timer = null; }
    else timer = setInterval(() => draw((+a.dataset.frame + 1) % 60), 40);
  });
}
for (const v of document.querySelectorAll('.mech-view3d')) {
  const svg = v.querySelector('svg');
  let last = null;
  if (v.hasAttribute('data-broken')) continue;
  svg.addEventListener('pointerdown', (e) => { last = [e.clientX, e.clientY]; });
  svg.addEventListener('pointermove', (e) => {
    if (!last) return;
    v.dataset.yaw = (+v.dataset.yaw + 0.01 * (e.clientX - last[0])).toFixed(4);
    v.dataset.pitch = (+v.dataset.pitch + 0.01 * (e.clientY - last[1])).toFixed(4);
    last = [e.clientX, e.clientY];
  });
  svg.addEventListener('pointerup', () => { last = null; });
}
</script>
"""

GOOD = f"""<!doctype html><html><head><meta charset="utf-8"><title>good</title></head><body>
<h1>A spherical four-bar (球面四杆机构)</h1>
<p>The coupler curve (连杆曲线) of a crank-rocker (曲柄摇杆机构). Cost: 5 dollars.</p>
<figure><img src="dot.svg" alt="a dot"><figcaption>A dot.</figcaption></figure>
<pre>$not math$ inside code is fine: \\(x\\)</pre>
{WIDGETS}
</body></html>"""

BAD = f"""<!doctype html><html><head><meta charset="utf-8"><title>bad</title></head><body>
<p>Unrendered: $a + b$ and \\(x^2\\).</p>
<p>A character that no font draws: \U00031350</p>
<img src="missing.png" alt="missing">
<img src="https://example.com/remote.png" alt="remote">
<figure><figcaption>A figure with nothing in it.</figcaption></figure>
<span class="math notranslate nohighlight">\\(y\\)</span>
{WIDGETS.replace('class="mech-anim"', 'class="mech-anim" data-broken').replace('class="mech-view3d"', 'class="mech-view3d" data-broken')}
<script>console.error("planted error"); undefinedFunction();</script>
</body></html>"""


@pytest.fixture(scope="module")
def results(chromium, tmp_path_factory):
    root = tmp_path_factory.mktemp("site")
    (root / "dot.svg").write_text(DOT_SVG, encoding="utf-8")
    (root / "good.html").write_text(GOOD, encoding="utf-8")
    (root / "bad.html").write_text(BAD, encoding="utf-8")
    (root / "index.html").write_text('<meta http-equiv="Refresh" content="0; url=good.html" />', encoding="utf-8")
    (root / "moved.html").write_text('<meta http-equiv="Refresh" content="0; url=gone.html" />', encoding="utf-8")
    # MathJax that never finishes typesetting: the page must time out, not hang the crawl.
    (root / "mathjax-never.js").write_text("window.MathJax = {startup: {promise: new Promise(() => {})}};")
    (root / "hang.html").write_text('<script src="mathjax-never.js"></script><p>x</p>', encoding="utf-8")
    (root / "_static").mkdir()
    (root / "_static" / "skipped.html").write_text("<p>not a page</p>", encoding="utf-8")
    shots = root / "shots"
    return _crawl.check_pages(root, screenshot_dir=shots, executable=chromium, page_timeout=60), shots


def test_good_page_has_no_problems(results):
    pages, shots = results
    problems, info = pages["good.html"]
    assert problems == []
    assert info["hanChecked"] >= 8  # 球面四杆机构, 连杆曲线, 曲柄摇杆 (distinct characters)
    assert info["images"] == 1
    assert (shots / "good.jpg").stat().st_size > 1000
    assert 1000 < info["bytes"] < 20000  # the page and its svg


@pytest.mark.parametrize("variable, value", [("MECH_BROWSER_TEST", "required"), ("CI", "true")])
def test_missing_browser_fails_where_required(monkeypatch, variable, value):
    monkeypatch.delenv("MECH_BROWSER_TEST", raising=False)
    monkeypatch.delenv("CI", raising=False)
    with pytest.raises(pytest.skip.Exception):
        unavailable("no browser")
    monkeypatch.setenv(variable, value)
    with pytest.raises(pytest.fail.Exception, match="required"):
        unavailable("no browser")


def test_asset_folders_are_not_pages(results):
    assert sorted(results[0]) == ["bad.html", "good.html", "hang.html", "index.html", "moved.html"]


def test_redirect_pages_are_checked_by_their_target(results):
    assert results[0]["index.html"] == ([], {"redirect": "good.html", "seconds": 0.0})
    assert results[0]["moved.html"][0] == ["redirects to a missing page: gone.html"]


def test_a_page_that_never_settles_times_out(results):
    assert results[0]["hang.html"][0] == ["page not checked within 60 s"]


@pytest.mark.parametrize("needle", [
    "console error: planted error",
    "uncaught exception: undefinedFunction is not defined",
    "HTTP 404 for missing.png",
    "image did not load: missing.png",
    "image did not load: https://example.com/remote.png",
    "request leaves the machine (blocked): https://example.com/remote.png",
    "figure with nothing to show",
    "math not typeset: \\(y\\)",
        "raw math in the text: ... Unrendered: $a + b$ and \\(x^2\\)",
    "missing glyphs",
    "animation 1: data-frame stays 0 after play",
    "animation 1: slider set to 19 but data-frame is 0",
    "animation 1: two slider values draw the same picture",
    "3-D view 1: data-yaw/data-pitch stay ('0.5', '0.3') after a drag",
])
def test_bad_page_fault_is_named(results, needle):
    problems = results[0]["bad.html"][0]
    assert any(needle in p for p in problems), problems


def test_tofu_reference_is_a_missing_glyph(results, chromium):
    """Two code points that no font has draw the same box; a Han character does not."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium, headless=True)
        page = browser.new_page()
        page.set_content("<p>x</p>")
        page.add_script_tag(content=_crawl.INIT_SCRIPT)
        font = "normal 400 40px serif"
        assert page.evaluate("([c, f]) => __mechTofu(c, f)", [["\U0010FFFC", "\U00031350"], font]) == [
            "\U0010FFFC", "\U00031350"]
        assert page.evaluate("([c, f]) => __mechTofu(c, f)", [["球", "杆", "A"], font]) == []
        browser.close()
