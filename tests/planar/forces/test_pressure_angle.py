"""Tests for ``mech.planar.forces._pressure_angle`` (F49 to F59, eq. 2-30).

References are independent of the code path: the angle between solved vectors with
``mpmath.acos`` at 50 digits, dense brute-force sweeps for the extremes, and the independently recomputed
check case gamma_min = 44.4153 degrees for (a, b, c, d) = (30, 70, 60, 80).
"""

import math

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, Linkage, SliderCrank, quick_return_guide_bar, watt_six_bar
from mech.planar.forces._pressure_angle import (
    design_check,
    fourbar_pressure_angle,
    guide_bar_pressure_angle,
    joint_transmission_angle,
    pressure_angle,
    slider_crank_min_transmission_angle,
    slider_crank_pressure_angle,
    transmission_extremes,
    watt_transmission_angles,
)

THETA = np.linspace(-np.pi, np.pi, 73)


def _acute_mp(u, v):
    """Acute angle between two plane vectors by acos of the normalised dot, 50 digits."""
    with mpmath.workdps(50):
        ux, uy, vx, vy = (mpmath.mpf(float(x)) for x in (u.real, u.imag, v.real, v.imag))
        c = abs(ux * vx + uy * vy) / (mpmath.sqrt(ux**2 + uy**2) * mpmath.sqrt(vx**2 + vy**2))
        return float(mpmath.acos(min(c, mpmath.mpf(1))))


def _fourbar_linkage(a, b, c, d, branch=1):
    return (Linkage({"A": 0, "D": d}).crank("crank", pivot="A", tip="B", length=a)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c), branch=branch))


@pytest.mark.parametrize("branch", [1, -1])
def test_pressure_angle_fourbar_matches_vectors_and_closed_form(branch):
    sol = _fourbar_linkage(30, 70, 60, 80, branch).solve(THETA, order=1)
    alpha = pressure_angle(sol, "C", "B")
    ref = [_acute_mp(sol.points["C"][i] - sol.points["B"][i], sol.velocities["C"][i]) for i in range(THETA.size)]
    np.testing.assert_allclose(alpha, ref, atol=1e-12)
    np.testing.assert_allclose(alpha, fourbar_pressure_angle(30, 70, 60, 80, THETA), atol=1e-12)
    gamma = FourBar(30, 70, 60, 80, branch=branch).transmission_angle(THETA)
    np.testing.assert_allclose(alpha + gamma, np.pi / 2, atol=1e-12)
    np.testing.assert_allclose(joint_transmission_angle(sol, "C", "B", pivot="D"), gamma, atol=1e-12)
    np.testing.assert_allclose(joint_transmission_angle(sol, "C", "B"), gamma, atol=1e-12)


def test_transmission_extremes_catalog_check():
    x = transmission_extremes(30, 70, 60, 80)
    sweep = np.radians(np.arange(0.0, 360.0, 0.001))
    brute = np.degrees(np.nanmin(FourBar(30, 70, 60, 80).transmission_angle(sweep)))
    assert round(math.degrees(x.gamma_min), 4) == 44.4153
    assert abs(math.degrees(x.gamma_min) - brute) < 1e-6
    assert round(math.degrees(x.delta_max), 3) == 115.377
    assert x.theta_at == 0.0


def test_transmission_extremes_minimum_at_pi():
    # delta_max obtuse and pi - delta_max < delta_min: the minimum is at theta = pi
    a, b, c, d = 20, 50, 50, 70
    x = transmission_extremes(a, b, c, d)
    sweep = np.radians(np.arange(0.0, 360.0, 0.001))
    gam = FourBar(a, b, c, d).transmission_angle(sweep)
    assert x.theta_at == pytest.approx(np.pi)
    assert abs(x.gamma_min - np.nanmin(gam)) < 1e-9
    assert abs(sweep[np.nanargmin(gam)] - np.pi) < 1e-4


def test_transmission_extremes_rejects_rocking_crank():
    with pytest.raises(ValueError, match="crank that turns fully"):
        transmission_extremes(40, 20, 30, 35)


@pytest.mark.parametrize("e", [0.0, 20.0, -15.0])
def test_slider_crank_pressure_angle_matches_vectors(e):
    theta = THETA
    pose = SliderCrank(30, 100, e).solve(theta)
    got = slider_crank_pressure_angle(30, 100, e, theta)
    ref = [_acute_mp(pose.C[i] - pose.B[i], 1 + 0j) for i in range(theta.size)]
    np.testing.assert_allclose(got, ref, atol=1e-12)
    np.testing.assert_allclose(got + SliderCrank(30, 100, e).transmission_angle(theta), np.pi / 2, atol=1e-12)


@pytest.mark.parametrize("e", [0.0, 20.0, -20.0, 45.0])
def test_slider_crank_min_transmission_angle_brute_force(e):
    g, th = slider_crank_min_transmission_angle(30, 100, e)
    sweep = np.radians(np.arange(-180.0, 180.0, 0.001))
    gam = np.pi / 2 - slider_crank_pressure_angle(30, 100, e, sweep)
    assert abs(g - gam.min()) < 1e-9
    with mpmath.workdps(50):
        assert abs(g - float(mpmath.acos(mpmath.mpf(30 + abs(e)) / 100))) < 1e-13      # F57
    if e != 0.0:
        assert abs(sweep[np.argmin(gam)] - th) < 1e-4
        assert th == (-np.pi / 2 if e > 0 else np.pi / 2)


def test_slider_crank_min_transmission_angle_offset_too_large():
    with pytest.raises(ValueError, match=r"Expected `a` \+ \|`e`\| <= `b` = 100.0.*got a \+ \|e\| = 110.0"):
        slider_crank_min_transmission_angle(30, 100, -80)


def test_guide_bar_pressure_angle_zero_on_the_textbook_guide_bar():
    lk = quick_return_guide_bar()
    sol = lk.solve(np.linspace(0, 2 * np.pi, 91), order=1)
    normal = 1j * sol.direction("bar")
    alpha = pressure_angle(sol, "B", normal, follower="bar")
    assert np.max(np.abs(alpha)) < 1e-12
    assert np.all(guide_bar_pressure_angle(np.linspace(-5, 5, 11)) == 0.0)


def test_guide_bar_pressure_angle_offset_guide():
    e = 12.0
    lk = (Linkage({"A": 0, "D": -60j}).crank("crank", pivot="A", tip="B", length=30)
          .rpr(("bar", "block"), pins=("D", "B"), offset=e, branch=1))
    sol = lk.solve(np.linspace(0, 2 * np.pi, 37), order=1)
    t = sol.direction("bar")
    rel = sol.points["B"] - sol.points["D"]
    s = np.real(np.conj(t) * rel)
    alpha = pressure_angle(sol, "B", 1j * t, follower="bar")
    ref = [_acute_mp(1j * t[i], 1j * sol.omegas["bar"][i] * rel[i]) for i in range(t.size)]
    np.testing.assert_allclose(alpha, ref, atol=1e-12)
    np.testing.assert_allclose(alpha, guide_bar_pressure_angle(s, e), atol=1e-12)


def test_watt_transmission_angles_two_loops():
    theta = np.linspace(0, 2 * np.pi, 721)
    sol = watt_six_bar().solve(theta, order=1)
    g1, g2 = watt_transmission_angles(sol)
    np.testing.assert_allclose(g1, FourBar(20, 50, 45, 50).transmission_angle(theta), atol=1e-12)
    np.testing.assert_allclose(g2, np.pi / 2 - pressure_angle(sol, "G", "E"), atol=1e-10)
    assert math.degrees(g1.min()) == pytest.approx(36.336, abs=1e-3)
    assert g2.min() > math.radians(60.0)


def test_pressure_angle_bad_inputs():
    sol = _fourbar_linkage(30, 70, 60, 80).solve(0.0)
    with pytest.raises(ValueError, match="order >= 1"):
        pressure_angle(sol, "C", "B")
    sol1 = _fourbar_linkage(30, 70, 60, 80).solve(0.0, order=1)
    with pytest.raises(ValueError, match="point name or a direction"):
        pressure_angle(sol1, "C", "Z")
    with pytest.raises(ValueError, match="moving link"):
        pressure_angle(sol1, "C", "B", follower="nothing")
    with pytest.raises(ValueError, match="Expected `a` > 0, got -30.0"):
        fourbar_pressure_angle(-30, 70, 60, 80, 0.0)
    with pytest.raises(ValueError, match="Expected `b` > 0, got -1.0"):
        slider_crank_pressure_angle(30, -1, 0, 0.0)


def test_design_check_limits():
    assert design_check(math.radians(40.0)) and not design_check(math.radians(39.9))
    assert design_check(math.radians(50.0), high_speed=True)
    assert not design_check(math.radians(49.9), high_speed=True)
