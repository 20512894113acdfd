"""Exercises of chapter 2 (planar linkages), stated as data and solved.

Each solver uses only public functions of :mod:`mech.planar`; the statements are written
anew in English with the textbook's numbers as defaults. Lengths are in millimetres,
angles in radians (the rendered solutions show degrees too).

Notes
-----
The theory behind the solvers is derived on the pages ``deriv-grashof`` (2-2 and part 2
of 2-3), ``deriv-fourbar-limit-positions`` and ``deriv-transmission-angle`` (part 1 of
2-3) and ``deriv-slider-crank`` (2-6); the solutions are shown on the book page
``book-exercises``. Exercises 2-4, 2-5, 2-7 and 2-10 (tag "A": their figures are lost)
are solved on an assumed layout, stated first in each solution, by the general solver
`mech.planar.Linkage` over a full crank turn and, for 2-10, by instant centres; they are
shown on ``book-analysis-exercises``; they live in :mod:`mech.exercises.chapter2_analysis`
and are collected here. The force exercises 2-19, 2-20, 2-21, 2-23 and 2-24 live in
:mod:`mech.exercises.chapter2_forces` (page ``book-forces-exercises``) and 2-22 in
:mod:`mech.exercises.chapter2_reactions` (page ``book-forces-static-forces``). The synthesis
exercises 2-27 (page ``synthesis-guidance``), 2-28 and 2-29
(:mod:`mech.exercises.chapter2_synthesis`, page ``book-synthesis-function-generation``)
and 2-30 to 2-32
(:mod:`mech.exercises.chapter2_quick_return`, page ``book-synthesis-quick-return``)
are collected here too, and so are 2-12 to 2-16 (velocity and acceleration on
assumed layouts, :mod:`mech.exercises.chapter2_relative_motion`, page
``book-analysis-exercises``), and 2-17, 2-18, 2-25 and 2-26 (reactions in the pairs, with 2-22 in the same module,
:mod:`mech.exercises.chapter2_reactions`, page ``book-forces-static-forces``), and the instant-centre
exercises 2-8, 2-9 and 2-11 (:mod:`mech.exercises.chapter2_instant_centres`, page
``book-analysis-exercises``). Each solver states its conventions in its solution.

Examples
--------
>>> from mech.exercises import chapter2
>>> [ex.number for ex in chapter2.EXERCISES]
['2-1', '2-2', '2-3', '2-4', '2-5', '2-6', '2-7', '2-8', '2-9', '2-10', '2-11', '2-12', '2-13', '2-14', '2-15', '2-16', '2-17', '2-18', '2-19', '2-20', '2-21', '2-22', '2-23', '2-24', '2-25', '2-26', '2-27', '2-28', '2-29', '2-30', '2-31', '2-32']
>>> s = chapter2.EXERCISE_2_2.solve()
>>> [str(iv) for iv in s["AB for a double-rocker"].value]
['(15, 45)', '(55, 115)']
>>> s = chapter2.EXERCISE_2_3.solve()
>>> s["type with AB as the frame"].value
'a double-crank: AD and BC both turn fully'
"""

from __future__ import annotations

import math


from mech._errors import InputTypeError
from mech._validate import instance, positive_length
from mech.exercises._core import Exercise, Interval, Parameter, Part, Result, Solution, check_links_close
from mech.planar import FourBar, GuideBar, SliderCrank, grashof
from mech.planar.structure import _grashof
from mech.exercises.chapter2_analysis import EXERCISE_2_4, EXERCISE_2_5, EXERCISE_2_7, EXERCISE_2_10
from mech.exercises.chapter2_forces import EXERCISE_2_19, EXERCISE_2_20, EXERCISE_2_21, EXERCISE_2_23, EXERCISE_2_24
from mech.exercises.chapter2_instant_centres import EXERCISE_2_8, EXERCISE_2_9, EXERCISE_2_11
from mech.exercises.chapter2_reactions import EXERCISE_2_17, EXERCISE_2_18, EXERCISE_2_22, EXERCISE_2_25, EXERCISE_2_26
from mech.exercises.chapter2_relative_motion import (EXERCISE_2_12, EXERCISE_2_13, EXERCISE_2_14, EXERCISE_2_15,
                                                     EXERCISE_2_16)
from mech.exercises.chapter2_synthesis import EXERCISE_2_27, EXERCISE_2_28, EXERCISE_2_29
from mech.exercises.chapter2_quick_return import EXERCISE_2_30, EXERCISE_2_31, EXERCISE_2_32

__all__ = [
    "EXERCISE_2_1",
    "EXERCISE_2_2",
    "EXERCISE_2_3",
    "EXERCISE_2_4",
    "EXERCISE_2_5",
    "EXERCISE_2_6",
    "EXERCISE_2_7",
    "EXERCISE_2_8",
    "EXERCISE_2_9",
    "EXERCISE_2_10",
    "EXERCISE_2_11",
    "EXERCISE_2_12",
    "EXERCISE_2_13",
    "EXERCISE_2_14",
    "EXERCISE_2_15",
    "EXERCISE_2_16",
    "EXERCISE_2_17",
    "EXERCISE_2_18",
    "EXERCISE_2_19",
    "EXERCISE_2_20",
    "EXERCISE_2_21",
    "EXERCISE_2_22",
    "EXERCISE_2_23",
    "EXERCISE_2_24",
    "EXERCISE_2_25",
    "EXERCISE_2_26",
    "EXERCISE_2_27",
    "EXERCISE_2_28",
    "EXERCISE_2_29",
    "EXERCISE_2_30",
    "EXERCISE_2_31",
    "EXERCISE_2_32",
    "EXERCISES",
    "merge_intervals",
]

_DEG = math.pi / 180.0


def merge_intervals(intervals):
    """Sort intervals and join those that touch, e.g. ``(0, 1] ∪ (1, 2)`` into ``(0, 2)``."""
    if isinstance(intervals, (str, bytes)) or not hasattr(intervals, "__iter__"):
        raise InputTypeError(f"Expected `intervals` to be a sequence of Interval, got {intervals!r}")
    intervals = [instance(f"intervals[{k}]", iv, Interval) for k, iv in enumerate(intervals)]
    merged = []
    for iv in sorted(intervals, key=lambda v: (v.low, not v.closed_low)):
        if merged:
            last = merged[-1]
            touches = iv.low < last.high or (
                iv.low == last.high and (iv.closed_low or last.closed_high)
            )
            if touches:
                high, closed = (last.high, last.closed_high)
                if iv.high > high or (iv.high == high and iv.closed_high):
                    high, closed = iv.high, iv.closed_high
                merged[-1] = Interval(last.low, high, last.closed_low, closed)
                continue
        merged.append(iv)
    return tuple(merged)


# ----------------------------------------------------------------------------- 2-2
_STATEMENT_2_2 = (
    "A hinged four-bar ABCD (铰链四杆机构) has BC = {BC} mm, CD = {CD} mm and AD = {AD} mm, "
    "and AD is the fixed link (机架). Find every length of AB for which the linkage is "
    "(1) a crank-rocker (曲柄摇杆机构) in which AB is the crank; (2) a double-crank "
    "(双曲柄机构); (3) a double-rocker (双摇杆机构)."
)


def _solve_2_2(p):
    b = positive_length("BC", p["BC"])
    c = positive_length("CD", p["CD"])
    d = positive_length("AD", p["AD"])
    for name, x, rest in (("BC", b, c + d), ("CD", c, b + d), ("AD", d, b + c)):
        if x >= rest:
            raise ValueError(
                f"Expected `{name}` < the sum of the other two given links ({rest:g}), "
                f"got {x!r}: then no AB can close the loop and leave a crank-rocker range"
            )
    records = _grashof.kind_intervals((b, c, d), "a")
    by_kind = {}
    for rec in records:
        iv = Interval(rec.low, rec.high, rec.closed_low, rec.closed_high)
        by_kind.setdefault(rec.kind, []).append(iv)
    how = "`kind_intervals((BC, CD, AD), 'a')`, i.e. `grashof` as AB varies"
    crank_rocker = merge_intervals(by_kind.get("crank-rocker", ()))
    double_crank = merge_intervals(by_kind.get("double-crank", ()))
    grashof_dr = merge_intervals(by_kind.get("double-rocker", ()))
    triple = merge_intervals(by_kind.get("triple-rocker", ()))
    rocker_crank = merge_intervals(by_kind.get("rocker-crank", ()))
    both = merge_intervals(grashof_dr + triple)
    total = b + c + d

    conventions = (
        "Grashof condition: with s the shortest and l the longest of the four links, a link "
        "can turn fully only if s + l ≤ p + q (p, q the other two); the joints that turn "
        "fully are the two ends of the shortest link.",
        "Boundary convention (the text does not say): when s + l = p + q exactly, the "
        "linkage is a change-point linkage. Like `grashof`, this solution counts it as "
        "Grashof, so such end points belong to the crank-rocker or double-crank range "
        "(closed brackets). At those lengths all four links can line up and the motion is "
        "indeterminate there, so a designer would keep away from them.",
        f"AB must be shorter than BC + CD + AD = {total:g} mm, or the loop cannot close.",
        "'Double-rocker' in part (3) means any linkage with neither side link turning "
        "fully: the Grashof double-rocker (the coupler is the shortest link) and the "
        "non-Grashof triple-rocker (no link turns fully) both count.",
    )
    parts = [
        Part(
            "(1) Crank-rocker with AB as the crank",
            (Result("AB for a crank-rocker", crank_rocker, "mm", how),),
            _remarks_2_2_crank(b, c, d),
        ),
        Part(
            "(2) Double-crank",
            (Result("AB for a double-crank", double_crank, "mm", how),),
            _remarks_2_2_double_crank(b, c, d),
        ),
        Part(
            "(3) Double-rocker",
            (
                Result("AB for a double-rocker", both, "mm", how),
                Result("of which Grashof double-rocker", grashof_dr, "mm", how),
                Result("of which triple-rocker", triple, "mm", how),
            ),
            (
                "Every other AB in (0, "
                f"{total:g}) mm gives a linkage in which neither AB nor CD turns fully. "
                + (
                    "No Grashof double-rocker occurs: that would need the coupler BC to be "
                    "the shortest link."
                    if not grashof_dr
                    else "Part of the range is a Grashof double-rocker (the coupler BC is "
                    "the shortest link and turns fully relative to both side links)."
                ),
            ),
        ),
    ]
    if rocker_crank:
        parts.append(
            Part(
                "Also: CD is the crank (rocker-crank)",
                (Result("AB for a rocker-crank", rocker_crank, "mm", how),),
            )
        )
    return Solution("2-2", EXERCISE_2_2.title, dict(p), conventions, tuple(parts))


def _remarks_2_2_crank(b, c, d):
    longest = max(b, c, d)
    others = b + c + d - longest
    shortest = min(b, c, d)
    bound = others - longest
    return (
        "AB must be the shortest link: then A and B are the joints that turn fully and, "
        "with AD fixed, AB is the crank. The longest link is then the longest given one, "
        f"{longest:g} mm, and the Grashof condition AB + {longest:g} ≤ {others:g} gives "
        f"AB ≤ {bound:g} mm"
        + (f"; with AB ≤ {shortest:g} mm (shortest) this leaves AB ≤ {min(bound, shortest):g} mm."
           if bound > shortest else "."),
    )


def _remarks_2_2_double_crank(b, c, d):
    if not d < min(b, c):
        return ("A double-crank needs the frame AD to be the shortest link.",)
    lo = d + max(b, c) - min(b, c)
    hi = b + c - d
    return (
        "The frame AD must be the shortest link, so AB ≥ AD. "
        f"If AB ≤ {max(b, c):g} mm the longest link is {max(b, c):g} mm and "
        f"{d:g} + {max(b, c):g} ≤ AB + {min(b, c):g} gives AB ≥ {lo:g} mm; "
        f"if AB ≥ {max(b, c):g} mm, AB is the longest and {d:g} + AB ≤ {b:g} + {c:g} "
        f"gives AB ≤ {hi:g} mm.",
    )


def _sample_2_2(rng):
    d = int(rng.integers(20, 41))
    c = d + int(rng.integers(3, 21))
    b = int(rng.integers(c - 5, c + d - 4))
    b = max(b, d + 3)
    return {"BC": b, "CD": c, "AD": d}


# ----------------------------------------------------------------------------- 2-3
_STATEMENT_2_3 = (
    "A hinged four-bar has AB = {AB} mm, BC = {BC} mm, CD = {CD} mm and AD = {AD} mm. "
    "(1) With AD as the frame, find the extreme-position angle θ (极位夹角, the crank angle "
    "between the two limit positions), the time ratio K (行程时间比系数), the largest swing "
    "φ of CD and the minimum transmission angle γ_min. (2) With AB as the frame instead, "
    "what kind of linkage is it, and why? Are the revolute joints C and D full-rotation "
    "joints (整转副) or oscillating joints (摇转副)?"
)

# Relabelling for part (2): the linkage with AB as the frame, read as A'B'C'D' with
# A' = A, B' = D, C' = C, D' = B: input a' = AD, coupler b' = DC, output c' = CB, frame
# d' = BA. New joint name -> textbook joint name.
_FRAME_AB = {"A": "A", "B": "D", "C": "C", "D": "B"}

_KIND_TEXT_AB_FRAME = {
    "crank-rocker": "a crank-rocker: AD turns fully, BC rocks",
    "rocker-crank": "a crank-rocker: BC turns fully, AD rocks",
    "double-crank": "a double-crank: AD and BC both turn fully",
    "double-rocker": "a double-rocker (Grashof): neither AD nor BC turns fully",
    "triple-rocker": "a triple-rocker: no link turns fully",
}


def _solve_2_3(p):
    a = positive_length("AB", p["AB"])
    b = positive_length("BC", p["BC"])
    c = positive_length("CD", p["CD"])
    d = positive_length("AD", p["AD"])
    check_links_close(AB=a, BC=b, CD=c, AD=d, resolved=True)
    g = grashof(a, b, c, d)
    if g.kind != "crank-rocker":
        raise ValueError(
            f"Expected a crank-rocker with AD as the frame from `AB`, `BC`, `CD` and `AD`, got a {g.kind} "
            f"(AB={a!r}, BC={b!r}, CD={c!r}, AD={d!r})"
        )
    linkage = FourBar(a, b, c, d)
    lp = linkage.limit_positions()
    gamma_min, theta_at = linkage.min_transmission_angle()
    how_lp = "`FourBar(AB, BC, CD, AD).limit_positions()`"
    how_g = "`FourBar(AB, BC, CD, AD).min_transmission_angle()`"
    part1 = Part(
        "(1) AD is the frame",
        (
            Result("type", g.kind, "", "`grashof(AB, BC, CD, AD).kind`"),
            Result("extreme-position angle θ", lp.extreme_angle, "rad", how_lp),
            Result("time ratio K", lp.time_ratio, "", how_lp + ", K = (180° + θ)/(180° − θ)"),
            Result("swing φ of CD", abs(lp.swing), "rad", how_lp + " (its size)"),
            Result("minimum transmission angle γ_min", gamma_min, "rad", how_g),
            Result("crank angle at γ_min", theta_at, "rad", how_g),
        ),
        (
            f"AB = {a:g} mm is the shortest link and {a:g} + {max(b, c, d):g} ≤ "
            f"{b + c + d - max(b, c, d):g} (Grashof), so with AD as the frame AB is a "
            "crank and CD a rocker.",
            "The rocker stops where crank and coupler line up: stretched out "
            f"(AC = BC + AB = {b + a:g} mm) and folded (AC = BC − AB = {b - a:g} mm). θ is "
            "the angle between the two crank positions there, K follows from (2-9), and the "
            "swing is the angle DC turns between the two positions.",
            "By (2-30) the angle BCD is smallest at θ = 0 and largest at θ = 180° (crank "
            "along the frame); γ_min is the smaller of δ_min and 180° − δ_max.",
        ),
    )
    g2 = grashof(d, c, b, a)
    revolving = frozenset(_FRAME_AB[j] for j in g2.revolving)
    joint = {j: ("full-rotation joint (整转副)" if j in revolving else "oscillating joint (摇转副)")
             for j in "CD"}
    part2 = Part(
        "(2) AB is the frame",
        (
            Result("type with AB as the frame", _KIND_TEXT_AB_FRAME[g2.kind], "",
                   "`grashof(AD, DC, CB, BA)`: the linkage relabelled with AB as the frame"),
            Result("joints that turn fully", revolving, "", "`.revolving`, names mapped back"),
            Result("joint C", joint["C"], "", ""),
            Result("joint D", joint["D"], "", ""),
        ),
        (
            "To reuse the convention that the fourth link is the frame, read the loop "
            "starting at A the other way round: A' = A, B' = D, C' = C, D' = B. Then the "
            "input link is a' = AD, the coupler b' = DC, the output c' = CB and the frame "
            "d' = BA, and a joint named A', B', C', D' in the result is the textbook's A, D, "
            "C, B.",
            "Why: whether a joint turns fully depends only on the link lengths, not on which "
            f"link is fixed. The chain satisfies the Grashof condition with AB = {a:g} mm the "
            "shortest link, so exactly the two joints at the ends of AB (A and B) turn "
            "fully. Fixing AB therefore lets both links hinged to the frame (AD at A, BC at "
            "B) turn fully: a double-crank (双曲柄机构). C and D, away from the shortest "
            "link, stay oscillating joints (摇转副) whichever link is fixed.",
        ),
    )
    return Solution("2-3", EXERCISE_2_3.title, dict(p), (), (part1, part2))


def _sample_2_3(rng):
    while True:
        a = int(rng.integers(15, 36))
        b, c, d = (int(x) for x in rng.integers(a + 6, a + 61, size=3))
        if a + max(b, c, d) <= b + c + d - max(b, c, d) - 3:
            return {"AB": a, "BC": b, "CD": c, "AD": d}


# ----------------------------------------------------------------------------- 2-6
_STATEMENT_2_6 = (
    "An offset slider-crank (偏置曲柄滑块机构) has crank r, connecting rod l and offset e "
    "(the textbook keeps them symbolic; here r = {r} mm, l = {l} mm, e = {e} mm). "
    "(1) With the crank driving, give an expression for the transmission angle γ and say "
    "how r, l and e affect it. (2) In which position does the minimum transmission angle "
    "occur? (3) For e = 0 (a centric slider-crank, 对心曲柄滑块机构), where is γ largest and "
    "where smallest, and how does the stroke H compare with the offset linkage?"
)


def _solve_2_6(p):
    r = positive_length("r", p["r"])
    length = positive_length("l", p["l"])
    e = float(p["e"])
    if not math.isfinite(e) or e < 0.0:
        raise ValueError(f"Expected `e` >= 0 (the side of the offset is fixed by the convention), got {e!r}")
    if r + e >= length:
        raise ValueError(
            f"Expected `r` + `e` < `l` so that the crank turns fully, got r + e = {r + e!r} "
            f">= l = {length!r}"
        )
    sc = SliderCrank(r, length, e)
    sc0 = SliderCrank(r, length, 0.0)
    gamma_min, theta_min = sc.min_transmission_angle()
    # largest gamma: 90 deg where B lies on the guide line (r sin theta = e), else at 90 deg
    theta_max = math.asin(min(e / r, 1.0))
    gamma_max = float(sc.transmission_angle(theta_max))
    gamma0_min, theta0_min = sc0.min_transmission_angle()
    gamma0_max = float(sc0.transmission_angle(0.0))
    stroke, stroke0 = sc.stroke(), sc0.stroke()
    how_t = "`SliderCrank(r, l, e).transmission_angle(θ)`"
    how_m = "`SliderCrank(r, l, e).min_transmission_angle()`"
    conventions = (
        "Crank pivot A at the origin, crank angle θ from the +x axis, counter-clockwise; "
        "the slider pin C moves on the line y = e (e ≥ 0), parallel to the x axis, to the "
        "right of B.",
        "Transmission angle γ: the acute angle between the rod BC and the normal to the "
        "guide (the slider's path), so that γ = 90° − α with α the pressure angle.",
        "The textbook keeps r, l, e symbolic; the numbers only illustrate the formulas.",
    )
    part1 = Part(
        "(1) The transmission angle",
        (
            Result("transmission angle", None, "", "the height of B above the guide line "
                   "is r sin θ − e, and the rod spans it", latex=r"\cos\gamma = \frac{|r\sin\theta - e|}{l}"),
            Result("range of γ: smallest", gamma_min, "rad", how_m),
            Result("range of γ: largest", gamma_max, "rad", how_t),
        ),
        (
            r"Over a turn $|r\sin\theta - e|$ runs up to $r + e$, so "
            r"$\gamma_{\min} = \arccos\frac{r + e}{l}$. A longer crank $r$ or a larger offset "
            r"$e$ lowers $\gamma_{\min}$; a longer rod $l$ raises it. The crank turns fully "
            r"only if $r + e < l$ (at $r + e = l$ the rod is perpendicular to the guide and "
            r"$\gamma_{\min} = 0$).",
        ),
    )
    part2 = Part(
        "(2) Where γ_min occurs",
        (
            Result("γ_min", gamma_min, "rad", how_m, latex=r"\gamma_{\min} = \arccos\frac{r+e}{l}"),
            Result("crank angle at γ_min", theta_min, "rad", how_m),
        ),
        (
            "γ is smallest when the crank is perpendicular to the guide and points away from "
            r"the side of the offset ($\theta = -90°$ with this convention): the crank pin is "
            "then farthest from the slider's line.",
        ),
    )
    part3 = Part(
        "(3) The centric slider-crank (e = 0)",
        (
            Result("largest γ (at θ = 0° and 180°)", gamma0_max, "rad",
                   "`SliderCrank(r, l, 0).transmission_angle(0)`"),
            Result("smallest γ (at θ = ±90°)", gamma0_min, "rad",
                   "`SliderCrank(r, l, 0).min_transmission_angle()`", latex=r"\arccos\frac{r}{l}"),
            Result("stroke, centric", stroke0, "mm", "`SliderCrank(r, l, 0).stroke()`", latex="H_0 = 2r"),
            Result("stroke, offset", stroke, "mm", "`SliderCrank(r, l, e).stroke()`",
                   latex=r"H = \sqrt{(l+r)^2 - e^2} - \sqrt{(l-r)^2 - e^2}"),
            Result("extreme-position angle, offset", sc.extreme_angle(), "rad",
                   "`SliderCrank(r, l, e).extreme_angle()`"),
            Result("time ratio K, offset", sc.time_ratio(), "", "`SliderCrank(r, l, e).time_ratio()`"),
        ),
        (
            "With e = 0, γ = 90° in the two limit (dead-centre) positions of the slider, where "
            "crank and rod both lie along the guide and the rod pushes the slider straight "
            "along its path (pressure angle 0). γ is smallest, "
            r"$\arccos(r/l)$, at both positions where the crank is perpendicular to the guide; "
            "the two are equal by symmetry.",
            r"The stroke is the distance between the slider's extreme positions, where crank "
            r"and rod line up: $H = f(l + r) - f(l - r)$ with $f(s) = \sqrt{s^2 - e^2}$. "
            r"Since $f'(s) = s/\sqrt{s^2 - e^2} > 1$ for $e \neq 0$, $H > 2r$: the offset "
            r"lengthens the stroke (and brings a quick return, $K > 1$), while the centric "
            r"linkage has $H = 2r$ and $K = 1$; the price is a smaller $\gamma_{\min}$.",
        ),
    )
    return Solution("2-6", EXERCISE_2_6.title, dict(p), conventions, (part1, part2, part3))


def _sample_2_6(rng):
    r = int(rng.integers(10, 51))
    e = int(rng.integers(1, max(2, int(0.8 * r))))
    low = int(math.ceil(r + e + 0.3 * r))
    length = int(rng.integers(low, max(low + 1, 5 * r)))
    return {"r": r, "l": length, "e": e}


# ----------------------------------------------------------------------------- 2-1
_STATEMENT_2_1 = (
    "Draw the kinematic (skeleton) diagram of each mechanism of figure 2-1 and say what kind of "
    "mechanism each one is. (The figure is lost; three common mechanisms are assumed: (a) a hinged "
    "four-bar with AB = {a} mm, BC = {b} mm, CD = {c} mm and frame AD = {d} mm; (b) a slider-crank "
    "with crank {r} mm, rod {l} mm and offset {e} mm; (c) a guide-bar with crank {g} mm and frame "
    "{h} mm.)"
)


def _solve_2_1(p):
    a, b, c, d, r, length, g, h = (positive_length(n, p[n]) for n in ("a", "b", "c", "d", "r", "l", "g", "h"))
    e = float(p["e"])
    if not math.isfinite(e):
        raise ValueError(f"Expected a finite offset `e`, got {e!r}")
    check_links_close(a=a, b=b, c=c, d=d)
    if r + abs(e) >= length:
        raise ValueError(f"Expected `r` + |`e`| < `l` = {length!r} so that the crank of (b) turns fully, got {r + abs(e)!r}")
    if g == h:
        raise ValueError(f"Expected `g` != `h` (a guide-bar with crank = frame is a special case), got {g!r}")
    how_f = "F = 3n − 2P_L − P_H (n moving links, P_L lower pairs, P_H higher pairs)"
    parts = []
    kind = grashof(a, b, c, d)
    parts.append(Part("(a) the hinged four-bar ABCD", (
        Result("(a) moving links n", 3.0, "", "crank AB, coupler BC, rocker CD"),
        Result("(a) lower pairs P_L", 4.0, "", "revolute pairs A, B, C, D"),
        Result("(a) degrees of freedom F", 3.0 * 3 - 2 * 4, "", how_f),
        Result("(a) type", kind.kind, "", "`grashof(AB, BC, CD, AD).kind`"),
        Result("(a) joints that turn fully", kind.revolving, "", "`grashof(...).revolving`"),
    ), ("Skeleton: the frame AD drawn with two fixed-pivot symbols, and the three moving links as "
        "lines between the revolute pairs.",)))
    sc = SliderCrank(r, length, e)
    parts.append(Part("(b) the slider-crank", (
        Result("(b) moving links n", 3.0, "", "crank, connecting rod, slider"),
        Result("(b) lower pairs P_L", 4.0, "", "three revolute pairs and one sliding pair"),
        Result("(b) degrees of freedom F", 3.0 * 3 - 2 * 4, "", how_f),
        Result("(b) type", "offset slider-crank (偏置曲柄滑块机构)" if e else "centric slider-crank (对心曲柄滑块机构)",
               "", "the crank turns fully since r + |e| < l"),
        Result("(b) stroke H", sc.stroke(), "mm", "`SliderCrank(r, l, e).stroke()`"),
        Result("(b) time ratio K", sc.time_ratio(), "", "`SliderCrank(r, l, e).time_ratio()`"),
    ), ("Skeleton: the crank and the rod as lines, the slider as a small rectangle on a hatched guide "
        "line.",)))
    if g < h:
        gb = GuideBar(g, h)
        rows = (Result("(c) type", "oscillating guide-bar (摆动导杆机构)", "", "crank shorter than the frame: the bar swings"),
                Result("(c) swing of the guide bar", gb.swing(), "rad", "`GuideBar(crank, frame).swing()`"),
                Result("(c) time ratio K", gb.time_ratio(), "", "`GuideBar(crank, frame).time_ratio()`"))
    else:
        rows = (Result("(c) type", "rotating guide-bar (转动导杆机构)", "",
                       "crank longer than the frame: the bar turns fully"),)
    parts.append(Part("(c) the guide-bar", (
        Result("(c) moving links n", 3.0, "", "crank, block, guide bar"),
        Result("(c) lower pairs P_L", 4.0, "", "three revolute pairs and one sliding pair"),
        Result("(c) degrees of freedom F", 3.0 * 3 - 2 * 4, "", how_f),
    ) + rows, ("Skeleton: the crank, the block on it as a small rectangle, and the slotted bar through the "
               "block, pivoted on the frame.",)))
    assumptions = (
        "The figure of exercise 2-1 is lost: its mechanisms, members and proportions are unknown. Three "
        "mechanisms that such figures usually show are taken instead: (a) a hinged four-bar (as in a "
        "sewing-machine treadle or a windscreen wiper), (b) a slider-crank (as in a piston pump), (c) a "
        "guide-bar (as in a shaper); the lengths are illustrative.",
        "Each has one input (the crank); the frame is the fixed link.",
    )
    return Solution("2-1", EXERCISE_2_1.title, dict(p), (), tuple(parts), assumptions=assumptions)


def _sample_2_1(rng):
    a = int(rng.integers(15, 40))
    return {"a": a, "b": int(rng.integers(a + 20, a + 60)), "c": int(rng.integers(a + 15, a + 50)),
            "d": int(rng.integers(a + 25, a + 60)), "r": int(rng.integers(15, 40)), "l": int(rng.integers(90, 150)),
            "e": int(rng.integers(0, 20)), "g": int(rng.integers(20, 60)), "h": int(rng.integers(30, 90))}


# ----------------------------------------------------------------------------- registry
EXERCISE_2_1 = Exercise(
    number="2-1",
    title="Kinematic diagrams, degrees of freedom and types of three mechanisms",
    tag="G",
    statement=_STATEMENT_2_1,
    parameters=(
        Parameter("a", 25.0, "mm", "assumed crank of (a)"), Parameter("b", 60.0, "mm", "assumed coupler of (a)"),
        Parameter("c", 50.0, "mm", "assumed rocker of (a)"), Parameter("d", 70.0, "mm", "assumed frame of (a)"),
        Parameter("r", 30.0, "mm", "assumed crank of (b)"), Parameter("l", 100.0, "mm", "assumed rod of (b)"),
        Parameter("e", 0.0, "mm", "assumed offset of (b)"), Parameter("g", 40.0, "mm", "assumed crank of (c)"),
        Parameter("h", 80.0, "mm", "assumed frame of (c)"),
    ),
    solver=_solve_2_1,
    sampler=_sample_2_1,
)

EXERCISE_2_2 = Exercise(
    number="2-2",
    title="Ranges of the crank length for each type of four-bar",
    tag="N",
    statement=_STATEMENT_2_2,
    parameters=(
        Parameter("BC", 50.0, "mm", "coupler"),
        Parameter("CD", 35.0, "mm", "side link at D"),
        Parameter("AD", 30.0, "mm", "frame"),
    ),
    solver=_solve_2_2,
    sampler=_sample_2_2,
)

EXERCISE_2_3 = Exercise(
    number="2-3",
    title="Quick return, swing and transmission angle; the inversion with AB as frame",
    tag="N",
    statement=_STATEMENT_2_3,
    parameters=(
        Parameter("AB", 28.0, "mm", "crank"),
        Parameter("BC", 52.0, "mm", "coupler"),
        Parameter("CD", 50.0, "mm", "rocker"),
        Parameter("AD", 72.0, "mm", "frame"),
    ),
    solver=_solve_2_3,
    sampler=_sample_2_3,
)

EXERCISE_2_6 = Exercise(
    number="2-6",
    title="Transmission angle and stroke of the offset slider-crank",
    tag="N",
    statement=_STATEMENT_2_6,
    parameters=(
        Parameter("r", 30.0, "mm", "crank (illustrative; symbolic in the text)"),
        Parameter("l", 100.0, "mm", "connecting rod (illustrative)"),
        Parameter("e", 20.0, "mm", "offset (illustrative)"),
    ),
    solver=_solve_2_6,
    sampler=_sample_2_6,
)

EXERCISES = (EXERCISE_2_1, EXERCISE_2_2, EXERCISE_2_3, EXERCISE_2_4, EXERCISE_2_5, EXERCISE_2_6, EXERCISE_2_7, EXERCISE_2_8,
             EXERCISE_2_9, EXERCISE_2_10, EXERCISE_2_11, EXERCISE_2_12, EXERCISE_2_13, EXERCISE_2_14,
             EXERCISE_2_15, EXERCISE_2_16, EXERCISE_2_17, EXERCISE_2_18, EXERCISE_2_19, EXERCISE_2_20,
             EXERCISE_2_21, EXERCISE_2_22, EXERCISE_2_23, EXERCISE_2_24, EXERCISE_2_25, EXERCISE_2_26, EXERCISE_2_27,
             EXERCISE_2_28, EXERCISE_2_29, EXERCISE_2_30, EXERCISE_2_31, EXERCISE_2_32)
