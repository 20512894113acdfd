"""Coordinate transforms of spatial linkages: rotations and Hartenberg-Denavit matrices.

A matrix ``R_ij`` or ``M_ij`` maps coordinates in frame j to coordinates in frame i
(``CONVENTIONS.md``). Every function takes scalars or arrays, broadcasts them against each
other like a ufunc and returns a stack of matrices in one vectorised call.
"""

import numpy as np

from mech._generated import transforms as _gen
from mech._validate import finite_array

__all__ = ["rot_z", "rot_x", "hd", "hd_inv", "homogeneous"]


def _rotation(angle, name, rows, entries):
    angle = finite_array(name, angle)
    out = np.zeros(angle.shape + (3, 3))
    fixed = ({0, 1, 2} - set(rows)).pop()
    out[..., fixed, fixed] = 1.0
    for (r, c), value in zip([(r, c) for r in rows for c in rows], entries(angle)):
        out[..., r, c] = value
    return out


def rot_z(phi):
    """Rotation about the common z axis by `phi`, eq. (2-60).

    ``R = rot_z(phi)`` maps the coordinates of a point in frame j, turned by `phi` about
    z_i (right-hand rule) from frame i, to its coordinates in frame i: r_i = R r_j (2-59).
    The inverse map (2-61) is ``R.T``, equal to ``rot_z(-phi)``.

    Parameters
    ----------
    phi : array_like, shape (...)
        Angle from x_i to x_j about z_i, radians.

    Returns
    -------
    R : ndarray, shape (..., 3, 3)
        One rotation matrix per angle.

    Raises
    ------
    ValueError
        If an angle is not finite.

    Notes
    -----
    Derived, with the proof that R is orthogonal with determinant 1, in
    :ref:`deriv-transforms` (``derivations/spatial/transforms.md``).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._transforms import rot_z
    >>> rot_z(np.pi / 2) @ [1.0, 0.0, 0.0]
    array([6.1e-17, 1.0e+00, 0.0e+00])
    >>> rot_z([0.1, 0.2, 0.3]).shape
    (3, 3, 3)
    """
    return _rotation(phi, "phi", (0, 1), _gen.rot_z_entries)


def rot_x(lam):
    """Rotation about the common x axis by `lam`, eq. (2-62).

    ``R = rot_x(lam)`` maps coordinates in frame j, turned by `lam` about x_i from frame i,
    to coordinates in frame i. The inverse is ``R.T``, equal to ``rot_x(-lam)``.

    Parameters
    ----------
    lam : array_like, shape (...)
        Angle from z_i to z_j about x_i, radians.

    Returns
    -------
    R : ndarray, shape (..., 3, 3)
        One rotation matrix per angle.

    Raises
    ------
    ValueError
        If an angle is not finite.

    Notes
    -----
    The composite turn of (2-63), ``rot_z(phi) @ rot_x(lam)``, turns about the moving axis
    x_k (the x axis after the first turn), not about the fixed x_i; see
    :ref:`deriv-transforms`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._transforms import rot_x
    >>> np.round(rot_x(np.pi / 2) @ [0.0, 1.0, 0.0], 12)
    array([0., 0., 1.])
    >>> np.allclose(rot_x([0.5, 1.5]) @ rot_x([-0.5, -1.5]), np.eye(3), rtol=0, atol=1e-15)
    True
    """
    return _rotation(lam, "lam", (1, 2), _gen.rot_x_entries)


def _assemble(entries, phi, lam, s, h):
    phi, lam, s, h = (finite_array(n, v) for n, v in zip(("phi", "lam", "s", "h"), (phi, lam, s, h)))
    shape = np.broadcast_shapes(phi.shape, lam.shape, s.shape, h.shape)
    out = np.empty(shape + (4, 4))
    out[..., 3, :3] = 0.0
    out[..., 3, 3] = 1.0
    for k, value in enumerate(entries(phi, lam, s, h)):
        out[..., k // 4, k % 4] = value
    return out


def hd(phi, lam, s, h):
    """Hartenberg-Denavit matrix M_ij of two neighbouring links, eq. (2-67).

    Frame j is reached from frame i by: a shift `s` (S_i) along z_i, a turn `phi`
    (phi_ij) about z_i, a shift `h` (h_j) along the new x axis x_j, and a turn `lam`
    (lambda_ij) about x_j. Then [r_i; 1] = M_ij [r_j; 1] (2-65). In the standard
    Denavit-Hartenberg symbols, (theta, d, a, alpha) = (phi, s, h, lam).

    Parameters
    ----------
    phi, lam : array_like
        Joint angle phi_ij about z_i and twist lambda_ij about x_j, radians.
    s, h : array_like
        Offsets S_i along z_i and h_j along x_j (any consistent length unit).

    Returns
    -------
    M : ndarray, shape (..., 4, 4)
        The broadcast shape of the four parameters, followed by (4, 4).

    Raises
    ------
    ValueError
        If a parameter is not finite.

    Notes
    -----
    Derived from the four elementary motions in :ref:`deriv-transforms`, where
    M_ij M_ji = I is proved exactly. A spherical pair (three rotations) cannot be
    described by one H-D matrix.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._transforms import hd, hd_inv
    >>> M = hd(np.pi / 2, np.pi / 2, 1.0, 2.0)
    >>> M @ [0.0, 0.0, 0.0, 1.0]          # origin of frame j in frame i
    array([1.2e-16, 2.0e+00, 1.0e+00, 1.0e+00])
    >>> hd(np.linspace(0, 1, 5), 0.3, [[0.0], [1.0]], 2.0).shape
    (2, 5, 4, 4)
    >>> np.allclose(hd_inv(0.3, 1.1, 2.0, -1.0) @ hd(0.3, 1.1, 2.0, -1.0), np.eye(4))
    True
    """
    return _assemble(_gen.hd_entries, phi, lam, s, h)


def hd_inv(phi, lam, s, h):
    """Inverse M_ji = M_ij^-1 of the H-D matrix, eq. (2-68).

    Takes the same parameters as `hd` (those of M_ij) and maps coordinates in frame i to
    coordinates in frame j: [r_j; 1] = M_ji [r_i; 1]. Its rotation block is R_ij^T and
    its last column, (-h, -s sin(lam), -s cos(lam)), is the origin O_i seen from frame j.

    Parameters
    ----------
    phi, lam : array_like
        Joint angle phi_ij and twist lambda_ij of M_ij, radians.
    s, h : array_like
        Offsets S_i and h_j of M_ij.

    Returns
    -------
    M_inv : ndarray, shape (..., 4, 4)
        The broadcast shape of the four parameters, followed by (4, 4).

    Raises
    ------
    ValueError
        If a parameter is not finite.

    Notes
    -----
    Exact, not a numerical inversion: see :ref:`deriv-transforms`.

    Examples
    --------
    >>> from mech.spatial._transforms import hd_inv
    >>> hd_inv(0.0, 0.0, 1.0, 2.0)[:3, 3]
    array([-2., -0., -1.])
    """
    return _assemble(_gen.hd_inv_entries, phi, lam, s, h)


def homogeneous(R, p):
    """Homogeneous 4x4 transform [[R, p], [0, 1]] of eq. (2-65).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation from frame j to frame i.
    p : array_like, shape (..., 3)
        Origin of frame j in frame i.

    Returns
    -------
    M : ndarray, shape (..., 4, 4)
        The broadcast stack of transforms.

    Raises
    ------
    ValueError
        If an entry is not finite or the shapes do not end in (3, 3) and (3,).

    Examples
    --------
    >>> from mech.spatial._transforms import homogeneous, rot_z
    >>> homogeneous(rot_z(0.0), [1.0, 2.0, 3.0])[:, 3]
    array([1., 2., 3., 1.])
    """
    R = finite_array("R", R)
    p = finite_array("p", p)
    if R.shape[-2:] != (3, 3) or p.shape[-1:] != (3,):
        raise ValueError(f"Expected `R` of shape (..., 3, 3) and `p` of shape (..., 3), got {R.shape} and {p.shape}")
    shape = np.broadcast_shapes(R.shape[:-2], p.shape[:-1])
    out = np.zeros(shape + (4, 4))
    out[..., :3, :3] = R
    out[..., :3, 3] = p
    out[..., 3, 3] = 1.0
    return out
