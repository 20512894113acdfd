"""`Linkage.solve` by the compiled loop (issue 30, item 1) against the NumPy path.

The loop repeats the NumPy path's operations pose by pose (the generated group functions,
the modes through change points, dead points, the finiteness check, the unit of length),
so the two agree bit for bit: every field of the solution, its validity and the first
failing group are compared exactly, NaN matching NaN. The NumPy path is checked against
independent oracles in ``test_linkage.py``; here it is the reference. Subjects: Jansen's
leg, the Watt and Stephenson six-bars, a parallelogram four-bar (change points at 0 and
pi, where the poses next to them are bridged by the NumPy path), a five-bar driven by
two cranks, and a linkage in a unit of length near 1e-200.
"""

import math
import subprocess
import sys

import numpy as np
import pytest

import mech
from mech.planar import Linkage
from mech.planar.kinematics._linkage import _compiled as _linkage_compiled
from mech.planar.special import _library as lib

numba = pytest.importorskip("numba")


@pytest.fixture
def backend():
    previous = mech.get_backend()
    yield mech.set_backend
    mech.set_backend(previous)


def _fields(sol):
    out = {("valid",): sol.valid}
    for kind, table in (("P", sol.points), ("V", sol.velocities), ("A", sol.accelerations),
                        ("W", sol.omegas), ("AL", sol.alphas), ("dir", sol._dirs), ("fail", sol.failures)):
        for key, value in table.items():
            out[(kind, key)] = np.asarray(value)
    return out


def _same(linkage, inputs, order, backend, **rates):
    backend("numpy")
    a = _fields(linkage.solve(inputs, order=order, **rates))
    backend("numba")
    b = _fields(linkage.solve(inputs, order=order, **rates))
    assert a.keys() == b.keys()
    for key in a:
        x, y = np.broadcast_arrays(a[key], b[key])
        if x.dtype == bool:
            assert np.array_equal(x, y), key
        else:
            same = (x == y) | (np.isnan(x) & np.isnan(y))
            assert same.all(), (key, np.flatnonzero(~same)[:5])
    return b


# each order of each topology is a loop of its own, compiled in seconds on a cold cache: the
# fast run compiles order 0 only (orders 1 and 2 are checked by the full run and by the
# five-bar and tiny-unit tests below)
ORDERS = [0, pytest.param(1, marks=pytest.mark.slow), pytest.param(2, marks=pytest.mark.slow)]


@pytest.mark.parametrize("make", [lib.jansen_linkage, lib.watt_six_bar, lib.stephenson_six_bar])
@pytest.mark.parametrize("order", ORDERS)
def test_bit_identical_to_numpy(make, order, backend):
    rng = np.random.default_rng(30)
    theta = rng.uniform(-20.0, 20.0, 1000)
    omega, alpha = rng.uniform(-3, 3, 1000), 0.7
    got = _same(make(), theta, order, backend, omega=omega, alpha=alpha)
    assert got[("valid",)].any()


def _parallelogram():
    return (Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(35, 10))
            .point("P", link="coupler", at=12 + 5j))


@pytest.mark.parametrize("order", ORDERS)
def test_change_points(order, backend):
    """Poses at, next to and within the bridge of the change points 0 and pi, and a turn."""
    lk = _parallelogram()
    near = np.concatenate([k * math.pi + np.array([0.0, 1e-15, -1e-12, 1e-9, 3e-3, -5e-3, 1e-2, -2e-2])
                           for k in range(-4, 5)])
    theta = np.concatenate([near, np.linspace(-7.0, 7.0, 997)])
    got = _same(lk, theta, order, backend)
    assert got[("valid",)].all()
    # the parallelogram stays one through the change points: the rocker turns with the crank
    assert np.allclose(got[("dir", "rocker")], got[("dir", "crank")], atol=1e-12)


def test_two_cranks_and_shapes(backend):
    """A five-bar driven by two cranks (modes fixed by ``branch``), inputs of shape (40, 25)."""
    lk = (Linkage({"A": 0, "E": 4}).crank("left", pivot="A", tip="B", length=2)
          .crank("right", pivot="E", tip="D", length=2)
          .rrr(("c1", "c2"), pins=("B", "D"), joint="C", lengths=(3, 3)))
    rng = np.random.default_rng(5)
    inputs = {"left": rng.uniform(0, 2 * math.pi, (40, 25)), "right": rng.uniform(0, 2 * math.pi, 25)}
    got = _same(lk, inputs, 2, backend, omega={"left": 1.5, "right": -0.5})
    assert got[("valid",)].shape == (40, 25)
    assert 0 < got[("valid",)].sum() < 1000


def test_tiny_unit(backend):
    """Lengths near 1e-200: the loop solves in the same power-of-two unit."""
    lk = lib.watt_six_bar(crank=20e-200, coupler=50e-200, rocker=45e-200, frame=50e-200, lever=44e-200)
    _same(lk, np.linspace(-4, 4, 600), 2, backend)


def test_read_only_and_cached(backend):
    backend("numba")
    lk = lib.watt_six_bar()
    sol = lk.solve(np.linspace(0, 1, 600))
    with pytest.raises(ValueError):
        sol.points["C"][0] = 0
    # another linkage of the same topology reuses the compiled loop
    before = len(_linkage_compiled._KERNELS)
    lib.watt_six_bar(crank=21.0).solve(np.linspace(0, 1, 600))
    assert len(_linkage_compiled._KERNELS) == before


def test_auto_small_solve_and_import_stay_without_numba():
    code = ("import sys, numpy as np, mech\n"
            "from mech.planar.special import _library as lib\n"
            "assert 'numba' not in sys.modules\n"
            "lib.jansen_linkage().solve(np.linspace(0, 1, 100))\n"
            "print('numba' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
