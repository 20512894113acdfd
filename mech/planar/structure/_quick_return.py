"""Quick return: the time ratio K of eq. (2-9) and its inverse (textbook §2.2)."""

import numpy as np

from mech._generated.fourbar_limit_positions import (
    quick_return_extreme_angle,
    quick_return_time_ratio,
)
from mech._validate import finite_array

__all__ = ["time_ratio", "extreme_angle"]


def _scalar_or_array(arr):
    return float(arr) if np.ndim(arr) == 0 else arr


def _first(arr, mask):
    """The first entry of ``arr`` where ``mask`` holds, as a Python float."""
    return float(np.broadcast_to(arr, np.shape(mask))[mask].ravel()[0])


def time_ratio(extreme_angle):
    """Time ratio K of a quick-return mechanism from its extreme angle.

    With a constant crank speed, the slow stroke of the output takes the crank through
    pi + theta and the fast stroke through pi - theta, so eq. (2-9) gives
    K = (pi + theta) / (pi - theta), where theta is the extreme angle (极位夹角), the
    angle between the two crank positions at the output's limit positions.

    Parameters
    ----------
    extreme_angle : array_like
        Extreme angle theta in [0, pi), radians.

    Returns
    -------
    K : float or ndarray
        Time ratio (行程时间比系数), >= 1; a float for scalar input.

    Raises
    ------
    ValueError
        If any entry of `extreme_angle` is not finite or lies outside [0, pi).

    See Also
    --------
    extreme_angle : the inverse, theta = pi (K - 1) / (K + 1).

    Notes
    -----
    Derived in :ref:`deriv-fourbar-limit-positions` (eq. 2-9). K = 1 (theta = 0) means
    no quick return; K grows without bound as theta approaches pi.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import time_ratio
    >>> time_ratio(0.0)
    1.0
    >>> time_ratio(np.radians([30.0, 60.0]))
    array([1.4, 2. ])
    """
    theta = finite_array("extreme_angle", extreme_angle)
    bad = (theta < 0.0) | (theta >= np.pi)
    if np.any(bad):
        raise ValueError(f"Expected `extreme_angle` in [0, pi), got {_first(theta, bad)!r}")
    return _scalar_or_array(quick_return_time_ratio(theta))


def extreme_angle(time_ratio):
    """Extreme angle of a quick-return mechanism from its time ratio K.

    The inverse of eq. (2-9): theta = pi (K - 1) / (K + 1), the angle between the two crank
    positions at the output's limit positions that gives the time ratio K.

    Parameters
    ----------
    time_ratio : array_like
        Time ratio K >= 1 (finite).

    Returns
    -------
    theta : float or ndarray
        Extreme angle in [0, pi), radians; a float for scalar input.

    Raises
    ------
    ValueError
        If any entry of `time_ratio` is not finite or is below 1.

    See Also
    --------
    time_ratio : the forward relation (2-9).

    Notes
    -----
    Derived in :ref:`deriv-fourbar-limit-positions` (eq. 2-9 and its inverse).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import extreme_angle
    >>> float(np.degrees(extreme_angle(2.0)))  # Example 2-2: K = 2
    60.0
    >>> np.degrees(extreme_angle([1.0, 1.4]))
    array([ 0., 30.])
    """
    K = finite_array("time_ratio", time_ratio)
    bad = K < 1.0
    if np.any(bad):
        raise ValueError(f"Expected `time_ratio` >= 1, got {_first(K, bad)!r}")
    return _scalar_or_array(quick_return_extreme_angle(K))
