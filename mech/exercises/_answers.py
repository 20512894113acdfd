"""One vocabulary of answer names (keys) for every exercise, and what each key asks for.

A key names a number that the exercise's statement asks for, in the symbol's own name
(``gamma_min``, ``K``, ``l_AB``, ``v_F``), the same name in every exercise. The worked
solution may hold more results (checks, intermediate values); only the keys listed here are
asked on a sheet, a quiz or a gradebook. Each key is a result of the solution, a number
read from one (an end of an interval, a coordinate of an instant centre), or one per
part. The old, automatically spelt keys (``minimum_transmission_angle_gamma_min``) stay
accepted by ``check`` as aliases. Only NumPy and the standard library are used here.
"""

from __future__ import annotations

import math
import re

import numpy as np

__all__ = ["ANSWER_KEYS", "key_table", "answers"]


def _r(name):
    """The numeric value of the result called ``name``."""
    return ("result", name)


def _interval(name, end):
    """The lowest (``end="low"``) or highest end of the union of intervals ``name``."""
    return ("interval", name, end)


def _centre(part, name, axis):
    """A coordinate (``axis`` 0 for x, 1 for y) of the instant centre ``name`` in ``part``."""
    return ("centre", part, name, axis)


def _reactions_2_26():
    rows = []
    for th in (45, 135, 225, 315):
        at = f"θ = {th}°: "
        rows += [(f"F_{th}", _r(at + "driving force F"), f"driving force F at θ = {th}°")]
        for pair, about in (("41", "A"), ("21", "B"), ("23", "C")):
            rows += [(f"R{pair}_{th}", _r(f"{at}R_{pair} size"), f"size of R{pair} at θ = {th}°"),
                     (f"R{pair}_angle_{th}", _r(f"{at}R_{pair} direction"),
                      f"direction of R{pair} from +x at θ = {th}°"),
                     (f"R{pair}_arm_{th}", _r(f"{at}R_{pair} moment arm about {about}"),
                      f"moment arm of R{pair} about {about} at θ = {th}°")]
        rows += [(f"R43_tilt_{th}", _r(at + "R_43 tilt from the guide normal"),
                  f"tilt of R43 from the guide's normal at θ = {th}°")]
    return rows


def _reactions(pairs, extra):
    rows = []
    for pair, at in pairs:
        rows += [(f"R{pair}", _r(f"R_{pair} at {at}"), f"size of the reaction R{pair} at {at}"),
                 (f"R{pair}_angle", _r(f"direction of R_{pair}"), f"direction of R{pair} from +x")]
    return rows + extra


def _centres_2_8():
    rows = []
    for part in "abc":
        for name in ("P12", "P13", "P14", "P23", "P24", "P34"):
            for axis, xy in enumerate("xy"):
                rows.append((f"{name}_{xy}_{part}", _centre(part, name, axis),
                             f"{xy} of the instant centre {name} of mechanism ({part})"))
    return rows


#: Exercise number -> tuple of (key, source, what it asks), in the order of the statement.
ANSWER_KEYS = {
    "2-1": tuple((f"{sym}_{m}", _r(f"({m}) {name}"), f"{what} of mechanism ({m})")
                 for m in "abc" for sym, name, what in (
                     ("n", "moving links n", "moving links n"), ("P_L", "lower pairs P_L", "lower pairs P_L"),
                     ("F", "degrees of freedom F", "degrees of freedom F"))),
    "2-2": (("AB_crank_rocker_max", _interval("AB for a crank-rocker", "high"),
             "longest AB of a crank-rocker"),
            ("AB_double_crank_min", _interval("AB for a double-crank", "low"), "shortest AB of a double-crank"),
            ("AB_double_crank_max", _interval("AB for a double-crank", "high"), "longest AB of a double-crank")),
    "2-3": (("theta", _r("extreme-position angle θ"), "extreme-position angle θ"),
            ("K", _r("time ratio K"), "time ratio K"),
            ("phi", _r("swing φ of CD"), "largest swing φ of CD"),
            ("gamma_min", _r("minimum transmission angle γ_min"), "minimum transmission angle γ_min")),
    "2-4": (("K", _r("time ratio K"), "time ratio K of the mechanism"),
            ("H", _r("stroke H of F"), "stroke H of the slider F"),
            ("gamma_min", _r("mechanism γ_min"), "minimum transmission angle of the mechanism"),
            ("h_guide", _r("best guide height h*"), "height h of the guide that makes the pressure angle smallest")),
    "2-5": (("K", _r("time ratio K"), "time ratio K"),
            ("H", _r("stroke H of member 5"), "stroke H of member 5"),
            ("gamma_min", _r("γ_min (slider stage)"), "minimum transmission angle γ_min"),
            ("gamma_max", _r("largest γ of the slider stage"), "largest transmission angle"),
            ("alpha_max", _r("α_max"), "largest pressure angle α_max of the slider"),
            ("l_AB_2H", _r("crank length for 2H"), "crank length AB that doubles the stroke")),
    "2-6": (("gamma_min", _r("γ_min"), "minimum transmission angle γ_min of the offset linkage"),
            ("theta_gamma_min", _r("crank angle at γ_min"), "crank angle where γ_min occurs"),
            ("gamma_max_centric", _r("largest γ (at θ = 0° and 180°)"), "largest γ for e = 0"),
            ("gamma_min_centric", _r("smallest γ (at θ = ±90°)"), "smallest γ for e = 0"),
            ("H_centric", _r("stroke, centric"), "stroke H for e = 0"),
            ("H", _r("stroke, offset"), "stroke H of the offset linkage")),
    "2-7": (("l_BC", _r("crank length BC"), "crank length BC"),
            ("H", _r("stroke H of P"), "stroke H of the tool P")),
    "2-8": tuple(_centres_2_8()),
    "2-9": (("omega1_omega3", _r("ω1/ω3"), "speed ratio ω1/ω3"),),
    "2-10": (("omega2", _r("ω2"), "angular velocity ω2 of the follower (counter-clockwise positive)"),),
    "2-11": (("omega4_omega2", _r("ω4/ω2"), "ratio ω4/ω2 (signed)"),),
    "2-12": (("v_I", _r("v_I"), "speed of the point I"),
             ("v_I_angle", _r("direction of v_I"), "direction of v_I from +x")),
    "2-13": (("x_E_min", _r("leftmost x_E"), "leftmost position x_E of the piston"),
             ("x_E_max", _r("rightmost x_E"), "rightmost position x_E of the piston"),
             ("H", _r("stroke H of E"), "stroke H of E"),
             ("v_E", _r("v_E"), "velocity of E along x at φ1 = 0"),
             ("a_E", _r("a_E"), "acceleration of E along x at φ1 = 0")),
    "2-14": (("v_F", _r("v_F"), "velocity of F"), ("a_F", _r("a_F"), "acceleration of F")),
    "2-15": (("omega3", _r("ω3"), "angular velocity of member 3"),
             ("alpha3", _r("α3"), "angular acceleration of member 3"),
             ("v5", _r("v5"), "velocity of member 5"), ("a5", _r("a5"), "acceleration of member 5")),
    "2-16": (("v_F", _r("v_F"), "velocity of F"), ("a_F", _r("a_F"), "acceleration of F")),
    "2-17": tuple(_reactions((("01", "A"), ("12", "B"), ("23", "C"), ("03", "D"), ("34", "S"), ("45", "K"),
                              ("05", "the guide")),
                             [("P1", _r("balancing force P1"), "balancing force P1 at E")])),
    "2-18": tuple(_reactions((("01", "A"), ("12", "B"), ("23", "C"), ("03", "E"), ("34", "D"), ("45", "F"),
                              ("05", "the guide")),
                             [("M1", _r("balancing moment M1"), "balancing moment M1 on member 1")])),
    "2-19": (("P", _r("P"), "force P on the wedge"),),
    "2-20": (("h_max", _r("largest thickness h_max"), "largest thickness of the workpiece"),),
    "2-21": (("L_min", _r("shortest guide L_min = 2μe"), "shortest guide length without self-locking"),),
    "2-22": (("Q", _r("Q with friction"), "force Q that P overcomes, with friction"),),
    "2-23": (("M_Q_flat", _r("flat brake: M/Q"), "braking torque of the flat brake per unit axial force"),
             ("M_Q_cone", _r("cone brake: M/Q"), "braking torque of the cone brake per unit axial force")),
    "2-24": (("eta", _r("efficiency (run-in collar)"), "efficiency of the jack (run-in collar)"),
             ("Q", _r("Q (run-in collar)"), "load Q lifted with F at the handle (run-in collar)")),
    "2-25": tuple((k, _r(n), w) for k, n, w in (
        ("R12", "R12 size", "size of R12"), ("R12_angle", "R12 direction", "direction of R12 from +x"),
        ("R12_arm", "R12 moment arm about K", "moment arm of R12 about K"),
        ("R32", "R32 size", "size of R32"), ("R32_angle", "R32 direction", "direction of R32 from +x"),
        ("R32_arm", "R32 moment arm about D", "moment arm of R32 about D"),
        ("R31", "R31 size", "size of R31"), ("R31_angle", "R31 direction", "direction of R31 from +x"),
        ("R31_arm", "R31 moment arm about A", "moment arm of R31 about A"),
        ("eta", "efficiency η", "efficiency η"))),
    "2-26": tuple(_reactions_2_26()),
    "2-27": (("A_y", _r("A (y)"), "height of the fixed pivot A"), ("D_y", _r("D (y)"), "height of the fixed pivot D"),
             ("l_AB", _r("l_AB"), "length AB"), ("l_BC", _r("l_BC"), "length BC"), ("l_CD", _r("l_CD"), "length CD")),
    "2-28": (("l_EF", _r("l_EF"), "length EF"), ("l_DE", _r("l_DE"), "distance DE of the hinge E from D"),
             ("DE_angle", _r("angle of DE from DC"), "angle of DE from DC")),
    "2-29": (("l_AB", _r("l_AB"), "length AB"), ("l_BC", _r("l_BC"), "length BC"), ("l_CD", _r("l_CD"), "length CD")),
    "2-30": (("l_BC_1", _r("(1) l_BC, D on the side of A"), "(1) coupler BC (D on the side of A)"),
             ("l_AD_1", _r("(1) l_AD, D on the side of A"), "(1) frame AD (D on the side of A)"),
             ("gamma_min_1", _r("(1) gamma_min simulated, D on the side of A"), "(1) minimum transmission angle"),
             ("l_AB_2", _r("(2) l_AB, D on the side of A"), "(2) crank AB (D on the side of A)"),
             ("l_AD_2", _r("(2) l_AD, D on the side of A"), "(2) frame AD (D on the side of A)")),
    # a variant whose other limit position gives no crank-rocker has design 1 only
    "2-31": (("l_AB_1", _r("design 1: l_AB"), "crank AB of design 1"),
             ("l_BC_1", _r("design 1: l_BC"), "coupler BC of design 1"),
             ("l_AB_2", _r("design 2: l_AB"), "crank AB of design 2"),
             ("l_BC_2", _r("design 2: l_BC"), "coupler BC of design 2")),
    "2-32": (("l_AC", _r("l_AC"), "frame AC"), ("l_CD", _r("l_CD"), "guide bar CD"),
             ("h_C", _r("distance of the ram's path from C"), "distance of the ram's path from C")),
    # the worked examples with variants (mech.exercises.examples_chapter2)
    "E2-1": (("phi", _r("swing φ of CD"), "swing φ of the rocker CD"),
             ("theta", _r("extreme-position angle θ"), "extreme-position angle θ"),
             ("K", _r("time ratio K"), "time ratio K"),
             ("gamma_min", _r("minimum transmission angle γ_min"), "minimum transmission angle γ_min")),
    "E2-2": (("l_AB", _r("crank length AB"), "crank length AB"), ("K", _r("time ratio K"), "time ratio K"),
             ("L_min", _r("shortest guide"), "shortest length of the guide")),
    "E2-3": (("theta", _r("extreme-position angle θ"), "extreme-position angle θ"),
             ("H", _r("stroke H"), "stroke H of the slider"), ("K", _r("time ratio K"), "time ratio K")),
    "E2-4": (("P13_x", _r("P13 (x)"), "x of the instant centre P13 (on the line AD, from A)"),
             ("P24_x", _r("P24 (x)"), "x of the instant centre P24"), ("P24_y", _r("P24 (y)"), "y of P24"),
             ("omega2", _r("ω2"), "angular velocity ω2 of the coupler (counter-clockwise positive)"),
             ("omega3", _r("ω3"), "angular velocity ω3 of the rocker (counter-clockwise positive)")),
    "E2-5": (("P13_y", _r("P13 (y)"), "y of the instant centre P13 (on the line through A across the guide)"),
             ("omega2", _r("ω2"), "angular velocity ω2 of the rod (counter-clockwise positive)"),
             ("v_C", _r("v3"), "velocity of the slider C along the guide (signed)")),
    "E2-7": (("P12_x", _r("P12 (x)"), "x of the instant centre P12 (on the line through A across the path)"),
             ("v2", _r("v2"), "velocity v2 of the follower (positive upwards)")),
    "E2-8": (("omega2", _r("ω2"), "angular velocity ω2 of the coupler (counter-clockwise positive)"),
             ("omega3", _r("ω3"), "angular velocity ω3 of the rocker (counter-clockwise positive)"),
             ("alpha2", _r("α2"), "angular acceleration α2 of the coupler (counter-clockwise positive)"),
             ("alpha3", _r("α3"), "angular acceleration α3 of the rocker (counter-clockwise positive)"),
             ("v_E", _r("v_E"), "speed of the coupler point E"), ("a_E", _r("a_E"), "acceleration of E (size)")),
    "E2-9": (("omega3", _r("ω3"), "angular velocity ω3 of the guide (counter-clockwise positive)"),
             ("alpha3", _r("α3"), "angular acceleration α3 of the guide (counter-clockwise positive)"),
             ("a_k", _r("Coriolis acceleration a^k"), "size of the Coriolis acceleration of B")),
    "E2-11": (("P", _r("push P"), "push P while pressing"), ("eta", _r("efficiency η"), "efficiency η"),
              ("P_release", _r("push P′ on the release"), "push P′ on the release (signed)"),
              ("eta_release", _r("efficiency η′"), "efficiency η′ of the release")),
    "E2-12": (("R12", _r("R12"), "size of the force R12 between crank and coupler"),
              ("M_d", _r("M_d"), "driving moment M_d on the crank (counter-clockwise positive)")),
    "E2-14": (("x_lock", _r("x_lock"), "largest distance x at which the linkage locks itself"),),
    "E2-17": (("l_BC", _r("coupler BC"), "coupler BC"), ("l_AD", _r("frame AD"), "frame AD"),
              ("gamma_min", _r("minimum transmission angle γ_min"), "minimum transmission angle γ_min")),
    "E2-18": (("l_AB", _r("crank AB"), "crank AB"), ("l_AD", _r("frame AD"), "frame AD"),
              ("gamma_min", _r("minimum transmission angle γ_min"), "minimum transmission angle γ_min")),
    "E2-25": (("P_x", _r("P (x0)"), "x0 of the gripper point P"), ("P_y", _r("P (y0)"), "y0 of P"),
              ("P_z", _r("P (z0)"), "z0 of P"), ("l_AP", _r("AP"), "distance AP of P from the base")),
    "E2-19": (("l_AB", _r("crank length AB"), "crank length AB"), ("l_BC", _r("rod length BC"), "rod length BC"),
              ("gamma_min", _r("minimum transmission angle γ_min"), "minimum transmission angle γ_min")),
    "E2-20": (("theta", _r("extreme-position angle θ"), "extreme-position angle θ"),
              ("l_AB", _r("crank length AB"), "crank length AB"),
              ("L_min", _r("shortest guide"), "shortest length of the guide")),
}

_POINT = re.compile(r"\(\s*(-?[0-9.]+(?:e[-+]?\d+)?),\s*(-?[0-9.]+(?:e[-+]?\d+)?)\)")


def _numeric(value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        return None
    value = float(value)
    return value if math.isfinite(value) else None


def answers(solution):
    """The answers of ``solution`` that the statement asks for, as a list of
    ``(key, name, value, unit, what)``; angles in degrees. A key whose number the variant does
    not have (an empty interval, an instant centre at infinity) is left out."""
    by_name = {}
    for r in solution.results():
        by_name.setdefault(r.name, r)
    out = []
    for key, source, what in ANSWER_KEYS.get(solution.number, ()):
        kind = source[0]
        if kind == "result":
            r = by_name.get(source[1])
            v = None if r is None else _numeric(r.value)
            if v is None:
                continue
            unit = r.unit
            if unit == "rad":
                v, unit = math.degrees(v), "deg"
            out.append((key, r.name, v, unit, what))
        elif kind == "interval":
            r = by_name.get(source[1])
            if r is None or not r.value:
                continue
            v = min(i.low for i in r.value) if source[2] == "low" else max(i.high for i in r.value)
            if math.isfinite(v):
                out.append((key, f"{r.name}: {'lowest' if source[2] == 'low' else 'highest'} end", v, "mm", what))
        else:
            _, part, name, axis = source
            for p in solution.parts:
                if not p.title.startswith(f"({part})"):
                    continue
                for r in p.results:
                    m = _POINT.fullmatch(str(r.value).replace(" mm", "").strip()) if r.name == name else None
                    if m:
                        out.append((key, f"({part}) {name} ({'xy'[axis]})", float(m.group(axis + 1)), "mm", what))
    return out


def key_table():
    """Rows ``(exercise, key, what it asks)`` of every exercise, for the book's table."""
    return [(number, key, what) for number, rows in ANSWER_KEYS.items() for key, _, what in rows]
