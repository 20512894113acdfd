"""Tests of `mech.planar.SliderCrank` against independent routes.

Reference values come from mpmath at 50 digits through the implicit-function route
(Newton's method on the constraint, then numerical partial derivatives of the constraint),
from brute-force sweeps of the crank angle, or from the textbook's corrected numbers:
never from the generated formulas themselves.
"""

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.planar import SliderCrank, SliderCrankPose


def _mp_reference(a, b, e, theta, m, omega, alpha):
    """x, v, acc, phi, omega_coupler, alpha_coupler at 50 digits, implicit-function route.

    F(x, theta) = (x - a cos theta)^2 + (e - a sin theta)^2 - b^2 = 0 is solved by Newton's
    method from the outside guess a cos(theta) + m b (which converges to the root of branch
    m); dx/dtheta and d2x/dtheta2 follow from numerical partial derivatives of F.
    """
    with mpmath.workdps(50):
        a, b, e, theta, omega, alpha = (mpmath.mpf(float(v)) for v in (a, b, e, theta, omega, alpha))

        def F(x, t):
            return (x - a * mpmath.cos(t)) ** 2 + (e - a * mpmath.sin(t)) ** 2 - b**2

        x = mpmath.findroot(lambda x: F(x, theta), a * mpmath.cos(theta) + m * b, solver="newton",
                            df=lambda x: 2 * (x - a * mpmath.cos(theta)), tol=mpmath.mpf(10) ** -90)
        assert mpmath.sign(x - a * mpmath.cos(theta)) == m
        d = {ij: mpmath.diff(F, (x, theta), ij) for ij in [(1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]}
        x1 = -d[0, 1] / d[1, 0]
        x2 = -(d[0, 2] + 2 * d[1, 1] * x1 + d[2, 0] * x1**2) / d[1, 0]
        X, Y = x - a * mpmath.cos(theta), e - a * mpmath.sin(theta)
        X1, Y1 = x1 + a * mpmath.sin(theta), -a * mpmath.cos(theta)
        X2, Y2 = x2 + a * mpmath.cos(theta), a * mpmath.sin(theta)
        phi1 = (X * Y1 - Y * X1) / (X**2 + Y**2)
        phi2 = (X * Y2 - Y * X2) / (X**2 + Y**2)
        return {
            "x": x, "v": x1 * omega, "acc": x2 * omega**2 + x1 * alpha,
            "phi": mpmath.atan2(Y, X), "omega_coupler": phi1 * omega,
            "alpha_coupler": phi2 * omega**2 + phi1 * alpha,
        }


def _random_cases(n, seed, turning=True):
    """n random (a, b, e, theta, omega, alpha); poses at least 5 % of b from a dead point."""
    rng = np.random.default_rng(seed)
    cases = []
    while len(cases) < n:
        a, e = rng.uniform(0.1, 1.0), rng.uniform(-1.0, 1.0)
        if turning:
            b = (a + abs(e)) * rng.uniform(1.02, 4.0)
        else:
            b = rng.uniform(max(abs(e) - a, 0.0) + 0.05, a + abs(e))
        theta = rng.uniform(-np.pi, np.pi)
        if abs(e - a * np.sin(theta)) > 0.95 * b:
            continue
        cases.append((a, b, e, theta, rng.uniform(-3, 3), rng.uniform(-3, 3)))
    return cases


@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("turning", [True, False])
def test_solve_accuracy_mpmath(branch, turning):
    """x, v, acc, phi and the rod rates agree with a 50-digit implicit route (1000 cases)."""
    worst = dict.fromkeys(["x", "v", "acc", "phi", "omega_coupler", "alpha_coupler"], 0.0)
    for a, b, e, theta, omega, alpha in _random_cases(250, 11 + branch + 5 * turning, turning):
        pose = SliderCrank(a, b, e, branch=branch).solve(theta, order=2, omega=omega, alpha=alpha)
        ref = _mp_reference(a, b, e, theta, branch, omega, alpha)
        scale = {"x": a + b, "v": (a + b) * max(1.0, abs(omega)),
                 "acc": (a + b) * max(1.0, omega**2 + abs(alpha)), "phi": 1.0,
                 "omega_coupler": max(1.0, abs(omega)), "alpha_coupler": max(1.0, omega**2 + abs(alpha))}
        assert pose.valid
        for name in worst:
            err = abs(float(getattr(pose, name)) - float(ref[name])) / scale[name]
            worst[name] = max(worst[name], err)
    assert max(worst.values()) <= 1e-12, worst


def test_solve_pins_close_the_loop():
    """|C - B| = b, Im C = e, B = a exp(i theta), vB and aB of a uniform-plus-accelerating crank."""
    mech = SliderCrank(0.7, 2.3, -0.4, branch=-1)
    theta = np.linspace(-np.pi, np.pi, 101)
    pose = mech.solve(theta, order=2, omega=2.0, alpha=-0.5)
    np.testing.assert_allclose(np.abs(pose.C - pose.B), 2.3, rtol=1e-14)
    np.testing.assert_allclose(pose.C.imag, -0.4, atol=1e-15)
    np.testing.assert_allclose(pose.B, 0.7 * np.exp(1j * theta), atol=1e-15)
    np.testing.assert_allclose(pose.vB, 0.7 * 2.0 * 1j * np.exp(1j * theta), atol=1e-14)
    np.testing.assert_allclose(pose.aB, 0.7 * (-0.5j - 4.0) * np.exp(1j * theta), atol=1e-14)
    np.testing.assert_allclose(np.exp(1j * pose.phi), (pose.C - pose.B) / 2.3, atol=1e-14)


@pytest.mark.parametrize("branch", [1, -1])
def test_solve_branch_continuity(branch):
    """Through a full turn the slider moves continuously and C stays on its side of B."""
    mech = SliderCrank(30.0, 100.0, 20.0, branch=branch)
    theta = np.linspace(0.0, 2 * np.pi, 20001)
    pose = mech.solve(theta)
    assert np.all(pose.valid)
    assert np.max(np.abs(np.diff(pose.x))) < 30.0 * (theta[1] - theta[0]) * 1.5
    assert np.all(branch * (pose.C - pose.B).real > 0)
    assert pose.x[0] == pytest.approx(pose.x[-1], abs=1e-12)


def test_solve_rocking_crank_valid_mask():
    """A crank that cannot turn: NaN and valid=False beyond the dead points, strict raises."""
    mech = SliderCrank(1.0, 1.2, 0.5)
    theta = np.array([0.0, -np.pi / 2, np.pi / 2])    # |e - a sin| = 0.5, 1.5, 0.5
    pose = mech.solve(theta, order=2)
    assert pose.valid.tolist() == [True, False, True]
    for name in ("x", "phi", "v", "acc", "omega_coupler", "alpha_coupler"):
        assert np.isnan(getattr(pose, name)[1])
    assert np.isnan(pose.C[1])
    with pytest.raises(AssemblyError, match="theta = -1.57"):
        mech.solve(theta, strict=True)
    assert not mech.crank_turns


def test_solve_dead_point_position_exact():
    """At a dead point (|e - a sin(theta)| = b) the position is exact and finite."""
    mech = SliderCrank(1.0, 1.5, 0.5)
    pose = mech.solve(-np.pi / 2, order=1)
    assert pose.assembled and pose.x == pytest.approx(0.0, abs=1e-15)
    assert abs(pose.phi) == pytest.approx(np.pi / 2)
    assert not pose.valid and np.isnan(pose.v) and np.isnan(pose.omega_coupler)


def test_solve_dead_point_rates_masked():
    """SliderCrank(1, 2, -1) at theta = pi/2: |e - a sin(theta)| = 2 = b, a dead point.

    The position exists (assembled, strict does not raise), the rates are infinite: they are
    NaN under `valid` False (with `assembled` True), never NaN or inf under a True mask. Just beside the dead
    point the rates are finite, large, and agree with the closed form of the loop.
    """
    mech = SliderCrank(1.0, 2.0, -1.0)
    pose = mech.solve([np.pi / 2, np.pi / 2 - 1e-6], order=2, strict=True)
    assert pose.assembled.tolist() == [True, True]
    assert pose.valid.tolist() == [False, True]
    assert pose.x[0] == pytest.approx(0.0, abs=1e-15) and pose.phi[0] == pytest.approx(-np.pi / 2)
    for name in ("v", "omega_coupler", "acc", "alpha_coupler"):
        value = getattr(pose, name)
        assert np.isnan(value[0]) and np.isfinite(value[1]), name
    assert pose.vB[0] == pytest.approx(-1.0, abs=1e-15) and np.isfinite(pose.aB[0])
    # beside it: phi' = -a omega cos(theta) / (b cos(phi)), independent of the generated code
    t = np.pi / 2 - 1e-6
    rod = pose.C[1] - pose.B[1]
    assert pose.omega_coupler[1] == pytest.approx(-np.cos(t) / rod.real, rel=1e-6)
    assert pose.v[1] == pytest.approx(-np.sin(t) - rod.imag * pose.omega_coupler[1], rel=1e-6)
    still = mech.solve(np.pi / 2, order=1, omega=0.0)          # undetermined: also masked
    assert still.assembled and not still.valid and np.isnan(still.v)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_solve_broadcasting(shape):
    rng = np.random.default_rng(3)
    theta = rng.uniform(-np.pi, np.pi, shape)
    pose = SliderCrank(1.0, 3.0, 0.5).solve(theta, order=2, omega=2.0)
    for name in ("x", "phi", "B", "C", "valid", "v", "omega_coupler", "vB", "acc", "alpha_coupler", "aB"):
        assert np.shape(getattr(pose, name)) == shape, name
    # rates broadcast against theta
    pose = SliderCrank(1.0, 3.0).solve(0.3, order=2, omega=np.ones(shape), alpha=np.zeros(shape))
    assert np.shape(pose.acc) == shape and np.shape(pose.x) == shape


def test_solve_order_gates_fields():
    pose = SliderCrank(1.0, 3.0).solve(0.2)
    assert isinstance(pose, SliderCrankPose)
    with pytest.raises(AttributeError, match="order=1"):
        pose.v
    with pytest.raises(AttributeError, match="order=2"):
        SliderCrank(1.0, 3.0).solve(0.2, order=1).acc
    with pytest.raises(AttributeError, match="immutable"):
        pose.x = 1.0


def _sweep_limits(a, b, e, branch, n=2_000_001):
    """Brute force: extreme slider positions and the crank angles there."""
    theta = np.linspace(0.0, 2 * np.pi, n)
    x = a * np.cos(theta) + branch * np.sqrt(b**2 - (e - a * np.sin(theta)) ** 2)
    return theta[np.argmax(x)], theta[np.argmin(x)], x.max(), x.min()


def test_example_2_3_limit_positions():
    """Example 2-3 (F31) with (a, b, e) = (30, 100, 20): theta_0 = 7.75167 deg, H = 61.3703.

    Expected values: the textbook's (corrected, |e|) arccos formula at 50 digits, and a
    brute-force sweep of two million crank angles.
    """
    mech = SliderCrank(30.0, 100.0, 20.0)
    with mpmath.workdps(50):
        a, b, e = mpmath.mpf(30), mpmath.mpf(100), mpmath.mpf(20)
        theta0 = mpmath.acos(e / (b + a)) - mpmath.acos(e / (b - a))
        H = mpmath.sqrt((b + a) ** 2 - e**2) - mpmath.sqrt((b - a) ** 2 - e**2)
    assert mech.extreme_angle() == pytest.approx(float(theta0), rel=1e-15)
    assert mech.stroke() == pytest.approx(float(H), rel=1e-15)
    assert np.degrees(mech.extreme_angle()) == pytest.approx(7.75167, abs=5e-6)
    assert mech.stroke() == pytest.approx(61.3703, abs=5e-5)
    assert mech.time_ratio() == pytest.approx((180 + 7.751672) / (180 - 7.751672), rel=1e-7)
    t_max, t_min, x_max, x_min = _sweep_limits(30.0, 100.0, 20.0, 1)
    lim = mech.limit_positions()
    assert lim.x_extended == pytest.approx(x_max, rel=1e-12)
    assert lim.x_folded == pytest.approx(x_min, rel=1e-12)
    assert np.exp(1j * lim.theta_extended) == pytest.approx(np.exp(1j * t_max), abs=1e-5)
    assert np.exp(1j * lim.theta_folded) == pytest.approx(np.exp(1j * t_min), abs=1e-5)
    # slow stroke: pi + theta_0 from extended to folded (branch * e > 0, crank ccw)
    assert (lim.theta_folded - lim.theta_extended) % (2 * np.pi) == pytest.approx(np.pi + lim.extreme_angle)


@pytest.mark.parametrize("a, b, e, branch", [(1.0, 2.5, -0.7, 1), (0.4, 3.0, 1.1, -1), (2.0, 2.5, 0.5, -1)])
def test_limit_positions_sweep(a, b, e, branch):
    """Limit positions, stroke and extreme angle agree with a brute-force sweep."""
    lim = SliderCrank(a, b, e, branch=branch).limit_positions()
    t_max, t_min, x_max, x_min = _sweep_limits(a, b, e, branch)
    ext, fold = (t_max, t_min) if branch == 1 else (t_min, t_max)
    assert abs(np.exp(1j * lim.theta_extended) - np.exp(1j * ext)) < 1e-5
    assert abs(np.exp(1j * lim.theta_folded) - np.exp(1j * fold)) < 1e-5
    assert lim.stroke == pytest.approx(x_max - x_min, rel=1e-12)
    swept = abs(abs(t_max - t_min) - np.pi)
    assert lim.extreme_angle == pytest.approx(swept, abs=1e-5)
    rotation = (lim.theta_folded - lim.theta_extended) % (2 * np.pi)
    assert rotation == pytest.approx(np.pi + np.sign(branch * e) * lim.extreme_angle)
    assert lim.time_ratio == pytest.approx((np.pi + swept) / (np.pi - swept), abs=1e-5)


def test_stroke_centred_and_offset():
    """F22: centred stroke 2a with no quick return; an offset gives H > 2a and K > 1."""
    centred = SliderCrank(30.0, 100.0)
    assert centred.stroke() == 60.0 and centred.extreme_angle() == 0.0 and centred.time_ratio() == 1.0
    for e in (-20.0, 5.0, 60.0):
        offset = SliderCrank(30.0, 100.0, e)
        assert offset.stroke() > 60.0 and offset.time_ratio() > 1.0


def test_stroke_needs_turning_crank():
    mech = SliderCrank(1.0, 1.2, 0.5)
    for method in (mech.stroke, mech.extreme_angle, mech.time_ratio, mech.limit_positions,
                   mech.min_transmission_angle):
        with pytest.raises(ValueError, match="turns fully"):
            method()


def test_transmission_angle_geometry():
    """gamma = pi/2 - (pressure angle between the rod BC and the guide direction)."""
    mech = SliderCrank(0.6, 2.0, 0.5, branch=-1)
    theta = np.linspace(-np.pi, np.pi, 37)
    rod = mech.solve(theta).C - mech.solve(theta).B
    pressure = np.arctan2(np.abs(rod.imag), np.abs(rod.real))
    np.testing.assert_allclose(mech.transmission_angle(theta), np.pi / 2 - pressure, atol=1e-14)


@pytest.mark.parametrize("e", [20.0, -20.0, 0.0])
def test_min_transmission_angle_sweep(e):
    """F57: cos(gamma_min) = (a + |e|) / b, at the crank angle found by a sweep."""
    mech = SliderCrank(30.0, 100.0, e)
    gamma_min, theta_at = mech.min_transmission_angle()
    theta = np.linspace(-np.pi, np.pi, 200001)
    gamma = mech.transmission_angle(theta)
    assert gamma_min == pytest.approx(gamma.min(), abs=1e-9)
    assert mech.transmission_angle(theta_at) == pytest.approx(gamma_min, abs=1e-14)
    assert np.cos(gamma_min) == pytest.approx((30 + abs(e)) / 100, rel=1e-14)


def test_transmission_angle_centred_extremes():
    """Exercise 2-6 (3): centred, gamma = 90 deg at the dead centres, smallest at +-90 deg."""
    mech = SliderCrank(30.0, 100.0)
    np.testing.assert_allclose(mech.transmission_angle([0.0, np.pi]), np.pi / 2)
    assert mech.transmission_angle(np.pi / 2) == pytest.approx(np.arccos(0.3), rel=1e-14)


def _max_abs_error(lam, quantity, n=20001):
    theta = np.linspace(0, 2 * np.pi, n)
    mech = SliderCrank(lam, 1.0)
    exact = mech.solve(theta, order=2)
    approx = mech.approximate(theta)
    if quantity == "cos":
        return np.max(np.abs(np.cos(exact.phi) - approx.cos_phi))
    got = {"x": exact.x, "v": exact.v, "acc": exact.acc}[quantity]
    return np.max(np.abs(got - getattr(approx, quantity))) / lam


@pytest.mark.parametrize("lam, cos_err, x_err", [
    (0.2, 2.04e-4, 1.02e-3), (0.25, 5.04e-4, 2.02e-3), (0.3, 1.06e-3, 3.54e-3), (1 / 3, 1.64e-3, 4.91e-3)])
def test_approximate_error_table(lam, cos_err, x_err):
    """(2-10) errors: an independently recomputed table (independent of this package)."""
    assert _max_abs_error(lam, "cos") == pytest.approx(cos_err, rel=0.01)
    assert _max_abs_error(lam, "x") == pytest.approx(x_err, rel=0.01)


@pytest.mark.parametrize("lam", [0.05, 0.1, 0.2, 0.3])
def test_approximate_error_law(lam):
    """Leading-order laws from the next series term: lam^3/8, 3 sqrt(3)/32 lam^3, lam^3/2."""
    assert _max_abs_error(lam, "x") / (lam**3 / 8) == pytest.approx(1.0, abs=1.2 * lam**2)
    assert _max_abs_error(lam, "v") / (3 * np.sqrt(3) / 32 * lam**3) == pytest.approx(1.0, abs=1.5 * lam**2)
    assert _max_abs_error(lam, "acc") / (lam**3 / 2) == pytest.approx(1.0, abs=1.2 * lam**2)


def test_approximate_three_decimals_claim():
    """The text's "three decimals" for cos(phi) holds up to lam = 0.25 and fails at 0.3."""
    assert _max_abs_error(0.25, "cos") < 5.1e-4 and _max_abs_error(0.3, "cos") > 1e-3


def test_approximate_f52_maxima():
    """F52: lam = 0.25, exact max|v| = 1.03088 a w and max|acc| = 1.25 a w^2 (> Scotch yoke)."""
    pose = SliderCrank(0.25, 1.0).solve(np.linspace(0, 2 * np.pi, 200001), order=2)
    assert np.max(np.abs(pose.v)) / 0.25 == pytest.approx(1.03088, abs=1e-5)
    assert np.max(np.abs(pose.acc)) / 0.25 == pytest.approx(1.25, abs=1e-9)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_approximate_broadcasting(shape):
    out = SliderCrank(1.0, 4.0).approximate(np.zeros(shape), omega=2.0)
    assert all(np.shape(v) == shape for v in out)
    assert float(np.ravel(out.x)[0]) == pytest.approx(5.0) and float(np.ravel(out.acc)[0]) == pytest.approx(-5.0)


def test_approximate_offset_raises():
    with pytest.raises(ValueError, match="centred"):
        SliderCrank(1.0, 4.0, 0.1).approximate(0.0)
    with pytest.raises(ValueError, match="branch"):
        SliderCrank(1.0, 4.0, branch=-1).approximate(0.0)


@pytest.mark.parametrize("kwargs, match", [
    (dict(a=-1.0, b=3.0), "Expected `a` > 0, got -1.0"),
    (dict(a=1.0, b=0.0), "Expected `b` > 0, got 0.0"),
    (dict(a=1.0, b=3.0, e=np.nan), "Expected finite `e`"),
    (dict(a=1.0, b=3.0, e="x"), "Expected `e` to be a real number"),
    (dict(a=1.0, b=3.0, branch=0), "Expected `branch` to be"),
    (dict(a=1.0, b=0.5, e=2.0), "Expected `b` >= |e| - a"),
])
def test_init_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match.replace("|", r"\|")):
        SliderCrank(**kwargs)


def test_solve_bad_input():
    mech = SliderCrank(1.0, 3.0)
    with pytest.raises(ValueError, match="Expected `order`"):
        mech.solve(0.0, order=3)
    with pytest.raises(ValueError, match="Expected finite `theta`"):
        mech.solve([0.0, np.inf])
    with pytest.raises(ValueError, match="Expected finite `omega`"):
        mech.solve(0.0, order=1, omega=np.nan)


def test_fig_2_7c_joint_c_rocks_when_b_exceeds_a():
    """Errata row 5 (caption of Fig 2-7c): with b > a joint C rocks. The slider does not
    turn, so the relative rotation at C is the rod angle phi; over a full crank turn it must
    sweep exactly [-asin(a/b), asin(a/b)] (sin phi = -a sin(theta)/b, evaluated in mpmath),
    never a full turn."""
    theta = np.linspace(0.0, 2.0 * np.pi, 4001)
    for a, b in [(1.0, 2.0), (1.0, 1.25), (3.0, 3.01), (1.0, 40.0)]:
        phi = SliderCrank(a, b).solve(theta).phi
        bound = float(mpmath.asin(mpmath.mpf(a) / b))
        assert np.max(phi) == pytest.approx(bound, rel=1e-6)
        assert np.min(phi) == pytest.approx(-bound, rel=1e-6)
        assert np.ptp(phi) < np.pi
