"""Exercise 2-29 of chapter 2: a four-bar through three pairs of side-link positions.

The figure of exercise 2-29 (题图 2-29) is lost, and with it the angle convention, so the
solution states one (both angles counter-clockwise from the frame line, the package's
convention), solves the three precision pairs with Freudenstein's equation
(`mech.planar.synthesis.precision_pairs`), proves the design by simulating it with
`FourBar`, and shows what the other common reading (the output angle measured as the
interior angle at D) gives. The solution is shown on the book page
``book-synthesis-function-generation``; the theory on ``deriv-function-generation``.

Examples
--------
>>> from mech.exercises.chapter2_synthesis import EXERCISE_2_29
>>> s = EXERCISE_2_29.solve()
>>> [round(float(s[k].value), 3) for k in ("l_AB", "l_BC", "l_CD")]
[245.948, 82.033, 262.127]
"""

from __future__ import annotations

import math

import numpy as np

from mech._validate import bool_flag, positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.planar import grashof
from mech.planar.synthesis import precision_pairs

__all__ = ["EXERCISE_2_29", "design_2_29"]

_DEG = math.pi / 180.0

_STATEMENT_2_29 = (
    "The two side links of a hinged four-bar take three pairs of corresponding positions: "
    "phi1 = {phi1}°, psi1 = {psi1}°; phi2 = {phi2}°, psi2 = {psi2}°; phi3 = {phi3}°, "
    "psi3 = {psi3}°. With the frame AD = {AD} mm, find the lengths of the links (the textbook "
    "asks for a graphical method; the figure with the angle convention is lost)."
)


def design_2_29(p, *, interior=False):
    """The precision-pair design of exercise 2-29 for the givens `p` (degrees, mm).

    With ``interior=False`` phi is the angle of A->B and psi that of D->C, both
    counter-clockwise from A->D (the +x axis); with ``interior=True`` psi is the interior
    angle between D->A and D->C, so the angle of D->C is 180° - psi.

    Examples
    --------
    >>> from mech.exercises.chapter2_synthesis import EXERCISE_2_29, design_2_29
    >>> g = design_2_29(EXERCISE_2_29.defaults)
    >>> g.pair_error < 1e-12, g.covers_range
    (True, True)
    """
    phi = np.array([real_number(k, p[k]) for k in ("phi1", "phi2", "phi3")]) * _DEG
    psi = np.array([real_number(k, p[k]) for k in ("psi1", "psi2", "psi3")]) * _DEG
    d = positive_length("AD", p["AD"])
    if bool_flag("interior", interior):
        psi = np.pi - psi
    x, y = phi - phi[0], psi - psi[0]
    design, = precision_pairs(x, y, theta0=phi[0], psi0=psi[0], d=d, x_range=(min(0.0, x.min()), max(0.0, x.max())))
    return design


def _flipped(angle, start):
    return bool(math.cos(angle - start) < 0.0)


def _solve_2_29(p):
    g = design_2_29(p)
    alt = design_2_29(p, interior=True)
    a, b, c, d = g.lengths
    pose = g.fourbar.solve(g.input_angles, strict=True)
    psi_given = np.array([p["psi1"], p["psi2"], p["psi3"]]) * _DEG
    err = float(np.max(np.abs(np.angle(np.exp(1j * (pose.psi - psi_given - np.pi * _flipped(g.psi0, psi_given[0])))))))
    gamma, at = g.min_transmission_angle
    kind = grashof(a, b, c, d).kind
    assumptions = (
        "A is the fixed pivot of the side link AB (angle phi) and D that of the side link DC "
        "(angle psi); A = (0, 0), D = (AD, 0).",
        "phi is the angle of A->B and psi the angle of D->C, both measured counter-clockwise "
        "from the direction A->D (psi from the extension of AD beyond D), as absolute "
        "positions, not only differences (CONVENTIONS.md; Freudenstein's form).",
        "The linkage is on one assembly branch through the three positions (the design found "
        "both pins on the branch of the first position).",
    )
    conventions = (
        "Solved analytically by Freudenstein's equation K1 cos psi - K2 cos phi + K3 = "
        "cos(phi - psi), three linear equations (page deriv-function-generation); the "
        "textbook's graphical inversion (2-43)-(2-45) gives the same linkage.",
        "A negative length from the equations means the link points the other way: it is "
        "built with the positive length and its angle + 180°.",
    )
    part1 = Part("The link lengths", (
        Result("l_AB", a, "mm", "|d / K1|"),
        Result("l_BC", b, "mm", "sqrt(a² + c² + d² − 2ac K3)"),
        Result("l_CD", c, "mm", "|d / K2|"),
        Result("l_AD", d, "mm", "given frame"),
        Result("AB points opposite to phi", _flipped(g.theta0, p["phi1"] * _DEG), "",
               "K1 < 0: B lies at phi + 180°"),
        Result("DC points opposite to psi", _flipped(g.psi0, p["psi1"] * _DEG), "",
               "K2 < 0: C lies at psi + 180°"),
    ))
    part2 = Part("Check by analysis", (
        Result("largest output error at the three positions", err, "rad",
               "`FourBar(...).solve` at phi1..phi3 against psi1..psi3 (+180° if DC is reversed)"),
        Result("assembly branch", float(g.branch), "", "+1: C left of B->D"),
        Result("one branch covers phi1..phi3", g.covers_range, "", "FourBar sampled over the range"),
        Result("type", kind, "", "`grashof`"),
        Result("smallest transmission angle over phi1..phi3", gamma, "rad",
               f"at phi = {p['phi1'] + math.degrees(at):.2f}°"),
    ))
    a2, b2, c2, _ = alt.lengths
    part3 = Part("Another reading of the figure", (
        Result("l_AB (psi interior at D)", a2, "mm", "psi measured from D->A: D->C at 180° − psi"),
        Result("l_BC (psi interior at D)", b2, "mm"),
        Result("l_CD (psi interior at D)", c2, "mm"),
    ), ("If the figure measures psi as the interior angle between DA and DC, the same method "
        "gives these lengths instead; the figure decides which is meant.",))
    return Solution("2-29", EXERCISE_2_29.title, dict(p), conventions, (part1, part2, part3),
                    assumptions=assumptions)


def _sample_2_29(rng):
    phi1 = float(rng.integers(20, 90))
    dphi = rng.integers(15, 45, 2)
    psi1 = float(rng.integers(10, 80))
    dpsi = rng.integers(10, 40, 2)
    return {"phi1": phi1, "phi2": phi1 + float(dphi[0]), "phi3": phi1 + float(dphi.sum()),
            "psi1": psi1, "psi2": psi1 + float(dpsi[0]), "psi3": psi1 + float(dpsi.sum()),
            "AD": float(rng.integers(50, 200))}


def _checked_solver(p):
    solution = _solve_2_29(p)
    if not solution["one branch covers phi1..phi3"].value:
        raise ValueError("Expected givens whose design one branch carries through the three positions, got "
                         f"{dict(p)!r}")
    return solution


EXERCISE_2_29 = Exercise(
    number="2-29",
    title="A four-bar through three pairs of side-link positions (function generation)",
    tag="A",
    statement=_STATEMENT_2_29,
    parameters=(
        Parameter("phi1", 60.0, "°", "input link AB, position 1"),
        Parameter("psi1", 30.0, "°", "output link DC, position 1"),
        Parameter("phi2", 90.0, "°", "input, position 2"),
        Parameter("psi2", 50.0, "°", "output, position 2"),
        Parameter("phi3", 120.0, "°", "input, position 3"),
        Parameter("psi3", 80.0, "°", "output, position 3"),
        Parameter("AD", 100.0, "mm", "frame"),
    ),
    solver=_checked_solver,
    sampler=_sample_2_29,
)
