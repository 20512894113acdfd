"""Spherical cranks (dyads) through two and three orientations, and spherical sliders
(the spherical monograph, §3.1 to §3.3).

A dyad is a fixed axis (the centre point) and a body axis (the circle point) whose positions
in all the orientations lie on one circle about the centre point. A slider is the dyad of
arc pi/2: its body axis stays on the great circle whose pole is the centre point.
"""

from dataclasses import dataclass

import numpy as np

from mech._geometry import unit_rows as _unit
from mech._validate import nonnegative_number, real_number
from mech.spherical._coordinates import unit_vectors as _vectors
from mech.spherical.guidance._orientations import orientation_set

__all__ = ["SphericalDyad", "dyad_for_circle_point", "dyad_for_centre_point", "slider_dyad_for_point"]


@dataclass(frozen=True)
class SphericalDyad:
    """A spherical crank (or, with arc pi/2, a slider) found by guidance synthesis.

    Attributes
    ----------
    circle_point : ndarray, shape (..., 3)
        The moving axis in body coordinates (at ``R_j @ circle_point`` in orientation j).
    moving_pivot : ndarray, shape (..., 3)
        The moving axis in the ground frame at the first orientation.
    centre_point : ndarray, shape (..., 3)
        The fixed axis (ground frame), the end nearer the moving axis (arc <= pi/2).
    arc : float or ndarray
        The crank arc from the centre point to the moving pivot, radians in (0, pi/2].
    """

    circle_point: np.ndarray
    moving_pivot: np.ndarray
    centre_point: np.ndarray
    arc: object


def arc_between(p, q):
    """Arc between unit vectors, accurate for short and nearly antipodal arcs."""
    return np.arctan2(np.linalg.norm(np.cross(p, q), axis=-1), np.sum(p * q, axis=-1))


def make_dyad(z, w, u, name, value):
    """A `SphericalDyad` with the centre's end chosen nearer w, after checking it is finite."""
    u = np.where(np.sum(u * w, axis=-1, keepdims=True) < 0.0, -u, u)
    arc = arc_between(u, w)
    bad = ~np.all(np.isfinite(u), axis=-1) | ~(arc > 0.0)
    if np.any(bad):
        k = np.flatnonzero(np.ravel(bad))[0]
        raise ValueError(f"Expected `{name}` whose positions fix a crank of non-zero arc (not a pole of two "
                         f"orientations), got {np.reshape(value, (-1, 3))[k].tolist()!r}")
    return SphericalDyad(z, w, u, arc[()])


def _bisector(w1, w2, along):
    """The point of the great circle bisecting w1 w2 at the angle `along` from the mid-point."""
    m = _unit(w1 + w2)
    p = _unit(np.cross(w1, w2))
    return np.cos(along) * m + np.sin(along) * p


def _circumpole(w1, w2, w3):
    """Pole of the circle through three points, eq. (6): (w2 - w1) x (w3 - w1), normalised."""
    return _unit(np.cross(w2 - w1, w3 - w1))


def _equidistant(w, along):
    """A point equidistant from the points w[..., j, :]: their circumpole (three) or a
    point of the bisecting great circle chosen by `along` (two)."""
    if w.shape[-2] == 3:
        return _circumpole(w[..., 0, :], w[..., 1, :], w[..., 2, :])
    return _bisector(w[..., 0, :], w[..., 1, :], along)


def dyad_for_circle_point(R, circle_point, *, along=0.0):
    """The spherical crank through two or three orientations with a chosen circle point.

    Three orientations (§3.2): the centre point is the pole of the circle through the three
    positions of the circle point, eq. (6). Two orientations (§3.1.1, the moving pivot
    given): it may be anywhere on the great circle that bisects the two positions; `along`
    picks the point at that angle from the mid-point of the arc.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations, n = 2 or 3.
    circle_point : array_like, shape (..., 3)
        Moving axes in body coordinates (normalised if not unit).
    along : float, optional
        Two orientations only: angle along the bisecting great circle from the mid-point
        of the arc toward the pole of the great circle w1 -> w2, radians.

    Returns
    -------
    SphericalDyad
        Fields of the shape of `circle_point`; the centre's end is the one nearer.

    Raises
    ------
    ValueError
        For a wrong number of orientations, bad input, or a circle point at a pole of two
        orientations (its positions coincide: no unique crank).

    Notes
    -----
    Eqs. (4) and (6) of :ref:`deriv-spherical-guidance`. A circle point whose three
    positions lie on a great circle gives the arc pi/2: a slider.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import dyad_for_circle_point, rotation_matrix
    >>> R = np.stack([np.eye(3), rotation_matrix([0.2, 0.1, 1], 0.5), rotation_matrix([-0.3, 0.2, 1], 1.0)])
    >>> crank = dyad_for_circle_point(R, [0.4, 0.1, 0.9])
    >>> arcs = [np.arccos(Rj @ crank.circle_point @ crank.centre_point) for Rj in R]
    >>> bool(np.ptp(arcs) < 1e-12)
    True
    """
    R = orientation_set("R", R, (2, 3))
    z = _vectors("circle_point", circle_point)
    along = real_number("along", along)
    w = np.einsum("nij,...j->...ni", R, z)
    u = _equidistant(w, along)
    return make_dyad(z, w[..., 0, :], u, "circle_point", z)


def dyad_for_centre_point(R, centre_point, *, along=0.0):
    """The spherical crank through two or three orientations with a chosen centre point.

    By kinematic inversion (§3.1.2, the fixed pivot given): seen from the body, the fixed
    axis takes the positions ``R_j^T u``; the circle point is the pole of the circle
    through them (three orientations) or a point of their bisecting great circle (two,
    chosen by `along` as in `dyad_for_circle_point`).

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations, n = 2 or 3.
    centre_point : array_like, shape (..., 3)
        Fixed axes in the ground frame.
    along : float, optional
        Two orientations only: angle along the bisecting great circle, radians.

    Returns
    -------
    SphericalDyad
        The centre point is returned as given (or its antipode, whichever is nearer the
        moving pivot).

    Raises
    ------
    ValueError
        As `dyad_for_circle_point`, for a centre point that is a pole of two orientations.

    Notes
    -----
    Eqs. (4) and (6) of :ref:`deriv-spherical-guidance`, with R_j replaced by R_j^T.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import dyad_for_centre_point, rotation_matrix
    >>> R = np.stack([np.eye(3), rotation_matrix([0.2, 0.1, 1], 0.5), rotation_matrix([-0.3, 0.2, 1], 1.0)])
    >>> crank = dyad_for_centre_point(R, [0.1, -0.2, 0.97])
    >>> arcs = [np.arccos(Rj @ crank.circle_point @ crank.centre_point) for Rj in R]
    >>> bool(np.ptp(arcs) < 1e-12)
    True
    """
    R = orientation_set("R", R, (2, 3))
    u = _vectors("centre_point", centre_point)
    along = real_number("along", along)
    seen = np.einsum("nji,...j->...ni", R, u)
    z = _equidistant(seen, along)
    z = np.where(np.sum(z * seen[..., 0, :], axis=-1, keepdims=True) < 0.0, -z, z)
    w = np.einsum("ij,...j->...i", R[0], z)
    dyad = make_dyad(z, w, u, "centre_point", u)
    return dyad


def slider_dyad_for_point(R, slider_point, *, rtol=1e-9):
    """The spherical slider through two or three orientations with a chosen slider point.

    A slider (§3.3) keeps its body axis on a great circle, the guide; its pole is the
    slider's fixed axis, at the arc pi/2 (eq. (5)). Two positions fix the guide; three must
    lie on one great circle (the slider point must be on the cubic (7), see
    `slider_point_curve`).

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations, n = 2 or 3.
    slider_point : array_like, shape (3,)
        The slider's axis in body coordinates.
    rtol : float, optional
        Largest accepted ``|det[w1, w2, w3]|`` (three orientations).

    Returns
    -------
    SphericalDyad
        ``centre_point`` is the guide's pole and ``arc`` is pi/2.

    Raises
    ------
    ValueError
        For bad input, a slider point at a pole, or three positions off one great circle.

    Notes
    -----
    Eqs. (5) and (7) of :ref:`deriv-spherical-guidance`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import slider_dyad_for_point, rotation_matrix
    >>> R = np.stack([np.eye(3), rotation_matrix([0, 0, 1], 0.4)])
    >>> s = slider_dyad_for_point(R, [1.0, 0.0, 0.0])
    >>> np.round(s.centre_point, 12).tolist(), round(float(s.arc), 12)
    ([0.0, 0.0, 1.0], 1.570796326795)
    """
    R = orientation_set("R", R, (2, 3))
    z = _vectors("slider_point", slider_point)
    rtol = nonnegative_number("rtol", rtol)
    if z.shape != (3,):
        raise ValueError(f"Expected `slider_point` of shape (3,), got shape {z.shape}")
    w = R @ z
    if R.shape[0] == 3:
        det = float(np.linalg.det(w))
        if abs(det) > rtol:
            raise ValueError(f"Expected `slider_point` whose three positions lie on one great circle "
                             f"(|det| <= `rtol` = {rtol!r}), got {z.tolist()!r} with det {det:.3e}")
        n = np.linalg.svd(w)[2][-1]
    else:
        n = _unit(np.cross(w[0], w[1]))
    return make_dyad(z, w[0], n, "slider_point", z)
