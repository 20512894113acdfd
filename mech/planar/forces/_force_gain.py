"""Force gain (mechanical advantage), dead points and toggle presses (§2.10, Figs. 2-75 to 2-78).

Closed forms from ``derivations/planar/force_gain.md`` through ``mech._generated.force_gain``;
the general function works on any solved `mech.planar.Linkage`, by its velocities or by its
instant centres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mech._generated import force_gain as _g
from mech._generated.transmission_angle import fourbar_crank_angle_at_diagonal
from mech._validate import (
    branch_sign, finite_array, instance, option, planar_point, planar_points, positive_length, real_number,
)
from mech.planar.kinematics._linkage import Guide, Linkage, LinkageSolution

__all__ = [
    "mechanical_advantage",
    "fourbar_mechanical_advantage",
    "slider_crank_mechanical_advantage",
    "DeadPoints",
    "fourbar_dead_points",
    "slider_crank_dead_points",
    "hand_press",
    "jaw_crusher",
]

_DRIVERS = ("crank", "rocker", "slider")


def _float(x):
    return float(x) if np.ndim(x) == 0 else x


def _spec(solution, spec, what):
    """('moment', link) or ('force', point, unit direction) from a user spec."""
    if isinstance(spec, str):
        if spec not in solution.omegas:
            raise ValueError(f"Expected `{what}` to be a moving link or (point, direction), got {spec!r}")
        return ("moment", spec)
    try:
        point, direction = spec
    except (TypeError, ValueError):
        raise ValueError(f"Expected `{what}` to be a link name or (point, direction), got {spec!r}") from None
    if point not in solution.points:
        raise ValueError(f"Expected the point of `{what}` to be a point of the linkage, got {point!r}")
    u = planar_points(what, direction)
    if np.any(u == 0):
        raise ValueError(f"Expected a non-zero direction in `{what}`, got {direction!r}")
    return ("force", point, u / np.abs(u))


def _rate_velocities(solution, spec):
    if spec[0] == "moment":
        return solution.omegas[spec[1]]
    v = solution.velocities[spec[1]]
    return np.real(np.conj(spec[2]) * v)


def _rate_centres(solution, spec, motion):
    if spec[0] == "moment":
        return np.asarray(motion.omega[spec[1]])
    link = solution.linkage._points[spec[1]]          # the link that carries the point
    if link == "ground":
        return np.zeros(np.shape(solution.points[spec[1]]))
    v = motion.point_velocity(link, solution.points[spec[1]])
    return np.real(np.conj(spec[2]) * v)


def mechanical_advantage(solution, input, output, *, method="velocities"):
    """Force gain of a solved linkage: the load at `output` one unit of effort balances.

    By virtual work, Q_in q_in' = Q_out q_out', so MA = Q_out / Q_in = q_in' / q_out'
    (a moment's rate is the link's omega, a force's the velocity of its point along it).

    Parameters
    ----------
    solution : LinkageSolution
        From ``Linkage.solve(..., order >= 1)``; every pose assembled for ``"centres"``.
    input, output : str or (str, complex array_like)
        A link name (a moment on it) or ``(point, direction)`` (a force at the point
        along the direction; the direction may vary with the pose).
    method : {"velocities", "centres"}
        Rates from the solution's loop velocities, or from the instant centres (Kennedy's
        theorem on the solved positions only); the two agree (:ref:`deriv-force-gain`).

    Returns
    -------
    ma : float or ndarray
        Signed; +-inf where the output stands still (a toggle), 0 where the input does (a
        dead point when driven from the input). Units: load unit per effort unit (1/length
        for force per moment).

    Raises
    ------
    ValueError
        For a solution without velocities, an unknown name, or an unknown method.

    Notes
    -----
    Derivation :ref:`deriv-force-gain`. No friction or inertia: an ideal force gain.

    Examples
    --------
    >>> from mech.planar import Linkage
    >>> lk = (Linkage({"A": 0, "D": 80}).crank("crank", pivot="A", tip="B", length=30)
    ...       .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(70, 60)))
    >>> sol = lk.solve(1.0, order=1)
    >>> a, b = (mechanical_advantage(sol, "crank", "rocker", method=m) for m in ("velocities", "centres"))
    >>> round(float(a), 9) == round(float(b), 9)
    True
    """
    instance("solution", solution, LinkageSolution)
    option("method", method, ("velocities", "centres"))
    if method == "velocities" and solution.order < 1:
        raise ValueError(f"Expected `solution` with velocities (order >= 1) for `method` = 'velocities', got order "
                         f"{solution.order}")
    s_in, s_out = _spec(solution, input, "input"), _spec(solution, output, "output")
    if method == "velocities":
        r_in, r_out = _rate_velocities(solution, s_in), _rate_velocities(solution, s_out)
    else:
        from mech.planar.kinematics._instant_centres import centre_velocities

        ic = solution.instant_centres()
        refs = [k for k in solution.linkage.links if k != "ground" and np.all(ic[k, "ground"].defined)
                and np.all(ic[k, "ground"].homogeneous[..., 2] != 0)]
        if not refs:
            raise ValueError("Expected a link turning about a finite centre to refer the rates to")
        motion = centre_velocities(ic, "ground", refs[0], 1.0)
        r_in, r_out = _rate_centres(solution, s_in, motion), _rate_centres(solution, s_out, motion)
    with np.errstate(divide="ignore", invalid="ignore"):
        return _float(np.asarray(r_in / r_out)[()])


def _driver(driver, allowed):
    return option("driver", driver, allowed)


def fourbar_mechanical_advantage(a, b, c, d, theta, *, branch=1, driver="crank"):
    """Force gain of the four-bar: c sin(psi - phi) / (a sin(theta - phi)) and its inverse.

    Driven by the crank, MA = omega_crank / omega_rocker (rocker moment per crank moment),
    infinite at the toggle (crank and coupler collinear). Driven by the rocker, the inverse
    (crank moment per rocker moment), zero there: the dead points (Fig. 2-75).

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, > 0.
    theta : array_like
        Crank angle, radians.
    branch : {1, -1}
        Assembly branch (`FourBar`).
    driver : {"crank", "rocker"}

    Returns
    -------
    ma : float or ndarray
        Signed; NaN where the linkage cannot be assembled.

    Raises
    ------
    ValueError
        For a bad length, angle, branch or driver.

    Notes
    -----
    Derivation :ref:`deriv-force-gain` (virtual work on the loop rates; equal to the
    ratio of distances from P24 to A and D).

    Examples
    --------
    >>> round(float(fourbar_mechanical_advantage(30, 70, 60, 80, 1.0)), 9)
    3.852088431
    """
    from mech.planar.kinematics._fourbar import FourBar

    _driver(driver, ("crank", "rocker"))
    theta = finite_array("theta", theta)
    pose = FourBar(a, b, c, d, branch=branch).solve(theta)
    with np.errstate(divide="ignore", invalid="ignore"):
        crank, rocker = _g.fourbar_mechanical_advantage(float(a), float(c), theta, pose.phi, pose.psi)
    return _float(np.asarray(crank if driver == "crank" else rocker)[()])


def slider_crank_mechanical_advantage(a, b, e, theta, *, branch=1, driver="crank"):
    """Force gain of the slider-crank: -cos(phi) / (a sin(theta - phi)) and its inverse.

    Driven by the crank (a press), MA = dtheta/dx: slider force per crank moment,
    infinite (np.inf) at the dead centres and within rounding of them where it exceeds the
    float range. Driven by the slider (an engine), MA = dx/dtheta: crank
    moment per piston force, zero at the dead centres: the engine's dead points.

    Parameters
    ----------
    a, b : float
        Crank and rod, > 0.
    e : float
        Offset: the guide is y = e.
    theta : array_like
        Crank angle, radians.
    branch : {1, -1}
        Assembly branch (`SliderCrank`).
    driver : {"crank", "slider"}

    Returns
    -------
    ma : float or ndarray
        Signed; NaN where the rod cannot reach the guide.

    Raises
    ------
    ValueError
        For a bad length, offset, angle, branch or driver.

    Notes
    -----
    Derivation :ref:`deriv-force-gain`; ``|cos(phi)|`` is the cosine of the pressure angle.

    Examples
    --------
    >>> round(float(slider_crank_mechanical_advantage(30, 100, 0, np.pi / 2)), 9)
    -0.033333333
    """
    from mech.planar.kinematics._slider_crank import SliderCrank

    _driver(driver, ("crank", "slider"))
    theta = finite_array("theta", theta)
    pose = SliderCrank(a, b, e, branch=branch).solve(theta)
    # infinite at a dead centre, and within rounding of one where it exceeds the float range
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        crank, slider = _g.slider_crank_mechanical_advantage(float(a), theta, pose.phi)
    return _float(np.asarray(crank if driver == "crank" else slider)[()])


@dataclass(frozen=True)
class DeadPoints:
    """Dead points of a linkage driven by its rocker or slider (`fourbar_dead_points`).

    ``inputs``: the driving link's coordinate there (rocker angle psi, or slider position
    x); ``theta``: the crank angle; ``collinear``: "extended" or "folded" (crank and
    coupler in line, pointing the same way or folded back). Tuples, in that order.
    """

    inputs: tuple
    theta: tuple
    collinear: tuple


def fourbar_dead_points(a, b, c, d, *, branch=1):
    """Rocker angles where a four-bar driven by its rocker CD is at a dead point.

    The coupler is collinear with the driven crank AB, so AC = b + a (extended) or ``|b - a|``
    (folded); the triangle ACD gives the rocker angle psi = +-(pi - angle ADC).

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, > 0.
    branch : {1, -1}
        Keep the poses of this assembly branch (`FourBar`'s convention).

    Returns
    -------
    DeadPoints
        Sorted by psi in (-pi, pi]; empty if the rocker never brings the crank in line.

    Raises
    ------
    ValueError
        For a bad length or branch, or a link not shorter than the other three together.

    Notes
    -----
    Derivation :ref:`deriv-force-gain`. For a crank-rocker these are its limit positions
    (`mech.planar.limit_positions`): the crank-driven toggle and the rocker-driven dead
    point are the same pose.

    Examples
    --------
    >>> dp = fourbar_dead_points(10, 40, 30, 35)           # example 2-1's crank-rocker
    >>> [round(float(np.degrees(p)), 4) for p in dp.inputs], dp.collinear
    ([79.7134, 125.6853], ('extended', 'folded'))
    """
    from mech.planar.structure._lengths import fourbar_lengths

    # angles only: lengths scaled by a power of two, so no product of two overflows
    a, b, c, d = fourbar_lengths(a, b, c, d)[0]
    branch = branch_sign(branch)
    found = []
    for name, k in (("extended", b + a), ("folded", abs(b - a))):
        if k == 0.0:
            continue
        with np.errstate(invalid="ignore"):
            angle_d = float(fourbar_crank_angle_at_diagonal(c, d, k))   # angle ADC
        if not math.isfinite(angle_d):
            continue
        for sign in (1.0, -1.0):
            psi = sign * (math.pi - angle_d)
            C = d + c * complex(math.cos(psi), math.sin(psi))
            B = a * C / (a + b) if name == "extended" else a * C / (a - b)
            cross = ((d - B).conjugate() * (C - B)).imag
            if cross * branch > 0 or (cross == 0 and sign > 0):
                found.append((math.atan2(math.sin(psi), math.cos(psi)), math.atan2(B.imag, B.real), name))
    found.sort()
    return DeadPoints(tuple(f[0] for f in found), tuple(f[1] for f in found), tuple(f[2] for f in found))


def slider_crank_dead_points(a, b, e=0.0, *, branch=1):
    """Slider positions where a slider-crank driven by its slider (an engine) is stuck.

    Crank and rod are collinear: the ends of the stroke (`SliderCrank.limit_positions`).

    Parameters
    ----------
    a, b : float
        Crank and rod, > 0, with b >= a + ``|e|``.
    e : float
        Offset: the guide is y = e.
    branch : {1, -1}

    Returns
    -------
    DeadPoints
        ``inputs`` = (x_extended, x_folded), with the crank angles.

    Raises
    ------
    ValueError
        For bad dimensions, or a crank that cannot turn fully (a + ``|e|`` > b).

    Notes
    -----
    Derivation :ref:`deriv-force-gain`: the engine's MA dx/dtheta is zero exactly there.

    Examples
    --------
    >>> dp = slider_crank_dead_points(30, 100)
    >>> [round(x, 9) for x in dp.inputs], [round(float(np.degrees(t)), 9) for t in dp.theta]
    ([130.0, 70.0], [0.0, -180.0])
    """
    from mech.planar.kinematics._slider_crank import SliderCrank

    a, b, e = positive_length("a", a), positive_length("b", b), real_number("e", e)
    if a + abs(e) > b:
        raise ValueError(f"Expected `a` + |`e`| <= `b` = {b!r} so that the crank turns fully, "
                         f"got a + |e| = {a + abs(e)!r}")
    lim = SliderCrank(a, b, e, branch=branch).limit_positions()
    return DeadPoints((lim.x_extended, lim.x_folded), (lim.theta_extended, lim.theta_folded),
                      ("extended", "folded"))


# ----------------------------------------------------------------------------- toggle presses
def hand_press(*, lever=25.0, handle=250.0, pivot=70.0 - 75.0j, link2=70.0, link3=50.0, link4=50.0):
    """Hand toggle press of Fig. 2-1d, a Watt six-bar with a ram (dimensions chosen here).

    The hand lever ``A B`` (pivot A = `pivot`, handle point H at `handle` behind A) pushes
    the knee C through link 2 ``B C``; link 3 ``D C`` hangs from D = 0 and link 4 ``C E``
    drives the ram E on the vertical guide through D. When D, C and E are collinear
    (lever angle pi/2, the ram at the bottom) the ram's force gain is infinite (肘杆机构).

    Parameters
    ----------
    lever, handle : float
        AB and AH (defaults 25 and 250).
    pivot : complex
        The lever's pivot A (default 70 - 75j).
    link2, link3, link4 : float
        BC, DC and CE (defaults 70, 50, 50).

    Returns
    -------
    Linkage
        Points D, A (ground), B, H, C, E; links lever, link2, link3, link4, ram; driver
        "lever" (its angle; pi/2 is the toggle).

    Raises
    ------
    ValueError
        If a length is not positive.

    Notes
    -----
    The textbook's figure has no dimensions. Force gain with `mechanical_advantage`
    (derivation :ref:`deriv-force-gain`).

    Examples
    --------
    >>> sol = hand_press().solve(np.pi / 2, order=1)
    >>> complex(sol.points["E"]).imag
    -100.0
    """
    L = {k: positive_length(k, v) for k, v in dict(lever=lever, handle=handle, link2=link2,
                                                        link3=link3, link4=link4).items()}
    return (Linkage({"D": 0.0, "A": planar_point("pivot", pivot)})
            .crank("lever", pivot="A", tip="B", length=L["lever"])
            .point("H", link="lever", at=-L["handle"])
            .rrr(("link2", "link3"), pins=("B", "D"), joint="C", lengths=(L["link2"], L["link3"]), branch=1)
            .rrp(("link4", "ram"), pin="C", guide=Guide("ground", "D", -math.pi / 2), joint="E",
                 length=L["link4"], branch=1))


def jaw_crusher(*, crank=12.0, pitman=250.0, toggle_back=90.0, toggle_front=90.0, jaw=300.0,
                back_pivot=88.0 - 268.0j, jaw_pivot=-100.0 + 32.0j):
    """Jaw crusher of Fig. 2-23a as a Watt six-bar toggle (dimensions chosen here).

    The eccentric crank ``A B`` (A = 0) lifts the pitman ``B C``; two toggle plates meet
    at its foot C: the back plate ``C D`` rests on the frame at D and the front plate
    ``C E`` pushes the swing jaw ``F E``, which hangs from F. As the plates come into line
    the jaw's moment per crank moment grows without bound (the toggle, 肘杆机构).

    Parameters
    ----------
    crank, pitman, toggle_back, toggle_front, jaw : float
        AB (the eccentricity), BC, CD, CE and FE (defaults 12, 250, 90, 90, 300).
    back_pivot, jaw_pivot : complex
        D and F (defaults 88 - 268j and -100 + 32j): the plates open to about 172 degrees.

    Returns
    -------
    Linkage
        Points A, D, F (ground), B, C, E; links crank, pitman, back, front, jaw.

    Raises
    ------
    ValueError
        If a length is not positive.

    Notes
    -----
    Force gain with `mechanical_advantage(sol, "crank", "jaw")` (derivation
    :ref:`deriv-force-gain`).

    Examples
    --------
    >>> sol = jaw_crusher().solve(np.linspace(0, 2 * np.pi, 73))
    >>> bool(sol.valid.all())
    True
    """
    L = {k: positive_length(k, v) for k, v in dict(crank=crank, pitman=pitman, toggle_back=toggle_back,
                                                        toggle_front=toggle_front, jaw=jaw).items()}
    return (Linkage({"A": 0.0, "D": planar_point("back_pivot", back_pivot),
                     "F": planar_point("jaw_pivot", jaw_pivot)})
            .crank("crank", pivot="A", tip="B", length=L["crank"])
            .rrr(("pitman", "back"), pins=("B", "D"), joint="C", lengths=(L["pitman"], L["toggle_back"]),
                 branch=-1)
            .rrr(("front", "jaw"), pins=("C", "F"), joint="E", lengths=(L["toggle_front"], L["jaw"]),
                 branch=1))
