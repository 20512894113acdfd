"""Tests for ``limit_positions`` (Example 2-1, Figs 2-37 and 2-38).

Expected values come from two independent routes: a brute-force simulation of the linkage
(dense sweep of the crank angle, refined by mpmath root finding of the crank-coupler cross
product) and the law of cosines with ``mpmath.acos`` at 50 digits.
"""

import math

import mpmath
import numpy as np
import pytest

from mech.planar import grashof
from mech.planar.structure._limit_positions import LimitPositions, limit_positions

TWO_PI = 2 * np.pi


def _wrap(x):
    """Angle difference wrapped to (-pi, pi]."""
    return (x + np.pi) % TWO_PI - np.pi


def _random_crank_rockers(n, seed, margin=0.02):
    """Crank-rockers with all Grashof slacks at least margin * (a + b + c + d)."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        a = rng.uniform(0.05, 1.0)
        b, c, d = rng.uniform(0.3, 3.0, 3)
        total = a + b + c + d
        if min(b, c, d) <= a or min(c + d - a - b, b + d - a - c, b + c - a - d) < margin * total:
            continue
        assert grashof(a, b, c, d).kind == "crank-rocker"
        out.append((a, b, c, d))
    return out


def _mp_pose(a, b, c, d, branch, t):
    """B, C at crank angle t by intersecting two circles (mpmath, current precision)."""
    B = a * mpmath.expj(t)
    BD = d - B
    k = abs(BD)
    angle_B = mpmath.acos((b**2 + k**2 - c**2) / (2 * b * k))
    return B, B + b * BD / k * mpmath.expj(branch * angle_B)


def _simulated_limits(a, b, c, d, branch, n=721):
    """(theta_ext, theta_fold, psi_ext, psi_fold) by sweep + mpmath root refinement."""
    t = np.linspace(-np.pi, np.pi, n)
    B = a * np.exp(1j * t)
    BD = d - B
    k = np.abs(BD)
    cos_b = np.clip((b * b + k * k - c * c) / (2 * b * k), -1.0, 1.0)
    C = B + b * BD / k * np.exp(1j * branch * np.arccos(cos_b))
    g = np.imag(np.conj(B) * (C - B))          # crank x coupler: zero at a limit
    brackets = np.nonzero(np.sign(g[:-1]) != np.sign(g[1:]))[0]
    assert len(brackets) == 2
    found = {}
    with mpmath.workdps(40):
        am, bm, cm, dm = (mpmath.mpf(v) for v in (a, b, c, d))

        def cross(x):
            Bx, Cx = _mp_pose(am, bm, cm, dm, branch, x)
            return mpmath.im(mpmath.conj(Bx) * (Cx - Bx))

        for i in brackets:
            root = mpmath.findroot(cross, (mpmath.mpf(t[i]), mpmath.mpf(t[i + 1])), solver="anderson")
            Bx, Cx = _mp_pose(am, bm, cm, dm, branch, root)
            kind = "ext" if mpmath.re(mpmath.conj(Bx) * (Cx - Bx)) > 0 else "fold"
            found[kind] = (float(root), float(mpmath.arg(Cx - dm)))
    return found["ext"][0], found["fold"][0], found["ext"][1], found["fold"][1]


def _acos_reference(a, b, c, d):
    """Branch +1 limits, swing and signed extreme angle by the law of cosines, 50 digits."""
    with mpmath.workdps(50):
        a, b, c, d = (mpmath.mpf(v) for v in (a, b, c, d))
        alpha = lambda r: mpmath.acos((r**2 + d**2 - c**2) / (2 * r * d))
        beta = lambda r: mpmath.acos((c**2 + d**2 - r**2) / (2 * c * d))
        ae, af, be, bf = alpha(b + a), alpha(b - a), beta(b + a), beta(b - a)
        return [float(v) for v in (ae, af - mpmath.pi, mpmath.pi - be, mpmath.pi - bf, be - bf, af - ae)]


def test_example_2_1_limit_positions():
    """Example 2-1, (10, 40, 30, 35): Fig. 2-37 gives the swing, theta and K of eq. (2-9).

    The text leaves them to a drawing; the values are those recomputed independently by a
    720 001-point simulation (swing 45.9719 deg, theta 18.1324 deg, K 1.22404, rocker range
    [79.7134, 125.685] deg).
    """
    for branch in (1, -1):
        lp = limit_positions(10, 40, 30, 35, branch=branch)
        assert np.degrees(lp.swing) == pytest.approx(45.9719, abs=5e-5)
        assert np.degrees(lp.extreme_angle) == pytest.approx(18.1324, abs=5e-5)
        assert lp.time_ratio == pytest.approx(1.22404, abs=5e-6)
        assert branch * np.degrees(lp.psi_extended) == pytest.approx(79.7134, abs=5e-5)
        assert branch * np.degrees(lp.psi_folded) == pytest.approx(125.685, abs=5e-4)
        assert branch * np.degrees(lp.theta_extended) == pytest.approx(36.1823, abs=5e-5)
        assert np.degrees(np.pi + branch * lp.theta_folded) == pytest.approx(54.3147, abs=5e-5)


def test_example_2_1_limit_positions_against_simulation():
    for branch in (1, -1):
        lp = limit_positions(10, 40, 30, 35, branch=branch)
        sim = _simulated_limits(10.0, 40.0, 30.0, 35.0, branch)
        got = (lp.theta_extended, lp.theta_folded, lp.psi_extended, lp.psi_folded)
        assert np.max(np.abs(_wrap(np.subtract(got, sim)))) < 1e-13


def test_limit_positions_returns_frozen_record():
    lp = limit_positions(10, 40, 30, 35)
    assert isinstance(lp, LimitPositions)
    with pytest.raises(AttributeError):
        lp.swing = 0.0


@pytest.mark.slow
def test_limit_positions_random_crank_rockers_against_simulation():
    """500 random crank-rockers, both branches: limits, swing, theta and K by simulation."""
    worst = 0.0
    for a, b, c, d in _random_crank_rockers(500, seed=11):
        for branch in (1, -1):
            lp = limit_positions(a, b, c, d, branch=branch)
            te, tf, pe, pf = _simulated_limits(a, b, c, d, branch)
            got = np.array([lp.theta_extended, lp.theta_folded, lp.psi_extended, lp.psi_folded])
            err = np.abs(_wrap(got - [te, tf, pe, pf]))
            worst = max(worst, err.max())
            assert np.all(err <= 1e-10 * np.maximum(1.0, np.abs(got))), (a, b, c, d, branch)
            # swing, extreme angle and K from the simulated stops
            assert lp.swing == pytest.approx(abs(_wrap(pf - pe)), rel=1e-10)
            crank_turn = (tf - te) % TWO_PI                  # the crank from one stop to the other
            slow, fast = max(crank_turn, TWO_PI - crank_turn), min(crank_turn, TWO_PI - crank_turn)
            assert lp.extreme_angle == pytest.approx(slow - np.pi, rel=1e-9, abs=1e-12)
            assert lp.time_ratio == pytest.approx(slow / fast, rel=1e-10)
    assert worst < 1e-12


def test_limit_positions_random_crank_rockers_against_law_of_cosines():
    """500 random crank-rockers: every output against acos at 50 digits (another formula)."""
    for a, b, c, d in _random_crank_rockers(500, seed=12):
        ref = _acos_reference(a, b, c, d)
        for branch in (1, -1):
            lp = limit_positions(a, b, c, d, branch=branch)
            got = [lp.theta_extended, lp.theta_folded, lp.psi_extended, lp.psi_folded]
            np.testing.assert_allclose(got, np.multiply(branch, ref[:4]), rtol=1e-13, atol=1e-14)
            assert lp.swing == pytest.approx(ref[4], rel=1e-13)
            assert lp.extreme_angle == pytest.approx(abs(ref[5]), rel=1e-12, abs=1e-15)


def test_limit_positions_negative_signed_extreme_angle():
    """a^2 + d^2 > b^2 + c^2: the slow stroke runs the other way; theta is still >= 0."""
    a, b, c, d = 1.0, 2.0, 2.2, 3.0
    ref = _acos_reference(a, b, c, d)
    assert ref[5] < 0
    lp = limit_positions(a, b, c, d)
    assert lp.extreme_angle == pytest.approx(-ref[5], rel=1e-13)
    te, tf, _, _ = _simulated_limits(a, b, c, d, 1)
    assert (tf - te) % TWO_PI == pytest.approx(np.pi - lp.extreme_angle, rel=1e-12)


def test_limit_positions_obtuse_extreme_angle_near_change_point():
    """Near a + c = b + d the angle between the crank stops exceeds 90 degrees."""
    a, b, c, d = 1.0, 1.01, 5.0, 4.99 + 1e-6      # a + c - b - d = -1e-6
    lp = limit_positions(a, b, c, d)
    assert lp.extreme_angle > np.pi / 2
    te, tf, _, _ = _simulated_limits(a, b, c, d, 1, n=20_001)
    crank_turn = (tf - te) % TWO_PI
    assert lp.extreme_angle == pytest.approx(max(crank_turn, TWO_PI - crank_turn) - np.pi, rel=1e-7)


@pytest.mark.parametrize("a", [1e-3, 1e-6, 1e-9])
def test_limit_positions_short_crank_keeps_relative_accuracy(a):
    """Swing and extreme angle shrink with the crank; no digits are lost to subtraction."""
    b, c, d = 4.0, 3.0, 3.5
    ref = _acos_reference(a, b, c, d)
    lp = limit_positions(a, b, c, d)
    assert lp.swing == pytest.approx(ref[4], rel=1e-13)
    assert lp.extreme_angle == pytest.approx(abs(ref[5]), rel=1e-12)
    assert lp.time_ratio - 1.0 == pytest.approx(2 * abs(ref[5]) / (np.pi - abs(ref[5])), rel=1e-6)


@pytest.mark.parametrize(
    "lengths, shared",
    [((10, 40, 30, 20), "psi_extended"), ((10, 30, 40, 20), "psi_folded"), ((10, 30, 20, 40), "psi_folded")],
)
def test_limit_positions_change_point_branches_meet(lengths, shared):
    """Fig. 2-38: at a change point both assembly modes share one limit position."""
    assert grashof(*lengths).change_point
    up, down = (limit_positions(*lengths, branch=s) for s in (1, -1))
    assert abs(_wrap(getattr(up, shared) - getattr(down, shared))) < 1e-7
    assert up.swing == pytest.approx(_acos_reference(*lengths)[4], rel=1e-12)


@pytest.mark.parametrize("lengths", [(40, 20, 30, 35), (35, 40, 30, 10), (30, 40, 20, 35)])
def test_limit_positions_rejects_other_kinds(lengths):
    with pytest.raises(ValueError, match="Expected `a`, `b`, `c` and `d` of a crank-rocker, got a"):
        limit_positions(*lengths)


def test_limit_positions_rejects_bad_input():
    with pytest.raises(ValueError, match="Expected `b` > 0, got -1.0"):
        limit_positions(10, -1, 30, 35)
    with pytest.raises(ValueError, match="Expected `branch` to be \\+1 or -1"):
        limit_positions(10, 40, 30, 35, branch=0)
    with pytest.raises(ValueError, match="Expected `d` shorter than the other three links together \\(80.0\\), got 90.0"):
        limit_positions(10, 40, 30, 90)


def test_line_669_designs_without_quick_return():
    """Errata row 78 (§2.2, part II): the sentence names a crank-rocker with K = 1 (Fig
    2-100) and the centric slider-crank (Fig 2-22) as designs without quick return, and says
    an oscillating guide-bar always has K > 1. A crank-rocker has K = 1 exactly when A lies on
    the line of its two limit positions C1C2, that is when the power of A with respect to the
    rocker circle, AC1 * AC2 = (b + a)(b - a), equals d^2 - c^2: a^2 + d^2 = b^2 + c^2."""
    from mech.planar import GuideBar, SliderCrank

    rng = np.random.default_rng(669)
    checked = 0
    for _ in range(200):
        a, c, d = 10.0, rng.uniform(20, 60), rng.uniform(20, 60)
        b2 = a * a + d * d - c * c
        if b2 <= 0:
            continue
        b = math.sqrt(b2)
        if grashof(a, b, c, d).kind != "crank-rocker":
            continue
        lp = limit_positions(a, b, c, d)
        assert lp.time_ratio == pytest.approx(1.0, abs=1e-12)
        assert lp.extreme_angle == pytest.approx(0.0, abs=1e-12)
        checked += 1
    assert checked > 20
    assert limit_positions(10, 40, 30, 35).time_ratio > 1.2          # example 2-1: a^2 + d^2 != b^2 + c^2
    assert SliderCrank(30.0, 100.0).time_ratio() == pytest.approx(1.0, abs=1e-15)
    for a, d in rng.uniform(1, 100, (50, 2)):
        a, d = min(a, d) * 0.99, max(a, d)
        assert GuideBar(a, d).time_ratio() > 1.0
