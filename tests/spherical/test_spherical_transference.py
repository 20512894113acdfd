"""Dual numbers and the transference principle (deriv-spherical-transference)."""

import re

import mpmath
import numpy as np
import pytest

from mech._generated import one_equation as abc
from mech.spatial import RSSR
from mech.spherical._dual import Dual, dual
from mech.spherical._transference import dual_fourbar_joints, dual_fourbar_output, rssr_from_transference

RNG = np.random.default_rng(20260505)


@pytest.mark.parametrize(
    "npf, mpf",
    [(np.cos, mpmath.cos), (np.sin, mpmath.sin), (np.tan, mpmath.tan), (np.arctan, mpmath.atan),
     (np.sqrt, mpmath.sqrt), (np.exp, mpmath.exp), (np.log, mpmath.log),
     (lambda z: z * z * z - 2.0 / z, lambda z: z**3 - 2 / z), (lambda z: z**1.5, lambda z: z**1.5)],
)
def test_dual_function_rule_against_mpmath_diff(npf, mpf):
    """f(x + eps y) has the dual part y f'(x); f' by mpmath.diff at 50 digits."""
    x, y = RNG.uniform(0.2, 1.4, 7), RNG.uniform(-2, 2, 7)
    got = npf(Dual(x, y))
    with mpmath.workdps(50):
        for xi, yi, re, du in zip(x, y, got.real_part, got.dual_part):
            assert abs(re - float(mpf(mpmath.mpf(xi)))) < 1e-14 * max(1, abs(re))
            assert abs(du - float(yi * mpmath.diff(mpf, mpmath.mpf(xi)))) < 1e-13 * max(1, abs(du))


def test_dual_atan2_and_quotient_against_mpmath_diff():
    x, y, x0, y0 = RNG.uniform(-2, 2, (4, 9))
    got = np.arctan2(Dual(y, y0), Dual(x, x0))
    q = Dual(y, y0) / Dual(x, x0)
    with mpmath.workdps(50):
        for i in range(9):
            f = lambda t: mpmath.atan2(y[i] + t * y0[i], x[i] + t * x0[i])
            g = lambda t: (y[i] + t * y0[i]) / (x[i] + t * x0[i])
            assert abs(got.dual_part[i] - float(mpmath.diff(f, 0))) < 1e-12
            assert abs(q.dual_part[i] - float(mpmath.diff(g, 0))) < 1e-12 * max(1, abs(q.dual_part[i]))


def test_dual_eps_squared_is_zero_and_immutable():
    e = dual(0.0, 1.0)
    assert (e * e).real_part == 0 and (e * e).dual_part == 0
    with pytest.raises(AttributeError):
        e.real_part = 1.0
    with pytest.raises(ValueError):
        e.dual_part[...] = 2.0


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_dual_broadcast_shape(shape):
    x = Dual(np.ones(shape), 2.0)
    assert (np.sin(x) * 3.0 + np.arange(1)[0]).shape == shape


def test_dual_unsupported_ufunc_raises():
    with pytest.raises(TypeError, match="Expected a ufunc"):
        np.floor(dual(1.0, 1.0))


def _random_linkage():
    while True:
        arcs = RNG.uniform(0.3, 2.8, 4)
        A, B, C = abc.spherical_fourbar_abc(*arcs, np.linspace(0, 2 * np.pi, 60))
        if np.all(abc.abc_discriminant(A, B, C) > 1e-2):
            return arcs, RNG.uniform(-2, 2, 4), RNG.uniform(-1, 1)


@pytest.mark.parametrize("branch", [1, -1])
def test_dual_fourbar_output_real_part_is_spherical_fourbar(branch):
    """Real part of the dual computation = the spherical four-bar's root, checked by dot products."""
    for _ in range(5):
        arcs, lengths, s1 = _random_linkage()
        theta = np.linspace(-np.pi, np.pi, 31)
        out = dual_fourbar_output(*zip(arcs, lengths), (theta, s1), branch=branch)
        a, b, c, d = arcs
        B = np.stack([np.sin(a) * np.cos(theta), np.sin(a) * np.sin(theta), np.full_like(theta, np.cos(a))], -1)
        Dv = np.array([np.sin(d), 0.0, np.cos(d)])
        t1, t2 = np.array([np.cos(d), 0.0, -np.sin(d)]), np.array([0.0, 1.0, 0.0])
        p = out.real_part[:, None]
        C = np.cos(c) * Dv + np.sin(c) * (np.cos(p) * t1 + np.sin(p) * t2)
        assert np.max(np.abs(np.sum(B * C, -1) - np.cos(b))) < 1e-13
        det = np.linalg.det(np.stack([B, np.broadcast_to(Dv, B.shape), C], -1))
        assert np.all(np.sign(det) == branch)


def _hd_mp(ph, la, s, h):
    cp, sp, cl, sl = mpmath.cos(ph), mpmath.sin(ph), mpmath.cos(la), mpmath.sin(la)
    return mpmath.matrix([[cp, -cl * sp, sl * sp, h * cp], [sp, cl * cp, -sl * cp, h * sp], [0, sl, cl, s], [0, 0, 0, 1]])


def test_dual_fourbar_joints_close_the_hd_loop():
    """All four dual joint angles close M12 M23 M34 M41 = I at 50 digits (mpmath H-D matrices)."""
    for _ in range(4):
        arcs, lengths, s1 = _random_linkage()
        th = RNG.uniform(-np.pi, np.pi)
        psi = dual_fourbar_output(*zip(arcs, lengths), (th, s1))
        p23, p34 = dual_fourbar_joints(*zip(arcs[[0, 2, 3]], lengths[[0, 2, 3]]), (th, s1), psi)
        p23 = tuple(map(float, (p23.real_part, p23.dual_part)))
        p34 = tuple(map(float, (p34.real_part, p34.dual_part)))
        ps = tuple(map(float, (psi.real_part, psi.dual_part)))
        with mpmath.workdps(50):
            M = (_hd_mp(th + mpmath.pi, arcs[0], s1, lengths[0]) * _hd_mp(p23[0], arcs[1], p23[1], lengths[1])
                 * _hd_mp(p34[0], arcs[2], p34[1], lengths[2])
                 * _hd_mp(-ps[0], arcs[3], -ps[1], lengths[3]))
            assert float(mpmath.mnorm(M - mpmath.eye(4), 1)) < 1e-12


@pytest.mark.parametrize("branch", [1, -1])
def test_rssr_from_transference_matches_rssr(branch):
    """The RSSR by its dual quadrilateral of lines against mech.spatial.RSSR, full turn."""
    checked = 0
    for _ in range(12):
        dims = (*RNG.uniform(0.5, 3, 3), *RNG.uniform(-2, 2, 3), RNG.uniform(0.1, 3.0))
        phi = np.linspace(-np.pi, np.pi, 73)
        ref = RSSR(*dims, branch=branch).solve(phi).phi03
        got = rssr_from_transference(*dims, phi, branch=branch)
        ok = np.isfinite(ref) & (RSSR(*dims).discriminant(phi) > 1e-6)
        assert np.array_equal(np.isfinite(got)[ok], np.isfinite(ref)[ok])
        if ok.any():
            assert np.max(np.abs(np.angle(np.exp(1j * (got[ok] - ref[ok]))))) < 1e-12
            checked += 1
    assert checked >= 4


def test_rssr_from_transference_bad_length():
    with pytest.raises(ValueError, match="Expected `l2` > 0"):
        rssr_from_transference(1.0, -4.0, 2.0, 0.5, 0.8, 3.0, 1.0, 0.0)


def test_dual_fourbar_output_bad_twist():
    with pytest.raises(ValueError, match="Expected `b_hat`"):
        dual_fourbar_output((0.5, 0), (3.5, 0), (1, 0), (1, 0), 0.0)


@pytest.mark.parametrize("scale", [1e-300, 1e-154, 1e154, 1e300])
def test_rssr_from_transference_any_unit_of_length(scale):
    """Squares of lengths 1e+-300 left the float range: every angle came back NaN. The
    reference is the RSSR's own solver, which shares no code with the dual route."""
    theta = np.linspace(-3.0, 3.0, 13)
    lengths = np.array([1.0, 4.0, 2.0, 0.5, 0.8, 3.0])
    want = RSSR(*lengths, 1.0).solve(theta).phi03
    got = rssr_from_transference(*(lengths * scale), 1.0, theta)
    np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
    np.testing.assert_allclose(got, want, atol=1e-12)


@pytest.mark.parametrize("lengths", [(1e-300, 4.0, 2.0, 0.5, 0.8, 3.0), (1.0, 1e300, 2.0, 0.5, 0.8, 3.0),
                                     (1.0, 4.0, 2.0, 0.5, 0.8, 1e154)])
def test_rssr_from_transference_extreme_ratio_named_like_rssr(lengths):
    """Divided by l1 l3 beside a far longer link, squares overflowed with RuntimeWarnings;
    the check and the message are those of `RSSR`."""
    with pytest.raises(ValueError, match="Expected `l1` \\* `l3` >= 2\\*\\*-500"):
        RSSR(*lengths, 1.0)
    with pytest.raises(ValueError, match="Expected `l1` \\* `l3` >= 2\\*\\*-500"):
        rssr_from_transference(*lengths, 1.0, [0.0, 1.0])


@pytest.mark.parametrize("a", [1e-12, 1e-150, 1e-300])
def test_dual_fourbar_joints_nearly_parallel_axes_named(a):
    """Twist a -> 0 with offset 0.2: the dual part of phi23 tends to -0.3331155369 (mpmath,
    120 digits, central differences of the real four-bar in each argument, a = 1e-4 ... 1e-50);
    floating point returned 3.6e283 at a = 1e-300. Where rounding swamps it: a named error."""
    args = (a, 0.2), (1.0, 0.1), (1.3, 0.4), (0.5, 0.3)
    psi = dual_fourbar_output(args[0], (1.2, 0.5), *args[1:])
    with pytest.raises(ValueError, match=r"Expected `a_hat`, .* axes A and B .*a_hat=\(" + re.escape(repr(a))):
        dual_fourbar_joints(*args, psi)


def test_dual_fourbar_joints_small_twist_matches_mpmath():
    args = (1e-8, 0.2), (1.0, 0.1), (1.3, 0.4), (0.5, 0.3)
    psi = dual_fourbar_output(args[0], (1.2, 0.5), *args[1:])
    p23, p34 = dual_fourbar_joints(*args, psi)
    # the mpmath reference of the test above, at a = 1e-8
    assert float(p23.dual_part) == pytest.approx(-0.3331155416, abs=1e-8)
    assert float(p34.dual_part) == pytest.approx(-0.06073532135, abs=1e-9)
