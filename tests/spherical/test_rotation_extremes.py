"""Axes and points of any finite non-zero size (1e-300 .. 1e300) on the sphere (issue 11, item 3).

The oracle is Rodrigues' formula evaluated in mpmath at 50 digits on the axis normalised
there; the other checks compare a scaled vector with the same direction given at unit size.
"""

import mpmath
import numpy as np
import pytest

from mech import spherical

EPS = np.finfo(float).eps
SCALES = [1e-300, 1e-200, 1e-163, 1e-160, 1e-100, 1e-8, 1.0, 1e8, 1e100, 1e160, 1e200, 1e300]
DIRECTIONS = [(0.0, 0.0, 1.0), (1.0, 2.0, 3.0), (-0.3, 1e-5, 0.7), (5e-17, -1.0, 2e-17)]


def _rodrigues_mp(axis, angle):
    """The rotation matrix at 50 digits, the axis normalised in mpmath."""
    with mpmath.workdps(50):
        k = mpmath.matrix([mpmath.mpf(float(x)) for x in axis])
        k = k / mpmath.norm(k)
        K = mpmath.matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        g = mpmath.mpf(float(angle))
        R = mpmath.eye(3) + mpmath.sin(g) * K + (1 - mpmath.cos(g)) * K * K
        return np.array([[float(R[i, j]) for j in range(3)] for i in range(3)])


@pytest.mark.parametrize("scale", SCALES)
@pytest.mark.parametrize("direction", DIRECTIONS)
def test_rotation_matrix_axis_any_size(scale, direction):
    axis = np.array(direction) * scale
    for angle in (0.5, -2.9, 1e-9, np.pi):
        R = spherical.rotation_matrix(axis, angle)
        assert np.max(np.abs(R.T @ R - np.eye(3))) <= 1e-15
        assert abs(np.linalg.det(R) - 1.0) <= 1e-15
        assert np.max(np.abs(R - _rodrigues_mp(axis, angle))) <= 1e-15


def test_rotation_matrix_issue_example():
    R = spherical.rotation_matrix([0, 0, 1e300], 0.5)
    want = np.array([[np.cos(0.5), -np.sin(0.5), 0], [np.sin(0.5), np.cos(0.5), 0], [0, 0, 1]])
    assert np.max(np.abs(R - want)) <= 1e-16


def test_rotation_matrix_subnormal_axis():
    R = spherical.rotation_matrix([0.0, 5e-324, 0.0], 1.0)
    assert np.max(np.abs(R - _rodrigues_mp([0, 1, 0], 1.0))) <= 1e-15


def test_rotation_matrix_zero_axis_rejected():
    with pytest.raises(ValueError, match="Expected non-zero vectors in `axis`"):
        spherical.rotation_matrix([0.0, 0.0, 0.0], 0.5)
    with pytest.raises(ValueError, match="`axis`"):
        spherical.rotation_matrix([[0, 0, 1], [0.0, -0.0, 0.0]], 0.5)


@pytest.mark.parametrize("scale", SCALES)
def test_vector_functions_scale_free(scale):
    """Every function that takes points gives the result of the unit-size input."""
    p = np.array([1.0, 2.0, 3.0])
    q = np.array([-0.5, 0.25, 2.0])
    r = np.array([0.3, -1.0, 0.2])
    unit = [x / np.linalg.norm(x) for x in (p, q, r)]
    big = [x * scale for x in (p, q, r)]
    tol = 1e-15          # a few units of rounding of results up to pi
    np.testing.assert_allclose(spherical.to_xyz(*spherical.from_xyz(big[0])), unit[0], rtol=0, atol=tol)
    for f in (spherical.distance, spherical.tangent, spherical.inclination):
        np.testing.assert_allclose(f(big[0], big[1]), f(unit[0], unit[1]), rtol=0, atol=tol)
    for got, want in zip(spherical.local_frame(big[0]), spherical.local_frame(unit[0])):
        np.testing.assert_allclose(got, want, rtol=0, atol=tol)
    np.testing.assert_allclose(spherical.rotate_about(big[0], big[1], 0.7),
                               spherical.rotate_about(unit[0], unit[1], 0.7), rtol=0, atol=tol)
    np.testing.assert_allclose(spherical.great_circle_through(big[0], big[1]).pole,
                               spherical.great_circle_through(unit[0], unit[1]).pole, rtol=0, atol=tol)
    np.testing.assert_allclose(spherical.bisector(big[0], big[1]).pole,
                               spherical.bisector(unit[0], unit[1]).pole, rtol=0, atol=tol)
    got, want = spherical.circle_through(*big), spherical.circle_through(*unit)
    np.testing.assert_allclose(got.pole, want.pole, rtol=0, atol=tol)
    np.testing.assert_allclose(got.radius, want.radius, rtol=0, atol=tol)
    np.testing.assert_allclose(spherical.intersect(big[0], big[1]).point,
                               spherical.intersect(unit[0], unit[1]).point, rtol=0, atol=tol)
    np.testing.assert_allclose(spherical.distance_to_great_circle(big[2], big[0]),
                               spherical.distance_to_great_circle(unit[2], unit[0]), rtol=0, atol=tol)
    got = spherical.close_polygon(np.array(big))
    want = spherical.close_polygon(np.array(unit))
    np.testing.assert_allclose(got.arcs, want.arcs, rtol=0, atol=tol)
    np.testing.assert_allclose(got.angles, want.angles, rtol=0, atol=tol)


@pytest.mark.parametrize("scale", [1e-300, 1e300])
def test_vectors_unit_results(scale):
    """Unit output for points given far from unit size, in every row of a batch."""
    rng = np.random.default_rng(11)
    v = rng.normal(size=(200, 3)) * scale
    x = spherical.to_xyz(*spherical.from_xyz(v))
    assert np.max(np.abs(np.sum(x * x, axis=-1) - 1.0)) <= 4 * EPS
    ex, ey = spherical.local_frame(v)
    assert np.max(np.abs(np.sum(ex * ex, axis=-1) - 1.0)) <= 4 * EPS
    assert np.max(np.abs(np.sum(ex * ey, axis=-1))) <= 4 * EPS
