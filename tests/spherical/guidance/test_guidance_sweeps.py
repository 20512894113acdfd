"""Acceptance sweep of the spherical `guidance_fourbars` (issue 24, item 3): for 200 random
and 50 near-degenerate orientation sets, every passing four-bar, checked by the test's own
geometry, carries both circle points on circles about its fixed axes through the five
orientations (`_chord_spread`, 40 digits) and meets them on one assembly branch (the sign of
det[B_j, C_j, D], the spherical triangle of coupler and output crank, never changes)."""

import numpy as np
import pytest

from mech.spherical import guidance_fourbars, planar_orientations, rotation_matrix
from tests.spherical.guidance.test_guidance_properties import _chord_spread, _planar_set, _random_set


def _near_degenerate(rng, k):
    if k % 2 == 0:                                       # two orientations 1e-3 rad apart
        R = _random_set(rng, 5)
        i, j = rng.choice(5, 2, replace=False)
        R[j] = rotation_matrix(rng.normal(size=3), 1e-3) @ R[i]
        return R
    theta, d = _planar_set(rng)                          # near the planar limit
    return planar_orientations(theta, d, 10.0 ** -rng.uniform(3, 5))


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
    wrong = {k: p for k, R in enumerate(_sets(3, 2, seed=5)) if (p := _problems(R))}
    assert not wrong, wrong


@pytest.mark.exhaustive
def test_guidance_fourbars_sweep():
    wrong = {k: p for k, R in enumerate(_sets(200, 50, seed=24)) if (p := _problems(R))}
    assert not wrong, wrong
