"""Search (``mech.atlas.query``): a target taken from a linkage of the atlas, moved, scaled,
turned, restarted, reversed and noisy, finds that linkage (or a cognate) first; the match is
placed on the target and its cognates trace the same curve.
"""

import numpy as np
import pytest

from mech.atlas import Match, build_atlas, query
from mech.atlas._planar._sampling import coupler_curves
from mech.planar import FourBar, cognates


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(3000, seed=21)


def _target(atlas, i, rng, noise=1e-3, points=300):
    """Curve of atlas row i: a random start (between steps), direction, similarity and noise."""
    row = atlas.linkages.take([i]).columns()
    curve = coupler_curves(row, 4 * points)[0]
    curve = np.roll(curve, int(rng.integers(4 * points)))[::4]          # start anywhere
    if rng.random() < 0.5:
        curve = curve[::-1]
    moved = complex(*rng.normal(scale=10, size=2)) + 10 ** rng.uniform(-2, 2) * np.exp(
        1j * rng.uniform(-np.pi, np.pi)) * curve
    size = np.sqrt(np.mean(np.abs(moved - moved.mean()) ** 2))
    return moved + noise * size * (rng.normal(size=points) + 1j * rng.normal(size=points)) / np.sqrt(2)


def _same_curve(atlas, i, match):
    """Row of the match is i, or the match's linkage is a cognate of row i (scaled)."""
    if match.index == i:
        return True
    L = atlas.linkages
    f = FourBar(L.a[i], L.b[i], L.c[i], L.d[i], branch=int(L.branch[i]), coupler=(L.p[i], L.q[i]))
    g = match.linkage.fourbar
    ratios = np.array([g.a, g.b, g.c, g.d]) / g.d
    return any(np.allclose(np.array(c.lengths) / c.lengths[3], ratios, rtol=1e-6) for c in cognates(f))


def test_query_recovers_linkage_under_similarity_and_noise(atlas):
    rng = np.random.default_rng(2024)
    rows = rng.choice(len(atlas), size=25, replace=False)
    misses = [int(i) for i in rows if not _same_curve(atlas, i, query(atlas, _target(atlas, i, rng), k=1)[0])]
    assert misses == []


def test_query_match_is_placed_on_target(atlas):
    rng = np.random.default_rng(3)
    target = _target(atlas, 123, rng, noise=0.0, points=600)
    best = query(atlas, target, k=3)[0]
    assert isinstance(best, Match) and best.rank == 0 and best.index == 123
    assert best.relative_error < 2e-3
    # the placed linkage, solved by FourBar, runs along the target
    L = atlas.linkages
    lo, hi = L.theta_lo[123], L.theta_hi[123]
    u = np.linspace(0, 2 * np.pi, 2000)          # dense near the dead centres of a rocking input
    theta = u if L.full_turn[123] else 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u)
    f = best.linkage.fourbar
    P = np.concatenate([f.solve(theta).P, FourBar(f.a, f.b, f.c, f.d, branch=-f.branch,
                                                  coupler=f.coupler).solve(theta).P])
    P = best.linkage.place(P[np.isfinite(P)])
    size = np.sqrt(np.mean(np.abs(target - target.mean()) ** 2))
    assert np.max(np.min(np.abs(target[:, None] - P[None, :]), axis=1)) < 1e-2 * size
    assert np.max(np.min(np.abs(best.curve[:, None] - target[None, :]), axis=1)) < 1e-2 * size
    # reported type and transmission angle are the row's
    assert best.kind == L.kind[123] and best.gamma_min == L.gamma_min[123]
    assert best.linkage.fourbar.d == pytest.approx(abs(best.linkage.pivots[1] - best.linkage.pivots[0]))


def test_query_cognates_trace_the_target(atlas):
    rng = np.random.default_rng(8)
    i = int(np.flatnonzero(atlas.linkages.full_turn)[4])
    target = _target(atlas, i, rng, noise=0.0, points=600)
    best = query(atlas, target, k=1)[0]
    assert best.index == i and [c.name for c in best.cognates] == ["AEGK", "DFHK"]
    size = np.sqrt(np.mean(np.abs(target - target.mean()) ** 2))
    original = best.linkage.fourbar.solve(np.linspace(0, 2 * np.pi, 720))
    for cog in best.cognates:
        # driven by the original coupler angle (derivation page of the cognates); a cognate
        # may switch branch at its own limit positions, so each pose is on one of the two
        f = cog.fourbar
        P = np.stack([cog.place(np.nan_to_num(FourBar(f.a, f.b, f.c, f.d, branch=br, coupler=f.coupler)
                                              .solve(original.phi).P, nan=1e6)) for br in (1, -1)])
        gaps = np.min(np.abs(P[:, :, None] - target[None, None, :]), axis=2)
        assert np.max(np.min(gaps, axis=0)) < 1e-2 * size
    A, D = best.cognates[0].pivots[0], best.cognates[1].pivots[0]
    assert abs(A - best.linkage.pivots[0]) < 1e-9 * size and abs(D - best.linkage.pivots[1]) < 1e-9 * size


def test_query_sorted_and_k(atlas):
    rng = np.random.default_rng(1)
    out = query(atlas, _target(atlas, 10, rng), k=6, shortlist=20)
    assert [m.rank for m in out] == list(range(6))
    assert all(a.error <= b.error for a, b in zip(out, out[1:]))


def test_query_resampled_target(atlas):
    from mech.atlas import resample

    rng = np.random.default_rng(4)
    t = resample(_target(atlas, 50, rng), atlas.samples)
    assert query(atlas, t, resampled=True, k=1)[0].index == 50


@pytest.mark.parametrize("kwargs, message", [
    ({"target": [1, 1, 1]}, "Expected `target` that are not all equal"),
    ({"target": [0, 1]}, "Expected `target` of shape"),
    ({"target": [[0, 1, 1j], [0, 2, 2j]]}, "Expected one curve in `target`"),
    ({"target": [0, 1, np.nan]}, "Expected finite `target`"),
    ({"k": 0}, "Expected `k`"), ({"k": 10, "shortlist": 5}, "Expected `k` <= shortlist"),
    ({"resampled": True}, "Expected 128 points in a resampled `target`"),
    ({"resampled": "yes"}, "Expected `resampled`"),
])
def test_query_bad_inputs_named(atlas, kwargs, message):
    call = {"target": [0, 1, 1 + 1j, 1j], **kwargs}
    with pytest.raises(ValueError, match=message):
        query(atlas, **call)


def test_query_atlas_type():
    with pytest.raises(TypeError, match="Expected `atlas` to be a Atlas"):
        query("atlas.parquet", [0, 1, 1j])


def test_refine_improves_a_linkage_not_in_the_atlas(atlas):
    """A four-bar outside the atlas: refinement lowers the error of the best matches."""
    from mech.atlas import refine

    u = np.linspace(0, 2 * np.pi, 400, endpoint=False)
    target = 3 - 1j + 2.0 * np.exp(0.4j) * FourBar(1.0, 2.7, 2.4, 3.1, coupler=(1.5, 0.8)).solve(u).P
    first = query(atlas, target, k=2)
    for m in first:
        better = refine(m, target, iterations=120)
        assert better.refined and better.relative_error < m.relative_error
        assert better.rank == m.rank and better.index == m.index
        # the refined linkage really traces the reported curve, placed on the target
        f = better.linkage.fourbar
        lo, hi = better.theta_range
        theta = u if better.full_turn else 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u)
        P = np.concatenate([f.solve(theta).P, FourBar(f.a, f.b, f.c, f.d, branch=-f.branch,
                                                      coupler=f.coupler).solve(theta).P])
        P = better.linkage.place(P[np.isfinite(P)])
        assert np.max(np.min(np.abs(better.curve[:, None] - P[None, :]), axis=1)) < 0.05 * abs(f.d)


def test_refine_bad_inputs_named(atlas):
    from mech.atlas import refine

    m = query(atlas, [0, 1, 1 + 1j, 1j], k=1)[0]
    with pytest.raises(TypeError, match="Expected `match`"):
        refine("m", [0, 1, 1j])
    with pytest.raises(ValueError, match="Expected `iterations`"):
        refine(m, [0, 1, 1j], iterations=0)
    with pytest.raises(ValueError, match="Expected `target` that are not all equal"):
        refine(m, [1, 1, 1])
