"""Tests of exercises 2-8, 2-9 and 2-11 (instant centres on assumed layouts).

The expected centres are constructed by hand in mpmath at 50 digits: the joint positions
by circle intersections, each derived centre as the meeting point of the two lines that
the three-centre theorem names for it, written out explicitly for each mechanism. The
velocity ratios are checked against the pitch radii (2-9) and against the derivative of
the hand-solved output angle (2-11).
"""

import math
import re
import subprocess
import sys

import mpmath as mp
import pytest

from mech.exercises import chapter2_instant_centres as ic

mp.mp.dps = 50
SEEDS = [0, 1, 7]


def _meet(p1, p2, q1, q2):
    """Meeting point of line p1 p2 and line q1 q2 (mpmath complex)."""
    d1, d2 = p2 - p1, q2 - q1
    cross = lambda a, b: a.real * b.imag - a.imag * b.real
    t = cross(q1 - p1, d2) / cross(d1, d2)
    return p1 + t * d1


def _xy(text):
    x, y = re.match(r"\((-?[\d.]+), (-?[\d.]+)\) mm", text).groups()
    return complex(float(x), float(y))


def _circles(p, rp, q, rq, side):
    d = q - p
    L = abs(d)
    a = (rp * rp - rq * rq + L * L) / (2 * L)
    return p + d / L * mp.mpc(a, side * mp.sqrt(rp * rp - a * a))


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_8_centres_by_hand(seed):
    ex = ic.EXERCISE_2_8
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    a, b, c, d, e = (mp.mpf(p[k]) for k in "abcde")
    A, D = mp.mpc(0), mp.mpc(d)
    B = a * mp.expjpi(mp.radians(p["theta"]) / mp.pi)
    # (a) four-bar: P13 = AD x BC, P24 = AB x DC
    C = _circles(B, b, D, c, 1)
    got = {r.name: r.value for r in s.parts[0].results}
    assert abs(_xy(got["P13"]) - complex(_meet(A, D, B, C))) < 1e-4
    assert abs(_xy(got["P24"]) - complex(_meet(A, B, D, C))) < 1e-4
    # (b) slider-crank: C on y = e; P13 = BC x (vertical through A), P24 = AB x (vertical through C)
    C = mp.mpc(B.real + mp.sqrt(b * b - (e - B.imag) ** 2), e)
    got = {r.name: r.value for r in s.parts[1].results}
    assert abs(_xy(got["P13"]) - complex(_meet(B, C, A, A + 1j))) < 1e-4
    assert abs(_xy(got["P24"]) - complex(_meet(A, B, C, C + 1j))) < 1e-4
    assert got["P34"].startswith("at infinity in the direction 90.0000°")
    # (c) guide-bar: guide along DB; P13 = AD x (normal to DB through B), P24 = AB x (normal to DB through D)
    n = (B - D) * 1j
    got = {r.name: r.value for r in s.parts[2].results}
    assert abs(_xy(got["P13"]) - complex(_meet(A, D, B, B + n))) < 1e-4
    assert abs(_xy(got["P24"]) - complex(_meet(A, B, D, D + n))) < 1e-4


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_9_ratio_and_p13(seed):
    ex = ic.EXERCISE_2_9
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    r1, r2, r3 = (mp.mpf(p[k]) for k in ("r1", "r2", "r3"))
    u = mp.expjpi(mp.radians(p["beta"]) / mp.pi)
    A, C = mp.mpc(r1 + r2), (r2 + r3) * u
    P13 = _meet(mp.mpc(r2), r2 * u, A, C)
    assert abs(_xy(s["P13"].value) - complex(P13)) < 1e-4
    # rolling without slip: w2 = -w1 r1/r2, w3 = -w2 r2/r3
    w1 = mp.mpf(1)
    w3 = (w1 * r1 / r2) * r2 / r3
    assert s["ω1/ω3"].value == pytest.approx(float(w1 / w3), rel=1e-12)
    assert s["ω1/ω3"].value == pytest.approx(float((P13 - C).real / (P13 - A).real), rel=1e-10)


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_11_ratio_by_differentiation(seed):
    ex = ic.EXERCISE_2_11
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    a, b, c, d = (mp.mpf(p[k]) for k in "abcd")

    def psi(t):
        B = a * mp.expjpi(t / mp.pi)
        C = _circles(B, b, mp.mpc(d), c, 1)
        return mp.atan2(C.imag, C.real - d)
    ratio = mp.diff(psi, mp.radians(p["theta"]))
    assert s["ω4/ω2"].value == pytest.approx(float(ratio), rel=1e-10)


@pytest.mark.parametrize("number", ["2-8", "2-9", "2-11"])
def test_cli_show_and_variant(number):
    for args in (["show", number], ["variant", number, "--seed", "7"]):
        out = subprocess.run([sys.executable, "-m", "mech.exercises", *args], capture_output=True, text=True,
                             check=True).stdout
        assert f"Solution of exercise {number}" in out and "Assumed layout" in out
