"""Planar displacements between poses: the matrix (2-37), the pole, and pose-set checks."""

import numpy as np

from mech._generated import displacement as _gen
from mech._task import distinct_poses
from mech._validate import common_shape, planar_points, real_array, _show

__all__ = ["displacement_matrix", "pole"]


def complex_array(name, value):
    """Return ``value`` as a finite complex array (planar points), naming it in any error.

    Real and complex numbers are accepted; booleans, strings, ``None`` and other objects
    raise `mech.InputTypeError`, NaN and infinities ``ValueError`` (`mech._validate.planar_points`).
    """
    return planar_points(name, value)


def pose_set(theta, d, counts, *, task=True):
    """Check a pose set: `theta` real of shape (n,), `d` complex of shape (n,), n in `counts`.

    With `task` (a design task, the default) no two poses may be the same pose
    (`mech._task.distinct_poses`: equal, or a whole number of turns apart).
    """
    theta = real_array("theta", theta)
    d = complex_array("d", d)
    if theta.ndim != 1 or d.shape != theta.shape:
        raise ValueError(
            f"Expected `theta` and `d` of the same shape (n,), got shapes {theta.shape} and {d.shape}"
        )
    if theta.size not in counts:
        allowed = " or ".join(str(c) for c in counts)
        raise ValueError(f"Expected {allowed} poses, got {theta.size}: `theta` = {_show(theta)}")
    if task:
        distinct_poses(theta, d)
    return theta, d


def _wrapped_turn(theta_1, theta_i):
    """theta_i - theta_1 less its nearest whole number of turns (exact when already small)."""
    turn = theta_i - theta_1
    return turn - 2 * np.pi * np.round(turn / (2 * np.pi))


def displacement_matrix(theta_1, d_1, theta_i, d_i):
    """Displacement matrix [P]_i1 carrying body points from pose 1 to pose i, eq. (2-37).

    A pose is an angle and a translation (CONVENTIONS.md): the body point ``z`` is at
    ``exp(1j*theta)*z + d``. The matrix acts on homogeneous columns ``[x, y, 1]`` of ground
    coordinates: ``[P]_i1 @ [x_B1, y_B1, 1] = [x_Bi, y_Bi, 1]``; with the textbook's
    reference point P_i as ``d_i``, it is the textbook's (2-37).

    Parameters
    ----------
    theta_1, theta_i : array_like, shape (...)
        Angles of the two poses, radians.
    d_1, d_i : array_like of complex, shape (...)
        Translations of the two poses (the reference points), broadcast with the angles.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        The displacement matrices.

    Raises
    ------
    ValueError
        For non-finite or non-numeric input (naming the argument).

    Notes
    -----
    The textbook's (2-33) and (2-34) swap sine and cosine in their second lines; the
    matrix (2-35), and so (2-37), are right. Derivation: :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import displacement_matrix
    >>> M = displacement_matrix(0.0, 13.84 + 188.47j, np.radians(8.88), -31.07 + 140.64j)
    >>> np.round(M[:2], 3)                        # example 2-15, [P]_21
    array([[  0.988,  -0.154, -15.651],
           [  0.154,   0.988, -47.707]])
    >>> displacement_matrix([0.0, 1.0], 0, 0.5, 1j).shape
    (2, 3, 3)
    """
    t1, ti = real_array("theta_1", theta_1), real_array("theta_i", theta_i)
    p1, pi_ = complex_array("d_1", d_1), complex_array("d_i", d_i)
    common_shape(theta_1=t1, theta_i=ti, d_1=p1, d_i=pi_)
    t1, ti, p1, pi_ = np.broadcast_arrays(t1, ti, p1, pi_)
    c, s, tx, ty = (np.broadcast_to(v, t1.shape) for v in
                    _gen.planar_displacement(t1, p1.real, p1.imag, ti, pi_.real, pi_.imag))
    out = np.zeros(t1.shape + (3, 3))
    out[..., 0, 0] = c
    out[..., 0, 1] = -s
    out[..., 0, 2] = tx
    out[..., 1, 0] = s
    out[..., 1, 1] = c
    out[..., 1, 2] = ty
    out[..., 2, 2] = 1.0
    return out


def pole(theta_1, d_1, theta_i, d_i):
    """The pole of two poses: the one point of the plane that the displacement leaves fixed.

    Solves ``Q = exp(1j*(theta_i - theta_1))*(Q - d_1) + d_i``: the pole lies on the
    perpendicular bisector of the chord d_1 d_i, ``Q = (d_1 + d_i)/2 + 0.5j*(d_i - d_1)*cot(h)``
    with ``h = (theta_i - theta_1)/2``.

    Parameters
    ----------
    theta_1, theta_i : array_like, shape (...)
        Angles of the two poses, radians.
    d_1, d_i : array_like of complex, shape (...)
        Translations of the two poses.

    Returns
    -------
    ndarray of complex, shape (...)
        The pole in the ground frame.

    Raises
    ------
    ValueError
        If the two poses differ by a pure translation (relative turn a whole number of
        turns, computed exactly): the pole is at infinity.

    Notes
    -----
    The relative turn is first reduced by its nearest whole number of turns, so poses a
    whole turn apart count as a translation. For a small turn the pole is far away, as it
    must be; the chord-first form keeps its relative accuracy, and a pole beyond the float
    range comes out infinite (never NaN). Derivation: :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import pole
    >>> Q = pole(0.0, 0.0, np.pi / 2, 1 + 1j)            # a quarter turn
    >>> complex(Q.round(12) + 0)                          # Q = 1j*(Q - 0) + 1 + 1j
    1j
    """
    t1, ti = real_array("theta_1", theta_1), real_array("theta_i", theta_i)
    p1, pi_ = complex_array("d_1", d_1), complex_array("d_i", d_i)
    common_shape(theta_1=t1, theta_i=ti, d_1=p1, d_i=pi_)
    t1, ti, p1, pi_ = np.broadcast_arrays(t1, ti, p1, pi_)
    turn = _wrapped_turn(t1, ti)
    if np.any(turn == 0.0):
        k = np.flatnonzero(turn.ravel() == 0.0)[0]
        raise ValueError(
            "Expected `theta_1` and `theta_i` of poses that turn relative to each other (a pure translation "
            f"has its pole at infinity), got theta_1={float(t1.ravel()[k])!r}, theta_i={float(ti.ravel()[k])!r}"
        )
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        qx, qy = _gen.displacement_pole(np.zeros_like(turn), p1.real, p1.imag, turn, pi_.real, pi_.imag)
    # A pole beyond the float range is infinite along the bisector; where the chord has a
    # zero component, 0 * inf gave NaN and the exact value is the midpoint's component.
    qx = np.where(np.isnan(qx), p1.real / 2 + pi_.real / 2, qx)
    qy = np.where(np.isnan(qy), p1.imag / 2 + pi_.imag / 2, qy)
    out = np.empty(turn.shape, dtype=complex)
    out.real, out.imag = qx, qy        # not qx + 1j*qy: 1j * inf would put a NaN in the real part
    return out[()]
