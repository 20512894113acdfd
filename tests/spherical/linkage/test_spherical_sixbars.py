"""The spherical linkage solver and the four six-bars (monograph §2.4) against independent routes."""

import numpy as np
import pytest

from mech import AssemblyError
from mech.spherical import SphericalFourBar, SphericalLinkage, ground_frame, stephenson1, stephenson2, watt1, watt2

from tests.spherical.sixbar_reference import reference

KINDS = {"stephenson1": stephenson1, "stephenson2": stephenson2, "watt1": watt1, "watt2": watt2}
# points carried by each moving link (besides the frame points), per type
CARRIED = {"stephenson1": {"AB": "E", "DC": "F"}, "stephenson2": {"BC": "E"},
           "watt1": {"BC": "E", "DC": "F"}, "watt2": {"DC": "E"}}


def random_sixbar(kind, rng, full_turn=True):
    """A random six-bar of `kind` that assembles over a whole input turn (or at least somewhere)."""
    for _ in range(5000):
        a = rng.uniform(0.15, 0.4)
        b, c, d = rng.uniform(0.6, 1.4, 3)
        E = (rng.uniform(0.2, 1.0), rng.uniform(-np.pi, np.pi))
        F = (rng.uniform(0.3, 1.5), rng.uniform(-np.pi, np.pi))
        arcs = tuple(rng.uniform(0.4, 1.5, 2))
        coupler = (rng.uniform(0.1, 1.0), rng.uniform(-np.pi, np.pi))
        branches = tuple(int(s) for s in rng.choice([-1, 1], 2))
        # placed anywhere on the sphere
        frame = ground_frame(rng.uniform(-np.pi, np.pi), rng.uniform(-1.5, 1.5), rng.uniform(-np.pi, np.pi))
        lk = KINDS[kind](a, b, c, d, E=E, F=F, arcs=arcs, coupler=coupler, branches=branches, frame=frame)
        ok = lk.solve(np.linspace(0, 2 * np.pi, 361), order=1).valid
        if (ok.all() if full_turn else ok.any()):
            return lk
    raise RuntimeError("no linkage found")


def _arc(p, q):
    return np.arctan2(np.linalg.norm(np.cross(p, q), axis=-1), np.sum(p * q, axis=-1))


def _dyads(lk):
    return [s for s in lk._steps if s[0] == "rrr"]


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_closure_of_every_loop(kind):
    rng = np.random.default_rng(sorted(KINDS).index(kind))
    for _ in range(3):
        lk = random_sixbar(kind, rng)
        th = np.linspace(-np.pi, 3 * np.pi, 2001)
        pose = lk.solve(th)
        P = pose.points
        assert pose.valid.all()
        for name, v in P.items():
            assert np.max(np.abs(np.linalg.norm(v, axis=-1) - 1.0)) < 1e-14, name
        for _, links, (p1, p2), j, (b1, b2), _s in _dyads(lk):
            assert np.max(np.abs(_arc(P[p1], P[j]) - b1)) < 1e-12 * b1
            assert np.max(np.abs(_arc(P[p2], P[j]) - b2)) < 1e-12 * b2
        # the crank arc, and every ternary link keeps its shape: arcs from the carried point
        # to both frame points are constant along the motion
        a = lk._steps[2][4]
        assert np.max(np.abs(_arc(P["A"], P["B"]) - a)) < 1e-12 * a
        frames = lk._links
        for link, name in {**CARRIED[kind], "EG": "P"}.items():
            o, x = frames[link]
            for ref in (o, x):
                dist = _arc(P[ref], P[name])
                assert np.ptp(dist) < 1e-12 * max(dist.max(), 1.0), (link, name, ref)
        # loop angle: the angle of every point about its link stays put (no mirror flips)
        for link, name in {**CARRIED[kind], "EG": "P"}.items():
            o, x = frames[link]
            side = np.einsum("ij,ij->i", np.cross(P[o], P[x]), P[name])
            assert np.all(side > 0) or np.all(side < 0) or np.ptp(side) < 1e-12


def _assert_no_jump(pose, th):
    """Every point valid and every step the arc swept at the local speed, to second order:
    a branch jump would be a step of order one."""
    assert pose.valid.all()
    step = th[1] - th[0]
    for name, P in pose.points.items():
        jump = np.linalg.norm(np.diff(P, axis=0), axis=-1)
        speed = np.linalg.norm(pose.velocities[name], axis=-1)
        assert np.all(jump <= 1.01 * np.maximum(speed[:-1], speed[1:]) * step + 1e-12), name


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_no_branch_jump_over_a_full_turn(kind):
    rng = np.random.default_rng(7 + len(kind))
    lk = random_sixbar(kind, rng)
    n = 100_000
    th = np.linspace(0.0, 2 * np.pi, n + 1)
    pose = lk.solve(th, order=1)
    _assert_no_jump(pose, th)
    for name, P in pose.points.items():
        assert np.allclose(P[0], P[-1], atol=1e-12), name        # back where it started
    for _, links, (p1, p2), j, arcs, sign in _dyads(lk):
        det = np.einsum("ij,ij->i", np.cross(pose.points[p1], pose.points[p2]), pose.points[j])
        assert np.all(sign * det > 0)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_rates_against_mpmath_rotation_chain(kind):
    rng = np.random.default_rng(100 + len(kind) + ord(kind[-1]))
    checked = 0
    while checked < 3:
        lk = random_sixbar(kind, rng, full_turn=False)
        grid = np.linspace(0, 2 * np.pi, 361)
        ok = grid[lk.solve(grid, order=2).valid]
        theta = float(rng.choice(ok)) + 1e-3
        omega, alpha = rng.uniform(-2, 2, 2)
        pose = lk.solve(theta, order=2, omega=omega, alpha=alpha)
        if not pose.valid:
            continue
        ref = reference(lk, theta, omega, alpha, pose.points)
        checked += 1
        for name, (p, v, a) in ref.items():
            p, v, a = (np.array([float(x) for x in q]) for q in (p, v, a))
            scale_v = max(1.0, np.linalg.norm(v))
            scale_a = max(1.0, np.linalg.norm(a))
            assert np.max(np.abs(pose.points[name] - p)) < 1e-13, name
            assert np.max(np.abs(pose.velocities[name] - v)) < 1e-11 * scale_v, name
            assert np.max(np.abs(pose.accelerations[name] - a)) < 1e-10 * scale_a, name
        # angular velocities: w x X is the reference velocity of every point X of the link
        links = {"AB": "ABE", "BC": "BCE", "DC": "DCFE", "EG": "EGP", "FG": "FG"}
        for link, names in links.items():
            w = pose.angular_velocities[link]
            dw = pose.angular_accelerations[link]
            for name in names:
                if lk._points.get(name) not in (link,) and name not in lk._links[link]:
                    continue
                p, v, a = (np.array([float(x) for x in q]) for q in ref[name])
                assert np.allclose(np.cross(w, p), v, rtol=0, atol=1e-11 * max(1, np.linalg.norm(v))), (link, name)
                acc = np.cross(dw, p) + np.cross(w, np.cross(w, p))
                assert np.allclose(acc, a, rtol=0, atol=1e-10 * max(1, np.linalg.norm(a))), (link, name)


@pytest.mark.parametrize("branch", [1, -1])
def test_built_as_a_fourbar_it_is_the_spherical_fourbar(branch):
    rng = np.random.default_rng(3)
    for _ in range(5):
        a = rng.uniform(0.1, 0.5)
        b, c, d = rng.uniform(0.5, 1.5, 3)
        r, g = rng.uniform(0.1, 1.0), rng.uniform(-3, 3)
        fb = SphericalFourBar(a, b, c, d, branch=branch, coupler=(r, g))
        lk = (SphericalLinkage({"A": (0, 0, 1), "D": (np.sin(d), 0, np.cos(d))})
              .crank("AB", pivot="A", tip="B", arc=a, reference="D")
              .rrr(("BC", "DC"), pins=("B", "D"), joint="C", arcs=(b, c), branch=branch)
              .point("P", link="BC", at=(r, g)))
        th = np.linspace(-7, 7, 301)
        p1, p2 = fb.solve(th, order=2, omega=1.7, alpha=-0.3), lk.solve(th, order=2, omega=1.7, alpha=-0.3)
        np.testing.assert_array_equal(p1.valid, p2.valid)
        v = p1.valid
        for k in "BCP":
            np.testing.assert_allclose(p2.points[k][v], getattr(p1, k)[v], rtol=0, atol=1e-13)
            np.testing.assert_allclose(p2.velocities[k][v], getattr(p1, "v" + k)[v], rtol=0, atol=1e-10)
            np.testing.assert_allclose(p2.accelerations[k][v], getattr(p1, "a" + k)[v], rtol=0, atol=1e-8)
        np.testing.assert_allclose(p2.angular_velocities["DC"][v], p1.w_output[v], rtol=0, atol=1e-10)


def test_a_six_bar_whose_second_dyad_copies_the_first_moves_as_the_fourbar():
    # Watt-1 with E = C on the coupler, F = D... instead: E = B on the crank and the second
    # dyad the same arcs as the first, pinned at B and D: G coincides with C
    a, b, c, d = 0.3, 0.9, 0.7, 1.0
    lk = stephenson1(a, b, c, d, E=(a, 0.0), F=(1e-9, 0.0), arcs=(b, c), coupler=(0.0, 0.0))
    fb = SphericalFourBar(a, b, c, d)
    th = np.linspace(0, 2 * np.pi, 50)
    pose = lk.solve(th)
    np.testing.assert_allclose(pose.points["E"], pose.points["B"], atol=1e-12)
    np.testing.assert_allclose(pose.points["G"], fb.solve(th).C, atol=1e-7)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_placed_anywhere_on_the_sphere_is_the_rotated_linkage(kind):
    R = ground_frame(0.7, -0.4, 2.1)
    args = dict(E=(0.4, 0.6), F=(0.9, 0.5), arcs=(0.7, 0.6), coupler=(0.3, 0.5))
    here, there = KINDS[kind](0.3, 0.9, 0.7, 1.0, **args), KINDS[kind](0.3, 0.9, 0.7, 1.0, frame=R, **args)
    th = np.linspace(0, 2 * np.pi, 25)
    p1, p2 = here.solve(th, order=2, omega=1.2, alpha=0.4), there.solve(th, order=2, omega=1.2, alpha=0.4)
    np.testing.assert_array_equal(p1.valid, p2.valid)
    assert p1.valid.any()
    for name in here.points:
        np.testing.assert_allclose(p2.points[name][p1.valid], p1.points[name][p1.valid] @ R.T, atol=1e-14)
        np.testing.assert_allclose(p2.accelerations[name][p1.valid], p1.accelerations[name][p1.valid] @ R.T,
                                   atol=1e-12)


def test_not_assembled_is_nan_and_strict_raises():
    lk = stephenson2(0.6, 0.5, 0.5, 1.0, E=(0.4, 0.7), F=(1.2, 0.5), arcs=(0.7, 0.6), coupler=(0.3, -0.4))
    th = np.linspace(0, 2 * np.pi, 91)
    pose = lk.solve(th, order=2)
    assert not pose.valid.all() and pose.valid.any()
    assert np.isnan(pose.points["C"][~pose.assembled]).all()
    assert np.isfinite(pose.points["C"][pose.assembled]).all()
    with pytest.raises(AssemblyError, match="theta = "):
        lk.solve(th, strict=True)


def test_coupler_curve_matches_solve():
    lk = watt2(0.3, 0.9, 0.7, 1.0, E=(0.3, 0.5), F=(1.4, 0.4), arcs=(0.6, 0.5), coupler=(0.3, 0.4))
    th = np.linspace(0, 2 * np.pi, 37)
    P, v, a, ok = lk.coupler_curve(th, order=2, omega=2.0, alpha=1.0)
    pose = lk.solve(th, order=2, omega=2.0, alpha=1.0)
    np.testing.assert_array_equal(P, pose.points["P"])
    np.testing.assert_array_equal(a, pose.accelerations["P"])
    np.testing.assert_array_equal(ok, pose.valid)


def test_builder_errors():
    lk = SphericalLinkage({"A": (0, 0, 1), "D": (1, 0, 0)})
    with pytest.raises(ValueError, match="`arc`"):
        lk.crank("AB", pivot="A", tip="B", arc=4.0, reference="D")
    with pytest.raises(ValueError, match="`pivot`"):
        lk.crank("AB", pivot="Z", tip="B", arc=0.3, reference="D")
    with pytest.raises(ValueError, match="unit vector"):
        SphericalLinkage({"A": (0, 0, 2)})
    with pytest.raises(ValueError, match="crank"):
        lk.solve(0.0)
    lk = lk.crank("AB", pivot="A", tip="B", arc=0.3, reference="D")
    with pytest.raises(ValueError, match="second"):
        lk.crank("AB2", pivot="A", tip="B2", arc=0.3, reference="D")
    with pytest.raises(ValueError, match="`link`"):
        lk.point("P", link="ground", at=(0.1, 0.1))


def test_limit_position_rates_are_masked_not_huge():
    # a triple-rocker: at the ends of its input range the dyad is stretched (J on the
    # great circle BD, det[B, D, C] = 0); there the rates are masked, never a huge number
    # passed as valid; just inside they are large and right
    a, b, c, d = 0.5, 0.6, 0.7, 0.9
    lk = _fourbar_linkage(a, b, c, d, 1)
    fb = SphericalFourBar(a, b, c, d)
    ends = fb.assembly_range().intervals[0]
    pose = lk.solve(ends, order=2)
    assert not pose.valid.any()
    inside = ends + np.array([1e-9, -1e-9])
    pose, ref = lk.solve(inside, order=1), fb.solve(inside, order=1)
    assert pose.valid.all()
    np.testing.assert_allclose(pose.velocities["C"], ref.vC, rtol=1e-5)


def _fourbar_linkage(a, b, c, d, branch):
    return (SphericalLinkage({"A": (0, 0, 1), "D": (np.sin(d), 0, np.cos(d))})
            .crank("AB", pivot="A", tip="B", arc=a, reference="D")
            .rrr(("BC", "DC"), pins=("B", "D"), joint="C", arcs=(b, c), branch=branch))


@pytest.mark.parametrize("arcs", [(0.4, 1.0, 0.4, 1.0), (0.5, 0.5, 0.8, 0.8), (0.6, 1.1, 0.6, 1.1),
                                  (0.3, 0.8, 0.9, 0.4), (0.2, 1.0, 0.2, 1.0)])
@pytest.mark.parametrize("branch", [1, -1])
def test_change_point_fourbars_continue_as_the_spherical_fourbar(arcs, branch):
    """Isograms, deltoids and any s + l = p + q: the branches meet and part again; the
    solver carries the motion onto the other sign as `SphericalFourBar` does, over two
    turns both ways, the meeting poses included."""
    lk, fb = _fourbar_linkage(*arcs, branch), SphericalFourBar(*arcs, branch=branch)
    th = np.concatenate((np.linspace(-4 * np.pi, 4 * np.pi, 4001), [0.0, np.pi, -np.pi, 2 * np.pi]))
    p1, p2 = fb.solve(th, order=2, omega=1.3, alpha=-0.6), lk.solve(th, order=2, omega=1.3, alpha=-0.6)
    np.testing.assert_array_equal(p1.valid, p2.valid)
    assert p1.valid.all()
    np.testing.assert_allclose(p2.points["C"], p1.C, rtol=0, atol=1e-13)
    np.testing.assert_allclose(p2.velocities["C"], p1.vC, rtol=0, atol=1e-10)
    np.testing.assert_allclose(p2.accelerations["C"], p1.aC, rtol=0, atol=1e-8)


@pytest.mark.parametrize("arcs", [(0.4, 1.0, 0.4, 1.0), (0.3, 0.8, 0.9, 0.4)])
def test_no_jump_through_change_points_at_1e5_steps(arcs):
    lk = _fourbar_linkage(*arcs, 1).point("P", link="BC", at=(0.3, 0.7))
    th = np.linspace(-2 * np.pi, 2 * np.pi, 100_001)
    pose = lk.solve(th, order=1)
    _assert_no_jump(pose, th)


@pytest.mark.parametrize("scale", [1.0, 1e-2, 1e-3])
def test_change_points_do_not_depend_on_the_cap(scale):
    """A small linkage keeps the change points of its shape (issue 24): the radicand of a
    dyad shrinks with about the fourth power of the arcs, and an absolute threshold gave a
    crank-rocker on a 1e-3 cap change points at 0 and pi, so the solver jumped branches."""
    def fourbar(a, b, c, d):
        A, D = np.array([0.0, 0.0, 1.0]), np.array([np.sin(d), 0.0, np.cos(d)])
        return (SphericalLinkage({"A": A, "D": D}).crank("AB", pivot="A", tip="B", arc=a, reference="D")
                .rrr(("BC", "DC"), pins=("B", "D"), joint="C", arcs=(b, c)))
    rocker = fourbar(*(scale * np.array([0.3, 0.9, 0.7, 1.0])))
    assert rocker.change_points[1][0].size == 0
    isogram = fourbar(*(scale * np.array([0.3, 1.0, 0.3, 1.0])))          # s + l = p + q: two per turn
    assert isogram.change_points[1][0].size == 2
