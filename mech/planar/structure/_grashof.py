"""Grashof classification of the revolute four-bar (textbook section 2.1, eqs. (2-1) to (2-8)).

The derivation page ``derivations/planar/grashof.md`` shows that every rotatability
condition of the chain reads the signs of three slacks, one per way of splitting the four
lengths into two pairs; ``mech._generated.grashof.grashof_margins`` computes them.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from mech._generated.grashof import grashof_margins
from mech._validate import nonnegative_number, option, positive_length, real_array

__all__ = ["GrashofResult", "KindInterval", "grashof", "kind_intervals"]

_LINKS = ("a", "b", "c", "d")


@dataclass(frozen=True)
class GrashofResult:
    """Type of a revolute four-bar with ground ``d``: the result of :func:`~mech.planar.structure.grashof`."""

    grashof: bool
    change_point: bool
    revolving: frozenset
    kind: str
    shortest: str
    longest: str
    margin: float


@dataclass(frozen=True)
class KindInterval:
    """One interval of a varying link length on which the four-bar keeps one ``kind``."""

    low: float
    high: float
    kind: str
    closed_low: bool
    closed_high: bool

    def __contains__(self, x):
        above = x >= self.low if self.closed_low else x > self.low
        below = x <= self.high if self.closed_high else x < self.high
        return bool(above and below)


def _lengths(a, b, c, d):
    values = [positive_length(name, x) for name, x in zip(_LINKS, (a, b, c, d))]
    total = sum(values)
    for k, (name, x) in enumerate(zip(_LINKS, values)):
        rest = math.fsum(values[:k] + values[k + 1:])     # not total - x: 0.0 beside a 1e300
        if x >= rest:
            raise ValueError(
                f"Expected `{name}` < {rest!r}, the sum of the other three links, got {x!r}"
            )
    return values, total


def _signs(margins, tol):
    """Signs (-1, 0, +1) of the slacks, with |slack| <= tol counted as zero."""
    return tuple(int(np.sign(m)) if abs(m) > tol else 0 for m in margins)


def _classify(s_ab, s_ac, s_ad):
    """Fully rotatable joints and kind from the slack signs (the joint table)."""
    joints = {
        "A": s_ad >= 0 and s_ab * s_ac >= 0,
        "B": s_ab >= 0 and s_ac * s_ad >= 0,
        "C": s_ad <= 0 and s_ab * s_ac <= 0,
        "D": s_ab <= 0 and s_ac * s_ad <= 0,
    }
    revolving = frozenset(j for j, turns in joints.items() if turns)
    is_grashof = s_ab * s_ac * s_ad >= 0
    if not is_grashof:
        kind = "triple-rocker"
    elif joints["A"] and joints["D"]:
        kind = "double-crank"
    elif joints["A"]:
        kind = "crank-rocker"
    elif joints["D"]:
        kind = "rocker-crank"
    else:
        kind = "double-rocker"
    return is_grashof, revolving, kind


def grashof(a, b, c, d, *, rtol=1e-12):
    """Classify a revolute four-bar by the Grashof conditions, with ``d`` as the ground.

    A joint is fully rotatable (整转副) when the relative angle of its two links can take
    every value; A joins ``a`` and ``d``, B joins ``a`` and ``b``, C joins ``b`` and
    ``c``, D joins ``c`` and ``d``. The conditions are the reachable-region conditions
    (2-1), (2-5), (2-6) of the textbook for any lengths, and the chain is Grashof when
    s + l <= p + q (shortest, longest and the other two lengths).

    Parameters
    ----------
    a, b, c, d : float
        Lengths of the input link AB, the coupler BC, the output link CD and the ground DA.
    rtol : float, optional
        Slacks within ``rtol * (a + b + c + d)`` of zero count as zero (change points).

    Returns
    -------
    GrashofResult
        Frozen record with ``grashof`` (bool), ``change_point`` (bool, s + l = p + q),
        ``revolving`` (frozenset of the fully rotatable joints), ``kind`` (one of
        "crank-rocker", "rocker-crank", "double-crank", "double-rocker",
        "triple-rocker"), ``shortest`` and ``longest`` (link names, the first in the
        order a, b, c, d on ties) and ``margin`` = (p + q) - (s + l).

    Raises
    ------
    ValueError
        If a length is not finite and > 0, or is at least the sum of the other three.

    Notes
    -----
    Derived on the page ``derivations/planar/grashof.md`` (label ``deriv-grashof``): with
    the slacks m_ab = (c + d) - (a + b), m_ac = (b + d) - (a + c) and m_ad = (b + c) -
    (a + d), joint A turns fully iff m_ad >= 0 and m_ab m_ac >= 0 (and likewise for B, C, D), and the
    chain is Grashof iff m_ab m_ac m_ad >= 0. "rocker-crank" is a crank-rocker driven
    from its rocker: the output link ``c`` is the crank. A change-point chain with two
    pairs of equal links (parallelogram, kite) has three or four fully rotatable joints.

    Examples
    --------
    >>> from mech.planar import grashof
    >>> r = grashof(10, 40, 30, 35)          # Example 2-1: a + b = 50 < c + d = 65
    >>> r.kind, sorted(r.revolving), r.margin
    ('crank-rocker', ['A', 'B'], 15.0)
    >>> grashof(35, 10, 40, 30).kind          # the same chain, shortest link as coupler
    'double-rocker'
    >>> grashof(20, 50, 40, 10).change_point  # U1 with AD = 10: 10 + 50 = 20 + 40
    True
    >>> r = grashof(2, 3, 2, 3)               # parallelogram
    >>> r.kind, sorted(r.revolving)
    ('double-crank', ['A', 'B', 'C', 'D'])
    >>> grashof(20, 50, 40, 80).kind          # 20 + 80 > 50 + 40
    'triple-rocker'
    """
    (a, b, c, d), total = _lengths(a, b, c, d)
    rtol = nonnegative_number("rtol", rtol)
    margins = tuple(float(m) for m in grashof_margins(a, b, c, d))
    signs = _signs(margins, rtol * total)
    is_grashof, revolving, kind = _classify(*signs)
    lengths = (a, b, c, d)
    product_sign = int(np.sign(margins[0]) * np.sign(margins[1]) * np.sign(margins[2]))
    return GrashofResult(
        grashof=bool(is_grashof),
        change_point=0 in signs,
        revolving=revolving,
        kind=kind,
        shortest=_LINKS[int(np.argmin(lengths))],
        longest=_LINKS[int(np.argmax(lengths))],
        margin=float(product_sign * min(abs(m) for m in margins)),
    )


def _fixed_lengths(lengths, vary):
    vary = option("vary", vary, _LINKS)
    others = [name for name in _LINKS if name != vary]
    if isinstance(lengths, Mapping):
        if sorted(lengths) != others:
            raise ValueError(f"Expected `lengths` to have the keys {others}, got {sorted(lengths)}")
        values = [lengths[name] for name in others]
    else:
        values = real_array("lengths", lengths, finite=False)
        if values.shape != (3,):
            raise ValueError(f"Expected 3 fixed lengths in `lengths`, got shape {values.shape}: {lengths!r}")
    out = {}
    for name, x in zip(others, values):
        try:
            out[name] = positive_length(f"lengths[{name!r}]", x)
        except ValueError as exc:      # named as the argument given, `lengths`
            raise ValueError(f"Expected `lengths` with every fixed length finite and > 0: {exc}") from exc
    return out


def kind_intervals(lengths, vary, *, rtol=1e-12):
    """Split the range of one varying link length into intervals of one four-bar kind.

    The other three lengths are fixed and ``d`` is the ground. Every slack of the Grashof
    conditions is linear in the varying length with slope +1 or -1, so the kind changes
    only where a slack vanishes; those change-point lengths are classified as
    :func:`grashof` classifies them.

    Parameters
    ----------
    lengths : sequence of 3 floats, or mapping
        The fixed lengths in the order a, b, c, d with the varying one left out, or a
        mapping from the three fixed link names to their lengths.
    vary : {"a", "b", "c", "d"}
        Name of the varying link ("d" is the ground).
    rtol : float, optional
        Passed to :func:`grashof`; also merges breakpoints closer than ``rtol`` times the
        total length.

    Returns
    -------
    tuple of KindInterval
        Records ``(low, high, kind, closed_low, closed_high)`` in increasing order that
        cover the open interval of lengths for which the chain closes, from
        ``max(0, 2 * max(fixed) - sum(fixed))`` to ``sum(fixed)``, without gaps or
        overlaps. A single change-point length can be an interval of its own.

    Raises
    ------
    ValueError
        If ``vary`` is not a link name or a fixed length is not finite and > 0.

    Notes
    -----
    Derived on the page ``derivations/planar/grashof.md`` (label ``deriv-grashof``); the
    worked sweep U1 of the textbook (its summary §2.1 III has two misprints) is the example below.

    Examples
    --------
    >>> from mech.planar import kind_intervals
    >>> for r in kind_intervals((20, 50, 40), "d"):   # U1: AB=20, BC=50, CD=40
    ...     print(r.kind, r.low, r.high, r.closed_low, r.closed_high)
    double-crank 0.0 10.0 False True
    triple-rocker 10.0 30.0 False False
    crank-rocker 30.0 70.0 True True
    triple-rocker 70.0 110.0 False False
    >>> [r.kind for r in kind_intervals({"b": 50, "c": 35, "d": 30}, "a")]  # exercise 2-2
    ['crank-rocker', 'triple-rocker', 'double-crank', 'triple-rocker']
    """
    fixed = _fixed_lengths(lengths, vary)
    rtol = nonnegative_number("rtol", rtol)
    total_fixed = sum(fixed.values())
    low = max(0.0, 2.0 * max(fixed.values()) - total_fixed)
    high = total_fixed
    if not low < high:      # one fixed length so long that the others vanish in its rounding
        raise ValueError(
            f"Expected `lengths` that leave an interval of `{vary}` for which the four-bar closes "
            f"(from {low!r} to {high!r} in floating point), got lengths={lengths!r}"
        )

    def margins_at(x):
        chain = dict(fixed, **{vary: x})
        return np.array([float(m) for m in grashof_margins(*(chain[n] for n in _LINKS))])

    # m(x) = m(0) + sigma * x with sigma = +1 or -1 (derivation page): each slack has one root
    m0 = margins_at(0.0)
    sigma = np.sign(margins_at(high) - m0)
    tol = rtol * 2.0 * total_fixed
    roots = sorted(float(r) for r in -sigma * m0 if low + tol < r < high - tol)
    breakpoints = []
    for r in roots:
        if not breakpoints or r - breakpoints[-1] > tol:
            breakpoints.append(r)

    def kind_at(x):
        chain = dict(fixed, **{vary: x})
        return grashof(*(chain[n] for n in _LINKS), rtol=rtol).kind

    edges = [low, *breakpoints, high]
    atoms = []  # (low, high, kind, closed_low, closed_high), in order
    for i in range(len(edges) - 1):
        lo, hi = edges[i], edges[i + 1]
        atoms.append((lo, hi, kind_at(0.5 * (lo + hi)), False, False))
        if i + 1 < len(edges) - 1:
            atoms.append((hi, hi, kind_at(hi), True, True))
    merged = [atoms[0]]
    for atom in atoms[1:]:
        last = merged[-1]
        if atom[2] == last[2]:
            merged[-1] = (last[0], atom[1], last[2], last[3], atom[4])
        else:
            merged.append(atom)
    return tuple(KindInterval(float(lo), float(hi), k, cl, ch) for lo, hi, k, cl, ch in merged)
