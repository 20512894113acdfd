"""Prove that the CSS purge (book/_ext/css_purge.py) changes no pixel of the book.

Usage (a script, not a test: it takes many minutes)::

    PYTHONPATH=. python tests/browser/compare_purge.py BEFORE_HTML AFTER_HTML OUT_DIR [--reverse] [--interactions-only] [PAGE ...]

BEFORE_HTML is a built book without the purge, AFTER_HTML the same book purged
(``python -m book._ext.css_purge`` style: see ``purge_copy`` below, or a build). Every page
is drawn in headless Chromium from both folders, whole-page PNG screenshots, in four
set-ups: light and dark mode (``prefers-color-scheme`` and the theme's stored ``mode``) at
a desktop width (1280 px) and a phone width (400 px, where the side bars fold away). Then,
on a few pages, states that scripts create: the side bars opened at the phone width, the
search dialog, the download drop-down, a tooltip, the copy button shown on hover, the
theme switched by its button and the page scrolled (the back-to-top button). Any pixel
that differs is reported, with both images and a difference image in OUT_DIR; the script
exits with status 1 then, 0 when every pair is identical.

Chromium does not always draw the same page twice to the same pixels: the anti-aliased
corners of a rounded box can come out one level apart from one load to the next, the same
files on both sides (measured: a few hundred pixels on about one page in twenty). So a pair
that differs is drawn again, up to ``TRIES`` times on each side, and counts as identical
only when some drawing before and some drawing after are equal in every pixel; the
tolerance stays zero. Raster settings that make drawing steadier are passed to both sides.
"""

import asyncio
import io
import sys
from pathlib import Path

import _crawl

TRIES = 4
ARGS = ["--disable-gpu", "--disable-gpu-rasterization", "--disable-partial-raster", "--force-color-profile=srgb",
        "--disable-checker-imaging", "--run-all-compositor-stages-before-draw", "--disable-threaded-animation",
        "--disable-threaded-scrolling"]
SETUPS = [("light", 1280), ("dark", 1280), ("light", 400), ("dark", 400)]
PREPARE = r"""
async () => {
  const imgs = [...document.images];
  for (const img of imgs) img.loading = 'eager';
  await Promise.all(imgs.map((img) => (img.complete && img.naturalWidth > 0) ? null :
    new Promise((r) => { img.addEventListener('load', r); img.addEventListener('error', r); setTimeout(r, 15000); })));
  await document.fonts.ready;
  await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
}
"""


def _mode_script(mode):
    return f"try {{ localStorage.setItem('mode', '{mode}'); localStorage.setItem('theme', '{mode}'); }} catch (e) {{}}"


# (name, width, mode, actions): each action is (kind, selector or key)
INTERACTIONS = [
    # the theme's own buttons open the side bars as modal dialogs at phone widths
    ("primary-sidebar", 400, "light", [("js", "document.querySelector('button.primary-toggle.pst-navbar-icon').click()")]),
    ("primary-sidebar-dark", 400, "dark", [("js", "document.querySelector('button.primary-toggle.pst-navbar-icon')"
                                                  ".click()")]),
    ("secondary-sidebar", 400, "light", [("js", "document.querySelector('button.secondary-toggle.pst-navbar-icon')"
                                                ".click()")]),
    ("search-dialog", 1280, "light", [("click", "button.search-button.pst-navbar-icon:visible, "
                                                "button.search-button-field:visible")]),
    ("search-dialog-dark", 1280, "dark", [("key", "Control+k")]),
    ("download-dropdown", 1280, "light", [("click", ".dropdown-download-buttons button.dropdown-toggle")]),
    ("download-dropdown-dark", 1280, "dark", [("click", ".dropdown-download-buttons button.dropdown-toggle")]),
    ("tooltip", 1280, "light", [("hover", "button.theme-switch-button:visible")]),
    ("theme-switch", 1280, "light", [("click", "button.theme-switch-button:visible")]),
    ("copy-button", 1280, "light", [("hover", "div.highlight")]),
    ("hide-sidebar", 1280, "light", [("click", "button.primary-toggle.btn:visible")]),
    ("toctree-expand", 1280, "light", [("js", "document.querySelector('nav.bd-docs-nav details:not([open]) > summary')"
                                              ".click()")]),
    ("details-open", 1280, "light", [("click", "details.sd-dropdown > summary:visible, .bd-article details > summary:visible, "
                                               "button.toggle-button:visible")]),
    ("details-open-dark", 1280, "dark", [("click", "details.sd-dropdown > summary:visible, .bd-article details > summary:visible, "
                                                   "button.toggle-button:visible")]),
    ("scrolled", 1280, "light", [("scroll", 2500)]),
    ("scrolled-phone", 400, "dark", [("scroll", 2500)]),
]


async def _shot(context, url, full_page=True, actions=()):
    page = await context.new_page()
    page.set_default_timeout(15000)  # a missing button fails fast ...
    try:
        await page.goto(url, wait_until="load", timeout=180000)  # ... a busy machine does not
        await page.evaluate(PREPARE)  # (evaluate has no timeout)
        for kind, arg in actions:
            if kind == "click":
                await page.locator(arg).first.click()
            elif kind == "hover":
                await page.locator(arg).first.hover()
            elif kind == "key":
                await page.keyboard.press(arg)
            elif kind == "js":
                await page.evaluate(arg)
            elif kind == "scroll":
                await page.evaluate(f"window.scrollTo(0, {arg})")
            await page.wait_for_timeout(700)  # transitions (Bootstrap's are 0.15 to 0.3 s)
        return await page.screenshot(full_page=full_page, animations="disabled", caret="hide", type="png",
                                     timeout=180000)
    finally:
        await page.close()


def _pixels(png):
    from PIL import Image

    return Image.open(io.BytesIO(png)).convert("RGBA")


def _count(a, b):
    """Number of differing pixels of two PNGs (0 when equal in every pixel)."""
    if a == b:
        return 0
    from PIL import ImageChops

    ia, ib = _pixels(a), _pixels(b)
    if ia.size != ib.size:
        return max(ia.size[0] * ia.size[1], ib.size[0] * ib.size[1])
    mask = ImageChops.difference(ia, ib).convert("RGB").point(lambda v: 255 if v else 0).convert("L")
    return mask.histogram()[255] if mask.getbbox() else 0


def _save(a, b, out, stem):
    from PIL import ImageChops

    (out / f"{stem}-before.png").write_bytes(a)
    (out / f"{stem}-after.png").write_bytes(b)
    ia, ib = _pixels(a), _pixels(b)
    if ia.size == ib.size:
        ImageChops.difference(ia, ib).convert("RGB").point(lambda v: 255 if v else 0).save(out / f"{stem}-diff.png")


async def compare(before, after, out, pages, interaction_pages, reverse=False):
    from playwright.async_api import async_playwright

    out.mkdir(parents=True, exist_ok=True)
    failures, skipped, redrawn, done = [], [], [], 0
    with _crawl.serve(before) as base_b, _crawl.serve(after) as base_a:
        async with async_playwright() as pw:
            browser = await pw.chromium.launch(executable_path=_crawl.chromium_path(), headless=True, args=ARGS)

            async def context(mode, width):
                ctx = await browser.new_context(viewport={"width": width, "height": 900}, color_scheme=mode,
                                                device_scale_factor=1, reduced_motion="reduce")
                await ctx.add_init_script(_mode_script(mode))
                return ctx

            jobs = [(rel, mode, width, ()) for rel in pages for mode, width in SETUPS]
            jobs += [(rel, mode, width, (name, acts)) for rel in interaction_pages
                     for name, width, mode, acts in INTERACTIONS]
            if reverse:  # a second process can start from the other end
                jobs.reverse()
            contexts = {}
            for rel, mode, width, extra in jobs:
                if (mode, width) not in contexts:
                    contexts[(mode, width)] = await context(mode, width)
                ctx = contexts[(mode, width)]
                name = extra[0] if extra else "page"
                actions = extra[1] if extra else ()
                stem = f"{rel.replace('/', '__')}-{mode}-{width}-{name}"
                shots_b, shots_a, count = [], [], None
                try:
                    for _ in range(TRIES):
                        shots_b.append(await _shot(ctx, base_b + rel, full_page=not extra, actions=actions))
                        shots_a.append(await _shot(ctx, base_a + rel, full_page=not extra, actions=actions))
                        count = min(_count(x, y) for x in shots_b for y in shots_a)
                        if count == 0:
                            break
                except Exception as err:  # an interaction that a page does not offer
                    skipped.append(f"{stem}: could not draw: {str(err).splitlines()[0]}")
                    print(skipped[-1], flush=True)
                    continue
                done += 1
                if len(shots_b) > 1:
                    redrawn.append(f"{stem}: drawn {len(shots_b)} times on each side, "
                                   f"{'then identical' if count == 0 else 'never identical'}")
                    print(redrawn[-1], flush=True)
                if count:
                    _save(shots_b[0], shots_a[0], out, stem)
                    failures.append(f"{stem}: {count} pixels differ")
                    print(failures[-1], flush=True)
                else:
                    print(f"identical ({done}/{len(jobs)}): {stem}", flush=True)
            await browser.close()
    return done, failures, skipped, redrawn


def main(argv):
    reverse = "--reverse" in argv
    only_interactions = "--interactions-only" in argv
    argv = [a for a in argv if a not in ("--reverse", "--interactions-only")]
    before, after, out = (Path(a) for a in argv[:3])
    pages = [] if only_interactions else (argv[3:] or _crawl.built_pages(before))
    interaction_pages = [p for p in ("derivations/planar/cognates.html", "forces/exercises.html",
                                     "spatial/rssr.html") if (before / p).exists()]
    done, failures, skipped, redrawn = asyncio.run(compare(before, after, out, pages, interaction_pages, reverse))
    print(f"{done} pairs compared ({len(pages)} pages x {len(SETUPS)} set-ups, "
          f"{len(interaction_pages)} pages x {len(INTERACTIONS)} interactions); {len(failures)} differ, "
          f"{len(skipped)} interactions not offered by a page, {len(redrawn)} pairs drawn again")
    for f in failures + skipped:
        print("  " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
