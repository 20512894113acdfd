"""Hostile inputs to the planar synthesis functions (issue 24): a task scaled to the ends of
the float range gives the same design scaled, with no warning; degenerate designs and
arguments of the wrong shape are refused by name."""

import warnings

import numpy as np
import pytest

import mech.planar.synthesis as sy

# example 2-21's drawn four-bar and its points
P21 = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
B21, C21, D21 = -95.524 + 80.407j, 76.791 + 170.535j, 174.194 + 18.575j


@pytest.mark.parametrize("scale", [1e-300, 1e-200, 1e200, 1e300])
def test_path_design_scales(scale):
    ref = sy.path_design(0j, B21, C21, D21, P21)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = sy.path_design(0j, B21 * scale, C21 * scale, D21 * scale, P21 * scale)
    # the coupler rotations are angles: independent of the unit
    assert np.allclose(got.coupler_rotation, ref.coupler_rotation, rtol=0, atol=1e-12)
    assert got.linkage.a / scale == pytest.approx(ref.linkage.a, rel=1e-12)
    assert got.passes == ref.passes


def test_path_design_one_pivot_far_beyond_the_task_is_quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            sy.path_design(0j, B21 * 1e200, C21, D21, P21)
        except ValueError as e:
            assert "four-bar" in str(e)


@pytest.mark.parametrize("k", range(4))
def test_path_residuals_coincident_pivots_named(k):
    design = np.array([0j, B21, C21, D21, P21[0]])
    design[(k + 1) % 4] = design[k]
    with pytest.raises(ValueError, match="`design`"):
        sy.path_residuals(design, P21[:2], [0.0, 0.5])


def test_path_residuals_all_zero_design_named():
    with pytest.raises(ValueError, match="`design`"):
        sy.path_residuals(np.zeros(5), P21[:2], [0.0, 0.5])


def test_path_untimed_guess_far_beyond_the_task_is_quiet():
    points = P21 * 1e-200
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            out = sy.path_untimed(points[:5], A=0j, D=D21, initial=[[0j, B21, C21, D21]], starts=1, max_steps=5)
        except ValueError:
            return
    assert all(np.all(np.isfinite(c.points)) for c in out.candidates)


@pytest.mark.parametrize("bad", [[], [0.1], [[0.1], [0.4]], [0.1, 0.2, 0.3]])
def test_steering_arm_range_shape_named(bad):
    with pytest.raises(ValueError, match="`arm_range`"):
        sy.steering_trapezoid_model(arm_range=bad)
