"""Many four-bars in one call (issue 30, item 2): `solve_fourbars` against `FourBar`, row by row.

Each row of the batch must be the four-bar's own solve: on numba bit for bit (the same
fused kernel per linkage), on NumPy within a few units in the last place of the linkage's
size (the same formulas, evaluated by NumPy on blocks). The subjects cover the rules
`FourBar` applies linkage by linkage: random Grashof and non-Grashof linkages in units
from 1e-3 to 1e3, change points (a parallelogram, s + l = p + q), a kite (solved by
`FourBar` itself), and a dead point within rounding of the motion. An independent check of
the positions: every valid pose closes its loop, |C - B| = b and |C - D| = c.
"""

import numpy as np
import pytest

import mech
from mech.planar import FourBar
from mech.planar.kinematics._fourbar_batch import solve_fourbars


@pytest.fixture
def backend():
    previous = mech.get_backend()
    yield mech.set_backend
    mech.set_backend(previous)


def _subjects():
    rng = np.random.default_rng(30)
    n = 300
    a, b, c = np.exp(rng.uniform(np.log(0.2), np.log(5.0), (3, n)))
    d = np.ones(n)
    unit = 10.0 ** rng.integers(-3, 4, n)
    a, b, c, d = a * unit, b * unit, c * unit, d * unit
    # change points, a kite, and a dead point all but met at theta = 0 (b + c = d - a + tiny)
    special = np.array([[20.0, 50.0, 20.0, 50.0], [20.0, 50.0, 40.0, 10.0], [1.0, 3.0, 3.0, 1.0],
                        [1.0, 1.5, 1.5 + 2e-15, 4.0]])
    a, b, c, d = (np.concatenate([x, s]) for x, s in zip((a, b, c, d), special.T))
    n = a.size
    keep = np.array([max(x) < sum((a[i], b[i], c[i], d[i])) - max(x) for i, x in enumerate(zip(a, b, c, d))])
    p, q = b * rng.uniform(-1, 2, n), b * rng.uniform(-1.5, 1.5, n)
    br = rng.choice([-1, 1], n)
    return tuple(x[keep] for x in (a, b, c, d, p, q, br))


@pytest.mark.parametrize("name", ["numpy", "numba"])
@pytest.mark.parametrize("per_row", [False, True])
def test_rows_are_fourbar_solves(name, per_row, backend):
    if name == "numba":
        pytest.importorskip("numba")
    a, b, c, d, p, q, br = _subjects()
    rng = np.random.default_rng(1)
    k = 64
    theta = rng.uniform(-7, 7, (a.size, k)) if per_row else np.concatenate([[0.0, np.pi], rng.uniform(-7, 7, k - 2)])
    backend(name)
    got = solve_fourbars(a, b, c, d, theta, coupler=(p, q), branch=br)
    assert got.C.shape == (a.size, k)
    worst = 0.0
    for i in range(a.size):
        pose = FourBar(a[i], b[i], c[i], d[i], branch=int(br[i]), coupler=(p[i], q[i])).solve(
            theta[i] if per_row else theta)
        assert np.array_equal(got.valid[i], pose.valid), i
        size = a[i] + b[i] + c[i] + d[i]
        for x, y in ((got.B[i], pose.B), (got.C[i], pose.C), (got.P[i], pose.P)):
            v = pose.valid
            if name == "numba":
                assert np.array_equal(x[v], y[v]), i
            worst = max(worst, float(np.max(np.abs(x[v] - y[v]), initial=0.0)) / size)
    assert worst <= 8 * np.finfo(float).eps
    # independent of the kernels: the loop closes at every valid pose
    v = got.valid
    bb, cc = np.broadcast_to(b[:, None], v.shape), np.broadcast_to(c[:, None], v.shape)
    D = np.broadcast_to(d[:, None], v.shape)
    assert np.allclose(np.abs(got.C - got.B)[v], bb[v], rtol=1e-12)
    assert np.allclose(np.abs(got.C - D)[v], cc[v], rtol=1e-12)


def test_bad_inputs():
    with pytest.raises(ValueError, match="`c` shorter"):
        solve_fourbars([1.0, 1.0], 1.0, [1.0, 9.0], 2.0, [0.0])
    with pytest.raises(ValueError, match="`a` > 0"):
        solve_fourbars([1.0, -1.0], 1.0, 1.0, 1.0, [0.0])
    with pytest.raises(ValueError, match="branch"):
        solve_fourbars(1.0, 2.0, 2.0, 2.0, [0.0], branch=0)
    with pytest.raises(ValueError, match="shape"):
        solve_fourbars([1.0, 1.0], 2.0, 2.0, 2.0, np.zeros((3, 4)))
    with pytest.raises(ValueError, match="theta"):
        solve_fourbars(1.0, 2.0, 2.0, 2.0, [np.nan])


@pytest.mark.parametrize("name", ["numpy", "numba"])
def test_inputs_on_dead_points(name, backend):
    """Inputs at and within rounding of the dead points |BD| = b + c of rockers, in three units."""
    if name == "numba":
        pytest.importorskip("numba")
    backend(name)
    a, b, c, d = np.array([2.0, 2e-3, 2e5]), np.array([3.0, 3e-3, 3e5]), np.array([2.0, 2e-3, 2e5]), np.array([4.0, 4e-3, 4e5])
    dead = 2 * np.arcsin(np.sqrt(21 / 32))              # |BD|^2 = 4 + 32 sin^2(theta / 2) = 25 (unit 1)
    theta = np.concatenate([dead + np.arange(-4, 5) * 2e-16, -dead + np.arange(-4, 5) * 2e-16, [0.0, 1.0]])
    got = solve_fourbars(a, b, c, d, theta, coupler=(b, 0.5 * b))
    for i in range(a.size):
        pose = FourBar(a[i], b[i], c[i], d[i], coupler=(b[i], 0.5 * b[i])).solve(theta)
        assert np.array_equal(got.valid[i], pose.valid)
        v = pose.valid
        for x, y in ((got.B[i], pose.B), (got.C[i], pose.C), (got.P[i], pose.P)):
            assert np.max(np.abs(x[v] - y[v])) <= 8 * np.finfo(float).eps * (a[i] + b[i] + c[i] + d[i])
    assert got.valid[:, :18].any()
