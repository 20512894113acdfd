"""Exercise 2-22 of chapter 2: a lever linkage with friction circles in every pin.

The figure of exercise 2-22 (题图 2-22) is lost: only "A and B are fixed pins, every pin is
25 mm in diameter, mu0 = 0.2, P = 30 N, find Q" survives. The solution states the layout it
assumes (two levers on the fixed pins A and B joined by a link), and solves it with
`mech.planar.forces._statics.static_forces`, with and without friction. The solution is shown on
the book page ``book-forces-static-forces``.

Examples
--------
>>> from mech.exercises.chapter2_statics import EXERCISE_2_22
>>> s = EXERCISE_2_22.solve()
>>> round(float(s["Q without friction"].value), 4)
34.9243
"""

from __future__ import annotations

import math

import numpy as np

from mech._validate import positive_length
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.planar import Linkage, friction_circle, static_forces

__all__ = ["EXERCISE_2_22", "linkage_2_22", "LAYOUT_2_22"]

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
    rho = friction_circle(p["mu0"], d_pin / 2.0)
    L = LAYOUT_2_22
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
            raise ValueError(f"Expected the assumed linkage to move, got self-locking with rho = {rho!r}")
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
