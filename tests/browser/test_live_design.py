"""The live design pages and the in-page exercise check, in headless Chromium (issue 25).

- Guidance: five poses typed into the guidance page's pose table give the Burmester dyads
  that `mech.planar.synthesis.burmester` gives, to 1e-9 of the pose set's size, on 20
  random pose sets; dragging a pose redraws the figure.
- Function generation: precision points typed into the page give the lengths of
  `mech.planar.synthesis.precision_pairs`.
- Exercise check: on 20 answer files (right, wrong, unit-converted, malformed and missing
  answers) the page's verdicts are the verdicts of ``python -m mech.exercises check``.

The pages come from a built book, ``book/_build/html`` (or the folder named by
``MECH_BOOK_HTML``); without one the tests skip (fail when the browser test is required).
No page may load anything from outside the book or log an error.
"""

import asyncio
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import _crawl
from conftest import unavailable

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
HTML = Path(os.environ.get("MECH_BOOK_HTML", ROOT / "book" / "_build" / "html"))
GUIDANCE = "synthesis/guidance.html"
FUNCTION = "synthesis/function-generation.html"
# exercise pages and the exercises of theirs that the answer files use
EXERCISE_PAGES = {"kinematics/exercises.html": ["2-1", "2-2", "2-3", "2-6"],
                  "synthesis/function-generation.html": ["2-28", "2-29"],
                  "synthesis/guidance.html": ["2-27"]}


def _page_or_skip(rel):
    if not (HTML / rel).is_file():
        unavailable(f"no built page {rel} under {HTML} (run `make book` first)")


async def _open(browser, base, rel, problems):
    page = await browser.new_page(viewport={"width": 1100, "height": 900})
    page.on("pageerror", lambda e: problems.append(f"{rel}: script error {e}"))
    page.on("console", lambda m: problems.append(f"{rel}: console {m.text}") if m.type == "error"
            and "favicon" not in m.text and "404" not in m.text else None)
    page.on("request", lambda r: problems.append(f"{rel}: request outside the book {r.url}")
            if not r.url.startswith(base) and not r.url.startswith("data:") else None)
    page.on("response", lambda r: problems.append(f"{rel}: {r.status} for {r.url}")
            if r.status >= 400 and not r.url.endswith("favicon.ico") else None)
    await page.goto(base + rel)
    return page


def _run(chromium, job):
    from playwright.async_api import async_playwright

    async def main():
        with _crawl.serve(HTML) as base:
            async with async_playwright() as p:
                browser = await p.chromium.launch(executable_path=chromium)
                try:
                    return await job(browser, base)
                finally:
                    await browser.close()
    return asyncio.run(main())


def _pose_sets(count, seed=2025):
    """Random five-pose tasks at scales 1e-3 to 1e3 (angles in degrees, as typed)."""
    rng = np.random.default_rng(seed)
    sets = []
    for _ in range(count):
        scale = 10.0 ** rng.uniform(-3, 3)
        deg = np.round(rng.uniform(-70.0, 70.0, 5), 4)
        xy = np.round(rng.uniform(-1.0, 1.0, (5, 2)), 4) * scale
        sets.append((deg.tolist(), [[float(f"{v:.6g}") for v in p] for p in xy]))
    return sets


def test_burmester_points_in_the_browser(chromium):
    _page_or_skip(GUIDANCE)
    from mech.planar.synthesis import burmester

    sets = _pose_sets(20)
    problems = []

    async def job(browser, base):
        page = await _open(browser, base, GUIDANCE, problems)
        root = page.locator(".mech-live-design").first
        await root.scroll_into_view_if_needed()
        assert await root.locator("[data-control=n]").input_value() == "5"
        found = []
        for deg, xy in sets:
            for k in range(5):
                await root.locator(f"input[data-pose='{k}'][data-field='1']").fill(repr(xy[k][0]))
                await root.locator(f"input[data-pose='{k}'][data-field='2']").fill(repr(xy[k][1]))
                await root.locator(f"input[data-pose='{k}'][data-field='0']").fill(repr(deg[k]))
            found.append((await root.get_attribute("data-dyads"), await root.get_attribute("data-error")))
        await page.close()
        return found

    found = _run(chromium, job)
    assert not problems, problems
    worst, dyads = 0.0, 0
    for (deg, xy), (text, error) in zip(sets, found):
        assert not error, error
        d = np.array([complex(*p) for p in xy])
        size = np.max(np.abs(d - d.mean()))
        want = burmester(np.radians(deg), d).dyads
        got = json.loads(text)
        assert len(got) == len(want), (deg, xy)
        for w, (z, A) in zip(want, got):
            err = max(abs(w.circle_point - complex(*z)), abs(w.centre_point - complex(*A))) / size
            worst = max(worst, err)
            dyads += 1
    print(f"{len(sets)} pose sets, {dyads} dyads, largest difference {worst:.2e} of the pose set's size")
    assert dyads >= 20
    assert worst <= 1e-9


def test_drag_a_pose(chromium):
    _page_or_skip(GUIDANCE)
    problems = []

    async def job(browser, base):
        page = await _open(browser, base, GUIDANCE, problems)
        root = page.locator(".mech-live-design").first
        await root.scroll_into_view_if_needed()
        before = (await root.get_attribute("data-dyads"), await root.locator("svg").inner_html())
        handle = root.locator("circle[data-handle=move][data-pose='2']")
        box = await handle.bounding_box()
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        await page.mouse.move(x, y)
        await page.mouse.down()
        for k in range(1, 11):
            await page.mouse.move(x + 3 * k, y - 2 * k)
        await page.mouse.up()
        after = (await root.get_attribute("data-dyads"), await root.locator("svg").inner_html(),
                 await root.locator("input[data-pose='2'][data-field='1']").input_value())
        # the time of one drag step (solve and redraw, five poses: Burmester and twelve
        # four-bars), measured in the page over 60 synthetic moves
        times = await root.evaluate("""(root) => {
          const svg = root.querySelector('svg');
          const h = svg.querySelector('circle[data-handle=move][data-pose="4"]');
          const r = h.getBoundingClientRect();
          const x = r.x + r.width / 2, y = r.y + r.height / 2;
          h.dispatchEvent(new PointerEvent('pointerdown', {bubbles: true, clientX: x, clientY: y, pointerId: 1}));
          const out = [];
          for (let k = 1; k <= 60; k++) {
            const t0 = performance.now();
            svg.dispatchEvent(new PointerEvent('pointermove', {bubbles: true, clientX: x + k, clientY: y - k / 2, pointerId: 1}));
            out.push(performance.now() - t0);
          }
          svg.dispatchEvent(new PointerEvent('pointerup', {bubbles: true, pointerId: 1}));
          return out;
        }""")
        # four poses: the curves are drawn
        await root.locator("[data-control=n]").select_option("4")
        curves = await root.locator("path.mech-centre-curve").count()
        await page.close()
        return before, after, curves, times

    before, after, curves, times = _run(chromium, job)
    assert not problems, problems
    p95 = float(np.percentile(times, 95))
    print(f"drag step with five poses: median {np.median(times):.1f} ms, 95th percentile {p95:.1f} ms")
    assert p95 < 500        # a loose bound: the figure stays interactive on a loaded 2-core machine
    assert after[0] != before[0] and after[1] != before[1]
    assert float(after[2]) != -51.64
    assert curves == 1


def test_function_generation_in_the_browser(chromium):
    _page_or_skip(FUNCTION)
    from mech.planar.synthesis import FunctionMap, precision_pairs

    problems = []
    trials = [(1.5, 5.0, 9.0), (2.0, 4.0, 8.0), (1.2, 6.5, 9.8)]

    async def job(browser, base):
        page = await _open(browser, base, FUNCTION, problems)
        root = page.locator(".mech-live-fg").first
        await root.scroll_into_view_if_needed()
        state = json.loads(await root.get_attribute("data-state"))
        out = []
        for xs in trials:
            for i, x in enumerate(xs):
                await root.locator(f"input[data-field=x{i}]").fill(repr(x))
            out.append(json.loads(await root.get_attribute("data-lengths")))
        await page.close()
        return state, out

    state, out = _run(chromium, job)
    assert not problems, problems
    task = FunctionMap(np.log10, (1.0, 10.0), np.radians(state["thetaRange"]), np.radians(state["psiRange"]))
    for xs, got in zip(trials, out):
        g, = precision_pairs(*task.rotations(np.array(xs)), theta0=np.radians(state["theta0"]),
                             psi0=np.radians(state["psi0"]), d=state["d"], target=task)
        assert np.allclose(got, g.lengths, rtol=1e-9, atol=0), (xs, got, g.lengths)


def _answer_files(tmp_path):
    """20 answer files (12 of the kinematics exercise page, 4 each of the function-generation
    and guidance pages): answers right, wrong, in another unit, malformed, by key and seed."""
    from mech.exercises import get
    from mech.exercises._sheet import answer_quantities, solved_variant

    unit_of = {"deg": (np.radians, "rad"), "mm": (lambda v: v / 1000.0, "m")}
    files = []
    rng = np.random.default_rng(7)
    plan = [(page, numbers) for page, numbers in EXERCISE_PAGES.items() for _ in range(12 if len(numbers) == 4 else 4)]
    for k, (page, numbers) in enumerate(plan):
        number, seed = numbers[k % len(numbers)], int(rng.integers(0, 100))
        _, solution = solved_variant(get(number), seed)
        lines = [f"seed = {seed}"]
        for j, q in enumerate(answer_quantities(solution)):
            kind = (j + k) % 5
            if kind == 0:
                text = f"{q.value:.6g}"
            elif kind == 1:
                text = f"{q.value * 1.03 + 0.5:.6g}"
            elif kind == 2 and q.unit in unit_of:
                convert, unit = unit_of[q.unit]
                text = f"{convert(q.value):.8g} {unit}"
            elif kind == 2:
                text = f"{q.value:.4g} N" if q.unit != "N" else f"{q.value / 1000:.6g} kN"
            elif kind == 3:
                text = "about 3"
            else:
                text = f"{q.value * (1 + 0.009):.6g}"     # inside 1 % (+0.01): right
            lines.append(f"{q.key} = {text}")
        path = tmp_path / f"answers_{k:02d}.txt"
        path.write_text("\n".join(lines) + "\n", encoding="utf-8")
        files.append((page, number, seed, path))
    return files


def _cli_verdicts(number, path, tmp_path):
    book = tmp_path / (path.stem + "_grades.csv")
    subprocess.run([sys.executable, "-m", "mech.exercises", "check", number, "--answers", str(path),
                    "--gradebook", str(book)], cwd=ROOT, capture_output=True, text=True, timeout=300,
                   env={**os.environ, "PYTHONPATH": str(ROOT)})
    with book.open(encoding="utf-8") as f:
        return {row["key"]: row["verdict"] for row in csv.DictReader(f)}


def test_exercise_check_agrees_with_the_cli(chromium, tmp_path):
    for page in EXERCISE_PAGES:
        _page_or_skip(page)
    files = _answer_files(tmp_path)
    problems = []

    async def job(browser, base):
        out = []
        for rel in EXERCISE_PAGES:
            page = await _open(browser, base, rel, problems)
            root = page.locator(".mech-exercise-check").first
            await root.scroll_into_view_if_needed()
            for where, number, seed, path in files:
                if where != rel:
                    continue
                await root.locator("[data-control=exercise]").select_option(number)
                await root.locator("[data-control=seed]").fill(str(seed))
                await root.locator("[data-control=seed]").dispatch_event("change")
                await page.wait_for_function(
                    "([el, n]) => el.querySelector('[data-part=answers]').dataset.number === n",
                    arg=[await root.element_handle(), number])
                for line in path.read_text(encoding="utf-8").splitlines()[1:]:
                    key, _, value = line.partition("=")
                    await root.locator(f"input[data-key='{key.strip()}']").fill(value.strip())
                await root.locator("[data-control=check]").click()
                await page.wait_for_function("el => el.dataset.verdicts", arg=await root.element_handle())
                out.append(((where, number, seed, path), json.loads(await root.get_attribute("data-verdicts"))))
                await root.evaluate("el => { delete el.dataset.verdicts; }")
            await page.close()
        return out

    pages = _run(chromium, job)
    assert not problems, problems
    assert len(pages) == len(files) == 20
    compared, statuses, converted = 0, {}, 0
    for (where, number, seed, path), page in pages:
        cli = _cli_verdicts(number, path, tmp_path)
        assert page == cli, (where, number, seed, path.read_text(), page, cli)
        compared += len(cli)
        for s in cli.values():
            statuses[s] = statuses.get(s, 0) + 1
        for line in path.read_text(encoding="utf-8").splitlines()[1:]:
            key, _, value = line.partition("=")
            if value.strip().endswith((" rad", " m", " kN")) and cli[key.strip()] == "right":
                converted += 1          # right after the unit conversion
    print(f"{len(files)} answer files on {len(EXERCISE_PAGES)} pages, {compared} answers, the same verdicts: "
          f"{statuses}; {converted} of the right ones in another unit (rad, m, kN)")
    assert {"right", "wrong", "malformed"} <= set(statuses)
    assert converted >= 5
