"""Exercises 2-4, 2-5, 2-7 and 2-10 of chapter 2: kinematic analysis on assumed layouts.

The figures of these exercises (tag "A") are lost, so each solution first
states the layout it assumes, then solves it with the general solver `mech.planar.Linkage`
over a full crank turn (limit positions and extremes refined by bisection) and, for 2-10,
by instant centres. ``linkage_2_4`` and the like return the assumed linkage, for figures
and checks. The solutions are shown on the book page ``book-analysis-exercises``.

Examples
--------
>>> from mech.exercises import chapter2_analysis as ca
>>> round(float(ca.EXERCISE_2_7.solve()["crank length BC"].value), 3)
87.272
"""

from __future__ import annotations

import math

import numpy as np

from mech._geometry import acute_angle as _acute
from mech._validate import branch_sign, positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.planar import (FourBar, Guide, GuideBar, Linkage, grashof, higher_pair, instant_centres, omega_ratio,
                         time_ratio)

__all__ = [
    "EXERCISE_2_4",
    "EXERCISE_2_5",
    "EXERCISE_2_7",
    "EXERCISE_2_10",
    "cam_2_10",
    "linkage_2_4",
    "linkage_2_5",
    "linkage_2_7",
]

# ----------------------------------------------------------------------------- helpers (2-4 to 2-10)
_TURN = 2.0 * math.pi


def _along(linkage, point, direction, theta):
    """Position of ``point`` along the unit ``direction`` and its rate d/d(theta)."""
    sol = linkage.solve(theta, order=1, omega=1.0)
    e = np.conj(direction)
    return np.real(sol.points[point] * e), np.real(sol.velocities[point] * e)


def _reversals(position, samples=2048, sections=64, rounds=10):
    """Crank angles in [0, 2 pi) where an output reverses, with the output there.

    ``position(theta) -> (x, dx/dtheta)``. The rate is sampled over one turn and each sign
    change is refined to rounding by multisection: every round splits all brackets at once
    into ``sections`` parts and keeps the part where the sign changes (a round narrows a
    bracket 64-fold, as six bisection steps would, for one call of ``position``).
    """
    theta = np.linspace(0.0, _TURN, samples, endpoint=False)
    _, v = position(theta)
    up = v > 0.0
    idx = np.flatnonzero(up != np.roll(up, -1))
    lo, hi = theta[idx], theta[idx] + _TURN / samples
    up_lo = up[idx]
    if idx.size == 0:                        # the output never reverses (or its rate is not finite)
        return np.empty(0), np.empty(0)
    frac = np.arange(1, sections) / sections
    rows = np.arange(idx.size)
    for _ in range(rounds):
        t = np.concatenate([lo[:, None], lo[:, None] + (hi - lo)[:, None] * frac, hi[:, None]], axis=1)
        same = (position(t[:, 1:-1].ravel())[1].reshape(idx.size, -1) > 0.0) == up_lo[:, None]
        # the first interior point past the sign change (or hi when there is none)
        j = np.argmax(np.concatenate([~same, np.ones((idx.size, 1), bool)], axis=1), axis=1)
        lo, hi = t[rows, j], t[rows, j + 1]
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


def _brentq(f, lo, hi, guess=None):
    """The root of ``f`` in [lo, hi]. With a ``guess`` (a closed form of the assumed layout),
    a bracket of relative width 2e-6 about it is tried first: when ``f`` changes sign there,
    the root of the simulation is found in a few steps instead of some thirty over the whole
    range (each step a crank turn simulated); otherwise the whole range is searched."""
    from scipy.optimize import brentq

    seen = {}

    def g(x):                                # brentq evaluates the bracket's ends again: reuse them
        if x not in seen:
            seen[x] = f(x)
        return seen[x]

    solve = lambda a, b: float(brentq(g, a, b, xtol=1e-13, rtol=4 * np.finfo(float).eps, maxiter=200))
    if guess is not None and lo < guess < hi:
        a, b = max(lo, guess * (1.0 - 1e-6)), min(hi, guess * (1.0 + 1e-6))
        fa, fb = g(a), g(b)
        if fa == 0.0:
            return float(a)
        if fb == 0.0:
            return float(b)
        if (fa < 0.0) != (fb < 0.0):
            return solve(a, b)
    return solve(lo, hi)


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
    links = {"AB": a, "BC": b, "CD": c, "AD": d}
    for name, x in links.items():      # here, under the exercise's names (grashof says `a`)
        rest = math.fsum(v for k, v in links.items() if k != name)
        if not x < rest:
            others = " + ".join(f"`{k}`" for k in links if k != name)
            raise ValueError(f"Expected `{name}` shorter than the other three links together ({others} = "
                             f"{rest!r}), got AB={a!r}, BC={b!r}, CD={c!r}, AD={d!r}")
    kind = grashof(a, b, c, d).kind
    if kind != "crank-rocker":
        raise ValueError(f"Expected a crank-rocker ABCD with AD as the frame from `AB`, `BC`, `CD` and `AD`, "
                         f"got a {kind} "
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

    >>> from mech.exercises.chapter2_analysis import linkage_2_4
    >>> linkage_2_4().groups
    ('crank crank', 'RRR coupler-rocker', 'RRP rod-slider')
    """
    p = EXERCISE_2_4.params(params)
    a, b, c, d, de, ef, h0 = _check_2_4(p)
    h = h0 if h is None else real_number("h", h)
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

    >>> from mech.exercises.chapter2_analysis import linkage_2_5
    >>> linkage_2_5().groups
    ('crank crank', 'RPR bar-block', 'RRP rod-slider')
    """
    p = EXERCISE_2_5.params(params)
    ab, ac, cd, de = _check_2_5(p)
    y = real_number("y", y)
    if abs(y) >= de - cd:
        raise ValueError(f"Expected |`y`| < DE - CD = {de - cd!r}, got {y!r}")
    return (Linkage({"C": 0.0, "A": 1j * ac})
            .crank("crank", pivot="A", tip="B", length=ab)
            .rpr(("bar", "block"), pins=("C", "B"), offset=0.0, branch=1)
            .point("D", link="bar", at=-cd)
            .rrp(("rod", "slider"), pin="D", guide=Guide("ground", through=1j * y, angle=0.0),
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
    # the stroke is the chord 2 CD AB/AC of D's arc: a root exists for 2 AB < AC, near 2 AB
    # (the simulation at the top of the range is asked only when that closed form says no)
    if 2.0 * ab < top or H(top) > target:
        ab2 = _brentq(lambda x: H(x) - target, 1e-6 * ac, top, guess=2.0 * ab)
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
    # part (5) asks for the crank that doubles the stroke; the stroke is 2 CD AB/AC, at most
    # 2 CD, so the answer exists only for AB < AC/2. Drawn independently within 20 %, AB and AC
    # reach AB/AC = 0.5 in about 1 draw of 200 (seed 106: AB = 239, AC = 477), so a draw
    # with AB > 0.45 AC is drawn again (the root then lies clear of the bracket's end AC).
    while True:
        p = {k: _around(rng, v) for k, v in (("AB", 200), ("AC", 585), ("CD", 30), ("DE", 700))}
        if p["AB"] <= 0.45 * p["AC"]:
            return p

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

    >>> from mech.exercises.chapter2_analysis import linkage_2_7
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
    # one stroke turns the crank through 2 arccos(AB/BC) = 360°/(K + 1): the root is near there
    return _brentq(f, ab * (1.0 + 1e-6), ab * 1e4, guess=ab / math.cos(math.pi / (k + 1.0)))


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

    >>> from mech.exercises.chapter2_analysis import cam_2_10
    >>> g = cam_2_10()
    >>> round(abs(g["K"] - g["O"]), 9), round(abs(g["O"] - 22j), 9)
    (50.0, 0.0)
    """
    p = EXERCISE_2_10.params(params)
    r, oa, ac, phi, _ = _check_2_10(p)
    side = branch_sign(side, "side")
    A, C = 0j, complex(ac)
    O = complex(oa * np.exp(1j * phi))
    dist = abs(O - C)
    if dist <= r:
        raise ValueError(f"Expected the pivot C outside the disc, |OC| > `r`, from `r`, `OA`, `AC` and `phi1`, "
                         f"got |OC| = {dist!r} with r={r!r}, OA={oa!r}, AC={ac!r}, phi1={p['phi1']!r}")
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
