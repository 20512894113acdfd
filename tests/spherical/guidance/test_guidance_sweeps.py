"""Acceptance sweep of the spherical `guidance_fourbars` (issue 24, item 3): for 200 random
and 50 near-degenerate orientation sets, and 250 taken from the coupler of a random
spherical four-bar (random sets seldom have a passing design), every passing four-bar, checked by the test's own
geometry, carries both circle points on circles about its fixed axes through the five
orientations (`_chord_spread`, 40 digits) and meets them on one assembly branch (the sign of
det[B_j, C_j, D], the spherical triangle of coupler and output crank, never changes)."""

import numpy as np
import pytest

from mech.spherical import SphericalFourBar, guidance_fourbars, planar_orientations, rotation_matrix
from tests.spherical.guidance.test_guidance_properties import _chord_spread, _planar_set, _random_set


def _near_degenerate(rng, k):
    if k % 2 == 0:                                       # two orientations 1e-3 rad apart
        R = _random_set(rng, 5)
        i, j = rng.choice(5, 2, replace=False)
        R[j] = rotation_matrix(rng.normal(size=3), 1e-3) @ R[i]
        return R
    theta, d = _planar_set(rng)                          # near the planar limit
    return planar_orientations(theta, d, 10.0 ** -rng.uniform(3, 5))


def _linkage_sets(n, seed):
    """Five orientations of the coupler of a random spherical four-bar (arcs: crank 0.2 to
    0.4, the others 0.6 to 1.2) at increasing crank angles, so that designs pass; `n`
    spread over up to 300 deg and `n // 4` with two crank angles 1e-3 rad apart."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n + n // 4:
        a = rng.uniform(0.2, 0.4)
        b, c, d = rng.uniform(0.6, 1.2, 3)
        crank = np.sort(rng.uniform(0.0, np.radians(300.0), 5))
        if len(out) >= n:
            crank[2] = crank[1] + 1e-3
        pose = SphericalFourBar(a, b, c, d, branch=int(rng.choice([-1, 1]))).solve(crank)
        if not np.all(pose.valid):
            continue
        B, C = np.asarray(pose.B, float), np.asarray(pose.C, float)
        n1 = C - np.sum(C * B, axis=1)[:, None] * B
        n1 /= np.linalg.norm(n1, axis=1)[:, None]
        R = np.stack([B, n1, np.cross(B, n1)], axis=2)        # columns: the coupler's frame
        turn = rotation_matrix(rng.normal(size=3), rng.uniform(0.2, 1.0))
        out.append(R @ turn)                                  # a body frame off B
    return out


def _sets(n_random, n_near, seed):
    rng = np.random.default_rng(seed)
    return [_random_set(rng, 5) for _ in range(n_random)] + [_near_degenerate(rng, k) for k in range(n_near)]


def _problems(R):
    try:
        result = guidance_fourbars(R)
    except ValueError:
        return []
    out = []
    for c in result.passing:
        zB, zC = np.asarray(c.input_dyad.circle_point), np.asarray(c.output_dyad.circle_point)
        for crank in (c.input_dyad, c.output_dyad):
            spread = _chord_spread(R, crank.circle_point, crank.centre_point)
            if not spread <= 1e-7:
                out.append(f"a circle point leaves its circle by {spread:.3g}")
        D = np.asarray(c.output_dyad.centre_point)
        side = [np.linalg.det(np.stack([Rj @ zB, Rj @ zC, D])) for Rj in R]
        if not (all(v > 0 for v in side) or all(v < 0 for v in side)):
            out.append("the orientations lie on two branches")
    return out


def test_a_few_sets():
    sets = _sets(3, 2, seed=5) + _linkage_sets(2, seed=5)
    assert sum(len(guidance_fourbars(R).passing) for R in sets) >= 2
    wrong = {k: p for k, R in enumerate(sets) if (p := _problems(R))}
    assert not wrong, wrong


@pytest.mark.exhaustive
def test_guidance_fourbars_sweep():
    sets = _sets(200, 50, seed=24) + _linkage_sets(200, seed=24)
    assert sum(len(guidance_fourbars(R).passing) for R in sets) >= 200
    wrong = {k: p for k, R in enumerate(sets) if (p := _problems(R))}
    assert not wrong, wrong
