"""Coupler-curve atlas dashes (Fig. 2-30, F25): ``mech.planar.coupler._atlas``.

Expected points come from a plain circle intersection (law of cosines with arccos, a
different formula from the package's atan2 form); arc lengths from a 20 000-step sweep.
"""

import numpy as np
import pytest

from mech.planar.coupler._atlas import CouplerDashes, coupler_dashes


def _points_by_circles(a, b, c, d, w, theta, branch=1):
    B = a * np.exp(1j * theta)
    k = np.abs(d - B)
    with np.errstate(invalid="ignore"):
        gamma = np.arccos((b**2 + k**2 - c**2) / (2 * b * k))     # angle at B of triangle BCD
    C = B + b * (d - B) / k * np.exp(1j * branch * gamma)
    return B + w * (C - B) / b


def test_coupler_dashes_fig_2_30_seventy_two_steps_of_five_degrees():
    dashes = coupler_dashes(1, 2, 2.5, 3, [0.5 + 0.5j, 1.5 - 0.5j])
    assert isinstance(dashes, CouplerDashes)
    assert dashes.points.shape == (2, 73) and dashes.length.shape == (2, 72)
    assert np.allclose(np.degrees(np.diff(dashes.theta)), 5.0, rtol=0, atol=1e-12)
    assert np.allclose(dashes.points[:, 0], dashes.points[:, -1], rtol=0, atol=1e-12)
    for i, w in enumerate([0.5 + 0.5j, 1.5 - 0.5j]):
        ref = _points_by_circles(1.0, 2.0, 2.5, 3.0, w, dashes.theta)
        assert np.abs(dashes.points[i] - ref).max() < 1e-11


def test_coupler_dashes_total_length_approximates_arc():
    """72 chords add up to the curve length within the chord error (< 0.5 % here)."""
    w = 1.0 + 1.0j
    dashes = coupler_dashes(1, 2, 2.5, 3, w)
    fine = _points_by_circles(1.0, 2.0, 2.5, 3.0, w, np.linspace(0, 2 * np.pi, 20001))
    arc = np.abs(np.diff(fine)).sum()
    total = dashes.length.sum()
    assert total < arc and (arc - total) / arc < 5e-3
    # the mean speed is length over the 5-degree step
    assert np.allclose(dashes.mean_speed, dashes.length / np.radians(5.0), rtol=1e-14)


def test_coupler_dashes_speed_shows_as_spacing():
    """Longest dash is where the point is fast: ratio of longest to shortest dash > 3 here."""
    dashes = coupler_dashes(1, 2, 2.5, 3, 1.0 + 1.0j)
    assert dashes.length.max() / dashes.length.min() > 3


def test_coupler_dashes_non_grashof_marks_invalid_steps():
    dashes = coupler_dashes(2.2, 1.3, 2.5, 1.9, 0.5 + 0.5j)            # triple-rocker
    assert 0 < dashes.valid.sum() < 72
    assert np.all(np.isnan(dashes.length[~dashes.valid]))
    assert np.all(np.isfinite(dashes.length[dashes.valid]))


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_coupler_dashes_lattice_shapes(shape):
    w = np.full(shape, 0.5 + 0.25j)
    dashes = coupler_dashes(1, 2, 2.5, 3, w, n=36)
    assert dashes.points.shape == shape + (37,)
    assert dashes.length.shape == shape + (36,)


def test_coupler_dashes_errors():
    with pytest.raises(ValueError, match="Expected `b` > 0"):
        coupler_dashes(1, -2, 2.5, 3, 0j)
    with pytest.raises(ValueError, match="Expected `n` to be an integer in \\[3, 10000000\\]"):
        coupler_dashes(1, 2, 2.5, 3, 0j, n=2)
    with pytest.raises(ValueError, match="Expected finite `coupler`"):
        coupler_dashes(1, 2, 2.5, 3, [0j, np.nan])
    with pytest.raises(ValueError, match="Expected `branch`"):
        coupler_dashes(1, 2, 2.5, 3, 0j, branch=2)
