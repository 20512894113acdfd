"""Exercise 2-29 (function generation through three pairs of positions), generated solution.

The expected lengths come from the textbook's graphical method done at 30 digits: the
frame turned back about D by the output rotation (inversion, F86), the moving pivot C1 as
the circumcentre of B1, B2', B3', with B1 slid along its line until C1 falls on the line
of DC1. No Freudenstein equation is used.
"""

import math

import mpmath
import numpy as np
import pytest

from mech.exercises.chapter2_synthesis import EXERCISE_2_29, design_2_29
from mech.planar import FourBar


def _circumcentre(p, q, r):
    a, b = q - p, r - p
    den = 2 * (a.real * b.imag - a.imag * b.real)
    ux = (b.imag * abs(a) ** 2 - a.imag * abs(b) ** 2) / den
    uy = (a.real * abs(b) ** 2 - b.real * abs(a) ** 2) / den
    return p + mpmath.mpc(ux, uy)


def _graphical(phi_deg, psi_deg, d, guess):
    with mpmath.workdps(30):
        phi = [mpmath.radians(v) for v in phi_deg]
        psi = [mpmath.radians(v) for v in psi_deg]
        d = mpmath.mpf(d)

        def centre(s):
            B = [s * mpmath.expj(f) for f in phi]
            Bp = [d + (B[i] - d) * mpmath.expj(-(psi[i] - psi[0])) for i in range(3)]
            return _circumcentre(*Bp)

        def off_line(s):          # C1 - D must be parallel to exp(i psi1)
            C1 = centre(s)
            return ((C1 - d) * mpmath.expj(-psi[0])).imag

        s = mpmath.findroot(off_line, guess)
        C1 = centre(s)
        return float(abs(s)), float(abs(C1 - s * mpmath.expj(phi[0]))), float(abs(C1 - d))


def test_exercise_2_29_lengths_by_graphical_inversion():
    s = EXERCISE_2_29.solve()
    want = _graphical((60, 90, 120), (30, 50, 80), 100, -240)
    got = [float(s[k].value) for k in ("l_AB", "l_BC", "l_CD")]
    assert np.allclose(got, want, rtol=1e-10)
    assert np.allclose(got, [245.948, 82.0333, 262.127], atol=1e-3)
    assert s["AB points opposite to phi"].value and s["DC points opposite to psi"].value


def test_exercise_2_29_interior_reading_by_graphical_inversion():
    s = EXERCISE_2_29.solve()
    want = _graphical((60, 90, 120), (150, 130, 100), 100, -40)
    got = [float(s[k].value) for k in ("l_AB (psi interior at D)", "l_BC (psi interior at D)",
                                       "l_CD (psi interior at D)")]
    assert np.allclose(got, want, rtol=1e-10)


def test_exercise_2_29_design_reproduces_the_positions():
    """FourBar built from the reported lengths alone (not the design object) meets the pairs."""
    s = EXERCISE_2_29.solve()
    a, b, c, d = (float(s[k].value) for k in ("l_AB", "l_BC", "l_CD", "l_AD"))
    phi = np.radians([60.0, 90.0, 120.0]) + np.pi           # AB reversed
    psi = np.radians([30.0, 50.0, 80.0]) + np.pi           # DC reversed
    pose = FourBar(a, b, c, d, branch=int(s["assembly branch"].value)).solve(phi, strict=True)
    assert np.max(np.abs(np.angle(np.exp(1j * (pose.psi - psi))))) < 1e-9
    assert float(s["largest output error at the three positions"].value) < 1e-12


@pytest.mark.parametrize("seed", [0, 1, 2, 7, 11])
def test_exercise_2_29_variants_meet_their_pairs(seed):
    p = EXERCISE_2_29.variant(seed)
    g = design_2_29(p)
    assert g.pair_error < 1e-9 and g.covers_range
    s = EXERCISE_2_29.solve(p)
    assert "Assumed layout" in s.as_markdown()


def test_exercise_2_29_bad_givens():
    with pytest.raises(ValueError, match="Expected `AD` > 0"):
        EXERCISE_2_29.solve(AD=-1.0)
    with pytest.raises(ValueError, match="Expected distinct `x`"):
        EXERCISE_2_29.solve(phi2=60.0)


def test_givens_without_a_carrying_branch_are_shown():
    """The message said "got one that does not" without the givens that failed."""
    import mech.exercises as ex

    with pytest.raises(ValueError, match=r"Expected `phi1`, .* whose design one branch carries .*phi1=0\.0"):
        ex.get("2-29").solve(phi1=0.0)
