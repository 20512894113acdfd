"""Exercises 2-8, 2-9 and 2-11 of chapter 2: instant centres and velocity ratios.

The three figures are lost and the statements carry no numbers (tag "G"): the text asks for
all the instant centres of "each mechanism in the figure" (2-8), for a speed ratio of three
rolling wheels through their relative centre P13 (2-9), and for a ratio omega4/omega2 (2-11).
Each solution states a concrete layout, finds every centre with `mech.planar.instant_centres`
(Kennedy's three-centre theorem, in homogeneous coordinates so that centres at infinity need
no special case) and reads the ratios with `mech.planar.omega_ratio`. ``mechanisms_2_8`` and
the like return the assumed layouts, for figures and checks. The solutions are shown on the
book page ``book-analysis-exercises``.

Examples
--------
>>> from mech.exercises import chapter2_instant_centres as ic
>>> round(float(ic.EXERCISE_2_9.solve()["ω1/ω3"].value), 6)
1.5
"""

from __future__ import annotations

import math

import numpy as np

from mech._validate import positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution, check_links_close, names_givens
from mech.exercises.chapter2_analysis import _around
from mech.planar import FourBar, Guide, Linkage, grashof, instant_centres, omega_ratio, revolute

__all__ = ["EXERCISE_2_8", "EXERCISE_2_9", "EXERCISE_2_11", "mechanisms_2_8", "wheels_2_9", "centres_2_11"]

_DEG = math.pi / 180.0
_FRAME = "4"


def _where(centre, unit="mm"):
    """A centre as text: its coordinates, or the direction of the line it lies at the end of."""
    if not bool(np.all(centre.defined)):
        return "not defined by the positions"
    if bool(np.all(centre.at_infinity)):
        u = complex(centre.direction)
        return f"at infinity in the direction {math.degrees(math.atan2(u.imag, u.real)) % 180.0:.4f}° (mod 180°)"
    z = complex(centre.point)
    return f"({z.real:.4f}, {z.imag:.4f}) {unit}"


def _label(pair):
    return "P" + "".join(_FRAME if k == "ground" else str(k) for k in sorted(pair, key=lambda k: "4" if k == "ground"
                                                                         else str(k)))


# ----------------------------------------------------------------------------- 2-8
_STATEMENT_2_8 = (
    "Find all the instant centres of each mechanism in the position shown. (The figure is lost; "
    "three common mechanisms are assumed, each with crank AB = {a} mm at θ = {theta}°: (a) a four-bar "
    "with BC = {b} mm, CD = {c} mm and frame AD = {d} mm; (b) an offset slider-crank with rod "
    "BC = {b} mm and offset e = {e} mm; (c) an oscillating guide-bar whose slotted link turns about D, "
    "AD = {d} mm from A.)"
)


def _check_2_8(p):
    a, b, c, d = (positive_length(n, p[n]) for n in ("a", "b", "c", "d"))
    e, theta = real_number("e", p["e"]), real_number("theta", p["theta"]) * _DEG
    check_links_close(a=a, b=b, c=c, d=d)          # the four-bar (a), under the exercise's names
    if a >= d:
        raise ValueError(f"Expected `a` < `d` = {d!r} so that the guide bar of (c) oscillates, got {a!r}")
    if a + abs(e) >= b:
        raise ValueError(f"Expected `a` + |`e`| < `b` = {b!r} so that the slider-crank (b) turns fully, got {a + abs(e)!r}")
    return a, b, c, d, e, theta


@names_givens("2-8")
def mechanisms_2_8(params=None):
    """The three assumed mechanisms of exercise 2-8, as a dict of name to `Linkage`.

    Links are named ``"1"`` (the crank AB), ``"2"``, ``"3"``; the frame (``"ground"``) is
    link 4. ``"four-bar"``: A = 0, D = d; coupler 2 = BC, rocker 3 = DC, C above the frame
    line. ``"slider-crank"``: A = 0; rod 2 = BC; slider 3 (pin C) on the line y = e, to the
    right of B. ``"guide-bar"``: A = 0, D = d; block 2 at B slides in guide bar 3, which
    turns about D.

    >>> from mech.exercises.chapter2_instant_centres import mechanisms_2_8
    >>> sorted(mechanisms_2_8())
    ['four-bar', 'guide-bar', 'slider-crank']
    """
    p = EXERCISE_2_8.params(params)
    a, b, c, d, e, _ = _check_2_8(p)
    return {
        "four-bar": (Linkage({"A": 0.0, "D": d}).crank("1", pivot="A", tip="B", length=a)
                     .rrr(("2", "3"), pins=("B", "D"), joint="C", lengths=(b, c), branch=1)),
        "slider-crank": (Linkage({"A": 0.0}).crank("1", pivot="A", tip="B", length=a)
                         .rrp(("2", "3"), pin="B", guide=Guide("ground", through=1j * e, angle=0.0), joint="C",
                              length=b, branch=1)),
        "guide-bar": (Linkage({"A": 0.0, "D": d}).crank("1", pivot="A", tip="B", length=a)
                      .rpr(("3", "2"), pins=("D", "B"), offset=0.0, branch=1)),
    }


@names_givens("2-8")
def _solve_2_8(p):
    a, b, c, d, e, theta = _check_2_8(p)
    parts = []
    for key, lk in mechanisms_2_8(p).items():
        sol = lk.solve(theta, order=1)
        if not bool(np.all(sol.valid)):
            raise ValueError(f"Expected the {key} of exercise 2-8 to assemble at θ = {math.degrees(theta)!r}°")
        ic = sol.instant_centres()
        results = []
        for pair in ic.pairs():
            centre = ic[pair]
            how = {"revolute": "a revolute pair", "prismatic": "a sliding pair: at infinity across the guide"}.get(
                centre.source, "Kennedy's theorem: on the line through two pairs of known centres")
            results.append(Result(_label(pair), _where(centre), "", how))
        w = {k: float(v) for k, v in sol.omegas.items()}
        parts.append(Part(f"({'abc'[len(parts)]}) the {key}", tuple(results), (
            f"{len(results)} centres for 4 links (n(n − 1)/2 = 6). Check: every centre moves with the same "
            "velocity as a point of either link; ω of links 1, 2, 3 per unit ω1: "
            + ", ".join(f"{w[k]:.6f}" for k in ("1", "2", "3")) + ".",)))
    assumptions = (
        "The figure is lost. Three common mechanisms are taken: (a) a hinged four-bar ABCD with frame AD, "
        "(b) an offset slider-crank, (c) an oscillating guide-bar (crank AB, block 2 at B sliding in "
        "the slotted link 3 pivoted at D).",
        "Numbering: 1 the crank AB, 2 the coupler / rod / block, 3 the rocker / slider / guide bar, 4 the "
        "frame. A = (0, 0); D = (AD, 0); θ is the crank angle from +x, counter-clockwise; C is above the "
        "frame line in (a) and to the right of B in (b).",
    )
    return Solution("2-8", EXERCISE_2_8.title, dict(p), (), tuple(parts), assumptions=assumptions)


def _sample_2_8(rng):
    return {"a": _around(rng, 30, 0.2), "b": _around(rng, 90, 0.15), "c": _around(rng, 70, 0.15),
            "d": _around(rng, 80, 0.15), "e": _around(rng, 15, 0.5), "theta": float(15 * rng.integers(1, 24))}


# ----------------------------------------------------------------------------- 2-9
_STATEMENT_2_9 = (
    "In a geared linkage three round wheels roll on one another without slipping. Using the relative "
    "instant centre P13, find the speed ratio of wheel 1 to wheel 3. (The figure is lost; assumed "
    "radii r1 = {r1} mm, r2 = {r2} mm, r3 = {r3} mm, and the angle ABC = {beta}° between the lines "
    "joining wheel 2's centre B to the centres A and C of wheels 1 and 3.)"
)


#: The smallest wheel of exercise 2-9 against the largest (2**-20 ~ 1e-6): the ratio found
#: through P13 then keeps about ten digits.
_SMALLEST_WHEEL = 2.0**-20


@names_givens("2-9")
def wheels_2_9(params=None):
    """Centres and contact points of exercise 2-9's assumed wheels, as a dict of complex points.

    B = 0 (wheel 2's centre), A = r1 + r2 on +x (wheel 1), C = (r2 + r3) at the angle ABC
    from +x (wheel 3); ``P12`` and ``P23`` are the rolling contacts.

    >>> from mech.exercises.chapter2_instant_centres import wheels_2_9
    >>> abs(wheels_2_9()["P12"] - 30.0) < 1e-12
    True
    """
    p = EXERCISE_2_9.params(params)
    r1, r2, r3 = (positive_length(n, p[n]) for n in ("r1", "r2", "r3"))
    beta = real_number("beta", p["beta"])
    if not 0.0 < beta < 180.0 or math.sin(beta * _DEG) * (r2 + r3) <= 0.0:
        raise ValueError(f"Expected 0 < `beta` < 180 degrees (A, B and C not in one line), got {beta!r}")
    radii = {"r1": r1, "r2": r2, "r3": r3}
    largest = max(radii, key=radii.get)
    for name in ("r1", "r3"):
        # P13 lies about r1 (or r3) from A (or C) on AC; built from contacts whose rounding is
        # eps * the largest radius, its distances keep no digits when the wheel is much smaller
        if radii[name] < _SMALLEST_WHEEL * radii[largest]:
            raise ValueError(f"Expected `{name}` at least 2**-20 times the largest radius `{largest}` = "
                             f"{radii[largest]!r} so that the instant centre P13 is resolved, got {radii[name]!r}")
    u = complex(np.exp(1j * beta * _DEG))
    if abs((r1 + r2) - (r2 + r3) * u) <= r1 + r3:
        raise ValueError(f"Expected `r1`, `r2`, `r3` and `beta` that keep wheels 1 and 3 apart (|AC| > r1 + r3), "
                         f"got r1={r1!r}, r2={r2!r}, r3={r3!r}, beta={beta!r}")
    return {"A": complex(r1 + r2), "B": 0j, "C": (r2 + r3) * u, "P12": complex(r2), "P23": r2 * u}


@names_givens("2-9")
def _solve_2_9(p):
    g = wheels_2_9(p)
    r1, r3 = p["r1"], p["r3"]
    # links: 1, 2, 3 the wheels, 4 the frame carrying the three axes
    direct = {(1, 4): revolute(g["A"]), (2, 4): revolute(g["B"]), (3, 4): revolute(g["C"]),
              (1, 2): revolute(g["P12"]), (2, 3): revolute(g["P23"])}
    ic = instant_centres((1, 2, 3, 4), direct)
    p13 = complex(ic[1, 3].point)
    ratio = float(omega_ratio(ic, 1, 3, 4))
    assumptions = (
        "Wheels 1, 2 and 3 turn about axes A, B and C fixed in the frame 4, and A, B, C are not in one "
        "line; wheel 2 touches wheel 1 and wheel 3 on the outside (external rolling); 1 and 3 do not touch.",
        "B = (0, 0), A on +x at r1 + r2, C at r2 + r3 along the direction at the angle ABC.",
    )
    part = Part("Speed ratio through P13", (
        Result("P14, P24, P34", "the axes A, B, C", "", "revolute pairs with the frame"),
        Result("P12", f"({g['P12'].real:.4f}, {g['P12'].imag:.4f}) mm", "", "the contact of wheels 1 and 2"),
        Result("P23", f"({g['P23'].real:.4f}, {g['P23'].imag:.4f}) mm", "", "the contact of wheels 2 and 3"),
        Result("P13", f"({p13.real:.4f}, {p13.imag:.4f}) mm", "",
               "`instant_centres`: line P12 P23 meets line P14 P34 = AC"),
        Result("ω1/ω3", ratio, "", "`omega_ratio(centres, 1, 3, 4)` = P13C / P13A, signed"),
        Result("r3/r1", r3 / r1, "", "the same ratio from the pitch radii"),
        Result("senses", "the same" if ratio > 0 else "opposite", "", "P13 outside the segment AC: the same"),
    ), ("At P13 wheels 1 and 3 have the same velocity, so ω1·AP13 = ω3·CP13. P13 lies on AC beyond the "
        "wheels, so 1 and 3 turn the same way, and the ratio equals r3/r1 whatever wheel 2 and the angle "
        "ABC: the idler changes neither.",))
    return Solution("2-9", EXERCISE_2_9.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_9(rng):
    return {"r1": float(rng.integers(10, 60)), "r2": float(rng.integers(10, 60)), "r3": float(rng.integers(10, 60)),
            "beta": float(rng.integers(60, 171))}


# ----------------------------------------------------------------------------- 2-11
_STATEMENT_2_11 = (
    "Find the ratio ω4/ω2 of the angular velocities of member 4 and member 2 of the linkage. (The "
    "figure is lost; assumed: a hinged four-bar with frame 1 = AD = {d} mm, crank 2 = AB = {a} mm, "
    "coupler 3 = BC = {b} mm and rocker 4 = DC = {c} mm, at the crank angle θ = {theta}°.)"
)


@names_givens("2-11")
def centres_2_11(params=None):
    """All instant centres of exercise 2-11's assumed four-bar, with links numbered 1 to 4.

    Link 1 is the frame, 2 the crank AB, 3 the coupler BC, 4 the rocker DC; A = 0, D = d;
    C above the frame line. Returns `mech.planar.InstantCentres`.

    >>> from mech.exercises.chapter2_instant_centres import centres_2_11
    >>> len(centres_2_11())
    6
    """
    p = EXERCISE_2_11.params(params)
    a, b, c, d = (positive_length(n, p[n]) for n in ("a", "b", "c", "d"))
    theta = real_number("theta", p["theta"]) * _DEG
    check_links_close(a=a, b=b, c=c, d=d, resolved=True)
    pose = FourBar(a, b, c, d).solve(theta)
    if not bool(np.all(pose.valid)):
        raise ValueError(f"Expected the four-bar of exercise 2-11 to assemble at `theta` = {p['theta']!r}")
    direct = {(1, 2): revolute(0j), (2, 3): revolute(complex(pose.B)), (3, 4): revolute(complex(pose.C)),
              (1, 4): revolute(complex(d))}
    return instant_centres((1, 2, 3, 4), direct)


@names_givens("2-11")
def _solve_2_11(p):
    ic = centres_2_11(p)
    a, b, c, d = (p[n] for n in ("a", "b", "c", "d"))
    theta = p["theta"] * _DEG
    ratio = float(omega_ratio(ic, 4, 2, 1))
    check = FourBar(a, b, c, d).solve(theta, order=1, omega=1.0)
    p24 = complex(ic[2, 4].point)
    assumptions = (
        "A hinged four-bar (the most common reading): frame 1 = AD, crank 2 = AB, coupler 3 = BC, "
        "rocker 4 = DC; A = (0, 0), D = (AD, 0), θ from +x counter-clockwise, C above the frame line.",
    )
    part = Part("The ratio ω4/ω2", (
        Result("P24", _where(ic[2, 4]), "", "`instant_centres`: line AD (P12 P14) meets line BC (P23 P34)"),
        Result("P13", _where(ic[1, 3]), "", "line AB (P12 P23) meets line DC (P14 P34)"),
        Result("ω4/ω2", ratio, "", "`omega_ratio(centres, 4, 2, 1)` = P12P24 / P14P24, signed"),
        Result("ω4/ω2 by the loop equations", float(check.omega_output), "", "`FourBar.solve(θ, order=1)`"),
        Result("type", grashof(a, b, c, d).kind, "", "`grashof`"),
    ), (f"At P24 = ({p24.real:.4f}, {p24.imag:.4f}) mm links 2 and 4 have the same velocity: "
        "ω2·AP24 = ω4·DP24. P24 outside the segment AD means the two turn the same way.",))
    return Solution("2-11", EXERCISE_2_11.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_11(rng):
    return {"a": _around(rng, 30, 0.2), "b": _around(rng, 80, 0.15), "c": _around(rng, 60, 0.15),
            "d": _around(rng, 70, 0.15), "theta": float(15 * rng.integers(1, 24))}


# ----------------------------------------------------------------------------- registry
EXERCISE_2_8 = Exercise(
    number="2-8", title="All instant centres of three common mechanisms", tag="G", statement=_STATEMENT_2_8,
    parameters=(Parameter("a", 30.0, "mm", "assumed crank AB"), Parameter("b", 90.0, "mm", "assumed coupler / rod"),
                Parameter("c", 70.0, "mm", "assumed rocker of (a)"), Parameter("d", 80.0, "mm", "assumed frame AD"),
                Parameter("e", 15.0, "mm", "assumed offset of (b)"), Parameter("theta", 60.0, "°", "assumed crank angle")),
    solver=_solve_2_8, sampler=_sample_2_8,
)
EXERCISE_2_9 = Exercise(
    number="2-9", title="Speed ratio of three rolling wheels through P13", tag="G", statement=_STATEMENT_2_9,
    parameters=(Parameter("r1", 20.0, "mm", "assumed radius of wheel 1"),
                Parameter("r2", 30.0, "mm", "assumed radius of wheel 2"),
                Parameter("r3", 30.0, "mm", "assumed radius of wheel 3"),
                Parameter("beta", 120.0, "°", "assumed angle ABC at wheel 2's centre")),
    solver=_solve_2_9, sampler=_sample_2_9,
)
EXERCISE_2_11 = Exercise(
    number="2-11", title="Angular velocity ratio ω4/ω2 by instant centres", tag="G", statement=_STATEMENT_2_11,
    parameters=(Parameter("a", 30.0, "mm", "assumed crank 2 = AB"), Parameter("b", 80.0, "mm", "assumed coupler 3"),
                Parameter("c", 60.0, "mm", "assumed rocker 4"), Parameter("d", 70.0, "mm", "assumed frame 1 = AD"),
                Parameter("theta", 60.0, "°", "assumed crank angle")),
    solver=_solve_2_11, sampler=_sample_2_11,
)

EXERCISES = (EXERCISE_2_8, EXERCISE_2_9, EXERCISE_2_11)
