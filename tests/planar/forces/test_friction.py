"""Friction in lower pairs (mech.planar.forces._friction) against independent routes: component
force balances solved numerically, pressure integrals by mpmath quadrature, tangent-line
geometry, and brute-force force balances of the rolling mill."""

import math

import mpmath
import numpy as np
import pytest

from mech.planar.forces._friction import (
    FRICTION_TABLE_2_2,
    collar_friction_radius,
    curved_contact_mu,
    friction_angle,
    friction_circle,
    incline_forces,
    journal_mu,
    journal_state,
    rolling_mill_max_thickness,
    slider_state,
    thrust_friction_moment,
    total_reaction,
    two_force_tilt_angle,
    vgroove_mu,
)

RNG = np.random.default_rng(6001)


def test_friction_angle_value():
    assert friction_angle(0.1) == pytest.approx(float(mpmath.atan(mpmath.mpf("0.1"))), rel=1e-15)


def test_friction_angle_negative_mu_raises():
    with pytest.raises(ValueError, match=r"Expected `mu` >= 0, got -0.1"):
        friction_angle(-0.1)


def test_total_reaction_resists_motion_at_90_plus_phi():
    normals = np.exp(1j * RNG.uniform(-np.pi, np.pi, 50))
    v = np.exp(1j * RNG.uniform(-np.pi, np.pi, 50)) * RNG.uniform(0.1, 3, 50)
    mu = RNG.uniform(0.0, 0.8, 50)
    d = total_reaction(normals, v, mu)
    tangent_v = v - np.real(v * np.conj(normals)) * normals          # tangential part of v
    angle = np.abs(np.angle(d * np.conj(tangent_v)))
    np.testing.assert_allclose(angle, np.pi / 2 + np.arctan(mu), atol=1e-12)
    np.testing.assert_allclose(np.abs(d), 1.0, atol=1e-14)


def test_total_reaction_force_magnitude_is_n_over_cos_phi():
    R = total_reaction(np.exp(0.3j), 2.0 * np.exp(0.3j - 0.5j * np.pi), 0.25, normal_force=40.0)
    assert abs(R) == pytest.approx(40.0 / math.cos(math.atan(0.25)), rel=1e-14)
    # its normal part is N and its tangential part opposes the sliding
    assert np.real(R * np.conj(np.exp(0.3j))) == pytest.approx(40.0, rel=1e-14)
    assert np.real(R * np.conj(np.exp(0.3j - 0.5j * np.pi))) == pytest.approx(-10.0, rel=1e-13)


def test_total_reaction_no_sliding_is_nan():
    assert np.isnan(total_reaction(1j, 2j, 0.2))                     # velocity along the normal


def test_slider_state_cone_rule():
    assert slider_state([0.05, 0.1, 0.2], 0.1).tolist() == [
        "decelerates or stays at rest", "keeps its state", "accelerates"]


def _incline_by_components(Q, lam, beta, mu, sense):
    # unknowns P, N: along the plane and along its normal (friction against the motion)
    A = np.array([[np.cos(beta), -sense * mu], [np.sin(beta), 1.0]])
    return np.linalg.solve(A, [Q * np.sin(lam), Q * np.cos(lam)])[0]


def test_incline_forces_match_component_balance():
    for _ in range(200):
        Q, lam, mu = RNG.uniform(1, 100), RNG.uniform(0, 1.2), RNG.uniform(0, 0.6)
        beta = RNG.uniform(-1.0, 0.5)
        f = incline_forces(Q, lam, mu, push_angle=beta)
        assert f.raising == pytest.approx(_incline_by_components(Q, lam, beta, mu, 1), rel=1e-11)
        assert f.lowering == pytest.approx(_incline_by_components(Q, lam, beta, mu, -1), rel=1e-9, abs=1e-9 * Q)


def test_incline_forces_horizontal_push_is_tan_form():
    f = incline_forces(100.0, math.radians(30), 0.2)
    phi = math.atan(0.2)
    assert f.raising == pytest.approx(100 * math.tan(math.radians(30) + phi), rel=1e-14)
    assert f.lowering == pytest.approx(100 * math.tan(math.radians(30) - phi), rel=1e-13)


def test_incline_forces_block_holds_itself_below_friction_angle():
    mu = 0.25
    lam = np.array([0.9, 0.999, 1.001, 1.1]) * math.atan(mu)
    assert (incline_forces(1.0, lam, mu).lowering <= 0).tolist() == [True, True, False, False]


def test_vgroove_mu_from_flank_balance():
    for _ in range(50):
        mu, theta, Q = RNG.uniform(0, 0.5), RNG.uniform(0.2, 1.5), RNG.uniform(1, 10)
        # flank normals (pointing into the slider), each at theta from the horizontal... up
        n1 = np.array([np.cos(theta), np.sin(theta)])
        n2 = np.array([-np.cos(theta), np.sin(theta)])
        N = np.linalg.solve(np.c_[n1, n2], [0.0, Q])                 # sideways and vertical balance
        assert vgroove_mu(mu, theta) == pytest.approx(mu * N.sum() / Q, rel=1e-12)


def test_vgroove_mu_bad_half_angle():
    with pytest.raises(ValueError, match="half_angle"):
        vgroove_mu(0.1, 2.0)


@pytest.mark.parametrize("condition, law", [("new", lambda t: 1), ("run-in", mpmath.cos)])
def test_journal_mu_pressure_integrals(condition, law):
    with mpmath.workdps(30):
        total = mpmath.quad(law, [-mpmath.pi / 2, mpmath.pi / 2])
        load = mpmath.quad(lambda t: law(t) * mpmath.cos(t), [-mpmath.pi / 2, mpmath.pi / 2])
        assert journal_mu(0.1, condition) == pytest.approx(float(0.1 * total / load), rel=1e-14)


def test_journal_mu_textbook_factors():
    assert round(journal_mu(1.0, "new"), 2) == 1.57 and round(journal_mu(1.0, "run-in"), 2) == 1.27
    assert journal_mu(0.2, "line") == 0.2
    with pytest.raises(ValueError, match="condition"):
        journal_mu(0.1, "old")


def test_curved_contact_mu_range():
    assert curved_contact_mu(0.1, 1.5) == pytest.approx(0.15)
    with pytest.raises(ValueError, match=r"Expected `k` in \[1, pi/2\], got 1.6"):
        curved_contact_mu(0.1, 1.6)


def test_friction_circle_and_journal_state():
    rho = friction_circle(journal_mu(0.1, "run-in"), 10.0)
    assert rho == pytest.approx(40 / math.pi * 0.1, rel=1e-14)
    assert journal_state([0.5 * rho, rho, 2 * rho], rho).tolist() == [
        "decelerates or stays at rest", "keeps its state", "accelerates"]
    with pytest.raises(ValueError, match="`r` > 0"):
        friction_circle(0.1, 0.0)


@pytest.mark.parametrize("cross", [True, False])
def test_two_force_tilt_angle_line_is_tangent_to_both_circles(cross):
    l, ra, rb = 80.0, 3.0, 5.0
    t = two_force_tilt_angle(l, ra, rb, cross=cross)
    t = t if cross else -t                          # a direct tangent leans towards the larger circle
    normal = np.array([-math.sin(t), math.cos(t)])
    c = -ra                                                         # signed distance of A is +ra
    dist_b = normal @ np.array([l, 0.0]) - c
    assert dist_b == pytest.approx(-rb if cross else rb, abs=1e-12)


def test_two_force_tilt_angle_overlapping_circles_raise():
    with pytest.raises(ValueError, match=r"rho_a \+ rho_b = 50.0 >= length = 50.0"):
        two_force_tilt_angle(50.0, 25.0, 25.0)


def _thrust_quad(Q, mu, R, r, alpha, law):
    with mpmath.workdps(30):
        p = (lambda s: 1) if law == "new" else (lambda s: 1 / s)
        load = mpmath.quad(lambda s: p(s) * 2 * mpmath.pi * s, [r, R])     # axial part of cone normal force
        moment = mpmath.quad(lambda s: mu * p(s) * s * 2 * mpmath.pi * s / mpmath.sin(alpha), [r, R])
        return float(Q * moment / load)


def test_thrust_friction_moment_matches_quadrature():
    for _ in range(20):
        Q, mu, R = RNG.uniform(1, 100), RNG.uniform(0.05, 0.5), RNG.uniform(5, 50)
        r, alpha = RNG.uniform(0, 0.95) * R, RNG.uniform(0.1, np.pi / 2)
        for law in ("new", "run-in"):
            got = thrust_friction_moment(Q, mu, R, r, condition=law, cone_half_angle=alpha)
            assert got == pytest.approx(_thrust_quad(Q, mu, R, max(r, 1e-300), alpha, law), rel=1e-12)


def test_thrust_friction_moment_limits():
    assert thrust_friction_moment(3.0, 0.2, 10.0) == pytest.approx(2 / 3 * 0.2 * 3 * 10, rel=1e-15)
    assert thrust_friction_moment(3.0, 0.2, 10.0, condition="run-in") == pytest.approx(0.2 * 3 * 10 / 2)
    near = 10.0 * (1 - 1e-12)                                       # a narrow ring: both laws give mu Q R
    for law in ("new", "run-in"):
        assert thrust_friction_moment(1.0, 0.2, 10.0, near, condition=law) == pytest.approx(2.0, rel=1e-11)


def test_thrust_friction_moment_bad_radii():
    with pytest.raises(ValueError, match=r"Expected `r_in` < `r_out`, got r_in = 12.0 >= r_out = 10.0"):
        thrust_friction_moment(1.0, 0.2, 10.0, 12.0)


def test_collar_friction_radius_exercise_2_24():
    assert collar_friction_radius(25.0, 21.0, "run-in") == 23.0
    assert collar_friction_radius(25.0, 21.0) == pytest.approx(2 / 3 * (25**3 - 21**3) / (25**2 - 21**2), rel=1e-15)


def _gripped(h, D, a, mu):
    """Brute force: at first contact, is the net horizontal force on the strip inward?"""
    cos_alpha = 1 - (h - a) / D                                     # D/2 (1 - cos) = (h - a)/2
    sin_alpha = math.sqrt(1 - cos_alpha**2)
    return mu * cos_alpha - sin_alpha >= 0


def test_rolling_mill_max_thickness_by_force_balance():
    D, a, mu = 1200.0, 25.0, 0.3
    h = rolling_mill_max_thickness(D, a, mu)
    assert _gripped(h * (1 - 1e-9), D, a, mu) and not _gripped(h * (1 + 1e-9), D, a, mu)


def test_rolling_mill_max_thickness_small_mu_no_cancellation():
    with mpmath.workdps(50):
        mu = mpmath.mpf("1e-6")
        want = 1000 * (1 - mpmath.cos(mpmath.atan(mu)))
    assert rolling_mill_max_thickness(1000.0, 0.0, 1e-6) == pytest.approx(float(want), rel=1e-14)


def test_friction_table_2_2_as_printed():
    assert len(FRICTION_TABLE_2_2) == 8
    assert FRICTION_TABLE_2_2["steel-steel"][0] == (0.15, 0.15)
    for row in FRICTION_TABLE_2_2.values():
        for cell in row:
            assert cell is None or 0 < cell[0] <= cell[1] < 1
