"""Exercises 2-2 to 2-7 and 2-10 of chapter 2 (planar linkages), stated as data and solved.

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
shown on ``book-analysis-exercises``. ``linkage_2_4`` and the like return the assumed
linkage, for figures and checks. Each solver states its conventions in its solution.

Examples
--------
>>> from mech.exercises import chapter2
>>> [ex.number for ex in chapter2.EXERCISES]
['2-2', '2-3', '2-4', '2-5', '2-6', '2-7', '2-10']
>>> s = chapter2.EXERCISE_2_2.solve()
>>> [str(iv) for iv in s["AB for a double-rocker"].value]
['(15, 45)', '(55, 115)']
>>> s = chapter2.EXERCISE_2_3.solve()
>>> s["type with AB as the frame"].value
'a double-crank: AD and BC both turn fully'
>>> round(float(chapter2.EXERCISE_2_7.solve()["crank length BC"].value), 3)
87.272
"""

from __future__ import annotations

import math

import numpy as np

from mech._validate import positive_length
from mech.exercises._core import Exercise, Interval, Parameter, Part, Result, Solution
from mech.planar import FourBar, Guide, GuideBar, Linkage, SliderCrank, grashof, time_ratio
from mech.planar import _grashof
from mech.planar._instant_centres import higher_pair, instant_centres, omega_ratio

__all__ = [
    "EXERCISE_2_2",
    "EXERCISE_2_3",
    "EXERCISE_2_4",
    "EXERCISE_2_5",
    "EXERCISE_2_6",
    "EXERCISE_2_7",
    "EXERCISE_2_10",
    "EXERCISES",
    "cam_2_10",
    "linkage_2_4",
    "linkage_2_5",
    "linkage_2_7",
    "merge_intervals",
]

_DEG = math.pi / 180.0


def merge_intervals(intervals):
    """Sort intervals and join those that touch, e.g. ``(0, 1] ∪ (1, 2)`` into ``(0, 2)``."""
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
    g = grashof(a, b, c, d)
    if g.kind != "crank-rocker":
        raise ValueError(
            f"Expected a crank-rocker with AD as the frame, got a {g.kind} "
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


# ----------------------------------------------------------------------------- helpers (2-4 to 2-10)
_TURN = 2.0 * math.pi


def _along(linkage, point, direction, theta):
    """Position of ``point`` along the unit ``direction`` and its rate d/d(theta)."""
    sol = linkage.solve(theta, order=1, omega=1.0)
    e = np.conj(direction)
    return np.real(sol.points[point] * e), np.real(sol.velocities[point] * e)


def _reversals(position, samples=2048, iterations=64):
    """Crank angles in [0, 2 pi) where an output reverses, with the output there.

    ``position(theta) -> (x, dx/dtheta)``. The rate is sampled over one turn and each sign
    change is refined by bisection (all brackets at once) to rounding.
    """
    theta = np.linspace(0.0, _TURN, samples, endpoint=False)
    _, v = position(theta)
    up = v > 0.0
    idx = np.flatnonzero(up != np.roll(up, -1))
    lo, hi = theta[idx], theta[idx] + _TURN / samples
    up_lo = up[idx]
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        same = (position(mid)[1] > 0.0) == up_lo
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    roots = np.mod(0.5 * (lo + hi), _TURN)
    return roots, position(roots)[0]


def _stroke(position, *, what="the output"):
    """Stroke, extreme angle, time ratio and the two dead-centre crank angles of an output."""
    roots, x = _reversals(position)
    if roots.size != 2:
        raise ValueError(
            f"Expected {what} to reverse twice per crank turn, got {roots.size} reversals: "
            "the stroke and time ratio are then not defined"
        )
    order = np.argsort(x)
    forward = (roots[order[1]] - roots[order[0]]) % _TURN      # crank turn while x rises
    theta = abs(forward - math.pi)
    return {
        "stroke": float(x[order[1]] - x[order[0]]),
        "extreme_angle": float(theta),
        "time_ratio": float(time_ratio(theta)),
        "theta_low": float(roots[order[0]]),
        "theta_high": float(roots[order[1]]),
        "rising": float(forward),
    }


def _extremum(f, *, largest=True, samples=2048, rounds=7, zoom=41):
    """Largest (or smallest) value of ``f(theta)`` over a crank turn and where it occurs.

    Dense sampling, then repeated zooming on the best sample; ``f`` is vectorised.
    """
    sign = 1.0 if largest else -1.0
    grid = np.linspace(0.0, _TURN, samples, endpoint=False)
    step = _TURN / samples
    y = sign * f(grid)
    best = int(np.argmax(y))
    at, value = grid[best], y[best]
    for _ in range(rounds):
        grid = at + np.linspace(-step, step, zoom)
        y = sign * f(grid)
        best = int(np.argmax(y))
        at, value = grid[best], y[best]
        step = 2.0 * step / (zoom - 1)
    return float(sign * value), float(at % _TURN)


def _acute(direction, guide):
    """Acute angle between unit directions (complex) ``direction`` and ``guide``."""
    u = direction * np.conj(guide)
    return np.arctan2(np.abs(np.imag(u)), np.abs(np.real(u)))


def _brentq(f, lo, hi):
    from scipy.optimize import brentq

    return float(brentq(f, lo, hi, xtol=1e-13, rtol=4 * np.finfo(float).eps, maxiter=200))


def _deg(x):
    return f"{math.degrees(x):.2f}°"


def _around(rng, value, spread=0.2, digits=0):
    """A number within +-spread of ``value``, rounded to ``digits`` decimals."""
    return round(float(value) * float(rng.uniform(1.0 - spread, 1.0 + spread)), digits)

# ----------------------------------------------------------------------------- 2-4
_STATEMENT_2_4 = (
    "In a six-bar linkage (六杆机构) AB = {AB} mm, BC = {BC} mm, AD = {AD} mm, CD = {CD} mm, "
    "DE = {DE} mm and EF = {EF} mm; the slider F is the output. Find (1) the type of the "
    "four-bar ABCD; (2) the time ratio K (行程时间比系数) of the mechanism; (3) the stroke H "
    "of the slider F; (4) the minimum transmission angle γ_min of the mechanism, and the "
    "largest transmission angle; (5) where the guide DF (导轨) should be placed so that the "
    "slider's pressure angle during the motion is smallest. (Assumed guide offset h = {h} mm.)"
)


def _check_2_4(p):
    names = ("AB", "BC", "CD", "AD", "DE", "EF")
    a, b, c, d, de, ef = (positive_length(n, p[n]) for n in names)
    h = float(p["h"])
    if not math.isfinite(h):
        raise ValueError(f"Expected a finite guide offset `h`, got {h!r}")
    kind = grashof(a, b, c, d).kind
    if kind != "crank-rocker":
        raise ValueError(f"Expected a crank-rocker ABCD with AD as the frame, got a {kind} "
                         f"(AB={a!r}, BC={b!r}, CD={c!r}, AD={d!r})")
    if de > c:
        raise ValueError(f"Expected `DE` <= `CD` = {c!r} (E lies on the rocker DC), got {de!r}")
    if ef <= de + abs(h):
        raise ValueError(f"Expected `EF` > `DE` + |`h`| = {de + abs(h)!r} so that the slider "
                         f"stage assembles in every pose, got {ef!r}")
    return a, b, c, d, de, ef, h


def linkage_2_4(params=None, *, h=None):
    """The six-bar of exercise 2-4 on its assumed layout, as a `mech.planar.Linkage`.

    A = 0 and D = AD on +x (frame AD); crank AB turns about A (input: its angle); the
    coupler BC and the rocker DC form an RRR group with C above the frame; E lies on the
    rocker, on segment DC at DE from D; the rod EF drives the slider F on a guide parallel
    to AD at height ``h`` above D (default: the parameter ``h``, 0 for a guide through D),
    with F to the right of E. Points ``A, B, C, D, E, F``; links ``crank, coupler, rocker,
    rod, slider``.

    >>> from mech.exercises.chapter2 import linkage_2_4
    >>> linkage_2_4().groups
    ('crank crank', 'RRR coupler-rocker', 'RRP rod-slider')
    """
    p = EXERCISE_2_4.params(params)
    a, b, c, d, de, ef, h0 = _check_2_4(p)
    h = h0 if h is None else float(h)
    return (Linkage({"A": 0.0, "D": d})
            .crank("crank", pivot="A", tip="B", length=a)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c), branch=1)
            .point("E", link="rocker", at=de)
            .rrp(("rod", "slider"), pin="E", guide=Guide("ground", through=d + 1j * h, angle=0.0),
                 joint="F", length=ef, branch=1))


def _slider_2_4(linkage):
    """Stroke data, and the slider stage's pressure angle as a function of theta."""
    stroke = _stroke(lambda t: _along(linkage, "F", 1.0, t), what="the slider F")
    alpha = lambda t: _acute(linkage.solve(t).direction("rod"), 1.0)
    return stroke, alpha


def _solve_2_4(p):
    a, b, c, d, de, ef, h = _check_2_4(p)
    linkage = linkage_2_4(p)
    fourbar = FourBar(a, b, c, d)
    lp = fourbar.limit_positions()
    stroke, alpha = _slider_2_4(linkage)
    how_sim = "`Linkage` of the assumed layout: slider reversals found over a crank turn and refined"
    g1_min, g1_at = fourbar.min_transmission_angle()
    g1_max, g1_max_at = _extremum(fourbar.transmission_angle)
    a_max, a_max_at = _extremum(alpha)
    a_min, a_min_at = _extremum(alpha, largest=False)
    height = lambda t: np.imag(linkage.solve(t).points["E"])
    y_hi, _ = _extremum(height)
    y_lo, _ = _extremum(height, largest=False)
    h_best = 0.5 * (y_hi + y_lo)
    best = linkage_2_4(p, h=h_best)
    stroke_best, alpha_best = _slider_2_4(best)
    a_best, _ = _extremum(alpha_best)
    g = grashof(a, b, c, d)
    lengths = sorted((a, b, c, d))
    assumptions = (
        f"The frame is AD (A = 0, D = {d:g} mm on the +x axis), AB is the input crank turning "
        "counter-clockwise, BC the coupler and DC the rocker, with C above the frame line.",
        f"E is a point of the rocker on the segment DC, DE = {de:g} mm from D (no arm at an "
        "angle to DC).",
        f"The slider F moves on a straight guide parallel to AD, at height h = {h:g} mm above "
        "D (h = 0: the guide passes through D, the literal reading of 'guide DF'); F is to the "
        "right of E. Part (5) treats h as the free quantity, the direction staying parallel to AD.",
    )
    conventions = (
        "Transmission angle of each stage: the acute angle between the driven link's velocity "
        "at the driving joint and the force from the two-force link (γ = 90° − α, α the "
        "pressure angle). Four-bar stage: between BC and DC at C; slider stage: between EF and "
        "the normal to the guide. 'The mechanism's' γ_min is the smaller of the two stages'.",
    )
    part1 = Part("(1) Type of ABCD", (
        Result("type of ABCD", g.kind, "", "`grashof(AB, BC, CD, AD).kind`"),), (
        f"Shortest + longest = {lengths[0]:g} + {lengths[3]:g} = {lengths[0] + lengths[3]:g} ≤ "
        f"{lengths[1]:g} + {lengths[2]:g} = {lengths[1] + lengths[2]:g} (Grashof) and the "
        "shortest link AB is next to the frame AD, so AB is a crank and DC a rocker.",))
    part2 = Part("(2) Time ratio", (
        Result("time ratio K", stroke["time_ratio"], "", how_sim),
        Result("extreme-position angle θ", stroke["extreme_angle"], "rad", how_sim),
        Result("K of the four-bar ABCD alone", lp.time_ratio, "", "`FourBar(...).limit_positions()`"),
        Result("swing of the rocker DC", abs(lp.swing), "rad", "`FourBar(...).limit_positions()`"),
    ), (
        "The slider's position is a monotonic function of the rocker angle over the swing, so "
        "the slider stops exactly when the rocker does: the six-bar has the four-bar's θ and K."
        if abs(stroke["time_ratio"] - lp.time_ratio) < 1e-8 * lp.time_ratio else
        "The slider does not stop exactly when the rocker does, so the six-bar's K differs "
        "from the four-bar's.",))
    part3 = Part("(3) Stroke", (
        Result("stroke H of F", stroke["stroke"], "mm", how_sim),
        Result("crank angle at F's left end", stroke["theta_low"], "rad", how_sim),
        Result("crank angle at F's right end", stroke["theta_high"], "rad", how_sim),), ())
    part4 = Part("(4) Transmission angles", (
        Result("four-bar stage: γ_min", g1_min, "rad", "`FourBar(...).min_transmission_angle()`"),
        Result("four-bar stage: largest γ", g1_max, "rad",
               "`FourBar(...).transmission_angle(θ)`, maximised over a turn"),
        Result("slider stage: γ_min", math.pi / 2 - a_max, "rad",
               "90° − largest pressure angle; `Linkage` of the assumed layout, maximised over a turn"),
        Result("slider stage: largest γ", math.pi / 2 - a_min, "rad", "90° − smallest pressure angle"),
        Result("mechanism γ_min", min(g1_min, math.pi / 2 - a_max), "rad", "the smaller of the two stages"),
    ), (
        f"The four-bar's γ is smallest with the crank along the frame (θ = {_deg(g1_at)}); it "
        + ("reaches 90° in between." if g1_max > math.pi / 2 - 1e-9 else f"peaks at {_deg(g1_max)}.")
        + f" In the slider stage sin α = |y_E − h| / EF, so α is largest when E is farthest "
        f"from the guide line (crank at θ = {_deg(a_max_at)}).",))
    part5 = Part("(5) Where to put the guide", (
        Result("E's lowest height above AD", y_lo, "mm", "`Linkage` over a crank turn"),
        Result("E's highest height above AD", y_hi, "mm", "`Linkage` over a crank turn"),
        Result("best guide height h*", h_best, "mm", "midway between E's extreme heights"),
        Result("largest pressure angle at h", a_max, "rad", "`Linkage` of the assumed layout"),
        Result("largest pressure angle at h*", a_best, "rad", "`Linkage` with the guide at h*"),
        Result("stroke at h*", stroke_best["stroke"], "mm", "`Linkage` with the guide at h*"),
        Result("K at h*", stroke_best["time_ratio"], "", "`Linkage` with the guide at h*"),
    ), (
        "With the guide parallel to AD at height h, the pressure angle obeys sin α = "
        "|y_E − h| / EF. Its largest value over a turn is set by whichever extreme height of "
        "E lies farther from h; it is smallest when h is midway between E's lowest and "
        "highest positions, i.e. the guide passes through the middle of the height (弦高, "
        "sagitta) of E's arc. The stroke and K hardly change.",))
    return Solution("2-4", EXERCISE_2_4.title, dict(p), conventions,
                    (part1, part2, part3, part4, part5), assumptions=assumptions)


def _sample_2_4(rng):
    p = {k: _around(rng, v) for k, v in (("AB", 30), ("BC", 55), ("AD", 50), ("CD", 40),
                                           ("DE", 20), ("EF", 60))}
    p["h"] = 0.0
    return p

# ----------------------------------------------------------------------------- 2-5
_STATEMENT_2_5 = (
    "In a six-bar linkage AB = {AB} mm, AC = {AC} mm, CD = {CD} mm and DE = {DE} mm, with AC "
    "perpendicular to EC, and the crank 1 turns at a constant ω1. Find (1) the time ratio K; "
    "(2) the stroke H of member 5; (3) the minimum transmission angle γ_min and the largest "
    "transmission angle; (4) where the slider's largest pressure angle α_max occurs and how "
    "large it is, and how the mechanism could be changed to reduce it; (5) with every other "
    "dimension kept, the crank length that doubles the stroke."
)


def _check_2_5(p):
    ab, ac, cd, de = (positive_length(n, p[n]) for n in ("AB", "AC", "CD", "DE"))
    if ab >= ac:
        raise ValueError(f"Expected `AB` < `AC` = {ac!r} so that the guide bar oscillates, got {ab!r}")
    if de <= cd:
        raise ValueError(f"Expected `DE` > `CD` = {cd!r} so that the slider stage assembles "
                         f"in every pose, got {de!r}")
    return ab, ac, cd, de


def linkage_2_5(params=None, *, y=0.0):
    """The six-bar of exercise 2-5 on its assumed layout, as a `mech.planar.Linkage`.

    C = 0 (the guide bar's pivot) and A = AC i above it; crank AB turns about A (input: its
    angle); the block at B slides on the guide bar through C (an RPR group); D is the end
    of the bar at CD from C on the side away from B; the rod DE drives slider 5 (point E)
    on the horizontal line y = ``y`` (default 0: through C, perpendicular to AC), E to the
    right of D. Points ``A, B, C, D, E``; links ``crank, bar, block, rod, slider``.

    >>> from mech.exercises.chapter2 import linkage_2_5
    >>> linkage_2_5().groups
    ('crank crank', 'RPR bar-block', 'RRP rod-slider')
    """
    p = EXERCISE_2_5.params(params)
    ab, ac, cd, de = _check_2_5(p)
    if abs(float(y)) >= de - cd:
        raise ValueError(f"Expected |`y`| < DE - CD = {de - cd!r}, got {y!r}")
    return (Linkage({"C": 0.0, "A": 1j * ac})
            .crank("crank", pivot="A", tip="B", length=ab)
            .rpr(("bar", "block"), pins=("C", "B"), offset=0.0, branch=1)
            .point("D", link="bar", at=-cd)
            .rrp(("rod", "slider"), pin="D", guide=Guide("ground", through=1j * float(y), angle=0.0),
                 joint="E", length=de, branch=1))


def _slider_2_5(linkage):
    stroke = _stroke(lambda t: _along(linkage, "E", 1.0, t), what="member 5")
    alpha = lambda t: _acute(linkage.solve(t).direction("rod"), 1.0)
    return stroke, alpha


def _solve_2_5(p):
    ab, ac, cd, de = _check_2_5(p)
    linkage = linkage_2_5(p)
    stroke, alpha = _slider_2_5(linkage)
    bar = GuideBar(ab, ac)
    how_sim = "`Linkage` of the assumed layout over a crank turn, reversals refined"
    a_max, a_max_at = _extremum(alpha)
    a_min, _ = _extremum(alpha, largest=False)
    pose = linkage.solve(a_max_at)
    bar_from_ca = abs(float(np.angle(pose.direction("bar") / 1j)))
    bar_from_ca = min(bar_from_ca, math.pi - bar_from_ca)
    # (4) guide through the middle of the sagitta of D's arc
    height = lambda t: np.imag(linkage.solve(t).points["D"])
    y_hi, _ = _extremum(height)
    y_lo, _ = _extremum(height, largest=False)
    y_best = 0.5 * (y_hi + y_lo)
    stroke_best, alpha_best = _slider_2_5(linkage_2_5(p, y=y_best))
    a_best, _ = _extremum(alpha_best)
    # (5) the crank that doubles the stroke
    target = 2.0 * stroke["stroke"]
    H = lambda x: _slider_2_5(linkage_2_5(dict(p, AB=x)))[0]["stroke"]
    top = ac * (1.0 - 1e-9)
    if H(top) > target:
        ab2 = _brentq(lambda x: H(x) - target, 1e-6 * ac, top)
        doubled = (Result("crank length for 2H", ab2, "mm", "root of H(AB) = 2H, `Linkage` strokes"),
                   Result("K with that crank", GuideBar(ab2, ac).time_ratio(), "", "`GuideBar(AB, AC).time_ratio()`"))
        note = ("The stroke equals the chord of D's arc, 2 CD sin(θ/2) with sin(θ/2) = AB/AC, so "
                "it grows in proportion to AB: doubling it doubles AB (as long as AB < AC/2), "
                "and the quick return grows too.")
    else:
        doubled = (Result("crank length for 2H", "not possible", "", "H(AB) < 2H for every AB < AC"),)
        note = "Even a crank as long as AC cannot double this stroke: D's arc spans at most a half-turn."
    big = _slider_2_5(linkage_2_5(dict(p, CD=10.0 * cd))) if 10.0 * cd < de else None
    assumptions = (
        f"The guide bar (导杆) turns about the fixed pivot C; the crank AB turns about the fixed "
        f"point A, AC = {ac:g} mm above C, and its block at B slides on the bar (an oscillating "
        "guide-bar, since AB < AC).",
        f"D is a point of the guide bar, CD = {cd:g} mm from C on the side away from B; the rod "
        "DE drives slider 5 at E.",
        "Slider 5 moves on the line through C perpendicular to AC (our reading of AC ⊥ EC); E "
        "is to the right of D. Placing D on B's side of C mirrors the motion and changes none "
        "of the numbers.",
    )
    conventions = (
        "Transmission angle γ = 90° − α, α the pressure angle: the angle between the force a "
        "two-force link (or block) applies and the velocity of the point it drives.",
    )
    parts = [
        Part("(1) Time ratio", (
            Result("time ratio K", stroke["time_ratio"], "", how_sim),
            Result("extreme-position angle θ", stroke["extreme_angle"], "rad", how_sim),
            Result("K of the guide-bar stage alone", bar.time_ratio(), "", "`GuideBar(AB, AC).time_ratio()`"),
        ), ("Slider 5 stops exactly when the guide bar does (crank perpendicular to the bar), "
            "so K is the guide-bar's: θ equals the bar's swing, 2 asin(AB/AC).",)),
        Part("(2) Stroke", (
            Result("stroke H of member 5", stroke["stroke"], "mm", how_sim),
            Result("crank angle at E's left end", stroke["theta_low"], "rad", how_sim),
            Result("crank angle at E's right end", stroke["theta_high"], "rad", how_sim),
        ), (
            "By the symmetry of the two limit positions about AC, the stroke equals the chord "
            "of D's arc, 2 CD sin(θ/2).",)),
        Part("(3) Transmission angles", (
            Result("guide-bar stage γ", math.pi / 2, "rad",
                   "the block presses perpendicular to the bar, and the bar's point under it moves "
                   "perpendicular to the bar: γ = 90° in every pose"),
            Result("γ_min (slider stage)", math.pi / 2 - a_max, "rad", "90° − α_max"),
            Result("largest γ of the slider stage", math.pi / 2 - a_min, "rad", "90° − smallest α, at the limit positions"),
        ), ()),
        Part("(4) Largest pressure angle", (
            Result("α_max", a_max, "rad", how_sim),
            Result("crank angle at α_max", a_max_at, "rad", "from +x, counter-clockwise; the crank then lies along AC"),
            Result("guide bar's angle from CA at α_max", bar_from_ca, "rad", "`Linkage` direction of the bar"),
            Result("better slider line: height below C", -y_best, "mm", "midway between D's extreme heights"),
            Result("α_max with that line", a_best, "rad", "`Linkage` with the moved slider line"),
            Result("stroke with that line", stroke_best["stroke"], "mm", "`Linkage` with the moved slider line"),
        ), ("sin α = (distance of D from the slider's line)/DE. With the line through C this "
            "distance is largest, CD, when the bar lies along AC, i.e. the crank is along AC, in "
            "the middle of each stroke. To reduce α_max, move the slider's line to pass through "
            "the middle of the height (弦高) of D's arc, or lengthen DE.",)),
        Part("(5) Doubling the stroke", doubled, (note,)),
    ]
    if big is not None:
        parts.append(Part("Data question: CD ten times longer (30 mm read as 300 mm)", (
            Result("stroke with 10 CD", big[0]["stroke"], "mm", "`Linkage` with CD × 10"),
            Result("α_max with 10 CD", _extremum(big[1])[0], "rad", "`Linkage` with CD × 10"),
            Result("K with 10 CD", big[0]["time_ratio"], "", "`Linkage` with CD × 10"),
        ), ("CD = 30 mm is an order of magnitude below the other lengths. On this layout it still "
            "works (any CD < DE does), but it gives a stroke of a few centimetres from a crank of "
            f"{ab:g} mm. Read as 300 mm, the stroke and the distance of D from the slider line "
            "grow tenfold, so sin α_max does too, while K stays the same. A layout with D beyond "
            f"B on the bar would need CD ≥ AC + AB = {ac + ab:g} mm, so neither 30 nor 300 fits "
            "that reading.",)))
    return Solution("2-5", EXERCISE_2_5.title, dict(p), conventions, tuple(parts), assumptions=assumptions)


def _sample_2_5(rng):
    return {k: _around(rng, v) for k, v in (("AB", 200), ("AC", 585), ("CD", 30), ("DE", 700))}

# ----------------------------------------------------------------------------- 2-7
_STATEMENT_2_7 = (
    "A rotating guide-bar mechanism (转动导杆机构), as used in small slotting machines (插床), "
    "has AB = {AB} mm and AD = {AD} mm, and its time ratio is K = {K}. Find (1) the length of "
    "the crank BC; (2) the stroke H of the slotting tool P. (Assumed: the rod from D to the "
    "tool is DP = {DP} mm; it does not affect the answers.)"
)


def _check_2_7(p):
    ab, ad, dp = (positive_length(n, p[n]) for n in ("AB", "AD", "DP"))
    k = float(p["K"])
    if not (math.isfinite(k) and 1.0001 < k < 1e6):
        raise ValueError(f"Expected a time ratio 1.0001 < `K` < 1e6, got {k!r}")
    if dp <= ad:
        raise ValueError(f"Expected `DP` > `AD` = {ad!r} so that the arm AD turns fully, got {dp!r}")
    return ab, ad, dp, k


def linkage_2_7(params=None, *, bc=None):
    """The slotting-machine mechanism of exercise 2-7 on its assumed layout (a `Linkage`).

    A = 0 (the guide bar's pivot) and B = AB on +x (the crank's pivot); the crank BC turns
    about B (input: the angle of B->C); the block at C slides on the guide bar through A;
    the arm AD is rigid with the bar, along the slot on the side away from C; the rod DP
    drives the tool P on the vertical line through A, below D. ``bc`` is the crank length
    (default: the one solved from K). Points ``A, B, C, D, P``; links ``crank, guide,
    block, rod, tool``.

    >>> from mech.exercises.chapter2 import linkage_2_7
    >>> linkage_2_7(bc=80.0).groups
    ('crank crank', 'RPR guide-block', 'RRP rod-tool')
    """
    p = EXERCISE_2_7.params(params)
    ab, ad, dp, k = _check_2_7(p)
    if bc is None:
        bc = _crank_2_7(ab, ad, dp, k)
    bc = positive_length("bc", bc)
    if bc <= ab:
        raise ValueError(f"Expected `bc` > `AB` = {ab!r} for a guide that turns fully, got {bc!r}")
    return _build_2_7(ab, ad, dp, bc)


def _build_2_7(ab, ad, dp, bc):
    return (Linkage({"A": 0.0, "B": ab})
            .crank("crank", pivot="B", tip="C", length=bc)
            .rpr(("guide", "block"), pins=("A", "C"), offset=0.0, branch=1)
            .point("D", link="guide", at=-ad)
            .rrp(("rod", "tool"), pin="D", guide=Guide("ground", through="A", angle=-math.pi / 2),
                 joint="P", length=dp, branch=1))


def _tool_2_7(linkage):
    return _stroke(lambda t: _along(linkage, "P", -1j, t), what="the tool P")


def _crank_2_7(ab, ad, dp, k):
    """Crank length whose simulated tool motion has time ratio ``k`` (a root solve)."""
    f = lambda bc: _tool_2_7(_build_2_7(ab, ad, dp, bc))["time_ratio"] - k
    return _brentq(f, ab * (1.0 + 1e-6), ab * 1e4)


def _solve_2_7(p):
    ab, ad, dp, k = _check_2_7(p)
    bc = _crank_2_7(ab, ad, dp, k)
    tool = _tool_2_7(_build_2_7(ab, ad, dp, bc))
    how = "`Linkage` of the assumed layout: tool reversals over a crank turn"
    assumptions = (
        f"AB is the frame: the crank BC turns about the fixed point B and the guide bar about "
        f"the fixed point A, AB = {ab:g} mm apart. The block at C slides in the bar's slot; "
        "since BC > AB the bar turns fully (a rotating guide-bar).",
        f"The arm AD ({ad:g} mm) is rigid with the guide bar and lies along the slot's line, on "
        "the side of A away from the block.",
        "The tool P is driven from D by a rod DP and moves on a straight line through A "
        f"perpendicular to AB. The text gives no DP; we take DP = {dp:g} mm, and any DP > AD "
        "gives the same K and H, because A, D, P then form a centred slider-crank whose dead "
        "centres are where AD lies along the tool's line.",
    )
    part1 = Part("(1) The crank BC", (
        Result("crank length BC", bc, "mm", "root of K(BC) = K, K from the simulated tool motion"),
        Result("extreme-position angle θ", tool["extreme_angle"], "rad", how),
        Result("time ratio K, checked", tool["time_ratio"], "", how),
    ), ("The tool stops when AD, and so the slot, lies along the tool's line, perpendicular to "
        "AB. Then C lies on that line: in the right triangle ABC the angle at B is "
        "arccos(AB/BC), and the crank turns through twice that angle on one stroke and the "
        "rest of the turn on the other. The longer BC, the closer K is to 1, so one BC fits K.",))
    part2 = Part("(2) Stroke of the tool", (
        Result("stroke H of P", tool["stroke"], "mm", how),
        Result("crank angle at P's lowest point", tool["theta_low"], "rad", how),
        Result("crank angle at P's highest point", tool["theta_high"], "rad", how),
    ), ("At the two dead centres D is on the tool's line, on either side of A: H = 2 AD.",))
    return Solution("2-7", EXERCISE_2_7.title, dict(p), (), (part1, part2), assumptions=assumptions)


def _sample_2_7(rng):
    return {"AB": _around(rng, 50), "AD": _around(rng, 40), "K": _around(rng, 2.27, 0.3, 2),
            "DP": _around(rng, 120)}

# ----------------------------------------------------------------------------- 2-10
_STATEMENT_2_10 = (
    "In a cam mechanism (凸轮机构) r = {r} mm, OA = {OA} mm, AC = {AC} mm and φ1 = {phi1}°; "
    "the cam 1 turns counter-clockwise at ω1 = {omega1} rad/s. Find the angular velocity ω2 "
    "of the follower 2 by the method of instant centres (瞬心法)."
)


def _check_2_10(p):
    r, oa, ac = (positive_length(n, p[n]) for n in ("r", "OA", "AC"))
    phi, w1 = float(p["phi1"]), float(p["omega1"])
    if not (math.isfinite(phi) and math.isfinite(w1)):
        raise ValueError(f"Expected finite `phi1` and `omega1`, got {phi!r}, {w1!r}")
    if oa >= r:
        raise ValueError(f"Expected `OA` < `r` = {r!r} (the shaft inside the disc), got {oa!r}")
    return r, oa, ac, math.radians(phi), w1


def cam_2_10(params=None, *, side=-1):
    """Geometry of exercise 2-10 on its assumed layout: a dict of complex points and more.

    A = 0 is the cam's fixed shaft and C = AC on +x the follower's fixed pivot; the disc
    (radius r) has its centre O at OA from A, at the angle φ1 counter-clockwise from A->C.
    The follower's flat face is the line through C tangent to the disc; ``side=-1`` (the
    default) takes the tangent whose contact point K is to the right of the directed line
    C->O, ``side=+1`` the other. Keys: ``A, C, O, K`` (points), ``normal`` (unit, from O to
    K), ``face`` (unit, from C to K), ``r``, ``side``.

    Raises
    ------
    ValueError
        If C lies inside the disc (no tangent from C).

    >>> from mech.exercises.chapter2 import cam_2_10
    >>> g = cam_2_10()
    >>> round(abs(g["K"] - g["O"]), 9), round(abs(g["O"] - 22j), 9)
    (50.0, 0.0)
    """
    p = EXERCISE_2_10.params(params)
    r, oa, ac, phi, _ = _check_2_10(p)
    side = 1 if side > 0 else -1
    A, C = 0j, complex(ac)
    O = complex(oa * np.exp(1j * phi))
    dist = abs(O - C)
    if dist <= r:
        raise ValueError(f"Expected the pivot C outside the disc, |OC| > r = {r!r}, got {dist!r}")
    reach = math.sqrt((dist - r) * (dist + r))
    face = (O - C) / dist * complex(np.exp(1j * side * math.atan2(r, reach)))
    K = C + reach * face
    return {"A": A, "C": C, "O": O, "K": K, "normal": (K - O) / r, "face": face, "r": r, "side": side}


def _omega_2_10(p, side):
    g = cam_2_10(p, side=side)
    w1 = float(p["omega1"])
    ic = instant_centres((1, 2, 3), {(1, 3): g["A"], (2, 3): g["C"], (1, 2): higher_pair(g["K"], g["normal"])})
    w2 = float(omega_ratio(ic, 2, 1, 3)) * w1
    # the same by the equivalent linkage (高副低代): a line parallel to the face through O
    lk = (Linkage({"A": g["A"], "C": g["C"]})
          .crank("cam", pivot="A", tip="O", length=float(p["OA"]))
          .rpr(("follower", "block"), pins=("C", "O"), offset=-side * g["r"], branch=1))
    sol = lk.solve(math.radians(float(p["phi1"])), order=1, omega=w1)
    return g, complex(ic[1, 2].point), w2, float(sol.omegas["follower"])


def _solve_2_10(p):
    r, oa, ac, phi, w1 = _check_2_10(p)
    g, p12, w2, w2_link = _omega_2_10(p, -1)
    _, p12_other, w2_other, _ = _omega_2_10(p, 1)
    sense = lambda w: "counter-clockwise" if w > 0 else "clockwise"
    assumptions = (
        f"The cam is a circular disc of radius r = {r:g} mm (an eccentric cam). A is its fixed "
        f"shaft and O the disc's centre, OA = {oa:g} mm; C is the follower's fixed pivot, "
        f"AC = {ac:g} mm (A = 0, C on +x).",
        f"φ1 is the angle from A->C to A->O, counter-clockwise: φ1 = {math.degrees(phi):g}°.",
        "The follower 2 is an oscillating flat-faced follower whose face is a straight line "
        "through C, touching the disc on the side where the contact point K is to the right of "
        "the line from C to O (in the textbook's numbers: above the frame line AC).",
        "'凸轮 I' is read as member 1, the cam (the speed is ω1).",
    )
    part = Part("The angular velocity of the follower", (
        Result("contact point K", f"({g['K'].real:.4f}, {g['K'].imag:.4f}) mm", "",
               "tangent from C to the disc"),
        Result("P13 (cam–frame)", "A", "", "the shaft"),
        Result("P23 (follower–frame)", "C", "", "the pivot"),
        Result("P12 on line AC, distance from A", p12.real, "mm",
               "`instant_centres`: the common normal OK meets line AC (three-centre theorem)"),
        Result("ω2", w2, "rad/s", "`omega_ratio(centres, 2, 1, 3)` × ω1 = AP12 / CP12 × ω1 (signed)"),
        Result("sense of ω2", sense(w2), "", "sign of ω2"),
        Result("ω2 by the equivalent linkage", w2_link, "rad/s",
               "`Linkage`: crank AO and a bar through C at distance r from O (高副低代)"),
    ), ("P12 is the point of the cam and the follower that has the same velocity on both. It "
        "lies on the common normal at the contact, which for a disc passes through its centre "
        "O, and, by the three-centre theorem, on the line through P13 = A and P23 = C. So "
        "ω1·AP12 = ω2·CP12, with the signs telling the senses: P12 outside the segment AC "
        "means both turn the same way.",
        f"On the other tangent from C (contact point left of C->O), P12 is {p12_other.real:.4f} "
        f"mm from A and ω2 = {w2_other:.4f} rad/s ({sense(w2_other)}).",))
    return Solution("2-10", EXERCISE_2_10.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_10(rng):
    return {"r": _around(rng, 50), "OA": _around(rng, 22), "AC": _around(rng, 80),
            "phi1": float(15 * rng.integers(0, 24)), "omega1": _around(rng, 10, 0.5)}


# ----------------------------------------------------------------------------- registry
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

EXERCISE_2_4 = Exercise(
    number="2-4",
    title="A four-bar driving a slider: type, time ratio, stroke, transmission and pressure angles",
    tag="A",
    statement=_STATEMENT_2_4,
    parameters=(
        Parameter("AB", 30.0, "mm", "crank"),
        Parameter("BC", 55.0, "mm", "coupler"),
        Parameter("AD", 50.0, "mm", "frame"),
        Parameter("CD", 40.0, "mm", "rocker"),
        Parameter("DE", 20.0, "mm", "E on the rocker, from D"),
        Parameter("EF", 60.0, "mm", "rod to the slider"),
        Parameter("h", 0.0, "mm", "assumed height of the guide above D"),
    ),
    solver=_solve_2_4,
    sampler=_sample_2_4,
)

EXERCISE_2_5 = Exercise(
    number="2-5",
    title="Guide-bar six-bar: time ratio, stroke, transmission and pressure angles",
    tag="A",
    statement=_STATEMENT_2_5,
    parameters=(
        Parameter("AB", 200.0, "mm", "crank"),
        Parameter("AC", 585.0, "mm", "frame: crank pivot to guide-bar pivot"),
        Parameter("CD", 30.0, "mm", "guide bar, pivot to D (as printed)"),
        Parameter("DE", 700.0, "mm", "rod to slider 5"),
    ),
    solver=_solve_2_5,
    sampler=_sample_2_5,
)

EXERCISE_2_7 = Exercise(
    number="2-7",
    title="Slotting machine: crank length from the time ratio, and the tool's stroke",
    tag="A",
    statement=_STATEMENT_2_7,
    parameters=(
        Parameter("AB", 50.0, "mm", "frame: guide pivot A to crank pivot B"),
        Parameter("AD", 40.0, "mm", "arm on the guide bar"),
        Parameter("K", 2.27, "", "time ratio"),
        Parameter("DP", 120.0, "mm", "assumed rod from D to the tool (no effect on the answers)"),
    ),
    solver=_solve_2_7,
    sampler=_sample_2_7,
)

EXERCISE_2_10 = Exercise(
    number="2-10",
    title="Follower speed of a disc cam by instant centres",
    tag="A",
    statement=_STATEMENT_2_10,
    parameters=(
        Parameter("r", 50.0, "mm", "disc radius"),
        Parameter("OA", 22.0, "mm", "eccentricity: shaft A to disc centre O"),
        Parameter("AC", 80.0, "mm", "frame: shaft A to follower pivot C"),
        Parameter("phi1", 90.0, "°", "cam angle, from A->C to A->O"),
        Parameter("omega1", 10.0, "rad/s", "cam speed, counter-clockwise"),
    ),
    solver=_solve_2_10,
    sampler=_sample_2_10,
)

EXERCISES = (EXERCISE_2_2, EXERCISE_2_3, EXERCISE_2_4, EXERCISE_2_5, EXERCISE_2_6, EXERCISE_2_7,
             EXERCISE_2_10)
