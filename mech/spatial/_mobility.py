"""Degrees of freedom of a spatial linkage by counting constraints (F67, §2.5, part II)."""

import numbers

import numpy as np

from mech._errors import InputTypeError
from mech._validate import nonnegative_int

__all__ = ["PAIR_FREEDOMS", "mobility"]

#: Relative freedoms of the lower pairs: revolute, prismatic, helical, cylindrical,
#: spherical (ball) and planar.
PAIR_FREEDOMS = {"R": 1, "P": 1, "H": 1, "C": 2, "S": 3, "E": 3}


def mobility(moving_links, pairs):
    """Degrees of freedom of a spatial linkage, F = 6 n - sum of (6 - f) over the pairs.

    Each free body has six freedoms and each pair with ``f`` relative freedoms removes
    ``6 - f`` of them. The count includes local freedoms that move no other link, such as
    the spin of a coupler between two spherical pairs; it can also be too small for
    linkages whose special geometry makes constraints redundant (the planar four-bar, read
    as a spatial chain, counts -2).

    Parameters
    ----------
    moving_links : int
        Number of links other than the frame, ``n``.
    pairs : str or iterable of str
        The pairs by letter, e.g. ``"RSSR"``: R, P, H (one freedom), C (two), S and E
        (three; E is a planar pair).

    Returns
    -------
    int

    Raises
    ------
    ValueError
        For an unknown pair letter or a negative number of links.

    Examples
    --------
    The RSSR four-bar: three moving links, two revolute and two spherical pairs. One of the
    two freedoms is the coupler's spin about BC:

    >>> mobility(3, "RSSR")
    2
    >>> mobility(3, "RSSR") - 1     # without the coupler's spin
    1
    """
    n = nonnegative_int("moving_links", moving_links, 10**6)
    total = 6 * n
    if isinstance(pairs, (bytes, bool, np.bool_, numbers.Number)) or not hasattr(pairs, "__iter__"):
        raise InputTypeError(f"Expected `pairs` to be pair letters such as 'RSSR', got {pairs!r}")
    for p in pairs:
        if not isinstance(p, str) or p not in PAIR_FREEDOMS:
            raise ValueError(f"Expected `pairs` to be pair letters among {', '.join(PAIR_FREEDOMS)}, "
                             f"got {p!r} in {pairs!r}")
        total -= 6 - PAIR_FREEDOMS[p]
    return total
