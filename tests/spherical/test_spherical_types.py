"""Tests of the spherical four-bar types (mech.spherical._types, mech.spherical._special).

Expected values come from a small independent solver: the far joint C of the loop is the
intersection of two circles on the sphere (Gram system of the two centres), and a joint
turns fully when the loop closes for every value of its own angle. Angles at the joints are
measured from the vectors. The planar limits use mech.planar; the universal joint uses
mech.spatial.hooke_output.
"""

import numpy as np
import pytest

from mech.planar import SliderCrank, grashof
from mech.spatial import hooke_output
from mech.spherical._fourbar import SphericalFourBar
from mech.spherical._special import (
    deltoid,
    deltoid_input,
    isogram,
    isogram_output,
    slider_crank_stroke,
    spherical_slider_crank,
    universal_joint,
)
from mech.spherical._types import antipode_reduction, classify, inversions

TWO_PI = 2 * np.pi


# ---------------------------------------------------------------- the independent solver
def circle_meet(p1, p2, r1, r2):
    """Both points at arc r1 from p1 and r2 from p2 (unit vectors, shape (..., 3)), and a mask."""
    g = np.sum(p1 * p2, axis=-1)
    det = 1.0 - g**2
    p = (np.cos(r1) - g * np.cos(r2)) / det
    q = (np.cos(r2) - g * np.cos(r1)) / det
    w2 = (1.0 - p**2 - q**2 - 2 * p * q * g) / det
    ok = w2 >= 0.0
    w = np.sqrt(np.where(ok, w2, 0.0))
    base = p[..., None] * p1 + q[..., None] * p2
    cross = np.cross(p1, p2)
    return base + w[..., None] * cross, base - w[..., None] * cross, ok


def loop_points(arcs, theta):
    """A, B, D and both C of the loop (a, b, c, d) at input angles theta (default frame)."""
    a, b, c, d = arcs
    theta = np.asarray(theta, dtype=float)
    A = np.broadcast_to([0.0, 0.0, 1.0], theta.shape + (3,))
    D = np.broadcast_to([np.sin(d), 0.0, np.cos(d)], theta.shape + (3,))
    B = np.stack([np.sin(a) * np.cos(theta), np.sin(a) * np.sin(theta), np.full(theta.shape, np.cos(a))], -1)
    C1, C2, ok = circle_meet(B, D, b, c)
    return A, B, D, C1, C2, ok


def drive_grid(n=720):
    """Angles over a full turn, containing 0 and pi exactly."""
    return np.concatenate([np.linspace(0.0, np.pi, n // 2 + 1), np.linspace(np.pi, TWO_PI, n // 2 + 1)[1:-1]])


def ring(arcs, joint):
    """The loop relabelled so that `joint` plays the part of A."""
    k = "ABCD".index(joint)
    return tuple(arcs[k:]) + tuple(arcs[:k])


def turns_fully_by_driving(arcs, joint):
    return bool(np.all(loop_points(ring(arcs, joint), drive_grid())[-1]))


def vertex_angle(v, prev, nxt):
    """Signed angle at v from the great circle v->prev to v->nxt, seen from outside."""
    tp = prev - np.sum(prev * v, -1)[..., None] * v
    tn = nxt - np.sum(nxt * v, -1)[..., None] * v
    return np.arctan2(np.sum(v * np.cross(tp, tn), -1), np.sum(tp * tn, -1))


def max_gap(angles):
    s = np.sort(np.mod(angles, TWO_PI))
    return float(np.max(np.diff(np.concatenate([s, [s[0] + TWO_PI]]))))


def slacks(arcs):
    a, b, c, d = arcs
    return ((c + d) - (a + b), (b + d) - (a + c), (b + c) - (a + d), TWO_PI - (a + b + c + d))


def assembles(arcs):
    return bool(np.any(loop_points(arcs, drive_grid())[-1]))


def random_linkages(count, seed, margin=1e-6, low=0.02):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        arcs = tuple(float(x) for x in rng.uniform(low, np.pi - low, 4))
        if min(abs(s) for s in slacks(arcs)) < margin or not assembles(arcs):
            continue
        out.append(arcs)
    return out


# ---------------------------------------------------------------- classify
def test_classify_random_agrees_with_driving_each_joint():
    """400 random linkages, arcs anywhere in (0, pi): revolving joints by simulation."""
    over = 0
    for arcs in random_linkages(400, seed=11):
        t = classify(*arcs)
        simulated = frozenset(j for j in "ABCD" if turns_fully_by_driving(arcs, j))
        assert t.revolving == simulated, arcs
        over += sum(arcs) > TWO_PI
    assert over > 50          # the sphere's own case is well represented


def test_classify_trace_both_branches_covers_revolving_joints():
    """Trace the configuration curve (both branches, every joint driven) and measure each
    joint's angle: a revolving joint covers the circle, a rocking one leaves a gap."""
    for arcs in random_linkages(40, seed=5, margin=0.05):
        t = classify(*arcs)
        samples = {j: [] for j in "ABCD"}
        for k, joint in enumerate("ABCD"):
            A, B, D, C1, C2, ok = loop_points(ring(arcs, joint), drive_grid(2000))
            for C in (C1[ok], C2[ok]):
                P = [A[ok], B[ok], C, D[ok]]                     # relabelled A, B, C, D
                for i in range(4):
                    original = "ABCD"[(k + i) % 4]
                    samples[original].append(vertex_angle(P[i], P[i - 1], P[(i + 1) % 4]))
        for j in "ABCD":
            gap = max_gap(np.concatenate(samples[j]))
            if j in t.revolving:
                assert gap < 0.05, (arcs, j, gap)
            else:
                assert gap > 0.05, (arcs, j, gap)


@pytest.mark.parametrize("seed", [1, 2])
def test_classify_planar_limit(seed):
    """Small arcs: the type of the planar four-bar with the same proportions."""
    rng = np.random.default_rng(seed)
    checked = 0
    while checked < 150:
        lengths = rng.uniform(0.5, 3.0, 4)
        if 2 * lengths.max() >= lengths.sum():
            continue
        planar = grashof(*lengths)
        if planar.change_point or min(abs(s) for s in slacks(lengths)[:3]) < 1e-3:
            continue
        t = classify(*(1e-3 * lengths))
        assert (t.kind, t.revolving, t.grashof) == (planar.kind, planar.revolving, planar.grashof)
        checked += 1


def test_antipode_reduction_normal_form_and_invariance():
    """The reduced arcs: at most one above pi/2, total <= 2 pi, reachable by the moves;
    moving any joint to its antipode leaves the fully rotatable joints unchanged."""
    moves_of = {"A": (0, 3), "B": (0, 1), "C": (1, 2), "D": (2, 3)}
    for arcs in random_linkages(150, seed=3):
        reduced, moves = antipode_reduction(*arcs)
        assert sum(x > np.pi / 2 for x in reduced) <= 1 and sum(reduced) <= TWO_PI
        rebuilt = list(arcs)
        for joint in moves:
            for i in moves_of[joint]:
                rebuilt[i] = np.pi - rebuilt[i]
        assert np.allclose(rebuilt, reduced, atol=1e-15)
        before = classify(*arcs).revolving
        for joint, (i, k) in moves_of.items():
            moved = list(arcs)
            moved[i], moved[k] = np.pi - moved[i], np.pi - moved[k]
            assert classify(*moved).revolving == before
            assert frozenset(j for j in "ABCD" if turns_fully_by_driving(moved, j)) == before


def test_classify_grashof_is_planar_rule_on_reduced_arcs():
    for arcs in random_linkages(200, seed=8):
        t = classify(*arcs)
        s = sorted(t.reduced)
        assert t.grashof == (s[0] + s[3] <= s[1] + s[2])
        if t.grashof:   # the joints on the shortest reduced arc turn fully
            ends = {"a": "AB", "b": "BC", "c": "CD", "d": "DA"}[t.shortest]
            assert set(ends) <= t.revolving


@pytest.mark.parametrize(
    ("arcs", "kind", "revolving"),
    [
        ((0.3, 0.9, 0.7, 1.0), "crank-rocker", "AB"),
        ((1.0, 0.9, 0.7, 0.3), "double-crank", "AD"),          # shortest arc is the ground
        ((0.9, 0.3, 1.0, 0.7), "double-rocker", "BC"),         # shortest arc is the coupler
        ((0.7, 1.0, 0.3, 0.9), "rocker-crank", "CD"),
        ((1.0, 0.4, 0.6, 0.7), "triple-rocker", ""),
        ((np.pi - 0.3, np.pi - 0.9, 0.7, 1.0), "crank-rocker", "AB"),   # B at its antipode
        ((2.9, 2.4, 2.3, 2.2), "crank-rocker", "AB"),          # total > 2 pi
    ],
)
def test_classify_kind_hand_picked(arcs, kind, revolving):
    t = classify(*arcs)
    assert t.kind == kind and t.revolving == frozenset(revolving)
    assert t.revolving == frozenset(j for j in "ABCD" if turns_fully_by_driving(arcs, j))


def test_classify_sum_over_two_pi_reverses_planar_reading():
    """Arcs (2.9, 2.4, 2.3, 2.2): read as planar lengths, s + l = 5.1 > p + q = 4.7, a
    triple-rocker; on the sphere (total 9.8 > 2 pi) it is a crank-rocker."""
    arcs = (2.9, 2.4, 2.3, 2.2)
    assert grashof(*arcs).kind == "triple-rocker"
    assert classify(*arcs).kind == "crank-rocker"
    assert frozenset(j for j in "ABCD" if turns_fully_by_driving(arcs, j)) == frozenset("AB")


@pytest.mark.parametrize(
    ("arcs", "meeting"),
    [
        ((0.4, 0.9, 0.4, 0.9), (0.0, np.pi)),                    # isogram
        ((0.5, 0.6, 0.7, 0.8), (np.pi,)),                        # a + d = b + c
        ((0.5, 0.9, 0.7, 0.7), (0.0,)),                          # a + b = c + d
        ((2.0, 1.5, 1.6, TWO_PI - 5.1), (np.pi,)),               # sum 2 pi: the sphere's own
    ],
)
def test_classify_change_point_meeting_angles(arcs, meeting):
    t = classify(*arcs)
    assert t.change_point and t.meeting_angles == meeting
    for theta in meeting:          # the two circles touch: one double C, the loop lies flat
        _, B, D, C1, C2, ok = loop_points(arcs, np.array([theta]))
        assert np.linalg.norm(C1 - C2) < 1e-6
        assert abs(np.linalg.det(np.stack([B[0], D[0], C1[0]]))) < 1e-6


def test_classify_errors():
    with pytest.raises(ValueError, match="Expected `a` in"):
        classify(-0.1, 1.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="Expected `d` in"):
        classify(0.5, 1.0, 1.0, np.pi)
    with pytest.raises(ValueError, match="cannot be assembled"):
        classify(0.2, 0.3, 0.2, 1.2)
    with pytest.raises(ValueError, match="Expected `tol`"):
        classify(0.3, 0.9, 0.7, 1.0, tol=-1.0)


def test_inversions_kinds():
    """Inversions of a chain with shortest arc a: by driving each ground's input joint."""
    arcs = (0.3, 0.9, 0.7, 1.0)
    kinds = inversions(*arcs)
    assert kinds == {"a": "double-crank", "b": "rocker-crank", "c": "double-rocker", "d": "crank-rocker"}
    # fixing b: the chain read from C is (c, d, a, b), input at C, output at B
    assert classify(*ring(arcs, "C")).kind == kinds["b"]
    assert classify(*ring(arcs, "B")).kind == kinds["a"]


# ---------------------------------------------------------------- special types
@pytest.mark.parametrize("alpha", [0.05, 0.3, np.radians(30.0), 1.0, 1.4])
def test_universal_joint_equals_hooke_output(alpha):
    theta = np.linspace(-np.pi, np.pi, 1441)
    psi = universal_joint(alpha).solve(theta).psi
    diff = np.angle(np.exp(1j * (psi + np.pi / 2 - hooke_output(theta, alpha))))
    assert np.max(np.abs(diff)) < 1e-13


def test_universal_joint_errors():
    with pytest.raises(ValueError, match="Expected `shaft_angle`"):
        universal_joint(np.pi / 2)


@pytest.mark.parametrize(("a", "b"), [(0.4, 0.9), (1.2, 0.5), (2.0, 0.7)])
def test_isogram_output_closes_the_loop(a, b):
    """Both motions put C at arc b from B (own construction of C from psi)."""
    theta = np.linspace(-3.0, 3.0, 61)
    for crossed in (False, True):
        psi = isogram_output(theta, a, b, crossed=crossed)
        B = np.stack([np.sin(a) * np.cos(theta), np.sin(a) * np.sin(theta), np.full_like(theta, np.cos(a))], -1)
        D = np.array([np.sin(b), 0.0, np.cos(b)])
        t1, t2 = np.array([np.cos(b), 0.0, -np.sin(b)]), np.array([0.0, 1.0, 0.0])
        C = np.cos(a) * D + np.sin(a) * (np.cos(psi)[:, None] * t1 + np.sin(psi)[:, None] * t2)
        assert np.max(np.abs(np.sum(B * C, -1) - np.cos(b))) < 1e-13
        assert np.all(np.abs(np.diff(psi)) < 0.5)          # continuous


def test_isogram_branch_plus_stays_parallel():
    """Through its change points at 0 and pi the parallel isogram stays parallel and the
    crossed one stays crossed (the branch guarantee of CONVENTIONS.md, section Spherical)."""
    a, b = 0.4, 0.9
    theta = np.array([-3.0, -1e-9, 0.0, 0.5, 2.0, np.pi, 3.5, 5.0])
    par = isogram_output(theta, a, b)
    cross = isogram_output(theta, a, b, crossed=True)
    wrap = lambda x: np.angle(np.exp(1j * x))
    assert np.allclose(wrap(isogram(a, b).solve(theta).psi - par), 0.0, atol=1e-12)
    assert np.allclose(wrap(isogram(a, b, branch=-1).solve(theta).psi - cross), 0.0, atol=1e-12)


def test_isogram_planar_limit():
    """Parallelogram psi = theta; anti-parallelogram tan(psi/2) = (a+b)/(a-b) tan(theta/2)."""
    theta = np.linspace(-3.0, 3.0, 25)
    eps = 1e-4
    assert np.max(np.abs(isogram_output(theta, 2 * eps, 5 * eps) - theta)) < 1e-7
    crossed = isogram_output(theta, 2 * eps, 5 * eps, crossed=True)
    assert np.allclose(np.tan(crossed / 2), (7 / -3) * np.tan(theta / 2), rtol=1e-6)


def test_deltoid_two_to_one():
    """One output turn for two crank turns; deltoid_input closes the loop; the motion
    through theta = 0 passes from branch +1 to branch -1."""
    a, b = 0.3, 0.8
    psi = np.linspace(-np.pi, 3 * np.pi, 801)
    theta = deltoid_input(psi, a, b)
    assert np.all(np.diff(theta) > 0) and np.isclose(theta[-1] - theta[0], 8 * np.pi)
    B = np.stack([np.sin(a) * np.cos(theta), np.sin(a) * np.sin(theta), np.full_like(theta, np.cos(a))], -1)
    D = np.array([np.sin(a), 0.0, np.cos(a)])
    t1, t2 = np.array([np.cos(a), 0.0, -np.sin(a)]), np.array([0.0, 1.0, 0.0])
    C = np.cos(b) * D + np.sin(b) * (np.cos(psi)[:, None] * t1 + np.sin(psi)[:, None] * t2)
    assert np.max(np.abs(np.sum(B * C, -1) - np.cos(b))) < 1e-13
    wrap = lambda x: np.angle(np.exp(1j * x))
    th = np.array([1.0, 3.0, 5.0])
    psi_first = deltoid(a, b, branch=1).solve(th).psi
    psi_second = deltoid(a, b, branch=-1).solve(th).psi
    first = np.interp(th, theta, psi)
    second = np.interp(th + TWO_PI, theta, psi)
    assert np.allclose(wrap(psi_first - first), 0, atol=1e-4)
    assert np.allclose(wrap(psi_second - second), 0, atol=1e-4)


def test_spherical_slider_crank_stroke_by_simulation():
    """Stroke and extreme angle from the slider positions of a densely driven crank."""
    for a, b, e in [(0.3, 0.8, 0.1), (0.2, 1.1, -0.3), (0.5, 0.9, 0.0)]:
        r = slider_crank_stroke(a, b, e)
        theta = np.linspace(0.0, TWO_PI, 400001)
        arcs = (a, b, np.pi / 2, np.pi / 2 + e)
        A, B, D, C1, C2, ok = loop_points(arcs, theta)
        F = np.array([np.sin(e), 0.0, np.cos(e)])          # foot of the perpendicular from A
        g = np.array([0.0, -1.0, 0.0])                     # guide direction at F
        spans = [np.arctan2(C @ g, C @ F) for C in (C1, C2)]
        s = max(spans, key=lambda x: np.max(x))            # the branch with the slider ahead
        assert np.isclose(np.max(s), r.s_extended, atol=1e-9)
        assert np.isclose(np.min(s), r.s_folded, atol=1e-9)
        extreme = abs(np.angle(np.exp(1j * (theta[np.argmin(s)] - theta[np.argmax(s)] - np.pi))))
        assert np.isclose(extreme, r.extreme_angle, atol=1e-4)
        assert np.isclose(r.time_ratio, (np.pi + extreme) / (np.pi - extreme), atol=1e-3)


def test_spherical_slider_crank_planar_limit():
    eps = 1e-3
    a, b, e = 2.0, 5.0, 1.0
    planar = SliderCrank(a, b, e)
    r = slider_crank_stroke(eps * a, eps * b, eps * e)
    assert np.isclose(r.stroke / eps, planar.stroke(), rtol=1e-5)
    assert np.isclose(r.extreme_angle, planar.extreme_angle(), rtol=1e-5)
    theta = np.linspace(0.0, TWO_PI, 13)
    psi = spherical_slider_crank(eps * a, eps * b, eps * e).solve(theta).psi
    s = np.mod(psi, TWO_PI) - np.pi
    assert np.allclose(s / eps, planar.solve(theta + np.pi / 2).x, atol=1e-4)


def test_slider_crank_stroke_errors():
    with pytest.raises(ValueError, match="Expected b - a > |e|"):
        slider_crank_stroke(0.5, 0.6, 0.2)
    with pytest.raises(ValueError, match="Expected `e`"):
        spherical_slider_crank(0.3, 0.8, 2.0)
