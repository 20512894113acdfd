"""Refinement from several starts: the best few matches of an atlas each refined (issues 13 and 28).

A target that is not in the atlas is matched only roughly by its nearest entries; `refine`
then improves one match by a local search, which can stop in a local minimum. Starting it
from several linkages (of different shapes, often of different Grashof types) and keeping
the best is the usual cure. The starts are chosen among the best matches *and their
Roberts-Chebyshev cognates* (the same curve, other proportions): those that already satisfy
the constraints come first, so that a triple-rocker match whose cognate is a crank-rocker
still gives a start a motor can drive.
"""

import dataclasses
from collections import namedtuple

import numpy as np

from mech._validate import instance, integer, nonnegative_number
from mech.atlas._planar._constraints import Constraints, motor_at_crank, transmission_margins
from mech.atlas._planar._refine import _placed_ok, _refine_closed, _unit
from mech.atlas._planar._search import query
from mech.atlas._planar._store import Atlas, mechanism_of
from mech.atlas._planar._signature import _curves, _resample_rows, _samples

__all__ = ["find_linkages"]

_Links = namedtuple("_Links", "a b c d")
#: Two starts closer than this in every ratio and coupler coordinate are one start.
_SAME = 1e-3
#: Refinements tried, at most, per start asked for, when the first ones end infeasible.
_TRIES = 3
#: Free refinements (of the best match and its cognates) whose results, and their cognates,
#: start constrained refinements.
_FREE = 2
#: A relative error at which the second stage (free refinements, then constrained ones from
#: their results) is skipped: the target is then a driven four-bar's curve, found already.
_CLOSE = 1e-4


def _feasible(atlas, constraints):
    """The rows of a four-bar atlas that satisfy `constraints` as they are or relabelled with the
    motor at the rocker (pivot box aside), as an atlas of their own with their row numbers;
    None when there are none or the atlas holds slider-cranks. Kept with the atlas.

    A row is feasible when its crank, or its rocker taken as the crank, turns fully with a
    transmission angle of at least ``mu`` ((C2) of `mech.atlas._planar._constraints`) and its
    longest link is at most `max_ratio` times its shortest.
    """
    if mechanism_of(atlas.settings) != "four-bar":
        return None
    key = (constraints.driven, constraints.min_transmission, constraints.max_ratio)
    cache = atlas._driven_cache
    if key not in cache:
        L = atlas.linkages
        ok = np.ones(len(atlas), dtype=bool)
        if constraints.driven:
            mu = max(constraints.min_transmission, 1e-3)
            ok = np.zeros(len(atlas), dtype=bool)
            for crank, rocker in ((L.a, L.c), (L.c, L.a)):
                g0, gpi = transmission_margins(crank, L.b, rocker, L.d, mu)
                ok |= (g0 >= 0.0) & (gpi >= 0.0)
        if constraints.max_ratio is not None:
            links = np.stack([L.a, L.b, L.c, L.d])
            ok &= links.max(axis=0) <= constraints.max_ratio * links.min(axis=0)
        rows = np.flatnonzero(ok & L.movable)
        cache[key] = None if rows.size == 0 else (
            Atlas(L.take(rows), atlas.signatures[rows], atlas.seeds[rows], atlas.settings), rows)
    return cache[key]


def _candidates(matches, constraints):
    """Starts from the matches and their cognates: (unit linkage, match), feasible ones first."""
    out = []
    for order, m in enumerate(matches):
        for placed in (m.linkage, *m.cognates):
            unit = _unit(placed.fourbar)
            if constraints.driven:
                unit, _ = motor_at_crank(*unit)
            bad = constraints.violations(_Links(*unit[:4]), placed.pivots)
            out.append((bool(bad), order, unit, m))
    out.sort(key=lambda c: (c[0], c[1]))
    kept = []
    for bad, _, unit, m in out:
        if not any(np.allclose(unit[:6], other[:6], rtol=_SAME, atol=_SAME) and unit[6] == other[6]
                   for other, _ in kept):
            kept.append((unit, m))
    return kept


def find_linkages(atlas, target, *, starts=4, goal=None, samples=128, iterations=100, constraints=None):
    """Find four-bars tracing a closed target curve: query an atlas, then refine from several starts.

    The best matches of `query` and their cognates give the starts, those satisfying the
    constraints first (a rocker-crank relabelled with the motor at its fully turning link),
    with the best matches among the atlas rows that satisfy the constraints (searched apart,
    so that a target whose nearest rows are all rockers still gets starts a motor drives);
    each of `starts` of them is refined by SLSQP under the constraints (`refine`). Then the
    best match and its cognates are refined without constraints, and the two best results,
    with their cognates, start constrained refinements too (the constrained optimum often
    lies on a constraint near a free one); this second stage is skipped when the first has
    reached a relative error of 1e-4 (or `goal`). Every result is checked against the constraints:
    a linkage that fails is not returned. By default the
    answer is a linkage a motor can drive: its input (the crank ``a``) turns fully, with a
    transmission angle of at least 30 degrees, and its longest link is at most ten times its
    shortest (`Constraints`).

    Parameters
    ----------
    atlas : Atlas
        The atlas to search.
    target : array_like, complex, shape (m,)
        Points along a closed curve, m >= 3, in any placement, size, start and direction.
    starts : int, optional
        Starts refined, in [1, 64] (a few more are tried if the first all fail the constraints).
    goal : float, optional
        Stop once a refined match has a `relative_error` at most this (>= 0); by default
        every start is refined.
    samples, iterations : int, optional
        Passed to `refine`.
    constraints : Constraints, optional
        What every returned linkage satisfies; default ``Constraints()``. Pass
        ``Constraints.none()`` for any four-bar (triple-rockers included).

    Returns
    -------
    list of Match
        The refined matches (``refined=True``, or the start where refinement found no better
        linkage), best first, ranked again from 0, each satisfying `constraints`; empty if no
        start led to a linkage that does.

    Raises
    ------
    ValueError
        For a bad target or options (named).

    Notes
    -----
    The error is the RMS distance between the target and the coupler curve at equal
    arc-length steps, best aligned, over the RMS radius of the target (`Match`). The book
    page :ref:`book-find-a-linkage` shows the error each start reaches, with and without
    the constraints.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_atlas, find_linkages
    >>> from mech.planar import FourBar
    >>> t = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    >>> target = FourBar(10, 40, 30, 35, coupler=(20, 15)).solve(t).P     # example 2-1's linkage
    >>> best = find_linkages(build_atlas(2000, seed=3), target, starts=3, goal=0.01)[0]
    >>> best.refined, best.relative_error < 0.01, best.full_turn, bool(np.degrees(best.gamma_min) >= 30)
    (True, True, True, True)
    """
    starts = integer("starts", starts, minimum=1, maximum=64)
    if goal is not None:
        goal = nonnegative_number("goal", goal)
    samples = _samples(samples, harmonics=1)
    iterations = integer("iterations", iterations, minimum=1, maximum=10**6)
    constraints = Constraints() if constraints is None else constraints
    instance("constraints", constraints, Constraints)
    k, shortlist = min(2 * starts, 64), max(64, 2 * starts)
    matches = query(atlas, target, k=k, shortlist=shortlist)
    ranked = matches
    if constraints != Constraints.none():
        # the best matches are often rockers far from any linkage a motor drives: the rows
        # that satisfy the constraints are searched on their own too, and give the first starts
        feasible = _feasible(atlas, constraints)
        if feasible is not None:
            sub, rows = feasible
            near = [dataclasses.replace(m, index=int(rows[m.index]))
                    for m in query(sub, target, k=min(k, len(sub)), shortlist=min(shortlist, len(sub)))]
            ranked = sorted([*near, *matches], key=lambda m: m.relative_error)
    z, _, scale = _curves(target, True, "target", scaled=True)
    t = _resample_rows(z, samples, True)[0]
    s = float(scale[0])
    out = []

    def run(unit, m, rules):
        results = [r for r in _refine_closed(unit, t, s, rules, samples, iterations, m.rank, m.index, m.distance)
                   if r is not None and _placed_ok(r, rules)]
        return min(results, key=lambda r: r.relative_error) if results else None

    for tried, (unit, m) in enumerate(_candidates(ranked, constraints)):
        if tried >= starts and (out or tried >= _TRIES * starts):
            break
        found = run(unit, m, constraints)
        if found is not None:
            out.append(found)
            if goal is not None and found.relative_error <= goal:
                break
    enough = _CLOSE if goal is None else max(goal, _CLOSE)
    if constraints != Constraints.none() and not (out and min(r.relative_error for r in out) <= enough):
        # the constrained optimum often lies on a constraint near an unconstrained one: the
        # best match and its cognates are refined freely, and the best results and their
        # cognates (other proportions, the same curve) start constrained refinements
        m = matches[0]
        free = [run(_unit(placed.fourbar), m, Constraints.none()) for placed in (m.linkage, *m.cognates)]
        free = sorted((f for f in free if f is not None), key=lambda f: f.relative_error)
        for f in free[:_FREE]:
            for placed in (f.linkage, *f.cognates):
                found = run(_unit(placed.fourbar), m, constraints)
                if found is not None:
                    out.append(found)
    out.sort(key=lambda m: m.relative_error)
    return [dataclasses.replace(m, rank=r) for r, m in enumerate(out)]
