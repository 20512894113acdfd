"""The parts the atlas's sample records share: row selection, range boxes, the record base class.

The planar, slider-crank and spherical sample modules all build on this module, which
imports none of them (so the four-bar sampler can dispatch to the slider-crank one at module
level without an import cycle).
"""

from dataclasses import fields

import numpy as np

from mech._errors import InputTypeError
from mech._validate import _show, real_tuple


class _Samples:
    """The methods shared by the sample records (FourBarSamples, SliderCrankSamples, SphereSamples)."""

    def __len__(self):
        return int(self.a.shape[0])

    def take(self, index):
        """The samples at `index` (integers, or a boolean mask of length n), as a new record."""
        pick = rows("index", index, len(self))
        return type(self)(**{f.name: getattr(self, f.name)[pick] for f in fields(self)})

    def columns(self):
        """The fields as a dict of arrays, in declaration order."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


def rows(name, index, n):
    """Check row numbers (an integer, integers, or a boolean mask of length n) of a table of n rows."""
    if isinstance(index, (int, np.integer)) and not isinstance(index, (bool, np.bool_)):
        index = [index]
    if isinstance(index, (bool, np.bool_)) or index is None or isinstance(index, (str, bytes, dict)):
        raise InputTypeError(f"Expected `{name}` to be row numbers or a boolean mask, got {_show(index)}")
    try:
        arr = np.asarray(index)
    except Exception:
        raise InputTypeError(f"Expected `{name}` to be row numbers or a boolean mask, got {_show(index)}") from None
    if arr.dtype.kind == "b" and arr.shape == (n,):
        return arr
    if arr.dtype.kind not in "iu" or arr.ndim != 1:
        raise InputTypeError(f"Expected `{name}` to be row numbers or a boolean mask of length {n}, "
                             f"got {_show(index)}")
    if np.any((arr < -n) | (arr >= n)):
        raise ValueError(f"Expected `{name}` in [-{n}, {n}), got {_show(index)}")
    return arr


def _box(name, value, size):
    box = real_tuple(name, value, size)
    for low, high in zip(box[::2], box[1::2]):
        if not low < high:
            raise ValueError(f"Expected `{name}` as increasing (low, high) pairs, got {_show(value)}")
    return box


#: The largest ratio of a link to the ground `sample_fourbars` draws.
_MAX_RATIO = 1e150
#: The largest coupler point (times the longest link) drawn: coupler curves are points, not
#: squares, so only their own size must stay finite (the signature scales them first).
_MAX_COUPLER = 1e306
#: The largest seed: an atlas keeps each row's seed in a 64-bit signed integer column.
_MAX_SEED = 2**63 - 1


def _check_sizes(*ranges):
    """Raise ValueError naming the first of ``(name, given, size)`` whose drawn lengths (as
    ratios to the ground) may exceed `_MAX_RATIO`: the type, input range and transmission
    angle use their squares and sums of squares, which must stay finite."""
    for name, given, size in ranges:
        if name == "coupler":
            if not size <= _MAX_COUPLER:
                raise ValueError(f"Expected `coupler` that keeps every coupler point within {_MAX_COUPLER:g} times "
                                 f"the ground, got {_show(given)}")
            continue
        if not size <= _MAX_RATIO:
            raise ValueError(f"Expected `{name}` that keeps every drawn length within {_MAX_RATIO:g} times the "
                             f"ground (their squares must stay finite), got {_show(given)}")
