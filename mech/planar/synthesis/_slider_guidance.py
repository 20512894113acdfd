"""Rigid-body guidance by slider (point-on-line) dyads, and guidance slider-cranks.

A slider dyad is an RR dyad whose centre point lies at infinity: a pin fixed in the guided
body whose positions in all the poses lie on one straight line, the guide of a block. Three
poses leave a circle of such body points (through the pole of poses 1 and 2), four poses a
finite set. A slider dyad and an RR crank make a slider-crank whose coupler is the body;
`guidance_slider_crank` builds it as a `mech.planar.Linkage` (crank + RRP group) and proves
it by analysis.
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import MAX_COUNT, _show, finite_array, instance, integer, nonnegative_number, planar_point
from mech.planar.kinematics._linkage import Guide, Linkage
from mech.planar.synthesis._displacement import pose_set
from mech.planar.synthesis._guidance import Dyad

__all__ = [
    "SliderDyad", "SliderCircle", "GuidanceSliderCrank",
    "slider_dyad_for_point", "slider_point_circle", "slider_dyads", "guidance_slider_crank",
]

_TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class SliderDyad:
    """A slider dyad: a body pin whose positions lie on one line (the guide).

    Attributes
    ----------
    slider_point : complex
        The pin in body coordinates (a body point ``z`` is at ``exp(1j*theta)*z + d``).
    moving_pivot : complex
        The pin in the ground frame at the first pose; it is also the guide's ``line_point``.
    line_point : complex
        A point of the guide line (the pin at the first pose).
    direction : complex
        Unit direction of the guide, from the first position towards the position farthest
        from it.
    s : ndarray, shape (n,)
        Position of the pin along the guide at every pose, ``s[0] = 0``.
    """

    slider_point: complex
    moving_pivot: complex
    line_point: complex
    direction: complex
    s: np.ndarray


@dataclass(frozen=True)
class SliderCircle:
    """The circle of body points whose three positions are collinear (returned by `slider_point_circle`).

    Attributes
    ----------
    centre : complex
        Centre, body coordinates.
    radius : float
        Radius.
    pole : complex
        The pole of poses 1 and 2 in body coordinates; it lies on the circle.
    """

    centre: complex
    radius: float
    pole: complex

    def points(self, n=360):
        """``n`` points of the circle (body coordinates), evenly spaced from the pole."""
        n = integer("n", n, minimum=1, maximum=MAX_COUNT)
        start = np.angle(self.pole - self.centre)
        return self.centre + self.radius * np.exp(1j * (start + _TWO_PI * np.arange(n) / n))


def _images(theta, d, z):
    return np.exp(1j * theta) * z + d


def _turn_factor(theta_1, theta_j):
    """exp(1j*theta_j) - exp(1j*theta_1), without cancellation for a small relative turn."""
    h = 0.5 * (theta_j - theta_1)
    return 2j * np.sin(h) * np.exp(1j * (theta_1 + h))


def _line_of(positions, name, value, rtol):
    """The line through `positions` (direction to the farthest one), after a collinearity check."""
    rel = positions - positions[0]
    far = int(np.argmax(np.abs(rel)))
    spread = float(np.abs(rel[far]))
    if not spread > 0.0:
        raise ValueError(
            f"Expected `{name}` whose positions are not all one point (it is a common pole), got {_show(value)}"
        )
    e = rel[far] / spread
    off = np.abs(np.imag(np.conj(e) * rel))
    if np.max(off) > rtol * spread:
        raise ValueError(
            f"Expected `{name}` whose positions are collinear (a slider point; within {rtol!r} of their "
            f"spread), got {_show(value)}, off the line by {float(np.max(off) / spread):.3g} of the spread"
        )
    return e, np.real(np.conj(e) * rel)


def _slider(theta, d, z, name, rtol):
    B = _images(theta, d, z)
    e, s = _line_of(B, name, z, rtol)
    return SliderDyad(complex(z), complex(B[0]), complex(B[0]), complex(e), s)


def slider_dyad_for_point(theta, d, slider_point, *, rtol=1e-9):
    """The slider dyad of a chosen body pin through two, three or four poses.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians, n = 2, 3 or 4.
    d : array_like of complex, shape (n,)
        Pose translations.
    slider_point : complex
        The pin in body coordinates.
    rtol : float, optional
        Three or four poses: largest distance of a position from the line through the first
        and the farthest position, relative to that distance.

    Returns
    -------
    SliderDyad

    Raises
    ------
    ValueError
        For bad poses, or a pin whose positions are not collinear (three or more poses) or
        all coincide (a common pole: no guide direction).

    Notes
    -----
    Two poses: the guide is the line through the two positions. Three poses: the pin must
    lie on `slider_point_circle`. Derivation of the collinearity condition:
    :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import slider_dyad_for_point
    >>> guide = slider_dyad_for_point([0.0, 0.4], [0, 1 + 1j], 2.0)
    >>> bool(np.isclose(guide.s[1], abs(np.exp(0.4j) * 2 + 1 + 1j - 2), rtol=1e-14))
    True
    """
    theta, d = pose_set(theta, d, (2, 3, 4))
    z = planar_point("slider_point", slider_point)
    rtol = nonnegative_number("rtol", rtol)
    return _slider(theta, d, z, "slider_point", rtol)


def _circle(theta, d):
    """Centre, radius and pole (body coordinates) of the slider circle of three poses, or None if a line."""
    a2, a3 = _turn_factor(theta[0], theta[1]), _turn_factor(theta[0], theta[2])
    b2, b3 = d[1] - d[0], d[2] - d[0]
    # G(z) = Im((a2 z + b2) conj(a3 z + b3)) = K |z|^2 + Im(c z) + Im(b2 conj(b3))
    K = np.imag(a2 * np.conj(a3))
    c = a2 * np.conj(b3) - a3 * np.conj(b2)
    if K == 0.0 or a2 == 0.0:
        return None
    centre = -1j * np.conj(c) / (2.0 * K)
    # relative to d[0]: body coordinates do not depend on where the ground origin is
    pole = -b2 / a2
    return complex(centre), float(abs(pole - centre)), complex(pole)


def _normalised(theta, d):
    size = float(np.max(np.abs(d - d[0])))
    size = size if size > 0.0 else 1.0
    return (d - d[0]) / size, size


def slider_point_circle(theta, d):
    """The circle of body points whose positions in three poses are collinear (slider points).

    Parameters
    ----------
    theta : array_like, shape (3,)
        Pose angles, radians.
    d : array_like of complex, shape (3,)
        Pose translations.

    Returns
    -------
    SliderCircle
        Centre and radius in body coordinates, and the pole of poses 1 and 2 on it;
        ``.points(n)`` samples it.

    Raises
    ------
    ValueError
        For bad poses, or poses whose slider points form a straight line, not a circle
        (poses 1 and 2 differ by a translation, or the turns make the ``|z|^2`` term vanish).

    Notes
    -----
    The collinearity of ``B_j = exp(1j*theta_j)*z + d_j`` is
    ``Im((B_2 - B_1) conj(B_3 - B_1)) = 0``, quadratic in ``z`` with the leading term
    ``|z|^2 Im(a_2 conj(a_3))``, ``a_j = exp(1j*theta_j) - exp(1j*theta_1)``: a circle
    through the pole of poses 1 and 2 (and that of poses 1 and 3). The translations are
    moved to the first and scaled by their spread, so the result is in proportion to the
    unit of length. Derivation: :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import slider_point_circle
    >>> theta, d = np.array([0.0, 0.3, 0.7]), np.array([0, 1 + 0.2j, 1.8 + 0.9j])
    >>> circle = slider_point_circle(theta, d)
    >>> B = np.exp(1j * theta) * circle.points(4)[:, None] + d
    >>> bool(np.allclose(np.imag((B[:, 1] - B[:, 0]) * np.conj(B[:, 2] - B[:, 0])), 0, atol=1e-12))
    True
    """
    theta, d = pose_set(theta, d, (3,))
    dn, size = _normalised(theta, d)
    found = _circle(theta, dn)
    if found is None:
        raise ValueError(
            "Expected three poses whose slider points form a circle, got poses whose slider points "
            f"form a line: `theta` = {_show(theta)}"
        )
    centre, radius, pole = found
    # moving every translation by -d[0] leaves body coordinates alone; the scale maps them back
    return SliderCircle(complex(centre * size), float(radius * size), complex(pole * size))


def slider_dyads(theta, d, *, rtol=1e-9):
    """Every slider dyad of four poses: the body points whose four positions are collinear.

    Parameters
    ----------
    theta : array_like, shape (4,)
        Pose angles, radians.
    d : array_like of complex, shape (4,)
        Pose translations.
    rtol : float, optional
        Collinearity check of each point found (as `slider_dyad_for_point`) and the
        distance, relative to the radius of the larger circle, below which the second
        intersection counts as the pole itself (tangent circles: no slider point).

    Returns
    -------
    tuple of SliderDyad
        None or one in general.

    Raises
    ------
    ValueError
        For bad poses, poses whose slider points of poses (1, 2, 3) or (1, 2, 4) form a line,
        or the same circle (then every point of it is a slider point).

    Notes
    -----
    The slider circles of poses (1, 2, 3) and (1, 2, 4) both pass through the pole of poses 1
    and 2, which is no slider point of all four poses (there B_1 = B_2, but B_1, B_3, B_4 are
    in general not collinear). Their second intersection is the mirror image of that pole
    in the line of their centres; it is checked for collinearity before it is returned.
    Derivation: :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import slider_dyads
    >>> phi = np.array([0.2, 0.9, 1.6, 2.5])                 # a slider-crank a = 1, b = 3, e = 0.5
    >>> B = np.exp(1j * phi)
    >>> C = B.real + np.sqrt(9 - (0.5 - B.imag) ** 2) + 0.5j
    >>> found = slider_dyads(np.angle(C - B), B)
    >>> [round(abs(g.slider_point), 9) for g in found]
    [3.0]
    """
    theta, d = pose_set(theta, d, (4,))
    rtol = nonnegative_number("rtol", rtol)
    dn, size = _normalised(theta, d)
    first = _circle(theta[[0, 1, 2]], dn[[0, 1, 2]])
    second = _circle(theta[[0, 1, 3]], dn[[0, 1, 3]])
    if first is None or second is None:
        raise ValueError(
            "Expected four poses whose slider points of poses (1, 2, 3) and (1, 2, 4) form circles, "
            f"got a line: `theta` = {_show(theta)}"
        )
    (c1, r1, pole), (c2, r2, _) = first, second
    axis = c2 - c1
    if axis == 0.0:
        raise ValueError(
            "Expected four poses with finitely many slider points, got poses whose slider circles "
            f"coincide: `theta` = {_show(theta)}"
        )
    u = axis / abs(axis)
    other = c1 + u * np.conj((pole - c1) / u)
    if abs(other - pole) <= rtol * max(r1, r2):
        return ()
    z = other * size
    try:
        return (_slider(theta, d, z, "slider point", rtol),)
    except ValueError:
        return ()


@dataclass(frozen=True)
class GuidanceSliderCrank:
    """A slider-crank for a guidance task, with the analysis that checks it.

    Attributes
    ----------
    linkage : Linkage
        In the task's ground frame: ground ``"A"`` (the crank's centre point), crank
        ``"crank"`` (A to ``"B"``), RRP group with the rod ``"coupler"`` (the guided body,
        frame from B towards ``"C"``) and the block ``"block"`` on the guide.
    crank, slider : Dyad, SliderDyad
        The two dyads.
    branch : int
        The RRP group's ``branch`` argument for which the analysis reproduces the poses.
    theta_input : ndarray, shape (n,)
        The crank's input angle (absolute, of A -> B) at every pose, in (-pi, pi].
    direction : int
        +1 if the crank turns counter-clockwise from pose to pose, -1 if clockwise, 0 if
        neither reaches the poses in order on one branch.
    in_order : bool
        The crank, turning one way by less than a turn, meets the poses in order, the
        linkage stays assembled all the way, and C stays on one side of the foot of B on
        the guide (one mode of the RRP group) at every pose.
    pose_error : float
        Largest error of the reproduced poses: translation error relative to the linkage's
        size, or rotation error in radians, whichever is larger.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    gamma_at_poses : ndarray, shape (n,)
        Transmission angle at each pose (between the rod and the guide's normal), radians.
    gamma_min : float
        Smallest transmission angle from the first pose to the last when `in_order`, else
        over the poses only.
    """

    linkage: Linkage
    crank: Dyad
    slider: SliderDyad
    branch: int
    theta_input: np.ndarray
    direction: int
    in_order: bool
    pose_error: float
    passes: bool
    gamma_at_poses: np.ndarray
    gamma_min: float

    def coupler_poses(self, theta_input):
        """The coupler's pose ``(theta, d)`` in the task frame at crank angles `theta_input`."""
        sol = self.linkage.solve(finite_array("theta_input", theta_input))
        return _body_pose(sol, self.crank, self.slider)


def _body_pose(sol, crank, slider):
    B, C = sol.points["B"], sol.points["C"]
    zB, zC = crank.circle_point, slider.slider_point
    theta = np.angle(np.exp(1j * (np.angle(C - B) - np.angle(zC - zB))))
    return theta, B - np.exp(1j * theta) * zB


def _gamma(sol, e):
    u = sol.points["C"] - sol.points["B"]
    with np.errstate(invalid="ignore"):
        return np.arcsin(np.clip(np.abs(np.real(np.conj(e) * u)) / np.abs(u), 0.0, 1.0))


def guidance_slider_crank(theta, d, crank, slider, *, rtol=1e-9):
    """A slider-crank from an RR crank and a slider dyad, proved by analysis.

    The crank's centre point A is the fixed pivot, its circle point B the crank pin, the
    slider dyad's pin C the block's pin on the guide; the coupler BC is the guided body.
    The linkage is built as a `mech.planar.Linkage` (crank + RRP group), solved at the crank
    angles of the poses, and must reproduce every pose on one mode of the RRP group and
    meet them in order as the crank turns one way by less than a turn.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians, 2 <= n <= 4.
    d : array_like of complex, shape (n,)
        Pose translations.
    crank : Dyad
        An RR dyad of these poses with scalar fields (`dyad_for_circle_point`,
        `dyad_for_centre_point`).
    slider : SliderDyad
        A slider dyad of these poses (`slider_dyad_for_point`, `slider_dyads`).
    rtol : float, optional
        Largest accepted pose error (relative to the linkage's size; radians for the angle).

    Returns
    -------
    GuidanceSliderCrank

    Raises
    ------
    ValueError
        For bad poses or dyads (`InputTypeError` for records of the wrong type), or a crank
        pin that coincides with the slider pin.

    Notes
    -----
    Both modes of the RRP group are tried; the one that reproduces the first pose is kept.
    The distance of B from the guide is extreme where the crank is normal to the guide, so
    the path of the crank from the first pose to the last is checked at its ends and at
    those angles inside it: if the linkage assembles there it assembles all the way, and
    the transmission angle is smallest at one of them. `Linkage` works in a unit near its
    longest length, so the check holds at any scale.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import dyad_for_circle_point, slider_dyad_for_point, guidance_slider_crank
    >>> phi = np.array([0.2, 0.9, 1.6])                       # a slider-crank a = 1, b = 3, e = 0.5
    >>> B = np.exp(1j * phi)
    >>> C = B.real + np.sqrt(9 - (0.5 - B.imag) ** 2) + 0.5j
    >>> theta = np.angle(C - B)
    >>> design = guidance_slider_crank(theta, B, dyad_for_circle_point(theta, B, 0.0),
    ...                                slider_dyad_for_point(theta, B, 3.0))
    >>> design.passes, design.direction
    (True, 1)
    """
    theta, d = pose_set(theta, d, (2, 3, 4))
    crank = instance("crank", crank, Dyad)
    slider = instance("slider", slider, SliderDyad)
    rtol = nonnegative_number("rtol", rtol)
    if np.ndim(crank.length) != 0:
        raise ValueError(f"Expected `crank` with scalar fields (one dyad), got {crank!r}")
    zB, zC = complex(crank.circle_point), complex(slider.slider_point)
    A = complex(crank.centre_point)
    rod = abs(zC - zB)
    if not (np.isfinite(rod) and rod > 0.0):
        raise ValueError(f"Expected `slider` whose pin differs from the crank's circle point, got {slider!r}")
    B = _images(theta, d, zB)
    C = _images(theta, d, zC)
    e = complex(slider.direction)
    theta_in = np.angle(B - A)
    guide = Guide("ground", through=complex(slider.line_point), angle=float(np.angle(e)))
    size = max(float(crank.length), rod, float(np.max(np.abs(C - A))))
    best = None
    for branch in (1, -1):
        lk = (Linkage({"A": A})
              .crank("crank", pivot="A", tip="B", length=float(crank.length))
              .rrp(("coupler", "block"), pin="B", guide=guide, joint="C", length=rod, branch=branch))
        sol = lk.solve(theta_in)
        if not np.all(sol.valid):
            continue
        t_rec, d_rec = _body_pose(sol, crank, slider)
        err = float(max(np.max(np.abs((d_rec - A) - (d - A))) / size,
                        np.max(np.abs(np.angle(np.exp(1j * (t_rec - theta)))))))
        if best is None or err < best[0]:
            best = (err, branch, lk, sol)
    if best is None:
        err, branch, lk = float("inf"), 1, None
        lk = (Linkage({"A": A})
              .crank("crank", pivot="A", tip="B", length=float(crank.length))
              .rrp(("coupler", "block"), pin="B", guide=guide, joint="C", length=rod, branch=1))
    else:
        err, branch, lk, _ = best
    mode = np.sign(np.real(np.conj(e) * (C - B)))
    one_mode = bool(np.all(mode == mode[0]) and mode[0] != 0)
    # the crank is normal to the guide where B is farthest from it on either side
    normal = float(np.angle(e)) + 0.5 * np.pi
    direction, critical = 0, None
    for sense in (1, -1):
        steps = np.remainder(sense * np.diff(theta_in), _TWO_PI)
        travel = float(np.sum(steps))
        if travel >= _TWO_PI:
            continue
        start = float(theta_in[0])
        lo, hi = (start, start + travel) if sense > 0 else (start - travel, start)
        k = np.arange(np.ceil((lo - normal) / np.pi), np.floor((hi - normal) / np.pi) + 1)
        path = np.concatenate([[lo, hi], normal + np.pi * k])
        if np.all(lk.solve(path).valid):
            direction, critical = sense, path
            break
    in_order = bool(direction != 0 and one_mode)
    gamma_at = _gamma(lk.solve(theta_in), e)
    gamma_min = float(np.min(_gamma(lk.solve(critical), e))) if in_order else float(np.min(gamma_at))
    return GuidanceSliderCrank(
        linkage=lk, crank=crank, slider=slider, branch=branch, theta_input=theta_in,
        direction=direction if in_order else 0, in_order=in_order, pose_error=err,
        passes=bool(in_order and err <= rtol), gamma_at_poses=gamma_at, gamma_min=gamma_min,
    )
