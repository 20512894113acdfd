"""Tests for ``time_ratio`` and ``extreme_angle`` (eq. 2-9 and its inverse)."""

import mpmath
import numpy as np
import pytest

from mech.planar import extreme_angle, time_ratio


def _stroke_ratio_by_timing(theta):
    """K as the ratio of the two stroke times at unit crank speed, at 50 digits."""
    with mpmath.workdps(50):
        t = mpmath.mpf(float(theta))
        slow, fast = mpmath.pi + t, 2 * mpmath.pi - (mpmath.pi + t)   # the turn splits in two
        return float(slow / fast)


def test_time_ratio_zero_is_one():
    assert time_ratio(0.0) == 1.0
    assert isinstance(time_ratio(0.0), float)


def test_example_2_2_time_ratio():
    """Example 2-2: theta = phi = 60 deg gives K = 2 (eq. 2-9)."""
    assert time_ratio(np.pi / 3) == pytest.approx(2.0, rel=1e-15)
    assert np.degrees(extreme_angle(2.0)) == pytest.approx(60.0, rel=1e-15)


def test_time_ratio_against_stroke_timing():
    rng = np.random.default_rng(1)
    theta = rng.uniform(0.0, 3.0, 200)
    want = np.array([_stroke_ratio_by_timing(t) for t in theta])
    np.testing.assert_allclose(time_ratio(theta), want, rtol=1e-13)


def test_extreme_angle_roundtrip():
    rng = np.random.default_rng(2)
    theta = rng.uniform(0.0, 3.1, 500)
    np.testing.assert_allclose(extreme_angle(time_ratio(theta)), theta, rtol=1e-12, atol=1e-15)
    K = 1.0 + rng.exponential(2.0, 500)
    np.testing.assert_allclose(time_ratio(extreme_angle(K)), K, rtol=1e-12)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_time_ratio_broadcast(shape):
    theta = np.full(shape, 0.5)
    K = time_ratio(theta)
    assert np.shape(K) == shape
    assert np.shape(extreme_angle(K)) == shape


@pytest.mark.parametrize("bad", [-0.1, np.pi, 4.0, [0.2, -1.0]])
def test_time_ratio_rejects_angles_outside_range(bad):
    with pytest.raises(ValueError, match="Expected `extreme_angle` in \\[0, pi\\), got"):
        time_ratio(bad)


def test_extreme_angle_rejects_ratio_below_one():
    with pytest.raises(ValueError, match="Expected `time_ratio` >= 1, got 0.5"):
        extreme_angle(0.5)
    with pytest.raises(ValueError, match="Expected `time_ratio` >= 1"):
        extreme_angle([2.0, 0.9])


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_quick_return_rejects_non_finite(bad):
    with pytest.raises(ValueError, match="Expected finite `time_ratio`"):
        extreme_angle(bad)
    with pytest.raises(ValueError, match="Expected finite `extreme_angle`"):
        time_ratio(bad)
