"""Exercises 2-19, 2-20, 2-21, 2-23 and 2-24 of chapter 2: friction, efficiency, self-locking.

The figures are lost; each solution states the geometry it assumes (tag "A") or the
modelling choices the statement leaves open, then computes its answers with the friction and
efficiency functions of `mech.planar` (modules ``forces._friction``, ``forces._efficiency``, ``forces._screw``).
The solutions are shown on the book page ``book-forces-exercises``.

Examples
--------
>>> from mech.exercises import chapter2_forces as cf
>>> round(float(cf.EXERCISE_2_24.solve()["efficiency (run-in collar)"].value), 4)
0.1573
"""

from __future__ import annotations

import math

from mech._validate import positive_length
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.planar import ScrewJack, friction_angle, push_rod, rolling_mill_max_thickness, spreading_wedge_force, thrust_friction_moment

__all__ = ["EXERCISE_2_19", "EXERCISE_2_20", "EXERCISE_2_21", "EXERCISE_2_23", "EXERCISE_2_24", "EXERCISES"]


def _angle(name, value, low=0.0, high=90.0):
    x = float(value)
    if not math.isfinite(x) or not low < x < high or not math.radians(low) < math.radians(x):
        # the last: an angle of a few 1e-324 degrees is 0.0 in radians
        raise ValueError(f"Expected `{name}` in ({low:g}, {high:g}) degrees (and above {low:g} once in radians), "
                         f"got {x!r}")
    return math.radians(x)


def _nonneg(name, value):
    x = float(value)
    if not math.isfinite(x) or x < 0:
        raise ValueError(f"Expected `{name}` >= 0, got {x!r}")
    return x


# ----------------------------------------------------------------------------- 2-19
_STATEMENT_2_19 = (
    "In the wedge connection (楔块联接) of figure 2-19 the angle θ is {theta}°, and the friction "
    "angle of every contact surface is {phi}°. Find the force P on the wedge C needed to "
    "overcome a resistance of {Q} N acting on each of A and B."
)


def _solve_2_19(p):
    Q = positive_length("Q", p["Q"])
    theta, phi = _angle("theta", p["theta"]), _angle("phi", p["phi"], high=45.0)
    if theta + 2 * phi >= math.pi / 2:
        raise ValueError(f"Expected θ + 2φ < 90° from `theta` and `phi` so that the wedge can move, got "
                         f"theta={p['theta']!r}, phi={p['phi']!r} (θ + 2φ = {math.degrees(theta + 2 * phi)!r}°)")
    P = spreading_wedge_force(Q, theta, phi)
    P_faces = spreading_wedge_force(Q, theta, phi, base_friction=False)
    P0 = spreading_wedge_force(Q, theta, 0.0)
    assumptions = (
        "C is a symmetric wedge driven straight down (along its axis) between A and B; each of "
        "its two faces makes θ with the direction of P (θ is the half angle of the wedge).",
        "A and B slide sideways (perpendicular to P) on the frame, each against the resistance "
        f"Q = {Q:g} N along its direction of motion; 'all contact surfaces' are the two wedge "
        "faces and the two surfaces on which A and B slide, all with the friction angle φ.",
    )
    part = Part("Driving force on C", (
        Result("P", P, "N", "`spreading_wedge_force(Q, θ, φ)`: free bodies of A (or B) and C",
               latex=r"P = 2Q\frac{\sin(\theta+\varphi)\cos\varphi}{\cos(\theta+2\varphi)}"),
        Result("P with friction on the wedge faces only", P_faces, "N",
               "`spreading_wedge_force(..., base_friction=False)`", latex=r"P = 2Q\tan(\theta+\varphi)"),
        Result("P without friction", P0, "N", "`spreading_wedge_force(Q, θ, 0)`", latex=r"P_0 = 2Q\tan\theta"),
        Result("efficiency P0/P", P0 / P, "", "(2-24)"),
    ), ("Each face's total reaction on a block is the normal turned by φ against the block's "
        "sliding up the face; the frame's reaction on the block is turned by φ against its "
        "sideways motion. The wedge then balances the vertical parts of both face reactions.",))
    return Solution("2-19", "Wedge connection", p, assumptions=assumptions, parts=(part,))


def _sample_2_19(rng):
    return {"theta": float(rng.integers(8, 31)), "phi": float(rng.integers(4, 16)),
            "Q": float(rng.integers(5, 30) * 100)}


# ----------------------------------------------------------------------------- 2-20
_STATEMENT_2_20 = (
    "In the rolling mill (轧钢机) of figure 2-20 the workpiece 1 is to be drawn in between the "
    "rolls 2 by friction alone, with no horizontal force. (1) Prove that the friction angle φ "
    "between roll and workpiece must not be smaller than α. (2) With roll diameter D = {D} mm, "
    "gap a = {a} mm between the rolls and coefficient of friction μ = {mu}, find the largest "
    "thickness of the workpiece."
)


def _solve_2_20(p):
    D = positive_length("D", p["D"])
    a, mu = _nonneg("a", p["a"]), _nonneg("mu", p["mu"])
    phi = friction_angle(mu)
    h = rolling_mill_max_thickness(D, a, mu)
    conventions = (
        "The two rolls are equal and placed symmetrically; the workpiece moves along the "
        "symmetry line, perpendicular to the line joining the roll centres.",
        "α is the bite angle: the angle at a roll centre between the line of centres and the "
        "radius to the first point of contact.",
    )
    part1 = Part("(1) Condition for gripping", (), (
        "At the first contact the roll pushes the workpiece with N along the radius, which leans "
        "back by α, so its horizontal part N sin α pushes the workpiece out; friction acts along "
        "the roll's surface, inward, with horizontal part at most μN cos α. The workpiece is "
        "drawn in only if μN cos α ≥ N sin α, i.e. tan α ≤ μ = tan φ: φ ≥ α. Equivalently, "
        "the total reaction (normal turned by up to φ) must lean inward of the normal to the "
        "strip's path.",))
    part2 = Part("(2) Largest thickness", (
        Result("friction angle φ", phi, "rad", "`friction_angle(μ)`"),
        Result("largest thickness h_max", h, "mm", "`rolling_mill_max_thickness(D, a, μ)`",
               latex=r"h_{\max} = a + D(1-\cos\varphi)"),
    ), ("With α = φ each roll contributes D(1 − cos φ)/2 to the thickness beyond the gap.",))
    return Solution("2-20", "Gripping by a rolling mill", p, conventions=conventions, parts=(part1, part2))


def _sample_2_20(rng):
    return {"D": float(rng.integers(4, 16) * 100), "a": float(rng.integers(5, 40)),
            "mu": round(float(rng.uniform(0.1, 0.4)), 2)}


# ----------------------------------------------------------------------------- 2-21
_STATEMENT_2_21 = (
    "In the mechanism of figure 2-21 the coefficient of friction between the push rod and its "
    "guide is μ = {mu}; the weights of the members are neglected. What condition must the "
    "length L of the guide satisfy for the force P to move the rod upward without "
    "self-locking? (Assumed offset of P from the rod axis e = {e} mm.)"
)


def _solve_2_21(p):
    mu, e = _nonneg("mu", p["mu"]), positive_length("e", p["e"])
    _, L_min = push_rod(mu, e, 1.0)
    if not (0.0 < L_min and math.isfinite(2.0 * L_min)):
        # mu = 0: no friction, no shortest guide; 2 mu e below the smallest float or too large
        raise ValueError(f"Expected `mu` > 0 and `e` whose shortest guide 2 mu e (and twice it) is a positive "
                         f"finite float, got mu={mu!r}, e={e!r} (2 mu e = {L_min!r})")
    L_example = 2.0 * L_min
    eta_example, _ = push_rod(mu, e, L_example)
    assumptions = (
        "P acts parallel to the guide, upward, along a line at the distance e from the rod's "
        "axis (the text gives no symbol for the offset; e is introduced here).",
        "The moment of P tilts the rod in its guide, so it bears on opposite walls at the two "
        "ends of the guide (two contact points a distance L apart); the resistance moved by "
        "the rod acts along its axis.",
    )
    part = Part("Condition on the guide length", (
        Result("efficiency", None, "", "", latex=r"\eta = 1 - \frac{2\mu e}{L}"),
        Result("shortest guide L_min = 2μe", L_min, "mm", "`push_rod(μ, e, L)`"),
        Result(f"efficiency with L = 2 L_min = {L_example:g} mm", eta_example, "", "`push_rod(μ, e, L)`"),
    ), (f"The rod moves without self-locking iff L > 2μe = {2 * mu:g} e. Moment balance gives "
        "equal normal forces N = P e / L at the guide's ends; the friction 2μN must stay below "
        "the push. The rod's width drops out.",))
    return Solution("2-21", "Push rod in a guide", p, assumptions=assumptions, parts=(part,))


def _sample_2_21(rng):
    return {"mu": round(float(rng.uniform(0.1, 0.4)), 2), "e": float(rng.integers(20, 200))}


# ----------------------------------------------------------------------------- 2-23
_STATEMENT_2_23 = (
    "Two axial-pressure brakes (轴向压力式制动器), figure 2-23: d1 = {d1} mm, d2 = {d2} mm, "
    "d1' = {d1p} mm, α = {alpha}°, μ = {mu}, and both carry the same axial force. Find the "
    "braking torque of each brake in the run-in (跑合) condition."
)


def _solve_2_23(p):
    d1, d2, d1p = (positive_length(n, p[n]) for n in ("d1", "d2", "d1p"))
    alpha, mu = _angle("alpha", p["alpha"], high=90.0 + 1e-9), _nonneg("mu", p["mu"])
    if d1 >= d2 or d1p >= d2:
        raise ValueError(f"Expected `d1` and `d1p` < `d2`, got d1 = {d1!r}, d1p = {d1p!r}, d2 = {d2!r}")
    if not mu > 0.0:
        raise ValueError(f"Expected `mu` > 0 (without friction a brake has no torque to compare), got {mu!r}")
    flat = thrust_friction_moment(1.0, mu, d2 / 2, d1 / 2, condition="run-in")
    cone = thrust_friction_moment(1.0, mu, d2 / 2, d1p / 2, condition="run-in", cone_half_angle=alpha)
    flat_new = thrust_friction_moment(1.0, mu, d2 / 2, d1 / 2)
    cone_new = thrust_friction_moment(1.0, mu, d2 / 2, d1p / 2, cone_half_angle=alpha)
    assumptions = (
        "Brake (a) has one flat annular friction face between the diameters d1 and d2; brake "
        "(b) has one conical friction face between the diameters d1' and d2.",
        "α is the half-angle of the cone: the angle between the cone's face (its generator) "
        "and the axis. A cone face carries the axial force Q with normal forces Q/sin α in "
        "total, which is what makes a cone brake strong.",
        "No value of the axial force is printed: torques are given per newton of axial force "
        "(N·mm/N = mm).",
    )
    part = Part("Braking torques, run in (uniform wear, p·ρ = const)", (
        Result("flat brake: M/Q", flat, "mm", "`thrust_friction_moment(1, μ, d2/2, d1/2, condition='run-in')`",
               latex=r"M = \tfrac12\mu Q\frac{d_1+d_2}{2}"),
        Result("cone brake: M/Q", cone, "mm",
               "`thrust_friction_moment(1, μ, d2/2, d1'/2, condition='run-in', cone_half_angle=α)`",
               latex=r"M = \frac{\mu Q}{2\sin\alpha}\frac{d_1'+d_2}{2}"),
        Result("ratio cone/flat", cone / flat, "", "same axial force"),
        Result("for comparison, new faces (uniform pressure): flat M/Q", flat_new, "mm", "`condition='new'`"),
        Result("for comparison, new faces: cone M/Q", cone_new, "mm", "`condition='new'`"),
    ), ())
    return Solution("2-23", "Flat and conical axial brakes", p, assumptions=assumptions, parts=(part,))


def _sample_2_23(rng):
    d2 = float(rng.integers(15, 30) * 10)
    return {"d1": float(rng.integers(3, 7)) * d2 / 10, "d2": d2, "d1p": float(rng.integers(75, 95)) * d2 / 100,
            "alpha": float(rng.integers(8, 30)), "mu": round(float(rng.uniform(0.15, 0.4)), 2)}


# ----------------------------------------------------------------------------- 2-24
_STATEMENT_2_24 = (
    "In the square-thread screw jack (矩形螺纹千斤顶) of figure 2-24 the thread has mean diameter "
    "d2 = {d2} mm and pitch p = {p} mm; the annular friction face of the collar (托环) has outer "
    "diameter D = {D} mm and inner diameter d0 = {d0} mm; the handle is l = {l} mm long; every "
    "friction surface has μ = {mu}. Find (1) the efficiency of the jack; (2) the load Q it lifts "
    "when F = {F} N is applied at the handle."
)


def _solve_2_24(p):
    d2, pitch, D, d0, l, F = (positive_length(n, p[n]) for n in ("d2", "p", "D", "d0", "l", "F"))
    mu = _nonneg("mu", p["mu"])
    if d0 >= D:
        raise ValueError(f"Expected `d0` < `D`, got d0 = {d0!r} >= D = {D!r}")
    lead = math.atan2(pitch, math.pi * d2)
    if not 0.0 < lead < math.pi / 2:
        # tan(lead) = p / (pi d2): a pitch too small or too large beside d2 rounds it to 0 or 90 degrees
        raise ValueError(f"Expected `p` and `d2` whose lead angle atan(p / (pi d2)) lies strictly between 0 and 90 "
                         f"degrees in floating point, got p={pitch!r}, d2={d2!r}")
    results = []
    for cond, label in (("run-in", "run-in collar"), ("new", "new collar")):
        jack = ScrewJack(d2, pitch, mu, collar=(D, d0), collar_condition=cond)
        r = jack.solve(1.0)
        results.append((label, jack, r))
    _, jack, r = results[0]
    thread_only = ScrewJack(d2, pitch, mu).solve(1.0)
    conventions = (
        "Single-start thread (only the pitch is given), so the lead is p and tan λ = p/(π d2).",
        "Square thread: φ = atan μ. The collar turns against the load cup with the friction "
        "radius (D + d0)/4 if run in (uniform wear), or (D³ − d0³)/(3(D² − d0²)) if new "
        "(uniform pressure); both are given, the run-in one first.",
        "The force F acts at the end of the handle, perpendicular to it: torque F l.",
    )
    part1 = Part("(1) Efficiency", (
        Result("lead angle λ", jack.lead_angle, "rad", "`ScrewJack(...).lead_angle`"),
        Result("friction angle φ", jack.friction_angle, "rad", "`ScrewJack(...).friction_angle`"),
        Result("efficiency of the thread alone", thread_only.efficiency, "",
               "`ScrewJack(d2, p, μ).solve().efficiency`", latex=r"\tan\lambda/\tan(\lambda+\varphi)"),
        *(Result(f"efficiency ({label})", rr.efficiency, "", "`ScrewJack(..., collar=(D, d0)).solve().efficiency`")
          for label, _, rr in results),
        Result("lowering efficiency (run-in collar)", r.reverse_efficiency, "", "`ScrewJack(...).solve().reverse_efficiency`"),
        Result("self-locking", bool(r.self_locking), "",
               f"lowering efficiency ≤ 0; the jack holds for λ ≤ {math.degrees(r.lock_angle):.3f}° "
               f"(the thread alone for λ ≤ φ = {math.degrees(jack.friction_angle):.3f}°)"),
    ), ())
    part2 = Part("(2) Load lifted with F at the handle", tuple(
        Result(f"Q ({label})", F * l / rr.raise_torque, "N", "F l / (torque per newton of load)")
        for label, _, rr in results), ())
    return Solution("2-24", "Screw jack", p, conventions=conventions, parts=(part1, part2))


def _sample_2_24(rng):
    d2 = float(rng.integers(16, 40))
    D = float(rng.integers(40, 70))
    return {"d2": d2, "p": float(rng.integers(3, 8)), "D": D, "d0": D - float(rng.integers(4, 15)),
            "l": float(rng.integers(20, 50) * 10), "mu": round(float(rng.uniform(0.06, 0.15)), 2),
            "F": float(rng.integers(5, 30) * 10)}


# ----------------------------------------------------------------------------- registry
EXERCISE_2_19 = Exercise(
    number="2-19", title="Wedge connection", tag="A", statement=_STATEMENT_2_19,
    parameters=(Parameter("theta", 15.0, "°", "face angle of the wedge"),
                Parameter("phi", 12.0, "°", "friction angle of every contact surface"),
                Parameter("Q", 1000.0, "N", "resistance on each of A and B")),
    solver=_solve_2_19, sampler=_sample_2_19,
)
EXERCISE_2_20 = Exercise(
    number="2-20", title="Gripping by a rolling mill", tag="N", statement=_STATEMENT_2_20,
    parameters=(Parameter("D", 1200.0, "mm", "roll diameter"), Parameter("a", 25.0, "mm", "gap between the rolls"),
                Parameter("mu", 0.3, "", "coefficient of friction roll-workpiece")),
    solver=_solve_2_20, sampler=_sample_2_20,
)
EXERCISE_2_21 = Exercise(
    number="2-21", title="Push rod in a guide", tag="A", statement=_STATEMENT_2_21,
    parameters=(Parameter("mu", 0.2, "", "coefficient of friction rod-guide"),
                Parameter("e", 100.0, "mm", "assumed offset of P from the rod axis (not in the text)")),
    solver=_solve_2_21, sampler=_sample_2_21,
)
EXERCISE_2_23 = Exercise(
    number="2-23", title="Flat and conical axial brakes", tag="A", statement=_STATEMENT_2_23,
    parameters=(Parameter("d1", 100.0, "mm", "inner diameter, flat brake"),
                Parameter("d2", 200.0, "mm", "outer diameter, both brakes"),
                Parameter("d1p", 170.0, "mm", "inner diameter d1', cone brake"),
                Parameter("alpha", 10.0, "°", "half-angle of the cone"),
                Parameter("mu", 0.3, "", "coefficient of friction")),
    solver=_solve_2_23, sampler=_sample_2_23,
)
EXERCISE_2_24 = Exercise(
    number="2-24", title="Screw jack", tag="N", statement=_STATEMENT_2_24,
    parameters=(Parameter("d2", 22.0, "mm", "mean thread diameter"), Parameter("p", 4.0, "mm", "pitch"),
                Parameter("D", 50.0, "mm", "collar outer diameter"), Parameter("d0", 42.0, "mm", "collar inner diameter"),
                Parameter("l", 300.0, "mm", "handle length"), Parameter("mu", 0.1, "", "coefficient of friction"),
                Parameter("F", 100.0, "N", "force at the handle")),
    solver=_solve_2_24, sampler=_sample_2_24,
)

EXERCISES = (EXERCISE_2_19, EXERCISE_2_20, EXERCISE_2_21, EXERCISE_2_23, EXERCISE_2_24)
