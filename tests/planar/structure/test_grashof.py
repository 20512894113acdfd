"""Tests of the Grashof classification (textbook section 2.1, eqs. (2-1) to (2-8), Table 2-1).

Expected values come from routes independent of the slack-sign rules of the package: the
textbook's stated rules by sorting the lengths (F13), the corrected textbook numbers (U1,
exercise 2-2), and a brute-force simulation that closes the loop by intersecting circles at
every relative angle of each joint.
"""

import dataclasses
import itertools

import numpy as np
import pytest

from mech.planar import GrashofResult, grashof
from mech.planar.structure._grashof import KindInterval, kind_intervals

KINDS = {"crank-rocker", "rocker-crank", "double-crank", "double-rocker", "triple-rocker"}


def _closes_everywhere(p, q, r_q, r_p, n=720, tol=1e-9):
    """Links p (joint to P on +x) and q (joint to Q at angle t) meet at the joint under
    test; the dyad Q-R-P has lengths r_q, r_p. True when R exists at every t of a grid
    that contains 0 and pi (where |QP| is extreme)."""
    t = 2 * np.pi * np.arange(n) / n
    k2 = np.abs(q * np.exp(1j * t) - p) ** 2
    two_k_h_sq = 4 * k2 * r_q**2 - (k2 + r_q**2 - r_p**2) ** 2
    return bool(np.all(two_k_h_sq >= -tol * (p + q + r_q + r_p) ** 4))


def _simulated_revolving(a, b, c, d):
    joints = {
        "A": _closes_everywhere(d, a, b, c),
        "B": _closes_everywhere(a, b, c, d),
        "C": _closes_everywhere(b, c, d, a),
        "D": _closes_everywhere(c, d, a, b),
    }
    return frozenset(j for j, ok in joints.items() if ok)


def _kind_from_revolving(revolving, is_grashof):
    if not is_grashof:
        return "triple-rocker"
    return {
        (True, True): "double-crank",
        (True, False): "crank-rocker",
        (False, True): "rocker-crank",
        (False, False): "double-rocker",
    }[("A" in revolving, "D" in revolving)]


def _textbook_kind(a, b, c, d):
    """F13 of the textbook, for a chain with a unique shortest link: by sorting."""
    lengths = {"a": a, "b": b, "c": c, "d": d}
    s, p, q, l = sorted(lengths.values())
    if s + l > p + q:
        return "triple-rocker"
    shortest = min(lengths, key=lengths.get)
    return {"d": "double-crank", "a": "crank-rocker", "c": "rocker-crank", "b": "double-rocker"}[
        shortest
    ]


# ----------------------------------------------------------------------------- grashof


@pytest.mark.parametrize(
    "lengths, kind, revolving",
    [
        ((10, 40, 30, 35), "crank-rocker", {"A", "B"}),
        ((30, 40, 10, 35), "rocker-crank", {"C", "D"}),
        ((40, 30, 35, 10), "double-crank", {"A", "D"}),
        ((35, 10, 40, 30), "double-rocker", {"B", "C"}),
        ((20, 50, 40, 80), "triple-rocker", set()),
    ],
)
def test_grashof_kind_each(lengths, kind, revolving):
    r = grashof(*lengths)
    assert isinstance(r, GrashofResult)
    assert r.kind == kind
    assert r.revolving == frozenset(revolving)
    assert r.grashof == (kind != "triple-rocker")
    assert not r.change_point


def test_example_2_1_grashof_crank_rocker():
    """Example 2-1: a = 10, b = 40, c = 30, d = 35; a + b = 50 < c + d = 65, crank-rocker."""
    r = grashof(10, 40, 30, 35)
    assert r.kind == "crank-rocker"
    assert r.shortest == "a" and r.longest == "b"
    assert r.margin == pytest.approx((30 + 35) - (10 + 40))


def test_grashof_kind_inversions_table_2_1():
    """Table 2-1, four-bar column: the four inversions of one Grashof chain."""
    chain = (10, 40, 30, 35)  # loop order AB, BC, CD, DA
    kinds = []
    for ground in range(4):
        a, b, c, d = (chain[(ground + k) % 4] for k in (1, 2, 3, 0))
        kinds.append(grashof(a, b, c, d).kind)
    # ground = 10 (shortest), 40 and 35 (its neighbours), 30 (opposite)
    assert kinds == ["double-crank", "rocker-crank", "double-rocker", "crank-rocker"]


@pytest.mark.parametrize("ground", range(4))
def test_grashof_change_point_parallelogram_any_ground(ground):
    chain = (2.0, 3.0, 2.0, 3.0)
    a, b, c, d = (chain[(ground + k) % 4] for k in (1, 2, 3, 0))
    r = grashof(a, b, c, d)
    assert r.change_point and r.grashof
    assert r.revolving == frozenset("ABCD")
    assert r.kind == "double-crank"


def test_grashof_change_point_rhombus():
    r = grashof(3, 3, 3, 3)
    assert r.change_point and r.revolving == frozenset("ABCD") and r.kind == "double-crank"
    assert r.margin == 0.0


def test_grashof_change_point_kite_ab_short():
    """a = b < c = d: C turns fully, D rocks (F12 case 2); long ground, crank-rocker."""
    r = grashof(2, 2, 5, 5)
    assert r.change_point
    assert r.revolving == frozenset("ABC")
    assert r.kind == "crank-rocker"


def test_grashof_change_point_kite_ad_short():
    """a = d < b = c: D turns fully, C rocks (F12 case 3); short ground, double-crank."""
    r = grashof(2, 5, 5, 2)
    assert r.change_point
    assert r.revolving == frozenset("ABD")
    assert r.kind == "double-crank"


@pytest.mark.parametrize(
    "lengths, kind",
    [((2, 2, 5, 5), "crank-rocker"), ((2, 5, 5, 2), "double-crank"),
     ((5, 5, 2, 2), "double-crank"), ((5, 2, 2, 5), "rocker-crank")],
)
def test_grashof_change_point_kite_by_ground(lengths, kind):
    """F13: a kite is a double-crank on a short ground, a crank-rocker on a long one."""
    r = grashof(*lengths)
    assert r.kind == kind
    assert len(r.revolving) == 3


def test_grashof_change_point_unequal_u1():
    """U1 with AD = 10: 10 + 50 = 20 + 40, no equal pairs; only the shortest link's joints."""
    r = grashof(20, 50, 40, 10)
    assert r.change_point and r.grashof
    assert r.revolving == frozenset("AD")
    assert r.kind == "double-crank"
    assert r.shortest == "d"


def test_grashof_change_point_rtol():
    assert not grashof(20, 50, 40, 10 + 1e-9).change_point
    assert grashof(20, 50, 40, 10 + 1e-9, rtol=1e-9).change_point
    assert grashof(20, 50, 40, 10 * (1 + 1e-15)).change_point
    assert not grashof(20, 50, 40, 10 + 1e-9).grashof


def test_grashof_result_frozen():
    r = grashof(10, 40, 30, 35)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.kind = "double-crank"


def test_grashof_margin_sorted_lengths():
    rng = np.random.default_rng(7)
    for _ in range(300):
        ch = rng.uniform(0.1, 2.0, 4)
        if 2 * ch.max() >= ch.sum():
            continue
        s, p, q, l = np.sort(ch)
        r = grashof(*ch)
        assert r.margin == pytest.approx((p + q) - (s + l), abs=1e-12)
        assert r.grashof == ((p + q) - (s + l) >= 0)


def test_grashof_kind_textbook_rules_random():
    """F13 by sorting the lengths agrees with the package on chains with a unique shortest."""
    rng = np.random.default_rng(11)
    checked = 0
    for _ in range(2000):
        ch = tuple(rng.uniform(0.1, 2.0, 4))
        if 2 * max(ch) >= sum(ch):
            continue
        assert grashof(*ch).kind == _textbook_kind(*ch), ch
        checked += 1
    assert checked > 1000


def _random_chains(n_float, n_int, seed):
    rng = np.random.default_rng(seed)
    chains = [tuple(rng.uniform(0.2, 3.0, 4)) for _ in range(n_float)]
    chains += [tuple(float(x) for x in rng.integers(1, 9, 4)) for _ in range(n_int)]
    return [ch for ch in chains if 2 * max(ch) < sum(ch)]


def test_grashof_revolving_brute_force_simulation():
    """Sweep every joint through a full turn and close the loop; >= 1000 chains, including
    integer chains that sit exactly on change points."""
    chains = _random_chains(700, 700, seed=2024)
    assert len(chains) >= 1000
    n_change = 0
    for ch in chains:
        r = grashof(*ch)
        simulated = _simulated_revolving(*ch)
        assert r.revolving == simulated, ch
        assert r.grashof == bool(simulated), ch
        assert r.kind == _kind_from_revolving(simulated, r.grashof), ch
        n_change += r.change_point
    assert n_change > 50  # the integer chains do exercise the change points


def test_grashof_revolving_exhaustive_small_integers():
    """Every closable integer chain with lengths 1..6 against the simulation."""
    for ch in itertools.product(range(1, 7), repeat=4):
        if 2 * max(ch) >= sum(ch):
            continue
        assert grashof(*ch).revolving == _simulated_revolving(*map(float, ch)), ch


@pytest.mark.parametrize("name, index", [("a", 0), ("b", 1), ("c", 2), ("d", 3)])
@pytest.mark.parametrize("bad", [-1.0, 0.0, np.nan, np.inf])
def test_grashof_bad_length(name, index, bad):
    lengths = [10.0, 40.0, 30.0, 35.0]
    lengths[index] = bad
    with pytest.raises(ValueError, match=f"Expected `{name}`"):
        grashof(*lengths)


def test_grashof_bad_length_message():
    with pytest.raises(ValueError, match=r"Expected `b` > 0, got -1.0"):
        grashof(1.0, -1.0, 1.0, 1.0)


@pytest.mark.parametrize("name, index", [("a", 0), ("b", 1), ("c", 2), ("d", 3)])
def test_grashof_link_too_long(name, index):
    lengths = [1.0, 1.5, 2.0, 2.5]
    lengths[index] = sum(lengths) - lengths[index]  # equal to the other three: no loop
    with pytest.raises(ValueError, match=f"Expected `{name}` < "):
        grashof(*lengths)


def test_grashof_bad_rtol():
    with pytest.raises(ValueError, match="Expected `rtol`"):
        grashof(10, 40, 30, 35, rtol=-1.0)


# ---------------------------------------------------------------------- kind_intervals


def _as_tuples(intervals):
    return [(r.kind, r.low, r.high, r.closed_low, r.closed_high) for r in intervals]


def test_kind_intervals_u1():
    """U1 (§2.1 III, corrected): AB = 20, BC = 50, CD = 40, ground AD varies."""
    got = kind_intervals((20, 50, 40), "d")
    assert all(isinstance(r, KindInterval) for r in got)
    assert _as_tuples(got) == [
        ("double-crank", 0.0, 10.0, False, True),
        ("triple-rocker", 10.0, 30.0, False, False),
        ("crank-rocker", 30.0, 70.0, True, True),
        ("triple-rocker", 70.0, 110.0, False, False),
    ]


def test_kind_intervals_u1_half_millimetre_sweep():
    """An independent recomputation: grashof swept over AD in 0.5 mm steps."""
    intervals = kind_intervals({"a": 20, "b": 50, "c": 40}, "d")
    for ad in np.arange(0.5, 110.0, 0.5):
        inside = [r for r in intervals if ad in r]
        assert len(inside) == 1
        assert inside[0].kind == grashof(20, 50, 40, ad).kind


def test_kind_intervals_exercise_2_2():
    """Exercise 2-2: BC = 50, CD = 35, AD = 30 (ground), AB varies; boundaries included."""
    got = kind_intervals((50, 35, 30), "a")
    assert _as_tuples(got) == [
        ("crank-rocker", 0.0, 15.0, False, True),
        ("triple-rocker", 15.0, 45.0, False, False),
        ("double-crank", 45.0, 55.0, True, True),
        ("triple-rocker", 55.0, 115.0, False, False),
    ]


def test_kind_intervals_isolated_change_point():
    """a = c = 1, b = 3: only the parallelogram d = 3 has a crank."""
    got = kind_intervals((1, 3, 1), "d")
    assert _as_tuples(got) == [
        ("triple-rocker", 1.0, 3.0, False, False),
        ("double-crank", 3.0, 3.0, True, True),
        ("triple-rocker", 3.0, 5.0, False, False),
    ]


@pytest.mark.parametrize("vary", ["a", "b", "c", "d"])
def test_kind_intervals_cover_and_agree(vary):
    rng = np.random.default_rng({"a": 1, "b": 2, "c": 3, "d": 4}[vary])
    for trial in range(40):
        fixed = (rng.integers(1, 9, 3) if trial % 2 else rng.uniform(0.2, 3.0, 3)).astype(float)
        got = kind_intervals(tuple(fixed), vary)
        low = max(0.0, 2 * fixed.max() - fixed.sum())
        assert got[0].low == pytest.approx(low) and not got[0].closed_low
        assert got[-1].high == pytest.approx(fixed.sum()) and not got[-1].closed_high
        for left, right in zip(got, got[1:]):
            assert left.high == right.low
            assert left.closed_high != right.closed_low  # each boundary belongs to one
            assert left.kind != right.kind
            assert all(r.kind in KINDS for r in (left, right))
        names = [n for n in "abcd" if n != vary]

        def kind_at(x):
            chain = dict(zip(names, fixed), **{vary: x})
            return grashof(*(chain[n] for n in "abcd")).kind

        for r in got:
            for x in rng.uniform(r.low, r.high, 5) if r.high > r.low else []:
                if r.low < x < r.high:
                    assert kind_at(x) == r.kind
            if r.closed_low:
                assert kind_at(r.low) == r.kind
            if r.closed_high:
                assert kind_at(r.high) == r.kind


def test_kind_intervals_bad_input():
    with pytest.raises(ValueError, match="Expected `vary`"):
        kind_intervals((1, 2, 3), "e")
    with pytest.raises(ValueError, match=r"Expected `lengths\[.a.\]` > 0"):
        kind_intervals((-1, 2, 3), "d")
    with pytest.raises(ValueError, match=r"Expected `lengths\[.c.\]` > 0"):
        kind_intervals({"a": 1, "b": 2, "c": 0}, "d")
    with pytest.raises(ValueError, match="Expected 3 fixed lengths"):
        kind_intervals((1, 2), "d")
    with pytest.raises(ValueError, match="Expected `lengths` to have the keys"):
        kind_intervals({"a": 1, "b": 2, "d": 3}, "d")


def test_grashof_change_point_decimal_lengths():
    """0.1 + 0.7 and 0.2 + 0.6 differ by one rounding in binary; still a change point."""
    assert (0.1 + 0.7) != (0.2 + 0.6)
    r = grashof(0.1, 0.7, 0.2, 0.6)
    assert r.change_point and r.grashof
    assert r.kind == "crank-rocker"


@pytest.mark.parametrize("scale", [1e-9, 1e-3, 1e3, 1e9])
def test_kind_intervals_scale_invariant(scale):
    base = kind_intervals((20, 50, 40), "d")
    scaled = kind_intervals((20 * scale, 50 * scale, 40 * scale), "d")
    assert [r.kind for r in scaled] == [r.kind for r in base]
    for r, s in zip(base, scaled):
        assert (s.closed_low, s.closed_high) == (r.closed_low, r.closed_high)
        assert s.low == pytest.approx(r.low * scale, rel=1e-12)
        assert s.high == pytest.approx(r.high * scale, rel=1e-12)


def test_fig_2_6_revolving_joints_by_the_diagonal_ranges():
    """Fig. 2-6: the joints `grashof` counts fully rotatable, for the figure's three chains,
    against the reachable-region test done directly: the joint between links x and y turns
    fully when the diagonal across it, which ranges over [|x - y|, x + y] as the joint
    turns, always fits the other two links u, v: |u - v| <= |x - y| and x + y <= u + v."""
    from mech.planar import grashof

    expected = {(10, 40, 30, 35): {"A", "B"}, (20, 40, 20, 40): {"A", "B", "C", "D"},
                (30, 45, 35, 25): set()}
    for (a, b, c, d), text in expected.items():
        sides = {"A": ((a, d), (b, c)), "B": ((a, b), (c, d)), "C": ((b, c), (a, d)), "D": ((c, d), (a, b))}
        direct = {j for j, ((x, y), (u, v)) in sides.items() if abs(u - v) <= abs(x - y) and x + y <= u + v}
        assert direct == text
        assert set(grashof(a, b, c, d).revolving) == text
