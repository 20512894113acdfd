"""The implicit coupler curves of the spherical six-bars (monograph §2.2, §2.7 to §2.9):
`sixbar_curve` against coupler points built independently in mpmath at 50 digits (rotations
and circle intersections, every assembly, random placement), its order on great circles,
its cone, and the Watt-2 curve against the four-bar quartic of DEGF.
"""

import mpmath
import numpy as np
import pytest

from mech.spherical import (SIXBAR_CURVE_ORDERS, SphericalFourBar, coupler_quartic, ground_frame, sixbar_curve,
                            stephenson1, stephenson2, watt1, watt2)

DPS = 50
KINDS = ("stephenson1", "stephenson2", "watt1", "watt2")
BUILD = {"stephenson1": stephenson1, "stephenson2": stephenson2, "watt1": watt1, "watt2": watt2}
NAMES = ("a", "b", "c", "d", "rE", "gE", "rF", "gF", "e", "f", "r", "g")


# ----------------------------------------------------------------------------- independent route
def _cross(p, q):
    return mpmath.matrix([p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]])


def _dot(p, q):
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def _rotate(axis, angle, p):
    """Rodrigues: p turned by angle about the unit axis (right hand)."""
    c, s = mpmath.cos(angle), mpmath.sin(angle)
    return p * c + _cross(axis, p) * s + axis * (_dot(axis, p) * (1 - c))


def _on(o, x, r, g=0):
    """At arc r from o toward x, then turned by g about o."""
    d = x - o * _dot(o, x)
    d = d / mpmath.sqrt(_dot(d, d))
    return _rotate(o, g, o * mpmath.cos(r) + d * mpmath.sin(r))


def _circles(P1, r1, P2, r2, sign):
    """The point at arcs r1 from P1 and r2 from P2, on the side `sign` of P1 -> P2 (None: none)."""
    c1, c2, g = mpmath.cos(r1), mpmath.cos(r2), _dot(P1, P2)
    base = P1 * ((c1 - g * c2) / (1 - g**2)) + P2 * ((c2 - g * c1) / (1 - g**2))
    n = _cross(P1, P2)
    h2 = (1 - _dot(base, base)) / _dot(n, n)
    return None if h2 < 0 else base + n * (sign * mpmath.sqrt(h2))


def _mp_points(kind, p, frame, thetas):
    """Coupler points of every assembly, at 50 digits, rounded to double."""
    out = []
    with mpmath.workdps(DPS):
        q = {k: mpmath.mpf(v) for k, v in p.items()}
        R = mpmath.matrix(np.asarray(frame).tolist())
        A = R * mpmath.matrix([0, 0, 1])
        D = R * mpmath.matrix([mpmath.sin(q["d"]), 0, mpmath.cos(q["d"])])
        on_e, on_f = {"stephenson1": ("AB", "DC"), "stephenson2": ("BC", None), "watt1": ("BC", "DC"),
                      "watt2": ("DC", None)}[kind]
        for s1 in (1, -1):
            for s2 in (1, -1):
                for th in thetas:
                    B = _rotate(A, mpmath.mpf(th), _on(A, D, q["a"]))
                    C = _circles(B, q["b"], D, q["c"], s1)
                    if C is None:
                        continue
                    links = {"AB": (A, B), "BC": (B, C), "DC": (D, C)}
                    E = _on(*links[on_e], q["rE"], q["gE"])
                    F = _on(A, D, q["rF"], q["gF"]) if on_f is None else _on(*links[on_f], q["rF"], q["gF"])
                    G = _circles(E, q["e"], F, q["f"], s2)
                    if G is not None:
                        out.append([float(v) for v in _on(E, G, q["r"], q["g"])])
    return np.array(out)


def _design(rng):
    low = dict(a=0.2, b=0.5, c=0.4, d=0.6, rE=0.1, gE=-3, rF=0.1, gF=-3, e=0.3, f=0.3, r=0.1, g=-3)
    high = dict(a=0.5, b=1.2, c=1.0, d=1.3, rE=0.8, gE=3, rF=1.5, gF=3, e=1.2, f=1.2, r=0.9, g=3)
    return {n: float(rng.uniform(low[n], high[n])) for n in NAMES}


def _build(kind, p, frame=None):
    return BUILD[kind](p["a"], p["b"], p["c"], p["d"], E=(p["rE"], p["gE"]), F=(p["rF"], p["gF"]),
                       arcs=(p["e"], p["f"]), coupler=(p["r"], p["g"]), frame=frame)


def _distance(linkage, points, h=1e-6):
    """|Q| over the tangential part of its gradient (central differences): a distance to the curve."""
    points = np.asarray(points, dtype=float)
    value = sixbar_curve(linkage, points)
    grad = np.stack([(sixbar_curve(linkage, points + h * e) - sixbar_curve(linkage, points - h * e)) / (2 * h)
                     for e in np.eye(3)], axis=-1)
    grad = grad - np.sum(grad * points, axis=-1, keepdims=True) * points
    return np.abs(value) / np.linalg.norm(grad, axis=-1)


# ----------------------------------------------------------------------------- tests
@pytest.mark.parametrize("kind", KINDS)
def test_sixbar_curve_mpmath_points_on_curve(kind):
    """Monograph §2.2, §2.7, §2.8, §2.9: coupler points at 50 digits satisfy the curve to 1e-10."""
    rng = np.random.default_rng(sum(map(ord, kind)))
    total = 0
    for _ in range(4):
        p = _design(rng)
        frame = ground_frame(*rng.uniform(-1.5, 1.5, 3))
        pts = _mp_points(kind, p, frame, np.linspace(0.05, 6.25, 10))
        if len(pts):
            assert _distance(_build(kind, p, frame), pts).max() < 1e-10
            total += len(pts)
    assert total > 20


@pytest.mark.parametrize("kind", KINDS)
def test_sixbar_curve_random_points_off_curve(kind):
    rng = np.random.default_rng(7)
    lk = _build(kind, _design(rng))
    q = rng.normal(size=(50, 3))
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    assert np.median(_distance(lk, q)) > 1e-3


@pytest.mark.parametrize("kind", KINDS)
def test_sixbar_curve_order_on_great_circle(kind):
    """Monograph §2.2, §2.7, §2.8, §2.9: on a great circle Q is a trigonometric polynomial of
    degree exactly order / 2."""
    rng = np.random.default_rng(3)
    lk = _build(kind, _design(rng), ground_frame(0.4, -0.3, 1.1))
    m = SIXBAR_CURVE_ORDERS[kind] // 2
    frame = ground_frame(1.0, 0.5, 0.2)
    s = np.linspace(0, 2 * np.pi, 4 * m + 8, endpoint=False)
    values = sixbar_curve(lk, np.outer(np.cos(s), frame[:, 0]) + np.outer(np.sin(s), frame[:, 1]))
    spectrum = np.abs(np.fft.rfft(values)) / len(s)
    assert spectrum[m + 1:].max() < 1e-8 * spectrum.max()
    assert spectrum[m] > 1e-6 * spectrum.max()


@pytest.mark.parametrize("kind", KINDS)
def test_sixbar_curve_cone_homogeneous(kind):
    lk = _build(kind, _design(np.random.default_rng(5)))
    x = np.random.default_rng(6).normal(size=(6, 3))
    H = sixbar_curve(lk, x, cone=True)
    np.testing.assert_allclose(sixbar_curve(lk, 1.7 * x, cone=True), 1.7 ** SIXBAR_CURVE_ORDERS[kind] * H, rtol=1e-10)
    np.testing.assert_allclose(sixbar_curve(lk, -x, cone=True), H, rtol=1e-12)
    unit = x / np.linalg.norm(x, axis=-1, keepdims=True)
    np.testing.assert_allclose(H, np.linalg.norm(x, axis=-1) ** SIXBAR_CURVE_ORDERS[kind]
                               * sixbar_curve(lk, unit) * sixbar_curve(lk, -unit), rtol=1e-10)


@pytest.mark.parametrize("kind", KINDS)
def test_sixbar_curve_placement(kind):
    """Placing the linkage by a rotation R turns its curve: Q_R(R x) = const * Q(x)."""
    p = _design(np.random.default_rng(11))
    R = ground_frame(0.7, 0.2, -1.3)
    x = np.random.default_rng(12).normal(size=(8, 3))
    ratio = sixbar_curve(_build(kind, p, R), x @ R.T) / sixbar_curve(_build(kind, p), x)
    np.testing.assert_allclose(ratio, ratio[0], rtol=1e-8)


def test_sixbar_curve_watt2_is_the_fourbar_quartic_of_DEGF():
    """The second loop of Watt-2 is the four-bar D-E-G-F: its curve is that four-bar's quartic."""
    a, b, c, d = 0.3, 0.9, 0.7, 1.0
    rE, gE, rF, gF, e, f, r, g = 0.4, 0.6, 1.4, 0.5, 0.6, 0.5, 0.3, 0.5
    lk = watt2(a, b, c, d, E=(rE, gE), F=(rF, gF), arcs=(e, f), coupler=(r, g))
    D = np.array([np.sin(d), 0.0, np.cos(d)])
    F = np.array([np.sin(rF) * np.cos(gF), np.sin(rF) * np.sin(gF), np.cos(rF)])
    u = F - (F @ D) * D
    u /= np.linalg.norm(u)
    frame = np.column_stack([u, np.cross(D, u), D])
    four = SphericalFourBar(rE, e, f, np.arccos(D @ F), coupler=(r, g), frame=frame)
    x = np.random.default_rng(2).normal(size=(10, 3))
    x /= np.linalg.norm(x, axis=-1, keepdims=True)
    ratio = sixbar_curve(lk, x) / coupler_quartic(four, x)[0]
    np.testing.assert_allclose(ratio, ratio[0], rtol=1e-9)


def test_sixbar_curve_orders():
    assert SIXBAR_CURVE_ORDERS == {"stephenson1": 24, "stephenson2": 32, "watt1": 24, "watt2": 8}


def test_sixbar_curve_rejects_other_linkages():
    with pytest.raises(ValueError, match="Expected `linkage`"):
        sixbar_curve(SphericalFourBar(0.5, 1.1, 0.9, 1.2), [0.0, 0.0, 1.0])
    with pytest.raises(ValueError, match="Expected non-zero `points`"):
        sixbar_curve(_build("watt1", _design(np.random.default_rng(1))), [0.0, 0.0, 0.0])


def test_sixbar_curve_stephenson1_crank_axis_is_continuous():
    """Along the crank axis one root theta goes to infinity: the value tends to its limit."""
    lk = stephenson1(0.3, 0.9, 0.7, 1.0, E=(0.25, 0.8), F=(0.35, -1.2), arcs=(0.8, 0.7), coupler=(0.4, 0.6))
    for pole in (1.0, -1.0):
        at = sixbar_curve(lk, [0.0, 0.0, pole])
        near = sixbar_curve(lk, [[1e-9, 3e-10, pole], [1e-6, -2e-6, pole]])
        assert np.isfinite(at)
        np.testing.assert_allclose(near, at, rtol=1e-4)


def test_sixbar_curve_watt1_at_the_pivot_D():
    """At P = +-D the Dixon determinant and |P x D|**4 both vanish: the limit is returned."""
    d = 1.0
    lk = watt1(0.3, 0.9, 0.7, d, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    D = np.array([np.sin(d), 0.0, np.cos(d)])
    for sign in (1.0, -1.0):
        at = sixbar_curve(lk, sign * D)
        scale = np.abs(sixbar_curve(lk, sign * D + np.array([0.0, 0.1, 0.0])))
        near = sixbar_curve(lk, sign * D + np.array([0.0, 1e-3, 0.0]))
        assert np.isfinite(at) and abs(at - near) < 0.05 * max(scale, abs(at))
