"""Exercises 2-12 to 2-16 of chapter 2: velocity and acceleration by relative motion.

The textbook asks for these by the graphical relative-motion method (相对运动图解法):
velocity and acceleration polygons drawn to scale. Here each assumed layout is built as a
`mech.planar.Linkage` and solved; the polygons of the book page are drawn from the vectors
that `mech.planar.relative_motion` computes from the same solution, so a reader can compare
them with a drawing by hand. The figures are lost (tag "A"), so every solution states its
layout first. ``linkage_2_13`` and the like return the assumed linkage. The solutions are
shown on the book page ``book-analysis-exercises``.

Examples
--------
>>> from mech.exercises import chapter2_relative_motion as rm
>>> round(float(rm.EXERCISE_2_15.solve()["ω3"].value), 4)
-1.9654
"""

from __future__ import annotations

import math

import numpy as np

from mech._validate import positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution, check_links_close, names_givens
from mech.exercises.chapter2_analysis import _along, _around, _stroke
from mech.planar import Guide, Linkage, grashof

_DEG = math.pi / 180.0

__all__ = ["EXERCISE_2_12", "EXERCISE_2_13", "EXERCISE_2_14", "EXERCISE_2_15", "EXERCISE_2_16", "linkage_2_12",
           "linkage_2_13", "linkage_2_14", "linkage_2_15", "linkage_2_16"]


def _sense(w):
    return "counter-clockwise" if w > 0 else "clockwise"


def _pose(lk, theta, omega, what):
    sol = lk.solve(theta, order=2, omega=omega)
    if not bool(np.all(sol.valid)):
        raise ValueError(f"Expected the assumed layout of exercise {what} to assemble at the crank angle "
                         f"asked for, got a pose that does not close")
    return sol


# ----------------------------------------------------------------------------- 2-13
_STATEMENT_2_13 = (
    "The six-bar linkage of a hay press (干草压缩机) has OA = {OA} mm, AB = {AB} mm, BC = {BC} mm, "
    "BD = {BD} mm and CE = {CE} mm, with x_D = {xD} mm, y_D = {yD} mm and y_E = {yE} mm; the crank "
    "turns at ω1 = {omega1} rad/s. (1) Find the displacement of the piston E over one cycle "
    "(graphically in the text). (2) Find the velocity and acceleration of E when the crank OA is "
    "at φ1 = 0 (by the relative-motion graphical method in the text)."
)


def _check_2_13(p):
    oa, ab, bc, bd, ce = (positive_length(n, p[n]) for n in ("OA", "AB", "BC", "BD", "CE"))
    xd, yd, ye, w = (real_number(n, p[n]) for n in ("xD", "yD", "yE", "omega1"))
    if bc >= bd:
        raise ValueError(f"Expected `BC` < `BD` = {bd!r} (C between B and D), got {bc!r}")
    kind = grashof(oa, ab, bd, abs(complex(xd, yd))).kind
    if kind != "crank-rocker":
        raise ValueError(f"Expected O-A-B-D to be a crank-rocker with OA the crank, got a {kind}")
    return oa, ab, bc, bd, ce, xd, yd, ye, w


@names_givens("2-13")
def linkage_2_13(params=None):
    """The hay-press six-bar of exercise 2-13 on its assumed layout, as a `mech.planar.Linkage`.

    O = 0 (crank pivot), D = x_D + i y_D; crank OA (input: its angle from +x); coupler AB and
    rocker DB, B to the right of A->D (``branch=-1``); C on the rocker between B and D,
    BC from B; rod CE; piston E on the line y = y_E, to the right of C. Links ``crank,
    coupler, rocker, rod, piston``.

    >>> from mech.exercises.chapter2_relative_motion import linkage_2_13
    >>> linkage_2_13().groups
    ('crank crank', 'RRR coupler-rocker', 'RRP rod-piston')
    """
    p = EXERCISE_2_13.params(params)
    oa, ab, bc, bd, ce, xd, yd, ye, _ = _check_2_13(p)
    return (Linkage({"O": 0.0, "D": complex(xd, yd)})
            .crank("crank", pivot="O", tip="A", length=oa)
            .rrr(("coupler", "rocker"), pins=("A", "D"), joint="B", lengths=(ab, bd), branch=-1)
            .point("C", link="rocker", at=bd - bc)
            .rrp(("rod", "piston"), pin="C", guide=Guide("ground", through=1j * ye, angle=0.0),
                 joint="E", length=ce, branch=1))


@names_givens("2-13")
def _solve_2_13(p):
    oa, ab, bc, bd, ce, xd, yd, ye, w = _check_2_13(p)
    lk = linkage_2_13(p)
    if not bool(np.all(lk.solve(np.linspace(0.0, 2 * math.pi, 721)).valid)):
        raise ValueError("Expected the assumed hay press to assemble over a full crank turn, got a pose that "
                         "does not close")
    st = _stroke(lambda t: _along(lk, "E", 1.0, t), what="the piston E")
    sol = _pose(lk, 0.0, w, "2-13")
    table = lk.solve(np.radians(np.arange(0.0, 360.0, 30.0))).points["E"].real
    how = "`Linkage` of the assumed layout"
    assumptions = (
        f"O is the crank's fixed pivot at the origin and D = ({xd:g}, {yd:g}) mm the rocker's fixed "
        f"pivot; x to the right, y up. O-A-B-D is a crank-rocker: crank OA, coupler AB, rocker DB.",
        "B lies to the right of the line from A to D (the assembly with the long piston stroke).",
        f"C is a point of the rocker on the segment BD, BC = {bc:g} mm from B (DC = {bd - bc:g} mm).",
        f"The piston E moves along the horizontal line y = y_E = {ye:g} mm, to the right of C, "
        "driven by the rod CE.",
        "φ1 is the angle of O->A from +x, counter-clockwise; the crank turns counter-clockwise "
        "(the text does not give the sense).",
    )
    part1 = Part("(1) Displacement of E over a cycle", (
        Result("x_E at φ1 = 0", float(sol.points["E"].real), "mm", how),
        Result("leftmost x_E", float(_along(lk, "E", 1.0, st["theta_low"])[0]), "mm",
               how + ": piston reversal refined by bisection"),
        Result("rightmost x_E", float(_along(lk, "E", 1.0, st["theta_high"])[0]), "mm", how),
        Result("stroke H of E", st["stroke"], "mm", how),
        Result("crank angle at the leftmost position", st["theta_low"], "rad", how),
        Result("crank angle at the rightmost position", st["theta_high"], "rad", how),
        Result("time ratio K", st["time_ratio"], "", "crank turn while E moves right / left"),
    ), ("x_E every 30° of φ1 from 0°: " + ", ".join(f"{x:.1f}" for x in table) + " mm. A drawing "
        "by hand finds the same positions by striking arcs at each crank position.",))
    v, a = complex(sol.velocities["E"]), complex(sol.accelerations["E"])
    part2 = Part("(2) Velocity and acceleration of E at φ1 = 0", (
        Result("v_E", v.real / 1000.0, "m/s", "`Linkage.solve(0, order=2, omega=ω1)`; + is to the right"),
        Result("a_E", a.real / 1000.0, "m/s²", "same solution; + is to the right"),
        Result("ω of the coupler AB", float(sol.omegas["coupler"]), "rad/s", how + " (+ counter-clockwise)"),
        Result("ω of the rocker DB", float(sol.omegas["rocker"]), "rad/s", how),
        Result("ω of the rod CE", float(sol.omegas["rod"]), "rad/s", how),
        Result("α of the coupler AB", float(sol.alphas["coupler"]), "rad/s²", how),
        Result("α of the rocker DB", float(sol.alphas["rocker"]), "rad/s²", how),
        Result("α of the rod CE", float(sol.alphas["rod"]), "rad/s²", how),
    ), ("The polygons are the equations v_B = v_A + v_BA (v_B ⊥ DB), v_C from the velocity image of "
        "the rocker (dc/db = DC/DB), v_E = v_C + v_EC (v_E along the guide), and the same with normal "
        "and tangential parts for the accelerations; `mech.planar.relative_motion` builds each from "
        "the solution.",))
    return Solution("2-13", EXERCISE_2_13.title, dict(p), (), (part1, part2), assumptions=assumptions)


def _sample_2_13(rng):
    return {"OA": _around(rng, 150, 0.15), "AB": _around(rng, 600, 0.08), "BC": _around(rng, 120, 0.2),
            "BD": _around(rng, 500, 0.08), "CE": _around(rng, 600, 0.1), "xD": _around(rng, 400, 0.1),
            "yD": _around(rng, 500, 0.1), "yE": _around(rng, 600, 0.1), "omega1": _around(rng, 10, 0.5)}


# ----------------------------------------------------------------------------- 2-15
_STATEMENT_2_15 = (
    "In a six-bar linkage ∠CAE = 90°, AB = {AB} mm, BC = {BC} mm, BD = {BD} mm and DE = {DE} mm; the "
    "crank turns counter-clockwise at a constant ω1 = {omega1} rad/s. When ∠BAE = {phi1}°, find the "
    "angular velocity and angular acceleration of member 3 and the velocity and acceleration of "
    "member 5 (by the relative-motion graphical method in the text)."
)


def _check_2_15(p):
    ab, bc, bd, de = (positive_length(n, p[n]) for n in ("AB", "BC", "BD", "DE"))
    phi, w = real_number("phi1", p["phi1"]), real_number("omega1", p["omega1"])
    if ab >= bc:
        raise ValueError(f"Expected `AB` < `BC` = {bc!r} so that the crank turns fully, got {ab!r}")
    if bd >= bc:
        raise ValueError(f"Expected `BD` < `BC` = {bc!r} (D between B and C), got {bd!r}")
    return ab, bc, bd, de, math.radians(phi), w


@names_givens("2-15")
def linkage_2_15(params=None):
    """The six-bar of exercise 2-15 on its assumed layout, as a `mech.planar.Linkage`.

    A = 0; the slider 5 (point E) runs on the x axis (line AE), the slider 2 (point C) on the
    y axis (line AC), so ∠CAE = 90°; crank AB (1, input: ∠BAE from +x); coupler 3 = BC with D
    on it at BD from B; rod 4 = DE. C above B, E to the right of D. Links ``crank, link3,
    slider2, rod4, slider5``.

    >>> from mech.exercises.chapter2_relative_motion import linkage_2_15
    >>> linkage_2_15().groups
    ('crank crank', 'RRP link3-slider2', 'RRP rod4-slider5')
    """
    p = EXERCISE_2_15.params(params)
    ab, bc, bd, de, _, _ = _check_2_15(p)
    return (Linkage({"A": 0.0})
            .crank("crank", pivot="A", tip="B", length=ab)
            .rrp(("link3", "slider2"), pin="B", guide=Guide("ground", through=0j, angle=math.pi / 2),
                 joint="C", length=bc, branch=1)
            .point("D", link="link3", at=bd)
            .rrp(("rod4", "slider5"), pin="D", guide=Guide("ground", through=0j, angle=0.0),
                 joint="E", length=de, branch=1))


@names_givens("2-15")
def _solve_2_15(p):
    ab, bc, bd, de, phi, w = _check_2_15(p)
    sol = _pose(linkage_2_15(p), phi, w, "2-15")
    how = "`Linkage.solve(∠BAE, order=2, omega=ω1)` of the assumed layout"
    assumptions = (
        "C and E are the pins of two sliders on two straight guides through A at right angles "
        "(∠CAE = 90°): E (member 5) on the horizontal line AE, C (member 2) on the vertical line AC.",
        "Members: 1 the crank AB, 2 the slider at C, 3 the coupler BC carrying D, 4 the rod DE, "
        "5 the slider at E. D lies on the segment BC, BD from B.",
        "∠BAE is measured from A->E (+x) counter-clockwise, so B is above AE; C is above B and E "
        "to the right of D.",
        "The text says 'relative-displacement' (相对位移) graphics; read as relative-motion, as in 2-13.",
    )
    part = Part(f"At ∠BAE = {math.degrees(phi):g}°", (
        Result("ω3", float(sol.omegas["link3"]), "rad/s", how + " (+ counter-clockwise)"),
        Result("α3", float(sol.alphas["link3"]), "rad/s²", how),
        Result("v5", float(sol.velocities["E"].real) / 1000.0, "m/s", how + "; + is A->E"),
        Result("a5", float(sol.accelerations["E"].real) / 1000.0, "m/s²", how + "; + is A->E"),
        Result("sense of ω3", _sense(float(sol.omegas["link3"])), "", "sign of ω3"),
        Result("v_C (slider 2)", float(sol.velocities["C"].imag) / 1000.0, "m/s", how + "; + is upward"),
        Result("a_C (slider 2)", float(sol.accelerations["C"].imag) / 1000.0, "m/s²", how),
    ), ("Polygons: v_C = v_B + v_CB with v_C vertical, which gives ω3 = |v_CB|/BC; v_D from the image "
        "of BC (bd/bc = BD/BC); v_E = v_D + v_ED with v_E horizontal. The accelerations follow with "
        "a_CB^n = ω3² BC and the tangential parts unknown in size.",))
    return Solution("2-15", EXERCISE_2_15.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_15(rng):
    return {"AB": _around(rng, 150, 0.2), "BC": _around(rng, 550, 0.1), "BD": _around(rng, 80, 0.3),
            "DE": _around(rng, 500, 0.1), "phi1": float(15 * rng.integers(1, 12)), "omega1": _around(rng, 10, 0.5)}


# ----------------------------------------------------------------------------- 2-16
_STATEMENT_2_16 = (
    "In a six-bar linkage AB = {AB} mm, BC = {BC} mm, CD = {CD} mm, x_F = {xF} mm, x_D = {xD} mm and "
    "y_D = {yD} mm; the crank turns at ω1 = {omega1} rad/s. Find the velocity and acceleration of the "
    "point F of member 5 when the crank angle is φ1 = {phi1}° (by the relative-motion graphical "
    "method in the text)."
)


def _check_2_16(p):
    ab, bc, cd = (positive_length(n, p[n]) for n in ("AB", "BC", "CD"))
    xf, xd, yd, w, phi = (real_number(n, p[n]) for n in ("xF", "xD", "yD", "omega1", "phi1"))
    return ab, bc, cd, xf, xd, yd, w, math.radians(phi)


@names_givens("2-16")
def linkage_2_16(params=None):
    """The six-bar of exercise 2-16 on its assumed layout, as a `mech.planar.Linkage`.

    A = 0 (crank pivot), D = x_D + i y_D; crank AB (input: the angle of A->B from +x,
    counter-clockwise; the book's φ1 is its negative); coupler BC, rocker DC with C to the
    right of B->D (``branch=-1``); block 4 pinned at F slides along the rocker's line DC;
    slider 5 carries F along the vertical line x = x_F. Links ``1`` (crank), ``2`` (coupler),
    ``3`` (rocker), ``4`` (block), ``5`` (slider), numbered as in the text.

    >>> from mech.exercises.chapter2_relative_motion import linkage_2_16
    >>> linkage_2_16().groups
    ('crank 1', 'RRR 2-3', 'PRP 4-5')
    """
    p = EXERCISE_2_16.params(params)
    ab, bc, cd, xf, xd, yd, _, _ = _check_2_16(p)
    return (Linkage({"A": 0.0, "D": complex(xd, yd)})
            .crank("1", pivot="A", tip="B", length=ab)
            .rrr(("2", "3"), pins=("B", "D"), joint="C", lengths=(bc, cd), branch=-1)
            .prp(("4", "5"), guides=(Guide("3", 0j, 0.0), Guide("ground", complex(xf), math.pi / 2)),
                 joint="F"))


@names_givens("2-16")
def _solve_2_16(p):
    ab, bc, cd, xf, xd, yd, w, phi = _check_2_16(p)
    # the book's φ1 is measured clockwise and the crank turns clockwise: input -φ1, rate -ω1
    sol = _pose(linkage_2_16(p), -phi, -w, "2-16")
    how = "`Linkage.solve(-φ1, order=2, omega=-ω1)` of the assumed layout"
    D = complex(xd, yd)
    bd = abs(D - ab * np.exp(1j * phi))
    # why clockwise: for the given lengths the counter-clockwise reading may or may not close
    if bd < cd - bc:
        ccw_note = (f"Measured counter-clockwise, B would be only {bd:.1f} mm from D, less than CD − BC = "
                    f"{cd - bc:g} mm, and the loop could not close.")
    elif bd > cd + bc:
        ccw_note = (f"Measured counter-clockwise, B would be {bd:.1f} mm from D, more than CD + BC = "
                    f"{cd + bc:g} mm, and the loop could not close.")
    else:
        ccw_note = (f"Measured counter-clockwise the loop would close too (BD = {bd:.1f} mm); the clockwise "
                    "reading is kept because with the default lengths it is the only one that closes.")
    kind = grashof(ab, bc, cd, abs(D)).kind
    # the note follows the lengths given: a variant may make the crank revolve
    links = sorted((ab, bc, cd, abs(D)))
    sums = f"shortest + longest = {links[0] + links[3]:.1f} mm against {links[1] + links[2]:.1f} mm for the other two"
    if kind in ("crank-rocker", "double-crank"):
        grashof_note = f"The four-bar is a {kind} ({sums}): the crank AB turns fully."
    else:
        grashof_note = (f"The four-bar is a {kind} ({sums}): the crank cannot turn fully, which does not "
                        "matter for one instant but casts doubt on the reading of the lost figure.")
    assumptions = (
        f"A is the crank's fixed pivot at the origin, D = ({xd:g}, {yd:g}) mm the fixed pivot of the "
        "rocker CD; x to the right, y up. A-B-C-D is a four-bar: crank AB (1), coupler BC (2), rocker "
        "DC (3).",
        "Member 5 is a slider on the vertical guide x = x_F; its pin F carries a block (member 4) that "
        "slides along the rocker's line DC. No length ends at F, which is why F needs only x_F.",
        "φ1 is measured from +x clockwise (B below AD), and the crank turns clockwise. " + ccw_note,
        "C lies to the right of the line from B to D, so that F falls between D and C.",
    )
    v, a = complex(sol.velocities["F"]), complex(sol.accelerations["F"])
    part = Part(f"At φ1 = {math.degrees(phi):g}°", (
        Result("v_F", v.imag / 1000.0, "m/s", how + "; + is upward"),
        Result("a_F", a.imag / 1000.0, "m/s²", how + "; + is upward"),
        Result("y_F", float(sol.points["F"].imag), "mm", how),
        Result("ω of the rocker DC", float(sol.omegas["3"]), "rad/s", how + " (+ counter-clockwise)"),
        Result("α of the rocker DC", float(sol.alphas["3"]), "rad/s²", how),
        Result("sliding speed of block 4 on DC", float(sol.slides[("4", "3")].v) / 1000.0, "m/s", how),
    ), ("Polygons: v_C = v_B + v_CB (v_C ⊥ DC); then the coincident points F5 and F3: "
        "v_F4 = v_F3 + v_F4F3 with v_F4 = v_F5 vertical and v_F4F3 along DC, and "
        "a_F4 = a_F3 + a^k_F4F3 + a^r_F4F3 with the Coriolis term 2 ω3 v_F4F3.",
        grashof_note,))
    return Solution("2-16", EXERCISE_2_16.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_16(rng):
    return {"AB": _around(rng, 200, 0.15), "BC": _around(rng, 500, 0.1), "CD": _around(rng, 800, 0.05),
            "xF": _around(rng, 400, 0.1), "xD": _around(rng, 350, 0.1), "yD": _around(rng, 350, 0.1),
            "omega1": _around(rng, 100, 0.5), "phi1": float(15 * rng.integers(1, 6))}


# ----------------------------------------------------------------------------- 2-12
_STATEMENT_2_12 = (
    "In a pantograph (缩放机构) the angular velocity ω1 of member 1 is known. Draw the velocity "
    "polygon of the mechanism and show the velocity v_I of the point I. (The figure is lost; assumed: "
    "OB = BA = {a} mm, BE = AD = {b} mm, the guide of E at y = {h} mm, member 1 at θ1 = {theta1}° "
    "turning at ω1 = {omega1} rad/s.)"
)


def _check_2_12(p):
    a, b = positive_length("a", p["a"]), positive_length("b", p["b"])
    h, theta, w = (real_number(n, p[n]) for n in ("h", "theta1", "omega1"))
    return a, b, h, theta * _DEG, w


@names_givens("2-12")
def linkage_2_12(params=None):
    """The pantograph of exercise 2-12 on its assumed layout, as a `mech.planar.Linkage`.

    O = 0 is the fixed pivot; member 1 = O-B-A (OB = BA = a, input: its angle); member 4 = BE
    (b); slider 5 carries E along the line y = h, E to the right of B; member 2 = A-D-I (AD = b,
    DI = b) and member 3 = ED (a) close the parallelogram B-A-D-E, so O, E, I stay on one line
    with OI = 2 OE.

    >>> from mech.exercises.chapter2_relative_motion import linkage_2_12
    >>> linkage_2_12().groups
    ('crank 1', 'RRP 4-5', 'RRR 2-3')
    """
    p = EXERCISE_2_12.params(params)
    a, b, h, _, _ = _check_2_12(p)
    if abs(h) >= a + b:
        raise ValueError(f"Expected |`h`| < `a` + `b` = {a + b!r} so that E can reach its guide, got {h!r}")
    return (Linkage({"O": 0.0})
            .crank("1", pivot="O", tip="A", length=2.0 * a)
            .point("B", link="1", at=a)
            .rrp(("4", "5"), pin="B", guide=Guide("ground", through=1j * h, angle=0.0), joint="E", length=b, branch=1)
            .rrr(("2", "3"), pins=("A", "E"), joint="D", lengths=(b, a), branch=-1)
            .point("I", link="2", at=2.0 * b))


@names_givens("2-12")
def _solve_2_12(p):
    a, b, h, theta, w = _check_2_12(p)
    sol = _pose(linkage_2_12(p), theta, w, "2-12")
    P = {k: complex(v) for k, v in sol.points.items()}
    if abs(P["D"] - (P["A"] + P["E"] - P["B"])) > 1e-9 * (a + b):
        raise ValueError("Expected the assumed pantograph to be a parallelogram in this pose, got the other "
                         "assembly of D")
    vI, vE = complex(sol.velocities["I"]), complex(sol.velocities["E"])
    how = "`Linkage.solve(θ1, order=1, omega=ω1)` of the assumed layout"
    assumptions = (
        "A pantograph with one fixed pivot O: member 1 is the bar O-B-A (OB = BA = a), member 2 the bar "
        "A-D-I (AD = DI = b), member 3 the bar ED (= a) and member 4 the bar BE (= b), so that B-A-D-E is "
        "a parallelogram and O, E, I lie on one line with OI = 2 OE.",
        "A pantograph alone has two degrees of freedom; here the tracing point E is carried by a "
        "slider 5 on the horizontal line y = h, so that the driven member 1 fixes the motion.",
        "O = (0, 0); θ1 is the angle of O->A from +x, counter-clockwise, and so is ω1; E is to the "
        "right of B.",
    )
    part = Part("Velocities", (
        Result("v_A", abs(complex(sol.velocities["A"])) / 1000.0, "m/s", "ω1·OA, perpendicular to OA"),
        Result("v_E", vE.real / 1000.0, "m/s", how + "; along the guide, + to the right"),
        Result("v_D", abs(complex(sol.velocities["D"])) / 1000.0, "m/s", how),
        Result("v_I", abs(vI) / 1000.0, "m/s", how),
        Result("direction of v_I", math.atan2(vI.imag, vI.real), "rad", "from +x, counter-clockwise"),
        Result("v_I / v_E", abs(vI) / abs(vE), "", "the pantograph's scale (OI / OE = 2)"),
        Result("ω2", float(sol.omegas["2"]), "rad/s", how + " (+ counter-clockwise)"),
        Result("ω4", float(sol.omegas["4"]), "rad/s", how),
    ), ("Polygon: pa ⊥ OA with pa = ω1·OA, and b at the midpoint of pa (image of member 1); "
        "v_E = v_B + v_EB with v_E along the guide and v_EB ⊥ BE; v_D = v_A + v_DA = v_E + v_DE; "
        "i on the line a d extended with ai = 2 ad (image of member 2). Since O is fixed and OI = 2 OE "
        "at every instant, pi = 2 pe: I moves parallel to E, twice as fast.",))
    return Solution("2-12", EXERCISE_2_12.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_12(rng):
    return {"a": _around(rng, 100, 0.2), "b": _around(rng, 150, 0.2), "h": _around(rng, 40, 0.5),
            "theta1": float(rng.integers(30, 81)), "omega1": _around(rng, 10, 0.5)}


# ----------------------------------------------------------------------------- 2-14
_STATEMENT_2_14 = (
    "The angular velocity ω1 of the crank is known. Sketch the velocity and acceleration polygons "
    "of the mechanism and show the velocity and acceleration of the point F. (The figure is lost; "
    "assumed: a four-bar AB = {AB} mm, BC = {BC} mm, CD = {CD} mm, AD = {AD} mm with a coupler point E "
    "at BE = {BE} mm, {beta}° from BC, driving a slider F through the rod EF = {EF} mm on the line "
    "y = {yF} mm; the crank at θ1 = {theta1}° turns at ω1 = {omega1} rad/s.)"
)

_NAMES_2_14 = ("AB", "BC", "CD", "AD", "BE", "EF")


@names_givens("2-14")
def linkage_2_14(params=None):
    """The six-bar of exercise 2-14 on its assumed layout, as a `mech.planar.Linkage`.

    A = 0, D = AD on +x; crank AB; coupler BC carrying E at BE, ``beta`` counter-clockwise
    from B->C; rocker DC (C above the frame line); rod EF; slider F on the line y = yF, to the
    right of E. Links ``crank, coupler, rocker, rod, slider``.

    >>> from mech.exercises.chapter2_relative_motion import linkage_2_14
    >>> linkage_2_14().groups
    ('crank crank', 'RRR coupler-rocker', 'RRP rod-slider')
    """
    p = EXERCISE_2_14.params(params)
    ab, bc, cd, ad, be, ef = (positive_length(n, p[n]) for n in _NAMES_2_14)
    beta, yf = real_number("beta", p["beta"]) * _DEG, real_number("yF", p["yF"])
    check_links_close(AB=ab, BC=bc, CD=cd, AD=ad)     # the four-bar ABCD, under the exercise's names
    return (Linkage({"A": 0.0, "D": ad})
            .crank("crank", pivot="A", tip="B", length=ab)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(bc, cd), branch=1)
            .point("E", link="coupler", at=be * complex(math.cos(beta), math.sin(beta)))
            .rrp(("rod", "slider"), pin="E", guide=Guide("ground", through=1j * yf, angle=0.0), joint="F",
                 length=ef, branch=1))


@names_givens("2-14")
def _solve_2_14(p):
    theta, w = real_number("theta1", p["theta1"]) * _DEG, real_number("omega1", p["omega1"])
    sol = _pose(linkage_2_14(p), theta, w, "2-14")
    v, a = complex(sol.velocities["F"]), complex(sol.accelerations["F"])
    how = "`Linkage.solve(θ1, order=2, omega=ω1)` of the assumed layout"
    assumptions = (
        "A common six-bar: a four-bar ABCD (frame AD, A = (0, 0), D on +x, C above the frame line) whose "
        "coupler carries a point E, driving a slider F through the rod EF; F moves on a horizontal "
        "line, to the right of E.",
        "E is fixed in the coupler at BE from B, at the angle β counter-clockwise from B->C.",
        "θ1 is the crank angle from +x; the crank turns counter-clockwise at a constant ω1 (α1 = 0).",
    )
    part = Part("Velocity and acceleration of F", (
        Result("v_F", v.real / 1000.0, "m/s", how + "; + to the right"),
        Result("a_F", a.real / 1000.0, "m/s²", how + "; + to the right"),
        Result("ω of the coupler", float(sol.omegas["coupler"]), "rad/s", how + " (+ counter-clockwise)"),
        Result("ω of the rocker", float(sol.omegas["rocker"]), "rad/s", how),
        Result("ω of the rod EF", float(sol.omegas["rod"]), "rad/s", how),
        Result("α of the coupler", float(sol.alphas["coupler"]), "rad/s²", how),
        Result("α of the rocker", float(sol.alphas["rocker"]), "rad/s²", how),
        Result("α of the rod EF", float(sol.alphas["rod"]), "rad/s²", how),
    ), ("Sketch: v_C = v_B + v_CB (v_C ⊥ DC, v_CB ⊥ BC); e by the velocity image of BCE (triangle bce "
        "similar to BCE, turned 90° in the sense of ω2); v_F = v_E + v_FE with v_F along the guide. "
        "Accelerations: a_C^n + a_C^t = a_B + a_CB^n + a_CB^t, e' by the acceleration image, then "
        "a_F = a_E + a_FE^n + a_FE^t.",))
    return Solution("2-14", EXERCISE_2_14.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_14(rng):
    return {"AB": _around(rng, 40, 0.2), "BC": _around(rng, 120, 0.1), "CD": _around(rng, 100, 0.1),
            "AD": _around(rng, 130, 0.1), "BE": _around(rng, 60, 0.2), "beta": float(rng.integers(20, 50)),
            "EF": _around(rng, 150, 0.1), "yF": _around(rng, 30, 0.5), "theta1": float(15 * rng.integers(0, 24)),
            "omega1": _around(rng, 10, 0.5)}


# ----------------------------------------------------------------------------- registry
EXERCISE_2_12 = Exercise(
    number="2-12", title="Velocity polygon of a pantograph and the velocity of its point I", tag="G",
    statement=_STATEMENT_2_12,
    parameters=(Parameter("a", 100.0, "mm", "assumed OB = BA"), Parameter("b", 150.0, "mm", "assumed BE = AD = DI"),
                Parameter("h", 40.0, "mm", "assumed guide line of E"), Parameter("theta1", 60.0, "°", "assumed angle"),
                Parameter("omega1", 10.0, "rad/s", "assumed ω1")),
    solver=_solve_2_12, sampler=_sample_2_12,
)
EXERCISE_2_14 = Exercise(
    number="2-14", title="Velocity and acceleration polygons of a six-bar and the motion of F", tag="G",
    statement=_STATEMENT_2_14,
    parameters=(Parameter("AB", 40.0, "mm", "assumed crank"), Parameter("BC", 120.0, "mm", "assumed coupler"),
                Parameter("CD", 100.0, "mm", "assumed rocker"), Parameter("AD", 130.0, "mm", "assumed frame"),
                Parameter("BE", 60.0, "mm", "assumed coupler point E, from B"),
                Parameter("beta", 30.0, "°", "assumed angle of BE from BC"),
                Parameter("EF", 150.0, "mm", "assumed rod"), Parameter("yF", 30.0, "mm", "assumed slider line"),
                Parameter("theta1", 60.0, "°", "assumed crank angle"),
                Parameter("omega1", 10.0, "rad/s", "assumed crank speed")),
    solver=_solve_2_14, sampler=_sample_2_14,
)
EXERCISE_2_13 = Exercise(
    number="2-13", title="Hay press: piston displacement over a cycle, velocity and acceleration", tag="A",
    statement=_STATEMENT_2_13,
    parameters=(Parameter("OA", 150.0, "mm", "crank"), Parameter("AB", 600.0, "mm", "coupler"),
                Parameter("BC", 120.0, "mm", "C on the rocker, from B"), Parameter("BD", 500.0, "mm", "rocker"),
                Parameter("CE", 600.0, "mm", "rod to the piston"), Parameter("xD", 400.0, "mm", "rocker pivot D, x"),
                Parameter("yD", 500.0, "mm", "rocker pivot D, y"), Parameter("yE", 600.0, "mm", "piston line"),
                Parameter("omega1", 10.0, "rad/s", "crank speed")),
    solver=_solve_2_13, sampler=_sample_2_13,
)
EXERCISE_2_15 = Exercise(
    number="2-15", title="Two sliders at right angles: ω and α of the coupler, motion of the slider", tag="A",
    statement=_STATEMENT_2_15,
    parameters=(Parameter("AB", 150.0, "mm", "crank"), Parameter("BC", 550.0, "mm", "coupler 3"),
                Parameter("BD", 80.0, "mm", "D on the coupler, from B"), Parameter("DE", 500.0, "mm", "rod 4"),
                Parameter("omega1", 10.0, "rad/s", "crank speed, counter-clockwise"),
                Parameter("phi1", 45.0, "°", "angle BAE")),
    solver=_solve_2_15, sampler=_sample_2_15,
)
EXERCISE_2_16 = Exercise(
    number="2-16", title="A slider driven through a block on a rocker: velocity and acceleration of F", tag="A",
    statement=_STATEMENT_2_16,
    parameters=(Parameter("AB", 200.0, "mm", "crank"), Parameter("BC", 500.0, "mm", "coupler"),
                Parameter("CD", 800.0, "mm", "rocker"), Parameter("xF", 400.0, "mm", "slider 5's vertical line"),
                Parameter("xD", 350.0, "mm", "rocker pivot D, x"), Parameter("yD", 350.0, "mm", "rocker pivot D, y"),
                Parameter("omega1", 100.0, "rad/s", "crank speed"), Parameter("phi1", 45.0, "°", "crank angle")),
    solver=_solve_2_16, sampler=_sample_2_16,
)

EXERCISES = (EXERCISE_2_12, EXERCISE_2_13, EXERCISE_2_14, EXERCISE_2_15, EXERCISE_2_16)
