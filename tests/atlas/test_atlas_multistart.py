"""Refinement from several starts (`find_linkages`): a target not in the atlas, within 1 %, answered
by a linkage a motor can drive (issue 28, item 2)."""

import math

import numpy as np
import pytest

from mech.atlas import Constraints, build_atlas, find_linkages, query, refine
from mech.planar import FourBar


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(2000, seed=3)


def _example_2_1_curve(points=300):
    """Example 2-1's linkage (a, b, c, d) = (10, 40, 30, 35) with a coupler point (20, 15) of our choosing."""
    t = np.linspace(0, 2 * np.pi, points, endpoint=False)
    return FourBar(10, 40, 30, 35, coupler=(20, 15)).solve(t).P


def _outline(corners, points=300):
    """Points at equal steps along a closed polygon (a hand-drawn letter's outline)."""
    z = np.append(np.asarray(corners, complex), corners[0])
    length = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(z)))])
    s = np.linspace(0.0, length[-1], points, endpoint=False)
    return np.interp(s, length, z.real) + 1j * np.interp(s, length, z.imag)


def _driven_check(match, target):
    """Check a returned linkage by simulation, not by the closed forms the search uses: the
    crank turns fully (every pose of a dense full turn assembles), the transmission angle
    (the angle at C between CB and CD, from the poses) stays >= 30 degrees, the link ratio
    is <= 10, and the placed coupler curve is the one reported."""
    f = match.linkage.fourbar
    theta = np.linspace(0.0, 2 * np.pi, 20001)
    pose = f.solve(theta)
    assert np.all(pose.valid)
    D = f.d + 0j
    delta = np.abs(np.angle((pose.B - pose.C) / (D - pose.C)))
    gamma = np.minimum(delta, np.pi - delta)
    assert gamma.min() >= math.radians(30) - 1e-9
    assert max(f.a, f.b, f.c, f.d) <= 10 * min(f.a, f.b, f.c, f.d) * (1 + 1e-9)
    placed = match.linkage.place(pose.P)
    size = np.sqrt(np.mean(np.abs(target - target.mean()) ** 2))
    gap = np.min(np.abs(match.curve[:, None] - placed[None, :]), axis=1)
    assert gap.max() < 1e-3 * size


def test_example_2_1_find_linkages_within_one_percent(atlas):
    target = _example_2_1_curve()
    first = query(atlas, target, k=1)[0]
    found = find_linkages(atlas, target, starts=4)
    assert [m.rank for m in found] == list(range(len(found))) and len(found) == 4
    errors = [m.relative_error for m in found]
    assert errors == sorted(errors)
    assert found[0].refined and found[0].relative_error < 0.01 < first.relative_error * 1.01 + 0.01
    assert found[0].relative_error <= 1.5 * refine(first, target).relative_error
    for m in found:
        _driven_check(m, target)


@pytest.mark.parametrize("name", ["double-rocker curve", "letter L"])
def test_default_find_linkages_is_driven_and_near_the_unconstrained_error(atlas, name):
    """Issue 28: the best unconstrained answers to such targets are rockers, which no motor
    drives; the default answer turns its crank, at most 1.5 times the free error."""
    if name == "double-rocker curve":
        from mech.atlas import sample_fourbars

        s = sample_fourbars(400, seed=99)
        row = int(np.flatnonzero(s.movable & (s.kind == "double-rocker"))[0])
        target = 3 - 2j + 7 * s.take([row]).curves(300)[0]
    else:
        target = _outline([0, 1, 1 + 0.25j, 0.25 + 0.25j, 0.25 + 1j, 1j])
    free = find_linkages(atlas, target, constraints=Constraints.none())
    found = find_linkages(atlas, target)
    assert found and found[0].full_turn and found[0].kind in ("crank-rocker", "double-crank")
    assert found[0].relative_error <= 1.5 * free[0].relative_error
    for m in found:
        _driven_check(m, target)


def test_rocker_crank_is_relabelled_with_the_motor_at_its_turning_link():
    """The relabelled linkage, driven at its new crank by the planar solver, traces the closed
    curve of the rocker-crank's circuit (the atlas's curve: the rocking input over both
    branches), and the other branch does not."""
    from scipy.spatial import cKDTree

    from mech.atlas._planar._constraints import motor_at_crank
    from mech.atlas._planar._sampling import coupler_points, describe

    a, b, c, d, p, q = 2.4, 2.0, 0.7, 2.2, 0.8, 0.5           # c shortest: a rocks, c turns
    for branch in (1, -1):
        (a2, b2, c2, d2, p2, q2, br2), moved = motor_at_crank(a, b, c, d, p, q, branch)
        assert moved and (a2, b2, c2, d2) == (c, b, a, d)
        old = coupler_points(describe([a], [b], [c], [d], [p], [q], [branch]).columns(),
                             np.linspace(0, 2 * np.pi, 200001)[None, :])[0]
        gaps = []
        for side in (br2, -br2):
            new = FourBar(a2, b2, c2, d2, branch=side, coupler=(p2, q2)).solve(np.linspace(0, 2 * np.pi, 721))
            assert np.all(new.valid)
            moved_back = d - new.P                              # z' = d - z: the new frame turned by pi
            # nearest of the 200,001 old points to each new one (a tree: the full distance
            # matrix would hold 1.4e8 entries)
            gaps.append(np.max(cKDTree(np.c_[old.real, old.imag]).query(np.c_[moved_back.real, moved_back.imag])[0]))
        assert gaps[0] < 1e-4 < 1.0 < gaps[1]
    assert motor_at_crank(1.0, 4.0, 3.0, 3.5, 0.2, 0.1, 1)[1] is False        # a crank-rocker stays


def test_no_rocker_crank_returned(atlas):
    """A rocker-crank's curve: the answer is a crank-rocker (the same linkage, relabelled) or another driven one."""
    rc = np.flatnonzero(atlas.linkages.kind == "rocker-crank")[0]
    target = atlas.curves(int(rc), 300)[0]
    found = find_linkages(atlas, target, starts=2)
    assert found[0].relative_error < 1e-3
    assert all(m.kind in ("crank-rocker", "double-crank") for m in found)


def test_feasible_rows_are_those_a_motor_drives(atlas):
    """The rows searched apart for starts: checked row by row by simulation of the linkage
    (motor at the crank, or at the rocker for a rocker-crank), not by the closed forms."""
    from mech.atlas._planar._multistart import _feasible

    sub, rows = _feasible(atlas, Constraints())
    assert len(sub) == rows.size and 0 < rows.size < len(atlas)
    np.testing.assert_array_equal(sub.signatures, atlas.signatures[rows])
    L = atlas.linkages
    theta = np.linspace(0.0, 2 * np.pi, 2001)

    def driven(a, b, c, d):
        pose = FourBar(a, b, c, d).solve(theta)
        if not np.all(pose.valid):
            return False
        delta = np.abs(np.angle((pose.B - pose.C) / (d - pose.C)))
        return np.minimum(delta, np.pi - delta).min() >= math.radians(30) - 1e-6

    feasible = set(rows.tolist())
    for i in np.random.default_rng(1).choice(len(atlas), 150, replace=False):
        a, b, c, d = (float(getattr(L, k)[i]) for k in "abcd")
        ok = (driven(a, b, c, d) or driven(c, b, a, d)) and max(a, b, c, d) <= 10 * min(a, b, c, d)
        assert (int(i) in feasible) == ok, (i, a, b, c, d)
    assert _feasible(atlas, Constraints()) is _feasible(atlas, Constraints())     # kept with the atlas


def test_pivot_box_keeps_the_fixed_pivots_inside(atlas):
    target = _example_2_1_curve()
    free = find_linkages(atlas, target, starts=3)
    A, D = free[0].linkage.pivots
    # a box that excludes the best free answer's pivots but holds the target's middle
    centre = target.mean()
    box = (centre.real - 30, centre.real + 30, centre.imag - 30, min(A.imag, D.imag) - 1.0)
    found = find_linkages(atlas, target, starts=3, constraints=Constraints(pivot_box=box))
    assert found
    for m in found:
        for P in m.linkage.pivots:
            assert box[0] <= P.real <= box[1] and box[2] <= P.imag <= box[3]
        _driven_check(m, target)


def test_find_linkages_goal_stops_early(atlas):
    found = find_linkages(atlas, _example_2_1_curve(), starts=6, goal=0.05)
    assert len(found) < 6 and found[0].relative_error <= 0.05


def test_find_linkages_options(atlas):
    with pytest.raises(ValueError, match="Expected `goal` >= 0"):
        find_linkages(atlas, _example_2_1_curve(), goal=-1.0)
    with pytest.raises(TypeError, match="constraints"):
        find_linkages(atlas, _example_2_1_curve(), constraints={"crank": True})


@pytest.mark.parametrize("kwargs, message", [
    ({"min_transmission": math.pi / 2}, "min_transmission"),
    ({"min_transmission": -0.1}, "min_transmission"),
    ({"max_ratio": 0.5}, "max_ratio"),
    ({"max_ratio": float("nan")}, "max_ratio"),
    ({"pivot_box": (0, 1, 2)}, "pivot_box"),
    ({"pivot_box": (1, 0, 0, 1)}, "pivot_box"),
    ({"crank": "yes"}, "crank"),
])
def test_constraints_bad_values_named(kwargs, message):
    with pytest.raises((ValueError, TypeError), match=message):
        Constraints(**kwargs)
