"""Spacing of precision points over an input range, shared by the planar and spherical syntheses."""

import numpy as np

from mech._validate import MAX_COUNT, integer, real_number

__all__ = ["chebyshev_spacing"]


def chebyshev_spacing(x0, x1, n):
    """Chebyshev spacing of `n` precision points over the input range [x0, x1].

    x_i = (x0 + x1)/2 - (x1 - x0)/2 cos((2i - 1) pi / (2n)), i = 1..n (the textbook's F92).

    Parameters
    ----------
    x0, x1 : float
        Ends of the range, x0 < x1.
    n : int
        Number of points, >= 1.

    Returns
    -------
    x : ndarray, shape (n,)
        Increasing.

    Raises
    ------
    ValueError
        If ``x1 <= x0`` or `n` is not a positive integer.

    Notes
    -----
    Page ``deriv-spherical-function-generation``. This is the corrected formula: the planar
    textbook's Ex. 2-16 centred its nodes on the half-width instead of the middle of the
    interval (row 53 of the errata page, ``book/errata.md``).

    Examples
    --------
    >>> from mech.spherical import chebyshev_spacing
    >>> chebyshev_spacing(1.0, 10.0, 3).round(5)
    array([1.60289, 5.5    , 9.39711])
    """
    x0, x1 = real_number("x0", x0), real_number("x1", x1)
    if not x1 > x0:
        raise ValueError(f"Expected `x1` > `x0`, got x0 = {x0!r}, x1 = {x1!r}")
    n = integer("n", n, minimum=1, maximum=MAX_COUNT)
    i = np.arange(1, n + 1)
    return 0.5 * (x0 + x1) - 0.5 * (x1 - x0) * np.cos((2 * i - 1) * np.pi / (2 * n))
