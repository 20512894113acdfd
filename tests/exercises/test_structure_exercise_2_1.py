"""Tests of exercise 2-1 (skeletons, degrees of freedom and types of three assumed mechanisms).

The four-bar's type is found by sampling each joint through a full turn (the loop must close
at every sampled angle), independently of the Grashof inequality; the slider-crank's stroke
and time ratio come from a dense crank sweep of the law-of-cosines position in mpmath at 30
digits; the guide-bar's swing from sin(swing / 2) = crank / frame in mpmath.
"""

import subprocess
import sys

import mpmath as mp
import numpy as np
import pytest

from mech.exercises import chapter2

mp.mp.dps = 30


def _turns(x, y, u, v, n=4001):
    t = np.linspace(0.0, 2.0 * np.pi, n)
    diag = np.sqrt(x * x + y * y - 2.0 * x * y * np.cos(t))
    return bool(np.all((diag >= abs(u - v) - 1e-12) & (diag <= u + v + 1e-12)))


@pytest.mark.parametrize("seed", [None, 0, 1, 7])
def test_exercise_2_1_against_sweeps(seed):
    ex = chapter2.EXERCISE_2_1
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    a, b, c, d = (p[k] for k in "abcd")
    a_turns, d_turns = _turns(a, d, b, c), _turns(c, d, a, b)
    kind = {(True, True): "double-crank", (True, False): "crank-rocker", (False, True): "rocker-crank"}.get(
        (a_turns, d_turns))
    if kind is not None:
        assert s["(a) type"].value == kind
    else:
        assert s["(a) type"].value in ("double-rocker", "triple-rocker")
    for part in "abc":
        assert s[f"({part}) degrees of freedom F"].value == 1
    # slider-crank: stroke and time ratio from a sweep, refined with mpmath's findroot
    r, l, e = (mp.mpf(p[k]) for k in ("r", "l", "e"))
    x = lambda t: r * mp.cos(t) + mp.sqrt(l * l - (r * mp.sin(t) - e) ** 2)
    grid = [2 * mp.pi * k / 720 for k in range(720)]
    lo = min(grid, key=x)
    hi = max(grid, key=x)
    t_lo = mp.findroot(lambda t: mp.diff(x, t), lo)
    t_hi = mp.findroot(lambda t: mp.diff(x, t), hi)
    assert s["(b) stroke H"].value == pytest.approx(float(x(t_hi) - x(t_lo)), rel=1e-12)
    theta = abs(((t_lo - t_hi) % (2 * mp.pi)) - mp.pi)
    assert s["(b) time ratio K"].value == pytest.approx(float((mp.pi + theta) / (mp.pi - theta)), rel=1e-10)
    if p["g"] < p["h"]:
        swing = 2 * mp.asin(mp.mpf(p["g"]) / p["h"])
        assert s["(c) swing of the guide bar"].value == pytest.approx(float(swing), rel=1e-13)
        assert s["(c) time ratio K"].value == pytest.approx(float((mp.pi + swing) / (mp.pi - swing)), rel=1e-12)
    else:
        assert s["(c) type"].value.startswith("rotating guide-bar")


def test_exercise_2_1_cli():
    for args in (["show", "2-1"], ["variant", "2-1", "--seed", "7"]):
        out = subprocess.run([sys.executable, "-m", "mech.exercises", *args], capture_output=True, text=True,
                             check=True).stdout
        assert "Solution of exercise 2-1" in out and "Assumed layout" in out
