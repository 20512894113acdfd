"""Coupler-curve atlas pages: curves sampled as dashes of equal crank rotation (Fig. 2-30)."""

from dataclasses import dataclass

import numpy as np

from mech._validate import MAX_COUNT, branch_sign, integer, planar_points, positive_length, real_number
from mech.planar.kinematics._fourbar import FourBar

__all__ = ["CouplerDashes", "coupler_dashes"]


@dataclass(frozen=True)
class CouplerDashes:
    """Coupler curves cut into equal steps of crank rotation (returned by `coupler_dashes`).

    Attributes
    ----------
    theta : ndarray, shape (n + 1,)
        Crank angles at the ends of the steps, radians (one full turn).
    coupler : ndarray of complex, shape (...)
        The coupler points ``p + 1j*q`` of the lattice.
    points : ndarray of complex, shape (..., n + 1)
        Coupler point at each crank angle; NaN where the linkage cannot be assembled.
    length : ndarray, shape (..., n)
        Chord length of each step: the dash length (NaN unless both ends are valid).
    mean_speed : ndarray, shape (..., n)
        ``length / step``: mean speed of the point per unit crank angular velocity.
    valid : ndarray of bool, shape (..., n)
        True where both ends of the step are assembled.
    """

    theta: np.ndarray
    coupler: np.ndarray
    points: np.ndarray
    length: np.ndarray
    mean_speed: np.ndarray
    valid: np.ndarray


def coupler_dashes(a, b, c, d, coupler, *, n=72, branch=1, start=0.0):
    """Coupler curves of a four-bar cut into `n` dashes of equal crank rotation.

    Each curve of a coupler-curve atlas page (连杆曲线图谱, Fig. 2-30, F25) is drawn as
    72 dashes, one for every 5 degrees of crank rotation, so that the spacing of the dashes
    shows the speed of the point: with the crank at constant speed, a long dash is a fast
    stretch. This function computes those dashes for a whole lattice of coupler points.

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD (an atlas page takes a = 1).
    coupler : array_like of complex, shape (...)
        Coupler points ``p + 1j*q`` in the ``FourBar`` convention (p along B->C, q to its
        left), e.g. a lattice attached to the coupler.
    n : int, optional
        Number of dashes per crank turn (72 gives 5-degree steps).
    branch : {1, -1}, optional
        Assembly branch, as in ``FourBar``.
    start : float, optional
        Crank angle of the first dash end, radians.

    Returns
    -------
    CouplerDashes
        ``theta``, ``points``, ``length``, ``mean_speed`` and ``valid``.

    Raises
    ------
    ValueError
        For a bad length, `branch`, `n` < 3 or a non-finite coupler point.

    Notes
    -----
    Positions come from ``FourBar.solve`` (derivation page :ref:`deriv-fourbar-position`).
    The chord of a step underestimates the arc by a relative amount of about
    ``(curvature * length)**2 / 24``, negligible for 5-degree steps except at cusps.

    Examples
    --------
    >>> from mech.planar.coupler._atlas import coupler_dashes
    >>> dashes = coupler_dashes(1, 2, 2.5, 3, [0.5 + 0.5j, 1.0 + 1.0j])
    >>> dashes.points.shape, dashes.length.shape, bool(dashes.valid.all())
    ((2, 73), (2, 72), True)
    """
    lengths = [positive_length(name, v) for name, v in zip("abcd", (a, b, c, d))]
    branch = branch_sign(branch)
    n = integer("n", n, minimum=3, maximum=MAX_COUNT)
    start = real_number("start", start)
    w = planar_points("coupler", coupler)
    theta = start + np.linspace(0.0, 2 * np.pi, n + 1)
    flat = w.reshape(-1)
    points = np.empty((flat.size, n + 1), dtype=complex)
    for i, z in enumerate(flat):
        points[i] = FourBar(*lengths, branch=branch, coupler=(z.real, z.imag)).solve(theta).P
    points = points.reshape(w.shape + (n + 1,))
    ok = np.isfinite(points)
    valid = ok[..., 1:] & ok[..., :-1]
    with np.errstate(invalid="ignore"):
        length = np.where(valid, np.abs(np.diff(points, axis=-1)), np.nan)
    return CouplerDashes(theta=theta, coupler=w[()], points=points, length=length,
                         mean_speed=length / (2 * np.pi / n), valid=valid)
