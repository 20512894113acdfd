"""`OpenChain.solve` by the compiled loop (issue 30) against the NumPy path.

The loop repeats the NumPy path's sums and cross products in its order, calling the same
generated ``hd_entries``; NumPy may hand its 4 x 4 products to BLAS and takes ``sin`` and
``cos`` from its own routines, so the bound is 4 ulp per joint of each field's largest
magnitude (2.2 ulp measured on a five-joint chain). The NumPy path is checked against a
50-digit mpmath product in ``test_chain.py``; here it is the reference.

One loop serves every chain and order; compiling it takes tens of seconds on a loaded
machine with a cold numba cache, so these tests are marked ``slow``.
"""

import numpy as np
import pytest

import mech
from mech.spatial._chain import Joint, OpenChain, example_2_25_manipulator

numba = pytest.importorskip("numba")
pytestmark = pytest.mark.slow

FIELDS = ("M", "P", "e1", "e2", "e3", "vP", "omega", "aP", "alpha")


@pytest.fixture
def backend():
    previous = mech.get_backend()
    yield mech.set_backend
    mech.set_backend(previous)


def _agree(chain, q, order, backend, qdot=None, qddot=None, point=(0.0, 0.0, 0.0)):
    backend("numpy")
    a = chain.solve(q, order, qdot, qddot, point=point)
    backend("numba")
    b = chain.solve(q, order, qdot, qddot, point=point)
    bound = 4 * len(chain.joints) * np.finfo(float).eps
    for name in FIELDS:
        if not hasattr(a, name):
            assert not hasattr(b, name), name
            continue
        x, y = getattr(a, name), getattr(b, name)
        assert x.shape == y.shape, name
        assert np.all(np.abs(x - y) <= bound * np.max(np.abs(x))), name
    return b


def _random_chain(rng, count):
    joints = []
    for kind in rng.choice(list("RPCH"), count):
        phi, lam, s, h = rng.uniform(-2.0, 2.0, 4)
        joints.append(Joint(str(kind), phi, lam, s, h, pitch=float(rng.uniform(-1, 1)) if kind == "H" else 0.0))
    return OpenChain(joints)


@pytest.mark.parametrize("order", [0, 1, 2])
def test_random_chains_agree(order, backend):
    rng = np.random.default_rng(30)
    for count in (1, 3, 6):
        chain = _random_chain(rng, count)
        q, qd, qdd = (rng.uniform(-3.0, 3.0, (5000, chain.dof)) for _ in range(3))
        _agree(chain, q, order, backend, qd if order >= 1 else None, qdd if order >= 2 else None,
               point=tuple(rng.uniform(-1, 1, 3)))


def test_shapes_broadcast_and_default_qddot(backend):
    chain = example_2_25_manipulator(0.5)
    rng = np.random.default_rng(3)
    q = rng.uniform(-3.0, 3.0, (40, 30, chain.dof))
    got = _agree(chain, q, 2, backend, qdot=rng.uniform(-1, 1, chain.dof), point=(0.2, 0.1, 0.3))
    assert got.M.shape == (40, 30, 4, 4) and got.aP.shape == (40, 30, 3)
    assert np.array_equal(got.e3, got.M[..., :3, 2])


def test_auto_uses_the_loop_from_its_threshold(backend, monkeypatch):
    from mech.spatial import _chain_compiled

    calls = []
    real = _chain_compiled.solve_fields
    monkeypatch.setattr(_chain_compiled, "solve_fields", lambda *args: calls.append(1) or real(*args))
    backend("auto")
    chain = OpenChain([Joint("R", h=1.0), Joint("R", h=1.0)])
    chain.solve(np.zeros((100, 2)))
    assert not calls
    chain.solve(np.zeros((5000, 2)))
    assert calls
