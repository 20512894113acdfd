"""Exercises 2-30, 2-31, 2-32: the generated solutions against independent oracles.

2-30: the crank-rocker rebuilt at 50 digits from the construction (alpha found by mpmath
root finding on the chord lengths) and the simulated values against `FourBar.limit_positions`.
2-31: every design checked with `FourBar.limit_positions` (the analysis code's own limit
positions, another route than the simulation inside the solver), and the candidates
counted by a brute-force scan of the other limit position on the rocker's circle.
2-32: the ram's path that minimises the largest pressure angle found by a numerical search
over the path, and the stroke and K measured.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from mech.exercises.chapter2_quick_return import (
    EXERCISE_2_30,
    EXERCISE_2_31,
    EXERCISE_2_32,
    Shaper,
    designs_2_30,
    designs_2_31,
    shaper_2_32,
)
from mech.planar import GuideBar

mpmath.mp.dps = 50


def _mp_design(K, c, swing_deg, given, value, side):
    """(a, b, d) at 50 digits: alpha solved from the chord lengths AC1 = b - a, AC2 = b + a."""
    K, c = mpmath.mpf(K), mpmath.mpf(c)
    swing = mpmath.radians(swing_deg)
    theta = mpmath.pi * (K - 1) / (K + 1)
    R = c * mpmath.sin(swing / 2) / mpmath.sin(theta)
    C1 = mpmath.mpc(-R * mpmath.sin(theta), R * mpmath.cos(theta))
    C2 = mpmath.mpc(R * mpmath.sin(theta), R * mpmath.cos(theta))
    D = mpmath.mpc(0, R * mpmath.cos(theta) - side * c * mpmath.cos(swing / 2))

    def lengths(al):
        A = R * mpmath.expj(mpmath.pi / 2 + theta + al)
        return (abs(C2 - A) - abs(C1 - A)) / 2, (abs(C2 - A) + abs(C1 - A)) / 2, abs(D - A)

    k = 0 if given == "a" else 1
    al = mpmath.findroot(lambda x: lengths(x)[k] - value, (mpmath.mpf("0.001"), mpmath.pi - theta - mpmath.mpf("0.001")),
                         solver="anderson")
    return lengths(al)


@pytest.mark.parametrize("given", ["a", "b"])
def test_2_30_designs_against_mpmath_and_limit_positions(given):
    p = EXERCISE_2_30.defaults
    found = designs_2_30(p, given)
    assert [side for side, _, _ in found] == [1, -1]
    for side, q, check in found:
        ref = _mp_design(p["K"], p["l_CD"], p["psi"], given, p["l_AB"] if given == "a" else p["l_BC"], side)
        a, b, c, d = q.lengths
        assert (a, b, d) == pytest.approx([float(x) for x in ref], rel=1e-12)
        lp = q.fourbar.limit_positions()
        assert float(lp.time_ratio) == pytest.approx(1.25, rel=1e-9)
        assert float(lp.swing) == pytest.approx(math.radians(32.0), rel=1e-9)
        assert check.time_ratio == pytest.approx(float(lp.time_ratio), rel=1e-9)
        gamma_min, _ = q.fourbar.min_transmission_angle()
        assert check.min_transmission_angle == pytest.approx(float(gamma_min), abs=1e-9)


def test_2_30_solution_values():
    s = EXERCISE_2_30.solve()
    assert round(float(s["(1) l_BC, D on the side of A"].value), 3) == 176.014
    assert round(float(s["(1) l_AD, D on the side of A"].value), 3) == 278.717
    assert round(math.degrees(s["(1) gamma_min simulated, D on the side of A"].value), 3) == 43.883
    assert s["(1) gamma_min >= [gamma], D on the side of A"].value is True
    assert s["(1) gamma_min >= [gamma], D across the chord"].value is False
    assert round(float(s["(2) l_AB, D on the side of A"].value), 3) == 79.230
    assert round(float(s["(2) l_AD, D on the side of A"].value), 3) == 288.371
    assert "Solution of exercise 2-30" in s.as_markdown()


def _other_limits_by_scan(p, n=200001):
    """Rocker angles of the other limit position found by scanning the other limit position around the rocker circle."""
    c, d, K = p["l_CD"], p["l_AD"], p["K"]
    theta = math.pi * (K - 1) / (K + 1)
    C = d + c * np.exp(1j * (math.pi - math.radians(p["phi"])))
    psi = np.linspace(-math.pi, math.pi, n)
    C2 = d + c * np.exp(1j * psi)
    seen = np.abs(np.angle(C2 / C))                    # angle C A C2 seen from A
    f = seen - theta
    idx = np.flatnonzero(np.sign(f[:-1]) != np.sign(f[1:]))
    return psi[idx]


def test_2_31_every_design_has_the_given_limit_position_and_K():
    p = EXERCISE_2_31.defaults
    found = designs_2_31(p)
    assert [limit for limit, _, _ in found] == ["extended", "folded"]
    # the other limit position: every point of the rocker circle seen from A at theta from C
    others = _other_limits_by_scan(p)
    assert len(others) == len(found) == 2
    for limit, fb, check in found:
        lp = fb.limit_positions()
        other = float(lp.psi_folded if limit == "extended" else lp.psi_extended)
        assert np.min(np.abs(np.angle(np.exp(1j * (others - other))))) < 1e-4
        assert float(lp.time_ratio) == pytest.approx(1.5, rel=1e-9)
        given = math.pi - math.radians(45.0)
        psi = float(lp.psi_extended if limit == "extended" else lp.psi_folded)
        assert math.remainder(psi - given, 2 * math.pi) == pytest.approx(0.0, abs=1e-9)
        assert check.time_ratio == pytest.approx(1.5, rel=1e-9)
    s = EXERCISE_2_31.solve()
    assert round(float(s["design 1: l_AB"].value), 3) == 26.916
    assert round(float(s["design 2: l_BC"].value), 3) == 98.167


def test_2_32_ram_path_minimises_the_pressure_angle():
    p = EXERCISE_2_32.defaults
    s = shaper_2_32(p)
    K, stroke, worst = s.measure()
    assert K == pytest.approx(2.0, rel=1e-9)
    assert stroke == pytest.approx(300.0, rel=1e-9)
    sagitta = 300.0 * (1 - math.cos(math.radians(30)))
    assert worst == pytest.approx(math.asin(sagitta / 2 / 100.0), abs=1e-6)

    def worst_at(x):
        return Shaper(s.guide_bar, s.l_CD, s.l_DE, x).measure(samples=2048)[2]

    best = minimize_scalar(worst_at, bounds=(s.x_ram - 20, s.x_ram + 20), method="bounded",
                           options={"xatol": 1e-8})
    assert best.x == pytest.approx(s.x_ram, abs=1e-4)
    assert s.guide_bar.d == pytest.approx(150.0) and s.l_CD == pytest.approx(300.0)
    assert isinstance(s.guide_bar, GuideBar)


@pytest.mark.parametrize("exercise", [EXERCISE_2_30, EXERCISE_2_31, EXERCISE_2_32])
def test_variants_solve_and_simulate(exercise):
    for seed in range(8):
        params = exercise.variant(seed)
        assert params == exercise.variant(seed)
        solution = exercise.solve(params)
        for r in solution.results():
            if "K simulated" in r.name:
                assert r.value == pytest.approx(params["K"], rel=1e-9)
        assert solution.as_markdown().startswith("**Solution of exercise")


def test_bad_givens_raise_value_error():
    with pytest.raises(ValueError, match="l_CD"):
        EXERCISE_2_30.solve(l_CD=-1.0)
    with pytest.raises(ValueError, match="l_DE"):
        EXERCISE_2_32.solve(l_DE=5.0)
    with pytest.raises(ValueError):
        EXERCISE_2_31.solve(l_AD=1000.0)


@pytest.mark.parametrize("l_DE", [1e10, 1e154, 1e300])
def test_shaper_2_32_any_link_DE(l_DE):
    """y_E = D_y + sqrt(l_DE^2 - dx^2) lost the ram's motion for a long DE (ZeroDivisionError at
    1e154, OverflowError at 1e300). The stroke and K do not depend on l_DE, and the largest
    pressure angle is asin(half the sagitta / l_DE)."""
    s = shaper_2_32({**EXERCISE_2_32.defaults, "l_DE": l_DE})
    K, stroke, worst = s.measure()
    assert math.isclose(K, 2.0, rel_tol=1e-9) and math.isclose(stroke, 300.0, rel_tol=1e-9)
    sagitta = s.l_CD * (1 - math.cos(math.pi / 3 / 2))
    assert math.isclose(worst, math.asin(sagitta / 2 / l_DE), rel_tol=1e-6)


@pytest.mark.parametrize("changes", [{"l_CD": 1e300}, {"l_AD": 1e300}, {"l_CD": 1e-300}])
def test_designs_2_31_extreme_givens_have_no_design(changes):
    """A square of 1e300 raised OverflowError; equal diagonals gave "Expected `a` > 0"."""
    assert designs_2_31({**EXERCISE_2_31.defaults, **changes}) == []
