"""Tests of the universal joint (2-72) and the double universal joint (F73-F76).

Expected values come from routes the package does not use: the quadrant-correct angle
atan2(sin theta1, cos(alpha) cos theta1) unwrapped in mpmath at 50 digits and
differentiated by ``mpmath.diff``; yoke unit vectors with perpendicular cross arms
(numpy and mpmath); and dense sampling.
"""

import mpmath
import numpy as np
import pytest

from mech.spatial._hooke import (
    DoubleUniversalJoint,
    hooke_acceleration,
    hooke_output,
    hooke_ratio,
)

ALPHAS = (1e-6, 0.1, 0.5, np.radians(45.0), 1.2, 1.5)


def _mp_output(t, alpha):
    """theta3 from tan(theta3) cos(alpha) = tan(theta1), unwrapped to follow theta1."""
    raw = mpmath.atan2(mpmath.sin(t), mpmath.cos(alpha) * mpmath.cos(t))
    return raw + 2 * mpmath.pi * mpmath.nint((t - raw) / (2 * mpmath.pi))


def _rx(lam, lib=np):
    c, s = lib.cos(lam), lib.sin(lam)
    return [[1, 0, 0], [0, c, -s], [0, s, c]]


def _mp_double_output(t, a1, a2, beta, arrangement="Z"):
    """Output angle of a double joint from yoke vectors alone, in mpmath (one branch of atan2)."""
    m = mpmath.matrix
    Ra = m(_rx(-a1, mpmath))
    R3 = Ra * m(_rx(a2 if arrangement == "Z" else -a2, mpmath))
    zC = Ra * m([0, 0, 1])
    z3 = R3 * m([0, 0, 1])
    e_in = m([-mpmath.sin(t), mpmath.cos(t), 0])

    def cross(u, v):
        return m([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]])

    eC1 = cross(e_in, zC)
    eC1 = eC1 / mpmath.norm(eC1)
    dot = sum(zC[i] * eC1[i] for i in range(3))
    eC2 = eC1 * mpmath.cos(beta) + cross(zC, eC1) * mpmath.sin(beta) + zC * dot * (1 - mpmath.cos(beta))
    e_out = R3.T * cross(eC2, z3)
    return mpmath.atan2(e_out[1], e_out[0])


def _np_double_output(t, a1, a2, beta, arrangement="Z"):
    """The same construction in numpy over an array of input angles, unwrapped."""
    Ra = np.array(_rx(-a1))
    R3 = Ra @ np.array(_rx(a2 if arrangement == "Z" else -a2))
    zC, z3 = Ra[:, 2], R3[:, 2]
    e_in = np.stack([-np.sin(t), np.cos(t), np.zeros_like(t)], axis=-1)
    eC1 = np.cross(e_in, zC)
    eC1 /= np.linalg.norm(eC1, axis=-1, keepdims=True)
    eC2 = eC1 * np.cos(beta) + np.cross(zC, eC1) * np.sin(beta) + np.outer(eC1 @ zC, zC) * (1 - np.cos(beta))
    e_out = np.cross(eC2, z3) @ R3
    return np.unwrap(np.arctan2(e_out[:, 1], e_out[:, 0]))


@pytest.mark.parametrize("alpha", ALPHAS)
def test_hooke_output_continuous_through_90_and_270(alpha):
    t = np.linspace(-4 * np.pi, 4 * np.pi, 400_001)
    out = hooke_output(t, alpha)
    step = t[1] - t[0]
    # no jump: every increment is bounded by the largest ratio 1/cos(alpha) times the step
    assert np.max(np.abs(np.diff(out))) <= step / np.cos(alpha) * (1 + 1e-9)
    assert np.all(np.abs(out - t) < np.pi / 2)
    quarter = np.radians([90.0, 270.0, -90.0, 450.0])
    assert np.allclose(hooke_output(quarter, alpha), quarter, rtol=0, atol=1e-15)


@pytest.mark.parametrize("alpha", ALPHAS)
def test_hooke_output_periodicity(alpha):
    t = np.linspace(-10.0, 10.0, 2001)
    np.testing.assert_allclose(hooke_output(t + 2 * np.pi, alpha) - hooke_output(t, alpha),
                               2 * np.pi, rtol=0, atol=4e-15)


def test_hooke_output_matches_mpmath():
    rng = np.random.default_rng(7)
    t = np.concatenate([rng.uniform(-20, 20, 200), np.radians([90.0, 270.0, 180.0, 0.0]) + 1e-9])
    alpha = rng.uniform(0.0, 1.55, t.size)
    got = hooke_output(t, alpha)
    with mpmath.workdps(50):
        want = [float(_mp_output(mpmath.mpf(float(x)), mpmath.mpf(float(a)))) for x, a in zip(t, alpha)]
    np.testing.assert_allclose(got, want, rtol=2e-16 * 8, atol=1e-15)


def test_hooke_ratio_matches_derivative_of_output():
    """Acceptance: the ratio (2-72) equals d theta3 / d theta1 to 1e-12."""
    ts = [-7.0, -np.pi / 2, 0.0, 0.3, np.pi / 2 + 1e-7, 2.0, 3 * np.pi / 2, 9.5]
    for alpha in (0.05, 0.5, 1.0, 1.5):
        got = hooke_ratio(ts, alpha)
        with mpmath.workdps(50):
            a = mpmath.mpf(alpha)
            want = [mpmath.diff(lambda x: _mp_output(x, a), mpmath.mpf(t)) for t in ts]
        np.testing.assert_allclose(got, [float(w) for w in want], rtol=1e-12, atol=0)


def test_hooke_ratio_extremes():
    """Text after (2-72): omega1/cos(alpha) at 0, 180 deg; omega1 cos(alpha) at 90, 270 deg."""
    for alpha in ALPHAS:
        r = hooke_ratio(np.radians([0.0, 180.0, 90.0, 270.0]), alpha)
        np.testing.assert_allclose(r, [1 / np.cos(alpha)] * 2 + [np.cos(alpha)] * 2, rtol=1e-15)
        dense = hooke_ratio(np.linspace(0, 2 * np.pi, 100_001), alpha)
        assert dense.max() <= 1 / np.cos(alpha) * (1 + 1e-15) and dense.min() >= np.cos(alpha) * (1 - 1e-15)


def test_hooke_acceleration_matches_second_derivative():
    ts = [-2.0, 0.2, 0.7853981633974483, 1.4, 2.5, 4.0]
    for alpha in (0.1, 0.6, 1.3):
        omega, epsilon = 3.0, -0.7
        got = hooke_acceleration(ts, alpha, omega=omega, epsilon=epsilon)
        with mpmath.workdps(50):
            a = mpmath.mpf(alpha)
            want = [mpmath.diff(lambda x: _mp_output(x, a), mpmath.mpf(t), 2) * omega**2
                    + mpmath.diff(lambda x: _mp_output(x, a), mpmath.mpf(t)) * epsilon for t in ts]
        np.testing.assert_allclose(got, [float(w) for w in want], rtol=1e-12, atol=1e-13)


def test_hooke_output_yokes_perpendicular():
    """F73: the yoke vectors e4(1) and R_x(-alpha) e4'(3) stay perpendicular."""
    t = np.linspace(-7.0, 7.0, 1001)
    for alpha in ALPHAS:
        th3 = hooke_output(t, alpha)
        e1 = np.stack([-np.sin(t), np.cos(t), np.zeros_like(t)], axis=-1)
        e3 = np.stack([np.cos(th3), np.sin(th3), np.zeros_like(t)], axis=-1) @ np.array(_rx(-alpha)).T
        assert np.max(np.abs(np.sum(e1 * e3, axis=-1))) < 1e-15


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_hooke_broadcast_shapes(shape):
    t = np.full(shape, 0.4)
    for f in (hooke_output, hooke_ratio, hooke_acceleration):
        out = f(t, 0.3)
        assert np.shape(out) == shape
        assert isinstance(out, float) == (shape == ())
    assert np.shape(hooke_ratio(np.zeros((5, 1)), np.array([0.1, 0.2, 0.3]))) == (5, 3)


@pytest.mark.parametrize("arrangement", ["Z", "W"])
@pytest.mark.parametrize("alpha", [0.2, 0.6, 1.2])
def test_double_joint_constant_ratio_when_conditions_hold(alpha, arrangement):
    """F76: equal shaft angles and coplanar yokes on C give i31 == 1, Z or W."""
    t = np.linspace(-2 * np.pi, 2 * np.pi, 4001)
    pose = DoubleUniversalJoint(alpha, alpha).solve(t, order=2, omega=2.0, epsilon=0.5)
    np.testing.assert_allclose(pose.ratio, 1.0, rtol=0, atol=1e-14)
    np.testing.assert_allclose(pose.theta3, t, rtol=0, atol=1e-14)
    np.testing.assert_allclose(pose.epsilon3, 0.5, rtol=0, atol=1e-13)
    by_vectors = _np_double_output(t, alpha, alpha, 0.0, arrangement)
    assert np.ptp(by_vectors - t) < 1e-14
    for phase in (np.pi, -np.pi):    # a half-turn of C's second yoke is the same yoke plane
        np.testing.assert_allclose(DoubleUniversalJoint(alpha, alpha, phase=phase).solve(t, 1).ratio,
                                   1.0, rtol=0, atol=1e-14)


@pytest.mark.parametrize("params", [(0.5, 0.3, 0.0), (0.6, 0.6, 0.2), (0.4, 0.7, -0.5), (1.0, 0.2, 2.0)])
def test_double_joint_output_matches_vectors(params):
    a1, a2, beta = params
    t = np.linspace(0.0, 4 * np.pi, 3001)
    got = DoubleUniversalJoint(a1, a2, phase=beta).solve(t).theta3
    want = _np_double_output(t, a1, a2, beta)
    np.testing.assert_allclose(got - got[0], want - want[0], rtol=0, atol=1e-13)


@pytest.mark.parametrize("params", [(0.5, 0.3, 0.0), (0.6, 0.6, 0.2), (0.4, 0.7, -0.5)])
def test_double_joint_rates_match_mpmath_derivatives(params):
    a1, a2, beta = params
    ts = [-1.0, 0.0, 0.8, 1.5707963267948966, 3.0]
    omega, epsilon = 1.5, 0.3
    pose = DoubleUniversalJoint(a1, a2, phase=beta).solve(ts, order=2, omega=omega, epsilon=epsilon)
    with mpmath.workdps(50):
        args = [mpmath.mpf(a1), mpmath.mpf(a2), mpmath.mpf(beta)]
        d1 = [mpmath.diff(lambda x: _mp_double_output(x, *args), mpmath.mpf(t)) for t in ts]
        d2 = [mpmath.diff(lambda x: _mp_double_output(x, *args), mpmath.mpf(t), 2) for t in ts]
    d1 = np.array([float(v) for v in d1])
    d2 = np.array([float(v) for v in d2])
    np.testing.assert_allclose(pose.ratio, d1, rtol=1e-12)
    np.testing.assert_allclose(pose.omega3, d1 * omega, rtol=1e-12)
    np.testing.assert_allclose(pose.epsilon3, d2 * omega**2 + d1 * epsilon, rtol=1e-12, atol=1e-13)


def test_double_joint_ratio_range_matches_dense_sampling():
    t = np.linspace(0.0, np.pi, 200_001)
    for a1, a2, beta in [(0.5, 0.3, 0.0), (0.6, 0.6, 0.2), (0.4, 0.7, -0.5), (1.2, 0.1, 1.0), (0.3, 0.3, np.pi / 2)]:
        joint = DoubleUniversalJoint(a1, a2, phase=beta)
        lo, hi = joint.ratio_range()
        r = joint.solve(t, order=1).ratio
        assert lo <= r.min() + 1e-15 and r.max() <= hi + 1e-15
        assert abs(r.min() - lo) < 1e-9 and abs(r.max() - hi) < 1e-9


def test_double_joint_fluctuation_when_conditions_violated():
    """Closed forms of the derivation: mismatch |m - 1/m|, crossed yokes tan^2(a)(1 + cos^2(a))."""
    a1, a2 = np.radians(30.0), np.radians(25.0)
    lo, hi = DoubleUniversalJoint(a1, a2).ratio_range()
    m = np.cos(a2) / np.cos(a1)
    assert abs((hi - lo) - abs(m - 1 / m)) < 1e-15
    a = np.radians(30.0)
    lo, hi = DoubleUniversalJoint(a, a, phase=np.pi / 2).ratio_range()
    assert abs((hi - lo) - np.tan(a) ** 2 * (1 + np.cos(a) ** 2)) < 1e-14
    assert abs(hi / lo - 1 / np.cos(a) ** 4) < 1e-13
    lo, hi = DoubleUniversalJoint(a, a, phase=1e-4).ratio_range()   # small phase error
    assert abs((hi - lo) / (2e-4 * np.sin(a) * np.tan(a)) - 1) < 1e-4
    lo, hi = DoubleUniversalJoint(a, a).ratio_range()
    assert abs(hi - 1) < 1e-15 and abs(lo - 1) < 1e-15


def test_hooke_bad_input_errors():
    with pytest.raises(ValueError, match=r"Expected `alpha` in \[0, pi/2\)"):
        hooke_output(0.3, np.pi / 2)
    with pytest.raises(ValueError, match="Expected `alpha`"):
        hooke_ratio(0.3, [0.1, -0.2])
    with pytest.raises(ValueError, match="Expected finite `theta1`"):
        hooke_ratio([0.1, np.nan], 0.3)
    with pytest.raises(ValueError, match="Expected finite `omega`"):
        hooke_acceleration(0.1, 0.3, omega=np.inf)
    with pytest.raises(ValueError, match="Expected `alpha2`"):
        DoubleUniversalJoint(0.3, 2.0)
    with pytest.raises(ValueError, match="Expected finite `phase`"):
        DoubleUniversalJoint(0.3, 0.3, phase=np.nan)
    with pytest.raises(ValueError, match="Expected `order`"):
        DoubleUniversalJoint(0.3, 0.3).solve(0.1, order=3)
    with pytest.raises(ValueError, match="Expected `alpha1` to be a real number"):
        DoubleUniversalJoint("x", 0.3)
