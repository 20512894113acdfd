"""A triple rocker just inside its limit angle assembles (issue 24, item 8).

The triple rocker (a, b, c, d) = (3, 2, 2.5, 4) meets its limit where the coupler and
rocker are stretched out (BD = b + c). 1e-14 and 1e-15 rad inside that angle a 50-digit
solve assembles it, with C within about the square root of the distance inside of the
dead-position pose; on both branches and at any unit the package must give a valid pose
there and that position of C (not NaN).
"""

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar

A, B, C, D = 3, 2, 2.5, 4


def _limit():
    with mpmath.workdps(50):
        return mpmath.acos((mpmath.mpf(A) ** 2 + D ** 2 - (B + C) ** 2) / (2 * A * D))


def _coupler_points(theta):
    """The two positions of C at the float input theta, at 50 digits (None if it does not
    assemble): the circles about B = a exp(i theta) of radius b and about D = d of radius c."""
    with mpmath.workdps(50):
        th = mpmath.mpf(float(theta))
        b_pt = A * mpmath.expj(th)
        chord = D - b_pt
        dist = abs(chord)
        if not abs(B - C) <= dist <= B + C:
            return None
        along = (B ** 2 - C ** 2 + dist ** 2) / (2 * dist)
        half = mpmath.sqrt(max(B ** 2 - along ** 2, 0))
        unit = chord / dist
        return [complex(b_pt + unit * (along + 1j * s * half)) for s in (1, -1)]


@pytest.mark.parametrize("inside", [1e-14, 1e-15])
@pytest.mark.parametrize("side", [1, -1])
@pytest.mark.parametrize("scale", [1.0, 1e-200, 1e200])
def test_triple_rocker_just_inside_its_limit(inside, side, scale):
    theta = side * float(_limit() - mpmath.mpf(inside))
    expected = _coupler_points(theta)
    assert expected is not None                      # the 50-digit solve assembles it
    for branch in (1, -1):
        pose = FourBar(A * scale, B * scale, C * scale, D * scale, branch=branch).solve(np.array([theta]))
        assert bool(pose.valid[0])
        got = complex(np.asarray(pose.C)[0]) / scale
        # near the dead position both branches are within sqrt(inside) of the stretched pose
        assert min(abs(got - e) for e in expected) <= 1e-6, (got, expected)
