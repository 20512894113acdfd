"""The spherical design space: types, input ranges, branches and transmission angles of the samples,
each checked by another route (the scalar `classify`, poses solved one by one, angles measured)."""

import numpy as np
import pytest

from mech.atlas import sample_sphere_fourbars
from mech.spherical import SphericalFourBar, classify


@pytest.fixture(scope="module")
def drawn():
    return sample_sphere_fourbars(400, seed=21)


def test_kinds_agree_with_classify(drawn):
    wide = sample_sphere_fourbars(300, seed=5, arcs=(0.1, 3.0))         # antipode reductions too
    for s in (drawn, wide):
        for i in range(len(s)):
            try:
                kind = classify(s.a[i], s.b[i], s.c[i], s.d[i]).kind
            except ValueError:                                          # cannot be assembled
                assert not s.movable[i]
                continue
            assert s.kind[i] == kind, i


def test_full_turn_by_simulation(drawn):
    """full_turn iff every pose over a dense turn assembles (SphericalFourBar.solve), and the
    type says the crank revolves."""
    theta = np.linspace(-np.pi, np.pi, 2001)
    for i in range(0, len(drawn), 3):
        valid = drawn.fourbar(i).solve(theta).valid
        assert bool(valid.all()) == bool(drawn.full_turn[i]), i
        assert bool(drawn.full_turn[i]) == (drawn.kind[i] in ("crank-rocker", "double-crank"))


def test_rocking_range_ends_are_limit_positions(drawn):
    """Inside the range the pose assembles, just outside it does not (unless wrapping round)."""
    rocking = np.flatnonzero(drawn.movable & ~drawn.full_turn)
    assert rocking.size > 50
    for i in rocking[:60]:
        f = drawn.fourbar(i)
        lo, hi = drawn.theta_lo[i], drawn.theta_hi[i]
        inside = np.linspace(lo, hi, 101)[1:-1]
        assert f.solve(inside).valid.all(), i
        assert not f.solve(lo - 1e-6).valid and not f.solve(hi + 1e-6).valid, i
        # at a limit position B, C and D lie on one great circle: det[B, C, D] = 0
        for end in (lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo)):
            pose = f.solve(end)
            assert abs(np.linalg.det(np.stack([pose.B, pose.C, [np.sin(f.d), 0.0, np.cos(f.d)]]))) < 1e-3


def test_gamma_min_measured(drawn):
    """The smallest transmission angle, measured as the angle at C between the great circles
    to B and to D over a dense turn of the crank."""
    theta = np.linspace(-np.pi, np.pi, 4001)
    full = np.flatnonzero(drawn.full_turn)
    assert full.size > 20
    for i in full[:40]:
        f = drawn.fourbar(i)
        pose = f.solve(theta)
        D = np.array([np.sin(f.d), 0.0, np.cos(f.d)])
        C = pose.C
        tb = pose.B - np.sum(pose.B * C, axis=1)[:, None] * C
        td = D - (C @ D)[:, None] * C
        cos = np.sum(tb * td, axis=1) / np.linalg.norm(tb, axis=1) / np.linalg.norm(td, axis=1)
        mu = np.arccos(np.clip(cos, -1, 1))
        measured = np.min(np.minimum(mu, np.pi - mu))
        assert abs(measured - drawn.gamma_min[i]) < 1e-5, i
    assert np.all(drawn.gamma_min[~drawn.full_turn] == 0.0)


def test_curves_of_rocking_inputs_match_poses(drawn):
    """The closed curve of a rocking input runs out on one branch and back on the other."""
    i = int(np.flatnonzero(drawn.movable & ~drawn.full_turn)[0])
    curve = drawn.take([i]).curves(64)[0]
    u = 2 * np.pi * (np.arange(64) + 0.5) / 64
    lo, hi = drawn.theta_lo[i], drawn.theta_hi[i]
    for j in range(64):
        side = int(drawn.branch[i]) * (1 if np.cos(u[j]) >= 0 else -1)
        f = SphericalFourBar(drawn.a[i], drawn.b[i], drawn.c[i], drawn.d[i], branch=side,
                             coupler=(drawn.r[i], drawn.gamma[i]))
        assert np.allclose(f.solve(0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u[j])).P, curve[j], atol=1e-12)
    # closed and continuous: no step is more than a fifth of the length
    steps = np.linalg.norm(np.diff(np.vstack([curve, curve[:1]]), axis=0), axis=1)
    assert steps.max() < 0.2 * steps.sum()


def test_usable_and_min_transmission():
    s = sample_sphere_fourbars(500, seed=8, min_transmission=0.4)
    assert np.array_equal(s.usable, s.movable & (s.gamma_min >= 0.4))
    assert np.all(s.full_turn[s.usable])
    one = sample_sphere_fourbars(50, seed=8, branch=-1)
    assert np.all(one.branch == -1)


@pytest.mark.parametrize("kwargs, message", [
    ({"n": -1}, "Expected `n`"), ({"n": 3, "arcs": (1.0, 0.5)}, "Expected `arcs`"),
    ({"n": 3, "coupler_arc": (0.1, 4.0)}, "Expected `coupler_arc`"),
    ({"n": 3, "min_transmission": 2.0}, "Expected `min_transmission`"), ({"n": 3, "branch": 0}, "branch"),
])
def test_bad_inputs_named(kwargs, message):
    with pytest.raises(ValueError, match=message):
        sample_sphere_fourbars(**kwargs)
