"""Function generation with the spherical four-bar (deriv-spherical-function-generation).

Expected values come from other routes: the linkage is re-assembled at 50 digits by
intersecting two small circles (not the Freudenstein equation), the coefficients are
evaluated from their definitions in mpmath, Chebyshev nodes are NumPy's roots of T_n, and
the planar limit is compared with a planar Freudenstein solve written here.
"""

import mpmath
import numpy as np
import pytest

from mech.spherical._function_generation import (
    arcs_from_coefficients,
    chebyshev_spacing,
    freudenstein_coefficients,
    least_squares,
    precision_pairs,
)

# The standard example: y = log10(u), u in [1, 10]; the input turns 90 deg, the output 60 deg.
SPAN_IN, SPAN_OUT = np.radians(90.0), np.radians(60.0)
THETA0, PSI0 = np.radians(-120.0), np.radians(-70.0)


def log_pairs(u):
    return SPAN_IN * (u - 1.0) / 9.0, SPAN_OUT * np.log10(u)


REFERENCE = log_pairs(np.linspace(1.0, 10.0, 401))


def chebyshev_log_pairs(n):
    return log_pairs(chebyshev_spacing(1.0, 10.0, n))


def output_by_small_circles(arcs, theta, branch):
    """psi at 50 digits: C on the circles of arc b about B and arc c about D (det[B, D, C] sign = branch)."""
    with mpmath.workdps(50):
        a, b, c, d = (mpmath.mpf(float(v)) for v in arcs)
        th = mpmath.mpf(float(theta))
        B = mpmath.matrix([mpmath.sin(a) * mpmath.cos(th), mpmath.sin(a) * mpmath.sin(th), mpmath.cos(a)])
        D = mpmath.matrix([mpmath.sin(d), 0, mpmath.cos(d)])
        m = (B.T * D)[0]
        alpha = (mpmath.cos(b) - m * mpmath.cos(c)) / (1 - m**2)
        beta = (mpmath.cos(c) - m * mpmath.cos(b)) / (1 - m**2)
        n = mpmath.matrix([B[1] * D[2] - B[2] * D[1], B[2] * D[0] - B[0] * D[2], B[0] * D[1] - B[1] * D[0]])
        n2 = (n.T * n)[0]
        gamma2 = (1 - alpha**2 - beta**2 - 2 * alpha * beta * m) / n2
        assert gamma2 > 0, "not assembled"
        C = alpha * B + beta * D + branch * mpmath.sqrt(gamma2) * n
        t1 = mpmath.matrix([mpmath.cos(d), 0, -mpmath.sin(d)])
        return float(mpmath.atan2(C[1], (C.T * t1)[0]))


def assert_meets_pairs(design, x, y, tol=1e-10):
    for xi, yi in zip(x, y):
        psi = output_by_small_circles(design.arcs, design.theta0 + xi, design.branch)
        err = np.angle(np.exp(1j * (psi - design.psi0 - yi)))
        assert abs(err) < tol, (xi, yi, err)


def test_freudenstein_coefficients_mpmath():
    arcs = (0.4, 0.9, 0.7, 1.0)
    with mpmath.workdps(50):
        a, b, c, d = (mpmath.mpf(v) for v in arcs)
        want = [mpmath.cos(d), mpmath.sin(d) * mpmath.cot(a), mpmath.sin(d) * mpmath.cot(c),
                (mpmath.cos(b) - mpmath.cos(a) * mpmath.cos(c) * mpmath.cos(d)) / (mpmath.sin(a) * mpmath.sin(c))]
    np.testing.assert_allclose(freudenstein_coefficients(*arcs), [float(w) for w in want], rtol=1e-14)


@pytest.mark.parametrize("arcs", [(0.4, 0.9, 0.7, 1.0), (2.5, 0.3, 2.9, 0.2), (1.2, 2.0, 2.4, 0.8)])
def test_arcs_from_coefficients_roundtrip(arcs):
    np.testing.assert_allclose(arcs_from_coefficients(*freudenstein_coefficients(*arcs)), arcs, rtol=1e-12)


def test_arcs_from_coefficients_no_linkage():
    with pytest.raises(ValueError, match=r"Expected \|`k1`\| < 1"):
        arcs_from_coefficients(1.2, 0.5, 0.5, 0.5)
    with pytest.raises(ValueError, match="Expected `k1` .. `k4` with \\|cos b\\| < 1"):
        arcs_from_coefficients(0.5, 0.1, 0.1, 5.0)


def test_freudenstein_coefficients_bad_arc():
    with pytest.raises(ValueError, match=r"Expected `c` in \(0, pi\), got 3.5"):
        freudenstein_coefficients(0.4, 0.9, 3.5, 1.0)
    with pytest.raises(ValueError, match=r"Expected `a` in \(0, pi\), got -0.4"):
        freudenstein_coefficients(-0.4, 0.9, 0.5, 1.0)


@pytest.mark.parametrize("n", [1, 3, 6])
def test_chebyshev_spacing_roots_of_chebyshev_polynomial(n):
    roots = np.sort(np.polynomial.Chebyshev.basis(n).roots())
    np.testing.assert_allclose(chebyshev_spacing(1.0, 10.0, n), 5.5 + 4.5 * roots, rtol=1e-13)


def test_chebyshev_spacing_bad_input():
    with pytest.raises(ValueError, match="Expected `x1` > `x0`"):
        chebyshev_spacing(2.0, 1.0, 3)
    with pytest.raises(ValueError, match="Expected `n`"):
        chebyshev_spacing(0.0, 1.0, 0)


@pytest.mark.parametrize("n, given", [(3, dict(theta0=THETA0, psi0=PSI0, d=2.31)),
                                      (4, dict(theta0=THETA0, psi0=PSI0)),
                                      (5, dict(psi0=PSI0)),
                                      (6, dict())])
def test_precision_pairs_log10_meets_every_pair(n, given):
    x, y = chebyshev_log_pairs(n)
    designs = precision_pairs(x, y, reference=REFERENCE, **given)
    assert designs
    for design in designs:
        assert design.defect is None
        assert np.all(np.isfinite(design.structural_error(*REFERENCE)))
        assert_meets_pairs(design, x, y)


def test_precision_pairs_three_family_in_d():
    """The one-parameter family: every d gives a linkage through the three pairs."""
    x, y = chebyshev_log_pairs(3)
    for d in (2.2, 2.31, 2.4):
        design, = precision_pairs(x, y, theta0=THETA0, psi0=PSI0, d=d)
        assert design.arcs[3] == pytest.approx(d, rel=1e-14)
        assert_meets_pairs(design, x, y)


@pytest.mark.parametrize("n, given", [(4, ("theta0", "psi0")), (5, ("theta0",)), (5, ("psi0",)), (6, ())])
def test_precision_pairs_recovers_known_linkage(n, given):
    """Pairs taken from a simulated linkage: the synthesis must find that linkage again."""
    arcs, theta0, psi0, branch = (0.5, 1.1, 0.8, 1.0), 0.6, 1.2, 1
    x = np.linspace(0.0, 1.2, n)
    y = np.array([output_by_small_circles(arcs, theta0 + xi, branch) for xi in x]) - psi0
    starts = {"theta0": theta0, "psi0": psi0}
    designs = precision_pairs(x, y, **{k: starts[k] for k in given})
    match = [g for g in designs if np.allclose(g.arcs, arcs, atol=1e-9)]
    assert len(match) == 1
    g = match[0]
    assert g.branch == branch
    assert np.angle(np.exp(1j * (g.theta0 - theta0))) == pytest.approx(0.0, abs=1e-9)
    assert np.angle(np.exp(1j * (g.psi0 - psi0))) == pytest.approx(0.0, abs=1e-9)
    for design in designs:
        assert_meets_pairs(design, x, y, tol=1e-9)


def test_precision_pairs_branch_defect():
    """Two pairs on each branch of one linkage: the unique 4-pair solution has a branch defect."""
    arcs, theta0, psi0 = (0.5, 1.1, 0.8, 1.0), 0.6, 1.2
    x = np.array([0.0, 0.3, 0.6, 0.9])
    branches = (1, 1, -1, -1)
    y = np.array([output_by_small_circles(arcs, theta0 + xi, s) for xi, s in zip(x, branches)]) - psi0
    with pytest.raises(ValueError, match="without branch or limit defect"):
        precision_pairs(x, y, theta0=theta0, psi0=psi0)
    design, = precision_pairs(x, y, theta0=theta0, psi0=psi0, keep_defective=True)
    assert design.defect == "branch"
    np.testing.assert_allclose(design.arcs, arcs, rtol=1e-10)


def test_precision_pairs_bad_counts():
    x, y = chebyshev_log_pairs(4)
    with pytest.raises(ValueError, match="Expected the ground arc `d` exactly for 3 pairs"):
        precision_pairs(x[:3], y[:3], theta0=THETA0, psi0=PSI0)
    with pytest.raises(ValueError, match="Expected 2 of `theta0`, `psi0` given for 4 pairs"):
        precision_pairs(x, y, theta0=THETA0)
    x7, y7 = chebyshev_log_pairs(7)
    with pytest.raises(ValueError, match="Expected at most 6 precision pairs"):
        precision_pairs(x7, y7)
    with pytest.raises(ValueError, match="Expected `x` and `y`"):
        precision_pairs(x, y[:3], theta0=THETA0, psi0=PSI0)


def test_precision_pairs_no_real_linkage():
    x, y = chebyshev_log_pairs(4)
    with pytest.raises(ValueError, match="that admit a real spherical four-bar"):
        precision_pairs(x, y, theta0=0.0, psi0=0.0)


def test_least_squares_not_worse_than_precision_pairs():
    """y = log10(u): the structural fit started at the 4-pair design never ends worse."""
    x, y = chebyshev_log_pairs(4)
    design, = precision_pairs(x, y, theta0=THETA0, psi0=PSI0, reference=REFERENCE)
    fit = least_squares(*REFERENCE, THETA0, PSI0, start=design)
    assert fit.rms_error <= design.rms_error
    assert fit.max_error < design.max_error
    linear = least_squares(*REFERENCE, THETA0, PSI0, kind="equation")
    assert fit.rms_error <= linear.rms_error * (1 + 1e-9)
    freed = least_squares(*REFERENCE, THETA0, PSI0, start=design, fit_start=True)
    assert freed.rms_error <= fit.rms_error
    sample = np.linspace(0.0, SPAN_IN, 7)
    want = [output_by_small_circles(freed.arcs, freed.theta0 + s, freed.branch) for s in sample]
    np.testing.assert_allclose(freed.output(sample), np.angle(np.exp(1j * (np.array(want) - freed.psi0))), atol=1e-12)


def test_least_squares_bad_kind():
    with pytest.raises(ValueError, match="Expected `kind`"):
        least_squares(*REFERENCE, THETA0, PSI0, kind="minimax")


def planar_freudenstein(alpha, phi, d):
    """Planar K1 cos(phi) - K2 cos(alpha) + K3 = cos(alpha - phi) at three pairs -> a, b, c."""
    K = np.linalg.solve(np.c_[np.cos(phi), -np.cos(alpha), np.ones(3)], np.cos(alpha - phi))
    a, c = d / K[0], d / K[1]
    return np.array([a, np.sqrt(a * a + c * c + d * d - 2 * a * c * K[2]), c])


def test_precision_pairs_planar_limit():
    """Three pairs with a short ground arc d = eps: arcs / eps tend to the planar design as eps^2."""
    x = np.radians([0.0, 30.0, 60.0])
    y = np.radians([0.0, 15.0, 40.0])
    theta0, psi0 = np.radians(60.0), np.radians(100.0)
    planar = planar_freudenstein(theta0 + x, psi0 + y, 1.0)
    assert np.all(planar > 0)
    errors = []
    for eps in (1e-1, 1e-2, 1e-3):
        design, = precision_pairs(x, y, theta0=theta0, psi0=psi0, d=eps, keep_defective=True)
        errors.append(np.max(np.abs(np.array(design.arcs[:3]) / eps - planar) / planar))
    assert errors[2] < 1e-5
    assert errors[1] < errors[0] / 50 and errors[2] < errors[1] / 50


def test_function_generator_fourbar_passes_the_pairs():
    """The SphericalFourBar handed back by a design meets every precision pair when solved
    by the four-bar's own (cancellation-free) route, not the synthesis equation."""
    from mech.spherical import SphericalFourBar

    u = chebyshev_spacing(1.0, 10.0, 4)
    x, y = np.radians(90.0) * (u - 1.0) / 9.0, np.radians(60.0) * np.log10(u)
    design = precision_pairs(x, y, theta0=np.radians(-120.0), psi0=np.radians(-70.0))[0]
    fourbar = design.fourbar
    assert isinstance(fourbar, SphericalFourBar)
    psi = fourbar.solve(design.theta0 + x, strict=True).psi
    miss = np.angle(np.exp(1j * (psi - (design.psi0 + y))))
    assert np.max(np.abs(miss)) < 1e-10
