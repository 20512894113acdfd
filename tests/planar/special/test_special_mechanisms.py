"""Tests of the special mechanisms of Table 2-1 (`mech.planar.special._special`, `_double_slider`).

Expected values come from other routes than the generated formulas: unwrapped angles of
brute-force sweeps, intersections of lines solved as linear systems, mpmath's numerical
derivatives of positions at 50 digits, numerical integration of the rolling condition,
or the textbook's statements (F16, F17, F22, F49, F50, F51, F52, F54).
"""

import mpmath
import numpy as np
import pytest

from mech.planar import GuideBar, SliderCrank
from mech.planar.special._double_slider import EllipticTrammel, OldhamCoupling, ScotchYoke, TangentMechanism
from mech.planar.special._special import RotatingGuideBar, SwingingBlock

mpmath.mp.dps = 50
RNG = np.random.default_rng(2024)


def _mp_rates(f, t):
    """f, f', f'' at t (mpmath, 50 digits) as Python complex numbers."""
    t = mpmath.mpf(float(t))
    return tuple(complex(mpmath.diff(f, t, k)) for k in range(3))


# --- rotating guide-bar -------------------------------------------------------------------

@pytest.mark.parametrize("a, d", [(2.0, 1.0), (1.0 + 1e-3, 1.0), (5.0, 0.3)])
def test_rotating_guide_bar_solve_sweep(a, d):
    """psi is the unwrapped angle of D->B, continuous, one guide turn per crank turn."""
    theta = np.linspace(-2 * np.pi, 2 * np.pi, 400001)
    pose = RotatingGuideBar(a, d).solve(theta)
    ref = np.unwrap(np.angle(a * np.exp(1j * theta) - d))
    ref += 2 * np.pi * np.round((pose.psi[0] - ref[0]) / (2 * np.pi))   # same sheet
    np.testing.assert_allclose(pose.psi, ref, atol=1e-9)
    # the reference |B - D| loses digits to cancellation near theta = 0 when a ~ d
    np.testing.assert_allclose(pose.rho, np.abs(a * np.exp(1j * theta) - d), rtol=1e-13, atol=4 * a * 1e-16)
    assert pose.psi[-1] - pose.psi[0] == pytest.approx(4 * np.pi, abs=1e-12)
    assert np.all(pose.valid)


@pytest.mark.parametrize("a, d", [(2.0, 1.0), (1.3, 1.0), (1.0, 1.0)])
def test_rotating_guide_bar_rates_mpmath(a, d):
    """omega_guide, v_slide and their derivatives against mpmath.diff of the geometry."""
    mech = RotatingGuideBar(a, d)
    for t0 in RNG.uniform(0.2, 6.0, 6):
        t0m = mpmath.mpf(float(t0))
        z0 = a * mpmath.expj(t0m) - d

        def angle(t):   # angle of D->B, relative to its value at t0 (no branch cut nearby)
            return mpmath.arg((a * mpmath.expj(t) - d) / z0)

        def dist(t):
            return abs(a * mpmath.expj(t) - d)

        w, al = 1.7, -0.4
        pose = mech.solve(t0, order=2, omega=w, alpha=al)
        _, d1, d2 = _mp_rates(angle, t0)
        assert float(pose.omega_guide) == pytest.approx(d1.real * w, rel=1e-12)
        assert float(pose.alpha_guide) == pytest.approx(d2.real * w**2 + d1.real * al, rel=1e-11, abs=1e-12)
        r0, r1, r2 = _mp_rates(dist, t0)
        sign = np.sign(float(pose.rho))                     # signed rho when a == d
        assert float(pose.rho) == pytest.approx(sign * r0.real, rel=1e-13)
        assert float(pose.v_slide) == pytest.approx(sign * r1.real * w, rel=1e-11, abs=1e-13)
        assert float(pose.a_slide) == pytest.approx(sign * (r2.real * w**2 + r1.real * al), rel=1e-10, abs=1e-12)


def test_rotating_guide_bar_equal_ratio_exactly_two():
    """F50, Fig. 2-58: with a = d the crank turns exactly twice per guide turn.

    The guide line's direction is half the unwrapped angle of (B - D)^2, which is smooth
    even where the block passes through D.
    """
    mech = RotatingGuideBar(1.0, 1.0)
    theta = np.linspace(1e-3, 4 * np.pi + 1e-3, 200001)
    pose = mech.solve(theta, order=1, omega=3.0)
    line = np.unwrap(np.angle((np.exp(1j * theta) - 1.0) ** 2)) / 2
    assert line[-1] - line[0] == pytest.approx(2 * np.pi, abs=1e-9)
    # the brute-force direction of exp(i theta) - 1 loses digits where B nears D
    np.testing.assert_allclose(np.sin(pose.psi - line), 0.0, atol=1e-10)
    np.testing.assert_array_equal(pose.omega_guide, 1.5)
    assert np.all(pose.psi - pose.psi[0] == pytest.approx(theta / 2 - theta[0] / 2, abs=1e-12))
    assert mech.guide_turns_per_crank_turn() == 0.5
    with mpmath.workdps(50):
        slope = mpmath.diff(lambda t: mpmath.arg((mpmath.expj(t) - 1) ** 2) / 2, mpmath.mpf("1.234"))
    assert slope == pytest.approx(0.5, abs=1e-40)


def test_rotating_guide_bar_equal_passes_pivot():
    """At theta = 0 the block is at D; rho changes sign smoothly and B - D = rho exp(i psi)."""
    theta = np.linspace(-0.1, 0.1, 201)
    pose = RotatingGuideBar(2.0, 2.0).solve(theta)
    np.testing.assert_allclose(pose.B - 2.0, pose.rho * np.exp(1j * pose.psi), atol=1e-15)
    assert pose.rho[0] < 0 < pose.rho[-1] and pose.rho[100] == 0.0


# --- oscillating and turning block --------------------------------------------------------

def test_swinging_block_kind_and_swing():
    """F16: the block oscillates when the crank is shorter than the frame, else turns."""
    theta = np.linspace(0, 2 * np.pi, 400001)
    block = SwingingBlock(1.0, 2.0)
    assert block.kind == "oscillating"
    psi = np.unwrap(np.angle(np.exp(1j * theta) - 2.0))
    assert block.swing() == pytest.approx(np.ptp(psi), abs=1e-9)
    assert SwingingBlock(2.0, 2.0).kind == SwingingBlock(3.0, 2.0).kind == "turning"
    turning = SwingingBlock(3.0, 2.0).solve(theta)
    assert turning.psi[-1] - turning.psi[0] == pytest.approx(2 * np.pi, abs=1e-12)


def test_swinging_block_solve_matches_guide_bar_geometry():
    """The rod passes through crank pin and pivot: rho is the pin-to-block length."""
    theta = RNG.uniform(-4, 4, 50)
    pose = SwingingBlock(0.7, 1.9).solve(theta, order=1)
    np.testing.assert_allclose(pose.rho, np.abs(0.7 * np.exp(1j * theta) - 1.9), rtol=1e-13)
    ref = GuideBar(0.7, 1.9).solve(theta, order=1)
    np.testing.assert_allclose(pose.omega_guide, ref.omega_guide, rtol=1e-15)


def test_swinging_block_swing_turning_raises():
    with pytest.raises(ValueError, match="Expected `a` < `d`"):
        SwingingBlock(2.0, 1.0).swing()


def test_fixed_block_is_slider_crank():
    """The fixed block with link CB = b turning about the block is SliderCrank(b, a):
    the guide point A at distance a from B on the guide line through C (brute force)."""
    a_rod, b_link = 3.0, 1.2
    phi = RNG.uniform(-3, 3, 40)
    B = b_link * np.exp(1j * phi)
    x_A = SliderCrank(b_link, a_rod).solve(phi).x
    np.testing.assert_allclose(np.abs(x_A - B), a_rod, rtol=1e-14)
    assert np.all(x_A > B.real)


# --- elliptic trammel -----------------------------------------------------------------------

@pytest.mark.parametrize("point", [(0.0, 0.0), (0.7, 0.0), (1.0, 0.0), (-0.4, 0.3), (2.5, -0.8)])
def test_trammel_solve_from_sliders(point):
    """Coupler points built from two slider positions (x_B, y_C) with x_B^2 + y_C^2 = L^2."""
    L = 2.0
    xb = RNG.uniform(-L, L, 30)
    yc = np.sqrt(L**2 - xb**2) * RNG.choice([-1.0, 1.0], 30)
    p, q = point
    expected = xb + (p + 1j * q) * (1j * yc - xb) / L
    theta = np.angle(xb + 1j * yc)                      # the crank points at the midpoint
    pose = EllipticTrammel(L, point=point).solve(theta)
    np.testing.assert_allclose(pose.P, expected, atol=1e-14)
    np.testing.assert_allclose(pose.M, (xb + 1j * yc) / 2, atol=1e-15)
    np.testing.assert_allclose(np.abs(pose.C - pose.B), L, rtol=1e-15)


def test_trammel_path_axes_sweep():
    """F17: P traces an ellipse; the midpoint a circle of radius L/2; B a segment of 2L."""
    theta = np.linspace(0, 2 * np.pi, 100001)
    for point in [(0.5, 0.0), (1.0, 0.0), (0.3, 0.4), (0.0, 0.0)]:
        mech = EllipticTrammel(2.0, point=point)
        P = mech.solve(theta).P
        r = np.abs(P)
        major, minor = mech.path_axes()
        assert r.max() == pytest.approx(major, abs=1e-9) and r.min() == pytest.approx(minor, abs=1e-8)
    np.testing.assert_allclose(np.abs(EllipticTrammel(2.0, point=(1.0, 0.0)).solve(theta).P), 1.0, rtol=1e-15)


def test_trammel_rates_mpmath():
    L, p, q, w, al = 1.6, 0.45, -0.2, 2.3, 0.7
    mech = EllipticTrammel(L, point=(p, q))

    def P_rolling(t):     # an independent formula: the rolling circle of Fig. 2-60
        return (L / 2) * mpmath.expj(t) + (p - L / 2 + 1j * q) * mpmath.expj(mpmath.pi - t)

    for t0 in RNG.uniform(-3, 3, 5):
        pose = mech.solve(t0, order=2, omega=w, alpha=al)
        z0, z1, z2 = _mp_rates(P_rolling, t0)
        assert abs(complex(pose.P) - z0) < 1e-14
        assert abs(complex(pose.vP) - z1 * w) < 1e-13
        assert abs(complex(pose.aP) - (z2 * w**2 + z1 * al)) < 1e-13
    assert float(pose.omega_coupler) == -w and float(pose.alpha_coupler) == -al


def test_trammel_centrodes():
    """F54: I has zero velocity, |I| = L (fixed centrode), |I - M| = L/2 (moving centrode)."""
    L = 3.0
    theta = RNG.uniform(-3, 3, 40)
    pose = EllipticTrammel(L).solve(theta, order=1)
    np.testing.assert_allclose(np.abs(pose.I), L, rtol=1e-15)
    np.testing.assert_allclose(np.abs(pose.I - pose.M), L / 2, rtol=1e-14)
    # velocity of the body point at I, from the velocities of B and C
    for k in range(5):
        body = (pose.I[k] - pose.B[k]) * np.exp(-1j * pose.phi[k])
        at_I = EllipticTrammel(L, point=(body.real, body.imag)).solve(theta[k], order=1)
        assert abs(complex(at_I.vP)) < 1e-13
    # and I lies on the normals to the guides at B and at C
    np.testing.assert_allclose(pose.I.real, pose.B.real, atol=1e-15)
    np.testing.assert_allclose(pose.I.imag, pose.C.imag, atol=1e-15)


def test_trammel_rolling_circle_equivalence():
    """Fig. 2-60: integrate the no-slip condition of a circle of radius L/2 rolling inside
    one of radius L, and compare every body point with the trammel point for point."""
    L = 2.0
    r, R = L / 2, L
    theta = np.linspace(0, 2 * np.pi, 20001)
    M = (R - r) * np.exp(1j * theta)
    dM = 1j * (R - r) * np.exp(1j * theta)                  # dM/dtheta
    K = R * np.exp(1j * theta)                              # contact point
    # no slip: dM + i beta' (K - M) = 0, solved in the least-squares sense at each step
    beta_rate = np.real(np.conj(1j * (K - M)) * (-dM)) / np.abs(K - M) ** 2
    beta = np.pi + np.concatenate([[0.0], np.cumsum((beta_rate[1:] + beta_rate[:-1]) / 2 * np.diff(theta))])
    for p, q in [(0.0, 0.0), (L, 0.0), (0.3, 0.5), (1.7, -0.9)]:
        rolling = M + (p - L / 2 + 1j * q) * np.exp(1j * beta)
        np.testing.assert_allclose(rolling, EllipticTrammel(L, point=(p, q)).solve(theta).P, atol=1e-12)
    np.testing.assert_allclose(beta_rate, -1.0, atol=1e-15)


def test_trammel_isosceles_stroke_4a():
    """F22, Fig. 2-22c: crank = rod = a, stroke 4a, symmetric about the crank centre; the
    auxiliary pin runs on the perpendicular guide."""
    a = 1.25
    mech = EllipticTrammel.from_crank(a)
    theta = np.linspace(0, 2 * np.pi, 100001)
    pose = mech.solve(theta)
    np.testing.assert_allclose(np.abs(pose.M), a, rtol=1e-15)          # the crank
    np.testing.assert_allclose(np.abs(pose.B - pose.M), a, rtol=1e-14)  # the rod
    np.testing.assert_allclose(pose.B.imag, 0.0, atol=0)
    np.testing.assert_allclose(pose.C.real, 0.0, atol=1e-15)
    assert np.ptp(pose.B.real) == pytest.approx(4 * a, rel=1e-12) == mech.stroke()
    assert pose.B.real.max() == pytest.approx(-pose.B.real.min(), rel=1e-12)
    # without the auxiliary pin the slider-crank with b = a has stroke 2a only
    assert SliderCrank(a, a).stroke() == pytest.approx(2 * a)


# --- sine and tangent mechanisms -------------------------------------------------------------

def test_scotch_yoke_rates_mpmath():
    a, w, al = 0.8, 1.9, -1.1
    mech = ScotchYoke(a)
    for t0 in RNG.uniform(-3, 3, 6):
        x0, x1, x2 = _mp_rates(lambda t: mpmath.re(a * mpmath.expj(t)), t0)
        pose = mech.solve(t0, order=2, omega=w, alpha=al)
        assert float(pose.x) == pytest.approx(x0.real, abs=1e-15)
        assert float(pose.v) == pytest.approx(x1.real * w, abs=1e-14)
        assert float(pose.acc) == pytest.approx(x2.real * w**2 + x1.real * al, abs=1e-14)
    assert mech.stroke() == 1.6


def test_scotch_yoke_f52_slider_crank_extremes_larger():
    """F52: the slider-crank's max |v| and max |acc| exceed the sine mechanism's; max |acc|
    is (1 + lambda) a omega^2, and max |v| = 1.03088 a omega at lambda = 0.25."""
    theta = np.linspace(0, 2 * np.pi, 200001)
    yoke = ScotchYoke(1.0).solve(theta, order=2)
    for lam in (0.1, 0.25, 1 / 3):
        sc = SliderCrank(1.0, 1 / lam).solve(theta, order=2)
        assert np.abs(sc.v).max() > np.abs(yoke.v).max() + 1e-3 * lam
        assert np.abs(sc.acc).max() == pytest.approx(1 + lam, rel=1e-12)
        assert np.abs(yoke.acc).max() == pytest.approx(1.0, rel=1e-12)
    sc = SliderCrank(1.0, 4.0).solve(theta, order=1)
    assert np.abs(sc.v).max() == pytest.approx(1.03088, abs=5e-6)


def test_tangent_solve_line_intersection():
    """h from intersecting the bar's line with the guide x = L (a 2x2 linear system)."""
    L = 1.5
    theta = np.concatenate([RNG.uniform(-1.5, 1.5, 20), RNG.uniform(1.7, 4.5, 10)])
    pose = TangentMechanism(L).solve(theta)
    for k, t in enumerate(theta):
        # s * exp(i t) = L + i h  ->  [cos t, 0; sin t, -1] [s, h] = [L, 0]
        s, h = np.linalg.solve([[np.cos(t), 0.0], [np.sin(t), -1.0]], [L, 0.0])
        assert float(pose.h[k]) == pytest.approx(h, rel=1e-13, abs=1e-14)
    np.testing.assert_allclose(pose.S.real, L)


def test_tangent_rates_mpmath():
    L, w, al = 2.0, 0.9, 0.3
    mech = TangentMechanism(L)
    for t0 in RNG.uniform(-1.3, 1.3, 6):
        h0, h1, h2 = _mp_rates(lambda t: L * mpmath.tan(t), t0)
        pose = mech.solve(t0, order=2, omega=w, alpha=al)
        assert float(pose.v) == pytest.approx(h1.real * w, rel=1e-13)
        assert float(pose.acc) == pytest.approx(h2.real * w**2 + h1.real * al, rel=1e-12, abs=1e-14)


def test_tangent_solve_near_parallel():
    """cos(theta) is never exactly zero at a float angle: near pi/2 the output is huge,
    finite and valid (the bar meets the guide far away)."""
    pose = TangentMechanism(1.0).solve(np.pi / 2, order=1)
    assert bool(pose.valid) and 1e15 < float(pose.h) < np.inf and float(pose.v) > 1e31


# --- Oldham coupling --------------------------------------------------------------------------

def _mp_oldham_centre(e0, t):
    """Centre of the cross-slider by intersecting the two tongue lines (mpmath LU solve)."""
    c, s = mpmath.cos(t), mpmath.sin(t)
    # s1 (c, s) = (e0, 0) + s3 (-s, c)
    sol = mpmath.lu_solve(mpmath.matrix([[c, s], [s, -c]]), mpmath.matrix([e0, 0]))
    return sol[0] * c + 1j * sol[0] * s


def test_oldham_solve_slot_intersection():
    e0 = 0.35
    theta = RNG.uniform(-4, 4, 30)
    pose = OldhamCoupling(e0).solve(theta)
    for k, t in enumerate(theta):
        s1, s3 = np.linalg.solve([[np.cos(t), np.sin(t)], [np.sin(t), -np.cos(t)]], [e0, 0.0])
        S = s1 * np.exp(1j * t)
        assert abs(complex(pose.S[k]) - S) < 1e-15
        assert abs(S - (e0 + s3 * 1j * np.exp(1j * t))) < 1e-15
        assert float(pose.s1[k]) == pytest.approx(s1, abs=1e-15)
        assert float(pose.s3[k]) == pytest.approx(s3, abs=1e-15)
    np.testing.assert_allclose(np.abs(pose.S - e0 / 2), e0 / 2, rtol=1e-14)


def test_oldham_speeds_slider_omega_centre_two_omega():
    """F49 (corrected): the centre orbits at 2 omega, the cross-slider turns at omega."""
    e0, w, al = 0.2, 5.0, 1.5
    mech = OldhamCoupling(e0)
    for t0 in RNG.uniform(-3, 3, 5):
        t0m = mpmath.mpf(float(t0))
        ref = _mp_oldham_centre(e0, t0m) - e0 / 2

        def orbit(t):
            return mpmath.arg((_mp_oldham_centre(e0, t) - e0 / 2) / ref)

        def output_line(t):   # output shaft: direction of S - O3, as a line (angle doubled)
            z = _mp_oldham_centre(e0, t) - e0
            z0 = _mp_oldham_centre(e0, t0m) - e0
            return mpmath.arg((z / z0) ** 2) / 2

        pose = mech.solve(t0, order=2, omega=w, alpha=al)
        assert mpmath.diff(orbit, t0m) == pytest.approx(2.0, abs=1e-30)
        assert mpmath.diff(output_line, t0m) == pytest.approx(1.0, abs=1e-30)
        assert float(pose.omega_orbit) == 2 * w and float(pose.omega_slider) == w
        assert float(pose.omega_output) == w and float(pose.alpha_orbit) == 2 * al
        s0, s1, s2 = _mp_rates(lambda t: _mp_oldham_centre(e0, t), t0)
        assert abs(complex(pose.vS) - s1 * w) < 1e-14
        assert abs(complex(pose.aS) - (s2 * w**2 + s1 * al)) < 1e-13


def test_oldham_inertia_force():
    """m (e0/2) (2 omega)^2 = m |a_S| at constant speed."""
    e0, m, w = 0.05, 3.0, 40.0
    mech = OldhamCoupling(e0)
    aS = mech.solve(RNG.uniform(-3, 3, 10), order=2, omega=w).aS
    np.testing.assert_allclose(m * np.abs(aS), m * (e0 / 2) * (2 * w) ** 2, rtol=1e-14)
    assert mech.inertia_force(m, w) == pytest.approx(m * (e0 / 2) * (2 * w) ** 2, rel=1e-15)


# --- API --------------------------------------------------------------------------------------

@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
@pytest.mark.parametrize("mech", [RotatingGuideBar(2.0, 1.0), RotatingGuideBar(1.0, 1.0),
                                  EllipticTrammel(1.0, point=(0.2, 0.1)), ScotchYoke(1.0),
                                  TangentMechanism(1.0), OldhamCoupling(0.1)])
def test_solve_broadcast(mech, shape):
    theta = RNG.uniform(-1.2, 1.2, shape)
    pose = mech.solve(theta, order=2, omega=2.0)
    for name, value in pose._fields.items():
        assert np.shape(value) == shape, name


def test_solve_order_fields():
    pose = OldhamCoupling(0.1).solve(0.3)
    with pytest.raises(AttributeError, match="order=1"):
        pose.vS
    with pytest.raises(AttributeError, match="immutable"):
        pose.S = 0


@pytest.mark.parametrize("make, match", [
    (lambda: RotatingGuideBar(0.5, 1.0), "Expected `a` >= `d`"),
    (lambda: RotatingGuideBar(-1.0, 1.0), "Expected `a` > 0"),
    (lambda: EllipticTrammel(0.0), "Expected `L` > 0"),
    (lambda: EllipticTrammel(1.0, point=(np.nan, 0)), "Expected finite `point`"),
    (lambda: EllipticTrammel(1.0, point=3), "Expected `point`"),
    (lambda: EllipticTrammel.from_crank(-2), "Expected `a` > 0"),
    (lambda: ScotchYoke(np.inf), "Expected `a` > 0"),
    (lambda: TangentMechanism("x"), "Expected `L` to be a real number"),
    (lambda: OldhamCoupling(-0.1), "Expected `e0` > 0"),
    (lambda: OldhamCoupling(0.1).inertia_force(0.0, 1.0), "Expected `m` > 0"),
    (lambda: SwingingBlock(1.0, 0.0), "Expected `d` > 0"),
    (lambda: ScotchYoke(1.0).solve(0.0, order=3), "Expected `order`"),
    (lambda: OldhamCoupling(1.0).solve(np.nan), "Expected finite `theta`"),
    (lambda: EllipticTrammel(1.0).solve(0.0, order=1, omega=np.inf), "Expected finite `omega`"),
])
def test_bad_input_errors(make, match):
    with pytest.raises(ValueError, match=match):
        make()
