"""Special spherical four-bars of the monograph's chapter 7: the universal joint, the
isogram, the deltoid and the spherical slider-crank.

Derived on ``derivations/spherical/types.md`` (label ``deriv-spherical-types``); the
formulas come from ``mech._generated.spherical_types``.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated.spherical_types import (
    deltoid_half_input,
    isogram_output_angle,
    isogram_ratios,
    spherical_slider_limits,
)
from mech._validate import arc as _arc, bool_flag, branch_sign, finite_array, real_number
from mech.planar import time_ratio
from mech.spherical._fourbar import SphericalFourBar

__all__ = [
    "universal_joint",
    "isogram",
    "isogram_output",
    "deltoid",
    "deltoid_input",
    "spherical_slider_crank",
    "slider_crank_stroke",
    "SliderStroke",
]


def _out(x):
    return float(x) if np.ndim(x) == 0 else x


def universal_joint(shaft_angle):
    """The universal joint (万向联轴节) as a spherical four-bar.

    Input, cross and output arcs are right angles, a = b = c = pi/2, and the ground arc is
    the shaft angle, d = alpha. The input angle theta is the textbook's theta1 and the
    output psi = theta3 - pi/2 (mod 2 pi), on branch +1 throughout.

    Parameters
    ----------
    shaft_angle : float
        Angle alpha between the shafts, radians in (0, pi/2).

    Returns
    -------
    SphericalFourBar
        ``SphericalFourBar(pi/2, pi/2, pi/2, alpha, branch=1)``.

    Raises
    ------
    ValueError
        If `shaft_angle` is not in (0, pi/2) (at pi/2 the joint locks).

    Notes
    -----
    Derived on :ref:`deriv-spherical-types` (section "The universal joint"): the loop
    equation B . C = 0 becomes tan(theta1) = tan(theta3) cos(alpha) (F74) of
    `mech.spatial.hooke_output`, and det[B, D, C] never vanishes. Ground arc pi - alpha
    describes the same joint (the antipode move of D). There is no planar limit.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial import hooke_output
    >>> from mech.spherical._special import universal_joint
    >>> joint = universal_joint(np.radians(30.0))
    >>> psi = joint.solve(np.radians(45.0)).psi
    >>> round(float(np.degrees(psi + np.pi / 2)), 6), round(float(np.degrees(hooke_output(np.radians(45.0), np.radians(30.0)))), 6)
    (49.106605, 49.106605)
    """
    alpha = real_number("shaft_angle", shaft_angle)
    if not 0.0 < alpha < np.pi / 2:
        raise ValueError(f"Expected `shaft_angle` in (0, pi/2), got {alpha!r}")
    return SphericalFourBar(np.pi / 2, np.pi / 2, np.pi / 2, alpha, branch=1)


def isogram(a, b, *, branch=1):
    """The spherical isogram: opposite arcs equal, a = c and b = d.

    Parameters
    ----------
    a : float
        Arcs AB = CD, radians in (0, pi).
    b : float
        Arcs BC = DA (the ground), radians in (0, pi).
    branch : {1, -1}, optional
        Assembly branch of the returned four-bar.

    Returns
    -------
    SphericalFourBar
        ``SphericalFourBar(a, b, a, b, branch=branch)``.

    Raises
    ------
    ValueError
        If an arc is not in (0, pi) or `branch` is not +1 or -1.

    Notes
    -----
    Its loop splits into two motions tan(psi/2) = k tan(theta/2) (eq. (3) of
    :ref:`deriv-spherical-types`, see `isogram_output`) that meet at theta = 0 and pi.
    `SphericalFourBar` continues each motion smoothly through these change points, so
    branch +1 is the "parallelogram" motion at every input angle and branch -1 the crossed
    one (each passes from one sign of det[B, D, C] to the other at 0 and pi).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._special import isogram, isogram_output
    >>> psi = isogram(0.4, 0.9).solve([1.0, 4.0]).psi
    >>> np.allclose(psi, np.angle(np.exp(1j * isogram_output([1.0, 4.0], 0.4, 0.9))))
    True
    """
    return SphericalFourBar(a, b, a, b, branch=branch_sign(branch))


def isogram_output(theta, a, b, *, crossed=False):
    """Output angle of the spherical isogram (a = c, b = d), continuous in theta.

    tan(psi/2) = k tan(theta/2) with k = cos((a+b)/2) / cos((a-b)/2) for the motion that
    becomes the planar parallelogram, and k = sin((a+b)/2) / sin((a-b)/2) for the crossed
    one (the anti-parallelogram), eq. (3).

    Parameters
    ----------
    theta : array_like, shape (...)
        Input angle, radians.
    a, b : float
        Arcs AB = CD and BC = DA, radians in (0, pi), a != b for the crossed motion.
    crossed : bool, optional
        The crossed motion instead of the parallel one.

    Returns
    -------
    psi : float or ndarray, shape (...)
        Output angle, continuous in theta: psi(theta + 2 pi) = psi(theta) + 2 pi sign(k).

    Raises
    ------
    ValueError
        If an arc is not in (0, pi), theta is not finite, or k is 0 (a + b = pi on the
        parallel motion) or infinite (a = b on the crossed one).

    Notes
    -----
    Derived on :ref:`deriv-spherical-types`; as the arcs shrink, k -> 1 (psi = theta) and
    k -> (a + b)/(a - b). On the sphere the parallel motion is not uniform.

    Examples
    --------
    >>> from mech.spherical._special import isogram_output
    >>> round(float(isogram_output(1.0, 0.4, 0.9)), 6)
    0.843805
    >>> round(float(isogram_output(1.0, 1e-4, 3e-4)), 6)    # planar parallelogram: psi = theta
    1.0
    """
    theta = finite_array("theta", theta)
    a, b = _arc("a", a), _arc("b", b)
    crossed = bool_flag("crossed", crossed)
    if crossed and a == b:
        raise ValueError(f"Expected `a` != `b` for the crossed isogram, got a = b = {a!r}")
    k_par, k_cross = (float(k) for k in isogram_ratios(a, b))
    k = k_cross if crossed else k_par
    if k == 0.0:
        raise ValueError(f"Expected `a` + `b` != pi for the parallel isogram, got {a + b!r}")
    sign = np.sign(k)
    return _out(sign * isogram_output_angle(theta, abs(k)))


def deltoid(a, b, *, branch=1):
    """The spherical deltoid (kite, 筝形) with crank equal to ground: a = d, b = c.

    Parameters
    ----------
    a : float
        Arcs AB = DA, radians in (0, pi).
    b : float
        Arcs BC = CD, radians in (0, pi).
    branch : {1, -1}, optional
        Assembly branch of the returned four-bar.

    Returns
    -------
    SphericalFourBar
        ``SphericalFourBar(a, b, b, a, branch=branch)``.

    Raises
    ------
    ValueError
        If an arc is not in (0, pi) or `branch` is not +1 or -1.

    Notes
    -----
    At theta = 0 the joint B lies on D and the coupler swings freely. C lies on the
    great circle through A that bisects the input angle, and for a < b < pi - a the
    motion continued through theta = 0 changes from branch +1 to -1 and the output turns
    once per two crank turns (eq. (6) of :ref:`deriv-spherical-types`, `deltoid_input`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._special import deltoid, deltoid_input
    >>> psi = deltoid(0.3, 0.8).solve(1.0).psi
    >>> bool(np.isclose(deltoid_input(psi, 0.3, 0.8), 1.0))
    True
    """
    return SphericalFourBar(a, b, b, a, branch=branch_sign(branch))


def deltoid_input(psi, a, b):
    """Input angle of the deltoid (a = d, b = c) as a function of its output angle.

    theta/2 = atan2(sin b sin psi, sin a cos b + cos a sin b cos psi) modulo 2 pi, eq. (6),
    taken within pi of psi: continuous, theta(psi + 2 pi) = theta(psi) + 4 pi.

    Parameters
    ----------
    psi : array_like, shape (...)
        Output angle, radians.
    a, b : float
        Arcs AB = DA and BC = CD, radians, with 0 < a < b < pi - a.

    Returns
    -------
    theta : float or ndarray, shape (...)
        Input angle on the motion through theta = 0, psi = 0.

    Raises
    ------
    ValueError
        If psi is not finite, or not 0 < a < b < pi - a (then the output does not turn).

    Notes
    -----
    Derived on :ref:`deriv-spherical-types`: the 2:1 property, the spherical Galloway kite.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._special import deltoid_input
    >>> float(deltoid_input(2 * np.pi, 0.3, 0.8) / np.pi)    # one output turn, two crank turns
    4.0
    """
    psi = finite_array("psi", psi)
    a, b = _arc("a", a), _arc("b", b)
    if not a < b < np.pi - a:
        raise ValueError(f"Expected 0 < `a` < `b` < pi - `a`, got a = {a!r}, b = {b!r}")
    half = deltoid_half_input(a, b, psi)
    # theta/2 and psi lie in the same half-turn (both in (0, pi) while sin(psi) > 0)
    return _out(2.0 * (psi + np.angle(np.exp(1j * (half - psi)))))


def spherical_slider_crank(a, b, e=0.0, *, branch=1):
    """The spherical slider-crank (球面曲柄滑块机构): c = pi/2, d = pi/2 + e.

    C moves on the great circle whose pole is D (the guide); A is at arc ``|e|`` from it.

    Parameters
    ----------
    a, b : float
        Crank arc AB and coupler arc BC, radians in (0, pi).
    e : float, optional
        Offset (偏距), radians in (-pi/2, pi/2).
    branch : {1, -1}, optional
        As for `mech.planar.SliderCrank`: +1 puts the slider ahead of the crank pin along
        the guide direction; the returned four-bar has ``branch = -branch``.

    Returns
    -------
    SphericalFourBar
        ``SphericalFourBar(a, b, pi/2, pi/2 + e, branch=-branch)``; the slider position
        along the guide is s = (psi mod 2 pi) - pi.

    Raises
    ------
    ValueError
        If an arc is not in (0, pi), `e` not in (-pi/2, pi/2), or `branch` not +1 or -1.

    Notes
    -----
    Derived on :ref:`deriv-spherical-types`: as a, b and e shrink, s tends to x of
    ``SliderCrank(a, b, e)`` at the planar crank angle theta + pi/2.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import SliderCrank
    >>> from mech.spherical._special import spherical_slider_crank
    >>> s = np.mod(spherical_slider_crank(2e-3, 5e-3, 1e-3).solve(1.0).psi, 2 * np.pi) - np.pi
    >>> x = SliderCrank(2e-3, 5e-3, 1e-3).solve(1.0 + np.pi / 2).x
    >>> bool(abs(s - x) < 1e-8)
    True
    """
    e = real_number("e", e)
    if not -np.pi / 2 < e < np.pi / 2:
        raise ValueError(f"Expected `e` in (-pi/2, pi/2), got {e!r}")
    return SphericalFourBar(a, b, np.pi / 2, np.pi / 2 + e, branch=-branch_sign(branch))


@dataclass(frozen=True)
class SliderStroke:
    """Limit positions of a spherical slider-crank: the result of `slider_crank_stroke`."""

    stroke: float
    s_extended: float
    s_folded: float
    extreme_angle: float
    time_ratio: float


def slider_crank_stroke(a, b, e=0.0):
    """Stroke, extreme angle and time ratio of the spherical slider-crank.

    With r = AC, the slider is at the arc s(r) = atan2(sqrt(sin(r + e) sin(r - e)), cos r)
    from the foot of the perpendicular from A (eq. (5)); the limit positions are
    r = a + b and r = b - a, the stroke (行程) is H = s(a + b) - s(b - a), and the
    extreme angle (极位夹角) is the crank angle between them less pi.

    Parameters
    ----------
    a, b : float
        Crank arc AB and coupler arc BC, radians in (0, pi).
    e : float, optional
        Offset, radians (ground arc d = pi/2 + e).

    Returns
    -------
    SliderStroke
        Frozen record with ``stroke``, ``s_extended``, ``s_folded`` (arcs along the guide),
        ``extreme_angle`` and ``time_ratio`` K = (pi + theta) / (pi - theta).

    Raises
    ------
    ValueError
        Unless the crank turns fully with b - a > ``|e|`` and a + b + ``|e|`` < pi.

    Notes
    -----
    Derived on :ref:`deriv-spherical-types`; as the arcs shrink these become
    ``SliderCrank(a, b, e).stroke()``, ``.extreme_angle()`` and ``.time_ratio()``.

    Examples
    --------
    >>> from mech.spherical._special import slider_crank_stroke
    >>> r = slider_crank_stroke(0.3, 0.8, 0.1)
    >>> round(r.stroke, 6), round(r.extreme_angle, 6), round(r.time_ratio, 6)
    (0.606712, 0.133621, 1.088844)
    """
    a, b = _arc("a", a), _arc("b", b)
    e = real_number("e", e)
    if not (b - a > abs(e) and a + b + abs(e) < np.pi):
        raise ValueError(
            f"Expected `a`, `b` and `e` with b - a > |e| and a + b + |e| < pi (a crank), got a={a!r}, b={b!r}, "
            f"e={e!r}"
        )
    s_ext, s_fold, g_ext, g_fold = (float(v) for v in spherical_slider_limits(a, b, e))
    theta = g_fold - g_ext
    return SliderStroke(
        stroke=s_ext - s_fold,
        s_extended=s_ext,
        s_folded=s_fold,
        extreme_angle=abs(theta),
        time_ratio=float(time_ratio(abs(theta))),
    )
