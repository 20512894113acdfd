"""Tests of `mech.planar.GuideBar` (crank and oscillating guide-bar, example 2-2).

Expected values come from brute-force sweeps, from mpmath's numerical derivatives of the
guide direction at 50 digits, or from the textbook's numbers.
"""

import mpmath
import numpy as np
import pytest

from mech.planar import GuideBar, GuideBarPose


def _sweep(a, d, n=2_000_001):
    theta = np.linspace(0.0, 2 * np.pi, n)
    psi = np.unwrap(np.angle(a * np.exp(1j * theta) - d))
    return theta, psi


def test_example_2_2_guide_bar():
    """Example 2-2 (F23, F30): d = 300, swing 60 deg -> a = 150, K = 2, guide >= 450.

    The swing, the extreme angle and the longest DB are re-measured by a sweep of two
    million crank angles.
    """
    mech = GuideBar.from_swing(300.0, np.radians(60.0))
    assert mech.a == pytest.approx(150.0, rel=1e-15)
    assert mech.time_ratio() == pytest.approx(2.0, rel=1e-14)
    assert mech.min_guide_length() == pytest.approx(450.0, rel=1e-15)
    theta, psi = _sweep(150.0, 300.0)
    assert np.degrees(psi.max() - psi.min()) == pytest.approx(60.0, abs=1e-6)
    assert mech.swing() == pytest.approx(psi.max() - psi.min(), abs=1e-10)
    # F23: the crank turns pi - theta_0 between the two limit positions on the short side
    short = abs(theta[np.argmax(psi)] - theta[np.argmin(psi)])
    short = min(short, 2 * np.pi - short)
    assert mech.extreme_angle() == pytest.approx(np.pi - short, abs=1e-5)
    assert np.max(np.abs(150.0 * np.exp(1j * theta) - 300.0)) == pytest.approx(450.0, rel=1e-12)


@pytest.mark.parametrize("a, d", [(0.3, 1.0), (0.9, 1.0), (2.0, 7.0)])
def test_swing_sweep(a, d):
    _, psi = _sweep(a, d, 400001)
    mech = GuideBar(a, d)
    assert mech.swing() == pytest.approx(psi.max() - psi.min(), abs=1e-9)
    assert mech.time_ratio() == pytest.approx((np.pi + mech.swing()) / (np.pi - mech.swing()), rel=1e-14)


def test_from_swing_roundtrip():
    for swing in np.radians([5.0, 60.0, 120.0, 170.0]):
        assert GuideBar.from_swing(2.5, swing).swing() == pytest.approx(swing, rel=1e-14)


def test_solve_geometry():
    """B - D = rho exp(i psi) with psi continuous in (pi/2, 3pi/2)."""
    mech = GuideBar(0.8, 1.0)
    theta = np.linspace(-3 * np.pi, 3 * np.pi, 3001)
    pose = mech.solve(theta)
    np.testing.assert_allclose(pose.B - 1.0, pose.rho * np.exp(1j * pose.psi), atol=1e-14)
    assert np.all((pose.psi > np.pi / 2) & (pose.psi < 3 * np.pi / 2)) and np.all(pose.valid)
    assert np.max(np.abs(np.diff(pose.psi))) < 0.1


def _mp_rates(a, d, theta, omega, alpha):
    """psi, rho and their time derivatives by mpmath.diff of a locally unwrapped angle."""
    with mpmath.workdps(50):
        a, d, theta, omega, alpha = (mpmath.mpf(float(v)) for v in (a, d, theta, omega, alpha))
        z0 = a * mpmath.expj(theta) - d
        psi0 = mpmath.arg(z0) % (2 * mpmath.pi)

        def psi(t):
            z = (a * mpmath.expj(t) - d) / z0
            return psi0 + mpmath.atan2(mpmath.im(z), mpmath.re(z))

        def rho(t):
            return abs(a * mpmath.expj(t) - d)

        out = {}
        for name, f in (("psi", psi), ("rho", rho)):
            f1, f2 = mpmath.diff(f, theta, 1), mpmath.diff(f, theta, 2)
            out[name] = (f(theta), f1 * omega, f2 * omega**2 + f1 * alpha)
        return out


def test_solve_accuracy_mpmath():
    rng = np.random.default_rng(5)
    worst = 0.0
    for _ in range(300):
        d = rng.uniform(0.5, 3.0)
        a = d * rng.uniform(0.02, 0.98)
        theta, omega, alpha = rng.uniform(-np.pi, np.pi), rng.uniform(-3, 3), rng.uniform(-3, 3)
        pose = GuideBar(a, d).solve(theta, order=2, omega=omega, alpha=alpha)
        ref = _mp_rates(a, d, theta, omega, alpha)
        scale_w = max(1.0, abs(omega)) * d / (d - a)
        scale_a = max(1.0, omega**2 + abs(alpha)) * (d / (d - a)) ** 2
        errs = [
            abs(pose.psi - float(ref["psi"][0])),
            abs(pose.omega_guide - float(ref["psi"][1])) / scale_w,
            abs(pose.alpha_guide - float(ref["psi"][2])) / scale_a,
            abs(pose.rho - float(ref["rho"][0])) / (a + d),
            abs(pose.v_slide - float(ref["rho"][1])) / ((a + d) * scale_w),
            abs(pose.a_slide - float(ref["rho"][2])) / ((a + d) * scale_a),
        ]
        worst = max(worst, *errs)
    assert worst < 1e-12


def test_solve_crank_pin_rates():
    mech = GuideBar(1.0, 2.0)
    theta = np.linspace(0, 2 * np.pi, 9)
    pose = mech.solve(theta, order=2, omega=3.0, alpha=0.5)
    np.testing.assert_allclose(pose.vB, 3j * np.exp(1j * theta), atol=1e-14)
    np.testing.assert_allclose(pose.aB, (0.5j - 9.0) * np.exp(1j * theta), atol=1e-14)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_solve_broadcasting(shape):
    pose = GuideBar(1.0, 2.0).solve(np.full(shape, 0.4), order=2)
    assert isinstance(pose, GuideBarPose)
    for name in ("B", "psi", "rho", "valid", "omega_guide", "v_slide", "vB", "alpha_guide", "a_slide", "aB"):
        assert np.shape(getattr(pose, name)) == shape, name
    assert np.shape(GuideBar(1.0, 2.0).solve(0.4, order=1, omega=np.ones(shape)).omega_guide) == shape


def test_solve_order_gates_fields():
    with pytest.raises(AttributeError, match="order=1"):
        GuideBar(1.0, 2.0).solve(0.1).omega_guide


@pytest.mark.parametrize("args, match", [
    ((-1.0, 2.0), "Expected `a` > 0, got -1.0"),
    ((1.0, 0.0), "Expected `d` > 0, got 0.0"),
    ((2.0, 2.0), "Expected `a` < `d`"),
])
def test_init_bad_input(args, match):
    with pytest.raises(ValueError, match=match):
        GuideBar(*args)


def test_from_swing_bad_input():
    with pytest.raises(ValueError, match="Expected `swing` < pi"):
        GuideBar.from_swing(1.0, np.pi)
    with pytest.raises(ValueError, match="Expected `swing` > 0"):
        GuideBar.from_swing(1.0, -0.1)


def test_fig_2_73_guide_bar_transmission_angle_constant_in_a_sweep():
    """Fig. 2-73: on the quick-return guide-bar the bar's point under the block moves along
    the bar's normal at every crank angle (alpha = 0, gamma = 90 deg). The bar's angular
    velocity is checked against an mpmath derivative of the angle of B - D at 50 digits."""
    from mech.planar import quick_return_guide_bar

    theta = np.linspace(0.0, 2 * np.pi, 73)
    sol = quick_return_guide_bar().solve(theta, order=1)
    B, D = sol.points["B"], sol.points["D"]
    v_bar = 1j * sol.omegas["bar"] * (B - D)
    normal = 1j * sol.direction("bar")
    alpha = np.abs(np.angle(v_bar / normal))
    alpha = np.minimum(alpha, np.pi - alpha)
    assert alpha.max() < 1e-12
    mpmath.mp.dps = 50
    for t, w in zip(theta[::6], sol.omegas["bar"][::6]):
        exact = mpmath.diff(lambda x: mpmath.atan2(124 * mpmath.sin(x) + 400, 124 * mpmath.cos(x)), t)
        assert w == pytest.approx(float(exact), rel=1e-12, abs=1e-15)
