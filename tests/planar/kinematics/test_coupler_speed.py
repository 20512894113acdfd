"""`FourBar.coupler_point_speed` (derivation page deriv-coupler-speed) against oracles that do
not use its formula: the position assembled in mpmath at 50 digits and differentiated by a
central difference, a parallelogram whose coupler translates, and the dashes of an atlas page."""

import math

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, coupler_dashes


def _point(t, a, b, c, d, coupler, branch):
    """The coupler point at crank angle t (mpmath): C on the circles about B and D, on the
    left of B->D for branch +1."""
    B = a * mpmath.expj(t)
    k = abs(d - B)
    along = (b**2 - c**2 + k**2) / (2 * k)
    C = B + (d - B) / k * (along + 1j * branch * mpmath.sqrt(b**2 - along**2))
    return B + (coupler[0] + 1j * coupler[1]) * (C - B) / b


def _speed_oracle(t, omega, a, b, c, d, coupler, branch):
    """|omega| |dP/dtheta| by a central difference of step 1e-20 at 50 digits (error ~1e-40)."""
    with mpmath.workdps(50):
        h = mpmath.mpf(10) ** -20
        t = mpmath.mpf(t)
        slope = abs(_point(t + h, a, b, c, d, coupler, branch) - _point(t - h, a, b, c, d, coupler, branch)) / (2 * h)
        return float(abs(mpmath.mpf(omega)) * slope)


@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("lengths, coupler", [((10, 40, 30, 35), (20, 10)),       # example 2-1, a crank-rocker
                                              ((1, 2, 2.5, 3), (3.0, -1.0)),       # the atlas page of Fig. 2-30
                                              ((30, 70, 60, 80), (-15, 25))])
def test_matches_the_derivative_of_the_position(lengths, coupler, branch):
    linkage = FourBar(*lengths, coupler=coupler, branch=branch)
    theta = np.array([-2.9, -1.0, 0.1, 0.7, 1.9, 3.0])
    got = linkage.coupler_point_speed(theta, omega=-2.5)
    want = [_speed_oracle(t, -2.5, *lengths, coupler, branch) for t in theta]
    np.testing.assert_allclose(got, want, rtol=1e-12)


def test_a_parallelogram_coupler_translates():
    """Every point of a parallelogram's coupler moves like B: speed a |omega|, also at the
    change points theta = 0 and pi where all four joints are in line."""
    theta = np.linspace(-np.pi, np.pi, 13)
    speed = FourBar(10, 30, 10, 30, coupler=(12, -7)).coupler_point_speed(theta, omega=3.0)
    np.testing.assert_allclose(speed, 30.0, rtol=1e-13)


def test_shapes_rates_and_unassembled_poses():
    linkage = FourBar(10, 40, 10, 25, coupler=(5, 5))           # cannot assemble near theta = 0
    theta = np.array([[0.0], [2.0], [3.0]])
    speed = linkage.coupler_point_speed(theta, omega=[1.0, -4.0])
    assert speed.shape == (3, 2)
    assert np.isnan(speed[0]).all() and np.isfinite(speed[1:]).all()
    np.testing.assert_allclose(speed[1:, 1], 4.0 * speed[1:, 0], rtol=1e-15)
    assert isinstance(linkage.coupler_point_speed(2.0), float)


@pytest.mark.parametrize("exponent", [-1000, -60, 50, 990])
def test_speed_scales_exactly_with_the_lengths(exponent):
    scale = 2.0**exponent
    lengths, coupler = np.array([10.0, 40.0, 30.0, 35.0]) / 64, (20.0 / 64, 10.0 / 64)
    theta = np.linspace(-3.0, 3.0, 7)
    unit = FourBar(*lengths, coupler=coupler).coupler_point_speed(theta, omega=0.5)
    scaled = FourBar(*(lengths * scale), coupler=tuple(v * scale for v in coupler)).coupler_point_speed(theta, omega=0.5)
    assert np.array_equal(scaled, unit * scale)


def test_no_overflow_where_the_speed_is_a_float():
    """Links near 1e300 at a rate 1e-300, and a rate of 1e300 with links near 1: every
    intermediate stays in range, only the speed scales."""
    linkage = FourBar(1e300, 4e300, 3e300, 3.5e300, coupler=(2e300, 1e300))
    want = FourBar(1, 4, 3, 3.5, coupler=(2, 1)).coupler_point_speed(0.5, omega=2.0)
    assert math.isclose(linkage.coupler_point_speed(0.5, omega=2e-300), want, rel_tol=1e-14)
    fast = FourBar(1, 4, 3, 3.5, coupler=(2, 1)).coupler_point_speed(0.5, omega=1e300)
    assert math.isclose(fast, want * 0.5e300, rel_tol=1e-14)


def test_an_atlas_dash_is_the_speed_times_its_crank_step():
    """F25: with 3600 dashes a dash's length divided by its crank step is the speed at its
    middle up to the step squared (a chord of a smooth curve)."""
    a, b, c, d, w = 1.0, 2.0, 2.5, 3.0, 2.0 + 1.0j
    page = coupler_dashes(a, b, c, d, w, n=3600)
    step = page.theta[1] - page.theta[0]
    middle = page.theta[:-1] + step / 2                 # n + 1 dash ends, n dashes
    speed = FourBar(a, b, c, d, coupler=(w.real, w.imag)).coupler_point_speed(middle)
    np.testing.assert_allclose(page.length / step, speed, rtol=1e-5)


@pytest.mark.parametrize("name, value", [("theta", math.nan), ("omega", 1 + 2j), ("omega", "2")])
def test_bad_input_named(name, value):
    linkage = FourBar(10, 40, 30, 35)
    with pytest.raises((ValueError, TypeError), match=f"`{name}`"):
        linkage.coupler_point_speed(**{"theta": 0.5, "omega": 1.0, name: value})
