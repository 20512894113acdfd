"""Transmission angle of the four-bar: eq. (2-30) and its minimum (textbook §2.3, F50-F55)."""

import numpy as np

from mech._generated.transmission_angle import (
    fourbar_crank_angle_at_diagonal,
    fourbar_transmission,
)
from mech._errors import AssemblyError
from mech._validate import bool_flag, finite_array
from mech.planar.kinematics._fourbar import register_transmission
from mech.planar.structure._lengths import (
    assembly_gaps, dead_points_near, fourbar_lengths, fourbar_lengths_resolved,
)
from mech.planar.structure._grashof import grashof

__all__ = ["transmission_angle", "min_transmission_angle"]

_CRANK_TURNS = ("crank-rocker", "double-crank")


def at_dead_points(gamma, a, b, c, d, theta):
    """Transmission angles with 0 at the inputs `FourBar` counts as dead points (B, C, D in
    line) where the formula, by a rounding, found no triangle BCD. Unit lengths."""
    near_far, near_close, _ = dead_points_near(a, b, c, d, theta, assembly_gaps(a, b, c, d, _RTOL))
    return np.where(np.isnan(gamma) & (near_far | near_close), 0.0, gamma)


#: `FourBar`'s default `rtol` (change points): the dead points here are those of `FourBar.solve`
_RTOL = 1e-12


def _lengths(a, b, c, d):
    # angles only: the lengths scaled by a power of two give the same values at any scale
    return fourbar_lengths(a, b, c, d)[0]


def check_assembled(angle, theta, lengths, strict):
    """Raise AssemblyError at the first `theta` where `angle` is NaN, if `strict`."""
    if bool_flag("strict", strict) and np.any(np.isnan(angle)):
        bad = float(np.broadcast_to(theta, np.shape(angle))[np.isnan(angle)].ravel()[0])
        raise AssemblyError(f"Cannot assemble the four-bar (a, b, c, d) = {lengths!r} "
                            f"at theta = {bad!r}")


def transmission_angle(a, b, c, d, theta, *, strict=False):
    """Transmission angle of the four-bar at crank angle theta.

    The angle delta = BCD between coupler and output follows from eq. (2-30),
    cos(delta) = (b^2 + c^2 - d^2 - a^2 + 2 a d cos(theta)) / (2 b c), and the transmission
    angle (传动角) is gamma = delta or pi - delta, whichever is in [0, pi/2] (F50).

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, output CD and ground AD, > 0.
    theta : array_like, shape (...)
        Crank angle, radians (the textbook's phi_1).
    strict : bool, optional
        Raise `AssemblyError` instead of returning NaN where the linkage cannot be
        assembled, as `FourBar.solve` does.

    Returns
    -------
    gamma : float or ndarray, shape (...)
        Transmission angle in [0, pi/2], radians; NaN where the linkage cannot be assembled
        at `theta`. A float for scalar `theta`.

    Raises
    ------
    ValueError
        If a length is not positive and finite, if one link is not shorter than the other
        three together (as for `FourBar`), or if `theta` is not finite.
    AssemblyError
        With ``strict=True``, naming the first input angle that cannot be assembled.

    Notes
    -----
    Derived in :ref:`deriv-transmission-angle`: delta = 2 atan2(sqrt(P), sqrt(Q)) with
    P = k^2 - (b - c)^2 and Q = (b + c)^2 - k^2 written through sin^2(theta/2) and
    cos^2(theta/2), so no digits are lost near theta = 0 or pi. The value does not depend
    on the assembly branch (the mirror image has the same angle BCD). Where P < 0 or Q < 0
    the triangle BCD does not close; NaN is returned there without a NumPy warning. The
    lengths are scaled internally by a power of two, so any finite positive lengths work
    and the angle does not depend on the unit of length.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.forces._transmission import transmission_angle
    >>> round(float(np.degrees(transmission_angle(30, 70, 60, 80, 0.0))), 4)
    44.4153
    >>> np.degrees(transmission_angle(30, 70, 60, 80, [np.pi / 2, np.pi])).round(4)
    array([81.7868, 64.6231])
    >>> transmission_angle(40, 20, 30, 35, 0.0)   # cannot be assembled at theta = 0
    nan
    """
    lengths = (a, b, c, d)
    a, b, c, d = _lengths(a, b, c, d)
    theta = finite_array("theta", theta)
    with np.errstate(invalid="ignore"):
        _, gamma = fourbar_transmission(a, b, c, d, theta)
    gamma = at_dead_points(gamma, a, b, c, d, theta)
    check_assembled(gamma, theta, lengths, strict)
    return float(gamma) if np.ndim(gamma) == 0 else gamma


def min_transmission_angle(a, b, c, d):
    """Minimum transmission angle over the motion of the four-bar, and where it occurs.

    For a linkage whose crank AB turns fully (a crank-rocker or a double-crank), the
    diagonal BD is shortest at theta = 0 and longest at theta = pi, so the angle BCD takes
    its extremes there (F53, F54) and gamma_min = min(gamma(0), gamma(pi)): the rule F55.

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, output CD and ground AD, > 0.

    Returns
    -------
    gamma_min : float
        Minimum transmission angle, radians, in [0, pi/2].
    theta_at : float
        Crank angle where it occurs: 0.0 or pi when the crank turns fully (0.0 on a tie).

    Raises
    ------
    ValueError
        If a length is not positive and finite, or one link is not shorter than the other
        three together.

    Notes
    -----
    Derived in :ref:`deriv-transmission-angle`. If the crank does not turn fully
    (``grashof(a, b, c, d).kind`` not "crank-rocker" or "double-crank"), the input rocks
    between dead-centre positions where coupler and output are collinear (BD = b + c or
    ``|b - c|``). The transmission angle is 0 there, so the function returns ``(0.0,
    theta_at)`` with ``theta_at`` the smallest crank angle in [0, pi] of such a position
    (its mirror -theta_at is another): a linkage driven at AB locks there.

    Examples
    --------
    The textbook's check case (F55): delta_min = 44.4153 deg at theta = 0.

    >>> import numpy as np
    >>> from mech.planar.forces._transmission import min_transmission_angle
    >>> gamma_min, theta_at = min_transmission_angle(30, 70, 60, 80)
    >>> round(float(np.degrees(gamma_min)), 4), theta_at
    (44.4153, 0.0)
    >>> gamma_min, theta_at = min_transmission_angle(10, 40, 30, 35)   # Example 2-1
    >>> round(float(np.degrees(gamma_min)), 4), theta_at
    (38.6248, 0.0)
    """
    a, b, c, d = fourbar_lengths_resolved(a, b, c, d)[0]
    kind = grashof(a, b, c, d).kind
    if kind in _CRANK_TURNS:
        _, (gamma_0, gamma_pi) = fourbar_transmission(a, b, c, d, np.array([0.0, np.pi]))
        if gamma_pi < gamma_0:
            return float(gamma_pi), float(np.pi)
        return float(gamma_0), 0.0
    with np.errstate(invalid="ignore"):
        theta_locks = fourbar_crank_angle_at_diagonal(a, d, np.array([b + c, abs(b - c)]))
    return 0.0, float(np.nanmin(theta_locks))


register_transmission(transmission_angle=transmission_angle, min_transmission_angle=min_transmission_angle)
