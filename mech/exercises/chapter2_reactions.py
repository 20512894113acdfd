"""Exercises 2-17, 2-18, 2-22, 2-25 and 2-26 of chapter 2: reactions in the pairs, by computation.

The textbook solves these with force polygons drawn by hand and, in 2-26, with the lines
of action of the total reactions tangent to friction circles. The figures are lost (tag
"G"): the lengths of 2-17 and 2-18 are printed, the configurations are not, and 2-26 has
no numbers at all. Each solution states the layout it assumes, builds it as a
`mech.planar.Linkage` and solves the statics with `mech.planar.static_forces` (group by
group, from the load back to the driver). ``linkage_2_17`` and the like return the assumed
linkage at its pose, for figures and checks. The solutions are shown on the book page
``book-forces-static-forces``.

Exercise 2-22 (题图 2-22 is lost too: only "A and B are fixed pins, every pin is 25 mm in
diameter, mu0 = 0.2, P = 30 N, find Q" survives) is solved on an assumed layout of two
levers on the fixed pins A and B joined by a link, with and without friction circles.

Examples
--------
>>> from mech.exercises import chapter2_reactions as cr
>>> round(float(cr.EXERCISE_2_18.solve()["balancing moment M1"].value), 3)
34.836
"""

from __future__ import annotations

import math

import numpy as np

from mech._errors import AssemblyError
from mech._validate import finite_result, naming, positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.exercises.chapter2_analysis import _around
from mech.planar import Guide, Linkage, friction_circle, static_forces

__all__ = ["EXERCISE_2_17", "EXERCISE_2_18", "EXERCISE_2_22", "EXERCISE_2_25", "EXERCISE_2_26", "LAYOUT_2_22",
           "THETAS_2_26", "linkage_2_17", "linkage_2_18", "linkage_2_22", "linkage_2_25", "linkage_2_26"]

_DEG = math.pi / 180.0


def _reaction_results(sf, pairs, unit="N"):
    """Size and direction of each reaction R_ij (force of link i on link j)."""
    out = []
    for label, key, where in pairs:
        R = complex(sf.reactions[key])
        out.append(Result(f"{label} at {where}", abs(R), unit, "`static_forces(...).reactions`"))
        out.append(Result(f"direction of {label}", math.atan2(R.imag, R.real), "rad", "from +x, counter-clockwise"))
    return tuple(out)


def _solved(lk, angle, what, /, **given):
    """Solve ``lk`` at ``theta``; if it does not close, name the givens of its layout."""
    sol = lk.solve(angle, order=1, omega=1.0)
    if not bool(np.all(sol.valid)):
        listed, shown = naming(**given)
        raise ValueError(f"Expected {listed} that let the assumed layout of exercise {what} assemble at the "
                         f"pose analysed, got {shown}: a pose that does not close")
    return sol


def _finite_forces(sf, what, /, **given):
    """The sizes of ``sf``'s reactions and its balancing effort finite, or a ValueError naming
    the givens (a layout far from the unit scale overflows the statics)."""
    with np.errstate(all="ignore"):
        sizes = np.abs(np.array([complex(v) for v in sf.reactions.values()] + [complex(sf.balancing)]))
    finite_result(sizes, f"every reaction of exercise {what}", **given)


def _tiny_link(what, name, value, factor, link):
    """A derived length ``factor * value`` that rounds to 0: named as the given ``name``."""
    if not factor * value > 0.0:
        raise ValueError(f"Expected `{name}` large enough that {link} = {factor:g}·`{name}` > 0 in exercise "
                         f"{what}, got {value!r}")


# ----------------------------------------------------------------------------- 2-17
_STATEMENT_2_17 = (
    "In a linkage the load on member 5 is P5 = {P5} N; AB = {AB} mm, AE = BE, BC = CD = 2AB, "
    "DS = 1.5AB and SK = 0.5AB; friction in the pairs is neglected. Find the reactions in all "
    "the pairs, and the balancing force P1 that must act at E perpendicular to the driving member 1. (Assumed crank angle: {theta}° from AD.)"
)


def linkage_2_17(params=None):
    """The assumed layout of exercise 2-17 as a `mech.planar.Linkage` (see the solution).

    A = 0, D = 2AB on +x; crank AB (1); coupler BC (2); rocker DC (3) with S on it at DS
    from D; rod SK (4); slider 5 (pin K) on a horizontal guide placed so that SK makes
    30° with it at the crank angle ``theta`` (default 60°), K to the right of S below it.
    Returns ``(linkage, theta)``.

    >>> from mech.exercises.chapter2_reactions import linkage_2_17
    >>> linkage_2_17()[0].groups
    ('crank crank1', 'RRR link2-rocker3', 'RRP rod4-slider5')
    """
    p = EXERCISE_2_17.params(params)
    ab = positive_length("AB", p["AB"])
    _tiny_link("2-17", "AB", ab, 0.5, "SK")
    theta = real_number("theta", p["theta"]) * _DEG
    four = (Linkage({"A": 0.0, "D": 2.0 * ab})
            .crank("crank1", pivot="A", tip="B", length=ab)
            .rrr(("link2", "rocker3"), pins=("B", "D"), joint="C", lengths=(2.0 * ab, 2.0 * ab), branch=1)
            .point("S", link="rocker3", at=1.5 * ab)
            .point("E", link="crank1", at=0.5 * ab))
    S = complex(_solved(four, theta, "2-17", AB=ab, theta=p["theta"]).points["S"])
    guide = Guide("ground", through=1j * (S.imag - 0.5 * ab * math.sin(30.0 * _DEG)), angle=0.0)
    return four.rrp(("rod4", "slider5"), pin="S", guide=guide, joint="K", length=0.5 * ab, branch=1), theta


def _solve_2_17(p):
    P5 = positive_length("P5", p["P5"])
    ab = positive_length("AB", p["AB"])
    k = math.frexp(ab)[1]             # solve at AB in [0.5, 1): forces keep, lengths scale by 2**k
    lk, theta = linkage_2_17(dict(p, AB=math.ldexp(ab, -k)))
    sol = _solved(lk, theta, "2-17", AB=ab, theta=p["theta"])
    vK_unit = float(sol.velocities["K"].real)
    vK = math.ldexp(vK_unit, k)
    load = -P5 * math.copysign(1.0, vK_unit)             # P5 resists the slider's motion
    with np.errstate(all="ignore"):
        sf = static_forces(sol, {("K", "slider5"): load})
    _finite_forces(sf, "2-17", P5=P5, AB=ab, theta=p["theta"])
    P1 = float(sf.balancing) / (0.5 * math.ldexp(ab, -k))
    Mb = math.ldexp(float(sf.balancing), k)
    assumptions = (
        f"A = (0, 0) and D = ({2 * ab:g}, 0) mm are the fixed pivots (AD = 2AB, a crank-rocker); member 1 "
        f"is the crank AB at {math.degrees(theta):g}° from AD, turning counter-clockwise.",
        "Member 2 is the coupler BC, member 3 the rocker DC; S lies on DC at DS from D.",
        "Member 4 is the rod SK; member 5 a slider whose pin K runs on a horizontal guide, placed so "
        "that SK makes 30° with it in this pose (K to the right of and below S).",
        "P5 acts on the slider along its guide, against its motion (a resistance). E is the midpoint "
        "of AB (AE = BE), and P1 acts there perpendicular to AB.",
    )
    part1 = Part("(1) Reactions in the pairs (R_ij: force of i on j; 0 is the frame)", _reaction_results(sf, (
        ("R_01", ("ground", "crank1"), "A"), ("R_12", ("crank1", "link2"), "B"),
        ("R_23", ("link2", "rocker3"), "C"), ("R_03", ("ground", "rocker3"), "D"),
        ("R_34", ("rocker3", "rod4"), "S"), ("R_45", ("rod4", "slider5"), "K"),
        ("R_05", ("ground", "slider5"), "the guide"))), (
        "BC and SK carry loads only at their ends, so each is a two-force member: R_12 lies along BC "
        "and R_45 along SK. The slider's three forces (P5, R_45, the guide's normal force) close a force "
        "triangle; the rocker's three (R_23, R_43, R_03) meet in one point; the crank balances R_21 with "
        "R_01 and P1.",))
    part2 = Part("(2) Balancing force", (
        Result("balancing moment on member 1", Mb / 1000.0, "N·m", "`static_forces(...).balancing`"),
        Result("balancing force P1", P1, "N", "P1 = M1 / AE, perpendicular to AB at E"),
        Result("slider velocity per unit ω1", vK, "mm/s", "`Linkage.solve(order=1)`, + to the right"),
    ), ("Check by virtual work: P1·AE·ω1 equals P5 times the slider's speed.",))
    return Solution("2-17", EXERCISE_2_17.title, dict(p), (), (part1, part2), assumptions=assumptions)


def _sample_2_17(rng):
    return {"P5": float(rng.integers(10, 60) * 100), "AB": _around(rng, 50, 0.3),
            "theta": float(rng.choice([30.0, 45.0, 60.0, 75.0, 90.0, 120.0]))}


# ----------------------------------------------------------------------------- 2-18
_STATEMENT_2_18 = (
    "In a linkage the load on member 5 is P5 = {P5} N; AB = {AB} mm, BC = CD = 2AB and CE = ED = DF; "
    "friction in the pairs is neglected. Find (graphically in the text) the reactions in all the "
    "pairs and the balancing moment M1 on member 1. (Assumed crank angle: {theta}°.)"
)


def linkage_2_18(params=None):
    """The assumed layout of exercise 2-18 as a `mech.planar.Linkage` (see the solution).

    A = 0 and E = 2.5AB + i AB fixed; crank AB (1) at ``theta`` (default 60°); coupler BC
    (2); lever CED (3) pivoted at its midpoint E (CE = ED = AB); rod DF (4); slider 5 (pin
    F) on the horizontal guide y = -AB/2, F to the right of D. Returns ``(linkage, theta)``.

    >>> from mech.exercises.chapter2_reactions import linkage_2_18
    >>> linkage_2_18()[0].groups
    ('crank crank1', 'RRR link2-lever3', 'RRP rod4-slider5')
    """
    p = EXERCISE_2_18.params(params)
    ab = positive_length("AB", p["AB"])
    _tiny_link("2-18", "AB", ab, 0.5, "the guide's offset")
    theta = real_number("theta", p["theta"]) * _DEG
    lk = (Linkage({"A": 0.0, "E": complex(2.5 * ab, ab)})
          .crank("crank1", pivot="A", tip="B", length=ab)
          .rrr(("link2", "lever3"), pins=("B", "E"), joint="C", lengths=(2.0 * ab, ab), branch=1)
          .point("D", link="lever3", at=-ab)
          .rrp(("rod4", "slider5"), pin="D", guide=Guide("ground", through=-0.5j * ab, angle=0.0),
               joint="F", length=ab, branch=1))
    return lk, theta


def _solve_2_18(p):
    P5 = positive_length("P5", p["P5"])
    ab = positive_length("AB", p["AB"])
    k = math.frexp(ab)[1]             # solve at AB in [0.5, 1): forces keep, lengths scale by 2**k
    lk, theta = linkage_2_18(dict(p, AB=math.ldexp(ab, -k)))
    sol = _solved(lk, theta, "2-18", AB=ab, theta=p["theta"])
    vF = float(sol.velocities["F"].real)
    if abs(vF) < 1e-9 * math.ldexp(ab, -k):
        raise ValueError(f"Expected `theta` away from a dead centre, where the slider moves, got theta="
                         f"{p['theta']!r} (AB={ab!r}): a dead-centre pose")
    with np.errstate(all="ignore"):
        sf = static_forces(sol, {("F", "slider5"): -P5 * math.copysign(1.0, vF)})
    _finite_forces(sf, "2-18", P5=P5, AB=ab, theta=p["theta"])
    Mb = math.ldexp(float(sf.balancing), k)
    vF = math.ldexp(vF, k)
    assumptions = (
        "CE = ED = DF is read as: C, E, D lie on one lever CD (CD = 2AB as printed) pivoted on the "
        "frame at its midpoint E, so CE = ED = DF = AB; DF is the rod to the slider.",
        f"A = (0, 0) and E = ({2.5 * ab:g}, {ab:g}) mm are the fixed pivots; member 1 is the crank AB at "
        f"{math.degrees(theta):g}° from +x, turning counter-clockwise; member 2 the coupler BC, member 3 "
        "the lever CED, member 4 the rod DF.",
        f"Member 5 is a slider whose pin F runs on the horizontal guide y = {-0.5 * ab:g} mm, to the right "
        "of D; P5 acts on it along the guide, against its motion.",
    )
    part1 = Part("(1) Reactions in the pairs (R_ij: force of i on j; 0 is the frame)", _reaction_results(sf, (
        ("R_01", ("ground", "crank1"), "A"), ("R_12", ("crank1", "link2"), "B"),
        ("R_23", ("link2", "lever3"), "C"), ("R_03", ("ground", "lever3"), "E"),
        ("R_34", ("lever3", "rod4"), "D"), ("R_45", ("rod4", "slider5"), "F"),
        ("R_05", ("ground", "slider5"), "the guide"))), (
        "Graphically: the slider's force triangle (P5, R_45 along DF, R_05 normal to the guide) gives "
        "R_45; the lever's three forces R_23 (along BC), R_43 = −R_34 and R_03 meet in one point, "
        "which fixes R_03's line, and close a triangle; the crank then balances R_21 with R_01 and M1.",))
    part2 = Part("(2) Balancing moment", (
        Result("balancing moment M1", Mb / 1000.0, "N·m", "`static_forces(...).balancing`, + counter-clockwise"),
        Result("slider velocity per unit ω1", vF, "mm/s", "`Linkage.solve(order=1)`, + to the right"),
    ), ("Check by virtual work: M1·ω1 equals P5 times the slider's speed.",))
    return Solution("2-18", EXERCISE_2_18.title, dict(p), (), (part1, part2), assumptions=assumptions)


def _sample_2_18(rng):
    return {"P5": float(rng.integers(5, 40) * 100), "AB": _around(rng, 100, 0.3),
            "theta": float(rng.choice([30.0, 45.0, 60.0, 90.0]))}


# ----------------------------------------------------------------------------- 2-26
#: The crank angles of exercise 2-26, degrees.
THETAS_2_26 = (45.0, 135.0, 225.0, 315.0)

_STATEMENT_2_26 = (
    "In a slider-crank whose dimensions, journal diameters included, are known, the equivalent "
    "friction coefficient of every journal is μ0 and the coefficient of friction between slider and "
    "guide is μ. The slider is driven by a force F (pointing right on the return stroke), and the "
    "driven crank 1 carries a resisting moment M_r; masses are neglected. Find the lines of action "
    "of the total reactions in all the pairs at θ = 45°, 135°, 225° and 315°. (Assumed: crank r = "
    "{r} mm, rod l = {l} mm, journal diameter {d} mm, μ0 = {mu0}, μ = {mu}, M_r = {Mr} N·m.)"
)


def linkage_2_26(params=None, *, theta=45.0):
    """The assumed slider-crank of exercise 2-26, driven by its slider, at crank angle ``theta``.

    A = 0; slider 3 (pin C) on the x axis, to the right of A, is the driver (input: x_C);
    rod 2 = CB and crank 1 = AB form an RRR group on the side of B given by ``theta``
    (degrees, from +x counter-clockwise). Returns ``(linkage, x_C, dx_C/dθ)``.

    >>> from mech.exercises.chapter2_reactions import linkage_2_26
    >>> linkage_2_26()[0].groups
    ('slider slider', 'RRR rod-crank')
    """
    p = EXERCISE_2_26.params(params)
    r, length = positive_length("r", p["r"]), positive_length("l", p["l"])
    if r >= length:
        raise ValueError(f"Expected `r` < `l` = {length!r} so that the crank turns fully, got {r!r}")
    t = real_number("theta", theta) * _DEG
    s, c = math.sin(t), math.cos(t)
    if abs(s) < 1e-9:
        raise ValueError(f"Expected `theta` away from the dead centres 0° and 180°, got {theta!r}")
    root = length * math.sqrt((1.0 - r * s / length) * (1.0 + r * s / length))   # no overflow of l**2
    x = r * c + root
    dx = -r * s - r * r * s * c / root
    lk = (Linkage({"A": 0.0})
          .slider("slider", guide=Guide("ground", 0j, 0.0), point="C")
          .rrr(("rod", "crank"), pins=("C", "A"), joint="B", lengths=(length, r), branch=-1 if s > 0 else 1))
    return lk, x, dx


def _solve_2_26(p):
    r, length, d = (positive_length(n, p[n]) for n in ("r", "l", "d"))
    Mr = positive_length("Mr", p["Mr"]) * 1000.0
    if not math.isfinite(Mr):
        raise ValueError(f"Expected `Mr` below {np.finfo(float).max / 1000:.6g} N·m (in N·mm it must stay finite), "
                         f"got {p['Mr']!r}")
    # the statics run on the moment divided by a power of two (in [1, 2) N·mm) and the forces
    # are multiplied back: friction lines and efficiencies do not depend on the load's size,
    # but a subnormal load would lose their digits
    unit = math.ldexp(1.0, math.frexp(Mr)[1] - 1)
    mu0, mu = real_number("mu0", p["mu0"]), real_number("mu", p["mu"])
    if r >= length:
        raise ValueError(f"Expected `r` < `l` = {length!r} so that the crank turns fully, got {r!r}")
    rho = 0.5 * float(friction_circle(mu0, d))           # mu0 (d/2), with d/2 of 5e-324 not 0
    if not (2 * rho < length and 2 * rho < r):
        raise ValueError(f"Expected `mu0` and `d` whose friction circles (ρ = `mu0`·`d`/2 = {rho!r} mm) fit "
                         f"between the pins, 2ρ < `r` and 2ρ < `l`, got mu0={mu0!r}, d={d!r}, r={r!r}, "
                         f"l={length!r}")
    parts = []
    for deg in THETAS_2_26:
        lk, x, dx = linkage_2_26(p, theta=deg)
        sol = lk.solve(x, order=1, omega=dx)            # the crank turns counter-clockwise at 1 rad/s
        if not bool(np.all(sol.valid)):
            # with l many orders longer than r the crank is lost in the rounding of l: the pose
            # computed from the closed form no longer closes in floating point
            raise AssemblyError(f"Expected `l` short enough beside `r` that the pose at θ = {deg:g}° closes "
                                f"in floating point (`l`/`r` below about 1e13), got l={length!r}, r={r!r}")
        sf = static_forces(sol, couples={"crank": -Mr / unit}, rho=rho, mu=mu)
        sf0 = static_forces(sol, couples={"crank": -Mr / unit})
        if bool(np.any(sf.self_locking)):
            raise ValueError(f"Expected `mu0`, `d` and `mu` that let the slider drive the crank at θ = {deg:g}°, "
                             f"got self-locking at mu0={mu0!r}, d={d!r}, mu={mu!r}")
        F = float(sf.balancing) * unit
        P = {k: complex(v) for k, v in sol.points.items()}
        res = [Result(f"θ = {deg:g}°: driving force F", F, "N", "`static_forces(..., rho=ρ, mu=μ).balancing`, "
                      "+ to the right"),
               Result(f"θ = {deg:g}°: F without friction", float(sf0.balancing) * unit, "N",
                      "`static_forces` with ρ = μ = 0"),
               Result(f"θ = {deg:g}°: efficiency", float(sf.efficiency), "", "frictionless over actual driving power")]
        notes = []
        for label, key, pin in (("R_41", ("ground", "crank"), "A"), ("R_21", ("rod", "crank"), "B"),
                                ("R_23", ("rod", "slider"), "C")):
            R = complex(sf.reactions[key])
            arm = float(np.imag(np.conj(complex(sf.lines[key]) - P[pin]) * R)) / abs(R)
            res.append(Result(f"θ = {deg:g}°: {label} size", abs(R) * unit, "N", "`static_forces(...).reactions`"))
            res.append(Result(f"θ = {deg:g}°: {label} direction", math.atan2(R.imag, R.real), "rad",
                              "from +x, counter-clockwise"))
            res.append(Result(f"θ = {deg:g}°: {label} moment arm about {pin}", arm, "mm",
                              "+: the line passes so that the force turns counter-clockwise about the pin"))
        R43 = complex(sf.reactions[("ground", "slider")])
        tilt = math.atan2(R43.real, abs(R43.imag)) * (1.0 if R43.imag > 0 else -1.0)
        res.append(Result(f"θ = {deg:g}°: R_43 tilt from the guide normal", tilt, "rad",
                          "+: leaning towards +x; its size is the friction angle"))
        rod = P["B"] - P["C"]
        tilt_rod = math.atan2(np.imag(np.conj(rod) * complex(sf.reactions[("rod", "crank")])),
                              np.real(np.conj(rod) * complex(sf.reactions[("rod", "crank")])))
        stroke = "working stroke (slider moving left)" if dx < 0 else "return stroke (slider moving right)"
        notes.append(f"{stroke}; the rod is in {'compression' if abs(tilt_rod) < math.pi / 2 else 'tension'}: "
                     "its force is tangent to both friction circles, at B and at C.")
        parts.append(Part(f"θ = {deg:g}°", tuple(res), tuple(notes)))
    assumptions = (
        f"The text prints no dimensions: we take crank AB = r = {r:g} mm, rod BC = l = {length:g} mm, "
        f"no offset, journals of diameter {d:g} mm (ρ = μ0·d/2 = {rho:g} mm), μ0 = {mu0:g}, μ = {mu:g}, "
        f"M_r = {Mr / 1000:g} N·m.",
        "A = 0, the slider C moves on the x axis to the right of A; θ is the angle of A->B from +x, "
        "counter-clockwise, and the crank turns counter-clockwise. Then the slider moves right for "
        "θ in (180°, 360°), which is the return stroke with F pointing right, as the text says.",
        "Members: 1 the crank (driven), 2 the rod, 3 the slider (driving), 4 the frame; R_ij is the "
        "force of i on j. F drives the slider along its motion; M_r resists the crank's turning.",
    )
    conventions = (
        "A journal's total reaction is tangent to its friction circle (radius ρ) on the side whose moment "
        "opposes the relative rotation of the two members; the slider's is tilted from the guide's "
        "normal by the friction angle atan μ against the sliding. The moment arm of each reaction about "
        "its pin is ±ρ.",
    )
    return Solution("2-26", EXERCISE_2_26.title, dict(p), conventions, tuple(parts), assumptions=assumptions)


def _sample_2_26(rng):
    return {"r": _around(rng, 100, 0.3), "l": _around(rng, 350, 0.2), "d": float(rng.integers(10, 31)),
            "mu0": round(float(rng.uniform(0.1, 0.25)), 2), "mu": round(float(rng.uniform(0.05, 0.2)), 2),
            "Mr": float(rng.integers(5, 50))}


# ----------------------------------------------------------------------------- 2-22
#: The assumed layout (mm, radians): pivots, lever arms, link, lever-1 angle.
LAYOUT_2_22 = {"AB": 400.0, "AC": 150.0, "AE": 300.0, "CD": 350.0, "BD": 150.0, "BF": 300.0,
               "theta": math.radians(60.0)}

_STATEMENT_2_22 = (
    "In the linkage of figure 2-22, A and B are fixed pins. Every pin has a diameter of "
    "{d_pin} mm and an equivalent friction coefficient mu0 = {mu0}. The force P = {P} N drives "
    "the linkage. Find the force Q that P can overcome (the figure is lost: a layout is assumed)."
)


def linkage_2_22(layout=None):
    """The assumed layout of exercise 2-22 as a `Linkage` (lever1 A-C-E, link C-D, lever2 B-D-F).

    Examples
    --------
    >>> from mech.exercises.chapter2_reactions import linkage_2_22
    >>> linkage_2_22().groups
    ('crank lever1', 'RRR link-lever2')
    """
    L = dict(LAYOUT_2_22, **(layout or {}))
    for k in ("AB", "AC", "AE", "CD", "BD", "BF"):
        positive_length(k, L[k])
    return (Linkage({"A": 0.0, "B": L["AB"]})
            .crank("lever1", pivot="A", tip="C", length=L["AC"])
            .point("E", link="lever1", at=L["AE"])
            .rrr(("link", "lever2"), pins=("C", "B"), joint="D", lengths=(L["CD"], L["BD"]), branch=1)
            .point("F", link="lever2", at=L["BF"]))


def _solve_2_22(p):
    P = positive_length("P", p["P"])
    d_pin = positive_length("d_pin", p["d_pin"])
    rho = 0.5 * float(friction_circle(p["mu0"], d_pin))       # mu0 (d/2), with d/2 of 5e-324 not 0
    L = LAYOUT_2_22
    if not 2.0 * rho < L["CD"]:
        # the friction circles at the two pins of the two-force link CD must not overlap (as
        # `static_forces` requires, naming its own `rho`)
        raise ValueError(f"Expected `mu0` and `d_pin` whose friction circles (ρ = `mu0`·`d_pin`/2 = {rho!r} mm) fit "
                         f"between the pins of CD, 2ρ < {L['CD']:g} mm, got mu0={p['mu0']!r}, d_pin={d_pin!r}")
    lk = linkage_2_22()
    sol = lk.solve(L["theta"], order=1, strict=True)          # lever 1 turns counter-clockwise
    w2 = float(sol.omegas["lever2"])
    u2 = sol.direction("lever2")
    q_unit = complex(-np.sign(w2) * 1j * u2)                   # unit Q, against lever 2's turning
    moment_P = P * L["AE"]                                     # P perpendicular to lever 1 at E
    Q = {}
    for label, r in (("without friction", 0.0), ("with friction", rho)):
        sf = static_forces(sol, {"F": q_unit}, rho=r)
        if bool(sf.self_locking):
            raise ValueError(f"Expected `mu0` and `d_pin` that let the assumed linkage move, got self-locking "
                             f"with mu0={p['mu0']!r}, d_pin={d_pin!r} (rho = {rho!r})")
        Q[label] = moment_P / float(sf.balancing)
    eta = Q["with friction"] / Q["without friction"]
    assumptions = (
        f"A = (0, 0) and B = ({L['AB']:g}, 0) mm. Lever 1 turns about A: C at {L['AC']:g} mm, "
        f"P acts at E, {L['AE']:g} mm from A, perpendicular to AE, turning it counter-clockwise; "
        f"the lever stands at {math.degrees(L['theta']):g}° to AB.",
        f"The link CD ({L['CD']:g} mm) joins lever 1 to lever 2, which turns about B: D at "
        f"{L['BD']:g} mm from B, Q at F, {L['BF']:g} mm from B, perpendicular to BF, resisting.",
        "P drives and Q resists (the textbook does not say which); weights are neglected.",
    )
    part = Part("The force Q", (
        Result("friction-circle radius", rho, "mm", "ρ = μ0 r (2-19), r = d/2"),
        Result("Q without friction", Q["without friction"], "N",
               "`static_forces` with ρ = 0: P·AE over the balancing moment for a unit Q"),
        Result("Q with friction", Q["with friction"], "N",
               "`static_forces` with friction circles at A, B, C, D; senses from the velocities"),
        Result("efficiency", eta, "", "η = Q / Q0 at the same P (eq. 2-24)"),
    ), ("The balancing moment is proportional to Q (every reaction, and so every friction "
        "moment ρ|R|, scales with the load), so Q follows from one solve with a unit Q.",))
    return Solution("2-22", EXERCISE_2_22.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_22(rng):
    return {"P": float(rng.integers(10, 100)), "d_pin": float(rng.integers(10, 40)),
            "mu0": float(np.round(rng.uniform(0.05, 0.3), 2))}


EXERCISE_2_22 = Exercise(
    number="2-22",
    title="Force Q that a lever linkage with friction circles transmits from P",
    tag="G",
    statement=_STATEMENT_2_22,
    parameters=(
        Parameter("P", 30.0, "N", "driving force"),
        Parameter("d_pin", 25.0, "mm", "pin diameter"),
        Parameter("mu0", 0.2, "", "equivalent friction coefficient of the pins"),
    ),
    solver=_solve_2_22,
    sampler=_sample_2_22,
)


# ----------------------------------------------------------------------------- 2-25
_STATEMENT_2_25 = (
    "In a disc cam with an oscillating follower the cam 1 turns counter-clockwise, and G = {G} N is "
    "the external load on the follower 2. The equivalent friction coefficients of all the pairs and "
    "the shaft radii are known; weights and inertia forces are neglected. Find the lines of action of "
    "the total reactions R12, R32 and R31, and the efficiency in the position shown. (Assumed: a "
    "circular disc of radius {R} mm whose centre is {e} mm from the shaft, at {theta}° from the line "
    "to the follower's pivot {AD} mm away; a knife-edge follower {L} mm long with G at {DH} mm from "
    "its pivot; μ = {mu} at every pair, shafts of radius {rs} mm.)"
)


def linkage_2_25(params=None):
    """The equivalent linkage of exercise 2-25's assumed cam (high pair replaced by a four-bar).

    A = 0 is the cam shaft and D = AD on +x the follower's pivot. The disc's centre of
    curvature O (its geometric centre) is a point of the cam at e from A (link ``"cam"``,
    input: the angle of A->O); the knife edge K (the follower profile's centre of curvature)
    is a point of the follower DK. The fictitious link ``"contact"`` = OK, of length R, joins
    the two centres of curvature; K is above the line from O to D. H is where G acts, on DK
    at DH from D. Returns ``(linkage, theta)``.

    >>> from mech.exercises.chapter2_reactions import linkage_2_25
    >>> linkage_2_25()[0].groups
    ('crank cam', 'RRR contact-follower')
    """
    p = EXERCISE_2_25.params(params)
    R, e, ad, L, dh = (positive_length(n, p[n]) for n in ("R", "e", "AD", "L", "DH"))
    if e >= R:
        raise ValueError(f"Expected `e` < `R` = {R!r} (the shaft inside the disc), got {e!r}")
    lk = (Linkage({"A": 0.0, "D": ad})
          .crank("cam", pivot="A", tip="O", length=e)
          .rrr(("contact", "follower"), pins=("O", "D"), joint="K", lengths=(R, L), branch=1)
          .point("H", link="follower", at=dh))
    return lk, real_number("theta", p["theta"]) * _DEG


def _solve_2_25(p):
    G = positive_length("G", p["G"])
    R, rs = positive_length("R", p["R"]), positive_length("rs", p["rs"])
    mu = real_number("mu", p["mu"])
    if not 0.0 <= mu < 1.0:
        raise ValueError(f"Expected 0 <= `mu` < 1, got {mu!r}")
    lk, theta = linkage_2_25(p)
    layout = {k: p[k] for k in ("R", "e", "theta", "AD", "L", "DH")}
    sol = _solved(lk, theta, "2-25", **layout)
    phi = math.atan(mu)
    rho_shaft = float(friction_circle(mu, rs))
    # the contact's friction: a friction circle of radius R sin(phi) about the disc's centre O makes the
    # coupler's line pass through K at the friction angle to the normal KO (exact for a circular disc)
    rho = {"A": rho_shaft, "D": rho_shaft, "O": R * math.sin(phi), "K": 0.0}
    w2 = float(sol.omegas["follower"])
    if not float(sol.velocities["H"].imag) > 0.0:
        listed, shown = naming(**layout)
        raise ValueError(f"Expected {listed} that make a pose of the rise (the follower lifted against G), got "
                         f"the return at {shown}: there G drives and the cam only holds the follower back")
    # the reactions are proportional to G (friction circles included): solved for G = 1 N, then scaled
    load = {"H": -1j}                                    # G presses the follower down onto the cam
    with np.errstate(all="ignore"):
        sf = static_forces(sol, load, rho=rho)
    if bool(np.any(sf.self_locking)):
        listed, shown = naming(mu=mu, rs=rs, **layout)
        raise ValueError(f"Expected {listed} that let the cam drive the follower in the pose analysed, got "
                         f"self-locking at {shown}")
    _finite_forces(sf, "2-25", mu=mu, rs=rs, **layout)
    P = {k: complex(v) for k, v in sol.points.items()}
    normal = (P["K"] - P["O"]) / R
    out = []
    for label, key, pin in (("R12", ("contact", "follower"), "K"), ("R32", ("ground", "follower"), "D"),
                            ("R31", ("ground", "cam"), "A")):
        F = complex(sf.reactions[key])
        line = complex(sf.lines[key])
        size = float(finite_result(abs(F) * G, f"the size of {label}", G=G, **layout))
        out.append(Result(f"{label} size", size, "N", "`static_forces` on the equivalent linkage"))
        out.append(Result(f"{label} direction", math.atan2(F.imag, F.real), "rad", "from +x, counter-clockwise"))
        arm = float(np.imag(np.conj(line - P[pin]) * F)) / abs(F)
        out.append(Result(f"{label} moment arm about {pin}", arm, "mm", "+: the force turns counter-clockwise "
                          "about the point; ±ρ at a journal, 0 at the contact"))
    F12 = complex(sf.reactions[("contact", "follower")])
    tilt = math.atan2(np.imag(np.conj(normal) * F12), np.real(np.conj(normal) * F12))
    out += [Result("R12 angle from the common normal", tilt, "rad", "± the friction angle φ = atan μ"),
            Result("driving moment M1", float(sf.balancing) * G / 1000.0, "N·m", "`static_forces(...).balancing`"),
            Result("driving moment without friction", float(sf.frictionless["cam"]) * G / 1000.0, "N·m",
                   "`static_forces(...).frictionless`"),
            Result("efficiency η", float(sf.efficiency), "", "M1 without friction / M1 (eq. 2-24)")]
    assumptions = (
        f"The cam 1 is a circular disc of radius R = {R:g} mm turning counter-clockwise about the shaft A "
        f"= (0, 0); its centre O is e = {p['e']:g} mm from A at θ = {p['theta']:g}° from A->D. The follower 2 "
        f"is a knife-edge lever pivoted at D = ({p['AD']:g}, 0) mm, DK = {p['L']:g} mm, touching the disc "
        "above the line OD. The frame is 3.",
        f"G = {G:g} N acts vertically downwards at H on DK, {p['DH']:g} mm from D, pressing the follower "
        "onto the cam; the pose is on the rise, so the cam lifts the follower against G.",
        f"Every pair has the equivalent friction coefficient μ = {mu:g}; both shafts have radius "
        f"{rs:g} mm, so their friction circles have ρ = μ r = {rho_shaft:g} mm; the contact's friction "
        f"angle is φ = atan μ = {math.degrees(phi):.4f}°.",
        "Equivalent linkage (高副低代): the contact is replaced by a link OK joining the centres of "
        "curvature of the two profiles (the disc's centre O and the knife edge K), pinned to the cam at O "
        "and to the follower at K. The contact's sliding friction becomes a friction circle of radius "
        "R sin φ about O (none at K), which makes the link's force pass through K at the angle φ to the "
        "normal KO, on the side that opposes the follower's sliding on the disc.",
    )
    part = Part("Lines of action and efficiency", tuple(out), (
        f"R12 passes through the contact K, tilted by φ from the common normal against the sliding; R32 "
        f"is tangent to the friction circle at D on the side that opposes the follower's turning "
        f"(ω2 = {w2:.4f} per unit ω1); R31 = R21 is tangent to the friction circle at A, opposing the "
        "cam's turning.",))
    return Solution("2-25", EXERCISE_2_25.title, dict(p), (), (part,), assumptions=assumptions)


def _sample_2_25(rng):
    return {"G": float(rng.integers(5, 50) * 20), "R": _around(rng, 40, 0.15), "e": _around(rng, 15, 0.2),
            "AD": _around(rng, 120, 0.1), "L": _around(rng, 100, 0.1), "DH": _around(rng, 60, 0.2),
            "theta": float(15 * rng.integers(1, 24)), "mu": round(float(rng.uniform(0.05, 0.2)), 2),
            "rs": float(rng.integers(5, 15))}


# ----------------------------------------------------------------------------- registry
EXERCISE_2_17 = Exercise(
    number="2-17", title="Reactions and the balancing force of a six-bar with a slider", tag="G",
    statement=_STATEMENT_2_17,
    parameters=(Parameter("P5", 3000.0, "N", "load on the slider 5"), Parameter("AB", 50.0, "mm", "crank"),
                Parameter("theta", 60.0, "°", "assumed crank angle from AD")),
    solver=_solve_2_17, sampler=_sample_2_17,
)
EXERCISE_2_18 = Exercise(
    number="2-18", title="Reactions and the balancing moment of a lever six-bar", tag="G",
    statement=_STATEMENT_2_18,
    parameters=(Parameter("P5", 1000.0, "N", "load on the slider 5"), Parameter("AB", 100.0, "mm", "crank"),
                Parameter("theta", 60.0, "°", "assumed crank angle")),
    solver=_solve_2_18, sampler=_sample_2_18,
)
EXERCISE_2_25 = Exercise(
    number="2-25", title="Total reactions and efficiency of a cam with an oscillating follower", tag="G",
    statement=_STATEMENT_2_25,
    parameters=(Parameter("G", 200.0, "N", "load on the follower"), Parameter("R", 40.0, "mm", "assumed disc radius"),
                Parameter("e", 15.0, "mm", "assumed eccentricity AO"),
                Parameter("theta", 300.0, "°", "assumed cam angle from A->D"),
                Parameter("AD", 120.0, "mm", "assumed shaft to follower pivot"),
                Parameter("L", 100.0, "mm", "assumed follower DK"), Parameter("DH", 60.0, "mm", "assumed point of G"),
                Parameter("mu", 0.15, "", "assumed equivalent friction coefficient"),
                Parameter("rs", 10.0, "mm", "assumed shaft radius")),
    solver=_solve_2_25, sampler=_sample_2_25,
)
EXERCISE_2_26 = Exercise(
    number="2-26", title="Lines of action of the total reactions in a slider-driven slider-crank", tag="G",
    statement=_STATEMENT_2_26,
    parameters=(Parameter("r", 100.0, "mm", "assumed crank"), Parameter("l", 350.0, "mm", "assumed rod"),
                Parameter("d", 20.0, "mm", "assumed journal diameter"),
                Parameter("mu0", 0.2, "", "assumed equivalent journal friction coefficient"),
                Parameter("mu", 0.15, "", "assumed slider friction coefficient"),
                Parameter("Mr", 20.0, "N·m", "assumed resisting moment on the crank")),
    solver=_solve_2_26, sampler=_sample_2_26,
)

EXERCISES = (EXERCISE_2_17, EXERCISE_2_18, EXERCISE_2_22, EXERCISE_2_25, EXERCISE_2_26)
