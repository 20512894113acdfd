"""Scale invariance by construction: solve with lengths divided by a power of two.

Every linkage solver works on lengths divided by `length_scale` of its links, so that the
longest link lies in [1, 2). Angles do not depend on the unit of length, and squares,
products and quotients of normalised lengths neither overflow nor underflow, whatever the
unit (lengths from 1e-300 to 1e300 give the same angles). Because the scale is a power of
two, dividing by it and multiplying lengths and linear rates back by it is exact (unless a
result leaves the range of floating point numbers), so a linkage given in metres and the
same linkage given in millimetres differ only by the rounding of their inputs.
"""

import math

import numpy as np

__all__ = ["DEAD_POINT_RTOL", "length_scale", "length_scale_array"]

#: An input within this fraction of a linkage's size (the sum of its lengths) of a dead
#: point counts as the dead point. Whether a float input on a dead point assembles is
#: decided by a rounding of a few ulps, which the same linkage in another unit of length
#: (its lengths then not exactly proportional) may decide the other way; 64 ulps cover it,
#: so `valid` does not depend on the unit. Not a modelling tolerance: 2**-46 ~ 1.4e-14.
DEAD_POINT_RTOL = 2.0**-46


def length_scale(*lengths):
    """The power of two ``2**k`` with ``2**k <= max(|lengths|) < 2**(k + 1)``.

    Returns 1.0 when every length is zero. All lengths must be finite floats.

    Examples
    --------
    >>> from mech._scaling import length_scale
    >>> length_scale(3.0, -10.0, 0.5), length_scale(0.0)
    (8.0, 1.0)
    """
    biggest = max(abs(float(x)) for x in lengths)
    if biggest == 0.0:
        return 1.0
    # frexp gives biggest = m * 2**e with m in [0.5, 1)
    return math.ldexp(1.0, math.frexp(biggest)[1] - 1)


def length_scale_array(*lengths):
    """`length_scale` element by element over broadcast arrays of finite lengths.

    Examples
    --------
    >>> from mech._scaling import length_scale_array
    >>> length_scale_array([3.0, 0.0, 1e-300], 0.5).tolist()
    [2.0, 0.5, 0.5]
    """
    biggest = np.maximum.reduce([np.abs(np.asarray(x, dtype=float)) for x in np.broadcast_arrays(*lengths)])
    exponent = np.frexp(biggest)[1] - 1
    return np.where(biggest == 0.0, 1.0, np.ldexp(1.0, exponent))
