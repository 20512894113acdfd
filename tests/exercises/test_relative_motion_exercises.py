"""Tests of exercises 2-13, 2-15 and 2-16 (velocity and acceleration on assumed layouts).

The expected values come from another route than the solver's `Linkage`: the positions are
written by hand as intersections of circles and lines on the assumed layout and evaluated
with mpmath at 50 digits; velocities and accelerations are their first and second
derivatives with respect to the crank angle (mpmath's numerical differentiation at that
precision) times the crank speed. The relative-motion polygons built from the solution
must close.
"""

import math
import subprocess
import sys

import mpmath as mp
import numpy as np
import pytest

from mech.exercises import chapter2_relative_motion as rm
from mech.planar import acceleration_polygon, relative_motion, velocity_polygon

mp.mp.dps = 50
SEEDS = [0, 1, 7]


def _circles(p, rp, q, rq, side):
    """Intersection of circle (p, rp) and circle (q, rq) to the left (side=+1) of p->q."""
    d = q - p
    L = abs(d)
    a = (rp * rp - rq * rq + L * L) / (2 * L)
    h = mp.sqrt(rp * rp - a * a)
    return p + d / L * mp.mpc(a, side * h)


def _line_y(c, r, y, right=True):
    """Point on the line y = const at distance r from c, to the right (or left) of c."""
    dx = mp.sqrt(r * r - (y - c.imag) ** 2)
    return mp.mpc(c.real + (dx if right else -dx), y)


def _rates(f, t, w):
    """Value, velocity and acceleration of f(theta) at theta = t for a constant rate w."""
    t = mp.mpf(t)
    return f(t), mp.diff(f, t) * w, mp.diff(f, t, 2) * w * w


# ----------------------------------------------------------------------------- 2-13
def _hay_press(p):
    P = {k: mp.mpf(v) for k, v in p.items()}
    D = mp.mpc(P["xD"], P["yD"])

    def E(t):
        A = P["OA"] * mp.expjpi(t / mp.pi)
        B = _circles(A, P["AB"], D, P["BD"], -1)
        C = B + (D - B) * P["BC"] / P["BD"]
        return _line_y(C, P["CE"], P["yE"]).real
    return E


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_13_against_hand_closure(seed):
    ex = rm.EXERCISE_2_13
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    E = _hay_press(p)
    x, v, a = _rates(E, 0, p["omega1"])
    assert s["x_E at φ1 = 0"].value == pytest.approx(float(x), rel=1e-12)
    assert s["v_E"].value == pytest.approx(float(v) / 1000, rel=1e-8, abs=1e-12)
    assert s["a_E"].value == pytest.approx(float(a) / 1000, rel=1e-7, abs=1e-10)
    # the extreme positions: roots of dx/dtheta by mpmath, started from the solver's angles
    for name, t0 in (("leftmost x_E", s["crank angle at the leftmost position"].value),
                     ("rightmost x_E", s["crank angle at the rightmost position"].value)):
        t = mp.findroot(lambda u: mp.diff(E, u), mp.mpf(t0) + mp.mpf("1e-3"))
        assert s[name].value == pytest.approx(float(E(t)), rel=1e-12)
        assert abs(float(t) - t0) % (2 * math.pi) < 1e-6
    assert s["stroke H of E"].value == pytest.approx(s["rightmost x_E"].value - s["leftmost x_E"].value, rel=1e-12)


def test_exercise_2_13_polygons_close():
    sol = rm.linkage_2_13().solve(0.0, order=2, omega=10.0)
    motions = [relative_motion(sol, "B", base="A", link="coupler", pivot="D", pivot_link="rocker"),
               relative_motion(sol, "E", base="C", link="rod")]
    assert velocity_polygon(motions).closure < 1e-9
    assert acceleration_polygon(motions).closure < 1e-6


# ----------------------------------------------------------------------------- 2-15
def _two_sliders(p):
    P = {k: mp.mpf(v) for k, v in p.items()}

    def pts(t):
        B = P["AB"] * mp.expjpi(t / mp.pi)
        C = mp.mpc(0, B.imag + mp.sqrt(P["BC"] ** 2 - B.real ** 2))
        D = B + (C - B) * P["BD"] / P["BC"]
        E = _line_y(D, P["DE"], 0)
        return B, C, D, E
    return pts


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_15_against_hand_closure(seed):
    ex = rm.EXERCISE_2_15
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    pts = _two_sliders(p)
    t = mp.radians(p["phi1"])

    def ang3(u):
        B, C, _, _ = pts(u)
        return mp.atan2((C - B).imag, (C - B).real)
    _, w3, a3 = _rates(ang3, t, p["omega1"])
    _, v5, a5 = _rates(lambda u: pts(u)[3].real, t, p["omega1"])
    assert s["ω3"].value == pytest.approx(float(w3), rel=1e-10)
    assert s["α3"].value == pytest.approx(float(a3), rel=1e-8)
    assert s["v5"].value == pytest.approx(float(v5) / 1000, rel=1e-10)
    assert s["a5"].value == pytest.approx(float(a5) / 1000, rel=1e-8)


def test_exercise_2_15_textbook_numbers():
    s = rm.EXERCISE_2_15.solve()
    assert s["ω3"].value == pytest.approx(-1.965365346, rel=1e-8)
    assert s["v5"].value == pytest.approx(-1.339696164, rel=1e-8)


# ----------------------------------------------------------------------------- 2-16
def _rocker_slider(p):
    P = {k: mp.mpf(v) for k, v in p.items()}
    D = mp.mpc(P["xD"], P["yD"])

    def yF(t):                                   # t: the book's clockwise crank angle
        B = P["AB"] * mp.expjpi(-t / mp.pi)
        C = _circles(B, P["BC"], D, P["CD"], -1)
        u = (C - D) / abs(C - D)
        return D.imag + (P["xF"] - D.real) * u.imag / u.real
    return yF


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_16_against_hand_closure(seed):
    ex = rm.EXERCISE_2_16
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    y, v, a = _rates(_rocker_slider(p), mp.radians(p["phi1"]), p["omega1"])
    assert s["y_F"].value == pytest.approx(float(y), rel=1e-12)
    assert s["v_F"].value == pytest.approx(float(v) / 1000, rel=1e-9)
    assert s["a_F"].value == pytest.approx(float(a) / 1000, rel=1e-8)


def test_exercise_2_16_coriolis_polygon_closes():
    p = rm.EXERCISE_2_16.defaults
    sol = rm.linkage_2_16().solve(-math.radians(p["phi1"]), order=2, omega=-p["omega1"])
    from mech.planar import coincident_motion
    motions = [relative_motion(sol, "C", base="B", link="2", pivot="D", pivot_link="3"),
               coincident_motion(sol, "F", carrier="4", link="3", pivot="D")]
    assert velocity_polygon(motions).closure < 1e-7
    assert acceleration_polygon(motions).closure < 1e-3


# ----------------------------------------------------------------------------- all three
@pytest.mark.parametrize("number", ["2-12", "2-13", "2-14", "2-15", "2-16"])
def test_cli_show_and_variant(number):
    for args in (["show", number], ["variant", number, "--seed", "7"]):
        out = subprocess.run([sys.executable, "-m", "mech.exercises", *args], capture_output=True, text=True,
                             check=True).stdout
        assert f"Solution of exercise {number}" in out and "Assumed layout" in out


@pytest.mark.parametrize("exercise", rm.EXERCISES, ids=lambda e: e.number)
def test_variant_reproducible(exercise):
    assert exercise.variant(7) == exercise.variant(7)
    assert np.all([np.isfinite(v) for v in exercise.solve(exercise.variant(7)).values().values()
                   if isinstance(v, float)])


# ----------------------------------------------------------------------------- 2-12 and 2-14
@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_12_pantograph_scale(seed):
    """v_I from I = 2 E (the pantograph's similarity about the fixed pivot O), differentiated."""
    ex = rm.EXERCISE_2_12
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    a, b, h = (mp.mpf(p[k]) for k in ("a", "b", "h"))

    def E(t):
        B = a * mp.expjpi(t / mp.pi)
        return _line_y(B, b, h)
    t = mp.radians(p["theta1"])
    vE = mp.diff(lambda u: E(u).real, t) * p["omega1"]
    assert s["v_E"].value == pytest.approx(float(vE) / 1000, rel=1e-10)
    assert s["v_I"].value == pytest.approx(float(2 * abs(vE)) / 1000, rel=1e-10)
    assert math.cos(s["direction of v_I"].value) == pytest.approx(float(mp.sign(vE)), abs=1e-12)


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_14_against_hand_closure(seed):
    ex = rm.EXERCISE_2_14
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    P = {k: mp.mpf(v) for k, v in p.items()}

    def xF(t):
        B = P["AB"] * mp.expjpi(t / mp.pi)
        C = _circles(B, P["BC"], mp.mpc(P["AD"]), P["CD"], 1)
        E = B + (C - B) / P["BC"] * P["BE"] * mp.expjpi(P["beta"] / 180)
        return _line_y(E, P["EF"], P["yF"]).real
    _, v, a = _rates(xF, mp.radians(p["theta1"]), p["omega1"])
    assert s["v_F"].value == pytest.approx(float(v) / 1000, rel=1e-9, abs=1e-12)
    assert s["a_F"].value == pytest.approx(float(a) / 1000, rel=1e-8, abs=1e-10)


def test_exercise_2_14_polygons_close():
    sol = rm.linkage_2_14().solve(math.radians(60.0), order=2, omega=10.0)
    motions = [relative_motion(sol, "C", base="B", link="coupler", pivot="D", pivot_link="rocker"),
               relative_motion(sol, "E", base="B", link="coupler"),
               relative_motion(sol, "F", base="E", link="rod")]
    assert velocity_polygon(motions).closure < 1e-9
    assert acceleration_polygon(motions).closure < 1e-7


@pytest.mark.parametrize("seed", range(6))
def test_exercise_2_16_grashof_note_matches_the_lengths(seed):
    """The note said 'a <kind> (AB + CD > AD + BC): the crank cannot turn fully' for every
    variant, though about half of the sampled variants are crank-rockers; the note now
    follows the lengths, checked against the Grashof sums computed here."""
    rng = np.random.default_rng(seed)
    p = rm._sample_2_16(rng)
    text = " ".join(n for part in rm.EXERCISE_2_16.solve(p).parts for n in part.remarks)
    ad = math.hypot(p["xD"], p["yD"])
    links = sorted((p["AB"], p["BC"], p["CD"], ad))
    revolves = links[0] == p["AB"] and links[0] + links[3] <= links[1] + links[2]
    assert ("the crank AB turns fully" in text) == revolves
    assert ("the crank cannot turn fully" in text) == (not revolves)
    assert f"{links[0] + links[3]:.1f} mm against {links[1] + links[2]:.1f} mm" in text


@pytest.mark.parametrize("seed", range(6))
def test_exercise_2_16_counter_clockwise_note_matches_the_lengths(seed):
    """The assumptions said the counter-clockwise reading of φ1 leaves B too near D to close
    the loop; for 198 of 300 sampled variants it closes. The sentence now follows BD."""
    p = rm._sample_2_16(np.random.default_rng(seed))
    text = " ".join(rm.EXERCISE_2_16.solve(p).assumptions)
    bd = abs(complex(p["xD"], p["yD"]) - p["AB"] * np.exp(1j * math.radians(p["phi1"])))
    closes = p["CD"] - p["BC"] <= bd <= p["CD"] + p["BC"]
    assert ("the loop would close too" in text) == closes
    assert ("the loop could not close" in text) == (not closes)
    assert f"{bd:.1f} mm" in text
