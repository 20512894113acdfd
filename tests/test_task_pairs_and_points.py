"""The task layer for function generation and spherical path synthesis (issue 24, item 2).

Function-generation pairs (planar and spherical, precision pairs and least-squares fits)
that repeat a pair a whole turn later, give one input direction two outputs, or (met
exactly) give three pairs one output direction are no task; nor are spherical precision
points whose input angles repeat, turn back or span a whole turn, or that are all one point.
Each is refused by a ValueError naming the arguments and the offending entries (counted
from 1). Before the task layer these inputs were solved (a design returned for fewer pairs
than given, or a fit to contradictory data) or refused without naming the entries.
"""

import numpy as np
import pytest

from mech.planar.synthesis import least_squares, precision_pairs
from mech.spherical import SphericalFourBar, path_fourbar, path_stephenson1
from mech.spherical._function_generation import least_squares as sph_least_squares
from mech.spherical._function_generation import precision_pairs as sph_precision_pairs

X3 = np.radians([0.0, 30.0, 60.0])
Y3 = np.radians([0.0, 20.0, 35.0])
X6 = np.radians([10.0, 25.0, 40.0, 55.0, 70.0, 85.0])
Y6 = 0.5 * np.sin(X6)

EXACT = {
    "planar precision_pairs": lambda x, y: precision_pairs(x, y, theta0=np.radians(60.0), psi0=np.radians(30.0),
                                                           d=100.0),
    "spherical precision_pairs": lambda x, y: sph_precision_pairs(x, y, theta0=np.radians(40.0),
                                                                  psi0=np.radians(80.0)),
}
FITS = {
    "planar least_squares": lambda x, y: least_squares(x, y, theta0=np.radians(60.0), psi0=np.radians(30.0), d=100.0),
    "spherical least_squares": lambda x, y: sph_least_squares(x, y, np.radians(40.0), np.radians(80.0)),
}


def _pairs(n):
    return (X3, Y3) if n == 3 else (X6, Y6)


@pytest.mark.parametrize("name", list(EXACT) + list(FITS))
@pytest.mark.parametrize("turns", [1, -1, 3])
def test_a_pair_repeated_whole_turns_later_is_refused(name, turns):
    call = {**EXACT, **FITS}[name]
    x, y = _pairs(3 if name in EXACT else 6)
    x, y = x.copy(), y.copy()
    x[-1], y[-1] = x[0] + 2 * np.pi * turns, y[0] + 2 * np.pi * (turns - 1)
    with pytest.raises(ValueError, match=rf"`x`/`y`, got pairs 1 and {x.size} the same pair"):
        call(x, y)


@pytest.mark.parametrize("name", list(EXACT) + list(FITS))
def test_one_input_direction_with_two_outputs_is_refused(name):
    call = {**EXACT, **FITS}[name]
    x, y = _pairs(3 if name in EXACT else 6)
    x, y = x.copy(), y.copy()
    x[1], y[1] = x[0] + 2 * np.pi, y[0] + 0.3
    with pytest.raises(ValueError, match=r"`y` for one input direction in `x`, got pairs 1 and 2"):
        call(x, y)


@pytest.mark.parametrize("name", list(EXACT))
def test_three_pairs_with_one_output_direction_are_refused(name):
    # at one output angle Freudenstein's equation is A cos(theta) + B sin(theta) = C: two
    # inputs of a turn at most meet it
    y = np.array([0.1, 0.1 + 2 * np.pi, 0.1])
    with pytest.raises(ValueError, match=r"got pairs 1, 2 and 3 of `x`/`y` with one output direction"):
        EXACT[name](X3, y)


@pytest.mark.parametrize("name", list(FITS))
def test_a_fit_to_an_output_that_does_not_move_is_refused(name):
    with pytest.raises(ValueError, match=r"got pairs 1, 2, 3, 4, 5 and 6 of `x`/`y` with one output direction"):
        FITS[name](X6, np.full(6, 0.4))


@pytest.mark.parametrize("name", list(FITS))
def test_a_fit_with_two_equal_outputs_is_still_a_task(name):
    y = Y6.copy()
    y[3] = y[1]                                   # a rocker's output returns: two inputs, one output
    try:
        FITS[name](X6, y)
    except ValueError as exc:                     # no good fit may exist, but the task stands
        assert "output direction" not in str(exc) and "same pair" not in str(exc)


# ------------------------------------------------------------------ spherical path precision points
X1 = np.array([0.4, 1.0, 0.6, 0.45, 1.05, 0.85, 1.15, 0.55, 0.7])


def _points(theta):
    return SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.3, 0.4)).solve(theta).P


@pytest.mark.parametrize("design", [lambda P, th: path_fourbar(P, th, X1),
                                    lambda P, th: path_stephenson1(P, th, np.r_[X1, X1[3:9]])])
@pytest.mark.parametrize("theta, message", [
    ([0.0, 1.0, 1.0, 2.0], r"`theta` strictly monotonic within one turn, got entries 2 and 3 that repeat"),
    ([0.0, 1.0, 0.5, 2.0], r"got entries 2 and 3 that turn back"),
    ([0.0, 2.0, 4.0, 6.4], r"got entries 1 and 4 a whole turn or more apart"),
])
def test_precision_point_timing_refused_naming_entries(design, theta, message):
    theta = np.array(theta)
    with pytest.raises(ValueError, match=message):
        design(_points(np.linspace(0.0, 2.0, 4)), theta)


def test_precision_points_all_one_point_refused():
    P = np.tile([0.0, 0.6, 0.8], (5, 1))
    with pytest.raises(ValueError, match=r"`points` that are not all one point, got 5 points"):
        path_fourbar(P, np.linspace(0.0, 2.0, 5), X1)


def test_a_coupler_curve_may_pass_one_point_twice():
    # a double point of the curve: one point at two input angles is a task (refused only
    # when every point is one)
    P = _points(np.linspace(0.0, 2.0, 5))
    P[3] = P[1]
    path_fourbar(P, np.linspace(0.0, 2.0, 5), X1)
