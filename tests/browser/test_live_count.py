"""Every animation player and turnable view of the built book is live (issue 25), counted.

Each page of ``book/_build/html`` that holds a figure of `figures.animate` is loaded once in
headless Chromium. A figure counts as live when its page has wired its controls
(``mechLive``) and moving one of its sliders changes the drawing; the test prints the count
of players (``.mech-anim``, moving 3-D views included) and turnable views
(``.mech-view3d``) and fails on any figure that is still a recording. Measured on the book
built with the step-built live figures: 24 of 24 players and 15 of 15 views on 16 pages,
27 to 42 s with the machine's load average near 20 (before them: 10 of 24 and 4 of 15).
"""

import re
from pathlib import Path

import pytest

import _crawl
from conftest import unavailable

ROOT = Path(__file__).resolve().parents[2]
HTML = ROOT / "book" / "_build" / "html"

PROBE = r"""
async () => {
  const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
  const figs = [...document.querySelectorAll('.mech-fig')];
  const t0 = Date.now();
  while (figs.some((d) => d.querySelector('.mech-live') && !d.querySelector('.mech-live-none') && !d.mechLive)
         && Date.now() - t0 < 20000) await sleep(50);
  return figs.map((div, k) => {
    const out = {k, player: div.classList.contains('mech-anim'), view: div.classList.contains('mech-view3d'),
                 caption: div.querySelector('svg').getAttribute('aria-label'), live: false, why: ''};
    const slider = div.querySelector('.mech-live input[type=range][data-k]');
    if (!div.mechLive || !slider) { out.why = div.querySelector('.mech-live') ? 'controls not wired' : 'no controls'; return out; }
    const before = div.querySelector('svg').innerHTML, value = +slider.value;
    const target = value + 0.05 * ((+slider.max - value) > (value - +slider.min) ? +slider.max - value : +slider.min - value);
    slider.value = String(target);
    slider.dispatchEvent(new Event('input', {bubbles: true}));
    const changed = div.querySelector('svg').innerHTML !== before;
    const msg = div.querySelector('.mech-live-msg').textContent;
    div.mechLive.set({[slider.dataset.k]: value});
    out.live = changed && !msg.startsWith('Cannot take');
    out.why = out.live ? '' : `slider ${slider.dataset.k} ${value} -> ${target}: ${changed ? msg : 'drawing unchanged'}`;
    return out;
  });
}
"""


def _pages():
    pages = []
    for page in _crawl.built_pages(HTML):
        if re.search(r'class="mech-fig ', (HTML / page).read_text(encoding="utf-8")):
            pages.append(page)
    return pages


def test_every_player_and_view_is_live(chromium):
    if not (HTML / "index.html").is_file():
        unavailable(f"no built book at {HTML.relative_to(ROOT)} (run `make book` first)")
    from playwright.sync_api import sync_playwright

    pages = _pages()
    found, errors = [], []
    with _crawl.serve(HTML) as base, sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium)
        tab = browser.new_page(viewport={"width": 1000, "height": 1400})
        tab.on("pageerror", lambda e: errors.append(str(e)))
        for page in pages:
            tab.goto(base + page, wait_until="load")
            found += [dict(fig, page=page) for fig in tab.evaluate(PROBE)]
        browser.close()
    players = [f for f in found if f["player"]]
    views = [f for f in found if f["view"]]
    count = lambda figs: f"{sum(f['live'] for f in figs)} of {len(figs)}"  # noqa: E731
    print(f"live players: {count(players)}; live turnable views: {count(views)} ({len(pages)} pages)")
    assert players and views
    assert errors == []
    dead = [(f["page"], f["k"], f["caption"], f["why"]) for f in found if not f["live"]]
    assert dead == [], dead
