"""`refine` (issue 28): an open match is refined as an open arc; the book and `Match.cognates` agree."""

from pathlib import Path

import numpy as np
import pytest

from mech.atlas import Constraints, build_atlas, query, refine
from mech.planar import FourBar


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(2000, seed=3)


def _traced(fourbar, points=40001):
    """The whole coupler curve of a four-bar by its own solver (both branches over a full
    sweep of the input, the poses that assemble), in its standard frame."""
    theta = np.linspace(0.0, 2 * np.pi, points)
    out = []
    for branch in (1, -1):
        f = FourBar(fourbar.a, fourbar.b, fourbar.c, fourbar.d, branch=branch, coupler=fourbar.coupler)
        P = f.solve(theta).P
        out.append(P[np.isfinite(P)])
    return np.concatenate(out)


@pytest.mark.parametrize("linkage", [FourBar(1.0, 2.7, 2.4, 3.1, coupler=(1.5, 0.8)),
                                     FourBar(10, 40, 30, 35, coupler=(20, 10))])
def test_refine_keeps_an_open_arc_open(atlas, linkage):
    """Issue 28: `refine` turned an open arc into a closed fit with a larger error, covering
    part of the arc. Now the refined match is open, its error no larger, its sub-arc runs
    from the target's first point to its last, and it lies on the refined linkage's curve."""
    arc = 3 - 1j + 2 * np.exp(0.4j) * linkage.solve(np.linspace(0.3, 0.3 + np.pi, 200)).P
    start = query(atlas, arc, k=1, closed=False)[0]
    better = refine(start, arc)
    assert better.arc is not None and better.refined
    assert better.relative_error <= start.relative_error
    size = np.sqrt(np.mean(np.abs(arc - arc.mean()) ** 2))
    assert abs(better.curve[0] - arc[0]) < 0.02 * size and abs(better.curve[-1] - arc[-1]) < 0.02 * size
    # every target point near the refined arc, and the refined arc on the linkage's curve
    gap = np.min(np.abs(arc[:, None] - better.curve[None, :]), axis=1)
    assert gap.max() < 0.05 * size
    curve = better.linkage.place(_traced(better.linkage.fourbar))
    assert np.min(np.abs(better.curve[:, None] - curve[None, :]), axis=1).max() < 5e-3 * size


def test_refine_open_with_constraints_turns_the_crank(atlas):
    arc = FourBar(10, 40, 30, 35, coupler=(20, 10)).solve(np.linspace(0.0, np.pi, 200)).P
    start = query(atlas, arc, k=1, closed=False)[0]
    better = refine(start, arc, constraints=Constraints())
    if better.refined:
        assert better.arc is not None and better.full_turn and better.gamma_min >= np.radians(30) - 1e-9
        assert better.relative_error <= start.relative_error


def test_book_and_slider_crank_cognates_agree():
    """Issue 28: the book said slider-crank matches have no cognates; a match carries one."""
    sliders = build_atlas(200, seed=5, mechanism="slider-crank")
    match = query(sliders, sliders.curves(7)[0], k=1)[0]
    assert len(match.cognates) == 1 and match.cognates[0].name == "cognate"
    page = (Path(__file__).parents[2] / "book" / "atlas" / "find-a-linkage.md").read_text()
    flat = " ".join(page.split())
    assert "have no cognates" not in flat
    assert "slider-crank matches carry their one cognate" in flat
