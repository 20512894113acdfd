"""Function generation with the planar four-bar: mech.planar.synthesis (F85 to F94, Ex. 2-16).

Every design is checked by `FourBar.solve` (the analysis code), not by the design equations;
the coefficients and the textbook example are checked against mpmath computations by other
routes (circle intersection, the textbook's kinematic inversion (2-43) to (2-45)).
"""

import mpmath
import numpy as np
import pytest

from mech import InputTypeError
from mech.planar import FourBar
from mech.planar.synthesis import (
    FunctionGenerator,
    FunctionMap,
    chebyshev_spacing,
    freudenstein_coefficients,
    least_squares,
    lengths_from_coefficients,
    precision_pairs,
)

DEG = np.pi / 180.0


def _wrap(t):
    return np.arctan2(np.sin(t), np.cos(t))


def _mp_pose(lengths, theta, branch):
    """B and C (mpmath complex) by intersecting the circle (B, b) with the circle (D, c)."""
    a, b, c, d = (mpmath.mpf(v) for v in lengths)
    B = a * mpmath.expj(mpmath.mpf(theta))
    u = d - B                                   # B -> D
    k = abs(u)
    # foot of C on B->D at distance (b^2 - c^2 + k^2)/(2k) from B, height h to its left/right
    along = (b**2 - c**2 + k**2) / (2 * k)
    if b**2 - along**2 < 0:
        raise ValueError("not assembled")
    h = mpmath.sqrt(b**2 - along**2)
    C = B + u / k * (along + 1j * branch * h)
    return B, C


def _mp_psi(lengths, theta, branch):
    B, C = _mp_pose(lengths, theta, branch)
    return mpmath.arg(C - mpmath.mpf(lengths[3]))


# ----------------------------------------------------------------------------- coefficients
@pytest.mark.parametrize("lengths", [(10, 40, 30, 35), (2.0, 3.0, 2.5, 1.5), (0.7, 1.3, 1.1, 1.0)])
def test_freudenstein_coefficients_mpmath_loop_closure(lengths):
    """K from three poses assembled at 50 digits by circle intersection, solved as a linear
    system in mpmath: a route that never uses K = (d/a, d/c, ...)."""
    with mpmath.workdps(50):
        rows, rhs = [], []
        for theta in (0.3, 1.4, 2.6):
            B, C = _mp_pose(lengths, theta, 1)
            psi = mpmath.arg(C - lengths[3])
            rows.append([mpmath.cos(psi), -mpmath.cos(theta), 1])
            rhs.append(mpmath.cos(theta - psi))
        K = mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix(rhs))
    got = freudenstein_coefficients(*lengths)
    want = np.array([float(v) for v in K])
    assert np.max(np.abs(got - want) / np.abs(want)) < 1e-13


def test_lengths_from_coefficients_roundtrip_and_scale():
    for d in (1e-300, 1.0, 35.0, 1e300):
        k = freudenstein_coefficients(10 * d / 35, 40 * d / 35, 30 * d / 35, d)
        assert np.allclose(lengths_from_coefficients(*k, d=d) / d, np.array([10, 40, 30, 35]) / 35, rtol=1e-14)


def test_lengths_from_coefficients_negative_link_is_flipped():
    """(-a, theta + pi) is the same linkage: Freudenstein's equation holds for both."""
    a, b, c, d = lengths_from_coefficients(-2.0, 0.8, 0.4, d=1.0)
    assert a < 0 < c and b > 0
    assert np.isclose(a, -0.5) and np.isclose(c, 1.25)


@pytest.mark.parametrize("k", [(0.0, 1.0, 0.5), (1.0, 0.0, 0.5), (1.0, 1.0, 100.0)])
def test_lengths_from_coefficients_no_linkage(k):
    with pytest.raises(ValueError, match="Expected"):
        lengths_from_coefficients(*k)


# ----------------------------------------------------------------------------- precision pairs
def _random_task(rng):
    """Three pairs taken from a real four-bar at 50 digits (so an exact design exists)."""
    while True:
        lengths = rng.uniform(0.3, 2.0, 4)
        if np.max(lengths) >= np.sum(lengths) - np.max(lengths):
            continue
        branch = int(rng.choice([-1, 1]))
        theta = np.sort(rng.uniform(-np.pi, np.pi, 3))
        with mpmath.workdps(50):
            try:
                psi = [_mp_psi(lengths, t, branch) for t in theta]
            except (ValueError, ZeroDivisionError):
                continue
            psi = np.array([float(p) for p in psi])
        return lengths, branch, theta, psi


def test_precision_pairs_met_when_resolved_by_fourbar():
    """Forty random tasks: the design, re-solved by FourBar, meets its pairs to 1e-9 rad,
    recovers the lengths the pairs came from, and closes |C - B| = b at each pair."""
    rng = np.random.default_rng(29)
    worst = worst_len = 0.0
    for _ in range(40):
        lengths, branch, theta, psi = _random_task(rng)
        theta0, psi0 = theta[0] - 0.1, psi[0] + 0.2
        g, = precision_pairs(theta - theta0, psi - psi0, theta0=theta0, psi0=psi0, d=lengths[3])
        pose = g.fourbar.solve(g.input_angles)
        assert np.all(pose.valid)
        worst = max(worst, np.max(np.abs(_wrap(pose.psi - (psi0 + psi - psi0)))))
        worst_len = max(worst_len, np.max(np.abs(np.array(g.lengths) - lengths) / lengths))
        a, b, c, d = g.lengths
        B = a * np.exp(1j * g.input_angles)
        C = d + c * np.exp(1j * (g.psi0 + g.y))
        assert np.allclose(np.abs(C - B), b, rtol=1e-9)
        assert g.branch == branch
    assert worst < 1e-9 and worst_len < 1e-8


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1.0, 1e150, 1e300])
def test_precision_pairs_scale_invariant(scale):
    x = np.radians([0.0, 30.0, 60.0])
    y = np.radians([0.0, 20.0, 35.0])
    ref, = precision_pairs(x, y, theta0=np.radians(60.0), psi0=np.radians(30.0), d=1.0)
    g, = precision_pairs(x, y, theta0=np.radians(60.0), psi0=np.radians(30.0), d=scale)
    assert np.allclose(np.array(g.lengths) / scale, ref.lengths, rtol=1e-13)
    assert g.pair_error < 1e-12 and g.defect == ref.defect
    xs = np.linspace(0.0, np.radians(60.0), 9)
    ys = np.interp(xs, x, y)
    fit_ref = least_squares(xs, ys, theta0=np.radians(60.0), psi0=np.radians(30.0), d=1.0)
    fit = least_squares(xs, ys, theta0=np.radians(60.0), psi0=np.radians(30.0), d=scale)
    rms = lambda g: np.sqrt(np.mean(g.structural_error(xs, ys) ** 2))
    assert np.isclose(rms(fit), rms(fit_ref), rtol=1e-9, atol=0.0)
    # the optimum is flat along one direction of the lengths: the fit stops anywhere on it
    # to about 1e-6, at any scale; the objective above is what is reproduced
    assert np.allclose(np.array(fit.lengths) / scale, fit_ref.lengths, rtol=1e-4)


def test_precision_pairs_singular_system():
    with pytest.raises(ValueError, match="Expected distinct `x`"):
        precision_pairs([0.0, 0.0, 1.0], [0.0, 0.1, 0.2], theta0=0.5, psi0=1.0)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(x=[0, 1], y=[0, 1]), "Expected at least 3 pairs"),
        (dict(x=[0, 1, 2, 3], y=[0, 1, 2, 3]), "Expected 1 of `theta0`, `psi0` given for 4 pairs"),
        (dict(x=np.arange(6.0), y=np.arange(6.0)), "Expected at most 5"),
        (dict(x=[0, 1, 2], y=[0, 1]), "Expected `x` and `y`"),
        (dict(x=[0, 1, np.nan], y=[0, 1, 2]), "`x`"),
        (dict(d=-1.0), "Expected `d` > 0"),
        (dict(theta0="1"), "`theta0`"),
        (dict(psi0=1j), "`psi0`"),
        (dict(samples=1), "Expected `samples`"),
        (dict(x_range=(1.0, 0.0)), "Expected `x_range`"),
        (dict(target=3.0), "Expected `target`"),
    ],
)
def test_precision_pairs_errors_name_the_argument(kwargs, match):
    args = dict(x=[0.0, 0.5, 1.0], y=[0.0, 0.3, 0.5], theta0=1.0, psi0=2.0)
    args.update(kwargs)
    x, y = args.pop("x"), args.pop("y")
    with pytest.raises(ValueError, match=match):
        precision_pairs(x, y, **args)


def test_bad_types_are_input_type_errors():
    with pytest.raises(InputTypeError, match="`theta0`"):
        precision_pairs([0.0, 0.5, 1.0], [0.0, 0.3, 0.5], theta0=True, psi0=2.0)
    with pytest.raises(InputTypeError, match="`fit_start`"):
        least_squares([0.0, 0.5, 1.0], [0.0, 0.3, 0.5], theta0=1.0, psi0=2.0, fit_start=1)


def _random_five(rng):
    """Five pairs taken at 30 digits from a random four-bar on one branch."""
    while True:
        lengths = rng.uniform(0.3, 2.0, 4)
        if np.max(lengths) >= np.sum(lengths) - np.max(lengths):
            continue
        branch = int(rng.choice([-1, 1]))
        theta = np.sort(rng.uniform(-np.pi, np.pi, 5))
        try:
            with mpmath.workdps(30):
                psi = np.array([float(_mp_psi(lengths, t, branch)) for t in theta])
        except ValueError:
            continue
        return lengths, theta, psi


@pytest.mark.parametrize("unknown", ["theta0", "psi0", "both"])
def test_precision_pairs_free_start_angles_recover_the_linkage(unknown):
    """Four pairs with one start angle unknown, five with both (F88): among the designs is
    the linkage the pairs came from, and every design meets its pairs when re-solved by
    FourBar (or is flagged as not doing so)."""
    rng = np.random.default_rng({"theta0": 1, "psi0": 2, "both": 3}[unknown])
    for _ in range(25):
        lengths, theta, psi = _random_five(rng)
        n = 5 if unknown == "both" else 4
        given = {"theta0": dict(psi0=psi[0]), "psi0": dict(theta0=theta[0]), "both": {}}[unknown]
        x, y = theta[:n] - theta[0], psi[:n] - psi[0]
        designs = precision_pairs(x, y, d=lengths[3], **given)
        assert 1 <= len(designs) <= 3
        assert any(np.allclose(g.lengths, lengths, rtol=1e-7) for g in designs)
        for g in designs:
            pose = FourBar(*g.lengths, branch=g.branch).solve(g.input_angles)
            met = np.max(np.abs(_wrap(pose.psi - g.psi0 - y)))
            assert (met < 1e-9) == (g.defect != "branch")
            if unknown != "theta0":
                assert np.isclose(np.cos(g.theta0 - theta[0]) ** 2, 1.0) or unknown == "both"


# ----------------------------------------------------------------------------- example 2-16
def _chebyshev_reference(x0, x1, n):
    """F92 at 30 digits, written out per node."""
    with mpmath.workdps(30):
        return [float((x0 + x1) / mpmath.mpf(2) - (x1 - x0) / mpmath.mpf(2)
                      * mpmath.cos((2 * i - 1) * mpmath.pi / (2 * n))) for i in range(1, n + 1)]


def test_example_2_16_chebyshev_nodes():
    """Ex. 2-16 (§2.4 II): the text prints 1.603, 4.5, 8.397; F92 gives 1.60289, 5.5, 9.39711."""
    x = chebyshev_spacing(1.0, 10.0, 3)
    assert np.allclose(x, _chebyshev_reference(1.0, 10.0, 3), rtol=1e-15)
    assert np.allclose(x, [1.60289, 5.5, 9.39711], atol=5e-6)
    assert not np.isclose(x[1], 4.5)
    assert np.isclose(np.log10(8.397), 0.92412, atol=1e-5)      # the text prints 0.9211


def test_example_2_16_printed_design_misses_its_pairs():
    """The text's final linkage (118.066, 54.23, 168.269, 100), simulated at its own
    precision inputs, turns its output by 27.30 and 44.60 deg (or 11.13 and 41.99 on the
    other branch), not by the 22.41 and 35.96 deg asked."""
    alpha = np.radians([66.7, 98.89, 142.19])
    want = np.radians([272.66 - 250.25, 286.21 - 250.25])
    for branch in (1, -1):
        pose = FourBar(118.066, 54.23, 168.269, 100.0, branch=branch).solve(alpha)
        assert pose.valid.all()
        got = _wrap(pose.psi[1:] - pose.psi[0])
        assert np.max(np.abs(got - want)) > np.radians(5.0)


def _inversion_design(alpha, phi, d, guess):
    """The textbook's route (2-43) to (2-45) with reference pose 1, at 30 digits: B1 on the
    line through A at alpha_1 (signed distance s), C1 on the line through D at phi_1
    (signed distance t); |P_i1 B1 - C1| = |B1 - C1| for i = 2, 3. Returns signed a, b, c."""
    with mpmath.workdps(30):
        al = [mpmath.mpf(v) for v in alpha]
        ph = [mpmath.mpf(v) for v in phi]
        d = mpmath.mpf(d)

        def moved(i, s):
            t, p = (al[i] - al[0]) - (ph[i] - ph[0]), ph[i] - ph[0]
            x1, y1 = s * mpmath.cos(al[0]), s * mpmath.sin(al[0])
            return (mpmath.cos(t) * x1 - mpmath.sin(t) * y1 + d - d * mpmath.cos(p),
                    mpmath.sin(t) * x1 + mpmath.cos(t) * y1 + d * mpmath.sin(p))

        def equations(s, t):
            cx, cy = d + t * mpmath.cos(ph[0]), t * mpmath.sin(ph[0])
            bx, by = s * mpmath.cos(al[0]), s * mpmath.sin(al[0])
            base = (bx - cx) ** 2 + (by - cy) ** 2
            return [(moved(i, s)[0] - cx) ** 2 + (moved(i, s)[1] - cy) ** 2 - base for i in (1, 2)]

        s, t = mpmath.findroot(equations, guess)
        b = mpmath.sqrt((s * mpmath.cos(al[0]) - d - t * mpmath.cos(ph[0])) ** 2
                        + (s * mpmath.sin(al[0]) - t * mpmath.sin(ph[0])) ** 2)
        return float(s), float(b), float(t)


def test_example_2_16_book_pairs_catalog_values():
    """The text's own posed system (its nodes, 50-degree range): the independently recomputed
    a = -117.194 (B at alpha + 180), b = 102.473, c = 165.724, also by inversion."""
    alpha = np.radians([66.7, 98.89, 142.19])
    phi = np.radians([250.25, 272.66, 286.21])
    g, = precision_pairs(alpha - alpha[0], phi - phi[0], theta0=alpha[0], psi0=phi[0], d=100.0)
    s, b, t = _inversion_design(alpha, phi, 100.0, [-117.0, 165.0])
    assert np.allclose(g.lengths, [abs(s), b, abs(t), 100.0], rtol=1e-10)
    assert np.allclose(g.lengths[:3], [117.194, 102.473, 165.724], atol=5e-4)
    assert np.isclose(np.cos(g.theta0 - alpha[0]), -1.0)         # B points the other way
    assert g.pair_error < 1e-9


def test_example_2_16_corrected_textbook_setup():
    """Ex. 2-16 as stated, corrected: nodes by F92, 60-degree output range, start angles 60
    and 240 degrees. The exact design (pinned by the inversion route) cannot cover the
    input range: it cannot be assembled near x = 10."""
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, 60 * DEG)
    X, Y = m.rotations(chebyshev_spacing(1.0, 10.0, 3))
    assert np.allclose(np.degrees(60 * DEG + X), [66.6987, 110.0, 153.3013], atol=1e-4)
    assert np.allclose(np.degrees(240 * DEG + Y), [252.2942, 284.4218, 298.3797], atol=1e-4)
    g, = precision_pairs(X, Y, theta0=60 * DEG, psi0=240 * DEG, d=100.0, target=m)
    s, b, t = _inversion_design(60 * DEG + X, 240 * DEG + Y, 100.0, [-107.0, 142.0])
    assert np.allclose(g.lengths, [abs(s), b, abs(t), 100.0], rtol=1e-10)
    assert np.allclose(g.lengths[:3], [106.7952, 105.8297, 142.4020], atol=1e-4)
    assert g.pair_error < 1e-9
    assert g.defect == "limit" and not g.covers_range
    pose = g.solve(np.radians([0.0, 99.0, 100.0]))
    assert pose.valid.tolist() == [True, True, False]


def test_example_2_16_free_start_angles_cover_the_range():
    """With the start angles 40 and 245 degrees and the output turning clockwise (the
    independent recomputation), one branch covers 1 <= x <= 10 with max error 0.0066 in y."""
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    X, Y = m.rotations(chebyshev_spacing(1.0, 10.0, 3))
    g, = precision_pairs(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0, target=m)
    assert g.covers_range and g.monotone and g.defect is None
    assert np.allclose(g.lengths[:3], [89.3158, 118.8922, 67.7154], atol=1e-4)
    # the error in y from FourBar poses, against log10 directly
    x = np.linspace(1.0, 10.0, 2001)
    pose = g.solve(m.input_rotation(x))
    y_generated = m.output_value(_wrap(pose.psi - g.psi0))
    err = y_generated - np.log10(x)
    assert 0.0065 < np.max(np.abs(err)) < 0.0067
    assert np.allclose(g.errors(2001)[0] / abs(m.output_scale), np.max(np.abs(err)), rtol=1e-9)
    gamma, _ = g.min_transmission_angle
    assert np.isclose(np.degrees(gamma), 26.36, atol=0.01)


def _inversion_five(x, y, d, guess):
    """F88 to (2-45) at 30 digits, rotations from pose 1 (x[0] = y[0] = 0): A turned about D
    by -y_i (F88), the input link turned by x_i - y_i (F89); B1 = (xB, yB) and C1 = (xC, yC) with |P_i1 B1 - C1| = |B1 - C1|,
    i = 2..5. Returns the lengths a, b, c."""
    with mpmath.workdps(30):
        x = [mpmath.mpf(v) for v in x]
        y = [mpmath.mpf(v) for v in y]
        d = mpmath.mpf(d)

        def equations(xb, yb, xc, yc):
            out = []
            for i in range(1, 5):
                t = x[i] - y[i]
                px = mpmath.cos(t) * xb - mpmath.sin(t) * yb + d - d * mpmath.cos(y[i])
                py = mpmath.sin(t) * xb + mpmath.cos(t) * yb + d * mpmath.sin(y[i])
                out.append((px - xc) ** 2 + (py - yc) ** 2 - (xb - xc) ** 2 - (yb - yc) ** 2)
            return out

        xb, yb, xc, yc = mpmath.findroot(equations, guess)
        return [float(mpmath.hypot(xb, yb)), float(mpmath.hypot(xb - xc, yb - yc)),
                float(mpmath.hypot(xc - d, yc))]


def test_example_2_16_five_chebyshev_points_free_start_angles():
    """Ex. 2-16's function through five Chebyshev points with both start angles free (the
    text's analytical route F88): the design agrees with the inversion equations solved at
    30 digits, covers the range, and has a largest error of about 0.0013 in y."""
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    X, Y = m.rotations(chebyshev_spacing(1.0, 10.0, 5))
    designs = precision_pairs(X, Y, d=100.0, target=m)
    g = designs[0]
    assert g.covers_range and g.pair_error < 1e-9
    a, b, c, d = g.lengths
    B1 = a * np.exp(1j * (g.theta0 + X[0]))          # pose 1 is the reference of the inversion
    C1 = d + c * np.exp(1j * (g.psi0 + Y[0]))
    guess = [B1.real + 0.5, B1.imag - 0.5, C1.real + 0.5, C1.imag + 0.5]
    want = _inversion_five(X - X[0], Y - Y[0], 100.0, guess)
    assert np.allclose(g.lengths[:3], want, rtol=1e-10)
    assert 0.0012 < g.errors(2001)[0] / abs(m.output_scale) < 0.0014


def test_reversal_and_branch_defects():
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    X, Y = m.rotations(chebyshev_spacing(1.0, 10.0, 3))
    # counter-clockwise pairs at the clockwise start angles: met, but not on one branch
    Xc, Yc = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, 60 * DEG).rotations(chebyshev_spacing(1.0, 10.0, 3))
    g, = precision_pairs(Xc, Yc, theta0=40 * DEG, psi0=245 * DEG, d=100.0)
    assert g.defect == "branch" and g.pair_error > 1e-3
    # Ex. 2-16 as posed, checked only up to x = 9.5: assembled there, but the output turns
    # back from x = 8.68 while log10 does not
    ccw = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, 60 * DEG)
    Xp, Yp = ccw.rotations(chebyshev_spacing(1.0, 10.0, 3))
    span = (0.0, float(ccw.input_rotation(9.5)))
    g, = precision_pairs(Xp, Yp, theta0=60 * DEG, psi0=240 * DEG, d=100.0, target=ccw, x_range=span)
    assert g.defect == "reversal" and not g.monotone
    g, = precision_pairs(Xp, Yp, theta0=60 * DEG, psi0=240 * DEG, d=100.0, target=ccw,
                         x_range=(0.0, float(ccw.input_rotation(8.5))))
    assert g.defect is None and g.monotone
    # a target that itself turns back may be followed by an output that does
    g, = precision_pairs(Xp, Yp, theta0=60 * DEG, psi0=240 * DEG, d=100.0, x_range=span,
                         target=lambda x: 0.3 * np.sin(4 * x))
    assert g.defect is None and not g.monotone


# ----------------------------------------------------------------------------- least squares
@pytest.mark.parametrize("kind", ["equation", "structural"])
def test_least_squares_three_points_is_exact(kind):
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    X, Y = m.rotations(chebyshev_spacing(1.0, 10.0, 3))
    exact, = precision_pairs(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0)
    fit = least_squares(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0, kind=kind)
    assert np.allclose(fit.lengths, exact.lengths, rtol=1e-9)
    assert fit.branch == exact.branch and fit.pair_error < 1e-9


def test_least_squares_structural_beats_equation():
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    X, Y = m.rotations(np.linspace(1.0, 10.0, 41))
    eq = least_squares(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0, kind="equation", target=m)
    st = least_squares(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0, target=m)
    rms = lambda g: np.sqrt(np.mean(g.structural_error(X, Y) ** 2))
    assert rms(st) < rms(eq)
    assert st.covers_range
    # the structural fit is a stationary point: a small change of any length raises the RMS
    for i in range(3):
        for step in (1e-4, -1e-4):
            lengths = np.array(st.lengths)
            lengths[i] *= 1 + step
            other = FunctionGenerator(lengths, st.theta0, st.psi0, st.branch, X, Y, tol=np.inf)
            assert rms(other) >= rms(st)


def test_least_squares_fit_start_improves_example_2_16():
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    X, Y = m.rotations(np.linspace(1.0, 10.0, 61))
    fixed = least_squares(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0, target=m)
    free = least_squares(X, Y, theta0=40 * DEG, psi0=245 * DEG, d=100.0, target=m, fit_start=True)
    assert free.covers_range
    assert free.errors()[0] < 0.5 * fixed.errors()[0]
    # the FourBar re-solved independently of the fit's model reproduces the reported error
    pose = FourBar(*free.lengths, branch=free.branch).solve(free.theta0 + X)
    assert np.allclose(_wrap(pose.psi - free.psi0 - Y), free.structural_error(X, Y), atol=1e-12)


def test_least_squares_errors():
    x, y = np.linspace(0, 1, 6), np.linspace(0, 0.5, 6)
    with pytest.raises(ValueError, match="Expected `kind`"):
        least_squares(x, y, theta0=1.0, psi0=2.0, kind="cubic")
    with pytest.raises(ValueError, match="at least 5 pairs"):
        least_squares(x[:4], y[:4], theta0=1.0, psi0=2.0, fit_start=True)
    with pytest.raises(ValueError, match="Expected `start`"):
        least_squares(x, y, theta0=1.0, psi0=2.0, start="design")


def test_function_map_errors_and_inverse():
    m = FunctionMap(np.log10, (1.0, 10.0), 100 * DEG, -60 * DEG)
    x = np.linspace(1, 10, 7)
    assert np.allclose(m.input_value(m.input_rotation(x)), x)
    assert np.allclose(m.output_value(m.output_rotation(np.log10(x))), np.log10(x))
    assert np.allclose(m(m.input_rotation(x)), m.output_rotation(np.log10(x)))
    with pytest.raises(ValueError, match="Expected `f`"):
        FunctionMap(3.0, (1.0, 10.0), 1.0, 1.0)
    with pytest.raises(ValueError, match="x_range"):
        FunctionMap(np.log10, (1.0, 1.0), 1.0, 1.0)
    with pytest.raises(ValueError, match="Expected `psi_range` != 0"):
        FunctionMap(np.log10, (1.0, 10.0), 1.0, 0.0)


def test_function_generator_read_only():
    g, = precision_pairs([0.0, 0.5, 1.0], [0.0, 0.3, 0.5], theta0=1.0, psi0=2.0)
    with pytest.raises(AttributeError):
        g.lengths = (1, 2, 3, 4)
    with pytest.raises(ValueError, match="Expected `y`"):
        g.structural_error([0.1])


def test_fig_2_27_second_lg_generator_closes_its_loop_at_the_pairs():
    """Fig. 2-27: the second four-bar for y = lg x (input 90 deg from 60 deg, output 60 deg
    clockwise from 260 deg, Chebyshev points). At each precision pair the pins placed by the
    prescribed angles are exactly a coupler length apart (loop closure, worked here), and
    an independent circle intersection over the range keeps the error in y under 0.051."""
    from mech.planar.synthesis import FunctionMap, chebyshev_spacing, precision_pairs

    nodes = chebyshev_spacing(1.0, 10.0, 3)
    task = FunctionMap(np.log10, (1.0, 10.0), np.radians(90.0), -np.radians(60.0))
    X, Y = task.rotations(nodes)
    g, = precision_pairs(X, Y, theta0=np.radians(60.0), psi0=np.radians(260.0), d=100.0, target=task)
    a, b, c, d = g.lengths
    B = a * np.exp(1j * (np.radians(60.0) + X))
    C = d + c * np.exp(1j * (np.radians(260.0) + Y))
    assert np.abs(np.abs(C - B) - b).max() < 1e-10 * d
    assert g.covers_range
    # independent analysis: C where the circles about B (radius b) and D (radius c) meet,
    # on the side of the line B D that holds the first precision position
    x = np.linspace(1.0, 10.0, 2001)
    Bx = a * np.exp(1j * (np.radians(60.0) + task.input_rotation(x)))
    m = np.abs(d - Bx)
    u = (d - Bx) / m
    along = (b**2 - c**2 + m**2) / (2 * m)
    side = np.sign(np.imag(np.conj(d - B[0]) * (C[0] - B[0])))
    Cx = Bx + u * (along + 1j * side * np.sqrt(b**2 - along**2))
    turned = np.unwrap(np.angle((Cx - d) * np.exp(-1j * np.radians(260.0))))  # from the start angle
    y = turned / task.output_scale                                             # y = 0 at the start
    err = np.abs(y - np.log10(x))
    assert 0.045 < err.max() < 0.051
    assert np.allclose(np.asarray(g.lengths) / d, [0.6913, 1.2300, 0.5213, 1.0], atol=5e-5)
