"""Spherical path synthesis by optimisation (monograph §2.5), checked by independent analysis.

The coupler points of every synthesised linkage are rebuilt here from its parameters by
Rodrigues rotations in mpmath (`sixbar_reference.chain`, and a four-bar built from the
cosine law below), not by `SphericalFourBar.solve` or `SphericalLinkage.solve`.
"""

import mpmath
import numpy as np
import pytest

from mech.spherical import SphericalFourBar, ground_frame, path_fourbar, path_stephenson1, path_verify, to_xyz
from mech.spherical.path._synthesis import _stephenson
from tests.spherical.sixbar_reference import chain, dyad_guesses

mpmath.mp.dps = 50

#: Example 1: a four-bar (nine parameters) whose coupler points, with noise, make the task.
X1 = np.array([0.4, 1.0, 0.6, 0.45, 1.05, 0.85, 1.15, 0.55, 0.7])
TH1 = np.linspace(0.3, 0.3 + np.radians(240.0), 8)
NOISE = 1e-3
#: Example 2: nine points 40 degrees apart on a small circle (arc radius 0.25 about
#: lon 0.5, lat 0.9), met at input angles 30 degrees apart; the start is the best of a
#: multi-start search (book page).
X2 = np.array([0.52653, 0.99258, -4.38134, 0.51352, 0.17085, 0.63038, 0.05345, 0.3594, -2.56499])
TH2 = np.radians(np.arange(9) * 30.0)
TOL2 = 5e-3


def small_circle(centre, rho, angles):
    z = np.asarray(centre, dtype=float)
    x = np.cross([0.0, 0.0, 1.0], z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return np.cos(rho) * z + np.sin(rho) * (np.cos(angles)[:, None] * x + np.sin(angles)[:, None] * y)


def example1_points():
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    rng = np.random.default_rng(1)
    Q = m.solve(TH1).P + NOISE * rng.standard_normal((TH1.size, 3))
    return Q / np.linalg.norm(Q, axis=1)[:, None]


def example2_points():
    return small_circle(to_xyz(0.5, 0.9), 0.25, np.radians(np.arange(9) * 40.0))


def mp_fourbar_points(linkage, theta):
    """Coupler points from the arcs and the frame alone: B by rotation about A, C from the
    two cosine conditions B.C = cos b, D.C = cos c with the branch sign, P by rotation about B."""
    R = [[mpmath.mpf(float(v)) for v in row] for row in linkage.frame]
    col = lambda j: mpmath.matrix([R[0][j], R[1][j], R[2][j]])
    X, Y, A = col(0), col(1), col(2)
    a, b, c, d = (mpmath.mpf(float(v)) for v in (linkage.a, linkage.b, linkage.c, linkage.d))
    r, g = (mpmath.mpf(float(v)) for v in linkage.coupler)
    dot = lambda p, q: sum(p[i] * q[i] for i in range(3))
    cross = lambda p, q: mpmath.matrix([p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]])
    D = A * mpmath.cos(d) + X * mpmath.sin(d)
    out = []
    for t in theta:
        t = mpmath.mpf(float(t))
        B = A * mpmath.cos(a) + (X * mpmath.cos(t) + Y * mpmath.sin(t)) * mpmath.sin(a)
        k = dot(B, D)
        # C = u B + v D + w (B x D): u + v k = cos b, u k + v = cos c, |C| = 1
        u = (mpmath.cos(b) - k * mpmath.cos(c)) / (1 - k * k)
        v = (mpmath.cos(c) - k * mpmath.cos(b)) / (1 - k * k)
        n = cross(B, D)
        w = linkage.branch * mpmath.sqrt((1 - u * u - v * v - 2 * u * v * k) / dot(n, n))
        C = B * u + D * v + n * w
        tb = C - B * dot(B, C)
        tb = tb / mpmath.sqrt(dot(tb, tb))
        P = B * mpmath.cos(r) + (tb * mpmath.cos(g) + cross(B, tb) * mpmath.sin(g)) * mpmath.sin(r)
        out.append([float(P[i]) for i in range(3)])
    return np.array(out)


def arcs(P, Q):
    return np.arctan2(np.linalg.norm(np.cross(P, Q), axis=1), np.sum(P * Q, axis=1))


def check_by_mpmath(design, tol):
    P = mp_fourbar_points(design.linkage, design.theta)
    assert np.max(np.abs(P - design.generated)) < 1e-12
    assert np.max(arcs(P, design.points)) <= tol


@pytest.mark.parametrize("formulation", ["distance", "constant-arc"])
def test_exact_points_are_recovered(formulation):
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    Q = m.solve(TH1).P
    d = path_fourbar(Q, TH1, X1 + 0.05, formulation=formulation)
    assert d.passes and d.in_order and d.max_error < 1e-9
    check_by_mpmath(d, 1e-9)


def test_example1_noisy_points_both_formulations():
    Q = example1_points()
    start = X1 + np.array([0.1, -0.1, 0.1, 0.05, -0.05, 0.05, -0.05, 0.1, -0.1])
    dist = path_fourbar(Q, TH1, start, tol=2e-3)
    const = path_fourbar(Q, TH1, start, formulation="constant-arc", tol=2e-3)
    for d in (dist, const):
        assert d.in_order and d.max_error <= 2e-3
        check_by_mpmath(d, 2e-3)
    # the distance formulation minimises the distances themselves: never worse in rms
    assert dist.rms_error <= const.rms_error + 1e-12
    # the noise is 1e-3 per coordinate: the designs stay near the linkage that made the task
    assert np.max(np.abs(dist.parameters - X1)) < 0.05
    # the chordal objective gives the same design to first order in the (small) errors
    chord = path_fourbar(Q, TH1, start, metric="chord")
    assert abs(chord.rms_error - dist.rms_error) < 1e-5


def test_example2_small_circle():
    Q = example2_points()
    d = path_fourbar(Q, TH2, X2, tol=TOL2)
    assert d.passes and d.in_order
    assert d.max_error == pytest.approx(4.179e-3, abs=2e-6)
    check_by_mpmath(d, TOL2)
    # the points are met in order: the coupler point's position angle about the circle's
    # centre increases from point to point along the sweep
    z = to_xyz(0.5, 0.9)
    sweep = d.linkage.solve(np.linspace(TH2[0], TH2[-1], 801)).P
    x = np.cross([0.0, 0.0, 1.0], z)
    x /= np.linalg.norm(x)
    ang = np.unwrap(np.arctan2(sweep @ np.cross(z, x), sweep @ x))
    assert np.all(np.diff(ang) > 0)


def test_stephenson1_recovers_a_known_sixbar():
    x = np.array([0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5])
    th = np.linspace(0.0, 1.6, 7)
    Q = _stephenson(x, (1, 1)).solve(th).points["P"]
    d = path_stephenson1(Q, th, x + 0.02)
    assert d.passes and d.max_error < 1e-6
    pose = d.linkage.solve(th)
    for i, t in enumerate(th):
        guesses = dyad_guesses(d.linkage, {k: v[i] for k, v in pose.points.items()})
        P = chain(d.linkage, t, guesses)["P"]
        assert np.allclose([float(P[k]) for k in range(3)], Q[i], atol=1e-6)


def test_verify_flags_the_other_branch_and_unassembled_sweeps():
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    other = SphericalFourBar(*X1[3:7], branch=-1, coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    Q = m.solve(TH1).P
    assert path_verify(m, Q, TH1)["passes"]
    v = path_verify(other, Q, TH1)
    assert not v["passes"] and v["max_error"] > 0.1
    # a triple rocker cannot sweep a full half turn of its input
    rocker = SphericalFourBar(0.9, 0.5, 0.6, 0.7, coupler=(0.2, 0.3))
    th = np.linspace(0.0, 3.0, 4)
    assert not path_verify(rocker, np.tile([0.0, 0.0, 1.0], (4, 1)), th)["in_order"]


@pytest.mark.parametrize("kwargs, name", [
    ({"points": np.ones((3, 3))}, "points"),
    ({"theta": np.array([0.0, 2.0, 1.0])}, "theta"),
    ({"start": np.ones(8)}, "start"),
    ({"formulation": "sum"}, "formulation"),
    ({"metric": "euclid"}, "metric"),
    ({"tol": -1.0}, "tol"),
])
def test_bad_inputs_are_named(kwargs, name):
    args = {"points": SphericalFourBar(0.5, 1.1, 0.9, 1.2).solve([0.0, 1.0, 2.0]).P,
            "theta": np.array([0.0, 1.0, 2.0]), "start": X1}
    args.update(kwargs)
    with pytest.raises(ValueError, match=f"`{name}`"):
        path_fourbar(args.pop("points"), args.pop("theta"), args.pop("start"), **args)


def test_formulations_compared_on_speed_and_result():
    """Exact points: the constant-arc formulation (dot-product residuals, exact Jacobian) is
    the faster one; the small-circle task, which no four-bar meets exactly: from the same
    start only the distance formulation ends near the points."""
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    Q = m.solve(TH1).P
    best = {f: min(path_fourbar(Q, TH1, X1 + 0.05, formulation=f).seconds for _ in range(3))
            for f in ("distance", "constant-arc")}
    assert best["constant-arc"] < best["distance"]
    Q2 = example2_points()
    dist = path_fourbar(Q2, TH2, X2, tol=TOL2)
    const = path_fourbar(Q2, TH2, X2, formulation="constant-arc", tol=TOL2)
    assert dist.passes and not const.passes
    assert const.max_error > 10 * dist.max_error
