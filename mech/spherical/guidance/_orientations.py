"""Spherical displacements between orientations, their poles, and the two design equations
(the spherical monograph, chapter 3, §3.1): a crank keeps a body point at a constant arc from
a fixed point; a slider keeps it on a great circle.

An orientation is a proper rotation ``R`` (``CONVENTIONS.md``, section Synthesis): the body
axis ``z`` points along ``R @ z`` in the ground frame. The displacement from orientation 1
to orientation j is ``D_j1 = R_j R_1^T``; it carries every ground position at orientation 1
to the position of the same body point at orientation j.
"""

import numpy as np

from mech._generated import spherical_guidance as _gen
from mech._task import distinct_orientations
from mech._validate import _show, finite_array
from mech.spherical._coordinates import unit_vectors as _vectors

__all__ = ["relative_rotation", "rotation_pole", "pole_triangle", "crank_residual", "slider_residual",
           "planar_orientations"]


def orientation_set(name, value, counts=None, tol=1e-9, *, task=None):
    """Check a set of orientations: finite proper rotations of shape (n, 3, 3), n in `counts`.

    With `task` (the default when `counts` is given: a design task) no two orientations
    may be the same (`mech._task.distinct_orientations`).
    """
    R = finite_array(name, value)
    shape = R.shape
    if R.ndim == 2:
        R = R[None]
    if R.ndim != 3 or R.shape[1:] != (3, 3):
        raise ValueError(f"Expected `{name}` of shape (n, 3, 3) (rotation matrices), got shape {shape}")
    if counts is not None and R.shape[0] not in counts:
        allowed = " or ".join(str(c) for c in counts)
        raise ValueError(f"Expected {allowed} orientations in `{name}`, got {R.shape[0]}")
    # entries of a rotation are at most 1: test that first, so R^T R cannot overflow
    big = np.max(np.abs(R), axis=(1, 2))
    with np.errstate(over="ignore", invalid="ignore"):
        gram = np.max(np.abs(np.einsum("nki,nkj->nij", R, R) - np.eye(3)), axis=(1, 2))
        det = np.linalg.det(R)
    bad = (big > 1.0 + tol) | ~(gram <= tol) | ~(det > 0.0)
    if np.any(bad):
        k = int(np.flatnonzero(bad)[0])
        raise ValueError(f"Expected `{name}` of proper rotations (R.T @ R = I, det R = +1), got "
                         f"{np.array2string(R[k], precision=6)} at index {k}")
    if task or (task is None and counts is not None):
        distinct_orientations(R, name)
    return R


def _stacks_broadcast(**leads):
    """Check that the leading (stack) shapes of named arguments broadcast; name them if not."""
    try:
        return np.broadcast_shapes(*leads.values())
    except ValueError:
        listed = ", ".join(f"`{k}` {tuple(v)}" for k, v in leads.items())
        raise ValueError(f"Expected stacks that broadcast together, got leading shapes {listed}") from None


def _parts(R1, Rj):
    """The generated entries of K = D_j1 - I = (R_j - R_1) R_1^T, shape (..., 3, 3)."""
    args = [R1[..., i, k] for i in range(3) for k in range(3)] + [Rj[..., i, k] for i in range(3) for k in range(3)]
    out = _gen.sg_displacement_minus_identity(*args)
    shape = np.broadcast_shapes(R1.shape[:-2], Rj.shape[:-2])
    return np.stack([np.broadcast_to(v, shape) for v in out], axis=-1).reshape(shape + (3, 3))


def relative_rotation(R_1, R_j):
    """The displacement ``D_j1 = R_j R_1^T`` from orientation 1 to orientation j (§3.1).

    Parameters
    ----------
    R_1, R_j : array_like, shape (3, 3) or (n, 3, 3)
        Orientations (proper rotations); stacks broadcast.

    Returns
    -------
    D : ndarray, shape (..., 3, 3)
        The rotation carrying ground positions at orientation 1 to orientation j.
    K : ndarray, shape (..., 3, 3)
        ``D - I``, computed as ``(R_j - R_1) R_1^T`` so that a small displacement keeps its
        relative accuracy (eq. (2) of :ref:`deriv-spherical-guidance`).

    Raises
    ------
    ValueError
        If an argument is not a stack of proper rotations (naming it).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import relative_rotation, rotation_matrix
    >>> R1, R2 = rotation_matrix([0, 0, 1], 0.2), rotation_matrix([1, 0, 0], 0.5)
    >>> D, K = relative_rotation(R1, R2)
    >>> bool(np.allclose(D @ R1, R2)), bool(np.allclose(K, D - np.eye(3)))
    (True, True)
    """
    R1 = orientation_set("R_1", R_1)
    Rj = orientation_set("R_j", R_j)
    _stacks_broadcast(R_1=R1.shape[:-2], R_j=Rj.shape[:-2])
    squeeze = np.ndim(R_1) == 2 and np.ndim(R_j) == 2
    K = _parts(R1, Rj)
    D = K + np.eye(3)
    return (D[0], K[0]) if squeeze else (D, K)


def _axis_angle(K):
    """Unit axes and angles in [0, pi] of the rotations I + K (stack (..., 3, 3)).

    The skew part of K is sin(phi) k and its trace is -2 (1 - cos phi) (eq. (3) of the
    derivation); near a half turn, where the skew part vanishes, the axis is read from the
    largest column of the symmetric part, (1 - cos phi) (k k^T - I) + ..., instead.
    """
    s1, s2, s3, vers = np.broadcast_arrays(*_gen.sg_pole_parts(*[K[..., i, k] for i in range(3) for k in range(3)]))
    s = np.stack([s1, s2, s3], axis=-1)                           # sin(phi) k
    vers = np.asarray(vers, dtype=float)                          # 1 - cos(phi), from the trace of K
    sin = np.linalg.norm(s, axis=-1)
    angle = np.arctan2(sin, 1.0 - vers)
    # symmetric part: S = (K + K^T)/2 = vers (k k^T - I); columns of S + vers I = vers k k^T
    S = 0.5 * (K + np.swapaxes(K, -1, -2)) + vers[..., None, None] * np.eye(3)
    col = np.argmax(np.einsum("...ii->...i", S), axis=-1)
    big = np.take_along_axis(S, col[..., None, None], axis=-1)[..., 0]
    with np.errstate(invalid="ignore", divide="ignore"):
        from_sym = big / np.linalg.norm(big, axis=-1, keepdims=True)
        from_sym *= np.where(np.sum(from_sym * s, axis=-1, keepdims=True) < 0.0, -1.0, 1.0)
        from_skew = s / sin[..., None]
    use_sym = (angle > 2.0) & (vers > 0)
    axis = np.where(use_sym[..., None], from_sym, from_skew)
    return axis, angle


def rotation_pole(R_1, R_j):
    """The pole of two orientations: the axis of the displacement between them (§3.1).

    On the sphere every displacement is a rotation about an axis through the centre; its
    two ends (antipodal points) are the only points that do not move, the spherical
    counterpart of the planar pole (2-38).

    Parameters
    ----------
    R_1, R_j : array_like, shape (3, 3) or (n, 3, 3)
        Orientations.

    Returns
    -------
    axis : ndarray, shape (..., 3)
        Unit pole P_1j, the end of the axis about which the turn is counter-clockwise seen
        from outside.
    angle : ndarray, shape (...)
        The turn, radians in [0, pi].

    Raises
    ------
    ValueError
        For input that is not a proper rotation, or two equal orientations (no turn: every
        point is a pole).

    Notes
    -----
    Eq. (3) of :ref:`deriv-spherical-guidance`. As the turns shrink to zero about points
    near the north pole, the pole tends to the planar pole of `mech.planar.synthesis.pole`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import rotation_pole, rotation_matrix
    >>> axis, angle = rotation_pole(np.eye(3), rotation_matrix([0, 0.6, 0.8], 0.7))
    >>> np.round(axis, 12).tolist(), round(float(angle), 12)
    ([0.0, 0.6, 0.8], 0.7)
    """
    D, K = relative_rotation(R_1, R_j)
    axis, angle = _axis_angle(K)
    if np.any(angle == 0.0):
        raise ValueError("Expected `R_1` and `R_j` of different orientations (equal ones have no pole), "
                         f"got equal orientations {_show(np.asarray(R_j))}")
    return axis, angle


def pole_triangle(R):
    """The pole triangle of three orientations: the poles P12, P13 and P23 (§3.2).

    Parameters
    ----------
    R : array_like, shape (3, 3, 3)
        Three orientations.

    Returns
    -------
    ndarray, shape (3, 3)
        Rows P12, P13, P23 (unit vectors, each the counter-clockwise end of its axis).

    Raises
    ------
    ValueError
        For a wrong number of orientations, or two equal ones.

    Notes
    -----
    The crank through three orientations with a given circle point has its centre point
    where the planar theory puts it: seen from the pole P_jk, the circle point's positions
    j and k subtend half the turn (eq. (6) of :ref:`deriv-spherical-guidance`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import pole_triangle, rotation_matrix
    >>> R = np.stack([np.eye(3), rotation_matrix([0, 0, 1], 0.4), rotation_matrix([1, 0, 0], 0.3)])
    >>> np.round(pole_triangle(R)[:2], 12).tolist()
    [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]
    """
    R = orientation_set("R", R, (3,))
    first = np.stack([R[0], R[0], R[1]])
    second = np.stack([R[1], R[2], R[2]])
    return rotation_pole(first, second)[0]


def crank_residual(R_1, R_j, circle_point, centre_point):
    """The crank design equation (§3.1): how far a body point is from a constant arc.

    ``u . (R_j - R_1) z``, the change of the cosine of the arc from the fixed point `u` to
    the body point `z` between orientations 1 and j; zero for every j is the design equation
    of a spherical crank (the planar (2-40)).

    Parameters
    ----------
    R_1, R_j : array_like, shape (3, 3) or (n, 3, 3)
        Orientations.
    circle_point : array_like, shape (..., 3)
        Body point z (body coordinates).
    centre_point : array_like, shape (..., 3)
        Fixed point u (ground frame).

    Returns
    -------
    ndarray
        The residuals, broadcast over the stacks.

    Raises
    ------
    ValueError
        For input that is not rotations or non-zero 3-vectors.

    Notes
    -----
    Eq. (4) of :ref:`deriv-spherical-guidance`; its limit as the arcs shrink is the planar
    half-form (2-40) times the square of the scale (eq. (12)).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import crank_residual, rotation_matrix
    >>> R2 = rotation_matrix([0, 0, 1], 0.9)                  # a turn about the north pole
    >>> float(crank_residual(np.eye(3), R2, [0.6, 0, 0.8], [0, 0, 1]))
    0.0
    """
    R1 = orientation_set("R_1", R_1)
    Rj = orientation_set("R_j", R_j)
    z = _vectors("circle_point", circle_point)
    u = _vectors("centre_point", centre_point)
    squeeze = np.ndim(R_1) == 2 and np.ndim(R_j) == 2
    if squeeze:
        R1, Rj = R1[0], Rj[0]
    _stacks_broadcast(R_1=R1.shape[:-2], R_j=Rj.shape[:-2], circle_point=z.shape[:-1], centre_point=u.shape[:-1])
    args = ([u[..., i] for i in range(3)] + [z[..., i] for i in range(3)]
            + [R1[..., i, k] for i in range(3) for k in range(3)] + [Rj[..., i, k] for i in range(3) for k in range(3)])
    return np.asarray(_gen.sg_crank_residual(*args))[()]


def slider_residual(R_j, slider_point, guide_pole):
    """The slider design equation (§3.3): how far a body point is from a great circle.

    ``n . R_j z``: the sine of the arc from the great circle with pole `n` (the guide) to
    the body point `z` at orientation j; zero for every j is the design equation of a
    spherical slider.

    Parameters
    ----------
    R_j : array_like, shape (3, 3) or (n, 3, 3)
        Orientations.
    slider_point : array_like, shape (..., 3)
        Body point z (body coordinates).
    guide_pole : array_like, shape (..., 3)
        Pole n of the guiding great circle (ground frame).

    Returns
    -------
    ndarray
        The residuals.

    Raises
    ------
    ValueError
        For input that is not rotations or non-zero 3-vectors.

    Notes
    -----
    Eq. (5) of :ref:`deriv-spherical-guidance`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import slider_residual, rotation_matrix
    >>> float(slider_residual(rotation_matrix([0, 0, 1], 0.5), [1, 0, 0], [0, 0, 1]))
    0.0
    """
    Rj = orientation_set("R_j", R_j)
    if np.ndim(R_j) == 2:
        Rj = Rj[0]
    z = _vectors("slider_point", slider_point)
    n = _vectors("guide_pole", guide_pole)
    _stacks_broadcast(R_j=Rj.shape[:-2], slider_point=z.shape[:-1], guide_pole=n.shape[:-1])
    args = [n[..., i] for i in range(3)] + [z[..., i] for i in range(3)] + [Rj[..., i, k] for i in range(3)
                                                                           for k in range(3)]
    return np.asarray(_gen.sg_slider_residual(*args))[()]


def planar_orientations(theta, d, scale):
    """Orientations that carry planar poses onto the sphere near the north pole.

    The planar pose ``(theta_j, d_j)`` becomes ``R_j = T(scale d_j) R_z(theta_j)``: a turn by
    theta_j about the north pole N = (0, 0, 1), then the roll that carries N along a great
    circle toward the direction of d_j by the arc ``scale |d_j|``. A planar point
    ``x + 1j*y`` corresponds to the axis ``(scale x, scale y, 1)`` (normalised), so as
    `scale` shrinks the spherical task tends to the planar one (eq. (11) of the derivation).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Pose angles, radians.
    d : array_like of complex, shape (n,)
        Pose translations.
    scale : float
        Radians of arc per unit of planar length, > 0 (the inverse of the sphere's radius
        in the planar unit).

    Returns
    -------
    ndarray, shape (n, 3, 3)
        The orientations.

    Raises
    ------
    ValueError
        For bad poses or a `scale` that is not positive and finite.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import planar_orientations
    >>> R = planar_orientations([0.0, 0.5], [0.0, 2.0 + 1.0j], 1e-3)
    >>> P = R[1] @ np.array([0.0, 0.0, 1.0])
    >>> np.round(P[:2] / P[2] / 1e-3, 4).tolist()          # the planar d_2, to O(scale^2)
    [2.0, 1.0]
    """
    from mech._validate import positive_length
    from mech.planar.synthesis._displacement import pose_set

    theta, d = pose_set(theta, d, range(1, 10**6), task=False)
    scale = positive_length("scale", scale)
    arc = scale * np.abs(d)
    if np.any(~np.isfinite(arc)):
        raise ValueError(f"Expected `scale` * |d| finite, got `scale` = {scale!r}")
    c, s = np.cos(theta), np.sin(theta)
    Rz = np.zeros(theta.shape + (3, 3))
    Rz[:, 0, 0], Rz[:, 0, 1], Rz[:, 1, 0], Rz[:, 1, 1], Rz[:, 2, 2] = c, -s, s, c, 1.0
    with np.errstate(invalid="ignore", divide="ignore"):
        direction = np.where(np.abs(d) > 0, d / np.abs(d), 1.0)
    kx, ky = -direction.imag, direction.real                  # axis (-dy, dx, 0) / |d|
    Kx = np.zeros(theta.shape + (3, 3))
    Kx[:, 0, 2], Kx[:, 1, 2], Kx[:, 2, 0], Kx[:, 2, 1] = ky, -kx, -ky, kx
    roll = (np.eye(3) + np.sin(arc)[:, None, None] * Kx
            + (2.0 * np.sin(arc / 2) ** 2)[:, None, None] * (Kx @ Kx))
    return roll @ Rz
