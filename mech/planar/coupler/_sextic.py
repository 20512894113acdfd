"""The planar coupler sextic (textbook §2.2; the planar limit of the spherical octic)."""

import numpy as np

from mech._generated import spherical_coupler_curve as _gen
from mech._validate import finite_array, planar_points

__all__ = ["coupler_sextic"]


def coupler_sextic(linkage, points):
    """The implicit coupler curve S(x, y) = 0 of a planar four-bar, and its gradient.

    Derived by the route of the spherical octic, eq. (5) of
    :ref:`deriv-spherical-coupler-curve`: the pin B solves two linear equations, and
    ``S = |N|**2 - a**2 Delta**2`` from Cramer's rule. S has degree exactly 6 (the
    coupler sextic), with nine parameters: the placement of A and of the direction A->D,
    the four lengths and the coupler point.

    Parameters
    ----------
    linkage : array_like, shape (..., 9), or FourBar
        ``(x0, y0, heading, a, b, c, d, p, q)``: pivot A at ``x0 + 1j*y0``, the ground line
        A->D at the angle `heading`, lengths AB, BC, CD, AD (> 0) and the coupler point
        ``(p, q)`` of `mech.planar.FourBar` (p along B->C, q to its left). A `FourBar`
        gives ``(0, 0, 0, a, b, c, d, p, q)``.
    points : array_like of complex, shape (...)
        Planar points ``x + 1j*y``.

    Returns
    -------
    value : ndarray, shape (...)
    gradient : ndarray of complex, shape (...)
        ``dS/dx + 1j*dS/dy``.

    Raises
    ------
    ValueError
        If an input is not finite, `linkage` has the wrong shape or a length is not > 0.

    Notes
    -----
    The mirrored coupler point ``(p, -q)`` traces another curve. As the spherical arcs
    shrink by eps, the spherical octic is ``eps**12 ell S / (16 r**2)`` plus higher orders
    (eq. (6) of the derivation).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import FourBar
    >>> from mech.planar.coupler import coupler_sextic
    >>> m = FourBar(1.0, 3.5, 3.0, 3.2, coupler=(1.5, 0.8))
    >>> value, gradient = coupler_sextic(m, m.solve(np.linspace(0, 6, 4)).P)
    >>> bool(np.all(np.abs(value) < 1e-10 * np.abs(gradient)))
    True
    """
    from mech.planar.kinematics import FourBar

    if isinstance(linkage, FourBar):
        p = np.array([0.0, 0.0, 0.0, linkage.a, linkage.b, linkage.c, linkage.d, *linkage.coupler])
    else:
        p = finite_array("linkage", linkage)
        if p.ndim == 0 or p.shape[-1] != 9:
            raise ValueError(f"Expected `linkage` of shape (..., 9) (x0, y0, heading, a, b, c, d, p, q), "
                             f"got shape {p.shape}")
        lengths = p[..., 3:7]
        if np.any(lengths <= 0.0):
            raise ValueError(f"Expected the lengths a, b, c, d of `linkage` > 0, got {float(lengths[lengths <= 0].ravel()[0])!r}")
    z = planar_points("points", points)
    shape = np.broadcast_shapes(z.shape, p.shape[:-1])
    args = [np.broadcast_to(v, shape) for v in (z.real, z.imag, *np.moveaxis(p, -1, 0))]
    with np.errstate(over="ignore", invalid="ignore"):
        S, Sx, Sy = (np.broadcast_to(v, shape) for v in _gen.planar_coupler_sextic(*args))
    if not (np.all(np.isfinite(S)) and np.all(np.isfinite(Sx)) and np.all(np.isfinite(Sy))):
        raise ValueError("Expected `points` and the lengths of `linkage` small enough for a finite sextic, "
                         f"got a point {complex(np.broadcast_to(z, shape)[~np.isfinite(S)].ravel()[0]) if np.any(~np.isfinite(S)) else complex(z.ravel()[0])!r}")
    return np.array(S, dtype=float), np.asarray(Sx + 1j * Sy)
