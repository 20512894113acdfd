"""The hand-written parts of the live figures' JS layer, under Node, against the package.

``spherical.js`` classify (the type a live spherical figure states) is compared with
``mech.spherical.classify`` (NumPy) on random arcs over (0, pi), arcs on change points and
arcs near the antipode boundary; the read-out that ``figures.live`` writes at build time is
the one ``live.js`` writes in the page (``tests/browser/test_live_figures.py`` checks that
in Chromium).
"""

import json
import subprocess

import numpy as np
import pytest

from derivations import _codegen, _node

pytestmark = pytest.mark.skipif(_node.node() is None, reason="node is not installed (make setup installs nodejs)")

SPHERICAL = _codegen.JS_DIR.parent / "mech" / "spherical.js"


def _node_json(script):
    done = subprocess.run([_node.node(), "--input-type=module", "-"], input=script, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _arcs():
    rng = np.random.default_rng(25)
    random = rng.uniform(0.02, np.pi - 0.02, (10_000, 4))
    # change points: a + b = c + d and friends, in degrees so that the sums are exact
    deg = rng.integers(5, 90, (400, 3)).astype(float)
    change = np.radians(np.c_[deg[:, 0], deg[:, 1], deg[:, 2], deg[:, 0] + deg[:, 1] - deg[:, 2]])
    change = change[(change > 0).all(axis=1) & (change < np.pi).all(axis=1)]
    isograms = np.radians(np.c_[deg[:, 0], deg[:, 1], deg[:, 0], deg[:, 1]])
    return np.vstack([random, change, isograms, np.pi - random[:500]])


def test_spherical_classify_agrees_with_the_package():
    from mech.spherical import classify

    arcs = _arcs()
    script = (f'import {{ classify }} from "{SPHERICAL.as_uri()}";\n'
              f"const arcs = {json.dumps(arcs.tolist())};\n"
              "process.stdout.write(JSON.stringify(arcs.map((x) => { try { const t = classify(...x); "
              "return [t.kind, t.changePoint, t.revolving.join('')]; } catch (e) { return [e.name]; } })));")
    got = _node_json(script)
    kinds = set()
    for x, js in zip(arcs, got):
        try:
            t = classify(*x)
        except ValueError:
            assert js == ["LinkageInputError"], (x, js)
            continue
        assert js == [t.kind, t.change_point, "".join(sorted(t.revolving))], (x, js, t)
        kinds.add(t.kind)
    assert kinds == {"crank-rocker", "rocker-crank", "double-crank", "double-rocker", "triple-rocker"}
    assert sum(js == ["LinkageInputError"] for js in got) > 0
