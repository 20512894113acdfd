"""Exercises 2-27, 2-28 and 2-29 of chapter 2: guidance and function generation by positions.

The figures of these exercises are lost, so each solution states the layout it assumes.

- 2-27 (furnace door): two-position rigid-body guidance with the moving hinges B and C
  given. Each fixed pivot lies on the perpendicular bisector of its hinge's two positions;
  the stated rule puts both on one vertical line of the furnace frame. The four-bar is
  proved by `guidance_fourbars`, which moves it with `FourBar`.
- 2-28 (rocker to slider): three pairs of rocker and slider positions; by inversion the
  hinge E on the rocker is the circumcentre of the slider pin's positions seen from the
  rocker (`dyad_for_circle_point` with the rocker held still). The six-bar is proved by
  `Linkage`.
- 2-29: three precision pairs of the side links, solved with Freudenstein's equation
  (`mech.planar.synthesis.precision_pairs`) and proved with `FourBar`, with the other common
  reading of the angle (the output angle measured as the interior angle at D).

The solutions are shown on the book pages ``synthesis-guidance`` (2-27) and
``book-synthesis-function-generation`` (2-28, 2-29); the theory on ``deriv-displacement``
and ``deriv-function-generation``.

Examples
--------
>>> from mech.exercises.chapter2_synthesis import EXERCISE_2_29
>>> s = EXERCISE_2_29.solve()
>>> [round(float(s[k].value), 3) for k in ("l_AB", "l_BC", "l_CD")]
[245.948, 82.033, 262.127]
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from mech._errors import AssemblyError
from mech._validate import bool_flag, naming, positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.planar import FourBar, Guide, Linkage, grashof
from mech.planar.synthesis import dyad_for_circle_point, guidance_fourbars, precision_pairs

__all__ = ["EXERCISE_2_27", "EXERCISE_2_28", "EXERCISE_2_29", "RockerSlider", "design_2_27", "design_2_28",
           "design_2_29"]

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
    try:
        design, = precision_pairs(x, y, theta0=phi[0], psi0=psi[0], d=d,
                                  x_range=(min(0.0, x.min()), max(0.0, x.max())))
    except ValueError as exc:      # its message names its own `x`, `y`, `theta0`, ...
        shown = ", ".join(f"{k}={p[k]!r}" for k in ("phi1", "phi2", "phi3", "psi1", "psi2", "psi3", "AD"))
        raise ValueError(
            f"Expected `phi1`, `phi2`, `phi3`, `psi1`, `psi2`, `psi3` and `AD` that admit a four-bar "
            f"through the three precision pairs, got {shown} ({exc})"
        ) from exc
    return design


def _flipped(angle, start):
    return bool(math.cos(angle - start) < 0.0)


def _solve_2_29(p):
    g = design_2_29(p)
    alt = design_2_29(p, interior=True)
    a, b, c, d = g.lengths
    try:
        pose = g.fourbar.solve(g.input_angles, strict=True)
    except AssemblyError as exc:      # its message names the designed four-bar, not a given
        raise AssemblyError(
            f"Expected `phi1`, `phi2` and `phi3` at which the designed four-bar assembles, got "
            f"phi1={p['phi1']!r}, phi2={p['phi2']!r}, phi3={p['phi3']!r} (degrees): {exc}"
        ) from exc
    psi_given = np.array([p["psi1"], p["psi2"], p["psi3"]]) * _DEG
    err = float(np.max(np.abs(np.angle(np.exp(1j * (pose.psi - psi_given - np.pi * _flipped(g.psi0, psi_given[0])))))))
    gamma, at = g.min_transmission_angle
    kind = grashof(a, b, c, d).kind
    assumptions = (
        "A is the fixed pivot of the side link AB (angle phi) and D that of the side link DC "
        "(angle psi); A = (0, 0), D = (AD, 0).",
        "phi is the angle of A->B and psi the angle of D->C, both measured counter-clockwise "
        "from the direction A->D (psi from the extension of AD beyond D), as absolute "
        "positions, not only differences (the book's Conventions page; Freudenstein's form).",
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
        listed, shown = naming(**dict(p))
        raise ValueError(f"Expected {listed} whose design one branch carries through the three positions, "
                         f"got {shown}")
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


# ----------------------------------------------------------------------------- 2-27
_STATEMENT_2_27 = (
    "A hinged four-bar opens and closes the door of an electric furnace. The door carries the "
    "moving hinges B and C: closed, B1 = ({xB1}, {yB1}) and C1 = ({xC1}, {yC1}); open, "
    "B2 = ({xB2}, {yB2}) and C2 = ({xC2}, {yC2}) (mm). Find the fixed pivots A and D and the "
    "lengths AB, BC and CD, with A and D on the vertical line x = {x0} mm of the furnace frame "
    "(the figure with the dimensions is lost)."
)


def _point(p, name):
    return complex(real_number(f"x{name}", p[f"x{name}"]), real_number(f"y{name}", p[f"y{name}"]))


def _bisector_along(P1, P2, x0, moving, fixed):
    """`along` (chords from the middle) of the point of the bisector of P1P2 on the line x = x0."""
    normal = 1j * (P2 - P1)
    if normal.real == 0.0:
        raise ValueError(
            f"Expected `y{moving}2` != `y{moving}1` (the bisector of {moving}1{moving}2 must cross the line "
            f"x = x0 that carries {fixed}), got y{moving}1 = y{moving}2 = {P1.imag!r}"
        )
    return (x0 - 0.5 * (P1 + P2).real) / normal.real


def design_2_27(p):
    """The two-position guidance four-bar of exercise 2-27 for the givens `p` (mm).

    The door is the coupler. Its two poses are taken from the hinges: the reference point is
    B, the reference line B->C, so the door turns by ``angle(C2 - B2) - angle(C1 - B1)``.
    Each fixed pivot lies on the perpendicular bisector of its moving hinge's two positions
    (`dyad_for_circle_point` with two poses); the rule of the exercise puts both on the
    vertical line ``x = p["x0"]``. The pair of cranks is handed to `guidance_fourbars`, which
    moves the four-bar with `FourBar` from the closed pose to the open one.

    Returns
    -------
    GuidanceFourBar
        The four-bar with AB driven (its ``passes``, ``pose_error``, ``gamma_min``, ...).

    Raises
    ------
    ValueError
        If BC differs between the two poses (the door is not rigid), a bisector is parallel
        to the line x = x0, or the lengths make no four-bar.

    Examples
    --------
    >>> from mech.exercises.chapter2_synthesis import EXERCISE_2_27, design_2_27
    >>> g = design_2_27(EXERCISE_2_27.defaults)
    >>> g.passes, g.pose_error < 1e-12, complex(g.origin)
    (True, True, (300+75j))
    """
    B1, C1, B2, C2 = (_point(p, k) for k in ("B1", "C1", "B2", "C2"))
    x0 = real_number("x0", p["x0"])
    span1, span2 = abs(C1 - B1), abs(C2 - B2)
    if not span1 > 0.0 or abs(span2 - span1) > 1e-9 * span1:
        listed, shown = naming(**{f"{x}{k}": p[f"{x}{k}"] for k in ("B1", "C1", "B2", "C2") for x in "xy"})
        raise ValueError(f"Expected {listed} with |B2C2| = |B1C1| > 0 (a rigid door), got {shown} "
                         f"(|B1C1| = {span1!r}, |B2C2| = {span2!r})")
    turn = float(np.angle((C2 - B2) / (C1 - B1)))
    theta, d = np.array([0.0, turn]), np.array([B1, B2])
    crank_b = dyad_for_circle_point(theta, d, 0.0, along=_bisector_along(B1, B2, x0, "B", "A"))
    crank_c = dyad_for_circle_point(theta, d, C1 - B1, along=_bisector_along(C1, C2, x0, "C", "D"))
    found = guidance_fourbars(theta, d, [crank_b, crank_c])
    driven_b = [g for g in found.candidates if g.input_dyad is crank_b]
    if not driven_b:
        listed, shown = naming(**dict(p))
        raise ValueError(f"Expected {listed} whose fixed pivots make a four-bar, got {shown} "
                         f"(A = {complex(crank_b.centre_point)!r}, D = {complex(crank_c.centre_point)!r})")
    return driven_b[0]


def _input_sweep(g):
    """Signed turn of the input from the first pose to the second, the way the analysis moves it."""
    step = float(g.theta_input[1] - g.theta_input[0])
    return float(g.direction * np.remainder(g.direction * step, 2.0 * np.pi)) if g.direction else float("nan")


def _solve_2_27(p):
    g = design_2_27(p)
    L = g.linkage
    A, D = complex(g.origin), complex(g.to_ground(L.d))
    B1, C1, B2 = _point(p, "B1"), _point(p, "C1"), _point(p, "B2")
    turn = float(np.angle((_point(p, "C2") - B2) / (C1 - B1)))
    sweep = _input_sweep(g)
    assumptions = (
        f"The furnace frame offers a vertical line x = {p['x0']:g} mm for the fixed pivots (the figure "
        "would show where A and D may go; the text gives no rule, and any points of the two "
        "bisectors work for two positions).",
        "The door is rigid: the hinges B and C are the same distance apart in both positions; "
        "x to the right, y up, angles counter-clockwise.",
        "AB is the driven link; the door moves from the closed position (1) to the open one (2).",
    )
    conventions = (
        "Two positions: a fixed pivot is any point of the perpendicular bisector of the two "
        "positions of its hinge (`dyad_for_circle_point`, two poses), here where that bisector "
        "meets the frame line.",
        "The four-bar is then moved by `FourBar` (through `guidance_fourbars`) from position 1 "
        "to position 2: it must reproduce both door poses on one assembly branch.",
    )
    part1 = Part("The fixed pivots and the link lengths", (
        Result("door turn from closed to open", turn, "rad", "angle(C2 - B2) - angle(C1 - B1)"),
        Result("A (x)", A.real, "mm", "bisector of B1B2 on the frame line"),
        Result("A (y)", A.imag, "mm"),
        Result("D (x)", D.real, "mm", "bisector of C1C2 on the frame line"),
        Result("D (y)", D.imag, "mm"),
        Result("l_AB", L.a, "mm", "|A - B1| = |A - B2|"),
        Result("l_BC", L.b, "mm", "|B1C1| (the door)"),
        Result("l_CD", L.c, "mm", "|D - C1| = |D - C2|"),
        Result("l_AD", L.d, "mm", "|A - D|"),
    ))
    part2 = Part("Check by analysis", (
        Result("reaches both door positions on one branch", g.passes, "",
               "`FourBar.solve` at the two input angles, C on one side of BD, no dead point between"),
        Result("largest pose error", g.pose_error, "", "relative to the longest link (radians for the turn)"),
        Result("input AB turns by", sweep, "rad", "from closed to open (negative: clockwise)"),
        Result("assembly branch", float(L.branch), "", "+1: C left of B->D"),
        Result("type", g.kind, "", "`grashof`"),
        Result("smallest transmission angle, closed to open", g.gamma_min, "rad", "over the motion"),
    ))
    return Solution("2-27", EXERCISE_2_27.title, dict(p), conventions, (part1, part2), assumptions=assumptions)


def _checked_2_27(p):
    solution = _solve_2_27(p)
    if not solution["reaches both door positions on one branch"].value:
        listed, shown = naming(**dict(p))
        raise ValueError(f"Expected {listed} whose four-bar moves the door from one position to the other "
                         f"on one branch, got {shown}")
    return solution


# rotations with rational sines and cosines keep C2 on the millimetre grid
_TURNS = ((0, 1), (0, -1), (3, 4), (-3, 4), (4, 3), (-4, 3), (3, -4), (4, -3))


def _draw_2_27(rng):
    xb, yb = float(rng.integers(30, 100)), float(rng.integers(300, 450))
    span = 5.0 * float(rng.integers(30, 60))
    c, s = _TURNS[int(rng.integers(len(_TURNS)))]
    c, s = (c / 5.0, s / 5.0) if abs(c) + abs(s) == 7 else (float(c), float(s))
    xB2, yB2 = float(rng.integers(-400, 500)), float(rng.integers(450, 800))
    return {"xB1": xb, "yB1": yb, "xC1": xb, "yC1": yb - span, "xB2": xB2, "yB2": yB2,
            "xC2": xB2 + s * span, "yC2": yB2 - c * span, "x0": float(rng.integers(-50, 300))}


def _sample_2_27(rng, tries=200):
    """A draw whose four-bar passes with a transmission angle of 25° or more and an input
    turn of at most half a turn (else the last draw)."""
    for _ in range(tries):
        p = _draw_2_27(rng)
        try:
            g = design_2_27(p)
        except ValueError:
            continue
        if g.passes and g.gamma_min >= 25.0 * _DEG and abs(_input_sweep(g)) <= np.pi:
            break
    return p


EXERCISE_2_27 = Exercise(
    number="2-27",
    title="A furnace-door four-bar through two positions (rigid-body guidance)",
    tag="A",
    statement=_STATEMENT_2_27,
    parameters=(
        Parameter("xB1", 60.0, "mm", "hinge B, door closed"),
        Parameter("yB1", 380.0, "mm"),
        Parameter("xC1", 60.0, "mm", "hinge C, door closed"),
        Parameter("yC1", 120.0, "mm"),
        Parameter("xB2", 400.0, "mm", "hinge B, door open"),
        Parameter("yB2", 450.0, "mm"),
        Parameter("xC2", 140.0, "mm", "hinge C, door open"),
        Parameter("yC2", 450.0, "mm"),
        Parameter("x0", 300.0, "mm", "vertical line of the frame that carries A and D"),
    ),
    solver=_checked_2_27,
    sampler=_sample_2_27,
)


# ----------------------------------------------------------------------------- 2-28
_STATEMENT_2_28 = (
    "The crank-rocker ABCD has AB = {AB}, BC = {BC}, CD = {CD} and AD = {AD} mm (A at the origin, "
    "D on the +x axis). A link EF is to join the rocker CD to a slider F that runs on the line "
    "y = {e} mm, so that the rocker positions psi1 = {psi1}°, psi2 = {psi2}°, psi3 = {psi3}° (the "
    "angle of D->C from +x) go with the slider positions xF1 = {xF1}, xF2 = {xF2}, xF3 = {xF3} mm "
    "(measured from D along +x). Find the length of EF and where it is hinged on the rocker "
    "(the figure with the dimensions is lost)."
)


@dataclass(frozen=True)
class RockerSlider:
    """The rocker-to-slider link of exercise 2-28 and the six-bar that proves it.

    Attributes
    ----------
    hinge : complex
        The hinge E in the rocker's frame: origin D, x axis along D->C (mm).
    length : float
        The link EF (mm).
    fourbar : FourBar
        The given crank-rocker on the branch that meets the rocker positions in order.
    linkage : Linkage
        The six-bar: crank AB, group BC-CD (joint C), E on the rocker, group EF-slider.
    crank_angles : ndarray, shape (3,)
        Crank angles (radians) at which the rocker is at psi1, psi2, psi3, reached in this
        order by the crank turning counter-clockwise by less than a turn.
    slider_branch : int
        Mode of the RRP group EF-slider (+1: E->F at an acute angle to +x).
    error : float
        Largest error of the six-bar at the three crank angles: slider position relative to
        the longest link, or rocker angle in radians, whichever is larger.
    stroke_assembles : bool
        The six-bar assembles at every sampled crank angle from the first position to the last.
    full_turn : bool
        It also assembles over a whole crank turn.
    gamma_min : float
        Smallest transmission angle at the slider (between EF and the normal to the guide)
        from the first position to the last, radians.
    """

    hinge: complex
    length: float
    fourbar: FourBar
    linkage: Linkage
    crank_angles: np.ndarray
    slider_branch: int
    error: float
    stroke_assembles: bool
    full_turn: bool
    gamma_min: float


def _crank_candidates(a, b, c, d, psi, given):
    """For each rocker angle, the crank angles (two) that put the rocker there, with their branch."""
    C = d + c * np.exp(1j * psi)
    r = np.abs(C)
    with np.errstate(over="ignore", divide="ignore"):      # a crank of 5e-324: |k| = inf, out of reach
        k = (a * a + r * r - b * b) / (2.0 * a * r)
    if np.any(np.abs(k) > 1.0):
        j = int(np.argmax(np.abs(k)))
        raise ValueError(f"Expected `psi{j + 1}` that the crank-rocker (`AB`, `BC`, `CD`, `AD`) = ({a!r}, {b!r}, {c!r}, "
                         f"{d!r}) reaches, got psi{j + 1}={given[j]!r} (degrees), out of its reach")
    out = []
    for Cj, kj in zip(C, k):
        row = []
        for sign in (1.0, -1.0):
            t = float(np.angle(Cj)) + sign * math.acos(float(kj))
            B = a * np.exp(1j * t)
            side = np.imag(np.conj(d - B) * (Cj - B))
            row.append((t, 1 if side > 0 else -1))
        out.append(row)
    return out


def _ordered_crank_angles(a, b, c, d, psi, given, samples=721):
    """Branch and crank angles meeting psi1, psi2, psi3 in order on one stroke (CCW crank)."""
    rows = _crank_candidates(a, b, c, d, psi, given)
    for choice in itertools.product(*rows):
        branch = choice[0][1]
        if any(s != branch for _, s in choice):
            continue
        t = np.array([x for x, _ in choice])
        steps = np.remainder(np.diff(t), 2.0 * math.pi)
        if steps.sum() >= 2.0 * math.pi:
            continue
        fb = FourBar(a, b, c, d, branch=branch)
        sweep = fb.solve(t[0] + np.linspace(0.0, steps.sum(), samples))
        at = fb.solve(t)
        rising = np.diff(np.unwrap(sweep.psi)) * np.sign(psi[-1] - psi[0])
        if (np.all(sweep.valid) and np.all(rising > 0.0)
                and np.max(np.abs(np.angle(np.exp(1j * (at.psi - psi))))) < 1e-9):
            return fb, t[0] + np.concatenate([[0.0], np.cumsum(steps)])
    p1, p2, p3 = given
    raise ValueError("Expected `psi1`, `psi2` and `psi3` that the crank, turning counter-clockwise, meets in this "
                     f"order on one stroke, got psi1={p1!r}, psi2={p2!r}, psi3={p3!r} (degrees) for (`AB`, `BC`, `CD`, `AD`) "
                     f"= ({a!r}, {b!r}, {c!r}, {d!r})")


def design_2_28(p):
    """The rocker-to-slider link of exercise 2-28 for the givens `p` (degrees, mm).

    Inversion: seen from the rocker (frame at D along D->C), the slider pin takes the
    positions ``exp(-1j*psi_j) * (F_j - D)``, and the hinge E is the point of the rocker
    equidistant from all three, their circumcentre. This is `dyad_for_circle_point` with the
    rocker as the fixed link: the relative poses of the slider are ``(-psi_j,
    exp(-1j*psi_j) * (F_j - D))`` and its pin is the body point 0. The six-bar (crank,
    four-bar group, the new link and the slider) is then built as a `Linkage` and moved
    through the three crank angles that put the rocker at psi1, psi2, psi3.

    Returns
    -------
    RockerSlider

    Raises
    ------
    ValueError
        For lengths that are not a four-bar, rocker angles it cannot reach in order on one
        stroke, or slider positions whose inverted images are collinear (no finite link).

    Examples
    --------
    >>> from mech.exercises.chapter2_synthesis import EXERCISE_2_28, design_2_28
    >>> g = design_2_28(EXERCISE_2_28.defaults)
    >>> round(abs(g.hinge), 3), round(g.length, 3), g.error < 1e-12
    (61.74, 152.593, True)
    """
    a, b, c, d = (positive_length(k, p[k]) for k in ("AB", "BC", "CD", "AD"))
    given = tuple(real_number(k, p[k]) for k in ("psi1", "psi2", "psi3"))
    psi = np.array(given) * _DEG
    e = real_number("e", p["e"])
    links = {"AB": a, "BC": b, "CD": c, "AD": d}
    for name, x in links.items():
        rest = math.fsum(v for k, v in links.items() if k != name)
        if not x < rest:      # before the crank angles, which would blame psi1
            others = " + ".join(f"`{k}`" for k in links if k != name)
            raise ValueError(f"Expected `{name}` shorter than the other three links together ({others} = "
                             f"{rest!r}), got AB={a!r}, BC={b!r}, CD={c!r}, AD={d!r}")
    xF = np.array([real_number(k, p[k]) for k in ("xF1", "xF2", "xF3")])
    F = d + xF + 1j * e
    fourbar, crank = _ordered_crank_angles(a, b, c, d, psi, given)
    try:
        link = dyad_for_circle_point(-psi, np.exp(-1j * psi) * (F - d), 0.0)
    except ValueError as exc:     # its message names its own `circle_point`, not a given here
        x1, x2, x3 = (p[k] for k in ("xF1", "xF2", "xF3"))
        raise ValueError(
            f"Expected `xF1`, `xF2`, `xF3` and `e` whose slider positions, seen from the rocker, fix a "
            f"hinge E at a finite, non-zero distance (their circumcentre), got xF1={x1!r}, xF2={x2!r}, "
            f"xF3={x3!r}, e={p['e']!r}"
        ) from exc
    E_local, EF = complex(link.centre_point), float(link.length)
    E1 = d + np.exp(1j * psi[0]) * E_local
    slider_branch = 1 if (F[0] - E1).real >= 0.0 else -1
    six = (Linkage({"A": 0.0, "D": d})
           .crank("crank", pivot="A", tip="B", length=a)
           .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c), branch=fourbar.branch)
           .point("E", link="rocker", at=E_local)
           .rrp(("link", "slider"), pin="E", guide=Guide("ground", through=1j * e, angle=0.0), joint="F",
                length=EF, branch=slider_branch))
    with np.errstate(invalid="ignore"):
        at = six.solve(crank)
        unit = max(a, b, c, d, EF)
        err_F = np.max(np.abs(at.points["F"] - F)) / unit
        err_psi = np.max(np.abs(np.angle(np.exp(1j * (np.angle(at.points["C"] - d) - psi)))))
        error = float(max(err_F, err_psi)) if np.all(at.valid) else float("inf")
        sweep = six.solve(np.linspace(crank[0], crank[-1], 721))
        turn = six.solve(np.linspace(0.0, 2.0 * math.pi, 1441))
        rod = sweep.points["F"] - sweep.points["E"]
        gamma = np.arcsin(np.clip(np.abs(rod.real) / np.abs(rod), 0.0, 1.0))
    stroke = bool(np.all(sweep.valid))
    return RockerSlider(E_local, EF, fourbar, six, crank, slider_branch, error, stroke,
                        bool(np.all(turn.valid)), float(np.min(gamma)) if stroke else float("nan"))


def _solve_2_28(p):
    g = design_2_28(p)
    E = g.hinge
    assumptions = (
        "A = (0, 0) and D = (AD, 0); the slider F runs on the horizontal line y = e; its "
        "positions are measured from D along +x; psi is the angle of D->C from +x, "
        "counter-clockwise.",
        "The crank turns counter-clockwise; the crank-rocker is on the assembly branch on "
        "which it meets the three rocker positions in order on one stroke.",
        "The rocker is a rigid plate: the hinge E may lie off the line DC (three position pairs "
        "fix E completely, so it falls on DC only for specially chosen data).",
    )
    conventions = (
        "Inversion principle: fix the rocker and turn everything else back by -psi_j about D; "
        "the slider pin then takes three positions in the rocker's frame, and E is the centre "
        "of the circle through them (`dyad_for_circle_point` with the rocker as the fixed link).",
        "The six-bar crank AB + group BC-CD + link EF + slider is then built as a `Linkage` and "
        "moved to the three crank angles that set the rocker at psi1, psi2, psi3.",
    )
    part1 = Part("The link EF", (
        Result("l_DE", abs(E), "mm", "distance of the hinge E from D"),
        Result("angle of DE from DC", float(np.angle(E)), "rad", "counter-clockwise, fixed in the rocker"),
        Result("E off the line DC", abs(E.imag), "mm", "distance of E from the line DC"),
        Result("l_EF", g.length, "mm", "radius of the circle through the inverted slider positions"),
        Result("E1 (x)", float((p["AD"] + np.exp(1j * p["psi1"] * _DEG) * E).real), "mm", "E at position 1"),
        Result("E1 (y)", float((p["AD"] + np.exp(1j * p["psi1"] * _DEG) * E).imag), "mm"),
    ))
    part2 = Part("Check by analysis", (
        Result("crank angle at position 1", float(np.angle(np.exp(1j * g.crank_angles[0]))), "rad",
               "where the rocker is at psi1"),
        Result("crank turn from position 1 to 3", float(g.crank_angles[-1] - g.crank_angles[0]), "rad",
               "counter-clockwise, one stroke"),
        Result("largest error at the three positions", g.error, "",
               "`Linkage.solve`: slider position (relative to the longest link) and rocker angle (rad)"),
        Result("assembles from position 1 to 3", g.stroke_assembles, "", "one mode of every group"),
        Result("assembles over a full crank turn", g.full_turn, "", "1441 crank angles"),
        Result("four-bar branch", float(g.fourbar.branch), "", "+1: C left of B->D"),
        Result("slider-group branch", float(g.slider_branch), "", "+1: E->F points along +x"),
        Result("smallest transmission angle at F, positions 1 to 3", g.gamma_min, "rad",
               "between EF and the normal to the guide"),
    ))
    return Solution("2-28", EXERCISE_2_28.title, dict(p), conventions, (part1, part2), assumptions=assumptions)


def _checked_2_28(p):
    solution = _solve_2_28(p)
    if not (solution["assembles from position 1 to 3"].value
            and solution["largest error at the three positions"].value <= 1e-9):
        listed, shown = naming(**dict(p))
        raise ValueError(f"Expected {listed} whose six-bar carries the link through the three positions, "
                         f"got {shown}")
    return solution


def _sample_2_28(rng):
    a = float(rng.integers(20, 50))
    d = float(rng.integers(100, 160))
    c = float(rng.integers(60, 110))
    low, high = max(d - c + a, c - d + a) + 10.0, d + c - a - 10.0      # a crank-rocker with a margin
    b = float(rng.integers(int(low), int(high)))
    lp = FourBar(a, b, c, d, branch=1).limit_positions()
    lo, hi = sorted((math.degrees(lp.psi_extended), math.degrees(lp.psi_folded)))
    psi = np.sort(rng.uniform(lo + 3.0, hi - 3.0, 3))
    if np.min(np.diff(psi)) < 5.0:
        psi = np.array([lo + 5.0, 0.5 * (lo + hi), hi - 5.0])
    psi = np.round(psi)
    DE, EF = float(rng.integers(30, 80)), float(rng.integers(100, 200))
    e = float(rng.integers(-40, 41))
    E = d + DE * np.exp(1j * (psi * _DEG + rng.uniform(-0.1, 0.1)))
    F = E.real + np.sqrt(np.maximum(EF**2 - (e - E.imag) ** 2, 0.0))
    xF = np.round(F - d)
    return {"AB": a, "BC": b, "CD": c, "AD": d, "psi1": float(psi[0]), "psi2": float(psi[1]),
            "psi3": float(psi[2]), "e": e, "xF1": float(xF[0]), "xF2": float(xF[1]), "xF3": float(xF[2])}


EXERCISE_2_28 = Exercise(
    number="2-28",
    title="A link from a rocker to a slider through three pairs of positions (inversion)",
    tag="A",
    statement=_STATEMENT_2_28,
    parameters=(
        Parameter("AB", 40.0, "mm", "crank"),
        Parameter("BC", 120.0, "mm", "coupler"),
        Parameter("CD", 80.0, "mm", "rocker"),
        Parameter("AD", 130.0, "mm", "frame"),
        Parameter("psi1", 90.0, "°", "rocker, position 1"),
        Parameter("psi2", 110.0, "°", "rocker, position 2"),
        Parameter("psi3", 130.0, "°", "rocker, position 3"),
        Parameter("e", 0.0, "mm", "height of the slider's line"),
        Parameter("xF1", 137.0, "mm", "slider, position 1 (from D)"),
        Parameter("xF2", 118.0, "mm", "slider, position 2"),
        Parameter("xF3", 104.0, "mm", "slider, position 3"),
    ),
    solver=_checked_2_28,
    sampler=_sample_2_28,
)
