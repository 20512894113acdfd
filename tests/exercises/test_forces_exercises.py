"""Exercises 2-19, 2-20, 2-21, 2-23 and 2-24 (friction and efficiency) checked by other
routes: free-body equations solved numerically, bisection on a force balance, mpmath
quadrature of the pressure integrals, and the screw jack worked at 50 digits."""

import math

import mpmath
import numpy as np
import pytest

from mech.exercises import chapter2_forces as cf

SEEDS = [0, 1, 2, 7, 11]


@pytest.mark.parametrize("exercise", cf.EXERCISES, ids=lambda e: e.number)
@pytest.mark.parametrize("seed", SEEDS)
def test_forces_exercise_variants_solve_and_render(exercise, seed):
    params = exercise.variant(seed)
    text = exercise.solve(params).as_markdown()
    assert f"exercise {exercise.number}" in text and "nan" not in text.lower()


def test_example_exercise_2_19_free_bodies():
    theta, phi, Q = math.radians(15), math.radians(12), 1000.0
    mu = math.tan(phi)
    # block A (moves +x): face reaction from C, normal (cos t, -sin t), friction against A's
    # upward sliding along the face; frame reaction N up with friction -mu N. Unknowns Nf, N.
    n = np.array([math.cos(theta), -math.sin(theta)])
    slide = np.array([math.sin(theta), math.cos(theta)])          # A relative to C
    face = n - mu * slide
    A = np.array([[face[0], -mu], [face[1], 1.0]])
    Nf, _ = np.linalg.solve(A, [Q, 0.0])
    P = 2 * Nf * (-face[1])                                        # the wedge: both faces, vertical
    got = cf.EXERCISE_2_19.solve()
    assert got["P"].value == pytest.approx(P, rel=1e-12)
    assert got["P without friction"].value == pytest.approx(2 * Q * math.tan(theta), rel=1e-14)
    assert got["P"].value == pytest.approx(1142.82, abs=0.01)


def test_example_exercise_2_20_bisection_on_gripping():
    D, a, mu = mpmath.mpf(1200), mpmath.mpf(25), mpmath.mpf("0.3")
    with mpmath.workdps(50):
        def net_inward(h):                                         # mu N cos(alpha) - N sin(alpha), N = 1
            alpha = mpmath.acos(1 - (h - a) / D)
            return mu * mpmath.cos(alpha) - mpmath.sin(alpha)
        h = mpmath.findroot(net_inward, (a + 1, a + 200), solver="bisect")
    assert cf.EXERCISE_2_20.solve()["largest thickness h_max"].value == pytest.approx(float(h), rel=1e-13)


def test_example_exercise_2_21_rod_equilibrium():
    mu, e, L, w = 0.2, 100.0, 80.0, 12.0
    A = np.array([[0, 1, -1], [1, mu, mu], [0, L - mu * w / 2, mu * w / 2]])
    G = np.linalg.solve(A, [0, 1.0, e])[0]                           # resistance moved by P = 1
    s = cf.EXERCISE_2_21.solve()
    assert s["efficiency with L = 2 L_min = 80 mm"].value == pytest.approx(G, rel=1e-12)
    assert s["shortest guide L_min = 2μe"].value == pytest.approx(40.0, rel=1e-15)
    A_min = np.array([[0, 1, -1], [1, mu, mu], [0, 40.0 - mu * w / 2, mu * w / 2]])
    assert abs(np.linalg.solve(A_min, [0, 1.0, e])[0]) < 1e-12     # at L_min nothing is moved


def test_example_exercise_2_23_quadrature():
    s = cf.EXERCISE_2_23.solve()
    with mpmath.workdps(30):
        mu, alpha = mpmath.mpf("0.3"), mpmath.radians(10)
        def moment(r, R, sin_a):                                    # p s = 1 (run in), per unit load
            load = mpmath.quad(lambda x: 1 / x * 2 * mpmath.pi * x, [r, R])
            m = mpmath.quad(lambda x: mu / x * x * 2 * mpmath.pi * x / sin_a, [r, R])
            return m / load
        flat = moment(50, 100, 1)
        cone = moment(85, 100, mpmath.sin(alpha))
    assert s["flat brake: M/Q"].value == pytest.approx(float(flat), rel=1e-13)
    assert s["cone brake: M/Q"].value == pytest.approx(float(cone), rel=1e-13)


def test_example_exercise_2_24_at_50_digits():
    s = cf.EXERCISE_2_24.solve()
    with mpmath.workdps(50):
        lam, phi = mpmath.atan(4 / (mpmath.pi * 22)), mpmath.atan(mpmath.mpf("0.1"))
        thread = 11 * mpmath.tan(lam + phi)
        M = thread + mpmath.mpf("0.1") * 23                          # run-in collar, r_c = (25 + 21)/2
        eta = 4 / (2 * mpmath.pi * M)                                # virtual work per turn
        Q = 100 * 300 / M
    assert s["efficiency (run-in collar)"].value == pytest.approx(float(eta), rel=1e-13)
    assert s["Q (run-in collar)"].value == pytest.approx(float(Q), rel=1e-13)
    assert s["efficiency of the thread alone"].value == pytest.approx(float(mpmath.tan(lam) / mpmath.tan(lam + phi)), rel=1e-13)
    assert s["self-locking"].value is True


def test_forces_exercise_bad_input():
    with pytest.raises(ValueError, match=r"Expected `d0` < `D`"):
        cf.EXERCISE_2_24.solve(d0=60.0)
    with pytest.raises(ValueError, match=r"θ \+ 2φ < 90°"):
        cf.EXERCISE_2_19.solve(theta=70.0)
