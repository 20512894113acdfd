"""Refinement from several starts: the best few matches of an atlas each refined (issue 13, item 4).

A target that is not in the atlas is matched only roughly by its nearest entries; `refine`
then improves one match by a local search, which can stop in a local minimum. Starting it
from several matches (of different shapes of linkage, often of different Grashof types)
and keeping the best is the usual cure, and cheap: the search is local and each start
takes about a second.
"""

import dataclasses

from mech._validate import integer, nonnegative_number
from mech.atlas._search import query, refine

__all__ = ["find_linkages"]


def find_linkages(atlas, target, *, starts=8, goal=None, samples=128, iterations=400):
    """Find four-bars tracing a closed target curve: query an atlas, then refine from several starts.

    The best `starts` matches of `query` are each refined by `refine` (a Nelder-Mead search
    on the real curve error), in the order of their errors; the refined linkages are
    returned best first.

    Parameters
    ----------
    atlas : Atlas
        The atlas to search.
    target : array_like, complex, shape (m,)
        Points along a closed curve, m >= 3, in any placement, size, start and direction.
    starts : int, optional
        Matches refined, in [1, 64].
    goal : float, optional
        Stop once a refined match has a `relative_error` at most this (>= 0); by default
        every start is refined.
    samples, iterations : int, optional
        Passed to `refine`.

    Returns
    -------
    list of Match
        The refined matches (``refined=True``, or the starting match where no better linkage
        was found), best first, ranked again from 0.

    Raises
    ------
    ValueError
        For a bad target or options (named).

    Notes
    -----
    The error is the RMS distance between the target and the coupler curve at equal
    arc-length steps, best aligned, over the RMS radius of the target (`Match`). The book
    page :ref:`book-find-a-linkage` shows the error each start reaches.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_atlas, find_linkages
    >>> from mech.planar import FourBar
    >>> t = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    >>> target = FourBar(10, 40, 30, 35, coupler=(20, 15)).solve(t).P     # example 2-1's linkage
    >>> best = find_linkages(build_atlas(2000, seed=3), target, starts=3, goal=0.01)[0]
    >>> best.refined, best.relative_error < 0.01
    (True, True)
    """
    starts = integer("starts", starts, minimum=1, maximum=64)
    if goal is not None:
        goal = nonnegative_number("goal", goal)
    matches = query(atlas, target, k=starts, shortlist=max(64, starts))
    out = []
    for match in matches:
        out.append(refine(match, target, samples=samples, iterations=iterations))
        if goal is not None and out[-1].relative_error <= goal:
            break
    out.sort(key=lambda m: m.relative_error)
    return [dataclasses.replace(m, rank=r) for r, m in enumerate(out)]
