"""The JavaScript backend agrees with the NumPy backend, run under Node.

Every function of every generated ES module (``book/_static/kernels/*.js``) is evaluated
by Node on 10^4 random points of the domain its notebook samples, and on adversarial
points (the domain's corners and the points where an argument is 0 or where two are
equal, the change points of a linkage); the NumPy function of the same name is the
reference. They evaluate the same expression tree, so they differ only where the two
libraries' sin, cos, atan2, pow round differently (within an ulp each): the test asks for
the same NaN pattern everywhere and 1e-13 relative agreement (of the output's largest
magnitude) wherever the point is well conditioned.

The hand-written layers ``book/_static/mech/planar.js`` and ``spherical.js`` are compared
with ``mech.planar.FourBar`` and ``mech.spherical.SphericalFourBar``
on random, change-point, kite and dead-point linkages at scales 1e-200 to 1e200.
"""

import importlib
import json
import subprocess

import numpy as np
import pytest

from derivations import _codegen, _node

pytestmark = pytest.mark.skipif(_node.node() is None, reason="node is not installed (make setup installs nodejs)")

KERNELS = sorted(_codegen.JS_DIR.glob("*.js"))
LAYER = _codegen.JS_DIR.parent / "mech" / "planar.js"
SPHERICAL = _codegen.JS_DIR.parent / "mech" / "spherical.js"
N = 10_000


def _node_json(script):
    """Run an ES-module script under Node; its stdout as JSON."""
    done = subprocess.run([_node.node(), "--input-type=module", "-"], input=script, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def signatures():
    imports = "\n".join(f'import * as m{k} from "{p.as_uri()}";' for k, p in enumerate(KERNELS))
    table = ", ".join(f'"{p.stem}": m{k}.SIGNATURES' for k, p in enumerate(KERNELS))
    return _node_json(f"{imports}\nprocess.stdout.write(JSON.stringify({{{table}}}));")


def _points(sig, rng):
    """N random points of the domain and the adversarial ones, one array per argument."""
    names = sig["args"]
    lows = np.array([sig["domain"].get(n, (-2.0, 2.0))[0] for n in names])
    highs = np.array([sig["domain"].get(n, (-2.0, 2.0))[1] for n in names])
    cols = [rng.uniform(lo, hi, N) for lo, hi in zip(lows, highs)]
    extra = []
    base = (lows + highs) / 2
    for k in range(len(names)):
        for v in (lows[k], highs[k], 0.0):
            if lows[k] <= v <= highs[k]:
                row = base.copy()
                row[k] = v
                extra.append(row)
        for j in range(k):        # two arguments equal: a rhombus, a kite, a change point
            lo, hi = max(lows[k], lows[j]), min(highs[k], highs[j])
            if lo <= hi:
                row = rng.uniform(lows, highs)
                row[k] = row[j] = rng.uniform(lo, hi)
                extra.append(row)
    extra = np.array(extra).reshape(-1, len(names))
    return [np.concatenate([c, extra[:, k]]) for k, c in enumerate(cols)]


def _numpy_outputs(stem, name, sig, args):
    f = getattr(importlib.import_module(f"mech._generated.{stem}"), name)
    with np.errstate(all="ignore"):
        got = f(*args)
    got = [got] if not isinstance(got, tuple) else list(got)
    n = args[0].shape[0] if args else 1
    parts = []
    for g in got:
        g = np.broadcast_to(np.asarray(g), (n,))
        if np.iscomplexobj(g):
            parts += [g.real, g.imag]
        else:
            parts.append(g.astype(float))
    assert len(parts) == len(sig["outputs"])
    return parts


def _conditioning(stem, name, args):
    """Per point, a bound on how much the inputs' rounding moves the outputs (relative):
    the largest relative change of any output under a relative nudge of 1e-12 of every
    argument, divided by 1e-12 (a cheap condition number, from the NumPy function)."""
    module = importlib.import_module(f"mech._generated.{stem}")
    f = getattr(module, name)
    rng = np.random.default_rng(7)
    with np.errstate(all="ignore"):
        ref = f(*args)
        ref = [ref] if not isinstance(ref, tuple) else list(ref)
        worst = np.zeros(args[0].shape[0] if args else 1)
        for _ in range(2):
            nudged = [a * (1 + 1e-12 * rng.choice((-1.0, 1.0), a.shape)) for a in args]
            out = f(*nudged)
            out = [out] if not isinstance(out, tuple) else list(out)
            for r, o in zip(ref, out):
                r, o = np.broadcast_to(np.asarray(r), worst.shape), np.broadcast_to(np.asarray(o), worst.shape)
                scale = np.max(np.abs(r[np.isfinite(r)])) if np.any(np.isfinite(r)) else 1.0
                worst = np.maximum(worst, np.abs(o - r) / max(scale, 1e-300) / 1e-12)
    return np.where(np.isfinite(worst), worst, np.inf)


def test_every_kernel_agrees_with_numpy(signatures):
    assert KERNELS, "no JavaScript kernels: run `python -m derivations`"
    rng = np.random.default_rng(20261129)
    calls, cases = [], []
    for path in KERNELS:
        for name, sig in signatures[path.stem].items():
            args = _points(sig, rng)
            calls.append((path, name, args, len(sig["outputs"])))
            cases.append((path.stem, name, sig, args))
    results = _node.evaluate(calls)
    report, loose = [], 0
    for (stem, name, sig, args), js in zip(cases, results):
        ref = _numpy_outputs(stem, name, sig, args)
        assert len(args) == 0 or args[0].shape[0] >= N
        well = None
        for out_name, r, j in zip(sig["outputs"], ref, js):
            assert np.array_equal(np.isnan(r), np.isnan(j)), (
                f"{stem}.{name}.{out_name}: NaN at different points, e.g. "
                f"{[float(a[np.argmax(np.isnan(r) != np.isnan(j))]) for a in args]}")
            finite = np.isfinite(r)
            assert np.array_equal(r[~finite & ~np.isnan(r)], j[~finite & ~np.isnan(r)])
            scale = np.max(np.abs(r[finite])) if finite.any() else 1.0
            with np.errstate(invalid="ignore"):     # inf - inf where both are infinite
                diff = np.abs(r - j)
            err = diff[finite] / max(scale, 1e-300)
            if err.size and err.max() > 1e-13:
                if well is None:
                    well = _conditioning(stem, name, args) <= 1e3
                beyond = (diff / max(scale, 1e-300) > 1e-13) & finite
                loose += int(np.sum(beyond))
                bad = beyond & well
                assert not bad.any(), (
                    f"{stem}.{name}.{out_name}: {diff[bad].max():.3g} off at a well conditioned "
                    f"point {[float(a[np.argmax(bad)]) for a in args]}")
                err = (diff / max(scale, 1e-300))[finite & ~beyond]
            report.append(float(err.max()) if err.size else 0.0)
    points = sum(len(args[0]) for *_, args in cases if args)
    print(f"\n{len(cases)} functions, {points} points: {loose} output values beyond 1e-13 (all at "
          f"ill-conditioned points); the largest relative difference of the others {max(report):.2g}")
    assert len(report) > 0


# --- the hand-written layers against the Python package ----------------------------------

def _near_limit_bound(delta):
    """Allowed relative difference of a pose a relative distance delta from a dead point or
    limit position. The inputs' rounding moves positions by about eps / sqrt(delta) and
    rates by up to eps / delta**1.5 there; beyond 1e-3 the bound is 1e-13 (as in
    tests/planar/kinematics/test_fourbar_scale.py), below 1e-10 the values are mostly rounding and
    only the masks and NaN are compared (as there below 1e-3)."""
    with np.errstate(divide="ignore"):
        near = np.maximum(1e-13, 1e-15 / np.maximum(delta, 1e-300) ** 1.5)
    return np.where(delta >= 1e-3, 1e-13, np.where(delta >= 1e-10, near, np.inf))


def _linkages(rng, count):
    """Random linkages and the hard ones: change points, kites, parallelograms, dead points."""
    out = []
    for _ in range(count):
        a, b, c, d = rng.uniform(0.2, 1.0, 4)
        if max(a, b, c, d) >= (a + b + c + d) - max(a, b, c, d):
            continue
        out.append((a, b, c, d))
    out += [(0.3, 0.9, 0.8, 0.4), (0.5, 1.0, 0.5, 1.0), (0.5, 1.0, 1.0, 0.5), (0.6, 0.6, 0.6, 0.6),
            (0.25, 0.75, 1.0, 0.5), (0.4, 0.9, 0.7, 0.2), (10, 40, 30, 35), (30, 70, 60, 80)]
    return out


def _thetas(rng, a, b, c, d):
    th = list(rng.uniform(-7, 7, 40)) + [0.0, np.pi, -np.pi, np.pi / 2]
    # the dead points: |BD| = b + c and |b - c| (where in reach)
    for k in (b + c, abs(b - c)):
        cos_t = (a * a + d * d - k * k) / (2 * a * d)
        if -1 <= cos_t <= 1:
            t = float(np.arccos(cos_t))
            th += [t, -t, np.nextafter(t, 0), np.nextafter(t, 4)]
    return th


def test_fourbar_layer_agrees_with_python():
    from mech.planar import FourBar

    rng = np.random.default_rng(5)
    cases = []
    for a, b, c, d in _linkages(rng, 30):
        for scale in (1e-200, 1e-7, 1.0, 3e5, 1e200):
            for branch in (1, -1):
                cases.append({"lengths": [a * scale, b * scale, c * scale, d * scale], "branch": branch,
                              "coupler": [0.3 * scale, -0.2 * scale], "theta": _thetas(rng, a, b, c, d)})
    script = (f'import {{ FourBar }} from "{LAYER.as_uri()}";\n'
              f"const cases = {json.dumps(cases)};\n"
              "const out = cases.map((k) => { const f = new FourBar(...k.lengths, {branch: k.branch, coupler: k.coupler});\n"
              "  const r = f.solve(k.theta, {order: 2, omega: 1.5, alpha: -0.5});\n"
              "  const o = {}; for (const key of Object.keys(r)) o[key] = Array.from(r[key], (v) => typeof v === 'number' && !Number.isFinite(v) ? String(v) : v);\n"
              "  return o; });\n"
              "process.stdout.write(JSON.stringify(out));")
    results = _node_json(script)
    checked = 0
    for case, js in zip(cases, results):
        fb = FourBar(*case["lengths"], branch=case["branch"], coupler=case["coupler"])
        with np.errstate(all="ignore"):
            pose = fb.solve(np.array(case["theta"]), order=2, omega=1.5, alpha=-0.5)
        where = f"FourBar{tuple(case['lengths'])}, branch {case['branch']}"
        assert list(pose.valid) == js["valid"], f"{where}: validity differs"
        size = max(case["lengths"])
        # relative distance delta of each pose from a dead point (|BD| = b + c or |b - c|):
        # the rounding of the inputs moves a pose by about eps / delta there, so poses with
        # delta < 1e-3 are held to that bound and the others to 1e-13 (tests/planar)
        a, b, c, d = (x / size for x in case["lengths"])
        theta = np.array(case["theta"])
        k = np.sqrt((a - d) ** 2 + 4 * a * d * np.sin(theta / 2) ** 2)
        delta = np.minimum(np.abs(k - (b + c)), np.abs(k - abs(b - c))) / (a + b + c + d)
        tol = _near_limit_bound(delta)
        for name in ("B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP"):
            want = np.asarray(getattr(pose, name))
            got = np.array(js[name + "x"], dtype=float) + 1j * np.array(js[name + "y"], dtype=float)
            assert np.array_equal(np.isnan(want), np.isnan(got)), f"{where}: {name} NaN differs"
            ok = np.isfinite(want)
            err = np.abs(want - got) / (size + np.abs(want))
            assert np.all(err[ok] <= tol[ok]), \
                f"{where}: {name} differs by {np.max(err[ok] / tol[ok]):.3g} times the bound"
        # the same branch: C on the same side of B->D wherever the triangle BCD is not flat
        def side_of(B, C):
            B, C = np.asarray(B) / size, np.asarray(C) / size
            return np.sign(np.imag((C - B) * np.conj(d - B)))

        side = side_of(pose.B, pose.C)
        js_side = side_of(np.array(js["Bx"], dtype=float) + 1j * np.array(js["By"], dtype=float),
                          np.array(js["Cx"], dtype=float) + 1j * np.array(js["Cy"], dtype=float))
        flat = delta < 1e-9
        assert np.array_equal(side[~flat & pose.valid], js_side[~flat & pose.valid]), f"{where}: branch differs"
        for name in ("omega_coupler", "omega_output", "alpha_coupler", "alpha_output"):
            want = np.asarray(getattr(pose, name))
            got = np.array(js[name], dtype=float)
            assert np.array_equal(np.isnan(want), np.isnan(got)), f"{where}: {name} NaN differs"
            ok = np.isfinite(want)
            err = np.abs(want - got) / (1 + np.abs(want))
            assert np.all(err[ok] <= tol[ok]), \
                f"{where}: {name} differs by {np.max(err[ok] / tol[ok]):.3g} times the bound"
        checked += len(theta)
    assert checked >= 10_000


def test_spherical_layer_agrees_with_python():
    from mech.spherical._fourbar import SphericalFourBar

    rng = np.random.default_rng(11)
    cases = []
    while len(cases) < 60:
        a, b, c, d = (float(x) for x in rng.uniform(0.1, 3.0, 4))
        try:
            linkage = SphericalFourBar(a, b, c, d, coupler=(0.4, 0.7))
        except ValueError:
            continue
        if linkage.change_point:
            continue
        theta = list(rng.uniform(-7, 7, 200)) + [0.0, np.pi]
        for lo, hi in linkage.assembly_range().intervals:       # the limit positions
            theta += [lo, hi, np.nextafter(lo, 9), np.nextafter(hi, -9)]
        cases.append({"arcs": [a, b, c, d], "branch": int(rng.choice((-1, 1))), "theta": theta})
    script = (f'import {{ SphericalFourBar }} from "{SPHERICAL.as_uri()}";\n'
              f"const cases = {json.dumps(cases)};\n"
              "const fix = (v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v);\n"
              "const out = cases.map((k) => { const f = new SphericalFourBar(...k.arcs, {branch: k.branch, coupler: [0.4, 0.7]});\n"
              "  const r = f.solve(k.theta, {order: 2, omega: 2.0, alpha: -3.0});\n"
              "  const o = {}; for (const key of Object.keys(r)) o[key] = Array.from(r[key], (v) => Array.isArray(v) ? v.map(fix) : fix(v));\n"
              "  return o; });\n"
              "process.stdout.write(JSON.stringify(out));")
    results = _node_json(script)
    checked = unsure = 0
    for case, js in zip(cases, results):
        a, b, c, d = case["arcs"]
        linkage = SphericalFourBar(a, b, c, d, branch=case["branch"], coupler=(0.4, 0.7))
        with np.errstate(all="ignore"):
            pose = linkage.solve(np.array(case["theta"]), order=2, omega=2.0, alpha=-3.0)
        where = f"SphericalFourBar{tuple(case['arcs'])}, branch {case['branch']}"
        theta = np.array(case["theta"])
        g = np.arccos(np.clip(np.cos(a) * np.cos(d) + np.sin(a) * np.sin(d) * np.cos(theta), -1, 1))
        delta = np.minimum(np.abs(g - abs(b - c)), np.abs(g - min(b + c, 2 * np.pi - b - c)))
        # on a limit position itself (within 2**-40) whether the pose exists is decided by
        # the last bit of sin and cos, which the two libraries round differently (the Python
        # package has no dead-point tolerance for the sphere): there the masks may differ,
        # and the values are rounding (only the count of such points is bounded)
        ends = linkage.assembly_range().intervals.ravel()
        on_limit = (np.min(np.abs(theta[:, None] - ends[None, :]), axis=1) <= 2.0**-40 if ends.size
                    else np.zeros(len(theta), dtype=bool))
        valid = np.array(js["valid"], dtype=bool)
        assert np.array_equal(pose.valid[~on_limit], valid[~on_limit]), f"{where}: validity differs"
        unsure += int(np.sum(pose.valid[on_limit] != valid[on_limit]))
        agree = ~on_limit
        tol = _near_limit_bound(delta)
        for name in ("B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP", "w_coupler", "w_output",
                     "dw_coupler", "dw_output", "psi", "omega_output", "alpha_output"):
            want = np.asarray(getattr(pose, name), dtype=float)[agree]
            got = np.array(js[name], dtype=float)[agree]
            assert np.array_equal(np.isnan(want), np.isnan(got)), f"{where}: {name} NaN differs"
            err = np.abs(want - got) / (1 + np.abs(want))
            err = err if err.ndim == 1 else err.max(axis=1)
            ok = np.isfinite(err) & True
            tol_here = tol[agree]
            if name == "psi":         # an angle: the same up to a turn at +-pi
                err = np.abs(np.angle(np.exp(1j * (want - got))))
            assert np.all(err[ok] <= tol_here[ok]), \
                f"{where}: {name} differs by {np.max(err[ok] / tol_here[ok]):.3g} times the bound"
        checked += len(theta)
    assert checked >= 10_000
    assert unsure <= 0.01 * checked


def test_slider_crank_layer_agrees_with_python():
    from mech.planar import SliderCrank

    rng = np.random.default_rng(13)
    cases = []
    while len(cases) < 100:
        a, b = rng.uniform(0.2, 1.0, 2)
        e = float(rng.uniform(-0.8, 0.8))
        if b < abs(e) - a:
            continue
        theta = list(rng.uniform(-7, 7, 100)) + [0.0, np.pi / 2, -np.pi / 2]
        for s in (b, -b):                          # the dead points a sin(theta) - e = +-b
            if abs((s + e) / a) <= 1:
                t = float(np.arcsin((s + e) / a))
                theta += [t, np.pi - t, np.nextafter(t, 9), np.nextafter(t, -9)]
        scale = float(rng.choice([1e-200, 1e-3, 1.0, 7e4, 1e200]))
        cases.append({"lengths": [a * scale, b * scale, e * scale], "branch": int(rng.choice((-1, 1))),
                      "theta": theta, "delta": [float(abs(abs(a * np.sin(t) - e) - b) / (a + b + abs(e)))
                                                 for t in theta]})
    script = (f'import {{ SliderCrank }} from "{LAYER.as_uri()}";\n'
              f"const cases = {json.dumps(cases)};\n"
              "const fix = (v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v);\n"
              "const out = cases.map((k) => { const f = new SliderCrank(...k.lengths, {branch: k.branch});\n"
              "  const r = f.solve(k.theta, {order: 2, omega: 1.5, alpha: 0.7});\n"
              "  const o = {}; for (const key of Object.keys(r)) o[key] = Array.from(r[key], fix);\n"
              "  return o; });\n"
              "process.stdout.write(JSON.stringify(out));")
    results = _node_json(script)
    checked = 0
    for case, js in zip(cases, results):
        linkage = SliderCrank(*case["lengths"], branch=case["branch"])
        with np.errstate(all="ignore"):
            pose = linkage.solve(np.array(case["theta"]), order=2, omega=1.5, alpha=0.7)
        where = f"SliderCrank{tuple(case['lengths'])}, branch {case['branch']}"
        assert list(pose.valid) == js["valid"], f"{where}: validity differs"
        assert list(pose.assembled) == js["assembled"], f"{where}: assembled differs"
        size = max(abs(x) for x in case["lengths"])
        delta = np.array(case["delta"])
        tol = _near_limit_bound(delta)
        for name, linear in (("x", 1), ("phi", 0), ("B", 1), ("C", 1), ("omega_coupler", 0), ("v", 1),
                             ("vB", 1), ("alpha_coupler", 0), ("acc", 1), ("aB", 1)):
            want = np.asarray(getattr(pose, name))
            if np.iscomplexobj(want):
                got = np.array(js[name + "x"], dtype=float) + 1j * np.array(js[name + "y"], dtype=float)
            else:
                got = np.array(js[name], dtype=float)
            assert np.array_equal(np.isnan(want), np.isnan(got)), f"{where}: {name} NaN differs"
            unit = size if linear else 1.0
            err = np.abs(want - got) / (unit + np.abs(want))
            ok = np.isfinite(err)
            assert np.all(err[ok] <= tol[ok]), f"{where}: {name} differs by {np.max(err[ok] / tol[ok]):.3g} times the bound"
        checked += len(case["theta"])
    assert checked >= 10_000


def test_grashof_transmission_and_limit_positions_agree_with_python():
    from mech.planar import grashof
    from mech.planar.forces._transmission import min_transmission_angle, transmission_angle

    rng = np.random.default_rng(17)
    lengths = [[float(v) for v in x] for x in rng.uniform(0.1, 1.0, (600, 4)) if 2 * max(x) < sum(x)]
    lengths += [[20.0, 50.0, 40.0, 10.0], [2.0, 3.0, 2.0, 3.0], [10.0, 40.0, 30.0, 35.0], [1.0, 2.0, 2.0, 1.0]]
    lengths += [[x * s for x in (0.3, 0.9, 0.8, 0.4)] for s in (1e-200, 1e-9, 1e9, 1e200)]
    theta = [float(t) for t in np.linspace(-4, 4, 9)]
    script = (f'import {{ grashof, transmissionAngle, minTransmissionAngle, limitPositions }} from "{LAYER.as_uri()}";\n'
              f"const cases = {json.dumps(lengths)};\n"
              "const fix = (v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v);\n"
              "const limits = (k, branch) => { try { return limitPositions(...k, {branch}); } catch (e) { return e.message; } };\n"
              f"const out = cases.map((k) => [grashof(...k), Array.from(transmissionAngle(...k, {theta}), fix),\n"
              "  minTransmissionAngle(...k), limits(k, 1), limits(k, -1)]);\n"
              "process.stdout.write(JSON.stringify(out));")
    results = _node_json(script)
    from mech.planar.structure._limit_positions import limit_positions

    for k, (g, gamma, gmin, *limits) in zip(lengths, results):
        for branch, got in zip((1, -1), limits):
            try:
                want = limit_positions(*k, branch=branch)
            except ValueError as exc:      # the same refusal (JavaScript prints 20 for 20.0)
                assert isinstance(got, str) and got.split(":")[0] == str(exc).split(":")[0], k
                continue
            for name, key in (("theta_extended", "thetaExtended"), ("theta_folded", "thetaFolded"),
                              ("psi_extended", "psiExtended"), ("psi_folded", "psiFolded"), ("swing", "swing"),
                              ("extreme_angle", "extremeAngle"), ("time_ratio", "timeRatio")):
                assert abs(getattr(want, name) - got[key]) <= 1e-13 * (1 + abs(getattr(want, name))), (k, name)
        want = grashof(*k)
        assert (g["grashof"], g["changePoint"], sorted(g["revolving"]), g["kind"], g["shortest"], g["longest"]) == (
            want.grashof, want.change_point, sorted(want.revolving), want.kind, want.shortest, want.longest), k
        assert g["margin"] == want.margin, k
        with np.errstate(all="ignore"):
            ref = transmission_angle(*k, theta)
        got = np.array(gamma, dtype=float)
        assert np.array_equal(np.isnan(ref), np.isnan(got)), k
        ok = ~np.isnan(ref)
        assert np.all(np.abs(ref[ok] - got[ok]) <= 1e-13 * (1 + np.abs(ref[ok]))), k
        ref_min = min_transmission_angle(*k)
        assert abs(ref_min[0] - gmin[0]) <= 1e-13 and ref_min[1] == pytest.approx(gmin[1], rel=1e-13, abs=1e-13), k


def test_centrodes_layer_agrees_with_python():
    from mech.planar import FourBar
    from mech.planar.coupler._centrodes import coupler_centrodes

    rng = np.random.default_rng(19)
    cases = []
    for a, b, c, d in _linkages(rng, 40):
        scale = float(rng.choice([1e-150, 1.0, 1e150]))
        theta = [float(t) for t in rng.uniform(-4, 4, 60)]
        cases.append({"lengths": [a * scale, b * scale, c * scale, d * scale], "branch": int(rng.choice((-1, 1))),
                      "theta": theta})
    script = (f'import {{ FourBar, couplerCentrodes }} from "{LAYER.as_uri()}";\n'
              f"const cases = {json.dumps(cases)};\n"
              "const fix = (v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v);\n"
              "const out = cases.map((k) => { const r = couplerCentrodes(new FourBar(...k.lengths, {branch: k.branch}), k.theta);\n"
              "  return {valid: r.valid, inf: r.atInfinity, fx: Array.from(r.fixed.x, fix), fy: Array.from(r.fixed.y, fix),\n"
              "          mx: Array.from(r.moving.x, fix), my: Array.from(r.moving.y, fix)}; });\n"
              "process.stdout.write(JSON.stringify(out));")
    for case, js in zip(cases, _node_json(script)):
        cen = coupler_centrodes(FourBar(*case["lengths"], branch=case["branch"]), case["theta"])
        where = f"FourBar{tuple(case['lengths'])}"
        assert list(cen.valid) == js["valid"] and list(cen.at_infinity) == js["inf"], where
        size = max(case["lengths"])
        for want, got in ((cen.fixed, (js["fx"], js["fy"])), (cen.moving, (js["mx"], js["my"]))):
            got = np.array(got[0], dtype=float) + 1j * np.array(got[1], dtype=float)
            assert np.array_equal(np.isnan(want), np.isnan(got)), where
            ok = ~np.isnan(want)
            # a pole far away (crank nearly parallel to the rocker) at distance R moves by about
            # eps R^2 / size when the inputs are rounded: its conditioning bound
            far = np.abs(want[ok]) / size
            assert np.all(np.abs(want[ok] - got[ok]) <= 1e-13 * size * (1 + far + far**2)), where


def test_guidance_layer_agrees_with_python():
    from mech.planar.synthesis import dyad_for_centre_point, dyad_for_circle_point, pole

    rng = np.random.default_rng(23)
    cases = []
    for _ in range(300):
        n = int(rng.choice((2, 3)))
        scale = float(rng.choice([1e-100, 1.0, 1e100]))
        theta = [float(t) for t in rng.uniform(-3, 3, n)]
        d = [[float(x) * scale for x in rng.uniform(-1, 1, 2)] for _ in range(n)]
        z = [float(x) * scale for x in rng.uniform(-1, 1, 2)]
        cases.append({"theta": theta, "d": d, "z": z, "along": float(rng.uniform(-1, 1)), "scale": scale})
    script = (f'import {{ pole, dyadForCirclePoint, dyadForCentrePoint }} from "{(LAYER.parent / "guidance.js").as_uri()}";\n'
              f"const cases = {json.dumps(cases)};\n"
              "const run = (f) => { try { return f(); } catch (e) { return e.message; } };\n"
              "const out = cases.map((k) => [run(() => pole(k.theta[0], k.d[0], k.theta[1], k.d[1])),\n"
              "  run(() => dyadForCirclePoint(k.theta, k.d, k.z, {along: k.along})),\n"
              "  run(() => dyadForCentrePoint(k.theta, k.d, k.z, {along: k.along}))]);\n"
              "process.stdout.write(JSON.stringify(out));")
    for case, (q, circle, centre) in zip(cases, _node_json(script)):
        theta = np.array(case["theta"])
        d = np.array([x + 1j * y for x, y in case["d"]])
        z = case["z"][0] + 1j * case["z"][1]
        size = case["scale"]

        def close(want, got):
            far = abs(want) / size           # a far point (near a translation, near collinear) is ill-conditioned
            return abs(want - complex(*got)) <= 1e-13 * size * (1 + far + far**2)

        want_q = pole(theta[0], d[0], theta[1], d[1])
        assert close(want_q, q), case
        for fn, got in ((dyad_for_circle_point, circle), (dyad_for_centre_point, centre)):
            want = fn(theta, d, z, along=case["along"])
            assert close(want.centre_point, got["centrePoint"]) and close(want.circle_point, got["circlePoint"]), case
            assert abs(want.length - got["length"]) <= 1e-13 * size * (1 + (want.length / size) ** 2), case
