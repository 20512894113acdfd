"""Open targets: an arc over half a turn finds the linkage it was taken from, or a cognate."""

import numpy as np
import pytest

from mech.atlas import build_atlas, query
from mech.atlas._planar._sampling import coupler_points
from mech.planar import FourBar, cognates


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(1500, seed=21)


def _arc(atlas, i, u0, rng, noise=1e-3, points=200):
    """Half a cycle of row i's closed curve from u0, moved, turned, scaled, maybe reversed, noisy."""
    arc = coupler_points(atlas.linkages.take([i]).columns(), (u0 + np.pi * np.linspace(0, 1, points))[None, :])[0]
    if rng.random() < 0.5:
        arc = arc[::-1]
    moved = complex(*rng.normal(scale=10, size=2)) + 10 ** rng.uniform(-2, 2) * np.exp(
        1j * rng.uniform(-np.pi, np.pi)) * arc
    size = np.sqrt(np.mean(np.abs(moved - moved.mean()) ** 2))
    return moved + noise * size * (rng.normal(size=points) + 1j * rng.normal(size=points)) / np.sqrt(2)


def _found(atlas, i, match):
    """The match is row i, or one of row i's Roberts-Chebyshev cognates (same shape of linkage)."""
    if match.index == i:
        return True
    f = atlas.linkages.fourbar(i)
    g = match.linkage.fourbar
    mine = np.array([g.a, g.b, g.c, g.d]) / g.d
    return any(np.allclose(np.array(c.lengths) / c.lengths[3], mine, rtol=1e-6) for c in cognates(f))


def test_query_open_arc_exact(atlas):
    """A noise-free half turn of a crank-rocker is found first, with its ends and a tiny error."""
    i = int(np.flatnonzero(atlas.linkages.kind == "crank-rocker")[3])
    rng = np.random.default_rng(0)
    target = _arc(atlas, i, 1.0, rng, noise=0.0)
    best = query(atlas, target, closed=False, k=3)[0]
    assert _found(atlas, i, best)
    assert best.relative_error < 2e-3
    u0, u1 = best.arc
    assert abs((u1 - u0) - np.pi) < 0.05
    assert best.curve.shape == (atlas.samples // 2 + 1,)
    # the placed arc lies on the target
    gap = np.min(np.abs(best.curve[:, None] - target[None, :]), axis=1)
    assert np.max(gap) < 0.02 * np.ptp(target.real) + 0.02 * np.ptp(target.imag)


def test_query_open_arc_caches_window_signatures(atlas):
    """Window signatures: float16, four harmonics per side, 65 windows (the first again at
    the end, so the path of signatures closes), about 2 kB per linkage at 64 starts."""
    from mech.atlas._planar._arcs import ARC_HARMONICS

    query(atlas, [0, 1, 1 + 1j, 2 + 1j], closed=False, k=1)
    sigs, norms, gaps = atlas._arc_cache[(0.5, 64)]
    assert sigs.dtype == np.float16 and sigs.shape == (len(atlas), 65, 4 * ARC_HARMONICS)
    assert norms.dtype == np.float32 and gaps.dtype == np.float32
    assert norms.shape == (len(atlas), 65) and gaps.shape == (len(atlas), 64)
    assert sigs.nbytes / len(atlas) == 2080
    # the gaps are the squared distances between neighbouring windows
    wide = sigs.astype(np.float64)
    assert np.allclose(gaps, np.sum(np.diff(wide, axis=1) ** 2, axis=2), rtol=1e-5, atol=1e-6)


def test_window_segments_rank_half_step_targets_first(atlas):
    """Arcs that start half a window step between two grid starts (the worst place for the
    signature stage), with a random similarity and 1e-3 noise: the distance to the segment
    between neighbouring windows ranks the true row first or second in every trial, where
    the distance to the nearest window alone (the stage before) ranks it far lower in some.

    Targets whose first harmonic is small (|c_1| < 0.1 of the RMS radius, where the
    normalisation of the signature is ill-conditioned and the windows' signatures jump as
    their start moves) are left out and counted."""
    from mech.atlas._planar._arcs import _WINDOW_TABLE, _truncate, arc_signatures, window_distances
    from mech.atlas._planar._signature import _close_arc, _resample_rows, normal_form

    sigs, norms, gaps = arc_signatures(atlas, 0.5, 64)
    wide = sigs.astype(np.float64)
    rng = np.random.default_rng(4)
    seg_ranks, point_ranks = [], []
    for _ in range(24):
        i = int(rng.integers(len(atlas)))
        j = int(rng.integers(64))
        target = _arc(atlas, i, 2 * np.pi * (j + 0.5) / 64 + np.pi / _WINDOW_TABLE, rng)
        t = _resample_rows(target[None], atlas.samples // 2 + 1, False)
        closed = _close_arc(t)[0]
        c = np.fft.fft(closed) / closed.size
        if abs(c[1]) < 0.1 * np.sqrt(np.sum(np.abs(c[1:]) ** 2)):
            continue
        cands = _truncate(normal_form(_close_arc(t), atlas.harmonics).candidates[0], atlas.harmonics)
        best, where, frac = window_distances(sigs, norms, gaps, cands)
        seg_ranks.append(int(np.sum(best < best[i])))
        # nearest window only, in float64, from the definition
        d2 = np.min(np.sum(wide**2, axis=2)[:, :, None] - 2 * wide @ cands.T + np.sum(cands**2, axis=1), axis=(1, 2))
        point_ranks.append(int(np.sum(d2 < d2[i])))
    assert len(seg_ranks) >= 18
    assert max(seg_ranks) <= 1, seg_ranks
    assert max(point_ranks) >= 5, point_ranks


def test_query_open_arc_recovery_quick(atlas):
    """Crank-driven arcs with random similarity and 1e-3 noise: found first in most trials."""
    rng = np.random.default_rng(7)
    rows = rng.choice(np.flatnonzero(atlas.linkages.full_turn), 6, replace=False)
    hits = sum(_found(atlas, int(i), query(atlas, _arc(atlas, int(i), rng.uniform(0, 2 * np.pi), rng),
                                           closed=False, k=1)[0]) for i in rows)
    assert hits >= 5


def test_query_open_arc_recovery_rate(atlas):
    """All kinds of linkage, 30 trials: at least 28 found first (the window stage before
    the segment distances found 21 to 24; the benchmark reports the rate on 10^4 linkages)."""
    rng = np.random.default_rng(11)
    hits = 0
    for _ in range(30):
        i = int(rng.integers(len(atlas)))
        hits += _found(atlas, i, query(atlas, _arc(atlas, i, rng.uniform(0, 2 * np.pi), rng), closed=False, k=1)[0])
    assert hits >= 28


def test_query_open_arc_options(atlas):
    with pytest.raises(ValueError, match="Expected `span` in"):
        query(atlas, [0, 1, 2j], closed=False, span=1.5)
    with pytest.raises(ValueError, match="Expected `target` of shape"):
        query(atlas, [0], closed=False)
    with pytest.raises(ValueError, match="Expected `target` of shape"):
        query(atlas, [0, 1], closed=True)


def test_align_arcs_rocking_input_from_offset_ends(atlas):
    """Noise-free half cycles of rocking inputs, the search started a half sub-arc step off:
    moving the ends in arc length reaches the true ends (the steps in u stalled where the
    coupler point is slow at one end and fast at the other)."""
    from mech.atlas._planar._arcs import align_arcs
    from mech.atlas._planar._signature import _resample_rows

    rng = np.random.default_rng(1)
    rows = np.flatnonzero(atlas.linkages.kind == "triple-rocker")[:12]
    errors = []
    for i in rows:
        u0 = rng.uniform(0, 2 * np.pi)
        arc = coupler_points(atlas.linkages.take([i]).columns(), (u0 + np.pi * np.linspace(0, 1, 200))[None, :])[0]
        t = _resample_rows(arc[None], atlas.samples // 2 + 1, False)[0]
        radius = np.sqrt(np.mean(np.abs(t - t.mean()) ** 2))
        e = align_arcs(t, atlas.linkages.take([i]), np.array([u0 + np.pi / 64]), np.array([u0 + np.pi * 65 / 64]),
                       1 / 64)[0][0]
        errors.append(e / radius)
    assert np.median(errors) < 1e-4
    assert np.sum(np.array(errors) < 2e-3) >= 11


def _first_harmonic(target):
    """|c_1| over the RMS radius of the arc run forward and back (resampled, 256 points)."""
    from mech.atlas import resample

    c = np.abs(np.fft.fft(resample(np.concatenate([target, target[-2:0:-1]]), 256)) / 256)
    return c[1] / np.sqrt(np.sum(c[1:] ** 2))


def test_query_open_arc_small_first_harmonic(atlas):
    """Arcs whose first harmonic is small (|c_1| < 0.2 of the RMS radius: the arc folds back
    on itself, and the window signatures normalised on c_1 are ill-conditioned): the first
    12 such draws are all found first. Without the second set of window signatures
    (normalised on c_2) and the second start per row, 2 of these 12 were missed (rows 1447
    and 1000, first matches 3.9 % and 1.5 % off; 3 of the first 40)."""
    rng = np.random.default_rng(5)
    hits, misses = 0, []
    for _ in range(3000):
        i = int(rng.integers(len(atlas)))
        target = _arc(atlas, i, rng.uniform(0, 2 * np.pi), rng)
        if _first_harmonic(target) >= 0.2:
            continue
        best = query(atlas, target, closed=False, k=1)[0]
        if _found(atlas, i, best):
            hits += 1
        else:
            misses.append((i, best.index, best.relative_error))
        if hits + len(misses) == 12:
            break
    assert hits + len(misses) == 12
    assert not misses, misses


def _benchmark_arc_draws(wanted):
    """Replay the random draws of `benchmarks/bench_atlas.py` (seed 2026) up to its open arcs
    on 10^4 linkages: the generator's state just after each of trials `wanted` drew its row.

    The benchmark first draws 200 closed targets (and one warm-up) on 10^4 and on 10^5
    linkages, then 50 arcs (and one warm-up) on 10^5; the queries draw nothing."""
    rng = np.random.default_rng(2026)

    def skip(n, points, arc, warm=False):
        if not warm:
            rng.integers(n)
        if arc:
            rng.uniform(0, 2 * np.pi)
        else:
            rng.integers(4 * points)
        rng.random()
        rng.normal(scale=10, size=2)
        rng.uniform(-2, 2)
        rng.uniform(-np.pi, np.pi)
        rng.normal(size=points)
        rng.normal(size=points)

    for n in (10_000, 100_000):
        for trial in range(201):
            skip(n, 300, False, warm=trial == 0)
    for trial in range(51):
        skip(100_000, 200, True, warm=trial == 0)
    skip(10_000, 200, True, warm=True)
    found = {}
    for trial in range(max(wanted) + 1):
        state = rng.bit_generator.state
        i = int(rng.integers(10_000))
        if trial in wanted:
            found[i] = np.random.default_rng(0)
            found[i].bit_generator.state = rng.bit_generator.state
        rng.bit_generator.state = state
        skip(10_000, 200, True)
    return found


def test_query_open_arc_benchmark_misses():
    """The two genuine misses of the open-arc benchmark at 10^4 linkages (trials 62 and 189:
    rows 415 and 1962, |c_1|/S = 0.17 and 0.10, first matches 1.7 % and 1.2 % off, the true
    rows ranked 365 and 985 by window signature) are now found first, within 1e-3."""
    big = build_atlas(10_000, seed=0)
    draws = _benchmark_arc_draws((62, 189))
    assert sorted(draws) == [415, 1962]
    for i, rng in draws.items():
        target = _arc(big, i, rng.uniform(0, 2 * np.pi), rng)
        assert _first_harmonic(target) < 0.2
        best = query(big, target, closed=False, k=1)[0]
        assert _found(big, i, best), (i, best.index, best.relative_error)
        assert best.relative_error < 1e-3


def test_open_arc_index_is_stored_with_the_atlas_and_loaded(tmp_path, monkeypatch):
    """Issue 28: the window signatures were built again in every process (minutes at 10^5).
    An atlas read from a folder stores them there; a new reading loads them (building them
    is made to fail here), and an appended part makes them be built anew."""
    import mech.atlas._planar._arcs as arcs
    from mech.atlas import Atlas

    build_atlas(300, seed=4).to_parquet(tmp_path)
    first = Atlas.from_parquet(tmp_path)
    target = _arc(first, 17, 0.5, np.random.default_rng(3), noise=0.0)
    before = query(first, target, closed=False, k=2)
    stored = sorted((tmp_path / "arcs").glob("*.npz"))
    assert [p.name for p in stored] == ["arcs-0.5-64.npz"]

    def no_build(*args, **kwargs):
        raise AssertionError("the window signatures were built again")

    with monkeypatch.context() as m:
        m.setattr(arcs, "normal_form", no_build)
        again = Atlas.from_parquet(tmp_path)
        after = query(again, target, closed=False, k=2)
        assert [x.index for x in after] == [x.index for x in before]
        assert [x.error for x in after] == [x.error for x in before]
        assert np.array_equal(again._arc_cache[(0.5, 64)][0], first._arc_cache[(0.5, 64)][0])
        build_atlas(50, seed=5).to_parquet(tmp_path, append=True)
        grown = Atlas.from_parquet(tmp_path)
        with pytest.raises(AssertionError, match="built again"):
            query(grown, target, closed=False, k=2)
    grown = Atlas.from_parquet(tmp_path)
    query(grown, target, closed=False, k=2)
    assert grown._arc_cache[(0.5, 64)][0].shape[0] == 350
