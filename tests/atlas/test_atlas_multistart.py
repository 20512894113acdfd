"""Refinement from several starts (`find_linkages`): a target not in the atlas, within 1 %."""

import numpy as np
import pytest

from mech.atlas import build_atlas, find_linkages, query, refine
from mech.planar import FourBar


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(2000, seed=3)


def _example_2_1_curve(points=300):
    """Example 2-1's linkage (a, b, c, d) = (10, 40, 30, 35) with a coupler point (20, 15) of our choosing."""
    t = np.linspace(0, 2 * np.pi, points, endpoint=False)
    return FourBar(10, 40, 30, 35, coupler=(20, 15)).solve(t).P


def test_example_2_1_find_linkages_within_one_percent(atlas):
    target = _example_2_1_curve()
    first = query(atlas, target, k=1)[0]
    found = find_linkages(atlas, target, starts=4)
    assert [m.rank for m in found] == list(range(len(found))) and len(found) == 4
    errors = [m.relative_error for m in found]
    assert errors == sorted(errors)
    assert found[0].refined and found[0].relative_error < 0.01 < first.relative_error * 1.01 + 0.01
    assert found[0].relative_error <= refine(first, target).relative_error


def test_find_linkages_goal_stops_early(atlas):
    found = find_linkages(atlas, _example_2_1_curve(), starts=6, goal=0.05)
    assert len(found) < 6 and found[0].relative_error <= 0.05


def test_find_linkages_options(atlas):
    with pytest.raises(ValueError, match="Expected `goal` >= 0"):
        find_linkages(atlas, _example_2_1_curve(), goal=-1.0)
