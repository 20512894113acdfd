"""Type classification of the spherical four-bar (the monograph's chapter 7).

The derivation page ``derivations/spherical/types.md`` (label ``deriv-spherical-types``)
shows that a joint turns fully according to the signs of four slacks: the three planar
ones and the sphere's sum slack ``2 pi - (a + b + c + d)``;
``mech._generated.spherical_types.spherical_type_slacks`` computes them.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated.spherical_types import spherical_type_slacks
from mech._validate import arc as _arc, real_number

__all__ = ["SphericalType", "classify", "inversions", "antipode_reduction"]

_LINKS = ("a", "b", "c", "d")
# the two joints at the ends of each arc: a = AB, b = BC, c = CD, d = DA
_ENDS = {"a": ("A", "B"), "b": ("B", "C"), "c": ("C", "D"), "d": ("D", "A")}


@dataclass(frozen=True)
class SphericalType:
    """Type of a spherical four-bar with ground ``d``: the result of :func:`classify`."""

    kind: str
    grashof: bool
    change_point: bool
    revolving: frozenset
    reduced: tuple
    moves: tuple
    shortest: str
    longest: str
    meeting_angles: tuple
    slacks: tuple


def antipode_reduction(a, b, c, d):
    """Move joint axes to their antipodes until at most one arc exceeds pi/2.

    Moving a joint's point to its antipode replaces the two arcs at that joint by their
    supplements (pi - arc) and leaves the motion unchanged. Every arc is made <= pi/2,
    except that when an odd number of arcs exceeds pi/2 the arc nearest to pi/2 stays
    obtuse; the reduced arcs then total at most 2 pi.

    Parameters
    ----------
    a, b, c, d : float
        Arcs AB, BC, CD, DA, radians in (0, pi).

    Returns
    -------
    reduced : tuple of 4 floats
        The arcs after the moves, in the order a, b, c, d.
    moves : tuple of str
        The joints moved to their antipodes, a subset of ("B", "C", "D") in that order
        (joint A is never moved: moving all four changes nothing).

    Raises
    ------
    ValueError
        If an arc is not in (0, pi).

    Notes
    -----
    Derived on :ref:`deriv-spherical-types` (section "The product invariants and the
    normal form").

    Examples
    --------
    >>> from mech.spherical._types import antipode_reduction
    >>> reduced, moves = antipode_reduction(2.5, 2.0, 0.7, 1.0)
    >>> [round(x, 6) for x in reduced], moves
    ([0.641593, 1.141593, 0.7, 1.0], ('B',))
    >>> antipode_reduction(2.0, 0.5, 0.6, 0.7)[1]     # one obtuse arc: nothing to do
    ()
    """
    arcs = [_arc(n, v) for n, v in zip(_LINKS, (a, b, c, d))]
    obtuse = [x > np.pi / 2 for x in arcs]
    target = [x if x <= np.pi / 2 else np.pi - x for x in arcs]   # the acute versions
    if sum(obtuse) % 2:
        keep = int(np.argmax(target))                            # nearest to pi/2
        target[keep] = np.pi - target[keep]
    toggled = [abs(t - x) > 0.0 for t, x in zip(target, arcs)]
    # arcs toggled by moving joint set F (A not in F): a iff B in F, b iff B xor C, c iff C xor D
    in_f = {"A": False}
    in_f["B"] = toggled[0]
    in_f["C"] = in_f["B"] != toggled[1]
    in_f["D"] = in_f["C"] != toggled[2]
    moves = tuple(j for j in "BCD" if in_f[j])
    return tuple(float(t) for t in target), moves


def _joint_table(m_ab, m_ac, m_ad, n):
    """Fully rotatable joints from the signs (-1, 0, +1) of the four slacks."""
    return {
        "A": m_ab * m_ac >= 0 and m_ad * n >= 0,
        "B": m_ac * m_ad >= 0 and m_ab * n >= 0,
        "C": m_ab * m_ac <= 0 and m_ad * n <= 0,
        "D": m_ac * m_ad <= 0 and m_ab * n <= 0,
    }


def _kind(revolving, ground):
    """Planar vocabulary for a chain with `revolving` joints and the two `ground` joints."""
    if not revolving:
        return "triple-rocker"
    first, second = ground
    if first in revolving and second in revolving:
        return "double-crank"
    if first in revolving:
        return "crank-rocker"
    if second in revolving:
        return "rocker-crank"
    return "double-rocker"


def classify(a, b, c, d, *, tol=1e-12):
    """Classify a spherical four-bar by its fully rotatable joints, with ``d`` as ground.

    Joint A turns fully iff m_ab m_ac >= 0 and m_ad n >= 0, with the planar slacks
    m_ab = (c + d) - (a + b), m_ac = (b + d) - (a + c), m_ad = (b + c) - (a + d) and the
    sphere's sum slack n = 2 pi - (a + b + c + d); B, C, D likewise (the table of
    :ref:`deriv-spherical-types`). For arcs totalling less than 2 pi this is the planar
    Grashof table; arcs above pi/2 are reduced by antipode moves (`antipode_reduction`).

    Parameters
    ----------
    a, b, c, d : float
        Arcs AB (input), BC (coupler), CD (output) and DA (ground), radians in (0, pi).
    tol : float, optional
        Slacks within `tol` (radians) of zero count as zero (change points).

    Returns
    -------
    SphericalType
        Frozen record: ``kind`` (one of "crank-rocker", "rocker-crank", "double-crank",
        "double-rocker", "triple-rocker"), ``grashof`` (s + l <= p + q on the reduced
        arcs), ``change_point``, ``revolving`` (frozenset of "A", "B", "C", "D"),
        ``reduced`` and ``moves`` (from `antipode_reduction`), ``shortest`` and
        ``longest`` (reduced-arc names), ``meeting_angles`` (the input angles among 0 and
        pi where the two branches meet) and ``slacks`` (m_ab, m_ac, m_ad, n).

    Raises
    ------
    ValueError
        If an arc is not in (0, pi), or the linkage cannot be assembled at any input
        angle (a reduced arc at least the sum of the other three).

    Notes
    -----
    The branches meet at theta = 0 iff m_ab m_ac = 0 and at theta = pi iff m_ad n = 0;
    n = 0 is the sphere's own change point, where the linkage folds along a great circle.
    As the arcs shrink, n -> 2 pi and the result becomes `mech.planar.grashof`.

    Examples
    --------
    >>> from mech.spherical._types import classify
    >>> t = classify(0.3, 0.9, 0.7, 1.0)
    >>> t.kind, sorted(t.revolving)
    ('crank-rocker', ['A', 'B'])
    >>> classify(2.5, 2.0, 0.7, 1.0).kind     # total 6.2 < 2 pi: planar words on raw arcs
    'triple-rocker'
    >>> t = classify(2.9, 2.4, 2.3, 2.2)      # total > 2 pi: crank AB once reduced
    >>> t.kind, t.moves, [round(x, 4) for x in t.reduced]
    ('crank-rocker', ('B', 'D'), [0.2416, 0.7416, 0.8416, 0.9416])
    >>> classify(0.4, 0.9, 0.4, 0.9).meeting_angles    # isogram: change points at 0 and pi
    (0.0, 3.141592653589793)
    """
    reduced, moves = antipode_reduction(a, b, c, d)
    tol = real_number("tol", tol)
    if tol < 0:
        raise ValueError(f"Expected `tol` >= 0, got {tol!r}")
    total = sum(reduced)
    for name, x in zip(_LINKS, reduced):
        if x >= total - x:
            raise ValueError(
                f"Expected every arc below the sum of the other three after the antipode "
                f"reduction, got reduced arc `{name}` = {x!r} >= {total - x!r}: "
                f"the linkage cannot be assembled"
            )
    raw = tuple(float(s) for s in spherical_type_slacks(*(float(v) for v in (a, b, c, d))))
    signs = tuple(0 if abs(s) <= tol else int(np.sign(s)) for s in raw)
    revolving = frozenset(j for j, turns in _joint_table(*signs).items() if turns)
    meeting = tuple(angle for angle, product in ((0.0, signs[0] * signs[1]), (np.pi, signs[2] * signs[3]))
                    if product == 0)
    order = np.argsort(reduced, kind="stable")
    return SphericalType(
        kind=_kind(revolving, ("A", "D")),
        grashof=bool(revolving),
        change_point=0 in signs,
        revolving=revolving,
        reduced=reduced,
        moves=moves,
        shortest=_LINKS[int(order[0])],
        longest=_LINKS[int(order[-1])],
        meeting_angles=meeting,
        slacks=raw,
    )


def inversions(a, b, c, d, *, tol=1e-12):
    """The kind of each inversion of a spherical four-bar chain (机构倒置).

    The fully rotatable joints are a property of the chain; fixing another link only
    changes which two joints sit on the ground.

    Parameters
    ----------
    a, b, c, d : float
        Arcs AB, BC, CD, DA of the chain, radians in (0, pi).
    tol : float, optional
        As for `classify`.

    Returns
    -------
    dict
        ``{link: kind}`` for the fixed link "a", "b", "c", "d"; the kind is read with the
        fixed link's two joints in chain order (for "d": A then D, the input at A).

    Raises
    ------
    ValueError
        As for `classify`.

    Notes
    -----
    Derived on :ref:`deriv-spherical-types` (section "Inversions").

    Examples
    --------
    >>> from mech.spherical._types import inversions
    >>> inversions(0.3, 0.9, 0.7, 1.0)          # shortest arc a
    {'a': 'double-crank', 'b': 'rocker-crank', 'c': 'double-rocker', 'd': 'crank-rocker'}
    """
    revolving = classify(a, b, c, d, tol=tol).revolving
    # the ground link's two joints, the first being where the input link (next in the loop) turns
    grounds = {"a": ("B", "A"), "b": ("C", "B"), "c": ("D", "C"), "d": ("A", "D")}
    return {link: _kind(revolving, joints) for link, joints in grounds.items()}
