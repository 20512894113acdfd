"""The live design pages' hand-written JavaScript against the package, under Node (issue 25).

``book/_static/mech/burmester.js`` finds the Burmester dyads of five poses by its own route
(Gram-Schmidt null space, Aberth's iteration for the quartic) around the generated kernel
``crank_design_row``; it must find the dyads of `mech.planar.synthesis.burmester`, the same
number and the same points, on random pose sets at scales 1e-3 to 1e3. Its circle-point
curve of four poses is checked by its defining property (each point's four positions on a
circle), ``design.js``'s four-bars against `guidance_fourbars`, and ``fgdesign.js`` against
`precision_pairs`.
"""

import json
import subprocess

import numpy as np
import pytest

from derivations import _node

pytestmark = pytest.mark.skipif(_node.node() is None, reason="node is not installed (make setup installs nodejs)")



def _mech_js():
    from pathlib import Path
    return Path(__file__).resolve().parents[2] / "book" / "_static" / "mech"


def _node_json(script):
    done = subprocess.run([_node.node(), "--input-type=module", "-"], input=script, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _sets(count, seed):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(count):
        scale = 10.0 ** rng.uniform(-3, 3)
        theta = rng.uniform(-1.2, 1.2, 5)
        d = (rng.uniform(-1, 1, 5) + 1j * rng.uniform(-1, 1, 5)) * scale
        out.append((theta, d))
    return out


def test_burmester_js_finds_the_dyads_of_burmester():
    from mech.planar.synthesis import burmester

    sets = _sets(200, 11)
    payload = json.dumps([[t.tolist(), [[z.real, z.imag] for z in d]] for t, d in sets])
    script = (f'import {{ burmester }} from "{(_mech_js() / "burmester.js").as_uri()}";\n'
              f"const sets = {payload};\n"
              "process.stdout.write(JSON.stringify(sets.map(([t, d]) => burmester(t, d))));")
    found = _node_json(script)
    worst, total, counts = 0.0, 0, {}
    for (theta, d), got in zip(sets, found):
        want = burmester(theta, d)
        size = np.max(np.abs(d - d.mean()))
        assert len(got["dyads"]) == len(want.dyads)
        assert got["nComplex"] == want.n_complex and got["nInfinite"] == want.n_infinite
        counts[len(want.dyads)] = counts.get(len(want.dyads), 0) + 1
        for w, g in zip(want.dyads, got["dyads"]):
            far = max(abs(w.circle_point), abs(w.centre_point - d.mean())) / size
            err = max(abs(w.circle_point - complex(*g["circlePoint"])), abs(w.centre_point - complex(*g["centrePoint"])))
            # to 1e-9 of the pose set's size; a dyad farther than 100 sizes (near a slider)
            # is conditioned by its distance, so the bound grows with it
            worst = max(worst, err / (size * max(1.0, far / 100.0)))
            total += 1
    assert set(counts) >= {0, 2, 4}
    assert total > 200
    assert worst <= 1e-9


def test_circle_point_curve_js_meets_the_four_poses():
    sets = _sets(20, 5)
    payload = json.dumps([[t[:4].tolist(), [[z.real, z.imag] for z in d[:4]]] for t, d in sets])
    script = (f'import {{ circlePointCurve }} from "{(_mech_js() / "burmester.js").as_uri()}";\n'
              f"const sets = {payload};\n"
              "process.stdout.write(JSON.stringify(sets.map(([t, d]) => circlePointCurve(t, d, { samples: 90 }))));")
    curves = _node_json(script)
    points = 0
    for (theta, d), curve in zip(sets, curves):
        size = np.max(np.abs(d[:4] - d[:4].mean()))
        for pair_z, pair_a, pair_ok in zip(curve["circlePoint"], curve["centrePoint"], curve["valid"]):
            for z, A, ok in zip(pair_z, pair_a, pair_ok):
                if not ok:
                    continue
                # with mpmath-free plain complex arithmetic in a different form: positions
                # of the body point in the four poses, their distances from the centre
                r = np.abs(np.exp(1j * theta[:4]) * complex(*z) + d[:4] - complex(*A))
                assert np.ptp(r) <= 1e-7 * max(size, r.max())
                points += 1
    assert points > 20 * 90


def test_design_js_four_bars_are_those_of_guidance_fourbars():
    from mech.planar.synthesis import guidance_fourbars

    P = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
    deg = [0.0, 8.88, 22.1, 63.68, -3.0]
    state = {"poses": [[t, z.real, z.imag] for t, z in zip(deg, P)], "n": 5, "pick": 0, "t": 0.0,
             "pivots": [[0, 0], [1, 1]], "choose": [0.2, 0.7]}
    script = (f'import {{ solveState }} from "{(_mech_js() / "design.js").as_uri()}";\n'
              f"const sol = solveState({json.dumps(state)});\n"
              "process.stdout.write(JSON.stringify(sol.designs.map((d) => [d.input, d.output, d.lengths, d.kind, "
              "d.passes, d.defects])));")
    got = _node_json(script)
    want = guidance_fourbars(np.radians(deg), P)
    dyads = want.dyads
    table = {(dyads.index(c.input_dyad) + 1, dyads.index(c.output_dyad) + 1): c for c in want.candidates}
    assert len(got) == len(table) == 12
    for i, o, lengths, kind, passes, defects in got:
        c = table[(i, o)]
        L = c.linkage
        assert np.allclose(lengths, [L.a, L.b, L.c, L.d], rtol=1e-9)
        assert kind == c.kind
        assert passes == c.passes
        # no defect exactly when the package finds the poses met in order on one branch
        assert (not any(defects.values())) == c.in_order
    assert sum(p for *_, p, _ in got) == len(want.passing) >= 1


def test_fgdesign_js_is_precision_pairs():
    from mech.planar.synthesis import FunctionMap, precision_pairs

    rng = np.random.default_rng(3)
    trials = []
    for _ in range(30):
        xs = np.sort(rng.uniform(1.0, 10.0, 3))
        trials.append({"x": xs.tolist(), "theta0": float(rng.uniform(0, 180)), "psi0": float(rng.uniform(0, 360)),
                       "thetaRange": 100.0, "psiRange": float(rng.choice([-60.0, 60.0])), "d": 100.0, "at": 5.0})
    script = (f'import {{ design }} from "{(_mech_js() / "fgdesign.js").as_uri()}";\n'
              f"const trials = {json.dumps(trials)};\n"
              "process.stdout.write(JSON.stringify(trials.map((s) => { const d = design(s); "
              "return d.problem ? null : [d.lengths, d.branch, d.covers && d.monotone]; })));")
    got = _node_json(script)
    compared = 0
    for state, g in zip(trials, got):
        task = FunctionMap(np.log10, (1.0, 10.0), np.radians(state["thetaRange"]), np.radians(state["psiRange"]))
        try:
            want, = precision_pairs(*task.rotations(np.array(state["x"])), theta0=np.radians(state["theta0"]),
                                    psi0=np.radians(state["psi0"]), d=state["d"], target=task)
        except ValueError:
            assert g is None
            continue
        assert g is not None
        assert np.allclose(g[0], want.lengths, rtol=1e-9)
        assert g[1] == want.branch
        assert g[2] == want.covers_range     # assembled over the range, output never turning back
        compared += 1
    assert compared >= 10
