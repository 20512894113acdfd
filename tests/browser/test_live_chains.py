"""Step-built live figures in headless Chromium: the planar six-bar, Jansen's leg and the
shaper, a spherical six-bar, the RSSR and the open chain (``_live_chains_page``). The page's
first read-out (JS kernels) is the build's (NumPy); every field changes the drawing (and the
coupler curve where the figure traces one); a dragged joint changes the linkage; the page's
poses after a change are the package's."""

import numpy as np
import pytest

import _live_chains_page
import _live_page

NAMES = ("watt", "jansen", "shaper", "sphsix", "rssr", "chain", "circles", "triad")


@pytest.fixture(scope="module")
def page(chromium, tmp_path_factory):
    folder = tmp_path_factory.mktemp("live_chains")
    _live_chains_page.write(folder)
    with _live_page.opened(chromium, folder) as tab:
        yield tab


STATE = """(name) => {
  const div = document.querySelector('#' + name + ' .mech-fig');
  return {svg: div.querySelector('svg').innerHTML,
          curve: [...div.querySelectorAll('.mf-path-all')].map((p) => p.getAttribute('d')).join('|'),
          out: div.querySelector('.mech-live-out').textContent, msg: div.querySelector('.mech-live-msg').textContent};
}"""


def test_first_readout_is_the_build_readout(page):
    got = page.evaluate("""() => [...document.querySelectorAll('.mech-fig')].map((div) => {
      const out = div.querySelector('.mech-live-out'), built = out.textContent;
      div.mechLive.update({});
      return [div.parentNode.id, built, out.textContent, div.querySelector('.mech-live-msg').textContent];
    })""")
    assert [g[0] for g in got] == list(NAMES)
    for name, built, live, msg in got:
        assert live == built and not msg, (name, built, live, msg)


def test_every_field_changes_the_drawing(page):
    """Each field moved by 3 % of its value (or its step range) redraws the linkage and its path."""
    for name in NAMES:
        keys = page.evaluate("(n) => [...document.querySelectorAll('#' + n + ' .mech-live input[type=number]')]"
                             ".map((i) => [i.dataset.k, +i.value])", name)
        assert keys, name
        for key, value in keys:
            before = page.evaluate(STATE, name)
            new = value * 1.03 if value else 0.02
            page.evaluate("""([n, k, v]) => { const i = document.querySelector(`#${n} .mech-live input[type=number][data-k="${k}"]`);
              i.value = String(v); i.dispatchEvent(new Event('input', {bubbles: true})); }""", [name, key, new])
            after = page.evaluate(STATE, name)
            assert after["svg"] != before["svg"] and "NaN" not in after["out"] + after["msg"], (name, key, after)
            if name not in ("chain", "circles"):
                assert after["curve"] != before["curve"], (name, key)
            page.evaluate("""([n, k, v]) => document.querySelector('#' + n + ' .mech-fig').mechLive.set({[k]: v})""",
                          [name, key, value])


def test_dragged_joint_and_branch_switch(page):
    for name, handle in (("watt", "G"), ("jansen", "E"), ("sphsix", "C")):
        before = page.evaluate(STATE, name)
        box = page.locator(f'#{name} circle.mf-handle[data-handle="{handle}"]').bounding_box()
        assert box is not None, (name, handle)
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + 6, y + 4, steps=4)
        page.mouse.up()
        after = page.evaluate(STATE, name)
        assert after["svg"] != before["svg"] and after["curve"] != before["curve"], (name, handle)
    before = page.evaluate(STATE, "watt")
    page.locator("#watt .mech-branch").click()
    assert page.evaluate(STATE, "watt")["svg"] != before["svg"]


def test_changed_poses_agree_with_the_package(page):
    from mech.planar import watt_six_bar
    from mech.planar.kinematics._linkage._records import _Step

    page.evaluate("() => document.querySelector('#watt .mech-fig').mechLive.set({L3: 26.0, L4: 18.0, b_G: -1, branch: 1})")
    f = 11
    theta = page.evaluate("(f) => document.querySelector('#watt .mech-fig').mechLive.data.live.theta[f]", f)
    G = page.evaluate("""(f) => { const d = document.querySelector('#watt .mech-fig').mechLive.data;
      const a = d.P[d.names.indexOf('G')]; return [a[2 * f] * d.grid, -a[2 * f + 1] * d.grid]; }""", f)
    lk = watt_six_bar()
    steps = []
    for s in lk._steps:           # the same linkage with EG = 26 (field L3)
        if s.kind == "rrr" and s.get("joint") == "G":
            data = dict(s.data, lengths=(26.0, s.get("lengths")[1]))
            s = _Step(s.kind, s.label, s.links, tuple(data.items()))
        steps.append(s)
    lk._steps = tuple(steps)
    want = complex(np.asarray(lk.solve(theta).points["G"]))
    assert abs(complex(*G) - want) < 1e-3 * 100       # the drawing's grid: 4 digits of the figure


def test_nothing_from_outside_and_no_errors(page):
    assert page.problems == []
