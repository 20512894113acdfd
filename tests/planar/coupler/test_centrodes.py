"""Tests of the four-bar coupler centrodes against the analytic velocities of `FourBar`.

P24 comes from the generated line intersection; it is checked by its defining property
(the coupler's velocity there is zero, rates from the loop derivatives), against the
general Kennedy construction, and by the rolling condition of the two centrodes.
"""

import numpy as np
import pytest

from mech.planar import FourBar
from mech.planar.coupler._centrodes import coupler_centrodes
from mech.planar.kinematics._instant_centres import instant_centres


@pytest.mark.parametrize("lengths, branch", [((10, 40, 30, 35), 1), ((10, 40, 30, 35), -1),
                                             ((2, 3, 2.5, 4), 1), ((1.0, 2.2, 1.7, 2.0), -1)])
def test_coupler_centrodes_pole_has_zero_velocity(lengths, branch):
    linkage = FourBar(*lengths, branch=branch)
    theta = np.linspace(-np.pi, np.pi, 721)
    cen = coupler_centrodes(linkage, theta)
    pose = linkage.solve(theta, order=1, omega=1.0)
    ok = cen.valid & ~cen.at_infinity
    assert ok.sum() > 100
    v = pose.vB[ok] + 1j * pose.omega_coupler[ok] * (cen.fixed[ok] - pose.B[ok])
    size = sum(lengths)
    scale = np.abs(pose.vB[ok]) + np.abs(pose.omega_coupler[ok]) * (np.abs(cen.fixed[ok]) + size)
    # near AB || DC the pole runs off: its rounding error grows like |P24|^2 / size
    assert np.all(np.abs(v) <= 1e-13 * scale * (1 + np.abs(cen.fixed[ok]) / size))


def test_coupler_centrodes_match_kennedy():
    linkage = FourBar(10, 40, 30, 35)
    theta = np.linspace(0.05, 6.2, 50)
    cen = coupler_centrodes(linkage, theta)
    pose = linkage.solve(theta)
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): 35.0})
    np.testing.assert_allclose(cen.fixed, centres[2, 4].point, rtol=1e-12)


def test_coupler_centrodes_moving_is_pole_in_coupler_frame():
    linkage = FourBar(10, 40, 30, 35, branch=-1)
    theta = np.linspace(0.0, 2 * np.pi, 91)
    cen = coupler_centrodes(linkage, theta)
    pose = linkage.solve(theta)
    want = (cen.fixed - pose.B) * np.exp(-1j * pose.phi)
    np.testing.assert_allclose(cen.moving, want, rtol=1e-12, atol=1e-12)
    for k in (0, 30, 60):
        assert cen.moving_placed(k)[k] == pytest.approx(cen.fixed[k], abs=1e-11)


def test_coupler_centrodes_roll_without_slipping():
    """The pole moves with equal speed along both centrodes (pure rolling)."""
    linkage = FourBar(10, 40, 30, 35)
    theta = np.linspace(0.1, 6.1, 41)
    h = 1e-5
    plus, minus = coupler_centrodes(linkage, theta + h), coupler_centrodes(linkage, theta - h)
    mid = coupler_centrodes(linkage, theta)
    ok = np.abs(mid.fixed) < 500
    speed_fixed = np.abs(plus.fixed - minus.fixed)[ok] / (2 * h)
    speed_moving = np.abs(plus.moving - minus.moving)[ok] / (2 * h)
    np.testing.assert_allclose(speed_fixed, speed_moving, rtol=1e-6)
    assert ok.sum() > 30


def test_coupler_centrodes_parallelogram_at_infinity_without_warnings():
    """AB stays parallel to DC: the coupler translates, P24 is always at infinity."""
    cen = coupler_centrodes(FourBar(1.0, 3.0, 1.0, 3.0), np.linspace(0.1, 3.0, 11))
    assert np.all(cen.at_infinity) and np.all(np.isnan(cen.fixed))
    assert cen.segments(100.0) == []


def test_coupler_centrodes_segments_split_at_infinity():
    linkage = FourBar(10, 40, 30, 35)
    theta = np.linspace(0.0, 2 * np.pi, 721)
    cen = coupler_centrodes(linkage, theta)
    W = cen.homogeneous[..., 2]
    crossings = int(np.sum(np.sign(W[1:]) != np.sign(W[:-1])))
    assert crossings == 2                        # AB parallel to DC twice per turn
    pieces = cen.segments(1000.0)
    assert len(pieces) == 3
    for piece in pieces:
        assert np.all(np.abs(piece.fixed) <= 1000.0)
        assert np.all(np.diff(piece.theta) > 0)


def test_coupler_centrodes_errors():
    with pytest.raises(ValueError, match="finite `theta`"):
        coupler_centrodes(FourBar(10, 40, 30, 35), [0.0, np.inf])
    with pytest.raises(ValueError, match="`limit` > 0"):
        coupler_centrodes(FourBar(10, 40, 30, 35), [0.0, 1.0]).segments(-1.0)
