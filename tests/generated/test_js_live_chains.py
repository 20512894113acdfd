"""The page's solver of step-built linkages (book/_static/mech/live_chains.js, on the generated
JavaScript kernels) against the package's own solvers (NumPy) under Node: the book's planar
six-bars, shapers and Jansen's leg, the four spherical six-bars, the RSSR in both modes.
"""

import json
import subprocess

import numpy as np
import pytest

from derivations import _node

pytestmark = pytest.mark.skipif(_node.node() is None, reason="node is not installed (make setup installs nodejs)")


def _module():
    from pathlib import Path
    return (Path(__file__).resolve().parents[2] / "book" / "_static" / "mech" / "live_chains.js").as_uri()


def _node_json(script):
    done = subprocess.run([_node.node(), "--input-type=module", "-"], input=script, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


THETA = np.linspace(-np.pi, np.pi, 97)


def _planar():
    from mech.planar import jansen_linkage, shaper_stephenson, shaper_watt, stephenson_six_bar, watt_six_bar

    return {"watt": watt_six_bar(), "stephenson": stephenson_six_bar(), "shaper": shaper_watt(),
            "shaper2": shaper_stephenson(), "jansen": jansen_linkage()}


def _spherical():
    from mech.spherical import stephenson1, stephenson2, watt1, watt2

    a, b, c, d = 0.3, 0.9, 0.7, 1.0
    return {"S1": stephenson1(a, b, c, d, E=(0.25, 0.8), F=(0.35, -1.2), arcs=(0.8, 0.7), coupler=(0.4, 0.6),
                              branches=(-1, 1)),
            "S2": stephenson2(a, b, c, d, E=(0.5, 0.6), F=(1.0, 0.8), arcs=(0.7, 0.6), coupler=(0.35, 0.5)),
            "W1": watt1(a, b, c, d, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4)),
            "W2": watt2(a, b, c, d, E=(0.4, 0.6), F=(1.4, 0.5), arcs=(0.6, 0.5), coupler=(0.3, 0.5))}


def _state(spec, angular):
    return {"branch": 1, **{k: (np.radians(v) if angular else v) for k, _, v, *_ in spec["fields"]}}


def test_planar_linkages_match_the_package():
    from figures.live_chains import linkage

    cases = {}
    for name, lk in _planar().items():
        try:
            spec = linkage(lk, [0.0])
        except ValueError:          # a step the page does not solve: not in the book's figures
            continue
        cases[name] = (spec, _state(spec, False))
    assert {"watt", "stephenson", "shaper", "jansen"} <= set(cases)
    script = (f'import {{ solvePlanar }} from "{_module()}";\n'
              f"const cases = {json.dumps({k: v for k, v in cases.items()})}, theta = {json.dumps(THETA.tolist())};\n"
              "const out = {};\n"
              "for (const [name, [spec, state]] of Object.entries(cases)) {\n"
              "  const s = solvePlanar(spec, state, theta);\n"
              "  out[name] = {ok: Array.from(s.ok), P: Object.fromEntries(Object.entries(s.P).map(([k, [x, y]]) =>"
              " [k, [Array.from(x), Array.from(y)]]))};\n"
              "}\nprocess.stdout.write(JSON.stringify(out));")
    got = _node_json(script)
    for name in cases:
        lk = _planar()[name]
        ref = lk.solve(THETA)
        size = max(abs(complex(s.get("at"))) for s in lk._steps if s.kind == "ground") + 100.0
        ok = np.array(got[name]["ok"], dtype=bool)
        for point, (x, y) in got[name]["P"].items():
            want = np.asarray(ref.points[point]) + np.zeros(THETA.shape)
            assert np.array_equal(ok, np.isfinite(want) | ~ok), (name, point)
            z = np.array(x, dtype=float) + 1j * np.array(y, dtype=float)
            assert np.max(np.abs(z[ok] - want[ok])) < 1e-12 * size, (name, point)
        assert ok.all() == bool(np.isfinite(np.asarray(ref.points[list(ref.points)[-1]])).all()), name


def test_spherical_six_bars_match_the_package():
    from figures.live_chains import spherical_linkage

    cases = {name: (spec := spherical_linkage(lk, [0.0]), _state(spec, True)) for name, lk in _spherical().items()}
    script = (f'import {{ solveSpherical }} from "{_module()}";\n'
              f"const cases = {json.dumps(cases)}, theta = {json.dumps(THETA.tolist())};\n"
              "const out = {};\n"
              "for (const [name, [spec, state]] of Object.entries(cases)) {\n"
              "  const s = solveSpherical(spec, state, theta);\n"
              "  out[name] = {ok: Array.from(s.ok), P: s.P};\n"
              "}\nprocess.stdout.write(JSON.stringify(out));")
    got = _node_json(script)
    for name, lk in _spherical().items():
        ref = lk.solve(THETA)
        ok = np.array(got[name]["ok"], dtype=bool)
        assert np.array_equal(ok, ref.assembled), name
        for point, pts in got[name]["P"].items():
            want = np.asarray(ref.points[point]) + np.zeros(THETA.shape + (3,))
            assert np.max(np.abs(np.array(pts, dtype=float)[ok] - want[ok])) < 1e-12, (name, point)


def test_rssr_both_modes_match_the_package():
    from mech.spatial import RSSR

    dims = dict(l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=np.radians(60.0))
    script = (f'import {{ solveRSSR }} from "{_module()}";\n'
              f"const v = {json.dumps(dims)}, theta = {json.dumps(THETA.tolist())};\n"
              "process.stdout.write(JSON.stringify([1, -1].map((b) => theta.map((t) => solveRSSR(v, b, t)))));")
    got = _node_json(script)
    for k, branch in enumerate((1, -1)):
        ref = RSSR(**dims, branch=branch).solve(THETA)
        assert np.max(np.abs(np.array([g[0] for g in got[k]]) - ref.B)) < 1e-12 * 4
        assert np.max(np.abs(np.array([g[1] for g in got[k]]) - ref.C)) < 1e-12 * 4


def test_stephenson3_triad_matches_the_package():
    """The page's march of the Stephenson-3 (live_triad.js) puts C, G, H where
    SphericalStephenson3.solve does, on both sides of the assembled pose."""
    from figures.live_chains import stephenson3 as describe
    from mech.spherical import stephenson3

    lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6), coupler=(0.3, 0.4), mu=0.8)
    run = np.linspace(-0.5, 1.0, 31)
    spec = describe(lk, run)
    triad = _module().replace("live_chains.js", "live_triad.js")
    script = (f'import {{ stephenson3 }} from "{triad}";\n'
              f"const spec = {json.dumps(spec)}, names = ['C', 'G', 'H', 'P'];\n"
              "const d = {names, P: names.map(() => new Array(3 * spec.theta.length).fill(0)), step: 1, c0: [0, 0, 0],"
              " trace: [], sphere: true};\n"
              "const fig = stephenson3(null, d, {}, spec);\nfig.compute();\n"
              "process.stdout.write(JSON.stringify({P: d.P, out: fig.readout()}));")
    got = _node_json(script)
    ref = lk.solve(run)
    assert got["out"] == spec["first"]
    for k, name in enumerate("CGHP"):
        assert np.max(np.abs(np.array(got["P"][k], dtype=float).reshape(-1, 3) - ref.points[name])) < 1e-12, name
