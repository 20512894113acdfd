"""Tests of the class III six-bar of example 2-6 (`TriadSixBar`).

References: the loop lengths themselves, mpmath at 50 digits (Newton on the same three
distances from a different unknown set, the three rocker/rod angles, then numerical
derivatives in theta), and the instant centres by Kennedy's theorem.
"""

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.planar.kinematics._instant_centres import instant_centres, centre_velocities
from mech.planar.kinematics._triad import TriadSixBar

CLAMP = dict(a=10, b=60, cd=36, ce=36, angle=-np.pi / 2, g=40, f=40, G=118 + 41j, F=91 - 48j)
START = (60 + 10j, np.pi / 3)


def _clamp():
    return TriadSixBar(**CLAMP)


def test_triad_solve_closes_every_loop():
    theta = np.linspace(np.pi / 2, np.pi / 2 + 2 * np.pi, 73)
    pose = _clamp().solve(theta, START)
    assert pose.valid.all() and pose.iterations.max() < 10
    for got, want in ((abs(pose.C - pose.B), 60), (abs(pose.D - 118 - 41j), 40), (abs(pose.E - 91 + 48j), 40),
                      (abs(pose.D - pose.C), 36), (abs(pose.E - pose.C), 36)):
        np.testing.assert_allclose(got, want, rtol=1e-14)
    turn = np.angle((pose.E - pose.C) / (pose.D - pose.C))
    np.testing.assert_allclose(turn, -np.pi / 2, rtol=1e-14)


def _mp_angles(theta, guess):
    """(phi_2, phi_4, phi_5) at 50 digits: B + b e^{i phi2} = C, D = G + g e^{i phi4}, ..."""
    a, b, cd, ce, g, f = (mpmath.mpf(CLAMP[k]) for k in ("a", "b", "cd", "ce", "g", "f"))
    G, F = mpmath.mpc(118, 41), mpmath.mpc(91, -48)

    def eqs(p2, p4, p5):
        B = a * mpmath.expj(theta)
        C = B + b * mpmath.expj(p2)
        D = G + g * mpmath.expj(p4)
        E = F + f * mpmath.expj(p5)
        # D - C has length cd and E - C = (D - C) * (ce / cd) * e^{-i pi/2}
        return [abs(D - C) ** 2 - cd**2, *(mpmath.re(x) for x in [E - C + 1j * (D - C) * ce / cd]),
                mpmath.im(E - C + 1j * (D - C) * ce / cd)]

    return mpmath.findroot(lambda *p: eqs(*p)[:1] + eqs(*p)[1:], guess, tol=mpmath.mpf(10) ** -45)


@pytest.mark.parametrize("theta", [np.pi / 2, 2.5, 4.0, 5.5])
def test_triad_velocities_against_mpmath(theta):
    pose = _clamp().solve(np.linspace(np.pi / 2, theta, 20), START, omega=1.0)
    guess = [float(pose.phi[-1, 1]), float(pose.phi[-1, 3]), float(pose.phi[-1, 4])]
    with mpmath.workdps(50):
        t = mpmath.mpf(float(theta))
        ref = _mp_angles(t, guess)
        for k, got in zip(range(3), (pose.phi[-1, 1], pose.phi[-1, 3], pose.phi[-1, 4])):
            assert abs(float(ref[k]) - got) < 1e-12
        rates = [mpmath.diff(lambda s, k=k: _mp_angles(s, [float(v) for v in ref])[k], t) for k in range(3)]
    np.testing.assert_allclose(pose.omega[-1, [1, 3, 4]], [float(r) for r in rates], rtol=1e-10, atol=1e-13)


def test_example_2_6_instant_centres_match_triad_velocities():
    clamp = _clamp()
    theta = np.linspace(np.pi / 2, np.pi / 2 + 2 * np.pi, 37)
    pose = clamp.solve(theta, START, omega=-2.0)
    centres = instant_centres(6, {(1, 6): 0j * pose.B, (1, 2): pose.B, (2, 3): pose.C, (3, 4): pose.D,
                                  (3, 5): pose.E, (4, 6): clamp.G + 0 * pose.B, (5, 6): clamp.F + 0 * pose.B})
    rounds = {step.pair: step.round for step in centres.construction}
    assert rounds[3, 6] < rounds[2, 6]           # P36 first, then P26 (the textbook's order)
    motion = centre_velocities(centres, frame=6, driver=1, omega=-2.0)
    for link in (2, 3, 4, 5):
        np.testing.assert_allclose(motion.omega[link], pose.omega[:, link - 1], rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(motion.point_velocity(3, pose.E), pose.vE, rtol=1e-10, atol=1e-10)


def test_triad_strict_raises_when_it_cannot_assemble():
    far = TriadSixBar(**{**CLAMP, "a": 45})
    with pytest.raises(AssemblyError, match="theta = "):
        far.solve(np.linspace(np.pi / 2, 2 * np.pi + np.pi / 2, 90), START, strict=True)
    pose = far.solve(np.linspace(np.pi / 2, 2 * np.pi + np.pi / 2, 90), START)
    assert not pose.valid.all() and np.isnan(pose.C[~pose.valid]).all()


def test_triad_input_errors():
    with pytest.raises(ValueError, match="`g` > 0"):
        TriadSixBar(**{**CLAMP, "g": -1.0})
    with pytest.raises(ValueError, match="finite `G`"):
        TriadSixBar(**{**CLAMP, "G": complex(np.nan, 0)})
