"""The universal (Hooke) joint of eq. (2-72) and the double universal joint (F73-F76)."""

from dataclasses import dataclass

import numpy as np

from mech._generated.hooke import (
    double_hooke_ratio_extremes,
    hooke_output_angle,
    hooke_ratio_terms,
)
from mech._pose import quiet_overflow
from mech._validate import common_shape, finite_array, nonnegative_int, real_number, _show

__all__ = [
    "hooke_output",
    "hooke_ratio",
    "hooke_acceleration",
    "DoubleUniversalJoint",
    "DoubleJointPose",
]


def _shaft_angle(name, value):
    """Return ``value`` as a float array after checking 0 <= value < pi/2."""
    arr = finite_array(name, value)
    bad = (arr < 0.0) | (arr >= np.pi / 2)
    if np.any(bad):
        raise ValueError(
            f"Expected `{name}` in [0, pi/2) (at pi/2 the joint locks), got {_show(arr[bad].ravel()[0])}"
        )
    return arr


def _out(x):
    return float(x) if np.ndim(x) == 0 else x


def hooke_output(theta1, alpha):
    """Output angle of a universal joint, continuous in the input angle.

    The yokes of input and output stay perpendicular through the cross, which gives
    tan(theta1) = tan(theta3) cos(alpha) (F74). Of the roots of that equation, the one
    returned is continuous in `theta1`: theta3 - theta1 stays in (-pi/2, pi/2).

    Parameters
    ----------
    theta1 : array_like, shape (...)
        Input yoke angle, radians (from the plane of the two shafts).
    alpha : array_like, shape (...)
        Shaft angle, radians, in [0, pi/2).

    Returns
    -------
    theta3 : float or ndarray, shape (...)
        Output yoke angle, radians; a float for scalar inputs.

    Raises
    ------
    ValueError
        If an input is not finite, or `alpha` is outside [0, pi/2).

    Notes
    -----
    Derived in :ref:`deriv-hooke`: theta3 = theta1 + atan2(sin^2(alpha/2) sin(2 theta1),
    cos(alpha) cos^2(theta1) + sin^2(theta1)). The second argument of atan2 is positive,
    so there is no jump at theta1 = 90 or 270 degrees, and theta3(theta1 + 2 pi) =
    theta3(theta1) + 2 pi. At alpha = pi/2 the joint locks (the ratio (2-72) vanishes at
    theta1 = 90 degrees); such an angle is rejected.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._hooke import hooke_output
    >>> round(float(np.degrees(hooke_output(np.radians(45.0), np.radians(30.0)))), 6)
    49.106605
    >>> np.degrees(hooke_output(np.radians([90.0, 270.0, 450.0]), np.radians(30.0)))
    array([ 90., 270., 450.])
    """
    theta1 = finite_array("theta1", theta1)
    alpha = _shaft_angle("alpha", alpha)
    common_shape(theta1=theta1, alpha=alpha)
    return _out(hooke_output_angle(theta1, alpha))


def hooke_ratio(theta1, alpha):
    """Velocity ratio i31 = omega3 / omega1 of a universal joint, eq. (2-72).

    i31 = cos(alpha) / (1 - sin^2(alpha) cos^2(theta1)): from 1/cos(alpha) at theta1 = 0
    and 180 degrees down to cos(alpha) at 90 and 270 degrees.

    Parameters
    ----------
    theta1 : array_like, shape (...)
        Input yoke angle, radians.
    alpha : array_like, shape (...)
        Shaft angle, radians, in [0, pi/2).

    Returns
    -------
    ratio : float or ndarray, shape (...)
        i31, the derivative of :func:`hooke_output` in `theta1`.

    Raises
    ------
    ValueError
        If an input is not finite, or `alpha` is outside [0, pi/2).

    Notes
    -----
    Derived in :ref:`deriv-hooke`. The denominator is evaluated as
    sin^2(theta1) + cos^2(alpha) cos^2(theta1), a sum of non-negative terms, so it keeps
    full relative accuracy for every input.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._hooke import hooke_ratio
    >>> alpha = np.radians(30.0)
    >>> hooke_ratio([0.0, np.pi / 2], alpha) * [np.cos(alpha), 1 / np.cos(alpha)]
    array([1., 1.])
    """
    theta1 = finite_array("theta1", theta1)
    alpha = _shaft_angle("alpha", alpha)
    common_shape(theta1=theta1, alpha=alpha)
    ratio, _ = hooke_ratio_terms(theta1, alpha)
    return _out(ratio)


@quiet_overflow
def hooke_acceleration(theta1, alpha, omega=1.0, epsilon=0.0):
    """Angular acceleration of the output shaft of a universal joint.

    With omega3 = i31 omega (2-72), the output's angular acceleration is
    epsilon3 = (d i31 / d theta1) omega^2 + i31 epsilon, where
    d i31 / d theta1 = -cos(alpha) sin^2(alpha) sin(2 theta1) / D^2 and
    D = 1 - sin^2(alpha) cos^2(theta1).

    Parameters
    ----------
    theta1 : array_like, shape (...)
        Input yoke angle, radians.
    alpha : array_like, shape (...)
        Shaft angle, radians, in [0, pi/2).
    omega, epsilon : array_like, shape (...)
        Angular velocity (rad/s) and acceleration (rad/s^2) of the input shaft. The
        acceleration is called epsilon because alpha is the shaft angle.

    Returns
    -------
    epsilon3 : float or ndarray, shape (...)
        Angular acceleration of the output shaft, rad/s^2.

    Raises
    ------
    ValueError
        If an input is not finite, or `alpha` is outside [0, pi/2).

    Notes
    -----
    Derived in :ref:`deriv-hooke`. With a uniformly turning input the output accelerates
    most near theta1 = +-(45 degrees) for small alpha and closer to 0 and 180 degrees as
    alpha grows.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._hooke import hooke_acceleration
    >>> float(hooke_acceleration(0.0, 0.5, omega=10.0))   # stationary speed at theta1 = 0
    0.0
    >>> round(float(hooke_acceleration(np.pi / 4, np.radians(30.0), omega=10.0)), 6)
    -28.278381
    """
    theta1 = finite_array("theta1", theta1)
    alpha = _shaft_angle("alpha", alpha)
    omega = finite_array("omega", omega)
    epsilon = finite_array("epsilon", epsilon)
    common_shape(theta1=theta1, alpha=alpha, omega=omega, epsilon=epsilon)
    ratio, slope = hooke_ratio_terms(theta1, alpha)
    # (slope omega) omega: where slope = 0 a square beyond the float range gave 0 inf = NaN
    return _out(slope * omega * omega + ratio * epsilon)


@dataclass(frozen=True)
class DoubleJointPose:
    """Solved state of a double universal joint (see :meth:`DoubleUniversalJoint.solve`).

    ``theta_c`` and ``theta3`` are always set; ``ratio``, ``omega_c`` and ``omega3`` with
    ``order >= 1``; ``epsilon_c`` and ``epsilon3`` with ``order >= 2`` (None otherwise).
    """

    order: int
    theta_c: object
    theta3: object
    ratio: object = None
    omega_c: object = None
    omega3: object = None
    epsilon_c: object = None
    epsilon3: object = None


class DoubleUniversalJoint:
    """Two universal joints in series through an intermediate shaft C (F76).

    The input shaft meets C at the shaft angle `alpha1`, C meets the output shaft at
    `alpha2`, and C's second yoke leads its first by `phase` about C's axis. The output
    turns exactly with the input (ratio 1) when alpha1 == alpha2 and phase == 0 (mod pi):
    equal shaft angles and coplanar yokes on C, in the Z or the W arrangement alike.

    Parameters
    ----------
    alpha1, alpha2 : float
        Shaft angles of the first and second joint, radians, in [0, pi/2).
    phase : float, optional
        Phase of C's output-end yoke ahead of its input-end yoke, radians (0: coplanar).
        If the plane of C and the output shaft is turned by some angle about C against the
        plane of the input shaft and C, subtract that angle: the two errors act alike.

    Raises
    ------
    ValueError
        If a shaft angle is outside [0, pi/2) or `phase` is not finite.

    Notes
    -----
    Derived in :ref:`deriv-hooke`. The first joint gives C's angle theta_c from theta1;
    the second joint has the input angle theta_c - pi/2 + phase; the output's zero is set
    so that straight shafts give theta3 == theta1. The ratio is the product of the two
    joints' ratios (2-72), and its extremes over a turn have a closed form
    (:meth:`ratio_range`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._hooke import DoubleUniversalJoint
    >>> theta1 = np.radians([0.0, 37.0, 90.0, 200.0])
    >>> good = DoubleUniversalJoint(0.5, 0.5)
    >>> bool(np.allclose(good.solve(theta1).theta3, theta1, rtol=0, atol=1e-15))
    True
    >>> lo, hi = DoubleUniversalJoint(0.5, 0.5, phase=np.radians(10.0)).ratio_range()
    >>> round(hi - lo, 6)
    0.090984
    """

    def __init__(self, alpha1, alpha2, *, phase=0.0):
        self.alpha1 = float(_shaft_angle("alpha1", real_number("alpha1", alpha1)))
        self.alpha2 = float(_shaft_angle("alpha2", real_number("alpha2", alpha2)))
        self.phase = real_number("phase", phase)

    def __repr__(self):
        return (f"DoubleUniversalJoint({self.alpha1!r}, {self.alpha2!r}, "
                f"phase={self.phase!r})")

    @quiet_overflow
    def solve(self, theta1, order=0, omega=1.0, epsilon=0.0):
        """Solve the double joint at input angles `theta1`.

        Parameters
        ----------
        theta1 : array_like, shape (...)
            Input yoke angle, radians.
        order : {0, 1, 2}, optional
            0: angles; 1: also the ratio and angular velocities; 2: also accelerations.
        omega, epsilon : array_like, shape (...), optional
            Input angular velocity and acceleration.

        Returns
        -------
        pose : DoubleJointPose
            ``theta_c`` (intermediate shaft), ``theta3`` (output, continuous); with
            ``order >= 1`` ``ratio`` (omega3 / omega), ``omega_c``, ``omega3``; with
            ``order >= 2`` ``epsilon_c``, ``epsilon3``.

        Raises
        ------
        ValueError
            If an input is not finite or `order` is not 0, 1 or 2.
        """
        order = nonnegative_int("order", order, 2)
        theta1 = finite_array("theta1", theta1)
        a1, a2, beta = self.alpha1, self.alpha2, self.phase
        theta_c = hooke_output_angle(theta1, a1)
        theta_b = theta_c - np.pi / 2 + beta
        theta3 = hooke_output_angle(theta_b, a2) + (np.pi / 2 - beta)
        if order == 0:
            return DoubleJointPose(0, _out(theta_c), _out(theta3))
        omega = finite_array("omega", omega)
        common_shape(theta1=theta1, omega=omega)
        ratio_a, slope_a = hooke_ratio_terms(theta1, a1)
        ratio_b, slope_b = hooke_ratio_terms(theta_b, a2)
        omega_c = ratio_a * omega
        omega3 = ratio_b * omega_c
        fields = dict(ratio=_out(ratio_a * ratio_b), omega_c=_out(omega_c), omega3=_out(omega3))
        if order == 2:
            epsilon = finite_array("epsilon", epsilon)
            common_shape(theta1=theta1, omega=omega, epsilon=epsilon)
            epsilon_c = slope_a * omega * omega + ratio_a * epsilon      # no 0 inf where slope_a = 0
            epsilon3 = slope_b * omega_c * omega_c + ratio_b * epsilon_c
            fields.update(epsilon_c=_out(epsilon_c), epsilon3=_out(epsilon3))
        return DoubleJointPose(order, _out(theta_c), _out(theta3), **fields)

    def ratio_range(self):
        """Smallest and largest velocity ratio omega3 / omega1 over a turn.

        Returns
        -------
        ratio_min, ratio_max : float
            Both 1.0 (to rounding) when the two conditions for uniform transmission hold.

        Notes
        -----
        Closed form from :ref:`deriv-hooke`: as a function of u = 2 theta_c the ratio is a
        quotient of two shifted cosines, stationary where A sin u + B cos u = C. For a
        single joint the range is (cos(alpha), 1 / cos(alpha)).
        """
        g_minus, g_plus = double_hooke_ratio_extremes(self.alpha1, self.alpha2, self.phase)
        return float(min(g_minus, g_plus)), float(max(g_minus, g_plus))
