"""Link-length checks of the planar four-bar, shared by its solver and the functions of its structure.

`fourbar_lengths` checks four lengths and scales them by a power of two (the unit of length
then drops out of every angle); `assembly_gaps` and `dead_points_near` give the factors of the
assembly condition and the inputs that count as dead points. `FourBar`, the limit positions,
the transmission and pressure angles all start here, so the rules are written once.
"""

import math

import numpy as np

from mech._generated import fourbar_position as _gen
from mech._scaling import DEAD_POINT_RTOL
from mech._validate import positive_length

__all__ = []        # internal to the subpackage: nothing here is re-exported


def fourbar_lengths(a, b, c, d):
    """Check four link lengths and scale them so that the longest lies in [1/2, 1).

    Returns ``(lengths, exponent)``: the lengths divided by ``2**exponent``, a power of two,
    so the scaling is exact, no product of lengths overflows or underflows, and angles do
    not depend on the unit of length. Raises ValueError naming a length that is not
    positive and finite, or one that is not shorter than the other three together.
    """
    raw = [positive_length(name, value) for name, value in zip("abcd", (a, b, c, d))]
    exponent = math.frexp(max(raw))[1]
    scaled = [math.ldexp(x, -exponent) for x in raw]
    total = math.fsum(scaled)
    for k, (name, value, x) in enumerate(zip("abcd", raw, scaled)):
        if x >= total - x:
            # from the unscaled lengths: scaled, a length 2**-1075 times the longest is 0.0
            rest = math.fsum(raw[:k] + raw[k + 1:])
            raise ValueError(
                f"Expected `{name}` shorter than the other three links together "
                f"({rest!r}), got {value!r}"
            )
    return tuple(scaled), exponent


def fourbar_lengths_resolved(a, b, c, d):
    """`fourbar_lengths`, and every scaled length above 0.0 (for Grashof's rule and limits).

    A length below about 2**-1074 times the longest is valid for `FourBar` (a crank of
    length 0.0 after scaling), but the helpers that classify the linkage need every scaled
    length > 0: raise ValueError naming that length with the value given.
    """
    scaled, exponent = fourbar_lengths(a, b, c, d)
    raw = (a, b, c, d)
    for name, value, x in zip("abcd", raw, scaled):
        if x == 0.0:
            longest = max(float(v) for v in raw)
            raise ValueError(
                f"Expected `{name}` at least 2**-1074 times the longest link ({longest!r}) "
                f"so that the linkage can be solved, got {value!r}"
            )
    return scaled, exponent


def assembly_gaps(a, b, c, d, rtol):
    """The gaps g2, g3, g4 of unit lengths, each set to 0.0 within ``rtol (a + b + c + d)``."""
    total = a + b + c + d
    gaps = [float(g) for g in _gen.fourbar_assembly_gaps(a, b, c, d)]
    return tuple(0.0 if abs(g) <= rtol * total else g for g in gaps)


def dead_points_near(a, b, c, d, theta, gaps):
    """Masks of the inputs within `DEAD_POINT_RTOL` (a + b + c + d) of a dead point, and |BD|.

    A dead point is where |BD| = b + c (``near_far``) or |b - c| (``near_close``) and the
    gap of that factor (`assembly_gaps`) is not zero; where it is zero, the branches meet
    there (a change point) and the linkage passes. Whether a float input on a dead point
    assembles is decided by a rounding, which the same linkage in another unit of length
    (its lengths not exactly proportional) may decide the other way: within the tolerance
    the input counts as the dead point, which assembles. Unit lengths (`fourbar_lengths`).
    """
    gap2, gap3, gap4 = gaps
    tol = DEAD_POINT_RTOL * (a + b + c + d)
    s = np.sin(0.5 * np.asarray(theta, dtype=float))
    k = np.sqrt((d - a) ** 2 + 4.0 * a * d * s * s)          # |BD|
    never = np.zeros(k.shape, dtype=bool)
    near_far = np.abs(k - (b + c)) <= tol if gap4 != 0.0 else never
    near_close = np.abs(abs(b - c) - k) <= tol if (gap2 if c > b else gap3) != 0.0 else never
    return near_far, near_close, k
