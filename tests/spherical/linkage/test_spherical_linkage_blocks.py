"""`SphericalLinkage.solve` in blocks (issue 30): the same bits as one piece, at every order.

Each pose's results depend on its own inputs alone, so cutting the inputs into blocks of
`_BLOCK` (to keep the temporaries of the rates in cache, for a cost per pose that stays
flat with N) must change nothing: compared exactly, NaN matching NaN, with blocks of 997
inputs against one piece, on a Watt-1 six-bar over inputs that include its dead and change
points' neighbourhoods (several turns, both directions) and per-pose rates.
"""

import numpy as np
import pytest

from mech.spherical import stephenson1, watt1
from mech.spherical.linkage import _linkage


def _leaves(pose):
    out = {}
    for name in ("points", "velocities", "accelerations", "angular_velocities", "angular_accelerations"):
        for key, value in pose._fields.get(name, {}).items():
            out[(name, key)] = np.asarray(value)
    out["valid"] = pose.valid
    return out


@pytest.mark.parametrize("make", [
    lambda: watt1(0.3, 0.9, 0.7, 1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7), coupler=(0.4, 0.5)),
    lambda: stephenson1(0.3, 0.9, 0.7, 1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7), coupler=(0.4, 0.5)),
])
@pytest.mark.parametrize("order", [0, 2])
def test_blocks_give_the_same_bits(make, order, monkeypatch):
    lk = make()
    rng = np.random.default_rng(30)
    theta = np.concatenate([rng.uniform(-13, 13, 4000), np.linspace(-np.pi, np.pi, 1001)])
    omega, alpha = rng.uniform(-2, 2, theta.size), 0.3
    whole = _leaves(lk.solve(theta, order=order, omega=omega, alpha=alpha))
    monkeypatch.setattr(_linkage, "_BLOCK", 997)
    blocks = _leaves(lk.solve(theta, order=order, omega=omega, alpha=alpha))
    assert whole.keys() == blocks.keys()
    for key in whole:
        x, y = whole[key], blocks[key]
        assert x.shape == y.shape
        assert np.array_equal(x, y, equal_nan=x.dtype != bool), key
    assert whole["valid"].any()
