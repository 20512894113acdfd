"""Which way a driven input turns through given angles, checked at the angles that decide it.

Shared by the planar and the spherical four-bar syntheses (`mech.planar.synthesis`,
`mech.spherical.guidance`): both need an input that meets the design's poses in order
without leaving the assembled range, and both linkages have their diagonal (or arc) BD
extreme at the input angles 0 and pi.
"""

import math

import numpy as np

__all__ = ["input_travel"]

_TURN = 2.0 * math.pi


def input_travel(linkage, theta_in):
    """Direction (+1, -1 or 0) in which the input meets the poses in order, and its path ends.

    The linkage can be assembled on an input interval exactly when it can at the interval's
    ends and at the angles 0 and pi inside it (the diagonal BD is extreme there), so those
    angles decide, by the analysis class itself. The spherical four-bar synthesis uses it
    too: its arc BD is extreme at the same angles.

    `linkage` is any analysis object whose ``solve(theta)`` returns a pose with a boolean
    ``valid`` per input; `theta_in` the input angles (radians) in the order the poses are
    met. Returns ``(direction, critical)``: the sense (+1 or -1) of an input that meets
    them in order without a full turn, and the angles checked; ``(0, None)`` if none can.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import FourBar
    >>> direction, critical = input_travel(FourBar(1.0, 3.0, 2.5, 3.0), np.array([0.1, 0.5, 1.0]))
    >>> direction, critical.tolist()
    (1, [0.1, 1.0])
    """
    for direction in (1, -1):
        steps = np.remainder(direction * np.diff(theta_in), _TURN)
        travel = float(np.sum(steps))
        if travel >= _TURN:
            continue
        start = float(theta_in[0])
        lo, hi = (start, start + travel) if direction > 0 else (start - travel, start)
        inside = np.arange(np.ceil(lo / np.pi), np.floor(hi / np.pi) + 1) * np.pi
        critical = np.concatenate([[lo, hi], inside])
        if np.all(linkage.solve(critical).valid):
            return direction, critical
    return 0, None
