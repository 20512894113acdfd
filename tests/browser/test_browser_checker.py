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
<p>Math as MathML: <span class="math notranslate nohighlight"><math><msup><mi>x</mi><mn>2</mn></msup></math></span>.</p>
<p>An icon: <svg class="svg-inline--fa fa-bars" viewBox="0 0 448 512"><path fill="currentColor" d="M0 96h448v64H0z"/></svg></p>
{WIDGETS}
</body></html>"""

BAD = f"""<!doctype html><html><head><meta charset="utf-8"><title>bad</title></head><body>
<p>Unrendered: $a + b$ and \\(x^2\\).</p>
<p>A character that no font draws: \U00031350</p>
<img src="missing.png" alt="missing">
<img src="https://example.com/remote.png" alt="remote">
<figure><figcaption>A figure with nothing in it.</figcaption></figure>
<span class="math notranslate nohighlight">\\(y\\)</span>
<span class="math notranslate nohighlight"><math><mi>\\unknown</mi></math></span>
<p><i class="fa-solid fa-bars"></i> <svg class="svg-inline--fa fa-list" viewBox="0 0 512 512"></svg></p>
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
    # A page over the 2 MB budget: an image of noise (PNG cannot compress it), 2.4 MB.
    import numpy as np
    from PIL import Image

    noise = np.random.default_rng(17).integers(0, 256, size=(800, 1000, 3), dtype=np.uint8)
    Image.fromarray(noise).save(root / "noise.png")
    (root / "heavy.html").write_text('<p>heavy</p><img src="noise.png" alt="noise">', encoding="utf-8")
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
    # Cold visit: the server sent the text gzip-compressed, and every byte was received.
    assert info["bytes"] < info["bytesDecoded"]
    assert info["bytesTransfer"] >= info["bytes"]
    assert info["math"] == 1 and info["icons"] == 1


def test_heavy_page_breaks_the_budget(results):
    problems, info = results[0]["heavy.html"]
    assert info["bytesTransfer"] > 2_000_000
    assert any(p.startswith("page weight ") and "over the budget of 2000 kB" in p and "noise.png" in p
               for p in problems), problems
    summary = _crawl.weight_summary({"heavy.html": results[0]["heavy.html"], "good.html": results[0]["good.html"]})
    assert summary["heaviest"] == "heavy.html"
    assert any("heaviest page heavy.html" in p for p in _crawl.budget_problems(summary))


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
    assert sorted(results[0]) == ["bad.html", "good.html", "hang.html", "heavy.html", "index.html", "moved.html"]


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
    "TeX left in MathML: \\unknown",
    'icon not drawn: <i class="fa-solid fa-bars">',
    "icon without an outline: svg-inline--fa fa-list",
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


def _fake(received, uncompressed):
    return [], {"bytesTransfer": received, "bytes": received, "bytesDecoded": uncompressed}


def test_weight_summary_and_median_budget():
    """The median and maximum over pages, redirects left out, and both budgets on both
    measures, received and uncompressed (no browser)."""
    pages = {f"p{k}.html": _fake(v, 3 * v // 2) for k, v in enumerate([100_000, 200_000, 300_000, 700_000])}
    pages["index.html"] = ([], {"redirect": "p0.html", "seconds": 0.0})
    summary = _crawl.weight_summary(pages)
    assert summary["pages"] == 4
    assert summary["received"] == {"median": 250_000, "max": 700_000}
    assert summary["uncompressed"] == {"median": 375_000, "max": 1_050_000}
    assert _crawl.budget_problems(summary) == []
    pages["p4.html"] = _fake(450_000, 900_000)  # received median 300 kB; uncompressed 450 kB: both under
    assert _crawl.budget_problems(_crawl.weight_summary(pages)) == []
    pages["p5.html"] = _fake(460_000, 1_400_000)  # uncompressed median 675 kB: over; received 375 kB
    problems = _crawl.budget_problems(_crawl.weight_summary(pages))
    assert problems == ["median page weight 675 kB uncompressed, over the budget of 500 kB"]
    pages["p6.html"] = _fake(2_100_000, 2_100_000)  # medians 450 / 900 kB and a page over 2 MB
    problems = _crawl.budget_problems(_crawl.weight_summary(pages))
    assert problems == ["heaviest page p6.html 2100 kB received, over the budget of 2000 kB",
                        "median page weight 900 kB uncompressed, over the budget of 500 kB",
                        "heaviest page p6.html 2100 kB uncompressed, over the budget of 2000 kB"]
    assert _crawl.budget_problems(_crawl.weight_summary({})) == ["no page weight was measured"]
