"""`Linkage.solve` over more inputs than one block (issue 16, item 1).

A large solve is cut into blocks (`mech.planar.kinematics._linkage._blocks`). These tests
shrink the block so that small arrays span many blocks, and check that

- the blocked solve equals, bit for bit, the concatenation of separate small solves (each
  under the block size, so solved in one piece), for every field of the solution;
- the branch rule holds across block boundaries: the poses are those of the mpmath
  reference solver (law of cosines, `linkage_reference`) on the poses either side of each
  boundary, and a parallelogram stays a parallelogram through change points that fall on a
  boundary (the bridge across a change point sees one block only).
"""

import math

import mpmath
import numpy as np
import pytest

from mech.planar import Guide, Linkage
from mech.planar.kinematics._linkage import _blocks as _linkage_blocks
from mech.planar.special import _library as lib
from tests.planar import linkage_reference as ref

BLOCK = 1000


@pytest.fixture
def small_blocks(monkeypatch):
    monkeypatch.setattr(_linkage_blocks, "BLOCK", BLOCK)


def _parallelogram():
    return (Linkage({"A": 0, "D": 3}).crank("crank", pivot="A", tip="B", length=1)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(3, 1)))


def _sliding():
    """Crank, guide-bar (RPR), RRP on the turning guide, PRP and RPP: every slide kind."""
    return (Linkage({"A": 0, "C": 60 + 0j}).crank("crank", pivot="A", tip="B", length=30)
            .rpr(("guide", "block"), pins=("C", "B"), offset=4.0)
            .rrp(("rod", "slider"), pin="B", guide=Guide("guide", 10 - 2j, 0.4), joint="S", length=35)
            .prp(("b1", "b2"), guides=(Guide("guide", 5 + 4j, 0.0), Guide("ground", 100j, 0.3)), joint="P")
            .rpp(("pinned", "yoke"), pin="B", guide=Guide("guide", -6 + 1j, 0.2), angle=1.2, point="J",
                 offset=0.5))


def _actuated():
    """Two drivers, a crank and an actuator length."""
    return (Linkage({"O": 0, "H": 40 + 0j}).crank("boom", pivot="H", tip="T", length=50)
            .rrr(("cyl", "rod"), pins=("O", "T"), joint="X", lengths=("stroke", 20.0)))


def _arrays(sol):
    """Every array of a solution, keyed by (table, name), with its shape kept."""
    out = {("valid",): sol.valid}
    for table in ("points", "velocities", "accelerations", "omegas", "alphas", "failures"):
        for name, value in getattr(sol, table).items():
            out[(table, name)] = np.asarray(value)
    for name in sol.angles:
        out[("direction", name)] = sol.direction(name)
    for key, slide in sol.slides.items():
        for part in ("s", "direction", "v", "a", "coriolis"):
            value = getattr(slide, part)
            if value is not None:
                out[("slide", key, part)] = np.broadcast_to(value, sol.valid.shape)
    return out


def _assert_identical(got, want):
    assert set(got) == set(want)
    for key, value in want.items():
        assert got[key].shape == value.shape, key
        assert got[key].dtype == value.dtype, key
        assert np.array_equal(got[key], value, equal_nan=True), key


@pytest.mark.parametrize("make, lo, hi", [
    (lib.jansen_linkage, -9.0, 9.0),
    (lib.watt_six_bar, -9.0, 9.0),
    (_parallelogram, -9.0, 9.0),       # change points at multiples of pi: the bridge
    (_sliding, -4.0, 4.0),             # does not assemble everywhere: failures, NaN
])
@pytest.mark.parametrize("order", [0, 2])
def test_blocked_solve_equals_concatenated_small_solves(small_blocks, make, lo, hi, order):
    linkage = make()
    n = 7 * BLOCK + 123
    theta = np.linspace(lo, hi, n)
    omega = np.linspace(0.5, 2.0, n)
    blocked = _arrays(linkage.solve(theta, order=order, omega=omega, alpha=0.3))
    # pieces of 300 poses (below the block size, so each solved in one piece) that do not
    # line up with the blocks
    pieces = [slice(k, k + 300) for k in range(0, n, 300)]
    solutions = [linkage.solve(theta[p], order=order, omega=omega[p], alpha=0.3) for p in pieces]
    want = {key: np.concatenate([_arrays(s)[key] for s in solutions]) for key in _arrays(solutions[0])}
    _assert_identical(blocked, want)


def test_blocked_solve_broadcasts_two_drivers(small_blocks):
    """Inputs of shapes (m, 1) and (1, k): blocks run over the flattened broadcast shape."""
    linkage = _actuated()
    boom = np.linspace(1.5, 2.2, 61)[:, None]
    stroke = np.linspace(55.0, 65.0, 50)[None, :]
    sol = linkage.solve({"boom": boom, "stroke": stroke}, order=2, omega={"boom": 0.0, "stroke": 1.0})
    got = _arrays(sol)
    assert sol.valid.shape == (61, 50)
    for i in (0, 19, 20, 40, 60):          # rows that straddle block boundaries (1000 = 20 x 50)
        row = _arrays(linkage.solve({"boom": boom[i], "stroke": stroke[0]}, order=2,
                                    omega={"boom": 0.0, "stroke": 1.0}))
        for key, value in row.items():
            assert np.array_equal(got[key][i], value, equal_nan=True), key


def test_branch_holds_across_block_boundaries(small_blocks):
    """Jansen's leg over three turns in blocks: each boundary's poses are the reference's."""
    linkage = lib.jansen_linkage()
    n = 6 * BLOCK
    theta = np.linspace(-3 * math.pi, 3 * math.pi, n)
    sol = linkage.solve(theta, order=1)
    assert sol.valid.all()
    for k in range(BLOCK, n, BLOCK):
        for i in (k - 1, k):
            want_p, want_v = ref.rates(ref.jansen_positions, mpmath.mpf(float(theta[i])))[:2]
            for name in ("B", "C", "D", "E", "F"):
                assert abs(complex(sol.points[name][i]) - complex(want_p[name])) < 1e-12 * 100
                assert abs(complex(sol.velocities[name][i]) - complex(want_v[name])) < 1e-10 * 100


def test_parallelogram_stays_one_through_change_points_on_block_boundaries(small_blocks):
    """Change points (theta = k pi) placed at the first and last pose of blocks."""
    linkage = _parallelogram()
    n = 8 * BLOCK
    # theta = pi at index BLOCK (a block's first pose) and 2 pi at 2 BLOCK - 1 (a last pose)
    step = math.pi / (BLOCK - 1)
    theta = (np.arange(n) - BLOCK) * step + math.pi
    theta[2 * BLOCK - 1] = 2 * math.pi
    sol = linkage.solve(theta, order=2)
    assert sol.valid.all()
    B, C = sol.points["B"], sol.points["C"]
    # a parallelogram: C - B = D - A = 3 at every pose, with the coupler not turning
    assert np.max(np.abs(C - B - 3.0)) < 1e-12
    assert np.max(np.abs(sol.omegas["coupler"])) < 1e-9
    assert np.max(np.abs(sol.omegas["rocker"] - 1.0)) < 1e-9
