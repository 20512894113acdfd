"""Limit positions, swing, extreme angle and time ratio of the crank-rocker (§2.2, Ex. 2-1)."""

from dataclasses import dataclass

from mech._generated.fourbar_limit_positions import fourbar_limit_positions
from mech._validate import branch_sign
from mech.planar.structure._lengths import fourbar_lengths_resolved
from mech.planar.structure._grashof import grashof
from mech.planar.structure._quick_return import time_ratio

__all__ = ["LimitPositions", "limit_positions"]


@dataclass(frozen=True)
class LimitPositions:
    """The two limit positions of a crank-rocker and its quick-return parameters.

    All angles are in radians, measured counter-clockwise from +x as in ``FourBar``.

    Attributes
    ----------
    theta_extended, theta_folded : float
        Crank angles where crank and coupler are collinear: extended (AC = b + a) and
        folded (AC = b - a).
    psi_extended, psi_folded : float
        Rocker angles (of D->C) at those positions; the rocker stops and turns back there.
    swing : float
        Rocker swing ``|psi_folded - psi_extended|`` (the textbook's phi).
    extreme_angle : float
        The angle between the two crank positions (极位夹角, the textbook's theta),
        in [0, pi).
    time_ratio : float
        K = (pi + theta) / (pi - theta), eq. (2-9).
    """

    theta_extended: float
    theta_folded: float
    psi_extended: float
    psi_folded: float
    swing: float
    extreme_angle: float
    time_ratio: float


def limit_positions(a, b, c, d, *, branch=1):
    """Limit positions of a crank-rocker, with its swing, extreme angle and time ratio.

    The rocker CD stops where crank AB and coupler BC are collinear: extended, with
    AC = b + a, or folded, with AC = b - a (Fig. 2-37). The triangle ACD then gives the
    crank and rocker angles; the swing, the extreme angle theta and K of eq. (2-9) follow.

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, > 0, forming a crank-rocker.
    branch : {1, -1}, optional
        Assembly mode: +1 puts C left of the directed line B->D (here: above the ground
        line at both limits); -1 is the mirror image in the ground line.

    Returns
    -------
    LimitPositions
        ``theta_extended``, ``theta_folded``, ``psi_extended``, ``psi_folded`` (radians,
        in [-pi, pi]), ``swing``, ``extreme_angle`` and ``time_ratio``.

    Raises
    ------
    ValueError
        If a length is not > 0, if `branch` is not +1 or -1, or if the linkage is not a
        crank-rocker (``grashof(a, b, c, d).kind != "crank-rocker"``).

    Notes
    -----
    Derived in :ref:`deriv-fourbar-limit-positions`: each angle is an ``atan2`` of Heron
    factors (no ``arccos``), and swing and extreme angle come from single ``atan2`` calls,
    not from differences of angles, so a short crank loses no relative accuracy. Branch
    -1 negates all four angles; swing, extreme angle and K are the same on both branches.
    The extreme angle is ``|alpha(b - a) - alpha(b + a)|`` with alpha the angle at A of the
    triangle ACD; it is acute except near the change point a + c = b + d. At a change
    point (s + l = p + q, Fig. 2-38) the two branches share one limit position and the
    linkage has a single assembly mode; the values returned are still the limits of the
    branch asked for. The lengths are scaled internally by a power of two, so any finite
    positive lengths work and the angles do not depend on the unit of length.

    Examples
    --------
    Example 2-1, (a, b, c, d) = (10, 40, 30, 35):

    >>> import numpy as np
    >>> from mech.planar.structure._limit_positions import limit_positions
    >>> lp = limit_positions(10, 40, 30, 35)
    >>> np.degrees([lp.swing, lp.extreme_angle]).round(4)
    array([45.9719, 18.1324])
    >>> round(lp.time_ratio, 5)
    1.22404
    >>> np.degrees([lp.psi_extended, lp.psi_folded]).round(4)
    array([ 79.7134, 125.6853])
    >>> mirror = limit_positions(10, 40, 30, 35, branch=-1)
    >>> bool(np.isclose(mirror.psi_extended, -lp.psi_extended))
    True
    """
    raw = (a, b, c, d)
    a, b, c, d = fourbar_lengths_resolved(a, b, c, d)[0]       # angles only: scale-free lengths
    sign = branch_sign(branch)
    kind = grashof(a, b, c, d).kind
    if kind != "crank-rocker":
        raise ValueError(
            f"Expected `a`, `b`, `c` and `d` of a crank-rocker, got a {kind}: a={raw[0]!r}, b={raw[1]!r}, "
            f"c={raw[2]!r}, d={raw[3]!r}"
        )
    th_e, th_f, ps_e, ps_f, swing, th_s = (float(v) for v in fourbar_limit_positions(a, b, c, d))
    theta = abs(th_s)
    return LimitPositions(
        theta_extended=sign * th_e,
        theta_folded=sign * th_f,
        psi_extended=sign * ps_e,
        psi_folded=sign * ps_f,
        swing=swing,
        extreme_angle=theta,
        time_ratio=time_ratio(theta),
    )
