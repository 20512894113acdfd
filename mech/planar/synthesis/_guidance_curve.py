"""Four poses: the circle-point and centre-point curves (Burmester's cubics), as curves."""

from dataclasses import dataclass

import numpy as np

from mech._generated import displacement as _gen
from mech._validate import nonnegative_int, real_array
from mech.planar.synthesis._displacement import pose_set
from mech.planar.synthesis._guidance import Dyad

__all__ = ["BurmesterCurve", "circle_point_curve"]


@dataclass(frozen=True)
class BurmesterCurve:
    """The circle-point curve of four poses and the matching centre points.

    The curve is traced by lines through a pole P_jk (a point of the curve): the line at
    angle ``phi[i]`` meets the cubic in the pole and in two more points, ``k = 0, 1``.

    Attributes
    ----------
    phi : ndarray, shape (m,)
        Directions of the tracing lines, radians.
    circle_point : ndarray of complex, shape (m, 2)
        Circle points in body coordinates; NaN where the two further intersections are
        complex or at infinity (``valid`` False).
    moving_pivot, centre_point : ndarray of complex, shape (m, 2)
        The circle point in the ground frame at pose 1, and its centre point.
    length : ndarray, shape (m, 2)
        Crank lengths.
    valid : ndarray of bool, shape (m, 2)
        True where the intersection is real and finite.
    pole : complex
        The pole (body coordinates) the tracing lines pass through.
    """

    phi: np.ndarray
    circle_point: np.ndarray
    moving_pivot: np.ndarray
    centre_point: np.ndarray
    length: np.ndarray
    valid: np.ndarray
    pole: complex

    def dyad(self, i, k):
        """The `Dyad` at tracing line `i`, intersection `k` (0 or 1); it must be valid."""
        i = nonnegative_int("i", i, self.phi.size - 1)
        k = nonnegative_int("k", k, 1)
        if not self.valid[i, k]:
            raise ValueError(f"Expected a valid point of the curve, got i = {i}, k = {k} (complex or infinite)")
        return Dyad(complex(self.circle_point[i, k]), complex(self.moving_pivot[i, k]),
                    complex(self.centre_point[i, k]), float(self.length[i, k]))


def _rows_at(rows, z):
    """The three equations at circle points z (shape (m,)), as rows [coef p, coef q, constant]
    of a linear system for the centre point; shape (m, 3, 3)."""
    kx, ky, kp, kq, k1, k2, k0 = (rows[:, i][None, :] for i in range(7))
    x, y = z.real[:, None], z.imag[:, None]
    return np.stack([kp + k1 * x + k2 * y, kq + k1 * y - k2 * x, kx * x + ky * y + k0], axis=-1)


def _affine_rows(rows, z0, v):
    """The rows along the lines z = z0 + r v, as affine functions a + b r; shape (m, 3, 3, 2)."""
    a = _rows_at(rows, np.full(v.shape, z0))
    b = _rows_at(rows, v) - _rows_at(rows, np.zeros_like(v))
    return np.stack([a, b], axis=-1)


def _pmul(f, g):
    """Product of polynomials in r stored along the last axis (lowest degree first)."""
    out = np.zeros(np.broadcast_shapes(f.shape[:-1], g.shape[:-1]) + (f.shape[-1] + g.shape[-1] - 1,))
    for i in range(f.shape[-1]):
        for j in range(g.shape[-1]):
            out[..., i + j] += f[..., i] * g[..., j]
    return out


def _det_cubic(E):
    """Coefficients (r^0 .. r^3) of the determinant of 3x3 matrices with affine entries E."""
    def e(i, j):
        return E[:, i, j]
    terms = [(+1, (0, 0), (1, 1), (2, 2)), (-1, (0, 0), (1, 2), (2, 1)), (-1, (0, 1), (1, 0), (2, 2)),
             (+1, (0, 1), (1, 2), (2, 0)), (+1, (0, 2), (1, 0), (2, 1)), (-1, (0, 2), (1, 1), (2, 0))]
    return sum(s * _pmul(_pmul(e(*p), e(*q)), e(*t)) for s, p, q, t in terms)


def circle_point_curve(theta, d, *, samples=360, phi=None):
    """The circle-point curve of four poses, with the centre point of each of its points.

    For four poses the three equations (2-40) leave one degree of freedom: the circle points
    (body points whose four positions lie on a circle) form a cubic curve, and their centres
    another cubic, the centre-point curve. Each line through a pole of two of the poses (a
    point of the curve) meets the cubic in two more points, the roots of a quadratic; the
    lines at ``samples`` directions trace the whole curve.

    Parameters
    ----------
    theta : array_like, shape (4,)
        Pose angles, radians.
    d : array_like of complex, shape (4,)
        Pose translations.
    samples : int, optional
        Number of tracing directions, evenly spread over [0, pi), at least 1.
    phi : array_like, shape (m,), optional
        Tracing directions (radians) to use instead of `samples` even ones.

    Returns
    -------
    BurmesterCurve
        ``circle_point``, ``moving_pivot``, ``centre_point``, ``length`` and ``valid`` of
        shape (samples, 2); ``dyad(i, k)`` gives one point as a `Dyad`.

    Raises
    ------
    ValueError
        For a wrong number of poses or non-finite input, or if every two poses differ by a
        pure translation (no pole to trace from).

    Notes
    -----
    The poses are moved to their centroid and scaled by their size first, so the curve
    does not depend on the unit of length. For each circle point the centre point solves
    the three (consistent) linear equations by least squares. Derivation of the equations:
    :ref:`deriv-displacement`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import circle_point_curve
    >>> theta, d = np.radians([0.0, 8.88, 22.1, 63.68]), [13.84 + 188.47j, -31.07 + 140.64j,
    ...                                                   -51.64 + 96.33j, 44.74 + 113.95j]
    >>> curve = circle_point_curve(theta, d, samples=90)
    >>> Z = np.exp(1j * theta) * curve.circle_point[curve.valid][:, None] + d
    >>> r = np.abs(Z - curve.centre_point[curve.valid][:, None])
    >>> bool(np.all(np.abs(r - r[:, :1]) < 1e-9 * r[:, :1]))
    True
    """
    theta, d = pose_set(theta, d, (4,))
    if phi is None:
        samples = nonnegative_int("samples", samples, 10**7)
        if samples < 1:
            raise ValueError(f"Expected `samples` >= 1, got {samples}")
        phi = np.arange(samples) * (np.pi / samples)
    else:
        phi = real_array("phi", phi).reshape(-1)
        samples = phi.size
    centre = d.mean()
    size = np.max(np.abs(d - centre))
    size = size if size > 0 else 1.0
    dn = (d - centre) / size
    w = np.exp(1j * theta)
    # trace from the pole of the two poses that turn most relative to each other
    j, k = max(((j, k) for j in range(4) for k in range(j + 1, 4)), key=lambda jk: abs(w[jk[0]] - w[jk[1]]))
    if abs(w[j] - w[k]) == 0:
        raise ValueError(f"Expected poses that turn relative to each other, got `theta` = {theta!r}")
    z0 = (dn[k] - dn[j]) / (w[j] - w[k])
    rows = np.array(_gen.crank_design_row(theta[0], dn[0].real, dn[0].imag,
                                          theta[1:], dn[1:].real, dn[1:].imag), dtype=float).T
    rows = np.broadcast_to(rows, (3, 7)).copy()
    rows /= np.linalg.norm(rows, axis=1, keepdims=True)
    v = np.exp(1j * phi)
    cubic = _det_cubic(_affine_rows(rows, z0, v))
    # r = 0 (the pole) is a root; the other two solve c3 r^2 + c2 r + c1 = 0
    c1, c2, c3 = cubic[:, 1], cubic[:, 2], cubic[:, 3]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        disc = c2 * c2 - 4 * c3 * c1
        root = np.sqrt(np.where(disc >= 0, disc, np.nan))
        q = -0.5 * (c2 + np.where(c2 >= 0, 1.0, -1.0) * root)
        r = np.stack([q / c3, c1 / q], axis=-1)
        valid = np.isfinite(r)
        z = np.where(valid, z0 + r * v[:, None], z0)
    M = _rows_at(rows, z.ravel())
    pq = np.einsum("nij,nj->ni", np.linalg.pinv(M[:, :, :2]), -M[:, :, 2])
    A = (pq[:, 0] + 1j * pq[:, 1]).reshape(samples, 2)
    zb = np.where(valid, z, np.nan) * size
    Ab = np.where(valid, centre + A * size, np.nan)
    moving = np.exp(1j * theta[0]) * zb + d[0]
    length = np.abs(moving - Ab)
    valid &= np.isfinite(length) & (length > 0)
    nan = complex(np.nan, np.nan)
    return BurmesterCurve(phi, np.where(valid, zb, nan), np.where(valid, moving, nan),
                          np.where(valid, Ab, nan), np.where(valid, length, np.nan), valid, complex(z0 * size))
