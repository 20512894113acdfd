"""Circles (小圆) and great circles (大圆) on the unit sphere (the spherical monograph, §1.7).

A circle is its pole N and arc radius r: the points P with N . P = cos r. A great circle
(r = pi/2) is the spherical straight line; it is directed counter-clockwise about its pole
seen from outside, so the pole lies on its left.
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import finite_array, vector3
from mech.spherical._coordinates import _cross_accurate, distance, local_frame, unit_vectors
from mech.spherical._coordinates import _norm as _robust_norm
from mech.spherical._rigid_body import _great_circle_normal

__all__ = ["Circle", "Collinearity", "Intersection", "great_circle_through", "great_circle_at",
           "distance_to_great_circle", "collinearity", "angle_between", "intersect", "bisector",
           "circle_through"]


def _dot(u, v):
    return np.sum(u * v, axis=-1)


def _norm(u):
    return _robust_norm(u)


def _frozen(value):
    arr = np.array(value, dtype=float)
    arr.flags.writeable = False
    return arr


@dataclass(frozen=True)
class Circle:
    """A circle of the unit sphere: `pole` (unit vectors, shape (..., 3)) and arc `radius`
    (shape (...), in (0, pi); pi/2 for a great circle). (N, r) and (-N, pi - r) are the same
    circle run in opposite senses."""

    pole: np.ndarray
    radius: np.ndarray

    def __post_init__(self):
        object.__setattr__(self, "pole", _frozen(self.pole))
        object.__setattr__(self, "radius", _frozen(self.radius))

    def residual(self, p):
        """Signed arc from the circle to the points `p`: distance(pole, p) - radius
        (negative inside, toward the pole)."""
        return distance(self.pole, vector3("p", p)) - self.radius


@dataclass(frozen=True)
class Collinearity:
    """`det` = det[a, b, c] (zero when the three points lie on one great circle) and
    `distance`, the signed arc of c from the great circle a -> b (positive on its left)."""

    det: np.ndarray
    distance: np.ndarray


@dataclass(frozen=True)
class Intersection:
    """The two antipodal common points of two directed great circles: at `point` the angle
    from circle 1 to circle 2 (counter-clockwise seen from outside) is `angle` in (0, pi);
    at `antipode` = -point it is -angle."""

    point: np.ndarray
    antipode: np.ndarray
    angle: np.ndarray


def great_circle_through(a, b):
    """The directed great circle through `a` and then `b` (pole N = a x b / ``|a x b|``).

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        Two points, neither equal nor antipodal.

    Returns
    -------
    Circle
        Pole (the cross product formed as (a - b) x b, accurate for close points) and radius
        pi/2.

    Raises
    ------
    ValueError
        If `a` and `b` are equal or antipodal (the great circle is undefined).

    Notes
    -----
    Pole form N . P = 0, page :ref:`deriv-spherical-calculus`, §5.

    Examples
    --------
    >>> from mech.spherical._circles import great_circle_through
    >>> great_circle_through([1, 0, 0], [0, 1, 0]).pole
    array([0., 0., 1.])
    """
    _, _, c = _great_circle_normal(unit_vectors("a", a), unit_vectors("b", b))
    pole = c / _norm(c)[..., None]
    return Circle(pole, np.full(pole.shape[:-1], np.pi / 2))


def great_circle_at(a, inclination):
    """The directed great circle leaving `a` with the given inclination (inclination form).

    Its pole is N = a x t with t = e_x cos(iota) + e_y sin(iota), so that N x a = t.

    Parameters
    ----------
    a : array_like, shape (..., 3)
        A point of the great circle.
    inclination : array_like, shape (...)
        Its inclination at `a`, radians.

    Returns
    -------
    Circle
        Pole and radius pi/2.

    Raises
    ------
    ValueError
        If an argument is malformed or not finite.

    Notes
    -----
    Page :ref:`deriv-spherical-calculus`, §5.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._circles import great_circle_at
    >>> great_circle_at([0, 0, 1], np.pi / 2).pole.round(12) + 0.0
    array([-1.,  0.,  0.])
    """
    a = unit_vectors("a", a)
    inc = finite_array("inclination", inclination)[..., None]
    ex, ey = local_frame(a)
    pole = np.cross(a, ex * np.cos(inc) + ey * np.sin(inc))
    return Circle(pole, np.full(pole.shape[:-1], np.pi / 2))


def distance_to_great_circle(p, pole):
    """Signed arc from the great circle with pole `pole` to the points `p`.

    atan2(p . N, ``|p x N|``): positive on the left of the directed great circle (the pole's
    side), in [-pi/2, pi/2].

    Parameters
    ----------
    p, pole : array_like, shape (..., 3)
        Points and the pole of the great circle; they broadcast.

    Returns
    -------
    ndarray, shape (...)
        The signed arc.

    Raises
    ------
    ValueError
        If an argument is malformed or has a zero row.

    Notes
    -----
    Page :ref:`deriv-spherical-calculus`, §5.

    Examples
    --------
    >>> from mech.spherical._circles import distance_to_great_circle
    >>> distance_to_great_circle([[0, 0.6, 0.8], [0, 0, -1]], [0, 0, 1])
    array([ 0.92729522, -1.57079633])
    """
    p, n = np.broadcast_arrays(unit_vectors("p", p), unit_vectors("pole", pole))
    c = _cross_accurate(p, n)
    return np.arctan2(_dot(p, n), _norm(c))


def collinearity(a, b, c):
    """Whether three points lie on one great circle: det[a, b, c] and the arc of `c` from
    the great circle a -> b.

    det[a, b, c] = det[b - a, c - a, a] (differences keep close points accurate); the arc
    is atan2(det / ``|a x b|``, ``|N x c|``) with N the pole of the great circle a -> b.

    Parameters
    ----------
    a, b, c : array_like, shape (..., 3)
        Points; `a` and `b` neither equal nor antipodal.

    Returns
    -------
    Collinearity
        `det` and the signed `distance` (positive when c is on the left of a -> b).

    Raises
    ------
    ValueError
        If `a` and `b` are equal or antipodal, or an argument is malformed.

    Notes
    -----
    Page :ref:`deriv-spherical-calculus`, §5.

    Examples
    --------
    >>> from mech.spherical._circles import collinearity
    >>> r = collinearity([1, 0, 0], [0, 1, 0], [0, 0.6, 0.8])
    >>> float(r.det), round(float(r.distance), 12)
    (0.8, 0.927295218002)
    """
    a, b, n = _great_circle_normal(unit_vectors("a", a), unit_vectors("b", b))
    c = unit_vectors("c", c)
    a, b, c, n = np.broadcast_arrays(a, b, c, n)
    det = _dot(np.cross(b - a, c - a), a)
    pole = n / _norm(n)[..., None]
    dist = np.arctan2(det / _norm(n), _norm(_cross_accurate(c, pole)))
    return Collinearity(_frozen(det), _frozen(dist))


def angle_between(pole1, pole2):
    """Angle from the directed great circle 1 to circle 2 at their common point
    `intersect(pole1, pole2).point`: the arc between the poles, in [0, pi] (eq. 11).

    Parameters
    ----------
    pole1, pole2 : array_like, shape (..., 3)
        Poles of the two great circles.

    Returns
    -------
    ndarray, shape (...)
        The angle; pi/2 when the circles are perpendicular (N1 . N2 = 0).

    Raises
    ------
    ValueError
        If an argument is malformed or has a zero row.

    Notes
    -----
    It equals the difference of the two inclinations at the common point. Page
    :ref:`deriv-spherical-calculus`, §3.

    Examples
    --------
    >>> from mech.spherical._circles import angle_between
    >>> float(angle_between([0, 0, 1], [0, 1, 0]))
    1.5707963267948966
    """
    return distance(unit_vectors("pole1", pole1), unit_vectors("pole2", pole2))


def intersect(pole1, pole2):
    """The two common points of two directed great circles, given by their poles.

    X = N1 x N2 / ``|N1 x N2|`` and -X; at X the angle from circle 1 to circle 2 is
    angle_between(pole1, pole2) in (0, pi), at -X its negative (eq. 11).

    Parameters
    ----------
    pole1, pole2 : array_like, shape (..., 3)
        Poles of the two great circles (for example `great_circle_through(a, b).pole`).

    Returns
    -------
    Intersection
        `point`, `antipode` (shape (..., 3)) and `angle` (shape (...)).

    Raises
    ------
    ValueError
        If the poles are equal or antipodal (the great circles coincide).

    Notes
    -----
    Any two great circles meet: there are no parallels on the sphere. Page
    :ref:`deriv-spherical-calculus`, §§3 and 5.

    Examples
    --------
    >>> from mech.spherical._circles import intersect
    >>> x = intersect([0, 0, 1], [1, 0, 0])
    >>> x.point, x.antipode, float(x.angle)
    (array([0., 1., 0.]), array([ 0., -1.,  0.]), 1.5707963267948966)
    """
    n1, n2, c = _great_circle_normal(unit_vectors("pole1", pole1), unit_vectors("pole2", pole2),
                                     "pole1", "pole2")
    x = c / _norm(c)[..., None]
    return Intersection(_frozen(x + 0.0), _frozen(0.0 - x), _frozen(distance(n1, n2)))


def bisector(a, b):
    """The perpendicular bisector of the arc AB: the great circle of points equidistant
    from `a` and `b`, with pole (a - b) / ``|a - b|`` (so `a` lies on its left).

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        Two different points.

    Returns
    -------
    Circle
        Pole and radius pi/2.

    Raises
    ------
    ValueError
        If `a` and `b` coincide.

    Notes
    -----
    P . a = P . b is P . (a - b) = 0. Near the north pole it becomes the planar
    perpendicular bisector. Page :ref:`deriv-spherical-calculus`, §5.

    Examples
    --------
    >>> from mech.spherical._circles import bisector
    >>> bisector([1, 0, 0], [0, 1, 0]).pole.round(12)
    array([ 0.70710678, -0.70710678,  0.        ])
    """
    a, b = np.broadcast_arrays(unit_vectors("a", a), unit_vectors("b", b))
    d = a - b
    n = _norm(d)
    if np.any(n == 0.0):
        raise ValueError(f"Expected `a` and `b` to differ (their bisector is undefined), got a = b = {a[n == 0.0][0]}")
    return Circle(d / n[..., None], np.full(n.shape, np.pi / 2))


def circle_through(a, b, c):
    """The circle through three points: pole N and arc radius r.

    N = n / ``|n|`` with n = (b - a) x (c - a), so that a -> b -> c runs counter-clockwise about
    N; r = atan2(``|ab|`` ``|bc|`` ``|ca|`` / 2, n . a) with the chord lengths (sin r is the Euclidean
    circumradius, cos r = N . a), accurate for small circles.

    Parameters
    ----------
    a, b, c : array_like, shape (..., 3)
        Three different points.

    Returns
    -------
    Circle
        `pole` and `radius` in (0, pi); radius pi/2 exactly when the points lie on one great
        circle (det[a, b, c] = 0): no special case.

    Raises
    ------
    ValueError
        If two of the points coincide.

    Notes
    -----
    Near the north pole, radius / scale tends to the planar circumradius. Page
    :ref:`deriv-spherical-calculus`, §5.

    Examples
    --------
    >>> from mech.spherical._circles import circle_through
    >>> k = circle_through([1, 0, 0], [0, 1, 0], [0, 0, 1])
    >>> k.pole.round(12), round(float(k.radius), 12)
    (array([0.57735027, 0.57735027, 0.57735027]), 0.955316618125)
    >>> float(circle_through([1, 0, 0], [0, 1, 0], [-1, 0, 0]).radius)
    1.5707963267948966
    """
    a, b, c = np.broadcast_arrays(unit_vectors("a", a), unit_vectors("b", b), unit_vectors("c", c))
    n = np.cross(b - a, c - a)
    size = _norm(n)
    if np.any(size == 0.0):
        i = tuple(np.argwhere(np.atleast_1d(size == 0.0))[0]) if size.ndim else ()
        raise ValueError(f"Expected three different points `a`, `b`, `c`, got a = {a[i]}, b = {b[i]}, c = {c[i]}")
    chords = _norm(b - a) * _norm(c - b) * _norm(a - c)
    return Circle(n / size[..., None], np.arctan2(chords / 2, _dot(n, a)))
