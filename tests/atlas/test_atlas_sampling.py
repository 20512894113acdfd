"""The sampled design space of the planar four-bar (``mech.atlas.sample_fourbars``).

References are independent of the vectorised code: the type from ``mech.planar.grashof``,
positions from ``mech.planar.FourBar.solve`` (on the branch named at each input angle), the
minimum transmission angle from ``FourBar.min_transmission_angle``.
"""

import numpy as np
import pytest

from mech.atlas import FourBarSamples, sample_fourbars
from mech.atlas._planar._sampling import describe
from mech.planar import FourBar, grashof


@pytest.fixture(scope="module")
def samples():
    return sample_fourbars(4000, seed=11)


def test_sample_fourbars_kinds_match_grashof(samples):
    movable = samples.take(samples.movable)
    for i in range(0, len(movable), 7):
        assert grashof(movable.a[i], movable.b[i], movable.c[i], movable.d[i]).kind == movable.kind[i]


def test_sample_fourbars_full_turn_iff_crank(samples):
    crank = (samples.kind == "crank-rocker") | (samples.kind == "double-crank")
    assert np.array_equal(samples.full_turn, crank & samples.movable)
    assert np.all(samples.theta_lo[samples.full_turn] == 0.0)
    assert np.all(samples.theta_hi[samples.full_turn] == 2 * np.pi)


def test_sample_fourbars_space(samples):
    assert np.all(samples.d == 1.0)
    for x in (samples.a, samples.b, samples.c):
        assert x.min() >= 0.2 and x.max() <= 5.0
    u, v = samples.p / samples.b, samples.q / samples.b
    assert u.min() >= -1.0 and u.max() <= 2.0 and v.min() >= -1.5 and v.max() <= 1.5
    assert set(np.unique(samples.branch)) == {-1, 1}
    assert set(np.unique(samples.kind)) == {"crank-rocker", "rocker-crank", "double-crank", "double-rocker",
                                            "triple-rocker"}


def test_sample_fourbars_reproducible():
    a, b = sample_fourbars(50, seed=4), sample_fourbars(50, seed=4)
    for name, col in a.columns().items():
        assert np.array_equal(col, b.columns()[name]), name
    assert not np.array_equal(a.a, sample_fourbars(50, seed=5).a)


def test_curves_match_fourbar_solve(samples):
    """Full turn on one branch; rocking over the range and back on the other branch."""
    movable = samples.take(samples.movable)
    curves = movable.curves(96)
    assert not np.isnan(curves).any()
    u = 2 * np.pi * (np.arange(96) + 0.5) / 96
    for i in list(np.flatnonzero(movable.full_turn)[:10]) + list(np.flatnonzero(~movable.full_turn)[:30]):
        a, b, c, d, p, q = (getattr(movable, k)[i] for k in "abcdpq")
        br = int(movable.branch[i])
        if movable.full_turn[i]:
            ref = FourBar(a, b, c, d, branch=br, coupler=(p, q)).solve(u).P
        else:
            lo, hi = movable.theta_lo[i], movable.theta_hi[i]
            theta = 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u)
            one = FourBar(a, b, c, d, branch=br, coupler=(p, q)).solve(theta).P
            other = FourBar(a, b, c, d, branch=-br, coupler=(p, q)).solve(theta).P
            ref = np.where(np.cos(u) >= 0, one, other)
        assert np.max(np.abs(ref - curves[i])) < 1e-12


def test_rocking_range_ends_at_dead_centres(samples):
    """At the ends of a rocking range coupler and rocker lie in line: |BD| = b + c or |b - c|."""
    rock = samples.take(samples.movable & ~samples.full_turn)
    for end in (rock.theta_lo, rock.theta_hi):
        bd = np.abs(rock.d - rock.a * np.exp(1j * end))
        gap = np.minimum(np.abs(bd - (rock.b + rock.c)), np.abs(bd - np.abs(rock.b - rock.c)))
        assert np.max(gap) < 1e-12
        # just inside the range the linkage assembles
    inside = 0.5 * (rock.theta_lo + rock.theta_hi)
    for i in range(0, len(rock), 25):
        f = FourBar(rock.a[i], rock.b[i], rock.c[i], rock.d[i])
        assert f.solve(inside[i]).valid


def test_rocking_curve_is_closed_and_continuous(samples):
    rock = samples.take(samples.movable & ~samples.full_turn)
    curves = rock.curves(512)
    steps = np.abs(np.diff(np.concatenate([curves, curves[:, :1]], axis=1), axis=1))
    # the closing step (through no dead centre: u = 0 is mid-range) is like its neighbours,
    # and the two steps across the dead centres (u = pi/2, 3 pi/2) are like theirs
    for j in (511, 127, 383):
        assert np.all(steps[:, j] <= 2.0 * np.maximum(steps[:, j - 1], steps[:, (j + 1) % 512]) + 1e-12)


def test_gamma_min_matches_fourbar(samples):
    full = samples.take(samples.full_turn)
    for i in range(0, len(full), 5):
        gamma, _ = FourBar(full.a[i], full.b[i], full.c[i], full.d[i]).min_transmission_angle()
        assert abs(gamma - full.gamma_min[i]) < 1e-12
    assert np.all(samples.gamma_min[samples.movable & ~samples.full_turn] == 0.0)


def test_unmovable_flagged():
    s = describe([5.0, 0.3], [0.3, 2.0], [0.3, 1.5], [1.0, 1.0], [0.1, 0.5], [0.0, 0.2], [1, 1])
    assert s.movable.tolist() == [False, True]
    assert np.isnan(s.curves(16)[0]).all() and not np.isnan(s.curves(16)[1]).any()


def test_min_transmission_flags_usable():
    s = sample_fourbars(2000, seed=2, min_transmission=np.radians(40))
    assert np.all(s.gamma_min[s.usable] >= np.radians(40))
    assert np.all(s.full_turn[s.usable])
    assert np.array_equal(sample_fourbars(2000, seed=2).movable, s.movable)


def test_take_and_fourbar(samples):
    part = samples.take([3, 1])
    assert isinstance(part, FourBarSamples) and len(part) == 2
    assert part.a[0] == samples.a[3]
    i = int(np.flatnonzero(samples.movable)[0])
    f = samples.fourbar(i)
    assert (f.a, f.b, f.c, f.d, f.coupler, f.branch) == (samples.a[i], samples.b[i], samples.c[i], 1.0,
                                                         (samples.p[i], samples.q[i]), samples.branch[i])


def test_branch_option():
    assert np.all(sample_fourbars(100, branch=-1).branch == -1)


@pytest.mark.parametrize("kwargs, message", [
    ({"n": -1}, "Expected `n`"),
    ({"n": 2.0}, "Expected `n`"),
    ({"n": 5, "seed": -3}, "Expected `seed`"),
    ({"n": 5, "lengths": (2.0, 1.0)}, "Expected `lengths` as increasing"),
    ({"n": 5, "lengths": (0.0, 1.0)}, "Expected `lengths` > 0"),
    ({"n": 5, "coupler": (0, 1, 0)}, "Expected `coupler` to be 4 numbers"),
    ({"n": 5, "branch": 0}, "Expected `branch`"),
    ({"n": 5, "min_transmission": 2.0}, "Expected `min_transmission` in"),
])
def test_sample_fourbars_bad_inputs_named(kwargs, message):
    with pytest.raises(ValueError, match=message):
        sample_fourbars(**kwargs)


@pytest.mark.parametrize("index, message", [
    (10**6, "Expected `index` in"), ([0.5], "Expected `index`"), (True, "Expected `index`"),
    ("1", "Expected `index`"), (np.array([True, False]), "Expected `index`"),
])
def test_take_bad_index_named(samples, index, message):
    with pytest.raises(ValueError, match=message):
        samples.take(index)
