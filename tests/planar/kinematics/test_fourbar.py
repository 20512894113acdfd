"""FourBar against an independent mpmath oracle, properties, and bad input.

The oracle intersects the circles about B and D directly at 50 digits and differentiates
that construction with ``mpmath.diff``: it shares no formula with the generated code.
Errors are measured relative to the linkage size L = a + b + c + d (positions), L |omega|
(velocities) and L (omega^2 + |alpha|) (accelerations), or to the value itself where that
is larger. The distance of a pose from a limit position is delta = min(f2, f3, f4) / L, the
relative slack of the diagonal BD in the triangle BCD.
"""

import mpmath
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mech import AssemblyError
from mech.planar import FourBar

EPS = np.finfo(float).eps


def oracle(a, b, c, d, p, q, theta, branch, omega, alpha):
    """Positions, velocities and accelerations of B, C, P at 50 digits, or None."""
    with mpmath.workdps(50):
        a, b, c, d, p, q, theta, omega, alpha = (
            mpmath.mpf(float(v)) for v in (a, b, c, d, p, q, theta, omega, alpha)
        )
        z = mpmath.mpc(p, q)

        def points(t):
            B = a * mpmath.expj(t)
            e = (d - B) / abs(d - B)
            dist = abs(d - B)
            along = (b**2 - c**2 + dist**2) / (2 * dist)
            height2 = b**2 - along**2
            if height2 < 0:
                raise ValueError("cannot assemble")
            C = B + e * (along + 1j * branch * mpmath.sqrt(height2))
            return B, C, B + z * (C - B) / b

        try:
            B, C, P = points(theta)
        except ValueError:
            return None
        dist = abs(d - B)
        f = [dist - (c - b), dist - (b - c), (b + c) - dist]
        delta = min(f) / (a + b + c + d)

        def coordinate(i, j):
            return lambda t: points(t)[i].real if j == 0 else points(t)[i].imag

        out = {"B": B, "C": C, "P": P, "delta": delta}
        for i, name in enumerate("BCP"):
            first = [mpmath.diff(coordinate(i, j), theta, 1) for j in (0, 1)]
            second = [mpmath.diff(coordinate(i, j), theta, 2) for j in (0, 1)]
            # chain rule: d/dt = omega d/dtheta, d2/dt2 = omega^2 d2/dtheta2 + alpha d/dtheta
            out["v" + name] = mpmath.mpc(*(omega * g for g in first))
            out["a" + name] = mpmath.mpc(*(omega**2 * h + alpha * g for g, h in zip(first, second)))
        return out


def errors(linkage, theta, omega, alpha, ref):
    pose = linkage.solve(theta, order=2, omega=omega, alpha=alpha)
    L = linkage.a + linkage.b + linkage.c + linkage.d
    scale = {"": L, "v": L * abs(omega), "a": L * (omega**2 + abs(alpha))}
    worst = {"": 0.0, "v": 0.0, "a": 0.0}
    for kind in worst:
        for name in "BCP":
            r = complex(ref[kind + name])
            g = complex(getattr(pose, kind + name))
            worst[kind] = max(worst[kind], abs(g - r) / max(scale[kind], abs(r)))
    return worst


def random_cases(rng, count):
    """Random linkages and poses; about half of the linkages have a limited input."""
    cases = []
    while len(cases) < count:
        a, b, c, d = rng.uniform(0.2, 1.0, 4)
        if max(a, b, c, d) >= (a + b + c + d) / 2:
            continue
        p, q = rng.uniform(-1, 1, 2)
        theta = rng.uniform(-np.pi, np.pi)
        branch = int(rng.choice([-1, 1]))
        omega, alpha = rng.uniform(-2, 2, 2)
        cases.append((a, b, c, d, p, q, theta, branch, omega, alpha))
    return cases


@pytest.mark.slow
def test_solve_accuracy_against_mpmath():
    """>= 1000 assembled random poses, both branches, at least 1e-3 from a limit: <= 1e-12."""
    rng = np.random.default_rng(2)
    checked, worst, invalid_agree = 0, {"": 0.0, "v": 0.0, "a": 0.0}, 0
    for case in random_cases(rng, 1600):
        ref = oracle(*case)
        linkage = FourBar(*case[:4], branch=case[7], coupler=case[4:6])
        if ref is None:
            assert not linkage.solve(case[6]).valid
            invalid_agree += 1
            continue
        if ref["delta"] < 1e-3:
            continue
        e = errors(linkage, case[6], case[8], case[9], ref)
        worst = {k: max(worst[k], e[k]) for k in worst}
        checked += 1
    assert checked >= 1000, checked
    assert invalid_agree > 100
    assert worst[""] <= 1e-12 and worst["v"] <= 1e-12 and worst["a"] <= 1e-12, worst


def test_solve_accuracy_near_limit_positions():
    """Approaching a limit position, the error grows no faster than sqrt(eps / delta)."""
    rng = np.random.default_rng(5)
    rows = 0
    while rows < 40:
        a, b, c, d = rng.uniform(0.2, 1.0, 4)
        if max(a, b, c, d) >= (a + b + c + d) / 2:
            continue
        # the input stops where the diagonal BD reaches b + c (or |b - c|)
        for k_limit in (b + c, abs(b - c)):
            cos_limit = (a * a + d * d - k_limit**2) / (2 * a * d)
            if not -1 < cos_limit < 1:
                continue
            with mpmath.workdps(50):
                theta_limit = mpmath.acos(mpmath.mpf(cos_limit))
            for exponent in (2, 4, 6, 8, 10, 12):
                for side in (1, -1):
                    theta = float(theta_limit + side * mpmath.mpf(10) ** -exponent)
                    ref = oracle(a, b, c, d, 0.3, 0.2, theta, 1, 1.0, 0.0)
                    if ref is None or ref["delta"] <= 0:
                        continue
                    e = errors(FourBar(a, b, c, d, coupler=(0.3, 0.2)), theta, 1.0, 0.0, ref)
                    bound = max(1e-12, 4 * np.sqrt(EPS / float(ref["delta"])))
                    assert max(e.values()) <= bound, (a, b, c, d, theta, e, float(ref["delta"]))
                    rows += 1


def test_solve_loop_closure_example_2_1():
    """Example 2-1 (a, b, c, d) = (10, 40, 30, 35): both branches close the loop."""
    theta = np.linspace(0, 2 * np.pi, 721)
    for branch in (1, -1):
        pose = FourBar(10, 40, 30, 35, branch=branch).solve(theta)
        assert pose.valid.all()
        np.testing.assert_allclose(abs(pose.C - pose.B), 40, rtol=0, atol=1e-12)
        np.testing.assert_allclose(abs(pose.C - 35), 30, rtol=0, atol=1e-12)
        cross = ((35 - pose.B).conj() * (pose.C - pose.B)).imag
        assert np.all(np.sign(cross) == branch)




@settings(max_examples=60, deadline=None)
@given(st.floats(0.1, 1.0), st.lists(st.floats(1.05, 10.0), min_size=3, max_size=3),
       st.booleans(), st.sampled_from([1, -1]))
def test_solve_branch_continuity(shortest, scales, crank_is_ground, branch):
    """Along a full turn of a crank, C moves continuously and keeps its side of B->D.

    The shortest link is the crank (crank-rocker) or the ground (double-crank); the others
    are drawn so that the chain is Grashof and not a change point.
    """
    others = [shortest * k for k in scales]
    l_ = max(others)
    assume(shortest + l_ < sum(others) - l_ - 1e-6 * l_)
    if crank_is_ground:
        a, b, c, d = others[0], others[1], others[2], shortest
    else:
        a, b, c, d = shortest, others[0], others[1], others[2]
    theta = np.linspace(0, 2 * np.pi, 4001)
    pose = FourBar(a, b, c, d, branch=branch).solve(theta, order=1)
    assert pose.valid.all()
    step = np.abs(np.diff(pose.C))
    speed = np.abs(pose.vC)
    assert np.all(step <= 1.01 * np.maximum(speed[:-1], speed[1:]) * (theta[1] - theta[0]) + 1e-9 * l_)
    cross = ((d - pose.B).conj() * (pose.C - pose.B)).imag
    assert np.all(np.sign(cross) == branch)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.1, 10.0), st.floats(0.1, 10.0), st.floats(-4 * np.pi, 4 * np.pi))
def test_solve_change_point_parallelogram(a, b, theta):
    """A parallelogram stays a parallelogram through its change points; the other branch stays anti."""
    assume(abs(a - b) >= 1e-3 * max(a, b))
    thetas = np.array([theta, 0.0, np.pi, -np.pi, 2 * np.pi, theta + 1e-9])
    para = FourBar(a, b, a, b, branch=1).solve(thetas)
    np.testing.assert_allclose(para.C - para.B, b, rtol=0, atol=1e-12 * (a + b))
    anti = FourBar(a, b, a, b, branch=-1).solve(thetas)
    assert anti.valid.all()
    np.testing.assert_allclose(abs(anti.C - anti.B), b, atol=1e-12 * (a + b))
    # the vertices of an antiparallelogram form a trapezoid with AC parallel to BD
    np.testing.assert_allclose((anti.C.conj() * (b - anti.B)).imag, 0, atol=1e-11 * (a + b) ** 2)
    away = np.abs(np.sin(thetas)) > 1e-6
    assert np.all(np.abs(anti.C - anti.B - b)[away] > 1e-9 * (a + b))


def test_solve_change_point_parallelogram_rates():
    """Near (not at) a change point the parallelogram's rocker turns with the crank."""
    theta = np.array([1e-6, 0.5, np.pi - 1e-6, 4.0])
    pose = FourBar(2.0, 5.0, 2.0, 5.0).solve(theta, order=2, omega=3.0)
    np.testing.assert_allclose(pose.omega_output, 3.0, rtol=1e-8)
    np.testing.assert_allclose(pose.omega_coupler, 0.0, atol=1e-8)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_solve_broadcasting(shape):
    theta = np.random.default_rng(0).uniform(-3, 3, shape)
    pose = FourBar(1, 4, 3, 3.5, coupler=(1, 0.5)).solve(theta, order=2)
    for name in ("B", "C", "P", "phi", "psi", "valid", "omega_output", "vP", "alpha_coupler", "aC"):
        assert np.shape(getattr(pose, name)) == shape


def test_solve_order_zero_computes_no_rates():
    pose = FourBar(1, 4, 3, 3.5).solve(0.3)
    with pytest.raises(AttributeError, match="order=1"):
        pose.omega_output
    with pytest.raises(AttributeError, match="order=2"):
        FourBar(1, 4, 3, 3.5).solve(0.3, order=1).aP


def test_solve_phi_psi_atan2():
    pose = FourBar(10, 40, 30, 35).solve(1.0)
    assert np.isclose(40 * np.exp(1j * pose.phi), pose.C - pose.B)
    assert np.isclose(30 * np.exp(1j * pose.psi), pose.C - 35)


def test_solve_unassemblable_gives_nan_and_strict_raises():
    linkage = FourBar(3, 2, 2.5, 4)  # triple-rocker: the crank cannot reach theta = pi
    pose = linkage.solve([0.0, np.pi])
    assert pose.valid.tolist() == [True, False]
    assert np.isnan(pose.C[1]) and np.isfinite(pose.C[0])
    with pytest.raises(AssemblyError, match="theta = 3.14159"):
        linkage.solve([0.0, np.pi], strict=True)


@pytest.mark.parametrize(
    "args, match",
    [((0, 4, 3, 3.5), "Expected `a` > 0, got 0.0"),
     ((1, -4, 3, 3.5), "Expected `b` > 0, got -4.0"),
     ((1, 4, 3, 9), "Expected `d` shorter than the other three"),
     ((1, 4, float("nan"), 3.5), "Expected `c` > 0, got nan")],
)
def test_fourbar_bad_lengths(args, match):
    with pytest.raises(ValueError, match=match):
        FourBar(*args)


def test_fourbar_bad_options():
    with pytest.raises(ValueError, match="Expected `branch` to be \\+1 or -1, got 0"):
        FourBar(1, 4, 3, 3.5, branch=0)
    with pytest.raises(ValueError, match="Expected `coupler`"):
        FourBar(1, 4, 3, 3.5, coupler=(1,))
    linkage = FourBar(1, 4, 3, 3.5)
    with pytest.raises(ValueError, match="Expected finite `theta`, got nan"):
        linkage.solve([0.0, np.nan])
    with pytest.raises(ValueError, match="Expected `order` to be an integer in \\[0, 2\\], got 3"):
        linkage.solve(0.0, order=3)


def test_solve_change_point_kite_turns_twice():
    """The kite a = d < b = c (Fig. 2-5b, short link as ground): C stays on the bisector of
    angle BAD, so the long crank CD turns once while the short crank AB turns twice. At
    theta = 0 the crank pin sits on D; C there is the limit along the branch, C = a + b."""
    a, b = 1.0, 2.0
    theta = np.linspace(-4 * np.pi, 4 * np.pi, 2001)
    theta = theta[np.abs(np.sin(theta / 2)) > 1e-9]
    pose = FourBar(a, b, b, a).solve(theta)
    half = theta / 2
    expected = np.exp(1j * half) * (a * np.cos(half) + np.sqrt(b * b - (a * np.sin(half)) ** 2))
    np.testing.assert_allclose(pose.C, expected, atol=1e-12)
    turns = np.ptp(np.unwrap(pose.psi[theta > 0])) / (2 * np.pi)
    assert abs(turns - 1.0) < 0.01  # crank angle spans 4 pi (less the sample at 0)
    at_zero = FourBar(a, b, b, a).solve(0.0)
    assert at_zero.valid and abs(at_zero.C - (a + b)) <= 1e-15 * (a + b)
