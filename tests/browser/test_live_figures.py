"""Live figures in headless Chromium (issue 25): every control changes the linkage.

The page is written from the figure functions (``_live_page``): a four-bar with a coupler
point and its 720-pose coupler curve, an offset slider-crank and a spherical four-bar. Each
field, slider, branch switch and drag handle must change the drawing and the coupler curve;
the length controls must change the stated type when they cross a Grashof boundary; a drag
through a change point must keep the branch (checked against `mech.planar.FourBar`, NumPy,
on the same branch); input the linkage cannot take must give a readable message, never NaN.
The frame time of a drag is measured (the update: kernels, drawing, forced layout) and its
95th percentile must stay under 8 ms (four-bar) and 16 ms (spherical four-bar).
"""

import json

import numpy as np
import pytest

import _live_page

FRAME_P95_MS = {"fourbar": 8.0, "spherical": 16.0}


@pytest.fixture(scope="module")
def page(chromium, tmp_path_factory):
    folder = tmp_path_factory.mktemp("live")
    _live_page.write(folder)
    with _live_page.opened(chromium, folder) as tab:
        yield tab


def state(page, name):
    return page.evaluate("""(name) => {
      const div = document.querySelector('#' + name + ' .mech-fig');
      return {svg: div.querySelector('svg').innerHTML,
              curve: [...div.querySelectorAll('.mf-path-all')].map((p) => p.getAttribute('d')).join('|'),
              kind: div.querySelector('.mech-live-type').textContent,
              out: div.querySelector('.mech-live-out').textContent,
              msg: div.querySelector('.mech-live-msg').textContent,
              branch: div.querySelector('.mech-branch').textContent};
    }""", name)


def set_field(page, name, key, value, kind="range"):
    page.evaluate("""([name, key, value, kind]) => {
      const input = document.querySelector(`#${name} .mech-live input[type=${kind}][data-k=${key}]`);
      input.value = String(value);
      input.dispatchEvent(new Event('input', {bubbles: true}));
    }""", [name, key, value, kind])


def drag(page, name, handle, dx, dy, steps=12):
    dot = page.locator(f'#{name} circle.mf-handle[data-handle="{handle}"]')
    box = dot.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + dx, y + dy, steps=steps)
    page.mouse.up()


def to_frame(page, name, frame):
    page.locator(f"#{name} input.mech-slider").evaluate(
        "(s, f) => { s.value = String(f); s.dispatchEvent(new Event('input', {bubbles: true})); }", frame)


def assert_changed(before, after, retypes, why):
    """The drawing and the coupler curve changed, no NaN is shown, and the type changed when it should."""
    assert after["svg"] != before["svg"], why
    assert after["curve"] != before["curve"], why
    assert "NaN" not in after["out"] + after["msg"], why
    if retypes:
        assert after["kind"] != before["kind"], (why, after["out"], after["msg"])


def reset(page, name, values):
    page.evaluate("([name, values]) => document.querySelector('#' + name + ' .mech-fig').mechLive.set(values)",
                  [name, values])


FOURBAR = {"a": 10, "b": 40, "c": 30, "d": 35, "p": 20, "q": 10, "branch": 1, "ox": 0, "oy": 0, "angle": 0}
SLIDER = {"a": 30, "b": 100, "e": 20, "branch": 1}
GUIDE = {"a": 150, "d": 300}
SPHERE = {"a": np.degrees(0.3), "b": np.degrees(0.9), "c": np.degrees(0.7), "d": np.degrees(1.0),
          "r": np.degrees(0.4), "g": np.degrees(0.6), "branch": 1}

# For each control, a value that changes the linkage and, for the lengths, its type.
CHANGES = [
    ("fourbar", FOURBAR, "a", 30, True), ("fourbar", FOURBAR, "b", 60, True), ("fourbar", FOURBAR, "c", 10, True),
    ("fourbar", FOURBAR, "d", 10, True), ("fourbar", FOURBAR, "p", -15, False), ("fourbar", FOURBAR, "q", 25, False),
    ("slidercrank", SLIDER, "a", 90, True), ("slidercrank", SLIDER, "b", 45, True), ("slidercrank", SLIDER, "e", 80, True),
    ("guidebar", GUIDE, "a", 200, False), ("guidebar", GUIDE, "d", 250, False),
    ("hooke", {"alpha": 30.0}, "alpha", 60, True),
    ("spherical", SPHERE, "a", 60, True), ("spherical", SPHERE, "b", 25, True), ("spherical", SPHERE, "c", 10, True),
    ("spherical", SPHERE, "d", 20, True), ("spherical", SPHERE, "r", 50, False), ("spherical", SPHERE, "g", -90, False),
]


@pytest.mark.parametrize("name, start, key, value, retypes", CHANGES, ids=[f"{c[0]}-{c[2]}" for c in CHANGES])
def test_each_slider_changes_drawing_curve_and_type(page, name, start, key, value, retypes):
    reset(page, name, start)
    before = state(page, name)
    set_field(page, name, key, value)
    assert_changed(before, state(page, name), retypes, (key, value))
    reset(page, name, start)
    assert state(page, name)["kind"] == before["kind"]


def drag_to(page, name, handle, target, steps=15):
    """Drag `handle` to the point `target` of the figure (x, y; or a unit 3-vector on the sphere)."""
    xy = page.evaluate("""([name, target]) => {
      const div = document.querySelector('#' + name + ' .mech-fig'), live = div.mechLive, d = live.data;
      const user = target.length === 3 ? live.api.project(target) : [target[0] / d.grid, -target[1] / d.grid];
      if (target.length === 3 && user[2] < 0) return null;  // behind the sphere
      const p = new DOMPoint(user[0], user[1]).matrixTransform(live.api.svg.getScreenCTM());
      return [p.x, p.y];
    }""", [name, list(map(float, target))])
    assert xy is not None, f"{handle} target {target} is behind the sphere"
    box = page.locator(f'#{name} circle.mf-handle[data-handle="{handle}"]').bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.down()
    page.mouse.move(xy[0], xy[1], steps=steps)
    page.mouse.up()


def fields(page, name):
    return page.evaluate("""(name) => Object.fromEntries([...document.querySelectorAll(
      '#' + name + ' .mech-live input[type=number]')].map((i) => [i.dataset.k, +i.value]))""", name)


def _towards(frm, to, angle):
    """The unit vector at arc `angle` from `frm` on the great circle towards `to`."""
    t = np.asarray(to) - np.dot(frm, to) * np.asarray(frm)
    return np.cos(angle) * np.asarray(frm) + np.sin(angle) * t / np.linalg.norm(t)


def _sphere():
    from mech.spherical import SphericalFourBar

    return SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.6))


def _drags():
    sph = _sphere()
    B, C = sph.solve(0.0).B, sph.solve(0.0).C
    return [
        # figure, handle, target, does the type change
        ("fourbar", "D", (12.0, 0.0), True), ("fourbar", "A", (20.0, 0.0), True), ("fourbar", "B", (30.0, 0.0), True),
        ("fourbar", "C", (35.0, 10.0), True), ("fourbar", "P", (5.0, 30.0), False),
        ("slidercrank", "B", (90.0, 0.0), True), ("slidercrank", "C", (60.0, 90.0), True),
        ("guidebar", "B", (100.0, 0.0), False), ("guidebar", "D", (250.0, 0.0), False),
        ("spherical", "P", _towards(B, sph.D, 0.5), False), ("spherical", "B", _towards(sph.A, B, np.radians(60.0)), True),
        ("spherical", "C", _towards(sph.D, C, np.radians(12.0)), True),
        ("spherical", "D", _towards(sph.A, sph.D, np.radians(20.0)), True),
    ]


def _stated_type(name, values):
    """The type by the Python package (NumPy), from the lengths the page's fields show."""
    if name == "fourbar":
        from mech.planar import grashof

        return grashof(values["a"], values["b"], values["c"], values["d"]).kind
    if name == "guidebar":
        return "oscillating guide-bar (the guide swings)"
    if name == "slidercrank":
        turns = values["b"] >= values["a"] + abs(values["e"])
        return "crank-slider (the crank turns fully)" if turns else "rocker-slider (the crank rocks)"
    from mech.spherical import classify

    return classify(*(np.radians(values[k]) for k in "abcd")).kind


@pytest.mark.parametrize("name, handle, target, retypes", _drags(), ids=[f"{d[0]}-{d[1]}" for d in _drags()])
def test_each_handle_changes_drawing_curve_and_type(page, name, handle, target, retypes):
    start = {"fourbar": FOURBAR, "slidercrank": SLIDER, "guidebar": GUIDE, "spherical": SPHERE}[name]
    reset(page, name, start)
    to_frame(page, name, 0)
    before = state(page, name)
    drag_to(page, name, handle, target)
    after = state(page, name)
    assert_changed(before, after, retypes, handle)
    # fields shown to 6 digits: far enough from a Grashof boundary for these targets
    assert after["kind"] == _stated_type(name, fields(page, name)), (after, fields(page, name))
    reset(page, name, start)


def test_first_drag_on_a_fresh_page(page):
    """Before any other change the drawing is the build's: a first drag of a coupler point or
    a joint works on it (the page solves the pose it shows)."""
    page.reload()
    page.wait_for_function("[...document.querySelectorAll('.mech-fig')].every((d) => d.mechLive)", timeout=30000)
    sph = _sphere()
    B, C = sph.solve(0.0).B, sph.solve(0.0).C
    for name, handle, target in (("fourbar", "P", (5.0, 30.0)), ("slidercrank", "C", (60.0, 90.0)),
                                 ("spherical", "C", _towards(sph.D, C, np.radians(12.0))),
                                 ("spherical", "P", _towards(B, sph.D, 0.5))):
        before = state(page, name)
        drag_to(page, name, handle, target)
        assert_changed(before, state(page, name), False, (name, handle))
        reset(page, name, {"fourbar": FOURBAR, "slidercrank": SLIDER, "spherical": SPHERE}[name])


def test_page_readout_is_the_build_readout(page):
    """The read-out the page computes (JS kernels) for the first linkage is, word for word and
    digit for digit, the one the build wrote (figures.live with mech, NumPy)."""
    got = page.evaluate("""() => [...document.querySelectorAll('.mech-fig')].map((div) => {
      const out = div.querySelector('.mech-live-out'), built = out.textContent;
      div.mechLive.update({});
      return [div.parentNode.id, built, out.textContent];
    })""")
    assert len(got) == 5
    for name, built, live in got:
        assert live == built, name


def test_branch_switch(page):
    reset(page, "fourbar", FOURBAR)
    before = state(page, "fourbar")
    page.locator("#fourbar .mech-branch").click()
    after = state(page, "fourbar")
    assert after["branch"] != before["branch"] and after["svg"] != before["svg"] and after["curve"] != before["curve"]
    page.locator("#fourbar .mech-branch").click()
    assert state(page, "fourbar")["svg"] == before["svg"]


def _pose_C(page, name, point):
    """The drawn position of `point` at the current frame, in the figure's units."""
    return page.evaluate("""([name, point]) => {
      const div = document.querySelector('#' + name + ' .mech-fig'), d = div.mechLive.data;
      const f = +div.getAttribute('data-frame'), arr = d.P[d.names.indexOf(point)];
      return [arr[2 * f] * d.grid, -arr[2 * f + 1] * d.grid];
    }""", [name, point])


def test_drag_through_change_point_keeps_branch(page):
    """d from 35 down to 15 passes the change point d = 20 (a + b = c + d): C moves on smoothly,
    on the branch that mech.planar.FourBar (NumPy) solves for branch +1 at every step."""
    from mech.planar import FourBar

    reset(page, "fourbar", FOURBAR)
    to_frame(page, "fourbar", 20)  # 60 degrees
    kinds, path = set(), []
    for d in np.linspace(35.0, 15.0, 201):
        set_field(page, "fourbar", "d", round(float(d), 6), "number")
        s = state(page, "fourbar")
        kinds.add(s["kind"])
        assert s["branch"] == "branch +1" and not s["msg"], s
        C = complex(*_pose_C(page, "fourbar", "C"))
        ref = complex(FourBar(10, 40, 30, round(float(d), 6), branch=1).solve(np.radians(60.0)).C)
        assert abs(C - ref) < 1e-3 * 35, (d, C, ref)  # the drawing's grid is 4 digits of the figure
        path.append(C)
    steps = np.abs(np.diff(path))
    assert steps.max() < 5 * np.median(steps) + 1e-9   # no jump to the other assembly
    assert {"crank-rocker", "triple-rocker"} <= kinds


def test_unassemblable_input_gives_a_message(page):
    reset(page, "fourbar", FOURBAR)
    set_field(page, "fourbar", "a", 110, "number")       # longer than the other three together
    s = state(page, "fourbar")
    assert "Expected `a` shorter than the other three links together" in s["msg"]
    assert "crank-rocker" in s["kind"]                   # the last linkage that assembles is kept
    to_frame(page, "fourbar", 0)
    set_field(page, "fourbar", "a", 30, "number")        # a triple-rocker: frame 0 does not assemble
    s = state(page, "fourbar")
    assert s["kind"] == "triple-rocker" and "cannot be assembled" in s["msg"] and "NaN" not in s["msg"]
    set_field(page, "guidebar", "a", 400, "number")      # mech.planar.GuideBar: an oscillating guide only
    assert "Expected `a` < `d` = 300 for an oscillating guide, got 400" in state(page, "guidebar")["msg"]
    reset(page, "guidebar", GUIDE)
    set_field(page, "spherical", "b", 170, "number")
    s = state(page, "spherical")
    assert s["msg"] and "NaN" not in s["msg"] + s["out"]
    reset(page, "fourbar", FOURBAR)
    reset(page, "spherical", SPHERE)


def _frame_times(page, name, handle, moves):
    page.evaluate("(name) => { document.querySelector('#' + name + ' .mech-fig').mechLive.times = []; }", name)
    dot = page.locator(f'#{name} circle.mf-handle[data-handle="{handle}"]')
    box = dot.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(moves):
        t = 2 * np.pi * k / moves
        page.mouse.move(x + 25 * np.sin(t), y + 20 * (1 - np.cos(t)))
    page.mouse.up()
    return page.evaluate("(name) => document.querySelector('#' + name + ' .mech-fig').mechLive.times", name)


@pytest.mark.parametrize("name, handle", [("fourbar", "P"), ("fourbar", "D"), ("spherical", "P"), ("spherical", "C")])
def test_drag_frame_time(page, name, handle, record_property):
    """The machine is shared (its load is often 10 to 20 on two cores): a round of 300 moves
    whose 95th percentile is over the bound is measured again, up to three rounds."""
    start = FOURBAR if name == "fourbar" else SPHERE
    rounds = []
    for _ in range(3):
        reset(page, name, start)
        times = np.array(_frame_times(page, name, handle, 320))[20:]  # after 20 moves of warm-up (compilation)
        assert times.size >= 280
        p50, p95 = np.percentile(times, [50, 95])
        rounds.append((round(float(p50), 2), round(float(p95), 2)))
        print(f"{name} {handle}: {times.size} drag frames, median {p50:.2f} ms, p95 {p95:.2f} ms")
        if p95 < FRAME_P95_MS[name]:
            break
    record_property("frame_ms", json.dumps(rounds))
    reset(page, name, start)
    assert rounds[-1][1] < FRAME_P95_MS[name], rounds


def test_nothing_from_outside_and_no_errors(page):
    assert page.problems == []


def _point(page, name, point, frame):
    """The drawn position of `point` at `frame` after a change (the page's own numbers)."""
    return page.evaluate("""([name, point, f]) => {
      const d = document.querySelector('#' + name + ' .mech-fig').mechLive.data;
      const arr = d.P[d.names.indexOf(point)];
      if (d.kind === '3d') return [0, 1, 2].map((k) => arr[3 * f + k] * d.step + d.c0[k]);
      return [arr[2 * f] * d.grid, -arr[2 * f + 1] * d.grid];
    }""", [name, point, frame])


def test_changed_poses_agree_with_the_package(page):
    """After a change, the page's poses (JS kernels) are the package's (NumPy) at the frame's angle."""
    from mech.planar import FourBar, GuideBar, SliderCrank
    from mech.spatial import hooke_output
    from mech.spherical import SphericalFourBar

    f = 17
    # the frames' angles as the page has them (7 decimals of a radian)
    angle = lambda name: page.evaluate(  # noqa: E731
        "([name, f]) => document.querySelector('#' + name + ' .mech-fig').mechLive.data.live.theta[f]", [name, f])
    theta = angle("fourbar")
    reset(page, "fourbar", dict(FOURBAR, a=12.5, d=33.0, p=-5.0, q=8.0))
    ref = FourBar(12.5, 40, 30, 33.0, coupler=(-5.0, 8.0)).solve(theta)
    for point, z in (("B", ref.B), ("C", ref.C), ("P", ref.P)):
        assert abs(complex(*_point(page, "fourbar", point, f)) - complex(z)) < 1e-12 * 40
    turn = angle("slidercrank")
    reset(page, "slidercrank", dict(SLIDER, a=35.0, e=-10.0))
    ref = SliderCrank(35.0, 100, -10.0).solve(turn)
    assert abs(complex(*_point(page, "slidercrank", "C", f)) - complex(ref.C)) < 1e-12 * 100
    reset(page, "guidebar", {"a": 120.0, "d": 300.0})
    ref = GuideBar(120.0, 300.0).solve(turn)
    assert abs(complex(*_point(page, "guidebar", "B", f)) - complex(ref.B)) < 1e-12 * 300
    E = complex(*_point(page, "guidebar", "E", f))
    assert abs(np.angle(E - 300.0) - float(ref.psi)) < 1e-12
    reset(page, "spherical", dict(SPHERE, a=20.0, r=30.0, g=-40.0, branch=-1))
    ref = SphericalFourBar(np.radians(20.0), 0.9, 0.7, 1.0, branch=-1,
                           coupler=(np.radians(30.0), np.radians(-40.0))).solve(angle("spherical"))
    for point, v in (("B", ref.B), ("C", ref.C), ("P", ref.P)):
        assert np.abs(np.array(_point(page, "spherical", point, f)) - v).max() < 1e-12
    reset(page, "hooke", {"alpha": 50.0})
    t3 = float(hooke_output(angle("hooke"), np.radians(50.0)))
    e3 = [np.cos(t3), np.cos(np.radians(50.0)) * np.sin(t3), -np.sin(np.radians(50.0)) * np.sin(t3)]
    assert np.abs(np.array(_point(page, "hooke", "e3", f)) - e3).max() < 1e-12
    for name, start in (("fourbar", FOURBAR), ("slidercrank", SLIDER), ("guidebar", GUIDE), ("spherical", SPHERE),
                        ("hooke", {"alpha": 30.0})):
        reset(page, name, start)


def test_spherical_drag_through_change_point_keeps_branch(page):
    """d from 57 to 20 degrees passes the change point a + b = c + d (d = 0.5 rad): C moves on
    smoothly on mech.spherical.SphericalFourBar's branch +1; at the change point itself the
    page says it does not solve it yet and keeps the last linkage."""
    from mech.spherical import SphericalFourBar

    reset(page, "spherical", SPHERE)
    to_frame(page, "spherical", 20)   # 60 degrees
    at = page.evaluate("() => document.querySelector('#spherical .mech-fig').mechLive.data.live.theta[20]")
    path = []
    for d in np.linspace(57.0, 20.0, 149):
        set_field(page, "spherical", "d", round(float(d), 6), "number")
        s = state(page, "spherical")
        assert s["branch"] == "branch +1" and "NaN" not in s["msg"] + s["out"]
        C = np.array(_point(page, "spherical", "C", 20))
        ref = SphericalFourBar(0.3, 0.9, 0.7, np.radians(round(float(d), 6)), branch=1,
                               coupler=(0.4, 0.6)).solve(at).C
        assert np.abs(C - ref).max() < 1e-12, (d, C, ref)
        path.append(C)
    steps = np.linalg.norm(np.diff(path, axis=0), axis=1)
    assert steps.max() < 5 * np.median(steps)
    set_field(page, "spherical", "d", float(np.degrees(0.5)), "number")   # a + b = c + d: a change point
    assert "not solved in the page yet" in state(page, "spherical")["msg"]
    reset(page, "spherical", SPHERE)
