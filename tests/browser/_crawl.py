"""Load built HTML pages in headless Chromium and list what is wrong with each.

One browser, a few tabs at once, a local HTTP server on 127.0.0.1 for the pages. For every
page :func:`check_pages` returns a list of problems (empty when the page is good):

- a JavaScript error (``console.error``, an uncaught exception) or a local file the page
  asked for and did not get (HTTP status 400 or more);
- a request for anything that is not on the local server (it is blocked, then reported);
- an ``<img>`` that did not load (``naturalWidth == 0``), or a ``<figure>`` with nothing to show;
- math that was not typeset: a ``.math`` element without its MathML ``<math>`` (the book
  writes MathML at build time, ``book/_ext/mathml.py``), a ``<math>`` with no size, an
  ``merror``, TeX left inside the MathML, or raw ``$...$``, ``\\(``, ``\\[`` in the visible text;
- an icon that was not drawn: an ``<i class="fa-solid fa-...">`` (or span) left in the page, or an icon SVG
  (``svg.svg-inline--fa``) without an outline or, where it is shown, without a size;
- a page heavier than the budget (``page_budget``, 2 MB): the bytes Chromium received for
  the page and everything it loaded, on a cold visit (see ``PAGE_CHECKS``);
- a Chinese character drawn as a missing glyph (tofu): each distinct Han character of the
  page is drawn on a canvas in the font of the element that holds it and compared pixel by
  pixel with a code point that no font has (U+10FFFD); equal bitmaps, or no ink, is tofu;
- an animation ``div.mech-anim`` that does not advance when played, does not stop when
  paused, or does not draw the frame its slider asks for; a 3-D view ``div.mech-view3d``
  that does not turn when dragged (the contract of issue 17).

A screenshot of each page (JPEG, the whole page) goes to ``screenshot_dir``.

The local server compresses text files with gzip (level 9) when the browser accepts it, as
a static host does (GitHub Pages, or nginx's ``gzip_static`` with pre-compressed files),
so the transfer sizes measured here are what a reader's browser receives. Each page is
loaded in a new browser context, with an empty cache: a cold first visit.
Playwright drives the operating system's Chromium (``executable_path``); it never
downloads a browser.
"""

import asyncio
import functools
import gzip
import io
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
PAGE_BUDGET = 2_000_000  # bytes received for any one page on a cold visit (issue 17)
MEDIAN_BUDGET = 500_000  # ... and for the median page
# Files the server compresses (the others are compressed already: PNG, JPEG, WOFF2).
COMPRESSIBLE = {".html", ".js", ".css", ".svg", ".json", ".txt", ".xml", ".map", ".ipynb", ".ttf", ".otf", ".ico"}
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
  // Math: every .math holds MathML that the browser lays out, with no TeX left in it.
  for (const m of document.querySelectorAll('.math')) {
    if (!m.querySelector('math')) {
      problems.push(`math not typeset: ${m.textContent.trim().slice(0, 80)}`);
    }
  }
  const maths = [...document.querySelectorAll('math')];
  for (const m of maths) {
    const r = m.getBoundingClientRect();
    if (m.getClientRects().length && (r.width === 0 || r.height === 0)) {
      problems.push(`math with no size: ${m.textContent.trim().slice(0, 80)}`);
    }
    if (/\\[A-Za-z]/.test(m.textContent)) problems.push(`TeX left in MathML: ${m.textContent.trim().slice(0, 80)}`);
  }
  for (const e of document.querySelectorAll('merror, mjx-merror')) {
    problems.push(`math error: ${(e.getAttribute('data-mjx-error') || e.textContent).slice(0, 80)}`);
  }
  // Icons (Font Awesome): each <i class="fa-solid fa-..."> (or span) must have become an SVG
  // with an outline.
  const FA = ['fa', 'fas', 'far', 'fab', 'fa-solid', 'fa-regular', 'fa-brands'].map((c) => `.${c}:not(svg)`).join(',');
  for (const i of document.querySelectorAll(FA)) {
    problems.push(`icon not drawn: <${i.localName} class="${i.className}">`);
  }
  const icons = [...document.querySelectorAll('svg.svg-inline--fa')];
  for (const svg of icons) {
    const path = svg.querySelector('path');
    const r = svg.getBoundingClientRect();
    if (!path || !(path.getAttribute('d') || '').length) {
      problems.push(`icon without an outline: ${svg.getAttribute('class')}`);
    } else if (svg.getClientRects().length && (r.width === 0 || r.height === 0)) {
      problems.push(`icon with no size: ${svg.getAttribute('class')}`);
    }
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
    // Han characters, and pictographs (emoji) too: a machine without an emoji font draws them as boxes
    const han = t.match(/\p{Script=Han}|\p{Extended_Pictographic}/gu);
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
    if (bad.length) problems.push(`characters drawn as missing glyphs in ${font}: ${bad.join('')}`);
  }
  // Page weight of this cold visit (an empty cache), over the page and every file it loaded
  // (lazy images included: they were loaded above): bytesTransfer is what Chromium received
  // (compressed bodies and response headers; the budget), bytes the compressed bodies,
  // bytesDecoded the files' own sizes (uncompressed).
  await document.fonts.ready;
  const entries = [...performance.getEntriesByType('navigation'), ...performance.getEntriesByType('resource')];
  const total = (list, key) => list.reduce((sum, e) => sum + (e[key] || 0), 0);
  // ... and without the theme's and the other files under _static/ that all pages share.
  const own = entries.filter((e) => !e.name.includes('/_static/'));
  const files = Object.fromEntries(entries.map((e) => [e.name.replace(location.origin + '/', ''),
    [e.transferSize || 0, e.decodedBodySize || 0]]));
  return {problems, hanChecked, bytes: total(entries, 'encodedBodySize'), bytesDecoded: total(entries, 'decodedBodySize'),
          bytesTransfer: total(entries, 'transferSize'), ownBytes: total(own, 'encodedBodySize'),
          ownBytesDecoded: total(own, 'decodedBodySize'), files, images: imgs.length, math: maths.length,
          icons: icons.length};
}
"""

# What does not fit (issue 26), measured at the viewport's width: display formulas wider
# than their column (a div.math that scrolls), whether the page itself is wider than the
# viewport (it pans sideways), and outputs of code cells that scroll sideways. Each item is
# named by its first characters, so a report says which formula or output it is.
FIT_CHECKS = r"""
() => {
  const name = (el) => Array.from((el.textContent || '').replace(/\s+/g, ' ').trim()).slice(0, 60).join('');
  const wide = (el) => el.scrollWidth > el.clientWidth + 2;
  const displays = [...document.querySelectorAll('div.math')].filter((d) => d.querySelector('math'));
  const wideDisplays = displays.filter(wide).map((d) => ({text: name(d), width: d.scrollWidth, column: d.clientWidth}));
  const outputs = [...document.querySelectorAll(
    'div.cell_output pre, div.cell_output div.output > table, div.cell_output table, div.cell_output .output_html')];
  const wideOutputs = outputs.filter(wide).map((o) => ({text: name(o), width: o.scrollWidth, column: o.clientWidth}));
  const doc = document.documentElement;
  const pageWidth = Math.max(doc.scrollWidth, document.body.scrollWidth);
  // what makes the page wider than the viewport: the widest elements that reach past it
  const culprits = [];
  // an element that reaches past the viewport and sits in no box that scrolls or clips
  const clipped = (el) => {
    for (let a = el.parentElement; a && a !== document.body && a !== doc; a = a.parentElement) {
      if (getComputedStyle(a).overflowX !== 'visible') return true;
    }
    return false;
  };
  if (pageWidth > window.innerWidth + 1) {
    for (const el of document.querySelectorAll('body *')) {
      const r = el.getBoundingClientRect();
      if (r.right > window.innerWidth + 1 && r.width > 0 && !clipped(el)
          && !el.closest('.bd-sidebar-primary, .bd-sidebar-secondary, dialog')) {
        culprits.push(`<${el.localName} class="${el.className}">${name(el)}`);
      }
      if (culprits.length >= 5) break;
    }
  }
  return {viewport: window.innerWidth, displays: displays.length, wideDisplays, outputs: outputs.length,
          wideOutputs, pageWidth, pans: pageWidth > window.innerWidth + 1, culprits};
}
"""
# Labels of the moving and turnable figures (figures/animate.py) that overlap, in every
# frame an animation can show (at most 90 frames, evenly spread) and in each turnable view
# as first drawn (issue 26). Two text boxes overlap when they share more than a sliver: a
# text box is taller than its ink, so 12 % of the smaller height may touch at top and bottom.
LABEL_CHECKS = r"""
() => {
  const found = [];
  const boxes = (svg) => [...svg.querySelectorAll('text')]
    .filter((t) => t.textContent.trim() && t.getClientRects().length)
    .map((t) => [t.textContent.trim(), t.getBoundingClientRect()]);
  const hit = (a, b) => {
    const h = 0.12 * Math.min(a.height, b.height);
    return a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top + h < b.bottom - h && b.top + h < a.bottom - h;
  };
  const check = (where, svg) => {
    const b = boxes(svg);
    for (let i = 0; i < b.length; i++) for (let j = i + 1; j < b.length; j++) {
      if (hit(b[i][1], b[j][1])) found.push(`${where}: "${b[i][0]}" overlaps "${b[j][0]}"`);
    }
  };
  const figs = [...document.querySelectorAll('div.mech-anim, div.mech-view3d')];
  figs.forEach((fig, k) => {
    const svg = fig.querySelector('svg');
    if (!svg) return;
    const name = `figure ${k + 1}` + (fig.querySelector('.mech-title') ? ` (${fig.querySelector('.mech-title').textContent})` : '');
    const slider = fig.querySelector('input.mech-slider');
    if (!slider) { check(name, svg); return; }
    const lo = +slider.min || 0, hi = +slider.max || 0, step = Math.max(1, Math.ceil((hi - lo + 1) / 90));
    for (let v = lo; v <= hi; v += step) {
      slider.value = String(v);
      slider.dispatchEvent(new Event('input', {bubbles: true}));
      check(`${name}, frame ${v}`, svg);
    }
    slider.value = String(lo);
    slider.dispatchEvent(new Event('input', {bubbles: true}));
  });
  // one line per pair of labels and figure: the first frame where they meet
  const seen = new Set(), out = [];
  for (const f of found) {
    const key = f.replace(/, frame \d+:/, ':');
    if (!seen.has(key)) { seen.add(key); out.push(f); }
  }
  return {figures: figs.length, overlaps: out};
}
"""
# Display formulas wider than the column at 1280 px, the whole book. Issue 26 asks for at
# most 5; the last eight (SymPy matrices and long roots on rssr, calculus, fourbar_position,
# path_optimisation and open_chains) are now shown by named parts and columns, so none is
# allowed: a new wide display fails.
WIDE_DISPLAY_LIMIT = 0
# Pages allowed to pan at 400 px: none (issue 26). The API reference's signatures, dotted
# names and field lists break at the column's edge and the general index's columns stack
# (book/_ext/mech-math.css).
PANNING_ALLOWED = ()
# Label collisions tolerated, as (page, label, label): none (issue 26). Kept as a named set
# so that a collision that cannot be fixed at once is listed here, not hidden.
KNOWN_LABEL_OVERLAPS = set()


def _known_overlap(rel, overlap):
    m = re.search(r'"(.+)" overlaps "(.+)"$', overlap)
    return bool(m) and any(rel.endswith(p) and {a, b} == {m.group(1), m.group(2)}
                           for p, a, b in KNOWN_LABEL_OVERLAPS)
FIT_WIDTHS = (1280, 400)


# Installed in every page before its scripts run: the tofu test on a canvas (and a resource
# timing buffer that keeps every entry: the default holds 250, too few for the page weight).
INIT_SCRIPT = r"""
performance.setResourceTimingBufferSize(100000);
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
    """A static server that sends text files gzip-compressed when the browser accepts it."""

    _cache = {}

    def log_message(self, *args):
        pass

    def send_head(self):
        path = self.translate_path(self.path)
        accepts = "gzip" in self.headers.get("Accept-Encoding", "")
        if not accepts or not os.path.isfile(path) or Path(path).suffix.lower() not in COMPRESSIBLE:
            return super().send_head()
        stat = os.stat(path)
        key = (path, stat.st_mtime_ns, stat.st_size)
        body = self._cache.get(key)
        if body is None:
            # mtime=0: the same bytes every time, as a pre-compressed file would be
            body = self._cache[key] = gzip.compress(Path(path).read_bytes(), compresslevel=9, mtime=0)
        self.send_response(200)
        self.send_header("Content-Type", self.guess_type(path))
        self.send_header("Content-Encoding", "gzip")
        self.send_header("Vary", "Accept-Encoding")
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Last-Modified", self.date_time_string(stat.st_mtime))
        self.end_headers()
        return io.BytesIO(body)


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


async def _check_one(browser, base, rel, screenshot_dir, page_budget):
    # A new context for each page: an empty cache, so the page weight is a cold first visit.
    context = await browser.new_context(viewport={"width": 1280, "height": 900}, service_workers="block")
    await context.add_init_script(INIT_SCRIPT)
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
        if page_budget is not None and info["bytesTransfer"] > page_budget:
            heavy = sorted(info["files"].items(), key=lambda kv: -kv[1][0])[:3]
            problems.append(f"page weight {info['bytesTransfer'] / 1e3:.0f} kB received, over the budget of "
                            f"{page_budget / 1e3:.0f} kB; largest: "
                            + ", ".join(f"{name} {sizes[0] / 1e3:.0f} kB" for name, sizes in heavy))
        info["fit"] = {}
        for width in FIT_WIDTHS:
            if width != 1280:
                await page.set_viewport_size({"width": width, "height": 900})
                await page.wait_for_timeout(300)
            info["fit"][width] = await page.evaluate(FIT_CHECKS)
        if FIT_WIDTHS[-1] != 1280:
            await page.set_viewport_size({"width": 1280, "height": 900})
            await page.wait_for_timeout(300)
        narrow = info["fit"][min(FIT_WIDTHS)]
        if narrow["pans"] and not rel.startswith(PANNING_ALLOWED):
            problems.append(f"page {narrow['pageWidth']} px wide at {narrow['viewport']} px, it pans sideways: "
                            + "; ".join(narrow["culprits"]))
        info["animations"] = await _check_animations(page, problems)
        labels = await page.evaluate(LABEL_CHECKS)
        info["label_overlaps"] = [o for o in labels["overlaps"] if not _known_overlap(rel, o)]
        problems.extend(f"labels collide: {o}" for o in info["label_overlaps"])
        info["views3d"] = await _check_views(page, problems)
        if screenshot_dir is not None:
            shot = Path(screenshot_dir) / (rel.removesuffix(".html").replace("/", "__") + ".jpg")
            await page.screenshot(path=str(shot), full_page=True, type="jpeg", quality=70)
    except Exception as exc:
        problems.append(f"page failed: {type(exc).__name__}: {exc}".splitlines()[0])
    finally:
        await page.close()
        await context.close()
    problems.extend(f"request leaves the machine (blocked): {url}" for url in dict.fromkeys(seen_outside))
    return rel, problems, info


async def _check_all(root, pages, screenshot_dir, tabs, executable, page_timeout, page_budget):
    from playwright.async_api import async_playwright

    results = {}
    with serve(root) as base:
        async with async_playwright() as pw:
            # Everything not on 127.0.0.1 goes to a proxy port where nothing listens, so
            # no request can leave the machine; each one is reported (see _check_one).
            browser = await pw.chromium.launch(
                executable_path=executable, headless=True,
                proxy={"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"})
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
                            _check_one(browser, base, rel, screenshot_dir, page_budget), timeout=page_timeout)
                    except asyncio.TimeoutError:
                        problems, info = [f"page not checked within {page_timeout} s"], {}
                    info["seconds"] = round(time.perf_counter() - t0, 2)
                    results[rel] = (problems, info)

            await asyncio.gather(*(one(rel) for rel in pages))
            await browser.close()
    return results


def check_pages(root, pages=None, *, screenshot_dir=None, tabs=3, executable=None, page_timeout=PAGE_TIMEOUT,
                page_budget=PAGE_BUDGET):
    """Check ``pages`` (relative paths; default: all) of the build at ``root``.

    Returns ``{page: (problems, info)}``: a list of strings, and counts (images, typeset
    formulas, icons, Han characters checked, the page weight of a cold visit: bytes
    received ``bytesTransfer``, compressed bodies ``bytes``, uncompressed ``bytesDecoded``,
    the same without the shared files of ``_static/``, and each file's ``[received,
    uncompressed]`` bytes in ``files``; animations and 3-D views exercised, seconds).
    A page that received more than ``page_budget`` bytes (None: no limit) has a problem.
    """
    root = Path(root)
    pages = built_pages(root) if pages is None else list(pages)
    if screenshot_dir is not None:
        Path(screenshot_dir).mkdir(parents=True, exist_ok=True)
    executable = executable or chromium_path()
    if executable is None:
        raise RuntimeError("no Chromium found (install the package `chromium`)")
    return asyncio.run(_check_all(root, pages, screenshot_dir, tabs, executable, page_timeout, page_budget))


def weight_summary(results):
    """Median and maximum page weight over the checked pages (redirect pages left out).

    ``{"pages": n, "received": {...}, "compressed": {...}, "uncompressed": {...}}`` with
    ``median`` and ``max`` in bytes (``received``: what Chromium received on a cold visit,
    the budget's measure; ``uncompressed``: the files' own sizes), and ``heaviest``.
    """
    infos = {page: info for page, (_, info) in results.items() if "redirect" not in info and "bytesTransfer" in info}
    def spread(key):
        values = sorted(info[key] for info in infos.values())
        if not values:
            return {}
        n = len(values)
        median = values[n // 2] if n % 2 else (values[n // 2 - 1] + values[n // 2]) / 2
        return {"median": median, "max": values[-1]}
    heaviest = max(infos, key=lambda page: infos[page]["bytesTransfer"]) if infos else None
    return {"pages": len(infos), "received": spread("bytesTransfer"), "compressed": spread("bytes"),
            "uncompressed": spread("bytesDecoded"), "heaviest": heaviest}


def budget_problems(summary, page_budget=PAGE_BUDGET, median_budget=MEDIAN_BUDGET):
    """What breaks the page-weight budget in a :func:`weight_summary` (empty when it holds).

    The budget holds whichever way a page is counted: the bytes received (gzip bodies and
    headers) and the files' own, uncompressed sizes (what the browser parses and keeps).
    """
    problems = []
    received = summary.get("received") or {}
    if not received:
        return ["no page weight was measured"]
    for measure in ("received", "uncompressed"):
        spread = summary.get(measure) or {}
        if not spread:
            problems.append(f"no {measure} page weight was measured")
            continue
        if spread["median"] >= median_budget:
            problems.append(f"median page weight {spread['median'] / 1e3:.0f} kB {measure}, "
                            f"over the budget of {median_budget / 1e3:.0f} kB")
        if spread["max"] >= page_budget:
            problems.append(f"heaviest page {summary['heaviest']} {spread['max'] / 1e3:.0f} kB {measure}, "
                            f"over the budget of {page_budget / 1e3:.0f} kB")
    return problems


async def _search(root, query, executable):
    from playwright.async_api import async_playwright

    with serve(root) as base:
        async with async_playwright() as pw:
            browser = await pw.chromium.launch(
                executable_path=executable, headless=True,
                proxy={"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"})
            page = await browser.new_page()
            errors = []
            page.on("pageerror", lambda e: errors.append(str(e)))
            await page.goto(base + "search.html", wait_until="load")
            # the search page's own field (the theme's pop-up search field is hidden)
            box = page.locator('input[name="q"]:visible').first
            await box.fill(query)
            await box.press("Enter")
            # Sphinx lists the results one by one and then writes its summary ("Search finished,
            # found N pages ..."): wait for the summary, not for the first result
            await page.wait_for_function(
                "() => /finished|did not match|no documents/i.test("
                "document.querySelector('#search-results .search-summary, #search-results p')?.textContent || '')",
                timeout=60000)
            hits = await page.eval_on_selector_all(
                "#search-results ul.search li a", "els => els.map((a) => a.getAttribute('href'))")
            await browser.close()
            return hits, errors


def search(root, query, executable=None):
    """(links of the results, uncaught errors) of typing ``query`` into the book's search page."""
    return asyncio.run(_search(Path(root), query, executable or chromium_path()))


# Key components and a style of each that only the theme's and extensions' CSS gives them:
# after the CSS purge (book/_ext/css_purge.py) they must still have it. Each entry is
# (width, mode, action, selector, JS test of `cs` (computed style) / `pseudo` (::before)).
STYLE_CHECKS = [
    (1280, "light", None, ".bd-header", "cs.display === 'flex' && cs.zIndex === '1030' && cs.boxShadow !== 'none'"),
    (1280, "light", None, ".bd-sidebar-primary", "cs.display !== 'none' && parseFloat(cs.width) > 150"),
    (1280, "light", None, "div.highlight pre", "cs.backgroundColor !== 'rgba(0, 0, 0, 0)' && cs.overflowX === 'auto'"),
    (1280, "light", None, "div.cell div.cell_input", "cs.borderLeftStyle === 'solid'"),
    (1280, "light", None, ".exercise.admonition", "cs.borderLeftStyle === 'solid' || cs.borderStyle !== 'none'"),
    (1280, "light", None, "details.admonition.hide", "cs.display === 'block'"),
    (1280, "light", None, "nav.bd-docs-nav details > summary .toctree-toggle", "cs.display === 'flex'"),
    (1280, "dark", None, "body", "cs.backgroundColor !== 'rgb(255, 255, 255)' && cs.color !== 'rgb(0, 0, 0)'"),
    (1280, "light", ("click", ".dropdown-download-buttons button.dropdown-toggle"),
     ".dropdown-download-buttons .dropdown-menu", "cs.display === 'block' && cs.position === 'absolute'"),
    (1280, "light", ("hover", "button.theme-switch-button"), ".tooltip .tooltip-arrow",
     "pseudo.borderBottomStyle === 'solid' && cs.position === 'absolute'"),
    (1280, "light", ("key", "Control+k"), "#pst-search-dialog[open]",
     "cs.display === 'block' && cs.position === 'fixed' && cs.width === '800px'"),
    # the phone layout (rules inside @media blocks): the side bar leaves the page, off-canvas
    (400, "light", None, ".bd-sidebar-primary",
     "cs.visibility === 'hidden' && cs.position === 'fixed' && cs.zIndex === '1081'"),
]


async def _styles(root, page_path, checks, executable):
    from playwright.async_api import async_playwright

    failures = []
    with serve(root) as base:
        async with async_playwright() as pw:
            browser = await pw.chromium.launch(executable_path=executable, headless=True)
            for width, mode, action, selector, test in checks:
                ctx = await browser.new_context(viewport={"width": width, "height": 900}, color_scheme=mode)
                await ctx.add_init_script(f"localStorage.setItem('mode', '{mode}')")
                page = await ctx.new_page()
                page.set_default_timeout(10000)
                await page.goto(base + page_path, wait_until="load")
                try:
                    if action is not None:
                        kind, target = action
                        if kind == "click":
                            await page.locator(target).first.click()
                        elif kind == "hover":
                            await page.locator(target).first.hover()
                        else:
                            await page.keyboard.press(target)
                        await page.wait_for_timeout(600)
                    ok = await page.evaluate(
                        "([sel, test]) => { const el = document.querySelector(sel); if (!el) return null;"
                        " const cs = getComputedStyle(el), pseudo = getComputedStyle(el, '::before');"
                        " return Boolean(new Function('cs', 'pseudo', 'return ' + test)(cs, pseudo)); }",
                        [selector, test])
                except Exception as err:
                    ok = f"error: {str(err).splitlines()[0]}"
                if ok is not True:
                    failures.append(f"{width} px {mode}, {action}: {selector}: "
                                    + ("not found" if ok is None else f"`{test}` is {ok}"))
                    if ok is False:
                        failures[-1] += " (" + await page.evaluate(
                            "s => { const c = getComputedStyle(document.querySelector(s)); return ['display',"
                            " 'position', 'visibility', 'width', 'zIndex', 'boxShadow', 'borderLeftStyle',"
                            " 'backgroundColor'].map((k) => k + ': ' + c[k]).join('; '); }", selector) + ")"
                await ctx.close()
            await browser.close()
    return failures


def style_problems(root, page, checks=STYLE_CHECKS, executable=None):
    """The :data:`STYLE_CHECKS` that fail on ``page`` of the build at ``root`` (empty: all hold)."""
    return asyncio.run(_styles(Path(root), page, checks, executable or chromium_path()))


def fit_summary(results):
    """Counts of what does not fit, from :func:`check_pages` or :func:`fit_pages` results.

    ``{width: {"wide_displays": n, "wide_display_pages": n, "panning_pages": [...],
    "wide_outputs": n, "wide_output_pages": n, "worst": [(page, width px, text), ...]}}``.
    """
    summary = {}
    for width in FIT_WIDTHS:
        fits = {page: info["fit"][width] for page, (_, info) in results.items()
                if "fit" in info and width in info["fit"]}
        displays = [(page, d["width"], d["text"]) for page, f in fits.items() for d in f["wideDisplays"]]
        outputs = [(page, o["width"], o["text"]) for page, f in fits.items() for o in f["wideOutputs"]]
        summary[width] = {
            "pages": len(fits),
            "wide_displays": len(displays),
            "wide_display_pages": len({p for p, _, _ in displays}),
            "panning_pages": sorted(page for page, f in fits.items() if f["pans"] and not page.startswith(PANNING_ALLOWED)),
            "wide_outputs": len(outputs),
            "wide_output_pages": len({p for p, _, _ in outputs}),
            "worst_displays": sorted(displays, key=lambda d: -d[1])[:10],
            "worst_outputs": sorted(outputs, key=lambda d: -d[1])[:10],
        }
    return summary


async def _fit_all(root, pages, executable, tabs):
    from playwright.async_api import async_playwright

    results = {}
    with serve(root) as base:
        async with async_playwright() as pw:
            browser = await pw.chromium.launch(
                executable_path=executable, headless=True,
                proxy={"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"})
            gate = asyncio.Semaphore(tabs)

            async def one(rel):
                async with gate:
                    if _redirect_target(root, rel) is not None:
                        return
                    fit = {}
                    for width in FIT_WIDTHS:
                        context = await browser.new_context(viewport={"width": width, "height": 900})
                        page = await context.new_page()
                        try:
                            await page.goto(base + rel, wait_until="load", timeout=60000)
                            await page.evaluate("document.fonts.ready")
                            fit[width] = await page.evaluate(FIT_CHECKS)
                            if width == 1280:
                                fit["labels"] = (await page.evaluate(LABEL_CHECKS))["overlaps"]
                        finally:
                            await context.close()
                    results[rel] = ([], {"fit": fit})

            await asyncio.gather(*(one(rel) for rel in pages))
            await browser.close()
    return results


def fit_pages(root, pages=None, executable=None, tabs=3):
    """Only the fit measures (``FIT_CHECKS``) of ``pages`` at each of ``FIT_WIDTHS``: a quick
    way to measure a build (``python tests/browser/_crawl.py fit [pages...]``)."""
    root = Path(root)
    pages = built_pages(root) if pages is None else list(pages)
    return asyncio.run(_fit_all(root, pages, executable or chromium_path(), tabs))


if __name__ == "__main__":
    import json
    import sys

    args = sys.argv[2:]
    html = Path(__file__).resolve().parents[2] / "book" / "_build" / "html"
    if args[:1] == ["--html"]:
        html, args = Path(args[1]), args[2:]
    verbose = "-v" in args
    args = [a for a in args if a != "-v"]
    chosen = [p if p.endswith(".html") else p + ".html" for p in args] or None
    res = fit_pages(html, chosen)
    out = fit_summary(res)
    if verbose or chosen:
        for page, (_, info) in sorted(res.items()):
            for width, f in info["fit"].items():
                if width == "labels":
                    continue
                for d in f["wideDisplays"]:
                    print(f"{width} display {page} {d['width']}/{d['column']}: {d['text']}")
                for d in f["wideOutputs"]:
                    print(f"{width} output {page} {d['width']}/{d['column']}: {d['text']}")
                if f["pans"]:
                    print(f"{width} PANS {page} {f['pageWidth']}: {f['culprits']}")
    overlaps = [(page, o) for page, (_, info) in sorted(res.items()) for o in info["fit"].get("labels", [])]
    for page, o in overlaps:
        print(f"LABELS {page}: {o}")
    print(json.dumps({w: {k: v for k, v in s.items() if not k.startswith("worst")} for w, s in out.items()}, indent=1))
    print("label overlaps:", len(overlaps))
