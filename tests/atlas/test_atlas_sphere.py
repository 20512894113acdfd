"""The spherical atlas: signatures invariant to rotations of the sphere, and recovery under noise."""

import numpy as np
import pytest

from mech.atlas import SphereAtlas, build_sphere_atlas, query_sphere, sphere_signature


@pytest.fixture(scope="module")
def atlas():
    return build_sphere_atlas(600, seed=4)


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


def test_build_sphere_atlas_cranks_turn(atlas):
    assert len(atlas) == 600 and set(np.unique(atlas.kind)) <= {"crank-rocker", "double-crank"}
    assert np.all(np.isfinite(atlas.signatures))
    again = build_sphere_atlas(600, seed=4)
    assert np.array_equal(again.signatures, atlas.signatures)
    idx = [0, 17]
    assert np.allclose(sphere_signature(atlas.curves(idx)), atlas.signatures[idx], atol=1e-12)


def test_query_sphere_recovery_under_rotation_and_noise(atlas):
    """A random rotation of the sphere, restart, reversal and 1e-3 noise: the row comes first."""
    rng = np.random.default_rng(2)
    hits = 0
    for _ in range(20):
        i = int(rng.integers(len(atlas)))
        c = np.roll(atlas.curves(i, 300)[0], int(rng.integers(300)), axis=0)
        if rng.random() < 0.5:
            c = c[::-1]
        x = c @ _rotation(rng).T + 1e-3 * rng.normal(size=c.shape)
        best = query_sphere(atlas, x / np.linalg.norm(x, axis=1)[:, None], k=2)[0]
        hits += best.index == i
        if best.index == i:
            assert best.error < 1e-2
    assert hits >= 19


def test_query_sphere_rotation_places_curve(atlas):
    rng = np.random.default_rng(5)
    R = _rotation(rng)
    target = atlas.curves(3, 256)[0] @ R.T
    best = query_sphere(atlas, target, k=1)[0]
    assert best.index == 3 and best.error < 2e-3 and best.direction == 1
    assert np.allclose(best.rotation, R, atol=1e-2)
    assert np.max(np.min(np.linalg.norm(best.curve[:, None] - target[None], axis=2), axis=1)) < 0.05


def test_query_sphere_errors(atlas):
    with pytest.raises(TypeError, match="Expected `atlas` to be a SphereAtlas"):
        query_sphere("atlas", np.eye(3))
    with pytest.raises(ValueError, match="Expected one curve in `target`"):
        query_sphere(atlas, np.ones((2, 5, 3)))
    assert isinstance(atlas, SphereAtlas)


def test_sphere_signature_derivation_checks_pass():
    """The derivation page generates no code, so the freshness test skips it: run its checks here."""
    pytest.importorskip("sympy")
    from derivations import __main__ as runner

    page = next(p for p in runner.notebooks() if p.stem == "sphere_signature")
    namespace = runner.run(page)
    assert namespace["worst"] < 1e-12 and namespace["apart"] > 1e-4
