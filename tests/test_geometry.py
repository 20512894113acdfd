"""The shared helpers of `mech._geometry` and the shared checks of `mech._validate`.

Each helper replaced several copies that differed in form; these tests pin the one
contract every caller now relies on, against mpmath at 50 digits by another route
(angles from atan2 of exact products, lengths from the square root of exact sums).
"""

import mpmath
import numpy as np
import pytest

from mech._geometry import (acute_angle, acute_angle_from_cosine, cross3, cross_components, plane_cross,
                            unit_rows, wrap_angle)
from mech._validate import proper_rotation, unit_vector

mpmath.mp.dps = 50
PI = float(mpmath.pi)


def _wrap_reference(x):
    """(-pi, pi] by subtracting whole turns in 50-digit arithmetic."""
    v = mpmath.mpf(x)
    turns = mpmath.ceil((v - mpmath.pi) / (2 * mpmath.pi))
    return float(v - 2 * mpmath.pi * turns)


@pytest.mark.parametrize("x", [0.0, 1.0, -1.0, 3.0, -3.0, 3 * PI / 2, -3 * PI / 2, 7.5, -7.5, 100.0, -1e3])
def test_wrap_angle_matches_whole_turns_removed(x):
    got = float(wrap_angle(x))
    assert -PI < got <= PI
    assert abs(got - _wrap_reference(x)) <= 4e-16 * max(1.0, abs(x))


def test_wrap_angle_ends_of_the_range():
    # the float np.pi is just below pi and -np.pi just above -pi: both are in (-pi, pi]
    assert float(wrap_angle(np.pi)) == np.pi
    assert float(wrap_angle(-np.pi)) == -np.pi
    assert float(wrap_angle(2 * np.pi)) == 0.0 or abs(float(wrap_angle(2 * np.pi))) < 1e-15
    assert wrap_angle(np.array([0.5, -0.5])).tolist() == [0.5, -0.5]     # in range: unchanged


def test_plane_cross_sign_and_value():
    u, w = 3.0 + 4.0j, -2.0 + 7.0j
    assert float(plane_cross(u, w)) == 3.0 * 7.0 - 4.0 * -2.0
    assert float(plane_cross(w, u)) == -29.0
    assert float(plane_cross(u, 2 * u)) == 0.0


def test_cross3_against_mpmath_and_broadcasting():
    rng = np.random.default_rng(3)
    a, b = rng.normal(size=(5, 3)), rng.normal(size=(1, 3))
    got = cross3(a, b)
    assert got.shape == (5, 3)
    for row, x in zip(got, a):
        y = b[0]
        ref = [mpmath.mpf(x[1]) * y[2] - mpmath.mpf(x[2]) * y[1], mpmath.mpf(x[2]) * y[0] - mpmath.mpf(x[0]) * y[2],
               mpmath.mpf(x[0]) * y[1] - mpmath.mpf(x[1]) * y[0]]
        assert np.allclose(row, [float(r) for r in ref], rtol=0, atol=1e-15)
    assert np.array_equal(cross_components(tuple(a[0]), tuple(b[0])), tuple(got[0]))


def test_unit_rows_length_one_and_zero_row_nan():
    v = np.array([[3.0, 0.0, 4.0], [1e-300, 0.0, 0.0], [0.0, 0.0, 0.0], [3e300, 0.0, -4e300]])
    got = unit_rows(v)
    assert got[0].tolist() == [0.6, 0.0, 0.8]
    assert got[1].tolist() == [1.0, 0.0, 0.0]               # no underflow in the squares
    assert np.all(np.isnan(got[2]))
    assert np.allclose(got[3], [0.6, 0.0, -0.8], rtol=1e-15, atol=0)   # no overflow either
    for row in np.random.default_rng(5).normal(size=(20, 3)):
        n = mpmath.sqrt(sum(mpmath.mpf(x) ** 2 for x in row))
        assert np.allclose(unit_rows(row), [float(x / n) for x in row], rtol=0, atol=3e-16)
        # a power-of-two change of unit gives the same floats
        assert np.array_equal(unit_rows(row * 2.0**-1000), unit_rows(row))
    assert np.allclose(unit_rows(np.array([3j, 4.0, 0.0])), [0.6j, 0.8, 0.0])    # complex rows


@pytest.mark.parametrize("u, v", [(1.0, 1.0 + 1.0j), (1.0 + 2.0j, -3.0 + 0.5j), (1e-200j, 1e200), (2.0, -2.0 + 1e-12j)])
def test_acute_angle_between_lines(u, v):
    # reference: the angle between the lines from acos of the normalised dot product at 50 digits
    ux, uy, vx, vy = (mpmath.mpf(t) for t in (u.real if isinstance(u, complex) else u,
                                               u.imag if isinstance(u, complex) else 0.0,
                                               v.real if isinstance(v, complex) else v,
                                               v.imag if isinstance(v, complex) else 0.0))
    ref = mpmath.atan2(abs(ux * vy - uy * vx), abs(ux * vx + uy * vy))
    got = float(acute_angle(u, v))
    assert 0.0 <= got <= PI / 2
    assert abs(got - float(ref)) <= 4e-16 * max(float(ref), 1e-300) + 1e-300
    assert float(acute_angle(v, u)) == got


@pytest.mark.parametrize("c", [0.0, 0.3, -0.3, 0.999, -1.0, 1.0000000001])
def test_acute_angle_from_cosine(c):
    got = float(acute_angle_from_cosine(c))
    ref = float(mpmath.acos(min(abs(mpmath.mpf(c)), 1)))
    assert 0.0 <= got <= PI / 2
    assert abs(got - ref) <= 1e-15


def test_unit_vector_check():
    assert unit_vector("axis", (0.0, 0.6, 0.8)).tolist() == [0.0, 0.6, 0.8]
    with pytest.raises(ValueError, match=r"`axis` to be a unit vector.*norm"):
        unit_vector("axis", (0.0, 0.6, 0.81))
    with pytest.raises(TypeError, match="`axis`"):
        unit_vector("axis", (0.0, "a", 1.0))


def test_proper_rotation_check():
    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    assert np.array_equal(proper_rotation("frame", R), R)
    with pytest.raises(ValueError, match=r"`frame` to be a proper rotation"):
        proper_rotation("frame", R @ np.diag([1.0, 1.0, -1.0]))        # a reflection
    with pytest.raises(ValueError, match=r"`frame` to be a proper rotation"):
        proper_rotation("frame", 2.0 * R)
    with pytest.raises(ValueError, match=r"`frame` to be a 3x3 rotation matrix, got shape \(2, 2\)"):
        proper_rotation("frame", np.eye(2))
    with pytest.raises(ValueError, match="`frame`"):
        proper_rotation("frame", np.full((3, 3), np.nan))
