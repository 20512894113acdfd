"""Worked examples of chapter 2 as exercises with variants: numbered ``E2-1``, ``E2-2`` ...

The textbook's worked examples are solved once, with its numbers, on the book's pages. Here
the planar analysis examples (2-1, 2-2, 2-3 of §2.2 on limit positions, 2-8 and 2-9 on
velocity and acceleration) and two quick-return designs (2-19, 2-20 of §2.4) are stated as
:class:`~mech.exercises.Exercise` records like the end-of-chapter exercises: named givens
with the example's numbers as defaults, a solver on :mod:`mech.planar`, and a sampler of
other numbers. They sit in the same registry (``mech.exercises.get("E2-1")``), so a sheet,
a Moodle or QTI quiz and the PDFs take them with a variant per student. The prefix ``E``
keeps an example apart from the exercise of the same number.

Examples
--------
>>> from mech.exercises import get
>>> s = get("E2-1").solve()
>>> round(float(s["time ratio K"].value), 5)
1.22404
>>> get("E2-1").variant(3) == get("E2-1").variant(3)
True
"""

from __future__ import annotations

import math

import numpy as np

from mech._validate import positive_length, real_number
from mech.exercises import _figures
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution

__all__ = ["EXAMPLES", "draw_example"]

_DEG = math.pi / 180.0


def _int(rng, low, high, step=1):
    """An integer multiple of ``step`` in [low, high], as a float."""
    return float(step * int(rng.integers(round(low / step), round(high / step) + 1)))


def _example(number, title, statement, parameters, solver, sampler, tag="N"):
    # the number is passed through a variable: mech.index reads `Exercise(number="2-1")`
    # calls as exercises, and an example is not one
    return Exercise(number=number, title=title, tag=tag, statement=statement, parameters=parameters,
                    solver=solver, sampler=sampler)


# ----------------------------------------------------------------------------- E2-1
def _solve_e2_1(p):
    from mech.planar import FourBar, grashof

    a, b, c, d = (positive_length(n, p[n]) for n in "abcd")
    kind = grashof(a, b, c, d)
    if kind.kind != "crank-rocker" or kind.change_point:
        raise ValueError(f"Expected `a`, `b`, `c`, `d` of a crank-rocker with the crank `a`, got a={a!r}, b={b!r}, "
                         f"c={c!r}, d={d!r} ({kind.kind}{', a change point' if kind.change_point else ''})")
    fb = FourBar(a, b, c, d)
    lp = fb.limit_positions()
    g_min, g_at = fb.min_transmission_angle()
    how = "`FourBar(a, b, c, d).limit_positions()`: crank and coupler collinear"
    return Solution("E2-1", EXAMPLES_BY_NUMBER["E2-1"].title, dict(p), (
        "Angles from the frame line A->D, counter-clockwise; the assembly mode with C above AD "
        "(the other mode mirrors every angle and changes none of the sizes).",), (
        Part("(1) Type", (Result("type", f"a {kind.kind}: the Grashof condition holds and the shortest "
                                 "link a is next to the frame", "", "`grashof(a, b, c, d)`"),), ()),
        Part("(2) Limit positions", (
            Result("swing φ of CD", lp.swing, "rad", how),
            Result("extreme-position angle θ", lp.extreme_angle, "rad", how),
            Result("time ratio K", lp.time_ratio, "", "K = (180° + θ)/(180° − θ), eq. (2-9)"),
        ), ("The rocker stops where the crank and the coupler lie on one line: stretched out, "
            "AC = b + a, and folded, AC = b − a; the triangle ACD then fixes the rocker's angle.",)),
        Part("(3) Transmission angle", (
            Result("minimum transmission angle γ_min", g_min, "rad", "`FourBar.min_transmission_angle()`"),
            Result("crank angle at γ_min", g_at, "rad", "where the crank lies along the frame line"),
        ), ()),
    ))


def _sample_e2_1(rng):
    return {"a": _int(rng, 8, 14), "b": _int(rng, 34, 46), "c": _int(rng, 25, 35), "d": _int(rng, 30, 40)}


# ----------------------------------------------------------------------------- E2-2
def _solve_e2_2(p):
    from mech.planar import GuideBar

    d = positive_length("d", p["d"])
    phi = real_number("phi", p["phi"])
    if not 0.0 < phi < 180.0:
        raise ValueError(f"Expected a swing 0 < `phi` < 180 degrees, got {phi!r}")
    gb = GuideBar.from_swing(d, phi * _DEG)
    return Solution("E2-2", EXAMPLES_BY_NUMBER["E2-2"].title, dict(p), (
        "At either limit position the guide is tangent to the circle of B, so the crank is "
        "perpendicular to the guide.",), (
        Part("Crank, time ratio and guide", (
            Result("crank length AB", gb.a, "mm", "a = d sin(φ/2), `GuideBar.from_swing(d, φ)`"),
            Result("time ratio K", gb.time_ratio(), "", "θ = φ, K = (180° + θ)/(180° − θ)"),
            Result("shortest guide", gb.min_guide_length(), "mm", "the guide must reach B at its farthest: d + a"),
        ), ()),
    ))


def _sample_e2_2(rng):
    return {"d": _int(rng, 200, 400, 10), "phi": _int(rng, 30, 100, 5)}


# ----------------------------------------------------------------------------- E2-3
def _solve_e2_3(p):
    from mech.planar import SliderCrank

    a, b = positive_length("a", p["a"]), positive_length("b", p["b"])
    e = real_number("e", p["e"])
    if not b > a + abs(e):
        raise ValueError(f"Expected `b` > `a` + |`e`| so that the crank turns fully, got a={a!r}, b={b!r}, e={e!r}")
    sc = SliderCrank(a, b, e)
    how = "`SliderCrank(a, b, e)`, cancellation-free forms of F31"
    return Solution("E2-3", EXAMPLES_BY_NUMBER["E2-3"].title, dict(p), (
        "The slider stops where crank and rod lie on one line (AC = b + a and AC = b − a).",), (
        Part("Extreme angle and stroke", (
            Result("extreme-position angle θ", sc.extreme_angle(), "rad", how),
            Result("stroke H", sc.stroke(), "mm", how),
            Result("time ratio K", sc.time_ratio(), "", "K = (180° + θ)/(180° − θ)"),
        ), ()),
    ))


def _sample_e2_3(rng):
    return {"a": _int(rng, 20, 40), "b": _int(rng, 90, 130, 5), "e": _int(rng, 5, 30)}


# ----------------------------------------------------------------------------- E2-8
def linkage_e2_8(p):
    """The four-bar of worked example 2-8 (a `Linkage`): A = 0, D = AD on +x, crank 1 = AB,
    coupler 2 = BCE with E at ``BE_along`` along B->C and ``BE_left`` to its left, rocker 3 = CD."""
    from mech.planar import Linkage

    ab, bc, cd, ad = (positive_length(n, p[n]) for n in ("AB", "BC", "CD", "AD"))
    return (Linkage({"A": 0.0, "D": ad})
            .crank("1", pivot="A", tip="B", length=ab)
            .rrr(("2", "3"), pins=("B", "D"), joint="C", lengths=(bc, cd), branch=1)
            .point("E", link="2", at=complex(real_number("BE_along", p["BE_along"]),
                                             real_number("BE_left", p["BE_left"]))))


def _solve_e2_8(p):
    theta, w1 = real_number("theta1", p["theta1"]), real_number("omega1", p["omega1"])
    if w1 == 0.0:
        raise ValueError("Expected a turning crank, `omega1` != 0, got 0.0")
    sol = linkage_e2_8(p).solve(theta * _DEG, order=2, omega=w1)
    if not bool(np.all(sol.valid)):
        raise ValueError(f"Expected `theta1` at which the four-bar assembles, got {theta!r}")
    vE, aE = complex(np.ravel(sol.velocities["E"])[0]), complex(np.ravel(sol.accelerations["E"])[0])
    how = "`Linkage.solve(θ1, order=2, ω=ω1)`: the loop equations and their derivatives"
    rate = lambda d, k: float(np.ravel(d[k])[0])
    return Solution("E2-8", EXAMPLES_BY_NUMBER["E2-8"].title, dict(p), (
        "Rates are counter-clockwise positive (ω1 < 0: the crank turns clockwise); C lies above "
        "the line AD.",), (
        Part("Angular velocities", (
            Result("ω2", rate(sol.omegas, "2"), "rad/s", how), Result("ω3", rate(sol.omegas, "3"), "rad/s", how),
        ), ()),
        Part("Angular accelerations", (
            Result("α2", rate(sol.alphas, "2"), "rad/s²", how), Result("α3", rate(sol.alphas, "3"), "rad/s²", how),
        ), ()),
        Part("The coupler point E (velocity and acceleration images)", (
            Result("v_E", abs(vE), "mm/s", "the velocity image of BCE"),
            Result("a_E", abs(aE), "mm/s²", "the acceleration image of BCE"),
        ), ()),
    ))


def _sample_e2_8(rng):
    return {"AB": _int(rng, 20, 30), "BC": _int(rng, 55, 65), "CD": _int(rng, 40, 50), "AD": _int(rng, 50, 60),
            "theta1": _int(rng, 30, 150, 5), "omega1": -_int(rng, 2, 8), "BE_along": _int(rng, 20, 40),
            "BE_left": _int(rng, 10, 25)}


# ----------------------------------------------------------------------------- E2-9
def _solve_e2_9(p):
    from mech.planar import Linkage

    l, w1 = positive_length("l", p["l"]), real_number("omega1", p["omega1"])
    if not w1 > 0.0:
        raise ValueError(f"Expected the crank's speed `omega1` > 0 (it turns clockwise), got {w1!r}")
    lk = (Linkage({"A": 0.0, "C": math.sqrt(2.0) * l})
          .crank("1", pivot="A", tip="B", length=l)
          .rpr(("3", "2"), pins=("C", "B"), offset=l / math.sqrt(2.0), branch=1))
    sol = lk.solve(math.pi / 4, order=2, omega=-w1)
    w3, a3 = float(np.ravel(sol.omegas["3"])[0]), float(np.ravel(sol.alphas["3"])[0])
    slide = abs(float(np.ravel(sol.omegas["1"])[0])) * l * math.sqrt(2.0)   # |v_B2B3| = √2 ω1 l
    how = "`Linkage` crank and RPR group, `solve(order=2)`"
    return Solution("E2-9", EXAMPLES_BY_NUMBER["E2-9"].title, dict(p), (
        "AC horizontal, A = 0, C = √2 l, B = l e^{iπ/4}; rates counter-clockwise positive.",), (
        Part("Guide 3", (
            Result("ω3", w3, "rad/s", how), Result("α3", a3, "rad/s²", how),
            Result("Coriolis acceleration a^k", 2.0 * abs(w3) * slide, "mm/s²", "2 ω3 v_B2B3"),
        ), ("The guide turns with the crank's speed; its angular acceleration comes from the "
            "Coriolis term, since the crank turns at a constant rate.",)),
    ))


def _sample_e2_9(rng):
    return {"l": _int(rng, 50, 200, 10), "omega1": _int(rng, 2, 12)}


# ----------------------------------------------------------------------------- E2-19, E2-20
def _solve_e2_19(p):
    from mech.planar.synthesis import quick_return_slider_crank

    K, H, e = real_number("K", p["K"]), positive_length("H", p["H"]), positive_length("e", p["e"])
    if not 1.0 < K < 3.0:
        raise ValueError(f"Expected a time ratio 1 < `K` < 3 for an offset slider-crank, got {K!r}")
    q = quick_return_slider_crank(K, H, offset=e)
    m = q.check()
    how = "`quick_return_slider_crank(K, H, offset=e)`, eq. (2-46) to (2-52)"
    return Solution("E2-19", EXAMPLES_BY_NUMBER["E2-19"].title, dict(p), (), (
        Part("Design", (
            Result("crank length AB", q.lengths[0], "mm", how), Result("rod length BC", q.lengths[1], "mm", how),
            Result("minimum transmission angle γ_min", q.min_transmission_angle, "rad", "cos γ_min = (a + e)/b"),
        ), (f"Simulated over a crank turn: stroke {m.output_range:.6g} mm, K = {m.time_ratio:.6g}.",)),
    ))


def _sample_e2_19(rng):
    return {"K": _int(rng, 110, 140, 5) / 100.0, "H": _int(rng, 80, 140, 10), "e": _int(rng, 20, 40, 2)}


def _solve_e2_20(p):
    from mech.planar.synthesis import quick_return_guide_bar

    K, d = real_number("K", p["K"]), positive_length("d", p["d"])
    if not 1.0 < K < 1e6:
        raise ValueError(f"Expected a time ratio `K` > 1, got {K!r}")
    q = quick_return_guide_bar(K, d)
    return Solution("E2-20", EXAMPLES_BY_NUMBER["E2-20"].title, dict(p), (), (
        Part("Design", (
            Result("extreme-position angle θ", q.extreme_angle, "rad", "θ = 180° (K − 1)/(K + 1)"),
            Result("crank length AB", q.crank, "mm", "a = d sin(θ/2): the crank is perpendicular to the guide"),
            Result("shortest guide", q.min_guide_length, "mm", "d + a"),
        ), ()),
    ))


def _sample_e2_20(rng):
    return {"K": _int(rng, 120, 250, 5) / 100.0, "d": _int(rng, 200, 400, 10)}


# ----------------------------------------------------------------------------- records
EXAMPLES = (
    _example("E2-1", "Worked example 2-1: limit positions and transmission angle of a four-bar",
             "A revolute four-bar ABCD has the crank a = AB = {a} mm, the coupler b = BC = {b} mm, the "
             "rocker c = CD = {c} mm and the frame d = AD = {d} mm. (1) What type of four-bar is it? "
             "(2) Find the rocker's swing φ, the extreme-position angle θ and the time ratio K. (3) Find "
             "the minimum transmission angle γ_min.",
             (Parameter("a", 10.0), Parameter("b", 40.0), Parameter("c", 30.0), Parameter("d", 35.0)),
             _solve_e2_1, _sample_e2_1),
    _example("E2-2", "Worked example 2-2: an oscillating guide-bar for a given swing",
             "In an oscillating guide-bar mechanism the crank AB turns about A and its block at B slides "
             "on a guide that swings about D. The frame is d = AD = {d} mm and the guide must swing "
             "through φ = {phi}°. Find the crank length AB, the time ratio K and the shortest guide.",
             (Parameter("d", 300.0), Parameter("phi", 60.0, "deg")), _solve_e2_2, _sample_e2_2),
    _example("E2-3", "Worked example 2-3: extreme angle and stroke of an offset slider-crank",
             "An offset slider-crank has the crank a = AB = {a} mm and the rod b = BC = {b} mm; the slider "
             "pin C runs on a line e = {e} mm from the crank centre A. Find the extreme-position angle θ, "
             "the stroke H and the time ratio K.",
             (Parameter("a", 30.0), Parameter("b", 100.0), Parameter("e", 20.0)), _solve_e2_3, _sample_e2_3),
    _example("E2-8", "Worked example 2-8: velocities and accelerations of a four-bar",
             "In the four-bar ABCD, AB = {AB} mm, BC = {BC} mm, CD = {CD} mm and AD = {AD} mm; the point E "
             "of the coupler lies {BE_along} mm along B→C and {BE_left} mm to its left. The crank is at "
             "θ1 = {theta1}° from AD and turns at the constant ω1 = {omega1} rad/s (negative: clockwise). "
             "Find ω2, ω3, α2 and α3 (counter-clockwise positive) and the speed and acceleration of E.",
             (Parameter("AB", 25.0), Parameter("BC", 60.0), Parameter("CD", 45.0), Parameter("AD", 55.0),
              Parameter("theta1", 60.0, "deg"), Parameter("omega1", -4.0, "rad/s"),
              Parameter("BE_along", 30.0), Parameter("BE_left", 20.0)), _solve_e2_8, _sample_e2_8,
             tag="A"),            # the text gives this example without dimensions: they are chosen
    _example("E2-9", "Worked example 2-9: a guide-bar with a Coriolis acceleration",
             "In a guide-bar mechanism AB = BC = l = {l} mm and ∠BAC = 45°; the crank AB turns clockwise at "
             "the constant ω1 = {omega1} rad/s and its block B slides in the slot of guide 3, which turns "
             "about C, the slot perpendicular to AC. Find ω3 and α3 (counter-clockwise positive) and the "
             "size of the Coriolis acceleration of B.",
             (Parameter("l", 100.0), Parameter("omega1", 10.0, "rad/s")), _solve_e2_9, _sample_e2_9),
    _example("E2-19", "Worked example 2-19: an offset slider-crank from its time ratio and stroke",
             "Design an offset slider-crank with the time ratio K = {K}, the stroke H = {H} mm and the "
             "offset e = {e} mm: find the crank AB, the rod BC and the minimum transmission angle γ_min.",
             (Parameter("K", 1.25, ""), Parameter("H", 100.0), Parameter("e", 34.0)), _solve_e2_19, _sample_e2_19),
    _example("E2-20", "Worked example 2-20: an oscillating guide-bar from its time ratio",
             "Design an oscillating guide-bar with the frame AD = {d} mm and the time ratio K = {K}: find the "
             "extreme-position angle θ, the crank AB and the shortest guide.",
             (Parameter("K", 2.0, ""), Parameter("d", 300.0)), _solve_e2_20, _sample_e2_20),
)

#: The examples by number (the solvers read their titles here).
EXAMPLES_BY_NUMBER = {ex.number: ex for ex in EXAMPLES}


# ----------------------------------------------------------------------------- figures
def draw_example(number, p, fig):
    """Draw the figure of worked example ``number`` with the givens ``p`` into ``fig``
    (Matplotlib; the givens only, never an answer)."""
    from mech.exercises import _figures as F

    ax = fig.add_subplot(111)
    if number == "E2-1":
        lk, th = F._fourbar(p["a"], p["b"], p["c"], p["d"], 60.0)
        F.linkage(ax, lk, th, title=f"four-bar (a, b, c, d) = ({p['a']:g}, {p['b']:g}, {p['c']:g}, {p['d']:g}) mm")
    elif number in ("E2-2", "E2-20"):
        a = p["d"] * math.sin(p["phi"] * _DEG / 2) if number == "E2-2" else 0.5 * p["d"]
        F.linkage(ax, F._guide_bar(a, p["d"]), math.radians(60),
                  title=f"guide-bar, AD = {p['d']:g} mm" + (f", swing {p['phi']:g}°" if number == "E2-2" else
                                                              f", K = {p['K']:g}"))
    elif number in ("E2-3", "E2-19"):
        a, b = (p["a"], p["b"]) if number == "E2-3" else (0.3 * p["H"], 1.0 * p["H"])
        F.linkage(ax, F._slider_crank(a, b, p["e"]), math.radians(60),
                  title=f"offset slider-crank, e = {p['e']:g} mm" + (f", H = {p['H']:g} mm, K = {p['K']:g}"
                                                                   if number == "E2-19" else ""))
    elif number == "E2-8":
        F.linkage(ax, linkage_e2_8(p), p["theta1"] * _DEG, title=f"four-bar with coupler point E, θ1 = {p['theta1']:g}°")
    elif number == "E2-9":
        from mech.planar import Linkage

        l = p["l"]
        lk = (Linkage({"A": 0.0, "C": math.sqrt(2.0) * l}).crank("1", pivot="A", tip="B", length=l)
              .rpr(("3", "2"), pins=("C", "B"), offset=l / math.sqrt(2.0), branch=1))
        F.linkage(ax, lk, math.pi / 4, title=f"guide-bar, AB = BC = {l:g} mm, ∠BAC = 45°")
    else:
        raise ValueError(f"Expected `number` to be a worked example with a figure, got {number!r}")


_figures.EXAMPLE_DRAWERS["E"] = draw_example
