"""Pressure and transmission angles: any solved linkage, the four-bar, slider-crank, guide-bar.

The formulas come from ``derivations/planar/pressure_angle.md`` (F49 to F59) through
``mech._generated.pressure_angle``; the four-bar's angle BCD of eq. (2-30) comes from
``mech.planar.forces._transmission``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mech._generated import pressure_angle as _g
from mech._generated.transmission_angle import fourbar_transmission
from mech._geometry import acute_angle
from mech._scaling import length_scale
from mech._validate import (
    bool_flag, finite_array, instance, known_name, planar_points, positive_length, real_number,
)
from mech.planar.structure._grashof import grashof
from mech.planar.forces._transmission import at_dead_points, check_assembled
from mech.planar.structure._lengths import fourbar_lengths, fourbar_lengths_resolved
from mech.planar.kinematics._linkage import LinkageSolution

__all__ = [
    "pressure_angle",
    "joint_transmission_angle",
    "fourbar_pressure_angle",
    "TransmissionExtremes",
    "transmission_extremes",
    "slider_crank_pressure_angle",
    "slider_crank_min_transmission_angle",
    "guide_bar_pressure_angle",
    "watt_transmission_angles",
    "design_check",
]


def _float(x):
    return float(x) if np.ndim(x) == 0 else x


def _is_key(value, mapping):
    try:
        return value in mapping
    except TypeError:            # an unhashable value is no name
        return False


def _force_direction(solution, joint, force):
    if isinstance(force, str):
        if force not in solution.points:
            raise ValueError(f"Expected `force` to be a point name or a direction, got {force!r}")
        return solution.points[joint] - solution.points[force]
    u = planar_points("force", force)
    if np.any(u == 0):
        raise ValueError(f"Expected a non-zero `force` direction, got {force!r}")
    return u


def _follower_velocity(solution, joint, follower):
    """Velocity of the point of `follower` at `joint`, i omega (J - P_f0), by the centres."""
    from mech.planar.kinematics._instant_centres import centre_velocities

    ic = solution.instant_centres()
    cranks = [k for k in solution.omegas if np.all(ic[k, "ground"].defined)
              and np.all(ic[k, "ground"].homogeneous[..., 2] != 0)]
    if not cranks:
        raise ValueError("Expected a link turning about a finite centre to refer the rates to")
    ref = cranks[0]
    motion = centre_velocities(ic, "ground", ref, solution.omegas[ref])
    return motion.point_velocity(follower, solution.points[joint])


def pressure_angle(solution, joint, force, *, follower=None):
    """Pressure angle at a point of a solved linkage: force against velocity (F49).

    alpha = atan2(``|u x v|``, ``|u . v|``) in [0, pi/2], the acute angle between the line of
    the driving force u and the velocity v of the follower's point where it acts.

    Parameters
    ----------
    solution : LinkageSolution
        From ``Linkage.solve(..., order=1)`` (or higher); every pose assembled if
        `follower` is given.
    joint : str
        The point where the force acts.
    force : str or complex array_like
        The other pin of a two-force coupler (the force is along that pin -> `joint`), or
        the force's direction (e.g. the normal of a guide).
    follower : str, optional
        The driven link. By default the velocity of the point `joint` itself is used
        (right for a revolute joint); for a block in a guide give the guide link, whose
        coincident point moves with i omega (J - P) about its instant centre P.

    Returns
    -------
    alpha : float or ndarray
        Pressure angle, radians; NaN where the pose is not assembled.

    Raises
    ------
    ValueError
        If `solution` has no velocities, or a name or direction is bad.

    Notes
    -----
    Derivation :ref:`deriv-pressure-angle`; the transmission angle is pi/2 - alpha
    (`joint_transmission_angle`). Where the point stands still (v = 0) the angle is that
    of u against the x axis and carries no meaning.

    Examples
    --------
    >>> from mech.planar import FourBar, Linkage
    >>> lk = (Linkage({"A": 0, "D": 80}).crank("crank", pivot="A", tip="B", length=30)
    ...       .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(70, 60)))
    >>> sol = lk.solve(0.0, order=1)
    >>> round(float(np.degrees(pressure_angle(sol, "C", "B"))), 4)
    45.5847
    """
    instance("solution", solution, LinkageSolution)
    if solution.order < 1:
        raise ValueError(f"Expected `solution` with velocities (order >= 1), got order {solution.order}")
    known_name("joint", joint, tuple(solution.points))
    u = _force_direction(solution, joint, force)
    if follower is None:
        v = solution.velocities[joint]
    else:
        if not _is_key(follower, solution.omegas):
            raise ValueError(f"Expected `follower` to be a moving link, got {follower!r}")
        v = _follower_velocity(solution, joint, follower)
    return _float(acute_angle(u, v))


def joint_transmission_angle(solution, joint, force, *, follower=None, pivot=None):
    """Transmission angle gamma = pi/2 - alpha at a joint of a solved linkage (F50).

    With `pivot`, the follower turns about that fixed point and positions suffice:
    gamma is the acute angle between the force line and the follower's arm pivot -> joint.

    Parameters
    ----------
    solution : LinkageSolution
        A solved linkage (any order with `pivot`, order >= 1 otherwise).
    joint, force, follower : see `pressure_angle`.
    pivot : str, optional
        The follower's fixed pivot (a point name).

    Returns
    -------
    gamma : float or ndarray
        Transmission angle in [0, pi/2], radians.

    Raises
    ------
    ValueError
        As `pressure_angle`, or if `pivot` is not a point.

    Notes
    -----
    Derivation :ref:`deriv-pressure-angle`: with v perpendicular to the arm, the acute
    angle between force and arm is pi/2 - alpha.

    Examples
    --------
    >>> from mech.planar import watt_six_bar
    >>> sol = watt_six_bar().solve(0.0)
    >>> round(float(np.degrees(joint_transmission_angle(sol, "C", "B", pivot="D"))), 4)
    36.3361
    """
    if pivot is None:
        return _float(np.pi / 2 - pressure_angle(solution, joint, force, follower=follower))
    instance("solution", solution, LinkageSolution)
    known_name("joint", joint, tuple(solution.points))
    known_name("pivot", pivot, tuple(solution.points))
    u = _force_direction(solution, joint, force)
    return _float(acute_angle(u, solution.points[joint] - solution.points[pivot]))


def fourbar_pressure_angle(a, b, c, d, theta, *, strict=False):
    """Pressure angle at the rocker pin C of the four-bar, alpha = pi/2 - gamma (F50).

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, > 0.
    theta : array_like
        Crank angle, radians.
    strict : bool, optional
        Raise `AssemblyError` instead of returning NaN where the linkage cannot be
        assembled, as `FourBar.solve` does.

    Returns
    -------
    alpha : float or ndarray
        Pressure angle in [0, pi/2], radians; NaN where the linkage cannot be assembled.

    Raises
    ------
    ValueError
        If a length is not positive and finite, if one link is not shorter than the other
        three together (as for `FourBar`), or if `theta` is not finite.
    AssemblyError
        With ``strict=True``, naming the first input angle that cannot be assembled.

    Notes
    -----
    gamma from eq. (2-30) as in `mech.planar.transmission_angle`; both branches have the
    same angle. Derivation :ref:`deriv-pressure-angle`. The lengths are scaled internally
    by a power of two, so the angle does not depend on the unit of length.

    Examples
    --------
    >>> round(float(np.degrees(fourbar_pressure_angle(30, 70, 60, 80, 0.0))), 4)
    45.5847
    """
    lengths = (a, b, c, d)
    a, b, c, d = fourbar_lengths(a, b, c, d)[0]     # angles only: any power-of-two scale
    theta = finite_array("theta", theta)
    with np.errstate(invalid="ignore"):
        _, gamma = fourbar_transmission(a, b, c, d, theta)
    gamma = at_dead_points(gamma, a, b, c, d, theta)
    check_assembled(gamma, theta, lengths, strict)
    return _float(np.pi / 2 - gamma)


@dataclass(frozen=True)
class TransmissionExtremes:
    """Extremes of the four-bar's angle BCD over a crank turn (F53 to F55), radians.

    ``delta_min`` at ``theta = 0`` (BD = d - a), ``delta_max`` at ``theta = pi``
    (BD = d + a), ``gamma_min`` = the minimum transmission angle and ``theta_at`` the crank
    angle where it occurs, ``rule`` the branch of F55 that decided it.
    """

    delta_min: float
    delta_max: float
    gamma_min: float
    theta_at: float
    rule: str


def transmission_extremes(a, b, c, d):
    """Extremes of the angle BCD and the minimum transmission angle of a turning crank.

    cos(delta_min) = (b^2 + c^2 - (d - a)^2) / (2bc), cos(delta_max) = (b^2 + c^2 -
    (d + a)^2) / (2bc) (F54); gamma_min = delta_min if delta_max <= pi/2, otherwise
    min(delta_min, pi - delta_max) (F55).

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, > 0, with a crank that turns fully.

    Returns
    -------
    TransmissionExtremes

    Raises
    ------
    ValueError
        If a length is not > 0, or the crank does not turn fully (not a crank-rocker or a
        double-crank).

    Notes
    -----
    The diagonal BD is monotone on [0, pi] (derivation :ref:`deriv-pressure-angle`).

    Examples
    --------
    >>> x = transmission_extremes(30, 70, 60, 80)
    >>> [round(float(np.degrees(v)), 4) for v in (x.delta_min, x.delta_max, x.gamma_min)]
    [44.4153, 115.3769, 44.4153]
    >>> x.theta_at, x.rule
    (0.0, 'min(delta_min, pi - delta_max)')
    """
    raw = (a, b, c, d)
    a, b, c, d = fourbar_lengths_resolved(a, b, c, d)[0]
    kind = grashof(a, b, c, d).kind
    if kind not in ("crank-rocker", "double-crank"):
        raise ValueError(f"Expected `a`, `b`, `c` and `d` of a crank that turns fully (crank-rocker or "
                         f"double-crank), got a {kind}: a={raw[0]!r}, b={raw[1]!r}, c={raw[2]!r}, d={raw[3]!r}")
    (d0, dpi), _ = fourbar_transmission(a, b, c, d, np.array([0.0, np.pi]))
    d0, dpi = float(d0), float(dpi)
    if dpi <= np.pi / 2:
        return TransmissionExtremes(d0, dpi, d0, 0.0, "delta_min")
    if np.pi - dpi < d0:
        return TransmissionExtremes(d0, dpi, np.pi - dpi, float(np.pi), "min(delta_min, pi - delta_max)")
    return TransmissionExtremes(d0, dpi, d0, 0.0, "min(delta_min, pi - delta_max)")


def slider_crank_pressure_angle(a, b, e, theta):
    """Pressure angle at the slider of the offset slider-crank (F56).

    sin(alpha) = ``|a sin(theta) - e|`` / b with the guide on y = e (`SliderCrank`'s
    convention; the textbook's e is measured on the other side, k = a sin(phi_1) + e).

    Parameters
    ----------
    a, b : float
        Crank AB and rod BC, > 0.
    e : float
        Offset: the guide is the line y = e.
    theta : array_like
        Crank angle, radians.

    Returns
    -------
    alpha : float or ndarray
        Pressure angle in [0, pi/2], radians; NaN where the rod cannot reach the guide.

    Raises
    ------
    ValueError
        If `a` or `b` is not > 0, or `e` or `theta` is not finite.

    Notes
    -----
    Derivation :ref:`deriv-pressure-angle`; the transmission angle
    `SliderCrank.transmission_angle` is pi/2 - alpha.

    Examples
    --------
    >>> round(float(np.degrees(slider_crank_pressure_angle(30, 100, 20, -np.pi / 2))), 9)
    30.0
    """
    a, b = positive_length("a", a), positive_length("b", b)
    e = real_number("e", e)
    theta = finite_array("theta", theta)
    unit = length_scale(a, b, e)         # an angle: the same in any unit of length
    with np.errstate(invalid="ignore"):
        return _float(_g.slider_crank_pressure_angle(a / unit, b / unit, e / unit, theta))


def slider_crank_min_transmission_angle(a, b, e=0.0):
    """Minimum transmission angle of the offset slider-crank and where it occurs (F57).

    cos(gamma_min) = (a + ``|e|``) / b, with the crank perpendicular to the guide and pointing
    away from it: theta_at = -pi/2 for e >= 0, +pi/2 for e < 0.

    Parameters
    ----------
    a, b : float
        Crank and rod, > 0.
    e : float, optional
        Offset: the guide is y = e.

    Returns
    -------
    gamma_min, theta_at : float
        Radians.

    Raises
    ------
    ValueError
        If a length is not > 0, or a + ``|e|`` > b (the crank cannot turn fully).

    Notes
    -----
    Derivation :ref:`deriv-pressure-angle` (F56, F57): gamma_min = pi/2 - max alpha.

    Examples
    --------
    >>> g, th = slider_crank_min_transmission_angle(30, 100, 20)
    >>> round(float(np.degrees(g)), 9), round(float(np.degrees(th)), 9)
    (60.0, -90.0)
    """
    a, b = positive_length("a", a), positive_length("b", b)
    e = real_number("e", e)
    if a + abs(e) > b:
        raise ValueError(f"Expected `a` + |`e`| <= `b` = {b!r} so that the crank turns fully, "
                         f"got a + |e| = {a + abs(e)!r}")
    theta_at = np.pi / 2 if e < 0 else -np.pi / 2
    unit = length_scale(a, b, e)         # an angle: the same in any unit of length
    alpha = _g.slider_crank_pressure_angle(a / unit, b / unit, e / unit, theta_at)
    return float(np.pi / 2 - alpha), float(theta_at)


def guide_bar_pressure_angle(s, e=0.0):
    """Pressure angle at the block of a guide-bar: tan(alpha) = ``|e|`` / ``|s|`` (F58).

    Parameters
    ----------
    s : array_like
        Block position along the guide, from the foot of the bar's pivot.
    e : float, optional
        Offset of the guide line from the pivot (0: the textbook's guide-bar).

    Returns
    -------
    alpha : float or ndarray
        Radians; identically 0 for e = 0 (gamma = 90 degrees at every position).

    Raises
    ------
    ValueError
        If `s` or `e` is not finite.

    Notes
    -----
    Derivation :ref:`deriv-pressure-angle`: the block pushes along the guide's normal and
    the bar's coincident point moves with omega (s n - e t).

    Examples
    --------
    >>> guide_bar_pressure_angle([10.0, 200.0]).tolist()
    [0.0, 0.0]
    >>> round(float(np.degrees(guide_bar_pressure_angle(10.0, 10.0))), 9)
    45.0
    """
    s = finite_array("s", s)
    e = real_number("e", e)
    return _float(_g.guide_bar_pressure_angle(e, s))


def watt_transmission_angles(solution):
    """Transmission angles of the two four-bars of a Watt six-bar (F59, Fig. 2-74).

    Parameters
    ----------
    solution : LinkageSolution
        A solved `mech.planar.watt_six_bar` (points B, C, D, E, F, G).

    Returns
    -------
    gamma_1, gamma_2 : float or ndarray
        At C (coupler BC on the rocker CD) and at G (link EG on the output FG), radians.

    Raises
    ------
    ValueError
        If the solution lacks those points.

    Notes
    -----
    Derivation :ref:`deriv-pressure-angle`; the chain's worst transmission is the smaller
    of the two minima over a crank turn.

    Examples
    --------
    >>> from mech.planar import watt_six_bar
    >>> g1, g2 = watt_transmission_angles(watt_six_bar().solve(0.0))
    >>> round(float(np.degrees(g1)), 4), round(float(np.degrees(g2)), 4)
    (36.3361, 78.5128)
    """
    instance("solution", solution, LinkageSolution)
    need = {"B", "C", "D", "E", "F", "G"} - set(solution.points)
    if need:
        raise ValueError(f"Expected a solved Watt six-bar with points B, C, D, E, F, G, missing {sorted(need)}")
    return (joint_transmission_angle(solution, "C", "B", pivot="D"),
            joint_transmission_angle(solution, "G", "E", pivot="F"))


def design_check(gamma_min, *, high_speed=False):
    """True if a minimum transmission angle meets the design limit (F51).

    gamma_min >= 40 degrees in general, >= 50 degrees for high-speed or high-power machines.

    Examples
    --------
    >>> design_check(np.radians(44.4153)), design_check(np.radians(44.4153), high_speed=True)
    (True, False)
    """
    g = real_number("gamma_min", gamma_min)
    high_speed = bool_flag("high_speed", high_speed)
    return bool(g >= np.radians(50.0 if high_speed else 40.0))
