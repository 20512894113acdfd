"""The RCCC by transference against an independent H-D closure at 50 digits."""

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.spatial._rccc import RCCC
from mech.spherical._transference import dual_fourbar_output

RNG = np.random.default_rng(7)
LINK = ((0.6, 0.2), (1.2, 0.5), (1.0, 0.1), (1.3, 0.4))


def _hd_mp(ph, la, s, h):
    cp, sp, cl, sl = mpmath.cos(ph), mpmath.sin(ph), mpmath.cos(la), mpmath.sin(la)
    return mpmath.matrix([[cp, -cl * sp, sl * sp, h * cp], [sp, cl * cp, -sl * cp, h * sp], [0, sl, cl, s], [0, 0, 0, 1]])


@pytest.mark.parametrize("branch", [1, -1])
def test_solve_output_against_mpmath_findroot_closure(branch):
    """Fix the computed output (phi41, S4); findroot on the closure for the middle pairs."""
    rccc = RCCC(*LINK, s1=0.3, branch=branch)
    for theta in RNG.uniform(-np.pi, np.pi, 3):
        pose = rccc.solve(theta)
        (a, a0), (b, b0), (c, c0), (d, d0) = LINK
        with mpmath.workdps(50):
            def closure(p23, s2, p34, s3):
                M = (_hd_mp(theta, a, 0.3, a0) * _hd_mp(p23, b, s2, b0) * _hd_mp(p34, c, s3, c0)
                     * _hd_mp(pose.phi41, d, pose.s4, d0))
                return M - mpmath.eye(4)
            start = (pose.phi23 + 1e-3, pose.s2 - 1e-3, pose.phi34 + 1e-3, pose.s3 + 1e-3)
            sol = mpmath.findroot(lambda *z: [closure(*z)[i, j] for i, j in ((0, 2), (1, 2), (0, 3), (1, 3))], start)
            assert float(mpmath.mnorm(closure(*sol), 1)) < 1e-12
            assert max(abs(float(x) - y) for x, y in zip(sol, (pose.phi23, pose.s2, pose.phi34, pose.s3))) < 1e-12


def test_solve_closed_form_equals_dual_route():
    rccc = RCCC(*LINK, s1=-0.7)
    theta = np.linspace(-np.pi, np.pi, 41)
    pose = rccc.solve(theta)
    out = dual_fourbar_output(*LINK, (theta - np.pi, -0.7))
    assert np.max(np.abs(pose.s4 + out.dual_part)) < 1e-12
    assert np.max(np.abs(np.angle(np.exp(1j * (pose.phi41 + out.real_part))))) < 1e-13


def test_solve_rates_against_mpmath_diff():
    rccc = RCCC(*LINK, s1=0.3)
    pose = rccc.solve(np.array([0.4, 2.0, -1.3]), order=1, omega=2.5)
    for i, th in enumerate((0.4, 2.0, -1.3)):
        f_angle = lambda t: mpmath.mpf(float(rccc.solve(float(t)).phi41))
        f_slide = lambda t: mpmath.mpf(float(rccc.solve(float(t)).s4))
        d_angle = mpmath.diff(f_angle, th, h=1e-5) * 2.5
        d_slide = mpmath.diff(f_slide, th, h=1e-5) * 2.5
        assert abs(pose.omega_output[i] - float(d_angle)) < 1e-7
        assert abs(pose.v_output[i] - float(d_slide)) < 1e-7


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_solve_broadcast_shape(shape):
    pose = RCCC(*LINK).solve(np.zeros(shape), order=1)
    assert pose.s4.shape == shape and pose.v_output.shape == shape


def test_solve_strict_raises_assembly_error():
    rccc = RCCC((0.3, 0.0), (0.2, 0.0), (1.0, 0.0), (1.4, 0.0))
    assert not rccc.solve(0.0).valid and rccc.solve(np.pi).valid
    with pytest.raises(AssemblyError, match="theta = 0.0"):
        rccc.solve([np.pi, 0.0], strict=True)


def test_rccc_bad_twist():
    with pytest.raises(ValueError, match="Expected the twist of `c`"):
        RCCC((0.5, 0), (1, 0), (0.0, 1), (1, 0))
