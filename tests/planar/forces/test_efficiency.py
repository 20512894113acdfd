"""Efficiency and self-locking (mech.planar.forces._efficiency) against independent routes: the
free-body equilibria of the wedges, rod and clamp solved numerically, sign changes found by
bisection, power bookkeeping for combined machines."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from mech.planar.forces._efficiency import (
    eccentric_clamp_locks,
    eccentric_clamp_max_angle,
    efficiency,
    efficiency_from_drive,
    efficiency_from_resistance,
    is_self_locking,
    parallel_efficiency,
    push_rod,
    series_efficiency,
    spreading_wedge_force,
    wedge_press,
    wedge_press_forces,
)

RNG = np.random.default_rng(6003)


def _press_free_bodies(lam, mu, sense):
    """P for Q = 1 from the four equilibrium equations of the two wedges (unknowns P, N1..N3)."""
    s, c, m = math.sin(lam), math.cos(lam), sense * mu
    A = np.array([[1, -m, -(s + m * c), 0], [0, 1, -(c - m * s), 0],
                  [0, 0, s + m * c, -1], [0, 0, c - m * s, -m]], dtype=float)
    return np.linalg.solve(A, [0, 0, 0, 1])[0]


def test_efficiency_forms_agree_on_a_pulley():
    # a machine with velocity ratio v_Q/v_P = 0.25 lifting Q = 300 with P = 100: eta = 0.75
    P, Q, ratio = 100.0, 300.0, 0.25
    assert efficiency(Q * ratio, P) == pytest.approx(0.75)
    assert efficiency_from_drive(Q * ratio, P) == pytest.approx(0.75)     # P0 = Q v_Q / v_P
    assert efficiency_from_resistance(Q, P / ratio) == pytest.approx(0.75)  # Q0 = P v_P / v_Q


def test_efficiency_bad_driving_raises():
    with pytest.raises(ValueError, match="Expected `driving` > 0, got 0.0"):
        efficiency(1.0, 0.0)


def test_series_and_parallel_by_power_bookkeeping():
    etas = RNG.uniform(0.5, 1.0, 4)
    power = 1000.0
    for e in etas:                                  # pass the power through each machine
        power *= e
    assert series_efficiency(etas) == pytest.approx(power / 1000.0, rel=1e-14)
    shares = RNG.uniform(0.0, 5.0, 4)
    out = sum(e * s for e, s in zip(etas, shares))
    assert parallel_efficiency(etas, shares) == pytest.approx(out / shares.sum(), rel=1e-14)
    assert min(etas) <= parallel_efficiency(etas, shares) <= max(etas)


def test_mixed_efficiency_nests():
    # motor -> gear (0.95) -> two parallel lines (0.9 on 60 %, 0.8 on 40 %)
    mixed = series_efficiency([0.95, parallel_efficiency([0.9, 0.8], [0.6, 0.4])])
    assert mixed == pytest.approx(0.95 * (0.6 * 0.9 + 0.4 * 0.8), rel=1e-15)


def test_combination_bad_input():
    with pytest.raises(ValueError, match=r"in \[0, 1\], got 1.2"):
        series_efficiency([0.9, 1.2])
    with pytest.raises(ValueError, match="as many"):
        parallel_efficiency([0.9, 0.8], [1.0])


def test_is_self_locking():
    assert is_self_locking([-1e-3, 0.0, 1e-3]).tolist() == [True, True, False]


def test_wedge_press_matches_free_bodies():
    for _ in range(100):
        lam, mu = RNG.uniform(0.05, 0.9), RNG.uniform(0.0, 0.25)
        if lam + 2 * math.atan(mu) >= 1.5:
            continue
        w = wedge_press(lam, math.atan(mu))
        assert w.forward_ratio == pytest.approx(_press_free_bodies(lam, mu, 1), rel=1e-10)
        assert w.reverse_ratio == pytest.approx(_press_free_bodies(lam, mu, -1), rel=1e-9, abs=1e-12)
        assert w.efficiency == pytest.approx(math.tan(lam) / _press_free_bodies(lam, mu, 1), rel=1e-10)


def test_example_2_11_assumed_data():
    w = wedge_press(math.radians(10), math.atan(0.1))
    assert w.forward_ratio == pytest.approx(0.392322, abs=5e-7)
    assert w.efficiency == pytest.approx(0.449444, abs=5e-7)
    assert w.reverse_efficiency == pytest.approx(-0.140701, abs=5e-7)
    assert w.reverse_locks and w.forward_moves


def test_example_2_11_reverse_efficiency_crosses_zero_at_twice_phi():
    for mu in (0.05, 0.1, 0.2):
        root = brentq(lambda lam: _press_free_bodies(lam, mu, -1), 1e-3, 1.2, xtol=1e-15)
        assert wedge_press(root, math.atan(mu)).lock_angle == pytest.approx(root, rel=1e-12)
        assert root == pytest.approx(2 * math.atan(mu), rel=1e-12)
        below, above = wedge_press(np.array([0.999, 1.001]) * root, math.atan(mu)).reverse_efficiency
        assert below < 0 < above


def test_example_2_11_efficiency_ratio_corrected_form():
    lam, phi = math.radians(30), math.radians(5)
    w = wedge_press(lam, phi)
    T, t2 = math.tan(lam), math.tan(2 * phi)
    ratio = w.efficiency / w.reverse_efficiency
    assert ratio == pytest.approx(T**2 * (1 - T**2 * t2**2) / (T**2 - t2**2), rel=1e-12)
    assert abs(ratio - T**2 / (T**2 - t2**2)) > 1e-2                # the printed middle form is wrong
    w45 = wedge_press(math.pi / 4, phi)
    assert w45.efficiency == pytest.approx(w45.reverse_efficiency, rel=1e-12)


def test_wedge_press_forward_stroke_jams_beyond_2_27():
    w = wedge_press(math.radians(75), math.radians(10))
    assert not w.forward_moves and w.efficiency == 0.0 and math.isinf(w.forward_ratio)


def test_wedge_press_bad_angles():
    with pytest.raises(ValueError, match="Expected `lam` < pi/2"):
        wedge_press(2.0, 0.1)
    with pytest.raises(ValueError, match="Expected `phi` >= 0"):
        wedge_press(0.2, -0.1)


def _spreader_free_bodies(Q, theta, mu, base):
    # block A: unknowns R (face normal), N (base normal); then the wedge takes both faces
    m = mu if base else 0.0
    A = np.array([[math.cos(theta) - mu * math.sin(theta), -m],
                  [-(math.sin(theta) + mu * math.cos(theta)), 1.0]])
    Nf, _ = np.linalg.solve(A, [Q, 0.0])
    return 2 * Nf * (math.sin(theta) + mu * math.cos(theta))


@pytest.mark.parametrize("base", [True, False])
def test_spreading_wedge_force_matches_free_bodies(base):
    for _ in range(50):
        Q, theta, mu = RNG.uniform(10, 1000), RNG.uniform(0.05, 0.7), RNG.uniform(0, 0.3)
        want = _spreader_free_bodies(Q, theta, mu, base)
        assert spreading_wedge_force(Q, theta, math.atan(mu), base) == pytest.approx(want, rel=1e-10)


def test_push_rod_matches_equilibrium_with_width():
    for _ in range(50):
        mu, e, L, w = RNG.uniform(0, 0.5), RNG.uniform(0, 80), RNG.uniform(10, 200), RNG.uniform(1, 30)
        P = 1.0
        # unknowns G, n1, n2: sideways, along the rod, moments about the guide's lower end
        A = np.array([[0, 1, -1], [1, mu, mu], [0, L - mu * w / 2, mu * w / 2]])
        G = np.linalg.solve(A, [0, P, e * P])[0]
        eta, L_min = push_rod(mu, e, L)
        assert eta == pytest.approx(G / P, rel=1e-10, abs=1e-12)
        assert (eta <= 0) == (L <= L_min)


def _clamp_moment(alpha, e, r, rho, mu):
    """Net moment about the pivot tending to release, minus the pin's capacity (>0: slips)."""
    C = np.array([0.0, r])                              # disc centre; contact K at the origin
    O = C + e * np.array([-math.sin(alpha), math.cos(alpha)])
    n = np.array([0.0, 1.0])                            # normal force on the disc at K (N = 1)
    K_rel = -O                                          # K - O
    m_normal = K_rel[0] * n[1] - K_rel[1] * n[0]        # its moment about O (releasing sense)
    # the disc turns about O with the sense of m_normal; friction at K opposes K's tangential motion
    vK = np.sign(m_normal) * np.array([-K_rel[1], K_rel[0]])
    f = -mu * np.sign(vK[0]) * np.array([1.0, 0.0])
    m_friction = K_rel[0] * f[1] - K_rel[1] * f[0]
    R = math.hypot(1.0, mu)
    return abs(m_normal + m_friction) - R * rho if abs(m_normal) > abs(m_friction) else -1.0


def test_eccentric_clamp_by_moment_balance():
    e, r, rho, mu = 10.0, 40.0, 1.0, 0.15
    alpha_max = eccentric_clamp_max_angle(e, r, rho, math.atan(mu))
    root = brentq(lambda a: _clamp_moment(a, e, r, rho, mu), 0.3, 1.4, xtol=1e-15)
    assert alpha_max == pytest.approx(root, rel=1e-12)
    alphas = np.linspace(0.0, 1.4, 57)
    locks = eccentric_clamp_locks(alphas, e, r, rho, math.atan(mu))
    brute = np.array([_clamp_moment(a, e, r, rho, mu) <= 0 for a in alphas])
    assert (locks == brute).all()


def test_eccentric_clamp_pin_radius_not_disc_radius():
    # the textbook's rho = mu0 * r_disc would claim locking at angles that slip
    mu0, r_pin, r_disc, e, phi = 0.2, 5.0, 40.0, 10.0, math.atan(0.15)
    right = eccentric_clamp_max_angle(e, r_disc, mu0 * r_pin, phi)
    printed = eccentric_clamp_max_angle(e, r_disc, mu0 * r_disc, phi)
    assert printed > right + 0.3
    assert not eccentric_clamp_locks(0.5 * (right + printed), e, r_disc, mu0 * r_pin, phi)


def test_eccentric_clamp_always_locks_when_argument_exceeds_one():
    assert eccentric_clamp_max_angle(5.0, 40.0, 1.0, 0.3) == pytest.approx(0.3 + math.pi / 2)


def test_example_2_11_ratio_is_2_26_over_2_28():
    """Errata rows 36 and 37 (example 2-11, §2.3 I). The forward efficiency is (2-26),
    eta = tan(lam)/tan(lam + 2 phi); the reverse one is (2-28), eta' = tan(lam - 2 phi)/tan(lam);
    their ratio eta/eta' is (2-26) / (2-28) = tan^2(lam)/(tan(lam + 2 phi) tan(lam - 2 phi)),
    the first form the text prints, and not (2-28) / (2-26) as the text says. The formulas
    are typed here from the text; `wedge_press` solves the free bodies."""
    for lam_deg, phi_deg in [(30, 5), (20, 3), (60, 8), (40, 10)]:
        lam, phi = math.radians(lam_deg), math.radians(phi_deg)
        w = wedge_press(lam, phi)
        eq_2_26 = math.tan(lam) / math.tan(lam + 2 * phi)
        eq_2_28 = math.tan(lam - 2 * phi) / math.tan(lam)
        assert w.efficiency == pytest.approx(eq_2_26, rel=1e-12)
        assert w.reverse_efficiency == pytest.approx(eq_2_28, rel=1e-12)
        ratio = w.efficiency / w.reverse_efficiency
        assert ratio == pytest.approx(math.tan(lam) ** 2 / (math.tan(lam + 2 * phi) * math.tan(lam - 2 * phi)),
                                      rel=1e-12)
        assert abs(ratio - eq_2_28 / eq_2_26) > 1e-3              # the division as the text words it


@pytest.mark.parametrize("phi", [np.pi / 2, 3.0, 1e300])
def test_eccentric_clamp_friction_angle_below_right_angle(phi):
    """A friction angle atan(mu) is below pi/2; phi = 1e300 returned NaN without a word."""
    with pytest.raises(ValueError, match=r"Expected `phi` in \[0, pi/2\)"):
        eccentric_clamp_max_angle(10.0, 40.0, 1.0, phi)


def test_fig_2_68_wedge_press_force_polygons_close():
    """Fig. 2-68b: the forces on each wedge close a polygon, the push matches the four
    free-body equations solved above and (2-25), and |R23| = Q cos(phi) / cos(lam + 2 phi)
    as the text's polygon gives (pressing; phi -> -phi on the release)."""
    for _ in range(50):
        lam, mu, Q = RNG.uniform(0.05, 0.9), RNG.uniform(0.0, 0.25), RNG.uniform(10.0, 5000.0)
        phi = math.atan(mu)
        for release, sense in ((False, 1), (True, -1)):
            if (not release and lam + 2 * phi >= 1.5) or (release and lam <= phi):
                continue
            f = wedge_press_forces(Q, lam, phi, release=release)
            assert abs(f.P + f.R12 + f.R32) < 1e-12 * Q
            assert abs(f.Q + f.R23 + f.R13) < 1e-12 * Q
            assert f.R23 == -f.R32 and f.Q == -1j * Q and f.P.imag == 0
            assert f.P.real == pytest.approx(Q * _press_free_bodies(lam, mu, sense), rel=1e-10, abs=1e-12 * Q)
            assert abs(f.R23) == pytest.approx(Q * math.cos(phi) / math.cos(lam + 2 * sense * phi), rel=1e-12)
            # each total reaction leans by phi from its face's normal
            normal = math.sin(lam) + 1j * math.cos(lam)
            assert abs(np.angle(f.R23 / normal)) == pytest.approx(phi, abs=1e-12)
            assert abs(np.angle(f.R12 / 1j)) == pytest.approx(phi, abs=1e-12)
            assert abs(np.angle(f.R13 / -1)) == pytest.approx(phi, abs=1e-12)
    w = wedge_press(math.radians(10), math.atan(0.1))
    f = wedge_press_forces(1000.0, math.radians(10), math.atan(0.1))
    assert f.P.real == pytest.approx(1000.0 * w.forward_ratio, rel=1e-13)


def test_wedge_press_forces_refuses_a_press_that_cannot_move():
    with pytest.raises(ValueError, match="Expected `lam` \\+ 2 `phi` < pi/2"):
        wedge_press_forces(1.0, math.radians(80), math.radians(6))
    with pytest.raises(ValueError, match="Expected `lam` > `phi` on the release"):
        wedge_press_forces(1.0, math.radians(5), math.radians(6), release=True)
