"""A rigid body on the sphere: inclinations, turning about a point, the rigid triangle and
spherical vectors (the spherical monograph, §§1.3 to 1.6).

The inclination (倾角) of a directed great circle at a point is the angle from the local x
axis (`local_frame`) to its direction, counter-clockwise seen from outside the sphere;
angles at a point are differences of inclinations, as planar angles are differences of line
angles.
"""

import numpy as np

from mech._generated.spherical_calculus import sph_rotation
from mech._validate import common_shape, finite_array
from mech.spherical._coordinates import _cross_accurate, _norm, local_frame, unit_vectors

__all__ = ["tangent", "inclination", "point_at", "rotation_matrix", "rotate_about", "turn",
           "angle_at", "triangle_point", "velocity"]


def _dot(u, v):
    return np.sum(u * v, axis=-1)


def _show(v):
    return np.array2string(np.asarray(v), precision=17, threshold=6)


def _great_circle_normal(a, b, name_a="a", name_b="b"):
    """a x b (accurate), raising if a and b are equal or antipodal (no great circle)."""
    a, b = np.broadcast_arrays(a, b)
    c = _cross_accurate(a, b)
    degenerate = np.all(c == 0.0, axis=-1)
    if np.any(degenerate):
        i = tuple(np.argwhere(np.atleast_1d(degenerate))[0]) if degenerate.ndim else ()
        raise ValueError(
            f"Expected `{name_a}` and `{name_b}` neither equal nor antipodal (the great circle "
            f"through them is undefined), got {name_a} = {_show(a[i])}, {name_b} = {_show(b[i])}")
    return a, b, c


def tangent(a, b):
    """Unit tangent at `a` of the great circle toward `b` (the spherical vector AB).

    t = ((a x b) x a) / ``|.|``, which is (b - (a . b) a) / ``|.|`` for unit vectors.

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        Points; they broadcast.

    Returns
    -------
    ndarray, shape (..., 3)
        Unit vectors tangent to the sphere at `a`.

    Raises
    ------
    ValueError
        If `a` and `b` are equal or antipodal, or an argument is malformed.

    Notes
    -----
    Near the north pole it becomes the planar unit vector of the line AB. Page
    :ref:`deriv-spherical-calculus`, §§3 and 4.

    Examples
    --------
    >>> from mech.spherical._rigid_body import tangent
    >>> tangent([0, 0, 1], [0, 1, 1]).round(12) + 0.0
    array([0., 1., 0.])
    """
    a, b, c = _great_circle_normal(unit_vectors("a", a), unit_vectors("b", b))
    t = np.cross(c, a)
    return t / _norm(t)[..., None]


def inclination(a, b):
    """Inclination at `a` of the directed great circle A->B (problem 1.3.2).

    iota = atan2((b - a) . e_y, (b - a) . e_x) with the local frame at `a` (eq. 6 of the
    spherical calculus); b + a replaces b - a when a . b < 0.

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        Points; they broadcast.

    Returns
    -------
    ndarray, shape (...)
        Inclination in (-pi, pi].

    Raises
    ------
    ValueError
        If `a` and `b` are equal or antipodal, or an argument is malformed.

    Notes
    -----
    Near the north pole, inclination + the longitude of `a` tends to the planar angle of
    the line AB; at the pole (longitude 0) they agree. Page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._rigid_body import inclination
    >>> float(inclination([0, 0, 1], [0, 1, 1]))
    1.5707963267948966
    >>> inclination([0, 0, 1], [[1, 0, 1], [-1, 0, 1]])
    array([0.        , 3.14159265])
    """
    a, b, _ = _great_circle_normal(unit_vectors("a", a), unit_vectors("b", b))
    ex, ey = local_frame(a)
    d = np.where((_dot(a, b) >= 0.0)[..., None], b - a, b + a)
    return np.arctan2(_dot(d, ey), _dot(d, ex))


def point_at(a, arc, inclination):
    """The point at `arc` from `a` along the great circle of the given inclination (1.3.1).

    B = a cos(arc) + (e_x cos(iota) + e_y sin(iota)) sin(arc), eq. (7).

    Parameters
    ----------
    a : array_like, shape (..., 3)
        Start point.
    arc, inclination : array_like, shape (...)
        Arc AB and inclination of A->B at `a`, radians.

    Returns
    -------
    ndarray, shape (..., 3)
        The point B.

    Raises
    ------
    ValueError
        If an argument is malformed or not finite.

    Notes
    -----
    The inverse of `distance` and `inclination` for 0 < arc < pi. Page
    :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._rigid_body import point_at
    >>> point_at([0, 0, 1], np.pi / 2, np.pi / 2).round(12) + 0.0
    array([0., 1., 0.])
    >>> point_at([1, 0, 0], [0.1, 0.2], 0.0).round(6)
    array([[ 0.995004,  0.      , -0.099833],
           [ 0.980067,  0.      , -0.198669]])
    """
    a = unit_vectors("a", a)
    arc = finite_array("arc", arc)[..., None]
    inc = finite_array("inclination", inclination)[..., None]
    common_shape(**{"a": a, "arc": arc, "inclination": inc})
    ex, ey = local_frame(a)
    return a * np.cos(arc) + (ex * np.cos(inc) + ey * np.sin(inc)) * np.sin(arc)


def rotation_matrix(axis, angle):
    """Rotation by `angle` about the axis through the point `axis`, counter-clockwise seen
    from outside at `axis` (Rodrigues' formula, eq. 8).

    R = I cos(g) + [k]x sin(g) + k k^T 2 sin^2(g/2).

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Point of the sphere on the axis (scaled to unit length).
    angle : array_like, shape (...)
        Turn angle, radians.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Proper rotation matrices.

    Raises
    ------
    ValueError
        If `axis` is malformed or zero, or `angle` is not finite.

    Notes
    -----
    The half-angle form keeps small turns accurate. Page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._rigid_body import rotation_matrix
    >>> rotation_matrix([0, 0, 1], np.pi / 2).round(12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    k = unit_vectors("axis", axis)
    angle = finite_array("angle", angle)
    common_shape(axis=k[..., 0], angle=angle)
    entries = np.broadcast_arrays(*sph_rotation(k[..., 0], k[..., 1], k[..., 2], angle))
    return np.stack(entries, axis=-1).reshape(entries[0].shape + (3, 3))


def rotate_about(p, axis, angle):
    """Turn the points `p` by `angle` about the axis through the point `axis`.

    p' = R(axis, angle) p with Rodrigues' matrix (eq. 8); counter-clockwise seen from
    outside at `axis`.

    Parameters
    ----------
    p : array_like, shape (..., 3)
        Points of the turning body.
    axis : array_like, shape (..., 3)
        Point of the sphere on the axis.
    angle : array_like, shape (...)
        Turn angle, radians.

    Returns
    -------
    ndarray, shape (..., 3)
        The turned points.

    Raises
    ------
    ValueError
        If an argument is malformed or not finite.

    Notes
    -----
    Near the north pole, turning about the pole is the planar rotation z -> z exp(i angle).
    Page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._rigid_body import rotate_about
    >>> rotate_about([1, 0, 0], [0, 0, 1], np.pi / 2).round(12) + 0.0
    array([0., 1., 0.])
    >>> rotate_about([[1, 0, 0], [0, 0, 1]], [1, 0, 0], np.pi / 2).round(12) + 0.0
    array([[ 1.,  0.,  0.],
           [ 0., -1.,  0.]])
    """
    p = unit_vectors("p", p)
    k, angle = unit_vectors("axis", axis), finite_array("angle", angle)
    common_shape(p=p[..., 0], axis=k[..., 0], angle=angle)
    return np.einsum("...ij,...j->...i", rotation_matrix(k, angle), p)


def turn(a, b, gamma):
    """Turn the arc AB about `a` by `gamma`: the new position B' of `b` (problem 1.3.3).

    B' = R(a, gamma) b: the arc AB is kept and gamma is added to its inclination.

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        The fixed point and the moving point.
    gamma : array_like, shape (...)
        Turn angle, radians, counter-clockwise seen from outside.

    Returns
    -------
    ndarray, shape (..., 3)
        B'.

    Raises
    ------
    ValueError
        If an argument is malformed or not finite.

    Notes
    -----
    Page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._rigid_body import turn
    >>> turn([0, 0, 1], [1, 0, 1], np.pi / 2).round(12) + 0.0
    array([0.        , 0.70710678, 0.70710678])
    """
    a, b, gamma = unit_vectors("a", a), unit_vectors("b", b), finite_array("gamma", gamma)
    return rotate_about(b, a, gamma)


def angle_at(a, b, c):
    """Signed angle at `a` from the great circle AB to the great circle AC (problem 1.4.2).

    gamma = atan2(a . (u x w), u . w) with u = a x b and w = a x c (accurate cross
    products), eq. (10); this equals inclination(a, c) - inclination(a, b) modulo 2 pi.

    Parameters
    ----------
    a, b, c : array_like, shape (..., 3)
        Vertex and the two other points; they broadcast.

    Returns
    -------
    ndarray, shape (...)
        gamma in (-pi, pi], counter-clockwise seen from outside positive.

    Raises
    ------
    ValueError
        If `b` or `c` equals `a` or its antipode, or an argument is malformed.

    Notes
    -----
    Positive when det[a, b, c] > 0. Near the north pole it tends to the planar angle BAC.
    Page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> from mech.spherical._rigid_body import angle_at
    >>> float(angle_at([0, 0, 1], [1, 0, 0], [0, 1, 0]))
    1.5707963267948966
    >>> angle_at([0, 0, 1], [1, 0, 0], [[0, -1, 0], [-1, 0, 0]])
    array([-1.57079633,  3.14159265])
    """
    a = unit_vectors("a", a)
    _, _, u = _great_circle_normal(a, unit_vectors("b", b), "a", "b")
    _, _, w = _great_circle_normal(a, unit_vectors("c", c), "a", "c")
    u, w, a = np.broadcast_arrays(u, w, a)
    return np.arctan2(_dot(a, np.cross(u, w)), _dot(u, w))


def triangle_point(a, b, gamma, arc):
    """The third vertex C of a rigid triangle from A, B, the angle gamma and the arc AC (1.4.1).

    C is at `arc` from `a` on the great circle whose inclination at `a` is
    inclination(a, b) + gamma, eq. (9).

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        Two vertices.
    gamma : array_like, shape (...)
        Angle at A from AB to AC, counter-clockwise seen from outside, radians.
    arc : array_like, shape (...)
        Arc AC, radians.

    Returns
    -------
    ndarray, shape (..., 3)
        The vertex C.

    Raises
    ------
    ValueError
        If `a` and `b` are equal or antipodal, or an argument is malformed.

    Notes
    -----
    The inverse of `angle_at` and `distance`. Page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._rigid_body import triangle_point
    >>> triangle_point([0, 0, 1], [1, 0, 0], np.pi / 2, np.pi / 2).round(12) + 0.0
    array([0., 1., 0.])
    """
    gamma = finite_array("gamma", gamma)
    return point_at(a, arc, inclination(a, b) + gamma)


def velocity(omega, p):
    """Velocity of the point `p` of a body turning with angular-velocity vector `omega`.

    v = omega x p (a spherical vector: tangent to the sphere at `p`).

    Parameters
    ----------
    omega : array_like, shape (..., 3)
        Angular velocity vector (rad/s times the unit axis through the turning point).
    p : array_like, shape (..., 3)
        Points of the body.

    Returns
    -------
    ndarray, shape (..., 3)
        Velocities.

    Raises
    ------
    ValueError
        If an argument is malformed or not finite.

    Notes
    -----
    Turning about the north pole near the pole, v tends to the planar i omega z. Page
    :ref:`deriv-spherical-calculus`, §4.

    Examples
    --------
    >>> from mech.spherical._rigid_body import velocity
    >>> velocity([0, 0, 2.0], [1, 0, 0])
    array([0., 2., 0.])
    """
    omega = finite_array("omega", omega)
    if omega.ndim == 0 or omega.shape[-1] != 3:
        raise ValueError(f"Expected `omega` of shape (..., 3), got shape {omega.shape}")
    return np.cross(omega, unit_vectors("p", p))
