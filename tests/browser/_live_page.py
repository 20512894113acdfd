"""A page of live figures for the browser test, written from the figure functions themselves.

The page holds a four-bar with its coupler point (the player of the book's first moving
figure), an offset slider-crank, a guide-bar and a spherical four-bar
on its sphere; next to it, ``_static/mech`` and ``_static/kernels`` as the book ships them.
``data-content_root`` is set as Sphinx sets it, so the player finds the modules as in the book.
"""

import shutil
from contextlib import contextmanager
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
STATIC = ROOT / "book" / "_static"


def figures():
    """The HTML of each live figure on the page, by name."""
    from figures import live
    from figures.animate import animate, great_circle, view3d
    from mech.planar import FourBar, GuideBar, SliderCrank
    from mech.spherical import SphericalFourBar

    theta = np.radians(np.arange(0.0, 360.0, 3.0))
    pose = FourBar(10, 40, 30, 35, coupler=(20, 10)).solve(theta)
    out = {"fourbar": animate({"A": 0, "D": 35, "B": pose.B, "C": pose.C, "P": pose.P},
                              [("A", "B"), ("B", "C", "P"), ("C", "D")], ground=["A", "D"], trace=["P"],
                              inputs=np.degrees(theta),
                              live=live.fourbar(10, 40, 30, 35, theta, couplers={"P": (20, 10)})).data}
    turn = np.radians(np.arange(0.0, 360.0, 2.0))
    sc = SliderCrank(30, 100, 20).solve(turn)
    out["slidercrank"] = animate({"A": 0, "B": 30.0 * np.exp(1j * turn), "C": sc.x + 20j}, [("A", "B"), ("B", "C")],
                                 ground=["A"], blocks=["C"], lines=[[-10 + 20j, 150 + 20j]], trace=["C"],
                                 inputs=np.degrees(turn), live=live.slider_crank(30, 100, 20, turn)).data
    gb = GuideBar(150.0, 300.0).solve(turn)
    out["guidebar"] = animate({"A": 0, "D": 300.0, "B": gb.B, "E": 300.0 + 495.0 * np.exp(1j * gb.psi)},
                              [("A", "B"), ("D", "E")], ground=["A", "D"], blocks=[("B", "E")], trace=["E"],
                              inputs=np.degrees(turn), live=live.guide_bar(150.0, 300.0, turn))
    out["guidebar"] = out["guidebar"].data
    sph = SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.6))
    go = sph.solve(np.radians(np.arange(0.0, 360.0, 3.0)))
    out["spherical"] = view3d({"A": sph.A, "D": sph.D, "B": go.B, "C": go.C, "P": go.P},
                              arcs=[("A", "B"), ("B", "C"), ("C", "D"), ("B", "P"), ("C", "P")],
                              still=[(great_circle([0, 0, 1]), "grid")], sphere=True, trace=["P"],
                              inputs=np.degrees(np.arange(0.0, 360.0, 3.0)), yaw=20.0, pitch=50.0,
                              live=live.spherical_fourbar(sph, np.radians(np.arange(0.0, 360.0, 3.0)))).data
    alpha, t1 = np.radians(30.0), np.radians(np.arange(0.0, 360.0, 3.0))
    from mech.spatial import hooke_output

    t3 = hooke_output(t1, alpha)
    z_out = np.array([0.0, np.sin(alpha), np.cos(alpha)])
    e1 = np.stack([-np.sin(t1), np.cos(t1), np.zeros_like(t1)], -1)
    e3 = np.stack([np.cos(t3), np.cos(alpha) * np.sin(t3), -np.sin(alpha) * np.sin(t3)], -1)
    k1, k3 = np.array([0.0, 0.0, -0.45]), 0.45 * z_out
    out["hooke"] = view3d({"in": [0.0, 0.0, -1.75], "k1": k1, "a1": k1 + e1, "b1": k1 - e1, "e1": e1, "-e1": -e1,
                           "out": 1.75 * z_out, "k3": k3, "a3": k3 + e3, "b3": k3 - e3, "e3": e3, "-e3": -e3},
                          links=[("in", "k1"), ("k1", "a1"), ("a1", "e1"), ("k1", "b1"), ("b1", "-e1"), ("e1", "-e1"),
                                 ("out", "k3"), ("k3", "a3"), ("a3", "e3"), ("k3", "b3"), ("b3", "-e3"), ("e3", "-e3")],
                          trace=["e3"], labels=False, inputs=np.degrees(t1), live=live.hooke(alpha, t1)).data
    return out


def write(folder):
    """Write the page (index.html) and the modules into `folder`; returns the page's path."""
    folder = Path(folder)
    for sub in ("mech", "kernels"):
        shutil.copytree(STATIC / sub, folder / "_static" / sub, dirs_exist_ok=True)
    body = "".join(f'<section id="{name}">{text}</section>' for name, text in figures().items())
    page = folder / "index.html"
    page.write_text('<!DOCTYPE html><html lang="en" data-content_root="./"><head><meta charset="utf-8">'
                    f"<title>Live figures</title></head><body>{body}</body></html>", encoding="utf-8")
    return page


@contextmanager
def opened(chromium, folder):
    """A Chromium tab on the page in `folder` (served locally), once every live figure is
    wired; ``tab.problems`` collects errors and any request for something outside."""
    import _crawl
    from playwright.sync_api import sync_playwright

    with _crawl.serve(folder) as base, sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium)
        tab = browser.new_page(viewport={"width": 1000, "height": 2600})
        tab.problems = []
        tab.on("console", lambda m: tab.problems.append(m.text) if m.type == "error" and "favicon" not in m.location.get("url", "") else None)
        tab.on("pageerror", lambda e: tab.problems.append(str(e)))
        tab.on("request", lambda r: None if r.url.startswith((base, "data:", "about:")) else tab.problems.append("outside: " + r.url))
        tab.goto(base + "index.html")
        tab.wait_for_function("[...document.querySelectorAll('.mech-fig')].every((d) => d.mechLive)", timeout=30000)
        yield tab
        browser.close()
