"""Tests for ``transmission_angle`` and ``min_transmission_angle`` (eq. 2-30, F50-F55).

Expected values come from eq. (2-30) as printed, evaluated with ``mpmath.acos`` at 50
digits, and from dense sweeps of the crank angle.
"""

import mpmath
import numpy as np
import pytest

from mech.planar import grashof
from mech.planar.forces._transmission import min_transmission_angle, transmission_angle


def _gamma_acos(a, b, c, d, theta):
    """Transmission angle from (2-30) with acos at 50 digits; nan where |cos| > 1."""
    with mpmath.workdps(50):
        a, b, c, d, t = (mpmath.mpf(float(v)) for v in (a, b, c, d, theta))
        cos_delta = (b**2 + c**2 - d**2 - a**2 + 2 * a * d * mpmath.cos(t)) / (2 * b * c)
        if abs(cos_delta) > 1:
            return np.nan
        delta = mpmath.acos(cos_delta)
        return float(min(delta, mpmath.pi - delta))


def _random_linkages(n, seed):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        L = rng.uniform(0.2, 3.0, 4)
        if L.max() < L.sum() - L.max():
            out.append(tuple(float(v) for v in L))
    return out


def test_transmission_angle_textbook_check_case():
    """F55 check: (30, 70, 60, 80) gives gamma_min = delta_min = 44.4153 deg at theta = 0."""
    gamma_min, theta_at = min_transmission_angle(30, 70, 60, 80)
    assert np.degrees(gamma_min) == pytest.approx(44.4153, abs=5e-5)
    assert theta_at == 0.0
    assert gamma_min == pytest.approx(_gamma_acos(30, 70, 60, 80, 0.0), rel=1e-14)
    # delta_max = 115.377 deg at theta = pi, so gamma(pi) = 64.623 deg
    assert np.degrees(transmission_angle(30, 70, 60, 80, np.pi)) == pytest.approx(180 - 115.377, abs=5e-4)


def test_example_2_1_min_transmission_angle():
    """Example 2-1, (10, 40, 30, 35): gamma_min at theta = 0, against a dense mpmath sweep."""
    gamma_min, theta_at = min_transmission_angle(10, 40, 30, 35)
    sweep = [_gamma_acos(10, 40, 30, 35, t) for t in np.linspace(-np.pi, np.pi, 2001)]
    assert theta_at == 0.0
    assert gamma_min == pytest.approx(min(sweep), rel=1e-13)   # the grid contains theta = 0


def test_transmission_angle_random_against_acos():
    """Random linkages of every kind and random crank angles, NaN where not assemblable."""
    rng = np.random.default_rng(21)
    n_nan = 0
    for a, b, c, d in _random_linkages(300, seed=22):
        theta = rng.uniform(-np.pi, np.pi, 8)
        got = transmission_angle(a, b, c, d, theta)
        want = np.array([_gamma_acos(a, b, c, d, t) for t in theta])
        np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
        ok = ~np.isnan(want)
        n_nan += int((~ok).sum())
        # acos of (2-30) is ill-conditioned near gamma = 0; compare in the absolute sense there
        tol = 1e-12 * want[ok] + np.where(want[ok] < 1e-3, 1e-9, 1e-15)
        assert np.all(np.abs(got[ok] - want[ok]) <= tol), (a, b, c, d)
    assert n_nan > 0                                          # the NaN path was exercised


def test_transmission_angle_near_dead_centre_keeps_relative_accuracy():
    """(1, 3, 2, 2) has d - a = b - c: gamma -> 0 as theta -> 0, and stays accurate.

    ``arccos`` of the rounded cosine of (2-30) would lose half the digits here; the
    half-angle form keeps full relative accuracy.
    """
    theta = np.array([1e-9, 1e-6, 1e-3, 0.1])
    got = transmission_angle(1, 3, 2, 2, theta)
    want = [_gamma_acos(1, 3, 2, 2, t) for t in theta]
    np.testing.assert_allclose(got, want, rtol=1e-13)
    assert transmission_angle(1, 3, 2, 2, 0.0) == 0.0


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_transmission_angle_broadcast(shape):
    theta = np.full(shape, 0.7)
    got = transmission_angle(10, 40, 30, 35, theta)
    assert np.shape(got) == shape
    assert isinstance(got, float) == (shape == ())
    np.testing.assert_allclose(got, _gamma_acos(10, 40, 30, 35, 0.7), rtol=1e-13)


def test_transmission_angle_is_in_range():
    theta = np.linspace(-np.pi, np.pi, 1001)
    for a, b, c, d in _random_linkages(50, seed=23):
        g = transmission_angle(a, b, c, d, theta)
        g = g[~np.isnan(g)]
        assert np.all((g >= 0.0) & (g <= np.pi / 2))


def test_min_transmission_angle_random_turning_cranks_against_sweep():
    """Crank-rockers and double-cranks: the minimum sits at theta = 0 or pi (F53-F55)."""
    theta = np.linspace(-np.pi, np.pi, 4001)
    count = 0
    for a, b, c, d in _random_linkages(400, seed=24):
        if grashof(a, b, c, d).kind not in ("crank-rocker", "double-crank"):
            continue
        count += 1
        gamma_min, theta_at = min_transmission_angle(a, b, c, d)
        assert theta_at in (0.0, np.pi)
        assert gamma_min == pytest.approx(_gamma_acos(a, b, c, d, theta_at), rel=1e-12, abs=1e-9)
        with np.errstate(invalid="ignore"):          # the reference sweep, NumPy arccos route
            cos_d = (b * b + c * c - d * d - a * a + 2 * a * d * np.cos(theta)) / (2 * b * c)
            delta = np.arccos(np.clip(cos_d, -1, 1))
        sweep = np.minimum(delta, np.pi - delta).min()
        assert gamma_min <= sweep + 1e-9
        assert gamma_min >= sweep - 1e-6
    assert count > 20


def test_min_transmission_angle_non_turning_crank_locks():
    """A crank that cannot turn fully meets a dead centre: gamma_min = 0 there."""
    count = 0
    for a, b, c, d in _random_linkages(200, seed=25):
        if grashof(a, b, c, d).kind in ("crank-rocker", "double-crank"):
            continue
        count += 1
        gamma_min, theta_at = min_transmission_angle(a, b, c, d)
        assert gamma_min == 0.0
        assert 0.0 <= theta_at <= np.pi
        with mpmath.workdps(50):                       # BD at theta_at by the law of cosines
            k = mpmath.sqrt(a * a + d * d - 2 * a * d * mpmath.cos(theta_at))
            gap = min(abs(k - (b + c)), abs(k - abs(b - c)))
        assert float(gap) < 1e-12 * (a + b + c + d)
        # no smaller crank angle in [0, pi] locks: the linkage assembles just below theta_at
        # when it assembles at 0, and fails to assemble everywhere below it otherwise
        below = np.linspace(0.0, theta_at, 50)[:-1]
        if below.size:
            ok = ~np.isnan(transmission_angle(a, b, c, d, below))
            assert ok.all() or not ok.any()
    assert count > 20


def test_transmission_angle_rejects_bad_input():
    with pytest.raises(ValueError, match="Expected `c` > 0, got -1.0"):
        transmission_angle(10, 40, -1, 35, 0.0)
    with pytest.raises(ValueError, match="Expected finite `theta`"):
        transmission_angle(10, 40, 30, 35, [0.0, np.nan])
    with pytest.raises(ValueError, match="Expected `a` > 0, got 0.0"):
        min_transmission_angle(0, 40, 30, 35)
    with pytest.raises(ValueError, match="Expected `d` shorter than the other three links together \\(80.0\\), got 90.0"):
        min_transmission_angle(10, 40, 30, 90)
