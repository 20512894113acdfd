"""The spherical atlas: signatures invariant to rotations of the sphere, and the search: closed
targets and open arcs recovered under a random rotation, start, direction and noise, and
refinement onto a linkage that is not in the atlas."""

import numpy as np
import pytest

from mech.atlas import (SphereAtlas, build_sphere_atlas, find_sphere_linkages, query_sphere, refine_sphere,
                        sample_sphere_fourbars, sphere_signature)
from mech.atlas._sphere._sampling import sphere_points
from mech.spherical import SphericalFourBar

#: Relative noise added to every target (of the RMS distance of its points from their mean).
NOISE = 1e-3


@pytest.fixture(scope="module")
def atlas():
    return build_sphere_atlas(600, seed=4)


@pytest.fixture(scope="module")
def big():
    """10^4 spherical four-bars (full-turn and rocking inputs): builds in a few seconds."""
    return build_sphere_atlas(10_000, seed=4)


def _rotation(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def _curve(rng, points=200):
    t = 2 * np.pi * np.arange(points) / points
    coef = rng.normal(size=(3, 5)) + 1j * rng.normal(size=(3, 5))
    coef[2, 2] += 3.0
    x = np.stack([sum(c * np.exp(1j * k * t) for k, c in enumerate(row, start=-2)).real for row in coef], axis=1)
    return x / np.linalg.norm(x, axis=1)[:, None]


@pytest.mark.parametrize("seed", range(5))
def test_sphere_signature_rotation_start_direction(seed):
    rng = np.random.default_rng(seed)
    x = _curve(rng)
    moved = np.roll(x[::-1], int(rng.integers(200)), axis=0) @ _rotation(rng).T
    assert np.max(np.abs(sphere_signature(moved, resampled=True) - sphere_signature(x, resampled=True))) < 1e-12


def test_sphere_signature_tells_curves_apart():
    rng = np.random.default_rng(9)
    x, y = _curve(rng), _curve(rng)
    assert np.max(np.abs(sphere_signature(x) - sphere_signature(y))) > 1e-3


def test_sphere_signature_shapes_and_errors():
    rng = np.random.default_rng(1)
    stack = np.stack([_curve(rng), _curve(rng)])
    assert sphere_signature(stack, harmonics=4).shape == (2, 15)
    with pytest.raises(ValueError, match="Expected `points` of shape"):
        sphere_signature(np.ones((5, 2)))
    with pytest.raises(ValueError, match="Expected `points` without zero vectors"):
        sphere_signature(np.zeros((5, 3)))


def _noisy(rng, c):
    radius = np.sqrt(np.mean(np.sum((c - c.mean(axis=0)) ** 2, axis=1)))
    x = c + NOISE * radius * rng.normal(size=c.shape)
    return x / np.linalg.norm(x, axis=1)[:, None]


def test_sphere_signature_open_arcs():
    """An open arc's signature ignores rotation and direction; the closed one differs."""
    rng = np.random.default_rng(3)
    x = _curve(rng, 400)[:150]
    moved = x[::-1] @ _rotation(rng).T
    s = sphere_signature(x, closed=False, samples=512)
    assert np.max(np.abs(sphere_signature(moved, closed=False, samples=512) - s)) < 1e-4
    assert np.max(np.abs(sphere_signature(x) - s)) > 1e-3


def test_build_sphere_atlas_rows(atlas):
    assert len(atlas) == 600 and np.all(atlas.linkages.usable)
    assert np.all(np.isfinite(atlas.signatures))
    again = build_sphere_atlas(600, seed=4)
    assert np.array_equal(again.signatures, atlas.signatures)
    idx = [0, 17]
    assert np.allclose(sphere_signature(atlas.curves(idx, 2048)), atlas.signatures[idx], atol=2e-3)


def test_query_sphere_closed_recovery_50_trials(big):
    """50 rows of a 10^4 atlas under a random rotation of the sphere, start, direction and
    1e-3 relative noise: the row comes first every time, fitted to within 1 % of the size."""
    rng = np.random.default_rng(2)
    for _ in range(50):
        i = int(rng.integers(len(big)))
        c = np.roll(big.curves(i, 300)[0], int(rng.integers(300)), axis=0)
        if rng.random() < 0.5:
            c = c[::-1]
        best = query_sphere(big, _noisy(rng, c @ _rotation(rng).T), k=3)[0]
        assert best.index == i
        assert best.relative_error < 1e-2


def test_query_sphere_open_half_turn_recovery():
    """Half a cycle of an atlas curve (half a turn of a crank that turns fully), from a random
    start, rotated, reversed half of the time, with 1e-3 noise: the row comes first."""
    atlas = build_sphere_atlas(1000, seed=6)
    rng = np.random.default_rng(7)
    hits, trials = 0, 20
    for _ in range(trials):
        i = int(rng.integers(len(atlas)))
        u = rng.uniform(0, 2 * np.pi) + np.linspace(0, np.pi, 200)
        c = sphere_points(atlas.linkages.take([i]).columns(), u[None])[0]
        if rng.random() < 0.5:
            c = c[::-1]
        best = query_sphere(atlas, _noisy(rng, c @ _rotation(rng).T), k=2, closed=False)[0]
        hits += best.index == i
        assert best.relative_error < 2e-2
        if best.index == i:
            # the part found: about half a cycle of the curve parameter
            assert abs((best.arc[1] - best.arc[0]) - np.pi) < 0.3
    assert hits == trials


def test_query_sphere_placed_linkage_traces_target(atlas):
    """`placed` (the linkage with frame = rotation) traces the target: checked by solving it."""
    rng = np.random.default_rng(5)
    R = _rotation(rng)
    i = int(np.flatnonzero(atlas.linkages.full_turn)[2])
    theta = 2 * np.pi * np.arange(256) / 256
    target = atlas.fourbar(i).solve(theta).P @ R.T
    best = query_sphere(atlas, target, k=1)[0]
    assert best.index == i and best.error < 1e-3 and best.full_turn
    assert np.allclose(best.rotation, R, atol=1e-3)
    assert np.max(np.abs(best.placed.solve(theta).P - target)) < 1e-3
    j = int(np.flatnonzero(~atlas.linkages.full_turn)[0])          # a rocking input
    rocking = atlas.curves(j, 300)[0] @ R.T
    m = query_sphere(atlas, rocking, k=1)[0]
    assert m.index == j and not m.full_turn and m.gamma_min == 0.0
    f = m.placed                      # the closed curve runs over both branches of the rocking input
    other = SphericalFourBar(f.a, f.b, f.c, f.d, branch=-f.branch, coupler=f.coupler, frame=f.frame)
    P = np.vstack([f.coupler_curve(20000)[1], other.coupler_curve(20000)[1]])
    P = P[np.all(np.isfinite(P), axis=1)]
    # RMS, not max: equal steps of theta leave gaps at the limit positions, where P is fast
    near = np.min(np.linalg.norm(rocking[:, None] - P[None], axis=2), axis=1)
    assert np.sqrt(np.mean(near**2)) < 1e-3


@pytest.fixture(scope="module")
def outside():
    """A closed target from a spherical four-bar drawn with another seed (not in the atlas)."""
    s = sample_sphere_fourbars(50, seed=999)
    i = int(np.flatnonzero(s.usable & s.full_turn)[0])
    R = _rotation(np.random.default_rng(4))
    return s.take([i]).curves(400)[0] @ R.T


def test_refine_sphere_not_in_atlas(big, outside):
    """Refinement of the first match on the real curve error: stated error 1 % of the size."""
    first = query_sphere(big, outside, k=1)[0]
    better = refine_sphere(first, outside, samples=64, iterations=400)
    assert better.refined and better.error < first.error
    assert better.relative_error < 1e-2
    # checked another way: every target point lies near the refined, placed linkage's curve
    _, P = better.placed.coupler_curve(6000)
    P = P[np.all(np.isfinite(P), axis=1)]
    radius = np.sqrt(np.mean(np.sum((outside - outside.mean(axis=0)) ** 2, axis=1)))
    near = np.min(np.linalg.norm(outside[:, None] - P[None], axis=2), axis=1)
    assert np.sqrt(np.mean(near**2)) < 1e-2 * radius


def test_find_sphere_linkages_multistart(atlas, outside):
    found = find_sphere_linkages(atlas, outside, starts=2, samples=48, iterations=150)
    assert [m.rank for m in found] == list(range(len(found))) and all(m.refined for m in found)
    assert found[0].error <= found[-1].error
    assert found[0].error < query_sphere(atlas, outside, k=1)[0].error


def test_query_sphere_errors(atlas):
    with pytest.raises(TypeError, match="Expected `atlas` to be a SphereAtlas"):
        query_sphere("atlas", np.eye(3))
    with pytest.raises(ValueError, match="Expected one curve in `target`"):
        query_sphere(atlas, np.ones((2, 5, 3)))
    with pytest.raises(ValueError, match="Expected `span`"):
        query_sphere(atlas, _curve(np.random.default_rng(1)), closed=False, span=1.5)
    arc = query_sphere(atlas, _curve(np.random.default_rng(1))[:50], closed=False, k=1)[0]
    with pytest.raises(ValueError, match="Expected `match` of a closed target"):
        refine_sphere(arc, np.eye(3))
    assert isinstance(atlas, SphereAtlas)


def test_sphere_signature_derivation_checks_pass():
    """The derivation page generates no code, so the freshness test skips it: run its checks here."""
    pytest.importorskip("sympy")
    from derivations import __main__ as runner

    page = next(p for p in runner.notebooks() if p.stem == "sphere_signature")
    namespace = runner.run(page)
    assert namespace["worst"] < 1e-12 and namespace["apart"] > 1e-4


def test_rotation_spectrum_needs_no_frame():
    """The spectra the search adds to its short list, ``|C_k|`` over the three coordinates, read
    from the signature, equal the DFT of the raw coordinates (no principal frame), turned or not."""
    from mech.atlas._sphere._store import spectra

    rng = np.random.default_rng(8)
    x = _curve(rng, 256)
    direct = np.linalg.norm(np.fft.rfft(x @ _rotation(rng).T, axis=0)[:9], axis=1) / 256
    assert np.max(np.abs(spectra(sphere_signature(x, resampled=True)) - direct)) < 1e-12


@pytest.mark.parametrize("closed", [True, False])
def test_query_sphere_rejects_a_target_of_one_point(atlas, closed):
    """A target whose points are all one point has no size: the relative error was inf (with
    a divide-by-zero warning) instead of an error naming `target`."""
    with pytest.raises(ValueError, match=r"Expected `target` that are not all equal"):
        query_sphere(atlas, np.tile([0.0, 0.6, 0.8], (10, 1)), closed=closed, k=1, starts=4)
    # the same point given at other lengths (all scaled to the sphere) is one point too
    with pytest.raises(ValueError, match=r"Expected `target` that are not all equal"):
        query_sphere(atlas, np.array([[0.0, 0.6, 0.8], [0.0, 6.0, 8.0], [0.0, 0.3, 0.4]]), k=1)


def test_build_sphere_atlas_with_no_usable_linkage_is_named():
    """A min_transmission that no sample meets made a block with no linkage, and the build
    failed in NumPy ('cannot reshape array of size 0'); now, as in the planar build, the
    error names the design space after the blocks tried."""
    with pytest.raises(ValueError, match=r"Expected `arcs`, `coupler_arc` and `min_transmission`.*none in"):
        build_sphere_atlas(20, min_transmission=1.5, block=16)
