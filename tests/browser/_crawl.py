"""Load built HTML pages in headless Chromium and list what is wrong with each.

One browser, a few tabs at once, a local HTTP server on 127.0.0.1 for the pages. For every
page :func:`check_pages` returns a list of problems (empty when the page is good):

- a JavaScript error (``console.error``, an uncaught exception) or a local file the page
  asked for and did not get (HTTP status 400 or more);
- a request for anything that is not on the local server (it is blocked, then reported);
- an ``<img>`` that did not load (``naturalWidth == 0``), or a ``<figure>`` with nothing to show;
- math that MathJax did not typeset: a ``.math`` element without its ``mjx-container``, a
  MathJax error box, or raw ``$...$``, ``\\(``, ``\\[`` left in the visible text;
- a Chinese character drawn as a missing glyph (tofu): each distinct Han character of the
  page is drawn on a canvas in the font of the element that holds it and compared pixel by
  pixel with a code point that no font has (U+10FFFD); equal bitmaps, or no ink, is tofu;
- an animation ``div.mech-anim`` that does not advance when played, does not stop when
  paused, or does not draw the frame its slider asks for; a 3-D view ``div.mech-view3d``
  that does not turn when dragged (the contract of issue 17).

A screenshot of each page (JPEG, the whole page) goes to ``screenshot_dir``.
Playwright drives the operating system's Chromium (``executable_path``); it never
downloads a browser.
"""

import asyncio
import functools
import re
import http.server
import os
import shutil
import subprocess
import threading
import time
from contextlib import contextmanager
from pathlib import Path

SKIP_DIRS = {"_static", "_sources", "_images", "_sphinx_design_static", "_downloads"}
PAGE_TIMEOUT = 150  # seconds for one page: load, checks and screenshot
MISSING = "\U0010FFFD"  # a private-use code point that no installed font draws

# Waits for MathJax, loads lazy images, then checks images, figures, math and Han glyphs.
PAGE_CHECKS = r"""
async () => {
  const problems = [];
  const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
  // MathJax 3: wait for the first typesetting pass when the page loads MathJax.
  if (document.querySelector('script[src*="mathjax" i]')) {
    const t0 = Date.now();
    while (!(window.MathJax && MathJax.startup && MathJax.startup.promise) && Date.now() - t0 < 30000) {
      await sleep(50);
    }
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      await MathJax.startup.promise;
    } else {
      problems.push('MathJax did not start within 30 s');
    }
  }
  // Images: load the lazy ones too.
  const imgs = [...document.images];
  for (const img of imgs) img.loading = 'eager';
  await Promise.all(imgs.map((img) => (img.complete && img.naturalWidth > 0) ? null :
    new Promise((r) => { img.addEventListener('load', r); img.addEventListener('error', r); setTimeout(r, 15000); })));
  for (const img of imgs) {
    if (!(img.complete && img.naturalWidth > 0)) problems.push(`image did not load: ${img.getAttribute('src')}`);
  }
  for (const fig of document.querySelectorAll('figure')) {
    if (!fig.querySelector('img, svg, object, video, canvas, iframe, table, .mech-anim, .mech-view3d')) {
      problems.push(`figure with nothing to show: ${(fig.id || fig.textContent).slice(0, 60)}`);
    }
  }
  // Math.
  for (const m of document.querySelectorAll('.math')) {
    if (!m.querySelector('mjx-container') && !m.closest('mjx-container')) {
      problems.push(`math not typeset: ${m.textContent.trim().slice(0, 80)}`);
    }
  }
  for (const e of document.querySelectorAll('mjx-merror')) {
    problems.push(`MathJax error: ${(e.getAttribute('data-mjx-error') || e.textContent).slice(0, 80)}`);
  }
  const SKIP = 'script, style, pre, code, textarea, kbd, mjx-container, .highlight, noscript, template';
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  const texts = [];
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const el = n.parentElement;
    if (!el || el.closest(SKIP)) continue;
    texts.push([n.nodeValue, el]);
  }
  const visible = texts.map(([t]) => t).join(' ').replace(/\s+/g, ' ');
  for (const re of [/\$\$?[^$\n]{1,300}?\$\$?/g, /\\\(|\\\)/g, /\\\[|\\\]/g]) {
    for (const m of visible.matchAll(re)) {
      const i = m.index;
      problems.push(`raw math in the text: ...${visible.slice(Math.max(0, i - 30), i + 50)}...`);
      break;
    }
  }
  // Han characters: draw each in its element's font and compare with a missing glyph.
  const byFont = new Map();
  for (const [t, el] of texts) {
    const han = t.match(/\p{Script=Han}/gu);
    if (!han) continue;
    const cs = getComputedStyle(el);
    const font = `${cs.fontStyle} ${cs.fontWeight} 40px ${cs.fontFamily}`;
    if (!byFont.has(font)) byFont.set(font, new Set());
    for (const c of han) byFont.get(font).add(c);
  }
  let hanChecked = 0;
  for (const [font, chars] of byFont) {
    const bad = window.__mechTofu([...chars], font);
    hanChecked += chars.size;
    if (bad.length) problems.push(`Chinese characters drawn as missing glyphs in ${font}: ${bad.join('')}`);
  }
  // Page weight: the page and every file it loaded, as sent (before any cache).
  const entries = [...performance.getEntriesByType('navigation'), ...performance.getEntriesByType('resource')];
  const bytes = entries.reduce((sum, e) => sum + (e.encodedBodySize || 0), 0);
  // ... and without the theme, MathJax and other files under _static/ that all pages share.
  const ownBytes = entries.filter((e) => !e.name.includes('/_static/'))
    .reduce((sum, e) => sum + (e.encodedBodySize || 0), 0);
  return {problems, hanChecked, bytes, ownBytes, images: imgs.length, math: document.querySelectorAll('mjx-container').length};
}
"""

# Installed in every page before its scripts run: the tofu test on a canvas.
INIT_SCRIPT = r"""
window.__mechTofu = (chars, font) => {
  const W = 64, H = 64;
  const canvas = document.createElement('canvas');
  canvas.width = W; canvas.height = H;
  const ctx = canvas.getContext('2d', {willReadFrequently: true});
  const draw = (c) => {
    ctx.clearRect(0, 0, W, H);
    ctx.font = font; ctx.textBaseline = 'middle'; ctx.fillStyle = '#000';
    ctx.fillText(c, 8, H / 2);
    return ctx.getImageData(0, 0, W, H).data;
  };
  const ref = draw('%s');
  const bad = [];
  for (const c of chars) {
    const img = draw(c);
    let ink = 0, same = true;
    for (let i = 3; i < img.length; i += 4) {
      if (img[i]) ink++;
      if (img[i] !== ref[i]) same = false;
    }
    if (same || ink === 0) bad.push(c);
  }
  return bad;
};
""" % MISSING


def chromium_path():
    """The operating system's Chromium, or None."""
    for name in (os.environ.get("MECH_CHROMIUM"), "chromium", "chromium-browser", "google-chrome"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def has_cjk_font():
    """True when fontconfig knows a font with Chinese glyphs."""
    try:
        out = subprocess.run(["fc-list", ":lang=zh"], capture_output=True, text=True, timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return False
    return bool(out.strip())


def built_pages(root):
    """Every HTML page of a Sphinx build, relative paths, sorted (assets excluded)."""
    root = Path(root)
    return sorted(
        p.relative_to(root).as_posix() for p in root.rglob("*.html")
        if not SKIP_DIRS.intersection(p.relative_to(root).parts)
    )


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@contextmanager
def serve(root):
    """Serve ``root`` on 127.0.0.1 (a free port) in a thread; yield the base URL."""
    handler = functools.partial(_Quiet, directory=str(root))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()


async def _check_animations(page, problems):
    anims = page.locator(".mech-anim")
    count = await anims.count()
    for i in range(count):
        anim = anims.nth(i)
        name = f"animation {i + 1}"
        try:
            await anim.scroll_into_view_if_needed(timeout=5000)
            handle = await anim.element_handle()
            start = await anim.get_attribute("data-frame")
            play = anim.locator(".mech-play").first
            slider = anim.locator("input.mech-slider").first
            if not await play.count() or not await slider.count() or not await anim.locator("svg").count():
                problems.append(f"{name}: needs an svg, a .mech-play button and an input.mech-slider")
                continue
            await play.click()
            try:
                await page.wait_for_function(
                    "([el, f]) => el.getAttribute('data-frame') !== f", arg=[handle, start], timeout=4000)
            except Exception:
                problems.append(f"{name}: data-frame stays {start} after play")
            await play.click()  # pause
            await page.wait_for_timeout(150)
            paused = await anim.get_attribute("data-frame")
            await page.wait_for_timeout(400)
            if await anim.get_attribute("data-frame") != paused:
                problems.append(f"{name}: still advancing after pause")
            lo = float(await slider.get_attribute("min") or 0)
            hi = float(await slider.get_attribute("max") or 100)
            drawn = []
            for value in (int(lo + (hi - lo) // 3), int(lo + 2 * (hi - lo) // 3)):
                await slider.evaluate(
                    "(s, v) => { s.value = String(v); s.dispatchEvent(new Event('input', {bubbles: true})); }", value)
                frame = await anim.get_attribute("data-frame")
                if frame != str(value):
                    problems.append(f"{name}: slider set to {value} but data-frame is {frame}")
                drawn.append(await anim.locator("svg").first.inner_html())
            if drawn[0] == drawn[1]:
                problems.append(f"{name}: two slider values draw the same picture")
        except Exception as exc:  # a broken widget must not stop the crawl
            problems.append(f"{name}: {type(exc).__name__}: {exc}".splitlines()[0])
    return count


async def _check_views(page, problems):
    views = page.locator(".mech-view3d")
    count = await views.count()
    for i in range(count):
        view = views.nth(i)
        name = f"3-D view {i + 1}"
        try:
            svg = view.locator("svg").first
            if not await svg.count():
                problems.append(f"{name}: no svg")
                continue
            await svg.scroll_into_view_if_needed(timeout=5000)
            before = (await view.get_attribute("data-yaw"), await view.get_attribute("data-pitch"))
            box = await svg.bounding_box()
            x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
            await page.mouse.move(x, y)
            await page.mouse.down()
            await page.mouse.move(x + 60, y + 30, steps=6)
            await page.mouse.up()
            after = (await view.get_attribute("data-yaw"), await view.get_attribute("data-pitch"))
            if after == before:
                problems.append(f"{name}: data-yaw/data-pitch stay {before} after a drag")
        except Exception as exc:
            problems.append(f"{name}: {type(exc).__name__}: {exc}".splitlines()[0])
    return count


REFRESH = re.compile(r"""<meta\s+http-equiv=["']refresh["']\s+content=["'][^"']*url=([^"'\s]+)""", re.I)


def _redirect_target(root, rel):
    """The target of a page that is only a ``<meta http-equiv="refresh">``, or None."""
    text = (Path(root) / rel).read_text(encoding="utf-8", errors="replace")
    match = REFRESH.search(text)
    if match and len(text) < 2000:
        return match.group(1)
    return None


async def _check_one(context, base, rel, screenshot_dir):
    page = await context.new_page()
    problems, seen_outside = [], []
    def console(message):
        # The browser's own probe for /favicon.ico is not a request of the page.
        if message.type == "error" and not message.location.get("url", "").endswith("/favicon.ico"):
            problems.append(f"console error: {message.text[:200]}")

    page.on("console", console)
    page.on("pageerror", lambda e: problems.append(f"uncaught exception: {str(e)[:200]}"))
    page.on("response", lambda r: problems.append(f"HTTP {r.status} for {r.url[len(base):]}")
            if r.status >= 400 and r.url.startswith(base) else None)
    page.on("request", lambda r: None if r.url.startswith((base, "data:", "blob:", "about:"))
            else seen_outside.append(r.url))
    info = {}
    try:
        await page.goto(base + rel, wait_until="load", timeout=60000)
        try:
            info = await page.evaluate(PAGE_CHECKS)
        except Exception as exc:  # a redirect page (meta refresh) navigates away
            if "context was destroyed" not in str(exc):
                raise
            await page.wait_for_load_state("load")
            info = await page.evaluate(PAGE_CHECKS)
        problems.extend(info.pop("problems"))
        info["animations"] = await _check_animations(page, problems)
        info["views3d"] = await _check_views(page, problems)
        if screenshot_dir is not None:
            shot = Path(screenshot_dir) / (rel.removesuffix(".html").replace("/", "__") + ".jpg")
            await page.screenshot(path=str(shot), full_page=True, type="jpeg", quality=70)
    except Exception as exc:
        problems.append(f"page failed: {type(exc).__name__}: {exc}".splitlines()[0])
    finally:
        await page.close()
    problems.extend(f"request leaves the machine (blocked): {url}" for url in dict.fromkeys(seen_outside))
    return rel, problems, info


async def _check_all(root, pages, screenshot_dir, tabs, executable, page_timeout):
    from playwright.async_api import async_playwright

    results = {}
    with serve(root) as base:
        async with async_playwright() as pw:
            # Everything not on 127.0.0.1 goes to a proxy port where nothing listens, so
            # no request can leave the machine; each one is reported (see _check_one).
            browser = await pw.chromium.launch(
                executable_path=executable, headless=True,
                proxy={"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"})
            context = await browser.new_context(viewport={"width": 1280, "height": 900}, service_workers="block")
            await context.add_init_script(INIT_SCRIPT)
            gate = asyncio.Semaphore(tabs)

            async def one(rel):
                async with gate:
                    t0 = time.perf_counter()
                    target = _redirect_target(root, rel)
                    if target is not None:  # the browser would leave it at once: check its target
                        ok = (Path(root) / Path(rel).parent / target.split("#")[0]).is_file()
                        results[rel] = ([] if ok else [f"redirects to a missing page: {target}"],
                                        {"redirect": target, "seconds": 0.0})
                        return
                    try:
                        _, problems, info = await asyncio.wait_for(
                            _check_one(context, base, rel, screenshot_dir), timeout=page_timeout)
                    except asyncio.TimeoutError:
                        problems, info = [f"page not checked within {page_timeout} s"], {}
                    info["seconds"] = round(time.perf_counter() - t0, 2)
                    results[rel] = (problems, info)

            await asyncio.gather(*(one(rel) for rel in pages))
            await browser.close()
    return results


def check_pages(root, pages=None, *, screenshot_dir=None, tabs=3, executable=None, page_timeout=PAGE_TIMEOUT):
    """Check ``pages`` (relative paths; default: all) of the build at ``root``.

    Returns ``{page: (problems, info)}``: a list of strings, and counts (images, typeset
    formulas, Han characters checked, bytes loaded by the page with and without the
    shared files of ``_static/``, animations and 3-D views exercised, seconds).
    """
    root = Path(root)
    pages = built_pages(root) if pages is None else list(pages)
    if screenshot_dir is not None:
        Path(screenshot_dir).mkdir(parents=True, exist_ok=True)
    executable = executable or chromium_path()
    if executable is None:
        raise RuntimeError("no Chromium found (install the package `chromium`)")
    return asyncio.run(_check_all(root, pages, screenshot_dir, tabs, executable, page_timeout))
