"""`RSSR.solve` and `OpenChain.solve` over more inputs than one block (issue 16, item 1).

The block size is shrunk so that small arrays span many blocks. A blocked solve must equal,
bit for bit, the concatenation of separate small solves; along a branch the rocker angle
must not jump at a block boundary (a change point placed on a boundary included); and the
open chain must agree with the closed form (2-75) of example 2-25 across boundaries.
"""

import math

import numpy as np
import pytest

import mech
from mech.spatial import _chain, _rssr
from mech.spatial._chain import Joint, OpenChain, example_2_25_manipulator, example_2_25_pose
from mech.spatial._rssr import RSSR

BLOCK = 1000


@pytest.fixture
def small_blocks(monkeypatch):
    monkeypatch.setattr(_rssr, "_BLOCK", BLOCK)
    monkeypatch.setattr(_chain, "_BLOCK", BLOCK)
    # blocks belong to the NumPy path (the compiled loops solve every input in one pass)
    previous = mech.set_backend("numpy")
    yield
    mech.set_backend(previous)


def _assert_identical(got, want):
    assert set(got._fields) == set(want._fields)
    for name, value in want._fields.items():
        value = np.asarray(value)
        assert got._fields[name].shape == value.shape, name
        assert got._fields[name].dtype == value.dtype, name
        assert np.array_equal(got._fields[name], value, equal_nan=True), name


def _joined(poses):
    """One pose-like record whose fields are the concatenated fields of `poses`."""
    fields = {name: np.concatenate([np.asarray(p._fields[name]) for p in poses]) for name in poses[0]._fields}
    return type("Joined", (), {"_fields": fields})


RSSRS = [
    RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, math.radians(60), coupler=(1.0, 0.5, 0.2)),   # full turn
    RSSR(2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8),                                          # rocks: NaN
    RSSR(1, 2, 2, 0, 0, 1, 0),                                                         # kite
    RSSR(1, 3, 1, 0, 0, 3, 0, coupler=(1.0, 0.0, 0.0)),                                # parallelogram
]


@pytest.mark.parametrize("rssr", RSSRS, ids=["turning", "rocking", "kite", "parallelogram"])
@pytest.mark.parametrize("order", [0, 1, 2])
def test_rssr_blocked_equals_concatenated_small_solves(small_blocks, rssr, order):
    n = 7 * BLOCK + 123
    phi01 = np.linspace(-9.0, 9.0, n)
    omega = np.linspace(0.5, 2.0, n)
    blocked = rssr.solve(phi01, order=order, omega=omega, alpha=0.3)
    pieces = [slice(k, k + 300) for k in range(0, n, 300)]
    _assert_identical(blocked, _joined([rssr.solve(phi01[p], order=order, omega=omega[p], alpha=0.3)
                                        for p in pieces]))


def test_rssr_blocked_keeps_the_input_shape(small_blocks):
    rssr = RSSRS[0]
    phi01 = np.linspace(-3.0, 3.0, 3000).reshape(30, 100, 1)
    pose = rssr.solve(phi01, order=1, omega=np.ones(2))
    assert pose.phi03.shape == (30, 100, 2) and pose.vC.shape == (30, 100, 2, 3)
    assert np.array_equal(pose.phi03[..., 0], rssr.solve(phi01[..., 0]).phi03)


@pytest.mark.parametrize("rssr", RSSRS[2:], ids=["kite", "parallelogram"])
def test_rssr_branch_continues_through_change_points_on_block_boundaries(small_blocks, rssr):
    """phi01 = 0 (a change point of both) at the last pose of one block and 2 pi at a first."""
    step = 2 * math.pi / (BLOCK + 1)
    phi01 = (np.arange(4 * BLOCK) - (BLOCK - 1)) * step
    phi01[BLOCK - 1], phi01[2 * BLOCK] = 0.0, 2 * math.pi
    pose = rssr.solve(phi01, order=1)
    assert pose.valid.all()
    # loop closure, checked by the pins (not the solver's equation): |C - B| = l2
    assert np.max(np.abs(np.linalg.norm(pose.C - pose.B, axis=-1) - rssr.l2)) < 1e-12
    # no jump anywhere, boundaries included: the rocker turns less than 3 crank steps per step
    jump = np.abs(np.angle(np.exp(1j * np.diff(pose.phi03))))
    assert np.max(jump) < 3 * step


def _six_r():
    return OpenChain([Joint("R", lam=math.pi / 2, s=0.4), Joint("C", h=0.6), Joint("H", h=0.5, pitch=0.3),
                      Joint("P", lam=math.pi / 2, s=0.1), Joint("R", lam=-math.pi / 2), Joint("R", s=0.1)])


@pytest.mark.parametrize("order", [0, 1, 2])
def test_chain_blocked_equals_concatenated_small_solves(small_blocks, order):
    chain = _six_r()
    rng = np.random.default_rng(16)
    n = 5 * BLOCK + 77
    q, qd, qdd = (rng.uniform(-3, 3, (n, chain.dof)) for _ in range(3))
    kw = lambda p: dict(qdot=qd[p] if order else None, qddot=qdd[p] if order else None, point=(0.1, 0.2, 0.3))
    blocked = chain.solve(q, order=order, **kw(slice(None)))
    pieces = [slice(k, k + 300) for k in range(0, n, 300)]
    _assert_identical(blocked, _joined([chain.solve(q[p], order=order, **kw(p)) for p in pieces]))
    # the unit vectors are views of M, as in one solve
    assert np.shares_memory(blocked.e1, blocked.M)


def test_chain_blocked_agrees_with_closed_form_2_75(small_blocks):
    """Example 2-25's manipulator in blocks against its closed form (2-75), an independent route."""
    rng = np.random.default_rng(25)
    n = 3 * BLOCK + 5
    q = np.column_stack([rng.uniform(-math.pi, math.pi, n), rng.uniform(-math.pi, math.pi, n),
                         rng.uniform(0.1, 0.4, n), rng.uniform(-math.pi, math.pi, n)])
    pose = example_2_25_manipulator(0.5).solve(q, point=(0.0, 0.0, 0.1))
    P, e1, e3 = example_2_25_pose(q[:, 0], q[:, 1], q[:, 2], q[:, 3], 0.5, 0.1)
    for got, want in ((pose.P, P), (pose.e1, e1), (pose.e3, e3)):
        assert np.max(np.abs(got - want)) < 1e-14
