"""`Linkage.solve` over a large array of inputs: cache-sized blocks, gathered in place.

A `Linkage` solves group after group, each step reading the arrays of the steps before it,
so a solve over N inputs holds a few dozen temporaries of N values at once. Over a large
array these leave the cache and every step streams them through memory. Every result of a
pose depends on that pose's inputs only (the modes through change points and the bridge
across them are local rules in the crank angle, `_linkage_modes`), so the inputs can be cut
into blocks of `BLOCK` poses, each block solved whole (positions, rates, the bridge, the
unit of length) while its temporaries stay in cache, and its results copied into outputs
allocated once. The results are those of one solve over all inputs, bit for bit (a test
checks it), and the temporaries of one block are freed before the next begins.
"""

from __future__ import annotations

import math

import numpy as np

from mech.planar.kinematics._linkage import _modes as _linkage_modes

__all__ = []        # internal to the subpackage: nothing here is re-exported

#: Poses per block: the temporaries of a six-bar's solve (a few dozen arrays of this
#: length) stay within the L2 and L3 caches, and the per-step cost of Python is spread over
#: enough poses to vanish (measured in benchmarks/bench_speed_linkage.py).
BLOCK = 16384


def flat_input(x, shape):
    """A driver's input as a flat array over `shape`, or as a 0-d array if it is one value."""
    x = np.asarray(x)
    if x.size == 1:
        return x.reshape(())
    return np.broadcast_to(x, shape).reshape(-1)         # a view unless `x` is broadcast


class _Gather:
    """Outputs of size `size`, filled block by block.

    A field that is one value in every block (a ground point, a zero rate) stays one value:
    0-d as the block gave it, or broadcast to the full shape if the block gave it as a
    broadcast array. It becomes a full array the first time a block gives anything else,
    as the bridge across a change point does where it interpolates every field.
    """

    def __init__(self, size):
        self.size = size
        self.values = {}         # key -> ndarray of length size, or (scalar 0-d array, broadcast)

    def put(self, key, value, block):
        value = np.asarray(value)
        current = self.values.get(key)
        constant = _constant(value)
        if current is None:
            if block.start != 0:
                raise RuntimeError(f"result {key!r} missing from the first block")
            if constant is not None:
                self.values[key] = (constant, value.ndim > 0)
                return
            current = self.values[key] = np.empty(self.size, dtype=value.dtype)
        elif isinstance(current, tuple):
            if constant is not None and _same(constant, current[0]):
                return
            full = np.empty(self.size, dtype=np.result_type(current[0], value))
            full[: block.start] = current[0]
            current = self.values[key] = full
        elif np.result_type(current, value) != current.dtype:
            current = self.values[key] = current.astype(np.result_type(current, value))
        current[block] = value

    def get(self, key, shape):
        value = self.values[key]
        if isinstance(value, tuple):
            constant, broadcast = value
            return np.broadcast_to(constant, shape) if broadcast else constant
        return value.reshape(shape)


def _constant(value):
    """The one value of a 0-d or stride-0 array (a 0-d array), else None."""
    if value.ndim == 0:
        return value
    if value.ndim == 1 and value.strides == (0,):
        return value[0:1].reshape(())
    return None


def _same(x, y):
    """True if the 0-d arrays hold the same value and type (NaN equal to NaN)."""
    return x.dtype == y.dtype and (x == y or (x != x and y != y))


def solve_blocks(linkage, steps, order, shape, q, w, al, crank, unit, block=None):
    """`Linkage._solve_all` over `shape` in blocks of `block` inputs; returns (state, failures)."""
    size = math.prod(shape)
    block = BLOCK if block is None else block
    flat = [{d: flat_input(v, shape) for d, v in x.items()} for x in (q, w, al)]
    gather = _Gather(size)
    first = labels = None
    for start in range(0, size, block):
        part = slice(start, min(start + block, size))
        n = part.stop - part.start
        inputs = [{d: v if v.ndim == 0 else v[part] for d, v in x.items()} for x in flat]
        state, failures = linkage._solve_all(steps, order, (n,), *inputs, crank, unit)
        if first is None:
            first, labels = state, tuple(failures)
        for key, value in _linkage_modes._fields(state).items():
            gather.put(key, value, part)
        gather.put(("valid",), state.valid, part)
        for label in labels:
            gather.put(("failure", label), failures[label], part)
    first.shape = shape
    _linkage_modes._store_fields(first, {key: gather.get(key, shape) for key in gather.values
                                         if key[0] not in ("valid", "failure")})
    first.valid = gather.get(("valid",), shape)
    return first, {label: gather.get(("failure", label), shape) for label in labels}
